"""Three-valued decisions about symbolic quantities: True, False or None.

screwsym raises or branches only on what is provable.  ``is_zero`` asks
SymPy's assumptions first; when they cannot tell, it brings the expression
to a canonical form, where a zero polynomial or rational function is
literally ``0``, and then factors what is left so that the assumptions can
prove each factor non-zero.  No ``simplify``.
"""

from __future__ import annotations

from sympy import Expr, Mul, Pow, cancel, expand, factor, fraction
from sympy.matrices import MatrixBase

__all__ = ["is_zero", "is_zero_vector"]


def _has_denominator(expr: Expr) -> bool:
    return any(p.exp.is_negative for p in expr.atoms(Pow))


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
    decided = expr.is_zero
    if decided is not None or expr.is_number:
        return decided
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


def is_zero_vector(v: MatrixBase) -> bool | None:
    """Decide whether every entry of the matrix ``v`` is zero.

    Stops at the first entry that is provably non-zero.
    """
    undecided = False
    for e in v:
        d = is_zero(e)
        if d is False:
            return False
        undecided = undecided or d is None
    return None if undecided else True
