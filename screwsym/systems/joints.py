r"""Kinematic pairs: each joint is the screw system of the unit twists it allows.

The book's lower pairs and the two compound ones used in its examples:
:class:`Revolute` (R), :class:`Prismatic` (P), :class:`Helical` (H),
:class:`Cylindrical` (C), :class:`Universal` (U) and :class:`Spherical` (S), and the
parallelogram four-bar as one compound pair, :class:`Parallelogram` (Pa).
The one-letter names are aliases in this module (``from screwsym.systems.joints
import R, P, S``); they are not exported by ``screwsym``, where ``S`` would
shadow SymPy's ``S``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from sympy import ImmutableMatrix

from ..core.basic import ScrewsymBasic
from ..core.checks import check_exact, check_nonzero_vector, check_scalar, check_vector
from ..core.decide import is_zero_vector
from ..core.screw import ScalarLike, VectorLike
from ..core.twist import Twist
from .screw_system import ScrewSystem

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = [
    "Joint", "Revolute", "Prismatic", "Helical", "Cylindrical", "Universal", "Spherical",
    "Parallelogram",
]

#: the unit axes x, y, z (a spherical joint's rotations; the mechanism's pure translations)
_E = ([1, 0, 0], [0, 1, 0], [0, 0, 1])


def _axis(value: Any, name: str) -> ImmutableMatrix:
    return check_exact(
        check_nonzero_vector(value, name, "a joint axis needs a non-zero direction"), name
    )


def _point(value: Any, name: str) -> ImmutableMatrix:
    return check_exact(check_vector(value, name), name)


def _rotation(point: ImmutableMatrix, direction: ImmutableMatrix) -> Twist:
    """The unit-rate rotation about the line through ``point`` along ``direction`` (1.48)."""
    return Twist.rotation(direction, point=point)


class Joint(ScrewsymBasic):
    """A kinematic pair: the screw system of the unit twists it allows.

    Subclasses: :class:`Revolute`, :class:`Prismatic`, :class:`Helical`, :class:`Cylindrical`, :class:`Universal`,
    :class:`Spherical`.  ``freedom`` is the number of joint variables (f_i).
    """

    __slots__ = ()
    freedom: int = 0

    @property
    def twists(self) -> ScrewSystem:
        """The joint's twists, one per freedom, as a :class:`~screwsym.systems.screw_system.ScrewSystem`."""
        return ScrewSystem(*self._twists())

    def _twists(self) -> list[Twist]:  # pragma: no cover - every subclass defines it
        raise NotImplementedError

    def _accelerations(self) -> list[Twist | None]:
        """The second derivative of the joint's displacement, beyond its exponentials.

        A lower pair moves by ``exp6(X_1 q_1) ... exp6(X_k q_k)`` (the axes in the
        order of :meth:`_twists`): nothing beyond, ``None`` per freedom.  A
        compound pair whose path is no exponential (:class:`Parallelogram`) gives
        the derivative of its spatial twist along the path, at rest.
        """
        return [None] * self.freedom


class Revolute(Joint):
    """Revolute joint: rotation about the line through ``point`` along ``direction``.

    >>> from screwsym.systems.joints import Revolute
    >>> Revolute([1, 0, 0], [0, 0, 1]).twists
    ScrewSystem(Twist([0, 0, 1], [0, -1, 0]))
    """

    __slots__ = ()
    freedom = 1

    def __new__(cls, point: VectorLike, direction: VectorLike) -> Self:
        return ScrewsymBasic.__new__(
            cls, _point(point, "point"), _axis(direction, "direction")
        )

    def _twists(self) -> list[Twist]:
        return [_rotation(*self.args)]


class Prismatic(Joint):
    """Prismatic joint: translation along ``direction``, the twist ``(0; direction)``.

    >>> from screwsym.systems.joints import Prismatic
    >>> Prismatic([0, 0, 1]).twists
    ScrewSystem(Twist([0, 0, 0], [0, 0, 1]))
    """

    __slots__ = ()
    freedom = 1

    def __new__(cls, direction: VectorLike) -> Self:
        return ScrewsymBasic.__new__(cls, _axis(direction, "direction"))

    def _twists(self) -> list[Twist]:
        return [Twist.translation(self.args[0])]


class Helical(Joint):
    """Helical joint: the screw motion of ``pitch`` about the line (point, direction) (1.52).

    >>> from screwsym.systems.joints import Helical
    >>> Helical([0, 0, 0], [0, 0, 1], 2).twists
    ScrewSystem(Twist([0, 0, 1], [0, 0, 2]))
    """

    __slots__ = ()
    freedom = 1

    def __new__(cls, point: VectorLike, direction: VectorLike, pitch: ScalarLike) -> Self:
        return ScrewsymBasic.__new__(
            cls,
            _point(point, "point"),
            _axis(direction, "direction"),
            check_exact(check_scalar(pitch, "pitch"), "pitch"),
        )

    def _twists(self) -> list[Twist]:
        r, u, h = self.args
        return [Twist.screw_motion(u, point=r, pitch=h)]


class Cylindrical(Joint):
    """Cylindrical joint: rotation about and translation along one line (2 freedoms).

    >>> from screwsym.systems.joints import Cylindrical
    >>> Cylindrical([1, 0, 0], [0, 0, 1]).twists
    ScrewSystem(Twist([0, 0, 1], [0, -1, 0]), Twist([0, 0, 0], [0, 0, 1]))
    """

    __slots__ = ()
    freedom = 2

    def __new__(cls, point: VectorLike, direction: VectorLike) -> Self:
        return ScrewsymBasic.__new__(
            cls, _point(point, "point"), _axis(direction, "direction")
        )

    def _twists(self) -> list[Twist]:
        r, u = self.args
        return [_rotation(r, u), Twist.translation(u)]


class Universal(Joint):
    """Universal (Hooke) joint: rotations about two axes through ``point`` (2 freedoms).

    ``dir1`` is the axis fixed in the link nearer the base, ``dir2`` the other.

    >>> from screwsym.systems.joints import Universal
    >>> Universal([0, 0, 1], [1, 0, 0], [0, 1, 0]).twists
    ScrewSystem(Twist([1, 0, 0], [0, 1, 0]), Twist([0, 1, 0], [-1, 0, 0]))
    >>> Universal([0, 0, 1], [1, 0, 0], [2, 0, 0])
    Traceback (most recent call last):
    ...
    ValueError: dir2: a universal joint needs two non-parallel axes, got dir1 = [1, 0, 0] and dir2 = [2, 0, 0] (parallel: that is one revolute joint)
    """

    __slots__ = ()
    freedom = 2

    def __new__(cls, point: VectorLike, dir1: VectorLike, dir2: VectorLike) -> Self:
        u1, u2 = _axis(dir1, "dir1"), _axis(dir2, "dir2")
        if is_zero_vector(u1.cross(u2)) is True:
            # parallel axes through one point are one revolute joint: every mobility built
            # on it would count a freedom too many
            raise ValueError(
                f"dir2: a universal joint needs two non-parallel axes, got dir1 = {list(u1)} "
                f"and dir2 = {list(u2)} (parallel: that is one revolute joint)"
            )
        return ScrewsymBasic.__new__(cls, _point(point, "point"), u1, u2)

    def _twists(self) -> list[Twist]:
        r, u1, u2 = self.args
        return [_rotation(r, u1), _rotation(r, u2)]


class Spherical(Joint):
    """Spherical joint: the three rotations about the axes x, y, z through ``point``.

    >>> from screwsym.systems.joints import Spherical
    >>> Spherical([0, 0, 1]).twists.rank
    3
    """

    __slots__ = ()
    freedom = 3

    def __new__(cls, point: VectorLike) -> Self:
        return ScrewsymBasic.__new__(cls, _point(point, "point"))

    def _twists(self) -> list[Twist]:
        return [_rotation(self.args[0], ImmutableMatrix(e)) for e in _E]


class Parallelogram(Joint):
    r"""A four-bar parallelogram as one compound pair: its output bar translates (1 freedom).

    Explanation
    ===========

    The input bar, fixed in the link nearer the base, carries the pivots
    ``p1`` and ``p2``; two equal rods run from them to the output bar's pivots
    ``q1`` and ``q2 = q1 + p2 - p1``.  The four revolute axes are normal to the
    parallelogram's plane, along ``n = (p2 - p1) x (q1 - p1)``.  Turning the rods
    about ``n`` at unit rate (an angular velocity ``n``, not a unit vector)
    carries the output bar on a *circular translation*: its instantaneous twist
    is the translation ``(0; n x (q1 - p1))``, and its displacement after the
    angle ``phi`` is the translation by ``(Rot(n, |n| phi) - I)(q1 - p1)``,
    whose second derivative at rest, ``n x (n x (q1 - p1))``, the second-order
    analysis of :class:`~screwsym.systems.linkage.Mechanism` uses.  The pair is
    the loop of :func:`Parallelogram.links` closed on itself (the tests show
    the same twist system both ways).

    Examples
    ========

    >>> from screwsym.systems.joints import Parallelogram
    >>> Parallelogram([0, 0, 0], [1, 0, 0], [0, 0, 2]).twists
    ScrewSystem(Twist([0, 0, 0], [-4, 0, 0]))
    """

    __slots__ = ()
    freedom = 1

    def __new__(cls, p1: VectorLike, p2: VectorLike, q1: VectorLike) -> Self:
        a, b, c = _point(p1, "p1"), _point(p2, "p2"), _point(q1, "q1")
        if is_zero_vector(b - a) is True:
            raise ValueError("p2: the input bar needs two distinct pivots, got p2 = p1")
        if is_zero_vector((b - a).cross(c - a)) is True:
            raise ValueError(
                "q1: the rod must not be parallel to the bar (a flat parallelogram has no "
                "plane; build it link by link with Mechanism), got q1 - p1 parallel to p2 - p1"
            )
        return ScrewsymBasic.__new__(cls, a, b, c)

    @property
    def normal(self) -> ImmutableMatrix:
        """The axes' common direction ``n = (p2 - p1) x (q1 - p1)``."""
        p1, p2, q1 = self.args
        return ImmutableMatrix((p2 - p1).cross(q1 - p1))

    def _twists(self) -> list[Twist]:
        p1, _, q1 = self.args
        return [Twist.translation(self.normal.cross(q1 - p1))]

    def _accelerations(self) -> list[Twist | None]:
        p1, _, q1 = self.args
        n = self.normal
        return [Twist.translation(n.cross(n.cross(q1 - p1)))]

    def links(self, a: Any = "a", b: Any = "b", rods: tuple[Any, Any] = ("rod1", "rod2")) -> list:
        """The same loop as ``(link_a, link_b, joint)`` triples of four revolutes, for
        :class:`~screwsym.systems.linkage.Mechanism`: ``a`` holds the input bar, ``b`` the output.

        >>> from screwsym.systems.joints import Parallelogram
        >>> [(x, y) for x, y, _ in Parallelogram([0, 0, 0], [1, 0, 0], [0, 0, 2]).links()]
        [('a', 'rod1'), ('rod1', 'b'), ('a', 'rod2'), ('rod2', 'b')]
        """
        p1, p2, q1 = self.args
        n, q2 = self.normal, q1 + p2 - p1
        r1, r2 = rods
        return [(a, r1, Revolute(p1, n)), (r1, b, Revolute(q1, n)),
                (a, r2, Revolute(p2, n)), (r2, b, Revolute(q2, n))]


def check_joints(joints: tuple[Any, ...], name: str) -> tuple[Joint, ...]:
    if not joints:
        raise ValueError(f"{name}: expected at least one joint, got none")
    for i, j in enumerate(joints):
        if not isinstance(j, Joint):
            raise TypeError(
                f"{name}[{i}]: expected a joint (Revolute, Prismatic, Helical, Cylindrical, Universal or Spherical), got {type(j).__name__}"
            )
    return joints


# The book's one-letter names (R, P, H, C, U, S), kept here and not exported: ``S`` would
# shadow SymPy's ``S`` under ``from sympy import *; from screwsym import *``.
R = Revolute
P = Prismatic
H = Helical
C = Cylindrical
U = Universal
S = Spherical
Pa = Parallelogram
