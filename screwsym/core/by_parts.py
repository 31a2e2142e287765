r"""Zero decisions by an expression's parts, for entries too large to expand.

Explanation
===========

:func:`screwsym.core.decide.is_zero` expands and factors; on ``(a + b + c + d)**40``
that is a polynomial of 12,341 terms to factor (minutes).  Here the structure is used
first, exactly: ``x**n`` (``n > 0`` an integer) is zero exactly when ``x`` is, a product
exactly when a factor is; and an entry whose expansion would have more than ``LARGE``
terms (:func:`expanded_terms`, read off the tree) is shown *not identically zero* by its
value at an integer point (:func:`nonzero_somewhere`), instead of factored.  Used by
:func:`screwsym.core.screw.pitch` to ask whether a direction vanishes.
"""

from __future__ import annotations

import math

from sympy import Expr, ImmutableMatrix

from .decide import is_zero, is_zero_vector

__all__ = ["is_zero_by_parts", "is_zero_vector_by_parts", "nonzero_somewhere", "expanded_terms", "LARGE"]


def is_zero_by_parts(e: Expr) -> bool | None:
    """:func:`is_zero` of ``e`` through its structure first: ``x**n`` (``n > 0`` an integer) is
    zero exactly when ``x`` is, a product exactly when a factor is; the parts, not the
    expanded whole, are decided (``(a + b + c + d)**40`` is ``a + b + c + d``, not a
    polynomial of 12,341 terms to factor).

    >>> from sympy import symbols
    >>> from screwsym.core.by_parts import is_zero_by_parts
    >>> a, b = symbols("a b", real=True)
    >>> is_zero_by_parts((a + b)**40 * (a - a)), is_zero_by_parts((a**2 + 1)**40)
    (True, False)
    """
    if e.is_Pow and e.exp.is_Integer and e.exp > 0:
        return is_zero_by_parts(e.base)
    if e.is_Mul:
        parts = [is_zero_by_parts(f) for f in e.args]
        if any(p is True for p in parts):
            return True
        return False if all(p is False for p in parts) else None
    if expanded_terms(e) > LARGE and nonzero_somewhere(e):
        return None  # not identically zero; whether it is zero somewhere is not decided
    return is_zero(e)


#: an entry whose expansion would have more terms than this is not expanded to decide it
LARGE = 2000


def expanded_terms(e: Expr) -> int:
    """An upper bound on the number of terms of ``expand(e)``, from its tree (not expanding).

    >>> from sympy import symbols
    >>> from screwsym.core.by_parts import expanded_terms
    >>> a, b, c, d = symbols("a b c d")
    >>> expanded_terms((a + b + c + d)**40)
    12341
    """
    if e.is_Add:
        return sum(expanded_terms(a) for a in e.args)
    if e.is_Mul:
        return math.prod(expanded_terms(a) for a in e.args)
    if e.is_Pow and e.exp.is_Integer and e.exp > 1 and e.base.is_Add:
        k = expanded_terms(e.base)
        return math.comb(int(e.exp) + k - 1, k - 1) if k < 10**6 and e.exp < 10**6 else 10**9
    return 1


def nonzero_somewhere(e: Expr) -> bool:
    """Whether the rational function ``e`` of plain symbols is non-zero at a point: then it is
    not identically zero (a non-zero polynomial vanishes on no open set, nor on all integers).

    Exact arithmetic at small integers (negative for a symbol declared negative), instead of
    expanding ``e``: ``(a + b + c + d)**40 + 1`` is one number to compute, not 12,341 terms
    to factor.  A symbol declared zero, or not a plain symbol, gives False (not decided here).

    >>> from sympy import symbols
    >>> from screwsym.core.by_parts import nonzero_somewhere
    >>> a, b = symbols("a b", real=True)
    >>> nonzero_somewhere((a + b)**40 + 1), nonzero_somewhere((a + b)**2 - a**2 - 2*a*b - b**2)
    (True, False)
    """
    symbols = sorted(e.free_symbols, key=str)
    if not symbols or any(not x.is_Symbol or x.is_zero for x in symbols) or not e.is_rational_function():
        return False
    for shift in (0, 11):
        point = {x: (-1 if x.is_negative else 1) * (2 + shift + 3 * i) for i, x in enumerate(symbols)}
        value = e.xreplace(point)
        if value.is_Rational and value != 0:
            return True
    return False


def is_zero_vector_by_parts(S: ImmutableMatrix) -> bool | None:
    """:func:`is_zero_vector` of ``S``, number entries first and each entry by its parts."""
    entries = ImmutableMatrix(sorted(S, key=lambda e: not e.is_number))
    return is_zero_vector(entries, decide=is_zero_by_parts)


