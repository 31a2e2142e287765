r"""Line vectors and the geometry of lines: Sections 1.2, 1.3 and 1.4.1.

A line is given by its Plücker coordinates ``(S; S0)`` in the book's ray
order: a direction ``S != 0`` and the moment ``S0 = r x S`` of the line about
the origin, for any point ``r`` of it (1.8, 1.9), so that ``S . S0 = 0``
(1.10).  The same pair is a *line vector* (Section 1.4.1): a force on its
line of action, or an angular velocity about its axis.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from sympy import Abs, Expr, ImmutableMatrix, atan2, sign, sqrt

from ._decide import is_zero, is_zero_vector
from ._validation import check_line_parts, check_screw, check_vector
from .screw import (
    Screw,
    ScrewLike,
    VectorLike,
    _axis_moment,
    _pitch_formula,
    _require_axis,
    foot,
    reciprocal_product,
)

__all__ = [
    "LineVector",
    "CommonNormal",
    "contains",
    "mutual_moment",
    "is_coplanar",
    "common_normal",
]

LineLike = Any  # a LineVector, a screw whose parts make a line, or a 6-vector


class LineVector(Screw):
    r"""A line vector ``(S; S0)`` with ``S != 0`` and ``S . S0 = 0`` (1.10, 1.28).

    Explanation
    ===========

    Constructing one whose ``S . S0`` is provably non-zero, or whose ``S`` is
    provably zero, raises ``ValueError``; symbolic cases that cannot be
    decided are accepted.  ``(S; S0)`` and ``(lambda S; lambda S0)``,
    ``lambda != 0``, are the same line (homogeneity).

    Examples
    ========

    >>> from screwsym import LineVector
    >>> L = LineVector.through([1, 0, 0], [1, 1, 0])      # (1.1), (1.9)
    >>> L
    LineVector([0, 1, 0], [0, 0, 1])
    >>> L.foot.T, L.contains([1, 5, 0])
    (Matrix([[1, 0, 0]]), True)
    >>> LineVector([1, 0, 0], [1, 0, 0])
    Traceback (most recent call last):
    ...
    ValueError: S, S0: a line vector needs S.S0 = 0 (1.10), got S.S0 = 1
    """

    __slots__ = ()

    @classmethod
    def _check_parts(cls, S: ImmutableMatrix, S0: ImmutableMatrix) -> None:
        check_line_parts(S, S0, cls._part_names)

    @classmethod
    def through(cls, A: VectorLike, B: VectorLike) -> LineVector:
        r"""The line through the points ``A`` and ``B``, directed from A to B.

        ``S = B - A`` (1.1) and ``S0 = A x S`` (1.9).

        >>> from screwsym import LineVector, vector
        >>> A, B = vector("A"), vector("B")
        >>> L = LineVector.through(A, B)
        >>> L.S.T
        Matrix([[-A_x + B_x, -A_y + B_y, -A_z + B_z]])
        """
        A = check_vector(A, "A")
        B = check_vector(B, "B")
        if is_zero_vector(B - A) is True:
            raise ValueError(f"A, B: expected two distinct points, got A = B = {list(A)}")
        return cls.from_point(A, B - A)

    @classmethod
    def from_point(cls, r: VectorLike, S: VectorLike) -> LineVector:
        r"""The line through the point ``r`` along ``S``: ``(S; r x S)`` (1.9).

        >>> from screwsym import LineVector
        >>> LineVector.from_point([0, 0, 1], [1, 0, 0])      # Fig. 1.5: (1 0 0; 0 1 0)
        LineVector([1, 0, 0], [0, 1, 0])
        """
        r = check_vector(r, "r")
        S = check_vector(S, "S")
        return cls(S, r.cross(S))

    def contains(self, point: VectorLike) -> bool | None:
        """Whether ``point`` lies on the line (1.8); see :func:`contains`."""
        return contains(self, point)

    def mutual_moment(self, other: LineLike) -> Expr:
        """The mutual moment with ``other`` (1.23); see :func:`mutual_moment`."""
        return mutual_moment(self, other)

    def is_coplanar(self, other: LineLike) -> bool | None:
        """Whether the two lines are coplanar (1.27); see :func:`is_coplanar`."""
        return is_coplanar(self, other)

    def common_normal(self, other: LineLike) -> CommonNormal:
        """The common normal to ``other`` (Fig. 1.3); see :func:`common_normal`."""
        return common_normal(self, other)


def contains(s: ScrewLike, point: VectorLike) -> bool | None:
    r"""Whether ``point`` lies on the line, or on the axis of the screw.

    Tests the line equation ``r x S = S0`` (1.8), or for a screw the axis
    equation ``r x S = S0 - h S`` (1.36).  True, False, or None when the
    symbols do not decide.

    >>> from screwsym import LineVector, contains
    >>> L = LineVector.through([0, 0, 0], [1, 1, 1])
    >>> contains(L, [2, 2, 2]), contains(L, [1, 0, 0])
    (True, False)
    """
    s = check_screw(s, "s")
    r = check_vector(point, "point")
    _require_axis(s, "foot point")  # a couple's axis is at infinity
    return is_zero_vector(r.cross(s.S) - _axis_moment(s, _pitch_formula(s)))


def mutual_moment(l1: LineLike, l2: LineLike) -> Expr:
    r"""The mutual moment of two lines, ``M = S1 . S02 + S2 . S01`` (1.23).

    It is the reciprocal product (1.45) of the two line vectors; for unit
    directions it equals ``-a12 sin(alpha12)`` (1.25), with ``a12`` and
    ``alpha12`` from :func:`common_normal`.

    >>> from screwsym import LineVector, mutual_moment
    >>> x_axis = LineVector.from_point([0, 0, 0], [1, 0, 0])
    >>> mutual_moment(x_axis, LineVector.from_point([0, 0, 2], [0, 1, 0]))
    -2
    """
    return reciprocal_product(check_screw(l1, "l1", LineVector), check_screw(l2, "l2", LineVector))


def is_coplanar(l1: LineLike, l2: LineLike) -> bool | None:
    r"""Whether two lines are coplanar (intersect or are parallel): ``M = 0`` (1.27).

    >>> from screwsym import LineVector, is_coplanar
    >>> x_axis = LineVector.from_point([0, 0, 0], [1, 0, 0])
    >>> is_coplanar(x_axis, LineVector.from_point([5, 0, 0], [0, 1, 1]))
    True
    """
    return is_zero(mutual_moment(l1, l2))


class CommonNormal(NamedTuple):
    """The common normal of two lines (Fig. 1.3), as returned by :func:`common_normal`."""

    #: the distance a12 >= 0 between the lines along the normal
    a12: Expr
    #: the unit vector of the normal, pointing from line 1 to line 2
    normal: ImmutableMatrix
    #: the twist angle from S1 to S2, measured right-handedly about ``normal``
    alpha12: Expr
    #: the foot of the normal on line 1
    foot1: ImmutableMatrix
    #: the foot of the normal on line 2
    foot2: ImmutableMatrix

    def _repr_latex_(self) -> str:
        r"""LaTeX for Jupyter, in the book's symbols (Fig. 1.3).

        >>> from screwsym import LineVector, common_normal
        >>> cn = common_normal(LineVector([1, 0, 0], [0, 0, 0]), LineVector([0, 1, 0], [-2, 0, 0]))
        >>> print(cn._repr_latex_())
        $\displaystyle a_{12} = 2,\quad \mathbf{a}_{12} = \left[\begin{matrix}0 & 0 & 1\end{matrix}\right]^{T},\quad \alpha_{12} = \frac{\pi}{2},\quad \mathbf{r}_{1} = \left[\begin{matrix}0 & 0 & 0\end{matrix}\right]^{T},\quad \mathbf{r}_{2} = \left[\begin{matrix}0 & 0 & 2\end{matrix}\right]^{T}$
        """
        from sympy import latex

        def column(v: ImmutableMatrix) -> str:
            return latex(v.T) + "^{T}"

        parts = [
            rf"a_{{12}} = {latex(self.a12)}",
            rf"\mathbf{{a}}_{{12}} = {column(self.normal)}",
            rf"\alpha_{{12}} = {latex(self.alpha12)}",
            rf"\mathbf{{r}}_{{1}} = {column(self.foot1)}",
            rf"\mathbf{{r}}_{{2}} = {column(self.foot2)}",
        ]
        return r"$\displaystyle " + r",\quad ".join(parts) + "$"


def common_normal(l1: LineLike, l2: LineLike) -> CommonNormal:
    r"""The common normal of two lines: distance, unit normal, twist angle and feet.

    Explanation
    ===========

    The convention is the one under which (1.24) and (1.25) hold: the unit
    normal ``a12_hat`` points from line 1 to line 2, ``a12 >= 0`` is the
    distance, ``alpha12`` is measured right-handedly about ``a12_hat`` from
    ``S1`` to ``S2``, so that

        S1 x S2 = |S1| |S2| sin(alpha12) a12_hat,   S1 . S2 = |S1| |S2| cos(alpha12),
        foot2 - foot1 = a12 a12_hat,   M = -|S1| |S2| a12 sin(alpha12).

    Intersecting lines (``a12 = 0``) take ``a12_hat`` along ``S1 x S2``;
    parallel lines have ``alpha12`` equal to 0 or pi, the normal through the
    foot point of line 1, and ``foot1`` the point of line 1 nearest the
    origin.  Coincident lines have no common normal and raise ``ValueError``.
    For skew lines with symbols, ``a12`` contains ``Abs`` and the normal
    ``sign`` of ``-M``, which become numbers when the sign of ``M`` is known.

    Examples
    ========

    >>> from screwsym import LineVector, common_normal
    >>> L1 = LineVector.from_point([0, 0, 0], [1, 0, 0])
    >>> L2 = LineVector.from_point([0, 0, 2], [0, 1, 0])
    >>> cn = common_normal(L1, L2)
    >>> cn.a12, cn.normal.T, cn.alpha12, cn.foot1.T, cn.foot2.T
    (2, Matrix([[0, 0, 1]]), pi/2, Matrix([[0, 0, 0]]), Matrix([[0, 0, 2]]))

    See Also
    ========

    mutual_moment
    """
    l1 = check_screw(l1, "l1", LineVector)
    l2 = check_screw(l2, "l2", LineVector)
    S1, S2 = l1.S, l2.S
    p1, p2 = foot(l1), foot(l2)
    d = p2 - p1
    n = S1.cross(S2)
    cos_part = S1.dot(S2)
    if is_zero_vector(n) is True:  # parallel (alpha12 = 0 or pi)
        # both feet are perpendicular to the common direction, so d is the normal
        if is_zero_vector(d) is True:
            raise ValueError(f"l1, l2: coincident lines have no common normal, got {l1} and {l2}")
        a12 = sqrt(d.dot(d))
        return CommonNormal(a12, d / a12, atan2(0, cos_part), p1, p2)
    nn = n.dot(n)
    n_len = sqrt(nn)
    m = -reciprocal_product(l1, l2)  # (foot2 - foot1) . (S1 x S2), by (1.22), (1.23)
    orientation = 1 if is_zero(m) is True else sign(m)
    t1 = d.cross(S2).dot(n) / nn
    t2 = d.cross(S1).dot(n) / nn
    return CommonNormal(
        Abs(m) / n_len,
        orientation * n / n_len,
        atan2(orientation * n_len, cos_part),
        p1 + t1 * S1,
        p2 + t2 * S2,
    )
