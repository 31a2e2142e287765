"""``python -m screwsym``: the command line, see :mod:`screwsym.cli`."""

import sys

try:
    from .cli import main
except KeyboardInterrupt:  # pragma: no cover - timing: Ctrl-C during the command's start
    from ._launch import exit_if_command_line

    exit_if_command_line()
    raise

if __name__ == "__main__":
    sys.exit(main())
