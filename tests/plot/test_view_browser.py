"""The exported view in a real browser: headless Chromium, network off, opens the HTML file.

Checks that the scene drew: the screenshot shows the twists' green in the scene (not a blank
or empty page), the page's plot holds the figure's traces and WebGL objects for each
(written into the DOM by the page itself, read with ``--dump-dom``), and no console error or
uncaught exception (counted by the page's first script).  Chromium from the system's
packages (``.ci/run`` installs Debian's where it can); skipped with the reason where absent.
The network is off: a fresh network namespace (``unshare -n``) where the user may make one,
and in any case Chromium's host resolver maps every name to nothing.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("plotly")
image = pytest.importorskip("matplotlib.image")

from screwsym.motion.chain import ur5  # noqa: E402
from screwsym.plot import view  # noqa: E402
from screwsym.plot.viewer import _ERROR_HOOK  # noqa: E402
from screwsym.systems.joints import P, R  # noqa: E402
from screwsym.systems.parallel import Limb, ParallelMechanism  # noqa: E402


def chromium() -> str | None:
    for name in (os.environ.get("SCREWSYM_CHROMIUM"), "chromium", "chromium-browser"):
        if name and (path := shutil.which(name)):
            return path
    return None


def _isolated() -> list[str]:
    """``unshare -n`` where it works (root, or user namespaces allowed), else nothing."""
    unshare = shutil.which("unshare")
    if unshare and subprocess.run([unshare, "-n", "true"], capture_output=True).returncode == 0:
        return [unshare, "-n"]
    return []


def open_in_chromium(page: str, tmp_path, size: str = "900,650",
                     budget: int = 3000) -> tuple[str, np.ndarray, str]:
    """``(dom, screenshot RGB array, stderr)`` of ``page`` (a file) in headless Chromium."""
    exe = chromium()
    if exe is None:
        pytest.skip("chromium not found (Debian: apt-get install chromium; or set SCREWSYM_CHROMIUM)")
    shot = tmp_path / "shot.png"
    cmd = [*_isolated(), exe, "--headless", "--no-sandbox", "--disable-gpu",
           "--enable-unsafe-swiftshader", "--disable-background-networking",
           "--disable-component-update", "--disable-sync", "--no-first-run",
           "--host-resolver-rules=MAP * ~NOTFOUND", "--proxy-server=127.0.0.1:9",
           f"--user-data-dir={tmp_path / 'profile'}", f"--window-size={size}",
           f"--virtual-time-budget={budget}", "--enable-logging=stderr", "--v=0",
           f"--screenshot={shot}", "--dump-dom", f"file://{page}"]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-2000:]
    return run.stdout, image.imread(str(shot))[..., :3], run.stderr


def attribute(dom: str, name: str) -> str | None:
    m = re.search(rf'{name}="([^"]*)"', dom)
    return m.group(1) if m else None


def green_pixels(rgb: np.ndarray) -> int:
    """Pixels of the twists' colour #2ca02c in the scene (the left 3/4: the legend is right)."""
    scene = rgb[:, : rgb.shape[1] * 3 // 4]
    target = np.array([0x2C, 0xA0, 0x2C]) / 255
    return int(np.sum(np.all(np.abs(scene - target) < 0.08, axis=-1)))


def drew(rgb: np.ndarray) -> bool:
    return float(rgb.std()) > 0.02 and green_pixels(rgb) >= 40


#: console lines that are no problem: software WebGL's performance notes, Chromium's advice,
#: and (on the documentation site) its note that MathJax's local web fonts load "slowly"
_BENIGN = ("GL Driver Message", "willReadFrequently", "Slow network is detected. See")


def console_errors(stderr: str) -> list[str]:
    """The page's console lines (Chromium logs them all at one level) but the benign ones:
    uncaught exceptions, failed loads (``net::ERR_...``), plotly's warnings, any message."""
    return [ln for ln in stderr.splitlines()
            if ":CONSOLE" in ln and not any(b in ln for b in _BENIGN)]


_NEW_PLOT = re.compile(r'Plotly\.newPlot\(\s*"(screwsym-[0-9a-f]+)",\s*')


def page_views(dom: str) -> dict[str, tuple[int, int | None, int | None]]:
    """Each view of a page (its plot div's id): ``(traces in its figure, traces drawn, WebGL
    objects)``; the figure's traces read from the page's own ``Plotly.newPlot`` call, the drawn
    ones from the attributes the view's post-script wrote (None: never drawn)."""
    out = {}
    for m in _NEW_PLOT.finditer(dom):
        data, _ = json.JSONDecoder().raw_decode(dom, m.end())
        tag = re.search(rf'<div[^>]*\bid="{m.group(1)}"[^>]*>', dom)
        drawn = tag and attribute(tag.group(0), "data-screwsym-traces")
        objects = tag and attribute(tag.group(0), "data-screwsym-objects")
        out[m.group(1)] = (len(data), int(drawn) if drawn else None,
                           int(objects) if objects else None)
    return out


def test_the_checks_can_fail():
    blank = np.ones((100, 120, 3))
    assert not drew(blank)
    grey = np.random.default_rng(0).random((100, 120, 3)) * 0.2 + 0.4     # busy, not green
    assert not drew(grey)
    painted = blank.copy()
    painted[40:60, 10:40] = np.array([0x2C, 0xA0, 0x2C]) / 255
    assert drew(painted)
    assert console_errors('[1:1:INFO:CONSOLE:3] "Uncaught Error: x", source: f (3)') != []
    assert console_errors('[1:1:INFO:CONSOLE:9] "WARN: Invalid color specifier"') != []
    assert console_errors('[1:1:INFO:CONSOLE:0] "[.WebGL-0x1]GL Driver Message (OpenGL, '
                          'Performance): GPU stall due to ReadPixels"') == []
    call = '<script>Plotly.newPlot(  "screwsym-0a", [{"type": "scatter3d"}, {"x": "]"}], {})'
    assert page_views(f'<div id="screwsym-0a" data-screwsym-traces="2" '
                      f'data-screwsym-objects="3"></div>{call}') == {"screwsym-0a": (2, 2, 3)}
    assert page_views(f'<div id="screwsym-0a"></div>{call}') == {"screwsym-0a": (2, None, None)}


@pytest.mark.slow
def test_the_exported_view_draws_in_headless_chromium(tmp_path):
    v = view(ur5(), [0, 0.5, -1, 0, 0.5, 0], twists=True)
    page = v.to_html(tmp_path / "ur5.html")
    dom, rgb, log = open_in_chromium(page, tmp_path)
    n = len(v.figure.data)
    assert attribute(dom, "data-screwsym-traces") == str(n)
    assert int(attribute(dom, "data-screwsym-objects") or -1) >= n     # a WebGL object per trace
    assert attribute(dom, "data-screwsym-errors") == "0"
    assert console_errors(log) == []
    assert drew(rgb), "the screenshot shows no drawn twist"


@pytest.mark.slow
def test_the_moving_delta_and_the_couples_draw_in_headless_chromium(tmp_path):
    from screwsym.plot.models import delta

    d = delta()
    s = np.linspace(0, 2 * np.pi, 12)
    circle = np.column_stack([0.5 * np.cos(s), 0.5 * np.sin(s), np.full(12, -2.8)])
    z = [0, 0, 1]
    base, platform = [(3, -1), (-1, 3), (-2, -3)], [(1, 0), (0, 1), (-1, -1)]
    rpr = ParallelMechanism(*(Limb(R([a[0], a[1], 0], z), P([b[0] - a[0], b[1] - a[1], 0]),
                                   R([b[0], b[1], 0], z), actuated=1)
                              for a, b in zip(base, platform, strict=True)))
    views = {"delta": view(d.mechanism, path=d.configurations(circle), variables=d.variables),
             "rpr": view(rpr, screws={"constraint": rpr.constraints.basis()})}
    assert views["rpr"].kinds["couples"] == 2
    for name, v in views.items():
        page = v.to_html(tmp_path / f"{name}.html")
        dom, rgb, log = open_in_chromium(page, tmp_path)
        n = len(v.figure.data)
        assert attribute(dom, "data-screwsym-traces") == str(n), name
        assert int(attribute(dom, "data-screwsym-objects") or -1) >= n, name
        assert attribute(dom, "data-screwsym-errors") == "0", name
        assert console_errors(log) == [], name
        assert float(rgb.std()) > 0.02, name


@pytest.mark.slow
def test_a_console_error_is_seen(tmp_path):
    page = tmp_path / "bad.html"
    page.write_text(f"<html><head>{_ERROR_HOOK}</head><body><p>x</p>"
                    "<script>console.error('boom')</script></body></html>", encoding="utf-8")
    dom, _, _ = open_in_chromium(str(page), tmp_path)
    assert attribute(dom, "data-screwsym-errors") == "1"


@pytest.mark.slow
def test_to_png_draws_the_view(tmp_path):
    if chromium() is None:
        pytest.skip("chromium not found (Debian: apt-get install chromium; or set SCREWSYM_CHROMIUM)")
    out = view(ur5(), [0, 0.5, -1, 0, 0.5, 0], twists=True).to_png(tmp_path / "ur5.png", width=700)
    rgb = image.imread(str(out))[..., :3]
    assert rgb.shape[1] == 700 and drew(rgb)


#: the documentation site's page of 3-D views (notebook 13), read from a built site
_SITE_PAGE = "13-mechanisms-in-3d.html"


def _site_page() -> Path:
    given = os.environ.get("SCREWSYM_SITE")
    if not given:
        pytest.skip("no built site: SCREWSYM_SITE=build/docs after python -m sphinx -b html "
                    "notebooks build/docs (CI sets it)")
    page = Path(given).resolve() / _SITE_PAGE
    if not page.exists():
        pytest.fail(f"SCREWSYM_SITE={given} has no {_SITE_PAGE}")
    return page


@pytest.mark.slow
def test_the_sites_page_draws_its_views_with_the_shared_plotlyjs(tmp_path):
    """The site's page opened from disk, network off: every view drawn, with the one plotly.js
    of the site's _static (the page embeds none: tests/docs/test_site.py), no console error."""
    page = _site_page()
    dom, rgb, log = open_in_chromium(str(page), tmp_path, size="1200,9600", budget=8000)
    views = page_views(dom)
    assert len(views) >= 6, views
    for name, (traces, drawn, objects) in views.items():
        assert drawn == traces, f"{name}: {drawn} of {traces} traces drawn"
        assert objects is not None and objects >= traces, f"{name}: {objects} WebGL objects"
    assert console_errors(log) == []
    assert drew(rgb), "the screenshot shows no drawn twist"          # the UR5's joint twists


@pytest.mark.slow
def test_the_sites_page_without_its_plotlyjs_draws_nothing(tmp_path):
    """Negative control: the same page with the site's plotly.js script removed draws no view
    and says so on the console (so the test above sees the shared script at work)."""
    page = _site_page()
    html = page.read_text(encoding="utf-8")
    stripped = re.sub(r'<script src="_static/plotly-[^"]*"></script>', "", html)
    assert stripped != html
    copy = tmp_path / "site"
    copy.mkdir()
    (copy / "_static").symlink_to(page.parent / "_static")
    (copy / _SITE_PAGE).write_text(stripped, encoding="utf-8")
    dom, _, log = open_in_chromium(str(copy / _SITE_PAGE), tmp_path, size="900,650", budget=3000)
    views = page_views(dom)
    assert len(views) >= 6 and all(drawn is None for _, drawn, _ in views.values()), views
    assert any("loads no plotly.js" in line for line in console_errors(log))
