"""Every snippet of the README runs: its Python blocks are doctests."""

import doctest
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
#: the module map of the docs, one row per public module
MODULES = ROOT / "notebooks" / "modules.md"


@pytest.fixture
def restore_displayhook():
    """The README calls screwsym.init_printing(), which outside IPython sets sys.displayhook."""
    saved = sys.displayhook
    yield
    sys.displayhook = saved


def test_readme_python_snippets_run_and_match_their_output(restore_displayhook):
    text = README.read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert blocks, "the README has no Python snippets"
    for block in blocks:
        assert ">>>" in block, f"a README Python snippet is not a doctest:\n{block}"
    result = doctest.testfile(
        str(README),
        module_relative=False,
        optionflags=doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS,
        verbose=False,
    )
    assert result.attempted > 0
    assert result.failed == 0


def test_readme_quickstart_commands_are_what_ci_runs():
    text = README.read_text(encoding="utf-8")
    quickstart = text[text.index("## Quickstart"):]
    quickstart = quickstart[:quickstart.index("\n## ", 3)]
    commands = re.findall(r"```bash\n(.*?)```", quickstart, flags=re.S)
    assert commands == [
        'pip install -e . && screwsym verify\n',
        'pip install -e ".[test]" && python -m pytest\n',
    ]
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert 'pip install -q -e ".[test]"' in ci and "python -m pytest" in ci


def _normalise(text):
    """CLI table text without timings and trailing blanks."""
    text = re.sub(r"\d+\.\d+ s\b", "T s", text)
    return [line.rstrip() for line in text.strip().splitlines()]


def test_readme_verify_output_is_what_the_cli_prints(capsys):
    from screwsym.cli import main

    text = README.read_text(encoding="utf-8")
    block = re.search(r"```text\n\$ screwsym verify (.*?)\n(.*?)```", text, flags=re.S)
    assert block, "the README shows no screwsym verify output"
    ids = re.findall(r'"([^"]+)"|(\S+)', block.group(1))
    ids = [a or b for a, b in ids]
    assert main(["verify", *ids, "--jobs", "1"]) == 0
    assert _normalise(capsys.readouterr().out) == _normalise(block.group(2))


#: modules documented in sections of their own rather than in the module table
_OWN_SECTION = ("screwsym.book", "screwsym.cli")


def test_module_map_lists_every_public_name():
    import importlib
    import pkgutil

    import screwsym

    rows = {
        m.group(1): m.group(0)
        for m in re.finditer(r"^\| \w+ \| `(screwsym\.[\w.]+)` \|.*$", MODULES.read_text(), re.M)
    }
    everything = "\n".join(rows.values())
    missing = {}
    for info in pkgutil.walk_packages(screwsym.__path__, "screwsym."):
        name = info.name
        if any(part.startswith("_") for part in name.split(".")) or name.startswith(_OWN_SECTION):
            continue
        module = importlib.import_module(name)
        # a floor's package re-exports its modules' names: each must stand in some row
        row = everything if info.ispkg and name not in rows else rows.get(name)
        if row is None:
            missing[name] = ["(no row)"]
            continue
        absent = [a for a in module.__all__ if not re.search(rf"`{re.escape(a)}[`(]", row)]
        if absent:
            missing[name] = absent
    assert missing == {}


def test_readme_links_point_at_files_that_exist():
    text = README.read_text(encoding="utf-8")
    local = [t for t in re.findall(r"\]\(([^)]+)\)", text) if "://" not in t]
    assert local
    missing = [t for t in local if not (ROOT / t.split("#")[0]).exists()]
    assert missing == []


def test_readme_links_every_notebook_and_stays_a_front_door():
    text = README.read_text(encoding="utf-8")
    from _site import notebook_paths

    for nb in notebook_paths(ROOT / "notebooks"):
        assert f"(notebooks/{nb.name})" in text, f"the README does not link {nb.name}"
    assert len(text.splitlines()) <= 250, "the README is a front door: detail goes to the docs"
