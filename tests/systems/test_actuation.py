"""Actuation wrenches, Jacobians, the three kinds of singularity and transmission indices.

Literature: Joshi & Tsai (2002) for actuation wrenches and Jx/Jq; Gosselin & Angeles (1990)
for the five-bar's three kinds of singularity; Zlatanov, Bonev & Gosselin (2002) for the
3-UPU's constraint singularity; Wang, Wu & Liu (2010) and Liu, Wang & Pritschow (2006) for
the five-bar's transmission indices.
"""

from __future__ import annotations

import numpy as np
import pytest
from sympy import Eq, Matrix, Ne, Rational, symbols, true

from screwsym import Twist
from screwsym.systems.actuation import (
    check_actuated,
    generic_limb_rank,
    limb_actuation_wrench,
    transmission_index,
)
from screwsym.systems.joints import P, R, S, U
from screwsym.systems.parallel import Limb, ParallelMechanism
from tests._actuated import five_bar
from tests._mechanisms import rps_leg

Z = [0, 0, 1]


def recip(w, t):
    return (w.S.dot(t.S0) + w.S0.dot(t.S)).expand()


# ------------------------------------------------------------------ Limb(actuated=)
def test_limb_names_its_actuated_joints_and_stays_a_value():
    leg = Limb(R([2, 0, 0], [0, 1, 0]), P([-1, 0, 2]), S([1, 0, 2]), actuated=1)
    assert leg.actuated == (1,) and len(leg.joints) == 3 and leg.freedom == 5
    assert leg.func(*leg.args) == leg and hash(leg) == hash(leg.func(*leg.args))
    assert leg != Limb(*leg.joints) and Limb(*leg.joints).actuated == ()
    assert "actuated=1" in repr(leg)
    a = symbols("a", real=True)
    moved = Limb(R([a, 0, 0], [0, 1, 0]), P([1, 0, 2]), S([1, 0, 2]), actuated=(1, 0))
    assert moved.actuated == (0, 1) and moved.xreplace({a: 2}).actuated == (0, 1)


@pytest.mark.parametrize(("value", "error", "match"), [
    ("1", TypeError, "actuated: expected an int or a tuple of ints"),
    (1.0, TypeError, "actuated: expected an int"),
    (True, TypeError, "actuated: expected an int"),
    (3, ValueError, "actuated: expected indices into the limb's 3 joints"),
    (-1, ValueError, "actuated: expected indices"),
    ((), ValueError, "actuated: expected at least one"),
    ((0, 0), ValueError, "actuated: expected distinct"),
])
def test_limb_refuses_bad_actuated(value, error, match):
    with pytest.raises(error, match=match):
        Limb(R([2, 0, 0], [0, 1, 0]), P([-1, 0, 2]), S([1, 0, 2]), actuated=value)
    assert check_actuated((2, 1), 3) == (1, 2)


def test_an_actuated_joint_has_one_freedom():
    leg = Limb(U([0, 0, 0], [1, 0, 0], [0, 1, 0]), P([0, 0, 1]), S([0, 0, 1]), actuated=0)
    with pytest.raises(ValueError, match="an actuated joint must have one freedom"):
        limb_actuation_wrench(leg, 0)


# ------------------------------------------------------------------ actuation wrenches
def test_rps_and_upu_legs_transmit_a_force_along_the_leg():
    # Joshi & Tsai (2002), Sec. 3-4: with the prismatic joint actuated, the actuation wrench
    # of an R-P-S (or U-P-U) leg is the force along the leg through the sphere (U) centre
    leg = Limb(*rps_leg(0, Rational(-1, 2), 2).joints, actuated=1)
    w = limb_actuation_wrench(leg, 1)
    d = leg.joints[1].args[0]
    top = leg.joints[2].args[0]
    twists = [t for j in leg.joints for t in j._twists()]
    assert w.S.cross(d) == Matrix([0, 0, 0]) and (w.S0 - top.cross(w.S)).expand() == Matrix([0, 0, 0])
    assert [recip(w, t) for i, t in enumerate(twists) if i != 1] == [0] * 4
    assert recip(w, twists[1]) != 0
    # the checker rejects a wrong answer: the constraint force (along the R axis) is
    # reciprocal to the passive twists too, but also to the actuated one
    (c,) = leg.constraints
    assert recip(c, twists[1]) == 0
    # Tsai's U-P-U leg: the force along the leg, not the constraint couple
    b, a1, top = Matrix([2, 0, 0]), Matrix([0, 1, 0]), Matrix([1, 0, 3])
    a2 = a1.cross(top - b)
    upu = Limb(U(b, a1, a2), P(top - b), U(top, a2, a1), actuated=1)
    w = limb_actuation_wrench(upu, 1)
    assert w.S.cross(top - b) == Matrix([0, 0, 0]) and w.S.dot(w.S0) == 0


# ------------------------------------------------------------------ Jacobian
def _five_bar_point(t1, t2, l1=1.0, l2=2.0, a2=3.0):
    """Forward kinematics of the five-bar (the elbow-up branch), by circle intersection."""
    b1 = np.array([l1 * np.cos(t1), l1 * np.sin(t1)])
    b2 = np.array([a2 + l1 * np.cos(t2), l1 * np.sin(t2)])
    mid, half = (b1 + b2) / 2, np.linalg.norm(b2 - b1) / 2
    n = np.array([-(b2 - b1)[1], (b2 - b1)[0]]) / (2 * half)
    return b1, b2, mid + np.sqrt(l2**2 - half**2) * n


def test_five_bar_jacobian_predicts_a_finite_motion():
    # Joshi & Tsai (2002), eq. 9: Jx t = Jq qdot.  Independent check: turn the cranks by
    # eps * qdot, solve the loop closure (circle intersection) in NumPy, and compare the
    # end point's velocity with the one Jx t = Jq qdot predicts
    from screwsym.numeric.transmission import jacobian_map

    b1x, b1y, b2x, b2y, px, py = syms = symbols("b1x b1y b2x b2y px py", real=True)
    mech = five_bar((px, py), b1=(b1x, b1y), b2=(b2x, b2y))
    jac = jacobian_map(mech, list(syms))
    t1, t2, qdot, eps = 1.7, 1.2, np.array([0.3, -0.7]), 1e-6
    b1, b2, p = _five_bar_point(t1, t2)
    _, _, p1 = _five_bar_point(t1 + eps * qdot[0], t2 + eps * qdot[1])
    _, _, p0 = _five_bar_point(t1 - eps * qdot[0], t2 - eps * qdot[1])
    v = (p1 - p0) / (2 * eps)
    Jx, Jq = jac(np.array([[*b1, *b2, *p]]))
    t = np.array([0, 0, 0, v[0], v[1], 0])
    assert np.allclose(Jx[0] @ t, Jq[0] @ qdot, atol=1e-6)
    # and rejects a wrong answer: the rates of the two cranks swapped
    assert not np.allclose(Jx[0] @ t, Jq[0] @ qdot[::-1], atol=1e-3)


@pytest.mark.slow
def test_three_rps_jacobian_holds_for_every_platform_twist():
    # Joshi & Tsai (2002), eq. 9, checked exactly: each platform twist is realised by each
    # leg's joint rates (a linear solve), and Jx t equals Jq times the actuated rates
    mech = ParallelMechanism(*(Limb(*rps_leg(i, Rational(-1, 2), h).joints, actuated=1)
                               for i, h in enumerate((2, 2, 3))))
    Jx, Jq = mech.jacobian()
    assert Jx.shape == (6, 6) and Jq.shape == (6, 3)
    for t in mech.twists:
        qdot = []
        for limb in mech.limbs:
            rates = limb.twists.matrix.solve(t.matrix)  # 5 independent twists: one solution
            qdot.append(rates[1])
        assert (Jx * t.matrix - Jq * Matrix(qdot)).expand() == Matrix.zeros(6, 1)
        assert (Jx * t.matrix - 2 * Jq * Matrix(qdot)).expand() != Matrix.zeros(6, 1)


# ------------------------------------------------------------------ singularities
@pytest.mark.slow
def test_five_bar_three_kinds_of_singularity():
    # Gosselin & Angeles (1990), Sec. IV, the five-bar: type I where a leg is stretched or
    # folded (A_i, B_i, P collinear), type II where B1, B2 and P are collinear
    x, y = symbols("x y", real=True)
    s = five_bar((x, y)).singularities()
    limb = [c for c, _ in s.limb]
    assert limb[0] == Eq(x, 0) and limb[2] == Eq(x, 3)
    assert [c for c, _ in s.actuation] == [Eq(y, 1)]
    assert s.constraint == []
    # independent check: the numeric rank of Jx and of the legs at points on and off them
    def ranks(px, py):
        m = five_bar((px, py))
        return (np.linalg.matrix_rank(np.array(m.jacobian()[0], dtype=float)),
                [limb.twists.rank for limb in m.limbs])
    assert ranks(1, 2) == (6, [3, 3, 2])
    assert ranks(Rational(1, 2), 1) == (5, [3, 3, 2])   # type II: on y = 1
    # type I: leg 1 stretched over A1 (its crank's twist in its other joints': no wrench)
    assert [limb.twists.rank for limb in five_bar((0, 2)).limbs] == [2, 3, 2]
    # the conditions hold exactly where the ranks drop, not elsewhere
    assert not any(c.subs({x: 1, y: 2}) for c in limb + [c for c, _ in s.actuation])


@pytest.mark.slow
def test_three_upu_constraint_singularity():
    # Zlatanov, Bonev & Gosselin (2002), the 3-UPU: the three constraint couples lose rank
    # (the platform gains a rotation) where 11 x + 48 = 0 for this geometry (as in
    # tests/systems/test_graph.py); no actuation singularity is reported there
    def leg(b, a1, top):
        b, a1, top = Matrix(b), Matrix(a1), Matrix(top)
        a2 = a1.cross(top - b)
        return Limb(U(b, a1, a2), P(top - b), U(top, a2, a1), actuated=1)

    x = symbols("x", real=True)
    mech = ParallelMechanism(leg([2, 0, 0], [0, 1, 0], [1, 0, 3]),
                             leg([-1, 2, 0], [-2, -1, 0], [0, 1, 3]),
                             leg([-1, -2, 0], [2, -1, 0], [x, -1, 3]))
    s = mech.singularities()
    assert s.constraint == [(Eq(x, Rational(-48, 11)), 2)]
    assert all(c.subs(x, Rational(-48, 11)) is not True or False for c, _ in s.actuation)
    # the checker rejects a wrong point: at x = 0 the couples keep their rank
    assert mech.xreplace({x: 0}).constraints.rank == 3
    assert mech.xreplace({x: Rational(-48, 11)}).constraints.rank == 2


# ------------------------------------------------------------------ mobility: known defect 5
def test_a_stretched_leg_is_an_internal_motion_not_a_passive_freedom():
    # issue 18, known defect 5: the five-bar keeps its 2 freedoms with a leg stretched
    # (Gosselin & Angeles 1990: a type I singularity); the leg's idle motion is momentary
    z = Z
    stretched = ParallelMechanism(Limb(R([0, 0, 0], z), R([0, 1, 0], z)),
                                  Limb(R([3, 0, 0], z), R([3, 1, 0], z), R([3, 2, 0], z)))
    m = stretched.mobility()
    assert (m.mobility, m.passive, m.internal, m.twists.rank) == (2, 0, 1, 1)
    generic = ParallelMechanism(Limb(R([0, 0, 0], z), R([0, 1, 0], z)),
                                Limb(R([3, 0, 0], z), R([3, 1, 0], z), R([2, 2, 0], z)))
    assert (generic.mobility().mobility, generic.mobility().internal) == (2, 0)
    # an S-S leg's spin about the line of its centres is a true passive freedom
    ss = Limb(S([0, 0, 0]), S([1, 2, 3]))
    assert (ss.passive, generic_limb_rank(ss)) == (1, 5)
    spin = ParallelMechanism(ss, Limb(S([2, 0, 0]), S([1, 2, 3]))).mobility()
    assert (spin.passive, spin.internal) == (2, 0)
    # the criterion rejects the wrong reading: a stretched R-R-R leg moves off its singularity
    leg = stretched.limbs[1]
    assert generic_limb_rank(leg) == 3 != leg.twists.rank


# ------------------------------------------------------------------ transmission
@pytest.mark.slow
def test_five_bar_transmission_indices_are_sines_of_link_angles():
    # Wang, Wu & Liu (2010), Sec. 4, and Liu, Wang & Pritschow (2006): the five-bar's input
    # index is |sin| of the angle between crank A_iB_i and distal link B_iP, its output
    # index |sin| of the angle between the distal links; independent NumPy angles
    from screwsym.numeric.transmission import transmission_map

    b1x, b1y, b2x, b2y, px, py = syms = symbols("b1x b1y b2x b2y px py", real=True)
    f = transmission_map(five_bar((px, py), b1=(b1x, b1y), b2=(b2x, b2y)), list(syms))
    rng = np.random.default_rng(18)
    t = rng.uniform(0.3, 2.8, size=(5, 2))
    cfg = np.array([np.concatenate(_five_bar_point(*q)) for q in t])
    out = f(cfg)
    b1, b2, p = cfg[:, 0:2], cfg[:, 2:4], cfg[:, 4:6]
    ang = lambda u: np.arctan2(u[:, 1], u[:, 0])  # noqa: E731
    lam = np.abs(np.sin(np.stack([ang(p - b1) - ang(b1), ang(p - b2) - ang(b2 - [3, 0])])))
    eta = np.abs(np.sin(ang(p - b1) - ang(p - b2)))
    assert np.allclose(out.input, lam) and np.allclose(out.output, [eta, eta])
    assert np.allclose(out.local, np.minimum(lam.min(axis=0), eta))
    # and rejects a wrong formula (cosines)
    assert not np.allclose(out.input, np.abs(np.cos(np.arcsin(lam))))


def test_transmission_index_of_pure_screws():
    # Wang et al. (2010), eq. 12-13 with h = 0: a force and a rotation, a force and a
    # translation (cosine of the angle), a couple and a rotation
    from screwsym import Wrench

    f = Wrench.force([1, 0, 0], point=[0, 1, 0])
    assert transmission_index(f, Twist.rotation([0, 0, 1], point=[0, 0, 0]), [0, 1, 0]) == 1
    assert transmission_index(f, Twist.translation([1, 1, 0]), [0, 1, 0]) ** 2 == Rational(1, 2)
    c = Wrench.couple([0, 0, 2])
    assert transmission_index(c, Twist.rotation([0, 0, 1], point=[5, 0, 0]), [0, 0, 0]) == 1
    assert transmission_index(c, Twist.translation([1, 0, 0]), [0, 0, 0]) == 0


@pytest.mark.slow
def test_octahedral_gough_stewart_is_singular_turned_by_a_quarter_turn():
    # Merlet (1989), "Singular configurations of parallel manipulators and Grassmann
    # geometry", Int. J. Robot. Res. 8(5): the 3-3 (octahedral) platform is singular when
    # turned by +-90 degrees about the vertical axis from its symmetric position (here
    # tau = tan(45 deg) = +-1); the six leg forces, Jx's rows, lose rank there, exactly
    from screwsym import ScrewSystem
    from tests._actuated import gough_stewart_33

    def rank(tau):
        return ScrewSystem(*gough_stewart_33(tau).actuation_wrenches()).rank

    assert rank(1) == 5
    assert rank(0) == 6  # the checker rejects a regular pose


@pytest.mark.slow
def test_octahedral_gough_stewart_turned_by_sin_and_cos_is_singular_at_a_quarter_turn():
    # the same platform (Merlet 1989) turned by theta written with cos(theta), sin(theta):
    # type II exactly at theta = +-90 degrees, and no limb or constraint singularity (the
    # legs' conditions sqrt(3) sin(theta) +- cos(theta) = 3 have no real solution: dropped)
    from sympy import And, pi

    from tests._actuated import gough_stewart_33

    theta = symbols("theta", real=True)
    s = gough_stewart_33(theta, trig=True).singularities()
    assert s.limb == [] and s.constraint == []
    ((cond, rank),) = s.actuation
    assert rank == 5
    # the condition holds at theta = +-pi/2 and nowhere else on a grid of the circle
    for k in range(24):
        at = k * pi / 12
        holds = bool(cond.subs(theta, at))
        assert holds == (k in (6, 18)), (k, cond)
    assert isinstance(cond, And)


@pytest.mark.slow
def test_three_rps_at_a_symbolic_pose_is_singular_where_jx_loses_rank():
    # Tsai's 3-RPS (Tsai 1999, Sec. 3.5; Joshi & Tsai 2002) at the pose (p, q, z) of
    # tests/_actuated.py: the type-II condition returned is checked independently, at exact
    # rational poses, against the rank of Jx built from the legs' own numbers there
    from sympy import Matrix as M

    from tests._actuated import three_rps_pose

    p, q, z = symbols("p q z", real=True)
    s = three_rps_pose(p, q, z).singularities()
    assert s.constraint == []
    # type II: the surface F = 0, Jx of rank 5 where moreover a 5 x 5 minor g is non-zero
    # (proved modulo F), None where both vanish
    (cond, rank), (rest, unknown) = s.actuation
    assert (rank, unknown) == (5, None)
    (surface,) = cond.atoms(Eq)
    assert surface in rest.atoms(Eq) and Ne(*surface.args) not in cond.atoms(Ne)
    f = surface.lhs - surface.rhs
    assert f.subs({p: 0, q: 0, z: 0}) == 0 and f.subs({p: 0, q: 0, z: 1}) != 0

    def jx_rank(pose):
        return M(three_rps_pose(*(Rational(x) for x in pose)).jacobian()[0]).rank()

    poses = [(0, 0, 1), (0, 0, 0), (Rational(1, 2), Rational(-1, 3), 2), (1, 2, Rational(3, 2)),
             (Rational(-2, 5), 0, 0), (0, 1, Rational(1, 7))]
    for pose in poses:
        at = dict(zip((p, q, z), pose, strict=True))
        on = f.subs(at) == 0
        assert (jx_rank(pose) < 6) == on, (pose, on)
        if cond.subs(at) is true:  # the case's rank, where it holds
            assert jx_rank(pose) == 5, pose
    # a wrong condition is rejected: f + 1 vanishes nowhere among these poses, yet Jx drops
    assert any(jx_rank(x) < 6 for x in poses)
    assert not any((f + 1).subs(dict(zip((p, q, z), x, strict=True))) == 0 for x in poses)
    # no limb singularity at all: an R-P-S leg keeps its five freedoms, and its actuation
    # force (along the leg, normal to the R axis) never falls into its constraint (a force
    # through the S centre along the R axis).  The split finds so exactly: its last pieces,
    # two curves meeting, are decided by a Groebner basis there, (z**2 + 1/2)**9: no real point
    assert s.limb == []
