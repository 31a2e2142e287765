r"""Wrenches: forces and couples on a rigid body, Section 1.7.

A wrench is written in the book's ray order ``(f; C_O)``: the resultant force
``f`` first, then ``C_O``, the moment of the system about the origin O
(1.55, 1.58).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from sympy import Expr, ImmutableMatrix

from .checks import check_flag, check_nonzero_vector, check_vector
from .formulas import dual_part
from .screw import (
    ScalarLike,
    Screw,
    ScrewLike,
    VectorLike,
    check_screw,
    reciprocal_product_unchecked,
    shift_origin_unchecked,
)
from .twist import Twist

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["Wrench", "power"]


class Wrench(Screw):
    r"""A wrench ``(f; C_O)``: resultant force, then the moment about the origin O.

    It builds with the constructors every kind has (``Wrench(f, C_O)``,
    :meth:`~screwsym.core.screw.Screw.from_axis` with the force's size as
    ``magnitude=`` (1.57, 1.58), :meth:`~screwsym.core.screw.Screw.couple`, ...)
    and with the book's sugar :meth:`force`, whose point is a keyword.

    Examples
    ========

    >>> from screwsym import Wrench
    >>> W = Wrench.force([0, 0, -10], point=[1, 0, 0])     # a weight acting at x = 1 (1.55)
    >>> W
    Wrench([0, 0, -10], [0, 10, 0])
    >>> W.moment_about([1, 0, 0]).T                # no moment about a point of its line
    Matrix([[0, 0, 0]])
    >>> Wrench.from_axis([0, 0, 0], [0, 0, 1], 3, magnitude=2)    # (1.57)
    Wrench([0, 0, 2], [0, 0, 6])
    """

    __slots__ = ()
    _part_names = ("f", "C_O")
    _kind: ClassVar[str | None] = "wrench"

    if TYPE_CHECKING:
        # a wrench's algebra closes: a sum with another screw, a multiple and a quotient are
        # a wrench (Screw.__add__ and __mul__ keep the kind of the operand that has one)
        def __add__(self, other: Screw) -> Self: ...
        def __sub__(self, other: Screw) -> Self: ...
        def __mul__(self, k: ScalarLike) -> Self: ...
        def __rmul__(self, k: ScalarLike) -> Self: ...
        def __truediv__(self, k: ScalarLike) -> Self: ...
        # and it splits into two of its kind, a force and a couple (Screw.decompose)
        def decompose(self, *, tidy: bool = True) -> tuple[Self, Self]: ...
        # a derivative is a linear combination, of the same kind (Screw._combination)
        def diff(self, *symbols: Any, **kwargs: Any) -> Self: ...

    @property
    def f(self) -> ImmutableMatrix:
        """The resultant force (the primary part)."""
        return self.S

    @property
    def C_O(self) -> ImmutableMatrix:
        """The moment about the origin O (the dual part)."""
        return self.S0

    @classmethod
    def force(cls, f: VectorLike, *, point: VectorLike) -> Self:
        r"""The force ``f`` acting along the line through ``point``: ``(f; r x f)`` (1.55).

        A zero force has no line of action and raises ``ValueError``.

        >>> Wrench.force([1, 0, 0], point=[0, 0, 2])
        Wrench([1, 0, 0], [0, 2, 0])
        """
        f = check_nonzero_vector(f, "f", "a force needs a non-zero vector for its line of action")
        r = check_vector(point, "point")
        return cls(f, dual_part(r, f))

    def moment_about(self, point: VectorLike, *, tidy: bool = True) -> ImmutableMatrix:
        r"""The moment of the wrench about ``point``: ``C_A = C_O - A x f`` (1.32).

        In lowest terms (``tidy=False``: as built); it holds for every value of the symbols.

        >>> Wrench.force([0, 0, -10], point=[1, 0, 0]).moment_about([0, 1, 0]).T
        Matrix([[10, 10, 0]])
        """
        return shift_origin_unchecked(self, check_vector(point, "point"), check_flag(tidy, "tidy")).S0


def power(twist: ScrewLike, wrench: ScrewLike, *, tidy: bool = True) -> Expr:
    r"""The power of a wrench on a body moving with a twist: ``omega . C_O + f . v_O``.

    It is the reciprocal product (1.45) of the twist and the wrench; it does
    not depend on the origin (1.47).  Zero power means the two are reciprocal.
    It holds for every value of the symbols and comes in lowest terms
    (``tidy=False``: as built).

    >>> from screwsym import Twist, Wrench, power
    >>> power(Twist.translation([1, 0, 0]), Wrench.force([3, 0, 0], point=[0, 0, 0]))
    3
    """
    return reciprocal_product_unchecked(
        check_screw(twist, "twist", Twist), check_screw(wrench, "wrench", Wrench),
        check_flag(tidy, "tidy"),
    )
