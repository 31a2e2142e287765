"""Motion types that say what moves: translations first ("3T1R"), helical freedoms named.

Issue 18 item 6.  A rotational freedom is helical when no translation of the system makes
it a rotation (pitch 0); its pitch is a principal pitch of the system (Hunt 1978,
*Kinematic Geometry of Mechanisms*, Ch. 12).  Each case is checked against an independent
numeric computation of the same twist (the loop's rates from a NumPy null space).
"""

import numpy as np
import pytest
from _linkages import ISOGRAM, bennett, cross, sub
from sympy import Rational, symbols

from screwsym import ScrewSystem, Twist
from screwsym.systems.joints import Cylindrical, Helical, Prismatic, Revolute
from screwsym.systems.linkage import Mechanism
from screwsym.systems.motion_type import motion_of, motion_type
from screwsym.systems.parallel import Limb, ParallelMechanism

Z = [0, 0, 1]


def loop_pitch(points, axes, pitch, upto):
    """The pitch of link ``upto`` of a 1-DOF 4-loop relative to link 0, in NumPy floats.

    The loop rates are the null vector of the four joint twists ``(u; p x u + h u)``; the
    link's twist is the sum of the first ``upto`` joints' rates times their twists.
    """
    S = np.array([np.r_[u, np.cross(p, u) + pitch * u]
                  for p, u in zip(np.array(points, float), np.array(axes, float), strict=True)]).T
    rates = np.linalg.svd(S)[2][-1]
    t = S[:, :upto] @ rates[:upto]
    return float(t[:3] @ t[3:] / (t[:3] @ t[:3]))


def test_the_usual_order_translations_first():
    # the literature writes 3T1R (Schoenflies), 2T1R (planar), 1T2R (3-RPS)
    assert [motion_type(*x) for x in ((1, 3), (1, 2), (2, 1), (3, 3), (1, 0), (0, 3))] == [
        "3T1R", "2T1R", "1T2R", "3T3R", "1R", "3T"]
    assert motion_type(1, 0, helical=1) == "1H" and motion_type(3, 1, helical=2) == "1T1R2H"
    with pytest.raises(ValueError, match=r"helical: expected at most rotations = 1, got 2"):
        motion_type(1, 0, helical=2)
    with pytest.raises(ValueError, match=r"translations: expected a non-negative integer, got -1"):
        motion_type(1, -1)


def test_a_single_helical_joint_is_1h_with_its_pitch():
    h = symbols("h", positive=True)
    m = ParallelMechanism(Limb(Helical([1, 2, 0], [0, 1, 1], h))).mobility()
    assert (m.mobility, m.motion, m.rotations, m.translations) == (1, "1H", 1, 0)
    assert m.helical_pitches == (h,)
    # pitch 0 is a revolute: a rotation, not a helix (the checker rejects the wrong label)
    r = ParallelMechanism(Limb(Helical([1, 2, 0], [0, 1, 1], 0))).mobility()
    assert (r.motion, r.helical_pitches) == ("1R", ())
    assert ParallelMechanism(Limb(Revolute([1, 2, 0], [0, 1, 1]))).mobility().motion == "1R"


def test_a_helix_with_a_translation_along_its_axis_is_a_cylinder():
    # H + P along the axis = C: "1T1R"; H + P across the axis stays helical: "1T1H"
    along = ParallelMechanism(Limb(Helical([0, 0, 0], Z, 2), Prismatic(Z))).mobility()
    across = ParallelMechanism(Limb(Helical([0, 0, 0], Z, 2), Prismatic([1, 0, 0]))).mobility()
    cyl = ParallelMechanism(Limb(Cylindrical([0, 0, 0], Z))).mobility()
    assert (along.motion, cyl.motion, across.motion) == ("1T1R", "1T1R", "1T1H")
    assert across.helical_pitches == (2,)


def test_two_skew_revolutes_are_2r_two_equal_helices_2h():
    # an R-R chain on skew axes: its principal pitches are +-, the pitch form is
    # indefinite and the system is spanned by its two lines: 2R, not helical
    rr = motion_of(ScrewSystem(Twist.rotation([1, 0, 0], point=[0, 0, 0]),
                               Twist.rotation([0, 1, 0], point=[0, 0, 1])))
    assert (rr.motion, rr.helical_pitches) == ("2R", ())
    # two helices of one pitch about crossing axes: every twist of the span has pitch 3
    hh = motion_of(ScrewSystem(Twist.screw_motion([1, 0, 0], point=[0, 0, 0], pitch=3),
                               Twist.screw_motion([0, 1, 0], point=[0, 0, 0], pitch=3)))
    assert (hh.motion, hh.helical_pitches) == ("2H", (3, 3))
    # two pitches of one sign (2 and 5): semidefinite, two helical freedoms
    h25 = motion_of(ScrewSystem(Twist.screw_motion([1, 0, 0], point=[0, 0, 0], pitch=2),
                                Twist.screw_motion([0, 1, 0], point=[0, 0, 0], pitch=5)))
    assert (h25.motion, sorted(h25.helical_pitches)) == ("2H", [2, 5])


def test_bennett_coupler_moves_helically():
    # Bennett's linkage (Bennett 1903): each link moves relative to its neighbours about a
    # joint axis (1R), but the coupler moves relative to the ground on a screw of non-zero
    # pitch (two skew rotations compound to a twist: Hunt 1978, §12.3)
    m = bennett()
    assert [m.motion(x) for x in ("crank", "coupler", "rocker")] == ["1R", "1H", "1R"]
    (p,) = m.helical_pitches("coupler")
    assert p == -2 and m.helical_pitches("crank") == ()
    # independent: the loop rates as the null space of the four joint twists (NumPy);
    # the coupler's twist relative to the ground is rate 1 * $1 + rate 2 * $2
    pts = ISOGRAM
    axes = [cross(sub(pts[(k + 1) % 4], pts[k]), sub(pts[k - 1], pts[k])) for k in range(4)]
    assert loop_pitch(pts, axes, 0.0, 2) == pytest.approx(-2, abs=1e-12)  # ground->crank->coupler


def test_delassus_hhhh_loop_with_parallel_axes():
    # Delassus (1922, Bull. Sci. Math. 46) HHHH linkage: four helical joints on parallel
    # axes with one pitch h: a 1-DOF loop, every link moving on a helix of pitch h about an
    # axis parallel to z (relative to the ground)
    h = Rational(1, 2)
    pts = [[0, 0, 0], [4, 0, 0], [3, 2, 0], [0, 3, 0]]  # not a parallelogram (its coupler
    # would translate: "1T")
    names = ("ground", "crank", "coupler", "rocker")
    m = Mechanism([(names[k], names[(k + 1) % 4], Helical(pts[k], Z, h)) for k in range(4)],
                  base="ground")
    assert m.mobility().mobility == 1
    assert [m.motion(x) for x in names[1:]] == ["1H", "1H", "1H"]
    assert [m.helical_pitches(x) for x in names[1:]] == [(h,), (h,), (h,)]
    assert loop_pitch(pts, [Z] * 4, 0.5, 2) == pytest.approx(0.5, abs=1e-12)
    # relative to the crank, the coupler turns on joint 2, a helix of pitch h as well
    assert m.helical_pitches("coupler", relative_to="crank") == (h,)


def test_bennett_geometry_with_helical_joints_of_one_pitch():
    # the Bennett axes with helical joints of one pitch h: the loop equation gains
    # h * sum(rate_k omega_k) = 0, so the freedom stays; the coupler's pitch shifts by h
    h = symbols("h", real=True)
    pts = ISOGRAM
    axes = [cross(sub(pts[(k + 1) % 4], pts[k]), sub(pts[k - 1], pts[k])) for k in range(4)]
    names = ("ground", "crank", "coupler", "rocker")
    m = Mechanism([(names[k], names[(k + 1) % 4], Helical(pts[k], axes[k], h)) for k in range(4)],
                  base="ground")
    assert m.motion("coupler") == "1H" and m.helical_pitches("coupler") == (h - 2,)
    assert m.helical_pitches("crank") == (h,)
    assert loop_pitch(pts, axes, 0.75, 2) == pytest.approx(0.75 - 2, abs=1e-12)
    # at h = 2 the coupler's screw becomes a line: a rotation
    assert m.xreplace({h: 2}).motion("coupler") == "1R"


def test_an_undecidable_pitch_form_gives_none_not_rotations():
    # Two helices about crossing axes with symbolic pitches a, b: the pitch form is diag(a, b)
    # (Hunt 1978, §12.3: the principal pitches), helical when a and b have one sign, spanned
    # by two rotations when they have opposite signs.  Neither is generic in (a, b): with
    # nothing known of the signs the answer is None ("cannot decide"), not a guess.
    def two(a, b):
        return motion_of(ScrewSystem(Twist.screw_motion([1, 0, 0], point=[0, 0, 0], pitch=a),
                                     Twist.screw_motion([0, 1, 0], point=[0, 0, 0], pitch=b)))

    a, b = symbols("a b", real=True)
    undecided = two(a, b)
    assert (undecided.motion, undecided.helical_pitches) == (None, None)
    assert (undecided.rotations, undecided.translations) == (2, 0)
    pa, pb = symbols("pa pb", positive=True)
    assert two(pa, pb).motion == "2H" and set(two(pa, pb).helical_pitches) == {pa, pb}
    assert two(pa, -pb).motion == "2R"
    # the decided cases agree with the same systems at numbers of those signs
    assert two(2, 5).motion == "2H" and two(2, -5).motion == "2R"
