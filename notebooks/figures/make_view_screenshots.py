"""Screenshots of three views of notebook 13, taken from the BUILT documentation site, offline.

Build the site, then run from the repository root (needs a Chromium: ``apt-get install
chromium``; nothing else beyond the standard library and matplotlib's Pillow)::

    python -m sphinx -b html notebooks build/docs
    python notebooks/figures/make_view_screenshots.py build/docs

How they are made: the site's own page of notebook 13 (``13-mechanisms-in-3d.html``, with the
one plotly.js of the site's ``_static``) is opened from disk (``file://``) in headless Chromium
with the network off: in a fresh network namespace (``unshare -n``) where the user may make one,
and in any case with every host name resolved to nothing and a dead proxy (as
tests/plot/test_view_browser.py does).  The page is not copied or edited.  The script drives
the browser through the DevTools protocol over a pipe (``--remote-debugging-pipe``: JSON
messages on file descriptors 3 and 4, no WebSocket library, no open port), waits until every
view of the page has drawn (each view's post-script writes ``data-screwsym-objects``, the
number of WebGL objects in its scene), scrolls each wanted view into the window and takes a
screenshot clipped to that view's plot (its ``<div>``: the scene, the legend and, on a path,
the slider).  It stops if the page logs a console error or an uncaught exception (the site's
MathJax note that its local fonts load "slowly" is no error), or if a wanted view draws no WebGL
object.  The PNGs are reduced to 256 colours (Pillow) to keep them small.

Writes ``notebooks/figures/screenshots/view-ur5.png`` (the UR5 with its joint twists, first
frame of its path), ``view-3rps.png`` (the rigid 3-RPS with its constraint and actuation
wrenches at its singular pose) and ``view-delta.png`` (the Delta with its parallelograms and
its solid platform, first frame of its circle).
"""

from __future__ import annotations

import base64
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

OUT = Path(__file__).resolve().parent / "screenshots"
PAGE = "13-mechanisms-in-3d.html"

#: each screenshot: (file name, the start of the view's title on the page)
WANTED = (("view-ur5", "UR5: joint twists along a path"),
          ("view-3rps", "3-RPS at its singular pose"),
          ("view-delta", "The Delta: arms, parallelograms and platform"))

#: console lines that are no problem: software WebGL's performance notes, and the site's MathJax
#: note that its local web fonts load "slowly" (Chromium's intervention for slow networks)
_BENIGN = ("GL Driver Message", "willReadFrequently", "Slow network is detected")


class Browser:
    """Headless Chromium driven by the DevTools protocol over ``--remote-debugging-pipe``."""

    def __init__(self, exe: str, profile: Path, isolated: list[str], width: int = 1100,
                 height: int = 900) -> None:
        self._to_chrome_r, self._to_chrome_w = os.pipe()
        self._from_chrome_r, self._from_chrome_w = os.pipe()

        def fds() -> None:                 # in the child: read fd 3, write fd 4
            import fcntl

            high = [fcntl.fcntl(fd, fcntl.F_DUPFD, 10)       # out of the way of 3 and 4 first
                    for fd in (self._to_chrome_r, self._from_chrome_w)]
            os.dup2(high[0], 3)
            os.dup2(high[1], 4)

        cmd = [*isolated, exe, "--headless", "--no-sandbox", "--disable-gpu",
               "--enable-unsafe-swiftshader", "--disable-background-networking",
               "--disable-component-update", "--disable-sync", "--no-first-run",
               "--hide-scrollbars", "--host-resolver-rules=MAP * ~NOTFOUND",
               "--proxy-server=127.0.0.1:9", f"--user-data-dir={profile}",
               f"--window-size={width},{height}", "--remote-debugging-pipe", "about:blank"]
        # close_fds=False: the child keeps the 3 and 4 made above (every other descriptor of
        # this process is close-on-exec, PEP 446)
        self.proc = subprocess.Popen(cmd, preexec_fn=fds, close_fds=False,
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(self._to_chrome_r)
        os.close(self._from_chrome_w)
        self._out = os.fdopen(self._to_chrome_w, "wb", buffering=0)
        self._in = os.fdopen(self._from_chrome_r, "rb", buffering=0)
        self._buf = b""
        self._next = 0
        self.events: list[dict] = []
        self.session: str | None = None

    def _read(self) -> dict:
        while b"\0" not in self._buf:
            chunk = self._in.read(1 << 16)
            if not chunk:
                raise RuntimeError("chromium closed the pipe")
            self._buf += chunk
        msg, self._buf = self._buf.split(b"\0", 1)
        return json.loads(msg)

    def send(self, method: str, session: bool = True, **params: object) -> dict:
        self._next += 1
        msg: dict = {"id": self._next, "method": method, "params": params}
        if session and self.session:
            msg["sessionId"] = self.session
        self._out.write(json.dumps(msg).encode() + b"\0")
        while True:
            reply = self._read()
            if reply.get("id") == self._next:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def evaluate(self, expression: str) -> object:
        out = self.send("Runtime.evaluate", expression=expression, returnByValue=True,
                        awaitPromise=True)
        if "exceptionDetails" in out:
            raise RuntimeError(f"{expression[:60]}...: {out['exceptionDetails']}")
        return out["result"].get("value")

    def open(self, url: str) -> None:
        target = self.send("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.send("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.send(f"{domain}.enable")
        self.send("Page.navigate", url=url)

    def console_errors(self) -> list[str]:
        """The page's console errors, uncaught exceptions and error log entries (failed loads)."""
        out = []
        for e in self.events:
            p = e.get("params", {})
            if e.get("method") == "Runtime.consoleAPICalled" and p.get("type") in ("error",
                                                                                   "warning"):
                out.append(" ".join(str(a.get("value", a.get("description", "")))
                                    for a in p.get("args", [])))
            elif e.get("method") == "Runtime.exceptionThrown":
                out.append(json.dumps(p.get("exceptionDetails", {}))[:300])
            elif e.get("method") == "Log.entryAdded" and p["entry"]["level"] in ("error",
                                                                                 "warning"):
                out.append(p["entry"].get("text", ""))
        return [m for m in out if not any(b in m for b in _BENIGN)]

    def close(self) -> None:
        try:
            self.send("Browser.close", session=False)
        except RuntimeError:
            pass
        self.proc.wait(timeout=30)


_VIEWS = """Array.from(document.querySelectorAll('div[id^="screwsym-"]')).map(function (d) {
  var t = d.layout && d.layout.title;
  return {id: d.id, title: t ? (t.text || t) : '',
          objects: d.getAttribute('data-screwsym-objects')};
})"""

_CLIP = """(function (id) {
  var d = document.getElementById(id);
  d.scrollIntoView({block: 'center'});
  var r = d.getBoundingClientRect();
  return {x: r.left + window.scrollX, y: r.top + window.scrollY, width: r.width,
          height: r.height};
})(%s)"""


def _isolated() -> list[str]:
    unshare = shutil.which("unshare")
    if unshare and subprocess.run([unshare, "-n", "true"], capture_output=True).returncode == 0:
        return [unshare, "-n"]
    return []


def _small_png(data: bytes) -> bytes:
    from PIL import Image

    img = Image.open(io.BytesIO(data)).convert("RGB").quantize(256, method=Image.Quantize.MEDIANCUT)
    out = io.BytesIO()
    img.save(out, format="PNG", optimize=True)
    return out.getvalue()


def shoot(site: Path, exe: str) -> None:
    page = (site / PAGE).resolve()
    if not page.exists():
        sys.exit(f"{page}: no such page (build the site first: python -m sphinx -b html "
                 "notebooks build/docs)")
    isolated = _isolated()
    with tempfile.TemporaryDirectory() as tmp:
        b = Browser(exe, Path(tmp) / "profile", isolated)
        try:
            b.open(page.as_uri())
            deadline = time.monotonic() + 240
            while True:                      # every view of the page drawn
                views = b.evaluate(_VIEWS) if b.evaluate("document.readyState") == "complete" \
                    else []
                if views and all(v["objects"] is not None for v in views):
                    break
                if time.monotonic() > deadline:
                    sys.exit(f"{PAGE}: not every view drew within 240 s: {views}")
                time.sleep(1)
            time.sleep(2)
            for name, title in WANTED:
                found = [v for v in views if str(v["title"]).startswith(title)]
                if len(found) != 1:
                    sys.exit(f"{PAGE}: {len(found)} views titled {title!r}: "
                             f"{[v['title'] for v in views]}")
                v = found[0]
                if int(v["objects"]) <= 0:
                    sys.exit(f"{PAGE}: the view {title!r} drew no WebGL object")
                clip = b.evaluate(_CLIP % json.dumps(v["id"]))
                time.sleep(1.5)              # the scrolled-to scene repaints
                shot = b.send("Page.captureScreenshot", format="png",
                              clip={**clip, "scale": 1}, captureBeyondViewport=False)
                png = OUT / f"{name}.png"
                png.write_bytes(_small_png(base64.b64decode(shot["data"])))
                print(f"{png.relative_to(OUT.parents[2])}: {v['title']!r}, {v['objects']} WebGL "
                      f"objects, {int(clip['width'])}x{int(clip['height'])} px")
            errors = b.console_errors()
            if errors:
                sys.exit(f"{PAGE}: console errors: {errors}")
            print(f"{len(views)} views on the page, all drawn; no console error; network "
                  f"{'off (unshare -n)' if isolated else 'unresolvable (no unshare -n)'}")
        finally:
            b.close()


def main() -> None:
    if len(sys.argv) != 2:
        sys.exit(f"usage: python {sys.argv[0]} BUILT_SITE_DIR (e.g. build/docs)")
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if exe is None:
        sys.exit("no chromium on the PATH (Debian: apt-get install chromium)")
    OUT.mkdir(exist_ok=True)
    shoot(Path(sys.argv[1]), exe)


if __name__ == "__main__":
    main()
