"""Time ``screwsym verify`` (the whole book) against the plain SymPy script, in one run.

Run: ``python benchmarks/bench_verify.py [--jobs N] [--repeat R]``.

Each side runs as a new process, imports included: ``python -m screwsym verify --jobs J``
and ``python benchmarks/plain_sympy_check.py``, interleaved, ``R`` times each (the best
of each is reported).  Both the wall time and the CPU time (user + sys of the process
and the workers it waited for, from ``os.wait4``) are printed: on a loaded machine the
CPU times are the fair comparison.  The in-process time of ``verify_all`` (registry
loaded, imports excluded) is printed too.  The issue 23 target is a ratio book/plain of
at most 0.5 for ``--jobs 1``.
"""

import argparse
import os
import pathlib
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent


def run(cmd: list[str]) -> tuple[float, float]:
    """Wall and CPU (user + sys) seconds of ``cmd`` as a new process; it must exit 0."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(HERE.parent)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else [])
    )
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, env=env)
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)}: exit status {p.returncode}")
    return wall, usage.ru_utime + usage.ru_stime


def in_process(jobs: int) -> tuple[float, float, int, bool]:
    sys.path.insert(0, str(HERE.parent))  # this checkout's screwsym, as in the processes
    from screwsym.book import entries, verify_all

    entries()  # load the registry outside the timing
    t0, c0 = time.perf_counter(), time.process_time()
    results = verify_all(jobs=jobs)
    return (time.perf_counter() - t0, time.process_time() - c0, len(results),
            all(r.ok for r in results))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=min(4, os.cpu_count() or 1))
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    plain_cmd = [sys.executable, str(HERE / "plain_sympy_check.py")]
    plain: list[tuple[float, float]] = []
    book: dict[int, list[tuple[float, float]]] = {j: [] for j in sorted({1, args.jobs})}
    for _ in range(args.repeat):
        plain.append(run(plain_cmd))
        for j in book:
            book[j].append(run([sys.executable, "-m", "screwsym", "verify", "--jobs", str(j)]))
    pw, pc = min(w for w, _ in plain), min(c for _, c in plain)
    print(f"plain SymPy script, 60 checks (new process, incl. import): "
          f"wall {pw:.2f} s, CPU {pc:.2f} s  (best of {args.repeat})")
    for j, times in book.items():
        bw, bc = min(w for w, _ in times), min(c for _, c in times)
        cpu = "" if j == 1 else " (CPU: all workers)"
        print(f"screwsym verify --jobs {j} (new process, incl. import): wall {bw:.2f} s, "
              f"CPU {bc:.2f} s{cpu}; ratio book/plain: wall {bw / pw:.2f}, CPU {bc / pc:.2f}")
    w, c, n, ok = in_process(1)
    print(f"verify_all(jobs=1) in process, {n} entries (all hold: {ok}), imports excluded: "
          f"wall {w:.2f} s, CPU {c:.2f} s; ratio to the plain process: wall {w / pw:.2f}, "
          f"CPU {c / pc:.2f}")


if __name__ == "__main__":
    main()
