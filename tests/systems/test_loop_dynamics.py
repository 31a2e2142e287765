"""The dynamics of closed loops (issue 35): ``Mechanism(..., inertias=)``, ``joint_rates``,
``joint_accelerations``, ``mass_matrix``, ``inverse_dynamics``, ``joint_reactions``,
``platform_dynamics``, ``redundant_inverse_dynamics``.

Ground truth is computed inside each test, independently of screwsym's screw algebra:
the Lagrangian of the linkage in its actuated angles (Lagrange's equations,
``tau = d/dt dT/dqd - dT/dq + dV/dq``; Tsai, *Robot Analysis*, Wiley 1999, §9.4 and
§9.6, the four-bar and five-bar examples; Uicker, Pennock & Shigley, *Theory of Machines
and Mechanisms*, 5th ed., ch. 4 for the position closure of the four-bar by the
intersection of two circles), with the closure solved in closed form and differentiated
numerically by mpmath at 40 digits (agreement asked: 1e-20, relative).  Each checker is shown to reject a wrong
answer (a perturbed inertia, a perturbed torque).
"""

from __future__ import annotations

import random

import numpy as np
import pytest
from _linkages import DELTA_RADIAL, bennett, delta_joints, shaky_4r
from mpmath import mp, mpf
from sympy import (
    Float,
    ImmutableMatrix,
    Matrix,
    Ne,
    Piecewise,
    Rational,
    cos,
    diag,
    lambdify,
    nan,
    sin,
    symbols,
    true,
)

from screwsym.core.inertia import SpatialInertia
from screwsym.systems.joints import R
from screwsym.systems.linkage import Mechanism

Z = [0, 0, 1]


# ------------------------------------------------------------------ ground truth
mp.dps = 40
TOL = 1e-20  # the ground truth: closed forms differentiated numerically at 40 digits


def vec(p):
    return [mpf(int(x.p)) / int(x.q) for x in (Rational(p[0]), Rational(p[1]))]


def circles(P, r1, Q, r2, sign):
    """The intersection of the circles (P, r1) and (Q, r2) on the side ``sign`` of PQ
    (closed form: Uicker, Pennock & Shigley, ch. 4)."""
    dx, dy = Q[0] - P[0], Q[1] - P[1]
    d2 = dx * dx + dy * dy
    d = mp.sqrt(d2)
    ex, ey = dx / d, dy / d
    l = (r1**2 - r2**2 + d2) / (2 * d)
    h = mp.sqrt(r1**2 - l**2)
    return [P[0] + l * ex - sign * h * ey, P[1] + l * ey + sign * h * ex]


def side(P, Q, X):
    """The side of the line PQ the point X is on (+1 left, -1 right)."""
    return 1 if (Q[0] - P[0]) * (X[1] - P[1]) - (Q[1] - P[1]) * (X[0] - P[0]) > 0 else -1


def dist(P, Q):
    return mp.sqrt((Q[0] - P[0]) ** 2 + (Q[1] - P[1]) ** 2)


def body(origin0, tip0, com0, origin, tip):
    """A body's com and unit vector now, from its pose at the configuration (two points)."""
    e0 = [(tip0[i] - origin0[i]) / dist(origin0, tip0) for i in range(2)]
    rel = [com0[i] - origin0[i] for i in range(2)]
    x, y = rel[0] * e0[0] + rel[1] * e0[1], -rel[0] * e0[1] + rel[1] * e0[0]
    e = [(tip[i] - origin[i]) / dist(origin, tip) for i in range(2)]
    return [origin[0] + x * e[0] - y * e[1], origin[1] + x * e[1] + y * e[0]], e


def lagrange(bodies, q0, qd, qdd, gravity):
    """Lagrange's equations at ``q0``: ``tau_i = sum_j H_ij qdd_j + sum_jk (dH_ij/dq_k
    - 1/2 dH_jk/dq_i) qd_j qd_k + dV/dq_i``, ``H = sum m Jc^T Jc + Izz Je^T Je``.

    ``bodies(q)``: a list of (mass, com, Izz, unit vector fixed in the body) in the plane;
    the derivatives by mpmath's numerical differentiation at 40 digits.
    """
    n = len(q0)
    q0 = [mpf(x) for x in q0]

    def partial(f, q, i):
        return mp.diff(lambda x: f(q[:i] + [x] + q[i + 1:]), q[i])

    def H(q):
        out = mp.zeros(n, n)
        for b in range(len(bodies(q))):
            m, _, Izz, _ = bodies(q)[b]
            Jc = [[partial(lambda x, b=b, r=r: bodies(x)[b][1][r], q, i) for i in range(n)] for r in range(2)]
            Je = [[partial(lambda x, b=b, r=r: bodies(x)[b][3][r], q, i) for i in range(n)] for r in range(2)]
            for i in range(n):
                for j in range(n):
                    out[i, j] += m * sum(Jc[r][i] * Jc[r][j] for r in range(2))
                    out[i, j] += Izz * sum(Je[r][i] * Je[r][j] for r in range(2))
        return out

    def V(q):
        return sum(-m * (gravity[0] * c[0] + gravity[1] * c[1]) for m, c, _, _ in bodies(q))

    H0 = H(q0)
    moving = any(x != 0 for x in qd)
    dH = [_dH(H, q0, k) if moving else None for k in range(n)]
    tau = []
    for i in range(n):
        val = sum(H0[i, j] * qdd[j] for j in range(n))
        if moving:
            val += sum((dH[k][i, j] - dH[i][j, k] / 2) * qd[j] * qd[k]
                       for j in range(n) for k in range(n))
        val += partial(V, q0, i)
        tau.append(val)
    return tau


def _dH(H, q0, k):
    """dH/dq_k at q0, entry by entry (mpmath's diff of a matrix-valued function)."""
    n = len(q0)
    return mp.matrix([[mp.diff(lambda x, i=i, j=j: H(q0[:k] + [x] + q0[k + 1:])[i, j], q0[k])
                       for j in range(n)] for i in range(n)])


def agrees(ours, truth, tol=TOL):
    ours = [mpf(str(x.evalf(45))) for x in ours]
    scale = max([mpf(1)] + [abs(t) for t in truth])
    return all(abs(a - b) <= tol * scale for a, b in zip(ours, truth, strict=True))


def tensor(a, b, c, d):
    """A symmetric positive definite inertia tensor with off-diagonal terms (out of plane too)."""
    return Matrix([[a, d, Rational(1, 9)], [d, b, Rational(1, 11)], [Rational(1, 9), Rational(1, 11), c]])


# ------------------------------------------------------------------ the four-bar
O, A0, B0, D = (Matrix([0, 0]), Matrix([1, 2]), Matrix([3, 3]), Matrix([4, 0]))
#: (link, mass, com at the configuration, tensor); Izz is the tensor's [2, 2]
FOURBAR_BODIES = (
    ("crank", 1, Matrix([Rational(1, 3), 1]), tensor(1, 1, Rational(3, 2), Rational(1, 7))),
    ("coupler", 2, Matrix([2, Rational(3, 2)]), tensor(2, Rational(3, 2), 3, Rational(-1, 5))),
    ("rocker", 3, Matrix([Rational(7, 2), 2]), tensor(1, 2, Rational(5, 2), Rational(1, 6))),
)


def fourbar(masses=None):
    masses = masses or {}
    inertias = {name: SpatialInertia(masses.get(name, m), [c[0], c[1], 0], I)
                for name, m, c, I in FOURBAR_BODIES}
    pt = [list(p) + [0] for p in (O, A0, B0, D)]
    return Mechanism([("ground", "crank", R(pt[0], Z)), ("crank", "coupler", R(pt[1], Z)),
                      ("coupler", "rocker", R(pt[2], Z)), ("rocker", "ground", R(pt[3], Z))],
                     base="ground", inertias=inertias)


def fourbar_truth(qd, qdd, gravity):
    """The four-bar's Lagrangian in its crank angle ``t`` (closure: two circles)."""
    o, a0, b0, d = (vec(p) for p in (O, A0, B0, D))
    a, b, c = dist(o, a0), dist(a0, b0), dist(d, b0)
    sign = side(a0, d, b0)

    def bodies(q):
        A = [a * mp.cos(q[0]), a * mp.sin(q[0])]
        B = circles(A, b, d, c, sign)
        poses = {"crank": (o, a0, o, A), "coupler": (a0, b0, A, B), "rocker": (d, b0, d, B)}
        out = []
        for name, m, com, I in FOURBAR_BODIES:
            p0, t0, p, t = poses[name]
            cq, e = body(p0, t0, vec(com), p, t)
            out.append((_mp(m)[0], cq, _mp(I[2, 2])[0], e))
        return out

    return lagrange(bodies, [mp.atan2(a0[1], a0[0])], _mp(qd), _mp(qdd), _mp(gravity))


def _mp(v):
    v = v if isinstance(v, (list, tuple)) else [v]
    return [mpf(int(Rational(x).p)) / int(Rational(x).q) for x in v]


def test_fourbar_inverse_dynamics_matches_the_lagrangian():
    """The crank torque of a four-bar (Tsai 1999, §9.4's example form) against its
    Lagrangian in the crank angle, the closure solved exactly by two circles."""
    mech = fourbar()
    qd, qdd, g = Rational(3, 2), Rational(-2, 3), [0, Rational(-981, 100), 0]
    ours = mech.inverse_dynamics([0], [qd], [qdd], g)
    truth = fourbar_truth(qd, qdd, g)
    assert ours.free_symbols == set()
    assert agrees(list(ours), truth)
    # the checker rejects a perturbed torque and a perturbed inertia
    assert not agrees([ours[0] + Rational(1, 10**12)], truth)
    heavier = fourbar({"coupler": 2 + Rational(1, 1000)}).inverse_dynamics([0], [qd], [qdd], g)
    assert not agrees(list(heavier), truth)


def pinocchio_fourbar(pin):
    """The four-bar of :func:`fourbar` in pinocchio (also benchmarks/bench_loop_dynamics.py):
    an open chain of three revolutes about z whose rocker point D is held at D by a 3D point
    constraint; ``(model, data, constraint models, constraint datas)``, initialised for
    ``constraintDynamics``, gravity ``-9.81`` along y."""
    model = pin.Model()
    pts = [np.array([float(p[0]), float(p[1]), 0.0]) for p in (O, A0, B0, D)]
    parent, prev = 0, np.zeros(3)
    for k, (name, m, c, I) in enumerate(FOURBAR_BODIES):
        jid = model.addJoint(parent, pin.JointModelRZ(), pin.SE3(np.eye(3), pts[k] - prev), name)
        com = np.array([float(c[0]), float(c[1]), 0.0]) - pts[k]
        model.appendBodyToJoint(jid, pin.Inertia(float(m), com, np.array(I.tolist(), dtype=float)),
                                pin.SE3.Identity())
        parent, prev = jid, pts[k]
    model.gravity.linear = np.array([0, -9.81, 0])
    data = model.createData()
    cm = pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, model, 3,
                                  pin.SE3(np.eye(3), pts[3] - pts[2]), 0,
                                  pin.SE3(np.eye(3), pts[3]), pin.ReferenceFrame.LOCAL)
    cms, cds = pin.StdVec_RigidConstraintModel(), pin.StdVec_RigidConstraintData()
    cms.append(cm)
    cds.append(cm.createData())
    pin.initConstraintDynamics(model, data, cms, cds)
    return model, data, cms, cds


def test_fourbar_against_pinocchios_constrained_dynamics():
    """pinocchio's ``constraintDynamics`` (Carpentier et al., RSS 2021, the proximal
    constrained dynamics) on the same four-bar: an open chain of three revolutes whose rocker
    point D is held at D by a 3D point constraint.  Driven by our crank torque, at our joint
    rates, it gives our joint accelerations (float precision); a torque off by 1e-6 does not."""
    pin = pytest.importorskip("pinocchio")
    mech = fourbar()
    model, data, cms, cds = pinocchio_fourbar(pin)
    qd, qdd = Rational(3, 2), Rational(-2, 3)
    v = np.array([float(x) for x in mech.joint_rates([0], [qd])[:3]])
    tau = float(mech.inverse_dynamics([0], [qd], [qdd], [0, Rational(-981, 100), 0])[0])
    ours = np.array([float(x) for x in mech.joint_accelerations([0], [qd], [qdd])[:3]])
    prox = pin.ProximalSettings(1e-12, 1e-10, 100)

    def pinocchio(t):
        return pin.constraintDynamics(model, data, np.zeros(3), v, np.array([t, 0, 0]), cms, cds,
                                      prox)

    assert np.max(np.abs(pinocchio(tau) - ours)) < 1e-12
    # the constraint's force on the rocker at D (the constraint frame is the world's here):
    # our last joint ("rocker", "ground") exerts the opposite on the ground
    pinocchio(tau)
    force = np.array(cds[0].contact_force.linear)
    reaction = mech.joint_reactions([0], [qd], [qdd], [0, Rational(-981, 100), 0])[3]
    assert np.max(np.abs(force + np.array([float(x) for x in reaction.matrix[:3]]))) < 1e-9
    assert np.max(np.abs(force - np.array([float(x) for x in reaction.matrix[:3]]))) > 1
    assert np.max(np.abs(pinocchio(tau + 1e-6) - ours)) > 1e-12


def test_roots_in_the_geometry_and_the_default_gravity():
    """Joints at (1, sqrt 3) and (3, sqrt 2): the exact mass matrix and static torque against
    the velocity polygon and virtual work in floating point; the default gravity is
    ``(0, 0, -g)`` as for serial chains (here along z: no torque on a planar loop)."""
    from sympy import sqrt

    from screwsym.motion.dynamics import GRAVITY
    from screwsym.systems.loop_dynamics import GRAVITY as LOOP_GRAVITY

    a, b = [1, sqrt(3), 0], [3, sqrt(2), 0]
    mech = Mechanism([("g", "c", R([0, 0, 0], Z)), ("c", "k", R(a, Z)), ("k", "r", R(b, Z)),
                      ("r", "g", R([4, 0, 0], Z))], base="g",
                     inertias={"c": SpatialInertia.point_mass(1, a),
                               "r": SpatialInertia.point_mass(2, b)})
    H = mech.mass_matrix([0])
    tau = mech.inverse_dynamics([0], [0], [0], [0, -10, 0])
    A, B, D = (np.array([float(x) for x in p[:2]]) for p in (a, b, [4, 0]))

    def perp(v):
        return np.array([-v[1], v[0]])

    w2, w3 = np.linalg.solve(np.column_stack([perp(B - A), -perp(B - D)]), -perp(A))
    vA, vB = perp(A), w3 * perp(B - D)  # per unit crank rate
    assert abs(float(H[0]) - (vA @ vA + 2 * vB @ vB)) < 1e-12
    assert abs(float(tau[0]) - (10 * vA[1] + 2 * 10 * vB[1])) < 1e-12
    assert abs(float(tau[0]) + 1e-9 - (10 * vA[1] + 2 * 10 * vB[1])) > 1e-12
    assert LOOP_GRAVITY == GRAVITY
    assert mech.inverse_dynamics([0], [0], [0]) == Matrix([[0]])


def test_decimal_rates_and_inertias_give_the_exact_answer_rounded():
    """Floats in the rates, accelerations and inertias (the joints stay exact): the answer is
    the exact one to float precision (the closure check takes the floats' exact values)."""
    exact = fourbar().inverse_dynamics([0], [Rational(3, 2)], [Rational(-1, 4)], [0, -10, 0])
    floats = fourbar({"coupler": 2.0}).inverse_dynamics([0], [1.5], [-0.25], [0, -10.0, 0])
    assert abs(float(floats[0]) - float(exact[0])) < 1e-12 * abs(float(exact[0]))
    assert abs(float(floats[0]) - float(exact[0]) * (1 + 1e-9)) > 1e-12 * abs(float(exact[0]))


def _float_fourbar():
    """The four-bar of :func:`fourbar` with every inertia in floats (masses, centres of mass,
    tensors: ``1/3``, ``1/7``, ... rounded), and its exact twin: the same floats read as
    their exact binary values (``Rational(float)``), which is what the float policy
    computes with."""
    def bodies(convert):
        return {name: SpatialInertia(convert(m), [convert(c[0]), convert(c[1]), 0],
                                     I.applyfunc(convert))
                for name, m, c, I in FOURBAR_BODIES}

    pt = [list(p) + [0] for p in (O, A0, B0, D)]
    joints = [("ground", "crank", R(pt[0], Z)), ("crank", "coupler", R(pt[1], Z)),
              ("coupler", "rocker", R(pt[2], Z)), ("rocker", "ground", R(pt[3], Z))]
    return (Mechanism(joints, base="ground", inertias=bodies(float)),
            Mechanism(joints, base="ground", inertias=bodies(lambda x: Rational(float(x)))))


def close(ours, exact, rtol=1e-15):
    """Each float entry within ``rtol`` of the exact value, relative to the largest."""
    ours, exact = [complex(x) for x in ours], [complex(x) for x in exact]
    scale = max(abs(x) for x in exact)
    return all(abs(a - b) <= rtol * scale for a, b in zip(ours, exact, strict=True))


def test_float_inertias_rates_and_gravity_give_the_exact_answer_rounded_once():
    """The float policy (notebooks/float-policy.md): floats in the inertias, rates,
    accelerations and gravity (``-9.81``) are read as their exact binary values and the
    result is rounded once, so it agrees with the exact computation on those values to
    float precision: mass matrix, inverse dynamics and every joint reaction (the float
    elimination of the reactions used to find a spurious pivot, "inconsistent input")."""
    floats, exact = _float_fourbar()
    qd, qdd, g = [1.5], [-0.3], [0, -9.81, 0]
    qx, qddx, gx = [Rational(1.5)], [Rational(-0.3)], [0, Rational(-9.81), 0]
    H, Hx = floats.mass_matrix([0]), exact.mass_matrix([0])
    assert H.atoms(Rational) <= {0} and close(H, Hx)
    tau, taux = floats.inverse_dynamics([0], qd, qdd, g), exact.inverse_dynamics([0], qx, qddx, gx)
    assert close(tau, taux) and not close(tau * (1 + 1e-12), taux)
    w = floats.joint_reactions([0], qd, qdd, g)
    wx = exact.joint_reactions([0], qx, qddx, gx)
    assert all(close(a.matrix, b.matrix, 1e-14) for a, b in zip(w, wx, strict=True))
    assert close(floats.joint_rates([0], qd), exact.joint_rates([0], qx))
    assert close(floats.joint_accelerations([0], qd, qdd), exact.joint_accelerations([0], qx, qddx))
    # the Lagrangian agrees too (the inertias differ from the rationals by the rounding only)
    assert abs(float(tau[0]) - float(fourbar_truth(qx[0], qddx[0], gx)[0])) < 1e-12 * abs(float(tau[0]))
    # exact input stays exact
    assert exact.inverse_dynamics([0], qx, qddx, gx).atoms(Float) == set()


def test_delta_with_floats_everywhere_matches_the_exact_delta():
    """The Delta link by link with float masses and inertias, decimal rates and
    accelerations that no rational joint rates match exactly in floats (``0.1``, ``-0.2``,
    ...) and ``g = -9.81``: no refusal (the passive rates follow the actuated ones
    exactly, so the closure holds to second order), and the torques, mass matrix and
    reactions agree with the exact Delta on the floats' binary values."""
    def mech(convert):
        inertias = {f"arm{i + 1}": SpatialInertia(convert(Rational(21, 10)),
                                                  [convert(Rational(5, 2) * e[0]),
                                                   convert(Rational(5, 2) * e[1]), convert(Rational(-1, 2))],
                                                  diag(1, 1, 1).applyfunc(lambda x: convert(x / 3)))
                    for i, e in enumerate(DELTA_RADIAL)}
        inertias["platform"] = SpatialInertia(convert(Rational(33, 10)), [0, 0, -3],
                                              diag(convert(Rational(3, 10)), convert(Rational(3, 10)),
                                                   convert(Rational(1, 2))))
        return Mechanism([t for i, e in enumerate(DELTA_RADIAL) for t in delta_joints(i + 1, e)],
                         base="base", inertias=inertias)

    floats, exact = mech(float), mech(lambda x: Rational(float(x)))
    qd, qdd, g = [0.1, -0.2, 0.3], [0.7, 0.0, -1.1], [0, 0, -9.81]
    ex = [[Rational(x) for x in v] for v in (qd, qdd, g)]
    act = [0, 7, 14]
    tau, taux = floats.inverse_dynamics(act, qd, qdd, g), exact.inverse_dynamics(act, *ex)
    assert close(tau, taux) and not close(tau.applyfunc(lambda x: x * (1 + 1e-12)), taux)
    assert close(floats.mass_matrix(act), exact.mass_matrix(act))
    w, wx = floats.joint_reactions(act, qd, qdd, g), exact.joint_reactions(act, *ex)
    scale = max(abs(float(x)) for r in wx for x in r.matrix)
    assert all(abs(float(a - b)) <= 1e-14 * scale
               for r, rx in zip(w, wx, strict=True) for a, b in zip(r.matrix, rx.matrix, strict=True))


def rocker_ratio():
    """d(rocker angle)/d(crank angle) of the four-bar at its configuration, from the closure
    by two circles differentiated by mpmath (independent of screwsym)."""
    o, a0, b0, d = (vec(p) for p in (O, A0, B0, D))
    a, b, c = dist(o, a0), dist(a0, b0), dist(d, b0)
    sign = side(a0, d, b0)

    def rocker(t):
        B = circles([a * mp.cos(t), a * mp.sin(t)], b, d, c, sign)
        return mp.atan2(B[1] - d[1], B[0] - d[0])

    return mp.diff(rocker, mp.atan2(a0[1], a0[0]))


def test_redundant_actuation_gives_the_least_norm_forces_and_the_internal_ones():
    """The four-bar driven at its crank and at its rocker pivot (joint 3, written rocker ->
    ground: its rate is minus the rocker's), at a moving state: virtual power fixes only
    ``B^T tau = Q``, ``B = (1, -r)`` (``r`` the rocker's rate per crank rate) and ``Q`` the
    crank torque of the Lagrangian; the least-norm forces are ``B Q / |B|^2`` (Cheng, Yiu &
    Li 2003), and ``(r, 1)`` spans the internal forces.  Against the Lagrangian and the
    closure by two circles; the checker rejects a perturbed force.  Inconsistent rates are
    refused; float rates rounded from a consistent motion are read to the float policy."""
    mech = fourbar()
    qd, qdd, g = Rational(3, 2), Rational(-2, 3), [0, Rational(-981, 100), 0]
    rates = list(mech.joint_rates([0], [qd]))
    accels = list(mech.joint_accelerations([0], [qd], [qdd]))
    red = mech.redundant_inverse_dynamics([0, 3], [rates[0], rates[3]], [accels[0], accels[3]], g)
    assert red.primary == (0,)
    Q, r = fourbar_truth(qd, qdd, g)[0], rocker_ratio()
    truth = [Q / (1 + r**2), -r * Q / (1 + r**2)]
    assert agrees(list(red.forces), truth)
    assert not agrees([red.forces[0] + Rational(1, 10**12), red.forces[1]], truth)
    (v,) = red.internal
    assert agrees([v[0] / v[1]], [r])  # (r, 1): no work on the allowed motion (1, -r)
    # k = M: inverse_dynamics' forces, no internal force
    alone = mech.redundant_inverse_dynamics([0], [qd], [qdd], g)
    assert alone.forces == mech.inverse_dynamics([0], [qd], [qdd], g) and alone.internal == ()
    with pytest.raises(ValueError, match=r"rates\[1\]: the actuated joints' rates must be "
                                         "consistent"):
        mech.redundant_inverse_dynamics([0, 3], [rates[0], rates[3] + 1], [0, 0], g)
    with pytest.raises(ValueError, match=r"accelerations\[1\]: .* must be consistent"):
        mech.redundant_inverse_dynamics([0, 3], [rates[0], rates[3]], [accels[0], 0], g)
    # floats: rates and accelerations rounded once are accepted; off by 1e-9 they are not
    f = [float(x) for x in (rates[0], rates[3], accels[0], accels[3])]
    floats = mech.redundant_inverse_dynamics([0, 3], f[:2], f[2:], [0, -9.81, 0])
    assert agrees(list(floats.forces), truth, 1e-12)
    with pytest.raises(ValueError, match="rates\\[1\\]"):
        mech.redundant_inverse_dynamics([0, 3], [f[0], f[1] * (1 + 1e-9)], f[2:], [0, -9.81, 0])


def test_fourbar_mass_matrix_and_joint_rates():
    """H = dT/dqd^2 of the Lagrangian (rates only), and the joint rates by instant centres."""
    mech = fourbar()
    H = mech.mass_matrix([0])
    # the Lagrangian's torque for qdd = 1, qd = 0, no gravity is H itself
    truth = fourbar_truth(0, 1, [0, 0, 0])
    assert agrees(list(H), truth)
    assert not agrees([H[0] * (1 + Rational(1, 10**9))], truth)
    # the coupler turns at -25/7 and the rocker at 15/7 per 5 of the crank (velocity polygon:
    # v_A + w2 x AB = w3 x DB, solved by hand)
    assert mech.joint_rates([0], [5]) == ImmutableMatrix([5, -Rational(60, 7), Rational(40, 7),
                                                          -Rational(15, 7)])
    # any joint can drive it: the rocker's joint 3 (the same motion, the same kinetic energy)
    q = mech.joint_rates([0], [5])
    H3 = mech.mass_matrix([3])
    assert H3[0] * q[3] ** 2 == H[0] * q[0] ** 2


def test_fourbar_accelerations_close_the_loop_and_links_move_rigidly():
    """The joint accelerations satisfy the differentiated closure, and the coupler's twist
    rate is the same computed along either side of the loop (path independence)."""
    mech = fourbar()
    qd = mech.joint_rates([0], [2])
    qdd = mech.joint_accelerations([0], [2], [5])
    A = mech.network_matrix()
    assert A * qdd + mech.quadratic_terms(qd) == ImmutableMatrix.zeros(6, 1)
    # the rocker's twist rate from the tree (through joint 3) equals the coupler's plus the
    # rocker-relative part: d/dt (V_coupler + $_2 qd_2) = Vdot_c + [V_c, $_2] qd_2 + $_2 qdd_2
    Vc = Matrix(mech.link_twist("coupler", [0], [2]).matrix)
    Ac = Matrix(mech.link_acceleration("coupler", [0], [2], [5]).matrix)
    Ar = Matrix(mech.link_acceleration("rocker", [0], [2], [5]).matrix)
    from screwsym.core.formulas import bracket

    s2 = Matrix([0, 0, 1, B0[1], -B0[0], 0])  # the rotation about z through (3, 3)
    assert Ar == Ac + Matrix(bracket(Vc, s2)) * qd[2] + s2 * qdd[2]


# ------------------------------------------------------------------ the five-bar
P1, Q1, C0, Q2, P2 = (Matrix([0, 0]), Matrix([-1, 2]), Matrix([2, 4]), Matrix([5, 2]),
                      Matrix([4, 0]))
FIVEBAR_BODIES = (
    ("l1", 1, Matrix([Rational(-1, 2), 1]), tensor(1, 1, Rational(3, 2), 0), P1, Q1),
    ("l2", Rational(3, 2), Matrix([1, 3]), tensor(2, 1, Rational(5, 2), Rational(1, 8)), Q1, C0),
    ("r2", 2, Matrix([Rational(7, 2), 3]), tensor(1, 2, 2, 0), Q2, C0),
    ("r1", Rational(5, 4), Matrix([Rational(9, 2), 1]), tensor(2, 2, 3, 0), P2, Q2),
)


def fivebar(masses=None):
    masses = masses or {}
    inertias = {name: SpatialInertia(masses.get(name, m), [c[0], c[1], 0], I)
                for name, m, c, I, _, _ in FIVEBAR_BODIES}
    pt = {k: list(p) + [0] for k, p in (("P1", P1), ("Q1", Q1), ("C", C0), ("Q2", Q2),
                                        ("P2", P2))}
    return Mechanism([("ground", "l1", R(pt["P1"], Z)), ("l1", "l2", R(pt["Q1"], Z)),
                      ("l2", "r2", R(pt["C"], Z)), ("r2", "r1", R(pt["Q2"], Z)),
                      ("ground", "r1", R(pt["P2"], Z))], base="ground", inertias=inertias)


def fivebar_truth(qd, qdd, gravity):
    """The five-bar's Lagrangian in its two base angles (closure: two circles about the
    elbows; Tsai 1999, §9.6's planar five-bar form)."""
    p1, q1, c0, q2, p2 = (vec(p) for p in (P1, Q1, C0, Q2, P2))
    r1, r2 = dist(p1, q1), dist(p2, q2)
    l2, l3 = dist(q1, c0), dist(q2, c0)
    sign = side(q1, q2, c0)

    def bodies(q):
        E1 = [p1[0] + r1 * mp.cos(q[0]), p1[1] + r1 * mp.sin(q[0])]
        E2 = [p2[0] + r2 * mp.cos(q[1]), p2[1] + r2 * mp.sin(q[1])]
        C = circles(E1, l2, E2, l3, sign)
        poses = {"l1": (p1, q1, p1, E1), "l2": (q1, c0, E1, C), "r2": (q2, c0, E2, C),
                 "r1": (p2, q2, p2, E2)}
        out = []
        for name, m, com, I, _, _ in FIVEBAR_BODIES:
            p0, t0, p, t = poses[name]
            cq, e = body(p0, t0, vec(com), p, t)
            out.append((_mp(m)[0], cq, _mp(I[2, 2])[0], e))
        return out

    q0 = [mp.atan2(q1[1] - p1[1], q1[0] - p1[0]), mp.atan2(q2[1] - p2[1], q2[0] - p2[0])]
    return lagrange(bodies, q0, _mp(qd), _mp(qdd), _mp(gravity))


def test_fivebar_inverse_dynamics_matches_the_lagrangian():
    """The planar five-bar driven at its two base joints against its Lagrangian."""
    mech = fivebar()
    qd, qdd, g = [Rational(1, 2), -1], [2, Rational(1, 3)], [0, -10, 0]
    ours = mech.inverse_dynamics([0, 4], qd, qdd, g)
    truth = fivebar_truth(qd, qdd, g)
    assert agrees(list(ours), truth)
    heavier = fivebar({"r2": 2 + Rational(1, 1000)}).inverse_dynamics([0, 4], qd, qdd, g)
    assert not agrees(list(heavier), truth)
    # the mass matrix is the Lagrangian's response to unit accelerations
    H = fivebar().mass_matrix([0, 4])
    for j in range(2):
        col = fivebar_truth([0, 0], [int(i == j) for i in range(2)], [0, 0, 0])
        assert agrees(list(H.col(j)), col)


def test_at_rest_the_torques_are_the_static_balance_by_virtual_work():
    """At rest, tau = -sum_l m_l g . dc_l/dqa (virtual work of the weights), the com
    velocities per actuated rate computed from the closure in closed form."""
    mech = fivebar()
    g = [Rational(3, 10), -10, 0]
    ours = mech.inverse_dynamics([0, 4], [0, 0], [0, 0], g)
    # the Lagrangian at rest is the gradient of the potential: the virtual work balance
    truth = fivebar_truth([0, 0], [0, 0], g)
    assert agrees(list(ours), truth)
    assert not agrees([ours[0], ours[1] + Rational(1, 10**15)], truth)
    # and the gravity terms do not depend on the masses' tensors, only on masses and coms
    assert ours.free_symbols == set()


def is_symmetric_positive_definite(H):
    """Exactly: symmetric, and its leading principal minors positive (Sylvester)."""
    H = Matrix(H)
    return H == H.T and all(H[:k, :k].det() > 0 for k in range(1, H.rows + 1))


def test_mass_matrix_symmetric_positive_definite_at_random_states():
    """At random non-singular configurations of the five-bar (random rational joint
    positions), the mass matrix is symmetric positive definite; the checker rejects a
    matrix made indefinite or non-symmetric."""
    rnd = random.Random(35)
    done = 0
    while done < 5:
        pts = [[Rational(rnd.randint(-9, 9), rnd.randint(1, 4)) for _ in range(2)] + [0]
               for _ in range(5)]
        names = ["l1", "l2", "r2", "r1"]
        inertias = {n: SpatialInertia(rnd.randint(1, 5), pts[i][:2] + [0],
                                      diag(1, 1, Rational(rnd.randint(1, 9), 10)))
                    for i, n in enumerate(names)}
        try:
            mech = Mechanism([("ground", "l1", R(pts[0], Z)), ("l1", "l2", R(pts[1], Z)),
                              ("l2", "r2", R(pts[2], Z)), ("r2", "r1", R(pts[3], Z)),
                              ("ground", "r1", R(pts[4], Z))], base="ground", inertias=inertias)
            H = mech.mass_matrix([0, 4])
        except ValueError:  # a coincident pair of points or an actuation singularity
            continue
        assert is_symmetric_positive_definite(H)
        done += 1
    assert not is_symmetric_positive_definite(H - diag(H[0, 0] + 1, 0))
    assert not is_symmetric_positive_definite(H + Matrix([[0, 1], [0, 0]]))


# ------------------------------------------------------------------ no loop: a serial chain
def test_a_serial_chain_agrees_with_the_recursive_newton_euler_algorithm():
    """A spatial R-R-P-H chain as a tree, every joint actuated, at its home configuration:
    the virtual-power sum along the tree paths equals screwsym's recursive Newton-Euler
    algorithm (Park, Bobrow & Ploen 1995; itself checked against pinocchio in
    tests/motion) exactly, brackets of non-parallel axes and a helical pitch included; a
    perturbed inertia disagrees."""
    from screwsym import Chain, Twist
    from screwsym.motion.dynamics import inverse_dynamics
    from screwsym.systems.joints import Helical, P

    twists = [Twist.rotation([0, 0, 1], point=[0, 0, 0]), Twist.rotation([0, 1, 0], point=[0, 0, 1]),
              Twist.translation([1, 0, 0]), Twist.screw_motion([1, 0, 0], point=[0, 1, 1], pitch=2)]
    joints = [R([0, 0, 0], [0, 0, 1]), R([0, 0, 1], [0, 1, 0]), P([1, 0, 0]),
              Helical([0, 1, 1], [1, 0, 0], 2)]
    I3 = Matrix([[2, Rational(1, 3), 0], [Rational(1, 3), 3, Rational(1, 5)], [0, Rational(1, 5), 4]])
    bodies = [SpatialInertia(k + 1, [k, 1 - k, 2], I3) for k in range(4)]
    qd, qdd, g = [1, -2, Rational(1, 2), 3], [2, 0, -1, Rational(1, 3)], [0, -10, Rational(-1, 2)]
    truth = inverse_dynamics(Chain(twists, inertias=bodies), [0, 0, 0, 0], qd, qdd, gravity=g)
    names = ["base", "l1", "l2", "l3", "l4"]

    def tree(inertias):
        return Mechanism([(names[i], names[i + 1], joints[i]) for i in range(4)], base="base",
                         inertias={names[i + 1]: inertias[i] for i in range(4)})

    assert tree(bodies).inverse_dynamics([0, 1, 2, 3], qd, qdd, g) == truth
    heavier = bodies[:2] + [SpatialInertia(3 + Rational(1, 100), [2, -1, 2], I3), bodies[3]]
    assert tree(heavier).inverse_dynamics([0, 1, 2, 3], qd, qdd, g) != truth
    with pytest.raises(ValueError, match="mobility, 4, got 3"):
        tree(bodies).mass_matrix([0, 1, 2])


# ------------------------------------------------------------------ a 3-RPR parallel mechanism
def test_3rpr_platform_dynamics_matches_tsais_virtual_work_model():
    """A planar 3-RPR (legs massless, prismatic joints actuated) built as a
    ``ParallelMechanism``: the mass matrix and the static forces against Tsai's
    virtual-work model, ``H = J^-T M_x J^-1`` and ``tau = -J^-T w_g``, with the inverse
    Jacobian rows ``[u_i; (p_i x u_i)_z]`` (Tsai, *Robot Analysis*, 1999, §4.6 and §9.6;
    ``u_i`` the unit leg directions, ``p_i`` the platform pivots)."""
    from screwsym.systems.joints import P
    from screwsym.systems.parallel import Limb, ParallelMechanism

    base = [Matrix([0, 0]), Matrix([10, 0]), Matrix([5, 12])]
    pivots = [Matrix([3, 4]), Matrix([6, 3]), Matrix([5, 7])]  # each leg 5 long
    u = [(p - b) / 5 for b, p in zip(base, pivots, strict=True)]
    pm = ParallelMechanism(*(Limb(R(list(b) + [0], Z), P(list(d) + [0]), R(list(p) + [0], Z))
                             for b, d, p in zip(base, u, pivots, strict=True)))
    m, c, Izz = 3, Matrix([Rational(14, 3), Rational(14, 3)]), Rational(5, 2)
    platform = SpatialInertia(m, list(c) + [0], diag(1, Rational(3, 2), Izz))
    mech = Mechanism.from_parallel(pm, inertias={"platform": platform})
    actuated = [1, 4, 7]  # the prismatic joints, limb by limb
    # Tsai's model, in the platform's coordinates (v_O, omega)
    Jinv = Matrix([[ui[0], ui[1], pi[0] * ui[1] - pi[1] * ui[0]]
                   for ui, pi in zip(u, pivots, strict=True)])
    J = Jinv.inv()
    # kinetic energy 1/2 m |v_O + omega x c|^2 + 1/2 Izz omega^2
    E = Matrix([[1, 0, -c[1]], [0, 1, c[0]]])  # the com's velocity per (v_O, omega)
    Mx = m * E.T * E + diag(0, 0, Izz)
    g = Matrix([0, -10])
    wg = Matrix([m * g[0], m * g[1], c[0] * m * g[1] - c[1] * m * g[0]])  # force, moment at O
    H = mech.mass_matrix(actuated)
    assert H == J.T * Mx * J
    tau = mech.inverse_dynamics(actuated, [0, 0, 0], [0, 0, 0], [0, -10, 0])
    assert tau == -J.T * wg
    # the checks reject a perturbed platform
    heavier = Mechanism.from_parallel(pm, inertias={
        "platform": SpatialInertia(m + Rational(1, 100), list(c) + [0], diag(1, Rational(3, 2), Izz))})
    assert heavier.mass_matrix(actuated) != J.T * Mx * J
    assert heavier.inverse_dynamics(actuated, [0, 0, 0], [0, 0, 0], [0, -10, 0]) != -J.T * wg


def test_3rpr_in_the_platforms_coordinates_is_tsais_virtual_work_model():
    """The 3-RPR of the test above in its platform's coordinates at its centre of mass,
    ``(wz, vx, vy)``, at a moving state: the legs massless, Tsai's virtual-work model (Tsai
    2000, J. Mech. Design 122; *Robot Analysis* §9.6) is the platform's own Newton-Euler
    balance, ``F = (Izz wz', m (a - g))`` with ``Lambda = diag(Izz, m, m)``, and ``tau =
    J^-T F``, ``J`` from :meth:`ParallelMechanism.jacobian`'s ``Jx t = Jq qa'`` (``t`` the
    platform twist in these coordinates).  The platform form agrees with the actuated form
    (``Lambda = J^T H J``); the checker rejects a perturbed platform mass."""
    from screwsym.systems.joints import P
    from screwsym.systems.parallel import Limb, ParallelMechanism

    base = [Matrix([0, 0]), Matrix([10, 0]), Matrix([5, 12])]
    pivots = [Matrix([3, 4]), Matrix([6, 3]), Matrix([5, 7])]
    u = [(p - b) / 5 for b, p in zip(base, pivots, strict=True)]
    pm = ParallelMechanism(*(Limb(R(list(b) + [0], Z), P(list(d) + [0]), R(list(p) + [0], Z),
                                  actuated=1)
                             for b, d, p in zip(base, u, pivots, strict=True)))
    c, Izz = [Rational(14, 3), Rational(14, 3), 0], Rational(5, 2)

    def mech(m):
        platform = SpatialInertia(m, c, diag(1, Rational(3, 2), Izz))
        return Mechanism.from_parallel(pm, inertias={"platform": platform})

    m, g = 3, [0, -10, 0]
    xd, xdd = [Rational(1, 2), -1, 2], [Rational(-1, 3), Rational(3, 2), 1]  # (wz, vx, vy) at c
    pd = mech(m).platform_dynamics([1, 4, 7], xd, xdd, g, point=c)
    assert pd.coordinates == ("wz", "vx", "vy")
    # the Jacobian through ParallelMechanism.jacobian: t = T x', Jx t = Jq qa'
    Jx, Jq = pm.jacobian()
    # v_O = v_c - omega x c
    T = Matrix([[0, 0, 0], [0, 0, 0], [1, 0, 0], [c[1], 1, 0], [-c[0], 0, 1], [0, 0, 0]])
    J = Jq[:3, :].inv() * Jx[:3, :] * T  # Jx's rows (C_O; f) times (omega; v_O)
    assert pd.jacobian == J
    Lam = diag(Izz, m, m)
    F = Matrix([Izz * xdd[0], m * (xdd[1] - g[0]), m * (xdd[2] - g[1])])
    assert pd.mass_matrix == Lam and pd.forces == F
    assert pd.actuator_forces == J.inv().T * F
    H = mech(m).mass_matrix([1, 4, 7])
    assert H == J.inv().T * Lam * J.inv()
    # at rest qa'' = J x'': the actuated form gives the same forces
    rest = mech(m).platform_dynamics([1, 4, 7], [0, 0, 0], xdd, g, point=c).actuator_forces
    assert rest == mech(m).inverse_dynamics([1, 4, 7], [0, 0, 0], list(J * Matrix(xdd)), g)
    wrong = mech(m + Rational(1, 100)).platform_dynamics([1, 4, 7], xd, xdd, g, point=c)
    assert wrong.forces != F and wrong.mass_matrix != Lam
    # named coordinates, Tsai's order (vx, vy, wz): the same model permuted
    tsai = mech(m).platform_dynamics([1, 4, 7], [xd[1], xd[2], xd[0]], [xdd[1], xdd[2], xdd[0]],
                                     g, point=c, coordinates=("vx", "vy", "wz"))
    assert tsai.mass_matrix == diag(m, m, Izz) and tsai.actuator_forces == pd.actuator_forces
    # floats (mass, rates, g = -9.81): the exact model on their binary values, rounded once
    fl = Mechanism.from_parallel(pm, inertias={"platform": SpatialInertia(3.1, c, diag(1, 1.5, 2.5))})
    ex = Mechanism.from_parallel(pm, inertias={"platform": SpatialInertia(Rational(3.1), c,
                                                                          diag(1, 1.5, 2.5))})
    xf, xfd = [0.1, -0.2, 0.3], [0.7, 0.0, -1.1]
    got = fl.platform_dynamics([1, 4, 7], xf, xfd, [0, -9.81, 0], point=c)
    want = ex.platform_dynamics([1, 4, 7], [Rational(x) for x in xf], [Rational(x) for x in xfd],
                                [0, Rational(-9.81), 0], point=c)
    assert close(got.actuator_forces, want.actuator_forces) and close(got.forces, want.forces)
    assert close(got.mass_matrix, want.mass_matrix)


# ------------------------------------------------------------------ the Delta robot (spatial)
def codourey(qd, qdd, g, m_arm=2, m_p=3, radial=DELTA_RADIAL):
    """Clavel's Delta link by link (17 links, 21 revolutes, 5 loops; the parallelogram
    forearms massless), its arms and platform with inertia, and Codourey's model of it
    (Codourey 1998, IJRR 17(12): the arms turning about fixed axes, the platform
    translating), computed here by vector algebra: the rod constraints ``s_i . pdot = s_i .
    w_i`` (``s_i`` the rod, ``w_i`` the elbow's velocity) and, differentiated, ``s_i .
    pddot = s_i . a_i - |pdot - w_i|**2``.  Returns the mechanism, the platform's velocity
    and acceleration, ``Jp`` (``pdot = Jp qd``), the motor torques and Codourey's
    Cartesian mass matrix ``m_p 1 + Jp^-T diag(I_axis) Jp^-1``.  ``radial``: the legs'
    directions from the centre (unit, horizontal)."""
    joints = [t for i, e in enumerate(radial) for t in delta_joints(i + 1, e)]
    I_c = diag(Rational(1, 5), Rational(1, 4), Rational(1, 3))
    legs = []
    for e in radial:
        e = Matrix(e)
        u = Matrix([-e[1], e[0], 0])
        b = 2 * e
        elbow = b + e + Matrix([0, 0, -1])
        attach = Matrix([0, 0, -3]) + e
        legs.append((u, b, elbow, attach, (b + elbow) / 2))  # the arm's com at its middle
    inertias = {f"arm{i + 1}": SpatialInertia(m_arm, list(leg[4]), I_c)
                for i, leg in enumerate(legs)}
    inertias["platform"] = SpatialInertia(m_p, [0, 0, -3], diag(1, 1, 2))
    mech = Mechanism(joints, base="base", inertias=inertias)
    S = Matrix.hstack(*(attach - elbow for u, b, elbow, attach, _ in legs)).T
    w = [u.cross(elbow - b) * qd[i] for i, (u, b, elbow, attach, _) in enumerate(legs)]
    pd = S.solve(Matrix([S.row(i).dot(w[i]) for i in range(3)]))
    acc = [u.cross(elbow - b) * qdd[i] + u.cross(u.cross(elbow - b)) * qd[i] ** 2
           for i, (u, b, elbow, attach, _) in enumerate(legs)]
    pdd = S.solve(Matrix([S.row(i).dot(acc[i]) - (pd - w[i]).dot(pd - w[i]) for i in range(3)]))
    J = S.solve(Matrix.diag(*(S.row(i).dot(u.cross(elbow - b))
                              for i, (u, b, elbow, attach, _) in enumerate(legs))))
    tau, axial = [], []
    for i, (u, b, _, _, c) in enumerate(legs):
        r = c - b
        axial.append((u.T * I_c * u)[0] + m_arm * (r.dot(r) - r.dot(u) ** 2))  # about the axis
        weight = m_arm * g.dot(u.cross(r))  # the weight's power per unit arm rate
        tau.append(axial[i] * qdd[i] - weight)
    truth = Matrix(tau) + J.T * (m_p * (pdd - g))
    Lam = m_p * Matrix.eye(3) + J.inv().T * diag(*axial) * J.inv()
    return mech, pd, pdd, J, truth, Lam


def test_delta_link_by_link_matches_codoureys_model_with_massless_forearms():
    """The Delta link by link at a moving state: the inverse dynamics against Codourey's
    model (:func:`codourey`).  Exact; the checker rejects a perturbed arm inertia."""
    qd, qdd, g = [1, -2, Rational(1, 2)], [Rational(1, 3), 0, -1], Matrix([0, 0, -10])
    mech, _, _, _, truth, _ = codourey(qd, qdd, g)
    ours = mech.inverse_dynamics([0, 7, 14], qd, qdd, list(g))
    assert ours == truth
    heavier = codourey(qd, qdd, g, m_arm=2 + Rational(1, 100))[0]
    assert heavier.inverse_dynamics([0, 7, 14], qd, qdd, list(g)) != truth
    H = mech.mass_matrix([0, 7, 14])
    assert is_symmetric_positive_definite(H)


def test_delta_in_the_platforms_coordinates_is_codoureys_model():
    """Codourey's form of the Delta (1998, IJRR 17(12), massless forearms): in the
    platform's coordinates ``(vx, vy, vz)`` the Jacobian is the inverse of his ``pdot = Jp
    qd``, the Cartesian mass matrix ``m_p 1 + Jp^-T diag(I_axis) Jp^-1``, and the motor
    torques from the platform's velocity and acceleration his; the platform form and the
    actuated form agree (``Lambda = J^T H J``, ``tau = J^-T F``).  The checker rejects a
    perturbed arm mass."""
    qd, qdd, g = [1, -2, Rational(1, 2)], [Rational(1, 3), 0, -1], Matrix([0, 0, -10])
    mech, pd, pdd, Jp, truth, Lam = codourey(qd, qdd, g)
    ours = mech.platform_dynamics([0, 7, 14], list(pd), list(pdd), list(g))
    assert ours.coordinates == ("vx", "vy", "vz")
    assert ours.jacobian == Jp.inv()
    assert ours.mass_matrix == Lam
    assert ours.actuator_forces == truth
    assert ours.forces == Jp.inv().T * truth
    H = mech.mass_matrix([0, 7, 14])
    assert ours.mass_matrix == ours.jacobian.T * H * ours.jacobian
    assert mech.platform_dynamics([0, 7, 14]).forces is None
    heavier = codourey(qd, qdd, g, m_arm=2 + Rational(1, 100))[0]
    assert heavier.platform_dynamics([0, 7, 14]).mass_matrix != Lam


def delta_at(top, radial=DELTA_RADIAL):
    """The Delta link by link (as tests/_linkages.py's) with its platform at ``top``."""

    def leg(i, e):
        e = list(e)
        u = [-e[1], e[0], 0]
        b = [2 * x for x in e]
        elbow = [3 * e[0], 3 * e[1], -1]
        attach = [e[0] + top[0], e[1] + top[1], top[2]]
        n = list(Matrix(u).cross(Matrix(attach) - Matrix(elbow)))
        half = [Rational(1, 2) * x for x in u]
        plus = [[p + h for p, h in zip(q, half, strict=True)] for q in (elbow, attach)]
        minus = [[p - h for p, h in zip(q, half, strict=True)] for q in (elbow, attach)]
        arm, upper, r1, r2, lower = (f"{k}{i}" for k in ("arm", "upper", "rodA", "rodB", "lower"))
        return [("base", arm, R(b, u)), (arm, upper, R(elbow, u)), (upper, r1, R(plus[0], n)),
                (r1, lower, R(plus[1], n)), (upper, r2, R(minus[0], n)), (r2, lower, R(minus[1], n)),
                (lower, "platform", R(attach, u))]

    return [t for i, e in enumerate(radial) for t in leg(i + 1, e)]


@pytest.mark.slow
def test_delta_at_a_symbolic_height_holds_off_the_flat_pose():
    """The Delta with its platform at height ``z`` (arms fixed; the rods' length follows):
    the crank-driven dynamics hold where ``z != -1``, the pose where the six rods lie flat
    and radial so that the platform moves up and down with the arms locked (the second kind
    of singularity of Gosselin & Angeles 1990); at ``z = -3`` the mass matrix is the numeric
    Delta's (10 s)."""
    z = symbols("z", real=True)
    top = [0, 0, z]

    joints = delta_at(top)
    # at z = -3 the joints are those of the Delta of tests/_linkages.py
    assert [(a, b, j.subs(z, -3)) for a, b, j in joints] == [
        t for i, e in enumerate(DELTA_RADIAL) for t in delta_joints(i + 1, e)]
    inertias = {f"arm{i + 1}": SpatialInertia(2, [Rational(5, 2) * e[0], Rational(5, 2) * e[1],
                                                  Rational(-1, 2)], diag(1, 1, 1))
                for i, e in enumerate(DELTA_RADIAL)}
    inertias["platform"] = SpatialInertia(3, top, diag(1, 1, 2))
    mech = Mechanism(joints, base="base", inertias=inertias)
    assert mech.actuation_condition([0, 7, 14]) == (Ne(z + 1, 0) & Ne(z**2 + 2 * z + 5, 0))
    H = mech.mass_matrix([0, 7, 14])
    here = Mechanism([(a, b, j.subs(z, -3)) for a, b, j in joints], base="base",
                     inertias={k: v.subs(z, -3) for k, v in inertias.items()})
    assert H.subs(z, -3) == here.mass_matrix([0, 7, 14])


def test_delta_with_compound_parallelograms_equals_the_delta_link_by_link():
    """The Delta's forearms as compound :class:`Parallelogram` pairs (their circular
    translation's second derivative enters the twist rates) against the same Delta link by
    link, the rods massless, the arms, the forearms' upper and lower bars and the platform
    with inertia: the same inverse dynamics and mass matrix, exactly."""
    from _linkages import HALF, add, scale, sub

    from screwsym.systems.joints import Parallelogram

    def leg(i, e):
        u = [-e[1], e[0], 0]
        b = scale(2, e)
        elbow = add(add(b, e), [0, 0, -1])
        attach = add([0, 0, -3], e)
        pair = Parallelogram(add(elbow, scale(HALF, u)), sub(elbow, scale(HALF, u)),
                             add(attach, scale(HALF, u)))
        return [("base", f"arm{i}", R(b, u)), (f"arm{i}", f"upper{i}", R(elbow, u)),
                (f"upper{i}", f"lower{i}", pair), (f"lower{i}", "platform", R(attach, u))]

    I_c = diag(Rational(1, 5), Rational(1, 4), Rational(1, 3))
    inertias = {"platform": SpatialInertia(3, [0, 0, -3], diag(1, 1, 2))}
    for i, e in enumerate(DELTA_RADIAL):
        e = Matrix(e)
        elbow = 3 * e + Matrix([0, 0, -1])
        inertias[f"arm{i + 1}"] = SpatialInertia(2, list((2 * e + elbow) / 2), I_c)
        inertias[f"upper{i + 1}"] = SpatialInertia(Rational(1, 2), list(elbow), I_c / 4)
        inertias[f"lower{i + 1}"] = SpatialInertia(Rational(1, 3), list(e + Matrix([0, 0, -3])),
                                                   I_c / 5)
    compound = Mechanism([t for i, e in enumerate(DELTA_RADIAL) for t in leg(i + 1, e)],
                         base="base", inertias=inertias)
    full = Mechanism([t for i, e in enumerate(DELTA_RADIAL) for t in delta_joints(i + 1, e)],
                     base="base", inertias=inertias)
    qd, qdd, g = [1, -2, Rational(1, 2)], [Rational(1, 3), 0, -1], [0, 0, -10]
    tau = full.inverse_dynamics([0, 7, 14], qd, qdd, g)
    assert compound.inverse_dynamics([0, 4, 8], qd, qdd, g) == tau
    assert compound.mass_matrix([0, 4, 8]) == full.mass_matrix([0, 7, 14])
    assert compound.inverse_dynamics([0, 4, 8], qd, [Rational(1, 3), 0, 0], g) != tau


def test_a_delta_at_a_symbolic_pose_is_refused_within_the_budget():
    """The Delta with its platform at (x, y, z): its elimination is charged in advance and
    refused by the default budget at once (it ran past 4 CPU minutes unbounded)."""
    x, y, z = symbols("x y z", real=True)
    mech = Mechanism(delta_at([x, y, z]), base="base",
                     inertias={"platform": SpatialInertia(3, [x, y, z], diag(1, 1, 2))})
    with pytest.raises(ValueError, match="mass_matrix: the exact arithmetic needs more than"):
        mech.mass_matrix([0, 7, 14])


# ------------------------------------------------------------------ singular and bad input
def test_actuation_singularity_is_a_clear_error():
    """Coupler and rocker in line (B on the line AD): the crank cannot drive the four-bar;
    the same four-bar driven at the rocker's joint can."""
    pt = [[0, 0, 0], [1, 2, 0], [3, 1, 0], [5, 0, 0]]  # (3, 1) lies on the line (1, 2)-(5, 0)
    mech = Mechanism([("ground", "crank", R(pt[0], Z)), ("crank", "coupler", R(pt[1], Z)),
                      ("coupler", "rocker", R(pt[2], Z)), ("rocker", "ground", R(pt[3], Z))],
                     base="ground", inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0])})
    with pytest.raises(ValueError, match="actuation singularity"):
        mech.mass_matrix([0])
    assert mech.mass_matrix([1]).shape == (1, 1)
    with pytest.raises(ValueError, match="mobility, 1, got 2"):
        mech.mass_matrix([0, 3])


def fourbar_at(x, y):
    """The four-bar of the docstrings (point masses 1 at the crank pin ``(1, 2, 0)`` and 2 at
    the rocker's pin) with its coupler-rocker joint at ``(x, y)``."""
    inert = {"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
             "rocker": SpatialInertia.point_mass(2, [x, y, 0])}
    return Mechanism([("ground", "crank", R([0, 0, 0], Z)), ("crank", "coupler", R([1, 2, 0], Z)),
                      ("coupler", "rocker", R([x, y, 0], Z)), ("rocker", "ground", R([4, 0, 0], Z))],
                     base="ground", inertias=inert)


def test_symbolic_configuration_gives_the_generic_result_and_its_condition():
    """The coupler joint at (x, y): the result holds where the coupler and rocker are not in
    line; ``conds="piecewise"`` says so; numbers put in agree with the numeric mechanism."""
    x, y = symbols("x y", real=True)
    mech = fourbar_at(x, y)
    cond = mech.actuation_condition([0])
    # (5/2, 1) lies on the line from the crank pin (1, 2) to the rocker pivot (4, 0)
    assert cond is not true and cond.subs({x: Rational(5, 2), y: 1}) == false_()
    H = mech.mass_matrix([0])
    assert H.subs({x: 3, y: 3}) == Matrix([[Rational(425, 49)]])
    pw = mech.mass_matrix([0], conds="piecewise")
    assert isinstance(pw[0], Piecewise) and pw[0].subs({x: Rational(5, 2), y: 1}) is nan
    tau = mech.inverse_dynamics([0], [0], [0], [0, -10, 0])
    assert tau.subs({x: 3, y: 3}) == Matrix([[Rational(10, 7)]])
    # every call is bounded: a budget too small is a clear error naming the method
    fresh = Mechanism([(a, b, j) for a, b, j in mech.joints], base="ground",
                      inertias={"crank": SpatialInertia.point_mass(3, [1, 2, 0])})
    with pytest.raises(ValueError, match="mass_matrix: the exact arithmetic needs more than "
                                         "budget=10 units"):
        fresh.mass_matrix([0], budget=10)
    with pytest.raises(ValueError, match="budget"):
        fresh.inverse_dynamics([0], [1], [0], budget=0)


def test_platform_coordinates_symbolic_and_bad_input():
    """The four-bar's coupler as a platform, its coupler joint at ``(x, y)``: the platform
    form is generic, ``conds="piecewise"`` adds the actuation condition, and numbers put in
    agree with the numeric four-bar of the docstring (``J = -7/5``, ``Lambda = 17``).
    Coordinates that miss the motion, bad names and half a state are refused clearly."""
    x, y = symbols("x y", real=True)
    mech = fourbar_at(x, y)
    pd = mech.platform_dynamics([0], platform="coupler")
    assert pd.coordinates == ("wz",)
    assert pd.jacobian.subs({x: 3, y: 3}) == Matrix([[Rational(-7, 5)]])
    assert pd.mass_matrix.subs({x: 3, y: 3}) == Matrix([[17]])
    pw = mech.platform_dynamics([0], platform="coupler", conds="piecewise").mass_matrix
    assert isinstance(pw[0], Piecewise) and pw[0].subs({x: Rational(5, 2), y: 1}) is nan
    assert pw[0].subs({x: 3, y: 3}) == 17
    numeric = mech.subs({x: 3, y: 3})
    with pytest.raises(ValueError, match="coordinates: the platform rates wx do not determine"):
        numeric.platform_dynamics([0], platform="coupler", coordinates=["wx"])
    with pytest.raises(ValueError, match="coordinates\\[0\\]: expected one of wx, wy"):
        numeric.platform_dynamics([0], platform="coupler", coordinates=["omega"])
    with pytest.raises(ValueError, match="rates, accelerations: give both"):
        numeric.platform_dynamics([0], [1], platform="coupler")
    with pytest.raises(ValueError, match="link: 'platform' is not a link"):
        numeric.platform_dynamics([0])
    with pytest.raises(ValueError, match="platform: its twist has rank 0 < 1"):
        numeric.platform_dynamics([0], platform="ground")


def test_a_mechanism_with_inertias_substitutes_and_compares_as_a_value():
    """``subs`` rebuilds the mechanism with its inertias (the canonical pairs are accepted)."""
    x, y = symbols("x y", real=True)
    inert = {"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
             "rocker": SpatialInertia.point_mass(2, [x, y, 0])}
    joints = [("ground", "crank", R([0, 0, 0], Z)), ("crank", "coupler", R([1, 2, 0], Z)),
              ("coupler", "rocker", R([x, y, 0], Z)), ("rocker", "ground", R([4, 0, 0], Z))]
    mech = Mechanism(joints, base="ground", inertias=inert)
    here = mech.subs({x: 3, y: 3})
    assert here.mass_matrix([0]) == Matrix([[Rational(425, 49)]])
    assert here.inertias["rocker"] == SpatialInertia.point_mass(2, [3, 3, 0])
    assert mech != Mechanism(joints, base="ground")
    assert mech == Mechanism(joints, base="ground", inertias=dict(reversed(list(inert.items()))))


def test_a_shaky_configuration_has_no_accelerations():
    """Four revolutes on one regulus (Müller 2016, §6): one instantaneous freedom, none to
    second order, so no joint accelerations close the loop for a non-zero rate: a clear
    error, not a number.  Bennett's linkage (a finite motion) has them."""
    mech = shaky_4r()
    assert mech.joint_rates([0], [1]) != ImmutableMatrix.zeros(4, 1)
    with pytest.raises(ValueError, match="second order"):
        mech.joint_accelerations([0], [1], [0])
    w = symbols("w", real=True)
    with pytest.raises(ValueError, match="second order"):
        mech.joint_accelerations([0], [w], [0])
    with pytest.raises(ValueError, match="second order"):
        mech.joint_accelerations([0], [0.5], [0])
    ben = bennett()
    qdd = ben.joint_accelerations([0], [1], [2])
    qd = ben.joint_rates([0], [1])
    assert ben.network_matrix() * qdd + ben.quadratic_terms(qd) == ImmutableMatrix.zeros(6, 1)


def false_():
    from sympy import false

    return false


def test_bad_input_is_refused_clearly():
    z = Z
    joints = [("g", "a", R([0, 0, 0], z)), ("a", "b", R([1, 2, 0], z)),
              ("b", "c", R([3, 3, 0], z)), ("c", "g", R([4, 0, 0], z))]
    with pytest.raises(ValueError, match="'x' is not a link"):
        Mechanism(joints, base="g", inertias={"x": SpatialInertia.point_mass(1, [0, 0, 0])})
    with pytest.raises(ValueError, match="is the base"):
        Mechanism(joints, base="g", inertias={"g": SpatialInertia.point_mass(1, [0, 0, 0])})
    with pytest.raises(TypeError, match="expected a SpatialInertia"):
        Mechanism(joints, base="g", inertias={"a": 3})
    with pytest.raises(TypeError, match="expected a dict"):
        Mechanism(joints, base="g", inertias=[("a", 3)])
    mech = Mechanism(joints, base="g", inertias={"a": SpatialInertia.point_mass(1, [1, 0, 0])})
    assert mech.inertias == {"a": SpatialInertia.point_mass(1, [1, 0, 0])}
    assert Mechanism(joints, base="g").inertias == {}
    with pytest.raises(ValueError, match="joint number 0..3"):
        mech.mass_matrix([7])
    with pytest.raises(TypeError, match="joint number"):
        mech.mass_matrix(["a"])
    with pytest.raises(ValueError, match="expected 1 actuated rates"):
        mech.inverse_dynamics([0], [1, 2], [0])
    # all the joints' rates (rounded, they would not close the loops): what to pass instead
    with pytest.raises(ValueError, match=r"rates: expected 1 actuated rates \(one per joint of "
                                         r"actuated, in its order; the other joints' follow"):
        mech.inverse_dynamics([0], [1.0, -2.0, 0.5, 0.25], [0])
    with pytest.raises(ValueError, match="conds"):
        mech.mass_matrix([0], conds="maybe")


# ------------------------------------------------------------------ forward dynamics
@pytest.mark.slow
def test_fourbar_released_under_gravity_conserves_energy_and_stays_closed():
    """Integrate H(q) qdd = -h(q, qd) (crank free, tau = 0) from rest for 0.5 s with RK4,
    the closed forms lambdified: the energy drifts by less than 1e-8 of its swing and the
    loop's position closure by less than 1e-8 (the integration error alone)."""
    t1, t2, t3 = symbols("t1 t2 t3", real=True)
    a, b, c, d = 1, Rational(5, 2), 2, 3
    e = [Matrix([cos(t), sin(t), 0]) for t in (t1, t2, t3)]
    A = a * e[0]
    B = A + b * e[1]
    Dp = Matrix([d, 0, 0])
    masses, Izz = (1, 2, 3), (Rational(1, 10), Rational(1, 5), Rational(1, 7))
    coms = (A / 2, A + b * e[1] / 2, Dp + c * e[2] / 2)
    inertias = {n: SpatialInertia(m, p, diag(Izz[i], Izz[i], Izz[i]))
                for i, (n, m, p) in enumerate(zip(("crank", "coupler", "rocker"), masses, coms, strict=True))}
    mech = Mechanism([("ground", "crank", R([0, 0, 0], Z)), ("crank", "coupler", R(A, Z)),
                      ("coupler", "rocker", R(B, Z)), ("rocker", "ground", R(Dp, Z))],
                     base="ground", inertias=inertias)
    g = [0, -10, 0]
    H = mech.mass_matrix([0])[0]
    coriolis = mech.inverse_dynamics([0], [1], [0], [0, 0, 0])[0]  # times qd**2
    weight = mech.inverse_dynamics([0], [0], [0], g)[0]
    G = mech.joint_rates([0], [1])  # joint rates per crank rate
    # absolute angle rates: coupler = joint0 + joint1, rocker = -joint3
    rates = lambdify((t1, t2, t3), [G[0] + G[1], -G[3]], "numpy")
    f_H, f_c, f_w = (lambdify((t1, t2, t3), x, "numpy") for x in (H, coriolis, weight))
    V = sum(m * 10 * p[1] for m, p in zip(masses, coms, strict=True))
    f_V, f_H2 = lambdify((t1, t2, t3), V, "numpy"), f_H
    closure = lambdify((t1, t2, t3), list(B - Dp - c * e[2])[:2], "numpy")

    # a closed configuration: t1 = 1.2, the elbow solved with numpy
    th1 = 1.2
    Ax = np.array([np.cos(th1), np.sin(th1)])
    dvec = np.array([3.0, 0]) - Ax
    dist = np.linalg.norm(dvec)
    l = (2.5**2 - 2.0**2 + dist**2) / (2 * dist)
    h = np.sqrt(2.5**2 - l**2)
    Bx = Ax + l * dvec / dist + h * np.array([-dvec[1], dvec[0]]) / dist
    th2 = np.arctan2(*(Bx - Ax)[::-1])
    th3 = np.arctan2(*(Bx - np.array([3.0, 0]))[::-1])
    assert np.allclose(closure(th1, th2, th3), 0, atol=1e-12)

    def deriv(s):
        q1, q2, q3, w = s
        acc = -(f_c(q1, q2, q3) * w**2 + f_w(q1, q2, q3)) / f_H(q1, q2, q3)
        r2, r3 = rates(q1, q2, q3)
        return np.array([w, r2 * w, r3 * w, acc])

    def energy(s):
        q1, q2, q3, w = s
        return 0.5 * f_H2(q1, q2, q3) * w**2 + f_V(q1, q2, q3)

    s = np.array([th1, th2, th3, 0.0])
    E0 = energy(s)
    dt, energies, residual = 1e-3, [], 0.0
    for _ in range(500):
        k1 = deriv(s)
        k2 = deriv(s + dt / 2 * k1)
        k3 = deriv(s + dt / 2 * k2)
        k4 = deriv(s + dt * k3)
        s = s + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        energies.append(energy(s))
        residual = max(residual, float(np.max(np.abs(closure(*s[:3])))))
    swing = float(np.max(np.abs(np.array(energies) - E0)))
    kinetic = 0.5 * f_H2(*s[:3]) * s[3] ** 2
    assert kinetic > 0.1  # it fell: the test is not vacuous
    assert swing < 1e-8 * kinetic
    assert residual < 1e-8

    # the checker rejects a wrong model: the crank's weight term off by 1 %
    def wrong(s):
        q1, q2, q3, w = s
        acc = -(f_c(q1, q2, q3) * w**2 + 1.01 * f_w(q1, q2, q3)) / f_H(q1, q2, q3)
        r2, r3 = rates(q1, q2, q3)
        return np.array([w, r2 * w, r3 * w, acc])

    s = np.array([th1, th2, th3, 0.0])
    for _ in range(500):
        k1 = wrong(s)
        k2 = wrong(s + dt / 2 * k1)
        k3 = wrong(s + dt / 2 * k2)
        k4 = wrong(s + dt * k3)
        s = s + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    assert abs(energy(s) - E0) > 1e-8 * kinetic


# ------------------------------------------------------------------ joint reactions
def fourbar_pin_forces(qd, qdd, gravity):
    """The four-bar's pin forces and crank torque by hand: the planar Newton–Euler equations
    of each link (Uicker, Pennock & Shigley, 5th ed., ch. 15, the four-bar's force analysis),
    the links' accelerations from the two-circle closure differentiated by mpmath.

    Unknowns: the force of each joint ``(a, b)`` on ``b`` (ground on crank at O, crank on
    coupler at A, coupler on rocker at B, rocker on ground at D) and the crank torque."""
    o, a0, b0, d = (vec(p) for p in (O, A0, B0, D))
    a, b, c = dist(o, a0), dist(a0, b0), dist(d, b0)
    sign = side(a0, d, b0)
    q0 = mp.atan2(a0[1], a0[0])

    def pose(q):
        A = [a * mp.cos(q), a * mp.sin(q)]
        B = circles(A, b, d, c, sign)
        poses = {"crank": (o, a0, o, A), "coupler": (a0, b0, A, B), "rocker": (d, b0, d, B)}
        out = {}
        for name, _, com, _ in FOURBAR_BODIES:
            p0, t0, p, t = poses[name]
            cq, e = body(p0, t0, vec(com), p, t)
            out[name] = (cq, mp.atan2(e[1], e[0]))
        return out

    def accel(f):  # d2/dt2 of f(q(t)) at q0: f' qdd + f'' qd^2
        return mp.diff(f, q0, 1) * qdd + mp.diff(f, q0, 2) * qd**2

    g = _mp(gravity)
    M = mp.zeros(9, 9)
    rhs = mp.zeros(9, 1)
    pins = [o, a0, b0, d]
    for k, (name, m, com, I) in enumerate(FOURBAR_BODIES):
        m = _mp(m)[0]
        cc = vec(com)
        ax = accel(lambda q, name=name: pose(q)[name][0][0])
        ay = accel(lambda q, name=name: pose(q)[name][0][1])
        alpha = accel(lambda q, name=name: pose(q)[name][1])
        # forces on link k: +F_k at pin k (joint k's b is link k), -F_{k+1} at pin k+1
        for j, s in ((k, 1), (k + 1, -1)):
            P = pins[j]
            M[3 * k, 2 * j] += s
            M[3 * k + 1, 2 * j + 1] += s
            M[3 * k + 2, 2 * j] += -s * (P[1] - cc[1])  # (P - c) x F, z component
            M[3 * k + 2, 2 * j + 1] += s * (P[0] - cc[0])
        if k == 0:
            M[2, 8] = 1  # the crank torque from the ground
        rhs[3 * k] = m * ax - m * g[0]
        rhs[3 * k + 1] = m * ay - m * g[1]
        rhs[3 * k + 2] = _mp(I[2, 2])[0] * alpha
    x = mp.lu_solve(M, rhs)
    return [x[i] for i in range(9)]


def test_fourbar_joint_reactions_match_the_hand_newton_euler_and_do_no_work():
    """The reactions of a moving four-bar under gravity against each link's planar
    Newton–Euler balance solved by hand (the in-plane pin forces and the crank torque are
    determinate; the out-of-plane part, a self-stress of the overconstrained planar loop, is
    not), and each reaction reciprocal to its joint's twist but the crank's, whose power on
    it is the crank torque of ``inverse_dynamics``."""
    from screwsym.core.wrench import power

    mech = fourbar()
    qd, qdd, g = Rational(3, 2), Rational(-2, 3), [0, Rational(-981, 100), 0]
    w = mech.joint_reactions([0], [qd], [qdd], g)
    assert len(w) == 4 and all(x.free_symbols == set() for x in w)
    tau = mech.inverse_dynamics([0], [qd], [qdd], g)[0]
    powers = [power(j.twists.screws[0], r) for (_, _, j), r in zip(mech.joints, w, strict=True)]
    assert powers == [tau, 0, 0, 0]
    truth = fourbar_pin_forces(_mp(qd)[0], _mp(qdd)[0], g)
    ours = [c for r in w for c in (r.matrix[0], r.matrix[1])] + [tau]
    assert agrees(ours, truth)
    # the checker rejects a pin force off by 1e-12
    assert not agrees(ours[:3] + [ours[3] + Rational(1, 10**12)] + ours[4:], truth)


def test_joint_reactions_with_symbols_and_bad_input():
    """Symbolic rates give the reactions as polynomials in them; bad input is refused."""
    s = symbols("s", real=True)
    mech = fourbar()
    w = mech.joint_reactions([0], [s], [0], [0, -10, 0])
    at = mech.joint_reactions([0], [2], [0], [0, -10, 0])
    assert [x.subs(s, 2) for x in w] == list(at)
    with pytest.raises(ValueError, match="actuated"):
        mech.joint_reactions([0, 1], [1, 1], [0, 0])
    with pytest.raises(TypeError, match="rates"):
        mech.joint_reactions([0], 1, [0])


def is_self_stress(mech, stress):
    """Joint wrenches (one per joint, the wrench of ``(a, b, joint)`` on ``b``) in equilibrium
    on every moving link and doing no work on any joint freedom: a self-stress."""
    from screwsym.core.wrench import power

    links = {}
    for (a, b, _), w in zip(mech.joints, stress, strict=True):
        links[b] = links.get(b, Matrix.zeros(6, 1)) + w.matrix
        links[a] = links.get(a, Matrix.zeros(6, 1)) - w.matrix
    balanced = all(v == Matrix.zeros(6, 1) for link, v in links.items() if link != mech.base)
    idle = all(power(t, w) == 0 for (_, _, j), w in zip(mech.joints, stress, strict=True)
               for t in j.twists.screws)
    return balanced and idle


def test_self_stresses_of_overconstrained_loops():
    """The reactions of an overconstrained loop are determined up to its self-stresses:
    ``self_stress=True`` gives a basis of them, as many as ``6 L - rank`` of the network
    matrix (the statics dual of Davies 1981: the loop equations' left null space), each
    balanced on every link and idle on every freedom; the particular reactions plus any
    combination still balance the links.  The planar four-bar has 3 (its out-of-plane
    force and moments), the Delta link by link 3 per parallelogram.  The checker rejects
    a wrench perturbed in one joint."""
    from screwsym.core.wrench import Wrench

    mech = fourbar()
    g = [0, Rational(-981, 100), 0]
    w, basis = mech.joint_reactions([0], [Rational(3, 2)], [Rational(-2, 3)], g, self_stress=True)
    mob = mech.mobility()
    assert len(basis) == 6 * mob.loops - mob.rank == 3
    assert w == mech.joint_reactions([0], [Rational(3, 2)], [Rational(-2, 3)], g)
    assert all(is_self_stress(mech, b) for b in basis)
    shaken = tuple(Wrench(*(r.matrix + 3 * b0.matrix - 2 * b2.matrix).reshape(2, 3).tolist())
                   for r, b0, b2 in zip(w, basis[0], basis[2], strict=True))
    difference = [Wrench(*(x.matrix - y.matrix).reshape(2, 3).tolist())
                  for x, y in zip(shaken, w, strict=True)]
    assert is_self_stress(mech, difference)
    wrong = list(basis[1])
    wrong[2] = Wrench(wrong[2].matrix[:3, 0], wrong[2].matrix[3:, 0] + Matrix([0, 0, 1]))
    assert not is_self_stress(mech, wrong)
    # the Delta link by link: five loops, three parallelograms
    delta = Mechanism([t for i, e in enumerate(DELTA_RADIAL) for t in delta_joints(i + 1, e)],
                      base="base", inertias={"platform": SpatialInertia(3, [0, 0, -3], diag(1, 1, 2))})
    _, basis = delta.joint_reactions([0, 7, 14], [1, -2, 0], [0, 0, 0], [0, 0, -10],
                                     self_stress=True)
    mob = delta.mobility()
    assert len(basis) == 6 * mob.loops - mob.rank
    assert all(is_self_stress(delta, b) for b in basis)


def test_joint_reactions_piecewise_with_symbols():
    """``conds="piecewise"``: the reactions of the four-bar whose coupler joint is at
    ``(x, y)`` hold where the crank drives it (``nan`` where coupler and rocker are in line),
    as columns in ray order; numbers put in give the numeric four-bar's wrenches."""
    x, y = symbols("x y", real=True)
    mech = fourbar_at(x, y)
    pw = mech.joint_reactions([0], [0], [0], [0, -10, 0], conds="piecewise")
    assert all(c.shape == (6, 1) for c in pw)
    assert any(isinstance(e, Piecewise) for e in pw[0])
    assert all(e.subs({x: Rational(5, 2), y: 1}) is nan for e in pw[0] if isinstance(e, Piecewise))
    numeric = mech.subs({x: 3, y: 3}).joint_reactions([0], [0], [0], [0, -10, 0])
    assert [c.subs({x: 3, y: 3}) for c in pw] == [r.matrix for r in numeric]
    # numbers: the condition is True and the wrenches come as without it
    assert mech.subs({x: 3, y: 3}).joint_reactions([0], [0], [0], [0, -10, 0],
                                                    conds="piecewise") == numeric
    with pytest.raises(TypeError, match="self_stress: expected True or False"):
        mech.joint_reactions([0], [0], [0], self_stress=1)


def test_a_rod_between_two_spherical_joints_is_refused_clearly():
    """An R-S-S-R linkage: the rod spins idly about its own axis (mobility 2, one idle
    freedom); whether one or two joints are actuated, the error names the idle freedom.
    With a universal joint in place of one S the same linkage has mobility 1 and works."""
    from screwsym.systems.joints import S, U

    rod = [("g", "crank", R([0, 0, 0], Z)), ("crank", "rod", S([1, 0, 0])),
           ("rod", "rocker", S([1, 3, 1])), ("rocker", "g", R([3, 3, 0], [1, 0, 0]))]
    inertias = {"rod": SpatialInertia.point_mass(1, [1, Rational(3, 2), Rational(1, 2)])}
    mech = Mechanism(rod, base="g", inertias=inertias)
    with pytest.raises(ValueError, match="mobility, 2, got 1; 1 of its freedoms are idle"):
        mech.mass_matrix([0])
    with pytest.raises(ValueError, match="1 idle freedoms .* universal joint"):
        mech.inverse_dynamics([0, 3], [1, 1], [0, 0])
    fixed = Mechanism(rod[:1] + [("crank", "rod", U([1, 0, 0], [0, 0, 1], [1, 0, 0]))] + rod[2:],
                      base="g", inertias=inertias)
    assert fixed.mass_matrix([0]).shape == (1, 1)


def test_delta_joint_reactions_balance_the_platform_and_do_no_work():
    """The Delta link by link (21 revolutes, overconstrained by its parallelograms): each
    reaction is reciprocal to its joint's twist but the actuators', whose power is the
    arm's torque; the three wrenches on the platform (it translates) sum to its mass times
    its acceleration minus its weight, ``m (a - g)``, with no moment about its centre, and the
    reactions at the base sum to the rate of change of the whole mechanism's momentum minus
    its weight (Newton's second law for the system)."""
    from _linkages import DELTA_RADIAL, delta_joints

    from screwsym.core.wrench import power

    inertias = {f"arm{i + 1}": SpatialInertia(2, [Rational(5, 2) * e[0], Rational(5, 2) * e[1],
                                                  Rational(-1, 2)], diag(1, 1, 1))
                for i, e in enumerate(DELTA_RADIAL)}
    inertias["platform"] = SpatialInertia(3, [0, 0, -3], diag(1, 1, 2))
    mech = Mechanism([t for i, e in enumerate(DELTA_RADIAL) for t in delta_joints(i + 1, e)],
                     base="base", inertias=inertias)
    qd, qdd, g = [1, -2, Rational(1, 2)], [Rational(1, 3), 0, -1], [0, 0, -10]
    w = mech.joint_reactions([0, 7, 14], qd, qdd, g)
    tau = mech.inverse_dynamics([0, 7, 14], qd, qdd, g)
    powers = [power(j.twists.screws[0], r) for (_, _, j), r in zip(mech.joints, w, strict=True)]
    assert powers == [tau[0]] + [0] * 6 + [tau[1]] + [0] * 6 + [tau[2]] + [0] * 6
    a = mech.link_acceleration("platform", [0, 7, 14], qd, qdd)
    assert a.matrix[:3, 0] == Matrix([0, 0, 0])  # a translation: its twist rate is (0; a)
    on_platform = w[6] + w[13] + w[20]
    assert on_platform.matrix[:3, 0] == 3 * (a.matrix[3:, 0] - Matrix(g))
    assert on_platform.moment_about([0, 0, -3]) == Matrix([0, 0, 0])
    # the force part of Newton's law for the whole mechanism: only the arms and the
    # platform have mass, each accelerating its centre of mass as m (a_c - g)
    arms_c = sum((I.mass * (Matrix(_com_acceleration(mech, link, qd, qdd)) - Matrix(g))
                  for link, I in inertias.items() if link.startswith("arm")), Matrix([0, 0, 0]))
    base = w[0] + w[7] + w[14]
    assert base.matrix[:3, 0] == arms_c + on_platform.matrix[:3, 0]
    assert base.matrix[:3, 0] != arms_c  # the checker sees the platform's share


def _com_acceleration(mech, link, qd, qdd):
    """A point's acceleration from its link's twist ``(w; v_O)`` and twist rate
    ``(w'; v_O')``: ``a = v_O' + w' x c + w x (v_O + w x c)``."""
    V = mech.link_twist(link, [0, 7, 14], qd).matrix
    A = mech.link_acceleration(link, [0, 7, 14], qd, qdd).matrix
    c = mech.inertias[link].com
    w, v, wd, vd = V[:3, 0], V[3:, 0], A[:3, 0], A[3:, 0]
    return vd + wd.cross(c) + w.cross(v + w.cross(c))


def test_delta_with_legs_120_degrees_apart_answers_within_a_small_budget():
    """Clavel's Delta with its legs 120 degrees apart (``sqrt(3)/2`` in the geometry): the
    actuation condition, once an uninterrupted elimination over SymPy's expression domain
    past 300 s, is decided over ``QQ<sqrt(3)>`` within a budget of 2e6 units (about 2 s),
    and the inverse dynamics at a moving state is Codourey's model (:func:`codourey`, the
    same vector algebra on this geometry), exactly; the checker rejects a heavier arm."""
    from sympy import radsimp, sqrt

    radial = [[1, 0, 0], [Rational(-1, 2), sqrt(3) / 2, 0], [Rational(-1, 2), -sqrt(3) / 2, 0]]
    qd, qdd, g = [1, -2, Rational(1, 2)], [Rational(1, 3), 0, -1], Matrix([0, 0, -10])
    mech, _, _, _, truth, _ = codourey(qd, qdd, g, radial=radial)
    assert mech.actuation_condition([0, 7, 14], budget=2_000_000) is true
    ours = mech.inverse_dynamics([0, 7, 14], qd, qdd, list(g), budget=10_000_000)

    def same(a, b):
        return all(radsimp(x - y).expand() == 0 for x, y in zip(a, b, strict=True))

    assert same(ours, truth)
    heavier = codourey(qd, qdd, g, m_arm=2 + Rational(1, 100), radial=radial)[4]
    assert not same(ours, heavier)
    # at a symbolic height the roots sit beside a symbol (SymPy's expression domain, its
    # eliminations uninterruptible): refused by the budget at once, not run for minutes
    z = symbols("z", real=True)
    high = Mechanism(delta_at([0, 0, z], radial), base="base")
    with pytest.raises(ValueError, match="actuation_condition: the exact arithmetic needs more"):
        high.actuation_condition([0, 7, 14])
    # the gallery's Delta (plot.models.delta) at its home pose x = y = 0, z = -3, the arms at
    # pi/4 (sqrt(2) and sqrt(3) in its geometry): decided within the budget, and True is
    # right: in floats the passive joints' columns of the network matrix (every joint a
    # revolute, one column each) have full rank, their least singular value far from zero
    from sympy import pi

    from screwsym.plot.models import delta

    d = delta()
    home = d.mechanism.subs(dict(zip(d.variables, [0, 0, -3, pi / 4, pi / 4, pi / 4],
                                     strict=True)))
    assert home.actuation_condition([0, 7, 14], budget=2_000_000) is true
    A = np.array(home.network_matrix().evalf(20).tolist(), dtype=float)
    passive = np.delete(A, [0, 7, 14], axis=1)
    smallest = np.linalg.svd(passive, compute_uv=False)[-1]
    assert passive.shape[1] == 18 and smallest > 1e-3 * np.linalg.norm(A, 2)
