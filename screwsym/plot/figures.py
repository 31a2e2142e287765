r"""Pictures of lines, screws, twists and wrenches in one matplotlib 3D axes.

Every function draws into a 3D ``Axes`` (a new one when ``ax`` is None) and
returns it, so a picture is built by passing the same ``ax`` again::

    ax = plot_line(L1)
    plot_line(L2, ax=ax, color="C1")
    plot_common_normal(L1, L2, ax=ax)

What is drawn (the glyphs):

* a **line vector** ``(S; S0)``: its line (thin), an arrow ``S`` on it starting
  at the foot point ``P = S x S0 / S.S`` (1.16), the foot marked, and the
  perpendicular from the origin O to it dashed (1.17, 1.18);
* a **screw**: its axis (1.36) with the arrow ``S`` from the foot point and a
  short helix around the axis, the *pitch glyph*: right-handed for ``h > 0``,
  left-handed for ``h < 0``, its advance per radian ``h rho / (rho + |h|)``
  for a helix of radius ``rho`` (the true lead for small pitches, bounded for
  large ones); a line vector (``h = 0``) gets no helix;
* a **couple** ``(0; C)``: a free vector, drawn at ``at`` (the origin by
  default) as a double-headed arrow with a curled arrow turning right-handedly
  about it;
* a **twist** ``(omega; v_O)``: the axis, the arrow ``omega``, a curled arrow
  giving the sense of rotation and the pitch helix; a pure translation
  ``(0; v)`` is an arrow ``v`` with a double head; in green;
* a **wrench** ``(f; C_O)``: the axis, the force ``f`` on it and the parallel
  couple ``h f`` as a double-headed arrow, with the pitch helix; in red;
* **two lines and their common normal** (Fig. 1.3): both lines, the segment
  between the feet of the normal, the twist angle as an arc about the normal
  from ``S1`` to ``S2``, and a label with ``a12`` and ``alpha12``.

Numbers come from the objects.  A symbolic object is drawn after substituting
``subs``; one with free symbols left raises ``ValueError`` naming them.

Every artist screwsym draws carries a ``gid`` ``"screwsym.<kind>"`` (kinds:
``line``, ``arrow``, ``head``, ``foot``, ``origin``, ``perpendicular``,
``helix``, ``curl``, ``curl-head``, ``normal``, ``angle``, ``label``,
``frame``), so that a picture can be inspected or restyled afterwards with
:func:`find_artists`.

matplotlib is an optional dependency (``pip install -e ".[plot]"`` from a clone); it is
imported only when a function here is called.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypeAlias

import numpy as np
from sympy import Abs, Basic, ImmutableMatrix
from sympy.matrices import MatrixBase

from ..core.checks import check_flag, check_no_strings, check_vector
from ..core.decide import is_zero_scaled
from ..core.formulas import foot_point, pitch_ratio
from ..core.line import LineLike, LineVector, common_normal, contains
from ..core.screw import Screw, ScrewLike, VectorLike, check_screw
from ..core.twist import Twist
from ..core.wrench import Wrench

if TYPE_CHECKING:
    from mpl_toolkits.mplot3d import Axes3D

__all__ = [
    "plot",
    "plot_line",
    "plot_screw",
    "plot_couple",
    "plot_twist",
    "plot_wrench",
    "plot_common_normal",
    "plot_frame",
    "find_artists",
    "helix_advance",
]

Subs: TypeAlias = Mapping[Any, Any] | None

TWIST_COLOR = "tab:green"
WRENCH_COLOR = "tab:red"
SCREW_COLOR = "tab:blue"


# --------------------------------------------------------------------------
# numbers from objects
# --------------------------------------------------------------------------


def _check_subs(subs: Any) -> dict:
    if subs is None:
        return {}
    check_no_strings(subs, "subs")
    if not isinstance(subs, Mapping):
        raise TypeError(
            f"subs: expected a dict mapping symbols to numbers, got {type(subs).__name__}"
        )
    return dict(subs)


def _numeric(value: Basic, subs: dict, name: str) -> Basic:
    """``value`` with ``subs`` applied; ``ValueError`` naming any free symbols left."""
    if subs:
        value = value.subs(subs)
    free = value.free_symbols
    if free:
        names = ", ".join(sorted(str(s) for s in free))
        raise ValueError(
            f"{name}: cannot draw a symbolic {type(value).__name__}: "
            f"substitute numbers for {names} (subs={{...}})"
        )
    return value


def _floats(m: ImmutableMatrix, name: str) -> np.ndarray:
    out = []
    for e in m:
        z = e.evalf()
        re, im = z.as_real_imag()
        # the float policy (screwsym.core.decide): an imaginary part within rounding of |z|
        if is_zero_scaled(im, Abs(z)) is False:
            raise ValueError(f"{name}: expected real components, got {e}")
        out.append(float(re))
    return np.array(out, dtype=float)


def _screw_floats(obj: Any, subs: dict, name: str,
                  cls: type[Screw] = Screw) -> tuple[Screw, np.ndarray, np.ndarray]:
    """Return the screw (after ``subs``) and its two parts as float arrays."""
    s = check_screw(obj, name, cls)
    s = _numeric(s, subs, name)
    return s, _floats(s.S, name), _floats(s.S0, name)


def _point(p: Any, subs: dict, name: str) -> np.ndarray:
    v = check_vector(p, name)
    return _floats(_numeric(v, subs, name), name)


# --------------------------------------------------------------------------
# geometry helpers
# --------------------------------------------------------------------------


def _norm(v: np.ndarray) -> float:
    return float(np.linalg.norm(v))


def _basis(n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors ``e1, e2`` with ``(e1, e2, n)`` right-handed and orthonormal."""
    n = n / _norm(n)
    helper = np.eye(3)[int(np.argmin(np.abs(n)))]
    e1 = np.cross(n, helper)
    e1 /= _norm(e1)
    return e1, np.cross(n, e1)


def helix_advance(h: float, radius: float) -> float:
    r"""Advance per radian of the pitch glyph of a screw of pitch ``h``.

    Explanation
    ===========

    A body point at distance ``radius`` from the axis of a screw motion of
    pitch ``h`` moves on a helix advancing ``h`` per radian: right-handed when
    ``h > 0``.  To keep the glyph compact for large pitches it advances
    ``h radius / (radius + |h|)``: the same sign as ``h``, growing with
    ``|h|``, close to ``h`` when ``|h|`` is small and never more than
    ``radius`` per radian.

    Examples
    ========

    >>> from screwsym.plot import helix_advance
    >>> helix_advance(0.0, 1.0), helix_advance(1.0, 1.0), helix_advance(-3.0, 1.0)
    (0.0, 0.5, -0.75)
    """
    return float(h) * radius / (radius + abs(float(h)))


def _mpl():
    try:
        import matplotlib.pyplot as plt
        from mpl_toolkits.mplot3d import Axes3D  # noqa: F401  (registers the 3d projection)
    except ImportError as exc:  # pragma: no cover - exercised only without matplotlib
        raise ImportError(
            "screwsym.plot needs matplotlib: pip install -e \".[plot]\" (from a clone of screwsym)"
        ) from exc
    return plt


def _axes(ax: Axes3D | None) -> Axes3D:
    plt = _mpl()
    if ax is None:
        fig = plt.figure(figsize=(6, 5))
        return fig.add_subplot(projection="3d")
    if getattr(ax, "name", None) != "3d":
        raise TypeError(
            f"ax: expected a 3D Axes (fig.add_subplot(projection='3d')), "
            f"got {type(ax).__name__}"
        )
    return ax


def _gid(kind: str) -> str:
    return f"screwsym.{kind}"


def find_artists(ax: Axes3D, kind: str) -> list[Any]:
    """The artists of one kind that screwsym drew into ``ax``.

    ``kind`` is one of ``line``, ``arrow``, ``head``, ``foot``, ``origin``,
    ``perpendicular``, ``helix``, ``curl``, ``curl-head``, ``normal``, ``angle``, ``label``,
    ``frame``.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym import LineVector
    >>> from screwsym.plot import plot_line, find_artists
    >>> ax = plot_line(LineVector.through([1, 2, 5], [1, 2, 6]))
    >>> [float(c[0]) for c in find_artists(ax, "foot")[0].get_data_3d()]   # P (1.16)
    [1.0, 2.0, 0.0]
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    return [a for a in ax.get_children() if a.get_gid() == _gid(kind)]


def _polyline(ax, pts: np.ndarray, kind: str, **kw):
    pts = np.asarray(pts, dtype=float) + 0.0  # no negative zeros in the drawn data
    (line,) = ax.plot(pts[:, 0], pts[:, 1], pts[:, 2], **kw)
    line.set_gid(_gid(kind))
    return line


def _cone(ax, tip: np.ndarray, direction: np.ndarray, length: float, color: str,
          kind: str = "head"):
    """A filled cone (arrowhead) with its tip at ``tip`` pointing along ``direction``."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    u = direction / _norm(direction)
    e1, e2 = _basis(u)
    base = tip - length * u
    radius = 0.35 * length
    ring = [base + radius * (math.cos(t) * e1 + math.sin(t) * e2)
            for t in np.linspace(0, 2 * math.pi, 13)]
    faces = [[tip, ring[i], ring[i + 1]] for i in range(12)]
    cone = Poly3DCollection(faces, facecolor=color, edgecolor=color, linewidths=0.3)
    cone.set_gid(_gid(kind))
    ax.add_collection3d(cone)
    return cone


def _arrow(ax, start: np.ndarray, vec: np.ndarray, color: str, *, head: float,
           double: bool = False, lw: float = 2.0, kind: str = "arrow"):
    """Shaft from ``start`` to ``start + vec`` with one (or two) conical heads."""
    size = _norm(vec)
    head = min(head, 0.4 * size)
    end = start + vec
    _polyline(ax, np.array([start, end]), kind, color=color, lw=lw)
    _cone(ax, end, vec, head, color)
    if double:
        _cone(ax, end - 0.8 * head * vec / size, vec, head, color)


def _curl(ax, center: np.ndarray, n: np.ndarray, radius: float, color: str, head: float):
    """A curled arrow turning right-handedly about ``n`` (three quarters of a turn)."""
    e1, e2 = _basis(n)
    t = np.linspace(0.0, 1.5 * math.pi, 60)
    pts = center + radius * (np.outer(np.cos(t), e1) + np.outer(np.sin(t), e2))
    _polyline(ax, pts, "curl", color=color, lw=1.5)
    tangent = -math.sin(t[-1]) * e1 + math.cos(t[-1]) * e2
    _cone(ax, pts[-1] + 0.5 * head * tangent, tangent, head, color, kind="curl-head")


def _helix(ax, center: np.ndarray, n: np.ndarray, radius: float, h: float, color: str,
           turns: float = 1.5):
    """The pitch glyph: a helix about the axis through ``center`` along ``n``."""
    e1, e2 = _basis(n)
    u = n / _norm(n)
    b = helix_advance(h, radius)
    t = np.linspace(-math.pi * turns, math.pi * turns, int(80 * turns))
    pts = (center + radius * (np.outer(np.cos(t), e1) + np.outer(np.sin(t), e2))
           + np.outer(b * t, u))
    return _polyline(ax, pts, "helix", color=color, lw=1.2)


def _label(ax, at: np.ndarray, text: str, color: str = "black"):
    t = ax.text(at[0], at[1], at[2], text, color=color, fontsize=9)
    t.set_gid(_gid("label"))
    return t


def _fit(ax) -> None:
    """Equal scales on the three axes, with every screwsym artist in view."""
    pts = []
    for line in ax.lines:
        xs, ys, zs = (np.asarray(c, dtype=float) for c in line.get_data_3d())
        pts.append(np.column_stack([xs, ys, zs]))
    if not pts:
        return
    allp = np.vstack(pts)
    allp = allp[np.all(np.isfinite(allp), axis=1)]
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    center = (lo + hi) / 2
    half = max(float((hi - lo).max()) / 2, 1e-9) * 1.1
    ax.set_xlim(center[0] - half, center[0] + half)
    ax.set_ylim(center[1] - half, center[1] + half)
    ax.set_zlim(center[2] - half, center[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")


def _sizes(length: float | None, S: np.ndarray, anchor: np.ndarray) -> tuple[float, float]:
    """Drawn line length and glyph size (helix radius, arrowhead length)."""
    if length is None:
        length = max(2.0, 2.0 * _norm(S), 1.2 * _norm(anchor))
    if not (isinstance(length, (int, float)) and length > 0):
        raise ValueError(f"length: expected a positive number, got {length!r}")
    return float(length), 0.08 * float(length)


def _draw_axis_line(ax, at: np.ndarray, u: np.ndarray, S_len: float, length: float,
                    color: str) -> None:
    back = length / 2
    ahead = max(length / 2, 1.15 * S_len)
    pts = np.array([at - back * u, at + ahead * u])
    _polyline(ax, pts, "line", color=color, lw=0.9, alpha=0.6)


def _draw_foot(ax, P: np.ndarray, color: str, show_perpendicular: bool) -> None:
    _polyline(ax, P[None, :], "foot", color=color, marker="o", ms=5, ls="none")
    if show_perpendicular and _norm(P) > 0:
        _polyline(ax, np.array([np.zeros(3), P]), "perpendicular", color="gray", lw=0.8,
                  ls="--")
        _polyline(ax, np.zeros((1, 3)), "origin", color="black", marker="o", ms=3, ls="none")


def _anchor(at: Any, subs: dict, s: Screw, P: np.ndarray) -> np.ndarray:
    """The point on the axis where the arrow starts: the foot, or ``at`` if it is on it.

    ``at`` is on the axis unless :func:`screwsym.core.line.contains` (the float policy)
    says it is not.
    """
    if at is None:
        return P
    point = _numeric(check_vector(at, "at"), subs, "at")
    a = _floats(point, "at")
    if contains(s, point) is False:
        raise ValueError(f"at: the point {list(a)} is not on the axis of {s}")
    return a


# --------------------------------------------------------------------------
# public drawing functions
# --------------------------------------------------------------------------


def plot_line(line: LineLike, ax: Axes3D | None = None, *, subs: Subs = None,
              at: VectorLike | None = None,
              length: float | None = None, color: str = SCREW_COLOR, label: str | None = None,
              show_foot: bool = True) -> Axes3D:
    r"""Draw a line vector ``(S; S0)``: its line, the arrow ``S`` and the foot point (1.16).

    Explanation
    ===========

    The arrow ``S`` starts at the foot ``P = S x S0 / S.S`` of the
    perpendicular from the origin (1.16), or at ``at`` when given (a point of
    the line); the foot is marked and joined to O by a dashed segment of length
    ``|S0| / |S|`` (1.18).  The line is drawn ``length`` long.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym import LineVector
    >>> from screwsym.plot import plot_line, find_artists
    >>> ax = plot_line(LineVector.through([1, 0, 0], [1, 1, 0]), label="$1")
    >>> xs, ys, zs = find_artists(ax, "arrow")[0].get_data_3d()
    >>> [float(x) for x in xs], [float(y) for y in ys]        # from P = (1, 0, 0) along S
    ([1.0, 1.0], [0.0, 1.0])
    >>> import matplotlib.pyplot as plt; plt.close("all")

    Parameters
    ==========

    line : LineVector or 6-vector
        The line vector; a screw of pitch 0 is accepted.
    ax : 3D Axes, optional
        Where to draw; a new figure when None.
    subs : dict, optional
        Numbers for the symbols in ``line``.
    at : 3-vector, optional
        Where on the line the arrow starts (default: the foot point).
    length : float, optional
        Length of the drawn line.
    color, label : str, optional
        Colour of the glyph; text placed at the arrow tip.
    show_foot : bool
        Mark the foot point and the perpendicular from O.

    See Also
    ========

    plot_screw, plot_common_normal
    """
    subs = _check_subs(subs)
    check_flag(show_foot, "show_foot")
    ax = _axes(ax)
    s, S, S0 = _screw_floats(line, subs, "line", LineVector)
    P = foot_point(S, S0)
    u = S / _norm(S)
    a = _anchor(at, subs, s, P)
    length, glyph = _sizes(length, S, a)
    _draw_axis_line(ax, a, u, _norm(S), length, color)
    _arrow(ax, a, S, color, head=glyph)
    if show_foot:
        _draw_foot(ax, P, color, True)
    if label:
        _label(ax, a + S + 0.3 * glyph * u, label, color)
    _fit(ax)
    return ax


def _axis_glyph(ax, s: Screw, S: np.ndarray, S0: np.ndarray, subs: dict, at: Any,
                length: float | None, color: str, *, moment_arrow: bool,
                curl: bool) -> tuple[np.ndarray, np.ndarray, float]:
    """Axis, arrow ``S``, pitch helix and optional couple arrow / curl; returns anchor."""
    h = float(pitch_ratio(S, S0))
    P = foot_point(S, S0)
    u = S / _norm(S)
    a = _anchor(at, subs, s, P)
    length, glyph = _sizes(length, S, a)
    _draw_axis_line(ax, a, u, _norm(S), length, color)
    _arrow(ax, a, S, color, head=glyph)
    _draw_foot(ax, P, color, at is None)
    radius = glyph * 1.2
    if h != 0.0:
        _helix(ax, a - 0.25 * length * u, u, radius, h, color)
        if moment_arrow:
            C = h * S
            _arrow(ax, a - 0.45 * length * u, C * min(1.0, 0.35 * length / _norm(C)), color,
                   head=glyph, double=True, lw=1.5)
    if curl:
        _curl(ax, a + 0.6 * _norm(S) * u, u, radius * 1.3, color, 0.6 * glyph)
    return a, u, h


def plot_screw(screw: ScrewLike, ax: Axes3D | None = None, *, subs: Subs = None,
               at: VectorLike | None = None,
               length: float | None = None, color: str = SCREW_COLOR,
               label: str | None = None) -> Axes3D:
    r"""Draw a screw: its axis (1.36), the arrow ``S`` and the pitch helix.

    Explanation
    ===========

    The axis passes through the foot point (1.16) and the arrow ``S`` starts
    there.  The helix winds about the axis right-handedly for ``h > 0`` and
    left-handedly for ``h < 0``, advancing :func:`helix_advance` per radian; a
    screw of pitch 0 (a line vector) has none.  A couple (``S = 0``) is drawn by
    :func:`plot_couple`.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym import Screw
    >>> from screwsym.plot import plot_screw, find_artists
    >>> ax = plot_screw(Screw([1, 1, 0], [1, 0, 0]))        # Example 1.4, h = 1/2
    >>> len(find_artists(ax, "helix"))
    1
    >>> import matplotlib.pyplot as plt; plt.close("all")

    Parameters
    ==========

    screw : Screw or 6-vector
    ax : 3D Axes, optional
    subs : dict, optional
        Numbers for the symbols in ``screw``.
    at : 3-vector, optional
        The point of the axis where the arrow starts (default: the foot point).
    length : float, optional
        Length of the drawn axis.
    color, label : str, optional

    See Also
    ========

    plot_line, plot_couple, plot_twist, plot_wrench
    """
    subs = _check_subs(subs)
    ax = _axes(ax)
    s, S, S0 = _screw_floats(screw, subs, "screw")
    if not S.any():
        return plot_couple(s, ax, at=at, color=color, label=label)
    a, u, h = _axis_glyph(ax, s, S, S0, subs, at, length, color, moment_arrow=False,
                          curl=False)
    text = f"h = {_fmt(h)}" if label is None else label
    _label(ax, a + S + 0.1 * u, text, color)
    _fit(ax)
    return ax


def _fmt(x: float) -> str:
    return f"{x:.3g}"


def plot_couple(couple: ScrewLike, ax: Axes3D | None = None, *, subs: Subs = None,
                at: VectorLike | None = None,
                color: str = WRENCH_COLOR, label: str | None = None) -> Axes3D:
    r"""Draw a couple ``(0; C)`` as a free vector: a double-headed arrow and a curled arrow.

    Explanation
    ===========

    A couple has no line of action (its axis lies at infinity, Section
    1.4.2), so it is drawn at ``at`` (the origin by default).  The curled arrow
    turns right-handedly about ``C``.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym import Screw
    >>> from screwsym.plot import plot_couple, find_artists
    >>> ax = plot_couple(Screw.couple([0, 0, 2]), at=[1, 0, 0])
    >>> xs, ys, zs = find_artists(ax, "arrow")[0].get_data_3d()
    >>> [float(z) for z in zs]
    [0.0, 2.0]
    >>> import matplotlib.pyplot as plt; plt.close("all")

    Parameters
    ==========

    couple : Screw, Wrench or 6-vector with ``S = 0``
    ax : 3D Axes, optional
    subs : dict, optional
    at : 3-vector, optional
        Where to draw the free vector (default: the origin).
    color, label : str, optional
    """
    subs = _check_subs(subs)
    ax = _axes(ax)
    s, S, C = _screw_floats(couple, subs, "couple")
    if S.any() or not C.any():
        raise ValueError(f"couple: expected a couple (0; C) with C != 0, got {s}")
    a = np.zeros(3) if at is None else _point(at, subs, "at")
    glyph = 0.15 * _norm(C)
    _arrow(ax, a, C, color, head=glyph, double=True)
    _curl(ax, a + 0.5 * C, C, 0.25 * _norm(C), color, 0.6 * glyph)
    if label:
        _label(ax, a + C * 1.05, label, color)
    _fit(ax)
    return ax


def plot_twist(twist: ScrewLike, ax: Axes3D | None = None, *, subs: Subs = None,
               at: VectorLike | None = None,
               length: float | None = None, color: str = TWIST_COLOR,
               label: str | None = None) -> Axes3D:
    r"""Draw a twist ``(omega; v_O)``: axis, ``omega``, sense of rotation and pitch helix.

    Explanation
    ===========

    The axis is the twist's screw axis (1.36) and the arrow is ``omega``
    (1.51); a curled arrow turns right-handedly about ``omega``, the sense in
    which the body turns; the helix is the path of a body point near the axis
    (right-handed when the pitch (1.54) is positive).  A pure translation
    ``(0; v)`` (Section 1.6.2) is drawn at ``at`` (default the origin) as the
    arrow ``v`` with a double head.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym import Twist
    >>> from screwsym.plot import plot_twist, find_artists
    >>> ax = plot_twist(Twist.from_axis([1, 0, 0], [0, 0, 1], 0.2))
    >>> len(find_artists(ax, "curl")), len(find_artists(ax, "helix"))
    (1, 1)
    >>> import matplotlib.pyplot as plt; plt.close("all")

    Parameters
    ==========

    twist : Twist or 6-vector ``(omega; v_O)``
    ax : 3D Axes, optional
    subs : dict, optional
    at : 3-vector, optional
    length : float, optional
    color, label : str, optional
    """
    subs = _check_subs(subs)
    ax = _axes(ax)
    s, w, v = _screw_floats(twist, subs, "twist", Twist)
    if not w.any():
        if not v.any():
            raise ValueError("twist: the zero twist (0; 0) has nothing to draw")
        a = np.zeros(3) if at is None else _point(at, subs, "at")
        _arrow(ax, a, v, color, head=0.15 * _norm(v), double=True)
        _label(ax, a + 1.05 * v, "v" if label is None else label, color)
        _fit(ax)
        return ax
    a, u, h = _axis_glyph(ax, s, w, v, subs, at, length, color, moment_arrow=False,
                          curl=True)
    text = f"ω, h = {_fmt(h)}" if label is None else label
    _label(ax, a + w + 0.1 * u, text, color)
    _fit(ax)
    return ax


def plot_wrench(wrench: ScrewLike, ax: Axes3D | None = None, *, subs: Subs = None,
                at: VectorLike | None = None,
                length: float | None = None, color: str = WRENCH_COLOR,
                label: str | None = None) -> Axes3D:
    r"""Draw a wrench ``(f; C_O)``: the force on its axis, the parallel couple and the helix.

    Explanation
    ===========

    The axis is the wrench's screw axis (1.36), the force ``f`` sits on it
    (1.55) and the couple ``h f`` parallel to it (1.57) is drawn as a
    double-headed arrow on the same axis; the helix gives the sign of the pitch.
    A pure couple ``(0; C)`` is drawn by :func:`plot_couple`.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym import Wrench
    >>> from screwsym.plot import plot_wrench, find_artists
    >>> ax = plot_wrench(Wrench.force([0, 0, -1], point=[1, 0, 0]))
    >>> len(find_artists(ax, "helix"))          # a pure force: pitch 0, no helix
    0
    >>> import matplotlib.pyplot as plt; plt.close("all")

    Parameters
    ==========

    wrench : Wrench or 6-vector ``(f; C_O)``
    ax : 3D Axes, optional
    subs : dict, optional
    at : 3-vector, optional
    length : float, optional
    color, label : str, optional
    """
    subs = _check_subs(subs)
    ax = _axes(ax)
    s, f, C = _screw_floats(wrench, subs, "wrench", Wrench)
    if not f.any():
        return plot_couple(s, ax, at=at, color=color, label=label)
    a, u, h = _axis_glyph(ax, s, f, C, subs, at, length, color, moment_arrow=True,
                          curl=False)
    text = f"f, h = {_fmt(h)}" if label is None else label
    _label(ax, a + f + 0.1 * u, text, color)
    _fit(ax)
    return ax


def plot_common_normal(l1: LineLike, l2: LineLike, ax: Axes3D | None = None, *,
                       subs: Subs = None, length: float | None = None,
                       colors: tuple[str, str] = ("C0", "C1")) -> Axes3D:
    r"""Draw two lines, their common normal and the twist angle (Fig. 1.3).

    Explanation
    ===========

    The values come from :func:`screwsym.common_normal`: the segment joins the
    feet of the normal, ``foot2 - foot1 = a12 a12_hat``; the arrows ``S1`` and
    ``S2`` start at the feet; the twist angle ``alpha12`` is drawn at the foot on
    line 2 as an arc turning right-handedly about ``a12_hat`` from (a copy of)
    ``S1`` to ``S2``: the convention under which ``M = -a12 sin(alpha12)``
    (1.25) for unit directions.  A label in the top left corner of the axes
    gives ``a12`` and ``alpha12``.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym import LineVector
    >>> from screwsym.plot import plot_common_normal, find_artists
    >>> L1 = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    >>> L2 = LineVector.from_axis([0, 0, 2], [0, 1, 0])
    >>> ax = plot_common_normal(L1, L2)
    >>> print(find_artists(ax, "label")[-1].get_text())
    $a_{12}$ = 2, $\alpha_{12}$ = 1.571 rad (90°)
    >>> import matplotlib.pyplot as plt; plt.close("all")

    Parameters
    ==========

    l1, l2 : LineVector or 6-vector
    ax : 3D Axes, optional
    subs : dict, optional
        Numbers for the symbols in either line.
    length : float, optional
        Length of each drawn line.
    colors : pair of str
        Colours of line 1 and line 2.
    """
    subs = _check_subs(subs)
    ax = _axes(ax)
    s1, _, _ = _screw_floats(l1, subs, "l1", LineVector)
    s2, _, _ = _screw_floats(l2, subs, "l2", LineVector)
    cn = common_normal(s1, s2)
    f1 = _floats(cn.foot1, "foot1")
    f2 = _floats(cn.foot2, "foot2")
    n = _floats(cn.normal, "normal")
    a12 = float(cn.a12.evalf())
    alpha = float(cn.alpha12.evalf())
    S1 = _floats(s1.S, "l1")
    S2 = _floats(s2.S, "l2")
    if length is None:
        length = max(2.0, 2.0 * max(_norm(S1), _norm(S2)), 2.0 * a12)
    plot_line(s1, ax, at=list(f1), length=length, color=colors[0], label="$S_1$",
              show_foot=False)
    plot_line(s2, ax, at=list(f2), length=length, color=colors[1], label="$S_2$",
              show_foot=False)
    _polyline(ax, np.array([f1, f2]), "normal", color="black", lw=1.5, ls="--",
              marker="o", ms=4)
    # the twist angle: an arc at foot2 from S1 (copied there) to S2, about the normal
    u1 = S1 / _norm(S1)
    w = np.cross(n, u1)
    r = 0.3 * length
    _polyline(ax, np.array([f2, f2 + r * u1]), "angle", color=colors[0], lw=0.8, ls=":")
    t = np.linspace(0.0, alpha, 40)
    arc = f2 + r * 0.8 * (np.outer(np.cos(t), u1) + np.outer(np.sin(t), w))
    _polyline(ax, arc, "angle", color="black", lw=1.0)
    text = (f"$a_{{12}}$ = {_fmt(a12)}, $\\alpha_{{12}}$ = {alpha:.4g} rad "
            f"({math.degrees(alpha):.4g}°)")
    # in the corner of the axes, where it cannot cover the lines, the normal or the axis labels
    caption = ax.text2D(0.02, 0.98, text, transform=ax.transAxes, va="top", fontsize=9)
    caption.set_gid(_gid("label"))
    _fit(ax)
    return ax


def plot_frame(ax: Axes3D | None = None, *, length: float = 1.0,
               origin: VectorLike = (0, 0, 0)) -> Axes3D:
    """Draw the coordinate frame: gray arrows x, y, z from the origin O.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym.plot import plot_frame, find_artists
    >>> ax = plot_frame(length=2)
    >>> len(find_artists(ax, "frame"))
    3
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    ax = _axes(ax)
    o = _point(origin, {}, "origin")
    if not (isinstance(length, (int, float)) and length > 0):
        raise ValueError(f"length: expected a positive number, got {length!r}")
    for e, name in zip(np.eye(3), "xyz", strict=True):
        _arrow(ax, o, length * e, "gray", head=0.08 * length, lw=1.0, kind="frame")
        t = ax.text(*(o + 1.08 * length * e), name, color="gray")
        t.set_gid(_gid("label"))
    t = ax.text(*(o - 0.08 * length * np.ones(3)), "O", color="gray")
    t.set_gid(_gid("label"))
    _fit(ax)
    return ax


def plot(obj: Screw | Sequence[Any], ax: Axes3D | None = None, **kw: Any) -> Axes3D:
    r"""Draw any screwsym object with its own glyph; a list or tuple draws each item.

    Dispatch: :class:`~screwsym.core.twist.Twist` to :func:`plot_twist`,
    :class:`~screwsym.core.wrench.Wrench` to :func:`plot_wrench`,
    :class:`~screwsym.core.line.LineVector` to :func:`plot_line`, a couple to
    :func:`plot_couple`, any other :class:`~screwsym.core.screw.Screw` to
    :func:`plot_screw`.  Keyword arguments go to that function.

    Examples
    ========

    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from screwsym import LineVector, Screw
    >>> from screwsym.plot import plot, find_artists
    >>> from sympy import symbols
    >>> h = symbols("h", real=True)
    >>> x_axis = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    >>> ax = plot([x_axis, Screw.from_axis([0, 1, 0], [0, 0, 1], h)], subs={h: -0.5})
    >>> len(find_artists(ax, "helix"))
    1
    >>> plot(Screw.from_axis([0, 1, 0], [0, 0, 1], h))
    Traceback (most recent call last):
    ...
    ValueError: screw: cannot draw a symbolic Screw: substitute numbers for h (subs={...})
    >>> import matplotlib.pyplot as plt; plt.close("all")
    """
    if isinstance(obj, (list, tuple)) and not isinstance(obj, MatrixBase):
        ax = _axes(ax)
        for item in obj:
            plot(item, ax, **kw)
        return ax
    if isinstance(obj, Twist):
        return plot_twist(obj, ax, **kw)
    if isinstance(obj, Wrench):
        return plot_wrench(obj, ax, **kw)
    if isinstance(obj, LineVector):
        return plot_line(obj, ax, **kw)
    if isinstance(obj, Screw):
        return plot_screw(obj, ax, **kw)
    raise TypeError(
        f"obj: expected a Screw, LineVector, Twist, Wrench or a list of them, "
        f"got {type(obj).__name__}"
    )

