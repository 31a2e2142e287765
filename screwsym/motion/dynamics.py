r"""The dynamics of a serial chain in screw form: Newton–Euler, mass matrix, Coriolis, regressor.

The algorithms
==============

Everything is written with the twists, wrenches
and spatial inertias of :mod:`screwsym.core` in ray order: a twist
``(omega; v_O)``, a wrench ``(f; C_O)``, the ray-order inertia
:attr:`~screwsym.core.inertia.SpatialInertia.matrix` ``M`` from twists to momenta.
Link ``i`` is moved by joints ``1 .. i``.  Its frame ``{i}`` is the link-fixed
frame that coincides with the space frame at home (``q = 0``), so that the
chain's data need no other frames: link ``i``'s inertia ``M_i`` in ``{i}`` is
its home inertia in the space frame (constant), joint ``i``'s twist in ``{i}``
is its home twist ``$_i``, and ``{i}`` is posed in ``{i-1}`` by
``E_i = exp6($_i, q_i)``.  The recursive Newton–Euler algorithm of Park,
Bobrow & Ploen (1995) (Lynch & Park (8.50)-(8.53), with these frames) is

    V_i = Ad(E_i^-1) V_{i-1} + $_i qd_i,                        V_0 = 0,
    A_i = Ad(E_i^-1) A_{i-1} + $_i qdd_i + [V_i, $_i] qd_i,    A_0 = (0; -gravity),
    F_i = Ad(E_{i+1}) F_{i+1} + M_i A_i + [V_i, M_i V_i],      F_{n+1} = 0,
    tau_i = $_i o F_i,

with ``V_i`` the twist of link ``i`` and ``A_i = dV_i/dt`` its spatial
acceleration, both in ``{i}`` (in the space frame they are ``Ad(g_i)`` of
these, ``g_i = E_1 ... E_i``: the same torques, since the reciprocal product is
invariant (1.47)), ``[V, s] = (omega x S; omega x S0 + v x S)`` the screw product
(:func:`screwsym.core.formulas.bracket`), the time derivative of a screw fixed in a
body moving with ``V`` (twists and wrenches alike: both move with ``Ad`` in ray
order), and ``o`` the reciprocal product (1.45,
:func:`screwsym.core.formulas.reciprocal_form`).  Gravity is the base accelerating upward (``A_0``), as in
Lynch & Park and pinocchio; ``gravity`` is the gravitational acceleration,
pointing down (``(0, 0, -g)``).

The mass matrix is computed by composite rigid bodies (not from columns of
the Newton–Euler algorithm): with ``M^c_i`` the inertia of links ``i .. n``
together, in ``{i}`` (``M^c_i = M_i + E_{i+1} . M^c_{i+1}``, the inertia carried
by ``E_{i+1}``), and ``k = max(i, j)``,

    H_ij = $_i o (Ad(E_{i+1} ... E_k) M^c_k $_k),

and the Coriolis matrix in the Christoffel form,
``C_ij = sum_k 1/2 (dH_ij/dq_k + dH_ik/dq_j - dH_jk/dq_i) qd_k``, for which
``dH/dt - 2 C`` is skew-symmetric.  The joint torques are linear in the ten
inertial parameters of each link; :func:`regressor` gives the matrix ``Y`` with
``tau = Y(q, qd, qdd) pi``, ``pi`` the parameters
``[m, mc_x, mc_y, mc_z, I_xx, I_xy, I_yy, I_xz, I_yz, I_zz]`` of each link in turn
(pinocchio's order) taken in the link-fixed frame that coincides with the
space frame at home (the inertia about the space origin, at ``q = 0``).

All results are exact SymPy expressions, tidied as the kinematics are
(:func:`screwsym.core.tidy.tidy` on each intermediate twist, wrench and
inertia up to ``INTERMEDIATE_SIZE`` nodes, and on each final entry; no
``simplify``).  For numbers over many states, pass them to
:func:`screwsym.lambdify`, or use :mod:`screwsym.numeric.dynamics`.

References
==========

F. C. Park, J. E. Bobrow, S. R. Ploen, "A Lie group formulation of robot
dynamics", *Int. J. Robotics Research* 14(6), 1995.  Lynch & Park, *Modern
Robotics*, Cambridge 2017, Sections 8.1-8.3 and 8.2.2 (the regressor).
R. Featherstone, *Rigid Body Dynamics Algorithms*, Springer 2008, Chapter 6
(composite rigid bodies).  Huang, Li & Ding, *Theory of Parallel Mechanisms*,
Springer 2013, (1.45).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, NamedTuple

from sympy import Dummy, Expr, Float, ImmutableMatrix, S, Symbol, cos, sin, zeros
from sympy.core.evalf import prec_to_dps

from ..algebra.budget import BUDGET, charge
from ..core.checks import check_scalar, check_sequence, check_vector
from ..core.formulas import bracket, cross_matrix, moved, reciprocal_form
from ..core.inertia import PARAMETER_NAMES, SpatialInertia, spatial_matrix
from ..core.tidy import tidy
from ..core.twist import Twist
from ._poe import STEP_UNITS, bounded
from ._ring_dynamics import ring_mass_matrix, ring_rnea
from .displacement import exp6
from .transform import Transform

if TYPE_CHECKING:
    from .chain import Chain

__all__ = [
    "inverse_dynamics",
    "mass_matrix",
    "coriolis_matrix",
    "gravity_torques",
    "regressor",
    "GRAVITY",
]

#: intermediate twists, wrenches and inertias are tidied up to this many nodes, and without
#: gathering sums of angles (the final torques and entries fully, up to tidy's own limit):
#: the recursions nest, and tidying large intermediate sums costs more than it saves
INTERMEDIATE_SIZE = 300


def _step(x: Any, angles: bool = False) -> Any:
    """``tidy`` for the recursions' intermediate results (see ``INTERMEDIATE_SIZE``).

    Newton–Euler's twists and wrenches are tidied without gathering sums of angles (on
    the UR5: 15 s instead of 50 s), the composite inertias with it (10 s instead of 27 s:
    they stay small enough to gain from it).
    """
    charge(STEP_UNITS)
    return tidy(x, max_size=INTERMEDIATE_SIZE, sum_of_angles=angles)


#: the default gravitational acceleration ``(0, 0, -g)``, with ``g`` a positive symbol
GRAVITY = (S.Zero, S.Zero, -Symbol("g", positive=True))


class _Params(NamedTuple):
    """A body's ten inertial parameters: mass, first moment ``m c``, inertia about the origin."""

    m: Expr
    h: ImmutableMatrix
    I_O: ImmutableMatrix


def _params(body: SpatialInertia) -> _Params:
    return _Params(body.mass, body.first_moment, body.inertia_about([0, 0, 0]))


def _moved_params(P: _Params, T: Transform, angles: bool = False) -> _Params:
    """The parameters carried by ``T = (R, p)``: ``h' = R h + m p``,
    ``I_O' = R I_O R^T - [R h]x [p]x - [p]x [R h]x - m [p]x^2`` (linear in the parameters)."""
    R, p = T.R, T.p
    Rh = R * P.h
    X, Y = cross_matrix(Rh), cross_matrix(p)
    I_O = R * P.I_O * R.T - X * Y - Y * X - P.m * Y * Y
    return _Params(P.m, _step(Rh + P.m * p, angles), _step(I_O, angles))


def _check_chain(chain: Any, name: str = "chain") -> tuple[Any, ...]:
    """The chain's inertias (home, space frame), or an error saying how to give them."""
    inertias = getattr(chain, "inertias", None)
    if not hasattr(chain, "twists") or not hasattr(chain, "n_joints"):
        raise TypeError(f"{name}: expected a Chain, got {type(chain).__name__}")
    if inertias is None:
        raise ValueError(
            f"{name}: the chain has no inertias; build it with Chain(twists, home, "
            "inertias=[SpatialInertia(...), ...]) (one per link, in the space frame at home)"
        )
    return tuple(inertias)


def _values(value: Any, name: str, n: int) -> tuple[Expr, ...]:
    values = check_sequence(value, name, "joint values", n)
    return tuple(check_scalar(v, f"{name}[{i}]") for i, v in enumerate(values))


def _gravity(gravity: Any) -> ImmutableMatrix:
    return check_vector(GRAVITY if gravity is None else gravity, "gravity")


def _carry(T: Transform, s: ImmutableMatrix, angles: bool = False) -> ImmutableMatrix:
    """``Ad(T) s`` for a ray-order 6x1 column (twist or wrench alike), tidied."""
    w, v = moved(T.R, T.p, s[:3, 0], s[3:, 0])
    return _step(ImmutableMatrix.vstack(w, v), angles)


def _joint_motions(twists: Sequence[Any], q: Sequence[Expr]) -> list[Transform]:
    """``exp6($_i, q_i)``: the pose of link ``i``'s frame in link ``i-1``'s (module docstring)."""
    return [_step(exp6(t, qi)) for t, qi in zip(twists, q, strict=True)]


#: guard digits of the sines of constant angles evaluated at a float state (:func:`_at_floats`)
GUARD_DIGITS = 15


def _at_floats(twists: Sequence[Any], params: Sequence[_Params],
               state: Sequence[Expr]) -> tuple[list[Any], list[_Params]]:
    """The chain's sines and cosines of constant angles as floats, at a float state.

    A robot file's angles that are no multiple of pi/12 (the SO-100's ``-1.8``) leave
    ``cos(9/5)``, ... in the twists and inertias; at a state of floats the torques are
    floats, and SymPy's products of floats with those exact numbers (kept apart, never
    collected) took minutes.  Each such sine is evaluated once, to the state's precision
    and :data:`GUARD_DIGITS` more; anything else (an exact state) is returned as given.
    """
    floats = [f for v in state for f in v.atoms(Float)]
    if not floats:
        return list(twists), list(params)
    exprs = [*(t.matrix for t in twists), *(x for P in params for x in (P.m, P.h, P.I_O))]
    atoms = {a for e in exprs for a in e.atoms(sin, cos) if not a.free_symbols}
    if not atoms:
        return list(twists), list(params)
    dps = prec_to_dps(min(f._prec for f in floats)) + GUARD_DIGITS
    values = {a: a.evalf(dps) for a in atoms}
    return ([Twist(t.omega.xreplace(values), t.v_O.xreplace(values)) for t in twists],
            [_Params(P.m.xreplace(values), P.h.xreplace(values), P.I_O.xreplace(values))
             for P in params])


def _rnea(twists: Sequence[Any], params: Sequence[_Params], q: Sequence[Expr],
          qd: Sequence[Expr], qdd: Sequence[Expr], gravity: ImmutableMatrix) -> ImmutableMatrix:
    """The Newton–Euler recursion of the module docstring, in the link frames ``{i}``.

    In the ring of the chain (:mod:`._ring_dynamics`) where the chain is in its class, else
    on expressions, each intermediate result tidied."""
    twists, params = _at_floats(twists, params, [*q, *qd, *qdd, *gravity])
    fast = ring_rnea(twists, Transform.identity(), params, q, qd, qdd, gravity)
    if fast is not None:
        return fast
    E = _joint_motions(twists, q)
    xi = [t.matrix for t in twists]
    n = len(twists)
    V = zeros(6, 1)
    A = ImmutableMatrix.vstack(zeros(3, 1), -gravity)
    Vs, As = [], []
    for i in range(n):
        back = E[i].inverse()
        V = _step(_carry(back, V) + xi[i] * qd[i])
        A = _step(_carry(back, A) + xi[i] * qdd[i] + bracket(V, xi[i]) * qd[i])
        Vs.append(V)
        As.append(A)
    F = zeros(6, 1)
    tau: list[Expr] = [S.Zero] * n
    for i in reversed(range(n)):
        M = spatial_matrix(*params[i])
        F = _carry(E[i + 1], F) if i + 1 < n else F
        F = _step(F + M * As[i] + bracket(Vs[i], M * Vs[i]))
        tau[i] = tidy(reciprocal_form(xi[i], F))
    return ImmutableMatrix(tau)


def inverse_dynamics(chain: Chain, q: Any, qd: Any, qdd: Any,
                     gravity: Any = None, *, budget: int = BUDGET) -> ImmutableMatrix:
    r"""The joint torques (forces, for prismatic joints) ``tau(q, qd, qdd)``: an n x 1 column.

    The recursive Newton–Euler algorithm in screw form (module docstring; Park,
    Bobrow & Ploen 1995; Lynch & Park Section 8.3), exact and symbolic,
    ``tau = H(q) qdd + C(q, qd) qd + g(q)``.  ``gravity`` is the
    gravitational acceleration, pointing down (default ``(0, 0, -g)`` with a
    positive symbol ``g``; ``[0, 0, -9.81]`` as modern_robotics and pinocchio
    take it).  The chain needs inertias (``Chain(..., inertias=...)``).

    ``budget`` bounds the exact arithmetic (default :data:`~screwsym.algebra.budget.BUDGET`,
    20,000,000 units of about a microsecond, and ``SLACK`` microseconds of CPU time a
    unit; :meth:`~screwsym.motion.chain.Chain.forward` says how they are counted): past
    it, a ``ValueError`` naming the function called, where
    :meth:`~screwsym.motion.chain.Chain.dynamics_program` grows linearly.  The same
    holds for :func:`gravity_torques`, :func:`mass_matrix`, :func:`coriolis_matrix`
    and :func:`regressor`; one calling another stays within the outer budget.

    >>> from sympy import symbols
    >>> from screwsym import Chain, Twist
    >>> from screwsym.core.inertia import SpatialInertia
    >>> q, qd, qdd, g = symbols("q qd qdd g", real=True)
    >>> pendulum = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])],
    ...                  inertias=[SpatialInertia.point_mass(1, [1, 0, 0])])
    >>> inverse_dynamics(pendulum, [q], [qd], [qdd], gravity=[0, -g, 0])
    Matrix([[g*cos(q) + qdd]])
    """
    inertias = _check_chain(chain)
    n = chain.n_joints
    q, qd, qdd = (_values(v, name, n) for v, name in ((q, "q"), (qd, "qd"), (qdd, "qdd")))
    with bounded(budget, "inverse_dynamics"):
        return _rnea(chain.twists, [_params(b) for b in inertias], q, qd, qdd, _gravity(gravity))


def gravity_torques(chain: Chain, q: Any, gravity: Any = None, *,
                    budget: int = BUDGET) -> ImmutableMatrix:
    r"""The torques that hold the chain still against gravity, ``g(q) = tau(q, 0, 0)``.

    The gradient of the potential energy: below, a mass 2 at ``x = 1`` turning about
    ``+y`` goes down as ``q`` grows, so holding it takes ``-20 cos(q)``.

    >>> from sympy import symbols
    >>> from screwsym import Chain, Twist
    >>> from screwsym.core.inertia import SpatialInertia
    >>> q = symbols("q", real=True)
    >>> pendulum = Chain([Twist.rotation([0, 1, 0], point=[0, 0, 0])],
    ...                  inertias=[SpatialInertia.point_mass(2, [1, 0, 0])])
    >>> gravity_torques(pendulum, [q], gravity=[0, 0, -10])
    Matrix([[-20*cos(q)]])
    """
    zero = [S.Zero] * chain.n_joints
    with bounded(budget, "gravity_torques"):
        return inverse_dynamics(chain, q, zero, zero, gravity)


def mass_matrix(chain: Chain, q: Any, *, budget: int = BUDGET) -> ImmutableMatrix:
    r"""The joint-space mass matrix ``H(q)`` by composite rigid bodies: symmetric, n x n, tidied.

    ``H_ij = $_i o (Ad(E_{i+1} ... E_k) M^c_k $_k)`` with ``k = max(i, j)`` and ``M^c_k`` the
    inertia of links ``k .. n`` together (module docstring; Featherstone 2008,
    Section 6.2, written with twists and the reciprocal product).  The kinetic
    energy is ``qd^T H qd / 2``.

    >>> from sympy import symbols
    >>> from screwsym import Chain, Twist
    >>> from screwsym.core.inertia import SpatialInertia
    >>> q1, q2 = symbols("q1 q2", real=True)
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])],
    ...             inertias=[SpatialInertia.point_mass(1, [1, 0, 0]),
    ...                       SpatialInertia.point_mass(1, [2, 0, 0])])
    >>> mass_matrix(arm, [q1, q2])
    Matrix([
    [2*cos(q2) + 3, cos(q2) + 1],
    [  cos(q2) + 1,           1]])
    """
    inertias = _check_chain(chain)
    n = chain.n_joints
    q = _values(q, "q", n)
    with bounded(budget, "mass_matrix"):
        return _composite(chain, inertias, q)


def _composite(chain: Chain, inertias: Sequence[SpatialInertia], q: tuple) -> ImmutableMatrix:
    """:func:`mass_matrix` within the budget under way."""
    n = chain.n_joints
    twists, bodies = _at_floats(chain.twists, [_params(b) for b in inertias], q)
    fast = ring_mass_matrix(twists, Transform.identity(), bodies, q)
    if fast is not None:  # in the ring of the chain (module docstring)
        return fast
    E = [tidy(exp6(t, qi)) for t, qi in zip(twists, q, strict=True)]
    xi = [t.matrix for t in twists]
    H = [[S.Zero] * n for _ in range(n)]
    composite: _Params | None = None
    for k in reversed(range(n)):
        P = bodies[k]
        if composite is not None:  # links k+1 .. n, carried into frame {k}
            Q = _moved_params(composite, E[k + 1], angles=True)
            P = _Params(P.m + Q.m, _step(P.h + Q.h, True), _step(P.I_O + Q.I_O, True))
        composite = P
        W = _step(spatial_matrix(*P) * xi[k], True)
        for i in reversed(range(k + 1)):
            if i < k:
                W = _carry(E[i + 1], W, angles=True)
            charge(STEP_UNITS)
            H[i][k] = H[k][i] = tidy(reciprocal_form(xi[i], W))
    return ImmutableMatrix(H)


def coriolis_matrix(chain: Chain, q: Any, qd: Any, *, mass_matrix: ImmutableMatrix | None = None,
                    budget: int = BUDGET) -> ImmutableMatrix:
    r"""The Coriolis matrix ``C(q, qd)`` in the Christoffel form, n x n, tidied.

    ``C_ij = sum_k c_ijk qd_k`` with the Christoffel symbols
    ``c_ijk = (dH_ij/dq_k + dH_ik/dq_j - dH_jk/dq_i) / 2`` of :func:`mass_matrix`,
    so that ``C qd`` is the velocity part of the torques and
    ``dH/dt - 2 C`` is skew-symmetric (Spong, Hutchinson & Vidyasagar, *Robot
    Modeling and Control*, 2006, Section 7.3, Property 7.1.1 and (7.51)).  The derivatives
    are taken at symbolic joint values and ``q`` substituted after, so ``q``
    may be numbers.  ``mass_matrix=H`` passes ``H(q)`` already computed at the
    distinct symbols ``q`` (so it is not computed again).

    >>> from sympy import symbols
    >>> from screwsym import Chain, Twist
    >>> from screwsym.core.inertia import SpatialInertia
    >>> q1, q2, u1, u2 = symbols("q1 q2 u1 u2", real=True)
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])],
    ...             inertias=[SpatialInertia.point_mass(1, [1, 0, 0]),
    ...                       SpatialInertia.point_mass(1, [2, 0, 0])])
    >>> coriolis_matrix(arm, [q1, q2], [u1, u2])
    Matrix([
    [-u2*sin(q2), (-u1 - u2)*sin(q2)],
    [ u1*sin(q2),                  0]])
    """
    _check_chain(chain)
    n = chain.n_joints
    q = _values(q, "q", n)
    qd = _values(qd, "qd", n)
    if mass_matrix is not None:
        if not all(isinstance(v, Symbol) for v in q) or len(set(q)) != n:
            raise ValueError("q: with mass_matrix=, expected the distinct symbols it is a function of")
        x: list[Any] = list(q)
        H: ImmutableMatrix | None = mass_matrix
    else:
        x = [Dummy(f"q{i}", real=True) for i in range(n)]
        H = None
    with bounded(budget, "coriolis_matrix"):
        if H is None:
            H = _mass_matrix(chain, x)
        dH = []
        for xk in x:
            charge(STEP_UNITS)
            dH.append(H.diff(xk))
        C = [[S.Zero] * n for _ in range(n)]
        for i in range(n):
            for j in range(n):
                charge(STEP_UNITS)
                C[i][j] = sum(
                    ((dH[k][i, j] + dH[j][i, k] - dH[i][j, k]) * qd[k] for k in range(n)), S.Zero
                ) / 2
        charge(STEP_UNITS)
        return tidy(ImmutableMatrix(C).xreplace(dict(zip(x, q, strict=True))))


_mass_matrix = mass_matrix


def regressor(chain: Chain, q: Any, qd: Any, qdd: Any, gravity: Any = None, *,
              budget: int = BUDGET) -> ImmutableMatrix:
    r"""The n x 10n matrix ``Y`` with ``tau(q, qd, qdd) = Y pi``, linear in the inertial parameters.

    ``pi`` stacks the ten parameters of each link, link 1 first, each in the
    order :data:`~screwsym.core.inertia.PARAMETER_NAMES`
    ``[m, mc_x, mc_y, mc_z, I_xx, I_xy, I_yy, I_xz, I_yz, I_zz]`` (pinocchio's),
    expressed in the link-fixed frame that coincides with the space frame at
    home: ``chain.inertias[i].parameters()`` (the first moment and the inertia
    about the space origin at ``q = 0``).  The form identification uses
    (Lynch & Park Section 8.2.2; Atkeson, An & Hollerbach 1986).  Only the chain's
    kinematics enter; its inertias need not be given.

    >>> from sympy import symbols
    >>> from screwsym import Chain, Twist
    >>> q, qd, qdd = symbols("q qd qdd", real=True)
    >>> hinge = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])])
    >>> regressor(hinge, [q], [qd], [qdd], gravity=[0, 0, 0])
    Matrix([[0, 0, 0, 0, 0, 0, 0, 0, 0, qdd]])
    """
    if not hasattr(chain, "twists") or not hasattr(chain, "n_joints"):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    n = chain.n_joints
    q, qd, qdd = (_values(v, name, n) for v, name in ((q, "q"), (qd, "qd"), (qdd, "qdd")))
    pis = [[Dummy(f"{name}_{i}", real=True) for name in PARAMETER_NAMES] for i in range(n)]
    params = []
    for p in pis:
        m, hx, hy, hz, xx, xy, yy, xz, yz, zz = p
        params.append(_Params(m, ImmutableMatrix([hx, hy, hz]),
                              ImmutableMatrix([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])))
    with bounded(budget, "regressor"):
        tau = _rnea(chain.twists, params, q, qd, qdd, _gravity(gravity))
        flat = [x for p in pis for x in p]
        # tau is linear in the parameters: each column is a derivative, free of them
        charge(STEP_UNITS)
        return tidy(tau.jacobian(flat))
