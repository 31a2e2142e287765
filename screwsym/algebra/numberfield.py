r"""Arithmetic over an algebraic number field ``Q(theta)`` through ``Q[x, theta]``.

Over K = Q(theta) (``QQ<sqrt(3)>``) SymPy's polynomials carry ANP coefficients, and its
determinants (Berkowitz), gcds (dense subresultant PRS) and factorisations (Trager,
whose gcds are those PRS) are slow: profiled on Tsai's 3-RPS at a symbolic pose, 316 s
of factoring one 6 x 6 determinant of degree 12 (not finished) and about 20 s of gcds.
Here an element of K[x] is lifted to Q[x, theta] (theta one more symbol, degree below
that of its minimal polynomial ``mp``); the map back, reduction modulo ``mp``, is a ring
homomorphism, so a determinant computed in Q[x, theta] and reduced is the determinant
over K exactly.  Factors and gcds are SymPy's own answers (the unique monic ones, in
SymPy's order), found by cheaper routes where a proof is at hand and by SymPy otherwise.
"""

from __future__ import annotations

import random
from functools import lru_cache
from itertools import combinations

from sympy import (
    QQ,
    Add,
    Dummy,
    Integer,
    Poly,
    Rational,
    S,
    factorint,
    sqrt,
)
from sympy.polys.densearith import dup_rem
from sympy.polys.polyutils import _sort_factors

__all__ = [
    "lifted_ring",
    "lift",
    "lower",
    "theta_parts",
    "field_norm",
    "field_gcd",
    "field_lcm",
    "ring_gcd",
    "irreducible_over_field",
    "field_factor_list",
    "surd_split",
    "reduce_surds",
    "surd_normal",
    "surd_quotient",
    "SURD_PRIMES",
]


@lru_cache(maxsize=64)
def lifted_ring(R):
    """``Q[x, theta]`` for the ring ``R = Q(theta)[x]`` (theta the last symbol)."""
    return QQ[tuple(R.symbols) + (Dummy("theta"),)]


def lift(p, R):
    """The element ``p`` of ``Q(theta)[x]`` as a polynomial of ``Q[x, theta]``."""
    L = lifted_ring(R)
    d = {}
    for m, c in p.items():
        rep = c.to_list()
        top = len(rep) - 1
        for i, q in enumerate(rep):
            if q:
                d[m + (top - i,)] = q
    return L.ring.from_dict(d) if d else L.zero


def lower(P, R):
    """``P`` of ``Q[x, theta]`` reduced modulo the minimal polynomial: an element of ``R``."""
    K = R.domain
    mod = K.mod.to_list()
    groups: dict = {}
    for m, c in P.items():
        groups.setdefault(m[:-1], {})[m[-1]] = c
    out = {}
    for m, cs in groups.items():
        rep = [cs.get(k, QQ.zero) for k in range(max(cs), -1, -1)]
        if len(rep) >= len(mod):
            rep = dup_rem(rep, mod, QQ)
        if rep:
            out[m] = K.new(rep)
    return R.ring.from_dict(out) if out else R.zero


def theta_parts(P, R) -> list:
    """The coefficients of ``theta**0, theta**1, ...`` in ``P`` (``Q[x, theta]``), as polynomials
    there (up to the highest power present)."""
    L = lifted_ring(R).ring
    parts: dict = {}
    for m, c in P.items():
        parts.setdefault(m[-1], {})[m[:-1] + (0,)] = c
    top = max(parts, default=-1)
    return [L.from_dict(parts[k]) if k in parts else L.zero for k in range(top + 1)]


def field_norm(P, R):
    """``Res_theta(P, mp)``: a polynomial of ``Q[x]`` (in ``Q[x, theta]``) that vanishes where
    ``P`` or one of its conjugates does."""
    L = lifted_ring(R)
    mod = R.domain.mod.to_list()
    if len(mod) == 3 and P.degree(len(R.symbols)) <= 1:
        # mp = t**2 + a t + b, P = u + v t: (u + v t1)(u + v t2) = u**2 - a u v + b v**2
        u, v = (theta_parts(P, R) + [L.zero, L.zero])[:2]
        a, b = mod[1], mod[2]
        return u**2 - u * v * a + v**2 * b
    t = L.gens[-1]
    m = L.zero
    for k, c in enumerate(reversed(mod)):
        m += c * t**k
    # the resultant in theta: theta first
    gens = (L.symbols[-1], *L.symbols[:-1])
    S = QQ[gens]
    perm = lambda e: e[-1:] + e[:-1]  # noqa: E731
    Ps = S.ring.from_dict({perm(k): v for k, v in P.items()})
    ms = S.ring.from_dict({perm(k): v for k, v in m.items()})
    r = Ps.resultant(ms)
    if not r:
        return L.zero
    # SymPy returns the resultant in the ring without theta (or, in older versions, with it)
    drop = 1 if len(next(iter(r.keys()))) == len(gens) else 0
    return L.ring.from_dict({k[drop:] + (0,): v for k, v in r.items()})


def field_gcd(a, b, R):
    """``R.gcd(a, b)`` over an algebraic field: the monic gcd, by SymPy's PRS only where needed.

    Both rational (no theta): the gcd over Q is the gcd over K.  Norms coprime over
    Q: the gcd is 1 (a common factor ``h`` would give the common factor ``N(h)``).
    """
    if not a or not b or len(a) == 1 or len(b) == 1:
        return R.gcd(a, b)
    A, B = lift(a, R), lift(b, R)
    i = len(R.symbols)
    if A.degree(i) <= 0 and B.degree(i) <= 0:
        g = A.gcd(B)
        return lower(g, R).monic()
    if field_norm(A, R).gcd(field_norm(B, R)).is_ground:
        return R.one
    return R.gcd(a, b)


def field_lcm(a, b, R):
    """``R.lcm(a, b)`` (SymPy's formula over a field) with the gcd of :func:`field_gcd`."""
    return (a * b).quo(field_gcd(a, b, R)).monic()


def ring_gcd(a, b, R):
    return field_gcd(a, b, R) if R.domain.is_Algebraic else R.gcd(a, b)


def irreducible_over_field(g, R, seed: int = 0, tries: int = 4) -> bool:
    """True if ``g`` (in ``Q[x, theta]`` without theta, irreducible over Q) is proved irreducible
    over the algebraic field of ``R``; False: not proved.

    Such a ``g`` has no content over K in any of its symbols (a factor ``c`` of the content
    would bring its conjugates, and their product, a rational factor of ``g``), so a
    specialisation of the other symbols to integers that keeps the degree in one symbol
    and is irreducible over K (a univariate factorisation) proves ``g`` irreducible over K.
    """
    L = lifted_ring(R)
    n = len(R.symbols)
    involved = [i for i in range(n) if g.degree(i) > 0]
    if not involved:
        return True
    x = max(involved, key=lambda i: g.degree(i))
    others = [i for i in involved if i != x]
    lead = g.coeff_wrt(L.gens[x], g.degree(x))
    if others:
        # the proof needs g primitive in x (true for g irreducible over Q, the callers'
        # case): a factor free of x would vanish from every specialisation unseen
        content = lead
        for k in range(g.degree(x)):
            if content.is_ground:
                break
            c = g.coeff_wrt(L.gens[x], k)
            if c:
                content = content.gcd(c)
        if not content.is_ground:
            return False
    rnd = random.Random(seed)
    K = R.domain
    for _ in range(tries):
        point = {i: rnd.randint(-9, 9) for i in others}
        if others:
            at = [(L.gens[i], QQ(point[i])) for i in others]
            if not lead.evaluate(at):
                continue
            u = g.evaluate(at)
        else:
            u = g
        expr = u.as_expr()
        poly = Poly(expr, L.symbols[x], domain=K)
        _, fl = poly.factor_list()
        if len(fl) == 1 and fl[0][1] == 1:
            return True
        if not others:
            return False
    return False


def field_factor_list(p, R) -> list:
    """``p.factor_list()[1]``: the irreducible factors with their multiplicities, SymPy's order.

    Over an algebraic field K, lifted to ``Q[x, theta]``: ``p = c * F`` with ``c`` the
    content over ``Q[x]`` of the coefficients of the powers of theta and ``F`` primitive.
    The factors of ``c`` over Q, each proved irreducible over K
    (:func:`irreducible_over_field`), and ``F``, proved irreducible over K by its norm being
    irreducible over Q (a factorisation over K is one of the norm), are the factors over K
    (made monic, as SymPy's).  Where a proof fails, SymPy factors ``p`` over K.
    """
    if not R.domain.is_Algebraic:
        return p.factor_list()[1]
    P = lift(p, R)
    i = len(R.symbols)
    parts = [e for e in theta_parts(P, R) if e]
    c = parts[0]
    for e in parts[1:]:
        c = c.gcd(e)
    F = P.exquo(c)
    out = []
    if not c.is_ground:
        for g, k in c.factor_list()[1]:
            if g.is_ground:
                continue
            if not irreducible_over_field(g, R):
                return p.factor_list()[1]
            out.append((lower(g, R).monic(), k))
    if F.degree(i) > 0:
        fl = [(g, k) for g, k in field_norm(F, R).factor_list()[1] if not g.is_ground]
        if len(fl) != 1 or fl[0][1] != 1:
            return p.factor_list()[1]
        out.append((lower(F, R).monic(), 1))
    ring = R.ring
    dense = [(f.to_dense(), k) for f, k in out]
    return [(ring.from_dense(f), k) for f, k in _sort_factors(dense)]


# --------------------------------------------------------------------------
# Square roots of rationals: Q(sqrt p_1, ..., sqrt p_k) as Q[r_1, ..., r_k] / (r_i**2 - p_i)
# --------------------------------------------------------------------------

#: integer powers above this are not expanded (a number's normal form, :func:`surd_normal`)
SURD_POWER = 32
#: square roots of numbers with more digits than this are not split into primes (factoring)
SURD_DIGITS = 30


def surd_split(n: Rational) -> tuple[Rational, tuple[int, ...]] | None:
    """``sqrt(n) = k * sqrt(p_1) ... sqrt(p_j)`` for a positive rational ``n``: ``(k, (p_1, ...))``.

    The primes are distinct and increasing; None for a number too large to factor cheaply
    (more than ``SURD_DIGITS`` digits).

    >>> from sympy import Rational
    >>> surd_split(Rational(3, 8))            # sqrt(3/8) = sqrt(6)/4 = 1/4 sqrt(2) sqrt(3)
    (1/4, (2, 3))
    >>> surd_split(Rational(12))
    (2, (3,))
    """
    n = Rational(n)
    if n <= 0:
        raise ValueError(f"n: expected a positive rational, got {n}")
    top = n.p * n.q  # sqrt(p/q) = sqrt(p q) / q
    if len(str(top)) > SURD_DIGITS:
        return None
    k, primes = Integer(1), []
    for prime, e in sorted(factorint(top).items()):
        k *= Integer(prime) ** (e // 2)
        if e % 2:
            primes.append(int(prime))
    return k / n.q, tuple(primes)


def reduce_surds(P, surds) -> object:
    """``P`` modulo ``r**2 - p`` for each ``(r, p)`` pair (generator index, prime):
    every ``r**k`` made ``p**(k // 2) r**(k mod 2)``.

    The normal form in ``Q(sqrt p_1, ..., sqrt p_k)[x]``: the leading terms ``r**2`` are
    coprime (a Groebner basis), and the square roots of distinct primes are linearly
    independent over Q (Besicovitch 1940), so ``P`` is zero there exactly when this is 0.

    >>> from sympy import QQ
    >>> from sympy.polys.rings import ring
    >>> R, x, r2, r3 = ring("x r2 r3", QQ)
    >>> reduce_surds((x + r2 * r3) ** 2, [(1, 2), (2, 3)])   # (x + sqrt 6)**2
    x**2 + 2*x*r2*r3 + 6
    """
    ring = P.ring
    if not any(m[r] >= 2 for m in P.itermonoms() for r, _ in surds):
        return P
    out: dict = {}
    zero = ring.domain.zero
    for m, c in P.iterterms():
        ml = list(m)
        for r, p in surds:
            j, ml[r] = divmod(ml[r], 2)
            if j:
                c = c * ring.domain(p) ** j
        mt = tuple(ml)
        out[mt] = out.get(mt, zero) + c
    return ring.from_dict({m: c for m, c in out.items() if c})


def surd_normal(e) -> object:
    """A number built from rationals and square roots of positive rationals by sums and
    products, as its normal form ``sum c_i sqrt(m_i)`` (rational ``c_i``, distinct square-free
    ``m_i``); None for any other number (a quotient by a root, a cube root, ``pi``, ...).

    SymPy merges ``sqrt(2)*sqrt(3)`` into ``sqrt(6)`` but does not expand products of
    sums, so an entry of a product of rotations at 15 degrees grows with every factor.

    >>> from sympy import sqrt
    >>> surd_normal((sqrt(2)/4 + sqrt(6)/4) * (sqrt(6)/4 - sqrt(2)/4))   # cos 15 sin 15 = sin 30 / 2
    1/4
    >>> surd_normal(sqrt(2) / (1 + sqrt(3))) is None
    True
    """
    primes: dict = {}
    terms = _surd_terms(e, primes)
    if terms is None:
        return None
    out = []
    for mono, c in sorted(terms.items()):
        root = 1
        for p in mono:
            root *= p
        out.append(Rational(c) * sqrt(Integer(root)) if root != 1 else Rational(c))
    return Add(*out)


def _surd_terms(e, primes: dict) -> dict | None:
    """``e`` as ``{(p_1, ..., p_j): rational}`` (a product of distinct primes' roots), or None."""
    if e.is_Rational:
        return {(): QQ(e.p, e.q)} if e else {}
    if e.is_Pow and e.exp == S.Half and e.base.is_Rational and e.base > 0:
        split = surd_split(e.base)
        if split is None:
            return None
        k, ps = split
        for p in ps:
            primes[p] = True
        return {ps: QQ(k.p, k.q)}
    if e.is_Add:
        total: dict = {}
        for a in e.args:
            t = _surd_terms(a, primes)
            if t is None:
                return None
            _merge(total, t)
        return total
    if e.is_Mul or e.is_Pow and e.exp.is_Integer and 0 <= e.exp <= SURD_POWER:
        factors = e.args if e.is_Mul else [e.base] * int(e.exp)
        prod: dict = {(): QQ.one}
        for a in factors:
            t = _surd_terms(a, primes)
            if t is None:
                return None
            prod = _multiply(prod, t)
        return prod
    return None


def _merge(total: dict, t: dict) -> None:
    for m, c in t.items():
        v = total.get(m, QQ.zero) + c
        if v:
            total[m] = v
        else:
            total.pop(m, None)


def _multiply(a: dict, b: dict) -> dict:
    out: dict = {}
    for ma, ca in a.items():
        for mb, cb in b.items():
            both = set(ma) & set(mb)
            c = ca * cb
            for p in both:
                c *= p
            _merge(out, {tuple(sorted(set(ma) ^ set(mb))): c})
    return out


#: a quotient is made a normal form (:func:`surd_quotient`) over at most this many primes' roots
#: (the inverse is the product of the ``2**k - 1`` conjugates)
SURD_PRIMES = 4


def surd_quotient(e) -> object:
    """A quotient of numbers built from rationals and square roots of rationals, in the normal
    form of :func:`surd_normal`; None for any other number, a zero denominator, or more than
    :data:`SURD_PRIMES` primes under the roots of the denominator.

    The inverse of ``x`` in ``Q(sqrt p_1, ..., sqrt p_k)`` is the product of its conjugates
    (each ``sqrt p_i -> -sqrt p_i`` for a non-empty set of the ``i``) over the norm ``N(x)``,
    their product with ``x``: a non-zero rational (the Galois group of the field is
    ``(Z/2)**k``; Besicovitch 1940 for the independence of the roots).

    >>> from sympy import sqrt
    >>> surd_quotient(sqrt(2) / (1 + sqrt(3)))
    -sqrt(2)/2 + sqrt(6)/2
    >>> surd_quotient(1 / (2 - sqrt(3)) / (2 + sqrt(3)))     # the norm of 2 - sqrt 3 is 1
    1
    >>> from sympy import Mul, Pow
    >>> surd_quotient(Mul(1, Pow((1 + sqrt(2))**2 - 3 - 2*sqrt(2), -1, evaluate=False),
    ...                   evaluate=False)) is None   # a denominator that is zero
    True
    """
    numer, denom = e.as_numer_denom()
    primes: dict = {}
    top = _surd_terms(numer, primes)
    bottom = _surd_terms(denom, {})
    if top is None or bottom is None or not bottom:
        return None
    inverse = _inverse(bottom)
    if inverse is None:
        return None
    out = []
    for mono, c in sorted(_multiply(top, inverse).items()):
        root = 1
        for p in mono:
            root *= p
        out.append(Rational(c) * sqrt(Integer(root)) if root != 1 else Rational(c))
    return Add(*out)


def _inverse(t: dict) -> dict | None:
    """``1/x`` for ``x`` given as :func:`_surd_terms`' dict (non-zero), by its conjugates."""
    ps = sorted({p for m in t for p in m})
    if len(ps) > SURD_PRIMES:
        return None
    conjugates: dict = {(): QQ.one}
    for r in range(1, len(ps) + 1):
        for flipped in combinations(ps, r):
            sign = set(flipped)
            conjugates = _multiply(conjugates, {m: c * (-1) ** len(sign & set(m)) for m, c in t.items()})
    norm = _multiply(t, conjugates)
    if set(norm) != {()}:  # pragma: no cover - the norm is rational (Galois theory)
        return None
    return {m: c / norm[()] for m, c in conjugates.items()}
