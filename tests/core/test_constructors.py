"""One constructor vocabulary for every kind of screw (issue 8).

Every kind builds from the same named constructors with the same argument
order, inherited unchanged: ``from_axis(point, direction, pitch=0, *,
magnitude=1)``, ``through(A, B)``, ``couple(C)``, ``from_matrix(M)``.  The
book's sugar (``rotation``, ``translation``, ``screw_motion``, ``force``)
takes every vector after the first by keyword.
"""

from __future__ import annotations

import inspect

import pytest
from sympy import Rational, symbols

from screwsym import LineVector, Screw, Twist, Wrench, pitch, vector

KINDS = [Screw, LineVector, Twist, Wrench]
h, w, f = symbols("h omega f", real=True)


@pytest.mark.parametrize("name", ["from_axis", "through", "couple", "from_matrix"])
def test_named_constructors_are_inherited_unchanged(name):
    # the same function object for every kind: no subclass overrides a constructor
    functions = {getattr(cls, name).__func__ for cls in KINDS}
    assert len(functions) == 1


def test_from_axis_signature():
    params = inspect.signature(Screw.from_axis).parameters
    assert list(params) == ["point", "direction", "pitch", "magnitude"]
    assert params["magnitude"].kind is inspect.Parameter.KEYWORD_ONLY
    assert params["pitch"].default == 0 and params["magnitude"].default == 1


@pytest.mark.parametrize("cls", [Screw, Twist, Wrench])
def test_from_axis_is_1_38_times_magnitude_for_every_kind(cls):
    r, S = vector("r"), vector("S")
    s = cls.from_axis(r, S, h, magnitude=w)
    assert type(s) is cls
    assert s.S == w * S
    assert (s.S0 - w * (r.cross(S) + h * S)).expand() == vector("r").zeros(3, 1)


def test_the_old_orders_are_refused_not_misread():
    # a point and a direction can no longer be swapped silently in the sugar
    with pytest.raises(TypeError):
        Twist.screw_motion([0, 0, 1], [1, 0, 0], 2)
    with pytest.raises(TypeError):
        Twist.rotation([0, 0, 1], [1, 0, 0])
    with pytest.raises(TypeError):
        Wrench.force([0, 0, 1], [1, 0, 0])
    assert not hasattr(LineVector, "from_point")


def test_sugar_agrees_with_from_axis():
    r = [1, 2, 0]
    assert Twist.rotation([0, 0, w], point=r) == Twist.from_axis(r, [0, 0, 1], magnitude=w)
    assert Twist.screw_motion([0, 0, 2], point=r, pitch=h) == Twist.from_axis(
        r, [0, 0, 1], h, magnitude=2
    )
    assert Wrench.force([0, 0, f], point=r) == Wrench.from_axis(r, [0, 0, 1], magnitude=f)
    assert Twist.translation([1, 2, 3]) == Twist.couple([1, 2, 3])


def test_wrench_from_axis_is_the_screws():
    # Wrench.from_axis(r, S, h) used to raise TypeError: it is Screw.from_axis now
    W = Wrench.from_axis([0, 1, 0], [1, 0, 0], h)
    assert W == Wrench(*Screw.from_axis([0, 1, 0], [1, 0, 0], h).args)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: Screw.from_axis([1, 2, 3], [0, 0, 0], 2),
         "direction: an axis needs a non-zero direction, got [0, 0, 0]"),
        (lambda: Twist.from_axis([1, 2, 3], [0, 0, 0], magnitude=w),
         "direction: an axis needs a non-zero direction, got [0, 0, 0]"),
        (lambda: Twist.rotation([0, 0, 0], point=[1, 0, 0]),
         "omega: a rotation needs a non-zero angular velocity, got [0, 0, 0]"),
        (lambda: Twist.screw_motion([0, 0, 0], point=[1, 0, 0], pitch=1),
         "omega: a screw motion needs a non-zero angular velocity (for a translation use "
         "Twist.translation(v)), got [0, 0, 0]"),
        (lambda: Wrench.force([0, 0, 0], point=[1, 0, 0]),
         "f: a force needs a non-zero vector for its line of action, got [0, 0, 0]"),
        (lambda: LineVector.from_axis([0, 0, 0], [1, 0, 0], 1),
         "point, direction, pitch: a line vector needs S.S0 = 0 (1.10), got S.S0 = 1"),
        (lambda: LineVector.couple([0, 0, 1]),
         "C: a line vector needs a non-zero direction S, got [0, 0, 0]"),
        # the error named "point, direction, pitch", none of which is at fault
        (lambda: LineVector.from_axis([0, 0, 0], [1, 0, 0], magnitude=0),
         "magnitude: a line vector needs a non-zero direction S, got [0, 0, 0]"),
        (lambda: LineVector.through([1, 2, 3], [1, 2, 3]),
         "A, B: expected two distinct points, got A = B = [1, 2, 3]"),
    ],
)
def test_zero_directions_raise(call, message):
    with pytest.raises(ValueError) as info:
        call()
    assert str(info.value) == message


def test_a_six_vector_says_from_matrix():
    with pytest.raises(TypeError) as info:
        Screw([1, 0, 0, 0, 0, 1])
    assert str(info.value) == (
        "Screw(S, S0) takes two 3-vectors; for a 6-vector (S; S0) use Screw.from_matrix(M)"
    )
    with pytest.raises(TypeError, match=r"Twist\.from_matrix\(M\)"):
        Twist(vector("a").col_join(vector("b")))
    with pytest.raises(TypeError, match=r"LineVector\(S, S0\): missing the dual part S0"):
        LineVector([1, 0, 0])


def test_through_for_every_kind():
    for cls in (LineVector, Screw, Twist, Wrench):
        s = cls.through([0, 0, 1], [1, 0, 1])
        assert type(s) is cls and s.matrix.T.tolist() == [[1, 0, 0, 0, 1, 0]]


@pytest.mark.parametrize(
    "s, expected",
    [
        (Screw([0, 3, 4], [1, 2, 3]), Screw([0, Rational(3, 5), Rational(4, 5)],
                                           [Rational(1, 5), Rational(2, 5), Rational(3, 5)])),
        (Screw.couple([0, 0, -2]), Screw([0, 0, 0], [0, 0, -1])),
        # Example 1.3: the line through (1, 0, 0) along (1, 1, 1), normalised
        (LineVector.from_axis([1, 0, 0], [1, 1, 1]), None),
    ],
)
def test_unit_normalises_as_the_book(s, expected):
    u = s.unit()
    assert type(u) is type(s)
    if expected is not None:
        assert u == expected
    if s.classify() != "couple":
        assert u.S.dot(u.S) == 1 and pitch(u) == pitch(s)
    else:
        assert u.S0.dot(u.S0) == 1


def test_unit_of_the_zero_screw_raises():
    with pytest.raises(ValueError, match=r"s: the zero screw \(0; 0\) cannot be normalised"):
        __import__("screwsym").unit(Screw([0, 0, 0], [0, 0, 0]))


def test_algebra_is_declared_by_each_kind():
    L = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    T = Twist.rotation([0, 0, 1], point=[0, 0, 0])
    W = Wrench.force([0, 0, 1], point=[1, 0, 0])
    assert type(L + L) is Screw and type(0 * L) is Screw and type(2 * L) is LineVector
    assert type(T + L) is Twist and type(L + T) is Twist and type(W + W) is Wrench
    assert type(T.decompose()[0]) is Twist and type(Screw([1, 0, 0], [1, 0, 0]).decompose()[0]) is LineVector
    with pytest.raises(TypeError, match="cannot add a Twist and a Wrench"):
        T + W
    # the declarations are data on the classes, read by the base
    assert (Twist._kind, Wrench._kind, Screw._kind, LineVector._kind) == ("twist", "wrench", None, None)
    assert Screw._line_class() is LineVector and Twist._line_class() is Twist
