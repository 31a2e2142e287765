"""Generated functions pickle by reference and load back from the disk cache (issue 33).

:mod:`screwsym.codegen.generated` names each function by the key of its code;
a new process on the same disk cache reads it back without SymPy work, and
one without it is told how to rebuild it.
"""

from __future__ import annotations

import json
import os
import pickle
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from _backends import BACKENDS, HAS_CC
from sympy import symbols

from screwsym import lambdify, numeric
from screwsym.codegen import generated

x, y = symbols("x y", real=True)
ROOT = Path(__file__).resolve().parents[2]

LOAD = textwrap.dedent("""
    import pickle, sys
    import numpy as np
    from screwsym.codegen import _build
    def boom(*args, **kwargs):
        raise AssertionError("built again")
    _build.prepared = boom  # no CSE, no printing: read back from the cache
    f = pickle.loads(open(sys.argv[1], "rb").read())
    print(f.__name__, f(np.array([1.0, 2.0]), 3.0).tolist())
""")


def load_elsewhere(data: bytes, tmp_path: Path, cache: Path) -> subprocess.CompletedProcess:
    path = tmp_path / "f.pkl"
    path.write_bytes(data)
    env = dict(os.environ, SCREWSYM_CACHE_DIR=str(cache))
    return subprocess.run([sys.executable, "-c", LOAD, str(path)], env=env, cwd=ROOT,
                          capture_output=True, text=True)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_generated_function_pickles_by_reference(backend):
    f = lambdify([x, y], x * y + 1, backend, name="product_plus_one")
    data = pickle.dumps(f)
    assert b"x * y" not in data and len(data) < 300  # a reference, not code
    assert pickle.loads(data) is f
    assert f.__module__ == "screwsym.codegen.generated" and f.__name__ == "product_plus_one"
    # the module functions too, scale-free wrapper or not
    for fn in (numeric.pitch, numeric.reciprocal_product):
        assert pickle.loads(pickle.dumps(fn)) is fn


@pytest.mark.parametrize("backend", ["numpy", pytest.param("c", marks=pytest.mark.skipif(
    not HAS_CC, reason="no C compiler"))])
def test_a_new_process_loads_it_from_the_disk_cache(backend, tmp_path, monkeypatch):
    cache = tmp_path / "cache"
    monkeypatch.setenv("SCREWSYM_CACHE_DIR", str(cache))
    f = lambdify([x, y], 2 * x + y, backend, name="twice_plus", doc="Twice x, plus y.")
    data = pickle.dumps(f)
    done = load_elsewhere(data, tmp_path, cache)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "twice_plus [5.0, 7.0]\n"
    # another disk cache: the error says how to rebuild it
    other = load_elsewhere(data, tmp_path, tmp_path / "other")
    assert other.returncode != 0
    assert "UnpicklingError" in other.stderr and "call screwsym.lambdify with the same " \
        "arguments here to rebuild it" in other.stderr
    # a description whose docstring is not the one its name was made from is not used
    (index,) = (cache / backend).glob("index-k*.json")
    meta = json.loads(index.read_text())
    index.write_text(json.dumps({**meta, "doc": "Something else."}))
    again = load_elsewhere(data, tmp_path, cache)
    assert again.returncode != 0 and "UnpicklingError" in again.stderr


def test_a_name_not_of_a_generated_function_is_an_attribute_error():
    with pytest.raises(AttributeError, match="has no attribute 'nothing'"):
        generated.nothing  # noqa: B018
    assert not hasattr(generated, "k123")
    f = lambdify([x], x + 2, "numpy")
    reference = f.__qualname__.split(".")[0]
    assert getattr(generated, reference).__dict__ == {f.__name__: f}
    assert np.array_equal(getattr(generated, reference).__dict__[f.__name__](np.ones(2)), [3, 3])
