r"""Inverse kinematics as a fast numeric function: every closed-form branch at many poses at once.

:func:`inverse_kinematics_function` compiles the closed forms of
:func:`screwsym.motion.inverse_kinematics.stage_forms` through :func:`screwsym.lambdify`:
per stage, the points its subproblem looks at (from the pose and the joints found before)
and the subproblem's generic branches (two solutions of Subproblems 2, 3 and 4, the
angle of Subproblem 1).  The stages are evaluated in turn on arrays, each branch of a
stage multiplying the columns, so the result holds every generic branch: ``(..., B, n)``,
``B = 8`` for the UR5 and the PUMA 560.  A branch that does not exist at a pose (a
negative discriminant: the pose out of reach for that branch) is NaN there, since the
square root of a negative number is NaN in every back end.  The degenerate branches
(a wrist or shoulder singularity, a tangent) hold on sets of measure zero and are left
to the exact :func:`~screwsym.motion.inverse_kinematics.inverse_kinematics`.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np
from sympy import Eq, ImmutableMatrix

from ..codegen import lambdify
from ..motion.chain import Chain
from ..motion.inverse_kinematics import G, Q, free_values, stage_forms

__all__ = ["inverse_kinematics_function"]


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


def _inverse(T: np.ndarray) -> np.ndarray:
    out = np.zeros_like(T)
    Rt = np.swapaxes(T[..., :3, :3], -1, -2)
    out[..., :3, :3] = Rt
    out[..., :3, 3] = -(Rt @ T[..., :3, 3:])[..., 0]
    out[..., 3, 3] = 1
    return out


class _Compiled:
    """The compiled stages of one chain (see :func:`inverse_kinematics_function`)."""

    def __init__(self, chain: Chain, free: tuple[int, ...], backend: str | None):
        n = chain.n_joints
        given = free_values(list(free), n)
        solved = [i for i in range(n) if i not in given]
        if solved != list(range(solved[0], solved[0] + len(solved))):
            raise ValueError(f"free: the compiled solver takes free joints at the ends of the chain "
                             f"(its first or last joints), got {sorted(given)}; "
                             "screwsym.motion.inverse_kinematics takes any")
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
                g = g @ _inverse(_exp_numeric(self.twists[i], f[:, j]))
        for j, i in enumerate(given):
            if i < self.before:
                g = _inverse(_exp_numeric(self.twists[i], f[:, j])) @ g
        if self.reversed:
            g = _inverse(g)
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
def _compiled(chain: Chain, free: tuple[int, ...], backend: str | None) -> _Compiled:
    return _Compiled(chain, free, backend)


def inverse_kinematics_function(chain: Chain, free: Any = (), backend: str | None = None) -> Any:
    r"""A function ``f(T[, free_values])`` giving every generic branch at many poses: ``(..., B, n)``.

    ``T`` is an array of poses ``(..., 4, 4)``; the result holds, per pose, the ``B``
    generic branches of the closed form (see the module docstring), revolute joints in
    ``(-pi, pi]``, NaN where a branch does not exist.  ``free`` are joint indices given
    at call time as ``free_values`` ``(..., k)``; the compiled solver takes those at the
    ends of the chain (the Panda's seventh joint).  ``backend`` as for
    :func:`screwsym.lambdify`.  Cached per chain, ``free`` and back end.

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
    """
    if not isinstance(chain, Chain):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    given = tuple(sorted(free_values(free if not isinstance(free, dict) else list(free), chain.n_joints)))
    return _compiled(chain, given, backend)
