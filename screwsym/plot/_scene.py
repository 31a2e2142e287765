r"""The numbers of a 3-D view: a mechanism at one configuration, as plain float arrays.

Explanation
===========

:func:`scene_maker` turns a :class:`~screwsym.motion.chain.Chain`, a
:class:`~screwsym.systems.parallel.ParallelMechanism`, a graph
:class:`~screwsym.systems.linkage.Mechanism` or a set of screws into a function
``values -> Scene``.  All the SymPy work (substitutions, exponentials, the
checks) happens once, in :func:`scene_maker`; the function it returns only
calls lambdified expressions (:func:`sympy.lambdify` to NumPy) and does NumPy
products, so a redraw along a path costs microseconds per joint and no
SymPy.

* A **chain** at joint values ``q``: each joint's exponential ``exp6($_i, q)``
  is lambdified in one symbol; ``T_i = T_{i-1} exp6($_i, q_i)``.  Each joint
  axis gets a point: the point of its home axis nearest the previous joint's
  point (the base origin before the first joint; a prismatic joint's point is
  the previous one), carried by ``T_{i-1}``; link ``i`` is the segment from joint
  ``i``'s point to joint ``i+1``'s (the flange, ``M``'s origin, after the last),
  both carried by ``T_i``.  The joint twists shown are ``Ad(T_{i-1}) $_i``, the
  columns of the space Jacobian.
* A **parallel mechanism** or a graph **mechanism**: its joints as placed, each
  at its point (a prismatic joint, which has none, midway between its
  neighbours).  Symbols named in ``variables`` are the configuration; every
  other symbol must be given a number by ``subs``.
* **Screws** (twists, wrenches, screw systems), fixed in space or functions
  of ``variables``, are evaluated by the same lambdified function.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from sympy import Basic, Dummy, ImmutableMatrix, Matrix, Symbol, lambdify, sympify

from ..core.checks import check_no_strings
from ..core.screw import Screw
from ..core.twist import Twist
from ..core.wrench import Wrench
from ..motion.chain import Chain
from ..motion.displacement import exp6
from ..systems.joints import (
    Cylindrical,
    Helical,
    Joint,
    Parallelogram,
    Prismatic,
    Revolute,
    Spherical,
    Universal,
)
from ..systems.linkage import Mechanism
from ..systems.parallel import ParallelMechanism
from ..systems.screw_system import ScrewSystem

__all__ = ["Scene", "ScrewGroup", "scene_maker", "cylindroid_rulings", "JOINT_KINDS",
           "CYLINDROID_STEPS"]

#: the joint kinds a view draws, each with its own glyph
JOINT_KINDS = ("revolute", "prismatic", "helical", "cylindrical", "universal", "spherical",
               "parallelogram")

_KIND_OF = {Revolute: "revolute", Prismatic: "prismatic", Helical: "helical",
            Cylindrical: "cylindrical", Universal: "universal", Spherical: "spherical",
            Parallelogram: "parallelogram"}


@dataclass(frozen=True)
class ScrewGroup:
    """A legend entry: a name and the family (``"twist"``, ``"wrench"`` or ``"screw"``)."""

    name: str
    family: str


@dataclass
class Scene:
    """One configuration in floats: polylines, solids, joints and screws."""

    links: list[np.ndarray] = field(default_factory=list)      # (k, 3) polylines
    link_names: list[str] = field(default_factory=list)
    solids: list[np.ndarray] = field(default_factory=list)     # (k, 3) flat polygons
    joints: list[tuple[str, np.ndarray, list[np.ndarray]]] = field(default_factory=list)
    sliders: list[np.ndarray] = field(default_factory=list)    # (2, 3) prismatic strokes
    screws: list[tuple[int, np.ndarray, np.ndarray | None, str]] = field(default_factory=list)
    frame: np.ndarray | None = None                            # 4 x 4 tool pose
    # where a couple (or a translation) of a placed group is drawn: the group's anchor, else
    # the body's (a chain's flange, a parallel mechanism's platform centre, ...)
    anchor: np.ndarray | None = None
    anchors: dict[int, np.ndarray] = field(default_factory=dict)
    # the cylindroid of two screws: the feet, unit directions and pitches of its rulings
    cylindroid: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None

    def points(self) -> np.ndarray:
        """Every point drawn (for the scene's extent)."""
        pts = [np.zeros((1, 3))]
        pts += [p for p in self.links] + [p for p in self.solids] + list(self.sliders)
        pts += [j[1][None, :] for j in self.joints]
        pts += [h[None, :] for _, _, h, _ in self.screws if h is not None]
        pts += [a[None, :] for a in self.anchors.values()]
        if self.anchor is not None:
            pts.append(self.anchor[None, :])
        if self.frame is not None:
            pts.append(self.frame[None, :3, 3])
        if self.cylindroid is not None:
            feet = self.cylindroid[0]
            pts.append(feet[np.all(np.isfinite(feet), axis=1)])
        return np.concatenate(pts, axis=0)


#: the rulings of a drawn cylindroid: theta in [0, pi] in this many steps
CYLINDROID_STEPS = 73


def cylindroid_rulings(s1: np.ndarray, s2: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Feet, unit directions and pitches of the axes of ``cos t s1 + sin t s2``, ``0 <= t <= pi``.

    The axes of the screws of a two-system fill its cylindroid (Ball 1900, ch. 4; Hunt 1978,
    §12.2).  A member whose ``S`` vanishes (a couple: its axis at infinity) gives a row of NaN.
    """
    t = np.linspace(0.0, math.pi, CYLINDROID_STEPS)
    S6 = np.cos(t)[:, None] * s1 + np.sin(t)[:, None] * s2
    w, v = S6[:, :3], S6[:, 3:]
    ww = np.einsum("ij,ij->i", w, w)
    scale = np.maximum(np.linalg.norm(S6, axis=1), 1e-300)
    line = np.sqrt(ww) > 1e-12 * scale
    with np.errstate(invalid="ignore", divide="ignore"):
        feet = np.where(line[:, None], np.cross(w, v) / ww[:, None], np.nan)
        dirs = np.where(line[:, None], w / np.sqrt(ww)[:, None], np.nan)
        pitch = np.where(line, np.einsum("ij,ij->i", w, v) / ww, np.nan)
    return feet, dirs, pitch


# --------------------------------------------------------------------------
# checks and numbers
# --------------------------------------------------------------------------


def check_subs(subs: Any) -> dict:
    """``subs`` as a dict of symbols to numbers (``TypeError`` otherwise)."""
    if subs is None:
        return {}
    check_no_strings(subs, "subs")
    if not isinstance(subs, Mapping):
        raise TypeError(f"subs: expected a dict mapping symbols to numbers, got {type(subs).__name__}")
    out = {}
    for k, v in subs.items():
        if not isinstance(k, Symbol):
            raise TypeError(f"subs: expected SymPy symbols as keys, got {k!r}")
        out[k] = sympify(v, strict=True)     # no strings here: check_no_strings above
    return out


def check_variables(variables: Any) -> tuple[Symbol, ...]:
    """``variables`` as a tuple of distinct symbols."""
    if variables is None:
        return ()
    if isinstance(variables, (str, bytes)) or not isinstance(variables, Sequence):
        raise TypeError("variables: expected a sequence of SymPy symbols, got "
                        f"{type(variables).__name__}")
    out = tuple(variables)
    for i, v in enumerate(out):
        if not isinstance(v, Symbol):
            raise TypeError(f"variables[{i}]: expected a SymPy Symbol, got {v!r}")
    if len(set(out)) != len(out):
        raise ValueError(f"variables: expected distinct symbols, got {out}")
    return out


class _Packer:
    """Collects SymPy matrices, lambdifies them together in ``variables``, unpacks the floats."""

    def __init__(self, variables: tuple[Symbol, ...], subs: dict) -> None:
        self.variables, self.subs = variables, subs
        self.exprs: list[Basic] = []
        self.fn: Callable[..., Any] | None = None

    def add(self, m: Any, name: str) -> slice:
        m = ImmutableMatrix(m)
        if self.subs:
            m = m.xreplace(self.subs)
        free = m.free_symbols - set(self.variables)
        if free:
            names = ", ".join(sorted(str(s) for s in free))
            raise ValueError(f"{name}: cannot draw symbolic values: give {names} numbers in "
                             "subs={...}, or name them in variables=[...] with q or path")
        start = len(self.exprs)
        self.exprs.extend(m)
        return slice(start, len(self.exprs))

    def compile(self) -> None:
        self.fn = lambdify(self.variables, list(self.exprs), "numpy")

    def __call__(self, values: np.ndarray) -> np.ndarray:
        assert self.fn is not None
        out = np.array(self.fn(*values[:len(self.variables)]), dtype=complex)
        if out.size and np.any(np.abs(out.imag) > 1e-9 * (1 + np.abs(out.real))):
            raise ValueError("q: these values give complex coordinates (outside the "
                             "mechanism's real configurations)")
        return out.real.astype(float)


def _point(joint: Joint) -> Any:
    if isinstance(joint, Prismatic):
        return None
    if isinstance(joint, Parallelogram):
        p1, p2, _ = joint.args
        return (p1 + p2) / 2
    return joint.args[0]


def _directions(joint: Joint) -> list[Any]:
    if isinstance(joint, Prismatic):
        return [joint.args[0]]
    if isinstance(joint, (Revolute, Helical, Cylindrical)):
        return [joint.args[1]]
    if isinstance(joint, Universal):
        return [joint.args[1], joint.args[2]]
    return []


def _screws(value: Any, name: str) -> list[Screw]:
    """A screw, a screw system or a sequence of either, as a list of screws."""
    if isinstance(value, Screw):
        return [value]
    if isinstance(value, ScrewSystem):
        return list(value.screws)
    if isinstance(value, (str, bytes)) or not isinstance(value, Sequence):
        raise TypeError(f"{name}: expected a Screw, Twist, Wrench, ScrewSystem or a list of "
                        f"them, got {type(value).__name__}")
    out: list[Screw] = []
    for i, s in enumerate(value):
        out += _screws(s, f"{name}[{i}]") if not isinstance(s, Screw) else [s]
    return out


def _family(screws: list[Screw]) -> str:
    kinds = {Twist if isinstance(s, Twist) else Wrench if isinstance(s, Wrench) else Screw
             for s in screws}
    return {Twist: "twist", Wrench: "wrench"}.get(kinds.pop(), "screw") if len(kinds) == 1 else "screw"


def check_screw_groups(screws: Any) -> list[tuple[str, list[Screw]]]:
    """``screws=`` as ``[(group name, [screw, ...]), ...]``."""
    if screws is None:
        return []
    if isinstance(screws, Mapping):
        out = []
        for k, v in screws.items():
            if not isinstance(k, str):
                raise TypeError(f"screws: expected string keys (the legend's names), got {k!r}")
            out.append((k, _screws(v, f"screws[{k!r}]")))
        return out
    return [("screws", _screws(screws, "screws"))]


# --------------------------------------------------------------------------
# the makers
# --------------------------------------------------------------------------


def _nearest_on_line(point: np.ndarray, foot: np.ndarray, u: np.ndarray) -> np.ndarray:
    return foot + u * float(np.dot(point - foot, u))


def _chain_maker(chain: Chain, subs: dict, twists: bool, packer: _Packer):
    n = chain.n_joints
    t = Dummy("t", real=True)
    exps, kinds, omegas, vs = [], [], [], []
    for i, tw in enumerate(chain.twists):
        tw = tw.xreplace(subs) if subs else tw
        free = tw.free_symbols
        if free:
            names = ", ".join(sorted(str(s) for s in free))
            raise ValueError(f"chain: joint twist {i + 1} is symbolic: give {names} numbers "
                             "in subs={...}")
        # the book's table (Section 1.4.2), under the float policy: a couple is a translation
        kind = {"couple": "prismatic", "line": "revolute", "screw": "helical"}.get(
            str(tw.classify()))
        if kind is None:
            raise ValueError(f"chain: joint twist {i + 1} is neither a rotation, a translation "
                             f"nor a screw motion: {tw}")
        kinds.append(kind)
        exps.append(lambdify(t, Matrix(exp6(tw, t).matrix), "numpy"))
        omegas.append(np.array([float(x) for x in tw.S]))
        vs.append(np.array([float(x) for x in tw.S0]))
    home = chain.home.matrix.xreplace(subs) if subs else chain.home.matrix
    if home.free_symbols:
        names = ", ".join(sorted(str(s) for s in home.free_symbols))
        raise ValueError(f"chain: the home pose is symbolic: give {names} numbers in subs={{...}}")
    M = np.array(home.tolist(), dtype=float)
    # the joints' points at home, each the nearest point of its axis to the previous one
    anchors, prev = [], np.zeros(3)
    for w, v, kind in zip(omegas, vs, kinds, strict=True):
        if kind != "prismatic":
            u = w / np.linalg.norm(w)
            h = float(np.dot(w, v) / np.dot(w, w))
            foot = np.cross(w, v - h * w) / np.dot(w, w)
            prev = _nearest_on_line(prev, foot, u)
        anchors.append(prev)
    anchors.append(M[:3, 3])

    def carry(T: np.ndarray, p: np.ndarray) -> np.ndarray:
        return T[:3, :3] @ p + T[:3, 3]

    def make(q: np.ndarray, flat: np.ndarray, scene: Scene) -> None:
        T = np.eye(4)
        scene.links.append(np.stack([np.zeros(3), anchors[0]]))
        scene.link_names.append("base")
        for i in range(n):
            R, p = T[:3, :3], T[:3, 3]
            at = carry(T, anchors[i])
            axis = R @ (vs[i] if kinds[i] == "prismatic" else omegas[i])
            scene.joints.append((kinds[i], at, [axis]))
            if twists:
                w = R @ omegas[i]
                s6 = np.concatenate([w, np.cross(p, w) + R @ vs[i]])
                scene.screws.append((0, s6, at, f"$_{i + 1}"))
            T = T @ np.asarray(exps[i](float(q[i])), dtype=float)
            if kinds[i] == "prismatic":
                scene.sliders.append(np.stack([at, carry(T, anchors[i])]))
            scene.links.append(np.stack([carry(T, anchors[i]), carry(T, anchors[i + 1])]))
            scene.link_names.append(f"link {i + 1}")
        scene.frame = T @ M
        scene.anchor = scene.frame[:3, 3]                   # a couple on the tool: at the flange

    return make, n


def _joint_parts(joint: Joint, packer: _Packer, name: str) -> tuple[str, Any, list[slice], Any]:
    p = _point(joint)
    ps = packer.add(p, name) if p is not None else None
    dirs = [packer.add(d, name) for d in _directions(joint)]
    quad = None
    if isinstance(joint, Parallelogram):
        p1, p2, q1 = joint.args
        quad = packer.add(Matrix.hstack(p1, p2, q1 + p2 - p1, q1).T, name)
    return _KIND_OF[type(joint)], ps, dirs, quad


def _unit(v: np.ndarray) -> np.ndarray:
    n = float(np.linalg.norm(v))
    return v / n if n > 0 else v


def _place_joints(parts: list, flat: np.ndarray, scene: Scene) -> list[np.ndarray | None]:
    """Append the joints' glyphs; return each joint's point (a prismatic joint's: None)."""
    out: list[np.ndarray | None] = []
    for _, ps, _, quad in parts:
        out.append(None if ps is None else flat[ps])
        if quad is not None:
            q = flat[quad].reshape(4, 3)
            scene.links.append(np.vstack([q, q[:1]]))
            scene.link_names.append("parallelogram")
    return out


def _fill_prismatic(points: list[np.ndarray | None]) -> list[np.ndarray]:
    """A prismatic joint's point: midway between the nearest joints with points on each side."""
    known = {i: p for i, p in enumerate(points) if p is not None}
    out = []
    for i, p in enumerate(points):
        if p is not None:
            out.append(p)
            continue
        before = [known[k] for k in known if k < i]
        after = [known[k] for k in known if k > i]
        ends = ([before[-1]] if before else []) + ([after[0]] if after else [])
        out.append(np.mean(ends, axis=0) if ends else np.zeros(3))
    return out


def _glyphs(parts: list, points: list[np.ndarray], flat: np.ndarray, scene: Scene) -> None:
    for (kind, _, dirs, _), p in zip(parts, points, strict=True):
        scene.joints.append((kind, p, [_unit(flat[d]) for d in dirs]))


def _parallel_maker(mech: ParallelMechanism, packer: _Packer):
    limbs = [[_joint_parts(j, packer, f"limbs[{i}].joints[{k}]") for k, j in enumerate(limb.joints)]
             for i, limb in enumerate(mech.limbs)]

    def make(q: np.ndarray, flat: np.ndarray, scene: Scene) -> None:
        firsts, lasts = [], []
        for i, parts in enumerate(limbs):
            pts = _fill_prismatic(_place_joints(parts, flat, scene))
            _glyphs(parts, pts, flat, scene)
            scene.links.append(np.stack(pts))
            scene.link_names.append(f"limb {i + 1}")
            firsts.append(pts[0])
            lasts.append(pts[-1])
        scene.anchor = np.mean(lasts, axis=0) if lasts else None     # the platform's centre
        for name, ring in (("base", firsts), ("platform", lasts)):
            if len(ring) >= 3:
                scene.solids.append(np.stack(ring))
            elif len(ring) == 2:
                scene.links.append(np.stack(ring))
                scene.link_names.append(name)

    return make


def _mechanism_maker(mech: Mechanism, packer: _Packer):
    triples = [(a, b, _joint_parts(j, packer, f"joints[{k}]"))
               for k, (a, b, j) in enumerate(mech.joints)]
    links = list(mech.links)

    def make(q: np.ndarray, flat: np.ndarray, scene: Scene) -> None:
        parts = [t[2] for t in triples]
        pts = _place_joints(parts, flat, scene)
        # a prismatic joint: midway between the other joints of its two links
        for k, (a, b, _) in enumerate(triples):
            if pts[k] is None:
                near = [p for m, (c, d, _) in enumerate(triples)
                        if m != k and (p := pts[m]) is not None and {c, d} & {a, b}]
                pts[k] = np.mean(near, axis=0) if near else np.zeros(3)
        full = [p for p in pts if p is not None]
        _glyphs(parts, full, flat, scene)
        # a couple: at the centre of the platform's joints (a link named "platform"), else of all
        on = [full[k] for k, (a, b, _) in enumerate(triples) if "platform" in (a, b)] or full
        scene.anchor = np.mean(on, axis=0) if on else None
        for link in links:
            ring = [full[k] for k, (a, b, _) in enumerate(triples) if link in (a, b)]
            if len(ring) < 2:
                continue
            # the base, and a link named "platform", as a flat solid through its joints (in the
            # order of the mechanism's joints)
            if (link == mech.base or link == "platform") and len(ring) >= 3:
                scene.solids.append(np.stack(ring))
                continue
            scene.links.append(np.stack(ring + ([ring[0]] if len(ring) >= 3 else [])))
            scene.link_names.append(str(link))

    return make


def _anchor_points(anchor: Any, names: list[str], packer: _Packer) -> tuple[Any, dict[int, slice]]:
    """``anchor=`` as (a slice for every group, or None; {group index: slice})."""
    if anchor is None:
        return None, {}
    if isinstance(anchor, Mapping):
        out = {}
        for k, p in anchor.items():
            if k not in names:
                raise ValueError(f"anchor: {k!r} is not a group of screws= (groups: "
                                 f"{', '.join(map(repr, names)) or 'none'})")
            out[names.index(k)] = _anchor_point(p, f"anchor[{k!r}]", packer)
        return None, out
    return _anchor_point(anchor, "anchor", packer), {}


def _anchor_point(p: Any, name: str, packer: _Packer) -> slice:
    check_no_strings(p, name)
    try:
        m = Matrix(p)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{name}: expected a point (three coordinates), got {p!r}") from exc
    if m.shape not in ((3, 1), (1, 3)):
        raise ValueError(f"{name}: expected a point (three coordinates), got shape {m.shape}")
    return packer.add(m, name)


def scene_maker(obj: Any, *, subs: dict, variables: tuple[Symbol, ...], screws: Any,
                twists: bool, cylindroid: Any = None, anchor: Any = None
                ) -> tuple[Callable[[np.ndarray], Scene], list[ScrewGroup], int]:
    """``(make, groups, n)``: ``make(values)`` gives the :class:`Scene` at ``n`` values.

    ``anchor``: where the couples (and translations) of the placed screws are drawn, a point
    (numbers, or expressions in ``variables``) or a dict of group name -> point; by default
    the body's own point (a chain's flange, a parallel mechanism's platform centre, a graph
    mechanism's link ``"platform"``), else the scene's centre.
    """
    groups_in = check_screw_groups(screws)
    packer = _Packer(variables, subs)
    groups: list[ScrewGroup] = []
    if isinstance(obj, Chain):
        if twists:
            groups.append(ScrewGroup("joint twists", "twist"))
        body, n = _chain_maker(obj, subs, twists, packer)
        if variables and len(variables) != n:
            raise ValueError(f"variables: expected {n} symbols (one per joint of the chain), "
                             f"got {len(variables)}")
    elif isinstance(obj, (ParallelMechanism, Mechanism)):
        if twists:
            raise ValueError("twists: joint twists are drawn for a Chain; pass a mechanism's "
                             "screw systems in screws={...}")
        body = (_parallel_maker(obj, packer) if isinstance(obj, ParallelMechanism)
                else _mechanism_maker(obj, packer))
        n = len(variables)
    elif isinstance(obj, (Screw, ScrewSystem)) or (
            isinstance(obj, Sequence) and not isinstance(obj, (str, bytes))):
        if twists:
            raise ValueError("twists: joint twists are drawn for a Chain")
        groups_in = [("screws", _screws(obj, "obj")), *groups_in]

        def body(q: np.ndarray, flat: np.ndarray, scene: Scene) -> None:
            return None

        n = len(variables)
    else:
        raise TypeError("obj: expected a Chain, ParallelMechanism, Mechanism, Screw, "
                        f"ScrewSystem or a list of screws, got {type(obj).__name__}")
    placed = []
    for name, ss in groups_in:
        g = len(groups)
        groups.append(ScrewGroup(name, _family(ss)))
        for k, s in enumerate(ss):
            placed.append((g, packer.add(s.matrix, f"screws[{name!r}][{k}]"), f"{name}[{k}]"))
    every, per_group = _anchor_points(anchor, [g.name for g in groups], packer)
    pair = None
    if cylindroid is not None:
        members = _screws(cylindroid, "cylindroid")
        if len(members) != 2:
            raise ValueError("cylindroid: expected two screws (the cylindroid of the "
                             f"two-system they span), got {len(members)}")
        pair = [packer.add(m.matrix, f"cylindroid[{k}]") for k, m in enumerate(members)]
    packer.compile()

    def make(q: np.ndarray) -> Scene:
        flat = packer(q)
        scene = Scene()
        body(q, flat, scene)
        if every is not None:
            scene.anchor = flat[every]
        scene.anchors = {g: flat[sl] for g, sl in per_group.items()}
        for g, sl, label in placed:
            scene.screws.append((g, flat[sl], None, label))
        if pair is not None:
            scene.cylindroid = cylindroid_rulings(flat[pair[0]], flat[pair[1]])
        return scene

    return make, groups, n


def finite(values: np.ndarray, name: str) -> np.ndarray:
    """``values`` as finite floats (``ValueError`` naming ``name`` otherwise)."""
    if not np.all(np.isfinite(values)):
        raise ValueError(f"{name}: expected finite numbers, got {values}")
    return values

