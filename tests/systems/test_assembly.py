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


def test_spatial_input_refused():
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


# --------------------------------------------------------------------------------------
# the general 6-6: Dietmaier's platform with 40 real modes, and random ones
# --------------------------------------------------------------------------------------

# Dietmaier, "The Stewart-Gough platform of general geometry can have 40 real postures",
# ARK 1998, pp. 1-10, as transcribed in PHCpack's demo file src/Demo/stewgou40
# (github.com/janverschelde/PHCpack): leg i joins A_i to n + R B_i.
DIET_A = [(0, 0, 0), ("1.107915", 0, 0), ("0.549094", "0.756063", 0),
          ("0.735077", "-0.223935", "0.525991"), ("0.514188", "-0.526063", "-0.368418"),
          ("0.590473", "0.094733", "-0.205018")]
DIET_B = [(0, 0, 0), ("0.542805", 0, 0), ("0.956919", "-0.528915", 0),
          ("0.665885", "-0.353482", "1.402538"), ("0.478359", "1.158742", "0.107672"),
          ("-0.137087", "-0.235121", "0.353913")]
DIET_L = ["1", "0.645275", "1.086284", "1.503439", "1.281933", "0.771071"]

# PHCpack's 40 solutions of src/Demo/stewgou40 (real parts; the imaginary parts listed there
# are below 1e-31), each "n1 n2 n3 a11 a12 a13 a21 a22 a23": n the platform's origin, a1 and
# a2 the first two columns of R.
PHC_STEWGOU40 = """
0.534003548614846 0.00617464537788932 -0.845459687874714 0.0636859679827326 -0.273293377921528 0.959820205593914 0.992514435679251 -0.0830827232386822 -0.0895117649671954
0.863325713770891 0.00564402867997359 -0.50461555354769 0.191288333012351 0.943756501770663 0.26968952337634 -0.727039337601767 -0.0483533608080227 0.684891052707037
0.458734196042698 -0.373482566386209 -0.806271486527107 0.368860267183001 0.0407073379420521 0.92859303030518 0.924342754384125 -0.12100625569733 -0.361867321679759
0.832284652705197 -0.282751760714109 0.476816210593203 -0.382981891941851 -0.266292049783987 -0.884541358369682 -0.475822014065617 -0.763878999533626 0.435984271507638
0.825080174807858 -0.31892563725912 0.46640019622412 -0.260309875080715 -0.306586498174506 -0.915556381700525 -0.22675020654105 -0.902315220510292 0.366621857871369
0.958098206425925 -0.284038680295125 -0.0370115514350629 -0.251037203502158 -0.0494976885688591 0.96671107435684 -0.00311210657578553 -0.998645308796313 -0.0519409473515592
0.535059805089595 -0.749596111150599 -0.389636593668234 0.275453499517998 0.490427569122504 0.826804795007794 0.958346562586592 -0.207623649715259 -0.196123140035486
0.539848418396206 0.678840402335085 0.4977342597337 0.872889092300304 -0.487412172424983 -0.0222262618339058 -0.426919121596827 -0.785022713166514 0.448864571366107
0.855765578596128 -0.334679158802413 0.394531538857596 -0.262159355550805 -0.305118645203351 -0.915519024732123 0.0753301863744732 -0.952275693659966 0.295797846992195
0.99357727988254 0.0796654869549876 -0.0803591879590493 0.0858684284463838 0.958900432623298 -0.27043774387278 -0.970578427677462 0.0192225092956508 -0.240016688718775
0.689418318569635 0.593656300371125 -0.415059729497196 -0.210582457802054 -0.971898937276348 0.105202111134483 -0.251238756720206 -0.0501948080335288 -0.966622764250958
0.636111780656805 0.771451960369755 0.014955779862322 0.403995111057654 -0.570369249047288 -0.71516911984701 0.546802941037561 -0.476187161523352 0.688659807795552
0.998901201703156 -0.0415643212288688 -0.0216517074794277 -0.768309996521777 -0.0380464598421854 -0.638946176245061 0.637073346346389 0.0511533959452041 -0.769103947108769
0.803267816614331 -0.296007114309009 0.51685646273419 0.347483676895208 0.924976155378647 0.153864246244288 0.66116532364085 -0.125334288273277 -0.739697053527944
0.891374858482066 -0.0798270407205689 -0.446182143564569 -0.772754070399605 0.124475148333286 0.622380176522556 -0.5304682379089 0.411756423596472 -0.740985894735433
0.854376241567566 -0.294202949023025 0.428352498102948 -0.512684519571621 -0.128566989770228 -0.848896408599447 -0.651892330670189 -0.585147000776723 0.482327043296761
0.955868038053903 -0.0469956294144925 -0.29001328356287 -0.0404503572788201 0.983337493668175 -0.177231888051804 -0.932229494182938 0.0266955230935295 0.360881586150066
0.993725753949452 0.111785841717458 0.00361269001070998 0.160649572104603 0.963663368265282 -0.213411873255029 -0.857007169860833 0.0289304252424857 -0.514491731034051
0.998523184555461 0.0311963433241766 0.0444773882823691 -0.967647453552388 0.0945970104164593 -0.233901285276178 0.251917037750896 0.413708197898153 -0.874861893719618
0.485480868222368 -0.200817523650534 -0.850870524101595 0.236223483879496 -0.102020949277161 0.966328200753978 0.965580988216924 -0.0867721144732894 -0.245201866517901
0.442198664294286 -0.713494517208498 -0.543494172194847 0.635108872193352 0.328441911591642 0.699115606442394 0.77200141612478 -0.299793875619531 -0.560479656760489
0.917778090378591 -0.111176182195232 0.381212845184314 0.099504273778378 0.981800859405347 0.161758993477207 0.279494636423541 0.12844311928329 -0.951517269059922
0.443037558993735 -0.558620406851917 -0.701185398000751 0.508689536806823 0.195638330781374 0.838427455819726 0.858129045381476 -0.193982996160302 -0.475378942185442
0.521847667572176 0.810720215374404 0.26534457641482 0.744610461306344 -0.62075620269688 0.245391519263612 -0.654481004425527 -0.606710821818961 0.45117246539867
0.989132291307142 0.116671335896421 0.0894712784843688 0.200591802337382 0.972716506813502 -0.116556965504332 -0.670069414937762 0.0494310791152468 -0.740650759523318
0.477891495744216 -0.781098769166185 -0.40187613900607 0.826711558940246 0.562537417927839 0.00998257209683472 0.168452377741072 -0.230552752606781 -0.958368000665097
0.679796319226422 0.348060722634918 -0.645546820707117 -0.316630836891232 -0.570962406372255 0.757460786865672 0.948521087940044 -0.196693912816955 0.248232250913921
0.781100385565255 0.0687982308185337 -0.620603731140935 -0.541606685574368 -0.173803010414417 0.822468669137028 -0.831931660393735 0.25121986459927 -0.494750737306422
0.995367590043985 -0.0511993233294401 0.0813756104778135 -0.944300925088411 0.327693285372367 0.0302137981564153 0.148424585882925 0.506047270810245 -0.849638924491448
0.991613476781441 -0.127016034010182 0.0238671273878463 -0.357494436822097 -0.163558833763925 0.91948150364161 0.216483051632442 -0.972241757701029 -0.0887752946394405
0.585910442911322 0.161497863147955 -0.794120515467333 -0.0856103454963281 -0.404087038763322 0.910705514339015 0.992920002672369 -0.110148655080763 0.0444650658045476
0.667532055667499 0.738317082958943 -0.0963786266104705 -0.274641413158143 -0.902131529759339 0.332762373462766 -0.848377924744068 0.0644572818041603 -0.525452334307659
0.719131226940004 0.633882537501859 -0.284680886414891 -0.368747962290968 -0.92363604796573 0.104505460165994 -0.443454701750678 0.0759957467835468 -0.893069187670266
0.968094275400576 0.236773416581551 -0.0820476881876155 0.108313821993718 0.512433497755402 0.851868549920279 -0.756895695744459 -0.513035561502901 0.404849871430034
0.870077503803752 -0.451122000544921 -0.198630506214379 -0.102377480196255 -0.020892458315868 0.994526197108043 -0.141893697316575 -0.989249133803585 -0.0353882739150989
0.999627516123705 0.0261758190800336 -0.00772369754979942 -0.901448309891712 -0.0115885888359757 -0.432731613361176 0.413965587164152 0.269235414070789 -0.869565859756447
0.903174122860764 -0.418445409132979 0.0958120210110546 -0.681556061565631 0.4274122201749 -0.593969804778247 -0.702125371338306 -0.153284563866731 0.695358760211757
0.707962981557702 0.68586842083427 -0.168442649130896 -0.389440329781405 -0.897709193093757 0.206044738284446 -0.667548527805184 0.120968632530243 -0.734673773159825
0.489122174358057 0.696229957966802 -0.525379238437142 0.777174054077347 -0.215031454973226 0.591406766144148 -0.628581348446903 -0.22081562798268 0.745738524432853
0.484611616103657 -0.87393474720485 -0.0372778642815946 0.853425304892223 0.469308241247517 0.226748811831019 0.505719394616724 -0.640298096731891 -0.578157626629634
"""


def dietmaier_input():
    A = [tuple(Rational(v) for v in p) for p in DIET_A]
    B = [tuple(Rational(v) for v in p) for p in DIET_B]
    return A, B, [Rational(v) for v in DIET_L]


@functools.lru_cache(maxsize=1)
def dietmaier():
    return direct_kinematics(*dietmaier_input())


def float_legs(base, platform, mode):
    """The leg lengths at a mode's pose, in floating point (NumPy, from the geometry alone)."""
    A, B = np.array(base, float), np.array(platform, float)
    t = np.array([float(v) for v in mode.position])
    R = np.array([[float(mode.rotation[i, j]) for j in range(3)] for i in range(3)])
    return np.linalg.norm(t + B @ R.T - A, axis=1)


def test_dietmaier_40_real_modes_agree_with_phcpack():
    A, B, L = dietmaier_input()
    m = dietmaier()
    assert m.polynomial is None and m.complete and m.certified == 40
    assert len(m.modes) == 40  # Dietmaier 1998: all 40 real
    for mode in m.modes:
        assert np.max(np.abs(float_legs(A, B, mode) - np.array(L, float))) < 1e-9
        R = np.array(mode.rotation, float)
        assert np.allclose(R.T @ R, np.eye(3), atol=1e-14) and np.linalg.det(R) > 0
    # PHCpack's 40 (a mixed-volume homotopy on another formulation), matched one to one
    phc = np.array([row.split() for row in PHC_STEWGOU40.split("\n") if row.strip()], float)
    ours = np.array([
        [float(v) for v in (*mode.position, *mode.rotation[:, 0], *mode.rotation[:, 1])]
        for mode in m.modes
    ])
    D = np.linalg.norm(ours[:, None, :] - phc[None, :, :], axis=2)
    nearest = D.argmin(axis=1)
    assert sorted(nearest) == list(range(40))
    # PHCpack's equations carry coefficients rounded to 10 digits (0.2946372680 for
    # 0.542805**2 = 0.294637268025), which moves its ill-conditioned solutions (rco down to
    # 3e-6) by up to 3e-6; every other PHCpack solution is at least 0.29 away
    assert D[np.arange(40), nearest].max() < 1e-5
    assert np.sort(D, axis=1)[:, 1].min() > 0.1


def test_a_6_6_mode_refines_to_50_digits():
    A, B, L = dietmaier_input()
    for mode in dietmaier().modes[::13]:
        errs = mp_leg_errors(A, B, mode.evalf(50), [v**2 for v in L], dps=60)
        assert max(errs) < mpmath.mpf(10) ** -45


@pytest.mark.parametrize("seed", [3])
def test_a_random_6_6_from_a_known_pose(seed):
    rnd = random.Random(seed)
    A = [tuple(Rational(rnd.randint(-20, 20), 10) for _ in range(3)) for _ in range(6)]
    B = [tuple(Rational(rnd.randint(-20, 20), 10) for _ in range(3)) for _ in range(6)]
    pose = (Matrix([Rational(rnd.randint(-10, 10), 5) for _ in range(3)]),
            rotation_from_quaternion(*[rnd.randint(1, 5) for _ in range(4)]))
    lengths = leg_lengths(A, B, pose)
    m = direct_kinematics(A, B, lengths)
    assert m.complete and m.certified == 40
    assert [mode.contains(pose) for mode in m.modes].count(True) == 1
    for mode in m.modes:
        assert np.max(np.abs(float_legs(A, B, mode) - np.array([float(v) for v in lengths]))) < 1e-9


def test_the_6_6_checkers_reject_a_wrong_mode():
    from fractions import Fraction

    from screwsym.systems._homotopy import _chart_system, krawczyk, study_quadrics

    A, B, L = dietmaier_input()
    m = dietmaier()
    mode = m.modes[7]
    # Krawczyk's test proves the certified box, and refuses it moved by ten radii
    Q = study_quadrics(tuple(A), tuple(B), tuple(v**2 for v in L))
    system = _chart_system(Q, mode.chart)
    assert krawczyk(*system, list(mode.study), mode.radius)
    moved = [mode.study[0] + 10 * mode.radius, *mode.study[1:]]
    assert not krawczyk(*system, moved, mode.radius)
    # a box holding no solution at all is refused too
    assert not krawczyk(*system, [Fraction(1, 2)] * 8, Fraction(1, 100))
    # contains: a pose is in one mode's box, not in another's; a rational pose near none
    other = m.modes[8]
    exact = (Matrix([Rational(v) for v in mode.position]), Matrix(3, 3, [Rational(v) for v in mode.rotation]))
    assert not other.contains(exact)
    # ... inside this mode's box, but not the mode: it does not close the legs exactly
    assert not mode.contains(exact)
    assert not mode.contains((POSE[0], POSE[1]))
    assert not mode.contains((exact[0], -exact[1]))  # no rotation
    # the closure decided exactly: the floating-point centre of a box does not close
    assert not m.closes(mode.pose)
    with pytest.raises(ValueError, match="contains: pose\\[0\\]: expected exact rational"):
        mode.contains((Matrix([sqrt(2), 0, 0]), eye(3)))


def test_an_architecturally_singular_6_6_is_reported_incomplete():
    # a planar base and a planar platform whose points lie on parabolas, matched by the same
    # parameter: a design of the architecturally singular kind (Roeschel & Mick 1998): no
    # isolated non-singular mode is certified, and the answer says so instead of an empty list
    m = direct_kinematics([(i, i * i, 0) for i in range(6)], [(i, 1, i * i) for i in range(6)], [5] * 6)
    assert not m.complete and m.certified < 40
    with pytest.raises(ValueError, match="complex assembly modes were certified"):
        _ = m.modes


def test_6_6_bad_input_and_budget():
    A, B, L = dietmaier_input()
    with pytest.raises(ValueError, match="lengths\\[2\\]: expected a non-negative length"):
        direct_kinematics(A, B, [1, 1, -1, 1, 1, 1])
    with pytest.raises(ValueError, match="platform_points: expected 6 3-D points, got 5"):
        direct_kinematics(A, B[:5], L)
    with pytest.raises(ValueError, match="direct_kinematics: the case split needs more work"):
        direct_kinematics(A, B, L, budget=1000)


# --------------------------------------------------------------------------------------
# the published 3-RPR with six real assembly modes
# --------------------------------------------------------------------------------------
# Gosselin & Merlet, "The direct kinematics of planar parallel manipulators: special
# architectures and number of solutions", Mech. Mach. Theory 29(8) (1994), and Merlet,
# "Parallel Robots" (2nd ed., Springer 2006, the planar 3-RPR of the direct-kinematics
# chapter): base joints A1 = (0, 0), A2 = (15.91, 0), A3 = (0, 10); platform joints B1 at the
# platform's origin, B2 at 17.04 along its x axis, B3 at 20.84 from B1 at the angle
# theta = 0.882603 rad from B1B2; leg lengths 14.98, 15.38, 12: six real assembly modes.
# The same geometry is the one studied by Zein, Wenger & Chablat ("Non-singular
# assembly-mode changing motions for 3-RPR parallel manipulators", Mech. Mach. Theory 43
# (2008)), who give the platform by its sides 17.04, 16.54, 20.84.  The numbers were recalled
# from these publications and confirmed in a public MATLAB script of this direct kinematics
# (Gamma-0/3RPR_Plan on GitHub, MGD.m: the same base, sides, angle and leg lengths, six roots
# sought), which cites no source; the papers themselves were not at hand.  What this test
# compares with the publications: the geometry (the third side, 16.54, recomputed), the
# number of real modes (six), and that each mode closes the legs.  The published table of the
# six poses was not available (see the notes of issue 36), so the poses are checked
# independently instead: mpmath at 50 digits, and a NumPy scan of the closure residual over
# phi from the geometry alone.
#
# B3 = 20.84 (cos theta, sin theta) is irrational; it is taken to 6 decimals, the precision
# of the published theta (a second B3, the exact binary values of the floats, gives six
# modes too, at angles within 1e-6 rad).
GM_BASE = [(0, 0), (Rational("15.91"), 0), (0, 10)]
GM_B3 = (Rational("13.236375"), Rational("16.096707"))
GM_PLATFORM = [(0, 0), (Rational("17.04"), 0), GM_B3]
GM_LENGTHS = [Rational("14.98"), Rational("15.38"), 12]


def test_gosselin_merlet_1994_six_real_modes():
    # B3 is 20.84 (cos theta, sin theta) to 6 decimals
    with mpmath.workdps(30):
        th, l3 = mpmath.mpf("0.882603"), mpmath.mpf("20.84")
        assert [mpmath.nstr(l3 * f(th), 8) for f in (mpmath.cos, mpmath.sin)] == ["13.236375", "16.096707"]
    # the platform triangle of Zein, Wenger & Chablat: sides 17.04, 16.54, 20.84
    B2B3 = sqrt((GM_B3[0] - Rational("17.04")) ** 2 + GM_B3[1] ** 2)
    assert round(float(B2B3), 2) == 16.54
    m = direct_kinematics(GM_BASE, GM_PLATFORM, GM_LENGTHS)
    assert m.is_finite and m.polynomial.degree() == 6
    assert len(m.modes) == 6  # the published count: all six modes real
    for mode in m.modes:
        assert mode.multiplicity == 1
        assert m.closes(mode.pose)  # exact
        got = mp_lengths(GM_BASE, GM_PLATFORM, mode.pose)
        with mpmath.workdps(50):
            assert all(abs(g - L) < mpmath.mpf(10) ** -30 for g, L in zip(got, GM_LENGTHS, strict=True))
    # completeness from the geometry alone: six sign changes of the residual over phi
    angles = residual_scan(GM_BASE, GM_PLATFORM, [float(L) ** 2 for L in GM_LENGTHS])
    ours = sorted(float(mode.phi) for mode in m.modes)
    assert len(angles) == 6 and np.allclose(sorted(angles), ours, atol=1e-4)
    # the platform's angles, degrees, to 0.01 (computed here, not copied from the papers)
    assert [round(v * 180 / np.pi, 2) for v in ours] == [-56.55, -2.71, 14.06, 33.56, 57.41, 122.21]
    # the float data (B3 as the binary values of 20.84*cos, 20.84*sin) move them by < 1e-6
    b3 = tuple(20.84 * f(0.882603) for f in (np.cos, np.sin))
    m2 = direct_kinematics(GM_BASE, [(0, 0), (Rational("17.04"), 0), b3], GM_LENGTHS)
    assert len(m2.modes) == 6
    assert np.allclose(sorted(float(mode.phi) for mode in m2.modes), ours, atol=1e-6)


def test_gosselin_merlet_1994_the_checker_rejects_a_wrong_mode():
    m = direct_kinematics(GM_BASE, GM_PLATFORM, GM_LENGTHS)
    mode, other = m.modes[0], m.modes[4]
    eps = Rational(1, 10**30)
    assert not m.closes((mode.x, mode.y + eps, mode.phi))
    assert not m.closes((mode.x, mode.y, other.phi))  # one mode's position, another's angle
    # a mode of the legs 14.98, 15.38, 12.01 closes those legs, not these
    m3 = direct_kinematics(GM_BASE, GM_PLATFORM, GM_LENGTHS[:2] + [Rational("12.01")])
    assert m3.closes(m3.modes[0].pose) and not m.closes(m3.modes[0].pose)
