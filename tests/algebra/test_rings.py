"""Expressions as columns of a sparse polynomial ring, and back (``screwsym.algebra.rings``).

The oracle is SymPy's ``cancel`` on the expressions the columns came from: each ring
column is its matrix column times its scale, as functions (on the unit circle of each
angle, checked at rational points of the circle).  ``vanishes`` and ``circle_normal`` are
checked against multiples of ``sin**2 + cos**2 - 1`` and against values on the circle.
"""

from __future__ import annotations

import random

import pytest
from sympy import (
    QQ,
    ImmutableMatrix,
    Poly,
    Rational,
    cancel,
    cos,
    exp,
    expand,
    fraction,
    sin,
    sqrt,
    symbols,
    tan,
)

from screwsym.algebra.circle import on_circle
from screwsym.algebra.rings import (
    PolyColumns,
    circle_normal,
    field_element,
    number_field,
    rational_parts,
    ring_element,
    ring_with,
    to_expr,
    to_ring,
    vanishes,
)

x, y, z = symbols("x y z")
q = symbols("q", real=True)


def random_polynomial(rng: random.Random, atoms, surd=None, terms: int = 3):
    e = 0
    for _ in range(terms):
        c = Rational(rng.randint(-6, 6), rng.randint(1, 3))
        if surd is not None and rng.random() < 0.4:
            c += rng.randint(-2, 2) * surd
        m = c
        for a in atoms:
            m *= a ** rng.randint(0, 2)
        e += m
    return e


def random_matrix(rng: random.Random, rows: int, cols: int, atoms, surd=None):
    """Entries: polynomials, some divided by a polynomial (a rational function)."""
    entries = []
    for _ in range(rows * cols):
        e = random_polynomial(rng, atoms, surd)
        if rng.random() < 0.3:
            den = random_polynomial(rng, atoms[:2], None, terms=2)
            if den != 0:
                e = e / den
        entries.append(e)
    return ImmutableMatrix(rows, cols, entries)


def at_circle_points(e, points):
    return [cancel(e.subs({sin(q): s, cos(q): c}).subs({x: v, y: -3}))
            for s, c in points for v in (2, Rational(-1, 3))]


CIRCLE = [on_circle(Rational(k, 7)) for k in (-5, 1, 3, 11)]


@pytest.mark.parametrize("kind", ["QQ", "sqrt3", "circle"])
@pytest.mark.parametrize("case", range(5))
def test_columns_are_the_matrix_columns_times_their_scales(kind, case):
    rng = random.Random(f"{case}-{kind}")
    atoms = [sin(q), cos(q), x] if kind == "circle" else [x, y, z]
    M = random_matrix(rng, 3, 2, atoms, sqrt(3) if kind == "sqrt3" else None)
    rg = to_ring(M)
    assert isinstance(rg, PolyColumns) and len(rg.cols) == M.cols == len(rg.scales)
    assert all(len(col) == M.rows for col in rg.cols)
    R = rg.ring
    assert R.domain == (QQ.algebraic_field(sqrt(3)) if kind == "sqrt3" else QQ)
    for j, col in enumerate(rg.cols):
        scale = to_expr(rg.scales[j], R)
        assert scale != 0
        for i, e in enumerate(col):
            diff = to_expr(e, R) - scale * M[i, j]
            if kind == "circle":  # equal on the circle, not as free symbols
                assert set(at_circle_points(diff, CIRCLE)) == {0}
                assert numerator_and_denominator_reduced(to_expr(e, R))
            else:
                assert cancel(diff) == 0
            # and polynomial: a ring element of degree <= 1 in cos(q) on the circle
            assert to_expr(e, R).is_polynomial(*atoms)
    # the check sees a wrong column
    wrong = to_expr(rg.cols[0][0], R) + 1 - to_expr(rg.scales[0], R) * M[0, 0]
    if kind == "circle":
        assert set(at_circle_points(wrong, CIRCLE)) != {0}
    else:
        assert cancel(wrong) != 0


def test_to_ring_cos_reduced_and_sin_cos_symbols():
    M = ImmutableMatrix([[cos(q) ** 3, x / (1 + cos(q))], [sin(q) ** 2 + cos(q) ** 2 - 1, 1 / x]])
    rg = to_ring(M)
    R = rg.ring
    assert rg.cols[0][1] == R.zero  # sin**2 + cos**2 - 1 is zero in the ring
    assert expand(to_expr(rg.cols[0][0], R) - cos(q) * (1 - sin(q) ** 2)) == 0
    assert set(rg.gens) == {x} | {g for g in R.symbols if g != x}
    assert expand(to_expr(rg.scales[1], R) - x * (1 + cos(q))) == 0


@pytest.mark.parametrize("bad", [tan(x), sqrt(x), exp(x), x**Rational(1, 3)])
def test_entries_that_are_not_rational_functions_are_refused(bad):
    with pytest.raises(ValueError, match="^screws: expected entries"):
        to_ring(ImmutableMatrix([[x, bad]]))
    with pytest.raises(ValueError, match="^joints: expected geometry"):
        rational_parts([bad + 1], "joints: expected geometry")


def test_rational_parts():
    syms, numbers, parts = rational_parts([x / y + sqrt(3), sin(q) * z], "what")
    assert [str(s) for s in syms] == sorted(str(s) for s in syms)
    assert {str(s) for s in syms} >= {"x", "y", "z"}
    assert numbers == [sqrt(3)]
    assert len(parts) == 4 and parts[1] == y  # numerators and denominators, in turn


def test_number_field():
    assert number_field(()) == QQ
    K = number_field((sqrt(3),))
    assert K.is_Algebraic and K.ext.as_expr() == sqrt(3)
    assert number_field((sqrt(2), sqrt(3))).mod.degree() == 4


@pytest.mark.parametrize("case", range(6))
def test_field_element_is_from_sympy(case):
    rng = random.Random(f"{case}-fe")
    K = number_field((sqrt(3),))
    big = Rational(rng.randint(-10**30, 10**30), rng.randint(1, 10**25))
    c = big + Rational(rng.randint(-9, 9), rng.randint(1, 9)) * sqrt(3)
    assert field_element(K, c) == K.from_sympy(c)
    assert field_element(K, c) != K.from_sympy(c + 1)
    assert field_element(QQ, big) == QQ.from_sympy(big)


@pytest.mark.parametrize("case", range(6))
def test_to_expr_and_ring_element_are_inverse(case):
    rng = random.Random(f"{case}-expr")
    e = expand(random_polynomial(rng, [sin(q), cos(q), x], sqrt(3), terms=4))
    rg = to_ring(ImmutableMatrix([e, y]))
    R = rg.ring
    p = ring_element(e, R)
    assert expand(to_expr(p, R) - e) == 0
    assert ring_element(to_expr(p, R), R) == p
    assert ring_element(e + 1, R) != p


@pytest.mark.parametrize("case", range(8))
def test_vanishes_on_multiples_of_the_circle(case):
    rng = random.Random(f"{case}-vanish")
    g = random_polynomial(rng, [sin(q), cos(q), x], sqrt(3) if case % 2 else None)
    circle = sin(q) ** 2 + cos(q) ** 2 - 1
    assert vanishes(expand(g * circle)) is True
    assert vanishes(expand(g * circle) / (x + 2)) is True
    # a non-zero polynomial of degree <= 1 in cos does not vanish on the circle
    low = random_polynomial(rng, [sin(q), x], None) + cos(q) * (x + 1)
    assert vanishes(low) is False
    assert vanishes(expand(g * circle) + low) is False


def test_vanishes_without_angles_is_cancel():
    assert vanishes((x**2 - 1) / (x - 1) - x - 1) is True
    assert vanishes((x + sqrt(3)) ** 2 - x**2 - 2 * sqrt(3) * x - 3) is True
    assert vanishes(x - y) is False


def numerator_and_denominator_reduced(n) -> bool:
    """Whether both parts of ``n`` have degree <= 1 in cos(q)."""
    return all(Poly(part.subs(cos(q), y), y).degree() <= 1 for part in fraction(n))


@pytest.mark.parametrize("case", range(6))
def test_circle_normal_of_a_polynomial_is_idempotent_and_agrees_on_the_circle(case):
    rng = random.Random(f"{case}-normal-poly")
    e = random_polynomial(rng, [sin(q), cos(q), x], terms=4) + cos(q) ** 3
    n = circle_normal(e)
    assert circle_normal(n) == n
    assert fraction(n)[1] == 1 and numerator_and_denominator_reduced(n)
    for s, c in CIRCLE:
        at = {sin(q): s, cos(q): c, x: Rational(3, 2)}
        assert n.subs(at) == e.subs(at)
    # the check sees a wrong normal form: cos**3 left as cos
    wrong = n - cos(q) ** 3 + cos(q)
    s, c = CIRCLE[0]
    at = {sin(q): s, cos(q): c, x: Rational(3, 2)}
    assert wrong.subs(at) != e.subs(at)


@pytest.mark.parametrize("case", range(6))
def test_circle_normal_of_a_fraction_agrees_on_the_circle(case):
    rng = random.Random(f"{case}-normal")
    num = random_polynomial(rng, [sin(q), cos(q), x], terms=4) + cos(q) ** 3
    den = random_polynomial(rng, [sin(q), cos(q)], terms=2) + 7
    e = num / den
    n = circle_normal(e)
    assert numerator_and_denominator_reduced(n)
    # idempotent (test_circle_normal_of_a_fraction_is_idempotent: once it was not), and the
    # same function
    assert circle_normal(n) == n
    assert cancel(circle_normal(n) - n) == 0
    # the same value as e at rational points of the circle
    for s, c in CIRCLE:
        at = {sin(q): s, cos(q): c, x: Rational(3, 2)}
        if den.subs(at) != 0:
            assert cancel(n.subs(at) - e.subs(at)) == 0
    # and the check sees a wrong normal form: one added sin**2 + cos**2 (1 on the circle)
    s, c = CIRCLE[0]
    at = {sin(q): s, cos(q): c, x: Rational(3, 2)}
    assert cancel((n + cos(q) ** 2 + sin(q) ** 2).subs(at) - e.subs(at)) != 0


def test_circle_normal_of_a_fraction_is_idempotent():
    n = circle_normal(1 / (sin(q) ** 2 * cos(q) ** 2 + 1))
    assert circle_normal(n) == n


def test_circle_normal_known():
    assert circle_normal(sin(q) ** 3 + sin(q) * cos(q) ** 2) == sin(q)
    assert circle_normal(x + 1) == x + 1  # no angle: unchanged


def test_ring_with_adds_the_symbols_of_the_relation():
    M = ImmutableMatrix([[x, 1], [2, y]])
    rg = ring_with(M, z**2 + x - 1)
    assert set(rg.ring.symbols) == {x, y, z}
    assert len(rg.cols) == 2
    plain = to_ring(M)
    for a, b in zip(rg.cols, plain.cols, strict=True):
        assert [to_expr(e, rg.ring) for e in a] == [to_expr(e, plain.ring) for e in b]
    assert ring_element(z**2 + x - 1, rg.ring) != rg.ring.zero
