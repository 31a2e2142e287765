"""Inverse kinematics by subproblems (issue 36, items 1, 2 and 4 for serial arms).

The decompositions are the classic ones: Paden (1985); Murray, Li & Sastry (1994), Section 3.3
(the spherical wrist of Pieper 1968); the UR5's three parallel axes (the standard UR
decomposition, as in IK-Geo, Elias & Wen 2025).  The robots: the UR5 of Lynch & Park, *Modern
Robotics*, Example 4.5 (``screwsym.motion.chain.ur5``); Corke's PUMA 560 (Robotics Toolbox
``mdl_puma560``, tests/_robots.py); the Stanford arm of Corke's ``mdl_stanford`` (standard DH,
d1 = 0.412, d2 = 0.154, d6 = 0.263, joint 3 prismatic); the Franka Panda of example-robot-data
with its seventh joint given.  Every branch is checked by an independent forward kinematics,
modern_robotics' ``FKinSpace`` (test-only), and the generating joints must be among the branches.
"""

from __future__ import annotations

import numpy as np
import pytest
from _robots import panda, puma560
from sympy import Dummy, Eq, Matrix, Rational, Symbol, pi, symbols

from screwsym import Chain, Twist
from screwsym.motion.chain import ur5
from screwsym.motion.inverse_kinematics import decomposition, inverse_kinematics, stage_order
from screwsym.numeric import inverse_kinematics_function

mr = pytest.importorskip("modern_robotics")

STANFORD_DH = [(0, -pi / 2, Rational(412, 1000), 0), (0, pi / 2, Rational(154, 1000), 0),
               (0, 0, 0, -pi / 2), (0, -pi / 2, 0, 0), (0, pi / 2, 0, 0),
               (0, 0, Rational(263, 1000), 0)]


def stanford() -> Chain:
    return Chain.from_dh(STANFORD_DH, "standard", "RRPRRR")


def fk(chain: Chain, q) -> np.ndarray:
    """The independent forward kinematics: modern_robotics' product of exponentials."""
    S = np.array([[float(x) for x in t.matrix] for t in chain.twists]).T
    return mr.FKinSpace(np.array(chain.home.matrix, dtype=float), S, np.asarray(q, dtype=float))


def reproduces(chain: Chain, q, T) -> bool:
    return bool(np.abs(fk(chain, q) - T).max() < 1e-9)


def wrapped(d: np.ndarray, revolute) -> np.ndarray:
    d = d.copy()
    d[..., revolute] = np.mod(d[..., revolute] + np.pi, 2 * np.pi) - np.pi
    return d


ROBOTS = {
    "ur5": (ur5, (), "three parallel axes"),
    "puma560": (puma560, (), "spherical wrist"),
    "stanford": (stanford, (), "spherical wrist"),
    "panda": (panda, (6,), "spherical wrist reversed"),
}


@pytest.mark.filterwarnings("ignore::UserWarning")
@pytest.mark.parametrize("name", sorted(ROBOTS))
def test_the_structure_is_found_exactly(name):
    make, free, kind = ROBOTS[name]
    arm = make()
    twists = [t for i, t in enumerate(arm.twists) if i not in free]
    assert decomposition(twists).kind == kind


@pytest.mark.filterwarnings("ignore::UserWarning")
@pytest.mark.parametrize("name", sorted(ROBOTS))
def test_numeric_round_trip_every_branch_reproduces_the_pose(name):
    make, free, _ = ROBOTS[name]
    arm = make()
    n = arm.n_joints
    revolute = [i for i in range(n) if not (name == "stanford" and i == 2)]
    f = inverse_kinematics_function(arm, free, backend="numpy")
    rng = np.random.default_rng(36)
    q = rng.uniform(-np.pi, np.pi, (60, n))
    if name == "stanford":
        q[:, 2] = rng.uniform(0.2, 1.0, len(q))
    T = np.array([fk(arm, x) for x in q])
    branches = f(T, q[:, list(free)]) if free else f(T)
    assert branches.shape == (len(q), 8, n)
    for k in range(len(q)):
        live = [b for b in branches[k] if not np.isnan(b).any()]
        assert live and all(reproduces(arm, b, T[k]) for b in live)
        assert (np.abs(wrapped(np.array(live) - q[k], revolute)).max(axis=1) < 1e-8).any()
    if name in ("ur5", "puma560"):
        # Murray, Li & Sastry / the UR and PUMA literature: 8 branches at a generic pose
        assert (~np.isnan(branches).any(axis=2)).sum(axis=1).max() == 8


def test_the_ur5_and_the_puma_have_eight_branches_at_a_generic_pose():
    for arm, q in ((ur5(), [0.3, -1.2, 1.5, -0.4, 1.1, 0.7]), (puma560(), [0.3, 0.4, -0.5, 0.6, 0.7, 0.8])):
        T = fk(arm, q)
        branches = inverse_kinematics_function(arm, backend="numpy")(T)
        assert (~np.isnan(branches).any(axis=1)).sum() == 8
        assert len({tuple(np.round(b, 6)) for b in branches}) == 8  # eight distinct solutions


def test_the_checker_rejects_a_wrong_answer():
    arm = ur5()
    q = np.array([0.3, -1.2, 1.5, -0.4, 1.1, 0.7])
    T = fk(arm, q)
    assert reproduces(arm, q, T)
    assert not reproduces(arm, q + [0, 0, 1e-6, 0, 0, 0], T)
    branches = inverse_kinematics_function(arm, backend="numpy")(T)
    wrong = branches.copy()
    wrong[:, 1] += 1e-3
    assert not any(reproduces(arm, b, T) for b in wrong if not np.isnan(b).any())


def test_a_pose_out_of_reach_has_no_branch():
    arm = ur5()
    T = np.eye(4)
    T[:3, 3] = [5, 0, 0]
    assert np.isnan(inverse_kinematics_function(arm, backend="numpy")(T)).all()
    # exact: the PUMA's first stage (joint 3 from the wrist centre's distance) holds numbers
    far = Matrix(4, 4, [1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])
    assert inverse_kinematics(puma560(), far) == ()


def _evaluate(chain, branch, pose, order, free_params):
    """The branch's joint values in stage order, at 30 digits (None: not real there)."""
    subs = dict(pose)
    values = [None] * chain.n_joints
    for j in order:
        v = branch.values[j].xreplace(free_params).xreplace(subs).evalf(30)
        if not v.is_Number:  # complex: the branch does not exist at this pose
            return None
        subs[Symbol(f"q{j + 1}", real=True)] = v
        values[j] = float(v)
    return values


@pytest.mark.slow
@pytest.mark.parametrize("make", [ur5, puma560], ids=["ur5", "puma560"])
def test_the_exact_closed_forms_reach_exact_poses(make):
    # the closed forms themselves, for a symbolic pose, evaluated at 30 digits at poses of
    # angles k pi/12: every real branch reproduces the pose; q is among them
    arm = make()
    entries = symbols("r11 r12 r13 px r21 r22 r23 py r31 r32 r33 pz", real=True)
    T = Matrix(4, 4, [*entries, 0, 0, 0, 1])
    branches = inverse_kinematics(arm, T)
    order = stage_order(arm)
    # the branches of positive measure (the tangent and g = 0 ones hold where an Eq does)
    generic = [b for b in branches
               if not any(v.atoms(Dummy) for v in b.values) and not b.condition.atoms(Eq)]
    rng = np.random.default_rng(12)
    for _ in range(1):
        q = [pi * int(k) / 12 for k in rng.integers(-11, 12, 6)]
        pose_exact = arm.forward(q).matrix
        # the exact pose's entries at 30 digits (exact radicals in evalf's subs are far slower)
        pose = dict(zip(entries, [pose_exact[i, j].evalf(30) for i in range(3) for j in range(4)],
                        strict=True))
        Tn = np.array(pose_exact, dtype=float)
        found = [v for b in generic if (v := _evaluate(arm, b, pose, order, {})) is not None]
        assert found and all(reproduces(arm, v, Tn) for v in found)
        qf = np.array([float(x) for x in q])
        assert (np.abs(wrapped(np.array(found) - qf, list(range(6)))).max(axis=1) < 1e-9).any()


@pytest.mark.slow
def test_a_wrist_singularity_is_its_own_branch_with_a_free_parameter():
    # PUMA at q5 = 0: axes 4 and 6 on one line, only q4 + q6 fixed
    arm = puma560()
    entries = symbols("r11 r12 r13 px r21 r22 r23 py r31 r32 r33 pz", real=True)
    branches = inverse_kinematics(arm, Matrix(4, 4, [*entries, 0, 0, 0, 1]))
    singular = [b for b in branches if isinstance(b.values[3], Dummy)]
    assert singular
    q = [Rational(3, 10), Rational(4, 10), Rational(-5, 10), Rational(6, 10), 0, Rational(8, 10)]
    Tn = fk(arm, [float(x) for x in q])
    pose = dict(zip(entries, arm.forward(q).matrix[:3, :4].evalf(30), strict=True))
    reached = 0
    for b in singular:
        if {d for v in b.values for d in v.atoms(Dummy)} != {b.values[3]}:
            continue
        free = {b.values[3]: Rational(1, 3)}
        v = _evaluate(arm, b, pose, stage_order(arm), free)
        if v is not None and not any(np.isnan(v)):
            reached += reproduces(arm, v, Tn)
    assert reached  # with q4 = 1/3 chosen freely, q6 follows and the pose is reached


def test_errors_name_what_prevents_a_decomposition():
    z = [Twist.rotation([0, 0, 1], point=[i, 0, 0]) for i in range(3)]
    x = [Twist.rotation([1, 0, 0], point=[0, i, 1]) for i in range(3)]
    with pytest.raises(ValueError, match="axes 4, 5, 6 do not meet in a point"):
        decomposition(z + x)
    with pytest.raises(ValueError, match="needs six joints"):
        decomposition(z)
    helix = Twist.screw_motion([0, 0, 1], point=[0, 0, 0], pitch=1)
    with pytest.raises(ValueError, match=r"twists\[0\]: expected a revolute or prismatic"):
        decomposition([helix, *z[1:], *x])
    with pytest.raises(TypeError, match="T: expected a Transform"):
        inverse_kinematics(ur5(), "T")
    with pytest.raises(ValueError, match="free: expected joint indices"):
        inverse_kinematics(ur5(), Matrix.eye(4), free=[9])
    with pytest.raises(ValueError, match="free: the compiled solver takes free joints at the ends"):
        inverse_kinematics_function(panda(), free=(3,))
    with pytest.raises(ValueError, match=r"T: expected an array of shape \(\.\.\., 4, 4\)"):
        inverse_kinematics_function(ur5(), backend="numpy")(np.eye(3))


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore::UserWarning")
def test_the_panda_with_its_seventh_joint_a_parameter():
    # the exact closed form with q7 a symbol (free=[6]), evaluated at a pose and its q7
    arm = panda()
    entries = symbols("r11 r12 r13 px r21 r22 r23 py r31 r32 r33 pz", real=True)
    branches = inverse_kinematics(arm, Matrix(4, 4, [*entries, 0, 0, 0, 1]), free=[6])
    q7 = Symbol("q7", real=True)
    assert all(b.values[6] == q7 for b in branches)
    q = [Rational(k, 10) for k in (3, -5, 4, -20, 6, 15, 7)]
    pose = dict(zip(entries, arm.forward(q).matrix[:3, :4].evalf(30), strict=True))
    pose[q7] = q[6].evalf(30)
    generic = [b for b in branches
               if not any(v.atoms(Dummy) for v in b.values) and not b.condition.atoms(Eq)]
    Tn = fk(arm, [float(x) for x in q])
    found = []
    for b in generic:
        v = _evaluate(arm, b, pose, stage_order(arm, free=[6]), {})
        if v is not None:
            v[6] = float(q[6])
            found.append(v)
    assert found and all(reproduces(arm, v, Tn) for v in found)
    qf = np.array([float(x) for x in q])
    assert (np.abs(wrapped(np.array(found) - qf, list(range(7)))).max(axis=1) < 1e-9).any()


#: the URDF robots, read by screwsym and by pinocchio from the same files (example-robot-data,
#: tests/data/urdf): (file, base, tip, free joints)
URDF_ROBOTS = {
    "ur5": ("ur5_robot.urdf", "base_link", "tool0", ()),
    "panda": ("panda.urdf", "panda_link0", "panda_link8", (6,)),
}


def pinocchio_fk(pin, path, base: str, tip: str):
    """pinocchio's forward kinematics of the file: ``q -> T`` (tip in base), an independent FK."""
    from screwsym.motion.urdf import path_joints

    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    slots = [model.joints[model.getJointId(j)].idx_q for j in path_joints(path, base, tip)]
    frame, base_frame = model.getFrameId(tip), model.getFrameId(base)

    def fk(q) -> np.ndarray:
        x = pin.neutral(model)
        x[slots] = q
        pin.framesForwardKinematics(model, data, x)
        return data.oMf[base_frame].actInv(data.oMf[frame]).homogeneous

    return fk


@pytest.mark.filterwarnings("ignore::UserWarning")
@pytest.mark.parametrize("name", sorted(URDF_ROBOTS))
def test_every_branch_reproduces_the_pose_under_pinocchio(name):
    """The URDF robots against pinocchio (Carpentier et al. 2019), test-only: pinocchio's FK of
    random joints, screwsym's IK of that pose (the chain read from the same URDF, its rpy
    decimals of pi/2 read as pi/2), every branch back through pinocchio's FK."""
    pin = pytest.importorskip("pinocchio")
    pytest.importorskip("defusedxml")
    from _robots import DATA

    file, base, tip, free = URDF_ROBOTS[name]
    arm = panda() if name == "panda" else Chain.from_urdf(DATA / file, base, tip, angles="pi/12")
    fk_pin = pinocchio_fk(pin, DATA / file, base, tip)
    n = arm.n_joints
    f = inverse_kinematics_function(arm, free, backend="numpy")
    q = np.random.default_rng(2019).uniform(-np.pi, np.pi, (20, n))
    T = np.array([fk_pin(x) for x in q])
    branches = f(T, q[:, list(free)]) if free else f(T)
    assert branches.shape == (len(q), 8, n)
    # the file's 1.57079632679 is 5e-12 from pi/2: pinocchio and screwsym differ by that much
    close = lambda b, t: np.abs(fk_pin(b) - t).max() < 1e-9  # noqa: E731
    for k in range(len(q)):
        live = [b for b in branches[k] if not np.isnan(b).any()]
        assert live and all(close(b, T[k]) for b in live)
        assert (np.abs(wrapped(np.array(live) - q[k], list(range(n)))).max(axis=1) < 1e-8).any()
        wrong = np.array(live) + 1e-6 * (np.arange(n) == 1)  # the check rejects a wrong branch
        assert not any(close(b, T[k]) for b in wrong)
