"""Rigid motions checked against implementations nobody here wrote.

modern_robotics (Lynch & Park's reference code for *Modern Robotics*,
Cambridge 2017, ``modern_robotics/core.py``) and pytransform3d
(``pytransform3d/transformations``) are numeric, so the comparison is in
floating point: screwsym's exact results are evaluated and compared with a
tolerance here, in the test, never as a verdict inside the library.  Both
write twists ``(omega; v)`` like the book's ray order; modern_robotics writes
wrenches moment first ``(m; f)``, converted with :func:`screwsym.convert`.

Each check runs on 200 random exact motions (rotations from rational
quaternions, rational translations) and twists (rational, non-unit omega), one
test case each, drawn from a generator seeded by the test's seed and the case
number: any one case reruns alone with its numbers
(``pytest "tests/crosscheck/test_modern_robotics.py::test_exp_agrees_with_mr_matrix_exp6[17]"``).
"""

from __future__ import annotations

import numpy as np
import pytest
from _motions import quaternion_rotation, random_transform, random_twist, rational_vector, to_float
from sympy import Matrix, Rational, pi, symbols

from screwsym import Transform, Twist, Wrench, convert, exp6, lambdify, log6, power
from screwsym.motion.chain import ur5 as ur5_chain

mr = pytest.importorskip("modern_robotics")

N = 200
CASES = range(N)


def _rng(seed: int, case: int) -> np.random.Generator:
    """The generator of one case: its numbers depend on ``(seed, case)`` only."""
    return np.random.default_rng([seed, case])


@pytest.mark.parametrize("case", CASES)
def test_apply_and_adjoint_agree_with_mr_adjoint(case):
    rng = _rng(101, case)
    T = random_transform(rng)
    twist, wrench = Twist(*(rational_vector(rng) for _ in "ab")), Wrench(
        *(rational_vector(rng) for _ in "ab")
    )
    Tf = to_float(T.matrix)
    Ad = mr.Adjoint(Tf)
    np.testing.assert_allclose(to_float(T.adjoint()), Ad, atol=1e-12)
    # twists move with Ad(T) in (omega; v) order
    moved = to_float(convert(T.apply(twist), to="modern_robotics")).ravel()
    np.testing.assert_allclose(
        moved, Ad @ to_float(convert(twist, to="modern_robotics")).ravel(), atol=1e-12
    )
    # wrenches, (m; f) in modern_robotics, move with Ad(T^-1)^T (Modern Robotics (3.95))
    moved = to_float(convert(T.apply(wrench), to="modern_robotics")).ravel()
    expected = mr.Adjoint(mr.TransInv(Tf)).T @ to_float(
        convert(wrench, to="modern_robotics")
    ).ravel()
    np.testing.assert_allclose(moved, expected, atol=1e-11)
    # and the power of a wrench on a twist is the plain dot product in MR's layout
    dot = float(
        to_float(convert(wrench, to="modern_robotics")).ravel()
        @ to_float(convert(twist, to="modern_robotics")).ravel()
    )
    assert abs(dot - float(power(twist, wrench))) < 1e-10


@pytest.mark.parametrize("case", CASES)
def test_exp_agrees_with_mr_matrix_exp6(case):
    rng = _rng(202, case)
    twist = random_twist(rng)
    theta = Rational(int(rng.integers(-40, 41)), 9)
    ours = to_float(exp6(twist, theta).matrix)
    se3 = mr.VecTose3(to_float(twist.matrix).ravel() * float(theta))
    np.testing.assert_allclose(ours, mr.MatrixExp6(se3), atol=1e-11)


@pytest.mark.parametrize("case", range(20))
def test_exp_of_a_translation_agrees_with_mr(case):
    rng = _rng(203, case)
    v = rational_vector(rng)
    theta = Rational(int(rng.integers(-40, 41)), 9)
    se3 = mr.VecTose3(np.r_[0.0, 0, 0, np.array(v, dtype=float)] * float(theta))
    np.testing.assert_allclose(
        to_float(exp6(Twist([0, 0, 0], v), theta).matrix), mr.MatrixExp6(se3), atol=1e-12
    )


def _assert_same_log(T, ours, theirs, half_turn: bool) -> int:
    """Compare exponential coordinates; a half-turn has two right answers (opposite axes)."""
    if not half_turn:
        np.testing.assert_allclose(ours, theirs, atol=1e-9)
        return 0
    np.testing.assert_allclose(np.abs(ours[:3]), np.abs(theirs[:3]), atol=1e-9)
    for coords in (ours, theirs):
        np.testing.assert_allclose(
            mr.MatrixExp6(mr.VecTose3(coords)), to_float(T.matrix), atol=1e-9
        )
    return 1


def _check_log(T) -> int:
    twist, theta = log6(T)
    ours = to_float(twist.matrix).ravel() * float(theta)
    theirs = mr.se3ToVec(mr.MatrixLog6(to_float(T.matrix)))
    assert float(theta) > 0 and abs(np.linalg.norm(to_float(twist.omega)) - 1) < 1e-12
    return _assert_same_log(T, ours, theirs, theta == pi)


@pytest.mark.parametrize("case", CASES)
def test_log_agrees_with_mr_matrix_log6(case):
    _check_log(random_transform(_rng(303, case)))


#: half-turns, where the logarithm has two right answers: quaternions with a zero real part
HALF_TURNS = [(1, 0, 0), (0, 0, 3), (1, 1, 0), (2, -1, 2), (-3, 1, 5)]


@pytest.mark.parametrize("bcd", HALF_TURNS)
def test_log_of_a_half_turn_agrees_with_mr_matrix_log6(bcd):
    T = Transform(quaternion_rotation(0, *bcd), [Rational(2, 7), -1, Rational(3, 5)])
    assert _check_log(T) == 1  # the half-turn branch of the comparison ran


@pytest.mark.parametrize("case", CASES)
def test_pytransform3d_exp_adjoint_and_log_agree(case):
    pt = pytest.importorskip("pytransform3d.transformations")
    rng = _rng(404, case)
    twist = random_twist(rng)
    theta = Rational(int(rng.integers(-40, 41)), 9)
    Stheta = to_float(twist.matrix).ravel() * float(theta)
    np.testing.assert_allclose(
        to_float(exp6(twist, theta).matrix),
        pt.transform_from_exponential_coordinates(Stheta),
        atol=1e-10,
    )
    T = random_transform(rng)
    Tf = to_float(T.matrix)
    np.testing.assert_allclose(to_float(T.adjoint()), pt.adjoint_from_transform(Tf), atol=1e-12)
    u, angle = log6(T)
    ours = to_float(u.matrix).ravel() * float(angle)
    theirs = pt.exponential_coordinates_from_transform(Tf)
    _assert_same_log(T, ours, theirs, angle == pi)


# -------------------------------------------------------------------------
# The UR5 of Modern Robotics, Example 4.5 (dimensions in metres, exact)
# -------------------------------------------------------------------------

UR5 = ur5_chain()
UR5_HOME = np.array(UR5.home.matrix, dtype=float)
UR5_S = [np.array(t.matrix, dtype=float).ravel() for t in UR5.twists]


@pytest.fixture(scope="module")
def ur5():
    chain = UR5
    q = Matrix(symbols("q1:7", real=True))
    fk = chain.forward(list(q)).matrix
    js = chain.jacobian(list(q))
    jb = chain.jacobian(list(q), frame="body")
    functions = lambdify([q], (fk, js, jb), names=["q"])
    return chain, functions


def _mr_ur5():
    M = UR5_HOME
    Slist = np.array(UR5_S, dtype=float).T
    Blist = mr.Adjoint(mr.TransInv(M)) @ Slist
    return M, Slist, Blist


@pytest.mark.slow
def test_ur5_kinematics_and_jacobians_agree_with_mr(ur5):
    _, functions = ur5
    M, Slist, Blist = _mr_ur5()
    rng = _rng(505, 0)  # one batch of N poses, one case
    Q = rng.uniform(-np.pi, np.pi, size=(N, 6))
    fk, js, jb = functions(Q)  # one batched call for all the poses
    for k in range(N):
        np.testing.assert_allclose(fk[k], mr.FKinSpace(M, Slist, Q[k]), atol=1e-12)
        np.testing.assert_allclose(fk[k], mr.FKinBody(M, Blist, Q[k]), atol=1e-12)
        np.testing.assert_allclose(js[k], mr.JacobianSpace(Slist, Q[k]), atol=1e-12)
        np.testing.assert_allclose(jb[k], mr.JacobianBody(Blist, Q[k]), atol=1e-12)


@pytest.mark.slow
def test_ur5_exact_numbers_agree_with_mr(ur5):
    """The exact path with numbers for q (no symbols, no lambdify)."""
    chain, _ = ur5
    M, Slist, Blist = _mr_ur5()
    rng = _rng(606, 0)  # three exact poses, one case
    for _ in range(3):
        q = [Rational(int(n), 7) for n in rng.integers(-21, 22, size=6)]
        qf = np.array(q, dtype=float)
        np.testing.assert_allclose(
            to_float(chain.forward(q).matrix), mr.FKinSpace(M, Slist, qf), atol=1e-12
        )
        np.testing.assert_allclose(
            to_float(chain.jacobian(q, frame="body")), mr.JacobianBody(Blist, qf), atol=1e-12
        )


def test_the_comparison_can_fail(ur5):
    """A wrong home pose, or a Jacobian in the wrong frame, is caught by the same checks."""
    _, functions = ur5
    M, Slist, Blist = _mr_ur5()
    q = np.array([0.3, -0.2, 0.5, 0.1, 0.7, -0.4])
    fk, js, jb = functions(q)
    assert not np.allclose(js, mr.JacobianBody(Blist, q), atol=1e-6)
    assert not np.allclose(fk, mr.FKinSpace(np.eye(4), Slist, q), atol=1e-6)
