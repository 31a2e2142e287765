"""The C back end's one-point call: a CPython extension module with a fast-call entry (issue 34).

Each C function is built as an extension module whose ``point`` function
(``METH_FASTCALL``) evaluates one plain point (native C-contiguous ``float64``
arrays of the arguments' own shapes, Python or NumPy floats) and returns
``None`` for anything else, which then takes the general path.  Every answer
is compared with the NumPy back end; the comparison is shown to catch a wrong
one.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import warnings
from pathlib import Path

import numpy as np
import pytest
from _backends import HAS_CC
from sympy import Matrix, Piecewise, symbols

from screwsym import Screw, foot, lambdify, pitch, vector
from screwsym.codegen import _build

pytestmark = pytest.mark.skipif(not HAS_CC or _build.python_headers() is None,
                                reason="no C compiler or no Python/NumPy headers")

s = Screw(vector("S"), vector("S0"))
A = vector("A")
h = symbols("h", real=True)
#: a scalar, a vector, a matrix and a scalar result, from a screw, a point and a scalar
EXPR = (pitch(s) * h, foot(s) + A, Matrix([[s.S[0], h], [s.S0[2], 1 / h]]),
        Piecewise((h, h > 0), (-s.S[1], True)))


def functions():
    c = lambdify([s, A, h], EXPR, "c", names=["s", "A", "h"])
    ref = lambdify([s, A, h], EXPR, "numpy", names=["s", "A", "h"])
    return c, ref


def same(got, want) -> bool:
    """The same results: the same types, shapes and values (nan where nan)."""
    return len(got) == len(want) and all(
        type(g) is type(w) and np.shape(g) == np.shape(w)
        and np.array_equal(np.asarray(g), np.asarray(w), equal_nan=True)
        for g, w in zip(got, want, strict=True))


def test_one_point_is_evaluated_by_the_extension_module():
    c, ref = functions()
    point = c.__globals__["_point"]
    assert point is not None and type(point).__name__ == "builtin_function_or_method"
    assert "METH_FASTCALL" in c.c_source and "PyInit_screwsym_k" in c.c_source
    args = (np.array([1.0, 1, 0, 1, 0, 0]), np.array([0.5, -1, 2]), 2.0)
    got = point(*args)
    assert got is not None and same(got, ref(*args)) and same(c(*args), got)
    assert type(got[0]) is np.float64 and got[1].flags.writeable and got[2].shape == (2, 2)
    # a NumPy float, zero and a couple: IEEE 754 as in the batch path, no warning
    for other in [(args[0], args[1], np.float64(-3.0)), (np.zeros(6), args[1], 0.0),
                  (np.array([0.0, 0, 0, 0, 0, 1]), args[1], 1.0)]:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            one = point(*other)
            batch = c(*(np.asarray(a)[None] for a in other))
        assert same(one, ref(*other)) and same(one, tuple(b[0] for b in batch))


@pytest.mark.parametrize("case", ["float32", "int list", "strided", "subclass", "swapped",
                                  "0-d", "python int", "batch"])
def test_anything_but_a_plain_point_takes_the_general_path(case):
    c, ref = functions()
    point = c.__globals__["_point"]
    S = np.array([1.0, 2, 0, 1, 0, 3])
    args = {
        "float32": (S.astype(np.float32), np.ones(3), 2.0),
        "int list": ([1, 2, 0, 1, 0, 3], np.ones(3), 2.0),
        "strided": (np.repeat(S, 2)[::2], np.ones(3), 2.0),
        "subclass": (S.view(np.memmap), np.ones(3), 2.0),
        "swapped": (S.astype(">f8"), np.ones(3), 2.0),
        "0-d": (S, np.ones(3), np.array(2.0)),
        "python int": (S, np.ones(3), 2),
        "batch": (np.stack([S, S]), np.ones(3), 2.0),
    }[case]
    assert point(*args) is None
    assert same(c(*args), ref(*args))


def test_wrong_input_is_refused_as_before():
    c, _ = functions()
    assert c.__globals__["_point"](np.ones(5), np.ones(3)) is None  # also a wrong count
    with pytest.raises(ValueError, match=r"s: expected an array of shape \(\.\.\., 6\)"):
        c(np.ones(5), np.ones(3), 1.0)
    with pytest.raises(TypeError):
        c(np.ones(6), np.ones(3), 1j)


def test_the_comparison_catches_a_wrong_point(monkeypatch):
    c, ref = functions()
    args = (np.array([1.0, 1, 0, 1, 0, 0]), np.array([0.5, -1, 2]), 2.0)
    good = c.__globals__["_point"]

    def wrong(*a):
        r = good(*a)
        return (r[0] + 1e-12, *r[1:])

    monkeypatch.setitem(c.__globals__, "_point", wrong)
    assert not same(c(*args), ref(*args))
    monkeypatch.setitem(c.__globals__, "_point", lambda *a: None)  # the general path
    assert same(c(*args), ref(*args))


def test_a_new_process_loads_the_extension_without_compiling(tmp_path):
    script = textwrap.dedent("""
        import sys
        import numpy as np
        from screwsym import Screw, lambdify, pitch, vector
        from screwsym.codegen import _build
        if sys.argv[1] == "second":
            def boom(*args, **kwargs):
                raise AssertionError("compiled again")
            _build._compile_c = boom
        s = Screw(vector("S"), vector("S0"))
        f = lambdify([s], 3 * pitch(s), "c")
        print(f(np.array([1.0, 1, 0, 1, 0, 0])), f.__globals__["_point"] is not None)
    """)
    env = dict(os.environ, SCREWSYM_CACHE_DIR=str(tmp_path))
    root = Path(__file__).resolve().parents[2]
    runs = [subprocess.run([sys.executable, "-c", script, mode], env=env, cwd=root,
                           capture_output=True, text=True) for mode in ("first", "second")]
    assert [r.returncode for r in runs] == [0, 0], runs[1].stderr
    assert runs[0].stdout == runs[1].stdout == "1.5 True\n"
    # the extension module is named for the Python and NumPy it was built for
    assert sorted(p.suffix for p in (tmp_path / "c").glob(f"*_py{_build._abi()}-*")) == [
        ".py", ".so"]
