"""Benchmark the direct kinematics of parallel mechanisms (issue 36, item 3), side by side with plain SymPy.

Run from the repository root::

    python benchmarks/bench_assembly.py               # best of 3
    python benchmarks/bench_assembly.py --repeat 1

Measures CPU time (``time.process_time``), in one run:

1. the planar 3-RPR with six real modes (tests/systems/test_assembly.py): screwsym's
   ``direct_kinematics`` (the sextic, its roots isolated, every mode exact) against plain
   SymPy on the closure equations in ``x, y, c, s`` (``c**2 + s**2 = 1``):
   ``solve_poly_system`` (which answers with NO solution: the sextic has no radical roots,
   and ``roots`` drops what it cannot write) and a lex ``groebner`` basis followed by
   ``Poly.real_roots`` of its univariate element (the roots only, no poses);
2. the octahedral 3-3 Gough-Stewart platform with eight real modes: ``direct_kinematics``
   (degree 16) against plain SymPy's ``solve_poly_system`` on the same six equations in
   ``x_j, y_j`` (run in a child process, stopped after ``--timeout`` seconds).

3. the general 6-6 of Dietmaier (1998), 40 real modes (issue 36's target: all 40, each closing
   to 1e-9, under 60 s CPU): ``direct_kinematics`` (a homotopy in Study's parameters, every
   mode certified by Krawczyk's test in exact rationals), with the worst leg-length error of
   the 40 poses (NumPy, from the geometry).  No plain-SymPy comparison: its ``groebner`` on
   these equations does not finish in minutes.

Nothing is asserted; the figures go to the notes.
"""

from __future__ import annotations

import argparse
import multiprocessing as mp
import sys
import time
from pathlib import Path

from sympy import Rational, expand, groebner, solve_poly_system, symbols

from screwsym.systems import direct_kinematics

BASE = [(0, 0), (10, 0), (-2, 9)]
PLATFORM = [(0, 0), (9, 0), (5, 6)]
LENGTHS = [11, 10, 11]

A3 = [(0, 0, 0), (6, 0, 0), (2, 5, 0)]
B3 = [(0, 0, 0), (3, 0, 0), (1, 2, 0)]
OCTA_BASE = [A3[0], A3[1], A3[1], A3[2], A3[2], A3[0]]
OCTA_PLATFORM = [B3[0], B3[0], B3[1], B3[1], B3[2], B3[2]]
OCTA_LENGTHS = [5] * 6


def dietmaier():
    """Dietmaier's (1998) platform as the tests hold it (tests/systems/test_assembly.py, with
    its source: PHCpack's demo src/Demo/stewgou40): base points, platform points, lengths."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "systems"))
    from test_assembly import dietmaier_input

    return dietmaier_input()


def best(fn, repeat: int) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeat):
        t = time.process_time()
        out = fn()
        times.append(time.process_time() - t)
    return min(times), out


def planar_equations():
    x, y, c, s = symbols("x y c s")
    eqs = [
        expand((x + c * bx - s * by - ax) ** 2 + (y + s * bx + c * by - ay) ** 2 - L**2)
        for (ax, ay), (bx, by), L in zip(BASE, PLATFORM, LENGTHS, strict=True)
    ]
    return eqs + [c**2 + s**2 - 1], (x, y, c, s)


def sympy_planar_groebner():
    eqs, gens = planar_equations()
    G = groebner(eqs, *gens, order="lex")
    return G.exprs[-1].as_poly(gens[-1]).real_roots()


def sympy_planar_solve():
    eqs, gens = planar_equations()
    return solve_poly_system(eqs, *gens)


def octahedral_equations():
    from sympy import Matrix

    xs = symbols("x1:4")
    ys = symbols("y1:4")
    n = Matrix([0, 0, 1])
    pts = []
    eqs = []
    for j, (i, k) in enumerate(((0, 1), (1, 2), (2, 0))):
        a1, a2 = Matrix(A3[i]), Matrix(A3[k])
        e = a2 - a1
        L = e.dot(e)
        s = Rational(L, 2 * L)  # equal legs: the centre is the midpoint
        u = n.cross(e)
        r2 = OCTA_LENGTHS[0] ** 2 - s**2 * L
        pts.append(a1 + s * e + xs[j] * u + ys[j] * n)
        eqs.append(expand(u.dot(u) * xs[j] ** 2 + ys[j] ** 2 - r2))
    for j, k in ((0, 1), (1, 2), (2, 0)):
        d = pts[j] - pts[k]
        f = Matrix(B3[j]) - Matrix(B3[k])
        eqs.append(expand(d.dot(d) - f.dot(f)))
    return eqs, (*xs, *ys)


def _child(q):
    eqs, gens = octahedral_equations()
    t = time.process_time()
    sol = solve_poly_system(eqs, *gens)
    q.put((time.process_time() - t, len(sol)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--timeout", type=float, default=120.0)
    args = parser.parse_args()

    print("1. the planar 3-RPR, six real modes")
    t, m = best(lambda: direct_kinematics(BASE, PLATFORM, LENGTHS), args.repeat)
    print(f"   screwsym direct_kinematics        {t:8.3f} s CPU  {len(m.modes)} modes (exact), degree {m.polynomial.degree()}")
    t, roots = best(sympy_planar_groebner, args.repeat)
    print(f"   SymPy groebner(lex) + real_roots  {t:8.3f} s CPU  {len(roots)} roots of sin(phi) (no poses)")
    t, sol = best(sympy_planar_solve, args.repeat)
    print(f"   SymPy solve_poly_system           {t:8.3f} s CPU  {len(sol)} solutions (WRONG: six real exist)")

    print("2. the octahedral 3-3 Gough-Stewart platform")
    t, m = best(lambda: direct_kinematics(OCTA_BASE, OCTA_PLATFORM, OCTA_LENGTHS), args.repeat)
    print(f"   screwsym direct_kinematics        {t:8.3f} s CPU  {len(m.modes)} modes (exact), degree {m.polynomial.degree()}")
    q: mp.Queue = mp.Queue()
    proc = mp.Process(target=_child, args=(q,))
    proc.start()
    proc.join(args.timeout)
    if proc.is_alive():
        proc.terminate()
        proc.join()
        print(f"   SymPy solve_poly_system           > {args.timeout:.0f} s (stopped)")
    else:
        t, n = q.get()
        print(f"   SymPy solve_poly_system           {t:8.3f} s CPU  {n} solutions")

    print("3. the general 6-6: Dietmaier (1998), 40 real modes")
    import numpy as np

    A, B, L = dietmaier()
    t, m = best(lambda: direct_kinematics(A, B, L), args.repeat)
    Af, Bf, Lf = np.array(A, float), np.array(B, float), np.array(L, float)
    worst = 0.0
    for mode in m.modes:
        p = np.array([float(v) for v in mode.position])
        R = np.array(mode.rotation.tolist(), float)
        worst = max(worst, float(np.max(np.abs(np.linalg.norm(p + Bf @ R.T - Af, axis=1) - Lf))))
    print(
        f"   screwsym direct_kinematics        {t:8.3f} s CPU  {len(m.isolated_modes)} real modes, "
        f"{m.certified} certified, complete={m.complete}, worst leg error {worst:.1e}"
    )


if __name__ == "__main__":
    main()
