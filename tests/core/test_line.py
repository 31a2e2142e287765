"""LineVector and the geometry of lines: Sections 1.2, 1.3, 1.4.1."""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import (
    ImmutableMatrix,
    Rational,
    cancel,
    cos,
    expand,
    pi,
    radsimp,
    sin,
    sqrt,
    symbols,
)

from screwsym import (
    LineVector,
    Screw,
    common_normal,
    contains,
    direction_cosines,
    distance_to_origin,
    foot,
    is_coplanar,
    mutual_moment,
    vector,
)

x = symbols("x", real=True)


def exactly_zero(e):
    """Exact test for small algebraic numbers and polynomials (no tolerance)."""
    e = radsimp(expand(e))
    return e == 0 or e.equals(0) is True


def norm(v):
    return sqrt(v.dot(v))


# --------------------------------------------------------------- constructors
def test_through_is_1_1_and_1_9():
    A, B = vector("A"), vector("B")
    L = LineVector.through(A, B)
    assert L.S == B - A
    assert all(expand(e) == 0 for e in L.S0 - A.cross(B - A))
    assert L.contains(A) is None or all(expand(e) == 0 for e in A.cross(L.S) - L.S0)


def test_from_point_is_1_9():
    r, S = vector("r"), vector("S")
    L = LineVector.from_axis(r, S)
    assert L.S == S and L.S0 == r.cross(S)


def test_line_vector_constraints():
    with pytest.raises(
        ValueError, match=r"S, S0: a line vector needs S.S0 = 0 \(1.10\), got S.S0 = 1"
    ):
        LineVector([1, 0, 0], [1, 0, 0])
    with pytest.raises(
        ValueError, match=r"S: a line vector needs a non-zero direction S, got \[0, 0, 0\]"
    ):
        LineVector([0, 0, 0], [1, 0, 0])
    with pytest.raises(ValueError, match="A, B: expected two distinct points, got A = B = "):
        LineVector.through([1, 2, 3], [1, 2, 3])
    # undecidable symbolic cases are accepted
    assert LineVector([1, 0, 0], [x, 1, 0]).S0[0] == x
    assert LineVector([x, 0, 0], [0, 1, 0]).S[0] == x


def test_line_vector_made_invalid_by_subs_raises():
    L = LineVector([1, 0, 0], [x, 1, 0])
    with pytest.raises(ValueError, match="a line vector needs S.S0 = 0"):
        L.subs(x, 1)


def test_float_lines_allow_rounding():
    A, B = (0.1, 0.2, 0.3), (0.4, 0.5, 0.7)
    L = LineVector.through(A, B)
    assert isinstance(L, LineVector)
    with pytest.raises(ValueError, match="S.S0 = 0"):
        LineVector([1.0, 0, 0], [0.5, 0, 0])


def test_twist_and_screw_are_read_as_lines_when_they_are():
    s = Screw([0, 0, 1], [1, 0, 0])
    assert mutual_moment(s, LineVector([1, 0, 0], [0, 0, 0])) == 1  # skew, 1 apart
    with pytest.raises(ValueError, match="a line vector needs S.S0 = 0"):
        mutual_moment(Screw([1, 0, 0], [1, 0, 0]), s)


# --------------------------------------------------------- point quantities
def test_direction_cosines_1_5():
    L = LineVector.through([0, 0, 0], [1, 2, 2])
    assert direction_cosines(L) == ImmutableMatrix([Rational(1, 3), Rational(2, 3), Rational(2, 3)])
    assert L.direction_cosines.dot(L.direction_cosines) == 1  # (1.6)


def test_foot_and_distance_1_16_to_1_18():
    L = LineVector.through([3, 4, 7], [3, 4, 9])
    assert foot(L) == ImmutableMatrix([3, 4, 0])
    assert L.foot.dot(L.S) == 0
    assert distance_to_origin(L) == 5
    assert L.distance_to_origin == norm(L.S0) / norm(L.S)


def test_foot_of_line_through_origin_is_origin():
    assert foot(LineVector([1, 2, 3], [0, 0, 0])) == ImmutableMatrix([0, 0, 0])


def test_contains_1_8():
    r, S, t = vector("r"), vector("S"), symbols("t", real=True)
    L = LineVector.from_axis(r, S)
    assert contains(L, r + t * S) is True
    assert contains(LineVector.through([0, 0, 0], [1, 1, 1]), [1, 0, 0]) is False
    assert contains(L, r + S.cross(vector("w"))) is None  # w may be parallel to S
    with pytest.raises(ValueError, match=r"s: a couple \(0; C\) has no axis"):
        contains(Screw.couple([1, 0, 0]), [0, 0, 0])


def test_contains_screw_axis_1_36():
    s = Screw.from_axis([0, 1, 0], [1, 0, 0], 3)
    assert contains(s, [7, 1, 0]) is True and contains(s, [0, 0, 0]) is False


# ----------------------------------------------------------- mutual moment
def test_mutual_moment_is_1_23():
    S1, S01, S2, S02 = vector("A"), vector("A0"), vector("B"), vector("B0")
    M = mutual_moment(Screw(S1, S01), Screw(S2, S02))
    assert expand(M - (S1.dot(S02) + S2.dot(S01))) == 0


def test_mutual_moment_is_the_triple_product_1_22():
    r1, r2, S1, S2 = vector("p"), vector("q"), vector("u"), vector("v")
    M = LineVector.from_axis(r1, S1).mutual_moment(LineVector.from_axis(r2, S2))
    assert expand(M - (r2 - r1).dot(S2.cross(S1))) == 0


def test_is_coplanar_1_27():
    c, A, B = vector("c"), vector("A"), vector("B")
    assert is_coplanar(LineVector.from_axis(c, A), LineVector.from_axis(c, B)) is True
    x_axis = LineVector([1, 0, 0], [0, 0, 0])
    assert x_axis.is_coplanar(LineVector.from_axis([0, 0, 5], [1, 0, 0])) is True
    assert x_axis.is_coplanar(LineVector.from_axis([0, 0, 5], [0, 1, 0])) is False


# ----------------------------------------------------------- common normal
def check_common_normal_convention(L1, L2):
    cn = common_normal(L1, L2)
    S1, S2 = L1.S, L2.S
    n1, n2 = norm(S1), norm(S2)
    assert cn.a12.is_nonnegative
    assert exactly_zero(cn.normal.dot(cn.normal) - 1)
    assert L1.contains(cn.foot1) is True and L2.contains(cn.foot2) is True
    assert all(exactly_zero(e) for e in cn.foot2 - cn.foot1 - cn.a12 * cn.normal)
    assert exactly_zero(cn.normal.dot(S1)) and exactly_zero(cn.normal.dot(S2))
    # (1.24) with the convention: S1 x S2 = |S1||S2| sin(alpha12) a12_hat
    assert all(exactly_zero(e) for e in S1.cross(S2) - n1 * n2 * sin(cn.alpha12) * cn.normal)
    assert exactly_zero(S1.dot(S2) - n1 * n2 * cos(cn.alpha12))
    # (1.25), general magnitudes: M = -|S1||S2| a12 sin(alpha12)
    assert exactly_zero(mutual_moment(L1, L2) + n1 * n2 * cn.a12 * sin(cn.alpha12))
    return cn


def test_common_normal_skew_lines_both_orders():
    L1 = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    L2 = LineVector.from_axis([0, 0, 2], [0, 1, 0])
    cn12 = check_common_normal_convention(L1, L2)
    assert (cn12.a12, cn12.alpha12) == (2, pi / 2)
    assert cn12.normal == ImmutableMatrix([0, 0, 1])
    assert mutual_moment(L1, L2) == -2
    cn21 = check_common_normal_convention(L2, L1)
    assert cn21.normal == ImmutableMatrix([0, 0, -1]) and cn21.alpha12 == pi / 2
    assert (cn21.foot1, cn21.foot2) == (cn12.foot2, cn12.foot1)


def test_common_normal_canonical_pair_of_the_transcription():
    a12, alpha = symbols("a12 alpha12", positive=True)
    L1 = LineVector([1, 0, 0], [0, 0, 0])
    L2 = LineVector.from_axis([0, 0, a12], [cos(alpha), sin(alpha), 0])
    cn = common_normal(L1, L2)
    assert mutual_moment(L1, L2) + a12 * sin(alpha) == 0
    assert cn.foot1 == ImmutableMatrix([0, 0, 0])
    assert all(cancel(e) == 0 for e in cn.foot2 - ImmutableMatrix([0, 0, a12]))


def test_common_normal_intersecting_lines():
    L1 = LineVector.from_axis([1, 1, 1], [1, 0, 0])
    L2 = LineVector.from_axis([1, 1, 1], [1, 1, 0])
    cn = check_common_normal_convention(L1, L2)
    assert cn.a12 == 0 and cn.alpha12 == pi / 4
    assert cn.foot1 == cn.foot2 == ImmutableMatrix([1, 1, 1])
    assert cn.normal == ImmutableMatrix([0, 0, 1])


@pytest.mark.parametrize("sense, alpha", [(1, 0), (-1, pi)])
def test_common_normal_parallel_and_antiparallel(sense, alpha):
    L1 = LineVector.from_axis([0, 0, 0], [0, 0, 1])
    L2 = LineVector.from_axis([3, 4, 9], [0, 0, sense * 2])
    cn = check_common_normal_convention(L1, L2)
    assert cn.a12 == 5 and cn.alpha12 == alpha
    assert cn.normal == ImmutableMatrix([Rational(3, 5), Rational(4, 5), 0])


def test_common_normal_of_coincident_lines_raises():
    L = LineVector.through([0, 0, 0], [1, 1, 1])
    with pytest.raises(ValueError, match="l1, l2: coincident lines have no common normal"):
        common_normal(L, 2 * L)


rationals = st.fractions(min_value=-5, max_value=5, max_denominator=7).map(Rational)
vectors = st.tuples(rationals, rationals, rationals)


@settings(max_examples=25, deadline=None)
@given(vectors, vectors, vectors, vectors)
def test_common_normal_convention_on_random_lines(p1, u1, p2, u2):
    if all(c == 0 for c in u1) or all(c == 0 for c in u2):
        return
    L1, L2 = LineVector.from_axis(p1, u1), LineVector.from_axis(p2, u2)
    if L1.S.cross(L2.S) == ImmutableMatrix([0, 0, 0]) and L1.contains(foot(L2)):
        return  # coincident
    check_common_normal_convention(L1, L2)


# ---------------------------------------------------------- closed forms (issue 12)
def test_common_normal_piecewise_holds_at_the_intersecting_case():
    z = symbols("z", real=True)
    L1 = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    Lz = LineVector.from_axis([0, 0, z], [0, 1, 0])
    generic = common_normal(L1, Lz).subs(z, 0)  # the generic form holds only where z != 0
    assert list(generic.normal) == [0, 0, 0]
    cn = common_normal(L1, Lz, conds="piecewise").subs(z, 0)
    assert cn == common_normal(L1, LineVector.from_axis([0, 0, 0], [0, 1, 0]))
    assert list(cn.normal) == [0, 0, 1] and cn.alpha12 == pi / 2


def test_distance_to_origin_is_the_axis_moment_over_the_direction():
    r, S = vector("r"), vector("S")
    L = LineVector.from_axis(r, S)
    d = distance_to_origin(L)
    assert d == sqrt(L.S0.dot(L.S0)) / sqrt(S.dot(S))  # (1.18) |S0| / |S|
    assert cancel(expand(d**2 - distance_to_origin(L, tidy=False) ** 2)) == 0
    assert mutual_moment(L, L) == 0
