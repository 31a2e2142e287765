r"""Second-order mobility of a linkage (Müller 2016), and the Lie bracket of twists.

A first-order motion ``qdot`` of a linkage (a null vector of its network matrix,
:mod:`~screwsym.systems.topology`) extends to a second-order one when some ``qddot``
satisfies, on every loop,

    sum_k $_k qddot_k + sum_{k<l} [$_k, $_l] qdot_k qdot_l + sum_k Y_k qdot_k**2 = 0,

the joints in the loop's order, ``[., .]`` the Lie bracket of twists
(:func:`lie_bracket`) and ``Y_k`` the second derivative of a compound pair's path
(zero for the lower pairs).  Projected on the loops' reciprocal wrenches, these are
quadratic forms on the first-order motions; their common zeros are the *second-order
cone*, found here exactly by Lagrange's reduction of each form (:class:`SecondOrder`,
:meth:`Mechanism.second_order <screwsym.systems.linkage.Mechanism.second_order>`).

References
==========

A. Müller, "Local kinematic analysis of closed-loop linkages: mobility,
singularities, and shakiness", J. Mechanisms Robotics 8(4) (2016) 041013.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

from sympy import (
    ImmutableMatrix,
    Matrix,
    expand,
    radsimp,
    sqrt,
    zeros,
)

from ..algebra.circle import has_trig
from ..algebra.linalg import field_rank, nullspace_basis
from ..algebra.rings import (
    circle_normal,
    vanishes,
)
from ..core.decide import is_zero
from ..core.formulas import bracket
from ..core.twist import Twist
from .topology import Network, network

if TYPE_CHECKING:
    from .linkage import Mechanism


__all__ = [
    "SecondOrder",
    "lie_bracket",
]


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
    >>> from screwsym.systems.second_order import lie_bracket
    >>> lie_bracket(Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...             Twist.rotation([0, 0, 1], point=[1, 0, 0]))
    Twist([0, 0, 0], [1, 0, 0])
    """
    for value, name in ((a, "a"), (b, "b")):
        if not isinstance(value, Twist):
            raise TypeError(f"{name}: expected a Twist, got {type(value).__name__}")
    c = bracket(a.matrix, b.matrix)
    return Twist(c[:3, 0], c[3:, 0])


class SecondOrder(NamedTuple):
    """The result of :meth:`Mechanism.second_order`."""

    instantaneous: int  #: M, the dimension of the first-order motions
    mobility: int | None  #: the dimension of the second-order cone (None: undecided)
    branches: int | None  #: how many components the cone is the union of (None: undecided)
    several_branches: bool | None  #: more than one (motion modes meeting here)
    cone: tuple[ImmutableMatrix, ...] | None  #: each linear component, F x k joint rates
    forms: tuple[ImmutableMatrix, ...]  #: the quadratic forms on the rates' coordinates


def chain_terms(net: Network, chain: tuple) -> tuple[list, list]:
    """The second-order terms of a chain of joints ``((joint, +1 or -1), ...)``, in its order.

    The pairs ``(a, b, [X_a, X_b])`` (freedom numbers, ``a`` before ``b`` along the
    chain, non-zero brackets only) and the squares ``(a, Y_a)``: the twist rate of the
    chain's end is ``sum X_a qddot_a + sum [X_a, X_b] qdot_a qdot_b + sum Y_a qdot_a**2``
    (each joint's axes in order ``link_a`` to ``link_b``, reversed and negated where
    the chain runs the other way).  A loop is a chain whose end is its start.
    """
    g = net.graph
    seq = []  # (freedom number, signed twist)
    squares = []
    for e, s in chain:
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
            c = bracket(seq[u][1], seq[v][1])
            if any(x != 0 for x in c):
                pairs.append((seq[u][0], seq[v][0], c))
    return pairs, squares


def loop_terms(net: Network) -> list:
    """Per loop: the pairs ``(a, b, [X_a, X_b])`` in loop order and the squares ``(a, Y_a)``."""
    return [chain_terms(net, loop) for loop in net.graph.loops]


def _forms(mech: Mechanism) -> list[Matrix]:
    net = network(mech)
    N = net.null
    M = N.cols
    if M == 0 or not net.graph.loops:
        return []
    W = nullspace_basis(Matrix(net.A.T))
    terms = loop_terms(net)
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
        if has_trig(Q):  # reduced on the circle: a form zero there is the zero matrix
            Q = Q.applyfunc(circle_normal)
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
            K = nullspace_basis(Matrix.vstack(*(l for _, l in sq)))
            return _cone(V * K, [_restrict(h, K) for h in forms if h is not f])
    for f, sq, signs in analysed:
        if len(sq) == 2:  # indefinite of rank 2: two hyperplanes
            (d1, l1), (d2, l2) = sq if signs[0] > 0 else sq[::-1]
            c = radsimp(sqrt(radsimp(-d2 / d1)))
            out = []
            for normal in (l1 - c * l2, l1 + c * l2):
                K = nullspace_basis(normal.applyfunc(radsimp))
                out.extend(_cone(V * K, [_restrict(h, K) for h in forms if h is not f]))
            return out
    first = forms[0]
    if all(_proportional(first, h) for h in forms[1:]):
        return [("quadric", V)]
    raise _Undecided


def _proportional(a: Matrix, b: Matrix) -> bool:
    M = Matrix.hstack(Matrix(list(a)), Matrix(list(b)))
    return field_rank(M.applyfunc(radsimp)) <= 1


def _contained(a: Matrix, b: Matrix) -> bool:
    """Whether span ``a`` lies in span ``b``."""
    if a.cols == 0:
        return True
    if b.cols == 0:
        return False
    return field_rank(Matrix.hstack(b, a)) == field_rank(b)


def second_order_of(mech: Mechanism) -> SecondOrder:
    net = network(mech)
    N = net.null
    M = N.cols
    forms = _forms(mech)
    frozen = tuple(ImmutableMatrix(f) for f in forms)
    if any(f.free_symbols for f in forms):
        if all(expand(e) == 0 or vanishes(e) for f in forms for e in f):
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
