"""The numeric back ends the codegen and numeric tests run on, skipped where unavailable."""

import importlib.util
import shutil

import pytest

HAS_NUMBA = importlib.util.find_spec("numba") is not None
HAS_CC = shutil.which("cc") is not None

BACKENDS = [
    "numpy",
    pytest.param("numba", marks=pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")),
    pytest.param("c", marks=pytest.mark.skipif(not HAS_CC, reason="no C compiler (cc)")),
]
