"""Assembly modes of parallel mechanisms: the direct kinematics of the planar 3-RPR, exact.

The planar 3-RPR has at most six assembly modes (Hunt 1983; Gosselin, Sefrioui & Richard,
"Solutions polynomiales au probleme de la cinematique directe des manipulateurs paralleles
plans a trois degres de liberte", Mech. Mach. Theory 27 (1992); Gosselin & Merlet, Mech.
Mach. Theory 29 (1994), who show the six can all be real).  The published tables are not
reproduced here from memory: the six-mode instance below was found by a search over small
integer geometries, and each of its modes is checked INDEPENDENTLY of the library's
algebra: the leg lengths recomputed from the pose with mpmath at 50 digits, and the count
by a dense scan over phi of the closure residual computed with NumPy from the geometry
alone (Cramer's rule in floating point), and by NumPy's roots of the polynomial.
"""

from __future__ import annotations

import random
from fractions import Fraction

import mpmath
import numpy as np
import pytest
from sympy import Rational, atan, pi, sqrt, sympify

from screwsym.systems import AssemblyModes, direct_kinematics, leg_lengths

# a base and a platform triangle with legs 11, 10, 11: six real modes
BASE = [(0, 0), (10, 0), (-2, 9)]
PLATFORM = [(0, 0), (9, 0), (5, 6)]
LENGTHS = [11, 10, 11]


def mp_lengths(a, b, pose, dps=50):
    """The leg lengths at ``pose`` with mpmath (independent of the library)."""
    with mpmath.workdps(dps):
        x, y, phi = (mpmath.mpf(str(sympify(v).evalf(dps + 10))) for v in pose)
        c, s = mpmath.cos(phi), mpmath.sin(phi)
        return [
            mpmath.sqrt((x + c * bx - s * by - ax) ** 2 + (y + s * bx + c * by - ay) ** 2)
            for (ax, ay), (bx, by) in zip(a, b, strict=True)
        ]


def residual_scan(a, b, l2, n=400_001):
    """The closure residual ``det**2 * E_1`` over a grid of phi, by NumPy: Cramer's rule for
    ``p`` from the differences of the closures, then the first closure.  Its sign changes
    are the angles of the modes (for modes of multiplicity one)."""
    a, b, l2 = (np.array(v, dtype=float) for v in (a, b, l2))
    phi = np.linspace(-np.pi, np.pi, n)[1:-1]
    c, s = np.cos(phi), np.sin(phi)
    rb = np.stack([c[:, None] * b[:, 0] - s[:, None] * b[:, 1], s[:, None] * b[:, 0] + c[:, None] * b[:, 1]], -1)
    w = rb - a  # (n, 3, 2): p + w_i is leg i
    k = np.sum(w**2, -1) - l2  # |p + w_i|**2 - l_i**2 = |p|**2 + 2 p.w_i + k_i
    M = 2 * (w[:, 1:] - w[:, :1])
    r = -(k[:, 1:] - k[:, :1])
    det = M[:, 0, 0] * M[:, 1, 1] - M[:, 0, 1] * M[:, 1, 0]
    nx = M[:, 1, 1] * r[:, 0] - M[:, 0, 1] * r[:, 1]
    ny = M[:, 0, 0] * r[:, 1] - M[:, 1, 0] * r[:, 0]
    f = nx**2 + ny**2 + 2 * det * (nx * w[:, 0, 0] + ny * w[:, 0, 1]) + det**2 * k[:, 0]
    changes = np.nonzero(np.sign(f[1:]) != np.sign(f[:-1]))[0]
    return phi[changes]


def test_six_real_modes_each_closing_to_1e_30():
    m = direct_kinematics(BASE, PLATFORM, LENGTHS)
    assert isinstance(m, AssemblyModes) and m.is_finite
    assert m.polynomial.degree() == 6
    assert len(m.modes) == 6
    for mode in m.modes:
        got = mp_lengths(BASE, PLATFORM, mode.pose)
        with mpmath.workdps(50):
            assert all(abs(g - L) < mpmath.mpf(10) ** -30 for g, L in zip(got, LENGTHS, strict=True))
        assert m.closes(mode.pose)
    # completeness: the residual's sign changes over phi, from the geometry alone
    angles = residual_scan(BASE, PLATFORM, [L**2 for L in LENGTHS])
    assert len(angles) == 6
    ours = sorted(float(mode.phi) for mode in m.modes)
    assert np.allclose(sorted(angles), ours, atol=1e-4)
    # and NumPy's roots of the polynomial: six real, the tangents of the half angles
    roots = np.roots([float(c) for c in m.polynomial.all_coeffs()])
    real = np.sort(roots[np.abs(roots.imag) < 1e-9].real)
    assert np.allclose(real, sorted(float(mode.t) for mode in m.modes), rtol=1e-8)


def test_a_mode_refines_to_any_precision():
    mode = direct_kinematics(BASE, PLATFORM, LENGTHS).modes[2]
    x60 = mode.evalf(60)
    got = mp_lengths(BASE, PLATFORM, x60, dps=60)
    with mpmath.workdps(60):
        assert all(abs(g - L) < mpmath.mpf(10) ** -55 for g, L in zip(got, LENGTHS, strict=True))


def test_the_checker_rejects_a_perturbed_mode():
    m = direct_kinematics(BASE, PLATFORM, LENGTHS)
    mode = m.modes[0]
    eps = Rational(1, 10**40)
    assert m.closes(mode.pose)
    assert not m.closes((mode.x + eps, mode.y, mode.phi))
    assert not m.closes((mode.x, mode.y, mode.phi + eps))
    assert not m.closes(m.modes[1].pose[:2] + (mode.phi,))
    # and the numeric check of this file too
    got = mp_lengths(BASE, PLATFORM, (mode.x + Rational(1, 10**20), mode.y, mode.phi))
    with mpmath.workdps(50):
        assert max(abs(g - L) for g, L in zip(got, LENGTHS, strict=True)) > mpmath.mpf(10) ** -30


def random_point(rnd, lo=-9, hi=9):
    return (Rational(rnd.randint(lo * 4, hi * 4), 4), Rational(rnd.randint(lo * 4, hi * 4), 4))


@pytest.mark.parametrize("seed", range(4))
def test_round_trip_pose_lengths_modes(seed):
    rnd = random.Random(seed)
    a = [random_point(rnd) for _ in range(3)]
    b = [random_point(rnd, -4, 4) for _ in range(3)]
    t = Rational(rnd.randint(-20, 20), rnd.randint(1, 9))
    pose = (*random_point(rnd), 2 * atan(t))
    lengths = leg_lengths(a, b, pose)
    m = direct_kinematics(a, b, lengths)
    assert m.is_finite and 1 <= len(m.modes) <= 6
    assert pose in [mode.pose for mode in m.modes]  # exactly: the root t is rational
    for mode in m.modes:
        assert m.closes(mode.pose)
        with mpmath.workdps(50):
            got = mp_lengths(a, b, mode.pose)
            want = [mpmath.sqrt(mpmath.mpf(Fraction(str(L**2)).numerator) / Fraction(str(L**2)).denominator) for L in lengths]
            assert all(abs(g - w) < mpmath.mpf(10) ** -30 for g, w in zip(got, want, strict=True))


def test_a_mode_at_phi_pi_is_not_lost():
    # t = tan(phi/2) is infinite there: the polynomial's degree drops, the mode is found apart
    pose = (Rational(1, 2), Rational(-3, 2), pi)
    lengths = leg_lengths(BASE, PLATFORM, pose)
    m = direct_kinematics(BASE, PLATFORM, lengths)
    assert m.polynomial.degree() < 6
    at_pi = [mode for mode in m.modes if mode.phi == pi]
    assert [mode.pose for mode in at_pi] == [pose] and at_pi[0].t is None
    assert all(m.closes(mode.pose) for mode in m.modes)


def test_a_root_where_cramers_rule_fails():
    # at phi = 0 the differences b_i - b_1 - (a_i - a_1) are parallel: a line of positions
    # meets the circle of the first leg there (two modes of one angle, square roots)
    a = [(0, 0), (4, 0), (0, 3)]
    b = [(0, 0), (5, 0), (2, 3)]
    pose = (Rational(1, 3), Rational(1, 2), 0)
    lengths = leg_lengths(a, b, pose)
    m = direct_kinematics(a, b, lengths)
    at_zero = [mode for mode in m.modes if mode.phi == 0]
    assert len(at_zero) == 2 and pose in [mode.pose for mode in at_zero]
    for mode in m.modes:
        assert m.closes(mode.pose)
    l2 = [L**2 for L in lengths]
    for mode in m.modes:
        got = mp_lengths(a, b, mode.pose)
        with mpmath.workdps(50):
            assert all(abs(g**2 - mpmath.mpf(Fraction(str(q)).numerator) / Fraction(str(q)).denominator) < mpmath.mpf(10) ** -30 for g, q in zip(got, l2, strict=True))


def test_a_circle_of_modes_is_reported_as_infinite():
    # the platform equal to the base, every leg 1: translations on the unit circle at phi = 0
    a = [(0, 0), (4, 0), (0, 3)]
    m = direct_kinematics(a, a, [1, 1, 1])
    assert not m.is_finite
    with pytest.raises(ValueError, match="infinitely many"):
        _ = m.modes
    (fam,) = m.families
    assert fam.kind == "circle" and fam.phi == 0 and fam.center == (0, 0) and fam.radius == 1
    assert m.closes((Rational(3, 5), Rational(4, 5), 0))  # a point of the family
    assert not m.closes((Rational(3, 5), Rational(3, 5), 0))
    for mode in m.isolated_modes:  # the other modes, at other angles
        assert m.closes(mode.pose) and mode.phi != 0


def test_a_curve_of_modes_is_reported_as_infinite():
    # the three legs meet at one base point, at the platform's circumcentre: any angle
    m = direct_kinematics([(0, 0)] * 3, [(0, 0), (4, 0), (0, 3)], [Rational(5, 2)] * 3)
    assert m.polynomial.is_zero and not m.is_finite
    (fam,) = m.families
    assert fam.kind == "curve"
    for t in (Rational(1, 3), Rational(-7, 2)):
        pose = (fam.x.subs("t", t), fam.y.subs("t", t), 2 * atan(t))
        assert m.closes(pose)
    with pytest.raises(ValueError, match="infinitely many"):
        len(m)


def test_floats_are_taken_as_exact_binary_values():
    exact = direct_kinematics(BASE, PLATFORM, LENGTHS)
    floats = direct_kinematics([(0.0, 0.0), (10.0, 0.0), (-2.0, 9.0)], PLATFORM, [11.0, 10.0, 11.0])
    assert floats.polynomial == exact.polynomial and floats.modes == exact.modes
    m = direct_kinematics(BASE, PLATFORM, [11, 10, 11.1])
    assert Rational(11.1) ** 2 in m.squared_lengths and Rational(111, 10) ** 2 not in m.squared_lengths


def test_bad_input_is_refused():
    with pytest.raises(TypeError, match="base_points"):
        direct_kinematics("abc", PLATFORM, LENGTHS)
    with pytest.raises(TypeError, match="strings are never evaluated"):
        direct_kinematics([(0, "1"), (10, 0), (-2, 9)], PLATFORM, LENGTHS)
    with pytest.raises(ValueError, match="expected 3 leg lengths"):
        direct_kinematics(BASE, PLATFORM, [1, 2])
    with pytest.raises(ValueError, match="platform_points\\[1\\]: expected 2 coordinates"):
        direct_kinematics(BASE, [(0, 0), (1, 0, 0), (0, 1)], LENGTHS)
    with pytest.raises(ValueError, match="rational number"):
        direct_kinematics([(0, sqrt(2)), (10, 0), (-2, 9)], PLATFORM, LENGTHS)
    with pytest.raises(ValueError, match="non-negative length"):
        direct_kinematics(BASE, PLATFORM, [11, -10, 11])
    with pytest.raises(ValueError, match="square is rational"):
        direct_kinematics(BASE, PLATFORM, [11, 10, 2 ** Rational(1, 4)])
    with pytest.raises(TypeError, match="budget"):
        direct_kinematics(BASE, PLATFORM, LENGTHS, budget=1.5)
    with pytest.raises(ValueError, match="direct_kinematics: the case split needs more work"):
        direct_kinematics(BASE, PLATFORM, LENGTHS, budget=10)


def test_the_mirror_architecture_is_refused_not_answered_wrongly():
    # the platform the mirror image of the base: Cramer's determinant vanishes at every angle
    with pytest.raises(NotImplementedError, match="parallel at every angle"):
        direct_kinematics([(0, 0), (4, 0), (0, 3)], [(0, 0), (4, 0), (0, -3)], [1, 2, 2])


def test_leg_lengths_is_the_inverse_kinematics():
    pose = (Rational(1, 2), 3, 2 * atan(Rational(1, 3)))
    got = leg_lengths(BASE, PLATFORM, pose)
    want = mp_lengths(BASE, PLATFORM, pose)
    with mpmath.workdps(50):
        assert all(abs(mpmath.mpf(str(g.evalf(60))) - w) < mpmath.mpf(10) ** -40 for g, w in zip(got, want, strict=True))
    assert all((g**2).is_Rational for g in got)
