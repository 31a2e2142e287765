"""Tests for screwsym.numeric.mobility: the mobility at many configurations agrees with the exact analysis."""

from __future__ import annotations

import numpy as np
import pytest
from _mechanisms import four_bar, three_rps
from sympy import Rational, symbols

from screwsym.numeric.mobility import mobility_map


def test_mobility_map_agrees_with_the_exact_analysis():
    # 3-RPS at random heights (generic: 3) and at the concurrent configuration (4)
    rho = symbols("rho1:4", real=True)
    h = symbols("h1:4", positive=True)
    mech = three_rps(rho, h)
    f = mobility_map(mech, [*rho, *h])
    rng = np.random.default_rng(0)
    vals = [rng.uniform(-1, 1, 50) for _ in range(3)] + [rng.uniform(1, 2, 50) for _ in range(3)]
    vals[4][:5] = vals[3][:5]
    vals[5][:5] = vals[3][:5]
    vals[2][:5] = -6 - vals[0][:5] - vals[1][:5]
    out = f(*vals)
    assert out.mobility.shape == (50,) and out.limb_constraints.shape == (50, 3)
    assert list(out.mobility[:5]) == [4] * 5 and (out.mobility[5:] == 3).all()
    assert (out.limb_constraints == 1).all()
    for j in (0, 7):  # exact check of two configurations
        at = {s: Rational(float(v[j])) for s, v in zip((*rho, *h), vals, strict=True)}
        if j == 0:  # on the singular set exactly, not only to rounding
            at[rho[2]] = -6 - at[rho[0]] - at[rho[1]]
        exact = mech.xreplace(at).mobility().mobility
        assert exact == out.mobility[j]
    # sigma: the third |R_jj| of the union vanishes only at the singular configurations
    assert (out.sigma[:5, 2] < 1e-12).all() and (out.sigma[5:, 2] > 1e-6).all()


def test_mobility_map_backends_agree():
    pytest.importorskip("numba")
    bx, by = symbols("b_x b_y", real=True)
    mech = four_bar(B=(bx, by, 0), Cp=(3, 0, 0))
    grid = np.meshgrid(np.linspace(-2, 2, 9), np.linspace(-1, 1, 5))
    a = mobility_map(mech, [bx, by])(*grid)
    b = mobility_map(mech, [bx, by], backend="numba")(*grid)
    assert a.mobility.shape == (5, 9)
    assert (a.mobility == b.mobility).all() and np.allclose(a.sigma, b.sigma)
    # b_y = 0: collinear, 2 DOF, except b = (0, 0) where B sits on A (exact analysis: 1 DOF)
    assert a.mobility[2].tolist() == [2, 2, 2, 2, 1, 2, 2, 2, 2]
    assert (a.mobility[[0, 1, 3, 4]] == 1).all()
    assert mech.xreplace({bx: 0, by: 0}).mobility().mobility == 1


def test_mobility_map_bad_input():
    bx = symbols("b_x", real=True)
    mech = four_bar(B=(bx, 1, 0))
    with pytest.raises(TypeError, match="mechanism: expected a ParallelMechanism, got Limb"):
        mobility_map(mech.limbs[0], [bx])
    message = "args: expected every symbol of the mechanism, missing b_x"
    with pytest.raises(ValueError, match=message):
        mobility_map(mech, [])
    with pytest.raises(ValueError, match="rtol: expected a positive finite number, got 0"):
        mobility_map(mech, [bx], rtol=0)


@pytest.mark.parametrize("backend", ["numpy", "numba"])
def test_an_undefined_configuration_is_marked_the_same_on_every_backend(backend):
    # issue 20: at a NaN/inf configuration the map returned an integer (6 on NumPy, 1 on numba)
    if backend == "numba":
        pytest.importorskip("numba")
    from screwsym.numeric.mobility import UNDEFINED

    bx, by = symbols("b_x b_y", real=True)
    mech = four_bar(B=(bx, by, 0), Cp=(3, 0, 0))
    out = mobility_map(mech, [bx, by], backend=backend)(
        np.array([1.0, np.nan, np.inf, 1.0, -np.inf]), np.array([1.0, 1.0, 1.0, np.nan, 0.0]))
    assert UNDEFINED == -1
    assert out.mobility.tolist() == [1, -1, -1, -1, -1]
    assert out.constraint_rank.tolist() == [5, -1, -1, -1, -1]
    assert (out.limb_constraints[1:] == -1).all() and (out.limb_constraints[0] >= 0).all()
    assert np.isnan(out.sigma[1:]).all() and np.isfinite(out.sigma[0]).all()


def test_stretched_leg_internal_motion_in_a_field_of_its_own():
    # issue 32: Bonev, Zlatanov & Gosselin (2003), a planar 3-RRR with leg 0 stretched
    # (crank pivot, elbow and platform pivot on one line) at t = 0: the leg has a momentary
    # idle motion, which mobility() counts (3) and the map reports as `internal` beside its
    # mobility (6 - rank of the constraints, 2): mobility + internal == mobility() everywhere
    from sympy import Symbol

    from screwsym.numeric.mobility import mobility_map
    from screwsym.systems.joints import R
    from screwsym.systems.parallel import Limb, ParallelMechanism

    t = Symbol("t", real=True)
    z = [0, 0, 1]
    mech = ParallelMechanism(
        Limb(R([0, 0, 0], z), R([1, t, 0], z), R([2, 0, 0], z)),
        Limb(R([4, 0, 0], z), R([4, 1, 0], z), R([3, 1, 0], z)),
        Limb(R([0, 3, 0], z), R([1, 3, 0], z), R([2, 1, 0], z)))
    values = [0, 0.5, -1.0]
    out = mobility_map(mech, [t])(np.array(values, dtype=float))
    for n, v in enumerate(values):
        exact = mech.xreplace({t: Rational(v)}).mobility()
        assert out.mobility[n] + out.internal[n] == exact.mobility
        assert out.internal[n] == exact.internal
    assert list(out.internal) == [1, 0, 0] and out.mobility[0] == 2
    # the checker rejects the map's mobility alone at the stretched leg: it misses the idle
    # motion that mobility() counts
    assert out.mobility[0] != mech.xreplace({t: 0}).mobility().mobility
    undefined = mobility_map(mech, [t])(np.array([np.nan]))
    assert undefined.internal[0] == -1
