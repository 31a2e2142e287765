r"""Twists: the instantaneous motion of a rigid body, Section 1.6.

A twist is written in the book's ray order ``(omega; v_O)``: the angular
velocity ``omega`` first, then ``v_O``, the velocity of the body point that
momentarily coincides with the origin O (1.51, 1.53).
"""

from __future__ import annotations

from typing import Any

from sympy import ImmutableMatrix, zeros

from ._validation import check_scalar, check_vector
from .screw import Screw, VectorLike, shift_origin

__all__ = ["Twist"]


class Twist(Screw):
    r"""A twist ``(omega; v_O)``: angular velocity, then the velocity of the point at O.

    Examples
    ========

    >>> from screwsym import Twist
    >>> from sympy import symbols
    >>> w = symbols("omega", real=True)
    >>> t = Twist.rotation(w, [0, 0, 1], [1, 0, 0])      # (1.48)
    >>> t
    Twist([0, 0, omega], [0, -omega, 0])
    >>> t.velocity_at([1, 0, 0]).T                      # a point on the axis stays still
    Matrix([[0, 0, 0]])
    """

    __slots__ = ()
    _part_names = ("omega", "v_O")

    @property
    def omega(self) -> ImmutableMatrix:
        """The angular velocity vector (the primary part)."""
        return self.S

    @property
    def v_O(self) -> ImmutableMatrix:
        """The velocity of the body point at the origin O (the dual part)."""
        return self.S0

    @classmethod
    def rotation(cls, omega: Any, S: VectorLike, r: VectorLike) -> Twist:
        r"""Rotation at rate ``omega`` about the axis through ``r`` along ``S`` (1.48).

        ``omega $ = (omega S; omega r x S)``; with a unit ``S``, ``omega`` is
        the angular speed.  The dual part is ``v_O = r x omega_vec`` (1.50).
        """
        omega = check_scalar(omega, "omega")
        S = check_vector(S, "S")
        r = check_vector(r, "r")
        return cls(omega * S, omega * r.cross(S))

    @classmethod
    def translation(cls, v: VectorLike) -> Twist:
        r"""Pure translation with velocity ``v``: the twist ``(0; v)`` (Section 1.6.2).

        >>> Twist.translation([1, 2, 3])
        Twist([0, 0, 0], [1, 2, 3])
        """
        return cls(zeros(3, 1), check_vector(v, "v"))

    @classmethod
    def screw_motion(cls, omega: Any, S: VectorLike, r: VectorLike, h: Any) -> Twist:
        r"""Screw motion: rotation ``omega`` about the axis (r, S) with pitch ``h`` (1.52, 1.53).

        ``omega $ = omega (S; r x S + h S) = (omega_vec; r x omega_vec + h omega_vec)``:
        the body turns at ``omega`` and advances ``h`` per radian along the axis.

        >>> Twist.screw_motion(2, [0, 0, 1], [0, 0, 0], 3)
        Twist([0, 0, 2], [0, 0, 6])
        """
        omega = check_scalar(omega, "omega")
        return omega * cls.from_axis(r, S, h)

    def velocity_at(self, point: VectorLike) -> ImmutableMatrix:
        r"""The velocity of the body point at ``point``: ``v_P = v_O + omega x P``.

        This is the dual part of the twist taken about ``point`` (1.32).

        >>> Twist.rotation(1, [0, 0, 1], [0, 0, 0]).velocity_at([1, 0, 0]).T
        Matrix([[0, 1, 0]])
        """
        return shift_origin(self, check_vector(point, "point")).S0
