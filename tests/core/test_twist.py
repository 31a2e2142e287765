"""Twists (Section 1.6): rotation, translation, screw motion, velocity of a point."""

import pytest
from sympy import ImmutableMatrix, expand, symbols, zeros

from screwsym import Twist, axis, pitch, shift_origin, vector

w, h = symbols("omega h", real=True)


def vanishes(M):
    return all(expand(e) == 0 for e in M)


def test_rotation_is_1_48_and_its_dual_part_is_v_O_1_50():
    S, r = vector("S"), vector("r")
    T = Twist.from_axis(r, S, magnitude=w)
    assert T.omega == w * S and vanishes(T.v_O - w * r.cross(S))
    # the body point at O moves with omega x (O - r)
    assert vanishes(T.v_O - (w * S).cross(zeros(3, 1) - r))
    assert T.axis.contains(r) is None or vanishes(r.cross(T.S) - axis(T).S0)


def test_translation():
    T = Twist.translation([1, 2, 3])
    assert T == Twist([0, 0, 0], [1, 2, 3])
    assert shift_origin(T, vector("a")) == T  # a translation does not depend on the origin
    assert T.classify() == "couple"


def test_screw_motion_1_52_1_53_pins_the_sign_of_v_O():
    S, r = vector("S"), vector("r")
    T = Twist.from_axis(r, S, h, magnitude=w)
    assert vanishes(T.v_O - (h * w * S + (w * S).cross(-r)))  # transcription 0.5
    assert vanishes(
        T.matrix - (Twist.from_axis(r, S, magnitude=w) + Twist.translation(h * w * S)).matrix
    )


def test_screw_motion_pitch_1_54():
    T = Twist.from_axis(vector("r"), vector("S"), h, magnitude=w)
    from sympy import cancel

    assert cancel(pitch(T) - h) == 0


def test_velocity_at_points_of_the_axis_is_along_the_axis():
    S, r, t = vector("S"), vector("r"), symbols("t", real=True)
    T = Twist.from_axis(r, S, h, magnitude=w)
    v = T.velocity_at(r + t * S)
    assert vanishes(v - h * w * S)


def test_velocity_at_is_rigid_body_velocity():
    T = Twist.from_axis([1, 0, 0], [0, 0, 1], magnitude=2)
    assert T.velocity_at([1, 0, 0]) == ImmutableMatrix([0, 0, 0])
    assert T.velocity_at([2, 0, 0]) == ImmutableMatrix([0, 2, 0])
    assert T.velocity_at([0, 0, 0]) == T.v_O


def test_bad_twist_input():
    with pytest.raises(
        TypeError, match="magnitude: expected a real number or SymPy expression, got str"
    ):
        Twist.from_axis([0, 0, 0], [0, 0, 1], magnitude="w")
    with pytest.raises(ValueError, match=r"v: expected a 3-vector, got shape \(2,\)"):
        Twist.translation([1, 2])
    with pytest.raises(ValueError, match=r"point: expected a 3-vector, got shape \(6,\)"):
        Twist.translation([1, 2, 3]).velocity_at([0] * 6)
    with pytest.raises(ValueError, match=r"omega\[1\]: expected a real value, got I"):
        from sympy import I

        Twist([0, I, 0], [0, 0, 0])
