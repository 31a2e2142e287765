"""Time ``screwsym verify`` (the whole book) against the plain SymPy script, in one run.

Run: ``python benchmarks/bench_verify.py [--jobs N]``.  Prints both times and the ratio.
"""

import argparse
import os
import pathlib
import subprocess
import sys
import time


def time_book(jobs: int) -> tuple[float, int, bool]:
    from screwsym.book import entries, verify_all

    entries()  # load the registry outside the timing
    t0 = time.perf_counter()
    results = verify_all(jobs=jobs)
    return time.perf_counter() - t0, len(results), all(r.ok for r in results)


def time_plain() -> float:
    script = pathlib.Path(__file__).with_name("plain_sympy_check.py")
    t0 = time.perf_counter()
    subprocess.run([sys.executable, str(script)], check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=min(4, os.cpu_count() or 1))
    jobs = ap.parse_args().jobs
    plain = time_plain()
    for j in sorted({1, jobs}):
        book, n, ok = time_book(j)
        print(f"screwsym verify, {n} entries, jobs={j}: {book:.2f} s (all hold: {ok})")
        print(f"  plain SymPy script (process, incl. import): {plain:.2f} s; ratio book/plain = {book / plain:.2f}")


if __name__ == "__main__":
    main()
