"""Determinants, Cramer's rule and ranks proved (``screwsym.algebra.linalg``).

Oracles: SymPy's ``DomainMatrix.det`` for the determinants (over ``QQ[x, y]`` and
``QQ<sqrt(3)>[x, y]``), the rank over the field of fractions (``DomainMatrix.to_field``)
and ``Matrix.rank`` at random rational points for the ranks, brute-force minors modulo a
small prime for ``rank_mod``.  Matrices of a known rank are built as products ``U V``
(rank at most r, exactly r where a random point says so).  Seeded per case.
"""

from __future__ import annotations

import math
import random
from itertools import combinations

import pytest
from sympy import (
    QQ,
    ZZ,
    Integer,
    Matrix,
    Rational,
    cancel,
    cos,
    igcd,
    sin,
    sqrt,
    symbols,
)
from sympy.polys.matrices import DomainMatrix

from screwsym.algebra.circle import on_circle, sample_point, trig_symbol
from screwsym.algebra.linalg import (
    MINOR_BUDGET,
    ProvedRank,
    choose_minor,
    clean_vector,
    cramer_vectors,
    det_cost,
    det_integer,
    det_laplace,
    det_rows,
    domain_matrix,
    field_matrix,
    field_rank,
    minor_det,
    nullspace_basis,
    primitive_vector,
    proved_at,
    rank_mod,
)

x, y = symbols("x y")
q = symbols("q", real=True)
FIELDS = {"QQ": QQ, "sqrt3": QQ.algebraic_field(sqrt(3))}


def random_entry(rng: random.Random, R, terms: int = 3, top: int = 2):
    K = R.domain
    X, Y = R.gens[:2]
    e = R.zero
    for _ in range(rng.randint(0, terms)):
        c = K.convert(QQ(rng.randint(-5, 5), rng.randint(1, 3)))
        if K.is_Algebraic and rng.random() < 0.5:
            c += rng.randint(-2, 2) * K.from_sympy(sqrt(3))
        e += c * X ** rng.randint(0, top) * Y ** rng.randint(0, 1)
    return e


def random_rows(rng: random.Random, R, n: int, m: int, **kw) -> list:
    return [[random_entry(rng, R, **kw) for _ in range(m)] for _ in range(n)]


def product_rows(rng: random.Random, R, n: int, m: int, r: int) -> list:
    """An n x m matrix ``U V`` of rank at most ``r``: U n x r, V r x m, small entries."""
    U = random_rows(rng, R, n, r, terms=2, top=1)
    V = random_rows(rng, R, r, m, terms=2, top=1)
    return [[sum((U[i][k] * V[k][j] for k in range(r)), R.zero) for j in range(m)]
            for i in range(n)]


def oracle_rank(rows, R) -> int:
    """The rank over the field of fractions of ``R`` (SymPy's; slow over an algebraic field)."""
    if not rows:
        return 0
    return domain_matrix(rows, R).to_field().rank()


def rank_at(rows, R, rng: random.Random) -> int:
    """The rank at a random rational point (SymPy's, over the coefficient field): a lower
    bound of the generic rank, equal to it but for an unlucky point."""
    K = R.domain
    point = [K.convert(QQ(rng.randint(-50, 50), rng.randint(1, 30))) for _ in R.gens]
    values = [[e(*point) if e else K.zero for e in r] for r in rows]
    return DomainMatrix(values, (len(rows), len(rows[0])), K).rank()


@pytest.mark.parametrize("field", list(FIELDS))
@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
@pytest.mark.parametrize("case", range(3))
def test_determinants_are_sympys(field, n, case):
    R = FIELDS[field][x, y]
    rows = random_rows(random.Random(f"{case}-{n}-{field}-det"), R, n, n)
    expected = DomainMatrix(rows, (n, n), R).det()
    assert det_rows(rows, R) == expected
    assert det_integer(rows, R) == expected
    if field == "QQ":
        assert det_laplace(rows, R.ring) == expected
    # the comparison rejects a wrong determinant: two rows swapped change its sign
    if n > 1 and expected:
        swapped = [rows[1], rows[0], *rows[2:]]
        assert det_rows(swapped, R) == -expected != expected


@pytest.mark.parametrize("case", range(4))
def test_det_laplace_over_the_integers(case):
    rng = random.Random(f"{case}-laplace")
    Z = ZZ[x, y]
    X, Y = Z.gens
    n = 4
    rows = [[rng.randint(-3, 3) * X ** rng.randint(0, 2) + rng.randint(-3, 3) * Y
             for _ in range(n)] for _ in range(n)]
    assert det_laplace(rows, Z.ring) == DomainMatrix(rows, (n, n), Z).det()


def test_determinant_edge_cases():
    R = QQ[x, y]
    X, Y = R.gens
    assert det_rows([], R) == R.one
    assert det_rows([[X + 1]], R) == X + 1
    zero_row = [[X, Y, R.one], [R.zero] * 3, [R.one, X, Y]]
    assert det_rows(zero_row, R) == R.zero == det_laplace(zero_row, R.ring)
    dependent = [[X, Y, R.one, X], [R.one, X, Y, R.zero], [X + 1, X + Y, Y + 1, X],
                 [Y, R.one, X, Y * Y]]
    assert det_rows(dependent, R) == R.zero  # row 3 = row 1 + row 2


def test_det_rows_reduces_on_the_circle():
    S, C = trig_symbol(sin, q), trig_symbol(cos, q)
    R = QQ[S, C]
    s, c = R.gens
    # det [[sin, 1 - cos], [1 + cos, sin]] = sin**2 + cos**2 - 1: zero on the circle
    assert det_rows([[s, 1 - c], [1 + c, s]], R) == R.zero
    assert det_rows([[s, c], [-c, s]], R) == R.one
    assert det_rows([[s, c], [c, s]], R) != R.zero  # sin**2 - cos**2 is not


def test_det_cost_and_minor_det():
    R = QQ[x, y]
    X, Y = R.gens
    rows = [[X + Y + 1, X], [R.zero, Y * X]]
    assert det_cost(rows) == math.factorial(2) * 3 * 1
    B = [[X, Y, R.one], [R.one, X, Y], [Y, R.one, X]]
    assert minor_det(B, (0, 2), (1, 2), R) == Y * X - R.one
    assert minor_det(B, (0, 2), (1, 2), R) != Y * X + R.one


@pytest.mark.parametrize("field", list(FIELDS))
@pytest.mark.parametrize("case", range(4))
def test_cramer_vectors_are_null_vectors_of_the_minors_rows(field, case):
    R = FIELDS[field][x, y]
    rng = random.Random(f"{case}-{field}-cramer")
    k = rng.randint(1, 4)
    B = random_rows(rng, R, k, 6, terms=2, top=1)
    rows = tuple(range(k))
    cols = tuple(sorted(rng.sample(range(6), k)))
    m = minor_det(B, rows, cols, R)
    vectors = cramer_vectors(B, rows, cols, R)
    assert len(vectors) == 6 - k
    others = [j for j in range(6) if j not in cols]
    for j, v in zip(others, vectors, strict=True):
        assert v[j] == m and all(not v[o] for o in others if o != j)
        for i in rows:
            assert not sum((b * e for b, e in zip(B[i], v, strict=True)), R.zero)
    assert cramer_vectors(B, rows, cols, R, m=m) == vectors


@pytest.mark.parametrize("field", list(FIELDS))
@pytest.mark.parametrize("r", [0, 1, 2, 3, 4, 6])
@pytest.mark.parametrize("case", range(2))
def test_proved_at_finds_the_rank_of_a_product(field, r, case):
    R = FIELDS[field][x, y]
    rng = random.Random(f"{case}-{r}-{field}-proved")
    n = max(r, 1) + rng.randint(0, 2)
    B = product_rows(rng, R, n, 6, r) if r else [[R.zero] * 6 for _ in range(n)]
    # at most r by construction, at least the rank at a point: the rank, but for an
    # unlucky point (or U V of lower rank than r)
    expected = rank_at(B, R, random.Random(f"{case}-{r}-point"))
    assert expected <= r
    found = proved_at(B, R, 1, skip_zero=False)
    assert isinstance(found, ProvedRank)  # a random point is not unlucky here
    assert found.rank == expected
    assert len(found.pivots) == len(found.cols) == expected
    if expected:
        assert minor_det(B, found.pivots, found.cols, R)  # the minor is non-zero
        assert rank_at([B[i] for i in found.pivots], R, rng) == expected
    # with skip_zero a matrix of zeros proves nothing
    if not expected:
        assert proved_at(B, R, 1, skip_zero=True) is None


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_proved_at_rejects_a_point_where_the_rank_drops(seed):
    # the second row vanishes at the seeded point: the point says rank 1, the proof must not
    R = QQ[x, y]
    X, Y = R.gens
    x0, y0 = sample_point(R, random.Random(seed))
    B = [[R.one, X, R.zero, Y, R.zero, R.zero],
         [R.zero, X - x0, R.zero, R.zero, (Y - y0) * X, R.zero]]
    assert oracle_rank(B, R) == 2
    assert proved_at(B, R, seed, skip_zero=False) is None
    # at another point the rank is found and proved
    other = next(s for s in (1, 2, 3, 4) if s != seed)
    assert proved_at(B, R, other, skip_zero=False).rank == 2


def test_proved_at_never_reports_full_rank_for_a_rank_deficit():
    R = QQ[x, y]
    X, Y = R.gens
    rows = [[X, Y, R.one, X * Y, R.zero, R.one], [Y, R.one, X, R.zero, X, Y]]
    third = [a + X * b for a, b in zip(*rows, strict=True)]  # dependent on the first two
    B = [*rows, third]
    for seed in (1, 2, 3):
        found = proved_at(B, R, seed, skip_zero=True)
        assert found is None or found.rank == 2
    assert proved_at(B, R, 1, skip_zero=True).rank == 2 != oracle_rank(B + [[R.one] * 6], R)


@pytest.mark.parametrize("field", list(FIELDS))
@pytest.mark.parametrize("case", range(4))
def test_choose_minor_is_a_nonzero_minor_of_least_degree(field, case):
    R = FIELDS[field][x, y]
    rng = random.Random(f"{case}-{field}-choose")
    r = rng.randint(1, 2)
    B = product_rows(rng, R, 3, 6, r)
    found = proved_at(B, R, 1, skip_zero=True)
    assert found is not None and found.rank == rank_at(B, R, rng) == r
    m, rows, cols = choose_minor(B, R, found.rank, found.pivots)
    assert len(rows) == len(cols) == r and m
    assert m == DomainMatrix([[B[i][j] for j in cols] for i in rows], (r, r), R).det()
    # among all r x r minors (few enough to compare all), none has a smaller key
    n_candidates = math.comb(len(B), r) * math.comb(6, r)
    if n_candidates <= MINOR_BUDGET:
        keys = []
        for rr in combinations(range(len(B)), r):
            for cc in combinations(range(6), r):
                d = minor_det(B, rr, cc, R)
                if d:
                    keys.append((max(sum(e) for e in d.monoms()), len(d.terms())))
        assert (max(sum(e) for e in m.monoms()), len(m.terms())) == min(keys)


def brute_rank_mod(rows: list, p: int) -> int:
    """The largest k with a k x k minor non-zero mod p (integer determinants)."""
    n, m = len(rows), len(rows[0])
    for k in range(min(n, m), 0, -1):
        for rr in combinations(range(n), k):
            for cc in combinations(range(m), k):
                if Matrix([[rows[i][j] for j in cc] for i in rr]).det() % p:
                    return k
    return 0


@pytest.mark.parametrize("p", [2, 3, 7])
@pytest.mark.parametrize("case", range(6))
def test_rank_mod_against_minors_mod_p(p, case):
    rng = random.Random(f"{case}-{p}-mod")
    n, m = rng.randint(1, 4), rng.randint(2, 5)
    rows = [[rng.randint(-6, 6) for _ in range(m)] for _ in range(n)]
    if case % 2:  # a dependent row: a combination of the others mod p
        rows.append([sum(rng.randint(0, p - 1) * r[j] for r in rows) + p * rng.randint(-2, 2)
                     for j in range(m)])
    pivots, cols = rank_mod(rows, p)
    assert len(pivots) == len(cols) == brute_rank_mod(rows, p)
    if pivots:
        # the first independent rows: each row is a pivot exactly when it raises the rank
        for i in range(len(rows)):
            before = brute_rank_mod(rows[:i], p) if i else 0
            assert (i in pivots) == (brute_rank_mod(rows[: i + 1], p) > before)
        minor = Matrix([[rows[i][j] for j in cols] for i in pivots]).det()
        assert minor % p != 0
    # the oracle sees a wrong answer: the rank over Q may be larger than mod 2
    assert brute_rank_mod([[2, 0], [0, 1]], 2) == 1 != brute_rank_mod([[2, 0], [0, 1]], 3)


def is_primitive(v: list, R) -> bool:
    """No common polynomial factor, integer coefficients without common factor, and the first
    non-zero entry with a positive leading coefficient (as a real number)."""
    nz = [e for e in v if e]
    g = nz[0]
    for e in nz[1:]:
        g = R.gcd(g, e)
    K = R.domain
    coeffs = [c for e in nz for c in e.coeffs()]
    parts = [q for c in coeffs for q in ([c] if K.is_QQ else c.to_list())]
    integer = all(QQ.convert(q).denominator == 1 for q in parts)
    common = 0
    for q in parts:
        common = igcd(common, int(QQ.convert(q).numerator))
    return g.is_ground and integer and common == 1 and K.to_sympy(nz[0].LC) > 0


def parallel(u: list, v: list) -> bool:
    return all(not (u[i] * v[j] - u[j] * v[i]) for i in range(len(u)) for j in range(len(u)))


@pytest.mark.parametrize("field", list(FIELDS))
@pytest.mark.parametrize("case", range(6))
def test_primitive_vector(field, case):
    R = FIELDS[field][x, y]
    rng = random.Random(f"{case}-{field}-prim")
    v = [random_entry(rng, R, terms=2) for _ in range(4)]
    if not any(v):
        v[0] = R.one
    g = random_entry(rng, R, terms=2) or R.one
    scaled = [e * g * R.domain.convert(QQ(-rng.randint(1, 9), rng.randint(1, 9))) for e in v]
    w = primitive_vector(scaled, R)
    assert parallel(w, scaled)  # a scalar multiple of the input
    assert is_primitive(w, R)
    assert primitive_vector(w, R) == w  # and its own primitive part
    # the checks reject what is not primitive
    assert not is_primitive([2 * e for e in w], R)
    assert not is_primitive([-e for e in w], R)
    assert not parallel(w, [scaled[0] + R.one, *scaled[1:]])


def test_primitive_vector_known():
    R = QQ[x, y]
    X, Y = R.gens
    assert primitive_vector([-X * Y / 2, Y * Y / 3, R.zero], R) == [3 * X, -2 * Y, R.zero]
    assert primitive_vector([R.zero, R.zero], R) == [R.zero, R.zero]
    K = FIELDS["sqrt3"]
    Rk = K[x, y]
    s3 = K.from_sympy(sqrt(3))
    # -sqrt(3) < 0: the sign is flipped
    assert primitive_vector([-s3 * Rk.gens[0], Rk.one * 2], Rk) == [s3 * Rk.gens[0], -2 * Rk.one]


def product_matrix(rng: random.Random, n: int, m: int, r: int, atoms) -> Matrix:
    def entry():
        return sum(Rational(rng.randint(-4, 4), rng.randint(1, 2)) * rng.choice(atoms)
                   for _ in range(2))
    U = Matrix(n, r, lambda i, j: entry())
    V = Matrix(r, m, lambda i, j: entry())
    return (U * V).applyfunc(lambda e: e)


T = symbols("t_check")


def on_the_circle(M: Matrix, kind: str) -> DomainMatrix:
    """``M`` over the field of rational functions (of t = tan(q/2) for sin(q), cos(q)): the
    exact oracle for ``M N = 0`` (SymPy's ``cancel`` on the entries takes seconds)."""
    K = FIELDS["sqrt3"] if kind == "sqrt3" else QQ
    F = K.frac_field(x, y, T)
    s, c = on_circle(T)
    rows = [[F.from_sympy(M[i, j].subs({sin(q): s, cos(q): c})) for j in range(M.cols)]
            for i in range(M.rows)]
    return DomainMatrix(rows, M.shape, F)


@pytest.mark.parametrize("kind", ["QQ", "sqrt3", "circle"])
@pytest.mark.parametrize("case", range(3))
def test_field_rank_and_nullspace_basis(kind, case):
    rng = random.Random(f"{case}-{kind}-field")
    atoms = {"QQ": [Integer(1), x, y, x * y],
             "sqrt3": [Integer(1), x, sqrt(3) * y, sqrt(3)],
             "circle": [Integer(1), sin(q), cos(q), x * cos(q)]}[kind]
    # over Q(sqrt 3)(x, y) SymPy's rank is slow (a 4 x 5 of rank 3: 20 s): smaller there
    n, m, top = (3, 4, 2) if kind == "sqrt3" else (4, 5, 3)
    r = rng.randint(1, top)
    M = product_matrix(rng, n, m, r, atoms)
    # the rank: at most r by construction, at least the rank at a point of the circle
    t = Rational(rng.randint(1, 9), rng.randint(1, 9))
    s, c = on_circle(t)
    at = {x: Rational(rng.randint(-9, 9), 7), y: Rational(rng.randint(-9, 9), 5),
          sin(q): s, cos(q): c}
    point_rank = M.subs(at).rank()
    assert point_rank <= r
    rank = field_rank(M)
    assert rank == point_rank  # generic: the point is not unlucky here
    N = nullspace_basis(M)
    assert N.shape == (M.cols, M.cols - rank)
    assert N.subs(at).rank() == N.cols  # independent columns
    # M N = 0: identically, or on the circle
    Mf, Nf = on_the_circle(M, kind), on_the_circle(N, kind)
    assert not any((Mf * Nf).to_list_flat())
    # the check rejects a wrong null vector
    wrong = N[:, 0]
    wrong[0] += 1
    assert any((Mf * on_the_circle(wrong, kind)).to_list_flat())


@pytest.mark.parametrize("case", range(2))
def test_field_rank_is_matrix_rank(case):
    rng = random.Random(f"{case}-matrix-rank")
    M = product_matrix(rng, 3, 3, rng.randint(1, 3), [Integer(1), x, y])
    assert field_rank(M) == M.rank()
    assert field_rank(M.row_join(Matrix([1, x, y]))) == Matrix.hstack(M, Matrix([1, x, y])).rank()


def test_field_rank_knows_the_circle():
    # det = sin**2 + cos**2 - 1: rank 1 on the circle, though 2 for free sin and cos
    M = Matrix([[sin(q), 1 - cos(q)], [1 + cos(q), sin(q)]])
    assert field_rank(M) == 1
    free = M.subs({sin(q): x, cos(q): y})
    assert field_rank(free) == 2
    N = nullspace_basis(M)
    assert N.shape == (2, 1)
    assert all(cancel((M * N)[i].subs({sin(q): Rational(3, 5), cos(q): Rational(4, 5)})) == 0
               for i in range(2))


def test_field_matrix_domains():
    assert field_matrix(Matrix([[1, Rational(1, 2)]])).domain == QQ
    assert field_matrix(Matrix([[x, sqrt(3)]])).domain == FIELDS["sqrt3"].frac_field(x)
    assert field_matrix(Matrix([[sqrt(3), 1]])).domain == FIELDS["sqrt3"]
    assert field_rank(Matrix.zeros(0, 3)) == 0 and field_rank(Matrix([[0, 0]])) == 0
    assert nullspace_basis(Matrix.zeros(0, 2)) == Matrix.eye(2)


@pytest.mark.parametrize("case", range(6))
def test_clean_vector_of_rationals(case):
    rng = random.Random(f"{case}-clean")
    v = [Rational(rng.randint(-20, 20), rng.randint(1, 12)) for _ in range(4)]
    if not any(v):
        v[0] = Integer(1)
    w = clean_vector(v)
    assert all(e.is_Integer for e in w)
    assert math.gcd(*(int(e) for e in w)) == 1
    assert next(e for e in w if e != 0) > 0
    assert all(w[i] * v[j] - w[j] * v[i] == 0 for i in range(4) for j in range(4))
    assert clean_vector(w) == w
    assert clean_vector([2 * e for e in w]) == w != [2 * e for e in w]


def test_clean_vector_on_the_circle_is_primitive():
    assert clean_vector([2 * sin(q) * x, 4 * sin(q)]) == [x, 2]
    assert clean_vector([sin(q) * x / 2, -sin(q) / 3]) == [3 * x, -2]
    # zero on the circle is 0
    assert clean_vector([sin(q) ** 2 + cos(q) ** 2 - 1, -2 * cos(q)]) == [0, 1]


def test_clean_vector_of_rational_functions_clears_their_denominators():
    assert clean_vector([1 / x, 1 / y]) == [y, x]
    assert clean_vector([-x / (x + 1), Integer(1)]) == [x, -x - 1]


def test_clean_vector_of_polynomials_is_in_lowest_terms():
    assert clean_vector([2 * x, 4 * x]) == [1, 2]
    assert clean_vector([x / 2 - 1, -x**2 / 3, Integer(0)]) == [3 * x - 6, -2 * x**2, 0]
