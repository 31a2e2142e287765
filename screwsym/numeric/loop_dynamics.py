r"""A closed loop's dynamics as generated numeric functions of its configuration's symbols.

:func:`loop_dynamics_functions` takes a :class:`~screwsym.systems.linkage.Mechanism` with
inertias whose configuration is given by symbols (a crank angle, a platform's pose, the
parameters of a family of closed configurations) and compiles its inverse dynamics and
mass matrix through :func:`screwsym.lambdify` on any back end: ``tau(p, qd, qdd)`` and
``H(p)`` over batches of states.  Two forms:

- ``form="program"`` (the default): the straight-line programs of
  :func:`~screwsym.numeric.loop_program.loop_dynamics_program` (the network matrix
  factored, sparse, the passive rates and accelerations solved, the links' Newton–Euler
  wrenches and the virtual power, one assignment per intermediate), written in a fraction
  of a second also for a Delta robot at a symbolic pose ``(x, y, z)``, where the closed
  forms are out of reach (``benchmarks/bench_loop_dynamics.py``);
- ``form="closed"``: the exact closed forms of :meth:`Mechanism.inverse_dynamics
  <screwsym.systems.linkage.Mechanism.inverse_dynamics>` and :meth:`Mechanism.mass_matrix
  <screwsym.systems.linkage.Mechanism.mass_matrix>`, with the actuated rates and
  accelerations as symbols, common subexpressions eliminated: dear with several
  symbols, but a closed form to read.

The functions hold on configurations that close the loops (the symbols' values must
describe one) and off the actuation singularities of :meth:`Mechanism.actuation_condition
<screwsym.systems.linkage.Mechanism.actuation_condition>`: there the programs give ``nan``
(each of their :attr:`~screwsym.numeric.loop_program.LoopProgram.conditions` fails), the
closed forms divide by zero.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, NamedTuple

from sympy import Dummy, ImmutableMatrix, Matrix

from ..algebra.budget import BUDGET
from ..codegen import lambdify
from ..core.checks import check_choice, check_count, check_sequence, check_vector
from ._batch import shaped
from ._loop_input import check_covered, check_mechanism, check_symbols
from .loop_program import loop_dynamics_program

__all__ = ["LoopDynamicsFunctions", "loop_dynamics_functions"]


class LoopDynamicsFunctions(NamedTuple):
    """Batched numeric functions of a closed loop: arrays ``(..., m)`` and ``(..., k)`` in."""

    #: ``inverse_dynamics(p, qd, qdd)``: the actuator forces, ``(..., k)``
    inverse_dynamics: Any
    #: ``mass_matrix(p)``: ``(..., k, k)``
    mass_matrix: Any
    #: the actuator forces in ``symbols``, the rates ``qd`` and accelerations ``qdd``: a
    #: :class:`~screwsym.numeric.loop_program.LoopProgram` (``form="program"``) or the
    #: closed form, a ``k x 1`` matrix (``form="closed"``)
    tau: Any
    #: the mass matrix in ``symbols``: its program, or its closed form
    H: Any
    #: the rate and acceleration symbols of ``tau``
    rates: tuple
    accelerations: tuple


@lru_cache(maxsize=16)
def _functions(mech: Any, actuated: tuple, symbols: tuple, gravity: ImmutableMatrix,
               backend: str | None, budget: int, form: str) -> LoopDynamicsFunctions:
    k = len(actuated)
    p = Matrix(symbols)
    if form == "program":
        tau_p = loop_dynamics_program(mech, list(actuated), list(symbols), "inverse_dynamics",
                                      gravity, budget=budget).float_guarded()
        H_p = loop_dynamics_program(mech, list(actuated), list(symbols), "mass_matrix",
                                    budget=budget).float_guarded()
        return LoopDynamicsFunctions(
            shaped(lambdify(list(tau_p.arguments), tau_p, backend, names=["p", "qd", "qdd"]),
                   (k,)),
            shaped(lambdify(list(H_p.arguments), H_p, backend, names=["p"]), (k, k)),
            tau_p, H_p, tuple(tau_p.arguments[1]), tuple(tau_p.arguments[2]))
    qd = tuple(Dummy(f"qd{i}", real=True) for i in range(k))
    qdd = tuple(Dummy(f"qdd{i}", real=True) for i in range(k))
    tau = mech.inverse_dynamics(list(actuated), list(qd), list(qdd), list(gravity),
                                budget=budget)
    H = mech.mass_matrix(list(actuated), budget=budget)
    return LoopDynamicsFunctions(
        shaped(lambdify([p, Matrix(qd), Matrix(qdd)], tau, backend,
                         names=["p", "qd", "qdd"]), (k,)),
        shaped(lambdify([p], H, backend, names=["p"]), (k, k)),
        tau, H, qd, qdd)


#: the forms :func:`loop_dynamics_functions` compiles
FORMS = ("program", "closed")


def loop_dynamics_functions(mech: Any, actuated: Any, symbols: Any,
                            gravity: Any = (0, 0, -9.81), backend: str | None = None, *,
                            form: str = "program",
                            budget: int = BUDGET) -> LoopDynamicsFunctions:
    r"""The closed loop's inverse dynamics and mass matrix as batched numeric functions.

    ``mech`` a :class:`~screwsym.systems.linkage.Mechanism` with inertias, ``actuated``
    the actuated joints' numbers, ``symbols`` the symbols its configuration (joints and
    inertias) is given in, in the order of the argument ``p`` (``(..., m)``); ``gravity``
    numbers (default ``(0, 0, -9.81)``); ``backend`` as for :func:`screwsym.lambdify`.
    ``form`` ``"program"`` (default: the straight-line programs of
    :func:`~screwsym.numeric.loop_program.loop_dynamics_program`, ``nan`` where one of
    their pivots vanishes) or ``"closed"`` (the exact closed forms; see the module
    docstring).  ``budget`` bounds the symbolic work (:mod:`screwsym.algebra.budget`; past
    it a ``ValueError``).  Cached per mechanism, actuation, symbols, gravity, back end and
    form.

    A parallelogram four-bar whose crank, at angle ``t``, carries a point mass of 2 at its
    pin: the coupler translates, the mass moves on the crank's circle, so the crank needs
    ``2 qdd + 2 * 10 cos(t)`` under gravity ``-10`` along y.

    >>> import numpy as np
    >>> from sympy import cos, sin, symbols
    >>> from screwsym.core.inertia import SpatialInertia
    >>> from screwsym.systems.joints import R
    >>> from screwsym.systems.linkage import Mechanism
    >>> t = symbols("t", real=True)
    >>> z, A = [0, 0, 1], [cos(t), sin(t), 0]
    >>> four = Mechanism([("ground", "crank", R([0, 0, 0], z)),
    ...                   ("crank", "coupler", R(A, z)),
    ...                   ("coupler", "rocker", R([cos(t) + 2, sin(t), 0], z)),
    ...                   ("rocker", "ground", R([2, 0, 0], z))], base="ground",
    ...                  inertias={"crank": SpatialInertia.point_mass(2, A)})
    >>> f = loop_dynamics_functions(four, [0], [t], gravity=(0, -10, 0), backend="numpy")
    >>> f.inverse_dynamics(np.array([[np.pi / 3], [2 * np.pi / 3]]), np.ones((2, 1)),
    ...                    np.full((2, 1), 0.5)).round(12)
    array([[11.],
           [-9.]])
    >>> f.mass_matrix(np.array([0.3]))
    array([[2.]])
    >>> f.tau.conditions        # the pivots it divides by: nan where one is zero
    (Ne(N2_2, 0), Ne(N3_3_2, 0), Ne(N4_4_2, 0))
    >>> f.mass_matrix(np.array([0.0]))      # folded: the crank does not drive it
    array([[nan]])
    >>> fc = loop_dynamics_functions(four, [0], [t], gravity=(0, -10, 0), backend="numpy",
    ...                              form="closed")
    >>> fc.tau
    Matrix([[2*_qdd0 + 20*cos(t)]])
    """
    check_mechanism(mech)
    acts = check_sequence(actuated, "actuated", "joint numbers")
    syms = check_symbols(symbols)
    g = check_vector(gravity, "gravity")
    if g.free_symbols:
        raise ValueError(f"gravity: expected numbers, got {list(g)}")
    check_covered(mech, syms)
    form = check_choice(form, "form", FORMS)
    return _functions(mech, tuple(int(a) if isinstance(a, int) else a for a in acts),
                      tuple(syms), ImmutableMatrix(g), backend, check_count(budget, "budget"),
                      form)
