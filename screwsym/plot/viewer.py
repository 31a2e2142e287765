r"""Mechanisms in 3-D in the browser: :func:`view` draws a chain, a parallel mechanism or screws with plotly.

``view(obj, q)`` returns a :class:`View`, an immutable value holding a plotly
figure: the mechanism's links as segments (a parallel mechanism's base and
platform as flat solids), its joints as glyphs by kind, and any screws,
twists, wrenches and screw systems placed in the same scene.  ``path=`` adds
precomputed animation frames with a slider and a play button, so a view turns
and moves on a static page with no kernel behind it.  ``View.to_html(path)``
writes one self-contained HTML file (plotly.js bundled: no CDN, no network),
``View.to_png(path)`` a picture taken with a headless Chromium on the machine;
in Jupyter the view shows itself as the same self-contained HTML
(``_repr_mimebundle_``: JupyterLab, VS Code, nbconvert and the documentation site
run it alike).

**One plotly.js for a whole site.**  Each self-contained view carries plotly.js
(about 4.8 MB), so a page of several views weighs tens of MB.  A site that loads
plotly.js once itself (the documentation site copies plotly's own
``plotly.min.js`` into its ``_static`` folder, see ``notebooks/conf.py``) sets the
environment variable ``SCREWSYM_VIEW_PLOTLYJS=site`` for the kernels that run its
notebooks: a view's Jupyter output (``_repr_html_``, ``_repr_mimebundle_``) then
leaves plotly.js out and calls the page's global ``Plotly`` (and logs a console
error if the page has none).  Unset, or ``inline``, the output is self-contained
(the default); any other value is a ``ValueError``.  :meth:`View.to_html` and
:meth:`View.to_png` are always self-contained, whatever the variable says.

Why plotly: its 3-D traces (WebGL) need nothing but one JavaScript file that
the Python package ships, so the same figure works offline in JupyterLab, VS
Code, an exported HTML file and a static Sphinx site; sliders and animation
frames are part of the figure itself (no kernel, no server, no websocket, as
meshcat and pythreejs need: the failure of remote kernels, drake #12645,
meshcat #67); it is widely used and kept.  k3d and pythreejs need a live
widget kernel to render, meshcat a server.

What is drawn (the glyphs):

* **links**: grey segments between the joints' points (hover: the link's name);
  a parallel mechanism's base and platform are flat translucent polygons through
  its limbs' first and last joints, and so are a graph mechanism's base and a
  link of it named ``"platform"`` (through their joints); a parallelogram joint
  is its four bars;
* **joints**: a marker by kind (revolute ``circle``, prismatic ``square``,
  helical ``diamond``, cylindrical ``square-open``, universal ``diamond-open``,
  spherical ``circle-open``, parallelogram ``cross``) and a short stub along each
  axis, with a ring about it for the rotating kinds; a chain's prismatic joint
  also shows its stroke as a thick bar;
* **screws** (one legend entry per group, one colour per group; twists in greens
  and blues, wrenches in reds and oranges): the axis as a dotted line, an arrow
  along it whose length is the magnitude (``|S|``, or ``|S0|`` for a couple or a
  translation; within a group, over all frames, the longest is a third of the
  scene), a single head for a force or a rotation, and for a finite non-zero pitch
  ``h`` a helix about the axis, right-handed for ``h > 0``, its advance per radian
  :func:`~screwsym.plot.figures.helix_advance` (as in the matplotlib figures);
* **couples and translations** (free vectors, pitch infinite): a **dashed** arrow
  with a **double head**, no axis, drawn on the body they act on (``anchor=``; by
  default a chain's flange or the joint whose twist it is, a parallel mechanism's
  platform centre); a group that has both kinds has two legend entries
  (``forces`` / ``couples``, ``rotations`` / ``translations``);
* a **cylindroid** (``cylindroid=(s1, s2)``): the surface of the axes of the
  two-system's screws, coloured by their pitch.

Numbers: every SymPy step (substitution, exponentials, checks) is done once by
:func:`view`; each configuration is then lambdified expressions and NumPy (see
:mod:`screwsym.plot._scene`).  plotly is optional: ``pip install -e ".[view]"``.

**In a live kernel**, :func:`live` takes the same arguments and returns a :class:`Live`:
``Live.redraw(values)`` recomputes every trace from numbers (about 1.5 ms for the UR5 with its
joint twists, 3 ms for the Delta by its platform: ``benchmarks/bench_view.py``), and
``Live.widget()`` shows a plotly ``FigureWidget`` with one slider per joint (or per control,
e.g. a Delta's platform position with ``solve=`` its inverse kinematics,
:mod:`screwsym.plot.models`).  The widget needs ipywidgets and anywidget (plotly's
``FigureWidget``), which the ``view`` extra does not install: the ``live`` extra does
(``pip install -e ".[live]"``); without them ``widget()`` says so, and a path of
precomputed frames (``view(..., path=...)``) is the offline equivalent.

For example, the UR5 with its joint twists:

>>> from screwsym.motion.chain import ur5
>>> from screwsym.plot import view
>>> v = view(ur5(), [0, 0.5, -1, 0, 0.5, 0], twists=True)
>>> v.kinds["joint:revolute"], v.kinds["screws"]
(6, 6)
>>> v
<View: 7 traces, 0 frames>
>>> v.to_html("ur5.html")                                     # doctest: +SKIP
'ur5.html'
"""

from __future__ import annotations

import hashlib
import html
import importlib
import json
import math
import os
import pathlib
import shutil
import subprocess
import tempfile
from collections.abc import Mapping
from typing import Any

import numpy as np

from ..motion.chain import Chain
from ._scene import JOINT_KINDS, Scene, ScrewGroup, check_subs, check_variables, finite, scene_maker
from .figures import helix_advance

__all__ = ["Live", "View", "live", "view"]

_TWIST_COLOURS = ("#2ca02c", "#1f77b4", "#17becf", "#9467bd")
_WRENCH_COLOURS = ("#d62728", "#ff7f0e", "#8c564b", "#e377c2")
_SCREW_COLOURS = ("#7f7f7f", "#bcbd22")
_SYMBOLS = {"revolute": "circle", "prismatic": "square", "helical": "diamond",
            "cylindrical": "square-open", "universal": "diamond-open", "spherical": "circle-open",
            "parallelogram": "cross"}
#: a couple or a translation: |S| below this fraction of |S0| (for drawing only, not a verdict)
_FREE = 1e-12


def _plotly() -> Any:
    try:
        import plotly.graph_objects as go
    except ImportError as exc:  # pragma: no cover - the view extra is installed in the tests
        raise ImportError("screwsym.plot.view needs plotly: pip install -e \".[view]\" "
                          "(or pip install plotly)") from exc
    return go


# --------------------------------------------------------------------------
# glyph geometry (floats)
# --------------------------------------------------------------------------


def _basis(n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors ``e1, e2`` with ``(e1, e2, n)`` right-handed and orthonormal."""
    helper = np.eye(3)[int(np.argmin(np.abs(n)))]
    e1 = np.cross(n, helper)
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(n, e1)


def _ring(c: np.ndarray, u: np.ndarray, radius: float, turns: float = 1.0,
          advance: float = 0.0, n: int = 24) -> np.ndarray:
    e1, e2 = _basis(u)
    t = np.linspace(-math.pi * turns, math.pi * turns, max(n, int(n * turns)))
    return (c + radius * (np.cos(t)[:, None] * e1 + np.sin(t)[:, None] * e2)
            + advance * t[:, None] * u)


class _Lines:
    """Polylines joined into one trace's x, y, z with ``None`` between them."""

    def __init__(self) -> None:
        self.x: list[Any] = []
        self.y: list[Any] = []
        self.z: list[Any] = []
        self.text: list[Any] = []
        self.count = 0

    def add(self, pts: np.ndarray, text: str = "") -> None:
        for p in pts:
            self.x.append(float(p[0]))
            self.y.append(float(p[1]))
            self.z.append(float(p[2]))
            self.text.append(text)
        self.x.append(None)
        self.y.append(None)
        self.z.append(None)
        self.text.append(None)
        self.count += 1

    def data(self) -> dict:
        return {"x": self.x, "y": self.y, "z": self.z, "hovertext": self.text}


class _Heads:
    def __init__(self) -> None:
        self.cols: list[list[float]] = [[] for _ in range(6)]

    def add(self, tip: np.ndarray, u: np.ndarray, length: float) -> None:
        for k, v in enumerate((*tip, *(u * length))):
            self.cols[k].append(float(v))

    def data(self) -> dict:
        return dict(zip(("x", "y", "z", "u", "v", "w"), self.cols, strict=True))


def _magnitude(s6: np.ndarray) -> tuple[bool, float]:
    """``(free, magnitude)``: a couple or translation (``S`` ~ 0) and its size."""
    S, S0 = s6[:3], s6[3:]
    nS, nS0 = float(np.linalg.norm(S)), float(np.linalg.norm(S0))
    if nS <= _FREE * max(1.0, nS0):
        return True, nS0
    return False, nS


def _screw_glyph(s6: np.ndarray, hint: np.ndarray, anchor: np.ndarray, size: float,
                 length: float, label: str, axes: _Lines, shafts: _Lines, heads: _Heads,
                 free_shafts: _Lines, free_heads: _Heads) -> None:
    free, mag = _magnitude(s6)
    S, S0 = s6[:3], s6[3:]
    head = 0.06 * size
    if mag == 0.0:
        return
    if free:
        # a free vector (a couple, a translation): drawn at its anchor, with a double head
        u = S0 / np.linalg.norm(S0)
        tip = anchor + u * max(length, 1.5 * head)
        free_shafts.add(np.stack([anchor, tip]), f"{label}: pitch inf, |S0| = {mag:.4g}")
        free_heads.add(tip, u, head)
        free_heads.add(tip - 0.9 * head * u, u, head)
        return
    u = S / mag
    h = float(np.dot(S, S0) / mag**2)
    foot = np.cross(S, S0) / mag**2
    at = foot + u * float(np.dot(hint - foot, u))
    text = f"{label}: pitch {h:.4g}, |S| = {mag:.4g}"
    axes.add(np.stack([at - 0.45 * size * u, at + 0.45 * size * u]), text)
    tip = at + u * max(length, 1.5 * head)
    shafts.add(np.stack([at, tip]), text)
    heads.add(tip, u, head)
    if abs(h) > 1e-12:
        rho = 0.035 * size
        shafts.add(_ring(at, u, rho, turns=2.0, advance=math.copysign(
            helix_advance(abs(h), rho), h)), text)


# --------------------------------------------------------------------------
# traces of one scene
# --------------------------------------------------------------------------


def _trace_data(scene: Scene, groups: list[ScrewGroup], size: float, centre: np.ndarray,
                scales: dict, layout: list[str]) -> tuple[list[dict], dict[str, int]]:
    """The data of every trace in ``layout`` order, and the count of glyphs per kind."""
    out: dict[str, dict] = {}
    counts: dict[str, int] = {}
    links = _Lines()
    for pts, name in zip(scene.links, scene.link_names, strict=True):
        links.add(pts, html.escape(name))
    out["links"], counts["links"] = links.data(), links.count
    sliders = _Lines()
    for s in scene.sliders:
        sliders.add(s, "prismatic stroke")
    out["sliders"], counts["sliders"] = sliders.data(), sliders.count
    verts: list[np.ndarray] = []
    tri: list[tuple[int, int, int]] = []
    for poly in scene.solids:
        base = int(sum(len(v) for v in verts))
        verts.append(poly)
        tri += [(base, base + k, base + k + 1) for k in range(1, len(poly) - 1)]
    v = np.concatenate(verts) if verts else np.zeros((0, 3))
    i, j, k = (np.array(tri, dtype=int).T.tolist() if tri else ([], [], []))
    out["solids"] = {"x": v[:, 0].tolist(), "y": v[:, 1].tolist(), "z": v[:, 2].tolist(),
                     "i": i, "j": j, "k": k}
    counts["solids"] = len(scene.solids)
    stubs = _Lines()
    by_kind: dict[str, list[np.ndarray]] = {kind: [] for kind in JOINT_KINDS}
    for kind, p, dirs in scene.joints:
        by_kind[kind].append(p)
        for d in dirs:
            u = d / np.linalg.norm(d)
            stubs.add(np.stack([p - 0.06 * size * u, p + 0.06 * size * u]), kind)
            if kind in ("revolute", "helical", "cylindrical", "universal"):
                adv = 0.004 * size if kind == "helical" else 0.0
                stubs.add(_ring(p, u, 0.025 * size, turns=1.5 if adv else 1.0, advance=adv), kind)
    out["joint-axes"], counts["joint-axes"] = stubs.data(), stubs.count
    for kind in JOINT_KINDS:
        pts = np.array(by_kind[kind]).reshape(-1, 3)
        out[f"joint:{kind}"] = {"x": pts[:, 0].tolist(), "y": pts[:, 1].tolist(),
                                "z": pts[:, 2].tolist()}
        counts[f"joint:{kind}"] = len(pts)
    frame = _Lines()
    if scene.frame is not None:
        T = scene.frame
        for c in range(3):
            frame.add(np.stack([T[:3, 3], T[:3, 3] + 0.08 * size * T[:3, c]]), "xyz"[c])
    out["frame"], counts["frame"] = frame.data(), frame.count
    if scene.cylindroid is not None:
        feet, rulings, pitch = scene.cylindroid
        r = np.array([-0.45, 0.45]) * size
        grid = feet[:, None, :] + r[None, :, None] * rulings[:, None, :]   # (steps, 2, 3)
        out["cylindroid"] = {c: _nulls(grid[:, :, k]) for k, c in enumerate("xyz")}
        out["cylindroid"]["surfacecolor"] = _nulls(np.repeat(pitch[:, None], 2, axis=1))
        counts["cylindroid"] = int(np.sum(np.isfinite(pitch)))
    parts = [(_Lines(), _Lines(), _Heads(), _Lines(), _Heads()) for _ in groups]
    for g, s6, hint, label in scene.screws:
        free, mag = _magnitude(s6)
        top = scales.get((g, free), 0.0)
        length = 0.33 * size * mag / top if top > 0 else 0.0
        near = centre if hint is None else hint
        anchor = hint if hint is not None else scene.anchors.get(
            g, centre if scene.anchor is None else scene.anchor)
        _screw_glyph(s6, near, anchor, size, length, html.escape(label), *parts[g])
    counts["screws"] = len(scene.screws)
    for g, (axes, shafts, heads, free_shafts, free_heads) in enumerate(parts):
        out[f"screw-axes:{g}"], out[f"screw-shafts:{g}"] = axes.data(), shafts.data()
        out[f"screw-heads:{g}"] = heads.data()
        out[f"screw-couples:{g}"] = free_shafts.data()
        out[f"screw-couple-heads:{g}"] = free_heads.data()
        counts[f"screws:{g}"] = sum(1 for s in scene.screws if s[0] == g)
        counts[f"couples:{g}"] = free_shafts.count
    counts["couples"] = sum(counts[f"couples:{g}"] for g in range(len(groups)))
    return [out[name] for name in layout], counts


def _nulls(a: np.ndarray) -> list:
    """A 2-D array as nested lists, NaN as None (a gap in a plotly surface; JSON has no NaN)."""
    return [[None if not math.isfinite(x) else float(x) for x in row] for row in a]


def _free_groups(scenes: list[Scene]) -> set[int]:
    """The groups with a couple or a translation in some scene (they get their own traces)."""
    return {g for sc in scenes for g, s6, _, _ in sc.screws if _magnitude(s6)[0]
            and _magnitude(s6)[1] > 0}


def _layout_names(first: Scene, groups: list[ScrewGroup], free: set[int]) -> list[str]:
    """The traces a view has, fixed for all its frames (``free``: the groups with couples)."""
    names = ["links"] if first.links else []       # none for screws alone
    if first.sliders:
        names.append("sliders")
    if first.solids:
        names.append("solids")
    if first.joints:
        names.append("joint-axes")
    names += [f"joint:{k}" for k in JOINT_KINDS if any(j[0] == k for j in first.joints)]
    if first.frame is not None:
        names.append("frame")
    if first.cylindroid is not None:
        names.append("cylindroid")
    for g in range(len(groups)):
        names += [f"screw-axes:{g}", f"screw-shafts:{g}", f"screw-heads:{g}"]
        if g in free:
            names += [f"screw-couples:{g}", f"screw-couple-heads:{g}"]
    return names


def _colours(groups: list[ScrewGroup]) -> list[str]:
    used = {"twist": 0, "wrench": 0, "screw": 0}
    palette = {"twist": _TWIST_COLOURS, "wrench": _WRENCH_COLOURS, "screw": _SCREW_COLOURS}
    out = []
    for g in groups:
        pal = palette[g.family]
        out.append(pal[used[g.family] % len(pal)])
        used[g.family] += 1
    return out


#: the legend's words for a group's two kinds of glyph, when it has both: (line, free vector)
_KIND_WORDS = {"twist": ("rotations", "translations"), "wrench": ("forces", "couples"),
               "screw": ("finite pitch", "infinite pitch")}


def _style(name: str, groups: list[ScrewGroup], colours: list[str], free: set[int]) -> dict:
    """The fixed attributes of the trace ``name`` (type, colour, legend)."""
    meta = {"screwsym": name}
    if name == "links":
        return dict(type="scatter3d", mode="lines+markers", name="links", meta=meta,
                    line={"color": "#555555", "width": 7}, marker={"size": 2, "color": "#555555"},
                    hoverinfo="text")
    if name == "sliders":
        return dict(type="scatter3d", mode="lines", name="prismatic strokes", meta=meta,
                    line={"color": "#222222", "width": 14}, hoverinfo="text")
    if name == "solids":
        return dict(type="mesh3d", name="base and platform", meta=meta, color="#9999bb",
                    opacity=0.35, flatshading=True, hoverinfo="name", showlegend=True)
    if name == "joint-axes":
        return dict(type="scatter3d", mode="lines", name="joint axes", meta=meta,
                    line={"color": "#222244", "width": 4}, hoverinfo="text")
    if name.startswith("joint:"):
        kind = name[6:]
        return dict(type="scatter3d", mode="markers", name=f"{kind} joints", meta=meta,
                    marker={"symbol": _SYMBOLS[kind], "size": 7, "color": "#222244",
                            "line": {"color": "#222244", "width": 2}},
                    hoverinfo="name")
    if name == "frame":
        # no legend entry: plotly's legend cannot draw a line coloured by an array
        return dict(type="scatter3d", mode="lines", name="tool frame (x, y, z)", meta=meta,
                    showlegend=False,
                    line={"color": [0, 0, 0, 1, 1, 1, 2, 2, 2], "cmin": 0, "cmax": 2,
                          "colorscale": [[0, "#d62728"], [0.5, "#2ca02c"], [1, "#1f77b4"]],
                          "width": 6}, hoverinfo="text")
    if name == "cylindroid":
        return dict(type="surface", name="cylindroid", meta=meta, showlegend=True,
                    colorscale="Viridis", opacity=0.75, hoverinfo="name+text",
                    colorbar={"title": {"text": "pitch"}, "len": 0.5, "x": 0.0},
                    hovertemplate="pitch %{surfacecolor:.3g}<extra>cylindroid</extra>")
    part, g = name.split(":")
    group, colour = groups[int(g)], colours[int(g)]
    legend = {"legendgroup": f"g{g}", "name": html.escape(group.name)}
    if int(g) in free:
        line_word, free_word = _KIND_WORDS[group.family]
        legend["name"] = html.escape(f"{group.name}: {line_word}")
        if part.startswith("screw-couple"):
            legend = {"legendgroup": f"c{g}", "name": html.escape(
                f"{group.name}: {free_word} (dashed, double head)")}
    if part == "screw-couples":
        return dict(type="scatter3d", mode="lines", meta=meta, showlegend=True,
                    line={"color": colour, "width": 5, "dash": "dash"}, hoverinfo="text",
                    **legend)
    if part == "screw-axes":
        return dict(type="scatter3d", mode="lines", meta=meta, showlegend=False,
                    line={"color": colour, "width": 2, "dash": "dot"}, hoverinfo="text", **legend)
    if part == "screw-shafts":
        return dict(type="scatter3d", mode="lines", meta=meta, showlegend=True,
                    line={"color": colour, "width": 5}, hoverinfo="text", **legend)
    return dict(type="cone", meta=meta, showlegend=False, showscale=False, anchor="tip",
                sizemode="raw", sizeref=1, colorscale=[[0, colour], [1, colour]],
                hoverinfo="skip", **legend)


def _browser(browser: str | None) -> str:
    """The Chromium to run: ``browser``, ``$SCREWSYM_CHROMIUM`` or one on the ``PATH``."""
    if browser is not None and not isinstance(browser, str):
        raise TypeError(f"browser: expected a program name or path, got {type(browser).__name__}")
    names = [browser] if browser else [os.environ.get("SCREWSYM_CHROMIUM", ""), "chromium",
                                       "chromium-browser", "google-chrome"]
    for name in names:
        if name and (found := shutil.which(name)):
            return found
    raise FileNotFoundError(
        f"browser: no Chromium found (tried {', '.join(n for n in names if n)}); install "
        "chromium (Debian: apt-get install chromium) or pass browser=...")


def _check_values(values: Any, name: str, n: int, rows: bool) -> np.ndarray:
    try:
        a = np.array(values, dtype=float)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{name}: expected numbers, got {values!r}") from exc
    shape = "(frames, n)" if rows else "(n,)"
    if a.ndim != (2 if rows else 1) or a.shape[-1] != n or (rows and a.shape[0] == 0):
        raise ValueError(f"{name}: expected an array of shape {shape} with n = {n}, "
                         f"got shape {a.shape}")
    return finite(a, name)


# --------------------------------------------------------------------------
# the value
# --------------------------------------------------------------------------

_POST_SCRIPT = """
var gd = document.getElementById('{plot_id}');
var sc = gd._fullLayout && gd._fullLayout.scene && gd._fullLayout.scene._scene;
gd.setAttribute('data-screwsym-traces', String(gd.data.length));
gd.setAttribute('data-screwsym-objects', String(sc && sc.glplot ? sc.glplot.objects.length : -1));
"""


#: a first script in an exported page: counts its console errors and uncaught exceptions in the
#: attribute data-screwsym-errors of <html>, so that a headless browser's --dump-dom reports them
_ERROR_HOOK = """<script>(function () {
  var root = document.documentElement, n = 0, error = console.error;
  function count() { n += 1; root.setAttribute('data-screwsym-errors', String(n)); }
  root.setAttribute('data-screwsym-errors', '0');
  window.addEventListener('error', count);
  window.addEventListener('unhandledrejection', count);
  console.error = function () { count(); return error.apply(console, arguments); };
})();</script>"""


#: the environment variable that tells a view's Jupyter output where plotly.js comes from
PLOTLYJS_ENV = "SCREWSYM_VIEW_PLOTLYJS"
_PLOTLYJS_MODES = {"": True, "inline": True, "site": False}

#: before a view that relies on the page's plotly.js: a console error where there is none
_NEEDS_PLOTLY = ("<script>if (typeof Plotly === 'undefined') {{ console.error("
                 "'screwsym view {plot_id}: this page loads no plotly.js ({env}=site)'); }}</script>")


def _include_plotlyjs() -> bool:
    """Whether a view's Jupyter output carries plotly.js (``$SCREWSYM_VIEW_PLOTLYJS``)."""
    mode = os.environ.get(PLOTLYJS_ENV, "").strip().lower()
    if mode not in _PLOTLYJS_MODES:
        raise ValueError(f"${PLOTLYJS_ENV}: expected 'inline' (plotly.js in each view, the "
                         f"default) or 'site' (the page loads plotly.js), got {mode!r}")
    return _PLOTLYJS_MODES[mode]


class View:
    """An immutable 3-D view: a plotly figure and the counts of what it draws.

    ``figure`` gives a new ``plotly.graph_objects.Figure`` at each access (so
    the view itself cannot be changed through it); ``kinds`` the number of
    glyphs of each kind in the first frame (``"links"``, ``"joint:revolute"``,
    ``"screws"``, ...); ``frames`` the number of animation frames (0 for one
    configuration).

    In Jupyter a view shows itself as HTML with plotly.js inside (self-contained:
    works offline in any front end).  With the environment variable
    ``SCREWSYM_VIEW_PLOTLYJS=site`` in the kernel, that output leaves plotly.js
    out and draws with the page's own ``Plotly`` (a documentation site that loads
    plotly.js once for all its pages: the screwsym site does, from its
    ``_static``).  :meth:`to_html` and :meth:`to_png` always embed plotly.js.

    >>> import os
    >>> from screwsym.motion.chain import ur5
    >>> v = view(ur5())
    >>> len(v._repr_html_()) > 4_000_000          # plotly.js inside
    True
    >>> os.environ["SCREWSYM_VIEW_PLOTLYJS"] = "site"
    >>> len(v._repr_html_()) < 100_000            # the page's plotly.js
    True
    >>> del os.environ["SCREWSYM_VIEW_PLOTLYJS"]
    """

    __slots__ = ("_json", "_kinds", "_frames", "_id")
    _json: str
    _kinds: dict[str, int]
    _frames: int
    _id: str

    def __init__(self, spec: dict, kinds: Mapping[str, int], frames: int) -> None:
        text = json.dumps(spec, sort_keys=True, allow_nan=False)
        object.__setattr__(self, "_json", text)
        object.__setattr__(self, "_kinds", dict(kinds))
        object.__setattr__(self, "_frames", frames)
        object.__setattr__(self, "_id", "screwsym-" + hashlib.sha256(text.encode()).hexdigest()[:12])

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("View is immutable")

    def __delattr__(self, name: str) -> None:
        raise AttributeError("View is immutable")

    def __repr__(self) -> str:
        return f"<View: {len(self.figure.data)} traces, {self._frames} frames>"

    @property
    def figure(self) -> Any:
        """A new plotly ``Figure`` of this view."""
        return _plotly().Figure(json.loads(self._json))

    @property
    def kinds(self) -> dict[str, int]:
        """The number of glyphs of each kind in the first configuration."""
        return dict(self._kinds)

    @property
    def frames(self) -> int:
        """The number of animation frames (0: one configuration)."""
        return self._frames

    def _html(self, full: bool, still: bool = False, plotlyjs: bool = True) -> str:
        import plotly.io as pio

        config = {"displaylogo": False, "responsive": True}
        if still:
            config["displayModeBar"] = False
        out = pio.to_html(self.figure, include_plotlyjs=plotlyjs, full_html=full,
                          div_id=self._id, post_script=_POST_SCRIPT, auto_play=False,
                          config=config)
        if plotlyjs:
            return out
        return _NEEDS_PLOTLY.format(plot_id=self._id, env=PLOTLYJS_ENV) + out

    def to_html(self, path: str | os.PathLike) -> str:
        """Write one self-contained HTML file (plotly.js inside, no network); return its path."""
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(f"path: expected a file name, got {type(path).__name__}")
        page = self._html(True).replace("<head>", "<head>" + _ERROR_HOOK, 1)
        with open(path, "w", encoding="utf-8") as f:
            f.write(page)
        return os.fspath(path)

    def to_png(self, path: str | os.PathLike, *, width: int = 900, browser: str | None = None,
               timeout: float = 60.0) -> str:
        """Write a PNG picture of the view (its first frame) with headless Chromium; return its path.

        plotly's own ``write_image`` needs kaleido; this uses a Chromium (or Chrome) already on
        the machine: ``browser``, else ``$SCREWSYM_CHROMIUM``, else ``chromium``,
        ``chromium-browser`` or ``google-chrome`` on the ``PATH``.  The page is the view's own
        self-contained HTML, opened from a temporary folder with every host name resolved to
        nothing (no network).  ``FileNotFoundError`` without a browser; ``RuntimeError`` if it
        fails or takes longer than ``timeout`` seconds.
        """
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(f"path: expected a file name, got {type(path).__name__}")
        if isinstance(width, bool) or not isinstance(width, int) or width < 100:
            raise ValueError(f"width: expected a whole number of pixels >= 100, got {width!r}")
        if isinstance(timeout, bool) or not isinstance(timeout, (int, float)) or not timeout > 0:
            raise ValueError(f"timeout: expected a positive number of seconds, got {timeout!r}")
        exe = _browser(browser)
        height = int(json.loads(self._json)["layout"]["height"])
        height += 90 if self._frames else 0           # the slider and the buttons
        out = os.path.abspath(os.fspath(path))
        with tempfile.TemporaryDirectory() as tmp:
            page = os.path.join(tmp, "view.html")
            with open(page, "w", encoding="utf-8") as f:
                f.write(self._html(True, still=True).replace(
                    "<head>", "<head><style>body { margin: 0; overflow: hidden; }</style>", 1))
            cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu",
                   "--enable-unsafe-swiftshader", "--disable-background-networking",
                   "--disable-component-update", "--disable-sync", "--no-first-run",
                   "--hide-scrollbars", "--host-resolver-rules=MAP * ~NOTFOUND",
                   "--proxy-server=127.0.0.1:9", f"--user-data-dir={os.path.join(tmp, 'profile')}",
                   f"--window-size={width},{height}", "--virtual-time-budget=3000",
                   f"--screenshot={out}", pathlib.Path(page).as_uri()]
            try:
                run = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
            except subprocess.TimeoutExpired as exc:
                raise RuntimeError(f"to_png: {exe} did not finish within {timeout} s") from exc
        if run.returncode != 0 or not os.path.exists(out):
            raise RuntimeError(f"to_png: {exe} failed: {run.stderr[-500:]}")
        return os.fspath(path)

    def _repr_html_(self) -> str:
        return self._html(False, plotlyjs=_include_plotlyjs())

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None) -> dict:
        # HTML only: every front end runs it (JupyterLab, VS Code, nbconvert, myst-nb), where
        # plotly's own MIME type needs a front-end extension and is not rendered by the
        # documentation site's builder; self-contained unless $SCREWSYM_VIEW_PLOTLYJS=site
        return {"text/html": self._html(False, plotlyjs=_include_plotlyjs()),
                "text/plain": repr(self)}


class _Drawer:
    """The fixed frame of a view (extent, scales, traces) and the data of any configuration.

    Built from sample scenes (a view's frames, a live view's first pose); then :meth:`data`
    turns any scene into the traces' data with NumPy only.
    """

    def __init__(self, make: Any, groups: list[ScrewGroup], scenes: list[Scene]) -> None:
        self.make, self.groups = make, groups
        feet = [np.cross(s6[:3], s6[3:]) / float(np.dot(s6[:3], s6[:3]))
                for sc in scenes for _, s6, _, _ in sc.screws if not _magnitude(s6)[0]]
        pts = np.concatenate([s.points() for s in scenes] + [np.reshape(feet, (-1, 3))])
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        self.centre = (lo + hi) / 2
        self.size = max(float(np.max(hi - lo)),
                        1.0 if len(pts) <= len(scenes) + len(feet) else 1e-9)
        self.scales: dict = {}
        for sc in scenes:
            for g, s6, _, _ in sc.screws:
                free, mag = _magnitude(s6)
                key = (g, free)
                self.scales[key] = max(self.scales.get(key, 0.0), mag)
        self.free = _free_groups(scenes)
        self.names = _layout_names(scenes[0], groups, self.free)
        self.colours = _colours(groups)

    def data(self, scene: Scene) -> tuple[list[dict], dict[str, int]]:
        return _trace_data(scene, self.groups, self.size, self.centre, self.scales, self.names)

    def traces(self, data: list[dict]) -> list[dict]:
        return [{**_style(name, self.groups, self.colours, self.free), **d}
                for name, d in zip(self.names, data, strict=True)]

    def layout(self, height: int, title: str | None, camera: dict | None = None) -> dict:
        half = 0.62 * self.size
        axis = {c: {"range": [float(self.centre[i] - half), float(self.centre[i] + half)],
                    "title": c} for i, c in enumerate("xyz")}
        layout: dict = {
            "height": height, "margin": {"l": 0, "r": 0, "t": 40 if title else 10, "b": 0},
            "scene": {"xaxis": axis["x"], "yaxis": axis["y"], "zaxis": axis["z"],
                      "aspectmode": "cube"},
            "legend": {"itemsizing": "constant"},
        }
        if camera is not None:
            layout["scene"]["camera"] = camera
        if title:
            layout["title"] = {"text": html.escape(title)}
        return layout


def _check_arguments(subs: Any, variables: Any, twists: Any, title: Any,
                     height: Any) -> tuple[dict, tuple]:
    """The arguments :func:`view` and :func:`live` share, checked: ``subs`` and ``variables``
    as the scene takes them."""
    if not isinstance(twists, bool):
        raise TypeError(f"twists: expected True or False, got {twists!r}")
    if title is not None and not isinstance(title, str):
        raise TypeError(f"title: expected a string, got {type(title).__name__}")
    if isinstance(height, bool) or not isinstance(height, int) or height < 100:
        raise ValueError(f"height: expected a whole number of pixels >= 100, got {height!r}")
    return check_subs(subs), check_variables(variables)


def _check_camera(camera: Any) -> dict | None:
    """plotly's ``scene.camera`` for ``camera=(x, y, z)``, the eye's position (None: plotly's)."""
    if camera is None:
        return None
    if isinstance(camera, (str, bytes)) or not isinstance(camera, (list, tuple, np.ndarray)):
        raise TypeError(f"camera: expected three numbers (the eye's position), got "
                        f"{type(camera).__name__}")
    try:
        eye = np.array(camera, dtype=float)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"camera: expected three numbers, got {camera!r}") from exc
    if eye.shape != (3,) or not np.all(np.isfinite(eye)) or not np.any(eye):
        raise ValueError(f"camera: expected three finite numbers, not all zero, got {camera!r}")
    return {"eye": dict(zip("xyz", (float(c) for c in eye), strict=True))}


def view(obj: Any, q: Any = None, *, path: Any = None, variables: Any = None, subs: Any = None,
         screws: Any = None, twists: bool = False, cylindroid: Any = None,
         anchor: Any = None, title: str | None = None, height: int = 560,
         camera: Any = None) -> View:
    r"""A 3-D view of a chain, a parallel mechanism, a graph mechanism or screws.

    Parameters
    ==========

    obj : Chain, ParallelMechanism, Mechanism, Screw, ScrewSystem or a list of screws
    q : sequence of numbers, optional
        A chain's joint values (default all zero); for any other object the
        values of ``variables``.
    path : array of shape (frames, n), optional
        Configurations to animate (instead of ``q``): one frame each, with a
        slider and play/pause buttons, all precomputed.
    variables : sequence of Symbol, optional
        The symbols ``q`` and ``path`` give values to: a mechanism's pose
        symbols, or the joint symbols in ``screws`` given for a chain (e.g. its
        Jacobian's columns), which are then recomputed at each frame.
    subs : dict, optional
        Numbers for every other symbol (the geometry's parameters).
    screws : screw(s) or dict of name -> screw(s), optional
        Screws, twists, wrenches or screw systems to place in the scene; a dict
        gives each group its legend entry and colour.
    twists : bool
        A chain's joint twists at ``q`` (the space Jacobian's columns) as a group.
    cylindroid : two screws (or a screw system of two), optional
        Their cylindroid as a surface: the axes of ``cos t $_1 + sin t $_2``
        (Ball 1900, ch. 4; Hunt 1978, §12.2), coloured by pitch.
    anchor : point, or dict of group name -> point, optional
        Where the couples (and translations) of ``screws`` are drawn: a free
        vector has no axis, so it is placed on the body it acts on.  Three
        numbers or expressions in ``variables`` (recomputed at each frame).
        By default a chain's flange, a parallel mechanism's platform centre
        (the mean of its limbs' last joints), a graph mechanism's link
        ``"platform"`` (the mean of its joints; all the joints if it has none),
        the scene's centre for screws alone.  A chain's joint twists are drawn
        at their joints.
    title : str, optional
    height : int
        The figure's height in pixels (default 560).
    camera : three numbers, optional
        Where the eye looks from at first (plotly's ``scene.camera.eye``, in
        units of the scene's half-size from its centre; default plotly's
        ``(1.25, 1.25, 1.25)``): e.g. ``(1.8, 1.1, 0.4)`` for a lower view of a
        tall mechanism.  The reader can still turn the view.

    Examples
    ========

    >>> from screwsym import Chain, Transform, Twist, Wrench
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])], Transform.translation([2, 0, 0]))
    >>> v = view(arm, [0.3, -0.6], twists=True,
    ...          screws={"load": Wrench([0, -1, 0], [0, 0, -2])})
    >>> v.kinds["joint:revolute"], v.kinds["screws"]
    (2, 3)

    Along a path (one frame per row, a slider and play/pause), with a wrench
    that depends on the joint symbols, recomputed at each frame:

    >>> from sympy import cos, sin, symbols
    >>> q1, q2 = symbols("q1 q2", real=True)
    >>> pull = Wrench([cos(q1), sin(q1), 0], [0, 0, 0])
    >>> v = view(arm, path=[[0, 0], [0.5, -1], [1, -2]], variables=[q1, q2],
    ...          screws={"pull": pull})
    >>> v.frames, len(v.figure.frames)
    (3, 3)
    """
    go = _plotly()
    subs, variables = _check_arguments(subs, variables, twists, title, height)
    eye = _check_camera(camera)
    make, groups, n = scene_maker(obj, subs=subs, variables=variables, screws=screws,
                                  twists=twists, cylindroid=cylindroid, anchor=anchor)
    if path is not None and q is not None:
        raise ValueError("q, path: give one configuration (q) or a path, not both")
    if path is not None:
        rows = _check_values(path, "path", n, rows=True)
    else:
        rows = _check_values(np.zeros(n) if q is None else q, "q", n, rows=False)[None, :]
    scenes = [make(r) for r in rows]
    drawer = _Drawer(make, groups, scenes)
    datas, counts = [], {}
    for k, sc in enumerate(scenes):
        data, c = drawer.data(sc)
        datas.append(data)
        if k == 0:
            counts = c
    traces = drawer.traces(datas[0])
    layout = drawer.layout(height, title, eye)
    spec = {"data": traces, "layout": layout}
    if path is not None:
        names = [str(k) for k in range(len(rows))]
        kinds = [t["type"] for t in traces]
        spec["frames"] = [{"name": nm, "data": [{"type": k, **e} for k, e in zip(kinds, d, strict=True)]}
                          for nm, d in zip(names, datas, strict=True)]
        labels = _labels(rows, variables, obj)
        step_args = {"mode": "immediate", "frame": {"duration": 0, "redraw": True},
                     "transition": {"duration": 0}}
        layout["sliders"] = [{"active": 0, "pad": {"t": 30},
                              "currentvalue": {"prefix": "", "font": {"color": "#222222"}},
                              "font": {"color": "rgba(0,0,0,0)"},
                              "steps": [{"method": "animate", "label": lab,
                                         "args": [[nm], step_args]}
                                        for nm, lab in zip(names, labels, strict=True)]}]
        layout["updatemenus"] = [{"type": "buttons", "showactive": False, "x": 0.0, "y": 0.0,
                                  "xanchor": "left", "yanchor": "top", "direction": "left",
                                  "buttons": [
            {"label": "play", "method": "animate",
             "args": [None, {"mode": "immediate", "fromcurrent": True,
                             "frame": {"duration": 80, "redraw": True},
                             "transition": {"duration": 0}}]},
            {"label": "pause", "method": "animate",
             "args": [[None], {"mode": "immediate", "frame": {"duration": 0, "redraw": False},
                               "transition": {"duration": 0}}]}]}]
    go.Figure(spec)              # plotly's own validation of every attribute
    return View(spec, counts, 0 if path is None else len(rows))


def _labels(rows: np.ndarray, variables: tuple, obj: Any) -> list[str]:
    if variables:
        names = [html.escape(str(v)) for v in variables]
    else:
        names = [f"q{i + 1}" for i in range(rows.shape[1])]
    # + 0.0: no "-0" in a label
    return [", ".join(f"{nm}={x + 0.0:.3g}" for nm, x in zip(names, r, strict=True)) for r in rows]


class Live:
    """A view to move in a live kernel: :meth:`redraw` recomputes every trace from numbers.

    Made by :func:`live`.  ``redraw(values)`` returns the data of the view's traces
    (``x``, ``y``, ``z``, ... lists) at ``values`` (the controls' values), through the
    lambdified functions :func:`view` uses for its frames: no SymPy in the loop.
    :meth:`figure` is the view at the first values; :meth:`widget` puts it in a plotly
    ``FigureWidget`` with one ipywidgets slider per control (needs ipywidgets and anywidget:
    an ``ImportError`` saying so without them).
    """

    def __init__(self, drawer: _Drawer, controls: list[tuple[str, float, float, float]],
                 solve: Any, n: int, height: int, title: str | None,
                 camera: dict | None = None) -> None:
        self._drawer, self.controls, self._solve, self._n = drawer, tuple(controls), solve, n
        self._height, self._title, self._camera = height, title, camera

    def __repr__(self) -> str:
        names = ", ".join(c[0] for c in self.controls)
        return f"<Live view: {len(self._drawer.names)} traces, controls {names}>"

    def configuration(self, values: Any) -> np.ndarray:
        """The mechanism's values (``q`` of :func:`view`) at the controls' ``values``."""
        v = _check_values(values, "values", len(self.controls), rows=False)
        if self._solve is None:
            return v
        return _check_values(self._solve(v), "solve(values)", self._n, rows=False)

    def redraw(self, values: Any) -> list[dict]:
        """The data of every trace at the controls' ``values`` (floats; no SymPy)."""
        return self._drawer.data(self._drawer.make(self.configuration(values)))[0]

    def figure(self) -> Any:
        """A plotly ``Figure`` at the controls' first values."""
        data = self.redraw([c[3] for c in self.controls])
        return _plotly().Figure({"data": self._drawer.traces(data),
                                 "layout": self._drawer.layout(self._height, self._title,
                                                               self._camera)})

    def widget(self) -> Any:
        """A plotly ``FigureWidget`` and one slider per control, redrawn as they move."""
        try:
            ipywidgets = importlib.import_module("ipywidgets")
            importlib.import_module("anywidget")        # plotly's FigureWidget (plotly >= 6)
        except ImportError as exc:
            raise ImportError("Live.widget needs ipywidgets and anywidget: the live extra "
                              "(pip install -e \".[live]\" from a clone, or pip install "
                              "ipywidgets anywidget); without them, view(..., path=...) draws "
                              "precomputed frames with a slider") from exc
        go = _plotly()
        fig = go.FigureWidget(self.figure())
        sliders = [ipywidgets.FloatSlider(value=start, min=lo, max=hi, step=(hi - lo) / 200,
                                          description=name, continuous_update=True)
                   for name, lo, hi, start in self.controls]

        def update(_: Any = None) -> None:
            try:
                data = self.redraw([s.value for s in sliders])
            except ValueError:
                return                              # out of reach: keep the last picture
            with fig.batch_update():
                for trace, d in zip(fig.data, data, strict=True):
                    trace.update(d)

        for s in sliders:
            s.observe(update, names="value")
        return ipywidgets.VBox([fig, *sliders])


def live(obj: Any, q: Any = None, *, variables: Any = None, subs: Any = None,
         screws: Any = None, twists: bool = False, anchor: Any = None,
         controls: Any = None, solve: Any = None, extent: Any = None,
         title: str | None = None, height: int = 560, camera: Any = None) -> Live:
    r"""A view to move with sliders in a live kernel, redrawn by generated numeric functions.

    The arguments are :func:`view`'s; the SymPy work is done here, once.  ``controls``:
    one ``(name, low, high)`` per slider (default: one per joint of a chain, in
    ``[-pi, pi]``, or one per symbol of ``variables``, ``q +- 1``); ``solve``: a function
    from the controls' values to the mechanism's values (e.g. a Delta's inverse
    kinematics, :meth:`screwsym.plot.models.Delta.configurations`), by default the
    identity; ``extent``: configurations (rows) that fix the scene's extent and the
    screws' scale (default: ``q`` alone).  A group of screws draws its couples only if
    one appears at ``q`` or in ``extent``.

    >>> from screwsym.motion.chain import ur5
    >>> lv = live(ur5(), [0, -0.5, 1, 0, 0.5, 0], twists=True)
    >>> lv
    <Live view: 7 traces, controls q1, q2, q3, q4, q5, q6>
    >>> data = lv.redraw([0.1, -0.5, 1, 0, 0.5, 0])       # NumPy only
    >>> len(data), len(data[-1]["x"])                      # the joint twists' six heads
    (7, 6)
    """
    subs, variables = _check_arguments(subs, variables, twists, title, height)
    eye = _check_camera(camera)
    if solve is not None and not callable(solve):
        raise TypeError(f"solve: expected a function of the controls' values, got {solve!r}")
    make, groups, n = scene_maker(obj, subs=subs, variables=variables, screws=screws,
                                  twists=twists, cylindroid=None, anchor=anchor)
    if controls is None:
        if solve is not None:
            raise ValueError("controls: give the controls that solve= takes")
        q0 = _check_values(np.zeros(n) if q is None else q, "q", n, rows=False)
        names = ([str(v) for v in variables] if variables
                 else [f"q{i + 1}" for i in range(n)])
        if isinstance(obj, Chain):
            controls = [(nm, -math.pi, math.pi) for nm in names]
        else:
            controls = [(nm, float(x) - 1.0, float(x) + 1.0) for nm, x in zip(names, q0,
                                                                              strict=True)]
        start = q0
    else:
        if isinstance(controls, (str, bytes)) or not isinstance(controls, (list, tuple)):
            raise TypeError("controls: expected a list of (name, low, high)")
        for k, c in enumerate(controls):
            if (not isinstance(c, (list, tuple)) or len(c) != 3 or not isinstance(c[0], str)
                    or not float(c[1]) < float(c[2])):
                raise ValueError(f"controls[{k}]: expected (name, low, high) with low < high, "
                                 f"got {c!r}")
        start = (np.array([(float(c[1]) + float(c[2])) / 2 for c in controls]) if q is None
                 else _check_values(q, "q", len(controls), rows=False))
        if not all(c[1] <= x <= c[2] for c, x in zip(controls, start, strict=True)):
            raise ValueError(f"q: expected values within the controls' ranges, got {start}")
    ctl = [(str(c[0]), float(c[1]), float(c[2]), float(x))
           for c, x in zip(controls, start, strict=True)]
    first = start if solve is None else _check_values(solve(start), "solve(values)", n, rows=False)
    if solve is None and len(first) != n:
        raise ValueError(f"controls: expected {n} controls (one per value), got {len(first)}")
    rows = [first]
    if extent is not None:
        rows += list(_check_values(extent, "extent", n, rows=True))
    drawer = _Drawer(make, groups, [make(r) for r in rows])
    return Live(drawer, ctl, solve, n, height, title, eye)
