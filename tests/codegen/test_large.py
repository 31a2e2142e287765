"""Large closed forms compile on every back end (issue 23 item 5).

A sum of thousands of terms prints as a left-nested chain ``a + b + ...`` that Python's
compiler walks recursively, and a deep tree overflows SymPy's recursive walks: both raised
``RecursionError`` before.  Each result is checked against the same formula evaluated by
another route (NumPy's own polynomial evaluation, a plain Python loop).
"""

import math

import numpy as np
import pytest
from sympy import Add, Integer, cos, sin, symbols

from screwsym.codegen import c_source, lambdify
from screwsym.codegen._plan import MAX_ARGS, MAX_DEPTH

x, y = symbols("x y", real=True)
BACKENDS = ["numpy", "c"]  # numba compiles such functions for tens of seconds: see below


def _needs(backend):
    if backend == "numba":
        pytest.importorskip("numba")
    if backend == "c":
        from screwsym.codegen._build import compiler

        if compiler() is None:
            pytest.skip("no C compiler")


@pytest.fixture(scope="module")
def wide():
    """A sum of 400 distinct monomials, and its coefficients (printed in chunks of MAX_ARGS)."""
    n = 400
    e = Add(*[Integer(k + 1) * x ** (k % 20) * y ** (k // 20) for k in range(n)])
    C = np.zeros((20, n // 20))
    for k in range(n):
        C[k % 20, k // 20] = k + 1
    return e, C


@pytest.fixture(scope="module")
def deep():
    """A tree 400 levels deep: SymPy's recursive walks (``free_symbols``, ``srepr``) and
    Python's parser (at most 200 nested parentheses) failed on it before."""
    n = 400
    e = x
    for k in range(n):
        e = sin(e) + y if k % 2 else cos(e) * y
    return e, n


def _deep_value(a, b, n):
    v = a
    for k in range(n):
        v = math.sin(v) + b if k % 2 else math.cos(v) * b
    return v


X, Y = np.array([0.3, -0.9, 0.95]), np.array([0.5, 0.2, -0.8])


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_wide_sum_compiles_and_agrees_with_numpy_polyval(wide, backend):
    _needs(backend)
    e, C = wide
    f = lambdify([x, y], e, backend=backend)
    expected = np.polynomial.polynomial.polyval2d(X, Y, C)
    assert np.allclose(f(X, Y), expected, rtol=1e-13, atol=0)
    assert f(0.3, 0.5) == pytest.approx(expected[0], rel=1e-13)
    # the checker rejects a wrong answer: one coefficient changed
    C2 = C.copy()
    C2[3, 7] += 1
    assert not np.allclose(f(X, Y), np.polynomial.polynomial.polyval2d(X, Y, C2), rtol=1e-13,
                           atol=0)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_deep_tree_compiles_and_agrees_with_a_loop(deep, backend):
    _needs(backend)
    e, n = deep
    f = lambdify([x, y], e, backend=backend)
    expected = [_deep_value(a, b, n) for a, b in zip(X, Y, strict=True)]
    assert np.allclose(f(X, Y), expected, rtol=1e-12, atol=1e-14)
    assert not np.allclose(f(X, Y), [_deep_value(a, b, n - 1) for a, b in zip(X, Y, strict=True)])


@pytest.mark.slow
def test_numba_compiles_a_deep_tree():
    # 160 levels: beyond CSE_DEPTH (the iterative path) and Python's 200 nested parentheses
    # once printed; numba's compilation takes seconds, so a smaller tree than above
    _needs("numba")
    n = 160
    u, v = symbols("u v", real=True)  # not x, y: building on SymPy's cache of the tree above
    e = u  # could compare deep trees recursively
    for k in range(n):
        e = sin(e) + v if k % 2 else cos(e) * v
    f = lambdify([u, v], e, backend="numba")
    expected = [_deep_value(a, b, n) for a, b in zip(X, Y, strict=True)]
    assert np.allclose(f(X, Y), expected, rtol=1e-12, atol=1e-14)
    assert not np.allclose(f(X, Y), [_deep_value(a, b, n - 1) for a, b in zip(X, Y, strict=True)])


def test_the_generated_statements_are_small(wide, deep):
    # straight-line code: no printed sum has more than MAX_ARGS terms, no line is deep
    for e in (wide[0], deep[0]):
        src = c_source([x, y], e)
        lines = [ln for ln in src.splitlines() if " = " in ln]
        assert len(lines) > 12
        assert max(ln.count(" + ") for ln in lines) < MAX_ARGS
        assert max(ln.count("(") for ln in lines) <= 2 * MAX_DEPTH + 2


@pytest.mark.parametrize("which", ["wide", "deep"])
def test_a_large_c_body_is_split_into_parts_that_agree(wide, deep, which, monkeypatch, tmp_path):
    # gcc's register allocation grows faster than the size of one function: a body longer
    # than C_CHUNK characters is written as noinline parts passing values through a scratch
    # array (7,000 monomials: 60 s of gcc -O3 in one function, 4 s in parts).  A small
    # C_CHUNK puts these two expressions on that path; the results must not change.
    _needs("c")
    from screwsym.codegen import _build, _emit

    monkeypatch.setattr(_emit, "C_CHUNK", 300)
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(tmp_path))  # not the library built before
    _build.clear_cache()
    e = (wide if which == "wide" else deep)[0]
    src = c_source([x, y], e)
    assert "_part2(_t);" in src and "double _t[" in src
    f = lambdify([x, y], e, backend="c")
    _build.clear_cache()
    if which == "wide":
        C2 = wide[1].copy()
        C2[3, 7] += 1
        expected, wrong = (np.polynomial.polynomial.polyval2d(X, Y, C) for C in (wide[1], C2))
    else:
        expected, wrong = ([_deep_value(a, b, n) for a, b in zip(X, Y, strict=True)]
                           for n in (deep[1], deep[1] - 1))
    assert np.allclose(f(X, Y), expected, rtol=1e-12, atol=1e-14)
    assert f(0.3, 0.5) == pytest.approx(expected[0], rel=1e-12)
    assert not np.allclose(f(X, Y), wrong, rtol=1e-12, atol=1e-14)
