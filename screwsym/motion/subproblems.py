r"""The Paden–Kahan subproblems in exact closed form, every branch with its condition.

Explanation
===========

Inverse kinematics by the product of exponentials reduces to three small
geometric problems (Paden 1985; Murray, Li & Sastry 1994, Section 3.2.2):

1. :func:`subproblem1`: the angle ``theta`` of a rotation about an axis that
   takes a point ``p`` to a point ``q``;
2. :func:`subproblem2`: the angles ``(theta1, theta2)`` with
   ``exp6(xi1, theta1) exp6(xi2, theta2) p = q`` for two axes that meet;
3. :func:`subproblem3`: the angles ``theta`` of a rotation that takes ``p`` to
   the distance ``delta`` from ``q``.

Each returns every solution branch as a tuple of :class:`Branch`
``(condition, values)``: ``values`` a tuple of angles (``atan2`` forms), and
``condition`` a SymPy Boolean saying where that branch exists.  The degenerate
cases are branches of their own: a point on the axis leaves its angle free (a
fresh real ``Dummy`` stands for it), Subproblem 2 has two solutions or one,
Subproblem 3 two, one (tangent) or a free angle.  With numbers the conditions
are decided exactly (``True`` or ``False``, no tolerance) and only the branches
that exist are returned (none: the empty tuple); with symbols they stay
symbolic, the symbols taken as real.  Angles are modulo a full turn.  A number
the exact decision cannot settle (``cos(3 atan(8/15))``, which SymPy leaves
unreduced) is treated like a symbol: its condition stays an unevaluated ``Eq``
and the branch is kept, never dropped on a guess.

An axis is a :class:`~screwsym.core.twist.Twist` of pitch 0 (a pure
rotation), or a direction with ``point=``, read as
``Twist.rotation(direction, point=point)``.  The angle is that of
:func:`~screwsym.motion.displacement.exp6`: ``exp6(twist, theta)`` turns by
``|omega| theta``, so a unit ``omega`` gives the geometric angle.  Entries are
exact (integers, rationals, algebraic numbers, symbols); floats are refused,
since an exact equality on rounded numbers would silently answer "no solution".

References
==========

B. Paden, *Kinematics and Control of Robot Manipulators*, PhD thesis, UC Berkeley 1985.
R. M. Murray, Z. Li & S. S. Sastry, *A Mathematical Introduction to Robotic
Manipulation*, CRC Press 1994, Section 3.2.2.
K. M. Lynch & F. C. Park, *Modern Robotics*, Cambridge 2017, Section 6.1.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from sympy import (
    And,
    Dummy,
    Eq,
    Expr,
    Float,
    Ge,
    Gt,
    ImmutableMatrix,
    Ne,
    S,
    atan2,
    sqrt,
)
from sympy.logic.boolalg import Boolean

from ..core.checks import check_nonzero_vector, check_scalar, check_vector, describe
from ..core.decide import is_zero, is_zero_vector
from ..core.formulas import foot_point
from ..core.screw import Screw
from ..core.tidy import tidy
from ..core.twist import Twist

__all__ = ["Branch", "subproblem1", "subproblem2", "subproblem3", "subproblem5"]


class Branch(NamedTuple):
    r"""One solution branch: the ``condition`` where it exists and its ``values`` (angles).

    >>> from sympy import true
    >>> Branch(true, (0,)).values
    (0,)
    """

    condition: Boolean
    values: tuple[Expr, ...]


# --------------------------------------------------------------------- conditions


#: a symbolic condition with more terms than this is left undecided (its exact zero
#: decision could take minutes): the branch keeps its ``Eq``/``Ne``, never a guess
MAX_DECIDED_TERMS = 200


def _decided(e: Expr) -> bool | None:
    """:func:`is_zero`, or None for a large symbolic polynomial (see :data:`MAX_DECIDED_TERMS`)."""
    if not e.is_number and len(e.args) > MAX_DECIDED_TERMS:
        return None
    return is_zero(e)


def _zero(e: Expr) -> Boolean:
    """``e = 0`` as a Boolean: ``True``/``False`` where decided exactly, else ``Eq(e, 0)``."""
    d = _decided(e)
    if d is None:
        return Eq(e, 0)
    return S.true if d else S.false


def _nonzero(e: Expr) -> Boolean:
    """``e != 0`` as a Boolean (see :func:`_zero`)."""
    d = _decided(e)
    if d is None:
        return Ne(e, 0)
    return S.false if d else S.true


def _positive(e: Expr, *, or_zero: bool) -> Boolean:
    """``e > 0`` (``e >= 0`` with ``or_zero``) as a Boolean, decided for numbers.

    A number is first decided zero or not exactly (:func:`is_zero`); a non-zero
    number's sign is then SymPy's (its evaluation at increasing precision).
    """
    d = _decided(e)
    if d is True:
        return S.true if or_zero else S.false
    if d is False and e.is_number:
        sign = e.is_positive
        if sign is not None:
            return S.true if sign else S.false
    return Ge(e, 0) if or_zero else Gt(e, 0)


def _kept(branches: list[Branch]) -> tuple[Branch, ...]:
    """The branches whose condition is not provably false."""
    return tuple(b for b in branches if b.condition is not S.false)


def _clean(e: Expr) -> Expr:
    """A polynomial quantity expanded (numbers in lowest terms)."""
    return tidy(e.expand()) if e.is_number else e.expand()


# --------------------------------------------------------------------- inputs


def _exact_point(value: Any, name: str) -> ImmutableMatrix:
    """A 3-vector of exact entries (see the module's note on floats)."""
    v = check_vector(value, name)
    _refuse_floats(v, name)
    return v


def _refuse_floats(v: Any, name: str) -> None:
    floats = v.atoms(Float)
    if floats:
        raise ValueError(
            f"{name}: expected exact entries (integers, rationals, algebraic numbers, symbols), "
            f"got the float {min(floats)}; the subproblems decide their conditions exactly "
            "(use Rational or nsimplify)"
        )


def _axis(axis: Any, point: Any, name: str) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    """``(omega, r)``: the rotation vector of ``axis`` and a point on it."""
    if isinstance(axis, Twist):
        if point is not None:
            raise TypeError(f"point: give it with a direction as {name}, not with a Twist")
        omega, v = axis.omega, axis.v_O
        _refuse_floats(axis.matrix, name)
        if is_zero_vector(omega) is True:
            raise ValueError(f"{name}: expected a rotation (a twist of pitch 0), got a "
                             f"translation {axis}")
        pitch = is_zero(omega.dot(v))
        if pitch is not True:
            raise ValueError(
                f"{name}: expected a rotation (a twist of pitch 0), got {axis} whose pitch "
                + ("is not 0" if pitch is False else "cannot be decided to be 0")
            )
        return omega, ImmutableMatrix(foot_point(omega, v))
    if isinstance(axis, Screw):
        raise TypeError(f"{name}: expected a Twist or a direction 3-vector, got {describe(axis)}")
    omega = check_nonzero_vector(axis, name, "a rotation axis needs a non-zero direction")
    _refuse_floats(omega, name)
    if point is None:
        raise TypeError(f"point: a direction as {name} needs the point= of its axis")
    return omega, _exact_point(point, "point")


def _length(ww: Expr) -> Expr:
    """``sqrt(ww)``, 1 for a unit axis."""
    return tidy(sqrt(ww)) if ww.is_number else sqrt(ww)


# --------------------------------------------------------------------- Subproblem 1


def _turn(omega: ImmutableMatrix, ww: Expr, A: ImmutableMatrix, B: ImmutableMatrix) -> Expr:
    """The angle from ``u'`` to ``v'`` about ``omega``, over ``|omega|`` (exp6's units).

    With ``A = omega x u``, ``B = omega x v`` (``u'``, ``v'`` turned a quarter and
    scaled by ``|omega|``): ``atan2(omega . (A x B), |omega| A . B) / |omega|``,
    polynomials in the data, no quotient to expand.
    """
    w = _length(ww)
    return atan2(_clean(omega.dot(A.cross(B))), _clean(w * A.dot(B))) / w


def _moment(omega: ImmutableMatrix, m: ImmutableMatrix, x: ImmutableMatrix) -> ImmutableMatrix:
    """``omega x (x - r) = omega x x + m`` for the axis's ``m = r x omega`` (a twist's ``v_O``)."""
    return (omega.cross(x) + m).applyfunc(_clean)


def subproblem1(axis: Any, p: Any, q: Any, *, point: Any = None) -> tuple[Branch, ...]:
    r"""Paden–Kahan Subproblem 1: ``theta`` with ``exp6(axis, theta) p = q``.

    Explanation
    ===========

    With ``r`` a point on the axis, ``u = p - r``, ``v = q - r`` and ``u'``,
    ``v'`` their projections on the plane normal to ``omega``, a solution
    exists iff ``omega . u = omega . v`` and ``|u'| = |v'|`` (Murray, Li &
    Sastry (3.18)-(3.20)); then

        theta = atan2(omega . (u' x v'), |omega| u' . v') / |omega|

    where ``u' != 0``, and ``theta`` is free where ``u' = 0`` (``p`` on the
    axis, and then ``q = p``): a fresh real ``Dummy``.

    Examples
    ========

    >>> from sympy import symbols
    >>> from screwsym import Twist
    >>> from screwsym.motion.subproblems import subproblem1
    >>> z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    >>> subproblem1(z, [1, 0, 0], [0, 1, 0])
    (Branch(condition=True, values=(pi/2,)),)
    >>> subproblem1(z, [1, 0, 0], [0, 2, 0])            # |u'| != |v'|: no branch
    ()
    >>> (b,) = subproblem1(z, [0, 0, 5], [0, 0, 5])     # p on the axis: theta free
    >>> b.values[0].is_Symbol
    True
    >>> x, y = symbols("x y", real=True)
    >>> for b in subproblem1(z, [1, 0, 0], [x, y, 0]): print(b)
    Branch(condition=Eq(x**2 + y**2 - 1, 0), values=(atan2(y, x),))

    Parameters
    ==========

    axis : Twist of pitch 0, or a direction 3-vector with ``point=``
    p, q : 3-vectors (numbers or symbols)
    point : a point on the axis, with a direction as ``axis``

    See Also
    ========

    subproblem2, subproblem3, screwsym.motion.displacement.exp6
    """
    omega, r = _axis(axis, point, "axis")
    pp, qq = _exact_point(p, "p"), _exact_point(q, "q")
    m = axis.v_O if isinstance(axis, Twist) else r.cross(omega)  # r x omega, polynomial
    A, B = _moment(omega, m, pp), _moment(omega, m, qq)
    ww = _clean(omega.dot(omega))
    return _kept(_sp1(omega, ww, A, B, [_zero(_clean(omega.dot(pp - qq)))], "theta", True))


def _sp1(omega: ImmutableMatrix, ww: Expr, A: ImmutableMatrix, B: ImmutableMatrix,
         given: list[Boolean], free: str, check_norms: bool) -> list[Branch]:
    """Subproblem 1's branches from ``A = omega x u``, ``B = omega x v``, under ``given``.

    ``|A| = |omega| |u'|``: ``u'`` is zero exactly where ``A . A`` is; with
    ``check_norms`` the condition ``|u'| = |v'|`` is added.
    """
    uu = _clean(A.dot(A))
    if check_norms:
        given = [*given, _zero(_clean(B.dot(B) - uu))]
    return [
        Branch(And(*given, _nonzero(uu)), (_turn(omega, ww, A, B),)),
        Branch(And(*given, _zero(uu)), (Dummy(free, real=True),)),
    ]


# --------------------------------------------------------------------- Subproblem 2


def _meeting_point(o1: ImmutableMatrix, r1: ImmutableMatrix, o2: ImmutableMatrix,
                   r2: ImmutableMatrix, nn: Expr) -> tuple[ImmutableMatrix, Boolean]:
    """The point where two non-parallel axes meet, and the condition that they meet."""
    n = o1.cross(o2)
    meet = _zero(_clean(n.dot(r2 - r1)))  # coplanar: the axes' mutual moment is zero
    if meet is S.false:
        raise ValueError("axis1, axis2: Subproblem 2 needs axes that meet; these are skew")
    s = (r2 - r1).cross(o2).dot(n) / nn
    return (r1 + o1 * s).applyfunc(lambda e: tidy(e) if e.is_number else e), meet


def subproblem2(axis1: Any, axis2: Any, p: Any, q: Any, *,
                point: Any = None) -> tuple[Branch, ...]:
    r"""Paden–Kahan Subproblem 2: ``(theta1, theta2)`` with ``exp6(axis1, theta1) exp6(axis2, theta2) p = q``.

    Explanation
    ===========

    The axes meet at ``r`` and are not parallel; ``u = p - r``, ``v = q - r``.
    The intermediate point ``c = exp6(axis2, theta2) p = exp6(axis1, -theta1) q``
    has ``c - r = a omega1 + b omega2 + g (omega1 x omega2)`` with (Murray, Li &
    Sastry (3.24)-(3.28), written for axes of any length, ``G`` their Gram
    matrix and ``N = |omega1 x omega2|^2 = det G``)

        a = (G22 omega1.v - G12 omega2.u) / N,   b = (G11 omega2.u - G12 omega1.v) / N,
        g^2 = (|u|^2 - a^2 G11 - 2 a b G12 - b^2 G22) / N.

    A solution exists iff ``|u| = |v|`` and ``g^2 >= 0``: two where ``g^2 > 0``
    (``g = +-sqrt(g^2)``), one where ``g^2 = 0``; each angle is then
    Subproblem 1 (``theta2`` from ``p`` to ``c``, ``theta1`` from ``c`` to
    ``q``), free where ``u`` lies on axis 2 (resp. ``v`` on axis 1), which
    happens only with ``g = 0``.

    Examples
    ========

    >>> from screwsym import Twist
    >>> from screwsym.motion.subproblems import subproblem2
    >>> z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    >>> y = Twist.rotation([0, 1, 0], point=[0, 0, 0])
    >>> for b in subproblem2(z, y, [0, 0, 1], [0, 1, 0]): print(b)
    Branch(condition=True, values=(-pi/2, -pi/2))
    Branch(condition=True, values=(pi/2, pi/2))
    >>> subproblem2(z, y, [0, 0, 1], [0, 2, 0])     # |u| != |v|
    ()

    Parameters
    ==========

    axis1, axis2 : Twists of pitch 0 whose axes meet, or two directions with
        ``point=`` their common point
    p, q : 3-vectors (numbers or symbols)

    See Also
    ========

    subproblem1, subproblem3
    """
    twists = isinstance(axis1, Twist), isinstance(axis2, Twist)
    if twists[0] != twists[1]:
        raise TypeError("axis1, axis2: give two Twists, or two directions with point=")
    if twists[0]:
        o1, r1 = _axis(axis1, point, "axis1")
        o2, r2 = _axis(axis2, None, "axis2")
    else:
        o1, r = _axis(axis1, point, "axis1")
        o2, r2 = _axis(axis2, point, "axis2")
        r1 = r
    nn = _clean(o1.cross(o2).dot(o1.cross(o2)))
    apart = _nonzero(nn)
    if apart is S.false:
        raise ValueError("axis1, axis2: Subproblem 2 needs axes that meet in one point; "
                         "these are parallel")
    if twists[0]:
        r, meet = _meeting_point(o1, r1, o2, r2, nn)
    else:
        meet = S.true
    u = _exact_point(p, "p") - r
    v = _exact_point(q, "q") - r
    g11, g22, g12 = (_clean(e) for e in (o1.dot(o1), o2.dot(o2), o1.dot(o2)))
    o1v, o2u = _clean(o1.dot(v)), _clean(o2.dot(u))
    a = _clean((g22 * o1v - g12 * o2u) / nn)
    b = _clean((g11 * o2u - g12 * o1v) / nn)
    uu = _clean(u.dot(u))
    gg = _clean((uu - a**2 * g11 - 2 * a * b * g12 - b**2 * g22) / nn)
    base = [apart, meet, _zero(_clean(uu - v.dot(v)))]
    n = o1.cross(o2)
    branches = []
    for g, cond in ((sqrt(gg), _positive(gg, or_zero=False)),
                    (-sqrt(gg), _positive(gg, or_zero=False)),
                    (S.Zero, _zero(gg))):
        here = And(*base, cond)
        if here is S.false:
            continue
        z = (o1 * a + o2 * b + n * g).applyfunc(_clean)
        second = _sp1(o2, g22, o2.cross(u).applyfunc(_clean), o2.cross(z).applyfunc(_clean),
                      [here], "theta2", False)
        first = _sp1(o1, g11, o1.cross(z).applyfunc(_clean), o1.cross(v).applyfunc(_clean),
                     [here], "theta1", False)
        for b2 in second:
            for b1 in first:
                if g != 0 and (b1.values[0].is_Dummy or b2.values[0].is_Dummy):
                    continue  # a point on an axis has g = 0: no such branch with g != 0
                branches.append(Branch(And(b1.condition, b2.condition),
                                       (b1.values[0], b2.values[0])))
    return _kept(branches)


# --------------------------------------------------------------------- Subproblem 3


def subproblem3(axis: Any, p: Any, q: Any, delta: Any, *, point: Any = None) -> tuple[Branch, ...]:
    r"""Paden–Kahan Subproblem 3: ``theta`` with ``|exp6(axis, theta) p - q| = delta``.

    Explanation
    ===========

    With ``u = p - r``, ``v = q - r``, their projections ``u'``, ``v'`` on the
    plane normal to ``omega``, ``delta'^2 = delta^2 - (omega . (p - q))^2 / |omega|^2``,
    ``c = |u'|^2 + |v'|^2 - delta'^2`` and the discriminant
    ``D = 4 |u'|^2 |v'|^2 - c^2`` (Murray, Li & Sastry (3.29)-(3.32), the
    ``acos`` written as an ``atan2``):

    - ``theta = theta0 +- atan2(sqrt(D), c)`` where ``|u'||v'| != 0`` and ``D > 0``
      (two solutions), ``theta0`` the Subproblem 1 angle from ``u'`` to ``v'``;
    - ``theta = theta0 + atan2(0, c)`` where ``|u'||v'| != 0`` and ``D = 0`` (tangent: one);
    - ``theta`` free where ``|u'||v'| = 0`` and ``c = 0`` (the distance does not
      depend on ``theta``, and is ``delta``).

    All angles are divided by ``|omega|`` as in :func:`subproblem1`.

    Examples
    ========

    >>> from screwsym import Twist
    >>> from screwsym.motion.subproblems import subproblem3
    >>> z = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    >>> for b in subproblem3(z, [1, 0, 0], [2, 0, 0], 1): print(b)   # tangent: one
    Branch(condition=True, values=(0,))
    >>> for b in subproblem3(z, [1, 0, 0], [1, 1, 0], 1): print(b)
    Branch(condition=True, values=(0,))
    Branch(condition=True, values=(pi/2,))
    >>> subproblem3(z, [1, 0, 0], [5, 0, 0], 1)                     # too far
    ()

    Parameters
    ==========

    axis : Twist of pitch 0, or a direction 3-vector with ``point=``
    p, q : 3-vectors (numbers or symbols)
    delta : the distance, a non-negative number or a symbol

    See Also
    ========

    subproblem1, subproblem2
    """
    omega, r = _axis(axis, point, "axis")
    pp, qq = _exact_point(p, "p"), _exact_point(q, "q")
    delta = check_scalar(delta, "delta")
    _refuse_floats(delta, "delta")
    if delta.is_negative:
        raise ValueError(f"delta: expected a distance (>= 0), got {delta}")
    ww = _clean(omega.dot(omega))
    # everything scaled by |omega|^2 (resp. its square), polynomials: uu = |omega|^2 |u'|^2, ...
    m = axis.v_O if isinstance(axis, Twist) else r.cross(omega)  # r x omega, polynomial
    A, B = _moment(omega, m, pp), _moment(omega, m, qq)
    uu, vv = _clean(A.dot(A)), _clean(B.dot(B))
    along = _clean(omega.dot(pp - qq))
    c = _clean(uu + vv - ww * delta**2 + along**2)
    D = _clean(4 * uu * vv - c**2)
    w = _length(ww)
    theta0 = _turn(omega, ww, A, B)
    moving = _nonzero(_clean(uu * vv))
    two = And(moving, _positive(D, or_zero=False))
    branches = [
        Branch(two, (theta0 - atan2(sqrt(D), c) / w,)),
        Branch(two, (theta0 + atan2(sqrt(D), c) / w,)),
        Branch(And(moving, _zero(D)), (theta0 + atan2(0, c) / w,)),
        Branch(And(_zero(_clean(uu * vv)), _zero(c)), (Dummy("theta", real=True),)),
    ]
    return _kept(branches)


# --------------------------------------------------------------------- Subproblem 5


def _rational_axis(axis: Any, name: str) -> tuple[ImmutableMatrix, Expr]:
    """``(k, w)``: a non-zero rational 3-vector and its length, which must be rational."""
    k = check_nonzero_vector(axis, name, "a rotation axis needs a non-zero direction")
    if not all(x.is_Rational for x in k):
        raise ValueError(f"{name}: expected rational entries (subproblem5 finds its roots "
                         f"exactly over the rationals), got {list(k)}")
    w = sqrt(k.dot(k))
    if not w.is_Rational:
        raise ValueError(f"{name}: expected an axis of rational length (such as a unit axis), "
                         f"got {list(k)} of length {w}")
    return k, w


def _circle_terms(k: ImmutableMatrix, ww: Expr, w: Expr, p: ImmutableMatrix,
                  h: ImmutableMatrix) -> tuple[Expr, Expr, Expr]:
    """``h . R(k, theta) p = a + b cos(w theta) + c sin(w theta)``: ``(a, b, c)``."""
    kp, kh = k.dot(p) / ww, k.dot(h)
    return (kp * kh, h.dot(p) - kp * kh, h.dot(k.cross(p)) / w)


def subproblem5(axis1: Any, axis2: Any, axis3: Any, p0: Any, p1: Any, p2: Any,
                p3: Any) -> tuple[Branch, ...]:
    r"""Subproblem 5 (IK-Geo): ``p0 + R(axis1, theta1) p1 = R(axis2, theta2) (p2 + R(axis3, theta3) p3)``.

    Explanation
    ===========

    ``R(k, theta)`` turns by ``|k| theta`` about the line through the origin along ``k``
    (as ``exp6`` and :func:`~screwsym.motion.inverse_kinematics.subproblem4`).  The point
    ``x = p0 + R1 p1`` runs on a circle about axis 1, ``y = p2 + R3 p3`` on one about
    axis 3, and a rotation about axis 2 takes ``y`` to ``x`` iff ``|x| = |y|`` and
    ``k2 . x = k2 . y``.  Both sides are affine in ``(cos, sin)`` of their angle
    (Elias & Wen 2025, Subproblem 5), so the two conditions give ``(cos, sin)`` of
    ``theta3`` as affine functions of those of ``theta1`` (a 2 x 2 linear system),
    ``cos^2 + sin^2 = 1`` a conic in those of ``theta1``, and ``t = tan(w1 theta1 / 2)`` a
    polynomial of degree at most 4: the quartic.  Each real root ``t`` (exact: a rational
    or a ``CRootOf``), and ``w1 theta1 = pi`` where it is a solution (the root at
    infinity), gives one branch: ``theta1 = 2 atan(t) / w1``, ``theta3`` the ``atan2`` of
    its ``(sin, cos)``, ``theta2`` Subproblem 1 from ``y`` to ``x`` about axis 2 (a free
    real ``Dummy`` where ``x`` lies on axis 2).  At most four branches, each exact.

    Exact rational data only (its roots are those of a rational quartic), axes of rational
    length; the case where the 2 x 2 system is singular (``theta3`` not fixed by the two
    conditions, as where axes 2 and 3 are parallel or ``p3`` lies on axis 3) and a quartic
    that vanishes identically (infinitely many solutions) are refused with
    ``NotImplementedError``, never answered by a guess.

    Examples
    ========

    >>> from sympy import Rational
    >>> from screwsym.motion.subproblems import subproblem5
    >>> x, y, z = [1, 0, 0], [0, 1, 0], [0, 0, 1]
    >>> p0 = [Rational(24, 25), Rational(1, 5), Rational(-52, 25)]
    >>> branches = subproblem5(x, y, z, p0, [0, 1, 0], [1, 0, 0], [1, 0, 0])
    >>> len(branches)
    2
    >>> branches[0].values                   # the quartic's rational root t = 1/2
    (2*atan(1/2), atan(4/3), atan(4/3))
    >>> [round(float(v), 6) for v in branches[1].values]     # a root of its cubic factor
    [2.529816, 1.003197, -0.666997]
    >>> subproblem5(x, y, z, [9, 0, 0], [0, 1, 0], [1, 0, 0], [1, 0, 0])   # out of reach
    ()

    Parameters
    ==========

    axis1, axis2, axis3 : rational 3-vectors of rational length (the axes through the origin)
    p0, p1, p2, p3 : rational 3-vectors

    See Also
    ========

    subproblem1, screwsym.motion.inverse_kinematics.subproblem4

    References
    ==========

    A. J. Elias & J. T. Wen, "IK-Geo: Unified robot inverse kinematics using subproblem
    decomposition", *Mechanism and Machine Theory* 209 (2025), Subproblem 5.
    """
    from sympy import Poly, atan, pi, real_roots

    k1, w1 = _rational_axis(axis1, "axis1")
    k2, w2 = _rational_axis(axis2, "axis2")
    k3, w3 = _rational_axis(axis3, "axis3")
    pts = []
    for name, value in (("p0", p0), ("p1", p1), ("p2", p2), ("p3", p3)):
        v = check_vector(value, name)
        if not all(e.is_Rational for e in v):
            raise ValueError(f"{name}: expected rational entries, got {list(v)}")
        pts.append(v)
    q0, q1, q2, q3 = pts
    ww1, ww3 = w1**2, w3**2
    # |x|^2 = A0 + A1 c1 + A2 s1, k2.x = B0 + B1 c1 + B2 s1 (c1, s1 of w1 theta1); same for y
    a = _circle_terms(k1, ww1, w1, q1, q0)
    A = (q0.dot(q0) + q1.dot(q1) + 2 * a[0], 2 * a[1], 2 * a[2])
    b = _circle_terms(k1, ww1, w1, q1, k2)
    B = (k2.dot(q0) + b[0], b[1], b[2])
    e = _circle_terms(k3, ww3, w3, q3, q2)
    E = (q2.dot(q2) + q3.dot(q3) + 2 * e[0], 2 * e[1], 2 * e[2])
    f = _circle_terms(k3, ww3, w3, q3, k2)
    F = (k2.dot(q2) + f[0], f[1], f[2])
    det = E[1] * F[2] - E[2] * F[1]
    if det == 0:
        raise NotImplementedError(
            "subproblem5: |y| and k2 . y do not fix theta3 (axes 2 and 3 parallel, or p3 on "
            "axis 3): this degenerate case is not handled")
    t = Dummy("t", real=True)

    def third(c1: Expr, s1: Expr, one: Expr = S.One) -> tuple[Expr, Expr]:
        """``(cos, sin)`` of ``w3 theta3`` where ``(cos, sin)`` of ``w1 theta1`` are
        ``(c1, s1) / one`` (times ``one``: homogeneous)."""
        r1 = (A[0] - E[0]) * one + A[1] * c1 + A[2] * s1
        r2 = (B[0] - F[0]) * one + B[1] * c1 + B[2] * s1
        return ((F[2] * r1 - E[2] * r2) / det, (E[1] * r2 - F[1] * r1) / det)

    den = 1 + t**2
    c3, s3 = third(1 - t**2, 2 * t, den)  # times 1 + t^2: polynomials in t
    quartic = Poly((c3**2 + s3**2 - den**2).expand(), t, domain="QQ")
    if quartic.is_zero:
        raise NotImplementedError(
            "subproblem5: the quartic vanishes identically (infinitely many solutions): this "
            "degenerate case is not handled")
    starts: list[tuple[Expr, Expr, Expr]] = []
    for root in dict.fromkeys(real_roots(quartic)):
        c1, s1 = (1 - root**2) / (1 + root**2), 2 * root / (1 + root**2)
        starts.append((2 * atan(root) / w1, c1, s1))
    cpi, spi = third(S.NegativeOne, S.Zero)
    if cpi**2 + spi**2 == 1:  # w1 theta1 = pi: the root at infinity
        starts.append((pi / w1, S.NegativeOne, S.Zero))
    branches = []
    for theta1, c1, s1 in starts:
        c3, s3 = third(c1, s1)
        theta3 = atan2(s3, c3) / w3
        x = q0 + _turned(k1, w1, q1, c1, s1)
        y = q2 + _turned(k3, w3, q3, c3, s3)
        X, Y = k2.cross(x), k2.cross(y)
        if all(v == 0 for v in X):  # x on axis 2 (then y too): theta2 free
            theta2: Expr = Dummy("theta2", real=True)
        else:
            theta2 = atan2(k2.dot(Y.cross(X)), w2 * Y.dot(X)) / w2
        branches.append(Branch(S.true, (theta1, theta2, theta3)))
    return tuple(branches)


def _turned(k: ImmutableMatrix, w: Expr, p: ImmutableMatrix, c: Expr, s: Expr) -> ImmutableMatrix:
    """``R(k, theta) p`` with ``(cos, sin)`` of ``|k| theta`` given (Rodrigues)."""
    ww = w**2
    along = k * (k.dot(p) / ww)
    return along + (p - along) * c + k.cross(p) * (s / w)
