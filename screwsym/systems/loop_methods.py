"""The closed-loop dynamics methods of :class:`~screwsym.systems.linkage.Mechanism`.

Each method checks its budget and calls the function of the same name in
:mod:`~screwsym.systems.loop_dynamics`, whose docstring gives the method (Davies' null
space, the differentiated closure, virtual power); the methods' docstrings give their
examples.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, cast

from sympy import ImmutableMatrix

from ..algebra.budget import BUDGET
from ..core.twist import Twist
from .loop_dynamics import (
    PlatformDynamics,
    RedundantForces,
    actuation_condition,
    bounded_call,
    inverse_dynamics,
    joint_accelerations,
    joint_rates,
    joint_reactions,
    link_acceleration,
    link_twist,
    mass_matrix,
    platform_dynamics,
    redundant_inverse_dynamics,
)

if TYPE_CHECKING:
    from .linkage import Mechanism

__all__: list[str] = []  # the methods of Mechanism; users reach them there


class LoopDynamicsMixin:
    """The closed-loop dynamics methods of :class:`~screwsym.systems.linkage.Mechanism`
    (:mod:`~screwsym.systems.loop_dynamics` computes them)."""

    __slots__ = ()

    def actuation_condition(self, actuated: Any, *, budget: int = BUDGET) -> Any:
        """Where the joints ``actuated`` (numbers into :attr:`joints`) determine the motion.

        ``True`` with numbers (an actuation singularity is a ``ValueError``); with
        symbols ``Ne(det, 0)``, ``det`` the minor of the passive joints' columns of
        the network matrix the results of :meth:`joint_rates`,
        :meth:`mass_matrix` and :meth:`inverse_dynamics` are solved on (see :mod:`~screwsym.systems.loop_dynamics`).

        The four-bar whose coupler-rocker joint is at ``(x, y)``: the crank drives it
        except where that joint lies on the line from the crank pin ``(1, 2)`` to the
        rocker pivot ``(4, 0)`` (coupler and rocker in line: Gosselin & Angeles' second kind).

        >>> from sympy import symbols
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> x, y = symbols("x y", real=True)
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([x, y, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.actuation_condition([0])
        Ne(2*x + 3*y - 8, 0)
        """
        with bounded_call(budget, "actuation_condition"):
            return actuation_condition(cast("Mechanism", self), actuated)

    def joint_rates(self, actuated: Any, rates: Any, *, budget: int = BUDGET) -> ImmutableMatrix:
        """All joint rates (F, the joints' freedoms in order) from the ``rates`` of the joints
        ``actuated``: Davies' null space restricted to the actuated rates (see
        :mod:`~screwsym.systems.loop_dynamics`).

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.joint_rates([0], [5]).T      # the coupler turns at 5 - 60/7 = -25/7
        Matrix([[5, -60/7, 40/7, -15/7]])

        Signs: a joint ``(a, b, joint)``'s rate is the coefficient of its twist as given,
        the motion of ``b`` relative to ``a`` about the axis as directed.  The last joint
        above is written ``("rocker", "ground", ...)``: its rate ``-15/7`` is the ground's
        turn relative to the rocker, so the rocker turns at ``+15/7`` relative to the
        ground.  Reversing a joint's pair or its axis reverses its rate, and an actuated
        joint's force with it (:meth:`inverse_dynamics`).

        >>> flipped = Mechanism(fourbar.joints[:3] + (("ground", "rocker", R([4, 0, 0], z)),),
        ...                     base="ground")
        >>> flipped.joint_rates([0], [5]).T
        Matrix([[5, -60/7, 40/7, 15/7]])
        """
        with bounded_call(budget, "joint_rates"):
            return joint_rates(cast("Mechanism", self), actuated, rates)

    def joint_accelerations(self, actuated: Any, rates: Any, accelerations: Any, *,
                            budget: int = BUDGET) -> ImmutableMatrix:
        """All joint accelerations from the actuated joints' ``rates`` and ``accelerations``:
        the differentiated closure ``A qddot + quadratic_terms(qdot) = 0`` solved for the
        passive ones (see :mod:`~screwsym.systems.loop_dynamics`).  A configuration whose
        closure does not extend to second order along the rates is a ``ValueError``.

        A crank turning steadily at 5 still accelerates the other joints:

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.joint_accelerations([0], [5], [0]).T
        Matrix([[0, 4500/343, 3300/343, -7800/343]])
        """
        with bounded_call(budget, "joint_accelerations"):
            return joint_accelerations(cast("Mechanism", self), actuated, rates, accelerations)

    def link_twist(self, link: Any, actuated: Any, rates: Any, *, budget: int = BUDGET) -> Twist:
        """The twist of ``link`` (space frame, ray order) for the actuated joints' ``rates``.

        The coupler turns about its instant centre ``(12/5, 24/5)``:

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.link_twist("coupler", [0], [7])
        Twist([0, 0, -5], [-24, 12, 0])
        """
        with bounded_call(budget, "link_twist"):
            return link_twist(cast("Mechanism", self), link, actuated, rates)

    def link_acceleration(self, link: Any, actuated: Any, rates: Any, accelerations: Any, *,
                          budget: int = BUDGET) -> Twist:
        """The twist rate ``dV/dt`` of ``link`` (its spatial acceleration, space frame, ray
        order) for the actuated joints' ``rates`` and ``accelerations``.

        The rate of change of the twist ``(omega; v_O)``, not a point's acceleration: a
        crank turning steadily about a fixed axis has a constant twist.

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.link_acceleration("crank", [0], [1], [0])
        Twist([0, 0, 0], [0, 0, 0])
        >>> fourbar.link_acceleration("coupler", [0], [7], [0])
        Twist([0, 0, 180/7], [-228/7, -1356/7, 0])
        """
        with bounded_call(budget, "link_acceleration"):
            return link_acceleration(cast("Mechanism", self), link, actuated, rates, accelerations)

    def mass_matrix(self, actuated: Any, *, conds: str = "none",
                    budget: int = BUDGET) -> ImmutableMatrix:
        r"""The k x k mass matrix in the rates of the joints ``actuated`` (k, the mobility).

        Explanation
        ===========

        ``H = sum_l A_l^T Delta M_l A_l``, ``A_l`` link ``l``'s twist per actuated
        rate and ``M_l`` its inertia (``inertias=``): the kinetic energy of the
        mechanism is ``1/2 qa^T H qa``.  A joint's rate is the coefficient of its twist
        as given (a unit axis: radians or lengths per unit time).  Exact; generic with symbols, holding where
        :meth:`actuation_condition` does (``conds="piecewise"``: each entry a
        ``Piecewise`` with that condition, ``nan`` elsewhere).  An actuation
        singularity (the passive joints move with the actuated ones locked) is a
        ``ValueError``.  ``budget`` bounds the exact arithmetic (units of about a
        microsecond, and the CPU time: :mod:`screwsym.algebra.budget`; every method here
        takes it).  See :mod:`~screwsym.systems.loop_dynamics`.

        Examples
        ========

        A four-bar driven by its crank, a point mass of 1 at the coupler joint
        ``(1, 2, 0)`` on the crank and one of 2 at ``(3, 3, 0)`` on the rocker
        (about ``(4, 0, 0)``, at distance ``sqrt(10)``).  Per unit crank rate the
        first moves at speed ``sqrt(5)`` and the rocker turns at ``3/7``
        (:meth:`joint_rates <screwsym.systems.linkage.Mechanism.joint_rates>`), so ``H = 1 * 5 + 2 * (3/7)**2 * 10 = 425/49``.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> fourbar.mass_matrix([0])
        Matrix([[425/49]])
        """
        with bounded_call(budget, "mass_matrix"):
            return mass_matrix(cast("Mechanism", self), actuated, conds)

    def inverse_dynamics(self, actuated: Any, rates: Any, accelerations: Any,
                         gravity: Any = None, *, conds: str = "none",
                         budget: int = BUDGET) -> ImmutableMatrix:
        r"""The forces or torques of the joints ``actuated`` for their ``rates`` and
        ``accelerations``, every other joint passive and frictionless.

        Explanation
        ===========

        By virtual power (Jourdain's principle):
        ``tau = sum_l A_l^T Delta (M_l dV_l/dt + [V_l, M_l V_l] - W_l)``, ``V_l``
        link ``l``'s twist, ``dV_l/dt`` its twist rate (:meth:`link_acceleration`),
        ``W_l`` its weight under ``gravity`` (default ``(0, 0, -g)``, ``g`` a
        positive symbol).  Exact; generic with symbols as :meth:`mass_matrix`.

        Signs: each force is the one that does positive work on its joint's rate as
        :meth:`joint_rates` counts it, the motion of the joint's second link relative
        to its first about the axis as given.  Reversing an actuated joint's pair
        ``(a, b)`` or its axis reverses its rate and its force: ask for the rates in the
        orientation the joints were written in.  The wrench each joint transmits, the
        actuator's included, is :meth:`joint_reactions`.

        Examples
        ========

        The four-bar of :meth:`mass_matrix` at rest, gravity ``-10`` along y.  Per
        unit crank rate the first mass rises at ``1`` and the second at ``-3/7``
        (it moves with ``3/7 * (-3, -1)``), so by virtual work the crank holds
        ``1 * 10 * 1 + 2 * 10 * (-3/7) = 10/7``.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> fourbar.inverse_dynamics([0], [0], [0], [0, -10, 0])
        Matrix([[10/7]])
        """
        with bounded_call(budget, "inverse_dynamics"):
            return inverse_dynamics(cast("Mechanism", self), actuated, rates, accelerations, gravity, conds)

    def platform_dynamics(self, actuated: Any, rates: Any = None, accelerations: Any = None,
                          gravity: Any = None, *, platform: Any = "platform", point: Any = None,
                          coordinates: Any = None, conds: str = "none",
                          budget: int = BUDGET) -> PlatformDynamics:
        r"""The dynamics in the coordinates of the link ``platform`` (its pose rates): the
        form of Tsai's virtual-work model and of Codourey's model of the Delta.

        Explanation
        ===========

        The platform's coordinates are ``k`` components (k, the mobility) of its twist
        written at the reference point ``point`` (default the origin): ``wx wy wz``, its
        angular velocity, and ``vx vy vz``, the velocity of its point at ``point``; their
        rates ``x''`` are the angular acceleration and that point's acceleration.  With
        ``coordinates=None`` the first ``k`` components, in that order, that the platform's
        motion leaves independent (``vx vy vz`` for a Delta, ``wz vx vy`` for a planar
        platform); or name them, e.g. ``("vx", "vy", "wz")``.  For a translating platform
        these are the rates of its position; with a rotation ``wx wy wz`` are angular
        velocities (quasi-velocities), not rates of angles.

        ``J`` is the actuated rates per platform rate, ``qa' = J x'`` (Tsai's ``J``, the
        inverse of the platform's twist per actuated rate; for a parallel mechanism the
        rows of :meth:`ParallelMechanism.jacobian
        <screwsym.systems.parallel.ParallelMechanism.jacobian>`'s ``Jx t = Jq qa'`` on the
        actuation wrenches, ``t`` the platform twist in these coordinates).  By virtual
        power the generalised forces on the platform coordinates are ``F = J^T tau`` and
        the actuator forces ``tau = J^-T F`` (Tsai 1999, §9.6); the kinetic energy
        ``1/2 qa'^T H qa'`` (:meth:`mass_matrix`) is ``1/2 x'^T Lambda x'`` with
        ``Lambda = J^T H J``.  Given the platform's ``rates`` and ``accelerations`` (``k``
        each) the actuated ones are ``qa' = J x'`` and ``qa'' = J (x'' - b)``, ``b`` the
        platform's accelerations with ``qa'' = 0``, and ``tau`` is :meth:`inverse_dynamics`'s
        there.  Without a state only ``J`` and ``Lambda`` (``forces`` and
        ``actuator_forces`` are ``None``).

        Exact for exact input (floats as in :meth:`inverse_dynamics`); generic with symbols,
        holding where the actuated joints determine the motion (:meth:`actuation_condition`)
        and ``det J^-1 != 0`` (``conds="piecewise"``: each result a ``Piecewise`` with that
        condition).  Coordinates that do not determine the actuated rates here (a
        singularity of the first kind) are a ``ValueError``.

        Examples
        ========

        The four-bar of :meth:`mass_matrix`, its coupler as the "platform": it turns at
        ``-5/7`` per unit crank rate (:meth:`joint_rates`: ``5 - 60/7`` for ``5``), so
        ``J = -7/5`` and ``Lambda = (7/5)**2 * 425/49 = 17``; at rest under gravity ``-10``
        along y the crank holds ``10/7``, a torque ``F = J tau = -2`` on the coupler.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> pd = fourbar.platform_dynamics([0], [0], [0], [0, -10, 0], platform="coupler")
        >>> pd.coordinates, pd.jacobian, pd.mass_matrix
        (('wz',), Matrix([[-7/5]]), Matrix([[17]]))
        >>> pd.forces, pd.actuator_forces
        (Matrix([[-2]]), Matrix([[10/7]]))

        References
        ==========

        L.-W. Tsai, *Robot Analysis*, Wiley 1999, §9.6 (virtual work); L.-W. Tsai, "Solving
        the inverse dynamics of a Stewart-Gough manipulator by the principle of virtual
        work", J. Mech. Design 122 (2000) 3-9; A. Codourey, "Dynamic modeling of parallel
        robots for computed-torque control implementation", Int. J. Robotics Research
        17(12) (1998) 1325-1336.
        """
        with bounded_call(budget, "platform_dynamics"):
            return platform_dynamics(cast("Mechanism", self), actuated, rates, accelerations,
                                     gravity, platform, point, coordinates, conds)

    def joint_reactions(self, actuated: Any, rates: Any, accelerations: Any,
                        gravity: Any = None, *, conds: str = "none", self_stress: bool = False,
                        budget: int = BUDGET) -> tuple:
        r"""The wrench each joint transmits, for the actuated joints' ``rates`` and
        ``accelerations`` driven by the forces of :meth:`inverse_dynamics`.

        Explanation
        ===========

        One :class:`~screwsym.core.wrench.Wrench` per joint, in the order of
        :attr:`joints`: the wrench the joint ``(a, b, joint)`` exerts on ``b`` (``a``
        bears its opposite), in the space frame, ray order ``(f; C_O)``.  The links'
        Newton–Euler balances, ``sum of the joint wrenches on l = M_l dV_l/dt +
        [V_l, M_l V_l] - W_l``, with each joint's wrench reciprocal to its twists
        (``$^T Delta w = 0``: no power on a passive freedom), except an actuated
        joint's, whose power on its unit twist is the actuator force: the reaction
        includes the actuator.  Exact for exact input; generic with symbols, holding
        where :meth:`actuation_condition` does.

        Where the loops are overconstrained (a planar linkage of revolutes: its forces
        along the axes and its moments about lines in the plane) the balances
        determine the reactions only up to a *self-stress*, a set of joint wrenches
        in equilibrium on every link by themselves; the solution returned sets the
        undetermined unknowns (the free columns of the reduced echelon form, the last
        joints' last components first) to zero.  For a planar linkage loaded in its
        plane that is the planar solution: the in-plane forces are the unique ones.
        With ``self_stress=True`` the result is the pair ``(reactions, basis)``, ``basis``
        a tuple of self-stresses (each a tuple of one wrench per joint, in equilibrium on
        every link, reciprocal to every joint's twists, with no power on the actuated
        ones either) spanning them: the reactions are ``reactions + sum c_i basis[i]`` for
        any ``c_i``.  There are ``6 L - rank`` of them (:meth:`mobility`'s loops and the
        network matrix's rank: the statics dual of Davies' kinematics), each depending on
        the geometry alone.

        With symbols and ``conds="piecewise"`` each reaction (and self-stress) is a 6 x 1
        column, ray order, of ``Piecewise`` entries that hold where
        :meth:`actuation_condition` does and are ``nan`` elsewhere (a
        :class:`~screwsym.core.wrench.Wrench` holds no ``nan``); where the condition is
        ``True`` they are wrenches as without it.

        Examples
        ========

        The four-bar of :meth:`mass_matrix` at rest under gravity ``-10`` along y.
        The crank, a point mass of 1 at its pin ``(1, 2, 0)`` held by the torque
        ``10/7``: the ground pin's wrench on it has moment ``10/7`` about z at ``O``,
        and its power on the crank's unit twist is that torque; the coupler's pin
        does no work on its joint.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.core.twist import Twist
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> w = fourbar.joint_reactions([0], [0], [0], [0, -10, 0])
        >>> w[0]
        Wrench([40/7, 90/7, 0], [0, 0, 10/7])
        >>> w[1]                    # along the massless coupler, (2, 1)
        Wrench([40/7, 20/7, 0], [0, 0, -60/7])
        >>> from screwsym.core.wrench import power
        >>> [power(j.twists.screws[0], r) for (_, _, j), r in zip(fourbar.joints, w)]
        [10/7, 0, 0, 0]

        Its self-stresses: three, the loop's out-of-plane force and moments (a planar
        loop has ``6 - 3`` overconstraints).  The first is a unit force along z through
        the origin, the same at every pin: each link bears it from one pin and its
        opposite from the other, and it does no work on any revolute about z.

        >>> w, basis = fourbar.joint_reactions([0], [0], [0], [0, -10, 0], self_stress=True)
        >>> len(basis), fourbar.mobility().loops * 6 - fourbar.mobility().rank
        (3, 3)
        >>> basis[0]
        (Wrench([0, 0, 1], [0, 0, 0]), Wrench([0, 0, 1], [0, 0, 0]), Wrench([0, 0, 1], [0, 0, 0]), Wrench([0, 0, 1], [0, 0, 0]))
        """
        with bounded_call(budget, "joint_reactions"):
            return joint_reactions(cast("Mechanism", self), actuated, rates, accelerations,
                                   gravity, conds, self_stress)

    def redundant_inverse_dynamics(self, actuated: Any, rates: Any, accelerations: Any,
                                   gravity: Any = None, *,
                                   budget: int = BUDGET) -> RedundantForces:
        r"""The minimum-norm forces of more actuated joints than the mobility, with the
        internal forces they leave free.

        Explanation
        ===========

        With ``k`` actuated joints and mobility ``M < k`` the actuated rates are not
        independent: ``qa' = B u'`` for the rates ``u'`` of ``M`` of them (``primary``,
        the first whose rates determine the motion), and virtual power fixes only
        ``B^T tau = Q``, ``Q`` the forces :meth:`inverse_dynamics` gives those ``M``
        joints alone.  The result's ``forces`` is the least-squares choice,
        ``tau = B (B^T B)^-1 Q``, the one of least Euclidean norm (each entry in its
        joint's units: torques and forces mixed as given; scale the rates to weigh
        them); ``internal`` is a basis of the null space of ``B^T`` (``k - M`` actuator
        force sets that do no work on any allowed motion), so every solution is
        ``forces + sum c_i internal[i]``.  ``k = M`` gives :meth:`inverse_dynamics`'s forces
        and no internal force.

        ``rates`` and ``accelerations`` are the ``k`` actuated joints', which must be
        those the loops allow: exactly for exact input (a ``ValueError`` names the first
        inconsistent one), for floats within the float policy's relative tolerance
        (``2**-40`` for double precision: the rates rounded once from a consistent
        motion), computed on their exact binary values from the primary ones.  Exact;
        generic with symbols (where :meth:`actuation_condition` holds for the primary
        joints and the rates given are consistent).

        Examples
        ========

        The four-bar of :meth:`mass_matrix` at rest under gravity ``-10`` along y,
        driven at the crank and at the rocker's pivot, joint 3 (the ground's turn
        relative to the rocker, ``-3/7`` per unit crank rate: :meth:`joint_rates`).  Alone
        the crank holds ``10/7``; shared, ``B = (1, -3/7)`` and ``tau = B * (10/7) /
        (1 + 9/49) = (35/29, -15/29)`` (its power ``35/29 + 3/7 * 15/29 = 10/7``); the
        internal force ``(3/7, 1)`` holds the linkage against itself.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> r = fourbar.redundant_inverse_dynamics([0, 3], [0, 0], [0, 0], [0, -10, 0])
        >>> r.forces.T, r.internal, r.primary
        (Matrix([[35/29, -15/29]]), (Matrix([
        [3/7],
        [  1]]),), (0,))

        References
        ==========

        H. Cheng, Y.-K. Yiu, Z. Li, "Dynamics and control of redundantly actuated parallel
        manipulators", IEEE/ASME Trans. Mechatronics 8(4) (2003) 483-491 (the least-norm
        actuator forces and their null space).
        """
        with bounded_call(budget, "redundant_inverse_dynamics"):
            return redundant_inverse_dynamics(cast("Mechanism", self), actuated, rates,
                                              accelerations, gravity)

