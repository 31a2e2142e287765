"""The fused numeric inverse kinematics (issue 36, item 2): every branch one generated program.

``screwsym.numeric.inverse_kinematics_function`` compiles all the closed-form branches of
``screwsym.motion.inverse_kinematics`` into one straight-line program over the poses.  Checked
here in every back end: each branch reproduces the pose under an independent forward kinematics
(modern_robotics' ``FKinSpace``, test-only) and the joints that made it are among the branches;
a branch that does not exist is NaN in every joint; the back ends agree with each other and
with the solver the program replaced (each stage compiled on its own, ``_staged``).  The UR5 of
Lynch & Park, *Modern Robotics*, Example 4.5, and Corke's PUMA 560 have eight branches at a
generic pose (Murray, Li & Sastry 1994, Section 3.3).
"""

from __future__ import annotations

import numpy as np
import pytest
from _backends import HAS_CC, HAS_NUMBA
from _robots import panda, puma560

from screwsym.codegen import c_source, default_backend
from screwsym.motion.chain import ur5
from screwsym.numeric import inverse_kinematics_function
from screwsym.numeric.ik import _Program, _staged, fastest_backend

mr = pytest.importorskip("modern_robotics")

ARMS = {"ur5": ur5, "puma560": puma560}
#: numba compiles the UR5's program in about 10 s (cold cache): slow
SOLVERS = [
    "numpy",
    pytest.param("numba", marks=[pytest.mark.slow, pytest.mark.skipif(not HAS_NUMBA, reason="no numba")]),
    pytest.param("c", marks=pytest.mark.skipif(not HAS_CC, reason="no C compiler")),
]


def fk(chain, q) -> np.ndarray:
    """The independent forward kinematics: modern_robotics' product of exponentials."""
    S = np.array([[float(x) for x in t.matrix] for t in chain.twists]).T
    return mr.FKinSpace(np.array(chain.home.matrix, dtype=float), S, np.asarray(q, dtype=float))


def poses(chain, count: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    q = np.random.default_rng(seed).uniform(-np.pi, np.pi, (count, chain.n_joints))
    return q, np.array([fk(chain, x) for x in q])


def wrapped(d: np.ndarray) -> np.ndarray:
    return np.mod(d + np.pi, 2 * np.pi) - np.pi


@pytest.mark.parametrize("backend", SOLVERS)
@pytest.mark.parametrize("name", sorted(ARMS))
def test_every_branch_reproduces_the_pose(name, backend):
    arm = ARMS[name]()
    q, T = poses(arm, 40, seed={"ur5": 1, "puma560": 2}[name])
    branches = inverse_kinematics_function(arm, backend=backend)(T)
    assert branches.shape == (40, 8, 6)
    live = ~np.isnan(branches).any(axis=2)
    assert live.sum(axis=1).max() == 8  # eight branches at a generic pose
    for k in range(len(q)):
        assert live[k].any()
        for b in branches[k][live[k]]:
            assert np.abs(fk(arm, b) - T[k]).max() < 1e-9
            assert (-np.pi <= b).all() and (b < np.pi).all()
        assert (np.abs(wrapped(branches[k][live[k]] - q[k])).max(axis=1) < 1e-8).any()


def test_the_round_trip_check_rejects_a_wrong_branch():
    arm = ur5()
    q, T = poses(arm, 1, seed=7)
    wrong = inverse_kinematics_function(arm)(T[0]).copy()
    wrong[:, 2] += 1e-4
    assert not any(np.abs(fk(arm, b) - T[0]).max() < 1e-9 for b in wrong if not np.isnan(b).any())


@pytest.mark.parametrize("backend", SOLVERS)
def test_a_branch_that_does_not_exist_is_nan_in_every_joint(backend):
    arm = ur5()
    f = inverse_kinematics_function(arm, backend=backend)
    q, T = poses(arm, 300, seed=3)
    branches = f(T)
    nan = np.isnan(branches)
    assert (nan.all(axis=2) | ~nan.any(axis=2)).all()  # never a branch with some joints only
    assert nan.any()  # some poses lose branches (a negative discriminant of Subproblem 3)
    # the same branches as the per-stage solver (its NaN tracked stage by stage)
    assert (nan == np.isnan(_staged(arm, (), "numpy")(T))).all()
    far = T[0].copy()
    far[:3, 3] = [5, 0, 0]  # out of reach
    assert np.isnan(f(far)).all()
    # a NaN or infinite pose gives no branch, never a number
    assert np.isnan(f(np.full((4, 4), np.nan))).all()


@pytest.mark.parametrize("backend", SOLVERS)
@pytest.mark.parametrize("name", sorted(ARMS))
def test_the_back_ends_agree_with_numpy_and_with_the_staged_solver(name, backend):
    arm = ARMS[name]()
    q, T = poses(arm, 200, seed=11)
    reference = _staged(arm, (), "numpy")(T)
    got = inverse_kinematics_function(arm, backend=backend)(T)
    for other in (reference, inverse_kinematics_function(arm, backend="numpy")(T)):
        assert (np.isnan(got) == np.isnan(other)).all()
        assert np.nanmax(np.abs(wrapped(got - other))) < 1e-10
    # one pose a call (the back end's one-point path: NumPy's on Python floats) gives the
    # rows of the batch, to rounding
    one = np.array([inverse_kinematics_function(arm, backend=backend)(x) for x in T[:20]])
    assert (np.isnan(one) == np.isnan(got[:20])).all()
    assert np.nanmax(np.abs(wrapped(one - got[:20]))) < 1e-10


@pytest.mark.filterwarnings("ignore::UserWarning")
@pytest.mark.parametrize("backend", ["numpy", pytest.param("c", marks=pytest.mark.skipif(
    not HAS_CC, reason="no C compiler"))])
def test_the_panda_with_its_seventh_joint_given(backend):
    arm = panda()
    f = inverse_kinematics_function(arm, free=(6,), backend=backend)
    q, T = poses(arm, 20, seed=5)
    branches = f(T, q[:, 6:])
    assert branches.shape == (20, 8, 7)
    assert np.allclose(branches[..., 6][~np.isnan(branches[..., 6])],
                       np.repeat(wrapped(q[:, 6:]), 8, axis=1)[~np.isnan(branches[..., 6])])
    for k in range(len(q)):
        live = [b for b in branches[k] if not np.isnan(b).any()]
        assert live and all(np.abs(fk(arm, b) - T[k]).max() < 1e-9 for b in live)
        assert (np.abs(wrapped(np.array(live) - q[k])).max(axis=1) < 1e-8).any()
    staged = _staged(arm, (6,), "numpy")(T, q[:, 6:])
    assert np.nanmax(np.abs(wrapped(branches - staged))) < 1e-10
    with pytest.raises(TypeError, match="free_values: expected the values of the 1 free joints"):
        f(T)
    with pytest.raises(ValueError, match="free_values: expected an array of shape"):
        f(T, np.zeros(2))
    for one in (f(T[0], q[0, 6]), f(T[0], q[0, 6:])):  # one joint: a scalar or (1,)
        assert (np.isnan(one) == np.isnan(branches[0])).all()
        assert np.nanmax(np.abs(wrapped(one - branches[0]))) < 1e-10


def test_one_pose_on_python_floats_has_the_same_missing_branches():
    """NumPy's one-pose path (the program on Python floats, screwsym.codegen's single-point
    path): a branch that does not exist (the square root of a negative number) is NaN there
    too, the others as in the batch."""
    arm = ur5()
    f = inverse_kinematics_function(arm, backend="numpy")
    q, T = poses(arm, 60, seed=3)
    batch = f(T)
    assert np.isnan(batch).any()  # some poses lose branches
    one = np.array([f(x) for x in T])
    assert (np.isnan(one) == np.isnan(batch)).all()
    assert np.nanmax(np.abs(wrapped(one - batch))) < 1e-10
    far = T[0].copy()
    far[:3, 3] = [5, 0, 0]
    assert np.isnan(f(far)).all()


def test_the_program_holds_only_its_own_symbols_and_the_default_is_the_fastest():
    program = _Program(ur5(), ())
    known = set(program.T)
    for t, e in program.assignments:  # a straight line: each right-hand side uses what came before
        assert e.free_symbols <= known and t not in known
        known.add(t)
    assert program.outputs.free_symbols <= known
    assert program.outputs.shape == (8, 6)
    # generated source names only screwsym's own locals (_x, _c, _t ...), never the program's
    # (each named _ik_...)
    source = c_source(program.arguments, program)
    names = {str(t) for t, _ in program.assignments} | {str(x) for x in program.T}
    assert all(n.startswith("_ik_") for n in names)
    assert "_ik_" not in source and "_ik_" in str(program.assignments)
    assert fastest_backend() == ("c" if HAS_CC else default_backend())


def test_bad_input_names_the_argument():
    with pytest.raises(TypeError, match="chain: expected a Chain"):
        inverse_kinematics_function("ur5")
    with pytest.raises(ValueError, match="T: expected an array of shape"):
        inverse_kinematics_function(ur5(), backend="numpy")(np.eye(3))
