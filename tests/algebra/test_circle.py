"""``sin(q)``, ``cos(q)`` as two ring symbols on the unit circle (``screwsym.algebra.circle``).

The normal form (degree at most 1 in ``cos(q)``) is checked against the circle itself:
idempotent, zero exactly on the ideal of ``sin**2 + cos**2 - 1``, equal in value to the
polynomial it reduces at the rational points of the circle (``on_circle``), and, for the
half-angle map back (``from_half_angle``), parallel to the vector it came from.  Random
polynomials are seeded per case; the rationals come from Hypothesis.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import (
    QQ,
    And,
    Eq,
    Integer,
    Or,
    Rational,
    cancel,
    cos,
    expand,
    expand_trig,
    pi,
    radsimp,
    reduced,
    sin,
    sqrt,
    symbols,
    tan,
)

from screwsym.algebra.circle import (
    TRIG_BACK,
    angles_of,
    circle_relations,
    circle_simplify,
    from_half_angle,
    half_angle_symbol,
    has_trig,
    on_circle,
    reduce_circle,
    sample_point,
    trig_entries,
    trig_normal,
    trig_substitute,
    trig_symbol,
)

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True)
rationals = st.fractions(min_value=-30, max_value=30, max_denominator=40).map(Rational)

q, r, x = symbols("q r x", real=True)
S, C = trig_symbol(sin, q), trig_symbol(cos, q)
S2, C2 = trig_symbol(sin, r), trig_symbol(cos, r)
#: x, sin(q), cos(q); and a ring with two angles, cos first
R1 = QQ[x, S, C]
R2 = QQ[C2, C, x, S, S2]


def random_poly(rng: random.Random, R, terms: int = 5, top: int = 3):
    d = {}
    for _ in range(terms):
        m = tuple(rng.randint(0, top) for _ in R.gens)
        d[m] = QQ(rng.randint(-9, 9), rng.randint(1, 4))
    return R.ring.from_dict(d)


def circle_point(R, rng: random.Random) -> list:
    """A rational point of ``R``'s symbols, each angle's (sin, cos) on the circle (an oracle
    apart from ``sample_point``: ``t = tan(q/2)`` drawn here)."""
    point = [QQ(rng.randint(-20, 20), rng.randint(1, 5)) for _ in R.gens]
    for _, ci, si in angles_of(R):
        t = Fraction(rng.randint(-30, 30), rng.randint(1, 30))
        point[si] = QQ(2 * t / (1 + t * t))
        point[ci] = QQ((1 - t * t) / (1 + t * t))
    return point


def cos_degrees(p, R) -> list:
    return [p.degree(ci) for _, ci, _ in angles_of(R)]


def test_trig_symbols_are_unique_and_map_back():
    assert trig_symbol(sin, q) is S and trig_symbol(cos, q) is C
    assert S != C and S != S2
    assert TRIG_BACK[S] == sin(q) and TRIG_BACK[C2] == cos(r)
    assert S.is_real


def test_angles_of_finds_each_angles_indices():
    assert angles_of(R1) == ((q, 2, 1),)
    assert sorted(angles_of(R2), key=str) == [(q, 1, 3), (r, 0, 4)]
    assert angles_of(QQ[x, S]) == ((q, None, 1),)  # sin alone
    assert angles_of(QQ[x]) == ()


def test_circle_relations():
    X, Sg, Cg = R1.gens
    assert circle_relations(R1) == [Sg**2 + Cg**2 - 1]
    assert len(circle_relations(R2)) == 2
    assert circle_relations(QQ[x, S]) == []  # sin without cos: no relation


@pytest.mark.parametrize("R", [R1, R2], ids=["one-angle", "two-angles"])
@pytest.mark.parametrize("case", range(6))
def test_reduce_circle_is_a_normal_form(R, case):
    rng = random.Random(f"{case}-reduce")
    p = random_poly(rng, R)
    red = reduce_circle(p, R)
    assert all(d <= 1 for d in cos_degrees(red, R))
    assert reduce_circle(red, R) == red  # idempotent
    # it differs from p by a multiple of the relations: the same value on the circle
    for k in range(3):
        point = circle_point(R, random.Random(f"{case}-{k}-point"))
        assert red(*point) == p(*point)
    # and the same element: p - red is in the ideal of the circles (SymPy's reduced)
    _, rem = reduced(R.to_sympy(p - red), [R.to_sympy(g) for g in circle_relations(R)],
                     *R.symbols)
    assert rem == 0


@pytest.mark.parametrize("R", [R1, R2], ids=["one-angle", "two-angles"])
@pytest.mark.parametrize("case", range(6))
def test_reduce_circle_is_zero_exactly_on_the_circle(R, case):
    rng = random.Random(f"{case}-zero")
    g = random_poly(rng, R)
    relations = circle_relations(R)
    multiple = sum((random_poly(rng, R, terms=3, top=2) * h for h in relations), g * relations[0])
    assert multiple and reduce_circle(multiple, R) == R.zero
    # a non-zero polynomial of degree <= 1 in each cos is already the normal form, not zero
    low = R.ring.from_dict({m: c for m, c in random_poly(rng, R).items()
                            if all(m[ci] <= 1 for _, ci, _ in angles_of(R))}) + R.one
    assert reduce_circle(low, R) == low != R.zero
    assert reduce_circle(multiple + low, R) == low


def test_reduce_circle_leaves_rings_without_both_alone():
    Rs = QQ[x, S]
    p = Rs.gens[1] ** 4 + Rs.gens[0]
    assert reduce_circle(p, Rs) == p
    Rx = QQ[x]
    assert reduce_circle(Rx.gens[0] ** 5, Rx) == Rx.gens[0] ** 5
    assert reduce_circle(R1.zero, R1) == R1.zero


def test_a_wrong_normal_form_is_rejected_by_the_checks():
    X, Sg, Cg = R1.gens
    p = Cg**3 + X
    wrong = Cg + X  # drops the -sin**2 cos: differs on the circle
    point = circle_point(R1, random.Random("wrong"))
    assert wrong(*point) != p(*point)
    assert reduce_circle(p, R1) == Cg - Sg**2 * Cg + X != wrong
    # and a relation off the circle (x**2 + cos**2 - 1) is not reduced away
    assert reduce_circle(X**2 + Cg**2 - 1, R1) != R1.zero


@SETTINGS
@given(rationals)
def test_on_circle_lies_on_the_circle(t):
    s, c = on_circle(t)
    assert s**2 + c**2 == 1
    assert (s, c) != (0, -1)  # q = pi is the one point t never reaches
    assert s.is_Rational and c.is_Rational


@pytest.mark.parametrize("angle", [pi / 3, pi / 4, -2 * pi / 3, pi / 2, 0])
def test_on_circle_is_the_half_angle_parametrisation(angle):
    s, c = on_circle(tan(angle / 2))
    assert radsimp(cancel(s - sin(angle))) == 0 and radsimp(cancel(c - cos(angle))) == 0
    assert radsimp(cancel(s - cos(angle))) != 0 or angle == pi / 4  # sin and cos not swapped


@pytest.mark.parametrize("case", range(5))
def test_sample_point_is_rational_and_on_the_circle(case):
    point = sample_point(R2, random.Random(case))
    assert point == sample_point(R2, random.Random(case))  # seeded: the same point
    for _, ci, si in angles_of(R2):
        assert point[si] ** 2 + point[ci] ** 2 == 1
    assert all(QQ.of_type(v) for v in point)
    assert sample_point(R2, random.Random(case)) != sample_point(R2, random.Random(case + 100))


def test_trig_entries_and_trig_normal():
    a, b = trig_entries([sin(q) * cos(q) + x, sin(2 * q)])
    assert a == S * C + x
    assert expand(b - 2 * S * C) == 0
    assert trig_normal(sin(q) + x) == sin(q) + x
    assert trig_normal(cos(q + r)) == cos(q) * cos(r) - sin(q) * sin(r)
    assert trig_entries([x + 1]) == [x + 1]
    assert has_trig([x, cos(r)]) and not has_trig([x, q])


def test_circle_simplify_merges_the_two_points_of_one_sine():
    for s in (Rational(3, 5), Rational(1, 3), Integer(0)):
        c = sqrt(1 - s**2)
        both = And(Eq(sin(q), s), Or(Eq(cos(q), c), Eq(cos(q), -c)))
        assert circle_simplify(both) == Eq(sin(q), s)
        pairs = Or(And(Eq(cos(q), s), Eq(sin(q), c)), And(Eq(cos(q), s), Eq(sin(q), -c)))
        assert circle_simplify(pairs) == Eq(cos(q), s)
        # one point alone, or a wrong cosine, is not the whole line sin(q) = s
        one = And(Eq(sin(q), s), Eq(cos(q), c))
        assert circle_simplify(one) == one
        wrong = And(Eq(sin(q), s), Or(Eq(cos(q), c), Eq(cos(q), -c + 1)))
        assert circle_simplify(wrong) == wrong
    assert circle_simplify(Eq(x, 1)) == Eq(x, 1)


@pytest.mark.parametrize("case", range(6))
def test_trig_substitute_agrees_with_the_angle_it_sets(case):
    rng = random.Random(f"{case}-subs")
    t = Rational(rng.randint(-9, 9), rng.randint(1, 9))
    s, c = on_circle(t)
    expr = (sin(2 * q) * x + cos(q + r) - rng.randint(1, 5) * sin(q - 2 * r) * cos(3 * q)
            + sin(q) ** 2)
    got = trig_substitute(expr, {sin(q): s, cos(q): c})
    assert not got.has(q)
    # the oracle: the expression at the angle q = 2 atan(t), r and x at random values
    angle = 2 * math.atan(float(t))
    vals = {x: rng.uniform(-2, 2), r: rng.uniform(-3, 3)}
    expected = float(expr.subs(vals).subs(q, angle))
    assert math.isclose(float(got.subs(vals)), expected, rel_tol=1e-9, abs_tol=1e-9)
    # a wrong cosine (the other point with the same sine) gives another value
    other = float(trig_substitute(expr, {sin(q): s, cos(q): -c}).subs(vals))
    assert c == 0 or not math.isclose(other, expected, rel_tol=1e-9, abs_tol=1e-9)


def test_trig_substitute_without_angles_is_xreplace():
    assert trig_substitute(x + sin(r), {x: 2}) == 2 + sin(r)
    assert trig_substitute(x, {}) == x
    assert expand_trig(trig_substitute(sin(2 * q), {sin(q): 0, cos(q): -1})) == 0


def test_half_angle_symbol_is_one_per_angle():
    t = half_angle_symbol(q)
    assert half_angle_symbol(q) is t and half_angle_symbol(r) is not t
    assert t.is_real


def parallel(u: list, v: list) -> bool:
    """Whether two vectors over a field are parallel: every 2 x 2 minor is zero."""
    return all(not (u[i] * v[j] - u[j] * v[i])
               for i in range(len(u)) for j in range(i + 1, len(u)))


@pytest.mark.parametrize("case", range(6))
def test_from_half_angle_is_the_same_vector_up_to_a_factor(case):
    rng = random.Random(f"{case}-half")
    t = half_angle_symbol(q)
    F = QQ.frac_field(t, x)
    T, X = F.gens
    s, c = 2 * T / (1 + T**2), (1 - T**2) / (1 + T**2)

    def entry():
        e = F.zero
        for _ in range(3):
            e += QQ(rng.randint(-5, 5)) * s ** rng.randint(0, 2) * c ** rng.randint(0, 2) \
                * X ** rng.randint(0, 1)
        return e

    row = [entry(), entry(), F.zero, entry() * X]
    if not any(row):
        row[0] = F.one
    out = from_half_angle(row)
    # polynomials in sin(q), cos(q), x (no t, no denominator)
    assert not any(e.has(t) for e in out)
    assert all(e.is_polynomial(sin(q), cos(q), x) for e in out)
    assert out[2] == 0
    # written back in t (sin, cos at on_circle(t)): the same vector up to a factor
    st_, ct_ = on_circle(t)
    back = [F.from_sympy(cancel(e.xreplace({sin(q): st_, cos(q): ct_}))) for e in out]
    assert any(back) and parallel(back, row)
    # the check rejects a vector that is not parallel
    assert not parallel(back, [row[0] + X, *row[1:]])


def test_from_half_angle_known_row():
    t = half_angle_symbol(q)
    F = QQ.frac_field(t, x)
    T, X = F.gens
    # (sin(q)/2, x, 0): t/(1 + t**2) is sin(q)/2
    assert [expand(e) for e in from_half_angle([T / (1 + T**2), X, F.zero])] == [sin(q), 2 * x, 0]
