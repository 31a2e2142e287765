"""Numeric maps: unit-free ranks and maps larger than memory (issue 18 items 6 and 7).

The 4-RUU is a Schoenflies (3T1R) platform (Kong & Gosselin 2007, *Type Synthesis of
Parallel Mechanisms*, §7: each R-U-U leg with its R and the adjacent U axis parallel
and the two inner U axes parallel exerts one constraint couple); scaled by 1e8 its map
gave 1 freedom instead of 4 with the default tolerance.
"""

from __future__ import annotations

import numpy as np
import pytest
from sympy import Rational, symbols

from screwsym.numeric.mobility import mobility_map
from screwsym.systems.joints import R, U
from screwsym.systems.parallel import Limb, ParallelMechanism

x, y, h = symbols("x y h", real=True)
K = symbols("k", positive=True)
Z = [0, 0, 1]
#: (base point, horizontal direction of the two inner U axes, platform attachment)
LEGS = [((2, 0), (1, 1), (1, 0)), ((0, 2), (-1, 2), (0, 1)),
        ((-2, 0), (2, -1), (-1, 0)), ((0, -2), (1, 3), (0, -1))]


def four_ruu(k):
    """The 4-RUU with every length times ``k``; the platform centre at (x, y, h)."""
    legs = []
    for (bx, by), (wx, wy), (cx, cy) in LEGS:
        w = [wx, wy, 0]
        base = [k * bx, k * by, 0]
        elbow = [k * (bx + wy), k * (by - wx), k]  # off the base, up by one unit
        top = [x + k * cx, y + k * cy, h]
        legs.append(Limb(R(base, Z), U(elbow, Z, w), U(top, w, Z)))
    return ParallelMechanism(*legs)


CONFIGS = (np.array([0.1, -0.3, 0.7, 0.0]), np.array([0.2, 0.5, -0.4, 0.0]),
           np.array([2.0, 2.5, 3.0, 1.0]))


def test_the_4ruu_is_3t1r_exactly():
    m = four_ruu(1).xreplace({x: Rational(1, 10), y: Rational(1, 5), h: 2}).mobility()
    assert (m.mobility, m.motion) == (4, "3T1R")


@pytest.mark.parametrize("backend", ["numpy", pytest.param("numba", marks=pytest.mark.slow)])
def test_the_map_does_not_change_with_the_length_unit(backend):
    if backend == "numba":
        pytest.importorskip("numba")
    # the unit as an argument k: one generated function (one numba compilation) for all three
    f = mobility_map(four_ruu(K), [x, y, h, K], backend=backend)
    maps = [f(*(k * c for c in CONFIGS), k) for k in (1e-8, 1.0, 1e8)]
    # the three units agree, and on a clear gap in sigma (its entries past the first are
    # not unique: pivoting breaks ties between unit null vectors by rounding)
    for m in maps:
        assert np.array_equal(m.mobility, maps[1].mobility)
        assert np.array_equal(m.constraint_rank, maps[1].constraint_rank)
        assert np.array_equal(m.limb_constraints, maps[1].limb_constraints)
        r = m.constraint_rank
        assert (np.take_along_axis(m.sigma, r[:, None] - 1, 1) > 0.1).all()
        assert (np.take_along_axis(m.sigma, r[:, None], 1) < 1e-12).all()
    assert list(maps[1].mobility) == [4, 4, 4, 4]


def test_without_the_unit_free_rank_the_scaled_map_was_wrong():
    # the checker rejects the old answer: the same analysis without the unit-free step
    from screwsym.numeric import mobility as mod

    f = mobility_map(four_ruu(K), [x, y, h, K])
    good = f(*(1e8 * c for c in CONFIGS), 1e8).mobility
    saved = mod._unit_free
    try:
        mod._unit_free = lambda T: T
        bad = f(*(1e8 * c for c in CONFIGS), 1e8).mobility
    finally:
        mod._unit_free = saved
    assert list(good[:3]) == [4, 4, 4] and not np.array_equal(bad, good)


def test_a_dask_map_runs_chunk_by_chunk_and_agrees_with_numpy():
    da = pytest.importorskip("dask.array")
    f = mobility_map(four_ruu(1), [x, y, h])
    rng = np.random.default_rng(7)
    X, Y, H = rng.uniform(-0.5, 0.5, (3, 50))
    H = H + 1.5
    X[10], H[20] = np.nan, 1.0  # one undefined configuration; one at the elbows' height
    expected = f(X, Y, H)
    calls = []
    lazy = f(da.from_array(X, chunks=16), da.from_array(Y, chunks=16), H)  # mixed inputs
    for field, want in zip(lazy, expected, strict=True):
        assert isinstance(field, da.Array) and field.numblocks[0] == 4
        got = field.compute(scheduler="threads")
        assert got.dtype == want.dtype and got.shape == want.shape
        assert np.array_equal(got, want, equal_nan=True)
    assert expected.mobility[10] == -1
    # lazy until computed: a chunk function that records its calls is not called before
    from screwsym.numeric._chunks import batched

    def record(a):
        calls.append(a.shape)
        return (a.sum(axis=-1),)

    out = batched(record, [da.ones((10, 3), chunks=(3, 3))], [(3,)], [((), float)])[0]
    assert calls == []
    assert out.compute().tolist() == [3.0] * 10 and sorted(calls) == [(1, 3)] + [(3, 3)] * 3
    with pytest.raises(ValueError, match=r"values\[0\]: expected an array of shape \(\.\.\., 3\), got shape \(10, 2\)"):
        batched(record, [da.ones((10, 2))], [(3,)], [((), float)])


def test_a_grid_of_vectors_in_dask_chunks():
    # vector arguments (..., 3) and a 2-D batch, chunked along both axes
    da = pytest.importorskip("dask.array")
    from sympy import Matrix

    p = Matrix(symbols("p_x p_y p_z", real=True))
    mech = four_ruu(1).xreplace({x: p[0], y: p[1], h: p[2]})
    f = mobility_map(mech, [p])
    P = np.stack(np.meshgrid(np.linspace(-0.4, 0.4, 6), np.linspace(-0.3, 0.3, 5),
                             indexing="ij"), axis=-1)
    P = np.concatenate([P, np.full(P.shape[:2] + (1,), 1.7)], axis=-1)  # (6, 5, 3)
    lazy = f(da.from_array(P, chunks=(4, 2, 3)))
    assert lazy.sigma.shape == (6, 5, 6) and lazy.mobility.numblocks == (2, 3)
    assert np.array_equal(lazy.mobility.compute(), f(P).mobility)
    assert np.allclose(lazy.sigma.compute(), f(P).sigma)


def test_a_dask_map_pickles_for_other_processes():
    # the process and distributed schedulers pickle the graph: it carries the recipe (the
    # mechanism, its arguments, rtol, back end), not the generated code, and a worker that
    # has not made the map makes it once (here: the memory of made maps emptied)
    da = pytest.importorskip("dask.array")
    cloudpickle = pytest.importorskip("cloudpickle")
    from screwsym.numeric import mobility as mod

    f = mobility_map(four_ruu(1), [x, y, h])
    X = np.array([0.1, 0.2, -0.1, 0.3])
    lazy = f(da.from_array(X, chunks=2), X, np.full(4, 1.5))
    graph = cloudpickle.loads(cloudpickle.dumps(dict(lazy.mobility.__dask_graph__())))
    assert len(graph) > 2
    mod._MADE.clear()
    assert lazy.mobility.compute(scheduler="sync").tolist() == [4, 4, 4, 4]
    assert len(mod._MADE) == 1
