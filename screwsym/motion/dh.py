r"""Denavit–Hartenberg tables to product-of-exponentials chains, exact.

Explanation
===========

A Denavit–Hartenberg table has one row per joint, ``(a, alpha, d, theta)``
in this column order, and each row is one homogeneous matrix; the forward
kinematics is their product, ``T(q) = A_1(q_1) A_2(q_2) ... A_n(q_n)``.  The
two conventions in use order the four elementary motions of a row
differently and attach the frames differently:

==============  ===================================================  =====================================
convention      row ``i`` is the matrix                              joint ``i`` turns about
==============  ===================================================  =====================================
``"standard"``  ``Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)``          ``z_{i-1}``, the frame before the row
``"modified"``  ``Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)``  ``z_i``, the frame after the row
==============  ===================================================  =====================================

``"standard"`` is Denavit & Hartenberg's (1955; Spong, Corke); ``"modified"``
is Craig's (1986/2005, (3.6)), where row ``i`` holds ``a_{i-1}, alpha_{i-1}``
of the link *before* joint ``i``.

In both, the joint variable ``q_i`` is *added* to the row's entry: a revolute
joint (``"R"``) turns ``theta_i = theta + q_i``, a prismatic joint (``"P"``)
slides ``d_i = d + q_i``; the table's entry is the joint's offset, its value
at ``q = 0``.  The home configuration of the chain is ``q = 0``.

Because ``Rz`` and ``Tz`` commute with each other, the joint's motion can be
pulled out of its row: ``A_i(q_i) = Z(q_i) A_i(0)`` (standard) or
``A_i(q_i) = A_i(0) Z(q_i)`` (modified), with ``Z`` the rotation about (or
translation along) the local z-axis.  Moving every ``Z`` to the front
(``F Z F^-1 = exp6(Ad(F) $_z)``) gives Brockett's product of exponentials

    T(q) = base exp6($_1, q_1) ... exp6($_n, q_n) M,

with the joint twist ``$_i = Ad(F) $_z`` (``$_z = (0, 0, 1; 0, 0, 0)`` for
``"R"``, ``(0, 0, 0; 0, 0, 1)`` for ``"P"``) for the home frame
``F = base A_1(0) ... A_{i-1}(0)`` (standard) or ``base A_1(0) ... A_i(0)``
(modified), and the home pose ``M = base A_1(0) ... A_n(0) tool``: the same
matrix function of ``q``, exactly (tests/motion/test_dh.py checks it
symbolically against the product of the rows).

References
==========

J. Denavit and R. S. Hartenberg, "A kinematic notation for lower-pair
mechanisms based on matrices", *J. Appl. Mech.* 22 (1955) 215–221.
J. J. Craig, *Introduction to Robotics: Mechanics and Control*, 3rd ed.,
Pearson 2005, Section 3.4 (the modified form, (3.6)).  Lynch & Park,
*Modern Robotics*, Cambridge 2017, Appendix C (both forms, and the product
of exponentials from them).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from sympy import Expr, Float, ImmutableMatrix, cos, sin

from ..core.checks import check_choice, check_instance, check_scalar, check_sequence
from ..core.screw import ScalarLike
from ..core.tidy import tidy
from ..core.twist import Twist
from .angles import RecognisedAngle, angle_step, recognise_float, warn_recognised
from .transform import Transform

__all__ = ["dh_twists_and_home", "dh_row_transform", "recognise_dh_angles"]

#: the conventions and their aliases
_CONVENTIONS = ("standard", "modified")


def _rot_z(t: Expr) -> ImmutableMatrix:
    c, s = cos(t), sin(t)
    return ImmutableMatrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _rot_x(t: Expr) -> ImmutableMatrix:
    c, s = cos(t), sin(t)
    return ImmutableMatrix([[1, 0, 0], [0, c, -s], [0, s, c]])


def dh_row_transform(a: ScalarLike, alpha: ScalarLike, d: ScalarLike, theta: ScalarLike,
                     convention: str = "standard") -> Transform:
    r"""The homogeneous transform of one Denavit–Hartenberg row ``(a, alpha, d, theta)``.

    ``"standard"``: ``Rz(theta) Tz(d) Tx(a) Rx(alpha)``;
    ``"modified"`` (Craig): ``Rx(alpha) Tx(a) Rz(theta) Tz(d)``.  See the
    module docstring for the table of both conventions.

    >>> from sympy import pi
    >>> from screwsym.motion.dh import dh_row_transform
    >>> dh_row_transform(1, pi/2, 2, 0).matrix
    Matrix([
    [1, 0,  0, 1],
    [0, 0, -1, 0],
    [0, 1,  0, 2],
    [0, 0,  0, 1]])
    >>> dh_row_transform(1, pi/2, 2, 0, "modified").matrix
    Matrix([
    [1, 0,  0,  1],
    [0, 0, -1, -2],
    [0, 1,  0,  0],
    [0, 0,  0,  1]])
    """
    a, alpha, d, theta = (check_scalar(v, n) for v, n in
                          ((a, "a"), (alpha, "alpha"), (d, "d"), (theta, "theta")))
    convention = check_choice(convention, "convention", _CONVENTIONS)
    Rz, Rx = _rot_z(theta), _rot_x(alpha)
    if convention == "standard":
        # Rz(theta) Tz(d) Tx(a) Rx(alpha): the origin is Rz(theta) (a, 0, d)
        R = Rz * Rx
        p = Rz * ImmutableMatrix([a, 0, d])
    else:
        # Rx(alpha) Tx(a) Rz(theta) Tz(d): the origin is (a, 0, 0) + Rx(alpha) (0, 0, d)
        R = Rx * Rz
        p = ImmutableMatrix([a, 0, 0]) + Rx * ImmutableMatrix([0, 0, d])
    return Transform._new(tidy(R), tidy(p))


def _check_joints(joints: Any, n: int) -> tuple[str, ...]:
    if joints is None:
        return ("R",) * n
    if isinstance(joints, str):
        kinds = tuple(joints)
    else:
        kinds = tuple(check_sequence(joints, "joints", "joint kinds 'R' or 'P'"))
    if len(kinds) != n:
        raise ValueError(f"joints: expected {n} joint kinds (one per row), got {len(kinds)}")
    out = []
    for i, k in enumerate(kinds):
        if not isinstance(k, str) or k.upper() not in ("R", "P"):
            raise ValueError(
                f"joints[{i}]: expected 'R' (revolute: theta is the variable) or "
                f"'P' (prismatic: d is the variable), got {k!r}")
        out.append(k.upper())
    return tuple(out)


def recognise_dh_angles(rows: Sequence[Sequence[ScalarLike]], angles: str = "pi/12"
                        ) -> tuple[list[tuple[Any, ...]], tuple[RecognisedAngle, ...]]:
    r"""The rows with their float angles (``alpha``, ``theta``) that are multiples of pi/N made exact.

    The rule of :func:`screwsym.motion.angles.recognise_float`: a float
    (Python, NumPy or SymPy ``Float``) within 4 units in its last place of
    ``k pi/N`` is that multiple (``numpy.pi/2`` is pi/2; ``1.5708`` is not: a
    float's printed precision is its own).  Exact and symbolic entries, and the
    lengths ``a`` and ``d``, are kept.  Returns the rows and what was recognised.

    >>> import numpy as np
    >>> from screwsym.motion.dh import recognise_dh_angles
    >>> rows, found = recognise_dh_angles([(0.5, np.pi / 2, 0.1, -np.pi / 6)])
    >>> rows
    [(0.5, pi/2, 0.1, -pi/6)]
    >>> found[0]
    RecognisedAngle(text='1.5707963267948966', element='rows[0][1] (alpha)', value=pi/2)
    """
    n = angle_step(angles)
    rows = check_sequence(rows, "rows", "DH rows (a, alpha, d, theta)")
    out: list[tuple[Any, ...]] = []
    found: list[RecognisedAngle] = []
    for i, row in enumerate(rows):
        row = list(check_sequence(row, f"rows[{i}]", "entries (a, alpha, d, theta)", 4))
        for j, label in ((1, "alpha"), (3, "theta")):
            value = row[j]
            is_float = isinstance(value, float | Float) or type(value).__module__ == "numpy"
            if n is None or not is_float or isinstance(value, bool):
                continue
            try:
                x = float(value)
            except (TypeError, ValueError):
                continue
            exact = recognise_float(x, n)
            if exact is not None:
                found.append(RecognisedAngle(repr(x), f"rows[{i}][{j}] ({label})", exact))
                row[j] = exact
        out.append(tuple(row))
    return out, tuple(found)


def dh_twists_and_home(rows: Sequence[Sequence[ScalarLike]], convention: str = "standard",
                       joints: str | Sequence[str] | None = None, *,
                       base: Transform | None = None,
                       tool: Transform | None = None,
                       angles: str = "exact") -> tuple[list[Twist], Transform]:
    r"""The joint twists and home pose of a Denavit–Hartenberg table: ``Chain.from_dh``'s work.

    Explanation
    ===========

    ``rows`` are ``(a, alpha, d, theta)``, one per joint, base to tip (each
    entry exact or symbolic); ``joints`` says per row which entry is the joint
    variable: ``"R"`` (revolute, ``theta``) or ``"P"`` (prismatic, ``d``), as a
    string such as ``"RRPRRR"`` or a sequence of such letters (default: all
    revolute).  The variable is added to the entry (the entry is the joint's
    offset).  The chain's forward kinematics is, exactly,
    ``base A_1(q_1) ... A_n(q_n) tool`` for the rows' matrices ``A_i`` of
    :func:`dh_row_transform`; ``base`` and ``tool`` are constant transforms
    (default the identity), for a robot's base frame or flange.  The module
    docstring tables the two conventions and gives the derivation.

    Use it as :meth:`Chain.from_dh <screwsym.motion.chain.Chain.from_dh>`, which
    makes the :class:`~screwsym.motion.chain.Chain` of these parts.

    Examples
    ========

    A planar RP arm in the standard convention (the prismatic joint slides
    along the first link):

    >>> from sympy import pi, symbols
    >>> from screwsym import Chain
    >>> arm = Chain.from_dh([(0, pi/2, 0, 0), (0, 0, 1, 0)], joints="RP")
    >>> arm.twists
    (Twist([0, 0, 1], [0, 0, 0]), Twist([0, 0, 0], [0, -1, 0]))
    >>> q1, q2 = symbols("q1 q2", real=True)
    >>> arm.forward([q1, q2]).p.T
    Matrix([[(q2 + 1)*sin(q1), -(q2 + 1)*cos(q1), 0]])

    Parameters
    ==========

    rows : sequence of 4-sequences ``(a, alpha, d, theta)``
    convention : ``"standard"`` (Denavit & Hartenberg 1955) or ``"modified"`` (Craig)
    joints : str or sequence of ``"R"``/``"P"``, optional
    base, tool : Transform, optional
    angles : ``"exact"`` (default) or ``"pi/N"``
        With ``"pi/N"``, float angles that are multiples of pi/N are read as
        those multiples (:func:`recognise_dh_angles`), with a
        :class:`~screwsym.motion.angles.RecognisedAngleWarning` listing them.

    References
    ==========

    Denavit & Hartenberg 1955; Craig 2005, (3.6); Lynch & Park 2017, Appendix C.
    """
    rows, found = recognise_dh_angles(rows, angles)
    warn_recognised(found, angle_step(angles) or 12)
    if len(rows) == 0:
        raise ValueError("rows: expected at least one DH row (a, alpha, d, theta), got none")
    convention = check_choice(convention, "convention", _CONVENTIONS)
    kinds = _check_joints(joints, len(rows))
    T = Transform.identity() if base is None else check_instance(base, "base", Transform)
    tool = Transform.identity() if tool is None else check_instance(tool, "tool", Transform)
    twists = []
    for i, (row, kind) in enumerate(zip(rows, kinds, strict=True)):
        a, alpha, d, theta = (check_scalar(v, f"rows[{i}][{j}]") for j, v in enumerate(row))
        A = dh_row_transform(a, alpha, d, theta, convention)
        if convention == "modified":
            T = tidy(T @ A)
        z = T.R[:, 2]
        twists.append(Twist.rotation(z, point=T.p) if kind == "R" else Twist.translation(z))
        if convention == "standard":
            T = tidy(T @ A)
    return twists, tidy(T @ tool)
