"""The decision procedure: exact, guarded, and able to fail."""

import pytest
from sympy import Abs, Matrix, cos, sin, sqrt, symbols

from screwsym.book import decide_nonzero, decide_zero

x, y, z = symbols("x y z", real=True)


@pytest.mark.parametrize(
    "expr",
    [
        (x + y) ** 2 - (x**2 + 2 * x * y + y**2),
        (x**2 - 1) / (x - 1) - (x + 1),
        sin(x) ** 2 + cos(x) ** 2 - 1,
        sin(2 * x) - 2 * sin(x) * cos(x),
        Abs(x) * sqrt(y**2 + 1) - sqrt(x**2 * y**2 + x**2),
        Matrix([x - x, y * (y + 1) - y**2 - y]),
    ],
)
def test_true_identities_reach_zero(expr):
    d = decide_zero(expr)
    assert d.ok and d.zero and d.guard
    assert d.residual == 0 or all(e == 0 for e in d.residual)


@pytest.mark.parametrize(
    "expr, residual",
    [
        ((x + y) ** 2 - (x**2 + 2 * x * y + y**2 + 1), -1),  # perturbed right-hand side
        ((x + y) ** 2 - (x**2 - 2 * x * y + y**2), 4 * x * y),  # flipped sign
        ((x + y) ** 2 - (x**2 + y**2), 2 * x * y),  # missing term
    ],
)
def test_wrong_identities_are_rejected_with_their_residual(expr, residual):
    d = decide_zero(expr)
    assert not d.ok and not d.zero
    assert (d.residual - residual).expand() == 0


def test_wrong_trig_identity_rejected():
    assert not decide_zero(sin(x) ** 2 - cos(x) ** 2 - 1).ok


def test_nonzero_shown_exactly():
    ok, point, value = decide_nonzero(x * y - z)
    assert ok and value != 0 and value.is_Rational
    assert decide_nonzero(sqrt(2) - 1)[0]
    assert not decide_nonzero(x - x)[0]


def test_guard_is_seeded_and_deterministic():
    a = decide_zero((x + 1) ** 2 - x**2 - 2 * x - 1, seed=5)
    b = decide_zero((x + 1) ** 2 - x**2 - 2 * x - 1, seed=5)
    assert a == b
