"""Display in Jupyter: every screwsym object in the book's notation, also inside containers.

The IPython display formatter is driven directly (no kernel): this is what a
notebook cell shows for its last expression after ``screwsym.init_printing()``.
"""

from __future__ import annotations

import pytest
from sympy import Rational, latex, sqrt, symbols

import screwsym
from screwsym import LineVector, Screw, Twist, Wrench, common_normal

IPython = pytest.importorskip("IPython")

h = symbols("h", real=True)
w = symbols("omega", real=True)

BOOK_1_4 = r"\left(1 \quad 1 \quad 0;\; 1 \quad 0 \quad 0\right)"  # Example 1.4
AXIS_1_4 = r"\left(1 \quad 1 \quad 0;\; \frac{1}{2} \quad - \frac{1}{2} \quad 0\right)"
COUPLE_1_4 = r"\left(0 \quad 0 \quad 0;\; \frac{1}{2} \quad \frac{1}{2} \quad 0\right)"


@pytest.fixture(scope="module")
def shell():
    from IPython.core.interactiveshell import InteractiveShell

    ip = InteractiveShell.instance()
    screwsym.init_printing(ip=ip)
    return ip


def shown(shell, obj) -> dict:
    data, _ = shell.display_formatter.format(obj)
    return data


@pytest.mark.parametrize(
    ("obj", "expected"),
    [
        (Screw([1, 1, 0], [1, 0, 0]), BOOK_1_4),
        (Screw([1, 1, 0], [1, 0, 0]).axis, AXIS_1_4),
        (LineVector.from_axis([0, 0, 1], [1, 0, 0]),
         r"\left(1 \quad 0 \quad 0;\; 0 \quad 1 \quad 0\right)"),
        (Twist.from_axis([0, 0, 0], [0, 0, 1], h, magnitude=w),
         r"\left(0 \quad 0 \quad \omega;\; 0 \quad 0 \quad h \omega\right)"),
        (Wrench.force([0, 0, -10], point=[1, 0, 0]),
         r"\left(0 \quad 0 \quad -10;\; 0 \quad 10 \quad 0\right)"),
        (Screw.couple([0, 0, 1]), r"\left(0 \quad 0 \quad 0;\; 0 \quad 0 \quad 1\right)"),
        (Screw([1, 0, 0], [sqrt(2), 0, 0]),
         r"\left(1 \quad 0 \quad 0;\; \sqrt{2} \quad 0 \quad 0\right)"),
    ],
)
def test_each_object_shows_in_book_notation(shell, obj, expected):
    assert latex(obj) == expected
    assert shown(shell, obj)["text/latex"] == rf"$\displaystyle {expected}$"


def test_plain_text_under_init_printing_is_the_book_form(shell):
    assert shown(shell, Screw([1, 1, 0], [1, 0, 0]))["text/plain"] == "(1  1  0; 1  0  0)"
    assert shown(shell, Twist.translation([1, 2, 3]))["text/plain"] == "(0  0  0; 1  2  3)"


def test_lists_and_tuples_of_screws(shell):
    s = Screw([1, 1, 0], [1, 0, 0])
    assert shown(shell, [s, s.axis])["text/latex"] == (
        rf"$\displaystyle \left[ {BOOK_1_4}, \  {AXIS_1_4}\right]$"
    )
    # decompose returns a tuple: the axis line vector and the parallel couple (1.37)
    assert shown(shell, s.decompose())["text/latex"] == (
        rf"$\displaystyle \left( {AXIS_1_4}, \  {COUPLE_1_4}\right)$"
    )
    # mixed with scalars, as a notebook cell "s, s.pitch" shows
    assert shown(shell, (s, s.pitch))["text/latex"] == (
        rf"$\displaystyle \left( {BOOK_1_4}, \  \frac{{1}}{{2}}\right)$"
    )
    # nested
    assert shown(shell, [[s], (Rational(1, 2),)])["text/latex"] == (
        rf"$\displaystyle \left[ \left[ {BOOK_1_4}\right], \  \left( \frac{{1}}{{2}},\right)\right]$"
    )


def test_symbols_keep_their_latex_names(shell):
    a12 = symbols("a_12", positive=True)
    L = LineVector.from_axis([0, 0, a12], [1, 0, 0])
    assert shown(shell, L)["text/latex"] == (
        r"$\displaystyle \left(1 \quad 0 \quad 0;\; 0 \quad a_{12} \quad 0\right)$"
    )


def test_common_normal_result_shows_as_latex(shell):
    L1 = LineVector.from_axis([0, 0, 0], [1, 0, 0])
    L2 = LineVector.from_axis([0, 0, 2], [0, 1, 0])
    assert "text/latex" in shown(shell, common_normal(L1, L2))


def test_registry_entry_shows_as_its_numbered_equation(shell):
    try:
        from screwsym.book import entry
    except ImportError:  # pragma: no cover - the registry is built in another issue
        pytest.skip("screwsym.book is not available")
    e = entry("1.34")
    text = shown(shell, e)["text/latex"]
    assert text.startswith("$$") and text.endswith("$$")
    assert r"\tag{1.34}" in text
