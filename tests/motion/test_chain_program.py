"""``Chain.kinematics_program``: FK and the space Jacobian as straight-line programs.

Checked against the closed forms of ``Chain.forward`` / ``Chain.jacobian`` exactly (the circle's
rational parametrisation, then ``cancel``), against modern_robotics' ``FKinSpace`` and
``JacobianSpace`` numerically (an independent implementation), and for a size linear in the joints.
"""

from __future__ import annotations

import random

import numpy as np
import pytest
from sympy import Rational, cancel, cos, expand_trig, pi, sin, symbols

from screwsym import Chain, Transform, Twist
from screwsym.motion.chain import ur5
from tests.motion.test_poe import _plain  # FK + J as plain SymPy products of exp6, untidied


def _spatial(k: int) -> Chain:
    axes = [(0, 0, 1), (0, 1, 0), (1, 0, 0)]
    return Chain([Twist.rotation(list(axes[i % 3]), point=[Rational(i, 2), Rational(i % 2, 3), Rational(i, 5)])
                  for i in range(k)], Transform.translation([1, Rational(1, 3), 0]))


def _vanishes(d, q, t):
    circle = {f(qi): e for qi, ti in zip(q, t, strict=True)
              for f, e in ((cos, (1 - ti**2) / (1 + ti**2)), (sin, 2 * ti / (1 + ti**2)))}
    return cancel(d.xreplace(circle)) == 0


def test_the_programs_equal_the_closed_forms_exactly():
    a = symbols("a", real=True)
    # a revolute joint, a prismatic one, a helical one (pitch 1/2) and symbolic geometry
    chain = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]), Twist.translation([1, 0, 0]),
                   Twist.screw_motion([0, 1, 0], point=[a, 0, 0], pitch=Rational(1, 2))],
                  Transform.translation([a, 1, 0]))
    fk, jac = chain.kinematics_program(), chain.kinematics_program("jacobian")
    q = list(fk.arguments[0])
    t = symbols("t1:4", real=True)
    T, J = chain.forward(q).matrix, chain.jacobian(q)
    assert fk.expressions().shape == (4, 4) and jac.expressions().shape == (6, 3)
    assert all(_vanishes(x, q, t) for x in fk.expressions() - T)
    assert all(_vanishes(x, q, t) for x in jac.expressions() - J)
    # the check tells a wrong entry apart
    wrong = fk.expressions()[0, 3] + sin(q[0]) / 1000
    assert not _vanishes(wrong - T[0, 3], q, t)


def test_the_programs_agree_with_modern_robotics():
    mr = pytest.importorskip("modern_robotics")
    chain = ur5()
    fk, jac = chain.kinematics_program(), chain.kinematics_program("jacobian")
    Slist = np.array([[float(x) for x in tw.matrix] for tw in chain.twists]).T
    M = np.array(chain.home.matrix.evalf(), dtype=float)
    rng = random.Random(7)
    for _ in range(3):
        qv = [rng.uniform(-3, 3) for _ in range(6)]
        ours_T = np.array(fk.evaluate(qv).evalf(), dtype=float)
        ours_J = np.array(jac.evaluate(qv).evalf(), dtype=float)
        assert np.allclose(ours_T, mr.FKinSpace(M, Slist, qv), atol=1e-12)
        assert np.allclose(ours_J, mr.JacobianSpace(Slist, qv), atol=1e-12)
    # a wrong program (one joint value off) is told apart
    assert not np.allclose(np.array(fk.evaluate([qv[0] + 1e-6, *qv[1:]]).evalf(), dtype=float),
                           mr.FKinSpace(M, Slist, qv), atol=1e-12)


def test_the_programs_grow_linearly_with_the_joints():
    sizes = []
    for k in range(4, 10):
        fk, jac = _spatial(k).kinematics_program(), _spatial(k).kinematics_program("jacobian")
        ops_fk, ops_j = fk.operations(), jac.operations()
        sizes.append((ops_fk.multiplications + ops_fk.additions, ops_j.multiplications + ops_j.additions))
        assert ops_fk.functions == ops_j.functions == 2 * k  # one cos and one sin per joint
    steps = [(b[0] - a[0], b[1] - a[1]) for a, b in zip(sizes, sizes[1:], strict=False)]
    # a bounded cost per added joint (the axes cycle z, y, x: the step repeats every 3 joints)
    assert max(s for s, _ in steps) <= 60 and max(s for _, s in steps) <= 80, steps


def test_a_number_pose_and_bad_what():
    fk = _spatial(2).kinematics_program()
    assert fk.evaluate([0, 0]) == _spatial(2).forward([0, 0]).matrix
    assert fk.evaluate([pi / 2, 0]) == _spatial(2).forward([pi / 2, 0]).matrix
    with pytest.raises(ValueError, match="what"):
        _spatial(2).kinematics_program("body")


def test_a_15_degree_robot_file_agrees_with_modern_robotics():
    # joint origins turned by multiples of 15 degrees: the constants live in Q(sqrt 2, sqrt 3)
    pytest.importorskip("defusedxml")
    mr = pytest.importorskip("modern_robotics")
    import math
    import warnings

    parts = ['<robot name="r15">', '<link name="l0"/>']
    rpys = [(1, 2, 5), (6, -2, 4), (-2, -2, 1)]
    for i, (a, b, c) in enumerate(rpys, start=1):
        rpy = " ".join(repr(k * math.pi / 12) for k in (a, b, c))
        parts.append(f'<link name="l{i}"/><joint name="j{i}" type="revolute"><parent link="l{i - 1}"/>'
                     f'<child link="l{i}"/><origin xyz="0.1 0 0.25" rpy="{rpy}"/><axis xyz="0 0 1"/>'
                     '<limit lower="-3" upper="3" effort="1" velocity="1"/></joint>')
    parts.append("</robot>")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        chain = Chain.from_urdf("\n".join(parts), angles="pi/12")
    fk, jac = chain.kinematics_program(), chain.kinematics_program("jacobian")
    Slist = np.array([[float(x) for x in tw.matrix] for tw in chain.twists]).T
    M = np.array(chain.home.matrix.evalf(), dtype=float)
    qv = [0.3, -1.2, 2.0]
    assert np.allclose(np.array(fk.evaluate(qv).evalf(), dtype=float), mr.FKinSpace(M, Slist, qv), atol=1e-12)
    assert np.allclose(np.array(jac.evaluate(qv).evalf(), dtype=float), mr.JacobianSpace(Slist, qv), atol=1e-12)
    assert not np.allclose(np.array(jac.evaluate(qv).evalf(), dtype=float), mr.JacobianSpace(Slist, [0.301, -1.2, 2.0]),
                           atol=1e-12)


# ---------------------------------------------------------------- forward / jacobian, form="product"
def _circle_point(q, rng):
    """cos and sin of each joint value at a rational point of the circle (exact)."""
    point = {}
    for qi in q:
        t = Rational(rng.randint(1, 9), rng.randint(1, 9))
        point[cos(qi)], point[sin(qi)] = (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)
    return point


def _single_angles(T, J, q) -> bool:
    return (T.atoms(cos, sin) | J.atoms(cos, sin)) <= {f(x) for x in q for f in (cos, sin)}


def test_the_product_form_equals_the_tidy_form_exactly():
    a = symbols("a", real=True)
    # revolute, prismatic, helical (pitch 1/2), a non-unit axis and symbolic geometry
    chain = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]), Twist.translation([1, 0, 0]),
                   Twist.screw_motion([0, 1, 0], point=[a, 0, 0], pitch=Rational(1, 2)),
                   Twist([0, 0, 2], [0, 1, 0])], Transform.translation([a, 1, 0]))
    q = symbols("q1:5", real=True)
    t = symbols("t1:5", real=True)
    pairs = [(chain.forward(q, form="product").matrix, chain.forward(q).matrix),
             (chain.jacobian(q, form="product"), chain.jacobian(q)),
             (chain.jacobian(q, "body", form="product"), chain.jacobian(q, "body"))]
    for product, tidy in pairs:
        assert product.shape == tidy.shape
        # cos(2 q4) of the axis of length 2 expanded to cos(q4), sin(q4) first
        assert all(_vanishes(expand_trig(x), q, t) for x in product - tidy)
    # the check tells a wrong entry apart
    wrong = pairs[1][0][3, 1] + cos(q[0]) / 1000
    assert not _vanishes(expand_trig(wrong - pairs[1][1][3, 1]), q, t)


def test_the_product_form_of_a_spatial_chain_is_no_larger_than_plain_sympys():
    from sympy import count_ops, srepr

    from screwsym.motion import _kinematics_program as kp

    k = 7
    chain = Chain(_spatial(k).twists)  # home = identity, as in the plain product below
    q = symbols(f"q1:{k + 1}", real=True)
    kp._RECENT.clear()
    T, J = chain.forward(q, form="product").matrix, chain.jacobian(q, form="product")
    kp._RECENT.clear()
    J2 = chain.jacobian(q, form="product")  # the other order: the same expressions
    assert srepr(J2) == srepr(J) and srepr(chain.forward(q, form="product").matrix) == srepr(T)
    tidy_T, tidy_J = chain.forward(q).matrix, chain.jacobian(q)
    # the tidy form gathers sums of angles, the product form keeps the product of the joints'
    assert not _single_angles(tidy_T, tidy_J, q) and _single_angles(T, J, q)
    # exactly equal at seeded rational points of the circles (the tidy form's sums expanded)
    rng = random.Random(11)
    for _ in range(2):
        point = _circle_point(q, rng)
        for x, y in ((T, tidy_T), (J, tidy_J)):
            assert x.xreplace(point) == y.applyfunc(lambda e: expand_trig(e)).xreplace(point)
    wrong = J[4, 5] + sin(q[2]) / 10**6
    assert wrong.xreplace(point) != expand_trig(tidy_J[4, 5]).xreplace(point)
    # no larger than the plain SymPy product of the same exponentials (tests/motion/test_poe.py)
    ours = [T[i, j] for i in range(3) for j in range(3)] + [T[i, 3] for i in range(3)] \
        + [J[r, c] for c in range(k) for r in range(6)]
    theirs = _plain(chain, q)
    assert sum(map(count_ops, ours)) <= sum(map(count_ops, theirs))


def test_the_product_form_with_numbers_and_a_bad_form():
    chain = _spatial(3)
    assert chain.forward([pi / 2, 0, pi], form="product").matrix == chain.forward([pi / 2, 0, pi]).matrix
    assert chain.jacobian([pi / 2, 0, pi], form="product") == chain.jacobian([pi / 2, 0, pi])
    with pytest.raises(ValueError, match="form"):
        chain.forward([0, 0, 0], form="expanded")
    with pytest.raises(ValueError, match="form"):
        chain.jacobian([0, 0, 0], form="nested")
    # bounded like the default form: past the budget, a ValueError naming the method
    q = symbols("u1:4", real=True)
    with pytest.raises(ValueError, match="forward: the exact arithmetic needs more than budget=10"):
        chain.forward(q, form="product", budget=10)
    with pytest.raises(ValueError, match="jacobian: the exact arithmetic needs more than budget=10"):
        chain.jacobian(q, form="product", budget=10)
