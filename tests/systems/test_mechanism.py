"""Joints, limbs and the mobility of worked parallel mechanisms, against the literature.

Each test names its source for the expected degrees of freedom and motion type.
The modified Grübler–Kutzbach criterion M = d(n - g - 1) + sum f + nu - zeta is
Huang, Li & Ding, *Theory of Parallel Mechanisms* (Springer 2013), Chapter 5,
after Huang, Zhao & Zhao, "Mobility of parallel mechanisms" (2003) and Huang,
Liu & Zeng (2009)/Huang, Li & Ding Ch. 2 for the common constraints lambda.
"""

from __future__ import annotations

import numpy as np
import pytest
from _mechanisms import E, O, Z, four_bar, three_rps
from sympy import Matrix, Rational, cancel, expand, sqrt, symbols, true

from screwsym import ScrewSystem, reciprocal_product
from screwsym.numeric.mobility import mobility_map
from screwsym.systems.joints import C, H, P, R, S, U
from screwsym.systems.motion_type import motion_type
from screwsym.systems.parallel import Limb, Mobility, ParallelMechanism


def sub(a, b):
    return [x - y for x, y in zip(a, b, strict=True)]


def cross(a, b):
    return list(Matrix(a).cross(Matrix(b)))


def check_consistent(m: Mobility, mech: ParallelMechanism):
    """The criterion agrees with the platform's twist system; twists reciprocal to constraints."""
    assert m.mobility == m.twists.rank == 6 - mech.constraints.rank
    assert m.order == 6 - m.common
    assert m.rotations + m.translations == m.twists.rank
    for t in m.twists:
        for w in mech.constraints:
            assert expand(reciprocal_product(t, w)) == 0


# ------------------------------------------------------------- mechanisms


def upu_leg(b, a1, top):
    """Tsai's UPU leg: base U (a1, a2), P along the leg, platform U (a2, a1), axes parallel."""
    d = sub(top, b)
    a2 = cross(a1, d)
    return Limb(U(b, a1, a2), P(d), U(top, a2, a1))


UPU_BASE = [[2, 0, 0], [-1, 2, 0], [-1, -2, 0], [1, -3, 0]]
UPU_AXIS = [[0, 1, 0], [-2, -1, 0], [2, -1, 0], [3, 1, 0]]
UPU_TOP = [[1, 0, 3], [0, 1, 3], [0, -1, 3], [1, -1, 3]]


def stewart(first=U):
    base = [[3, 0, 0], [2, 2, 0], [-1, 3, 0], [-3, 0, 0], [-1, -3, 0], [2, -2, 0]]
    top = [[1, 1, 2], [-1, 1, 2], [-1, 0, 2], [-1, -1, 2], [0, -1, 2], [1, -1, 3]]
    legs = []
    for b, p in zip(base, top, strict=True):
        j = U(b, [1, 0, 0], [0, 1, 0]) if first is U else S(b)
        legs.append(Limb(j, P(sub(p, b)), S(p)))
    return ParallelMechanism(*legs)


# ------------------------------------------------------------------ tests


def test_four_bar():
    # 1 DOF; the classical count gives 6(4-4-1)+4 = -2 (Huang, Li & Ding, Ch. 2 and 5:
    # the planar four-bar has lambda = 3 common constraints, d = 3, M = 3(-1)+4 = 1)
    mech = four_bar()
    m = mech.mobility()
    assert (m.mobility, m.classical, m.common, m.order, m.redundant, m.passive) == (1, -2, 3, 3, 0, 0)
    assert (m.links, m.joints, m.freedoms) == (4, 4, 4)
    assert m.motion == "1R"  # an instantaneous rotation about the instant centre
    check_consistent(m, mech)


def test_four_bar_collinear_singularity():
    # all four joints on one line: the coupler gains an instantaneous freedom, the
    # "uncertainty configuration" of a change-point four-bar (Norton, Design of
    # Machinery, §2.15; Gosselin & Angeles 1990, IEEE T-RA 6(3), type II singularity)
    bx, by = symbols("b_x b_y", real=True)
    mech = four_bar(B=(bx, by, 0), Cp=(3, 0, 0))
    cases = mech.mobility_cases()
    by_dof = {m.mobility: c for c, m in cases}
    assert cases[0][1].mobility == 1 and by_dof[2].free_symbols == {by} | {bx}
    two = [c for c, m in cases if m.mobility == 2]
    assert two and all(c.xreplace({by: 0, bx: 1}) is true for c in two[:1])
    assert mech.xreplace({by: 0, bx: 1}).mobility().mobility == 2
    assert mech.xreplace({by: 0, bx: 1}).mobility().motion == "1T1R"


def test_stewart_gough_6ups():
    # 6 DOF, 3T3R (Gough 1956; Stewart 1965; Merlet, Parallel Robots, 2006, Ch. 1)
    mech = stewart()
    m = mech.mobility()
    assert (m.mobility, m.motion, m.classical, m.common, m.redundant, m.passive) == (
        6, "3T3R", 6, 0, 0, 0)
    assert mech.constraints.rank == 0
    check_consistent(m, mech)


def test_stewart_gough_6sps_has_six_passive_freedoms():
    # 6-SPS: each leg spins about its own axis; the classical count gives
    # 6(14-18-1)+42 = 12, the platform has 6 (Tsai, Robot Analysis, 1999, §1.4:
    # mobility 12 minus 6 idle/passive leg rotations)
    m = stewart(first=S).mobility()
    assert (m.mobility, m.classical, m.passive, m.motion) == (6, 12, 6, "3T3R")


def test_three_rps():
    # 3 DOF, two rotations and one translation (Hunt 1983, J. Mech. Trans. Autom. Des.
    # 105; Lee & Shah 1988, J. Mech. Trans. Autom. Des. 110)
    mech = three_rps()
    m = mech.mobility()
    assert (m.mobility, m.motion, m.classical, m.common, m.redundant, m.passive) == (
        3, "1T2R", 3, 0, 0, 0)
    # each leg transmits one force, through its sphere centre along its R axis (Huang,
    # Li & Ding, Ch. 5: constraint analysis of 3-RPS)
    for limb in mech.limbs:
        (w,) = limb.constraints
        rj, _, sj = limb.joints
        assert Matrix(w.f).cross(rj.args[1]) == Matrix([0, 0, 0])
        assert expand(Matrix(w.C_O) - Matrix(sj.args[0]).cross(w.f)) == Matrix([0, 0, 0])
    check_consistent(m, mech)


@pytest.mark.slow
def test_three_rps_symbolic_and_its_constraint_singularity():
    # generic: 3 DOF, two angular velocities of which one is instantaneously helical
    # ("1T1R1H", the parasitic motion; see test_three_prs).  Legs at one height with the three constraint forces concurrent
    # (here rho1 + rho2 + rho3 = -6 with base radius 2): the forces are coplanar and
    # concurrent, rank 2, and the platform gains a rotation, 4 DOF 1T3R (a constraint
    # singularity: Zlatanov, Bonev & Gosselin, ICRA 2002; for 3-RPS see Schadlbauer,
    # Walter & Husty, Mech. Mach. Theory 77, 2014)
    rho = symbols("rho1:4", real=True)
    h = symbols("h1:4", positive=True)
    mech = three_rps(rho, h)
    cases = mech.mobility_cases()
    assert cases[0][1].mobility == 3 and cases[0][1].motion == "1T1R1H"
    singular = [(c, m) for c, m in cases if m.mobility != 3]
    assert len(singular) == 1
    cond, m = singular[0]
    assert (m.mobility, m.motion) == (4, "1T3R")
    at = {rho[0]: 1, rho[1]: -3, rho[2]: -4, h[0]: 2, h[1]: 2, h[2]: 2}
    assert cond.xreplace(at) is true
    assert all(c.xreplace(at) is not true for c, mm in cases if mm.mobility == 3)
    # independently, in floating point
    f = mobility_map(mech, [*rho, *h])
    vals = [np.array([at[s], 0.5]) for s in (*rho, *h)]
    assert list(f(*vals).mobility) == [4, 3]


def test_three_rrr_spherical():
    # 3 DOF, three rotations about the common centre (Gosselin & Angeles 1989,
    # J. Mech. Trans. Autom. Des. 111); lambda = 3, d = 3 (Huang, Li & Ding, Ch. 5)
    mech = ParallelMechanism(
        Limb(R(O, [1, 0, 0]), R(O, [0, 1, 1]), R(O, [1, 1, 2])),
        Limb(R(O, [0, 1, 0]), R(O, [1, 0, 1]), R(O, [2, 1, 1])),
        Limb(R(O, [0, 0, 1]), R(O, [1, 1, 0]), R(O, [1, 2, 1])),
    )
    m = mech.mobility()
    assert (m.mobility, m.motion, m.classical, m.common, m.order, m.redundant) == (
        3, "3R", -3, 3, 3, 0)
    check_consistent(m, mech)


def test_three_upu_translational():
    # 3 DOF pure translation (Tsai 1996, ASME DETC 96/MECH-1152; Tsai & Joshi 2000):
    # each leg transmits one couple normal to its two U axes
    legs = zip(UPU_BASE[:3], UPU_AXIS[:3], UPU_TOP[:3], strict=True)
    mech = ParallelMechanism(*(upu_leg(*x) for x in legs))
    m = mech.mobility()
    assert (m.mobility, m.motion, m.classical, m.redundant) == (3, "3T", 3, 0)
    for limb in mech.limbs:
        (w,) = limb.constraints
        assert w.f == Matrix([0, 0, 0])  # a couple
    check_consistent(m, mech)


def test_four_upu_is_overconstrained():
    # a fourth UPU leg adds a fourth couple in the span of the other three: nu = 1, so
    # the classical count 6(10-12-1)+20 = 2 is wrong and the criterion gives 3
    # (expected motion as Tsai's 3-UPU, above; nu by the definition of Huang, Li &
    # Ding, Ch. 5: constraints in excess of the rank of their union)
    legs = zip(UPU_BASE, UPU_AXIS, UPU_TOP, strict=True)
    mech = ParallelMechanism(*(upu_leg(*x) for x in legs))
    m = mech.mobility()
    assert (m.mobility, m.motion, m.classical, m.redundant, m.common) == (3, "3T", 2, 1, 0)
    check_consistent(m, mech)


def test_three_rrr_planar():
    # 3 DOF, two translations in the plane and the rotation normal to it (Gosselin &
    # Angeles 1990, IEEE T-RA 6(3); Merlet, Parallel Robots, Ch. 2); lambda = 3, d = 3
    mech = ParallelMechanism(
        Limb(R(O, Z), R([1, 1, 0], Z), R([2, 1, 0], Z)),
        Limb(R([4, 0, 0], Z), R([4, 2, 0], Z), R([3, 2, 0], Z)),
        Limb(R([2, 4, 0], Z), R([1, 3, 0], Z), R([2, 2, 0], Z)),
    )
    m = mech.mobility()
    assert (m.mobility, m.motion, m.classical, m.common, m.redundant) == (3, "2T1R", -3, 3, 0)
    check_consistent(m, mech)


def test_three_prs():
    # 3 DOF, 1T2R (Carretero, Podhorodeski, Nahon & Gosselin 2000, J. Mech. Des. 122:
    # vertical P, R tangent to the base circle, S on the platform)
    s = symbols("s1:4", real=True)

    def leg(i):
        e = E[i]
        hinge = [2 * e[0], 2 * e[1], s[i]]
        top = [e[0], e[1], s[i] + 2]
        return Limb(P(Z), R(hinge, [-e[1], e[0], 0]), S(top))

    mech = ParallelMechanism(*(leg(i) for i in range(3)))
    m = mech.mobility()
    # the literature's 1T2R holds where two sliders are at one height; at a generic pose one
    # of the two rotations is instantaneously a helix (the parasitic motion couples it with a
    # horizontal translation), with the pitch below, zero where two heights agree
    assert (m.mobility, m.motion, m.classical) == (3, "1T1R1H", 3)
    (p,) = m.helical_pitches
    s1, s2, s3 = s
    q = s1**2 + s2**2 + s3**2 - s1 * s2 - s1 * s3 - s2 * s3
    assert cancel(p + sqrt(3) * (s1 - s2) * (s1 - s3) * (s2 - s3) / (2 * q)) == 0
    assert mech.xreplace({s2: s1}).mobility().motion == "1T2R"
    check_consistent(m, mech)
    # independent (NumPy): at heights (0, 1, 3) the constraint forces run through the S
    # centres along the R axes; their reciprocal twists with omega horizontal (orthogonal to
    # the vertical translation) are that translation and one helix, whose pitch is the one
    h = np.array([0.0, 1.0, 3.0])
    F = []
    for i in range(3):
        e = np.array([float(x) for x in E[i]])
        u, top = np.array([-e[1], e[0], 0.0]), np.array([e[0], e[1], h[i] + 2])
        F.append(np.r_[np.cross(top, u), u])  # the force's row of (Delta W)^T: (C; f)
    T = np.linalg.svd(np.array(F))[2][3:].T  # twists (omega; v), 6 x 3
    horizontal = T @ np.linalg.svd(T[2:3])[2][1:].T  # omega_z = 0: 6 x 2
    x = horizontal @ np.linalg.svd(horizontal[:3])[2][0]  # the one with omega != 0
    value = float(p.subs(dict(zip(s, h, strict=True))))
    assert abs(x[:3] @ x[3:] / (x[:3] @ x[:3]) - value) < 1e-12 and abs(value) > 0.1


# ----------------------------------------------------------------- joints


def test_joint_twists():
    assert R([1, 0, 0], Z).twists.matrix.T.tolist() == [[0, 0, 1, 0, -1, 0]]
    assert P([1, 2, 3]).twists.matrix.T.tolist() == [[0, 0, 0, 1, 2, 3]]
    assert H(O, Z, 2).twists.matrix.T.tolist() == [[0, 0, 1, 0, 0, 2]]
    assert C(O, Z).twists.rank == 2 and C(O, Z).freedom == 2
    assert U(O, [1, 0, 0], [0, 1, 0]).twists.rank == 2
    assert S([1, 2, 3]).twists.rank == 3 and S(O).freedom == 3
    leg = Limb(R(O, Z), P([1, 0, 0]), S([1, 0, 1]))
    assert leg.freedom == 5 and leg.passive == 0
    assert Limb(S(O), S([0, 0, 1])).passive == 1  # the S-S link spins about its axis


def test_motion_type_names():
    assert [motion_type(*x) for x in ((3, 3), (2, 1), (0, 3), (1, 0), (0, 0))] == [
        "3T3R", "1T2R", "3T", "1R", "0"]


def test_objects_are_basic():
    mech = four_bar()
    assert mech.func(*mech.args) == mech
    a = symbols("a", real=True)
    leg = Limb(R([a, 0, 0], Z), P(Z))
    assert leg.subs(a, 1) == Limb(R([1, 0, 0], Z), P(Z))
    with pytest.raises(TypeError, match="strings are never evaluated"):
        leg.subs(a, "1")
    assert isinstance(leg.twists, ScrewSystem)


def test_bad_input():
    message = r"direction: a joint axis needs a non-zero direction, got \[0, 0, 0\]"
    with pytest.raises(ValueError, match=message):
        R(O, [0, 0, 0])
    with pytest.raises(ValueError, match="dir2: a joint axis needs a non-zero direction"):
        U(O, Z, [0, 0, 0])
    with pytest.raises(ValueError, match="point: expected a 3-vector, got shape"):
        S([1, 2])
    with pytest.raises(ValueError, match="joints: expected at least one joint, got none"):
        Limb()
    with pytest.raises(TypeError, match=r"joints\[1\]: expected a joint \(Revolute, Prismatic, Helical, Cylindrical, Universal or Spherical\)"):
        Limb(R(O, Z), [1, 0, 0])
    with pytest.raises(ValueError, match="limbs: expected at least one limb, got none"):
        ParallelMechanism()
    with pytest.raises(TypeError, match=r"limbs\[0\]: expected a Limb, got R"):
        ParallelMechanism(R(O, Z))
    with pytest.raises(TypeError, match="pitch: expected a real number"):
        H(O, Z, "2")


def test_joints_refuse_floats_naming_the_argument():
    # the ranks are exact: a float was accepted here and refused later by the limb's screw
    # system, as "screws[0]: ... got the float -0.5" (a moment the user never wrote)
    exact = r"expected exact entries .* got the float 0.5"
    with pytest.raises(ValueError, match=rf"^point: {exact}"):
        R([0.5, 0, 0], Z)
    with pytest.raises(ValueError, match=rf"^direction: {exact}"):
        P([0, 0.5, 1])
    with pytest.raises(ValueError, match=rf"^pitch: {exact}"):
        H(O, Z, 0.5)
    with pytest.raises(ValueError, match=rf"^dir1: {exact}"):
        U(O, [0.5, 1, 0], Z)
    with pytest.raises(ValueError, match=rf"^point: {exact}"):
        S([0, 0, 0.5])
    assert R([Rational(1, 2), 0, 0], Z).twists.rank == 1


# ---------------------------------------------------------------- numeric


def test_which_rotations_and_translations():
    # 3-UPU: the three translations; planar 3-RRR: rotation about z, translations in the plane
    legs = zip(UPU_BASE[:3], UPU_AXIS[:3], UPU_TOP[:3], strict=True)
    m = ParallelMechanism(*(upu_leg(*x) for x in legs)).mobility()
    assert m.rotation_directions.shape == (3, 0)
    assert Matrix(m.translation_directions).rank() == 3
    m = ParallelMechanism(
        Limb(R(O, Z), R([1, 1, 0], Z), R([2, 1, 0], Z)),
        Limb(R([4, 0, 0], Z), R([4, 2, 0], Z), R([3, 2, 0], Z)),
        Limb(R([2, 4, 0], Z), R([1, 3, 0], Z), R([2, 2, 0], Z)),
    ).mobility()
    (w,) = m.rotation_directions.T.tolist()
    assert w[0] == w[1] == 0 and w[2] != 0
    assert m.translation_directions.shape == (3, 2)
    assert all(e == 0 for e in m.translation_directions[2, :])


def test_joint_twists_match_modern_robotics():
    # modern_robotics' ScrewToAxis(q, s, h) = (s; -s x q + h s): the same convention as R and H
    mr = pytest.importorskip("modern_robotics")
    q, s_, h = [1.0, 2.0, 3.0], [0.0, 0.6, 0.8], 0.5
    ours = np.array(H([1, 2, 3], [0, Rational(3, 5), Rational(4, 5)], Rational(1, 2))
                    .twists.matrix, dtype=float).ravel()
    assert np.allclose(ours, mr.ScrewToAxis(np.array(q), np.array(s_), h))
    ours_r = np.array(R([1, 2, 3], [0, Rational(3, 5), Rational(4, 5)]).twists.matrix,
                      dtype=float).ravel()
    assert np.allclose(ours_r, mr.ScrewToAxis(np.array(q), np.array(s_), 0))


def test_three_upu_constraint_singularity():
    # Tsai's 3-UPU meets constraint singularities where its three constraint couples become
    # linearly dependent, and gains a rotation there (Zlatanov, Bonev & Gosselin,
    # "Constraint singularities of parallel mechanisms", ICRA 2002, the 3-UPU example;
    # Parenti-Castelli & Di Gregorio 2000).  Here the third platform joint slides along x.
    x, z = symbols("x", real=True), symbols("z", positive=True)
    tops = [[1, 0, z], [0, 1, z], [x, -1, z]]
    legs = zip(UPU_BASE[:3], UPU_AXIS[:3], tops, strict=True)
    mech = ParallelMechanism(*(upu_leg(*leg) for leg in legs))
    cases = mech.mobility_cases()
    assert [(m.mobility, m.motion) for _, m in cases] == [(3, "3T"), (4, "3T1R")]
    singular = cases[1][0]
    assert singular.xreplace({x: Rational(-48, 11), z: 3}) is true
    # the three couples are dependent there, independent elsewhere (exactly and in floats)
    couples = lambda at: Matrix.hstack(*(limb.constraints.matrix[3:, :]  # noqa: E731
                                         for limb in mech.xreplace(at).limbs))
    assert couples({x: Rational(-48, 11), z: 3}).rank() == 2
    assert couples({x: 0, z: 3}).rank() == 3
    f = mobility_map(mech, [x, z])
    assert list(f(np.array([-48 / 11, 0.0]), 3.0).mobility) == [4, 3]


def test_sarrus_linkage():
    # Sarrus (1853): two planar 3R chains with perpendicular axes give the platform one
    # translation; the classical count gives 6(6-6-1)+6 = 0 (Gogu, "Mobility of
    # mechanisms: a critical review", Mech. Mach. Theory 40, 2005).  Here lambda = 1 (the
    # couple about z is common), d = 5: M = 5(-1)+6 = 1.
    X, Y = [1, 0, 0], [0, 1, 0]
    mech = ParallelMechanism(
        Limb(R([0, 0, 0], X), R([0, 1, 1], X), R([0, 0, 2], X)),
        Limb(R([0, 0, 0], Y), R([1, 0, 1], Y), R([0, 0, 2], Y)),
    )
    m = mech.mobility()
    assert (m.mobility, m.motion, m.classical, m.common, m.order, m.redundant) == (1, "1T", 0, 1, 5, 0)
    assert Matrix(m.translation_directions).cross(Matrix(Z)) == Matrix([0, 0, 0])  # along z
    check_consistent(m, mech)


def assert_mobility_cases_exhaustive(mech, points):
    """At each point: some case holds, and every case that holds gives the exact DOF there."""
    cases = mech.mobility_cases()
    for point in points:
        exact = mech.xreplace(point).mobility().mobility
        holding = [m for c, m in cases if c.xreplace(point) is true]
        assert holding, f"no case holds at {point}"
        assert all(m is None or m.mobility == exact for m in holding), (point, exact)


def test_mobility_cases_are_exhaustive_at_special_and_random_points():
    bx, by = symbols("b_x b_y", real=True)
    fourbar = four_bar(B=(bx, by, 0), Cp=(3, 0, 0))
    grid = [{bx: u, by: v} for u in (-1, 0, 3, 4, Rational(7, 2)) for v in (0, 1, Rational(-2, 3))]
    assert_mobility_cases_exhaustive(fourbar, grid)
    x, z = symbols("x", real=True), symbols("z", positive=True)
    legs = zip(UPU_BASE[:3], UPU_AXIS[:3], [[1, 0, z], [0, 1, z], [x, -1, z]], strict=True)
    upu = ParallelMechanism(*(upu_leg(*leg) for leg in legs))
    pts = [{x: u, z: w} for u in (Rational(-48, 11), 0, -1, -3) for w in (1, 3)]
    assert_mobility_cases_exhaustive(upu, pts)


def test_assert_mobility_cases_exhaustive_rejects_a_wrong_dof():
    bx, by = symbols("b_x b_y", real=True)
    fourbar = four_bar(B=(bx, by, 0), Cp=(3, 0, 0))

    class Lying:
        def mobility_cases(self):
            return [(c, m._replace(mobility=1)) for c, m in fourbar.mobility_cases()]

        def xreplace(self, point):
            return fourbar.xreplace(point)

    with pytest.raises(AssertionError):
        assert_mobility_cases_exhaustive(Lying(), [{bx: 1, by: 0}])


def test_an_unconstrained_platform_has_twists():
    # 6-DOF limbs leave no constraint: the empty constraint system is of wrenches, and the
    # platform's twist system (its reciprocal) holds twists
    from screwsym import Twist, Wrench
    from screwsym.systems.joints import Prismatic, S, U
    from screwsym.systems.parallel import Limb, ParallelMechanism

    legs = [Limb(U([k, 0, 0], [1, 0, 0], [0, 1, 0]), Prismatic([0, 0, 1]), S([k, 0, 1]))
            for k in range(6)]
    mech = ParallelMechanism(*legs)
    assert mech.constraints.kind is Wrench and len(mech.constraints) == 0
    assert mech.twists.kind is Twist and mech.mobility().twists.kind is Twist


def test_mobility_cases_with_the_same_answer_are_merged():
    from sympy import Eq, Ne, symbols

    b, c = symbols("b c", real=True)
    z = [0, 0, 1]
    fourbar = ParallelMechanism(Limb(R([0, 0, 0], z), R([1, b, 0], z)),
                                Limb(R([4, 0, 0], z), R([3, c, 0], z)))
    each = fourbar.mobility_cases(merge=False)
    merged = fourbar.mobility_cases()
    assert [m.answer() for _, m in each][:2] == [each[0][1].answer()] * 2 and len(each) == 3
    assert [(cond, m.mobility, m.motion) for cond, m in merged] == [
        (Ne(b, 0) | Ne(c, 0), 1, "1R"), (Eq(b, 0) & Eq(c, 0), 2, "1T1R")]
    assert merged[0][1] == each[0][1]  # the first case's analysis, twists included
    # the merged conditions still cover every point, the same answer at each
    for point in ({b: 0, c: 0}, {b: 1, c: 0}, {b: 0, c: 2}, {b: 3, c: -1}):
        hit = [m.answer() for cond, m in merged if cond.subs(point)]
        want = [m.answer() for cond, m in each if cond.subs(point)]
        assert hit == want
    with pytest.raises(TypeError, match="merge: expected True or False"):
        fourbar.mobility_cases(merge="no")


def test_mobility_prints_as_a_short_summary_and_keeps_its_fields():
    z = [0, 0, 1]
    m = ParallelMechanism(Limb(R([0, 0, 0], z), R([1, 2, 0], z)),
                          Limb(R([4, 0, 0], z), R([3, 3, 0], z))).mobility()
    assert repr(m) == ("Mobility(mobility=1, motion='1R', common=3, redundant=0, passive=0, "
                       "classical=-2)")
    assert m.links == 4 and m.joints == 4 and m.twists.rank == 1 and len(m) == 17
    assert m.helical_pitches == () and m.internal == 0


def test_a_universal_joint_with_parallel_axes_is_refused():
    # issue 20: U(p, [1, 0, 0], [2, 0, 0]) is one revolute joint; accepted, every mobility
    # built on it was wrong by one
    with pytest.raises(ValueError, match=r"dir2: a universal joint needs two non-parallel "
                                         r"axes, got dir1 = \[1, 0, 0\] and dir2 = \[2, 0, 0\]"):
        U([0, 0, 0], [1, 0, 0], [2, 0, 0])
    with pytest.raises(ValueError, match="dir2: a universal joint needs two non-parallel"):
        U([0, 0, 0], [1, 2, 3], [-2, -4, -6])
    a = symbols("a", real=True)
    assert U([0, 0, 0], [1, 0, 0], [a, 1, 0]).freedom == 2  # never parallel: kept
    assert U([0, 0, 0], [1, 0, 0], [1, a, 0]).freedom == 2  # parallel only at a = 0: kept


def test_the_case_limit_names_the_method_the_user_called():
    # the splitter is shared (ScrewSystem.rank_conditions, both mobility_cases): its errors
    # name the method called, not the splitter's first user
    from screwsym.systems.linkage import Mechanism

    b = symbols("b", real=True)
    mech = four_bar(B=(1, b, 0), Cp=(3, 0, 0))  # folds flat where b = 0
    assert len(mech.mobility_cases(merge=False)) == 2  # so a limit of 1 is too small
    with pytest.raises(ValueError, match=r"^mobility_cases: .*more than 1 cases"):
        mech.mobility_cases(max_cases=1)
    with pytest.raises(ValueError, match=r"^mobility_cases: .*more than 1 cases"):
        Mechanism.from_parallel(mech).mobility_cases(max_cases=1)
    with pytest.raises(ValueError, match=r"^rank_conditions: .*more than 1 cases"):
        mech.constraints.rank_conditions(max_cases=1)
    c = symbols("c", real=True)  # a mechanism not split yet (a split's results are cached)
    with pytest.raises(ValueError, match=r"^mobility_cases: .*budget=10 units"):
        four_bar(B=(1, c, 0), Cp=(3, 0, 0)).mobility_cases(budget=10)
