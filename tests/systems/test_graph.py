"""Mechanisms of any topology (Davies' method), the parallelogram pair, and second-order mobility.

Each literature case names its source and is checked, where cheap, by an independent
floating-point finite motion (tests/_linkages.py: the loop closure solved by Gauss-Newton a
small step away, with exponentials and a spanning tree of its own).
"""

from __future__ import annotations

import random

import numpy as np
import pytest
from _linkages import (
    ISOGRAM,
    Closure,
    Z,
    assert_case_at,
    bennett,
    cross,
    delta,
    flat_parallelogram,
    four_r,
    h4,
    orthoglide,
    shaky_4r,
    stephenson,
    sub,
    watt,
)
from _mechanisms import O, four_bar, three_rps
from sympy import Matrix, Rational, expand, symbols, true

from screwsym import ScrewSystem, Twist
from screwsym.systems.joints import P, Parallelogram, R, S, U
from screwsym.systems.linkage import Mechanism
from screwsym.systems.parallel import Degenerate, Limb, ParallelMechanism
from screwsym.systems.second_order import lie_bracket


def same_span(a: ScrewSystem, b: ScrewSystem) -> bool:
    return a.rank == b.rank == (a | b).rank


def rates_of(mech, k=0):
    return np.array(mech.mobility().rates, dtype=float)[:, k]


# ------------------------------------------------- ParallelMechanism as a graph


def stewart_sps():
    base = [[3, 0, 0], [2, 2, 0], [-1, 3, 0], [-3, 0, 0], [-1, -3, 0], [2, -2, 0]]
    top = [[1, 1, 2], [-1, 1, 2], [-1, 0, 2], [-1, -1, 2], [0, -1, 2], [1, -1, 3]]
    return ParallelMechanism(*(Limb(S(b), P(sub(p, b)), S(p)) for b, p in zip(base, top, strict=True)))


def three_upu():
    def leg(b, a1, top):
        d = sub(top, b)
        a2 = cross(a1, d)
        return Limb(U(b, a1, a2), P(d), U(top, a2, a1))

    return ParallelMechanism(leg([2, 0, 0], [0, 1, 0], [1, 0, 3]),
                             leg([-1, 2, 0], [-2, -1, 0], [0, 1, 3]),
                             leg([-1, -2, 0], [2, -1, 0], [0, -1, 3]))


def sarrus():
    X, Y = [1, 0, 0], [0, 1, 0]
    return ParallelMechanism(Limb(R([0, 0, 0], X), R([0, 1, 1], X), R([0, 0, 2], X)),
                             Limb(R([0, 0, 0], Y), R([1, 0, 1], Y), R([0, 0, 2], Y)))


BX, BY = symbols("b_x b_y", real=True)
PARALLEL = {
    "four_bar": four_bar,
    "four_bar_symbolic": lambda: four_bar(B=(BX, BY, 0), Cp=(3, 0, 0)),
    "three_rps": three_rps,
    "stewart_6sps": stewart_sps,
    "three_upu": three_upu,
    "sarrus": sarrus,
}


SLOW = {"stewart_6sps", "three_rps"}  # over 2 s each (algebraic sqrt(3); 42 freedoms)


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow) if n in SLOW else n
                                  for n in sorted(PARALLEL)])
def test_from_parallel_gives_the_same_answers(name):
    # every mechanism of tests/_mechanisms.py (four-bar, 3-RPS) and of test_mechanism.py's
    # literature cases that are cheap: the graph's platform twists, motion type, passive
    # (idle) freedoms and classical count are ParallelMechanism's
    pm = PARALLEL[name]()
    old = pm.mobility()
    mech = Mechanism.from_parallel(pm)
    new = mech.mobility()
    T = mech.relative_twists("platform")
    assert T.rank == old.mobility
    assert same_span(T, old.twists)
    assert mech.motion("platform") == old.motion
    assert new.passive == old.passive
    assert new.classical == old.classical
    assert new.loops == len(pm.limbs) - 1
    assert new.mobility == old.mobility + old.passive  # joint rates: the platform's and the idle


def test_from_parallel_refuses_other_things():
    with pytest.raises(TypeError, match="pm: expected a ParallelMechanism, got Limb"):
        Mechanism.from_parallel(Limb(R(O, Z)))


# ------------------------------------------------------------- the graph


def test_loops_from_a_spanning_tree():
    m = watt()
    assert len(m.loops) == 2 == len(m.joints) - len(m.links) + 1
    assert m.network_matrix().shape == (12, 7)
    # each loop closes: going round it returns to the link it left
    for loop in m.loops:
        joints = m.joints
        e, s = loop[0]
        here = joints[e][1] if s == 1 else joints[e][0]
        for e, s in loop[1:]:
            a, b, _ = joints[e]
            assert here == (a if s == 1 else b)
            here = b if s == 1 else a
        first = joints[loop[0][0]]
        assert here == (first[0] if loop[0][1] == 1 else first[1])


def test_two_joints_between_two_links_make_a_loop():
    m = Mechanism([("g", "a", R(O, Z)), ("g", "a", R([1, 0, 0], Z))], base="g")
    assert len(m.loops) == 1 and m.mobility().mobility == 0


def test_a_tree_has_no_loop_and_moves_freely():
    # a serial R-R-P arm: no loop, every joint rate free; its end link is not idle
    m = Mechanism([("g", "a", R(O, Z)), ("a", "b", R([1, 0, 0], Z)), ("b", "c", P(Z))], base="g")
    mo = m.mobility()
    assert (mo.loops, mo.mobility, mo.passive, mo.redundant) == (0, 3, 0, 0)
    assert m.motion("c") == "2T1R" and m.motion("a") == "1R"
    assert m.second_order().mobility == 3


def test_a_rigid_triangle():
    # three revolutes on parallel axes not on one line: a structure, to every order
    m = Mechanism([("g", "a", R(O, Z)), ("a", "b", R([1, 0, 0], Z)), ("b", "g", R([0, 1, 0], Z))],
                  base="g")
    assert m.mobility().mobility == 0 and m.mobility().classical == -3
    so = m.second_order()
    assert (so.instantaneous, so.mobility, so.branches, so.several_branches) == (0, 0, 1, False)
    assert m.motion("b") == "0" and len(m.relative_twists("b")) == 0


def test_idle_freedoms_are_found_not_declared():
    # S-P-S closed on the base: its one joint motion spins the leg about its own line
    m = Mechanism([("g", "lo", S(O)), ("lo", "up", P(Z)), ("up", "g", S([0, 0, 2]))], base="g")
    mo = m.mobility()
    assert (mo.mobility, mo.passive) == (1, 1)
    spin = Matrix(mo.passive_rates)
    # the spin: the lower ball turns about z, the upper one back (the x, y, z order of S)
    assert spin.T * Matrix(m.network_matrix()).T == Matrix.zeros(1, 6)
    assert spin[2] != 0 and spin[2] == -spin[6] and all(spin[k] == 0 for k in (0, 1, 3, 4, 5))
    # a pendant link turning about its joint is no idle freedom; nor is a four-bar's motion
    arm = Mechanism([("g", "a", R(O, Z)), ("a", "b", S([1, 0, 0]))], base="g").mobility()
    assert (arm.mobility, arm.passive) == (4, 0)
    assert four_bar_graph().mobility().passive == 0


def four_bar_graph():
    return Mechanism.from_parallel(four_bar())


def test_common_and_redundant_constraints_of_a_planar_loop_and_the_delta():
    m = four_bar_graph().mobility()
    (W,) = m.common_constraints
    assert W.rank == 3 and m.orders == (3,)
    # the planar loop's common constraints: the force along z and the couples about x and y
    for w in W:
        for e in (Twist.rotation(Z, point=[7, 5, 0]), Twist.translation([2, 3, 0])):
            assert expand(w.reciprocal_product(e)) == 0
    d = delta().mobility()
    assert d.redundant == sum(d.orders) - d.rank == 3


def test_mechanism_is_basic_and_substitutes():
    a = symbols("a", real=True)
    m = Mechanism([("g", "x", R([a, 0, 0], Z)), ("x", "g", R([1, 0, 0], Z))], base="g")
    assert m.func(*m.args) == m
    assert m.xreplace({a: 2}).joints[0][2] == R([2, 0, 0], Z)
    assert m.links == ("g", "x") and m.base == "g"
    s = symbols("s")
    assert Mechanism([(s, 1, R(O, Z))], base=s).links == (s, 1)


def test_bad_input():
    r = R(O, Z)
    with pytest.raises(TypeError, match=r"joints: expected a list of \(link_a, link_b, joint\) triples, got str"):
        Mechanism("ab", base="a")
    with pytest.raises(TypeError, match=r"joints\[0\]: expected a triple \(link_a, link_b, joint\), got \('a', 'b'\)"):
        Mechanism([("a", "b")], base="a")
    with pytest.raises(TypeError, match=r"joints\[0\]\[2\]: expected a joint of screwsym.systems.joints"):
        Mechanism([("a", "b", [0, 0, 1])], base="a")
    with pytest.raises(TypeError, match=r"joints\[0\]\[1\]: expected a link name \(a string or a SymPy symbol\), got None"):
        Mechanism([("a", None, r)], base="a")
    with pytest.raises(TypeError, match=r"joints\[0\]\[0\]: expected a link name .* got float"):
        Mechanism([(1.5, "b", r)], base="b")
    with pytest.raises(ValueError, match=r"joints\[0\]: a joint joins two different links, got 'a' twice"):
        Mechanism([("a", "a", r)], base="a")
    with pytest.raises(ValueError, match=r"joints: expected at least one"):
        Mechanism([], base="a")
    with pytest.raises(TypeError, match="base: expected the name of the fixed link, got None"):
        Mechanism([("a", "b", r)])
    with pytest.raises(ValueError, match="base: 'c' is not a link of any joint"):
        Mechanism([("a", "b", r)], base="c")
    with pytest.raises(ValueError, match=r"joints: the links 'c', 'd' are not connected to the base 'a'"):
        Mechanism([("a", "b", r), ("c", "d", r)], base="a")
    m = Mechanism([("a", "b", r)], base="a")
    with pytest.raises(ValueError, match="link: 'z' is not a link of this mechanism"):
        m.relative_twists("z")
    with pytest.raises(ValueError, match="relative_to: 'z' is not a link"):
        m.relative_twists("b", relative_to="z")
    with pytest.raises(ValueError, match=r"rates: expected 1 joint rates, got shape \(2, 1\)"):
        m.quadratic_terms([1, 2])
    with pytest.raises(TypeError, match="a: expected a Twist, got list"):
        lie_bracket([0] * 6, Twist.translation(Z))


# ---------------------------------------------------------- parallelogram


def test_parallelogram_pair_equals_the_loop_built_link_by_link():
    # a four-bar parallelogram's output bar translates, along the circular translation's
    # tangent: the compound pair and the four revolutes give the same twist system
    for p1, p2, q1 in (([0, 0, 0], [1, 0, 0], [0, 0, 2]), ([1, 2, 0], [1, 2, 1], [4, 6, 3])):
        pa = Parallelogram(p1, p2, q1)
        loop = Mechanism(pa.links("in", "out"), base="in")
        assert loop.mobility().mobility == 1
        T = loop.relative_twists("out")
        assert same_span(T, pa.twists) and T.rank == 1 and loop.motion("out") == "1T"
        # the compound pair inside a limb: the same
        limb = Limb(R(O, Z), pa)
        assert limb.freedom == 2
    with pytest.raises(ValueError, match="p2: the input bar needs two distinct pivots"):
        Parallelogram(O, O, Z)
    with pytest.raises(ValueError, match="q1: the rod must not be parallel to the bar"):
        Parallelogram(O, [1, 0, 0], [2, 0, 0])


def parallelogram_legged(compound: bool):
    """A planar two-leg mechanism, one leg R-Pa (a parallelogram from the arm to the platform),
    the other R-R."""
    pa = Parallelogram([1, 1, 0], [2, 1, 0], [1, 3, 0])
    leg = [("arm1", "platform", pa)] if compound else pa.links("arm1", "platform")
    return Mechanism([("base", "arm1", R(O, Z)), *leg, ("base", "arm2", R([5, 0, 0], Z)),
                      ("arm2", "platform", R([4, 3, 0], Z))], base="base")


def test_a_parallelogram_legged_planar_mechanism():
    # one freedom: the planar Grübler count 3(n - j - 1) + F = 3(6 - 7 - 1) + 7 = 1 (Grübler
    # 1883; valid here, the loops being planar and not overconstrained in the plane), the
    # same with the parallelogram as one pair, 3(4 - 4 - 1) + 4 = 1, and as a ParallelMechanism
    a, b = parallelogram_legged(False), parallelogram_legged(True)
    ma, mb = a.mobility(), b.mobility()
    assert (ma.mobility, ma.loops, mb.mobility, mb.loops) == (1, 2, 1, 1)
    assert same_span(a.relative_twists("platform"), b.relative_twists("platform"))
    pm = ParallelMechanism(Limb(R(O, Z), b.joints[1][2]), Limb(R([5, 0, 0], Z), R([4, 3, 0], Z)))
    assert same_span(pm.mobility().twists, a.relative_twists("platform"))
    # the platform keeps the arm's orientation (the parallelogram): it turns with arm 1
    assert same_span(a.relative_twists("platform", relative_to="arm1"), ScrewSystem(Twist.translation(
        Parallelogram([1, 1, 0], [2, 1, 0], [1, 3, 0]).twists.matrix[3:, 0])))
    assert a.second_order().mobility == b.second_order().mobility == 1
    # finite motion: both close a step away, and the platform turns exactly as arm 1 does
    for mech in (a, b):
        c = Closure(mech)
        q, res = c.solve({0: 0.05}, start=0.05 * rates_of(mech) / rates_of(mech)[0])
        assert res < 1e-12
        D = c.poses(q)
        assert np.allclose(D["platform"][:3, :3], D["arm1"][:3, :3], atol=1e-12)
        assert not np.allclose(D["arm1"][:3, :3], np.eye(3), atol=1e-3)


# -------------------------------------------------------------- literature


def test_delta_robot_built_link_by_link_is_3t():
    # the Delta robot (Clavel 1988, "DELTA, a fast robot with parallel geometry", 18th ISIR):
    # three translations; here each leg R-R-Pa-R with four revolutes in the parallelogram
    # (17 links, 21 joints, 5 loops)
    m = delta()
    mo = m.mobility()
    assert (mo.links, mo.joints, mo.loops, mo.freedoms) == (17, 21, 5, 21)
    assert (mo.mobility, mo.passive) == (3, 0)
    assert mo.classical == 6 * (17 - 21 - 1) + 21 == -9
    T = m.relative_twists("platform")
    assert T.rank == 3 and m.motion("platform") == "3T"
    assert all(t.omega == Matrix([0, 0, 0]) for t in T)
    # finite motion: the three arms turned a little, the loops closed, the platform translated
    c = Closure(m)
    q, res = c.solve({0: 0.02, 7: -0.01, 14: 0.015})
    assert res < 1e-12
    D = c.poses(q)["platform"]
    assert np.abs(D[:3, :3] - np.eye(3)).max() < 1e-12 and np.linalg.norm(D[:3, 3]) > 1e-2


def test_orthoglide_is_3t():
    # the Orthoglide (Wenger & Chablat 2000, "Kinematic analysis of a new parallel machine
    # tool: the Orthoglide", ARK 2000): three orthogonal prismatic legs P-R-Pa-R, three
    # translations; here at its isotropic pose, the rods along the sliders' axes
    m = orthoglide()
    mo = m.mobility()
    assert (mo.loops, mo.freedoms, mo.mobility, mo.passive) == (5, 21, 3, 0)
    assert m.motion("platform") == "3T"
    c = Closure(m)
    q, res = c.solve({0: 0.02, 7: -0.01, 14: 0.015})  # the three sliders
    D = c.poses(q)["platform"]
    assert res < 1e-12 and np.abs(D[:3, :3] - np.eye(3)).max() < 1e-12
    assert np.allclose(D[:3, 3], [0.02, -0.01, 0.015], atol=1e-3)


@pytest.mark.slow
def test_h4_is_3t1r():
    # the H4 (Pierrot & Company 1999, "H4: a new family of 4-dof parallel robots", AIM'99):
    # four Delta-like legs, two on each side bar of an articulated travelling plate whose
    # central bar turns about z relative to both: three translations and the rotation about z
    # (Schoenflies motion); 24 links, 30 joints, 7 loops.  Slow: about 3 s
    m = h4()
    mo = m.mobility()
    assert (mo.links, mo.joints, mo.loops, mo.mobility, mo.passive) == (24, 30, 7, 4, 0)
    assert m.motion("C") == "3T1R" and m.motion("A") == "3T"
    (w,) = [t.omega for t in m.relative_twists("C") if t.omega != Matrix([0, 0, 0])]
    assert w.cross(Matrix(Z)) == Matrix([0, 0, 0])  # the rotation is about z
    c = Closure(m)
    q, res = c.solve({0: 0.02, 7: -0.01, 14: 0.015, 21: 0.01})  # the four actuated arms
    D = c.poses(q)["C"]
    assert res < 1e-11
    assert np.allclose(D[:3, 2], [0, 0, 1], atol=1e-12) and abs(D[0, 1]) > 1e-3  # turned about z


@pytest.mark.slow
def test_delta_and_orthoglide_translate_to_second_order():
    # their three translations extend to second order (no shakiness); about 2 s
    assert delta().second_order()[:4] == (3, 3, 1, False)
    assert orthoglide().second_order()[:4] == (3, 3, 1, False)


@pytest.mark.parametrize("build", [watt, stephenson], ids=["watt", "stephenson"])
def test_watt_and_stephenson_six_bars_have_one_freedom(build):
    # the two six-bar chains of one freedom (Watt: the ternary links joined; Stephenson: not;
    # e.g. Hunt, Kinematic Geometry of Mechanisms, 1978): planar, two loops of order 3
    m = build()
    mo = m.mobility()
    assert (mo.mobility, mo.loops, mo.orders, mo.redundant, mo.passive) == (1, 2, (3, 3), 0, 0)
    assert m.second_order()[:4] == (1, 1, 1, False)
    c = Closure(m)
    q, res = c.solve({0: 0.05}, start=0.05 * rates_of(m) / rates_of(m)[0])
    assert res < 1e-12


def finite_residual(mech, eps, steps=1):
    """The least loop-closure residual with the first joint turned by ``eps`` (1-DOF loops),
    reached in ``steps`` steps, each starting from the last."""
    r = rates_of(mech)
    c, q, res = Closure(mech), eps / steps * r / r[0], 0.0
    for k in range(1, steps + 1):
        q, res = c.solve({0: k * eps / steps}, start=q if k == 1 else q + eps / steps * r / r[0])
    return res


def test_shaky_4r_moves_to_first_order_only():
    # four revolutes on lines of one regulus of the hyperboloid x^2 + y^2 - z^2 = 1: the
    # axes span a 3-system, so one instantaneous freedom, but a generic such 4R is rigid
    # (Bennett 1914 shows that only his isogram moves; a "shaky" linkage: Müller 2016,
    # J. Mech. Robot. 8(4) 041013, §6): no second-order motion
    m = shaky_4r()
    assert m.mobility().mobility == 1
    so = m.second_order()
    assert (so.instantaneous, so.mobility, so.branches, so.several_branches) == (1, 0, 1, False)
    nonzero = [f for f in so.forms if f != Matrix([[0]])]
    assert nonzero and all(f.shape == (1, 1) for f in nonzero)
    # finite motion: no closure a step away; the least residual falls as eps**2
    r2, r3 = finite_residual(m, 1e-2), finite_residual(m, 1e-3)
    assert r2 > 1e-4 and 50 < r2 / r3 < 200


def test_bennett_linkage_moves_to_second_order():
    # Bennett's linkage (Bennett 1903, "A new mechanism", Engineering 76; 1914, "The skew
    # isogram mechanism", Proc. London Math. Soc. 13): a skew isogram, each axis normal to
    # the two sides at its vertex; one freedom, finite (mobility 1 and 1)
    m = bennett()
    pts = ISOGRAM
    sides = [sum(x * x for x in sub(pts[(k + 1) % 4], pts[k])) for k in range(4)]
    assert sides[0] == sides[2] and sides[1] == sides[3] and sides[0] != sides[1]
    assert m.mobility().mobility == 1
    assert m.second_order()[:4] == (1, 1, 1, False)
    # closed a step away, and after a turn of the first joint by about 0.5 rad (the axis
    # direction is not a unit vector: the rate 0.05 turns it by 0.05 |(8, -4, 4)|)
    assert finite_residual(m, 1e-2) < 1e-12 and finite_residual(m, 0.05, steps=5) < 1e-12


def test_flat_parallelogram_has_two_branches_meeting():
    # the parallelogram four-bar folded flat: the parallelogram and anti-parallelogram
    # modes meet (a change point; e.g. Müller 2016 §6, Lopez-Custodio et al. 2016 on
    # kinematotropic/bifurcating linkages): two instantaneous freedoms, two 1-dimensional
    # branches to second order
    m = flat_parallelogram()
    so = m.second_order()
    assert (so.instantaneous, so.mobility, so.branches, so.several_branches) == (2, 1, 2, True)
    directions = sorted(tuple(Matrix(V).T / V[0]) for V in so.cone)
    assert directions == [(1, -3, -1, 3), (1, -1, 1, -1)]
    # finite motion along each branch: a closure a step away, in that direction
    c = Closure(m)
    for d in directions:
        d = np.array(d, dtype=float)
        q, res = c.solve({0: 1e-3}, start=1e-3 * d)
        assert res < 1e-12 and np.allclose(q / 1e-3, d, atol=1e-4)


def test_second_order_decides_none_with_symbols_that_it_cannot_sign():
    # the regulus of x^2 + y^2 - z^2 = a^2, a symbolic: the form does not vanish identically
    a = symbols("a", positive=True)
    ring = [(1, 0), (0, 1), (-1, 0), (Rational(3, 5), Rational(-4, 5))]
    m = four_r([[a * c, a * s, 0] for c, s in ring], [[-s, c, 1] for c, s in ring])
    assert m.mobility().mobility == 1
    so = m.second_order()
    assert so.instantaneous == 1 and so.mobility is None and so.branches is None
    assert m.xreplace({a: 1}).second_order().mobility == 0


# ------------------------------------------------------------ second order


def random_twist(rng):
    q = lambda: Rational(rng.randint(-9, 9), rng.randint(1, 5))  # noqa: E731
    return Twist([q(), q(), q()], [q(), q(), q()])


def test_lie_bracket_is_a_lie_bracket():
    rng = random.Random(7)
    for _ in range(3):
        a, b, c = (random_twist(rng) for _ in range(3))
        assert lie_bracket(a, b) == -lie_bracket(b, a)
        jacobi = (lie_bracket(a, lie_bracket(b, c)) + lie_bracket(b, lie_bracket(c, a))
                  + lie_bracket(c, lie_bracket(a, b)))
        assert jacobi == Twist([0, 0, 0], [0, 0, 0])
        # reciprocity is invariant: [a, .] is skew for the reciprocal product (Klein form)
        w = random_twist(rng)
        assert expand(lie_bracket(a, b).reciprocal_product(w) + b.reciprocal_product(
            lie_bracket(a, w))) == 0


def numeric_acceleration_residual(mech, sign=1.0, h=1e-3):
    """|A q'' + sign * quadratic_terms(q')| for a finite motion through the configuration."""
    c = Closure(mech)
    r = rates_of(mech)
    r = r / r[0]
    qp, res_p = c.solve({0: h}, start=h * r)
    qm, res_m = c.solve({0: -h}, start=-h * r)
    assert res_p < 1e-12 and res_m < 1e-12
    qdot = (qp - qm) / (2 * h)
    qddot = (qp + qm) / h**2
    A = np.array(mech.network_matrix(), dtype=float)
    B = np.array(mech.quadratic_terms(qdot.tolist()), dtype=float).ravel()
    return np.linalg.norm(A @ qddot + sign * B), np.linalg.norm(B)


def rsur():
    """A spatial R-S-U-R loop; the loop runs through the ball joint from coupler to crank,
    against its order (its axes x, y, z reversed), and through the U from dir1 to dir2."""
    return Mechanism([("ground", "crank", R([0, 0, 0], Z)), ("crank", "coupler", S([1, 0, 1])),
                      ("rocker", "coupler", U([3, 2, 1], [1, 0, 0], [0, 1, 1])),
                      ("rocker", "ground", R([3, 2, 0], [0, 1, 0]))], base="ground")


@pytest.mark.parametrize("build", [bennett, lambda: parallelogram_legged(True), rsur],
                         ids=["bennett", "parallelogram_pair", "rsur"])
def test_the_second_order_condition_holds_on_a_finite_motion(build):
    # A q'' + sum_{k<l} [$_k, $_l] q'_k q'_l (+ Y q'^2 for the parallelogram pair) = 0 along a
    # finite motion solved numerically: the bracket's order and sign and the pair's
    # acceleration term; with the sign flipped it fails (the check can fail)
    m = build()
    assert m.mobility().mobility == 1
    if build is rsur:
        assert (1, -1) in m.loops[0] and (2, 1) in m.loops[0]  # S backward, U forward
    good, size = numeric_acceleration_residual(m)
    bad, _ = numeric_acceleration_residual(m, sign=-1.0)
    assert size > 0.1 and good < 1e-4 * size and bad > 0.1 * size


# ------------------------------------------------------------ mobility_cases


def assert_graph_cases_exhaustive(mech, pm, points, splits=None):
    """At each point some case holds, and each case that holds gives the exact figures there.

    Exact: the mechanism with the point substituted (no symbols left), and the
    ParallelMechanism's own case split (joint rates = platform freedoms + passive ones).
    ``splits``: the case lists to check (default: with and without merging).
    if splits is None:
        splits = (mech.mobility_cases(merge=False), mech.mobility_cases())
    A point where a joint cannot be built (``xreplace`` raises ``ValueError``) must fall in
    ``Degenerate`` cases only, in both splits; every other point in none.
    """
    if splits is None:
        splits = (mech.mobility_cases(merge=False), mech.mobility_cases())
    pm_cases = pm.mobility_cases()
    for point in points:
        try:
            here = mech.xreplace(point).mobility()
        except ValueError:  # the values unmake a joint
            here = None
        for split in splits:
            holding = [m for c, m in split if c.xreplace(point) is true]
            assert holding, f"no case holds at {point}"
            for m in holding:
                if here is None:
                    assert isinstance(m, Degenerate), (point, m)
                    continue
                assert m is not None and not isinstance(m, Degenerate), (point, m)
                assert (m.mobility, m.rank, m.orders) == (
                    here.mobility, here.rank, here.orders), (point, m, here)
        [pmm] = {m.answer(): m for c, m in pm_cases if c.xreplace(point) is true}.values()
        if here is None:
            assert isinstance(pmm, Degenerate), (point, pmm)
            continue
        assert here.mobility == pmm.mobility + pmm.passive


def test_mobility_cases_of_a_symbolic_four_bar_match_parallel_mechanism():
    # the planar four-bar A(0,0) B(bx,by) C(3,0) D(4,0) (the case of test_mechanism's
    # exhaustive test): one freedom (Grübler's planar count 3(4-1) - 2*4 = 1); two where
    # B lies on the ground line (the folded four-bar, all axes in one plane: Hunt 1978,
    # Kinematic Geometry of Mechanisms, §2 on the change point), one of them idle at B = A
    bx, by = symbols("b_x b_y", real=True)
    pm = four_bar(B=(bx, by, 0), Cp=(3, 0, 0))
    mech = Mechanism.from_parallel(pm)
    cases = mech.mobility_cases(merge=False)
    assert [(m.mobility, m.orders, m.passive) for _, m in cases] == [
        (1, (3,), 0), (2, (2,), 0), (2, (2,), 1)]
    rnd = random.Random(19)
    special = [{bx: u, by: 0} for u in (0, 1, 3, 4, Rational(7, 2))]
    rand = [{bx: Rational(rnd.randint(-9, 9), rnd.randint(1, 5)),
             by: Rational(rnd.randint(-9, 9), rnd.randint(1, 5))} for _ in range(4)]
    assert_graph_cases_exhaustive(mech, pm, special + rand)
    merged = mech.mobility_cases()
    assert len(merged) == 3  # the idle freedom at B = A keeps the last case apart
    assert Mechanism.from_parallel(four_bar()).mobility_cases() == [
        (true, Mechanism.from_parallel(four_bar()).mobility())]


def test_mobility_cases_of_two_loops():
    # a coupler carried by three RR dyads (two independent loops): a planar structure,
    # 3(5-1) - 2*6 = 0 (Grübler's count), which moves where a dyad folds onto the line of
    # its neighbour's (a = 0: the first dyad's joints on the ground line through D, C) and
    # gains an idle spin where the third dyad's two joints coincide (b = -1)
    a, b = symbols("a b", real=True)
    pm = ParallelMechanism(Limb(R([0, 0, 0], Z), R([1, a, 0], Z)),
                           Limb(R([4, 0, 0], Z), R([3, 0, 0], Z)),
                           Limb(R([2, -1, 0], Z), R([2, b, 0], Z)))
    mech = Mechanism.from_parallel(pm)
    assert mech.mobility().loops == 2
    cases = mech.mobility_cases(merge=False)
    assert [m.mobility for _, m in cases] == [0, 1, 0, 1, 1]
    special = [{a: u, b: v} for u in (0, Rational(-1, 2), 1) for v in (-1, 0, 2)]
    assert_graph_cases_exhaustive(mech, pm, special + [{a: Rational(5, 7), b: Rational(-3, 11)}])
    merged = mech.mobility_cases()
    assert [m.answer() for _, m in merged] == list(dict.fromkeys(m.answer() for _, m in cases))


def test_assert_graph_cases_exhaustive_rejects_a_wrong_answer():
    bx, by = symbols("b_x b_y", real=True)
    pm = four_bar(B=(bx, by, 0), Cp=(3, 0, 0))
    mech = Mechanism.from_parallel(pm)

    class Lying:
        def mobility_cases(self, merge=True):
            return [(c, m._replace(mobility=1)) for c, m in mech.mobility_cases(merge=merge)]

        def xreplace(self, point):
            return mech.xreplace(point)

    with pytest.raises(AssertionError):
        assert_graph_cases_exhaustive(Lying(), pm, [{bx: 1, by: 0}])

    class Missing(Lying):
        def mobility_cases(self, merge=True):
            return mech.mobility_cases(merge=merge)[:1]

    with pytest.raises(AssertionError, match="no case holds"):
        assert_graph_cases_exhaustive(Missing(), pm, [{bx: 1, by: 0}])


def test_mobility_cases_reports_a_joint_that_its_values_unmake():
    # a four-bar whose coupler joint's axis is (0, 0, a): at a = 0 there is no joint, so no
    # mechanism to analyse; reported as Degenerate (listed last, as ParallelMechanism does),
    # the joint named as the graph knows it
    from sympy import Eq, Ne

    a = symbols("a", real=True)
    pm = ParallelMechanism(Limb(R([0, 0, 0], Z), R([1, 2, 0], [0, 0, a])),
                           Limb(R([4, 0, 0], Z), R([3, 3, 0], Z)))
    mech = Mechanism.from_parallel(pm)
    cases = mech.mobility_cases()
    assert [c for c, _ in cases] == [Ne(a, 0), Eq(a, 0)]
    assert cases[0][1].mobility == 1
    assert cases[1][1] == Degenerate("joints[1] ('limb1.1', 'platform'): direction: a joint "
                                     "axis needs a non-zero direction, got [0, 0, 0]")
    assert isinstance(pm.mobility_cases()[1][1], Degenerate)
    assert_graph_cases_exhaustive(mech, pm, [{a: 0}, {a: 1}, {a: Rational(-2, 3)}])


def test_mobility_cases_reports_a_universal_joint_made_parallel():
    # the U's second axis (1, a, 0) parallel to its first (1, 0, 0) at a = 0 (the case of
    # test_exact_roots, as a graph: one loop): the joint named by its number and links
    from sympy import Eq, Ne

    a = symbols("a", real=True)
    leg1 = Limb(U([0, 0, 0], [1, 0, 0], [1, a, 0]), P([0, 0, 1]), S([0, 0, 2]))
    leg2 = Limb(R([1, 0, 0], [1, 0, 0]), P([0, 1, 1]), S([1, 1, 1]))
    pm = ParallelMechanism(leg1, leg2)
    mech = Mechanism.from_parallel(pm)
    cases = mech.mobility_cases()
    assert [c for c, _ in cases] == [Ne(a, 0), Eq(a, 0)]
    pmm = pm.mobility_cases()[0][1]
    assert cases[0][1].mobility == pmm.mobility + pmm.passive == 5
    assert isinstance(cases[1][1], Degenerate)
    assert cases[1][1].reason.startswith("joints[0] ('base', 'limb1.1'): ")
    assert "a universal joint needs two non-parallel axes" in cases[1][1].reason
    assert_graph_cases_exhaustive(mech, pm, [{a: 0}, {a: 2}, {a: Rational(-1, 3)}])


def test_assert_graph_cases_exhaustive_rejects_a_wrong_degenerate_case():
    a = symbols("a", real=True)
    pm = ParallelMechanism(Limb(R([0, 0, 0], Z), R([1, 2, 0], [0, 0, a])),
                           Limb(R([4, 0, 0], Z), R([3, 3, 0], Z)))
    mech = Mechanism.from_parallel(pm)
    right = mech.mobility_cases()

    class Wrong:
        def __init__(self, cases):
            self.cases = cases

        def mobility_cases(self, merge=True):
            return self.cases

        def xreplace(self, point):
            return mech.xreplace(point)

    hidden = [right[0], (right[1][0], right[0][1])]  # the degenerate case given a mobility
    with pytest.raises(AssertionError):
        assert_graph_cases_exhaustive(Wrong(hidden), pm, [{a: 0}])
    invented = [(true, Degenerate("joints[1]: made up"))]  # a degenerate case everywhere
    with pytest.raises(AssertionError):
        assert_graph_cases_exhaustive(Wrong(invented), pm, [{a: 1}])


def test_mobility_cases_checks_its_arguments():
    b = symbols("b", real=True)
    mech = Mechanism.from_parallel(four_bar(B=(1, b, 0), Cp=(3, 0, 0)))
    with pytest.raises(TypeError, match="merge"):
        mech.mobility_cases(merge="no")
    with pytest.raises(ValueError, match="more than 1 case"):
        mech.mobility_cases(max_cases=1)


@pytest.mark.slow
def test_mobility_cases_of_two_loops_with_a_solved_denominator():
    # the three dyads again, with three symbols and conditions such as 2ab = 1, solved as
    # b = 1/(2a): the bases of the case split then carry denominators (about 10 s)
    a, b, c = symbols("a b c", real=True)
    pm = ParallelMechanism(Limb(R([0, 0, 0], Z), R([1, a * b - 1, 0], Z)),
                           Limb(R([4, 0, 0], Z), R([3, b, 0], Z)),
                           Limb(R([2, -1, 0], Z), R([c, b * c, 0], Z)))
    mech = Mechanism.from_parallel(pm)
    assert {m.mobility for _, m in mech.mobility_cases(merge=False)} == {0, 1, 2}
    half = Rational(1, 2)
    points = [{a: 1, b: 1, c: 3}, {a: half, b: 1, c: 0}, {a: -1, b: -half, c: 2},
              {a: 1, b: -half, c: 2}, {a: 0, b: 0, c: 0}, {a: 2, b: 1, c: Rational(4, 3)},
              {a: -1, b: 2, c: 2}, {a: Rational(3, 7), b: Rational(-5, 2), c: Rational(1, 3)}]
    assert_graph_cases_exhaustive(mech, pm, points)


@pytest.mark.slow
def test_mobility_cases_of_the_three_upu_as_a_graph():
    # Tsai's 3-UPU (two loops as a graph) meets a constraint singularity at x = -48/11 and
    # gains a rotation there (Zlatanov, Bonev & Gosselin, "Constraint singularities of parallel
    # mechanisms", ICRA 2002, the 3-UPU example); the same split as ParallelMechanism's,
    # the graph's joint rates the platform's freedoms (about 25 s)
    def leg(b, a1, top):  # as in three_upu above and test_mechanism.py
        d = sub(top, b)
        a2 = cross(a1, d)
        return Limb(U(b, a1, a2), P(d), U(top, a2, a1))

    x, z = symbols("x", real=True), symbols("z", positive=True)
    pm = ParallelMechanism(leg([2, 0, 0], [0, 1, 0], [1, 0, z]),
                           leg([-1, 2, 0], [-2, -1, 0], [0, 1, z]),
                           leg([-1, -2, 0], [2, -1, 0], [x, -1, z]))
    mech = Mechanism.from_parallel(pm)
    cases = mech.mobility_cases(budget=10**9)  # about 25 s of work: past the default budget
    assert [(str(c), m.mobility, m.loops) for c, m in cases] == [
        ("Ne(11*x + 48, 0)", 3, 2), ("Eq(11*x + 48, 0)", 4, 2)]
    pts = [{x: Rational(-48, 11), z: 1}, {x: Rational(-48, 11), z: 3}, {x: -3, z: 1}]
    assert_graph_cases_exhaustive(mech, pm, pts, splits=[cases])


def test_mobility_cases_decides_a_quadratic_at_its_roots():
    # the coupler joint at (1, t**2 - 2): the four-bar folds where t = +-sqrt(2), an equation
    # linear in no symbol but in one symbol: decided at its two real roots
    from sympy import Eq, Ne, Or, sqrt

    t = symbols("t", real=True)
    mech = four_r([[0, 0, 0], [1, t**2 - 2, 0], [3, 0, 0], [4, 0, 0]], [Z] * 4)
    cases = mech.mobility_cases()
    assert [(c, None if m is None else m.mobility) for c, m in cases] == [
        (Ne(t**2 - 2, 0), 1), (Or(Eq(t, sqrt(2)), Eq(t, -sqrt(2))), 2)]
    # independently: at t = sqrt(2) the four-bar is folded (2 freedoms)
    assert mech.xreplace({t: sqrt(2)}).mobility().mobility == 2


def test_mobility_cases_decides_a_case_that_no_substitution_states():
    # the coupler joint at (1, t**2 + u**2 - 2): a circle of folded four-bars (Gosselin &
    # Angeles 1990: a planar loop is singular with its four pivots in one line), an
    # equation in two symbols linear in neither.  No substitution states it; the split
    # goes on modulo it, and every figure of the case holds at exact points of the circle
    from sympy import Eq, Ne, Rational, sqrt

    t, u = symbols("t u", real=True)
    f = t**2 + u**2 - 2
    mech = four_r([[0, 0, 0], [1, f, 0], [3, 0, 0], [4, 0, 0]], [Z] * 4)
    cases = mech.mobility_cases()
    assert [(c, m.mobility, m.orders) for c, m in cases] == [(Ne(f, 0), 1, (3,)),
                                                             (Eq(f, 0), 2, (2,))]
    on = [{t: 1, u: 1}, {t: Rational(7, 5), u: Rational(1, 5)}, {t: sqrt(2), u: 0}]
    off = [{t: 0, u: 0}, {t: 2, u: Rational(1, 3)}]
    for point in on:
        assert_case_at(mech, cases[1][1], point)
    for point in off:
        assert_case_at(mech, cases[0][1], point)
    # the checker rejects a wrong answer: the generic case's figures on the circle, its
    # rates with an entry changed, a loop's common constraints cut short
    m = cases[1][1]
    with pytest.raises(AssertionError):
        assert_case_at(mech, cases[0][1], on[0])
    with pytest.raises(AssertionError):
        assert_case_at(mech, m._replace(rates=m.rates + Matrix.eye(4)[:, :2]), on[1])
    with pytest.raises(AssertionError):
        assert_case_at(mech, m._replace(common_constraints=(ScrewSystem(*m.common_constraints[0].screws[:3]),)), on[0])


def test_mobility_cases_reports_a_joint_unmade_on_a_surface():
    # the first axis (0, 0, t**2 + u**2 - 2) vanishes on the circle: a degenerate joint on a
    # case that no substitution states, found by its twist losing rank there
    from sympy import Eq, Ne

    t, u = symbols("t u", real=True)
    f = t**2 + u**2 - 2
    mech = four_r([[0, 0, 0], [1, 2, 0], [3, 3, 0], [4, 0, 0]], [[0, 0, f]] + [Z] * 3)
    cases = mech.mobility_cases()
    assert [c for c, _ in cases] == [Ne(f, 0), Eq(f, 0)]
    assert cases[1][1] == Degenerate(
        "joints[0] ('ground', 'crank'): its 1 twist(s) have rank 0 where t**2 + u**2 - 2 = 0 "
        "(a zero axis, or axes made parallel)")
    with pytest.raises(ValueError, match="non-zero direction"):  # the joint refuses it there
        mech.xreplace({t: 1, u: 1})
    assert_case_at(mech, cases[0][1], {t: 0, u: 0})


def test_mobility_cases_decides_where_two_curves_meet():
    # B = (1, t**2 + u**2 - 2), C = (3, t**3 + u**2 - 2): O, B, C are in one line on a
    # cubic curve (the loop keeps its order 3 there), and all four pivots where it meets
    # the circle: at four points, found exactly (test_exact_roots has the split)
    from sympy import sqrt

    t, u = symbols("t u", real=True)
    mech = four_r([[0, 0, 0], [1, t**2 + u**2 - 2, 0], [3, t**3 + u**2 - 2, 0], [4, 0, 0]],
                  [Z] * 4)
    cases = mech.mobility_cases(merge=False)
    assert [m.mobility for _, m in cases] == [1, 1, 2, 2, 2, 2]
    points = {1: [{t: 2, u: 0}, {t: 0, u: 0}, {t: 3, u: -1}],
              2: [{t: 1, u: 1}, {t: 1, u: -1}, {t: 0, u: sqrt(2)}, {t: 0, u: -sqrt(2)}]}
    for mobility, at in points.items():
        for point in at:
            [m] = [m for c, m in cases if c.xreplace(point) is true]
            assert m.mobility == mobility
            assert_case_at(mech, m, point)
    assert [m.mobility for _, m in mech.mobility_cases()] == [1, 2]


def test_mobility_cases_says_none_where_sympy_cannot_decide():
    # with a third symbol, B = (1, t**2 + u**2 + w**2 - 2): the two surfaces meet in a
    # curve that no substitution states and no point decides: that case is undecided
    # (None), never guessed, and holds only there
    t, u, w = symbols("t u w", real=True)
    mech = four_r([[0, 0, 0], [1, t**2 + u**2 + w**2 - 2, 0], [3, t**3 + u**2 - 2, 0],
                   [4, 0, 0]], [Z] * 4)
    cases = mech.mobility_cases()
    assert [None if m is None else m.mobility for _, m in cases] == [1, None]
    meet, beside = {t: 1, u: 1, w: 0}, {t: 1, u: 0, w: 1}
    assert cases[1][0].xreplace(meet) is true and cases[1][0].xreplace(beside) is not true
    # and it is undecided, not wrong: there the four-bar is folded
    assert mech.xreplace(meet).mobility().mobility == 2
    assert_case_at(mech, cases[0][1], beside)


def test_mobility_cases_keeps_to_its_budget():
    b = symbols("b", real=True)
    mech = Mechanism.from_parallel(four_bar(B=(1, b, 0), Cp=(3, 0, 0)))
    with pytest.raises(ValueError, match="mobility_cases: .*budget=1 "):
        mech.mobility_cases(budget=1)
    with pytest.raises(TypeError, match="budget"):
        mech.mobility_cases(budget="lots")
