"""The inverse kinematics of parallel mechanisms limb by limb (issue 36, item 3).

Each limb's branches are round-tripped through the limb's own forward kinematics, the
product of exponentials of ``screwsym.Chain`` (a separate implementation: Rodrigues'
formula on the joint twists): ``Chain(twists).forward(q) == pose``.  The planar poses are
built so that every joint value has a rational cosine and sine (Pythagorean angles), so the
round trip is decided exactly (``expand_trig`` and ``expand`` to an exact zero); the
Gough-Stewart legs' values are nested radicals whose exact decision (minimal polynomials)
takes minutes, so they are checked at 50 digits.  Sources: the 3-RPR and 3-RRR (Gosselin &
Angeles 1990; Merlet, Parallel Robots, 2006, Chapter 4: two branches per leg, the 3-RRR's
``2**3`` elbow combinations), the U-P-S Gough-Stewart leg (Merlet 2006, Chapter 4: the leg
length, then the universal joint's two angles and the spherical joint's three).
"""

from __future__ import annotations

import itertools

import pytest
from sympy import Matrix, Rational, S, atan2, cos, expand, expand_trig, eye, sin

from screwsym import Chain, Transform
from screwsym.systems import (
    Limb,
    LimbBranch,
    ParallelMechanism,
    Prismatic,
    Revolute,
    Spherical,
    Universal,
    limb_joint_values,
)


def twists(limb):
    return [t for j in limb.joints for t in j.twists.args]


def round_trip_exact(limb, values, T):
    F = Chain(twists(limb)).forward(list(values), form="product").matrix
    return all(expand(expand_trig(e)) == 0 for e in (F - T))


def round_trip_digits(limb, values, T, n=50):
    F = Chain(twists(limb)).forward([v.evalf(n + 10) for v in values], form="product").matrix
    return max(abs((e).evalf(n)) for e in (F - T))


def same_angle(x, y):
    """Whether the angles ``x`` and ``y`` are equal modulo 2 pi, exactly."""
    return expand(expand_trig(cos(x - y))) == 1 and expand(expand_trig(sin(x - y))) == 0


def rot(c, s):
    return Matrix([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])


def planar(c, s, x, y):
    T = rot(c, s)
    T[0, 3], T[1, 3] = x, y
    return T


def about(p, c, s):
    """The planar rotation with cosine ``c`` and sine ``s`` about the point ``p``."""
    return planar(1, 0, *p) * rot(c, s) * planar(1, 0, -p[0], -p[1])


def fixed_point(G):
    """The fixed point of a planar rigid motion that turns (exact)."""
    A = Matrix([[G[0, 0] - 1, G[0, 1]], [G[1, 0], G[1, 1] - 1]])
    return list(A.solve(-Matrix([G[0, 3], G[1, 3]])))


# Pythagorean angles: cosine and sine rational
P345, P51213, P81517 = (Rational(3, 5), Rational(4, 5)), (Rational(5, 13), Rational(12, 13)), (Rational(8, 17), Rational(15, 17))
POSE = planar(*P51213, Rational(1, 2), Rational(-1, 3))  # the platform's displacement


def rrr_leg(a, m, angle1, angle2):
    """An R-R-R leg from ``a`` through the elbow ``m`` whose joints at ``angle1``,
    ``angle2`` (cos, sin) and the angle making up POSE's carry the platform by POSE: its
    platform joint at the fixed point of ``(e1 e2)^-1 POSE``."""
    G = (about(a, *angle1) * about(m, *angle2)).inv() * POSE
    b = fixed_point(G)
    return Limb(*(Revolute([*p, 0], [0, 0, 1]) for p in (a, m, b)))


def rpr_leg(a, angle1, b0):
    """An R-P-R leg from ``a`` to the platform point ``b0`` (reference)."""
    return Limb(Revolute([*a, 0], [0, 0, 1]), Prismatic([b0[0] - a[0], b0[1] - a[1], 0]),
                Revolute([*b0, 0], [0, 0, 1]))


def test_3_rpr_two_branches_per_leg_each_exact():
    pm = ParallelMechanism(rpr_leg((0, 0), None, (1, 1)), rpr_leg((4, 0), None, (2, 1)),
                           rpr_leg((0, 4), None, (1, 2)))
    T = planar(*P345, 1, 1)
    legs = limb_joint_values(pm, T)
    assert [len(b) for b in legs] == [2, 2, 2]
    for limb, branches in zip(pm.limbs, legs, strict=True):
        for b in branches:
            assert isinstance(b, LimbBranch) and b.condition is S.true
            assert round_trip_exact(limb, b.values, T)
        # the two branches: the leg turned half a turn, the prismatic joint past the base
        # joint by as much (the leg's length at the pose, + or -)
        (t1, q1, _), (t2, q2, _) = (b.values for b in branches)
        assert expand(expand_trig(cos(t2 - t1))) == -1
        rest = Matrix(limb.joints[1].args[0]).norm()
        assert expand(rest * (1 + q1) + rest * (1 + q2)) == 0
    # the checker rejects a wrong value: the leg's prismatic joint off by 1/1000
    limb, (b, _) = pm.limbs[0], legs[0]
    wrong = (b.values[0], b.values[1] + Rational(1, 1000), b.values[2])
    assert not round_trip_exact(limb, wrong, T)


def test_3_rrr_eight_elbow_combinations_each_exact():
    legs_geometry = [((0, 0), (2, 0), P345, P81517), ((6, 0), (6, 2), P51213, P345),
                     ((3, 7), (2, 5), P81517, P51213)]
    pm = ParallelMechanism(*(rrr_leg(a, m, u, v) for a, m, u, v in legs_geometry))
    legs = limb_joint_values(pm, POSE)
    assert [len(b) for b in legs] == [2, 2, 2]  # elbow one way or the other, each leg
    combos = list(itertools.product(*legs))
    assert len(combos) == 8  # 2**3 assemblies of the legs at one platform pose
    for limb, branches, (_, _, u, v) in zip(pm.limbs, legs, legs_geometry, strict=True):
        for b in branches:
            assert b.condition is S.true
            assert round_trip_exact(limb, b.values, POSE)
        # the joints that built the leg are one of its two branches (exactly, modulo 2 pi)
        made = [atan2(u[1], u[0]), atan2(v[1], v[0])]
        assert sum(all(same_angle(x, y) for x, y in zip(b.values[:2], made, strict=True)) for b in branches) == 1
    # the two elbows differ, and a mixed one (leg 1's elbow with leg 2's shoulder) fails
    b1, b2 = legs[0]
    assert not round_trip_exact(pm.limbs[0], (b1.values[0], b2.values[1], b1.values[2]), POSE)


def test_an_unreachable_pose_has_no_branch():
    pm = ParallelMechanism(rrr_leg((0, 0), (2, 0), P345, P81517))
    far = planar(1, 0, 100, 0)
    (branches,) = limb_joint_values(pm, far)
    assert branches == ()


def ups_leg(A, B):
    return Limb(Universal(A, [1, 0, 0], [0, 1, 0]), Prismatic([b - a for a, b in zip(A, B, strict=True)]),
                Spherical(B))


def gough_stewart():
    A = [(2, 0, 0), (1, 2, 0), (-1, 2, 0), (-2, 0, 0), (-1, -2, 0), (1, -2, 0)]
    B = [(1, 0, 2), (1, 1, 2), (0, 1, 2), (-1, 0, 2), (0, -1, 2), (1, -1, 2)]
    return ParallelMechanism(*(ups_leg(a, b) for a, b in zip(A, B, strict=True)))


def rational_rotation(w, x, y, z):
    n = w * w + x * x + y * y + z * z
    return Matrix([[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
                   [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
                   [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]]) / n


def test_gough_stewart_eight_branches_per_leg_to_50_digits():
    gs = gough_stewart()
    R = rational_rotation(3, 1, 0, 1)
    T = Transform(R, Matrix([Rational(1, 2), Rational(1, 3), 1]))
    legs = limb_joint_values(gs, T)
    assert [len(b) for b in legs] == [8] * 6
    limb, branches = gs.limbs[0], legs[0]
    for b in branches:
        assert b.condition is S.true
        assert round_trip_digits(limb, b.values, T.matrix) < Rational(1, 10**45)
    # every leg's length (the prismatic joint) is the leg length at the pose, or its mirror
    # (the leg turned half a turn by the universal joint)
    from screwsym.systems import leg_lengths

    base = [tuple(L.joints[0].args[0]) for L in gs.limbs]
    top = [tuple(L.joints[2].args[0]) for L in gs.limbs]
    lengths = leg_lengths(base, top, (Matrix([Rational(1, 2), Rational(1, 3), 1]), R))
    for limb, branches, length in zip(gs.limbs, legs, lengths, strict=True):
        rest = Matrix(limb.joints[1].args[0]).norm()
        got = sorted({round(float(rest * (1 + b.values[2])), 12) for b in branches})
        assert got == sorted({round(float(length), 12), round(-float(length), 12)})
    # the checker rejects a wrong value: one spherical angle off by 1e-20
    b = branches[0]
    wrong = (*b.values[:3], b.values[3] + Rational(1, 10**20), *b.values[4:])
    assert round_trip_digits(gs.limbs[-1], wrong, T.matrix) > Rational(1, 10**25)


def test_bad_input_is_refused():
    pm = ParallelMechanism(rrr_leg((0, 0), (2, 0), P345, P81517))
    with pytest.raises(TypeError, match="mechanism: expected a ParallelMechanism"):
        limb_joint_values("3-RRR", POSE)
    with pytest.raises(ValueError, match="pose: expected a rigid motion"):
        limb_joint_values(pm, Matrix.ones(4, 4))
    with pytest.raises(ValueError, match="pose: limb 0 is planar"):
        limb_joint_values(pm, Transform(eye(3), Matrix([0, 0, 1])))
    spatial = ParallelMechanism(Limb(Revolute([0, 0, 0], [1, 0, 0]), Revolute([0, 0, 1], [0, 1, 0])))
    with pytest.raises(ValueError, match="limb 0 \\(RR, 2 freedoms\\) is not one solved here"):
        limb_joint_values(spatial, POSE)
    with pytest.raises(ValueError, match="limb_joint_values: the case split needs more work than budget=1000"):
        limb_joint_values(gough_stewart(), POSE, budget=1000)
    # the platform joint brought onto the base joint: the first joint is free
    leg = ParallelMechanism(Limb(Revolute([0, 0, 0], [0, 0, 1]), Prismatic([1, 0, 0]), Revolute([1, 0, 0], [0, 0, 1])))
    with pytest.raises(ValueError, match="the first joint is free"):
        limb_joint_values(leg, planar(1, 0, -1, 0))


def test_a_symbolic_pose_gives_closed_forms_with_their_conditions():
    from sympy import symbols

    x, y, phi = symbols("x y phi", real=True)
    T = Matrix([[cos(phi), -sin(phi), 0, x], [sin(phi), cos(phi), 0, y], [0, 0, 1, 0], [0, 0, 0, 1]])
    pm = ParallelMechanism(rrr_leg((0, 0), (2, 0), P345, P81517))
    (branches,) = limb_joint_values(pm, T)
    assert len(branches) == 2
    for b in branches:
        assert b.condition.free_symbols == {x, y, phi}  # the reach, a condition on the pose
    # at POSE the closed forms give the numeric call's branches (30 digits)
    at = {x: POSE[0, 3], y: POSE[1, 3], phi: atan2(POSE[1, 0], POSE[0, 0])}
    (numeric,) = limb_joint_values(pm, POSE)
    for b, n in zip(branches, numeric, strict=True):
        assert bool(b.condition.xreplace(at)) is True
        assert all(abs((u.xreplace(at) - v).evalf(30)) < Rational(1, 10**25) for u, v in zip(b.values, n.values, strict=True))
