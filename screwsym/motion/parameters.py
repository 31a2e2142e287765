r"""A chain's inertial parameters: the standard ten per link, and the base parameters, exactly.

The joint torques are linear in the ten parameters of each link,
``tau = Y(q, qd, qdd) pi`` (:func:`screwsym.motion.dynamics.regressor`, the columns in the
order ``[m, mc_x, mc_y, mc_z, I_xx, I_xy, I_yy, I_xz, I_yz, I_zz]`` of each link, each in the
link frame that coincides with the space frame at home, about its origin).  Not all ``10 n``
are identifiable: some columns of ``Y`` vanish for every motion and others are fixed linear
combinations of the rest.  The *base parameters* (Khalil & Gautier; Gautier 1991) are a
smallest set of linear combinations ``beta = B pi`` with ``Y pi = Y_b beta`` for every
state, ``Y_b`` the columns of ``Y`` at ``B``'s pivots.

How they are found
==================

``B`` is the reduced row echelon form of ``Y`` stacked at exact random states
(Gautier 1991's numeric QR, here exact): the states have rational ``cos q_i, sin q_i``
(points ``((1 - t^2)/(1 + t^2), 2t/(1 + t^2))`` of the unit circle) and rational
velocities, accelerations and gravity, and ``Y`` at each is computed exactly by the
regressor's straight-line program (:func:`regressor_program`, Newton–Euler in the frames
of :mod:`screwsym.motion.newton_euler`), so the arithmetic is over the rationals, or over
the rational functions of the chain's own symbols where its geometry is symbolic (then
the result is generic: it holds where the pivots found are not zero).  States are added
until the rank has not grown for two batches.  A dependency among the columns that holds
at the states but not identically would need every state to be a root of a non-zero
polynomial of bounded degree, which random points avoid except with a negligible
probability (Schwartz–Zippel); the tests check the identity ``Y pi == Y_b beta``
symbolically on small chains and the number of base parameters against the numeric rank
of pinocchio's regressor.  The pivots are the first independent columns in the standard
order, so parameters are grouped onto the links nearer the base.

References
==========

M. Gautier, "Numerical calculation of the base inertial parameters of robots",
*J. Robotic Systems* 8(4), 1991.  W. Khalil, F. Bennis, "Symbolic calculation of the base
inertial parameters of closed-loop robots", *Int. J. Robotics Research* 14(2), 1995.
W. Khalil, E. Dombre, *Modeling, Identification and Control of Robots*, 2002, Ch. 12.
"""

from __future__ import annotations

import random
from fractions import Fraction
from functools import lru_cache
from typing import TYPE_CHECKING, Any, NamedTuple

from sympy import Add, Float, ImmutableMatrix, Rational, Symbol, cos, sign, sin
from sympy.polys.domains import GF, QQ
from sympy.polys.matrices import DomainMatrix

from ..core.checks import check_sequence, check_vector
from .dynamics import GRAVITY
from .newton_euler import EXTRAS, Program, dynamics_program, parameter_symbols, regressor_program

if TYPE_CHECKING:
    from .chain import Chain

__all__ = ["parameters", "BaseParameters", "base_parameters", "base_regressor", "base_symbols",
           "base_values", "base_program"]


def parameters(chain: Chain, numbers: bool = False, extras: Any = ()) -> ImmutableMatrix:
    r"""The ``10 n`` standard inertial parameters, a column in the order of the regressor's columns.

    Symbols ``m_i, mc_x_i, mc_y_i, mc_z_i, I_xx_i, I_xy_i, I_yy_i, I_xz_i, I_yz_i, I_zz_i`` for
    link ``i = 1 .. n`` (real); with ``numbers=True`` the chain's own values
    (``chain.inertias[i].parameters()``, which needs inertias).  ``extras`` (names among
    ``"armature", "viscous", "coulomb"``) appends the joints' ``Ia_i, Fv_i, Fc_i``
    (:func:`screwsym.motion.newton_euler.parameter_symbols`; symbols only).

    >>> from screwsym import Chain, SpatialInertia, Twist
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])],
    ...             inertias=[SpatialInertia.point_mass(2, [1, 0, 0])])
    >>> parameters(arm).T
    Matrix([[m_1, mc_x_1, mc_y_1, mc_z_1, I_xx_1, I_xy_1, I_yy_1, I_xz_1, I_yz_1, I_zz_1]])
    >>> parameters(arm, numbers=True).T
    Matrix([[2, 2, 0, 0, 0, 0, 2, 0, 0, 2]])
    """
    if not hasattr(chain, "twists") or not hasattr(chain, "n_joints"):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    if numbers:
        if extras:
            raise ValueError("extras: the chain has no numbers for its joints' friction and rotor inertia")
        if chain.inertias is None:
            raise ValueError("chain: the chain has no inertias, so no numbers for its parameters")
        return ImmutableMatrix.vstack(*(b.parameters() for b in chain.inertias))
    return parameter_symbols(chain.n_joints, extras)


class BaseParameters(NamedTuple):
    """``beta = B pi``: the base parameters, the pivots (columns of the regressor kept) and ``B``."""

    #: the b base parameters, exact linear combinations of :func:`parameters`
    parameters: ImmutableMatrix
    #: the columns of the regressor that form the base regressor
    columns: tuple[int, ...]
    #: the b x 10n matrix ``B`` (reduced row echelon form), ``beta = B pi``
    matrix: ImmutableMatrix


def _state(rng: random.Random, program: Program, n: int, gsyms: list[Symbol]) -> dict[Any, Any]:
    env: dict[Any, Any] = {}
    q, qd, qdd = program.arguments
    for i in range(n):
        t = Rational(rng.randint(-6, 6), rng.randint(1, 4))
        env[cos(q[i])] = (1 - t**2) / (1 + t**2)
        env[sin(q[i])] = 2 * t / (1 + t**2)
        env[q[i]] = Rational(rng.randint(-9, 9), rng.randint(1, 4))  # a prismatic joint's
        env[qd[i]] = Rational(rng.randint(-9, 9))
        env[qdd[i]] = Rational(rng.randint(-9, 9))
    for s in gsyms:
        env[s] = Rational(rng.randint(1, 40), rng.randint(1, 7))
    return env


def _rows(program: Program, env: dict[Any, Any]) -> list[list[Any]]:
    """The outputs at ``env`` by substitution, assignment by assignment (any exact values)."""
    values = dict(env)
    for t, e in program.assignments:
        values[t] = e.xreplace(values)
    Y = program.outputs.xreplace(values)
    return [list(Y.row(i)) for i in range(Y.rows)]


def _rational_runner(program: Program, inputs: list[Any]) -> Any:
    """The program as a Python function of ``inputs`` over ``Fraction``, or None.

    For a program whose constants are all rational (a chain with rational geometry), each
    expression becomes a closure over ``Fraction`` arithmetic: some hundred times faster
    than substitution.  Anything but sums, products, integer powers, rationals and the
    inputs gives None (then substitution is used).
    """
    index = {s: k for k, s in enumerate(inputs)}

    def build(e: Any) -> Any:
        if e in index:
            k = index[e]
            return lambda x: x[k]
        if e.is_Rational:
            c = Fraction(int(e.p), int(e.q))
            return lambda x: c
        if isinstance(e, Add) or e.is_Mul:
            fs = [build(a) for a in e.args]
            if isinstance(e, Add):
                return lambda x: sum(f(x) for f in fs)

            def product(x: Any) -> Any:
                v = fs[0](x)
                for f in fs[1:]:
                    v = v * f(x)
                return v
            return product
        if e.func is sign:
            g = build(e.args[0])
            return lambda x: (g(x) > 0) - (g(x) < 0)
        if e.is_Pow and e.exp.is_Integer and e.exp > 0:
            f, k = build(e.base), int(e.exp)
            return lambda x: f(x) ** k
        raise _NotRational

    size = len(inputs)
    steps = []
    try:
        for t, e in program.assignments:
            if e.func in (sin, cos) and e in index:
                index[t] = index[e]
                continue
            steps.append(build(e))
            index[t] = size
            size += 1
        outs = [build(e) for e in program.outputs]
    except _NotRational:
        return None

    def run(x: list[Any]) -> list[Any]:
        x = list(x)
        for f in steps:
            x.append(f(x))
        return [f(x) for f in outs]
    return run


class _NotRational(Exception):
    pass


def _check_joints(chain: Chain, program: Program) -> None:
    q = program.arguments[0]
    for _, e in program.assignments:
        for f in e.atoms(sin, cos):
            if f.args[0] not in set(q):
                raise ValueError(f"chain: base_parameters needs unit-speed joints (|omega| = 1 "
                                 f"or 0), got the function {f}")
    for i, twist in enumerate(chain.twists):
        w, v = twist.matrix[:3, :], twist.matrix[3:, :]
        if w.dot(v) != 0 and any(x != 0 for x in w):
            raise ValueError(f"twists[{i}]: base_parameters needs revolute or prismatic joints, "
                             f"got a helical one ({twist})")


#: a prime for the rank of the stacked regressor while states are added (the final
#: echelon form is exact, over the rationals)
PRIME = 2**61 - 1


@lru_cache(maxsize=32)
def _base(chain: Chain, gravity: ImmutableMatrix, extras: tuple[str, ...]) -> BaseParameters:
    n = chain.n_joints
    program = regressor_program(chain, gravity, extras)
    cols = program.outputs.cols
    _check_joints(chain, program)
    gsyms = sorted(gravity.free_symbols, key=str)
    q, qd, qdd = program.arguments
    inputs = [f(x) for x in q for f in (cos, sin)] + list(q) + list(qd) + list(qdd) + gsyms
    run = _rational_runner(program, inputs)
    rng = random.Random(3434)
    rows: list[list[Any]] = []
    rank, stable = -1, 0
    batch = 10 + 2
    while stable < 2:
        for _ in range(batch):
            env = _state(rng, program, n, gsyms)
            if run is None:
                rows.extend(_rows(program, env))
            else:
                flat = run([Fraction(int(env[x].p), int(env[x].q)) for x in inputs])
                rows.extend([Rational(v.numerator, v.denominator)
                             for v in flat[cols * i:cols * (i + 1)]] for i in range(n))
        M = DomainMatrix.from_list_sympy(len(rows), cols, rows)
        if not M.domain.is_Exact:
            raise ValueError("chain: base_parameters needs exact numbers (rationals or symbols) in "
                             "the chain's geometry, got floats")
        if M.domain == QQ:  # the rank modulo a large prime, which is the rank but by chance
            Mp = DomainMatrix.from_list([[_modp(x) for x in row] for row in rows],
                                        GF(PRIME))
            r = Mp.rank()
        else:
            r = M.rank()
        stable = stable + 1 if r == rank else 0
        rank, batch = r, 4
    R, pivots = M.rref()
    B = ImmutableMatrix(R.to_Matrix()[:len(pivots), :])
    pi = parameters(chain, extras=extras)
    beta = ImmutableMatrix([Add(*(B[k, j] * pi[j] for j in range(cols) if B[k, j] != 0))
                            for k in range(len(pivots))])
    return BaseParameters(beta, tuple(pivots), B)


def _modp(x: Any) -> int:
    x = Rational(x)
    return int(x.p) * pow(int(x.q), -1, PRIME) % PRIME


def base_parameters(chain: Chain, gravity: Any = None, extras: Any = ()) -> BaseParameters:
    r"""The base inertial parameters of the chain, exact (module docstring).

    Returns :class:`BaseParameters` ``(parameters, columns, matrix)``: ``beta = B pi`` with
    ``pi`` the standard parameters (:func:`parameters`), and ``Y pi = Y[:, columns] beta``
    for every state (with ``extras``, the joints' rotor inertia and friction parameters
    too: :func:`screwsym.motion.newton_euler.regressor_program`).  ``gravity`` as for the regressor (a symbolic default ``(0, 0, -g)``:
    the base parameters are those of any non-zero gravity along it).  Needs revolute and
    prismatic joints with unit-speed twists.  Cached per chain and gravity.

    A hinge about z identifies only ``I_zz``:

    >>> from screwsym import Chain, Twist
    >>> hinge = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])])
    >>> base_parameters(hinge).parameters.T
    Matrix([[I_zz_1]])

    The planar 2R arm (hinges about z at ``x = 0`` and ``x = 1``, gravity along the axes) has
    the four of Khalil & Dombre's grouping, ``ZZ1R``, ``ZZ2``, ``MX2``, ``MY2`` (here the
    parameters are about the space origin: link 2's about its joint are
    ``ZZ2 = I_zz_2 - 2 mc_x_2 + m_2`` and ``MX2 = mc_x_2 - m_2``, combinations of these):

    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])])
    >>> base_parameters(arm).parameters.T
    Matrix([[I_zz_1 + I_zz_2, -I_zz_2 + m_2, -I_zz_2 + mc_x_2, mc_y_2]])
    """
    if not hasattr(chain, "twists") or not hasattr(chain, "n_joints"):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    parameter_symbols(0, extras)  # checks the names
    chosen = tuple(e for e in EXTRAS if e in extras)
    g = check_vector(GRAVITY if gravity is None else gravity, "gravity")
    # a decimal gravity, e.g. -9.81, as the rational it is (its exact binary value): the
    # echelon form must be exact (floats would make spurious pivots)
    g = g.xreplace({f: Rational(f) for f in g.atoms(Float)})
    return _base(chain, g, chosen)


def base_regressor(chain: Chain, q: Any, qd: Any, qdd: Any, gravity: Any = None,
                   extras: Any = ()) -> ImmutableMatrix:
    r"""The n x b base regressor ``Y_b``: ``Y_b beta == Y pi`` for every state (module docstring).

    The columns of the regressor at :func:`base_parameters`' pivots, from the regressor's
    program at ``q, qd, qdd`` (numbers or symbols; untidied).

    >>> from sympy import symbols
    >>> from screwsym import Chain, Twist
    >>> q, qd, qdd = symbols("q qd qdd", real=True)
    >>> hinge = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])])
    >>> base_regressor(hinge, [q], [qd], [qdd])
    Matrix([[qdd]])
    """
    base = base_parameters(chain, gravity, extras)
    n = chain.n_joints
    values = [check_sequence(v, name, "joint values", n) for v, name in
              ((q, "q"), (qd, "qd"), (qdd, "qdd"))]
    Y = regressor_program(chain, gravity, extras).evaluate(*values)
    return ImmutableMatrix(Y.extract(list(range(n)), list(base.columns)))


def base_symbols(chain: Chain, gravity: Any = None, extras: Any = ()) -> ImmutableMatrix:
    r"""Symbols for the base parameters, each named for its group (Khalil & Dombre's ``R``).

    The ``k``-th is named for the standard parameter at :func:`base_parameters`'
    ``columns[k]``, with ``R`` appended where other parameters are grouped into it
    (``ZZ1R``: here ``I_zz_1R``).  They are the last argument of
    :func:`base_program` (``Chain.dynamics_program(what, parameters="base")``);
    their values are
    :func:`base_values`.

    >>> from screwsym import Chain, Twist
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])])
    >>> base_symbols(arm).T
    Matrix([[I_zz_1R, m_2R, mc_x_2R, mc_y_2]])
    """
    base = base_parameters(chain, gravity, extras)
    pi = parameters(chain, extras=extras)
    names = []
    for k, col in enumerate(base.columns):
        grouped = sum(1 for x in base.matrix.row(k) if x != 0) > 1
        names.append(Symbol(f"{pi[col].name}{'R' if grouped else ''}", real=True))
    return ImmutableMatrix(names)


def base_values(chain: Chain, gravity: Any = None) -> ImmutableMatrix:
    r"""The base parameters of the chain's own inertias, exact: ``B pi`` at its numbers.

    >>> from screwsym import Chain, SpatialInertia, Twist
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])],
    ...             inertias=[SpatialInertia.point_mass(1, [1, 0, 0]),
    ...                       SpatialInertia.point_mass(1, [2, 0, 0])])
    >>> base_values(arm).T
    Matrix([[5, -3, -2, 0]])
    """
    base = base_parameters(chain, gravity)
    return ImmutableMatrix(base.matrix * parameters(chain, numbers=True))


def base_program(chain: Chain, what: str = "inverse_dynamics", gravity: Any = None,
                 extras: Any = (), **joint_terms: Any) -> Program:
    r"""The chain's dynamics as a straight-line program in its base parameters.

    :func:`screwsym.motion.newton_euler.dynamics_program` (``what`` and ``gravity`` as there;
    also ``Chain.dynamics_program(what, gravity, parameters="base")``) with one more
    argument, the column :func:`base_symbols` (each named for its group), computing
    ``Y_b beta`` (:func:`base_regressor`) identically: Khalil & Kleinfinger (1987)'s
    customised Newton–Euler model in the base parameters, the recursion in the parameters
    about each link's origin with each standard parameter at a pivot of
    :func:`base_parameters` replaced by its base parameter and the others by ``0`` (folded
    away as the program is written).  Then ``Y pi = Y_b beta`` makes it the chain's
    dynamics for any ``pi`` with ``beta = B pi``.  The base parameters are those for
    ``gravity``; ``extras`` (among ``"armature", "viscous", "coulomb"``) adds the joints'
    rotor inertia and friction.  The chain needs no inertias.

    The planar 2R arm (gravity along the axes: Khalil & Dombre's four, grouped):

    >>> from screwsym import Chain, Twist
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])])
    >>> p = base_program(arm, "mass_matrix")
    >>> p.arguments[1].T
    Matrix([[I_zz_1R, m_2R, mc_x_2R, mc_y_2]])
    >>> print(p)
    s2 = sin(q2)
    c2 = cos(q2)
    J2_yy = m_2R - 2*mc_x_2R
    MS2x = -m_2R + mc_x_2R
    F2f1_y = MS2x*c2 - mc_y_2*s2
    F2C1_z = F2f1_y + J2_yy
    sp2 = 2*F2f1_y + m_2R
    Ic1_zz = I_zz_1R + J2_yy + sp2
    H = [Ic1_zz, F2C1_z, F2C1_z, J2_yy]
    """
    for name in joint_terms:
        raise ValueError(f"{name}: in the base parameters the joints' terms are parameters too: "
                         f"give extras=[{name!r}, ...] instead")
    base = base_parameters(chain, gravity, extras)
    beta = base_symbols(chain, gravity, extras)
    values: list[Any] = [0] * base.matrix.cols
    for b, col in zip(beta, base.columns, strict=True):
        values[col] = b
    return dynamics_program(chain, what, gravity, parameters=(beta, ImmutableMatrix(values)),
                            extras=list(extras))
