"""The registry: every statement of Chapter 1, in the book's order."""

from __future__ import annotations

import difflib
import re

from ._entry import Entry
from ._statement import _REGISTRY

__all__ = ["entries", "entry", "ids"]

def _load() -> None:
    if not _REGISTRY:
        from . import (  # noqa: F401  (importing registers the entries)
            _s12_lines,
            _s13_mutual,
            _s14_line_vector,
            _s14_screw,
            _s15_algebra,
            _s16_kinematics,
            _s17_statics,
            _s18_counting,
        )


def entries() -> tuple[Entry, ...]:
    """Every entry of the registry, in the book's order.

    >>> from screwsym.book import entries
    >>> [e.id for e in entries()][:3]
    ['1.1', '1.2', '1.3']
    """
    _load()
    return tuple(_REGISTRY.values())


def ids() -> tuple[str, ...]:
    """The ids of all entries, in the book's order."""
    return tuple(e.id for e in entries())


def _normal(s: str) -> str:
    s = s.strip().lower()
    s = re.sub(r"^(eq\.?|equation)\s*", "", s)
    s = re.sub(r"^\((.*)\)$", r"\1", s)
    return re.sub(r"\s+", " ", s)


_ABBREVIATIONS = (
    (r"^(ex|exa|exam|exmp|example|eg)\.?\s*(?=\d)", "example "),
    (r"^(th|thm|theo|theorem)\.?\s*(?=\d)", "theorem "),
    (r"^(fig|figure)\.?\s*(?=\d)", "fig. "),
)


def _spelled_out(s: str) -> str:
    for pattern, word in _ABBREVIATIONS:
        s = re.sub(pattern, word, s)
    return s


def entry(id: str) -> Entry:
    """The entry with the given id: ``"1.34"``, ``"(1.34)"``, ``"Example 1.4"``, ...

    >>> from screwsym.book import entry
    >>> entry("(1.34)").title
    'Pitch of a screw'
    >>> entry("1.99")
    Traceback (most recent call last):
    ...
    KeyError: "unknown entry id '1.99'; did you mean '1.9'? (screwsym list shows every id)"
    >>> entry("ex1.4")
    Traceback (most recent call last):
    ...
    KeyError: "unknown entry id 'ex1.4'; did you mean 'Example 1.4'? (screwsym list shows every id)"
    """
    if not isinstance(id, str):
        raise TypeError(f"id: expected a string such as '1.34', got {type(id).__name__}")
    _load()
    if id in _REGISTRY:
        return _REGISTRY[id]
    wanted = _normal(id)
    for key, e in _REGISTRY.items():
        if _normal(key) == wanted:
            return e
    # the suggestion reads abbreviations as the ids spell them ("ex1.4" -> "Example 1.4")
    spelled = _spelled_out(wanted)
    by_normal = {_normal(key): key for key in _REGISTRY}
    close = difflib.get_close_matches(spelled, list(by_normal), n=1)
    hint = f"; did you mean {by_normal[close[0]]!r}?" if close else ";"
    raise KeyError(f"unknown entry id {id!r}{hint} (screwsym list shows every id)")
