r"""The conditions of a result on request: the machinery of ``conds="piecewise"``.

A core operation on symbols returns its *generic* result by default
(``conds="none"``): the pitch ``S . S0 / S . S`` holds where ``S != 0``, the
common normal of two lines where they are skew.  With ``conds="piecewise"``
it returns a ``Piecewise`` over the cases the symbols leave open, each value
right where its condition holds (a couple's pitch ``oo`` where ``S = 0``, the
parallel and intersecting cases of a common normal).  SymPy's ``integrate``
names the same choice ``conds=``.

This module holds what those operations share: the values of ``conds=``
(:data:`CONDS`), the condition that a column vanishes (:func:`vanishes`) and
the ``Piecewise`` of a list of cases, entry by entry for a column
(:func:`piecewise`).  Which cases an operation has, and where each holds, is
the operation's own (:func:`screwsym.core.screw.pitch`,
:func:`screwsym.core.line.common_normal`, ...).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from sympy import And, Eq, ImmutableMatrix, Piecewise
from sympy.logic.boolalg import false
from sympy.matrices import MatrixBase

__all__ = ["CONDS", "vanishes", "piecewise"]

#: the values of ``conds=``, SymPy's words (``integrate(..., conds=...)``)
CONDS = ("none", "piecewise")


def vanishes(v: Iterable[Any]) -> Any:
    """The condition that every entry of the column ``v`` is zero, as a SymPy Boolean.

    >>> from sympy import ImmutableMatrix, symbols
    >>> x, y = symbols("x y", real=True)
    >>> vanishes(ImmutableMatrix([x, 0, y]))
    Eq(x, 0) & Eq(y, 0)
    """
    return And(*(Eq(e, 0) for e in v))


def piecewise(branches: Iterable[tuple[Any, Any]], default: Any) -> Any:
    """``Piecewise`` of ``branches`` ((value, condition) pairs) then ``default``, entrywise.

    The values are expressions or columns of the same shape (an expression
    stands for a column of it); a column gives a column of ``Piecewise``.
    Branches whose condition is ``False`` drop out, and with none left the
    result is ``default`` itself.

    >>> from sympy import ImmutableMatrix, false, nan, symbols
    >>> x = symbols("x", real=True)
    >>> piecewise([(nan, vanishes([x]))], 1 / x)
    Piecewise((nan, Eq(x, 0)), (1/x, True))
    >>> piecewise([(0, x > 0), (1, false)], ImmutableMatrix([x, 2])).T
    Matrix([[Piecewise((0, x > 0), (x, True)), Piecewise((0, x > 0), (2, True))]])
    >>> piecewise([(0, false)], x)
    x
    """
    branches = [(v, c) for v, c in branches if c is not false]
    if not branches:
        return default
    if isinstance(default, MatrixBase):
        return ImmutableMatrix(
            default.shape[0], default.shape[1],
            [piecewise([(v[i] if isinstance(v, MatrixBase) else v, c) for v, c in branches],
                       default[i])
             for i in range(len(default))],
        )
    return Piecewise(*branches, (default, True))
