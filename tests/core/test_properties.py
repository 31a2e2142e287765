"""Property tests on exact rationals (Hypothesis): invariants of the chapter."""

from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import ImmutableMatrix, Rational

from screwsym import Screw, axis, decompose_screw, foot, pitch, reciprocal_product, shift_origin

rationals = st.fractions(min_value=-20, max_value=20, max_denominator=50).map(Rational)
vectors = st.tuples(rationals, rationals, rationals).map(lambda v: ImmutableMatrix(v))
nonzero_vectors = vectors.filter(lambda v: any(c != 0 for c in v))
screws = st.builds(Screw, nonzero_vectors, vectors)
any_screws = st.builds(Screw, vectors, vectors)
nonzero = rationals.filter(lambda k: k != 0)

SETTINGS = settings(max_examples=60, deadline=None)


@SETTINGS
@given(screws, vectors)
def test_pitch_unchanged_by_shift_origin(s, A):
    assert pitch(shift_origin(s, A)) == pitch(s)


@SETTINGS
@given(any_screws, any_screws, vectors)
def test_reciprocal_product_unchanged_by_shift_origin(s1, s2, A):
    assert reciprocal_product(shift_origin(s1, A), shift_origin(s2, A)) == reciprocal_product(
        s1, s2
    )


@SETTINGS
@given(screws, vectors)
def test_shift_origin_moves_the_axis_by_minus_A(s, A):
    assert foot(shift_origin(s, A)) == foot(s) - A + (A.dot(s.S) / s.S.dot(s.S)) * s.S


@SETTINGS
@given(screws)
def test_axis_has_pitch_zero_and_lies_along_S(s):
    L = axis(s)
    assert pitch(L) == 0
    assert L.S == s.S
    assert L.contains(foot(s)) is True
    assert L.classify() == "line"


@SETTINGS
@given(screws)
def test_decompose_sums_back(s):
    line, couple = decompose_screw(s)
    assert line + couple == s
    assert couple.S == ImmutableMatrix([0, 0, 0])
    assert couple.S0 == pitch(s) * s.S


@SETTINGS
@given(screws, nonzero)
def test_scaling_leaves_pitch_and_axis(s, k):
    assert pitch(k * s) == pitch(s)
    assert foot(k * s) == foot(s)
    assert axis(k * s).contains(foot(s) + s.S) is True


@SETTINGS
@given(screws, screws)
def test_reciprocal_product_is_symmetric_and_self_product_is_twice_pitch(s1, s2):
    assert reciprocal_product(s1, s2) == reciprocal_product(s2, s1)
    assert reciprocal_product(s1, s1) == 2 * pitch(s1) * s1.S.dot(s1.S)
