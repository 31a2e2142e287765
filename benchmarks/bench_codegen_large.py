"""Large closed forms and a new process's first call (issue 23 items 4 and 5).

(C) ``screwsym.lambdify`` of a closed form of about 120,000 operations (a sum of 20,000
monomials ``k x^a y^b z``, the shape of an expanded inverse dynamics), of the real one
(the UR5's joint-4 torque, ``tests/_dynamics.py::ur5_torque_expanded``: 7,242 terms,
127,137 operations, in 18 variables) and of a tree 3,000 levels deep, on each back end,
beside plain ``sympy.lambdify(..., cse=True)``;
(D) in new processes: ``import sympy``, ``import screwsym``, and the first batch call
of ``screwsym.numeric.pitch`` with the disk cache warm (default back end, and with
numba imported first), beside a plain ``sympy.lambdify`` of the same formula.

    python benchmarks/bench_codegen_large.py            # about 120,000 operations
    python benchmarks/bench_codegen_large.py --terms 2000 --depth 1000   # a quick run

Prints one table per part; asserts nothing.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time

import numpy as np
from sympy import Add, ImmutableMatrix, Integer, cos, count_ops, sin, symbols
from sympy import lambdify as sympy_lambdify

from screwsym.codegen import lambdify

x, y, z = symbols("x y z", real=True)


def wide(n: int):
    return Add(*[Integer(k + 1) * x ** (k % 97) * y ** (k // 97) * z for k in range(n)])


def deep(n: int):
    e = x
    for k in range(n):
        e = sin(e) + y if k % 2 else cos(e) * y
    return e


XYZ = (np.array([0.3, 0.4]), np.array([0.9, 0.8]), np.array([1.0, 2.0]))


def ur5():
    """The UR5's joint-4 torque, its 18 joint values as three 6-vectors, sample inputs."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))
    from _dynamics import ur5_torque_expanded

    e, qs = ur5_torque_expanded(3)
    return e, [ImmutableMatrix(v) for v in qs], tuple(
        np.random.default_rng(0).uniform(-3, 3, size=(3, 2, 6)))


def timed(make, inputs):
    t = time.perf_counter()
    try:
        f = make()
        f(*inputs)
        return f"{time.perf_counter() - t:.2f} s"
    except RecursionError:
        return f"RecursionError ({time.perf_counter() - t:.2f} s)"


def _plain(e, args):
    """Plain ``sympy.lambdify`` with the same call: matrix arguments as (N, k) arrays."""
    scalars = [list(a) if hasattr(a, "shape") else [a] for a in args]
    f = sympy_lambdify([s for group in scalars for s in group], e, "numpy", cse=True)
    return lambda *arrays: f(*(a[..., i] if a.ndim > 1 else a for a, g in zip(arrays, scalars, strict=True)
                               for i in range(len(g))))


def part_c(terms: int, depth: int, backends: list[str]) -> None:
    # compiled and generated anew: a disk cache of an earlier run would be read back instead
    os.environ["SCREWSYM_CACHE_DIR"] = tempfile.mkdtemp(prefix="bench-codegen-large-")
    rows = []
    for label, build in (("wide", lambda: (wide(terms), [x, y, z], XYZ)),
                         ("UR5 joint-4 torque, expanded", ur5),
                         ("deep", lambda: (deep(depth), [x, y, z], XYZ))):
        t = time.perf_counter()
        e, args, inputs = build()
        made = time.perf_counter() - t
        ops = f"depth {depth}" if label == "deep" else f"{count_ops(e):,} ops"
        row = [f"{label} ({ops})", f"{made:.2f} s"]
        for b in backends:
            row.append(timed(lambda b=b, e=e, a=args: lambdify(a, e, backend=b), inputs))
        row.append(timed(lambda e=e, a=args: _plain(e, a), inputs))
        rows.append(row)
    head = ["expression", "build (SymPy)", *[f"screwsym {b}" for b in backends],
            "sympy.lambdify cse=True"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        print("| " + " | ".join(r) + " |")


FIRST = textwrap.dedent("""
    import sys, time
    t0 = time.perf_counter()
    if sys.argv[1] == "sympy":
        import sympy
        print(time.perf_counter() - t0); raise SystemExit
    if sys.argv[1] == "numba-first":
        import numba  # noqa: F401
    import numpy as np
    if sys.argv[1] == "import":
        import sympy  # noqa: F401
    t1 = time.perf_counter()
    if sys.argv[1] == "plain":
        import sympy
        S, S0 = sympy.Matrix(sympy.symbols("s0:3", real=True)), sympy.Matrix(sympy.symbols("s3:6", real=True))
        t2 = time.perf_counter()
        f = sympy.lambdify([list(S) + list(S0)], S.dot(S0) / S.dot(S), "numpy", cse=True)
        f(np.ones((6, 1000))); print(time.perf_counter() - t2); raise SystemExit
    import screwsym
    t2 = time.perf_counter()
    if sys.argv[1] == "import":
        print(t2 - t1); raise SystemExit
    from screwsym import numeric
    x = np.ones((1000, 6))
    t3 = time.perf_counter()
    numeric.pitch(x)
    print(time.perf_counter() - t3)
""")


def new_process(mode: str, repeat: int) -> float:
    """Median time of ``mode`` in new processes, with Python's bytecode cache (a first run
    writes it where ``PYTHONDONTWRITEBYTECODE`` had kept it from being written)."""
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    subprocess.run([sys.executable, "-c", FIRST, mode], capture_output=True, env=env)
    times = []
    for _ in range(repeat):
        out = subprocess.run([sys.executable, "-c", FIRST, mode], capture_output=True,
                             text=True, env=env, check=True)
        times.append(float(out.stdout.split()[-1]))
    return statistics.median(times)


def part_d(repeat: int) -> None:
    new_process("default", 1)  # warm the disk caches
    new_process("numba-first", 1)
    rows = [
        ("import sympy", new_process("sympy", repeat)),
        ("import screwsym after numpy and sympy (its own cost)", new_process("import", repeat)),

        ("first numeric.pitch call, (1000, 6), default back end, warm cache",
         new_process("default", repeat)),
        ("first numeric.pitch call, numba imported first, warm cache",
         new_process("numba-first", repeat)),
        ("plain sympy.lambdify of the pitch formula and its first call",
         new_process("plain", repeat)),
    ]
    print(f"| new process (median of {repeat}) | time |")
    print("|---|---|")
    for label, t in rows:
        print(f"| {label} | {1000 * t:.1f} ms |")


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--terms", type=int, default=20000)
    p.add_argument("--depth", type=int, default=3000)
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--backends", default="numpy,c,numba")
    p.add_argument("--part", choices=["c", "d", "both"], default="both")
    a = p.parse_args()
    if a.part in ("c", "both"):
        part_c(a.terms, a.depth, a.backends.split(","))
        print()
    if a.part in ("d", "both"):
        part_d(a.repeat)


if __name__ == "__main__":
    main()
