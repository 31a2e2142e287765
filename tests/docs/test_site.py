"""The built documentation site shows what the notebooks show, with no network.

The site is the one ``SCREWSYM_SITE`` names (a folder built with
``python -m sphinx -W -b html notebooks DIR``; CI builds it once and points
here), or else built here into a temporary folder (slow: every notebook is
executed).  myst-nb keeps the executed notebooks beside the site, in
``DIR/../jupyter_execute``; the figures each one drew are counted there.

Checked on every page: no Markdown left raw (tables, maths between dollars),
no script, stylesheet or image from the network, every formula typeset by the
site's own MathJax without an error (under Node.js), and on a notebook's page
as many figures as the notebook drew, every drawing cell having drawn one.  Each
check is first shown to reject a page made wrong on purpose.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import _site
import pytest

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = _site.notebook_paths(ROOT / "notebooks")


# --- each check rejects a wrong page (cheap: the default run) ---------------------------

def test_raw_markdown_is_found_outside_code():
    assert _site.raw_markdown("<p>| a | b |</p><p>|---|---|</p>")
    assert _site.raw_markdown("<p>the pitch $h = \\frac{1}{2}$ here</p>")
    assert _site.raw_markdown("<p>$$x$$</p>")
    assert _site.raw_markdown("<td>the distance \\vert AB\\vert</td>")
    assert not _site.raw_markdown('<pre>rows = ["|---|---|", "$x$"]</pre>')
    assert not _site.raw_markdown('<table><tr><td>a</td></tr></table><p>costs $5 or more</p>')
    assert not _site.raw_markdown('<span class="math">\\(h = 1\\)</span>')


def test_empty_table_headers_are_found():
    assert _site.empty_headers("<table><thead><tr><th><p></p></th><th>b</th></tr></thead></table>")
    assert _site.empty_headers("<thead><tr><th class='head'> </th><th></th></tr></thead>")
    assert not _site.empty_headers("<table><thead><tr><th><p>a</p></th><th>b</th></tr></thead>"
                                   "<tbody><tr><td></td></tr></tbody></table>")


def test_network_resources_are_found():
    bad = ('<script src="https://cdn.jsdelivr.net/npm/mathjax@3/es5/tex-chtml.js"></script>'
           '<link rel="stylesheet" href="//fonts.example.org/a.css"><img src="http://x/y.png">')
    assert len(_site.network_resources(bad)) == 3
    good = ('<script src="_static/mathjax/tex-chtml.js"></script>'
            '<link rel="stylesheet" href="_static/alabaster.css">'
            '<a href="https://github.com/">a link is not a load</a>')
    assert _site.network_resources(good) == []
    assert _site.css_network_imports('@import url("https://fonts.example.org/x.css");')
    assert not _site.css_network_imports('@import url("basic.css");')


def test_missing_figures_are_found():
    draws = {"cell_type": "code", "source": "fig, ax = plt.subplots()\nplt.show()"}
    as_text = {"output_type": "execute_result", "data": {"text/plain": "<Figure size 500x350>"}}
    png = {"output_type": "display_data", "data": {"image/png": "iVBOR", "text/plain": "<F>"}}
    formula = {"output_type": "execute_result",
               "data": {"image/png": "iVBOR", "text/latex": "$x$", "text/plain": "x"}}
    assert _site.figure_outputs({"cells": [dict(draws, outputs=[png])]}) == (1, [])
    n, findings = _site.figure_outputs({"cells": [dict(draws, outputs=[])]})
    assert n == 0 and "draws but shows no figure" in findings[0]
    n, findings = _site.figure_outputs({"cells": [dict(draws, outputs=[as_text])]})
    assert n == 0 and any("printed as text" in f for f in findings)
    # a formula's PNG is not a figure
    assert _site.figure_outputs({"cells": [{"cell_type": "code", "source": "x",
                                            "outputs": [formula]}]}) == (0, [])
    page = '<img src="_images/a.png"><img src="_static/logo.png">'
    assert _site.page_figures(page) == 1


def test_views_without_the_shared_plotlyjs_are_found():
    view = '<div id="v"></div><script>Plotly.newPlot("v", [], {})</script>'
    shared = '<script src="_static/plotly-4.1.1.min.js?v=ab5aad05"></script>'
    assert _site.shared_plotlyjs(f"<html><head>{shared}</head><body>{view}</body></html>") == []
    assert _site.shared_plotlyjs("<p>no view</p>") == []
    assert _site.shared_plotlyjs(f"<html><body>{view}</body></html>") != []          # none
    assert _site.shared_plotlyjs(f"{shared}{shared}{view}") != []                     # twice
    assert _site.shared_plotlyjs(f"{shared}{shared}<p>no view</p>") != []
    cdn = '<script src="https://cdn.plot.ly/plotly-2.35.2.min.js"></script>'
    assert _site.shared_plotlyjs(f"{cdn}{view}") != []
    embedded = "<script>/**\n* plotly.js v4.1.1\n*/ (function(){})()</script>"
    assert _site.shared_plotlyjs(f"{shared}{embedded}{view}") != []
    assert _site.shared_plotlyjs(f"{shared}{view}" + "x" * 2000, most=1000) != []    # heavy


def test_nbconvert_copies_are_not_notebooks(tmp_path):
    for name in ("01-a.ipynb", "01-a.nbconvert.ipynb", "conf.py", "02-b.ipynb"):
        (tmp_path / name).write_text("{}")
    assert [p.name for p in _site.notebook_paths(tmp_path)] == ["01-a.ipynb", "02-b.ipynb"]


def test_every_notebook_has_its_picture_in_the_gallery():
    gallery = ROOT / "notebooks" / "figures" / "gallery"
    for path in NOTEBOOKS:
        thumb = gallery / f"{path.stem}.png"
        assert thumb.exists(), f"no gallery picture for {path.name}: run notebooks/make_gallery.py"
        assert thumb.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "{screwsym-gallery}" in (ROOT / "notebooks" / "index.md").read_text(encoding="utf-8")


def test_math_is_extracted_with_its_display_mode():
    page = _site.read_page('<div class="math notranslate">\\[ a \\tag{1} \\]</div>'
                           '<p>text <span class="math">\\(b\\)</span></p>')
    assert page.math == [("a \\tag{1}", True), ("b", False)]


@pytest.fixture(scope="module")
def mathjax_dir():
    try:
        import importlib.util

        spec = importlib.util.find_spec("sphinx-mathjax-offline")
    except (ImportError, ValueError):
        spec = None
    if spec is None or spec.origin is None:
        pytest.skip("the docs extra (sphinx-mathjax-offline, which bundles MathJax) is not "
                    "installed: pip install -e \".[docs]\"")
    if shutil.which("node") is None:
        pytest.skip("Node.js is not installed: MathJax is run under Node.js to check the maths")
    return Path(spec.origin).parent / "static" / "mathjax"


def test_mathjax_errors_are_found(mathjax_dir):
    errors = _site.mathjax_errors(
        [("a \\tag{1} \\qquad b \\tag{2}", True), ("\\frac{1}{", True),
         ("(\\boldsymbol\\omega;\\ \\mathbf v_O)", False), ("x^2 \\tag{1.4}", True)],
        mathjax_dir)
    assert len(errors) == 2, errors
    assert errors[0].startswith("Multiple \\tag") and "Missing close brace" in errors[1]


# --- the real site (slow: it is built, or CI's build is read) ----------------------------

@pytest.fixture(scope="module")
def site(tmp_path_factory):
    given = os.environ.get("SCREWSYM_SITE")
    if given:
        out = Path(given).resolve()
        if not (out / "index.html").exists():
            pytest.fail(f"SCREWSYM_SITE={given} holds no built site (no index.html)")
        return out
    pytest.importorskip("sphinx", reason="the docs extra is not installed: "
                        "pip install -e \".[docs]\"")
    pytest.importorskip("myst_nb", reason="the docs extra is not installed")
    out = tmp_path_factory.mktemp("site") / "html"
    env = dict(os.environ)
    env.pop("MPLBACKEND", None)  # the notebooks' kernels draw with their own inline backend
    subprocess.run([sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html",
                    str(ROOT / "notebooks"), str(out)], check=True, env=env, cwd=ROOT)
    return out


@pytest.fixture(scope="module")
def pages(site):
    return {p.name: p.read_text(encoding="utf-8") for p in sorted(site.glob("*.html"))}


@pytest.mark.slow
def test_every_notebook_is_a_page_with_every_figure_it_drew(site, pages):
    executed = site.parent / "jupyter_execute"
    assert NOTEBOOKS
    for path in NOTEBOOKS:
        nb = json.loads((executed / path.name).read_text(encoding="utf-8"))
        drawn, findings = _site.figure_outputs(nb)
        assert findings == [], f"{path.name}: {findings}"
        shown = _site.page_figures(pages[path.stem + ".html"])
        assert shown == drawn, f"{path.stem}.html shows {shown} of the {drawn} figures drawn"


@pytest.mark.slow
def test_no_page_leaves_markdown_raw(pages):
    found = {name: f for name, html in pages.items() if (f := _site.raw_markdown(html))}
    assert found == {}


@pytest.mark.slow
def test_no_table_has_an_empty_header(pages):
    found = {name: f for name, html in pages.items() if (f := _site.empty_headers(html))}
    assert found == {}


@pytest.mark.slow
def test_nothing_is_loaded_from_the_network(site, pages):
    found = {name: f for name, html in pages.items() if (f := _site.network_resources(html))}
    for css in (site / "_static").glob("*.css"):
        if f := _site.css_network_imports(css.read_text(encoding="utf-8")):
            found[css.name] = f
    assert found == {}
    # the MathJax every page loads is in the site itself
    assert (site / "_static" / "mathjax" / "tex-chtml.js").exists()
    assert all('src="_static/mathjax/tex-chtml.js"' in html
               for name, html in pages.items() if 'class="math' in html)


@pytest.mark.slow
def test_every_formula_typesets_without_a_mathjax_error(site, pages):
    if shutil.which("node") is None:
        pytest.skip("Node.js is not installed: MathJax is run under Node.js to check the maths")
    fragments = [m for html in pages.values() for m in _site.read_page(html).math]
    assert len(fragments) > 300  # the notebooks, the book page and the API reference
    assert _site.mathjax_errors(fragments, site / "_static" / "mathjax") == []


@pytest.mark.slow
def test_formula_outputs_are_mathjax_not_pictures(site, pages):
    executed = site.parent / "jupyter_execute"
    for path in NOTEBOOKS:
        nb = json.loads((executed / path.name).read_text(encoding="utf-8"))
        formulas = sum(1 for c in nb["cells"] if c["cell_type"] == "code"
                       for o in c.get("outputs", []) if "text/latex" in o.get("data", {}))
        html = pages[path.stem + ".html"]
        # every formula output is a MathJax block of the page, none an image
        assert html.count('class="math notranslate nohighlight"') >= formulas, path.name


@pytest.mark.slow
def test_views_load_the_sites_own_plotlyjs_once(site, pages):
    found = {name: f for name, html in pages.items() if (f := _site.shared_plotlyjs(html))}
    assert found == {}
    with_views = [name for name, html in pages.items() if "Plotly.newPlot(" in html]
    assert "13-mechanisms-in-3d.html" in with_views
    # the file in _static is plotly's own, from the installed package (no CDN)
    offline = pytest.importorskip("plotly.offline")
    shipped = site / "_static" / f"plotly-{offline.get_plotlyjs_version()}.min.js"
    assert shipped.read_text(encoding="utf-8") == offline.get_plotlyjs()
