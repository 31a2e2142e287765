"""Case conditions decided exactly: at real roots, dropped without real points, never overlapping.

A condition in one symbol is decided at each real root (surds, ``CRootOf``);
a sum of squares at the point where each square vanishes; a polynomial with no
real zero (a positive definite one) is no case at all; a case whose values
unmake a joint is reported as :class:`Degenerate`.  Every split is checked at
sample points: exactly one case holds there, and its answer is the one of the
mechanism (or system) built at that point.
"""

from __future__ import annotations

import random

import numpy as np
import pytest
from _mechanisms import Z
from sympy import And, Eq, Matrix, Ne, Or, Rational, sqrt, symbols, true

from screwsym import ScrewSystem, Twist, Wrench
from screwsym.systems.joints import P, R, S, U
from screwsym.systems.parallel import Degenerate, Limb, ParallelMechanism


def sub(a, b):
    return [x - y for x, y in zip(a, b, strict=True)]


def upu_leg(b, a1, top):
    """Tsai's UPU leg (as in test_mechanism): base U (a1, a2), P along the leg, top U (a2, a1)."""
    d = sub(top, b)
    a2 = list(Matrix(a1).cross(Matrix(d)))
    return Limb(U(b, a1, a2), P(d), U(top, a2, a1))


UPU_BASE = [[2, 0, 0], [-1, 2, 0], [-1, -2, 0]]
UPU_AXIS = [[0, 1, 0], [-2, -1, 0], [2, -1, 0]]


def turned_upu(c, s):
    """Tsai's 3-UPU (Tsai 1996) with the third platform joint turned about z: (-5c, -5s, 3)."""
    tops = [[1, 0, 3], [0, 1, 3], [-5 * c, -5 * s, 3]]
    return ParallelMechanism(*(upu_leg(*leg) for leg in zip(UPU_BASE, UPU_AXIS, tops, strict=True)))


def assert_cases_at(mech, cases, points):
    """At each point exactly one case holds, and its mobility is that of the mechanism there."""
    for point in points:
        holding = [m for c, m in cases if c.xreplace(point) is true]
        assert len(holding) == 1, f"{len(holding)} cases hold at {point}"
        m = holding[0]
        try:
            here = mech.xreplace(point)
        except ValueError:  # the joint cannot be built there
            assert isinstance(m, Degenerate), (point, m)
            continue
        assert not isinstance(m, Degenerate), (point, m)
        if m is not None:
            assert m.answer()[0] == here.mobility().mobility, (point, m)


@pytest.fixture(scope="module")
def turned():
    tau = symbols("tau", real=True)
    mech = turned_upu((1 - tau**2) / (1 + tau**2), 2 * tau / (1 + tau**2))
    return tau, mech, mech.mobility_cases()


@pytest.mark.slow
def test_three_upu_turned_is_decided_at_the_roots_of_a_quadratic(turned):
    # Constraint singularity of the 3-UPU (Zlatanov, Bonev & Gosselin, "Constraint
    # singularities of parallel mechanisms", ICRA 2002): where the three constraint couples
    # become dependent the platform gains a rotation, 4 freedoms (3T1R) instead of 3T.  With
    # the third platform joint turned by theta, tau = tan(theta/2), the couples' determinant
    # is a multiple of 25 tau**2 - 44 tau + 3: singular at tau = (22 +- sqrt(409))/25.
    tau, mech, cases = turned
    assert [(m.mobility, m.motion) for _, m in cases] == [(3, "3T"), (4, "3T1R")]
    roots = [Rational(22, 25) - sqrt(409) / 25, Rational(22, 25) + sqrt(409) / 25]
    assert cases[1][0].has(Or(*(Eq(tau, r) for r in roots)))
    # independently: the couples' rank, exactly, at the roots and beside them
    for value, rank in ((roots[0], 2), (roots[1], 2), (0, 3), (1, 3)):
        couples = Matrix.hstack(*(limb.constraints.matrix[3:, :]
                                  for limb in mech.xreplace({tau: value}).limbs))
        assert couples.rank(simplify=True) == rank
    assert_cases_at(mech, cases, [{tau: r} for r in (*roots, 0, 2, Rational(1, 3), -5)])


@pytest.mark.slow
def test_three_upu_turned_by_sin_and_cos():
    # the same mechanism written with cos(theta), sin(theta): the two singular points of
    # the circle, exact, in the user's symbols
    th = symbols("theta", real=True)
    from sympy import cos, sin

    mech = turned_upu(cos(th), sin(th))
    cases = mech.mobility_cases(merge=False)
    assert [m.mobility for _, m in cases] == [3, 4, 4]
    # the two points are those of tau = tan(theta/2) = (22 +- sqrt(409))/25 (in floats)
    expected = sorted((float(2 * r / (1 + r**2)), float((1 - r**2) / (1 + r**2)))
                      for r in (Rational(22, 25) - sqrt(409) / 25, Rational(22, 25) + sqrt(409) / 25))
    got = []
    for cond, _ in cases[1:]:
        values = {eq.lhs: eq.rhs for eq in cond.args}
        got.append((float(values[sin(th)]), float(values[cos(th)])))
    assert np.allclose(sorted(got), expected)


@pytest.mark.slow
def test_the_checker_rejects_overlaps_and_wrong_answers(turned):
    tau, mech, cases = turned
    root = Rational(22, 25) + sqrt(409) / 25
    with pytest.raises(AssertionError, match="2 cases hold"):
        assert_cases_at(mech, [(true, cases[0][1]), *cases[1:]], [{tau: root}])
    with pytest.raises(AssertionError):
        assert_cases_at(mech, [(c, cases[0][1]) for c, _ in cases], [{tau: root}])


def test_conditions_without_real_solutions_are_dropped():
    x, y = symbols("x y", real=True)
    # (x + 2)**2 + (y + 2)**2 + 4 is never zero: the two axes never coincide
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]),
                    Wrench.force(Z, point=[(x + 2)**2 + (y + 2)**2 + 4, 0, 0]))
    assert W.rank_conditions() == [(True, 2)]
    # t**2 + t + 1 has no real root: no case either
    t = symbols("t", real=True)
    W2 = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]), Wrench.force(Z, point=[t**2 + t + 1, 0, 0]))
    assert W2.rank_conditions() == [(True, 2)]
    # a checker of that: a positive value at samples (it rejects t**2 - 1, which vanishes at 1)
    for expr, positive in ((t**2 + t + 1, True), (t**2 - 1, False)):
        values = [expr.xreplace({t: Rational(k, 4)}) for k in range(-12, 13)]
        assert all(v > 0 for v in values) is positive


def test_a_sum_of_squares_is_decided_square_by_square():
    x, y = symbols("x y", real=True)
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]),
                    Wrench.force(Z, point=[(x - 1)**2 + (y + 2)**2, 0, 0]))
    cases = W.rank_conditions()
    assert [r for _, r in cases] == [2, 1]
    assert cases[1][0].xreplace({x: 1, y: -2}) is true
    assert W.xreplace({x: 1, y: -2}).rank == 1
    rng = random.Random(0)
    for _ in range(5):
        point = {x: Rational(rng.randint(-9, 9), 2), y: Rational(rng.randint(-9, 9), 3)}
        holding = [r for c, r in cases if c.xreplace(point) is true]
        assert holding == [W.xreplace(point).rank]


def test_cases_do_not_overlap():
    # two axes that become parallel (t = 0) and then coincide (b = 0 too), and a third
    # that meets them: at sample points, including the special ones, one case holds
    t, b = symbols("t b", real=True)
    T = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]), Twist.rotation([t, 0, 1], point=[0, b, 0]),
                    Twist.rotation(Z, point=[b, t, 0]))
    cases = T.rank_conditions()
    points = [{t: 0, b: 0}, {t: 0, b: 1}, {t: 1, b: 0}, {t: 2, b: 3}, {t: -1, b: Rational(1, 2)}]
    for point in points:
        holding = [r for c, r in cases if c.xreplace(point) is true]
        assert holding == [Matrix(T.matrix.xreplace(point)).rank()], point


def test_a_case_that_unmakes_a_joint_is_reported():
    # an R-P-S leg whose base point is symbolic: where it reaches the sphere's centre the
    # prismatic direction vanishes (no joint); a second leg holds the platform
    a = symbols("a1:3", real=True)
    top = [1, 1, 2]
    base = [a[0], a[1], 2]
    leg1 = Limb(R(base, [0, 0, 1]), P(sub(top, base)), S(top))
    leg2 = Limb(R([0, 0, 0], [1, 0, 0]), P([0, 1, 1]), S([0, 1, 1]))
    mech = ParallelMechanism(leg1, leg2)
    cases = mech.mobility_cases()
    degenerate = [(c, m) for c, m in cases if isinstance(m, Degenerate)]
    assert len(degenerate) == 1
    cond, m = degenerate[0]
    assert cond.xreplace({a[0]: 1, a[1]: 1}) is true
    assert m.reason.startswith("limbs[0]: direction: a joint axis needs a non-zero direction")
    assert m.answer() == ("degenerate joint", m.reason)
    points = [{a[0]: 1, a[1]: 1}, {a[0]: 1, a[1]: 0}, {a[0]: 0, a[1]: 3}, {a[0]: 2, a[1]: 1}]
    assert_cases_at(mech, cases, points)


def rank_at(W, point):
    return W.xreplace(point).matrix.rank(simplify=True)


def test_a_curve_linear_in_no_symbol_is_decided_on_itself():
    # u**2 = v**3 + 2 (an elliptic curve: no rational parametrisation, no substitution):
    # the second force's line meets the first's there; the rank is proved modulo the curve
    u, v = symbols("u v", real=True)
    f = u**2 - v**3 - 2
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]), Wrench.force(Z, point=[f, 0, 0]))
    cases = W.rank_conditions()
    assert cases == [(Ne(f, 0), 2), (Eq(f, 0), 1)]
    assert W.substitutions()[1] == (Eq(f, 0), None)  # no substitution states the case
    # independently, at exact points of the curve and beside it
    on = [{u: 1, v: -1}, {u: -sqrt(3), v: 1}, {u: sqrt(10), v: 2}]
    off = [{u: 0, v: 0}, {u: 2, v: 1}]
    assert [rank_at(W, pt) for pt in on + off] == [1, 1, 1, 2, 2]
    for pt in on + off:
        assert len([c for c, _ in cases if c.xreplace(pt) is true]) == 1
    # the check rejects a wrong claim (rank 2 on the curve)
    assert rank_at(W, on[2]) != 2


def test_cosines_of_two_angles_are_decided_on_their_curve():
    # cos(a) + cos(b) = 1: sines and cosines of two angles, linear in no symbol the
    # split may solve for; decided modulo the curve and the two circles
    from sympy import cos, pi

    a, b = symbols("a b", real=True)
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]),
                    Wrench.force(Z, point=[cos(a) + cos(b) - 1, 0, 0]))
    cases = W.rank_conditions()
    assert cases == [(Ne(cos(a) + cos(b) - 1, 0), 2), (Eq(cos(a) + cos(b) - 1, 0), 1)]
    on = [{a: pi / 3, b: pi / 3}, {a: 0, b: pi / 2}, {a: -pi / 2, b: 0}]
    assert [rank_at(W, pt) for pt in on] == [1, 1, 1]
    for pt in on:
        assert cases[1][0].xreplace(pt) is true
    assert rank_at(W, {a: 0, b: 0}) == 2


def test_where_two_curves_meet_the_points_are_decided():
    # three parallel forces at (0, 0), (f, 0), (0, h): rank 3 off f h = 0, 2 on f = 0
    # where h != 0; where both vanish, h modulo f is v**3 + v**2 - 3 (one symbol): decided
    # at its real root, then f there (u = +-sqrt(5 - v**2)): all three forces at the origin
    from sympy import CRootOf

    u, v = symbols("u v", real=True)
    f, h = u**2 - v**3 - 2, u**2 + v**2 - 5
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]), Wrench.force(Z, point=[f, 0, 0]),
                    Wrench.force(Z, point=[0, h, 0]))
    cases = W.rank_conditions()
    assert cases[0] == (And(Ne(f, 0), Ne(h, 0)), 3)
    assert None not in [r for _, r in cases]
    r = CRootOf(v**3 + v**2 - 3, 0)
    assert (And(Ne(v**3 + v**2 - 3, 0), Eq(f, 0)), 2) in cases
    assert [c for c, rank in cases if rank == 1 and c.has(Eq(v, r))]
    # independently: on f = 0 with h != 0 the rank is 2; off both, 3; where both vanish, 1
    assert rank_at(W, {u: 1, v: -1}) == 2
    assert rank_at(W, {u: 0, v: 0}) == 3
    assert float(5 - r**2) > 0  # and u = sqrt(5 - r**2) is real there


@pytest.mark.slow
def test_pure_translations_agree_with_the_intersection():
    # the platform's pure translations by Cramer's rule on the omega block, against the
    # definition: the intersection of its twist system with the three translations
    from _mechanisms import three_rps

    from screwsym.systems.motion_type import pure_translations

    r = symbols("r", real=True)
    rho = (r, Rational(-1, 2), Rational(-1, 2))
    at = {r: 1}
    for mech in (three_rps(rho), three_rps()):
        T = mech.twists
        m = mech.mobility()
        ours = pure_translations(T.matrix, m.rotations)
        pure = T & ScrewSystem(*(Twist.translation(e) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])))
        theirs = pure.basis().matrix[3:, :]
        A, B = Matrix(ours.xreplace(at)), Matrix(theirs.xreplace(at))
        assert A.rank() == B.rank() == Matrix.hstack(A, B).rank() == m.translations
    # and it rejects a wrong answer: a rotation's v part is not a pure translation here
    wrong = Matrix(T.matrix[3:, :1].xreplace(at))
    assert Matrix.hstack(Matrix(ours.xreplace(at)), wrong).rank() > m.translations


def test_a_universal_joint_made_parallel_is_reported():
    # the U's second axis (1, a, 0) is parallel to its first (1, 0, 0) at a = 0
    a = symbols("a", real=True)
    leg1 = Limb(U([0, 0, 0], [1, 0, 0], [1, a, 0]), P([0, 0, 1]), S([0, 0, 2]))
    leg2 = Limb(R([1, 0, 0], [1, 0, 0]), P([0, 1, 1]), S([1, 1, 1]))
    mech = ParallelMechanism(leg1, leg2)
    cases = mech.mobility_cases()
    assert [c for c, _ in cases] == [Ne(a, 0), Eq(a, 0)]
    assert cases[0][1].mobility == 5
    assert isinstance(cases[1][1], Degenerate)
    assert "a universal joint needs two non-parallel axes" in cases[1][1].reason
    assert_cases_at(mech, cases, [{a: 0}, {a: 2}, {a: Rational(-1, 3)}])


def test_roots_that_the_assumptions_refute_are_no_case():
    # h positive: of the roots of h**2 - 2 only h = sqrt(2) is a case
    h, t = symbols("h", positive=True), symbols("t", real=True)
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]), Wrench.force(Z, point=[h**2 - 2, 0, 0]))
    assert W.rank_conditions() == [(Ne(h**2 - 2, 0), 2), (Eq(h, sqrt(2)), 1)]
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]), Wrench.force(Z, point=[t**2 - 2, 0, 0]))
    assert W.rank_conditions() == [(Ne(t**2 - 2, 0), 2), (Eq(t, -sqrt(2)), 1), (Eq(t, sqrt(2)), 1)]


def test_a_condition_with_surd_coefficients_and_no_real_root_is_dropped():
    # t**2 + sqrt(3) t + 1 has discriminant 3 - 4 < 0: its norm over the rationals,
    # (t**2 + 1)**2 - 3 t**2 = t**4 - t**2 + 1, has no real root, so no real t makes the
    # first twist vanish; t**2 + sqrt(3) t - 1 has real roots and keeps its case
    t = symbols("t", real=True)

    def cases(f):
        return ScrewSystem(Twist([f, 0, 0], [0, 0, 0]), Twist([0, 1, 0], [0, 0, 0])).rank_conditions()

    assert cases(t**2 + sqrt(3) * t + 1) == [(true, 2)]
    real = cases(t**2 + sqrt(3) * t - 1)
    assert len(real) == 2 and real[1][0] == Eq(t**2 + sqrt(3) * t - 1, 0)


def test_a_product_of_positive_factors_has_no_real_zero():
    # (x**2 + y**2 + 1)**2 z**2 + 1: quadratic in z whose leading coefficient and
    # discriminant are proved positive factor by factor; no case at all
    x, y, z = symbols("x y z", real=True)
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]),
                    Wrench.force(Z, point=[(x**2 + y**2 + 1)**2 * z**2 + 1, 0, 0]))
    assert W.rank_conditions() == [(True, 2)]
    # and the proof rejects a polynomial with real zeros: (x**2 + y**2 - 1) z**2 - 1 vanishes
    # at x = 2, y = 0, z = 1/sqrt(3), so its case is listed, and decided there
    g = (x**2 + y**2 - 1) * z**2 - 1
    W2 = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]), Wrench.force(Z, point=[g, 0, 0]))
    cases = W2.rank_conditions()
    assert [r for _, r in cases] == [2, 1]
    assert cases[1][0].xreplace({x: 2, y: 0, z: 1 / sqrt(3)}) is true
    assert W2.xreplace({x: 2, y: 0, z: 1 / sqrt(3)}).matrix.rank() == 1


def planar_4r_twists(f, h):
    """The twists of a planar 4R loop: pivots O, B = (1, f), C = (3, h), D = (4, 0) on z axes."""
    return ScrewSystem(*(Twist.rotation(Z, point=p)
                         for p in ([0, 0, 0], [1, f, 0], [3, h, 0], [4, 0, 0])))


def assert_one_case_with_its_rank(T, cases, points):
    for point in points:
        holding = [r for c, r in cases if c.xreplace(point) is true]
        assert len(holding) == 1, (point, holding)
        assert holding[0] is None or holding[0] == rank_at(T, point), (point, holding)


def test_where_two_curves_meet_off_any_substitution_their_points_are_decided():
    # B = (1, f), C = (3, h) with f = t**2 + u**2 - 2, h = t**3 + u**2 - 2.  The generic minor
    # is g = h - 3 f (O, B, C in one line), a cubic linear in no symbol; on g = 0 the rank
    # stays 3 (Gosselin & Angeles 1990: a planar loop loses rank only with its four pivots
    # in one line) until f = 0 too, and f modulo g is f itself: two curves, linear in no
    # symbol, meeting.  A lex Groebner basis of both gives t**2 (t - 1) there (one symbol),
    # decided at its roots: the four points (1, +-1), (0, +-sqrt(2)), rank 2
    t, u = symbols("t u", real=True)
    f, h = t**2 + u**2 - 2, t**3 + u**2 - 2
    T = planar_4r_twists(f, h)
    cases = T.rank_conditions()
    g = t**3 - 3 * t**2 - 2 * u**2 + 4
    assert cases[:2] == [(Ne(g, 0), 3), (And(Ne(f, 0), Eq(g, 0)), 3)]
    assert [r for _, r in cases[2:]] == [2, 2, 2, 2]
    meet = [{t: 1, u: 1}, {t: 1, u: -1}, {t: 0, u: sqrt(2)}, {t: 0, u: -sqrt(2)}]
    on_g = [{t: 2, u: 0}, {t: -1, u: 0}]  # g = 0, f != 0
    on_f = [{t: Rational(7, 5), u: Rational(1, 5)}, {t: -1, u: 1}]  # f = 0, g != 0
    rng = random.Random(3)
    off = [{t: Rational(rng.randint(-9, 9), rng.randint(1, 4)),
            u: Rational(rng.randint(-9, 9), rng.randint(1, 4))} for _ in range(4)]
    assert [rank_at(T, p) for p in meet + on_g] == [2] * 4 + [3] * 2
    assert_one_case_with_its_rank(T, cases, meet + on_g + on_f + off)
    # the check rejects a wrong answer: the points of f = 0 and g = 0 given rank 3
    with pytest.raises(AssertionError):
        assert_one_case_with_its_rank(T, cases[:2] + [(c, 3) for c, _ in cases[2:]], meet)


def test_an_intersection_left_undecided_states_both_equations():
    # with a third symbol the two surfaces meet in a curve: that case is undecided (None),
    # and its condition holds only where both equations do (it once said f = 0 alone, and
    # two cases held at the points of f = 0 off g = 0)
    t, u, w = symbols("t u w", real=True)
    f, h = t**2 + u**2 + w**2 - 2, t**3 + u**2 - 2
    T = planar_4r_twists(f, h)
    cases = T.rank_conditions()
    g = h - 3 * f
    assert cases[-1] == (And(Eq(f, 0), Eq(g.expand(), 0)), None)
    on_f = [{t: Rational(7, 5), u: Rational(1, 5), w: 0}, {t: 1, u: 0, w: 1}]
    meet = [{t: 1, u: 1, w: 0}, {t: 1, u: -1, w: 0}]
    assert_one_case_with_its_rank(T, cases, on_f + meet + [{t: 0, u: 0, w: 0}])
    assert [rank_at(T, p) for p in meet] == [2, 2]  # undecided there, not wrong


def assert_mobility_at(pm, m, point):
    """A ParallelMechanism case's Mobility checked where it holds: the mechanism rebuilt at the
    exact ``point`` has its numbers, and the case's platform twists span its twists there."""
    here = pm.xreplace(point).mobility()
    assert m.answer() == here.answer(), (point, m, here)
    twists = m.twists.xreplace(point)
    assert twists.rank == here.twists.rank == (twists | here.twists).rank, (point, twists)


def test_a_parallel_mechanism_is_decided_on_a_surface():
    # the four-bar of test_graph's circle as a ParallelMechanism, B = (1, t**2 + u**2 - 2):
    # folded on the circle (Gosselin & Angeles 1990), a case no substitution states.  The
    # split goes on modulo it: the platform's twists by Cramer's rule on the proved minor
    t, u = symbols("t u", real=True)
    f = t**2 + u**2 - 2
    pm = ParallelMechanism(Limb(R([0, 0, 0], Z), R([1, f, 0], Z)),
                           Limb(R([4, 0, 0], Z), R([3, 0, 0], Z)))
    cases = pm.mobility_cases()
    assert [(c, m.mobility, m.motion) for c, m in cases] == [(Ne(f, 0), 1, "1R"),
                                                             (Eq(f, 0), 2, "1T1R")]
    on = [{t: 1, u: 1}, {t: Rational(7, 5), u: Rational(1, 5)}, {t: sqrt(2), u: 0}]
    for point in on:
        assert_mobility_at(pm, cases[1][1], point)
    assert_mobility_at(pm, cases[0][1], {t: 0, u: 0})
    # the checker rejects a wrong answer: the generic case's figures on the circle
    with pytest.raises(AssertionError):
        assert_mobility_at(pm, cases[0][1], on[0])


def test_a_helical_freedom_on_a_surface_keeps_its_pitch():
    # two H-P limbs about the z axis, pitches 1 and t**2 + u**2 - 1: the helices agree on the
    # circle t**2 + u**2 = 2, where the platform gains a screw motion of pitch 1 (Hunt 1978,
    # Ch. 12: a helical freedom is no rotation); off it, the translation alone
    from screwsym.systems.joints import Helical

    t, u = symbols("t u", real=True)
    f = t**2 + u**2 - 2
    pm = ParallelMechanism(Limb(Helical([0, 0, 0], Z, 1), P([1, 0, 0])),
                           Limb(Helical([0, 0, 0], Z, f + 1), P([1, 0, 0])))
    cases = pm.mobility_cases()
    assert [(c, m.motion, m.helical_pitches) for c, m in cases] == [
        (Ne(f, 0), "1T", ()), (Eq(f, 0), "1T1H", (1,))]
    for point in ({t: 1, u: 1}, {t: 0, u: sqrt(2)}):
        assert_mobility_at(pm, cases[1][1], point)
        assert pm.xreplace(point).mobility().helical_pitches == (1,)


def test_pure_translations_on_a_surface_are_decided():
    # two P-P limbs, the second's axis (0, 1, t**2 + u**2 - 2): in the plane of the first's
    # exactly on the circle, where the platform translates in the plane (2T); off it along x
    # alone.  No angular velocity at all on the circle (rank 0 proved modulo it)
    t, u = symbols("t u", real=True)
    f = t**2 + u**2 - 2
    pm = ParallelMechanism(Limb(P([1, 0, 0]), P([0, 1, 0])), Limb(P([1, 0, 0]), P([0, 1, f])))
    cases = pm.mobility_cases()
    assert [(c, m.motion) for c, m in cases] == [(Ne(f, 0), "1T"), (Eq(f, 0), "2T")]
    assert cases[1][1].translation_directions == Matrix([[1, 0], [0, 1], [0, 0]])
    for point in ({t: 1, u: 1}, {t: sqrt(2), u: 0}):
        assert_mobility_at(pm, cases[1][1], point)


def test_a_joint_unmade_on_a_surface_is_reported():
    # an R axis (0, 0, t**2 + u**2 - 2) vanishes on the circle, and a universal joint's axes
    # (1, 0, 0), (1, t**2 + u**2 - 2, 0) become parallel there: no substitution states the
    # case, so the joints cannot be rebuilt; their twists lose rank on it instead
    t, u = symbols("t u", real=True)
    f = t**2 + u**2 - 2
    on = {t: 1, u: 1}
    zero_axis = ParallelMechanism(Limb(R([0, 0, 0], [0, 0, f]), R([1, 2, 0], Z)),
                                  Limb(R([4, 0, 0], Z), R([3, 3, 0], Z)))
    parallel = ParallelMechanism(Limb(U([0, 0, 0], [1, 0, 0], [1, f, 0]), P(Z), S([0, 0, 1])),
                                 Limb(S([2, 0, 0]), S([1, 1, 1])))
    for pm, where in ((zero_axis, "limbs[0]: joints[0]: its 1 twist(s) have rank 0"),
                      (parallel, "limbs[0]: joints[0]: its 2 twist(s) have rank 1")):
        cases = pm.mobility_cases()
        assert cases[0][0] == Ne(f, 0) and not isinstance(cases[0][1], Degenerate)
        (cond, found), = [(c, m) for c, m in cases if isinstance(m, Degenerate)]
        assert cond == Eq(f, 0) and found.reason.startswith(where)
        # independently: the joint's constructor refuses it at a point of the circle
        with pytest.raises(ValueError):
            pm.xreplace(on)
        assert_cases_at(pm, cases, [on, {t: 0, u: 0}])


def test_a_power_of_a_high_degree_root_is_taken_inside_its_field():
    # issue 32: field_element(K, r**11) of a degree-11 CRootOf went through K.from_sympy of
    # the power (a minimal polynomial of r**11: minutes, uncharged); now r is converted once
    # and the power taken in K.  Checked against the identity r**11 = 3 r - 1 (r a root of
    # x**11 - 3 x + 1), which also rejects a wrong answer
    from sympy import QQ, CRootOf, symbols

    from screwsym.algebra.rings import field_element

    x = symbols("x")
    r = CRootOf(x**11 - 3 * x + 1, 0)
    K = QQ.algebraic_field(r)
    got = field_element(K, 2 * r**11 + r**-2)
    inverse_square = K.quo(K.one, field_element(K, r) ** 2)
    assert got == field_element(K, 6 * r - 2) + inverse_square
    assert got != field_element(K, 6 * r - 2)
