"""Chain: forward kinematics and Jacobians by the product of exponentials, exact."""

from __future__ import annotations

import numpy as np
import pytest
from sympy import (
    ImmutableMatrix,
    Matrix,
    Rational,
    cancel,
    cos,
    count_ops,
    expand,
    pi,
    sin,
    symbols,
    trigsimp,
)

from screwsym import Chain, Transform, Twist, Wrench, exp6, lambdify, tidy
from screwsym.motion.displacement import se3_matrix

q1, q2, q3 = q = symbols("q1:4", real=True)


def is_exactly_zero(m) -> bool:
    return all(cancel(trigsimp(expand(e))) == 0 for e in m)


@pytest.fixture(scope="module")
def rph():
    """Revolute about z, prismatic along a skew direction, helical of pitch 1/2 about x."""
    return Chain(
        [
            Twist.rotation([0, 0, 1], point=[1, 0, 0]),
            Twist.translation([Rational(3, 5), 0, Rational(4, 5)]),
            Twist.screw_motion([1, 0, 0], point=[0, 1, 2], pitch=Rational(1, 2)),
        ],
        Transform.rotation([0, 1, 0], pi / 2, point=[1, 1, 1]),
    )


@pytest.mark.slow
def test_space_jacobian_columns_are_the_derivatives_of_the_motion(rph):
    """[J_s column i] = dT/dq_i T^-1, the definition of the space Jacobian."""
    T = rph.forward(q).matrix
    Tinv = rph.forward(q).inverse().matrix
    J = rph.jacobian(q)
    for i, qi in enumerate(q):
        assert is_exactly_zero(T.diff(qi) * Tinv - se3_matrix(J[:, i]))


def test_body_jacobian_columns_are_the_derivatives_in_the_end_frame(rph):
    """[J_b column i] = T^-1 dT/dq_i."""
    T = rph.forward(q).matrix
    Tinv = rph.forward(q).inverse().matrix
    J = rph.jacobian(q, frame="body")
    for i, qi in enumerate(q):
        assert is_exactly_zero(Tinv * T.diff(qi) - se3_matrix(J[:, i]))


def test_the_derivative_check_can_fail(rph):
    T = rph.forward(q).matrix
    Tinv = rph.forward(q).inverse().matrix
    J = rph.jacobian(q, frame="body")  # the body Jacobian is not the space one
    assert not is_exactly_zero(T.diff(q1) * Tinv - se3_matrix(J[:, 0]))


def test_space_and_body_jacobians_are_related_by_the_adjoint(rph):
    T = rph.forward(q)
    assert is_exactly_zero(rph.jacobian(q) - T.adjoint() * rph.jacobian(q, frame="body"))


def test_forward_is_the_product_of_exponentials(rph):
    expected = Transform.identity()
    for twist, qi in zip(rph.twists, q, strict=True):
        expected = expected @ exp6(twist, qi)
    expected = expected @ rph.home
    assert is_exactly_zero(rph.forward(q).matrix - expected.matrix)


def test_at_home(rph):
    zero = [0, 0, 0]
    assert rph.forward(zero) == rph.home
    assert rph.jacobian(zero) == ImmutableMatrix.hstack(*(t.matrix for t in rph.twists))
    assert rph.jacobian(zero, frame="body") == ImmutableMatrix.hstack(
        *(t.matrix for t in rph.body_twists())
    )


def test_numbers_for_q_give_exact_numbers(rph):
    T = rph.forward([pi / 2, 2, 0])
    assert T.equals(rph.forward(q).subs({q1: pi / 2, q2: 2, q3: 0})) is True
    assert not T.free_symbols


def test_tidy_is_an_identity_and_gathers_sums():
    a, b = symbols("a b", real=True)
    e = (cos(a) * cos(b) - sin(a) * sin(b)) * (2 + sin(b) ** 2) + 2 * cos(b) ** 2
    assert is_exactly_zero(Matrix([tidy(e) - e]))
    assert count_ops(tidy(e)) < count_ops(expand(e))
    assert tidy(3 * sin(a) ** 2 + 3 * cos(a) ** 2) == 3
    assert count_ops(tidy(a * (a + 1))) <= count_ops(a**2 + a)


def test_tidied_jacobian_is_no_larger_than_the_raw_product(rph):
    raw = Transform.identity()
    columns = []
    for twist, qi in zip(rph.twists, q, strict=True):
        columns.append(raw.adjoint() * twist.matrix)
        raw = raw @ exp6(twist, qi)
    assert count_ops(rph.jacobian(q)) <= count_ops(ImmutableMatrix.hstack(*columns))


def test_lambdify_gives_batched_kinematics(rph):
    qv = Matrix(q)
    fk = lambdify([qv], (rph.forward(q).matrix, rph.jacobian(q)))
    Q = np.array([[0.1, 0.2, 0.3], [1.0, -2.0, 0.5]])
    T, J = fk(Q)
    assert T.shape == (2, 4, 4) and J.shape == (2, 6, 3)
    at = rph.forward([Rational(1), Rational(-2), Rational(1, 2)]).matrix
    np.testing.assert_allclose(T[1], np.array(at.evalf(), dtype=float), atol=1e-12)


def test_args_rebuild_and_properties(rph):
    assert rph.func(*rph.args) == rph
    assert rph.n_joints == 3 and len(rph.twists) == 3
    assert Chain([Twist([0, 0, 1], [0, 0, 0])]).home == Transform.identity()
    assert str(Chain([Twist([0, 0, 1], [0, 0, 0])])).startswith("Chain([Twist([0, 0, 1]")


def test_bad_arguments(rph):
    with pytest.raises(ValueError, match="twists: expected at least one joint twist, got none"):
        Chain([])
    with pytest.raises(TypeError, match="twists: expected a sequence of twists, got Twist"):
        Chain(Twist([0, 0, 1], [0, 0, 0]))
    with pytest.raises(TypeError, match=r"twists\[0\]: expected a Twist, got Wrench"):
        Chain([Wrench([0, 0, 1], [0, 0, 0])])
    with pytest.raises(ValueError, match=r"twists\[1\]: a joint twist cannot be zero"):
        Chain([Twist([0, 0, 1], [0, 0, 0]), Twist([0, 0, 0], [0, 0, 0])])
    with pytest.raises(TypeError, match="home: expected a Transform, got ImmutableDenseMatrix"):
        Chain([Twist([0, 0, 1], [0, 0, 0])], ImmutableMatrix.eye(4))
    with pytest.raises(ValueError, match="q: expected 3 joint values, got 2"):
        rph.forward([0, 0])
    with pytest.raises(TypeError, match="q: expected a sequence of joint values, got str"):
        rph.forward("q1q2q3")
    with pytest.raises(TypeError, match=r"q\[1\]: expected a real number .*strings"):
        rph.jacobian([0, "1", 0])
    with pytest.raises(ValueError, match="frame: expected one of 'space', 'body', got 'world'"):
        rph.jacobian(q, frame="world")


# ---------------------------------------------------------------- the ring path (issue 23 item 1)
#: rational points (c, s) of the unit circle: exact values of cos and sin of an angle
_CIRCLE = [(Rational(3, 5), Rational(4, 5)), (Rational(5, 13), Rational(12, 13)),
           (Rational(8, 17), Rational(15, 17)), (Rational(7, 25), Rational(24, 25)),
           (Rational(20, 29), Rational(21, 29))]


def _at_circle_points(angles, seed, extra=None):
    """A map ``cos(q_i) -> c_i, sin(q_i) -> s_i`` at random exact points of the circle (signs too)."""
    import random

    rng = random.Random(seed)
    point = dict(extra or {})
    for qi in angles:
        c, s = rng.choice(_CIRCLE)
        point[cos(qi)] = c * rng.choice([1, -1])
        point[sin(qi)] = s * rng.choice([1, -1])
    return point


def _exact_values(M, point):
    """``M`` at the point: sums of angles expanded (``expand_trig``), then the exact values put in."""
    from sympy import expand_trig

    return M.applyfunc(lambda e: expand(expand_trig(e).xreplace(point)))


def _raw_products(chain, qs, frame="space"):
    """T(q) and the Jacobian as plain products of ``exp6`` and adjoints, nothing tidied in between."""
    T = Transform.identity()
    cols = []
    for twist, qi in zip(chain.twists, qs, strict=True):
        cols.append(T.adjoint() * twist.matrix)
        T = T @ exp6(twist, qi)
    T = T @ chain.home
    J = ImmutableMatrix.hstack(*cols)
    if frame == "body":
        J = T.inverse().adjoint() * J
    return T.matrix, J


def _agree(fast, raw, angles, seeds, extra=None):
    return all(_exact_values(fast, _at_circle_points(angles, s, extra)) ==
               _exact_values(raw, _at_circle_points(angles, s, extra)) for s in seeds)


def test_the_ring_path_equals_the_products_on_the_ur5_and_is_no_larger():
    """The UR5 of Lynch & Park (2017, Example 4.5): forward kinematics and space Jacobian.

    Equal to the plain product of exponentials at exact points of the circle, as small as the
    stepwise tidied products were (count_ops 242 and 343 before issue 23), and the comparison
    rejects a wrong entry.
    """
    from screwsym.motion.chain import ur5

    arm = ur5()
    qs = symbols("q1:7", real=True)
    T, Js = arm.forward(qs).matrix, arm.jacobian(qs)
    T0, J0 = _raw_products(arm, qs)
    assert _agree(T, T0, qs, [1]) and _agree(Js, J0, qs, [2])
    assert count_ops(T) <= 242 and count_ops(Js) <= 343
    assert Js[0, 1] == -sin(qs[0])  # the second axis turns with the first joint alone
    wrong = Js.as_mutable()
    wrong[3, 4] += sin(qs[1] + qs[2]) ** 2 + cos(qs[1] + qs[2]) ** 2 - 1 + sin(qs[0] - qs[5]) / 1000
    assert not _agree(wrong, J0, qs, [1])


@pytest.mark.slow
def test_the_ring_path_body_jacobian_of_the_ur5():
    """The body Jacobian by the ring (the space recursion on the body twists, angles negated)."""
    from screwsym.motion.chain import ur5

    arm = ur5()
    qs = symbols("q1:7", real=True)
    assert _agree(arm.jacobian(qs, frame="body"), _raw_products(arm, qs, "body")[1], qs, [3])


def test_the_ring_path_body_jacobian_with_a_prismatic_joint():
    """An RPR arm from a DH table: body Jacobian equal to Ad(T^-1) J_s of the plain products."""
    arm = Chain.from_dh([(0, pi / 2, 0, 0), (0, 0, 1, 0), (1, 0, 0, 0)], joints="RPR")
    assert _agree(arm.jacobian(q, frame="body"), _raw_products(arm, q, "body")[1], q, [4],
                  {q2: Rational(3, 7)})
    wrong = arm.jacobian(q, frame="body").as_mutable()
    wrong[4, 1] += q2 * sin(q3) / 5
    assert not _agree(wrong, _raw_products(arm, q, "body")[1], q, [4], {q2: Rational(3, 7)})


def test_the_ring_path_gathers_sums_of_angles_of_parallel_joints():
    """A planar 3R arm: the end point is ``sum_k l_k (cos, sin)(q1 + ... + qk)``."""
    arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                 Twist.rotation([0, 0, 1], point=[2, 0, 0]),
                 Twist.rotation([0, 0, 1], point=[3, 0, 0])], Transform.translation([4, 0, 0]))
    p = arm.forward(q).p
    assert p[0] == 2 * cos(q1) + cos(q1 + q2) + cos(q1 + q2 + q3)
    assert p[1] == 2 * sin(q1) + sin(q1 + q2) + sin(q1 + q2 + q3)
    # an axis turned the other way: the angle is a difference
    flipped = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                     Twist.rotation([0, 0, -1], point=[1, 0, 0])], Transform.translation([2, 0, 0]))
    assert flipped.forward([q1, q2]).p[0] == cos(q1) + cos(q1 - q2)


def test_chains_outside_the_ring_path_take_the_stepwise_one(rph):
    """Helical joints, numbers or repeated symbols as joint values: the general path, same answers."""
    from screwsym.motion import _poe

    assert _poe.fast_forward(rph.twists, rph.home, q) is None  # the helical joint
    arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                 Twist.rotation([0, 0, 1], point=[1, 0, 0])], Transform.translation([2, 0, 0]))
    assert _poe.fast_forward(arm.twists, arm.home, (q1, q1)) is None
    assert expand(arm.forward([q1, q1]).p[0] - cos(q1) - 2 * cos(q1) ** 2 + 1) == 0
    assert arm.forward([pi / 2, 0]).p.T == Matrix([[0, 2, 0]])


def test_a_generic_6r_with_symbolic_lengths_and_offsets():
    """Issue 23 item 2: DH links with symbolic a_i, d_i (UR-like twists alpha), tidied in seconds.

    Equal to the plain product at exact points with rational geometry.
    """
    a = symbols("a1:7", real=True)
    d = symbols("d1:7", real=True)
    alpha = [pi / 2, 0, 0, pi / 2, -pi / 2, 0]
    arm = Chain.from_dh([(a[i], alpha[i], d[i], 0) for i in range(6)])
    qs = symbols("q1:7", real=True)
    T, J = arm.forward(qs).matrix, arm.jacobian(qs)
    T0, J0 = _raw_products(arm, qs)
    geometry = {x: Rational(k + 2, 7) for k, x in enumerate(a + d)}
    assert _agree(T, T0, qs, [5], geometry) and _agree(J, J0, qs, [6], geometry)
    assert count_ops(T) <= count_ops(T0) and count_ops(J) <= count_ops(J0)


@pytest.mark.slow
def test_the_ring_path_on_the_franka_panda():
    """The Panda (panda.urdf, link0 to hand_tcp, pi/12 angles): equal to the plain products, and no
    larger than the stepwise tidied forms were before issue 23 (count_ops 1608 and 1652)."""
    pytest.importorskip("defusedxml")
    from pathlib import Path

    urdf = Path(__file__).resolve().parent.parent / "data" / "urdf" / "panda.urdf"
    arm = Chain.from_urdf(urdf, "panda_link0", "panda_hand_tcp", angles="pi/12")
    qs = symbols("q1:8", real=True)
    T, J = arm.forward(qs).matrix, arm.jacobian(qs)
    T0, J0 = _raw_products(arm, qs)
    assert _agree(T, T0, qs, [7]) and _agree(J, J0, qs, [8])
    assert count_ops(T) <= 1608 and count_ops(J) <= 1652


# ---------------------------------------------------------------- symbolic twist angles (issue 23 item 2)
def _circle_geometry(alphas, others, seed):
    """Exact values of the geometry: ``(cos, sin)`` of each twist angle at a rational point of the
    circle, ``((1 - t^2)/(1 + t^2), 2 t/(1 + t^2))`` for a random rational ``t``, and rationals."""
    import random

    rng = random.Random(seed)
    point = {}
    for al in alphas:
        t = Rational(rng.randint(-9, 9), rng.randint(1, 9))
        point[cos(al)] = (1 - t**2) / (1 + t**2)
        point[sin(al)] = 2 * t / (1 + t**2)
    for x in others:
        point[x] = Rational(rng.randint(-9, 9), rng.randint(1, 9))
    return point


def _chain_at(chain, point):
    """The chain with its geometry put in (sums of the twist angles expanded first): numeric twists."""
    from sympy import expand_trig

    def put(m):
        return m.applyfunc(lambda e: expand(expand_trig(e)).xreplace(point))

    return Chain([Twist(put(t.omega), put(t.v_O)) for t in chain.twists],
                 Transform._new(put(chain.home.R), put(chain.home.p)))


def _agree_at_geometry(ours, chain, qs, seeds, frame="space", forward=True):
    """``ours`` (T(q) or the Jacobian) equal to the plain products of the chain with the geometry
    put in, at exact points of the circle for the twist angles and the joint angles."""
    from sympy import expand_trig

    for seed in seeds:
        point = _circle_geometry(*seed)
        T0, J0 = _raw_products(_chain_at(chain, point), qs, frame)
        ref = T0 if forward else J0
        mine = ours.applyfunc(lambda e, point=point: expand(expand_trig(e)).xreplace(point))
        if not _agree(mine, ref, qs, [seed[2]]):
            return False
    return True


def test_symbolic_twist_angles_take_the_ring_path_and_equal_the_products():
    """A 3R DH arm with symbolic a_i, alpha_i, d_i: the ring path (not the stepwise one) gives
    T(q) and both Jacobians equal to the plain products at exact points of the circles, and the
    comparison rejects a result with one sign flipped."""
    from screwsym.motion import _poe

    a = symbols("a1:4", real=True)
    d = symbols("d1:4", real=True)
    al = symbols("alpha1:4", real=True)
    arm = Chain.from_dh([(a[i], al[i], d[i], 0) for i in range(3)])
    assert _poe.fast_forward(arm.twists, arm.home, q) is not None
    assert _poe.fast_space_jacobian(arm.twists, arm.home, q) is not None
    assert _poe.fast_body_jacobian(arm.body_twists(), arm.home, q) is not None
    T, Js, Jb = arm.forward(q).matrix, arm.jacobian(q), arm.jacobian(q, frame="body")
    seeds = [(al, a + d, 11), (al, a + d, 12)]
    assert _agree_at_geometry(T, arm, q, seeds)
    assert _agree_at_geometry(Js, arm, q, seeds, forward=False)
    assert _agree_at_geometry(Jb, arm, q, seeds[:1], "body", forward=False)
    # the forward kinematics is the product of the table's rows, exactly
    from screwsym.motion.dh import dh_row_transform

    rows = ImmutableMatrix.eye(4)
    for i in range(3):
        rows = rows * dh_row_transform(a[i], al[i], d[i], q[i]).matrix
    assert expand(T - rows) == ImmutableMatrix.zeros(4, 4)
    # one sign flipped in one term: rejected
    wrong = T.as_mutable()
    term = wrong[0, 3].args[0]
    wrong[0, 3] -= 2 * term
    assert not _agree_at_geometry(wrong, arm, q, seeds[:1])
    wrong = Js.as_mutable()
    wrong[4, 2] = -wrong[4, 2]
    assert not _agree_at_geometry(wrong, arm, q, seeds[:1], forward=False)


def test_the_unit_axis_is_decided_modulo_the_circles():
    """``omega . omega = 1`` holds by ``sin^2 + cos^2 = 1`` only: revolute; off the circle: stepwise."""
    from screwsym.motion import _poe

    b = symbols("beta", real=True)
    turned = Twist([0, -sin(b), cos(b)], [0, 0, 0])
    assert _poe._joint_kind(turned.omega, turned.v_O) is None  # expand alone cannot see it
    assert _poe.fast_forward([turned], Transform.identity(), (q1,)) is not None
    long = Twist([0, -2 * sin(b), cos(b)], [0, 0, 0])  # |omega| != 1
    assert _poe.fast_forward([long], Transform.identity(), (q1,)) is None
    skew = Twist([0, -sin(b), cos(b)], [0, sin(b), cos(b)])  # omega . v = cos^2 - sin^2 != 0
    assert _poe.fast_forward([skew], Transform.identity(), (q1,)) is None
    T = Chain([turned], Transform.translation([0, 0, 1])).forward([q1])
    T0 = exp6(turned, q1) @ Transform.translation([0, 0, 1])
    assert is_exactly_zero(T.matrix - T0.matrix)
    wrong = T.matrix.as_mutable()
    wrong[1, 3] += sin(b) ** 2 + cos(b) ** 2 - 1 + sin(q1) / 7
    assert not is_exactly_zero(wrong - T0.matrix)


def test_numeric_twist_angles_keep_the_former_ring_path():
    """No sine or cosine of a symbol in the geometry: no circles, the product of exponentials as before."""
    from screwsym.motion import _poe
    from screwsym.motion.chain import ur5

    arm = ur5()
    engine = _poe._engine(arm.twists, arm.home, symbols("q1:7", real=True))
    assert engine.bases == [] and engine._walk() is None


@pytest.mark.slow
def test_a_generic_6r_with_every_dh_parameter_symbolic():
    """Issue 23 item 2: a_i, d_i and alpha_i all symbols (18), symbolic joint angles: T(q) and
    J_s(q) by the ring, equal to the plain products at exact points, no larger than plain SymPy's
    untidied products (count_ops 61,594 and 60,022, benchmarks/bench_scaling.py)."""
    a = symbols("a1:7", real=True)
    d = symbols("d1:7", real=True)
    al = symbols("alpha1:7", real=True)
    arm = Chain.from_dh([(a[i], al[i], d[i], 0) for i in range(6)])
    qs = symbols("q1:7", real=True)
    T, J = arm.forward(qs).matrix, arm.jacobian(qs)
    assert _agree_at_geometry(T, arm, qs, [(al, a + d, 21)])
    assert _agree_at_geometry(J, arm, qs, [(al, a + d, 22)], forward=False)
    assert count_ops(T) <= 61594 and count_ops(J) <= 60022
    wrong = J.as_mutable()
    wrong[3, 5] = -wrong[3, 5]
    assert not _agree_at_geometry(wrong, arm, qs, [(al, a + d, 22)], forward=False)


# ---------------------------------------------------------------- the dynamics in the chain's ring
C15, S15 = (sqrt6 := Rational(1, 4) * 6 ** Rational(1, 2)) + 2 ** Rational(1, 2) / 4, \
    sqrt6 - 2 ** Rational(1, 2) / 4  # cos 15 and sin 15 degrees, in Q(sqrt 2, sqrt 3)


def _on_circle_at(e, q, ts):
    """``e`` exactly at the rational points ``cos q_i = (1 - t^2)/(1 + t^2)``, ``sin q_i = 2t/(1 + t^2)``."""
    from sympy import expand_trig, sqrt

    # the general path writes |w| = sqrt(c15**2 + s15**2) inside the angles: a number, 1
    e = e.replace(lambda a: a.is_Pow and a.is_number and a.exp == Rational(1, 2) and not a.base.is_Rational,
                  lambda a: sqrt(expand(a.base)))
    e = expand_trig(e)
    values = {}
    for qi, t in zip(q, ts, strict=True):
        values[cos(qi)] = (1 - t**2) / (1 + t**2)
        values[sin(qi)] = 2 * t / (1 + t**2)
    return expand(e.xreplace(values))


def _same_at_points(A, B, q, rounds=2):
    """Entry by entry equal at seeded rational points of the circles (SymPy merges the roots,
    so ``expand`` of a number of Q(sqrt 2, sqrt 3) is zero exactly when it is)."""
    rng = np.random.default_rng(7)
    for _ in range(rounds):
        ts = [Rational(int(a), int(b)) for a, b in zip(rng.integers(-9, 9, len(q)), rng.integers(1, 7, len(q)),
                                                        strict=True)]
        if any(_on_circle_at(a - b, q, ts) != 0 for a, b in zip(A, B, strict=True)):
            return False
    return True


@pytest.fixture(scope="module")
def arm15():
    """Two revolute joints and a prismatic one at 15 degrees (the geometry in Q(sqrt 2, sqrt 3)), one prismatic, general inertias."""
    from screwsym import SpatialInertia

    inertia = ImmutableMatrix([[Rational(1, 5), Rational(1, 100), 0], [Rational(1, 100), Rational(1, 4), 0],
                               [0, 0, Rational(3, 10)]])
    twists = [Twist.rotation([0, 0, 1], point=[0, 0, 0]),
              Twist.rotation([C15, S15, 0], point=[0, 0, Rational(1, 2)]),
              Twist.translation([0, C15, S15])]
    bodies = [SpatialInertia(Rational(2 + i, 2), [Rational(i, 3), Rational(1, 5), C15 / 2], inertia)
              for i in range(3)]
    return Chain(twists, inertias=bodies)


@pytest.mark.slow
def test_the_ring_mass_matrix_equals_the_recursion_on_expressions(arm15, monkeypatch):
    from screwsym.motion import _ring_dynamics, dynamics

    x = symbols("x1:4", real=True)
    ring_H = arm15.mass_matrix(x)
    assert _ring_dynamics.ring_mass_matrix(arm15.twists, Transform.identity(),
                                           [dynamics._params(b) for b in arm15.inertias], x) is not None
    monkeypatch.setattr(dynamics, "ring_mass_matrix", lambda *args: None)
    general_H = arm15.mass_matrix(x)
    assert ring_H.is_symmetric()
    assert _same_at_points(list(ring_H), list(general_H), x)
    # the comparison tells a wrong entry apart
    wrong = list(ring_H)
    wrong[5] += 2 ** Rational(1, 2) / 1000
    assert not _same_at_points(wrong, list(general_H), x)
    assert sum(count_ops(e) for e in ring_H) <= sum(count_ops(e) for e in general_H)


@pytest.mark.slow
def test_the_ring_inverse_dynamics_equals_the_recursion_on_expressions(arm15, monkeypatch):
    from screwsym.motion import dynamics

    x = symbols("x1:4", real=True)
    u = symbols("u1:4", real=True)
    a = symbols("a1:4", real=True)
    g = symbols("g", positive=True)
    gravity = [0, g / 3, -g]
    ring_tau = arm15.inverse_dynamics(x, u, a, gravity)
    monkeypatch.setattr(dynamics, "ring_rnea", lambda *args: None)
    general_tau = arm15.inverse_dynamics(x, u, a, gravity)
    assert _same_at_points(list(ring_tau), list(general_tau), x, rounds=1)
    assert not _same_at_points([ring_tau[0] + u[1] * a[2] / 7] + list(ring_tau[1:]), list(general_tau), x, rounds=1)


def test_the_ring_dynamics_leave_other_chains_to_the_general_path(rph):
    """A helical joint, or numbers for q: no ring (None), the recursions on expressions answer."""
    from screwsym import SpatialInertia
    from screwsym.motion._ring_dynamics import ring_mass_matrix

    body = SpatialInertia.point_mass(1, [1, 0, 0])
    params = [(body.mass, body.first_moment, body.inertia_about([0, 0, 0]))] * 3
    assert ring_mass_matrix(rph.twists, Transform.identity(), params, q) is None
    line = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])], inertias=[body])
    assert ring_mass_matrix(line.twists, Transform.identity(), params[:1], [Rational(1, 2)]) is None
    assert line.mass_matrix([pi / 3]) == Matrix([[1]])


@pytest.mark.slow
def test_the_ring_dynamics_at_a_pose_of_15_degree_multiples(arm15, monkeypatch):
    """Numbers for q whose sines and cosines are in Q(sqrt 2, sqrt 3) (the Kinova's poses of
    issue 33) stay in the ring: the same exact numbers as the recursion on expressions."""
    from screwsym.motion import _ring_dynamics, dynamics

    pose = [pi / 4, pi / 12, Rational(1, 3)]  # the third joint is prismatic: a length
    rates = symbols("u1:4", real=True)
    params = [dynamics._params(b) for b in arm15.inertias]
    assert _ring_dynamics.ring_mass_matrix(arm15.twists, Transform.identity(), params, pose) is not None
    assert _ring_dynamics.ring_mass_matrix(arm15.twists, Transform.identity(), params,
                                           [Rational(1, 2), 0, 0]) is None  # cos(1/2): no root form
    H, tau = arm15.mass_matrix(pose), arm15.inverse_dynamics(pose, rates, [0, 0, 0])
    monkeypatch.setattr(dynamics, "ring_mass_matrix", lambda *args: None)
    monkeypatch.setattr(dynamics, "ring_rnea", lambda *args: None)
    H2, tau2 = arm15.mass_matrix(pose), arm15.inverse_dynamics(pose, rates, [0, 0, 0])
    # SymPy merges products of roots, so expand decides equality in Q(sqrt 2, sqrt 3)[u]
    assert all(expand(a - b) == 0 for a, b in zip(H, H2, strict=True))
    assert all(expand(a - b) == 0 for a, b in zip(tau, tau2, strict=True))
    assert expand(H[0, 1] + 2 ** Rational(1, 2) / 10**6 - H2[0, 1]) != 0
