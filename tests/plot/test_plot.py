"""Tests of screwsym.plot: the geometry of what was drawn, read back from the artists."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
from sympy import Rational, pi, sqrt, symbols  # noqa: E402

from screwsym import LineVector, Screw, Twist, Wrench, common_normal, foot  # noqa: E402
from screwsym.plot import (  # noqa: E402
    find_artists,
    helix_advance,
    plot,
    plot_common_normal,
    plot_couple,
    plot_frame,
    plot_line,
    plot_screw,
    plot_twist,
)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def vertices(artist) -> np.ndarray:
    """The drawn 3D vertex data of a Line3D, as an (n, 3) array."""
    return np.column_stack([np.asarray(c, dtype=float) for c in artist.get_data_3d()])


def the(ax, kind: str) -> np.ndarray:
    found = find_artists(ax, kind)
    assert len(found) == 1, f"expected one {kind!r} artist, found {len(found)}"
    return vertices(found[0])


def as_float(m) -> np.ndarray:
    return np.array([float(e) for e in m], dtype=float)


def distance_to_line(p: np.ndarray, point: np.ndarray, direction: np.ndarray) -> float:
    d = p - point
    return float(np.linalg.norm(np.cross(d, direction)) / np.linalg.norm(direction))


def torsion_sign(pts: np.ndarray) -> float:
    """Sign of the torsion of a polyline: +1 for a right-handed helix, -1 left-handed.

    Torsion is ``(r' x r'') . r''' / |r' x r''|^2``; its sign is the hand of the
    helix whatever the direction of its axis or of travel.
    """
    d1 = np.gradient(pts, axis=0)
    d2 = np.gradient(d1, axis=0)
    d3 = np.gradient(d2, axis=0)
    triple = np.einsum("ij,ij->i", np.cross(d1, d2), d3)[3:-3]
    assert np.all(np.sign(triple) == np.sign(triple[0])), "the helix changes hand"
    return float(np.sign(triple[0]))


def turning_sense(pts: np.ndarray, axis: np.ndarray, center=None) -> float:
    """Sum of the angles swept about ``axis`` through ``center``: > 0 right-handed.

    ``center`` defaults to the centroid of the points.
    """
    c = pts.mean(axis=0) if center is None else np.asarray(center, dtype=float)
    u = axis / np.linalg.norm(axis)
    rel = pts - c
    rel -= np.outer(rel @ u, u)
    cross = np.cross(rel[:-1], rel[1:]) @ u
    dot = np.einsum("ij,ij->i", rel[:-1], rel[1:])
    return float(np.sum(np.arctan2(cross, dot)))


# ---------------------------------------------------------------- line vectors


def test_line_is_drawn_through_its_foot_point_with_the_arrow_S():
    L = LineVector.through([1, 2, 3], [2, 2, 5])
    ax = plot_line(L)
    P = as_float(foot(L))
    S = as_float(L.S)
    drawn_line = the(ax, "line")
    for p in drawn_line:
        assert distance_to_line(p, P, S) < 1e-12
    np.testing.assert_allclose(the(ax, "foot")[0], P)  # (1.16)
    arrow = the(ax, "arrow")
    np.testing.assert_allclose(arrow[0], P)
    np.testing.assert_allclose(arrow[1] - arrow[0], S)
    perpendicular = the(ax, "perpendicular")  # from O to P, normal to the line (1.17)
    np.testing.assert_allclose(perpendicular, [np.zeros(3), P], atol=1e-12)
    assert abs(np.dot(P, S)) < 1e-12
    # (1.18): the length of the perpendicular is |S0| / |S|
    S0 = as_float(L.S0)
    assert math.isclose(np.linalg.norm(P), np.linalg.norm(S0) / np.linalg.norm(S))


def test_line_arrow_can_start_at_a_given_point_of_the_line():
    L = LineVector.from_axis([0, 0, 1], [1, 0, 0])
    ax = plot_line(L, at=[3, 0, 1])
    np.testing.assert_allclose(the(ax, "arrow"), [[3, 0, 1], [4, 0, 1]])
    with pytest.raises(ValueError, match=r"at: the point .* is not on the axis"):
        plot_line(L, at=[0, 1, 1])


def test_a_point_off_the_line_is_refused_however_small_the_offset_in_absolute_terms():
    # the float policy (relative to the sizes involved), not an absolute tolerance: a point
    # 1e-10 off the x axis is off it (the old test accepted anything within 1e-9)
    L = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    with pytest.raises(ValueError, match=r"at: the point .* is not on the axis"):
        plot_line(L, at=[0, 1e-10, 0])
    tiny = LineVector.from_axis([0, 0, 0], [1e-6, 0, 0])
    with pytest.raises(ValueError, match=r"at: the point .* is not on the axis"):
        plot_line(tiny, at=[0, 1e-10, 0])
    plot_line(L, at=[2.5, 1e-17, 0])  # on the axis up to rounding
    plt.close("all")


def test_an_imaginary_component_is_refused_however_small():
    # a purely imaginary 1e-15 i is not a real number up to rounding (the old test accepted
    # an imaginary part up to 1e-12 absolute)
    x = symbols("x", nonnegative=True)
    L = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    with pytest.raises(ValueError, match=r"at: expected real components"):
        plot_line(L, at=[Rational(1, 10**15) * sqrt(x), 0, 0], subs={x: -1})
    plt.close("all")


def test_pictures_accumulate_in_one_axes():
    ax = plot_frame()
    plot_line(LineVector.from_axis([0, 0, 0], [1, 0, 0]), ax)
    same = plot_line(LineVector.from_axis([0, 1, 0], [0, 0, 1]), ax, label="$2")
    assert same is ax
    assert len(find_artists(ax, "frame")) == 3
    assert len(find_artists(ax, "arrow")) == 2
    assert "$2" in [t.get_text() for t in find_artists(ax, "label")]
    # every drawn point is inside the axes limits
    lo = [ax.get_xlim()[0], ax.get_ylim()[0], ax.get_zlim()[0]]
    hi = [ax.get_xlim()[1], ax.get_ylim()[1], ax.get_zlim()[1]]
    for kind in ("arrow", "line", "frame"):
        for artist in find_artists(ax, kind):
            pts = vertices(artist)
            assert np.all(pts >= np.array(lo) - 1e-9) and np.all(pts <= np.array(hi) + 1e-9)


# ---------------------------------------------------------------------- screws


@pytest.mark.parametrize("h", [Rational(1, 2), Rational(-1, 2), 3, -3, Rational(1, 20)])
def test_screw_axis_and_helix_hand_follow_the_screw(h):
    s = Screw.from_axis([1, -1, 2], [1, 2, 2], h)
    ax = plot_screw(s)
    P = as_float(s.foot)
    S = as_float(s.S)
    for p in the(ax, "line"):  # the drawn axis passes through the foot point (1.36)
        assert distance_to_line(p, P, S) < 1e-12
    np.testing.assert_allclose(the(ax, "foot")[0], P)
    helix = the(ax, "helix")
    # wound around the screw axis at constant radius
    radii = [distance_to_line(p, P, S) for p in helix]
    assert max(radii) - min(radii) < 1e-9
    # its hand is the sign of the pitch
    assert torsion_sign(helix) == np.sign(float(h))
    # and it advances helix_advance(h, radius) per radian along S
    u = S / np.linalg.norm(S)
    swept = turning_sense(helix, S, center=P)
    advance = float((helix[-1] - helix[0]) @ u)
    assert math.isclose(advance / swept, helix_advance(float(h), radii[0]), rel_tol=1e-6)
    label = find_artists(ax, "label")[-1].get_text()
    assert label == f"h = {float(h):.3g}"


def test_helix_lead_grows_with_the_size_of_the_pitch():
    leads = []
    for h in (0.05, 0.2, 1, 5):
        ax = plot_screw(Screw.from_axis([0, 0, 0], [0, 0, 1], h), length=2)
        helix = the(ax, "helix")
        swept = turning_sense(helix, np.array([0, 0, 1.0]), center=[0, 0, 0])
        leads.append((helix[-1] - helix[0])[2] / swept)
        plt.close("all")
    assert leads == sorted(leads) and leads[0] > 0
    assert leads[-1] < 2 * 0.08 * 1.2  # bounded by the helix radius
    assert math.isclose(leads[0], 0.05, rel_tol=0.25)  # close to the true lead when small


def test_line_vector_has_no_helix_and_symbols_are_substituted():
    h, x = symbols("h x", real=True)
    ax = plot_screw(Screw.from_axis([x, 0, 0], [0, 1, 0], h), subs={h: 0, x: 1})
    assert find_artists(ax, "helix") == []
    np.testing.assert_allclose(the(ax, "foot")[0], [1, 0, 0])


def test_symbolic_objects_need_subs():
    h, x = symbols("h x", real=True)
    s = Screw.from_axis([x, 0, 0], [0, 1, 0], h)
    with pytest.raises(ValueError, match=r"screw: cannot draw a symbolic Screw: "
                                         r"substitute numbers for h, x \(subs=\{\.\.\.\}\)"):
        plot_screw(s)
    with pytest.raises(ValueError, match=r"substitute numbers for x \("):
        plot(s, subs={h: 1})
    with pytest.raises(ValueError, match=r"line: cannot draw a symbolic LineVector"):
        plot_line(LineVector.from_axis([x, 0, 0], [0, 1, 0]))
    with pytest.raises(TypeError, match=r"subs: expected a dict"):
        plot_screw(s, subs=[(h, 1)])
    # exact irrational numbers are fine
    ax = plot_screw(Screw([1, 1, 1], [1, 1, 1]) / sqrt(3))  # Example 1.3
    assert torsion_sign(the(ax, "helix")) == 1


def test_argument_errors_name_the_argument():
    with pytest.raises(TypeError, match=r"ax: expected a 3D Axes"):
        plot_line(LineVector.from_axis([0, 0, 0], [1, 0, 0]), ax=plt.figure().add_subplot())
    with pytest.raises(TypeError, match=r"obj: expected a Screw, LineVector, Twist, Wrench"):
        plot("S")
    with pytest.raises(ValueError, match=r"couple: expected a couple \(0; C\) with C != 0"):
        plot_couple(Screw([1, 0, 0], [0, 0, 0]))
    with pytest.raises(ValueError, match=r"length: expected a positive number, got -1"):
        plot_line(LineVector.from_axis([0, 0, 0], [1, 0, 0]), length=-1)
    with pytest.raises(ValueError, match=r"twist: the zero twist"):
        plot_twist(Twist.translation([0, 0, 0]))


# --------------------------------------------------------------------- couples


@pytest.mark.parametrize("C", [[0, 0, 2], [1, -1, 0]])
def test_couple_is_a_free_vector_with_a_right_handed_curl(C):
    ax = plot_couple(Screw.couple(C), at=[1, 2, 3])
    arrow = the(ax, "arrow")
    np.testing.assert_allclose(arrow, [[1, 2, 3], np.array([1, 2, 3]) + C])
    assert len(find_artists(ax, "head")) == 2  # double-headed: a moment vector
    curl = the(ax, "curl")
    assert turning_sense(curl, np.array(C, dtype=float)) > 0


def test_screw_with_zero_direction_is_drawn_as_a_couple():
    ax = plot(Screw.couple([0, 3, 0]))
    np.testing.assert_allclose(the(ax, "arrow"), [[0, 0, 0], [0, 3, 0]])


# ------------------------------------------------------------ twists, wrenches


@pytest.mark.parametrize("omega", [2, -2])
def test_twist_glyph(omega):
    t = Twist.from_axis([1, 0, 0], [0, 0, 1], Rational(-1, 5), magnitude=omega)
    ax = plot(t)
    w = as_float(t.omega)
    np.testing.assert_allclose(the(ax, "arrow"), [[1, 0, 0], np.array([1, 0, 0]) + w])
    for p in the(ax, "line"):
        assert distance_to_line(p, np.array([1.0, 0, 0]), w) < 1e-12
    # the curl turns right-handedly about omega: the body's sense of rotation
    assert turning_sense(the(ax, "curl"), w) > 0
    # the pitch of the twist is -1/5 whatever the sign of omega: left-handed helix
    assert torsion_sign(the(ax, "helix")) == -1
    # the point of the body on the axis moves along it: check with the library
    v_axis = as_float(t.velocity_at([1, 0, 0]))
    assert np.linalg.norm(np.cross(v_axis, w)) < 1e-12


def test_translation_is_a_free_arrow():
    ax = plot(Twist.translation([0, 1, 0]), at=[0, 0, 1])
    np.testing.assert_allclose(the(ax, "arrow"), [[0, 0, 1], [0, 1, 1]])


@pytest.mark.parametrize("h", [Rational(1, 2), Rational(-1, 2)])
def test_wrench_glyph(h):
    W = Wrench.from_axis([0, 1, 1], [1, 0, 0], h, magnitude=3)
    ax = plot(W)
    arrows = find_artists(ax, "arrow")
    force, couple = (vertices(a) for a in arrows)
    np.testing.assert_allclose(force, [[0, 1, 1], [3, 1, 1]])  # f on its axis (1.55)
    C = couple[1] - couple[0]
    for p in couple:  # the couple h f lies on the same axis
        assert distance_to_line(p, np.array([0.0, 1, 1]), np.array([1.0, 0, 0])) < 1e-12
    assert np.sign(C[0]) == np.sign(float(h))  # and points along h f
    assert torsion_sign(the(ax, "helix")) == np.sign(float(h))


def test_pure_force_and_pure_couple_wrenches():
    ax = plot(Wrench.force([0, 0, -1], point=[2, 0, 0]))
    assert find_artists(ax, "helix") == []
    np.testing.assert_allclose(the(ax, "arrow"), [[2, 0, 0], [2, 0, -1]])
    ax = plot(Wrench.couple([0, 0, 1]))
    assert turning_sense(the(ax, "curl"), np.array([0, 0, 1.0])) > 0


# ------------------------------------------------------------- common normal


def test_common_normal_segment_joins_the_feet_and_labels_a12_alpha12():
    L1 = LineVector.from_axis([1, 0, 0], [1, 0, 0])
    L2 = LineVector.from_axis([0, 2, 3], [1, 1, 0])
    cn = common_normal(L1, L2)
    ax = plot_common_normal(L1, L2)
    seg = the(ax, "normal")
    np.testing.assert_allclose(seg, [as_float(cn.foot1), as_float(cn.foot2)])
    assert math.isclose(np.linalg.norm(seg[1] - seg[0]), float(cn.a12))  # a12 = 3
    # each arrow starts at its foot of the normal, and the lines pass through the feet
    arrows = [vertices(a) for a in find_artists(ax, "arrow")]
    np.testing.assert_allclose(arrows[0][0], as_float(cn.foot1))
    np.testing.assert_allclose(arrows[1][0], as_float(cn.foot2))
    # the arc turns about the normal from S1 to S2 through alpha12
    arc = find_artists(ax, "angle")[-1]
    pts = vertices(arc) - as_float(cn.foot2)
    u1 = as_float(L1.S) / np.linalg.norm(as_float(L1.S))
    u2 = as_float(L2.S) / np.linalg.norm(as_float(L2.S))
    np.testing.assert_allclose(pts[0] / np.linalg.norm(pts[0]), u1, atol=1e-12)
    np.testing.assert_allclose(pts[-1] / np.linalg.norm(pts[-1]), u2, atol=1e-12)
    assert math.isclose(turning_sense(pts, as_float(cn.normal), center=[0, 0, 0]),
                        float(cn.alpha12), rel_tol=1e-9)
    label = find_artists(ax, "label")[-1].get_text()
    assert "$a_{12}$ = 3" in label
    assert r"$\alpha_{12}$ = 0.7854 rad (45°)" in label
    assert cn.alpha12 == pi / 4


def test_common_normal_negative_angle_and_symbols():
    a = symbols("a", positive=True)
    L1 = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    L2 = LineVector.from_axis([0, 0, a], [1, -1, 0])
    with pytest.raises(ValueError, match=r"l2: cannot draw a symbolic LineVector: "
                                         r"substitute numbers for a"):
        plot_common_normal(L1, L2)
    ax = plot_common_normal(L1, L2, subs={a: 2})
    seg = the(ax, "normal")
    np.testing.assert_allclose(seg, [[0, 0, 0], [0, 0, 2]])
    label = find_artists(ax, "label")[-1].get_text()
    assert "$a_{12}$ = 2" in label and r"-0.7854 rad (-45°)" in label


# --------------------------------------------------------------- packaging


def test_import_screwsym_does_not_import_matplotlib():
    code = "import sys, screwsym; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"


def test_show_foot_is_a_boolean():
    # issue 20: flags are booleans, checked by the one shared check (core.checks.check_flag)
    with pytest.raises(TypeError, match="show_foot: expected True or False, got str 'no'"):
        plot_line(LineVector.from_axis([0, 0, 0], [1, 0, 0]), show_foot="no")
