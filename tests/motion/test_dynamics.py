"""The dynamics of a Chain, symbolic and exact (issue 21).

The planar two-link arm is compared with the textbook's closed form: Spong, Hutchinson &
Vidyasagar, *Robot Modeling and Control*, Wiley 2006, Section 7.4 ("planar elbow
manipulator", the inertia matrix, Christoffel symbols and gravity terms), which is also
Lynch & Park, *Modern Robotics*, 2017, Example 8.1 for point masses.  Identities are
tested as an exact zero of the difference after ``tidy``/``expand``.
"""

from __future__ import annotations

import numpy as np
import pytest
from _dynamics import random_chain
from sympy import Float, ImmutableMatrix, Rational, cos, expand, sin, symbols, trigsimp, zeros

import screwsym
from screwsym import Chain, SpatialInertia, Transform, Twist, tidy

q1, q2, u1, u2, a1, a2 = symbols("q1 q2 u1 u2 a1 a2", real=True)
m1, m2, l1, lc1, lc2, I1, I2, J1, J2, g = symbols("m1 m2 l1 lc1 lc2 I1 I2 J1 J2 g", positive=True)


def planar_2r() -> Chain:
    """The elbow arm in the x-y plane, gravity along -y; links' centres at lc1, l1 + lc2."""
    return Chain(
        [Twist.rotation([0, 0, 1], point=[0, 0, 0]), Twist.rotation([0, 0, 1], point=[l1, 0, 0])],
        Transform.translation([l1 + 1, 0, 0]),
        [SpatialInertia(m1, [lc1, 0, 0], ImmutableMatrix.diag(J1, J1, I1)),
         SpatialInertia(m2, [l1 + lc2, 0, 0], ImmutableMatrix.diag(J2, J2, I2))],
    )


def textbook_2r():
    """Spong et al. 2006, Section 7.4: d_ij, the Christoffel symbols with h, and phi_i."""
    d11 = m1 * lc1**2 + m2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * cos(q2)) + I1 + I2
    d12 = m2 * (lc2**2 + l1 * lc2 * cos(q2)) + I2
    d22 = m2 * lc2**2 + I2
    h = -m2 * l1 * lc2 * sin(q2)
    D = ImmutableMatrix([[d11, d12], [d12, d22]])
    C = ImmutableMatrix([[h * u2, h * u2 + h * u1], [-h * u1, 0]])
    phi = ImmutableMatrix([(m1 * lc1 + m2 * l1) * g * cos(q1) + m2 * lc2 * g * cos(q1 + q2),
                           m2 * lc2 * g * cos(q1 + q2)])
    return D, C, phi


def _zero(M) -> bool:
    return all(trigsimp(expand(e)) == 0 for e in tidy(ImmutableMatrix(M)))


def test_planar_2r_matches_the_textbook_exactly():
    arm, (D, C, phi) = planar_2r(), textbook_2r()
    gravity = [0, -g, 0]
    assert _zero(arm.mass_matrix([q1, q2]) - D)
    assert _zero(arm.coriolis_matrix([q1, q2], [u1, u2]) - C)
    assert _zero(arm.gravity_torques([q1, q2], gravity) - phi)
    tau = arm.inverse_dynamics([q1, q2], [u1, u2], [a1, a2], gravity)
    assert _zero(tau - (D * ImmutableMatrix([a1, a2]) + C * ImmutableMatrix([u1, u2]) + phi))
    # the check can fail: the textbook with the sign of h reversed is not our arm
    assert not _zero(arm.coriolis_matrix([q1, q2], [u1, u2]) + C)


def test_point_mass_2r_is_modern_robotics_example_8_1():
    # Lynch & Park (8.9)-(8.10): point masses at the link ends, M entries as printed
    L1, L2 = symbols("L1 L2", positive=True)
    arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                 Twist.rotation([0, 0, 1], point=[L1, 0, 0])],
                inertias=[SpatialInertia.point_mass(m1, [L1, 0, 0]),
                          SpatialInertia.point_mass(m2, [L1 + L2, 0, 0])])
    M = ImmutableMatrix([
        [m1 * L1**2 + m2 * (L1**2 + 2 * L1 * L2 * cos(q2) + L2**2), m2 * (L1 * L2 * cos(q2) + L2**2)],
        [m2 * (L1 * L2 * cos(q2) + L2**2), m2 * L2**2]])
    assert _zero(arm.mass_matrix([q1, q2]) - M)
    c = ImmutableMatrix([-m2 * L1 * L2 * sin(q2) * (2 * u1 * u2 + u2**2), m2 * L1 * L2 * u1**2 * sin(q2)])
    assert _zero(arm.inverse_dynamics([q1, q2], [u1, u2], [0, 0], [0, 0, 0]) - c)


def test_mdot_minus_2c_is_skew_symmetric_on_the_planar_2r():
    arm = planar_2r()
    H, C = arm.mass_matrix([q1, q2]), arm.coriolis_matrix([q1, q2], [u1, u2])
    N = H.diff(q1) * u1 + H.diff(q2) * u2 - 2 * C
    assert _zero(N + N.T) and not _zero(N)


@pytest.mark.slow
def test_mdot_minus_2c_is_skew_symmetric_on_a_spatial_3r_arm():
    # a 3R arm with skew axes and full (rational) inertias, symbolic q and qd
    q = symbols("q1:4", real=True)
    qd = symbols("u1:4", real=True)
    arm = Chain(
        [Twist.rotation([0, 0, 1], point=[0, 0, 0]), Twist.rotation([0, 1, 0], point=[0, 0, 1]),
         Twist.rotation([1, 0, 0], point=[1, 0, 1])],
        inertias=[SpatialInertia(2, [0, 0, Rational(1, 2)], ImmutableMatrix.diag(1, 1, 1)),
                  SpatialInertia(1, [Rational(1, 2), 0, 1], [[1, 0, 0], [0, 2, 0], [0, 0, 2]]),
                  SpatialInertia(1, [1, Rational(1, 3), 1], ImmutableMatrix.diag(1, 1, 1))],
    )
    H, C = arm.mass_matrix(q), arm.coriolis_matrix(q, qd)
    Hdot = sum((H.diff(qk) * uk for qk, uk in zip(q, qd, strict=True)), zeros(3, 3))
    N = Hdot - 2 * C
    assert _zero(N + N.T)
    # N itself is not zero (the property is not vacuous), nor symmetric
    assert not _zero(N) and not _zero(N - N.T)
    # and C qd is the velocity part of Newton-Euler's torques
    assert _zero(C * ImmutableMatrix(qd) - arm.inverse_dynamics(q, qd, [0, 0, 0], [0, 0, 0]))


def test_regressor_times_parameters_is_the_torque():
    arm = planar_2r()
    Y = arm.regressor([q1, q2], [u1, u2], [a1, a2], [0, -g, 0])
    assert Y.shape == (2, 20)
    pi = ImmutableMatrix.vstack(*(b.parameters() for b in arm.inertias))
    tau = arm.inverse_dynamics([q1, q2], [u1, u2], [a1, a2], [0, -g, 0])
    assert _zero(Y * pi - tau)
    assert not Y.free_symbols & {m1, m2, lc1, lc2, I1, I2}   # free of the inertial parameters
    # a wrong parameter order (I_yy and I_xz exchanged) breaks it on a spatial chain
    rng = np.random.default_rng(2111)
    chain = random_chain(rng, 3)
    x = [Float(v) for v in rng.normal(size=9)]
    Y = np.array(chain.regressor(x[:3], x[3:6], x[6:], [0, 0, -9.81]), dtype=float)
    tau = np.array(chain.inverse_dynamics(x[:3], x[3:6], x[6:], [0, 0, -9.81]), dtype=float).ravel()
    p = np.concatenate([np.array(b.parameters(), dtype=float).ravel() for b in chain.inertias])
    np.testing.assert_allclose(Y @ p, tau, rtol=1e-10, atol=1e-9)
    swapped = p.reshape(3, 10)[:, [0, 1, 2, 3, 4, 5, 7, 6, 8, 9]].ravel()
    assert np.abs(Y @ swapped - tau).max() > 1e-6


def test_prismatic_joint_carries_weight_and_inertia():
    # a vertical slider with mass m: force = m (qdd + g); a horizontal one feels no weight
    m, z, zd, zdd = symbols("m", positive=True), *symbols("z zd zdd", real=True)
    up = Chain([Twist.translation([0, 0, 1])], inertias=[SpatialInertia.point_mass(m, [1, 2, 3])])
    assert up.inverse_dynamics([z], [zd], [zdd], [0, 0, -g]) == ImmutableMatrix([m * (g + zdd)])
    side = Chain([Twist.translation([1, 0, 0])], inertias=[SpatialInertia.point_mass(m, [1, 2, 3])])
    assert side.inverse_dynamics([z], [zd], [zdd], [0, 0, -g]) == ImmutableMatrix([m * zdd])


def test_default_gravity_is_symbolic_and_downward():
    (g0,) = screwsym.motion.dynamics.GRAVITY[2].free_symbols
    # a mass at x = 1 turning about -y rises as q grows: holding it takes m g0 cos(q)
    pendulum = Chain([Twist.rotation([0, -1, 0], point=[0, 0, 0])],
                     inertias=[SpatialInertia.point_mass(m1, [1, 0, 0])])
    assert pendulum.gravity_torques([q1]) == ImmutableMatrix([g0 * m1 * cos(q1)])
    # the planar arm lies in the horizontal plane: gravity along -z does no work on it
    assert planar_2r().gravity_torques([q1, q2]) == zeros(2, 1)


def test_chain_without_inertias_is_unchanged_and_refuses_dynamics():
    twists = [Twist.rotation([0, 0, 1], point=[0, 0, 0])]
    kinematic = Chain(twists, Transform.translation([1, 0, 0]))
    assert len(kinematic.args) == 2 and kinematic.inertias is None
    assert str(kinematic) == "Chain([Twist([0, 0, 1], [0, 0, 0])], Transform(R=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], p=[1, 0, 0]))"
    with pytest.raises(ValueError, match="chain: the chain has no inertias"):
        kinematic.mass_matrix([q1])
    body = SpatialInertia.point_mass(1, [1, 0, 0])
    dynamic = Chain(twists, Transform.translation([1, 0, 0]), [body])
    assert dynamic.func(*dynamic.args) == dynamic and dynamic.inertias == (body,)
    assert "inertias=[SpatialInertia(mass=1, com=[1, 0, 0]" in str(dynamic)
    assert dynamic.forward([q1]) == kinematic.forward([q1])
    with pytest.raises(ValueError, match="inertias: expected 1 spatial inertias, got 2"):
        Chain(twists, None, [body, body])
    with pytest.raises(TypeError, match=r"inertias\[0\]: expected"):
        Chain(twists, None, [1])
    with pytest.raises(ValueError, match="link_frames: given without inertias"):
        Chain(twists, None, link_frames=[Transform.identity()])
    with pytest.raises(ValueError, match="qd: expected 1 joint values, got 2"):
        dynamic.inverse_dynamics([q1], [u1, u2], [a1])


def test_link_frames_carry_link_inertias_to_the_space_frame():
    T = Transform.rotation([0, 0, 1], Rational(1, 1) * 0 + 1, point=[1, 0, 0])
    local = SpatialInertia(2, [1, 0, 0], ImmutableMatrix.diag(1, 2, 3))
    twists = [Twist.rotation([0, 0, 1], point=[0, 0, 0])]
    a = Chain(twists, None, [local], link_frames=[T])
    assert a.inertias == (T.apply(local),)


def test_through_lambdify_batched():
    pytest.importorskip("numpy")
    arm = Chain(
        [Twist.rotation([0, 0, 1], point=[0, 0, 0]), Twist.rotation([0, 0, 1], point=[1, 0, 0])],
        inertias=[SpatialInertia(1, [Rational(1, 2), 0, 0], ImmutableMatrix.diag(1, 1, 1)),
                  SpatialInertia(2, [Rational(3, 2), 0, 0], ImmutableMatrix.diag(1, 1, 1))],
    )
    q, qd, qdd = ImmutableMatrix(symbols("q1:3", real=True)), ImmutableMatrix(symbols("u1:3", real=True)), ImmutableMatrix(symbols("a1:3", real=True))
    tau = arm.inverse_dynamics(q, qd, qdd, [0, -Rational(981, 100), 0])
    f = screwsym.lambdify([q, qd, qdd], tau, backend="numpy")
    rng = np.random.default_rng(2112)
    X = rng.normal(size=(3, 50, 2))
    out = f(*X)
    assert out.shape == (50, 2, 1) or out.shape == (50, 2)
    for k in (0, 17, 49):
        sub = dict(zip([*q, *qd, *qdd], [Float(v) for v in X[:, k, :].ravel()], strict=True))
        np.testing.assert_allclose(np.ravel(out[k]), np.array(tau.xreplace(sub), dtype=float).ravel(), rtol=1e-12)
