r"""Rigid motions SE(3): :class:`Transform`, and the adjoint that moves screws.

Explanation
===========

A rigid motion ``T = (R, p)`` maps a point ``x`` to ``R x + p``; as a 4x4
matrix it is ``[[R, p], [0, 1]]``.  Read as a pose, ``T`` is the frame B
seen from frame A: the columns of ``R`` are B's axes and ``p`` is B's origin,
both in A's coordinates.

In the book's ray order every screw moves with the same 6x6 matrix, the
adjoint

    Ad(T) = [[R, 0], [[p]x R, R]]

a line vector ``(S; S0)``, a twist ``(omega; v_O)`` and a wrench
``(f; C_O)`` alike: the direction part turns, ``S' = R S``, and the moment part
is turned and taken about the new origin, ``S0' = R S0 + p x R S`` (the origin
shift (1.32) after a rotation).  ``T.apply`` does this for screws and is
``R x + p`` for points and ``R x`` for directions.

Everything a :class:`Transform` is lives in its ``args`` ``(R, p)`` (a 3x3 and
a 3x1 ``ImmutableMatrix``), and exact values stay exact: a rotation about a
symbolic angle is Rodrigues' formula in ``sin`` and ``cos`` of that angle.

References
==========

Huang, Li & Ding, *Theory of Parallel Mechanisms*, Springer 2013, (1.32).
Lynch & Park, *Modern Robotics*, Cambridge 2017, Sections 3.3 and 3.4.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, NoReturn, TypeVar, overload

import numpy as np
from sympy import Expr, Float, ImmutableMatrix, S, cancel, cos, sin, sqrt, trigsimp, zeros
from sympy.polys.polyerrors import CoercionFailed, GeneratorsError, PolynomialError
from sympy.polys.rings import sring

from ..algebra.circle import reduce_circle, trig_entries
from ..core.basic import ScrewsymBasic
from ..core.checks import (
    check_flag,
    check_instance,
    check_matrix,
    check_point_or_direction,
    check_scalar,
    check_vector,
    refusing_strings,
)
from ..core.decide import (
    float_tau,
    is_zero,
    is_zero_scaled,
    is_zero_vector,
    is_zero_vector_scaled,
    norm,
)
from ..core.formulas import cross_matrix, moved
from ..core.inertia import SpatialInertia
from ..core.screw import MatrixLike, ScalarLike, Screw, VectorLike
from ..core.tidy import tidy
from .angles import RecognisedAngle, angle_step, recognise_trig_float, warn_recognised

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["Transform", "skew", "adjoint_matrix"]

#: a screw of any kind: Transform.apply gives back the kind it is given
_S = TypeVar("_S", bound=Screw)


def skew(v: VectorLike) -> ImmutableMatrix:
    r"""The 3x3 matrix ``[v]x`` with ``[v]x w = v x w``, of a checked 3-vector ``v``.

    The formula is :func:`screwsym.core.formulas.cross_matrix`'s; this checks
    ``v`` first (a list, tuple or SymPy matrix of three real entries).

    >>> from screwsym.motion.transform import skew
    >>> skew([1, 2, 3])
    Matrix([
    [ 0, -3,  2],
    [ 3,  0, -1],
    [-2,  1,  0]])
    """
    return cross_matrix(check_vector(v, "v"))


#: symbolic entries larger than this (``count_ops``) are not put through the
#: exact decision of :func:`check_rotation`; they are accepted undecided
ROTATION_CHECK_OPS = 400


def _decide_small(expr: Expr) -> bool | None:
    """Zero-decision for an entry of size 1: of ``R^T R - I``, or of a 4x4 last row minus ``[0, 0, 0, 1]``.

    Numbers follow the float policy (:func:`screwsym.core.decide.is_zero_scaled`
    with scale 1: exact for exact numbers); symbolic entries up to
    ``ROTATION_CHECK_OPS`` operations are decided exactly, larger ones not at all.
    """
    if expr.is_number:
        return is_zero_scaled(expr, S.One)
    if expr.count_ops() > ROTATION_CHECK_OPS:
        return None
    return is_zero(expr)


def _with_precision(value: Any) -> Any:
    """A NumPy array of singles (or halves) as nested lists of SymPy Floats of that precision.

    NumPy converts them to doubles, whose float policy (``2**(13 - 53)``) a
    single's rounding (``2**-24``) fails: ``Float(x, precision=24)`` keeps the
    precision the data has, and the float policy's tolerance follows it
    (``2**(13 - 24) = 2**-11`` for a single, 8192 of its units in the last place).
    """
    if isinstance(value, np.ndarray) and value.dtype.kind == "f" and value.dtype.itemsize < 8:
        bits = np.finfo(value.dtype).nmant + 1
        return [[Float(float(x), precision=bits) for x in row] for row in value.tolist()] \
            if value.ndim == 2 else value
    return value


def check_rotation(value: Any, name: str) -> ImmutableMatrix:
    """Return ``value`` as a 3x3 rotation matrix, refusing a provably improper one.

    A rotation satisfies ``R^T R = I`` and ``det R = 1``.  Only a provable
    violation raises: entries that are numbers are decided exactly (floats by
    the float policy of :func:`screwsym.core.decide.is_zero_scaled`), symbolic
    entries with the exact decision of
    :func:`screwsym.core.decide.is_zero` when they are no larger than
    ``ROTATION_CHECK_OPS`` operations; larger ones are accepted undecided.
    A matrix rational in its symbols whose determinant cancels to -1 is a
    reflection for every value of them, and is refused; so is one rational in
    ``sin(q)``, ``cos(q)`` whose determinant is -1 on the circle
    ``sin(q)**2 + cos(q)**2 = 1`` (decided exactly by reduction modulo the
    circle, :mod:`screwsym.algebra.circle`).  A NumPy array of
    singles is judged at a single's precision: the float policy's tolerance
    ``2**(13 - 24) = 2**-11`` on the entries of ``R^T R - I`` (doubles:
    ``2**-40``).

    >>> check_rotation([[0, -1, 0], [1, 0, 0], [0, 0, 1]], "R").shape
    (3, 3)
    >>> check_rotation([[1, 0, 0], [0, 1, 0], [0, 0, -1]], "R")
    Traceback (most recent call last):
    ...
    ValueError: R: expected a rotation (det R = 1), got det R = -1
    >>> check_rotation([[1, 1, 0], [0, 1, 0], [0, 0, 1]], "R")
    Traceback (most recent call last):
    ...
    ValueError: R: expected an orthonormal matrix (R^T R = I), got R^T R - I = Matrix([[0, 1, 0], [1, 1, 0], [0, 0, 0]])
    """
    R = check_matrix(_with_precision(value), name, (3, 3))
    gram = R.T * R - ImmutableMatrix.eye(3)
    if any(_decide_small(e) is False for e in gram):
        raise ValueError(
            f"{name}: expected an orthonormal matrix (R^T R = I), got R^T R - I = "
            f"Matrix({gram.tolist()})"
        )
    # R^T R = I leaves det R = +-1: numbers are decided; entries rational in the symbols are
    # refused where the determinant cancels to -1 (a reflection for every value of them)
    if all(e.is_number for e in R):
        det = R.det(method="berkowitz")
        if _decide_small(det - 1) is False:
            raise ValueError(f"{name}: expected a rotation (det R = 1), got det R = {det}")
    elif (
        all(e.is_rational_function() for e in R)
        and sum(e.count_ops() for e in R) <= ROTATION_CHECK_OPS
    ):
        if is_zero(cancel(R.det(method="berkowitz") + 1)) is True:
            raise ValueError(
                f"{name}: expected a rotation (det R = 1), got det R = -1 (a reflection for "
                "every value of its symbols)"
            )
    elif sum(e.count_ops() for e in R) <= ROTATION_CHECK_OPS and _reflection_on_circle(R):
        raise ValueError(
            f"{name}: expected a rotation (det R = 1), got det R = -1 (a reflection for every "
            "value of its angles, on the circle sin**2 + cos**2 = 1)"
        )
    return R


def _reflection_on_circle(R: ImmutableMatrix) -> bool:
    """Whether ``det R + 1`` is provably zero with ``sin(q)``, ``cos(q)`` on the unit circle.

    The entries rational in symbols and in ``sin(q)``, ``cos(q)`` of symbols
    ``q`` (sums and multiples expanded): the numerator of ``det R + 1`` is
    reduced modulo ``sin(q)**2 + cos(q)**2 - 1`` (its normal form,
    :func:`screwsym.algebra.circle.reduce_circle`), and is zero exactly when it
    vanishes on the circles.  Anything else (other functions) is not decided: False.
    """
    entries = trig_entries(list(R))
    if any(e.has(sin, cos) or not e.is_rational_function() for e in entries):
        return False
    num, _ = cancel(ImmutableMatrix(3, 3, entries).det(method="berkowitz") + 1).as_numer_denom()
    if num == 0:
        return True
    symbols = sorted(num.free_symbols, key=str)
    if not symbols:
        return False
    try:
        ring, P = sring(num, *symbols, extension=True)
    except (CoercionFailed, GeneratorsError, PolynomialError):
        return False
    return not reduce_circle(P, ring)


def rodrigues(omega: ImmutableMatrix, theta: Expr, w: Expr = S.One) -> ImmutableMatrix:
    r"""Rodrigues' formula: the rotation ``exp([omega]x theta)`` by ``w theta`` about ``omega``.

    ``R = I + sin(w theta)/w K + (1 - cos(w theta))/w^2 K^2`` with ``K = [omega]x``
    and ``w = |omega|``, which the caller passes (the default 1: a unit
    ``omega``, ``R = I + sin(theta) K + (1 - cos(theta)) K^2``).  It is the
    rotation part of the finite screw displacement of a twist (1.48)-(1.53).

    >>> from sympy import pi
    >>> rodrigues(ImmutableMatrix([0, 0, 1]), pi/2)
    Matrix([
    [0, -1, 0],
    [1,  0, 0],
    [0,  0, 1]])

    For floats ``1 - cos(w theta)`` is computed as ``2 sin^2(w theta / 2)``:
    at a small angle the difference loses its digits (a relative error of
    9e-5 at 1e-6 rad, the whole term at 1e-9), the product keeps them.

    >>> rotation_minus_identity(ImmutableMatrix([0, 0, 1]), 1e-9)[0, 0]
    -5.00000000000000e-19
    """
    return ImmutableMatrix.eye(3) + rotation_minus_identity(omega, theta, w)


def rotation_minus_identity(omega: ImmutableMatrix, theta: Expr, w: Expr = S.One) -> ImmutableMatrix:
    r"""``R - I = sin(w theta)/w K + (1 - cos(w theta))/w^2 K^2`` of :func:`rodrigues`, formed directly.

    What ``(I - R) r`` of a screw displacement needs: at a small float angle
    ``R`` itself rounds its diagonal to 1, and ``I - R`` would lose the digits.
    """
    K = skew(omega)
    angle = w * theta
    if float_tau(angle, *omega) is not None:
        versine = 2 * sin(angle / 2) ** 2
    else:
        versine = 1 - cos(angle)
    return ImmutableMatrix((sin(angle) / w) * K + (versine / w**2) * (K * K))


def _both(a: bool | None, b: bool | None) -> bool | None:
    """Three-valued ``and``: False if either is False, True if both are True, else None."""
    return False if False in (a, b) else True if a is True and b is True else None


def _tidy(e: Expr) -> Expr:
    """``trigsimp`` where there is trigonometry (``sin^2 + cos^2``), else the entry itself."""
    return trigsimp(e) if e.has(sin, cos) else e


def _recognise_rotation(R: ImmutableMatrix, n: int, name: str) -> ImmutableMatrix:
    """``R`` with float entries that are sines and cosines of multiples of pi/n made exact.

    All or nothing: every float entry must be recognised and the exact matrix
    must be a rotation exactly (``R^T R = I``, ``det R = 1``); else ``R`` as given.
    """
    floats = [(i, e) for i, e in enumerate(R) if isinstance(e, Float)]
    if not floats or not all(e.is_number for e in R):
        return R
    exact = list(R)
    found = []
    for i, e in floats:
        value = recognise_trig_float(float(e), n)
        if value is None:
            return R
        exact[i] = value
        found.append(RecognisedAngle(repr(float(e)), f"{name}[{i // 3}, {i % 3}]", value))
    E = ImmutableMatrix(3, 3, exact)
    gram = (E.T * E - ImmutableMatrix.eye(3)).applyfunc(lambda x: x.expand())
    if not gram.is_zero_matrix or (E.det(method="berkowitz") - 1).expand() != 0:
        return R
    warn_recognised(found, n, stacklevel=3)
    return E


class Transform(ScrewsymBasic):
    r"""A rigid motion (an element of SE(3)): ``x -> R x + p``.

    Explanation
    ===========

    ``args == (R, p)``: ``R`` a 3x3 rotation, ``p`` a 3x1 translation, both
    ``ImmutableMatrix``.  A rotation part that is provably not orthonormal
    with determinant 1 is refused (see
    :func:`check_rotation`: exact for numbers, exact for
    small symbolic entries, undecided large symbolic entries are accepted).
    Composition is ``T1 @ T2`` (first ``T2``, then ``T1``), as for the 4x4
    matrices.

    Examples
    ========

    >>> from sympy import pi, symbols
    >>> from screwsym import Transform, Twist
    >>> t = symbols("theta", real=True)
    >>> T = Transform.rotation([0, 0, 1], t, point=[1, 0, 0])   # a hinge on x = 1
    >>> T.R
    Matrix([
    [cos(theta), -sin(theta), 0],
    [sin(theta),  cos(theta), 0],
    [         0,           0, 1]])
    >>> T.apply([1, 0, 0]).T                    # the hinge stays put
    Matrix([[1, 0, 0]])
    >>> Q = Transform.rotation([0, 0, 1], pi/2) @ Transform.translation([1, 0, 0])
    >>> Q
    Transform(R=[[0, -1, 0], [1, 0, 0], [0, 0, 1]], p=[0, 1, 0])
    >>> Q.apply(Twist.rotation([1, 0, 0], point=[0, 0, 0]))   # the x axis turned onto y
    Twist([0, 1, 0], [0, 0, 0])
    >>> Transform([[1, 1, 0], [0, 1, 0], [0, 0, 1]], [0, 0, 0])
    Traceback (most recent call last):
    ...
    ValueError: R: expected an orthonormal matrix (R^T R = I), got R^T R - I = Matrix([[0, 1, 0], [1, 1, 0], [0, 0, 0]])

    Parameters
    ==========

    R : 3x3 matrix
        The rotation (SymPy matrix, NumPy array or nested lists).
    p : 3-vector
        The translation.

    See Also
    ========

    screwsym.motion.displacement.exp6, screwsym.motion.displacement.log6, screwsym.motion.chain.Chain
    """

    __slots__ = ()

    # above Matrix's 10.01 and Screw's 20, so ``matrix @ T`` and ``T @ screw`` come here
    _op_priority = 30.0
    __array_ufunc__ = None

    def __new__(cls, R: MatrixLike, p: VectorLike) -> Self:
        return cls._new(check_rotation(R, "R"), check_vector(p, "p"))

    @classmethod
    def _new(cls, R: ImmutableMatrix, p: ImmutableMatrix) -> Self:
        """Build from parts already known to be a rotation and a 3x1 vector (no checks)."""
        return ScrewsymBasic.__new__(cls, ImmutableMatrix(R), ImmutableMatrix(p))

    # ------------------------------------------------------------ constructors
    @classmethod
    def identity(cls) -> Self:
        """The identity motion.

        >>> Transform.identity()
        Transform(R=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], p=[0, 0, 0])
        """
        return cls._new(ImmutableMatrix.eye(3), zeros(3, 1))

    @classmethod
    def translation(cls, d: VectorLike) -> Self:
        """The translation by ``d``.

        >>> Transform.translation([1, 2, 3]).apply([0, 0, 0]).T
        Matrix([[1, 2, 3]])
        """
        return cls._new(ImmutableMatrix.eye(3), check_vector(d, "d"))

    @classmethod
    def rotation(cls, direction: VectorLike, angle: ScalarLike, *,
                 point: VectorLike | None = None) -> Self:
        r"""The rotation by ``angle`` about the line through ``point`` along ``direction``.

        Rodrigues' formula ``R = I + sin(angle) K + (1 - cos(angle)) K^2`` with
        ``K = [u]x`` for the unit axis ``u = direction/|direction|``, and ``p = (I - R) point``
        so that the points of the line stay put.  Right-handed about ``direction``.
        Exact for symbolic angles and axes; a non-unit direction brings its length
        ``|direction|`` (a root) into the formula.  A zero direction is refused; a
        symbolic direction that is not provably zero gives the formula, which holds
        where ``direction != 0``.

        >>> from sympy import pi
        >>> Transform.rotation([1, 1, 0], pi).R         # a half-turn about x = y
        Matrix([
        [0, 1,  0],
        [1, 0,  0],
        [0, 0, -1]])
        """
        direction = check_vector(direction, "direction")
        angle = check_scalar(angle, "angle")
        if is_zero_vector(direction) is True:
            raise ValueError(f"direction: expected a non-zero direction, got {list(direction)}")
        R = rodrigues(direction / sqrt(direction.dot(direction)), angle)
        R = R.applyfunc(lambda e: e.expand() if e.is_number else e)
        if point is None:
            return cls._new(R, zeros(3, 1))
        point = check_vector(point, "point")
        return cls._new(R, (ImmutableMatrix.eye(3) - R) * point)

    @classmethod
    def from_matrix(cls, M: MatrixLike, *, name: str = "M", angles: str = "exact") -> Self:
        """The transform of the 4x4 homogeneous matrix ``[[R, p], [0, 1]]``.

        Errors name the argument ``name`` (as :meth:`Screw.from_matrix
        <screwsym.core.screw.Screw.from_matrix>`'s do).  As for the rotation
        part, only a provably wrong last row raises: exact entries are decided
        exactly, floats by the float policy of
        :func:`screwsym.core.decide.is_zero_scaled` (entries of size 1), and an
        entry the symbols leave undecided is accepted.

        >>> Transform.from_matrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
        Transform(R=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], p=[5, 0, 0])
        >>> Transform.from_matrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]])
        Traceback (most recent call last):
        ...
        ValueError: M: expected the last row [0, 0, 0, 1], got [0, 0, 1, 1]

        ``angles="pi/12"`` (or ``"pi/N"``) reads a rotation written in floats
        whose every entry is, to a float's precision
        (:func:`screwsym.motion.angles.recognise_trig_float`), a sine or cosine
        of a multiple of pi/12 as those exact values, when they make an exact
        rotation, with a :class:`~screwsym.motion.angles.RecognisedAngleWarning`;
        the translation is kept as given:

        >>> import warnings, numpy as np
        >>> c = np.cos(np.pi / 6)
        >>> with warnings.catch_warnings():
        ...     warnings.simplefilter("ignore")
        ...     T = Transform.from_matrix([[c, -0.5, 0, 0.25], [0.5, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        ...                               angles="pi/12")
        >>> T.R
        Matrix([
        [sqrt(3)/2,      -1/2, 0],
        [      1/2, sqrt(3)/2, 0],
        [        0,         0, 1]])
        """
        n = angle_step(angles)
        M = check_matrix(_with_precision(M), name, (4, 4))
        last = list(M[3, :])
        if any(_decide_small(e - target) is False for e, target in zip(last, (0, 0, 0, 1), strict=True)):
            raise ValueError(f"{name}: expected the last row [0, 0, 0, 1], got {last}")
        R = check_rotation(M[:3, :3], f"{name}[:3, :3]")
        if n is not None:
            R = _recognise_rotation(R, n, f"{name}[:3, :3]")
        return cls._new(R, M[:3, 3])

    # ------------------------------------------------------------------ parts
    @property
    def R(self) -> ImmutableMatrix:
        """The rotation part, a 3x3 ``ImmutableMatrix``."""
        return self.args[0]

    @property
    def p(self) -> ImmutableMatrix:
        """The translation part, a 3x1 ``ImmutableMatrix``."""
        return self.args[1]

    @property
    def matrix(self) -> ImmutableMatrix:
        """The 4x4 homogeneous matrix ``[[R, p], [0, 1]]``.

        >>> Transform.translation([1, 2, 3]).matrix
        Matrix([
        [1, 0, 0, 1],
        [0, 1, 0, 2],
        [0, 0, 1, 3],
        [0, 0, 0, 1]])
        """
        top = self.R.row_join(self.p)
        return ImmutableMatrix(top.col_join(ImmutableMatrix([[0, 0, 0, 1]])))

    # -------------------------------------------------------------- the group
    def __matmul__(self, other: Transform) -> Transform:
        """``T1 @ T2 = (R1 R2, R1 p2 + p1)``: first ``T2``, then ``T1``."""
        if not isinstance(other, Transform):
            return NotImplemented
        return Transform._new(self.R * other.R, self.R * other.p + self.p)

    def __rmatmul__(self, other: object) -> NoReturn:
        raise TypeError(
            f"cannot compose a {type(other).__name__} with a Transform; use T.matrix for the 4x4"
        )

    def __mul__(self, other: object) -> NoReturn:
        raise TypeError("compose transforms with '@' (T1 @ T2), and move objects with T.apply(x)")

    __rmul__ = __mul__

    def _lambdify_outputs(self) -> ImmutableMatrix:
        """The 4x4 matrix, for :func:`screwsym.lambdify` (an array of shape ``(..., 4, 4)``).

        >>> import numpy as np
        >>> from sympy import symbols
        >>> from screwsym import lambdify
        >>> t = symbols("t", real=True)
        >>> f = lambdify([t], Transform.rotation([0, 0, 1], t), backend="numpy")
        >>> np.round(f(np.array([0.0, np.pi / 2]))[:, :2, :2], 12) + 0.0
        array([[[ 1.,  0.],
                [ 0.,  1.]],
        <BLANKLINE>
               [[ 0., -1.],
                [ 1.,  0.]]])
        """
        return self.matrix

    def inverse(self) -> Transform:
        """``T^-1 = (R^T, -R^T p)``.

        >>> T = Transform.rotation([0, 0, 1], 1, point=[1, 2, 0])
        >>> (T @ T.inverse()).equals(Transform.identity())
        True
        """
        Rt = self.R.T
        return Transform._new(Rt, -(Rt * self.p))

    def adjoint(self) -> ImmutableMatrix:
        r"""The 6x6 matrix ``[[R, 0], [[p]x R, R]]`` that moves ray-order screws.

        It maps a line vector ``(S; S0)``, a twist ``(omega; v_O)`` and a
        wrench ``(f; C_O)`` alike (the same matrix for all three, because in
        ray order the direction part comes first): ``Ad(T) s`` is ``s`` carried
        by the motion ``T``.  ``Ad(T1 @ T2) = Ad(T1) Ad(T2)``.

        >>> Transform.translation([0, 0, 1]).adjoint()
        Matrix([
        [1,  0, 0, 0, 0, 0],
        [0,  1, 0, 0, 0, 0],
        [0,  0, 1, 0, 0, 0],
        [0, -1, 0, 1, 0, 0],
        [1,  0, 0, 0, 1, 0],
        [0,  0, 0, 0, 0, 1]])
        """
        return adjoint_matrix(self)

    @overload
    def apply(self, obj: Transform, *, direction: bool = False) -> Transform: ...
    @overload
    def apply(self, obj: SpatialInertia, *, direction: bool = False) -> SpatialInertia: ...
    @overload
    def apply(self, obj: _S, *, direction: bool = False) -> _S: ...
    @overload
    def apply(self, obj: VectorLike, *, direction: bool = False) -> ImmutableMatrix: ...

    def apply(self, obj: Transform | Screw | SpatialInertia | VectorLike, *,
              direction: bool = False) -> Transform | Screw | SpatialInertia | ImmutableMatrix:
        r"""Carry ``obj`` by the motion: a point, a direction, or any screw.

        * a 3-vector is a point, ``R x + p`` (a 3x1 matrix back), or with
          ``direction=True`` a free vector, ``R x``;
        * a :class:`~screwsym.core.screw.Screw` (a line vector, twist or wrench, or
          a general screw) comes back as the same kind, ``Ad(T) [S; S0]``:
          ``(R S; R S0 + p x R S)``;
        * a :class:`~screwsym.core.inertia.SpatialInertia` is carried as a body:
          its centre of mass ``R c + p``, its inertia ``R I R^T``; its 6x6 matrix
          is then ``Ad(T) M Ad(T)^-1`` (see :mod:`screwsym.core.inertia`);
        * a :class:`Transform` ``X`` is composed, ``T @ X``.

        A bare 6-vector is refused: say what it is with ``Screw.from_matrix``
        (or ``Twist``/``Wrench``/``LineVector``) first.

        >>> from screwsym import LineVector, Wrench
        >>> T = Transform.translation([0, 0, 1])
        >>> T.apply(LineVector.from_axis([0, 0, 0], [1, 0, 0]))
        LineVector([1, 0, 0], [0, 1, 0])
        >>> T.apply([1, 0, 0]).T, T.apply([1, 0, 0], direction=True).T
        (Matrix([[1, 0, 1]]), Matrix([[1, 0, 0]]))
        >>> T.apply([1, 0, 0, 0, 0, 0])
        Traceback (most recent call last):
        ...
        TypeError: obj: expected a point or direction (3-vector), a screw or a Transform, got list [1, 0, 0, 0, 0, 0]; wrap a 6-vector with Screw.from_matrix, Twist.from_matrix or Wrench.from_matrix
        """
        check_flag(direction, "direction")
        if isinstance(obj, Transform):
            return self @ obj
        if isinstance(obj, Screw):
            return tidy(type(obj)(*moved(self.R, self.p, obj.S, obj.S0)))
        if isinstance(obj, SpatialInertia):
            return obj.transformed(self.R, self.p)
        x = check_point_or_direction(obj, "obj")
        return ImmutableMatrix(self.R * x) if direction else ImmutableMatrix(self.R * x + self.p)

    def equals(self, other: Transform) -> bool | None:
        """Whether the two motions are equal mathematically: True, False or None.

        ``==`` compares structure, as everywhere in SymPy.  Floats follow the
        float policy (:func:`screwsym.core.decide.is_zero_scaled`): ``R``
        against 1, ``p`` against ``1 + |p1| + |p2|``.

        >>> from sympy import pi
        >>> Transform.rotation([0, 0, 1], 2*pi).equals(Transform.identity())
        True
        >>> T = Transform.rotation([1, 2, 2], 0.7, point=[1.0, -2.0, 3.0])
        >>> T.inverse().inverse().equals(T)
        True
        """
        check_instance(other, "other", Transform)
        diff = (self.matrix - other.matrix).applyfunc(_tidy)
        if float_tau(*diff) is None:
            return is_zero_vector(diff)
        # floats: the float policy (screwsym.core.decide), R against 1, p against its size
        dR = (self.R - other.R).applyfunc(_tidy).reshape(9, 1)
        dp = (self.p - other.p).applyfunc(_tidy)
        size = S.One + norm(self.p) + norm(other.p)
        return _both(is_zero_vector_scaled(dR, S.One), is_zero_vector_scaled(dp, size))

    # ------------------------------------------------------- SymPy integration
    def applyfunc(self, f: Callable[[Expr], Any]) -> Transform:
        """Apply ``f`` to every entry of ``R`` and ``p`` (e.g. ``trigsimp``); checked again.

        >>> from sympy import symbols
        >>> t = symbols("t", real=True)
        >>> Transform.rotation([0, 0, 1], t).applyfunc(lambda e: e.subs(t, 0))
        Transform(R=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], p=[0, 0, 0])
        """
        g = refusing_strings(f, "applyfunc")  # a matrix would parse a string result
        return Transform(self.R.applyfunc(g), self.p.applyfunc(g))

    def _eval_simplify(self, **kwargs: Any) -> Transform:
        return Transform._new(self.R.simplify(**kwargs), self.p.simplify(**kwargs))

    def _eval_diff_parts(self, *symbols: Any, **kwargs: Any) -> ImmutableMatrix:
        """The derivative of the 4x4 matrix (a derivative of a motion is not a motion).

        >>> from sympy import symbols
        >>> t = symbols("t", real=True)
        >>> Transform.translation([t, t**2, 0]).diff(t)
        Matrix([
        [0, 0, 0,   1],
        [0, 0, 0, 2*t],
        [0, 0, 0,   0],
        [0, 0, 0,   0]])
        """
        return self.matrix.diff(*symbols, **kwargs)

    def _eval_evalf_parts(self, n: int = 15, **options: Any) -> Transform:
        return Transform(self.R.evalf(n, **options), self.p.evalf(n, **options))

    def _sympystr(self, printer: Any) -> str:
        rows = ", ".join(
            "[" + ", ".join(printer._print(e) for e in self.R.row(i)) + "]" for i in range(3)
        )
        p = ", ".join(printer._print(e) for e in self.p)
        return f"Transform(R=[{rows}], p=[{p}])"

    def _latex(self, printer: Any) -> str:
        return printer._print(self.matrix)

    def _pretty(self, printer: Any) -> Any:
        """The 4x4 matrix, as SymPy draws matrices.

        >>> from sympy import pretty
        >>> print(pretty(Transform.translation([1, 2, 3])))
        ⎡1  0  0  1⎤
        ⎢          ⎥
        ⎢0  1  0  2⎥
        ⎢          ⎥
        ⎢0  0  1  3⎥
        ⎢          ⎥
        ⎣0  0  0  1⎦
        """
        return printer._print(self.matrix)


def adjoint_matrix(T: Transform) -> ImmutableMatrix:
    r"""The 6x6 adjoint ``[[R, 0], [[p]x R, R]]`` of ``T`` in ray order; see :meth:`Transform.adjoint`.

    >>> from screwsym.motion.transform import adjoint_matrix
    >>> from screwsym import Transform
    >>> adjoint_matrix(Transform.identity()) == ImmutableMatrix.eye(6)
    True
    """
    check_instance(T, "T", Transform)
    # column j is the action (:func:`screwsym.core.formulas.moved`) on the j-th unit 6-vector
    e = ImmutableMatrix.eye(6)
    columns = [ImmutableMatrix.vstack(*moved(T.R, T.p, e[:3, j], e[3:, j])) for j in range(6)]
    return ImmutableMatrix.hstack(*columns)
