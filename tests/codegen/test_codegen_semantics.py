"""screwsym.codegen: one semantics in every back end and in the single-point path (issue 9).

A corpus of expressions runs through the NumPy, numba and C batch paths and
the single-point path of each; all must agree with each other (to rounding
of the libm functions: ``rtol=1e-12``, ``nan`` where ``nan``) and, at points
where the exact value is a finite real, with SymPy's exact evaluation.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from _backends import BACKENDS
from sympy import (
    Abs,
    And,
    E,
    Eq,
    Float,
    Max,
    Min,
    Mod,
    Ne,
    Or,
    Piecewise,
    Rational,
    S,
    acos,
    acosh,
    asin,
    asinh,
    atan,
    atan2,
    atanh,
    ceiling,
    cos,
    cosh,
    exp,
    expand,
    floor,
    log,
    nan,
    oo,
    pi,
    sign,
    sin,
    sinh,
    sqrt,
    symbols,
    tan,
    tanh,
)

from screwsym import lambdify

x, y = symbols("x y", real=True)

CORPUS = {
    "large integers (expanded (x+1)**70)": expand((x + 1) ** 70),
    "10**30 x": 10**30 * x,
    "2**70 x": S(2) ** 70 * x,
    "Mod(x, y)": Mod(x, y),
    "Mod(x, 3)": Mod(x, 3),
    "Mod(-x, -2.5)": Mod(-x, Float(-2.5)),
    "x**(1/3)": x ** Rational(1, 3),
    "y**(2/3) + x**(3/2)": y ** Rational(2, 3) + x ** Rational(3, 2),
    "sqrt": sqrt(x) + 1 / sqrt(y),
    "negative powers": x**-2 + y**-1,
    "pi and E": pi * x + E,
    "Min, Max": Min(x, y) + 2 * Max(x, y, 1),
    "Abs, sign": Abs(x) * sign(y) + sign(x),
    "atan2": atan2(x, y),
    "floor, ceiling": floor(x) * 3 + ceiling(y / 2),
    "Piecewise with default": Piecewise((x, x > 0), (y**2, True)),
    "Piecewise without default": Piecewise((x, x > 0), (y, y < 0)),
    "Piecewise with And/Or/Eq/Ne": Piecewise(
        (x, And(x > 0, y < 1)), (-y, Or(Eq(x, 0), Ne(y, 2))), (3, True)
    ),
    "exp, log": exp(x / 4) - log(y),
    "trig": sin(x) * cos(y) + tan(x / 7),
    "inverse trig": asin(x / 10) + acos(y / 10) + atan(x),
    "hyperbolic": sinh(x / 3) + cosh(y / 3) + tanh(x),
    "inverse hyperbolic": asinh(x) + acosh(y) + atanh(x / 10),
    "division": x / y + 1 / x,
    "oo and nan": oo * x + nan * (y - y + 1),
    "rational and float literals": Rational(1, 3) * x + Float("0.1") * y,
}

# points where an entry is ill-conditioned in floating point (huge cancellation), so that
# the rounding of x**70 (repeated products in numba, pow elsewhere) shows: not compared
ILL_CONDITIONED = {"large integers (expanded (x+1)**70)": lambda xs, ys: xs < 0}

XS = np.array([1.0, -8.0, 0.0, 2.5, -0.5, 3.0, np.nan, np.inf, -7.0, 7.0, -0.0, 1e300])
YS = np.array([2.0, 3.0, -3.0, 0.0, 1.0, -1.5, 1.0, 2.0, 3.0, 0.3, -0.0, -1e300])
# points where every exact value in the corpus that is real is also finite
EXACT_POINTS = [(1.0, 2.0), (2.5, 1.5), (7.0, 0.5)]


def close(a, b, keep=None) -> bool:
    a, b = np.asarray(a, float), np.asarray(b, float)
    if keep is not None:
        a, b = a[keep], b[keep]
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=1e-12, atol=0, equal_nan=True))


def evaluate(f, xs, ys) -> tuple[np.ndarray, np.ndarray]:
    """The batch result and the point-by-point result of ``f`` (no warning allowed)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        batch = f(xs, ys)
        points = np.array([f(float(a), float(b)) for a, b in zip(xs, ys, strict=True)])
    return batch, points


@pytest.fixture(scope="module")
def reference():
    """The NumPy batch path, the reference the others are compared with."""
    return {label: lambdify([x, y], e, "numpy")(XS, YS) for label, e in CORPUS.items()}


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("label", list(CORPUS))
def test_every_path_agrees(backend, label, reference):
    f = lambdify([x, y], CORPUS[label], backend)
    batch, points = evaluate(f, XS, YS)
    want = reference[label]
    keep = ~ILL_CONDITIONED[label](XS, YS) if label in ILL_CONDITIONED else None
    assert close(batch, want, keep), (backend, "batch", batch, want)
    assert close(points, want, keep), (backend, "single point", points, want)
    # broadcasting a single y against all xs takes the same path
    assert close(f(XS, YS[:1]), [f(float(a), float(YS[0])) for a in XS], keep)


@pytest.mark.parametrize("label", list(CORPUS))
def test_the_common_semantics_is_the_exact_value_where_that_is_a_finite_real(label):
    f = lambdify([x, y], CORPUS[label], "numpy")
    for a, b in EXACT_POINTS:
        exact = CORPUS[label].xreplace({x: Rational(a), y: Rational(b)}).evalf(40)
        if not exact.is_extended_real or not exact.is_finite:
            assert math.isnan(f(a, b)) or math.isinf(f(a, b)), (label, a, b, exact)
            continue
        assert f(a, b) == pytest.approx(float(exact), rel=1e-12, abs=1e-300), (label, a, b)


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_cases_of_the_issue(backend):
    f = lambdify([x], (expand((x + 1) ** 70), 10**30 * x, Mod(x, 3), x ** Rational(1, 3),
                       pi + E * x), backend)
    for args in [(1.0,), (np.array([1.0]),)]:
        big, huge, _, _, _ = f(*args)
        assert np.allclose(big, 2.0**70, rtol=1e-14) and np.all(huge == 1e30)  # C truncated both
    _, _, mod, cube, _ = f(-7.0)
    assert mod == 2.0  # the sign of the divisor, also in C (fmod gave -1)
    assert math.isnan(cube)  # a real power of a negative: nan (C's cbrt gave -2)
    assert math.isnan(f(np.array([-8.0]))[3][0])
    assert f(1.0)[4] == pytest.approx(math.pi + math.e, rel=1e-15)
    # Piecewise without a default: nan where no branch holds, on a batch too
    g = lambdify([x], Piecewise((x, x > 0), (-x, x < -1)), backend)
    np.testing.assert_array_equal(g(np.array([2.0, -0.5, -3.0])), [2.0, np.nan, 3.0])
    # Min and Max propagate nan in every path
    h = lambdify([x, y], (Min(x, y), Max(x, y)), backend)
    assert all(math.isnan(v) for v in h(np.nan, 1.0)) and all(math.isnan(v) for v in h(1.0, np.nan))
    assert [float(v[0]) for v in h(np.array([1.0]), np.array([np.nan]))] != [1.0, 1.0]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_wrong_value_is_caught_by_the_comparison(backend, reference):
    # the differential check can fail: a deliberately different expression disagrees
    f = lambdify([x, y], CORPUS["Mod(x, y)"] + 1e-9, backend)
    assert not close(evaluate(f, XS, YS)[0], reference["Mod(x, y)"])
