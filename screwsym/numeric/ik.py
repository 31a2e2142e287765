r"""Inverse kinematics as a fast numeric function: every closed-form branch at many poses at once.

:func:`inverse_kinematics_function` compiles the closed forms of
:func:`screwsym.motion.inverse_kinematics.stage_forms` into one straight-line program
(:class:`_Program`) through :func:`screwsym.lambdify`: the target pose from ``T`` (and the
free joints), then stage by stage, for every branch of the stages before, the points the
stage's subproblem looks at and its generic branches (two solutions of Subproblems 2, 3
and 4, the angle of Subproblem 1), each stage's expressions of all branches through one
common-subexpression elimination and every sine and cosine of a joint computed once.
Compiled in C (where a compiler is found; numba or NumPy otherwise) this is one loop over
the poses: the UR5's eight branches in about 1.5 us a pose (``benchmarks/bench_ik.py``).
The result holds every generic branch: ``(..., B, n)``, ``B = 8`` for the UR5 and the
PUMA 560.  A branch that does not exist at a pose (a negative discriminant: the pose out of
reach for that branch) is NaN in all its joints, since the square root of a negative
number is NaN in every back end.  The degenerate branches (a wrist or shoulder
singularity, a tangent) hold on sets of measure zero and are left to the exact
:func:`~screwsym.motion.inverse_kinematics.inverse_kinematics`.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np
from sympy import (
    Abs,
    Add,
    Dummy,
    Eq,
    Float,
    ImmutableMatrix,
    Lt,
    Mul,
    Piecewise,
    cos,
    cse,
    floor,
    numbered_symbols,
    pi,
    sin,
)

from ..codegen import compiler, default_backend, lambdify
from ..motion.chain import Chain
from ..motion.inverse_kinematics import (
    G,
    Motion,
    Q,
    free_values,
    motion_exp,
    motion_inverse,
    motion_product,
    stage_forms,
)

__all__ = ["fastest_backend", "inverse_kinematics_function"]


def _generic(branches: Any) -> list:
    """The branches of positive measure: no free parameter, no equality in the condition."""
    return [b for b in branches
            if not any(v.is_Dummy for v in b.values) and not b.condition.atoms(Eq)]


def _exp_numeric(twist: Any, q: np.ndarray) -> np.ndarray:
    """``exp6(twist, q)`` as ``(..., 4, 4)`` float arrays (Rodrigues; a translation for omega = 0)."""
    w = np.array(twist.omega, dtype=float).ravel()
    v = np.array(twist.v_O, dtype=float).ravel()
    out = np.zeros(q.shape + (4, 4))
    out[..., 3, 3] = 1
    if not w.any():
        out[..., :3, :3] = np.eye(3)
        out[..., :3, 3] = q[..., None] * v
        return out
    n = np.linalg.norm(w)
    k, th = w / n, q * n
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    s, c = np.sin(th)[..., None, None], np.cos(th)[..., None, None]
    R = np.eye(3) + s * K + (1 - c) * (K @ K)
    r = np.cross(w, v) / (w @ w)
    h = (w @ v) / (w @ w)
    out[..., :3, :3] = R
    out[..., :3, 3] = (np.eye(3) - R) @ r + (h * q * n)[..., None] * k
    return out


def _inverse_numeric(T: np.ndarray) -> np.ndarray:
    out = np.zeros_like(T)
    Rt = np.swapaxes(T[..., :3, :3], -1, -2)
    out[..., :3, :3] = Rt
    out[..., :3, 3] = -(Rt @ T[..., :3, 3:])[..., 0]
    out[..., 3, 3] = 1
    return out


def _solved(chain: Chain, free: tuple[int, ...]) -> list[int]:
    """The joints the solver finds (``free`` given at call time): a run of consecutive ones."""
    n = chain.n_joints
    solved = [i for i in range(n) if i not in free]
    if solved != list(range(solved[0], solved[0] + len(solved))):
        raise ValueError(f"free: the compiled solver takes free joints at the ends of the chain "
                         f"(its first or last joints), got {sorted(free)}; "
                         "screwsym.motion.inverse_kinematics takes any")
    return solved


class _Program:
    """Every generic branch as one straight-line program of the pose (and the free joints).

    The assignments, in order: the target ``g`` (the pose times the home pose's inverse,
    the free joints' motions taken off, inverted for a reversed decomposition); then per
    stage, per branch of the stages before (a prefix), the points its subproblem looks at
    and the joint values of its branches, each stage's expressions of all prefixes through
    one ``sympy.cse``, so that what the prefixes share (the pose's products, a sine of a
    joint found before) is computed once.  The outputs ``(B, n)``: revolute joints wrapped
    into ``[-pi, pi)`` and a branch NaN in every joint where one of its joints is NaN (the
    sum of its joints is not finite).  Every symbol is a ``Dummy`` of this module; the
    numbers come from the chain's twists and home pose; :func:`screwsym.lambdify` renames
    everything before it prints (no user text reaches generated source).
    """

    def __init__(self, chain: Chain, free: tuple[int, ...]):
        n = chain.n_joints
        solved = _solved(chain, free)
        before, after = solved[0], solved[-1] + 1
        self.T = ImmutableMatrix(4, 4, [Dummy(f"ik_T{i}{j}", real=True) for i in range(4) for j in range(4)])
        self.F = ImmutableMatrix([Dummy(f"ik_f{k}", real=True) for k in free]) if free else None
        self.assignments: list[tuple[Dummy, Any]] = []
        self._trig: dict[Any, Any] = {}
        self._squares: dict[Any, Any] = {}
        H = chain.home.inverse()
        g: Motion = motion_product((self.T[:3, :3], self.T[:3, 3]), (H.R, H.p))
        fv = dict(zip(free, self.F if self.F is not None else (), strict=True))
        for i in sorted((i for i in free if i >= after), reverse=True):
            g = motion_product(g, motion_inverse(motion_exp(chain.twists[i], fv[i])))
        for i in sorted(i for i in free if i < before):
            g = motion_product(motion_inverse(motion_exp(chain.twists[i], fv[i])), g)
        plan, forms = stage_forms(tuple(chain.twists[i] for i in solved))
        if plan.reversed:
            g = motion_inverse(g)
        order = list(reversed(solved)) if plan.reversed else solved
        gs = self._let([*g[0], *g[1]], "g")
        pose = dict(zip(G, gs, strict=True))
        prefixes: list[dict[int, Any]] = [{}]
        for k, form in enumerate(forms):
            generic = _generic(form.branches)
            points = [form.points.xreplace({**pose, **{Q[j]: v for j, v in p.items()}})
                      for p in prefixes]
            xs = self._let([x for m in points for x in m], f"x{k}_")
            size = len(form.symbols)
            values = []
            for m, _p in enumerate(prefixes):
                at = dict(zip(form.symbols, xs[m * size:(m + 1) * size], strict=True))
                values += [v.xreplace(at) for b in generic for v in b.values]
            qs = self._let(values, f"q{k}_")
            width = len(form.stage.joints)
            grown = []
            for m, p in enumerate(prefixes):
                for b in range(len(generic)):
                    got = qs[(m * len(generic) + b) * width:(m * len(generic) + b + 1) * width]
                    grown.append({**p, **dict(zip(form.stage.joints, got, strict=True))})
            prefixes = grown
        revolute = [bool(any(t.omega)) for t in chain.twists]
        rows = []
        for p in prefixes:
            row = {order[j]: v for j, v in p.items()}
            row.update(fv)
            (total,) = self._let([Add(*[row[i] for i in range(n) if i not in fv])], "s")
            exists = Lt(Abs(total), Float(1e300))  # NaN (or inf) in a joint: no branch
            rows.append([Piecewise((row[i] - 2 * pi * floor((row[i] + pi) / (2 * pi)) if revolute[i]
                                    else row[i], exists))
                         for i in range(n)])
        self.outputs = ImmutableMatrix(rows)
        self.arguments = [self.T] if self.F is None else [self.T, self.F]

    def _let(self, exprs: list, stem: str) -> list:
        """``exprs`` as symbols assigned after their common subexpressions (numbers stay).

        Before the stage's ``cse``, a sine or cosine of a symbol assigned before becomes
        the symbol assigned to it once for the whole program (the stages' ``cse`` are
        separate, and C does not merge two calls of ``sin``), and each integer power
        above 2 a product of squares (C's ``pow(x, 4.0)`` is a library call)."""
        exprs = [self._shared(e) for e in exprs]
        replacements, reduced = cse(exprs, symbols=numbered_symbols(f"ik_{stem}c", cls=Dummy, real=True))
        replacements = [(t, self._powers(e)) for t, e in replacements]
        reduced = [self._powers(e) for e in reduced]
        self.assignments += replacements
        out = []
        for m, e in enumerate(reduced):
            if e.is_Atom:
                out.append(e)
            else:
                t = Dummy(f"ik_{stem}{m}", real=True)
                self.assignments.append((t, e))
                out.append(t)
        return out

    def _shared(self, e: Any) -> Any:
        found = {x for x in e.atoms(sin, cos) if x.args[0].is_Symbol}
        for x in sorted(found, key=str):
            if x not in self._trig:
                t = Dummy(f"ik_trig{len(self._trig)}", real=True)
                self.assignments.append((t, x))
                self._trig[x] = t
        return e.xreplace({x: self._trig[x] for x in found}) if found else e

    def _powers(self, e: Any) -> Any:
        def square(b: Any) -> Any:
            t = self._squares.get(b)
            if t is None:
                t = self._squares[b] = Dummy(f"ik_sq{len(self._squares)}", real=True)
                self.assignments.append((t, b**2))
            return t

        def power(x: Any) -> Any:
            if not (x.is_Pow and x.exp.is_Integer and x.exp > 2):
                return x
            n, b = int(x.exp), x.base
            return Mul(*([square(b)] * (n // 2) + [b] * (n % 2)))

        return e.replace(lambda x: x.is_Pow and x.exp.is_Integer and x.exp > 2, power)

    def _lambdify_program(self) -> tuple[tuple[tuple[Any, Any], ...], ImmutableMatrix]:
        return tuple(self.assignments), self.outputs


class _Staged:
    """The stages of one chain compiled one by one and evaluated in turn on arrays.

    The solver before the fused program (:func:`_fused`): kept to compare against
    (``benchmarks/bench_ik.py``, the tests).
    """

    def __init__(self, chain: Chain, free: tuple[int, ...], backend: str | None):
        n = chain.n_joints
        solved = _solved(chain, free)
        self.n, self.before, self.after = n, solved[0], solved[-1] + 1
        twists = tuple(chain.twists[i] for i in solved)
        self.twists = chain.twists
        self.home_inv = np.array(chain.home.inverse().matrix, dtype=float)
        plan, forms = stage_forms(twists)
        self.reversed = plan.reversed
        order = list(reversed(solved)) if plan.reversed else solved
        self.stages = []
        for form in forms:
            generic = _generic(form.branches)
            prep = lambdify([G, Q], form.points, backend)
            values = ImmutableMatrix([v for b in generic for v in b.values])
            solve = lambdify([form.symbols], values, backend)
            self.stages.append((form.stage.joints, len(generic), prep, solve))
        self.order = order
        self.revolute = [bool(np.any(np.array(t.omega, dtype=float))) for t in chain.twists]
        self.width = int(np.prod([k for _, k, _, _ in self.stages]))

    def __call__(self, T: Any, free_values: Any = None) -> np.ndarray:
        T = np.asarray(T, dtype=float)
        if T.shape[-2:] != (4, 4):
            raise ValueError(f"T: expected poses of shape (..., 4, 4), got {T.shape}")
        batch = T.shape[:-2]
        T = T.reshape(-1, 4, 4)
        k = self.n - (self.after - self.before)
        if k:
            if free_values is None:
                raise TypeError(f"free_values: expected the values of the {k} free joints, (..., {k})")
            f = np.broadcast_to(np.asarray(free_values, dtype=float), batch + (k,)).reshape(-1, k)
        else:
            f = np.zeros((T.shape[0], 0))
        given = [i for i in range(self.n) if not self.before <= i < self.after]
        g = T @ self.home_inv
        for j, i in reversed(list(enumerate(given))):
            if i >= self.after:
                g = g @ _inverse_numeric(_exp_numeric(self.twists[i], f[:, j]))
        for j, i in enumerate(given):
            if i < self.before:
                g = _inverse_numeric(_exp_numeric(self.twists[i], f[:, j])) @ g
        if self.reversed:
            g = _inverse_numeric(g)
        N = g.shape[0]
        gv = np.concatenate([g[:, :3, :3].reshape(N, 9), g[:, :3, 3]], axis=1)
        q = np.zeros((N, 1, 6))
        for joints, nb, prep, solve in self.stages:
            B = q.shape[1]
            points = prep(gv[:, None, :], q)
            vals = np.asarray(solve(points)).reshape(N, B, nb, len(joints))
            q = np.repeat(q[:, :, None, :], nb, axis=2)
            q[..., list(joints)] = vals
            q = q.reshape(N, B * nb, 6)
        out = np.empty((N, q.shape[1], self.n))
        if self.order == list(range(self.before, self.after)) and not given:
            out[...] = q
        else:
            out[..., self.order] = q
        for j, i in enumerate(given):
            out[..., i] = f[:, None, j]
        out[np.isnan(out.sum(axis=-1))] = np.nan  # a branch missing a joint does not exist
        if all(self.revolute):  # angles into (-pi, pi], in place
            out += np.pi
            np.mod(out, 2 * np.pi, out=out)
            out -= np.pi
        else:
            turn = np.array(self.revolute)
            out[..., turn] = np.mod(out[..., turn] + np.pi, 2 * np.pi) - np.pi
        return out.reshape(batch + out.shape[1:])


@lru_cache(maxsize=16)
def _staged(chain: Chain, free: tuple[int, ...], backend: str | None) -> _Staged:
    return _Staged(chain, free, backend)


class _GivenFree:
    """The compiled program of a chain with free joints: ``f(T, free_values)``, a scalar for one."""

    def __init__(self, fn: Any, k: int):
        self.fn, self.k = fn, k

    def __call__(self, T: Any, free_values: Any = None) -> np.ndarray:
        if free_values is None:
            raise TypeError(f"free_values: expected the values of the {self.k} free joints, (..., {self.k})")
        if self.k == 1 and np.ndim(free_values) == 0:
            free_values = np.reshape(np.asarray(free_values, dtype=float), (1,))
        return self.fn(T, free_values)


@lru_cache(maxsize=16)
def _fused(chain: Chain, free: tuple[int, ...], backend: str) -> Any:
    program = _Program(chain, free)
    if program.F is None:
        return lambdify(program.arguments, program, backend, names=["T"])
    return _GivenFree(lambdify(program.arguments, program, backend, names=["T", "free_values"]), len(free))


def fastest_backend() -> str:
    """``"c"`` where a C compiler is found, else ``"numba"`` where installed, else ``"numpy"``.

    >>> fastest_backend() in ("c", "numba", "numpy")
    True
    """
    return "c" if compiler() is not None else default_backend()


def inverse_kinematics_function(chain: Chain, free: Any = (), backend: str | None = None) -> Any:
    r"""A function ``f(T[, free_values])`` giving every generic branch at many poses: ``(..., B, n)``.

    ``T`` is an array of poses ``(..., 4, 4)``; the result holds, per pose, the ``B``
    generic branches of the closed form (see the module docstring), revolute joints in
    ``[-pi, pi)``, NaN in every joint of a branch that does not exist.  ``free`` are joint
    indices given at call time as ``free_values`` ``(..., k)`` (broadcast against the
    poses); the compiled solver takes those at the ends of the chain (the Panda's seventh
    joint).  All branches are one generated program (:class:`_Program`), one loop over
    the poses; ``backend`` as for :func:`screwsym.lambdify`, by default the fastest
    there is (:func:`fastest_backend`: C where a compiler is found).  One pose
    ``(4, 4)`` takes the back end's one-point path (NumPy's: the program on Python floats,
    a branch that does not exist NaN there too; 44 us for the UR5 against 1.4 ms on the
    array code, ``benchmarks/bench_ik.py``).  Cached per chain, ``free`` and back end.

    >>> import numpy as np
    >>> from screwsym.motion.chain import ur5
    >>> arm = ur5()
    >>> f = inverse_kinematics_function(arm, backend="numpy")
    >>> q = np.array([0.3, -1.2, 1.5, -0.4, 1.1, 0.7])
    >>> T = np.array(arm.forward(list(q)).matrix, dtype=float)
    >>> branches = f(T)
    >>> branches.shape
    (8, 6)
    >>> bool(np.isclose(branches, q).all(axis=1).any())
    True
    >>> far = T.copy(); far[:3, 3] = [5, 0, 0]          # 5 m away: out of reach
    >>> bool(np.isnan(f(far)).all())
    True
    >>> f(np.stack([T, far])).shape                     # a batch of poses
    (2, 8, 6)
    """
    if not isinstance(chain, Chain):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    given = tuple(sorted(free_values(free if not isinstance(free, dict) else list(free), chain.n_joints)))
    _solved(chain, given)
    return _fused(chain, given, fastest_backend() if backend is None else backend)
