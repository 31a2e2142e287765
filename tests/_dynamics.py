"""Chains with inertias for the dynamics tests: the UR5 of Modern Robotics, random chains.

The UR5 is built from Lynch & Park's own numbers (the UR5 data of the *Modern Robotics*
course's Chapter 8 simulation project, as ``Mlist``, ``Glist`` and ``Slist`` for
``modern_robotics.InverseDynamics``), made exact by reading each decimal as a rational, so
it does not depend on ``screwsym.motion.chain.ur5`` (whose joint-6 twist is a separate fix).
``Glist[i]`` is ``diag(I_xx, I_yy, I_zz, m, m, m)`` in link ``i``'s frame at its centre of
mass, whose pose at home is ``M_01 M_12 ... M_{i-1,i}``.
"""

from __future__ import annotations

import numpy as np
from _motions import random_transform
from sympy import ImmutableMatrix, Rational, cos, expand_trig, sin, symbols
from sympy.polys.domains import QQ
from sympy.polys.rings import ring

from screwsym import Chain, SpatialInertia, Transform, Twist

MR_UR5_M = [
    [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.089159], [0, 0, 0, 1]],
    [[0, 0, 1, 0.28], [0, 1, 0, 0.13585], [-1, 0, 0, 0], [0, 0, 0, 1]],
    [[1, 0, 0, 0], [0, 1, 0, -0.1197], [0, 0, 1, 0.395], [0, 0, 0, 1]],
    [[0, 0, 1, 0], [0, 1, 0, 0], [-1, 0, 0, 0.14225], [0, 0, 0, 1]],
    [[1, 0, 0, 0], [0, 1, 0, 0.093], [0, 0, 1, 0], [0, 0, 0, 1]],
    [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.09465], [0, 0, 0, 1]],
    [[1, 0, 0, 0], [0, 0, 1, 0.0823], [0, -1, 0, 0], [0, 0, 0, 1]],
]
#: (I_xx, I_yy, I_zz, m) of each link about its centre of mass
MR_UR5_G = [
    (0.010267495893, 0.010267495893, 0.00666, 3.7),
    (0.22689067591, 0.22689067591, 0.0151074, 8.393),
    (0.049443313556, 0.049443313556, 0.004095, 2.275),
    (0.111172755531, 0.111172755531, 0.21942, 1.219),
    (0.111172755531, 0.111172755531, 0.21942, 1.219),
    (0.0171364731454, 0.0171364731454, 0.033822, 0.1879),
]
#: the space-frame screw axes (omega; v), one per row
MR_UR5_S = [
    (0, 0, 1, 0, 0, 0),
    (0, 1, 0, -0.089159, 0, 0),
    (0, 1, 0, -0.089159, 0, 0.425),
    (0, 1, 0, -0.089159, 0, 0.81725),
    (0, 0, -1, -0.10915, 0.81725, 0),
    (0, 1, 0, 0.005491, 0, 0.81725),
]


def exact(x) -> Rational:
    """A decimal as the rational it reads as (0.1 -> 1/10)."""
    return Rational(str(x))


def mr_ur5_lists():
    """``(Mlist, Glist, Slist)`` as modern_robotics takes them."""
    Mlist = [np.array(M, dtype=float) for M in MR_UR5_M]
    Glist = [np.diag([a, b, c, m, m, m]) for a, b, c, m in MR_UR5_G]
    return Mlist, Glist, np.array(MR_UR5_S, dtype=float).T


def mr_ur5_chain() -> Chain:
    """The UR5 with the book's inertias, exact: inertias given in the link frames at home."""
    frames, T = [], Transform.identity()
    for M in MR_UR5_M[:6]:
        T = T @ Transform.from_matrix([[exact(x) for x in row] for row in M])
        frames.append(T)
    home = T @ Transform.from_matrix([[exact(x) for x in row] for row in MR_UR5_M[6]])
    bodies = [
        SpatialInertia(exact(m), [0, 0, 0], ImmutableMatrix.diag(exact(a), exact(b), exact(c)))
        for a, b, c, m in MR_UR5_G
    ]
    twists = [Twist.from_matrix([exact(x) for x in s]) for s in MR_UR5_S]
    return Chain(twists, home, bodies, link_frames=frames)


def random_body(rng: np.random.Generator) -> SpatialInertia:
    """A physical body with rational data: a box's principal moments, turned by a rational rotation."""
    m = Rational(int(rng.integers(1, 30)), 4)
    a, b, c = (Rational(int(k), 5) for k in rng.integers(1, 10, size=3))
    Ic = ImmutableMatrix.diag(m * (b**2 + c**2), m * (a**2 + c**2), m * (a**2 + b**2)) / 12
    T = random_transform(rng)
    com = [Rational(int(k), 7) for k in rng.integers(-10, 11, size=3)]
    return SpatialInertia(m, com, T.R * Ic * T.R.T)


def random_chain(rng: np.random.Generator, n: int) -> Chain:
    """``n`` joints, revolute or prismatic at random, along rational unit directions.

    A unit direction with rational components is a column of an exact rational rotation.
    """
    twists = []
    for _ in range(n):
        axis = random_transform(rng).R[:, int(rng.integers(0, 3))]
        if rng.random() < 0.7:
            point = [Rational(int(k), 5) for k in rng.integers(-5, 6, size=3)]
            twists.append(Twist.rotation(axis, point=point))
        else:
            twists.append(Twist.translation(axis))
    bodies = [random_body(rng) for _ in range(n)]
    return Chain(twists, random_transform(rng), bodies)


def ur5_torque_expanded(joint: int = 3):
    """One joint torque of :func:`mr_ur5_chain`'s inverse dynamics, exact and fully expanded.

    ``inverse_dynamics`` (gravity 981/100 down) keeps the recursion's nesting; here each
    ``sin(q_i)``, ``cos(q_i)`` becomes a generator of a sparse polynomial ring over QQ, in
    which the torque is expanded (SymPy's ``expand`` of the same tree takes 10 to 40 times
    longer), and is written back in ``sin``, ``cos``.  Joint 4's (``joint=3``) has 7,242
    terms, about 127,000 operations: the "expanded UR5 inverse dynamics" of issue 23.
    Returns ``(expr, (q, qd, qdd))``.
    """
    from screwsym.motion import dynamics

    q, qd, qdd = (symbols(f"{n}1:7", real=True) for n in ("q", "qd", "qdd"))
    # the recursion on expressions (not reduced on the circles): the large expanded form that
    # issue 23 lambdified; the ring path's torque, reduced modulo cos^2 + sin^2 = 1, expands
    # to about 2,000 operations only
    ring_rnea, dynamics.ring_rnea = dynamics.ring_rnea, lambda *args: None
    try:
        tau = mr_ur5_chain().inverse_dynamics(q, qd, qdd, [0, 0, -Rational(981, 100)])
    finally:
        dynamics.ring_rnea = ring_rnea
    s, c = symbols("s1:7"), symbols("c1:7")
    to_ring = {**{sin(a): x for a, x in zip(q, s, strict=True)}, **{cos(a): x for a, x in zip(q, c, strict=True)}}
    R, *_ = ring([*s, *c, *qd, *qdd], QQ)
    e = R.from_expr(expand_trig(tau[joint]).xreplace(to_ring)).as_expr()
    return e.xreplace({x: a for a, x in to_ring.items()}), (q, qd, qdd)
