r"""The dynamics of a serial chain by polynomial arithmetic: the fast path of :mod:`.dynamics`.

Explanation
===========

The mass matrix (composite rigid bodies) and the inverse dynamics (Newton–Euler) of
:mod:`screwsym.motion.dynamics`, computed with the same formulas in the ring of the
product of exponentials (:mod:`screwsym.motion._poe`): ``cos(q_i)`` and ``sin(q_i)`` of
each revolute joint are generators reduced modulo ``cos^2 + sin^2 = 1``, the square
roots of primes in the geometry (``sqrt 2``, ``sqrt 3`` at 15 degrees) generators
reduced modulo ``r^2 = p``, and the inertias, the joint rates and the geometry's
symbols are generators too.  Every intermediate twist, wrench and inertia is a vector
of polynomials in their normal form (no expression tree is built or tidied on the
way), and only the final entries are written back as expressions, with the angle-sum
formulas gathered and the terms nested by the joints (``_poe``'s writer).

Every step is an identity of that ring (the Pythagorean relation and ``r^2 = p`` are
true for the values they stand for), so the results equal those of the recursions of
:mod:`.dynamics` on expressions.  A chain outside ``_poe``'s class (helical joints,
non-unit axes, joint values that are neither distinct symbols nor numbers whose cosine
and sine are sums of products of square roots, a joint variable in the inertias) gives
None here and takes that general path.

References
==========

R. Featherstone, *Rigid Body Dynamics Algorithms*, Springer 2008, Section 6.2.
F. C. Park, J. E. Bobrow, S. R. Ploen, "A Lie group formulation of robot dynamics", 1995.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from sympy import Dummy, Expr, Float, ImmutableMatrix, S, Symbol, cos, sin

from ..algebra.budget import charge
from ..algebra.numberfield import surd_normal
from . import _poe

__all__: list[str] = []

#: units of the budget per product of two terms: the ring is over the rationals here (a fraction
#: normalised per product: 2 to 5 microseconds, measured on the mass matrix and Newton–Euler), over the integers in ``_poe``'s products
QQ_UNITS = 5


class _Ring:
    """Vector arithmetic of 3- and 6-vectors over one chain's ring, in the normal form."""

    def __init__(self, twists: Sequence[Any], home: Any, q: tuple, extra: list,
                 values: dict | None = None) -> None:
        """``values``: joint -> ``(q, cos q, sin q)`` for the joints given as numbers (``q`` holds
        a stand-in symbol there); their motions are built from these numbers."""
        self.values = values or {}
        extra = extra + [x for v in self.values.values() for x in v]
        self.engine = engine = _poe._Engine(list(twists), home, q, extra=extra, groups=False)
        # the joints' own circles cos(q_i)^2 + sin(q_i)^2 = 1, reduced with the geometry's
        index = {s: i for i, s in enumerate(engine.symbols)}
        engine.pairs = engine.pairs + [(index[engine.cos_gen[a]], index[engine.sin_gen[a]])
                                       for a in engine.cos_gen]
        self.R = engine.R
        self.red = engine._reduce
        self.el = engine._el

    def mv(self, M: list, v: list) -> list:
        charge(QQ_UNITS * sum(len(M[i][j]) * len(v[j]) for i in range(3) for j in range(3)))
        return [self.red(M[i][0] * v[0] + M[i][1] * v[1] + M[i][2] * v[2]) for i in range(3)]

    def cross(self, a: list, b: list) -> list:
        charge(QQ_UNITS * 2 * (len(a[0]) + len(a[1]) + len(a[2])) * (len(b[0]) + len(b[1]) + len(b[2])) // 3)
        return [self.red(x) for x in
                (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])]

    def dot(self, a: list, b: list) -> Any:
        charge(QQ_UNITS * sum(len(x) * len(y) for x, y in zip(a, b, strict=True)))
        return self.red(sum((x * y for x, y in zip(a, b, strict=True)), self.R.zero))

    def motions(self) -> list[tuple[list, list]]:
        """``E_i = exp6($_i, q_i) = (R_i, p_i)`` of each joint, as ring elements."""
        e = self.engine
        out = []
        one, zero = self.R.one, self.R.zero
        for i in range(e.n):
            w, v = e.twists[i]
            given = self.values.get(i)
            if e.kinds[i] == "P":
                qi = self.el(given[0]) if given else e.gen_of[e.q[i]]
                out.append((e._rot(w, None, 1), [x * qi for x in v]))
                continue
            if given:  # R = I + s K + (1 - c) K^2 at the numbers cos q, sin q
                c, s_ = self.el(given[1]), self.el(given[2])
                Kw = [[zero, -w[2], w[1]], [w[2], zero, -w[0]], [-w[1], w[0], zero]]
                K2 = [[self.red(sum((Kw[a][b] * Kw[b][d] for b in range(3)), zero)) for d in range(3)]
                      for a in range(3)]
                R = [[self.red((one if a == d else zero) + s_ * Kw[a][d] + (one - c) * K2[a][d]) for d in range(3)]
                     for a in range(3)]
            else:
                R = e._rot(w, e.angle_of[i], 1)
            r = self.cross(w, v)  # the axis point nearest the origin
            Rr = self.mv(R, r)
            out.append((R, [r[k] - Rr[k] for k in range(3)]))
        return out

    @staticmethod
    def transposed(R: list) -> list:
        return [[R[j][i] for j in range(3)] for i in range(3)]

    def carry(self, E: tuple, s: list) -> list:
        """``Ad(E) s = (R a; R b + p x R a)`` for ``s = (a; b)`` (a twist or a wrench, ray order)."""
        R, p = E
        Ra = self.mv(R, s[:3])
        Rb = self.mv(R, s[3:])
        pRa = self.cross(p, Ra)
        return Ra + [Rb[k] + pRa[k] for k in range(3)]

    def back(self, E: tuple, s: list) -> list:
        """``Ad(E^-1) s = (R^T a; R^T (b - p x a))``."""
        R, p = E
        Rt = self.transposed(R)
        pa = self.cross(p, s[:3])
        return self.mv(Rt, s[:3]) + self.mv(Rt, [s[3 + k] - pa[k] for k in range(3)])

    def momentum(self, P: tuple, s: list) -> list:
        """``M s`` of the ray-order inertia ``[[-[h]x, m 1], [I_O, [h]x]]`` (``spatial_matrix``)."""
        m, h, I_O = P
        w, v = s[:3], s[3:]
        hw = self.cross(h, w)
        hv = self.cross(h, v)
        Iw = self.mv(I_O, w)
        return [self.red(m * v[k] - hw[k]) for k in range(3)] + [Iw[k] + hv[k] for k in range(3)]

    def moved(self, P: tuple, E: tuple) -> tuple:
        """The parameters carried by ``E = (R, p)`` (``dynamics._moved_params``): ``h' = R h + m p``,
        ``I_O' = R I_O R^T - [R h]x [p]x - [p]x [R h]x - m [p]x^2``."""
        m, h, I_O = P
        R, p = E
        Rh = self.mv(R, h)
        Rt = self.transposed(R)
        RI = [self.mv(I_O, [Rt[0][j], Rt[1][j], Rt[2][j]]) for j in range(3)]  # columns of I_O R^T
        nR, nRI = [sum(len(x) for x in row) for row in R], [sum(len(x) for x in col) for col in RI]
        nh, np_ = sum(len(x) for x in Rh), sum(len(x) for x in p)
        charge(QQ_UNITS * (sum(a * b for a in nR for b in nRI) + 3 * (2 * nh + len(m) * np_) * np_))
        RIRt = [[self.red(R[i][0] * RI[j][0] + R[i][1] * RI[j][1] + R[i][2] * RI[j][2]) for j in range(3)]
                for i in range(3)]
        # -[a]x[p]x - [p]x[a]x - m[p]x^2 = -(a p^T + p a^T) + 2 (a.p) 1 - m (p p^T - (p.p) 1)
        ap, pp = self.dot(Rh, p), self.dot(p, p)
        out = [[self.red(RIRt[i][j] - Rh[i] * p[j] - p[i] * Rh[j] - m * p[i] * p[j]
                         + ((2 * ap + m * pp) if i == j else 0)) for j in range(3)] for i in range(3)]
        return m, [self.red(Rh[k] + m * p[k]) for k in range(3)], out

    def bracket(self, a: list, b: list) -> list:
        """``[a, b] = (wa x wb; wa x vb - wb x va)`` (``formulas.bracket``)."""
        top = self.cross(a[:3], b[:3])
        x, y = self.cross(a[:3], b[3:]), self.cross(b[:3], a[3:])
        return top + [x[k] - y[k] for k in range(3)]

    @staticmethod
    def reciprocal(x: list, y: list) -> Any:
        return x[0] * y[3] + x[1] * y[4] + x[2] * y[5] + x[3] * y[0] + x[4] * y[1] + x[5] * y[2]

    def params(self, P: Any) -> tuple:
        m, h, I_O = P
        return self.el(m), [self.el(x) for x in h], [[self.el(I_O[i, j]) for j in range(3)] for i in range(3)]


def _params_exprs(params: Sequence[Any]) -> list:
    return [x for m, h, I_O in params for x in (m, *h, *I_O)]


def _ring(twists: Sequence[Any], home: Any, q: Sequence[Expr], extra: list) -> _Ring | None:
    """The ring of the chain, or None.  Joint values are distinct symbols, or numbers whose
    cosine and sine are sums of products of roots of rationals (``pi/4``, ``pi/12``, 0:
    :func:`screwsym.algebra.numberfield.surd_normal`); a prismatic joint's number is any
    such number."""
    values: dict = {}
    stand_in = []
    for i, x in enumerate(q):
        if isinstance(x, Symbol):
            stand_in.append(x)
            continue
        if not x.is_number or x.has(Float):
            return None
        if twists[i].omega.is_zero_matrix:  # a prismatic joint's length
            values[i] = (x, S.Zero, S.Zero)
        else:
            c, s = surd_normal(cos(x)), surd_normal(sin(x))
            if c is None or s is None:
                return None
            values[i] = (x, c, s)
        stand_in.append(Dummy(f"q{i}"))
    qs = tuple(stand_in)
    if len(set(qs)) != len(qs):
        return None
    try:
        return _Ring(twists, home, qs, extra, values)
    except _poe._NotPolynomial:
        return None


def ring_mass_matrix(twists: Sequence[Any], home: Any, params: Sequence[Any],
                     q: Sequence[Expr]) -> ImmutableMatrix | None:
    """``H(q)`` by composite rigid bodies in the ring (``dynamics.mass_matrix``), or None."""
    K = _ring(twists, home, q, _params_exprs(params))
    if K is None:
        return None
    e = K.engine
    n = e.n
    E = K.motions()
    xi = [w + v for w, v in e.twists]
    H: list = [[None] * n for _ in range(n)]
    composite = None
    for k in reversed(range(n)):
        P = K.params(params[k])
        if composite is not None:  # links k+1 .. n, carried into frame {k}
            Q = K.moved(composite, E[k + 1])
            P = (P[0] + Q[0], [P[1][i] + Q[1][i] for i in range(3)],
                 [[P[2][i][j] + Q[2][i][j] for j in range(3)] for i in range(3)])
        composite = P
        W = K.momentum(P, xi[k])
        for i in reversed(range(k + 1)):
            if i < k:
                W = K.carry(E[i + 1], W)
            H[i][k] = H[k][i] = K.red(K.reciprocal(xi[i], W))
    entries = e.expressions([H[i][j] for i in range(n) for j in range(i, n)])
    out: list = [[None] * n for _ in range(n)]
    it = iter(entries)
    for i in range(n):
        for j in range(i, n):
            out[i][j] = out[j][i] = next(it)
    return ImmutableMatrix(out)


def ring_rnea(twists: Sequence[Any], home: Any, params: Sequence[Any], q: Sequence[Expr],
              qd: Sequence[Expr], qdd: Sequence[Expr], gravity: Any) -> ImmutableMatrix | None:
    """``tau(q, qd, qdd)`` by Newton–Euler in the ring (``dynamics._rnea``), or None."""
    K = _ring(twists, home, q, _params_exprs(params) + list(qd) + list(qdd) + list(gravity))
    if K is None:
        return None
    e = K.engine
    n = e.n
    E = K.motions()
    xi = [w + v for w, v in e.twists]
    qd_r = [K.el(x) for x in qd]
    qdd_r = [K.el(x) for x in qdd]
    zero = K.R.zero
    V = [zero] * 6
    A = [zero] * 3 + [-K.el(x) for x in gravity]
    Vs, As = [], []
    for i in range(n):
        V = [K.red(x + s * qd_r[i]) for x, s in zip(K.back(E[i], V), xi[i], strict=True)]
        br = K.bracket(V, xi[i])
        A = [K.red(x + s * qdd_r[i] + b * qd_r[i])
             for x, s, b in zip(K.back(E[i], A), xi[i], br, strict=True)]
        Vs.append(V)
        As.append(A)
    F = [zero] * 6
    tau: list = [zero] * n
    for i in reversed(range(n)):
        P = K.params(params[i])
        if i + 1 < n:
            F = K.carry(E[i + 1], F)
        MA = K.momentum(P, As[i])
        MV = K.momentum(P, Vs[i])
        VMV = K.bracket(Vs[i], MV)
        F = [K.red(F[k] + MA[k] + VMV[k]) for k in range(6)]
        tau[i] = K.red(K.reciprocal(xi[i], F))
    return ImmutableMatrix(e.expressions(tau))
