"""Ctrl-C while the command line is still starting (importing SymPy) ends it quietly.

The ``screwsym`` command and ``python -m screwsym`` import the package before
:func:`screwsym.cli.main` runs, and that import takes most of the first second;
a ``KeyboardInterrupt`` there would print a traceback of SymPy's import.  The
package calls :func:`exit_if_command_line` from its import's ``except
KeyboardInterrupt``: launched as the command, it says so and exits with 130,
as ``main`` does; imported by anything else, it does nothing and the
interrupt goes on as usual.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterator
from contextlib import contextmanager


def launched_as_command() -> bool:
    """True when this process is the ``screwsym`` command or ``python -m screwsym``."""
    name = os.path.basename(sys.argv[0]) if sys.argv else ""
    if name in ("screwsym", "screwsym.exe", "screwsym-script.py"):
        return True
    orig = list(getattr(sys, "orig_argv", []))
    return any(a == "-m" and b == "screwsym" for a, b in zip(orig, orig[1:], strict=False))


def exit_if_command_line() -> None:
    if launched_as_command():
        sys.stderr.write("screwsym: interrupted\n")
        raise SystemExit(130)


@contextmanager
def interrupted_quietly() -> Iterator[None]:
    """Around the imports of the command's start: a ``KeyboardInterrupt`` inside ends the
    command quietly (:func:`exit_if_command_line`) and goes on as usual for anything else."""
    try:
        yield
    except KeyboardInterrupt:
        exit_if_command_line()
        raise
