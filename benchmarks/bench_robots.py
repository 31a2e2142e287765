"""Per-robot times: every serial arm of example-robot-data, default options, pinocchio beside.

Run from the repository root (needs ``pip install example-robot-data pin``)::

    python benchmarks/bench_robots.py            # every arm
    python benchmarks/bench_robots.py ur5 panda  # some
    python benchmarks/bench_robots.py --limit 120

For each arm of tests/crosscheck/test_example_robot_data.py (base: the root link, tip as
there), CPU time (``time.process_time``) of:

- ``load``: ``Chain.from_urdf(path, base, tip)``, default options (the angle rule, no inertias);
- ``FK+J``: ``chain.forward(q)`` and ``chain.jacobian(q)`` with symbolic joint angles ``q``;
- ``load+I``: ``Chain.from_urdf(..., inertias=True)``;
- ``M+tau``: ``chain.mass_matrix(q)`` and ``chain.inverse_dynamics(q, qd, qdd)`` at a seeded
  random state in floats (``sympy.Float``), gravity (0, 0, -9.81);
- ``pinocchio``: pinocchio's ``buildModelFromUrdf`` + FK + frame Jacobian + ``crba`` + ``rnea``
  at the same state (the reference: numbers only, C++).

Targets (issue 33): load + FK + J under 2 s, M + tau under 30 s.  A step over ``--limit``
seconds (default 60) is stopped (SIGALRM) and shown as ``> limit``; the steps after it are
not run.  Results go to stdout as a Markdown table.
"""

from __future__ import annotations

import argparse
import signal
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from sympy import Rational, symbols

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests" / "crosscheck"))

from screwsym import Chain  # noqa: E402


class OverLimit(Exception):
    pass


def _alarm(*_):
    raise OverLimit


def timed(limit, f, *args, **kwargs):
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(limit)
    start = time.process_time()
    try:
        return f(*args, **kwargs), time.process_time() - start
    except OverLimit:
        return None, None
    finally:
        signal.alarm(0)


def kinematics(chain, q):
    return chain.forward(q), chain.jacobian(q)


def dynamics(chain, q, qd, qdd, gravity):
    return chain.mass_matrix(q), chain.inverse_dynamics(q, qd, qdd, gravity=gravity)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("arms", nargs="*", help="arms to run (default: all)")
    parser.add_argument("--limit", type=int, default=60, help="seconds per step (default 60)")
    args = parser.parse_args()
    import pinocchio as pin
    import test_example_robot_data as erd

    warnings.simplefilter("ignore")
    arms = args.arms or list(erd.ARMS)
    over = f"> {args.limit}"
    print("| arm | joints | load | FK+J | load + FK + J | load+I | M+tau | pinocchio (all) |")
    print("|---|---|---|---|---|---|---|---|")
    for name in arms:
        path, tip = erd.ARMS[name]
        file = erd.ROOT / path
        chain, t_load = timed(args.limit, Chain.from_urdf, file, None, tip)
        cells = [name, "?", "", "", "", "", "", ""]
        if chain is not None:
            cells[1] = str(chain.n_joints)
            q = list(symbols(f"q1:{chain.n_joints + 1}", real=True))
            _, t_fkj = timed(args.limit, kinematics, chain, q)
            cells[2] = f"{t_load:.2f}"
            cells[3] = over if t_fkj is None else f"{t_fkj:.2f}"
            cells[4] = over if t_fkj is None else f"{t_load + t_fkj:.2f}"
            full, t_loadi = timed(args.limit, Chain.from_urdf, file, None, tip, inertias=True)
            cells[5] = over if t_loadi is None else f"{t_loadi:.2f}"
            if full is not None:
                qs, qd, qdd = erd.states(name, chain.n_joints, 1)[0]
                F = erd.floats
                g = [0, 0, Rational(-981, 100)]
                _, t_dyn = timed(args.limit, dynamics, full, F(qs), F(qd), F(qdd), g)
                cells[6] = over if t_dyn is None else f"{t_dyn:.2f}"
                start = time.process_time()
                ref = erd.Pinocchio(name, as_written=True)
                ref.model = pin.buildModelFromUrdf(str(file))
                ref.data = ref.model.createData()
                ref.kinematics(qs)
                ref.dynamics(qs, qd, qdd)
                cells[7] = f"{time.process_time() - start:.4f}"
        else:
            cells[2] = over
        print("| " + " | ".join(cells) + " |", flush=True)
    print(f"\nCPU seconds, {time.strftime('%Y-%m-%d')}, numpy {np.__version__}; "
          f"Float states; symbolic q for FK+J.", flush=True)


if __name__ == "__main__":
    main()
