"""Every constant and function the printers emit compiles and agrees in every back end (issue 20).

The C back end printed ``pi/2``, ``pi/4``, ``log(2)``, ``log(10)``, ... as
SymPy's math macros (``M_PI_2``, ``M_LN2``), which ``-std=c99`` lacks, so a
tidied chain holding ``pi/4`` did not build.  One function of the whole corpus
is built per back end; its values are checked against mpmath at 30 digits.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from _backends import HAS_CC, HAS_NUMBA
from sympy import (
    Abs,
    E,
    Max,
    Min,
    Mod,
    Piecewise,
    Rational,
    acos,
    asin,
    atan,
    atan2,
    ceiling,
    cos,
    cosh,
    exp,
    floor,
    log,
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

x = symbols("x", real=True)

#: numba compiles the corpus' kernel for seconds: a slow test (CI runs it)
BACKENDS = [
    "numpy",
    pytest.param("numba", marks=[pytest.mark.slow,
                                 pytest.mark.skipif(not HAS_NUMBA, reason="numba not installed")]),
    pytest.param("c", marks=pytest.mark.skipif(not HAS_CC, reason="no C compiler")),
]

#: every constant that SymPy's C printer has a macro for, and a few more
CONSTANTS = [pi, pi / 2, pi / 4, 1 / pi, 2 / pi, 2 / sqrt(pi), 1 / sqrt(pi), E, log(2), log(10),
             1 / log(2), 1 / log(10), log(2) / log(10), sqrt(2), sqrt(2) / 2, 1 / sqrt(2),
             pi**2, Rational(1, 3), Rational(2**60 + 1, 3), sqrt(3) / 2, exp(Rational(1, 2))]
#: the functions, at x = 0.37
FUNCTIONS = [sin(x), cos(x), tan(x), asin(x), acos(x), atan(x), atan2(x, -1), sinh(x), cosh(x),
             tanh(x), exp(x), log(x), sqrt(x), x ** Rational(1, 3), Abs(-x), sign(x - 1),
             Min(x, pi / 4), Max(x, log(2)), Mod(x + 1, pi / 4), floor(10 * x), ceiling(10 * x),
             Piecewise((pi / 4, x > 0), (log(10), True)), x ** 3 - x / 7]
AT = 0.37


def _reference(e) -> float:
    mpmath.mp.dps = 30
    return float(e.subs(x, mpmath.mpf(AT)).evalf(30))


@pytest.mark.parametrize("backend", BACKENDS)
def test_every_constant_and_function_compiles_and_agrees(backend):
    corpus = CONSTANTS + FUNCTIONS
    f = lambdify([x], tuple(x * 0 + e for e in corpus), backend)
    got = [np.asarray(v).ravel() for v in f(np.array([AT, AT]))]
    for e, v in zip(corpus, got, strict=True):
        want = _reference(e)
        assert v.shape == (2,) and np.allclose(v, want, rtol=4e-16, atol=4e-16), (e, v, want)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_tidied_chain_holding_pi_over_4_builds(backend):
    from screwsym import Chain, Twist

    q = symbols("q1:3", real=True)
    chain = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                   Twist.rotation([1, 1, 0], point=[0, 0, 1])])
    T = chain.forward([q[0], pi / 4])  # tidied entries hold pi/4
    assert T.has(pi / 4)
    g = lambdify([q[0]], T, backend)
    want = np.array(T.matrix.subs(q[0], 0.7).evalf(), dtype=float)
    np.testing.assert_allclose(g(np.array([0.7]))[0], want, rtol=1e-14, atol=1e-15)
