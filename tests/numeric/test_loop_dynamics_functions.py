"""Generated closed-loop dynamics (issue 35, item 3): ``numeric.loop_dynamics_functions``.

A parallelogram four-bar at crank angle ``t`` (crank and rocker of length 1, coupler and
ground of length 2): the coupler translates on the crank pin's circle, so its Lagrangian is
written by hand here (Tsai, *Robot Analysis*, 1999, §9.4's form): the kinetic energy
``1/2 H qd^2`` with ``H = Izz_1 + m_1/4 + Izz_3 + m_3/4 + m_2`` constant, the potential
``g sin(t) (m_1/2 + m_2 + m_3/2)``, so ``tau = H qdd + g cos(t) (m_1/2 + m_2 + m_3/2)``.
The generated functions on every back end agree with it and with the exact closed form at
seeded random states; a wrong mass is rejected.
"""

from __future__ import annotations

import shutil

import numpy as np
import pytest
from sympy import Float, Rational, cos, diag, sin, symbols

from screwsym.core.inertia import SpatialInertia
from screwsym.numeric import loop_dynamics_functions
from screwsym.systems.joints import R
from screwsym.systems.linkage import Mechanism

t = symbols("t", real=True)
Z = [0, 0, 1]
MASSES = (Rational(3, 2), 2, Rational(5, 4))
IZZ = (Rational(1, 5), Rational(1, 3), Rational(1, 7))


def parallelogram(masses=MASSES):
    A = [cos(t), sin(t), 0]
    B = [cos(t) + 2, sin(t), 0]
    m1, m2, m3 = masses
    inertias = {
        "crank": SpatialInertia(m1, [cos(t) / 2, sin(t) / 2, 0], diag(1, 1, IZZ[0])),
        "coupler": SpatialInertia(m2, [cos(t) + 1, sin(t), 0], diag(1, 1, IZZ[1])),
        "rocker": SpatialInertia(m3, [cos(t) / 2 + 2, sin(t) / 2, 0], diag(1, 1, IZZ[2])),
    }
    return Mechanism([("ground", "crank", R([0, 0, 0], Z)), ("crank", "coupler", R(A, Z)),
                      ("coupler", "rocker", R(B, Z)), ("rocker", "ground", R([2, 0, 0], Z))],
                     base="ground", inertias=inertias)


def lagrangian(q, qd, qdd, g=9.81):
    m1, m2, m3 = (float(m) for m in MASSES)
    H = float(IZZ[0]) + m1 / 4 + float(IZZ[2]) + m3 / 4 + m2
    return H * qdd + g * np.cos(q) * (m1 / 2 + m2 + m3 / 2), H


@pytest.mark.parametrize("backend", ["numpy", "numba", "c"])
def test_generated_loop_dynamics_agree_with_the_lagrangian_and_the_closed_form(backend):
    if backend == "numba":
        pytest.importorskip("numba")
    if backend == "c" and shutil.which("cc") is None:
        pytest.skip("no C compiler")
    mech = parallelogram()
    f = loop_dynamics_functions(mech, [0], [t], gravity=(0, -9.81, 0),
                                backend=backend)  # the straight-line programs (the default)
    rng = np.random.default_rng(35)
    q = rng.uniform(0.2, 2.9, (50, 1))  # off sin(t) = 0, where the parallelogram folds
    qd, qdd = rng.normal(size=(50, 1)), rng.normal(size=(50, 1))
    truth, H = lagrangian(q, qd, qdd)
    np.testing.assert_allclose(f.inverse_dynamics(q, qd, qdd), truth, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(f.mass_matrix(q), np.full((50, 1, 1), H), rtol=1e-12)
    # the program evaluated by SymPy at a few of the states agrees with the compiled one
    for i in range(3):
        value = f.tau.evaluate([Float(q[i, 0], 30)], [qd[i, 0]], [qdd[i, 0]])[0]
        assert abs(float(value) - f.inverse_dynamics(q[i], qd[i], qdd[i])[0]) < 1e-12
    # folded flat (t = 0, an actuation singularity): nan, not a number
    assert np.isnan(f.inverse_dynamics(np.zeros(1), np.ones(1), np.ones(1))).all()
    assert np.isnan(f.mass_matrix(np.zeros(1))).all()
    # the checker rejects a heavier coupler
    heavier = loop_dynamics_functions(parallelogram((MASSES[0], 2.001, MASSES[2])), [0], [t],
                                      gravity=(0, -9.81, 0), backend=backend)
    assert np.abs(heavier.inverse_dynamics(q, qd, qdd) - truth).max() > 1e-4


def test_the_closed_forms_agree_with_the_lagrangian():
    f = loop_dynamics_functions(parallelogram(), [0], [t], gravity=(0, -9.81, 0),
                                backend="numpy", form="closed")
    rng = np.random.default_rng(36)
    q = rng.uniform(0.2, 2.9, (20, 1))
    qd, qdd = rng.normal(size=(20, 1)), rng.normal(size=(20, 1))
    truth, H = lagrangian(q, qd, qdd)
    np.testing.assert_allclose(f.inverse_dynamics(q, qd, qdd), truth, rtol=1e-12, atol=1e-12)
    for i in range(3):  # the exact closed form at 30 digits
        subs = {t: q[i, 0], f.rates[0]: qd[i, 0], f.accelerations[0]: qdd[i, 0]}
        assert abs(float(f.tau[0].evalf(30, subs=subs)) - truth[i, 0]) < 1e-12


def test_bad_input_is_refused_clearly():
    mech = parallelogram()
    with pytest.raises(TypeError, match="mech"):
        loop_dynamics_functions("four-bar", [0], [t])
    with pytest.raises(ValueError, match=r"symbols: .*\['t'\]"):
        loop_dynamics_functions(mech, [0], [])
    with pytest.raises(TypeError, match=r"symbols\[0\]"):
        loop_dynamics_functions(mech, [0], ["t"])
    with pytest.raises(ValueError, match="gravity"):
        loop_dynamics_functions(mech, [0], [t], gravity=(0, 0, -t))
    with pytest.raises(ValueError, match="form"):
        loop_dynamics_functions(mech, [0], [t], form="closed-form")
    bare = Mechanism(list(mech.joints), base="ground")
    with pytest.raises(ValueError, match="no inertias"):
        loop_dynamics_functions(bare, [0], [t])
