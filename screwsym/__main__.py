"""``python -m screwsym``: the command line, see :mod:`screwsym.cli`."""

import sys

from ._launch import interrupted_quietly

with interrupted_quietly():  # Ctrl-C during the command's start ends it quietly
    from .cli import main

if __name__ == "__main__":
    sys.exit(main())
