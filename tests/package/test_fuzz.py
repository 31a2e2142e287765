"""A seeded, bounded fuzz of the public API: bad input is refused clearly, nothing runs, numbers hold.

Each test draws a fixed number of cases from a seeded generator (the same
cases on every run) and checks one promise of issue 20:

* constructors and operations given hostile values (strings, containers of
  strings, NaN, infinities, huge integers, booleans, None, complex numbers,
  wrong shapes) raise ``TypeError`` or ``ValueError`` and nothing else, and no
  string is evaluated;
* the generated numeric functions given hostile arrays do the same;
* float rotations at random angles, many of them near 0 (down to 1e-11) and
  near a half-turn (to 1e-15), survive ``exp6(log6(T))`` to a few ulps;
* ``numeric.pitch`` and ``numeric.foot`` of random screws at random scales
  from 1e-300 to 1e300 are scale-invariant as they must be;
* ``tidy`` of random powers of sums returns (``max_size`` bounds its work).
"""

from __future__ import annotations

import math
import sys
import types

import numpy as np
import pytest
from sympy import Float, ImmutableMatrix, Symbol, symbols

import screwsym
from screwsym import (
    Chain,
    LineVector,
    Screw,
    ScrewSystem,
    Transform,
    Twist,
    Wrench,
    exp6,
    log6,
    numeric,
    pitch,
    tidy,
    unit,
)
from screwsym.systems.joints import Cylindrical, Helical, Prismatic, Revolute, Spherical, Universal

TRACE = types.ModuleType("fuzz_trace")
PAYLOAD = "__import__('sys').modules['fuzz_trace'].__setattr__('ran', 1)"
x = Symbol("x", real=True)


@pytest.fixture(autouse=True)
def _trace(monkeypatch):
    monkeypatch.setitem(sys.modules, "fuzz_trace", TRACE)
    TRACE.__dict__.pop("ran", None)
    yield
    assert "ran" not in TRACE.__dict__, "a string was evaluated"


def _hostile(rng: np.random.Generator):
    """One hostile scalar, vector or container."""
    atoms = [PAYLOAD, (PAYLOAD,), {x: PAYLOAD}, [PAYLOAD], {PAYLOAD}, np.array([PAYLOAD]),
             float("nan"), float("inf"), -float("inf"), 10**400, True, None, 1 + 2j,
             np.array([1.0, 2.0]), np.zeros((3, 1, 1)), Symbol("z"), b"1", object()]
    k = int(rng.integers(len(atoms)))
    if rng.random() < 0.5:  # inside a 3-vector
        v = [1, 2, 3]
        v[int(rng.integers(3))] = atoms[k]
        return v
    return atoms[k]


CALLS = {
    "Screw": lambda a, b: Screw(a, b),
    "LineVector": lambda a, b: LineVector(a, b),
    "Twist": lambda a, b: Twist(a, b),
    "Wrench": lambda a, b: Wrench(a, b),
    "Twist.rotation": lambda a, b: Twist.rotation(a, point=b),
    "Transform.rotation": lambda a, b: Transform.rotation(a, b),
    "Transform.translation": lambda a, b: Transform.translation(a),
    "Transform.apply": lambda a, b: Transform.translation([1, 0, 0]).apply(a, direction=b),
    "exp6": lambda a, b: exp6(Twist.rotation([0, 0, 1], point=[0, 0, 0]), a),
    "pitch": lambda a, b: pitch(a),
    "unit": lambda a, b: unit(a),
    "Screw * k": lambda a, b: Screw([1, 0, 0], [0, 0, 0]) * a,
    "Screw.subs": lambda a, b: Screw([x, 0, 0], [0, 0, 0]).subs(x, a),
    "Screw.refine": lambda a, b: Screw([x, 0, 0], [0, 0, 0]).refine(a),
    "Revolute": lambda a, b: Revolute(a, b),
    "Prismatic": lambda a, b: Prismatic(a),
    "Helical": lambda a, b: Helical([0, 0, 0], [0, 0, 1], a),
    "Cylindrical": lambda a, b: Cylindrical(a, b),
    "Universal": lambda a, b: Universal([0, 0, 0], a, b),
    "Spherical": lambda a, b: Spherical(a),
    "ScrewSystem": lambda a, b: ScrewSystem(Screw([1, 0, 0], [0, 0, 0]), a),
    "Chain": lambda a, b: Chain([a]),
    "tidy": lambda a, b: tidy(a),
}


def test_fuzz_the_symbolic_api_refuses_hostile_values_clearly():
    rng = np.random.default_rng(20)
    unexpected = []
    for _ in range(8):
        for name, call in CALLS.items():
            a, b = _hostile(rng), _hostile(rng)
            try:
                call(a, b)
            except (TypeError, ValueError):
                pass
            except Exception as exc:  # noqa: BLE001 - the point: no other exception
                unexpected.append(f"{name}({a!r:.40}, {b!r:.40}): {type(exc).__name__}: {exc}")
    assert unexpected == []


def test_fuzz_the_generated_functions_refuse_hostile_arrays_clearly():
    rng = np.random.default_rng(21)
    f = numeric.functions_for("numpy")
    hostile = [np.array([PAYLOAD] * 6), [1, 2, 3, 4, 5, 10**400], np.zeros((2, 1)),
               np.zeros((4, 5)), np.zeros(6, dtype=complex), None, True, PAYLOAD,
               [[1, 2], [3]], np.array([object()] * 6), np.zeros(6, dtype=bool)]
    outs = [None, (np.empty(()),), np.empty(3), np.empty((), dtype=np.float32), [np.empty(())]]
    unexpected = []
    for _ in range(40):
        s = hostile[int(rng.integers(len(hostile)))]
        out = outs[int(rng.integers(len(outs)))]
        for name in ("pitch", "foot", "reciprocal_product"):
            fn = getattr(f, name)
            args = (s, s) if name == "reciprocal_product" else (s,)
            try:
                fn(*args, out=out)
            except (TypeError, ValueError):
                pass
            except Exception as exc:  # noqa: BLE001
                unexpected.append(f"{name}({s!r:.40}, out={out!r:.30}): {type(exc).__name__}")
    assert unexpected == []


def test_fuzz_float_rotations_survive_log6_and_exp6_at_every_angle():
    rng = np.random.default_rng(22)
    worst = 0.0
    for _ in range(30):
        axis = rng.standard_normal(3)
        kind = rng.integers(3)
        # a third near 0, a third near a half-turn, a third anywhere; a turn below the float
        # policy's 2^-40 relative tolerance (9e-13) is the identity, by that policy
        angle = (10.0 ** -rng.uniform(1, 11) if kind == 0 else
                 math.pi - 10.0 ** -rng.uniform(1, 15) if kind == 1 else rng.uniform(0, math.pi))
        point = rng.standard_normal(3)
        T = Transform.rotation([Float(a) for a in axis], Float(angle),
                               point=[Float(p) for p in point])
        twist, theta = log6(T)
        back = exp6(twist, theta)
        err = max(abs(float(u - v)) for u, v in zip([*back.R, *back.p], [*T.R, *T.p], strict=True))
        worst = max(worst, err)
        assert abs(float(theta) - angle) <= 1e-15 * max(1.0, angle) * 8, (angle, theta)
    assert worst < 1e-14


def test_fuzz_numeric_pitch_and_foot_are_scale_invariant():
    rng = np.random.default_rng(23)
    f = numeric.functions_for("numpy")
    s = rng.integers(-9, 10, size=(50, 6)).astype(float)
    s[:, 0] += (s[:, :3] == 0).all(axis=1)  # no couples: a finite pitch
    ref_h, ref_P = f.pitch(s), f.foot(s)
    for j in rng.integers(-300, 301, size=6):
        k = 10.0 ** float(j)
        # one scale for the screw: pitch and foot unchanged (they are of degree 0)
        np.testing.assert_allclose(f.pitch(s * k), ref_h, rtol=1e-14, atol=1e-300)
        np.testing.assert_allclose(f.foot(s * k), ref_P, rtol=1e-13, atol=1e-13)


def test_fuzz_tidy_of_large_powers_returns():
    rng = np.random.default_rng(24)
    gens = symbols("a b c d e", real=True)
    for _ in range(6):
        k = int(rng.integers(4, 6))
        n = int(rng.integers(40, 80))  # at least C(43, 3) = 12341 terms expanded
        base = sum(gens[:k])
        e = base**n + 1
        assert tidy(e) == e  # too many terms to expand: as given (never a minute)
    assert tidy(ImmutableMatrix([gens[0] ** 2 / gens[0]])) == ImmutableMatrix([gens[0]])
    assert screwsym.tidy is tidy
