"""The store of the registry: the ``statement`` decorator that the section modules use.

Kept apart from :mod:`._registry`, which loads the section modules, so that the
sections and the registry do not import each other in a circle.
"""

from __future__ import annotations

from collections.abc import Callable

from ._entry import Construction, Entry

__all__ = ["statement"]

_REGISTRY: dict[str, Entry] = {}


def statement(
    id: str,
    section: str,
    title: str,
    latex: str,
    kind: str,
    construction: str,
    *,
    errata: tuple[str, ...] = (),
    notes: tuple[str, ...] = (),
) -> Callable[[Callable[[Construction], None]], Callable[[Construction], None]]:
    """Register the decorated construction as the entry ``id``."""

    def register(build: Callable[[Construction], None]) -> Callable[[Construction], None]:
        if id in _REGISTRY:
            raise ValueError(f"id: entry {id!r} is registered twice")
        _REGISTRY[id] = Entry(
            id, section, title, latex.strip(), kind, " ".join(construction.split()), build,
            tuple(errata), tuple(notes),
        )
        return build

    return register
