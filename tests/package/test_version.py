"""The package's version is one string: the newest release of CHANGELOG.md, as CITATION.cff cites it.

A release bumps ``screwsym/_version.py`` (which pyproject reads), adds its
changelog section and updates the citation; forgetting one fails here.
"""

import re
from pathlib import Path

import screwsym

ROOT = Path(__file__).resolve().parents[2]

_RELEASE = re.compile(r"^## \[(\d+\.\d+\.\d+)\] - (\d{4}-\d{2}-\d{2})$", re.M)


def newest_release(changelog: str) -> tuple[str, str]:
    """``(version, date)`` of the first released section of a Keep a Changelog file."""
    releases = _RELEASE.findall(changelog)
    assert releases, "the changelog names no release"
    return releases[0]


def test_the_version_is_the_newest_release_of_the_changelog():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert text.index("## [Unreleased]") < text.index("## [" + screwsym.__version__ + "]")
    version, _ = newest_release(text)
    assert screwsym.__version__ == version


def test_the_citation_cites_the_newest_release():
    version, date = newest_release((ROOT / "CHANGELOG.md").read_text(encoding="utf-8"))
    cff = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    assert re.search(rf"^version: {re.escape(version)}$", cff, re.M)
    assert re.search(rf"^date-released: {date}$", cff, re.M)


def test_the_reader_finds_the_first_release_not_unreleased():
    text = "## [Unreleased]\n\n## [1.2.3] - 2030-01-02\n\n## [1.2.2] - 2029-12-31\n"
    assert newest_release(text) == ("1.2.3", "2030-01-02")
