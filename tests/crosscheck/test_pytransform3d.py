"""Cross-check against an implementation nobody here wrote: pytransform3d.

pytransform3d writes a screw axis as (omega; v) with a unit omega, the same
ray order as the book, so pitch, axis direction and axis point must agree.
Floating-point comparison is right here: pytransform3d is numeric.
"""

import numpy as np
import pytest

pt = pytest.importorskip("pytransform3d.transformations")

from sympy import Rational  # noqa: E402

from screwsym import Screw, Twist, foot, pitch  # noqa: E402

#: each case draws from its own generator, seeded by the case's parameters, so that any
#: one case reruns alone (``pytest "...::test_screw_motion_twist_agrees[7]"``) with its numbers
SEED = 20261123


def case_rng(test: str, trial: int) -> np.random.Generator:
    return np.random.default_rng([SEED, sum(map(ord, test)), trial])


def random_rational_vector(rng, scale=10):
    return [Rational(int(n), 7) for n in rng.integers(-7 * scale, 7 * scale, size=3)]


@pytest.mark.parametrize("trial", range(40))
def test_pitch_axis_direction_and_point_agree(trial):
    rng = case_rng("pitch", trial)
    S, S0 = random_rational_vector(rng), random_rational_vector(rng)
    if all(c == 0 for c in S):
        S[0] = 1
    s = Screw(S, S0)
    norm = float(np.linalg.norm(np.array(S, dtype=float)))
    unit = np.array([float(c) for c in s.matrix]) / norm  # pytransform3d needs |omega| = 1
    q, s_axis, h = pt.screw_parameters_from_screw_axis(unit)
    np.testing.assert_allclose(float(pitch(s)), h, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(np.array(s.S, dtype=float).ravel() / norm, s_axis, rtol=1e-12)
    np.testing.assert_allclose(np.array(foot(s), dtype=float).ravel(), q, rtol=1e-10, atol=1e-10)


@pytest.mark.parametrize("trial", range(20))
def test_screw_motion_twist_agrees(trial):
    rng = case_rng("screw motion", trial)
    r = random_rational_vector(rng)
    d = np.array(random_rational_vector(rng), dtype=float)
    while np.linalg.norm(d) == 0:
        d = np.array(random_rational_vector(rng), dtype=float)
    S = d / np.linalg.norm(d)
    h = Rational(int(rng.integers(-30, 30)), 11)
    omega = Rational(int(rng.integers(1, 20)), 3)
    T = Twist.from_axis(r, S.tolist(), h, magnitude=omega)
    expected = float(omega) * pt.screw_axis_from_screw_parameters(
        np.array(r, dtype=float), S, float(h)
    )
    np.testing.assert_allclose(np.array(T.matrix, dtype=float).ravel(), expected, atol=1e-10)


def test_pure_translation_agrees():
    q, s_axis, h = pt.screw_parameters_from_screw_axis(np.array([0, 0, 0, 0, 0, 1.0]))
    assert h == np.inf and pitch(Twist.translation([0, 0, 1])).is_infinite
