"""Views that move: the Delta along a platform path, live redraws, the 3-RPS at a singular pose.

The Delta's frames are checked against its geometry (each rod keeps its length 2 sqrt 2 and each
parallelogram stays one, Clavel's Delta as in notebook 11), the live redraw against the exact
space Jacobian of the UR5 (its columns' axes through the drawn joints, Lynch & Park §5.1.1),
and the 3-RPS singular pose against the determinant of its six wrenches; each check is shown to
reject a wrong picture.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("plotly")

from sympy import Rational, sqrt, symbols  # noqa: E402

from screwsym.motion.chain import ur5  # noqa: E402
from screwsym.plot import Live, live, view  # noqa: E402
from screwsym.plot.models import delta  # noqa: E402
from screwsym.systems.joints import P, R, S  # noqa: E402
from screwsym.systems.parallel import Limb, ParallelMechanism  # noqa: E402

ROD = 2 * np.sqrt(2)


@pytest.fixture(scope="module")
def robot():
    return delta()


def platform_path(k: int = 8) -> np.ndarray:
    s = np.linspace(0, 2 * np.pi, k)
    return np.column_stack([0.5 * np.cos(s), 0.5 * np.sin(s), -2.8 + 0.2 * np.sin(2 * s)])


def named_links(data: dict, names: list[str]) -> dict[str, np.ndarray]:
    """Each link's polyline in a frame's data of the "links" trace, by its hover name."""
    out, cur, name = {}, [], None
    for x, y, z, t in zip(data["x"], data["y"], data["z"], data["hovertext"], strict=True):
        if x is None:
            out[name] = np.array(cur)
            cur = []
        else:
            cur.append((x, y, z))
            name = t
    return out


def rods_keep_their_length(links: dict[str, np.ndarray]) -> bool:
    rods = [p for n, p in links.items() if n.startswith("rod")]
    return len(rods) == 6 and all(abs(np.linalg.norm(p[1] - p[0]) - ROD) < 1e-9 for p in rods)


def test_the_delta_moves_along_its_platform_path(robot):
    rows = robot.configurations(platform_path())
    v = view(robot.mechanism, path=rows, variables=robot.variables)
    fig = v.figure
    names = [t.meta["screwsym"] for t in fig.data]
    k = names.index("links")
    frames = [fr.data[k] for fr in fig.frames]
    assert v.frames == len(rows) == 8
    links = [named_links({"x": f.x, "y": f.y, "z": f.z, "hovertext": f.hovertext}, names)
             for f in frames]
    assert all(rods_keep_their_length(lk) for lk in links)
    # the platform moves: its pivots' centre follows the path (pivot i at p + e_i, sum e_i = 0
    # up to the radial directions' mean (-1/15, 0, 0))
    for lk, row in zip(links, rows, strict=True):
        ring = lk["platform"][:-1]
        assert np.allclose(ring.mean(axis=0), row[:3] + [-1 / 15, 0, 0], atol=1e-9)
    assert not np.allclose(links[0]["platform"], links[3]["platform"])


def test_the_rod_check_rejects_a_wrong_arm_angle(robot):
    rows = robot.configurations(platform_path(2))
    rows[1, 3] += 0.1                                        # leg 1's arm off its solution
    v = view(robot.mechanism, path=rows, variables=robot.variables)
    k = [t.meta["screwsym"] for t in v.figure.data].index("links")
    f = v.figure.frames[1].data[k]
    links = named_links({"x": f.x, "y": f.y, "z": f.z, "hovertext": f.hovertext}, [])
    assert not rods_keep_their_length(links)


def test_the_delta_home_and_an_unreachable_point(robot):
    assert np.allclose(robot.configurations([0, 0, -3])[0, 3:], np.pi / 4)
    with pytest.raises(ValueError, match=r"points\[0\]: the platform cannot reach"):
        robot.configurations([[0, 0, -10]])
    with pytest.raises(ValueError, match="points"):
        robot.configurations([[0, 0]])


def test_live_ur5_redraw_follows_the_jacobian():
    arm = ur5()
    lv = live(arm, twists=True)
    assert isinstance(lv, Live) and [c[0] for c in lv.controls] == [f"q{i}" for i in range(1, 7)]
    q = [0.1, -0.4, 0.9, 0.2, 0.5, -0.3]
    names = [t.meta["screwsym"] for t in lv.figure().data]
    data = lv.redraw(q)
    joints = data[names.index("joint:revolute")]
    pts = np.column_stack([joints["x"], joints["y"], joints["z"]])
    J = np.array(arm.jacobian(q).tolist(), dtype=float)

    def on_axes(pts):
        out = []
        for i, p in enumerate(pts):
            w, v = J[:3, i], J[3:, i]
            foot = np.cross(w, v) / w.dot(w)
            out.append(np.linalg.norm(np.cross(p - foot, w / np.linalg.norm(w))))
        return max(out) < 1e-9

    assert on_axes(pts)
    other = lv.redraw([0.1, -0.4, 0.9, 0.2, 0.5, 0.3])          # ... and fails elsewhere
    assert on_axes(np.column_stack([other[names.index("joint:revolute")][c] for c in "xyz"]))
    moved = lv.redraw([0.6, -0.4, 0.9, 0.2, 0.5, -0.3])
    assert not on_axes(np.column_stack([moved[names.index("joint:revolute")][c] for c in "xyz"]))


def test_live_delta_with_a_solver(robot):
    lv = live(robot.mechanism, variables=robot.variables,
              solve=lambda v: robot.configurations(v)[0],
              controls=[("x", -0.5, 0.5), ("y", -0.5, 0.5), ("z", -3.2, -2.5)], q=[0, 0, -3])
    names = [t.meta["screwsym"] for t in lv.figure().data]
    links = named_links(lv.redraw([0.3, -0.2, -2.7])[names.index("links")], names)
    assert rods_keep_their_length(links)
    with pytest.raises(ValueError, match="q: expected values within"):
        live(robot.mechanism, variables=robot.variables, solve=lambda v: v,
             controls=[("x", -0.5, 0.5), ("y", -0.5, 0.5), ("z", -3.2, -2.5)], q=[0, 0, 0])


@pytest.mark.parametrize("kwargs, error", [
    ({"controls": "q1"}, TypeError), ({"controls": [("q1", 1, 0)]}, ValueError),
    ({"solve": 3}, TypeError), ({"solve": lambda v: v}, ValueError)])
def test_live_refuses_bad_arguments(kwargs, error):
    with pytest.raises(error, match="controls|solve"):
        live(ur5(), **kwargs)


def test_live_widget_needs_ipywidgets():
    lv = live(ur5(), twists=True)
    try:
        import anywidget  # noqa: F401
        import ipywidgets  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match="ipywidgets"):
            lv.widget()
        return
    box = lv.widget()
    fig, sliders = box.children[0], box.children[1:]
    before = fig.data[0].x
    sliders[1].value = 0.7
    assert fig.data[0].x != before


# the 3-RPS of notebook 13 (Tsai 1999): det of its six wrenches is
# -72 (11 h1^2 h2 + 11 h1^2 h3 + 11 h1 h2^2 - 147 h1 h2 h3 + 11 h1 h3^2 + 11 h2^2 h3 + 11 h2 h3^2),
# which with h1 = h2 = 2 is -72 * 4 (11 h3^2 - 125 h3 + 44): zero at h3 = 4/11 and 11
E = [[1, 0, 0], [-Rational(1, 2), sqrt(3) / 2, 0], [-Rational(1, 2), -sqrt(3) / 2, 0]]


def rps(heights):
    def leg(e, h, base=2):
        rho = -Rational(1, 2)
        b = [base * c for c in e]
        top = [b[0] + rho * e[0], b[1] + rho * e[1], h]
        return Limb(R(b, [-e[1], e[0], 0]), P([t - s for t, s in zip(top, b, strict=True)]),
                    S(top), actuated=1)
    return ParallelMechanism(*(leg(e, h) for e, h in zip(E, heights, strict=True)))


def test_the_3rps_singular_pose_is_singular_and_drawn():
    h = symbols("h1:4", real=True)
    regular, singular = rps([2, 2, 2]), rps([2, 2, Rational(4, 11)])
    assert regular.singularities().rows() == []
    # type II: J_x loses rank (5) while the constraints keep theirs
    assert singular.singularities().rows() == [("actuation", "", True, 5)]
    assert rps([2, 2, Rational(5, 11)]).singularities().rows() == []    # the check can fail
    m = rps(h)
    screws = {"constraint wrenches": m.constraints, "actuation wrenches": m.actuation_wrenches()}
    v = view(m, [2, 2, 4 / 11], variables=h, screws=screws)
    assert v.kinds["screws"] == 6 and v.kinds["solids"] == 2
