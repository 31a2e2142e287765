"""convert and convert_from: the neighbours' layouts, and exact round trips.

The layouts are checked against behaviour, not only against the table:
modern_robotics' own functions (a wrench pairs with a twist by the plain dot
product, and moves by Ad^T), pinocchio's ``MotionDense::se3Action_impl`` and
``MotionDense::dot`` (transcribed from
``include/pinocchio/spatial/motion-dense.hpp``), and Featherstone's ``pluho``
(``spatial/pluho.m`` of spatial_v2).
"""

from __future__ import annotations

import numpy as np
import pytest
from _motions import random_transform, rational_vector
from sympy import ImmutableMatrix, Matrix, symbols

from screwsym import (
    LineVector,
    Screw,
    Transform,
    Twist,
    Wrench,
    convert,
    convert_from,
    power,
    vector,
)
from screwsym.motion.conventions import CONVENTIONS
from screwsym.motion.transform import skew

NAMES = tuple(CONVENTIONS)


@pytest.mark.parametrize("name", NAMES)
def test_round_trips_are_exact_with_symbols(name):
    t = symbols("theta", real=True)
    objects = [
        Twist(vector("w"), vector("v")),
        Wrench(vector("f"), vector("C")),
        Screw(vector("S"), vector("S0")),
        LineVector([1, 0, 0], [0, 1, 0]),
        Transform.rotation([0, 0, 1], t, point=vector("c")),
    ]
    for obj in objects:
        back = convert_from(convert(obj, to=name), name, type(obj))
        if name == "featherstone" and isinstance(obj, Transform):
            # inverted twice: R R^T p is p by sin^2 + cos^2 = 1, decided exactly by equals
            assert back.equals(obj) is True
        else:
            assert back == obj
    rng = np.random.default_rng(20)
    for _ in range(20):  # with exact numbers every round trip is structural equality
        T = random_transform(rng)
        assert convert_from(convert(T, to=name), name, Transform) == T


def test_the_layouts():
    tw, wr = Twist([1, 2, 3], [4, 5, 6]), Wrench([1, 2, 3], [4, 5, 6])
    angular_first, linear_first = Matrix([1, 2, 3, 4, 5, 6]), Matrix([4, 5, 6, 1, 2, 3])
    for name in ("modern_robotics", "pytransform3d", "featherstone"):
        assert convert(tw, to=name) == angular_first
        assert convert(wr, to=name) == Matrix([4, 5, 6, 1, 2, 3])  # moment first
    for name in ("spatialmath", "pinocchio"):
        assert convert(tw, to=name) == linear_first
        assert convert(wr, to=name) == Matrix([1, 2, 3, 4, 5, 6])  # force first
    T = Transform.rotation([0, 0, 1], 1, point=[1, 2, 3])
    for name in NAMES:
        expected = T.inverse().matrix if name == "featherstone" else T.matrix
        assert convert(T, to=name) == expected


@pytest.mark.parametrize("name", NAMES)
def test_power_is_the_plain_dot_product_in_every_layout(name):
    """Each library pairs its motion and force vectors by the dot product: a layout test."""
    rng = np.random.default_rng(21)
    for _ in range(10):
        tw = Twist(rational_vector(rng), rational_vector(rng))
        wr = Wrench(rational_vector(rng), rational_vector(rng))
        assert convert(tw, to=name).dot(convert(wr, to=name)) == power(tw, wr)


def test_a_wrong_layout_fails_the_power_test():
    tw, wr = Twist([1, 0, 0], [0, 0, 0]), Wrench([1, 0, 0], [0, 0, 0])
    # a wrench written force first against a twist written angular first: no power
    assert convert(tw, to="modern_robotics").dot(convert(wr, to="pinocchio")) != power(tw, wr)


def test_pinocchio_se3_action_on_a_motion():
    """pinocchio: w' = R w, v' = R v + p x w' (MotionDense::se3Action_impl), linear first."""
    rng = np.random.default_rng(22)
    for _ in range(20):
        T = random_transform(rng)
        tw = Twist(rational_vector(rng), rational_vector(rng))
        m = convert(tw, to="pinocchio")
        v, w = m[:3, :], m[3:, :]
        w2 = T.R * w
        v2 = T.R * v + T.p.cross(w2)
        assert convert(T.apply(tw), to="pinocchio") == Matrix.vstack(v2, w2)


def test_featherstone_pluho_of_the_coordinate_transform_moves_motion_vectors():
    """pluho: T = [E, -E r; 0 1] -> X = [E, 0; skew(-E r) E, E]; X moves motion vectors
    from the base frame A to the moved frame B, the inverse of screwsym's apply."""
    rng = np.random.default_rng(23)
    for _ in range(20):
        T = random_transform(rng)
        F = convert(T, to="featherstone")
        E, mEr = F[:3, :3], F[:3, 3]
        X = Matrix.vstack(
            Matrix.hstack(E, ImmutableMatrix.zeros(3, 3)), Matrix.hstack(skew(mEr) * E, E)
        )
        tw = Twist(rational_vector(rng), rational_vector(rng))
        moved = convert(T.apply(tw), to="featherstone")
        assert X * moved == convert(tw, to="featherstone")


def test_bad_arguments():
    with pytest.raises(ValueError, match="to: expected one of 'modern_robotics', .* got 'ros'"):
        convert(Twist([0, 0, 1], [0, 0, 0]), to="ros")
    with pytest.raises(TypeError, match="obj: expected a Twist, Wrench, LineVector, Screw or"):
        convert([0, 0, 1, 0, 0, 0], to="pinocchio")
    with pytest.raises(ValueError, match="source: expected one of"):
        convert_from([0, 0, 1, 0, 0, 0], "drake", Twist)
    with pytest.raises(TypeError, match="kind: expected one of Screw, LineVector, Twist, "):
        convert_from([0, 0, 1, 0, 0, 0], "pinocchio", "Twist")
    with pytest.raises(ValueError, match=r"value: expected a 6-vector \(S; S0\), got shape \(4, 4\)"):
        convert_from(ImmutableMatrix.eye(4), "pinocchio", Twist)
    # the errors name convert_from's argument, value, not the M of the constructor it calls
    with pytest.raises(ValueError, match=r"^value: expected a 4x4 matrix, got shape \(6, 1\)"):
        convert_from(ImmutableMatrix.zeros(6, 1), "pinocchio", Transform)
    with pytest.raises(ValueError, match=r"^value: expected the last row \[0, 0, 0, 1\]"):
        convert_from([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]], "featherstone",
                     Transform)
    with pytest.raises(ValueError, match=r"^value\[:3, :3\]: expected an orthonormal matrix"):
        convert_from([[1, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], "pinocchio",
                     Transform)
    with pytest.raises(ValueError, match=r"^value: a line vector needs S.S0 = 0 \(1.10\)"):
        convert_from([1, 0, 0, 1, 0, 0], "spatialmath", LineVector)
