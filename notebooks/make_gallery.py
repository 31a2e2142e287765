"""Write the landing page's gallery: one thumbnail per notebook, from the site's own build.

Run after building the site (``python -m sphinx -W -b html notebooks build/docs``)::

    python notebooks/make_gallery.py build/jupyter_execute

Each notebook's thumbnail is its first figure (an ``image/png`` output that is
not a formula), scaled to 400 pixels wide, written to
``notebooks/figures/gallery/<notebook>.png``.  The thumbnails are committed, so
that the landing page needs no second build; ``tests/docs/test_site.py`` checks
that every notebook has one.
"""

from __future__ import annotations

import base64
import io
import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "figures" / "gallery"


def first_figure(notebook: dict) -> bytes | None:
    for cell in notebook.get("cells", []):
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            if "image/png" in data and "text/latex" not in data:
                return base64.b64decode(data["image/png"])
    return None


def main(executed: Path) -> list[Path]:
    from PIL import Image  # Pillow comes with matplotlib (the docs extra)

    OUT.mkdir(parents=True, exist_ok=True)
    written = []
    for nb_path in sorted(executed.glob("[0-9][0-9]-*.ipynb")):
        if nb_path.name.endswith(".nbconvert.ipynb"):
            continue
        png = first_figure(json.loads(nb_path.read_text(encoding="utf-8")))
        if png is None:
            raise SystemExit(f"{nb_path.name} draws no figure: the gallery needs one")
        image = Image.open(io.BytesIO(png)).convert("RGB")
        image.thumbnail((400, 400))
        target = OUT / f"{nb_path.stem}.png"
        image.save(target, optimize=True)
        written.append(target)
    return written


if __name__ == "__main__":
    for path in main(Path(sys.argv[1] if len(sys.argv) > 1 else "build/jupyter_execute")):
        print(path)
