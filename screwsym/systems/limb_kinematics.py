r"""The inverse kinematics of a parallel mechanism limb by limb: every limb's joint values at a
platform pose, exact, branch by branch.

A :class:`~screwsym.systems.parallel.Limb` lists its joints at one configuration of the
mechanism, the *reference*; with the platform displaced from there by the rigid motion
``T`` (a 4x4 matrix, or anything with a ``.matrix`` of that shape, as a
:class:`~screwsym.motion.transform.Transform`), each limb is a serial chain from the base to
the platform: its joints' unit twists ``$_1, ..., $_n`` in the limb's order (a universal or a
spherical joint gives its axes in the order of ``Joint.twists``) and

    exp([$_1] q_1) ... exp([$_n] q_n) = T            (the product of exponentials, M = I)

:func:`limb_joint_values` solves it for every limb in closed form, each solution a
:class:`LimbBranch` ``(condition, values)``: the values exist (are real and are a solution)
where the condition holds.  The limbs solved, by their joint twists:

``R-P-R`` and ``R-R-R`` in the plane
    three joints, revolute axes normal to the plane ``z = 0``, prismatic directions in it,
    ``T`` a planar motion (the planar 3-RPR and 3-RRR).  The platform point ``c`` on the
    last axis goes to ``T c``; its distance ``D`` from the first axis ``a`` fixes the
    middle joint: for ``R-P-R`` the quadratic ``|c - a + q_2 u|^2 = D^2`` (two branches
    where its discriminant is positive: the leg pointing at ``T c`` or away from it), for
    ``R-R-R`` the cosine law ``alpha cos q_2 + beta sin q_2 = gamma`` (two branches where
    ``alpha^2 + beta^2 > gamma^2``: elbow one way or the other).  The first joint turns the
    middle point onto ``T c`` (needs ``T c != a``), the last makes up the angle of ``T``.
``U-P-S`` in space
    a universal joint (two axes meeting at ``A``), a prismatic joint, a spherical joint
    (three axes meeting at ``B``): the Gough-Stewart leg.  The spherical joint leaves ``B``
    where it is, so ``|B - A + q_3 d| = |T B - A|`` (two branches, the leg's two signs),
    then the universal joint turns ``B - A + q_3 d`` onto ``T B - A`` (Paden-Kahan
    subproblem 2 on two meeting axes: two branches where the point lies off the two
    axes' cone; Murray, Li & Sastry 1994, Section 3.3) and the spherical joint makes up
    the rotation ``(R_1 R_2)^T R_T = e^{[x] q_4} e^{[y] q_5} e^{[z] q_6}`` (two branches
    where ``|W_13| < 1``, ``W`` that matrix): up to 8 per leg.

On a boundary where a discriminant is zero the two branches meet and are given once (their
condition an ``Eq``).  A numeric pose where a joint is free (``T c = a`` for the planar limbs:
the first joint; ``|W_13| = 1`` for the U-P-S: only ``q_4 + q_6`` is fixed, the spherical
joint's axes 4 and 6 aligned) is refused, not answered partly: a ``ValueError`` says which.
With a symbolic pose those places are excluded by the conditions (``Ne``, ``Lt``) instead.

References
==========

C. M. Gosselin, J. Angeles, *Singularity analysis of closed-loop kinematic chains*, IEEE
Trans. Robot. Autom. 6 (1990) 281-290 (the 3-RRR and its elbow branches).
J.-P. Merlet, *Parallel Robots*, 2nd ed., Springer 2006, Chapter 4 (inverse kinematics).
R. M. Murray, Z. Li, S. S. Sastry, *A Mathematical Introduction to Robotic Manipulation*,
CRC Press 1994, Section 3.3 (the Paden-Kahan subproblems).
"""

from __future__ import annotations

from typing import Any, NamedTuple

from sympy import (
    And,
    Eq,
    Expr,
    Gt,
    ImmutableMatrix,
    Integer,
    Lt,
    Matrix,
    Ne,
    S,
    atan2,
    eye,
    sqrt,
)
from sympy.logic.boolalg import Boolean

from ..algebra.budget import BUDGET, case_budget, charge
from ..core.checks import check_count, check_matrix, describe
from ..core.decide import is_zero

__all__ = ["LimbBranch", "limb_joint_values"]

#: the budget units charged per branch (a few milliseconds of exact arithmetic)
BRANCH_UNITS = 20_000


class LimbBranch(NamedTuple):
    """One solution of a limb: the ``condition`` where it holds and the joint ``values``
    (one per freedom, in the limb's joint order)."""

    condition: Boolean
    values: tuple[Expr, ...]


def _twists(limb: Any) -> list[tuple[ImmutableMatrix, ImmutableMatrix]]:
    return [(ImmutableMatrix(t.args[0]), ImmutableMatrix(t.args[1])) for j in limb.joints for t in j._twists()]


def _pose(pose: Any) -> ImmutableMatrix:
    M = check_matrix(getattr(pose, "matrix", pose), "pose", (4, 4))
    if list(M[3, :]) != [0, 0, 0, 1]:
        raise ValueError(f"pose: expected a rigid motion (last row 0, 0, 0, 1), got {list(M[3, :])}")
    return M


def _cross2(u: Any, v: Any) -> Expr:
    return u[0] * v[1] - u[1] * v[0]


def _dot(u: Any, v: Any) -> Expr:
    return sum((a * b for a, b in zip(u, v, strict=True)), Integer(0))


def _cond(*parts: Boolean) -> Boolean:
    return And(*parts)


def _planar(tw: list, T: ImmutableMatrix, k: int) -> tuple[LimbBranch, ...]:
    """The R-P-R and R-R-R limbs in the plane z = 0 (see the module docstring)."""
    if not all(is_zero(e) for e in (T[0, 2], T[1, 2], T[2, 0], T[2, 1], T[2, 3])) or not is_zero(T[2, 2] - 1):
        raise ValueError(f"pose: limb {k} is planar (the plane z = 0): expected a planar motion, got {T.tolist()}")
    kinds = "".join("R" if not w.is_zero_matrix else "P" for w, _ in tw)
    c, s = T[0, 0], T[1, 0]
    phi = atan2(s, c)

    def axis(i: int) -> tuple[Expr, Matrix]:  # the rate w of the rotation, the point on its axis
        w, v = tw[i]
        return w[2], Matrix([-v[1] / w[2], v[0] / w[2]])

    def moved(p: Matrix) -> Matrix:
        return Matrix([c * p[0] - s * p[1] + T[0, 3], s * p[0] + c * p[1] + T[1, 3]])

    w1, a = axis(0)
    w3, cpt = axis(2)
    g = moved(cpt) - a
    D2 = _dot(g, g)
    if is_zero(D2):
        raise ValueError(f"pose: limb {k}: the last axis comes onto the first: the first joint is free there")
    out = []
    if kinds == "RPR":
        u = Matrix(tw[1][1][:2])
        e = cpt - a
        A_, B_, C_ = _dot(u, u), _dot(e, u), _dot(e, e) - D2
        disc = B_**2 - A_ * C_
        for sign in (1, -1) if not is_zero(disc) else (1,):
            q2 = (-B_ + sign * sqrt(disc)) / A_
            v = e + q2 * u
            theta1 = atan2(_cross2(v, g), _dot(v, g))
            cond = And(Gt(disc, 0) if not is_zero(disc) else Eq(disc, 0), Ne(D2, 0))
            charge(BRANCH_UNITS)
            out.append(LimbBranch(cond, (theta1 / w1, q2, (phi - theta1) / w3)))
    elif kinds == "RRR":
        w2, b = axis(1)
        v, w = b - a, cpt - b
        alpha, beta = _dot(v, w), -_cross2(v, w)
        gamma = (D2 - _dot(v, v) - _dot(w, w)) / 2
        r2 = alpha**2 + beta**2
        disc = r2 - gamma**2
        for sign in (1, -1) if not is_zero(disc) else (1,):
            h = sign * sqrt(disc)
            c2, s2 = (alpha * gamma - beta * h) / r2, (beta * gamma + alpha * h) / r2
            m = v + Matrix([c2 * w[0] - s2 * w[1], s2 * w[0] + c2 * w[1]])
            theta2 = atan2(s2, c2)
            theta1 = atan2(_cross2(m, g), _dot(m, g))
            cond = And(Gt(disc, 0) if not is_zero(disc) else Eq(disc, 0), Ne(D2, 0), Ne(r2, 0))
            charge(BRANCH_UNITS)
            out.append(LimbBranch(cond, (theta1 / w1, theta2 / w2, (phi - theta1 - theta2) / w3)))
    else:
        raise ValueError(f"mechanism: limb {k} is a planar {kinds} chain: only R-P-R and R-R-R are solved")
    return tuple(b for b in out if b.condition is not S.false)


def _rodrigues(n: Matrix, c: Expr, s: Expr) -> Matrix:
    """The rotation about the unit axis ``n`` with cosine ``c`` and sine ``s``."""
    K = Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    return eye(3) + s * K + (1 - c) * K * K


def _sub1(n: Matrix, x: Matrix, y: Matrix) -> tuple[Expr, Expr, Expr]:
    """Subproblem 1: the angle turning ``x`` onto ``y`` about the unit axis ``n`` (through
    the origin), with its cosine and sine."""
    xp, yp = x - n.dot(x) * n, y - n.dot(y) * n
    dot_, crs = xp.dot(yp), n.dot(xp.cross(yp))
    r = sqrt(xp.dot(xp) * yp.dot(yp))
    return atan2(crs, dot_), dot_ / r, crs / r


def _ups(limb: Any, tw: list, T: ImmutableMatrix, k: int) -> tuple[LimbBranch, ...]:
    """The U-P-S leg (see the module docstring)."""
    (o1, _), (o2, _), (_, d), (o4, _), (o5, _), (o6, _) = tw
    A, B = Matrix(limb.joints[0].args[0]), Matrix(limb.joints[2].args[0])
    n1, n2 = (Matrix(o) / sqrt(o.dot(o)) for o in (o1, o2))
    n4, n5, n6 = (Matrix(o) / sqrt(o.dot(o)) for o in (o4, o5, o6))
    if [list(x) for x in (n4, n5, n6)] != [[1, 0, 0], [0, 1, 0], [0, 0, 1]]:
        raise ValueError(f"mechanism: limb {k}: the spherical joint's axes must be x, y, z (as Spherical gives them)")
    R_T = T[:3, :3]
    g = R_T * B + T[:3, 3] - A
    e, dv = B - A, Matrix(d)
    qa, qb, qc = dv.dot(dv), e.dot(dv), e.dot(e) - g.dot(g)
    disc3 = qb**2 - qa * qc
    out = []
    for s3 in (1, -1) if not is_zero(disc3) else (1,):
        q3 = (-qb + s3 * sqrt(disc3)) / qa
        v = e + q3 * dv
        # subproblem 2: R1 R2 v = g, R2 v = z = a1 n1 + a2 n2 + a3 n1 x n2 = R1^T g
        c12 = n1.dot(n2)
        a1 = (c12 * n2.dot(v) - n1.dot(g)) / (c12**2 - 1)
        a2 = (c12 * n1.dot(g) - n2.dot(v)) / (c12**2 - 1)
        n12 = n1.cross(n2)
        rad = v.dot(v) - a1**2 - a2**2 - 2 * a1 * a2 * c12
        for s2 in (1, -1) if not is_zero(rad) else (1,):
            z = a1 * n1 + a2 * n2 + s2 * sqrt(rad / n12.dot(n12)) * n12
            q2, cq2, sq2 = _sub1(n2, v, z)
            q1, cq1, sq1 = _sub1(n1, z, g)
            charge(4 * BRANCH_UNITS)
            W = (_rodrigues(n1, cq1, sq1) * _rodrigues(n2, cq2, sq2)).T * R_T
            w13 = W[0, 2]
            if is_zero(w13**2 - 1):
                raise ValueError(f"pose: limb {k}: the spherical joint's axes 4 and 6 align: q4 + q6 alone is fixed")
            for s5 in (1, -1):
                cb = s5 * sqrt(1 - w13**2)
                q4, q5, q6 = atan2(-W[1, 2] / cb, W[2, 2] / cb), atan2(w13, cb), atan2(-W[0, 1] / cb, W[0, 0] / cb)
                cond = _cond(Gt(disc3, 0) if not is_zero(disc3) else Eq(disc3, 0),
                             Gt(rad, 0) if not is_zero(rad) else Eq(rad, 0), Lt(w13**2, 1))
                scale = [sqrt(o.dot(o)) for o in (o1, o2)] + [1] + [sqrt(o.dot(o)) for o in (o4, o5, o6)]
                vals = (q1, q2, q3, q4, q5, q6)
                out.append(LimbBranch(cond, tuple(x / sc for x, sc in zip(vals, scale, strict=True))))
    return tuple(b for b in out if b.condition is not S.false)


def limb_joint_values(mechanism: Any, pose: Any, *, budget: int = BUDGET) -> tuple[tuple[LimbBranch, ...], ...]:
    r"""Every limb's joint values with the platform at ``pose``, exact: one tuple of
    :class:`LimbBranch` ``(condition, values)`` per limb (see the module docstring for the
    limbs solved and their branches).

    ``pose`` is the platform's displacement from the configuration the limbs' joints
    describe (a 4x4 rigid motion, or a ``Transform``); each limb's values ``q`` satisfy
    ``exp([$_1] q_1) ... exp([$_n] q_n) = pose``, its joints' twists in the limb's order.
    ``budget`` bounds the exact arithmetic (:mod:`screwsym.algebra.budget`): past it a
    ``ValueError`` naming ``limb_joint_values``.

    The planar 3-RPR with legs from ``(0, 0)``, ``(4, 0)``, ``(0, 4)`` to a platform
    triangle, translated by ``(1, 1)`` and turned by ``phi`` with ``cos phi = 3/5``: each leg
    has two branches (its prismatic joint extended by ``q_2``, or the leg turned half a turn
    and ``q_2`` past its opposite):

    >>> from sympy import Matrix, Rational
    >>> from screwsym.systems import Limb, ParallelMechanism, Prismatic, Revolute
    >>> def rpr(a, b):
    ...     return Limb(Revolute([*a, 0], [0, 0, 1]), Prismatic([b[0] - a[0], b[1] - a[1], 0]),
    ...                 Revolute([*b, 0], [0, 0, 1]))
    >>> pm = ParallelMechanism(rpr((0, 0), (1, 1)), rpr((4, 0), (2, 1)), rpr((0, 4), (1, 2)))
    >>> c, s = Rational(3, 5), Rational(4, 5)
    >>> T = Matrix([[c, -s, 0, 1], [s, c, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]])
    >>> legs = limb_joint_values(pm, T)
    >>> [len(branches) for branches in legs]
    [2, 2, 2]
    >>> legs[0][0]
    LimbBranch(condition=True, values=(atan(1/2), -1 + 4*sqrt(5)/5, -atan(1/2) + atan(4/3)))
    >>> legs[0][1].values
    (-pi + atan(1/2), -4*sqrt(5)/5 - 1, -atan(1/2) + atan(4/3) + pi)

    Leg 0 turns by ``atan(1/2)`` and its prismatic joint (the direction ``(1, 1)`` from
    ``(0, 0)`` to ``(1, 1)``, unit rate) moves by ``4 sqrt(5)/5 - 1``: the leg, of length
    ``sqrt(2)`` at the reference, is ``(1 + q_2) sqrt(2) = 4 sqrt(10)/5`` long, the
    distance from ``(0, 0)`` to ``T (1, 1) = (4/5, 12/5)``.

    Bad input is refused:

    >>> limb_joint_values(pm, Matrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1], [0, 0, 0, 1]]))
    Traceback (most recent call last):
    ...
    ValueError: pose: limb 0 is planar (the plane z = 0): expected a planar motion, got [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1], [0, 0, 0, 1]]
    """
    limbs = getattr(mechanism, "limbs", None)
    if limbs is None:
        raise TypeError(f"mechanism: expected a ParallelMechanism, got {describe(mechanism)}")
    T = _pose(pose)
    budget = check_count(budget, "budget")
    with case_budget(budget, "limb_joint_values"):
        return tuple(_limb(k, limb, T) for k, limb in enumerate(limbs))


def _limb(k: int, limb: Any, T: ImmutableMatrix) -> tuple[LimbBranch, ...]:
    """The branches of limb ``k``: the planar or the U-P-S closed forms."""
    tw = _twists(limb)
    planar = all(is_zero(w[0]) and is_zero(w[1]) and is_zero(v[2]) for w, v in tw)
    names = "".join(type(j).__name__[0] for j in limb.joints)
    if planar and len(tw) == 3:
        return _planar(tw, T, k)
    if names == "UPS":
        return _ups(limb, tw, T, k)
    raise ValueError(
        f"mechanism: limb {k} ({names}, {len(tw)} freedoms) is not one solved here: "
        "planar R-P-R or R-R-R, or U-P-S"
    )
