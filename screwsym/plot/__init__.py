r"""Pictures of lines, screws, twists and wrenches in matplotlib 3D axes, and mechanisms in 3-D.

:func:`view` draws a chain, a parallel mechanism or screws in the browser with plotly (the
``view`` extra); see :mod:`screwsym.plot.viewer`.

Needs matplotlib (``pip install -e ".[plot]"`` from a clone); see :mod:`screwsym.plot.figures`.
``screwsym.plot`` is loaded on first use and is not part of ``from screwsym import *``
(it would shadow SymPy's ``plot``).
"""

from .figures import (
    find_artists,
    helix_advance,
    plot,
    plot_common_normal,
    plot_couple,
    plot_frame,
    plot_line,
    plot_screw,
    plot_twist,
    plot_wrench,
)
from .viewer import Live, View, live, view

__all__ = [
    "plot",
    "plot_line",
    "plot_screw",
    "plot_couple",
    "plot_twist",
    "plot_wrench",
    "plot_common_normal",
    "plot_frame",
    "find_artists",
    "helix_advance",
    "view",
    "View",
    "live",
    "Live",
]
