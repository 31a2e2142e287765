"""Tests for screwsym.codegen: lambdify's back ends, c_source, input checking."""

from __future__ import annotations

import ctypes
import inspect
import random
import subprocess
import sys
import warnings

import numpy as np
import pytest
from _backends import BACKENDS, HAS_CC, HAS_NUMBA
from sympy import Matrix, Rational, cos, sin, sqrt, symbols

from screwsym import Screw, Twist, foot, lambdify, pitch, reciprocal_product, vector
from screwsym.codegen import c_source

S, S0 = vector("S"), vector("S0")
s = Screw(S, S0)
A = vector("A")
h, k = symbols("h k", real=True)

# One function that exercises every kind of argument and result: a scalar,
# a 3-vector, a 3x2 matrix, a screw, and a tuple of them; with sqrt, trig
# and a division, so that CSE and the printers all have work to do.
ARGS = [s, A, h]
EXPR = (
    pitch(s) * h + sqrt(1 + A.dot(A)),
    foot(s) + A * cos(h),
    Screw(S * h, S0 + A.cross(S)),
    Matrix([[A[0], sin(h)], [A[1] * S[0], 1], [A[2] / (1 + h**2), S0[2]]]),
)


def rationals(rng: random.Random, n: int) -> list[Rational]:
    return [Rational(rng.randint(-60, 60), rng.randint(1, 13)) for _ in range(n)]


def exact_value(args, expr, values):
    """Exact SymPy evaluation of each result of ``expr`` at one point, as float arrays."""
    subs = {}
    for a, v in zip(args, values, strict=True):
        syms = list(a.matrix) if isinstance(a, Screw) else (list(a) if a.is_Matrix else [a])
        vals = v if isinstance(v, list) else [v]
        subs.update(dict(zip(syms, vals, strict=True)))
    out = []
    for e in expr:
        m = e.matrix if isinstance(e, Screw) else e
        exact = m.xreplace(subs).evalf(30) if hasattr(m, "is_Matrix") and m.is_Matrix else None
        if exact is None:
            out.append(np.float64(float(e.xreplace(subs).evalf(30))))
        else:
            arr = np.array([float(x) for x in exact], dtype=float)
            out.append(arr if 1 in m.shape else arr.reshape(m.shape))
    return out


def assert_close(got, want, rtol=1e-12):
    got, want = np.asarray(got, float), np.asarray(want, float)
    assert got.shape == want.shape
    scale = max(np.max(np.abs(want)), 1e-300)
    assert np.max(np.abs(got - want)) <= rtol * scale, (got, want)


def random_point(rng):
    # a screw whose S is not zero, a point, a scalar
    return [rationals(rng, 6), rationals(rng, 3), rationals(rng, 1)[0]]


@pytest.mark.parametrize("backend", BACKENDS)
def test_agrees_with_exact_evaluation_scalar_and_batched(backend):
    f = lambdify(ARGS, EXPR, backend, names=["s", "A", "h"])
    rng = random.Random(4)
    points = [random_point(rng) for _ in range(6)]
    wants = [exact_value(ARGS, EXPR, p) for p in points]
    # one point at a time (the single-point fast path)
    for p, want in zip(points, wants, strict=True):
        got = f(np.array(p[0], float), np.array(p[1], float), float(p[2]))
        assert isinstance(got, tuple) and len(got) == 4
        for g, w in zip(got, want, strict=True):
            assert_close(g, w)
    # all points at once, batch shape (2, 3)
    sb = np.array([[float(x) for x in p[0]] for p in points]).reshape(2, 3, 6)
    Ab = np.array([[float(x) for x in p[1]] for p in points]).reshape(2, 3, 3)
    hb = np.array([float(p[2]) for p in points]).reshape(2, 3)
    got = f(sb, Ab, hb)
    assert [g.shape for g in got] == [(2, 3), (2, 3, 3), (2, 3, 6), (2, 3, 3, 2)]
    for i, want in enumerate(wants):
        for g, w in zip(got, want, strict=True):
            assert_close(g.reshape((6,) + g.shape[2:])[i], w)


@pytest.mark.parametrize("backend", BACKENDS)
def test_broadcasting_and_layouts(backend):
    f = lambdify([s, A], reciprocal_product(s, Screw(A, A)), backend)
    rng = np.random.default_rng(0)
    screws = rng.standard_normal((4, 1, 6))
    points = rng.standard_normal((5, 3))
    want = np.einsum("...i,...i->...", screws[..., :3], points) + np.einsum(
        "...i,...i->...", points, screws[..., 3:]
    )
    assert_close(f(screws, points), want)
    assert f(screws, points).shape == (4, 5)
    # one screw against many points, non-contiguous and float32 and int input
    big = rng.standard_normal((10, 12))[:, ::2]
    assert_close(f(big, points[0]), f(np.ascontiguousarray(big), points[0]))
    assert f(big.astype(np.float32), [1, 2, 3]).dtype == np.float64
    assert f(np.arange(6), np.arange(3)) == (0 + 1 + 4) + (0 + 4 + 10)  # S.A + A.S0
    # an empty batch
    assert f(np.zeros((0, 6)), points[0]).shape == (0,)


@pytest.mark.parametrize("backend", BACKENDS)
def test_constant_and_single_result_tuple(backend):
    f = lambdify([s, h], (Screw([0, 0, 0], [0, 0, 1]),), backend, names=["s", "h"])
    (out,) = f(np.ones((3, 6)), np.zeros(3))
    assert out.shape == (3, 6)
    np.testing.assert_array_equal(out, np.tile([0, 0, 0, 0, 0, 1.0], (3, 1)))
    (one,) = f(np.ones(6), 0.0)
    np.testing.assert_array_equal(one, [0, 0, 0, 0, 0, 1.0])


@pytest.mark.parametrize("backend", BACKENDS)
def test_division_by_zero_follows_ieee_without_warning(backend):
    f = lambdify([s], pitch(s), backend)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.isnan(f(np.zeros(6)))
        out = f(np.array([[0.0, 0, 0, 0, 0, 1], [1, 0, 0, 2, 0, 0]]))
    assert np.isnan(out[0]) and out[1] == 2.0


def test_cse_is_on_by_default_and_can_be_switched_off():
    expr = (S.dot(S0) / S.dot(S), S.dot(S) * 2)
    with_cse = inspect.getsource(lambdify([s], expr, "numpy", name="with_cse"))
    without = inspect.getsource(lambdify([s], expr, "numpy", name="without_cse", cse=False))
    assert "_c0 = " in with_cse and "_c0" not in without


def test_names_source_and_cache():
    f = lambdify([s], foot(s))
    assert f.__name__.startswith("lambdified_") and len(f.__name__) == len("lambdified_") + 10
    # the name depends only on the expression: rebuilding it gives the same one
    g = lambdify([Screw(vector("S"), vector("S0"))], foot(Screw(vector("S"), vector("S0"))))
    assert g is f
    assert lambdify([s], foot(s), name="foot_point").__name__ == "foot_point"
    assert str(inspect.signature(f)) == "(s, *, out=None)"
    source = inspect.getsource(f)
    # the source uses screwsym's names only; the user's live on the code object
    assert source.startswith("def _fn(_a0, *, out=None):")
    assert "(_x0*_x0)" in source and "S_x" not in source
    assert lambdify([s], foot(s), cse=False) is not f


@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_numba_kernel_source_is_visible():
    f = lambdify([s], pitch(s), "numba", name="pitch_nb")
    assert "_kernel(_n, _a0, _o0)" in inspect.getsource(f)
    assert "for _i in range(_n):" in inspect.getsource(f.load_kernel().py_func)


def test_numba_missing_gives_a_clear_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "numba", None)
    with pytest.raises(ImportError, match=r"backend 'numba' needs numba: pip install"):
        lambdify([h], h**3 + 7, "numba")


def test_argument_names_are_derived_and_clean():
    t, P = Twist(vector("w"), vector("v")), vector("P")
    f = lambdify([t, P, h], t.velocity_at(P) * h)
    assert str(inspect.signature(f)) == "(w, P, h, *, out=None)"
    # symbols whose names are not identifiers are renamed in the code
    x, y = symbols("x[0] lambda", real=True)
    g = lambdify([Matrix([x, y])], x * y)
    assert g(np.array([2.0, 3.0])) == 6.0


# ----------------------------------------------------------- bad input


def test_wrong_trailing_shape():
    f = lambdify([s, A], reciprocal_product(s, Screw(A, A)), names=["s", "A"])
    with pytest.raises(ValueError, match=r"s: expected an array of shape \(\.\.\., 6\) for a screw "
                       r"\(S; S0\), got shape \(4, 5\)"):
        f(np.zeros((4, 5)), np.zeros(3))
    with pytest.raises(ValueError, match=r"A: expected an array of shape \(\.\.\., 3\) for a "
                       r"3-vector, got shape \(6,\)"):
        f(np.zeros(6), np.zeros(6))


def test_mismatched_batch_shapes():
    f = lambdify([s, A], reciprocal_product(s, Screw(A, A)), names=["s", "A"])
    with pytest.raises(ValueError, match=r"s, A: expected batch \(leading\) shapes that broadcast "
                       r"together, got s has batch shape \(3,\), A has batch shape \(4,\)"):
        f(np.zeros((3, 6)), np.zeros((4, 3)))


@pytest.mark.parametrize("backend", BACKENDS)
def test_complex_and_non_numeric_input(backend):
    f = lambdify([s, h], pitch(s) * h, backend, names=["s", "h"])
    with pytest.raises(TypeError, match=r"s: expected real numbers, got dtype complex128"):
        f(np.ones(6, complex), 1.0)
    with pytest.raises(TypeError, match=r"h: expected real numbers, got dtype complex128"):
        f(np.ones(6), 1j)
    with pytest.raises(TypeError, match=r"s: expected an array of real numbers, got dtype bool"):
        f(np.ones(6, bool), 1.0)
    with pytest.raises(TypeError, match=r"s: expected an array of real numbers, got dtype <U1"):
        f(["1"] * 6, 1.0)
    with pytest.raises(TypeError, match=r"h: expected an array of real numbers, got ndarray holding objects"):
        f(np.ones(6), np.array([symbols("x")], dtype=object))
    # SymPy numbers are accepted
    assert f([Rational(1), 0, 0, Rational(1, 2), 0, 0], Rational(2)) == 1.0


def test_bad_args_and_expr():
    with pytest.raises(TypeError, match=r"args\[0\]: expected symbols as entries, got 1"):
        lambdify([Matrix([1, h, k])], h)
    with pytest.raises(ValueError, match=r"args: the symbol h appears twice"):
        lambdify([h, Matrix([h, k, k + 1]).col(0)[:2, 0]], h)
    with pytest.raises(ValueError, match=r"expr: the symbols k are not among args"):
        lambdify([h], h + k)
    with pytest.raises(TypeError, match=r"args\[0\]: expected a Symbol, a matrix of symbols"):
        lambdify([h + 1], h)
    with pytest.raises(TypeError, match=r"expr: expected a SymPy expression, matrix, screw"):
        lambdify([h], "h + 1")
    with pytest.raises(ValueError, match=r"expr: expected real expressions"):
        lambdify([h], h * sqrt(-1))
    with pytest.raises(ValueError, match=r"backend: expected one of 'numpy', 'numba', 'c' or None, got 'jax'"):
        lambdify([h], h, "jax")
    with pytest.raises(ValueError, match=r"name: expected a Python identifier"):
        lambdify([h], h, name="not valid")
    with pytest.raises(ValueError, match=r"names: expected 1 names, one per argument, got 2"):
        lambdify([h], h, names=["a", "b"])


# ------------------------------------------------------------------ C


@pytest.mark.skipif(not HAS_CC, reason="no C compiler (cc)")
def test_c_source_compiles_and_runs(tmp_path):
    s2 = Screw(vector("T"), vector("T0"))
    src = c_source([s, s2, h], (reciprocal_product(s, s2) * h, foot(s)), name="demo",
                   names=["s1", "s2", "h"])
    c_file, so_file = tmp_path / "demo.c", tmp_path / "demo.so"
    c_file.write_text(src)
    subprocess.run(["cc", "-O2", "-std=c99", "-Wall", "-Werror", "-shared", "-fPIC", str(c_file),
                    "-o", str(so_file), "-lm"], check=True, capture_output=True)
    lib = ctypes.CDLL(str(so_file))
    dp = ctypes.POINTER(ctypes.c_double)
    lib.screwsym_demo.argtypes = [ctypes.c_size_t] + [dp, ctypes.c_ssize_t] * 3 + [dp, dp]
    lib.screwsym_demo_point.argtypes = [dp, dp, ctypes.c_double, dp, dp]

    rng = random.Random(7)
    n = 5
    pts = [(rationals(rng, 6), rationals(rng, 6), rationals(rng, 1)[0]) for _ in range(n)]
    a = np.array([[float(x) for x in p[0]] for p in pts])
    b = np.array([[float(x) for x in p[1]] for p in pts])
    hv = np.array([float(p[2]) for p in pts])
    out0, out1 = np.empty(n), np.empty((n, 3))
    ptr = lambda arr: arr.ctypes.data_as(dp)  # noqa: E731
    lib.screwsym_demo(n, ptr(a), 6, ptr(b), 6, ptr(hv), 1, ptr(out0), ptr(out1))
    for i, (p1, p2, hh) in enumerate(pts):
        sa, sb = Screw(p1[:3], p1[3:]), Screw(p2[:3], p2[3:])
        assert_close(out0[i], float(reciprocal_product(sa, sb) * hh))
        assert_close(out1[i], np.array([float(x) for x in foot(sa)]))
    # the point function, and a broadcast row (step 0)
    r0, r1 = np.empty(1), np.empty(3)
    lib.screwsym_demo_point(ptr(a[1]), ptr(b[1]), hv[1], ptr(r0), ptr(r1))
    assert_close(r0[0], out0[1])
    lib.screwsym_demo(n, ptr(a[:1].copy()), 0, ptr(b), 6, ptr(hv), 1, ptr(out0), ptr(out1))
    assert_close(out1, np.tile(out1[0], (n, 1)))


def test_c_source_is_plain_c99_from_sympy_printers():
    src = c_source([s], pitch(s), name="p")
    assert "#include <math.h>" in src
    assert "void screwsym_p_point(const double *restrict _a0, double *restrict _o0)" in src
    assert "size_t screwsym_p(size_t n, const double *_a0, ptrdiff_t _s0, double *_o0)" in src
    assert "pow(_x0, 2.0)" in src  # SymPy's C99 printer, integers as doubles


def test_generated_functions_run_the_lambdify_tuple_of_screws():
    f = lambdify([s, h], (s * h, pitch(s)), names=["s", "h"])
    a, b = f(np.array([1.0, 0, 0, 3, 0, 0]), 2.0)
    np.testing.assert_array_equal(a, [2, 0, 0, 6, 0, 0])
    assert b == 3.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_out_arrays_are_filled_and_checked(backend):
    f = lambdify([s, A], (foot(s), reciprocal_product(s, Screw(A, A))), backend, names=["s", "A"])
    x = np.random.default_rng(3).standard_normal((4, 6))
    P = np.random.default_rng(4).standard_normal(3)
    o0, o1 = np.empty((4, 3)), np.empty(4)
    r0, r1 = f(x, P, out=(o0, o1))
    assert np.shares_memory(r0, o0) and np.shares_memory(r1, o1)
    w0, w1 = f(x, P)
    np.testing.assert_array_equal(o0, w0)
    np.testing.assert_array_equal(o1, w1)
    with pytest.raises(ValueError, match=r"out: expected 2 arrays, one per result, got 1"):
        f(x, P, out=o0)
    with pytest.raises(ValueError, match=r"out\[1\]: expected a writeable C-contiguous float64 "
                       r"array of shape \(4,\), got float32 array of shape \(4,\)"):
        f(x, P, out=(o0, np.empty(4, np.float32)))
    with pytest.raises(ValueError, match=r"out\[0\]: .* got float64 array of shape \(4, 3\), "
                       r"not C-contiguous"):
        f(x, P, out=(np.empty((4, 6))[:, :3], o1))


@pytest.mark.parametrize("backend", BACKENDS)
def test_single_point_results_are_ordinary_writeable_arrays(backend):
    f = lambdify([s], (foot(s), Matrix([[S[0], S[1]], [S0[0], 1]])), backend, names=["s"])
    P, M = f(np.array([1.0, 1, 0, 1, 0, 0]))
    assert P.dtype == np.float64 and P.shape == (3,) and P.flags.writeable
    assert M.shape == (2, 2) and M.flags.writeable
    P[0] = 7.0
    np.testing.assert_array_equal(M, [[1.0, 1.0], [1.0, 1.0]])


def test_default_backend_is_numba_when_installed_else_numpy(monkeypatch):
    from screwsym import codegen

    assert codegen.default_backend() == ("numba" if HAS_NUMBA else "numpy")
    monkeypatch.setattr(codegen, "_HAS_NUMBA", False)
    f = lambdify([h], h**2 + 41)  # not built elsewhere
    assert "_errstate" in inspect.getsource(f) and "Generated by screwsym.lambdify (backend " \
        "'numpy')" in f.__doc__
    assert f(np.array([1.0, 2.0])).tolist() == [42.0, 45.0]


def test_a_negated_condition_prints_as_python_on_every_sympy():
    # SymPy 1.13's printer wrote Not(_c1) as `not_c1`, a NameError in the generated code
    from sympy import Not, Symbol

    from screwsym.codegen._printers import ScalarPrinter

    text = ScalarPrinter().doprint(Not(Symbol("_c1")))
    assert text == "(not (_c1))"
    assert eval(text, {"_c1": False}) is True and eval(text, {"_c1": True}) is False
