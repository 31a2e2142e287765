"""Linkages built link by link, and an independent floating-point solver of their loop closure.

The solver knows nothing of screwsym's analysis: it reads each joint's geometry from its
arguments, builds the joint's displacement with a 4 x 4 matrix exponential of its own
(scaling and squaring), places the links along a spanning tree of its own, and closes
the remaining joints by Gauss-Newton.  Tests use it for a finite motion a small step away.
"""

from __future__ import annotations

from collections import deque
from functools import cache

import numpy as np
from sympy import Matrix, expand
from sympy import Rational as Q

from screwsym.systems.joints import (
    Cylindrical,
    Helical,
    Parallelogram,
    Prismatic,
    R,
    Revolute,
    Spherical,
    Universal,
)
from screwsym.systems.linkage import Mechanism

Z = [0, 0, 1]


def cross(a, b):
    return list(Matrix(a).cross(Matrix(b)))


def sub(a, b):
    return [x - y for x, y in zip(a, b, strict=True)]


def add(a, b):
    return [x + y for x, y in zip(a, b, strict=True)]


def scale(k, a):
    return [k * x for x in a]


# ------------------------------------------------------------------ numeric


def _f(v):
    return np.array([float(x) for x in v])


def _hat(xi):
    w, v = xi[:3], xi[3:]
    X = np.zeros((4, 4))
    X[:3, :3] = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
    X[:3, 3] = v
    return X


def exp_twist(xi, t):
    """``exp(hat(xi) t)`` in closed form (Murray, Li & Sastry 1994, (2.36), any |omega|)."""
    w, v = xi[:3], xi[3:]
    a = float(np.linalg.norm(w))
    out = np.eye(4)
    if a == 0:
        out[:3, 3] = v * t
        return out
    W = _hat(np.r_[w, 0, 0, 0])[:3, :3]
    th = a * t
    s, c = np.sin(th), 1 - np.cos(th)
    out[:3, :3] = np.eye(3) + s / a * W + c / a**2 * W @ W
    out[:3, 3] = (np.eye(3) * t + c / a**2 * W + (th - s) / a**3 * W @ W) @ v
    return out


@cache
def _axes(j):
    """The joint's screws (omega; v_O) in axis order, from its own arguments."""
    a = j.args
    if isinstance(j, Revolute):
        p, u = _f(a[0]), _f(a[1])
        return [np.r_[u, np.cross(p, u)]]
    if isinstance(j, Prismatic):
        return [np.r_[np.zeros(3), _f(a[0])]]
    if isinstance(j, Helical):
        p, u, h = _f(a[0]), _f(a[1]), float(a[2])
        return [np.r_[u, np.cross(p, u) + h * u]]
    if isinstance(j, Cylindrical):
        p, u = _f(a[0]), _f(a[1])
        return [np.r_[u, np.cross(p, u)], np.r_[np.zeros(3), u]]
    if isinstance(j, Universal):
        p = _f(a[0])
        return [np.r_[_f(u), np.cross(p, _f(u))] for u in a[1:]]
    if isinstance(j, Spherical):
        p = _f(a[0])
        return [np.r_[e, np.cross(p, e)] for e in np.eye(3)]
    raise TypeError(type(j))


@cache
def _pa(j):
    p1, _, q1 = (_f(x) for x in j.args)
    return _f(j.normal), q1 - p1


def displacement(j, q):
    """The displacement of link_b relative to link_a for the joint variables ``q``."""
    if isinstance(j, Parallelogram):
        n, rod = _pa(j)
        Rot = exp_twist(np.r_[n, 0, 0, 0], q[0])[:3, :3]
        out = np.eye(4)
        out[:3, 3] = (Rot - np.eye(3)) @ rod
        return out
    out = np.eye(4)
    for xi, x in zip(_axes(j), q, strict=True):
        out = out @ exp_twist(xi, x)
    return out


class Closure:
    """The loop closure of a Mechanism in floating point."""

    def __init__(self, mech: Mechanism):
        self.joints = mech.joints
        self.base = mech.base
        self.sizes = [j.freedom for _, _, j in self.joints]
        self.offsets = np.cumsum([0] + self.sizes)[:-1]
        self.F = sum(self.sizes)
        incident: dict = {}
        for e, (a, b, _) in enumerate(self.joints):
            incident.setdefault(a, []).append(e)
            incident.setdefault(b, []).append(e)
        self.order, self.tree, seen = [], set(), {self.base}
        queue = deque([self.base])
        while queue:
            x = queue.popleft()
            for e in incident[x]:
                a, b, _ = self.joints[e]
                y = b if a == x else a
                if y not in seen:
                    seen.add(y)
                    self.tree.add(e)
                    self.order.append((e, x, y))
                    queue.append(y)
        self.chords = [e for e in range(len(self.joints)) if e not in self.tree]

    def _q(self, q, e):
        o = self.offsets[e]
        return q[o:o + self.sizes[e]]

    def poses(self, q):
        D = {self.base: np.eye(4)}
        for e, x, y in self.order:
            a, b, j = self.joints[e]
            g = displacement(j, self._q(q, e))
            D[y] = D[x] @ g if x == a else D[x] @ np.linalg.inv(g)
        return D

    def residual(self, q):
        D = self.poses(q)
        out = []
        for e in self.chords:
            a, b, j = self.joints[e]
            out.append((D[a] @ displacement(j, self._q(q, e)) - D[b])[:3, :].ravel())
        return np.concatenate(out) if out else np.zeros(0)

    def solve(self, fixed: dict, start=None, iterations=100):
        """Close the loops with the freedoms in ``fixed`` held; the least residual found."""
        q = np.zeros(self.F) if start is None else np.array(start, dtype=float)
        for k, v in fixed.items():
            q[k] = v
        free = [k for k in range(self.F) if k not in fixed]
        h = 1e-7
        for _ in range(iterations):
            r = self.residual(q)
            if np.linalg.norm(r) < 1e-13:
                break
            J = np.empty((r.size, len(free)))
            for c, k in enumerate(free):
                dq = np.zeros(self.F)
                dq[k] = h
                J[:, c] = (self.residual(q + dq) - self.residual(q - dq)) / (2 * h)
            step = np.linalg.lstsq(J, -r, rcond=None)[0]
            q[free] += step
            if np.linalg.norm(step) < 1e-13:
                break
        return q, float(np.linalg.norm(self.residual(q)))


# ------------------------------------------------------------ checking a case


def assert_case_at(mech, m, point):
    """A case's figures ``m`` (of ``mech.mobility_cases()``) checked at an exact ``point`` of it.

    ``point`` is a substitution (``{t: 1, u: 1}``, ``{sin(a): 0, cos(a): 1}``) that leaves no
    symbol: there the mechanism is rebuilt and analysed on the rational (or algebraic) path of
    ``Mechanism.mobility``.  Its numbers are the case's, and the case's bases hold there: its
    joint rates close every loop and are ``mobility`` independent ones, its idle rates too, and
    each loop's common constraints span that loop's there.
    """
    def exact_zero(M):
        return all(expand(e) == 0 for e in M)

    here = mech.xreplace(point)
    A = here.network_matrix()
    assert not A.free_symbols, point
    generic = here.mobility()
    assert m.answer() == generic.answer(), (point, m.answer(), generic.answer())
    rates = Matrix(m.rates.xreplace(point)).applyfunc(expand)
    assert exact_zero(A * rates) and rates.rank(simplify=True) == m.mobility, (point, rates)
    idle = Matrix(m.passive_rates.xreplace(point)).applyfunc(expand)
    assert exact_zero(A * idle) and idle.rank(simplify=True) == m.passive, (point, idle)
    for case_common, common in zip(m.common_constraints, generic.common_constraints, strict=True):
        case_common = case_common.xreplace(point)
        assert case_common.rank == common.rank == case_common.union(common).rank, (
            point, case_common, common)


# ------------------------------------------------------------------ linkages


def four_r(points, axes, names=("ground", "crank", "coupler", "rocker")):
    """A closed 4R: joint k joins link k to link k + 1 (mod 4), on the line (points[k], axes[k])."""
    return Mechanism([(names[k], names[(k + 1) % 4], R(points[k], axes[k])) for k in range(4)],
                     base=names[0])


#: a rational point of the unit circle per axis: four lines of one regulus of x^2 + y^2 - z^2 = 1
REGULUS = [(1, 0), (0, 1), (-1, 0), (Q(3, 5), Q(-4, 5))]


def shaky_4r():
    """Four revolutes on lines of one regulus: the lines through (c, s, 0) along (-s, c, 1)."""
    return four_r([[c, s, 0] for c, s in REGULUS], [[-s, c, 1] for c, s in REGULUS])


#: a skew isogram (opposite sides equal): symmetric under the half-turn about z
ISOGRAM = [[1, 0, 0], [1, 2, 2], [-1, 0, 0], [-1, -2, 2]]


def bennett():
    """Bennett's linkage from a skew isogram: each axis normal to the two sides at its vertex."""
    pts = ISOGRAM
    axes = [cross(sub(pts[(k + 1) % 4], pts[k]), sub(pts[k - 1], pts[k])) for k in range(4)]
    return four_r(pts, axes)


def flat_parallelogram():
    """The parallelogram four-bar (sides 1, 2, 1, 2) folded flat on the x-axis."""
    return four_r([[0, 0, 0], [1, 0, 0], [3, 0, 0], [2, 0, 0]], [Z] * 4)


def planar(triples, base):
    return Mechanism([(a, b, R([x, y, 0], Z)) for a, b, (x, y) in triples], base=base)


def watt():
    """Watt's six-bar: the ternary links T1 (ground) and T2 joined; two binary pairs between."""
    return planar([("T1", "T2", (0, 0)), ("T1", "a", (4, 0)), ("a", "b", (5, 3)),
                   ("b", "T2", (2, 4)), ("T1", "c", (-3, 1)), ("c", "d", (-4, 4)),
                   ("d", "T2", (-1, 3))], base="T1")


def stephenson():
    """Stephenson's six-bar: the ternary links T1 (ground) and T2 not joined."""
    return planar([("T1", "a", (0, 0)), ("a", "T2", (1, 3)), ("T1", "b", (4, 0)),
                   ("b", "T2", (4, 3)), ("T1", "c", (7, 1)), ("c", "d", (8, 4)),
                   ("d", "T2", (6, 5))], base="T1")


#: the Delta's radial directions (Pythagorean, about 127 degrees apart)
DELTA_RADIAL = [[1, 0, 0], [Q(-3, 5), Q(4, 5), 0], [Q(-3, 5), Q(-4, 5), 0]]


HALF = Q(1, 2)


def delta_joints(i, e, platform="platform", radius=2, w=HALF):
    """Leg i of the Delta, R-R-Pa-R: the arm on the base, the parallelogram's four revolutes."""
    u = [-e[1], e[0], 0]  # the arm's axis, tangent to the base circle
    b = scale(radius, e)
    elbow = add(add(b, e), [0, 0, -1])
    top = [0, 0, -3]
    attach = add(top, e)  # the platform's pivot of this leg
    rod = sub(attach, elbow)
    n = cross(u, rod)  # the parallelogram's axes: normal to its plane
    arm, upper, r1, r2, lower = (f"{name}{i}" for name in ("arm", "upper", "rodA", "rodB", "lower"))
    return [
        ("base", arm, R(b, u)),
        (arm, upper, R(elbow, u)),
        (upper, r1, R(add(elbow, scale(w, u)), n)),
        (r1, lower, R(add(attach, scale(w, u)), n)),
        (upper, r2, R(sub(elbow, scale(w, u)), n)),
        (r2, lower, R(sub(attach, scale(w, u)), n)),
        (lower, platform, R(attach, u)),
    ]


def delta():
    """Clavel's Delta robot, built link by link: 17 links, 21 revolutes, 5 loops."""
    return Mechanism([t for i, e in enumerate(DELTA_RADIAL) for t in delta_joints(i + 1, e)],
                     base="base")


def orthoglide():
    """The Orthoglide (Wenger & Chablat 2000) at its isotropic pose, link by link: leg i a
    prismatic along the axis e_i, then R-Pa-R, the rods along e_i, the revolutes' axis e_{i+1}."""
    E3 = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    triples = []
    for i in range(3):
        e, u = E3[i], E3[(i + 1) % 3]
        slider = scale(-3, e)  # the slider's pivot, on the axis e_i
        attach = scale(Q(-1, 2), e)  # the platform's pivot of this leg
        rod = sub(attach, slider)
        n = cross(u, rod)
        w = scale(Q(1, 2), u)
        s, up, r1, r2, lo = (f"{k}{i + 1}" for k in ("slider", "upper", "rodA", "rodB", "lower"))
        triples += [
            ("base", s, Prismatic(e)),
            (s, up, R(slider, u)),
            (up, r1, R(add(slider, w), n)), (r1, lo, R(add(attach, w), n)),
            (up, r2, R(sub(slider, w), n)), (r2, lo, R(sub(attach, w), n)),
            (lo, "platform", R(attach, u)),
        ]
    return Mechanism(triples, base="base")


def h4():
    """The H4 (Pierrot & Company 1999), link by link: four Delta-like legs R-R-Pa-R, legs 1
    and 2 on the side bar A of the travelling plate, legs 3 and 4 on B, and the central bar C
    joined to A and to B by revolutes about z (the articulated plate)."""
    radial = [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]]
    triples = []
    for i, e in enumerate(radial, 1):
        triples += delta_joints(i, e, platform="A" if i <= 2 else "B")
    triples += [("A", "C", R([Q(1, 2), Q(1, 2), -3], Z)), ("C", "B", R([Q(-1, 2), Q(-1, 2), -3], Z))]
    return Mechanism(triples, base="base")
