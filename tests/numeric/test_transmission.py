"""Batched transmission indices and Jacobians (screwsym.numeric.transmission), issue 18 item 5.

The five-bar's indices are |sin| of the angles between its links (Wang, Wu & Liu 2010, Sec. 4;
Liu, Wang & Pritschow 2006); here the batched function is checked against the exact one at
points, for its input forms and its refusals.
"""

from __future__ import annotations

import numpy as np
import pytest
from sympy import Matrix, Rational, Symbol, symbols

from screwsym.numeric.transmission import jacobian_map, transmission_map
from tests._actuated import five_bar

x, y = symbols("x y", real=True)


@pytest.fixture(scope="module")
def mech():
    return five_bar((x, y))


@pytest.fixture(scope="module")
def fn(mech):
    return transmission_map(mech, [x, y])


def test_batched_indices_equal_the_exact_ones(mech, fn):
    pts = [(Rational(1, 2), 2), (2, Rational(5, 2)), (Rational(3, 2), Rational(5, 2))]
    out = fn(np.array(pts, dtype=float))
    tr = mech.transmission()
    for n, (px, py) in enumerate(pts):
        tr_n = [[float(v.xreplace({x: px, y: py})) for v in vals] for vals in tr[:2]]
        assert np.allclose(out.input[:, n], tr_n[0])
        assert np.allclose(out.output[:, n], tr_n[1])
    for n, (px, py) in enumerate(pts[:1]):  # and the mechanism built at the point itself
        tr = mech.xreplace({x: px, y: py}).transmission()
        assert np.allclose(out.input[:, n], [float(v) for v in tr.input])
        assert np.allclose(out.output[:, n], [float(v) for v in tr.output])
        assert np.isclose(out.local[n], float(tr.local))
    # at (3/2, 5/2) the distal links meet at a right angle (Wang et al.: eta = 1) and make
    # 45 degrees with the cranks (lambda = sin 45); the checker rejects lambda = 1 there
    assert np.allclose(out.output[:, 2], 1) and np.allclose(out.input[:, 2], np.sqrt(0.5))
    assert not np.allclose(out.input[:, 2], 1)


def test_columns_or_arrays_and_batch_shape(fn):
    cfg = np.array([[0.5, 2.0], [2.0, 2.5], [1.0, 3.0]])
    a, b = fn(cfg), fn(cfg[:, 0], cfg[:, 1])
    assert a.local.shape == (3,) and a.input.shape == (2, 3)
    assert np.array_equal(a.local, b.local)
    # a singular configuration (y = 1: type II) gives eta = 0, not an error
    assert fn(np.array([[1.0, 1.0]])).output[0, 0] == 0


def test_jacobian_map_matches_the_exact_jacobian(mech):
    # the mechanism built at the point has its own (primitive) scale of each actuation
    # wrench: each row of Jx and of Jq is the same multiple of the batched one, and the
    # constraint rows span the same space
    Jx, Jq = jacobian_map(mech, [x, y])(np.array([[0.5, 2.0]]))
    ex, eq = mech.xreplace({x: Rational(1, 2), y: 2}).jacobian()
    ex, eq = np.array(ex, dtype=float), np.array(eq, dtype=float)
    for i in range(2):
        k = eq[i, i] / Jq[0, i, i]
        assert np.allclose(ex[i], k * Jx[0, i]) and np.allclose(eq[i], k * Jq[0, i])
    assert np.linalg.matrix_rank(np.vstack([ex[2:], Jx[0, 2:]])) == 4
    assert not np.allclose(ex[0], Jx[0, 1])  # the checker tells the rows apart


def test_refusals(mech, fn):
    with pytest.raises(TypeError, match="symbols"):
        transmission_map(mech, ["x", "y"])
    with pytest.raises(TypeError, match="mech: expected a ParallelMechanism"):
        transmission_map("five-bar", [x, y])
    with pytest.raises(ValueError, match="symbols: the indices also depend on"):
        transmission_map(mech, [x])
    with pytest.raises(ValueError, match=r"configurations: expected an array of shape \(N, 2\)"):
        fn(np.zeros((4, 3)))
    with pytest.raises(ValueError, match="configurations: expected one"):
        fn(np.zeros(4), np.zeros(4), np.zeros(4))
    assert isinstance(Symbol("t"), Symbol)


def test_a_dask_transmission_map_runs_chunk_by_chunk_and_agrees_with_numpy(fn):
    """Issue 18 item 7: Dask arrays in, lazy Dask arrays out, equal to the NumPy map."""
    da = pytest.importorskip("dask.array")
    rng = np.random.default_rng(7)
    grid = np.column_stack([rng.uniform(0.2, 2.8, 50), rng.uniform(1.5, 3.5, 50)])
    want = fn(grid)
    for args in ((da.from_array(grid, chunks=(16, 2)),),
                 (da.from_array(grid[:, 0], chunks=16), da.from_array(grid[:, 1], chunks=16))):
        got = fn(*args)
        assert isinstance(got.local, da.Array) and got.local.numblocks == (4,)
        assert got.input.shape == want.input.shape
        np.testing.assert_array_equal(got.input.compute(), want.input)
        np.testing.assert_array_equal(got.output.compute(), want.output)
        np.testing.assert_array_equal(got.local.compute(), want.local)
    # the check sees a wrong map: another chunk's rows in the place of these
    shifted = fn(da.from_array(np.roll(grid, 1, axis=0), chunks=(16, 2)))
    assert not np.array_equal(shifted.local.compute(), want.local)


def test_three_rpr_map_is_finite_where_two_legs_are_parallel():
    # issue 32, item 4: on the line x - 3 y = 5 legs 1 and 3 of this 3-RPR are parallel (not
    # singular: the third leg is not), and with them locked the platform translates; the map
    # gave nan there (0/0 of the general formula).  Independent check: the exact indices at
    # the same rational poses, whose output twist is a translation (Twist([0, 0, 0], ...))
    from tests._actuated import RPR_BASE, RPR_PLATFORM, three_rpr

    x, y = symbols("x y", real=True)
    f = transmission_map(three_rpr(x, y, 1, 0, RPR_BASE, RPR_PLATFORM), [x, y])
    poses = [(5, 0), (8, 1), (Rational(7, 2), Rational(-1, 2))]
    out = f(np.array(poses, dtype=float))
    for n, (px, py) in enumerate(poses):
        exact = three_rpr(px, py, 1, 0, RPR_BASE, RPR_PLATFORM).transmission()
        assert exact.outputs[1].S == Matrix([0, 0, 0])  # a translation: the case in question
        want = [float(v) for v in exact.output]
        assert np.allclose(out.output[:, n], want, rtol=1e-12)
        assert 0 <= out.local[n] <= 1
    # the check rejects a wrong answer: nan (what the map gave) is not close to the exact
    assert not np.allclose(np.nan, float(exact.output[1]))


# ------------------------------------------------------------------ issue 32: maps that cannot mislead
def _five_bar_symbols(a2=None):
    syms = list(symbols("b1x b1y b2x b2y px py", real=True))
    kw = {} if a2 is None else {"a2": (a2, 0)}
    return syms, five_bar((syms[4], syms[5]), b1=syms[0:2], b2=syms[2:4], **kw)


_CFG = np.array([[np.cos(1.0), np.sin(1.0), 3 + np.cos(2.0), np.sin(2.0), 1.5, 2.2]])


def test_map_is_scale_free_where_the_geometry_scales():
    # the indices are dimensionless (Wang, Wu & Liu 2010): a five-bar whose every point is a
    # symbol (A1 at the origin, A2 = (a2, 0)) has the same indices at 1e-150, 1e150 and 1e300
    # times a configuration as at it (inside, each configuration divided by a power of two)
    a2 = Symbol("a2", real=True)
    syms, m = _five_bar_symbols(a2)
    f = transmission_map(m, [*syms, a2])
    cfg = np.append(_CFG, [[3.0]], axis=1)
    at1 = f(cfg)
    for scale in (1e-150, 1e150, 1e300):
        out = f(cfg * scale)
        assert np.allclose(out.input, at1.input, rtol=1e-12)
        assert np.allclose(out.output, at1.output, rtol=1e-12)
    # the checker rejects the float formula unscaled: it overflows there (nan)
    from screwsym.codegen import lambdify

    tr = m.transmission()
    raw = lambdify([*syms, a2], (*tr.input, *tr.output), "numpy", name="raw")
    with np.errstate(all="ignore"):
        assert np.isnan(np.asarray(raw(*(cfg[0] * 1e154)), dtype=float)).all()


def test_map_beyond_the_float_range_equals_the_exact_indices():
    # issue 32: at 1e154 times a configuration the map gave nan (overflow) or 0, the value
    # that marks a singularity; the five-bar of the benchmark (A2 a constant: not rescaled)
    # is evaluated there in mpmath, and agrees with the exact indices at the exact point
    syms, m = _five_bar_symbols()
    f = transmission_map(m, syms)
    tr = m.transmission()
    for scale in (10**154, 10**200):
        out = f(_CFG * float(scale))
        at = {s: Rational(float(v)) * scale for s, v in zip(syms, _CFG[0], strict=True)}
        assert np.allclose(out.input[:, 0], [float(e.xreplace(at)) for e in tr.input])
        assert np.allclose(out.output[:, 0], [float(e.xreplace(at)) for e in tr.output])
        assert 0 < out.local[0] <= 1
    # and the checker rejects a wrong value: the indices at scale 1 differ from these
    assert not np.allclose(f(_CFG).input, f(_CFG * 1e154).input)


def test_indices_lie_in_zero_one_and_nan_only_at_singular_poses(fn):
    # random configurations (some near the singular lines): each index in [0, 1] or nan,
    # and nan only where Jx is singular (the distal links on one line, y = 1) here exactly
    rng = np.random.default_rng(32)
    cfg = np.concatenate([rng.uniform(-5, 5, (200, 2)), [[1.0, 1.0], [2.0, 1.0]]])
    out = fn(cfg)
    for a in (out.input, out.output, out.local[None, :]):
        finite = a[np.isfinite(a)]
        assert ((finite >= 0) & (finite <= 1)).all()
    bad = ~np.isfinite(out.output).all(axis=0)
    assert set(np.nonzero(bad)[0]) <= {200, 201} or all(abs(cfg[i, 1] - 1) < 1e-12 or
                                                       abs(cfg[i, 0]) < 1e-12 or
                                                       abs(cfg[i, 0] - 3) < 1e-12
                                                       for i in np.nonzero(bad)[0])
