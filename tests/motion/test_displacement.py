"""exp and log: the finite screw displacement and the Mozzi-Chasles screw of a motion."""

from __future__ import annotations

import math

import numpy as np
import pytest
from _motions import random_transform, random_twist, rational_vector
from sympy import (
    Float,
    ImmutableMatrix,
    Matrix,
    Rational,
    cancel,
    pi,
    sqrt,
    symbols,
    trigsimp,
)

from screwsym import Transform, Twist, Wrench, exp6, log6, pitch, vector
from screwsym.motion.displacement import se3_matrix

t, s = symbols("theta s", real=True)
h = symbols("h", real=True)


def is_exactly_zero(m) -> bool:
    return all(cancel(trigsimp(e.expand())) == 0 for e in m)


def solves_the_exponential_ode(twist, T) -> bool:
    """T(theta) = exp([$] theta) exactly when T(0) = I and dT/dtheta = [$] T."""
    M = T.matrix
    return is_exactly_zero(M.subs(t, 0) - ImmutableMatrix.eye(4)) and is_exactly_zero(
        M.diff(t) - se3_matrix(twist) * M
    )


@pytest.mark.parametrize(
    "twist",
    [
        Twist.rotation([0, 0, 1], point=[1, 2, 0]),  # revolute, unit
        Twist.screw_motion([0, 0, 1], point=[1, 0, 0], pitch=h),  # helical, symbolic pitch
        Twist([1, 2, 2], [0, 1, -1]),  # |omega| = 3, non-unit
        Twist([1, 1, 0], [3, 0, 1]),  # |omega| = sqrt(2)
        Twist.translation([1, -2, 5]),  # infinite pitch
    ],
    ids=["revolute", "helical", "non-unit", "irrational-norm", "translation"],
)
def test_exp_is_the_matrix_exponential(twist):
    assert solves_the_exponential_ode(twist, exp6(twist, t))


def test_the_ode_check_can_fail():
    twist = Twist.rotation([0, 0, 1], point=[1, 2, 0])
    wrong = Twist.screw_motion([0, 0, 1], point=[1, 2, 0], pitch=1)
    assert not solves_the_exponential_ode(wrong, exp6(twist, t))


def test_exp_with_a_generic_twist_is_the_exponential_where_omega_is_not_zero():
    twist = Twist([0, 0, symbols("w", positive=True)], vector("v"))
    assert solves_the_exponential_ode(twist, exp6(twist, t))


def test_exp_is_a_one_parameter_group():
    twist = Twist.screw_motion([0, 1, 0], point=[2, 0, 1], pitch=Rational(1, 3))
    lhs = exp6(twist, t) @ exp6(twist, s)
    assert is_exactly_zero(trigsimp(lhs.matrix - exp6(twist, t + s).matrix))


def test_exp_turns_about_the_axis_and_slides_h_theta():
    """A point of the axis slides by h theta along it (Mozzi-Chasles)."""
    r, direction = Matrix([1, -2, 3]), Matrix([0, 0, 1])
    twist = Twist.screw_motion(direction, point=r, pitch=h)
    assert is_exactly_zero(exp6(twist, t).apply(r) - (r + h * t * direction))


@pytest.mark.slow
def test_log_inverts_exp_exactly_on_random_motions():
    rng = np.random.default_rng(11)
    for _ in range(40):
        T = random_transform(rng)
        twist, theta = log6(T)
        assert exp6(twist, theta).equals(T) is True
        assert twist.omega.dot(twist.omega) == 1


def test_exp_then_log_gives_the_twist_back():
    rng = np.random.default_rng(12)
    for _ in range(20):
        twist = random_twist(rng)
        unit = twist / sqrt(twist.omega.dot(twist.omega))
        T = exp6(unit, pi / 3)
        back, theta = log6(T)
        assert theta == pi / 3
        assert (back.matrix - unit.matrix).applyfunc(
            lambda e: e.expand().simplify()  # a test may use simplify; the library does not
        ) == ImmutableMatrix.zeros(6, 1)


def test_log_special_cases_are_exact():
    assert log6(Transform.identity()) == (Twist([0, 0, 0], [0, 0, 0]), 0)
    assert log6(Transform.translation([0, 0, -2])) == (Twist([0, 0, 0], [0, 0, -1]), 2)
    # half-turns: about a coordinate axis, about a diagonal, and with a slide
    assert log6(Transform.rotation([0, 1, 0], pi)) == (Twist([0, 1, 0], [0, 0, 0]), pi)
    T = Transform.rotation([1, 1, 0], pi, point=[0, 0, 1]) @ Transform.translation([2, 2, 0])
    twist, theta = log6(T)
    assert theta == pi
    assert twist.omega == Matrix([sqrt(2) / 2, sqrt(2) / 2, 0])
    assert exp6(twist, theta).equals(T) is True
    assert pitch(twist).expand() == 2 * sqrt(2) / pi  # slide 2 sqrt(2) over the half-turn
    # the axis sign of a half-turn: the first non-zero component positive
    assert log6(Transform.rotation([-1, 0, 0], pi))[0].omega == Matrix([1, 0, 0])


def test_log_with_a_symbolic_translation_and_a_refused_symbolic_angle():
    p = vector("p")
    T = Transform.rotation([0, 0, 1], pi / 3, point=[1, 0, 0]) @ Transform.translation(p)
    twist, theta = log6(T)
    assert theta == pi / 3
    assert is_exactly_zero(exp6(twist, theta).matrix - T.matrix)
    with pytest.raises(ValueError, match=r"T: log needs a rotation whose angle is a number, "
                                         r"got cos\(theta\) = \(tr R - 1\)/2 = cos\(theta\)"):
        log6(Transform.rotation([0, 0, 1], t))


def test_bad_arguments():
    with pytest.raises(TypeError, match="twist: expected a Twist, got Wrench"):
        exp6(Wrench([0, 0, 1], [0, 0, 0]), 1)
    with pytest.raises(TypeError, match="theta: expected a real number"):
        exp6(Twist([0, 0, 1], [0, 0, 0]), "1")
    with pytest.raises(ValueError, match=r"twist: expected a 6-vector \(S; S0\), got shape \(3,\)"):
        exp6([0, 0, 1], 1)
    with pytest.raises(TypeError, match="T: expected a Transform, got ImmutableDenseMatrix"):
        log6(ImmutableMatrix.eye(4))


def test_exp_of_a_six_vector_and_se3_matrix():
    assert exp6([0, 0, 0, 1, 2, 3], 2) == Transform.translation([2, 4, 6])
    v = rational_vector(np.random.default_rng(13))
    assert se3_matrix(Twist([0, 0, 0], v))[:3, 3] == Matrix(v)


def test_log_of_float_motions_follows_the_float_policy():
    half = Transform.rotation([0, 1, 1], pi, point=[1, 0, 0]).evalf()
    twist, theta = log6(half)
    assert isinstance(theta, Float) and float(theta) == math.pi  # floats in, a float out
    np.testing.assert_allclose(
        np.array(exp6(twist, theta).matrix.evalf(), dtype=float),
        np.array(half.matrix, dtype=float),
        atol=1e-12,
    )
    twist, d = log6(Transform.translation([0.0, 3.0, 4.0]))
    assert abs(d - 5) < 1e-12 and twist.omega == Matrix([0, 0, 0])


def test_log_of_a_float_half_turn_with_rounding_on_a_zero_diagonal():
    # (R + I)/2 = omega omega^T has R[0, 0] + 1 = 2.2e-16 where omega_x = 0: the axis must come
    # from the largest diagonal, not from the first one that is not exactly zero (which gave
    # omega = (1.05e-8, 0, 0) and an exp(log6(T)) off by 2)
    R = [[-1 + 2.2e-16, 0, 0], [0, 0, 1.0], [0, 1.0, 0]]
    T = Transform(R, [0, 0, 0])
    twist, theta = log6(T)
    assert isinstance(theta, Float) and float(theta) == math.pi  # floats in, a float out
    np.testing.assert_allclose(
        np.array(twist.omega, dtype=float).ravel(), [0, np.sqrt(0.5), np.sqrt(0.5)], atol=1e-12
    )
    np.testing.assert_allclose(
        np.array(exp6(twist, theta).matrix.evalf(), dtype=float),
        np.array(T.matrix, dtype=float),
        atol=1e-12,
    )
    # rounding in the first component (-1.4e-16) does not decide the axis' sign
    R = [[-1.0, -2e-16, 0], [-2e-16, 0, 1.0], [0, 1.0, 0]]
    omega = log6(Transform(R, [0, 0, 0]))[0].omega
    assert abs(omega[0]) < 1e-15 and omega[1] > 0 and omega[2] > 0
    # cos(theta) = -1 + 1e-16 is a half-turn: sin(theta) is 0, not sqrt(2e-16) = 1.4e-8, which
    # moved the axis by 3.7e-9
    R = [[-1.0, 0, 0], [0, -1.0 + 2e-16, 0], [0, 0, 1.0]]
    twist, theta = log6(Transform(R, [1.0, 0, 0]))
    assert float(theta) == math.pi and twist.v_O[0] == 0 and twist.v_O[1] == -0.5


@pytest.mark.parametrize("angle", [1e-8, 1e-5, 0.3, 2.0, 3.14159])
def test_log_of_a_float_turn_keeps_a_unit_axis_at_every_angle(angle):
    # theta was acos(cos theta): near 0 it keeps half the digits (a turn by 1e-5 gave
    # |omega| = 1 - 4e-8) and at 1e-8 cos theta rounds to 1 (a NaN and a TypeError)
    T = Transform.rotation([0, 0, 1], angle, point=[1.0, 0, 0]) @ Transform.translation([0, 0, 0.5])
    twist, theta = log6(T)
    assert abs(float(theta) - angle) <= 1e-15 * angle
    assert abs(np.linalg.norm(np.array(twist.omega, dtype=float)) - 1) <= 1e-15
    np.testing.assert_allclose(
        np.array(exp6(twist, theta).matrix.evalf(), dtype=float),
        np.array(T.matrix, dtype=float),
        atol=1e-15,
    )


# --------------------------------------------------------------- issue 20: near a half-turn
def _mp_rotation(axis, theta):
    """The rotation by ``theta`` about ``axis`` in mpmath at 50 digits: the careful reference."""
    import mpmath

    n = mpmath.sqrt(sum(a * a for a in axis))
    a = [mpmath.mpf(c) / n for c in axis]
    K = mpmath.matrix([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return mpmath.eye(3) + mpmath.sin(theta) * K + (1 - mpmath.cos(theta)) * K * K, a


@pytest.mark.parametrize("bits", [53, 24])
def test_log6_near_a_half_turn_is_decided_by_the_rotation_not_a_tolerance(bits):
    # issue 20: within sqrt(2 tau) of pi the angle came back as exactly pi (1.35e-6 rad off
    # for doubles, 0.03 rad for 24-bit floats) and the axis lost digits; the reference is the
    # rotation computed by mpmath at 50 digits, rounded to the floats given
    import mpmath

    mpmath.mp.dps = 50
    eps = 2.0**-bits
    for k in (1, 3, 5, 7, 9, 12, 15):
        if 10.0**-k < eps:
            continue
        theta = mpmath.pi - mpmath.mpf(10) ** -k
        Rm, a = _mp_rotation([1, 2, -2], theta)
        R = ImmutableMatrix(3, 3, [Float(mpmath.nstr(Rm[i, j], 30), precision=bits)
                                   for i in range(3) for j in range(3)])
        T = Transform(R, [Float(1.0, precision=bits), Float(0.5, precision=bits), 0])
        twist, angle = log6(T)
        assert isinstance(angle, Float), (k, angle)
        assert abs(mpmath.mpf(angle) - theta) < 8 * eps, k
        assert max(abs(mpmath.mpf(w) - c) for w, c in zip(twist.omega, a, strict=True)) < 8 * eps, k
        back = exp6(twist, angle)
        assert max(abs(float(u - v)) for u, v in zip([*back.R, *back.p], [*T.R, *T.p], strict=True)) < 32 * eps


def test_log6_of_an_exact_float_half_turn_is_pi_with_the_sign_convention():
    T = Transform(ImmutableMatrix([[-1.0, 0, 0], [0, -1.0, 0], [0, 0, 1.0]]), [0, 0, 0])
    twist, angle = log6(T)
    assert angle == Float(pi, 16) or abs(float(angle) - float(pi)) < 1e-15
    assert [float(w) for w in twist.omega] == [0, 0, 1]


@pytest.mark.parametrize("angle", [1e-3, 1e-6, 1e-9, 1e-12])
def test_exp6_at_a_small_float_angle_keeps_the_digits_of_one_minus_cos(angle):
    # issue 20: 1 - cos(theta) lost its digits (a relative error of 9e-5 in p at 1e-6 rad,
    # the whole term at 1e-9); 2 sin^2(theta/2) keeps them.  Reference: Rodrigues in mpmath
    import mpmath

    mpmath.mp.dps = 40
    point = [1.0, -2.0, 0.5]
    Rm, a = _mp_rotation([1, 2, 2], mpmath.mpf(angle))
    twist = Twist.rotation([1 / 3, 2 / 3, 2 / 3], point=point)
    T = exp6(twist, angle)
    want = (mpmath.eye(3) - Rm) * mpmath.matrix(point)  # p = (I - R) r, pitch 0
    for got, ref in zip(T.p, want, strict=True):
        assert abs(mpmath.mpf(got) - ref) <= 4e-16 * angle * 3, (got, ref)
