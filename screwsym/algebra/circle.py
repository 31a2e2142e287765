r"""``sin(q)`` and ``cos(q)`` as two ring symbols on the unit circle.

Why s = sin(q), c = cos(q) with s**2 + c**2 = 1, and not t = tan(q/2): the half-angle
substitution misses q = pi (t infinite) and writes every condition in t, a symbol the
user never wrote; with s and c the factors of the minors are polynomials in the user's
own sin(q) and cos(q), and every point of the circle is in the ring's reach.  The ring
Q[s, c] / (s**2 + c**2 - 1) is an integral domain (the circle's polynomial is
irreducible), and the polynomial of degree at most 1 in c is the unique normal form of
a class (c**2 -> 1 - s**2: ``reduce_circle``), so zero is decided exactly by reducing.  The
rational points (2t/(1+t**2), (1-t**2)/(1+t**2)) are dense on the circle, so a minor
non-zero at one of them is a non-zero element, and a rank found there is the generic
rank.  Factoring a reduced minor in Q[s, c, ...] covers its zeros on the circle (each
zero is a zero of a factor).  A condition on sin(q) and cos(q) alone is decided at its
points, found exactly through t (the real roots of the numerator of f(2t/(1+t**2),
(1-t**2)/(1+t**2))) together with q = pi, which t cannot reach (``circle_points``).
A symbol ``q`` that also appears outside sin and cos is never solved for (a condition
``q sin(q) = 1`` is not a substitution): such a case is left undecided (None).

The half-angle map itself (:func:`on_circle`, :func:`half_angle_symbol`,
:func:`from_half_angle`) serves where a *field* is needed: the rational functions of
``t`` are those of the circle, so a rank or a null space over them is the generic one
(:func:`screwsym.algebra.linalg.field_matrix`), and a basis found in ``t`` is written
back in ``sin(q)``, ``cos(q)``.

Where it does not simply call SymPy: ``trigsimp`` and ``fu`` search for short forms
and decide nothing; a Groebner basis of the circles would give the same normal form as
:func:`reduce_powers`, which reads it off in one pass (the relations' leading terms are
coprime).  SymPy's ``expand_trig`` brings sums and multiples of angles to ``sin(q)``,
``cos(q)`` (:func:`trig_normal`).
"""

from __future__ import annotations

import random
from functools import lru_cache
from math import comb
from typing import Any

from sympy import (
    QQ,
    Add,
    And,
    Dummy,
    Eq,
    Mul,
    Or,
    cancel,
    cos,
    expand_trig,
    radsimp,
    sin,
    sqrt,
)

__all__ = [
    "trig_symbol",
    "trig_normal",
    "trig_entries",
    "angles_of",
    "reduce_circle",
    "reduce_powers",
    "on_circle",
    "sample_point",
    "circle_simplify",
    "trig_substitute",
    "circle_relations",
    "half_angle_symbol",
    "from_half_angle",
    "has_trig",
    "TRIG_BACK",
]


#: the ring symbol of ``sin(q)`` or ``cos(q)``, by ``(sin or cos, q)``; and back
_TRIG_SYMBOL: dict[tuple[Any, Any], Dummy] = {}


TRIG_BACK: dict[Dummy, Any] = {}


def trig_symbol(f: Any, q: Any) -> Dummy:
    d = _TRIG_SYMBOL.get((f, q))
    if d is None:
        d = Dummy(f"{f.__name__}_{q}", real=True)
        _TRIG_SYMBOL[(f, q)] = d
        TRIG_BACK[d] = f(q)
    return d


def trig_normal(e: Any) -> Any:
    """``e`` with sin and cos of sums and integer multiples of symbols expanded (``expand_trig``)."""
    if not e.has(sin, cos) or all(a.args[0].is_Symbol for a in e.atoms(sin, cos)):
        return e
    return expand_trig(e)


def trig_entries(entries: list) -> list:
    """``entries`` with ``sin(q)``, ``cos(q)`` (``q`` a symbol) replaced by their ring symbols."""
    out = []
    for e in entries:
        e = trig_normal(e)
        atoms = e.atoms(sin, cos)
        if atoms:
            e = e.xreplace({a: trig_symbol(a.func, a.args[0]) for a in atoms
                            if a.args[0].is_Symbol})
        out.append(e)
    return out


@lru_cache(maxsize=256)
def angles_of(R) -> tuple:
    """``(q, index of cos(q) or None, index of sin(q) or None)`` for each angle in the ring."""
    found: dict[Any, list] = {}
    for i, x in enumerate(R.symbols):
        back = TRIG_BACK.get(x)
        if back is not None:
            found.setdefault(back.args[0], [None, None])[0 if back.func is cos else 1] = i
    return tuple((q, ci, si) for q, (ci, si) in found.items())


def reduce_powers(P: Any, pairs: Any) -> Any:
    """``P`` modulo ``low**2 + high**2 - 1`` for each ``(low, high)`` pair of generator indices:
    every ``high**k``, ``k >= 2``, made ``high**(k mod 2) (1 - low**2)**(k // 2)``.

    The normal form modulo the circles (their leading terms ``high**2`` are coprime, a
    Groebner basis): ``P`` vanishes on the circles exactly when this is zero.  One pass
    by the binomial expansion; used with ``high`` the cosine here (:func:`reduce_circle`)
    and the sine in the product of exponentials (``screwsym.motion``).

    >>> from sympy import QQ
    >>> from sympy.polys.rings import ring
    >>> R, c, s = ring("c s", QQ)
    >>> reduce_powers(s**3 + c, [(0, 1)])          # s**3 = s (1 - c**2)
    -c**2*s + c + s
    >>> reduce_powers(s**2 + c**2 - 1, [(0, 1)])   # zero on the circle
    0
    """
    ring = P.ring
    zero = ring.domain.zero
    for low, high in pairs:
        if all(m[high] < 2 for m in P.itermonoms()):
            continue
        out: dict = {}
        for m, c in P.iterterms():
            k = m[high]
            if k < 2:
                out[m] = out.get(m, zero) + c
                continue
            j, r = divmod(k, 2)
            base = list(m)
            base[high] = r
            for t in range(j + 1):
                ml = list(base)
                ml[low] += 2 * t
                mt = tuple(ml)
                out[mt] = out.get(mt, zero) + c * comb(j, t) * (-1) ** t
        P = ring.from_dict({m: c for m, c in out.items() if c})
    return P


def reduce_circle(p, R):
    """``p`` reduced modulo ``sin(q)**2 + cos(q)**2 - 1`` for each angle: degree <= 1 in cos(q)."""
    pairs = [(si, ci) for _, ci, si in angles_of(R) if ci is not None and si is not None]
    if not pairs or not p:
        return p
    return reduce_powers(p, pairs)


def on_circle(t: Any) -> tuple:
    """The point ``(sin q, cos q)`` of the unit circle at ``t = tan(q/2)``: every point but ``q = pi``.

    ``(2 t / (1 + t**2), (1 - t**2) / (1 + t**2))``, for a number or a symbol ``t``:
    the rational parametrisation, a bijection of the function field of the circle with
    the rational functions of ``t`` (so a rank over those is the generic rank on the circle).

    >>> from sympy import Rational
    >>> from screwsym.algebra.circle import on_circle
    >>> on_circle(Rational(1, 2))
    (4/5, 3/5)
    """
    return 2 * t / (1 + t**2), (1 - t**2) / (1 + t**2)


def sample_point(R, rnd: random.Random) -> list:
    """A random rational point of the ring's symbols, ``(sin q, cos q)`` on the unit circle."""
    K = R.domain
    point = [K.convert(rnd.randint(-97, 97)) for _ in R.gens]
    for _, ci, si in angles_of(R):
        t = QQ(rnd.randint(-97, 97), rnd.randint(1, 97))
        s, c = on_circle(t)
        if si is not None:
            point[si] = K.convert(s)
        if ci is not None:
            point[ci] = K.convert(c)
    return point


def circle_simplify(expr: Any) -> Any:
    """``expr`` with ``Eq(sin(q), s) & (Eq(cos(q), c) | Eq(cos(q), -c))`` written ``Eq(sin(q), s)``.

    On the unit circle ``sin(q) = s`` holds at exactly the two points
    ``cos(q) = +-sqrt(1 - s**2)`` (one where ``s = +-1``); likewise with sin and
    cos exchanged.  For merged cases: the points of one factor given as one
    condition.

    >>> from sympy import Eq, cos, sin, symbols
    >>> from screwsym.algebra.circle import circle_simplify
    >>> q = symbols("q", real=True)
    >>> circle_simplify(Eq(sin(q), 0) & (Eq(cos(q), 1) | Eq(cos(q), -1)))
    Eq(sin(q), 0)
    >>> circle_simplify((Eq(sin(q), 0) & Eq(cos(q), 1)) | (Eq(sin(q), 0) & Eq(cos(q), -1)))
    Eq(sin(q), 0)
    >>> circle_simplify((Eq(sin(q), 1) & Eq(cos(q), 0)) | (Eq(sin(q), 0) & Eq(cos(q), -1)))
    (Eq(sin(q), 0) & Eq(cos(q), -1)) | (Eq(sin(q), 1) & Eq(cos(q), 0))
    """
    def one(node: Any) -> Any:
        if not isinstance(node, And):
            return node
        args = list(node.args)
        for i, a in enumerate(args):
            if not (isinstance(a, Eq) and isinstance(a.lhs, (sin, cos))):
                continue
            other = cos if isinstance(a.lhs, sin) else sin
            q, value = a.lhs.args[0], a.rhs
            need = {radsimp(cancel(r)) for r in (sqrt(1 - value**2), -sqrt(1 - value**2))}
            for j, b in enumerate(args):
                if j == i or not isinstance(b, Or):
                    continue
                if all(isinstance(e, Eq) and e.lhs == other(q) for e in b.args) and \
                        {radsimp(cancel(e.rhs)) for e in b.args} == need:
                    return And(*(x for k, x in enumerate(args) if k != j))
        return node

    def pairs(node: Any) -> Any:
        if not isinstance(node, Or):
            return node
        args = [set(a.args) if isinstance(a, And) else {a} for a in node.args]
        for i in range(len(args)):
            for j in range(i + 1, len(args)):
                da, db = args[i] - args[j], args[j] - args[i]
                if len(da) != 1 or len(db) != 1:
                    continue
                (x,), (y,) = da, db
                common = args[i] & args[j]
                if not (isinstance(x, Eq) and isinstance(y, Eq) and x.lhs == y.lhs
                        and isinstance(x.lhs, (sin, cos))):
                    continue
                other = cos if isinstance(x.lhs, sin) else sin
                line = [a for a in common if isinstance(a, Eq) and a.lhs == other(x.lhs.args[0])]
                if not line:
                    continue
                value = line[0].rhs
                need = {radsimp(cancel(r)) for r in (sqrt(1 - value**2), -sqrt(1 - value**2))}
                if {radsimp(cancel(x.rhs)), radsimp(cancel(y.rhs))} == need:
                    rest = [And(*a) for k, a in enumerate(args) if k not in (i, j)]
                    return pairs(Or(And(*common), *rest))
        return node

    if not expr.has(sin, cos):
        return expr
    return expr.replace(lambda x: isinstance(x, And), one).replace(
        lambda x: isinstance(x, Or), pairs)


def trig_substitute(obj: Any, subs: Any) -> Any:
    """``obj.xreplace(subs)``, where keys ``sin(q)`` and ``cos(q)`` reach ``sin(2 q)``, ``cos(q + r)``.

    The substitutions of a case split may set ``sin(q)`` and ``cos(q)`` of an
    angle ``q`` (a point of the circle); sin and cos of sums and integer
    multiples of ``q`` are expanded (``expand_trig``) before they are replaced.

    >>> from sympy import symbols, sin, cos
    >>> from screwsym.algebra.circle import trig_substitute
    >>> q, r = symbols("q r", real=True)
    >>> trig_substitute(sin(q + r) + cos(q), {sin(q): 0, cos(q): -1})
    -sin(r) - 1
    """
    d = dict(subs)
    angles = {k.args[0] for k in d if isinstance(k, (sin, cos))}
    if angles and hasattr(obj, "atoms"):
        for a in obj.atoms(sin, cos):
            if a not in d and not a.args[0].is_Symbol and a.args[0].free_symbols & angles:
                d[a] = expand_trig(a).xreplace(d)
    return obj.xreplace(d) if d else obj


def circle_relations(R) -> list:
    """``sin(q)**2 + cos(q)**2 - 1`` for each angle with both in the ring."""
    g = R.ring.gens
    return [g[si] ** 2 + g[ci] ** 2 - 1 for _, ci, si in angles_of(R)
            if ci is not None and si is not None]


#: the half-angle symbol ``t = tan(q/2)`` of each angle ``q`` (:func:`half_angle_symbol`); and its angle
_HALF: dict = {}


_HALF_BACK: dict = {}


def half_angle_symbol(q: Any) -> Dummy:
    t = _HALF.get(q)
    if t is None:
        t = Dummy(f"t_{q}", real=True)
        _HALF[q] = t
        _HALF_BACK[t] = q
    return t


def from_half_angle(row: list) -> list:
    """A vector over the rational functions of ``t = tan(q/2)`` (and the other symbols) as
    polynomials in ``sin(q)``, ``cos(q)``: the same vector up to a factor non-zero generically.

    Cleared of denominators and of the common factor, a polynomial vector of degree ``D``
    in ``t`` divided by ``(1 + t**2)**n``, ``n = ceil(D/2)``, is one of degree ``n`` in
    ``sin(q)`` and ``cos(q)``: with ``t = sin(q)/(1 + cos(q))`` and ``1 + t**2 =
    2/(1 + cos(q))``, ``t**k/(1 + t**2)**n = sin(q)**(k % 2) (1 - cos(q))**(k // 2)
    (1 + cos(q))**(n - k + k // 2) / 2**n`` (``sin(q)**2 = (1 - cos(q)) (1 + cos(q))``),
    a polynomial for every ``k <= 2 n``.
    """
    nz = [e for e in row if e]
    ring = nz[0].numer.ring
    den = ring.one
    for e in nz:
        den = den.lcm(e.denom)
    polys = [e.numer * den.exquo(e.denom) if e else ring.zero for e in row]
    g = ring.zero
    for p in polys:
        if p:
            g = p if not g else g.gcd(p)
    polys = [p.exquo(g) if p else p for p in polys]
    angles = {i: _HALF_BACK[x] for i, x in enumerate(ring.symbols) if x in _HALF_BACK}
    half = {i: (max(p.degree(i) for p in polys if p) + 1) // 2 for i in angles}
    K0 = ring.domain
    out = []
    for p in polys:
        terms = []
        for monom, c in p.terms():
            factors = [K0.to_sympy(c)]
            for i, k in enumerate(monom):
                if i in angles:
                    q, n = angles[i], half[i]
                    factors.append(sin(q) ** (k % 2) * (1 - cos(q)) ** (k // 2)
                                   * (1 + cos(q)) ** (n - k + k // 2))
                elif k:
                    factors.append(ring.symbols[i] ** k)
            terms.append(Mul(*factors))
        out.append(Add(*terms))
    return out


def has_trig(entries: Any) -> bool:
    return any(e.has(sin, cos) for e in entries)
