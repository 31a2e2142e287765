r"""Printing in the book's notation ``(S; S^0)``: LaTeX, Unicode and plain text.

Every screw prints as its six coordinates in ray order, the two parts
separated by a semicolon, as the book writes ``(1 1 0; 1 0 0)``.  Components
go through the active printer, so user settings (``order``, symbol names,
``mat_str``...) reach them.

A result that holds algebraic numbers (``CRootOf``, the root of a polynomial)
prints each with a variable that is none of the user's (:func:`result_str`,
:func:`result_latex`): SymPy prints ``CRootOf(x**3 - x - 1, 0)`` with the
variable the polynomial was made in, often the name of a coordinate of the
user's own (``x``), which reads as a condition on that coordinate.  SymPy's
``CRootOf`` compares equal whatever its variable is called (and is cached), so
the variable cannot be replaced in the expression: the printers rename it.
"""

from __future__ import annotations

from functools import lru_cache
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from sympy import Basic
    from sympy.printing.pretty.stringpict import prettyForm
    from sympy.printing.printer import Printer

__all__ = ["init_printing", "latex_screw", "pretty_screw", "result_str", "result_latex"]


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


def _fresh(expr: Any, base: str) -> Any:
    """A symbol named ``base`` (``base1``, ``base2``... if taken) that is none of ``expr``'s."""
    from sympy import Symbol

    taken = {str(a) for a in getattr(expr, "free_symbols", ())}
    name, k = base, 0
    while name in taken:
        k += 1
        name = f"{base}{k}"
    return Symbol(name)


@lru_cache(maxsize=1)
def _root_printers() -> tuple[type, type]:
    """SymPy's string and LaTeX printers, each printing a ``CRootOf`` in a variable of its own."""
    from sympy.printing.latex import LatexPrinter
    from sympy.printing.str import StrPrinter

    class RootStrPrinter(StrPrinter):
        def _print_ComplexRootOf(self, expr: Any) -> str:
            poly = expr.expr.xreplace({expr.poly.gen: self._settings["root_variable"]})
            return f"CRootOf({self._print_Add(poly, order='lex')}, {expr.index})"

    class RootLatexPrinter(LatexPrinter):
        def _print_ComplexRootOf(self, expr: Any) -> str:
            poly = expr.expr.xreplace({expr.poly.gen: self._settings["root_variable"]})
            return rf"\operatorname{{CRootOf}} {{\left({self._print(poly)}, {expr.index}\right)}}"

    RootStrPrinter._default_settings = {**StrPrinter._default_settings, "root_variable": None}
    RootLatexPrinter._default_settings = {**LatexPrinter._default_settings, "root_variable": None}
    return RootStrPrinter, RootLatexPrinter


def result_str(expr: Any) -> str:
    """``sstr(expr)`` with each ``CRootOf`` written in the variable ``_t``, none of ``expr``'s.

    >>> from sympy import CRootOf, Eq, symbols
    >>> x = symbols("x", real=True)
    >>> r = CRootOf(x**3 - x - 1, 0)
    >>> result_str(Eq(x, r))
    'Eq(x, CRootOf(_t**3 - _t - 1, 0))'
    >>> str(Eq(x, r))          # SymPy's own: the root reads as if it were about x
    'Eq(x, CRootOf(x**3 - x - 1, 0))'
    """
    return _root_printers()[0]({"root_variable": _fresh(expr, "_t")}).doprint(expr)


def result_latex(expr: Any) -> str:
    r"""``latex(expr)`` with each ``CRootOf`` written in the variable ``\tau``, none of ``expr``'s.

    >>> from sympy import CRootOf, symbols
    >>> x = symbols("x", real=True)
    >>> print(result_latex(x - CRootOf(x**3 - x - 1, 0)))
    x - \operatorname{CRootOf} {\left(\tau^{3} - \tau - 1, 0\right)}
    """
    return _root_printers()[1]({"root_variable": _fresh(expr, "tau")}).doprint(expr)


def init_printing(**settings: Any) -> None:
    """Turn on SymPy's rich printing, so screws render in the book's notation.

    A thin wrapper around :func:`sympy.init_printing` (same settings); in
    Jupyter every screwsym object, also inside lists and tuples, then shows
    as LaTeX through SymPy's own printer protocol (each class's ``_latex``).
    """
    from sympy import init_printing as sympy_init_printing

    sympy_init_printing(**settings)
