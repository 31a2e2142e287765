"""Real zeros and positivity, proved (``screwsym.algebra.real``).

A proof of positivity must never be given for a polynomial with a real zero: each such
case is built with its zero and the zero is confirmed by evaluation.  Sums of squares of
affine forms plus a positive constant must be proved.  Real roots are compared with
SymPy's ``Poly.real_roots`` and checked by minimal polynomials; the points of the circle
are checked on the circle and on the equation, ``q = pi`` included.  Seeded per case.
"""

from __future__ import annotations

import random

import pytest
from sympy import (
    QQ,
    Eq,
    Integer,
    Poly,
    Rational,
    cos,
    minimal_polynomial,
    sin,
    sqf_part,
    sqrt,
    symbols,
)

from screwsym.algebra.circle import on_circle, trig_symbol
from screwsym.algebra.real import (
    admissible,
    circle_points,
    dimension,
    involved_indices,
    largest_degree,
    linear_in,
    no_real_zero,
    proved_positive,
    rational_domain,
    rational_norm,
    real_factors,
    real_points,
    real_zeros,
    solvable,
    square_split,
)

x, y, z = symbols("x y z")
q = symbols("q", real=True)
S, C = trig_symbol(sin, q), trig_symbol(cos, q)
R3 = QQ[x, y, z]
K3 = QQ.algebraic_field(sqrt(3))


def affine(rng: random.Random, R):
    return sum((R.domain.convert(rng.randint(-3, 3)) * g for g in R.gens), R.zero) \
        + R.domain.convert(rng.randint(-3, 3))


def random_poly(rng: random.Random, R, terms: int = 5, top: int = 2):
    d = {}
    for _ in range(terms):
        d[tuple(rng.randint(0, top) for _ in R.gens)] = QQ(rng.randint(-9, 9), rng.randint(1, 3))
    return R.ring.from_dict(d)


@pytest.mark.parametrize("nvars", [1, 2, 3])
@pytest.mark.parametrize("case", range(8))
def test_sums_of_squares_plus_a_constant_are_proved_positive(nvars, case):
    R = QQ[(x, y, z)[:nvars]]
    rng = random.Random(f"{case}-{nvars}-sos")
    p = sum((affine(rng, R) ** 2 for _ in range(rng.randint(1, 3))), R.zero)
    p += QQ(rng.randint(1, 9), rng.randint(1, 9))
    assert proved_positive(p, R) is True
    assert no_real_zero(p, R) is True and no_real_zero(-p, R) is True
    assert proved_positive(-p, R) is False


@pytest.mark.parametrize("nvars", [1, 2, 3])
@pytest.mark.parametrize("case", range(10))
def test_never_proved_positive_with_a_real_zero(nvars, case):
    R = QQ[(x, y, z)[:nvars]]
    rng = random.Random(f"{case}-{nvars}-zero")
    if case % 2:  # a sum of squares shifted down to a zero: p >= 0, zero at the point
        g = sum((affine(rng, R) ** 2 for _ in range(3)), R.zero) + 1
    else:
        g = random_poly(rng, R)
    point = [QQ(rng.randint(-4, 4), rng.randint(1, 3)) for _ in R.gens]
    p = g - g(*point)
    if not p:
        return
    assert p(*point) == 0  # the zero, confirmed
    assert proved_positive(p, R) is False
    assert proved_positive(-p, R) is False
    assert no_real_zero(p, R) is False


def test_a_nonnegative_polynomial_with_a_zero_is_not_positive():
    R = QQ[x, y]
    X, Y = R.gens
    p = (X - 1) ** 2 + (Y - 2) ** 2
    assert p(QQ(1), QQ(2)) == 0
    assert proved_positive(p, R) is False and no_real_zero(p, R) is False
    assert proved_positive(p + 1, R) is True  # the check can say yes


def test_proved_positive_over_the_field_and_constants():
    R = K3[x]
    X = R.gens[0]
    s3 = K3.from_sympy(sqrt(3))
    assert proved_positive((X - s3) ** 2 + 1, R) is True
    assert proved_positive((X - s3) ** 2, R) is False  # zero at sqrt(3)
    assert proved_positive(X**2 - 3, R) is False
    assert no_real_zero(X**2 + 2 + s3, R) is True
    # x**2 + sqrt(3) > 0, but its conjugate x**2 - sqrt(3) has real zeros: not proved
    assert no_real_zero(X**2 + s3, R) is False
    assert proved_positive(R.one * 2, R) is True
    assert proved_positive(-R.one, R) is False and no_real_zero(-R.one, R) is True
    assert proved_positive(R.zero, R) is False


def test_proved_positive_uses_the_assumptions():
    a = symbols("a", positive=True)
    R = QQ[a, x]
    A, X = R.gens
    assert proved_positive(A + 1, R) is True
    assert proved_positive(X + 1, R) is False


@pytest.mark.parametrize("case", range(10))
def test_real_points_are_sympys_real_roots(case):
    rng = random.Random(f"{case}-roots")
    e = Integer(rng.randint(1, 3))
    for _ in range(rng.randint(1, 3)):
        if rng.random() < 0.5:
            e *= x - Rational(rng.randint(-5, 5), rng.randint(1, 3))
        else:  # a quadratic: two, one or no real roots
            e *= x**2 + rng.randint(-4, 4) * x + rng.randint(-5, 5)
    e = e.expand()
    got = [r for (((_, r),), _) in real_points(e, x)]
    assert set(got) == set(Poly(e, x).real_roots())
    assert len(got) == len(set(got)) == sqf_part(Poly(e, x)).count_roots()
    for r in got:  # a root, exactly: its minimal polynomial divides e
        assert Poly(e, x).rem(Poly(minimal_polynomial(r, x), x)).is_zero
    assert all(cond == Eq(x, r) for (((_, r),), cond) in real_points(e, x))
    # the comparison sees a missing root
    assert set(got) != set(Poly(e * (x - 17), x).real_roots())


def test_real_points_respects_the_assumptions():
    p = symbols("p", positive=True)
    e = (p - 2) * (p + 3) * (p**2 - 2)
    assert [r for (((_, r),), _) in real_points(e, p)] == [sqrt(2), 2]
    assert admissible(p, Integer(-3)) is False and admissible(x, Integer(-3)) is True
    n = symbols("n", integer=True)
    assert [r for (((_, r),), _) in real_points(n**2 - 2, n)] == []


def exactly_zero(e) -> bool:
    """Whether the algebraic number ``e`` is 0: its minimal polynomial is the symbol's."""
    w = symbols("w")
    return minimal_polynomial(e, w) == w


def on_the_circle_and_the_curve(e, s, c) -> bool:
    return exactly_zero(s**2 + c**2 - 1) and exactly_zero(e.xreplace({S: s, C: c}))


def line(a, b):
    """The line through two points (sin, cos) of the circle, in the ring symbols."""
    return (b[1] - a[1]) * (S - a[0]) - (b[0] - a[0]) * (C - a[1])


PI = (Integer(0), Integer(-1))


@pytest.mark.parametrize("case", range(8))
def test_circle_points_are_the_known_points(case):
    rng = random.Random(f"{case}-circle")
    # two or three chords between rational points of the circle, one of them maybe q = pi
    points = [on_circle(Rational(rng.randint(-9, 9), rng.randint(1, 9))) for _ in range(4)]
    if case % 2:
        points[1] = PI
    e = line(points[0], points[1]) * line(points[2], points[3])
    known = {tuple(p) for p in points}
    found = circle_points(e.expand(), q)
    assert found is not None
    got = {(s, c) for (((_, s), (_, c)), _) in found}
    assert got == known
    assert len(found) == len(got)  # no point twice
    for (((f1, s), (f2, c)), cond) in found:
        assert (f1, f2) == (sin(q), cos(q))
        assert on_the_circle_and_the_curve(e, s, c)
        assert cond == (Eq(sin(q), s) & Eq(cos(q), c))
    # the comparisons see a point too few, and a point off the curve
    assert got != known - {tuple(points[0])}
    assert not on_the_circle_and_the_curve(e + S + 1, *points[0])


def test_circle_points_with_surds_and_q_pi():
    # sin(q) = 0: q = 0 and q = pi, the latter out of reach of t = tan(q/2)
    found = {(s, c) for (((_, s), (_, c)), _) in circle_points(S, q)}
    assert found == {(0, 1), PI}
    assert {(s, c) for (((_, s), (_, c)), _) in circle_points(C + 1, q)} == {PI}
    half = {(s, c) for (((_, s), (_, c)), _) in circle_points(S - Rational(1, 2), q)}
    assert half == {(Rational(1, 2), sqrt(3) / 2), (Rational(1, 2), -sqrt(3) / 2)}
    e = 5 * S - 4 * C - 3
    pts = circle_points(e, q)
    assert len(pts) == 2
    assert all(on_the_circle_and_the_curve(e, s, c) for (((_, s), (_, c)), _) in pts)
    assert circle_points(S**2 + C**2 + 1, q) == ()  # no point at all


def test_circle_points_with_radical_coefficients():
    # on the circle, cos + 1 + (2 + sqrt 3) sin**2 = 0 only at q = pi (both conjugates too)
    e = C + 1 + (2 + sqrt(3)) * S**2
    assert {(s, c) for (((_, s), (_, c)), _) in circle_points(e, q)} == {PI}
    assert circle_points(e + 1, q) == ()
    # a conjugate with real points: undecided, never a wrong answer
    assert circle_points(S - sqrt(3) / 2, q) is None


def test_real_zeros():
    R = QQ[x, y]
    X, Y = R.gens
    assert [r for (((_, r),), _) in real_zeros(X**2 - 2, R)] == [-sqrt(2), sqrt(2)]
    assert real_zeros(X**2 + 2, R) == ()
    assert real_zeros(X * Y - 1, R) is None  # a curve: not finitely many
    assert real_zeros(R.one, R) is None
    Rk = K3[x]
    s3 = K3.from_sympy(sqrt(3))
    assert real_zeros(Rk.gens[0] ** 2 + 2 + s3, Rk) == ()
    assert real_zeros(Rk.gens[0] - s3, Rk) is None  # surd coefficients with a real zero
    Rc = QQ[S, C]
    assert {(s, c) for (((_, s), (_, c)), _) in real_zeros(Rc.gens[1] + 1, Rc)} == {PI}


def test_real_factors_drop_what_cannot_vanish():
    R = QQ[x, y]
    X, Y = R.gens
    p = (X**2 + 1) * (X - Y) * (Y**2 + Y + 1) * 3
    assert real_factors(p, R) == [X - Y]
    assert real_factors(p, R, lambda e: e == x - y) == []
    assert real_factors(R.one * 5, R) == []
    assert set(real_factors((X**2 - 2) * (Y - 1), R)) == {X**2 - 2, Y - 1}


def test_square_split():
    R = QQ[x, y]
    X, Y = R.gens
    f = (X - 1) ** 2 + (Y - 2) ** 2
    lin, D = square_split(f, R)
    a = f.coeff_wrt(X, 2)
    assert 4 * a * f == lin**2 + D  # 4 a f = (2 a x + b)**2 + D
    assert D == 4 * (Y - 2) ** 2  # zero with lin exactly at (1, 2)
    assert square_split(f + 1, R)[1] == D + 4 * a
    assert square_split(X**2 - Y**2, R) is None  # not a sum of squares
    assert square_split(X**2 + Y, R) is None


def test_linear_in_and_solvable():
    R = QQ[x, y, S, C]
    X, Y, Sg, Cg = R.gens
    sym, a, b = linear_in(X * Y + X + 1, R)
    assert sym == y and a == X and b == X + 1
    assert a * R.gens[1] + b == X * Y + X + 1
    sym, a, b = linear_in(2 * X + Y**2, R)
    assert (sym, a, b) == (x, 2 * R.one, Y**2)
    assert linear_in(X**2 + Y**2, R) is None
    assert linear_in(Sg + Cg**2, R) is None  # sin(q) is never solved for
    assert solvable(0, R) and not solvable(2, R) and not solvable(3, R)


def test_indices_dimension_degree():
    R = QQ[x, y, S, C]
    X, Y, Sg, Cg = R.gens
    assert involved_indices(X * Sg + 1, R) == [0, 2]
    assert dimension([X * Sg, Cg + Y], R) == 3  # x, y and the angle q
    assert dimension([Sg * Cg], R) == 1
    assert largest_degree(X**2 * Y + Sg) == 3 and largest_degree(R.one) == 0


def test_rational_norm_and_domain():
    n = rational_norm(x - sqrt(3), x)
    assert n == Poly(x**2 - 3, x)
    n = rational_norm(x - sqrt(2) - sqrt(3), x)
    assert n is not None and n.rem(Poly(minimal_polynomial(sqrt(2) + sqrt(3), x), x)).is_zero
    assert rational_domain(Poly(x**2 - 3, x)) and not rational_domain(Poly(x - sqrt(3), x))
    assert rational_norm(x - 2 ** Rational(1, 3), x) == Poly(x**3 - 2, x)
