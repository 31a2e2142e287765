"""The numeric back ends the codegen and numeric tests run on, skipped where unavailable.

Importing this module points screwsym's disk cache (generated numba modules,
compiled C libraries) at a temporary directory for the test session, so
that tests never write to the user's cache directory.
"""

import atexit
import importlib.util
import os
import shutil
import tempfile

import pytest

if "SCREWSYM_CACHE_DIR" not in os.environ:
    _TMP_CACHE = tempfile.mkdtemp(prefix="screwsym-test-cache-")
    os.environ["SCREWSYM_CACHE_DIR"] = _TMP_CACHE
    atexit.register(shutil.rmtree, _TMP_CACHE, ignore_errors=True)

from screwsym.codegen._build import compiler  # noqa: E402 - after the cache directory is set

HAS_NUMBA = importlib.util.find_spec("numba") is not None
HAS_CC = compiler() is not None

BACKENDS = [
    "numpy",
    pytest.param("numba", marks=pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")),
    pytest.param("c", marks=pytest.mark.skipif(not HAS_CC, reason="no C compiler")),
]
