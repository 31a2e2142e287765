"""Regenerate the README picture ``notebooks/figures/cylindroid.png``.

The cylindroid: the axes of the screws ``cos(theta) $1 + sin(theta) $2`` as
theta turns, for two principal screws on the x and y axes with pitches
``h1 = 1/2`` and ``h2 = -1/2``.  The pitch and the height of each axis are
derived symbolically with screwsym, turned into a NumPy function with
``screwsym.lambdify`` and drawn; the two principal screws are drawn with
``screwsym.plot``, their helices showing the sign of the pitch.

Usage: ``python notebooks/make_readme_figure.py [output.png]``
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import sympy as sp  # noqa: E402

import screwsym  # noqa: E402
from screwsym import Screw  # noqa: E402
from screwsym.plot import plot_screw  # noqa: E402

DEFAULT = Path(__file__).resolve().parent / "figures" / "cylindroid.png"


def main(out: Path = DEFAULT) -> Path:
    theta, h1, h2 = sp.symbols("theta h_1 h_2", real=True)
    s1 = Screw.from_axis([0, 0, 0], [1, 0, 0], h1)
    s2 = Screw.from_axis([0, 0, 0], [0, 1, 0], h2)
    s = sp.cos(theta) * s1 + sp.sin(theta) * s2
    closed_form = (sp.trigsimp(s.pitch), sp.trigsimp(s.foot[2]))
    cylindroid = screwsym.lambdify([theta, h1, h2], closed_form, name="cylindroid")

    H1, H2 = 0.5, -0.5
    T, R = np.meshgrid(np.linspace(0, np.pi, 181), np.linspace(-1.2, 1.2, 25))
    pitch, height = cylindroid(T, H1, H2)

    fig = plt.figure(figsize=(7, 5.6), dpi=110)
    ax = fig.add_subplot(projection="3d")
    norm = plt.Normalize(min(H1, H2), max(H1, H2))
    ax.plot_surface(R * np.cos(T), R * np.sin(T), height, facecolors=plt.cm.coolwarm(norm(pitch)),
                    rstride=1, cstride=3, linewidth=0.2, edgecolor=(1, 1, 1, 0.25),
                    alpha=0.6, shade=False)
    values = {h1: sp.Rational(1, 2), h2: -sp.Rational(1, 2)}
    plot_screw(s1, ax, subs=values, length=2.4, color="darkred", label=r"$\$_1$, h = +1/2")
    plot_screw(s2, ax, subs=values, length=2.4, color="navy", label=r"$\$_2$, h = -1/2")
    ax.set_zlim(-1.2, 1.2)
    ax.view_init(elev=24, azim=-58)
    ax.set_title(r"The cylindroid: axes of $\cos\theta\,\$_1 + \sin\theta\,\$_2$, coloured by pitch",
                 fontsize=10)
    bar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="coolwarm"), ax=ax, shrink=0.6,
                       pad=0.1)
    bar.set_label("pitch h")
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, bbox_inches="tight", metadata={"Software": None})
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(Path(sys.argv[1]) if len(sys.argv) > 1 else DEFAULT))
