"""Closed-loop dynamics as straight-line programs (issue 35, item 3): ``numeric.loop_program``.

The ground truth is the exact ``Mechanism.mass_matrix`` and ``Mechanism.inverse_dynamics``
(tests/systems/test_loop_dynamics.py checks those against the four-bar's Lagrangian,
Uicker, Pennock & Shigley's pin forces, Tsai's virtual work and pinocchio 3): the program,
written once at a symbolic configuration and evaluated at random exact values, must equal
them exactly, on the four-bar with a symbolic coupler-rocker joint and on Clavel's Delta,
link by link (Clavel 1988), with its platform at a symbolic pose ``(x, y, z)``.
"""

from __future__ import annotations

import random
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from sympy import Mul, Rational, cancel, diag, nan, symbols

from screwsym.codegen import lambdify
from screwsym.core.inertia import SpatialInertia
from screwsym.numeric import LoopProgram, loop_dynamics_program
from screwsym.systems.joints import R, Spherical, Universal
from screwsym.systems.linkage import Mechanism

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "systems"))
from _linkages import DELTA_RADIAL  # noqa: E402
from test_loop_dynamics import delta_at  # noqa: E402

x, y, z = symbols("x y z", real=True)
Z = [0, 0, 1]
GRAVITY = [0, Rational(-981, 100), Rational(1, 3)]  # not along an axis: every weight term counts


def fourbar(px, py):
    """The four-bar of Mechanism.mass_matrix's docstring, its coupler-rocker joint at (px, py)."""
    return Mechanism([("ground", "crank", R([0, 0, 0], Z)), ("crank", "coupler", R([1, 2, 0], Z)),
                      ("coupler", "rocker", R([px, py, 0], Z)),
                      ("rocker", "ground", R([4, 0, 0], Z))], base="ground",
                     inertias={"crank": SpatialInertia(1, [Rational(1, 2), 1, 0], diag(1, 1, 2)),
                               "coupler": SpatialInertia(3, [(px + 1) / 2, (py + 2) / 2, 0],
                                                         diag(1, 2, Rational(5, 2))),
                               "rocker": SpatialInertia.point_mass(2, [px, py, 0])})


def delta(top):
    inertias = {f"arm{i + 1}": SpatialInertia(2, [Rational(5, 2) * e[0], Rational(5, 2) * e[1],
                                                  Rational(-1, 2)], diag(1, 1, 1))
                for i, e in enumerate(DELTA_RADIAL)}
    inertias["upper1"] = SpatialInertia(Rational(1, 2), [3, 0, -1], diag(1, 1, 1))
    inertias["platform"] = SpatialInertia(3, top, diag(1, 1, 2))
    return Mechanism(delta_at(top), base="base", inertias=inertias)


def rational(rng, lo, hi):
    return Rational(rng.randint(lo * 97, hi * 97), 97)


def agrees(tau, H, make, point, act, rng):
    """The programs at the exact ``point`` and random exact rates equal the mechanism's own."""
    mech = make(point)
    k = len(act)
    qd = [rational(rng, -3, 3) for _ in range(k)]
    qdd = [rational(rng, -3, 3) for _ in range(k)]
    want_tau = mech.inverse_dynamics(act, qd, qdd, GRAVITY)
    want_H = mech.mass_matrix(act)
    got_tau, got_H = tau.evaluate(point, qd, qdd), H.evaluate(point)
    return (got_tau - want_tau).expand().is_zero_matrix and (got_H - want_H).expand().is_zero_matrix


def test_fourbar_programs_equal_the_exact_dynamics_and_give_nan_at_the_singularity():
    mech = fourbar(x, y)
    tau = loop_dynamics_program(mech, [0], [x, y], gravity=GRAVITY)
    H = loop_dynamics_program(mech, [0], [x, y], "mass_matrix")
    assert isinstance(tau, LoopProgram) and tau.arguments[0].T.tolist() == [[x, y]]
    rng = random.Random(35)
    for _ in range(3):
        point = [rational(rng, 2, 5), rational(rng, 2, 5)]
        assert agrees(tau, H, lambda p: fourbar(*p), point, [0], rng)
    # the pivots' product is det(A_p^T A_p): for a planar four-bar the square of its one
    # minor, the actuation condition 2x + 3y - 8 (Gosselin & Angeles' second kind)
    assert mech.actuation_condition([0]).lhs in (2 * x + 3 * y - 8, -2 * x - 3 * y + 8)
    ratio = cancel(Mul(*tau.condition_values([x, y], [1], [1])) / (2 * x + 3 * y - 8) ** 2)
    assert ratio != 0 and not ratio.free_symbols
    # on it (coupler and rocker in line at (5/2, 1)): nan, exactly and in floats
    assert tau.evaluate([Rational(5, 2), 1], [1], [1])[0] is nan
    # in floats the pivot there is a rounding error: the float policy's guard makes it nan
    f = lambdify(list(H.arguments), H.float_guarded(), "numpy")
    assert np.isnan(f(np.array([2.5, 1.0]))).all() and np.isfinite(f(np.array([3.0, 3.0]))).all()
    assert np.isfinite(f(np.array([2.5, 1.0 + 1e-5]))).all()  # near it, a number


def test_the_check_rejects_a_wrong_program():
    mech = fourbar(x, y)
    tau = loop_dynamics_program(mech, [0], [x, y], gravity=GRAVITY)
    H = loop_dynamics_program(mech, [0], [x, y], "mass_matrix")
    point = [Rational(3), Rational(3)]
    assert agrees(tau, H, lambda p: fourbar(*p), point, [0], random.Random(1))
    # one assignment of the torque program altered: the closing joint's bracket, sign flipped
    i = next(i for i, (t, _) in enumerate(tau.assignments) if t.name.startswith("C1B"))
    t, e = tau.assignments[i]
    wrong = replace(tau, assignments=tau.assignments[:i] + ((t, -e),) + tau.assignments[i + 1:])
    assert not agrees(wrong, H, lambda p: fourbar(*p), point, [0], random.Random(1))


def test_delta_at_a_symbolic_pose_equals_the_exact_dynamics_at_numeric_poses():
    """Clavel's Delta link by link, its platform at (x, y, z): 21 revolutes, 18 passive, five
    loops; arms, one parallelogram's upper bar and the platform with inertia."""
    top = [x, y, z]
    mech = delta(top)
    tau = loop_dynamics_program(mech, [0, 7, 14], [x, y, z], gravity=GRAVITY)
    H = loop_dynamics_program(mech, [0, 7, 14], [x, y, z], "mass_matrix")
    assert tau.conditions and len(tau.conditions) <= 18
    rng = random.Random(36)
    point = [rational(rng, -1, 1) / 3, rational(rng, -1, 1) / 3, rational(rng, -4, -2)]
    assert agrees(tau, H, delta, point, [0, 7, 14], rng)
    # and at the home pose, on the plane y = 0 where a statically pivoted LU of the network
    # matrix divided by zero: the normal equations' pivots stay positive
    home = [0, 0, -3]
    assert all(v > 0 for v in tau.condition_values(home, [1, 1, 1], [1, 1, 1]))
    assert agrees(tau, H, delta, home, [0, 7, 14], rng)
    # the mass matrix is symmetric positive definite there
    Hp = H.evaluate(point)
    assert Hp == Hp.T and all(Hp[:i, :i].det() > 0 for i in (1, 2, 3))


def rsur(h):
    """A spatial RSUR four-bar (crank about z, rocker about x), the universal joint at height
    ``h``; the spanning tree closes the loop at the universal joint (two freedoms), so the
    program sums the loop's brackets in loop order there."""
    return Mechanism([("ground", "crank", R([0, 0, 0], Z)), ("crank", "rod", Spherical([1, 0, 0])),
                      ("rocker", "rod", Universal([2, 1, h], [1, 0, 0], [0, 1, 0])),
                      ("rocker", "ground", R([3, 1, 0], [1, 0, 0]))], base="ground",
                     inertias={"crank": SpatialInertia(1, [Rational(1, 2), 0, 0], diag(1, 1, 1)),
                               "rod": SpatialInertia(2, [Rational(3, 2), Rational(1, 2), h / 2],
                                                     diag(1, 2, 2)),
                               "rocker": SpatialInertia(1, [Rational(5, 2), 1, h / 2],
                                                        diag(2, 1, 2))})


def test_a_loop_closed_by_a_joint_of_several_freedoms():
    mech = rsur(z)
    tau = loop_dynamics_program(mech, [0], [z], gravity=GRAVITY)
    H = loop_dynamics_program(mech, [0], [z], "mass_matrix")
    assert any(t.name.startswith("L1_") for t, _ in tau.assignments)  # the loop-order sum
    assert agrees(tau, H, lambda p: rsur(p[0]), [Rational(3, 2)], [0], random.Random(37))


def test_bad_input_is_refused_clearly():
    mech = fourbar(x, y)
    with pytest.raises(TypeError, match="mech"):
        loop_dynamics_program("four-bar", [0], [x, y])
    with pytest.raises(ValueError, match="what"):
        loop_dynamics_program(mech, [0], [x, y], "forward_dynamics")
    with pytest.raises(ValueError, match=r"symbols: .*\['y'\]"):
        loop_dynamics_program(mech, [0], [x])
    with pytest.raises(TypeError, match=r"actuated\[0\]"):
        loop_dynamics_program(mech, ["crank"], [x, y])
    with pytest.raises(TypeError, match="at"):
        loop_dynamics_program(mech, [0], [x, y], at=[1, 2])
    with pytest.raises(ValueError, match="actuation singularity at the sample point"):
        loop_dynamics_program(mech, [0], [x, y], at={x: Rational(5, 2), y: 1})
    with pytest.raises(ValueError, match="loop_dynamics_program: .*budget=10 units"):
        loop_dynamics_program(mech, [0], [x, y], budget=10)
    with pytest.raises(ValueError, match="no inertias"):
        loop_dynamics_program(Mechanism(list(mech.joints), base="ground"), [0], [x, y])
