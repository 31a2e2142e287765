r"""Customised Newton–Euler: a chain's dynamics as straight-line programs over exact numbers.

The closed forms of :mod:`screwsym.motion.dynamics` are single expressions in the joint
variables, shortened afterwards.  The programs here are what the published record of
symbolic dynamics generates instead (Khalil & Kleinfinger 1987, SYMORO; Murray & Neuman's
ARM, 1984): an ordered list of assignments ``t = expr``, one intermediate per link
quantity (each component of a twist, an acceleration, a wrench, a composite inertia),
in which every product by a known ``0`` or ``1`` is dropped as the program is written
(SymPy folds it: the chain's numbers are exact), each link's ``sin q_i`` and ``cos q_i``
are computed once, and equal right-hand sides are computed once.

The frames
==========

The recursions are those of :mod:`screwsym.motion.dynamics` (twists and wrenches in ray
order, :func:`~screwsym.core.formulas.bracket`, the reciprocal product), but each link
``i`` gets the frame ``{i}`` parallel to the space frame at home whose origin ``o_i`` is a
point of joint ``i``'s axis: the point nearest joint ``i+1``'s axis when the two are not
parallel, else the foot of the perpendicular from ``o_{i-1}`` (a prismatic joint keeps
``o_{i-1}``).  Then joint ``i``'s twist in ``{i}`` is ``(w_i; h_i w_i)`` (a hinge:
``(w_i; 0)``), ``{i}`` is posed in ``{i-1}`` by ``T_i = Trans(o_i - o_{i-1}) exp6``,
a rotation about an axis through the origin, and for the axis-aligned joints of most arms
``R_i`` has four non-constant entries.  Writing the recursion in these frames is what makes
most products vanish; the torques are the same (the reciprocal product is invariant).

Link ``i``'s wrench is written about ``o_i`` from its centre of mass ``c`` (in ``{i}``),
``h = m c`` and its inertia ``I_c`` about ``c`` (Luh, Walker & Paul 1980):

    a_O = dv + w x v,   f = m a_O + dw x h + w x (w x h),   C = I_c dw + w x (I_c w) + c x f,

with ``(w; v)`` the link's twist and ``(dw; dv)`` its spatial acceleration in ``{i}``.
The mass matrix program is the composite rigid body method (Featherstone 2008, 6.2) in
the same frames, the composite inertias carried by ``T_{i+1}`` as ten parameters
(``m``, ``h``, ``I_O``) each an intermediate.

References
==========

W. Khalil, J.-F. Kleinfinger, "Minimum operations and minimum parameters of the dynamic
models of tree structure robots", *IEEE J. Robotics and Automation* 3(6), 1987.
J. J. Murray, C. P. Neuman, "ARM: an algebraic robot dynamic modeling program", *IEEE
Int. Conf. Robotics*, 1984.  J. Y. S. Luh, M. W. Walker, R. P. C. Paul, "On-line
computational scheme for mechanical manipulators", *ASME J. Dyn. Syst.* 102, 1980.
R. Featherstone, *Rigid Body Dynamics Algorithms*, Springer 2008.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any, NamedTuple

from sympy import (
    Add,
    Basic,
    Expr,
    Function,
    ImmutableMatrix,
    Mul,
    Pow,
    S,
    Symbol,
    cos,
    sign,
    sin,
    sympify,
)

from ..algebra.numberfield import surd_quotient
from ..core.checks import check_choice, check_scalar, check_sequence, check_vector
from ..core.decide import is_zero_vector
from ..core.inertia import PARAMETER_NAMES
from ..core.twist import Twist
from .displacement import exp6
from .dynamics import GRAVITY

if TYPE_CHECKING:
    from .chain import Chain

__all__ = ["Operations", "Program", "dynamics_program", "regressor_program", "parameter_symbols"]

Vec = tuple[Expr, Expr, Expr]


class Operations(NamedTuple):
    """A program's arithmetic: multiplications (divisions included), additions, function calls.

    A negation is free (it is folded into an addition or a sign); a constant coefficient
    is one multiplication (a constant such as ``sqrt(2)/2`` costs nothing: it is computed
    once); ``x**k`` is ``k - 1`` multiplications.
    """

    multiplications: int
    additions: int
    functions: int


def _count(e: Basic, tally: list[int]) -> None:
    stack = [e]
    while stack:
        x = stack.pop()
        if not x.args or not x.free_symbols:  # a constant (sqrt(2)/2, ...) is folded once
            continue
        if isinstance(x, Add):
            tally[1] += len(x.args) - 1
        elif isinstance(x, Mul):
            factors = len(x.args) - (1 if x.args[0] == -1 else 0)
            tally[0] += max(factors - 1, 0)
        elif isinstance(x, Pow):
            k = x.exp
            if k.is_Integer and k > 0:
                tally[0] += int(k) - 1
            elif k.is_Integer:
                tally[0] += -int(k)
            else:
                tally[2] += 1
            stack.append(x.base)
            continue
        elif isinstance(x, Function):
            tally[2] += 1
        stack.extend(x.args)


@dataclass(frozen=True)
class Program:
    r"""A straight-line program: ``assignments`` in order, then ``outputs`` from them.

    ``arguments`` are the matrices of input symbols (e.g. ``q, qd, qdd``); each
    assignment ``(t, expr)`` defines a new symbol ``t`` from the arguments and the
    symbols assigned before it; ``outputs`` is a matrix in the same.  Immutable.
    :func:`screwsym.lambdify` compiles a program directly (its assignments are the
    generated code's common subexpressions).

    >>> from sympy import symbols
    >>> from screwsym import Chain, SpatialInertia, Twist
    >>> pendulum = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])],
    ...                  inertias=[SpatialInertia.point_mass(1, [1, 0, 0])])
    >>> p = dynamics_program(pendulum, "inverse_dynamics", gravity=[0, -10, 0])
    >>> print(p)
    c1 = cos(q1)
    a1y = 10*c1
    fb1y = a1y + qdd1
    tau = [fb1y]
    >>> p.operations()
    Operations(multiplications=1, additions=1, functions=1)
    >>> p.expressions()
    Matrix([[qdd1 + 10*cos(q1)]])
    """

    arguments: tuple[ImmutableMatrix, ...]
    assignments: tuple[tuple[Symbol, Expr], ...]
    outputs: ImmutableMatrix
    name: str = "out"

    def operations(self) -> Operations:
        """The multiplications, additions and function calls of the whole program."""
        tally = [0, 0, 0]
        for _, e in self.assignments:
            _count(e, tally)
        for e in self.outputs:
            _count(e, tally)
        return Operations(*tally)

    def evaluate(self, *values: Any) -> ImmutableMatrix:
        """The outputs at ``values`` (one sequence per argument), assignment by assignment.

        Exact when the values are (SymPy numbers or symbols); floats stay floats.
        """
        if len(values) != len(self.arguments):
            raise ValueError(f"values: expected {len(self.arguments)} sequences, got {len(values)}")
        env: dict[Basic, Any] = {}
        for k, (arg, val) in enumerate(zip(self.arguments, values, strict=True)):
            val = list(val)
            if len(val) != len(arg):
                raise ValueError(f"values[{k}]: expected {len(arg)} values, got {len(val)}")
            env.update((x, check_scalar(v, f"values[{k}][{j}]"))
                       for j, (x, v) in enumerate(zip(arg, val, strict=True)))
        for t, e in self.assignments:
            env[t] = e.xreplace(env)
        return self.outputs.xreplace(env)

    def expressions(self) -> ImmutableMatrix:
        """The outputs as closed forms in the arguments (the assignments substituted back, untidied)."""
        return self.evaluate(*self.arguments)

    def _lambdify_program(self) -> tuple[tuple[tuple[Symbol, Expr], ...], ImmutableMatrix]:
        return self.assignments, self.outputs

    def __str__(self) -> str:
        lines = [f"{t} = {e}" for t, e in self.assignments]
        lines.append(f"{self.name} = {list(self.outputs)}")
        return "\n".join(lines)


# ---------------------------------------------------------------- writing a program


class _Writer:
    """Appends assignments; an atom, a negated atom or a right-hand side seen before is not assigned."""

    def __init__(self, taken: set[str]) -> None:
        self.assigns: list[tuple[Symbol, Expr]] = []
        self.seen: dict[Expr, Symbol] = {}
        self.taken = set(taken)

    def let(self, expr: Any, name: str) -> Expr:
        e = sympify(expr, strict=True)
        if not e.args or (isinstance(e, Mul) and len(e.args) == 2 and e.args[0] == -1
                          and not e.args[1].args):
            return e
        if e in self.seen:
            return self.seen[e]
        if -e in self.seen:
            return -self.seen[-e]
        while name in self.taken:
            name += "'"
        self.taken.add(name)
        t = Symbol(name, real=True)
        self.assigns.append((t, e))
        self.seen[e] = t
        return t

    def vec(self, v: Sequence[Any], name: str) -> Vec:
        return tuple(self.let(x, f"{name}{a}") for x, a in zip(v, "xyz", strict=True))  # type: ignore[return-value]


def _cross(a: Sequence[Expr], b: Sequence[Expr]) -> Vec:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a: Sequence[Expr], b: Sequence[Expr]) -> Expr:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _mat(M: Sequence[Sequence[Expr]], v: Sequence[Expr]) -> Vec:
    return tuple(_dot(row, v) for row in M)  # type: ignore[return-value]


def _matT(M: Sequence[Sequence[Expr]], v: Sequence[Expr]) -> Vec:
    return tuple(_dot([M[0][j], M[1][j], M[2][j]], v) for j in range(3))  # type: ignore[return-value]


def _add(*vs: Sequence[Expr]) -> Vec:
    return tuple(Add(*xs) for xs in zip(*vs, strict=True))  # type: ignore[return-value]


def _scale(k: Expr, v: Sequence[Expr]) -> Vec:
    return (k * v[0], k * v[1], k * v[2])


def _col(v: Any) -> Vec:
    return (v[0], v[1], v[2])


class _Link(NamedTuple):
    """Joint ``i`` in the frames of the module docstring."""

    w: Vec   # the joint twist in {i}: (w; v)
    v: Vec
    d: Vec   # o_i - o_{i-1}, in {i-1} (parallel to the space frame at home)


def _nearest_on(p: Any, u: Any, p2: Any, u2: Any) -> Any:
    """The point of the line ``p + t u`` nearest the line ``p2 + s u2``; None when parallel."""
    n = u.cross(u2)
    if is_zero_vector(n) is not False:
        return None
    t = (p2 - p).cross(u2).dot(n) / n.dot(n)
    return p + t * u


def _exact_number(x: Expr) -> Expr:
    """``x`` expanded; a number built from square roots by sums, products and quotients (a
    robot at 15 degrees) in its normal form ``a + b sqrt 2 + c sqrt 3 + d sqrt 6``: the
    quotients by ``n . n`` below otherwise nest with every frame (a 2-joint program took
    over 20 s)."""
    if x.free_symbols:
        return x.expand()
    normal = surd_quotient(x)
    return x if normal is None else normal


def _links(chain: Chain) -> tuple[list[_Link], list[Any]]:
    """The joints' twists in their frames ``{i}`` and the frames' offsets (module docstring)."""
    axes = []
    for t in chain.twists:
        w, v = t.matrix[:3, :], t.matrix[3:, :]
        if is_zero_vector(w) is True:
            axes.append((None, v))
        else:
            axes.append(((w.cross(v) / w.dot(w)).applyfunc(_exact_number), w))
    origins = []
    prev = ImmutableMatrix([0, 0, 0])
    for i, (point, u) in enumerate(axes):
        if point is None:
            o = prev
        else:
            o = None
            if i + 1 < len(axes) and axes[i + 1][0] is not None:
                o = _nearest_on(point, u, axes[i + 1][0], axes[i + 1][1])
            if o is None:
                o = point + (prev - point).dot(u) / u.dot(u) * u
        o = o.applyfunc(_exact_number)
        origins.append(o)
        prev = o
    links = []
    prev = ImmutableMatrix([0, 0, 0])
    for t, o in zip(chain.twists, origins, strict=True):
        w, v = t.matrix[:3, :], t.matrix[3:, :]
        v_local = (v + w.cross(o)).applyfunc(_exact_number)
        links.append(_Link(_col(w), _col(v_local), _col((o - prev).applyfunc(_exact_number))))
        prev = o
    return links, origins


class _Body(NamedTuple):
    m: Expr
    c: Vec                                  # centre of mass in {i}
    h: Vec                                  # m c
    I: tuple[Vec, Vec, Vec]                 # about c


class _Params(NamedTuple):
    """A link's parameters about its origin ``o_i`` in ``{i}``: symbols or their combinations."""

    m: Expr
    h: Vec                                  # first moment about o_i
    I: tuple[Vec, Vec, Vec]                 # about o_i


def _parametric_bodies(W: _Writer, values: Sequence[Expr], origins: list[Any]) -> list[_Params]:
    """Each link's ``(m, h, I)`` about ``o_i`` from the ``10 n`` standard ``values`` (linear), named once."""
    out = []
    for j, o in enumerate(origins):
        m, h, I = _link_parameters(list(values[10 * j:10 * j + 10]), o)
        k = j + 1
        I = tuple(tuple(W.let(I[r][c], f"J{k}_{'xyz'[min(r, c)]}{'xyz'[max(r, c)]}")
                        for c in range(3)) for r in range(3))
        out.append(_Params(W.let(m, f"M{k}"), W.vec(h, f"MS{k}"), I))
    return out


def _bodies(chain: Chain, origins: list[Any]) -> list[_Body]:
    out = []
    for b, o in zip(chain.inertias or (), origins, strict=True):
        c = _col(b.com - o)
        I = tuple(_col(b.inertia[k, :].T) for k in range(3))
        out.append(_Body(b.mass, c, _scale(b.mass, c), I))  # type: ignore[arg-type]
    return out


def _joint_pose(W: _Writer, link: _Link, q: Expr, i: int) -> tuple[list[list[Expr]], Vec]:
    """``T_i = Trans(d_i) exp6(joint twist in {i}, q_i)``: its rotation and translation, trig named once."""
    E = exp6(Twist(list(link.w), list(link.v)), q)
    trig = {f for f in E.R.atoms(sin, cos) | E.p.atoms(sin, cos)}
    names = {}
    for f in sorted(trig, key=lambda f: (f.func is cos, str(f))):
        names[f] = W.let(f, f"{'s' if f.func is sin else 'c'}{i}")
    R = [[W.let(E.R[r, k].xreplace(names).expand(), f"R{i}_{r}{k}") for k in range(3)]
         for r in range(3)]
    p = W.vec(_add(link.d, _col(E.p.xreplace(names).applyfunc(lambda x: x.expand()))), f"p{i}_")
    return R, p


def _gravity(gravity: Any) -> ImmutableMatrix:
    return check_vector(GRAVITY if gravity is None else gravity, "gravity")


def _check_chain(chain: Any) -> None:
    if not hasattr(chain, "twists") or not hasattr(chain, "n_joints"):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    if chain.inertias is None:
        raise ValueError(
            "chain: the chain has no inertias; build it with Chain(twists, home, "
            "inertias=[SpatialInertia(...), ...]) (one per link, in the space frame at home)"
        )


def _program(chain: Chain, what: str, gravity: Any,
             params: tuple[ImmutableMatrix, ImmutableMatrix] | None = None) -> Program:
    """The program of ``what``; with ``params = (symbols, values)``, in the parameter ``symbols``
    (an argument after the joints'), the ``10 n`` standard parameters being ``values``."""
    if params is None:
        _check_chain(chain)
    n = chain.n_joints
    q, qd, qdd = (ImmutableMatrix([Symbol(f"{s}{i + 1}", real=True) for i in range(n)])
                  for s in ("q", "qd", "qdd"))
    g = _gravity(gravity)
    taken = {s.name for s in chain.free_symbols | g.free_symbols} | {
        x.name for m in (q, qd, qdd) for x in m}
    extra: tuple[ImmutableMatrix, ...] = ()
    if params is not None:
        extra = (params[0],)
        taken |= {x.name for x in params[0]}
    W = _Writer(taken)
    links, origins = _links(chain)
    poses = [_joint_pose(W, link, q[i], i + 1) for i, link in enumerate(links)]
    bodies: Sequence[_Body | _Params]
    bodies = _bodies(chain, origins) if params is None else _parametric_bodies(W, params[1], origins)
    if what == "mass_matrix":
        H = _crba(W, links, bodies, poses)
        return Program((q, *extra), _live(W.assigns, H), H, "H")
    zero = [S.Zero] * n
    args: tuple[ImmutableMatrix, ...]
    if what == "gravity":
        args, u, a = (q,), zero, zero
    elif what == "coriolis":
        args, u, a, g = (q, qd), list(qd), zero, ImmutableMatrix([0, 0, 0])
    elif what == "bias":
        args, u, a = (q, qd), list(qd), zero
    else:
        args, u, a = (q, qd, qdd), list(qd), list(qdd)
    tau = _rnea(W, links, bodies, poses, u, a, _col(-g))
    return Program(args + extra, _live(W.assigns, tau), tau, "tau")


def _live(assigns: list[tuple[Symbol, Expr]], outputs: ImmutableMatrix) -> tuple[tuple[Symbol, Expr], ...]:
    """The assignments the outputs need, in order (the rest is dead code: e.g. the base's reaction)."""
    needed = set(outputs.free_symbols)
    kept = []
    for t, e in reversed(assigns):
        if t in needed:
            kept.append((t, e))
            needed |= e.free_symbols
    return tuple(reversed(kept))


def _forward(W: _Writer, links: list[_Link], poses: list[Any], qd: Sequence[Expr],
             qdd: Sequence[Expr], a0: Vec) -> list[tuple[Vec, Vec, Vec]]:
    """Each link's ``(w, dw, a)`` in ``{i}``: angular velocity and acceleration, its origin's acceleration."""
    zero = (S.Zero, S.Zero, S.Zero)
    w, dw, a = zero, zero, a0
    motions = []
    for i, (link, (R, p)) in enumerate(zip(links, poses, strict=True)):
        k = i + 1
        # the origin o_i: a + dw x p + w x (w x p), with p its place in {i-1}
        wp = W.vec(_cross(w, p), f"wp{k}")
        a = _add(a, _cross(dw, p), _cross(w, wp))
        wr = W.vec(_matT(R, w), f"wr{k}")  # w_{i-1} in {i}
        # slides along the joint: v' qdd + 2 (R^T w_{i-1}) x v' qd
        a = W.vec(_add(_matT(R, W.vec(a, f"ap{k}")), _scale(qdd[i], link.v),
                       _scale(2 * qd[i], _cross(wr, link.v))), f"a{k}")
        dw = W.vec(_add(_matT(R, dw), _scale(qdd[i], link.w), _scale(qd[i], _cross(wr, link.w))),
                   f"dw{k}")
        w = W.vec(_add(wr, _scale(qd[i], link.w)), f"w{k}")
        motions.append((w, dw, a))
    return motions


def _rnea(W: _Writer, links: list[_Link], bodies: Sequence[_Body | _Params], poses: list[Any],
          qd: list[Expr], qdd: list[Expr], a0: Vec) -> ImmutableMatrix:
    """Newton–Euler with each link's angular velocity ``w``, angular acceleration ``dw`` and
    the acceleration ``a`` of its origin, in ``{i}`` (module docstring)."""
    n = len(links)
    zero = (S.Zero, S.Zero, S.Zero)
    motions = _forward(W, links, poses, qd, qdd, a0)
    tau: list[Expr] = [S.Zero] * n
    f, C = zero, zero
    for i in reversed(range(n)):
        k = i + 1
        w, dw, a = motions[i]
        b = bodies[i]
        wh = W.vec(_cross(w, b.h), f"wh{k}")
        fi = W.vec(_add(_scale(b.m, a), _cross(dw, b.h), _cross(w, wh)), f"fb{k}")
        if isinstance(b, _Params):  # about o_i: C = I_O dw + w x (I_O w) + h x a
            Iw = W.vec(_mat(b.I, w), f"Iw{k}")
            Ci = _add(_mat(b.I, dw), _cross(w, Iw), _cross(b.h, a))
        elif all(b.I[r][c] == 0 for r in range(3) for c in range(3) if r != c):
            Iw = _mat(b.I, w)  # inline: w x (I w) collects to (I_zz - I_yy) w_y w_z, ...
        else:
            Iw = W.vec(_mat(b.I, w), f"Iw{k}")
        if not isinstance(b, _Params):
            Ci = _add(_mat(b.I, dw), _cross(w, Iw), _cross(b.c, fi))
        if i + 1 < n:  # the wrench of links i+2.., carried from {i+1} into {i}
            R, p = poses[i + 1]
            f = W.vec(_mat(R, f), f"Rf{k + 1}_")
            C = _add(_mat(R, C), _cross(p, f))
        f = W.vec(_add(fi, f), f"f{k}")
        C = W.vec(_add(Ci, C), f"C{k}")
        tau[i] = W.let(_dot(links[i].w, C) + _dot(links[i].v, f), f"tau{k}")
    return ImmutableMatrix(tau)


def _crba(W: _Writer, links: list[_Link], bodies: Sequence[_Body | _Params],
          poses: list[Any]) -> ImmutableMatrix:
    """Composite rigid bodies in the frames ``{i}``: ``(m, h, I_O)`` of links ``i..n`` in ``{i}``."""
    n = len(links)
    H: list[list[Expr]] = [[S.Zero] * n for _ in range(n)]
    comp = None
    for j in reversed(range(n)):
        k = j + 1
        b = bodies[j]
        I_O: Any = _inertia_about_origin(b)
        m, h = b.m, b.h
        if comp is not None:
            R, p = poses[j + 1]
            m2, h2, I2 = comp
            Rh = W.vec(_mat(R, h2), f"Rh{k + 1}_")
            RI = [_mat(R, [I2[0][c], I2[1][c], I2[2][c]]) for c in range(3)]  # columns of R I
            RI = [W.vec(col, f"RI{k + 1}_{c}") for c, col in enumerate(RI)]
            RIRt = [[_dot([RI[0][r], RI[1][r], RI[2][r]], R[s]) for s in range(3)] for r in range(3)]
            # - [Rh]x [p]x - [p]x [Rh]x - m [p]x^2 = (Rh.p + m p.p) 1 - Rh p^T - p Rh^T - m p p^T
            mp = W.vec(_scale(m2, p), f"mp{k + 1}_")
            s = W.let(_dot(Rh, p) * 2 + _dot(mp, p), f"sp{k + 1}")
            extra = [[(s if r == c else 0) - Rh[r] * p[c] - p[r] * Rh[c] - mp[r] * p[c]
                      for c in range(3)] for r in range(3)]
            m = W.let(m + m2, f"mc{k}")
            h = W.vec(_add(h, Rh, mp), f"hc{k}_")
            I_O = tuple(tuple(I_O[r][c] + RIRt[r][c] + extra[r][c] for c in range(3)) for r in range(3))
        I_O = tuple(tuple(W.let(I_O[r][c], f"Ic{k}_{'xyz'[min(r, c)]}{'xyz'[max(r, c)]}")
                          for c in range(3)) for r in range(3))
        comp = (m, h, I_O)
        # F = I^c_j $_j: f = m v - h x w, C = I_O w + h x v
        link = links[j]
        f = W.vec(_add(_scale(m, link.v), _cross(link.w, h)), f"F{k}f")
        C = W.vec(_add(_mat(I_O, link.w), _cross(h, link.v)), f"F{k}C")
        for i in reversed(range(j + 1)):
            if i < j:
                R, p = poses[i + 1]
                f = W.vec(_mat(R, f), f"F{k}f{i + 1}_")
                C = W.vec(_add(_mat(R, C), _cross(p, f)), f"F{k}C{i + 1}_")
            H[i][j] = H[j][i] = W.let(_dot(links[i].w, C) + _dot(links[i].v, f), f"H{i + 1}{k}")
    return ImmutableMatrix(H)


def _inertia_about_origin(b: _Body | _Params) -> Any:
    """``I_c - m [c]x^2 = I_c + m (c.c 1 - c c^T)``."""
    if isinstance(b, _Params):
        return b.I
    cc = _dot(b.c, b.c)
    return tuple(tuple(b.I[r][c] + b.m * ((cc if r == c else 0) - b.c[r] * b.c[c])  # type: ignore[misc]
                       for c in range(3)) for r in range(3))


WHAT = ("inverse_dynamics", "mass_matrix", "gravity", "coriolis", "bias")


def dynamics_program(chain: Chain, what: str = "inverse_dynamics", gravity: Any = None, *,
                     armature: Any = None, viscous: Any = None, coulomb: Any = None,
                     parameters: Any = None, extras: Sequence[str] = ()) -> Program:
    r"""The chain's dynamics as a straight-line :class:`Program` (customised Newton–Euler).

    ``what`` is ``"inverse_dynamics"`` (``tau(q, qd, qdd)``, arguments ``q, qd, qdd``),
    ``"mass_matrix"`` (``H(q)`` by composite rigid bodies), ``"gravity"`` (``g(q)``),
    ``"coriolis"`` (``C(q, qd) qd``, without gravity) or ``"bias"`` (``C qd + g``);
    the arguments are the symbols ``q1 .. qn`` (``qd1 ..``, ``qdd1 ..``).
    ``gravity`` as for :func:`screwsym.motion.dynamics.inverse_dynamics`.  The program
    computes exactly the closed forms of :mod:`screwsym.motion.dynamics` (the tests compare
    them, and with pinocchio); its :meth:`Program.operations` are the cost of evaluating it.

    ``armature``, ``viscous``, ``coulomb`` (numbers or symbols, one per joint) add the
    joints' rotor inertia ``Ia qdd`` and friction ``Fv qd + Fc sign(qd)``.

    ``parameters="standard"`` writes the program in the ``10 n`` standard inertial
    parameters (:func:`parameter_symbols`, one more argument) instead of the chain's
    numbers: the Newton–Euler recursion in the parameters about each link's origin
    (``tau = Y pi`` identically); ``extras`` (among ``"armature", "viscous", "coulomb"``)
    adds the joints' rotor inertia and friction as parameters too, and the chain needs no
    inertias.  ``parameters`` may also be a pair ``(symbols, values)``: the argument's
    symbols and the standard parameters (with the extras') as expressions in them, linear.
    In the *base* parameters: ``Chain.dynamics_program(what, parameters="base")``
    (:func:`screwsym.motion.parameters.base_program`, which gives the pair).

    >>> from screwsym import Chain, SpatialInertia, Twist
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])],
    ...             inertias=[SpatialInertia.point_mass(1, [1, 0, 0]),
    ...                       SpatialInertia.point_mass(1, [2, 0, 0])])
    >>> dynamics_program(arm, "mass_matrix").expressions()
    Matrix([
    [2*cos(q2) + 3, cos(q2) + 1],
    [  cos(q2) + 1,           1]])

    In the standard parameters (about the space origin; here at ``q = 0``):

    >>> p = dynamics_program(arm, "gravity", [0, -1, 0], parameters="standard")
    >>> p.evaluate([0, 0], p.arguments[1]).T
    Matrix([[mc_x_1 + mc_x_2, -m_2 + mc_x_2]])
    """
    what = check_choice(what, "what", WHAT)
    n = chain.n_joints if hasattr(chain, "n_joints") else 0
    joint_terms = (("armature", armature), ("viscous", viscous), ("coulomb", coulomb))
    if parameters is None:
        if extras:
            raise ValueError("extras: the joints' terms as parameters need parameters='base' or "
                             "'standard'; with the chain's numbers give armature=, viscous=, coulomb=")
        p = _program(chain, what, gravity)
        terms = {name: None if v is None else [check_scalar(x, f"{name}[{i}]") for i, x in
                                               enumerate(check_sequence(v, name, "joint values", n))]
                 for name, v in joint_terms}
    else:
        for name, v in joint_terms:
            if v is not None:
                raise ValueError(f"{name}: with parameters the joints' terms are parameters "
                                 f"too: give extras=[{name!r}, ...] instead")
        chosen = _extras(extras)
        symbols, values = _parameter_inputs(chain, parameters, chosen)
        p = _program(chain, what, gravity, (symbols, values))
        terms = {name: None if name not in chosen else
                 [values[10 * n + i * len(chosen) + chosen.index(name)] for i in range(n)]
                 for name, _ in joint_terms}
    if all(v is None for v in terms.values()):
        return p
    out = p.outputs.as_mutable()
    if what == "mass_matrix":
        for i in range(n):
            out[i, i] += (terms["armature"] or [0] * n)[i]
        return Program(p.arguments, p.assignments, ImmutableMatrix(out), p.name)
    if what in ("inverse_dynamics", "bias"):
        qd = p.arguments[1]
        for i in range(n):
            if terms["armature"] and what == "inverse_dynamics":
                out[i] += terms["armature"][i] * p.arguments[2][i]
            if terms["viscous"]:
                out[i] += terms["viscous"][i] * qd[i]
            if terms["coulomb"]:
                out[i] += terms["coulomb"][i] * sign(qd[i])
    return Program(p.arguments, p.assignments, ImmutableMatrix(out), p.name)


def _parameter_inputs(chain: Chain, parameters: Any,
                      extras: tuple[str, ...]) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    """The program's parameter argument and the standard parameters' values in it."""
    if not hasattr(chain, "twists") or not hasattr(chain, "n_joints"):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    pi = parameter_symbols(chain.n_joints, extras)
    if isinstance(parameters, tuple) and len(parameters) == 2:
        symbols, values = (ImmutableMatrix(x) for x in parameters)
        if len(values) != len(pi) or not all(isinstance(x, Symbol) for x in symbols):
            raise ValueError(f"parameters: expected (symbols, values) with {len(pi)} values")
    elif parameters == "standard":
        symbols, values = pi, pi
    else:
        raise ValueError(f"parameters: expected 'standard' or (symbols, values), got {parameters!r} "
                         "(the base parameters: Chain.dynamics_program(..., parameters='base'))")
    clash = {x.name for x in symbols} & {s.name for s in chain.free_symbols}
    if clash:
        raise ValueError(f"chain: its symbols {sorted(clash)} have the names of inertial parameters")
    return symbols, values


#: the optional joint terms: rotor inertia ``Ia qdd``, viscous ``Fv qd`` and Coulomb ``Fc sign(qd)``
#: friction (SYMORO's ``IA``, ``FV``, ``FS``; pinocchio's ``armature`` and friction)
EXTRAS = {"armature": "Ia", "viscous": "Fv", "coulomb": "Fc"}


def _extras(extras: Any) -> tuple[str, ...]:
    if isinstance(extras, str) or not isinstance(extras, (list, tuple)):
        raise TypeError(f"extras: expected a list of names among {list(EXTRAS)}, got {extras!r}")
    for e in extras:
        check_choice(e, "extras", tuple(EXTRAS))
    return tuple(e for e in EXTRAS if e in extras)


def parameter_symbols(n: int, extras: Sequence[str] = ()) -> ImmutableMatrix:
    """The symbols ``m_i, mc_x_i, ..., I_zz_i`` of links ``1 .. n``, a column (the regressor's order).

    With ``extras`` (names among ``"armature", "viscous", "coulomb"``), then ``Ia_i``,
    ``Fv_i``, ``Fc_i`` of each joint in turn, after the ``10 n``.

    >>> parameter_symbols(1, ["viscous"]).T
    Matrix([[m_1, mc_x_1, mc_y_1, mc_z_1, I_xx_1, I_xy_1, I_yy_1, I_xz_1, I_yz_1, I_zz_1, Fv_1]])
    """
    chosen = _extras(extras)
    return ImmutableMatrix([Symbol(f"{name}_{i + 1}", real=True)
                            for i in range(n) for name in PARAMETER_NAMES]
                           + [Symbol(f"{EXTRAS[e]}_{i + 1}", real=True)
                              for i in range(n) for e in chosen])


def _link_parameters(pi: list[Symbol], o: Any) -> tuple[Any, Any, Any]:
    """``(m, h, I)`` about ``o`` (frame parallel to the space frame) from the standard ten about the origin.

    ``h' = h - m o``, ``I' = I + [h]x [o]x + [o]x [h]x - m [o]x^2`` (parallel axes, linear).
    """
    m, hx, hy, hz, xx, xy, yy, xz, yz, zz = pi
    h = ImmutableMatrix([hx, hy, hz])
    I = ImmutableMatrix([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    o = ImmutableMatrix(o)

    def skew(v: Any) -> ImmutableMatrix:
        return ImmutableMatrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])

    H, Oo = skew(h), skew(o)
    I2 = (I + H * Oo + Oo * H - m * Oo * Oo).applyfunc(lambda x: x.expand())
    return m, _col((h - m * o).applyfunc(lambda x: x.expand())), tuple(_col(I2[r, :].T) for r in range(3))


def regressor_program(chain: Chain, gravity: Any = None, extras: Sequence[str] = ()) -> Program:
    r"""The regressor ``Y(q, qd, qdd)`` (n x 10n) as a straight-line program (Newton–Euler).

    The same matrix as :func:`screwsym.motion.dynamics.regressor` (the tests compare them):
    for each link the wrench of each parameter, written in the frames of
    :mod:`screwsym.motion.newton_euler` and carried down to the joints.  Only the chain's
    kinematics enter.  With ``extras`` (among ``"armature", "viscous", "coulomb"``), the
    columns ``qdd_i``, ``qd_i``, ``sign(qd_i)`` of the joints' rotor inertia and friction
    follow, in the order of :func:`parameter_symbols`.  Cached per chain, gravity and extras.

    >>> from sympy import symbols
    >>> from screwsym import Chain, Twist
    >>> hinge = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])])
    >>> regressor_program(hinge, gravity=[0, 0, 0]).expressions()
    Matrix([[0, 0, 0, 0, 0, 0, 0, 0, 0, qdd1]])
    """
    if not hasattr(chain, "twists") or not hasattr(chain, "n_joints"):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    return _regressor_program(chain, _gravity(gravity), _extras(extras))


@lru_cache(maxsize=32)
def _regressor_program(chain: Chain, g: ImmutableMatrix, extras: tuple[str, ...]) -> Program:
    n = chain.n_joints
    q, qd, qdd = (ImmutableMatrix([Symbol(f"{s}{i + 1}", real=True) for i in range(n)])
                  for s in ("q", "qd", "qdd"))
    pi = list(parameter_symbols(n, extras))
    taken = {s.name for s in chain.free_symbols | g.free_symbols} | {
        x.name for m in (q, qd, qdd) for x in m} | {p.name for p in pi}
    W = _Writer(taken)
    links, origins = _links(chain)
    poses = [_joint_pose(W, link, q[i], i + 1) for i, link in enumerate(links)]
    motions = _forward(W, links, poses, list(qd), list(qdd), _col(-g))
    Y: list[list[Any]] = [[S.Zero] * (10 * n) for _ in range(n)]
    for j in range(n):
        w, dw, a = motions[j]
        block = pi[10 * j:10 * j + 10]
        m, h, I = _link_parameters(block, origins[j])
        # the origin form: f = m a + dw x h + w x (w x h), C = I dw + w x (I w) + h x a
        f = _add([m * x for x in a], _cross(dw, h), _cross(w, _cross(w, h)))
        C = _add(_mat(I, dw), _cross(w, _mat(I, w)), _cross(h, a))
        for k, p in enumerate(block):
            col = 10 * j + k
            fk = W.vec([x.expand().coeff(p) for x in f], f"Yf{j + 1}_{k}_")
            Ck = W.vec([x.expand().coeff(p) for x in C], f"YC{j + 1}_{k}_")
            for i in reversed(range(j + 1)):
                if i < j:
                    R, pp = poses[i + 1]
                    fk = W.vec(_mat(R, fk), f"Yf{j + 1}_{k}_{i + 1}")
                    Ck = W.vec(_add(_mat(R, Ck), _cross(pp, fk)), f"YC{j + 1}_{k}_{i + 1}")
                Y[i][col] = W.let(_dot(links[i].w, Ck) + _dot(links[i].v, fk), f"Y{i + 1}_{col + 1}")
    term = {"armature": lambda i: qdd[i], "viscous": lambda i: qd[i], "coulomb": lambda i: sign(qd[i])}
    for i in range(n):
        Y[i].extend(term[e](i) if j == i else S.Zero for j in range(n) for e in extras)
    out = ImmutableMatrix(Y)
    return Program((q, qd, qdd), _live(W.assigns, out), out, "Y")


