r"""Mechanisms to move in a view: Clavel's Delta robot with its parallelograms, posed by its platform,
and a rigid 3-RPS posed by its platform's height and tilt.

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

The geometry (lengths in any unit), Clavel's: the legs 120 degrees apart, on the
radial directions ``e_i = (cos 2 pi k/3, sin 2 pi k/3, 0)``, ``k = 0, 1, 2`` (exact:
``(1, 0)`` and ``(-1/2, +-sqrt(3)/2)``); the base pivots at ``radius * e_i`` with
the arm's axis tangent to the base circle (``u_i = z x e_i``), arms of length
``sqrt(2)``, rods of length ``2 sqrt(2)``, ``2 w = 1`` apart, and the platform's
pivots at ``p + e_i``.  With the arm at angle ``theta`` below the base plane the
elbow is ``radius e_i + sqrt(2) (cos theta e_i - sin theta z)``; the rod's
length fixes ``theta``: ``A cos theta + B sin theta = C`` with
``d = p + e_i - radius e_i``, ``A = 2 L d.e_i``, ``B = -2 L d.z``,
``C = |d|^2 + L^2 - l^2`` (the Delta's inverse kinematics, Clavel 1991), of
which the branch with the elbow out is taken.  The home pose ``p = (0, 0, -3)``
has ``theta = pi/4`` on every leg: exactly, as the second example checks (the
rods' lengths there, in SymPy).  A view draws the platform (the link named
``"platform"``) as a solid triangle through its three pivots.

>>> import numpy as np
>>> d = delta()
>>> rows = d.configurations([[0, 0, -3], [0.3, 0.2, -2.8]])
>>> np.allclose(rows[0, 3:], np.pi / 4)
True
>>> len(d.mechanism.joints), d.variables
(21, (x, y, z, theta1, theta2, theta3))

The home pose is exact: each rod (elbow to the platform's pivot) is ``2 sqrt(2)`` long at
``theta = pi/4``, ``p = (0, 0, -3)``:

>>> from sympy import pi
>>> home = dict(zip(d.variables, (0, 0, -3, pi / 4, pi / 4, pi / 4)))
>>> rods = [j.args[0].subs(home) - k.args[0].subs(home) for (a, b, j), (c, e, k)
...         in zip(d.mechanism.joints[2::7], d.mechanism.joints[3::7])]
>>> [r.dot(r) for r in rods]
[8, 8, 8]

:func:`three_rps` builds Tsai's 3-RPS (Lee & Shah 1988; Tsai 1999) as a
:class:`~screwsym.systems.parallel.ParallelMechanism` with a **rigid** platform
at a pose given by its height and its tilt, exactly (see its docstring).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from sympy import Expr, Matrix, Rational, Symbol, cancel, cos, eye, sin, sqrt, symbols

from ..core.checks import check_exact, check_scalar, check_sequence
from ..systems.joints import P, R, S
from ..systems.linkage import Mechanism
from ..systems.parallel import Limb, ParallelMechanism

__all__ = ["Delta", "delta", "three_rps"]

#: the Delta's unit radial directions, 120 degrees apart (Clavel's geometry), exact:
#: (cos, sin) of 0, 2 pi/3 and 4 pi/3
_RADIAL = ((1, 0), (Rational(-1, 2), sqrt(3) / 2), (Rational(-1, 2), -sqrt(3) / 2))


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


def _positive(value: Any, name: str) -> Expr:
    v = check_exact(check_scalar(value, name), name)
    if not (v.is_number and v.is_positive):
        raise ValueError(f"{name}: expected an exact positive length, got {value!r}")
    return v


def three_rps(height: Any, tilt: Any, *, base: Any = 2, platform: Any = 1) -> ParallelMechanism:
    r"""Tsai's 3-RPS with a rigid platform at height ``height``, tilted by ``tilt = (gx, gy)``.

    The legs 120 degrees apart, on ``e_i = (cos 2 pi k/3, sin 2 pi k/3, 0)``: each an R joint
    at ``base * e_i`` about ``u_i = z x e_i`` (tangent to the base circle), an actuated P
    along the leg, and an S at the platform's pivot ``c + platform * Rot e_i``.  The platform
    is an equilateral triangle (side ``sqrt(3) platform``) turned by ``Rot`` about a
    **horizontal** axis: ``tilt`` is that rotation's Rodrigues (Gibbs) vector
    ``(gx, gy, 0) = tan(theta/2) * axis``, so that ``Rot = ((1 - g.g) I + 2 g g^T + 2 [g]x)
    / (1 + g.g)`` is rational in ``gx, gy`` (``g = (0, 1/2)``: a turn about ``y`` with
    ``cos theta = 3/5, sin theta = 4/5``).  The rest of the pose follows from the legs'
    constraints (each pivot in its R joint's plane, ``u_i . (pivot_i - base e_i) = 0``): no
    spin about the platform's normal (Euler angles ``(phi, theta, -phi)``), and the centre
    ``c = (platform (gx^2 - gy^2), -2 platform gx gy, height (1 + g.g)) / (1 + g.g)``, the
    3-RPS's parasitic motion (K.-M. Lee, D. K. Shah, IEEE J. Robot. Autom. 4(3), 1988;
    L.-W. Tsai, Robot Analysis, Wiley 1999).

    ``height``, ``gx``, ``gy``: exact numbers or symbols (a view along a path of the tilt takes
    them as its ``variables``); ``base``, ``platform``: exact positive radii.  Floats are
    refused (``ValueError``): the mechanism's screw systems decide ranks exactly.

    >>> from sympy import Rational, symbols
    >>> m = three_rps(2, (0, 0))
    >>> m.limbs[0].joints[2].args[0].T                   # leg 1's sphere, above the base
    Matrix([[1, 0, 2]])
    >>> print(m.singularities())
    Singularities: none (regular)

    At height 44/15 and tilt ``(0, 1/2)`` leg 1 lies in the platform's plane and the actuation
    wrenches fall into a five-system with the constraints (type II):

    >>> print(three_rps(Rational(44, 15), (0, Rational(1, 2))).singularities().rows())
    [('actuation', '', True, 5)]
    >>> three_rps(2, (0.1, 0))
    Traceback (most recent call last):
    ...
    ValueError: tilt[0]: expected exact entries (integers, rationals, algebraic numbers, symbols), got the float 0.100000000000000; screw systems decide ranks exactly (use Rational, or screwsym.numeric.mobility for floating point)
    """
    z = check_exact(check_scalar(height, "height"), "height")
    gx, gy = (check_exact(check_scalar(g, f"tilt[{k}]"), f"tilt[{k}]")
              for k, g in enumerate(check_sequence(tilt, "tilt", "numbers", 2)))
    b, a = _positive(base, "base"), _positive(platform, "platform")
    g = Matrix([gx, gy, 0])
    gg = gx**2 + gy**2
    skew = Matrix([[0, 0, gy], [0, 0, -gx], [-gy, gx, 0]])
    rot = ((1 - gg) * eye(3) + 2 * g * g.T + 2 * skew) / (1 + gg)
    centre = Matrix([a * (gx**2 - gy**2) / (1 + gg), -2 * a * gx * gy / (1 + gg), z])
    limbs = []
    for ex, ey in _RADIAL:
        e = Matrix([ex, ey, 0])
        pivot = (centre + a * rot * e).applyfunc(cancel)
        foot = b * e
        limbs.append(Limb(R(foot, [-ey, ex, 0]), P(pivot - foot), S(pivot), actuated=1))
    return ParallelMechanism(*limbs)
