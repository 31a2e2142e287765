"""Chain: forward kinematics and Jacobians by the product of exponentials, exact."""

from __future__ import annotations

import numpy as np
import pytest
from sympy import (
    ImmutableMatrix,
    Matrix,
    Rational,
    cancel,
    cos,
    count_ops,
    expand,
    pi,
    sin,
    symbols,
    trigsimp,
)

from screwsym import Chain, Transform, Twist, Wrench, exp6, lambdify, tidy
from screwsym.motion.displacement import se3_matrix

q1, q2, q3 = q = symbols("q1:4", real=True)


def is_exactly_zero(m) -> bool:
    return all(cancel(trigsimp(expand(e))) == 0 for e in m)


@pytest.fixture(scope="module")
def rph():
    """Revolute about z, prismatic along a skew direction, helical of pitch 1/2 about x."""
    return Chain(
        [
            Twist.rotation([0, 0, 1], point=[1, 0, 0]),
            Twist.translation([Rational(3, 5), 0, Rational(4, 5)]),
            Twist.screw_motion([1, 0, 0], point=[0, 1, 2], pitch=Rational(1, 2)),
        ],
        Transform.rotation([0, 1, 0], pi / 2, point=[1, 1, 1]),
    )


@pytest.mark.slow
def test_space_jacobian_columns_are_the_derivatives_of_the_motion(rph):
    """[J_s column i] = dT/dq_i T^-1, the definition of the space Jacobian."""
    T = rph.forward(q).matrix
    Tinv = rph.forward(q).inverse().matrix
    J = rph.jacobian(q)
    for i, qi in enumerate(q):
        assert is_exactly_zero(T.diff(qi) * Tinv - se3_matrix(J[:, i]))


def test_body_jacobian_columns_are_the_derivatives_in_the_end_frame(rph):
    """[J_b column i] = T^-1 dT/dq_i."""
    T = rph.forward(q).matrix
    Tinv = rph.forward(q).inverse().matrix
    J = rph.jacobian(q, frame="body")
    for i, qi in enumerate(q):
        assert is_exactly_zero(Tinv * T.diff(qi) - se3_matrix(J[:, i]))


def test_the_derivative_check_can_fail(rph):
    T = rph.forward(q).matrix
    Tinv = rph.forward(q).inverse().matrix
    J = rph.jacobian(q, frame="body")  # the body Jacobian is not the space one
    assert not is_exactly_zero(T.diff(q1) * Tinv - se3_matrix(J[:, 0]))


def test_space_and_body_jacobians_are_related_by_the_adjoint(rph):
    T = rph.forward(q)
    assert is_exactly_zero(rph.jacobian(q) - T.adjoint() * rph.jacobian(q, frame="body"))


def test_forward_is_the_product_of_exponentials(rph):
    expected = Transform.identity()
    for twist, qi in zip(rph.twists, q, strict=True):
        expected = expected @ exp6(twist, qi)
    expected = expected @ rph.home
    assert is_exactly_zero(rph.forward(q).matrix - expected.matrix)


def test_at_home(rph):
    zero = [0, 0, 0]
    assert rph.forward(zero) == rph.home
    assert rph.jacobian(zero) == ImmutableMatrix.hstack(*(t.matrix for t in rph.twists))
    assert rph.jacobian(zero, frame="body") == ImmutableMatrix.hstack(
        *(t.matrix for t in rph.body_twists())
    )


def test_numbers_for_q_give_exact_numbers(rph):
    T = rph.forward([pi / 2, 2, 0])
    assert T.equals(rph.forward(q).subs({q1: pi / 2, q2: 2, q3: 0})) is True
    assert not T.free_symbols


def test_tidy_is_an_identity_and_gathers_sums():
    a, b = symbols("a b", real=True)
    e = (cos(a) * cos(b) - sin(a) * sin(b)) * (2 + sin(b) ** 2) + 2 * cos(b) ** 2
    assert is_exactly_zero(Matrix([tidy(e) - e]))
    assert count_ops(tidy(e)) < count_ops(expand(e))
    assert tidy(3 * sin(a) ** 2 + 3 * cos(a) ** 2) == 3
    assert count_ops(tidy(a * (a + 1))) <= count_ops(a**2 + a)


def test_tidied_jacobian_is_no_larger_than_the_raw_product(rph):
    raw = Transform.identity()
    columns = []
    for twist, qi in zip(rph.twists, q, strict=True):
        columns.append(raw.adjoint() * twist.matrix)
        raw = raw @ exp6(twist, qi)
    assert count_ops(rph.jacobian(q)) <= count_ops(ImmutableMatrix.hstack(*columns))


def test_lambdify_gives_batched_kinematics(rph):
    qv = Matrix(q)
    fk = lambdify([qv], (rph.forward(q).matrix, rph.jacobian(q)))
    Q = np.array([[0.1, 0.2, 0.3], [1.0, -2.0, 0.5]])
    T, J = fk(Q)
    assert T.shape == (2, 4, 4) and J.shape == (2, 6, 3)
    at = rph.forward([Rational(1), Rational(-2), Rational(1, 2)]).matrix
    np.testing.assert_allclose(T[1], np.array(at.evalf(), dtype=float), atol=1e-12)


def test_args_rebuild_and_properties(rph):
    assert rph.func(*rph.args) == rph
    assert rph.n_joints == 3 and len(rph.twists) == 3
    assert Chain([Twist([0, 0, 1], [0, 0, 0])]).home == Transform.identity()
    assert str(Chain([Twist([0, 0, 1], [0, 0, 0])])).startswith("Chain([Twist([0, 0, 1]")


def test_bad_arguments(rph):
    with pytest.raises(ValueError, match="twists: expected at least one joint twist, got none"):
        Chain([])
    with pytest.raises(TypeError, match="twists: expected a sequence of twists, got Twist"):
        Chain(Twist([0, 0, 1], [0, 0, 0]))
    with pytest.raises(TypeError, match=r"twists\[0\]: expected a Twist, got Wrench"):
        Chain([Wrench([0, 0, 1], [0, 0, 0])])
    with pytest.raises(ValueError, match=r"twists\[1\]: a joint twist cannot be zero"):
        Chain([Twist([0, 0, 1], [0, 0, 0]), Twist([0, 0, 0], [0, 0, 0])])
    with pytest.raises(TypeError, match="home: expected a Transform, got ImmutableDenseMatrix"):
        Chain([Twist([0, 0, 1], [0, 0, 0])], ImmutableMatrix.eye(4))
    with pytest.raises(ValueError, match="q: expected 3 joint values, got 2"):
        rph.forward([0, 0])
    with pytest.raises(TypeError, match="q: expected a sequence of joint values, got str"):
        rph.forward("q1q2q3")
    with pytest.raises(TypeError, match=r"q\[1\]: expected a real number .*strings"):
        rph.jacobian([0, "1", 0])
    with pytest.raises(ValueError, match="frame: expected one of 'space', 'body', got 'world'"):
        rph.jacobian(q, frame="world")
