"""Printing in the book's notation (S; S^0)."""

from sympy import Rational, latex, pretty, sqrt, sstr, symbols

import screwsym
from screwsym import LineVector, Screw, Twist, Wrench

h = symbols("h", real=True)
w = symbols("omega", real=True)


def test_latex_uses_semicolon_and_book_order():
    assert (
        latex(Screw([1, 1, 0], [1, 0, 0])) == r"\left(1 \quad 1 \quad 0;\; 1 \quad 0 \quad 0\right)"
    )
    assert (
        latex(Screw([1, 0, 0], [h, 0, 0])) == r"\left(1 \quad 0 \quad 0;\; h \quad 0 \quad 0\right)"
    )
    assert (
        latex(Twist.from_axis([1, 0, 0], [0, 0, 1], magnitude=w))
        == r"\left(0 \quad 0 \quad \omega;\; 0 \quad - \omega \quad 0\right)"
    )
    assert (
        latex(Screw([1, 1, 1], [1, 1, 1]) / sqrt(3))
        == r"\left(\frac{\sqrt{3}}{3} \quad \frac{\sqrt{3}}{3} \quad \frac{\sqrt{3}}{3};\; "
        r"\frac{\sqrt{3}}{3} \quad \frac{\sqrt{3}}{3} \quad \frac{\sqrt{3}}{3}\right)"
    )


def test_repr_latex_for_jupyter():
    assert Screw([1, 0, 0], [0, 0, 0])._repr_latex_() == (
        r"$\displaystyle \left(1 \quad 0 \quad 0;\; 0 \quad 0 \quad 0\right)$"
    )


def test_latex_respects_printer_settings():
    assert latex(Screw([Rational(1, 2), 0, 0], [0, 0, 0]), fold_short_frac=True) == (
        r"\left(1 / 2 \quad 0 \quad 0;\; 0 \quad 0 \quad 0\right)"
    )


def test_str_and_repr_round_trip_names():
    s = LineVector([1, 0, 0], [0, h, 0])
    assert sstr(s) == str(s) == repr(s) == "LineVector([1, 0, 0], [0, h, 0])"
    assert str(Wrench.couple([0, 0, 1])) == "Wrench([0, 0, 0], [0, 0, 1])"


def test_pretty():
    assert pretty(Screw([1, 0, 0], [h, 0, 0])) == "(1  0  0; h  0  0)"
    assert pretty(Screw([1, 0, 0], [h, 0, 0]), use_unicode=False) == "(1  0  0; h  0  0)"
    assert pretty(Screw([Rational(1, 2), 0, 0], [0, 0, 0])) == "(1/2  0  0; 0  0  0)"
    tall = pretty(Screw([sqrt(2) / 2, 0, 0], [0, 0, 0]), use_unicode=True)
    assert tall == "⎛√2               ⎞\n⎜──  0  0; 0  0  0⎟\n⎝2                ⎠"


def test_init_printing_is_sympys(monkeypatch):
    seen = {}

    def fake(**settings):
        seen.update(settings)

    monkeypatch.setattr("sympy.init_printing", fake)
    screwsym.init_printing(use_latex="mathjax")
    assert seen == {"use_latex": "mathjax"}
