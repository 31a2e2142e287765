"""Type synthesis (screwsym.systems.synthesis) against the literature's tables.

Each family the literature lists is looked for by name in what the enumeration finds; the
finite motion of a found design is checked independently by modern_robotics (the inverse
kinematics of each limb, a product of exponentials, solved to a platform pose a finite step
away inside the wanted motion, and the limb's twists there still containing the motion).

The published tables themselves (Kong & Gosselin, "Type synthesis of 3-DOF translational
parallel manipulators based on screw theory", ASME J. Mech. Des. 126(1) (2004) 83-92; "...
spherical parallel manipulators ...", 126 (2004) 101-108; *Type Synthesis of Parallel
Mechanisms*, Springer 2007, the 3T, 3R and 3T1R chapters) could not be read here: they are
not in the stored corpora searched for this work (docs, pages, code).  So the tests compare
with the families those works *name* (and Tsai's, Clavel's, Pierrot's, Merlet's), not number
for number with their tables; the counts asserted are what this grammar finds, and
benchmarks/bench_synthesis.py prints the full table of them (limb types by length and
certified mechanisms, per motion pattern and grammar).
"""

from __future__ import annotations

import numpy as np
import pytest
from _linkages import cross, sub

from screwsym.systems.joints import P, R, U
from screwsym.systems.parallel import Limb, ParallelMechanism
from screwsym.systems.synthesis import (
    LimbType,
    limbs,
    mechanisms,
    motion,
    refusals,
)

mr = pytest.importorskip("modern_robotics")

O3 = [0, 0, 0]


def names(found):
    return {t.name for t in found}


# ------------------------------------------------------------ an independent finite motion
def slist(limb):
    return np.array([[float(x) for x in t.matrix] for t in limb.twists]).T


def target(name, rng):
    """A platform pose a finite step away, inside the motion ``name``."""
    w = {"3T": [0, 0, 0], "3T1R": [0, 0, 1], "3R": rng.normal(size=3), "2T1R": [0, 0, 1]}[name]
    v = {"3T": rng.normal(size=3), "3T1R": rng.normal(size=3), "3R": [0, 0, 0],
         "2T1R": [*rng.normal(size=2), 0]}[name]
    xi = 0.05 * np.array([*w, *v], dtype=float)
    return mr.MatrixExp6(mr.VecTose3(xi))


def reaches(limb, T, mo):
    """Whether the limb reaches the pose T (modern_robotics' Newton iteration from zero), and
    whether its twists there still contain the wanted motion (singular values)."""
    S = slist(limb)
    theta, _ = mr.IKinSpace(S, np.eye(4), T, np.zeros(S.shape[1]), 1e-13, 1e-13)
    for _ in range(5):  # IKinSpace stops after 20 steps: a few more restarts
        theta, _ = mr.IKinSpace(S, np.eye(4), T, theta, 1e-13, 1e-13)
    err = np.linalg.norm(mr.FKinSpace(np.eye(4), S, theta) - T)
    J = mr.JacobianSpace(S, theta)
    G = np.array([[float(x) for x in t.matrix] for t in mo.twists]).T
    s_j = np.linalg.svd(J, compute_uv=False)
    s_all = np.linalg.svd(np.hstack([J, G]), compute_uv=False)
    keeps = int((s_all > 1e-8).sum()) == int((s_j > 1e-8).sum()) == S.shape[1]
    return bool(err < 1e-9), bool(keeps)


# ------------------------------------------------------------ motions
def test_motion_patterns_and_their_wrenches():
    assert [motion(n).dimension for n in ("3T", "3R", "3T1R", "2T1R")] == [3, 3, 4, 3]
    assert [motion(n).wrenches.rank for n in ("3T", "3R", "3T1R", "2T1R")] == [3, 3, 2, 3]
    with pytest.raises(ValueError, match="name: expected one of"):
        motion("3T2R")  # not a subgroup: needs virtual chains (not done)
    with pytest.raises(TypeError, match="name: expected a str"):
        motion(3)
    with pytest.raises(TypeError, match="mo: expected a Motion"):
        limbs("3T")
    with pytest.raises(ValueError, match="kinds: expected"):
        limbs(motion("3T"), kinds=("H",))
    from sympy import Symbol, sqrt
    for v in (Symbol("a", real=True), sqrt(2)):
        with pytest.raises(ValueError, match="obj: expected rational geometry"):
            refusals(Limb(R(O3, [1, 0, v])), motion("3T"))


# ------------------------------------------------------------ 3T
def test_3t_limbs_of_four_joints_at_most():
    # Kong & Gosselin, "Type synthesis of 3-DOF translational parallel manipulators based on
    # screw theory", ASME J. Mech. Des. 126 (2004) 83-92 (the legs of 3 and 4 joints, with
    # three or two constraint couples): PPP and the PRRR with parallel revolutes are in it;
    # Kong & Gosselin, IJRR 21(9) (2002) 791-798: the 3-CRR (the C and both R parallel)
    found = limbs(motion("3T"), max_joints=4)
    assert {"PPP", "PRRR (2∥3∥4)", "CRR (1∥2∥3∥4)"} <= names(found)
    # what the grammar finds, all of it (two couples for the 4-joint legs, three for PPP)
    assert len(found) == 10
    assert all(t.instance(1).constraints.rank == 6 - t.freedom for t in found)


@pytest.mark.slow
def test_3t_limbs_of_five_joints_include_tsai_and_kong_gosselin():
    # Tsai's 3-UPU (Tsai 1996, "Kinematics of a three-DOF platform with three extensible
    # limbs"): base and platform U with crossed parallel axes (1∥5, 2∥4); Kong & Gosselin
    # (2004; the legs of five joints, one constraint couple): the 5R legs R∥R∥R-R∥R in both
    # orders, the PRRRR, RPRRR, RRPRR families
    found = limbs(motion("3T"), max_joints=5)
    assert {"UPU (1∥5, 2∥4)", "RRRRR (1∥2∥3, 4∥5)", "RRRRR (1∥5, 2∥3∥4)",
            "PRRRR (2∥3, 4∥5)", "RPRRR (1∥3, 4∥5)", "RRPRR (1∥2, 4∥5)"} <= names(found)
    # the grammar: 1 of 3 joints, 9 of 4, 43 of 5 (the U of two revolutes through one point
    # counted apart from the two revolutes anywhere)
    assert [sum(t.freedom == n for t in found) for n in (3, 4, 5)] == [1, 9, 43]
    # and nothing of a wrong arrangement: R_a R_b R_a R_b is 3T at first order only
    assert "PRRRR (2∥4, 3∥5)" not in names(found)


def test_3t_mechanisms_are_certified_and_actuated():
    designs = mechanisms(motion("3T"), max_joints=4)
    assert len(designs) == 10
    for d in designs:
        m = d.mobility
        assert (m.mobility, m.motion, m.passive) == (3, "3T", 0)
        assert d.second_order[:4] == (3, 3, 1, False)
        assert d.actuated is not None
    assert refusals(designs[0].mechanism, motion("3T")) == ()  # the same checks, by hand
    assert "3-CRR (1∥2∥3∥4)" in {d.name for d in designs}


@pytest.mark.parametrize("case", range(3))
def test_3t_designs_move_a_finite_step(case):
    rng = np.random.default_rng([38, case])
    mo = motion("3T")
    types = [LimbType(mo, (("R", 0, "g"), ("R", 1, "u"), ("P", 2, "-"), ("R", 1, "g"),
                           ("R", 0, "u"))),                        # Tsai's UPU
             LimbType(mo, (("R", 0, "g"), ("R", 0, "g"), ("R", 0, "g"), ("R", 1, "g"),
                           ("R", 1, "g")))]                        # R∥R∥R-R∥R
    (upu, rrrrr) = sorted(mechanisms(mo, types=types), key=lambda d: d.name)[::-1]
    assert upu.name.startswith("3-UPU") and rrrrr.name.startswith("3-RRRRR")
    T = target("3T", rng)
    for d in (upu, rrrrr):
        for leg in d.mechanism.limbs:
            assert reaches(leg, T, mo) == (True, True)


def test_3t_refuses_a_tilted_axis_and_a_first_order_arrangement():
    mo = motion("3T")
    a, b = [1, 2, 3], [3, -1, 2]
    prrr = Limb(P([2, 1, 5]), R([0, 0, 0], a), R([4, 1, 0], a), R([0, 3, 7], a))
    assert refusals(prrr, mo) == ()
    tilted = Limb(P([2, 1, 5]), R([0, 0, 0], a), R([4, 1, 0], [1, 2, 4]), R([0, 3, 7], a))
    assert refusals(tilted, mo) == ("limb: its twists do not contain the wanted motion",)
    # R_a R_b R_a R_b: the twists contain 3T here, but not a finite step away
    abab = Limb(P([2, 1, 5]), R([0, 0, 0], a), R([4, 1, 0], b), R([0, 3, 7], a),
                R([5, -2, 1], b))
    assert refusals(abab, mo) == (
        "limb: its motion does not extend to second order within the wanted motion",)
    rng = np.random.default_rng([38, 99])
    assert reaches(abab, target("3T", rng), mo)[0] is False  # modern_robotics agrees
    assert reaches(prrr, target("3T", rng), mo) == (True, True)


def test_3t_mechanism_of_first_order_limbs_moves_but_leaves_3t():
    # three R_a R_b R_a R_b legs: 3T at first order and 3 freedoms to second order (Müller's
    # test of the mechanism, which asks whether it moves, not how), but each leg's 3T motion
    # does not extend within 3T: the platform starts to turn.  The limb check refuses it.
    from screwsym.systems.linkage import Mechanism

    def perm(v, k):
        return v[k:] + v[:k]

    def leg(k):  # the legs carried by the rotations that permute x, y, z
        a, b = perm([1, 2, 3], k), perm([3, -1, 2], k)
        return Limb(P(perm([2, 1, 5], k)), R(perm([0, 0, 0], k), a), R(perm([4, 1, 0], k), b),
                    R(perm([0, 3, 7], k), a), R(perm([5, -2, 1], k), b))

    m = ParallelMechanism(*(leg(k) for k in range(3)))
    assert (m.mobility().mobility, m.mobility().motion) == (3, "3T")
    assert Mechanism.from_parallel(m).second_order()[:4] == (3, 3, 1, False)
    assert refusals(m, motion("3T")) == tuple(
        f"limbs[{i}]: its motion does not extend to second order within the wanted motion"
        for i in range(3))
    with pytest.raises(ValueError, match="seed: no generic instance of PRRRR"):
        LimbType(motion("3T"), (("P", 0, "-"), ("R", 1, "g"), ("R", 2, "g"), ("R", 1, "g"),
                                ("R", 2, "g"))).instance()


def test_3t_refuses_tsai_3upu_with_a_wrongly_turned_joint():
    # Tsai's 3-UPU needs the platform U's axes parallel to the base U's crossed; with one
    # platform U turned, the platform also rotates
    def leg(b, a1, top, flip=False):
        d = sub(top, b)
        a2 = cross(a1, d)
        return Limb(U(b, a1, a2), P(d), U(top, a1 if flip else a2, [1, 1, 1] if flip else a1))

    legs = ([2, 0, 0], [0, 1, 0], [1, 0, 3]), ([-1, 2, 0], [-2, -1, 0], [0, 1, 3]), \
        ([-1, -2, 0], [2, -1, 0], [0, -1, 3])
    good = ParallelMechanism(*(leg(*x) for x in legs))
    assert refusals(good, motion("3T")) == ()
    bad = ParallelMechanism(leg(*legs[0]), leg(*legs[1]), leg(*legs[2], flip=True))
    why = refusals(bad, motion("3T"))
    assert why[0] == "limbs[2]: its twists do not contain the wanted motion"
    assert why[1:] == ("motion 2T1R, wanted 3T",)  # a rotation about the turned axis


# ------------------------------------------------------------ 3R
def test_3r_limbs_and_the_spherical_3rrr():
    # Gosselin & Angeles (1989), the Agile Eye (Gosselin & Hamel 1994): 3-RRR, every axis
    # through the centre; Kong & Gosselin, "Type synthesis of 3-DOF spherical parallel
    # manipulators based on screw theory", ASME J. Mech. Des. 126 (2004) 101-108: legs of
    # five joints with one constraint force through the centre
    found = limbs(motion("3R"), max_joints=4)
    assert names(found) == {"RRR (1,2,3 through O)"}
    d, = mechanisms(motion("3R"), max_joints=3)
    assert (d.mobility.mobility, d.mobility.motion, d.mobility.common) == (3, "3R", 3)
    assert d.second_order[:4] == (3, 3, 1, False)
    assert d.actuated == 0
    rng = np.random.default_rng([38, 3])
    T = target("3R", rng)
    assert all(reaches(leg, T, motion("3R")) == (True, True) for leg in d.mechanism.limbs)
    # an axis off the centre is refused
    off = Limb(R([0, 0, 0], [1, 0, 0]), R([0, 0, 0], [0, 1, 1]), R([0, 1, 0], [1, 1, 0]))
    assert refusals(off, motion("3R")) == ("limb: its twists do not contain the wanted motion",)
    # a slide after a spherical wrist: the twists contain 3R, but the slide never moves in it
    slide = Limb(R(O3, [1, 0, 0]), R(O3, [0, 1, 0]), R(O3, [0, 0, 1]), P([1, 2, 3]))
    assert refusals(slide, motion("3R")) == (
        "limb: joint 4 (from the base) is locked in the wanted motion",)


@pytest.mark.slow
def test_3r_limbs_of_five_joints():
    found = limbs(motion("3R"), max_joints=5)
    assert names(found) == {"RRR (1,2,3 through O)", "RRRRR (2∥3∥4, 1,5 through O)",
                            "RRRRR (3∥4∥5, 1,2 through O)", "RRS (1,2 through O)",
                            "RSR (1,5 through O)"}
    assert len(mechanisms(motion("3R"), types=found)) == 5


# ------------------------------------------------------------ 3T1R
def test_3t1r_limbs_of_four_joints_and_their_mechanisms():
    # Kong & Gosselin, Type Synthesis of Parallel Mechanisms (Springer 2007), the 3T1R
    # chapter: legs of four joints with two constraint couples normal to z; the revolute
    # axes all parallel to z
    mo = motion("3T1R")
    found = limbs(mo, max_joints=4)
    assert "PRRR (2∥3∥4∥z)" in names(found)
    assert len(found) == 13
    some = [t for t in found if t.letters in ("PRRR", "CRR", "PPPR")]
    designs = mechanisms(mo, 4, types=some)
    assert len(designs) == len(some) == 4
    assert all((d.mobility.mobility, d.mobility.motion) == (4, "3T1R") for d in designs)


@pytest.mark.slow
def test_3t1r_uru_and_rrrrr_families():
    # Kong & Gosselin (2007), the 3T1R chapter, and Fang & Tsai, IJRR 21(9) (2002) 799-810
    # (4-dof manipulators with identical limbs): the 4-URU (the U's outer axes along z, the inner ones and the R parallel) and the
    # R∥R∥R(z)-R∥R legs
    mo = motion("3T1R")
    found = limbs(mo, max_joints=5)
    assert {"URU (1∥5∥z, 2∥3∥4)", "RRRRR (1∥2∥3∥z, 4∥5)"} <= names(found)
    assert len(found) == 152
    uru = [t for t in found if t.name == "URU (1∥5∥z, 2∥3∥4)"]
    d, = mechanisms(mo, 4, types=uru)
    assert (d.mobility.mobility, d.mobility.motion) == (4, "3T1R") and d.actuated == 0
    T = target("3T1R", np.random.default_rng([38, 4]))
    assert all(reaches(leg, T, mo) == (True, True) for leg in d.mechanism.limbs)


# ------------------------------------------------------------ 2T1R
def test_2t1r_the_planar_chains():
    # the seven planar chains of three joints of the planar 3-dof parallel manipulators
    # (Merlet, Parallel Robots, 2nd ed. 2006, Ch. 2, the planar 3-dof robots: RRR, RPR, RRP,
    # PRR, PPR, PRP, RPP): five up to reversal (RRP~PRR, RPP~PPR), each prismatic joint in the plane (⊥z)
    mo = motion("2T1R")
    found = limbs(mo, max_joints=3)
    assert names(found) == {"RRR (1∥2∥3∥z)", "PRR (1⊥z, 2∥3∥z)", "RPR (1∥3∥z, 2⊥z)",
                            "PPR (1⊥z, 2⊥z, 3∥z)", "PRP (1⊥z, 2∥z, 3⊥z)"}
    designs = mechanisms(mo, types=found)
    assert len(designs) == 5
    assert all((d.mobility.mobility, d.mobility.motion) == (3, "2T1R") for d in designs)
    assert all(d.actuated is not None for d in designs)
    # a prismatic joint out of the plane is refused
    tilted = Limb(R([0, 0, 0], [0, 0, 1]), P([1, 2, 1]), R([3, 1, 0], [0, 0, 1]))
    assert refusals(tilted, mo) == ("limb: its twists do not contain the wanted motion",)


def test_budget_stops_the_enumeration():
    with pytest.raises(ValueError, match="limbs: the enumeration passed its budget of 10"):
        limbs(motion("3T"), max_joints=4, budget=10)


# ------------------------------------------------------------ parallelograms (Pa)
def test_a_parallelogram_keeps_its_coupler_turned_nowhere_a_finite_step_away():
    # the finite argument for the Pa (Kong & Gosselin 2007; Clavel 1988): a parallelogram
    # loop moves its output bar on a circular translation.  Checked independently: the Pa of
    # a generic Delta-type limb instance (the library's compound pair) opened into its four
    # revolutes, the loop closed by modern_robotics' inverse kinematics with the first
    # revolute turned by 0.3 rad; the coupler does not turn, and moves by (Rot(h, 0.3) - I) rod
    from screwsym.systems.joints import Parallelogram
    (t,) = [t for t in limbs(motion("3T"), kinds=("R", "Pa"), max_joints=4)
            if t.name == "RPaRR (1∥3∥4)"]
    leg = t.instance(seed=5)
    (pa,) = [j for j in leg.joints if isinstance(j, Parallelogram)]
    p1, p2, q1 = (np.array([float(x) for x in v]) for v in pa.args)
    # (the loop in a frame at p1, lengths divided by the rod's: a similarity, which keeps
    # whether the coupler turns, and keeps modern_robotics' absolute tolerance meaningful)
    size = np.linalg.norm(q1 - p1)
    a, b, c = np.zeros(3), (p2 - p1) / size, (q1 - p1) / size
    h = np.cross(b, c)
    h /= np.linalg.norm(h)

    def screw(p):  # the revolute about h through p, (omega; p x omega)
        return np.r_[h, np.cross(p, h)]

    loop = [screw(p) for p in (a, c, c + b, b)]  # bar a -> rod 1 -> bar b -> rod 2 -> bar a
    first = mr.MatrixExp6(mr.VecTose3(0.3 * loop[0]))
    rest = np.array(loop[1:]).T
    th, _ = mr.IKinSpace(rest, np.eye(4), mr.TransInv(first), np.zeros(3), 1e-14, 1e-14)
    closure = first @ mr.FKinSpace(np.eye(4), rest, th)
    assert np.abs(closure - np.eye(4)).max() < 1e-12  # the loop is closed
    coupler = first @ mr.MatrixExp6(mr.VecTose3(th[0] * loop[1]))
    turned = mr.MatrixExp3(mr.VecToso3(0.3 * h))
    assert np.abs(coupler[:3, :3] - np.eye(3)).max() < 1e-12  # orientation kept
    assert np.allclose(coupler[:3, 3], (turned - np.eye(3)) @ c, atol=1e-12)
    assert np.linalg.norm(coupler[:3, 3]) > 0.1  # and it did move
    # the compound pair's twist is that circle's tangent at rest: n x (q1 - p1)
    (tw,) = pa.twists
    assert np.allclose(np.cross(np.cross(p2 - p1, q1 - p1), q1 - p1),
                       [float(x) for x in tw.matrix[3:]])


def test_the_delta_type_limbs_and_mechanism_are_found():
    # Clavel's Delta (1988): legs R-R-Pa-R, the arm, the elbow and the wrist revolutes
    # parallel; read from the platform it is R-Pa-R-R, Kong & Gosselin's (2007) notation
    # with the three revolutes parallel.  The grammar leaves the hinges' direction free (the
    # Delta's, normal to the arm, is one instance; a relation not needed is not named).
    mo = motion("3T")
    found = limbs(mo, kinds=("R", "Pa"), max_joints=4)
    assert "RPaRR (1∥3∥4)" in names(found)
    assert len(found) == 17  # every 3T limb of R and Pa with at most 4 joints (the table)
    (t,) = [t for t in found if t.name == "RPaRR (1∥3∥4)"]
    (d,) = mechanisms(mo, types=[t], every_actuation=True)
    assert d.name == "3-RPaRR (1∥3∥4)"
    assert (d.mobility.mobility, d.mobility.motion, d.mobility.passive) == (3, "3T", 0)
    assert d.second_order[:4] == (3, 3, 1, False)  # with the Pa's own term (the turning rods)
    assert d.actuated == 0 and 0 in d.actuations  # the base revolute, the Delta's motor
    # the Delta's own leg, by hand (the bar along the arm's axis u, so the hinges are
    # normal to u), passes; with the hinges along u it has a passive freedom
    from screwsym.systems.joints import Parallelogram
    u = [0, 1, 0]
    delta_leg = Limb(R([2, 0, 0], u), R([3, 0, -1], u),
                     Parallelogram([3, 0, -1], [3, 1, -1], [1, 0, -3]), R([1, 0, -3], u))
    assert refusals(delta_leg, mo) == ()
    flat = Limb(R([2, 0, 0], u), R([3, 0, -1], u),
                Parallelogram([3, 0, -1], [4, 0, -1], [1, 0, -3]), R([1, 0, -3], u))
    assert refusals(flat, mo) == ("limb: its joint twists are dependent (a passive freedom)",)


def test_the_delta_with_rod_pairs_has_only_idle_extra_freedoms():
    # the Delta as built, (R)(SS)^2 per leg (Clavel 1988): mobility 9 by the exact analysis
    # of the linkage, 3 translations of the platform and 6 passive freedoms, the rods' spins
    from _linkages import DELTA_RADIAL, HALF, add, scale

    from screwsym.systems.joints import S
    from screwsym.systems.linkage import Mechanism

    def leg(i, e):
        u = [-e[1], e[0], 0]
        elbow, attach = add(scale(3, e), [0, 0, -1]), add([0, 0, -3], e)
        return [("base", f"arm{i}", R(scale(2, e), u))] + [
            t for k, w in enumerate((scale(HALF, u), scale(-HALF, u)))
            for t in ((f"arm{i}", f"rod{i}{k}", S(add(elbow, w))),
                      (f"rod{i}{k}", "platform", S(add(attach, w))))]

    m = Mechanism([t for i, e in enumerate(DELTA_RADIAL) for t in leg(i, e)], base="base")
    mob = m.mobility()
    assert (mob.mobility, mob.passive) == (9, 6) and m.motion("platform") == "3T"


def test_the_h4_type_limb_with_the_plate_revolute_folded_in():
    # the H4 (Pierrot & Company 1999): Delta legs R-R-Pa-R on an articulated plate whose
    # revolute about z gives the fourth freedom.  With a rigid platform, that revolute goes
    # into each limb: R_u R_u Pa R_u R_z, read from the platform "RRPaRR (1∥z, 2∥4∥5)";
    # four of them give the Schoenflies motion.  (The full enumeration of 3T1R limbs of R
    # and Pa with five joints, benchmarks/bench_synthesis.py, finds it among 235.)
    mo = motion("3T1R")
    h4 = LimbType(mo, (("R", 0, "g"), ("R", 1, "g"), ("Pa", 2, "-"), ("R", 1, "g"),
                       ("R", 1, "g")))
    assert h4.name == "RRPaRR (1∥z, 2∥4∥5)"
    (d,) = mechanisms(mo, 4, types=[h4], every_actuation=True)
    assert (d.mobility.mobility, d.mobility.motion, d.mobility.passive) == (4, "3T1R", 0)
    # every joint but the revolute about z drives it; 4 is the H4's motor (the arm's revolute,
    # on the base side of the leg: the type is read from the platform)
    assert d.actuations == (1, 2, 3, 4)
    # and a Pa in a planar chain about z: the 4-joint Schoenflies limb R_z Pa R_z R_z
    found = limbs(mo, kinds=("R", "Pa"), max_joints=4)
    assert "RPaRR (1∥3∥4∥z)" in names(found) and len(found) == 29


def test_a_parallelogram_is_refused_where_its_turning_leaves_the_motion():
    # a spherical leg R(O) R_b X R_b R(O) (Kong & Gosselin 2004, 3-DOF spherical PMs: a
    # planar chain normal to b between two axes through the centre): a slide X normal to b
    # passes; a parallelogram whose output moves normal to b at the instance passes only
    # with its hinges along b (its translation then turns in the plane normal to b);
    # hinges normal to b turn the translation out of that plane: refused at second order
    from screwsym.systems.joints import Parallelogram
    mo, z = motion("3R"), [0, 0, 1]

    def leg(mid):
        return Limb(R(O3, [1, 2, 3]), R([5, 1, 0], z), mid, R([1, -4, 2], z), R(O3, [2, -1, 1]))

    assert refusals(leg(P([0, -1, 0])), mo) == ()
    assert refusals(leg(Parallelogram(O3, [1, 0, 0], [0, 1, 0])), mo) == ()
    tilted = Parallelogram(O3, [0, 1, 1], [0, 0, 1])  # its twist (0; 0, -1, 0) too
    (tw,) = tilted.twists
    assert list(tw.matrix) == [0, 0, 0, 0, -1, 0]
    assert refusals(leg(tilted), mo) == (
        "limb: its motion does not extend to second order within the wanted motion",)
    assert refusals(leg(P([1, -1, 2])), mo) == (
        "limb: its twists do not contain the wanted motion",)


# ------------------------------------------------------------ perpendicular relations
def test_spherical_legs_with_a_slide_need_a_perpendicular_relation():
    # Kong & Gosselin, "Type synthesis of 3-DOF spherical parallel manipulators based on
    # screw theory", ASME J. Mech. Des. 126 (2004) 101-108: legs with one constraint force
    # through the centre, e.g. two axes through O around a planar chain whose slide is
    # normal to its revolutes.  The grammar names the relation "3⟂2"
    mo = motion("3R")
    seq = (("R", 0, "c"), ("R", 1, "g"), ("P", 2, "-"), ("R", 1, "g"), ("R", 3, "c"))
    leg = LimbType(mo, seq, ((1, 2),))
    assert leg.name == "RRPRR (2∥4, 3⟂2, 1,5 through O)"
    assert refusals(leg.instance(seed=2), mo) == ()
    with pytest.raises(ValueError, match="seed: no generic instance"):
        LimbType(mo, seq).instance()  # without the relation: not a spherical leg
    (d,) = mechanisms(mo, types=[leg])
    assert (d.mobility.mobility, d.mobility.motion, d.mobility.passive) == (3, "3R", 0)
    assert d.second_order[:4] == (3, 3, 1, False) and d.actuated == 0
    # a slide normal to a plane (two relations): P P R with R normal to both slides
    plane = LimbType(mo, (("P", 0, "-"), ("P", 1, "-"), ("R", 2, "g"), ("R", 3, "c"),
                          ("R", 4, "c")), ((0, 2), (1, 2)))
    assert plane.name == "PPRRR (3⟂1, 3⟂2, 4,5 through O)"
    assert refusals(plane.instance(), mo) == ()
    with pytest.raises(ValueError, match="perpendicular: expected pairs of two direction"):
        LimbType(mo, seq, ((1, 7),)).instance()  # no joint has the label 7


def test_perpendicular_relations_are_named_only_where_needed():
    # with perpendicular=True nothing changes where the generic types pass: the planar
    # chains of 2T1R (Merlet 2006) keep their "⊥z" slides, no "⟂z" twin; and 3T limbs of
    # four joints need no perpendicular relation (Kong & Gosselin 2004 name none)
    assert names(limbs(motion("2T1R"), max_joints=3, perpendicular=True)) == \
        names(limbs(motion("2T1R"), max_joints=3))
    assert names(limbs(motion("3T"), max_joints=4, perpendicular=True)) == \
        names(limbs(motion("3T"), max_joints=4))


# ------------------------------------------------------------ asymmetric designs
def test_mixed_designs_of_unequal_limbs_are_certified_too():
    # the 3T limbs combine freely: each supplies couples only, and three limbs in general
    # position span all three (Kong & Gosselin 2004); so every multiset of three of PPP,
    # the 3-CRR's limb and the Delta-type limb, not all equal, is a 3T design: 10 - 3 = 7
    mo = motion("3T")
    pool = [t for t in limbs(mo, kinds=("R", "P", "Pa"), max_joints=4)
            if t.name in ("PPP", "CRR (1∥2∥3∥4)", "RPaRR (1∥3∥4)")]
    designs = mechanisms(mo, types=pool, mixed=True)
    assert len(pool) == 3 and len(designs) == 7
    assert "1-PPP + 1-CRR (1∥2∥3∥4) + 1-RPaRR (1∥3∥4)" in {d.name for d in designs}
    for d in designs:
        assert len(set(d.limb_types)) > 1 and len(d.mechanism.limbs) == 3
        assert (d.mobility.mobility, d.mobility.motion, d.mobility.passive) == (3, "3T", 0)
        assert d.actuated is not None
    assert refusals(designs[-1].mechanism, mo) == ()
