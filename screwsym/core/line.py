r"""Line vectors and the geometry of lines: Sections 1.2, 1.3 and 1.4.1.

A line is given by its Plücker coordinates ``(S; S0)`` in the book's ray
order: a direction ``S != 0`` and the moment ``S0 = r x S`` of the line about
the origin, for any point ``r`` of it (1.8, 1.9), so that ``S . S0 = 0``
(1.10).  The same pair is a *line vector* (Section 1.4.1): a force on its
line of action, or an angular velocity about its axis.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, TypeAlias

from sympy import Abs, Eq, Expr, Float, ImmutableMatrix, Rational, atan2, nan, sign, sqrt
from sympy.core.evalf import prec_to_dps

from .basic import ScrewsymBasic
from .checks import check_choice, check_flag, check_no_strings, check_vector
from .conditions import CONDS, piecewise, vanishes
from .decide import float_tau, is_zero_scaled, is_zero_vector, is_zero_vector_scaled, norm
from .formulas import dot, foot_point, reciprocal_form
from .screw import (
    ScalarLike,
    Screw,
    ScrewLike,
    VectorLike,
    check_screw,
    finite_pitch,
    reciprocal_product_unchecked,
    require_axis,
)
from .tidy import finish

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = [
    "LineVector",
    "CommonNormal",
    "contains",
    "mutual_moment",
    "is_coplanar",
    "common_normal",
]

#: a LineVector, a screw whose parts make a line, or a 6-vector (S; S0)
LineLike: TypeAlias = ScrewLike


def check_line_parts(S: ImmutableMatrix, S0: ImmutableMatrix, label: str | tuple[str, str],
                     incident: bool = False) -> None:
    """Raise ``ValueError`` unless ``(S; S0)`` may be a line vector.

    A line vector has ``S != 0`` and ``S . S0 = 0`` (1.10).  Only a provable
    violation raises: undecidable symbolic cases are accepted, and floats are
    judged by the float policy of :func:`screwsym.core.decide.is_zero_scaled`.
    ``label`` starts the message: the argument's name, or the names of the
    two parts (a tuple) when the parts were given.  ``incident=True`` says the
    construction makes ``S . S0 = 0`` an identity (``S0 = r x S``): only ``S != 0``
    is checked (the proof of the identity was a third of the book's verification time).
    """
    first, both = (label[0], ", ".join(label)) if isinstance(label, tuple) else (label, label)
    if is_zero_vector(S) is True:
        raise ValueError(f"{first}: a line vector needs a non-zero direction S, got {list(S)}")
    if incident:
        return
    ss0 = dot(S, S0)
    if is_zero_scaled(ss0, norm(S) * norm(S0)) is False:
        raise ValueError(f"{both}: a line vector needs S.S0 = 0 (1.10), got S.S0 = {ss0}")


class LineVector(Screw, line_of=Screw):
    r"""A line vector ``(S; S0)`` with ``S != 0`` and ``S . S0 = 0`` (1.10, 1.28).

    Explanation
    ===========

    Constructing one whose ``S . S0`` is provably non-zero, or whose ``S`` is
    provably zero, raises ``ValueError``; symbolic cases that cannot be
    decided are accepted, and floats follow the float policy.  ``(S; S0)``
    and ``(lambda S; lambda S0)``, ``lambda != 0``, are the same line
    (homogeneity).  Its pitch is 0 by this invariant.  It builds with the
    constructors every kind has: :meth:`~screwsym.core.screw.Screw.from_axis`
    (point, direction), :meth:`~screwsym.core.screw.Screw.through` (two points),
    :meth:`~screwsym.core.screw.Screw.from_matrix`.

    Examples
    ========

    >>> from screwsym import LineVector
    >>> L = LineVector.through([1, 0, 0], [1, 1, 0])      # (1.1), (1.9)
    >>> L
    LineVector([0, 1, 0], [0, 0, 1])
    >>> L.foot.T, L.contains([1, 5, 0])
    (Matrix([[1, 0, 0]]), True)
    >>> LineVector([1, 0, 0], [1, 0, 0])
    Traceback (most recent call last):
    ...
    ValueError: S, S0: a line vector needs S.S0 = 0 (1.10), got S.S0 = 1
    """

    __slots__ = ()
    _combination = Screw  # a sum of lines is a screw; so is 0 * line
    _pitch_is_zero = True

    @classmethod
    def _check_parts(cls, S: ImmutableMatrix, S0: ImmutableMatrix,
                     label: str | tuple[str, str], incident: bool = False) -> None:
        check_line_parts(S, S0, label, incident)

    def contains(self, point: VectorLike) -> bool | None:
        """Whether ``point`` lies on the line (1.8); see :func:`contains`."""
        return _contains(self, check_vector(point, "point"))

    def mutual_moment(self, other: LineLike, *, tidy: bool = True) -> Expr:
        """The mutual moment with ``other`` (1.23); see :func:`mutual_moment`."""
        return reciprocal_product_unchecked(
            self, check_screw(other, "other", LineVector), check_flag(tidy, "tidy")
        )

    def is_coplanar(self, other: LineLike) -> bool | None:
        """Whether the two lines are coplanar (1.27); see :func:`is_coplanar`."""
        return _is_coplanar(self, check_screw(other, "other", LineVector))

    def common_normal(self, other: LineLike, *, tidy: bool = True,
                      conds: str = "none") -> CommonNormal:
        """The common normal to ``other`` (Fig. 1.3); see :func:`common_normal`."""
        return _common_normal(
            self, check_screw(other, "other", LineVector), ("self", "other"),
            check_flag(tidy, "tidy"), check_choice(conds, "conds", CONDS),
        )


def _contains(s: Screw, r: ImmutableMatrix, name: str | None = None) -> bool | None:
    require_axis(s, "axis", name)  # a couple's axis is at infinity
    h = finite_pitch(s)
    residual = r.cross(s.S) - (s.S0 - h * s.S)
    return is_zero_vector_scaled(residual, norm(r) * norm(s.S) + norm(s.S0))


def contains(s: ScrewLike, point: VectorLike) -> bool | None:
    r"""Whether ``point`` lies on the line, or on the axis of the screw.

    Tests the line equation ``r x S = S0`` (1.8), or for a screw the axis
    equation ``r x S = S0 - h S`` (1.36).  True, False, or None when the
    symbols do not decide; floats follow the float policy, relative to
    ``|r| |S| + |S0|``.

    >>> from screwsym import LineVector, contains
    >>> L = LineVector.through([0, 0, 0], [1, 1, 1])
    >>> contains(L, [2, 2, 2]), contains(L, [1, 0, 0])
    (True, False)
    """
    return _contains(check_screw(s, "s", Screw), check_vector(point, "point"), "s")


def mutual_moment(l1: LineLike, l2: LineLike, *, tidy: bool = True) -> Expr:
    r"""The mutual moment of two lines, ``M = S1 . S02 + S2 . S01`` (1.23).

    It is the reciprocal product (1.45) of the two line vectors; for unit
    directions it equals ``-a12 sin(alpha12)`` (1.25), with ``a12`` and
    ``alpha12`` from :func:`common_normal`.  In lowest terms (``tidy=False``:
    as built); it holds for every value of the symbols.

    >>> from screwsym import LineVector, mutual_moment
    >>> x_axis = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    >>> mutual_moment(x_axis, LineVector.from_axis([0, 0, 2], [0, 1, 0]))
    -2
    """
    return reciprocal_product_unchecked(
        check_screw(l1, "l1", LineVector), check_screw(l2, "l2", LineVector),
        check_flag(tidy, "tidy"),
    )


def _coplanar_scale(l1: Screw, l2: Screw) -> Expr:
    return norm(l1.S) * norm(l2.S0) + norm(l2.S) * norm(l1.S0)


def _is_coplanar(l1: Screw, l2: Screw) -> bool | None:
    return is_zero_scaled(reciprocal_product_unchecked(l1, l2), _coplanar_scale(l1, l2))


def is_coplanar(l1: LineLike, l2: LineLike) -> bool | None:
    r"""Whether two lines are coplanar (intersect or are parallel): ``M = 0`` (1.27).

    Floats follow the float policy, relative to ``|S1||S02| + |S2||S01|``.

    >>> from screwsym import LineVector, is_coplanar
    >>> x_axis = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    >>> is_coplanar(x_axis, LineVector.from_axis([5, 0, 0], [0, 1, 1]))
    True
    >>> is_coplanar(x_axis, LineVector.from_axis([0, 0, 1], [0, 1, 0]))
    False
    """
    return _is_coplanar(check_screw(l1, "l1", LineVector), check_screw(l2, "l2", LineVector))


class CommonNormal(ScrewsymBasic):
    r"""The common normal of two lines (Fig. 1.3), as returned by :func:`common_normal`.

    A SymPy object whose ``args`` are ``(a12, normal, alpha12, foot1, foot2)``:
    ``subs``, ``free_symbols``, LaTeX and :func:`screwsym.lambdify` work on it.

    >>> from sympy import latex
    >>> from screwsym import LineVector, common_normal
    >>> cn = common_normal(LineVector([1, 0, 0], [0, 0, 0]), LineVector([0, 1, 0], [-2, 0, 0]))
    >>> cn
    CommonNormal(a12=2, normal=[0, 0, 1], alpha12=pi/2, foot1=[0, 0, 0], foot2=[0, 0, 2])
    >>> print(latex(cn))
    a_{12} = 2,\quad \mathbf{a}_{12} = \left[\begin{matrix}0 & 0 & 1\end{matrix}\right]^{T},\quad \alpha_{12} = \frac{\pi}{2},\quad \mathbf{r}_{1} = \left[\begin{matrix}0 & 0 & 0\end{matrix}\right]^{T},\quad \mathbf{r}_{2} = \left[\begin{matrix}0 & 0 & 2\end{matrix}\right]^{T}
    """

    __slots__ = ()
    _fields = ("a12", "normal", "alpha12", "foot1", "foot2")

    def __new__(cls, a12: ScalarLike, normal: VectorLike, alpha12: ScalarLike,
                foot1: VectorLike, foot2: VectorLike) -> Self:
        # ImmutableMatrix sympifies its entries without strict=True: refuse text first
        check_no_strings((a12, normal, alpha12, foot1, foot2), "CommonNormal")
        return ScrewsymBasic.__new__(
            cls, a12, ImmutableMatrix(normal), alpha12, ImmutableMatrix(foot1), ImmutableMatrix(foot2)
        )

    @property
    def a12(self) -> Expr:
        """The distance ``a12 >= 0`` between the lines along the normal."""
        return self.args[0]

    @property
    def normal(self) -> ImmutableMatrix:
        """The unit vector of the normal, pointing from line 1 to line 2."""
        return self.args[1]

    @property
    def alpha12(self) -> Expr:
        """The twist angle from ``S1`` to ``S2``, right-handed about ``normal``."""
        return self.args[2]

    @property
    def foot1(self) -> ImmutableMatrix:
        """The foot of the normal on line 1."""
        return self.args[3]

    @property
    def foot2(self) -> ImmutableMatrix:
        """The foot of the normal on line 2."""
        return self.args[4]

    def _lambdify_outputs(self) -> tuple[Any, ...]:
        """The five parts, for :func:`screwsym.lambdify` (a tuple of results)."""
        return tuple(self.args)

    def _sympystr(self, printer: Any) -> str:
        def show(v: Any) -> str:
            if isinstance(v, ImmutableMatrix):
                return "[" + ", ".join(printer._print(e) for e in v) + "]"
            return printer._print(v)

        parts = ", ".join(f"{k}={show(v)}" for k, v in zip(self._fields, self.args, strict=True))
        return f"CommonNormal({parts})"

    def _latex(self, printer: Any) -> str:
        def column(v: ImmutableMatrix) -> str:
            return printer._print(v.T) + "^{T}"

        parts = [
            rf"a_{{12}} = {printer._print(self.a12)}",
            rf"\mathbf{{a}}_{{12}} = {column(self.normal)}",
            rf"\alpha_{{12}} = {printer._print(self.alpha12)}",
            rf"\mathbf{{r}}_{{1}} = {column(self.foot1)}",
            rf"\mathbf{{r}}_{{2}} = {column(self.foot2)}",
        ]
        return r",\quad ".join(parts)


def _exact(v: ImmutableMatrix) -> ImmutableMatrix:
    """The column with every float replaced by the exact binary rational it stands for."""
    return v.xreplace({f: Rational(f) for f in v.atoms(Float)})


def _common_normal(l1: Screw, l2: Screw, names: tuple[str, str], tidy: bool = True,
                   conds: str = "none") -> CommonNormal:
    tau = float_tau(*l1.matrix, *l2.matrix)
    if tau is None or l1.free_symbols or l2.free_symbols:
        return finish(_common_normal_parts(l1.S, l1.S0, l2.S, l2.S0, None, names, conds), tidy)
    # Float lines: decide by the float policy, compute exactly from the numbers given, round
    # once at the end (so nearly parallel lines get their true distance, not cancellation).
    # The moments are made exactly perpendicular to the directions first: a float line's
    # S.S0 is zero only up to rounding, and that residue divided by a small |S1 x S2| would
    # move the distance of nearly parallel lines far more than the rounding moved the lines.
    prec = min(f._prec for m in (l1.matrix, l2.matrix) for f in m.atoms(Float))
    S1, S2 = _exact(l1.S), _exact(l2.S)
    S01, S02 = _exact(l1.S0), _exact(l2.S0)
    S01 = S01 - dot(S1, S01) / dot(S1, S1) * S1
    S02 = S02 - dot(S2, S02) / dot(S2, S2) * S2
    cn = _common_normal_parts(S1, S01, S2, S02, tau, names)
    # the floats' digits and one guard digit (16 for double precision, as before)
    return cn.func(*(a.evalf(n=max(15, prec_to_dps(prec) + 1)) for a in cn.args))


def _common_normal_parts(S1: ImmutableMatrix, S01: ImmutableMatrix, S2: ImmutableMatrix,
                         S02: ImmutableMatrix, tau: Expr | None, names: tuple[str, str],
                         conds: str = "none") -> CommonNormal:
    nn1, nn2 = dot(S1, S1), dot(S2, S2)
    p1, p2 = foot_point(S1, S01), foot_point(S2, S02)  # the feet (1.16)
    d = p2 - p1
    n = S1.cross(S2)
    nn = dot(n, n)
    cos_part = dot(S1, S2)
    # parallel: |S1 x S2| against |S1||S2| (compared squared, so no root is taken)
    parallel = is_zero_scaled(nn, nn1 * nn2, None if tau is None else tau**2)
    if parallel is True:
        # both feet are perpendicular to the common direction, so d is the normal
        if is_zero_scaled(norm(d), norm(p1) + norm(p2), tau) is True:
            raise ValueError(
                f"{names[0]}, {names[1]}: coincident lines have no common normal, "
                f"got {list(S1)}; {list(S01)} and {list(S2)}; {list(S02)}"
            )
        a12 = norm(d)
        return CommonNormal(a12, d / a12, atan2(0, cos_part), p1, p2)
    n_len = sqrt(nn)
    m = -reciprocal_form([*S1, *S01], [*S2, *S02])  # (foot2 - foot1) . (S1 x S2), by (1.22), (1.23)
    scale = sqrt(nn1) * norm(S02) + sqrt(nn2) * norm(S01)
    met = is_zero_scaled(m, scale, tau)
    intersecting = met is True
    if intersecting:
        m = 0
    orientation = 1 if intersecting else sign(m)
    t1 = dot(d.cross(S2), n) / nn
    t2 = dot(d.cross(S1), n) / nn
    feet = (p1 + t1 * S1, p2 + t2 * S2)
    generic = CommonNormal(
        Abs(m) / n_len,
        orientation * n / n_len,
        atan2(orientation * n_len, cos_part),
        *feet,
    )
    if conds != "piecewise" or tau is not None:
        return generic
    # The cases the symbols leave open, each right where its condition holds (Fig. 1.3).
    branches = []
    if parallel is None:
        a12 = norm(d)
        none = ImmutableMatrix([nan, nan, nan])
        branches += [
            ((nan, none, nan, none, none), vanishes(n) & vanishes(d)),  # coincident
            ((a12, d / a12, atan2(0, cos_part), p1, p2), vanishes(n)),  # parallel
        ]
    if met is None:
        branches.append(((0, n / n_len, atan2(n_len, cos_part), *feet), Eq(m, 0)))
    return CommonNormal(*(
        piecewise([(parts[i], c) for parts, c in branches], generic.args[i]) for i in range(5)
    ))


def common_normal(l1: LineLike, l2: LineLike, *, tidy: bool = True,
                  conds: str = "none") -> CommonNormal:
    r"""The common normal of two lines: distance, unit normal, twist angle and feet.

    Explanation
    ===========

    The convention is the one under which (1.24) and (1.25) hold: the unit
    normal ``a12_hat`` points from line 1 to line 2, ``a12 >= 0`` is the
    distance, ``alpha12`` is measured right-handedly about ``a12_hat`` from
    ``S1`` to ``S2``, so that

        S1 x S2 = |S1| |S2| sin(alpha12) a12_hat,   S1 . S2 = |S1| |S2| cos(alpha12),
        foot2 - foot1 = a12 a12_hat,   M = -|S1| |S2| a12 sin(alpha12).

    Intersecting lines (``a12 = 0``) take ``a12_hat`` along ``S1 x S2``;
    parallel lines have ``alpha12`` equal to 0 or pi, the normal through the
    foot point of line 1, and ``foot1`` the point of line 1 nearest the
    origin.  Coincident lines have no common normal and raise ``ValueError``.

    With symbols the result is the generic one, in lowest terms
    (``tidy=False``: as built): it holds where the lines are skew
    (``S1 x S2 != 0`` and ``M != 0``) unless the symbols decide otherwise;
    ``a12`` contains ``Abs`` and the normal ``sign`` of ``-M``.  With
    ``conds="piecewise"`` each part is a ``Piecewise`` over the cases the
    symbols leave open, right for every value: coincident (``nan``),
    parallel, intersecting (``M = 0``), skew.
    Floats follow the float policy for the parallel and intersecting cases,
    and the result is computed exactly from the numbers given and rounded
    once, so nearly parallel skew lines get their true distance.

    Examples
    ========

    >>> from screwsym import LineVector, common_normal
    >>> L1 = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    >>> L2 = LineVector.from_axis([0, 0, 2], [0, 1, 0])
    >>> cn = common_normal(L1, L2)
    >>> cn.a12, cn.normal.T, cn.alpha12, cn.foot1.T, cn.foot2.T
    (2, Matrix([[0, 0, 1]]), pi/2, Matrix([[0, 0, 0]]), Matrix([[0, 0, 2]]))
    >>> from sympy import symbols
    >>> z = symbols("z", real=True)
    >>> Lz = LineVector.from_axis([0, 0, z], [0, 1, 0])
    >>> common_normal(L1, Lz).alpha12                      # generic: holds where z != 0
    atan2(sign(z), 0)
    >>> cn = common_normal(L1, Lz, conds="piecewise")
    >>> cn.alpha12
    Piecewise((pi/2, Eq(z, 0)), (atan2(sign(z), 0), True))
    >>> cn.subs(z, 0).normal.T, cn.subs(z, 0).alpha12
    (Matrix([[0, 0, 1]]), pi/2)

    See Also
    ========

    mutual_moment
    """
    l1 = check_screw(l1, "l1", LineVector)
    l2 = check_screw(l2, "l2", LineVector)
    return _common_normal(
        l1, l2, ("l1", "l2"), check_flag(tidy, "tidy"), check_choice(conds, "conds", CONDS)
    )
