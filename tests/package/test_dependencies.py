"""The dependency floor that pyproject declares is the one CI tests.

``.ci/run`` ends with a run of the whole suite in a fresh environment holding
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
