"""The budget of ``direct_kinematics`` holds inside SymPy's Groebner basis (issue 36).

SymPy's ``groebner`` cannot be stopped midway; the Gough-Stewart solver runs it in a worker
process ended when the budget's CPU time runs out (``screwsym.algebra.budget.run_bounded``).
The 6-3 platform whose base points are not coplanar (tests/systems/test_assembly.py: its
basis takes about 70 s) is refused with the library's error after the budget's CPU time
(``budget x SLACK`` microseconds: 2 s here), not after the basis.
"""

from __future__ import annotations

import pytest
from sympy import Matrix, Rational

from screwsym.systems import direct_kinematics, leg_lengths

B3 = [(0, 0, 0), (3, 0, 0), (1, 2, 0)]
PLATFORM63 = [B3[0], B3[0], B3[1], B3[1], B3[2], B3[2]]
BASE63 = [(0, 0, 0), (4, -1, 0), (7, 1, 1), (5, 6, 0), (1, 7, -1), (-2, 3, 0)]  # out of plane


def rotation_from_quaternion(w, x, y, z):
    """A rational rotation (Euler-Rodrigues), exact."""
    n = w * w + x * x + y * y + z * z
    return Matrix([
        [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z],
    ]) / n


def test_a_small_budget_stops_the_groebner_basis_of_the_6_3():
    pose = (Matrix([2, 3, 5]), rotation_from_quaternion(2, -1, Rational(1, 2), 1))
    lengths = leg_lengths(BASE63, PLATFORM63, pose)
    with pytest.raises(ValueError, match="direct_kinematics: the case split needs more work than "
                                         "budget=400000"):
        direct_kinematics(BASE63, PLATFORM63, lengths, budget=400_000)
