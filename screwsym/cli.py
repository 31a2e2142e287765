r"""The ``screwsym`` command line: verify, show and list the book's statements.

``screwsym verify [IDS...] [-v] [--format table|markdown|json] [--jobs N]``
verifies every entry of :mod:`screwsym.book` (or the named ones, each once)
and prints a table; ``-v`` adds each statement, its checks with their
residuals and stages, the counter-examples and the errata (the JSON always
has them).  The exit status is 0 only if all hold, 1 if one fails, 2 for a
usage error and 130 when interrupted (after a summary of what was verified).
``screwsym show ID [--latex]`` prints one entry as plain text; ``screwsym
list`` prints one line per entry; ``screwsym --version`` the version.

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

import os
import sys

from ._launch import interrupted_quietly

with interrupted_quietly():  # Ctrl-C while the command is still importing ends it quietly
    import argparse
    import json
    import time
    from collections.abc import Sequence

__all__ = ["main"]

#: how the book is cited in errata
BOOK = "Huang, Li & Ding, Theory of Parallel Mechanisms (Springer 2013), Chapter 1"


def _cpus() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover (macOS, Windows)
        return max(1, os.cpu_count() or 1)


def _parser() -> argparse.ArgumentParser:
    from ._version import __version__

    p = argparse.ArgumentParser(
        prog="screwsym",
        description="Chapter 1 of Huang, Li & Ding as symbolically verified statements.",
    )
    p.add_argument("--version", action="version", version=f"screwsym {__version__}")
    sub = p.add_subparsers(dest="command", required=True)
    v = sub.add_parser("verify", help="verify all statements (or the named ones)")
    v.add_argument("ids", nargs="*", metavar="ID", help="entry ids such as 1.34 or 'Example 1.4'")
    v.add_argument("-v", "--verbose", action="store_true",
                   help="show each statement, its checks with residuals and stages, and errata")
    v.add_argument("--format", choices=("table", "markdown", "json"), default="table")
    v.add_argument("--jobs", type=int, default=None,
                   help="worker processes (default: the number of CPUs, at most 4; "
                        "never more than the CPUs)")
    v.add_argument("--seed", type=int, default=0, help="seed of the numeric guard")
    s = sub.add_parser("show", help="show one statement")
    s.add_argument("id", metavar="ID")
    s.add_argument("--latex", action="store_true", help="print the statement as LaTeX")
    sub.add_parser("list", help="list every statement, one a line")
    return p


class _Out:
    """A stream that notes when it is closed (``>&-``, a pipe whose reader left)."""

    def __init__(self, stream) -> None:
        self.stream, self.closed = stream, stream is None

    def write(self, text: str) -> None:
        if self.closed:
            return
        try:
            self.stream.write(text)
            self.stream.flush()
        except (BrokenPipeError, OSError, ValueError):
            self.closed = True
            try:  # keep Python's flush at exit from failing on the dead stream
                devnull = os.open(os.devnull, os.O_WRONLY)
                os.dup2(devnull, self.stream.fileno())
            except (OSError, ValueError, AttributeError):
                pass


def _where(e) -> str:
    label = f"Eq. ({e.id})" if e.id[:1].isdigit() else e.id
    return f"{BOOK}, Section {e.section}, {label}"


def _result_word(r) -> str:
    return "holds" if r.ok else "FAILS"


def _table(rows: list[list[str]], header: list[str]) -> str:
    widths = [max([len(h)] + [len(r[i]) for r in rows]) for i, h in enumerate(header)]
    out = ["  ".join(h.ljust(w) for h, w in zip(header, widths, strict=True)).rstrip(),
           "  ".join("-" * w for w in widths)]
    out += ["  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows]
    return "\n".join(out)


def _check_line(c) -> str:
    from .book import as_text

    word = "holds" if c.ok else "FAILS"
    book = "  [the book's wording, shown failing]" if c.book else ""
    if c.kind == "zero":
        detail = f"residual {as_text(c.residual) if not c.ok else 0} ({c.how})"
    elif c.kind == "nonzero":
        detail = c.how
    elif c.kind == "holds":
        detail = f"predicate is {c.residual}"
    else:
        detail = f"{c.how}: {as_text(c.residual)}"
    return f"    {word}  {c.kind:<11} {c.label}\n{'':17}{detail}{book}"


def _details(r, e) -> list[str]:
    lines = [f"{e.id}  {e.title}  (Section {e.section}, {e.kind}): {_result_word(r)}, "
             f"{r.elapsed:.3f} s"]
    lines += ["  statement:"] + [f"    {x}" for x in e.text.splitlines()]
    lines.append("  checks:")
    if r.error:
        lines.append(f"    the construction raised {r.error}")
    lines += [_check_line(c) for c in r.checks]
    if e.errata:
        lines.append(f"  errata ({_where(e)}):")
        lines += [f"    - {x}" for x in e.errata]
    if e.notes:
        lines.append("  notes:")
        lines += [f"    - {x}" for x in e.notes]
    return lines


def _failure_lines(r) -> list[str]:
    from .book import as_text

    if r.error:
        return [f"  {r.id}: construction raised {r.error}"]
    return [f"  {r.id}: {c.label}: residual {as_text(c.residual)} ({c.how})" for c in r.failures]


def _json(results, total, complete) -> dict:
    from .book import as_text, entry

    def one(r):
        e = entry(r.id)
        return {
            "id": r.id, "title": e.title, "section": e.section, "kind": e.kind,
            "statement": e.text, "statement_latex": e.statement, "ok": r.ok,
            "seconds": round(r.elapsed, 4), "error": r.error,
            "checks": [{"label": c.label, "kind": c.kind, "ok": c.ok,
                        "residual": as_text(c.residual), "how": c.how, "book": c.book}
                       for c in r.checks],
            "failures": [c.label for c in r.failures],
            "errata": list(e.errata), "errata_source": _where(e) if e.errata else None,
            "notes": list(e.notes),
        }

    held = sum(r.ok for r in results)
    return {"ok": complete and held == len(results), "complete": complete, "held": held,
            "total": len(results), "seconds": round(total, 3),
            "entries": [one(r) for r in results]}


def _verify(args, out: _Out, err) -> int:
    from .book import entry, verify_all

    chosen: list[str] = []
    for i in args.ids:
        id_ = entry(i).id  # raises KeyError for a bad id before any work
        if id_ not in chosen:
            chosen.append(id_)
    if args.jobs is not None and args.jobs < 1:
        raise ValueError(f"--jobs: expected a positive integer, got {args.jobs}")
    jobs = min(args.jobs or 4, _cpus())
    tty = err.isatty()
    done: list = []

    def progress(i, n, r):
        done.append(r)
        if tty:
            err.write(f"\r[{i + 1}/{n}] {r.id:<28}")
            err.flush()

    t0 = time.perf_counter()
    interrupted = False
    try:
        verify_all(chosen or None, seed=args.seed, progress=progress, jobs=jobs)
    except KeyboardInterrupt:
        interrupted = True
    total = time.perf_counter() - t0
    if tty:
        err.write("\r" + " " * 40 + "\r")
    results = done
    held = sum(r.ok for r in results)
    summary = f"{held} of {len(results)} statements hold ({total:.2f} s)"
    if interrupted:
        summary = f"interrupted after {len(results)} statements: " + summary
    if args.format == "json":
        out.write(json.dumps(_json(results, total, not interrupted), indent=2,
                             ensure_ascii=False) + "\n")
    else:
        rows = [[r.id, entry(r.id).title, entry(r.id).kind, _result_word(r), f"{r.elapsed:.3f} s"]
                for r in results]
        header = ["id", "title", "kind", "result", "time"]
        if args.verbose:
            for r in results:
                out.write("\n".join(_details(r, entry(r.id))) + "\n\n")
        elif args.format == "markdown":
            out.write("| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
            out.write("".join("| " + " | ".join(r) + " |\n" for r in rows))
        else:
            out.write(_table(rows, header) + "\n")
        if not args.verbose:
            out.write("\n")
        out.write(summary + "\n")
        if not args.verbose:
            for r in results:
                if not r.ok:
                    out.write("\n".join(_failure_lines(r)) + "\n")
    if out.closed:
        err.write(f"screwsym: standard output is closed; {summary}\n")
    if interrupted:
        if args.format == "json":
            err.write(f"screwsym: {summary}\n")
        return 130
    return 0 if held == len(results) else 1


def _show(args, out: _Out) -> int:
    from .book import entry

    e = entry(args.id)
    out.write(f"{e.id}  {e.title}\n")
    out.write(f"Section {e.section}, {e.kind}\n\n")
    out.write((e.statement if args.latex else e.text) + "\n")
    out.write("\nconstruction: " + e.construction + "\n")
    kinds = {"zero": "vanishes", "nonzero": "counter-example, non-zero", "holds": "is True",
             "nonnegative": "nonnegative"}
    out.write("\nchecks (screwsym verify -v shows their results):\n")
    out.write("".join(f"  - {c.label}: {kinds[c.kind]}"
                      + (" (shows the book's wording failing)" if c.book else "") + "\n"
                      for c in e.construct().checks))
    if e.errata:
        out.write(f"\nerrata ({_where(e)}):\n" + "".join(f"  - {x}\n" for x in e.errata))
    if e.notes:
        out.write("\nnotes:\n" + "".join(f"  - {x}\n" for x in e.notes))
    return 0


def _list(out: _Out) -> int:
    from .book import entries

    es = entries()
    w = max(len(e.id) for e in es)
    for e in es:
        out.write(f"{e.id:<{w}}  {e.kind:<11}  {e.title}\n")
        if out.closed:
            break
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line with ``argv`` (default: ``sys.argv[1:]``); return the exit status."""
    out, err = _Out(sys.stdout), sys.stderr
    try:
        args = _parser().parse_args(list(argv) if argv is not None else None)
    except SystemExit as exc:  # argparse: --help and --version give 0, a usage error 2
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
    except KeyboardInterrupt:
        err.write("screwsym: interrupted\n")
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
