r"""Ranks on a hypersurface ``f = 0``, by points over finite fields and Groebner bases.

Why not a substitution: an irreducible f in two or more symbols and linear in none
(the 3-RPS's 2 p**2 - 2 q**2 + 1 = 0, a degree-12 type II surface cubic in z) has no
rational solution for any symbol; its roots are algebraic functions of the others.  The
rank on the case is proved instead, pointwise: with g an r x r minor of the members
(rows I, coordinates J) and v_1, ..., v_{6-r} the vectors of Cramer's rule on it, every
other member's products with the v_k lie in the ideal of f (and of the circles'
relations): wherever f = 0 and g != 0, the rows I are independent, the v_k span their
null space, and every member is orthogonal to it, so the rank is r exactly there.
Membership is decided by the normal form modulo a Groebner basis (SymPy's
``groebner``), exact.  The rank r and the minor are first found at a point of f = 0
over a finite field (a root of f in one symbol, the others at random): a point's
minor non-zero there is non-zero modulo f, so r is at most the rank on the case, and
the proof above decides; a point that proves nothing is followed by another (seeds).
What is left, f = 0 with a factor h of g zero, is imposed as two equations, h first
(solved for a symbol or at its points where it can be, and f then in fewer symbols).
Where h is neither and f, h are curves of a plane (two symbols or angles between them,
``meeting``), they meet in finitely many points: the last polynomial of a lex Groebner
basis of f, h (and the circles) is in one symbol, and is imposed first.  In three or
more symbols the intersection is listed with rank None: a Groebner basis of two such
surfaces (a curve in common) did not finish in 90 s on the 3-RPS.

Where it does not simply call SymPy: the Groebner bases and the factorisations mod p
are SymPy's (``groebner``, ``gf_factor_sqf``); SymPy has no point on a hypersurface
over a finite field, and a rank over the function field of ``f = 0`` cannot be asked
of it, hence :func:`point_on` and :func:`rank_on`.
"""

from __future__ import annotations

import random
from typing import Any

from sympy import (
    QQ,
    ZZ,
    ImmutableMatrix,
    cancel,
    fraction,
)

from .budget import charge
from .circle import TRIG_BACK, angles_of, circle_relations, reduce_circle
from .linalg import cramer_vectors, det_rows, minor_det, primitive_vector, rank_mod
from .real import dimension, involved_indices, largest_degree
from .rings import ring_element, ring_with, to_expr

__all__ = [
    "meeting",
    "Unlucky",
    "groebner_ideal",
    "modular",
    "term_mod",
    "roots_mod",
    "at_point",
    "point_on",
    "rank_on",
    "zero_on_surface",
    "null_on_surface",
    "MEETING",
    "PRIMES",
]


#: the most common points (Bezout's bound, the product of the degrees) two curves may have
#: for ``meeting`` to look for them: the 3-RPS's limb curves have 60, found in 0.5 s
MEETING = 100


def meeting(f, h_expr: Any, R) -> Any:
    """Where ``f = 0`` (linear in no symbol) meets ``h = 0``: an equation in fewer symbols.

    Two distinct irreducible curves of a plane (two symbols, or angles, between
    them) meet in finitely many points; the last polynomial of a lex Groebner
    basis of ``f``, ``h`` and the circles (SymPy's ``groebner``) is in one ring
    symbol and vanishes at each of them, so imposing it first, then ``f`` and
    ``h`` there, decides them.  Returns that polynomial (an element of ``R``),
    ``R.zero`` where the two have no common point even over the complex numbers
    (the basis is 1), or None: more than two symbols (a curve or more in common,
    whose basis may take minutes: see this module's docstring), a Bezout bound
    over ``MEETING``, or no such polynomial.
    """
    try:
        h = reduce_circle(ring_element(h_expr, R), R)
    except Exception:  # h has symbols (or a form) the ring of f has not
        return None
    if not h or dimension([f, h], R) > 2 or largest_degree(f) * largest_degree(h) > MEETING:
        return None
    G = groebner_ideal([f, h], R)
    if G == [R.ring.one]:
        return R.zero
    fewer = [g for g in G if reduce_circle(g, R) and len(involved_indices(g, R)) < len(involved_indices(f, R))]
    return min(fewer, key=lambda g: (len(involved_indices(g, R)), len(g.terms()))) if fewer else None


#: the primes of the points of f = 0 over a finite field (large: an unlucky zero of a
#: minor at the point has probability about degree / prime)
PRIMES = (2_147_483_647, 2_147_483_629, 2_147_483_587, 2_147_483_579, 2_147_483_563)


class Unlucky(Exception):
    """This prime or point does not serve (a denominator or a leading coefficient vanishes)."""


def groebner_ideal(polys: list, R) -> list:
    """A Groebner basis (SymPy's) of ``polys`` and the circles' relations, in ``R``'s order."""
    from sympy.polys.groebnertools import groebner

    gens = [p.monic() for p in polys + circle_relations(R)]
    charge(sum(len(p.terms()) for p in gens) ** 2)
    return groebner(gens, R.ring)


def modular(c, K, p: int, theta: int | None) -> int:
    """The coefficient ``c`` of ``K`` (a rational, or an algebraic number at ``theta``) mod ``p``."""
    parts = [c] if theta is None else c.to_list()
    v = 0
    for q in parts:
        q = QQ.convert(q)
        den = int(q.denominator) % p
        if not den:
            raise Unlucky
        v = (v * (theta or 0) + int(q.numerator) * pow(den, -1, p)) % p
    return v


def term_mod(m: tuple, c, K, p: int, theta: int | None, point: list, skip: tuple = ()) -> int:
    """The term ``c x**m`` mod ``p`` at ``point``, the symbols of ``skip`` left out."""
    t = modular(c, K, p, theta)
    for i, k in enumerate(m):
        if k and i not in skip:
            t = t * pow(point[i], k, p) % p
    return t


def roots_mod(coeffs: list, p: int) -> list:
    """The roots mod ``p`` of the polynomial with integer coefficients ``coeffs`` (highest first)."""
    from sympy.polys.galoistools import gf_factor_sqf, gf_sqf_part, gf_strip

    f = gf_strip([c % p for c in coeffs])
    if len(f) < 2:
        return []
    _, factors = gf_factor_sqf(gf_sqf_part(f, p, ZZ), p, ZZ)
    return [(-int(g[1])) % p for g in factors if len(g) == 2]


def at_point(polys_rows: list, R, p: int, point: list, theta: int | None) -> list:
    """The entries (ring elements) evaluated mod ``p`` at ``point``."""
    K = R.domain
    out = []
    for row in polys_rows:
        vals = []
        for e in row:
            vals.append(sum(term_mod(m, c, K, p, theta, point) for m, c in e.items()) % p
                        if e else 0)
        out.append(vals)
    return out


def point_on(f, R, p: int, rnd: random.Random) -> tuple[list, int | None]:
    """A point mod ``p`` where ``f`` vanishes (and every circle holds), with ``theta``'s value.

    One symbol of ``f`` is solved for (a root of ``f`` in it, the others at random);
    when ``f`` is in sines and cosines alone, one angle's ``tan(q/2)``.  Raises
    ``Unlucky`` where this prime or point has no such root.
    """
    K = R.domain
    theta = None
    if K.is_Algebraic:
        roots = roots_mod([modular(c, QQ, p, None) for c in K.mod.to_list()], p)
        if not roots:
            raise Unlucky
        theta = roots[0]
    n = len(R.gens)
    point = [rnd.randrange(p) for _ in range(n)]
    circles = {}
    for q, ci, si in angles_of(R):
        t = rnd.randrange(p)
        den = (1 + t * t) % p
        if not den:
            raise Unlucky
        inv = pow(den, -1, p)
        circles[q] = (ci, si)
        if si is not None:
            point[si] = 2 * t * inv % p
        if ci is not None:
            point[ci] = (1 - t * t) * inv % p
    involved = involved_indices(f, R)
    plain = [i for i in involved if R.symbols[i] not in TRIG_BACK]
    if plain:
        x = max(plain, key=lambda i: f.degree(i))
        by_degree: dict = {}
        for m, c in f.items():
            t = term_mod(m, c, K, p, theta, point, skip=(x,))
            by_degree[m[x]] = (by_degree.get(m[x], 0) + t) % p
        top = max(by_degree)
        if not by_degree[top]:
            raise Unlucky
        roots = roots_mod([by_degree.get(k, 0) for k in range(top, -1, -1)], p)
        if not roots:
            raise Unlucky
        point[x] = rnd.choice(roots)
        return point, theta
    # sines and cosines alone: one angle through t = tan(q/2), the numerator of f in t
    from sympy.polys.galoistools import gf_add, gf_mul, gf_pow

    q = next(TRIG_BACK[R.symbols[i]].args[0] for i in involved)
    ci, si = circles[q]
    top = max((m[ci] if ci is not None else 0) + (m[si] if si is not None else 0)
              for m in f.monoms())
    num: list = []
    for m, c in f.items():
        t = term_mod(m, c, K, p, theta, point, skip=(ci, si))
        a = m[si] if si is not None else 0
        b = m[ci] if ci is not None else 0
        term = gf_mul(gf_mul(gf_pow([2 % p, 0], a, p, ZZ), gf_pow([p - 1, 0, 1], b, p, ZZ), p, ZZ),
                      gf_pow([1, 0, 1], top - a - b, p, ZZ), p, ZZ)
        num = gf_add(num, [t * k % p for k in term], p, ZZ)
    roots = [t for t in roots_mod(num, p) if (1 + t * t) % p]
    if not roots:
        raise Unlucky
    t = rnd.choice(roots)
    inv = pow(1 + t * t, -1, p)
    if si is not None:
        point[si] = 2 * t * inv % p
    if ci is not None:
        point[ci] = (1 - t * t) * inv % p
    return point, theta


def rank_on(B: list, RM: Any, f, seeds: int = 4) -> tuple | None:
    """``(rank, rows, cols, minor, basis)`` proved on ``f = 0`` where the minor is non-zero.

    ``B`` holds the members, each a tuple of elements of the ring ``RM`` (a screw
    system's members with their halves swapped, as ``analysis`` takes them, or the
    columns of any matrix); ``f`` is an element of ``RM``; ``rows`` are members,
    ``cols`` coordinates; ``basis`` is the Groebner basis of ``f`` and the circles
    (see the module's docstring).  None where no point proved a rank.
    """
    G = groebner_ideal([f], RM)
    if G == [RM.ring.one]:
        return None  # pragma: no cover - f has points (it came with real ones)
    if all(not e.rem(G) for b in B for e in b if e):  # every member (or none) zero there
        return 0, (), (), RM.one, G
    tried: set = set()
    for seed in range(seeds):
        rnd = random.Random(seed)
        for prime in PRIMES:
            try:
                point, theta = point_on(f, RM, prime, rnd)
                values = at_point(B, RM, prime, point, theta)
            except Unlucky:
                continue
            break
        else:
            continue
        rows, cols = rank_mod(values, prime)
        if not rows or (rows, cols) in tried:
            continue
        tried.add((rows, cols))
        minor = minor_det(B, rows, cols, RM)
        if not minor.rem(G):
            continue  # pragma: no cover - zero modulo f although not at the point
        vectors = cramer_vectors(B, rows, cols, RM, m=minor, width=len(B[0]))
        charge(sum(len(e.terms()) for v in vectors for e in v) * len(B))
        if all(not sum((b * x for b, x in zip(B[i], v, strict=True)), RM.zero).rem(G)
               for v in vectors for i in range(len(B)) if i not in rows):
            return len(rows), rows, cols, minor, G
    return None


def zero_on_surface(entries: list, fe: Any) -> bool:
    """Whether every polynomial (or rational function) of ``entries`` vanishes wherever
    ``fe = 0`` (where it is defined): each numerator is in the ideal of ``fe`` and the
    circles (one ring, one Groebner basis for all)."""
    nums = [fraction(cancel(e))[0] for e in entries]
    rg = ring_with(ImmutableMatrix(len(nums), 1, nums), fe)
    R = rg.ring
    G = groebner_ideal([ring_element(fe, R)], R)
    return all(not e.rem(G) for e in rg.cols[0])


def null_on_surface(M: ImmutableMatrix, fe: Any) -> tuple | None:
    """The null space of the matrix ``M`` at the generic point of ``fe = 0``: ring columns.

    ``(rank, members, null)``: ``rank`` columns of ``M`` (``members``) are
    independent at a point of the surface, and each vector of Cramer's rule on
    their minor (one per other column, polynomial, that column's entry the
    minor, reduced modulo ``fe``) is a null vector wherever ``fe = 0``: the
    columns of ``null`` (``M.cols x (M.cols - rank)``, in lowest terms), a
    basis of the null space wherever ``fe = 0`` and the minor is non-zero.
    None where no point proved it.
    """
    rg = ring_with(M, fe)
    found = rank_on([tuple(c) for c in rg.cols], rg.ring, ring_element(fe, rg.ring))
    R = rg.ring
    if found is None:
        return None
    rank, members, coords, minor, G = found
    B = [tuple(c) for c in rg.cols]
    vectors = []
    for j in range(len(B)):
        if j in members:
            continue
        x = [R.zero] * len(B)
        x[j] = minor
        for pp, p in enumerate(members):
            rows = [[B[j if q == pp else members[q]][c] for c in coords]
                    for q in range(len(members))]
            x[p] = -det_rows(rows, R)
        # the columns were cleared of denominators (cols[k] = scales[k] * column k)
        v = [(e * s).rem(G) for e, s in zip(x, rg.scales, strict=True)]
        vectors.append([to_expr(e, R) for e in primitive_vector(v, R)])
    null = ImmutableMatrix(vectors).T if vectors else ImmutableMatrix.zeros(M.cols, 0)
    return rank, members, null
