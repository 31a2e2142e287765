"""Sphinx configuration of the screwsym documentation.

The source directory is ``notebooks/``: the teaching notebooks are pages of the
site, executed at build time by myst-nb (they are stored without outputs), next
to the API reference from the docstrings, the book registry (generated from
:mod:`screwsym.book` at build time) and the benchmark tables.  Build with

    python -m sphinx -W -b html notebooks build/docs
"""

from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path

from docutils import nodes
from docutils.statemachine import StringList
from sphinx.util.docutils import SphinxDirective

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import screwsym  # noqa: E402

project = "screwsym"
author = "screwsym developers"
copyright = "screwsym developers, BSD-3-Clause"
release = version = screwsym.__version__

extensions = [
    "myst_nb",
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
]
# MathJax bundled into the site (_static/mathjax), so the maths renders with no network: the
# files are those of the sphinx-mathjax-offline package (the docs extra), copied by
# _copy_mathjax below rather than by that package's extension, which does not declare itself
# safe for parallel reading (sphinx -j would warn, and -W fail)
_MATHJAX = Path(importlib.util.find_spec("sphinx-mathjax-offline").origin).parent / "static" / "mathjax"
mathjax_path = "mathjax/tex-chtml.js"
exclude_patterns = ["_build", "figures/*.py", "make_readme_figure.py", "make_gallery.py",
                    "**.ipynb_checkpoints", "**.nbconvert.ipynb"]
source_suffix = {".md": "myst-nb", ".ipynb": "myst-nb"}
myst_enable_extensions = ["dollarmath", "amsmath"]
myst_heading_anchors = 3
html_theme = "alabaster"
html_title = f"screwsym {release}"
html_static_path = ["_static"]
html_css_files = ["screwsym.css"]
html_theme_options = {"page_width": "1100px", "body_max_width": "none"}

# the notebooks are stored without outputs: run every one at build time, fail on an error
nb_execution_mode = "force"
nb_execution_timeout = 300
nb_execution_raise_on_error = True
nb_execution_show_tb = True
nb_merge_streams = True
# a notebook's Markdown outputs (tables with maths) are read as MyST, with the page's extensions
nb_render_markdown_format = "myst"
# a formula output is MathJax, not SymPy's PNG rendering of it (lower number = preferred)
nb_mime_priority_overrides = [("html", "text/latex", 45)]

autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": True}
autodoc_member_order = "bysource"
autodoc_typehints = "description"
napoleon_numpy_docstring = True
napoleon_google_docstring = False
suppress_warnings = ["myst.header"]


def _rst(text: str) -> str:
    """Plain text for reStructuredText: |x|, *, _ and backquotes are not markup here."""
    for ch in ("\\", "|", "*", "_", "`"):
        text = text.replace(ch, "\\" + ch)
    return text


def _plain_formulas(app, what, name, obj, options, lines) -> None:
    """Docstrings write norms as |S1| in plain text; reStructuredText reads |S1| as a
    substitution.  Escape the bars outside doctest blocks, inline literals and math."""
    in_doctest = False
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        if stripped.startswith(">>>"):
            in_doctest = True
        elif not stripped:
            in_doctest = False
        if in_doctest or "|" not in line or "``" in line or ":math:" in line:
            continue
        lines[i] = line.replace("|", "\\|")


def _book_lines() -> list[str]:
    """The registry as reStructuredText: statement, how it is checked, errata, notes."""
    from screwsym.book import entries

    out: list[str] = []
    section = None
    # each section once: the registry lists the worked examples after the equations, so
    # order by section (stable: within a section the registry's order stays)
    by_section = sorted(entries(), key=lambda e: tuple(int(n) for n in e.section.split(".")))
    for e in by_section:
        if e.section.split(".")[:2] != section:
            section = e.section.split(".")[:2]
            title = f"Section {'.'.join(section)}"
            out += [title, "-" * len(title), ""]
        title = _rst(f"({e.id}) {e.title}" if e.id[:1].isdigit() else f"{e.id}: {e.title}")
        out += [title, "~" * len(title), ""]
        out += [f"*{e.kind}*, Section {e.section}", "", ".. math::", ""]
        out += ["   " + line for line in e.statement.splitlines()] + [""]
        out += ["**How it is checked.** " + _rst(e.construction), ""]
        checks = e.construct().checks
        out += ["Checks:", ""]
        for c in checks:
            what = {"zero": "vanishes exactly", "nonzero": "counter-example, shown non-zero",
                    "holds": "predicate is True", "nonnegative": "nonnegative"}[c.kind]
            book = " (the book's wording, shown failing)" if c.book else ""
            out.append(f"- ``{c.label}``: {what}{book}")
        out.append("")
        for label, items in (("Errata", e.errata), ("Notes", e.notes)):
            if items:
                out += [f"**{label}.**", ""]
                out += ["- " + _rst(x) for x in items]
                out.append("")
    return out


class BookRegistry(SphinxDirective):
    """``.. screwsym-book::`` inserts every entry of the registry."""

    def run(self) -> list[nodes.Node]:
        container = nodes.section()
        container.document = self.state.document
        self.state.nested_parse(StringList(_book_lines(), source="screwsym.book"), 0, container,
                                match_titles=True)
        return container.children


def _notebook_title(path: Path) -> str:
    import json

    for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
        if cell["cell_type"] == "markdown":
            for line in "".join(cell["source"]).splitlines():
                if line.startswith("# "):
                    return line[2:].strip()
    return path.stem


class Gallery(SphinxDirective):
    """``.. screwsym-gallery::``: a picture per notebook (``figures/gallery/<notebook>.png``,
    written by ``make_gallery.py`` from the site's build), each linking to its page."""

    def run(self) -> list[nodes.Node]:
        here = Path(self.env.srcdir)
        grid = nodes.container(classes=["screwsym-gallery"])
        for path in sorted(here.glob("[0-9][0-9]-*.ipynb")):
            if path.name.endswith(".nbconvert.ipynb"):  # left by jupyter nbconvert --execute
                continue
            thumb = f"figures/gallery/{path.stem}.png"
            if not (here / thumb).exists():
                raise self.error(f"no gallery picture {thumb}: run notebooks/make_gallery.py")
            # the page of the notebook, as the html builder names it beside index.html
            page = f"{path.stem}.html"
            figure = nodes.figure()
            link = nodes.reference("", "", refuri=page)
            link += nodes.image(uri=thumb, alt=_notebook_title(path))
            figure += link
            caption = nodes.caption()
            caption += nodes.reference(_notebook_title(path), _notebook_title(path), refuri=page)
            figure += caption
            grid += figure
        return [grid]


#: repository files that a page of the site includes: a notebook's link to the file goes there
_INCLUDED = {str(ROOT / "benchmarks" / "README"): "benchmarks"}


def _links_to_included_files(app, doctree) -> None:
    from sphinx.addnodes import pending_xref

    for node in doctree.findall(pending_xref):
        target = node.get("reftarget", "")
        if node.get("reftype") == "myst" and target in _INCLUDED:
            node["reftarget"] = _INCLUDED[target]


def _copy_mathjax(app, exc) -> None:
    from sphinx.util.fileutil import copy_asset

    if exc is None and app.builder.format == "html":
        copy_asset(str(_MATHJAX), os.path.join(app.outdir, "_static", "mathjax"))


# plotly.js once for the whole site: plotly's own plotly.min.js (from the installed plotly
# package, no CDN) copied into the site's _static, and loaded by the pages that show a 3-D view
# (screwsym.plot.view) only, where the browser caches it from one page to the next.  The
# notebooks' kernels inherit SCREWSYM_VIEW_PLOTLYJS=site: a view's output then leaves plotly.js
# out (each would otherwise carry its 4.8 MB) and draws with the page's global Plotly.
# View.to_html stays one self-contained file whatever the variable says.  Set in setup(), when
# Sphinx builds, not on import (a test that reads this file must not change its own process).
#: what a view's output (plotly's to_html) calls on the page
_PLOTLY_CALL = "Plotly.newPlot("


def _plotlyjs_name() -> str | None:
    """``plotly-<plotly.js version>.min.js`` (the name changes with the version: no stale cache),
    or None without plotly (the notebooks that draw a view then fail to run, as they should)."""
    try:
        from plotly.offline import get_plotlyjs_version
    except ImportError:
        return None
    return f"plotly-{get_plotlyjs_version()}.min.js"


def _copy_plotlyjs(app) -> None:
    """Write plotly's own plotly.min.js into the site's _static (before the pages are written,
    so that Sphinx gives its link a checksum)."""
    name = _plotlyjs_name()
    if name is None or app.builder.format != "html":
        return
    from plotly.offline import get_plotlyjs

    static = Path(app.outdir) / "_static"
    static.mkdir(parents=True, exist_ok=True)
    target = static / name
    text = get_plotlyjs()
    if not target.exists() or target.read_text(encoding="utf-8") != text:
        target.write_text(text, encoding="utf-8")


def _plotlyjs_on_pages_with_views(app, pagename, templatename, context, doctree) -> None:
    name = _plotlyjs_name()
    if name is None or _PLOTLY_CALL not in context.get("body", ""):
        return
    # as plotly's own self-contained output does: MathJax stays configured by the page
    app.add_js_file(None, body="window.PlotlyConfig = {MathJaxConfig: 'local'};", priority=300)
    app.add_js_file(name, priority=301)


def setup(app):
    os.environ["SCREWSYM_VIEW_PLOTLYJS"] = "site"
    app.connect("builder-inited", _copy_plotlyjs)
    app.connect("html-page-context", _plotlyjs_on_pages_with_views)
    app.connect("build-finished", _copy_mathjax)
    app.connect("doctree-read", _links_to_included_files)
    app.add_directive("screwsym-book", BookRegistry)
    app.add_directive("screwsym-gallery", Gallery)
    app.connect("autodoc-process-docstring", _plain_formulas)
    return {"parallel_read_safe": True}
