"""The "your robot in closed form" page shows what the code does: its snippets are doctests."""

import doctest
import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "notebooks" / "robots.md"


def test_robots_page_snippets_run_and_match_their_output():
    pytest.importorskip("defusedxml")
    flags = doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS
    here = os.getcwd()
    os.chdir(ROOT)  # the page reads tests/data/urdf relative to the repository root
    try:
        failed, attempted = doctest.testfile(str(PAGE), module_relative=False, optionflags=flags)
    finally:
        os.chdir(here)
    assert attempted > 0 and failed == 0
