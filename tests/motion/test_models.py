"""The shipped robot models against independent sources.

Each shipped model (today: ``ur5()``) is checked three ways, none of which reuses the model's
own numbers: (1) the published screw-axis table, typed here from the book; (2) the same robot
built from its Denavit-Hartenberg table by ``Chain.from_dh`` (and from the UR5's URDF where
defusedxml is installed); (3) a geometric property that a transcription slip breaks.
"""

from __future__ import annotations

import pytest
from sympy import ImmutableMatrix, Rational, pi

from screwsym import Chain, Transform, Twist
from screwsym.motion.chain import ur5

# Lynch & Park, Modern Robotics (2017), Example 4.5 (UR5), dimensions in metres
W1, W2, L1, L2, H1, H2 = (Rational(x, 1000) for x in (109, 82, 425, 392, 89, 95))


def mr_example_4_5(W1, W2, L1, L2, H1, H2) -> Chain:
    """Modern Robotics, Example 4.5: M and the table of space screw axes S_i = (omega_i; v_i)."""
    M = [[-1, 0, 0, L1 + L2], [0, 0, 1, W1 + W2], [0, 1, 0, H1 - H2], [0, 0, 0, 1]]
    table = [
        # omega        v
        ((0, 0, 1), (0, 0, 0)),
        ((0, 1, 0), (-H1, 0, 0)),
        ((0, 1, 0), (-H1, 0, L1)),
        ((0, 1, 0), (-H1, 0, L1 + L2)),
        ((0, 0, -1), (-W1, L1 + L2, 0)),
        ((0, 1, 0), (H2 - H1, 0, L1 + L2)),
    ]
    return Chain([Twist(w, v) for w, v in table], Transform.from_matrix(M))


def same_chain(a: Chain, b: Chain, base: Transform | None = None) -> bool:
    """``base a(q) == b(q)`` for every q, by the product of exponentials: the twists moved by
    ``base`` and the home pose agree exactly (then T_b(q) = base T_a(q) identically)."""
    base = Transform.identity() if base is None else base
    return (a.n_joints == b.n_joints
            and all(base.apply(s) == t for s, t in zip(a.twists, b.twists, strict=True))
            and base @ a.home == b.home)


def moment_about(twist: Twist, point) -> ImmutableMatrix:
    """The moment of the joint's line about ``point``: v_O - point x omega (zero iff on the line)."""
    return twist.v_O - ImmutableMatrix(point).cross(twist.omega)


def mutual_moment(s: Twist, t: Twist):
    """The mutual moment of two joint lines, S1.S02 + S2.S01 (zero iff coplanar)."""
    return s.omega.dot(t.v_O) + t.omega.dot(s.v_O)


def test_ur5_is_the_published_table():
    assert ur5() == mr_example_4_5(W1, W2, L1, L2, H1, H2)


def test_ur5_from_its_standard_dh_table():
    """The UR5's standard DH structure (Universal Robots' published table: d1, a2, a3, d4, d5,
    d6 with alpha = pi/2, 0, 0, pi/2, -pi/2, 0) with Modern Robotics' dimensions
    (d1 = H1, a2 = -L1, a3 = -L2, d4 = W1, d5 = H2, d6 = W2).  The DH base frame is the book's
    turned a half-turn about z (x points the other way), the joint zeros and the flange agree:
    T_dh(q) = Rz(pi) T_ur5(q) exactly."""
    rows = [(0, pi / 2, H1, 0), (-L1, 0, 0, 0), (-L2, 0, 0, 0),
            (0, pi / 2, W1, 0), (0, -pi / 2, H2, 0), (0, 0, W2, 0)]
    half_turn = Transform.rotation([0, 0, 1], pi)
    assert same_chain(ur5(), Chain.from_dh(rows), half_turn)
    # the modified (Craig) table of the same robot gives the same chain
    modified = [(0, 0, H1, 0), (0, pi / 2, 0, 0), (-L1, 0, 0, 0),
                (-L2, 0, W1, 0), (0, pi / 2, H2, 0), (0, -pi / 2, W2, 0)]
    assert same_chain(ur5(), Chain.from_dh(modified, "modified"), half_turn)
    # the check is not blind: without the half-turn, or with the old slip, it fails
    assert not same_chain(ur5(), Chain.from_dh(rows))
    assert not same_chain(_with_old_slip(), Chain.from_dh(rows), half_turn)


def test_the_ur5_urdf_is_the_published_table_with_the_real_dimensions():
    """ur5_robot.urdf (example-robot-data, from ros-industrial) from base_link to tool0 is
    Example 4.5's table with the UR5's real dimensions (UR's DH: H1 = d1 = 0.089159,
    L1 = 0.425, L2 = 0.39225, W1 = d4 = 0.10915, H2 = d5 = 0.09465, W2 = d6 = 0.0823),
    exactly, with the file's 1.57079632679 read as pi/2 (angles="pi/12"; they are 5e-12 off)."""
    pytest.importorskip("defusedxml")
    from pathlib import Path

    path = Path(__file__).parent.parent / "data" / "urdf" / "ur5_robot.urdf"
    real = [Rational(x) for x in ("0.10915", "0.0823", "0.425", "0.39225", "0.089159", "0.09465")]
    urdf = Chain.from_urdf(path, base="base_link", tip="tool0", angles="pi/12")
    assert same_chain(urdf, mr_example_4_5(*real))
    assert not same_chain(urdf, mr_example_4_5(W1, W2, L1, L2, H1, H2))  # the book rounds


def _with_old_slip() -> Chain:
    """ur5() as shipped up to 0.2.0: joint 6's v had H2 - W2 for H2 - H1."""
    arm = ur5()
    slip = Twist([0, 1, 0], [H2 - W2, 0, L1 + L2])
    return Chain([*arm.twists[:5], slip], arm.home)


@pytest.mark.parametrize("arm", [ur5(), _with_old_slip()], ids=["ur5", "old-slip"])
def test_ur5_geometry(arm):
    """The UR5's wrist (Modern Robotics Fig. 4.5): joint 6 is the flange's z-axis through the
    flange origin; axes 4 and 5, and 5 and 6, meet at right angles; axes 2, 3, 4 are parallel.
    (The UR5's wrist is not spherical: axes 4 and 5 do not pass through the flange origin.)
    A transcription slip in any wrist twist breaks one of these."""
    s = arm.twists
    flange = arm.home.p
    checks = [
        moment_about(s[5], flange) == ImmutableMatrix([0, 0, 0]),
        s[5].omega == arm.home.R[:, 2],
        mutual_moment(s[3], s[4]) == 0 and s[3].omega.dot(s[4].omega) == 0,
        mutual_moment(s[4], s[5]) == 0 and s[4].omega.dot(s[5].omega) == 0,
        s[1].omega == s[2].omega == s[3].omega,
    ]
    if arm == ur5():
        assert all(checks)
        assert moment_about(s[3], flange) != ImmutableMatrix([0, 0, 0])  # not a spherical wrist
    else:
        # the slip moves axis 6 off the flange origin (by H1 - W2 = 7 mm in z); it still
        # meets axis 5 and is still parallel to the flange's z-axis: only the first check sees it
        assert checks == [False, True, True, True, True]


def test_the_slip_moved_the_flange():
    """The issue's symptom: turning joint 6 alone moved the old model's flange origin; the fixed
    one stays put.  The old axis 6 ran d = H1 - W2 = 7 mm below the flange origin (z), so a
    quarter-turn about it (+y) carries the flange by Ry(pi/2) (0, 0, d) - (0, 0, d) = (d, 0, -d)."""
    for angle in (pi / 2, Rational(1, 3)):
        q = [0, 0, 0, 0, 0, angle]
        assert ur5().forward(q).p == ur5().home.p
    moved = _with_old_slip().forward([0, 0, 0, 0, 0, pi / 2]).p - ur5().home.p
    d = H1 - W2
    assert moved == ImmutableMatrix([d, 0, -d])
