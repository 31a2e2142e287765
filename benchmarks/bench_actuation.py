"""Benchmark actuation analysis (issue 18) against its targets.

Run from the repository root::

    python benchmarks/bench_actuation.py                # N = 10^6 configurations
    python benchmarks/bench_actuation.py --n 100000 --repeat 3

Measures (each symbolic case in a fresh process, so its caches are cold, stopped
after ``--cap`` seconds; the numeric maps the best of ``--repeat``):

1. ``singularities()`` of Tsai's symmetric 3-RPS at a symbolic pose, three pose
   parameters (``s = tan(phi/2)``, ``t = tan(theta/2)``, the height ``z``; the
   rotation ``Rz(phi) Ry(theta) Rz(-phi)`` in rational form, the parasitic
   translation in closed form) -- target under 10 s;
2. ``singularities()`` of a 3-3 Gough-Stewart (octahedral) platform turned
   about its vertical axis by ``theta = 2 atan(tau)`` (rational) and by ``theta``
   written with ``cos(theta)``, ``sin(theta)`` -- target under 10 s;
   and, for comparison, the 3-RPS with three symbolic leg heights (not a rigid
   pose: the platform's size changes with them);
3. the transmission map (input, output, local index) of the planar five-bar
   on N configurations, the generated NumPy function against hand-written
   vectorised NumPy of the same formula -- target under 1 s for N = 10^6 and
   within 2x of the hand-written one;
4. (issue 32) ``transmission()`` and ``singularities()`` of a planar 3-RPR with its
   pose (x, y, phi) symbolic (target under 30 s each) and at numeric poses, regular and
   type II (target under 1 s), CPU time in a fresh process (``--only rpr``).

Nothing here is asserted; the figures go to ``benchmarks/README.md``.
"""

from __future__ import annotations

import argparse
import multiprocessing as mp
import sys
import time
from pathlib import Path

import numpy as np
from sympy import symbols

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bench_systems import best  # noqa: E402  (the script beside this one; clears the caches)

from screwsym.numeric.transmission import transmission_map  # noqa: E402
from tests._actuated import five_bar, gough_stewart_33, three_rps_pose  # noqa: E402


def hand_five_bar(cfg: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The five-bar's indices by hand: |sin| of the angles between the links (A1 = 0, A2 = (3, 0))."""
    b1, b2, p = cfg[:, 0:2], cfg[:, 2:4], cfg[:, 4:6]
    c1, c2 = b1, b2 - np.array([3.0, 0.0])
    d1, d2 = p - b1, p - b2

    def sin(u, v):
        return np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]) / (
            np.hypot(u[:, 0], u[:, 1]) * np.hypot(v[:, 0], v[:, 1]))

    lam = np.stack([sin(c1, d1), sin(c2, d2)])
    eta = sin(d1, d2)
    return lam, np.stack([eta, eta]), np.minimum(lam.min(axis=0), eta)


def configurations(n: int) -> np.ndarray:
    rng = np.random.default_rng(0)
    t1, t2 = rng.uniform(0.3, 2.8, n), rng.uniform(0.3, 2.8, n)
    b1 = np.stack([np.cos(t1), np.sin(t1)], axis=1)
    b2 = np.stack([3 + np.cos(t2), np.sin(t2)], axis=1)
    mid, half = (b1 + b2) / 2, np.linalg.norm(b2 - b1, axis=1, keepdims=True) / 2
    nrm = np.stack([-(b2 - b1)[:, 1], (b2 - b1)[:, 0]], axis=1) / (2 * half)
    p = mid + np.sqrt(np.clip(4.0 - half**2, 0, None)) * nrm
    return np.concatenate([b1, b2, p], axis=1)


def _rpr(name: str):
    """The planar 3-RPR of tests/_actuated.py: its pose (x, y, phi) symbolic, or numbers at a
    concurrent-legs (type II) pose and at a regular one."""
    from sympy import cos, sin

    from tests._actuated import RPR_BASE, RPR_CONCURRENT, RPR_PLATFORM, three_rpr

    if name.startswith("rpr_sym"):
        x, y, phi = symbols("x y phi", real=True)
        return three_rpr(x, y, cos(phi), sin(phi), RPR_BASE, RPR_PLATFORM)
    base = RPR_CONCURRENT if name.endswith("singular") else RPR_BASE
    return three_rpr(0, 0, 1, 0, base, RPR_PLATFORM)


def _symbolic_case(name: str, queue) -> None:
    from sympy import Rational

    from tests._actuated import E
    from tests._mechanisms import rps_leg

    if name.startswith("rpr"):
        mech = _rpr(name)
        t = time.process_time()
        if "transmission" in name:
            tr = mech.transmission()
            sec = time.process_time() - t
            queue.put((sec, f"CPU; {len(tr.input)} input, {len(tr.output)} output indices, "
                            f"singular limbs {tr.singular}"))
            return
        out = mech.singularities()
        sec = time.process_time() - t
        queue.put((sec, f"CPU; {len(out.limb)}/{len(out.actuation)}/{len(out.constraint)} cases "
                        f"(limb/actuation/constraint), actuation ranks "
                        f"{[r for _, r in out.actuation]}"))
        return
    if name == "rps_pose":
        mech = three_rps_pose(*symbols("p q z", real=True))
    elif name == "rps_heights":
        from screwsym.systems.parallel import Limb, ParallelMechanism

        hs = symbols("h1:4", real=True)
        mech = ParallelMechanism(*(Limb(*rps_leg(i, Rational(-1, 2), h).joints, actuated=1)
                                   for i, h in enumerate(hs)))
    elif name == "gs33trig":
        mech = gough_stewart_33(symbols("theta", real=True), trig=True)
    else:
        mech = gough_stewart_33(symbols("tau", real=True))
    del E
    t = time.perf_counter()
    out = mech.singularities()
    sec = time.perf_counter() - t
    queue.put((sec, f"{len(out.limb)}/{len(out.actuation)}/{len(out.constraint)} cases "
                    f"(limb/actuation/constraint): {[c for c, _ in out.actuation][:2]}"))


def capped(label: str, name: str, cap: float, target: str = "< 10 s") -> tuple[str, str, str, str]:
    """Run one symbolic case in a child process, stopped after ``cap`` seconds."""
    queue: mp.Queue = mp.Queue()
    proc = mp.Process(target=_symbolic_case, args=(name, queue))
    proc.start()
    proc.join(cap)
    if proc.is_alive():
        proc.terminate()
        proc.join()
        return (label, f"> {cap:.0f} s", target, "not finished: stopped at the cap")
    if proc.exitcode != 0 or queue.empty():
        return (label, "failed", target, f"the analysis raised (exit code {proc.exitcode})")
    sec, note = queue.get()
    return (label, f"{sec:.2f} s", target, note[:160])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=10**6)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--cap", type=float, default=120.0, help="seconds per symbolic case")
    ap.add_argument("--only", choices=("rps_pose", "rps_heights", "gs33", "gs33trig", "rpr"),
                    help="run this symbolic case alone (no transmission map)")
    args = ap.parse_args()
    rows = []

    for label, build in (("3-RPS singularities(), pose (p, q, z)", "rps_pose"),
                         ("3-RPS singularities(), leg heights (h1, h2, h3)", "rps_heights"),
                         ("3-3 Gough-Stewart singularities(), tau", "gs33"),
                         ("3-3 Gough-Stewart singularities(), cos/sin theta", "gs33trig")):
        if args.only in (None, build):
            rows.append(capped(label, build, args.cap))
    # issue 32: the planar 3-RPR, its pose symbolic (target 30 s) and given by numbers (1 s)
    for label, build, target in (
            ("3-RPR transmission(), pose (x, y, phi)", "rpr_sym_transmission", "< 30 s"),
            ("3-RPR singularities(), pose (x, y, phi)", "rpr_sym_singularities", "< 30 s"),
            ("3-RPR transmission(), numeric pose, regular", "rpr_num_transmission", "< 1 s"),
            ("3-RPR singularities(), numeric pose, regular", "rpr_num_singularities", "< 1 s"),
            ("3-RPR transmission(), numeric pose, type II", "rpr_num_transmission_singular",
             "< 1 s"),
            ("3-RPR singularities(), numeric pose, type II", "rpr_num_singularities_singular",
             "< 1 s")):
        if args.only in (None, "rpr"):
            rows.append(capped(label, build, args.cap, target))
    if args.only:
        print("| benchmark | time | target | notes |")
        print("|---|---|---|---|")
        for r in rows:
            print("| " + " | ".join(r) + " |")
        return
    syms = symbols("b1x b1y b2x b2y px py", real=True)
    mech = five_bar((syms[4], syms[5]), b1=syms[0:2], b2=syms[2:4])
    t0 = time.perf_counter()
    fn = transmission_map(mech, list(syms))
    gen = time.perf_counter() - t0
    cfg = configurations(args.n)
    fn(cfg[:10])
    sec_gen, got = best(lambda: fn(cfg), args.repeat, clear=lambda: None)
    sec_hand, want = best(lambda: hand_five_bar(cfg), args.repeat, clear=lambda: None)
    ok = all(np.allclose(a, b, equal_nan=True) for a, b in zip(got, want, strict=True))
    rows.append((f"five-bar transmission map, N = {args.n:.0e} (generated)", f"{sec_gen:.3f} s",
                 "< 1 s", f"agrees with hand: {ok}; generation {gen:.1f} s"))
    rows.append((f"five-bar transmission map, N = {args.n:.0e} (hand NumPy)", f"{sec_hand:.3f} s",
                 "", f"generated / hand = {sec_gen / sec_hand:.2f} (target < 2)"))

    print("| benchmark | time | target | notes |")
    print("|---|---|---|---|")
    for r in rows:
        print("| " + " | ".join(r) + " |")


if __name__ == "__main__":
    main()
