r"""The closed forms of a serial chain by polynomial arithmetic: the fast path of :class:`Chain`.

Explanation
===========

A chain of revolute joints (unit ``omega``, ``omega . v_O = 0``) and prismatic
joints (``omega = 0``) with distinct symbolic joint variables has a product of
exponentials whose entries are polynomials in the sines and cosines of the joint
angles, the prismatic joints' lengths and the geometry.  This module computes
the product with exactly that structure, in one of SymPy's sparse polynomial
rings, instead of as expression trees tidied after every factor:

1. **Sums of angles from the structure.**  Consecutive revolute joints about
   parallel axes (``omega_{j+1} = +-omega_j``) form a group whose product is a
   turn by the cumulative angle ``phi_k = q_g +- ... +- q_k`` about the common
   direction: ``exp6($_g, q_g) ... exp6($_k, q_k) = (R(phi_k), sum_j (R(phi_{j-1}) -
   R(phi_j)) r_j)`` for points ``r_j`` of the axes.  ``R(phi) = I + sin(phi) K +
   (1 - cos(phi)) K^2`` (Rodrigues) with ``cos(phi)`` and ``sin(phi)`` as ring
   generators: no sum-of-angles search is needed for these.
2. **Products of two angles' sines and cosines gathered** where the pattern of
   the angle-sum formulas occurs with equal coefficients (``a cos A cos B - a sin A
   sin B -> a cos(A + B)``, the four formulas and their differences), and
   ``sin(A)**2 -> 1 - cos(A)**2`` where it shortens: read off the terms of the
   polynomial, several times cheaper than SymPy's ``TR10i`` on the expression.
3. **The form of the product kept.**  Each entry is written back nested by the
   joints, the last joint's factors outermost (``T_k = T_{k-1} exp6($_k, q_k)``), with
   the content and the common monomial of each level pulled out, or flat where
   that is smaller (by ``count_ops``).

**Sines and cosines in the geometry** (symbolic Denavit-Hartenberg twist angles
``alpha_i``): each ``sin`` or ``cos`` of ``sum k_i x_i + c`` (integers ``k_i``, symbols
``x_i``) is expanded by the angle-sum formulas into ``cos(x_i), sin(x_i)``, which are
ring generators on their circles: polynomials are kept in the normal form modulo
``cos(x)^2 + sin(x)^2 - 1`` (``sin(x)^k``, ``k >= 2``, made ``sin(x)^(k mod 2) (1 -
cos(x)^2)^(k // 2)``; the relations' leading terms are coprime, so this is a normal
form, and it is zero exactly when the polynomial vanishes on the circles).  A unit
axis such as ``(0, -sin(alpha), cos(alpha))`` is decided so (``omega . omega - 1`` and
``omega . v_O`` reduce to zero).  The product of exponentials itself is then walked
through the joints' own frames, ``exp6($_k, q_k) = F_k Z(q_k) F_k^-1``, so that
``T(q) = F_1 Z(q_1) L_1 Z(q_2) ... Z(q_n) L_n`` with the constant links ``L_k = F_k^-1
F_(k+1)``: the rows of the table, short in ``cos(alpha_k), sin(alpha_k)``, where the
joint twists of a symbolic table are long polynomials in them (Lynch & Park 2017,
Appendix C).  The frames are built from the twists (``z`` the unit axis, ``x`` the
previous frame's ``x`` or ``y`` or a base unit vector orthogonal to it, the origin
the foot of the perpendicular from the previous one); a chain without them is
multiplied as above.  Chains without sines or cosines of symbols in the geometry
are unchanged by this.

Every step is an exact identity (ring arithmetic over the rationals, the
Pythagorean identity, the angle-sum formulas), so the results equal the
product of the exponentials.  Chains outside this class (helical joints,
non-unit axes, numeric or repeated joint values) take the general path.

References
==========

R. W. Brockett, "Robotic manipulators and the product of exponentials
formula", 1984.  Lynch & Park, *Modern Robotics*, 2017, Sections 4.1, 5.1.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from math import gcd
from typing import Any, cast

from sympy import (
    Add,
    Dummy,
    Expr,
    ImmutableMatrix,
    Mul,
    Pow,
    S,
    Symbol,
    cos,
    expand,
    expand_trig,
    sin,
)
from sympy.core.sorting import default_sort_key
from sympy.polys.domains import QQ, ZZ
from sympy.polys.polyerrors import CoercionFailed, GeneratorsError, PolynomialError
from sympy.polys.rings import ring

from ..algebra.budget import bounded as _budget_bounded
from ..algebra.budget import charge
from ..algebra.circle import reduce_powers
from ..algebra.numberfield import reduce_surds, surd_split
from ..core.checks import check_count
from ._poe_writer import _canonical, _Writer

__all__: list[str] = []

#: units charged per step of the general (expression) paths of the kinematics and dynamics, a
#: tidied product or recursion step: their cost is bounded by the CPU time checked at each charge
STEP_UNITS = 100

#: units per term of a polynomial brought to the normal form modulo the circles and the square
#: roots (``_Engine._reduce``: a few microseconds a term, measured on a 20-joint URDF at 15 degrees)
REDUCE_UNITS = 4


#: the error past a kinematics' or dynamics' budget (:func:`bounded`)
_MESSAGE = ("{name}: the exact arithmetic needs more than budget={budget} units (a long chain, or "
            "symbolic joint values with angles that are no multiple of pi/12); pass a larger "
            "budget, or use Chain.kinematics_program (Chain.dynamics_program for the dynamics) "
            "for a straight-line program that grows linearly")


@contextmanager
def bounded(budget: Any, name: str) -> Iterator[None]:
    """The kinematics' and dynamics' exact arithmetic within ``budget`` units (about a microsecond
    each: a product of polynomials of ``a`` and ``b`` terms is ``a b`` units, a term written back
    one; the CPU time is bounded too, :mod:`screwsym.algebra.budget`).  Inside another budget (one
    public method calling another) the outer one holds.  Past it, ``ValueError`` naming ``name``.

    >>> with bounded(10, "forward"):
    ...     charge(11)
    Traceback (most recent call last):
    ...
    ValueError: forward: the exact arithmetic needs more than budget=10 units (a long chain, or symbolic joint values with angles that are no multiple of pi/12); pass a larger budget, or use Chain.kinematics_program (Chain.dynamics_program for the dynamics) for a straight-line program that grows linearly
    """
    with _budget_bounded(check_count(budget, "budget"), name, _MESSAGE):
        yield


class _NotPolynomial(Exception):
    """The chain is outside the class this module handles: take the general path."""


def _joint_kind(omega: Any, v: Any) -> str | None:
    """``"R"`` for a unit revolute twist, ``"P"`` for a prismatic one, None otherwise."""
    if all(e == 0 for e in omega):
        return "P" if any(e != 0 for e in v) else None
    if expand(omega.dot(omega)) == 1 and expand(omega.dot(v)) == 0:
        return "R"
    return None


class _Engine:
    """One chain's ring: the geometry's symbols, the prismatic lengths, the angles' sines and cosines."""

    def __init__(self, twists: list, home: Any, q: tuple, sign: int = 1, extra: Sequence[Expr] = (),
                 groups: bool = True) -> None:
        """``extra``: more expressions whose symbols and roots join the ring (the dynamics' inertias
        and joint rates); ``groups=False``: a generator pair per joint, no cumulative angles."""
        self.n = len(twists)
        self.q = q
        self.sign = sign
        # sines and cosines of the geometry (symbolic DH twist angles): polynomials in the
        # sines and cosines of their arguments' symbols, generators on the circle
        forms, self.bases, self.circle = _circle_forms([t.matrix for t in twists] + [home.matrix])
        twist_parts = [(t.omega.xreplace(forms), t.v_O.xreplace(forms)) for t in twists]
        home_parts = home.R.xreplace(forms), home.p.xreplace(forms)
        kinds = [_joint_kind(t.omega, t.v_O) for t in twists]
        # a revolute joint whose unit axis needs sin^2 + cos^2 = 1 of the geometry: decided in the ring
        pending = [i for i, k in enumerate(kinds) if k is None and self.circle
                   and not all(e == 0 for e in twists[i].omega)]
        for i in pending:
            kinds[i] = "R"
        if None in kinds:
            raise _NotPolynomial("a joint is neither a unit revolute nor a prismatic twist")
        self.kinds = kinds
        # groups of consecutive revolute joints about parallel axes: joint -> (group start, sign)
        self.group: list[tuple[int, int]] = []
        for i, t in enumerate(twists):
            if groups and i and kinds[i] == "R" and kinds[i - 1] == "R" and not self.bases:
                g, _ = self.group[i - 1]
                w0 = twists[g].omega
                if t.omega == w0:
                    self.group.append((g, 1))
                    continue
                if t.omega == -w0:
                    self.group.append((g, -1))
                    continue
            self.group.append((i, 1))
        # the angles: cumulative sums over each group, as integer coefficient tuples over q
        # (then zeros over the geometry's circle bases, which the writer's gathering may fill)
        m = len(self.bases)
        self.angle_of: list[tuple[int, ...] | None] = []
        for i in range(self.n):
            if kinds[i] != "R":
                self.angle_of.append(None)
                continue
            g, s = self.group[i]
            before = self.angle_of[i - 1] if g != i else None
            coeffs = list(before) if before is not None else [0] * (self.n + m)
            coeffs[i] = s * sign
            self.angle_of.append(tuple(coeffs))
        angles = sorted({_canonical(a)[0] for a in self.angle_of if a is not None})
        extra = [x.xreplace(forms) for x in extra]
        if set(q) & set().union(*(t.matrix.free_symbols for t in twists), home.matrix.free_symbols,
                                *(x.free_symbols for x in extra)):
            raise _NotPolynomial("a joint variable occurs in the geometry")
        # roots and functions of the geometry (sqrt(2)/2 in a rotation) become generators
        self.frozen: dict = {}
        exprs = [e for w, v in twist_parts for e in (*w, *v)] + [*home_parts[0], *home_parts[1]] + extra
        exprs = [_frozen(e, self.frozen) for e in exprs]
        trig_gens = {d for pair in self.circle.values() for d in pair}
        geometry = set().union(*(e.free_symbols for e in exprs)) - set(self.frozen.values()) - trig_gens
        self.geometry = sorted(geometry, key=default_sort_key) + list(self.frozen.values())
        self.thaw = {d: f for f, d in self.frozen.items()}
        # ring generators: geometry symbols, prismatic lengths, cos/sin per geometry base, per angle
        self.cos_gen: dict[tuple, Any] = {}
        self.sin_gen: dict[tuple, Any] = {}
        gens: list = list(self.geometry)
        prismatic = [q[i] for i in range(self.n) if kinds[i] == "P"]
        gens += prismatic
        for b in self.bases:
            gens += list(self.circle[b])
        for a in angles:
            c, s_ = Dummy("c"), Dummy("s")
            self.cos_gen[a], self.sin_gen[a] = c, s_
            gens += [c, s_]
        self.R, *self.gens = ring(gens, QQ)
        self.RZ = self.R.clone(domain=ZZ)  # the same generators over the integers (_sum_products)
        self.gen_of = dict(zip(gens, self.gens, strict=True))
        self.symbols = gens
        # the circle relations c^2 + s^2 = 1, as generator indices (cos, sin)
        self.pairs = [(gens.index(self.circle[b][0]), gens.index(self.circle[b][1])) for b in self.bases]
        # the square roots of primes in the geometry (15 degrees: sqrt 2, sqrt 3), r^2 = p
        self.surds = [(gens.index(d), int(f.base)) for f, d in self.frozen.items()
                      if f.is_Pow and f.exp == S.Half and f.base.is_Integer and f.base.is_prime]
        self.level: dict[int, int] = {}  # generator -> its level in the written form (by _walk)
        self._prefixes: list | None = None
        try:
            self.twists = [(self._vec(w), self._vec(v)) for w, v in twist_parts]
            self.home = self._mat(home_parts[0]), self._vec(home_parts[1])
        except (CoercionFailed, GeneratorsError, PolynomialError, ValueError) as exc:
            raise _NotPolynomial(str(exc)) from None
        for i in pending:
            w, v = self.twists[i]
            if self._reduce(_dot(w, w) - 1) or self._reduce(_dot(w, v)):
                raise _NotPolynomial("a joint is neither a unit revolute nor a prismatic twist")

    # --- conversions
    def _el(self, e: Expr) -> Any:
        e = _frozen(e, self.frozen)
        return self._reduce(self.R.from_expr(e) if e.free_symbols else self.R(QQ.from_sympy(e)))

    def _reduce(self, P: Any) -> Any:
        """``P`` modulo ``c^2 + s^2 - 1`` of each geometry base: every ``s^k`` with ``k >= 2`` made
        ``s^(k mod 2) (1 - c^2)^(k // 2)`` (:func:`screwsym.algebra.circle.reduce_powers`), and
        modulo ``r^2 - p`` for each square root of a prime ``p`` in the geometry
        (:func:`screwsym.algebra.numberfield.reduce_surds`): the normal form over
        ``Q(sqrt 2, sqrt 3, ...)``, so that entries at 15 degrees do not grow."""
        charge(len(P) * (REDUCE_UNITS if self.surds or self.pairs else 1))
        if self.surds:
            P = reduce_surds(P, self.surds)
        return reduce_powers(P, self.pairs) if self.pairs else P

    def _vec(self, v: Any) -> list:
        return [self._el(e) for e in v]

    def _mat(self, m: Any) -> list:
        return [[self._el(m[i, j]) for j in range(3)] for i in range(3)]

    # --- 3-vector and 3x3 matrix arithmetic on ring elements (reduced on the geometry's circles)
    # The products below run over the integers: each factor times the least common multiple of
    # its coefficients' denominators, the products and their sum in Z[x] (Python integers, no
    # gcd per coefficient), then one division per term of the sum.  Over Q, SymPy's product
    # normalises a fraction for every pair of terms; the result is the same polynomial.
    def _integral(self, a: Any) -> tuple[int, Any]:
        """``(d, d a)`` with ``d a`` in ``Z[x]`` (``d`` the lcm of the denominators)."""
        d = 1
        for c in a.values():
            den = c.denominator
            if den != 1:
                d = d * den // gcd(d, den)
        return d, self.RZ.dtype({m: c.numerator * (d // c.denominator) for m, c in a.items()})

    def _sum_products(self, pairs: list) -> Any:
        """``sum a b`` over the pairs of integral forms ``((d_a, A), (d_b, B))``, reduced."""
        charge(sum(len(A) * len(B) for (_, A), (_, B) in pairs))
        parts = [(da * db, A * B) for (da, A), (db, B) in pairs if A and B]
        if not parts:
            return self.R.zero
        L = 1
        for d, _ in parts:
            L = L * d // gcd(L, d)
        total = parts[0][1] * (L // parts[0][0])
        for d, P in parts[1:]:
            total += P * (L // d)
        QQ_ = QQ
        return self._reduce(self.R.dtype({m: QQ_(c, L) for m, c in total.items()}))

    def _mv(self, M: list, v: list) -> list:
        Mi = [[self._integral(x) for x in row] for row in M]
        vi = [self._integral(x) for x in v]
        return [self._sum_products(list(zip(Mi[i], vi, strict=True))) for i in range(3)]

    def _mm(self, A: list, B: list) -> list:
        Ai = [[self._integral(x) for x in row] for row in A]
        Bi = [[self._integral(x) for x in row] for row in B]
        return [[self._sum_products([(Ai[i][k], Bi[k][j]) for k in range(3)]) for j in range(3)]
                for i in range(3)]

    def _cross(self, a: list, b: list) -> list:
        ai = [self._integral(x) for x in a]
        bi = [self._integral(x) for x in b]
        neg = [(d, -P) for d, P in bi]
        return [self._sum_products([(ai[1], bi[2]), (ai[2], neg[1])]),
                self._sum_products([(ai[2], bi[0]), (ai[0], neg[2])]),
                self._sum_products([(ai[0], bi[1]), (ai[1], neg[0])])]

    def _rot(self, w: list, angle: tuple | None, sgn: int) -> list:
        """``R = I + sin K + (1 - cos) K^2`` about the unit ``w`` by the angle (``sgn`` its sign)."""
        one, zero = self.R.one, self.R.zero
        if angle is None:
            return [[one, zero, zero], [zero, one, zero], [zero, zero, one]]
        c, s = self.gen_of[self.cos_gen[angle]], self.gen_of[self.sin_gen[angle]] * sgn
        K = [[zero, -w[2], w[1]], [w[2], zero, -w[0]], [-w[1], w[0], zero]]
        K2 = self._mm(K, K)
        return [[(one if i == j else zero) + s * K[i][j] + (one - c) * K2[i][j] for j in range(3)]
                for i in range(3)]

    def prefixes(self) -> list[tuple[list, list]]:
        """``T_0 = I, T_1, ..., T_n``: the products of the first ``k`` exponentials (computed once)."""
        if self._prefixes is None:
            self._prefixes = self._products()
        return self._prefixes

    def _products(self) -> list[tuple[list, list]]:
        one, zero = self.R.one, self.R.zero
        eye = [[one, zero, zero], [zero, one, zero], [zero, zero, one]]
        out = [(eye, [zero, zero, zero])]
        base = out[0]  # the product of the joints before the current group
        for i in range(self.n):
            w, v = self.twists[i]
            g, _ = self.group[i]
            if g == i:
                base = out[i]
            if self.kinds[i] == "P":
                q = self.gen_of[self.q[i]] * self.sign
                R0, p0 = base
                out.append((R0, [p0[k] + q * x for k, x in enumerate(self._mv(R0, v))]))
                continue
            # the group g..i: R(phi_i), translation sum_j (R(phi_{j-1}) - R(phi_j)) r_j
            wg = self.twists[g][0]
            prev = self._rot(wg, None, 1)
            p = [zero, zero, zero]
            for j in range(g, i + 1):
                angle, sgn = _canonical(self.angle_of[j])
                Rj = self._rot(wg, angle, sgn)
                r = self._cross(*self.twists[j])  # omega x v_O: the axis point nearest the origin
                d = [prev[k][0] - Rj[k][0] for k in range(3)], [prev[k][1] - Rj[k][1] for k in range(3)], \
                    [prev[k][2] - Rj[k][2] for k in range(3)]
                for k in range(3):
                    p[k] = self._reduce(p[k] + d[0][k] * r[0] + d[1][k] * r[1] + d[2][k] * r[2])
                prev = Rj
            R0, p0 = base
            out.append((self._mm(R0, prev), [p0[k] + x for k, x in enumerate(self._mv(R0, p))]))
        return out

    def forward(self) -> tuple[list, list]:
        walk = self._walk()
        if walk is not None:
            return walk[1]
        R, p = self.prefixes()[-1]
        HR, Hp = self.home
        return self._mm(R, HR), [p[k] + x for k, x in enumerate(self._mv(R, Hp))]

    def columns(self) -> list[list]:
        """The space Jacobian's columns ``Ad(T_{i-1}) $_i`` as ring elements (omega; v)."""
        walk = self._walk()
        if walk is not None:
            cols = []
            for i, (R, p) in enumerate(walk[0]):
                z = [R[0][2], R[1][2], R[2][2]]
                zero = self.R.zero
                cols.append(z + self._cross(p, z) if self.kinds[i] == "R" else [zero, zero, zero] + z)
            return cols
        pre = self.prefixes()
        cols = []
        for i in range(self.n):
            R, p = pre[i]
            w, v = self.twists[i]
            Rw = self._mv(R, w)
            Rv = self._mv(R, v)
            cols.append(Rw + [Rv[k] + x for k, x in enumerate(self._cross(p, Rw))])
        return cols

    # --- the joints' own frames: the product as Denavit and Hartenberg wrote it
    def _frames(self) -> list[tuple[list, list]] | None:
        """A frame ``F_k = (R_k, o_k)`` per joint with ``$_k = Ad(F_k) $_z``, or None.

        ``R_k = [x, z x x, z]`` for the joint's unit direction ``z`` and the first of the
        previous frame's ``x``, ``y``, the base's unit vectors and the previous ``z`` that is orthogonal to ``z``
        (decided modulo the circles); ``o_k`` is the foot of the perpendicular from the
        previous origin onto the axis (a revolute joint) or the previous origin (prismatic).
        """
        one, zero = self.R.one, self.R.zero
        units = [[one, zero, zero], [zero, one, zero], [zero, zero, one]]
        frames: list = []
        o_prev = [zero, zero, zero]
        for k, (w, v) in enumerate(self.twists):
            z = w if self.kinds[k] == "R" else v
            if self._reduce(_dot(z, z) - 1):
                return None
            candidates = list(units)
            if frames:
                Rp = frames[-1][0]
                candidates[:0] = [[Rp[i][0] for i in range(3)], [Rp[i][1] for i in range(3)]]
                # last, its z: an axis at right angles to the previous one's, turned by a
                # constant angle about it (a robot file's wrist: the SO-100's gripper)
                candidates.append([Rp[i][2] for i in range(3)])
            x = next((c for c in candidates if not self._reduce(_dot(c, z))), None)
            if x is None:
                return None
            y = self._cross(z, x)
            R = [[x[i], y[i], z[i]] for i in range(3)]
            if self.kinds[k] == "R":
                r = self._cross(w, v)  # the axis point nearest the base origin
                t = self._reduce(-_dot([r[i] - o_prev[i] for i in range(3)], z))
                o = [self._reduce(r[i] + t * z[i]) for i in range(3)]
            else:
                o = o_prev
            frames.append((R, o))
            o_prev = o
        return frames

    def _walk(self) -> tuple[list, tuple[list, list]] | None:
        """``F_1 Z(q_1) L_1 Z(q_2) L_2 ... Z(q_n) L_n`` with ``L_k = F_k^-1 F_(k+1)``, ``L_n = F_n^-1 M``.

        Equal to the product of exponentials, since ``exp6($_k, q_k) = F_k Z(q_k) F_k^-1``
        (Lynch & Park 2017, Appendix C: the Denavit-Hartenberg form).  With symbolic
        twist angles the ``L_k`` are short polynomials in their sines and cosines (the
        rows of the table) where the joint twists are long ones.  Returns the frames of the
        joints at ``q`` (``F_1 Z(q_1) L_1 ... Z(q_(k-1)) L_(k-1)``) and ``T(q)``; None for a
        chain without the geometry's circles or without the frames.
        """
        if not self.bases:
            return None
        if hasattr(self, "_walked"):
            return cast(Any, self._walked)
        frames = self._frames()
        if frames is None:
            self._walked: Any = None
            return None
        one, zero = self.R.one, self.R.zero

        def relative(A: tuple, B: tuple) -> tuple[list, list]:
            RA, oA = A
            RAt = [[RA[j][i] for j in range(3)] for i in range(3)]
            return self._mm(RAt, B[0]), self._mv(RAt, [B[1][i] - oA[i] for i in range(3)])

        links = [relative(frames[k], frames[k + 1]) for k in range(self.n - 1)]
        links.append(relative(frames[-1], self.home))
        # the written form's level of each geometry sine or cosine: the joint after the first
        # link it occurs in (alpha_k of the link k between joints k and k + 1), as a joint's own
        circle = {i for pair in self.pairs for i in pair}
        for k, (LR, Lp) in enumerate(links):
            for e in [x for row in LR for x in row] + Lp:
                for mon in e.itermonoms():
                    for g in circle:
                        if mon[g] and g not in self.level:
                            self.level[g] = k + 1
        at = []
        R, p = frames[0]
        for k in range(self.n):
            at.append((R, p))
            if self.kinds[k] == "R":
                angle, sgn = _canonical(self.angle_of[k])
                c, s = self.gen_of[self.cos_gen[angle]], self.gen_of[self.sin_gen[angle]] * sgn
                R = self._mm(R, [[c, -s, zero], [s, c, zero], [zero, zero, one]])
            else:
                qk = self.gen_of[self.q[k]] * self.sign
                p = [p[i] + qk * R[i][2] for i in range(3)]
            LR, Lp = links[k]
            R, p = self._mm(R, LR), [self._reduce(p[i] + x) for i, x in enumerate(self._mv(R, Lp))]
        self._walked = at, (R, p)
        return self._walked

    # --- back to expressions
    def expressions(self, elements: list) -> list[Expr]:
        writer = _Writer(self)
        return [writer.expr(e) for e in elements]


def _dot(a: list, b: list) -> Any:
    charge(len(a[0]) * len(b[0]) + len(a[1]) * len(b[1]) + len(a[2]) * len(b[2]))
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _linear(arg: Expr) -> dict | None:
    """``{symbol: integer}`` of an argument ``sum k_i x_i + constant``, or None for another argument."""
    _, terms = arg.as_coeff_Add()
    out: dict = {}
    for t in Add.make_args(terms):
        k, x = t.as_coeff_Mul()
        if not (k.is_Integer and x.is_Symbol):
            return None
        out[x] = out.get(x, 0) + int(k)
    return {x: k for x, k in out.items() if k}


def _circle_forms(matrices: list) -> tuple[dict, list, dict]:
    """The sines and cosines of the geometry in the generators of their bases' circles.

    A sine or cosine of ``sum k_i x_i + c`` (integers ``k_i``, symbols ``x_i``) is expanded by the
    angle-sum formulas (``expand_trig``) into a polynomial in ``cos(x_i), sin(x_i)``, each a
    ``Dummy``; one of any other argument ``u`` (a constant angle such as ``9/5`` included: an
    angle of a robot file that is no multiple of pi/12) is ``cos(u)`` or ``sin(u)`` of its own
    base ``u``.
    Returns the replacements, the bases (sorted) and ``base -> (cos Dummy, sin Dummy)``.
    """
    atoms: set = set()
    for M in matrices:
        atoms |= M.atoms(sin, cos)  # of symbols, or of a constant angle (cos(9/5) of a file)
    if not atoms:
        return {}, [], {}
    linear = {a: _linear(a.args[0]) for a in atoms}
    bases = set()
    for a, lin in linear.items():
        bases |= set(lin) if lin is not None else {a.args[0]}
    order = sorted(bases, key=default_sort_key)
    circle = {b: (Dummy("cg"), Dummy("sg")) for b in order}
    on_circle = {}
    for b, (c, s_) in circle.items():
        on_circle[cos(b)], on_circle[sin(b)] = c, s_
    forms = {a: on_circle[a] if lin is None else expand(expand_trig(a)).xreplace(on_circle)
             for a, lin in linear.items()}
    return forms, order, circle


def _frozen(e: Expr, parts: dict) -> Expr:
    """``e`` with each maximal non-polynomial part replaced by its ``Dummy`` in ``parts``."""
    if e.is_Symbol or e.is_Rational:
        return e
    if e.is_Add or e.is_Mul or e.is_Pow and e.exp.is_Integer and e.exp >= 0:
        return e.func(*(_frozen(a, parts) for a in e.args))
    if e.is_Float or not e.is_finite and e.is_number:
        raise _NotPolynomial("a float or an infinity in the geometry")
    if e.is_Pow and e.exp == S.Half and e.base.is_Rational and e.base > 0:
        split = surd_split(e.base)  # sqrt(3/8) = 1/4 sqrt(2) sqrt(3): one generator per prime
        if split is not None:
            k, primes = split
            roots = [parts.setdefault(Pow(p, S.Half), Dummy("r")) for p in primes]
            return Mul(k, *roots)
    if e not in parts:
        parts[e] = Dummy("g")
    return parts[e]


def fast_forward(twists: Sequence[Any], home: Any, q: tuple) -> tuple[ImmutableMatrix, ImmutableMatrix] | None:
    """``(R, p)`` of the forward kinematics by the ring, or None when the chain is outside its class."""
    engine = _engine(twists, home, q)
    if engine is None:
        return None
    R, p = engine.forward()
    entries = engine.expressions([x for row in R for x in row] + p)
    return ImmutableMatrix(3, 3, entries[:9]), ImmutableMatrix(3, 1, entries[9:])


def fast_space_jacobian(twists: Sequence[Any], home: Any, q: tuple) -> ImmutableMatrix | None:
    """The space Jacobian by the ring, or None when the chain is outside its class."""
    engine = _engine(twists, home, q)
    if engine is None:
        return None
    cols = engine.columns()
    entries = engine.expressions([x for col in cols for x in col])
    return ImmutableMatrix(engine.n, 6, entries).T


def fast_body_jacobian(body_twists: Sequence[Any], home: Any, q: tuple) -> ImmutableMatrix | None:
    """The body Jacobian by the ring: column ``i`` is ``Ad(exp6(B_n, -q_n) ... exp6(B_{i+1}, -q_{i+1})) B_i``.

    The space Jacobian's recursion run on the body twists from the tip, with the angles negated.
    """
    engine = _engine(list(reversed(body_twists)), home, tuple(reversed(q)), sign=-1)
    if engine is None:
        return None
    cols = engine.columns()[::-1]
    entries = engine.expressions([x for col in cols for x in col])
    return ImmutableMatrix(engine.n, 6, entries).T


#: the engines of the last few chains and joint values: ``forward`` and ``jacobian`` at the same
#: ``q`` share one ring product (an engine's results depend only on its key; each call writes
#: its own expressions with a new writer, so a result does not depend on the calls before it)
_RECENT: dict = {}
_RECENT_SIZE = 4
_UNSEEN = object()


def _engine(twists: Sequence[Any], home: Any, q: tuple, sign: int = 1) -> _Engine | None:
    if not all(isinstance(x, Symbol) for x in q) or len(set(q)) != len(q):
        return None
    key = (tuple(twists), home, q, sign)
    hit = _RECENT.get(key, _UNSEEN)
    if hit is not _UNSEEN:
        return cast(Any, hit)
    try:
        engine = _Engine(list(twists), home, q, sign)
    except _NotPolynomial:
        engine = None
    _RECENT[key] = engine
    while len(_RECENT) > _RECENT_SIZE:  # the oldest first (a plain dict keeps insertion order)
        try:
            del _RECENT[next(iter(_RECENT))]
        except (KeyError, RuntimeError, StopIteration):  # another thread took it first
            break
    return engine


