"""Screw systems and mechanisms whose geometry moves: entries polynomial in sin and cos.

The case split keeps ``sin(q)`` and ``cos(q)`` as two ring symbols on the unit
circle, so its conditions are in the user's ``sin(q)``/``cos(q)`` and reach
every angle, ``q = pi`` included (which the half-angle ``tan(q/2)`` cannot).
Each split is checked against a plain rank (``Matrix.rank``, exact) at sampled
angles: at every sample exactly one case holds, with the true rank.
"""

from __future__ import annotations

import random

import numpy as np
import pytest
from sympy import (
    Eq,
    Matrix,
    Ne,
    Rational,
    cancel,
    cos,
    expand_trig,
    pi,
    sin,
    symbols,
    true,
)

from screwsym import Chain, ScrewSystem, Twist
from screwsym.motion.chain import ur5
from screwsym.systems.joints import R
from screwsym.systems.parallel import Limb, ParallelMechanism

Z = [0, 0, 1]


def circle_point(rng: random.Random) -> tuple:
    """A random exact point (sin, cos) of the unit circle: (2t/(1+t^2), (1-t^2)/(1+t^2))."""
    t = Rational(rng.randint(-9, 9), rng.randint(1, 5))
    return 2 * t / (1 + t**2), (1 - t**2) / (1 + t**2)


def angle_samples(angles, special=(), seed=0, count=6):
    """Substitutions {sin(q): s, cos(q): c, ...}: random points, and each ``special`` angle set."""
    rng = random.Random(seed)
    out = []
    for _ in range(count):
        d = {}
        for q in angles:
            s, c = circle_point(rng)
            d[sin(q)], d[cos(q)] = s, c
        out.append(d)
    for known in special:  # known: {q: exact angle}, the other angles random
        d = dict(out[len(out) % count])
        for q, value in known.items():
            d[sin(q)], d[cos(q)] = sin(value), cos(value)
        out.append(d)
    return out


def assert_trig_exhaustive(system, angles, special=(), seed=0):
    """At each sample exactly one case of ``rank_conditions`` holds, with the plain rank there."""
    cases = system.rank_conditions()
    for point in angle_samples(angles, special, seed):
        # sin and cos of sums expanded first, so that the point reaches sin(q1 + q2)
        actual = Matrix(system.matrix.applyfunc(expand_trig).xreplace(point)).rank()
        holding = [r for c, r in cases if c.xreplace(point) is true]
        assert len(holding) == 1, f"{len(holding)} cases hold at {point}"
        assert holding[0] is None or holding[0] == actual, (point, holding[0], actual)


def planar_3r(q, lengths=(3, 2)):
    """The space twists of a planar 3R arm at angles q (Lynch & Park 2017, Section 5.3)."""
    l1, l2 = lengths
    p2 = [l1 * cos(q[0]), l1 * sin(q[0]), 0]
    p3 = [p2[0] + l2 * cos(q[0] + q[1]), p2[1] + l2 * sin(q[0] + q[1]), 0]
    return ScrewSystem(*(Twist.rotation(Z, point=p) for p in ([0, 0, 0], p2, p3)))


def test_planar_3r_is_singular_where_sin_q2_vanishes():
    # Lynch & Park, Modern Robotics (2017), Section 5.3: the planar 3R arm loses rank
    # exactly where the three joint axes are coplanar with one line, sin(theta2) = 0
    q = symbols("q1:4", real=True)
    T = planar_3r(q)
    cases = T.rank_conditions()
    assert cases[0] == (Ne(sin(q[1]), 0), 3)
    assert all(r == 2 and c.has(Eq(sin(q[1]), 0)) for c, r in cases[1:])
    assert {c.has(Eq(cos(q[1]), 1)) for c, _ in cases[1:]} == {True, False}  # q2 = 0 and q2 = pi
    assert_trig_exhaustive(T, q, special=[{q[1]: 0}, {q[1]: pi}, {q[1]: pi, q[0]: pi}])


def test_the_checker_rejects_a_wrong_split():
    q = symbols("q1:4", real=True)
    T = planar_3r(q)

    class Wrong:  # the singular cases dropped, or given the generic rank
        matrix = T.matrix

        def __init__(self, cases):
            self.cases = cases

        def rank_conditions(self):
            return self.cases

    good = T.rank_conditions()
    with pytest.raises(AssertionError, match="0 cases hold"):
        assert_trig_exhaustive(Wrong(good[:1]), q, special=[{q[1]: pi}])
    with pytest.raises(AssertionError):
        assert_trig_exhaustive(Wrong([(c, 3) for c, _ in good]), q, special=[{q[1]: pi}])
    with pytest.raises(AssertionError, match="2 cases hold"):
        assert_trig_exhaustive(Wrong(good + [(Eq(sin(q[1]), 0), 2)]), q, special=[{q[1]: 0}])


def test_q_equal_pi_is_found():
    # the second axis on a circle of radius 1 about (1, 0): it meets the first axis only at
    # q = pi, the angle a half-angle substitution t = tan(q/2) cannot reach
    q = symbols("q", real=True)
    T = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]),
                    Twist.rotation(Z, point=[1 + cos(q), sin(q), 0]))
    cases = T.rank_conditions()
    assert (Eq(sin(q), 0) & Eq(cos(q), -1), 1) in cases
    assert [r for _, r in cases].count(1) == 1
    subs = dict(T.substitutions())[Eq(sin(q), 0) & Eq(cos(q), -1)]
    assert subs == {sin(q): 0, cos(q): -1}
    assert T.xreplace({q: pi}).rank == 1
    assert_trig_exhaustive(T, [q], special=[{q: pi}, {q: 0}])
    for cond, W in T.reciprocal_cases():  # each case's basis: reciprocal and complete there
        if cond.has(Eq(cos(q), -1)):
            assert W.rank == 5


def test_angles_that_cannot_be_reached_are_dropped():
    # sin(q) = 2 has no point on the circle: no case
    q, a = symbols("q a", real=True)
    T = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]),
                    Twist.rotation(Z, point=[sin(q) - 2, 0, 0]))
    assert T.rank_conditions() == [(True, 2)]
    # sin and cos of sums and multiples are expanded: sin(2 q) = 2 sin(q) cos(q)
    T2 = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]),
                     Twist.rotation(Z, point=[sin(2 * q), a * cos(q), 0]))
    assert_trig_exhaustive(T2.xreplace({a: 3}), [q], special=[{q: pi / 2}, {q: 0}, {q: pi}])


def test_a_chain_jacobian_goes_in_as_it_is():
    q = symbols("q1:3", real=True)
    arm = Chain([Twist.rotation(Z, point=[0, 0, 0]), Twist.rotation(Z, point=[1, 0, 0]),
                 Twist.translation(Z)])
    J = arm.jacobian([q[0], q[1], 0])
    T = ScrewSystem(*(Twist.from_matrix(J[:, i]) for i in range(J.cols)))
    assert T.rank == 3 and ScrewSystem(*(J[:, i] for i in range(J.cols))).rank == 3
    # rank 3 everywhere (the minor chosen splits off sin(q1) = 0, where another takes over)
    assert {r for _, r in T.rank_conditions()} == {3}
    assert_trig_exhaustive(T, [q[0]], special=[{q[0]: 0}, {q[0]: pi}])


@pytest.mark.slow
def test_ur5_singularities_are_the_textbook_ones():
    # Lynch & Park, Modern Robotics (2017), Section 5.3 (and Exercise 5.x on the UR5): the
    # elbow singularity sin(theta3) = 0, the wrist singularity sin(theta5) = 0 (axes 4 and 6
    # parallel), and the shoulder singularity where the wrist centre meets the axis of
    # joint 1.  theta1 and theta6 do not enter (the space Jacobian turns rigidly with q1).
    from screwsym.systems._rank_cases import case_here, trig_normal_matrix

    q = symbols("q1:7", real=True)
    J = ur5().jacobian([0, *q[1:5], 0])
    T = ScrewSystem(*(Twist.from_matrix(J[:, i]) for i in range(6)))
    assert T.rank == 6
    node, factors = case_here(trig_normal_matrix(T.matrix), (), (), ())  # the generic case, without the split
    assert sin(q[2]) in factors and sin(q[4]) in factors and len(factors) == 3
    (shoulder,) = [f for f in factors if f not in (sin(q[2]), sin(q[4]))]
    assert node.condition == Ne(sin(q[2]), 0) & Ne(sin(q[4]), 0) & Ne(shoulder, 0)
    # the shoulder factor: L1 cos q2 + L2 cos(q2 + q3) - H2 sin(q2 + q3 + q4), up to a constant
    l1, l2, h2 = Rational(425, 1000), Rational(392, 1000), Rational(95, 1000)
    shoulder_lp = l1 * cos(q[1]) + l2 * cos(q[1] + q[2]) - h2 * sin(q[1] + q[2] + q[3])
    assert cancel(shoulder / expand_trig(shoulder_lp)).is_number
    # independently, in floats: det J / (sin q3 sin q5 shoulder) is one non-zero constant
    rng = np.random.default_rng(0)
    ratios = []
    for _ in range(3):
        vals = dict(zip(q[1:5], rng.uniform(-3, 3, 4), strict=True))
        Jn = np.array(J.xreplace(vals).evalf(), dtype=float)
        ratios.append(np.linalg.det(Jn) / float((sin(q[2]) * sin(q[4]) * shoulder_lp).xreplace(vals)))
    assert abs(ratios[0]) > 1e-3 and ratios == pytest.approx([ratios[0]] * 3)


def test_a_crank_four_bar_folds_at_zero_and_pi():
    # the coupler pivot on the unit circle at angle q, the rocker pivots on the x axis: the
    # four-bar folds (2 instantaneous freedoms) where all four pivots are collinear, q = 0, pi
    # (Gosselin & Angeles 1990: the type-I/II singularities of a closed planar chain are
    # where its pivots align)
    q = symbols("q", real=True)
    mech = ParallelMechanism(Limb(R([0, 0, 0], Z), R([cos(q), sin(q), 0], Z)),
                             Limb(R([4, 0, 0], Z), R([3, 0, 0], Z)))
    cases = mech.mobility_cases(merge=False)
    assert [(c, m.mobility) for c, m in cases] == [
        (Ne(sin(q), 0), 1), (Eq(sin(q), 0) & Eq(cos(q), 1), 2), (Eq(sin(q), 0) & Eq(cos(q), -1), 2)]
    for value, expected in ((0, 2), (pi, 2), (pi / 3, 1), (pi / 2, 1)):
        assert mech.xreplace({q: value}).mobility().mobility == expected


def test_a_substitution_that_makes_an_assumed_factor_vanish_on_the_circle_contradicts_the_case():
    # x = 1 - sin(q)**2 makes the factor x - cos(q)**2, assumed non-zero by the case, zero on
    # the whole circle (not as an expression): the case has no point
    from screwsym.systems._rank_cases import substitute_nonzero

    q, x = symbols("q x", real=True)
    assert substitute_nonzero((x - cos(q) ** 2,), ((x, 1 - sin(q) ** 2),)) is None
    kept = substitute_nonzero((x - cos(q),), ((x, 1 - sin(q) ** 2),))
    assert kept is not None and len(kept) == 1
