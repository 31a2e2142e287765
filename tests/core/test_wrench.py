"""Wrenches (Section 1.7): forces, couples, wrenches on an axis, and power."""

import pytest
from sympy import ImmutableMatrix, Rational, cancel, expand, symbols

from screwsym import Screw, Twist, Wrench, pitch, power, reciprocal_product, vector

f, h, C = symbols("f h C", real=True)


def vanishes(M):
    return all(expand(e) == 0 for e in M)


def test_force_is_1_55():
    fv, r = vector("f"), vector("r")
    W = Wrench.force(fv, point=r)
    assert W.f == fv and vanishes(W.C_O - r.cross(fv))
    assert W.moment_about(r) == ImmutableMatrix([0, 0, 0]) or vanishes(W.moment_about(r))


def test_force_through_a_has_no_moment_about_a():
    a = vector("a")
    assert vanishes(Wrench.force(vector("f"), point=a).moment_about(a))


def test_couple():
    W = Wrench.couple([0, 0, 5])
    assert W == Wrench([0, 0, 0], [0, 0, 5])
    assert W.moment_about(vector("a")) == ImmutableMatrix([0, 0, 5])
    assert pitch(W).is_infinite


def test_from_axis_is_1_57_and_1_58():
    S, r = vector("S"), vector("r")
    W = Wrench.from_axis(r, S, h, magnitude=f)
    assert vanishes(W.C_O - (r.cross(f * S) + h * f * S))  # (1.58)
    W0 = Wrench.from_axis([0, 0, 0], S, h, magnitude=f)
    assert vanishes(W0.C_O - h * W0.f)  # (1.57): O on the axis, a pure parallel couple
    assert cancel(pitch(W) - h) == 0


def test_wrench_as_force_plus_parallel_couple():
    S, r = vector("S"), vector("r")
    lhs = Wrench.from_axis(r, S, C / f, magnitude=f)
    rhs = Wrench.force(f * S, point=r) + Wrench.couple(C * S)
    assert all(cancel(e) == 0 for e in (lhs - rhs).matrix)


def test_power_is_the_reciprocal_product_and_physical_power():
    """omega.C_O + f.v_O = f . v(point of application) + C . omega (transcription (1.45))."""
    w, vP, rp, fv, rf, Cw = (vector(n) for n in ("w", "vP", "rp", "F", "rf", "Cw"))
    T = Twist(w, vP + w.cross(-rp))
    W = Wrench.force(fv, point=rf) + Wrench.couple(Cw)
    v_rf = vP + w.cross(rf - rp)
    assert expand(power(T, W) - (fv.dot(v_rf) + Cw.dot(w))) == 0
    assert power(T, W) == reciprocal_product(T, W)


def test_power_examples():
    assert power(Twist.translation([1, 0, 0]), Wrench.force([3, 0, 0], point=[0, 0, 0])) == 3
    # a pure rotation does no work against a force through its axis
    T = Twist.from_axis([1, 2, 0], [0, 0, 1], magnitude=5)
    assert power(T, Wrench.force([0, 0, 7], point=[1, 2, 9])) == 0
    assert power([0, 0, 1, 0, 0, 0], [0, 0, 0, 0, 0, Rational(1, 2)]) == Rational(1, 2)


def test_power_refuses_swapped_arguments():
    with pytest.raises(TypeError, match="twist: expected a Twist, got Wrench"):
        power(Wrench.couple([0, 0, 1]), Twist.translation([1, 0, 0]))
    with pytest.raises(TypeError, match="wrench: expected a Wrench, got Twist"):
        power(Twist.translation([1, 0, 0]), Twist.translation([1, 0, 0]))
    # a plain screw serves as either
    assert power(Screw([0, 0, 1], [0, 0, 0]), Screw([0, 0, 0], [0, 0, 2])) == 2
