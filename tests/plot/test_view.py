"""Tests of screwsym.plot.view: the plotly scene read back against the kinematics.

The joints' places are checked against the exact space Jacobian (its columns are the joint
axes at ``q``, Lynch & Park, *Modern Robotics* §5.1.1) and the tool frame against
``Chain.forward`` and modern_robotics' ``FKinSpace`` (an independent peer); each check is
shown to reject a view drawn at other joint values.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("plotly")

from sympy import Rational, pi, sqrt, symbols  # noqa: E402

from screwsym import Chain, Transform, Twist, Wrench  # noqa: E402
from screwsym.motion.chain import ur5  # noqa: E402
from screwsym.plot import View, live, view  # noqa: E402
from screwsym.systems.joints import P, R, S  # noqa: E402
from screwsym.systems.linkage import Mechanism  # noqa: E402
from screwsym.systems.parallel import Limb, ParallelMechanism  # noqa: E402

Q_EXACT = (0, pi / 6, -pi / 3, pi / 4, pi / 2, -pi / 12)
Q = [float(x) for x in Q_EXACT]
EVIL = "</script><script>alert(1)</script>"


def trace(fig, name: str):
    found = [t for t in fig.data if (t.meta or {}).get("screwsym") == name]
    assert len(found) == 1, f"no single trace {name!r}"
    return found[0]


def points(t) -> np.ndarray:
    return np.array([p for p in zip(t.x, t.y, t.z, strict=True) if p[0] is not None], dtype=float)


def segments(t) -> list[np.ndarray]:
    out, cur = [], []
    for p in zip(t.x, t.y, t.z, strict=True):
        if p[0] is None:
            out.append(np.array(cur, dtype=float))
            cur = []
        else:
            cur.append(p)
    return out


def on_axis(point: np.ndarray, column) -> float:
    """Distance from ``point`` to the axis of the twist ``column`` (6 numbers, ray order)."""
    w = np.array([float(x) for x in column[:3]])
    v = np.array([float(x) for x in column[3:]])
    foot = np.cross(w, v) / w.dot(w)
    return float(np.linalg.norm(np.cross(point - foot, w / np.linalg.norm(w))))


def joints_on_jacobian_axes(v: View, chain: Chain, q_exact) -> bool:
    J = chain.jacobian(list(q_exact))
    pts = points(trace(v.figure, "joint:revolute"))
    return len(pts) == J.shape[1] and all(
        on_axis(p, J[:, i]) < 1e-9 for i, p in enumerate(pts))


def tool_at(v: View, chain: Chain, q_exact) -> bool:
    T = chain.forward(list(q_exact)).matrix
    p = np.array([float(x) for x in T[:3, 3]])
    frame = segments(trace(v.figure, "frame"))
    R = np.array(T[:3, :3].tolist(), dtype=float)
    return all(np.allclose(s[0], p, atol=1e-12) for s in frame) and all(
        np.allclose((s[1] - s[0]) / np.linalg.norm(s[1] - s[0]), R[:, c], atol=1e-12)
        for c, s in enumerate(frame))


def test_ur5_joints_lie_on_the_space_jacobians_axes():
    arm = ur5()
    v = view(arm, Q, twists=True)
    assert joints_on_jacobian_axes(v, arm, Q_EXACT)
    assert tool_at(v, arm, Q_EXACT)
    # the checks reject a view at other joint values (the last joint only moves the tool)
    wrong = view(arm, [Q[0], Q[1] + 0.01, *Q[2:]], twists=True)
    assert not joints_on_jacobian_axes(wrong, arm, Q_EXACT)
    assert not tool_at(view(arm, [*Q[:5], Q[5] + 0.01]), arm, Q_EXACT)


def test_ur5_tool_frame_matches_modern_robotics():
    mr = pytest.importorskip("modern_robotics")
    arm = ur5()
    M = np.array(arm.home.matrix.tolist(), dtype=float)
    Slist = np.array([[float(x) for x in t.matrix] for t in arm.twists]).T
    T = mr.FKinSpace(M, Slist, np.array(Q))
    frame = segments(trace(view(arm, Q).figure, "frame"))
    assert np.allclose(frame[0][0], T[:3, 3], atol=1e-12)


def test_ur5_counts_and_twist_axes():
    arm = ur5()
    v = view(arm, Q, twists=True)
    k = v.kinds
    assert (k["joint:revolute"], k["joint:prismatic"], k["joint:helical"]) == (6, 0, 0)
    assert k["links"] == 7 and k["screws"] == 6 and k["frame"] == 3
    fig = v.figure
    assert len(fig.data) == 7 and v.frames == 0
    # the drawn twist axes are the Jacobian's columns: one dotted axis per joint on its line
    J = arm.jacobian(list(Q_EXACT))
    axes = segments(trace(fig, "screw-axes:0"))
    assert len(axes) == 6
    for i, seg in enumerate(axes):
        assert max(on_axis(p, J[:, i]) for p in seg) < 1e-9
    heads = trace(fig, "screw-heads:0")
    assert len(heads.x) == 6                        # one head each: rotations, no couple
    # the links join the joints, and the last ends at the flange
    links = segments(trace(fig, "links"))
    joints = points(trace(fig, "joint:revolute"))
    for i in range(1, 6):
        assert np.allclose(links[i][1], joints[i], atol=1e-12)
    T = arm.forward(list(Q_EXACT)).matrix
    assert np.allclose(links[6][1], [float(x) for x in T[:3, 3]], atol=1e-12)


def test_joint_kinds_and_a_couple_and_a_force():
    # revolute, prismatic, helical (pitch 1/10) in one chain
    chain = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                   Twist.translation([1, 0, 0]),
                   Twist.screw_motion([0, 0, 1], point=[1, 0, 0], pitch=Rational(1, 10))],
                  Transform.translation([1, 0, 1]))
    v = view(chain, [0.2, 0.5, 0.3],
             screws={"load": [Wrench([0, 0, -1], [0, 1, 0]), Wrench([0, 0, 0], [1, 0, 0])]})
    k = v.kinds
    assert (k["joint:revolute"], k["joint:prismatic"], k["joint:helical"]) == (1, 1, 1)
    assert k["sliders"] == 1 and k["screws"] == 2
    fig = v.figure
    # the force has one head, the couple two (a free vector), in traces of their own and
    # legend entries of their own; only the force has an axis
    assert len(trace(fig, "screw-heads:0").x) == 1
    assert len(trace(fig, "screw-couple-heads:0").x) == 2
    assert len(segments(trace(fig, "screw-axes:0"))) == 1
    assert trace(fig, "screw-shafts:0").name == "load: forces"
    couples = trace(fig, "screw-couples:0")
    assert couples.name.startswith("load: couples") and couples.line.dash == "dash"
    assert k["couples"] == 1
    # the couple is drawn on the body it acts on: by default the chain's flange
    T = chain.forward([Rational(1, 5), Rational(1, 2), Rational(3, 10)]).matrix
    assert np.allclose(segments(couples)[0][0], [float(x) for x in T[:3, 3]], atol=1e-12)
    # the prismatic stroke is q2 = 0.5 long, along the x-axis turned by q1
    stroke = segments(trace(fig, "sliders"))[0]
    assert np.allclose(stroke[1] - stroke[0], 0.5 * np.array([math.cos(0.2), math.sin(0.2), 0]))


def test_a_pitch_gets_a_helix_and_a_line_none():
    v = view([Twist([0, 0, 1], [0, 0, 0]), Twist([0, 0, 1], [0, 0, 2])])
    shafts = segments(trace(v.figure, "screw-shafts:0"))
    assert [len(s) for s in shafts][:1] == [2] and len(shafts) == 3   # arrow; arrow + helix
    helix = shafts[2]
    rise = helix[-1] - helix[0]
    assert rise[2] > 0 and abs(rise[0]) < 1e-9                 # right-handed: h = 2 > 0


def _rps_leg(e, rho, h, base=2):
    b = [base * c for c in e]
    top = [b[0] + rho * e[0], b[1] + rho * e[1], h]
    return Limb(R(b, [-e[1], e[0], 0]), P([t - s for t, s in zip(top, b, strict=True)]), S(top),
                actuated=1)


E = [[1, 0, 0], [-Rational(1, 2), sqrt(3) / 2, 0], [-Rational(1, 2), -sqrt(3) / 2, 0]]


def test_rps_path_recomputes_the_wrenches_per_frame():
    h = symbols("h1:4", real=True)
    rps = ParallelMechanism(*(_rps_leg(e, -Rational(1, 2), hi) for e, hi in zip(E, h, strict=True)))
    path = [[2, 2, 2], [2, 2, 3]]
    v = view(rps, path=path, variables=h,
             screws={"constraint": rps.constraints, "actuation": rps.actuation_wrenches()})
    k = v.kinds
    assert (k["joint:revolute"], k["joint:prismatic"], k["joint:spherical"]) == (3, 3, 3)
    assert k["solids"] == 2 and k["screws:0"] == 3 and k["screws:1"] == 3 and v.frames == 2
    fig = v.figure
    assert len(fig.frames) == 2 and len(fig.layout.sliders[0].steps) == 2
    names = [(t.meta or {}).get("screwsym") for t in fig.data]
    sph = names.index("joint:spherical")
    for frame, hs in zip(fig.frames, path, strict=True):
        z = sorted(frame.data[sph].z)
        assert np.allclose(z, sorted(hs))
    # each actuation wrench's axis (the leg's line) passes through its sphere centre at h3 = 3
    top3 = np.array([-1 + 0.25, -math.sqrt(3) + math.sqrt(3) / 4, 3.0])
    axes = segments(fig.frames[1].data[names.index("screw-axes:1")])
    W = rps.actuation_wrenches()[2].subs(dict(zip(h, (2, 2, 3), strict=True)))
    assert any(max(on_axis(p, W.matrix) for p in seg) < 1e-9 for seg in axes)
    assert on_axis(top3, W.matrix) < 1e-9


def test_mechanism_graph_and_escaped_names():
    z = [0, 0, 1]
    x = symbols(EVIL, real=True)
    four = Mechanism([("ground", EVIL, R([0, 0, 0], z)), (EVIL, "coupler", R([1, x, 0], z)),
                      ("coupler", "rocker", R([3, 3, 0], z)), ("rocker", "ground", R([4, 0, 0], z))],
                     base="ground")
    v = view(four, path=[[1.5], [2.0]], variables=[x], title=EVIL,
             screws={EVIL: four.relative_twists("coupler").subs(x, 2)})
    assert v.kinds["joint:revolute"] == 4
    page = v._repr_html_()
    assert EVIL not in page and "<script>alert(1)" not in page
    assert "&lt;/script&gt;" in json_unescaped(page)


def json_unescaped(page: str) -> str:
    return page.replace("\\u003c", "<").replace("\\u003e", ">").replace("\\u002f", "/")


def test_to_html_is_one_file_with_plotly_inside(tmp_path):
    out = view(ur5(), Q).to_html(tmp_path / "ur5.html")
    page = open(out, encoding="utf-8").read()
    assert "<script src=" not in page and "Plotly.newPlot" in page
    assert len(page) > 1_000_000                     # plotly.js itself is in the file
    assert 'data-screwsym-errors' in page


def test_site_mode_leaves_plotlyjs_to_the_page_but_not_in_to_html(tmp_path, monkeypatch):
    v = view(ur5(), Q)
    banner = "* plotly.js v"                          # the first lines of plotly.min.js
    monkeypatch.delenv("SCREWSYM_VIEW_PLOTLYJS", raising=False)
    inline = v._repr_mimebundle_()["text/html"]
    assert banner in inline and v._repr_html_() == inline
    monkeypatch.setenv("SCREWSYM_VIEW_PLOTLYJS", "inline")
    assert v._repr_mimebundle_()["text/html"] == inline
    monkeypatch.setenv("SCREWSYM_VIEW_PLOTLYJS", "site")
    site = v._repr_mimebundle_()["text/html"]
    assert banner not in site and "<script src=" not in site and len(site) < 100_000
    assert site == v._repr_html_()
    # the same figure, and a console error where the page has no Plotly
    assert site.count("Plotly.newPlot(") == 1 and "typeof Plotly === 'undefined'" in site
    assert inline[inline.index("Plotly.newPlot("):] == site[site.index("Plotly.newPlot("):]
    page = open(v.to_html(tmp_path / "ur5.html"), encoding="utf-8").read()
    assert banner in page and "<script src=" not in page       # to_html stays self-contained
    monkeypatch.setenv("SCREWSYM_VIEW_PLOTLYJS", "cdn")
    with pytest.raises(ValueError, match="SCREWSYM_VIEW_PLOTLYJS.*'cdn'"):
        v._repr_mimebundle_()


def test_the_view_is_immutable_and_its_figure_a_copy():
    v = view(ur5(), Q)
    with pytest.raises(AttributeError):
        v._json = "{}"
    fig = v.figure
    fig.data[0].x = (0.0,)
    assert len(v.figure.data[0].x) > 1
    bundle = v._repr_mimebundle_()
    assert set(bundle) == {"text/html", "text/plain"}
    assert "Plotly.newPlot" in bundle["text/html"] and "<script src=" not in bundle["text/html"]


@pytest.mark.parametrize(("kwargs", "error", "match"), [
    ({"q": [0, 0]}, ValueError, "q: expected an array of shape"),
    ({"q": [0] * 5 + ["a"]}, TypeError, "q: expected numbers"),
    ({"q": [0] * 5 + [float("nan")]}, ValueError, "q: expected finite"),
    ({"path": [[0] * 6, [0] * 5]}, TypeError, "path: expected numbers"),
    ({"path": [0] * 6}, ValueError, "path: expected an array of shape"),
    ({"q": [0] * 6, "path": [[0] * 6]}, ValueError, "q, path"),
    ({"variables": ["q1"]}, TypeError, "variables\\[0\\]"),
    ({"subs": "x=1"}, TypeError, "subs"),
    ({"subs": {symbols("L"): "1"}}, TypeError, "subs: strings are never evaluated"),
    ({"subs": {1: 1}}, TypeError, "subs: expected SymPy symbols"),
    ({"twists": 1}, TypeError, "twists"),
    ({"screws": {1: Twist([0, 0, 1], [0, 0, 0])}}, TypeError, "screws"),
    ({"screws": "S"}, TypeError, "screws"),
    ({"height": 10}, ValueError, "height"),
    ({"camera": "top"}, TypeError, "camera"),
    ({"camera": [1, "a", 0]}, TypeError, "camera"),
    ({"camera": [0, 0, 0]}, ValueError, "camera"),
    ({"camera": [1, 2]}, ValueError, "camera"),
    ({"camera": [1, float("inf"), 0]}, ValueError, "camera"),
])
def test_bad_input(kwargs, error, match):
    with pytest.raises(error, match=match):
        view(ur5(), **kwargs)


def test_the_camera_is_where_the_view_looks_from():
    v = view(ur5(), camera=(1.8, 1.1, 0.4))
    assert v.figure.layout.scene.camera.eye.to_plotly_json() == {"x": 1.8, "y": 1.1, "z": 0.4}
    assert view(ur5()).figure.layout.scene.camera.eye.x is None      # plotly's default
    lv = live(ur5(), camera=[2, 0, 0])
    assert lv.figure().layout.scene.camera.eye.x == 2
    with pytest.raises(ValueError, match="camera"):
        live(ur5(), camera=[0, 0, 0])


def test_bad_objects_and_symbols():
    with pytest.raises(TypeError, match="obj: expected a Chain"):
        view(3)
    L = symbols("L", positive=True)
    arm = Chain([Twist.rotation([0, 0, 1], point=[L, 0, 0])])
    with pytest.raises(ValueError, match="give L numbers"):
        view(arm, [0])
    assert view(arm, [0], subs={L: 1}).kinds["joint:revolute"] == 1
    assert view(arm, [0], subs={L: 0.5}).kinds["joint:revolute"] == 1
    with pytest.raises(ValueError, match="give L numbers in subs"):
        view(Twist([0, 0, 1], [L, 0, 0]))
    rps = ParallelMechanism(*(_rps_leg(e, -Rational(1, 2), 2) for e in E))
    with pytest.raises(ValueError, match="twists"):
        view(rps, twists=True)


def test_to_png_bad_input(tmp_path):
    v = view(ur5(), Q)
    with pytest.raises(FileNotFoundError, match="browser: no Chromium found"):
        v.to_png(tmp_path / "a.png", browser="/nonexistent/chromium")
    with pytest.raises(ValueError, match="width"):
        v.to_png(tmp_path / "a.png", width=10)
    with pytest.raises(ValueError, match="timeout"):
        v.to_png(tmp_path / "a.png", timeout=0)
    with pytest.raises(TypeError, match="path"):
        v.to_png(3)


def test_slider_labels_have_no_negative_zero():
    v = view(ur5(), path=[[-0.0] * 6, [0.5] * 6])
    labels = [s.label for s in v.figure.layout.sliders[0].steps]
    assert labels[0] == "q1=0, q2=0, q3=0, q4=0, q5=0, q6=0" and "q6=0.5" in labels[1]


def test_a_robot_from_its_urdf_file_in_floats():
    pytest.importorskip("defusedxml")
    from screwsym.motion.urdf import sample_urdf

    panda = Chain.from_urdf(sample_urdf("panda.urdf"), tip="panda_leftfinger", angles="exact")
    q = [0.1, -0.3, 0.2, -1.5, 0.1, 1.2, 0.4, 0.02]
    v = view(panda, q, twists=True)
    assert (v.kinds["joint:revolute"], v.kinds["joint:prismatic"], v.kinds["sliders"]) == (7, 1, 1)
    J = panda.jacobian(q)
    axes = segments(trace(v.figure, "screw-axes:0"))       # the seven rotations have axes
    assert len(axes) == 7
    for i, seg in enumerate(axes):
        assert max(on_axis(p, J[:, i]) for p in seg) < 1e-9
    stroke = segments(trace(v.figure, "sliders"))[0]
    assert np.isclose(np.linalg.norm(stroke[1] - stroke[0]), 0.02)


def cylindroid_matches(v: View, h1: float, h2: float) -> bool:
    """The drawn rulings against the cylindroid of (1,0,0; h1,0,0) and (0,1,0; 0,h2,0): the
    axis of cos t $_1 + sin t $_2 lies at height z = (h2 - h1) sin t cos t, along
    (cos t, sin t, 0), with pitch h1 cos^2 t + h2 sin^2 t (Hunt 1978, §12.2, eq. of the
    cylindroid z = (h_b - h_a) sin t cos t; Ball 1900, §22)."""
    s = trace(v.figure, "cylindroid")
    t = np.linspace(0, math.pi, len(s.z))
    x, y, z = (np.array(c, dtype=float) for c in (s.x, s.y, s.z))
    d = np.stack([x[:, 1] - x[:, 0], y[:, 1] - y[:, 0]], axis=1)
    d /= np.linalg.norm(d, axis=1)[:, None]
    return (np.allclose(z[:, 0], (h2 - h1) * np.sin(t) * np.cos(t), atol=1e-12)
            and np.allclose(z[:, 1], z[:, 0], atol=1e-12)
            and np.allclose(np.abs(d[:, 0] * np.cos(t) + d[:, 1] * np.sin(t)), 1, atol=1e-12)
            and np.allclose(np.array(s.surfacecolor, dtype=float)[:, 0],
                            h1 * np.cos(t) ** 2 + h2 * np.sin(t) ** 2, atol=1e-12))


def test_the_cylindroid_of_two_screws():
    s1, s2 = Twist([1, 0, 0], [1, 0, 0]), Twist([0, 1, 0], [0, Rational(-1, 2), 0])
    v = view([s1, s2], cylindroid=[s1, s2])
    assert v.kinds["cylindroid"] == 73
    assert len(v.figure.data) == 4                  # the surface and the screws' three traces
    assert cylindroid_matches(v, 1, -0.5)
    assert not cylindroid_matches(v, -0.5, 1)              # the check sees a swapped pair
    # a symbolic pitch along a path: the surface is recomputed per frame
    h = symbols("h", real=True)
    w = view([s1], path=[[0.0], [2.0]], variables=[h],
             cylindroid=[s1, Twist([0, 1, 0], [0, h, 0])])
    fig = w.figure
    k = [(t.meta or {}).get("screwsym") for t in fig.data].index("cylindroid")
    for frame, hv in zip(fig.frames, (0.0, 2.0), strict=True):
        z = np.array(frame.data[k].z, dtype=float)[:, 0]
        t = np.linspace(0, math.pi, len(z))
        assert np.allclose(z, (hv - 1) * np.sin(t) * np.cos(t), atol=1e-12)
    with pytest.raises(ValueError, match="cylindroid: expected two screws"):
        view(s1, cylindroid=[s1, s2, s1])


def _planar_rpr():
    z = [0, 0, 1]
    base, platform = [(3, -1), (-1, 3), (-2, -3)], [(1, 0), (0, 1), (-1, -1)]
    return ParallelMechanism(*(Limb(R([a[0], a[1], 0], z), P([b[0] - a[0], b[1] - a[1], 0]),
                                    R([b[0], b[1], 0], z), actuated=1)
                               for a, b in zip(base, platform, strict=True)))


def test_couples_are_drawn_at_the_platform_centre_or_the_given_anchor():
    rpr = _planar_rpr()
    wrenches = {"actuation": rpr.actuation_wrenches(), "constraint": rpr.constraints.basis()}
    v = view(rpr, screws=wrenches)
    fig = v.figure
    # the planar mechanism's constraints: a force along z and two couples (Hunt 1978, §12.4)
    assert v.kinds["couples"] == 2 and v.kinds["couples:1"] == 2
    starts = [s[0] for s in segments(trace(fig, "screw-couples:1"))]
    centre = np.mean([[1, 0, 0], [0, 1, 0], [-1, -1, 0]], axis=0)      # the platform's joints
    assert all(np.allclose(p, centre, atol=1e-12) for p in starts)
    # the check fails for a view whose couples are elsewhere
    moved = view(rpr, screws=wrenches, anchor={"constraint": [5, 5, 1]})
    starts = [s[0] for s in segments(trace(moved.figure, "screw-couples:1"))]
    assert all(np.allclose(p, [5, 5, 1]) for p in starts)
    assert not np.allclose(starts[0], centre)
    # the actuation forces keep one legend entry (no couples in that group)
    assert trace(fig, "screw-shafts:0").name == "actuation"
    assert not [t for t in fig.data if (t.meta or {}).get("screwsym") == "screw-couples:0"]


def test_a_symbolic_anchor_follows_the_path():
    t = symbols("t", real=True)
    v = view([Wrench([0, 0, 0], [0, 0, 1])], path=[[0], [1]], variables=[t], anchor=[t, 0, 0])
    first = segments(trace(v.figure, "screw-couples:0"))[0][0]
    last = v.figure.frames[1].data[[t_.meta["screwsym"] for t_ in v.figure.data]
                                   .index("screw-couples:0")]
    assert np.allclose(first, 0) and np.isclose(last.x[0], 1.0)


@pytest.mark.parametrize("anchor, error", [
    ([1, 2], ValueError), ("origin", TypeError), ({"nope": [0, 0, 0]}, ValueError),
    ([symbols("a"), 0, 0], ValueError)])
def test_bad_anchors_are_refused(anchor, error):
    with pytest.raises(error, match="anchor"):
        view([Wrench([0, 0, 0], [0, 0, 1])], anchor=anchor)
