r"""Actuation of parallel mechanisms: transmission wrenches, Jacobians, singularities, transmission.

A limb names its actuated joints (``Limb(*joints, actuated=i)``).  Locking
every joint of a limb but the actuated joint ``a`` leaves the wrenches
reciprocal to the other joints' twists ``T_p`` (Joshi & Tsai 2002): a system
of rank ``c + 1`` where ``c`` is the rank of the limb's constraint system
``W_c = T^r``, which it contains.  Its members outside ``W_c`` are the
*actuation* (transmission) wrenches of the joint; they are defined modulo
``W_c``, which no platform twist the limb allows sees.  This module chooses
one:

    the actuation wrench of joint ``a`` is the wrench ``w`` of ``T_p^r``
    orthogonal to every member ``c`` of ``W_c`` in the Euclidean product
    ``<w, c> = f_w . f_c + C_w . C_c`` of forces and moments taken about
    the point ``X`` of the limb's last joint that has one (the sphere centre of
    an R-P-S leg, the centre of the platform's universal joint, the last
    revolute's point),

so the actuation wrench of an R-P-S or U-P-U leg is the force along the leg
and that of a S-P-S or U-P-S leg (no constraint) the only one.  The choice is
invariant under rigid motions of the frame.  It is written polynomial (exact)
in the symbols: the null vector of a ``c x (c + 1)`` matrix, its denominators
cleared and the common factor of its entries divided out (it keeps its
sign, its sign chosen so that ``w o $_a``, the actuated joint's entry of
:func:`jacobian`'s ``Jq``, has a positive leading coefficient).

Jacobian (Joshi & Tsai 2002, eq. 6-9): the rows of ``Jx`` are the actuation
wrenches followed by a basis of the mechanism's constraint system, each
written in *axis coordinates* ``(C_O; f)`` (the wrench with its halves
swapped, ``Delta w``), so that for a platform twist ``t = (omega; v_O)``,
``Jx * t`` is the column of reciprocal products ``w o t`` (1.45); ``Jq`` is
``diag(w_a o $_a)``.  For every twist reached by actuated rates ``qdot``,
``Jx * t = Jq * qdot`` stacked on zeros.

Singularities (:func:`mechanism_singularities`, the method ``singularities()``, Gosselin & Angeles 1990, Zlatanov,
Fenton & Benhabib 1995, Zlatanov, Bonev & Gosselin 2002): ``limb`` (a limb's
twist system or the system of its constraints and actuation wrenches loses
rank: the inverse-kinematic kind, "type I"), ``actuation`` (``Jx`` loses rank
while the constraints keep theirs: "type II") and ``constraint`` (the
constraint system loses rank).

Transmission (:func:`transmission`, Wang, Liu, Wang & Chen 2010): see there.

References
==========

S. A. Joshi and L.-W. Tsai, "Jacobian analysis of limited-DOF parallel
manipulators", ASME J. Mech. Des. 124 (2002) 254-258.
C. Gosselin and J. Angeles, "Singularity analysis of closed-loop kinematic
chains", IEEE Trans. Robot. Autom. 6(3) (1990) 281-290.
D. Zlatanov, I. A. Bonev and C. M. Gosselin, "Constraint singularities of
parallel mechanisms", Proc. IEEE ICRA 2002, 496-502.
J. Wang, C. Wu and X.-J. Liu, "Performance evaluation of parallel
manipulators: motion/force transmissibility and its index", Mech. Mach.
Theory 45 (2010) 1462-1476.
"""

from __future__ import annotations

import random
from typing import Any, NamedTuple

from sympy import (
    Abs,
    Dummy,
    ImmutableMatrix,
    Integer,
    Matrix,
    Min,
    Poly,
    Rational,
    cancel,
    cos,
    expand,
    eye,
    fraction,
    nan,
    sin,
    sqrt,
    sring,
)
from sympy.polys.polyerrors import DomainError

from ..algebra.budget import BUDGET, charge
from ..algebra.circle import trig_substitute
from ..algebra.linalg import primitive_entries
from ..core.decide import is_zero_vector
from ..core.formulas import cross_matrix, reciprocal_form
from ..core.twist import Twist
from ..core.wrench import Wrench
from ._rank_cases import case_budget
from .joints import (
    Cylindrical,
    Helical,
    Joint,
    Parallelogram,
    Prismatic,
    Revolute,
    Spherical,
    Universal,
)
from .screw_system import ScrewSystem

#: a Limb and a ParallelMechanism (screwsym.systems.parallel imports this module)
_Limb = Any
_Mechanism = Any

__all__ = [
    "actuation_wrenches",
    "jacobian",
    "transmission",
    "Transmission",
    "transmission_index",
    "generic_limb_rank",
    "limb_actuation_wrench",
    "check_actuated",
    "generic_values",
]


# ------------------------------------------------------------------ the actuated joints
def check_actuated(value: Any, count: int) -> tuple[Integer, ...]:
    """``actuated`` as a sorted tuple of distinct indices into ``count`` joints.

    >>> check_actuated(1, 3), check_actuated((2, 0), 3)
    ((1,), (0, 2))
    >>> check_actuated(3, 3)
    Traceback (most recent call last):
    ...
    ValueError: actuated: expected indices into the limb's 3 joints (0 to 2), got 3
    >>> check_actuated("1", 3)
    Traceback (most recent call last):
    ...
    TypeError: actuated: expected an int or a tuple of ints (joint indices), got str
    """
    items = tuple(value) if isinstance(value, (tuple, list)) else (value,)
    if not items:
        raise ValueError("actuated: expected at least one joint index, got an empty tuple")
    out = []
    for i in items:
        if isinstance(i, bool) or not isinstance(i, (int, Integer)):
            raise TypeError(
                "actuated: expected an int or a tuple of ints (joint indices), "
                f"got {type(i).__name__}"
            )
        if not 0 <= int(i) < count:
            raise ValueError(
                f"actuated: expected indices into the limb's {count} joints "
                f"(0 to {count - 1}), got {int(i)}"
            )
        out.append(int(i))
    if len(set(out)) != len(out):
        raise ValueError(f"actuated: expected distinct joint indices, got {tuple(out)}")
    return tuple(Integer(i) for i in sorted(out))


def _joint_twist_groups(limb: _Limb) -> list[list[Twist]]:
    return [list(j._twists()) for j in limb.joints]


def _check_actuated_joint(limb: _Limb, k: int, where: str) -> None:
    j = limb.joints[k]
    if j.freedom != 1:
        raise ValueError(
            f"{where}: an actuated joint must have one freedom (R, P, H or a parallelogram), "
            f"got {type(j).__name__} with {j.freedom}"
        )


# ------------------------------------------------------------------ the actuation wrenches
def _point_of(j: Joint) -> ImmutableMatrix | None:
    if isinstance(j, Parallelogram):
        return j.args[2]
    if isinstance(j, Prismatic):
        return None
    return j.args[0]


def _last_point(limb: _Limb) -> ImmutableMatrix:
    return _last_point_of(list(limb.joints))


def _last_point_of(joints: list[Joint]) -> ImmutableMatrix:
    for j in reversed(joints):
        p = _point_of(j)
        if p is not None:
            return p
    return ImmutableMatrix([0, 0, 0])


def _euclid(a: Any, b: Any, X: ImmutableMatrix) -> Any:
    """``f_a . f_b + C_a . C_b`` with the moments about ``X``."""
    ma = a.S0 - X.cross(a.S)
    mb = b.S0 - X.cross(b.S)
    return a.S.dot(b.S) + ma.dot(mb)


def limb_actuation_wrench(limb: _Limb, k: int) -> Wrench:
    """The actuation wrench of joint ``k`` of ``limb`` (the module docstring gives the choice).

    >>> from screwsym.systems.parallel import Limb
    >>> from screwsym.systems.joints import R, P, S
    >>> leg = Limb(R([2, 0, 0], [0, 1, 0]), P([-1, 0, 2]), S([1, 0, 2]), actuated=1)
    >>> limb_actuation_wrench(leg, 1)       # the force along the leg, through the sphere
    Wrench([-1, 0, 2], [0, -4, 0])

    Where joint ``k`` adds no freedom to the others (a type I, limb singularity:
    the crank of a stretched R-R-R leg), every wrench reciprocal to the others
    is reciprocal to it too, and the actuation wrench is the *limit* of the
    one of the nearby configurations: the limb moved through one of its joints
    by ``s`` (the first joint whose motion takes the limb out of the
    singularity), the wrench found exactly in ``s`` and taken at ``s = 0``.
    Its product with the actuated joint's twist is then zero (``Jq`` singular,
    Gosselin & Angeles 1990; Bonev, Zlatanov & Gosselin 2003):

    >>> z = [0, 0, 1]
    >>> stretched = Limb(R([0, 0, 0], z), R([1, 0, 0], z), R([2, 0, 0], z), actuated=0)
    >>> limb_actuation_wrench(stretched, 0)  # the force along the leg's line
    Wrench([-1, 0, 0], [0, 0, 0])
    """
    _check_actuated_joint(limb, k, f"joints[{k}]")
    twist = limb.joints[k]._twists()[0]
    w = _wrench_of(list(limb.joints), k)
    if w is None:
        w = _limit_wrench(list(limb.joints), k)
    return _signed(_wrench_from(w), twist)


def _wrench_of(joints: list[Joint], k: int) -> ImmutableMatrix | None:
    """The actuation wrench's column (not yet signed), None where joint ``k`` adds no freedom."""
    others = [t for i, j in enumerate(joints) if i != k for t in j._twists()]
    passive_r = ScrewSystem(*others, kind=Twist).reciprocal().basis()
    every = [t for j in joints for t in j._twists()]
    constraints = ScrewSystem(*every, kind=Twist).reciprocal().basis()
    B, C = list(passive_r), list(constraints)
    if len(B) != len(C) + 1:
        return None
    if not C:
        return B[0].matrix
    X = _last_point_of(joints)
    G = Matrix([[_euclid(c, b, X) for b in B] for c in C])
    null = G.nullspace(simplify=False)
    if len(null) != 1:  # pragma: no cover - the product is definite on forces and couples
        raise ValueError("actuated: the actuation wrench is not unique here")
    beta = primitive_entries(list(null[0]))
    return sum((beta[j] * B[j].matrix for j in range(len(B))), ImmutableMatrix.zeros(6, 1))


def _limit_wrench(joints: list[Joint], k: int) -> ImmutableMatrix:
    """The actuation wrench at a limb singularity: the limit along a motion of one joint."""
    s = Dummy("s", real=True)
    for m in range(len(joints)):
        for moved in _moved_by(joints, m, s):
            w = _wrench_of(moved, k)
            if w is None:
                continue
            entries = primitive_entries([w[i] for i in range(6)])  # polynomial, no common s
            limit = [cancel(e.subs(s, 0)) for e in entries]
            if any(e != 0 for e in limit):
                return ImmutableMatrix(limit)
    raise ValueError(  # pragma: no cover - every joint moved and none left the singularity
        f"actuated: joint {k} of the limb adds no freedom to its other joints at any "
        "configuration near this one, so it transmits no actuation wrench")


def _moved_by(joints: list[Joint], m: int, s: Any) -> list[list[Joint]]:
    """The limb with joint ``m`` moved by ``s`` (each of its motions in turn; PoE)."""
    j = joints[m]
    zero = ImmutableMatrix([0, 0, 0])
    I3 = ImmutableMatrix(eye(3))
    motions: list[tuple[ImmutableMatrix, ImmutableMatrix, ImmutableMatrix]] = []
    if isinstance(j, (Revolute, Helical, Cylindrical)):
        motions.append((_cayley(j.args[1], s), j.args[0], zero))
        if isinstance(j, Cylindrical):
            motions.append((I3, zero, ImmutableMatrix(s * j.args[1])))
    elif isinstance(j, Prismatic):
        motions.append((I3, zero, ImmutableMatrix(s * j.args[0])))
    elif isinstance(j, Spherical):
        motions.extend((_cayley(ImmutableMatrix(e), s), j.args[0], zero)
                       for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1]))
    elif isinstance(j, Universal):
        motions.extend((_cayley(u, s), j.args[0], zero) for u in (j.args[2], j.args[1]))
    out = []
    for Rm, c, shift in motions:
        out.append(joints[:m + 1] + [_moved(x, Rm, c, shift) for x in joints[m + 1:]])
    return out


def _wrench_from(column: Any) -> Wrench:
    entries = primitive_entries([column[i] for i in range(6)])
    return Wrench(entries[:3], entries[3:])


def _signed(w: Wrench, twist: Twist) -> Wrench:
    """``w`` or ``-w``: the one whose ``w o $_a`` has a positive leading coefficient."""
    p = cancel(reciprocal_form(w.matrix, twist.matrix))
    if p == 0:
        return w
    num, den = fraction(p)
    # the generators SymPy finds: the symbols, or sin/cos of them (trigonometric geometry)
    def lc(e: Any) -> Any:
        return e if e.is_number else Poly(e).LC()

    lead = lc(num) * lc(den)
    return Wrench(-w.S, -w.S0) if lead.is_negative else w


def _actuated(mech: _Mechanism) -> list[tuple[int, int]]:
    pairs = [(i, int(k)) for i, limb in enumerate(mech.limbs) for k in limb.actuated]
    if not pairs:
        raise ValueError(
            "actuated: no limb names an actuated joint (build limbs with Limb(..., actuated=i))"
        )
    return pairs


def actuation_wrenches(mech: _Mechanism) -> tuple[Wrench, ...]:
    """The actuation wrench of each actuated joint, limb by limb, in the order of the indices.

    >>> from sympy import Rational
    >>> from screwsym.systems.parallel import Limb, ParallelMechanism
    >>> from screwsym.systems.joints import R, P
    >>> z = [0, 0, 1]
    >>> e = [Rational(3, 2), Rational(5, 2), 0]      # the end point
    >>> m = ParallelMechanism(Limb(R([0, 0, 0], z), R([0, 1, 0], z), R(e, z), actuated=0),
    ...                       Limb(R([3, 0, 0], z), R([3, 1, 0], z), R(e, z), actuated=0),
    ...                       Limb(P([1, 0, 0]), P([0, 1, 0])))   # a P-P leg locks the spin
    >>> actuation_wrenches(m)       # the forces along the distal links of a five-bar
    (Wrench([-1, -1, 0], [0, 0, 1]), Wrench([-1, 1, 0], [0, 0, 4]))
    """
    return tuple(limb_actuation_wrench(mech.limbs[i], k) for i, k in _actuated(mech))


def jacobian(mech: _Mechanism) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    r"""``(Jx, Jq)``: ``Jx * t = Jq * qdot`` (stacked on zeros) for every platform twist ``t``.

    ``Jx`` has the actuation wrenches and then a basis of the constraint
    system as rows, each in axis coordinates ``(C_O; f)`` so that ``Jx * t``
    (``t = (omega; v_O)``) is the column of reciprocal products (1.45);
    ``Jq = diag(w_a o $_a)``, one per actuated joint, padded with zero rows
    for the constraints (Joshi & Tsai 2002, eq. 9).  ``Jx`` is 6 x 6 when the
    actuators and the constraints together number six.

    >>> from sympy import Rational
    >>> from screwsym.systems.parallel import Limb, ParallelMechanism
    >>> from screwsym.systems.joints import R, P
    >>> z = [0, 0, 1]
    >>> e = [Rational(3, 2), Rational(5, 2), 0]      # the end point
    >>> m = ParallelMechanism(Limb(R([0, 0, 0], z), R([0, 1, 0], z), R(e, z), actuated=0),
    ...                       Limb(R([3, 0, 0], z), R([3, 1, 0], z), R(e, z), actuated=0),
    ...                       Limb(P([1, 0, 0]), P([0, 1, 0])))
    >>> Jx, Jq = jacobian(m)
    >>> Jx.shape, Jq
    ((6, 6), Matrix([
    [1, 0],
    [0, 1],
    [0, 0],
    [0, 0],
    [0, 0],
    [0, 0]]))
    """
    wrenches = actuation_wrenches(mech)
    pairs = _actuated(mech)
    constraints = mech.constraints.basis()
    rows = [_axis_row(w) for w in wrenches] + [_axis_row(c) for c in constraints]
    Jx = ImmutableMatrix.vstack(*rows)
    n = len(wrenches)
    diag = []
    for w, (i, k) in zip(wrenches, pairs, strict=True):
        twist = mech.limbs[i].joints[k]._twists()[0]
        diag.append(cancel(reciprocal_form(w.matrix, twist.matrix)))
    Jq = ImmutableMatrix(Jx.rows, n, lambda r, c: diag[r] if r == c else 0)
    return Jx, Jq


def _axis_row(w: Any) -> ImmutableMatrix:
    return ImmutableMatrix([[*w.S0, *w.S]])


# ------------------------------------------------------------------ transmission
def transmission_index(wrench: Any, twist: Any, point: Any) -> Any:
    r"""The normalised power coefficient ``|$_T o $| / |$_T o $|_max`` of Wang et al. (2010).

    Explanation
    ===========

    For a wrench ``$_T = (f; C_O)`` with ``f != 0`` (pitch ``h_T``) and a twist
    ``$ = (omega; v_O)`` with ``omega != 0`` (pitch ``h``), both made unit,
    ``$_T o $ = (h_T + h) cos(alpha) - d sin(alpha)`` (``d`` the distance and
    ``alpha`` the angle between their axes), and Wang et al. (2010, eq. 12-13)
    divide by its potential maximum ``sqrt((h_T + h)**2 + d_max**2)``, where
    ``d_max`` is the distance from the twist's axis to the point where the
    wrench acts, here ``point`` projected onto the wrench's axis (so
    ``d <= d_max`` and the index lies in ``[0, 1]``).  A pure translation
    ``(0; v)`` gives ``|f . v| / (|f| |v|)`` (the cosine of the angle between
    force and velocity); a couple ``(0; C)`` gives ``|C . omega| /
    (|C| |omega|)``, and nothing with a translation.  For the planar five-bar
    the input index is ``|sin|`` of the angle between the crank and the distal
    link, the output index ``|sin|`` of the angle between the distal links
    (Liu, Wang & Pritschow 2006; Wang et al. 2010, Section 4).

    >>> from screwsym import Twist, Wrench
    >>> f = Wrench.force([1, 1, 0], point=[0, 1, 0])     # along a distal link
    >>> transmission_index(f, Twist.rotation([0, 0, 1], point=[0, 0, 0]), [0, 1, 0])
    sqrt(2)/2
    """
    f, m = wrench.S, wrench.S0
    omega, v = twist.S, twist.S0
    power = f.dot(v) + m.dot(omega)
    f_zero, w_zero = is_zero_vector(f), is_zero_vector(omega)
    if f_zero is True:
        if w_zero is True:
            return Integer(0)
        return Abs(cancel(m.dot(omega))) / (sqrt(m.dot(m)) * sqrt(omega.dot(omega)))
    if w_zero is True:
        return Abs(cancel(f.dot(v))) / (sqrt(f.dot(f)) * sqrt(v.dot(v)))
    # with a = f . C_O, b = omega . v_O (so h_T = a/|f|^2, h = b/|omega|^2), the point
    # X = (f x C_O + (P . f) f)/|f|^2 and r0 = omega x v_O/|omega|^2 of the twist's axis,
    # |f|^2 |omega|^2 ((h_T + h)^2 + d_max^2) = E / (|f|^2 |omega|^4) with E polynomial:
    # E = |omega|^2 (|omega|^2 a + |f|^2 b)^2 + |Q x omega|^2,
    # Q = |omega|^2 (f x C_O + (P . f) f) - |f|^2 (omega x v_O)
    P = ImmutableMatrix(point)
    found = _index_in_ring(f, m, omega, v, P)
    if found is not None:
        return found
    ff, ww = expand(f.dot(f)), expand(omega.dot(omega))  # pragma: no cover - EX coefficients
    a, b = expand(f.dot(m)), expand(omega.dot(v))  # pragma: no cover
    Q = ww * (f.cross(m) + P.dot(f) * f) - ff * omega.cross(v)  # pragma: no cover
    arm = Q.cross(omega)  # pragma: no cover
    E = expand(ww * (ww * a + ff * b) ** 2 + arm.dot(arm))  # pragma: no cover
    num, den = fraction(cancel(ff / E))  # pragma: no cover
    return Abs(expand(power)) * ww * sqrt(num) / sqrt(den)  # pragma: no cover


def _index_in_ring(f: Any, m: Any, omega: Any, v: Any, P: Any) -> Any:
    """:func:`transmission_index`'s general case computed in a sparse polynomial ring
    (SymPy's ``sring``): ``expand`` and ``cancel`` of the same polynomials as expressions
    take minutes at a symbolic pose (a 3-RPR in x, y, sin(phi), cos(phi)); the work is
    charged to the budget under way.  None where the ring has no exact domain."""
    entries = [*f, *m, *omega, *v, *P]
    try:
        R, els = sring(entries, extension=True)
    except (ValueError, TypeError, NotImplementedError):  # pragma: no cover
        return None
    if R.domain.is_EX or R.domain.is_EXRAW:  # pragma: no cover - not an exact domain
        return None
    F, Mo, W, V, Pt = (els[3 * i:3 * i + 3] for i in range(5))

    def dot(p: list, q: list) -> Any:
        return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]

    def cross(p: list, q: list) -> list:
        return [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]]

    ff, ww = dot(F, F), dot(W, W)
    a, b = dot(F, Mo), dot(W, V)
    pf = dot(Pt, F)
    fm, wv = cross(F, Mo), cross(W, V)
    Q = [ww * (fm[i] + pf * F[i]) - ff * wv[i] for i in range(3)]
    arm = cross(Q, W)
    E = ww * (ww * a + ff * b) ** 2 + dot(arm, arm)
    # the gcd below, about 16 microseconds per pair of terms of E and |f|^2 (measured: 1 s
    # for the 5546 and 11 terms of a 3-RPR at the pose (x, y, phi))
    charge(16 * len(E.terms()) * len(ff.terms()))
    # |omega|^2 / sqrt(E): where |omega|^4 divides E (a planar mechanism: b = 0 and Q a
    # multiple of omega), it cancels, so the formula stays finite where omega vanishes (the
    # output twist a translation there: two legs of a 3-RPR parallel), not 0/0 (issue 32)
    outside = ww
    if not ww.is_ground:
        q, r = E.div(ww**2)
        if not r:
            E, outside = q, R.one
    try:
        g = ff.gcd(E)
    except (NotImplementedError, DomainError):  # pragma: no cover - a domain without gcd
        g = R.one
    num, den = ff.exquo(g), E.exquo(g)
    power = dot(F, V) + dot(Mo, W)
    return (Abs(power.as_expr()) * outside.as_expr() * sqrt(num.as_expr())
            / sqrt(den.as_expr()))


class Transmission(NamedTuple):
    """The result of :func:`transmission`: one entry per actuated joint, and the local index."""

    input: tuple  #: lambda_i, the input transmission index of each actuator
    output: tuple  #: eta_i, the output transmission index of each actuator
    local: Any  #: Gamma = min(lambda_i, eta_i)
    wrenches: tuple  #: the transmission (actuation) wrenches
    outputs: tuple  #: the output twists, the platform's twist with the other actuators locked
    #: the limbs (indices) at a limb (type I) singularity, where the indices are not all defined
    singular: tuple = ()


def _point_after(limb: _Limb, k: int) -> ImmutableMatrix:
    for j in limb.joints[k + 1:]:
        p = _point_of(j)
        if p is not None:
            return p
    return _last_point(limb)


def transmission(mech: _Mechanism, *, budget: int = BUDGET) -> Transmission:
    r"""The input, output and local transmission indices of Wang et al. (2010).

    Explanation
    ===========

    For actuated joint ``i`` with twist ``$_I`` and transmission wrench
    ``$_T`` (:func:`actuation_wrenches`), the input index is
    ``lambda_i = transmission_index($_T, $_I, X_I)``, ``X_I`` the point of the
    next joint of the limb (where the wrench enters the link the actuator
    drives); the output twist ``$_O`` is the platform twist reciprocal to the
    constraints and to every other actuation wrench (the other actuators
    locked), and ``eta_i = transmission_index($_T, $_O, X_O)`` with ``X_O``
    the point of the limb's last joint (where the wrench enters the
    platform).  The local index is ``min(lambda_i, eta_i)``, evaluated where
    the indices are numbers and otherwise left as an unevaluated ``Min`` (SymPy
    compares symbolic square roots for minutes to simplify it; substitute
    values, or use :mod:`screwsym.numeric.transmission` for many
    configurations).  Exact (``Abs`` and ``sqrt`` of the symbols).  The work of
    its screw systems is bounded by ``budget``, past which a ``ValueError``
    names ``transmission``.

    At a singular configuration nothing is raised.  A limb at a type I
    (limb) singularity transmits through its limit wrench
    (:func:`limb_actuation_wrench`), its input index is ``0`` and it is named
    in ``singular``; where the other actuators locked leave the platform no
    freedom (such a limb constrains it), the output indices are ``nan`` and
    their twists ``None``, and the local index is ``0``.  Where they leave it
    more than one (a type II configuration), the output index is ``0`` (the
    wrench does no work on a motion the platform keeps) and the twist
    ``None``.

    Examples
    ========

    The five-bar of :func:`actuation_wrenches`: cranks along y, distal links
    at 45 degrees to them and at 90 degrees to each other.

    >>> from sympy import Rational
    >>> from screwsym.systems.parallel import Limb, ParallelMechanism
    >>> from screwsym.systems.joints import R, P
    >>> z = [0, 0, 1]
    >>> e = [Rational(3, 2), Rational(5, 2), 0]      # the end point
    >>> m = ParallelMechanism(Limb(R([0, 0, 0], z), R([0, 1, 0], z), R(e, z), actuated=0),
    ...                       Limb(R([3, 0, 0], z), R([3, 1, 0], z), R(e, z), actuated=0),
    ...                       Limb(P([1, 0, 0]), P([0, 1, 0])))
    >>> tr = transmission(m)
    >>> tr.input, tr.output, tr.local
    ((sqrt(2)/2, sqrt(2)/2), (1, 1), sqrt(2)/2)
    """
    with case_budget(budget, "transmission"):
        return _transmission(mech)


def _transmission(mech: _Mechanism) -> Transmission:
    pairs = _actuated(mech)
    wrenches = actuation_wrenches(mech)
    constraints = list(mech.constraints.basis())
    constraint_rank = len(constraints)
    singular = [i for i, limb in enumerate(mech.limbs)
                if limb.actuated and limb.twists.rank < generic_limb_rank(limb)]
    ins: list = []
    outs: list = []
    twists: list = []
    for n, (i, k) in enumerate(pairs):
        limb = mech.limbs[i]
        w = wrenches[n]
        t_in = limb.joints[k]._twists()[0]
        ins.append(transmission_index(w, t_in, _point_after(limb, k)))
        others = [x for m, x in enumerate(wrenches) if m != n]
        free = ScrewSystem(*others, *constraints, kind=Wrench).reciprocal()
        if len(free) == 1:
            t_out = free.screws[0]
            twists.append(t_out)
            outs.append(transmission_index(w, t_out, _last_point(limb)))
            continue
        if len(free) == 0 and singular:  # a stretched limb constrains the platform
            twists.append(None)
            outs.append(nan)
            continue
        if len(free) > 1 and len(pairs) + constraint_rank >= 6:
            twists.append(None)  # a type II configuration: a motion no actuator resists
            outs.append(Integer(0))
            continue
        raise ValueError(
            "transmission: with the other actuators locked the platform keeps "
            f"{len(free)} freedoms (expected 1: as many actuators as freedoms)"
        )
    every = [*ins, *outs]
    if singular and any(o is nan for o in outs):
        local = Integer(0)
    elif all(e.is_number for e in every):
        local = Min(*every)
    else:
        local = Min(*every, evaluate=False)
    return Transmission(tuple(ins), tuple(outs), local, wrenches, tuple(twists), tuple(singular))


# ------------------------------------------------------------------ the limb's generic rank
def _cayley(u: ImmutableMatrix, s: Any) -> ImmutableMatrix:
    """The rotation about ``u`` by the angle ``2 atan(s |u|)``, rational in ``s`` and ``u``."""
    K = cross_matrix(u)
    k = 2 / (1 + s**2 * u.dot(u))
    return ImmutableMatrix(eye(3) + k * (s * K + s**2 * K * K)).applyfunc(cancel)


def _moved(j: Joint, Rm: ImmutableMatrix, c: ImmutableMatrix, shift: ImmutableMatrix) -> Joint:
    """``j`` carried by ``x -> Rm (x - c) + c + shift`` (directions by ``Rm``)."""

    def pt(p: Any) -> ImmutableMatrix:
        return ImmutableMatrix(Rm * (p - c) + c + shift).applyfunc(cancel)

    def dr(u: Any) -> ImmutableMatrix:
        return ImmutableMatrix(Rm * u).applyfunc(cancel)

    if isinstance(j, (Revolute, Cylindrical)):
        return type(j)(pt(j.args[0]), dr(j.args[1]))
    if isinstance(j, Prismatic):
        return Prismatic(dr(j.args[0]))
    if isinstance(j, Helical):
        return Helical(pt(j.args[0]), dr(j.args[1]), j.args[2])
    if isinstance(j, Universal):
        return Universal(pt(j.args[0]), dr(j.args[1]), dr(j.args[2]))
    if isinstance(j, Spherical):
        return Spherical(pt(j.args[0]))
    if isinstance(j, Parallelogram):
        return Parallelogram(*(pt(p) for p in j.args))
    raise TypeError(f"joints: cannot move a {type(j).__name__}")  # pragma: no cover


def _displaced(joints: list[Joint], rnd: random.Random) -> list[Joint]:
    """The limb in another configuration: each joint moved by a random rational amount (PoE)."""
    joints = list(joints)
    zero = ImmutableMatrix([0, 0, 0])
    I3 = ImmutableMatrix(eye(3))

    def val() -> Rational:
        return Rational(rnd.randint(-40, 40), rnd.randint(7, 41))

    for k in range(len(joints) - 1, -1, -1):
        j = joints[k]
        motions: list[tuple[ImmutableMatrix, ImmutableMatrix, ImmutableMatrix]] = []
        if isinstance(j, (Revolute, Helical, Cylindrical)):
            p, u = j.args[0], j.args[1]
            shift = val() * u if not isinstance(j, Revolute) else zero
            motions.append((_cayley(u, val()), p, ImmutableMatrix(shift)))
        elif isinstance(j, Prismatic):
            motions.append((I3, zero, ImmutableMatrix(val() * j.args[0])))
        elif isinstance(j, Spherical):
            p = j.args[0]
            for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1]):
                motions.append((_cayley(ImmutableMatrix(e), val()), p, zero))
        elif isinstance(j, Universal):
            p, u1, u2 = j.args
            R1 = _cayley(u1, val())
            R2 = _cayley(u2, val())
            # PoE: the distal joints turn about dir2, then all about dir1, which carries dir2
            joints[k] = Universal(p, u1, ImmutableMatrix(R1 * u2).applyfunc(cancel))
            motions.append((R2, p, zero))
            motions.append((R1, p, zero))
        elif isinstance(j, Parallelogram):
            p1, p2, q1 = j.args
            Rn = _cayley(j.normal, val())
            q1n = ImmutableMatrix(Rn * (q1 - p1) + p1).applyfunc(cancel)
            joints[k] = Parallelogram(p1, ImmutableMatrix(p2), q1n)
            motions.append((I3, zero, ImmutableMatrix(q1n - q1)))
        for Rm, c, shift in motions:
            joints[k + 1:] = [_moved(x, Rm, c, shift) for x in joints[k + 1:]]
    return joints


def generic_values(obj: Any, rnd: random.Random) -> dict:
    """Random rational values of the symbols of ``obj``: ``sin(q)``, ``cos(q)`` at a rational
    point of the circle, the other symbols at rationals (for :func:`trig_substitute`).

    >>> from sympy import cos, sin, symbols
    >>> q, x = symbols("q x", real=True)
    >>> v = generic_values(x * cos(q) + sin(q), random.Random(1))
    >>> sorted(map(str, v)), v[sin(q)] ** 2 + v[cos(q)] ** 2
    (['cos(q)', 'q', 'sin(q)', 'x'], 1)
    """
    values: dict = {}
    angles = {a.args[0] for a in obj.atoms(sin, cos) if a.args[0].is_Symbol}
    for q in sorted(angles, key=str):
        t = Rational(rnd.randint(-40, 40), rnd.randint(7, 41))
        values[sin(q)] = 2 * t / (1 + t**2)
        values[cos(q)] = (1 - t**2) / (1 + t**2)
    for x in sorted(obj.free_symbols - angles, key=str):
        values[x] = Rational(rnd.randint(-60, 60), rnd.randint(1, 13))
    for q in sorted(angles, key=str):  # q itself outside sin and cos
        values.setdefault(q, Rational(rnd.randint(-60, 60), rnd.randint(1, 13)))
    return values


def generic_limb_rank(limb: _Limb, seeds: tuple[int, ...] = (1, 2)) -> int:
    """The rank of the limb's twist system at a generic configuration of the limb.

    Explanation
    ===========

    The limb is moved through its own joints (a product of exponentials:
    every joint turned or slid by a random rational amount, rotations in the
    rational Cayley form, its symbols given random rational values) and the
    rank of its twist system taken there, exactly; the largest over ``seeds``
    and the configuration given.  A rank
    at one configuration is at most the generic one, so this is a lower bound
    that equals it but at configurations of measure zero.  A limb whose rank
    here is less than this has a *momentary internal motion* (a limb
    singularity: an R-R-R leg stretched), not a passive freedom: the
    ``freedom - generic_limb_rank`` idle motions that persist at every
    configuration (a S-S leg spinning about its axis) are the passive ones.

    >>> from screwsym.systems.parallel import Limb
    >>> from screwsym.systems.joints import R, S
    >>> z = [0, 0, 1]
    >>> stretched = Limb(R([0, 0, 0], z), R([1, 0, 0], z), R([2, 0, 0], z))
    >>> stretched.twists.rank, generic_limb_rank(stretched)
    (2, 3)
    >>> ss = Limb(S([0, 0, 0]), S([1, 2, 3]))
    >>> ss.twists.rank, generic_limb_rank(ss)
    (5, 5)
    """
    here = limb.twists.rank
    best = here
    if best == limb.freedom:
        return best
    symbols = sorted(limb.free_symbols, key=str)
    for seed in seeds:
        rnd = random.Random(seed)
        # the symbols at random rationals too: a rank there is still at most the generic one,
        # and numbers are fast (a value that degenerates a joint is skipped)
        values = generic_values(limb, rnd) if symbols else {}
        try:
            joints = [trig_substitute(j, values) for j in limb.joints] if values else list(limb.joints)
            moved = _displaced(joints, rnd)
        except ValueError:
            continue
        rank = ScrewSystem(*(t for j in moved for t in j._twists()), kind=Twist).rank
        best = max(best, rank)
        if best == limb.freedom:
            break
    return best

