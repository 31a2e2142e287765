"""The conds="piecewise" machinery (screwsym.core.conditions); the operations' cases are in
test_tidy.py, test_screw.py and test_line.py."""

from sympy import And, Eq, ImmutableMatrix, Piecewise, false, nan, oo, symbols, true

from screwsym.core.conditions import CONDS, piecewise, vanishes

x, y = symbols("x y", real=True)


def test_conds_are_sympys_words():
    assert CONDS == ("none", "piecewise")


def test_vanishes_is_every_entry_zero():
    assert vanishes(ImmutableMatrix([x, y, 0])) == And(Eq(x, 0), Eq(y, 0))
    assert vanishes(ImmutableMatrix([0, 0, 0])) is true
    assert vanishes(ImmutableMatrix([1, x, 0])) is false


def test_piecewise_keeps_the_order_of_the_cases_then_the_default():
    c1, c2 = Eq(x, 0), Eq(y, 0)
    assert piecewise([(nan, c1), (oo, c2)], x / y) == Piecewise((nan, c1), (oo, c2), (x / y, True))


def test_piecewise_of_a_column_is_a_column_of_piecewise():
    default = ImmutableMatrix([x, y])
    got = piecewise([(ImmutableMatrix([1, 2]), Eq(x, 0)), (0, Eq(y, 0))], default)
    assert isinstance(got, ImmutableMatrix) and got.shape == (2, 1)
    assert got[0] == Piecewise((1, Eq(x, 0)), (0, Eq(y, 0)), (x, True))
    assert got[1] == Piecewise((2, Eq(x, 0)), (0, Eq(y, 0)), (y, True))


def test_piecewise_drops_false_cases_and_is_the_default_without_cases():
    assert piecewise([(1, false), (2, Eq(x, 0))], y) == Piecewise((2, Eq(x, 0)), (y, True))
    default = ImmutableMatrix([x, y])
    assert piecewise([(1, false)], default) is default
    assert piecewise([], y) is y
