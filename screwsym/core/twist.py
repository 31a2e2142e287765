r"""Twists: the instantaneous motion of a rigid body, Section 1.6.

A twist is written in the book's ray order ``(omega; v_O)``: the angular
velocity ``omega`` first, then ``v_O``, the velocity of the body point that
momentarily coincides with the origin O (1.51, 1.53).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from sympy import ImmutableMatrix, zeros

from .checks import check_flag, check_nonzero_vector, check_vector
from .formulas import dual_part
from .screw import ScalarLike, Screw, VectorLike, shift_origin_unchecked

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["Twist"]


class Twist(Screw):
    r"""A twist ``(omega; v_O)``: angular velocity, then the velocity of the point at O.

    It builds with the constructors every kind has (``Twist(omega, v_O)``,
    :meth:`~screwsym.core.screw.Screw.from_axis` with the angular speed as
    ``magnitude=``, :meth:`~screwsym.core.screw.Screw.from_matrix`, ...) and with
    the book's sugar, whose first argument is the motion's vector and every
    later vector a keyword: :meth:`rotation`, :meth:`translation`,
    :meth:`screw_motion`.  A twist and a wrench never add.

    Examples
    ========

    >>> from screwsym import Twist
    >>> from sympy import symbols
    >>> w = symbols("omega", real=True)
    >>> t = Twist.rotation([0, 0, w], point=[1, 0, 0])      # (1.48)
    >>> t
    Twist([0, 0, omega], [0, -omega, 0])
    >>> t.velocity_at([1, 0, 0]).T                      # a point on the axis stays still
    Matrix([[0, 0, 0]])
    """

    __slots__ = ()
    _part_names = ("omega", "v_O")
    _kind: ClassVar[str | None] = "twist"

    if TYPE_CHECKING:
        # a twist's algebra closes: a sum with another screw, a multiple and a quotient are
        # a twist (Screw.__add__ and __mul__ keep the kind of the operand that has one)
        def __add__(self, other: Screw) -> Self: ...
        def __sub__(self, other: Screw) -> Self: ...
        def __mul__(self, k: ScalarLike) -> Self: ...
        def __rmul__(self, k: ScalarLike) -> Self: ...
        def __truediv__(self, k: ScalarLike) -> Self: ...
        # and it splits into two of its kind, a rotation and a translation (Screw.decompose)
        def decompose(self, *, tidy: bool = True) -> tuple[Self, Self]: ...
        # a derivative is a linear combination, of the same kind (Screw._combination)
        def diff(self, *symbols: Any, **kwargs: Any) -> Self: ...

    @property
    def omega(self) -> ImmutableMatrix:
        """The angular velocity vector (the primary part)."""
        return self.S

    @property
    def v_O(self) -> ImmutableMatrix:
        """The velocity of the body point at the origin O (the dual part)."""
        return self.S0

    @classmethod
    def rotation(cls, omega: VectorLike, *, point: VectorLike) -> Self:
        r"""Rotation with angular velocity ``omega`` about the axis through ``point`` (1.48, 1.50).

        ``(omega; r x omega)`` with ``r = point``: the velocity of the body
        point at O is ``v_O = r x omega`` (1.50).  A zero ``omega`` has no axis
        and raises ``ValueError``.

        >>> Twist.rotation([0, 0, 2], point=[0, 1, 0])
        Twist([0, 0, 2], [2, 0, 0])
        """
        omega = check_nonzero_vector(omega, "omega", "a rotation needs a non-zero angular velocity")
        r = check_vector(point, "point")
        return cls(omega, dual_part(r, omega))

    @classmethod
    def translation(cls, v: VectorLike) -> Self:
        r"""Pure translation with velocity ``v``: the twist ``(0; v)`` (Section 1.6.2).

        >>> Twist.translation([1, 2, 3])
        Twist([0, 0, 0], [1, 2, 3])
        """
        return cls(zeros(3, 1), check_vector(v, "v"))

    @classmethod
    def screw_motion(cls, omega: VectorLike, *, point: VectorLike, pitch: ScalarLike) -> Self:
        r"""Screw motion: angular velocity ``omega`` about the axis through ``point``, pitch ``h`` (1.52, 1.53).

        ``(omega; r x omega + h omega)``: the body turns at ``|omega|`` and
        advances ``h`` per radian along the axis.  The same as
        ``Twist.from_axis(point, omega, pitch)``.

        >>> Twist.screw_motion([0, 0, 2], point=[0, 0, 0], pitch=3)
        Twist([0, 0, 2], [0, 0, 6])
        """
        omega = check_nonzero_vector(
            omega, "omega", "a screw motion needs a non-zero angular velocity (for a "
            "translation use Twist.translation(v))"
        )
        return cls.from_axis(point, omega, pitch)

    def velocity_at(self, point: VectorLike, *, tidy: bool = True) -> ImmutableMatrix:
        r"""The velocity of the body point at ``point``: ``v_P = v_O + omega x P``.

        This is the dual part of the twist taken about ``point`` (1.32), in
        lowest terms (``tidy=False``: as built); it holds for every value of
        the symbols.

        >>> Twist.rotation([0, 0, 1], point=[0, 0, 0]).velocity_at([1, 0, 0]).T
        Matrix([[0, 1, 0]])
        """
        return shift_origin_unchecked(self, check_vector(point, "point"), check_flag(tidy, "tidy")).S0
