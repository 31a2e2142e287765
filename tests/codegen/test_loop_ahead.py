"""The C loop asks for its input rows ahead (``SS_PREFETCH``): every row is still computed once.

The loop reads the rows in four stretches of ``q = n // 4`` rows in turn, the last ``n - 4q``
after them; each stretch asks for its rows ``ahead`` further on only while they are in the
array (the loop is split at ``q - ahead``, nothing past the end is addressed).  Each size
around the splits, broadcast inputs (stride 0) and a batch of one give exactly the NumPy
back end's numbers.  The comparison is shown to catch a row left out.  The loop returns the
number of rows whose first result is ``nan`` (what :mod:`screwsym.numeric` uses instead of
a pass over the result): checked against a count in NumPy, around the same splits.
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
    assert "const size_t q = n / 4;" in src
    assert "i + 64 < q" in src  # 3072 bytes of the widest row (6 doubles) ahead


SIZES = [0, 1, 2, 3, 4, 5, 7, 255, 256, 257, 259, 260, 261, 263, 264, 1000, 1003]


@pytest.mark.parametrize("n", SIZES)
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
    assert "i + 384 < q" in c_source([h], h * 2)  # 3072 bytes of one double


@pytest.mark.parametrize("n", SIZES)
def test_the_loop_counts_the_rows_whose_first_result_is_nan(n):
    fc = lambdify([s, A, h], EXPR, "c", names=["s", "A", "h"])
    rng = np.random.default_rng(n)
    S, P, H = rng.standard_normal((n, 6)), rng.standard_normal((n, 3)), rng.standard_normal(n)
    H[::3] = np.nan  # nan pitch * h in the first result: rows in each stretch and the last ones
    S[1::7, :3] = 0.0  # couples: pitch inf (times h: inf, or nan where h is 0 or nan)
    H[2::5] = 0.0

    def count(H):
        outs = np.empty(n), np.empty((n, 3))
        return fc.kernel(n, S, P, H.reshape(n, 1), *outs)

    got = count(H)
    assert got == np.isnan(fc(S, P, H)[0]).sum()
    if n:  # one nan row fewer: the count tells it (the check can fail)
        H[0] = 1.0
        assert count(H) == got - 1 == np.isnan(fc(S, P, H)[0]).sum()
