"""The graph ``Mechanism`` (Davies' method) with geometry that moves: sin and cos of symbols.

Every split is checked independently at exact points of the unit circle: the rational points
``(2t/(1+t^2), (1-t^2)/(1+t^2))`` (``sin = 4/5, cos = 3/5`` among them) and the special angles
(``q = 0``, ``q = pi``, which the half-angle ``tan(q/2)`` cannot reach, and the case's own
surd points).  There ``sin(q)`` and ``cos(q)`` become numbers and the mechanism goes through
the rational path of ``Mechanism.mobility`` (exact rank over QQ or an algebraic field): exactly
one case holds, with that mobility, rank and loop orders; and, where the mechanism is a
``ParallelMechanism``'s, its own case split agrees (joint rates = platform freedoms + passive).
"""

from __future__ import annotations

import random

import pytest
from _linkages import assert_case_at, four_r, planar
from sympy import Eq, Matrix, Ne, Rational, cos, pi, sin, sqrt, symbols, tan, true

from screwsym import Twist
from screwsym.systems.joints import R
from screwsym.systems.linkage import Mechanism
from screwsym.systems.parallel import Limb, ParallelMechanism

Z = [0, 0, 1]
q = symbols("q", real=True)


def circle_points(angles, special=(), seed=0, count=5):
    """Substitutions ``{sin(q): s, cos(q): c, ...}``: random rational points and the ``special`` ones.

    ``special``: ``{q: exact angle}`` each (the other angles at the first random point).
    """
    rng = random.Random(seed)
    out = [{sin(a): Rational(4, 5), cos(a): Rational(3, 5)} for a in angles]
    out = [dict(p for d in out for p in d.items())]
    for _ in range(count):
        d = {}
        for a in angles:
            t = Rational(rng.randint(-9, 9), rng.randint(1, 5))
            d[sin(a)], d[cos(a)] = 2 * t / (1 + t**2), (1 - t**2) / (1 + t**2)
        out.append(d)
    for known in special:
        d = dict(out[1])
        for a, value in known.items():
            d[sin(a)], d[cos(a)] = sin(value), cos(value)
        out.append(d)
    return out


def assert_circle_cases(mech, points, pm=None, cases=None):
    """At each point exactly one case holds, with the figures of the rational path there."""
    splits = [cases] if cases is not None else [mech.mobility_cases(merge=False),
                                                mech.mobility_cases()]
    pm_cases = None if pm is None else pm.mobility_cases()
    for point in points:
        here_mech = mech.xreplace(point)
        assert not here_mech.network_matrix().free_symbols  # the rational path, no angle left
        here = here_mech.mobility()
        for split in splits:
            holding = [m for c, m in split if c.xreplace(point) is true]
            assert len(holding) == 1, f"{len(holding)} cases hold at {point}"
            m = holding[0]
            assert m is None or (m.mobility, m.rank, m.orders) == (
                here.mobility, here.rank, here.orders), (point, m, here)
        if pm_cases is not None:
            [pmm] = [m for c, m in pm_cases if c.xreplace(point) is true]
            assert here.mobility == pmm.mobility + pmm.passive, (point, here, pmm)


def crank_four_bar():
    # the construction of test_trig_cases.test_a_crank_four_bar_folds_at_zero_and_pi
    return ParallelMechanism(Limb(R([0, 0, 0], Z), R([cos(q), sin(q), 0], Z)),
                             Limb(R([4, 0, 0], Z), R([3, 0, 0], Z)))


def test_a_crank_four_bar_as_a_graph_folds_at_zero_and_pi_as_the_parallel_mechanism_does():
    # the coupler pivot on the unit circle, the rocker pivots on the x axis: the four-bar folds
    # (2 instantaneous freedoms) where the four pivots are collinear, q = 0 and q = pi
    # (Gosselin & Angeles 1990: a closed planar chain is singular where its pivots align);
    # the same cases as ParallelMechanism's (tests/systems/test_trig_cases.py)
    pm = crank_four_bar()
    mech = Mechanism.from_parallel(pm)
    assert mech.mobility().mobility == 1
    merged = [(c, m.mobility) for c, m in mech.mobility_cases()]
    assert merged == [(Ne(sin(q), 0), 1), (Eq(sin(q), 0), 2)]
    assert merged == [(c, m.mobility) for c, m in pm.mobility_cases()]
    split = mech.mobility_cases(merge=False)
    assert [c for c, _ in split] == [c for c, _ in pm.mobility_cases(merge=False)] == [
        Ne(sin(q), 0), Eq(sin(q), 0) & Eq(cos(q), 1), Eq(sin(q), 0) & Eq(cos(q), -1)]
    assert [(m.mobility, m.orders) for _, m in split] == [(1, (3,)), (2, (2,)), (2, (2,))]
    assert_circle_cases(mech, circle_points([q], [{q: 0}, {q: pi}, {q: pi / 2}]), pm)
    for value, expected in ((0, 2), (pi, 2), (pi / 3, 1)):  # q itself, not sin and cos
        assert mech.xreplace({q: value}).mobility().mobility == expected


def parallelogram():
    """The planar parallelogram: crank and rocker of length 1 at angle q, ground and coupler 2."""
    return four_r([[0, 0, 0], [cos(q), sin(q), 0], [2 + cos(q), sin(q), 0], [2, 0, 0]], [Z] * 4,
                  names=("ground", "left", "coupler", "right"))


def test_a_parallelogram_translates_its_coupler_at_every_angle_off_the_flat_poses():
    # the parallelogram loop of the Delta robot's forearms (Clavel 1988): its coupler
    # translates on a circle, one freedom, at every angle q but the flat poses sin(q) = 0,
    # where the four pivots are collinear and a second (instantaneous) freedom appears: the
    # change point where the parallelogram and the anti-parallelogram branches meet (Hunt,
    # Kinematic Geometry of Mechanisms, 1978, §2; test_graph's flat parallelogram)
    mech = parallelogram()
    m = mech.mobility()
    assert (m.mobility, m.orders, m.passive) == (1, (3,), 0)
    assert m.rates == Matrix([1, -1, 1, -1])
    assert mech.motion("coupler") == "1T"
    assert mech.relative_twists("coupler").screws == (Twist([0, 0, 0], [sin(q), -cos(q), 0]),)
    assert mech.helical_pitches("coupler") == ()
    assert mech.second_order().mobility == 1  # the forms vanish on the whole circle
    assert [(c, m.mobility) for c, m in mech.mobility_cases()] == [
        (Ne(sin(q), 0), 1), (Eq(sin(q), 0), 2)]
    assert_circle_cases(mech, circle_points([q], [{q: 0}, {q: pi}, {q: -pi / 2}]))


def three_dyads():
    # two loops: two parallel cranks (a parallelogram, the coupler translating) and a third
    # dyad from E = (3, -1) to the coupler point F = B + (1, 1)
    return ParallelMechanism(Limb(R([0, 0, 0], Z), R([cos(q), sin(q), 0], Z)),
                             Limb(R([2, 0, 0], Z), R([2 + cos(q), sin(q), 0], Z)),
                             Limb(R([3, -1, 0], Z), R([1 + cos(q), 1 + sin(q), 0], Z)))


def test_two_loops_at_a_moving_configuration():
    # the parallelogram's coupler translates along v = (-sin q, cos q); the third dyad lets F
    # move only at right angles to F - E = (cos q - 2, sin q + 2), so the structure is rigid
    # (Grübler: 3 (5 - 1) - 2 * 6 = 0) except where v . (F - E) = 2 (sin q + cos q) = 0,
    # q = 3 pi / 4 and q = -pi / 4 (a dead point: the translation is allowed), and at the
    # flat poses sin(q) = 0 (the parallelogram folded)
    pm = three_dyads()
    mech = Mechanism.from_parallel(pm)
    assert (mech.mobility().mobility, mech.mobility().loops) == (0, 2)
    split = mech.mobility_cases(merge=False)
    moving = [c for c, m in split if m.mobility == 1]
    assert sorted(moving, key=str) == sorted([
        Ne(sin(q), 0) & Eq(sin(q), -sqrt(2) / 2) & Eq(cos(q), sqrt(2) / 2) & Ne(3 * sin(q) + cos(q), 0),
        Ne(sin(q), 0) & Eq(sin(q), sqrt(2) / 2) & Eq(cos(q), -sqrt(2) / 2) & Ne(3 * sin(q) + cos(q), 0),
        Eq(sin(q), 0) & Eq(cos(q), 1), Eq(sin(q), 0) & Eq(cos(q), -1)], key=str)
    special = [{q: 0}, {q: pi}, {q: 3 * pi / 4}, {q: -pi / 4}, {q: pi / 2}]
    points = circle_points([q], special, count=2)
    # and where 3 sin(q) + cos(q) = 0 (a factor of a minor, not a change of mobility)
    points += [{sin(q): s * sqrt(10) / 10, cos(q): -3 * s * sqrt(10) / 10} for s in (1, -1)]
    assert_circle_cases(mech, points, pm, cases=split)
    assert_circle_cases(mech, points, pm, cases=mech.mobility_cases())


def test_a_watt_six_bar_gains_a_freedom_where_its_dyad_is_stretched():
    # Watt's six-bar (tests/_linkages.watt: ternary links T1, the ground, and T2 joined at O),
    # its second loop T1-c-d-T2 at a toggle position: the pivots C = (-3, 1), D = (-4, 4),
    # E = (-2, -2) of the dyad c-d in one line, so the output rocker T2 has no velocity
    # (the toggle of a four-bar, input and coupler in line: Hartenberg & Denavit, Kinematic
    # Synthesis of Linkages, 1964, on toggle positions) and c keeps one instantaneous
    # freedom (v_D along the line CDE is zero for any rate of c).  With T2 held, the
    # dyad a-b between A = (4, 0) and B = (2, 4), its middle pivot P = A + (cos q, sin q),
    # moves only where it is stretched: P on the line AB, sin(q) + 2 cos(q) = 0, two freedoms
    mech = planar([("T1", "T2", (0, 0)), ("T1", "a", (4, 0)), ("a", "b", (4 + cos(q), sin(q))),
                   ("b", "T2", (2, 4)), ("T1", "c", (-3, 1)), ("c", "d", (-4, 4)),
                   ("d", "T2", (-2, -2))], base="T1")
    m = mech.mobility()
    assert (m.mobility, m.loops, m.orders) == (1, 2, (3, 3))
    assert m.rates.T == Matrix([[0, 0, 0, 0, 2, -1, -1]])  # c alone moves; T2 is held
    split = mech.mobility_cases(merge=False)
    r5 = sqrt(5) / 5
    assert [c for c, m in split if m.mobility == 2] == [
        Ne(sin(q), 0) & Eq(sin(q), -2 * r5) & Eq(cos(q), r5),
        Ne(sin(q), 0) & Eq(sin(q), 2 * r5) & Eq(cos(q), -r5)]
    points = circle_points([q], [{q: 0}, {q: pi}], count=3)
    points += [{sin(q): 2 * s * r5, cos(q): -s * r5} for s in (1, -1)]
    assert_circle_cases(mech, points, cases=split)
    assert_circle_cases(mech, points, cases=mech.mobility_cases())


def test_the_rates_are_polynomial_in_sin_and_cos_and_hold_at_q_equal_pi():
    # a four-bar with the crank pivot B = (cos q, sin q), C = (3, 1), D = (4, 0): never folded
    # (the line CD, x + y = 4, misses the unit circle), one freedom at every q; the basis of
    # its joint rates, found over tan(q/2) and written back, is of degree 1 in sin and cos and
    # is a non-zero null vector at every angle, q = pi included
    mech = four_r([[0, 0, 0], [cos(q), sin(q), 0], [3, 1, 0], [4, 0, 0]], [Z] * 4)
    rates = mech.mobility().rates
    assert rates.T == Matrix([[sin(q) + cos(q) - 4, 4, -4 * sin(q), 3 * sin(q) - cos(q)]])
    for point in circle_points([q], [{q: pi}, {q: 0}]):
        A = mech.network_matrix().xreplace(point)
        r = rates.xreplace(point)
        assert A * r == Matrix.zeros(6, 1) and any(e != 0 for e in r)
    assert {m.mobility for _, m in mech.mobility_cases(merge=False)} == {1}
    assert mech.motion("coupler") == "1R"
    assert mech.second_order().mobility == 1


def test_an_angle_and_a_length_together():
    # the crank four-bar with the rocker's upper pivot at C = (3, a): folded (two freedoms)
    # only where all four pivots are collinear, a = 0 and sin(q) = 0 (Gosselin & Angeles 1990,
    # as above); a symbol solved for (a) and an angle decided at its points in one split
    a = symbols("a", real=True)
    pm = ParallelMechanism(Limb(R([0, 0, 0], Z), R([cos(q), sin(q), 0], Z)),
                           Limb(R([4, 0, 0], Z), R([3, a, 0], Z)))
    mech = Mechanism.from_parallel(pm)
    cases = mech.mobility_cases()
    assert [(c, m.mobility) for c, m in cases][1:] == [(Eq(a, 0) & Eq(sin(q), 0), 2)]
    points = [{**p, a: v} for v in (0, 1, Rational(-2, 3))
              for p in circle_points([q], [{q: 0}, {q: pi}], count=2)]
    assert_circle_cases(mech, points, pm)


def test_second_order_with_an_angle_decides_where_the_forms_vanish_on_the_circle_else_none():
    # four revolutes on lines of one regulus of x**2 + y**2 - z**2 = 1, the line through
    # (c, s, 0) along (-s, c, 1), the fourth at angle q: a shaky 4R at every q (one
    # instantaneous freedom, none to second order: Müller 2016, §6; test_graph's shaky_4r is
    # q at (3/5, -4/5)).  With the angle a symbol the forms, reduced on the circle (the first
    # is zero there, though not as written), do not vanish and cannot be signed: None, not a
    # guess; at rational points the rational path decides 0.  The parallelogram's forms vanish
    # on the whole circle: it moves to second order at every angle.
    ring = [(1, 0), (0, 1), (-1, 0), (cos(q), sin(q))]
    shaky = four_r([[c, s, 0] for c, s in ring], [[-s, c, 1] for c, s in ring])
    so = shaky.second_order()
    assert (so.instantaneous, so.mobility, so.cone) == (1, None, None)
    assert so.forms[0] == Matrix([[0]]) and so.forms[2] == Matrix([[12 * sin(q) - 12 * sin(q)**2]])
    for point in circle_points([q], count=2)[:3]:
        assert shaky.xreplace(point).second_order().mobility == 0
    assert parallelogram().second_order().mobility == 1


def test_the_checker_rejects_a_wrong_answer():
    pm = crank_four_bar()
    mech = Mechanism.from_parallel(pm)
    good = mech.mobility_cases(merge=False)
    points = circle_points([q], [{q: pi}])
    with pytest.raises(AssertionError):  # q = pi given the generic mobility
        assert_circle_cases(mech, points, cases=[(c, m._replace(mobility=1)) for c, m in good])
    with pytest.raises(AssertionError, match="0 cases hold"):  # q = pi left out
        assert_circle_cases(mech, points, cases=good[:2])
    with pytest.raises(AssertionError, match="2 cases hold"):  # overlapping cases
        assert_circle_cases(mech, points, cases=good + [(Eq(cos(q), -1), good[2][1])])

    class Liar(ParallelMechanism):  # a ParallelMechanism split that says 1 at the flat poses
        def mobility_cases(self, **kwargs):
            return [(c, m._replace(mobility=1)) for c, m in super().mobility_cases(**kwargs)]

    with pytest.raises(AssertionError):
        assert_circle_cases(mech, points, Liar(*pm.args))


def test_two_angles_a_curve_no_substitution_states_is_decided_on_itself():
    # both pivots on circles, B = (cos a, sin a), C = (4 + cos b, sin b): the loop's minor
    # vanishes where O, B, C are in one line, sin(b - a) = 4 sin(a), a curve in two angles
    # linear in no symbol.  No substitution states it; the split goes on modulo it: the loop
    # keeps order 3 there (one freedom, as off it) unless sin(a) = 0 too, where the curve
    # meets sin(b) = 0: the four points in one line, folded (mobility 2)
    a, b = symbols("a b", real=True)
    mech = four_r([[0, 0, 0], [cos(a), sin(a), 0], [4 + cos(b), sin(b), 0], [4, 0, 0]], [Z] * 4)
    unmerged = mech.mobility_cases(merge=False)
    curve = sin(b) * cos(a) - sin(a) * cos(b) - 4 * sin(a)
    assert unmerged[1][0] == (Ne(sin(a), 0) & Eq(curve, 0))
    assert [m.mobility for _, m in unmerged] == [1, 1, 2, 2, 2, 2]
    cases = mech.mobility_cases()
    assert [m.mobility for _, m in cases] == [1, 2]
    points = circle_points([a, b], [{a: 0, b: pi}, {a: pi, b: 0}, {a: 0, b: 0}])
    # on the curve: b = pi/2 with tan(a) = 1/4, and b = -pi/2 with tan(a) = -1/4 (B, C and
    # the origin in one line)
    on_curve = [{sin(a): 1 / sqrt(17), cos(a): 4 / sqrt(17), sin(b): 1, cos(b): 0},
                {sin(a): -1 / sqrt(17), cos(a): 4 / sqrt(17), sin(b): -1, cos(b): 0}]
    assert_circle_cases(mech, points + on_curve, cases=unmerged)
    assert_circle_cases(mech, points + on_curve, cases=cases)
    for point in on_curve:
        assert unmerged[1][0].xreplace(point) is true
        assert_case_at(mech, unmerged[1][1], point)
    folded = {sin(a): 0, cos(a): 1, sin(b): 0, cos(b): 1}
    assert cases[1][0].xreplace(folded) is true
    assert_case_at(mech, cases[1][1], folded)
    assert mech.xreplace({a: 0, b: 0}).mobility().mobility == 2


def test_a_merged_case_is_written_as_where_no_other_holds():
    # the same four-bar as a ParallelMechanism: its generic case merges five conjunctions
    # (sin(a) = +-1, or sin(a), cos(a) non-zero, ...) that say, on the circles, "not both
    # sines zero"; the cases hold one at each point, so it is written as that complement
    a, b = symbols("a b", real=True)
    pm = ParallelMechanism(Limb(R([0, 0, 0], Z), R([cos(a), sin(a), 0], Z)),
                           Limb(R([4, 0, 0], Z), R([4 + cos(b), sin(b), 0], Z)))
    cases = pm.mobility_cases()
    assert [(c, m.mobility) for c, m in cases] == [
        (Ne(sin(a), 0) | Ne(sin(b), 0), 1), (Eq(sin(a), 0) & Eq(sin(b), 0), 2)]
    points = circle_points([a, b], [{a: 0, b: pi}, {a: pi, b: 0}, {a: 0, b: 0},
                                    {a: pi / 2, b: 0}, {a: -pi / 2, b: pi}])
    assert_circle_cases(Mechanism.from_parallel(pm), points, pm)
    # the unmerged split says the same at every point
    unmerged = pm.mobility_cases(merge=False)
    for point in points:
        [m] = [m for c, m in unmerged if c.xreplace(point) is true]
        [merged] = [mm for c, mm in cases if c.xreplace(point) is true]
        assert m.answer() == merged.answer(), point


def test_geometry_that_is_not_polynomial_in_sin_and_cos_is_refused():
    mech = four_r([[0, 0, 0], [tan(q), 1, 0], [3, 1, 0], [4, 0, 0]], [Z] * 4)
    with pytest.raises(ValueError, match="polynomial in sin and cos of symbols.*tan"):
        mech.mobility()
    with pytest.raises(ValueError, match="polynomial in sin and cos of symbols.*sin\\(q\\*\\*2\\)"):
        four_r([[0, 0, 0], [sin(q**2), 1, 0], [3, 1, 0], [4, 0, 0]], [Z] * 4).mobility()
