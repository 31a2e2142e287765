"""SpatialInertia: the physical checks, the momentum, energy, sums and moves (issue 21).

The formulas are Featherstone's (*Rigid Body Dynamics Algorithms*, 2008, (2.62)-(2.63),
written for screwsym's ray order) and are checked here against their definitions: the
momentum of a body as the integral of its points' momenta (a finite set of point masses,
whose sum is exact), the energy as ``1/2 sum m_k |v_k|^2``.
"""

from __future__ import annotations

import numpy as np
import pytest
from _motions import random_transform, rational_vector
from sympy import ImmutableMatrix, Rational, Symbol, symbols, zeros

from screwsym import SpatialInertia, Transform, Twist, Wrench, power
from screwsym.core.inertia import check_inertia_tensor

Z3 = zeros(3, 3)


def _points(rng, k=4):
    """A few point masses with rational data: a body whose momentum is an exact sum."""
    return [(Rational(int(rng.integers(1, 9)), 3), ImmutableMatrix(rational_vector(rng)))
            for _ in range(k)]


def _body_of(points):
    total = None
    for m, r in points:
        b = SpatialInertia.point_mass(m, r)
        total = b if total is None else total + b
    return total


@pytest.mark.parametrize("case", range(5))
def test_momentum_and_energy_are_the_sums_over_the_points(case):
    rng = np.random.default_rng([2101, case])
    points = _points(rng)
    body = _body_of(points)
    twist = Twist(rational_vector(rng), rational_vector(rng))
    w, v = twist.omega, twist.v_O
    # each point moves with v_O + omega x r; its momentum is the force m v_r acting through r
    f = sum((m * (v + w.cross(r)) for m, r in points), zeros(3, 1))
    C = sum((r.cross(m * (v + w.cross(r))) for m, r in points), zeros(3, 1))
    assert body.momentum(twist) == Wrench(f, C)
    energy = sum(m * (v + w.cross(r)).dot(v + w.cross(r)) for m, r in points) / 2
    assert body.kinetic_energy(twist) == energy
    assert body.kinetic_energy(twist) == power(twist, body.momentum(twist)) / 2
    # the matrix is the momentum map, and Delta M is symmetric
    assert body.matrix * twist.matrix == body.momentum(twist).matrix
    D = body.matrix[[3, 4, 5, 0, 1, 2], :]
    assert D == D.T
    # a wrong matrix would be caught: the transpose is not the momentum map
    assert body.matrix.T * twist.matrix != body.momentum(twist).matrix


@pytest.mark.parametrize("case", range(5))
def test_transform_moves_com_inertia_and_matrix_by_the_adjoint(case):
    rng = np.random.default_rng([2102, case])
    body = _body_of(_points(rng))
    T = random_transform(rng)
    moved = T.apply(body)
    assert moved.com == T.R * body.com + T.p
    assert moved.inertia == T.R * body.inertia * T.R.T
    Ad, Adinv = T.adjoint(), T.inverse().adjoint()
    # the ray-order map moves by similarity: twists and wrenches both move with Ad(T)
    assert moved.matrix == Ad * body.matrix * Adinv
    # the symmetric form Delta M by congruence with Ad(T^-1)
    swap = [3, 4, 5, 0, 1, 2]
    assert moved.matrix[swap, :] == Adinv.T * body.matrix[swap, :] * Adinv
    # and the congruence with Ad(T) itself (the wrong way round) does not hold
    assert moved.matrix[swap, :] != Ad.T * body.matrix[swap, :] * Ad
    # the points moved one by one give the same body
    assert moved == _body_of([(m, T.apply(r)) for m, r in _points(np.random.default_rng([2102, case]))])


def test_sum_of_bodies_is_exact_and_associative():
    a = SpatialInertia(2, [1, 0, 0], ImmutableMatrix.diag(1, 2, 2))
    b = SpatialInertia(1, [0, 1, 0], ImmutableMatrix.diag(1, 1, 1))
    c = SpatialInertia.point_mass(3, [0, 0, 1])
    s = a + b + c
    assert s.mass == 6 and s.com == ImmutableMatrix([Rational(1, 3), Rational(1, 6), Rational(1, 2)])
    assert (a + (b + c)) == s and s.matrix == a.matrix + b.matrix + c.matrix
    assert s.parameters() == a.parameters() + b.parameters() + c.parameters()


def test_parameters_round_trip_and_pinocchio_order():
    m, x, y = symbols("m", positive=True), *symbols("x y", real=True)
    body = SpatialInertia(m, [x, y, 0], ImmutableMatrix.diag(1, 2, 3))
    p = body.parameters()
    # [m, mc_x, mc_y, mc_z, I_xx, I_xy, I_yy, I_xz, I_yz, I_zz] about the origin
    assert list(p) == [m, m * x, m * y, 0, m * y**2 + 1, -m * x * y, m * x**2 + 2, 0, 0,
                       m * x**2 + m * y**2 + 3]
    assert SpatialInertia.from_parameters(list(p)).equals(body) is True


def test_gravity_wrench_is_the_weight_through_the_com():
    body = SpatialInertia(2, [1, 2, 3], ImmutableMatrix.diag(1, 1, 1))
    W = body.gravity_wrench([0, 0, -10])
    assert W == Wrench.force([0, 0, -20], point=[1, 2, 3])
    assert W.moment_about([1, 2, 3]) == zeros(3, 1)


@pytest.mark.parametrize(
    "args, match",
    [
        ((0, [0, 0, 0], Z3), "mass: expected a positive mass, got 0"),
        ((-2, [0, 0, 0], Z3), "mass: expected a positive mass"),
        ((Symbol("m", negative=True), [0, 0, 0], Z3), "mass: expected a positive mass"),
        ((1, [0, 0, 0], [[1, 2, 0], [0, 1, 0], [0, 0, 1]]), r"inertia: expected a symmetric matrix, got \[0, 1\] = 2"),
        ((1, [0, 0, 0], ImmutableMatrix.diag(1, -1, 1)), "inertia: expected a positive semi-definite"),
        ((1, [0, 0, 0], [[1, 2, 0], [2, 1, 0], [0, 0, 1]]), "positive semi-definite.*minor"),
        ((1, [0, 0, 0], ImmutableMatrix.diag(1, 1, 3)), "triangle inequalities"),
        ((1.0, [0, 0, 0], ImmutableMatrix.diag(1.0, 1.0, 2.5)), "triangle inequalities"),
        ((1, [0, 0], Z3), "com: expected a 3-vector"),
    ],
)
def test_unphysical_input_is_refused_naming_the_argument(args, match):
    with pytest.raises(ValueError, match=match):
        SpatialInertia(*args)


def test_what_is_physical_or_undecidable_is_accepted():
    # a thin rod (I_1 + I_2 = I_3 on the boundary) and a float rounding of it
    assert SpatialInertia(1, [0, 0, 0], ImmutableMatrix.diag(0, 1, 1)).mass == 1
    assert SpatialInertia(1.0, [0, 0, 0], ImmutableMatrix.diag(1e-17, 0.1 + 0.2, 0.3))
    # symbols whose signs are not known: accepted undecided (documented)
    a, b, c = symbols("a b c", real=True)
    assert SpatialInertia(Symbol("m", positive=True), [0, 0, 0], ImmutableMatrix.diag(a, b, c))
    # positive symbols prove the diagonal non-negative, but not the triangle inequalities
    p = symbols("p", positive=True)
    with pytest.raises(ValueError, match="positive semi-definite"):
        check_inertia_tensor(ImmutableMatrix.diag(-p, 1, 1), "inertia")


def test_is_a_sympy_value():
    m, x = Symbol("m", positive=True), Symbol("x", real=True)
    body = SpatialInertia(m, [x, 0, 0], ImmutableMatrix.diag(1, 1, 1))
    assert body.func(*body.args) == body and hash(body) == hash(body.func(*body.args))
    assert body.subs(x, 2).com == ImmutableMatrix([2, 0, 0]) and body.free_symbols == {m, x}
    assert str(body) == "SpatialInertia(mass=m, com=[x, 0, 0], inertia=[[1, 0, 0], [0, 1, 0], [0, 0, 1]])"
    with pytest.raises(TypeError, match="strings are never evaluated"):
        body.subs(x, "2")
    with pytest.raises(TypeError, match="other: expected"):
        body.equals(3)
    assert Transform.identity().apply(body) == body
