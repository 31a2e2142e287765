"""Singularities at every configuration, numbers or symbols (issue 32).

Literature: Gosselin & Angeles (1990) for the planar 3-RPR (type II where the three leg
lines are concurrent or all parallel); Ma & Angeles (1991) for the architecture
singularity of a Gough-Stewart platform with similar base and platform hexagons at zero
orientation; Bonev, Zlatanov & Gosselin (2003) for the stretched leg of a planar 3-RRR
(type I: the crank's actuation wrench passes through its own axis, Jq singular, Jx
regular).  Each check is independent of the code under test (the numeric rank of the
legs' own lines, a NumPy rank) and is shown to reject a wrong answer.
"""

from __future__ import annotations

import numpy as np
import pytest
from sympy import Matrix, Min, Rational, cos, nan, sin, symbols, true

from screwsym.systems.joints import P, R
from screwsym.systems.parallel import Limb, ParallelMechanism
from tests._actuated import (
    HEXAGON,
    RPR_BASE,
    RPR_CONCURRENT,
    RPR_PARALLEL,
    RPR_PLATFORM,
    gough_stewart_66,
    three_rpr,
)

Z = [0, 0, 1]


def leg_lines_rank(base, platform, pose=(0, 0)):
    """The rank of the three leg lines of a 3-RPR as planar forces (f_x, f_y, moment): an
    independent NumPy check (Gosselin & Angeles 1990: singular where they are dependent)."""
    rows = []
    for a, b in zip(base, platform, strict=True):
        top = np.array([b[0] + pose[0], b[1] + pose[1]], dtype=float)
        d = top - np.array(a, dtype=float)
        rows.append([d[0], d[1], top[0] * d[1] - top[1] * d[0]])
    return np.linalg.matrix_rank(np.array(rows))


# ------------------------------------------------------------------ 3-RPR: type II at numbers
@pytest.mark.parametrize("base", [RPR_CONCURRENT, RPR_PARALLEL])
def test_three_rpr_concurrent_or_parallel_legs_are_type_two_at_numbers(base):
    # Gosselin & Angeles (1990), Sec. III-B: the 3-RPR is singular (type II) where its three
    # leg lines meet in one point or are all parallel: Jx of rank 5, given by numbers
    assert leg_lines_rank(base, RPR_PLATFORM) == 2  # the independent check: dependent lines
    s = three_rpr(0, 0, 1, 0, base, RPR_PLATFORM).singularities()
    assert s.actuation == [(True, 5)]
    assert s.limb == [] and s.constraint == []
    assert "actuation" in str(s) and r"\text{actuation}" in s._repr_latex_()


def test_three_rpr_regular_pose_has_no_singularity_and_the_check_rejects_it():
    assert leg_lines_rank(RPR_BASE, RPR_PLATFORM) == 3  # independent lines: regular
    s = three_rpr(0, 0, 1, 0, RPR_BASE, RPR_PLATFORM).singularities()
    assert s == ([], [], [], ())
    assert "regular" in str(s)
    # the checker rejects a wrong answer: the singular bases give a non-empty type II part,
    # and the regular one must not be read as singular
    assert three_rpr(0, 0, 1, 0, RPR_CONCURRENT, RPR_PLATFORM).singularities().actuation != []


@pytest.mark.slow
def test_three_rpr_symbolic_translation_type_two_set_holds_where_the_legs_are_dependent():
    # with the pose (x, y) symbolic (phi = 0), the type II condition returned holds exactly
    # where the leg lines are dependent (the NumPy rank above), here at exact poses
    x, y = symbols("x y", real=True)
    s = three_rpr(x, y, 1, 0, RPR_BASE, RPR_PLATFORM).singularities()
    assert s.constraint == [] and s.actuation
    conds = [c for c, _ in s.actuation]
    hits = 0
    for px in range(-3, 4):
        for py in range(-3, 4):
            holds = any(c.subs({x: px, y: py}) is true for c in conds)
            singular = leg_lines_rank(RPR_BASE, RPR_PLATFORM, (px, py)) < 3
            lengths = all(np.hypot(b[0] + px - a[0], b[1] + py - a[1]) > 0
                          for a, b in zip(RPR_BASE, RPR_PLATFORM, strict=True))
            if lengths:
                assert holds == singular, (px, py)
                hits += holds
    assert hits > 0  # some singular pose is in the grid, so a wrong (empty) answer fails


# ------------------------------------------------------------------ Ma & Angeles 1991
def test_similar_hexagons_are_an_architecture_singularity():
    # Ma & Angeles (1991): a Gough-Stewart platform whose base and platform are similar
    # planar hexagons is singular at every translation with zero orientation.  Given by
    # numbers: type II, rank 3; the checker: a NumPy rank of the six leg lines
    def numeric_rank(x, y, z):
        rows = []
        for a in HEXAGON:
            b = np.array([a[0], a[1], 0.0])
            top = np.array([a[0] / 2 + x, a[1] / 2 + y, z])
            d = top - b
            rows.append([*d, *np.cross(top, d)])
        return np.linalg.matrix_rank(np.array(rows))

    assert numeric_rank(1, 2, 3) == numeric_rank(-2, 0.5, 1.5) == 3
    s = gough_stewart_66(1, 2, 3, HEXAGON).singularities()
    assert s.actuation == [(True, 3)] and s.limb == [] and s.constraint == []
    # the checker rejects a wrong answer: a platform that is not similar (one vertex moved)
    other = [*HEXAGON[:5], (5, -1)]
    assert np.linalg.matrix_rank(np.array(
        [[*(np.array([a[0] / 2 + 1, a[1] / 2 + 2, 3]) - [a[0], a[1], 0]),
          *np.cross([a[0] / 2 + 1, a[1] / 2 + 2, 3],
                    np.array([a[0] / 2 + 1, a[1] / 2 + 2, 3]) - [a[0], a[1], 0])]
         for a in HEXAGON])) == 3
    legs = list(gough_stewart_66(1, 2, 3, HEXAGON).limbs)
    from screwsym.systems.joints import S
    b, top = Matrix([*other[5], 0]), Matrix([Rational(7, 3), Rational(5, 4), 3])
    legs[5] = Limb(S(b), P(top - b), S(top), actuated=1)
    assert ParallelMechanism(*legs).singularities().actuation != [(True, 3)]


@pytest.mark.slow
def test_similar_hexagons_symbolic_translation_is_singular_everywhere():
    # the same platform at a symbolic translation: the first entry holds everywhere
    x, y, z = symbols("x y z", real=True)
    s = gough_stewart_66(x, y, z, HEXAGON).singularities()
    assert s.actuation[0] == (True, 3)
    assert all(r < 3 for _, r in s.actuation[1:])


# ------------------------------------------------------------------ Bonev et al. 2003: type I
def stretched_three_rrr():
    """A planar 3-RRR, crank (joint 0) actuated; leg 0 stretched: A, elbow and platform
    pivot collinear along the x axis; the platform triangle (2,0), (3,1), (2,1)."""
    return ParallelMechanism(
        Limb(R([0, 0, 0], Z), R([1, 0, 0], Z), R([2, 0, 0], Z), actuated=0),
        Limb(R([4, 0, 0], Z), R([4, 1, 0], Z), R([3, 1, 0], Z), actuated=0),
        Limb(R([0, 3, 0], Z), R([1, 3, 0], Z), R([2, 1, 0], Z), actuated=0))


def test_stretched_three_rrr_leg_is_reported_not_raised():
    # Bonev, Zlatanov & Gosselin (2003), Sec. 4 (and Gosselin & Angeles 1990, type I): with
    # a leg stretched, its actuation wrench is the force along the leg's line, through the
    # crank's own axis: its entry of Jq is zero, Jx keeps its rank (no type II)
    m = stretched_three_rrr()
    w0 = m.actuation_wrenches()[0]
    assert w0.S.cross(Matrix([1, 0, 0])) == Matrix([0, 0, 0])  # along the x axis line
    assert w0.S0 == Matrix([0, 0, 0])                         # through the origin (A)
    Jx, Jq = m.jacobian()
    assert Jq[0, 0] == 0 and Jq[1, 1] != 0 and Jq[2, 2] != 0
    assert Matrix(Jx).rank() == 6
    s = m.singularities()
    assert s.limb == [(True, 2)] and s.limbs == (0,) and s.actuation == []
    tr = m.transmission()
    assert tr.input[0] == 0 and tr.local == 0 and tr.singular == (0,)
    # the checker rejects a wrong answer: the same mechanism with leg 0 bent is regular
    bent = ParallelMechanism(Limb(R([0, 0, 0], Z), R([1, 1, 0], Z), R([2, 0, 0], Z), actuated=0),
                             *m.limbs[1:])
    assert bent.jacobian()[1][0, 0] != 0 and bent.singularities().limb == []
    assert bent.transmission().singular == () and bent.transmission().local != 0
    assert nan not in bent.transmission().output


# ------------------------------------------------------------------ the symbolic pose
@pytest.mark.slow
def test_symbolic_three_rpr_transmission_within_the_budget():
    # a 3-RPR with its whole pose (x, y, phi) symbolic: the indices come back (the local
    # index an unevaluated Min), and agree with the indices at a numeric pose
    x, y, phi = symbols("x y phi", real=True)
    tr = three_rpr(x, y, cos(phi), sin(phi), RPR_BASE, RPR_PLATFORM).transmission()
    assert isinstance(tr.local, Min) and len(tr.input) == 3
    at = {x: Rational(1, 3), y: Rational(-1, 2), phi: 0}
    num = three_rpr(Rational(1, 3), Rational(-1, 2), 1, 0, RPR_BASE, RPR_PLATFORM).transmission()
    for a, b in zip((*tr.input, *tr.output), (*num.input, *num.output), strict=True):
        assert abs(float(a.subs(at)) - float(b)) < 1e-12
    # and rejects a wrong answer: another pose gives other indices
    assert abs(float(tr.output[0].subs({**at, x: 2})) - float(num.output[0])) > 1e-6


def test_budget_stops_singularities_with_a_clear_error():
    x, y, phi = symbols("x y phi", real=True)
    m = three_rpr(x, y, cos(phi), sin(phi), RPR_BASE, RPR_PLATFORM)
    with pytest.raises(ValueError, match="singularities: the case split needs more work"):
        m.singularities(budget=1000)
    with pytest.raises(ValueError, match="budget"):
        m.singularities(budget=0)


def test_graph_mobility_is_bounded_by_its_budget():
    # issue 32, item 3: the graph Mechanism.mobility() charges its elimination to a budget
    from screwsym.systems._rank_cases import clear_caches
    from screwsym.systems.joints import S
    from screwsym.systems.linkage import Mechanism

    m = Mechanism([("base", "lower", S([0, 0, 0])), ("lower", "upper", P([0, 0, 1])),
                   ("upper", "base", S([0, 0, 2]))], base="base")
    clear_caches()  # the network is cached: a cached one costs nothing
    with pytest.raises(ValueError, match="mobility: the case split needs more work than budget=10 "):
        m.mobility(budget=10)
    assert (m.mobility().mobility, m.mobility().passive) == (1, 1)  # within the default


@pytest.mark.slow
def test_three_rps_has_no_limb_singularity_the_benchmark_readme_was_wrong():
    # issue 32, item 6: benchmarks/README.md (measured on a branch before the merge) gave the
    # 3-RPS at the pose (p, q, z) 6 limb cases; bench_actuation.py now gives 0, and 0 is right
    # (pinned exactly by test_actuation's test_three_rps_at_a_symbolic_pose...): an R-P-S leg
    # keeps its 5 freedoms wherever its length is not zero (R horizontal, P along the leg and
    # normal to it, three rotations at the sphere), and its actuation force along the leg
    # never falls into its constraint (a force along the R axis), which the old split left
    # undecided (None) where two curves met.  Independently, at exact poses:
    from tests._actuated import three_rps_pose

    for pose in ((0, 0, 1), (Rational(1, 2), Rational(-1, 3), 2), (1, 2, Rational(3, 2)),
                 (Rational(-2, 5), 0, Rational(1, 7))):
        m = three_rps_pose(*(Rational(v) for v in pose))
        assert [limb.twists.rank for limb in m.limbs] == [5, 5, 5]
        assert all(Jq != 0 for Jq in m.jacobian()[1].diagonal())
        assert m.singularities().limb == []
    # the checker rejects a limb singularity: a leg of zero length (its P axis zero) would
    # not be built at all, and a leg made to lose a freedom is seen
    z3 = [0, 0, 1]
    assert Limb(R([0, 0, 0], z3), R([1, 0, 0], z3), R([2, 0, 0], z3)).twists.rank == 2


def test_graph_twists_of_tsai_three_upu_are_a_reduced_basis():
    # issue 32, item 2: Tsai's 3-UPU (Tsai 1996: a pure translator) as a graph, link by
    # link: the platform's twists are the three translations as the identity basis (reduced
    # echelon, primitive), the same span as ParallelMechanism.twists, not columns of 1e17
    from screwsym import ScrewSystem
    from screwsym.systems.joints import U
    from screwsym.systems.linkage import Mechanism

    def leg(b, a1, top):
        b, a1, top = Matrix(b), Matrix(a1), Matrix(top)
        a2 = a1.cross(top - b)
        return Limb(U(b, a1, a2), P(top - b), U(top, a2, a1), actuated=1)

    pm = ParallelMechanism(leg([2, 0, 0], [0, 1, 0], [1, 0, 3]),
                           leg([-1, 2, 0], [-2, -1, 0], [0, 1, 3]),
                           leg([-1, -2, 0], [2, -1, 0], [0, -1, 3]))
    got = Mechanism.from_parallel(pm).relative_twists("platform")
    assert [list(t.matrix) for t in got.screws] == [list(r) for r in Matrix.eye(6)[3:, :].tolist()]
    assert max(abs(e) for t in got.screws for e in t.matrix) == 1
    assert (got | pm.twists).rank == 3 == got.rank
    # the checker rejects a wrong span: a rotation in place of a translation
    from screwsym import Twist
    wrong = ScrewSystem(*got.screws[:2], Twist([0, 0, 1], [0, 0, 0]))
    assert (wrong | pm.twists).rank == 4


# ------------------------------------------------------------------ minimal singular sets
def leg_lines_det(base, platform, x, y, c, s):
    """The determinant of the three leg lines of a 3-RPR as planar forces (f_x, f_y, moment),
    written here by hand from the geometry (Gosselin & Angeles 1990, eq. 25: the matrix A)."""
    rows = []
    for a, b in zip(base, platform, strict=True):
        top = (c * b[0] - s * b[1] + x, s * b[0] + c * b[1] + y)
        d = (top[0] - a[0], top[1] - a[1])
        rows.append([d[0], d[1], top[0] * d[1] - top[1] * d[0]])
    return Matrix(rows).det()


def is_minimal_conic(part, det, x, y):
    """The checker: ``part`` is one pair, rank 5, one equation ``F = 0`` with no ``Ne`` guard
    and no ``Or`` of points, ``F`` of degree two in (x, y), written factored (a product of its
    irreducible factors where it has more than one), and a constant multiple of the
    hand-written determinant ``det`` (the same conic)."""
    from sympy import Eq, Mul, Poly, cancel, factor_list

    if len(part) != 1 or part[0][1] != 5 or not isinstance(part[0][0], Eq):
        return False
    cond = part[0][0]
    f = cond.lhs - cond.rhs
    ratio = cancel(f / det)
    factored = len(factor_list(f)[1]) == 1 or isinstance(f, Mul)
    return ratio.is_number and ratio != 0 and Poly(f, x, y).total_degree() == 2 and factored


def test_three_rpr_type_two_set_at_a_fixed_orientation_is_one_conic():
    # Gosselin & Angeles (1990), Sec. III-B, and Sefrioui & Gosselin (1995), "On the
    # quadratic nature of the singularity curves of planar three-degree-of-freedom parallel
    # manipulators", Mech. Mach. Theory 30(4): with the orientation fixed, the type II set of
    # a 3-RPR is a conic in (x, y); it comes back as that one conic, no points on it, no Ne
    from sympy import And, Eq, Ne, Or

    x, y = symbols("x y", real=True)
    c, s = 1, 0
    got = three_rpr(x, y, c, s, RPR_BASE, RPR_PLATFORM).singularities()
    det = leg_lines_det(RPR_BASE, RPR_PLATFORM, x, y, c, s)
    assert is_minimal_conic(got.actuation, det, x, y)
    # at this orientation the conic degenerates into two lines, given as their product
    assert got.actuation[0][0].lhs.is_Mul
    # each leg: singular only where its length is zero, two equations, rank 1 (R and R
    # coincide, the P axis zero), the limb named, no condition twice
    assert [r for _, r in got.limb] == [1, 1, 1] and got.limbs == (0, 1, 2)
    for (cond, _), a, b in zip(got.limb, RPR_BASE, RPR_PLATFORM, strict=True):
        assert isinstance(cond, And) and len(cond.args) == 2
        assert cond.subs({x: a[0] - (c * b[0] - s * b[1]), y: a[1] - (s * b[0] + c * b[1])})
    assert got.constraint == []
    # the checker rejects a non-minimal answer (the conic guarded by Ne's, or with points
    # on it), a wrong conic, and a conic of another orientation
    (cond, _), = got.actuation
    f = cond.lhs - cond.rhs
    assert not is_minimal_conic([(And(cond, Ne(x, 0)), 5)], det, x, y)
    assert not is_minimal_conic([(Or(And(Eq(x, 0), Eq(y, 0)), cond), 5)], det, x, y)
    assert not is_minimal_conic([(Eq(f + 1, 0), 5)], det, x, y)
    assert not is_minimal_conic([(Eq(f.expand() * (x - 7), 0), 5)], det, x, y)
    assert not is_minimal_conic([(Eq(f.expand(), 0), 5)], det, x, y)  # not factored
    turned = leg_lines_det(RPR_BASE, RPR_PLATFORM, x, y, Rational(3, 5), Rational(4, 5))
    assert not is_minimal_conic([(cond, 5)], turned, x, y)
    # and the conic holds exactly where NumPy finds the legs dependent, on a grid with some
    on = [(px, py) for px in range(-5, 6) for py in range(-5, 6) if f.subs({x: px, y: py}) == 0]
    assert len(on) >= 3
    for px in range(-5, 6):
        for py in range(-5, 6):
            assert (leg_lines_rank(RPR_BASE, RPR_PLATFORM, (px, py)) < 3) == ((px, py) in on)


@pytest.mark.slow
def test_three_rpr_symbolic_pose_type_two_set_is_one_surface():
    # the whole pose (x, y, phi) symbolic (issue 32's target: under 30 s, here about 3 s):
    # one type II surface, the hand-written determinant up to a constant on the circle
    from screwsym.algebra.rings import vanishes

    x, y, phi = symbols("x y phi", real=True)
    got = three_rpr(x, y, cos(phi), sin(phi), RPR_BASE, RPR_PLATFORM).singularities()
    ((cond, rank),) = got.actuation
    det = leg_lines_det(RPR_BASE, RPR_PLATFORM, x, y, cos(phi), sin(phi))
    f = cond.lhs - cond.rhs
    k = f.subs({x: 1, y: 2, phi: 0}) / det.subs({x: 1, y: 2, phi: 0})
    assert rank == 5 and vanishes(f - k * det)
    assert not vanishes(f - (k + 1) * det)  # the check rejects another multiple
    assert [r for _, r in got.limb] == [1, 1, 1] and got.constraint == []


# ------------------------------------------------------------------ algebraic numbers printed
def test_algebraic_numbers_print_with_a_variable_none_of_the_users():
    # issue 32, item 2: a CRootOf made in the user's own x printed "CRootOf(x**3 - x - 1, 0)",
    # a condition on x in appearance; the table prints it in _t (tau in LaTeX), also where
    # the user has a symbol called _t
    from sympy import CRootOf, Eq

    from screwsym.systems.singularities import Singularities

    x, t = symbols("x _t", real=True)
    r = CRootOf(x**3 - x - 1, 0)
    s = Singularities(limb=[], actuation=[(Eq(x, r), 5)], constraint=[])
    assert "CRootOf(_t**3 - _t - 1, 0)" in str(s) and "x**3" not in str(s)
    assert r"\tau^{3} - \tau - 1" in s._repr_latex_() and "x^{3}" not in s._repr_latex_()
    taken = Singularities(limb=[], actuation=[(Eq(t, r), 5)], constraint=[])
    assert "CRootOf(_t1**3 - _t1 - 1, 0)" in str(taken)
    # the checker rejects SymPy's own printing, which keeps x
    assert "CRootOf(x**3 - x - 1, 0)" in str(Eq(x, r))


@pytest.mark.slow
def test_strata_and_the_case_split_give_the_same_sets_on_a_three_rrr():
    # a planar 3-RRR, platform translated by (x, y) (Bonev, Zlatanov & Gosselin 2003): the
    # strata (one set per rank, fewest equations) and the old disjoint case split are two
    # algorithms for the same singular sets; they agree at every point of a grid, and the
    # type II set holds exactly where NumPy finds Jx singular there
    from sympy import Or, false

    import screwsym.systems.singularities as sing

    x, y = symbols("x y", real=True)
    pts = [(x + 1, y), (x, y + 1), (x - 1, y - 1)]
    mech = ParallelMechanism(*(
        Limb(R([a, b, 0], Z), R([a + 1, b + 2, 0], Z), R([p[0], p[1], 0], Z), actuated=0)
        for (a, b), p in zip([(3, -1), (-1, 3), (-2, -3)], pts, strict=True)))
    new = mech.singularities()
    assert len(new.actuation) == 1 and new.actuation[0][1] == 5
    saved = sing._drops
    sing._drops = sing._split_drops
    try:
        old = sing._singularities(mech)
    finally:
        sing._drops = saved

    def union(part):
        return Or(*(c for c, _ in part)) if part else false

    grid = [{x: a, y: b} for a in range(-4, 5) for b in range(-4, 5)]
    for part in ("limb", "actuation", "constraint"):
        a, b = union(getattr(new, part)), union(getattr(old, part))
        assert all(bool(a.subs(p)) == bool(b.subs(p)) for p in grid), part
    hits = 0
    limb_set = union(new.limb)
    for p in grid:
        if limb_set.subs(p):  # a leg degenerate there: Jx's wrench is a limit (a superset)
            continue
        Jx = np.array(mech.xreplace(p).jacobian()[0], dtype=float)
        singular = np.linalg.matrix_rank(Jx) < 6
        assert bool(new.actuation[0][0].subs(p)) == singular, p
        hits += singular
    assert hits >= 3  # the grid meets the set: an empty answer would fail
    # the checker rejects another set: a shifted condition disagrees somewhere on the grid
    cond = new.actuation[0][0]
    shifted = cond.subs(x, x + 1)
    assert any(bool(shifted.subs(p)) != bool(cond.subs(p)) for p in grid)
