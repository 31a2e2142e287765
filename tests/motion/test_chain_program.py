"""``Chain.kinematics_program``: FK and the space Jacobian as straight-line programs.

Checked against the closed forms of ``Chain.forward`` / ``Chain.jacobian`` exactly (the circle's
rational parametrisation, then ``cancel``), against modern_robotics' ``FKinSpace`` and
``JacobianSpace`` numerically (an independent implementation), and for a size linear in the joints.
"""

from __future__ import annotations

import random

import numpy as np
import pytest
from sympy import Rational, cancel, cos, pi, sin, symbols

from screwsym import Chain, Transform, Twist
from screwsym.motion.chain import ur5


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
