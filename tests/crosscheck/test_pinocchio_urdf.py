"""Chains read from real robots' URDF files against pinocchio loading the same files.

The files (tests/data/urdf, from example-robot-data) are the Universal Robots UR5 and the
Franka Emika Panda.  pinocchio (``pin.buildModelFromUrdf``) gives the frame placements and the
frame Jacobians at 200 random configurations per robot; screwsym's symbolic chain is turned into
one numeric function by ``screwsym.lambdify`` and evaluated on the whole batch.  pinocchio's
6-vectors are (v; omega), ours (omega; v): its WORLD frame Jacobian is our space Jacobian, its
LOCAL one our body Jacobian, with the halves swapped.  The angle policy is angles="pi/12" (the
files' rpy decimals of pi/2 are within 5e-12 of it); the exact reading is compared too, on the
twists and home.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from _motions import to_float
from sympy import Matrix, symbols

from screwsym import Chain, lambdify

pin = pytest.importorskip("pinocchio")
pytest.importorskip("defusedxml")
mr = pytest.importorskip("modern_robotics")

from screwsym.motion.urdf import path_joints, read_inertials  # noqa: E402

DATA = Path(__file__).parent.parent / "data" / "urdf"
N = 200  # configurations per robot (issue 22)
ROBOTS = {
    "ur5": (DATA / "ur5_robot.urdf", "base_link", "tool0"),
    "panda": (DATA / "panda.urdf", "panda_link0", "panda_hand_tcp"),
}


def _swap(J):
    """(v; omega) rows to (omega; v)."""
    return np.concatenate([J[..., 3:, :], J[..., :3, :]], axis=-2)


def pinocchio_batch(name, Q):
    """pinocchio's tip placement and its WORLD and LOCAL Jacobians (ray order) for each row of Q."""
    path, base, tip = ROBOTS[name]
    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    ids = [model.getJointId(j) for j in path_joints(path, base, tip)]
    frame = model.getFrameId(tip)
    base_frame = model.getFrameId(base)
    T, Js, Jb = [], [], []
    for qs in Q:
        q = pin.neutral(model)
        for jid, value in zip(ids, qs, strict=True):
            q[model.joints[jid].idx_q] = value
        pin.computeJointJacobians(model, data, q)
        pin.updateFramePlacements(model, data)
        assert np.allclose(data.oMf[base_frame].homogeneous, np.eye(4))  # the base is the world here
        columns = [model.joints[jid].idx_v for jid in ids]
        T.append(data.oMf[frame].homogeneous)
        Js.append(_swap(pin.getFrameJacobian(model, data, frame, pin.WORLD)[:, columns]))
        Jb.append(_swap(pin.getFrameJacobian(model, data, frame, pin.LOCAL)[:, columns]))
    return np.array(T), np.array(Js), np.array(Jb), model, data, ids


def chain_of(name, angles="pi/12"):
    path, base, tip = ROBOTS[name]
    return Chain.from_urdf(path, base=base, tip=tip, angles=angles)


def configurations(seed, n_joints):
    return np.random.default_rng(seed).uniform(-np.pi, np.pi, size=(N, n_joints))


@pytest.mark.slow
def test_ur5_symbolic_chain_against_pinocchio():
    """Forward kinematics, space and body Jacobians, symbolic then lambdified, 200 poses."""
    chain = chain_of("ur5")
    q = Matrix(symbols("q1:7", real=True))
    f = lambdify([q], (chain.forward(list(q)).matrix, chain.jacobian(list(q)),
                       chain.jacobian(list(q), frame="body")), names=["q"])
    Q = configurations(2201, 6)
    T, Js, Jb = f(Q)
    T_pin, Js_pin, Jb_pin, *_ = pinocchio_batch("ur5", Q)
    np.testing.assert_allclose(T, T_pin, atol=1e-10)
    np.testing.assert_allclose(Js, Js_pin, atol=1e-10)
    np.testing.assert_allclose(Jb, Jb_pin, atol=1e-10)
    # the comparison can fail: the halves unswapped, or the frames exchanged
    assert not np.allclose(Js, Jb_pin, atol=1e-3)
    assert not np.allclose(Js, _swap(Js_pin), atol=1e-3)


@pytest.mark.parametrize("name,seed", [("ur5", 2204), ("panda", 2202)])
def test_chain_against_pinocchio_numerically(name, seed):
    """The exact chain (twists and home as read), evaluated by the product of exponentials in
    floats (modern_robotics' FKinSpace, JacobianSpace, JacobianBody), 200 poses.  This checks
    the reading of the file cheaply; the symbolic path (Chain.forward, Chain.jacobian) is in the
    slow tests."""
    chain = chain_of(name)
    M = to_float(chain.home.matrix)
    S = np.array([to_float(t.matrix).ravel() for t in chain.twists]).T
    B = mr.Adjoint(mr.TransInv(M)) @ S
    Q = configurations(seed, chain.n_joints)
    T_pin, Js_pin, Jb_pin, *_ = pinocchio_batch(name, Q)
    for k, qs in enumerate(Q):
        np.testing.assert_allclose(mr.FKinSpace(M, S, qs), T_pin[k], atol=1e-10)
        np.testing.assert_allclose(mr.JacobianSpace(S, qs), Js_pin[k], atol=1e-10)
        np.testing.assert_allclose(mr.JacobianBody(B, qs), Jb_pin[k], atol=1e-10)
    # the exact reading of the decimals (the default policy) is the same robot to 1e-10 (the
    # UR5 file writes pi/2 as 1.57079632679, 4.9e-12 short; the Panda's 17 digits are 1e-16 off)
    exact = chain_of(name, angles="exact")
    np.testing.assert_allclose(to_float(exact.home.matrix), M, atol=1e-10)
    for s, t in zip(exact.twists, chain.twists, strict=True):
        np.testing.assert_allclose(to_float(s.matrix), to_float(t.matrix), atol=1e-10)


@pytest.mark.slow
def test_panda_symbolic_chain_against_pinocchio():
    """Seven symbolic angles (angles="pi/12"): forward kinematics and the space Jacobian, then
    lambdified, 200 poses; the body Jacobian as Ad(T^-1) J_s of the same numbers (the symbolic
    body Jacobian of the Panda takes minutes today: benchmarks/bench_urdf.py)."""
    chain = chain_of("panda")
    q = Matrix(symbols("q1:8", real=True))
    f = lambdify([q], (chain.forward(list(q)).matrix, chain.jacobian(list(q))), names=["q"])
    Q = configurations(2203, 7)
    T, Js = f(Q)
    T_pin, Js_pin, Jb_pin, *_ = pinocchio_batch("panda", Q)
    np.testing.assert_allclose(T, T_pin, atol=1e-10)
    np.testing.assert_allclose(Js, Js_pin, atol=1e-10)
    Jb = np.array([mr.Adjoint(mr.TransInv(T[k])) @ Js[k] for k in range(N)])
    np.testing.assert_allclose(Jb, Jb_pin, atol=1e-10)


@pytest.mark.parametrize("name", ["ur5", "panda"])
def test_inertias_against_pinocchio(name):
    """read_inertials' bodies (mass, com, inertia about the com, space frame at home) against
    pinocchio's model.inertias (per joint, fixed links merged, in the joint frame) moved to the
    world at q = 0.  Read exactly as written (angles="exact"), as pinocchio reads the decimals."""
    path, base, tip = ROBOTS[name]
    ours = read_inertials(path, base, tip, angles="exact")
    *_, model, data, ids = pinocchio_batch(name, np.zeros((1, len(ours))))
    pin.forwardKinematics(model, data, pin.neutral(model))
    def below(j, jid):  # is pinocchio's joint j jid itself or behind it, off the path?
        while j > 0 and j not in ids:
            j = model.parents[j]
        return j == jid

    for body, jid in zip(ours, ids, strict=True):
        # the body in the world: the joint's inertia, and those of the joints off the path behind
        # it (the Panda's fingers) at their zero position, added as pinocchio adds inertias
        world = pin.Inertia.Zero()
        for j in range(1, model.njoints):
            if below(j, jid):
                world = world + data.oMi[j].act(model.inertias[j])
        assert float(body.mass) == pytest.approx(world.mass, abs=1e-12)
        np.testing.assert_allclose(to_float(body.com).ravel(), world.lever, atol=1e-12)
        np.testing.assert_allclose(to_float(body.inertia), world.inertia, atol=1e-12)


@pytest.mark.parametrize("name", ["ur5", "panda"])
def test_a_urdf_chain_with_its_inertias_gives_pinocchios_torques(name):
    # issues 21 and 22 together: Chain.from_urdf(..., inertias=True) keeps the file's inertias on
    # the chain, and Newton-Euler in screw form (screwsym.motion.dynamics) gives the torques
    # pinocchio's rnea computes from the same file, gravity (0, 0, -9.81) as pinocchio's default
    from sympy import Float, Rational

    path, base, tip = ROBOTS[name]
    chain = Chain.from_urdf(path, base, tip, angles="pi/12", inertias=True)
    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    ids = [model.getJointId(j) for j in path_joints(path, base, tip)]
    rng = np.random.default_rng([22, 21, len(name)])
    for _ in range(2):
        q, qd, qdd = (rng.uniform(-2, 2, chain.n_joints) for _ in range(3))
        tau = chain.inverse_dynamics(*([Float(x) for x in v] for v in (q, qd, qdd)),
                                     gravity=[0, 0, Rational(-981, 100)])
        full = [pin.neutral(model), np.zeros(model.nv), np.zeros(model.nv)]
        for jid, *values in zip(ids, q, qd, qdd, strict=True):
            joint = model.joints[jid]
            full[0][joint.idx_q], full[1][joint.idx_v], full[2][joint.idx_v] = values
        ref = pin.rnea(model, data, *full)[[model.joints[j].idx_v for j in ids]]
        got = np.array(tau, dtype=float).ravel()
        assert np.allclose(got, ref, rtol=1e-9, atol=1e-9 * np.abs(ref).max())
        assert not np.allclose(got, pin.rnea(model, data, full[0], full[1], 0 * full[2])
                               [[model.joints[j].idx_v for j in ids]])  # the check can fail
