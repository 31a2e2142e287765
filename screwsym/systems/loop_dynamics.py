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
self-stress free, set to zero there, and given as a basis on request (``self_stress=True``:
``6 L - rank`` of them, the statics dual of the network matrix).

Platform coordinates.  In ``k`` components ``x'`` of a platform's twist at a reference point
(:meth:`Mechanism.platform_dynamics <screwsym.systems.linkage.Mechanism.platform_dynamics>`),
``qa' = J x'``, ``Lambda = J^T H J`` and ``tau = J^-T F``: the form of Tsai's virtual-work
model and of Codourey's model of the Delta.

Redundant actuation.  With more actuated joints than the mobility the forces are fixed only
up to internal forces that do no work; :meth:`Mechanism.redundant_inverse_dynamics
<screwsym.systems.linkage.Mechanism.redundant_inverse_dynamics>` gives the least-norm ones
and a basis of the others.

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
from typing import TYPE_CHECKING, Any, NamedTuple

from sympy import (
    Add,
    And,
    Float,
    ImmutableMatrix,
    Matrix,
    Ne,
    Poly,
    Pow,
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

from ..algebra.budget import bounded, charge
from ..algebra.linalg import field_matrix, field_rank
from ..algebra.rings import vanishes
from ..core.checks import (
    check_choice,
    check_count,
    check_flag,
    check_scalar,
    check_sequence,
    check_vector,
)
from ..core.conditions import CONDS, piecewise
from ..core.decide import float_tau, is_zero, is_zero_scaled
from ..core.formulas import bracket
from ..core.inertia import SpatialInertia
from ..core.tidy import tidy
from ..core.twist import Twist
from .second_order import chain_terms, loop_terms
from .topology import bare_network, check_link, link_label, path_matrix, spanning_tree

if TYPE_CHECKING:
    from .linkage import Mechanism

__all__ = ["PlatformDynamics", "RedundantForces"]  # the rest serves Mechanism's methods; users reach it there

#: the default gravitational acceleration, ``(0, 0, -g)``: the same as
#: :data:`screwsym.motion.dynamics.GRAVITY` (systems does not import motion)
GRAVITY = (S.Zero, S.Zero, -Symbol("g", positive=True))


#: the units charged per symbolic entry tidied or product formed (about a millisecond)
STEP_UNITS = 1000


#: the error past a closed loop's budget (:func:`bounded_call`)
_MESSAGE = ("{name}: the exact arithmetic needs more than budget={budget} units (or its CPU "
            "time); give some symbols values (subs) or pass a larger budget")


@contextmanager
def bounded_call(budget: Any, name: str) -> Iterator[None]:
    """The exact arithmetic of ``name`` within ``budget`` units (about a microsecond each,
    and the CPU time ``SLACK`` times that: :mod:`screwsym.algebra.budget`); past it a
    ``ValueError`` naming ``name``.  Inside another budget the outer one holds."""
    with bounded(check_count(budget, "budget"), name, _MESSAGE):
        yield


_bounded = bounded_call  # its name before the methods moved to loop_methods


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


def _domain_matrix(M: Matrix) -> DomainMatrix:
    """``M`` as a ``DomainMatrix``: numbers over their field (QQ or a number field such as
    ``QQ<sqrt(3)>``, :func:`~screwsym.algebra.linalg.field_matrix`), else over the
    polynomial ring of the entries.

    Why not ``DomainMatrix.from_Matrix`` for numbers too: it puts roots such as ``sqrt(3)``
    in SymPy's expression domain ``EX``, where every pivot's zero test is a minimal
    polynomial; the Delta with its legs 120 degrees apart (``sqrt(3)/2`` in its geometry)
    spent over 300 s in one elimination there, uninterrupted by the budget, against a
    fraction of a second over ``QQ<sqrt(3)>``.  With symbols beside the roots the
    elimination stays in ``EX``, charged in advance as a fifth power of its size."""
    if not M.free_symbols:
        try:
            return field_matrix(M)
        except ValueError:  # pragma: no cover - a number outside a number field (pi, e)
            pass
    dm = DomainMatrix.from_Matrix(M)
    if dm.domain.is_EX and any(p.base.is_number and not p.exp.is_Integer
                               for p in M.atoms(Pow)):
        # roots beside symbols: SymPy's expression domain, whose eliminations are not
        # interrupted and whose zero tests are minimal polynomials (the Delta with legs
        # 120 degrees apart at a symbolic height ran past 150 s in one, and building the
        # ring over QQ<sqrt(3)> instead took as long): charged as a fifth power, so that
        # a budget refuses it at once
        _charge_matrix(M, 5)
    return dm


def _solve(B: Matrix, C: Matrix) -> Matrix:
    """``B^-1 C`` for a square ``B`` non-singular where the result is used: exact, fraction
    free in the polynomial ring of the entries (``sin(q)``, ``cos(q)`` and roots as its
    symbols: an identity there is one at every value), one denominator."""
    n = B.cols
    dm = _domain_matrix(Matrix.hstack(B, C))
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
    dm = _domain_matrix(B)
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
    items = check_sequence(value, name, "actuated rates")
    if len(items) != k:
        raise ValueError(
            f"{name}: expected {k} actuated rates (one per joint of actuated, in its order; "
            f"the other joints' follow from the loop closure, exactly), got {len(items)}")
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
    if not Y.free_symbols:  # numbers: over their field, QQ or QQ<sqrt(3)> (not SymPy's EX)
        both = _domain_matrix(Matrix.hstack(X.T, Y))
        if both.domain.is_QQ or both.domain.is_AlgebraicField:
            return (both[:, :X.rows].transpose() * both[:, X.rows:]).to_Matrix()
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
        # the body's matrix from its exact parts (its own .matrix of floats is rounded): the
        # point mass's, plus the rotational inertia about the centre in I_O's block
        M = Matrix(point.matrix)
        M[3:, :3] += _exact(I.inertia)
        out.append((int(g.index[p.args[0]]), M, point))
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
                    gravity: Any = None, conds: str = "none", self_stress: bool = False) -> tuple:
    from ..core.wrench import Wrench

    conds = check_choice(conds, "conds", CONDS)
    self_stress = check_flag(self_stress, "self_stress")
    act = _actuation(mech, _check_actuated(mech, actuated))
    qd, qdd, g, digits = _motion(mech, act, rates, accelerations, gravity)
    balances = _balances(mech, act, qd, qdd, g)
    tau = _forces(act, balances).applyfunc(_tidy)
    K, r = _reaction_system(act, tau, balances)
    aug = Matrix.hstack(K, r)
    _charge_matrix(aug, 3)
    dm = _domain_matrix(aug).to_field()
    reduced, pivots = dm.rref()
    if K.cols in pivots:  # pragma: no cover - tau is the virtual-power balance
        raise ValueError("the Newton-Euler balance of the links has no solution with these "
                         "actuator forces (inconsistent input)")
    R = reduced.to_Matrix()
    w = zeros(K.cols, 1)
    for i, p in enumerate(pivots):
        w[p, 0] = R[i, K.cols]  # the free unknowns (a self-stress) are zero
    edges = range(len(act.net.graph.edges))

    def wrenches(v: Matrix, digits: int | None) -> tuple:
        v = v.applyfunc(_tidy)
        if conds == "piecewise" and act.condition is not true:  # columns: a Wrench holds no nan
            return tuple(_conds(_rounded(ImmutableMatrix(v[6 * e:6 * e + 6, 0]), digits), act,
                                conds) for e in edges)
        return _rounded(tuple(Wrench(v[6 * e:6 * e + 3, 0], v[6 * e + 3:6 * e + 6, 0])
                              for e in edges), digits)

    out = wrenches(w, digits)
    if not self_stress:
        return out
    # the null space of the balances: one self-stress per free unknown (the geometry's alone)
    basis = []
    for f in (c for c in range(K.cols) if c not in pivots):
        charge(STEP_UNITS * len(pivots))
        v = zeros(K.cols, 1)
        v[f, 0] = 1
        for i, p in enumerate(pivots):
            v[p, 0] = -R[i, f]
        basis.append(wrenches(v, None))
    return out, tuple(basis)


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


# ------------------------------------------------------------------ redundant actuation
class RedundantForces(NamedTuple):
    """The actuator forces of a redundantly actuated mechanism
    (:meth:`Mechanism.redundant_inverse_dynamics
    <screwsym.systems.linkage.Mechanism.redundant_inverse_dynamics>`)."""

    #: the minimum-norm actuator forces (k x 1, in the order of ``actuated``)
    forces: ImmutableMatrix
    #: a basis of the internal forces (k x 1 columns, ``k - M`` of them): actuator forces
    #: doing no work on any motion the loops allow, which load the mechanism and move nothing
    internal: tuple
    #: the ``M`` joints of ``actuated`` (numbers into the joints) whose rates determine the
    #: motion: the first independent ones in the order given
    primary: tuple


def _consistent(given: Matrix, implied: Matrix, name: str, tau: Any) -> None:
    """Refuse ``given`` unless it equals ``implied`` exactly (floats: to the float policy's
    relative tolerance ``tau``, on their exact values); symbols undecided are accepted."""
    for i, (a, b) in enumerate(zip(given, implied, strict=True)):
        scale = abs(a) + abs(b) if tau is not None else S.One
        if is_zero_scaled(expand(a - b), scale, tau) is False:
            raise ValueError(
                f"{name}[{i}]: the actuated joints' {name} must be consistent, as the loops "
                f"allow: expected {b} (from the primary joints'), got {a}; give {name} that "
                "close the loops, or the mobility's count of them to inverse_dynamics")


def redundant_inverse_dynamics(mech: Mechanism, actuated: Any, rates: Any, accelerations: Any,
                               gravity: Any = None) -> RedundantForces:
    offsets = _check_actuated(mech, actuated)
    joints = [int(a) for a in check_sequence(actuated, "actuated", "joint numbers")]
    net = bare_network(mech)
    A = net.A
    M = A.cols - field_rank(A)
    k = len(offsets)
    if k < M:
        _check_count(A, k, mech)
    basis = mech.mobility().rates  # F x M, the joint rates the loops allow
    Bfull = basis.extract(list(offsets), list(range(basis.cols)))
    _charge_matrix(Bfull, 3)
    _, pivots = field_matrix(Bfull.T).rref()
    if len(pivots) < M:
        raise ValueError(
            f"actuated: an actuation singularity: the actuated joints' rates span {len(pivots)} "
            f"of the mobility's {M} (the mechanism moves with all of them locked)")
    primary = tuple(pivots[:M])
    act = _actuation(mech, tuple(offsets[i] for i in primary))
    B = act.G.extract(list(offsets), list(range(M)))  # each actuated rate per primary rate
    qa, qa2 = _rates(rates, "rates", k), _rates(accelerations, "accelerations", k)
    g = check_vector(GRAVITY if gravity is None else gravity, "gravity")
    digits = _digits(qa, qa2, g, *_inertias(mech))
    tau_rates, tau_accels = float_tau(*qa), float_tau(*qa2)
    qa, qa2, g = _exact(qa), _exact(qa2), _exact(g)
    qd = act.G * qa.extract(list(primary), [0])
    _consistent(qa, qd.extract(list(offsets), [0]), "rates", tau_rates)
    qdd = _accelerations(mech, act, qd, qa2.extract(list(primary), [0]))
    _consistent(qa2, qdd.extract(list(offsets), [0]), "accelerations", tau_accels)
    Q = _forces(act, _balances(mech, act, qd, qdd, g))
    charge(STEP_UNITS * k * M)
    # the least-norm tau with B^T tau = Q (virtual power on every allowed motion)
    tau = (B * _solve(B.T * B, Q)).applyfunc(_tidy)
    internal = tuple(ImmutableMatrix(v.applyfunc(_tidy)) for v in B.T.nullspace())
    return RedundantForces(_rounded(ImmutableMatrix(tau), digits), internal,
                           tuple(joints[i] for i in primary))

