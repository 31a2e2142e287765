"""The typing promise: mypy passes on screwsym, and typed use of it checks.

``py.typed`` ships, so users' type checkers read screwsym's annotations.  One
mypy run (the configuration in pyproject.toml, a fresh cache) checks the
package and ``typing_usage.py`` beside this file, whose refusals must stay
refusals (it warns of unused ignores); the usage is then run, so its
annotations are also true of the values.  CI runs ``python -m mypy screwsym``
as well (.ci/run).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

import screwsym

ROOT = Path(screwsym.__file__).parent.parent
USAGE = Path(__file__).with_name("typing_usage.py")


def test_py_typed_ships():
    assert (ROOT / "screwsym" / "py.typed").is_file()


@pytest.mark.slow
def test_mypy_passes_on_the_package_and_the_typed_usage(tmp_path, monkeypatch):
    api = pytest.importorskip("mypy.api")
    monkeypatch.chdir(ROOT)  # the package checked is this checkout's, not an installed one
    stdout, stderr, status = api.run([
        "--config-file", str(ROOT / "pyproject.toml"),
        "--cache-dir", str(tmp_path / "mypy_cache"),
        "screwsym", str(USAGE),
    ])
    assert status == 0, stdout + stderr


def test_the_typed_usage_runs():
    spec = importlib.util.spec_from_file_location("typing_usage", USAGE)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.usage()
