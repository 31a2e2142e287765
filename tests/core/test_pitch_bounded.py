"""pitch of a screw with a large power in its direction answers at once (issue 33): whether
S = 0 is decided by the parts of each entry (x**n is zero exactly when x is), and an entry
whose expansion would be large is shown non-zero at an integer point instead of factored."""

from __future__ import annotations

import time

from sympy import Eq, Piecewise, nan, oo, symbols

from screwsym import Screw, pitch


def test_pitch_of_a_fortieth_power_is_fast_and_right():
    a, b, c, d = symbols("a b c d", real=True)
    e = (a + b + c + d) ** 40
    start = time.process_time()
    assert pitch(Screw([e, 1, 0], [e, 0, 1])) == e**2 / (e**2 + 1)
    assert pitch(Screw([e, 0, 0], [e, 0, 0])) == 1
    assert pitch(Screw([e, e, 0], [1, 0, 0])) == 1 / (2 * e)
    assert pitch(Screw([e + 1, 0, 0], [0, e, 1])) == 0
    # the piecewise form: a couple (or nothing) where the direction vanishes
    assert pitch(Screw([e, 0, 0], [0, 0, 1]), conds="piecewise") == Piecewise((oo, Eq(e, 0)), (0, True))
    assert pitch(Screw([e, 0, 0], [e, 0, 0]), conds="piecewise") == Piecewise((nan, Eq(e, 0)), (1, True))
    assert time.process_time() - start < 10  # each was over 120 s (a factorisation of 12,341 terms)


def test_a_direction_that_is_zero_is_still_found():
    """The shortcut proves only non-zero: an entry that cancels to zero is a couple (oo), with a
    large power too."""
    a, b, c, d, f = symbols("a b c d f", real=True)
    e = (a + b + c + d + f) ** 12  # 1,820 terms expanded: past the shortcut's threshold of 2,000 with its negative
    zero = e - e.expand()
    assert zero != 0  # not zero as written
    assert pitch(Screw([zero, 0, 0], [0, 0, 1])) == oo
    assert pitch(Screw([(a - a) * e, 0, 0], [1, 0, 0])) == oo
