r"""Assembly modes of parallel mechanisms: the direct kinematics, exact, and its inverse.

Given where the legs are attached (``base_points`` on the fixed base, ``platform_points``
in the frame of the moving platform) and the leg lengths, :func:`direct_kinematics` finds
every real pose of the platform (every *assembly mode*); :func:`leg_lengths` is the inverse
kinematics, the leg lengths of a given pose.

The planar 3-RPR (three legs of variable length between base and platform points, 2-D
points; Hunt 1983; Gosselin, Sefrioui & Richard 1992).  With the platform at ``(x, y)``
turned by ``phi`` the legs close when ``|p + R(phi) b_i - a_i|**2 = rho_i**2``.  The
differences of the three closures are linear in ``p``: Cramer's rule gives ``p`` as a
rational function of ``cos phi``, ``sin phi``, and the first closure a polynomial in
``t = tan(phi/2)`` which, rid of its factors ``1 + t**2`` (the circular points, no real
root), has degree at most 6: :attr:`AssemblyModes.polynomial`.  Its real roots are
isolated exactly (Sturm sequences: SymPy's ``intervals``/``CRootOf``), and ``x``, ``y``
are polynomials in the root (the Cramer quotient reduced modulo its minimal polynomial).
Handled apart, never lost: ``phi = pi`` (``t`` infinite: the closures solved at
``cos phi = -1``), a root where Cramer's determinant vanishes (a line of positions meets
a circle: zero, one or two modes, the square root of an exactly signed number), and the
infinite families: the whole curve when the polynomial vanishes identically, a circle of
positions at one angle when both differences vanish there (:class:`AssemblyFamily`).

Input: rational coordinates (``int``, ``Fraction``, SymPy ``Rational``); a leg length is
a number whose square is rational (``sqrt(5)`` is fine).  Floats are taken as the exact
rationals of their binary values (``0.1`` is ``3602879701896397/36028797018963968``), so a
float input gives the exact answer of the float data, not of the decimal the user meant.

The general 6-6 Gough-Stewart platform (six legs, no two sharing a point as the 3-3 and 6-3
do): Study's parameters (Husty 1996), a homotopy continuation in NumPy that proposes every
mode, Krawczyk's test in exact rational arithmetic that proves each (one mode in a box,
real or not), and the bound of 40 complex modes (Ronga & Vust 1995; Lazard 1993; Mourrain
1993) that proves the list complete when 40 are certified: :mod:`._homotopy`.

Every step charges the work budget (:mod:`screwsym.algebra.budget`): past it a
``ValueError`` naming ``direct_kinematics``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from sympy import (
    CRootOf,
    Expr,
    Float,
    ImmutableMatrix,
    Integer,
    Matrix,
    Poly,
    Rational,
    Symbol,
    atan,
    cos,
    eye,
    factor_list,
    minimal_polynomial,
    pi,
    sin,
    sqrt,
    together,
)
from sympy.core.evalf import PrecisionExhausted
from sympy.polys.polyerrors import CoercionFailed, NotAlgebraic, PolynomialError

from ..algebra.budget import BUDGET, case_budget, charge
from ..core.checks import (
    check_count,
    check_matrix,
    check_scalar,
    check_sequence,
    check_vector,
    describe,
)
from ._gough_stewart import SpatialMode, paired_legs, paired_modes
from ._homotopy import CertifiedMode
from ._root_field import RealRoot, real_roots_of

__all__ = [
    "direct_kinematics",
    "leg_lengths",
    "AssemblyModes",
    "PlanarMode",
    "AssemblyFamily",
    "SpatialMode",
    "CertifiedMode",
]

#: the variable of the univariate polynomials: ``t = tan(phi/2)``
T = Symbol("t")


# --------------------------------------------------------------------------------------
# results
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PlanarMode:
    """One assembly mode of a planar platform: its origin at ``(x, y)``, turned by ``phi``.

    ``x``, ``y``, ``phi`` are exact SymPy numbers (``phi = 2*atan(t)`` with ``t`` a root of the
    polynomial, or ``pi``); ``t`` is ``tan(phi/2)`` (``None`` at ``phi = pi``);
    ``multiplicity`` is the root's (above 1: the legs are at a singularity, two modes
    merged).  :meth:`evalf` gives the pose to any number of digits.
    """

    x: Expr
    y: Expr
    phi: Expr
    t: Expr | None
    multiplicity: int = 1

    @property
    def pose(self) -> tuple[Expr, Expr, Expr]:
        """``(x, y, phi)``, exact."""
        return (self.x, self.y, self.phi)

    def evalf(self, n: int = 15) -> tuple[Float, Float, Float]:
        """``(x, y, phi)`` to ``n`` significant digits (the roots refined as far as needed)."""
        check_count(n, "n")
        return (self.x.evalf(n), self.y.evalf(n), self.phi.evalf(n))


@dataclass(frozen=True)
class AssemblyFamily:
    """Infinitely many assembly modes: a curve of them, or a circle of positions at one angle.

    ``kind`` is ``"curve"`` (``x``, ``y`` rational functions of ``t = tan(phi/2)``, the
    symbol :data:`T`, for every real ``t`` but the zeros of ``where_not``) or ``"circle"``
    (at the angle ``phi``, every position at distance ``radius`` from ``center``).
    """

    kind: str
    description: str
    x: Expr | None = None
    y: Expr | None = None
    where_not: Expr | None = None
    phi: Expr | None = None
    center: tuple[Expr, Expr] | None = None
    radius: Expr | None = None


@dataclass(frozen=True)
class AssemblyModes:
    """The assembly modes of a mechanism for given leg lengths (:func:`direct_kinematics`).

    ``polynomial`` is the univariate polynomial solved (a ``Poly`` in ``t = tan(phi/2)``
    for the 3-RPR), or None for the general 6-6 Gough-Stewart platform (no univariate
    polynomial is computed there: its modes are found by a homotopy and each certified),
    ``isolated_modes`` the modes found one by one, ``families`` the infinite families
    (empty when the modes are finitely many).  :attr:`modes` is the complete list, and
    refuses to answer when there are infinitely many or when the list is not proven complete.

    ``complete`` says whether every isolated mode is proven found (always, but for a 6-6
    whose certified complex modes fall short of the bound 40); ``certified`` is, for the
    6-6, the number of distinct complex modes proven (real or not; None otherwise).
    """

    polynomial: Poly | None
    isolated_modes: tuple
    families: tuple
    base_points: tuple
    platform_points: tuple
    squared_lengths: tuple
    complete: bool = True
    certified: int | None = None

    @property
    def is_finite(self) -> bool:
        """Whether the modes are finitely many."""
        return not self.families

    @property
    def modes(self) -> tuple:
        """Every real assembly mode; ``ValueError`` when they are infinitely many, or when
        the list is not proven complete (``complete`` False: see ``.isolated_modes``)."""
        if not self.complete:
            raise ValueError(
                f"direct_kinematics: only {self.certified} of at most 40 complex assembly modes "
                "were certified, so the real ones found may not be all: see .isolated_modes "
                "(each certified) and .certified"
            )
        if self.families:
            raise ValueError(
                "direct_kinematics: infinitely many assembly modes ("
                + "; ".join(f.description for f in self.families)
                + "): see .families (and .isolated_modes for the others)"
            )
        return self.isolated_modes

    def closes(self, pose: Sequence) -> bool:
        """Whether ``pose`` gives every leg its length, decided exactly (a float is taken as
        its exact binary value, so a rounded pose does not close).

        >>> m = direct_kinematics([(0, 0), (4, 0), (0, 3)], [(0, 0), (4, 0), (0, 3)], [1, 1, 1])
        >>> m.closes((1, 0, 0)), m.closes((1 + Rational(1, 10**40), 0, 0))
        (True, False)
        """
        lengths = leg_lengths(self.base_points, self.platform_points, pose)
        with case_budget(BUDGET, "closes"):
            if len(self.base_points[0]) == 3:  # a rotation, exactly: R^T R = 1, det R = 1
                R = _exact(check_matrix(pose[1], "pose[1]", (3, 3)))
                if not all(_is_zero_number(e) for e in (R.T * R - eye(3))) or not _is_zero_number(R.det(method="berkowitz") - 1):
                    return False
            return all(
                _is_zero_number(length**2 - l2)
                for length, l2 in zip(lengths, self.squared_lengths, strict=True)
            )


# --------------------------------------------------------------------------------------
# input
# --------------------------------------------------------------------------------------


def _rational(value: Any, name: str) -> Rational:
    """``value`` as an exact rational (a float as its binary value), else a clear error."""
    if isinstance(value, Fraction):
        return Rational(value.numerator, value.denominator)
    e = check_scalar(value, name)
    if isinstance(e, Float):
        return Rational(e)
    if not e.is_Rational:
        raise ValueError(
            f"{name}: expected a rational number (int, Fraction, Rational or float), got {e}"
        )
    return e


def _squared_length(value: Any, name: str) -> Rational:
    """The square of a non-negative leg length whose square is rational."""
    if isinstance(value, Fraction):
        value = Rational(value.numerator, value.denominator)
    e = check_scalar(value, name)
    if isinstance(e, Float):
        e = Rational(e)
    if e.is_negative:
        raise ValueError(f"{name}: expected a non-negative length, got {e}")
    sq = (e**2).expand()
    if not (sq.is_Rational and e.is_nonnegative):
        raise ValueError(
            f"{name}: expected a non-negative number whose square is rational, got {e}"
        )
    return sq


def _points(value: Any, name: str, dim: int, count: int | None) -> tuple:
    items = check_sequence(value, name, f"{dim}-D points", count)
    out = []
    for i, p in enumerate(items):
        coords = check_sequence(p, f"{name}[{i}]", "coordinates", dim)
        out.append(tuple(_rational(c, f"{name}[{i}]") for c in coords))
    return tuple(out)


def _dimension(value: Any, name: str) -> int:
    items = check_sequence(value, name, "points")
    if not items:
        raise ValueError(f"{name}: expected points, got an empty sequence")
    first = check_sequence(items[0], f"{name}[0]", "coordinates")
    if len(first) not in (2, 3):
        raise ValueError(f"{name}[0]: expected a 2-D or 3-D point, got {describe(items[0])}")
    return len(first)


# --------------------------------------------------------------------------------------
# the planar 3-RPR
# --------------------------------------------------------------------------------------


def _p(e: Any) -> Poly:
    return Poly(e, T, domain="QQ")


def _planar_system(a: tuple, b: tuple, l2: tuple, at_pi: bool) -> dict:
    """The closures scaled by ``U = 1 + t**2`` (``c = C/U``, ``s = S/U``), as polynomials in
    ``t`` (constants at ``phi = pi``): the rows of Cramer's system, its right side, and the
    first closure's ``W_1``, ``K_1`` (the closure: ``U |p|**2 + 2 p.W_1 + K_1 = 0``)."""
    if at_pi:
        U, C, S = _p(1), _p(-1), _p(0)
    else:
        U, C, S = _p(1 + T**2), _p(1 - T**2), _p(2 * T)
    W, K = [], []
    for (ax, ay), (bx, by), q in zip(a, b, l2, strict=True):
        rbx, rby = C * bx - S * by, S * bx + C * by
        W.append((rbx - U * ax, rby - U * ay))
        K.append(U * (bx**2 + by**2 + ax**2 + ay**2 - q) - 2 * (ax * rbx + ay * rby))
    rows = [tuple(2 * (W[i][j] - W[0][j]) for j in range(2)) for i in (1, 2)]
    rhs = [K[0] - K[i] for i in (1, 2)]
    return {"U": U, "rows": rows, "rhs": rhs, "W": W[0], "K": K[0]}


def _cramer(sys_: dict) -> tuple[Poly, Poly, Poly]:
    """``det`` and ``adj(rows) rhs`` of Cramer's rule: ``p = (nx, ny) / det``."""
    (m11, m12), (m21, m22) = sys_["rows"]
    r1, r2 = sys_["rhs"]
    return m11 * m22 - m12 * m21, m22 * r1 - m12 * r2, m11 * r2 - m21 * r1


def _angle(root: RealRoot | None) -> tuple[Expr, Expr | None]:
    if root is None:
        return pi, None
    r = root.expr
    return 2 * atan(r), r


def _planar_modes_at(sys_: dict, root: RealRoot, at_pi: bool, mult: int) -> tuple[list, list]:
    """The modes (and families) at one angle: ``t`` the root (or ``phi = pi``), by the rank of
    Cramer's system there."""
    phi, tval = _angle(None if at_pi else root)
    (m11, m12), (m21, m22) = sys_["rows"]
    r1, r2 = sys_["rhs"]
    U, W, K = sys_["U"], sys_["W"], sys_["K"]
    det, nx, ny = _cramer(sys_)
    val = root.value
    if not root.is_zero(det):  # one position: Cramer's rule
        charge(root.g.degree() ** 2 * 10)
        inv = root.inverse(det)
        x, y = val(nx * inv), val(ny * inv)
        if not root.is_zero(U * (nx**2 + ny**2) + 2 * det * (nx * W[0] + ny * W[1]) + det**2 * K):
            return [], []  # phi = pi need not be a mode
        return [PlanarMode(x, y, phi, tval, mult)], []
    rows = [((m11, m12), r1), ((m21, m22), r2)]
    live = [(m, r) for m, r in rows if not (root.is_zero(m[0]) and root.is_zero(m[1]))]
    if not live:  # both differences vanish: the first closure alone, a circle of positions
        if not (root.is_zero(r1) and root.is_zero(r2)):
            return [], []
        r2c = W[0] ** 2 + W[1] ** 2 - U * K  # radius**2 * U**2
        sign = root.sign(r2c)
        if sign < 0:
            return [], []
        cx, cy = val(-W[0]) / val(U), val(-W[1]) / val(U)
        if sign == 0:
            return [PlanarMode(cx, cy, phi, tval, mult)], []
        radius = sqrt(val(r2c)) / val(U)
        fam = AssemblyFamily(
            "circle",
            f"at phi = {phi}, every position at distance {radius} from ({cx}, {cy})",
            phi=phi,
            center=(cx, cy),
            radius=radius,
        )
        return [], [fam]
    (mx, my), v = live[0]
    for (ox, oy), w in live[1:]:  # the other row, parallel: consistent or no mode
        if not (root.is_zero(w * mx - v * ox) and root.is_zero(w * my - v * oy)):
            return [], []
    # the line m.p = v: p = v m / N + lam (-my, mx), N = |m|**2; the closure times N
    N = mx**2 + my**2
    qa = U * N**2
    qb = 2 * N * (mx * W[1] - my * W[0])
    qc = U * v**2 + 2 * v * (mx * W[0] + my * W[1]) + N * K
    disc = qb**2 - 4 * qa * qc
    sign = root.sign(disc)
    if sign < 0:
        return [], []
    # lam = (-qb + d) / (2 qa), d = +-sqrt(disc): p = p0 + d p1, p0 and p1 in Q(r)
    inv_n, inv_a = root.inverse(N), root.inverse(2 * qa)
    x0 = v * mx * inv_n + qb * inv_a * my
    y0 = v * my * inv_n - qb * inv_a * mx
    x1, y1 = -inv_a * my, inv_a * mx
    roots = [Integer(0)] if sign == 0 else [sqrt(val(disc)), -sqrt(val(disc))]
    modes = [PlanarMode(val(x0) + d * val(x1), val(y0) + d * val(y1), phi, tval, mult) for d in roots]
    return modes, []


def _strip_circular(p: Poly) -> Poly:
    """``p`` rid of its factors ``1 + t**2`` (no real root: the circular points)."""
    q = _p(1 + T**2)
    while not p.is_zero and p.degree() >= 2:
        quo, rem = p.div(q)
        if not rem.is_zero:
            break
        p = quo
    if p.is_zero:
        return p.set_domain("ZZ")
    _, p = p.clear_denoms(convert=True)
    p = p.primitive()[1]
    return -p if p.LC() < 0 else p


def _parallel_rows(sys_: dict) -> Poly:
    """The polynomial whose real roots hold every mode when Cramer's determinant vanishes at
    every angle (the platform the base's mirror image, or both collinear in proportion): the
    two rows stay parallel, so a mode needs the right sides in proportion too,
    ``r_2 m_3 - r_3 m_2 = 0``, or a row vanishing; each root is then solved as any
    Cramer-singular root (:func:`_planar_modes_at`)."""
    (m2, r2), (m3, r3) = zip(sys_["rows"], sys_["rhs"], strict=True)
    cons = (r2 * m3[0] - r3 * m2[0]).gcd(r2 * m3[1] - r3 * m2[1])
    if cons.is_zero:  # consistent at every angle: a line meets a circle at each
        raise NotImplementedError(
            "direct_kinematics: the leg differences stay parallel and consistent at every angle "
            "(the platform the base's mirror image with special lengths); whether a curve of "
            "modes is real is not decided here"
        )
    row = m2 if not (m2[0].is_zero and m2[1].is_zero) else m3
    vanish = row[0].gcd(row[1])
    return _strip_circular(cons * vanish)


def _planar(a: tuple, b: tuple, l2: tuple) -> AssemblyModes:
    sys_ = _planar_system(a, b, l2, at_pi=False)
    det, nx, ny = _cramer(sys_)
    U, W, K = sys_["U"], sys_["W"], sys_["K"]
    charge(2000)
    if det.is_zero:
        poly = _parallel_rows(sys_)
    else:
        full = U * (nx**2 + ny**2) + 2 * det * (nx * W[0] + ny * W[1]) + det**2 * K
        poly = _strip_circular(full)
    modes: list = []
    families: list = []
    if poly.is_zero:
        common = det.gcd(nx).gcd(ny)
        where = det.quo(common).as_expr()
        families.append(
            AssemblyFamily(
                "curve",
                f"a curve of modes: every phi = 2*atan(t), t real (and {where} != 0)",
                x=nx.quo(common).as_expr() / where,
                y=ny.quo(common).as_expr() / where,
                where_not=where,
            )
        )
    else:
        charge(len(poly.terms()) ** 2 * 50)
        _, factors = factor_list(poly)
        for g, mult in factors:
            for root in real_roots_of(g.set_domain("QQ")):
                found, fams = _planar_modes_at(sys_, root, False, mult)
                modes.extend(found)
                families.extend(fams)
    pi_sys = _planar_system(a, b, l2, at_pi=True)
    found, fams = _planar_modes_at(pi_sys, real_roots_of(_p(T))[0], True, 1)
    if not poly.is_zero:
        modes.extend(found)
    families.extend(fams)
    modes.sort(key=lambda m: (m.phi.evalf(30), m.x.evalf(30), m.y.evalf(30)))
    return AssemblyModes(poly, tuple(modes), tuple(families), a, b, l2)


# --------------------------------------------------------------------------------------
# public
# --------------------------------------------------------------------------------------


def direct_kinematics(
    base_points: Sequence, platform_points: Sequence, lengths: Sequence, *, budget: int = BUDGET
) -> AssemblyModes:
    r"""Every real assembly mode of a parallel mechanism for given leg lengths, exact.

    Floats, in every case, are taken as the exact rationals of their binary values.

    The planar 3-RPR: ``base_points`` three 2-D points on the base, ``platform_points`` three
    2-D points in the platform's frame, ``lengths`` the three leg lengths.  A pose is
    ``(x, y, phi)``: the platform's origin and its angle.  The answer
    (:class:`AssemblyModes`) holds the univariate polynomial in ``t = tan(phi/2)`` (degree at
    most 6), the modes (:class:`PlanarMode`: ``phi = 2*atan(t)`` at each real root ``t``,
    ``x``, ``y`` polynomials in the root; ``phi = pi`` checked apart) and the infinite
    families if any (then ``.modes`` raises).  Floats are taken as the exact rationals of
    their binary values; lengths may be any non-negative numbers with rational squares.

    Gosselin, Sefrioui & Richard (1992) bound the modes by 6, and six real ones occur.  Here
    legs of lengths 11, 10, 11 between a base and a platform triangle give six, each closing
    the legs exactly:

    >>> m = direct_kinematics([(0, 0), (10, 0), (-2, 9)], [(0, 0), (9, 0), (5, 6)], [11, 10, 11])
    >>> m.polynomial
    Poly(275625*t**6 - 1052100*t**5 - 1078329*t**4 + 1629624*t**3 - 474185*t**2 + 18444*t + 2809, t, domain='ZZ')
    >>> len(m.modes)
    6
    >>> m.modes[0].t
    CRootOf(275625*t**6 - 1052100*t**5 - 1078329*t**4 + 1629624*t**3 - 474185*t**2 + 18444*t + 2809, 0)
    >>> m.modes[0].evalf(20)
    (3.9932828818367840853, 10.249570323951600105, -2.0035926418648734321)
    >>> m.closes(m.modes[0].pose)
    True

    A platform equal to its base with equal legs translates on a circle: infinitely many
    modes, reported as such (``.modes`` raises; ``.isolated_modes`` holds the others):

    >>> m = direct_kinematics([(0, 0), (4, 0), (0, 3)], [(0, 0), (4, 0), (0, 3)], [1, 1, 1])
    >>> m.is_finite, m.families[0].description
    (False, 'at phi = 0, every position at distance 1 from (0, 0)')
    >>> len(m.isolated_modes)
    2

    The Gough-Stewart platforms (3-D points, six legs) whose legs meet in pairs at three
    platform points (the octahedral 3-3, the 6-3) or at three base points (the 3-6): a pose
    is ``(position, rotation)`` (:class:`SpatialMode`), the polynomial of degree at most 16
    (Nanua, Waldron & Murthy 1990) is in one coordinate of a platform point, every
    coordinate of a mode a polynomial in its root.  The 3-3 below has eight real modes, four
    pairs mirrored in the base plane:

    >>> A, B = [(0, 0, 0), (6, 0, 0), (2, 5, 0)], [(0, 0, 0), (3, 0, 0), (1, 2, 0)]
    >>> base, platform = [A[0], A[1], A[1], A[2], A[2], A[0]], [B[0], B[0], B[1], B[1], B[2], B[2]]
    >>> m = direct_kinematics(base, platform, [5, 5, 5, 5, 5, 5])
    >>> m.polynomial.degree(), len(m.modes)
    (16, 8)
    >>> sorted(round(float(mode.position[2]), 6) for mode in m.modes)
    [-3.987801, -3.769533, -2.692076, -2.571284, 2.571284, 2.692076, 3.769533, 3.987801]

    The general 6-6 (any six legs: at most 40 isolated complex modes, Ronga & Vust 1995,
    Husty 1996) is solved otherwise: a homotopy in Study's parameters proposes the modes and
    Krawczyk's test proves each one in exact arithmetic, a box holding exactly one mode, a
    real one (:mod:`screwsym.systems._homotopy`).  No univariate polynomial is computed
    (``polynomial`` is None); each mode is a :class:`CertifiedMode`, its pose the box's
    centre in floating point (``closes`` therefore says False: use ``mode.contains`` for an
    exact pose), and ``complete`` is True only when 40 distinct complex modes are proven
    (then none is missing; otherwise ``.modes`` raises and ``certified`` says how many).
    Dietmaier's (1998) platform has all 40 real:

    >>> from sympy import Rational as Q
    >>> A = [(0, 0, 0), (Q('1.107915'), 0, 0), (Q('0.549094'), Q('0.756063'), 0),
    ...      (Q('0.735077'), Q('-0.223935'), Q('0.525991')),
    ...      (Q('0.514188'), Q('-0.526063'), Q('-0.368418')),
    ...      (Q('0.590473'), Q('0.094733'), Q('-0.205018'))]
    >>> B = [(0, 0, 0), (Q('0.542805'), 0, 0), (Q('0.956919'), Q('-0.528915'), 0),
    ...      (Q('0.665885'), Q('-0.353482'), Q('1.402538')),
    ...      (Q('0.478359'), Q('1.158742'), Q('0.107672')),
    ...      (Q('-0.137087'), Q('-0.235121'), Q('0.353913'))]
    >>> L = [1] + [Q(v) for v in ('0.645275', '1.086284', '1.503439', '1.281933', '0.771071')]
    >>> m = direct_kinematics(A, B, L)
    >>> m.polynomial is None, m.complete, m.certified, len(m.modes)
    (True, True, 40, 40)
    >>> [round(float(v), 6) for v in m.modes[0].position]
    [0.442199, -0.713494, -0.543494]
    >>> m.modes[0].contains(m.modes[1].pose)
    False

    Bad input is refused:

    >>> direct_kinematics([(0, 0), (1, 0)], [(0, 0), (1, 0), (0, 1)], [1, 1, 1])
    Traceback (most recent call last):
    ...
    ValueError: base_points: expected 3 2-D points, got 2
    """
    budget = check_count(budget, "budget")
    dim = _dimension(base_points, "base_points")
    legs = 3 if dim == 2 else 6
    a = _points(base_points, "base_points", dim, legs)
    b = _points(platform_points, "platform_points", dim, legs)
    items = check_sequence(lengths, "lengths", "leg lengths", legs)
    l2 = tuple(_squared_length(v, f"lengths[{i}]") for i, v in enumerate(items))
    with case_budget(budget, "direct_kinematics"):
        if dim == 2:
            return _planar(a, b, l2)
        return _spatial(a, b, l2)


def _spatial(a: tuple, b: tuple, l2: tuple) -> AssemblyModes:
    """The Gough-Stewart platforms whose legs pair at three platform points (or, inverted, at
    three base points): :mod:`screwsym.systems._gough_stewart`."""
    for pts in (a, b):
        if len(set(pts)) == 3:
            p, q, r = (Matrix(v) for v in dict.fromkeys(pts))
            if (q - p).cross(r - p).is_zero_matrix:
                raise ValueError(
                    "direct_kinematics: the three distinct points of the base or the platform "
                    "are collinear (a degenerate Gough-Stewart platform)"
                )
    pairs = paired_legs(a, b)
    if pairs is not None:
        poly, modes = paired_modes(a, b, l2, pairs)
    else:
        pairs = paired_legs(b, a)
        if pairs is None:
            return _general(a, b, l2)
        poly, inverse = paired_modes(b, a, l2, pairs)
        # the inverted mechanism's pose (p', R') is the inverse of ours: R = R'^T, p = -R p'
        modes = []
        for m in inverse:
            rot = m.rotation.T
            modes.append(SpatialMode(ImmutableMatrix(-(rot * m.position)), rot, m.root, m.multiplicity))
    modes.sort(key=lambda m: m.root.evalf(30))
    return AssemblyModes(poly, tuple(modes), (), a, b, l2)


def _general(a: tuple, b: tuple, l2: tuple) -> AssemblyModes:
    """The general 6-6 (any six legs): a homotopy in Study's parameters, every mode
    certified by Krawczyk's test in exact arithmetic (:mod:`screwsym.systems._homotopy`)."""
    from ._homotopy import general_modes

    modes, certified, complete = general_modes(a, b, l2)
    return AssemblyModes(None, tuple(modes), (), a, b, l2, complete, certified)


def _cos_sin(phi: Expr) -> tuple[Expr, Expr]:
    """``cos(phi)``, ``sin(phi)`` exact, rational in ``t`` where ``phi = 2*atan(t)``."""
    if phi == pi:
        return Integer(-1), Integer(0)
    k, rest = phi.as_coeff_Mul()
    if k in (2, -2) and isinstance(rest, atan):
        t = rest.args[0] if k == 2 else -rest.args[0]
        return (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)
    return cos(phi), sin(phi)


def leg_lengths(base_points: Sequence, platform_points: Sequence, pose: Sequence) -> tuple:
    r"""The inverse kinematics of a parallel mechanism: the leg lengths at ``pose``, exact.

    Planar (2-D points): ``pose = (x, y, phi)``, the leg ``i`` from ``base_points[i]`` to
    ``(x, y) + R(phi) platform_points[i]``.

    >>> leg_lengths([(0, 0), (4, 0), (0, 3)], [(0, 0), (4, 0), (0, 3)], (1, 0, 0))
    (1, 1, 1)
    >>> from sympy import pi
    >>> leg_lengths([(0, 0), (4, 0), (0, 3)], [(0, 0), (1, 0), (0, 1)], (0, 0, pi/2))
    (0, sqrt(17), sqrt(10))
    """
    dim = _dimension(base_points, "base_points")
    a = _points(base_points, "base_points", dim, None)
    b = _points(platform_points, "platform_points", dim, len(a))
    if dim == 3:
        items = check_sequence(pose, "pose", "parts (position, rotation)", 2)
        p = _exact(check_vector(items[0], "pose[0]"))
        R = _exact(check_matrix(items[1], "pose[1]", (3, 3)))
        return tuple(sqrt(_squared(p + R * Matrix(bi) - Matrix(ai))) for ai, bi in zip(a, b, strict=True))
    x, y, phi = (check_scalar(v, f"pose[{i}]") for i, v in enumerate(check_sequence(pose, "pose", "values (x, y, phi)", 3)))
    x, y = (Rational(v) if isinstance(v, Float) else v for v in (x, y))
    c, s = _cos_sin(phi)
    out = []
    for (ax, ay), (bx, by) in zip(a, b, strict=True):
        dx = x + c * bx - s * by - ax
        dy = y + s * bx + c * by - ay
        out.append(sqrt(dx**2 + dy**2))
    return tuple(out)


def _exact(M: Any) -> ImmutableMatrix:
    """``M`` with its floats taken as their exact binary values."""
    return ImmutableMatrix(M.applyfunc(lambda v: Rational(v) if isinstance(v, Float) else v))


def _squared(v: Any) -> Expr:
    return sum((e**2 for e in v), Integer(0))


def _is_zero_number(e: Expr) -> bool:
    """Whether the real number ``e`` is zero, decided: exactly as a rational, as an element
    of ``Q(r)`` for one ``CRootOf`` ``r`` (reduced modulo its polynomial); else non-zero when
    30 significant digits of it are (SymPy's ``evalf(strict=True)``, which refuses digits it
    cannot vouch for), zero by its minimal polynomial; ``ValueError`` where none decides."""
    if e.is_Rational:
        return e == 0
    roots = e.atoms(CRootOf)
    if len(roots) == 1:
        (r,) = roots
        z = Symbol("z")
        num, den = together(e.xreplace({r: z})).as_numer_denom()
        try:
            pn, pd = Poly(num, z, domain="QQ"), Poly(den, z, domain="QQ")
        except (PolynomialError, CoercionFailed):  # other irrationals than r: below
            pass
        else:
            g = Poly(r.poly.as_expr().subs(r.poly.gen, z), z, domain="QQ")
            if not pd.rem(g).is_zero:
                return pn.rem(g).is_zero
    try:
        if e.evalf(30, strict=True, maxn=120) != 0:
            return False
    except PrecisionExhausted:  # zero, or too close to it for 30 digits: decide exactly
        pass
    charge(10_000)
    try:
        return minimal_polynomial(e, Symbol("z")).as_expr() == Symbol("z")
    except NotAlgebraic:
        raise ValueError(
            f"closes: cannot decide whether {e} is zero (not algebraic, and zero to 30 digits)"
        ) from None
