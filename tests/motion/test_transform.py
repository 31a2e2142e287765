"""Transform: SE(3) with exact values, the ray-order adjoint and apply."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
from _motions import quaternion_rotation, random_transform, rational_vector
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import (
    Float,
    ImmutableMatrix,
    Matrix,
    Rational,
    cancel,
    cos,
    latex,
    pi,
    sin,
    sqrt,
    symbols,
    trigsimp,
)

from screwsym import (
    LineVector,
    Screw,
    Transform,
    Twist,
    Wrench,
    pitch,
    power,
    reciprocal_product,
    shift_origin,
    vector,
)
from screwsym.core.formulas import cross_matrix
from screwsym.motion.transform import adjoint_matrix, skew

t, u = symbols("theta phi", real=True)


def zero_matrix(m) -> bool:
    """Exact zero of every entry after trigsimp and cancel (a checker that can fail)."""
    return all(cancel(trigsimp(e)) == 0 for e in m)


def test_zero_matrix_checker_rejects_a_wrong_identity():
    assert not zero_matrix(Matrix([trigsimp(1) - 1 + t]))
    assert zero_matrix(Matrix([t * (t + 1) - t**2 - t]))


# ------------------------------------------------------------------ constructors
@pytest.mark.slow
def test_symbolic_rotation_is_exactly_a_rotation():
    T = Transform.rotation([1, 2, 2], t, point=vector("c"))
    R = T.R
    assert zero_matrix(R.T * R - ImmutableMatrix.eye(3))
    assert trigsimp(R.det()) == 1
    # the axis is fixed (R a = a) and the points of the line stay put
    assert zero_matrix(R * Matrix([1, 2, 2]) - Matrix([1, 2, 2]))
    c = vector("c")
    assert zero_matrix(T.apply(c + 3 * Matrix([1, 2, 2])) - (c + 3 * Matrix([1, 2, 2])))


def test_rotation_is_right_handed_and_exact():
    assert Transform.rotation([0, 0, 1], pi / 2).apply([1, 0, 0]) == Matrix([0, 1, 0])
    R = Transform.rotation([1, 1, 1], 2 * pi / 3).R  # the cyclic permutation x -> y -> z
    assert R == Matrix([[0, 0, 1], [1, 0, 0], [0, 1, 0]])
    R = Transform.rotation([0, 0, 1], pi / 6).R
    assert R[0, 0] == sqrt(3) / 2 and R[1, 0] == Rational(1, 2)


def test_identity_translation_and_from_matrix_round_trip():
    rng = np.random.default_rng(1)
    for _ in range(20):
        T = random_transform(rng)
        assert Transform.from_matrix(T.matrix) == T
        assert T.func(*T.args) == T
    assert Transform.identity().matrix == ImmutableMatrix.eye(4)
    assert Transform.translation([1, 2, 3]).p == Matrix([1, 2, 3])
    assert Transform.from_matrix(np.eye(4)).equals(Transform.identity())


# -------------------------------------------------------------------- the group
def test_composition_inverse_and_associativity_are_exact():
    rng = np.random.default_rng(2)
    for _ in range(20):
        A, B, C = (random_transform(rng) for _ in range(3))
        assert (A @ B) @ C == A @ (B @ C)
        assert A @ A.inverse() == Transform.identity()
        assert A.inverse() @ A == Transform.identity()
        assert (A @ B).matrix == A.matrix * B.matrix
        assert (A @ B).inverse() == B.inverse() @ A.inverse()


def test_adjoint_is_a_homomorphism_exactly_and_symbolically():
    rng = np.random.default_rng(3)
    for _ in range(20):
        A, B = random_transform(rng), random_transform(rng)
        assert (A @ B).adjoint() == A.adjoint() * B.adjoint()
        assert A.inverse().adjoint() == A.adjoint().inv()
    A = Transform.rotation([0, 0, 1], t, point=[1, 0, 0])
    B = Transform.rotation([1, 0, 0], u, point=[0, 2, 0])
    assert zero_matrix((A @ B).adjoint() - A.adjoint() * B.adjoint())
    assert adjoint_matrix(A) == A.adjoint()


# ------------------------------------------------------------------------ apply
def test_apply_keeps_the_kind():
    T = Transform.rotation([0, 0, 1], pi / 2, point=[1, 0, 0])
    line = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    assert isinstance(T.apply(line), LineVector)
    assert isinstance(T.apply(Twist([0, 0, 1], [0, 0, 0])), Twist)
    assert isinstance(T.apply(Wrench([0, 0, 1], [0, 0, 0])), Wrench)
    assert type(T.apply(Screw([1, 0, 0], [1, 0, 0]))) is Screw
    assert T.apply(Transform.identity()) == T
    assert T.apply(line) == LineVector.from_axis([1, 0, 0], [0, 1, 0])  # x axis onto x = 1


def test_apply_a_line_is_the_line_through_the_moved_points():
    rng = np.random.default_rng(4)
    for _ in range(20):
        T = random_transform(rng)
        A, B = rational_vector(rng), rational_vector(rng)
        if A == B:
            continue
        moved = T.apply(LineVector.through(A, B))
        assert moved == LineVector.through(T.apply(A), T.apply(B))


def test_apply_with_generic_symbols_keeps_pitch_and_reciprocal_product():
    """Pitch (1.34) and the reciprocal product (1.45) are invariant under motions."""
    T = Transform.rotation([0, 0, 1], t, point=vector("c"))
    s1, s2 = Screw(vector("S"), vector("S0")), Screw(vector("P"), vector("P0"))
    assert cancel(trigsimp(pitch(T.apply(s1)) - pitch(s1))) == 0
    residual = reciprocal_product(T.apply(s1), T.apply(s2)) - reciprocal_product(s1, s2)
    assert trigsimp(residual.expand()) == 0
    # the check can fail: a wrench moved and a twist left alone do not keep their power
    tw, wr = Twist(vector("w"), vector("v")), Wrench(vector("f"), vector("C"))
    assert trigsimp((power(tw, T.apply(wr)) - power(tw, wr)).expand()) != 0


def test_translation_by_minus_a_is_the_origin_shift_of_the_book():
    """Moving a screw by -a is viewing it from A: (1.32)."""
    s, a = Screw(vector("S"), vector("S0")), vector("a")
    assert Transform.translation(-a).apply(s).expand() == shift_origin(s, a).expand()


def test_twist_moves_with_the_velocity_field():
    """The moved twist gives the moved body's velocities: v'(T x) = R v(x)."""
    rng = np.random.default_rng(5)
    for _ in range(20):
        T = random_transform(rng)
        tw = Twist(rational_vector(rng), rational_vector(rng))
        x = Matrix(rational_vector(rng))
        assert T.apply(tw).velocity_at(T.apply(x)) == T.R * tw.velocity_at(x)


def test_direction_and_point():
    T = Transform.translation([1, 2, 3])
    assert T.apply([1, 0, 0]) == Matrix([2, 2, 3])
    assert T.apply([1, 0, 0], direction=True) == Matrix([1, 0, 0])


# -------------------------------------------------------------------- validation
@pytest.mark.parametrize(
    "R, match",
    [
        ([[1, 0, 0], [0, 1, 0], [0, 0, -1]], r"R: expected a rotation \(det R = 1\), got det R = -1"),
        ([[2, 0, 0], [0, 1, 0], [0, 0, 1]], r"R: expected an orthonormal matrix \(R\^T R = I\)"),
        ([[1, 0], [0, 1]], r"R: expected a 3x3 matrix, got shape \(2, 2\)"),
    ],
)
def test_not_a_rotation_is_refused(R, match):
    with pytest.raises(ValueError, match=match):
        Transform(R, [0, 0, 0])


def test_symbolic_rotation_part_refused_only_when_provably_wrong():
    x = symbols("x", real=True)
    Transform([[x, 0, 0], [0, 1, 0], [0, 0, 1]], [0, 0, 0])  # orthonormal for x = +-1
    with pytest.raises(ValueError, match="orthonormal"):
        Transform([[x, 1, 0], [0, 1, 0], [0, 0, 1]], [0, 0, 0])  # (R^T R)[1, 1] = 2


def test_quaternion_rotations_are_accepted_and_a_perturbed_one_is_not():
    R = quaternion_rotation(1, 2, 3, 4)
    Transform(R, [0, 0, 0])
    with pytest.raises(ValueError, match="orthonormal"):
        Transform(R + Matrix.diag(Rational(1, 10**9), 0, 0), [0, 0, 0])


def test_bad_arguments_are_refused_with_the_argument_named():
    with pytest.raises(TypeError, match=r"R\[0, 0\]: expected a real number .*strings"):
        Transform([["1", 0, 0], [0, 1, 0], [0, 0, 1]], [0, 0, 0])
    with pytest.raises(ValueError, match=r"p: expected a 3-vector, got shape \(2,\)"):
        Transform(ImmutableMatrix.eye(3), [0, 0])
    with pytest.raises(ValueError, match=r"direction: expected a non-zero direction, got \[0, 0, 0\]"):
        Transform.rotation([0, 0, 0], 1)
    with pytest.raises(TypeError, match="angle: expected a real number"):
        Transform.rotation([0, 0, 1], "pi")
    with pytest.raises(ValueError, match=r"M: expected the last row \[0, 0, 0, 1\]"):
        Transform.from_matrix(2 * ImmutableMatrix.eye(4))
    with pytest.raises(ValueError, match=r"M: expected a 4x4 matrix, got shape \(3, 3\)"):
        Transform.from_matrix(ImmutableMatrix.eye(3))
    with pytest.raises(TypeError, match="obj: expected a point or direction"):
        Transform.identity().apply([1, 0, 0, 0, 0, 0])
    with pytest.raises(TypeError, match="compose transforms with '@'"):
        Transform.identity() * Transform.identity()
    with pytest.raises(TypeError, match="cannot compose a ImmutableDenseMatrix with a Transform"):
        ImmutableMatrix.eye(4) @ Transform.identity()
    with pytest.raises(TypeError, match="other: expected a Transform, got int"):
        Transform.identity().equals(1)
    with pytest.raises(TypeError, match="T: expected a Transform, got int"):
        adjoint_matrix(1)


# ------------------------------------------------------------- SymPy integration
def test_args_subs_pickle_diff_evalf_and_printing():
    T = Transform.rotation([0, 0, 1], t, point=[1, 0, 0])
    assert T.func(*T.args) == T
    assert T.subs(t, 0).equals(Transform.identity())
    assert pickle.loads(pickle.dumps(T)) == T
    with pytest.raises(TypeError, match="subs: strings are never evaluated"):
        T.subs(t, "0")
    payload = "__import__('builtins').__setattr__('screwsym_was_here', 1)"
    with pytest.raises(TypeError, match="applyfunc: strings are never evaluated"):
        T.applyfunc(lambda e: payload)  # Matrix.applyfunc would parse the result as code
    assert not hasattr(__import__("builtins"), "screwsym_was_here")
    d = T.diff(t)
    assert d.shape == (4, 4) and d[0, 0] == -Matrix([[__import__("sympy").sin(t)]])[0]
    n = Transform.rotation([0, 0, 1], 1).evalf(20)
    assert isinstance(n, Transform) and n.R[0, 0].has(Float)
    assert str(Transform.identity()) == (
        "Transform(R=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], p=[0, 0, 0])"
    )
    assert latex(Transform.translation([1, 0, 0])).startswith(r"\left[\begin{matrix}")
    assert T.free_symbols == {t}


def test_equals_decides_and_can_say_no():
    A = Transform.rotation([0, 0, 1], t)
    assert A.equals(Transform.rotation([0, 0, -1], -t)) is True
    assert A.equals(Transform.rotation([0, 0, 1], -t)) is not True
    assert Transform.identity().equals(Transform.translation([0, 0, 1])) is False


def test_skew_is_the_checked_cross_matrix():
    # the identity [a]x b = a x b is checked once, in tests/core/test_formulas.py
    a = vector("a")
    assert skew(a) == cross_matrix(a)
    assert skew([1, 2, 3]) == cross_matrix(ImmutableMatrix([1, 2, 3]))
    with pytest.raises(ValueError, match=r"v: expected a 3-vector, got shape \(2,\)"):
        skew([1, 2])
    with pytest.raises(TypeError, match="v: expected a 3-vector .*, got str 'abc'"):
        skew("abc")


# ------------------------------------------------------------ property tests
_ints = st.integers(-6, 6)
_quaternions = st.tuples(_ints, _ints, _ints, _ints).filter(lambda q: any(q))
_rationals = st.fractions(min_value=-5, max_value=5, max_denominator=9)
_vectors = st.lists(_rationals, min_size=3, max_size=3).map(
    lambda v: [Rational(x.numerator, x.denominator) for x in v]
)
_transforms = st.builds(
    lambda q, p: Transform(quaternion_rotation(*q), p), _quaternions, _vectors
)


@settings(max_examples=30, deadline=None)
@given(_transforms, _transforms, _vectors, _vectors)
def test_property_apply_is_an_action_and_keeps_the_reciprocal_product(A, B, S, S0):
    s = Screw(S, S0)
    assert A.apply(B.apply(s)) == (A @ B).apply(s)
    assert A.inverse().apply(A.apply(s)) == s
    w = Wrench(S0, S)
    assert reciprocal_product(A.apply(s), A.apply(w)) == reciprocal_product(s, w)


def test_a_symbolic_forward_kinematics_rotation_is_accepted():
    from screwsym import Chain

    q = symbols("q1:5", real=True)
    chain = Chain([Twist.rotation(a, point=[i, 0, 1]) for i, a in
                   enumerate([[0, 0, 1], [0, 1, 0], [1, 0, 0], [0, 1, 0]])])
    M = chain.forward(q).matrix
    assert Transform.from_matrix(M).matrix == M


def test_from_matrix_accepts_a_last_row_that_is_provably_0001():
    # only a provable violation raises (the float policy of screwsym.core.decide), as for R
    one = sin(t) ** 2 + cos(t) ** 2  # 1 for every real t, though not literally 1
    M = [[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, one]]
    assert Transform.from_matrix(M) == Transform.translation([5, 0, 0])


def test_from_matrix_accepts_a_float_last_row_off_0001_by_rounding():
    residue = [[1.0, 0, 0, 5], [0, 1.0, 0, 0], [0, 0, 1.0, 0], [1e-30, 0, 0, 1.0]]
    assert Transform.from_matrix(residue).p.T == ImmutableMatrix([[5, 0, 0]])


def test_from_matrix_refuses_a_provably_wrong_last_row():
    y = symbols("y", real=True)
    for last in ([0, 0, 0, 2], [0, 0, 0, y**2 + 2], [0, 0, 1e-3, 1.0], [0, 0, 0, 1 + 1e-9]):
        M = ImmutableMatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], last])
        with pytest.raises(ValueError, match=r"T: expected the last row \[0, 0, 0, 1\]"):
            Transform.from_matrix(M, name="T")


def test_entries_beyond_the_size_limit_are_not_decided(monkeypatch):
    """Beyond ROTATION_CHECK_OPS a symbolic entry is accepted undecided (documented)."""
    import screwsym.motion.transform as validation

    y = symbols("y", positive=True)
    wrong = [[1, 2 * y, 0], [0, 1, 0], [0, 0, 1]]  # (R^T R)[0, 1] = 2 y != 0: provably wrong
    with pytest.raises(ValueError, match="orthonormal"):
        Transform(wrong, [0, 0, 0])
    monkeypatch.setattr(validation, "ROTATION_CHECK_OPS", 0)
    Transform(wrong, [0, 0, 0])  # ...but too large to look at under a limit of 0


def test_lambdify_takes_a_transform():
    import numpy as np
    from sympy import symbols

    from screwsym import lambdify

    t, d = symbols("t d", real=True)
    T = Transform.rotation([0, 0, 1], t, point=[1, 0, 0]) @ Transform.translation([0, 0, d])
    f = lambdify([t, d], T, backend="numpy")
    got = f(np.array([0.3, -1.2]), np.array([2.0, 0.5]))
    assert got.shape == (2, 4, 4)
    for k, (tv, dv) in enumerate([(0.3, 2.0), (-1.2, 0.5)]):
        want = np.array(T.matrix.subs({t: tv, d: dv}).evalf(), dtype=float)
        np.testing.assert_allclose(got[k], want, rtol=1e-13, atol=1e-15)


def test_a_provable_symbolic_reflection_is_refused_as_a_rotation():
    # issue 20: entries (1-u^2)/(1+u^2), 2u/(1+u^2) are orthonormal for every u, and det = -1
    # by cancel: it was accepted, and a Chain built on it mirrored
    from sympy import Symbol

    from screwsym import Chain, Twist

    u = Symbol("u", real=True)
    a, b = (1 - u**2) / (1 + u**2), 2 * u / (1 + u**2)
    mirror = [[a, b, 0], [b, -a, 0], [0, 0, 1]]
    with pytest.raises(ValueError, match=r"R: expected a rotation \(det R = 1\), got det R = -1"):
        Transform(mirror, [0, 0, 0])
    with pytest.raises(ValueError, match="got det R = -1"):
        Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])], home=Transform(mirror, [0, 0, 0]))
    # the same entries as a rotation (det = +1 by cancel) are accepted
    turn = Transform([[a, -b, 0], [b, a, 0], [0, 0, 1]], [0, 0, 0])
    assert turn.R[1, 0] == b


def test_equals_of_float_motions_follows_the_float_policy():
    # issue 20: T.inverse().inverse().equals(T) was False for a float transform
    T = Transform.rotation([1, 2, 2], 0.7, point=[1.0, -2.0, 3.0])
    assert T.inverse().inverse() != T  # rounding: not the same floats ...
    assert T.inverse().inverse().equals(T) is True  # ... but the same motion
    assert T.equals(Transform.rotation([1, 2, 2], 0.7 + 1e-9, point=[1.0, -2.0, 3.0])) is False
    big = Transform.translation([1e12, 0, 0]) @ T
    assert big.inverse().inverse().equals(big) is True
    assert big.equals(Transform.translation([1e12 + 1e3, 0, 0]) @ T) is False  # tau = 2^-40


@pytest.mark.parametrize("flag", ["no", 1, None, 0.0])
def test_apply_direction_is_a_boolean(flag):
    # issue 20: direction="no" was taken as direction=True
    T = Transform.translation([1, 0, 0])
    with pytest.raises(TypeError, match=r"direction: expected True or False, got"):
        T.apply([1, 0, 0], direction=flag)
    assert T.apply([1, 0, 0], direction=False) == Matrix([2, 0, 0])


def test_an_axis_such_as_1_over_y_is_normalised_not_refused_with_an_internal_name():
    # issue 20: unit() and Transform.rotation() refused [1/y, 1, 0] with "S[0]" / "v[0]": the
    # normalised entry 1/(y sqrt(1 + y^-2)) is real wherever it is defined
    from sympy import Symbol, cancel

    from screwsym import Screw, unit

    y = Symbol("y", real=True)
    u = unit(Screw([1 / y, 1, 0], [0, 0, 0])).S
    assert cancel(u.dot(u) - 1) == 0
    R = Transform.rotation([1 / y, 1, 0], t).R
    assert zero_matrix(R * Matrix([1 / y, 1, 0]) - Matrix([1 / y, 1, 0]))
    # a direction that is not real is refused under the user's name
    with pytest.raises(ValueError, match=r"direction\[0\]: expected a real value, got sqrt\(y\)"):
        Transform.rotation([sqrt(y), 1, 0], t)


def test_a_reflection_written_with_sin_and_cos_is_refused():
    """det R = -(cos t**2 + sin t**2) = -1 for every t: decided exactly on the circle
    (screwsym.algebra.circle), by Transform and Transform.from_matrix; the rotation with the
    same entries but +1 is accepted (the check can say yes), and so are angle sums."""
    from sympy import Matrix, cos, sin, symbols

    t, u = symbols("t u", real=True)
    reflections = [
        [[-1, 0, 0], [0, cos(t), -sin(t)], [0, sin(t), cos(t)]],
        [[cos(t), sin(t), 0], [sin(t), -cos(t), 0], [0, 0, 1]],
        [[cos(t + u), -sin(t + u), 0], [sin(t + u), cos(t + u), 0], [0, 0, -1]],
        [[cos(2 * t), sin(2 * t), 0], [sin(2 * t), -cos(2 * t), 0], [0, 0, 1]],
    ]
    for R in reflections:
        with pytest.raises(ValueError, match=r"R: expected a rotation \(det R = 1\), got det R = -1 "
                           r"\(a reflection for every value of its angles"):
            Transform(R, [0, 0, 0])
        M = Matrix(R).row_join(Matrix([1, 2, 3])).col_join(Matrix([[0, 0, 0, 1]]))
        with pytest.raises(ValueError, match=r"M\[:3, :3\]: expected a rotation \(det R = 1\)"):
            Transform.from_matrix(M)
        flipped = Matrix(R)
        flipped[:, 0] = -flipped[:, 0]  # det +1: a rotation
        assert Transform(flipped, [0, 0, 0]).R == flipped


def test_a_float32_rotation_is_judged_at_its_precision():
    """A rotation in numpy.float32 is orthonormal to a single's precision (2**-24), which the
    double's tolerance refused; it is judged with the float policy at 24 bits (2**-11 on the
    entries of R^T R - I).  A matrix off by 1e-2 is still refused."""
    import numpy as np

    c, s = np.cos(0.3), np.sin(0.3)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]], dtype=np.float32)
    T = Transform(R, [0, 0, 0])
    assert abs(float(T.R[0, 0]) - c) < 1e-7
    M = np.eye(4, dtype=np.float32)
    M[:3, :3] = R
    assert Transform.from_matrix(M).R == T.R
    with pytest.raises(ValueError, match="expected an orthonormal matrix"):
        Transform(R * np.float32(1.01), [0, 0, 0])
    with pytest.raises(ValueError, match="expected an orthonormal matrix"):
        Transform(np.array(R, dtype=np.float64), [0, 0, 0])  # as doubles, a single's error is too big
