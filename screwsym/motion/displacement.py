r"""Finite screw displacements: :func:`exp6` of a twist and :func:`log6` of a motion.

Explanation
===========

Every rigid motion is a screw displacement (Mozzi 1763, Chasles 1830): a
turn by an angle ``theta`` about a line together with a slide ``h theta``
along it.  With the unit twist ``$ = (omega; r x omega + h omega)`` of that
screw (1.52, 1.53), the motion is the matrix exponential of the twist's 4x4
matrix ``[$] = [[[omega]x, v_O], [0, 0]]`` times ``theta``:

    exp6($, theta) = (R, (I - R) r + h theta omega),   R = Rodrigues(omega, theta),

and a twist of infinite pitch ``(0; v)`` gives the translation by
``theta v``.  :func:`log6` inverts it: the axis, pitch and angle of a given
motion, with the identity, the pure translations and the half-turns handled
exactly.

References
==========

Huang, Li & Ding, *Theory of Parallel Mechanisms*, Springer 2013, (1.48)-(1.53).
Lynch & Park, *Modern Robotics*, Cambridge 2017, Section 3.3.3 (Proposition 3.25).
"""

from __future__ import annotations

from sympy import Expr, Float, ImmutableMatrix, S, acos, atan2, cos, pi, sin, sqrt, zeros
from sympy.core.evalf import prec_to_dps

from ..core.checks import check_instance, check_scalar
from ..core.decide import (
    float_tau,
    is_zero,
    is_zero_scaled,
    is_zero_vector,
    is_zero_vector_scaled,
    norm,
)
from ..core.formulas import dual_part, foot_point, pitch_ratio
from ..core.screw import ScalarLike, ScrewLike, check_screw
from ..core.tidy import tidy
from ..core.twist import Twist
from .transform import Transform, rotation_minus_identity, skew

__all__ = ["exp6", "log6", "se3_matrix"]


def se3_matrix(twist: ScrewLike) -> ImmutableMatrix:
    r"""The 4x4 matrix ``[[[omega]x, v_O], [0, 0]]`` of a twist (an element of se(3)).

    ``d/dt exp6($, t) = [$] exp6($, t)``.

    >>> from screwsym import Twist
    >>> from screwsym.motion.displacement import se3_matrix
    >>> se3_matrix(Twist([0, 0, 1], [1, 0, 0]))
    Matrix([
    [0, -1, 0, 1],
    [1,  0, 0, 0],
    [0,  0, 0, 0],
    [0,  0, 0, 0]])
    """
    t = check_screw(twist, "twist", Twist)
    top = skew(t.omega).row_join(t.v_O)
    return ImmutableMatrix(top.col_join(zeros(1, 4)))


def exp6(twist: ScrewLike, theta: ScalarLike) -> Transform:
    r"""The finite screw displacement ``exp([$] theta)`` of a twist: a :class:`Transform`.

    Explanation
    ===========

    For a twist ``$ = (omega; v_O)`` with ``omega != 0``, with
    ``w = |omega|``, the axis point ``r = omega x v_O / (omega . omega)`` (1.16)
    and the pitch ``h = omega . v_O / (omega . omega)`` (1.34):

        R = I + sin(w theta)/w K + (1 - cos(w theta))/w^2 K^2,   K = [omega]x,
        p = (I - R) r + h theta omega,

    the turn by ``w theta`` about the axis with the slide ``h w theta`` along it;
    for a unit ``omega`` (``w = 1``) the turn is ``theta``.  A twist whose
    ``omega`` is provably zero (infinite pitch) gives the translation by
    ``theta v_O``.  This is the matrix exponential of ``[$] theta``
    (:func:`se3_matrix`), exact for symbolic ``theta`` and twists.  When
    ``omega`` is symbolic and not provably zero, the formula above is
    returned: it holds where ``omega != 0``.

    Examples
    ========

    >>> from sympy import pi, symbols
    >>> from screwsym import Twist, exp6
    >>> t = symbols("theta", real=True)
    >>> hinge = Twist.rotation([0, 0, 1], point=[1, 0, 0])    # unit twist of a hinge on x = 1
    >>> exp6(hinge, pi/2)
    Transform(R=[[0, -1, 0], [1, 0, 0], [0, 0, 1]], p=[1, -1, 0])
    >>> exp6(Twist.screw_motion([0, 0, 1], point=[0, 0, 0], pitch=2), t)   # pitch 2: a helix
    Transform(R=[[cos(theta), -sin(theta), 0], [sin(theta), cos(theta), 0], [0, 0, 1]], p=[0, 0, 2*theta])
    >>> exp6(Twist.translation([1, 0, 0]), t).p.T
    Matrix([[theta, 0, 0]])

    Parameters
    ==========

    twist : Twist (or a 6-vector (omega; v_O))
    theta : real number or expression

    See Also
    ========

    log6, se3_matrix, screwsym.motion.transform.Transform
    """
    t = check_screw(twist, "twist", Twist)
    theta = check_scalar(theta, "theta")
    omega, v = t.omega, t.v_O
    if is_zero_vector(omega) is True:
        return Transform._new(ImmutableMatrix.eye(3), theta * v)
    ww = omega.dot(omega)
    if ww.is_number:  # numbers in Q(sqrt 2, sqrt 3): a unit axis at 15 degrees gives 1, not a
        ww = tidy(ww)  # sum of squares of sums of roots (and no sqrt of it in every angle)
    turn = rotation_minus_identity(omega, theta, sqrt(ww))  # R - I, digits kept for floats
    R = ImmutableMatrix.eye(3) + turn
    r = foot_point(omega, v)
    h = pitch_ratio(omega, v)
    p = -turn * r + (h * theta) * omega
    if _float_with_constants(R, p):
        # a float angle on a twist holding sines of constant angles (a robot file's -1.8):
        # the entries are floats; evaluated at the floats' precision, where expanding the
        # products of those sines would take minutes (the SO-100 arm)
        dps = prec_to_dps(min(f._prec for f in (*R.atoms(Float), *p.atoms(Float))))
        # each sine once, with guard digits (evalf would take each again in every term)
        values = {a: a.evalf(dps + _GUARD) for a in (*R.atoms(sin, cos), *p.atoms(sin, cos))
                  if not a.free_symbols}
        return Transform._new(R.xreplace(values).evalf(dps), p.xreplace(values).evalf(dps))
    if all(e.is_number for e in p) or is_zero(ww - 1) is True:
        p = p.applyfunc(lambda e: e.expand())
    return tidy(Transform._new(R, p))


#: guard digits of the sines of constant angles in a float displacement (exp6)
_GUARD = 15


def _float_with_constants(R: ImmutableMatrix, p: ImmutableMatrix) -> bool:
    """Whether every entry is a number, some hold floats and some a sine or cosine of a constant."""
    entries = [*R, *p]
    return (all(e.is_number for e in entries) and any(e.has(Float) for e in entries)
            and any(e.has(sin, cos) for e in entries))


def _half_turn(c: Expr) -> bool:
    """Whether ``cos theta = c`` is exactly -1 (float rotations: :func:`_float_rotation_axis`)."""
    return is_zero_scaled(c + 1, S.One) is True


def _rotation_axis(R: ImmutableMatrix, c: Expr) -> tuple[ImmutableMatrix, Expr]:
    """The unit axis and ``sin`` of the angle of ``R``, whose angle's cosine is ``c``."""
    s = sqrt(1 - c**2)
    if _half_turn(c):
        # a half-turn: R = I + 2 K^2, so omega omega^T = (R + I)/2; pick a column with a
        # non-zero diagonal (the sign of the axis does not matter for a half-turn)
        # non-zero diagonal, the largest: a float diagonal that should be 0 carries rounding,
        # and dividing by its root would give a far from unit axis
        P = (R + ImmutableMatrix.eye(3)) / 2
        found = [i for i in range(3) if is_zero(P[i, i]) is False]
        if found:
            if all(P[i, i].is_comparable for i in found):
                found = [max(found, key=lambda i: P[i, i])]
            i = found[0]
            return P[:, i] / sqrt(P[i, i]), S.Zero  # sin(pi), not the root of a rounding residue
        raise ValueError(f"T: cannot decide the axis of this half-turn, R = {R.tolist()}")
    vee = ImmutableMatrix([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    return (vee / (2 * s)).applyfunc(lambda e: e.expand() if e.is_number else e), s


def _float_rotation_axis(R: ImmutableMatrix, c: Expr) -> tuple[ImmutableMatrix, Expr, Expr]:
    """The unit axis, ``sin theta`` and ``theta`` of a float rotation, taken from ``R`` itself.

    ``sin theta = |vee(R)|/2`` from the skew part and ``theta = atan2(sin, cos)``
    keep every digit near 0 and pi.  For ``cos theta >= 0`` the axis is
    ``vee/(2 sin theta)``; otherwise it comes from the symmetric part,
    ``(R + R^T)/2 - cos(theta) I = (1 - cos theta) omega omega^T`` (its largest
    diagonal's column), with the sign of ``vee``: near a half-turn ``vee`` is
    tiny and dividing by it would lose the digits, but its sign is still right.
    No tolerance decides the half-turn: ``theta`` is whatever the matrix says,
    ``pi`` to the last digit when ``vee`` is zero.
    """
    prec = min(f._prec for f in R.atoms(Float))
    dps = max(15, prec_to_dps(prec) + 1)  # the floats' digits and one guard digit
    vee = ImmutableMatrix([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = (norm(vee) / 2).evalf(dps)
    theta = atan2(s, c).evalf(dps)
    if c >= 0:
        return (vee / (2 * s)).applyfunc(_expand_number), s, theta
    B = (R + R.T) / 2 - c * ImmutableMatrix.eye(3)
    i = max(range(3), key=lambda k: B[k, k])
    col = B[:, i]
    omega = (col / norm(col)).applyfunc(lambda e: e.evalf(prec_to_dps(prec)))
    along = omega.dot(vee)
    if along == 0:  # a half-turn to the last digit: either sign; the first component that is
        # not a rounding residue (float policy) positive, as for exact half-turns
        along = next((e for e in omega if is_zero_scaled(e, S.One) is False), S.One)
    if along < 0:
        omega = -omega
    return omega, s, theta


def log6(T: Transform) -> tuple[Twist, Expr]:
    r"""The screw of a rigid motion (Mozzi-Chasles): a unit twist and an angle.

    Explanation
    ===========

    Returns ``(twist, theta)`` with ``exp6(twist, theta) == T``:

    * a rotation by ``theta`` in ``(0, pi]`` (``cos theta = (tr R - 1)/2``):
      the unit twist ``(omega; r x omega + h omega)`` of the screw axis, ``|omega| = 1``.
      Its axis point is ``r = p_perp/2 + sin(theta)/(2 (1 - cos theta)) omega x p``, with
      ``p_perp`` the part of ``p`` perpendicular to ``omega``, and its pitch is
      ``h = omega . p / theta``.  A half-turn (``theta = pi``) takes its axis
      from ``(R + I)/2 = omega omega^T``; of the two opposite axes, the one
      whose first non-zero component is positive;
    * a pure translation ``(I, p)``: the twist ``(0; p/|p|)`` of infinite
      pitch and ``theta = |p|``;
    * the identity: the zero twist and ``theta = 0``.

    Exact: the angle is ``acos((tr R - 1)/2)`` (a number such as ``pi/3`` when
    SymPy knows it), the axis and the moment are exact algebraic numbers.
    A float rotation takes ``sin theta`` from the skew part of ``R``, the
    angle from ``atan2`` and, past a quarter-turn, the axis from the symmetric
    part of ``R``: every digit is kept near 0 and near pi, and no tolerance on
    ``cos theta`` decides a half-turn (a turn by ``pi - 1e-7`` is not ``pi``).
    The translation ``p`` may be symbolic; a rotation whose angle is symbolic
    (``tr R`` not a number) is refused: ``acos`` of a symbolic cosine is not
    known to be real, and which case applies is not decided.

    Examples
    ========

    >>> from sympy import pi
    >>> from screwsym import Transform, Twist, exp6, log6
    >>> T = Transform.rotation([0, 0, 1], pi/2, point=[1, 0, 0]) @ Transform.translation([0, 0, 3])
    >>> log6(T)                             # the axis x = 1, y = 0, pitch 3/(pi/2)
    (Twist([0, 0, 1], [0, -1, 6/pi]), pi/2)
    >>> twist, theta = log6(T)
    >>> exp6(twist, theta).equals(T)
    True
    >>> log6(Transform.rotation([1, 0, 0], pi))
    (Twist([1, 0, 0], [0, 0, 0]), pi)
    >>> log6(Transform.translation([3, 4, 0]))
    (Twist([0, 0, 0], [3/5, 4/5, 0]), 5)

    See Also
    ========

    exp6
    """
    check_instance(T, "T", Transform)
    R, p = T.R, T.p
    c = (R.trace() - 1) / 2
    if not c.is_number:
        raise ValueError(
            "T: log needs a rotation whose angle is a number, got cos(theta) = (tr R - 1)/2 "
            f"= {c}"
        )
    # R = I decided exactly, or for floats by the float policy (entries of size 1)
    if is_zero_vector_scaled((R - ImmutableMatrix.eye(3)).reshape(9, 1), S.One) is True:
        if is_zero_vector(p) is True:
            return Twist(zeros(3, 1), zeros(3, 1)), S.Zero
        d = sqrt(p.dot(p))
        return Twist(zeros(3, 1), (p / d).applyfunc(_expand_number)), d
    floats = float_tau(*R) is not None
    half_turn = not floats and _half_turn(c)
    if floats:
        omega, s, theta = _float_rotation_axis(R, c)
    else:
        omega, s = _rotation_axis(R, c)
        theta = pi if half_turn else acos(c)
    if half_turn:
        # fix the sign: the first non-zero component positive
        for e in omega:
            if is_zero_scaled(e, S.One) is False:  # a unit axis: rounding residue is zero
                if e.is_negative:
                    omega = -omega
                break
    along = omega.dot(p)
    p_perp = p - along * omega
    # cot(theta/2) = sin/(1 - cos) = (1 + cos)/sin; for floats the form without cancellation
    cot_half = (1 + c) / s if floats and c > 0 else s / (1 - c)
    r = p_perp / 2 + (cot_half / 2) * omega.cross(p)
    h = along / theta
    v = dual_part(r, omega, h)
    return Twist(omega, v.applyfunc(_expand_number)), theta


def _expand_number(e: Expr) -> Expr:
    return e.expand() if e.is_number else e

