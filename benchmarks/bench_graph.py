"""Benchmark mechanisms of any topology (issue 19) against its targets.

Run from the repository root::

    python benchmarks/bench_graph.py             # best of 3
    python benchmarks/bench_graph.py --repeat 5

Measures, each from cold caches (the graph's and the screw systems' caches are
cleared before every repetition; the best of ``--repeat`` is printed):

1. ``Mechanism.mobility()`` of the Delta robot built link by link (17 links,
   21 revolutes, 5 loops), exact -- target under 5 s; beside it
   ``twists("platform")`` and, as the floating-point peer, the rank of the same
   network matrix by NumPy's SVD;
2. ``Mechanism.second_order()`` of the shaky 4R (axes on one regulus) and of
   Bennett's linkage (a skew isogram), exact -- target under 2 s each.

Nothing here is asserted; the figures go to ``benchmarks/README.md``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from bench_systems import best as _best  # the script beside this one
from sympy import Matrix, Rational

from screwsym.systems._rank_cases import clear_caches
from screwsym.systems.joints import R
from screwsym.systems.linkage import Mechanism

Q = Rational


def clear() -> None:
    clear_caches()


def best(fn, repeat: int) -> tuple[float, object]:
    return _best(fn, repeat, clear)


def _add(a, b):
    return [x + y for x, y in zip(a, b, strict=True)]


def _sub(a, b):
    return [x - y for x, y in zip(a, b, strict=True)]


def delta() -> Mechanism:
    """The Delta robot (Clavel 1988), legs R-R-Pa-R, the parallelogram of four revolutes."""
    triples = []
    for i, e in enumerate([[1, 0, 0], [Q(-3, 5), Q(4, 5), 0], [Q(-3, 5), Q(-4, 5), 0]], 1):
        u = [-e[1], e[0], 0]
        b = [2 * x for x in e]
        elbow = _add(b, [e[0], e[1], -1])
        attach = [e[0], e[1], -3]
        n = list(Matrix(u).cross(Matrix(_sub(attach, elbow))))
        w = [Q(x) / 2 for x in u]
        arm, up, r1, r2, lo = (f"{k}{i}" for k in ("arm", "upper", "rodA", "rodB", "lower"))
        triples += [("base", arm, R(b, u)), (arm, up, R(elbow, u)),
                    (up, r1, R(_add(elbow, w), n)), (r1, lo, R(_add(attach, w), n)),
                    (up, r2, R(_sub(elbow, w), n)), (r2, lo, R(_sub(attach, w), n)),
                    (lo, "platform", R(attach, u))]
    return Mechanism(triples, base="base")


def four_r(points, axes) -> Mechanism:
    return Mechanism([(k, (k + 1) % 4, R(points[k], axes[k])) for k in range(4)], base=0)


def shaky() -> Mechanism:
    ring = [(1, 0), (0, 1), (-1, 0), (Q(3, 5), Q(-4, 5))]
    return four_r([[c, s, 0] for c, s in ring], [[-s, c, 1] for c, s in ring])


def bennett() -> Mechanism:
    pts = [[1, 0, 0], [1, 2, 2], [-1, 0, 0], [-1, -2, 2]]
    d = lambda a, b: Matrix(a) - Matrix(b)  # noqa: E731
    return four_r(pts, [list(d(pts[(k + 1) % 4], pts[k]).cross(d(pts[k - 1], pts[k])))
                        for k in range(4)])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    rows = []
    build, mech = best(delta, args.repeat)
    t, m = best(mech.mobility, args.repeat)
    rows.append(("Delta: build (21 joints)", build, "-", ""))
    rows.append(("Delta: mobility(), exact", t, "< 5 s",
                 f"M = {m.mobility}, L = {m.loops}, nu = {m.redundant}"))
    t, T = best(lambda: mech.relative_twists("platform"), args.repeat)
    rows.append(("Delta: twists('platform') (cold)", t, "-", f"rank {T.rank}, {mech.motion('platform')}"))
    A = np.array(mech.network_matrix(), dtype=float)
    t0 = time.perf_counter()
    for _ in range(100):
        s = np.linalg.svd(A, compute_uv=False)
    t_svd = (time.perf_counter() - t0) / 100
    rank = int((s > 1e-9 * s[0]).sum())
    rows.append(("  peer: NumPy SVD rank of the network matrix", t_svd, "-", f"M = {A.shape[1] - rank}"))
    for name, make in (("shaky 4R", shaky), ("Bennett", bennett)):
        mech4 = make()
        t, so = best(mech4.second_order, args.repeat)
        rows.append((f"{name}: second_order(), exact (cold)", t, "< 2 s",
                     f"instantaneous {so.instantaneous}, second order {so.mobility}"))
    width = max(len(r[0]) for r in rows)
    print(f"{'case':<{width}}  {'seconds':>9}  {'target':>7}  result")
    for name, sec, target, result in rows:
        print(f"{name:<{width}}  {sec:9.4f}  {target:>7}  {result}")


if __name__ == "__main__":
    main()
