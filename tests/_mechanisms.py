"""Mechanisms for the tests: the builders that tests/systems and tests/numeric share."""

from __future__ import annotations

from sympy import Rational, sqrt

from screwsym.systems.joints import P, R, S
from screwsym.systems.parallel import Limb, ParallelMechanism

Z = [0, 0, 1]
O = [0, 0, 0]
#: unit radial directions at 0, 120 and 240 degrees
E = [[1, 0, 0], [-Rational(1, 2), sqrt(3) / 2, 0], [-Rational(1, 2), -sqrt(3) / 2, 0]]


def four_bar(B=(1, 2, 0), Cp=(3, 3, 0)):
    """A-B-C-D, base joints A = O and D = (4, 0, 0); limbs A-B and D-C carry the coupler B-C."""
    return ParallelMechanism(Limb(R(O, Z), R(list(B), Z)), Limb(R([4, 0, 0], Z), R(list(Cp), Z)))


def rps_leg(i, rho, h, base=2):
    """3-RPS leg i: R at base * e_i, axis tangent; the leg in the plane normal to the R axis."""
    e = E[i]
    b = [base * c for c in e]
    d = [rho * e[0], rho * e[1], h]
    top = [x + y for x, y in zip(b, d, strict=True)]
    return Limb(R(b, [-e[1], e[0], 0]), P(d), S(top))


def three_rps(rho=None, h=(2, 2, 3)):
    rho = (Rational(-1, 2),) * 3 if rho is None else rho
    return ParallelMechanism(*(rps_leg(i, rho[i], h[i]) for i in range(3)))
