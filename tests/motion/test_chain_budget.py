"""The budget of a chain's kinematics and dynamics: an answer within it, or a ValueError naming the method.

The project rule (``screwsym.algebra.budget``): no call may run without a bound.  ``Chain.forward``,
``Chain.jacobian`` and the dynamics take ``budget=``; the ring arithmetic of ``_poe`` and
``_ring_dynamics`` and the steps of the general paths charge it.
"""

import re

import pytest
from sympy import Rational, pi, symbols

from screwsym import Chain, Transform, Twist
from screwsym.algebra.budget import BUDGET, case_budget, charge
from screwsym.core.inertia import SpatialInertia
from screwsym.motion import _poe, dynamics
from screwsym.motion.chain import ur5


def _arm(n: int, inertias: bool = False) -> Chain:
    """An n-joint spatial chain, axes cycling through z, y, x (no two consecutive parallel)."""
    axes = [[0, 0, 1], [0, 1, 0], [1, 0, 0]]
    twists = [Twist.rotation(axes[i % 3], point=[Rational(i, 3), Rational(i % 2, 2), i]) for i in range(n)]
    bodies = [SpatialInertia.point_mass(1, [i + 1, Rational(1, 2), 0]) for i in range(n)] if inertias else None
    return Chain(twists, Transform.translation([1, 2, 3]), bodies)


def _qs(n: int) -> tuple:
    return symbols(f"q1:{n + 1}", real=True)


BOUNDED = {
    "forward": lambda c, q, b: c.forward(q, budget=b),
    "jacobian": lambda c, q, b: c.jacobian(q, budget=b),
    "jacobian body": lambda c, q, b: c.jacobian(q, frame="body", budget=b),
    "mass_matrix": lambda c, q, b: c.mass_matrix(q, budget=b),
    "inverse_dynamics": lambda c, q, b: c.inverse_dynamics(q, q, q, budget=b),
    "gravity_torques": lambda c, q, b: c.gravity_torques(q, budget=b),
    "coriolis_matrix": lambda c, q, b: c.coriolis_matrix(q, q, budget=b),
    "regressor": lambda c, q, b: c.regressor(q, q, q, budget=b),
}


@pytest.mark.parametrize("method", sorted(BOUNDED))
def test_a_small_budget_stops_each_method_with_an_error_naming_it(method):
    chain = _arm(2, inertias=True)
    name = method.split()[0]
    message = rf"^{name}: the exact arithmetic needs more than budget=10 units .*pass a larger budget"
    with pytest.raises(ValueError, match=message):
        BOUNDED[method](chain, _qs(2), 10)


@pytest.mark.parametrize("q", [[Rational(1, 3), Rational(-9, 5)], [0.3, -1.8], [pi / 6, -pi / 4]])
def test_numbers_take_the_budget_too(q):
    """Numeric joint values (the general path, or the ring at 15-degree multiples) are bounded too."""
    chain = _arm(2, inertias=True)
    with pytest.raises(ValueError, match=r"^forward: .*budget=10 "):
        chain.forward(q, budget=10)
    with pytest.raises(ValueError, match=r"^mass_matrix: .*budget=10 "):
        chain.mass_matrix(q, budget=10)
    assert chain.forward(q) == chain.forward(q, budget=10**9)


def test_a_moderately_long_chain_answers_by_default():
    """Ten joints (a few hundred thousand units): well within the default budget, and right."""
    mr = pytest.importorskip("modern_robotics")
    np = pytest.importorskip("numpy")
    chain = _arm(10)
    q = _qs(10)
    T = chain.forward(q)
    J = chain.jacobian(q)
    values = [0.1 * k - 0.45 for k in range(10)]
    at = dict(zip(q, values, strict=True))
    # an independent check: modern_robotics' product of exponentials (Lynch & Park 4.1, 5.1.1)
    S = np.array([[float(x) for x in t.matrix] for t in chain.twists]).T
    M = np.array(chain.home.matrix.tolist(), dtype=float)
    T_mr = mr.FKinSpace(M, S, np.array(values))
    J_mr = mr.JacobianSpace(S, np.array(values))
    T_ours = np.array(T.matrix.xreplace(at).evalf().tolist(), dtype=float)
    J_ours = np.array(J.xreplace(at).evalf().tolist(), dtype=float)
    assert np.abs(T_ours - T_mr).max() < 1e-9
    assert np.abs(J_ours - J_mr).max() < 1e-9
    # the check rejects a wrong answer: another configuration differs
    other = dict(at)
    other[q[3]] += 0.1
    assert np.abs(np.array(T.matrix.xreplace(other).evalf().tolist(), dtype=float) - T_mr).max() > 1e-3


def test_a_long_chain_is_stopped_soon():
    """24 joints at symbolic angles: minutes unbounded; a budget of 10**5 units stops it."""
    chain = _arm(24)
    with pytest.raises(ValueError, match=r"^jacobian: .*budget=100000 .*kinematics_program"):
        chain.jacobian(_qs(24), budget=10**5)


def test_the_outer_budget_holds():
    chain = _arm(3, inertias=True)
    q = _qs(3)
    # coriolis_matrix calls mass_matrix, gravity_torques calls inverse_dynamics: the outer names
    with pytest.raises(ValueError, match=r"^coriolis_matrix: .*budget=50 "):
        dynamics.coriolis_matrix(chain, q, q, budget=50)
    with pytest.raises(ValueError, match=r"^gravity_torques: .*budget=50 "):
        dynamics.gravity_torques(chain, q, budget=50)
    # inside a call with a large budget, an inner small budget does not stop the work
    with _poe.bounded(10**9, "outer"):
        assert chain.forward(q, budget=10) == chain.forward(q)
    # and inside a small one, the inner default does not lift it: the outer method is named
    with pytest.raises(ValueError, match=r"^singularities: "):
        with case_budget(10, "singularities"):
            chain.forward(q)


def test_a_call_stopped_half_way_leaves_no_trace():
    """The ring engines are cached: a call stopped in the middle must leave no half-done state."""
    alpha = symbols("alpha", real=True)
    # symbolic twist angles: the engine walks the joints' frames (a state kept on the engine)
    chain = Chain.from_dh([(1, alpha, 0, 0), (1, 0, 0, 0), (0, alpha, 1, 0)])
    q = _qs(3)
    _poe._RECENT.clear()
    fresh = chain.forward(q)
    stopped = 0
    for b in range(100, 4000, 50):  # the whole call is about 3,000 units: stopped at every stage
        _poe._RECENT.clear()
        try:
            chain.forward(q, budget=b)
        except ValueError:
            stopped += 1
        for engine in _poe._RECENT.values():
            # the walk through the joints' frames is recorded complete or not at all
            assert getattr(engine, "_walked", "not yet") is not None
        assert chain.forward(q) == fresh
    assert stopped >= 10


def test_the_budget_is_checked():
    chain = _arm(2)
    with pytest.raises(ValueError, match="budget"):
        chain.forward(_qs(2), budget=0)
    with pytest.raises(TypeError, match="budget"):
        chain.jacobian(_qs(2), budget="many")
    with pytest.raises((TypeError, ValueError), match="budget"):
        chain.forward(_qs(2), budget=1.5)


def test_the_default_is_the_floor_budget_and_covers_the_ur5():
    q = _qs(6)
    arm = ur5()
    with _poe.bounded(BUDGET, "ur5"):
        T = arm.forward(q)
    assert T == arm.forward(q, budget=BUDGET)
    # the charges are counted: the UR5's kinematics is more than a thousand units, well below the default
    with pytest.raises(ValueError, match=re.escape("budget=1000 ")):
        _poe._RECENT.clear()
        arm.forward(q, budget=1000)
    charge(10**12)  # outside a budget nothing is counted
