"""Benchmark the redraw of a live 3-D view: the UR5 with its joint twists, the Delta by its platform.

Run from the repository root::

    python benchmarks/bench_view.py
    python benchmarks/bench_view.py --number 200 --rounds 5

``screwsym.plot.live`` does every SymPy step once; ``Live.redraw(values)`` then recomputes
the data of every trace (links, joints, axes, screws) with lambdified functions and NumPy.
Timed here (CPU time per redraw, best of the rounds): the UR5 at a configuration with its
six joint twists recomputed, and the Delta (21 revolutes, three parallelograms) at a
platform position, its arms' angles solved in closed form at each redraw
(``screwsym.plot.models.Delta.configurations``).  Target (issue 37 item 2): a redraw well
under 50 ms.  Also shown: the one-off set-up (``live(...)``) and the time of a whole
precomputed ``view(..., path=...)`` of 30 frames.  Nothing is asserted; plotly's own
drawing in the browser is not part of the figures.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from screwsym.motion.chain import ur5
from screwsym.plot import live, view
from screwsym.plot.models import delta


def best(fn, number: int, rounds: int) -> float:
    out = []
    for _ in range(rounds):
        t0 = time.process_time()
        for _ in range(number):
            fn()
        out.append((time.process_time() - t0) / number)
    return min(out)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--number", type=int, default=100)
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    rng = np.random.default_rng(37)

    t0 = time.process_time()
    arm = live(ur5(), [0, -0.5, 1, 0, 0.5, 0], twists=True)
    set_ur5 = time.process_time() - t0
    qs = rng.uniform(-np.pi, np.pi, (args.number, 6))
    it = iter(np.tile(qs, (args.rounds + 1, 1)))
    ur5_redraw = best(lambda: arm.redraw(next(it)), args.number, args.rounds)

    t0 = time.process_time()
    d = delta()
    s = np.linspace(0, 2 * np.pi, 30)
    path = np.column_stack([0.5 * np.cos(s), 0.5 * np.sin(s), -2.8 + 0.2 * np.sin(2 * s)])
    robot = live(d.mechanism, variables=d.variables, solve=lambda v: d.configurations(v)[0],
                 controls=[("x", -0.6, 0.6), ("y", -0.6, 0.6), ("z", -3.2, -2.4)],
                 q=[0, 0, -3], extent=d.configurations(path))
    set_delta = time.process_time() - t0
    pts = np.column_stack([rng.uniform(-0.5, 0.5, (args.number, 2)),
                           rng.uniform(-3.1, -2.5, args.number)])
    it2 = iter(np.tile(pts, (args.rounds + 1, 1)))
    delta_redraw = best(lambda: robot.redraw(next(it2)), args.number, args.rounds)

    t0 = time.process_time()
    view(d.mechanism, path=d.configurations(path), variables=d.variables)
    delta_frames = time.process_time() - t0

    print(f"{'view':<34} {'set-up (s)':>10} {'redraw (ms)':>12}")
    print(f"{'UR5 + 6 joint twists':<34} {set_ur5:>10.2f} {1e3 * ur5_redraw:>12.2f}")
    print(f"{'Delta (21 R) by its platform':<34} {set_delta:>10.2f} {1e3 * delta_redraw:>12.2f}")
    print(f"Delta, view(path=...) of 30 precomputed frames: {delta_frames:.2f} s")


if __name__ == "__main__":
    main()
