r"""The neighbours' conventions: :func:`convert` to their layouts and :func:`convert_from` back.

Explanation
===========

screwsym writes every screw in the book's ray order, direction part first:
a twist ``(omega; v_O)``, a wrench ``(f; C_O)``.  The robotics libraries
order their 6-vectors by what the parts *are* (angular or linear) rather
than by the line geometry, and not all alike:

================  ==========================  ============================  =====================
convention        motion (twist, screw axis)  force (wrench)                transform (4x4)
================  ==========================  ============================  =====================
modern_robotics   ``(omega; v)``              ``(m; f)``, moment first      pose ``[[R, p], [0, 1]]``
pytransform3d     ``(omega; v)``              ``(m; f)``, moment first      pose ``[[R, p], [0, 1]]``
spatialmath       ``(v; omega)``, linear 1st  ``(f; m)``, force first       pose ``[[R, p], [0, 1]]``
pinocchio         ``(v; omega)``, linear 1st  ``(f; m)``, force first       pose ``[[R, p], [0, 1]]``
featherstone      ``(omega; v_O)``            ``(n_O; f)``, moment first    coordinate transform
                                                                            ``[[R^T, -R^T p], [0, 1]]``
================  ==========================  ============================  =====================

``v`` (``v_O``) is the velocity of the body point at the origin and ``m``
(``n_O``) the moment about the origin in every row, as in screwsym; only the
order differs.  A screwsym twist and the neighbours' motion vectors agree up
to the order of the halves; a screwsym wrench ``(f; C_O)`` is *force first*,
which modern_robotics, pytransform3d and Featherstone write moment first.  A
general :class:`~screwsym.core.screw.Screw` or a
:class:`~screwsym.core.line.LineVector` is converted as a motion (a screw axis).
Featherstone's 4x4 matrix (``pluho`` in his spatial_v2) is the coordinate
transform from the base frame A to the moved frame B, the inverse of the
pose ``T`` of B in A that the others use.

Sources (read for this table): modern_robotics ``core.py`` (``VecTose3``: a
twist ``V = (omega, v)``; ``InverseDynamics``: ``tau_i = F_i . A_i``, so a
wrench ``F = (m, f)``); pytransform3d ``transformations/_screws.py``
(``check_screw_axis``: ``(omega_1, omega_2, omega_3, v_1, v_2, v_3)``) and
``_transform.py`` (``adjoint_from_transform``: wrenches move by
``Ad^T``, so ``(m, f)``); spatialmath-python ``spatialmath/twist.py``
(``Twist3``: "translational components first", ``v = S[:3]``,
``w = S[3:6]``) and ``spatialmath/spatialvector.py`` ("Compared to
Featherstone's papers these spatial vectors have the translational
components first"); pinocchio ``include/pinocchio/spatial/motion-tpl.hpp``
and ``force-tpl.hpp`` (``LINEAR = 0, ANGULAR = 3``); Featherstone's
spatial_v2 ``spatial/crm.m`` (motion ``(omega; v)``), ``crf.m``
(``crf = -crm'``: force ``(n; f)``) and ``pluho.m`` (``T = [E, -E r; 0 1]``).

Spatial inertias
----------------

A :class:`~screwsym.core.inertia.SpatialInertia` is the 6x6 map from a motion
to a force (the momentum): in screwsym's ray order ``M`` maps ``(omega; v_O)``
to ``(f; C_O)`` (:mod:`screwsym.core.inertia`).  In a library's layout it is
``P_f M P_m^-1``, with ``P_m`` and ``P_f`` the permutations of the table above:

================  ==========================================  ===================================
convention        6x6 spatial inertia                         the library's own
================  ==========================================  ===================================
modern_robotics   ``[[I_O, m [c]x], [-m [c]x, m 1]]``         ``G_i`` of ``Glist`` (``(8.32)``)
featherstone      ``[[I_O, m [c]x], [-m [c]x, m 1]]``         ``mcI(m, c, I_c)`` (spatial_v2)
pinocchio         ``[[m 1, -m [c]x], [m [c]x, I_O]]``         ``pin.Inertia(m, c, I_c).matrix()``
spatialmath       as pinocchio                                (linear first)
pytransform3d     as modern_robotics
================  ==========================================  ===================================

with ``I_O = I_c - m [c]x^2`` the rotational inertia about the frame's origin:
the symmetric form (``Delta M`` for the angular-first layouts).  pinocchio's
``pin.Inertia(mass, lever, inertia)`` takes screwsym's three parameters as
they are (``lever`` the centre of mass, ``inertia`` about it), as does
Featherstone's ``mcI(m, c, I)`` (spatial_v2 ``spatial/mcI.m``); Lynch & Park's
``G_i = diag(I_c, m 1)`` is the case of a frame at the centre of mass.

Every conversion is a permutation (or, for Featherstone's transform, the
exact inverse), so round trips are exact: equal structurally, except that
Featherstone's transform of a symbolic motion comes back as ``R R^T p``,
equal to ``p`` by ``R R^T = I`` (``Transform.equals`` decides it).
"""

from __future__ import annotations

from typing import NamedTuple, TypeVar, cast, overload

from sympy import ImmutableMatrix

from ..core.checks import check_choice, check_matrix, check_six
from ..core.decide import is_zero
from ..core.formulas import SWAP, cross_matrix
from ..core.inertia import SpatialInertia
from ..core.line import LineVector
from ..core.screw import MatrixLike, Screw, SixVectorLike
from ..core.twist import Twist
from ..core.wrench import Wrench
from .transform import Transform

__all__ = ["convert", "convert_from", "CONVENTIONS", "Convention"]


class Convention(NamedTuple):
    """How one library lays out motion vectors, force vectors and transforms."""

    #: True when a motion vector is written angular part first, ``(omega; v)``
    motion_angular_first: bool
    #: True when a force vector is written moment first, ``(m; f)``
    force_moment_first: bool
    #: True when the 4x4 matrix is the coordinate transform, the inverse of the pose
    transform_inverse: bool


CONVENTIONS: dict[str, Convention] = {
    "modern_robotics": Convention(True, True, False),
    "pytransform3d": Convention(True, True, False),
    "spatialmath": Convention(False, False, False),
    "pinocchio": Convention(False, False, False),
    "featherstone": Convention(True, True, True),
}

_KINDS = (Screw, LineVector, Twist, Wrench, Transform, SpatialInertia)


def _swap(first: ImmutableMatrix, second: ImmutableMatrix, swap: bool) -> ImmutableMatrix:
    """``(first; second)``, its halves swapped by the core's ``SWAP`` (1.45) when ``swap``."""
    m = ImmutableMatrix.vstack(first, second)
    return m[list(SWAP), :] if swap else m


#: a screw of any kind: convert_from gives back the kind it is asked for
_S = TypeVar("_S", bound=Screw)


def _permutation(swap: bool) -> ImmutableMatrix:
    """The 6x6 permutation matrix of the half swap (1.45), or the identity."""
    return ImmutableMatrix.eye(6)[list(SWAP), :] if swap else ImmutableMatrix.eye(6)


def _inertia_layout(c: Convention) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    """``(P_f, P_m)``: a ray-order wrench and twist in the layout of ``c``."""
    return _permutation(c.force_moment_first), _permutation(not c.motion_angular_first)


def convert(obj: Screw | Transform | SpatialInertia, to: str) -> ImmutableMatrix:
    r"""``obj`` in the layout of another library: a 6x1 matrix, or 4x4 for a transform.

    Explanation
    ===========

    ``to`` is one of ``"modern_robotics"``, ``"pytransform3d"``,
    ``"spatialmath"``, ``"pinocchio"``, ``"featherstone"``; the layouts are
    in the module docstring's table.  A twist, line vector or screw is
    converted as a motion vector, a wrench as a force vector, a
    :class:`~screwsym.motion.transform.Transform` to the library's 4x4 matrix.
    Exact: entries are only reordered (and, for Featherstone's transform,
    inverted exactly).  :func:`convert_from` is the inverse.

    Examples
    ========

    >>> from screwsym import Twist, Wrench, Transform, convert
    >>> t = Twist([0, 0, 1], [1, 2, 3])                  # (omega; v_O)
    >>> convert(t, to="modern_robotics").T, convert(t, to="pinocchio").T
    (Matrix([[0, 0, 1, 1, 2, 3]]), Matrix([[1, 2, 3, 0, 0, 1]]))
    >>> w = Wrench([0, 0, 5], [7, 0, 0])                 # (f; C_O)
    >>> convert(w, to="modern_robotics").T, convert(w, to="spatialmath").T
    (Matrix([[7, 0, 0, 0, 0, 5]]), Matrix([[0, 0, 5, 7, 0, 0]]))
    >>> convert(Transform.translation([1, 0, 0]), to="featherstone")[:3, 3].T
    Matrix([[-1, 0, 0]])
    >>> from screwsym import SpatialInertia
    >>> convert(SpatialInertia.point_mass(1, [0, 0, 0]), to="pinocchio") == ImmutableMatrix.diag(1, 1, 1, 0, 0, 0)
    True

    Parameters
    ==========

    obj : Twist, Wrench, LineVector, Screw, Transform or SpatialInertia
        A spatial inertia comes as the library's 6x6 matrix (module docstring).
    to : str

    See Also
    ========

    convert_from
    """
    to = check_choice(to, "to", tuple(CONVENTIONS))
    c = CONVENTIONS[to]
    if isinstance(obj, Transform):
        return (obj.inverse() if c.transform_inverse else obj).matrix
    if isinstance(obj, SpatialInertia):
        Pf, Pm = _inertia_layout(c)
        return ImmutableMatrix(Pf * obj.matrix * Pm.T)
    if isinstance(obj, Wrench):
        return _swap(obj.f, obj.C_O, c.force_moment_first)
    if isinstance(obj, Screw):
        return _swap(obj.S, obj.S0, not c.motion_angular_first)
    raise TypeError(
        "obj: expected a Twist, Wrench, LineVector, Screw or Transform (or a SpatialInertia), "
        f"got {type(obj).__name__}"
    )


@overload
def convert_from(value: SixVectorLike, source: str, kind: type[_S]) -> _S: ...
@overload
def convert_from(value: MatrixLike, source: str, kind: type[Transform]) -> Transform: ...
@overload
def convert_from(value: MatrixLike, source: str, kind: type[SpatialInertia]) -> SpatialInertia: ...


def convert_from(value: SixVectorLike | MatrixLike, source: str,
                 kind: type[Screw] | type[Transform] | type[SpatialInertia],
                 ) -> Screw | Transform | SpatialInertia:
    r"""The screwsym object of ``kind`` from ``value`` in the layout of ``source``.

    The inverse of :func:`convert`: ``convert_from(convert(x, to=c), c, type(x)) == x``
    for every ``x`` and every convention ``c``.  ``value`` is a 6-vector (list,
    tuple, SymPy matrix or NumPy array) for a screw, twist or wrench, a 4x4
    matrix for a transform, a 6x6 matrix for a spatial inertia (refused when it
    provably is not of the form of one: the blocks of the module docstring).

    >>> from screwsym import Twist, Wrench, convert_from
    >>> convert_from([1, 2, 3, 0, 0, 1], "spatialmath", Twist)       # (v; omega)
    Twist([0, 0, 1], [1, 2, 3])
    >>> convert_from([7, 0, 0, 0, 0, 5], "featherstone", Wrench)     # (n_O; f)
    Wrench([0, 0, 5], [7, 0, 0])
    >>> convert_from([1, 2, 3, 0, 0, 1], "spatialmath", dict)
    Traceback (most recent call last):
    ...
    TypeError: kind: expected one of Screw, LineVector, Twist, Wrench, Transform, SpatialInertia, got dict
    """
    source = check_choice(source, "source", tuple(CONVENTIONS))
    if not (isinstance(kind, type) and kind in _KINDS):
        raise TypeError(
            f"kind: expected one of {', '.join(k.__name__ for k in _KINDS)}, "
            f"got {getattr(kind, '__name__', type(kind).__name__)}"
        )
    c = CONVENTIONS[source]
    if kind is Transform:
        T = Transform.from_matrix(value, name="value")
        return T.inverse() if c.transform_inverse else T
    if kind is SpatialInertia:
        return _inertia_from_matrix(value, c)
    first, second = check_six(value, "value")
    swap = c.force_moment_first if kind is Wrench else not c.motion_angular_first
    return cast("type[Screw]", kind).from_matrix(_swap(first, second, swap), name="value")


def _inertia_from_matrix(value: MatrixLike, c: Convention) -> SpatialInertia:
    """The body of a 6x6 spatial inertia in the layout ``c``, its block form checked."""
    X = check_matrix(value, "value", (6, 6))
    Pf, Pm = _inertia_layout(c)
    M = ImmutableMatrix(Pf.T * X * Pm)  # ray order: [[-[h]x, m 1], [I_O, [h]x]]
    m = M[0, 3]
    h = ImmutableMatrix([M[5, 4], M[3, 5], M[4, 3]])
    expected = ImmutableMatrix(
        (-cross_matrix(h)).row_join(ImmutableMatrix.eye(3) * m).col_join(
            M[3:, :3].row_join(cross_matrix(h))
        )
    )
    for i in range(6):
        for j in range(6):
            if is_zero(M[i, j] - expected[i, j]) is False:
                raise ValueError(
                    "value: expected a spatial inertia (the blocks m 1 and [m c]x of the "
                    f"module docstring), got the entry {M[i, j]} where {expected[i, j]} belongs "
                    "(in screwsym's ray order)"
                )
    I_O = M[3:, :3]
    return SpatialInertia.from_parameters(
        [m, *h, I_O[0, 0], I_O[0, 1], I_O[1, 1], I_O[0, 2], I_O[1, 2], I_O[2, 2]]
    )
