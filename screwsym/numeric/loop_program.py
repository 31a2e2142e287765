r"""A closed loop's mass matrix and inverse dynamics as straight-line programs.

:func:`loop_dynamics_program` writes the dynamics of
:meth:`Mechanism.mass_matrix <screwsym.systems.linkage.Mechanism.mass_matrix>` and
:meth:`Mechanism.inverse_dynamics <screwsym.systems.linkage.Mechanism.inverse_dynamics>`
(see :mod:`screwsym.systems.loop_dynamics` for the formulas) at a configuration given
by symbols, not as closed forms but as a :class:`~screwsym.motion.newton_euler.Program`:
an ordered list of assignments ``t = expr``, one per intermediate quantity, as the
customised Newton–Euler programs of a serial chain are
(:mod:`screwsym.motion.newton_euler`; Khalil & Kleinfinger 1987).  Nothing is expanded
and no expression is simplified, so a symbolic pose costs what a numeric one does: the
program is written in time linear in its length.

The program, in order:

1. the joints' twists at the configuration (each non-constant entry assigned once) and
   Davies' network matrix ``A`` (Davies 1981), in the loops of a spanning tree;
2. the normal equations of the passive joints' columns ``A_p``: ``N = A_p^T A_p``
   (entry ``(c, d)`` the twists' dot product times the number of loops that hold both,
   signed), factored ``L D L^T`` without roots in a minimum-degree order (chosen from the
   sparsity alone: a joint couples only to the joints of its loops).  ``N`` is positive
   definite exactly where ``A_p`` has full column rank, the actuated joints determining
   the motion, so every pivot of every order is positive there: no pivot vanishes off an
   actuation singularity (an LU of ``A_p`` itself, tried first, needs its pivots chosen at a
   sample point, and for Clavel's Delta one of them vanished on the plane ``y = 0``
   through the home pose);
3. the passive rates from ``A_p qd_p = -A_a qd_a``; each link's twist ``V`` and bias
   rate ``B`` (its twist rate at zero accelerations) along the spanning tree from the
   base, ``B_child = B_parent + [V, X] qd`` joint by joint
   (:func:`~screwsym.core.formulas.bracket`: one bracket per joint, not one per pair as
   in the loop-order sum of Müller 2016); the passive accelerations from the
   differentiated closure ``A_p qdd_p = -A_a qdd_a - c(qd)``, loop by loop from the
   chord ``(a, b)`` that closes it: ``V_b - V_a = X qd`` gives
   ``(P_b - P_a - X) qdd + B_b - B_a - [V_a, X] qd = 0`` (a chord of several
   freedoms: the loop-order sum ``sum_v [V_{<v}, X_v] qd_v``);
4. each body's twist rate ``B + P qdd`` (a forward Newton–Euler pass) and its
   Newton–Euler wrench ``M V' + [V, M V] - W``;
5. the virtual power: the wrenches summed over each subtree (a backward pass) give the
   tree joints' forces ``f``; then ``tau = G^T f = f_a - A_a^T lambda`` with
   ``lambda = A_p (A_p^T A_p)^-1 f_p``, the loops' multipliers (the least-norm solution of
   ``A_p^T lambda = f_p``: one more solve with the same factors, instead of the ``k``
   solves of ``G``).  The mass matrix is
   ``H = sum_l A_l^T Delta M_l A_l`` with ``A_l = P_l G`` (``k`` solves for ``G``).

Where it divides.  Each pivot ``d`` of ``D`` that is not a number is a condition of the
program (:attr:`LoopProgram.conditions`, ``Ne(d, 0)``): the product of all the pivots is
``det(A_p^T A_p)``, the sum of the squares of the minors ``det A_p[R]`` (Cauchy–Binet), so
all of them hold exactly where the actuated rates determine the motion
(:meth:`Mechanism.actuation_condition
<screwsym.systems.linkage.Mechanism.actuation_condition>` holds for some rows ``R``).
Every output is multiplied by ``ok``, ``1`` where all of them hold and ``nan`` elsewhere,
so the generated functions give ``nan`` at an actuation singularity, never a wrong number.
The passive rates are the least-squares solution of a consistent system, which is its
exact solution on a closed configuration; near a singularity the normal equations square
the condition number (floats lose accuracy there first).

Why not fraction-free.  Fraction-free elimination (Bareiss) keeps a closed form
polynomial; a program needs no such thing: a division is one operation, each quotient is
a new symbol, and at exact values the quotients are exact rationals.  The sample point
(``at=``, default seeded random rationals) only serves to refuse a mechanism whose
actuated joints never determine its motion: it is evaluated exactly where the
configuration's entries are rational there (a platform's coordinates), else at
``DIGITS`` digits with a value below ``10**-30`` taken as zero.

Exact: evaluated at exact values (:meth:`Program.evaluate
<screwsym.motion.newton_euler.Program.evaluate>`) a program gives the exact
``mass_matrix`` and ``inverse_dynamics`` of the mechanism at those values wherever its
conditions hold and the values describe a closed configuration.

References
==========

J. M. Davies, "Kirchhoff's circulation law applied to multi-loop kinematic chains",
Mech. Mach. Theory 16 (1981) 171-183.  A. Müller, "Local kinematic analysis of
closed-loop linkages", J. Mechanisms Robotics 8(4) (2016) 041013.  W. Khalil,
J.-F. Kleinfinger, "Minimum operations and minimum parameters of the dynamic models of
tree structure robots", IEEE J. Robotics and Automation 3(6) (1987).  W. F. Tinney, J. W. Walker, "Direct solutions of sparse
network equations by optimally ordered triangular factorization", Proc. IEEE 55 (1967)
1801-1809 (the minimum-degree order).  L.-W. Tsai, *Robot Analysis*, Wiley 1999, Chapter 9.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, replace
from fractions import Fraction
from functools import lru_cache
from itertools import count
from typing import Any

import mpmath  # type: ignore[import-untyped]  # SymPy's own dependency
from sympy import (
    Add,
    And,
    Expr,
    ImmutableMatrix,
    Mul,
    Ne,
    Piecewise,
    Rational,
    S,
    Symbol,
    cse,
    nan,
    sympify,
)

from ..algebra.budget import BUDGET, bounded, charge
from ..core.checks import check_choice, check_count, check_scalar, check_sequence, check_vector
from ..core.formulas import bracket
from ..motion.newton_euler import Program
from ..systems.topology import bare_network, spanning_tree
from ._loop_input import check_covered, check_mechanism, check_symbols

__all__ = ["LoopProgram", "loop_dynamics_program"]

#: the float policy's relative tolerance for double precision (:func:`screwsym.core.decide.float_tau`)
FLOAT_TOLERANCE = Rational(1, 2**40)

#: what :func:`loop_dynamics_program` writes
WHATS = ("inverse_dynamics", "mass_matrix")

#: the digits of the sample point where it is not rational (an angle's sine, a root)
DIGITS = 60

_MESSAGE = ("{name}: writing the program needs more than budget={budget} units; pass a "
            "larger budget")


@dataclass(frozen=True)
class LoopProgram(Program):
    r"""A closed loop's straight-line :class:`~screwsym.motion.newton_euler.Program`, with
    the conditions it assumes.

    ``conditions``: ``Ne(u, 0)`` for each pivot ``u`` (a symbol of the program) the
    elimination divides by; where one fails, the outputs are ``nan`` (see
    :mod:`~screwsym.numeric.loop_program`).  ``pivots`` the pivots themselves, in order.

    >>> from screwsym.systems.joints import R
    >>> from screwsym.systems.linkage import Mechanism
    >>> from screwsym.core.inertia import SpatialInertia
    >>> from sympy import symbols
    >>> x, y = symbols("x y", real=True)
    >>> z = [0, 0, 1]
    >>> four = Mechanism([("ground", "crank", R([0, 0, 0], z)),
    ...                   ("crank", "coupler", R([1, 2, 0], z)),
    ...                   ("coupler", "rocker", R([x, y, 0], z)),
    ...                   ("rocker", "ground", R([4, 0, 0], z))], base="ground",
    ...                  inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0])})
    >>> p = loop_dynamics_program(four, [0], [x, y], "mass_matrix")
    >>> len(p.conditions), p.evaluate([3, 3])
    (2, Matrix([[5]]))
    >>> p.evaluate([1, 2])             # coupler and rocker in line: nan, not a number
    Matrix([[nan]])
    >>> p.condition_values([1, 2]), p.condition_values([3, 3])
    ((0, nan), (7/3, 7/2))
    """

    conditions: tuple = ()
    pivots: tuple = ()
    scales: tuple = ()  # each pivot's size without cancellation (N's diagonal entry)
    guard: Any = None  # the symbol ``ok`` the outputs are multiplied by

    def float_guarded(self, tolerance: Any = FLOAT_TOLERANCE) -> LoopProgram:
        """The program with the float policy's guard: in floats a pivot ``d`` counts as zero
        when ``d <= tolerance * s``, ``s`` its size without cancellation (the diagonal
        entry of ``A_p^T A_p`` it comes from), ``tolerance`` the library's ``2**-40``
        (:mod:`screwsym.core.decide`); there the outputs are ``nan``.  What
        :func:`~screwsym.numeric.loop_dynamics.loop_dynamics_functions` compiles; the
        program itself decides exactly (``d != 0``)."""
        if self.guard is None:
            return self
        cond = And(*(d > tolerance * s for d, s in zip(self.pivots, self.scales, strict=True)))
        assigns = tuple((t, Piecewise((S.One, cond), (nan, True))) if t == self.guard else (t, e)
                        for t, e in self.assignments)
        return replace(self, assignments=assigns)

    def condition_values(self, *values: Any) -> tuple:
        """The pivots' values at ``values`` (as for :meth:`evaluate`): the program holds
        where none is zero."""
        env = dict(zip([x for a in self.arguments for x in a],
                       [check_scalar(v, "values") for vs in values for v in vs], strict=True))
        for t, e in self.assignments:
            env[t] = e.xreplace(env)
        return tuple(sympify(u, strict=True).xreplace(env) for u in self.pivots)


# ---------------------------------------------------------------- writing
class _Writer:
    """Appends assignments; a number, a symbol, its negative or a right-hand side seen before
    is not assigned again."""

    def __init__(self, taken: set[str]) -> None:
        self.assigns: list[tuple[Symbol, Expr]] = []
        self.seen: dict[Expr, Symbol] = {}
        self.taken = set(taken)

    def let(self, expr: Any, name: str) -> Expr:
        e = sympify(expr, strict=True)
        if not e.free_symbols or not e.args or (
                isinstance(e, Mul) and len(e.args) == 2 and e.args[0].is_Number
                and not e.args[1].args):
            return e
        if e in self.seen:
            return self.seen[e]
        if -e in self.seen:
            return -self.seen[-e]
        charge(10)
        base, k = name, 1
        while name in self.taken:
            k += 1
            name = f"{base}_{k}"
        self.taken.add(name)
        t = Symbol(name, real=True)
        self.assigns.append((t, e))
        self.seen[e] = t
        return t


_SIX = ("wx", "wy", "wz", "vx", "vy", "vz")
_SIX_W = ("fx", "fy", "fz", "cx", "cy", "cz")


def _six(W: _Writer, v: Any, name: str, parts: tuple = _SIX) -> list:
    return [W.let(x, name + c) for x, c in zip(v, parts, strict=True)]


def _power(t: list, w: list) -> Expr:
    """``t^T Delta w``: the power of the wrench ``w`` on the twist ``t`` (1.45)."""
    return Add(*(t[i] * w[3 + i] + t[3 + i] * w[i] for i in range(3)))


def _live(assigns: list, outputs: list) -> tuple:
    """The assignments the outputs need, in order (dead code removed)."""
    need = set().union(*(sympify(e, strict=True).free_symbols for e in outputs))
    keep = []
    for t, e in reversed(assigns):
        if t in need:
            keep.append((t, e))
            need |= e.free_symbols
    return tuple(reversed(keep))


# ---------------------------------------------------------------- the sample point
def _sample(symbols: tuple, at: Any) -> dict:
    """A point of the configuration's symbols: ``at`` (a dict) or random rationals."""
    if at is not None:
        if not isinstance(at, dict):
            raise TypeError(f"at: expected a dict {{symbol: value}}, got {type(at).__name__}")
        out = {k: check_scalar(v, f"at[{k}]") for k, v in at.items()}
        missing = [s for s in symbols if s not in out]
        if missing:
            raise ValueError(f"at: no value for {sorted(map(str, missing))}")
        return out
    rng = random.Random(35)
    return {s: S(rng.randint(-997, 997)) / rng.randint(211, 997) for s in symbols}


class _Values:
    """Exact rationals where every sampled entry is one, else ``DIGITS``-digit floats."""

    def __init__(self, exprs: list, point: dict) -> None:
        vals = [e.xreplace(point) if hasattr(e, "xreplace") else sympify(e, strict=True) for e in exprs]
        self.exact = all(v.is_Rational for v in vals)
        self.table: dict = {}
        for e, v in zip(exprs, vals, strict=True):
            self.table[e] = self.number(v)

    def number(self, v: Any) -> Any:
        if self.exact:
            return Fraction(int(v.p), int(v.q))
        with mpmath.workdps(DIGITS + 10):
            return mpmath.mpf(str(sympify(v, strict=True).evalf(DIGITS + 10)))

    def zero(self, v: Any) -> bool:
        if self.exact:
            return bool(v == 0)
        return bool(abs(v) < mpmath.mpf(10) ** (-DIGITS // 2))


# ---------------------------------------------------------------- the elimination
class _Normal:
    """The passive columns' normal equations ``N = A_p^T A_p``, factored ``L D L^T`` in a
    minimum-degree order (module docstring, step 2)."""

    def __init__(self, W: _Writer, rows: dict, n: int, values: _Values, labels: list,
                 twists: list, loops: list) -> None:
        # rows: r -> {c: (expr, value)} over the passive columns 0..n-1; twists[c] the
        # column's twist (6 exprs) and its values; loops: per loop, its (column, sign)
        self.rows = {r: {c: e for c, (e, _) in row.items()} for r, row in rows.items() if row}
        self.prow = sorted(self.rows)
        # N[c, d] = (sum over the loops holding both of s_c s_d) (twist_c . twist_d)
        count_: dict[tuple, int] = {}
        for loop in loops:
            for a, (c, sc) in enumerate(loop):
                for d, sd in loop[a:]:
                    key = (min(c, d), max(c, d))
                    count_[key] = count_.get(key, 0) + sc * sd
        N: dict[tuple, tuple] = {}
        adj: dict[int, set] = {c: set() for c in range(n)}
        with mpmath.workdps(DIGITS + 10):
            for (i, j), m in sorted(count_.items()):
                if m == 0:
                    continue
                (ti, vi), (tj, vj) = twists[i], twists[j]
                dot = W.let(Add(*(a * b for a, b in zip(ti, tj, strict=True))),
                            f"N{labels[i]}_{labels[j]}")
                if dot == 0:
                    continue
                N[(i, j)] = (m * dot, m * sum((a * b for a, b in zip(vi, vj, strict=True)), 0))
                adj[i].add(j)
                adj[j].add(i)
            diagonal = {t: e for (i, t), (e, _) in N.items() if i == t}
            self.scales: list[Expr] = []  # each pivot's size without cancellation
            charge(100 * len(N))
            self.order: list[int] = []
            self.inv: dict[int, Expr] = {}
            self.mult: dict[int, dict[int, Expr]] = {}  # step column -> {later column: l}
            self.pivots: list[Expr] = []
            remaining = set(range(n))
            while remaining:
                t = min(remaining, key=lambda c: (len(adj[c] & remaining), c))
                remaining.discard(t)
                u, uv = N.get((t, t), (S.Zero, 0))
                if u == 0 or values.zero(uv):
                    raise ValueError(
                        "mech: an actuation singularity at the sample point of the symbols: the "
                        f"passive joints' columns of the network matrix have rank < {n} there "
                        "(pass at= a point of the symbols where the actuated joints determine "
                        "the motion)")
                self.order.append(t)
                if u.free_symbols:
                    self.inv[t] = W.let(1 / u, f"inv{labels[t]}")
                    self.pivots.append(u)
                    self.scales.append(diagonal[t])
                else:
                    self.inv[t] = 1 / u
                invv = 1 / uv
                near = sorted(adj[t] & remaining)
                mult, multv = {}, {}
                for i in near:
                    e, v = N[(min(i, t), max(i, t))]
                    mult[i] = W.let(e * self.inv[t], f"l{labels[i]}_{labels[t]}")
                    multv[i] = v * invv
                for a, i in enumerate(near):
                    for j in near[a:]:
                        e, v = N.get((i, j), (S.Zero, 0))
                        b, bv = N[(min(t, j), max(t, j))]
                        new = W.let(e - mult[i] * b, f"N{labels[i]}_{labels[j]}")
                        N[(i, j)] = (new, v - multv[i] * bv)
                        adj[i].add(j)
                        adj[j].add(i)
                self.mult[t] = mult
                charge(100 * len(near) ** 2)
        self.labels = labels

    def _solve(self, W: _Writer, g: dict, name: str) -> dict:
        """``N x = g`` over the passive columns."""
        y: dict[int, Expr] = {}
        for t in self.order:
            rest = Add(*(m[t] * y[s] for s, m in self.mult.items() if t in m and s in y))
            y[t] = W.let(g.get(t, S.Zero) - rest, f"{name}y{self.labels[t]}")
        x: dict[int, Expr] = {}
        for t in reversed(self.order):
            rest = Add(*(m * x[i] for i, m in self.mult[t].items()))
            x[t] = W.let(y[t] * self.inv[t] - rest, f"{name}{self.labels[t]}")
        return x

    def solve(self, W: _Writer, b: dict, name: str, labels: list) -> dict:
        """``A_p x = b`` (``b`` over the rows, consistent): ``x = N^-1 A_p^T b``."""
        g: dict[int, Any] = {}
        for r, row in self.rows.items():
            if b.get(r, S.Zero) != 0:
                br = W.let(b[r], f"{name}b{r + 1}")
                for c, e in row.items():
                    g.setdefault(c, []).append(e * br)
        rhs = {c: W.let(Add(*ts), f"{name}g{self.labels[c]}") for c, ts in g.items()}
        return self._solve(W, rhs, name)

    def solve_transposed(self, W: _Writer, g: dict, name: str) -> dict:
        """The least-norm ``z`` over the rows with ``A_p^T z = g``: ``z = A_p N^-1 g``."""
        w = self._solve(W, g, name + "w")
        return {r: W.let(Add(*(e * w[c] for c, e in row.items())), f"{name}{r + 1}")
                for r, row in self.rows.items()}


# ---------------------------------------------------------------- the program
def _seq(net: Any, tw: list, acc: list, e: int, s: int) -> list:
    """Joint ``e``'s freedoms along a chain in direction ``s``: (freedom, X, Y or None)."""
    g = net.graph
    idx = list(range(len(tw[e])))
    if s < 0:
        idx.reverse()
    out = []
    for k in idx:
        X = [s * x for x in tw[e][k]]
        Y = None if acc[e][k] is None else [s * x for x in acc[e][k]]
        out.append((g.offsets[e] + k, X, Y))
    return out


def _rate_step(W: _Writer, V: list, Vd: list | None, X: list, Y: list | None, qd: Expr,
               qdd: Expr | None, name: str) -> tuple[list, list | None]:
    """One freedom along a chain: ``V' = V + X qd`` and
    ``V'd = Vd + X qdd + [V, X] qd + Y qd**2`` (``Vd`` None: rates only)."""
    Vn = _six(W, [a + b * qd for a, b in zip(V, X, strict=True)], name + "V")
    if Vd is None:
        return Vn, None
    br = bracket(V, X) if any(x != 0 for x in V) else [S.Zero] * 6
    br = _six(W, list(br), name + "B")
    new = [a + (b * qdd if qdd is not None else 0) + c * qd for a, b, c in zip(Vd, X, br, strict=True)]
    if Y is not None:
        new = [a + y * qd**2 for a, y in zip(new, Y, strict=True)]
    return Vn, _six(W, new, name + "A")


class _Geometry:
    """The twists, accelerations, inertia matrices and weights of the configuration, their
    common subexpressions assigned first (``sympy.cse``; names ``k1, k2, ...``)."""

    def __init__(self, W: _Writer, net: Any, bodies: list, g: Any) -> None:
        flat: list = []
        for ts in net.twists:
            for t in ts:
                flat += list(t)
        for ys in net.accel:
            for y in ys:
                flat += [] if y is None else list(y)
        for _, I in bodies:
            flat += list(I.matrix)
            if g is not None:
                flat += list(I.gravity_wrench(g).matrix)
        charge(10 * len(flat))
        names = (f"k{i}" for i in count(1))
        fresh = (Symbol(nm, real=True) for nm in names if nm not in W.taken)
        pairs, reduced = cse([sympify(e, strict=True) for e in flat], symbols=fresh)
        rename: dict = {}
        for t, e in pairs:
            rename[t] = W.let(e.xreplace(rename), t.name)
        it = iter([e.xreplace(rename) for e in reduced])
        self.twists = [[[next(it) for _ in range(6)] for _ in ts] for ts in net.twists]
        self.accel = [[None if y is None else [next(it) for _ in range(6)] for y in ys]
                      for ys in net.accel]
        self.inertia: dict = {}
        self.weight: dict = {}
        for link, _ in bodies:
            self.inertia[link] = [[next(it) for _ in range(6)] for _ in range(6)]
            if g is not None:
                self.weight[link] = [next(it) for _ in range(6)]


def _program(mech: Any, actuated: tuple, symbols: tuple, what: str, gravity: Any,
             at: Any) -> LoopProgram:
    net = bare_network(mech)
    graph = net.graph
    F = net.A.cols
    k = len(actuated)
    offsets = graph.offsets
    act_f = []
    for a in actuated:
        if graph.edges[a][2].freedom != 1:
            raise ValueError(f"actuated: joint {a} has {graph.edges[a][2].freedom} freedoms; "
                             "an actuated joint has one")
        act_f.append(offsets[a])
    if len(set(act_f)) != k:
        raise ValueError("actuated: a joint is given twice")
    passive = [f for f in range(F) if f not in act_f]
    n = len(passive)
    pindex = {f: i for i, f in enumerate(passive)}
    labels = [f + 1 for f in passive]  # the passive joints' rates are named by freedom
    taken = {s.name for s in symbols}
    names = []
    for base in ("qd", "qdd"):
        row = []
        for i in range(k):
            nm = f"{base}{i + 1}"
            while nm in taken:
                nm += "'"
            row.append(Symbol(nm, real=True))
        names.append(row)
    qda, qdda = names
    W = _Writer(taken | {s.name for s in qda + qdda})

    # 1. the twists, and the network matrix on them
    bodies = [(int(graph.index[p.args[0]]), p.args[1]) for p in mech.inertia_pairs]
    g = check_vector(gravity, "gravity")
    # the configuration's own expressions (twists, inertias, weights): their common
    # subexpressions (an angle's sine, a difference of points) assigned once
    geometry = _Geometry(W, net, bodies, g if what == "inverse_dynamics" else None)
    tw = [[_six(W, t, f"S{offsets[e] + k_ + 1}") for k_, t in enumerate(ts)]
          for e, ts in enumerate(geometry.twists)]
    acc = [[None if y is None else _six(W, y, f"Y{offsets[e] + k_ + 1}")
            for k_, y in enumerate(ys)] for e, ys in enumerate(geometry.accel)]
    entries: dict[int, dict[int, Expr]] = {}
    for i, loop in enumerate(graph.loops):
        for e, s in loop:
            for k_, t in enumerate(tw[e]):
                for r in range(6):
                    if t[r] != 0:
                        line = entries.setdefault(6 * i + r, {})
                        line[offsets[e] + k_] = line.get(offsets[e] + k_, S.Zero) + s * t[r]
    # the values at the sample point of the entries of A_p
    point = _sample(symbols, at)
    base_exprs = {e for row in entries.values() for e in row.values()}
    env: dict = dict(point)
    for t, rhs in W.assigns:
        env[t] = rhs.xreplace(env)
    raw = {e: e.xreplace(env) for e in base_exprs}
    vals = _Values(list(raw.values()), {})
    Ap = {r: {pindex[c]: (e, vals.table[raw[e]]) for c, e in row.items()
              if c in pindex and e != 0} for r, row in entries.items()}
    columns = []  # each passive column's twist, and its values there
    for f in passive:
        e = next(e for e in range(len(graph.edges)) if offsets[e] <= f < offsets[e] + len(tw[e]))
        t = tw[e][f - offsets[e]]
        columns.append((t, [vals.number(sympify(x, strict=True).xreplace(env)) for x in t]))
    loops = [[(pindex[offsets[e] + k_], s) for e, s in loop for k_ in range(len(tw[e]))
              if offsets[e] + k_ in pindex] for loop in graph.loops]
    lu = _Normal(W, Ap, n, vals, labels, columns, loops)
    Aa = {r: [entries.get(r, {}).get(f, S.Zero) for f in act_f] for r in lu.prow}

    parent: dict[int, tuple] = {}
    for link, path in enumerate(graph.paths):
        if path:
            e, s = path[-1]
            a, b, _ = graph.edges[e]
            parent[link] = ((a if s > 0 else b), e, s)

    if what == "mass_matrix":
        # G: the passive rates per actuated rate (k solves)
        G: dict[int, list] = {f: [S.One if f == af else S.Zero for af in act_f] for f in act_f}
        cols = [lu.solve(W, {r: -Aa[r][c] for r in lu.prow}, f"G{c + 1}_", labels)
                for c in range(k)]
        for f in passive:
            G[f] = [cols[c][pindex[f]] for c in range(k)]
        Al: dict[int, list] = {0: [[S.Zero] * 6 for _ in range(k)]}

        def twist_per_rate(link: int) -> list:
            if link in Al:
                return Al[link]
            p, e, s = parent[link]
            cur = [list(v) for v in twist_per_rate(p)]
            for f, X, _ in _seq(net, tw, acc, e, s):
                for c in range(k):
                    if G[f][c] != 0:
                        cur[c] = [a + x * G[f][c] for a, x in zip(cur[c], X, strict=True)]
            Al[link] = [_six(W, cur[c], f"J{link}_{c + 1}") for c in range(k)]
            return Al[link]

        H: list[list[Any]] = [[S.Zero] * k for _ in range(k)]
        for link, _ in bodies:
            J = twist_per_rate(link)
            M = [[W.let(geometry.inertia[link][i][j], f"M{link}_{i + 1}{j + 1}")
                  for j in range(6)] for i in range(6)]
            MJ = [_six(W, [Add(*(M[i][j] * J[c][j] for j in range(6))) for i in range(6)],
                       f"MJ{link}_{c + 1}", _SIX_W) for c in range(k)]
            for i in range(k):
                for j in range(i, k):
                    H[i][j] += _power(J[i], MJ[j])
        out = [[None] * k for _ in range(k)]
        for i in range(k):
            for j in range(i, k):
                out[i][j] = out[j][i] = W.let(H[i][j], f"H{i + 1}{j + 1}")
        flat = [x for row in out for x in row]
        shape = (k, k)
    else:
        # 3. the passive rates and accelerations
        xs = lu.solve(W, {r: -Add(*(Aa[r][c] * qda[c] for c in range(k))) for r in lu.prow},
                      "dq", labels)
        qd: list[Any] = [S.Zero] * F
        for c, f in enumerate(act_f):
            qd[f] = qda[c]
        for f in passive:
            qd[f] = xs[pindex[f]]
        # 4a. each link's twist V and bias rate B (its twist rate at zero accelerations,
        # the brackets along its tree path), shared by the loops and the bodies
        bias: dict[int, tuple] = {0: ([S.Zero] * 6, [S.Zero] * 6)}

        def biased(link: int) -> tuple:
            if link in bias:
                return bias[link]
            p, e, s = parent[link]
            V, B = biased(p)
            for f, X, Y in _seq(net, tw, acc, e, s):
                V, B = _rate_step(W, V, B, X, Y, qd[f], None, f"l{link}_{f + 1}")
            bias[link] = (V, B)
            return bias[link]

        tree = {e for _, e, _ in parent.values()}
        crow: dict[int, Expr] = {}
        for i, loop in enumerate(graph.loops):
            if not any(6 * i + r in lu.prow for r in range(6)):
                continue
            (e, s), = [(e, s) for e, s in loop if e not in tree]
            a, b, j = graph.edges[e]
            if j.freedom == 1 and acc[e][0] is None:
                # the chord joins a to b: V_b - V_a = X qd, so, X moving with a,
                # (P_b - P_a - X) qdd + B_b - B_a - [V_a, X] qd = 0; the loop's row of A is
                # -s times (P_b - P_a - X) (the chord's coefficient there is s)
                Va, Ba = biased(a)
                _, Bb = biased(b)
                X = tw[e][0]
                br = bracket(Va, X) if any(v != 0 for v in Va) else [S.Zero] * 6
                br = _six(W, list(br), f"C{i + 1}B")
                for r in range(6):
                    crow[6 * i + r] = -s * (Bb[r] - Ba[r] - br[r] * qd[offsets[e]])
                continue
            V: list = [S.Zero] * 6  # else along the loop, in its order
            Vd: list | None = [S.Zero] * 6
            for e, s in loop:
                for f, X, Y in _seq(net, tw, acc, e, s):
                    V, Vd = _rate_step(W, V, Vd, X, Y, qd[f], None, f"L{i + 1}_{f + 1}")
            assert Vd is not None
            for r in range(6):
                crow[6 * i + r] = Vd[r]
        ys = lu.solve(W, {r: -Add(*(Aa[r][c] * qdda[c] for c in range(k))) - crow[r]
                          for r in lu.prow}, "ddq", labels)
        qdd: list[Any] = [S.Zero] * F
        for c, f in enumerate(act_f):
            qdd[f] = qdda[c]
        for f in passive:
            qdd[f] = ys[pindex[f]]
        # 4b. the bodies' twist rates: B plus the accelerations along the tree path
        lin: dict[int, list] = {0: [S.Zero] * 6}

        def linear(link: int) -> list:
            if link in lin:
                return lin[link]
            p, e, s = parent[link]
            cur = list(linear(p))
            for f, X, _ in _seq(net, tw, acc, e, s):
                cur = [c + x * qdd[f] for c, x in zip(cur, X, strict=True)]
            lin[link] = _six(W, cur, f"a{link}_")
            return lin[link]

        def motion(link: int) -> tuple:
            V, B = biased(link)
            return V, _six(W, [a + b for a, b in zip(linear(link), B, strict=True)],
                           f"l{link}_A")

        wrench: dict[int, list] = {}
        for link, _ in bodies:
            V, Vd = motion(link)
            M = [[W.let(geometry.inertia[link][i][j], f"M{link}_{i + 1}{j + 1}")
                  for j in range(6)] for i in range(6)]
            mom = _six(W, [Add(*(M[i][j] * V[j] for j in range(6))) for i in range(6)],
                       f"h{link}", _SIX_W)
            br = bracket(V, mom)
            weight = geometry.weight[link]
            D = [Add(*(M[i][j] * Vd[j] for j in range(6))) + br[i] - weight[i]
                 for i in range(6)]
            wrench[link] = _six(W, D, f"D{link}", _SIX_W)
        # 5. the subtree wrenches, the tree joints' forces and the virtual power
        children: dict[int, list] = {}
        for link, (p, _, _) in parent.items():
            children.setdefault(p, []).append(link)
        sub: dict[int, list | None] = {}

        def subtree(link: int) -> list | None:
            if link in sub:
                return sub[link]
            parts = [wrench[link]] if link in wrench else []
            parts += [w for c in children.get(link, []) if (w := subtree(c)) is not None]
            sub[link] = (None if not parts else
                         _six(W, [Add(*(w[i] for w in parts)) for i in range(6)],
                              f"W{link}", _SIX_W))
            return sub[link]

        force: dict[int, Expr] = {}
        for link, (_, e, s) in parent.items():
            w = subtree(link)
            if w is None:
                continue
            for f, X, _ in _seq(net, tw, acc, e, s):
                force[f] = W.let(_power(X, w), f"f{f + 1}")
        lam = lu.solve_transposed(W, {pindex[f]: v for f, v in force.items() if f in pindex},
                                  "lam")
        flat = [W.let(force.get(f, S.Zero) - Add(*(Aa[r][c] * lam[r] for r in lu.prow)),
                      f"tau{c + 1}") for c, f in enumerate(act_f)]
        shape = (k, 1)
    # where a pivot vanishes: nan, in every output
    conditions = tuple(Ne(u, 0) for u in lu.pivots)
    ok: Any = None
    if conditions:
        name = "ok"
        while name in W.taken:
            name += "'"
        ok = Symbol(name, real=True)
        cond = conditions[0] if len(conditions) == 1 else And(*conditions)
        W.assigns.append((ok, Piecewise((S.One, cond), (nan, True))))
        flat = [ok * x for x in flat]
    outputs = ImmutableMatrix(*shape, flat)
    arguments: tuple = (ImmutableMatrix(list(symbols)),)
    if what == "inverse_dynamics":
        arguments += (ImmutableMatrix(qda), ImmutableMatrix(qdda))
    return LoopProgram(arguments, _live(W.assigns, flat), outputs,
                       "tau" if what == "inverse_dynamics" else "H", conditions,
                       tuple(lu.pivots), tuple(lu.scales), ok)


@lru_cache(maxsize=32)
def _cached(mech: Any, actuated: tuple, symbols: tuple, what: str, gravity: Any,
            budget: int) -> LoopProgram:
    with bounded(budget, "loop_dynamics_program", _MESSAGE):
        return _program(mech, actuated, symbols, what, gravity, None)


def loop_dynamics_program(mech: Any, actuated: Any, symbols: Any,
                          what: str = "inverse_dynamics", gravity: Any = None, *,
                          at: Any = None, budget: int = BUDGET) -> LoopProgram:
    r"""The closed loop's inverse dynamics or mass matrix as a straight-line program.

    Explanation
    ===========

    ``mech`` a :class:`~screwsym.systems.linkage.Mechanism` with inertias, ``actuated``
    the actuated joints' numbers (one freedom each, as many as the mobility),
    ``symbols`` the symbols its configuration is given in (the program's first
    argument ``p``).  ``what="inverse_dynamics"`` (arguments ``p, qd, qdd``, the
    actuated rates and accelerations; output ``tau``, ``k x 1``) or ``"mass_matrix"``
    (argument ``p``; output ``H``, ``k x k``).  ``gravity`` numbers or expressions in
    ``symbols`` (default ``(0, 0, -9.81)``, exactly ``-981/100``).  The pivots are chosen at
    ``at`` (a dict ``{symbol: value}`` of a configuration where the actuated joints
    determine the motion; default a seeded random rational point).  See
    :mod:`~screwsym.numeric.loop_program` for the program's steps and its
    :attr:`~LoopProgram.conditions`.  Cached per mechanism, actuation, symbols, ``what``
    and gravity (not with ``at``).  :func:`screwsym.lambdify` compiles it;
    :func:`~screwsym.numeric.loop_dynamics.loop_dynamics_functions` with
    ``form="program"`` does so for every back end.

    Examples
    ========

    The four-bar of :meth:`Mechanism.inverse_dynamics
    <screwsym.systems.linkage.Mechanism.inverse_dynamics>` with its coupler-rocker joint
    at ``(x, y)``: at ``(3, 3)`` the program gives that method's ``10/7``, exactly.

    >>> from sympy import symbols
    >>> from screwsym.core.inertia import SpatialInertia
    >>> from screwsym.systems.joints import R
    >>> from screwsym.systems.linkage import Mechanism
    >>> x, y = symbols("x y", real=True)
    >>> z = [0, 0, 1]
    >>> four = Mechanism([("ground", "crank", R([0, 0, 0], z)),
    ...                   ("crank", "coupler", R([1, 2, 0], z)),
    ...                   ("coupler", "rocker", R([x, y, 0], z)),
    ...                   ("rocker", "ground", R([4, 0, 0], z))], base="ground",
    ...                  inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
    ...                            "rocker": SpatialInertia.point_mass(2, [x, y, 0])})
    >>> tau = loop_dynamics_program(four, [0], [x, y], gravity=[0, -10, 0])
    >>> tau.evaluate([3, 3], [0], [0])
    Matrix([[10/7]])
    >>> tau.conditions       # their product: a constant times (2x + 3y - 8)**2
    (Ne(N3_3_2, 0), Ne(N4_4, 0))
    >>> tau.evaluate([1, 2], [0], [0])      # (1, 2): coupler and rocker in line
    Matrix([[nan]])
    >>> tau.operations()
    Operations(multiplications=63, additions=39, functions=1)

    Parameters
    ==========

    mech : Mechanism
    actuated : sequence of int
    symbols : sequence of Symbol
    what : {"inverse_dynamics", "mass_matrix"}
    gravity : 3 numbers or expressions in ``symbols``
    at : dict, optional
    budget : int

    See Also
    ========

    screwsym.motion.newton_euler.dynamics_program, screwsym.numeric.loop_dynamics_functions
    """
    check_mechanism(mech)
    what = check_choice(what, "what", WHATS)
    acts = check_sequence(actuated, "actuated", "joint numbers")
    out = []
    for i, a in enumerate(acts):
        if isinstance(a, bool) or not (isinstance(a, int) or getattr(a, "is_Integer", False)):
            raise TypeError(f"actuated[{i}]: expected a joint number (an int), got {a!r}")
        if not 0 <= int(a) < len(mech.joints):
            raise ValueError(f"actuated[{i}]: expected a joint number 0..{len(mech.joints) - 1}, "
                             f"got {a}")
        out.append(int(a))
    syms = check_symbols(symbols)
    g = check_vector((0, 0, -S(981) / 100) if gravity is None else gravity, "gravity")
    check_covered(mech, syms, g.free_symbols)
    budget = check_count(budget, "budget")
    spanning_tree(mech)  # a disconnected mechanism is refused here, with its message
    if at is not None:
        with bounded(budget, "loop_dynamics_program", _MESSAGE):
            return _program(mech, tuple(out), tuple(syms), what, ImmutableMatrix(g), at)
    return _cached(mech, tuple(out), tuple(syms), what, ImmutableMatrix(g), budget)
