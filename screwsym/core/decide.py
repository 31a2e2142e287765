"""Three-valued decisions about symbolic quantities: True, False or None.

screwsym raises or branches only on what is provable.  ``is_zero`` asks
SymPy's assumptions first; when they cannot tell, it brings the expression
to a canonical form, where a zero polynomial or rational function is
literally ``0``, and then factors what is left so that the assumptions can
prove each factor non-zero.  No ``simplify``.

The float policy
================

Exact and symbolic values are decided exactly.  A quantity computed from
floating-point numbers carries rounding error, so every decision of the core
(the line condition of a constructor, ``classify``, ``pitch``,
``is_coplanar``, ``contains``, the parallel and intersecting cases of
``common_normal``; and above it the rotation check and the last row of
``Transform.from_matrix``, ``log6``'s identity and half-turn, the plots'
checks) goes through :func:`is_zero_scaled`: a float quantity
``q`` counts as zero when ``|q| <= tau * scale``, where ``scale`` is the
size the quantity would have without cancellation (``|S| |S0|`` for
``S . S0``, ``|S1| |S2|`` for ``S1 x S2``) and ``tau = 2**(13 - p)`` for
``p``-bit floats (``tau = 2**-40``, about ``9.1e-13``, for double precision).
The test is relative, so it does not change when the input is scaled by any
power of ten, and it is made in SymPy's arbitrary-exponent floats, so
``1e200`` does not overflow.  The documentation's page "Decisions and the
float policy" lists every decision with its scale.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from sympy import (
    Abs,
    Add,
    Expr,
    Float,
    Max,
    Min,
    Mul,
    Piecewise,
    Pow,
    Rational,
    Symbol,
    acot,
    atan,
    atan2,
    cancel,
    ceiling,
    cot,
    csc,
    expand,
    factor,
    floor,
    fraction,
    sec,
    sign,
    sqrt,
    tan,
    tanh,
)
from sympy.matrices import MatrixBase
from sympy.polys.domains import QQ
from sympy.polys.rings import PolyRing

from ..algebra.rings import NotInRing, tree_to_ring
from .formulas import dot

__all__ = [
    "is_zero",
    "is_zero_vector",
    "is_zero_scaled",
    "is_zero_vector_scaled",
    "is_real_where_defined",
    "float_tau",
    "norm",
]

# functions that are real wherever they are defined when their arguments are real
# (SymPy's assumptions answer None for them because of their poles)
_REAL_FUNCTIONS = (tan, cot, sec, csc, atan2, sign, floor, ceiling, Min, Max, acot, atan, tanh)


def _has_denominator(expr: Expr) -> bool:
    return any(p.exp.is_negative for p in expr.atoms(Pow))


class _NotRational(Exception):
    """A float, or a denominator that is the zero polynomial: not for :func:`_rational_parts`."""


def _generators(e: Expr) -> list[Expr]:
    """The symbols and non-rational parts of ``e``; ``b**(p/q)`` gives ``b**(1/q)``."""
    gens: dict[Expr, None] = {}
    seen: set[int] = set()
    stack = [e]
    while stack:
        x = stack.pop()
        if id(x) in seen:
            continue
        seen.add(id(x))
        if x.is_Rational:
            continue
        if x.is_Float:
            raise _NotRational
        if x.is_Add or x.is_Mul:
            stack.extend(x.args)
        elif x.is_Pow and x.exp.is_Integer:
            stack.append(x.base)
        elif x.is_Pow and x.exp.is_Rational:
            gens[Pow(x.base, Rational(1, x.exp.q))] = None
        else:
            gens[x] = None
    return list(gens)  # any fixed order: the zero polynomial is zero in every order


def _rational_parts(expr: Expr) -> tuple | None:
    """Numerator and denominator of ``expr`` as ring elements, or None (floats, no symbols).

    The numerator and the denominator are built by exact arithmetic in a sparse
    polynomial ring over QQ whose generators are the symbols, roots and
    functions of ``expr``, read off the expression tree (no ``expand``, no
    ``cancel``, no gcds).  Evaluating the generators is a ring homomorphism, so
    a zero numerator proves ``expr`` zero wherever it is defined (the standard
    of ``cancel``); a non-zero one proves nothing (the generators may be
    related: ``sqrt(x)**2 = x``), and the caller goes on.
    """
    try:
        gens = _generators(expr)
    except _NotRational:
        return None
    if not gens:
        return None
    R = PolyRing(gens, QQ, "lex")
    try:
        return tree_to_ring(expr, R, dict(zip(gens, R.gens, strict=True)), fractions=True)
    except NotInRing:
        return None


def is_zero(expr: Expr) -> bool | None:
    """Decide whether ``expr`` is zero: True, False, or None when undecided.

    The stages, cheapest first: SymPy's assumptions; ``expand`` (and
    ``cancel`` when there are denominators), which turns an identically zero
    polynomial or rational function into ``0``; and ``factor`` of the
    numerator, which is non-zero when the assumptions prove every factor
    non-zero.

    >>> from sympy import symbols
    >>> x = symbols("x", real=True)
    >>> is_zero(x**2 - x*x), is_zero(x**2 + 1), is_zero(x) is None
    (True, False, True)
    >>> is_zero((x**2 - 1)/(x - 1) - x - 1)
    True
    >>> h, l = symbols("h", nonzero=True), symbols("l", positive=True)
    >>> m = symbols("m", real=True)
    >>> is_zero(h*l**2 + h*m**2)            # h (l**2 + m**2): both factors non-zero
    False
    """
    parts = None if expr.is_Atom else _rational_parts(expr)
    if parts is not None and not parts[0]:
        return True  # before the assumptions, which are slow to find it of a large expression
    decided = expr.is_zero
    if decided is not None or expr.is_number or isinstance(expr, Symbol):
        return decided  # a symbol is its own canonical form and its only factor
    if parts is not None and all(isinstance(g, Symbol) for g in parts[0].ring.symbols):
        # a rational function of independent symbols: its numerator in lowest terms,
        # factored in the ring, is what expand, cancel and factor give (up to signs)
        numerator = parts[0].cancel(parts[1])[0]
        decisions = [f.as_expr().is_zero for f, _ in numerator.factor_list()[1]]
        if any(d is True for d in decisions):  # pragma: no cover - a symbol declared zero
            return True
        return False if all(d is False for d in decisions) else None
    canonical = expand(expr)
    if _has_denominator(canonical):
        canonical = cancel(canonical)
    if canonical == 0:
        return True
    numerator = fraction(canonical)[0]
    factors = Mul.make_args(factor(numerator))
    decisions = [f.is_zero for f in factors]
    if any(d is True for d in decisions):  # pragma: no cover - a canonical non-zero form
        return True
    return False if all(d is False for d in decisions) else None


def is_zero_vector(v: MatrixBase, decide: Callable[[Any], bool | None] | None = None
                   ) -> bool | None:
    """Decide whether every entry of the matrix ``v`` is zero.

    Stops at the first entry that is provably non-zero.  ``decide`` decides one
    entry (default :func:`is_zero`).
    """
    decide = is_zero if decide is None else decide
    undecided = False
    for e in v:
        d = decide(e)
        if d is False:
            return False
        undecided = undecided or d is None
    return None if undecided else True


def norm(v: MatrixBase) -> Expr:
    """The Euclidean length ``sqrt(v . v)`` of a column."""
    return sqrt(dot(v, v))


def float_tau(*exprs: Expr) -> Expr | None:
    """The relative tolerance of the float policy, or None when no float is involved.

    ``2**(13 - p)`` for the lowest precision ``p`` (in bits) among the floats.

    >>> from sympy import Float, Rational
    >>> float_tau(Float(1.5)) == Rational(1, 2**40), float_tau(Rational(1, 3)) is None
    (True, True)
    """
    floats = [f for e in exprs for f in e.atoms(Float)]
    if not floats:
        return None
    precision = min(f._prec for f in floats)
    return Pow(2, 13 - precision)


def is_zero_scaled(q: Expr, scale: Expr, tau: Expr | None = None) -> bool | None:
    """Decide ``q == 0`` under the float policy: relative to ``scale`` for floats, else exact.

    ``scale`` is the size ``q`` would have without cancellation; for exact
    and symbolic input it plays no part and the answer is :func:`is_zero`'s.
    ``tau`` is found from the floats in ``q`` and ``scale``; a caller that has
    made its floats exact (to compute without rounding) passes the tolerance of
    the floats it started from.

    >>> from sympy import Float
    >>> is_zero_scaled(Float("1e-17"), Float(1)), is_zero_scaled(Float("1e-17"), Float("1e-17"))
    (True, False)
    >>> is_zero_scaled(Float("1e-300"), Float("1e-300") * 3)    # scale-invariant
    False
    """
    tau = float_tau(q, scale) if tau is None else tau
    if tau is None or not (q.is_number and scale.is_number):
        return is_zero(q)
    return bool(Abs(q) <= tau * scale)


def is_zero_vector_scaled(v: MatrixBase, scale: Expr, tau: Expr | None = None) -> bool | None:
    """:func:`is_zero_scaled` for a column: its length against ``scale``."""
    tau = float_tau(*v, scale) if tau is None else tau
    if tau is None or not (all(e.is_number for e in v) and scale.is_number):
        return is_zero_vector(v)
    return bool(norm(v) <= tau * scale)


def is_real_where_defined(expr: Expr) -> bool | None:
    """Decide whether ``expr`` is real at every point where it is defined.

    SymPy's ``is_extended_real`` answers None for ``x/y`` with real ``x`` and
    ``y`` (at ``y = 0`` it is ``zoo``); screwsym's symbolic results are full
    of such quotients, which are real wherever they are defined.  This walks
    sums, products, integer powers and the functions that are real off their
    poles, and asks the assumptions about the rest.  A fractional power is
    real only of a base known to be non-negative.

    >>> from sympy import I, Symbol, sqrt
    >>> x, y = Symbol("x", real=True), Symbol("y", real=True)
    >>> is_real_where_defined(x / y), is_real_where_defined(sqrt(x)), is_real_where_defined(Symbol("z"))
    (True, None, None)
    >>> is_real_where_defined(sqrt(x**2 + y**2)), is_real_where_defined(1 + 2*I)
    (True, False)
    >>> is_real_where_defined(1 / (y * sqrt(1 + y**-2)))    # [1/y, 1, 0] normalised
    True
    """
    known = expr.is_extended_real
    if known is not None:
        return known
    if isinstance(expr, (Add, Mul)) or isinstance(expr, _REAL_FUNCTIONS):
        parts = expr.args
    elif isinstance(expr, Pow):
        if not (expr.exp.is_integer or _nonnegative_where_defined(expr.base)):
            return None
        parts = expr.args
    elif isinstance(expr, Piecewise):
        parts = [e for e, _ in expr.args]
    else:
        return None
    decisions = [is_real_where_defined(a) for a in parts]
    if all(d is True for d in decisions):
        return True
    return None


def _nonnegative_where_defined(expr: Expr) -> bool:
    """Whether ``expr`` is provably ``>= 0`` wherever it is defined (False: not proved).

    Sums and products of such terms, even integer powers of what is real where
    defined (``y**-2`` for a real ``y``: ``1 + y**-2`` under a root, from
    normalising ``[1/y, ...]``), and non-negative bases to real powers.
    """
    if expr.is_extended_nonnegative:
        return True
    if isinstance(expr, (Add, Mul)):
        return all(_nonnegative_where_defined(a) for a in expr.args)
    if isinstance(expr, Pow):
        if expr.exp.is_integer and expr.exp.is_even:
            return is_real_where_defined(expr.base) is True
        return _nonnegative_where_defined(expr.base) and is_real_where_defined(expr.exp) is True
    return False
