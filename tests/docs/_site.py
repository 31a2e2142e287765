"""Checks of a built documentation site, as plain functions over its files.

Each check returns a list of findings (empty: the page passes), so that
``test_site.py`` can show it failing on a page made wrong on purpose as well as
passing on the real site.  Nothing here imports screwsym or Sphinx.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path

HERE = Path(__file__).resolve().parent

#: a cell that draws: matplotlib's pyplot, or a figure function of screwsym.plot
DRAWS = re.compile(r"\bplt\.(show|subplots|figure)\b|\bplot\.\w+\(|\bfigures?\.\w+\(")

_ABSOLUTE = re.compile(r"^\s*(https?:)?//", re.IGNORECASE)
_SKIP_TEXT = {"pre", "code", "script", "style", "textarea"}


class _Page(HTMLParser):
    """One pass over a page: its math, its visible prose, its images and its resources."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.math: list[tuple[str, bool]] = []  # (TeX, display)
        self.prose: list[str] = []
        self.images: list[str] = []
        self.resources: list[str] = []  # script src, stylesheet href, image src
        self._stack: list[tuple[str, bool, bool]] = []  # (tag, is_math, skip_text)
        self._math_text: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = {k: (v or "") for k, v in attrs}
        if tag == "script" and a.get("src"):
            self.resources.append(a["src"])
        if tag == "link" and a.get("href") and a.get("rel", "") in ("stylesheet", "preload",
                                                                      "modulepreload"):
            self.resources.append(a["href"])
        if tag == "img":
            self.images.append(a.get("src", ""))
            self.resources.append(a.get("src", ""))
        if tag in ("img", "link", "meta", "br", "hr", "input"):  # void elements
            return
        classes = a.get("class", "").split()
        is_math = "math" in classes and self._math_text is None
        if is_math:
            self._math_text = []
        skip = tag in _SKIP_TEXT or any(s for _, _, s in self._stack[-1:])
        self._stack.append((tag, is_math, skip))

    def handle_endtag(self, tag: str) -> None:
        while self._stack:
            t, is_math, _ = self._stack.pop()
            if is_math and self._math_text is not None:
                tex = "".join(self._math_text).strip()
                self._math_text = None
                self.math.append(_strip_delimiters(tex))
            if t == tag:
                break

    def handle_data(self, data: str) -> None:
        if self._math_text is not None:
            self._math_text.append(data)
        elif not (self._stack and self._stack[-1][2]):
            self.prose.append(data)


def _strip_delimiters(tex: str) -> tuple[str, bool]:
    for left, right, display in (("\\[", "\\]", True), ("$$", "$$", True),
                                 ("\\(", "\\)", False), ("$", "$", False)):
        if tex.startswith(left) and tex.endswith(right) and len(tex) >= len(left) + len(right):
            return tex[len(left):len(tex) - len(right)].strip(), display
    return tex, True


def read_page(html: str) -> _Page:
    page = _Page()
    page.feed(html)
    page.close()
    return page


def raw_markdown(html: str) -> list[str]:
    """Markdown that was not rendered: a table's rule row or maths still between dollars."""
    found = []
    for line in "".join(read_page(html).prose).splitlines():
        if re.search(r"\|\s*:?-{3,}:?\s*\|", line):
            found.append(f"raw Markdown table: {line.strip()[:80]!r}")
        if re.search(r"\$\$|\$[^$\n]*\\[A-Za-z]+[^$\n]*\$|\$[^$\s]{1,40}\$", line):
            found.append(f"raw maths between dollars: {line.strip()[:80]!r}")
        if re.search(r"\\(vert|frac|mathbf|times|cdot|alpha|theta|omega|sqrt)\b", line):
            found.append(f"a TeX command outside the maths: {line.strip()[:80]!r}")
    return found


def empty_headers(html: str) -> list[str]:
    """Table headers with an empty cell: a reader sees a column, or a whole row, with no name."""
    found = []
    for head in re.findall(r"<thead>(.*?)</thead>", html, re.S):
        cells = [re.sub(r"<[^>]+>", "", c).strip()
                 for c in re.findall(r"<th\b[^>]*>(.*?)</th>", head, re.S)]
        if any(not c for c in cells):
            found.append(f"a table header with an empty cell: {cells}")
    return found


def network_resources(html: str) -> list[str]:
    """Scripts, stylesheets and images a page would load from the network."""
    return [f"loads {src!r} from the network" for src in read_page(html).resources
            if _ABSOLUTE.match(src)]


def css_network_imports(css: str) -> list[str]:
    return [f"imports {m!r} from the network"
            for m in re.findall(r"@import\s+(?:url\()?\s*['\"]?([^'\")\s;]+)", css)
            if _ABSOLUTE.match(m)]


def notebook_paths(folder: Path) -> list[Path]:
    """The teaching notebooks of a folder: ``NN-name.ipynb``, without the copies that
    ``jupyter nbconvert --execute`` leaves beside them (``NN-name.nbconvert.ipynb``)."""
    return sorted(p for p in folder.glob("[0-9][0-9]-*.ipynb")
                  if not p.name.endswith(".nbconvert.ipynb"))


def figure_outputs(notebook: dict) -> tuple[int, list[str]]:
    """(figures shown, findings) of an executed notebook.

    A figure is an ``image/png`` output that is not a formula (SymPy's printing
    gives a formula both as LaTeX and as a PNG).  A cell that draws must show a
    figure; a figure's text form (``<Figure size ...>``) alone means the kernel
    drew it with a non-interactive backend and nothing reached the page.
    """
    shown = 0
    findings = []
    for i, cell in enumerate(notebook.get("cells", [])):
        if cell.get("cell_type") != "code":
            continue
        source = "".join(cell.get("source", ""))
        n = 0
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            if "image/png" in data and "text/latex" not in data:
                n += 1
            elif "".join(data.get("text/plain", "")).startswith("<Figure size"):
                findings.append(f"cell {i}: a figure printed as text, not drawn")
        if DRAWS.search(source) and n == 0:
            findings.append(f"cell {i} draws but shows no figure")
        shown += n
    return shown, findings


def page_figures(html: str) -> int:
    """Images of a notebook page that are its figures (the outputs myst-nb wrote)."""
    return sum(1 for src in read_page(html).images if "_images/" in src)


def mathjax_errors(fragments: list[tuple[str, bool]], mathjax: Path) -> list[str]:
    """Typeset every fragment with the site's own MathJax (under Node.js); the errors.

    Raises ``FileNotFoundError`` when Node.js is not installed.
    """
    node = shutil.which("node")
    if node is None:
        raise FileNotFoundError("node")
    result = subprocess.run(
        [node, str(HERE / "mathjax_check.js"), str(mathjax)],
        input=json.dumps([[t, d] for t, d in fragments]),
        capture_output=True, text=True, timeout=600, check=False,
    )
    if result.returncode != 0:
        raise RuntimeError(f"mathjax_check.js failed: {result.stderr[-2000:]}")
    return json.loads(result.stdout)


#: a 3-D view's output on a page (plotly's to_html), and plotly.js's own banner
_PLOTLY_CALL = "Plotly.newPlot("
_PLOTLY_BANNER = re.compile(r"\*\s*plotly\.js v\d")
_SHARED_PLOTLY = re.compile(r"^_static/plotly-\d+\.\d+\.\d+\.min\.js(\?v=[0-9a-f]+)?$")


def shared_plotlyjs(html: str, most: int = 5_000_000) -> list[str]:
    """A page with 3-D views loads plotly.js once from the site's ``_static`` (shared by every
    page, cached by the browser) and embeds no copy of it; it weighs under ``most`` bytes.  A
    page without a view loads no plotly.js.  The findings."""
    scripts = [s for s in read_page(html).resources if "plotly" in s.lower()]
    shared = [s for s in scripts if _SHARED_PLOTLY.match(s)]
    findings = [f"plotly.js loaded from elsewhere: {s}" for s in scripts if s not in shared]
    embedded = len(_PLOTLY_BANNER.findall(html))
    if _PLOTLY_CALL not in html:
        return findings + [f"no view, yet loads {s}" for s in shared]
    if len(shared) != 1:
        findings.append(f"views, and {len(shared)} plotly.js from _static (expected 1)")
    if embedded:
        findings.append(f"{embedded} copies of plotly.js embedded in the page")
    if len(html.encode("utf-8")) > most:
        findings.append(f"{len(html.encode('utf-8')) / 1e6:.1f} MB, over {most / 1e6:.1f} MB")
    return findings
