r"""Mechanisms to move in a view: Clavel's Delta robot with its parallelograms, posed by its platform.

:func:`delta` builds the Delta robot of notebook 11 as a graph
:class:`~screwsym.systems.linkage.Mechanism` (17 links, 21 revolutes: on each leg
an arm turning on the base, then a parallelogram of four revolutes whose rods join
the arm's end to the platform), with its joints placed by **symbols**: the
platform's centre ``x, y, z`` and the arms' angles ``theta1..3``.  The
:class:`Delta` it returns also solves the Delta's inverse kinematics in floats
(:meth:`Delta.configurations`: one row of ``(x, y, z, theta1, theta2, theta3)``
per platform position, each leg's angle in closed form), so that
``view(d.mechanism, path=d.configurations(points), variables=d.variables)``
draws the Delta moving along a platform path, every frame precomputed.

The geometry (lengths in any unit): the base pivots at ``radius * e_i`` with
the arm's axis tangent to the base circle (``u_i = z x e_i``), arms of length
``sqrt(2)``, rods of length ``2 sqrt(2)``, ``2 w = 1`` apart, and the platform's
pivots at ``p + e_i``.  With the arm at angle ``theta`` below the base plane the
elbow is ``radius e_i + sqrt(2) (cos theta e_i - sin theta z)``; the rod's
length fixes ``theta``: ``A cos theta + B sin theta = C`` with
``d = p + e_i - radius e_i``, ``A = 2 L d.e_i``, ``B = -2 L d.z``,
``C = |d|^2 + L^2 - l^2`` (the Delta's inverse kinematics, Clavel 1991), of
which the branch with the elbow out is taken.  The home pose ``p = (0, 0, -3)``
has ``theta = pi/4`` on every leg (the placement of notebook 11).

>>> import numpy as np
>>> d = delta()
>>> rows = d.configurations([[0, 0, -3], [0.3, 0.2, -2.8]])
>>> np.allclose(rows[0, 3:], np.pi / 4)
True
>>> len(d.mechanism.joints), d.variables
(21, (x, y, z, theta1, theta2, theta3))
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from sympy import Matrix, Rational, Symbol, cos, sin, sqrt, symbols

from ..systems.joints import R
from ..systems.linkage import Mechanism

__all__ = ["Delta", "delta"]

#: the Delta's unit radial directions (exact, Pythagorean)
_RADIAL = ((1, 0), (Rational(-3, 5), Rational(4, 5)), (Rational(-3, 5), Rational(-4, 5)))


@dataclass(frozen=True)
class Delta:
    """A Delta robot placed by symbols, and its inverse kinematics in floats."""

    mechanism: Mechanism
    variables: tuple[Symbol, ...]
    radius: float
    arm: float
    rod: float

    def configurations(self, points: Any) -> np.ndarray:
        """Rows ``(x, y, z, theta1, theta2, theta3)`` placing the platform at ``points``.

        ``points``: an array of shape ``(k, 3)`` (or one point).  ``ValueError`` naming
        the first point the platform cannot reach.
        """
        try:
            p = np.array(points, dtype=float)
        except (TypeError, ValueError) as exc:
            raise TypeError(f"points: expected numbers, got {points!r}") from exc
        if p.ndim == 1:
            p = p[None, :]
        if p.ndim != 2 or p.shape[1] != 3 or not np.all(np.isfinite(p)):
            raise ValueError(f"points: expected finite points of shape (k, 3), got {p.shape}")
        out = np.empty((len(p), 6))
        for k, c in enumerate(p):
            out[k, :3] = c
            for i, (ex, ey) in enumerate(_RADIAL):
                e = np.array([float(ex), float(ey), 0.0])
                dv = c + e - self.radius * e
                A, B = 2 * self.arm * float(dv @ e), -2 * self.arm * float(dv[2])
                C = float(dv @ dv) + self.arm**2 - self.rod**2
                r = math.hypot(A, B)
                if r == 0 or abs(C) > r:
                    raise ValueError(f"points[{k}]: the platform cannot reach {c.tolist()} "
                                     f"(leg {i + 1})")
                phi, spread = math.atan2(B, A), math.acos(C / r)
                # the two branches: the one nearer pi/4 (elbow out, as at home)
                out[k, 3 + i] = min((phi + spread, phi - spread),
                                    key=lambda t: abs(math.remainder(t - math.pi / 4, 2 * math.pi)))
        return out


def delta() -> Delta:
    """Clavel's Delta as a :class:`~screwsym.systems.linkage.Mechanism` placed by symbols.

    See the module's docstring: base radius 2, arms ``sqrt(2)``, rods ``2 sqrt(2)``, each
    parallelogram's rods 1 apart.
    """
    radius, w = 2, Rational(1, 2)
    x, y, z, *thetas = symbols("x y z theta1:4", real=True)
    p = Matrix([x, y, z])
    L = sqrt(2)
    triples = []
    for i, ((ex, ey), th) in enumerate(zip(_RADIAL, thetas, strict=True), start=1):
        e = Matrix([ex, ey, 0])
        u = Matrix([-ey, ex, 0])                      # the arm's axis, tangent to the base circle
        b = radius * e
        elbow = b + L * (cos(th) * e - sin(th) * Matrix([0, 0, 1]))
        attach = p + e                                # the platform's pivot of this leg
        n = u.cross(attach - elbow)                   # the parallelogram's axes: normal to its plane
        arm, upper, r1, r2, lower = (f"{name}{i}" for name in ("arm", "upper", "rodA", "rodB",
                                                               "lower"))
        triples += [("base", arm, R(b, u)), (arm, upper, R(elbow, u)),
                    (upper, r1, R(elbow + w * u, n)), (r1, lower, R(attach + w * u, n)),
                    (upper, r2, R(elbow - w * u, n)), (r2, lower, R(attach - w * u, n)),
                    (lower, "platform", R(attach, u))]
    return Delta(Mechanism(triples, base="base"), (x, y, z, *thetas), float(radius),
                 math.sqrt(2), 2 * math.sqrt(2))
