"""The tests marked ``slow`` run only with ``--slow``; the doctests of an optional floor are skipped where its extra is not installed.

``testpaths`` collects the doctests of every module of ``screwsym``; those of
``screwsym.plot`` draw with matplotlib (the ``plot`` extra), so without it they
are skipped (those of ``screwsym.plot.viewer`` without plotly, the ``view`` extra),
as ``tests/plot`` skips itself with ``pytest.importorskip``; so are
those of ``screwsym.motion.urdf`` without ``defusedxml`` (the ``urdf`` extra).  This
file imports nothing of screwsym (``tests/conftest.py`` must set the cache
directory before screwsym loads).
"""

from __future__ import annotations

import importlib.util

import pytest

#: package folder or module (relative to the repository root) -> the module its doctests need
OPTIONAL = {"screwsym/plot/": "matplotlib", "screwsym/plot/viewer.py": "plotly",
            "screwsym/motion/urdf.py": "defusedxml"}
#: doctests elsewhere (by name) -> the module they need
OPTIONAL_DOCTESTS = {"screwsym.motion.chain.Chain.from_urdf": "defusedxml"}


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--slow",
        action="store_true",
        default=False,
        help="also run the tests marked slow (CI does; the default run leaves them out)",
    )


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    run_slow = config.getoption("--slow")
    skip_slow = pytest.mark.skip(reason="slow: run with --slow (CI does)")
    for item in items:
        if not run_slow and "slow" in item.keywords:
            item.add_marker(skip_slow)
    for item in items:  # under screwsym/ every item is a doctest
        path = item.path.resolve().relative_to(config.rootpath.resolve()).as_posix()
        for folder, module in OPTIONAL.items():
            if path.startswith(folder) and importlib.util.find_spec(module) is None:
                item.add_marker(pytest.mark.skip(reason=f"{module} not installed"))
        module = OPTIONAL_DOCTESTS.get(item.name)
        if module is not None and importlib.util.find_spec(module) is None:
            item.add_marker(pytest.mark.skip(reason=f"{module} not installed"))
