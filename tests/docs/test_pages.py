"""Every page of the documentation shows what the code does: its Python snippets are doctests.

The pages are the MyST files of ``notebooks/`` (the guide, the module map, the float policy,
...); a page whose examples stopped matching the library fails here, as the README does in
``test_readme.py``.
"""

import doctest
import re
import sys
from pathlib import Path

import pytest

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"
PAGES = sorted(p for p in NOTEBOOKS.glob("*.md") if ">>>" in p.read_text(encoding="utf-8"))


@pytest.fixture
def restore_displayhook():
    saved = sys.displayhook
    yield
    sys.displayhook = saved


def test_the_guide_has_examples():
    assert NOTEBOOKS / "guide.md" in PAGES and NOTEBOOKS / "float-policy.md" in PAGES


#: pages whose examples need an optional extra
NEEDS = {"robots.md": "defusedxml"}


@pytest.mark.parametrize("page", PAGES, ids=[p.stem for p in PAGES])
def test_page_snippets_run_and_match_their_output(page, restore_displayhook, monkeypatch):
    if page.name in NEEDS:
        pytest.importorskip(NEEDS[page.name], reason=f"{page.name} needs {NEEDS[page.name]}")
    monkeypatch.chdir(NOTEBOOKS.parent)  # pages read files such as tests/data/urdf from the root
    text = page.read_text(encoding="utf-8")
    for block in re.findall(r"```python\n(.*?)```", text, flags=re.S):
        assert ">>>" in block, f"{page.name}: a Python snippet is not a doctest:\n{block}"
    flags = doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS
    failed, attempted = doctest.testfile(str(page), module_relative=False, optionflags=flags)
    assert attempted > 0 and failed == 0
