"""The dependency floor that pyproject declares is the one CI tests.

``.ci/run`` ends with a run of the default suite (the tests not marked slow) in a fresh environment holding
exactly the floors (``sympy==SYMPY_MIN``, ``numpy==NUMPY_MIN``, Python 3.10 where
available); these tests keep its pins and pyproject's ``dependencies`` equal, so
that raising or lowering one without the other fails.
"""

import re
from importlib.metadata import version
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def release(v: str) -> tuple[int, ...]:
    """``"1.13"`` and ``"1.13.0"`` are the same release: ``(1, 13, 0)``."""
    parts = [int(p) for p in re.match(r"\d+(?:\.\d+)*", v).group(0).split(".")]
    return tuple(parts + [0] * (3 - len(parts)))


def floors() -> dict[str, str]:
    """``{name: minimum}`` from pyproject's ``dependencies``."""
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    deps = re.search(r"^dependencies = \[(.*?)\]", text, re.M | re.S).group(1)
    specs = re.findall(r'"([^"]+)"', deps)
    found = dict(re.fullmatch(r"([A-Za-z0-9_.-]+)>=([\d.]+)", s).groups() for s in specs)
    assert len(found) == len(specs), f"every dependency has a floor (name>=version): {specs}"
    return found


def ci_pins() -> dict[str, str]:
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    pins = dict(re.findall(r"^([A-Z]+)_MIN=([\d.]+)$", ci, re.M))
    for name in pins:
        assert f'"{name.lower()}==${name}_MIN"' in ci, f"{name}_MIN is set but not installed"
    return {name.lower(): v for name, v in pins.items()}


def test_the_minimum_versions_run_pins_pyprojects_floors():
    pins, declared = ci_pins(), floors()
    assert sorted(pins) == sorted(declared) == ["numpy", "sympy"]
    assert {n: release(v) for n, v in pins.items()} == {n: release(v) for n, v in declared.items()}


def test_the_installed_versions_meet_the_floors():
    for name, floor in floors().items():
        assert release(version(name)) >= release(floor), (name, version(name), floor)


def test_release_reads_versions():
    assert release("1.13") == release("1.13.0") == (1, 13, 0)
    assert release("2.0.0rc1") == (2, 0, 0) and release("1.9") < release("1.13")


# --- the test extra holds what the default run imports -----------------------------------

def _extra(name: str) -> list[str]:
    """The requirement names of pyproject's optional extra ``name``."""
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    body = re.search(rf"^{name} = \[(.*?)^\]", text, re.M | re.S).group(1)
    return [re.match(r"[A-Za-z0-9_.-]+", s).group(0)
            for s in re.findall(r'^\s*"([^"]+)"', body, re.M)]


def _norm(dist: str) -> str:
    return re.sub(r"[-_.]+", "-", dist).lower()


def _skipped_imports() -> set[str]:
    """Top-level modules the tests skip without (``pytest.importorskip`` of a module)."""
    found = set()
    for path in (ROOT / "tests").rglob("*.py"):
        for name in re.findall(r"importorskip\(\s*\"([A-Za-z0-9_.]+)\"",
                               path.read_text(encoding="utf-8")):
            found.add(name.split(".")[0])
    return found


def _closure(names: list[str]) -> set[str]:
    """The distributions ``names`` bring, with what they require, as installed here."""
    from importlib.metadata import PackageNotFoundError, requires

    seen: set[str] = set()
    todo = [_norm(n) for n in names]
    while todo:
        dist = todo.pop()
        if dist in seen:
            continue
        seen.add(dist)
        try:
            reqs = requires(dist) or []
        except PackageNotFoundError:
            continue
        for r in reqs:
            if "extra ==" in r:
                continue
            todo.append(_norm(re.match(r"[A-Za-z0-9_.-]+", r).group(0)))
    return seen


# modules the extra brings only on some Pythons (a marker in pyproject): absent is no defect
_MARKER_GATED = {"pinocchio"}


def _extra_installed(extra: list[str]) -> bool:
    from importlib.metadata import PackageNotFoundError, version

    try:
        for dist in extra:
            version(dist)
    except PackageNotFoundError:
        return False
    return True


def missing_from_extra(modules: set[str], extra: list[str]) -> set[str]:
    """The modules among ``modules`` that the extra does not bring: not installed at all (in an
    environment holding the extra), or installed by a distribution outside what it requires."""
    from importlib.metadata import packages_distributions
    from importlib.util import find_spec

    owners = packages_distributions()
    brought = _closure(extra)
    return {m for m in modules
            if (m not in owners and m not in _MARKER_GATED and find_spec(m) is None)
            or (m in owners and not any(_norm(d) in brought for d in owners[m]))}


def test_the_test_extra_brings_every_module_a_test_skips_without():
    # `pip install -e ".[test]" && python -m pytest` (the README's command) must run every
    # default test: an optional module a test skips without belongs in the extra (or in what
    # the extra requires), checked on the installed distributions' metadata
    import pytest

    modules = _skipped_imports()
    assert {"matplotlib", "pinocchio", "sphinx"} <= modules
    extra = _extra("test")
    if not _extra_installed([d for d in extra if d != "pin"]):
        pytest.skip("the test extra is not installed here (the dependency floor's environment)")
    assert missing_from_extra(modules, extra) == set()


def test_a_module_left_out_of_the_extra_is_found():
    # the check above can fail: a module the extra's distributions do not bring, installed or
    # not, is found
    import pytest

    if not _closure(["numba"]) - {"numba"}:
        pytest.skip("numba is not installed here")
    extra = [d for d in _extra("test") if _norm(d) != "numba"]
    found = missing_from_extra({"numba", "numpy", "not_a_module_of_any_extra"}, extra)
    assert found == {"numba", "not_a_module_of_any_extra"}
    assert missing_from_extra({"numba", "numpy"}, _extra("test")) == set()
