"""The disk cache loads only what this user wrote and what its name says (issue 20).

A planted module in a symlinked or world-writable ``numba/`` subfolder, or in a
folder of another user, is never run; a tampered module or library is refused
(its content no longer matches the digest in its name) and rebuilt; a cache that
cannot be written builds in memory, with no ``PermissionError``.
"""

from __future__ import annotations

import os
import sys
import types

import numpy as np
import pytest
from _backends import HAS_CC, HAS_NUMBA
from sympy import symbols

from screwsym import lambdify
from screwsym.codegen import _build

x = symbols("x", real=True)
TRACE = types.ModuleType("cache_trace")
PLANT = b"__import__('sys').modules['cache_trace'].__setattr__('ran', 1)\n"
AS_ROOT = hasattr(os, "getuid") and os.getuid() == 0


@pytest.fixture(autouse=True)
def _isolated(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "cache_trace", TRACE)
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(tmp_path / "cache"))
    TRACE.__dict__.pop("ran", None)
    _build.clear_cache()
    yield
    _build.clear_cache()


def _ran() -> bool:
    return TRACE.__dict__.pop("ran", None) is not None


def _forget(f) -> None:
    """Make the next lambdify of the same expression look in the disk cache again."""
    _build.clear_cache()
    sys.modules.pop(f"screwsym_generated_{f._screwsym_meta['key']}", None)


def _plant(folder, key) -> None:
    """A module under the right name, with the digest of its own (hostile) content."""
    stem = f"screwsym_generated_{key}"
    (folder / f"{stem}-{_build._digest(PLANT)}.py").write_bytes(PLANT)


def _key(expr) -> str:
    f = lambdify([x], expr, "numba")
    _forget(f)
    return f._screwsym_meta["key"]


@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_a_planted_module_with_the_right_name_and_digest_runs_in_a_private_cache(tmp_path):
    # the checker below is shown to see a planted module when the folder is ours alone
    expr = 7 * x + 3000.25
    key = _key(expr)
    numba = tmp_path / "cache" / "numba"
    for old in numba.glob(f"screwsym_generated_{key}-*.py"):
        old.unlink()
    _plant(numba, key)
    with pytest.raises(AttributeError):  # the planted module has no _fn
        lambdify([x], expr, "numba")
    assert _ran()


@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
@pytest.mark.parametrize("how", ["symlink", "world-writable", "group-writable", "other owner"])
def test_a_planted_module_in_an_unsafe_subfolder_never_runs(tmp_path, how):
    n = ["symlink", "world-writable", "group-writable", "other owner"].index(how)
    expr = 7 * x + 3001.25 + 100 * n  # one module per case: sys.modules keeps what ran
    key = _key(expr)
    cache, numba = tmp_path / "cache", tmp_path / "cache" / "numba"
    for old in numba.iterdir():
        old.unlink()
    if how == "symlink":
        elsewhere = tmp_path / "elsewhere"
        elsewhere.mkdir(mode=0o700)
        numba.rmdir()
        numba.symlink_to(elsewhere)
        _plant(elsewhere, key)
    elif how == "other owner":
        if not AS_ROOT:
            pytest.skip("needs root to give the folder to another user")
        _plant(numba, key)
        os.chown(numba, 12345, -1)
    else:
        _plant(numba, key)
        numba.chmod(0o777 if how == "world-writable" else 0o770)
    assert cache.stat().st_mode & 0o777 == 0o700
    f = lambdify([x], expr, "numba")
    assert f(2.0) == 3015.25 + 100 * n and not _ran()
    assert "cache=False" in "".join(__import__("linecache").getlines(f.__code__.co_filename))


@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_a_tampered_module_is_refused_and_rebuilt(tmp_path):
    expr = 7 * x + 3002.25
    f = lambdify([x], expr, "numba")
    (path,) = (tmp_path / "cache" / "numba").glob(f"screwsym_generated_{f._screwsym_meta['key']}-*")
    path.write_bytes(path.read_bytes() + PLANT)  # same name, other content
    _forget(f)
    g = lambdify([x], expr, "numba")
    assert g(2.0) == 3016.25 and not _ran()
    (again,) = (tmp_path / "cache" / "numba").glob(f"screwsym_generated_{f._screwsym_meta['key']}-*")
    assert PLANT not in again.read_bytes()


@pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")
def test_an_index_whose_module_was_tampered_loads_nothing(tmp_path):
    f = lambdify([x], 7 * x + 3003.25, "numba")
    _build.save_index("t20", f)
    assert _build.load_index("t20", "doc") is not None
    (path,) = (tmp_path / "cache" / "numba").glob(f"screwsym_generated_{f._screwsym_meta['key']}-*")
    path.write_bytes(PLANT)
    _forget(f)
    assert _build.load_index("t20", "doc") is None and not _ran()


@pytest.mark.skipif(not HAS_CC, reason="no C compiler")
def test_a_tampered_library_is_refused_and_rebuilt(tmp_path):
    c = tmp_path / "cache" / "c"
    f = lambdify([x], 5 * x + 1.5, "c")
    (mine,) = c.glob("*.so")
    g = lambdify([x], 5 * x - 99.0, "c")  # another library of the same signature
    (other,) = set(c.glob("*.so")) - {mine}
    stem = mine.name.rpartition("-")[0]
    assert _build.find_artifact(c, stem, ".so") == (mine, mine.read_bytes())
    planted = other.read_bytes()
    mine.unlink()  # a new file under f's name, with g's code (f's stays mapped)
    mine.write_bytes(planted)
    assert _build.find_artifact(c, stem, ".so") is None and not mine.exists()
    _build.clear_cache()
    h = lambdify([x], 5 * x + 1.5, "c")  # rebuilt
    assert np.array_equal(h(np.array([1.0, 2.0])), [6.5, 11.5]) and g(2.0) == -89.0
    path, data = _build.find_artifact(c, stem, ".so")
    assert path == mine and data != planted and f(2.0) == 11.5


@pytest.mark.parametrize("backend", ["numba", "c"])
def test_a_cache_that_cannot_be_written_builds_in_memory(tmp_path, monkeypatch, backend):
    if backend == "numba" and not HAS_NUMBA or backend == "c" and not HAS_CC:
        pytest.skip(f"{backend} not available")
    cache = tmp_path / "cache"
    cache.mkdir(mode=0o700)
    (cache / backend).mkdir(mode=0o700)

    def read_only(path, data):
        raise PermissionError(13, "Read-only file system", str(path))

    # a read-only file system: every write fails (root ignores a folder's mode bits)
    monkeypatch.setattr(_build, "_write_atomic", read_only)
    f = lambdify([x], 9 * x + 4004.5, backend)
    assert f(1.0) == 4013.5  # a point: numba itself is not compiled (seconds)
    if backend == "c":
        assert np.array_equal(f(np.array([0.0, 1.0])), [4004.5, 4013.5])
    assert list((cache / backend).iterdir()) == []


@pytest.mark.skipif(AS_ROOT, reason="root writes into read-only folders")
def test_a_read_only_cache_root_is_not_used(tmp_path):
    cache = tmp_path / "cache"
    cache.mkdir(mode=0o500)
    try:
        assert _build.cache_dir() is None
        f = lambdify([x], 9 * x + 4005.5, "numpy")
        assert f(1.0) == 4014.5
    finally:
        cache.chmod(0o700)
