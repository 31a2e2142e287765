"""Benchmark the dynamics of a chain on the UR5 with the inertias of Modern Robotics.

Run from the repository root::

    .venv/bin/python benchmarks/bench_dynamics.py              # N = 100,000 states
    .venv/bin/python benchmarks/bench_dynamics.py --n 20000

Measured side by side in one process:

1. Symbolic: ``Chain.mass_matrix`` (composite rigid bodies) with six symbolic joint
   angles, and ``Chain.inverse_dynamics`` (Newton-Euler) with symbolic ``q, qd, qdd``,
   the inertias numeric (exact rationals read from the Modern Robotics course's UR5
   ``Glist``/``Mlist``, tests/_dynamics.py) and gravity ``(0, 0, -981/100)``; cold caches.
   Target: under 10 s together.
2. Numeric: the inverse dynamics generated with ``screwsym.lambdify`` (numba when
   installed, else NumPy) on N states at once, against pinocchio's ``rnea`` and
   modern_robotics' ``InverseDynamics`` called in a Python loop (timed on a subset, per
   state).  Target: at least 50x faster per state than ``rnea`` in a Python loop.

Nothing here is asserted; the figures go to the report and ``benchmarks/README.md``.
"""

from __future__ import annotations

import argparse
import importlib.util
import sys
import time
from pathlib import Path

import numpy as np
from sympy import ImmutableMatrix, Rational, count_ops, symbols

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))  # the UR5 data
from _dynamics import mr_ur5_chain, mr_ur5_lists  # noqa: E402

from screwsym import lambdify  # noqa: E402


def timed(fn, *args):
    t0 = time.perf_counter()
    out = fn(*args)
    return out, time.perf_counter() - t0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000, help="states for the numeric part")
    parser.add_argument("--loop", type=int, default=2000, help="states for the Python loops")
    args = parser.parse_args()

    arm = mr_ur5_chain()
    q = ImmutableMatrix(symbols("q1:7", real=True))
    qd = ImmutableMatrix(symbols("qd1:7", real=True))
    qdd = ImmutableMatrix(symbols("qdd1:7", real=True))
    gravity = [0, 0, -Rational(981, 100)]
    rows = []
    H, t_mass = timed(arm.mass_matrix, q)
    rows.append(("mass_matrix(q), symbolic (CRBA)", f"{t_mass:.2f} s", f"{sum(count_ops(e) for e in H)} ops"))
    tau, t_id = timed(arm.inverse_dynamics, q, qd, qdd, gravity)
    rows.append(("inverse_dynamics(q, qd, qdd), symbolic (RNEA)", f"{t_id:.2f} s",
                 f"{sum(count_ops(e) for e in tau)} ops"))
    rows.append(("  together (target < 10 s)", f"{t_mass + t_id:.2f} s", ""))

    backend = "numba" if importlib.util.find_spec("numba") else "numpy"
    f, t_gen = timed(lambda: lambdify([q, qd, qdd], tau, backend, names=["q", "qd", "qdd"]))
    rng = np.random.default_rng(0)
    Q, QD, QDD = rng.uniform(-np.pi, np.pi, size=(3, args.n, 6))
    f(Q[:2], QD[:2], QDD[:2])  # compile
    _, t_gen_first = timed(lambda: None)
    out, t_batch = timed(f, Q, QD, QDD)
    per_ours = t_batch / args.n
    rows.append((f"lambdify ({backend}) generation", f"{t_gen:.2f} s", ""))
    rows.append((f"generated inverse dynamics, {args.n} states", f"{t_batch * 1e3:.1f} ms",
                 f"{per_ours * 1e9:.0f} ns/state"))

    Mlist, Glist, Slist = mr_ur5_lists()
    import modern_robotics as mr

    k = min(args.loop, args.n)
    g = np.array([0, 0, -9.81])
    t0 = time.perf_counter()
    ref = [mr.InverseDynamics(Q[i], QD[i], QDD[i], g, np.zeros(6), Mlist, Glist, Slist) for i in range(k)]
    per_mr = (time.perf_counter() - t0) / k
    err = np.abs(np.asarray(out).reshape(args.n, 6)[:k] - np.array(ref)).max()
    rows.append(("modern_robotics InverseDynamics, Python loop", f"{per_mr * 1e6:.1f} us/state",
                 f"ours {per_mr / per_ours:.0f}x faster; max |diff| {err:.1e}"))
    try:
        import pinocchio as pin
    except ImportError:
        rows.append(("pinocchio rnea", "not installed", ""))
    else:
        sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests" / "crosscheck"))
        from test_dynamics_peers import _pin_model

        model = _pin_model(pin, arm)
        data = model.createData()
        t0 = time.perf_counter()
        ref = [pin.rnea(model, data, Q[i], QD[i], QDD[i]).copy() for i in range(k)]
        per_pin = (time.perf_counter() - t0) / k
        err = np.abs(np.asarray(out).reshape(args.n, 6)[:k] - np.array(ref)).max()
        rows.append(("pinocchio rnea, Python loop", f"{per_pin * 1e6:.2f} us/state",
                     f"ours {per_pin / per_ours:.1f}x faster (target >= 50x); max |diff| {err:.1e}"))
    width = max(len(r[0]) for r in rows)
    print(f"UR5 (Modern Robotics inertias), screwsym {__import__('screwsym').__version__}")
    for name, value, note in rows:
        print(f"{name:<{width}}  {value:>16}  {note}")


if __name__ == "__main__":
    main()
