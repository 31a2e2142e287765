r"""A chain's dynamics as fast numeric functions, and forward dynamics by solving with them.

:func:`dynamics_functions` compiles the chain's customised Newton–Euler programs
(:func:`screwsym.motion.newton_euler.dynamics_program`: straight-line code over exact
coefficients, one intermediate per link quantity) through :func:`screwsym.lambdify`: the
torques ``tau(q, qd, qdd)``, the mass matrix ``H(q)`` by composite rigid bodies and the bias
``h(q, qd) = C(q, qd) qd + g(q)``; :func:`forward_dynamics` solves ``H(q) qdd = tau - h(q, qd)``
with ``numpy.linalg.solve`` for many states at once.  The programs are written in a fraction
of a second and are small (the UR5's torques: 240 multiplications and 165 additions, where
the closed forms ``H qdd + C qd + g`` it used before took about 14,000 operations and seconds
of symbolic work); the closed forms of :mod:`screwsym.motion.dynamics` stay available, and
the tests check the two against each other and against pinocchio.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any, NamedTuple

import numpy as np
from sympy import ImmutableMatrix

from ..codegen import lambdify
from ..core.checks import check_choice, check_vector
from ..motion.chain import Chain
from ._batch import shaped

__all__ = ["DynamicsFunctions", "dynamics_functions", "forward_dynamics"]


class DynamicsFunctions(NamedTuple):
    """Batched numeric functions of a chain: arrays ``(..., n)`` in, as below out."""

    #: ``inverse_dynamics(q, qd, qdd)``: the torques, ``(..., n)``
    inverse_dynamics: Any
    #: ``mass_matrix(q)``: ``(..., n, n)``
    mass_matrix: Any
    #: ``bias(q, qd)``: ``C(q, qd) qd + g(q)``, ``(..., n)``
    bias: Any


@lru_cache(maxsize=16)
def _functions(chain: Chain, gravity: ImmutableMatrix, backend: str | None,
               parameters: str | None = None) -> DynamicsFunctions:
    n = chain.n_joints
    options = {} if parameters is None else {"parameters": parameters}
    tau = chain.dynamics_program("inverse_dynamics", gravity, **options)
    H = chain.dynamics_program("mass_matrix", gravity, **options)
    bias = chain.dynamics_program("bias", gravity, **options)
    extra = [] if parameters is None else ["beta" if parameters == "base" else "pi"]
    return DynamicsFunctions(
        shaped(lambdify(list(tau.arguments), tau, backend, names=["q", "qd", "qdd", *extra]), (n,)),
        shaped(lambdify(list(H.arguments), H, backend, names=["q", *extra]), (n, n)),
        shaped(lambdify(list(bias.arguments), bias, backend, names=["q", "qd", *extra]), (n,)),
    )


def dynamics_functions(chain: Chain, gravity: Any = (0, 0, -9.81),
                       backend: str | None = None, parameters: str | None = None) -> DynamicsFunctions:
    r"""The chain's inverse dynamics, mass matrix and bias as batched numeric functions.

    ``gravity`` is the gravitational acceleration, numbers (default
    ``(0, 0, -9.81)``); ``backend`` as for :func:`screwsym.lambdify`.  Cached per
    chain, gravity, back end and ``parameters``.

    With ``parameters="base"`` the functions take the base inertial parameters as a last
    argument ``beta`` (``(..., b)``, in the order of
    :func:`screwsym.motion.parameters.base_symbols`; the chain's own are
    :func:`~screwsym.motion.parameters.base_values`), compiled from
    ``chain.dynamics_program(what, parameters="base")``; with ``"standard"``, the ``10 n``
    standard parameters ``pi``.  Then the chain needs no inertias (for identification).

    >>> import numpy as np
    >>> from screwsym import Chain, SpatialInertia, Twist
    >>> pendulum = Chain([Twist.rotation([0, -1, 0], point=[0, 0, 0])],
    ...                  inertias=[SpatialInertia.point_mass(2, [1, 0, 0])])
    >>> f = dynamics_functions(pendulum, gravity=(0, 0, -10), backend="numpy")
    >>> f.bias(np.array([[0.0], [np.pi / 2]]), np.zeros((2, 1))).round(12) + 0.0
    array([[20.],
           [ 0.]])
    >>> f.mass_matrix(np.zeros((5, 1))).shape
    (5, 1, 1)

    The same in the base parameters (the pendulum's ``mc_x_1, mc_z_1, I_yy_1``):

    >>> from screwsym.motion.parameters import base_symbols, base_values
    >>> base_symbols(pendulum, (0, 0, -10)).T, base_values(pendulum, (0, 0, -10)).T
    (Matrix([[mc_x_1, mc_z_1, I_yy_1]]), Matrix([[2, 0, 2]]))
    >>> fb = dynamics_functions(pendulum, gravity=(0, 0, -10), backend="numpy", parameters="base")
    >>> beta = np.array([2.0, 0.0, 2.0])
    >>> fb.bias(np.array([[0.0], [np.pi / 2]]), np.zeros((2, 1)), beta).round(12) + 0.0
    array([[20.],
           [ 0.]])
    """
    if not isinstance(chain, Chain):
        raise TypeError(f"chain: expected a Chain, got {type(chain).__name__}")
    if parameters is not None:
        parameters = check_choice(parameters, "parameters", ("base", "standard"))
    elif chain.inertias is None:
        raise ValueError("chain: the chain has no inertias; build it with Chain(..., inertias=[...])")
    g = check_vector(gravity, "gravity")
    if g.free_symbols:
        raise ValueError(f"gravity: expected numbers, got {list(g)}")
    return _functions(chain, g, backend, parameters)


def forward_dynamics(chain: Chain, q: Any, qd: Any, tau: Any, gravity: Any = (0, 0, -9.81),
                     backend: str | None = None) -> np.ndarray:
    r"""The joint accelerations ``qdd`` for the torques ``tau``: ``H(q) qdd = tau - h(q, qd)``.

    ``q``, ``qd``, ``tau`` are arrays ``(..., n)`` (broadcast against each
    other); the result is ``(..., n)``.  Solved with ``numpy.linalg.solve`` from
    the generated mass matrix and bias of :func:`dynamics_functions`.

    >>> import numpy as np
    >>> from screwsym import Chain, SpatialInertia, Twist
    >>> slider = Chain([Twist.translation([0, 0, 1])], inertias=[SpatialInertia.point_mass(2, [0, 0, 0])])
    >>> forward_dynamics(slider, np.zeros(1), np.zeros(1), np.array([[0.0], [19.62]]), backend="numpy")
    array([[-9.81],
           [ 0.  ]])
    """
    f = dynamics_functions(chain, gravity, backend)
    q, qd, tau = (np.asarray(x, dtype=float) for x in (q, qd, tau))
    q, qd, tau = np.broadcast_arrays(q, qd, tau)
    H = f.mass_matrix(q)
    rhs = tau - f.bias(q, qd)
    return np.linalg.solve(H, rhs[..., None])[..., 0]
