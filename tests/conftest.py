"""Shared fixtures.  Importing ``_backends`` first points screwsym's disk cache of compiled
code at a temporary directory for the whole session (doctests included), so tests never
write to the user's cache directory."""

import pytest
from _backends import BACKENDS  # noqa: F401  (sets SCREWSYM_CACHE_DIR before screwsym loads code)
from sympy import symbols

from screwsym import vector


@pytest.fixture
def generic():
    """Generic real symbols used across the core tests."""
    return {
        "S": vector("S"),
        "S0": vector("S0"),
        "r": vector("r"),
        "a": vector("a"),
        "h": symbols("h", real=True),
        "k": symbols("k", real=True),
    }
