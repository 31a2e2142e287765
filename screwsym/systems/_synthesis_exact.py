"""Exact integer linear algebra of :mod:`screwsym.systems.synthesis`: ranks, null spaces and
the check of a limb's joint twists against a wanted motion (the checks 1-3 of that module's
docstring), on rows of integers or fractions.

Written apart from SymPy's DomainMatrix (or the library's ScrewSystem, lie_bracket and
reciprocal product) because the screening runs them on thousands of small integer matrices:
with DomainMatrix over QQ for rank and null, limbs() took 3-9x longer (3R 1.8 -> 16 s, 3T1R
11 -> 31 s) for the same limb types.  The kept types are re-checked by ScrewSystem.
"""

from __future__ import annotations

from fractions import Fraction
from math import gcd
from typing import Any

__all__ = ["rank", "null", "null_rows", "cross", "bracket", "reciprocal", "check_rows"]


def rank(rows: list) -> int:
    """The rank of a list of rational vectors, by fraction-free elimination over Z (exact)."""
    m = []
    for r in rows:
        if all(type(x) is int for x in r):
            m.append(list(r))
            continue
        den = 1
        for x in r:
            den = den * Fraction(x).denominator // gcd(den, Fraction(x).denominator)
        m.append([int(Fraction(x) * den) for x in r])
    rank, cols = 0, len(m[0]) if m else 0
    for c in range(cols):
        piv = next((i for i in range(rank, len(m)) if m[i][c]), None)
        if piv is None:
            continue
        m[rank], m[piv] = m[piv], m[rank]
        p = m[rank]
        for i in range(rank + 1, len(m)):
            a = m[i][c]
            if a:
                row = [p[c] * x - a * y for x, y in zip(m[i], p, strict=True)]
                g = 0
                for x in row:
                    g = gcd(g, x)
                m[i] = [x // g for x in row] if g > 1 else row
        rank += 1
    return rank


def null(cols: list) -> list:
    """A basis of ``{x : sum x_i cols[i] = 0}`` (the columns as vectors), exact over Q."""
    n = len(cols)
    rows = [[Fraction(c[k]) for c in cols] for k in range(len(cols[0]))]
    pivots: list = []
    r = 0
    for c in range(n):
        piv = next((i for i in range(r, len(rows)) if rows[i][c]), None)
        if piv is None:
            continue
        rows[r], rows[piv] = rows[piv], rows[r]
        p = rows[r][c]
        rows[r] = [a / p for a in rows[r]]
        for i in range(len(rows)):
            if i != r and rows[i][c]:
                f = rows[i][c]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[r], strict=True)]
        pivots.append(c)
        r += 1
    basis = []
    for free in (c for c in range(n) if c not in pivots):
        x = [Fraction(0)] * n
        x[free] = Fraction(1)
        for i, c in enumerate(pivots):
            x[c] = -rows[i][free]
        basis.append(x)
    return basis


def cross(a: tuple, b: tuple) -> tuple:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def bracket(a: tuple, b: tuple) -> tuple:
    """``ad_a b`` in ray order (the formula of :func:`~screwsym.systems.second_order.lie_bracket`)."""
    wa, va, wb, vb = a[:3], a[3:], b[:3], b[3:]
    w = cross(wa, wb)
    v = tuple(x - y for x, y in zip(cross(wa, vb), cross(wb, va), strict=True))
    return w + v


def reciprocal(w: tuple, t: tuple) -> Any:
    """``w o t = f . v + m . omega`` (1.45), ``w = (f; m)``, ``t = (omega; v)``."""
    return sum(w[i] * t[i + 3] + w[i + 3] * t[i] for i in range(3))




def check_rows(J: list, G: list, acc: dict | None = None) -> str | None:
    """Why the joint twists ``J`` (integer 6-tuples) do not give the motion ``G``, or None;
    ``acc``: the derivative of joint ``k``'s twist along its own path (a parallelogram's)."""
    n, m = len(J), len(G)
    if rank(J) < n:
        return "its joint twists are dependent (a passive freedom)"
    if rank(J + G) > n:
        return "its twists do not contain the wanted motion"
    for k in range(n):
        if rank(J[:k] + J[k + 1:] + G) < n:
            return f"joint {k + 1} (from the base) is locked in the wanted motion"
    if n == 6:
        return None
    # rates qdot with J qdot in T_M: the x parts of the null vectors of [J | G]
    K = [x[:n] for x in null(J + G)]
    assert len(K) == m
    # the constraint wrenches: reciprocal to every row of J (the rows with halves swapped)
    W = null_rows([r[3:] + r[:3] for r in J])
    for w in W:
        S = [[Fraction(0)] * n for _ in range(n)]
        for i in range(n):
            for j in range(i + 1, n):
                S[i][j] = Fraction(reciprocal(w, bracket(J[i], J[j])))
        D = {k: Fraction(reciprocal(w, t)) for k, t in (acc or {}).items()}
        for a in K:
            for b in K:
                val = sum(S[i][j] * (a[i] * b[j] + b[i] * a[j]) for i in range(n)
                          for j in range(i + 1, n))
                val += sum(2 * d * a[k] * b[k] for k, d in D.items())
                if val:
                    return "its motion does not extend to second order within the wanted motion"
    return None


def null_rows(rows: list) -> list:
    """A basis of ``{x : r . x = 0 for every row r}``."""
    return null([list(c) for c in zip(*rows, strict=True)])
