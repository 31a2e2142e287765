"""The C loop asks for its input rows ahead (``SS_PREFETCH``): every row is still computed once.

The loop is split at ``n - ahead`` (rows ``ahead`` further on are prefetched, never read
past the end); each size around the split, broadcast inputs (stride 0) and a batch of
one give exactly the NumPy back end's numbers.  The comparison is shown to catch a row
left out.
"""

from __future__ import annotations

import numpy as np
import pytest
from _backends import HAS_CC
from sympy import symbols

from screwsym import Screw, foot, lambdify, pitch, vector
from screwsym.codegen import c_source

pytestmark = pytest.mark.skipif(not HAS_CC, reason="no C compiler")

s = Screw(vector("S"), vector("S0"))
A = vector("A")
h = symbols("h", real=True)
EXPR = (pitch(s) * h, foot(s) + A)


def test_the_loop_prefetches_ahead_and_splits():
    src = c_source([s, A, h], EXPR, names=["s", "A", "h"])
    assert src.count("SS_PREFETCH(_a") == 3  # one per input
    assert "i + 128 < n" in src  # 6144 bytes of the widest row (6 doubles) ahead


@pytest.mark.parametrize("n", [0, 1, 2, 127, 128, 129, 130, 1000])
def test_every_row_around_the_split_is_the_numpy_back_ends(n):
    fc = lambdify([s, A, h], EXPR, "c", names=["s", "A", "h"])
    fn = lambdify([s, A, h], EXPR, "numpy", names=["s", "A", "h"])
    rng = np.random.default_rng(n)
    S, P, H = rng.standard_normal((n, 6)), rng.standard_normal((n, 3)), rng.standard_normal(n)
    cases = [(S, P, H)] + ([(S, P[0], 2.0), (S[0], P, H)] if n else [])  # broadcast: stride 0
    for args in cases:
        for x, y in zip(fc(*args), fn(*args), strict=True):
            np.testing.assert_array_equal(x, y)
    if n > 1:  # the comparison catches one row wrong
        out = fc(S, P, H)
        wrong = out[0].copy()
        wrong[-1] = np.nextafter(wrong[-1], np.inf)
        assert not np.array_equal(wrong, fn(S, P, H)[0])


def test_the_look_ahead_depends_on_the_widest_row():
    assert "i + 768 < n" in c_source([h], h * 2)  # 6144 bytes of one double
