r"""The ``screwsym`` command line: verify, show and list the book's statements.

``screwsym verify [IDS...] [--format table|markdown|json] [--jobs N]`` verifies
every entry of :mod:`screwsym.book` (or the named ones) and prints a table;
the exit status is 0 only if all hold.  ``screwsym show ID [--latex]`` prints
one entry; ``screwsym list`` prints one line per entry.  A bad id gives a
clear message and exit status 2.

>>> from screwsym.cli import main
>>> main(["verify", "1.34", "--format", "markdown"])  # doctest: +ELLIPSIS
| id | title | kind | result | time |
|---|---|---|---|---|
| 1.34 | Pitch of a screw | definition | holds | ... s |
<BLANKLINE>
1 of 1 statements hold (... s)
0
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from collections.abc import Sequence

__all__ = ["main"]


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="screwsym",
        description="Chapter 1 of Huang, Li & Ding as symbolically verified statements.",
    )
    sub = p.add_subparsers(dest="command", required=True)
    v = sub.add_parser("verify", help="verify all statements (or the named ones)")
    v.add_argument("ids", nargs="*", metavar="ID", help="entry ids such as 1.34 or 'Example 1.4'")
    v.add_argument("--format", choices=("table", "markdown", "json"), default="table")
    v.add_argument("--jobs", type=int, default=None,
                   help="worker processes (default: the number of CPUs, at most 4)")
    v.add_argument("--seed", type=int, default=0, help="seed of the numeric guard")
    s = sub.add_parser("show", help="show one statement")
    s.add_argument("id", metavar="ID")
    s.add_argument("--latex", action="store_true", help="print the statement as LaTeX")
    sub.add_parser("list", help="list every statement, one a line")
    return p


def _result_word(r) -> str:
    return "holds" if r.ok else "FAILS"


def _table(rows: list[list[str]], header: list[str]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(header)]
    line = "  ".join(h.ljust(w) for h, w in zip(header, widths, strict=False))
    out = [line, "  ".join("-" * w for w in widths)]
    out += ["  ".join(c.ljust(w) for c, w in zip(r, widths, strict=False)) for r in rows]
    return "\n".join(out)


def _failure_lines(r) -> list[str]:
    from .book._entry import as_text

    if r.error:
        return [f"  {r.id}: construction raised {r.error}"]
    return [f"  {r.id}: {c.label}: residual {as_text(c.residual)} ({c.how})" for c in r.failures]


def _verify(args, out, err) -> int:
    from .book import entry, verify_all

    for i in args.ids:
        entry(i)  # raises KeyError for a bad id before any work
    jobs = args.jobs or max(1, min(4, os.cpu_count() or 1))
    tty = err.isatty()

    def progress(i, n, r):
        if tty:
            err.write(f"\r[{i + 1}/{n}] {r.id:<28}")
            err.flush()

    t0 = time.perf_counter()
    results = verify_all(args.ids or None, seed=args.seed, progress=progress, jobs=jobs)
    total = time.perf_counter() - t0
    if tty:
        err.write("\r" + " " * 40 + "\r")
    from .book import entry as get

    held = sum(r.ok for r in results)
    if args.format == "json":
        data = {
            "ok": held == len(results),
            "held": held,
            "total": len(results),
            "seconds": round(total, 3),
            "entries": [
                {
                    "id": r.id, "title": get(r.id).title, "kind": get(r.id).kind, "ok": r.ok,
                    "seconds": round(r.elapsed, 4), "error": r.error,
                    "failures": [{"check": c.label, "residual": str(c.residual), "how": c.how}
                                 for c in r.failures],
                }
                for r in results
            ],
        }
        out.write(json.dumps(data, indent=2) + "\n")
    else:
        rows = [[r.id, get(r.id).title, get(r.id).kind, _result_word(r), f"{r.elapsed:.3f} s"]
                for r in results]
        header = ["id", "title", "kind", "result", "time"]
        if args.format == "markdown":
            out.write("| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
            out.write("".join("| " + " | ".join(r) + " |\n" for r in rows))
        else:
            out.write(_table(rows, header) + "\n")
        out.write(f"\n{held} of {len(results)} statements hold ({total:.2f} s)\n")
        for r in results:
            if not r.ok:
                out.write("\n".join(_failure_lines(r)) + "\n")
    return 0 if held == len(results) else 1


def _show(args, out) -> int:
    from .book import entry

    e = entry(args.id)
    out.write(f"{e.id}  ({e.section})  {e.title}\n")
    out.write(f"kind: {e.kind}\n\n")
    if args.latex:
        out.write(e.statement + "\n")
    else:
        out.write(_pretty(e.statement) + "\n")
    out.write("\nconstruction: " + e.construction + "\n")
    for label, items in (("errata", e.errata), ("notes", e.notes)):
        if items:
            out.write(f"\n{label}:\n" + "".join(f"  - {x}\n" for x in items))
    return 0


def _pretty(tex: str) -> str:
    """A Unicode rendering of the LaTeX statement, without a LaTeX parser."""
    import re

    rep = [
        (r"\\mathbf\{(\w+)\}", r"\1"), (r"\\mathbf\s*(\w)", r"\1"), (r"\\boldsymbol\\omega", "ω"),
        (r"\\overrightarrow\{(\w+)\}", r"\1⃗"), (r"\\frac\{([^{}]*)\}\{([^{}]*)\}", r"(\1)/(\2)"),
        (r"\\tfrac\{([^{}]*)\}\{([^{}]*)\}", r"(\1)/(\2)"), (r"\\sqrt\{([^{}]*)\}", r"√(\1)"),
        (r"\\times", "×"), (r"\\cdot", "·"), (r"\\circ", "∘"), (r"\\neq", "≠"), (r"\\iff", "⇔"),
        (r"\\Rightarrow", "⇒"), (r"\\perp", "⊥"), (r"\\infty", "∞"), (r"\\lambda", "λ"),
        (r"\\omega", "ω"), (r"\\alpha", "α"), (r"\\rho", "ρ"), (r"\\dim", "dim"),
        (r"\\sin", "sin"), (r"\\cos", "cos"), (r"\\in", "∈"), (r"\\\$", "$"), (r"\\text\{([^{}]*)\}", r"\1"),
        (r"\\left|\\right", ""), (r"\\qquad|\\quad", "    "), (r"\\[,;!]|\\ ", " "), (r"\\\\", "\n"),
        (r"\\(begin|end)\{(vmatrix|array)\}(\{[lc]+\})?", ""), (r"&", "  "), (r"\^0", "⁰"),
        (r"_\{?0\}?", "₀"), (r"_\{(\w+)\}", r"_\1"), (r"\^T", "ᵀ"), (r"\^\{?2\}?", "²"),
        (r"\\\{|\\\}", ""), (r"[{}]", ""),
    ]
    for pat, new in rep:
        tex = re.sub(pat, new, tex)
    return "\n".join("  " + " ".join(line.split()) for line in tex.splitlines())


def _list(out) -> int:
    from .book import entries

    es = entries()
    w = max(len(e.id) for e in es)
    for e in es:
        out.write(f"{e.id:<{w}}  {e.kind:<11}  {e.title}\n")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line with ``argv`` (default: ``sys.argv[1:]``); return the exit status."""
    out, err = sys.stdout, sys.stderr
    try:
        args = _parser().parse_args(list(argv) if argv is not None else None)
    except SystemExit as exc:  # argparse: --help gives 0, a usage error 2
        return int(exc.code or 0)
    try:
        if args.command == "verify":
            return _verify(args, out, err)
        if args.command == "show":
            return _show(args, out)
        return _list(out)
    except KeyError as exc:
        err.write(f"screwsym: error: {exc.args[0]}\n")
        return 2
    except ValueError as exc:
        err.write(f"screwsym: error: {exc}\n")
        return 2
    except BrokenPipeError:  # e.g. `screwsym list | head`
        sys.stderr.close()
        return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
