"""The teaching notebooks run top to bottom from a clean kernel, so a broken one fails CI.

Each notebook in ``notebooks/`` is executed with nbclient in a fresh kernel
started from the interpreter running the tests (a temporary ``python3``
kernelspec pointing at ``sys.executable``), drawing with matplotlib's inline
backend as Jupyter does, and must show its maths and every figure it draws.
Where ``SCREWSYM_SITE`` names a built site (CI builds it first), the notebooks
that build executed (it fails on any error) are read instead of running them a
second time.  The notebooks are stored without outputs; that is checked too.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import pytest
from _site import figure_outputs, notebook_paths

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")
pytest.importorskip("matplotlib")

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"
PATHS = notebook_paths(NOTEBOOKS)


@pytest.fixture(scope="module")
def kernel_env(tmp_path_factory, monkeypatch_module):
    """A ``python3`` kernelspec for this interpreter, first on the Jupyter path."""
    root = tmp_path_factory.mktemp("jupyter")
    spec_dir = root / "kernels" / "python3"
    spec_dir.mkdir(parents=True)
    spec = {
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python 3 (screwsym tests)",
        "language": "python",
    }
    (spec_dir / "kernel.json").write_text(json.dumps(spec))
    monkeypatch_module.setenv("JUPYTER_PATH", str(root))
    # as in Jupyter: each figure a cell draws becomes an image output (Agg would show none)
    monkeypatch_module.setenv("MPLBACKEND", "module://matplotlib_inline.backend_inline")
    monkeypatch_module.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    return root


@pytest.fixture(scope="module")
def monkeypatch_module():
    mp = pytest.MonkeyPatch()
    yield mp
    mp.undo()


def test_the_notebooks_are_there():
    numbers = [p.name[:2] for p in PATHS]
    assert numbers == ["01", "02", "03", "04", "05", "06", "07", "08", "09", "11"], numbers


@pytest.mark.parametrize("path", PATHS, ids=[p.stem for p in PATHS])
def test_notebook_is_stored_without_outputs(path):
    nb = nbformat.read(path, as_version=4)
    for cell in nb.cells:
        if cell.cell_type == "code":
            assert cell.outputs == [] and cell.execution_count is None, (
                f"{path.name}: clear the outputs before committing "
                "(jupyter nbconvert --clear-output --inplace)"
            )


def _executed(path, kernel_env):
    site = os.environ.get("SCREWSYM_SITE")
    if site:
        return nbformat.read(Path(site).resolve().parent / "jupyter_execute" / path.name,
                             as_version=4)
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(
        nb,
        kernel_name="python3",
        timeout=120,
        resources={"metadata": {"path": str(NOTEBOOKS)}},
    )
    client.execute()  # raises CellExecutionError, with the failing cell, on any error
    return nb


@pytest.mark.slow
@pytest.mark.parametrize("path", PATHS, ids=[p.stem for p in PATHS])
def test_notebook_runs(path, kernel_env):
    nb = _executed(path, kernel_env)
    # the notebook teaches with pictures and formulas: it must have shown them
    kinds = {k for c in nb.cells if c.cell_type == "code" for o in c.outputs
             for k in o.get("data", {})}
    assert "text/latex" in kinds or "text/markdown" in kinds, f"{path.name} displayed no math"
    drawn, findings = figure_outputs(nb)
    assert findings == [], f"{path.name}: {findings}"
    assert drawn >= 1, f"{path.name} shows no figure"


def test_readme_figure_script_draws_the_cylindroid(tmp_path):
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_readme_figure",
                                                  NOTEBOOKS / "make_readme_figure.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = module.main(tmp_path / "cylindroid.png")
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (NOTEBOOKS / "figures" / "cylindroid.png").exists()
