r"""Exact linear algebra over polynomial rings: determinants, Cramer's rule, ranks proved.

A rank over the field of rational functions is found at a rational point (a minor
non-zero there is a non-zero polynomial) and *proved*: the vectors Cramer's rule builds
from that minor are checked to be orthogonal to every member identically
(:func:`proved_at`), so the rank is exact for all values of the symbols off the minor's
zeros.  :func:`choose_minor` picks the simplest minor that proves it (its factors are
the conditions of the special cases); :func:`primitive_vector` brings a vector to lowest terms.

Where it does not simply call SymPy: :func:`det_rows` is cofactor expansion up to 3 x 3
and, over Q or a number field, Laplace expansion with shared minors over ``Z[x]``
(:func:`det_integer`, :func:`det_laplace`): measured on the 5 x 5 minors of a 3-RPS leg
at a symbolic pose over ``Q(sqrt 3)``, 2 ms, against 124 ms for SymPy's fraction-free
elimination over ``Q[x, theta]`` and seconds for Berkowitz over ``Q(sqrt 3)[x]``.
:func:`rank_mod` is SymPy's ``DomainMatrix.rref`` over ``GF(p)``.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from functools import lru_cache, reduce
from itertools import combinations
from math import gcd, lcm
from typing import Any

from sympy import (
    QQ,
    ZZ,
    Abs,
    Dummy,
    ImmutableMatrix,
    Matrix,
    cancel,
    igcd,
    ilcm,
    sin,
    zeros,
)
from sympy import gcd as expr_gcd
from sympy import lcm as expr_lcm
from sympy.polys.matrices import DomainMatrix
from sympy.polys.polyutils import parallel_dict_from_expr

from .budget import charge
from .circle import (
    TRIG_BACK,
    from_half_angle,
    half_angle_symbol,
    has_trig,
    on_circle,
    reduce_circle,
    sample_point,
    trig_entries,
)
from .numberfield import lift, lifted_ring, lower, ring_gcd
from .rings import field_element, number_field, rational_parts, to_expr, to_ring

__all__ = [
    "domain_matrix",
    "det_rows",
    "det_integer",
    "det_laplace",
    "ProvedRank",
    "cramer_vectors",
    "proved_at",
    "minor_det",
    "det_cost",
    "choose_minor",
    "rank_mod",
    "primitive_vector",
    "field_matrix",
    "clean_vector",
    "primitive_entries",
    "nullspace_basis",
    "field_rank",
    "MINOR_BUDGET",
    "SEEDS",
    "EXACT_CHOICE",
]


#: at most this many r x r minors are compared when choosing the one that states a case
MINOR_BUDGET = 64


def domain_matrix(rows, R) -> DomainMatrix:
    rows = [list(r) for r in rows]
    ncols = len(rows[0]) if rows else 0
    return DomainMatrix(rows, (len(rows), ncols), R)


def det_rows(rows, R):
    """The determinant of a small square matrix of polynomials.

    Division-free where division is dear: cofactor expansion up to 3 x 3, and
    Berkowitz (``charpoly``) over algebraic number fields, where the exact
    divisions of fraction-free elimination cost a polynomial inversion per
    coefficient (measured: 1.5 s against 14 s for a dense 5 x 5).
    """
    n = len(rows)
    if n == 0:
        return R.one
    charge(math.factorial(n) * math.prod(max((len(e.terms()) for e in r), default=1) or 1
                                          for r in rows))
    return reduce_circle(_det_unreduced(rows, R, n), R)


def _det_unreduced(rows, R, n):
    if n == 1:
        return rows[0][0]
    if R.domain.is_Algebraic:
        return det_integer(rows, R)
    if n == 2:
        return rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0]
    if n == 3:
        (a, b, c), (d, e, f), (g, h, i) = rows
        return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    K = R.domain
    if K.is_QQ or K.is_ZZ or K.is_Algebraic:
        return det_integer(rows, R)
    M = domain_matrix(rows, R)
    return M.charpoly()[-1] * (-1) ** n


@lru_cache(maxsize=64)
def _integer_ring(symbols: tuple):
    return ZZ[symbols]


def det_integer(rows, R):
    """The determinant of polynomial rows over Q or an algebraic field, through ``Z[x]``.

    Over ``Q(theta)`` the rows are lifted to ``Q[x, theta]`` (:func:`lift`) and the result
    reduced; each row is multiplied by the common denominator of its coefficients, and
    the determinant over ``Z[x]`` by Laplace expansion with its minors shared
    (:func:`det_laplace`: ``n 2**(n-1)`` products, no division) divided by their product.
    Measured on the 5 x 5 minors of a 3-RPS leg at a symbolic pose over ``Q(sqrt 3)``:
    2 ms, against 124 ms for SymPy's fraction-free elimination over ``Q[x, theta]`` and
    seconds for Berkowitz over ``Q(sqrt 3)[x]``.
    """
    K = R.domain
    if K.is_Algebraic:
        base = lifted_ring(R)
        rows = [[lift(e, R) for e in r] for r in rows]
    else:
        base = R
    if base.domain.is_ZZ:
        return det_laplace(rows, base.ring)
    Z = _integer_ring(tuple(base.symbols))
    scale = 1
    zrows = []
    for r in rows:
        den = 1
        for e in r:
            for c in e.values():
                den = lcm(den, int(c.denominator))
        scale *= den
        zrows.append([Z.ring.from_dict({m: int(c.numerator) * (den // int(c.denominator))
                                        for m, c in e.items()}) if e else Z.zero for e in r])
    d = det_laplace(zrows, Z.ring)
    out = base.ring.from_dict({m: QQ(int(c), scale) for m, c in d.items()}) if d else base.zero
    return lower(out, R) if K.is_Algebraic else out


def det_laplace(rows, ring):
    """The determinant by Laplace expansion along the rows, each minor computed once."""
    n = len(rows)
    # the minors of the last rows, by the set of their columns (a bit mask)
    prev = {1 << j: e for j, e in enumerate(rows[n - 1]) if e}
    for k in range(n - 2, -1, -1):
        row = rows[k]
        cur: dict = {}
        for mask, minor in prev.items():
            for j in range(n):
                if mask >> j & 1 or not row[j]:
                    continue
                term = row[j] * minor
                if bin(mask & ((1 << j) - 1)).count("1") % 2:
                    term = -term
                new = mask | 1 << j
                cur[new] = cur[new] + term if new in cur else term
        prev = {m: v for m, v in cur.items() if v}
        if not prev:
            return ring.zero
    return prev.get((1 << n) - 1, ring.zero)


@dataclass(frozen=True)
class ProvedRank:
    rank: int
    pivots: tuple  # the first independent members
    cols: tuple  # coordinates (of the swapped rows) of a non-zero minor on the pivots


#: the points (seeds) at which a rank is first found, then proved for all values
SEEDS = (1, 2, 3)


def cramer_vectors(B, rows, cols, R, m=None, width: int = 6) -> list:
    """Null vectors of the rows ``B[rows]`` by Cramer's rule on the minor ``(rows, cols)``.

    Each is multiplied through by the minor ``m``, so it is polynomial; they
    are independent wherever ``m`` is non-zero.  ``width``: the length of the rows.
    """
    if m is None:
        m = det_rows([[B[i][j] for j in cols] for i in rows], R)
    vectors = []
    for k in range(width):
        if k in cols:
            continue
        v = [R.zero] * width
        v[k] = m
        for jj, j in enumerate(cols):
            replaced = [[B[i][k] if c == jj else B[i][cc] for c, cc in enumerate(cols)]
                        for i in rows]
            v[j] = -det_rows(replaced, R)
        vectors.append(v)
    return vectors


def proved_at(B: list, R: Any, seed: int, skip_zero: bool) -> ProvedRank | None:
    """The rank found at the seeded rational point and proved for every value; None if not.

    The independent members and the minor are those of the point; the rank is
    proved when the vectors of Cramer's rule on that minor are reciprocal to
    every member identically.  ``skip_zero``: a point where every entry vanishes
    proves nothing (None) instead of being tried as rank 0.
    """
    K = R.domain
    point = sample_point(R, random.Random(seed))
    B0 = DomainMatrix([[b(*point) if b else K.zero for b in row] for row in B], (len(B), 6), K)
    _, rows = B0.transpose().rref()
    if not rows and skip_zero:
        return None
    _, cols = B0.extract(list(rows), list(range(6))).rref() if rows else (None, ())
    if all(
        not reduce_circle(sum((b * x for b, x in zip(B[i], v, strict=True)), R.zero), R)
        for v in cramer_vectors(B, rows, cols, R)
        for i in range(len(B))
        if i not in rows
    ):
        return ProvedRank(len(rows), tuple(rows), tuple(cols))
    return None


def minor_det(B, rows, cols, R):
    return det_rows([[B[i][j] for j in cols] for i in rows], R)


#: below this estimated work (``charge`` units) every candidate minor is computed to choose
#: the simplest; above it, candidates are ranked by a degree bound and checked at a point first
EXACT_CHOICE = 200_000


def det_cost(rows) -> int:
    """The work ``det_rows`` charges for these rows (see :data:`BUDGET`)."""
    return math.factorial(len(rows)) * math.prod(
        max((len(e.terms()) for e in r), default=1) or 1 for r in rows)


def choose_minor(B: list, R: Any, rank: int, pivots: tuple):
    """A non-zero ``rank x rank`` minor of the rows ``B`` (ring elements of ``R``), as simple
    as can be found: ``(minor, rows, cols)``.

    Small systems: every candidate is computed and the one of least degree
    (then fewest terms) kept.  Where that would cost more than
    :data:`EXACT_CHOICE`, the candidates are ranked by a bound on their
    degree (the sum over rows of the largest total degree), those that vanish
    at a random point (of the circle, for angles) are passed over, and the
    best of the first three non-zero ones is kept: the determinants of many
    symbols are the dearest part of a mobility analysis (profiled on a 3-RPS
    with 12 symbols: 29 of 44 s in choosing the minor).
    """
    all_rows = list(combinations(range(len(B)), rank))
    col_sets = list(combinations(range(6), rank))
    row_sets = all_rows if len(all_rows) * len(col_sets) <= MINOR_BUDGET else [tuple(pivots)]
    candidates = [(rows, cols) for rows in row_sets for cols in col_sets]
    subs = {c: [[B[i][j] for j in c[1]] for i in c[0]] for c in candidates}
    if sum(det_cost(m) for m in subs.values()) > EXACT_CHOICE:
        K = R.domain
        point = sample_point(R, random.Random(7))
        B0 = [[b(*point) if b else K.zero for b in row] for row in B]

        def bound(c):
            deg = sum(max((sum(e.LM) if e else 0) for e in r) for r in subs[c])
            return (deg, det_cost(subs[c]))

        picked = []
        for c in sorted(candidates, key=bound):
            rows, cols = c
            if domain_matrix([[B0[i][j] for j in cols] for i in rows], K).det():
                picked.append(c)
                if len(picked) == 3:
                    break
        candidates = picked or candidates
    best = None
    for rows, cols in candidates:
        m = det_rows(subs[(rows, cols)], R)
        if not m:
            continue
        key = (max(sum(e) for e in m.monoms()), len(m.terms()))
        if best is None or key < best[0]:
            best = (key, m, rows, cols)
            if key[0] == 0:
                return best[1:]
    assert best is not None, "a system of rank r has a non-zero r x r minor on its pivot rows"
    return best[1:]


def rank_mod(rows: list, p: int) -> tuple[tuple, tuple]:
    """The first independent rows of an integer matrix mod ``p``, and pivot coordinates of them."""
    from sympy.polys.domains import FF

    F = FF(p)
    A = DomainMatrix([[F(v) for v in r] for r in rows], (len(rows), len(rows[0])), F)
    _, pivots = A.transpose().rref()
    if not pivots:
        return (), ()
    _, cols = A.extract(list(pivots), list(range(A.shape[1]))).rref()
    return tuple(pivots), tuple(cols)


def _rationals(c, K) -> list:
    """The rational numbers that make up an element of ``K`` (itself, or an algebraic's)."""
    return [c] if (K.is_QQ or K.is_ZZ) else [q for q in c.to_list() if q]


def primitive_vector(v: list, R) -> list:
    """``v`` divided by the gcd of its entries, its first non-zero entry with a positive lead."""
    g = R.zero
    for e in v:
        if e:
            g = e if not g else ring_gcd(g, e, R)
    if not g:
        return v
    v = [R.exquo(e, g) if e else e for e in v]
    first = next(e for e in v if e)
    lc = first.LC
    if R.domain.is_QQ or R.domain.is_ZZ:
        neg = lc < 0
    else:  # an algebraic number: its sign as a real number
        neg = bool(R.domain.to_sympy(lc) < 0)
    if neg:
        v = [-e for e in v]
    # clear the rational content too: integer coefficients without a common factor
    coeffs = [q for e in v for c in e.coeffs() for q in _rationals(c, R.domain)]
    den = lcm(*(int(q.denominator) for q in coeffs))
    num = gcd(*(int(q.numerator * den // q.denominator) for q in coeffs))
    scale = R.domain.convert(QQ(den, num))
    v = [e * scale for e in v]
    return v


def field_matrix(M: Matrix) -> DomainMatrix:
    """``M`` over its field: QQ, an algebraic field, or rational functions over one.

    The entries go through polynomial dictionaries and the cached algebraic
    coefficients of :mod:`screwsym.algebra.rings` (``K.from_sympy`` on an
    algebraic field computes a minimal polynomial per entry: seconds).

    ``sin(q)`` and ``cos(q)`` of a symbol (sums and multiples expanded) live on
    the unit circle, whose rational functions are those of ``t = tan(q/2)``
    (:func:`~screwsym.algebra.circle.on_circle`, a bijection of the two
    fields): they are written in ``t``, so that rank and null space are exact,
    the generic ones on the circle (a field of fractions in ``sin(q)``,
    ``cos(q)`` as free symbols would not know ``sin(q)**2 + cos(q)**2 = 1``).
    :func:`nullspace_basis` writes its basis back in ``sin(q)`` and ``cos(q)``.
    """
    entries = list(M)
    if all(e.is_Rational for e in entries):  # the common case, at once
        rows = [[QQ(int(e.p), int(e.q)) for e in entries[i * M.cols:(i + 1) * M.cols]]
                for i in range(M.rows)]
        return DomainMatrix(rows, (M.rows, M.cols), QQ)
    trig = has_trig(entries)
    if trig:
        entries = trig_entries(entries)  # sin(q), cos(q) as the ring's symbols, then in t
        half = {}
        for x in set().union(*(e.free_symbols for e in entries)):
            back = TRIG_BACK.get(x)
            if back is not None:
                point = on_circle(half_angle_symbol(back.args[0]))
                half[x] = point[0] if back.func is sin else point[1]
        entries = [e.xreplace(half) for e in entries]
    syms, numbers, parts = rational_parts(entries, "joints: expected geometry")
    K0 = number_field(tuple(sorted(set(numbers), key=str)))
    gens = tuple(syms) if syms else (Dummy("c"),)
    R = K0[gens]
    K = K0.frac_field(*syms) if syms else K0
    dicts, _ = parallel_dict_from_expr(parts, gens=gens) if parts else ([], None)
    polys = [R.ring.from_dict({m: field_element(K0, c) for m, c in d.items()}) for d in dicts]
    values = []
    for k in range(len(entries)):
        num, den = polys[2 * k], polys[2 * k + 1]
        if syms:
            values.append(K.convert_from(num, R) / K.convert_from(den, R))
        else:
            values.append(num.LC / den.LC if num else K0.zero)
    rows = [values[i * M.cols:(i + 1) * M.cols] for i in range(M.rows)]
    return DomainMatrix(rows, (M.rows, M.cols), K)


def primitive_entries(entries: list[Any]) -> list[Any]:
    """The entries with denominators cleared and their gcd divided out (exact): a primitive
    vector of expressions, up to its sign (:func:`clean_vector` also fixes the sign).

    >>> from sympy import symbols
    >>> x, y = symbols("x y")
    >>> primitive_entries([x / 2, x * y / 3, 0])
    [3, 2*y, 0]
    >>> primitive_entries([x / 2 - 1, -x**2 / 3])   # rational coefficients too
    [3*x - 6, -2*x**2]
    """
    entries = [cancel(e) for e in entries]
    # as_numer_denom, not fraction: x/2 - 1 is an Add whose denominator fraction() misses
    dens = [e.as_numer_denom()[1] for e in entries if e != 0]
    if not dens:
        return entries
    m = reduce(expr_lcm, dens)
    entries = [cancel(e * m) for e in entries]
    nonzero = [e for e in entries if e != 0]
    g = reduce(expr_gcd, nonzero)
    if g.is_number and g.is_positive is not True:
        g = Abs(g)
    return [cancel(e / g) for e in entries]


def clean_vector(v: list) -> list:
    """A vector scaled to lowest terms: no denominators, no common factor, first entry positive.

    With ``sin``/``cos`` of symbols, in the ring of :mod:`~screwsym.algebra.rings`:
    polynomial, reduced by ``sin(q)**2 + cos(q)**2 = 1`` (so an entry zero on the circle is 0).
    """
    if has_trig(v):
        rg = to_ring(ImmutableMatrix(len(v), 1, v))
        return [to_expr(e, rg.ring) for e in primitive_vector(list(rg.cols[0]), rg.ring)]
    v = [cancel(e) for e in v]
    nz = [e for e in v if e != 0]
    if not nz:
        return v
    if all(e.is_Rational for e in nz):
        den = reduce(ilcm, [int(e.q) for e in nz])
        ints = [e * den for e in v]
        g = reduce(igcd, [abs(int(e)) for e in ints if e != 0])
        v = [e / g for e in ints]
    else:
        v = primitive_entries(v)
    first = next(e for e in v if e != 0)
    if first.is_number and first.is_negative or (not first.is_number
                                                  and first.could_extract_minus_sign()):
        v = [-e for e in v]
    return v


def nullspace_basis(M: Matrix) -> Matrix:
    """A basis of the (generic) null space of ``M``, as the columns of a matrix."""
    if M.rows == 0:
        return Matrix.eye(M.cols)
    if M.cols == 0:
        return zeros(0, 0)
    null = field_matrix(M).nullspace()
    if has_trig(M) and null.domain.is_FractionField:  # from t = tan(q/2) to sin(q), cos(q)
        cols = [clean_vector(from_half_angle(row)) for row in null.to_list()]
    else:
        null = null.to_Matrix()
        cols = [clean_vector(list(null.row(i))) for i in range(null.rows)]
    return Matrix.hstack(*(Matrix(c) for c in cols)) if cols else zeros(M.cols, 0)


def field_rank(M: Matrix) -> int:
    if M.rows == 0 or M.cols == 0:
        return 0
    return int(field_matrix(M).rank())
