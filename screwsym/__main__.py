"""``python -m screwsym``: the command line, see :mod:`screwsym.cli`."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
