r"""Closed forms in lowest terms, cheaply: :func:`tidy`.

Explanation
===========

The core operations of screwsym return their results *tidied*: cancelled and
compact, as a reader would write them (``Screw.from_axis(r, S, h).pitch`` is
``h``, not a 26-operation quotient).  The work is split in two:

1. **What the construction knows**, used by the operations themselves before
   any rewrite: a line vector's pitch is 0 by its invariant; ``S . S`` is a
   common factor of the pitch when the dual part is ``r x S + h S`` (the cross
   term vanishes on expansion), so the pitch is cancelled first and the axis
   moment ``S0 - h S`` then needs no quotient at all; the distance of a screw
   axis from the origin is ``|S0'| / |S|`` for the axis moment ``S0'``
   (Lagrange's identity ``|S x S0'|^2 = |S|^2 |S0'|^2 - (S . S0')^2`` with
   ``S . S0' = 0``); an axis or a shifted line keeps the kind's invariant
   identically, so it is not proved again.
2. **Cheap rewrites** of each expression: the form as built, its common
   factors pulled out, its lowest terms (SymPy's polynomial rings: what
   ``cancel`` computes, without ``cancel``'s extra passes), that with the
   numerator's content and monomial factor pulled out over a compact
   denominator, and, where ``sin(a)`` and ``cos(a)`` both occur, the same
   reduced by ``sin(a)**2 + cos(a)**2 = 1``.  The smallest by ``count_ops``
   wins (ties keep the earlier form).  The arguments of roots and functions
   (``sqrt``, ``Abs``, ``sign``, ``atan2``, ``Piecewise`` branches) are
   tidied first, bottom-up, and are generators for the rings.  Never a
   blanket ``simplify``: its cost is unpredictable.

Every rewrite is an identity of rational functions (and of ``sin``/``cos``),
so a tidied result equals the raw one wherever the raw one is defined
(lowest terms may remove a removable singularity, as ``cancel`` does).

Cost is guarded: an expression with more than ``max_size`` nodes (see
:func:`tidy`) comes back unchanged, and expressions with floating-point
numbers are left as they are (rewriting would reorder rounding).  The core
operations take ``tidy=False`` to return the raw result.
"""

from __future__ import annotations

import math
from typing import Any, TypeVar

from sympy import (
    Add,
    Basic,
    Derivative,
    Dummy,
    Expr,
    Float,
    Integral,
    Mul,
    Piecewise,
    Pow,
    Rational,
    S,
    Sum,
    Tuple,
    cos,
    count_ops,
    expand,
    factor,
    fraction,
    sin,
)
from sympy.core.cache import cacheit
from sympy.core.function import Application, _coeff_isneg
from sympy.core.operations import LatticeOp
from sympy.core.sorting import default_sort_key
from sympy.matrices import MatrixBase
from sympy.polys.domains import QQ, ZZ
from sympy.polys.monomials import monomial_min
from sympy.polys.polyerrors import CoercionFailed, GeneratorsError, PolynomialError
from sympy.polys.rings import ring
from sympy.simplify.fu import TR10i

from ..algebra.numberfield import surd_normal
from ..algebra.rings import NotInRing, tree_to_ring
from .basic import ScrewsymBasic
from .checks import check_count, check_tidy_input

__all__ = ["tidy"]

#: expressions with more nodes than this come back unchanged (the rewrites grow faster)
MAX_SIZE = 3000
#: ``factor`` is tried only on denominators with at most this many nodes (it is the dear one)
FACTOR_SIZE = 40


#: what tidy gives back: the kind it is given (a screwsym object keeps its class)
_T = TypeVar("_T")


def tidy(expr: _T, *, max_size: int = MAX_SIZE, sum_of_angles: bool = True) -> _T:
    r"""Bring ``expr`` to lowest terms and a compact form, without ``simplify``.

    Explanation
    ===========

    Works on a SymPy expression, a matrix (entry by entry), a screwsym object
    (a screw, a common normal, ... : part by part, keeping its class), and on
    tuples and lists of these.  Each expression is brought to lowest terms
    (as ``cancel``), its common factors are pulled out (as ``factor_terms``),
    ``sin(a)**2 + cos(a)**2`` is reduced to 1, and the smallest form by
    ``count_ops`` is kept, the expression as given among the candidates, so
    the result is never larger.  It equals ``expr`` wherever ``expr`` is
    defined.  The results of screwsym's own operations come tidied already
    (module docstring); this is for a user's own expressions.

    Expressions with more than ``max_size`` nodes, expressions whose
    expansion (the polynomial arithmetic of lowest terms) would have more
    than ``max_size`` terms, and expressions with floats come back
    unchanged: ``max_size`` bounds the work, not only the input
    (``tidy((a + b + c + d)**60 + 1)``, 39,711 terms expanded, took a minute).

    Examples
    ========

    >>> from sympy import symbols
    >>> from screwsym import Screw, tidy, vector
    >>> h = symbols("h", real=True)
    >>> r, S = vector("r"), vector("S")
    >>> s = Screw.from_axis(r, S, h)
    >>> tidy(S.dot(s.S0) / S.dot(S))                    # the pitch (1.34), as built
    h
    >>> x, y = symbols("x y", real=True)
    >>> tidy((x**2 - y**2) / (x + y) + y)
    x
    >>> tidy([x*y + x*y**2, (x**2 - 1)/(x - 1)])
    [x*y*(y + 1), x + 1]
    >>> from sympy import cos, sin
    >>> tidy((h*cos(x)**2 + y*sin(x)**2) / (sin(x)**2 + cos(x)**2))
    h*cos(x)**2 + y*sin(x)**2

    Parameters
    ==========

    expr : Expr, Matrix, screwsym object, or a tuple or list of these
    max_size : int
        Expressions with more nodes than this come back unchanged.
    sum_of_angles : bool
        Also try gathering products of sines and cosines into sines and cosines
        of sums (SymPy's ``TR10i``; default True).  It is the dearest rewrite: a
        recursion that tidies many intermediate results and only its final ones
        for a reader (the dynamics of a chain) passes False for the former.

    See Also
    ========

    sympy.polys.polytools.cancel, sympy.core.exprtools.factor_terms
    """
    check_tidy_input(expr, "expr")
    if not isinstance(sum_of_angles, bool):
        raise TypeError(f"sum_of_angles: expected True or False, got {type(sum_of_angles).__name__}")
    return _tidy_any(expr, check_count(max_size, "max_size"), sum_of_angles)


def _tidy_any(obj: Any, limit: int, angles: bool = True) -> Any:
    if isinstance(obj, Expr) and not isinstance(obj, MatrixBase):
        return _tidy_expr(obj, limit, angles)
    if isinstance(obj, MatrixBase):
        return obj.applyfunc(lambda e: _tidy_expr(e, limit, angles))
    if isinstance(obj, ScrewsymBasic):
        args = tuple(_tidy_any(a, limit, angles) for a in obj.args)
        if args == obj.args:
            return obj
        # Every part is equal to the one it replaces, so the object's invariants (a line
        # vector's S.S0 = 0, ...) still hold: rebuild without validating again.
        return Basic.__new__(type(obj), *args)
    if isinstance(obj, Tuple):  # SymPy's tuple, as in the args of a chain
        args = tuple(_tidy_any(a, limit, angles) for a in obj.args)
        return obj if args == obj.args else Tuple(*args)
    if isinstance(obj, list):
        return [_tidy_any(o, limit, angles) for o in obj]
    if isinstance(obj, tuple) and not hasattr(obj, "_fields"):
        return tuple(_tidy_any(o, limit, angles) for o in obj)
    return obj  # numbers, booleans, named tuples and other Basic objects: as they are


def _size(e: Basic, limit: int) -> int:
    """The number of nodes of ``e``, counted up to ``limit + 1``."""
    n = 0
    stack = [e]
    while stack:
        node = stack.pop()
        n += 1
        if n > limit:
            break
        stack.extend(node.args)
    return n


def _tidy_expr(e: Expr, limit: int, angles: bool = True) -> Expr:
    # the size first: it stops counting at the limit, where free_symbols and has walk it all
    if e.is_Atom or _size(e, limit) > limit:
        return e
    if _expanded_terms(e, limit) > limit or e.has(Float):
        return e
    if not e.free_symbols:
        return _number(e)
    return _rewrite(e, angles)


@cacheit
def _number(e: Expr) -> Expr:
    """A number in ``Q(sqrt p_1, ..., sqrt p_k)`` (sums and products of rationals and square
    roots of rationals) in its normal form ``sum c_i sqrt(m_i)`` when that is not larger: the
    entries of products of rotations at 15 degrees stay four terms instead of growing with
    every factor (:func:`screwsym.algebra.numberfield.surd_normal`).  Other numbers as given.
    """
    normal = surd_normal(e)
    if normal is None or normal == e:
        return e
    return normal if _count_ops(normal) <= _count_ops(e) else e


def _expanded_terms(e: Basic, limit: int) -> int:
    """How many terms expanding ``e`` gives (roots and functions count 1), up to ``limit + 1``.

    A power ``(t terms)**n`` expands to ``C(n + t - 1, t - 1)`` terms at most.
    """
    cap = limit + 1
    if isinstance(e, Add):
        return min(cap, sum(_expanded_terms(a, limit) for a in e.args))
    if isinstance(e, Mul):
        n = 1
        for a in e.args:
            n = min(cap, n * _expanded_terms(a, limit))
        return n
    if isinstance(e, Pow) and e.exp.is_Integer:
        t = _expanded_terms(e.base, limit)
        k = abs(int(e.exp))
        if t <= 1 or k <= 1:
            return t
        if k >= cap:  # C(k + t - 1, t - 1) >= k + 1 > cap already
            return cap
        return min(cap, math.comb(k + t - 1, t - 1))
    return 1


@cacheit
def _rewrite(e: Expr, angles: bool = True) -> Expr:
    """The smallest of the cheap rewrites of ``e`` (its inner functions tidied first)."""
    e = _inside(e)
    if not isinstance(e, (Add, Mul, Pow)):
        return e
    candidates = [e, _common_factor(e)]
    if e.is_Add and all(a.is_Pow and a.exp.is_even for a in e.args) and not e.has(sin, cos):
        return _smallest(candidates)  # a sum of squares: expanding it only grows it
    # roots and functions (already tidied inside) become plain generators, so that the ring
    # arithmetic below neither expands their arguments nor looks into them
    frozen, thaw = _freeze(e)
    try:
        num, den = _together(frozen)
        rational = den.free_symbols != set()
        # sin(a)**2 + cos(a)**2 = 1 for the angles whose sine and cosine both occur
        relations = _pythagoras(thaw)
        P, D, *R = _to_ring([num, den, *relations])
        forms = []
        # reduced modulo the relations: nothing, the denominator, or both parts
        for Pr, Dr in [(P, D)] + ([(P, D.rem(R)), (P.rem(R), D.rem(R))] if R else []):
            if rational:
                Pr, Q = Pr.cancel(Dr)
                # lowest terms, expanded; then with the content and monomial factor of the
                # numerator pulled out, over the denominator as built when nothing cancelled
                compact_den = den if Q == D else _factored(Q.as_expr())
                forms += [Pr.as_expr() / Q.as_expr(), _pulled(Pr) / compact_den]
            else:
                scale = Dr.as_expr()  # a number
                forms += [Pr.as_expr() / scale, _pulled(Pr) / scale]
        if rational:
            forms.append(num / den)
    except (PolynomialError, GeneratorsError, CoercionFailed):  # pragma: no cover
        return _smallest(candidates)  # a form the polynomial rings refuse
    candidates += [x.xreplace(thaw) for x in forms]
    if not rational and relations and angles:
        candidates.append(_sum_of_angles(e))
    return _smallest(candidates)


def _sum_of_angles(e: Expr) -> Expr:
    """A trigonometric polynomial with products gathered into sines and cosines of sums.

    ``expand``; ``sin(a)**2 -> 1 - cos(a)**2`` where both squares occur (if shorter);
    then SymPy's ``TR10i`` (``cos(a)cos(b) - sin(a)sin(b) -> cos(a + b)``).  This is
    the form a chain's forward kinematics reads best in.
    """
    e = expand(e)
    squares = {p.base.args[0] for p in e.atoms(Pow) if p.exp == 2 and isinstance(p.base, sin)}
    both = [a for a in squares if e.has(cos(a) ** 2)]
    if both:
        reduced = expand(e.xreplace({sin(a) ** 2: 1 - cos(a) ** 2 for a in both}))
        e = _smallest([e, reduced])
    return TR10i(e)


def _smallest(candidates: list) -> Expr:
    """The candidate with the fewest operations (``count_ops``); the earliest among equals."""
    costs = [_count_ops(x) if isinstance(x, Expr) else count_ops(x) for x in candidates]
    return candidates[costs.index(min(costs))]


def _common_factor(e: Expr) -> Expr:
    """``e`` with the factors common to all its terms pulled out, nothing expanded.

    ``F*w*a + F*w*b`` becomes ``F*w*(a + b)``; the cheap part of ``factor_terms``.
    """
    if not e.is_Add:
        return e
    powers = [t.as_powers_dict() for t in e.args]
    common = {}
    for b, k in powers[0].items():
        if b.is_number or not k.is_Integer or k <= 0:
            continue
        low = min(pw.get(b, 0) for pw in powers)
        if low != 0 and low.is_Integer and low.is_positive:
            common[b] = low
    if not common:
        return e
    f = Mul(*(b**k for b, k in common.items()))
    return f * Add(*(t / f for t in e.args))


def _pythagoras(thaw: dict) -> list:
    """``s**2 + c**2 - 1`` for every pair of frozen ``sin(a)``, ``cos(a)`` (dummies s, c)."""
    sines = {x.args[0]: d for d, x in thaw.items() if isinstance(x, sin)}
    cosines = {x.args[0]: d for d, x in thaw.items() if isinstance(x, cos)}
    return [sines[a] ** 2 + cosines[a] ** 2 - 1 for a in sines if a in cosines]


def _together(e: Expr) -> tuple[Expr, Expr]:
    """Numerator and denominator of the rational expression ``e`` over a common denominator.

    The denominator is the product of the distinct denominators met, each to its highest
    power (compared as built, so ``(a**2 + 1)**2`` and ``a**2 + 1`` share their factor).
    SymPy's ``together`` does this and then runs ``gcd_terms`` on every level, which was
    half the cost of tidying; ``as_numer_denom`` skips the sharing, and its denominators
    grow as products of repeated factors.
    """
    if e.is_Add:
        parts = [_together(a) for a in e.args]
        powers = [d.as_powers_dict() for _, d in parts]
        common: dict = {}
        for pw in powers:
            for b, k in pw.items():
                common[b] = max(common.get(b, 0), k)
        num = Add(*(n * Mul(*(b ** (k - pw.get(b, 0)) for b, k in common.items()))
                    for (n, _), pw in zip(parts, powers, strict=True)))
        return num, Mul(*(b**k for b, k in common.items()))
    if e.is_Mul:
        parts = [_together(a) for a in e.args]
        return Mul(*(n for n, _ in parts)), Mul(*(d for _, d in parts))
    if e.is_Pow and e.exp.is_Integer:
        n, d = _together(e.base)
        return (n**e.exp, d**e.exp) if e.exp > 0 else (d ** -e.exp, n ** -e.exp)
    return e, S.One


def _freeze(e: Expr) -> tuple[Expr, dict]:
    """``e`` with every maximal non-rational part (root, function) replaced by a ``Dummy``.

    Returns the frozen expression and the map back.
    """
    parts: dict = {}

    def walk(x):
        if x.is_Symbol or x.is_Rational:
            return x
        if isinstance(x, (Add, Mul)) or isinstance(x, Pow) and x.exp.is_Integer:
            return x.func(*(walk(a) for a in x.args))
        if x not in parts:
            parts[x] = Dummy(real=True)
        return parts[x]

    frozen = walk(e)
    return frozen, {d: x for x, d in parts.items()}


def _to_ring(exprs: list) -> list:
    """The polynomial expressions ``exprs`` as elements of one ring over ZZ (or QQ).

    ``sring`` would find the same ring by expanding every expression first; building the
    elements by ring arithmetic from the expression tree is several times faster.
    """
    gens = sorted(set().union(*(e.free_symbols for e in exprs)), key=default_sort_key)
    integral = all(r.is_Integer for e in exprs for r in e.atoms(Rational))
    R = ring(gens, ZZ if integral else QQ)[0] if gens else None
    if R is None:
        raise GeneratorsError("no symbols")
    index = dict(zip(R.symbols, R.gens, strict=True))
    return [_ring_element(R, index, e) for e in exprs]


def _ring_element(R: Any, index: dict, e: Expr) -> Any:
    """The polynomial expression ``e`` as an element of ``R``, by ring arithmetic on its tree
    (:func:`screwsym.algebra.rings.tree_to_ring`); ``CoercionFailed`` for anything that is
    not a polynomial in ``R``'s symbols over its domain."""
    try:
        return tree_to_ring(e, R, index)
    except NotInRing as error:
        raise CoercionFailed(str(error)) from None


def _pulled(P) -> Expr:
    """The polynomial ``P`` (a ring element) as content times monomial times the rest.

    What ``factor_terms`` does for an expanded polynomial, read off the ring
    element instead of rediscovered from the expression (several times cheaper).
    """
    ring = P.ring
    if not P:
        return S.Zero
    content, rest = P.primitive()
    low = monomial_min(*rest.itermonoms())
    if any(low):
        rest = rest.quo_term((low, ring.domain.one))
    monomial = Mul(*(g**k for g, k in zip(ring.symbols, low, strict=True)))
    return ring.domain.to_sympy(content) * monomial * rest.as_expr()


def _has_denominator(e: Expr) -> bool:
    """Whether ``e`` divides by something with symbols (a negative power of such a base)."""
    return any(p.exp.is_negative and p.base.free_symbols for p in e.atoms(Pow))


def _factored(den: Expr) -> Expr:
    """A small denominator factored (``cancel`` leaves it expanded), a large one as it is."""
    if den.is_Add and _size(den, FACTOR_SIZE) <= FACTOR_SIZE:
        try:
            return factor(den)
        except PolynomialError:  # pragma: no cover
            return den
    return den


def _inside(e: Expr) -> Expr:
    """``e`` with the arguments of its roots and functions tidied (the rational layer kept)."""
    if e.is_Atom:
        return e
    if isinstance(e, (Add, Mul)):
        args = [_inside(a) for a in e.args]
        return e if all(a is b for a, b in zip(args, e.args, strict=True)) else e.func(*args)
    if isinstance(e, Pow):
        if e.exp.is_Integer:
            base = _inside(e.base)
            return e if base is e.base else Pow(base, e.exp)
        return Pow(_rewrite(e.base) if e.base.free_symbols else e.base, e.exp)
    if isinstance(e, Piecewise):
        return Piecewise(*((_rewrite(v) if isinstance(v, Expr) else v, c) for v, c in e.args))
    if isinstance(e, Application):
        return e.func(*(_rewrite(a) if isinstance(a, Expr) else a for a in e.args))
    return e


# --------------------------------------------------------------------------
# Helpers of the core operations: their tidy= flag (the conds="piecewise"
# machinery is screwsym.core.conditions).
# --------------------------------------------------------------------------


def finish(value: Any, flag: bool = True) -> Any:
    """``value`` tidied when ``flag`` is set: the core operations' ``tidy=``.

    :func:`tidy` without its input checks and options, for results the core
    built itself.

    >>> from sympy import symbols
    >>> x = symbols("x", real=True)
    >>> finish((x**2 - 1) / (x - 1)), finish((x**2 - 1) / (x - 1), False)
    (x + 1, (x**2 - 1)/(x - 1))
    """
    return _tidy_any(value, MAX_SIZE) if flag else value


def is_polynomial(e: Expr) -> bool:
    """Whether ``e`` has no symbolic denominator (a cancelled quotient is then a polynomial).

    >>> from sympy import symbols
    >>> x, y = symbols("x y", real=True)
    >>> is_polynomial(x * y + 1), is_polynomial(x / y)
    (True, False)
    """
    return not _has_denominator(e)


def moment_minus(S0: Any, h: Expr, S: Any) -> Any:
    """``S0 - h S``, tidied: the moment of a screw's axis (1.36).

    In full when ``h`` is a polynomial; else entry by entry only with common
    factors pulled out, since with ``h = N/D`` in lowest terms the single
    fractions ``(S0 D - N S)/D`` only grow (and proving so costs a gcd per entry).

    >>> from sympy import ImmutableMatrix, symbols
    >>> h = symbols("h", real=True)
    >>> moment_minus(ImmutableMatrix([h, 0, 1]), h, ImmutableMatrix([1, 0, 0])).T
    Matrix([[0, 0, 1]])
    """
    value = S0 - h * S
    if is_polynomial(h):
        return finish(value)
    return value.applyfunc(
        lambda e: e if e.is_Atom or e.has(Float) else _smallest([e, _common_factor(e)])
    )


def _count_ops(expr: Expr) -> int:
    """SymPy's ``count_ops(expr)`` (not visual) for an expression, counted in integers.

    The same walk as ``sympy.core.function.count_ops``, step by step; where SymPy
    collects a symbol per operation (``ADD``, ``MUL``, ``NEG``, ...) into a sum and
    then adds up the coefficients, this adds the counts directly (``SUB - ADD`` is
    ``+1 - 1``).  The result is the same number, without building that sum.
    """
    n = 0
    args = [expr]
    while args:
        a = args.pop()
        if a.is_Rational:
            if a is not S.One:
                n += (a.p < 0) + (a.q != 1)
                continue
        elif a.is_Mul or a.is_MatMul:
            if _coeff_isneg(a):
                n += 1
                a = a.as_two_terms()[1] if a.args[0] is S.NegativeOne else -a
            num, den = fraction(a)
            if num.is_Integer:
                n += 2 if num < 0 else 1
                args.append(den)
                continue
            if den is not S.One:
                if not den.is_Integer:
                    args.append(den)
                n += 1
                args.append(num)
                continue
        elif a.is_Add or a.is_MatAdd:
            aargs = a.args
            negs = 0
            for i, ai in enumerate(aargs):
                if _coeff_isneg(ai):
                    negs += 1
                    args.append(-ai)
                else:
                    args.append(ai)
                if i > 0:
                    n += 1
            if negs == len(aargs):
                n += 1
            continue
        if a.is_Pow and a.exp is S.NegativeOne:
            n += 1
            args.append(a.base)
            continue
        if a == S.Exp1:
            n += 1
            continue
        if a.is_Pow and a.base == S.Exp1:
            n += 1
            args.append(a.exp)
            continue
        if a.is_Mul or isinstance(a, LatticeOp):
            n += len(a.args) - 1
        elif a.args and (a.is_Pow or a.is_Function or isinstance(a, (Derivative, Integral, Sum))):
            n += 1
        if not a.is_Symbol:
            args.extend(a.args)
    return n
