"""Generated dynamics and forward dynamics (screwsym.numeric.dynamics, issue 21).

Forward dynamics must invert the inverse dynamics state by state (batched), and agree with
modern_robotics' ``ForwardDynamics`` (Lynch & Park 2017, Section 8.5) on a random chain.
"""

from __future__ import annotations

import numpy as np
import pytest
from sympy import ImmutableMatrix, Rational

from screwsym import Chain, SpatialInertia, Transform, Twist, convert
from screwsym.numeric.dynamics import dynamics_functions, forward_dynamics


@pytest.fixture(scope="module")
def chain():
    """A spatial RP arm (a turn about z, then a slide along a tilted axis), simple exact bodies."""
    half = Rational(1, 2)
    return Chain(
        [Twist.rotation([0, 0, 1], point=[0, 0, 0]), Twist.translation([Rational(3, 5), 0, Rational(4, 5)])],
        Transform.translation([1, 0, 1]),
        [SpatialInertia(2, [half, 0, 0], ImmutableMatrix.diag(1, 1, 1)),
         SpatialInertia(1, [1, half, 1], [[1, 0, 0], [0, 2, 0], [0, 0, 2]])],
    )


def test_forward_dynamics_inverts_inverse_dynamics_batched(chain):
    f = dynamics_functions(chain, backend="numpy")
    rng = np.random.default_rng(2132)
    q, qd, qdd = rng.uniform(-2, 2, size=(3, 40, 2))
    tau = f.inverse_dynamics(q, qd, qdd)
    assert tau.shape == (40, 2) and f.mass_matrix(q).shape == (40, 2, 2)
    back = forward_dynamics(chain, q, qd, tau, backend="numpy")
    np.testing.assert_allclose(back, qdd, rtol=1e-9, atol=1e-9)
    # tau = H qdd + h, as the two generated parts say
    H, h = f.mass_matrix(q), f.bias(q, qd)
    np.testing.assert_allclose(np.einsum("kij,kj->ki", H, qdd) + h, tau, rtol=1e-10, atol=1e-10)
    # a wrong torque gives a different acceleration
    assert np.abs(forward_dynamics(chain, q, qd, tau + 1, backend="numpy") - qdd).max() > 1e-3


def test_forward_dynamics_agrees_with_modern_robotics(chain):
    mr = pytest.importorskip("modern_robotics")
    rng = np.random.default_rng(2133)
    q, qd, tau = rng.uniform(-2, 2, size=(3, 2))
    n = chain.n_joints
    Mlist = [np.eye(4)] * n + [np.array(chain.home.matrix, dtype=float)]
    Glist = [np.array(convert(b, to="modern_robotics"), dtype=float) for b in chain.inertias]
    Slist = np.array([np.array(t.matrix, dtype=float).ravel() for t in chain.twists]).T
    expected = mr.ForwardDynamics(q, qd, tau, np.array([0, 0, -9.81]), np.zeros(6), Mlist, Glist, Slist)
    np.testing.assert_allclose(forward_dynamics(chain, q, qd, tau, backend="numpy"), expected, atol=1e-9)


def test_refuses_what_it_cannot_generate(chain):
    with pytest.raises(ValueError, match="chain: the chain has no inertias"):
        dynamics_functions(Chain([Twist.translation([1, 0, 0])]))
    with pytest.raises(TypeError, match="chain: expected a Chain"):
        dynamics_functions("arm")
    from sympy import Symbol

    with pytest.raises(ValueError, match="gravity: expected numbers"):
        dynamics_functions(chain, gravity=(0, 0, -Symbol("g", positive=True)))


def test_generated_from_the_programs_agrees_with_pinocchio_on_the_puma_560():
    """dynamics_functions compiles the Newton–Euler programs (issue 34): tau, H and the bias."""
    pin = pytest.importorskip("pinocchio")
    from _robots import pin_model, puma560

    arm = puma560()
    f = dynamics_functions(arm, backend="numpy")
    model = pin_model(pin, arm, (0, 0, -9.81))
    data = model.createData()
    rng = np.random.default_rng(560)
    Q, QD, QDD = rng.uniform(-2, 2, size=(3, 4, 6))
    tau, H, bias = f.inverse_dynamics(Q, QD, QDD), f.mass_matrix(Q), f.bias(Q, QD)
    for k in range(4):
        np.testing.assert_allclose(tau[k], pin.rnea(model, data, Q[k], QD[k], QDD[k]), atol=1e-9)
        np.testing.assert_allclose(bias[k], pin.rnea(model, data, Q[k], QD[k], 0 * QD[k]), atol=1e-9)
        M = np.triu(pin.crba(model, data, Q[k]))
        np.testing.assert_allclose(H[k], M + np.triu(M, 1).T, atol=1e-9)
    assert not np.allclose(tau[0], pin.rnea(model, data, Q[1], QD[1], QDD[1]), atol=1e-6)
