r"""The dynamics of closed loops at a configuration, in the rates of the actuated joints.

A :class:`~screwsym.systems.linkage.Mechanism` with an inertia on each moving link
(``inertias=``) has, at the configuration given, a mass matrix and an inverse
dynamics in the rates of any set of ``k`` actuated one-freedom joints that
determines its motion (``k`` the mobility).  Everything is first and second
order kinematics of the loops (:mod:`~screwsym.systems.topology`,
:mod:`~screwsym.systems.second_order`) and the principle of virtual power.

Velocities.  The joint rates ``qdot`` (``F`` of them) close the loops when
``A qdot = 0``, ``A`` the network matrix (Davies 1981).  Split into the actuated
rates ``qa`` and the passive ones ``qp``: ``A_p qp = -A_a qa``.  The actuated
rates determine the others iff ``A_p`` has full column rank ``F - k`` (else the
passive joints can move with the actuators locked: an *actuation singularity*,
the singularity of the second kind of Gosselin & Angeles for a parallel
mechanism).  Then ``F - k`` rows ``R`` of ``A_p`` are independent, and
``qdot = G qa`` with ``G`` the identity on the actuated rates and
``-A_p[R]^-1 A_a[R]`` on the passive ones: Davies' null space restricted to the
actuated rates.  ``G`` holds wherever ``det A_p[R] != 0``.

Accelerations.  Differentiating the closure, on every loop (Müller 2016)
``sum_i $_i qddot_i + sum_{i<j} [$_i, $_j] qdot_i qdot_j = 0`` in loop order,
stacked ``A qddot + c(qdot) = 0`` (:meth:`Mechanism.quadratic_terms
<screwsym.systems.linkage.Mechanism.quadratic_terms>`), so
``qddot = G qa'' + b`` with ``b`` zero on the actuated rates and
``-A_p[R]^-1 c_R`` on the passive ones.

Links.  Link ``l``'s twist is the sum of the joint twists along the tree path
from the base, ``V_l = P_l qdot`` (:func:`~screwsym.systems.topology.path_matrix`),
and its twist rate (its spatial acceleration, ``dV_l/dt`` in the space frame)
the same chain differentiated, ``P_l qddot + sum_{i<j} [$_i, $_j] qdot_i qdot_j``
along the path (:func:`~screwsym.systems.second_order.chain_terms`).

Dynamics.  Link ``l``'s twist per actuated rate is ``A_l = P_l G``; its momentum
``M_l V_l`` (:class:`~screwsym.core.inertia.SpatialInertia`, ray order) changes
as ``M_l dV_l/dt + [V_l, M_l V_l]`` (the Newton–Euler equation in screw form,
as in :mod:`screwsym.motion.dynamics`).  The constraint wrenches of
frictionless joints do no work on a motion the loops allow, so by virtual power
(Jourdain's principle) the actuator forces are

    tau = sum_l A_l^T Delta (M_l dV_l/dt + [V_l, M_l V_l] - W_l),

``W_l`` the weight of link ``l`` (:meth:`SpatialInertia.gravity_wrench
<screwsym.core.inertia.SpatialInertia.gravity_wrench>`) and ``Delta`` the half
swap, so that ``x^T Delta w`` is the power of the wrench ``w`` on the twist ``x``
(1.45).  The mass matrix, from the kinetic energy
``T = 1/2 sum_l V_l^T Delta M_l V_l``, is ``H = sum_l A_l^T Delta M_l A_l``
(``Delta M_l`` is symmetric), and ``tau = H qa'' + h(qa')``.

Reactions.  The wrench ``w_j`` joint ``j = (a, b)`` exerts on ``b`` (``-w_j`` on ``a``)
solves, with the actuator forces ``tau`` above, each moving link's balance
``sum_j ±w_j = M_l dV_l/dt + [V_l, M_l V_l] - W_l`` and each freedom's reciprocity
``$^T Delta w_j = 0`` (``tau`` on an actuated freedom) (:meth:`Mechanism.joint_reactions
<screwsym.systems.linkage.Mechanism.joint_reactions>`); an overconstrained loop leaves a
self-stress free, set to zero there.

Exact for exact input.  With symbols in the geometry the results are the generic
ones: they hold where ``det A_p[R] != 0`` (:func:`actuation_condition`;
``conds="piecewise"`` returns them with that condition, ``nan`` elsewhere).  With
numbers an actuation singularity is a ``ValueError``; so is a configuration
whose closure does not extend to second order along the rates given (a shaky
one: no acceleration closes the loops).  With symbols the rows outside ``R`` are
taken to close to second order as they do on a genuine configuration.

Floats (the float policy, ``notebooks/float-policy.md``).  The joints are exact (a
mechanism refuses floats in its geometry); floats in the inertias, the actuated rates
and accelerations and the gravity (``-9.81``) are read as the exact rationals of their
binary values (``Rational(0.1)``, not a decimal guess), the computation is exact, and
the result is rounded once to the floats' precision and a guard digit, as
:func:`~screwsym.core.line.common_normal` rounds.  So the passive joints' rates follow
the actuated ones exactly and close the loops to second order (rates rounded joint by
joint would not), and no elimination pivots on a rounding residue.

References
==========

J. M. Davies, "Kirchhoff's circulation law applied to multi-loop kinematic
chains", Mech. Mach. Theory 16 (1981) 171-183.
A. Müller, "Local kinematic analysis of closed-loop linkages", J. Mechanisms
Robotics 8(4) (2016) 041013.
C. Gosselin, J. Angeles, "Singularity analysis of closed-loop kinematic chains",
IEEE Trans. Robotics and Automation 6(3) (1990) 281-290.
L.-W. Tsai, *Robot Analysis*, Wiley 1999, Chapter 9 (virtual work); F. E. Udwadia,
R. E. Kalaba, *Analytical Dynamics*, Cambridge 1996 (Jourdain's principle).
Lynch & Park, *Modern Robotics*, Cambridge 2017, Section 8.2.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any, NamedTuple, cast

from sympy import (
    Add,
    And,
    Float,
    ImmutableMatrix,
    Matrix,
    Ne,
    Poly,
    Rational,
    S,
    Symbol,
    Tuple,
    expand,
    nan,
    radsimp,
    true,
    zeros,
)
from sympy.core.evalf import prec_to_dps
from sympy.polys.matrices import DomainMatrix

from ..algebra.budget import BUDGET, bounded, charge
from ..algebra.linalg import field_matrix, field_rank
from ..algebra.rings import vanishes
from ..core.checks import check_choice, check_count, check_scalar, check_sequence, check_vector
from ..core.conditions import CONDS, piecewise
from ..core.decide import is_zero
from ..core.formulas import bracket
from ..core.inertia import SpatialInertia
from ..core.tidy import tidy
from ..core.twist import Twist
from .second_order import chain_terms, loop_terms
from .topology import bare_network, check_link, link_label, path_matrix, spanning_tree

if TYPE_CHECKING:
    from .linkage import Mechanism

__all__ = ["PlatformDynamics"]  # the rest serves Mechanism's methods; users reach it there

#: the default gravitational acceleration, ``(0, 0, -g)``: the same as
#: :data:`screwsym.motion.dynamics.GRAVITY` (systems does not import motion)
GRAVITY = (S.Zero, S.Zero, -Symbol("g", positive=True))


#: the units charged per symbolic entry tidied or product formed (about a millisecond)
STEP_UNITS = 1000


#: the error past a closed loop's budget (:func:`_bounded`)
_MESSAGE = ("{name}: the exact arithmetic needs more than budget={budget} units (or its CPU "
            "time); give some symbols values (subs) or pass a larger budget")


@contextmanager
def _bounded(budget: Any, name: str) -> Iterator[None]:
    """The exact arithmetic of ``name`` within ``budget`` units (about a microsecond each,
    and the CPU time ``SLACK`` times that: :mod:`screwsym.algebra.budget`); past it a
    ``ValueError`` naming ``name``.  Inside another budget the outer one holds."""
    with bounded(check_count(budget, "budget"), name, _MESSAGE):
        yield


def _charge_matrix(M: Matrix, power: int) -> None:
    """Charge an elimination on ``M`` before it runs: ``n**power`` times the largest entry's
    terms, times ``10**s`` for ``s`` symbols (an angle's sine and cosine count once).

    A single SymPy elimination is not interrupted, so its cost is charged in advance: a
    rough bound on the swell of rational functions in ``s`` symbols, not a calibration.
    Measured: the Delta link by link with one pose symbol (30 x 18, 1e6 units) takes
    seconds; with three (3e7 units) it ran past 4 CPU minutes, and is now refused at once
    by the default budget."""
    n = max(M.rows, M.cols, 1)
    terms = max((len(Add.make_args(e)) for e in M), default=1)
    charge(n**power * terms * 10 ** len(M.free_symbols))


def check_inertias(inertias: Any, links: dict, base: Any) -> Tuple:
    """``inertias`` (a dict link -> SpatialInertia) as the canonical ``Tuple`` of pairs.

    ``links`` maps each link object to its number; the pairs come in that order.
    """
    if isinstance(inertias, Tuple):  # the canonical form (rebuilt by SymPy)
        pairs = [(p.args[0], p.args[1]) for p in inertias.args]
    elif isinstance(inertias, dict):
        pairs = list(inertias.items())
    else:
        raise TypeError(
            f"inertias: expected a dict {{link: SpatialInertia}}, got {type(inertias).__name__}")
    out = {}
    for key, value in pairs:
        link = check_link(key, "inertias")
        label = link_label(link)
        if link not in links:
            raise ValueError(f"inertias: {label!r} is not a link of this mechanism")
        if link == base:
            raise ValueError(f"inertias: {label!r} is the base, which does not move")
        if not isinstance(value, SpatialInertia):
            raise TypeError(f"inertias[{label!r}]: expected a SpatialInertia, got "
                            f"{type(value).__name__}")
        if link in out:
            raise ValueError(f"inertias: {label!r} given twice")
        out[link] = value
    return Tuple(*(Tuple(k, v) for k, v in sorted(out.items(), key=lambda kv: links[kv[0]])))


# ------------------------------------------------------------------ the actuation
@dataclass(frozen=True)
class _Actuation:
    actuated: tuple  # the freedom numbers of the actuated joints, in the order given
    passive: tuple  # the other freedom numbers, in order
    rows: tuple  # R: rows of the network matrix, independent on the passive columns
    G: ImmutableMatrix  # F x k: all joint rates per actuated rate
    det: Any  # det A_p[R] (a non-zero number, or an expression in the symbols)
    condition: Any  # where G holds: True, or Ne(det, 0)
    terms: list  # the loops' second-order terms (loop_terms)
    inverse: ImmutableMatrix  # A_p[R]^-1, (F - k) x (F - k)
    net: Any  # the network (its matrix, tree paths and twists)


def _check_actuated(mech: Mechanism, actuated: Any) -> tuple:
    items = check_sequence(actuated, "actuated", "joint numbers")
    joints = mech.joints
    g = spanning_tree(mech)
    out = []
    for i, a in enumerate(items):
        if isinstance(a, bool) or not isinstance(a, int) and not getattr(a, "is_Integer", False):
            raise TypeError(f"actuated[{i}]: expected a joint number (an int), got {a!r}")
        a = int(a)
        if not 0 <= a < len(joints):
            raise ValueError(f"actuated[{i}]: expected a joint number 0..{len(joints) - 1}, "
                             f"got {a}")
        if joints[a][2].freedom != 1:
            raise ValueError(f"actuated[{i}]: joint {a} has {joints[a][2].freedom} freedoms; an "
                             "actuated joint has one (a revolute, prismatic or helical joint)")
        if g.offsets[a] in out:
            raise ValueError(f"actuated: joint {a} is given twice")
        out.append(g.offsets[a])
    return tuple(out)


def _solve(B: Matrix, C: Matrix) -> Matrix:
    """``B^-1 C`` for a square ``B`` non-singular where the result is used: exact, fraction
    free in the polynomial ring of the entries (``sin(q)``, ``cos(q)`` and roots as its
    symbols: an identity there is one at every value), one denominator."""
    n = B.cols
    dm = DomainMatrix.from_Matrix(Matrix.hstack(B, C))
    K = dm.domain
    num, den = dm[:, :n].solve_den(dm[:, n:])
    d = K.to_sympy(den)
    return num.to_Matrix().applyfunc(lambda e: e / d)


#: the most terms of a determinant factored for the condition (SymPy's multivariate
#: factorisation has no bound; past this the condition is the determinant itself)
FACTOR_TERMS = 300


def _determinant(B: Matrix) -> tuple[Any, Any]:
    """``det B`` and the condition ``det B != 0``: ``True`` for a number, else one ``Ne`` per
    distinct irreducible factor of the determinant in the polynomial ring of its entries
    (``sin(q)``, ``cos(q)`` as independent symbols: a factorisation there holds on the
    circle too), or ``Ne(det, 0)`` where the ring is not a polynomial ring or the
    determinant has more than :data:`FACTOR_TERMS` terms."""
    dm = DomainMatrix.from_Matrix(B)
    K = dm.domain
    d = dm.det()
    det = K.to_sympy(d)
    if not getattr(det, "free_symbols", None):
        return det, true
    if K.is_PolynomialRing and len(d.terms()) <= FACTOR_TERMS:
        charge(len(d.terms()) ** 2)
        factors = [f for f, _ in d.factor_list()[1] if not f.is_ground]
        return det, And(*(Ne(f.as_expr(), 0) for f in factors))
    return det, Ne(det, 0)


@lru_cache(maxsize=64)
def _actuation(mech: Mechanism, actuated: tuple) -> _Actuation:
    # the network matrix without its null space (a generic null space of a symbolic
    # mechanism is dear, and only the rank on the passive columns is needed here)
    net = bare_network(mech)
    A = net.A
    F = A.cols
    k = len(actuated)
    passive = tuple(i for i in range(F) if i not in actuated)
    Ap = A.extract(list(range(A.rows)), list(passive))
    if passive:
        # the independent rows of A_p: exact (generic with symbols, on the circle for angles)
        _charge_matrix(Ap, 3)
        _, rows = field_matrix(Ap.T).rref()
    else:
        rows = ()
    if len(rows) < len(passive):
        _check_count(A, k, mech)
        idle = mech.mobility().passive
        if idle:
            raise ValueError(f"actuated: the mechanism has {idle} idle freedoms {_IDLE_LINK}, "
                             f"which the actuated joints do not determine: {_IDLE_FIX}")
        with_symbols = " at every value of the symbols" if A.free_symbols else ""
        raise ValueError(
            "actuated: an actuation singularity: the passive joints' columns of the network "
            f"matrix have rank {len(rows)} < {len(passive)}{with_symbols}, so the passive "
            "joints move with the actuated ones locked (the actuated rates do not determine "
            "the motion)")
    rows = tuple(rows)
    G = zeros(F, k)
    for c, a in enumerate(actuated):
        G[a, c] = 1
    det: Any = S.One
    inverse = zeros(0, 0)
    condition: Any = true
    if passive:
        B = Ap.extract(list(rows), list(range(len(passive))))
        Aa = A.extract(list(rows), list(actuated))
        _charge_matrix(B, 3)
        inverse = _solve(B, Matrix.eye(len(passive))).applyfunc(_tidy)
        X = inverse * -Aa
        for r, p in enumerate(passive):
            for c in range(k):
                G[p, c] = X[r, c]
        det, condition = _determinant(B)
    G = G.applyfunc(_tidy)
    # the other rows hold too unless the actuated rates are constrained (k > the mobility)
    others = [r for r in range(A.rows) if r not in rows]
    if others and not all(e == 0 or vanishes(e) for e in A.extract(others, list(range(F))) * G):
        _check_count(A, k, mech)
        raise ValueError("actuated: the actuated joints' rates are not independent here")  # pragma: no cover
    return _Actuation(actuated, passive, rows, ImmutableMatrix(G), det,
                      condition, loop_terms(net), ImmutableMatrix(inverse), net)


#: what an idle freedom is, and what to do (the errors of :func:`_actuation`, :func:`_check_count`)
_IDLE_LINK = ("(a link such as a rod between two spherical joints spins about its own axis, "
              "moving nothing else)")
_IDLE_FIX = ("the closed-loop dynamics of mechanisms with idle freedoms are not supported; "
             "replace one spherical joint of each such rod by a universal joint")


def _check_count(A: Matrix, k: int, mech: Mechanism | None = None) -> None:
    """A ``ValueError`` unless ``k`` is the mobility (the generic one with symbols); where
    fewer are given and the mechanism has idle freedoms, the message says so."""
    M = A.cols - field_rank(A)
    if k != M:
        idle = mech.mobility().passive if mech is not None and k < M else 0
        extra = "" if not idle else (f"; {idle} of its freedoms are idle {_IDLE_LINK}: no actuator "
                                     f"drives them, and {_IDLE_FIX}")
        raise ValueError(f"actuated: expected as many actuated joints as the mobility, {M}, "
                         f"got {k}{extra}")


def _tidy(e: Any) -> Any:
    if e.is_Rational:
        return e
    charge(STEP_UNITS if e.free_symbols else 1)
    # a number with roots: denominators rationalised, so that a zero shows as 0
    return tidy(e) if e.free_symbols else radsimp(expand(e))


def _rates(value: Any, name: str, k: int) -> Matrix:
    """The ``k`` actuated rates (or accelerations) given, checked; floats kept (see :func:`_exact`)."""
    items = check_sequence(value, name, "actuated rates", k)
    return Matrix([check_scalar(x, f"{name}[{i}]") for i, x in enumerate(items)])


# ------------------------------------------------------------------ floats (the float policy)
def _exact(value: Any) -> Any:
    """``value`` with every float replaced by the exact rational of its binary value
    (``Rational(0.1) == 3602879701896397/36028797018963968``; not ``nsimplify``'s guess)."""
    floats = value.atoms(Float)
    return value.xreplace({f: Rational(f) for f in floats}) if floats else value


def _digits(*values: Any) -> int | None:
    """The digits a result from floats among ``values`` is rounded to: those of the least
    precise float and one guard digit (16 for double precision, as ``common_normal``
    rounds), or ``None`` when no float is involved (then the result stays exact)."""
    precs = [f._prec for v in values for f in v.atoms(Float)]
    return max(15, prec_to_dps(min(precs)) + 1) if precs else None


def _rounded(value: Any, digits: int | None) -> Any:
    """``value`` (a matrix, or a tuple of wrenches) rounded once to ``digits``, or as it is."""
    if digits is None:
        return value
    if isinstance(value, tuple):
        return tuple(_rounded(v, digits) for v in value)
    return value.evalf(n=digits)


def _inertias(mech: Mechanism) -> list:
    """The mechanism's inertias as given (for :func:`_digits`)."""
    return [p.args[1] for p in mech.inertia_pairs]


def actuation_condition(mech: Mechanism, actuated: Any) -> Any:
    """Where the actuated joints determine the motion: ``True``, or ``Ne(det, 0)``."""
    return _actuation(mech, _check_actuated(mech, actuated)).condition


def joint_rates(mech: Mechanism, actuated: Any, rates: Any) -> ImmutableMatrix:
    act = _actuation(mech, _check_actuated(mech, actuated))
    qa = _rates(rates, "rates", len(act.actuated))
    return _rounded(ImmutableMatrix((act.G * _exact(qa)).applyfunc(_tidy)), _digits(qa))


def _accelerations(mech: Mechanism, act: _Actuation, qd: Matrix, qa2: Matrix) -> Matrix:
    """All joint accelerations for the joint rates ``qd`` and actuated accelerations ``qa2``."""
    A = act.net.A
    c = _quadratic(act.terms, qd)
    qdd = Matrix(act.G * qa2)
    if act.passive:
        b = _matmul(act.inverse, -c.extract(list(act.rows), [0]))
        for r, p in enumerate(act.passive):
            qdd[p] += b[r]
    qdd = qdd.applyfunc(_tidy)
    if not A.free_symbols:
        _check_second_order(act, A, qd)
    return qdd


def _check_second_order(act: _Actuation, A: Matrix, qd: Matrix) -> None:
    """Refuse rates along which the closure does not extend to second order: the rows of the
    differentiated closure outside ``R`` must hold too.  Exact: floats in the rates are taken
    at their exact binary values; rates with symbols must satisfy it identically."""
    qx = qd.applyfunc(lambda e: e.xreplace({f: Rational(f) for f in e.atoms(Float)}))
    c = _quadratic(act.terms, qx)
    b = zeros(A.cols, 1)
    if act.passive:
        x = _matmul(act.inverse, -c.extract(list(act.rows), [0]))
        for r, p in enumerate(act.passive):
            b[p] = x[r]
    residual = _matmul(A, b) + c
    rates = sorted(qx.free_symbols, key=str)
    for e in residual:
        e = expand(e)
        if e == 0:
            continue
        coefficients = Poly(e, *rates).coeffs() if rates else [e]
        if any(is_zero(radsimp(expand(k))) is not True for k in coefficients):
            raise ValueError(
                "rates: the loop closure does not extend to second order along these rates "
                "(no joint accelerations close the loops: a shaky configuration), or that it "
                "does could not be proved")


def _matmul(X: Matrix, Y: Matrix) -> Matrix:
    """``X Y`` exactly: for a numeric ``X`` (a configuration in numbers) in the polynomial
    ring of the entries over the rationals or a number field (the rates as symbols: several
    times faster than SymPy's generic product), else SymPy's product."""
    if X.free_symbols:  # a geometry in symbols: SymPy's own product keeps its forms smaller
        return X * Y
    dx, dy = DomainMatrix.from_Matrix(X), DomainMatrix.from_Matrix(Y)
    dx, dy = dx.unify(dy)
    K = dx.domain
    ground = K.domain if K.is_PolynomialRing else K
    if not (ground.is_QQ or ground.is_ZZ or ground.is_AlgebraicField):
        return X * Y
    return (dx * dy).to_Matrix()


def _quadratic(terms: list, qd: Matrix) -> Matrix:
    """The second-order terms of each chain of ``terms`` for the joint rates ``qd``, stacked."""
    out = zeros(6 * len(terms), 1)
    for i, (pairs, squares) in enumerate(terms):
        for a, b, c in pairs:
            out[6 * i:6 * i + 6, 0] += Matrix(c) * qd[a] * qd[b]
        for a, y in squares:
            out[6 * i:6 * i + 6, 0] += Matrix(y) * qd[a] ** 2
    return out


def joint_accelerations(mech: Mechanism, actuated: Any, rates: Any,
                        accelerations: Any) -> ImmutableMatrix:
    act = _actuation(mech, _check_actuated(mech, actuated))
    k = len(act.actuated)
    qa, qa2 = _rates(rates, "rates", k), _rates(accelerations, "accelerations", k)
    qdd = _accelerations(mech, act, act.G * _exact(qa), _exact(qa2))
    return _rounded(ImmutableMatrix(qdd), _digits(qa, qa2))


def _link(mech: Mechanism, link: Any) -> int:
    key = check_link(link, "link")
    g = spanning_tree(mech)
    if key not in g.index:
        raise ValueError(f"link: {link_label(key)!r} is not a link of this mechanism")
    return int(g.index[key])


def _twist(V: Matrix) -> Twist:
    V = V.applyfunc(_tidy)
    return Twist(V[:3, 0], V[3:, 0])


def link_twist(mech: Mechanism, link: Any, actuated: Any, rates: Any) -> Twist:
    act = _actuation(mech, _check_actuated(mech, actuated))
    qa = _rates(rates, "rates", len(act.actuated))
    return _rounded(_twist(path_matrix(act.net, _link(mech, link)) * act.G * _exact(qa)),
                    _digits(qa))


def _link_rate(act: _Actuation, n: int, qd: Matrix, qdd: Matrix) -> Matrix:
    net = act.net
    return path_matrix(net, n) * qdd + _quadratic([chain_terms(net, net.graph.paths[n])], qd)


def link_acceleration(mech: Mechanism, link: Any, actuated: Any, rates: Any,
                      accelerations: Any) -> Twist:
    act = _actuation(mech, _check_actuated(mech, actuated))
    k = len(act.actuated)
    qa, qa2 = _rates(rates, "rates", k), _rates(accelerations, "accelerations", k)
    qd = Matrix(act.G * _exact(qa))
    n = _link(mech, link)
    return _rounded(_twist(_link_rate(act, n, qd, _accelerations(mech, act, qd, _exact(qa2)))),
                    _digits(qa, qa2))


def _bodies(mech: Mechanism) -> list[tuple[int, Matrix, SpatialInertia]]:
    """Per body: its link number, its 6 x 6 inertia matrix and a point mass at its centre of
    mass (for its weight), floats taken as their exact binary values (:func:`_exact`)."""
    g = spanning_tree(mech)
    out = []
    for p in mech.inertia_pairs:
        I = p.args[1]
        point = SpatialInertia.point_mass(_exact(I.mass), _exact(I.com))  # the weight's source
        out.append((int(g.index[p.args[0]]), Matrix(_exact(I.matrix)), point))
    return out


def _power_rows(mech: Mechanism, act: _Actuation) -> list[tuple[Matrix, Matrix, Matrix]]:
    """Per body: ``P_l``, ``A_l^T Delta`` (k x 6) and its inertia matrix (exact)."""
    net = act.net
    out = []
    for n, M, _ in _bodies(mech):
        P = path_matrix(net, n)
        Al = P * act.G
        swapped = Matrix.hstack(Al[3:, :].T, Al[:3, :].T)  # A_l^T Delta
        out.append((P, swapped, M))
    return out


def _conds(value: ImmutableMatrix, act: _Actuation, conds: str) -> ImmutableMatrix:
    """``value``, or with ``conds="piecewise"`` each entry where the actuation holds, nan elsewhere."""
    if conds == "none" or act.condition is true:
        return value
    return ImmutableMatrix(piecewise([(value, act.condition)], value.applyfunc(lambda _: nan)))


def mass_matrix(mech: Mechanism, actuated: Any, conds: str = "none") -> ImmutableMatrix:
    conds = check_choice(conds, "conds", CONDS)
    act = _actuation(mech, _check_actuated(mech, actuated))
    H = _rounded(ImmutableMatrix(_mass(mech, act)), _digits(*_inertias(mech)))
    return _conds(H, act, conds)


def _mass(mech: Mechanism, act: _Actuation) -> Matrix:
    """``H = sum_l A_l^T Delta M_l A_l``, exact (floats read exactly), tidied."""
    k = len(act.actuated)
    H = zeros(k, k)
    for P, swapped, M in _power_rows(mech, act):
        charge(STEP_UNITS * k * k)
        H += swapped * M * (P * act.G)
    return H.applyfunc(_tidy)


def _motion(mech: Mechanism, act: _Actuation, rates: Any, accelerations: Any,
            gravity: Any) -> tuple[Matrix, Matrix, Matrix, int | None]:
    """All joints' rates and accelerations for the actuated ones, the gravity vector, and
    the digits the results are rounded to (:func:`_digits`: ``None`` for exact input).

    Floats in the actuated rates, accelerations, gravity and inertias are taken as their
    exact binary values (:func:`_exact`) and the other joints' rates and accelerations
    follow exactly, so they close the loops exactly (rates rounded joint by joint would
    not, and the second-order check would refuse them)."""
    k = len(act.actuated)
    qa, qa2 = _rates(rates, "rates", k), _rates(accelerations, "accelerations", k)
    g = check_vector(GRAVITY if gravity is None else gravity, "gravity")
    digits = _digits(qa, qa2, g, *_inertias(mech))
    qd = Matrix(act.G * _exact(qa))
    return qd, _accelerations(mech, act, qd, _exact(qa2)), _exact(g), digits


def _balances(mech: Mechanism, act: _Actuation, qd: Matrix, qdd: Matrix,
              g: Any) -> list[tuple[int, Matrix, Matrix]]:
    """Per body: its link number, ``A_l^T Delta`` and the wrench its motion needs,
    ``M_l dV_l/dt + [V_l, M_l V_l] - W_l``."""
    out = []
    for (P, swapped, M), (n, _, point) in zip(_power_rows(mech, act), _bodies(mech), strict=True):
        charge(STEP_UNITS * len(act.actuated))
        V = P * qd
        Vdot = _link_rate(act, n, qd, qdd)
        weight = point.gravity_wrench(g).matrix
        out.append((n, swapped, M * Vdot + Matrix(bracket(V, M * V)) - weight))
    return out


def _forces(act: _Actuation, balances: list) -> Matrix:
    """The actuator forces by virtual power: ``sum_l A_l^T Delta D_l``."""
    tau = zeros(len(act.actuated), 1)
    for _, swapped, D in balances:
        tau += swapped * D
    return tau


def inverse_dynamics(mech: Mechanism, actuated: Any, rates: Any, accelerations: Any,
                     gravity: Any = None, conds: str = "none") -> ImmutableMatrix:
    conds = check_choice(conds, "conds", CONDS)
    act = _actuation(mech, _check_actuated(mech, actuated))
    qd, qdd, g, digits = _motion(mech, act, rates, accelerations, gravity)
    tau = _forces(act, _balances(mech, act, qd, qdd, g))
    return _conds(_rounded(ImmutableMatrix(tau.applyfunc(_tidy)), digits), act, conds)


def _reaction_system(act: _Actuation, tau: Matrix, balances: list) -> tuple[Matrix, Matrix]:
    """The linear system ``K w = r`` of the joints' wrenches ``w`` (6 per joint, ray order,
    joint by joint): each moving link's Newton–Euler balance (``balances``, from
    :func:`_balances`), then each freedom's reciprocity (zero power on a passive freedom,
    ``tau`` on an actuated one)."""
    net = act.net
    graph = net.graph
    J, L = len(graph.edges), len(graph.links)
    F = net.A.cols
    K = zeros(6 * (L - 1) + F, 6 * J)
    r = zeros(6 * (L - 1) + F, 1)
    for e, (a, b, _) in enumerate(graph.edges):
        for link, sign in ((b, 1), (a, -1)):
            if link:
                for i in range(6):
                    K[6 * (link - 1) + i, 6 * e + i] += sign
        for k, t in enumerate(net.twists[e]):
            row = 6 * (L - 1) + graph.offsets[e] + k
            for i in range(3):  # t^T Delta w = omega . m + v . f
                K[row, 6 * e + i] = t[3 + i]
                K[row, 6 * e + 3 + i] = t[i]
    for c, f in enumerate(act.actuated):
        r[6 * (L - 1) + f, 0] = tau[c]
    for n, _, D in balances:
        r[6 * (n - 1):6 * n, 0] = D
    return K, r


def joint_reactions(mech: Mechanism, actuated: Any, rates: Any, accelerations: Any,
                    gravity: Any = None) -> tuple:
    from ..core.wrench import Wrench

    act = _actuation(mech, _check_actuated(mech, actuated))
    qd, qdd, g, digits = _motion(mech, act, rates, accelerations, gravity)
    balances = _balances(mech, act, qd, qdd, g)
    tau = _forces(act, balances).applyfunc(_tidy)
    K, r = _reaction_system(act, tau, balances)
    aug = Matrix.hstack(K, r)
    _charge_matrix(aug, 3)
    dm = DomainMatrix.from_Matrix(aug).to_field()
    reduced, pivots = dm.rref()
    if K.cols in pivots:  # pragma: no cover - tau is the virtual-power balance
        raise ValueError("the Newton-Euler balance of the links has no solution with these "
                         "actuator forces (inconsistent input)")
    R = reduced.to_Matrix()
    w = zeros(K.cols, 1)
    for i, p in enumerate(pivots):
        w[p, 0] = R[i, K.cols]  # the free unknowns (a self-stress) are zero
    w = w.applyfunc(_tidy)
    return _rounded(tuple(Wrench(w[6 * e:6 * e + 3, 0], w[6 * e + 3:6 * e + 6, 0])
                          for e in range(len(act.net.graph.edges))), digits)


# ------------------------------------------------------------------ the platform's coordinates
#: the names of a platform twist's components at the reference point: ``(omega; v_P)``
COMPONENTS = ("wx", "wy", "wz", "vx", "vy", "vz")


class PlatformDynamics(NamedTuple):
    """The dynamics of a mechanism in its platform's coordinates
    (:meth:`Mechanism.platform_dynamics <screwsym.systems.linkage.Mechanism.platform_dynamics>`)."""

    #: the names of the ``k`` platform coordinates, from ``wx wy wz`` (the angular
    #: velocity) and ``vx vy vz`` (the velocity of the platform's point at ``point``)
    coordinates: tuple
    #: ``J`` (k x k): the actuated rates per platform rate, ``qa' = J x'`` (Tsai's ``J``)
    jacobian: ImmutableMatrix
    #: ``Lambda = J^T H J`` (k x k): the kinetic energy is ``1/2 x'^T Lambda x'``
    mass_matrix: ImmutableMatrix
    #: ``F`` (k x 1): the generalised forces on the platform coordinates, ``J^T tau``
    #: (``None`` without a state)
    forces: ImmutableMatrix | None
    #: ``tau = J^-T F`` (k x 1): the actuator forces (``None`` without a state)
    actuator_forces: ImmutableMatrix | None


def _skew(p: Matrix) -> Matrix:
    return Matrix([[0, -p[2], p[1]], [p[2], 0, -p[0]], [-p[1], p[0], 0]])


def _coordinates(value: Any, X: Matrix) -> tuple[int, ...]:
    """The rows of ``X`` (6 x k, the platform twist at the point per actuated rate) named by
    ``value``, or with ``None`` the first ``k`` independent ones in the order ``COMPONENTS``."""
    k = X.cols
    if value is None:
        _charge_matrix(X, 3)
        _, pivots = field_matrix(X.T).rref()
        if len(pivots) < k:
            raise ValueError(
                f"platform: its twist has rank {len(pivots)} < {k} in the actuated rates, so "
                "its motion does not determine the actuated joints' (name a link the "
                "actuators all move)")
        return tuple(pivots[:k])
    names = check_sequence(value, "coordinates", "component names", k)
    rows = []
    for i, c in enumerate(names):
        if c not in COMPONENTS:
            raise ValueError(f"coordinates[{i}]: expected one of {', '.join(COMPONENTS)}, got {c!r}")
        if COMPONENTS.index(c) in rows:
            raise ValueError(f"coordinates: {c!r} given twice")
        rows.append(COMPONENTS.index(c))
    return tuple(rows)


def platform_dynamics(mech: Mechanism, actuated: Any, rates: Any, accelerations: Any,
                      gravity: Any, platform: Any, point: Any, coordinates: Any,
                      conds: str) -> PlatformDynamics:
    conds = check_choice(conds, "conds", CONDS)
    act = _actuation(mech, _check_actuated(mech, actuated))
    k = len(act.actuated)
    n = _link(mech, platform)
    c = _exact(check_vector([0, 0, 0] if point is None else point, "point"))
    if (rates is None) != (accelerations is None):
        raise ValueError("rates, accelerations: give both (a state) or neither (the mass "
                         "matrix and the Jacobian alone)")
    # the platform twist at the point per actuated rate: omega; v_P = v_O - c x omega
    shift = Matrix.vstack(Matrix.hstack(Matrix.eye(3), zeros(3, 3)),
                          Matrix.hstack(-_skew(c), Matrix.eye(3)))
    X = (shift * path_matrix(act.net, n) * act.G).applyfunc(_tidy)
    rows = _coordinates(coordinates, X)
    B = X.extract(list(rows), list(range(k)))  # x' = B qa'
    charge(STEP_UNITS * k**3)
    det, condition = _determinant(B)
    if det == 0 or not det.free_symbols and vanishes(det):
        raise ValueError(
            f"coordinates: the platform rates {', '.join(COMPONENTS[r] for r in rows)} do not "
            "determine the actuated rates here (the actuators move with them held: a "
            "singularity of the first kind, or coordinates that miss a freedom)")
    J = _solve(B, Matrix.eye(k)).applyfunc(_tidy)
    digits = _digits(*_inertias(mech))
    Lam = (J.T * _mass(mech, act) * J).applyfunc(_tidy)
    forces = tau = None
    if rates is not None:
        xd, xdd = _rates(rates, "rates", k), _rates(accelerations, "accelerations", k)
        g = check_vector(GRAVITY if gravity is None else gravity, "gravity")
        digits = _digits(xd, xdd, g, *_inertias(mech))
        qa = J * _exact(xd)
        qd = act.G * qa
        # the platform's accelerations with the actuated ones zero: x'' = B qa'' + b
        rest = _link_rate(act, n, qd, _accelerations(mech, act, qd, zeros(k, 1)))
        V = path_matrix(act.net, n) * qd
        w, v, wd, vd = V[:3, 0], V[3:, 0], rest[:3, 0], rest[3:, 0]
        a = vd + wd.cross(c) + w.cross(v + w.cross(c))  # the point's acceleration
        b = Matrix.vstack(wd, a).extract(list(rows), [0])
        qa2 = (J * (_exact(xdd) - b)).applyfunc(_tidy)
        qdd = _accelerations(mech, act, qd, qa2)
        tau = _forces(act, _balances(mech, act, qd, qdd, _exact(g))).applyfunc(_tidy)
        forces = (J.T * tau).applyfunc(_tidy)
    if act.condition is not true or condition is not true:
        condition = And(act.condition, condition)
    else:
        condition = true

    def out(M: Any) -> Any:
        if M is None:
            return None
        M = _rounded(ImmutableMatrix(M), digits)
        if conds == "none" or condition is true:
            return M
        return ImmutableMatrix(piecewise([(M, condition)], M.applyfunc(lambda _: nan)))

    return PlatformDynamics(tuple(COMPONENTS[r] for r in rows), out(J), out(Lam), out(forces),
                            out(tau))


class LoopDynamicsMixin:
    """The closed-loop dynamics methods of :class:`~screwsym.systems.linkage.Mechanism`
    (a module of their own: see the module docstring)."""

    __slots__ = ()

    def actuation_condition(self, actuated: Any, *, budget: int = BUDGET) -> Any:
        """Where the joints ``actuated`` (numbers into :attr:`joints`) determine the motion.

        ``True`` with numbers (an actuation singularity is a ``ValueError``); with
        symbols ``Ne(det, 0)``, ``det`` the minor of the passive joints' columns of
        the network matrix the results of :meth:`joint_rates`,
        :meth:`mass_matrix` and :meth:`inverse_dynamics` are solved on (see :mod:`~screwsym.systems.loop_dynamics`).

        The four-bar whose coupler-rocker joint is at ``(x, y)``: the crank drives it
        except where that joint lies on the line from the crank pin ``(1, 2)`` to the
        rocker pivot ``(4, 0)`` (coupler and rocker in line: Gosselin & Angeles' second kind).

        >>> from sympy import symbols
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> x, y = symbols("x y", real=True)
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([x, y, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.actuation_condition([0])
        Ne(2*x + 3*y - 8, 0)
        """
        with _bounded(budget, "actuation_condition"):
            return actuation_condition(cast("Mechanism", self), actuated)

    def joint_rates(self, actuated: Any, rates: Any, *, budget: int = BUDGET) -> ImmutableMatrix:
        """All joint rates (F, the joints' freedoms in order) from the ``rates`` of the joints
        ``actuated``: Davies' null space restricted to the actuated rates (see
        :mod:`~screwsym.systems.loop_dynamics`).

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.joint_rates([0], [5]).T      # the coupler turns at 5 - 60/7 = -25/7
        Matrix([[5, -60/7, 40/7, -15/7]])

        Signs: a joint ``(a, b, joint)``'s rate is the coefficient of its twist as given,
        the motion of ``b`` relative to ``a`` about the axis as directed.  The last joint
        above is written ``("rocker", "ground", ...)``: its rate ``-15/7`` is the ground's
        turn relative to the rocker, so the rocker turns at ``+15/7`` relative to the
        ground.  Reversing a joint's pair or its axis reverses its rate, and an actuated
        joint's force with it (:meth:`inverse_dynamics`).

        >>> flipped = Mechanism(fourbar.joints[:3] + (("ground", "rocker", R([4, 0, 0], z)),),
        ...                     base="ground")
        >>> flipped.joint_rates([0], [5]).T
        Matrix([[5, -60/7, 40/7, 15/7]])
        """
        with _bounded(budget, "joint_rates"):
            return joint_rates(cast("Mechanism", self), actuated, rates)

    def joint_accelerations(self, actuated: Any, rates: Any, accelerations: Any, *,
                            budget: int = BUDGET) -> ImmutableMatrix:
        """All joint accelerations from the actuated joints' ``rates`` and ``accelerations``:
        the differentiated closure ``A qddot + quadratic_terms(qdot) = 0`` solved for the
        passive ones (see :mod:`~screwsym.systems.loop_dynamics`).  A configuration whose
        closure does not extend to second order along the rates is a ``ValueError``.

        A crank turning steadily at 5 still accelerates the other joints:

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.joint_accelerations([0], [5], [0]).T
        Matrix([[0, 4500/343, 3300/343, -7800/343]])
        """
        with _bounded(budget, "joint_accelerations"):
            return joint_accelerations(cast("Mechanism", self), actuated, rates, accelerations)

    def link_twist(self, link: Any, actuated: Any, rates: Any, *, budget: int = BUDGET) -> Twist:
        """The twist of ``link`` (space frame, ray order) for the actuated joints' ``rates``.

        The coupler turns about its instant centre ``(12/5, 24/5)``:

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.link_twist("coupler", [0], [7])
        Twist([0, 0, -5], [-24, 12, 0])
        """
        with _bounded(budget, "link_twist"):
            return link_twist(cast("Mechanism", self), link, actuated, rates)

    def link_acceleration(self, link: Any, actuated: Any, rates: Any, accelerations: Any, *,
                          budget: int = BUDGET) -> Twist:
        """The twist rate ``dV/dt`` of ``link`` (its spatial acceleration, space frame, ray
        order) for the actuated joints' ``rates`` and ``accelerations``.

        The rate of change of the twist ``(omega; v_O)``, not a point's acceleration: a
        crank turning steadily about a fixed axis has a constant twist.

        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground")
        >>> fourbar.link_acceleration("crank", [0], [1], [0])
        Twist([0, 0, 0], [0, 0, 0])
        >>> fourbar.link_acceleration("coupler", [0], [7], [0])
        Twist([0, 0, 180/7], [-228/7, -1356/7, 0])
        """
        with _bounded(budget, "link_acceleration"):
            return link_acceleration(cast("Mechanism", self), link, actuated, rates, accelerations)

    def mass_matrix(self, actuated: Any, *, conds: str = "none",
                    budget: int = BUDGET) -> ImmutableMatrix:
        r"""The k x k mass matrix in the rates of the joints ``actuated`` (k, the mobility).

        Explanation
        ===========

        ``H = sum_l A_l^T Delta M_l A_l``, ``A_l`` link ``l``'s twist per actuated
        rate and ``M_l`` its inertia (``inertias=``): the kinetic energy of the
        mechanism is ``1/2 qa^T H qa``.  A joint's rate is the coefficient of its twist
        as given (a unit axis: radians or lengths per unit time).  Exact; generic with symbols, holding where
        :meth:`actuation_condition` does (``conds="piecewise"``: each entry a
        ``Piecewise`` with that condition, ``nan`` elsewhere).  An actuation
        singularity (the passive joints move with the actuated ones locked) is a
        ``ValueError``.  ``budget`` bounds the exact arithmetic (units of about a
        microsecond, and the CPU time: :mod:`screwsym.algebra.budget`; every method here
        takes it).  See :mod:`~screwsym.systems.loop_dynamics`.

        Examples
        ========

        A four-bar driven by its crank, a point mass of 1 at the coupler joint
        ``(1, 2, 0)`` on the crank and one of 2 at ``(3, 3, 0)`` on the rocker
        (about ``(4, 0, 0)``, at distance ``sqrt(10)``).  Per unit crank rate the
        first moves at speed ``sqrt(5)`` and the rocker turns at ``3/7``
        (:meth:`joint_rates <screwsym.systems.linkage.Mechanism.joint_rates>`), so ``H = 1 * 5 + 2 * (3/7)**2 * 10 = 425/49``.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> fourbar.mass_matrix([0])
        Matrix([[425/49]])
        """
        with _bounded(budget, "mass_matrix"):
            return mass_matrix(cast("Mechanism", self), actuated, conds)

    def inverse_dynamics(self, actuated: Any, rates: Any, accelerations: Any,
                         gravity: Any = None, *, conds: str = "none",
                         budget: int = BUDGET) -> ImmutableMatrix:
        r"""The forces or torques of the joints ``actuated`` for their ``rates`` and
        ``accelerations``, every other joint passive and frictionless.

        Explanation
        ===========

        By virtual power (Jourdain's principle):
        ``tau = sum_l A_l^T Delta (M_l dV_l/dt + [V_l, M_l V_l] - W_l)``, ``V_l``
        link ``l``'s twist, ``dV_l/dt`` its twist rate (:meth:`link_acceleration`),
        ``W_l`` its weight under ``gravity`` (default ``(0, 0, -g)``, ``g`` a
        positive symbol).  Exact; generic with symbols as :meth:`mass_matrix`.

        Signs: each force is the one that does positive work on its joint's rate as
        :meth:`joint_rates` counts it, the motion of the joint's second link relative
        to its first about the axis as given.  Reversing an actuated joint's pair
        ``(a, b)`` or its axis reverses its rate and its force: ask for the rates in the
        orientation the joints were written in.  The wrench each joint transmits, the
        actuator's included, is :meth:`joint_reactions`.

        Examples
        ========

        The four-bar of :meth:`mass_matrix` at rest, gravity ``-10`` along y.  Per
        unit crank rate the first mass rises at ``1`` and the second at ``-3/7``
        (it moves with ``3/7 * (-3, -1)``), so by virtual work the crank holds
        ``1 * 10 * 1 + 2 * 10 * (-3/7) = 10/7``.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> fourbar.inverse_dynamics([0], [0], [0], [0, -10, 0])
        Matrix([[10/7]])
        """
        with _bounded(budget, "inverse_dynamics"):
            return inverse_dynamics(cast("Mechanism", self), actuated, rates, accelerations, gravity, conds)

    def platform_dynamics(self, actuated: Any, rates: Any = None, accelerations: Any = None,
                          gravity: Any = None, *, platform: Any = "platform", point: Any = None,
                          coordinates: Any = None, conds: str = "none",
                          budget: int = BUDGET) -> PlatformDynamics:
        r"""The dynamics in the coordinates of the link ``platform`` (its pose rates): the
        form of Tsai's virtual-work model and of Codourey's model of the Delta.

        Explanation
        ===========

        The platform's coordinates are ``k`` components (k, the mobility) of its twist
        written at the reference point ``point`` (default the origin): ``wx wy wz``, its
        angular velocity, and ``vx vy vz``, the velocity of its point at ``point``; their
        rates ``x''`` are the angular acceleration and that point's acceleration.  With
        ``coordinates=None`` the first ``k`` components, in that order, that the platform's
        motion leaves independent (``vx vy vz`` for a Delta, ``wz vx vy`` for a planar
        platform); or name them, e.g. ``("vx", "vy", "wz")``.  For a translating platform
        these are the rates of its position; with a rotation ``wx wy wz`` are angular
        velocities (quasi-velocities), not rates of angles.

        ``J`` is the actuated rates per platform rate, ``qa' = J x'`` (Tsai's ``J``, the
        inverse of the platform's twist per actuated rate; for a parallel mechanism the
        rows of :meth:`ParallelMechanism.jacobian
        <screwsym.systems.parallel.ParallelMechanism.jacobian>`'s ``Jx t = Jq qa'`` on the
        actuation wrenches, ``t`` the platform twist in these coordinates).  By virtual
        power the generalised forces on the platform coordinates are ``F = J^T tau`` and
        the actuator forces ``tau = J^-T F`` (Tsai 1999, §9.6); the kinetic energy
        ``1/2 qa'^T H qa'`` (:meth:`mass_matrix`) is ``1/2 x'^T Lambda x'`` with
        ``Lambda = J^T H J``.  Given the platform's ``rates`` and ``accelerations`` (``k``
        each) the actuated ones are ``qa' = J x'`` and ``qa'' = J (x'' - b)``, ``b`` the
        platform's accelerations with ``qa'' = 0``, and ``tau`` is :meth:`inverse_dynamics`'s
        there.  Without a state only ``J`` and ``Lambda`` (``forces`` and
        ``actuator_forces`` are ``None``).

        Exact for exact input (floats as in :meth:`inverse_dynamics`); generic with symbols,
        holding where the actuated joints determine the motion (:meth:`actuation_condition`)
        and ``det J^-1 != 0`` (``conds="piecewise"``: each result a ``Piecewise`` with that
        condition).  Coordinates that do not determine the actuated rates here (a
        singularity of the first kind) are a ``ValueError``.

        Examples
        ========

        The four-bar of :meth:`mass_matrix`, its coupler as the "platform": it turns at
        ``-5/7`` per unit crank rate (:meth:`joint_rates`: ``5 - 60/7`` for ``5``), so
        ``J = -7/5`` and ``Lambda = (7/5)**2 * 425/49 = 17``; at rest under gravity ``-10``
        along y the crank holds ``10/7``, a torque ``F = J tau = -2`` on the coupler.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> pd = fourbar.platform_dynamics([0], [0], [0], [0, -10, 0], platform="coupler")
        >>> pd.coordinates, pd.jacobian, pd.mass_matrix
        (('wz',), Matrix([[-7/5]]), Matrix([[17]]))
        >>> pd.forces, pd.actuator_forces
        (Matrix([[-2]]), Matrix([[10/7]]))

        References
        ==========

        L.-W. Tsai, *Robot Analysis*, Wiley 1999, §9.6 (virtual work); L.-W. Tsai, "Solving
        the inverse dynamics of a Stewart-Gough manipulator by the principle of virtual
        work", J. Mech. Design 122 (2000) 3-9; A. Codourey, "Dynamic modeling of parallel
        robots for computed-torque control implementation", Int. J. Robotics Research
        17(12) (1998) 1325-1336.
        """
        with _bounded(budget, "platform_dynamics"):
            return platform_dynamics(cast("Mechanism", self), actuated, rates, accelerations,
                                     gravity, platform, point, coordinates, conds)

    def joint_reactions(self, actuated: Any, rates: Any, accelerations: Any,
                        gravity: Any = None, *, budget: int = BUDGET) -> tuple:
        r"""The wrench each joint transmits, for the actuated joints' ``rates`` and
        ``accelerations`` driven by the forces of :meth:`inverse_dynamics`.

        Explanation
        ===========

        One :class:`~screwsym.core.wrench.Wrench` per joint, in the order of
        :attr:`joints`: the wrench the joint ``(a, b, joint)`` exerts on ``b`` (``a``
        bears its opposite), in the space frame, ray order ``(f; C_O)``.  The links'
        Newton–Euler balances, ``sum of the joint wrenches on l = M_l dV_l/dt +
        [V_l, M_l V_l] - W_l``, with each joint's wrench reciprocal to its twists
        (``$^T Delta w = 0``: no power on a passive freedom), except an actuated
        joint's, whose power on its unit twist is the actuator force: the reaction
        includes the actuator.  Exact for exact input; generic with symbols, holding
        where :meth:`actuation_condition` does.

        Where the loops are overconstrained (a planar linkage of revolutes: its forces
        along the axes and its moments about lines in the plane) the balances
        determine the reactions only up to a *self-stress*, a set of joint wrenches
        in equilibrium on every link by themselves; the solution returned sets the
        undetermined unknowns (the free columns of the reduced echelon form, the last
        joints' last components first) to zero.  For a planar linkage loaded in its
        plane that is the planar solution: the in-plane forces are the unique ones.

        Examples
        ========

        The four-bar of :meth:`mass_matrix` at rest under gravity ``-10`` along y.
        The crank, a point mass of 1 at its pin ``(1, 2, 0)`` held by the torque
        ``10/7``: the ground pin's wrench on it has moment ``10/7`` about z at ``O``,
        and its power on the crank's unit twist is that torque; the coupler's pin
        does no work on its joint.

        >>> from screwsym.core.inertia import SpatialInertia
        >>> from screwsym.core.twist import Twist
        >>> from screwsym.systems.linkage import Mechanism
        >>> from screwsym.systems.joints import R
        >>> z = [0, 0, 1]
        >>> fourbar = Mechanism([("ground", "crank", R([0, 0, 0], z)),
        ...                      ("crank", "coupler", R([1, 2, 0], z)),
        ...                      ("coupler", "rocker", R([3, 3, 0], z)),
        ...                      ("rocker", "ground", R([4, 0, 0], z))], base="ground",
        ...                     inertias={"crank": SpatialInertia.point_mass(1, [1, 2, 0]),
        ...                               "rocker": SpatialInertia.point_mass(2, [3, 3, 0])})
        >>> w = fourbar.joint_reactions([0], [0], [0], [0, -10, 0])
        >>> w[0]
        Wrench([40/7, 90/7, 0], [0, 0, 10/7])
        >>> w[1]                    # along the massless coupler, (2, 1)
        Wrench([40/7, 20/7, 0], [0, 0, -60/7])
        >>> from screwsym.core.wrench import power
        >>> [power(j.twists.screws[0], r) for (_, _, j), r in zip(fourbar.joints, w)]
        [10/7, 0, 0, 0]
        """
        with _bounded(budget, "joint_reactions"):
            return joint_reactions(cast("Mechanism", self), actuated, rates, accelerations,
                                   gravity)
