r"""The general 6-6 Gough-Stewart platform: every assembly mode, found numerically, each certified.

What it decides.  Six legs join base points ``a_i`` to platform points ``b_i`` (no pairing
assumed); given the squared leg lengths ``l_i**2`` (rational) it finds the isolated assembly
modes, proves each one (a box proven to hold exactly one solution of the exact equations),
proves which are real, and proves the list complete when it holds as many modes as a
general 6-6 can have (40).

The equations: Study's parameters (Husty 1996).  A pose is a point ``z = (x, y)`` of
``P^7``: ``x`` a quaternion (the rotation ``R v = x v x~ / |x|**2``), ``y`` a quaternion with
the translation ``t = 2 y x~ / |x|**2``, on the Study quadric ``x . y = 0`` (the scalar part
of ``y x~``).  Leg ``i`` closes, ``|t + R b_i - a_i|**2 = l_i**2``, exactly when (times
``|x|**2``, the Study quadric used once)

    ``|2 y + x b_i - a_i x|**2 - l_i**2 |x|**2 = 0``

a quadric in ``z``: the quaternion ``2 y x~ + x b_i x~ - |x|**2 a_i = (2 y + x b_i - a_i x) x~``
has norm ``|2 y + x b_i - a_i x|**2 |x|**2`` and, on the Study quadric, no scalar part.
Seven quadrics in ``P^7`` (total degree 2**7 = 128).  Every point of the *exceptional
generator* ``x = 0`` with ``y . y = 0`` solves them (a surface, no pose): 88 of the 128
paths end there and are discarded.  A general 6-6 has at most 40 isolated complex modes
(Raghavan 1993 numerically; Ronga & Vust 1995, Lazard 1993, Mourrain 1993 proved it; Husty
1996 the univariate polynomial of degree 40), and 40 can all be real (Dietmaier 1998).

How: a homotopy, then a proof.
1. *Homotopy continuation* (total degree, the gamma trick: Morgan & Sommese 1987; Sommese &
   Wampler 2005) from ``G_k = z_k**2 - z_0**2`` (128 known solutions) to the quadrics, on
   a random complex patch ``h . z = 1``: ``H(z, s) = (1 - s) gamma G(z) + s F(z)``.  All
   paths are tracked together, vectorised in NumPy: a fourth-order Runge-Kutta predictor
   along ``dz/ds = -H_z^{-1} H_s``, Newton's corrector, the step per path doubled after
   three successes and halved on a failure.  Endpoints whose ``x`` vanishes are the
   exceptional generator's; the others are polished by Newton's method at ``s = 1``.
   Floating point decides nothing here: it only proposes.
2. *Krawczyk's test* (Krawczyk 1969; Moore, Kearfott & Cloud 2009) proves
   each proposal, in exact rational arithmetic (Python's ``Fraction``) on the exact
   equations: on the real chart ``c . x = 1`` (``c`` rational) the 8 equations
   ``F(w) = 0`` are quadratic, so for a box ``X = m +- r`` the Krawczyk operator
   ``K = m - Y F(m) + (I - Y F'(X)) (X - m)`` is bounded exactly, entry by entry:
   ``|Y F(m)| + (|I - Y F'(m)| + |Y| rad F'(X)) r``.  Below ``r`` everywhere: exactly one
   solution in ``X``, and it is non-singular.  A real proposal is proved in ``R^8`` (a real
   solution in a real box: a real mode); a non-real one in ``R^16`` (real and imaginary
   parts), with a box whose imaginary part excludes 0 (a non-real solution).  Pairwise
   disjoint boxes hold distinct solutions.
3. *Completeness*: 40 distinct certified solutions reach the bound, so no isolated mode is
   missing (``complete=True``; the bound is on isolated modes: a curve of modes besides them,
   a self-motion, is not excluded by this argument); fewer (a path lost, after three homotopies with new random
   constants) is reported as such (``complete=False`` and the count), never silently.

Why not the alternatives.  SymPy's ``groebner`` already takes about 70 s on a 6-3 platform
(16 modes: tests/systems/test_assembly.py) and is not tried on 40; Husty's elimination to a
univariate polynomial of degree 40 is not done either, so the result's ``polynomial`` is
``None``.  The total-degree homotopy in Study's parameters has 128 paths, where PHCpack's
formulation of Dietmaier's example (position and two columns of the rotation, 9 unknowns)
has a mixed volume of 1536 (``src/Demo/stewgou40``): fewer paths, each short.
Certification by Krawczyk's test on the exact equations, rather than a residual below a
tolerance, keeps the library's rule: no tolerance as a verdict.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from math import gcd
from typing import Any

import numpy as np

from ..algebra.budget import charge

__all__ = ["CertifiedMode", "general_modes", "study_quadrics", "krawczyk", "MAX_MODES"]

#: the most isolated complex assembly modes a general 6-6 Gough-Stewart platform has
#: (Ronga & Vust 1995; Lazard 1993; Mourrain 1993; Husty 1996)
MAX_MODES = 40


# --------------------------------------------------------------------------------------
# quaternions and the equations, exact
# --------------------------------------------------------------------------------------


def _qmul(p: tuple, q: tuple) -> tuple:
    """The quaternion product ``p q`` (``(w, x, y, z)``, generic entries)."""
    a0, a1, a2, a3 = p
    b0, b1, b2, b3 = q
    return (
        a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3,
        a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
        a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1,
        a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0,
    )


def _mul_matrix(a: tuple, b: tuple) -> list:
    """The 4 x 4 matrix ``M`` with ``M x = x b - a x`` (``a``, ``b`` pure quaternions)."""
    cols = []
    for k in range(4):
        e = tuple(Fraction(int(i == k)) for i in range(4))
        xb = _qmul(e, (Fraction(0), *b))
        ax = _qmul((Fraction(0), *a), e)
        cols.append([u - v for u, v in zip(xb, ax, strict=True)])
    return [[cols[j][i] for j in range(4)] for i in range(4)]


def study_quadrics(a: tuple, b: tuple, l2: tuple) -> list:
    """The seven quadrics of the 6-6 in Study's parameters, exact: 8 x 8 symmetric matrices
    of ``Fraction`` (``z = (x0, x1, x2, x3, y0, y1, y2, y3)``, the quadric ``z^T Q z``).

    Leg ``i``: ``|2 y + M_i x|**2 - l_i**2 |x|**2`` with ``M_i x = x b_i - a_i x``; the last,
    the Study quadric ``x . y``.

    >>> Q = study_quadrics(((0, 0, 0),) * 6, ((0, 0, 0),) * 6, (1,) * 6)
    >>> [int(Q[0][i][i]) for i in range(8)], Q[6][0][4]
    ([-1, -1, -1, -1, 4, 4, 4, 4], Fraction(1, 2))
    """
    out = []
    for ai, bi, q in zip(a, b, l2, strict=True):
        M = _mul_matrix(tuple(Fraction(v) for v in ai), tuple(Fraction(v) for v in bi))
        Q = [[Fraction(0)] * 8 for _ in range(8)]
        for i in range(4):
            for j in range(4):
                Q[i][j] = sum((M[k][i] * M[k][j] for k in range(4)), Fraction(0))
            Q[i][i] -= Fraction(q)
            Q[4 + i][4 + i] = Fraction(4)
            for j in range(4):  # 4 y . M x, split symmetrically
                Q[4 + i][j] += 2 * M[i][j]
                Q[j][4 + i] += 2 * M[i][j]
        out.append(Q)
    S = [[Fraction(0)] * 8 for _ in range(8)]
    for i in range(4):
        S[i][4 + i] = S[4 + i][i] = Fraction(1, 2)
    out.append(S)
    return out


def _rotation(x: tuple) -> list:
    """``R`` with ``R v = x v x~ / |x|**2`` (Euler-Rodrigues), exact for exact ``x``."""
    w, i, j, k = x
    d = w * w + i * i + j * j + k * k
    return [
        [(w * w + i * i - j * j - k * k) / d, 2 * (i * j - w * k) / d, 2 * (i * k + w * j) / d],
        [2 * (i * j + w * k) / d, (w * w - i * i + j * j - k * k) / d, 2 * (j * k - w * i) / d],
        [2 * (i * k - w * j) / d, 2 * (j * k + w * i) / d, (w * w - i * i - j * j + k * k) / d],
    ]


def pose_from_study(z: tuple) -> tuple[list, list]:
    """``(t, R)`` of the Study point ``z = (x, y)``: ``t = 2 y x~ / |x|**2`` (``y`` first
    made Study-orthogonal to ``x``, exactly: ``y - (x . y / |x|**2) x``), ``R`` of ``x``."""
    x, y = z[:4], z[4:]
    d = sum(v * v for v in x)
    s = sum(u * v for u, v in zip(x, y, strict=True)) / d
    y = tuple(v - s * u for u, v in zip(x, y, strict=True))
    q = _qmul(y, (x[0], -x[1], -x[2], -x[3]))
    return [2 * q[n] / d for n in (1, 2, 3)], _rotation(x)


def study_from_pose(t: Any, R: Any) -> tuple:
    """Study's parameters ``(x, y)`` of a pose with exact rational ``t`` and rotation ``R``,
    up to a factor and rational: ``x`` is the column of ``4 x x^T`` (a matrix of the entries
    of ``R``) with the largest diagonal entry (Shepperd 1978; never zero for a rotation), and
    ``y = t x / 2``.

    >>> [str(v) for v in study_from_pose([0, 0, 2], [[1, 0, 0], [0, 1, 0], [0, 0, 1]])]
    ['4', '0', '0', '0', '0', '0', '0', '4']
    """
    (r11, r12, r13), (r21, r22, r23), (r31, r32, r33) = R
    cols = [
        (1 + r11 + r22 + r33, r32 - r23, r13 - r31, r21 - r12),
        (r32 - r23, 1 + r11 - r22 - r33, r12 + r21, r13 + r31),
        (r13 - r31, r12 + r21, 1 - r11 + r22 - r33, r23 + r32),
        (r21 - r12, r13 + r31, r23 + r32, 1 - r11 - r22 + r33),
    ]
    x = tuple(Fraction(v) for v in cols[max(range(4), key=lambda i: cols[i][i])])
    y = _qmul((Fraction(0), *(Fraction(v) for v in t)), x)
    return (*x, *(v / 2 for v in y))


# --------------------------------------------------------------------------------------
# Krawczyk's test, exact
# --------------------------------------------------------------------------------------


def _chart_system(quadrics: list, c: tuple) -> tuple[list, list, list]:
    """The 8 equations on the chart ``c . x = 1`` as ``(A, b, k)``: ``w^T A_e w + b_e . w +
    k_e``; the quadrics, then the chart."""
    zero = [[Fraction(0)] * 8 for _ in range(8)]
    A = [*quadrics, zero]
    b = [[Fraction(0)] * 8 for _ in quadrics] + [[Fraction(v) for v in c] + [Fraction(0)] * 4]
    k = [Fraction(0)] * len(quadrics) + [Fraction(-1)]
    return A, b, k


def _split(A: list, b: list, k: list) -> tuple[list, list, list]:
    """The real form (``w = u + i v``, unknowns ``(u, v)``) of a system with real
    coefficients: each equation its real and its imaginary part."""
    n = len(b[0])
    A2, b2, k2 = [], [], []
    for Ae, be, ke in zip(A, b, k, strict=True):
        re = [[Fraction(0)] * (2 * n) for _ in range(2 * n)]
        im = [[Fraction(0)] * (2 * n) for _ in range(2 * n)]
        for i in range(n):
            for j in range(n):
                re[i][j], re[n + i][n + j] = Ae[i][j], -Ae[i][j]
                im[i][n + j] = im[n + i][j] = Ae[i][j]
        A2 += [re, im]
        b2 += [[*be, *[Fraction(0)] * n], [*[Fraction(0)] * n, *be]]
        k2 += [ke, Fraction(0)]
    return A2, b2, k2


def krawczyk(A: list, b: list, k: list, m: list, r: Fraction) -> bool:
    """Whether the box ``m +- r`` (every coordinate) provably holds exactly one solution of
    the quadratic system ``w^T A_e w + b_e . w + k_e = 0`` (``e = 1..n``, ``n`` unknowns),
    a non-singular one: Krawczyk's test, every bound exact (``Fraction``).

    ``Y`` is a floating-point inverse of the Jacobian at ``m`` (any matrix is sound; a good
    one makes the test pass).  With ``C = I - Y F'(m)`` and ``F'(X) = F'(m) +- D`` (``D``
    exact: ``2 sum_l |A_e[j][l]| r``), ``K(X) - m`` lies within
    ``|Y F(m)| + (|C| + |Y| D) r``; strictly below ``r``: ``K(X)`` in the interior of ``X``.

    >>> A = [[[Fraction(1)]]]; b = [[Fraction(0)]]; k = [Fraction(-2)]     # w**2 = 2
    >>> krawczyk(A, b, k, [Fraction(141421, 100000)], Fraction(1, 1000))
    True
    >>> krawczyk(A, b, k, [Fraction(15, 10)], Fraction(1, 1000))   # sqrt(2) not within
    False
    """
    n = len(m)
    charge(5 * n**3)
    # integers throughout: the system times its common denominator q, m = M / dm, Y = Yi / 2**60
    q = _lcm([v.denominator for Ae in A for row in Ae for v in row] + [v.denominator for be in b for v in be] + [v.denominator for v in k])
    dm = _lcm([Fraction(v).denominator for v in m])
    M = [int(Fraction(v) * dm) for v in m]
    F, J, S = [], [], []  # F * q * dm**2, J * q * dm, sum_l |A_e[j][l]| * q
    for Ae, be, ke in zip(A, b, k, strict=True):
        Ai = [[int(v * q) for v in row] for row in Ae]
        bi, ki = [int(v * q) for v in be], int(ke * q)
        AM = [sum(a * x for a, x in zip(row, M, strict=True) if a) for row in Ai]
        F.append(sum(x * y for x, y in zip(M, AM, strict=True)) + dm * sum(u * x for u, x in zip(bi, M, strict=True) if u) + dm * dm * ki)
        J.append([2 * AM[j] + dm * bi[j] for j in range(n)])
        S.append([sum(abs(a) for a in row) for row in Ai])
    try:  # the Jacobian at m, in floats, inverted
        Yf = np.linalg.inv(np.array([[float(Fraction(v, q * dm)) for v in row] for row in J]))
    except np.linalg.LinAlgError:
        return False
    if not np.all(np.isfinite(Yf)):
        return False
    # Y = Yi / 2**60 with Yi = Yf 2**60 rounded (any Y is sound): Y J = Yi J / (2**60 q dm),
    # Y F = Yi F / (2**60 q dm**2), and the sum over j of (|Y| D)_ij is 2 r sum |Yi| S / (2**60 q)
    big = 2**60
    Yi = [[int(round(float(v) * big)) for v in row] for row in Yf]
    sj = big * q * dm
    for i in range(n):
        row = Yi[i]
        yf = Fraction(abs(sum(y * f for y, f in zip(row, F, strict=True))), sj * dm)
        c = sum(abs((sj if i == j else 0) - sum(row[e] * J[e][j] for e in range(n))) for j in range(n))
        d = sum(abs(row[e]) * S[e][j] for e in range(n) for j in range(n))
        bound = yf + (Fraction(c, sj) + 2 * r * Fraction(d, big * q)) * r
        if not bound < r:
            return False
    return True


def _lcm(values: list) -> int:
    out = 1
    for v in values:
        out = out * v // gcd(out, v)
    return out


# --------------------------------------------------------------------------------------
# the homotopy, in floating point: it proposes, the test decides
# --------------------------------------------------------------------------------------


def _track(Q: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """The 128 endpoints (complex, homogeneous, on a random patch) of the total-degree
    homotopy to the quadrics ``Q`` (7 x 8 x 8, float); NaN rows for lost paths."""
    n = Q.shape[1]
    gamma = np.exp(2j * np.pi * rng.random())
    h = rng.normal(size=n) + 1j * rng.normal(size=n)
    signs = np.array(np.meshgrid(*[[1.0, -1.0]] * (n - 1), indexing="ij")).reshape(n - 1, -1).T
    Z = np.concatenate([np.ones((signs.shape[0], 1)), signs], axis=1).astype(complex)
    Z /= (Z @ h)[:, None]
    P = Z.shape[0]
    Qc = Q.astype(complex)

    def F(Z: np.ndarray) -> np.ndarray:
        return np.einsum("pi,kij,pj->pk", Z, Qc, Z)

    def dF(Z: np.ndarray) -> np.ndarray:
        return 2 * np.einsum("kij,pj->pki", Qc, Z)

    def G(Z: np.ndarray) -> np.ndarray:
        return Z[:, 1:] ** 2 - Z[:, :1] ** 2

    def dG(Z: np.ndarray) -> np.ndarray:
        out = np.zeros((Z.shape[0], n - 1, n), complex)
        out[:, :, 0] = -2 * Z[:, :1]
        idx = np.arange(n - 1)
        out[:, idx, idx + 1] = 2 * Z[:, 1:]
        return out

    def jac(Z: np.ndarray, s: np.ndarray) -> np.ndarray:
        J = (1 - s)[:, None, None] * gamma * dG(Z) + s[:, None, None] * dF(Z)
        return np.concatenate([J, np.broadcast_to(h, (Z.shape[0], 1, n))], axis=1)

    def value(Z: np.ndarray, s: np.ndarray) -> np.ndarray:
        Hv = (1 - s)[:, None] * gamma * G(Z) + s[:, None] * F(Z)
        return np.concatenate([Hv, (Z @ h - 1)[:, None]], axis=1)

    def tangent(Z: np.ndarray, s: np.ndarray) -> np.ndarray:
        rhs = np.concatenate([-(F(Z) - gamma * G(Z)), np.zeros((Z.shape[0], 1))], axis=1)
        return np.linalg.solve(jac(Z, s), rhs[..., None])[..., 0]

    s = np.zeros(P)
    ds = np.full(P, 0.02)
    ok_run = np.zeros(P, int)
    active = np.ones(P, bool)
    lost = np.zeros(P, bool)
    with np.errstate(all="ignore"):
        for _ in range(20_000):
            idx = np.nonzero(active)[0]
            if idx.size == 0:
                break
            charge(50 * idx.size)
            z, t, d = Z[idx], s[idx], np.minimum(ds[idx], 1 - s[idx])
            try:
                k1 = tangent(z, t)
                k2 = tangent(z + d[:, None] / 2 * k1, t + d / 2)
                k3 = tangent(z + d[:, None] / 2 * k2, t + d / 2)
                k4 = tangent(z + d[:, None] * k3, t + d)
            except np.linalg.LinAlgError:
                k1 = k2 = k3 = k4 = np.full_like(z, np.nan)
            zn = z + d[:, None] / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            tn = t + d
            good = np.all(np.isfinite(zn), axis=1)
            last = np.full(idx.size, np.inf)
            for it in range(3):
                try:
                    dz = np.linalg.solve(jac(zn, tn), value(zn, tn)[..., None])[..., 0]
                except np.linalg.LinAlgError:
                    good[:] = False
                    break
                zn = zn - dz
                size = np.linalg.norm(dz, axis=1) / (1 + np.linalg.norm(zn, axis=1))
                if it == 1:
                    good &= size < 0.1 * last + 1e-14  # contracting
                last = size
            good &= np.all(np.isfinite(zn), axis=1) & (last < 1e-9)
            acc, rej = idx[good], idx[~good]
            Z[acc], s[acc] = zn[good], tn[good]
            ok_run[acc] += 1
            grow = acc[ok_run[acc] >= 3]
            ds[grow] = np.minimum(2 * ds[grow], 0.1)
            ok_run[grow] = 0
            ds[rej] /= 2
            ok_run[rej] = 0
            done = acc[s[acc] >= 1.0]
            active[done] = False
            small = rej[ds[rej] < 1e-13]
            active[small] = False
            lost[small] = True
    Z[lost | active] = np.nan
    return Z


def _polish(Q: np.ndarray, c: np.ndarray, w: np.ndarray, real: bool, steps: int = 6) -> np.ndarray:
    """Newton's method on the chart equations from ``w`` (real arithmetic when ``real``)."""
    dt = float if real else complex
    Qd, cd = Q.astype(dt), np.concatenate([c, np.zeros(4)]).astype(dt)
    w = (w.real if real else w).astype(dt)
    for _ in range(steps):
        Fv = np.append(np.einsum("i,kij,j->k", w, Qd, w), cd @ w - 1)
        J = np.vstack([2 * np.einsum("kij,j->ki", Qd, w), cd])
        try:
            w = w - np.linalg.solve(J, Fv)
        except np.linalg.LinAlgError:
            break
    return w


def _rational_newton(A: list, b: list, k: list, m: list, bits: int = 100) -> list:
    """One Newton step from ``m`` in exact arithmetic (a float inverse of the Jacobian), the
    result rounded to ``2**-bits``: the centre of the box to more than double precision."""
    n = len(m)
    F, J = [], []
    for Ae, be, ke in zip(A, b, k, strict=True):
        Am = [sum((Ae[i][j] * m[j] for j in range(n) if Ae[i][j]), Fraction(0)) for i in range(n)]
        F.append(sum((m[i] * Am[i] for i in range(n)), Fraction(0)) + sum((be[i] * m[i] for i in range(n) if be[i]), Fraction(0)) + ke)
        J.append([2 * Am[j] + be[j] for j in range(n)])
    try:
        Y = np.linalg.inv(np.array([[float(v) for v in row] for row in J]))
    except np.linalg.LinAlgError:
        return m
    # the residual F(m) is tiny and exact: Y F(m) in floats loses nothing that matters
    step = Y @ np.array([float(v) for v in F])
    scale = 2**bits
    return [Fraction(round((mi - Fraction(float(si))) * scale), scale) for mi, si in zip(m, step, strict=True)]


@dataclass(frozen=True)
class CertifiedMode:
    """One assembly mode of a general 6-6, certified (:func:`general_modes`).

    ``position`` and ``rotation`` are SymPy ``Float`` matrices (17 digits) of the certified
    box's centre, within about ``radius`` of the mode (the centre's rotation is exactly
    orthogonal); ``study`` is that centre, exact (``Fraction``), in Study's parameters on
    the chart ``chart . x = 1``, and the box ``study +- radius`` (each coordinate) is proven
    to hold exactly one solution of the exact equations, a real one
    (:meth:`contains` decides whether an exact pose is that one); ``scale`` the power of 2
    the geometry was divided by, ``quadrics`` the equations so scaled.
    """

    position: Any
    rotation: Any
    study: tuple
    radius: Fraction
    chart: tuple
    scale: Fraction
    multiplicity: int = 1
    quadrics: tuple = field(default=(), repr=False, compare=False)

    @property
    def pose(self) -> tuple:
        """``(position, rotation)``, the box's centre as Floats."""
        return (self.position, self.rotation)

    def evalf(self, n: int = 15) -> tuple:
        """``(position, rotation)`` to about ``n`` digits: past 15, the box's centre refined by
        Newton's method in exact arithmetic and a box of radius ``2**-(3.4 n + 20)`` inside the
        certified one proven by Krawczyk's test again (``ValueError`` if it fails)."""
        from sympy import Float, ImmutableMatrix, Rational

        if n <= 15 or not self.quadrics:
            return (self.position.evalf(n), self.rotation.evalf(n))
        A, b, k = _chart_system(list(self.quadrics), self.chart)
        bits = int(3.4 * n) + 40
        m = list(self.study)
        for _ in range(n // 8 + 3):
            m = _rational_newton(A, b, k, m, bits)
        r = Fraction(1, 2 ** (bits - 20))
        inside = all(abs(u - v) + r <= self.radius for u, v in zip(m, self.study, strict=True))
        if not (inside and krawczyk(A, b, k, m, r)):
            raise ValueError(f"evalf: could not certify the mode to {n} digits")
        t, R = pose_from_study(tuple(m))

        def num(v: Fraction) -> Float:
            return Float(Rational(v.numerator, v.denominator), n)

        return (
            ImmutableMatrix([num(v * self.scale) for v in t]),
            ImmutableMatrix([[num(v) for v in row] for row in R]),
        )

    def contains(self, pose: Any) -> bool:
        """Whether the exact rational pose ``(position, rotation)`` is this mode (its Study
        point, on the chart, in the certified box: the mode is the only solution there, so a
        pose inside that closes every leg is it; one outside is not)."""
        from sympy import Matrix

        t = [_frac(v, "pose[0]") for v in Matrix(pose[0])]
        M = Matrix(pose[1])
        if M.shape != (3, 3) or len(t) != 3:
            raise ValueError(f"contains: expected a pose (3-vector, 3 x 3 rotation), got shapes {len(t)}, {M.shape}")
        R = [[_frac(M[i, j], "pose[1]") for j in range(3)] for i in range(3)]
        orthogonal = all(
            sum((R[k][i] * R[k][j] for k in range(3)), Fraction(0)) == (1 if i == j else 0)
            for i in range(3) for j in range(3)
        )
        det = (R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) - R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0])
               + R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]))
        if not (orthogonal and det == 1):
            return False  # no pose
        z = study_from_pose([v / self.scale for v in t], R)
        lam = sum((ci * zi for ci, zi in zip(self.chart, z[:4], strict=True)), Fraction(0))
        if lam == 0:
            return False
        w = [zi / lam for zi in z]
        if not all(abs(wi - mi) <= self.radius for wi, mi in zip(w, self.study, strict=True)):
            return False
        # inside the box: the mode exactly when it closes every leg (the box's only solution)
        return all(
            sum((w[i] * Qk[i][j] * w[j] for i in range(8) for j in range(8) if Qk[i][j]), Fraction(0)) == 0
            for Qk in self.quadrics
        )


def _frac(v: Any, name: str) -> Fraction:
    """An exact rational as a ``Fraction`` (a float as its exact binary value)."""
    from sympy import Float, Rational, sympify

    e = sympify(v, strict=True)
    if isinstance(e, Float):
        e = Rational(e)
    if not e.is_Rational:
        raise ValueError(f"contains: {name}: expected exact rational entries, got {e}")
    return Fraction(int(e.p), int(e.q))


#: rational charts ``c . x = 1`` tried in turn (one that meets every mode is needed)
_CHARTS = (
    (Fraction(1), Fraction(1, 3), Fraction(-1, 5), Fraction(1, 7)),
    (Fraction(1, 2), Fraction(-1, 1), Fraction(2, 3), Fraction(3, 11)),
    (Fraction(-2, 7), Fraction(1, 2), Fraction(1, 1), Fraction(-3, 5)),
)


def _candidates(Qf: np.ndarray, seed: int) -> list:
    """The homotopy's endpoints off the exceptional generator, homogeneous, complex."""
    Z = _track(Qf, np.random.default_rng([36, 66, seed]))
    out = []
    for z in Z:
        if not np.all(np.isfinite(z)):
            continue
        if np.linalg.norm(z[:4]) < 1e-6 * np.linalg.norm(z):
            continue  # on the exceptional generator x = 0: no pose
        out.append(z)
    return out


def _certify(quadrics: list, Qf: np.ndarray, c: tuple, z: np.ndarray) -> tuple | None:
    """``(is_real, centre, radius)`` of a certified box around the solution near ``z`` on the
    chart ``c``, or None."""
    cf = np.array([float(v) for v in c])
    lam = cf @ z[:4]
    if abs(lam) < 1e-8 * np.linalg.norm(z[:4]):
        return None
    w = _polish(Qf, cf, z / lam, real=False)
    if not np.all(np.isfinite(w)):
        return None
    A, b, k = _chart_system(quadrics, c)
    scale = 1 + float(np.max(np.abs(w)))
    if float(np.max(np.abs(w.imag))) < 1e-7 * scale:  # a real mode, if the test agrees
        wr = _polish(Qf, cf, w.real, real=True)
        m = [Fraction(float(v)) for v in wr]
        for _ in range(2):
            m = _rational_newton(A, b, k, m)
        for r in (Fraction(1, 2**40), Fraction(1, 2**30), Fraction(1, 2**20)):
            if krawczyk(A, b, k, m, r * Fraction(scale)):
                return True, tuple(m), r * Fraction(scale)
    A2, b2, k2 = _split(A, b, k)
    m2 = [Fraction(float(v)) for v in w.real] + [Fraction(float(v)) for v in w.imag]
    for _ in range(2):
        m2 = _rational_newton(A2, b2, k2, m2)
    for r in (Fraction(1, 2**40), Fraction(1, 2**30), Fraction(1, 2**20)):
        rr = r * Fraction(scale)
        if any(abs(v) > rr for v in m2[8:]) and krawczyk(A2, b2, k2, m2, rr):
            return False, tuple(m2), rr
    return None


def _disjoint(p: tuple, q: tuple) -> bool:
    """Whether two certified boxes (``(centre, radius)`` in ``C^8``: 16 real coordinates, a
    real box's imaginary part ``[0, 0]``) are disjoint."""
    (mp, rp), (mq, rq) = p, q
    return any(abs(u - v) > rp_ + rq_ for u, v, rp_, rq_ in zip(mp, mq, rp, rq, strict=True))


def general_modes(a: tuple, b: tuple, l2: tuple, attempts: int = 3) -> tuple[list, int, bool]:
    """The real assembly modes of a general 6-6 (exact rational input), certified:
    ``(modes, certified, complete)`` with ``modes`` the :class:`CertifiedMode` of every real
    mode found, ``certified`` the number of distinct complex modes proven, ``complete``
    whether that number reaches :data:`MAX_MODES` (then no mode is missing).

    Up to ``attempts`` homotopies (new random constants each) are run until 40 are proven.
    """
    from sympy import Float, ImmutableMatrix

    # scale the geometry to size about 1 (a power of 2, exact): the floats are then well scaled
    size = max([abs(float(v)) for p in (*a, *b) for v in p] + [abs(float(q)) ** 0.5 for q in l2] + [1e-300])
    e = int(np.floor(np.log2(float(size))))
    sc = Fraction(2) ** e if e >= 0 else Fraction(1, 2 ** (-e))
    fa = [tuple(_frac(v, "base_points") / sc for v in p) for p in a]
    fb = [tuple(_frac(v, "platform_points") / sc for v in p) for p in b]
    fl = [_frac(q, "lengths") / sc**2 for q in l2]
    quadrics = study_quadrics(tuple(fa), tuple(fb), tuple(fl))
    Qf = np.array([[[float(v) for v in row] for row in Qk] for Qk in quadrics])
    found: list = []  # (is_real, centre, radius, chart)
    boxes: list = []  # (centre in C^8 as 16 reals, radii)
    chart = _CHARTS[0]
    for attempt in range(attempts):
        cands = _candidates(Qf, attempt)
        if not cands:
            continue
        # a chart that meets every candidate (|c . x| not small)
        for c in _CHARTS:
            cf = np.array([float(v) for v in c])
            if all(abs(cf @ z[:4]) > 1e-3 * np.linalg.norm(z[:4]) for z in cands):
                if c != chart and found:
                    continue  # keep the chart of the modes already proven
                chart = c
                break
        for z in cands:
            cert = _certify(quadrics, Qf, chart, z)
            if cert is None:
                continue
            is_real, m, r = cert
            if is_real:
                box = (tuple(m) + (Fraction(0),) * 8, (r,) * 8 + (Fraction(0),) * 8)
            else:
                box = (tuple(m), (r,) * 16)
            if all(_disjoint(box, other) for other in boxes):
                boxes.append(box)
                found.append((is_real, m, r))
            charge(20_000)
        if len(found) >= MAX_MODES:
            break
    modes = []
    for is_real, m, r in found:
        if not is_real:
            continue
        t, R = pose_from_study(m)
        position = ImmutableMatrix([Float(float(v * sc), 17) for v in t])
        rotation = ImmutableMatrix([[Float(float(v), 17) for v in row] for row in R])
        modes.append(CertifiedMode(position, rotation, m, r, chart, sc, 1, tuple(quadrics)))
    modes.sort(key=lambda md: tuple(float(v) for v in md.position))
    return modes, len(found), len(found) >= MAX_MODES
