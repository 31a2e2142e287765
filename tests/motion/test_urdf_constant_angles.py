"""Robot files whose angles are no multiple of pi/12 (the SO-100's ``-1.8``): exact and bounded.

Their sines and cosines are transcendental numbers; the reader keeps them as generators on
their circles (``constant_trig_normal``), checks each link's inertia where the file writes it,
and bounds its arithmetic by a budget.  The arms themselves are compared with pinocchio in
tests/crosscheck/test_example_robot_data.py.
"""

from __future__ import annotations

import random
import warnings

import pytest
from sympy import Float, ImmutableMatrix, Rational, cos, pi, sin, sqrt, symbols

from screwsym import Chain, Twist, exp6
from screwsym.motion.angles import constant_trig_normal
from screwsym.motion.urdf import read_urdf

A, B = Rational(9, 5), Rational(157079, 100000)


def _same_number(x, y):
    return abs(float((x - y).evalf(50))) < 1e-40


def test_constant_trig_normal_is_the_same_number_in_a_flat_form():
    rng = random.Random(33)
    gens = [cos(A), sin(A), cos(B), sin(B), cos(2 * B), sin(2 * B), sqrt(2), Rational(1, 3)]
    for _ in range(20):
        e = sum(rng.randint(-3, 3) * rng.choice(gens) * rng.choice(gens) * rng.choice(gens)
                for _ in range(4)) * (rng.choice(gens) + rng.choice(gens))
        [flat] = constant_trig_normal([e])
        assert _same_number(flat, e)
        assert not _same_number(flat + Rational(1, 10**6), e)  # the check can fail
        # flat: no s**2 of a pair (reduced on the circle), no cos/sin of 2B (B's multiple)
        assert not flat.has(sin(A) ** 2, sin(B) ** 2, cos(2 * B), sin(2 * B))
    # a rotation's R^T R reduces to the identity exactly
    R = ImmutableMatrix([[cos(A), -sin(A), 0], [sin(A), cos(A), 0], [0, 0, 1]])
    Ry = ImmutableMatrix([[cos(B), 0, sin(B)], [0, 1, 0], [-sin(B), 0, cos(B)]])
    M = R * Ry
    assert constant_trig_normal(list(M.T * M)) == [1, 0, 0, 0, 1, 0, 0, 0, 1]
    assert constant_trig_normal([Rational(1, 2), sqrt(2)]) is None  # nothing to do
    assert constant_trig_normal([cos(A) / (1 + sin(A))]) is None    # not a polynomial
    assert constant_trig_normal([cos(A) * Float(0.5)]) is None      # a float


def _chain_urdf(n, rpy, inertia="0.01 0 0 0.02 0 0.03"):
    ixx, ixy, ixz, iyy, iyz, izz = inertia.split()
    links = "".join(
        f'<link name="l{i}"><inertial><origin xyz="0.01 0 0" rpy="{rpy(i)}"/><mass value="1"/>'
        f'<inertia ixx="{ixx}" ixy="{ixy}" ixz="{ixz}" iyy="{iyy}" iyz="{iyz}" izz="{izz}"/>'
        f'</inertial></link>' for i in range(n + 1))
    joints = "".join(
        f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        f'<origin xyz="0.1 0.02 0.3" rpy="{rpy(i)}"/><axis xyz="0 0 1"/></joint>' for i in range(n))
    return f'<robot name="r">{links}{joints}</robot>'


def test_a_huge_file_stops_with_the_budget_error():
    pytest.importorskip("defusedxml")  # the URDF reader's parser (extra "urdf")
    # 14 joints, three new angles each (no multiple of pi/12): the exact frames grow without end
    text = _chain_urdf(14, lambda i: f"{0.1 + 0.01 * i:.2f} {0.2 + 0.013 * i:.3f} {0.3 + 0.017 * i:.3f}")
    with pytest.raises(ValueError, match=r"from_urdf: .*budget=200000 units"):
        Chain.from_urdf(text, budget=200_000)
    with pytest.raises(TypeError, match="budget"):
        Chain.from_urdf(text, budget=1.5)
    # a small file with such angles is read within the same budget, exactly
    small = Chain.from_urdf(_chain_urdf(2, lambda i: "-1.8 0 0.3"), budget=200_000)
    assert small.twists[1].omega.has(cos(Rational(9, 5)))


def test_an_unphysical_inertia_is_refused_where_the_file_writes_it():
    pytest.importorskip("defusedxml")  # the URDF reader's parser (extra "urdf")
    # principal moments 1, 1, 3 break the triangle inequality; turned by -1.8 about x
    bad = _chain_urdf(2, lambda i: "-1.8 0 0", inertia="1 0 0 1 0 3")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ValueError, match=r"<link name='l1'>: <inertial> <inertia>: .*triangle"):
            Chain.from_urdf(bad, inertias=True)
        good = Chain.from_urdf(_chain_urdf(2, lambda i: "-1.8 0 0"), inertias=True)
    # the turned inertia is the file's, R I R^T, exactly: its trace and determinant are kept
    I = good.inertias[0].inertia
    assert _same_number(I.trace(), Rational(6, 100))
    assert _same_number(I.det(), Rational(6, 10**6))


def test_a_float_displacement_on_constant_sines_is_its_exact_value():
    t = Twist.rotation([0, cos(A), sin(A)], point=[Rational(1, 10), 0, sin(B)])
    theta = symbols("theta", real=True)
    exact = exp6(t, theta).matrix.subs(theta, Rational(3, 10))
    at_float = exp6(t, Float("0.3")).matrix
    assert all(e.is_Float or e.is_Integer for e in at_float)
    gap = max(abs(float((a - b).evalf(30))) for a, b in zip(at_float, exact, strict=True))
    assert gap < 1e-14
    assert max(abs(float((a - b).evalf(30))) for a, b in zip(exp6(t, Float("0.31")).matrix, exact, strict=True)) > 1e-3


def test_so_arm_reading_keeps_the_files_angles():
    pytest.importorskip("defusedxml")  # the URDF reader's parser (extra "urdf")
    text = _chain_urdf(3, lambda i: "1.57079 0 -1.8" if i % 2 else "0 3.14158 0")
    chain = read_urdf(text)
    # 1.57079 is pi/2 truncated, not a printing of it: kept exact, never pi/2
    assert not any(t.matrix.has(pi) for t in chain.twists)
    assert any(t.matrix.has(cos(B)) for t in chain.twists)


def test_spatial_inertia_decides_signs_of_constant_sines_by_certified_evaluation():
    from screwsym.core.inertia import SpatialInertia

    Rx = ImmutableMatrix([[1, 0, 0], [0, cos(A), -sin(A)], [0, sin(A), cos(A)]])
    Ry = ImmutableMatrix([[cos(B), 0, sin(B)], [0, 1, 0], [-sin(B), 0, cos(B)]])
    R = Rx * Ry

    def turned(*moments):
        return R * ImmutableMatrix.diag(*moments) * R.T

    body = SpatialInertia(2, [0, 0, 0], turned(1, 2, 2))          # physical: accepted
    assert _same_number(body.inertia.trace(), 5)
    SpatialInertia(2, [0, 0, 0], turned(0, 1, 1))                  # a rod: det = 0, not syntactically
    with pytest.raises(ValueError, match="triangle"):
        SpatialInertia(2, [0, 0, 0], turned(1, 1, 3))              # 1 + 1 < 3
    with pytest.raises(ValueError, match="positive semi-definite"):
        SpatialInertia(2, [0, 0, 0], turned(1, -Rational(1, 10**20), 1))  # a tiny negative moment


def _urdf_15(k):
    """A seeded k-joint URDF whose joint origins are turned by multiples of 15 degrees (as
    benchmarks/bench_scaling.py's ``urdf_15``), with inertias."""
    rnd = random.Random(1)
    parts = ['<robot name="r15">', '<link name="l0"/>']
    for i in range(1, k + 1):
        rpy = " ".join(repr(rnd.choice([1, 2, 3, 4, 5, -1, -2, 6, 0]) * 3.141592653589793 / 12)
                       for _ in range(3))
        xyz = " ".join(str(rnd.choice([0, 0.1, 0.25, -0.3, 0.05])) for _ in range(3))
        parts.append(f'<link name="l{i}"><inertial><origin xyz="0.01 0.02 0.03" '
                     f'rpy="0 {3.141592653589793 / 12!r} 0"/><mass value="1.5"/><inertia ixx="0.1" '
                     'ixy="0.01" ixz="0" iyy="0.2" iyz="0" izz="0.3"/></inertial></link>')
        parts.append(f'<joint name="j{i}" type="revolute"><parent link="l{i - 1}"/>'
                     f'<child link="l{i}"/><origin xyz="{xyz}" rpy="{rpy}"/><axis xyz="0 0 1"/></joint>')
    parts.append("</robot>")
    return "\n".join(parts)


def _circle_point(q, ts):
    point = {}
    for x, t in zip(q, ts, strict=True):
        point[cos(x)] = (1 - t**2) / (1 + t**2)
        point[sin(x)] = 2 * t / (1 + t**2)
    return point


def _at_circle_points(M, q, ts):
    """``M`` at the rational points ``cos q_i = (1 - t^2)/(1 + t^2)``, ``sin q_i = 2t/(1 + t^2)``:
    numbers in Q(sqrt 2, sqrt 3), each in its normal form (exact)."""
    from sympy import expand_trig

    from screwsym.algebra.numberfield import surd_quotient

    point = _circle_point(q, ts)
    return [surd_quotient(expand_trig(e).xreplace(point)) for e in M]


def _program_at_circle_points(program, values, q, ts):
    """The program run at the same points, assignment by assignment, each value in normal form."""
    from screwsym.algebra.numberfield import surd_quotient

    env = {**_circle_point(q, ts), **values}
    for t, e in program.assignments:
        env[t] = surd_quotient(e.xreplace(env))
    return [surd_quotient(e.xreplace(env)) for e in program.outputs]


def test_newton_euler_programs_build_at_15_degrees_and_equal_the_closed_forms():
    """The programs' frames hold quotients by n . n in Q(sqrt 2, sqrt 3) (newton_euler._links):
    in normal form (surd_quotient) a 3-joint program builds in about a second (it took over
    20 s at 2 joints), and it computes exactly the closed forms."""
    pytest.importorskip("defusedxml")  # the URDF reader's parser (extra "urdf")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        chain = Chain.from_urdf(_urdf_15(2), inertias=True)
    q = symbols("q1:3", real=True)
    qd, qdd = symbols("qd1:3", real=True), symbols("qdd1:3", real=True)
    M = chain.dynamics_program("mass_matrix")
    tau = chain.dynamics_program("inverse_dynamics", gravity=[0, 0, -Rational(981, 100)])
    closed_M = chain.mass_matrix(q)
    closed_tau = chain.inverse_dynamics(q, qd, qdd, gravity=[0, 0, -Rational(981, 100)])
    ts = [(Rational(1, 3), Rational(-2, 5)), (Rational(3, 7), Rational(5, 2))]
    rates = {**dict(zip(qd, (Rational(1, 2), -3), strict=True)),
             **dict(zip(qdd, (2, Rational(-1, 7)), strict=True))}
    for t in ts[:1]:
        a = _program_at_circle_points(M, {}, q, t)
        b = _at_circle_points(closed_M, q, t)
        assert None not in a and a == b
        a = _program_at_circle_points(tau, rates, q, t)
        b = _at_circle_points(closed_tau.xreplace(rates), q, t)
        assert None not in a and a == b
    # the comparison can fail: another point of the circles differs
    assert _at_circle_points(closed_M, q, ts[0]) != _at_circle_points(closed_M, q, ts[1])


def test_surd_quotient_is_the_inverse_in_the_field():
    from screwsym.algebra.numberfield import surd_normal, surd_quotient

    rng = random.Random(7)
    roots = [1, sqrt(2), sqrt(3), sqrt(6), sqrt(5)]
    for _ in range(20):
        x = sum(Rational(rng.randint(-9, 9), rng.randint(1, 5)) * r for r in rng.sample(roots, 3))
        if x == 0:
            continue
        y = Rational(rng.randint(1, 9), 7) + rng.choice(roots)
        inv = surd_quotient(y / x)
        assert surd_normal(inv * x) == surd_normal(y)           # y/x times x is y, exactly
        assert surd_normal((inv + Rational(1, 10**9)) * x) != surd_normal(y)  # can fail
    assert surd_quotient(1 / (1 + pi)) is None               # not a root of a rational
