"""Screenshots of three views of notebook 13, each exported as one self-contained HTML file.

Run from the repository root (needs plotly and a Chromium: ``apt-get install chromium``)::

    python notebooks/figures/make_view_screenshots.py

Writes ``notebooks/figures/screenshots/view-ur5.png`` (the UR5 with its joint twists),
``view-3rps.png`` (the 3-RPS with its constraint and actuation wrenches at its singular pose
h = (2, 2, 4/11)) and ``view-delta.png`` (the Delta with its parallelograms, on its platform
circle).  Each view is written by ``View.to_html`` and opened from disk in headless Chromium
with the network off (``unshare -n`` where allowed, and every host name resolved to nothing,
as tests/plot/test_view_browser.py does); the script stops if a page logs a console error or
draws no WebGL object.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from sympy import Rational, sqrt, symbols

from screwsym.motion.chain import ur5
from screwsym.plot import view
from screwsym.plot.models import delta
from screwsym.systems.joints import P, R, S
from screwsym.systems.parallel import Limb, ParallelMechanism

OUT = Path(__file__).resolve().parent / "screenshots"


def views() -> dict[str, object]:
    q0 = np.array([0, -np.pi / 4, np.pi / 2, -np.pi / 4, np.pi / 2, 0])
    out = {"view-ur5": view(ur5(), q0, twists=True, title="UR5: joint twists at q0")}
    E = [[1, 0, 0], [-Rational(1, 2), sqrt(3) / 2, 0], [-Rational(1, 2), -sqrt(3) / 2, 0]]
    h = symbols("h1:4", real=True)

    def leg(e, hi):
        b = [2 * c for c in e]
        top = [b[0] - Rational(1, 2) * e[0], b[1] - Rational(1, 2) * e[1], hi]
        return Limb(R(b, [-e[1], e[0], 0]), P([t - s for t, s in zip(top, b, strict=True)]),
                    S(top), actuated=1)

    rps = ParallelMechanism(*(leg(e, hi) for e, hi in zip(E, h, strict=True)))
    out["view-3rps"] = view(rps, [2, 2, 4 / 11], variables=h,
                            screws={"constraint wrenches": rps.constraints,
                                    "actuation wrenches": rps.actuation_wrenches()},
                            title="3-RPS at h = (2, 2, 4/11): singular (type II)")
    d = delta()
    s = np.linspace(0, 2 * np.pi, 36)
    circle = np.column_stack([0.5 * np.cos(s), 0.5 * np.sin(s), -2.8 + 0.2 * np.sin(2 * s)])
    out["view-delta"] = view(d.mechanism, path=d.configurations(circle), variables=d.variables,
                             title="The Delta: arms, parallelograms and platform")
    return out


def shoot(html: Path, png: Path, tmp: Path, exe: str) -> None:
    unshare = shutil.which("unshare")
    isolated = ([unshare, "-n"] if unshare and subprocess.run(
        [unshare, "-n", "true"], capture_output=True).returncode == 0 else [])
    cmd = [*isolated, exe, "--headless", "--no-sandbox", "--disable-gpu",
           "--enable-unsafe-swiftshader", "--disable-background-networking",
           "--disable-component-update", "--disable-sync", "--no-first-run",
           "--hide-scrollbars", "--host-resolver-rules=MAP * ~NOTFOUND",
           "--proxy-server=127.0.0.1:9", f"--user-data-dir={tmp / 'profile'}",
           "--window-size=1000,700", "--virtual-time-budget=4000", "--enable-logging=stderr",
           "--v=0", f"--screenshot={png}", "--dump-dom", html.as_uri()]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=180)
    if run.returncode != 0:
        sys.exit(f"{html.name}: chromium failed: {run.stderr[-1000:]}")
    errors = re.search(r'data-screwsym-errors="(\d+)"', run.stdout)
    objects = re.search(r'data-screwsym-objects="(-?\d+)"', run.stdout)
    if not errors or errors.group(1) != "0" or not objects or int(objects.group(1)) <= 0:
        sys.exit(f"{html.name}: errors {errors and errors.group(1)}, WebGL objects "
                 f"{objects and objects.group(1)}")
    print(f"{png.relative_to(OUT.parent.parent.parent)}: {objects.group(1)} WebGL objects, "
          f"network {'off (unshare -n)' if isolated else 'unresolvable'}")


def main() -> None:
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if exe is None:
        sys.exit("no chromium on the PATH (Debian: apt-get install chromium)")
    OUT.mkdir(exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        for name, v in views().items():
            html = Path(tmp) / f"{name}.html"
            v.to_html(html)
            shoot(html, OUT / f"{name}.png", Path(tmp), exe)


if __name__ == "__main__":
    main()
