"""Screw systems: generic rank, polynomial reciprocal bases, and the exhaustive case split."""

from __future__ import annotations

import pickle
import random

import pytest
from sympy import Eq, Matrix, Ne, Rational, Symbol, cos, expand, sqrt, symbols, tan, true

from screwsym import Screw, ScrewSystem, Twist, Wrench, reciprocal_product, vector
from screwsym.systems._rank_cases import rank_cases

Z = [0, 0, 1]


def ball(p):
    return ScrewSystem(*(Twist.rotation(e, point=p) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])))


def assert_reciprocal(system, other):
    """Every member of ``other`` is reciprocal to every member of ``system``, identically."""
    for s in system:
        for w in other:
            product = expand(reciprocal_product(s, w))
            if product != 0:
                raise AssertionError(f"{s} and {w} are not reciprocal: {product}")


def test_assert_reciprocal_rejects_a_wrong_basis():
    T = ball(vector("p"))
    with pytest.raises(AssertionError, match="not reciprocal"):
        assert_reciprocal(T, ScrewSystem(Wrench.force([1, 0, 0], point=[0, 0, 0])))


# ------------------------------------------------------------------ generic


def test_ball_joint_reciprocal_is_polynomial_and_valid_at_pz_zero():
    # the motivating case of issue 11: a hand-made null space gives p_x/p_z
    p = vector("p")
    T = ball(p)
    W = T.reciprocal()
    assert W.kind is Wrench and W.rank == 3
    assert all(e.is_polynomial(*p) for e in W.matrix)
    assert_reciprocal(T, W)
    # the three forces through p
    assert W == ScrewSystem(*(Wrench.force(e, point=p) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])))
    at = {p[0]: 1, p[1]: 2, p[2]: 0}
    assert Matrix(W.matrix.xreplace(at)).rank() == 3
    assert T.rank_conditions() == [(true, 3)]


def test_five_joint_limb_reciprocal_with_symbolic_placement():
    pts = [vector(f"p{i}") for i in range(5)]
    dirs = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]
    T = ScrewSystem(*(Twist.rotation(d, point=p) for d, p in zip(dirs, pts, strict=True)))
    W = T.reciprocal()
    assert T.rank == 5 and W.rank == 1
    assert all(e.is_polynomial() for e in W.matrix)
    assert_reciprocal(T, W)


def test_rank_basis_contains():
    s = ScrewSystem([1, 0, 0, 0, 0, 0], [2, 0, 0, 0, 0, 0], [0, 0, 0, 1, 0, 0])
    assert s.rank == 2
    assert s.basis() == ScrewSystem([1, 0, 0, 0, 0, 0], [0, 0, 0, 1, 0, 0])
    assert s.contains([3, 0, 0, 5, 0, 0]) is True
    assert s.contains([0, 1, 0, 0, 0, 0]) is False
    assert ScrewSystem().contains([0, 0, 0, 0, 0, 0]) is True
    assert ScrewSystem().contains([1, 0, 0, 0, 0, 0]) is False


def test_union_and_intersection():
    a = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]), Twist.translation([1, 0, 0]))
    b = ScrewSystem(Twist.translation([1, 0, 0]), Twist.translation([0, 1, 0]))
    assert (a | b).rank == 3 and len(a | b) == 4
    both = a & b
    assert both.kind is Twist and both.rank == 1
    assert both.contains(Twist.translation([1, 0, 0]))
    assert not both.contains(Twist.translation([0, 1, 0]))


def test_empty_system():
    e = ScrewSystem()
    assert e.rank == 0 and e.matrix.shape == (6, 0) and e.kind.__name__ == "Screw"
    assert e.reciprocal().rank == 6
    assert e.rank_conditions() == [(true, 0)]


def test_algebraic_coefficients():
    # three forces in the plane z = 0, tangent to a circle at 120 degrees: not concurrent
    e = [[1, 0, 0], [-Rational(1, 2), sqrt(3) / 2, 0], [-Rational(1, 2), -sqrt(3) / 2, 0]]
    W = ScrewSystem(*(Wrench.force([-v[1], v[0], 0], point=v) for v in e))
    assert W.rank == 3
    assert_reciprocal(W, W.reciprocal())
    # the same three lines moved to pass through the centre are concurrent: rank 2
    W0 = ScrewSystem(*(Wrench.force([-v[1], v[0], 0], point=[0, 0, 0]) for v in e))
    assert W0.rank == 2


def test_assumptions_drop_impossible_cases():
    a = symbols("a", real=True)
    ap = symbols("a", positive=True)
    for sym, expected in ((a, 2), (ap, 1)):
        RR = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]), Twist.rotation(Z, point=[sym, 0, 0]))
        assert len(RR.rank_conditions()) == expected


# -------------------------------------------------------- exhaustive cases


def _sample(system, cases, rng, tries=20):
    """Points (dicts symbol -> Rational): random ones, and one on each case's substitution."""
    syms = sorted(system.matrix.free_symbols, key=str)

    def value(s):
        v = Rational(rng.randint(-9, 9), rng.randint(1, 4))
        return abs(v) + 1 if s.is_positive else v

    points = [{s: value(s) for s in syms} for _ in range(3)]
    for cond, subs in cases:
        for _ in range(tries):
            free = {s: value(s) for s in syms if s not in subs}
            try:
                point = {**free, **{k: v.xreplace(free) for k, v in subs.items()}}
            except ZeroDivisionError:  # pragma: no cover - a denominator hit zero
                continue
            if any(v.has(Symbol) or not v.is_finite for v in point.values()):
                continue
            if cond.xreplace(point) is true:
                points.append(point)
                break
        else:  # pragma: no cover - a case without a sample point fails the test
            raise AssertionError(f"no sample point found for the case {cond}")
    return points


def assert_exhaustive(system, special=(), seed=0):
    """At sample points: some condition holds, and every one that holds gives the true rank.

    The points: random ones, one on each case, and the ``special`` values known
    from the geometry (completed with random values for the other symbols).
    """
    rng = random.Random(seed)
    ranks = system.rank_conditions()
    cases = system.substitutions()
    recips = system.reciprocal_cases()
    assert [c for c, _ in ranks] == [c for c, _ in cases] == [c for c, _ in recips]
    points = _sample(system, cases, rng)
    for known in special:
        for _ in range(3):
            base = _sample(system, [], rng)[0]
            points.append({**base, **known})
    for point in points:
        M = Matrix(system.matrix.xreplace(point))
        actual = M.rank()
        holding = [(r, w) for (c, r), (_, w) in zip(ranks, recips, strict=True)
                   if c.xreplace(point) is true]
        assert holding, f"no condition holds at {point}"
        for r, w in holding:
            if r is None:
                continue
            assert r == actual, (point, r, actual)
            # the case's reciprocal basis: reciprocal, and of full dimension, at the point
            Wp = Matrix(w.matrix.xreplace(point))
            assert Wp.rank() == 6 - actual
            swapped = Matrix.vstack(M[3:, :], M[:3, :])
            assert (swapped.T * Wp).is_zero_matrix


def test_exhaustive_two_parallel_axes():
    a = symbols("a", real=True)
    RR = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]), Twist.rotation(Z, point=[a, 0, 0]))
    assert RR.rank_conditions() == [(Ne(a, 0), 2), (Eq(a, 0), 1)]
    assert_exhaustive(RR, special=[{a: 0}])


def test_exhaustive_two_axes_that_become_parallel():
    # the second axis turns with t: parallel to the first at t = 0, and coincident if also b = 0
    t, b = symbols("t b", real=True)
    RR = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]), Twist.rotation([t, 0, 1], point=[0, b, 0]))
    assert [r for _, r in RR.rank_conditions()] == [2, 2, 1]
    assert RR.rank_conditions()[-1][0].free_symbols == {t, b}
    assert_exhaustive(RR, special=[{t: 0}, {t: 0, b: 0}])


def test_exhaustive_point_reaching_a_plane():
    # three forces along z through the points (0,0), (1,0) and (x, y): rank 2 when the
    # third point reaches the line y = 0 of the other two (their plane with the z axis)
    x, y = symbols("x y", real=True)
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]), Wrench.force(Z, point=[1, 0, 0]),
                    Wrench.force(Z, point=[x, y, 0]))
    conds = W.rank_conditions()
    assert conds[0] == (conds[0][0], 3) and conds[0][0].free_symbols == {y}
    assert any(r == 2 and c.free_symbols == {y} for c, r in conds[1:])
    assert_exhaustive(W, special=[{y: 0}, {y: 0, x: 0}, {y: 0, x: 1}])


def test_exhaustive_five_joint_limb_with_one_symbolic_joint():
    p = vector("p")
    T = ScrewSystem(
        Twist.rotation([1, 0, 0], point=[0, 0, 0]),
        Twist.rotation([0, 1, 0], point=[0, 0, 1]),
        Twist.translation([0, 0, 1]),
        Twist.rotation([1, 1, 0], point=[1, 0, 0]),
        Twist.rotation([0, 1, 1], point=p),
    )
    assert T.rank == 5
    assert_exhaustive(T, seed=1)


def test_a_factor_in_one_symbol_is_decided_at_its_roots():
    t = symbols("t", real=True)
    # parallel force lines through (0,0,0) and (t**2 - 2, 0, 0) coincide where t**2 = 2
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]), Wrench.force(Z, point=[t**2 - 2, 0, 0]))
    assert W.rank_conditions() == [(Ne(t**2 - 2, 0), 2), (Eq(t, -sqrt(2)), 1), (Eq(t, sqrt(2)), 1)]
    assert_exhaustive(W, special=[{t: sqrt(2)}, {t: -sqrt(2)}])


def test_nonlinear_factor_is_decided_on_its_circle():
    t, u = symbols("t u", real=True)
    # the second line through (t**2 + u**2 - 2, 0, 0): a circle of (t, u), solved for
    # neither; the rank is proved modulo it, and the reciprocal basis holds on it
    W = ScrewSystem(Wrench.force(Z, point=[0, 0, 0]),
                    Wrench.force(Z, point=[t**2 + u**2 - 2, 0, 0]))
    conds = W.rank_conditions()
    assert conds == [(Ne(t**2 + u**2 - 2, 0), 2), (Eq(t**2 + u**2 - 2, 0), 1)]
    basis = W.reciprocal_cases()[1][1]
    assert basis.rank == 5
    for point in ({t: 1, u: 1}, {t: sqrt(2), u: 0}, {t: Rational(7, 5), u: Rational(1, 5)}):
        here = W.xreplace(point)
        assert here.matrix.rank() == 1
        recip = basis.xreplace(point)
        assert recip.matrix.rank() == 5
        assert all(expand(reciprocal_product(s, w)) == 0 for s in here for w in recip)
    # the check rejects the generic basis there: one reciprocal screw short
    generic = W.reciprocal_cases()[0][1].xreplace({t: 1, u: 1})
    assert generic.rank == 4


def test_too_many_cases_raise():
    pts = [vector(f"p{i}") for i in range(3)]
    T = ScrewSystem(*(Twist.rotation(Z, point=p) for p in pts))
    with pytest.raises(ValueError, match="more than 1 cases"):
        T.rank_conditions(max_cases=1)
    rank_cases.cache_clear()


# ---------------------------------------------------------------- objects


def test_basic_protocol():
    p = vector("p")
    T = ball(p)
    assert T.func(*T.args) == T
    assert pickle.loads(pickle.dumps(T)) == T
    assert T.subs(p[2], 0).matrix == T.matrix.subs(p[2], 0)
    with pytest.raises(TypeError, match="strings are never evaluated"):
        T.subs(p[2], "0")
    assert T.free_symbols == set(p)


def test_bad_input():
    with pytest.raises(TypeError, match="expected screws of one kind, got Twist and Wrench"):
        ScrewSystem(Twist([1, 0, 0], [0, 0, 0]), Wrench([1, 0, 0], [0, 0, 0]))
    with pytest.raises(ValueError, match=r"screws\[0\]: expected a 6-vector"):
        ScrewSystem([1, 0, 0])
    with pytest.raises(TypeError, match="other: expected a ScrewSystem, got list"):
        ScrewSystem([1, 0, 0, 0, 0, 0]).union([1, 0, 0, 0, 0, 0])
    th = symbols("theta", real=True)
    with pytest.raises(ValueError, match=r"polynomial in sin and cos of symbols.*got tan\(theta\)"):
        _ = ScrewSystem(Twist.rotation([tan(th), 0, 1], point=[0, 0, 0])).rank
    with pytest.raises(ValueError, match=r"polynomial in sin and cos.*got cos\(theta\*\*2\)"):
        _ = ScrewSystem(Twist.rotation([cos(th**2), 0, 1], point=[0, 0, 0])).rank
    with pytest.raises(ValueError, match="max_cases: expected a positive integer, got 0"):
        ScrewSystem().rank_conditions(max_cases=0)
    with pytest.raises(TypeError, match="max_cases: expected a positive integer, got float"):
        ScrewSystem().rank_conditions(max_cases=2.0)


def test_rational_entries_are_cleared_per_column():
    a = symbols("a", positive=True)
    W = ScrewSystem(Wrench([1 / a, 0, 0], [0, 0, 0]), Wrench([0, 1, 0], [0, 0, 0]))
    assert W.rank == 2
    assert_reciprocal(W, W.reciprocal())


class _Tampered:
    """A system whose case list lies: the checker must notice."""

    def __init__(self, system, ranks=None, drop_last=False):
        self.system, self.ranks, self.drop_last = system, ranks, drop_last
        self.matrix = system.matrix

    def _cut(self, items):
        return items[:-1] if self.drop_last else items

    def rank_conditions(self):
        got = self.system.rank_conditions()
        if self.ranks is not None:
            got = [(c, r) for (c, _), r in zip(got, self.ranks, strict=True)]
        return self._cut(got)

    def substitutions(self):
        return self._cut(self.system.substitutions())

    def reciprocal_cases(self):
        return self._cut(self.system.reciprocal_cases())


def test_assert_exhaustive_rejects_wrong_ranks_and_missing_cases():
    a = symbols("a", real=True)
    RR = ScrewSystem(Twist.rotation(Z, point=[0, 0, 0]), Twist.rotation(Z, point=[a, 0, 0]))
    with pytest.raises(AssertionError):
        assert_exhaustive(_Tampered(RR, ranks=[2, 2]))
    with pytest.raises(AssertionError, match="no condition holds"):
        assert_exhaustive(_Tampered(RR, drop_last=True), special=[{a: 0}])


def test_kinds():
    from screwsym import LineVector, Screw

    mixed = ScrewSystem(LineVector([1, 0, 0], [0, 0, 0]), Screw([0, 1, 0], [0, 1, 0]))
    assert mixed.kind is Screw and mixed.reciprocal().kind is Screw
    assert ScrewSystem([1, 0, 0, 0, 0, 0]).kind is Screw
    assert ScrewSystem(Twist.translation([1, 0, 0]), [0, 1, 0, 0, 0, 0]).kind is Twist
    assert ScrewSystem(Twist.translation([1, 0, 0])).reciprocal().kind is Wrench


def test_floats_are_refused():
    message = r"screws\[1\]: expected exact entries .* got the float 0.5"
    with pytest.raises(ValueError, match=message):
        ScrewSystem(Twist.translation([1, 0, 0]), Twist.translation([0.5, 0, 0]))


# ------------------------------------------------------------- properties

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

_Q = st.fractions(min_value=-5, max_value=5, max_denominator=4).map(Rational)
_SCREW = st.lists(_Q, min_size=6, max_size=6)


@settings(max_examples=25, deadline=None)
@given(st.lists(_SCREW, min_size=1, max_size=6), st.integers(0, 5))
def test_property_rank_and_reciprocal_of_rational_systems(columns, repeat):
    # a dependent member (a combination of the others) is added half the time
    if repeat % 2 and len(columns) > 1:
        columns = columns + [[a + 2 * b for a, b in zip(columns[0], columns[1], strict=True)]]
    system = ScrewSystem(*columns)
    M = Matrix(system.matrix)
    assert system.rank == M.rank()
    W = system.reciprocal()
    assert W.rank == 6 - system.rank
    assert_reciprocal(system, W)
    assert system.basis().rank == system.rank == len(system.basis())


def test_factors_without_real_zeros_split_nothing():
    # parallel forces through (0, 0) and (x**2 + 2x + 2, 0): the distance (x+1)**2 + 1 never
    # vanishes for real x, so there is one case; with (x + 1)**2 it vanishes at x = -1
    x = symbols("x", real=True)
    origin = Wrench.force(Z, point=[0, 0, 0])
    far = ScrewSystem(origin, Wrench.force(Z, point=[x**2 + 2 * x + 2, 0, 0]))
    assert far.rank_conditions() == [(true, 2)]
    near = ScrewSystem(origin, Wrench.force(Z, point=[x**2 + 2 * x + 1, 0, 0]))
    assert near.rank_conditions() == [(Ne(x + 1, 0), 2), (Eq(x + 1, 0), 1)]
    assert_exhaustive(near, special=[{x: -1}])


def test_latex_is_the_span():
    from sympy import latex

    s = ScrewSystem(Twist.translation([1, 0, 0]), Twist.rotation(Z, point=[0, 0, 0]))
    text = latex(s)
    assert text.startswith(r"\operatorname{span}\left\{") and text.count(r"\;") >= 3
    assert latex(ScrewSystem()) == r"\left\{0\right\}"


def test_an_empty_system_keeps_its_kind():
    # the reciprocal of a full twist system is the empty wrench system, and back
    full = ScrewSystem(*(Twist.from_matrix([int(i == k) for i in range(6)]) for k in range(6)))
    empty = full.reciprocal()
    assert empty.kind is Wrench and len(empty) == 0 and empty.rank == 0
    assert empty.func(*empty.args) == empty and str(empty) == "ScrewSystem(kind=Wrench)"
    assert empty.reciprocal().kind is Twist and empty.reciprocal().rank == 6
    assert (full & full).kind is Twist
    assert (empty | ScrewSystem(Wrench([1, 0, 0], [0, 0, 0]))).kind is Wrench
    assert ScrewSystem().kind is Screw
    with pytest.raises(TypeError, match=r"screws: expected members of kind Twist, got Wrench"):
        ScrewSystem(Wrench([1, 0, 0], [0, 0, 0]), kind=Twist)


def _five_random_screws(tag: str):
    """Five screws linear in three fresh symbols (fresh: the case split's caches miss)."""
    import random as _random

    from screwsym import Screw

    x, y, z = symbols(f"x_{tag} y_{tag} z_{tag}", real=True)
    rnd = _random.Random(1)

    def r():
        return sum(rnd.randint(-3, 3) * v for v in (x, y, z, 1))

    return ScrewSystem(*(Screw([r() for _ in range(3)], [r() for _ in range(3)])
                         for _ in range(5)))


def test_the_case_split_takes_a_work_budget_and_names_it():
    # issue 20: rank_conditions() of five or six random screws in three symbols ran for
    # minutes with no limit; a budget (units of polynomial arithmetic) ends it with an error
    from screwsym.algebra.budget import BUDGET

    assert BUDGET == 20_000_000
    with pytest.raises(ValueError, match=r"rank_conditions: the case split needs more work "
                                         r"than budget=100000 units .* pass a larger budget"):
        _five_random_screws("a").rank_conditions(budget=100_000)
    with pytest.raises(ValueError, match=r"reciprocal_cases: .* budget=1000 units"):
        _five_random_screws("b").reciprocal_cases(budget=1000)
    with pytest.raises(ValueError, match="budget: expected a positive integer, got 0"):
        _five_random_screws("c").rank_conditions(budget=0)
    a = symbols("a_budget", real=True)
    RR = ScrewSystem(Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                     Twist.rotation([0, 0, 1], point=[a, 0, 0]))
    assert RR.rank_conditions(budget=10_000) == [(Ne(a, 0), 2), (Eq(a, 0), 1)]


def test_mobility_cases_takes_one_budget_for_the_whole_split():
    from _mechanisms import four_bar

    b = symbols("b_budget", real=True)
    mech = four_bar(B=(1, b, 0), Cp=(3, 0, 0))
    with pytest.raises(ValueError, match=r"mobility_cases: the case split needs more work than "
                                         r"budget=10 units"):
        mech.mobility_cases(budget=10)
    assert [m.mobility for _, m in mech.mobility_cases()] == [1, 2]
