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

import functools
import random
from fractions import Fraction

import mpmath
import numpy as np
import pytest
from sympy import Matrix, Rational, atan, diag, eye, pi, sqrt, sympify

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
        _ = m.modes
    assert m.isolated_modes == ()


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


def planar_newton(a, b, l2, starts=2000, seed=1):
    """Every real pose a batched Newton on (x, y, phi) finds from random starts (NumPy alone)."""
    rnd = np.random.default_rng(seed)
    a, b, l2 = (np.array(v, dtype=float) for v in (a, b, l2))
    z = np.column_stack([rnd.normal(scale=8, size=starts), rnd.normal(scale=8, size=starts), rnd.uniform(-np.pi, np.pi, starts)])
    for _ in range(80):
        c, s = np.cos(z[:, 2]), np.sin(z[:, 2])
        px = z[:, :1] + c[:, None] * b[:, 0] - s[:, None] * b[:, 1] - a[:, 0]
        py = z[:, 1:2] + s[:, None] * b[:, 0] + c[:, None] * b[:, 1] - a[:, 1]
        F = px**2 + py**2 - l2
        dphi = 2 * px * (-s[:, None] * b[:, 0] - c[:, None] * b[:, 1]) + 2 * py * (c[:, None] * b[:, 0] - s[:, None] * b[:, 1])
        J = np.stack([2 * px, 2 * py, dphi], -1)
        step = np.linalg.lstsq(J[0], F[0], rcond=None)[0] if starts == 1 else np.linalg.solve(J + 1e-300 * np.eye(3), F[..., None])[..., 0]
        z = z - step
        z[:, 2] = (z[:, 2] + np.pi) % (2 * np.pi) - np.pi
    ok = np.max(np.abs(F), -1) < 1e-9
    found = []
    for sol in z[ok]:
        if not any(np.allclose(sol, f, atol=1e-6) for f in found):
            found.append(sol)
    return found


def test_the_mirror_architecture():
    # the platform the base's mirror image: Cramer's determinant vanishes at every angle;
    # the modes come from the consistency of the two parallel rows, in pairs at one angle
    a, b = [(0, 0), (4, 0), (0, 3)], [(0, 0), (4, 0), (0, -3)]
    pose = (Rational(1, 3), Rational(1, 2), 2 * atan(Rational(2, 5)))
    lengths = leg_lengths(a, b, pose)
    m = direct_kinematics(a, b, lengths)
    assert pose in [mode.pose for mode in m.modes]
    l2 = [L**2 for L in lengths]
    found = planar_newton(a, b, l2)
    ours = [np.array([float(v) for v in mode.evalf(20)]) for mode in m.modes]
    assert len(found) == len(ours) == 4
    assert all(any(np.allclose(f, o, atol=1e-6) for o in ours) for f in found)
    assert all(m.closes(mode.pose) for mode in m.modes if mode.x.is_Rational)
    assert m.closes(next(mode.pose for mode in m.modes if not mode.x.is_Rational))  # square roots
    # lengths without a mode: none found, none claimed
    assert direct_kinematics(a, b, [1, 2, 2]).modes == ()
    assert planar_newton(a, b, [1, 4, 4]) == []


def test_leg_lengths_is_the_inverse_kinematics():
    pose = (Rational(1, 2), 3, 2 * atan(Rational(1, 3)))
    got = leg_lengths(BASE, PLATFORM, pose)
    want = mp_lengths(BASE, PLATFORM, pose)
    with mpmath.workdps(50):
        assert all(abs(mpmath.mpf(str(g.evalf(60))) - w) < mpmath.mpf(10) ** -40 for g, w in zip(got, want, strict=True))
    assert all((g**2).is_Rational for g in got)


# --------------------------------------------------------------------------------------
# Gough-Stewart platforms whose legs meet in pairs (3-3 octahedral, 6-3, 3-6)
# --------------------------------------------------------------------------------------

A3 = [(0, 0, 0), (6, 0, 0), (2, 5, 0)]
B3 = [(0, 0, 0), (3, 0, 0), (1, 2, 0)]
# the octahedral 3-3: B1-A1, B1-A2, B2-A2, B2-A3, B3-A3, B3-A1
OCTA_BASE = [A3[0], A3[1], A3[1], A3[2], A3[2], A3[0]]
OCTA_PLATFORM = [B3[0], B3[0], B3[1], B3[1], B3[2], B3[2]]


def rotation_from_quaternion(w, x, y, z):
    """A rational rotation (Euler-Rodrigues), exact."""
    n = w * w + x * x + y * y + z * z
    return Matrix(
        [
            [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z],
        ]
    ) / n


POSE = (Matrix([1, 2, Rational(7, 2)]), rotation_from_quaternion(1, Rational(1, 3), Rational(-1, 2), Rational(1, 4)))


def mp_points(platform, mode_or_pose, dps=50):
    p, R = mode_or_pose
    with mpmath.workdps(dps):
        P = mpmath.matrix([mpmath.mpf(str(sympify(v).evalf(dps + 10))) for v in p])
        M = mpmath.matrix([[mpmath.mpf(str(sympify(R[i, j]).evalf(dps + 10))) for j in range(3)] for i in range(3)])
        return [P + M * mpmath.matrix(list(b)) for b in platform]


def mp_leg_errors(base, platform, pose, l2, dps=50):
    with mpmath.workdps(dps):
        pts = mp_points(platform, pose, dps)
        return [
            abs(sum((pts[i][k] - a[k]) ** 2 for k in range(3)) - mpmath.mpf(Fraction(str(q)).numerator) / Fraction(str(q)).denominator)
            for i, (a, q) in enumerate(zip(base, l2, strict=True))
        ]


def newton_solutions(base, platform, l2, starts=400, seed=0):
    """Every real solution a batched Newton finds from random starts, with NumPy alone: the
    three platform points as nine unknowns, the six legs and the platform's three sides."""
    rnd = np.random.default_rng(seed)
    pts = sorted(set(platform), key=platform.index)
    idx = [pts.index(b) for b in platform]
    A = np.array(base, float)
    L2 = np.array([float(q) for q in l2])
    P = np.array(pts, float)
    sides = [(0, 1), (1, 2), (2, 0)]
    D2 = np.array([np.sum((P[j] - P[k]) ** 2) for j, k in sides])
    z = rnd.normal(scale=6, size=(starts, 3, 3))
    for _ in range(60):
        F = np.zeros((starts, 9))
        J = np.zeros((starts, 9, 9))
        for i in range(6):
            d = z[:, idx[i]] - A[i]
            F[:, i] = np.sum(d**2, -1) - L2[i]
            J[:, i, 3 * idx[i]: 3 * idx[i] + 3] = 2 * d
        for r, (j, k) in enumerate(sides):
            d = z[:, j] - z[:, k]
            F[:, 6 + r] = np.sum(d**2, -1) - D2[r]
            J[:, 6 + r, 3 * j: 3 * j + 3] = 2 * d
            J[:, 6 + r, 3 * k: 3 * k + 3] = -2 * d
        try:
            step = np.linalg.solve(J, F[..., None])[..., 0]
        except np.linalg.LinAlgError:
            step = np.linalg.lstsq(J[0], F[0], rcond=None)[0][None] * 0
        z = z - step.reshape(starts, 3, 3)
    ok = np.max(np.abs(F), -1) < 1e-9
    found = []
    for sol in z[ok]:
        if not any(np.allclose(sol, f, atol=1e-6) for f in found):
            found.append(sol)
    return found


@functools.lru_cache(maxsize=1)
def octahedral():
    lengths = leg_lengths(OCTA_BASE, OCTA_PLATFORM, POSE)
    return lengths, direct_kinematics(OCTA_BASE, OCTA_PLATFORM, lengths)


def test_octahedral_3_3_round_trip_and_every_mode_closes():
    lengths, m = octahedral()
    l2 = [L**2 for L in lengths]
    assert m.polynomial.degree() == 16  # Nanua, Waldron & Murthy 1990: 16 complex modes
    assert (POSE[0], POSE[1]) in [mode.pose for mode in m.modes]  # exactly
    assert len(m.modes) % 2 == 0
    S = diag(1, 1, -1)
    mirrored = [(S * mode.position, S * mode.rotation * S) for mode in m.modes]
    for mode in m.modes:
        errs = mp_leg_errors(OCTA_BASE, OCTA_PLATFORM, mode.pose, l2)
        assert max(errs) < mpmath.mpf(10) ** -30
        R = mode.rotation.evalf(40)
        assert (R.T * R - eye(3)).norm() < 1e-35 and abs(R.det() - 1) < 1e-35
    # the mirror image of each mode in the base plane is a mode (the platform is planar)
    for p, R in mirrored:
        assert any((p - q.position).evalf(30).norm() < 1e-25 and (R - q.rotation).evalf(30).norm() < 1e-25 for q in m.modes)
    # completeness, independently: Newton from random starts (NumPy) finds no other mode
    found = newton_solutions(OCTA_BASE, OCTA_PLATFORM, l2)
    ours = [np.array([[float(v) for v in (mode.position + mode.rotation * Matrix(b)).evalf(20)] for b in B3]) for mode in m.modes]
    assert len(found) == len(ours)
    assert all(any(np.allclose(f, o, atol=1e-6) for o in ours) for f in found)


def test_the_spatial_checker_rejects_a_perturbed_or_improper_pose():
    lengths, m = octahedral()
    mode = next(mode for mode in m.modes if mode.pose == POSE)
    assert m.closes(mode.pose)
    eps = Rational(1, 10**40)
    assert not m.closes((mode.position + Matrix([eps, 0, 0]), mode.rotation))
    assert not m.closes((mode.position, mode.rotation * (1 + eps)))
    # a reflection closes every leg of a planar platform, but is no pose
    S = diag(1, 1, -1)
    assert leg_lengths(OCTA_BASE, OCTA_PLATFORM, (POSE[0], POSE[1] * S)) == lengths
    assert not m.closes((POSE[0], POSE[1] * S))


def check_round_trip(base, plat, pose):
    lengths = leg_lengths(base, plat, pose)
    m = direct_kinematics(base, plat, lengths)
    assert m.polynomial.degree() <= 16 and pose in [mode.pose for mode in m.modes]
    for mode in m.modes:
        assert max(mp_leg_errors(base, plat, mode.pose, [L**2 for L in lengths])) < mpmath.mpf(10) ** -30
        assert m.closes(mode.pose) if mode.pose == pose else True


PLATFORM63 = [B3[0], B3[0], B3[1], B3[1], B3[2], B3[2]]
POSE63 = (Matrix([2, 3, 5]), rotation_from_quaternion(2, -1, Rational(1, 2), 1))


BASE6 = [(0, 0, 0), (4, -1, 0), (7, 1, 0), (5, 6, 0), (1, 7, 0), (-2, 3, 0)]  # a planar base


@pytest.mark.slow
def test_6_3_round_trip():
    # about 8 s alone: SymPy's Groebner basis and 50-digit checks of eight modes
    check_round_trip(BASE6, PLATFORM63, POSE63)


@pytest.mark.slow
def test_3_6_round_trip():
    # inverted: three base points, six platform points (about 12 s)
    check_round_trip(PLATFORM63, BASE6, POSE63)


@pytest.mark.slow
def test_6_3_with_a_base_out_of_plane():
    # SymPy's Groebner basis takes about 70 s here (2 s with a planar base): slow
    base6 = [(0, 0, 0), (4, -1, 0), (7, 1, 1), (5, 6, 0), (1, 7, -1), (-2, 3, 0)]
    check_round_trip(base6, PLATFORM63, POSE63)


def test_spatial_input_refused_or_not_handled():
    with pytest.raises(NotImplementedError, match="general 6-6"):
        direct_kinematics([(i, i * i, 0) for i in range(6)], [(i, 1, i * i) for i in range(6)], [5] * 6)
    with pytest.raises(ValueError, match="collinear"):
        direct_kinematics([(0, 0, 0), (1, 0, 0), (1, 0, 0), (2, 0, 0), (2, 0, 0), (0, 0, 0)], OCTA_PLATFORM, [5] * 6)
    with pytest.raises(ValueError, match="expected 6 leg lengths"):
        direct_kinematics(OCTA_BASE, OCTA_PLATFORM, [5] * 3)
    with pytest.raises(ValueError, match="direct_kinematics: the case split needs more work"):
        direct_kinematics(OCTA_BASE, OCTA_PLATFORM, [5] * 6, budget=1000)
    with pytest.raises(ValueError, match="pose\\[1\\]"):
        leg_lengths(OCTA_BASE, OCTA_PLATFORM, (POSE[0], [[1, 0], [0, 1]]))


def test_spatial_leg_lengths_is_the_inverse_kinematics():
    got = leg_lengths(OCTA_BASE, OCTA_PLATFORM, POSE)
    errs = mp_leg_errors(OCTA_BASE, OCTA_PLATFORM, POSE, [g**2 for g in got])
    assert max(errs) < mpmath.mpf(10) ** -40
    assert all((g**2).is_Rational for g in got)
