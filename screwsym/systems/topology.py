r"""The graph of a linkage: spanning tree, fundamental loops and network matrix (Davies 1981).

Each joint joins two links; a spanning tree is grown from the base
(:func:`spanning_tree`, breadth first), and each joint outside it (a *chord*) closes
one fundamental loop, so a connected linkage of N links and J joints has
``L = J - N + 1`` of them.  Kirchhoff's circulation law on each loop stacks into the
network matrix (6L x F, :func:`network`), whose null space is the set of joint
rates the linkage allows at the configuration given.  The twist of any link
relative to the base is :func:`path_matrix` times the rates.

References
==========

J. M. Davies, "Kirchhoff's circulation law applied to multi-loop kinematic
chains", Mech. Mach. Theory 16 (1981) 171-183.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from sympy import (
    Basic,
    Integer,
    Matrix,
    Symbol,
    zeros,
)
from sympy.core.symbol import Str

from ..algebra.budget import charge
from ..algebra.linalg import nullspace_basis

if TYPE_CHECKING:
    from .linkage import Mechanism


__all__: list[str] = []  # its names serve the floor; users reach them through linkage


def check_link(value: Any, name: str) -> Basic:
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


def link_label(link: Basic) -> Any:
    """The name as the user wrote it: a ``str`` for a string, an ``int`` for an integer."""
    if isinstance(link, Str):
        return link.name
    if isinstance(link, Integer):
        return int(link)
    return link


@dataclass(frozen=True)
class Graph:
    links: tuple  # link objects, base first, then in order of discovery
    index: dict  # link -> its number
    edges: tuple  # (a, b, joint): link numbers and the joint
    offsets: tuple  # the number of joint e's first freedom
    paths: tuple  # per link: ((edge, sign), ...) along the tree from the base
    loops: tuple  # per chord: ((edge, sign), ...) round the loop, from the chord's link_a
    degree: tuple  # the number of joints at each link


def spanning_tree(mech: Mechanism) -> Graph:
    triples, base = mech.args[:2]
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
    missing = [link_label(links[i]) for i, p in enumerate(paths) if p is None]
    if missing:
        raise ValueError(
            f"joints: the links {', '.join(repr(m) for m in missing)} are not connected to the "
            f"base {link_label(base)!r} (the mechanism must be one connected graph)"
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
    return Graph(tuple(links), index, tuple(edges), tuple(offsets), tuple(paths),
                  tuple(loops), tuple(len(i) for i in incident))


@dataclass(frozen=True)
class Network:
    graph: Graph
    twists: tuple  # per joint: its twists as lists of 6 entries
    accel: tuple  # per joint: its accelerations (lists of 6) or None
    A: Matrix  # 6L x F
    rank: int
    null: Matrix  # F x M


@lru_cache(maxsize=64)
def network(mech: Mechanism) -> Network:
    net = bare_network(mech)
    if net.graph.loops:  # elimination: about rows x cols x rank steps, charged to the budget
        charge(net.A.rows * net.A.cols * min(net.A.rows, net.A.cols))
    null = nullspace_basis(net.A) if net.graph.loops else Matrix.eye(net.A.cols)
    return Network(net.graph, net.twists, net.accel, net.A, net.A.cols - null.cols, null)


def bare_network(mech: Mechanism) -> Network:
    """The network without its (generic) null space: ``rank`` and ``null`` left empty."""
    g = spanning_tree(mech)
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
    return Network(g, twists, accel, A, 0, zeros(F, 0))


def path_matrix(net: Network, link: int) -> Matrix:
    """The 6 x F matrix taking joint rates to the twist of ``link`` relative to the base."""
    g = net.graph
    J = zeros(6, net.A.cols)
    for e, s in g.paths[link]:
        for k, t in enumerate(net.twists[e]):
            for r in range(6):
                J[r, g.offsets[e] + k] += s * t[r]
    return J
