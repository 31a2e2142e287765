"""Symbolic speed at scale (issue 23): screwsym side by side with plain SymPy, SymEngine, SymForce.

Run from the repository root::

    python benchmarks/bench_scaling.py            # every row
    python benchmarks/bench_scaling.py --quick    # the chains and verify only

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

5. Growth per added joint (``--growth``; issues 33 item 2 and 34 item 5), CPU time
   (``time.process_time``), each row stopped after ``--limit`` CPU seconds:
   forward kinematics + space Jacobian of a spatial k-joint chain (axes cycling z, y, x
   through rational points, k = 3 .. 9), the mass matrix of the same chain with a general
   rational inertia per link (k = 2 .. 7), and a k-joint URDF whose joint origins are turned
   by multiples of 15 degrees (read with ``angles="pi/12"``: the geometry in Q(sqrt 2, sqrt 3);
   read, FK + J, mass matrix).  screwsym (the calls a user makes, results tidied) against the
   same algorithm written as plain scalar products, untidied, in plain SymPy, SymEngine and
   SymForce (the composite rigid body method for the mass matrix, ray-order twists and
   inertias as screwsym's).  The last column of each engine is the growth factor per added
   joint; then the 6-link chain at a pose of 15-degree multiples (``--pose`` alone).  Run it
   with ``PYTHONPATH`` pointing to another checkout to measure that one.  ``--kinematics``:
   the FK + J tables alone, with a column for ``Chain.kinematics_program`` (FK and J as
   straight-line programs, whose size grows linearly with the joints).  The FK + J tables
   have a column for ``forward(q, form="product")`` + ``jacobian(q, form="product")`` (the
   untidied nested product, opt-in) beside the default tidied forms.

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


# ---------------------------------------------------------------- growth per joint (item 5)
AXES = [(0, 0, 1), (0, 1, 0), (1, 0, 0)]


def spatial_chain(k: int) -> Chain:
    """k revolute joints, axes cycling z, y, x through rational points; a general inertia per link."""
    from sympy import ImmutableMatrix, Rational

    from screwsym import SpatialInertia, Twist

    twists, bodies = [], []
    inertia = ImmutableMatrix([[Rational(1, 5), Rational(1, 100), 0], [Rational(1, 100), Rational(1, 4), Rational(1, 50)],
                               [0, Rational(1, 50), Rational(3, 10)]])
    for i in range(k):
        point = [Rational(i, 2), Rational(i % 2, 3), Rational(i, 5)]
        twists.append(Twist.rotation(list(AXES[i % 3]), point=point))
        com = [Rational(i, 2) + Rational(1, 4), Rational(1, 5), Rational(i, 5) + Rational(1, 10)]
        bodies.append(SpatialInertia(Rational(3 + i, 2), com, inertia))
    return Chain(twists, inertias=bodies)


def urdf_15(k: int) -> str:
    """A k-joint URDF whose joint origins are turned by multiples of 15 degrees (seeded)."""
    import math
    import random

    rnd = random.Random(1)
    parts = ['<robot name="r15">', '<link name="l0"/>']
    for i in range(1, k + 1):
        rpy = " ".join(repr(rnd.choice([1, 2, 3, 4, 5, -1, -2, 6, 0]) * math.pi / 12) for _ in range(3))
        xyz = " ".join(str(rnd.choice([0, 0.1, 0.25, -0.3, 0.05])) for _ in range(3))
        parts.append(f'<link name="l{i}"><inertial><origin xyz="0.01 0.02 0.03" rpy="0 {math.pi / 12!r} 0"/>'
                     '<mass value="1.5"/><inertia ixx="0.1" ixy="0.01" ixz="0" iyy="0.2" iyz="0" izz="0.3"/>'
                     '</inertial></link>')
        parts.append(f'<joint name="j{i}" type="revolute"><parent link="l{i - 1}"/><child link="l{i}"/>'
                     f'<origin xyz="{xyz}" rpy="{rpy}"/><axis xyz="0 0 1"/>'
                     '<limit lower="-3" upper="3" effort="1" velocity="1"/></joint>')
    parts.append("</robot>")
    return "\n".join(parts)


def plain_crba(twists: list, inertias: list, q: list, sin: Callable, cos: Callable,
               num: Callable) -> list:
    """The mass matrix by composite rigid bodies in an engine's plain scalar arithmetic, untidied.

    Ray order as screwsym's: ``E_i = exp6($_i, q_i)`` as ``Ad`` (6x6), the composite inertia
    ``M^c_k = M_k + Ad(E_{k+1}) M^c_{k+1} Ad(E_{k+1}^-1)``, ``H_ik = $_i o (Ad(E_{i+1} ... E_k)
    M^c_k $_k)`` with ``o`` the reciprocal product.  Products by a literal 0 are skipped.
    """
    n = len(twists)
    zero, one = num(0), num(1)

    def mm(A, B):
        return [[sum((A[i][k] * B[k][j] for k in range(len(B)) if not (A[i][k] == 0 or B[k][j] == 0)), zero)
                 for j in range(len(B[0]))] for i in range(len(A))]

    def hat(w):
        return [[zero, -w[2], w[1]], [w[2], zero, -w[0]], [-w[1], w[0], zero]]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    def adjoint(R, p):
        P = mm(hat(p), R)
        return [R[i] + [zero] * 3 for i in range(3)] + [P[i] + R[i] for i in range(3)]

    E = []
    for t, qi in zip(twists, q, strict=True):
        w, v = [num(e) for e in t.omega], [num(e) for e in t.v_O]
        K = hat(w)
        K2 = mm(K, K)
        s, c = sin(qi), cos(qi)
        R = [[(one if i == j else zero) + s * K[i][j] + (one - c) * K2[i][j] for j in range(3)] for i in range(3)]
        r = cross(w, v)
        p = [r[i] - sum((R[i][j] * r[j] for j in range(3)), zero) for i in range(3)]
        Rt = [[R[j][i] for j in range(3)] for i in range(3)]
        E.append((adjoint(R, p), adjoint(Rt, [-sum((Rt[i][j] * p[j] for j in range(3)), zero) for i in range(3)])))
    xi = [[num(e) for e in t.matrix] for t in twists]
    H = [[zero] * n for _ in range(n)]
    Mc: list = []
    for k in reversed(range(n)):
        M = [[num(x) for x in row] for row in inertias[k].matrix.tolist()]
        if Mc:
            C = mm(mm(E[k + 1][0], Mc), E[k + 1][1])
            M = [[M[i][j] + C[i][j] for j in range(6)] for i in range(6)]
        Mc = M
        W = [sum((Mc[i][j] * xi[k][j] for j in range(6)), zero) for i in range(6)]
        for i in reversed(range(k + 1)):
            if i < k:
                A = E[i + 1][0]
                W = [sum((A[r][j] * W[j] for j in range(6)), zero) for r in range(6)]
            x = xi[i]
            H[i][k] = H[k][i] = x[0] * W[3] + x[1] * W[4] + x[2] * W[5] + x[3] * W[0] + x[4] * W[1] + x[5] * W[2]
    return [e for row in H for e in row]


class _OverLimit(Exception):
    pass


def cpu_timed(fn: Callable, limit: float) -> tuple[float | None, Any]:
    """``(CPU seconds, result)``, or ``(None, None)`` when ``fn`` used more than ``limit`` CPU s."""
    import signal

    def stop(signum, frame):
        raise _OverLimit

    clear_cache()
    old = signal.signal(signal.SIGPROF, stop)
    signal.setitimer(signal.ITIMER_PROF, limit)
    t0 = time.process_time()
    try:
        out = fn()
    except _OverLimit:
        return None, None
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, old)
    return time.process_time() - t0, out


def growth_rows(limit: float, kinematics_only: bool = False) -> None:
    """Per added joint: screwsym and the plain products of each engine (module docstring, item 5).

    ``kinematics_only``: the FK + J tables alone, with a column for ``Chain.kinematics_program``
    (FK and J as straight-line programs: CPU s to build both, and their operations, the
    multiplications + additions + functions of ``Program.operations``)."""
    peers = engines()

    def table(title: str, ks: range, build: Callable, ours: Callable, theirs: Callable | None,
              program: Callable | None = None, product: Callable | None = None) -> None:
        labels = ["screwsym"] + (["screwsym form='product'"] if product else []) \
            + ([name for name in peers] if theirs else [])
        if program is not None:
            labels.append("screwsym program")
        print(f"\n{title}: CPU s (count_ops of the result) [growth per added joint]\n")
        print("| joints | " + " | ".join(labels) + " |")
        print("|---|" + "---|" * len(labels))
        last: dict = {}
        for k in ks:
            _, chain = cpu_timed(lambda k=k: build(k), limit)
            if chain is None:
                print(f"| {k} | building the chain: > {limit:g} (stopped) |")
                continue
            q = list(symbols(f"q1:{k + 1}", real=True))
            cells = []
            for label in labels:
                if label == "screwsym":
                    t, out = cpu_timed(lambda chain=chain, q=q: ours(chain, q), limit)
                elif label == "screwsym form='product'":
                    t, out = cpu_timed(lambda chain=chain, q=q: product(chain, q), limit)  # type: ignore[misc]
                elif label == "screwsym program":
                    t, out = cpu_timed(lambda chain=chain: program(chain), limit)  # type: ignore[misc]
                else:
                    engine = peers[label]
                    if engine is None:
                        cells.append("not installed")
                        continue
                    make, sin, cos, num = engine
                    qs = list(make(f"q1:{k + 1}"))
                    t, out = cpu_timed(lambda chain=chain, qs=qs, e=engine: theirs(chain, qs, e[1], e[2], e[3]),
                                       limit)
                if t is None:
                    cells.append(f"> {limit:g} (stopped)")
                    last[label] = None
                    continue
                size = (ops(out) if not isinstance(out, int) else out) if out is not None else 0
                grow = f" [{t / last[label]:.1f}x]" if last.get(label) else ""
                cells.append(f"{t:.3f} ({size:,}){grow}")
                last[label] = t
            print(f"| {k} | " + " | ".join(cells) + " |")

    def fk_j(chain, q):
        return list(chain.forward(q).matrix[:3, :]) + list(chain.jacobian(q))

    def fk_j_plain(chain, q, sin, cos, num):
        T, cols = plain_products(chain.twists, chain.home, q, sin, cos, num)
        return T + cols

    def fk_j_product(chain, q):
        _kp._RECENT.clear()  # no partial products kept from an earlier call
        return list(chain.forward(q, form="product").matrix[:3, :]) + list(chain.jacobian(q, form="product"))

    def fk_j_program(chain):
        total = 0
        for what in ("forward", "jacobian"):
            o = chain.kinematics_program(what).operations()
            total += o.multiplications + o.additions + o.functions
        return total

    def mass(chain, q):
        return list(chain.mass_matrix(q))

    def mass_plain(chain, q, sin, cos, num):
        return plain_crba(chain.twists, chain.inertias, q, sin, cos, num)

    program = fk_j_program if hasattr(Chain, "kinematics_program") else None  # not on older trees
    _kp = importlib.import_module("screwsym.motion._kinematics_program")
    product = fk_j_product if hasattr(_kp, "FORMS") else None  # not on older trees
    table("FK + J (space), spatial k-joint chain", range(3, 10), spatial_chain, fk_j, fk_j_plain, program,
          product)
    if kinematics_only:
        if importlib.util.find_spec("defusedxml"):
            def read15(k):
                return Chain.from_urdf(urdf_15(k), angles="pi/12")

            table("FK + J (space), URDF at 15-degree multiples", range(3, 7), read15, fk_j, fk_j_plain, program,
                  product)
        return
    table("mass matrix, spatial k-link chain", range(2, 8), spatial_chain, mass, mass_plain)
    if importlib.util.find_spec("defusedxml"):
        def read(k):
            return Chain.from_urdf(urdf_15(k), angles="pi/12")

        def read_inertias(k):
            return Chain.from_urdf(urdf_15(k), angles="pi/12", inertias=True)

        print("\nURDF at 15-degree multiples (angles='pi/12'): read, CPU s\n")
        print("| joints | from_urdf | from_urdf(inertias=True) |")
        print("|---|---|---|")
        for k in range(3, 8):
            cells = []
            for fn in (read, read_inertias):
                t, _ = cpu_timed(lambda k=k, fn=fn: fn(k), limit)
                cells.append(f"> {limit:g} (stopped)" if t is None else f"{t:.3f}")
            print(f"| {k} | " + " | ".join(cells) + " |")
        table("FK + J (space), URDF at 15-degree multiples", range(3, 7), read, fk_j, fk_j_plain, None, product)
        table("mass matrix, URDF at 15-degree multiples", range(2, 6), read_inertias, mass, mass_plain)


def dynamics15_rows(limit: float) -> None:
    """Per added joint, a URDF at 15-degree multiples with symbolic joint variables: the closed
    forms (mass matrix, inverse dynamics: the ring of ``_ring_dynamics``) beside the
    straight-line programs of ``Chain.dynamics_program`` (customised Newton-Euler), CPU s and
    the size of each (count_ops of the closed form, operations of the program)."""
    if not importlib.util.find_spec("defusedxml"):
        return
    print("\nDynamics of a k-joint URDF at 15-degree multiples, symbolic q, qd, qdd: CPU s (size)\n")
    print("| joints | mass_matrix(q) | inverse_dynamics(q, qd, qdd) | program: mass matrix | "
          "program: inverse dynamics |")
    print("|---|---|---|---|---|")
    for k in range(2, 8):
        _, chain = cpu_timed(lambda k=k: Chain.from_urdf(urdf_15(k), angles="pi/12", inertias=True), limit)
        if chain is None:
            print(f"| {k} | building the chain: > {limit:g} (stopped) |")
            continue
        q, qd, qdd = (list(symbols(f"{x}1:{k + 1}", real=True)) for x in ("q", "qd", "qdd"))
        cells = []
        def program_size(p):
            return sum(p.operations())

        steps = (("mass_matrix", count_ops), ("inverse_dynamics", count_ops),
                 ("program mass_matrix", program_size), ("program inverse_dynamics", program_size))
        for what, size in steps:
            def run(what=what, chain=chain, q=q, qd=qd, qdd=qdd):
                if what == "mass_matrix":
                    return chain.mass_matrix(q)
                if what == "inverse_dynamics":
                    return chain.inverse_dynamics(q, qd, qdd)
                return chain.dynamics_program(what.split()[1])

            t, out = cpu_timed(run, limit)
            cells.append(f"> {limit:g} (stopped)" if t is None else f"{t:.2f} ({size(out):,})")
        print(f"| {k} | " + " | ".join(cells) + " |", flush=True)


def pose_rows(limit: float) -> None:
    """The spatial 6-link chain at a pose of 15-degree multiples (numbers in Q(sqrt 2, sqrt 3),
    as issue 33's Kinova): mass matrix, and inverse dynamics with symbolic rates."""
    from sympy import pi

    chain = spatial_chain(6)
    q = [pi / 4, pi / 6, pi / 12, pi / 3, pi / 4, pi / 6]
    qd, qdd = symbols("qd1:7", real=True), symbols("qdd1:7", real=True)
    print("\n| spatial 6-link at q = (45, 30, 15, 60, 45, 30) degrees | CPU s | count_ops |")
    print("|---|---|---|")
    for what, fn in (("mass_matrix(q)", lambda: chain.mass_matrix(q)),
                     ("inverse_dynamics(q, qd, qdd)", lambda: chain.inverse_dynamics(q, qd, qdd))):
        t, out = cpu_timed(fn, limit)
        print(f"| {what} | " + (f"> {limit:g} (stopped) | |" if t is None else f"{t:.2f} | {count_ops(out):,} |"))


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the chains and verify only")
    parser.add_argument("--growth", action="store_true", help="only the growth per added joint (item 5)")
    parser.add_argument("--pose", action="store_true", help="only the 6-link chain at a 15-degree pose")
    parser.add_argument("--kinematics", action="store_true",
                        help="only the FK + J tables of --growth, with the straight-line program column")
    parser.add_argument("--dynamics15", action="store_true",
                        help="only the dynamics of URDFs at 15-degree multiples, closed forms and programs")
    parser.add_argument("--limit", type=float, default=20.0, help="CPU seconds per row of --growth")
    args = parser.parse_args(argv)
    if args.dynamics15:
        dynamics15_rows(args.limit)
        return
    parser_pose = args.pose
    if parser_pose:
        pose_rows(args.limit)
        return
    if args.kinematics:
        import warnings

        warnings.simplefilter("ignore")  # the URDF reader's notes on the angles it recognised
        growth_rows(args.limit, kinematics_only=True)
        return
    if args.growth:
        growth_rows(args.limit)
        pose_rows(args.limit)
        return

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
