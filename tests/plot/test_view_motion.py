"""Views that move: the Delta along a platform path, live redraws, the rigid 3-RPS at a singular pose.

The Delta's frames are checked against its geometry (each rod keeps its length 2 sqrt 2 and each
parallelogram stays one, Clavel's Delta as in notebook 11), the live redraw against the exact
space Jacobian of the UR5 (its columns' axes through the drawn joints, Lynch & Park §5.1.1),
and the rigid 3-RPS against its constraints (a rigid platform, each pivot in its R joint's plane)
and its singular pose against the determinant of its six wrenches; each check is shown to
reject a wrong picture.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("plotly")

from sympy import Rational, cancel, pi, symbols  # noqa: E402

from screwsym.motion.chain import ur5  # noqa: E402
from screwsym.plot import Live, live, view  # noqa: E402
from screwsym.plot.models import delta, three_rps  # noqa: E402

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
    # the platform, a solid triangle through its three pivots p + e_i (the e_i 120 degrees
    # apart, Clavel's: their sum is 0), moves: its centre follows the path
    s = names.index("solids")
    platforms = [np.column_stack([fr.data[s].x, fr.data[s].y, fr.data[s].z])[3:]
                 for fr in fig.frames]                         # the base's 3 vertices first
    assert fig.data[s].type == "mesh3d" and all(len(p) == 3 for p in platforms)
    for tri, row in zip(platforms, rows, strict=True):
        assert np.allclose(tri.mean(axis=0), row[:3], atol=1e-9)
        sides = np.linalg.norm(tri - np.roll(tri, 1, axis=0), axis=1)
        assert np.allclose(sides, np.sqrt(3), atol=1e-9)          # equilateral, legs 120 apart
    assert not np.allclose(platforms[0], platforms[3])


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
    # the closed form against the symbolic joints: the rods' lengths exact at home
    home = dict(zip(robot.variables, (0, 0, -3, pi / 4, pi / 4, pi / 4), strict=True))
    joints = robot.mechanism.joints
    ends = [(joints[7 * i + 2][2].args[0], joints[7 * i + 3][2].args[0]) for i in range(3)]
    assert [(a - b).subs(home).dot((a - b).subs(home)) for a, b in ends] == [8, 8, 8]
    off = (ends[0][0] - ends[0][1]).subs({**home, robot.variables[3]: pi / 3})    # ... can fail
    assert abs(float(off.dot(off)) - 8) > 0.1
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
        with pytest.raises(ImportError, match=r"ipywidgets and anywidget: the live extra"):
            lv.widget()
        return
    box = lv.widget()
    fig, sliders = box.children[0], box.children[1:]
    before = fig.data[0].x
    sliders[1].value = 0.7
    assert fig.data[0].x != before


# the rigid 3-RPS of notebook 13 (Tsai 1999; Lee & Shah 1988): tilted about y by the Rodrigues
# parameter g at height z, det of its six wrenches has the factor g^4 z + 6 g^3 + 4 g - z, which
# is -(1 + g^2)^2 n . d1 (zero: leg 1 in the platform's plane): zero at z = 44/15 for g = 1/2


def test_the_rigid_3rps_keeps_its_platform_and_its_legs_constraints():
    z, gx, gy = symbols("z g_x g_y", real=True)
    m = three_rps(z, (gx, gy))
    pivots = [limb.joints[2].args[0] for limb in m.limbs]
    sides = [(pivots[i] - pivots[j]).dot(pivots[i] - pivots[j]) for i, j in ((0, 1), (1, 2), (2, 0))]
    assert [cancel(s) for s in sides] == [3, 3, 3]                 # rigid: side sqrt(3)
    for limb, p in zip(m.limbs, pivots, strict=True):             # each pivot in its R's plane
        foot, axis = limb.joints[0].args
        assert cancel(axis.dot(p - foot)) == 0
    wrong = three_rps(z, (gx, gy), platform=Rational(3, 2))        # ... the checks can fail
    q = wrong.limbs[0].joints[2].args[0] - wrong.limbs[1].joints[2].args[0]
    assert cancel(q.dot(q)) != 3
    with pytest.raises(ValueError, match="tilt"):
        three_rps(2, (0.5, 0))
    with pytest.raises(ValueError, match="platform"):
        three_rps(2, (0, 0), platform=-1)


def test_the_3rps_singular_pose_is_singular_and_drawn():
    height, gy = Rational(44, 15), symbols("g_y", real=True)
    regular, singular = three_rps(height, (0, Rational(1, 3))), three_rps(height, (0, Rational(1, 2)))
    assert regular.singularities().rows() == []
    # type II: J_x loses rank (5) while the constraints keep theirs
    assert singular.singularities().rows() == [("actuation", "", True, 5)]
    assert three_rps(3, (0, Rational(1, 2))).singularities().rows() == []   # the check can fail
    pivots = [limb.joints[2].args[0] for limb in singular.limbs]
    normal = (pivots[1] - pivots[0]).cross(pivots[2] - pivots[0])
    assert normal.dot(pivots[0] - singular.limbs[0].joints[0].args[0]) == 0   # leg 1 in plane
    m = three_rps(height, (0, gy))
    screws = {"constraint wrenches": m.constraints, "actuation wrenches": m.actuation_wrenches()}
    v = view(m, [0.5], variables=[gy], screws=screws)
    assert v.kinds["screws"] == 6 and v.kinds["solids"] == 2
