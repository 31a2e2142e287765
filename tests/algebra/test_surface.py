"""Ranks on a hypersurface, by modular points and Groebner bases (``screwsym.algebra.surface``).

Oracles: SymPy's ``reduced``/``groebner`` for membership in the ideal of the surface (a
null vector must be one modulo the relation), brute force over ``GF(p)`` for the roots
and the values mod ``p``, and circles built through known points for ``meeting``.
Seeded per case; the polynomials mod p come from Hypothesis.
"""

from __future__ import annotations

import random
from functools import lru_cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import QQ, ImmutableMatrix, Matrix, Poly, Rational, cos, groebner, reduced, sin, sqrt
from sympy import symbols as sym
from sympy.ntheory import sqrt_mod

from screwsym.algebra.circle import trig_symbol
from screwsym.algebra.rings import ring_element, ring_with
from screwsym.algebra.surface import (
    PRIMES,
    Unlucky,
    at_point,
    groebner_ideal,
    meeting,
    modular,
    null_on_surface,
    point_on,
    rank_on,
    roots_mod,
    term_mod,
    zero_on_surface,
)

x, y, z = sym("x y z")
SETTINGS = settings(max_examples=60, deadline=None, derandomize=True)


@lru_cache(maxsize=16)
def basis(relations: tuple, gens: tuple) -> list:
    return list(groebner(list(relations), *gens, order="lex"))


def in_ideal(e, relations, gens) -> bool:
    """Whether ``e`` is in the ideal of ``relations`` (SymPy: the remainder modulo a
    Groebner basis)."""
    _, rem = reduced(e, basis(tuple(relations), tuple(gens)), *gens, order="lex")
    return rem == 0


def test_null_on_surface_two_by_two():
    fe = x**2 + y**2 - 2
    M = ImmutableMatrix([[x, -1], [y**2 - 2, x]])  # det = x**2 + y**2 - 2
    rank, members, null = null_on_surface(M, fe)
    assert rank == 1 and len(members) == 1 and null.shape == (2, 1)
    for e in M * null:
        assert in_ideal(e, [fe], (x, y))
    assert not all(in_ideal(e, [fe], (x, y)) for e in null)  # not zero on the surface
    # generically the columns are independent: no null vector off the surface
    assert Matrix(M).rank() == 2


@pytest.mark.parametrize("case", range(4))
def test_null_on_surface_columns_dependent_exactly_on_the_surface(case):
    rng = random.Random(f"{case}-null")

    def poly(top=1):
        return sum(rng.randint(-3, 3) * x ** rng.randint(0, top) * y ** rng.randint(0, top)
                   for _ in range(2)) or 1

    fe = x**2 + y**2 - 2
    c1 = Matrix([poly() for _ in range(4)])
    c2 = Matrix([poly() for _ in range(4)])
    a, b = poly(), poly()
    d = Matrix([poly() for _ in range(4)])
    c3 = (a * c1 + b * c2 + fe * d).expand()  # = a c1 + b c2 exactly where fe = 0
    M = ImmutableMatrix(Matrix.hstack(c1, c2, c3))
    assert M.subs({x: 7, y: -5}).rank() == 3  # generically independent (at a point)
    rank, members, null = null_on_surface(M, fe)
    assert rank == 2 and null.shape == (3, 1)
    v = list(null)
    for e in (M * null):
        assert in_ideal(e.expand(), [fe], (x, y))
    # the null vector is (a, b, -1) up to a factor, modulo the relation
    w = [a, b, -1]
    for i in range(3):
        for j in range(i + 1, 3):
            assert in_ideal((v[i] * w[j] - v[j] * w[i]).expand(), [fe], (x, y))
    # the check rejects a wrong vector: (a, b, 1)
    assert not all(in_ideal((M * Matrix([a, b, 1]))[i].expand(), [fe], (x, y))
                   for i in range(4))


def test_null_on_surface_full_rank_and_zero_columns():
    fe = x**2 + y**2 - 2
    rank, members, null = null_on_surface(ImmutableMatrix([[x, 1], [y, 0]]), fe)
    assert rank == 2 and members == (0, 1) and null.shape == (2, 0)
    # every column zero on the surface: rank 0, the whole space null
    M = ImmutableMatrix([[fe * x, fe], [0, fe * y]])
    rank, members, null = null_on_surface(M, fe)
    assert rank == 0


def test_rank_on_returns_a_minor_nonzero_on_the_surface():
    M = ImmutableMatrix([[x, -1], [y**2 - 2, x], [y, 1]])
    fe = x**2 + y**2 - 2
    rg = ring_with(M, fe)
    R = rg.ring
    f = ring_element(fe, R)
    rank, rows, cols, minor, G = rank_on([tuple(c) for c in rg.cols], R, f)
    assert rank == 2 and len(rows) == len(cols) == 2
    assert G == groebner_ideal([f], R)
    assert minor.rem(G)  # non-zero modulo the surface
    B = [tuple(c) for c in rg.cols]
    sub = Matrix([[R.to_sympy(B[i][j]) for j in cols] for i in rows])
    assert minor == R.from_sympy(sub.det().expand())
    # every member's products with the null vectors of the minor's rows are in the ideal:
    # here, with rank 2 of 2 columns, there is nothing left to check but the rank itself
    assert Matrix(M).rank() == 2


def test_zero_on_surface():
    fe = x**2 + y**2 - 2
    assert zero_on_surface([(x**2 + y**2 - 2) * (x + y), x**4 - y**4 - 2 * x**2 + 2 * y**2], fe)
    assert zero_on_surface([(fe * x) / (y + 1)], fe)
    assert not zero_on_surface([x**2 - 2], fe)  # zero at y = 0 only
    assert not zero_on_surface([fe * x, y], fe)


def test_zero_on_surface_knows_the_circle():
    q = sym("q", real=True)
    fe = x - cos(q)
    assert zero_on_surface([x**2 + sin(q) ** 2 - 1], fe)  # on x = cos(q): cos**2 + sin**2 - 1
    assert not zero_on_surface([x**2 + sin(q) ** 2], fe)


def test_groebner_ideal_is_sympys_with_the_circles():
    q = sym("q", real=True)
    S, C = trig_symbol(sin, q), trig_symbol(cos, q)
    R = QQ[x, S, C]
    X, Sg, Cg = R.gens
    G = groebner_ideal([X * Cg - 1], R)
    expected = groebner([x * C - 1, S**2 + C**2 - 1], x, S, C, order="lex")
    assert sorted(map(str, (R.to_sympy(g) for g in G))) == \
        sorted(map(str, (g.as_expr() for g in expected.exprs)))


@SETTINGS
@given(st.sampled_from([2, 3, 5, 7, 11, 13]), st.lists(st.integers(-30, 30), max_size=7))
def test_roots_mod_by_brute_force(p, coeffs):
    got = sorted(roots_mod(coeffs, p))

    def value(t):
        v = 0
        for c in coeffs:
            v = (v * t + c) % p
        return v

    if all(c % p == 0 for c in coeffs):
        assert got == []  # the zero polynomial: no list of all of GF(p)
    else:
        assert got == [t for t in range(p) if value(t) == 0]


def test_roots_mod_known():
    assert sorted(roots_mod([1, 0, 1], 5)) == [2, 3]  # x**2 + 1 mod 5
    assert roots_mod([1, 0, 1], 7) == []  # -1 is no square mod 7
    assert sorted(roots_mod([1, -2, 1], 7)) == [1]  # (x - 1)**2: once
    # the brute force sees a wrong answer
    assert sorted(roots_mod([1, 0, 1], 5)) != [2]


@pytest.mark.parametrize("case", range(6))
def test_modular_and_term_mod(case):
    rng = random.Random(f"{case}-mod")
    p = rng.choice([47, 73, PRIMES[1]])  # 3 is a square mod each (p = +-1 mod 12)
    c = QQ(rng.randint(-50, 50), rng.randint(1, 50))
    v = modular(c, QQ, p, None)
    assert (v * int(c.denominator) - int(c.numerator)) % p == 0
    assert (v + 1) % p != v
    # over Q(sqrt 3): r sqrt(3) + s at theta, a square root of 3 mod p
    K = QQ.algebraic_field(sqrt(3))
    r, t = QQ(rng.randint(-9, 9), rng.randint(1, 9)), QQ(rng.randint(-9, 9), rng.randint(1, 9))
    a = K.convert(r) * K.from_sympy(sqrt(3)) + K.convert(t)
    theta = sqrt_mod(3, p)  # SymPy's
    assert theta is not None
    expected = (modular(r, QQ, p, None) * theta + modular(t, QQ, p, None)) % p
    assert modular(a, K, p, theta) == expected
    # a term at a point, one symbol skipped
    point = [rng.randrange(p) for _ in range(3)]
    m = (2, 0, 3)
    assert term_mod(m, c, QQ, p, None, point) == v * pow(point[0], 2, p) * pow(point[2], 3, p) % p
    assert term_mod(m, c, QQ, p, None, point, skip=(0,)) == v * pow(point[2], 3, p) % p


def test_modular_refuses_a_denominator_divisible_by_p():
    with pytest.raises(Unlucky):
        modular(QQ(1, 7), QQ, 7, None)


@pytest.mark.parametrize("case", range(6))
def test_point_on_is_on_the_surface_mod_p(case):
    rng = random.Random(f"{case}-point")
    q = sym("q", real=True)
    S, C = trig_symbol(sin, q), trig_symbol(cos, q)
    R = QQ[x, y, S, C]
    X, Y, Sg, Cg = R.gens
    f = [X**2 + Y**2 - 2, X * Sg - Y * Cg + 1, Sg + 2 * Cg - 1, X * Y**3 - Cg][case % 4]
    p = PRIMES[case % len(PRIMES)]
    for k in range(10):
        try:
            point, theta = point_on(f, R, p, random.Random(f"{case}-{k}"))
            break
        except Unlucky:
            continue
    else:
        pytest.fail("no point in ten tries")
    assert theta is None
    (value,), = at_point([[f]], R, p, point, None)
    assert value == 0
    assert (point[2] ** 2 + point[3] ** 2 - 1) % p == 0  # on the circle mod p
    (other,), = at_point([[f + 1]], R, p, point, None)
    assert other == 1  # the check sees a polynomial that is not zero there
    # at_point is the value of each entry, by Python's integers
    g = 3 * X * Y - Sg / 2
    (gv,), = at_point([[g]], R, p, point, None)
    assert gv == (3 * point[0] * point[1] - point[2] * pow(2, -1, p)) % p
    del rng


def circle_through(p1, p2, k):
    """The circle through the points p1, p2 whose centre is the midpoint moved k times
    along the perpendicular: an equation in x, y with rational coefficients."""
    mx, my = (p1[0] + p2[0]) / 2, (p1[1] + p2[1]) / 2
    cx, cy = mx - k * (p2[1] - p1[1]), my + k * (p2[0] - p1[0])
    r2 = (p1[0] - cx) ** 2 + (p1[1] - cy) ** 2
    return ((x - cx) ** 2 + (y - cy) ** 2 - r2).expand()


@pytest.mark.parametrize("case", range(6))
def test_meeting_of_two_circles_through_known_points(case):
    rng = random.Random(f"{case}-meet")
    p1 = (Rational(rng.randint(-5, 5)), Rational(rng.randint(-5, 5)))
    p2 = p1
    while p2 == p1:
        p2 = (Rational(rng.randint(-5, 5)), Rational(rng.randint(-5, 5), rng.randint(1, 2)))
    k1 = Rational(rng.randint(-3, 3), rng.randint(1, 3))
    k2 = k1
    while k2 == k1:
        k2 = Rational(rng.randint(-3, 3), rng.randint(1, 3))
    f_expr, h_expr = circle_through(p1, p2, k1), circle_through(p1, p2, k2)
    for pt in (p1, p2):
        assert f_expr.subs({x: pt[0], y: pt[1]}) == h_expr.subs({x: pt[0], y: pt[1]}) == 0
    R = QQ[x, y]
    g = meeting(R.from_sympy(f_expr), h_expr, R)
    assert g is not None and g != R.zero
    (s,) = [R.symbols[i] for i in range(2) if g.degree(i) > 0]  # in one symbol
    coords = {pt[R.symbols.index(s)] for pt in (p1, p2)}
    assert set(Poly(R.to_sympy(g), s).real_roots()) == coords
    assert all(g(*pt) == 0 for pt in (p1, p2))
    # the comparison sees a third point that is not a meeting point
    assert set(Poly(R.to_sympy(g), s).real_roots()) != coords | {Rational(99)}


def test_meeting_known_cases():
    R = QQ[x, y]
    X, Y = R.gens
    f = X**2 + Y**2 - 2
    g = meeting(f, (x - 2) ** 2 + y**2 - 2, R)  # meet at (1, 1) and (1, -1)
    assert g in (X - 1, Y**2 - 1)
    assert meeting(f, x**2 + y**2 - 4, R) == R.zero  # concentric: no common point at all
    assert meeting(f, x**2 + y**2 - 2, R) is None  # the same curve: no finite meeting
    assert meeting(f, z + x, R) is None  # a symbol the ring has not
    R3 = QQ[x, y, z]
    assert meeting(R3.from_sympy(x**2 + y**2 + z**2 - 1), x * y * z - 1, R3) is None
