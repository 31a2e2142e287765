r"""Kinematic pairs, limbs and the mobility of parallel mechanisms.

A joint is the screw system of the unit twists it allows; a limb (a serial
chain from the base to the moving platform) is the union of its joints' twist
systems, and the wrenches it transmits to the platform, its *constraints*, are
the reciprocal system.  A parallel mechanism is a platform carried by limbs:
its constraint system is the union of the limbs' constraint systems, and the
platform's instantaneous motions are the reciprocal of that.

Mobility by the modified Grübler–Kutzbach criterion (Huang, Li & Ding,
Chapters 2 and 5; Huang, Zhao & Zhao 2003, 2011)::

    M = d (n - g - 1) + sum f_i + nu - zeta,    d = 6 - lambda

with n links (base and platform included), g joints of f_i freedoms each, and,
found here from the screw systems of the k limbs (T_i the twist system of limb
i, W_i = T_i^r its constraint system, c_i = rank W_i):

- ``lambda``, the common constraints: the wrenches reciprocal to every joint
  twist of the whole mechanism, ``lambda = 6 - rank(T_1 u ... u T_k)``
  (the rank of the intersection of all W_i);
- ``nu``, the redundant constraints once the common ones are set aside:
  ``nu = sum_i (c_i - lambda) - (rank(W_1 u ... u W_k) - lambda)``;
- ``zeta``, the passive (local) freedoms: ``zeta = sum_i (f(limb i) - g_i)``,
  ``g_i`` the rank of ``T_i`` at a *generic configuration of the limb*
  (:func:`~screwsym.systems.actuation.generic_limb_rank`): joint motions that
  leave the platform at rest at every configuration of the limb (a S-S leg
  spinning about itself).  An idle motion that the limb has only here, at its
  own (serial) singularity (an R-R-R leg stretched), is a momentary *internal*
  motion: ``Mobility.internal = sum_i (g_i - rank T_i)``, which M keeps (the
  planar five-bar with a leg stretched keeps its 2 freedoms).

With these definitions M equals ``6 - rank(W_1 u ... u W_k)`` plus the
internal motions: the dimension of the platform's twist system where no limb
is at a singularity, which the tests check.  The classical count
``6 (n - g - 1) + sum f_i`` is reported beside it; it fails for
over-constrained mechanisms (the planar four-bar gives -2).

All ranks are generic in the symbols (see :mod:`screwsym.systems.screw_system`);
:meth:`ParallelMechanism.mobility_cases` splits the analysis where the rank of
the constraint system changes.  The analysis is of the free mechanism (no
joint is actuated), so the singularities it finds are *constraint*
singularities (the platform gains a freedom, as the 3-UPU and 3-RPS platforms
do in the tests).  Name the actuated joints (``Limb(*joints, actuated=i)``) for
the actuation wrenches, the Jacobian, all three kinds of singularity (limb,
actuation and constraint) and the transmission indices:
:meth:`ParallelMechanism.actuation_wrenches`, :meth:`~ParallelMechanism.jacobian`,
:meth:`~ParallelMechanism.singularities`, :meth:`~ParallelMechanism.transmission`
(:mod:`screwsym.systems.actuation`).
"""

from __future__ import annotations

import operator
import sys
from typing import TYPE_CHECKING, Any, NamedTuple, SupportsIndex, cast

from sympy import (
    Basic,
    ImmutableMatrix,
    Tuple,
)

from ..algebra.budget import BUDGET, MAX_CASES
from ..algebra.circle import trig_substitute
from ..core.basic import ScrewsymBasic
from ..core.checks import check_count, check_flag, find_string
from ..core.twist import Twist
from ..core.wrench import Wrench
from . import actuation as _actuation
from . import singularities as _singular
from ._cases import Answered, Leaf, Stage, merge_cases, split_mechanism
from ._rank_cases import case_budget, rank_on_surface
from .actuation import check_actuated, generic_limb_rank
from .joints import Joint, check_joints
from .motion_type import MotionType, motion_of, motion_on_surface
from .screw_system import ScrewSystem, basis_system, basis_with

if TYPE_CHECKING:
    from typing_extensions import Self


__all__ = ["Limb", "ParallelMechanism", "Mobility", "Degenerate"]


class Limb(ScrewsymBasic):
    """A serial chain of joints from the base to the platform.

    >>> from screwsym.systems.parallel import Limb
    >>> from screwsym.systems.joints import R, P, S
    >>> leg = Limb(R([1, 0, 0], [0, 1, 0]), P([0, 0, 1]), S([1, 0, 1]))   # R-P-S
    >>> leg.freedom, leg.twists.rank
    (5, 5)
    >>> leg.constraints          # one force through the sphere, along the R axis
    ScrewSystem(Wrench([0, 1, 0], [-1, 0, 1]))

    ``actuated`` names the driven joints, an index or a tuple of indices into
    ``joints`` (kept in ``args`` as a last ``Tuple``, so the limb stays a value):

    >>> Limb(*leg.joints, actuated=1).actuated
    (1,)
    >>> Limb(*leg.joints, actuated=5)
    Traceback (most recent call last):
    ...
    ValueError: actuated: expected indices into the limb's 3 joints (0 to 2), got 5
    """

    __slots__ = ()

    def __new__(cls, *joints: Joint, actuated: Any = None) -> Self:
        # the actuated joints are kept as a last argument, a Tuple of indices, so that
        # ``func(*args)`` rebuilds the limb (screwsym.systems.actuation.check_actuated)
        if joints and isinstance(joints[-1], Tuple):
            if actuated is not None:
                raise TypeError("actuated: given twice (as a keyword and as a last Tuple)")
            joints, actuated = joints[:-1], tuple(joints[-1])
        joints = check_joints(joints, "joints")
        if actuated is None:
            return ScrewsymBasic.__new__(cls, *joints)
        marker = Tuple(*check_actuated(actuated, len(joints)))
        return ScrewsymBasic.__new__(cls, *joints, marker)

    def _sympystr(self, printer: Any) -> str:
        inner = ", ".join(printer._print(j) for j in self.joints)
        if self.actuated:
            act = self.actuated[0] if len(self.actuated) == 1 else self.actuated
            inner += f", actuated={act}"
        return f"Limb({inner})"

    @property
    def joints(self) -> tuple[Joint, ...]:
        """The joints, base to platform."""
        args = self.args
        return args[:-1] if args and isinstance(args[-1], Tuple) else args

    @property
    def actuated(self) -> tuple[int, ...]:
        """The indices of the actuated joints (into :attr:`joints`); ``()`` if none.

        >>> from screwsym.systems.parallel import Limb
        >>> from screwsym.systems.joints import R, P, S
        >>> leg = Limb(R([1, 0, 0], [0, 1, 0]), P([0, 0, 1]), S([1, 0, 1]), actuated=1)
        >>> leg.actuated, leg.func(*leg.args) == leg
        ((1,), True)
        >>> leg
        Limb(Revolute(Matrix([
        [1],
        [0],
        [0]]), Matrix([
        [0],
        [1],
        [0]])), Prismatic(Matrix([
        [0],
        [0],
        [1]])), Spherical(Matrix([
        [1],
        [0],
        [1]])), actuated=1)
        """
        args = self.args
        if args and isinstance(args[-1], Tuple):
            return tuple(int(i) for i in args[-1])
        return ()

    @property
    def freedom(self) -> int:
        """The number of joint variables, the sum of the joints' freedoms."""
        return sum(j.freedom for j in self.joints)

    @property
    def twists(self) -> ScrewSystem:
        """The limb's twist system: every joint's twists, base to platform."""
        return ScrewSystem(*(t for j in self.joints for t in j._twists()))

    @property
    def constraints(self) -> ScrewSystem:
        """The limb's constraint (wrench) system, the reciprocal of :attr:`twists`."""
        return self.twists.reciprocal()

    @property
    def passive(self) -> int:
        """Idle motions here: ``freedom - rank`` of the twist system (generic in the symbols).

        They are passive freedoms and, at a limb singularity, momentary internal
        motions (:func:`~screwsym.systems.actuation.generic_limb_rank`,
        :attr:`Mobility.internal`).
        """
        return self.freedom - self.twists.rank


class Mobility(NamedTuple):
    """The result of :meth:`ParallelMechanism.mobility` (see the module docstring)."""

    mobility: int  #: M, by the modified Grübler–Kutzbach criterion: instantaneous (first order)
    order: int  #: d = 6 - lambda
    common: int  #: lambda, common constraints
    redundant: int  #: nu, redundant constraints
    passive: int  #: zeta, passive freedoms
    classical: int  #: 6 (n - g - 1) + sum f_i
    rotations: int  #: independent rotations of the platform
    translations: int  #: independent translations of the platform
    #: e.g. "1T2R", "3T1R", "1H" (translations, rotations, helical; :func:`motion_type`); None
    #: where the helical freedoms cannot be decided (:func:`motion_of`)
    motion: str | None
    twists: ScrewSystem  #: the platform's twist system
    links: int  #: n, base and platform included
    joints: int  #: g
    freedoms: int  #: sum f_i
    rotation_directions: ImmutableMatrix  #: 3 x rotations: independent angular velocities
    translation_directions: ImmutableMatrix  #: 3 x translations: the pure translations
    #: the pitches of the helical freedoms (one per "H" of ``motion``), principal pitches;
    #: None with ``motion``
    helical_pitches: tuple | None = ()
    #: momentary internal motions: idle motions of limbs at their own (serial) singularities,
    #: counted in ``mobility`` (the mechanism keeps them) but not in ``twists``
    internal: int = 0

    def __repr__(self) -> str:
        """A short summary; every field stays an attribute (``m.twists``, ``m.links``, ...).

        >>> from screwsym.systems.parallel import Limb, ParallelMechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> ParallelMechanism(Limb(R([0, 0, 0], z), R([1, 2, 0], z)),
        ...                   Limb(R([4, 0, 0], z), R([3, 3, 0], z))).mobility()
        Mobility(mobility=1, motion='1R', common=3, redundant=0, passive=0, classical=-2)
        """
        extra = f", internal={self.internal}" if self.internal else ""
        return (f"Mobility(mobility={self.mobility}, motion={self.motion!r}, "
                f"common={self.common}, redundant={self.redundant}, passive={self.passive}, "
                f"classical={self.classical}{extra})")

    def answer(self) -> tuple[int, int, int, int, int, int, str | None, tuple | None, int]:
        """The numbers of the analysis, without the twists: what two cases compare."""
        return (self.mobility, self.order, self.common, self.redundant, self.passive,
                self.classical, self.motion, self.helical_pitches, self.internal)

    # a tuple compares its items with ==, and a SymPy matrix's == parses the strings inside
    # a tuple or dict: these compare without handing a string to SymPy (screwsym.core.basic)
    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, tuple)
            and len(other) == len(self)
            and all(_same(a, b) for a, b in zip(self, other, strict=True))
        )

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __hash__(self) -> int:
        return tuple.__hash__(self)

    def __contains__(self, value: object) -> bool:
        return any(_same(a, value) for a in self)

    def count(self, value: Any) -> int:
        """How many fields equal ``value`` (strings in ``value`` never reach SymPy)."""
        return sum(_same(a, value) for a in self)

    def index(self, value: Any, start: SupportsIndex = 0, stop: SupportsIndex = sys.maxsize) -> int:
        """The first field equal to ``value`` (strings in ``value`` never reach SymPy)."""
        for i in range(*slice(operator.index(start), operator.index(stop)).indices(len(self))):
            if _same(self[i], value):
                return i
        raise ValueError("Mobility.index(value): value not found")


class Degenerate(NamedTuple):
    """A case of ``mobility_cases`` where a joint degenerates: the case's values unmake it.

    The values of the symbols on the case make a joint impossible to build
    (a zero axis direction; the two axes of a universal joint made parallel),
    so no mechanism is there to analyse: this is a finding, reported in the
    place of a :class:`Mobility`.  ``reason`` is what the joint says (the
    ``ValueError`` it raises when built with those values); on a case that no
    substitution states (a surface ``f = 0``), where the joint cannot be
    rebuilt, that its twists lose rank there.

    >>> from screwsym.systems.parallel import Degenerate
    >>> Degenerate("limbs[0]: direction: a joint axis needs a non-zero direction").answer()
    ('degenerate joint', 'limbs[0]: direction: a joint axis needs a non-zero direction')
    """

    reason: str  #: the joint's own error message, prefixed by the limb: ``limbs[i]: ...``

    def answer(self) -> tuple[str, str]:
        """What two cases compare when they are merged: degenerate, and why."""
        return ("degenerate joint", self.reason)


def _same(field: Any, value: Any) -> bool:
    """``field == value``, ``False`` where a SymPy ``field`` would meet a string in ``value``."""
    if isinstance(field, Basic) and not isinstance(value, Basic) and find_string(value) is not None:
        return False
    return bool(field == value)


class ParallelMechanism(ScrewsymBasic):
    """A moving platform carried by limbs, each a serial chain from the base.

    Examples
    ========

    The 3-RPS platform (Hunt 1983): three R-P-S legs, each R axis tangent to
    the base circle, every leg in the plane normal to its R axis.

    >>> from sympy import sqrt, Rational
    >>> from screwsym.systems.parallel import ParallelMechanism, Limb
    >>> from screwsym.systems.joints import R, P, S
    >>> def leg(b, u, top):
    ...     d = [t - s for t, s in zip(top, b)]
    ...     return Limb(R(b, u), P(d), S(top))
    >>> m = ParallelMechanism(
    ...     leg([2, 0, 0], [0, 1, 0], [1, 0, 2]),
    ...     leg([-1, sqrt(3), 0], [-sqrt(3), -1, 0], [-Rational(1, 2), sqrt(3)/2, 2]),
    ...     leg([-1, -sqrt(3), 0], [sqrt(3), -1, 0], [-Rational(1, 2), -sqrt(3)/2, 2]),
    ... ).mobility()
    >>> m.mobility, m.motion, m.classical, (m.common, m.redundant, m.passive)
    (3, '1T2R', 3, (0, 0, 0))
    >>> m.rotation_directions.shape, m.translation_directions.shape
    ((3, 2), (3, 1))

    Parameters
    ==========

    *limbs : Limb

    References
    ==========

    Huang, Li & Ding, *Theory of Parallel Mechanisms*, Chapters 2 and 5.
    """

    __slots__ = ()

    def __new__(cls, *limbs: Limb) -> Self:
        if not limbs:
            raise ValueError("limbs: expected at least one limb, got none")
        for i, limb in enumerate(limbs):
            if not isinstance(limb, Limb):
                raise TypeError(f"limbs[{i}]: expected a Limb, got {type(limb).__name__}")
        return ScrewsymBasic.__new__(cls, *limbs)

    @property
    def limbs(self) -> tuple[Limb, ...]:
        return self.args

    @property
    def constraints(self) -> ScrewSystem:
        """The union of the limbs' constraint systems: every wrench on the platform."""
        return ScrewSystem(*(w for limb in self.args for w in limb.constraints), kind=Wrench)

    @property
    def twists(self) -> ScrewSystem:
        """The platform's instantaneous motions: the reciprocal of :attr:`constraints`."""
        return self.constraints.reciprocal()

    def mobility(self) -> Mobility:
        """The instantaneous mobility by the modified Grübler–Kutzbach criterion, generic in the symbols.

        Instantaneous: the first-order motions at the configuration given, which
        a finite motion need not have (a shaky linkage); for the second order,
        write the mechanism as a graph (:meth:`screwsym.systems.linkage.Mechanism.from_parallel`)
        and call its ``second_order()``.  See the module docstring for how ``common`` (lambda), ``redundant``
        (nu) and ``passive`` (zeta) come from the screw systems.
        """
        return _mobility(self)

    def actuation_wrenches(self) -> tuple[Wrench, ...]:
        """Per actuated joint, its actuation (transmission) wrench (Joshi & Tsai 2002).

        See :func:`screwsym.systems.actuation.actuation_wrenches`.
        """
        return _actuation.actuation_wrenches(self)

    def jacobian(self) -> tuple[ImmutableMatrix, ImmutableMatrix]:
        """``(Jx, Jq)`` with ``Jx * t = Jq * qdot`` (see :func:`screwsym.systems.actuation.jacobian`)."""
        return _actuation.jacobian(self)

    def singularities(self, *, budget: int = BUDGET) -> _singular.Singularities:
        """The limb, actuation and constraint singularities as conditions on the symbols.

        See :func:`screwsym.systems.singularities.mechanism_singularities`.
        """
        return _singular.mechanism_singularities(self, budget=budget)

    def transmission(self, *, budget: int = BUDGET) -> _actuation.Transmission:
        """The input, output and local transmission indices (Wang et al. 2010).

        See :func:`screwsym.systems.actuation.transmission`.
        """
        return _actuation.transmission(self, budget=budget)

    def mobility_cases(
        self, *, max_cases: int = MAX_CASES, budget: int = BUDGET, merge: bool = True
    ) -> list[tuple[Any, Mobility | Degenerate | None]]:
        """The mobility in each case where the symbols change a rank: an exhaustive split.

        Explanation
        ===========

        The cases are split first by the rank conditions of each limb's twist
        system (where a limb gains constraints or passive freedoms), limb by
        limb, then, within each, by those of the union of the limbs'
        constraint systems (:meth:`ScrewSystem.rank_conditions`); the
        conditions of a case are the conjunction.  Every real value of the
        symbols satisfies exactly one case (before merging; after it, still
        exactly one).  Each case's mobility is the
        analysis of the mechanism with the case's substitution made, so
        ``mobility``, ``passive`` and the platform's twists are exact on the whole
        case, ``common`` and ``redundant`` generic within it.  A condition
        in one symbol (or in ``sin(q)``, ``cos(q)`` of one angle), once the
        earlier ones are substituted, is decided at each of its real roots
        (points of the circle); a condition with no real solution is dropped.
        A case that no substitution states (a condition ``f = 0`` in two or
        more symbols linear in none of them, ``x**2 + y**2 = 2``) is split on
        modulo ``f``, as :meth:`ScrewSystem.rank_conditions` proves a rank
        there: the limbs' and the constraints' ranks hold at every point of
        the case, the platform's ``twists`` are Cramer's rule on the minor that
        proved the constraints' rank, and ``common`` and the motion type are
        those of the surface's generic point (the motion ``None`` where two or
        more rotations are left: the sign of the pitch form is not decided on
        a surface).  A case comes with ``None`` only where the rank conditions
        give ``None``.  A case whose values unmake a joint (a zero axis, a
        universal joint's axes made parallel) comes with a
        :class:`Degenerate` that says which and why.  Geometry may be
        polynomial in ``sin`` and ``cos`` of the symbols: the conditions are
        then in ``sin(q)`` and ``cos(q)``, and a substitution sets both.  At most ``max_cases`` cases (a ``ValueError`` beyond), and
        at most ``budget`` units of polynomial arithmetic for the whole split
        (:meth:`ScrewSystem.rank_conditions`; a ``ValueError`` naming it beyond).

        With ``merge=True`` (the default) cases with the same answer (the same
        mobility, order, common and redundant constraints, passive freedoms,
        classical count and motion type: :meth:`Mobility.answer`) are given as
        one, whose condition is the ``Or`` of theirs (or, where that is shorter
        and made of inequalities alone, the negation of the other cases': the
        cases hold one at each point), in the place of the first;
        its :class:`Mobility` is the first case's, so its ``twists`` (a basis
        of the platform's twists) are those of that case: ``merge=False`` gives
        each case with its own.

        Examples
        ========

        >>> from sympy import symbols
        >>> from screwsym.systems.parallel import Limb, ParallelMechanism
        >>> from screwsym.systems.joints import R
        >>> b = symbols("b", real=True)
        >>> z = [0, 0, 1]
        >>> fourbar = ParallelMechanism(Limb(R([0, 0, 0], z), R([1, b, 0], z)),
        ...                             Limb(R([4, 0, 0], z), R([3, 0, 0], z)))
        >>> [(case, m.mobility, m.motion) for case, m in fourbar.mobility_cases()]
        [(Ne(b, 0), 1, '1R'), (Eq(b, 0), 2, '1T1R')]

        The coupler pivot on a circle, at angle ``q``: the four-bar folds where
        the pivot reaches the x axis, at ``q = 0`` and ``q = pi``.

        >>> from sympy import cos, sin
        >>> q = symbols("q", real=True)
        >>> crank = ParallelMechanism(Limb(R([0, 0, 0], z), R([cos(q), sin(q), 0], z)),
        ...                           Limb(R([4, 0, 0], z), R([3, 0, 0], z)))
        >>> [(case, m.mobility) for case, m in crank.mobility_cases()]
        [(Ne(sin(q), 0), 1), (Eq(sin(q), 0), 2)]

        The coupler pivot at ``(1, s**2 + t**2 - 2)``: folded on a circle, a
        case no substitution states, decided on the circle itself.

        >>> s, t = symbols("s t", real=True)
        >>> folds = ParallelMechanism(Limb(R([0, 0, 0], z), R([1, s**2 + t**2 - 2, 0], z)),
        ...                           Limb(R([4, 0, 0], z), R([3, 0, 0], z)))
        >>> [(case, m.mobility, m.motion) for case, m in folds.mobility_cases()]
        [(Ne(s**2 + t**2 - 2, 0), 1, '1R'), (Eq(s**2 + t**2 - 2, 0), 2, '1T1R')]
        """
        max_cases = check_count(max_cases, "max_cases")
        merge = check_flag(merge, "merge")
        with case_budget(budget, "mobility_cases"):
            cases = self._mobility_cases(max_cases)
        if not merge:
            return cases
        # both kinds of result have an answer(): merged as Answered, given back as they were
        answered = cast("list[tuple[Any, Answered | None]]", cases)
        return cast("list[tuple[Any, Mobility | Degenerate | None]]", merge_cases(answered))

    def _mobility_cases(self, max_cases: int) -> list[tuple[Any, Mobility | Degenerate | None]]:
        """The split of :meth:`mobility_cases` before merging: by each limb's twists, then by
        the union of the limbs' constraints (:func:`~screwsym.systems._cases.split_mechanism`)."""
        limbs = self.args

        def limb_twists(i: int) -> Stage:
            return Stage(lambda leaf: (_substituted(limbs[i], leaf.subs).twists.matrix, None))

        def constraints(leaf: Leaf) -> tuple[ImmutableMatrix, None]:
            # on a surface, each limb's constraints are those its own case proved there
            W = (_surface_constraints(leaf) if leaf.relation
                 else _substituted(self, leaf.subs).constraints)
            return W.matrix, None

        def result(leaf: Leaf) -> Mobility | None:
            here = _substituted(self, leaf.subs)
            return _surface_mobility(here, leaf) if leaf.relation else _mobility(here)

        stages = [limb_twists(i) for i in range(len(limbs))] + [Stage(constraints)]
        units = [(f"limbs[{i}]", limb) for i, limb in enumerate(limbs)]
        return split_mechanism(stages, units, _limb_joints(self), result, Degenerate, max_cases)


def _substituted(obj: Any, subs: Any) -> Any:
    """``obj`` with a case's substitution made (none: ``obj`` itself)."""
    return trig_substitute(obj, subs) if subs else obj


def _limb_joints(mech: ParallelMechanism) -> list[tuple[str, Joint]]:
    return [(f"limbs[{i}]: joints[{k}]", j) for i, limb in enumerate(mech.args)
            for k, j in enumerate(limb.joints)]


def _surface_constraints(leaf: Leaf) -> ScrewSystem:
    """The union of the limbs' constraints on a case on a surface, each by Cramer's rule on
    the minor that proved its limb's rank there (non-zero on the case), with the case's
    substitution made (a later limb's case may set more symbols)."""
    return ScrewSystem(*(w for node in leaf.nodes for w in basis_with(node, Wrench, leaf.subs)),
                       kind=Wrench)


def _mobility(mech: ParallelMechanism) -> Mobility:
    limb_twists = [limb.twists for limb in mech.args]
    all_twists = ScrewSystem(*(t for T in limb_twists for t in T), kind=Twist)
    W = mech.constraints
    twists = W.reciprocal()
    return _figures(mech, [T.rank for T in limb_twists], all_twists.rank, W.rank, twists,
                    motion_of(twists))


def _surface_mobility(mech: ParallelMechanism, leaf: Leaf) -> Mobility | None:
    """The figures of a case on a surface ``fe = 0`` (``leaf.relation``): each limb's rank and
    the constraints' rank as the split proved them at every point of the case, the platform's
    twists by Cramer's rule on the constraints' minor there; the rank of all the limbs' twists
    (``common``) and the motion type those of the surface's generic point
    (:func:`motion_on_surface`).  None where no point of the surface proved them."""
    fe = leaf.relation[0]
    *limb_nodes, w_node = leaf.nodes
    all_twists = ScrewSystem(*(t for limb in mech.args for t in limb.twists), kind=Twist)
    all_rank = rank_on_surface(all_twists.matrix, fe)
    twists = basis_system(w_node, Twist)
    kinds = motion_on_surface(twists, fe)
    if all_rank is None or kinds is None:  # pragma: no cover - no point proved a rank
        return None
    return _figures(mech, [node.rank for node in limb_nodes], all_rank, w_node.rank, twists,
                    kinds)


def _figures(mech: ParallelMechanism, limb_ranks: list, all_rank: int, union: int,
             twists: ScrewSystem, kinds: MotionType) -> Mobility:
    """The modified Grübler–Kutzbach count and its parts from the ranks of a case."""
    limbs = mech.args
    freedoms = sum(limb.freedom for limb in limbs)
    g = sum(len(limb.joints) for limb in limbs)
    n = 2 + sum(len(limb.joints) - 1 for limb in limbs)
    common = 6 - all_rank
    constraint_counts = [6 - r for r in limb_ranks]
    redundant = sum(c - common for c in constraint_counts) - (union - common)
    # an idle motion of a limb (freedom - rank) is a passive freedom when the limb has it at
    # every configuration (a S-S leg's spin), a momentary internal motion when only here
    # (a leg at its own serial singularity): generic_limb_rank tells them apart
    generic_ranks = [r if r == limb.freedom else generic_limb_rank(limb)
                     for limb, r in zip(limbs, limb_ranks, strict=True)]
    passive = freedoms - sum(generic_ranks)
    internal = sum(generic_ranks) - sum(limb_ranks)
    order = 6 - common
    dof = order * (n - g - 1) + freedoms + redundant - passive
    return Mobility(
        mobility=dof,
        order=order,
        common=common,
        redundant=redundant,
        passive=passive,
        classical=6 * (n - g - 1) + freedoms,
        rotations=kinds.rotations,
        translations=kinds.translations,
        motion=kinds.motion,
        twists=twists,
        links=n,
        joints=g,
        freedoms=freedoms,
        rotation_directions=kinds.rotation_directions,
        translation_directions=kinds.translation_directions,
        helical_pitches=kinds.helical_pitches,
        internal=internal,
    )
