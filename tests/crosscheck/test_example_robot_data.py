"""Every serial arm of example-robot-data, read with the default options, against pinocchio.

example-robot-data (a test-only dependency, ``pip install example-robot-data``: the robots'
URDF files as data) ships fifteen serial arms, from a double pendulum to the Kinova j2s6s200,
the Franka Panda and the xArm7.  Each is read by ``Chain.from_urdf(path, base, tip)`` with the
default angle rule (decimals that print a multiple of pi/12 are that multiple), and compared
with pinocchio loading the same file (``pin.buildModelFromUrdf``: the root link fixed as the
world) at seeded random states: the tip placement, the space Jacobian (pinocchio's WORLD frame
Jacobian, its halves swapped to ray order), the mass matrix (``pin.crba``) and the inverse
dynamics (``pin.rnea``, gravity (0, 0, -9.81)).  Joints off the path (grippers) are held at
their zero position and at rest in pinocchio, which is what ``read_inertials`` locks them at.
The states are floats (``sympy.Float``): the exact chain evaluated at them.

The default run has FK and J for every arm and M and tau for the quick ones; M and tau of the
7-joint Panda and the Kinova (a few seconds each) are in the slow set.  The SO-100 and SO-101
files have angles that are no multiple of pi/12 (``-1.8``, ``0.0486795``, ``1.57079``: pi/2
truncated, not rounded), read exactly: their chains hold sines and cosines of those numbers
(kept as ring generators on their circles, ``screwsym.motion.angles.constant_trig_normal``),
and they are compared like the others.
"""

from __future__ import annotations

import importlib.metadata
import re
import warnings
from pathlib import Path

import numpy as np
import pytest
from sympy import Float, Rational

from screwsym import Chain

pin = pytest.importorskip("pinocchio")
pytest.importorskip("defusedxml")

from screwsym.motion.angles import recognise_decimal  # noqa: E402
from screwsym.motion.urdf import path_joints  # noqa: E402


def robots_dir() -> Path | None:
    """The robots folder of the installed example-robot-data (a data-only wheel), or None."""
    try:
        dist = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        return None
    path = Path(str(dist.locate_file("cmeel.prefix/share/example-robot-data/robots")))
    return path if path.is_dir() else None


ROOT = robots_dir()
if ROOT is None:
    pytest.skip("example-robot-data is not installed (pip install example-robot-data)",
                allow_module_level=True)

#: name: (file under robots/, tip link or None for the only leaf); the base is the root link
ARMS = {
    "double_pendulum": ("double_pendulum_description/urdf/double_pendulum.urdf", None),
    "asr_twodof": ("asr_twodof_description/urdf/TwoDofs.urdf", None),
    "borinot_flying_arm_2": ("borinot_description/urdf/borinot_flying_arm_2.urdf", None),
    "finger_edu": ("finger_edu_description/robots/finger_edu.urdf", None),
    "hextilt_flying_arm_5": ("hextilt_description/urdf/hextilt_flying_arm_5.urdf", None),
    "so100": ("so_arm_description/urdf/so100.urdf", None),
    "so101": ("so_arm_description/urdf/so101.urdf", "gripper_frame_link"),
    "ur3": ("ur_description/urdf/ur3_robot.urdf", "tool0"),
    "ur5": ("ur_description/urdf/ur5_robot.urdf", "tool0"),
    "ur10": ("ur_description/urdf/ur10_robot.urdf", "tool0"),
    "kinova": ("kinova_description/robots/kinova.urdf", "j2s6s200_end_effector"),
    "talos_left_arm": ("talos_data/robots/talos_left_arm.urdf", "gripper_left_base_link"),
    "panda": ("panda_description/urdf/panda.urdf", "panda_hand_tcp"),
    "xarm7": ("xarm_description/urdf/xarm7.urdf", None),
    "z1": ("z1_description/urdf/z1.urdf", None),
}
#: M and tau of these take a few seconds each (the slow set)
SLOW_DYNAMICS = {"panda", "kinova", "so100"}
#: FK and J at floats of these take a few seconds each (the slow set): the SO-100's six frames
#: hold the sines of three angles that are no multiple of pi/12
SLOW_KINEMATICS = {"so100"}
STATES = 2
TOL = 1e-9


def read(name: str, inertias: bool = False) -> Chain:
    path, tip = ARMS[name]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the RecognisedAngleWarning: listed on chain.recognised
        return Chain.from_urdf(ROOT / path, None, tip, inertias=inertias)


def as_read(text: str) -> str:
    """The URDF text with each rpy decimal that the angle rule recognises written as the double
    of the value it is read as (1.5708 -> 1.5707963267948966): the robot screwsym reads."""
    def one(m):
        values = []
        for token in m.group(1).split():
            value = recognise_decimal(token)
            values.append(token if value is None else repr(float(value)))
        return f'rpy="{" ".join(values)}"'
    return re.sub(r'rpy="([^"]*)"', one, text)


class Pinocchio:
    """pinocchio's model of the file, with the chain's joints picked out (base: the root).

    ``exact=False``: the file as written; else the file as screwsym reads it (:func:`as_read`).
    """

    def __init__(self, name: str, as_written: bool = False):
        path, tip = ARMS[name]
        text = (ROOT / path).read_text(encoding="utf-8")
        self.model = pin.buildModelFromXML(text if as_written else as_read(text))
        self.data = self.model.createData()
        self.joints = [self.model.joints[self.model.getJointId(j)]
                       for j in path_joints(ROOT / path, None, tip)]
        self.frame = self.model.getFrameId(tip) if tip else self.model.nframes - 1
        self.columns = [j.idx_v for j in self.joints]

    def q(self, values):
        q = pin.neutral(self.model)
        for joint, x in zip(self.joints, values, strict=True):
            if joint.nq == 2:  # a continuous joint: (cos, sin)
                q[joint.idx_q:joint.idx_q + 2] = np.cos(x), np.sin(x)
            else:
                q[joint.idx_q] = x
        return q

    def v(self, values):
        v = np.zeros(self.model.nv)
        v[self.columns] = values
        return v

    def kinematics(self, values):
        q = self.q(values)
        pin.computeJointJacobians(self.model, self.data, q)
        pin.updateFramePlacements(self.model, self.data)
        J = pin.getFrameJacobian(self.model, self.data, self.frame, pin.WORLD)[:, self.columns]
        return self.data.oMf[self.frame].homogeneous, np.vstack([J[3:], J[:3]])

    def dynamics(self, q, qd, qdd):
        M = pin.crba(self.model, self.data, self.q(q))
        M = np.triu(M) + np.triu(M, 1).T
        tau = pin.rnea(self.model, self.data, self.q(q), self.v(qd), self.v(qdd))
        return M[np.ix_(self.columns, self.columns)], tau[self.columns]


def _places(text: str) -> int:
    mantissa, _, exponent = text.lower().partition("e")
    return len(mantissa.partition(".")[2]) - int(exponent or 0)


def states(name: str, n: int, k: int = STATES):
    rng = np.random.default_rng([33, len(name), sum(map(ord, name))])
    return [tuple(rng.uniform(-2, 2, n) for _ in range(3)) for _ in range(k)]


def floats(values):
    return [Float(float(x)) for x in values]


def numeric(m):
    return np.array(m, dtype=float)


def kinematics(name, chain, q):
    """The chain's tip pose and space Jacobian at the float state ``q``."""
    return numeric(chain.forward(floats(q)).matrix), numeric(chain.jacobian(floats(q)))


@pytest.mark.parametrize("name", [pytest.param(name, marks=[pytest.mark.slow] * (name in SLOW_KINEMATICS))
                                  for name in ARMS])
def test_forward_kinematics_and_jacobian_against_pinocchio(name):
    chain, ref = read(name), Pinocchio(name)
    assert chain.n_joints == len(ref.joints) >= 2
    for q, _, _ in states(name, chain.n_joints):
        T_ref, J_ref = ref.kinematics(q)
        T, J = kinematics(name, chain, q)
        np.testing.assert_allclose(T, T_ref, atol=TOL)
        np.testing.assert_allclose(J, J_ref, atol=TOL)
        # the comparison can fail: pinocchio at another state differs
        assert not np.allclose(T, ref.kinematics(np.asarray(q) + 0.1)[0], atol=1e-3)
    # against the file as written: the recognised angles moved the robot by no more than their
    # printed precision (5e-5 rad per angle at four places), and by something where any moved
    written = Pinocchio(name, as_written=True)
    q = states(name, chain.n_joints)[0][0]
    gap = np.abs(kinematics(name, chain, q)[0] - written.kinematics(q)[0]).max()
    bound = sum(10.0 ** -_places(r.text) for r in chain.recognised)
    assert gap <= 4 * bound + 1e-12, (gap, bound)


def _dynamics_params():
    out = []
    for name in ARMS:
        marks = []
        if name in SLOW_DYNAMICS:
            marks.append(pytest.mark.slow)
        out.append(pytest.param(name, marks=marks))
    return out


@pytest.mark.parametrize("name", _dynamics_params())
def test_mass_matrix_and_inverse_dynamics_against_pinocchio(name):
    chain, ref = read(name, inertias=True), Pinocchio(name)
    gravity = [0, 0, Rational(-981, 100)]
    for q, qd, qdd in states(name, chain.n_joints, 1):
        M_ref, tau_ref = ref.dynamics(q, qd, qdd)
        M = numeric(chain.mass_matrix(floats(q)))
        tau = numeric(chain.inverse_dynamics(floats(q), floats(qd), floats(qdd), gravity=gravity)).ravel()
        scale = max(1.0, np.abs(M_ref).max())
        np.testing.assert_allclose(M, M_ref, atol=TOL * scale)
        np.testing.assert_allclose(tau, tau_ref, atol=TOL * max(1.0, np.abs(tau_ref).max()))
        assert not np.allclose(tau, ref.dynamics(q, qd, 0 * qdd)[1], atol=1e-6)  # can fail


def test_the_arms_are_read_with_the_angle_rule():
    """What the default rule did on these files: the Kinova's and the xArm's decimals of pi/2
    are recognised (the cases of issue 33), the SO-100's truncated 1.57079 is not."""
    kinova, xarm, so100 = read("kinova"), read("xarm7"), read("so100")
    assert len(kinova.recognised) >= 6 and len(xarm.recognised) >= 6
    assert {r.text for r in xarm.recognised} >= {"1.5708", "-1.5708"}
    assert not any(r.text == "1.57079" for r in so100.recognised)
