"""Symbolic speed at scale (issue 23): screwsym side by side with plain SymPy, SymEngine, SymForce.

Run from the repository root::

    .venv/bin/python benchmarks/bench_scaling.py            # every row
    .venv/bin/python benchmarks/bench_scaling.py --quick    # the chains and verify only

The peers are optional (``pip install -e ".[bench]"``: symengine, symforce); a peer that
is not installed prints "not installed".  Each row is timed once from cold caches
(SymPy's cache cleared before each), in this one process, and the sizes of the
results are SymPy's ``count_ops`` (the peers' results converted to SymPy to count).

1. The Franka Panda (tests/data/urdf/panda.urdf, panda_link0 to panda_hand_tcp, seven
   revolute joints, ``angles="pi/12"``: exact geometry) and the UR5 (Lynch & Park,
   Example 4.5): forward kinematics and space Jacobian with symbolic joint angles.
   ``Chain.forward`` + ``Chain.jacobian`` against the same product of exponentials
   written as plain matrix products (Rodrigues' formula per joint, the Jacobian's
   columns ``(R w; R v + p x R w)``), without any simplification, in each engine; and
   in SymPy also the textbook way (4x4 exponential matrices multiplied, the Jacobian's
   columns as 6x6 adjoints times the twists), as issue 23 measured it.
2. A 6R arm whose DH link lengths and offsets are all symbols (``a_i, d_i``, 12
   symbols; the UR-like twists ``alpha = (pi/2, 0, 0, pi/2, -pi/2, 0)``): the same; and
   the 6R whose every DH parameter is a symbol (``a_i, d_i, alpha_i``, 18 symbols).
3. The 3-RPS with 9 and 12 symbolic geometry parameters: ``mobility()`` and
   ``mobility_cases()`` (screwsym only: no peer has a mobility analysis).
4. ``screwsym verify --jobs 1`` against ``benchmarks/plain_sympy_check.py``.

Nothing here is asserted; the figures go to ``benchmarks/README.md`` and
``notebooks/benchmarks.md``.
"""

from __future__ import annotations

import argparse
import importlib.util
import pathlib
import sys
import time
from collections.abc import Callable
from typing import Any

import sympy
from sympy import count_ops, pi, symbols
from sympy.core.cache import clear_cache

from screwsym import Chain
from screwsym.motion.chain import ur5

HERE = pathlib.Path(__file__).resolve().parent
PANDA = HERE.parent / "tests" / "data" / "urdf" / "panda.urdf"


# ---------------------------------------------------------------- the plain product, any engine
def plain_products(twists: list, home: Any, q: list, sin: Callable, cos: Callable,
                   num: Callable) -> tuple[list, list]:
    """``T(q)`` (12 entries: R row by row, then p) and the space Jacobian (6 n, column by column).

    Plain scalar arithmetic of the engine: Rodrigues' ``R = I + s K + (1 - c) K^2``,
    ``p = (I - R) r`` for the axis point ``r = w x v`` (unit revolute twists), products
    of 3x3 blocks, the columns ``(R w; R v + p x R w)``.  Nothing is simplified.
    """
    def mm(A, B):
        return [[A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j] for j in range(3)]
                for i in range(3)]

    def mv(A, x):
        return [A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2] for i in range(3)]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    zero, one = num(0), num(1)
    R = [[one, zero, zero], [zero, one, zero], [zero, zero, one]]
    p = [zero, zero, zero]
    cols = []
    for t, qi in zip(twists, q, strict=True):
        w = [num(e) for e in t.omega]
        v = [num(e) for e in t.v_O]
        Rw = mv(R, w)
        cols += Rw + [a + b for a, b in zip(mv(R, v), cross(p, Rw), strict=True)]
        s, c = sin(qi), cos(qi)
        K = [[zero, -w[2], w[1]], [w[2], zero, -w[0]], [-w[1], w[0], zero]]
        K2 = mm(K, K)
        E = [[(one if i == j else zero) + s * K[i][j] + (one - c) * K2[i][j] for j in range(3)]
             for i in range(3)]
        r = cross(w, v)
        Ep = [r[i] - sum((E[i][j] * r[j] for j in range(3)), zero) for i in range(3)]
        p = [a + b for a, b in zip(mv(R, Ep), p, strict=True)]
        R = mm(R, E)
    HR = [[num(home.R[i, j]) for j in range(3)] for i in range(3)]
    Hp = [num(e) for e in home.p]
    T = [x for row in mm(R, HR) for x in row] + [a + b for a, b in zip(mv(R, Hp), p, strict=True)]
    return T, cols


def naive_products(twists: list, home: Any, q: list) -> tuple[Any, Any]:
    """The textbook way in SymPy: 4x4 exponentials multiplied, 6x6 adjoints times the twists."""
    from sympy import Matrix, eye, zeros

    def hat(w):
        return Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])

    T = eye(4)
    cols = []
    for t, qi in zip(twists, q, strict=True):
        R, p = T[:3, :3], T[:3, 3]
        Ad = zeros(6, 6)
        Ad[:3, :3] = R
        Ad[3:, 3:] = R
        Ad[3:, :3] = hat(p) * R
        cols.append(Ad * t.matrix)
        K = hat(t.omega)
        E = eye(4)
        E[:3, :3] = eye(3) + sympy.sin(qi) * K + (1 - sympy.cos(qi)) * K**2
        E[:3, 3] = (eye(3) - E[:3, :3]) * t.omega.cross(t.v_O)
        T = T * E
    return T * home.matrix, Matrix.hstack(*cols)


def ops(entries: list) -> int:
    return sum(count_ops(sympy.sympify(e)) for e in entries)


def engines() -> dict[str, Any]:
    """name -> (symbols, sin, cos, number) for each engine installed."""
    out: dict[str, Any] = {
        "plain SymPy": (lambda names: symbols(names, real=True), sympy.sin, sympy.cos, sympy.sympify),
    }
    if importlib.util.find_spec("symengine"):
        import symengine as se

        out["SymEngine"] = (lambda names: se.symbols(names), se.sin, se.cos, se.sympify)
    else:
        out["SymEngine"] = None
    if importlib.util.find_spec("symforce"):
        import symforce

        symforce.set_symbolic_api("symengine")
        import symforce.symbolic as sf

        def sf_symbols(names):
            return [sf.Symbol(str(x)) for x in symbols(names)]

        out["SymForce"] = (sf_symbols, sf.sin, sf.cos, lambda e: sf.sympify(e) if hasattr(sf, "sympify")
                           else sf.S(e) if hasattr(sf, "S") else sympy.sympify(e))
    else:
        out["SymForce"] = None
    return out


def timed(fn: Callable) -> tuple[float, Any]:
    clear_cache()
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


# ---------------------------------------------------------------- the chains
def generic_6r() -> Chain:
    a = symbols("a1:7", real=True)
    d = symbols("d1:7", real=True)
    alpha = [pi / 2, 0, 0, pi / 2, -pi / 2, 0]
    return Chain.from_dh([(a[i], alpha[i], d[i], 0) for i in range(6)])


def generic_6r_all() -> Chain:
    """The 6R with every DH parameter symbolic: ``a_i, d_i`` and the twist angles ``alpha_i``."""
    a = symbols("a1:7", real=True)
    d = symbols("d1:7", real=True)
    alpha = symbols("alpha1:7", real=True)
    return Chain.from_dh([(a[i], alpha[i], d[i], 0) for i in range(6)])


def chain_rows(name: str, chain: Chain, rows: list) -> None:
    n = chain.n_joints
    names = f"q1:{n + 1}"
    q = symbols(names, real=True)

    def ours():
        return chain.forward(q).matrix, chain.jacobian(q)

    t, (T, J) = timed(ours)
    rows.append((name, "screwsym Chain (tidied)", t, count_ops(T), count_ops(J)))
    t, (T, J) = timed(lambda: naive_products(chain.twists, chain.home, q))
    rows.append((name, "plain SymPy Matrix: 4x4 exps, 6x6 adjoints (untidied)", t,
                 count_ops(T[:3, :]), count_ops(J)))
    for label, engine in engines().items():
        if engine is None:
            rows.append((name, label, None, None, None))
            continue
        make, sin, cos, num = engine
        qs = list(make(names))

        def theirs(sin=sin, cos=cos, num=num, qs=qs):
            return plain_products(chain.twists, chain.home, qs, sin, cos, num)

        t, (T, J) = timed(theirs)
        rows.append((name, f"{label} scalar products (untidied)", t, ops(T), ops(J)))


def print_rows(rows: list) -> None:
    print("| case | engine | time (s) | count_ops T(q) | count_ops J_s(q) |")
    print("|---|---|---|---|---|")
    for case, label, t, a, b in rows:
        if t is None:
            print(f"| {case} | {label} | not installed | | |")
        else:
            print(f"| {case} | {label} | {t:.3f} | {a:,} | {b:,} |")


# ---------------------------------------------------------------- many-symbol mobility (item 3)
def mobility_rows() -> None:
    sys.path.insert(0, str(HERE))
    from bench_systems import many_rps  # the 3-RPS of bench_systems, the script beside this one

    from screwsym.systems._rank_cases import clear_caches

    print("\n| 3-RPS, symbolic parameters | mobility() (s) | mobility_cases() (s) | cases |")
    print("|---|---|---|---|")
    for n in (9, 12):
        mech, _ = many_rps(n)
        clear_caches()
        t1, m = timed(mech.mobility)
        t2, cases = timed(mech.mobility_cases)
        print(f"| {n} | {t1:.2f} (mobility {m.mobility}) | {t2:.2f} | {len(cases)} |")


# ---------------------------------------------------------------- verify (item 4)
def verify_rows() -> None:
    sys.path.insert(0, str(HERE))
    import bench_verify

    plain_cmd = [sys.executable, str(HERE / "plain_sympy_check.py")]
    book_cmd = [sys.executable, "-m", "screwsym", "verify", "--jobs", "1"]
    runs = [(bench_verify.run(plain_cmd), bench_verify.run(book_cmd)) for _ in range(3)]
    plain = min(p[1] for p, _ in runs)  # CPU seconds, best of three, interleaved
    book = min(b[1] for _, b in runs)
    print(f"\nscrewsym verify --jobs 1 (new process, incl. import): CPU {book:.2f} s; plain "
          f"SymPy script (the same): CPU {plain:.2f} s; ratio {book / plain:.2f} (target <= 0.5)")


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the chains and verify only")
    args = parser.parse_args(argv)

    rows: list = []
    chain_rows("UR5", ur5(), rows)
    if importlib.util.find_spec("defusedxml"):
        chain_rows("Panda", Chain.from_urdf(PANDA, "panda_link0", "panda_hand_tcp", angles="pi/12"), rows)
    else:
        rows.append(("Panda", "screwsym Chain (needs defusedxml)", None, None, None))
    chain_rows("generic 6R (a_i, d_i symbols)", generic_6r(), rows)
    chain_rows("6R, all DH geometry symbolic (a, d, alpha)", generic_6r_all(), rows)
    print_rows(rows)
    if not args.quick:
        mobility_rows()
    verify_rows()


if __name__ == "__main__":
    main()
