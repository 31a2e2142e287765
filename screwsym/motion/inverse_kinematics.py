r"""Inverse kinematics of serial arms in closed form, by the Paden–Kahan subproblems.

Explanation
===========

For a chain ``T(q) = exp6($_1, q_1) ... exp6($_6, q_6) M`` and a pose ``T``,
the product ``g = T M^-1`` is split, where the joint axes allow, into the
subproblems of :mod:`screwsym.motion.subproblems` (Paden 1985; Murray, Li &
Sastry 1994, Section 3.3), each joint's value from points and directions that
the remaining joints leave fixed.  The structure is found exactly from the
twists (:func:`decomposition`):

``"spherical wrist"``
    axes 4, 5, 6 meet in a point ``c`` (the PUMA 560, the Stanford arm).  The
    wrist centre ``g c = e1 e2 e3 c`` gives the first three joints: where
    axes 1 and 2 meet in ``r``, ``|e3 c - r| = |g c - r|`` is Subproblem 3 for a
    revolute joint 3 (a quadratic for a prismatic one, the Stanford arm), then
    Subproblem 2 for joints 1 and 2; where axes 2 and 3 meet, the same with
    joint 1 first.  The wrist ``e4 e5 e6 = (e1 e2 e3)^-1 g`` is Subproblem 2 on
    a point of axis 6, then Subproblem 1 for joint 6.
``"three parallel axes"``
    axes 2, 3, 4 parallel (direction ``w``), axes 5 and 6 meeting in ``c``: the
    UR5 family.  ``e2 e3 e4`` is a planar motion, which keeps ``w . x``, so
    ``w . e1^-1 g c = w . c`` gives joint 1 and ``w . R1^T R_g w6 = w . R5 w6``
    joint 5 (Subproblem 4 of IK-Geo, ``h . R(k, theta) p = d``, below), then joint 6 by
    Subproblem 1 on directions, and the planar arm by Subproblem 3 (joint 3)
    and Subproblem 1 (joints 2 and 4).
``"... reversed"``
    the same structure read from the tip (axes 1, 2, 3 meeting: a spherical
    shoulder, as the Franka Panda's; axes 3, 4, 5 parallel with axes 1 and 2
    meeting): the reversed chain ``(-$_6, ..., -$_1)`` reaches ``g^-1``.

Every branch is a :class:`~screwsym.motion.subproblems.Branch` ``(condition,
q)``: the conditions of its subproblems joined.  The closed forms are built once per
chain (:func:`stage_forms`: each stage's subproblem on symbols standing for its points,
the UR5's in about a second) and the pose substituted; each joint's value is a closed
form in the pose and the joints solved before it (:func:`stage_order`), as IKFast's
generated code reads, since substituting nests square roots in square roots (see
:func:`inverse_kinematics`).  Subproblems 1 and 2 are called without their existence
conditions where the stages before imply them (each stage says why).  Degenerate
poses are branches of their own: a wrist singularity (joints 4 and 6 on one line)
gives a branch with joint 4 a free parameter (a real ``Dummy``) and joint 6 depending
on it (only their sum is fixed), a shoulder singularity one with joint 1 free, and so
on, each with its condition.

``free=`` makes joints parameters of a redundant arm: joint ``k`` with value
``s`` is moved to the right of the product
(``e_k e_j = exp6(Ad(e_k) $_j) e_k``), leaving six joints to solve.  A chain
without a decomposition above gets a ``ValueError`` saying which axes fail.

References
==========

B. Paden, *Kinematics and Control of Robot Manipulators*, PhD thesis, UC Berkeley 1985.
R. M. Murray, Z. Li & S. S. Sastry, *A Mathematical Introduction to Robotic
Manipulation*, CRC Press 1994, Section 3.3 (the elbow manipulator, Example 3.12).
A. J. Elias & J. T. Wen, "IK-Geo: unified robot inverse kinematics using
subproblem decomposition", *Mechanism and Machine Theory* 209 (2025), Section 3 (subproblem 4).
D. L. Pieper, *The kinematics of manipulators under computer control*, PhD thesis,
Stanford 1968 (three axes meeting).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from functools import lru_cache
from typing import Any, NamedTuple

from sympy import (
    And,
    Dummy,
    Eq,
    Expr,
    Ge,
    Gt,
    ImmutableMatrix,
    Ne,
    S,
    Symbol,
    atan2,
    sqrt,
)
from sympy.core.evalf import PrecisionExhausted
from sympy.logic.boolalg import Boolean
from sympy.matrices import MatrixBase

from ..algebra.budget import BUDGET, case_budget, charge
from ..core.checks import check_count, check_scalar
from ..core.decide import is_zero, is_zero_vector
from ..core.formulas import foot_point
from ..core.tidy import tidy
from ..core.twist import Twist
from .displacement import exp6
from .subproblems import MAX_DECIDED_TERMS, Branch
from .transform import Transform

__all__ = ["Decomposition", "Stage", "StageForm", "decomposition", "stage_forms", "inverse_kinematics",
           "stage_order", "subproblem4", "free_values", "reduced_chain"]

#: the budget units charged for one subproblem (a few milliseconds of exact arithmetic)
STAGE_UNITS = 20_000

ORIGIN = ImmutableMatrix([0, 0, 0])


# --------------------------------------------------------------------- conditions
# Numbers here are nested radicals (each stage's sqrt inside the next one's data), kept as
# trees: screwsym's exact zero decision expands them (minutes), while a non-zero number's
# sign is certified by SymPy's evalf at 30 digits with strict=True (its error is tracked, and
# it raises where it cannot reach that accuracy).  Only where it cannot (a zero: a degenerate
# pose) is the exact decision run.  Symbols: the subproblems' exact decisions.

#: the digits of the certified evaluation of a number's sign
DIGITS = 30


def _kept(branches: list[Branch]) -> tuple[Branch, ...]:
    """The branches whose condition is not provably false."""
    return tuple(b for b in branches if b.condition is not S.false)


def _symbolic(e: Expr) -> bool | None:
    """:func:`is_zero` of a symbolic expression, None past ``MAX_DECIDED_TERMS`` terms (as the
    subproblems do: the decision of a large polynomial could take minutes)."""
    return None if len(e.args) > MAX_DECIDED_TERMS else is_zero(e)


def _symbolic_zero(e: Expr) -> Boolean:
    d = _symbolic(e)
    return Eq(e, 0) if d is None else S.true if d else S.false


def _symbolic_nonzero(e: Expr) -> Boolean:
    d = _symbolic(e)
    return Ne(e, 0) if d is None else S.false if d else S.true


def _symbolic_positive(e: Expr, *, or_zero: bool) -> Boolean:
    if _symbolic(e) is True:
        return S.true if or_zero else S.false
    return Ge(e, 0) if or_zero else Gt(e, 0)


def _sign(e: Expr) -> int | None:
    """The sign of a real number certified by evalf, or None (maybe zero; not real)."""
    if e.is_Rational:
        return 1 if e > 0 else -1 if e < 0 else 0
    try:
        v = e.evalf(DIGITS, strict=True)
    except (PrecisionExhausted, ValueError, TypeError):
        return None
    if not v.is_real or not v.is_Number:
        return None
    return 1 if v > 0 else -1 if v < 0 else 0


def _zero(e: Expr) -> Boolean:
    """``e = 0``: decided for numbers (a certified sign, else exactly), symbolic otherwise."""
    if e.is_number:
        s = _sign(e)
        if s is not None:
            return S.true if s == 0 else S.false
        d = is_zero(e)
        if d is not None:
            return S.true if d else S.false
    return _symbolic_zero(e)


def _nonzero(e: Expr) -> Boolean:
    z = _zero(e)
    return S.false if z is S.true else S.true if z is S.false else _symbolic_nonzero(e)


def _positive(e: Expr, *, or_zero: bool = False) -> Boolean:
    if e.is_number:
        s = _sign(e)
        if s is None and is_zero(e) is True:
            s = 0
        if s is not None:
            return S.true if (s > 0 or (or_zero and s == 0)) else S.false
    return _symbolic_positive(e, or_zero=or_zero)


def _clean(e: Expr) -> Expr:
    """A symbolic polynomial expanded; a number kept as its tree (see above)."""
    return e if e.is_number else e.expand()


# --------------------------------------------------------------------- Subproblem 4


def subproblem4(axis: Any, h: Any, p: Any, d: Any) -> tuple[Branch, ...]:
    r"""Subproblem 4 (IK-Geo): ``theta`` with ``h . R(axis, theta) p = d``.

    ``R(axis, theta)`` is the rotation of ``exp6`` about the line through the
    origin along ``axis`` (it turns by ``|axis| theta``).  With ``k = axis``,
    ``w = |k|`` and

        A = w^2 h.p - (k.p)(k.h),   B = w h.(k x p),   C = w^2 d - (k.p)(k.h),

    the equation is ``A cos(w theta) + B sin(w theta) = C``: two solutions
    ``(atan2(B, A) +- atan2(sqrt(A^2 + B^2 - C^2), C)) / w`` where the
    discriminant is positive, one where it is zero, ``theta`` free (a real
    ``Dummy``) where ``A = B = C = 0``.

    >>> from screwsym.motion.inverse_kinematics import subproblem4
    >>> for b in subproblem4([0, 0, 1], [1, 0, 0], [1, 0, 0], 0): print(b)
    Branch(condition=True, values=(-pi/2,))
    Branch(condition=True, values=(pi/2,))
    >>> subproblem4([0, 0, 1], [1, 0, 0], [1, 0, 0], 2)      # |h . R p| <= 1 < 2
    ()
    """
    k, hh, pp = (ImmutableMatrix(x) for x in (axis, h, p))
    if k.shape != (3, 1) or hh.shape != (3, 1) or pp.shape != (3, 1):
        raise ValueError("axis, h, p: expected 3-vectors")
    d = check_scalar(d, "d")
    ww = _clean(k.dot(k))
    w = _length(ww)
    kp_kh = _clean(k.dot(pp) * k.dot(hh))
    A = _clean(ww * hh.dot(pp) - kp_kh)
    B = _clean(w * hh.dot(k.cross(pp)))
    C = _clean(ww * d - kp_kh)
    D = _clean(A**2 + B**2 - C**2)
    phi = atan2(B, A)
    moving = _nonzero(_clean(A**2 + B**2))
    two = And(moving, _positive(D, or_zero=False))
    return _kept([
        Branch(two, ((phi - atan2(sqrt(D), C)) / w,)),
        Branch(two, ((phi + atan2(sqrt(D), C)) / w,)),
        Branch(And(moving, _zero(D)), ((phi + atan2(0, C)) / w,)),
        Branch(And(_zero(_clean(A**2 + B**2)), _zero(C)), (Dummy("theta", real=True),)),
    ])


def _slide(v: ImmutableMatrix, p: ImmutableMatrix, r: ImmutableMatrix,
           delta2: Expr) -> tuple[Branch, ...]:
    """``d`` with ``|p + d v - r|^2 = delta2``: a prismatic joint's distance subproblem.

    ``a d^2 + 2 b d + e = 0`` with ``a = v.v``, ``b = v.(p - r)``,
    ``e = |p - r|^2 - delta2``: two roots where ``b^2 - a e > 0``, one where it is 0.
    """
    u = p - r
    a, b = _clean(v.dot(v)), _clean(v.dot(u))
    D = _clean(b**2 - a * (_clean(u.dot(u)) - delta2))
    two = _positive(D, or_zero=False)
    return _kept([
        Branch(two, ((-b - sqrt(D)) / a,)),
        Branch(two, ((-b + sqrt(D)) / a,)),
        Branch(_zero(D), (-b / a,)),
    ])


def _sp3(t: Twist, p: ImmutableMatrix, q: ImmutableMatrix, delta2: Expr) -> tuple[Branch, ...]:
    """Subproblem 3, ``|exp6(t, theta) p - q|^2 = delta2``, as
    :func:`~screwsym.motion.subproblems.subproblem3` (same formulas and branches) with the
    conditions decided as above."""
    omega, r = t.omega, _point(t)
    A, B = omega.cross(p - r).applyfunc(_clean), omega.cross(q - r).applyfunc(_clean)
    ww = _clean(omega.dot(omega))
    w = _length(ww)
    uu, vv = _clean(A.dot(A)), _clean(B.dot(B))
    along = _clean(omega.dot(p - q))
    c = _clean(uu + vv - ww * delta2 + along**2)
    D = _clean(4 * uu * vv - c**2)
    theta0 = atan2(_clean(omega.dot(A.cross(B))), _clean(w * A.dot(B))) / w
    moving = _nonzero(_clean(uu * vv))
    two = And(moving, _positive(D))
    return _kept([
        Branch(two, (theta0 - atan2(sqrt(D), c) / w,)),
        Branch(two, (theta0 + atan2(sqrt(D), c) / w,)),
        Branch(And(moving, _zero(D)), (theta0 + atan2(0, c) / w,)),
        Branch(And(_zero(_clean(uu * vv)), _zero(c)), (Dummy("theta", real=True),)),
    ])


# --------------------------------------------------------------------- axes


def _revolute(t: Twist) -> bool:
    return is_zero_vector(t.omega) is False and is_zero(t.omega.dot(t.v_O)) is True


def _prismatic(t: Twist) -> bool:
    return is_zero_vector(t.omega) is True


def _point(t: Twist) -> ImmutableMatrix:
    """The point of a revolute axis nearest the origin."""
    return ImmutableMatrix(foot_point(t.omega, t.v_O)).applyfunc(_tidy_number)


def _tidy_number(e: Expr) -> Expr:
    return tidy(e) if e.is_number else e


def _parallel(a: ImmutableMatrix, b: ImmutableMatrix) -> bool:
    return is_zero_vector(a.cross(b)) is True


def _meet(ta: Twist, tb: Twist) -> ImmutableMatrix | None:
    """The point where two revolute axes meet (decided exactly), or None."""
    if not (_revolute(ta) and _revolute(tb)):
        return None
    n = ta.omega.cross(tb.omega)
    if is_zero_vector(n) is not False:
        return None
    ra, rb = _point(ta), _point(tb)
    if is_zero(n.dot(rb - ra)) is not True:
        return None
    s = (rb - ra).cross(tb.omega).dot(n) / n.dot(n)
    return (ra + ta.omega * s).applyfunc(_tidy_number)


def _on(t: Twist, x: ImmutableMatrix) -> bool:
    return is_zero_vector(t.omega.cross(x - _point(t))) is True


def _negated(t: Twist) -> Twist:
    return Twist(-t.omega, -t.v_O)


# --------------------------------------------------------------------- motions
# A motion is a pair (R, p) of matrices here: Transform's constructor checks R is a rotation,
# an exact decision per product, while these products are rotations by construction.

Motion = tuple[ImmutableMatrix, ImmutableMatrix]


def _entry(e: Expr) -> Expr:
    """A number's sines and cosines of sums expanded and brought to lowest terms (symbols: as is)."""
    return e


def motion_exp(t: Twist, q: Expr) -> Motion:
    """``exp6(t, q)`` as ``(R, p)``, numbers tidied."""
    T = exp6(t, q)
    return T.R.applyfunc(_entry), T.p.applyfunc(_entry)


def motion_product(a: Motion, b: Motion) -> Motion:
    """The product of two motions ``(R, p)``, entries tidied (``numeric.ik`` builds its program with it).

    >>> from sympy import pi
    >>> from screwsym import Twist
    >>> turn = motion_exp(Twist.rotation([0, 0, 1], point=[1, 0, 0]), pi / 2)
    >>> turn[1].T                                   # the origin goes to (1, -1, 0)
    Matrix([[1, -1, 0]])
    >>> motion_product(turn, motion_inverse(turn))[1].T
    Matrix([[0, 0, 0]])
    """
    return (a[0] * b[0]).applyfunc(_clean_entry), (a[0] * b[1] + a[1]).applyfunc(_clean_entry)


def motion_inverse(a: Motion) -> Motion:
    """The inverse of a motion ``(R, p)``: ``(R^T, -R^T p)``."""
    return a[0].T, (-a[0].T * a[1]).applyfunc(_clean_entry)


def _product(ts: Sequence[Twist], qs: Sequence[Expr]) -> Motion:
    M: Motion = (ImmutableMatrix.eye(3), ORIGIN)
    for t, q in zip(ts, qs, strict=True):
        M = motion_product(M, motion_exp(t, q))
    return M


def _clean_entry(e: Expr) -> Expr:
    return e


def _at(T: Motion, x: ImmutableMatrix) -> ImmutableMatrix:
    return ImmutableMatrix(T[0] * x + T[1]).applyfunc(_clean_entry)


def _dir(R: ImmutableMatrix, x: ImmutableMatrix) -> ImmutableMatrix:
    return ImmutableMatrix(R * x).applyfunc(_clean_entry)


# --------------------------------------------------------------------- implied subproblems
# Subproblems 1 and 2 as the decompositions call them: their existence conditions
# (omega . (p - q) = 0 and |u'| = |v'| for Subproblem 1, |u| = |v| for Subproblem 2) follow
# from the earlier stages for a rigid T (each stage's comment says why), so they are not
# decided again: for numbers that decision is a proof that an algebraic number with nested
# radicals is zero (a minimal polynomial: minutes), and it can only come out True.


def _sp1(omega: ImmutableMatrix, r: ImmutableMatrix, p: ImmutableMatrix, q: ImmutableMatrix,
         given: Boolean = S.true) -> list[Branch]:
    """Subproblem 1 (its existence implied): the angle, free where ``p`` is on the axis."""
    A, B = omega.cross(p - r).applyfunc(_clean), omega.cross(q - r).applyfunc(_clean)
    ww = _clean(omega.dot(omega))
    w = _length(ww)
    uu = _clean(A.dot(A))
    return [Branch(And(given, _nonzero(uu)),
                   (atan2(_clean(omega.dot(A.cross(B))), _clean(w * A.dot(B))) / w,)),
            Branch(And(given, _zero(uu)), (Dummy("theta", real=True),))]


def _sp2(o1: ImmutableMatrix, o2: ImmutableMatrix, r: ImmutableMatrix, p: ImmutableMatrix,
         q: ImmutableMatrix) -> tuple[Branch, ...]:
    """Subproblem 2 for axes meeting at ``r`` (``|p - r| = |q - r|`` implied): as
    :func:`~screwsym.motion.subproblems.subproblem2`, two branches where ``g^2 > 0``, one where 0."""
    u, v = p - r, q - r
    nn = _clean(o1.cross(o2).dot(o1.cross(o2)))
    g11, g22, g12 = (_clean(e) for e in (o1.dot(o1), o2.dot(o2), o1.dot(o2)))
    o1v, o2u = _clean(o1.dot(v)), _clean(o2.dot(u))
    a = _clean((g22 * o1v - g12 * o2u) / nn)
    b = _clean((g11 * o2u - g12 * o1v) / nn)
    gg = _clean((_clean(u.dot(u)) - a**2 * g11 - 2 * a * b * g12 - b**2 * g22) / nn)
    n = o1.cross(o2)
    branches = []
    for g, cond in ((-_length(gg), _positive(gg, or_zero=False)),
                    (_length(gg), _positive(gg, or_zero=False)),
                    (S.Zero, _zero(gg))):
        if cond is S.false:
            continue
        z = (o1 * a + o2 * b + n * g).applyfunc(_clean) + r
        for b2 in _sp1(o2, r, p, z, cond):
            for b1 in _sp1(o1, r, z, q, b2.condition):
                if g != 0 and (b1.values[0].is_Dummy or b2.values[0].is_Dummy):
                    continue  # a point on an axis has g = 0 (subproblem2's comment)
                branches.append(Branch(b1.condition, (b1.values[0], b2.values[0])))
    return _kept(branches)


# --------------------------------------------------------------------- stages
# A stage is split in two: ``prepare(g, q)`` computes the points (or directions) its
# subproblem needs from the pose and the joints found before, and ``solve(*points)`` is
# the subproblem on them.  The split keeps the closed forms small (the subproblem's formulas
# are in the points, not in the pose: the compiled solver of screwsym.numeric.ik evaluates
# the two in turn), and it names, for a reader, what each stage looks at.

#: ``prepare(g, known joint values) -> points``, ``solve(*points) -> branches``
Prepare = Callable[[Motion, Mapping[int, Expr]], tuple[ImmutableMatrix, ...]]
Solve = Callable[..., Sequence[Branch]]


class Stage(NamedTuple):
    """One step of a decomposition: the (0-based) ``joints`` it solves, then ``prepare`` and
    ``solve`` (see above), and its ``name``."""

    joints: tuple[int, ...]
    prepare: Prepare
    solve: Solve
    name: str


class Decomposition(NamedTuple):
    r"""How a 6-joint chain's inverse kinematics splits into subproblems.

    ``kind`` names the structure (see the module docstring), ``reversed`` says
    whether it is read from the tip (the stages then solve the reversed chain
    ``(-$_6, ..., -$_1)`` for ``g^-1``, its joint ``i`` being joint ``5 - i``),
    ``stages`` the steps in order, each solving ``g = (R, p)`` given the joints before.
    """

    kind: str
    reversed: bool
    stages: tuple[Stage, ...]


def _distance(t: Twist, p: ImmutableMatrix, r: ImmutableMatrix, delta2: Expr) -> Sequence[Branch]:
    """The joint value of ``t`` putting ``exp6(t, q) p`` at the distance ``sqrt(delta2)`` from ``r``."""
    if _prismatic(t):
        return _slide(t.v_O, p, r, delta2)
    return _sp3(t, p, r, delta2)


def _square(x: ImmutableMatrix) -> Expr:
    return _clean(x.dot(x))


def _spherical_wrist(t: Sequence[Twist]) -> tuple[Stage, ...] | None:
    c = _meet(t[3], t[4])
    if c is None or not _revolute(t[5]) or not _on(t[5], c) or _parallel(t[4].omega, t[5].omega):
        return None
    r01, r12 = _meet(t[0], t[1]), _meet(t[1], t[2])
    if r01 is not None and (_revolute(t[2]) or _prismatic(t[2])):
        first = _wrist_centre_a(t, c, r01)
    elif r12 is not None and (_revolute(t[0]) or _prismatic(t[0])):
        first = _wrist_centre_b(t, c, r12)
    else:
        return None
    w3, w4, w5 = t[3].omega, t[4].omega, t[5].omega
    p_on6, x_off6, r6 = c + w5, c + w4.cross(w5), _point(t[5])

    def wrist(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # E = (e1 e2 e3)^-1 g fixes c (the first stages put g c = e1 e2 e3 c): |E p - c| = |p - c|
        E = motion_product(motion_inverse(_product(t[:3], [q[0], q[1], q[2]])), g)
        return (_at(E, p_on6),)

    def last(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # (e1 ... e5)^-1 g fixes c and c + w6: a turn about axis 6, so Subproblem 1's data agree
        E = motion_product(motion_inverse(_product(t[:5], [q[i] for i in range(5)])), g)
        return (_at(E, x_off6),)

    return (*first,
            Stage((3, 4), wrist, lambda y: _sp2(w3, w4, c, p_on6, y),
                  "subproblem 2: joints 4 and 5 on a point of axis 6"),
            Stage((5,), last, lambda y: _sp1(w5, r6, x_off6, y), "subproblem 1: joint 6"))


def _wrist_centre_a(t: Sequence[Twist], c: ImmutableMatrix, r: ImmutableMatrix) -> tuple[Stage, ...]:
    """Axes 1 and 2 meet at ``r``: joint 3 from the distance to ``r``, then Subproblem 2."""
    w0, w1 = t[0].omega, t[1].omega

    def third(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        return (_at(g, c),)

    def shoulder(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # |e3 c - r| = |g c - r| by the stage before
        return _at(motion_exp(t[2], q[2]), c), _at(g, c)

    return (Stage((2,), third, lambda y: _distance(t[2], c, r, _square(y - r)),
                  "subproblem 3: joint 3 from the distance of the wrist centre"),
            Stage((0, 1), shoulder, lambda x, y: _sp2(w0, w1, r, x, y),
                  "subproblem 2: joints 1 and 2 to the wrist centre"))


def _wrist_centre_b(t: Sequence[Twist], c: ImmutableMatrix, r: ImmutableMatrix) -> tuple[Stage, ...]:
    """Axes 2 and 3 meet at ``r``: joint 1 from the distance to ``r`` (turned back), then Subproblem 2."""
    back, w1, w2 = _negated(t[0]), t[1].omega, t[2].omega

    def first(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        return (_at(g, c),)

    def elbow(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # |e1^-1 g c - r| = |c - r| by the stage before
        return (_at(motion_product(motion_inverse(motion_exp(t[0], q[0])), g), c),)

    return (Stage((0,), first, lambda y: _distance(back, y, r, _square(c - r)),
                  "subproblem 3: joint 1 from the distance of the wrist centre"),
            Stage((1, 2), elbow, lambda y: _sp2(w1, w2, r, c, y),
                  "subproblem 2: joints 2 and 3 to the wrist centre"))


def _three_parallel(t: Sequence[Twist]) -> tuple[Stage, ...] | None:
    if not all(_revolute(x) for x in t):
        return None
    w = t[1].omega
    if not (_parallel(w, t[2].omega) and _parallel(w, t[3].omega)):
        return None
    c = _meet(t[4], t[5])
    if c is None or _parallel(w, t[0].omega) or _parallel(w, t[4].omega):
        return None
    r0, r1, p3 = _point(t[0]), _point(t[1]), _point(t[3])
    w0, w3, w4, w5 = t[0].omega, t[3].omega, t[4].omega, t[5].omega
    x_off3 = p3 + w.cross(w4)
    height = _clean(w.dot(c - r0))

    def first(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # e2 e3 e4 is planar (turns about w, moves normal to w): w . e1^-1 g c = w . c
        return (_at(g, c) - r0,)

    def fifth(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # w^T R1^T R_g w6 = w^T R2 R3 R4 R5 R6 w6 = w^T R5 w6
        return (_dir(motion_exp(t[0], q[0])[0].T * g[0], w5),)

    def sixth(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # R6^T R5^T w = R_g^T R1 w: both unit-length images of w, their w6 parts equal by the
        # stage before (w . R5 w6 = w . R1^T R_g w6)
        return _dir(motion_exp(t[4], q[4])[0].T, w), _dir(g[0].T * motion_exp(t[0], q[0])[0], w)

    def planar(g: Motion, q: Mapping[int, Expr]) -> Motion:
        # e2 e3 e4 = e1^-1 g e6^-1 e5^-1: it turns about w and keeps w . x (the stages before)
        rest = motion_product(motion_exp(t[4], q[4]), motion_exp(t[5], q[5]))
        return motion_product(motion_product(motion_inverse(motion_exp(t[0], q[0])), g), motion_inverse(rest))

    def third(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        return (_at(planar(g, q), p3),)

    def second(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # |e3 p4 - r2| = |P p4 - r2| (stage before) and both at the height w . p4
        return _at(motion_exp(t[2], q[2]), p3), _at(planar(g, q), p3)

    def fourth(g: Motion, q: Mapping[int, Expr]) -> tuple[ImmutableMatrix, ...]:
        # (e2 e3)^-1 P fixes p4 and turns about w: a turn about axis 4
        E = motion_product(motion_inverse(_product(t[1:3], [q[1], q[2]])), planar(g, q))
        return (_at(E, x_off3),)

    return (Stage((0,), first, lambda y: subproblem4(-w0, w, y, height),
                  "subproblem 4: joint 1 from the height of axes 5 and 6's point"),
            Stage((4,), fifth, lambda m: subproblem4(w4, w, w5, _clean(w.dot(m))),
                  "subproblem 4: joint 5 from the parallel axes' direction"),
            Stage((5,), sixth, lambda a, b: _sp1(-w5, ORIGIN, a, b),
                  "subproblem 1: joint 6 on directions"),
            Stage((2,), third, lambda y: _sp3(t[2], p3, r1, _square(y - r1)),
                  "subproblem 3: joint 3 of the planar arm"),
            Stage((1,), second, lambda a, b: _sp1(w, r1, a, b), "subproblem 1: joint 2"),
            Stage((3,), fourth, lambda b: _sp1(w3, p3, x_off3, b), "subproblem 1: joint 4"))


def _length(e: Expr) -> Expr:
    return sqrt(e)


def decomposition(twists: Sequence[Twist]) -> Decomposition:
    r"""The decomposition of a 6-joint chain's inverse kinematics, found exactly from its twists.

    >>> from screwsym.motion.chain import ur5
    >>> d = decomposition(ur5().twists)
    >>> d.kind, d.reversed, [s.joints for s in d.stages]
    ('three parallel axes', False, [(0,), (4,), (5,), (2,), (1,), (3,)])

    A chain without one of the structures gets a ``ValueError`` naming the axes:

    >>> from screwsym import Twist
    >>> z = [Twist.rotation([0, 0, 1], point=[i, 0, 0]) for i in range(3)]
    >>> x = [Twist.rotation([1, 0, 0], point=[0, i, 1]) for i in range(3)]
    >>> decomposition(z + x)
    Traceback (most recent call last):
    ...
    ValueError: twists: no closed-form decomposition: axes 4, 5, 6 do not meet in a point, nor axes 1, 2, 3; axes 2, 3, 4 are not parallel with axes 5, 6 meeting, nor axes 3, 4, 5 with axes 1, 2 meeting; the closed form needs one of these (Pieper's condition); give a joint a value with free= or solve numerically
    """
    t = tuple(twists)
    if len(t) != 6:
        raise ValueError(f"twists: a closed-form decomposition needs six joints to solve, got {len(t)}; "
                         "give the others values with free=")
    for i, x in enumerate(t):
        if not (_revolute(x) or _prismatic(x)):
            raise ValueError(f"twists[{i}]: expected a revolute or prismatic joint (pitch 0 or a "
                             f"translation), got {x}")
    back = tuple(_negated(x) for x in reversed(t))
    for kind, build in (("spherical wrist", _spherical_wrist), ("three parallel axes", _three_parallel)):
        for rev, chain in ((False, t), (True, back)):
            stages = build(chain)
            if stages is not None:
                return Decomposition(kind + (" reversed" if rev else ""), rev, stages)
    raise ValueError(
        "twists: no closed-form decomposition: axes 4, 5, 6 do not meet in a point, nor axes 1, 2, 3; "
        "axes 2, 3, 4 are not parallel with axes 5, 6 meeting, nor axes 3, 4, 5 with axes 1, 2 "
        "meeting; the closed form needs one of these (Pieper's condition); give a joint a value "
        "with free= or solve numerically"
    )


# --------------------------------------------------------------------- the solver


def free_values(free: Any, n: int) -> dict[int, Expr]:
    """``free`` as ``{joint index: value}``: indices (0-based) get the symbols ``q1 ... qn``.

    >>> free_values([6], 7)
    {6: q7}
    >>> free_values({6: 0}, 7)
    {6: 0}
    """
    if isinstance(free, Mapping):
        items = list(free.items())
    else:
        if isinstance(free, (str, bytes)) or not isinstance(free, Sequence):
            raise TypeError(f"free: expected a sequence of joint indices or a dict {{index: value}}, "
                            f"got {type(free).__name__}")
        items = [(k, None) for k in free]
    out: dict[int, Expr] = {}
    for k, v in items:
        if isinstance(k, bool) or not isinstance(k, int) or not 0 <= k < n:
            raise ValueError(f"free: expected joint indices 0 .. {n - 1}, got {k!r}")
        if k in out:
            raise ValueError(f"free: joint {k} given twice")
        out[k] = Symbol(f"q{k + 1}", real=True) if v is None else check_scalar(v, f"free[{k}]")
    return out


def reduced_chain(twists: Sequence[Twist], home: Transform, T: Transform,
            free: Mapping[int, Expr]) -> tuple[tuple[Twist, ...], Motion, tuple[int, ...]]:
    """The twists left to solve, the target ``g`` they must reach, and their joint indices.

    ``g = T M^-1``; each free joint ``k`` (last first) moves right:
    ``e_k e_j = exp6(Ad(e_k) $_j) e_k``, so ``g <- g e_k^-1`` and the later twists are carried.
    """
    ts = list(twists)
    index = list(range(len(ts)))
    H = home.inverse()
    g: Motion = motion_product((T.R, T.p), (H.R, H.p))
    for k in sorted(free, reverse=True):
        pos = index.index(k)
        E = motion_exp(ts[pos], free[k])
        g = motion_product(g, motion_inverse(E))
        ts = ts[:pos] + [tidy(Transform._new(*E).apply(x)) for x in ts[pos + 1:]]
        index.pop(pos)
    return tuple(ts), g, tuple(index)


#: the pose's entries in the closed forms: ``R`` row by row, then ``p``
G = ImmutableMatrix([Dummy(f"g{i}", real=True) for i in range(12)])
#: the joints found by earlier stages, in the closed forms
Q = ImmutableMatrix([Dummy(f"q{i + 1}", real=True) for i in range(6)])


class StageForm(NamedTuple):
    """A stage in closed form: its ``points`` (expressions in :data:`G` and :data:`Q`),
    the ``symbols`` standing for them, and the subproblem's ``branches`` in those symbols."""

    stage: Stage
    points: ImmutableMatrix
    symbols: ImmutableMatrix
    branches: tuple[Branch, ...]


@lru_cache(maxsize=32)
def stage_forms(twists: tuple[Twist, ...]) -> tuple[Decomposition, tuple[StageForm, ...]]:
    """The decomposition of ``twists`` and each stage's closed form (cached per twists).

    >>> from screwsym.motion.chain import ur5
    >>> plan, forms = stage_forms(ur5().twists)
    >>> [len(f.branches) for f in forms]
    [3, 3, 2, 3, 2, 1]
    """
    plan = decomposition(twists)
    g: Motion = (ImmutableMatrix(3, 3, list(G[:9])), ImmutableMatrix(G[9:]))
    known = dict(enumerate(Q))
    forms = []
    for k, stage in enumerate(plan.stages):
        charge(STAGE_UNITS)
        points = stage.prepare(g, known)
        symbols = [ImmutableMatrix([Dummy(f"x{k}_{i}_{j}", real=True) for j in range(x.rows)])
                   for i, x in enumerate(points)]
        branches = _kept(list(stage.solve(*symbols)))
        forms.append(StageForm(stage, ImmutableMatrix.vstack(*points),
                               ImmutableMatrix.vstack(*symbols), branches))
    return plan, tuple(forms)


def _walk(forms: Sequence[StageForm], g: Motion) -> list[tuple[Boolean, dict[int, Expr]]]:
    """Every branch: each stage's closed form with the pose substituted (the joints found
    before stay the symbols of :data:`Q`: substituting their closed forms nests radicals in
    radicals, see :func:`inverse_kinematics`)."""
    pose = dict(zip(G, [*g[0], *g[1]], strict=True))
    found: list[tuple[Boolean, dict[int, Expr]]] = [(S.true, {})]
    for form in forms:
        points = form.points.xreplace(pose)
        at = dict(zip(form.symbols, points, strict=True))
        here = [(b.condition.xreplace(at), [v.xreplace(at) for v in b.values]) for b in form.branches]
        grown = []
        for cond, q in found:
            charge(STAGE_UNITS)
            for c, values in here:
                both = And(cond, c)
                if both is S.false:
                    continue
                grown.append((both, {**q, **dict(zip(form.stage.joints, values, strict=True))}))
        found = grown
    return found


def stage_order(chain: Any, free: Any = ()) -> tuple[int, ...]:
    """The joints (0-based) in the order :func:`inverse_kinematics` solves them.

    >>> from screwsym.motion.chain import ur5
    >>> stage_order(ur5())
    (0, 4, 5, 2, 1, 3)
    """
    given = free_values(free, chain.n_joints)
    index = [i for i in range(chain.n_joints) if i not in given]
    twists = tuple(t for i, t in enumerate(chain.twists) if i not in given)
    plan, _ = stage_forms(twists) if not given else (decomposition(
        reduced_chain(chain.twists, chain.home, Transform.identity(), given)[0]), None)
    order = list(reversed(index)) if plan.reversed else index
    return tuple(order[j] for stage in plan.stages for j in stage.joints)


def _pose(T: Any) -> Transform | ImmutableMatrix:
    if isinstance(T, Transform):
        return T
    if not isinstance(T, MatrixBase) or T.shape != (4, 4):
        raise TypeError(f"T: expected a Transform or a 4x4 SymPy matrix, got {type(T).__name__}")
    return ImmutableMatrix(T)


def inverse_kinematics(chain: Any, T: Any, free: Any = (), *, budget: int = BUDGET) -> tuple[Branch, ...]:
    r"""Every closed-form branch ``(condition, q)`` of ``chain.forward(q) == T``, stage by stage.

    See the module docstring for the decompositions.  ``T`` is a
    :class:`~screwsym.motion.transform.Transform` (exact or symbolic) or a 4x4
    matrix of symbols (the closed forms hold where it is a rigid motion).
    ``free`` are joint indices (0-based; their values the symbols ``q<k+1>``) or
    a dict ``{index: value}`` of joints given.

    Each branch's ``values`` is an ``n``-tuple: joint ``k``'s closed form in
    ``T``'s entries and in the symbols ``q1 ... qn`` of the joints solved before it
    (the order of :func:`stage_order`), as IKFast's generated code reads: substitute
    the values in that order.  They are not substituted here: each stage's angle is an
    ``atan2`` with a square root, and substituting nests those radicals stage in stage,
    where exact decisions (and even SymPy's automatic evaluation) take minutes.  The
    conditions likewise: decided where they hold numbers (the first stage's, for a pose
    of numbers), symbolic otherwise.  A free parameter of a degenerate branch (a
    wrist singularity: joint 4 free, joint 6 then depends on it) is a real
    ``Dummy``.  :func:`screwsym.numeric.inverse_kinematics_function` evaluates the
    same closed forms for numbers, fast.  ``budget`` bounds the work
    (:mod:`screwsym.algebra.budget`).

    >>> from sympy import Matrix, symbols
    >>> from screwsym.motion.chain import ur5
    >>> T = Matrix(4, 4, [*symbols("r11 r12 r13 px r21 r22 r23 py r31 r32 r33 pz", real=True),
    ...                   0, 0, 0, 1])
    >>> branches = inverse_kinematics(ur5(), T)
    >>> len(branches), stage_order(ur5())
    (108, (0, 4, 5, 2, 1, 3))
    >>> generic = [b for b in branches if not any(v.is_Dummy for v in b.values)]
    >>> len(generic)
    27
    >>> print(generic[0].values[4])
    -atan2(sqrt(1 - (-r13*sin(q1) + r23*cos(q1))**2), -r13*sin(q1) + r23*cos(q1))
    """
    pose = _pose(T)
    n = chain.n_joints
    given = free_values(free, n)
    budget = check_count(budget, "budget")
    with case_budget(budget, "inverse_kinematics"):
        if isinstance(pose, Transform):
            T = pose
        else:
            T = Transform._new(ImmutableMatrix(pose[:3, :3]), ImmutableMatrix(pose[:3, 3]))
        twists, g, index = reduced_chain(chain.twists, chain.home, T, given)
        plan, forms = stage_forms(twists)
        if plan.reversed:
            g = motion_inverse(g)
        order = list(reversed(index)) if plan.reversed else list(index)
        names = {Q[i]: Symbol(f"q{order[i] + 1}", real=True) for i in range(6)}
        branches = []
        for cond, q in _walk(forms, g):
            values: list[Expr] = [S.Zero] * n
            for k, v in given.items():
                values[k] = v
            for i in range(6):
                values[order[i]] = q[i].xreplace(names)
            branches.append(Branch(cond.xreplace(names), tuple(values)))
    return tuple(branches)
