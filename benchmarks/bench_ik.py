"""Benchmark the UR5's closed-form inverse kinematics (issue 36 targets).

Run from the repository root::

    python benchmarks/bench_ik.py
    python benchmarks/bench_ik.py --poses 10000 --rounds 3

Three figures, all CPU time (``time.process_time``):

1. generation: the decomposition found from the twists, each stage's closed form
   (``stage_forms``) and its compilation by ``screwsym.lambdify``
   (``numeric.inverse_kinematics_function``), in a fresh process for each back end
   (target: under 60 s; IKFast "usually within 10 minutes");
2. the solver per pose, batched: ``f(T)`` on ``--poses`` poses ``(N, 4, 4)`` giving
   ``(N, 8, 6)``, best of ``--rounds``, per pose (target: under 5 us; IKFast's published ~4 us
   per solve), side by side with the peer modern_robotics ``IKinSpace`` (Newton's method from
   a guess 0.1 rad off, one branch per call) on a subset, in the same run;
3. round trips on ``--poses`` random poses away from singularities (the smallest singular
   value of the space Jacobian over 0.05, modern_robotics): the joints that made the pose
   are among the branches (to 1e-8 rad) and every branch that exists reproduces the pose
   under modern_robotics' ``FKinSpace`` (to 1e-9) (target: 100 %).
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

GENERATE = """
import time
t = time.process_time()
from screwsym.motion.chain import ur5
from screwsym.numeric import inverse_kinematics_function
f = inverse_kinematics_function(ur5(), backend={backend!r})
import numpy as np
f(np.eye(4)[None])
print(time.process_time() - t)
"""


def generation(backend: str) -> float:
    out = subprocess.run([sys.executable, "-c", GENERATE.format(backend=backend)],
                         capture_output=True, text=True, check=True, cwd=ROOT,
                         env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    return float(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--poses", type=int, default=10_000)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--peer", type=int, default=200, help="poses for modern_robotics IKinSpace")
    args = parser.parse_args()

    import modern_robotics as mr

    from screwsym.motion.chain import ur5
    from screwsym.numeric import inverse_kinematics_function

    arm = ur5()
    S = np.array([[float(x) for x in t.matrix] for t in arm.twists]).T
    M = np.array(arm.home.matrix, dtype=float)
    backends = ["numpy"]
    try:
        import numba  # noqa: F401
        backends.append("numba")
    except ImportError:
        pass

    print("1. generation (fresh process, CPU s):")
    for b in backends:
        print(f"   {b:6s} {generation(b):7.2f} s   (target < 60 s)")

    rng = np.random.default_rng(2026)
    qs, Ts = [], []
    while len(qs) < args.poses:
        q = rng.uniform(-np.pi, np.pi, 6)
        if np.linalg.svd(mr.JacobianSpace(S, q), compute_uv=False)[-1] > 0.05:
            qs.append(q)
            Ts.append(mr.FKinSpace(M, S, q))
    q = np.array(qs)
    T = np.array(Ts)

    print(f"2. solver, {args.poses} poses batched (best of {args.rounds}, CPU us per pose):")
    for b in backends:
        f = inverse_kinematics_function(arm, backend=b)
        f(T[:10])
        best = min(_timed(f, T) for _ in range(args.rounds))
        print(f"   screwsym {b:6s} {best / args.poses * 1e6:8.2f} us   (target < 5 us)")
    guesses = q[: args.peer] + 0.1
    t0 = time.process_time()
    converged = sum(mr.IKinSpace(S, M, T[k], guesses[k], 1e-9, 1e-9)[1] for k in range(args.peer))
    peer = (time.process_time() - t0) / args.peer
    print(f"   modern_robotics IKinSpace (one branch, Newton from 0.1 rad off) {peer * 1e6:8.1f} us "
          f"({converged}/{args.peer} converged)")

    print(f"3. round trips on {args.poses} poses away from singularities:")
    for b in backends:
        branches = inverse_kinematics_function(arm, backend=b)(T)
        d = np.mod(branches - q[:, None, :] + np.pi, 2 * np.pi) - np.pi
        among = (np.abs(d).max(axis=2) < 1e-8).any(axis=1)
        live = ~np.isnan(branches).any(axis=2)
        worst = 0.0
        for k in range(args.poses):
            for br in branches[k][live[k]]:
                worst = max(worst, float(np.abs(mr.FKinSpace(M, S, br) - T[k]).max()))
        print(f"   {b:6s} q among the branches: {among.mean() * 100:.2f} %; branches existing: "
              f"{live.sum()} ({live.sum(axis=1).mean():.2f} a pose); worst FK error of a branch {worst:.1e}")


def _timed(f, T) -> float:
    t0 = time.process_time()
    f(T)
    return time.process_time() - t0


if __name__ == "__main__":
    main()
