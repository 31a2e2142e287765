"""screwsym.codegen: no user text runs, arguments and caches (issue 9)."""

from __future__ import annotations

import inspect
import linecache
import os
import stat
import subprocess
import sys
import tempfile
import textwrap
import threading
from pathlib import Path

import numpy as np
import pytest
from _backends import BACKENDS, HAS_CC, HAS_NUMBA
from sympy import (
    Basic,
    Function,
    ImmutableMatrix,
    Integral,
    Lambda,
    Matrix,
    Min,
    Subs,
    Sum,
    Symbol,
    erf,
    factorial,
    gamma,
    symbols,
    zoo,
)

from screwsym import Screw, lambdify, pitch, vector
from screwsym.codegen import _build, c_source

x, y = symbols("x y", real=True)
MARK = "SCREWSYM_PWNED"
PAYLOAD = f"__import__('os').environ.__setitem__('{MARK}', '1')"
C_PAYLOAD = f'x; }} __attribute__((constructor)) static void {MARK}(void) {{ abort(); }} /*'


def generated_texts(fn) -> str:
    """Every piece of generated source behind ``fn``: Python (linecache or file) and C."""
    texts = [text for name, entry in list(linecache.cache.items())
             if "screwsym-codegen" in name or "screwsym_generated" in name
             for text in ["".join(entry[2])]]
    code_file = fn.__code__.co_filename
    if os.path.exists(code_file):
        texts.append(Path(code_file).read_text())
    texts.append(getattr(fn, "c_source", ""))
    return "\n".join(texts)


@pytest.fixture(autouse=True)
def _no_mark():
    os.environ.pop(MARK, None)
    yield
    assert MARK not in os.environ, "generated code ran user text"


# ------------------------------------------------------------ injection


@pytest.mark.parametrize("backend", BACKENDS)
def test_crafted_argument_symbol_names_leave_no_trace(backend):
    evil = Symbol(f"a'); {PAYLOAD}; #", real=True)
    evil_c = Symbol(C_PAYLOAD, real=True)
    vec = Matrix([Symbol(f"{PAYLOAD}\n{i}", real=True) for i in range(3)])
    f = lambdify([evil, evil_c, vec], evil * evil_c + vec.dot(vec), backend)
    assert f(2.0, 3.0, np.array([1.0, 2, 3])) == 20.0
    np.testing.assert_array_equal(f(np.ones(2), 2.0, np.ones((2, 3))), [5.0, 5.0])
    text = generated_texts(f)
    assert MARK not in text and "__import__" not in text
    assert f.__code__.co_varnames[:3] == ("arg0", "arg1", "arg2")


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize(
    "construct",
    [
        lambda: Sum(x * Symbol(PAYLOAD, integer=True), (Symbol(PAYLOAD, integer=True), 0, 3)),
        lambda: Subs(x * Symbol(PAYLOAD), Symbol(PAYLOAD), y),
        lambda: Integral(Symbol(PAYLOAD, real=True), (Symbol(PAYLOAD, real=True), 0, x)),
        lambda: Function(PAYLOAD)(x),
        lambda: Lambda(Symbol(PAYLOAD), x)(y) + Function(MARK)(x),
    ],
    ids=["Sum", "Subs", "Integral", "undefined function", "applied undefined"],
)
def test_bound_symbols_and_unknown_functions_are_refused_up_front(backend, construct):
    expr = construct()
    with pytest.raises(TypeError, match=rf"expr: backend '{backend}' cannot generate code for"):
        lambdify([x, y], expr, backend)
    with pytest.raises(TypeError, match=r"expr: backend 'c' cannot generate code for"):
        c_source([x, y], expr)


@pytest.mark.parametrize("backend", BACKENDS)
def test_crafted_function_and_parameter_names_are_refused(backend):
    for bad in [PAYLOAD, "a b", "_private", "out", "class", "\u0430", ""]:
        with pytest.raises(ValueError, match=r"names\[0\]: expected a Python identifier"):
            lambdify([x], x, backend, names=[bad])
        with pytest.raises(ValueError, match=r"name: expected a Python identifier"):
            lambdify([x], x, backend, name=bad)
    with pytest.raises(ValueError, match=r"name: expected a Python identifier"):
        c_source([x], x, name=C_PAYLOAD)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_crafted_docstring_is_data(backend):
    f = lambdify([x], x + 1, backend, doc=f'"""\n{PAYLOAD}\n"""')
    assert f(1.0) == 2.0 and PAYLOAD in f.__doc__
    assert MARK not in generated_texts(f)


# Names that clashed with generated names before (issue 9)
CLASHING = ["out0", "range", "list", "abs", "min", "max", "n", "i", "size_t", "NAN", "sqrt",
            "numpy", "math", "float", "int", "double", "restrict", "lambdified"]


@pytest.mark.parametrize("backend", BACKENDS)
def test_user_names_never_clash_with_generated_names(backend):
    syms = symbols(" ".join(CLASHING), real=True)
    expr = sum((k + 1) * s for k, s in enumerate(syms)) + syms[0] * syms[-1]
    f = lambdify(list(syms), expr, backend, name="range", names=CLASHING)
    vals = [float(k) for k in range(len(syms))]
    want = sum((k + 1) * v for k, v in enumerate(vals)) + vals[0] * vals[-1]
    assert f(*vals) == want
    assert f(**dict(zip(CLASHING, np.array(vals)[:, None], strict=True)))[0] == want
    assert f.__name__ == "range"
    g = lambdify([Matrix(syms[:3])], syms[0] - syms[2], backend, name="sqrt")
    assert g(np.array([[5.0, 0, 2]])) == 3.0
    out = np.empty(1)
    assert f(*[np.array([v]) for v in vals], out=out) is not None and out[0] == want
    # a symbol called out keeps its value apart from the out= keyword
    o = Symbol("out", real=True)
    k = lambdify([o], o * 2, backend)
    assert str(inspect.signature(k)) == "(arg0, *, out=None)" and k(4.0) == 8.0


@pytest.mark.skipif(not HAS_CC, reason="no C compiler")
def test_c_source_with_crafted_and_clashing_names_compiles_cleanly(tmp_path):
    syms = symbols(" ".join(CLASHING), real=True) + (Symbol(C_PAYLOAD, real=True),)
    src = c_source(list(syms), sum(syms) * syms[1], name="sqrt")
    assert MARK not in src and "constructor" not in src
    (tmp_path / "k.c").write_text(src)
    subprocess.run([_build.compiler(), "-std=c99", "-Wall", "-Werror", "-c", str(tmp_path / "k.c"),
                    "-o", str(tmp_path / "k.o")], check=True, capture_output=True)


# ------------------------------------------------------------ refusals


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("expr,what", [(gamma(x), "gamma"), (erf(x), "erf"),
                                       (factorial(x), "factorial"), (x + zoo, "ComplexInfinity")])
def test_unsupported_constructs_are_refused_naming_them(backend, expr, what):
    with pytest.raises(TypeError, match=rf"backend '{backend}' cannot generate code for {what}"):
        lambdify([x], expr, backend)


def test_degenerate_calls_get_clear_errors():
    with pytest.raises(ValueError, match=r"args: expected at least one symbol, vector or screw"):
        lambdify([], 1)
    with pytest.raises(ValueError, match=r"expr: expected at least one result, got an empty tuple"):
        lambdify([x], ())
    with pytest.raises(TypeError, match=r"name: expected a string, got int 123"):
        lambdify([x], x, name=123)
    with pytest.raises(TypeError, match=r"names: expected a list of strings, got str"):
        lambdify([x], x, names="x")
    with pytest.raises(ValueError, match=r"names\[1\]: expected distinct names, got 'a' twice"):
        lambdify([x, y], x, names=["a", "a"])
    with pytest.raises(ValueError, match=r"backend: expected one of .* or None, got 1"):
        lambdify([x], x, 1)
    with pytest.raises(TypeError, match=r"cse: expected True or False, got int 1"):
        lambdify([x], x, cse=1)
    with pytest.raises(ValueError, match=r"args\[0\]: expected a non-empty matrix"):
        lambdify([Matrix(0, 1, [])], 1)


def test_booleans_are_not_numbers_and_keys_tell_them_apart():
    with pytest.raises(TypeError, match=r"expr: expected a SymPy expression.*got bool True"):
        lambdify([x], True)
    one = lambdify([x], 1, "numpy")
    assert one(2.0) == 1.0
    with pytest.raises(TypeError, match=r"expr\[1\]: expected a SymPy expression.*got bool False"):
        lambdify([x], (1, False))
    # keys are built from srepr, not ==: 1 and 1.0 (equal in SymPy) are two functions
    assert lambdify([x], x + 1, "numpy") is not lambdify([x], x + 1.0, "numpy")
    assert lambdify([x], x + 1, "numpy") is lambdify([x], x + 1, "numpy")


@pytest.mark.parametrize("backend", BACKENDS)
def test_none_booleans_and_objects_are_refused_as_numbers(backend):
    f = lambdify([x, vector("A")], x * vector("A")[0], backend, names=["x", "A"])
    A = np.ones(3)
    with pytest.raises(TypeError, match=r"x: expected real numbers, got None"):
        f(None, A)
    with pytest.raises(TypeError, match=r"x: expected real numbers, got True"):
        f(True, A)
    with pytest.raises(TypeError, match=r"x: expected real numbers, got np.True_"):
        f(np.True_, A)
    with pytest.raises(TypeError, match=r"A: expected an array of real numbers, got list holding "
                                        r"objects that are not real numbers \(NoneType None\)"):
        f(1.0, [1.0, None, 2.0])
    with pytest.raises(TypeError, match=r"A: .* not real numbers \(bool True\)"):
        f(1.0, np.array([1.0, True, 2.0], dtype=object))
    assert f(2, [1, 2, 3]) == 2.0  # integers are numbers


@pytest.mark.parametrize("backend", BACKENDS)
def test_out_overlapping_itself_is_refused(backend):
    f = lambdify([x], (x, 2 * x), backend)
    buf = np.zeros(4)
    with pytest.raises(ValueError, match=r"out: expected separate arrays, out\[0\] and out\[1\] "
                                         r"overlap"):
        f(np.ones(4), out=(buf, buf))


# ------------------------------------------------------ the expr protocol


class _Normal(Basic):
    """A stand-in for the core's CommonNormal: (a12, n, alpha12, foot1, foot2)."""

    def _lambdify_outputs(self):
        return tuple(self.args)


@pytest.mark.parametrize("backend", BACKENDS)
def test_objects_with_lambdify_outputs_give_a_tuple_in_order(backend):
    A, B = vector("A"), vector("B")
    obj = _Normal(A.dot(B), ImmutableMatrix(A.cross(B)), x**2, ImmutableMatrix(A * x),
                  ImmutableMatrix(B - A))
    f = lambdify([A, B, x], obj, backend, names=["A", "B", "x"])
    a, b = np.array([1.0, 2, 3]), np.array([0.0, 1, 0])
    got = f(a, b, 3.0)
    assert isinstance(got, tuple) and len(got) == 5
    np.testing.assert_allclose(got[0], 2.0)
    np.testing.assert_allclose(got[1], np.cross(a, b))
    np.testing.assert_allclose(got[2], 9.0)
    np.testing.assert_allclose(got[3], 3 * a)
    np.testing.assert_allclose(got[4], b - a)
    batch = f(np.tile(a, (4, 1)), b, np.arange(4.0))
    assert [g.shape for g in batch] == [(4,), (4, 3), (4,), (4, 3), (4, 3)]


def test_lambdify_outputs_must_be_a_tuple():
    class Bad(Basic):
        def _lambdify_outputs(self):
            return [x]

    with pytest.raises(TypeError, match=r"_lambdify_outputs\(\) must return a tuple or a matrix, got list"):
        lambdify([x], Bad())


# ------------------------------------------------------------- caches


def test_one_build_per_signature_across_threads(monkeypatch):
    builds = []
    real = _build.BUILDERS["numpy"]

    def counting(*a):
        builds.append(1)
        return real(*a)

    monkeypatch.setitem(_build.BUILDERS, "numpy", counting)
    expr = x**7 + y * 13 - x * y / 11  # not built anywhere else
    barrier = threading.Barrier(8)
    got = []

    def worker():
        barrier.wait()
        got.append(lambdify([x, y], expr, "numpy"))

    threads = [threading.Thread(target=worker) for _ in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(builds) == 1 and len({id(g) for g in got}) == 1


def test_memory_cache_is_bounded(monkeypatch):
    monkeypatch.setattr(_build, "CACHE_SIZE", 3)
    fns = [lambdify([x], x + k + 1000, "numpy") for k in range(6)]
    assert len(_build._CACHE) <= 3
    assert fns[-1] is lambdify([x], x + 1005, "numpy")


def test_cache_dir_is_private(tmp_path, monkeypatch):
    target = tmp_path / "cache"
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(target))
    assert _build.cache_dir() == target
    assert stat.S_IMODE(target.stat().st_mode) == 0o700
    # a directory others can write is not used
    target.chmod(0o777)
    assert _build.cache_dir() is None
    # nor a file
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(tmp_path / "file"))
    (tmp_path / "file").write_text("")
    assert _build.cache_dir() is None


@pytest.mark.skipif(not HAS_CC, reason="no C compiler")
def test_c_build_leaves_no_temporary_directory(tmp_path, monkeypatch):
    # a private temporary directory: another test's build (xdist) cannot show up here
    private = tmp_path / "tmp"
    private.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(private))

    def leftovers():
        return {p for p in os.listdir(tempfile.gettempdir()) if p.startswith("screwsym-c-")}

    before = leftovers()
    # with a cache directory: the library is kept there, content-addressed
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(tmp_path / "cache"))
    f = lambdify([x], x**3 + 17.5, "c")
    assert f(2.0) == 25.5 and np.array_equal(f(np.array([1.0, 2.0])), [18.5, 25.5])
    # the library and its Python wrapper (read back without CSE nor printing in a new process)
    # and its description for a new process (unpickling, codegen.generated)
    assert sorted(p.suffix for p in (tmp_path / "cache" / "c").iterdir()) == [".json", ".py", ".so"]
    # without a usable one: a temporary directory, removed after loading
    (tmp_path / "file").write_text("")
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(tmp_path / "file"))
    g = lambdify([x], x**3 + 18.5, "c")
    assert np.array_equal(g(np.array([1.0, 2.0])), [19.5, 26.5])
    assert leftovers() == before


@pytest.mark.slow
@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_numba_disk_cache_serves_a_new_process(tmp_path):
    script = textwrap.dedent("""
        import sys
        import numpy as np
        from sympy import symbols
        from screwsym import lambdify
        x, y = symbols("x y", real=True)
        f = lambdify([x, y], x**3 - y / (x + 2), "numba")
        assert f(1.0, 3.0) == 0.0 and "numba" not in sys.modules  # a point needs no loop
        k = f.load_kernel
        print(f(np.arange(4.0), 1.0).tolist(), sum(k().stats.cache_hits.values()),
              sum(k().stats.cache_misses.values()))
    """)
    env = dict(os.environ, SCREWSYM_CACHE_DIR=str(tmp_path))
    root = Path(__file__).resolve().parents[2]
    runs = [subprocess.run([sys.executable, "-c", script], env=env, cwd=root, check=True,
                           capture_output=True, text=True).stdout.split("]") for _ in range(2)]
    assert runs[0][0] == runs[1][0] == "[-0.5, 0.6666666666666667, 7.75, 26.8"
    assert runs[0][1].split() == ["0", "1"]  # compiled once ...
    assert runs[1][1].split() == ["1", "0"]  # ... and loaded from disk by the next process


def test_pitch_is_still_a_screw_function():
    s = Screw(vector("S"), vector("S0"))
    assert lambdify([s], pitch(s), "numpy")(np.array([1.0, 0, 0, 2, 0, 0])) == 2.0


def test_the_cores_common_normal_lambdifies_to_its_five_parts():
    from screwsym import LineVector, common_normal

    h = symbols("h", real=True)
    cn = common_normal(LineVector.from_axis([0, 0, 0], [1, 0, 0]),
                       LineVector.from_axis([0, 0, h], [0, 1, 1]))
    a12, normal, alpha12, foot1, foot2 = lambdify([h], cn, "numpy")(np.array([2.0, -1.0]))
    np.testing.assert_allclose(a12, [np.sqrt(2), np.sqrt(2) / 2])
    np.testing.assert_allclose(normal[0], [0, -np.sqrt(0.5), np.sqrt(0.5)])
    np.testing.assert_allclose(alpha12, np.pi / 2 * np.sign([2.0, -1.0]))
    np.testing.assert_array_equal(foot1, np.zeros((2, 3)))
    np.testing.assert_allclose(foot2, [[0, -1, 1], [0, 0.5, -0.5]])


@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_numba_without_a_usable_cache_directory_compiles_in_memory(tmp_path, monkeypatch):
    (tmp_path / "file").write_text("")
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(tmp_path / "file"))
    f = lambdify([x, y], Min(x, y) * 3 + 0.25, "numba")  # not built elsewhere
    assert f(np.array([1.0, 5.0]), 2.0).tolist() == [3.25, 6.25]
    kernel = f.load_kernel()
    assert f(np.array([4.0]), 2.0).tolist() == [6.25] and f.load_kernel() is kernel
    source = "".join(linecache.getlines(f.__code__.co_filename))
    assert "cache=False" in source and "cache=True" not in source
    assert list(tmp_path.iterdir()) == [tmp_path / "file"]


@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_disk_cache_is_bounded(tmp_path, monkeypatch):
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(_build, "DISK_FILES", 2)
    fns = [lambdify([x], x * 3 + k + 2000, "numba") for k in range(4)]  # written, not compiled
    assert len(list((tmp_path / "numba").glob("screwsym_generated_*.py"))) == 2
    assert [f(1.0) for f in fns] == [2003.0, 2004.0, 2005.0, 2006.0]  # loaded ones still run


@pytest.mark.parametrize("backend", BACKENDS)
def test_array_entry_points_check_huge_integers_and_out(backend):
    # issue 20: a Python int beyond the doubles raised a bare OverflowError; out= given a
    # tuple was accepted by a function with one (non-tuple) result
    f = lambdify([x, y], 3 * x - y + 0.125, backend)
    for bad in (10**400, [1, -(10**400)], np.array([10**309], dtype=object)):
        with pytest.raises(ValueError, match=r"x: expected real numbers within the range of "
                                             r"doubles \(\|x\| <= 1.8e308\), got an integer of"):
            f(bad, 1.0)
    assert f(10**300, 0.0) == 3e300  # within range: fine
    with pytest.raises(ValueError, match=r"out: expected one array \(the function has one "
                                         r"result, not a tuple\), got a tuple of 1"):
        f(np.ones(2), np.ones(2), out=(np.empty(2),))
    g = lambdify([x, y], (3 * x - y + 0.125,), backend)  # a tuple of one: a tuple of one
    out = (np.empty(2),)
    g(np.ones(2), np.ones(2), out=out)
    assert out[0].tolist() == [2.125] * 2


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_constant_beyond_the_doubles_is_refused_by_name(backend):
    # issue 33: x/10**400 gave a bare OverflowError naming nothing; its nearest double is 0,
    # so generated code would give 0 where x = 1e300 makes the result 1e-100
    from sympy import Float, Rational

    for expr, held in [(x / 10**400, "0"), (x * 10**400, "inf"), (x + 10**309, "inf"),
                       (x * Float("1e400"), "inf"), (y * Rational(1, 3 * 10**330), "0"),
                       (x * y ** Rational(1, 10**400), "0")]:
        with pytest.raises(ValueError, match=r"expr: the constant (\S+E[+-]\d+ \(written in \d+ "
                                             rf"characters\)|\S+) is out of the range of float64 "
                                             rf".*would hold {held} for it"):
            lambdify([x, y], expr, backend)
    # a rational whose numerator and denominator are beyond the doubles, its value not: the
    # correctly rounded quotient (printing p/q as doubles gave inf/inf = nan)
    f = lambdify([x, y], x * Rational(10**400 + 1, 10**400) + y * Rational(2**60 + 1, 3),
                 backend)
    assert f(2.0, 0.0) == 2.0 and f(0.0, 3.0) == float(2**60 + 1)
    assert f(np.array([2.0]), np.array([0.0])).tolist() == [2.0]
    # the smallest doubles are constants like any other (subnormal: the nearest double)
    assert lambdify([x], x * Rational(1, 10**310), backend)(2.0) == 2e-310
