"""The C loops called directly on plain batches, into recycled results (issue 34 item 4).

The direct path must give exactly what the generated function's own path gives, for every
kind of input (plain batches take it, everything else falls through), and a recycled result
must never be one that the caller still holds in any way.
"""

from __future__ import annotations

import numpy as np
import pytest
from _backends import HAS_CC

from screwsym import numeric
from screwsym.numeric import _direct

pytestmark = pytest.mark.skipif(not HAS_CC, reason="no C compiler")

KINDS = {"pitch": (6,), "foot": (6,), "reciprocal_product": (6, 6), "shift_origin": (6, 3),
         "line_through": (3, 3), "velocity_at": (6, 3), "moment_about": (6, 3)}


def args_for(name: str, batch: tuple[int, ...], seed: int = 0) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    return [rng.standard_normal(batch + (k,)) for k in KINDS[name]]


@pytest.mark.parametrize("name", numeric.NAMES)
def test_the_direct_path_gives_the_generated_functions_numbers(name, monkeypatch):
    c = getattr(numeric.functions_for("c"), name)
    generic = c.__wrapped__  # the generated function: checks, prepare, the same C loop
    reference = getattr(numeric.functions_for("numpy"), name)
    reference = getattr(reference, "__wrapped__", reference)  # without the rescaling
    prepared = []
    real = generic.__globals__["_prepare"]

    def spy(*a):  # the generated path checks and reshapes its arguments here
        prepared.append(a)
        return real(*a)

    monkeypatch.setitem(generic.__globals__, "_prepare", spy)
    for batch in [(0,), (1,), (5,), (1001,), (3, 7)]:
        args = args_for(name, batch)
        got = c(*args)
        assert not prepared, "the plain batch did not take the direct path"
        np.testing.assert_array_equal(got, generic(*args))
        assert len(prepared) == 1  # (the spy sees the generated path)
        prepared.clear()
        np.testing.assert_array_equal(got, reference(*args))
        out = np.empty_like(got)
        assert c(*args, out=out) is out
        np.testing.assert_array_equal(out, got)
    # what is not a plain batch takes the generated function's path: the same numbers
    args = args_for(name, (8,))
    want = reference(*args)
    others = [
        [a.tolist() for a in args],  # lists
        [np.repeat(a, 2, axis=0)[::2] for a in args],  # strided
        [a.astype(">f8") for a in args],  # byte-swapped
    ]
    for other in others:
        np.testing.assert_array_equal(c(*other), want)
    assert len(prepared) == 3  # the three that are not plain batches
    one = [a[3] for a in args]  # one screw: the extension's fast call
    np.testing.assert_array_equal(c(*one), want[3])
    if len(args) == 2:  # batch shapes that broadcast: one point for all screws
        np.testing.assert_array_equal(c(args[0], args[1][:1]), reference(args[0], args[1][:1]))
    names = list(c.__wrapped__.__code__.co_varnames[: len(args)])
    np.testing.assert_array_equal(c(**dict(zip(names, args, strict=True))), want)
    with pytest.raises(ValueError, match="expected an array of shape"):
        c(*[a[:, :2] for a in args])


def test_out_that_is_an_input_takes_the_generated_path():
    s, A = args_for("shift_origin", (50,))
    want = numeric.functions_for("numpy").shift_origin(s, A)
    numeric.functions_for("c").shift_origin(s, A, out=s)  # out= aliases s: prepare reads from a copy
    np.testing.assert_array_equal(s, want)
    with pytest.raises(ValueError, match=r"out: expected a writeable C-contiguous float64"):
        numeric.functions_for("c").shift_origin(s, A, out=np.empty((50, 6), np.float32))


BIG = (40_000,)  # 40,000 screws of 6 doubles: 1.9 MB, recycled


def test_a_result_is_recycled_only_once_let_go():
    f = numeric.functions_for("c").shift_origin  # (the default is numba once imported)
    x, y = args_for("shift_origin", BIG, 1), args_for("shift_origin", BIG, 2)
    want_x, want_y = f.__wrapped__(*x), f.__wrapped__(*y)
    a = f(*x)
    b = f(*y)  # a is held: a new array
    assert a is not b and not np.shares_memory(a, b)
    np.testing.assert_array_equal(a, want_x)
    np.testing.assert_array_equal(b, want_y)
    held = {"view": None, "list": None, "memoryview": None}
    for kind in held:
        r = f(*x)
        held[kind] = r[:10] if kind == "view" else [r] if kind == "list" else memoryview(r)
        del r
        fresh = f(*y)
        got = (held[kind] if kind == "view" else held[kind][0] if kind == "list"
               else np.asarray(held[kind]))
        np.testing.assert_array_equal(got, want_x[: len(got)])  # never written over
        assert not np.shares_memory(fresh, got)
    last_id = id(fresh)  # the recycler keeps the last result made
    del b, held, fresh
    again = f(*x)  # let go: the same array again, with the new numbers
    assert id(again) == last_id
    np.testing.assert_array_equal(again, want_x)


def test_the_recycling_check_fails_where_references_are_not_looked_at(monkeypatch):
    # the assertion of the test above is not vacuous: a recycler that did not count the
    # references would write over a result still held, and that is seen
    recycler = _direct.Recycler()
    a = recycler.empty((40_000, 6))
    a[...] = 1.0
    monkeypatch.setattr(_direct.sys, "getrefcount", lambda obj: 3)
    b = recycler.empty((40_000, 6))
    b[...] = 2.0
    assert b is a and (a == 2.0).all()  # overwritten: the held result changed
    monkeypatch.undo()  # the real reference count again: a (and b) held, a new array
    c = recycler.empty((40_000, 6))
    assert c is not a


def test_small_large_and_read_only_results_are_not_recycled():
    recycler = _direct.Recycler()
    for shape in [(100, 6), (_direct.RECYCLE_MAX // 48 + 1, 6)]:
        recycler.empty(shape)
        assert recycler._last is None  # not kept
    for writeable in (True, False):
        r = recycler.empty((40_000, 6))
        r_id = id(r)
        r.flags.writeable = writeable
        del r
        # the recycler held it until now: a new array cannot have its id
        assert (id(recycler.empty((40_000, 6))) == r_id) is writeable


def test_recycling_can_be_turned_off():
    import weakref

    f = numeric.functions_for("c").shift_origin
    x = args_for("shift_origin", BIG, 1)
    was = numeric.recycle_results()
    try:
        first = f(*x)
        ref = weakref.ref(first)
        del first
        assert ref() is not None  # on (the default): kept after its last use, for the next call
        assert f(*x) is ref()
        assert numeric.recycle_results(False) is False
        f(*x)
        assert ref() is None  # off: the one kept is let go at the next call
        kept = f(*x)
        ref = weakref.ref(kept)
        del kept
        assert ref() is None  # off: nothing held after its last use
    finally:
        numeric.recycle_results(was)
    with pytest.raises(TypeError, match="recycle_results: expected enabled"):
        numeric.recycle_results(1)
