"""Benchmark screw systems and mobility (issue 11) against its targets.

Run from the repository root::

    python benchmarks/bench_systems.py                 # N = 100,000 poses
    python benchmarks/bench_systems.py --n 10000 --repeat 3

Measures, each from cold caches (screwsym's rank and case caches are cleared
before every repetition; the best of ``--repeat`` is printed):

1. the reciprocal system of a 5-joint limb (five revolute joints, each at a
   symbolic point ``p_i``: 15 symbols) -- target under 1 s; and its full
   ``rank_conditions()`` case split, for information;
2. the full mobility analysis of the 3-RPS platform with symbolic leg
   geometry (``rho_i``, ``h_i``: 6 symbols): ``mobility()`` and the case split
   ``mobility_cases()`` -- target under 5 s;
3. the numeric singularity map of the 3-RPS platform on N poses with
   ``mobility_map`` (NumPy and, if installed, numba) -- target under 1 s for
   N = 1e5; generation and numba's first-call compilation are printed apart;
4. many symbols (issue 23, item 3): the 3-RPS with 9 symbolic parameters
   (``rho_i``, ``h_i`` and each leg's base radius ``b_i``) and with 12 (and
   each base pivot's height ``z_i``): ``mobility()`` (target under 5 s with 12)
   and ``mobility_cases()`` (target under 15 s with 12), side by side with
   plain SymPy computing the generic mobility alone (each limb's constraint
   wrenches by ``Matrix.nullspace`` of its swapped twists, then ``Matrix.rank``
   of their union); ``--many-only`` runs this part alone.

Nothing here is asserted; the figures go to ``benchmarks/README.md``.
"""

from __future__ import annotations

import argparse
import importlib.util
import time

import numpy as np
from sympy import Rational, sqrt, symbols

from screwsym import ScrewSystem, Twist, vector
from screwsym.numeric.mobility import mobility_map
from screwsym.systems._rank_cases import clear_caches
from screwsym.systems.joints import P, R, S
from screwsym.systems.parallel import Limb, ParallelMechanism

E = [[1, 0, 0], [-Rational(1, 2), sqrt(3) / 2, 0], [-Rational(1, 2), -sqrt(3) / 2, 0]]


def clear() -> None:
    clear_caches()


def best(fn, repeat: int, clear=clear) -> tuple[float, object]:
    """The least time of ``repeat`` calls of ``fn``, each after ``clear()``, and its result."""
    times, out = [], None
    for _ in range(repeat):
        clear()
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), out


def five_joint_limb() -> ScrewSystem:
    pts = [vector(f"p{i}") for i in range(5)]
    dirs = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]
    return ScrewSystem(*(Twist.rotation(d, point=p) for d, p in zip(dirs, pts, strict=True)))


def three_rps(rho, h, base=2) -> ParallelMechanism:
    legs = []
    for i, e in enumerate(E):
        b = [base * c for c in e]
        d = [rho[i] * e[0], rho[i] * e[1], h[i]]
        top = [x + y for x, y in zip(b, d, strict=True)]
        legs.append(Limb(R(b, [-e[1], e[0], 0]), P(d), S(top)))
    return ParallelMechanism(*legs)


def many_rps(n: int) -> tuple[ParallelMechanism, list]:
    """The 3-RPS with ``n`` = 6, 9 or 12 symbolic parameters (see the module docstring)."""
    rho, h = symbols("rho1:4", real=True), symbols("h1:4", real=True)
    b = symbols("b1:4", real=True) if n >= 9 else (2, 2, 2)
    z = symbols("z1:4", real=True) if n >= 12 else (0, 0, 0)
    legs = []
    for i, e in enumerate(E):
        base = [b[i] * e[0], b[i] * e[1], z[i]]
        d = [rho[i] * e[0], rho[i] * e[1], h[i]]
        top = [x + y for x, y in zip(base, d, strict=True)]
        legs.append(Limb(R(base, [-e[1], e[0], 0]), P(d), S(top)))
    syms = [*rho, *h] + (list(b) if n >= 9 else []) + (list(z) if n >= 12 else [])
    return ParallelMechanism(*legs), syms


def plain_sympy_mobility(mech: ParallelMechanism) -> int:
    """The generic mobility by plain SymPy: nullspaces of the swapped twists, rank of the union."""
    from sympy import Matrix

    wrenches = []
    for limb in mech.limbs:
        T = Matrix(limb.twists.matrix)
        wrenches.extend(Matrix.vstack(T[3:, :], T[:3, :]).T.nullspace())
    return 6 - Matrix.hstack(*wrenches).rank()


def many_symbols(repeat: int) -> None:
    for n in (9, 12):
        mech, _ = many_rps(n)
        t, m = best(mech.mobility, repeat)
        print(f"3-RPS, {n} symbols: mobility() {t:.2f} s -> {m.mobility} {m.motion}"
              + (" (target < 5 s)" if n == 12 else ""))
        t, cases = best(mech.mobility_cases, repeat)
        kinds: dict = {}
        for _, mm in cases:
            key = getattr(mm, "mobility", "None" if mm is None else type(mm).__name__)
            kinds[key] = kinds.get(key, 0) + 1
        print(f"  mobility_cases(): {len(cases)} cases {kinds} in {t:.2f} s"
              + (" (target < 15 s)" if n == 12 else ""))
        t0 = time.perf_counter()
        dof = plain_sympy_mobility(mech)
        print(f"  plain SymPy, generic mobility alone: {time.perf_counter() - t0:.2f} s -> {dof}")


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000, help="poses for the numeric map")
    parser.add_argument("--repeat", type=int, default=5, help="best of this many runs")
    parser.add_argument("--many-only", action="store_true", help="only the many-symbol part (4.)")
    parser.add_argument("--before", metavar="DIR", default=None,
                        help="also run part 4 on the screwsym of another checkout (a PYTHONPATH), "
                             "in a subprocess, for a side-by-side table")
    args = parser.parse_args(argv)
    if args.many_only:
        many_symbols(max(1, args.repeat // 2))
        if args.before:
            import os
            import subprocess
            import sys

            print(f"--- the same on {args.before}:", flush=True)
            env = {**os.environ, "PYTHONPATH": args.before}
            subprocess.run([sys.executable, "-c", "import sys; sys.path.insert(0, sys.argv[1]); "
                            "import bench_systems; bench_systems.many_symbols(1)",
                            os.path.dirname(os.path.abspath(__file__))], env=env, check=True,
                           cwd=args.before)
        return

    T = five_joint_limb()
    t, W = best(T.reciprocal, args.repeat)
    print(f"5-joint limb, 15 symbols: reciprocal() {t:.3f} s (rank {W.rank}; target < 1 s)")
    t, cases = best(T.rank_conditions, max(1, args.repeat // 2))
    print(f"  rank_conditions(): {len(cases)} cases in {t:.2f} s")

    rho = symbols("rho1:4", real=True)
    h = symbols("h1:4", positive=True)
    mech = three_rps(rho, h)
    t, m = best(mech.mobility, args.repeat)
    print(f"3-RPS, 6 symbols: mobility() {t:.3f} s -> mobility {m.mobility}, {m.motion} (target < 5 s)")
    t, cases = best(mech.mobility_cases, max(1, args.repeat // 2))
    dofs = [mm.mobility for _, mm in cases]
    print(f"  mobility_cases(): {len(cases)} cases, mobility {dofs}, in {t:.2f} s (target < 5 s)")

    rng = np.random.default_rng(0)
    n = args.n
    vals = [rng.uniform(-1, 1, n) for _ in range(3)] + [rng.uniform(1, 2, n) for _ in range(3)]
    backends = ["numpy"] + (["numba"] if importlib.util.find_spec("numba") else [])
    for backend in backends:
        t0 = time.perf_counter()
        f = mobility_map(mech, [*rho, *h], backend=backend)
        gen = time.perf_counter() - t0
        t0 = time.perf_counter()
        f(*(v[:4] for v in vals))
        first = time.perf_counter() - t0
        times = []
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            out = f(*vals)
            times.append(time.perf_counter() - t0)
        print(
            f"3-RPS map, {n} poses, {backend}: {min(times):.3f} s "
            f"({1e6 * min(times) / n:.2f} us/pose; generation {gen:.2f} s, first call "
            f"{first:.2f} s); mobility counts {np.bincount(out.mobility).tolist()} (target < 1 s)"
        )
    many_symbols(max(1, args.repeat // 2))


if __name__ == "__main__":
    main()
