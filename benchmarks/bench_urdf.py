"""Benchmark chains read from URDF: the Franka Panda (and the UR5) with symbolic joint angles.

Run from the repository root::

    python benchmarks/bench_urdf.py                  # angles="pi/12" (the fast path)
    python benchmarks/bench_urdf.py --angles exact   # the default policy (slow)
    python benchmarks/bench_urdf.py --skip-simplify

Measured, first call in a fresh process (cold SymPy caches):

1. Reading the file: ``Chain.from_urdf`` (tests/data/urdf/panda.urdf, panda_link0 to
   panda_hand_tcp, seven revolute joints) with the angle policy given (``--angles``: the
   file's ``1.5707963267948966`` is pi/2 under ``"pi/12"``, the rational number as written
   under ``"exact"``).
2. Symbolic: ``Chain.forward`` and ``Chain.jacobian`` (space frame) with seven symbolic angles
   (issue 22's target: together under 3 s), and the Jacobian's ``count_ops`` against SymPy's
   ``simplify`` of the same Jacobian, entrywise (the yardstick; the issue's target: no
   larger than simplify's result).
3. The same for the UR5 (ur5_robot.urdf, base_link to tool0), for scale.

Nothing here is asserted; the figures go to ``benchmarks/README.md``.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from sympy import count_ops, simplify, symbols

from screwsym import Chain

DATA = Path(__file__).resolve().parent.parent / "tests" / "data" / "urdf"
ROBOTS = [("Panda", DATA / "panda.urdf", "panda_link0", "panda_hand_tcp"),
          ("UR5", DATA / "ur5_robot.urdf", "base_link", "tool0")]


def timed(fn, *args, **kwargs):
    t0 = time.perf_counter()
    out = fn(*args, **kwargs)
    return out, time.perf_counter() - t0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--angles", default="pi/12", help='the angle policy: "exact" or "pi/N"')
    parser.add_argument("--skip-simplify", action="store_true")
    parser.add_argument("--robot", choices=[r[0] for r in ROBOTS], default=None)
    args = parser.parse_args(argv)

    for name, path, base, tip in ROBOTS:
        if args.robot not in (None, name):
            continue
        chain, t_read = timed(Chain.from_urdf, path, base=base, tip=tip, angles=args.angles)
        q = symbols(f"q1:{chain.n_joints + 1}", real=True)
        print(f"== {name}: {path.name}, {base} -> {tip}, angles={args.angles!r}, "
              f"{chain.n_joints} symbolic joint angles ==")
        print(f"from_urdf               {t_read:8.3f} s")
        T, t_fk = timed(chain.forward, q)
        print(f"forward kinematics      {t_fk:8.3f} s   count_ops {count_ops(T.matrix)}")
        J, t_js = timed(chain.jacobian, q)
        ops = count_ops(J)
        print(f"space Jacobian          {t_js:8.3f} s   count_ops {ops}")
        print(f"together                {t_fk + t_js:8.3f} s   (issue 22's target for the Panda: < 3 s)")
        if not args.skip_simplify:
            simplified, t_simp = timed(lambda m: m.applyfunc(simplify), J)
            print(f"simplify(J), entrywise  {t_simp:8.3f} s   count_ops {count_ops(simplified)}"
                  f"   ratio ours/simplify {ops / count_ops(simplified):.2f}")
        print()


if __name__ == "__main__":
    main()
