"""Closed forms of derivations: screwsym's tidy results against ``simplify`` of the raw ones.

Run from the repository root: ``python benchmarks/bench_closed_forms.py [--markdown]``.

For each derivation of the corpus (the chapter's, generic screws from an axis, sums of screws,
common normals of generic lines, twist velocities, ...) it reports the ``count_ops`` of the raw
result (``tidy=False``), of screwsym's result (the operation as a user calls it, tidy by
default) and of ``sympy.simplify`` applied entry by entry to the raw result, with the times of
the tidy call, of the raw call and of ``simplify``.  SymPy's cache is cleared before each
timed call.  Each tidy result is checked against the raw one entry by entry with SymPy's
``equals`` (a pair that ``equals`` proves different is reported as a MISMATCH).

Targets (issue 12): screwsym's result no larger than simplify's for at least 90 % of the items
and never more than 1.5x; total time at most 0.1x of simplify's.
"""

from __future__ import annotations

import argparse
import signal
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from sympy import Basic, Expr, ImmutableMatrix, cos, count_ops, simplify, sin, symbols  # noqa: E402
from sympy.core.cache import clear_cache  # noqa: E402
from sympy.matrices import MatrixBase  # noqa: E402

import screwsym as ss  # noqa: E402
from screwsym import LineVector, Screw, Twist, Wrench, vector  # noqa: E402
from screwsym.core.basic import ScrewsymBasic  # noqa: E402

#: simplify is stopped after this many seconds (then its time is a lower bound)
SIMPLIFY_LIMIT = 60


def corpus():
    """(name, f) pairs: ``f(tidy)`` performs the derivation with ``tidy=tidy``."""
    h, h1, h2, w, F, th, z = symbols("h h1 h2 omega F theta z", real=True)
    r, S, p, q, A = vector("r"), vector("S"), vector("p"), vector("q"), vector("A")
    r1, S1, r2, S2 = vector("r1"), vector("S1"), vector("r2"), vector("S2")
    S0, C, f, wv = vector("S0"), vector("C"), vector("f"), vector("w")
    s = Screw.from_axis(r, S, h)
    g = Screw(S, S0)
    L = LineVector.through(p, q)
    total = Screw.from_axis(r1, S1, h1) + Screw.from_axis(r2, S2, h2)
    lines = LineVector.from_axis(r1, S1), LineVector.from_axis(r2, S2)
    x_axis = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    tilted = LineVector.from_axis([0, 0, z], [0, cos(th), sin(th)])
    # the cylindroid's generators: pitch h1 on the x-axis, pitch h2 on the y-axis at height z
    cyl = cos(th) * Screw.from_axis([0, 0, 0], [1, 0, 0], h1) + sin(th) * Screw.from_axis(
        [0, 0, z], [0, 1, 0], h2)
    T = Twist.from_axis(r, S, h, magnitude=w)
    W = Wrench.from_axis(r2, S2, h2, magnitude=F)
    through = Screw.through(p, q)
    line_couple = lines[0] + Screw.couple(C)
    screws = Screw.from_axis(r1, S1, h1), Screw.from_axis(r2, S2, h2)
    rotation, motion = Twist.rotation(wv, point=r), Twist.screw_motion(wv, point=r, pitch=h)
    rotation_q, force = Twist.rotation(wv, point=q), Wrench.force(f, point=r)
    line_sum = lines[0] + lines[1]
    return [
        ("(1.34) pitch of from_axis(r, S, h)", lambda t: ss.pitch(s, tidy=t)),
        ("(1.36) axis of from_axis(r, S, h)", lambda t: ss.axis(s, tidy=t)),
        ("(1.16) foot of from_axis(r, S, h)", lambda t: ss.foot(s, tidy=t)),
        ("(1.18) distance of from_axis(r, S, h)", lambda t: ss.distance_to_origin(s, tidy=t)),
        ("(1.37) decompose from_axis(r, S, h)", lambda t: ss.decompose_screw(s, tidy=t)),
        ("(1.5) unit of from_axis(r, S, h)", lambda t: ss.unit(s, tidy=t)),
        ("(1.32) shift_origin(from_axis(r, S, h), A)", lambda t: ss.shift_origin(s, A, tidy=t)),
        ("(1.34) pitch of LineVector.through(p, q)", lambda t: ss.pitch(L, tidy=t)),
        ("(1.34) pitch of Screw.through(p, q)",
         lambda t: ss.pitch(through, tidy=t)),
        ("(1.9) axis of Screw.through(p, q)", lambda t: ss.axis(through, tidy=t)),
        ("(1.16) foot of through(p, q)", lambda t: ss.foot(L, tidy=t)),
        ("(1.18) distance of through(p, q)", lambda t: ss.distance_to_origin(L, tidy=t)),
        ("(1.5) direction cosines of through(p, q)", lambda t: ss.direction_cosines(L, tidy=t)),
        ("(1.34) pitch of (S; S0)", lambda t: ss.pitch(g, tidy=t)),
        ("(1.36) axis of (S; S0)", lambda t: ss.axis(g, tidy=t)),
        ("(1.16) foot of (S; S0)", lambda t: ss.foot(g, tidy=t)),
        ("(1.18) distance of (S; S0)", lambda t: ss.distance_to_origin(g, tidy=t)),
        ("(1.39) pitch of a sum of two screws", lambda t: ss.pitch(total, tidy=t)),
        ("(1.36) axis of a sum of two screws", lambda t: ss.axis(total, tidy=t)),
        ("(1.16) foot of a sum of two screws", lambda t: ss.foot(total, tidy=t)),
        ("Thm 1.1 pitch of a sum of two lines", lambda t: ss.pitch(line_sum, tidy=t)),
        ("(1.38) pitch of line + couple", lambda t: ss.pitch(line_couple, tidy=t)),
        ("(1.23) mutual moment of two lines", lambda t: ss.mutual_moment(*lines, tidy=t)),
        ("(1.45) reciprocal product of two screws",
         lambda t: ss.reciprocal_product(*screws, tidy=t)),
        ("(1.24) common normal, x-axis and from_axis(r2, S2)",
         lambda t: ss.common_normal(x_axis, lines[1], tidy=t)),
        ("(1.24) common normal, x-axis and a tilted line",
         lambda t: ss.common_normal(x_axis, tilted, tidy=t)),
        ("(1.23) mutual moment, x-axis and a tilted line",
         lambda t: ss.mutual_moment(x_axis, tilted, tidy=t)),
        ("cylindroid: pitch of cos th $1 + sin th $2", lambda t: ss.pitch(cyl, tidy=t)),
        ("cylindroid: axis of cos th $1 + sin th $2", lambda t: ss.axis(cyl, tidy=t)),
        ("(1.50) velocity of a rotation at p",
         lambda t: rotation.velocity_at(p, tidy=t)),
        ("(1.53) velocity of a screw motion at p",
         lambda t: motion.velocity_at(p, tidy=t)),
        ("(1.52) pitch of a twist with angular speed", lambda t: ss.pitch(T, tidy=t)),
        ("(1.52) axis of a twist with angular speed", lambda t: ss.axis(T, tidy=t)),
        ("(1.16) foot of a rotation about q", lambda t: ss.foot(rotation_q, tidy=t)),
        ("(1.45) power of a twist and a wrench", lambda t: ss.power(T, W, tidy=t)),
        ("(1.32) moment of a force about A",
         lambda t: force.moment_about(A, tidy=t)),
        ("(1.58) decompose a wrench from its axis", lambda t: ss.decompose_screw(W, tidy=t)),
        ("(1.57) pitch of a wrench from its axis", lambda t: ss.pitch(W, tidy=t)),
    ]


def ops(x) -> int:
    """``count_ops`` of a result: an expression, a matrix, a screwsym object or a tuple."""
    if isinstance(x, MatrixBase):
        return sum(count_ops(e) for e in x)
    if isinstance(x, ScrewsymBasic):
        return sum(ops(a) for a in x.args)
    if isinstance(x, (tuple, list)):
        return sum(ops(a) for a in x)
    return count_ops(x)


def simplify_any(x):
    if isinstance(x, MatrixBase):
        return ImmutableMatrix(x.shape[0], x.shape[1], [simplify(e) for e in x])
    if isinstance(x, ScrewsymBasic):
        return Basic.__new__(type(x), *(simplify_any(a) for a in x.args))
    if isinstance(x, (tuple, list)):
        return type(x)(simplify_any(a) for a in x)
    return simplify(x)


def entries(x):
    if isinstance(x, MatrixBase):
        return list(x)
    if isinstance(x, ScrewsymBasic):
        return [e for a in x.args for e in entries(a)]
    if isinstance(x, (tuple, list)):
        return [e for a in x for e in entries(a)]
    return [x]


def same(a, b) -> bool:
    """No entry of ``a - b`` is provably non-zero (``equals``), entry by entry."""
    return all(not isinstance(u, Expr) or (u - v).equals(0) is not False
               for u, v in zip(entries(a), entries(b), strict=True))


class _Stop(Exception):
    pass


def _alarm(signum, frame):
    raise _Stop


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--markdown", action="store_true", help="print the table as markdown")
    markdown = ap.parse_args().markdown
    signal.signal(signal.SIGALRM, _alarm)
    rows = []
    for name, f in corpus():
        clear_cache()
        t0 = time.perf_counter()
        ours = f(True)
        t_ours = time.perf_counter() - t0
        clear_cache()
        t0 = time.perf_counter()
        raw = f(False)
        t_raw = time.perf_counter() - t0
        t0 = time.perf_counter()
        signal.alarm(SIMPLIFY_LIMIT)
        try:
            simp, stopped = simplify_any(raw), False
        except _Stop:
            simp, stopped = raw, True
        finally:
            signal.alarm(0)
        t_simp = time.perf_counter() - t0
        ok = same(ours, raw)
        rows.append((name, ops(raw), ops(ours), ops(simp), t_ours, t_raw, t_simp, stopped, ok))

    n = len(rows)
    ratios = [o / s if s else (1.0 if o == 0 else float("inf")) for _, _, o, s, *_ in rows]
    at_most = sum(1 for _, _, o, s, *_ in rows if o <= s)
    total_ours = sum(r[4] for r in rows)
    total_raw = sum(r[5] for r in rows)
    total_simp = sum(r[6] for r in rows)
    if markdown:
        print("| derivation | raw ops | screwsym ops | simplify ops | screwsym s | raw s "
              "| simplify s |")
        print("|---|---|---|---|---|---|---|")
    for (name, raw_ops, o, s, t1, t0, t2, stopped, ok), ratio in zip(rows, ratios, strict=True):
        flag = "" if ok else "  MISMATCH"
        simp_t = f">{t2:.2f}" if stopped else f"{t2:.3f}"
        if markdown:
            print(f"| {name} | {raw_ops} | {o} | {s} | {t1:.3f} | {t0:.3f} | {simp_t} |{flag}")
        else:
            print(f"{name:52s} raw {raw_ops:4d}  screwsym {o:4d}  simplify {s:4d}  "
                  f"({ratio:4.2f})  {t1:6.3f} s  raw {t0:6.3f} s  simplify {simp_t:>6s} s{flag}")
    print()
    print(f"{n} derivations; screwsym's result at most simplify's size for {at_most} "
          f"({100 * at_most / n:.0f} %); worst ratio {max(ratios):.2f}; all equal: "
          f"{all(r[8] for r in rows)}")
    print(f"time: screwsym {total_ours:.2f} s; raw operation {total_raw:.2f} s + simplify "
          f"{total_simp:.2f} s = {total_raw + total_simp:.2f} s; ratio "
          f"{total_ours / (total_raw + total_simp):.3f} (against simplify alone "
          f"{total_ours / total_simp:.3f}; tidying alone, screwsym minus raw: "
          f"{(total_ours - total_raw) / total_simp:.3f})")


if __name__ == "__main__":
    main()
