"""The page on mechanisms of any topology shows what the code does: its snippets are doctests."""

import doctest
from pathlib import Path

PAGE = Path(__file__).resolve().parents[2] / "notebooks" / "mechanisms-any-topology.md"


def test_mechanisms_page_snippets_run_and_match_their_output():
    flags = doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS
    failed, attempted = doctest.testfile(str(PAGE), module_relative=False, optionflags=flags)
    assert attempted > 0 and failed == 0
