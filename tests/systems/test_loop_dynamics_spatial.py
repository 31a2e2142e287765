"""The dynamics of a spatial six-freedom parallel mechanism (issue 35, item 4): the
Gough-Stewart platform as a 6-UPS with massive legs, against Tsai's virtual-work model.

The model: six legs, each a universal joint on the base, an actuated prismatic joint and a
spherical joint on the platform (6-UPS); each leg is two bodies, the cylinder (the link
between the U and the P) and the piston (between the P and the S), plus the platform: 13
moving bodies, 36 joint freedoms, 5 loops, mobility 6.  Why U-P-S and not S-P-S: an S at each
end leaves the leg free to spin about its own axis, an idle freedom the library refuses (see
``test_a_rod_between_two_spherical_joints_is_refused_clearly``); the universal joint at the base
stops the spin of the cylinder and piston, and the spherical joint at the platform takes the
platform's share of it, so the leg has exactly six freedoms and none idle.  This is the leg of
Tsai 2000 (universal joint at the base, spherical at the platform).

The ground truth is computed in the test, with mpmath at 50 digits and without screwsym:
Tsai's principle of virtual work (L.-W. Tsai, "Solving the inverse dynamics of a Stewart-Gough
manipulator by the principle of virtual work", J. Mech. Des. 122(1):3-9, 2000),
``J_L^T tau = sum_b J_b^T W_b``, with ``W_b = (m_b (a_b - g), I_b alpha_b + omega_b x I_b
omega_b)`` each body's Newton-Euler inertia-and-gravity wrench at its centre of mass, ``J_b``
the body's (centre of mass velocity, angular velocity) per platform twist and ``J_L`` the leg
rates per platform twist.  Every body's pose is written explicitly as a function of the
platform's pose (the leg's direction from the two pivots, the universal joint's two angles
from that direction, closed form) and differentiated numerically by central differences
(step 1e-12 at 50 digits, error about 1e-24).  The mass matrix is ``J_L^-T (sum_b J_b^T M_b
J_b) J_L^-1``.  The state is exact (a rational rotation, legs of rational length, rational
rates), so screwsym's answer is exact and the agreement asked is 1e-18, relative.
"""

from __future__ import annotations

import pytest
from mpmath import matrix as mpmatrix
from mpmath import mp, mpf
from sympy import Matrix, Rational, eye

from screwsym.core.inertia import SpatialInertia
from screwsym.systems.joints import P, S, U
from screwsym.systems.linkage import Mechanism
from screwsym.systems.parallel import Limb, ParallelMechanism

Q = Rational
DPS = 50
H = mpf("1e-12")
TOL = 1e-18

# ------------------------------------------------------------------ the platform at its pose
# a rational rotation (Euler-Rodrigues from the quaternion (5, 1, -1, 2)), the platform's
# pivots in its own frame, the legs' unit directions from Pythagorean quadruples, so that
# every leg has a rational length and direction and the whole state is exact
QUAT = (5, 1, -1, 2)
ORIGIN = Matrix([Q(1, 5), Q(-1, 10), 4])
PIVOTS = [(2, 1, 0), (1, 2, 0), (-2, 1, Q(1, 5)), (-1, -2, 0), (1, -2, Q(-1, 5)), (2, -1, 0)]
DIRECTIONS = [(2, 3, 6), (-2, 3, 6), (-6, 2, 9), (-3, -2, 6), (2, -6, 9), (6, -2, 9)]
LENGTHS = [3, Q(7, 2), 3, 4, Q(10, 3), 3]


def rotation(q):
    a, b, c, d = q
    n = a * a + b * b + c * c + d * d
    return Matrix([[a*a + b*b - c*c - d*d, 2*(b*c - a*d), 2*(b*d + a*c)],
                   [2*(b*c + a*d), a*a - b*b + c*c - d*d, 2*(c*d - a*b)],
                   [2*(b*d - a*c), 2*(c*d + a*b), a*a - b*b - c*c + d*d]]) / n


def geometry():
    """The exact geometry: the platform's rotation, each leg's pivots, unit direction and
    universal joint's axes (the first fixed in the base, normal to the leg, the second normal
    to both)."""
    R0 = rotation(QUAT)
    legs = []
    for r, d, length in zip(PIVOTS, DIRECTIONS, LENGTHS, strict=True):
        d = Matrix(d)
        u = d / d.norm()
        p = ORIGIN + R0 * Matrix(r)
        b = p - length * u
        a1 = u.cross(Matrix([0, 0, 1]))
        a2 = a1.cross(u)
        legs.append((b, p, u, a1, a2, Q(length)))
    return R0, legs


def axisymmetric(u, axial, transverse):
    return axial * u * u.T + transverse * (eye(3) - u * u.T)


def body_data(masses):
    """Each body's mass, centre of mass and inertia in the space frame at the pose, with the
    platform's inertia and centre in its own frame and the legs' bodies axisymmetric."""
    R0, legs = geometry()
    com_p = Matrix([Q(1, 10), 0, Q(-1, 5)])
    inertia_p = Matrix([[Q(3, 2), Q(1, 10), 0], [Q(1, 10), 2, Q(-1, 20)], [0, Q(-1, 20), 3]])
    bodies = {"platform": (masses["platform"], ORIGIN + R0 * com_p, R0 * inertia_p * R0.T)}
    for i, (b, p, u, _, _, _) in enumerate(legs):
        m1, m2 = masses[f"cylinder{i + 1}"], masses[f"piston{i + 1}"]
        bodies[f"limb{i + 1}.1"] = (m1, b + Q(3, 4) * u, axisymmetric(u, Q(1, 50), Q(1, 5)))
        bodies[f"limb{i + 1}.2"] = (m2, p - Q(3, 4) * u, axisymmetric(u, Q(1, 80), Q(1, 8)))
    return R0, legs, com_p, bodies


def stewart(masses):
    _, legs = geometry()
    pm = ParallelMechanism(*(Limb(U(list(b), list(a1), list(a2)), P(list(u)), S(list(p)))
                             for b, p, u, a1, a2, _ in legs))
    _, _, _, bodies = body_data(masses)
    inertias = {k: SpatialInertia(m, list(c), I) for k, (m, c, I) in bodies.items()}
    return Mechanism.from_parallel(pm, inertias=inertias)


ACTUATED = [1, 4, 7, 10, 13, 16]  # the prismatic joint of each leg (U, P, S: joints 0, 1, 2)


def default_masses(heavier=None):
    masses = {"platform": 5}
    for i in range(1, 7):
        masses[f"cylinder{i}"] = 2
        masses[f"piston{i}"] = 1
    if heavier:
        masses[heavier] = masses[heavier] * Q(101, 100)
    return masses


def leg_rates(v, w, a, al):
    """The legs' rates and accelerations in closed form (exact): ``pd = v + w x r``, ``pdd =
    a + al x r + w x (w x r)``, ``Ld = u.pd``, ``Ldd = u.pdd + (|pd|^2 - Ld^2)/L``."""
    _, legs = geometry()
    Ld, Ldd = [], []
    for _, p, u, _, _, length in legs:
        r = p - ORIGIN
        pd = v + w.cross(r)
        pdd = a + al.cross(r) + w.cross(w.cross(r))
        ld = u.dot(pd)
        Ld.append(ld)
        Ldd.append(u.dot(pdd) + (pd.dot(pd) - ld * ld) / length)
    return Ld, Ldd


# ------------------------------------------------------------------ the ground truth (mpmath)
def mpv(M):
    return mpmatrix([[mpf(int(Q(x).p)) / int(Q(x).q) for x in row] for row in Matrix(M).tolist()])


def mp_rot(axis, angle):
    """Rodrigues' rotation about a unit axis."""
    x, y, z = axis
    K = mpmatrix([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return mp.eye(3) + mp.sin(angle) * K + (1 - mp.cos(angle)) * K * K


def mp_exp(phi):
    n = mp.norm(phi)
    return mp.eye(3) if n == 0 else mp_rot(phi / n, n)


def cross(a, b):
    return mpmatrix([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def vee(W):
    return mpmatrix([(W[2, 1] - W[1, 2]) / 2, (W[0, 2] - W[2, 0]) / 2, (W[1, 0] - W[0, 1]) / 2])


class Truth:
    """Every body's pose as an explicit function of the platform's pose, at 50 digits."""

    def __init__(self, masses):
        R0, legs, com_p, bodies = body_data(masses)
        self.R0, self.com_p = mpv(R0), mpv(com_p)
        self.o0 = mpv(ORIGIN)
        self.legs = []
        for b, p, u, a1, _, _ in legs:
            r = mpv(R0.T * (p - ORIGIN))
            u0, e1 = mpv(u), mpv(a1)
            e1 = e1 / mp.norm(e1)
            self.legs.append((mpv(b), r, u0, e1, cross(e1, u0)))
        self.bodies = {k: (mpf(int(Q(m).p)) / int(Q(m).q), mpv(c), mpv(I))
                       for k, (m, c, I) in bodies.items()}
        # the leg bodies' centres along the leg: the cylinder's from the base pivot, the piston's
        self.offsets = (mpf(3) / 4, mpf(3) / 4)

    def poses(self, o, R):
        """``{body: (centre of mass, rotation from the pose of the test)}`` and the leg lengths."""
        out = {"platform": (o + R * self.com_p, R * self.R0.T)}
        lengths = []
        for i, (b, r, u0, e1, e2) in enumerate(self.legs):
            d = o + R * r - b
            L = mp.norm(d)
            u = d / L
            lengths.append(L)
            # the universal joint: u = Rot(e1, t1) Rot(e2, t2) u0, e2 = e1 x u0, e1 normal to u0
            t2 = -mp.asin(mp.fdot(u, e1))
            t1 = mp.atan2(mp.fdot(u, e2), mp.fdot(u, u0))
            Rl = mp_rot(e1, t1) * mp_rot(e2, t2)
            out[f"limb{i + 1}.1"] = (b + self.offsets[0] * u, Rl)
            out[f"limb{i + 1}.2"] = (o + R * r - self.offsets[1] * u, Rl)
        return out, lengths

    def along(self, v, w, a, al, t):
        """The poses at time ``t`` on ``o = o0 + v t + a t^2/2``, ``R = exp((w t + al t^2/2)x) R0``."""
        o = self.o0 + v * t + a * t * t / 2
        R = mp_exp(w * t + al * t * t / 2) * self.R0
        return self.poses(o, R)

    def derivatives(self, v, w, a, al):
        """Each body's (c, cd, cdd, omega, alpha) at t = 0, and the legs' lengths' rates."""
        (p0, L0), (pp, Lp), (pm, Lm) = (self.along(v, w, a, al, t) for t in (0, H, -H))
        out = {}
        for k in p0:
            c, R = p0[k]
            cd = (pp[k][0] - pm[k][0]) / (2 * H)
            cdd = (pp[k][0] - 2 * c + pm[k][0]) / (H * H)
            Rd = (pp[k][1] - pm[k][1]) / (2 * H)
            Rdd = (pp[k][1] - 2 * R + pm[k][1]) / (H * H)
            out[k] = (c, cd, cdd, vee(Rd * R.T), vee(Rdd * R.T + Rd * Rd.T))
        Ld = [(x - y) / (2 * H) for x, y in zip(Lp, Lm, strict=True)]
        Ldd = [(x - 2 * z + y) / (H * H) for x, y, z in zip(Lp, Lm, L0, strict=True)]
        return out, Ld, Ldd

    def virtual(self):
        """For each unit platform twist (v; w): the bodies' (cd, omega) and the legs' rates."""
        zero = mpmatrix(3, 1)
        rows = []
        for k in range(6):
            e = mpmatrix(6, 1)
            e[k] = 1
            v, w = e[0:3], e[3:6]
            d, Ld, _ = self.derivatives(v, w, zero, zero)
            rows.append(({b: (x[1], x[3]) for b, x in d.items()}, Ld))
        JL = mpmatrix([[rows[k][1][i] for k in range(6)] for i in range(6)])
        return rows, JL

    def forces(self, v, w, a, al, g):
        """Tsai's virtual work: ``J_L^T tau = sum_b J_b^T W_b``."""
        d, Ld, Ldd = self.derivatives(v, w, a, al)
        rows, JL = self.virtual()
        G = mpmatrix(6, 1)
        for b, (_, _, cdd, om, alpha) in d.items():
            # the inertia in the space frame at the pose (each body's rotation is the
            # identity there: the rotations of poses() are relative to the pose)
            m, _, I = self.bodies[b]
            F = m * (cdd - g)
            M = I * alpha + cross(om, I * om)
            for k in range(6):
                dc, dw = rows[k][0][b]
                G[k] += mp.fdot(F, dc) + mp.fdot(M, dw)
        return mp.lu_solve(JL.T, G), Ld, Ldd

    def mass_matrix(self):
        rows, JL = self.virtual()
        K = mpmatrix(6, 6)
        for b, (m, _, I) in self.bodies.items():
            for k in range(6):
                for j in range(6):
                    K[k, j] += (m * mp.fdot(rows[k][0][b][0], rows[j][0][b][0])
                                + mp.fdot(rows[k][0][b][1], I * rows[j][0][b][1]))
        Jinv = mp.inverse(JL)
        return Jinv.T * K * Jinv


def agrees(ours, truth, tol=TOL):
    ours = [mpf(int(Q(x).p)) / int(Q(x).q) for x in Matrix(ours)]
    if isinstance(truth, list):
        truth = mpmatrix(truth)
    truth = [truth[i, j] for i in range(truth.rows) for j in range(truth.cols)]
    scale = max(abs(x) for x in truth)
    return max(abs(x - y) for x, y in zip(ours, truth, strict=True)) <= tol * scale


STATES = [
    # (v, w, a, alpha) of the platform at ORIGIN, and gravity
    ((Q(1, 3), Q(-1, 5), Q(1, 2)), (Q(1, 4), Q(-1, 2), Q(1, 3)),
     (Q(-1, 2), Q(2, 3), Q(1, 7)), (Q(3, 5), Q(1, 9), Q(-2, 3)), (0, 0, Q(-981, 100))),
    ((Q(-2, 3), Q(1, 2), Q(-1, 4)), (Q(-1, 3), Q(1, 5), Q(2, 3)),
     (Q(1, 3), Q(-1, 2), Q(5, 4)), (Q(-1, 2), Q(3, 4), Q(1, 6)), (Q(1, 2), Q(-1, 3), -10)),
]


@pytest.mark.parametrize("case", range(len(STATES)))
def test_stewart_inverse_dynamics_is_tsais_virtual_work_model(case):
    """The 6-UPS's actuator forces at a moving state against Tsai's virtual-work model
    computed above; the legs' rates from their closed form agree with the differentiated
    lengths; a leg's piston 1 % heavier is rejected."""
    with mp.workdps(DPS):
        v, w, a, al, g = (Matrix(x) for x in STATES[case])
        Ld, Ldd = leg_rates(v, w, a, al)
        truth = Truth(default_masses())
        tau, mLd, mLdd = truth.forces(*(mpv(x) for x in (v, w, a, al, g)))
        assert agrees(Ld, mLd) and agrees(Ldd, mLdd)
        ours = stewart(default_masses()).inverse_dynamics(ACTUATED, Ld, Ldd, list(g))
        assert agrees(ours, tau)
        wrong = stewart(default_masses("piston3")).inverse_dynamics(ACTUATED, Ld, Ldd, list(g))
        assert not agrees(wrong, tau, 1e-6)


def is_symmetric_positive_definite(M):
    """Exactly: symmetric, and its leading principal minors positive (Sylvester)."""
    M = Matrix(M)
    return M == M.T and all(M[:k, :k].det() > 0 for k in range(1, M.rows + 1))


def test_stewart_mass_matrix_is_tsais_and_positive_definite():
    """The 6x6 mass matrix in the legs' rates against ``J_L^-T (sum_b J_b^T M_b J_b) J_L^-1``
    of the virtual-work model, symmetric positive definite (exactly, by Sylvester's
    criterion); the platform 1 % heavier is rejected."""
    with mp.workdps(DPS):
        truth = Truth(default_masses()).mass_matrix()
        ours = stewart(default_masses()).mass_matrix(ACTUATED)
        assert is_symmetric_positive_definite(ours)
        assert agrees(ours, truth)
        wrong = stewart(default_masses("platform")).mass_matrix(ACTUATED)
        assert not agrees(wrong, truth, 1e-6)


def static_balance(masses, g):
    """The legs' forces holding the 6-UPS at rest, by virtual work in closed form (exact):
    ``J_L^T tau = -sum_b m_b J_c,b^T g``, the leg rates ``Ld_i = u_i.(v + w x r_i)``, the
    centres' velocities ``v + w x (c - o)`` (platform), ``s1 ud`` (cylinder), ``pd - s2 ud``
    (piston), with ``ud = (E - u u^T) pd / L``."""
    R0, legs, _, bodies = body_data(masses)

    def skew(r):  # w x r = -skew(r) w
        return Matrix([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])

    def twist_map(r):  # pd = v + w x r as a 3x6 map of (v; w)
        return Matrix.hstack(eye(3), -skew(r))

    JL = Matrix([list(u.T) + list(r.cross(u).T)
                 for _, p, u, _, _, _ in legs for r in [p - ORIGIN]])
    G = Matrix.zeros(6, 1)
    g = Matrix(g)
    m, c, _ = bodies["platform"]
    G -= m * twist_map(c - ORIGIN).T * g
    for i, (_, p, u, _, _, length) in enumerate(legs):
        Pd = twist_map(p - ORIGIN)
        Ud = (eye(3) - u * u.T) * Pd / length
        for link, Jc in ((f"limb{i + 1}.1", Q(3, 4) * Ud), (f"limb{i + 1}.2", Pd - Q(3, 4) * Ud)):
            G -= bodies[link][0] * Jc.T * g
    return JL.T.solve(G)


def test_stewart_at_rest_is_the_static_balance_by_virtual_work():
    """At rest the inverse dynamics is the static balance by virtual work, exactly; the
    balance of a rig with a cylinder 1 % heavier differs."""
    g = [Q(1, 2), Q(-1, 3), -10]
    ours = stewart(default_masses()).inverse_dynamics(ACTUATED, [0] * 6, [0] * 6, g)
    assert ours == static_balance(default_masses(), g)
    assert ours != static_balance(default_masses("cylinder2"), g)
