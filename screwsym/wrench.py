r"""Wrenches: forces and couples on a rigid body, Section 1.7.

A wrench is written in the book's ray order ``(f; C_O)``: the resultant force
``f`` first, then ``C_O``, the moment of the system about the origin O
(1.55, 1.58).
"""

from __future__ import annotations

from typing import Any

from sympy import Expr, ImmutableMatrix

from ._validation import check_scalar, check_screw, check_vector
from .screw import Screw, ScrewLike, VectorLike, reciprocal_product, shift_origin
from .twist import Twist

__all__ = ["Wrench", "power"]


class Wrench(Screw):
    r"""A wrench ``(f; C_O)``: resultant force, then the moment about the origin O.

    Examples
    ========

    >>> from screwsym import Wrench
    >>> W = Wrench.force([0, 0, -10], [1, 0, 0])     # a weight acting at x = 1 (1.55)
    >>> W
    Wrench([0, 0, -10], [0, 10, 0])
    >>> W.moment_about([1, 0, 0]).T                # no moment about a point of its line
    Matrix([[0, 0, 0]])
    """

    __slots__ = ()
    _part_names = ("f", "C_O")

    @property
    def f(self) -> ImmutableMatrix:
        """The resultant force (the primary part)."""
        return self.S

    @property
    def C_O(self) -> ImmutableMatrix:
        """The moment about the origin O (the dual part)."""
        return self.S0

    @classmethod
    def force(cls, f: VectorLike, r: VectorLike) -> Wrench:
        r"""The force ``f`` acting along the line through ``r``: ``(f; r x f)`` (1.55)."""
        f = check_vector(f, "f")
        r = check_vector(r, "r")
        return cls(f, r.cross(f))

    @classmethod
    def from_axis(cls, f: Any, S: VectorLike, r: VectorLike, h: Any) -> Wrench:  # type: ignore[override]
        r"""A wrench of intensity ``f`` on the axis through ``r`` along ``S`` with pitch ``h``.

        ``f (S; S^0) = (f S; f (r x S + h S)) = (f_vec; r x f_vec + h f_vec)``
        (1.57, 1.58): a force ``f S`` on the axis plus the parallel couple
        ``C = h f S``.  With ``r`` = 0 (origin on the axis) the dual part is the
        couple alone (1.57).

        >>> Wrench.from_axis(2, [0, 0, 1], [0, 0, 0], 3)
        Wrench([0, 0, 2], [0, 0, 6])
        """
        f = check_scalar(f, "f")
        unit = Screw.from_axis(r, S, h)
        return cls(f * unit.S, f * unit.S0)

    def moment_about(self, point: VectorLike) -> ImmutableMatrix:
        r"""The moment of the wrench about ``point``: ``C_A = C_O - A x f`` (1.32)."""
        return shift_origin(self, check_vector(point, "point")).S0


def power(twist: ScrewLike, wrench: ScrewLike) -> Expr:
    r"""The power of a wrench on a body moving with a twist: ``omega . C_O + f . v_O``.

    It is the reciprocal product (1.45) of the twist and the wrench; it does
    not depend on the origin (1.47).  Zero power means the two are reciprocal.

    >>> from screwsym import Twist, Wrench, power
    >>> power(Twist.translation([1, 0, 0]), Wrench.force([3, 0, 0], [0, 0, 0]))
    3
    """
    return reciprocal_product(
        check_screw(twist, "twist", Twist), check_screw(wrench, "wrench", Wrench)
    )
