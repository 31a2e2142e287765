"""Dynamics checked against implementations nobody here wrote: modern_robotics and pinocchio.

modern_robotics (Lynch & Park's code for *Modern Robotics*, 2017: ``InverseDynamics``,
``MassMatrix``, ``GravityForces``, the recursive Newton-Euler of their Section 8.3) and
pinocchio (``rnea``, ``crba``, ``computeCoriolisMatrix``, ``computeGeneralizedGravity``)
are numeric, so screwsym's exact algorithm is run on floating-point joint values (tidy
leaves floats as they are, which keeps this cheap) and compared with a tolerance here, in
the test.  The chains: the UR5 with the inertias of the Modern Robotics course (its
``Mlist``, ``Glist``, ``Slist``, tests/_dynamics.py) and 200 random chains of 2 to 7
revolute and prismatic joints with random rational bodies (each case reruns alone:
``pytest "tests/crosscheck/test_dynamics_peers.py::test_random_chains[17]" --slow``).

For modern_robotics a random chain is given with every link frame ``{i}`` coinciding with
the space frame at home (``M_{i-1,i} = 1``), the frames screwsym's dynamics use, and
``G_i = convert(inertia, to="modern_robotics")``; for pinocchio each joint gets a frame on
its axis with z along it, and the body is carried into it.
"""

from __future__ import annotations

import numpy as np
import pytest
from _backends import HAS_CC
from _dynamics import mr_ur5_chain, mr_ur5_lists, random_chain, ur5_torque_expanded
from _robots import pin_model
from sympy import Float, ImmutableMatrix, count_ops

from screwsym import SpatialInertia, convert, convert_from

mr = pytest.importorskip("modern_robotics")

GRAVITY = np.array([0.0, 0.0, -9.81])
N_DEFAULT = 6  # the first cases run by default; all 200 with --slow


def _f(x) -> list[Float]:
    return [Float(float(v)) for v in x]


def _ours(chain, q, qd, qdd):
    g = list(_f(GRAVITY))
    tau = np.array(chain.inverse_dynamics(_f(q), _f(qd), _f(qdd), g), dtype=float).ravel()
    H = np.array(chain.mass_matrix(_f(q)), dtype=float)
    return tau, H


def _mr_lists(chain):
    n = chain.n_joints
    Mlist = [np.eye(4)] * n + [np.array(chain.home.matrix, dtype=float)]
    Glist = [np.array(convert(b, to="modern_robotics"), dtype=float) for b in chain.inertias]
    Slist = np.array([np.array(t.matrix, dtype=float).ravel() for t in chain.twists]).T
    return Mlist, Glist, Slist


def _check_against_peers(chain, rng):
    n = chain.n_joints
    q, qd, qdd = rng.uniform(-2, 2, size=(3, n))
    tau, H = _ours(chain, q, qd, qdd)
    Mlist, Glist, Slist = _mr_lists(chain)
    np.testing.assert_allclose(
        tau, mr.InverseDynamics(q, qd, qdd, GRAVITY, np.zeros(6), Mlist, Glist, Slist),
        rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(H, mr.MassMatrix(q, Mlist, Glist, Slist), rtol=1e-9, atol=1e-9)
    try:
        import pinocchio as pin
    except ImportError:
        return
    model = pin_model(pin, chain, GRAVITY)
    data = model.createData()
    np.testing.assert_allclose(tau, pin.rnea(model, data, q, qd, qdd), rtol=1e-9, atol=1e-9)
    M = np.triu(pin.crba(model, data, q))
    np.testing.assert_allclose(H, M + np.triu(M, 1).T, rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize(
    "case", [pytest.param(c, marks=() if c < N_DEFAULT else pytest.mark.slow) for c in range(200)]
)
def test_random_chains(case):
    rng = np.random.default_rng([2121, case])
    chain = random_chain(rng, 2 + case % 6)
    _check_against_peers(chain, rng)


@pytest.mark.parametrize("case", range(3))
def test_gravity_and_coriolis_against_peers(case):
    rng = np.random.default_rng([2122, case])
    chain = random_chain(rng, 3 + case)
    n = chain.n_joints
    q, qd = rng.uniform(-2, 2, size=(2, n))
    Mlist, Glist, Slist = _mr_lists(chain)
    G = np.array(chain.gravity_torques(_f(q), _f(GRAVITY)), dtype=float).ravel()
    np.testing.assert_allclose(G, mr.GravityForces(q, GRAVITY, Mlist, Glist, Slist), atol=1e-9)
    pin = pytest.importorskip("pinocchio")
    model = pin_model(pin, chain, GRAVITY)
    np.testing.assert_allclose(G, pin.computeGeneralizedGravity(model, model.createData(), q), atol=1e-9)


@pytest.mark.parametrize("case", range(2))
def test_coriolis_against_peers(case):
    # the Christoffel symbols differentiate the symbolic mass matrix: two joints keep it cheap
    rng = np.random.default_rng([2126, case])
    chain = random_chain(rng, 2)
    q, qd = rng.uniform(-2, 2, size=(2, 2))
    Mlist, Glist, Slist = _mr_lists(chain)
    C = np.array(chain.coriolis_matrix(_f(q), _f(qd)), dtype=float)
    np.testing.assert_allclose(C @ qd, mr.VelQuadraticForces(q, qd, Mlist, Glist, Slist), atol=1e-9)
    pin = pytest.importorskip("pinocchio")
    model = pin_model(pin, chain, GRAVITY)
    data = model.createData()
    # pinocchio's C is another factorisation; C qd and the skew property are what both share
    Cp = pin.computeCoriolisMatrix(model, data, q, qd)
    np.testing.assert_allclose(C @ qd, Cp @ qd, atol=1e-9)


def test_ur5_with_the_book_inertias():
    chain = mr_ur5_chain()
    Mlist, Glist, Slist = mr_ur5_lists()
    rng = np.random.default_rng(2123)
    for _ in range(3):
        q, qd, qdd = rng.uniform(-np.pi, np.pi, size=(3, 6))
        tau, H = _ours(chain, q, qd, qdd)
        np.testing.assert_allclose(
            tau, mr.InverseDynamics(q, qd, qdd, GRAVITY, np.zeros(6), Mlist, Glist, Slist),
            rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(H, mr.MassMatrix(q, Mlist, Glist, Slist), atol=1e-12)
        G = np.array(chain.gravity_torques(_f(q), _f(GRAVITY)), dtype=float).ravel()
        np.testing.assert_allclose(G, mr.GravityForces(q, GRAVITY, Mlist, Glist, Slist), atol=1e-10)
    # a wrong inertia would be seen: the last link's mass doubled changes the torques
    wrong = mr.InverseDynamics(q, qd, qdd, GRAVITY, np.zeros(6), Mlist, Glist[:5] + [2 * Glist[5]], Slist)
    assert np.abs(tau - wrong).max() > 1e-3


@pytest.fixture(scope="module")
def ur5_wrist_torque():
    return ur5_torque_expanded(3)


@pytest.mark.slow
@pytest.mark.parametrize("backend", ["numpy", pytest.param(
    "c", marks=pytest.mark.skipif(not HAS_CC, reason="no C compiler"))])
def test_the_ur5s_expanded_inverse_dynamics_compiles_and_agrees(ur5_wrist_torque, backend):
    # Issue 23 item 5: lambdify of the UR5's expanded inverse dynamics (about 120,000
    # operations) raised RecursionError.  Joint 4's torque, expanded, through NumPy and C,
    # against modern_robotics.InverseDynamics (Lynch & Park 2017, Section 8.3) at random
    # configurations; numba compiles such a function for minutes (tests/codegen/test_large.py).
    from screwsym.codegen import lambdify

    e, (q, qd, qdd) = ur5_wrist_torque
    assert count_ops(e) > 100_000
    f = lambdify([ImmutableMatrix(v) for v in (q, qd, qdd)], e, backend=backend)
    rng = np.random.default_rng([2127, 0])
    Q, QD, QDD = rng.uniform(-np.pi, np.pi, size=(3, 20, 6))
    ours = f(Q, QD, QDD)
    Mlist, Glist, Slist = mr_ur5_lists()
    ref = np.array([mr.InverseDynamics(*x, GRAVITY, np.zeros(6), Mlist, Glist, Slist)
                    for x in zip(Q, QD, QDD, strict=True)])
    np.testing.assert_allclose(ours, ref[:, 3], rtol=1e-9, atol=1e-9)
    assert f(Q[0], QD[0], QDD[0]) == pytest.approx(ref[0, 3], rel=1e-9, abs=1e-9)
    # the check would see a wrong function: joint 3's torque is not joint 4's
    assert np.abs(ours - ref[:, 2]).max() > 1e-2


def test_inertia_conversions_round_trip_and_match_the_peers():
    rng = np.random.default_rng(2124)
    chain = random_chain(rng, 2)
    for body in chain.inertias:
        for source in ("modern_robotics", "featherstone", "pinocchio", "spatialmath", "pytransform3d"):
            assert convert_from(convert(body, to=source), source, SpatialInertia) == body
        m = float(body.mass)
        c = np.array(body.com, dtype=float).ravel()
        Ic = np.array(body.inertia, dtype=float)
        C = np.array([[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]])
        # Featherstone (2008) (2.63), spatial_v2 mcI: [[I_c + m C C^T, m C], [m C^T, m 1]]
        mcI = np.block([[Ic + m * C @ C.T, m * C], [m * C.T, m * np.eye(3)]])
        np.testing.assert_allclose(np.array(convert(body, to="featherstone"), dtype=float), mcI, atol=1e-12)
    with pytest.raises(ValueError, match="value: expected a spatial inertia"):
        convert_from(np.diag([1.0, 2, 3, 1, 1, 1]), "pinocchio", SpatialInertia)   # m 1 is no multiple of 1


def test_inertia_matches_pinocchio_inertia():
    pin = pytest.importorskip("pinocchio")
    rng = np.random.default_rng(2125)
    body = random_chain(rng, 2).inertias[1]
    m, c, Ic = float(body.mass), np.array(body.com, dtype=float).ravel(), np.array(body.inertia, dtype=float)
    P = pin.Inertia(m, c, Ic)
    np.testing.assert_allclose(np.array(convert(body, to="pinocchio"), dtype=float), P.matrix(), atol=1e-12)
    np.testing.assert_allclose(np.array(body.parameters(), dtype=float).ravel(), P.toDynamicParameters(), atol=1e-12)
