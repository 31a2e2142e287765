"""Screw: representation, SymPy integration, and the operations of Sections 1.4.2 and 1.5."""

import pickle

import pytest
from sympy import (
    Basic,
    Float,
    ImmutableMatrix,
    Matrix,
    Rational,
    cancel,
    cos,
    diff,
    expand,
    oo,
    simplify,
    sin,
    srepr,
    symbols,
    zeros,
)

from screwsym import (
    LineVector,
    Screw,
    Twist,
    Wrench,
    axis,
    classify,
    decompose_screw,
    foot,
    is_reciprocal,
    pitch,
    reciprocal_product,
    shift_origin,
    vector,
)

x, y, t = symbols("x y t", real=True)


def is_zero_matrix(M):
    return all(cancel(expand(e)) == 0 for e in M)


# ------------------------------------------------------------ representation
def test_screw_is_basic_with_two_immutable_parts():
    s = Screw([1, 2, 3], [4, 5, 6])
    assert isinstance(s, Basic)
    assert s.args == (ImmutableMatrix([1, 2, 3]), ImmutableMatrix([4, 5, 6]))
    assert s.S == ImmutableMatrix([1, 2, 3]) and s.S0 == ImmutableMatrix([4, 5, 6])
    assert s.S.shape == (3, 1) and isinstance(s.S, ImmutableMatrix)


@pytest.mark.parametrize("cls", [Screw, LineVector, Twist, Wrench])
def test_every_annotated_class_attribute_has_a_value(cls):
    # an annotation without a value tells mypy of an attribute that raises AttributeError
    for klass in (k for k in cls.__mro__ if k.__module__.startswith("screwsym.")):
        for name in vars(klass).get("__annotations__", {}):
            assert hasattr(cls, name), f"{klass.__name__}.{name} is annotated but never set"


def test_as_matrix_and_from_matrix_round_trip():
    s = Screw([1, 2, 3], [4, 5, 6])
    M = s.matrix
    assert M == ImmutableMatrix([1, 2, 3, 4, 5, 6])
    assert Screw.from_matrix(M) == s
    assert Screw.from_matrix(M.T) == s
    assert Screw.from_matrix((1, 2, 3, 4, 5, 6)) == s
    assert type(Twist.from_matrix(M)) is Twist


def test_func_args_round_trip_for_every_class(generic):
    for s in (
        Screw(generic["S"], generic["S0"]),
        LineVector.from_axis(generic["r"], generic["S"]),
        Twist(generic["S"], generic["S0"]),
        Wrench(generic["S"], generic["S0"]),
    ):
        assert s.func(*s.args) == s
        assert type(s.func(*s.args)) is type(s)


def test_subs_xreplace_free_symbols(generic):
    s = Screw([x, 1, 0], [0, y, 0])
    assert s.free_symbols == {x, y}
    assert s.subs(x, 2) == Screw([2, 1, 0], [0, y, 0])
    assert s.xreplace({y: 3}) == Screw([x, 1, 0], [0, 3, 0])
    assert type(Twist([x, 0, 0], [0, 0, 0]).subs(x, 1)) is Twist


def test_hash_and_equality_are_structural():
    a, b = Screw([x, 1, 0], [0, y, 0]), Screw([x, 1, 0], [0, y, 0])
    assert a == b and hash(a) == hash(b)
    assert len({a, b}) == 1
    # same parts, different meaning: not equal
    assert Twist([1, 0, 0], [0, 0, 0]) != Wrench([1, 0, 0], [0, 0, 0])


def test_pickle_and_srepr(generic):
    for s in (Screw(generic["S"], generic["S0"]), LineVector.through([0, 0, 0], [x, 1, 0])):
        assert pickle.loads(pickle.dumps(s)) == s
    assert srepr(Screw([1, 0, 0], [0, 0, 0])).startswith("Screw(ImmutableDenseMatrix(")


def test_simplify_acts_on_components():
    s = Screw([sin(x) ** 2 + cos(x) ** 2, 0, 0], [0, 0, 0])
    assert simplify(s) == Screw([1, 0, 0], [0, 0, 0])
    assert type(simplify(Twist([sin(x) ** 2 + cos(x) ** 2, 0, 0], [0, 0, 0]))) is Twist


def test_diff_differentiates_both_parts():
    s = Screw([t, 0, 0], [0, t**2, 0])
    assert s.diff(t) == Screw([1, 0, 0], [0, 2 * t, 0])
    assert diff(s, t) == s.diff(t)
    # the derivative of a moving line is not a line vector in general
    L = LineVector.from_axis([0, t, 0], [1, 0, t])
    assert type(L.diff(t)) is Screw
    assert type(Twist([t, 0, 0], [0, 0, 0]).diff(t)) is Twist


def test_evalf_gives_floats():
    s = Screw([Rational(1, 3), 0, 0], [0, 0, 0]).evalf(5)
    assert isinstance(s.S[0], Float) and abs(float(s.S[0]) - 1 / 3) < 1e-4
    assert type(LineVector([1, 0, 0], [0, 1, 0]).evalf()) is LineVector
    assert Screw([Rational(1, 3), 0, 0], [0, 0, 0]).n(3) == Screw([1, 0, 0], [0, 0, 0]).n(3) / 3


def test_expand_and_applyfunc():
    s = Screw([x * (x + 1), 0, 0], [0, 0, 0])
    assert s.expand() == Screw([x**2 + x, 0, 0], [0, 0, 0])
    assert s.applyfunc(lambda e: e.subs(x, 1)) == Screw([2, 0, 0], [0, 0, 0])


# ---------------------------------------------------------------- operations
def test_pitch_formula_is_1_34(generic):
    S, S0 = generic["S"], generic["S0"]
    assert cancel(pitch(Screw(S, S0)) - S.dot(S0) / S.dot(S)) == 0
    assert Screw(S, S0).pitch == pitch(Screw(S, S0))


def test_pitch_of_the_book_examples():
    assert pitch(Screw([1, 0, 0], [1, 0, 0])) == 1  # Example 1.2
    assert pitch(Screw([1, 1, 0], [1, 0, 0])) == Rational(1, 2)  # Example 1.4
    assert pitch(Screw.couple([0, 0, 3])) == oo
    assert pitch(LineVector.through([1, 2, 3], [4, 5, 7])) == 0


def test_pitch_of_the_zero_screw_raises():
    with pytest.raises(ValueError, match=r"s: the zero screw \(0; 0\) has no pitch"):
        pitch(Screw([0, 0, 0], [0, 0, 0]))


def test_from_axis_is_1_38(generic):
    r, S, h = generic["r"], generic["S"], generic["h"]
    s = Screw.from_axis(r, S, h)
    assert s.S == S
    assert is_zero_matrix(s.S0 - (r.cross(S) + h * S))
    assert cancel(s.pitch - h) == 0
    assert s.axis.contains(r) is True


def test_from_axis_refuses_infinite_pitch():
    with pytest.raises(ValueError, match="h: expected a finite pitch; build a couple"):
        Screw.from_axis([0, 0, 0], [1, 0, 0], oo)


def test_axis_is_the_line_s_s0_minus_hs(generic):
    S, S0 = generic["S"], generic["S0"]
    s = Screw(S, S0)
    L = axis(s)
    assert type(L) is LineVector and L.S == S
    assert is_zero_matrix(L.S0 - (S0 - s.pitch * S))
    assert cancel(L.pitch) == 0
    assert L.classify() is None  # a generic S may be zero: undecided
    p = symbols("p", positive=True)
    assert axis(Screw([p, S[1], S[2]], S0)).classify() == "line"


def test_axis_of_example_1_4():
    s = Screw([1, 1, 0], [1, 0, 0])
    assert s.axis == LineVector([1, 1, 0], [Rational(1, 2), -Rational(1, 2), 0])
    assert foot(s) == ImmutableMatrix([0, 0, -Rational(1, 2)])
    assert s.axis.contains([5, 5, -Rational(1, 2)]) is True
    assert s.distance_to_origin == Rational(1, 2)


def test_couple_has_no_axis_or_foot():
    c = Screw.couple([1, 2, 3])
    for f in (axis, foot, decompose_screw):
        with pytest.raises(ValueError, match=r"s: a couple \(0; C\) has no"):
            f(c)


def test_decompose_sums_back_and_parts_are_line_and_parallel_couple(generic):
    s = Screw(generic["S"], generic["S0"])
    line, couple = decompose_screw(s)
    assert type(line) is LineVector and type(couple) is Screw
    assert is_zero_matrix((line + couple - s).matrix)
    assert couple.S == zeros(3, 1)
    assert is_zero_matrix(couple.S0.cross(s.S))  # parallel to S


def test_decompose_keeps_twist_and_wrench_types():
    rot, trans = Twist.from_axis([1, 0, 0], [0, 0, 1], 3, magnitude=2).decompose()
    assert type(rot) is Twist and type(trans) is Twist
    assert trans == Twist.translation([0, 0, 6])
    force, couple = Wrench.from_axis([1, 0, 0], [0, 0, 1], 3, magnitude=2).decompose()
    assert type(force) is Wrench and couple == Wrench.couple([0, 0, 6])


@pytest.mark.parametrize(
    "S, S0, expected",
    [
        ([1, 1, 0], [1, 0, 0], "screw"),
        ([1, 0, 0], [0, 1, 0], "line"),
        ([0, 0, 0], [0, 1, 0], "couple"),
        ([0, 0, 0], [0, 0, 0], "zero"),
        ([1, 0, 0], [x, 0, 0], None),
        ([x, 0, 0], [0, 1, 0], None),
        ([0, 0, 0], [x, 0, 0], None),
    ],
)
def test_classify(S, S0, expected):
    assert classify(Screw(S, S0)) == expected
    assert Screw(S, S0).classify() == expected


def test_classify_uses_assumptions():
    p = symbols("p", positive=True)
    assert classify(Screw([1, 0, 0], [p, 0, 0])) == "screw"
    assert classify(Screw([p, 0, 0], [0, p, 0])) == "line"


def test_shift_origin_direction_is_pinned(generic):
    """(1.32): S^A = S^0 - a x S; the axis point p is seen from A at p - a."""
    p, S, h, a = generic["r"], generic["S"], generic["h"], generic["a"]
    shifted = shift_origin(Screw.from_axis(p, S, h), a)
    assert is_zero_matrix((shifted - Screw.from_axis(p - a, S, h)).matrix)
    assert cancel(shifted.pitch - h) == 0
    assert type(shift_origin(LineVector.from_axis(p, S), a)) is LineVector


def test_reciprocal_product_is_1_45_and_symmetric(generic):
    S1, S01, S2, S02 = vector("A"), vector("A0"), vector("B"), vector("B0")
    s1, s2 = Screw(S1, S01), Screw(S2, S02)
    assert expand(reciprocal_product(s1, s2) - (S1.dot(S02) + S2.dot(S01))) == 0
    assert expand(reciprocal_product(s1, s2) - reciprocal_product(s2, s1)) == 0
    assert expand(s1.reciprocal_product(s1) - 2 * S1.dot(S01)) == 0


def test_reciprocal_product_is_origin_independent(generic):
    s1, s2, a = Screw(vector("A"), vector("A0")), Screw(vector("B"), vector("B0")), generic["a"]
    lhs = reciprocal_product(shift_origin(s1, a), shift_origin(s2, a))
    assert expand(lhs - reciprocal_product(s1, s2)) == 0


def test_is_reciprocal():
    assert is_reciprocal(Screw([1, 0, 0], [0, 0, 0]), Screw([0, 1, 0], [0, 0, 1])) is True
    assert is_reciprocal(Screw([1, 0, 0], [1, 0, 0]), Screw([1, 0, 0], [0, 0, 0])) is False
    assert is_reciprocal(Screw([1, 0, 0], [x, 0, 0]), Screw([1, 0, 0], [0, 0, 0])) is None


def test_functions_accept_6_vectors():
    assert pitch([1, 1, 0, 1, 0, 0]) == Rational(1, 2)
    assert pitch((1, 1, 0, 1, 0, 0)) == Rational(1, 2)
    assert pitch(Matrix([1, 1, 0, 1, 0, 0])) == Rational(1, 2)
    assert reciprocal_product([1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 1]) == 0


# ------------------------------------------------------------------ algebra
def test_addition_subtraction_negation_scaling(generic):
    a, b = Screw([1, 2, 3], [4, 5, 6]), Screw([1, 0, 0], [0, 1, 0])
    assert a + b == Screw([2, 2, 3], [4, 6, 6])  # (1.39)
    assert a - b == Screw([0, 2, 3], [4, 4, 6])
    assert -a == Screw([-1, -2, -3], [-4, -5, -6])
    assert +a is a
    assert 2 * a == a * 2 == Screw([2, 4, 6], [8, 10, 12])  # (1.44)
    assert a / 2 == Screw([Rational(1, 2), 1, Rational(3, 2)], [2, Rational(5, 2), 3])
    k = generic["k"]
    assert k * a == Screw([k, 2 * k, 3 * k], [4 * k, 5 * k, 6 * k])


def test_scaling_leaves_pitch_and_axis(generic):
    s, k = Screw(generic["S"], generic["S0"]), symbols("k", positive=True)
    assert cancel((k * s).pitch - s.pitch) == 0
    assert is_zero_matrix(foot(k * s) - foot(s))


def test_result_classes():
    L1 = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    L2 = LineVector.from_axis([0, 0, 1], [0, 1, 0])
    assert type(L1 + L2) is Screw  # the sum of two lines is a screw in general
    assert type(2 * L1) is LineVector and type(-L1) is LineVector
    assert type(0 * L1) is Screw and 0 * L1 == Screw([0, 0, 0], [0, 0, 0])
    T = Twist.translation([1, 0, 0])
    assert type(T + T) is Twist and type(T + L1) is Twist and type(L1 + T) is Twist
    W = Wrench.couple([0, 0, 1])
    assert type(W + W) is Wrench and type(W - L1) is Wrench


def test_twist_plus_wrench_is_refused():
    with pytest.raises(TypeError, match="cannot add a Twist and a Wrench"):
        Twist.translation([1, 0, 0]) + Wrench.couple([0, 0, 1])


def test_arithmetic_refusals():
    s = Screw([1, 0, 0], [0, 0, 1])
    with pytest.raises(TypeError, match="cannot multiply two screws"):
        s * s
    with pytest.raises(TypeError, match="k: expected a real number or SymPy expression, got str"):
        "2" * s
    with pytest.raises(TypeError, match=r"got MutableDenseMatrix of shape \(2, 1\)"):
        Matrix([1, 2]) * s
    with pytest.raises(ValueError, match="k: expected a non-zero value, got 0"):
        s / 0
    with pytest.raises(TypeError):
        s + 1
    with pytest.raises(TypeError):
        s + [1, 2, 3, 4, 5, 6]


def test_equals_is_mathematical_equality():
    a, b = Screw([x * (x + 1), 0, 0], [0, 0, 0]), Screw([x**2 + x, 0, 0], [0, 0, 0])
    assert a != b and a.equals(b) is True
    assert a.equals(Screw([x, 0, 0], [0, 0, 0])) is None
    assert Screw([1, 0, 0], [0, 0, 0]).equals(LineVector([1, 0, 0], [0, 0, 0])) is True
    assert Screw([1, 0, 0], [0, 0, 0]).equals([2, 0, 0, 0, 0, 0]) is False


def test_classify_proves_nonzero_through_factors():
    """h (l**2 + m**2 + n**2) != 0 needs factoring before the assumptions can see it."""
    h = symbols("h", nonzero=True)
    l = symbols("l", positive=True)
    m, n = symbols("m n", real=True)
    assert classify(Screw([l, m, n], [h * l, h * m, h * n])) == "screw"  # Example 1.1
    assert classify(Screw([l, m, n], [x * l, x * m, x * n])) is None  # x may be 0


# ---------------------------------------------------------- closed forms (issue 12)
def test_derived_quantities_come_in_lowest_terms():
    h = symbols("h", real=True)
    r, S = vector("r"), vector("S")
    s = Screw.from_axis(r, S, h)
    assert s.pitch == pitch(s) == h  # S.S cancels (1.34), (1.38)
    assert s.axis == axis(s) == LineVector(S, r.cross(S))  # (1.36)
    line, couple = decompose_screw(s)
    assert line == s.axis and couple == Screw([0, 0, 0], h * S)  # (1.37)
    assert LineVector.through(vector("p"), vector("q")).pitch == 0
    assert shift_origin(s, r) == Screw(S, h * S)  # the axis through the new origin


def test_tidy_false_returns_the_raw_forms():
    h = symbols("h", real=True)
    s = Screw.from_axis(vector("r"), vector("S"), h)
    raw = pitch(s, tidy=False)
    assert raw != h and cancel(raw - h) == 0
    assert axis(s, tidy=False) != axis(s) and axis(s, tidy=False).equals(axis(s))
    assert is_zero_matrix(foot(s, tidy=False) - foot(s))


def test_pitch_piecewise_is_oo_where_the_direction_vanishes():
    s = Screw([x, 0, 0], [0, 0, 1])
    assert pitch(s) == 0  # generic, holds where x != 0
    assert pitch(s, conds="piecewise").subs(x, 0) == oo
    assert pitch(s, conds="piecewise").subs(x, 2) == 0
    assert pitch(Screw.couple([0, 0, 1]), conds="piecewise") == oo
