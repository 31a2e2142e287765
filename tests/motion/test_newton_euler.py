"""The customised Newton–Euler programs (issue 34, item 1) against the closed forms and pinocchio.

Each program (inverse dynamics, the mass matrix by composite rigid bodies, gravity,
Coriolis, bias) is evaluated at random states and compared with the closed forms of
screwsym.motion.dynamics (exactly on a small chain, in floats on random chains of revolute
and prismatic joints) and with pinocchio's ``rnea``, ``crba``,
``computeGeneralizedGravity`` and ``computeCoriolisMatrix`` (test-only) on the UR5 of
Modern Robotics, Corke's PUMA 560 and the Panda.  The operation counts are those the
benchmark reports against ARM's 224 multiplications and 174 additions for the PUMA 560
(Murray & Neuman 1984, as tabulated by Corke).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from _dynamics import mr_ur5_chain, random_chain
from _robots import panda, pin_model, puma560
from sympy import Float, ImmutableMatrix, Rational, pi, radsimp, symbols, trigsimp

from screwsym import Chain, SpatialInertia, Twist, lambdify
from screwsym.motion.newton_euler import Operations, Program, dynamics_program

G = [0.0, 0.0, -9.81]


def _f(x):
    return [Float(float(v)) for v in x]


def _close(a, b) -> bool:
    a, b = np.array(a, dtype=float), np.array(b, dtype=float)
    return a.shape == b.shape and np.allclose(a, b, rtol=1e-9, atol=1e-9)


def _programs_agree_with_closed_forms(chain, rng) -> bool:
    n = chain.n_joints
    q, qd, qdd = (_f(x) for x in rng.uniform(-2, 2, size=(3, n)))
    g = _f(G)
    ok = _close(dynamics_program(chain, gravity=g).evaluate(q, qd, qdd),
                chain.inverse_dynamics(q, qd, qdd, g))
    ok &= _close(dynamics_program(chain, "mass_matrix").evaluate(q), chain.mass_matrix(q))
    ok &= _close(dynamics_program(chain, "gravity", gravity=g).evaluate(q),
                 chain.gravity_torques(q, g))
    zero = [0] * n
    ok &= _close(dynamics_program(chain, "coriolis").evaluate(q, qd),
                 chain.inverse_dynamics(q, qd, zero, [0, 0, 0]))
    ok &= _close(dynamics_program(chain, "bias", gravity=g).evaluate(q, qd),
                 chain.inverse_dynamics(q, qd, zero, g))
    return bool(ok)


@pytest.mark.parametrize("case", [0, 1, pytest.param(2, marks=pytest.mark.slow),
                                  pytest.param(3, marks=pytest.mark.slow)])
def test_programs_equal_the_closed_forms_on_random_chains(case):
    rng = np.random.default_rng([3434, case])
    chain = random_chain(rng, 2 + case)  # revolute and prismatic joints, rational bodies
    assert _programs_agree_with_closed_forms(chain, rng)


def test_the_comparison_rejects_a_wrong_program():
    rng = np.random.default_rng([3434, 1])
    chain = random_chain(rng, 3)
    bodies = list(chain.inertias)
    b = bodies[2]
    bodies[2] = SpatialInertia(b.mass * Rational(101, 100), b.com, b.inertia)
    wrong = Chain(chain.twists, chain.home, bodies)
    n = chain.n_joints
    q, qd, qdd = (_f(x) for x in rng.uniform(-2, 2, size=(3, n)))
    assert not _close(dynamics_program(wrong, gravity=_f(G)).evaluate(q, qd, qdd),
                      chain.inverse_dynamics(q, qd, qdd, _f(G)))


def test_exactly_the_closed_form_on_a_spatial_3r_arm():
    a, m = symbols("a m", positive=True)
    arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                 Twist.rotation([0, 1, 0], point=[0, 0, 1]),
                 Twist.translation([1, 0, 0])],
                inertias=[SpatialInertia.point_mass(1, [0, 1, 0]),
                          SpatialInertia(m, [a, 0, 1], ImmutableMatrix.diag(1, 2, 2)),
                          SpatialInertia.point_mass(2, [2, 0, 1])])
    q = [pi / 3, pi / 4, Rational(1, 2)]
    qd, qdd = [1, -2, Rational(1, 3)], [Rational(1, 2), 3, -1]
    gsym = symbols("g", positive=True)
    gravity = [0, 0, -gsym]
    ours = dynamics_program(arm, gravity=gravity).evaluate(q, qd, qdd)
    theirs = arm.inverse_dynamics(q, qd, qdd, gravity)
    assert all(radsimp((x - y).expand()) == 0 for x, y in zip(ours, theirs, strict=True))
    H = dynamics_program(arm, "mass_matrix").evaluate(q)
    assert all(radsimp((x - y).expand()) == 0 for x, y in zip(H, arm.mass_matrix(q), strict=True))
    # and a symbolic state: the closed form in q itself
    qs = symbols("q1:4", real=True)
    diff = dynamics_program(arm, "mass_matrix").expressions() - arm.mass_matrix(qs)
    assert all(trigsimp(x.expand()) == 0 for x in diff)


@pytest.mark.parametrize("name", ["ur5", "puma560", pytest.param("panda", marks=pytest.mark.slow)])
def test_programs_against_pinocchio(name):
    pin = pytest.importorskip("pinocchio")
    chain = {"ur5": mr_ur5_chain, "puma560": puma560, "panda": panda}[name]()
    model = pin_model(pin, chain, G)
    data = model.createData()
    n = chain.n_joints
    tau_p = dynamics_program(chain, gravity=G)
    fns = [lambdify(list(p.arguments), p, "numpy") for p in (
        tau_p, dynamics_program(chain, "mass_matrix"), dynamics_program(chain, "gravity", G),
        dynamics_program(chain, "coriolis"))]
    rng = np.random.default_rng(34)
    for _ in range(5):
        q, qd, qdd = rng.uniform(-2, 2, size=(3, n))
        np.testing.assert_allclose(fns[0](q, qd, qdd), pin.rnea(model, data, q, qd, qdd),
                                   rtol=1e-9, atol=1e-9)
        M = np.triu(pin.crba(model, data, q))
        np.testing.assert_allclose(fns[1](q), M + np.triu(M, 1).T, rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(fns[2](q), pin.computeGeneralizedGravity(model, data, q),
                                   rtol=1e-9, atol=1e-9)
        C = pin.computeCoriolisMatrix(model, data, q, qd)
        np.testing.assert_allclose(fns[3](q, qd), C @ qd, rtol=1e-9, atol=1e-9)
    # a program for another arm's numbers is caught
    q, qd, qdd = rng.uniform(-2, 2, size=(3, n))
    wrong = lambdify(list(tau_p.arguments), dynamics_program(chain, gravity=[0, 0, -9.0]), "numpy")
    assert not np.allclose(wrong(q, qd, qdd), pin.rnea(model, data, q, qd, qdd), rtol=1e-9)


def test_operation_counts():
    pendulum = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])],
                     inertias=[SpatialInertia.point_mass(1, [1, 0, 0])])
    p = dynamics_program(pendulum, gravity=[0, -10, 0])
    # c1 = cos(q1); a1y = 10*c1; fb1y = a1y + qdd1: tau = fb1y
    assert p.operations() == Operations(1, 1, 1)
    assert [str(t) for t, _ in p.assignments] == ["c1", "a1y", "fb1y"]
    # the PUMA 560 within 1.2x of ARM's 224 multiplications and 174 additions
    ops = dynamics_program(puma560(), gravity=[0, 0, -Rational(981, 100)]).operations()
    assert ops.multiplications <= 1.2 * 224 and ops.additions <= 1.2 * 174


def test_program_is_immutable_and_checks_its_input():
    p = dynamics_program(mr_ur5_chain(), "gravity", G)
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.outputs = ImmutableMatrix([0])  # type: ignore[misc]
    with pytest.raises(ValueError, match="what"):
        dynamics_program(mr_ur5_chain(), "torques")
    with pytest.raises(ValueError, match="values"):
        p.evaluate([0, 0])
    with pytest.raises(ValueError, match="inertias"):
        dynamics_program(Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])]))
    assert isinstance(p, Program)


def test_generated_code_follows_the_program():
    """lambdify compiles the program's assignments as they are (no names of the program in it)."""
    from screwsym.codegen import c_source

    p = dynamics_program(mr_ur5_chain(), gravity=G)
    src = c_source(list(p.arguments), p, names=["q", "qd", "qdd"])
    assert "fb6" not in src and src.count("= ") >= len(p.assignments)


def test_armature_and_friction_terms_against_pinocchio():
    pin = pytest.importorskip("pinocchio")
    chain = mr_ur5_chain()
    Ia = [Rational(k, 10) for k in range(1, 7)]
    Fv, Fc = [Rational(1, 2)] * 6, [Rational(1, 3)] * 6
    model = pin_model(pin, chain, G)
    model.armature = np.array([float(x) for x in Ia])
    data = model.createData()
    tau = lambdify(list(dynamics_program(chain).arguments[:3]),
                   dynamics_program(chain, gravity=G, armature=Ia, viscous=Fv, coulomb=Fc), "numpy")
    H = lambdify(list(dynamics_program(chain, "mass_matrix").arguments),
                 dynamics_program(chain, "mass_matrix", armature=Ia), "numpy")
    rng = np.random.default_rng(35)
    q, qd, qdd = rng.uniform(-2, 2, size=(3, 6))
    friction = 0.5 * qd + np.sign(qd) / 3
    np.testing.assert_allclose(tau(q, qd, qdd), pin.rnea(model, data, q, qd, qdd) + friction,
                               rtol=1e-9, atol=1e-9)
    M = np.triu(pin.crba(model, data, q))
    np.testing.assert_allclose(H(q), M + np.triu(M, 1).T, rtol=1e-9, atol=1e-9)
    assert not np.allclose(tau(q, qd, qdd), pin.rnea(model, data, q, qd, qdd), rtol=1e-6)
    with pytest.raises(ValueError, match="viscous"):
        dynamics_program(chain, viscous=[1, 2])


# ----------------------------------------------------------------- in the base parameters


def _spatial_rrp(a):
    return Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                  Twist.rotation([0, 1, 0], point=[0, 0, 1]),
                  Twist.translation([1, 0, 0])],
                 inertias=[SpatialInertia.point_mass(1, [0, 1, 0]),
                           SpatialInertia(3, [a, 0, 1], ImmutableMatrix.diag(1, 2, 2)),
                           SpatialInertia.point_mass(2, [2, 0, 1])])


def _is_zero(e) -> bool:
    return trigsimp(e.expand()) == 0


@pytest.mark.parametrize("extras", [[], ["armature", "viscous", "coulomb"]])
def test_base_parameter_program_is_the_base_regressor_exactly(extras):
    """Issue 34 item 2: tau(q, qd, qdd, beta) == Y_b beta identically (symbolic q, qd, qdd, beta)."""
    from screwsym.motion.parameters import base_parameters, base_symbols

    arm = _spatial_rrp(Rational(1, 2))
    gsym = symbols("g", positive=True)
    g = [0, 0, -gsym]
    p = arm.dynamics_program(gravity=g, parameters="base", extras=extras)
    q, qd, qdd, beta = p.arguments
    assert beta == base_symbols(arm, g, extras)
    assert len(beta) == len(base_parameters(arm, g, extras).columns)
    Yb = arm.base_regressor(q, qd, qdd, g, extras)
    assert all(_is_zero(x) for x in p.expressions() - Yb * beta)
    # the check catches a program in one base parameter too many (the last one doubled)
    wrong = p.expressions().xreplace({beta[-1]: 2 * beta[-1]})
    assert not all(_is_zero(x) for x in wrong - Yb * beta)
    # and it is the chain's own inverse dynamics at its own base parameters
    if not extras:
        from screwsym.motion.parameters import base_values

        mine = dict(zip(beta, base_values(arm, g), strict=True))
        ours = p.expressions().xreplace(mine)
        theirs = dynamics_program(arm, gravity=g).expressions()
        assert all(_is_zero(x) for x in ours - theirs)


def test_mass_matrix_gravity_and_bias_in_the_base_parameters():
    from screwsym.motion.parameters import base_values

    arm = _spatial_rrp(Rational(1, 2))
    g = [0, 0, -Rational(981, 100)]
    beta = base_values(arm, g)
    for what in ("mass_matrix", "gravity", "coriolis", "bias"):
        p = arm.dynamics_program(what, g, parameters="base")
        ours = p.expressions().xreplace(dict(zip(p.arguments[-1], beta, strict=True)))
        theirs = dynamics_program(arm, what, g).expressions()
        assert all(_is_zero(x) for x in ours - theirs), what
        # a perturbed beta is caught
        off = dict(zip(p.arguments[-1], [b + k + 1 for k, b in enumerate(beta)], strict=True))
        assert not all(_is_zero(x) for x in p.expressions().xreplace(off) - theirs), what
    # in the standard parameters: Y pi, with the regressor's own program
    from screwsym.motion.newton_euler import regressor_program

    p = dynamics_program(arm, gravity=g, parameters="standard")
    q_, qd_, qdd_, pis = p.arguments
    Y = regressor_program(arm, g).expressions()
    assert all(_is_zero(x) for x in p.expressions() - Y * pis)


def test_base_parameter_program_against_pinocchio_on_the_ur5():
    """Generated (C and NumPy) in beta, at beta of the UR5's inertias: pinocchio's rnea; a perturbed beta is not."""
    pin = pytest.importorskip("pinocchio")
    from screwsym.motion.parameters import base_values
    from screwsym.numeric.dynamics import dynamics_functions

    chain = mr_ur5_chain()
    g = [0, 0, -Rational(981, 100)]
    model = pin_model(pin, chain, G)
    data = model.createData()
    p = chain.dynamics_program(gravity=g, parameters="base")
    beta = np.array(base_values(chain, g), dtype=float).ravel()
    assert len(beta) == 36 == len(p.arguments[3])
    standard = dynamics_program(chain, gravity=g)
    assert p.operations().multiplications < 2 * standard.operations().multiplications
    rng = np.random.default_rng(342)
    q, qd, qdd = rng.uniform(-2, 2, size=(3, 20, 6))
    expected = np.array([pin.rnea(model, data, *s) for s in zip(q, qd, qdd, strict=True)])
    fs = [lambdify(list(p.arguments), p, "numpy"), dynamics_functions(chain, G, parameters="base").inverse_dynamics]
    for f in fs:
        np.testing.assert_allclose(f(q, qd, qdd, beta), expected, rtol=1e-9, atol=1e-9)
        for k in (0, 17, 35):
            wrong = beta.copy()
            wrong[k] *= 1.001
            assert not np.allclose(f(q, qd, qdd, wrong), expected, rtol=1e-9, atol=1e-9)
    fb = dynamics_functions(chain, G, parameters="base")
    M = np.triu(pin.crba(model, data, q[0]))
    np.testing.assert_allclose(fb.mass_matrix(q[0], beta), M + np.triu(M, 1).T, rtol=1e-9, atol=1e-9)
    # and in the 60 standard parameters, at the chain's own numbers
    fs = dynamics_functions(chain, G, "numpy", parameters="standard")
    pi_ = np.array(chain.parameters(numbers=True), dtype=float).ravel()
    np.testing.assert_allclose(fs.inverse_dynamics(q, qd, qdd, pi_), expected, rtol=1e-9, atol=1e-9)
    assert not np.allclose(fs.inverse_dynamics(q, qd, qdd, pi_ * 1.001), expected, rtol=1e-9, atol=1e-9)


def test_base_parameter_program_checks_its_input():
    arm = _spatial_rrp(1)
    with pytest.raises(ValueError, match="parameters"):
        dynamics_program(arm, parameters="minimal")
    with pytest.raises(ValueError, match="extras="):
        arm.dynamics_program(parameters="base", armature=[1, 1, 1])
    with pytest.raises(ValueError, match="base"):
        dynamics_program(arm, parameters="base")
    with pytest.raises(ValueError, match="extras"):
        dynamics_program(arm, extras=["armature"])
    with pytest.raises(ValueError, match="names of inertial parameters"):
        m_1 = symbols("m_1", real=True)
        dynamics_program(Chain([Twist.rotation([0, 0, 1], point=[m_1, 0, 0])]), parameters="standard")
    # no inertias needed in the parameters
    bare = Chain(arm.twists)
    assert bare.dynamics_program(parameters="base").arguments[3] == arm.dynamics_program(parameters="base").arguments[3]


def test_rx90_in_symbolic_parameters_against_symoros_counts():
    """The Staubli RX-90 with general symbolic inertial parameters, per state, within 1.1x of SYMORO.

    SYMORO's generated inertia matrix (composite links, with rotor inertias) and inverse
    dynamics (Newton-Euler, with IA, FV, FS and an external wrench on link 6) for its example
    RX-90, github.com/symoro/symoro@23db8e5 Robots/RX90/RX90_inm.txt and RX90_idm.txt, counted
    by Program.operations' rule: 177 / 147 and 343 / 300 multiplications / additions
    (benchmarks/bench_dynamics.py, SYMORO_RX90).  The assignments free of the state (moving the
    parameters from the space origin to each link's frame; SYMORO's are in the DH frames) are
    left out, as they are computed once per parameter set.
    """
    D3, RL4 = symbols("D3 RL4", positive=True)
    rx90 = Chain.from_dh([(0, 0, 0, 0), (0, pi / 2, 0, 0), (D3, 0, 0, 0), (0, -pi / 2, RL4, 0),
                          (0, pi / 2, 0, 0), (0, -pi / 2, 0, 0)], "modified")

    def per_state(p):
        state = {x for arg in p.arguments[:-1] for x in arg}
        rest = []
        for t, e in p.assignments:
            if e.free_symbols & state:
                rest.append((t, e))
                state.add(t)
        return Program((), tuple(rest), p.outputs).operations()

    H = per_state(rx90.dynamics_program("mass_matrix", parameters="standard", extras=["armature"]))
    tau = per_state(rx90.dynamics_program(parameters="standard", extras=["armature", "viscous", "coulomb"]))
    for ours, (mult, add) in ((H, (177, 147)), (tau, (343, 300))):
        assert ours.multiplications <= 1.1 * mult and ours.additions <= 1.1 * add, ours
    # the check is not empty: the whole program, moves included, is not within 1.1x
    whole = rx90.dynamics_program("mass_matrix", parameters="standard", extras=["armature"]).operations()
    assert whole.multiplications > 1.1 * 177
