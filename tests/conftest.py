import pytest
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
