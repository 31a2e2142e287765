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


def _many_points(sym, k=200):
    import random

    from screwsym.book._verify import rational_point

    rng = random.Random(3)
    return [rational_point([sym], rng)[sym] for _ in range(k)]


@pytest.mark.parametrize(
    "assumptions, holds",
    [
        ({"positive": True}, lambda v: v > 0),
        ({"negative": True}, lambda v: v < 0),
        ({"nonnegative": True}, lambda v: v >= 0),
        ({"nonpositive": True}, lambda v: v <= 0),
        ({"nonzero": True, "real": True}, lambda v: v != 0),
        ({"integer": True}, lambda v: v.is_integer),
        ({"integer": True, "negative": True}, lambda v: v.is_integer and v < 0),
        ({"even": True}, lambda v: v.is_integer and v % 2 == 0),
        ({"odd": True, "positive": True}, lambda v: v.is_integer and v % 2 == 1 and v > 0),
    ],
)
def test_points_stay_inside_the_assumptions(assumptions, holds):
    sym = symbols("s", **assumptions)
    values = _many_points(sym)
    assert all(holds(v) for v in values)
    assert len(set(values)) > 3  # it does sample


def test_real_symbols_get_both_signs_and_fractions():
    values = _many_points(x)
    assert any(v < 0 for v in values) and any(v > 0 for v in values)
    assert any(not v.is_integer for v in values)


def test_no_false_nonzero_outside_the_domain():
    """|n| + n vanishes for every negative n: no sampled point may "prove" it non-zero.

    (Sampled among positive rationals, as before, it would be 2n != 0.)
    """
    n = symbols("n", negative=True)
    expr = Abs(n, evaluate=False) + n
    assert not decide_nonzero(expr)[0]
    assert decide_zero(expr).guard is True  # the guard agrees with a zero verdict there
    p = symbols("p", positive=True)
    assert decide_nonzero(Abs(p, evaluate=False) + p)[0]

