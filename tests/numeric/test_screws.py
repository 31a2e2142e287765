"""Tests for screwsym.numeric.screws: generated functions agree with the symbolic core; their cache."""

from __future__ import annotations

import hashlib
import inspect
import json
import os
import random
import shutil
import subprocess
import sys
import textwrap
import warnings
from pathlib import Path

import numpy as np
import pytest
import sympy
from _backends import BACKENDS, HAS_NUMBA
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from sympy import Rational, sqrt, symbols

import screwsym
from screwsym import LineVector, Screw, Twist, Wrench, codegen, numeric
from screwsym.codegen import compiler
from screwsym.numeric.screws import DEFINITIONS, Definitions, numeric_definition


def rationals(rng: random.Random, n: int) -> list[Rational]:
    return [Rational(rng.randint(-40, 40), rng.randint(1, 11)) for _ in range(n)]


def floats(values) -> np.ndarray:
    return np.array([float(v) for v in values])


def as_array(x) -> np.ndarray:
    """An exact SymPy result (number, matrix or screw) as a float array."""
    if isinstance(x, Screw):
        x = x.matrix
    if hasattr(x, "is_Matrix") and x.is_Matrix:
        return floats(x)
    return np.float64(float(x))


# name -> (kinds of the arguments, the symbolic operation of the core)
CASES = {
    "pitch": (("screw",), lambda s: screwsym.pitch(Screw(s[:3], s[3:]))),
    "foot": (("screw",), lambda s: screwsym.foot(Screw(s[:3], s[3:]))),
    "reciprocal_product": (
        ("screw", "screw"),
        lambda a, b: screwsym.reciprocal_product(Screw(a[:3], a[3:]), Screw(b[:3], b[3:])),
    ),
    "shift_origin": (
        ("screw", "point"),
        lambda s, A: screwsym.shift_origin(Screw(s[:3], s[3:]), A),
    ),
    "line_through": (("point", "point"), lambda A, B: LineVector.through(A, B)),
    "velocity_at": (("screw", "point"), lambda t, P: Twist(t[:3], t[3:]).velocity_at(P)),
    "moment_about": (("screw", "point"), lambda w, P: Wrench(w[:3], w[3:]).moment_about(P)),
}


def assert_close(got, want, rtol=1e-12):
    got, want = np.asarray(got, float), np.asarray(want, float)
    assert got.shape == want.shape, (got.shape, want.shape)
    scale = max(np.max(np.abs(want)), 1e-300)
    assert np.max(np.abs(got - want)) <= rtol * scale, (got, want)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("name", list(CASES))
def test_agrees_with_the_symbolic_core(name, backend):
    fn = getattr(numeric.functions_for(backend), name)
    kinds, exact = CASES[name]
    rng = random.Random(sum(map(ord, name)))
    n = 8
    points = [[rationals(rng, 6 if k == "screw" else 3) for k in kinds] for _ in range(n)]
    wants = [as_array(exact(*p)) for p in points]
    for p, want in zip(points, wants, strict=True):
        assert_close(fn(*[floats(v) for v in p]), want)
    batched = [np.stack([floats(p[i]) for p in points]).reshape((2, 4, -1)) for i in range(len(kinds))]
    got = fn(*batched)
    assert_close(got.reshape((n,) + got.shape[2:]), np.stack(wants))


def test_module_functions_are_the_default_back_end_and_generated():
    # lambdify compiles by default when numba is installed (the issue's "fast by default");
    # the numeric functions use numba once numba is imported, so that a first call pays no
    # numba import (issue 23 item 4),
    assert codegen.default_backend() == ("numba" if HAS_NUMBA else "numpy")
    # else C where a compiler is (compiled loops at memory speed, issue 34 item 4)
    default = ("numba" if HAS_NUMBA and "numba" in sys.modules
               else "c" if compiler() is not None else "numpy")
    assert numeric.screws.default_backend() == default
    assert numeric.pitch is numeric.functions_for().pitch is numeric.functions_for(default).pitch
    assert numeric.pitch is not numeric.functions_for("numpy").pitch or default == "numpy"
    assert set(numeric.NAMES) <= set(dir(numeric))
    for name in numeric.NAMES:
        fn = getattr(numeric, name)
        assert fn.__name__ == name
        source = inspect.getsource(fn)
        assert source.startswith("def _fn(")
        assert "_prepare(_SPECS" in source
        assert fn.__doc__ and "Generated from" in fn.__doc__
    with pytest.raises(AttributeError, match="has no attribute 'nope'"):
        numeric.nope  # noqa: B018


@pytest.mark.parametrize("backend", BACKENDS)
def test_out_may_be_an_input(backend):
    # issue 9: numeric.velocity_at(tw, q, out=q) gave wrong numbers in the NumPy back end
    f = numeric.functions_for(backend)
    rng = np.random.default_rng(9)
    tw, q = rng.standard_normal((40000, 6)), rng.standard_normal((40000, 3))
    want = f.velocity_at(tw, q)
    got = f.velocity_at(tw, q, out=q)
    assert got is not None and np.shares_memory(got, q)
    np.testing.assert_array_equal(q, want)
    s, A = rng.standard_normal((5, 6)), rng.standard_normal((5, 3))
    want = f.shift_origin(s, A)
    f.shift_origin(s, A, out=s)
    np.testing.assert_array_equal(s, want)


def test_broadcasting_one_screw_against_many_points():
    s = np.array([0.0, 0, 1, 0, 0, 0])
    points = np.arange(12.0).reshape(4, 3)
    v = numeric.velocity_at(s, points)
    assert v.shape == (4, 3)
    np.testing.assert_allclose(v, np.cross(s[:3], points))
    shifted = numeric.shift_origin(s[None, :], points[:, None, :])
    assert shifted.shape == (4, 1, 6)


def test_pitch_of_a_couple_is_inf_and_of_the_zero_screw_nan():
    # the symbolic pitch of a couple is oo; of the zero screw it raises
    assert screwsym.pitch(Screw.couple([0, 0, 5])) == screwsym.pitch(Screw.couple([1, 0, 0]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no RuntimeWarning either
        assert numeric.pitch(np.array([0.0, 0, 0, 0, 0, 5])) == np.inf
        assert np.isnan(numeric.pitch(np.zeros(6)))
        batch = numeric.pitch(np.array([[0.0, 0, 0, 0, 0, 5], [0, 0, 0, 0, 0, 0], [1, 0, 0, 3, 0, 0]]))
    assert batch[0] == np.inf and np.isnan(batch[1]) and batch[2] == 3.0


@pytest.mark.parametrize("backend", BACKENDS)
def test_non_finite_results_are_the_documented_ones_in_every_back_end(backend):
    f = numeric.functions_for(backend)
    couples = np.array([[0.0, 0, 0, 0, 0, 5], [0, 0, 0, 0, 0, 0], [0, 0, 2, 1, 0, 0]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        h = f.pitch(couples)
        P = f.foot(couples)
    assert h[0] == np.inf and np.isnan(h[1]) and h[2] == 0.0
    assert np.isnan(P[:2]).all() and np.isfinite(P[2]).all()
    # the symbolic foot point of a couple raises
    with pytest.raises(ValueError, match="couple"):
        screwsym.foot(Screw.couple([0, 0, 5]))
    # line through a point and itself: the zero screw
    np.testing.assert_array_equal(f.line_through(np.ones(3), np.ones(3)), np.zeros(6))


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match=r"s: expected an array of shape \(\.\.\., 6\) for a screw "
                       r"\(S; S0\), got shape \(3,\)"):
        numeric.pitch(np.zeros(3))
    with pytest.raises(ValueError, match=r"point: expected an array of shape \(\.\.\., 3\) for a "
                       r"3-vector, got shape \(2, 6\)"):
        numeric.velocity_at(np.zeros(6), np.zeros((2, 6)))
    with pytest.raises(ValueError, match=r"s1, s2: expected batch \(leading\) shapes that broadcast "
                       r"together, got s1 has batch shape \(2,\), s2 has batch shape \(3,\)"):
        numeric.reciprocal_product(np.zeros((2, 6)), np.zeros((3, 6)))
    with pytest.raises(TypeError, match=r"A: expected real numbers, got dtype complex128"):
        numeric.line_through(np.zeros(3, complex), np.ones(3))
    with pytest.raises(TypeError, match=r"wrench: expected an array of real numbers, got dtype"):
        numeric.moment_about(np.zeros(6, bool), np.zeros(3))
    # a numeric Screw is read through np.asarray in ray order; a symbolic one is refused
    assert numeric.pitch(Screw([1, 1, 0], [1, 0, 0])) == 0.5
    x = symbols("x", real=True)
    with pytest.raises(TypeError, match=r"s: expected an array of real numbers, got Screw holding objects"):
        numeric.pitch(Screw([x, 0, 0], [0, 0, 0]))


def test_one_definition_per_function_in_the_order_of_names():
    # issue 31 item 6: NAMES, the docstrings and the definitions are one registry
    assert tuple(DEFINITIONS) == numeric.NAMES == numeric.screws.NAMES == (
        "pitch", "foot", "reciprocal_product", "shift_origin", "line_through", "velocity_at",
        "moment_about")
    assert numeric.screws.__all__ == [*numeric.NAMES, "functions_for", "NAMES"]
    for backend in ("numpy", None):
        functions = numeric.functions_for(backend)
        for name, definition in DEFINITIONS.items():
            fn = getattr(functions, name)
            assert definition.name == name and definition.make.__name__ == f"_{name}"
            assert fn.__doc__ == definition.doc == definition.make.__doc__
            assert numeric.screws.__test__[name] == definition.doc  # its doctests run
            _, _, names = definition.build()
            assert list(inspect.signature(fn).parameters) == [*names, "out"]
    assert numeric.moment_about.__doc__ == DEFINITIONS["moment_about"].doc


def test_the_registry_refuses_a_name_twice_and_other_wrong_definitions():
    registry = Definitions()
    x = symbols("x", real=True)

    @registry.register
    def _half():
        "Half of ``x``."
        return {"x": x}, x / 2

    def _half_again():
        "Half of ``x``, again."
        return {"x": x}, x / 2

    _half_again.__name__ = "_half"
    with pytest.raises(ValueError, match="_half: a function 'half' is defined already"):
        registry.register(_half_again)
    assert list(registry) == ["half"] and registry["half"].doc == "Half of ``x``."
    assert registry["half"].build() == ([x], x / 2, ["x"])

    def half():
        "No underscore: the module attribute would hide the generated function."

    def _undocumented():
        return {"x": x}, x

    with pytest.raises(ValueError, match="half: expected the name '_' "):
        registry.register(half)
    with pytest.raises(ValueError, match="_undocumented: expected a docstring"):
        registry.register(_undocumented)
    registry.close()
    with pytest.raises(ValueError, match="the registry is closed"):
        registry.register(_half_again)
    assert list(registry) == ["half"]
    # the module's registry is closed: NAMES cannot fall behind it
    with pytest.raises(ValueError, match="the registry is closed"):
        numeric_definition(_half_again)
    assert tuple(DEFINITIONS) == numeric.NAMES


def test_symbolic_and_numeric_share_the_formula():
    # the module builds its functions from the core at import: check one of
    # them against a hand derivation to be sure the wiring is (S; S0) order
    s = np.array([1.0, 2, 3, 4, 5, 6])
    assert numeric.pitch(s) == pytest.approx((4 + 10 + 18) / 14)
    np.testing.assert_allclose(numeric.foot(s), np.cross(s[:3], s[3:]) / 14)


@pytest.mark.slow
@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_a_new_process_loads_the_compiled_functions_without_rebuilding_them(tmp_path):
    script = textwrap.dedent("""
        import sys
        import numpy as np
        from screwsym import numeric
        if sys.argv[1] == "second":
            def boom(definition):
                raise AssertionError("rebuilt " + definition.name)
            numeric.screws.Definition.build = boom
        print(numeric.pitch(np.array([1.0, 1, 0, 1, 0, 0])), numeric.foot(np.ones((2, 6)))[1, 1],
              "numba" in sys.modules)  # a first call pays no numba import (issue 23 item 4)
    """)
    env = dict(os.environ, SCREWSYM_CACHE_DIR=str(tmp_path))
    root = Path(__file__).resolve().parents[2]

    def run(mode):
        return subprocess.run([sys.executable, "-c", script, mode], env=env, cwd=root,
                              capture_output=True, text=True)

    first = run("first")
    assert first.returncode == 0, first.stderr
    second = run("second")
    assert second.returncode == 0, second.stderr
    assert first.stdout == second.stdout == "0.5 0.0 False\n"
    # an unreadable index is ignored: the function is built again
    indexes = list(tmp_path.glob("*/index-pitch-*.json"))
    # numba is not imported there: the default is C (a compiler found), else NumPy
    assert [p.parent.name for p in indexes] == ["c" if compiler() else "numpy"]
    for index in indexes:
        index.write_text('{"key": "../../evil"}')
    third = run("second")
    assert third.returncode != 0 and "rebuilt pitch" in third.stderr


# --------------------------------------------------------------- the cache cannot go stale
#: A fresh process on a copy of the package: which functions it built (rather than loaded
#: from the numba index), the digest that tags the index, and the pitch of Example 1.4.
_PROBE = textwrap.dedent("""
    import json, sys
    import numpy as np
    from screwsym import numeric
    from screwsym import codegen
    from screwsym.numeric.screws import Definition
    built, build = [], Definition.build
    def spy(definition):
        built.append(definition.name)
        return build(definition)
    Definition.build = spy
    h = float(numeric.pitch(np.array([1.0, 1, 0, 1, 0, 0]))) if sys.argv[1] == "pitch" else None
    print(json.dumps({"file": numeric.screws.__file__, "tag": codegen.code_digest(),
                      "built": built, "pitch": h}))
""")

#: An edited formula in a subfolder of the package: core/screw.py's pitch, doubled.
_EDIT = """

_book_pitch = pitch


def pitch(s, **kwargs):  # an edited formula: twice the book's pitch
    return 2 * _book_pitch(s, **kwargs)
"""


def _copy_package(dest: Path) -> Path:
    package = dest / "screwsym"
    shutil.copytree(Path(screwsym.__file__).parent, package,
                    ignore=shutil.ignore_patterns("__pycache__"))
    return package


def _probe(package: Path, cache: Path, what: str = "tag") -> dict:
    env = dict(os.environ, SCREWSYM_CACHE_DIR=str(cache), PYTHONPATH=str(package.parent))
    out = subprocess.run([sys.executable, "-c", _PROBE, what], env=env, cwd=package.parent,
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    result = json.loads(out.stdout.splitlines()[-1])
    assert Path(result["file"]).resolve().parent.parent == package.resolve()  # the copy ran
    return result


def old_digest(package: Path) -> str:
    """The rule before 0.2.0: the top-level modules and codegen's, keyed by file name."""
    h = hashlib.sha256(sympy.__version__.encode())
    for path in sorted([*package.glob("*.py"), *package.glob("codegen/*.py")]):
        h.update(path.name.encode() + b"\0" + path.read_bytes())
    return h.hexdigest()[:24]


@pytest.mark.slow
def test_the_digest_sees_every_file_by_its_path(tmp_path):
    a, b = _copy_package(tmp_path / "a"), _copy_package(tmp_path / "b")
    cache = tmp_path / "cache"
    tag = _probe(a, cache)["tag"]
    assert _probe(b, cache)["tag"] == tag  # the same source elsewhere: the same tag
    # an edited formula in a subpackage changes the tag; the old rule did not see it
    with open(b / "core" / "screw.py", "a", encoding="utf-8") as f:
        f.write(_EDIT)
    assert _probe(b, cache)["tag"] != tag
    assert old_digest(b) == old_digest(a)
    # the same bytes at another path (a module moved into a new subfolder) change it too
    for package, folder in ((a, "here"), (b, "there")):
        (package / "core" / folder).mkdir()
        (package / "core" / folder / "__init__.py").write_text("")
        (package / "core" / folder / "moved.py").write_text("def f():\n    return 1\n")
    shutil.copyfile(a / "core" / "screw.py", b / "core" / "screw.py")  # undo the edit
    assert _probe(a, cache)["tag"] != _probe(b, cache)["tag"]
    assert old_digest(a) == old_digest(b)


@pytest.mark.slow
@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_an_edited_formula_is_rebuilt_not_loaded_from_the_old_index(tmp_path):
    package, cache = _copy_package(tmp_path), tmp_path / "cache"
    first = _probe(package, cache, "pitch")
    assert first["built"] == ["pitch"] and first["pitch"] == 0.5  # built, saved to the index
    # numba not imported there: the default is C (a compiler found), else NumPy
    assert list((cache / ("c" if compiler() else "numpy")).glob("index-pitch-*.json"))
    again = _probe(package, cache, "pitch")
    assert again["built"] == [] and again["pitch"] == 0.5  # the same source: loaded
    with open(package / "core" / "screw.py", "a", encoding="utf-8") as f:
        f.write(_EDIT)
    edited = _probe(package, cache, "pitch")
    # rebuilt with the edit (a stale index would give the old formula's 0.5, building nothing)
    assert (edited["built"], edited["pitch"]) == (["pitch"], 1.0)
    assert edited["tag"] != first["tag"]


# ------------------------------------------------ issue 20: scale-robust from 1e-300 to 1e300
def test_pitch_and_foot_at_extreme_scales_the_issues_examples():
    f = numeric.functions_for("numpy")
    for k in (1e-300, 1e-200, 1.0, 1e200, 1e300):
        s = np.array([1.0, 1, 0, 1, 0, 0]) * k  # pitch 1/2 and foot (0, 0, -1/2) at any scale
        assert f.pitch(s) == pytest.approx(0.5, rel=1e-15)
        np.testing.assert_allclose(f.foot(s), [0, 0, -0.5], rtol=1e-15, atol=0)
    assert f.pitch(np.array([1e-170, 0, 0, 1e-170, 0, 0])) == 1.0  # S . S underflowed: nan
    assert f.pitch(np.array([1e-170, 0, 0, 0, 0, 1e-170])) == 0.0
    # the special cases keep their meaning: a couple, the zero screw, a result beyond floats
    assert f.pitch(np.array([[0.0, 0, 0, 0, 0, 1e-300], [0.0] * 6, [1e-300, 0, 0, 1e300, 0, 0]])
                   ).tolist()[::2] == [np.inf, np.inf]
    assert np.isnan(f.pitch(np.zeros(6))) and np.isnan(f.foot(np.array([0.0, 0, 0, 1, 0, 0]))).all()
    out = np.empty(2)
    assert f.pitch(np.array([[1e-200, 0, 0, 1e-200, 0, 0]] * 2), out=out) is not None
    assert out.tolist() == [1.0, 1.0]


_component = st.integers(-9, 9)
_scale = st.integers(-300, 300)


def _assert_scale_robust(pitch, foot, s) -> None:
    """``pitch(s)`` and ``foot(s)`` against the exact (1.34) and (1.16) of the very floats given.

    The error bound of the formulas: eps times the size of their terms, ``|S0|/|S|``."""
    from sympy import Matrix

    S, S0 = Matrix([Rational(v) for v in s[:3]]), Matrix([Rational(v) for v in s[3:]])
    h, P = S.dot(S0) / S.dot(S), S.cross(S0) / S.dot(S)
    size = float(sqrt(S0.dot(S0) / S.dot(S)))
    for got, want in [(pitch(s), h), *zip(foot(s), P, strict=True)]:
        assert abs(got - float(want)) <= 8 * np.finfo(float).eps * size, (got, want)


def _scaled_screw(c, j, j0) -> np.ndarray:
    return np.array([float(Rational(v) * Rational(10) ** j) for v in c[:3]]
                    + [float(Rational(v) * Rational(10) ** j0) for v in c[3:]])


@pytest.mark.parametrize("backend", BACKENDS)
@settings(max_examples=25, deadline=None, derandomize=True)
@given(c=st.lists(_component, min_size=6, max_size=6), j=_scale, j0=_scale)
def test_property_pitch_and_foot_are_scale_robust_against_sympys_exact_values(backend, c, j, j0):
    # the parts scaled by 10^j and 10^j0 (floats from 1e-300 to 1e300); the reference is the
    # exact pitch (1.34) and foot (1.16) of the very floats given, in SymPy's rationals; every
    # back end (the kernels' guard is generated code, issue 34 item 4)
    assume(any(c[:3]))
    s = _scaled_screw(c, j, j0)
    S, S0 = [sum(Rational(v) ** 2 for v in part) for part in (s[:3], s[3:])]
    assume(1e-300 < float(sqrt(S0 / S)) < 1e300 or not any(c[3:]))
    f = numeric.functions_for(backend)
    _assert_scale_robust(f.pitch, f.foot, s)
    # batched: the same values, the rescaled elements among plain ones
    batch = np.stack([s, [1.0, 2, 3, 4, 5, 6], s])
    assert f.pitch(batch)[[0, 2]].tolist() == [f.pitch(s)] * 2
    np.testing.assert_array_equal(f.foot(batch)[[0, 2]], [f.foot(s)] * 2)


def test_the_scale_check_rejects_the_plain_formula():
    # the checker above fails the book's formulas evaluated as they stand in floats: at 1e-160
    # S . S is subnormal (a few digits left), at 1e-200 it is 0, at 1e200 it overflows
    s = Screw(screwsym.vector("S"), screwsym.vector("S0"))
    plain = screwsym.lambdify([s], (screwsym.pitch(s), screwsym.foot(s)), "numpy")
    for k in (1e-160, 1e-200, 1e200):
        x = np.array([1.0, 2, 0, 3, 0, 1]) * k
        with pytest.raises(AssertionError):
            _assert_scale_robust(lambda v: plain(v)[0], lambda v: plain(v)[1], x)
        f = numeric.functions_for("numpy")
        _assert_scale_robust(f.pitch, f.foot, x)


@pytest.mark.parametrize("backend", BACKENDS)
def test_only_the_out_of_range_elements_are_recomputed(backend, monkeypatch):
    # the kernel's guard (one branch per element) marks what it cannot compute in range with
    # nan; the wrapper rescales those rows, and only those: no pass over the array before
    f = numeric.functions_for(backend)
    raw = f.pitch.__wrapped__  # the generated kernel with its guard
    assert np.isnan(raw(np.array([1.0, 1, 0, 1, 0, 0]) * 1e-200))
    assert raw(np.array([1.0, 1, 0, 1, 0, 0])) == 0.5
    seen = []
    real = numeric.screws._rescaled

    def spy(fn, a, name):
        seen.append(a.shape)
        return real(fn, a, name)

    monkeypatch.setattr(numeric.screws, "_rescaled", spy)
    rng = np.random.default_rng(3)
    batch = rng.standard_normal((1000, 6))
    batch[[5, 500]] *= 1e-200
    batch[999] *= 1e200
    want = numeric.functions_for("numpy").pitch.__wrapped__(batch / np.array([1.0]))
    got = f.pitch(batch)
    assert seen == [(3, 6)]
    normal = np.ones(1000, bool)
    normal[[5, 500, 999]] = False
    np.testing.assert_allclose(got[normal], want[normal], rtol=1e-15)
    np.testing.assert_allclose(got[~normal], [
        numeric.functions_for("numpy").pitch(batch[k] / (1e-200 if k < 999 else 1e200))
        for k in (5, 500, 999)], rtol=1e-14)
    seen.clear()
    foot = f.foot(batch)
    assert seen == [(3, 6)] and foot.shape == (1000, 3) and np.isfinite(foot).all()
    seen.clear()
    out = np.empty(1000)
    assert f.pitch(batch, out=out) is not None and seen == [(3, 6)]
    np.testing.assert_array_equal(out, got)
    # one screw, rescaled, into a 0-d out= (its result is a copy of out: the new value)
    one, foot3 = np.empty(()), np.empty(3)
    assert f.pitch(np.array([1.0, 1, 0, 1, 0, 0]) * 1e-200, out=one) == 0.5 and one == 0.5
    f.foot(np.array([1.0, 1, 0, 1, 0, 0]) * 1e200, out=foot3)
    assert foot3.tolist() == [0.0, 0.0, -0.5]


def test_the_default_back_end_without_numba_imported(monkeypatch):
    # compiled loops at memory speed without a numba import (issue 34 item 4): C where a
    # compiler is found, NumPy without one; numba once the user has imported it
    monkeypatch.delitem(sys.modules, "numba", raising=False)
    monkeypatch.setattr(numeric.screws, "compiler", lambda: "cc")
    assert numeric.screws.default_backend() == "c"
    monkeypatch.setattr(numeric.screws, "compiler", lambda: None)
    assert numeric.screws.default_backend() == "numpy"
    if HAS_NUMBA:
        monkeypatch.setitem(sys.modules, "numba", __import__("numba"))
        assert numeric.screws.default_backend() == "numba"
