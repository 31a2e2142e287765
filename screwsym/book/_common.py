"""Shared building blocks of the constructions: symbols, the book's formulas written out.

Constructions call screwsym through the package (``ss.pitch``, ``ss.Screw``),
so that a replaced operation (a monkeypatched ``screwsym.pitch``) is what the
entries use.  The book's own formulas are written here independently, in
components, never by calling the library.
"""

from __future__ import annotations

from sympy import ImmutableMatrix, Matrix, Symbol, cos, sin, symbols, zeros

import screwsym as ss

__all__ = ["ss", "real", "vec", "book_cross", "book_dot", "Z3", "canonical_pair", "six",
           "placed_pair"]

Z3 = ImmutableMatrix(zeros(3, 1))


def real(names: str, **assumptions) -> tuple[Symbol, ...] | Symbol:
    """Real symbols (``symbols(names, real=True, ...)``)."""
    return symbols(names, real=True, **assumptions)


def vec(name: str) -> ImmutableMatrix:
    """A generic real 3-vector, through the library's ``vector``."""
    return ss.vector(name)


def book_cross(a, b) -> ImmutableMatrix:
    """The determinant expansion of ``a x b`` (1.11), written out in components."""
    return ImmutableMatrix(
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    )


def book_dot(a, b):
    """``a . b`` written out."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def six(s) -> ImmutableMatrix:
    """The 6x1 column of a screw, through the library."""
    return s.matrix


def stack(S, S0) -> ImmutableMatrix:
    """The book's ``(S; S0)`` as a 6x1 column, built by hand."""
    return ImmutableMatrix(Matrix.vstack(Matrix(S), Matrix(S0)))


def canonical_pair():
    """The canonical pair of unit lines (Section 1.3 of the book), via the library.

    Line 1 is the X axis; line 2 passes through ``a12 k`` along
    ``(cos alpha12, sin alpha12, 0)``.  Returns ``(L1, L2, a12, alpha12)``.
    """
    a12 = symbols("a12", positive=True)
    alpha = symbols("alpha12", real=True)
    L1 = ss.LineVector.from_axis([0, 0, 0], [1, 0, 0])
    L2 = ss.LineVector.from_axis([0, 0, a12], [cos(alpha), sin(alpha), 0])
    return L1, L2, a12, alpha


def generic_lines():
    """Two generic lines through points ``p``, ``q`` along ``u``, ``w``, via the library."""
    p, q, u, w = vec("p"), vec("q"), vec("u"), vec("w")
    return ss.LineVector.from_axis(p, u), ss.LineVector.from_axis(q, w), p, q, u, w


def placed_pair():
    """Two lines off the origin with non-unit directions, via the library.

    Line 1 passes through the generic point ``p`` along ``(k, 0, 0)``, ``k > 0``;
    line 2 through the generic point ``q`` along the generic ``w``.  Every
    statement of Section 1.3 is invariant under rotations ((1.22), (1.47)), so
    turning line 1's direction onto the X axis loses no generality, while its
    position and both lengths stay generic: a ``common_normal`` that dropped
    line 1's position or assumed unit directions would fail.  Returns
    ``(L1, L2, p, q, k, w)``.
    """
    k = symbols("k", positive=True)
    p, q, w = vec("p"), vec("q"), vec("w")
    L1 = ss.LineVector.from_axis(p, [k, 0, 0])
    return L1, ss.LineVector.from_axis(q, w), p, q, k, w


def x_axis_and_generic_line():
    """Line 1 the X axis, line 2 generic (through ``q`` along ``w``), via the library.

    Every statement of Section 1.3 is frame independent ((1.22), (1.47)), so
    placing line 1 on the X axis loses no generality; it keeps the common
    normal's radicals small enough to decide quickly.
    """
    q, w = vec("q"), vec("w")
    L1 = ss.LineVector.from_axis([0, 0, 0], [1, 0, 0])
    return L1, ss.LineVector.from_axis(q, w), q, w
