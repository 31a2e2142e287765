"""The documentation site's sources: every notebook is listed, the book page has every entry."""

import fnmatch
import importlib.util
import re
from pathlib import Path

import pytest

from screwsym.book import entries

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"


def test_every_notebook_is_on_the_site():
    index = (NOTEBOOKS / "index.md").read_text(encoding="utf-8")
    block = re.search(r"```\{toctree\}\n(.*?)```", index, flags=re.S).group(1)
    assert ":glob:" in block
    patterns = [line.strip() for line in block.splitlines()
                if line.strip() and not line.startswith(":")]
    notebooks = sorted(p.stem for p in NOTEBOOKS.glob("*.ipynb"))
    assert notebooks and all(any(fnmatch.fnmatch(n, p) for p in patterns) for n in notebooks)


def test_reference_pages_exist():
    for page in ("book", "api", "benchmarks"):
        assert (NOTEBOOKS / f"{page}.md").exists()
    assert "../benchmarks/README.md" in (NOTEBOOKS / "benchmarks.md").read_text(encoding="utf-8")


_DOCS = "it reads the site's Sphinx configuration: needs the docs extra, pip install -e \".[docs]\""


def test_book_page_has_every_entry_with_its_checks_and_errata():
    pytest.importorskip("sphinx", reason=_DOCS)
    pytest.importorskip("myst_nb", reason=_DOCS)
    spec = importlib.util.spec_from_file_location("screwsym_docs_conf", NOTEBOOKS / "conf.py")
    conf = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(conf)
    text = "\n".join(conf._book_lines())
    for e in entries():
        assert conf._rst(e.title) in text, e.id
        for x in e.errata:
            assert conf._rst(x) in text, e.id
        for c in e.construct().checks:
            assert f"``{c.label}``" in text, (e.id, c.label)
    assert text.count(".. math::") == len(entries())
    lines = text.splitlines()
    sections = [a for a, b in zip(lines, lines[1:], strict=False)
                if a.startswith("Section ") and set(b) == {"-"}]
    assert sections and len(sections) == len(set(sections)), sections  # each section once
