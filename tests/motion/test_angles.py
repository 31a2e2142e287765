"""The angle rule (screwsym.motion.angles): a decimal is k pi/12 when it prints k pi/12 to its
own precision (four places or more), a float when it is within 4 ulps; from_dh and
Transform.from_matrix with angles="pi/12"."""

from __future__ import annotations

import math
import random
import warnings

import mpmath
import numpy as np
import pytest
from sympy import Float, ImmutableMatrix, Rational, cos, pi, sin, sqrt

from screwsym import Chain, Transform
from screwsym.motion.angles import (
    MIN_PLACES,
    RecognisedAngle,
    RecognisedAngleWarning,
    angle_step,
    recognise_decimal,
    recognise_float,
    recognise_trig_float,
)


def _round(k: int, places: int) -> str:
    with mpmath.workdps(80):
        scaled = mpmath.nint(mpmath.mpf(k) * mpmath.pi / 12 * mpmath.mpf(10) ** places)
    digits = str(abs(int(scaled))).rjust(places + 1, "0")
    sign = "-" if scaled < 0 else ""
    return f"{sign}{digits[:-places]}.{digits[-places:]}"


def test_every_multiple_in_every_printing_a_program_makes():
    """pi/12 .. 4 pi both signs: printed by %f to 4..12 places, repr of the double (and of
    k*math.pi/12, an ulp or two away), %.17g, %.20f (the double's exact digits), %e, and
    numpy.float32 printed."""
    for k in range(-48, 49):
        if k == 0:
            continue
        v, want = k * math.pi / 12, k * pi / 12
        texts = [_round(k, d) for d in range(MIN_PLACES, 13)]
        texts += [repr(v), repr(k / 12 * math.pi), repr(math.radians(15 * k)), f"{v:.17g}",
                  f"{v:.20f}", f"{v:e}", str(np.float32(v)), f"{np.float32(v):.9g}"]
        for text in texts:
            assert recognise_decimal(text) == want, (k, text)
        for value in (v, k / 12 * math.pi, math.radians(15 * k), float(np.float32(v)), np.float32(v)):
            assert recognise_float(value) == want, (k, value)


def test_the_rule_is_the_rounding_to_the_printed_places():
    """Against an independent oracle: a decimal of d >= 4 places is recognised exactly when it
    is the rounding of some k pi/12 to d places (the neighbours one unit off are not, checked
    at 4 and 5 places: from 7 significant digits on, the single-float window of 4 ulps is
    wider than half a unit of the last place, and a neighbour is a float32 printing)."""
    rng = random.Random(33)
    for _ in range(300):
        k, d = rng.choice([i for i in range(-30, 31) if i]), rng.randint(MIN_PLACES, 14)
        text = _round(k, d)
        unit = Rational(1, 10**d)
        assert recognise_decimal(text) == k * pi / 12
        for off in (-unit, unit):  # one unit in the last place off: not a printing of it
            neighbour = Rational(text) + off
            digits = f"{float(neighbour):.{d}f}" if d <= 5 else None
            if digits is not None and Rational(digits) == neighbour:
                assert recognise_decimal(digits) is None, (text, digits)
    # decimals chosen without pi in mind: one in a few thousand at four places, none at six
    hits4 = sum(recognise_decimal(f"{rng.uniform(-4, 4):.4f}") is not None for _ in range(4000))
    hits6 = sum(recognise_decimal(f"{rng.uniform(-4, 4):.6f}") is not None for _ in range(4000))
    assert hits4 <= 8 and hits6 <= 1


def test_what_is_not_recognised():
    """Too few places (1.57 is round(pi/2, 2); 0.5 rounds pi/6 to one place), a near miss at
    four places, zero (exact already), lengths of no angle, non-decimals."""
    for text in ("1.57", "3.14", "0.5", "1", "0.785", "1.5709", "1.5707", "0.0000", "0", "2.0000",
                 "1.5708x", "", "pi", "1e5", "١.٥٧٠٨", "1" * 401, "1e-13", "-4e-15", "0.0001"):
        assert recognise_decimal(text) is None, text
    # float noise around a multiple (an exporter's zero, so101.urdf) is that multiple
    for text, value in (("-5.19179e-17", 0), ("2.35221e-33", 0), ("-2.55351e-15", 0),
                        ("3.5e-15", 0), (repr(math.pi / 2 + 2e-15), pi / 2)):
        assert recognise_decimal(text) == value, text
    assert recognise_decimal("15708e-4000") == 0 and recognise_decimal("1e-99999999") == 0  # at once
    assert recognise_decimal("15708e-4") == pi / 2 and recognise_decimal("+.7854") == pi / 4
    assert recognise_float(-5.19179e-17) == 0
    for value in (1.5708, 0.0, 1.5707963267948966 + 1e-12, float("nan"), float("inf"), 1e300, 1e-13):
        assert recognise_float(value) is None, value
    assert recognise_decimal("0.7854", 4) == pi / 4 and recognise_decimal("0.2618", 4) is None


def test_trig_values_of_a_rotation_written_in_floats():
    for k in range(24):
        for f in (cos, sin):
            exact = f(k * pi / 12)
            for x in (float(exact), float(np.float32(float(exact))), getattr(np, f.__name__)(k * np.pi / 12)):
                assert (recognise_trig_float(x) - exact).equals(0), (k, f, x)
    assert recognise_trig_float(0.7071) is None and recognise_trig_float(0.3) is None


def test_angle_step_errors():
    assert angle_step("pi / 12") == 12 and angle_step("exact") is None
    with pytest.raises(TypeError, match="angles: expected 'exact' or 'pi/N' \\(a str\\), got int"):
        angle_step(12)
    for bad in ("pi/0", "pi/１２", "tau/12", "pi/12.0"):
        with pytest.raises(ValueError, match="angles: expected 'exact' or 'pi/N'"):
            angle_step(bad)


def test_from_dh_with_float_angles():
    """The Puma-like table written with numpy floats: with angles="pi/12" the chain equals the
    exact table's, and the recognised values are listed and warned; by default floats stay."""
    a2, d3 = 0.4318, 0.15005
    floats = [(0, -np.pi / 2, 0, 0), (a2, 0.0, 0, 0), (0, np.pi / 2, d3, np.pi / 4)]
    exact = [(0, -pi / 2, 0, 0), (a2, 0, 0, 0), (0, pi / 2, d3, pi / 4)]
    with pytest.warns(RecognisedAngleWarning, match=r"rows\[0\]\[1\] \(alpha\): -1\.5707963267948966 -> -pi/2"):
        chain = Chain.from_dh(floats, angles="pi/12")
    assert chain == Chain.from_dh(exact)
    assert chain.recognised == (RecognisedAngle(repr(-np.pi / 2), "rows[0][1] (alpha)", -pi / 2),
                                RecognisedAngle(repr(np.pi / 2), "rows[2][1] (alpha)", pi / 2),
                                RecognisedAngle(repr(np.pi / 4), "rows[2][3] (theta)", pi / 4))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        plain = Chain.from_dh(floats)
    assert plain != chain and plain.recognised == ()
    assert plain.home.R[0, 0].has(Float)
    # a float that is not a multiple stays a float
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        odd = Chain.from_dh([(0, 1.5708, 0, 0)], angles="pi/12")
    assert odd.recognised == () and odd.home.R[1, 1] == cos(Float(1.5708))


def test_from_matrix_with_a_float_rotation():
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    M = [[c, -s, 0, 0.1], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    with pytest.warns(RecognisedAngleWarning, match=r"M\[:3, :3\]\[0, 0\]: 0\.866025403784438\d* -> sqrt\(3\)/2"):
        T = Transform.from_matrix(M, angles="pi/12")
    assert T.R == ImmutableMatrix([[sqrt(3) / 2, -Rational(1, 2), 0], [Rational(1, 2), sqrt(3) / 2, 0], [0, 0, 1]])
    assert T.p[0] == Float(0.1)  # the translation as given
    # float32 too, and a rotation about a 15-degree multiple on another axis
    M32 = np.array(Transform.rotation([1, 0, 0], pi / 12).matrix.evalf(), dtype=np.float32)
    with pytest.warns(RecognisedAngleWarning):
        assert Transform.from_matrix(M32, angles="pi/12").R == Transform.rotation([1, 0, 0], pi / 12).R
    # all or nothing: one entry that is no sine/cosine keeps the floats (no warning)
    r = Transform.rotation([0, 0, 1], Rational(1, 10)).matrix.evalf()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        kept = Transform.from_matrix(r, angles="pi/12")
        assert kept.R[0, 0] == Float(math.cos(0.1)) or kept.R[0, 0].has(Float)
        assert Transform.from_matrix(M).R[0, 0] == Float(c)  # default: as given
