"""Random exact rigid motions and twists for the tests (seeded, rational).

A rotation from a quaternion with integer components ``(a, b, c, d)`` is
``R = (1/n) [...]`` with ``n = a^2 + b^2 + c^2 + d^2``: its entries are
rational and it is exactly orthonormal with determinant 1, so the symbolic
layer sees exact values.
"""

from __future__ import annotations

import numpy as np
from sympy import ImmutableMatrix, Rational

from screwsym import Transform, Twist


def rational_vector(rng: np.random.Generator, scale: int = 5, den: int = 7) -> list[Rational]:
    return [Rational(int(n), den) for n in rng.integers(-scale * den, scale * den + 1, size=3)]


def quaternion_rotation(a: int, b: int, c: int, d: int) -> ImmutableMatrix:
    """The exact rotation of the (unnormalised) quaternion ``a + b i + c j + d k``."""
    n = a * a + b * b + c * c + d * d
    return ImmutableMatrix(
        [
            [a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
            [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
            [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d],
        ]
    ) / n


def random_rotation(rng: np.random.Generator) -> ImmutableMatrix:
    while True:
        a, b, c, d = (int(x) for x in rng.integers(-9, 10, size=4))
        if a * a + b * b + c * c + d * d:
            return quaternion_rotation(a, b, c, d)


def random_transform(rng: np.random.Generator) -> Transform:
    return Transform(random_rotation(rng), rational_vector(rng))


def random_twist(rng: np.random.Generator) -> Twist:
    """A twist with a rational, generally non-unit, non-zero ``omega``."""
    while True:
        omega = rational_vector(rng, scale=2, den=3)
        if any(omega):
            return Twist(omega, rational_vector(rng))


def to_float(m) -> np.ndarray:
    return np.array(m.evalf(), dtype=float)
