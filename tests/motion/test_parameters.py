"""Standard and base inertial parameters (issue 34, item 2).

``base_regressor @ base_parameters == regressor @ parameters`` identically (symbolically on
small chains, one with symbolic geometry; at random float states on the arms), the
regressor's program equal to the closed-form ``regressor``, and the number of base
parameters equal to the numeric rank of pinocchio's joint-torque regressor
(``computeJointTorqueRegressor``, test-only) stacked over random states, for the UR5, the
PUMA 560 and the Panda (7 joints).  Known counts: the planar 2R arm has 4 base parameters
(Khalil & Dombre 2002, Section 12.5.3: ZZ1R, ZZ2, MX2, MY2).
"""

from __future__ import annotations

import random

import numpy as np
import pytest
from _dynamics import mr_ur5_chain, random_chain
from _robots import panda, pin_model, puma560
from sympy import Float, ImmutableMatrix, Rational, cancel, symbols, trigsimp

from screwsym import Chain, Twist
from screwsym.motion.parameters import _rows, _state, base_parameters, parameters, regressor_program


def _identity_holds(chain, gravity=None) -> bool:
    n = chain.n_joints
    q, qd, qdd = (ImmutableMatrix(symbols(f"{s}1:{n + 1}", real=True)) for s in ("q", "qd", "qdd"))
    lhs = chain.base_regressor(q, qd, qdd, gravity) * chain.base_parameters(gravity)
    rhs = chain.regressor(q, qd, qdd, gravity) * chain.parameters()
    return all(trigsimp((x - y).expand()) == 0 for x, y in zip(lhs, rhs, strict=True))


def test_planar_2r_has_khalils_four():
    arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                 Twist.rotation([0, 0, 1], point=[1, 0, 0])])
    assert len(arm.base_parameters()) == 4
    assert _identity_holds(arm)


def _holds_at_fresh_exact_states(chain, base, seed) -> bool:
    """``Y == Y[:, columns] B`` exactly at states other than those the method used."""
    prog = regressor_program(chain)
    rng = random.Random(seed)
    gsyms = sorted(chain.free_symbols | {symbols("g", positive=True)}, key=str)
    gsyms = [s for s in gsyms if s.name == "g"]
    for _ in range(3):
        Y = ImmutableMatrix(_rows(prog, _state(rng, prog, chain.n_joints, gsyms)))
        if not (Y - Y[:, list(base.columns)] * base.matrix).applyfunc(cancel).is_zero_matrix:
            return False
    return True


@pytest.mark.slow
def test_identity_on_a_spatial_chain_with_symbolic_geometry():
    a, d = symbols("a d", positive=True)
    arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                 Twist.rotation([0, 1, 0], point=[0, 0, d]),
                 Twist.translation([1, 0, 0]),
                 Twist.rotation([1, 0, 0], point=[a, 0, d])])
    base = base_parameters(arm)
    assert base.parameters.free_symbols <= set(parameters(arm)) | {a, d}
    assert {a, d} & base.matrix.free_symbols  # the grouping depends on the geometry
    assert _holds_at_fresh_exact_states(arm, base, 7)
    # a grouping with one coefficient changed fails
    B = base.matrix.as_mutable()
    k = next(j for j in range(B.cols) if j not in base.columns and B[0, j] != 0)
    B[0, k] += 1
    wrong = base._replace(matrix=ImmutableMatrix(B))
    assert not _holds_at_fresh_exact_states(arm, wrong, 7)


def test_a_wrong_grouping_is_rejected():
    arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                 Twist.rotation([0, 0, 1], point=[1, 0, 0])])
    base = base_parameters(arm)
    n = 2
    q, qd, qdd = (ImmutableMatrix(symbols(f"{s}1:{n + 1}", real=True)) for s in ("q", "qd", "qdd"))
    wrong = base.parameters.subs(symbols("m_2", real=True), 0)  # drop a grouped term
    lhs = arm.base_regressor(q, qd, qdd) * wrong
    rhs = arm.regressor(q, qd, qdd) * arm.parameters()
    assert any(trigsimp((x - y).expand()) != 0 for x, y in zip(lhs, rhs, strict=True))


def test_regressor_program_is_the_closed_form_regressor():
    rng = np.random.default_rng(3401)
    chain = random_chain(rng, 3)
    g = [0, 0, -9.81]
    x = [[Float(v) for v in r] for r in rng.uniform(-2, 2, (3, 3))]
    Y = np.array(chain.regressor(*x, g), dtype=float)
    Yp = np.array(regressor_program(chain, g).evaluate(*x), dtype=float)
    assert np.allclose(Y, Yp, rtol=1e-9, atol=1e-9)
    Yw = np.array(regressor_program(chain, [0, 0, -9.8]).evaluate(*x), dtype=float)
    assert not np.allclose(Y, Yw, rtol=1e-9, atol=1e-9)


def test_parameters_symbols_and_numbers():
    chain = mr_ur5_chain()
    pi = chain.parameters()
    assert pi.shape == (60, 1) and str(pi[0]) == "m_1" and str(pi[14]) == "I_xx_2"
    values = chain.parameters(numbers=True)
    assert values[:10, 0] == chain.inertias[0].parameters()
    with pytest.raises(ValueError, match="no inertias"):
        Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])]).parameters(numbers=True)
    with pytest.raises(TypeError, match="chain"):
        parameters("ur5")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="helical"):
        Chain([Twist.screw_motion([0, 0, 1], point=[0, 0, 0], pitch=1)]).base_parameters()


@pytest.mark.parametrize("name", ["ur5", pytest.param("puma560", marks=pytest.mark.slow),
                                  pytest.param("panda", marks=pytest.mark.slow)])
def test_base_parameter_count_is_pinocchios_rank(name):
    pin = pytest.importorskip("pinocchio")
    chain = {"ur5": mr_ur5_chain, "puma560": puma560, "panda": panda}[name]()
    g = [0, 0, -Rational(981, 100)]
    base = base_parameters(chain, g)
    model = pin_model(pin, chain, [0, 0, -9.81])
    data = model.createData()
    n = chain.n_joints
    rng = np.random.default_rng(34)
    states = rng.uniform(-np.pi, np.pi, size=(40, 3, n))
    W = np.vstack([pin.computeJointTorqueRegressor(model, data, *s) for s in states])
    assert len(base.columns) == np.linalg.matrix_rank(W)
    # and Y_b beta == Y pi at random float states with random parameter values
    prog = regressor_program(chain, g)
    pi = np.array(chain.parameters(numbers=True), dtype=float).ravel()
    beta = np.array(base.matrix, dtype=float) @ pi
    for s in states[:3]:
        Y = np.array(prog.evaluate(*(list(map(float, x)) for x in s)), dtype=float)
        assert np.allclose(Y[:, list(base.columns)] @ beta, Y @ pi, rtol=1e-9, atol=1e-9)
        assert not np.allclose(Y[:, list(base.columns)] @ (beta * 1.01), Y @ pi, rtol=1e-9)
        # and the torques are pinocchio's
        tau = pin.rnea(model, data, *s)
        assert np.allclose(Y @ pi, tau, rtol=1e-8, atol=1e-8)


def test_rotor_inertia_and_friction_as_parameters():
    """SYMORO's IA, FV, FS: the armature of joint 1 (axis fixed) groups with its I_zz."""
    arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                 Twist.rotation([0, 0, 1], point=[1, 0, 0])])
    beta = arm.base_parameters(extras=["armature", "viscous", "coulomb"])
    Ia1, Fv1, Fc1, Ia2, Fv2, Fc2, zz1, zz2 = symbols("Ia_1 Fv_1 Fc_1 Ia_2 Fv_2 Fc_2 I_zz_1 I_zz_2",
                                                      real=True)
    assert beta[0] == zz1 + zz2 + Ia1
    assert {Fv1, Fc1, Ia2, Fv2, Fc2} <= set(beta)
    assert len(beta) == 4 + 5
    assert _identity_holds_with(arm, ["armature", "viscous", "coulomb"])
    with pytest.raises(ValueError, match="extras"):
        arm.base_parameters(extras=["damping"])


def _identity_holds_with(chain, extras) -> bool:
    n = chain.n_joints
    q, qd, qdd = (ImmutableMatrix(symbols(f"{s}1:{n + 1}", real=True)) for s in ("q", "qd", "qdd"))
    lhs = chain.base_regressor(q, qd, qdd, extras=extras) * chain.base_parameters(extras=extras)
    rhs = regressor_program(chain, extras=extras).expressions() * chain.parameters(extras=extras)
    return all(trigsimp((x - y).expand()) == 0 for x, y in zip(lhs, rhs, strict=True))


def test_a_decimal_gravity_gives_the_same_base_parameters():
    """-9.81 is read as the rational it is: floats in the echelon form made spurious pivots (51 for 36)."""
    chain = mr_ur5_chain()
    exact = base_parameters(chain, [0, 0, -Rational(981, 100)])
    decimal = base_parameters(chain, [0.0, 0.0, -9.81])
    assert decimal.columns == exact.columns and len(decimal.columns) == 36
