"""Benchmark the UR5's closed-form inverse kinematics (issue 36 targets).

Run from the repository root::

    python benchmarks/bench_ik.py
    python benchmarks/bench_ik.py --poses 10000 --rounds 3

Three figures, all CPU time (``time.process_time``), for the solver
``numeric.inverse_kinematics_function`` (every branch one generated program, one loop
over the poses: "fused") in each back end, and side by side, in the same run, the solver
it replaced (each stage compiled on its own and evaluated in turn on arrays: "staged",
``screwsym.numeric.ik._staged``, the "before"):

1. generation: the decomposition found from the twists, each stage's closed form
   (``stage_forms``) and its compilation by ``screwsym.lambdify``, in a fresh process for
   each back end (target: under 60 s; IKFast "usually within 10 minutes");
2. the solver per pose, batched: ``f(T)`` on ``--poses`` poses ``(N, 4, 4)`` giving
   ``(N, 8, 6)``, best of ``--rounds``, per pose (target: under 5 us; IKFast's published ~4 us
   per solve), and one pose ``(4, 4)`` per call; side by side with the peer modern_robotics
   ``IKinSpace`` (Newton's method from a guess 0.1 rad off, one branch per call) on a subset;
   and a batch of one pose ``(1, 4, 4)`` per call, which takes the array code (in NumPy the
   one-pose path before the single-point path on floats reached programs of this size);
3. round trips on ``--poses`` random poses away from singularities (the smallest singular
   value of the space Jacobian over 0.05, modern_robotics): the joints that made the pose
   are among the branches (to 1e-8 rad) and every branch that exists reproduces the pose
   under modern_robotics' ``FKinSpace`` (to 1e-9) (target: 100 %), for the default back end;
   every other back end and the staged solver agree with it (NaN in the same places).

``--quick`` skips the fresh-process generation (figure 1); ``--backends numpy`` measures NumPy
alone (as on a machine without a C compiler or numba).
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
from screwsym.numeric.ik import _fused, _staged
f = {solver}(ur5(), (), {backend!r})
import numpy as np
f(np.eye(4)[None])
print(time.process_time() - t)
"""


def generation(solver: str, backend: str) -> float:
    """CPU seconds in a fresh process (the on-disk caches of lambdify off: a cold build)."""
    import tempfile

    with tempfile.TemporaryDirectory(prefix="bench-ik-") as cache:
        return _generation(solver, backend, cache)


def _generation(solver: str, backend: str, cache: str) -> float:
    out = subprocess.run([sys.executable, "-c", GENERATE.format(solver=solver, backend=backend)],
                         capture_output=True, text=True, check=True, cwd=ROOT,
                         env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin",
                              "SCREWSYM_CACHE_DIR": cache, "NUMBA_CACHE_DIR": cache})
    return float(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--poses", type=int, default=10_000)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--peer", type=int, default=200, help="poses for modern_robotics IKinSpace")
    parser.add_argument("--quick", action="store_true", help="skip the fresh-process generation")
    parser.add_argument("--backends", default="numpy,numba,c",
                        help="comma-separated back ends to measure, those available among them "
                             "(--backends numpy: NumPy alone, as without a compiler or numba)")
    args = parser.parse_args()

    import modern_robotics as mr

    from screwsym.motion.chain import ur5
    from screwsym.numeric.ik import _fused, _staged, fastest_backend

    arm = ur5()
    S = np.array([[float(x) for x in t.matrix] for t in arm.twists]).T
    M = np.array(arm.home.matrix, dtype=float)
    wanted = set(args.backends.split(","))
    backends = ["numpy"] if "numpy" in wanted else []
    try:
        import numba  # noqa: F401
        if "numba" in wanted:
            backends.append("numba")
    except ImportError:
        pass
    from screwsym.codegen._build import compiler
    if compiler() is not None and "c" in wanted:
        backends.append("c")
    if not backends:
        parser.error(f"--backends: none of {args.backends!r} is available")
    default = fastest_backend() if fastest_backend() in backends else backends[-1]
    solvers = [("fused", _fused, b) for b in backends] + [("staged", _staged, b) for b in backends
                                                          if b != "c"]

    if not args.quick:
        print("1. generation (fresh process, empty caches, CPU s; target < 60 s, IKFast ~10 min):")
        for label, solver, b in solvers:
            print(f"   {label:6s} {b:6s} {generation(solver.__name__, b):7.2f} s")

    rng = np.random.default_rng(2026)
    qs, Ts = [], []
    while len(qs) < args.poses:
        q = rng.uniform(-np.pi, np.pi, 6)
        if np.linalg.svd(mr.JacobianSpace(S, q), compute_uv=False)[-1] > 0.05:
            qs.append(q)
            Ts.append(mr.FKinSpace(M, S, q))
    q = np.array(qs)
    T = np.array(Ts)

    print(f"2. solver, {args.poses} poses (CPU us per pose, best of {args.rounds}; "
          "target < 5 us batched, IKFast ~4 us per solve):")
    print("   solver back end   batched   one pose a call   a batch of one a call")
    for label, solver, b in solvers:
        f = solver(arm, (), b)
        f(T[:10])
        f(T[0])
        best = min(_timed(f, T) for _ in range(args.rounds))
        calls = min(1000, args.poses)
        one = min(_timed_each(f, T[:calls]) for _ in range(args.rounds))
        ones = min(_timed_each(f, T[:calls, None]) for _ in range(args.rounds))  # (1, 4, 4): arrays
        mark = " (default)" if label == "fused" and b == default else ""
        print(f"   {label:6s} {b:6s} {best / args.poses * 1e6:9.2f} {one / calls * 1e6:12.2f} "
              f"{ones / calls * 1e6:18.2f}{mark}")
    guesses = q[: args.peer] + 0.1
    t0 = time.process_time()
    converged = sum(mr.IKinSpace(S, M, T[k], guesses[k], 1e-9, 1e-9)[1] for k in range(args.peer))
    peer = (time.process_time() - t0) / args.peer
    print(f"   modern_robotics IKinSpace (one branch, Newton from 0.1 rad off) {peer * 1e6:8.1f} us "
          f"({converged}/{args.peer} converged)")

    print(f"3. round trips on {args.poses} poses away from singularities (target 100 %):")
    branches = _fused(arm, (), default)(T)
    d = np.mod(branches - q[:, None, :] + np.pi, 2 * np.pi) - np.pi
    among = (np.abs(d).max(axis=2) < 1e-8).any(axis=1)
    live = ~np.isnan(branches).any(axis=2)
    worst = 0.0
    for k in range(args.poses):
        for br in branches[k][live[k]]:
            worst = max(worst, float(np.abs(mr.FKinSpace(M, S, br) - T[k]).max()))
    print(f"   fused  {default:6s} q among the branches: {among.mean() * 100:.2f} %; branches existing: "
          f"{live.sum()} ({live.sum(axis=1).mean():.2f} a pose); worst FK error of a branch {worst:.1e}")
    for label, solver, b in solvers:
        if label == "fused" and b == default:
            continue
        other = solver(arm, (), b)(T)
        same_nan = bool((np.isnan(other) == np.isnan(branches)).all())
        gap = np.nanmax(np.abs(np.mod(other - branches + np.pi, 2 * np.pi) - np.pi))
        print(f"   {label:6s} {b:6s} NaN in the same places: {same_nan}; largest difference {gap:.1e} rad")


def _timed(f, T) -> float:
    t0 = time.process_time()
    f(T)
    return time.process_time() - t0


def _timed_each(f, T) -> float:
    t0 = time.process_time()
    for x in T:
        f(x)
    return time.process_time() - t0


if __name__ == "__main__":
    main()
