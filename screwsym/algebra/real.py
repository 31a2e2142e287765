r"""Real zeros and positivity of polynomials, proved.

A case of a split holds only where its equations have a real point; a factor that
has none is dropped (:func:`real_factors`).  Proofs, each exact: a polynomial in one
symbol without a real root (SymPy's ``count_roots``, through the norm over Q where the
coefficients hold surds: :func:`rational_norm`); a quadratic ``a x**2 + b x + c`` with
``a > 0`` and ``4 a c - b**2 > 0`` everywhere, recursively (:func:`proved_positive`); a
product proved factor by factor.  The real zeros of a condition in one symbol
(:func:`real_points`, SymPy's ``real_roots``: surds or ``CRootOf``) or on the circle of
one angle (:func:`circle_points`, through ``t = tan(q/2)`` and ``q = pi`` apart) are the
points where a split decides the case by substitution; :func:`square_split` writes a
sum of squares as two equations.

Where it does not simply call SymPy: SymPy's ``is_positive`` answers ``None`` for most
such polynomials, and ``real_roots`` refuses algebraic coefficients (a ``DomainError``
over ``EX``); such a condition stays undecided (``None``) unless a norm decides it.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import lru_cache
from typing import Any

from sympy import (
    And,
    Dummy,
    Eq,
    Integer,
    Poly,
    Pow,
    cancel,
    cos,
    fraction,
    minimal_polynomial,
    radsimp,
    resultant,
    sin,
)

from .budget import charge
from .circle import TRIG_BACK, angles_of, on_circle, trig_symbol
from .numberfield import field_factor_list
from .rings import to_expr

__all__ = [
    "real_factors",
    "involved_indices",
    "proved_positive",
    "square_split",
    "no_real_zero",
    "dimension",
    "largest_degree",
    "solvable",
    "linear_in",
    "real_zeros",
    "rational_domain",
    "rational_norm",
    "real_points",
    "admissible",
    "circle_points",
]


def real_factors(p, R, proved_nonzero: Callable[[Any], bool] = lambda e: False) -> list:
    """The irreducible factors of ``p`` that can vanish at a real point: not proved non-zero.

    A factor is proved non-zero by ``proved_nonzero`` (given its expression: the
    caller's decision, for instance the symbols' assumptions), by
    :func:`no_real_zero` (a definite polynomial), or by having no real root
    (a polynomial in one symbol) or no point on the unit circle (a
    polynomial in ``sin(q)`` and ``cos(q)`` alone).
    """
    if p.is_ground:
        return []
    charge(len(p.terms()) ** 2)
    fl = field_factor_list(p, R)
    out = []
    for f, _ in fl:
        if f.is_ground:
            continue
        e = to_expr(f, R)
        if proved_nonzero(e) or no_real_zero(f, R) or real_zeros(f, R) == ():
            continue
        out.append(f)
    return out


def involved_indices(f, R) -> list:
    """The indices of the ring symbols that ``f`` depends on."""
    return [i for i in range(len(R.gens)) if f.degree(i) > 0]


def proved_positive(p, R, depth: int = 0) -> bool:
    """True if ``p > 0`` at every real point, as proved here (False: not proved).

    Proofs: a positive constant; the symbols' assumptions (``is_positive``);
    a polynomial in one symbol without a real root, positive at one point
    (``count_roots``); a quadratic ``a x**2 + b x + c`` in a symbol with
    ``a > 0`` and ``4 a c - b**2 > 0`` everywhere, each proved the same way
    (``(x + 2)**2 + (y + 2)**2 + 4``: ``4 (y + 2)**2 + 16 > 0``).  The ring
    symbols of ``sin(q)`` and ``cos(q)`` are read as free real symbols, which
    is stronger than needed.
    """
    if not p:
        return False
    if p.is_ground:
        return bool(R.domain.to_sympy(p.LC) > 0)
    if to_expr(p, R).is_positive:
        return True
    involved = involved_indices(p, R)
    if len(involved) == 1:
        x = R.symbols[involved[0]]
        u = Poly(R.to_sympy(p), x)
        if not rational_domain(u):
            # count_roots counts over the rationals only: a polynomial over them whose roots
            # include u's (its norm) without a real root proves u of one sign
            n = rational_norm(u.as_expr(), x)
            return n is not None and n.count_roots() == 0 and u.nth(0).is_positive is True
        return u.count_roots() == 0 and bool(u.nth(0) > 0)  # no root, positive at 0
    if depth >= 3:
        return False
    for i in involved:
        x = R.symbols[i]
        if p.degree(i) != 2 or x.is_real is False:
            continue
        g = R.gens[i]
        a, b = p.coeff_wrt(g, 2), p.coeff_wrt(g, 1)
        c = p - a * g**2 - b * g
        if proved_positive(a, R, depth + 1) and proved_positive(4 * a * c - b**2, R, depth + 1):
            return True
    # at depth 0 the callers pass irreducible factors (``real_factors``): nothing to split
    return depth > 0 and _positive_product(p, R, depth)


def _positive_product(p, R, depth: int) -> bool:
    """True if ``p = c f_1**e_1 ... f_k**e_k`` is proved positive factor by factor.

    Each factor of odd power proved positive or negative (:func:`proved_positive`), each of
    even power without a real zero, and the signs' product positive:
    ``(p**2 + q**2 + 1)**2`` (the leading coefficient in ``z`` of a 3-RPS's leg
    condition) and ``36 (p**2 + q**2 + 1)**2 ((p + q/sqrt(3))**2 + 1/3)**2``.
    """
    charge(len(p.terms()) ** 2)
    fl = field_factor_list(p, R)
    if len(fl) == 1 and fl[0][1] == 1:
        return False  # irreducible: nothing to gain
    sign = 1
    lead = R.domain.to_sympy(p.LC)  # LC(p) = c * prod LC(f)**k: c's sign, with the signs below
    for f, k in fl:
        lead /= R.domain.to_sympy(f.LC) ** k
        if k % 2 == 0:
            if not no_real_zero(f, R, depth + 1):
                return False
        elif proved_positive(f, R, depth + 1):
            pass
        elif proved_positive(-f, R, depth + 1):
            sign = -sign
        else:
            return False
    return bool(lead * sign > 0)


def square_split(f, R, depth: int = 0):
    """``(2 a x + b, 4 a c - b**2)`` where ``f = a x**2 + b x + c >= 0`` is a sum of squares, else None.

    With ``a`` a positive number and ``D = 4 a c - b**2 >= 0`` everywhere
    (proved: positive, zero, or itself of this form), ``4 a f = (2 a x + b)**2 + D``,
    so ``f = 0`` exactly where both ``2 a x + b = 0`` and ``D = 0``: two
    equations in the place of one (``(x - 1)**2 + (y - 1)**2 = 0``: ``x = 1, y = 1``).
    """
    if depth >= 4:
        return None
    for i in involved_indices(f, R):
        if f.degree(i) != 2 or not solvable(i, R):
            continue
        g = R.gens[i]
        a, b = f.coeff_wrt(g, 2), f.coeff_wrt(g, 1)
        if not a.is_ground or not R.domain.to_sympy(a.LC) > 0:
            continue
        c = f - a * g**2 - b * g
        D = 4 * a * c - b**2
        if not D or proved_positive(D, R) or square_split(D, R, depth + 1) is not None:
            return 2 * a * g + b, D
    return None


def no_real_zero(f, R, depth: int = 0) -> bool:
    """True if ``f`` has no real zero: ``f`` or ``-f`` proved positive (:func:`proved_positive`)."""
    return proved_positive(f, R, depth) or proved_positive(-f, R, depth)


def dimension(polys: list, R) -> int:
    """How many user symbols the polynomials involve: plain ones and angles (``sin(q)``, ``cos(q)``)."""
    seen = set()
    for p in polys:
        for i in involved_indices(p, R):
            x = R.symbols[i]
            seen.add(TRIG_BACK[x].args[0] if x in TRIG_BACK else x)
    return len(seen)


def largest_degree(p) -> int:
    return max((sum(m) for m in p.monoms()), default=0)


def solvable(i: int, R) -> bool:
    """Whether ring symbol ``i`` may be solved for: a user symbol that is not an angle of sin/cos."""
    x = R.symbols[i]
    return x not in TRIG_BACK and not any(q == x for q, _, _ in angles_of(R))


def linear_in(f, R):
    """``(symbol, a, b)`` with ``f = a*symbol + b``; a constant ``a`` preferred; or None.

    Only a symbol that :func:`solvable` allows (never ``sin(q)``'s ring symbol, nor ``q``).
    """
    best = None
    for i, g in enumerate(R.gens):
        if f.degree(i) != 1 or not solvable(i, R):
            continue
        a = f.coeff_wrt(g, 1)
        b = f - a * g
        key = (0 if a.is_ground else 1, len(a.terms()), len(b.terms()), str(R.symbols[i]))
        if best is None or key < best[0]:
            best = (key, R.symbols[i], a, b)
    return None if best is None else best[1:]


def real_zeros(f, R) -> tuple | None:
    """The real zeros of ``f`` when they are finitely many and found exactly; else None.

    Each zero is ``(pairs, condition)``: the substitution (``((x, root),)``, or
    ``((sin(q), s), (cos(q), c))``) and its condition in the user's symbols.
    Decided: ``f`` in one symbol (its real roots: ``real_roots``, surds or
    ``CRootOf``) and ``f`` in ``sin(q)``, ``cos(q)`` of one angle (the points of
    the circle, :func:`circle_points`).  ``()`` where there is no real zero.
    """
    involved = involved_indices(f, R)
    if not involved:
        return None
    angles = {TRIG_BACK[R.symbols[i]].args[0] for i in involved if R.symbols[i] in TRIG_BACK}
    if len(angles) == 1 and all(R.symbols[i] in TRIG_BACK for i in involved):
        return circle_points(R.to_sympy(f), next(iter(angles)))
    if len(involved) == 1 and solvable(involved[0], R):
        x = R.symbols[involved[0]]
        if not rational_domain(Poly(R.to_sympy(f), x)):
            n = rational_norm(R.to_sympy(f), x)
            return () if n is not None and n.count_roots() == 0 else None
        return real_points(R.to_sympy(f), x)
    return None


def rational_domain(u: Poly) -> bool:
    """Whether SymPy isolates the real roots of ``u``: integer or rational coefficients.

    ``real_roots`` and ``count_roots`` refuse algebraic coefficients (``sqrt(3) x - 1``:
    ``DomainError`` over ``EX``); such a condition stays undecided (``None``).
    """
    return u.domain.is_ZZ or u.domain.is_QQ


def rational_norm(e: Any, x: Any) -> Poly | None:
    """A non-zero polynomial in ``x`` over the rationals whose roots include those of ``e``.

    ``e`` is a polynomial in ``x`` whose coefficients hold square roots (or other
    radicals) of rationals: each radical ``a`` becomes a symbol ``y`` and is
    eliminated by the resultant with its minimal polynomial, the product of ``e``
    over the conjugates of ``a``, which vanishes wherever ``e`` does.  None where
    no such polynomial is found (other algebraic coefficients).
    """
    radicals = sorted((a for a in e.atoms(Pow)
                       if a.base.is_Rational and a.exp.is_Rational and not a.exp.is_Integer),
                      key=str)
    for a in radicals:
        y = Dummy("y")
        charge(Poly(e, x).degree() ** 3)
        e = resultant(e.xreplace({a: y}).expand(), minimal_polynomial(a, y), y)
    u = Poly(e, x)
    return u if rational_domain(u) and not u.is_zero else None


@lru_cache(maxsize=1024)
def real_points(e: Any, x: Any) -> tuple:
    """The distinct real roots ``r`` of the polynomial ``e`` in ``x``, as ``(((x, r),), Eq(x, r))``."""
    charge(Poly(e, x).degree() ** 3)
    roots: list = []
    for r in Poly(e, x).real_roots():
        if r not in roots and admissible(x, r):
            roots.append(r)
    return tuple((((x, r),), Eq(x, r)) for r in roots)


def admissible(x: Any, r: Any) -> bool:
    """Whether the value ``r`` may be the symbol ``x``'s: no assumption of ``x`` refutes it."""
    for prop in ("positive", "nonnegative", "negative", "nonpositive", "nonzero", "integer"):
        if getattr(x, f"is_{prop}") and getattr(r, f"is_{prop}") is False:
            return False
    return True


@lru_cache(maxsize=1024)
def circle_points(e: Any, q: Any) -> tuple | None:
    """The points ``(sin q, cos q)`` of the unit circle where the polynomial ``e`` vanishes.

    ``e`` is in the ring symbols of ``sin(q)`` and ``cos(q)``.  Through
    ``t = tan(q/2)``: the real roots of the numerator of ``e(2t/(1+t**2),
    (1-t**2)/(1+t**2))`` give every point but ``q = pi``, ``(0, -1)``, which is
    checked apart.  Each point is ``(((sin(q), s), (cos(q), c)), condition)``.
    """
    S, C = trig_symbol(sin, q), trig_symbol(cos, q)
    t = Dummy("t", real=True)
    s, c = on_circle(t)
    num = fraction(cancel(e.xreplace({S: s, C: c})))[0]
    values: list = []
    if num.has(t) and not rational_domain(Poly(num, t)):
        # radical coefficients: decided only where the circle has no point but q = pi
        n = rational_norm(num, t)
        if n is None or n.count_roots() != 0:
            return None
        at_pi = radsimp(e.xreplace({S: 0, C: -1}))
        if at_pi.is_zero is None:
            return None
        values = [(Integer(0), Integer(-1))] if at_pi.is_zero else []
        return tuple((((sin(q), s), (cos(q), c)), And(Eq(sin(q), s), Eq(cos(q), c)))
                     for s, c in values)
    if num.has(t):
        charge(Poly(num, t).degree() ** 3)
        for r in Poly(num, t).real_roots():
            value = (radsimp(cancel(2 * r / (1 + r**2))), radsimp(cancel((1 - r**2) / (1 + r**2))))
            if value not in values:
                values.append(value)
    if e.xreplace({S: 0, C: -1}) == 0 and (0, -1) not in values:
        values.append((Integer(0), Integer(-1)))
    return tuple((((sin(q), s), (cos(q), c)), And(Eq(sin(q), s), Eq(cos(q), c)))
                 for s, c in values)
