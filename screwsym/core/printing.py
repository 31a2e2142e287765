r"""Printing in the book's notation ``(S; S^0)``: LaTeX, Unicode and plain text.

Every screw prints as its six coordinates in ray order, the two parts
separated by a semicolon, as the book writes ``(1 1 0; 1 0 0)``.  Components
go through the active printer, so user settings (``order``, symbol names,
``mat_str``...) reach them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from sympy import Basic
    from sympy.printing.pretty.stringpict import prettyForm
    from sympy.printing.printer import Printer

__all__ = ["init_printing", "latex_screw", "pretty_screw"]


# ``s`` is a screw (screwsym.core.screw.Screw, which imports this module): a Basic whose
# args are its two parts
def latex_screw(s: Basic, printer: Printer) -> str:
    r"""LaTeX for a screw: ``\left(l \quad m \quad n;\; p \quad q \quad r\right)``.

    >>> from sympy import latex, symbols
    >>> from screwsym import Screw
    >>> h = symbols("h", real=True)
    >>> print(latex(Screw([1, 0, 0], [h, 0, 0])))
    \left(1 \quad 0 \quad 0;\; h \quad 0 \quad 0\right)
    """
    S, S0 = (r" \quad ".join(printer._print(e) for e in part) for part in s.args)
    return rf"\left({S};\; {S0}\right)"


def pretty_screw(s: Basic, printer: Printer) -> prettyForm:
    """Unicode/ASCII pretty form: ``(1  0  0; h  0  0)``.

    >>> from sympy import pretty, symbols
    >>> from screwsym import Screw
    >>> print(pretty(Screw([1, 0, 0], [symbols("h", real=True), 0, 0])))
    (1  0  0; h  0  0)
    """
    from sympy.printing.pretty.stringpict import prettyForm

    pieces: list[prettyForm] = []
    for i, part in enumerate(s.args):
        for j, e in enumerate(part):
            if pieces:
                pieces.append(prettyForm("; " if (i, j) == (1, 0) else "  "))
            pieces.append(printer._print(e))
    form = pieces[0]
    for p in pieces[1:]:
        form = prettyForm(*form.right(p))
    return prettyForm(*form.parens())


def init_printing(**settings: Any) -> None:
    """Turn on SymPy's rich printing, so screws render in the book's notation.

    A thin wrapper around :func:`sympy.init_printing` (same settings); in
    Jupyter every screwsym object, also inside lists and tuples, then shows
    as LaTeX through SymPy's own printer protocol (each class's ``_latex``).
    """
    from sympy import init_printing as sympy_init_printing

    sympy_init_printing(**settings)
