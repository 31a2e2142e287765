"""The Paden–Kahan subproblems: every branch, its condition, the degenerate cases.

References: B. Paden, *Kinematics and Control of Robot Manipulators*, PhD thesis,
UC Berkeley 1985; R. M. Murray, Z. Li & S. S. Sastry, *A Mathematical Introduction
to Robotic Manipulation*, CRC Press 1994, Section 3.2.2 (Subproblems 1-3, (3.18)-(3.32)).

Each target point is built by screwsym's own exponential (``exp6``); each answer is
then checked independently: Rodrigues' formula evaluated in mpmath at 60 digits
(not screwsym's code), the two sides agreeing to 40 digits.  Each checker is shown
to reject a perturbed angle.  Subproblem 5 (three rotations, a quartic: A. J. Elias &
J. T. Wen, "IK-Geo", *Mechanism and Machine Theory* 209, 2025) is checked in floats by an
independent Rodrigues formula.
"""

from __future__ import annotations

import random

import mpmath
import numpy as np
import pytest
from sympy import (
    Dummy,
    Float,
    ImmutableMatrix,
    Integer,
    Matrix,
    Rational,
    S,
    atan2,
    lambdify,
    pi,
    sqrt,
    symbols,
)

from screwsym import Twist, Wrench, exp6
from screwsym.motion import Branch, subproblem1, subproblem2, subproblem3, subproblem5

DPS = 60
CLOSE = mpmath.mpf(10) ** -40

#: axis directions: unit, non-unit rational, and surd
DIRECTIONS = [
    (0, 0, 1),
    (Rational(3, 5), Rational(4, 5), 0),
    (Rational(2, 3), Rational(-1, 3), Rational(2, 3)),
    (1, 2, 2),  # |omega| = 3: exp6 turns by 3 theta
    (1, 1, 0),  # |omega| = sqrt(2)
    (sqrt(2) / 2, 0, sqrt(2) / 2),
    (1, -1, 3),  # |omega| = sqrt(11)
]

#: angles with algebraic sines and cosines: multiples of pi/12 and Pythagorean angles
ANGLES = [pi / 3, -pi / 4, 5 * pi / 6, pi / 12, 7 * pi / 12, atan2(4, 3), -atan2(12, 5),
          atan2(24, -7), pi / 2 + atan2(8, 15)]


def rational(rng: random.Random, lo: int = -9, hi: int = 9) -> Rational:
    return Rational(rng.randint(lo, hi), rng.randint(1, 4))


def point(rng: random.Random) -> ImmutableMatrix:
    p = [rational(rng) for _ in range(3)]
    if rng.random() < 0.3:
        p[rng.randrange(3)] += sqrt(3) / 2
    return ImmutableMatrix(p)


def num(e) -> mpmath.mpf:
    """The value of the exact number ``e`` at DPS digits, through mpmath."""
    with mpmath.workdps(DPS):
        return mpmath.mpf(lambdify([], e, "mpmath")())


def rodrigues(omega, r, theta, p) -> list:
    """``exp6(Twist.rotation(omega, point=r), theta) p`` by Rodrigues' formula in mpmath."""
    with mpmath.workdps(DPS):
        w = [num(x) for x in omega]
        n = mpmath.sqrt(sum(x * x for x in w))
        k = [x / n for x in w]
        angle = n * num(theta)
        x = [num(a) - num(b) for a, b in zip(p, r, strict=True)]
        c, s = mpmath.cos(angle), mpmath.sin(angle)
        kx = sum(a * b for a, b in zip(k, x, strict=True))
        cross = [k[1] * x[2] - k[2] * x[1], k[2] * x[0] - k[0] * x[2], k[0] * x[1] - k[1] * x[0]]
        return [x[i] * c + cross[i] * s + k[i] * kx * (1 - c) + num(r[i]) for i in range(3)]


def axis_of(twist):
    """(omega, a point on the axis) of a twist of pitch 0."""
    omega = twist.omega
    return omega, twist.foot


def maps(twist, theta, p, q) -> bool:
    """Whether ``exp6(twist, theta) p = q`` (to 40 digits at 60)."""
    with mpmath.workdps(DPS):
        got = rodrigues(*axis_of(twist), theta, p)
        return all(abs(g - num(e)) < CLOSE for g, e in zip(got, q, strict=True))


def maps2(twist1, twist2, thetas, p, q) -> bool:
    """Whether ``exp6(twist1, theta1) exp6(twist2, theta2) p = q``."""
    with mpmath.workdps(DPS):
        c = rodrigues(*axis_of(twist2), thetas[1], p)
        got = rodrigues(*axis_of(twist1), thetas[0], [mpmath.mpf(x) for x in c])
        return all(abs(g - num(e)) < CLOSE for g, e in zip(got, q, strict=True))


def at_distance(twist, theta, p, q, delta) -> bool:
    """Whether ``|exp6(twist, theta) p - q| = delta``."""
    with mpmath.workdps(DPS):
        got = rodrigues(*axis_of(twist), theta, p)
        d = mpmath.sqrt(sum((g - num(e)) ** 2 for g, e in zip(got, q, strict=True)))
        return abs(d - num(delta)) < CLOSE


def same_angle(a, b, twist) -> bool:
    """Whether ``a = b`` modulo the full turn ``2 pi / |omega|`` of ``exp6(twist, .)``."""
    with mpmath.workdps(DPS):
        period = 2 * mpmath.pi / mpmath.sqrt(sum(num(x) ** 2 for x in twist.omega))
        k = (num(a) - num(b)) / period
        return abs(k - mpmath.nint(k)) < CLOSE


def random_twist(rng: random.Random) -> Twist:
    return Twist.rotation(rng.choice(DIRECTIONS), point=point(rng))


def length(omega):
    return sqrt(sum(x**2 for x in omega))


# ------------------------------------------------------------------ the checkers reject


def test_the_checkers_reject_a_perturbed_angle():
    z = Twist.rotation([0, 0, 1], point=[1, 0, 0])
    p, q = ImmutableMatrix([2, 0, 0]), ImmutableMatrix([1, 1, 0])
    assert maps(z, pi / 2, p, q)
    assert not maps(z, pi / 2 + Rational(1, 10**30), p, q)
    assert not maps(z, -pi / 2, p, q)
    assert maps2(z, z, (pi / 4, pi / 4), p, q)
    assert not maps2(z, z, (pi / 4, pi / 4 + Rational(1, 10**30)), p, q)
    assert at_distance(z, pi / 2, p, [3, 1, 0], 2)
    assert not at_distance(z, pi / 2 + Rational(1, 10**30), p, [3, 1, 0], 2)
    assert same_angle(pi / 3, pi / 3 - 2 * pi, z)
    assert not same_angle(pi / 3, pi / 3 + Rational(1, 10**30), z)
    assert same_angle(pi / 3, pi / 3 + 2 * pi / 3, Twist.rotation([0, 0, 3], point=[0, 0, 0]))


# ------------------------------------------------------------------ Subproblem 1


def test_subproblem1_round_trip_exact_inputs():
    """MLS (3.18)-(3.20): for random axes, points and angles, theta maps p to q."""
    rng = random.Random(1)
    for _ in range(12):
        twist, p = random_twist(rng), point(rng)
        phi = rng.choice(ANGLES) / length(twist.omega)  # exp6 turns by |omega| phi
        q = exp6(twist, phi).apply(p)
        branches = subproblem1(twist, p, q)
        assert len(branches) == 1
        (b,) = branches
        assert b.condition is S.true
        assert maps(twist, b.values[0], p, q)
        assert same_angle(b.values[0], phi, twist)
        # the same answer from the direction and a point of the axis
        assert subproblem1(twist.omega, p, q, point=twist.foot) == branches


def test_subproblem1_exact_values():
    z = Twist.rotation([0, 0, 1], point=[1, 1, 0])
    assert subproblem1(z, [2, 1, 7], [1, 2, 7]) == (Branch(S.true, (pi / 2,)),)
    assert subproblem1(z, [2, 1, 7], [2, 1, 7]) == (Branch(S.true, (0,)),)
    assert subproblem1(z, [2, 1, 7], [0, 1, 7]) == (Branch(S.true, (pi,)),)
    # |omega| = 2: exp6 turns by 2 theta, so a quarter turn is theta = pi/4
    assert subproblem1(Twist.rotation([0, 0, 2], point=[1, 1, 0]), [2, 1, 7], [1, 2, 7]) == (
        Branch(S.true, (pi / 4,)),)


def test_subproblem1_no_solution():
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    assert subproblem1(z, [1, 0, 0], [0, 1, 1]) == ()  # different component along the axis
    assert subproblem1(z, [1, 0, 0], [0, 2, 0]) == ()  # different distance to the axis
    assert subproblem1(z, [0, 0, 3], [1, 0, 3]) == ()  # p on the axis, q not


def test_subproblem1_point_on_the_axis_leaves_theta_free():
    axis = Twist.rotation([1, 2, 2], point=[1, 0, 0])
    (b,) = subproblem1(axis, [2, 2, 2], [2, 2, 2])
    assert b.condition is S.true
    (t,) = b.values
    assert isinstance(t, Dummy) and t.is_real
    for value in (0, Rational(7, 3), pi / 5):
        assert maps(axis, value, [2, 2, 2], [2, 2, 2])
    (b2,) = subproblem1(axis, [2, 2, 2], [2, 2, 2])
    assert b2.values[0] != t  # a fresh parameter each time


def test_subproblem1_symbolic_inputs():
    x, y, c = symbols("x y c", real=True)
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    branches = subproblem1(z, [x, y, c], [y, -x, c])
    assert len(branches) == 2  # p off the axis / on it: both conditions symbolic
    regular, free = branches
    assert regular.condition.free_symbols == {x, y}
    assert isinstance(free.values[0], Dummy)
    at = {x: 3, y: 4, c: 1}
    assert regular.condition.subs(at) is S.true
    assert free.condition.subs(at) is S.false
    assert maps(z, regular.values[0].subs(at), [3, 4, 1], [4, -3, 1])
    assert free.condition.subs({x: 0, y: 0}) is S.true
    # a symbolic axis: the condition holds for its numbers, the angle maps
    a = symbols("a", positive=True)
    (reg,) = subproblem1(Twist.rotation([0, 0, a], point=[0, 0, 0]), [1, 0, 0], [0, 1, 0])
    assert reg.condition is S.true
    assert maps(Twist.rotation([0, 0, 3], point=[0, 0, 0]), reg.values[0].subs(a, 3),
                [1, 0, 0], [0, 1, 0])


def test_subproblem1_bad_input():
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    with pytest.raises(ValueError, match="axis: expected a rotation.*pitch is not 0"):
        subproblem1(Twist.screw_motion([0, 0, 1], point=[0, 0, 0], pitch=1), [1, 0, 0], [0, 1, 0])
    h = symbols("h", real=True)
    with pytest.raises(ValueError, match="axis:.*cannot be decided"):
        subproblem1(Twist.screw_motion([0, 0, 1], point=[0, 0, 0], pitch=h), [1, 0, 0], [0, 1, 0])
    with pytest.raises(ValueError, match="axis: expected a rotation.*translation"):
        subproblem1(Twist.translation([0, 0, 1]), [1, 0, 0], [0, 1, 0])
    with pytest.raises(TypeError, match="axis: expected a Twist"):
        subproblem1(Wrench.force([0, 0, 1], point=[0, 0, 0]), [1, 0, 0], [0, 1, 0])
    with pytest.raises(TypeError, match="point: a direction"):
        subproblem1([0, 0, 1], [1, 0, 0], [0, 1, 0])
    with pytest.raises(TypeError, match="point: give it with a direction"):
        subproblem1(z, [1, 0, 0], [0, 1, 0], point=[0, 0, 0])
    with pytest.raises(ValueError, match="axis: a rotation axis needs a non-zero direction"):
        subproblem1([0, 0, 0], [1, 0, 0], [0, 1, 0], point=[0, 0, 0])
    with pytest.raises(ValueError, match="q: expected exact entries.*float"):
        subproblem1(z, [1, 0, 0], [0, 1.0, 0])
    with pytest.raises(ValueError, match="axis: expected exact entries"):
        subproblem1(Twist.rotation([0, 0, 1.0], point=[0, 0, 0]), [1, 0, 0], [0, 1, 0])
    with pytest.raises(ValueError, match="p: expected a 3-vector"):
        subproblem1(z, [1, 0], [0, 1, 0])
    with pytest.raises(TypeError, match="p:"):
        subproblem1(z, "1, 0, 0", [0, 1, 0])


# ------------------------------------------------------------------ Subproblem 2


def random_meeting_pair(rng: random.Random) -> tuple[Twist, Twist]:
    """Two twists whose axes meet, given by different points of their lines."""
    while True:
        d1, d2 = rng.sample(DIRECTIONS, 2)
        if ImmutableMatrix(d1).cross(ImmutableMatrix(d2)).expand() != ImmutableMatrix([0, 0, 0]):
            break
    r = point(rng)
    return (Twist.rotation(d1, point=r + rational(rng) * ImmutableMatrix(d1)),
            Twist.rotation(d2, point=r - rational(rng) * ImmutableMatrix(d2)))


def test_subproblem2_round_trip_exact_inputs():
    """MLS (3.24)-(3.28): both branches map p to q, the generating pair is one of them."""
    rng = random.Random(2)
    for _ in range(8):
        t1, t2 = random_meeting_pair(rng)
        p = point(rng)
        phi = (rng.choice(ANGLES) / length(t1.omega), rng.choice(ANGLES) / length(t2.omega))
        q = exp6(t1, phi[0]).apply(exp6(t2, phi[1]).apply(p))
        branches = subproblem2(t1, t2, p, q)
        assert len(branches) in (1, 2)
        for b in branches:
            assert b.condition is S.true
            assert maps2(t1, t2, b.values, p, q)
        assert any(same_angle(b.values[0], phi[0], t1) and same_angle(b.values[1], phi[1], t2)
                   for b in branches)


def test_subproblem2_one_solution_and_none():
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    x = Twist.rotation([1, 0, 0], point=[0, 0, 0])
    # c = (1, 0, 1) lies in the plane of the axes: g = 0, one solution
    assert subproblem2(z, x, [1, 1, 0], [0, 1, 1]) == (Branch(S.true, (pi / 2, pi / 2)),)
    assert maps2(z, x, (pi / 2, pi / 2), [1, 1, 0], [0, 1, 1])
    assert subproblem2(z, x, [1, 1, 0], [0, 2, 1]) == ()  # |u| != |v|
    assert subproblem2(z, x, [1, 0, 0], [0, 0, 1]) == ()  # g^2 = -1 < 0: out of reach


def test_subproblem2_points_on_the_axes():
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    x = Twist.rotation([1, 0, 0], point=[0, 0, 0])
    # p on axis 2: theta2 free, theta1 a quarter turn
    (b,) = subproblem2(z, x, [2, 0, 0], [0, 2, 0])
    assert b.condition is S.true and b.values[0] == pi / 2 and isinstance(b.values[1], Dummy)
    assert maps2(z, x, (b.values[0], Rational(5, 7)), [2, 0, 0], [0, 2, 0])
    # q on axis 1: theta1 free
    (b,) = subproblem2(z, x, [0, 2, 0], [0, 0, 2])
    assert isinstance(b.values[0], Dummy) and b.values[1] == pi / 2
    # p = q = the common point: both free
    (b,) = subproblem2(z, x, [0, 0, 0], [0, 0, 0])
    assert all(isinstance(t, Dummy) for t in b.values)


def test_subproblem2_directions_with_the_common_point():
    rng = random.Random(3)
    t1, t2 = random_meeting_pair(rng)
    p = point(rng)
    q = exp6(t1, pi / 3).apply(exp6(t2, -pi / 4).apply(p))
    r = (t1.foot + (t2.foot - t1.foot).cross(t2.omega).dot(t1.omega.cross(t2.omega))
         / t1.omega.cross(t2.omega).dot(t1.omega.cross(t2.omega)) * t1.omega)
    by_twists = subproblem2(t1, t2, p, q)
    by_point = subproblem2(t1.omega, t2.omega, p, q, point=r)
    assert len(by_point) == len(by_twists) == 2
    for b in by_point:
        assert maps2(t1, t2, b.values, p, q)


def test_subproblem2_symbolic_inputs():
    a, b = symbols("a b", real=True)
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    x = Twist.rotation([1, 0, 0], point=[0, 0, 0])
    q = ImmutableMatrix([a, b, 1])
    branches = subproblem2(z, x, [1, 1, 0], q)
    assert branches and all(br.condition.free_symbols <= {a, b} for br in branches)
    # at a = 1, b = 0: |u| = |v|, g^2 = 0: the single branch, and it maps
    at = {a: 0, b: 1}
    live = [br for br in branches if br.condition.subs(at) is S.true]
    assert len(live) == 1
    assert maps2(z, x, [t.subs(at) for t in live[0].values], [1, 1, 0], [0, 1, 1])
    # where |q| != |p| no branch holds
    assert all(br.condition.subs({a: 3, b: 0}) is S.false for br in branches)


def test_subproblem2_bad_input():
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    with pytest.raises(ValueError, match="axis1, axis2:.*parallel"):
        subproblem2(z, Twist.rotation([0, 0, 2], point=[1, 0, 0]), [1, 0, 0], [0, 1, 0])
    with pytest.raises(ValueError, match="axis1, axis2:.*skew"):
        subproblem2(z, Twist.rotation([1, 0, 0], point=[0, 1, 0]),
                    [1, 0, 0], [0, 1, 0])
    with pytest.raises(TypeError, match="axis1, axis2: give two Twists"):
        subproblem2(z, [1, 0, 0], [1, 0, 0], [0, 1, 0], point=[0, 0, 0])
    with pytest.raises(ValueError, match="axis2: expected a rotation"):
        subproblem2(z, Twist.screw_motion([1, 0, 0], point=[0, 0, 0], pitch=2),
                    [1, 0, 0], [0, 1, 0])


# ------------------------------------------------------------------ Subproblem 3


def test_subproblem3_round_trip_exact_inputs():
    """MLS (3.29)-(3.32): every branch puts p at distance delta from q."""
    rng = random.Random(4)
    for _ in range(10):
        twist, p, q = random_twist(rng), point(rng), point(rng)
        phi = rng.choice(ANGLES) / length(twist.omega)
        d = exp6(twist, phi).apply(p) - q
        delta = sqrt(d.dot(d))
        branches = subproblem3(twist, p, q, delta)
        assert len(branches) in (1, 2)
        for b in branches:
            assert b.condition is S.true
            assert at_distance(twist, b.values[0], p, q, delta)
        assert any(same_angle(b.values[0], phi, twist) for b in branches)


def test_subproblem3_tangent_free_and_none():
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    (b,) = subproblem3(z, [1, 0, 0], [2, 0, 0], 1)  # the circle touches the sphere
    assert b.condition is S.true and b.values == (0,)
    (b,) = subproblem3(z, [1, 0, 0], [3, 0, 0], 4)  # touches on the far side
    assert at_distance(z, b.values[0], [1, 0, 0], [3, 0, 0], 4) and b.values == (pi,)
    assert subproblem3(z, [1, 0, 0], [5, 0, 0], 1) == ()  # too far
    assert subproblem3(z, [1, 0, 0], [0, 0, 0], 2) == ()  # q on the axis, wrong distance
    # q on the axis: every angle is at the distance sqrt(2)
    (b,) = subproblem3(z, [1, 0, 0], [0, 0, 1], sqrt(2))
    assert isinstance(b.values[0], Dummy)
    assert at_distance(z, Rational(2, 3), [1, 0, 0], [0, 0, 1], sqrt(2))
    # two solutions, exact
    assert {b.values[0] for b in subproblem3(z, [1, 0, 0], [1, 1, 0], 1)} == {0, pi / 2}


def test_subproblem3_symbolic_delta():
    delta = symbols("delta", nonnegative=True)
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    branches = subproblem3(z, [1, 0, 0], [2, 0, 0], delta)
    assert len(branches) == 3  # two, tangent; q and p off the axis: never free
    for value, alive in ((Rational(3, 2), 2), (1, 1), (3, 1), (4, 0)):
        live = [b for b in branches if b.condition.subs(delta, value) is S.true]
        assert len(live) == alive
        for b in live:
            assert at_distance(z, b.values[0].subs(delta, value), [1, 0, 0], [2, 0, 0], value)


def test_subproblem3_bad_input():
    z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    with pytest.raises(ValueError, match="delta: expected a distance"):
        subproblem3(z, [1, 0, 0], [2, 0, 0], -1)
    with pytest.raises(ValueError, match="delta: expected exact entries"):
        subproblem3(z, [1, 0, 0], [2, 0, 0], Float(0.5))
    with pytest.raises(ValueError, match="axis: expected a rotation"):
        subproblem3(Twist.screw_motion([0, 0, 1], point=[0, 0, 0], pitch=1),
                    [1, 0, 0], [2, 0, 0], 1)
    with pytest.raises(TypeError, match="delta"):
        subproblem3(z, [1, 0, 0], [2, 0, 0], "1")


# ------------------------------------------------------------------ exact checks, undecided numbers


def test_exact_round_trips_on_rational_data():
    """The answers checked exactly (screwsym's exp6, zero decided exactly), not only at 60 digits."""
    from screwsym.core.decide import is_zero_vector

    axis = Twist.rotation([Rational(3, 5), Rational(4, 5), 0], point=[1, -2, Rational(1, 2)])
    p = ImmutableMatrix([2, Rational(1, 3), -1])
    q = exp6(axis, atan2(4, 3)).apply(p)
    (b,) = subproblem1(axis, p, q)
    assert is_zero_vector(exp6(axis, b.values[0]).apply(p) - q) is True
    assert is_zero_vector(exp6(axis, b.values[0] + Rational(1, 10**6)).apply(p) - q) is False
    z = Twist.rotation([0, 0, 1], point=[1, 1, 0])
    p, q = ImmutableMatrix([4, 1, 2]), ImmutableMatrix([1, 2, 0])
    # |u'| = 3, |v'| = 1, 2 apart along the axis: the distances squared fill [8, 20]
    assert subproblem3(z, p, q, sqrt(Rational(29, 4))) == ()
    delta = 3
    branches = subproblem3(z, p, q, delta)
    assert len(branches) == 2
    for b in branches:
        d = exp6(z, b.values[0]).apply(p) - q
        assert (d.dot(d) - delta**2).expand() == 0
        d = exp6(z, b.values[0] + Rational(1, 10**6)).apply(p) - q
        assert (d.dot(d) - delta**2).expand() != 0


def test_a_number_the_decision_cannot_settle_keeps_its_condition():
    """None means undecided: a condition on a number SymPy cannot reduce stays an ``Eq``.

    ``exp6`` of a non-unit axis at ``atan(8/15)`` leaves ``cos(3 atan(8/15))`` in ``q``:
    the branch is kept with its condition unevaluated, never dropped or guessed.
    """
    axis = Twist.rotation([1, 2, 2], point=[0, 0, 0])
    p = ImmutableMatrix([1, 0, 0])
    q = exp6(axis, atan2(8, 15)).apply(p)  # a turn by 3 atan(8/15)
    branches = subproblem1(axis, p, q)
    assert branches and all(b.condition not in (S.true, S.false) for b in branches)
    regular = [b for b in branches if not isinstance(b.values[0], Dummy)]
    assert len(regular) == 1 and maps(axis, regular[0].values[0], p, q)
    assert same_angle(regular[0].values[0], atan2(8, 15), axis)


def test_subproblem3_finds_every_solution():
    """Completeness, independently: the sign changes of |R(t) p - q|^2 - delta^2 on a fine grid
    (NumPy, float) over a full turn number the distinct angles returned."""
    import numpy as np

    rng = random.Random(5)
    counts = set()
    for _ in range(8):
        twist, p, q = random_twist(rng), point(rng), point(rng)
        delta = abs(rational(rng, 1, 12))
        branches = subproblem3(twist, p, q, delta)
        w = float(length(twist.omega))
        ts = np.linspace(0, 2 * np.pi / w, 20001)
        with mpmath.workdps(15):
            omega, r = axis_of(twist)
            k = np.array([float(x) for x in omega]) / w
            x = np.array([float(a - b) for a, b in zip(p, r, strict=True)])
            rr = np.array([float(e) for e in r])
            qq = np.array([float(e) for e in q])
        c, s = np.cos(w * ts)[:, None], np.sin(w * ts)[:, None]
        moved = x * c + np.cross(k, x) * s + np.outer(1 - c, k * k.dot(x)).reshape(-1, 3) + rr
        f = ((moved - qq) ** 2).sum(axis=1) - float(delta) ** 2
        changes = int((np.sign(f[1:]) != np.sign(f[:-1])).sum())
        assert len(branches) == changes
        counts.add(changes)
        for b in branches:
            assert at_distance(twist, b.values[0], p, q, delta)
    assert counts == {0, 2}  # both cases met by these draws


# --------------------------------------------------------------------- Subproblem 5 (IK-Geo)

#: rational axes of rational length (Pythagorean quadruples), the angles' half-tangents
SP5_AXES = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (Rational(3, 5), Rational(4, 5), 0),
            (0, Rational(5, 13), Rational(12, 13)), (Rational(2, 3), Rational(1, 3), Rational(2, 3)),
            (2, 1, 2)]


def _rodrigues(k, theta):
    """The rotation of ``exp6`` about ``k`` through the origin (turning |k| theta), floats:
    independent of screwsym."""
    k = np.array([float(x) for x in k])
    w = np.linalg.norm(k)
    u = k / w
    K = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    return np.eye(3) + np.sin(w * theta) * K + (1 - np.cos(w * theta)) * (K @ K)


def _rational_turn(k, t, p):
    """``R(k, theta) p`` exact, where ``tan(|k| theta / 2) = t`` (``t = None``: a half turn)."""
    k, p = Matrix(k), Matrix(p)
    w = sqrt(k.dot(k))
    c, s = (Integer(-1), Integer(0)) if t is None else ((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))
    along = k * k.dot(p) / w**2
    return along + (p - along) * c + k.cross(p) * s / w


def _sp5_residual(axes, points, values):
    k1, k2, k3 = axes
    p0, p1, p2, p3 = (np.array([float(x) for x in p]) for p in points)
    t1, t2, t3 = (float(v.evalf(30)) for v in values)
    return np.abs(p0 + _rodrigues(k1, t1) @ p1 - _rodrigues(k2, t2) @ (p2 + _rodrigues(k3, t3) @ p3)).max()


def _sp5_case(rng, half_turn=False):
    """Axes, points and the angles that solve them (p0 made from the others and the angles)."""
    axes = [SP5_AXES[i] for i in rng.choice(len(SP5_AXES), 3, replace=False)]
    p1, p2, p3 = ([Rational(int(x), 4) for x in rng.integers(-8, 9, 3)] for _ in range(3))
    ts = [None if half_turn else Rational(int(rng.integers(-9, 10)), 5),
          Rational(int(rng.integers(-9, 10)), 5), Rational(int(rng.integers(-9, 10)), 5)]
    y = Matrix(p2) + _rational_turn(axes[2], ts[2], p3)
    p0 = _rational_turn(axes[1], ts[1], y) - _rational_turn(axes[0], ts[0], p1)
    angles = [np.pi if t is None else 2 * np.arctan(float(t)) for t in ts]
    angles = [a / float(sqrt(Matrix(k).dot(Matrix(k)))) for a, k in zip(angles, axes, strict=True)]
    return axes, [list(p0), p1, p2, p3], angles


@pytest.mark.parametrize("half_turn", [False, True])
def test_subproblem5_every_branch_solves_it_and_the_angles_are_among_them(half_turn):
    """Elias & Wen 2025, Subproblem 5 (IK-Geo): every branch checked in floats by an
    independent Rodrigues formula, the angles that made the data among them, a wrong one
    rejected; the half turn is the quartic's root at infinity."""
    rng = np.random.default_rng(5 + half_turn)
    done = 0
    while done < (2 if half_turn else 4):
        axes, points, angles = _sp5_case(rng, half_turn)
        try:
            branches = subproblem5(*axes, *points)
        except NotImplementedError:  # a degenerate draw (axes 2 and 3 parallel, ...)
            continue
        done += 1
        assert 1 <= len(branches) <= 4
        for b in branches:
            assert b.condition is S.true
            assert _sp5_residual(axes, points, b.values) < 1e-12
        got = np.array([[float(v.evalf(30)) for v in b.values] for b in branches])
        turn = [2 * np.pi / float(sqrt(Matrix(k).dot(Matrix(k)))) for k in axes]
        gap = np.abs(np.mod(got - angles + np.array(turn) / 2, turn) - np.array(turn) / 2)
        assert (gap.max(axis=1) < 1e-9).any()
        wrong = list(branches[0].values)
        wrong[2] += Rational(1, 10**4)
        assert _sp5_residual(axes, points, wrong) > 1e-6


def test_subproblem5_refuses_what_it_does_not_handle():
    x, y, z = [1, 0, 0], [0, 1, 0], [0, 0, 1]
    with pytest.raises(NotImplementedError, match="do not fix theta3"):  # |y| constant
        subproblem5(x, y, z, [0, 0, 0], [0, 1, 0], [0, 0, 0], [1, 0, 0])
    with pytest.raises(ValueError, match="axis1: expected an axis of rational length"):
        subproblem5([1, 1, 0], y, z, [0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 0, 0])
    with pytest.raises(ValueError, match="p1: expected rational entries"):
        subproblem5(x, y, z, [0, 0, 0], [0, 0.5, 0], [1, 0, 0], [1, 0, 0])
    with pytest.raises(ValueError, match="axis2: expected rational entries"):
        subproblem5(x, [0, sqrt(2), 0], z, [0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 0, 0])
