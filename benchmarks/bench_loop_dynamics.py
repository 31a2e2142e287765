"""Benchmark the dynamics of closed loops (issue 35): the four-bar and the Delta robot.

Run from the repository root::

    python benchmarks/bench_loop_dynamics.py              # N = 100,000 states
    python benchmarks/bench_loop_dynamics.py --n 20000 --skip-delta-z

Measured side by side in one process, cold caches per case:

1. Symbolic (``Mechanism.mass_matrix`` and ``Mechanism.inverse_dynamics`` with symbolic
   actuated rates and accelerations, exact):
   - the four-bar of tests/systems/test_loop_dynamics.py at its numeric configuration;
   - the Delta robot link by link (tests/_linkages.py: three arms, six rods, 21 revolutes,
     the platform and the arms with inertia) at the numeric pose ``z = -3``;
   - the same Delta with its platform at a symbolic height ``z`` (one pose symbol);
   - the same Delta at a symbolic pose ``(x, y, z)`` (the issue's target: under 30 s): the
     closed forms are refused by the default budget (the time to refuse is reported); the
     straight-line programs of ``numeric.loop_dynamics_program`` are written (CPU seconds,
     their operation counts) and evaluated exactly at a numeric pose against the exact
     closed forms there.
2. Numeric: the generated inverse dynamics (``numeric.loop_dynamics_functions``, the
   closed form through ``screwsym.lambdify``, numba when installed) on N states at once,
   per state, for a parallelogram four-bar in its crank angle and the Delta in its height
   ``z``; against pinocchio 3's ``constraintDynamics`` (the proximal constrained forward
   dynamics, Carpentier et al., RSS 2021) on the four-bar of the tests, called in a Python
   loop; the Delta at a symbolic pose ``(x, y, z)`` as programs on numba, C and NumPy
   against pinocchio's Delta; Clavel's Delta over its workspace (``plot.models.delta()``,
   placed by ``x, y, z`` and the arms' angles from its inverse kinematics) on numba.  Not the same problem: pinocchio solves the forward dynamics (accelerations from
   torques), ours the inverse; this is the comparison the issue's target names (at least
   10x faster per state).

Nothing here is asserted; the figures go to the report and ``benchmarks/README.md``.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
from sympy import Rational, cos, diag, sin, symbols

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests" / "systems"))
from _linkages import DELTA_RADIAL, delta_joints  # noqa: E402

from screwsym.core.inertia import SpatialInertia  # noqa: E402
from screwsym.numeric import loop_dynamics_functions, loop_dynamics_program  # noqa: E402
from screwsym.systems.joints import R  # noqa: E402
from screwsym.systems.linkage import Mechanism  # noqa: E402

Z = [0, 0, 1]
ACT = [0, 7, 14]


def timed(f, *args, **kw):
    t0 = time.perf_counter()
    out = f(*args, **kw)
    return out, time.perf_counter() - t0


def fourbar():
    from test_loop_dynamics import fourbar as make

    return make()


def delta_inertias(top):
    inertias = {f"arm{i + 1}": SpatialInertia(2, [Rational(5, 2) * e[0], Rational(5, 2) * e[1],
                                                  Rational(-1, 2)], diag(1, 1, 1))
                for i, e in enumerate(DELTA_RADIAL)}
    inertias["platform"] = SpatialInertia(3, top, diag(1, 1, 2))
    return inertias


def delta_numeric():
    joints = [t for i, e in enumerate(DELTA_RADIAL) for t in delta_joints(i + 1, e)]
    return Mechanism(joints, base="base", inertias=delta_inertias([0, 0, -3]))


def delta_symbolic(top):
    from test_loop_dynamics import delta_at

    return Mechanism(delta_at(top), base="base", inertias=delta_inertias(top))


def delta_compound(top):
    """The same Delta with each forearm one compound ``Parallelogram`` joint (12 joints, 4
    per leg; equal to the link-by-link Delta where the rods have no mass: a test shows it)."""
    from _linkages import HALF, add, scale, sub

    from screwsym.systems.joints import Parallelogram

    def leg(i, e):
        u = [-e[1], e[0], 0]
        b = scale(2, e)
        elbow = add(add(b, e), [0, 0, -1])
        attach = add(top, e)
        pair = Parallelogram(add(elbow, scale(HALF, u)), sub(elbow, scale(HALF, u)),
                             add(attach, scale(HALF, u)))
        return [("base", f"arm{i}", R(b, u)), (f"arm{i}", f"upper{i}", R(elbow, u)),
                (f"upper{i}", f"lower{i}", pair), (f"lower{i}", "platform", R(attach, u))]

    return Mechanism([t for i, e in enumerate(DELTA_RADIAL) for t in leg(i + 1, e)],
                     base="base", inertias=delta_inertias(top))


def clavel_delta():
    """plot.models.delta() with inertias: each arm a rod of mass 2 (centre at its middle,
    moving with its angle), the platform of mass 3 at (x, y, z)."""
    from sympy import sqrt

    from screwsym.plot.models import delta

    d = delta()
    x, y, z, *thetas = d.variables
    inertias = {}
    for i, (e, th) in enumerate(zip(DELTA_RADIAL, thetas, strict=True)):
        mid = [2 * e[0] + sqrt(2) / 2 * cos(th) * e[0], 2 * e[1] + sqrt(2) / 2 * cos(th) * e[1],
               -sqrt(2) / 2 * sin(th)]
        inertias[f"arm{i + 1}"] = SpatialInertia(2, mid, diag(1, 1, 1))
    inertias["platform"] = SpatialInertia(3, [x, y, z], diag(1, 1, 2))
    mech = Mechanism(list(d.mechanism.joints), base="base", inertias=inertias)
    return type(d)(mech, d.variables, d.radius, d.arm, d.rod)


def parallelogram(t):
    A, B = [cos(t), sin(t), 0], [cos(t) + 2, sin(t), 0]
    inertias = {"crank": SpatialInertia(1, [cos(t) / 2, sin(t) / 2, 0], diag(1, 1, Rational(1, 5))),
                "coupler": SpatialInertia(2, [cos(t) + 1, sin(t), 0], diag(1, 1, Rational(1, 3))),
                "rocker": SpatialInertia(1, [cos(t) / 2 + 2, sin(t) / 2, 0], diag(1, 1, Rational(1, 7)))}
    return Mechanism([("ground", "crank", R([0, 0, 0], Z)), ("crank", "coupler", R(A, Z)),
                      ("coupler", "rocker", R(B, Z)), ("rocker", "ground", R([2, 0, 0], Z))],
                     base="ground", inertias=inertias)


def symbolic_part(skip_z):
    print("1. symbolic (exact), cold caches")
    k1, k2, k3 = symbols("qd1:4", real=True), symbols("qdd1:4", real=True), None
    mech = fourbar()
    _, th = timed(mech.mass_matrix, [0])
    tau, ti = timed(mech.inverse_dynamics, [0], [k1[0]], [k2[0]])
    print(f"   four-bar, numeric configuration: mass matrix {th:.2f} s, inverse dynamics "
          f"(symbolic rates) {ti:.2f} s")
    mech = delta_numeric()
    _, th = timed(mech.mass_matrix, ACT)
    _, ti = timed(mech.inverse_dynamics, ACT, list(k1), list(k2))
    print(f"   Delta link by link at z = -3: mass matrix {th:.2f} s, inverse dynamics "
          f"(symbolic rates) {ti:.2f} s")
    if not skip_z:
        z = symbols("z", real=True)
        mech = delta_symbolic([0, 0, z])
        _, th = timed(mech.mass_matrix, ACT)
        try:
            _, ti = timed(mech.inverse_dynamics, ACT, list(k1), list(k2))
            ti_s = f"{ti:.2f} s"
        except ValueError as err:
            ti_s = f"refused by the budget ({str(err)[:60]}...)"
        print(f"   Delta at a symbolic height z: mass matrix {th:.2f} s, inverse dynamics "
              f"(symbolic rates) {ti_s}")
    x, y, z = symbols("x y z", real=True)
    if not skip_z:
        mech = delta_compound([0, 0, z])
        _, th = timed(mech.mass_matrix, [0, 4, 8])
        print(f"   Delta with compound parallelograms at a symbolic height z: mass matrix "
              f"{th:.2f} s")
        mech = delta_compound([x, y, z])
        t0 = time.perf_counter()
        try:
            H = mech.mass_matrix([0, 4, 8])
            budget = "the default budget"
        except ValueError:
            budget = "budget=10**12 (refused by the default one)"
            H = mech.mass_matrix([0, 4, 8], budget=10**12)
        print(f"   Delta with compound parallelograms at a symbolic pose (x, y, z), {budget}: "
              f"mass matrix {time.perf_counter() - t0:.2f} s ({sum(len(str(e)) for e in H)} "
              "characters; its inverse dynamics with symbolic rates ran past 14 minutes: "
              "not timed here)")
    mech = delta_symbolic([x, y, z])
    t0 = time.perf_counter()
    try:
        mech.mass_matrix(ACT)
        print(f"   Delta at a symbolic pose (x, y, z), closed form: mass matrix "
              f"{time.perf_counter() - t0:.2f} s")
    except ValueError:
        print(f"   Delta at a symbolic pose (x, y, z), closed form: refused by the default "
              f"budget after {time.perf_counter() - t0:.2f} s")
    del k3
    # the straight-line programs (numeric.loop_program), fresh mechanism: CPU seconds
    mech = delta_symbolic([x, y, z])
    c0 = time.process_time()
    tau = loop_dynamics_program(mech, ACT, [x, y, z], gravity=(0, 0, -9.81))
    c1 = time.process_time()
    H = loop_dynamics_program(mech, ACT, [x, y, z], "mass_matrix")
    c2 = time.process_time()
    total = c2 - c0
    print(f"   Delta at a symbolic pose (x, y, z), straight-line programs: inverse dynamics "
          f"{c1 - c0:.2f} s CPU ({tau.operations()}, {len(tau.assignments)} assignments, "
          f"{len(tau.conditions)} pivot conditions), mass matrix {c2 - c1:.2f} s CPU "
          f"({H.operations()}) -> {total:.2f} s in all (target under 30 s: "
          f"{'met' if total < 30 else 'NOT met'})")
    pt = [Rational(1, 5), Rational(-1, 7), -3]
    exact = delta_symbolic(pt)
    qd, qdd = [Rational(1, 2), Rational(-2, 3), Rational(1, 4)], [Rational(3, 2), Rational(1, 3), 1]
    g = [0, 0, Rational(-981, 100)]
    tau_x = loop_dynamics_program(mech, ACT, [x, y, z], gravity=g)
    same = ((tau_x.evaluate(pt, qd, qdd) - exact.inverse_dynamics(ACT, qd, qdd, g)).expand()
            .is_zero_matrix and (H.evaluate(pt) - exact.mass_matrix(ACT)).expand().is_zero_matrix)
    print(f"   ... evaluated exactly at (1/5, -1/7, -3) with exact rates: equal to the exact "
          f"mass_matrix and inverse_dynamics there: {same}")
    mech = delta_compound([x, y, z])
    c0 = time.process_time()
    tau = loop_dynamics_program(mech, [0, 4, 8], [x, y, z], gravity=g)
    H = loop_dynamics_program(mech, [0, 4, 8], [x, y, z], "mass_matrix")
    c1 = time.process_time()
    exact = delta_compound(pt)
    same = ((tau.evaluate(pt, qd, qdd) - exact.inverse_dynamics([0, 4, 8], qd, qdd, g)).expand()
            .is_zero_matrix and (H.evaluate(pt) - exact.mass_matrix([0, 4, 8])).expand()
            .is_zero_matrix)
    print(f"   Delta with compound parallelograms at (x, y, z), straight-line programs: M and "
          f"tau {c1 - c0:.2f} s CPU in all (tau {tau.operations()}, H {H.operations()}); "
          f"exact at (1/5, -1/7, -3): {same}")


def pinocchio_fourbar():
    import pinocchio as pin
    from test_loop_dynamics import pinocchio_fourbar as build

    model, data, cms, cds = build(pin)
    prox = pin.ProximalSettings(1e-12, 1e-10, 100)
    return pin, model, data, cms, cds, prox


def pinocchio_delta():
    """The same Delta's geometry in pinocchio at z = -3: each arm a revolute on the base, each
    parallelogram two rods on spherical joints at the elbow, closed on the platform (a free
    flyer) by six 3D point constraints (the rods' spins are idle there; the proximal solver
    copes).  Not the link-by-link model of the symbolic part: the size of the problem
    (27 velocities, 18 constraint rows) for timing, not a check."""
    import pinocchio as pin

    model = pin.Model()
    fl = [[float(x) for x in e] for e in DELTA_RADIAL]
    top = np.array([0.0, 0.0, -3.0])
    plat = model.addJoint(0, pin.JointModelFreeFlyer(), pin.SE3(np.eye(3), top), "platform")
    model.appendBodyToJoint(plat, pin.Inertia(3.0, np.zeros(3), np.diag([1.0, 1.0, 2.0])),
                            pin.SE3.Identity())
    pending = []
    for i, e in enumerate(fl):
        e = np.array(e)
        u = np.array([-e[1], e[0], 0.0])
        b, elbow, attach = 2 * e, 3 * e + np.array([0, 0, -1.0]), top + e
        arm = model.addJoint(0, pin.JointModelRevoluteUnaligned(u), pin.SE3(np.eye(3), b),
                             f"arm{i}")
        model.appendBodyToJoint(arm, pin.Inertia(2.0, 0.5 * e + np.array([0, 0, -0.5]),
                                                 np.eye(3)), pin.SE3.Identity())
        for s in (0.5, -0.5):
            rod = model.addJoint(arm, pin.JointModelSpherical(),
                                 pin.SE3(np.eye(3), elbow + s * u - b), f"rod{i}{s}")
            model.appendBodyToJoint(rod, pin.Inertia(0.1, (attach - elbow) / 2,
                                                     0.01 * np.eye(3)), pin.SE3.Identity())
            pending.append((rod, attach - elbow, attach + s * u - top))
    model.gravity.linear = np.array([0, 0, -9.81])
    data = model.createData()
    cms, cds = pin.StdVec_RigidConstraintModel(), pin.StdVec_RigidConstraintData()
    for rod, on_rod, on_platform in pending:
        cm = pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, model, rod,
                                      pin.SE3(np.eye(3), on_rod), plat,
                                      pin.SE3(np.eye(3), on_platform), pin.ReferenceFrame.LOCAL)
        cms.append(cm)
        cds.append(cm.createData())
    pin.initConstraintDynamics(model, data, cms, cds)
    return pin, model, data, cms, cds, pin.ProximalSettings(1e-12, 1e-10, 100), pin.neutral(model)


def pinocchio_per_state(built, m, rng, actuated):
    pin, model, data, cms, cds, prox, q0 = built
    V = np.zeros((m, model.nv))
    T = np.zeros((m, model.nv))
    T[:, actuated] = rng.normal(size=(m, len(actuated)))
    t0 = time.perf_counter()
    for i in range(m):
        pin.constraintDynamics(model, data, q0, V[i], T[i], cms, cds, prox)
    return (time.perf_counter() - t0) / m


def numeric_part(n, skip_z):
    print(f"2. numeric, N = {n} states")
    rng = np.random.default_rng(35)
    t = symbols("t", real=True)
    q = rng.uniform(0.2, 2.9, (n, 1))
    qd, qdd = rng.normal(size=(n, 1)), rng.normal(size=(n, 1))
    for form in ("closed", "program"):
        f, tg = timed(loop_dynamics_functions, parallelogram(t), [0], [t], (0, -9.81, 0),
                      form=form)
        f.inverse_dynamics(q[:10], qd[:10], qdd[:10])  # compile / warm
        best = min(timed(f.inverse_dynamics, q, qd, qdd)[1] for _ in range(3))
        ours4 = best / n
        print(f"   generated four-bar inverse dynamics, form={form!r}: built in {tg:.2f} s, "
              f"{ours4 * 1e9:.0f} ns per state batched")
    try:
        pin, model, data, cms, cds, prox = pinocchio_fourbar()
    except ImportError:
        print("   pinocchio not installed: no comparison")
        return
    m = min(n, 20000)
    pin_per = pinocchio_per_state((pin, model, data, cms, cds, prox, np.zeros(3)), m, rng,
                                  [0])
    print(f"   pinocchio constraintDynamics, four-bar, Python loop: {pin_per * 1e9:.0f} ns per "
          f"state -> ours {pin_per / ours4:.0f}x faster per state")
    built = pinocchio_delta()
    arms = [built[1].joints[built[1].getJointId(f"arm{i}")].idx_v for i in range(3)]
    pin_delta = pinocchio_per_state(built, min(n, 5000), rng, arms)
    print(f"   pinocchio constraintDynamics, Delta (6 S-S rods, 18 constraint rows), Python "
          f"loop: {pin_delta * 1e9:.0f} ns per state")
    x, y, z = symbols("x y z", real=True)
    for backend in ("numba", "c", "numpy"):
        c0, w0 = time.process_time(), time.perf_counter()
        fp = loop_dynamics_functions(delta_symbolic([x, y, z]), ACT, [x, y, z], (0, 0, -9.81),
                                     backend)
        p = np.column_stack([rng.uniform(-0.5, 0.5, n), rng.uniform(-0.5, 0.5, n),
                             rng.uniform(-3.5, -2.5, n)])
        qd, qdd = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
        fp.inverse_dynamics(p[:10], qd[:10], qdd[:10])
        built, wall = time.process_time() - c0, time.perf_counter() - w0
        best = min(timed(fp.inverse_dynamics, p, qd, qdd)[1] for _ in range(3))
        bestH = min(timed(fp.mass_matrix, p)[1] for _ in range(3))
        print(f"   generated Delta at a symbolic pose (x, y, z), program form, {backend}: built "
              f"and compiled in {built:.2f} s CPU ({wall:.2f} s wall, a C compiler's included; "
              f"on-disk caches may serve); inverse dynamics {best / n * 1e9:.0f} ns per "
              f"state batched -> {pin_delta / (best / n):.0f}x faster than pinocchio's Delta "
              f"per state (target 10x); mass matrix {bestH / n * 1e9:.0f} ns per state")
    # one Delta over its workspace: plot.models.delta(), placed by x, y, z and the arms'
    # angles theta1..3 (the rods keep their length where the angles come from
    # Delta.configurations, the closed-form inverse kinematics)
    d = clavel_delta()
    c0 = time.process_time()
    fw = loop_dynamics_functions(d.mechanism, ACT, list(d.variables), (0, 0, -9.81), "numba")
    pts = np.column_stack([rng.uniform(-0.4, 0.4, n), rng.uniform(-0.4, 0.4, n),
                           rng.uniform(-3.2, -2.8, n)])
    p = d.configurations(pts)
    qd, qdd = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
    fw.inverse_dynamics(p[:10], qd[:10], qdd[:10])
    built = time.process_time() - c0
    best = min(timed(fw.inverse_dynamics, p, qd, qdd)[1] for _ in range(3))
    print(f"   Clavel's Delta over its workspace (plot.models.delta: x, y, z, theta1..3), program "
          f"form, numba: built and compiled in {built:.2f} s CPU ({fw.tau.operations()}); "
          f"inverse dynamics {best / n * 1e9:.0f} ns per state batched -> "
          f"{pin_delta / (best / n):.0f}x faster than pinocchio's Delta per state")
    if skip_z:
        return
    for form in ("closed", "program"):
        try:
            fd, tg = timed(loop_dynamics_functions, delta_symbolic([0, 0, z]), ACT, [z],
                           (0, 0, -9.81), form=form)
        except ValueError as err:
            print(f"   Delta at a symbolic height, form={form!r}: not generated ({err})")
            continue
        p = rng.uniform(-4, -2, (n, 1))
        qd, qdd = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
        fd.inverse_dynamics(p[:10], qd[:10], qdd[:10])
        best = min(timed(fd.inverse_dynamics, p, qd, qdd)[1] for _ in range(3))
        print(f"   generated Delta inverse dynamics (in its height z), form={form!r}: built in "
              f"{tg:.2f} s, {best / n * 1e9:.0f} ns per state batched -> "
              f"{pin_delta / (best / n):.0f}x faster than pinocchio's Delta per state (a family "
              "of Deltas in z only, arms fixed)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=100_000)
    ap.add_argument("--skip-delta-z", action="store_true")
    args = ap.parse_args()
    symbolic_part(args.skip_delta_z)
    numeric_part(args.n, args.skip_delta_z)


if __name__ == "__main__":
    main()
