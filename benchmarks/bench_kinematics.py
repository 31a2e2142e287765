"""Benchmark the rigid-motion layer on the UR5 of Modern Robotics (Example 4.5).

Run from the repository root::

    python benchmarks/bench_kinematics.py                 # N = 100,000 poses
    python benchmarks/bench_kinematics.py --n 20000 --skip-simplify

Measured side by side in one process:

1. Symbolic: ``Chain.forward`` and ``Chain.jacobian`` (space) of the 6R arm
   with six symbolic joint angles, first call (cold SymPy caches), and the
   Jacobian's ``count_ops`` against SymPy's ``simplify`` applied entrywise to
   the same Jacobian built as the plain product of adjoints, and to the tidied
   one (the one place in screwsym where ``simplify`` is called: it is the
   yardstick).
2. Numeric: the forward kinematics generated with ``screwsym.lambdify``
   (NumPy and numba back ends) on N poses, against modern_robotics
   ``FKinSpace`` called in a Python loop (timed on a subset, per pose) and a
   hand-written vectorised NumPy product of exponentials.

Nothing here is asserted; the figures go to ``benchmarks/README.md``.
"""

from __future__ import annotations

import argparse
import importlib.util
import time

import numpy as np
from sympy import ImmutableMatrix, Matrix, count_ops, simplify, symbols

from screwsym import Transform, exp6, lambdify
from screwsym.motion.chain import ur5


def timed(fn, *args):
    t0 = time.perf_counter()
    out = fn(*args)
    return out, time.perf_counter() - t0


def best(fn, args, repeat):
    fn(*args)
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn(*args)
        times.append(time.perf_counter() - t0)
    return min(times)


def raw_space_jacobian(chain, q):
    """The space Jacobian as the plain product of adjoints, untidied."""
    T = Transform.identity()
    columns = []
    for twist, qi in zip(chain.twists, q, strict=True):
        columns.append(T.adjoint() * twist.matrix)
        T = T @ exp6(twist, qi)
    return ImmutableMatrix.hstack(*columns)


def hand_numpy_fk(Q, M, S):
    """Product of exponentials vectorised by hand: batched Rodrigues, then matmul."""
    n = Q.shape[0]
    T = np.broadcast_to(np.eye(4), (n, 4, 4)).copy()
    eye = np.eye(3)
    for i in range(S.shape[1]):
        w, v = S[:3, i], S[3:, i]
        K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        K2 = K @ K
        th = Q[:, i][:, None, None]
        s, c = np.sin(th), np.cos(th)
        E = np.zeros((n, 4, 4))
        E[:, :3, :3] = eye + s * K + (1 - c) * K2
        E[:, :3, 3] = (eye * th + (1 - c) * K + (th - s) * K2) @ v
        E[:, 3, 3] = 1
        T = T @ E
    return T @ M


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000, help="poses for the numeric part")
    parser.add_argument("--mr-n", type=int, default=2_000, help="poses for the MR loop")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--skip-simplify", action="store_true")
    args = parser.parse_args(argv)

    chain = ur5()  # Modern Robotics, Example 4.5, exact
    q = symbols("q1:7", real=True)

    print("== symbolic: UR5, six symbolic joint angles (first call) ==")
    T, t_fk = timed(chain.forward, q)
    J, t_js = timed(chain.jacobian, q)
    print(f"forward kinematics      {t_fk:7.3f} s   count_ops {count_ops(T.matrix)}")
    print(f"space Jacobian          {t_js:7.3f} s   count_ops {count_ops(J)}")
    print(f"together                {t_fk + t_js:7.3f} s   (target < 2 s)")
    raw = raw_space_jacobian(chain, q)
    print(f"raw adjoint product     count_ops {count_ops(raw)}")
    if not args.skip_simplify:
        simplified, t_simp = timed(lambda m: m.applyfunc(simplify), raw)
        print(
            f"simplify(raw), entrywise {t_simp:6.2f} s   count_ops {count_ops(simplified)}"
            f"   ratio ours/simplify {count_ops(J) / count_ops(simplified):.2f}"
        )
        again, t_again = timed(lambda m: m.applyfunc(simplify), J)
        print(f"simplify(ours), entrywise {t_again:5.2f} s   count_ops {count_ops(again)}")

    print(f"\n== numeric: forward kinematics on N = {args.n:,} poses ==")
    qv = Matrix(q)
    rng = np.random.default_rng(0)
    Q = rng.uniform(-np.pi, np.pi, size=(args.n, 6))
    (f_np, t_gen) = timed(lambdify, [qv], T.matrix)
    print(f"generation (numpy)      {t_gen:7.3f} s")
    results = {}
    results["screwsym numpy"] = best(f_np, (Q,), args.repeat)
    if importlib.util.find_spec("numba"):
        f_nb, t_gen = timed(lambdify, [qv], T.matrix, "numba")
        _, t_jit = timed(f_nb, Q[:2])
        print(f"generation (numba)      {t_gen:7.3f} s   + first-call JIT {t_jit:.2f} s")
        results["screwsym numba"] = best(f_nb, (Q,), args.repeat)
    M = np.array(chain.home.matrix, dtype=float)
    S = np.array([np.array(t.matrix, dtype=float).ravel() for t in chain.twists]).T
    results["hand-written NumPy"] = best(hand_numpy_fk, (Q, M, S), args.repeat)
    np.testing.assert_allclose(f_np(Q[:100]), hand_numpy_fk(Q[:100], M, S), atol=1e-12)
    per_pose = {k: v / args.n * 1e9 for k, v in results.items()}
    if importlib.util.find_spec("modern_robotics"):
        import modern_robotics as mr

        sub = Q[: args.mr_n]

        def loop():
            for row in sub:
                mr.FKinSpace(M, S, row)

        per_pose["modern_robotics loop"] = best(loop, (), max(1, args.repeat // 2)) / len(
            sub
        ) * 1e9
        np.testing.assert_allclose(f_np(sub[:10]), [mr.FKinSpace(M, S, r) for r in sub[:10]],
                                   atol=1e-12)
    hand = per_pose["hand-written NumPy"]
    mr_ns = per_pose.get("modern_robotics loop")
    print(f"{'':24s}{'ns/pose':>10s}{'vs MR loop':>12s}{'vs hand NumPy':>15s}")
    for name, ns in per_pose.items():
        speedup = f"{mr_ns / ns:10.0f}x" if mr_ns else "         -"
        print(f"{name:24s}{ns:10.1f}  {speedup}  {ns / hand:12.2f}")


if __name__ == "__main__":
    main()
