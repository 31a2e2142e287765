r"""Spatial inertia: the map from a body's twist to its momentum wrench.

Explanation
===========

A rigid body of mass ``m`` whose centre of mass is at ``c`` and whose
rotational inertia about the centre of mass is the symmetric 3x3 ``I_c`` (all
in one frame, the frame the object lives in) has, when it moves with the twist
``(omega; v_O)`` (ray order, :mod:`screwsym.core.twist`), the momentum wrench
in ray order ``(f; C_O)`` (:mod:`screwsym.core.wrench`): the linear momentum
first, then the angular momentum about the origin O,

    p   = m (v_O + omega x c)            = m v_O - m [c]x omega,
    L_O = I_c omega + c x p              = (I_c - m [c]x^2) omega + m [c]x v_O.

So the 6x6 matrix of :attr:`SpatialInertia.matrix`, from a ray-order twist to
a ray-order wrench, is

    M = [[-m [c]x,            m 1   ],
         [I_c - m [c]x [c]x,  m [c]x]].

It is not symmetric: ``Delta M`` is, with ``Delta = [[0, 1], [1, 0]]`` the
half swap of the reciprocal product (1.45), and ``Delta M`` is the symmetric
spatial inertia of Featherstone and of Lynch & Park written for ``(omega; v)``
motions and ``(n; f)`` forces.  The kinetic energy is half the reciprocal
product (the power, (1.45)) of the twist and its momentum, ``T = 1/2 $ o M $``.

Under a rigid motion ``(R, p)`` the body's data move as points and tensors:
``c' = R c + p``, ``I_c' = R I_c R^T``, and the matrix by similarity with the
adjoint, ``M' = Ad(T) M Ad(T)^-1`` (both twists and wrenches move with
``Ad(T)`` in ray order); equivalently ``Delta M' = Ad(T^-1)^T (Delta M) Ad(T^-1)``,
the congruence of the symmetric form.

References
==========

R. Featherstone, *Rigid Body Dynamics Algorithms*, Springer 2008, Section 2.13,
(2.62)-(2.63).  Lynch & Park, *Modern Robotics*, Cambridge 2017, Section 8.2.
Huang, Li & Ding, *Theory of Parallel Mechanisms*, Springer 2013, (1.45).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from sympy import Abs, Expr, ImmutableMatrix, S
from sympy.core.evalf import PrecisionExhausted

from .basic import ScrewsymBasic
from .checks import (
    check_flag,
    check_instance,
    check_matrix,
    check_scalar,
    check_vector,
    describe,
)
from .decide import float_tau, is_zero, is_zero_scaled
from .formulas import cross_matrix
from .screw import ScalarLike, VectorLike, check_screw
from .tidy import tidy
from .twist import Twist
from .wrench import Wrench, power

if TYPE_CHECKING:
    from typing_extensions import Self

# cross_matrix (the matrix [v]x) lives in screwsym.core.formulas and is re-exported here
__all__ = ["SpatialInertia", "cross_matrix", "PARAMETER_NAMES"]

#: the ten inertial parameters of a body, in pinocchio's order (``Inertia.toDynamicParameters``):
#: the mass, the first moment ``m c`` and the rotational inertia about the frame's origin
PARAMETER_NAMES = ("m", "mc_x", "mc_y", "mc_z", "I_xx", "I_xy", "I_yy", "I_xz", "I_yz", "I_zz")


#: digits to which :func:`_certified_negative` evaluates an exact number, and the most it lets
#: SymPy's evalf work to reach them (an exact zero never reaches them: then "not proved")
SIGN_DIGITS = 30
SIGN_MAXPREC = 400


def _certified_negative(value: Expr) -> bool:
    """An exact number proved negative by evaluation with a guaranteed accuracy.

    SymPy's ``evalf(strict=True)`` returns a value with :data:`SIGN_DIGITS` correct digits
    (its error bounds tracked through the expression) or raises; a non-zero value so
    evaluated has its sign.  A zero, or a number too close to zero for :data:`SIGN_MAXPREC`
    bits, is not proved negative (False: accepted, as an undecided symbolic condition is).
    Bounded where ``value.is_negative`` (SymPy's own evaluation, with simplification) is not:
    an inertia turned by the sines of a robot file's angles (``cos(9/5)``) took minutes.
    """
    if value.is_Rational:
        return bool(value < 0)
    try:
        v = value.evalf(SIGN_DIGITS, strict=True, maxn=SIGN_MAXPREC)
    except (PrecisionExhausted, ValueError, TypeError):
        return False
    return bool(v.is_Float and v < 0)


def _provably_negative(value: Expr, scale: Expr) -> bool:
    """``value < 0`` provably: exact numbers exactly, floats beyond the float policy's residue.

    A symbolic value is negative only when SymPy's assumptions prove it.
    """
    if value.is_number:
        if float_tau(value, scale) is not None:
            if is_zero_scaled(value, scale) is True:
                return False  # a float residue of a zero
            return bool(value.is_negative)
        return _certified_negative(value)
    return value.is_negative is True


def _principal_minors(A: ImmutableMatrix) -> list[tuple[str, Expr, int]]:
    """The seven principal minors of a 3x3 matrix: ``(name, value, order)``.

    For numbers the determinant is the cofactor sum as written (evaluated, never expanded:
    entries with sines of constant angles made Berkowitz's expansion take minutes)."""
    out: list[tuple[str, Expr, int]] = [(f"[{i}, {i}]", A[i, i], 1) for i in range(3)]
    for i, j in ((0, 1), (0, 2), (1, 2)):
        out.append((f"[{i}{j}, {i}{j}]", A[i, i] * A[j, j] - A[i, j] * A[j, i], 2))
    if all(e.is_number for e in A) and not all(e.is_Rational for e in A):
        det = (A[0, 0] * (A[1, 1] * A[2, 2] - A[1, 2] * A[2, 1])
               - A[0, 1] * (A[1, 0] * A[2, 2] - A[1, 2] * A[2, 0])
               + A[0, 2] * (A[1, 0] * A[2, 1] - A[1, 1] * A[2, 0]))
    else:
        det = A.det(method="berkowitz")
    out.append(("det", det, 3))
    return out


def _check_psd(A: ImmutableMatrix, name: str, what: str) -> None:
    """Raise ValueError when a principal minor of the symmetric ``A`` is provably negative.

    A symmetric matrix is positive semi-definite exactly when all its principal
    minors are non-negative (not only the leading ones).
    """
    # the size of the entries, for the float policy's residue (floats only: |e| of an exact
    # entry with sines of constants is costly and unused)
    scale = sum((Abs(e) for e in A), S.Zero) if float_tau(*A) is not None else S.One
    for label, minor, order in _principal_minors(A):
        if _provably_negative(minor, scale**order):
            raise ValueError(
                f"{name}: expected {what}, got the principal minor {label} = {minor} < 0"
            )


def check_inertia_tensor(value: Any, name: str) -> ImmutableMatrix:
    r"""Return ``value`` as a symmetric 3x3 rotational inertia, refusing a provably unphysical one.

    Refused (``ValueError`` naming ``name``): an asymmetric matrix (an entry of
    ``I - I^T`` provably non-zero), one that is not positive semi-definite (a
    principal minor provably negative), and one whose principal moments break the
    triangle inequalities ``I_1 + I_2 >= I_3`` (the same as ``tr(I)/2 1 - I``,
    the body's second moment of mass, being positive semi-definite).  Exact entries
    are decided exactly, floats by the float policy; a symbolic condition the
    assumptions cannot decide is accepted (declare the symbols ``positive=True``
    to have more decided).

    >>> check_inertia_tensor([[1, 0, 0], [0, 1, 0], [0, 0, 3]], "inertia")
    Traceback (most recent call last):
    ...
    ValueError: inertia: expected principal moments that satisfy the triangle inequalities (tr(I)/2 - I positive semi-definite), got the principal minor [2, 2] = -1/2 < 0
    """
    I = check_matrix(value, name, (3, 3))
    for i, j in ((0, 1), (0, 2), (1, 2)):
        if is_zero(I[i, j] - I[j, i]) is False:
            raise ValueError(
                f"{name}: expected a symmetric matrix, got [{i}, {j}] = {I[i, j]} and "
                f"[{j}, {i}] = {I[j, i]}"
            )
    _check_psd(I, name, "a positive semi-definite matrix")
    half_trace = (I[0, 0] + I[1, 1] + I[2, 2]) / 2
    _check_psd(
        ImmutableMatrix.eye(3) * half_trace - I, name,
        "principal moments that satisfy the triangle inequalities (tr(I)/2 - I positive "
        "semi-definite)",
    )
    return I


class SpatialInertia(ScrewsymBasic):
    r"""The inertia of a rigid body: mass, centre of mass, rotational inertia about it.

    Explanation
    ===========

    ``args == (mass, com, inertia)``: a scalar, a 3x1 and a symmetric 3x3
    ``ImmutableMatrix``, all in the frame the object lives in; ``inertia`` is
    about the centre of mass ``com``.  The module docstring gives the 6x6
    :attr:`matrix` from a ray-order twist ``(omega; v_O)`` to the momentum
    wrench ``(f; C_O)`` (linear momentum first).  Checked where provable: the
    mass positive, the inertia symmetric, positive semi-definite, its principal
    moments satisfying the triangle inequalities (see
    :func:`check_inertia_tensor`); a symbolic condition that cannot be decided is
    accepted.  ``==`` is structural, as in SymPy; :meth:`equals` decides.

    Examples
    ========

    A point mass 2 at ``(1, 0, 0)`` turning about the z axis:

    >>> from screwsym import Twist
    >>> from screwsym.core.inertia import SpatialInertia
    >>> body = SpatialInertia(2, [1, 0, 0], [[0, 0, 0], [0, 0, 0], [0, 0, 0]])
    >>> t = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    >>> body.momentum(t)                  # linear momentum 2 along y, angular 2 about z
    Wrench([0, 2, 0], [0, 0, 2])
    >>> body.kinetic_energy(t)
    1
    >>> body + SpatialInertia(2, [-1, 0, 0], [[0, 0, 0], [0, 0, 0], [0, 0, 0]])
    SpatialInertia(mass=4, com=[0, 0, 0], inertia=[[0, 0, 0], [0, 4, 0], [0, 0, 4]])
    >>> SpatialInertia(-1, [0, 0, 0], [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    Traceback (most recent call last):
    ...
    ValueError: mass: expected a positive mass, got -1

    Parameters
    ==========

    mass : scalar
        Positive (a symbol should be declared ``positive=True``).
    com : 3-vector
        The centre of mass.
    inertia : 3x3 matrix
        The rotational inertia about the centre of mass.

    See Also
    ========

    screwsym.motion.transform.Transform.apply, screwsym.motion.chain.Chain
    """

    __slots__ = ()

    def __new__(cls, mass: ScalarLike, com: VectorLike, inertia: Any) -> Self:
        m = check_scalar(mass, "mass")
        if is_zero(m) is True or m.is_nonpositive is True or (
            m.is_number and _provably_negative(m, S.One)
        ):
            raise ValueError(f"mass: expected a positive mass, got {m}")
        c = check_vector(com, "com")
        I = check_inertia_tensor(inertia, "inertia")
        return ScrewsymBasic.__new__(cls, m, c, I)

    @classmethod
    def _new(cls, m: Expr, c: ImmutableMatrix, I: ImmutableMatrix) -> Self:
        """From parts known to be physical (moved or summed from checked ones): no checks."""
        return ScrewsymBasic.__new__(cls, m, ImmutableMatrix(c), ImmutableMatrix(I))

    @classmethod
    def point_mass(cls, mass: ScalarLike, point: VectorLike) -> Self:
        """A point mass at ``point`` (zero rotational inertia about it).

        >>> SpatialInertia.point_mass(3, [0, 0, 1]).inertia_about([0, 0, 0])
        Matrix([
        [3, 0, 0],
        [0, 3, 0],
        [0, 0, 0]])
        """
        return cls(mass, point, ImmutableMatrix.zeros(3, 3))

    @classmethod
    def from_parameters(cls, parameters: Any) -> Self:
        r"""The body of the ten parameters ``[m, mc_x, mc_y, mc_z, I_xx, I_xy, I_yy, I_xz, I_yz, I_zz]``.

        The inverse of :meth:`parameters` (pinocchio's order, the inertia about
        the frame's origin): ``c = (m c)/m``, ``I_c = I_O + m [c]x^2``.  Checked as
        the constructor checks.

        >>> SpatialInertia.from_parameters([2, 2, 0, 0, 0, 0, 2, 0, 0, 2])
        SpatialInertia(mass=2, com=[1, 0, 0], inertia=[[0, 0, 0], [0, 0, 0], [0, 0, 0]])
        """
        if isinstance(parameters, (str, bytes)) or not hasattr(parameters, "__len__") or len(
            parameters
        ) != 10:
            raise ValueError(
                f"parameters: expected the ten inertial parameters {list(PARAMETER_NAMES)}, "
                f"got {describe(parameters)}"
            )
        p = [check_scalar(x, f"parameters[{i}]") for i, x in enumerate(parameters)]
        m = p[0]
        if is_zero(m) is True or m.is_nonpositive is True:
            raise ValueError(f"parameters[0]: expected a positive mass, got {m}")
        c = ImmutableMatrix(p[1:4]) / m
        xx, xy, yy, xz, yz, zz = p[4:]
        I_O = ImmutableMatrix([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
        cx = cross_matrix(c)
        return cls(m, tidy(c), tidy(I_O + m * cx * cx))

    # ------------------------------------------------------------------ parts
    @property
    def mass(self) -> Expr:
        """The mass."""
        return self.args[0]

    @property
    def com(self) -> ImmutableMatrix:
        """The centre of mass, a 3x1 ``ImmutableMatrix``."""
        return self.args[1]

    @property
    def inertia(self) -> ImmutableMatrix:
        """The rotational inertia about the centre of mass, a symmetric 3x3 ``ImmutableMatrix``."""
        return self.args[2]

    @property
    def first_moment(self) -> ImmutableMatrix:
        """The first moment of mass ``m c`` about the origin."""
        return self.mass * self.com

    def inertia_about(self, point: VectorLike) -> ImmutableMatrix:
        r"""The rotational inertia about ``point``: ``I_c - m [c - point]x^2`` (parallel axes), tidied.

        >>> SpatialInertia.point_mass(1, [1, 0, 0]).inertia_about([0, 0, 0])
        Matrix([
        [0, 0, 0],
        [0, 1, 0],
        [0, 0, 1]])
        """
        d = cross_matrix(self.com - check_vector(point, "point"))
        return tidy(self.inertia - self.mass * d * d)

    def parameters(self) -> ImmutableMatrix:
        r"""The ten inertial parameters about the origin, a 10x1 column, tidied.

        ``[m, mc_x, mc_y, mc_z, I_xx, I_xy, I_yy, I_xz, I_yz, I_zz]``
        (:data:`PARAMETER_NAMES`, pinocchio's ``Inertia.toDynamicParameters``
        order): the mass, the first moment ``m c`` and the entries of the
        rotational inertia about the frame's origin, ``I_O = I_c - m [c]x^2``.  The
        momentum (and so the dynamics of a chain) is linear in them.

        >>> SpatialInertia.point_mass(2, [1, 0, 0]).parameters().T
        Matrix([[2, 2, 0, 0, 0, 0, 2, 0, 0, 2]])
        """
        I_O = self.inertia_about([0, 0, 0])
        h = tidy(self.first_moment)
        return ImmutableMatrix(
            [self.mass, *h, I_O[0, 0], I_O[0, 1], I_O[1, 1], I_O[0, 2], I_O[1, 2], I_O[2, 2]]
        )

    @property
    def matrix(self) -> ImmutableMatrix:
        r"""The 6x6 map from a ray-order twist ``(omega; v_O)`` to the momentum wrench ``(f; C_O)``.

        A property, as :attr:`Screw.matrix <screwsym.core.screw.Screw.matrix>`
        is: ``[[-m [c]x, m 1], [I_c - m [c]x^2, m [c]x]]`` (module docstring).

        >>> SpatialInertia(1, [0, 0, 1], [[1, 0, 0], [0, 1, 0], [0, 0, 1]]).matrix
        Matrix([
        [ 0, 1, 0, 1,  0, 0],
        [-1, 0, 0, 0,  1, 0],
        [ 0, 0, 0, 0,  0, 1],
        [ 2, 0, 0, 0, -1, 0],
        [ 0, 2, 0, 1,  0, 0],
        [ 0, 0, 1, 0,  0, 0]])
        """
        return spatial_matrix(self.mass, self.first_moment, self.inertia_about([0, 0, 0]))

    def _lambdify_outputs(self) -> ImmutableMatrix:
        """The 6x6 :attr:`matrix`, for :func:`screwsym.lambdify` (``(..., 6, 6)``)."""
        return self.matrix

    # ---------------------------------------------------------------- physics
    def momentum(self, twist: Any, *, tidy: bool = True) -> Wrench:
        r"""The momentum wrench ``(m (v_O + omega x c); I_c omega + c x p)`` of the body moving with ``twist``.

        Linear momentum first, then the angular momentum about the origin
        (ray order, as a wrench ``(f; C_O)``); tidied unless ``tidy=False``.

        >>> from screwsym import Twist
        >>> SpatialInertia.point_mass(1, [0, 0, 0]).momentum(Twist.translation([1, 0, 0]))
        Wrench([1, 0, 0], [0, 0, 0])
        """
        t = check_screw(twist, "twist", Twist)
        w = self.matrix * t.matrix
        out = Wrench.from_matrix(w)
        return _tidied(out) if check_flag(tidy, "tidy") else out

    def kinetic_energy(self, twist: Any) -> Expr:
        r"""The kinetic energy ``1/2 $ o M $``: half the power of the momentum on the twist (1.45).

        >>> from sympy import symbols
        >>> from screwsym import Twist
        >>> w = symbols("w", real=True)
        >>> rod = SpatialInertia(3, [0, 0, 0], [[1, 0, 0], [0, 1, 0], [0, 0, 0]])
        >>> rod.kinetic_energy(Twist([0, w, 0], [0, 0, 0]))
        w**2/2
        """
        t = check_screw(twist, "twist", Twist)
        return tidy(power(t, self.momentum(t, tidy=False), tidy=False) / 2)

    def gravity_wrench(self, g: VectorLike) -> Wrench:
        r"""The weight ``(m g; c x m g)`` of the body under the gravitational acceleration ``g``.

        The force ``m g`` acting through the centre of mass; ``g`` points down,
        e.g. ``[0, 0, -9.81]``.

        >>> SpatialInertia.point_mass(2, [1, 0, 0]).gravity_wrench([0, 0, -10])
        Wrench([0, 0, -20], [0, 20, 0])
        """
        f = self.mass * check_vector(g, "g")
        return _tidied(Wrench(f, self.com.cross(f)))

    def transformed(self, R: ImmutableMatrix, p: ImmutableMatrix) -> SpatialInertia:
        r"""The body carried by the rigid motion ``x -> R x + p``: ``c' = R c + p``, ``I' = R I R^T``.

        For a checked rotation ``R`` and 3x1 ``p``; use
        :meth:`Transform.apply <screwsym.motion.transform.Transform.apply>`, which
        checks them.  Tidied.
        """
        return SpatialInertia._new(
            self.mass, tidy(R * self.com + p), tidy(R * self.inertia * R.T)
        )

    def __add__(self, other: object) -> SpatialInertia:
        r"""Two bodies as one: masses add, ``c = (m1 c1 + m2 c2)/(m1 + m2)``, inertias by parallel axes."""
        if not isinstance(other, SpatialInertia):
            return NotImplemented
        m = self.mass + other.mass
        c = tidy((self.first_moment + other.first_moment) / m)
        I = self.inertia_about(c) + other.inertia_about(c)
        return SpatialInertia._new(tidy(m), c, tidy(I))

    def equals(self, other: SpatialInertia) -> bool | None:
        """Whether the two bodies are equal mathematically: True, False or None.

        >>> a = SpatialInertia(1, [0, 0, 0], [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
        >>> a.equals(SpatialInertia(1, [0, 0, 0], [[1, 0, 0], [0, 1, 0], [0, 0, 2]]))
        False
        """
        check_instance(other, "other", SpatialInertia)
        parts = [self.mass - other.mass, *(self.com - other.com), *(self.inertia - other.inertia)]
        decisions = [is_zero(tidy(d)) for d in parts]
        if any(d is False for d in decisions):
            return False
        return True if all(d is True for d in decisions) else None

    # ------------------------------------------------------- SymPy integration
    def _eval_simplify(self, **kwargs: Any) -> SpatialInertia:
        from sympy import simplify

        return SpatialInertia._new(
            simplify(self.mass, **kwargs), self.com.simplify(**kwargs),
            self.inertia.simplify(**kwargs),
        )

    def _eval_evalf_parts(self, n: int = 15, **options: Any) -> SpatialInertia:
        return SpatialInertia._new(
            self.mass.evalf(n, **options), self.com.evalf(n, **options),
            self.inertia.evalf(n, **options),
        )

    def _sympystr(self, printer: Any) -> str:
        c = ", ".join(printer._print(e) for e in self.com)
        rows = ", ".join(
            "[" + ", ".join(printer._print(e) for e in self.inertia.row(i)) + "]" for i in range(3)
        )
        return f"SpatialInertia(mass={printer._print(self.mass)}, com=[{c}], inertia=[{rows}])"

    def _latex(self, printer: Any) -> str:
        return printer._print(self.matrix)


def _tidied(w: Wrench) -> Wrench:
    return tidy(w)


def spatial_matrix(m: Expr, h: ImmutableMatrix, I_O: ImmutableMatrix) -> ImmutableMatrix:
    r"""The ray-order 6x6 ``[[-[h]x, m 1], [I_O, [h]x]]`` of the mass ``m``, first moment ``h = m c`` and ``I_O``.

    Linear in the ten parameters ``(m, h, I_O)``: the one formula of the
    momentum, which :class:`SpatialInertia` and the dynamics of a chain share.
    """
    H = cross_matrix(h)
    top = (-H).row_join(ImmutableMatrix.eye(3) * m)
    return ImmutableMatrix(top.col_join(I_O.row_join(H)))
