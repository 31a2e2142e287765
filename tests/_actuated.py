"""Actuated mechanisms for the tests and benchmarks of screwsym.systems.actuation."""

from __future__ import annotations

from sympy import Matrix, Rational, cancel, cos, eye, sin, sqrt, sympify

from screwsym.systems.joints import P, R, S
from screwsym.systems.parallel import Limb, ParallelMechanism

Z = [0, 0, 1]
#: unit radial directions at 0, 120 and 240 degrees
E = [Matrix([1, 0, 0]), Matrix([-Rational(1, 2), sqrt(3) / 2, 0]),
     Matrix([-Rational(1, 2), -sqrt(3) / 2, 0])]


def five_bar(p, a1=(0, 0), b1=(0, 1), a2=(3, 0), b2=(3, 1)):
    """The planar five-bar A1-B1-P-B2-A2, cranks at A1 and A2 actuated; end point ``p``.

    Each leg is R-R-R to the end point; a P-P leg (translations x, y) keeps the
    end link from spinning, so the end point's two translations are the freedoms,
    as in Wang et al. (2010), Section 4, and Liu, Wang & Pritschow (2006).
    """
    pt = [p[0], p[1], 0]
    return ParallelMechanism(
        Limb(R([*a1, 0], Z), R([*b1, 0], Z), R(pt, Z), actuated=0),
        Limb(R([*a2, 0], Z), R([*b2, 0], Z), R(pt, Z), actuated=0),
        Limb(P([1, 0, 0]), P([0, 1, 0])),
    )


def _rz(s):
    s = sympify(s, strict=True)
    c, n = (1 - s**2) / (1 + s**2), 2 * s / (1 + s**2)
    return Matrix([[c, -n, 0], [n, c, 0], [0, 0, 1]])


def three_rps_pose(p, q, z, rb=2, rp=1):
    """Tsai's symmetric 3-RPS at a symbolic pose: a tilt and the height ``z``.

    The platform turns about the horizontal axis ``(p, q, 0)`` by ``2 atan(|(p, q)|)``
    (the Cayley form, rational: the rotations ``Rz(phi) Ry(theta) Rz(-phi)`` of the
    3-RPS), and the parasitic translation ``(c_x, c_y)`` that keeps every sphere
    centre in its leg's plane (Tsai 1999, Sec. 3.5; Huang, Li & Ding 2013, Ch. 5) is
    ``rp (p^2 - q^2, -2 p q) / (1 + p^2 + q^2)``, solved in closed form and checked in
    the tests.  Base radius ``rb``, platform radius ``rp``; the P joints actuated.
    """
    K = Matrix([[0, 0, q], [0, 0, -p], [-q, p, 0]])
    den = 1 + p**2 + q**2
    Rm = (eye(3) + 2 / den * (K + K * K)).applyfunc(cancel)
    c = Matrix([cancel(rp * (p**2 - q**2) / den), cancel(-2 * rp * p * q / den), z])
    legs = []
    for e in E:
        b = rb * e
        u = Matrix([-e[1], e[0], 0])
        top = (Rm * (rp * e) + c).applyfunc(cancel)
        legs.append(Limb(R(b, u), P(top - b), S(top), actuated=1))
    return ParallelMechanism(*legs)


def gough_stewart_33(tau, h=1, rb=2, rp=1, trig=False):
    """A 3-3 Gough-Stewart (octahedral) platform turned about the vertical axis by
    ``theta = 2 atan(tau)`` from the position where its triangle is opposite the base's
    (``trig=True``: by the angle ``tau`` itself, the turn written with its cos and sin).

    Base vertices at radius ``rb`` (0, 120, 240 degrees), platform vertices at radius
    ``rp`` (60, 180, 300 degrees before the turn), height ``h``; each base vertex
    is joined to its two neighbouring platform vertices by S-P-S legs (P actuated).
    """
    if trig:
        c, n = cos(tau), sin(tau)
        Rm = Matrix([[c, -n, 0], [n, c, 0], [0, 0, 1]])
    else:
        Rm = _rz(tau).applyfunc(cancel)
    base = [rb * e for e in E]
    top = [(Rm * (-rp * e) + Matrix([0, 0, h])).applyfunc(cancel) for e in E]
    legs = []
    for i in range(3):
        for j in ((i + 1) % 3, (i + 2) % 3):
            b, p = base[i], top[j]
            legs.append(Limb(S(b), P(p - b), S(p), actuated=1))
    return ParallelMechanism(*legs)


def three_rpr(x, y, c, s, base, platform):
    """A planar 3-RPR: legs from the base points ``base`` (R) to the platform points (R),
    their prismatic joints actuated; ``platform`` in the platform's frame, placed by the
    pose ``(x, y)`` turned by the angle of cosine ``c`` and sine ``s`` (Gosselin & Angeles
    1990, Fig. 4)."""
    legs = []
    for a, b in zip(base, platform, strict=True):
        a = Matrix([a[0], a[1], 0])
        top = Matrix([c * b[0] - s * b[1] + x, s * b[0] + c * b[1] + y, 0])
        legs.append(Limb(R(a, Z), P(top - a), R(top, Z), actuated=1))
    return ParallelMechanism(*legs)


#: a platform triangle, and two bases: at the pose (0, 0, 0) the legs of the first meet at
#: the origin (concurrent), those of the second are all parallel (Gosselin & Angeles 1990)
RPR_PLATFORM = [(1, 0), (0, 1), (-1, -1)]
RPR_CONCURRENT = [(2, 0), (0, 2), (-2, -2)]
RPR_PARALLEL = [(1, -2), (0, -1), (-1, -3)]
#: a base on which no pose near (0, 0, 0) is singular
RPR_BASE = [(3, -1), (-1, 3), (-2, -3)]


def gough_stewart_66(x, y, z, base, k=None):
    """A 6-6 Gough-Stewart platform (S-P-S legs, P actuated) whose platform hexagon is the
    base hexagon ``base`` (six points of the plane) scaled by ``k``: similar hexagons, at zero
    orientation, translated by ``(x, y, z)`` (Ma & Angeles 1991: an architecture
    singularity, singular at every translation)."""
    k = Rational(1, 2) if k is None else k
    legs = []
    for a in base:
        b = Matrix([a[0], a[1], 0])
        top = Matrix([k * a[0] + x, k * a[1] + y, z])
        legs.append(Limb(S(b), P(top - b), S(top), actuated=1))
    return ParallelMechanism(*legs)


#: a semi-regular base hexagon (not regular: a regular one gives another degeneracy)
HEXAGON = [(4, 1), (-1, 4), (-3, 3), (-3, -3), (-1, -4), (4, -1)]
