"""Three-valued decisions about symbolic quantities: True, False or None.

screwsym raises or branches only on what is provable.  ``is_zero`` first asks
SymPy's assumptions; when they cannot tell, it rewrites the expression once
with ``cancel`` (a polynomial or rational function in canonical form is zero
exactly when it is the zero polynomial) and asks again.  No ``simplify``.
"""

from __future__ import annotations

from sympy import Expr, cancel
from sympy.matrices import MatrixBase

__all__ = ["is_zero", "is_zero_vector"]


def is_zero(expr: Expr) -> bool | None:
    """Decide whether ``expr`` is zero: True, False, or None when undecided.

    >>> from sympy import symbols
    >>> x = symbols("x", real=True)
    >>> is_zero(x**2 - x*x), is_zero(x**2 + 1), is_zero(x) is None
    (True, False, True)
    >>> is_zero((x**2 - 1)/(x - 1) - x - 1)
    True
    """
    decided = expr.is_zero
    if decided is not None or expr.is_number:
        return decided
    return cancel(expr).is_zero


def is_zero_vector(v: MatrixBase) -> bool | None:
    """Decide whether every entry of the matrix ``v`` is zero."""
    decisions = [is_zero(e) for e in v]
    if all(d is True for d in decisions):
        return True
    if any(d is False for d in decisions):
        return False
    return None
