r"""Mechanisms of any topology: a graph of links and joints, analysed by Davies' method.

A mechanism is a set of rigid links joined by joints.  Here it is a graph:
each joint joins two links, ``(link_a, link_b, joint)``, and one link is the
base.  The graph may have any shape: one loop, several loops sharing links,
loops inside limbs (the parallelograms of the Delta robot), trees hanging off
the loops.

The analysis is the screw form of Davies' method (Davies 1981; Huang, Li &
Ding, Chapter 5 for multi-loop mechanisms).  A spanning tree of the graph is
grown from the base; each joint outside it (a *chord*) closes one fundamental
loop, so a connected mechanism of N links and J joints has ``L = J - N + 1``
independent loops.  Kirchhoff's circulation law holds on each loop: going round
it, the sum of the joint twists times their rates is zero,

    sum_k (+-1) $_k qdot_k = 0,

the sign ``+1`` where the loop passes the joint from ``link_a`` to ``link_b``,
``-1`` the other way.  Stacked, the loops' equations make the *network matrix*
(6L x F, F the total number of joint freedoms) whose null space is the set of
joint rates the mechanism allows *at the configuration given*: its dimension is
the **instantaneous** mobility.  It is found exactly: the rank of the network
matrix over the rationals, algebraic numbers, or (with symbols) the field of
rational functions, that is the *generic* rank.  Geometry may be polynomial in
``sin(q)`` and ``cos(q)`` of symbols (a configuration that moves): those live on
the unit circle, whose field of rational functions is that of ``t = tan(q/2)``,
so the rank is taken there and the bases written back in ``sin(q)``, ``cos(q)``;
the case split (:meth:`Mechanism.mobility_cases`) keeps ``sin(q)`` and
``cos(q)`` as symbols on the circle, as :mod:`screwsym.systems.screw_system` does,
and reaches every angle, ``q = pi`` included.

Second order (Müller 2016): a first-order motion ``qdot`` extends to a
second-order one when some ``qddot`` satisfies, on every loop,

    sum_k $_k qddot_k + sum_{k<l} [$_k, $_l] qdot_k qdot_l + sum_k Y_k qdot_k**2 = 0,

the joints in the loop's order (each joint's axes in order ``link_a`` to
``link_b``, reversed and negated where the loop runs the other way), ``[., .]``
the Lie bracket of twists (:func:`lie_bracket`) and ``Y_k`` the second
derivative of a compound pair's path (zero for the lower pairs, see
:class:`~screwsym.systems.joints.Parallelogram`).  See
:meth:`Mechanism.second_order`.

References
==========

J. M. Davies, "Kirchhoff's circulation law applied to multi-loop kinematic
chains", Mech. Mach. Theory 16 (1981) 171-183.
A. Müller, "Local kinematic analysis of closed-loop linkages: mobility,
singularities, and shakiness", J. Mechanisms Robotics 8(4) (2016) 041013.
Huang, Li & Ding, *Theory of Parallel Mechanisms*, Springer 2013, Chapter 5.
"""

from __future__ import annotations

from functools import reduce
from typing import TYPE_CHECKING, Any, NamedTuple, cast

from sympy import (
    ImmutableMatrix,
    Integer,
    Matrix,
    Tuple,
    cancel,
    expand,
    fraction,
    lcm,
    true,
    zeros,
)

from ..algebra.budget import BUDGET, MAX_CASES
from ..algebra.circle import trig_substitute
from ..algebra.linalg import clean_vector, det_rows, nullspace_basis
from ..algebra.rings import (
    to_expr,
    to_ring,
)
from ..algebra.surface import null_on_surface
from ..core.basic import ScrewsymBasic
from ..core.checks import check_count, check_flag
from ..core.formulas import ad_matrix, cross_matrix
from ..core.inertia import SpatialInertia
from ..core.twist import Twist
from ..core.wrench import Wrench
from ._cases import Leaf, Stage, merge_cases, split_mechanism
from ._rank_cases import apply_subs, case_budget, swapped
from .joints import Joint, Parallelogram, Spherical, Universal
from .loop_dynamics import check_inertias
from .loop_methods import LoopDynamicsMixin
from .motion_type import motion_of
from .parallel import Degenerate, ParallelMechanism
from .screw_system import ScrewSystem, basis_with
from .second_order import SecondOrder, loop_terms, second_order_of
from .topology import (
    Network,
    bare_network,
    check_link,
    link_label,
    network,
    path_matrix,
    spanning_tree,
)

if TYPE_CHECKING:
    from typing_extensions import Self


__all__ = ["Mechanism", "MechanismMobility"]




class MechanismMobility(NamedTuple):
    """The result of :meth:`Mechanism.mobility`: first-order (instantaneous) figures."""

    mobility: int  #: the instantaneous mobility M = F - rank: independent joint rates
    freedoms: int  #: F, the total number of joint freedoms
    loops: int  #: L = J - N + 1, the independent loops
    rank: int  #: the rank of the network matrix (6L x F)
    orders: tuple[int, ...]  #: d_i = rank of loop i's twists = 6 - lambda_i
    common: tuple[int, ...]  #: lambda_i = 6 - d_i: the count of each loop's common constraints
    common_constraints: tuple[ScrewSystem, ...]  #: each loop's common constraints (a basis)
    redundant: int  #: nu = sum d_i - rank: loop equations in excess (overconstraint)
    passive: int  #: zeta: the passive (idle) freedoms, as ``Mobility.passive``
    passive_rates: ImmutableMatrix  #: F x zeta: a basis of the passive joint rates
    rates: ImmutableMatrix  #: F x M: a basis of the joint rates allowed
    classical: int  #: Grübler–Kutzbach, 6 (N - J - 1) + F
    links: int  #: N, base included
    joints: int  #: J

    def answer(self) -> tuple[Any, ...]:
        """The numbers of the analysis, without the screw systems and bases: what two cases compare."""
        return (self.mobility, self.freedoms, self.loops, self.rank, self.orders,
                self.redundant, self.passive, self.classical)




class Mechanism(LoopDynamicsMixin, ScrewsymBasic):
    r"""A mechanism of any topology: links joined by joints, one link the base.

    Explanation
    ===========

    ``joints`` is a list of triples ``(link_a, link_b, joint)``: the joint
    (one of :mod:`screwsym.systems.joints`, placed at the configuration to
    analyse) joins the links named ``link_a`` and ``link_b``.  Links are named
    by strings, integers or SymPy symbols (a symbol naming a link should not
    also be a symbol of the geometry).  A joint's twists are the motions of
    ``link_b`` relative to ``link_a``.  **A joint with several axes has its
    first axis fixed in** ``link_a`` **and its last in** ``link_b``: a
    :class:`~screwsym.systems.joints.Universal` joint's ``dir1`` turns with
    ``link_a``, its ``dir2`` with ``link_b``; a
    :class:`~screwsym.systems.joints.Spherical` joint is the rotations about
    x, y, z in that order; a :class:`~screwsym.systems.joints.Cylindrical` its
    rotation, then its translation.  First-order results do not depend on
    this, but the second-order test of :meth:`second_order` does where the
    axes move (at a singular pose the answer depends on it).

    The graph must be connected; two joints may join the same two links (the
    pair is one loop).  The independent loops come from a spanning tree grown
    from the base (breadth first, the joints in the order given): each joint
    outside the tree closes one loop, ``L = J - N + 1`` of them.

    Examples
    ========

    The planar four-bar, four revolutes on z-parallel axes: one loop, one
    freedom, the classical count -2, three common constraints (the loop is
    planar: two moments and the force along z).

    >>> from screwsym.systems.linkage import Mechanism
    >>> from screwsym.systems.joints import R
    >>> z = [0, 0, 1]
    >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
    ...                      ("crank", "coupler", R([1, 2, 0], z)),
    ...                      ("coupler", "rocker", R([3, 3, 0], z)),
    ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
    >>> m = fourbar.mobility()
    >>> m.mobility, m.loops, m.classical, m.orders, m.redundant, m.passive
    (1, 1, -2, (3,), 0, 0)
    >>> fourbar.relative_twists("coupler")   # a rotation about the instant centre (12/5, 24/5, 0)
    ScrewSystem(Twist([0, 0, 5], [24, -12, 0]))
    >>> fourbar.second_order().mobility     # a four-bar in general position moves on
    1

    A configuration that moves: the parallelogram of the Delta robot's forearms
    (Clavel 1988), its cranks at angle ``q``.  The coupler translates, one
    freedom, at every angle but the flat poses ``sin(q) = 0`` (``q = 0`` and
    ``q = pi``), where the four pivots are collinear (Hunt 1978, §2: the change
    point, where the anti-parallelogram branch meets it).

    >>> from sympy import cos, sin, symbols
    >>> q = symbols("q", real=True)
    >>> para = Mechanism([("ground", "left", R([0, 0, 0], z)),
    ...                   ("left", "coupler", R([cos(q), sin(q), 0], z)),
    ...                   ("coupler", "right", R([2 + cos(q), sin(q), 0], z)),
    ...                   ("right", "ground", R([2, 0, 0], z))], base="ground")
    >>> para.motion("coupler"), para.relative_twists("coupler")
    ('1T', ScrewSystem(Twist([0, 0, 0], [sin(q), -cos(q), 0])))
    >>> [(case, m.mobility) for case, m in para.mobility_cases()]
    [(Ne(sin(q), 0), 1), (Eq(sin(q), 0), 2)]

    Parameters
    ==========

    joints : list of (link_a, link_b, joint)
    base : str, int or Symbol
        The link that is fixed.
    inertias : dict, optional
        ``{link: SpatialInertia}``: each moving link's inertia in the space frame at
        the configuration given (a link left out is massless), for
        :meth:`mass_matrix` and :meth:`inverse_dynamics`.

    See Also
    ========

    screwsym.systems.parallel.ParallelMechanism

    References
    ==========

    Davies 1981; Müller 2016; Huang, Li & Ding, Chapter 5 (see the module docstring).
    """

    __slots__ = ()

    def __new__(cls, joints: Any, base: Any = None, inertias: Any = None) -> Self:
        if isinstance(joints, (str, bytes)) or not hasattr(joints, "__iter__"):
            raise TypeError(
                "joints: expected a list of (link_a, link_b, joint) triples, got "
                f"{type(joints).__name__}"
            )
        triples = []
        for i, item in enumerate(joints):
            if isinstance(item, (str, bytes)) or not hasattr(item, "__len__") or len(item) != 3:
                raise TypeError(f"joints[{i}]: expected a triple (link_a, link_b, joint), got {item!r}")
            a = check_link(item[0], f"joints[{i}][0]")
            b = check_link(item[1], f"joints[{i}][1]")
            j = item[2]
            if not isinstance(j, Joint):
                raise TypeError(
                    f"joints[{i}][2]: expected a joint of screwsym.systems.joints (Revolute, "
                    f"Prismatic, Helical, Cylindrical, Universal, Spherical, Parallelogram), got "
                    f"{type(j).__name__}"
                )
            if a == b:
                raise ValueError(f"joints[{i}]: a joint joins two different links, got "
                                 f"{link_label(a)!r} twice")
            triples.append(Tuple(a, b, j))
        if not triples:
            raise ValueError("joints: expected at least one (link_a, link_b, joint), got none")
        if base is None:
            raise TypeError("base: expected the name of the fixed link, got None")
        base = check_link(base, "base")
        if not any(base in t.args[:2] for t in triples):
            raise ValueError(f"base: {link_label(base)!r} is not a link of any joint")
        obj = ScrewsymBasic.__new__(cls, Tuple(*triples), base)
        g = spanning_tree(obj)  # refuses a disconnected graph now
        if inertias is not None:
            pairs = check_inertias(inertias, g.index, base)
            if pairs.args:
                obj = ScrewsymBasic.__new__(cls, Tuple(*triples), base, pairs)
        return obj

    @classmethod
    def from_parallel(cls, pm: ParallelMechanism, inertias: Any = None) -> Mechanism:
        """The mechanism of a :class:`~screwsym.systems.parallel.ParallelMechanism`, as a graph.

        The links are ``"base"``, ``"platform"`` and, for limb ``i`` (from 1),
        ``"limb<i>.<k>"``, the ``k``-th link from the base; the joints are the limbs'
        in order (limb 1's first).  ``inertias`` as for :class:`Mechanism`, by those
        names: the dynamics of the parallel mechanism (:meth:`mass_matrix`,
        :meth:`inverse_dynamics`) in its actuated joints' rates.

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.parallel import Limb, ParallelMechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> pm = ParallelMechanism(Limb(R([0, 0, 0], z), R([1, 2, 0], z)),
        ...                        Limb(R([4, 0, 0], z), R([3, 3, 0], z)))
        >>> m = Mechanism.from_parallel(pm)
        >>> m.links
        ('base', 'limb1.1', 'platform', 'limb2.1')
        >>> m.relative_twists("platform").rank == pm.mobility().mobility == 1
        True
        """
        return _from_parallel(pm, inertias)

    # ------------------------------------------------------------ parts
    @property
    def base(self) -> Any:
        """The fixed link's name."""
        return link_label(self.args[1])

    @property
    def links(self) -> tuple[Any, ...]:
        """The links' names, the base first."""
        return tuple(link_label(x) for x in spanning_tree(self).links)

    @property
    def joints(self) -> tuple[tuple[Any, Any, Joint], ...]:
        """The triples ``(link_a, link_b, joint)`` as given."""
        return tuple((link_label(a), link_label(b), j) for a, b, j in self.args[0].args)

    @property
    def inertias(self) -> dict[Any, SpatialInertia]:
        """``{link: SpatialInertia}`` as given (in the space frame, at this configuration)."""
        return {link_label(p.args[0]): p.args[1] for p in self.inertia_pairs}

    @property
    def inertia_pairs(self) -> tuple[Tuple, ...]:
        """The inertias as ``(link, SpatialInertia)`` pairs of link objects, in link order."""
        return tuple(self.args[2].args) if len(self.args) > 2 else ()

    @property
    def freedom(self) -> int:
        """F, the sum of the joints' freedoms."""
        return sum(j.freedom for _, _, j in self.args[0].args)

    @property
    def loops(self) -> tuple[tuple[tuple[int, int], ...], ...]:
        """The fundamental loops: for each, ``(joint number, +1 or -1)`` in order round it.

        ``+1`` where the loop passes the joint from its ``link_a`` to its
        ``link_b``.  Each loop starts with the joint that closes it (the chord).

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> Mechanism([("g", "a", R([0, 0, 0], z)), ("a", "b", R([1, 0, 0], z)),
        ...            ("b", "g", R([1, 1, 0], z))], base="g").loops
        (((1, 1), (2, 1), (0, 1)),)
        """
        return spanning_tree(self).loops

    def network_matrix(self) -> ImmutableMatrix:
        """The 6L x F matrix of the loops' circulation equations (the network matrix).

        Row block ``i`` is loop ``i`` (:attr:`loops`); column ``k`` is the ``k``-th
        joint freedom, the joints in the order given, each joint's axes in order.
        """
        return ImmutableMatrix(network(self).A)

    # -------------------------------------------------------- first order
    def mobility(self, *, budget: int = BUDGET) -> MechanismMobility:
        r"""The **instantaneous** mobility and its parts, at the configuration given.

        Explanation
        ===========

        All figures are first order: they describe the joint rates (velocities)
        the loops allow here, not whether the mechanism can move a finite
        amount (see :meth:`second_order`).  With symbols in the geometry they
        are generic (for all values outside a proper algebraic subset): the
        rank is taken over the field of rational functions (of ``tan(q/2)`` for
        ``sin(q)``, ``cos(q)``: exact on the circle), with no case split
        (:meth:`mobility_cases` gives the exhaustive split), and
        many symbols make it slow (the 3-RPS with six symbols and ``sqrt(3)``
        takes minutes): give the symbols values where you can.  The work is
        bounded by ``budget`` (:data:`~screwsym.algebra.budget.BUDGET`), past
        which a ``ValueError`` names ``mobility``.

        - ``mobility``: ``M = F - rank``, the dimension of the null space of the
          network matrix (the independent joint rates), found exactly;
        - ``orders``, ``common``, ``common_constraints``: for each loop,
          ``d_i``, the rank of the loop's twists, ``lambda_i = 6 - d_i``, the
          count of its common constraints (as ``Mobility.common`` counts a
          parallel mechanism's), and a basis of them: the wrenches reciprocal
          to all its joint twists;
        - ``redundant``: ``nu = sum d_i - rank``, the loop equations that are
          consequences of the others (overconstraint beyond the common
          constraints), so that ``M = F - sum d_i + nu``;
        - ``passive``: zeta, the passive (idle) freedoms, as ``Mobility.passive``: joint rates allowed that leave
          at rest every link with other than two joints (the base, the links
          where loops meet, end links) and move each two-joint link so that its
          joints' axes, lines and centres stay where they are (the spin of an
          S-S or S-P-S leg about its own line); ``passive_rates`` a basis;
        - ``classical``: the Grübler–Kutzbach count ``6 (N - J - 1) + F``.

        Examples
        ========

        An S-P-S leg closed on the base spins about its line: its one
        freedom is idle.

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import P, S
        >>> m = Mechanism([("base", "lower", S([0, 0, 0])), ("lower", "upper", P([0, 0, 1])),
        ...                ("upper", "base", S([0, 0, 2]))], base="base").mobility()
        >>> m.mobility, m.passive, m.orders
        (1, 1, (6,))
        """
        with case_budget(budget, "mobility"):
            return self._mobility()

    def _mobility(self) -> MechanismMobility:
        net = network(self)
        g = net.graph
        orders, commons = [], []
        for loop in g.loops:
            T = ScrewSystem(*(Twist(t[:3], t[3:]) for e, _ in loop for t in net.twists[e]))
            orders.append(T.rank)
            commons.append(T.reciprocal())
        idle = _idle(net)
        assert idle is not None  # the generic null space is always found
        return _figures(net, tuple(orders), tuple(commons), net.null, idle)

    def mobility_cases(
        self, *, max_cases: int = MAX_CASES, budget: int = BUDGET, merge: bool = True
    ) -> list[tuple[Any, MechanismMobility | Degenerate | None]]:
        r"""The **instantaneous** mobility in each case where the symbols change a rank: an exhaustive split.

        Explanation
        ===========

        :meth:`mobility` is generic in the symbols; this splits the real
        values of the symbols into cases, each a SymPy boolean (``Eq``, ``Ne``,
        ``And``) with its :class:`MechanismMobility`.  Every real point satisfies
        at least one case; at every point of a case its ``mobility`` and
        ``rank`` hold exactly, and so do ``orders`` (the rank of each loop's
        twists); ``common``, ``redundant`` follow from them, while ``passive`` and
        the bases are those of the case's generic point.

        The split is made by the rank conditions of
        :meth:`ScrewSystem.rank_conditions
        <screwsym.systems.screw_system.ScrewSystem.rank_conditions>`, exact
        (irreducible factors of minors, solved for a symbol they are linear
        in), first on each loop's twists, then on the network matrix loop by
        loop: with ``N`` a basis of the joint rates that close loops
        ``1..i-1`` (valid on the whole case: Cramer's rule on the minor that
        proves the case's rank, so its leading entries are that non-zero
        minor), the rates that also close loop ``i`` are the null space of the
        six-row matrix ``A_i N``, whose rank conditions split the case again;
        ``rank = F - dim`` of the final null space.  Geometry polynomial in
        ``sin`` and ``cos`` of symbols is split as
        :meth:`ScrewSystem.rank_conditions
        <screwsym.systems.screw_system.ScrewSystem.rank_conditions>` splits it: a
        condition in ``sin(q)``, ``cos(q)`` of one angle is decided at each of its
        points on the circle (``q = pi`` included), written
        ``Eq(sin(q), s) & Eq(cos(q), c)`` and, merged, ``Eq(sin(q), 0)`` for both
        points.  A case that no substitution states (an equation ``f = 0``
        linear in no symbol, ``x**2 + y**2 = 2``, ``cos(a) + cos(b) = 1``) is
        split on: its rank is proved modulo ``f`` (:meth:`ScrewSystem.rank_conditions
        <screwsym.systems.screw_system.ScrewSystem.rank_conditions>`), and so
        is every later split of the case, so its figures hold at every point of
        it as elsewhere (its idle rates those of the surface's generic point).
        A case comes with ``None`` only where the rank conditions give ``None``
        (two such surfaces in three or more symbols meeting).  A case whose
        values unmake a joint (a zero
        axis, a universal joint's axes made parallel) comes with a
        :class:`~screwsym.systems.parallel.Degenerate` naming the joint,
        ``joints[k] (link_a, link_b): <its error>``; these are listed last,
        as :meth:`ParallelMechanism.mobility_cases
        <screwsym.systems.parallel.ParallelMechanism.mobility_cases>` lists them.
        Cases whose conditions contradict each other are left out.  At most
        ``max_cases`` cases (a ``ValueError`` beyond), and at most ``budget``
        units of polynomial arithmetic for the whole split (as
        :meth:`ScrewSystem.rank_conditions
        <screwsym.systems.screw_system.ScrewSystem.rank_conditions>`).  The split costs a case
        analysis per loop and case: Tsai's 3-UPU as a graph (15 freedoms, two
        loops, two symbols) takes about 20 s; give symbols values where you can.

        With ``merge=True`` (the default) cases with the same answer
        (:meth:`MechanismMobility.answer`) are given as one, whose condition is
        the ``Or`` of theirs (or, where that is shorter and made of
        inequalities alone, the negation of the other cases': the cases hold
        one at each point), in the place of the first, with the first case's
        :class:`MechanismMobility`; ``merge=False`` gives each case with its own.

        Examples
        ========

        The four-bar whose coupler joint is at ``(1, b)``: one freedom, but
        two instantaneous ones when ``b = 0`` (the four axes in one plane: the
        four-bar folded flat on the ground line; the loop's twists drop to
        order 2).

        >>> from sympy import symbols
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> b = symbols("b", real=True)
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, b, 0], z)),
        ...                      ("coupler", "rocker", R([3, 0, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> [(case, m.mobility, m.orders) for case, m in fourbar.mobility_cases()]
        [(Ne(b, 0), 1, (3,)), (Eq(b, 0), 2, (2,))]

        The coupler joint at ``(1, s**2 + t**2 - 2)``: the four-bar folds on a
        circle, a case no substitution states; it is decided on the circle
        itself, its joint rates proved there.

        >>> s, t = symbols("s t", real=True)
        >>> on_circle = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                        ("crank", "coupler", R([1, s**2 + t**2 - 2, 0], z)),
        ...                        ("coupler", "rocker", R([3, 0, 0], z)),
        ...                        ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> [(case, m.mobility) for case, m in on_circle.mobility_cases()]
        [(Ne(s**2 + t**2 - 2, 0), 1), (Eq(s**2 + t**2 - 2, 0), 2)]
        >>> on_circle.mobility_cases()[1][1].rates.T
        Matrix([
        [2, -3, 1, 0],
        [3, -4, 0, 1]])
        """
        max_cases = check_count(max_cases, "max_cases")
        merge = check_flag(merge, "merge")
        with case_budget(budget, "mobility_cases"):
            out = _mobility_cases(self, max_cases)
        merged = merge_cases(cast("list[tuple[Any, Any]]", out)) if merge else out
        return cast("list[tuple[Any, MechanismMobility | Degenerate | None]]", merged)

    def relative_twists(self, link: Any, relative_to: Any = None) -> ScrewSystem:
        """The instantaneous motions of ``link`` relative to ``relative_to`` (the base by default).

        For every joint rate the loops allow (a basis of the null space), the
        twist of ``link`` is the sum of the joint twists along the tree from the
        base, and the same for ``relative_to``; the result is the
        :class:`~screwsym.systems.screw_system.ScrewSystem` of their
        differences (a basis, generic in the symbols).

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import Parallelogram
        >>> pa = Parallelogram([0, 0, 0], [1, 0, 0], [0, 0, 2])
        >>> Mechanism(pa.links("a", "b"), base="a").relative_twists("b")   # a translation
        ScrewSystem(Twist([0, 0, 0], [1, 0, 0]))
        >>> pa.twists                                              # the compound pair: the same
        ScrewSystem(Twist([0, 0, 0], [-4, 0, 0]))
        """
        target = self._link_number(link, "link")
        ref = 0 if relative_to is None else self._link_number(relative_to, "relative_to")
        net = network(self)
        J = (path_matrix(net, target) - path_matrix(net, ref)) * net.null
        cols = [clean_vector(list(J.col(k))) for k in range(J.cols)]
        members = [Twist(c[:3], c[3:]) for c in cols if any(e != 0 for e in c)]
        if not members:
            return ScrewSystem(kind=Twist)
        return _reduced(ScrewSystem(*members).basis())

    def motion(self, link: Any, relative_to: Any = None) -> str | None:
        """The motion type of ``link`` relative to ``relative_to``: ``"3T"``, ``"1R"``, ``"1H"``, ...

        The label of :func:`~screwsym.systems.motion_type.motion_of` for
        :meth:`relative_twists`: translations, rotations, helical freedoms (translations
        first, "3T1R"), generic in the symbols; :meth:`helical_pitches` gives
        the pitch of each helical freedom.  None where the helical freedoms depend
        on the signs of the symbols (see ``motion_of``).
        """
        return motion_of(self.relative_twists(link, relative_to)).motion

    def helical_pitches(self, link: Any, relative_to: Any = None) -> tuple | None:
        """The pitches of the helical freedoms ("H" in :meth:`motion`) of ``link`` relative to
        ``relative_to`` (None with :meth:`motion`)."""
        return motion_of(self.relative_twists(link, relative_to)).helical_pitches

    def _link_number(self, link: Any, name: str) -> int:
        key = check_link(link, name)
        g = spanning_tree(self)
        if key not in g.index:
            raise ValueError(f"{name}: {link_label(key)!r} is not a link of this mechanism")
        return int(g.index[key])

    # ------------------------------------------------------ second order
    def quadratic_terms(self, rates: Any) -> ImmutableMatrix:
        r"""The second-order terms of the loop closure for the joint rates ``rates``.

        For each loop, ``sum_{k<l} [$_k, $_l] qdot_k qdot_l + sum_k Y_k qdot_k**2``
        (see the module docstring), stacked like the rows of
        :meth:`network_matrix`: a motion ``q(t)`` of the closed loops with
        ``q'(0) = rates`` has ``network_matrix() * q''(0) + quadratic_terms(rates) = 0``.
        """
        net = network(self)
        q = Matrix(rates)
        if q.shape != (net.A.cols, 1):
            raise ValueError(f"rates: expected {net.A.cols} joint rates, got shape {q.shape}")
        out = zeros(net.A.rows, 1)
        for i, (pairs, squares) in enumerate(loop_terms(net)):
            block = zeros(6, 1)
            for a, b, c in pairs:
                block += Matrix(c) * q[a] * q[b]
            for a, y in squares:
                block += Matrix(y) * q[a] ** 2
            out[6 * i:6 * i + 6, 0] = block
        return ImmutableMatrix(out.applyfunc(expand))

    def second_order(self) -> SecondOrder:
        r"""How far the instantaneous motions extend: the mobility **to second order**.

        Explanation
        ===========

        A first-order motion ``qdot = N x`` (``N`` the basis
        ``mobility().rates``) extends to second order iff the quadratic terms
        (:meth:`quadratic_terms`) lie in the column span of the network matrix,
        that is iff ``w . quadratic_terms(N x) = 0`` for every ``w`` in the left
        null space of the network matrix: one quadratic form ``x^T Q_w x`` per
        ``w`` (``forms``).  The set of such ``x`` is the second-order cone; it is
        decided exactly, by Lagrange's reduction of each form to squares:
        a semidefinite form vanishes on its kernel, an indefinite one of rank 2
        on two hyperplanes, and the cone is the union of linear spaces these
        cut out (``cone``, as joint rates).  ``mobility`` is its dimension,
        ``branches`` the number of its components (several where motion modes
        meet, as a flat parallelogram's two do).  An indefinite form of rank 3
        or more is a quadric cone: its dimension is known when no other form
        remains, else the test cannot decide and says ``None``; likewise with
        symbols in a form that does not vanish identically (with ``sin(q)``,
        ``cos(q)``: identically on the circle, decided exactly in the ring of
        :mod:`~screwsym.systems.screw_system`).

        A mobility to second order is not a proof of a finite motion (a
        higher order may stop it); a drop below ``instantaneous`` is a proof that
        the missing first-order motions are not finite: the configuration is
        *shaky* in those directions (Müller 2016, §3).

        Examples
        ========

        Four revolutes on the lines of one regulus of the hyperboloid
        ``x**2 + y**2 - z**2 = 1``: one instantaneous freedom, none to second
        order (a shaky 4R; Müller 2016, §6).

        >>> from sympy import Rational as Q
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> ring = [(1, 0), (0, 1), (-1, 0), (Q(3, 5), Q(-4, 5))]
        >>> axes = [R([c, s, 0], [-s, c, 1]) for c, s in ring]
        >>> shaky = Mechanism([(k, (k + 1) % 4, axes[k]) for k in range(4)], base=0)
        >>> shaky.mobility().mobility, shaky.second_order().mobility
        (1, 0)
        """
        return second_order_of(self)



def _put(M: Matrix, subs: dict | None) -> Matrix:
    """``M`` with a case's substitution made (``sin(q)``, ``cos(q)`` reach ``sin(2 q)``)."""
    return Matrix(apply_subs(M, subs)) if subs else M


def _relations(node: Any) -> Matrix:
    """A basis of the linear relations among the members of a case (its columns' null space).

    Cramer's rule on the minor that proves the case's rank: for each member
    ``j`` off the minor, ``x_j = m`` (the minor, non-zero on the whole case)
    and ``x_p = -`` the minor with member ``p`` replaced by ``j``.  So the
    basis is valid at every point of the case, not only generically.  The
    determinants are taken in the polynomial ring of the case, on the members
    cleared of their denominators (``cleared_k = d_k member_k``), so the
    relation among the members themselves is ``x_k d_k``.
    """
    k = node.matrix.cols
    members = list(node.rows)
    free = [j for j in range(k) if j not in members]
    if not free:
        return zeros(k, 0)
    if not members:
        return Matrix.eye(k)
    rg = to_ring(node.matrix)
    R = rg.ring
    B = [swapped(c) for c in rg.cols]
    cols = list(node.cols)
    m = det_rows([[B[p][c] for c in cols] for p in members], R)
    scale = [to_expr(d, R) for d in rg.scales]
    out = []
    for j in free:
        x = [Integer(0)] * k
        x[j] = to_expr(m, R) * scale[j]
        for pp, p in enumerate(members):
            rows = [[B[j if q == pp else members[q]][c] for c in cols] for q in range(len(members))]
            x[p] = -to_expr(det_rows(rows, R), R) * scale[p]
        out.append(Matrix(x).applyfunc(expand))
    return Matrix.hstack(*out)


def _polynomial_columns(block: Matrix, N: Matrix) -> tuple[Matrix, Matrix]:
    """``block`` and ``N`` with each column of ``block`` cleared of its denominators, and the
    same column of ``N`` scaled alike (a non-zero factor wherever the geometry is defined)."""
    block, N = Matrix(block), Matrix(N)
    for c in range(block.cols):
        entries = [cancel(e) for e in block.col(c)]
        den = reduce(lcm, [fraction(e)[1] for e in entries], Integer(1))
        if den != 1:
            entries = [cancel(e * den) for e in entries]
            N[:, c] = (N.col(c) * den).applyfunc(expand)
        block[:, c] = Matrix(entries)
    return block, N


def _named_joints(mech: Mechanism) -> list[tuple[str, Joint]]:
    return [(f"joints[{k}] ({a!r}, {b!r})", j) for k, (a, b, j) in enumerate(mech.joints)]


def _mobility_cases(mech: Mechanism,
                    limit: int) -> list[tuple[Any, MechanismMobility | Degenerate | None]]:
    """The split of :meth:`Mechanism.mobility_cases` before merging: by each loop's twists
    (its order, exact on each case), then by the network matrix loop by loop, the joint rates
    closing the loops so far carried in each leaf
    (:func:`~screwsym.systems._cases.split_mechanism`)."""
    net = network(mech)
    g = net.graph
    A = net.A
    F = A.cols
    if not A.free_symbols:
        return [(true, mech.mobility())]
    used = [sorted({g.offsets[e] + k for e, _ in loop for k in range(g.edges[e][2].freedom)})
            for loop in g.loops]

    def rows(i: int) -> list[int]:
        return list(range(6 * i, 6 * i + 6))

    def order(i: int) -> Stage:
        # the loop's twists: its order with the node that proved it (recorded in leaf.nodes)
        return Stage(lambda leaf: (ImmutableMatrix(_put(A.extract(rows(i), used[i]), leaf.subs)),
                                   None))

    def closure(i: int) -> Stage:
        def system(leaf: Leaf) -> tuple[ImmutableMatrix, Matrix]:
            rates = Matrix.eye(F) if leaf.extra is None else leaf.extra
            block = _put(A.extract(rows(i), list(range(F))), leaf.subs)
            block, N = _polynomial_columns(block * rates, rates)
            return ImmutableMatrix(block), N

        def grow(leaf: Leaf, node: Any, N: Matrix) -> Leaf:
            rates = (_put(N, dict(node.subs)) * _relations(node)).applyfunc(cancel)
            return leaf._replace(extra=rates)

        return Stage(system, grow)

    def result(leaf: Leaf) -> MechanismMobility | None:
        here = trig_substitute(mech, leaf.subs) if leaf.subs else mech
        if leaf.relation:  # on a surface: the figures of the split, proved there
            return _on_surface_mobility(here, leaf)
        m = here.mobility()
        if m.mobility != leaf.extra.cols:  # pragma: no cover - the split proves the rank
            raise AssertionError("mobility_cases: the case's rank and its generic rank differ")
        return m

    loops = range(len(g.loops))
    stages = [order(i) for i in loops] + [closure(i) for i in loops]
    named = _named_joints(mech)
    return split_mechanism(stages, named, named, result, Degenerate, limit)


def _on_surface_mobility(mech: Mechanism, leaf: Leaf) -> MechanismMobility | None:
    """The figures of a case on a surface ``fe = 0`` (``leaf.relation``) from its split.

    The mobility, rank, orders and common constraints are proved at every point of the
    case (the split proved each rank there, and each basis is Cramer's rule on the
    minor that proved it); the idle rates, as elsewhere, are those of the generic point
    of the case, here of the surface (the null space proved modulo ``fe``).  None where
    no point of the surface proved that null space.
    """
    fe = leaf.relation[0]
    net = bare_network(mech)
    N = cast(Matrix, leaf.extra)
    N = Matrix.hstack(*(Matrix(clean_vector(list(N.col(k)))) for k in range(N.cols))) if N.cols \
        else N

    def nullspace(C: Matrix) -> Matrix | None:
        found = null_on_surface(ImmutableMatrix(C), fe)
        if found is None:
            return None
        return Matrix(found[2])

    idle = _idle(net, N, nullspace)
    if idle is None:  # pragma: no cover - no point of the surface proved the idle rates
        return None
    # each basis by Cramer's rule on the minor that proved its loop's order (non-zero on
    # the case), written with the case's substitution (a later case's may set more symbols)
    return _figures(net, tuple(node.rank for node in leaf.nodes),
                    tuple(basis_with(node, Wrench, leaf.subs) for node in leaf.nodes), N, idle)


def _figures(net: Network, orders: tuple, common: tuple, rates: Matrix,
             idle: Matrix) -> MechanismMobility:
    """The figures of :class:`MechanismMobility` from each loop's order and common
    constraints, the joint rates allowed and the idle ones."""
    g = net.graph
    F = net.A.cols
    rank = F - rates.cols
    n, J = len(g.links), len(g.edges)
    return MechanismMobility(
        mobility=rates.cols,
        freedoms=F,
        loops=len(g.loops),
        rank=rank,
        orders=orders,
        common=tuple(6 - d for d in orders),
        common_constraints=common,
        redundant=sum(orders) - rank,
        passive=idle.cols,
        passive_rates=ImmutableMatrix(idle),
        rates=ImmutableMatrix(rates),
        classical=6 * (n - J - 1) + F,
        links=n,
        joints=J,
    )


def _idle(net: Network, N: Matrix | None = None, nullspace: Any = None) -> Matrix | None:
    """A basis of the idle rates among the rates ``N`` (the network's null space by default),
    the null space taken by ``nullspace`` (generic: ``nullspace_basis``); None where it says None."""
    g = net.graph
    N = net.null if N is None else N
    if N.cols == 0:
        return zeros(N.rows, 0)
    rows: list[Matrix] = []
    carried: list[list[Matrix]] = [[] for _ in g.links]
    for e, (a, b, j) in enumerate(g.edges):
        for side, link in ((0, a), (1, b)):
            if g.degree[link] == 2:
                carried[link].extend(_elements(j, net.twists[e], side))
    for link in range(1, len(g.links)):
        P = path_matrix(net, link) * N
        if g.degree[link] != 2:
            rows.append(P)
        else:
            rows.extend(op * P for op in carried[link])
    if not rows:
        return Matrix(N)
    C = Matrix.vstack(*rows)
    K = (nullspace or nullspace_basis)(C)
    if K is None:
        return None
    if K.cols == 0:
        return zeros(N.rows, 0)
    cols = [clean_vector(list((N * K).col(k))) for k in range(K.cols)]
    return Matrix.hstack(*(Matrix(c) for c in cols))


def _line_op(t: Any) -> Matrix:
    return ad_matrix(list(t))


def _point_op(p: Any) -> Matrix:
    # the velocity at p: v_O + omega x p = v_O - p x omega
    return Matrix.hstack(-cross_matrix(list(p)), Matrix.eye(3))


def _elements(j: Joint, twists: tuple, side: int) -> list[Matrix]:
    """Operators on a link's twist that vanish when the joint's geometry in that link is at rest."""
    if isinstance(j, Spherical):
        return [_point_op(j.args[0])]
    if isinstance(j, Universal):
        return [_line_op(twists[side]), _point_op(j.args[0])]
    if isinstance(j, Parallelogram):
        p1, p2, q1 = j.args
        n = j.normal
        pts = (p1, p2) if side == 0 else (q1, q1 + p2 - p1)
        return [_line_op(list(n) + list(Matrix(p).cross(n))) for p in pts]
    ops = []
    for t in twists:
        if all(e == 0 for e in t[:3]):  # a direction (prismatic)
            ops.append(Matrix.hstack(-cross_matrix(t[3:]), zeros(3)))
        else:
            ops.append(_line_op(t))
    return ops




def _from_parallel(pm: ParallelMechanism, inertias: Any = None) -> Mechanism:
    if not isinstance(pm, ParallelMechanism):
        raise TypeError(f"pm: expected a ParallelMechanism, got {type(pm).__name__}")
    triples = []
    for i, limb in enumerate(pm.limbs):
        chain = ["base"] + [f"limb{i + 1}.{k}" for k in range(1, len(limb.joints))] + ["platform"]
        for k, j in enumerate(limb.joints):
            triples.append((chain[k], chain[k + 1], j))
    return Mechanism(triples, base="base", inertias=inertias)


def _reduced(system: ScrewSystem) -> ScrewSystem:
    """A basis of rational twists in reduced echelon form, each member primitive (small
    integers): a null space taken link by link has entries of 1e17 where the span is
    the identity's (issue 32).  A basis with symbols or surds is kept as it is."""
    rows = [list(t.matrix) for t in system.screws]
    if not rows or not all(e.is_Rational for r in rows for e in r):
        return system
    E = Matrix(rows).rref()[0]
    out = [clean_vector(list(E.row(i))) for i in range(E.rows) if any(e != 0 for e in E.row(i))]
    return ScrewSystem(*(Twist(c[:3], c[3:]) for c in out))
