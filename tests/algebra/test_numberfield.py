"""Arithmetic over ``Q(theta)`` lifted to ``Q[x, theta]`` (``screwsym.algebra.numberfield``).

SymPy is the oracle throughout: ``Poly.factor_list`` over the same algebraic field
(``extension=``) for the factor lists, ``resultant`` with ``minimal_polynomial`` for the
norms, the ring's own ``gcd``/``lcm`` for the gcds, and its factorisation over the field
for every irreducibility claimed.  Inputs are seeded per case (``random.Random(case)``).
"""

from __future__ import annotations

import random

import pytest
from sympy import QQ, Mul, Poly, cbrt, expand, minimal_polynomial, resultant, sqrt, symbols

from screwsym.algebra.numberfield import (
    field_factor_list,
    field_gcd,
    field_lcm,
    field_norm,
    irreducible_over_field,
    lift,
    lifted_ring,
    lower,
    ring_gcd,
    theta_parts,
)

x, y = symbols("x y")
SURDS = {"sqrt3": sqrt(3), "sqrt2": sqrt(2)}
#: fields of degree 2, 3 and 4 (the norm has a shortcut for degree 2 only)
FIELDS = {"sqrt3": sqrt(3), "cbrt2": cbrt(2), "sqrt2+sqrt3": sqrt(2) + sqrt(3)}


def ring(a, gens=(x, y)):
    return QQ.algebraic_field(a)[gens]


def random_factor(rng: random.Random, a, surd: bool, degree: int):
    """A non-constant polynomial in x, y of total degree <= ``degree``, small integer
    coefficients, some of them ``m + n a`` where ``surd``."""
    monoms = [(i, j) for i in range(degree + 1) for j in range(degree + 1 - i)]
    while True:
        e = 0
        for i, j in monoms:
            c = rng.randint(-3, 3)
            if surd and rng.random() < 0.5:
                c += rng.randint(-2, 2) * a
            e += c * x**i * y**j
        e = expand(e)
        if e.has(x) or e.has(y):
            return e


def random_product(rng: random.Random, a):
    """A product of one to three random factors (at most one quadratic), one maybe squared."""
    n = rng.randint(1, 3)
    degrees = [2 if k == 0 and rng.random() < 0.5 else 1 for k in range(n)]
    factors = [random_factor(rng, a, rng.random() < 0.6, d) for d in degrees]
    powers = [1] * n
    powers[rng.randrange(n)] = rng.choice([1, 2])
    return expand(Mul(*(f**k for f, k in zip(factors, powers, strict=True))))


def sympy_factors(e, a, R):
    """SymPy's factor list of ``e`` over ``Q(a)``, as elements of ``R`` (SymPy's order)."""
    _, fl = Poly(e, x, y, extension=a).factor_list()
    return [(R.from_sympy(f.as_expr()), k) for f, k in fl]


@pytest.mark.parametrize("field", list(SURDS))
@pytest.mark.parametrize("case", range(8))
def test_factor_list_is_sympys_over_the_field(field, case):
    a = SURDS[field]
    R = ring(a)
    e = random_product(random.Random(f"{case}-1"), a)
    p = R.from_sympy(e)
    ours = field_factor_list(p, R)
    assert ours == sympy_factors(e, a, R)
    # and the factors (monic) multiply back to p up to its leading coefficient
    prod = R.one
    for f, k in ours:
        prod *= f**k
    assert prod * p.LC == p


def test_factor_list_known_cases():
    a = sqrt(3)
    R = ring(a)
    X, Y = R.gens
    s3 = R.domain.from_sympy(a)
    # x**2 - 3 is irreducible over Q, splits over Q(sqrt 3); x**2 - 2 does not
    p = (X**2 - 3) * (X**2 - 2) * (X + s3 * Y) ** 2
    got = {(R.to_sympy(f), k) for f, k in field_factor_list(p, R)}
    assert got == {(x - a, 1), (x + a, 1), (x**2 - 2, 1), (x + a * y, 2)}


def test_factor_list_over_q_is_the_rings():
    R = QQ[x, y]
    X, Y = R.gens
    p = 6 * (X + Y) ** 2 * (X**2 - 3)
    assert field_factor_list(p, R) == p.factor_list()[1]
    assert len(field_factor_list(p, R)) == 2  # x**2 - 3 stays whole over Q


def test_a_wrong_factor_list_is_rejected():
    a = sqrt(3)
    R = ring(a)
    e = random_product(random.Random("0-1"), a)
    ours = field_factor_list(R.from_sympy(e), R)
    assert ours != sympy_factors(expand(e * (x + 1)), a, R)
    assert ours != sympy_factors(expand(e + 1), a, R)
    assert [(f, k + 1) for f, k in ours] != sympy_factors(e, a, R)  # multiplicities count


def resultant_oracle(P, R):
    """``Res_theta(P, mp)`` by SymPy, as an element of the lifted ring."""
    L = lifted_ring(R)
    theta = L.symbols[-1]
    return L.from_sympy(expand(resultant(L.to_sympy(P), minimal_polynomial(R.domain.ext, theta),
                                         theta)))


def random_lifted(rng: random.Random, R):
    L = lifted_ring(R)
    deg = R.domain.mod.degree()
    d = {}
    for _ in range(rng.randint(1, 5)):
        m = (rng.randint(0, 2), rng.randint(0, 2), rng.randint(0, deg - 1))
        d[m] = QQ(rng.randint(-5, 5), rng.randint(1, 3))
    return L.ring.from_dict(d)


@pytest.mark.parametrize("field", list(FIELDS))
@pytest.mark.parametrize("case", range(8))
def test_norm_is_the_resultant_with_the_minimal_polynomial(field, case):
    R = ring(FIELDS[field])
    P = random_lifted(random.Random(f"{case}-2"), R)
    assert field_norm(P, R) == resultant_oracle(P, R)


@pytest.mark.parametrize("field", list(FIELDS))
def test_norm_edge_cases(field):
    R = ring(FIELDS[field])
    L = lifted_ring(R)
    X, Y, T = L.gens
    n = R.domain.mod.degree()
    assert field_norm(L.zero, R) == L.zero
    assert field_norm(X + Y, R) == (X + Y) ** n  # no theta: the n-th power
    for P in (T, T + X, 3 * T - 1):
        assert field_norm(P, R) == resultant_oracle(P, R)


def test_norm_in_one_symbol_vanishes_at_the_conjugates():
    R = ring(sqrt(3), (x,))
    L = lifted_ring(R)
    X, T = L.gens
    N = field_norm(X - T, R)  # x - sqrt(3): its norm is x**2 - 3
    assert N == X**2 - 3
    assert N != resultant_oracle(X + T + 1, R)  # the comparison sees a different element


@pytest.mark.parametrize("field", list(FIELDS))
@pytest.mark.parametrize("case", range(4))
def test_lift_and_lower_are_inverse_and_lower_multiplies(field, case):
    R = ring(FIELDS[field])
    rng = random.Random(f"{case}-3")
    L = lifted_ring(R)
    A, B = random_lifted(rng, R), random_lifted(rng, R)
    a, b = lower(A, R), lower(B, R)
    assert lift(a, R) == A and lift(b, R) == B  # theta's degree is below the field's
    # reduction modulo the minimal polynomial is a ring homomorphism
    assert lower(A * B, R) == a * b
    assert lower(A + B, R) == a + b
    # theta_parts: P = sum parts[k] theta**k
    theta = L.gens[-1]
    parts = theta_parts(A * B, R)
    assert sum((c * theta**k for k, c in enumerate(parts)), L.zero) == A * B
    assert all(c.degree(2) <= 0 for c in parts)
    # the value of a lifted polynomial at theta = the field's generator is the element's
    at = expand(L.to_sympy(A).subs(L.symbols[-1], R.domain.ext.as_expr()))
    assert R.from_sympy(at) == a
    assert R.from_sympy(at) != a + R.one


@pytest.mark.parametrize("field", list(SURDS))
@pytest.mark.parametrize("case", range(8))
def test_gcd_and_lcm_are_the_rings(field, case):
    a = SURDS[field]
    R = ring(a)
    rng = random.Random(f"{case}-4")
    g = R.from_sympy(random_factor(rng, a, rng.random() < 0.5, 1)) if case % 4 else R.one
    u = R.from_sympy(random_factor(rng, a, True, rng.randint(1, 2)))
    v = R.from_sympy(random_factor(rng, a, case % 2 == 0, 1))
    A, B = g * u, g * v
    assert field_gcd(A, B, R) == R.gcd(A, B)
    assert ring_gcd(A, B, R) == R.gcd(A, B)
    assert field_lcm(A, B, R) == R.lcm(A, B)
    if not g.is_ground:
        assert not field_gcd(A, B, R).rem(g)  # the common factor is found
        assert field_gcd(A * g, B * g, R) == R.gcd(A * g, B * g) != field_gcd(A, B, R)


def test_gcd_special_cases():
    R = ring(sqrt(3))
    X, Y = R.gens
    s3 = R.domain.from_sympy(sqrt(3))
    assert field_gcd(R.zero, X + s3, R) == R.gcd(R.zero, X + s3)
    assert field_gcd((X + 1) * (Y - 2), (X + 1) * Y, R) == X + 1  # both rational
    assert field_gcd(X + s3, X - s3, R) == R.one  # conjugates: coprime over the field
    assert field_gcd((X + s3) * Y, (X + s3) * (Y + 1), R) == X + s3
    Q = QQ[x, y]
    assert ring_gcd(Q.gens[0] * 2, Q.gens[0] ** 2, Q) == Q.gens[0]


def random_irreducible_over_q(rng: random.Random):
    """A random polynomial of Q[x, y], irreducible over Q, involving both symbols."""
    while True:
        e = random_factor(rng, 0, False, rng.randint(1, 3))
        p = Poly(e, x, y)
        if p.degree(x) > 0 and p.degree(y) > 0 and p.is_irreducible:
            return e


def as_lifted(e, R):
    """A rational polynomial of x, y as an element of ``Q[x, y, theta]`` (no theta)."""
    L = lifted_ring(R)
    return L.from_sympy(e)


@pytest.mark.parametrize("field", list(SURDS))
@pytest.mark.parametrize("case", range(10))
def test_irreducibility_is_never_claimed_for_a_product(field, case):
    # both factors involve both symbols: a product with no content in either symbol
    R = ring(SURDS[field])
    rng = random.Random(f"{case}-5")
    f, g = random_irreducible_over_q(rng), random_irreducible_over_q(rng)
    product = as_lifted(expand(f * g), R)
    assert irreducible_over_field(product, R, seed=case) is False


@pytest.mark.parametrize("field", list(SURDS))
@pytest.mark.parametrize("case", range(10))
def test_irreducibility_claimed_only_when_sympy_agrees(field, case):
    a = SURDS[field]
    R = ring(a)
    e = random_irreducible_over_q(random.Random(f"{case}-6"))
    claimed = irreducible_over_field(as_lifted(e, R), R, seed=case)
    _, fl = Poly(e, x, y, extension=a).factor_list()
    if claimed:
        assert len(fl) == 1 and fl[0][1] == 1


def test_irreducibility_over_the_field_known_cases():
    R = ring(sqrt(3))
    L = lifted_ring(R)
    X, Y, _ = L.gens
    assert irreducible_over_field(X**2 - 2, R) is True
    assert irreducible_over_field(X**2 - 3, R) is False  # (x - sqrt 3)(x + sqrt 3)
    assert irreducible_over_field(X**2 - 3 * Y**2, R) is False
    assert irreducible_over_field(X**2 - 2 * Y**2 + Y, R) is True
    assert irreducible_over_field(L.one * 5, R) is True  # a constant: nothing to split


def test_irreducibility_is_never_claimed_for_a_product_with_content():
    R = ring(sqrt(3))
    X, Y, _ = lifted_ring(R).gens
    assert irreducible_over_field(X * (X + Y**3), R) is False  # y has degree 3: the main symbol



# ---------------------------------------------------------------- square roots of primes (surds)
from screwsym.algebra.numberfield import reduce_surds, surd_normal, surd_split  # noqa: E402


@pytest.mark.parametrize("n", [2, 3, 12, 18, 72, QQ(3, 8), QQ(50, 27), 2 * 3 * 5 * 7 * 11, 1, QQ(1, 4)])
def test_surd_split_is_the_square_root(n):
    from sympy import Rational

    n = Rational(n.numerator, n.denominator) if hasattr(n, "denominator") else Rational(n)
    k, primes = surd_split(n)
    assert list(primes) == sorted(set(primes)) and all(Poly(x - p, x).is_irreducible for p in primes)
    assert k * Mul(*(sqrt(p) for p in primes)) == sqrt(n)  # SymPy's own root of n
    with pytest.raises(ValueError, match="positive rational"):
        surd_split(-n)


def random_surd_number(rng: random.Random, depth: int):
    """Products of sums of rationals times square roots of small rationals (seeded)."""
    from sympy import Rational

    if depth == 0:
        return sum((Rational(rng.randint(-5, 5), rng.randint(1, 4)) * sqrt(Rational(rng.choice([2, 3, 6, 8, 12, 5, 1]),
                                                                                    rng.choice([1, 2, 3])))
                    for _ in range(rng.randint(1, 3))), Rational(0))
    return random_surd_number(rng, depth - 1) * random_surd_number(rng, depth - 1) + random_surd_number(rng, 0)


@pytest.mark.parametrize("case", range(12))
def test_surd_normal_is_sympys_expansion_and_no_other_number(case):
    rng = random.Random(case)
    e = random_surd_number(rng, 2)
    normal = surd_normal(e)
    # SymPy merges products of square roots of integers, so its expansion is the normal form too
    assert expand(normal - e) == 0
    # each term a rational times the root of a square-free integer, no two alike
    from sympy import Add, factorint

    roots = [t.as_coeff_Mul()[1] for t in Add.make_args(normal)]
    assert len(set(roots)) == len(roots)
    for r in roots:
        assert r == 1 or r.is_Pow and r.exp == QQ(1, 2) and r.base.is_Integer \
            and all(k == 1 for k in factorint(r.base).values())
    # a perturbed value is told apart
    assert expand(surd_normal(e + sqrt(2) / 1000) - e) != 0


def test_surd_normal_refuses_what_is_not_a_sum_of_products_of_roots():
    assert surd_normal(1 / (1 + sqrt(3))) is None
    assert surd_normal(cbrt(2) + 1) is None
    assert surd_normal(sqrt(2) ** 40 - 2**20) == 0
    from sympy import pi
    assert surd_normal(pi * sqrt(2)) is None


@pytest.mark.parametrize("case", range(8))
def test_reduce_surds_is_the_normal_form_over_the_field(case):
    """Zero exactly when the value at r_p = sqrt(p) is zero: SymPy's expansion as the oracle."""
    from sympy.polys.rings import ring as make_ring

    rng = random.Random(100 + case)
    R, t, r2, r3, r5 = make_ring("t r2 r3 r5", QQ)
    gens = [t, r2, r3, r5]
    P = R.zero
    for _ in range(6):
        term = R(QQ(rng.randint(-4, 4), rng.randint(1, 3)))
        for g in gens:
            term *= g ** rng.randint(0, 3)
        P += term
    reduced = reduce_surds(P, [(1, 2), (2, 3), (3, 5)])
    assert all(m[i] <= 1 for m in reduced.itermonoms() for i in (1, 2, 3))
    T = symbols("t")
    value = {R.symbols[0]: T, R.symbols[1]: sqrt(2), R.symbols[2]: sqrt(3), R.symbols[3]: sqrt(5)}
    assert expand(P.as_expr().xreplace(value) - reduced.as_expr().xreplace(value)) == 0
    # r2 r3 - sqrt 6 reduces to nothing only with the right primes: a wrong relation is caught
    wrong = reduce_surds(r2**2 - 2, [(1, 3)])
    assert wrong != 0
    assert reduce_surds(r2**2 - 2, [(1, 2)]) == 0
