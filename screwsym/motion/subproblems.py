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

__all__ = ["Branch", "subproblem1", "subproblem2", "subproblem3"]


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
