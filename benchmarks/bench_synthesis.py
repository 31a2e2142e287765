"""Type synthesis (issue 38): how many limb types and mechanisms the grammar finds, and how long.

Run from the repository root::

    python benchmarks/bench_synthesis.py              # every row (several minutes)
    python benchmarks/bench_synthesis.py --quick      # the rows of at most four joints
    python benchmarks/bench_synthesis.py --no-mechanisms

For each motion pattern and grammar (joint kinds, the longest limb, with or without
perpendicular relations) it prints the number of limb types :func:`limbs` certifies, by
number of joints, and the CPU time; then the number of symmetrical mechanisms of those
limbs :func:`mechanisms` certifies (mobility, motion type, twists, no passive freedom,
second order), how many of them have an actuated joint per limb with an invertible
Jacobian at the instance, and the CPU time.

The published tables to compare with (Kong & Gosselin, ASME J. Mech. Des. 126 (2004)
83-92 for 3T and 101-108 for 3R; *Type Synthesis of Parallel Mechanisms*, Springer 2007,
for 3T1R) could not be read here (not in the stored corpora): the comparison is with the
families they name, in tests/systems/test_synthesis.py.  Nothing is asserted here.
"""

from __future__ import annotations

import argparse
import time

from screwsym.systems.synthesis import limbs, mechanisms, motion

#: (motion, kinds, longest limb, perpendicular relations, limbs per mechanism)
ROWS = [
    ("3T", ("R", "P"), 4, False, 3),
    ("3T", ("R", "P"), 5, False, 3),
    ("3T", ("R", "P"), 5, True, 3),
    ("3T", ("R", "Pa"), 4, False, 3),
    ("3T", ("R", "P", "Pa"), 4, False, 3),
    ("3T", ("R", "Pa"), 5, False, 3),
    ("3R", ("R", "P"), 5, False, 3),
    ("3R", ("R", "P"), 5, True, 3),
    ("3T1R", ("R", "P"), 4, False, 4),
    ("3T1R", ("R", "P"), 5, False, 4),
    ("3T1R", ("R", "Pa"), 4, False, 4),
    ("3T1R", ("R", "Pa"), 5, False, 4),
    ("2T1R", ("R", "P"), 3, False, 3),
    ("2T1R", ("R", "P"), 3, True, 3),
]


#: the families the literature names, looked for in each row of their motion
FAMILIES = {
    "3T": ["PPP", "PRRR (2∥3∥4)", "CRR (1∥2∥3∥4)", "UPU (1∥5, 2∥4)", "RRRRR (1∥2∥3, 4∥5)",
           "RPaRR (1∥3∥4)"],
    "3R": ["RRR (1,2,3 through O)", "RRPRR (2∥4, 3⟂2, 1,5 through O)"],
    "3T1R": ["PRRR (2∥3∥4∥z)", "URU (1∥5∥z, 2∥3∥4)", "RPaRR (1∥3∥4∥z)",
             "RRPaRR (1∥z, 2∥4∥5)"],
    "2T1R": ["RRR (1∥2∥3∥z)", "RPR (1∥3∥z, 2⊥z)"],
}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="only the rows of at most 4 joints")
    ap.add_argument("--no-mechanisms", action="store_true", help="count limb types only")
    args = ap.parse_args()
    print("| motion | kinds | joints | ⟂ | limb types (by length) | CPU s | mechanisms "
          "| actuated | CPU s | named families found |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, kinds, n, perp, count in ROWS:
        if args.quick and n > 4:
            continue
        mo = motion(name)
        t0 = time.process_time()
        found = limbs(mo, kinds=kinds, max_joints=n, perpendicular=perp, budget=10**12)
        t_limbs = time.process_time() - t0
        by = [sum(t.freedom == k for t in found) for k in range(mo.dimension, n + 1)]
        mech = act = "-"
        t_mech = 0.0
        if not args.no_mechanisms:
            t0 = time.process_time()
            designs = mechanisms(mo, count, types=found, budget=10**12)
            t_mech = time.process_time() - t0
            mech = str(len(designs))
            act = str(sum(d.actuated is not None for d in designs))
        have = {t.name for t in found}
        named = [f for f in FAMILIES[name] if f in have]
        print(f"| {name} | {','.join(kinds)} | ≤{n} | {'yes' if perp else 'no'} | {len(found)} "
              f"({'+'.join(map(str, by))}) | {t_limbs:.1f} | {mech} | {act} | {t_mech:.1f} | "
              f"{'; '.join(named) or '-'} |", flush=True)


if __name__ == "__main__":
    main()
