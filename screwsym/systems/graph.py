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

from collections import deque
from dataclasses import dataclass
from functools import lru_cache, reduce
from typing import TYPE_CHECKING, Any, NamedTuple, cast

from sympy import (
    QQ,
    Add,
    And,
    Basic,
    Dummy,
    ImmutableMatrix,
    Integer,
    Matrix,
    Mul,
    Ne,
    Symbol,
    Tuple,
    cancel,
    cos,
    expand,
    false,
    fraction,
    igcd,
    ilcm,
    lcm,
    radsimp,
    sin,
    sqrt,
    true,
    zeros,
)
from sympy.core.symbol import Str
from sympy.polys.matrices import DomainMatrix
from sympy.polys.polyutils import parallel_dict_from_expr

from ..core.basic import ScrewsymBasic
from ..core.checks import check_count, check_flag
from ..core.decide import is_zero
from ..core.twist import Twist
from ..core.wrench import Wrench
from .joints import Joint, Parallelogram, Spherical, Universal
from .mechanism import (
    Degenerate,
    ParallelMechanism,
    _check_cases,
    _merge_cases,
    _unmade_on_surface,
    motion_of,
)
from .screw_system import (
    _TRIG_BACK,
    BUDGET,
    MAX_CASES,
    ScrewSystem,
    _apply,
    _basis_with,
    _cases,
    _circle_normal,
    _coefficient,
    _det,
    _field,
    _null_on_surface,
    _on_circle,
    _poly_expr,
    _primitive,
    _rational_parts,
    _substitute,
    _surface_cases,
    _swap,
    _to_ring,
    _trig_entries,
    _vanishes,
    _within,
    case_budget,
)

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["Mechanism", "MechanismMobility", "SecondOrder", "lie_bracket"]


# ------------------------------------------------------------------ screws


def _skew(v: Any) -> Matrix:
    x, y, z = v
    return Matrix([[0, -z, y], [z, 0, -x], [-y, x, 0]])


def _ad(s: Any) -> Matrix:
    """The 6 x 6 matrix of ``X -> [s, X]`` for a twist ``s = (w; v)`` in ray order."""
    w, v = _skew(s[:3]), _skew(s[3:])
    return Matrix.vstack(Matrix.hstack(w, zeros(3)), Matrix.hstack(v, w))


def _bracket(a: Any, b: Any) -> list:
    """``[a, b] = (wa x wb; wa x vb - wb x va)`` of two 6-vectors (ray order)."""
    wa, va, wb, vb = Matrix(a[:3]), Matrix(a[3:]), Matrix(b[:3]), Matrix(b[3:])
    return list(wa.cross(wb)) + list(wa.cross(vb) - wb.cross(va))


def lie_bracket(a: Twist, b: Twist) -> Twist:
    r"""The Lie bracket of two twists in the book's ray order: ``(wa x wb; wa x vb - wb x va)``.

    Explanation
    ===========

    For twists ``a = (wa; va)`` and ``b = (wb; vb)`` (``v`` the velocity of
    the body point at the origin) this is ``ad_a b``, the derivative of ``b``
    carried by the motion ``exp6(a t)``: ``d/dt Ad_{exp6(a t)} b`` at ``t = 0``
    (Murray, Li & Sastry 1994, §2.4, written here in the order ``(w; v)``).  It
    is what the second-order loop-closure condition of :meth:`Mechanism.second_order`
    uses; the tests check it against a finite motion.

    Examples
    ========

    Two rotations about parallel axes do not commute: their bracket is a
    translation at right angles to both axes, in their plane.

    >>> from screwsym import Twist
    >>> from screwsym.systems.graph import lie_bracket
    >>> lie_bracket(Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...             Twist.rotation([0, 0, 1], point=[1, 0, 0]))
    Twist([0, 0, 0], [1, 0, 0])
    """
    for value, name in ((a, "a"), (b, "b")):
        if not isinstance(value, Twist):
            raise TypeError(f"{name}: expected a Twist, got {type(value).__name__}")
    c = _bracket(list(a.matrix), list(b.matrix))
    return Twist(c[:3], c[3:])


# ------------------------------------------------------ exact linear algebra


#: the half-angle symbol ``t = tan(q/2)`` of each angle ``q`` (:func:`_half_angle`); and its angle
_HALF: dict = {}
_HALF_BACK: dict = {}


def _half_angle(q: Any) -> Dummy:
    t = _HALF.get(q)
    if t is None:
        t = Dummy(f"t_{q}", real=True)
        _HALF[q] = t
        _HALF_BACK[t] = q
    return t


def _from_half_angle(row: list) -> list:
    """A vector over the rational functions of ``t = tan(q/2)`` (and the other symbols) as
    polynomials in ``sin(q)``, ``cos(q)``: the same vector up to a factor non-zero generically.

    Cleared of denominators and of the common factor, a polynomial vector of degree ``D``
    in ``t`` divided by ``(1 + t**2)**n``, ``n = ceil(D/2)``, is one of degree ``n`` in
    ``sin(q)`` and ``cos(q)``: with ``t = sin(q)/(1 + cos(q))`` and ``1 + t**2 =
    2/(1 + cos(q))``, ``t**k/(1 + t**2)**n = sin(q)**(k % 2) (1 - cos(q))**(k // 2)
    (1 + cos(q))**(n - k + k // 2) / 2**n`` (``sin(q)**2 = (1 - cos(q)) (1 + cos(q))``),
    a polynomial for every ``k <= 2 n``.
    """
    nz = [e for e in row if e]
    ring = nz[0].numer.ring
    den = ring.one
    for e in nz:
        den = den.lcm(e.denom)
    polys = [e.numer * den.exquo(e.denom) if e else ring.zero for e in row]
    g = ring.zero
    for p in polys:
        if p:
            g = p if not g else g.gcd(p)
    polys = [p.exquo(g) if p else p for p in polys]
    angles = {i: _HALF_BACK[x] for i, x in enumerate(ring.symbols) if x in _HALF_BACK}
    half = {i: (max(p.degree(i) for p in polys if p) + 1) // 2 for i in angles}
    K0 = ring.domain
    out = []
    for p in polys:
        terms = []
        for monom, c in p.terms():
            factors = [K0.to_sympy(c)]
            for i, k in enumerate(monom):
                if i in angles:
                    q, n = angles[i], half[i]
                    factors.append(sin(q) ** (k % 2) * (1 - cos(q)) ** (k // 2)
                                   * (1 + cos(q)) ** (n - k + k // 2))
                elif k:
                    factors.append(ring.symbols[i] ** k)
            terms.append(Mul(*factors))
        out.append(Add(*terms))
    return out


def _trig(entries: Any) -> bool:
    return any(e.has(sin, cos) for e in entries)


def _dm(M: Matrix) -> DomainMatrix:
    """``M`` over its field: QQ, an algebraic field, or rational functions over one.

    The entries go through polynomial dictionaries and the cached algebraic
    coefficients of :mod:`screwsym.systems.screw_system` (``K.from_sympy`` on an
    algebraic field computes a minimal polynomial per entry: seconds).

    ``sin(q)`` and ``cos(q)`` of a symbol (sums and multiples expanded) live on
    the unit circle, whose rational functions are those of ``t = tan(q/2)``
    (:func:`~screwsym.systems.screw_system._on_circle`, a bijection of the two
    fields): they are written in ``t``, so that rank and null space are exact,
    the generic ones on the circle (a field of fractions in ``sin(q)``,
    ``cos(q)`` as free symbols would not know ``sin(q)**2 + cos(q)**2 = 1``).
    :func:`_nullspace` writes its basis back in ``sin(q)`` and ``cos(q)``.
    """
    entries = list(M)
    if all(e.is_Rational for e in entries):  # the common case, at once
        rows = [[QQ(int(e.p), int(e.q)) for e in entries[i * M.cols:(i + 1) * M.cols]]
                for i in range(M.rows)]
        return DomainMatrix(rows, (M.rows, M.cols), QQ)
    trig = _trig(entries)
    if trig:
        entries = _trig_entries(entries)  # sin(q), cos(q) as the ring's symbols, then in t
        half = {}
        for x in set().union(*(e.free_symbols for e in entries)):
            back = _TRIG_BACK.get(x)
            if back is not None:
                point = _on_circle(_half_angle(back.args[0]))
                half[x] = point[0] if back.func is sin else point[1]
        entries = [e.xreplace(half) for e in entries]
    syms, numbers, parts = _rational_parts(entries, "joints: expected geometry")
    K0 = _field(tuple(sorted(set(numbers), key=str)))
    gens = tuple(syms) if syms else (Dummy("c"),)
    R = K0[gens]
    K = K0.frac_field(*syms) if syms else K0
    dicts, _ = parallel_dict_from_expr(parts, gens=gens) if parts else ([], None)
    polys = [R.ring.from_dict({m: _coefficient(K0, c) for m, c in d.items()}) for d in dicts]
    values = []
    for k in range(len(entries)):
        num, den = polys[2 * k], polys[2 * k + 1]
        if syms:
            values.append(K.convert_from(num, R) / K.convert_from(den, R))
        else:
            values.append(num.LC / den.LC if num else K0.zero)
    rows = [values[i * M.cols:(i + 1) * M.cols] for i in range(M.rows)]
    return DomainMatrix(rows, (M.rows, M.cols), K)


def _clean(v: list) -> list:
    """A vector scaled to lowest terms: no denominators, no common factor, first entry positive.

    With ``sin``/``cos`` of symbols, in the ring of :mod:`~screwsym.systems.screw_system`:
    polynomial, reduced by ``sin(q)**2 + cos(q)**2 = 1`` (so an entry zero on the circle is 0).
    """
    if _trig(v):
        rg = _to_ring(ImmutableMatrix(len(v), 1, v))
        return [_poly_expr(e, rg.ring) for e in _primitive(list(rg.cols[0]), rg.ring)]
    v = [cancel(e) for e in v]
    nz = [e for e in v if e != 0]
    if not nz:
        return v
    if all(e.is_Rational for e in nz):
        den = reduce(ilcm, [int(e.q) for e in nz])
        ints = [e * den for e in v]
        g = reduce(igcd, [abs(int(e)) for e in ints if e != 0])
        v = [e / g for e in ints]
    else:
        den = reduce(lcm, [fraction(e)[1] for e in nz], Integer(1))
        v = [cancel(e * den) for e in v]
    first = next(e for e in v if e != 0)
    if first.is_number and first.is_negative or (not first.is_number
                                                  and first.could_extract_minus_sign()):
        v = [-e for e in v]
    return v


def _nullspace(M: Matrix) -> Matrix:
    """A basis of the (generic) null space of ``M``, as the columns of a matrix."""
    if M.rows == 0:
        return Matrix.eye(M.cols)
    if M.cols == 0:
        return zeros(0, 0)
    null = _dm(M).nullspace()
    if _trig(M) and null.domain.is_FractionField:  # from t = tan(q/2) to sin(q), cos(q)
        cols = [_clean(_from_half_angle(row)) for row in null.to_list()]
    else:
        null = null.to_Matrix()
        cols = [_clean(list(null.row(i))) for i in range(null.rows)]
    return Matrix.hstack(*(Matrix(c) for c in cols)) if cols else zeros(M.cols, 0)


def _rank(M: Matrix) -> int:
    if M.rows == 0 or M.cols == 0:
        return 0
    return int(_dm(M).rank())


# --------------------------------------------------------------- the graph


def _check_link(value: Any, name: str) -> Basic:
    if isinstance(value, str):
        return Str(value)
    if isinstance(value, bool) or value is None:
        raise TypeError(f"{name}: expected a link name (a string or a SymPy symbol), got {value!r}")
    if isinstance(value, int):
        return Integer(value)
    if isinstance(value, (Symbol, Str, Integer)):
        return value
    raise TypeError(
        f"{name}: expected a link name (a string or a SymPy symbol), got {type(value).__name__}"
    )


def _label(link: Basic) -> Any:
    """The name as the user wrote it: a ``str`` for a string, an ``int`` for an integer."""
    if isinstance(link, Str):
        return link.name
    if isinstance(link, Integer):
        return int(link)
    return link


@dataclass(frozen=True)
class _Graph:
    links: tuple  # link objects, base first, then in order of discovery
    index: dict  # link -> its number
    edges: tuple  # (a, b, joint): link numbers and the joint
    offsets: tuple  # the number of joint e's first freedom
    paths: tuple  # per link: ((edge, sign), ...) along the tree from the base
    loops: tuple  # per chord: ((edge, sign), ...) round the loop, from the chord's link_a
    degree: tuple  # the number of joints at each link


def _spanning(mech: Mechanism) -> _Graph:
    triples, base = mech.args
    links: list = [base]
    index = {base: 0}
    edges = []
    for a, b, j in triples:
        for x in (a, b):
            if x not in index:
                index[x] = len(links)
                links.append(x)
        edges.append((index[a], index[b], j))
    incident: list[list[int]] = [[] for _ in links]
    for e, (a, b, _) in enumerate(edges):
        incident[a].append(e)
        incident[b].append(e)
    paths: list = [None] * len(links)
    paths[0] = ()
    tree = set()
    queue = deque([0])
    while queue:
        x = queue.popleft()
        for e in incident[x]:
            a, b, _ = edges[e]
            y, sign = (b, 1) if a == x else (a, -1)
            if paths[y] is None:
                paths[y] = paths[x] + ((e, sign),)
                tree.add(e)
                queue.append(y)
    missing = [_label(links[i]) for i, p in enumerate(paths) if p is None]
    if missing:
        raise ValueError(
            f"joints: the links {', '.join(repr(m) for m in missing)} are not connected to the "
            f"base {_label(base)!r} (the mechanism must be one connected graph)"
        )
    loops = []
    for e, (a, b, _) in enumerate(edges):
        if e in tree:
            continue
        pa, pb = paths[a], paths[b]
        c = 0
        while c < min(len(pa), len(pb)) and pa[c] == pb[c]:
            c += 1
        up = tuple((f, -s) for f, s in reversed(pb[c:]))
        loops.append(((e, 1),) + up + pa[c:])
    offsets, total = [], 0
    for _, _, j in edges:
        offsets.append(total)
        total += j.freedom
    return _Graph(tuple(links), index, tuple(edges), tuple(offsets), tuple(paths),
                  tuple(loops), tuple(len(i) for i in incident))


@dataclass(frozen=True)
class _Network:
    graph: _Graph
    twists: tuple  # per joint: its twists as lists of 6 entries
    accel: tuple  # per joint: its accelerations (lists of 6) or None
    A: Matrix  # 6L x F
    rank: int
    null: Matrix  # F x M


@lru_cache(maxsize=64)
def _network(mech: Mechanism) -> _Network:
    net = _bare_network(mech)
    null = _nullspace(net.A) if net.graph.loops else Matrix.eye(net.A.cols)
    return _Network(net.graph, net.twists, net.accel, net.A, net.A.cols - null.cols, null)


def _bare_network(mech: Mechanism) -> _Network:
    """The network without its (generic) null space: ``rank`` and ``null`` left empty."""
    g = _spanning(mech)
    twists = tuple(tuple(list(t.matrix) for t in j._twists()) for _, _, j in g.edges)
    accel = tuple(tuple(None if y is None else list(y.matrix) for y in j._accelerations())
                  for _, _, j in g.edges)
    F = sum(j.freedom for _, _, j in g.edges)
    A = zeros(6 * len(g.loops), F)
    for i, loop in enumerate(g.loops):
        for e, s in loop:
            for k, t in enumerate(twists[e]):
                for r in range(6):
                    A[6 * i + r, g.offsets[e] + k] += s * t[r]
    return _Network(g, twists, accel, A, 0, zeros(F, 0))


def _path_matrix(net: _Network, link: int) -> Matrix:
    """The 6 x F matrix taking joint rates to the twist of ``link`` relative to the base."""
    g = net.graph
    J = zeros(6, net.A.cols)
    for e, s in g.paths[link]:
        for k, t in enumerate(net.twists[e]):
            for r in range(6):
                J[r, g.offsets[e] + k] += s * t[r]
    return J


# ------------------------------------------------------------------ results


class MechanismMobility(NamedTuple):
    """The result of :meth:`Mechanism.mobility`: first-order (instantaneous) figures."""

    mobility: int  #: the instantaneous mobility M = F - rank: independent joint rates
    freedoms: int  #: F, the total number of joint freedoms
    loops: int  #: L = J - N + 1, the independent loops
    rank: int  #: the rank of the network matrix (6L x F)
    orders: tuple[int, ...]  #: d_i = rank of loop i's twists = 6 - lambda_i
    common: tuple[ScrewSystem, ...]  #: each loop's common constraints (lambda_i wrenches)
    redundant: int  #: nu = sum d_i - rank: loop equations in excess (overconstraint)
    idle: int  #: zeta: the dimension of the idle freedoms
    idle_rates: ImmutableMatrix  #: F x zeta: a basis of the idle joint rates
    rates: ImmutableMatrix  #: F x M: a basis of the joint rates allowed
    classical: int  #: Grübler–Kutzbach, 6 (N - J - 1) + F
    links: int  #: N, base included
    joints: int  #: J

    def answer(self) -> tuple[Any, ...]:
        """The numbers of the analysis, without the screw systems and bases: what two cases compare."""
        return (self.mobility, self.freedoms, self.loops, self.rank, self.orders,
                self.redundant, self.idle, self.classical)


class SecondOrder(NamedTuple):
    """The result of :meth:`Mechanism.second_order`."""

    instantaneous: int  #: M, the dimension of the first-order motions
    mobility: int | None  #: the dimension of the second-order cone (None: undecided)
    branches: int | None  #: how many components the cone is the union of (None: undecided)
    several_branches: bool | None  #: more than one (motion modes meeting here)
    cone: tuple[ImmutableMatrix, ...] | None  #: each linear component, F x k joint rates
    forms: tuple[ImmutableMatrix, ...]  #: the quadratic forms on the rates' coordinates


# -------------------------------------------------------------- mechanism


class Mechanism(ScrewsymBasic):
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

    >>> from screwsym.systems.graph import Mechanism
    >>> from screwsym.systems.joints import R
    >>> z = [0, 0, 1]
    >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
    ...                      ("crank", "coupler", R([1, 2, 0], z)),
    ...                      ("coupler", "rocker", R([3, 3, 0], z)),
    ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
    >>> m = fourbar.mobility()
    >>> m.mobility, m.loops, m.classical, m.orders, m.redundant, m.idle
    (1, 1, -2, (3,), 0, 0)
    >>> fourbar.twists("coupler")   # a rotation about the instant centre (12/5, 24/5, 0)
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
    >>> para.motion("coupler"), para.twists("coupler")
    ('1T', ScrewSystem(Twist([0, 0, 0], [sin(q), -cos(q), 0])))
    >>> [(case, m.mobility) for case, m in para.mobility_cases()]
    [(Ne(sin(q), 0), 1), (Eq(sin(q), 0), 2)]

    Parameters
    ==========

    joints : list of (link_a, link_b, joint)
    base : str, int or Symbol
        The link that is fixed.

    See Also
    ========

    screwsym.systems.mechanism.ParallelMechanism

    References
    ==========

    Davies 1981; Müller 2016; Huang, Li & Ding, Chapter 5 (see the module docstring).
    """

    __slots__ = ()

    def __new__(cls, joints: Any, base: Any = None) -> Self:
        if isinstance(joints, (str, bytes)) or not hasattr(joints, "__iter__"):
            raise TypeError(
                "joints: expected a list of (link_a, link_b, joint) triples, got "
                f"{type(joints).__name__}"
            )
        triples = []
        for i, item in enumerate(joints):
            if isinstance(item, (str, bytes)) or not hasattr(item, "__len__") or len(item) != 3:
                raise TypeError(f"joints[{i}]: expected a triple (link_a, link_b, joint), got {item!r}")
            a = _check_link(item[0], f"joints[{i}][0]")
            b = _check_link(item[1], f"joints[{i}][1]")
            j = item[2]
            if not isinstance(j, Joint):
                raise TypeError(
                    f"joints[{i}][2]: expected a joint of screwsym.systems.joints (Revolute, "
                    f"Prismatic, Helical, Cylindrical, Universal, Spherical, Parallelogram), got "
                    f"{type(j).__name__}"
                )
            if a == b:
                raise ValueError(f"joints[{i}]: a joint joins two different links, got "
                                 f"{_label(a)!r} twice")
            triples.append(Tuple(a, b, j))
        if not triples:
            raise ValueError("joints: expected at least one (link_a, link_b, joint), got none")
        if base is None:
            raise TypeError("base: expected the name of the fixed link, got None")
        base = _check_link(base, "base")
        if not any(base in t.args[:2] for t in triples):
            raise ValueError(f"base: {_label(base)!r} is not a link of any joint")
        obj = ScrewsymBasic.__new__(cls, Tuple(*triples), base)
        _spanning(obj)  # refuses a disconnected graph now
        return obj

    @classmethod
    def from_parallel(cls, pm: ParallelMechanism) -> Mechanism:
        """The mechanism of a :class:`~screwsym.systems.mechanism.ParallelMechanism`, as a graph.

        The links are ``"base"``, ``"platform"`` and, for limb ``i`` (from 1),
        ``"limb<i>.<k>"``, the ``k``-th link from the base.

        >>> from screwsym.systems.graph import Mechanism
        >>> from screwsym.systems.mechanism import Limb, ParallelMechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> pm = ParallelMechanism(Limb(R([0, 0, 0], z), R([1, 2, 0], z)),
        ...                        Limb(R([4, 0, 0], z), R([3, 3, 0], z)))
        >>> m = Mechanism.from_parallel(pm)
        >>> m.links
        ('base', 'limb1.1', 'platform', 'limb2.1')
        >>> m.twists("platform").rank == pm.mobility().mobility == 1
        True
        """
        return _from_parallel(pm)

    # ------------------------------------------------------------ parts
    @property
    def base(self) -> Any:
        """The fixed link's name."""
        return _label(self.args[1])

    @property
    def links(self) -> tuple[Any, ...]:
        """The links' names, the base first."""
        return tuple(_label(x) for x in _spanning(self).links)

    @property
    def joints(self) -> tuple[tuple[Any, Any, Joint], ...]:
        """The triples ``(link_a, link_b, joint)`` as given."""
        return tuple((_label(a), _label(b), j) for a, b, j in self.args[0].args)

    @property
    def freedom(self) -> int:
        """F, the sum of the joints' freedoms."""
        return sum(j.freedom for _, _, j in self.args[0].args)

    @property
    def loops(self) -> tuple[tuple[tuple[int, int], ...], ...]:
        """The fundamental loops: for each, ``(joint number, +1 or -1)`` in order round it.

        ``+1`` where the loop passes the joint from its ``link_a`` to its
        ``link_b``.  Each loop starts with the joint that closes it (the chord).

        >>> from screwsym.systems.graph import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> Mechanism([("g", "a", R([0, 0, 0], z)), ("a", "b", R([1, 0, 0], z)),
        ...            ("b", "g", R([1, 1, 0], z))], base="g").loops
        (((1, 1), (2, 1), (0, 1)),)
        """
        return _spanning(self).loops

    def network_matrix(self) -> ImmutableMatrix:
        """The 6L x F matrix of the loops' circulation equations (the network matrix).

        Row block ``i`` is loop ``i`` (:attr:`loops`); column ``k`` is the ``k``-th
        joint freedom, the joints in the order given, each joint's axes in order.
        """
        return ImmutableMatrix(_network(self).A)

    # -------------------------------------------------------- first order
    def mobility(self) -> MechanismMobility:
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
        takes minutes): give the symbols values where you can.

        - ``mobility``: ``M = F - rank``, the dimension of the null space of the
          network matrix (the independent joint rates), found exactly;
        - ``orders``, ``common``: for each loop, the system of wrenches
          reciprocal to all its joint twists (its common constraints, lambda_i of
          them) and ``d_i = 6 - lambda_i``, the rank of the loop's twists;
        - ``redundant``: ``nu = sum d_i - rank``, the loop equations that are
          consequences of the others (overconstraint beyond the common
          constraints), so that ``M = F - sum d_i + nu``;
        - ``idle``: the idle (passive) freedoms: joint rates allowed that leave
          at rest every link with other than two joints (the base, the links
          where loops meet, end links) and move each two-joint link so that its
          joints' axes, lines and centres stay where they are (the spin of an
          S-S or S-P-S leg about its own line); ``idle_rates`` a basis;
        - ``classical``: the Grübler–Kutzbach count ``6 (N - J - 1) + F``.

        Examples
        ========

        An S-P-S leg closed on the base spins about its line: its one
        freedom is idle.

        >>> from screwsym.systems.graph import Mechanism
        >>> from screwsym.systems.joints import P, S
        >>> m = Mechanism([("base", "lower", S([0, 0, 0])), ("lower", "upper", P([0, 0, 1])),
        ...                ("upper", "base", S([0, 0, 2]))], base="base").mobility()
        >>> m.mobility, m.idle, m.orders
        (1, 1, (6,))
        """
        net = _network(self)
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
        twists); ``common``, ``redundant`` follow from them, while ``idle`` and
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
        :class:`~screwsym.systems.mechanism.Degenerate` naming the joint,
        ``joints[k] (link_a, link_b): <its error>``; these are listed last,
        as :meth:`ParallelMechanism.mobility_cases
        <screwsym.systems.mechanism.ParallelMechanism.mobility_cases>` lists them.
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
        >>> from screwsym.systems.graph import Mechanism
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
        merged = _merge_cases(cast("list[tuple[Any, Any]]", out)) if merge else out
        return cast("list[tuple[Any, MechanismMobility | Degenerate | None]]", merged)

    def twists(self, link: Any, relative_to: Any = None) -> ScrewSystem:
        """The instantaneous motions of ``link`` relative to ``relative_to`` (the base by default).

        For every joint rate the loops allow (a basis of the null space), the
        twist of ``link`` is the sum of the joint twists along the tree from the
        base, and the same for ``relative_to``; the result is the
        :class:`~screwsym.systems.screw_system.ScrewSystem` of their
        differences (a basis, generic in the symbols).

        >>> from screwsym.systems.graph import Mechanism
        >>> from screwsym.systems.joints import Parallelogram
        >>> pa = Parallelogram([0, 0, 0], [1, 0, 0], [0, 0, 2])
        >>> Mechanism(pa.links("a", "b"), base="a").twists("b")   # a translation
        ScrewSystem(Twist([0, 0, 0], [1, 0, 0]))
        >>> pa.twists                                              # the compound pair: the same
        ScrewSystem(Twist([0, 0, 0], [-4, 0, 0]))
        """
        g = _spanning(self)
        target = self._link_number(link, "link")
        ref = 0 if relative_to is None else self._link_number(relative_to, "relative_to")
        net = _network(self)
        J = (_path_matrix(net, target) - _path_matrix(net, ref)) * net.null
        cols = [_clean(list(J.col(k))) for k in range(J.cols)]
        members = [Twist(c[:3], c[3:]) for c in cols if any(e != 0 for e in c)]
        del g
        if not members:
            return ScrewSystem(kind=Twist)
        return ScrewSystem(*members).basis()

    def motion(self, link: Any, relative_to: Any = None) -> str | None:
        """The motion type of ``link`` relative to ``relative_to``: ``"3T"``, ``"1R"``, ``"1H"``, ...

        The label of :func:`~screwsym.systems.mechanism.motion_of` for
        :meth:`twists`: translations, rotations, helical freedoms (translations
        first, "3T1R"), generic in the symbols; :meth:`helical_pitches` gives
        the pitch of each helical freedom.  None where the helical freedoms depend
        on the signs of the symbols (see ``motion_of``).
        """
        return motion_of(self.twists(link, relative_to)).motion

    def helical_pitches(self, link: Any, relative_to: Any = None) -> tuple | None:
        """The pitches of the helical freedoms ("H" in :meth:`motion`) of ``link`` relative to
        ``relative_to`` (None with :meth:`motion`)."""
        return motion_of(self.twists(link, relative_to)).helical_pitches

    def _link_number(self, link: Any, name: str) -> int:
        key = _check_link(link, name)
        g = _spanning(self)
        if key not in g.index:
            raise ValueError(f"{name}: {_label(key)!r} is not a link of this mechanism")
        return int(g.index[key])

    # ------------------------------------------------------ second order
    def quadratic_terms(self, rates: Any) -> ImmutableMatrix:
        r"""The second-order terms of the loop closure for the joint rates ``rates``.

        For each loop, ``sum_{k<l} [$_k, $_l] qdot_k qdot_l + sum_k Y_k qdot_k**2``
        (see the module docstring), stacked like the rows of
        :meth:`network_matrix`: a motion ``q(t)`` of the closed loops with
        ``q'(0) = rates`` has ``network_matrix() * q''(0) + quadratic_terms(rates) = 0``.
        """
        net = _network(self)
        q = Matrix(rates)
        if q.shape != (net.A.cols, 1):
            raise ValueError(f"rates: expected {net.A.cols} joint rates, got shape {q.shape}")
        out = zeros(net.A.rows, 1)
        for i, (pairs, squares) in enumerate(_loop_terms(net)):
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
        >>> from screwsym.systems.graph import Mechanism
        >>> from screwsym.systems.joints import R
        >>> ring = [(1, 0), (0, 1), (-1, 0), (Q(3, 5), Q(-4, 5))]
        >>> axes = [R([c, s, 0], [-s, c, 1]) for c, s in ring]
        >>> shaky = Mechanism([(k, (k + 1) % 4, axes[k]) for k in range(4)], base=0)
        >>> shaky.mobility().mobility, shaky.second_order().mobility
        (1, 0)
        """
        return _second_order(self)


# ----------------------------------------------------------- case split


def _put(M: Matrix, subs: dict) -> Matrix:
    """``M`` with a case's substitution made (``sin(q)``, ``cos(q)`` reach ``sin(2 q)``)."""
    return Matrix(_apply(M, subs)) if subs else M


def _contradicts(conds: tuple, subs: dict) -> bool:
    """Whether the substitution of a case makes one of its own ``Ne`` conditions false."""
    for c in conds:
        for atom in c.atoms(Ne):
            if _vanishes(_substitute(atom.lhs - atom.rhs, subs)):
                return True
    return False


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
    rg = _to_ring(node.matrix)
    R = rg.ring
    B = [_swap(c) for c in rg.cols]
    cols = list(node.cols)
    m = _det([[B[p][c] for c in cols] for p in members], R)
    scale = [_poly_expr(d, R) for d in rg.scales]
    out = []
    for j in free:
        x = [Integer(0)] * k
        x[j] = _poly_expr(m, R) * scale[j]
        for pp, p in enumerate(members):
            rows = [[B[j if q == pp else members[q]][c] for c in cols] for q in range(len(members))]
            x[p] = -_poly_expr(_det(rows, R), R) * scale[p]
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


def _unmade(mech: Mechanism, subs: dict) -> Degenerate | None:
    """The first joint that ``subs`` unmakes (its ``ValueError`` when built with those values),
    named as the graph knows it, ``joints[k] (link_a, link_b): ...``; ``None`` when all stand."""
    for name, j in _named_joints(mech):
        try:
            _substitute(j, subs)
        except ValueError as error:
            return Degenerate(f"{name}: {error}")
    return None


def _mobility_cases(mech: Mechanism,
                    limit: int) -> list[tuple[Any, MechanismMobility | Degenerate | None]]:
    net = _network(mech)
    g = net.graph
    A = net.A
    F = A.cols
    if not A.free_symbols:
        return [(true, mech.mobility())]
    # a leaf: its conditions; its substitution (None: undecided); its relation, the equation
    # of a case that no substitution states, () if none (the later splits are made on that
    # surface, modulo it: _surface_cases); the nodes that proved each loop's order; and the
    # rates closing the loops so far
    leaves: list[_Leaf] = [_Leaf((), {}, (), (), None)]
    used = [sorted({g.offsets[e] + k for e, _ in loop for k in range(g.edges[e][2].freedom)})
            for loop in g.loops]

    degenerate: list[tuple[Any, MechanismMobility | Degenerate | None]] = []  # listed last

    def split(leaf: _Leaf, M: Matrix) -> list[tuple[_Leaf, Any]]:
        found: list[tuple[_Leaf, Any]] = []
        M = ImmutableMatrix(M)
        nodes = _surface_cases(M, leaf.relation[0], limit) if leaf.relation else _cases(M, limit)
        for node in nodes:
            new = leaf.conds if node.condition is true else leaf.conds + (node.condition,)
            if node.rank is None:  # undecided
                found.append((_Leaf(new, None, (), (), None), node))
                continue
            # split is called on decided leaves only
            composed, relation = _within(cast("dict", leaf.subs), leaf.relation, node)
            if _contradicts(new, composed):
                continue
            unmade = _unmade(mech, composed) if node.subs else None
            if unmade is None and relation and relation != leaf.relation:  # a new surface
                why = _unmade_on_surface(_named_joints(mech), composed, relation[0])
                unmade = None if why is None else Degenerate(why)
            if unmade is not None:  # the case's values unmake a joint: nothing to analyse there
                degenerate.append((And(*new), unmade))
                continue
            found.append((_Leaf(new, composed, relation, leaf.orders, leaf.rates), node))
        return found

    for i in range(len(g.loops)):  # each loop's twists: its order d_i exact on each case
        grown: list[_Leaf] = []
        for leaf in leaves:
            if leaf.subs is None:
                grown.append(leaf)
                continue
            block = _put(A.extract(list(range(6 * i, 6 * i + 6)), used[i]), leaf.subs)
            # each loop's order with the node that proved it, at every point of its case
            grown.extend(new._replace(orders=new.orders + (node,)) if new.subs is not None
                         else new for new, node in split(leaf, block))
        leaves = grown
        _check_cases(len(leaves), limit)
    leaves = [leaf._replace(rates=None if leaf.subs is None else Matrix.eye(F)) for leaf in leaves]
    for i in range(len(g.loops)):  # the network matrix, loop by loop
        grown = []
        for leaf in leaves:
            if leaf.subs is None or leaf.rates is None:
                grown.append(leaf)
                continue
            block = _put(A.extract(list(range(6 * i, 6 * i + 6)), list(range(F))), leaf.subs)
            block, N = _polynomial_columns(block * leaf.rates, leaf.rates)
            for new, node in split(leaf._replace(rates=N), block):
                if new.subs is None:
                    grown.append(new)
                    continue
                more = dict(node.subs)
                rates = (_put(N, more) * _relations(node)).applyfunc(cancel)
                grown.append(new._replace(rates=rates))
        leaves = grown
        _check_cases(len(leaves), limit)
    out: list[tuple[Any, MechanismMobility | Degenerate | None]] = []
    for leaf in leaves:
        condition = And(*leaf.conds) if leaf.conds else true
        if condition is false:
            continue
        if leaf.subs is None or leaf.rates is None:
            out.append((condition, None))
            continue
        here = _substitute(mech, leaf.subs) if leaf.subs else mech
        if leaf.relation:  # on a surface: the figures of the split, proved there
            out.append((condition, _on_surface_mobility(here, leaf)))
            continue
        m = here.mobility()
        if m.mobility != leaf.rates.cols:  # pragma: no cover - the split proves the rank on the case
            raise AssertionError("mobility_cases: the case's rank and its generic rank differ")
        out.append((condition, m))
    return out + degenerate


class _Leaf(NamedTuple):
    """A case of the graph's split (see ``_mobility_cases``)."""

    conds: tuple
    subs: dict | None
    relation: tuple
    orders: tuple  # the nodes (of screw_system's split) that proved each loop's order
    rates: Matrix | None


def _on_surface_mobility(mech: Mechanism, leaf: _Leaf) -> MechanismMobility | None:
    """The figures of a case on a surface ``fe = 0`` (``leaf.relation``) from its split.

    The mobility, rank, orders and common constraints are proved at every point of the
    case (the split proved each rank there, and each basis is Cramer's rule on the
    minor that proved it); the idle rates, as elsewhere, are those of the generic point
    of the case, here of the surface (the null space proved modulo ``fe``).  None where
    no point of the surface proved that null space.
    """
    fe = leaf.relation[0]
    net = _bare_network(mech)
    N = cast(Matrix, leaf.rates)
    N = Matrix.hstack(*(Matrix(_clean(list(N.col(k)))) for k in range(N.cols))) if N.cols \
        else N

    def nullspace(C: Matrix) -> Matrix | None:
        found = _null_on_surface(ImmutableMatrix(C), fe)
        if found is None:
            return None
        return Matrix(found[2])

    idle = _idle(net, N, nullspace)
    if idle is None:  # pragma: no cover - no point of the surface proved the idle rates
        return None
    # each basis by Cramer's rule on the minor that proved its loop's order (non-zero on
    # the case), written with the case's substitution (a later case's may set more symbols)
    return _figures(net, tuple(node.rank for node in leaf.orders),
                    tuple(_basis_with(node, Wrench, leaf.subs) for node in leaf.orders), N, idle)


def _figures(net: _Network, orders: tuple, common: tuple, rates: Matrix,
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
        common=common,
        redundant=sum(orders) - rank,
        idle=idle.cols,
        idle_rates=ImmutableMatrix(idle),
        rates=ImmutableMatrix(rates),
        classical=6 * (n - J - 1) + F,
        links=n,
        joints=J,
    )


def _idle(net: _Network, N: Matrix | None = None, nullspace: Any = None) -> Matrix | None:
    """A basis of the idle rates among the rates ``N`` (the network's null space by default),
    the null space taken by ``nullspace`` (generic: ``_nullspace``); None where it says None."""
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
        P = _path_matrix(net, link) * N
        if g.degree[link] != 2:
            rows.append(P)
        else:
            rows.extend(op * P for op in carried[link])
    if not rows:
        return Matrix(N)
    C = Matrix.vstack(*rows)
    K = (nullspace or _nullspace)(C)
    if K is None:
        return None
    if K.cols == 0:
        return zeros(N.rows, 0)
    cols = [_clean(list((N * K).col(k))) for k in range(K.cols)]
    return Matrix.hstack(*(Matrix(c) for c in cols))


def _line_op(t: Any) -> Matrix:
    return _ad(list(t))


def _point_op(p: Any) -> Matrix:
    # the velocity at p: v_O + omega x p = v_O - p x omega
    return Matrix.hstack(-_skew(list(p)), Matrix.eye(3))


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
            ops.append(Matrix.hstack(-_skew(t[3:]), zeros(3)))
        else:
            ops.append(_line_op(t))
    return ops


def _loop_terms(net: _Network) -> list:
    """Per loop: the pairs ``(a, b, [X_a, X_b])`` in loop order and the squares ``(a, Y_a)``."""
    g = net.graph
    out = []
    for loop in g.loops:
        seq = []  # (freedom number, signed twist)
        squares = []
        for e, s in loop:
            idx = list(range(len(net.twists[e])))
            if s < 0:
                idx.reverse()
            for k in idx:
                seq.append((g.offsets[e] + k, [s * x for x in net.twists[e][k]]))
                y = net.accel[e][k]
                if y is not None:
                    squares.append((g.offsets[e] + k, [s * x for x in y]))
        pairs = []
        for u in range(len(seq)):
            for v in range(u + 1, len(seq)):
                c = _bracket(seq[u][1], seq[v][1])
                if any(x != 0 for x in c):
                    pairs.append((seq[u][0], seq[v][0], c))
        out.append((pairs, squares))
    return out


def _forms(mech: Mechanism) -> list[Matrix]:
    net = _network(mech)
    N = net.null
    M = N.cols
    if M == 0 or not net.graph.loops:
        return []
    W = _nullspace(Matrix(net.A.T))
    terms = _loop_terms(net)
    F = net.A.cols
    forms = []
    for k in range(W.cols):
        w = W.col(k)
        G = zeros(F, F)
        for i, (pairs, squares) in enumerate(terms):
            wi = w[6 * i:6 * i + 6]
            if all(x == 0 for x in wi):
                continue
            for a, b, c in pairs:
                val = sum(x * y for x, y in zip(wi, c, strict=True))
                G[a, b] += val / 2
                G[b, a] += val / 2
            for a, y in squares:
                G[a, a] += sum(x * z for x, z in zip(wi, y, strict=True))
        Q = (N.T * G * N).applyfunc(lambda e: radsimp(expand(e)))
        if _trig(Q):  # reduced on the circle: a form zero there is the zero matrix
            Q = Q.applyfunc(_circle_normal)
        forms.append(Q)
    return forms


class _Undecided(Exception):
    pass


def _zero(e: Any) -> bool:
    z = is_zero(radsimp(expand(e)))
    if z is None:
        raise _Undecided
    return z


def _squares(Q: Matrix) -> list[tuple[Any, Matrix]]:
    """Lagrange's reduction: ``x^T Q x = sum d (l . x)**2`` with independent rows ``l``."""
    Q = Matrix(Q)
    n = Q.rows
    out: list[tuple[Any, Matrix]] = []
    while True:
        nz = [(i, j) for i in range(n) for j in range(n) if not _zero(Q[i, j])]
        if not nz:
            return out
        diag = [i for i, j in nz if i == j]
        if diag:
            i = diag[0]
            a = Q[i, i]
            u = Q.row(i)
            out.append((a, (u / a).applyfunc(radsimp)))
            Q = (Q - u.T * u / a).applyfunc(lambda e: radsimp(expand(e)))
        else:
            i, j = nz[0]
            c = Q[i, j]
            u, v = Q.row(i), Q.row(j)
            out.append((1 / (2 * c), u + v))
            out.append((-1 / (2 * c), u - v))
            Q = (Q - (u.T * v + v.T * u) / c).applyfunc(lambda e: radsimp(expand(e)))


def _sign(d: Any) -> int:
    d = radsimp(d)
    if d.is_positive:
        return 1
    if d.is_negative:
        return -1
    raise _Undecided


def _restrict(Q: Matrix, K: Matrix) -> Matrix:
    return (K.T * Q * K).applyfunc(lambda e: radsimp(expand(e)))


def _cone(V: Matrix, forms: list[Matrix]) -> list[tuple[str, Matrix]]:
    """The components of ``{x in span V: every form vanishes}``: ('space', basis) or ('quadric', basis)."""
    forms = [f for f in forms if not all(_zero(e) for e in f)]
    if not forms or V.cols == 0:
        return [("space", V)]
    analysed = []
    for f in forms:
        sq = _squares(f)
        signs = [_sign(d) for d, _ in sq]
        analysed.append((f, sq, signs))
    # a semidefinite form first: its zero set is its kernel
    for f, sq, signs in analysed:
        if all(s > 0 for s in signs) or all(s < 0 for s in signs):
            K = _nullspace(Matrix.vstack(*(l for _, l in sq)))
            return _cone(V * K, [_restrict(h, K) for h in forms if h is not f])
    for f, sq, signs in analysed:
        if len(sq) == 2:  # indefinite of rank 2: two hyperplanes
            (d1, l1), (d2, l2) = sq if signs[0] > 0 else sq[::-1]
            c = radsimp(sqrt(radsimp(-d2 / d1)))
            out = []
            for normal in (l1 - c * l2, l1 + c * l2):
                K = _nullspace(normal.applyfunc(radsimp))
                out.extend(_cone(V * K, [_restrict(h, K) for h in forms if h is not f]))
            return out
    first = forms[0]
    if all(_proportional(first, h) for h in forms[1:]):
        return [("quadric", V)]
    raise _Undecided


def _proportional(a: Matrix, b: Matrix) -> bool:
    M = Matrix.hstack(Matrix(list(a)), Matrix(list(b)))
    return _rank(M.applyfunc(radsimp)) <= 1


def _contained(a: Matrix, b: Matrix) -> bool:
    """Whether span ``a`` lies in span ``b``."""
    if a.cols == 0:
        return True
    if b.cols == 0:
        return False
    return _rank(Matrix.hstack(b, a)) == _rank(b)


def _second_order(mech: Mechanism) -> SecondOrder:
    net = _network(mech)
    N = net.null
    M = N.cols
    forms = _forms(mech)
    frozen = tuple(ImmutableMatrix(f) for f in forms)
    if any(f.free_symbols for f in forms):
        if all(expand(e) == 0 or _vanishes(e) for f in forms for e in f):
            return SecondOrder(M, M, 1, False, (ImmutableMatrix(N),), frozen)
        return SecondOrder(M, None, None, None, None, frozen)
    try:
        parts = _cone(Matrix.eye(M), forms)
    except _Undecided:
        return SecondOrder(M, None, None, None, None, frozen)
    dims = [(kind, V, V.cols - (1 if kind == "quadric" else 0)) for kind, V in parts]
    # the maximal components: drop a linear space inside another (the first of equal ones
    # kept), and the point {0} wherever anything else is there (a quadric cone holds it too)
    maximal = []
    for i, (kind, V, d) in enumerate(dims):
        if kind == "space" and any(
            j != i and k2 == "space" and _contained(V, W) and (not _contained(W, V) or j < i)
            for j, (k2, W, _) in enumerate(dims)
        ):
            continue
        if kind == "space" and V.cols == 0 and any(
            k2 == "quadric" or W.cols > 0 for k2, W, _ in dims
        ):
            continue
        maximal.append((kind, V, d))
    mobility = max(d for _, _, d in maximal)
    cone = tuple(ImmutableMatrix(N * V) for kind, V, _ in maximal if kind == "space")
    if any(kind == "quadric" for kind, _, _ in maximal):
        cone_out: tuple[ImmutableMatrix, ...] | None = None
    else:
        cone_out = cone
    return SecondOrder(M, mobility, len(maximal), len(maximal) > 1, cone_out, frozen)


# ------------------------------------------------------------ from_parallel


def _from_parallel(pm: ParallelMechanism) -> Mechanism:
    if not isinstance(pm, ParallelMechanism):
        raise TypeError(f"pm: expected a ParallelMechanism, got {type(pm).__name__}")
    triples = []
    for i, limb in enumerate(pm.limbs):
        chain = ["base"] + [f"limb{i + 1}.{k}" for k in range(1, len(limb.joints))] + ["platform"]
        for k, j in enumerate(limb.joints):
            triples.append((chain[k], chain[k + 1], j))
    return Mechanism(triples, base="base")


