r"""Transmission indices and Jacobians at many configurations at once, in floating point.

:func:`transmission_map` turns the exact indices of
:meth:`~screwsym.systems.parallel.ParallelMechanism.transmission` (Wang, Wu &
Liu 2010) of a mechanism whose geometry depends on symbols into one
vectorised function of those symbols' values, generated once with
:func:`screwsym.lambdify`; :func:`jacobian_map` does the same for
``(Jx, Jq)``.  The functions work elementwise along the batch: they take a
``(N, k)`` array of configurations (column ``j`` the values of
``symbols[j]``), or ``k`` arrays of one shape, and return arrays of shape
``(N,)`` (of the batch shape).  The transmission maps also take Dask arrays
(``pip install -e ".[dask]"`` from a clone, or ``pip install "dask[array]"``) and
return lazy Dask arrays computed chunk by chunk, on any scheduler
(``screwsym.numeric._chunks``).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from typing import Any, NamedTuple

import numpy as np
from sympy import Symbol

from ..codegen import lambdify
from ..systems.parallel import ParallelMechanism
from ._chunks import batched, is_dask

__all__ = ["TransmissionMap", "transmission_map", "jacobian_map"]


class TransmissionMap(NamedTuple):
    """The indices at each configuration: ``input`` and ``output`` ``(n, N)``, ``local`` ``(N,)``."""

    input: np.ndarray  #: lambda_i, one row per actuated joint
    output: np.ndarray  #: eta_i, one row per actuated joint
    local: np.ndarray  #: the least of them


def _symbols(symbols: Any) -> list[Symbol]:
    if isinstance(symbols, Symbol):
        symbols = [symbols]
    if not isinstance(symbols, Sequence) or isinstance(symbols, str) or not symbols:
        raise TypeError(f"symbols: expected a non-empty sequence of SymPy symbols, got "
                        f"{type(symbols).__name__}")
    for i, s in enumerate(symbols):
        if not isinstance(s, Symbol):
            raise TypeError(f"symbols[{i}]: expected a SymPy Symbol, got {type(s).__name__}")
    return list(symbols)


def _columns(values: tuple[Any, ...], k: int) -> list[np.ndarray]:
    if len(values) == 1 and k > 1 or (len(values) == 1 and np.ndim(values[0]) == 2):
        a = np.asarray(values[0], dtype=float)
        if a.ndim != 2 or a.shape[1] != k:
            raise ValueError(f"configurations: expected an array of shape (N, {k}), "
                             f"got shape {a.shape}")
        return [a[:, j] for j in range(k)]
    if len(values) != k:
        raise ValueError(f"configurations: expected one (N, {k}) array or {k} arrays, "
                         f"got {len(values)} arrays")
    return [np.asarray(v, dtype=float) for v in values]


def transmission_map(mech: ParallelMechanism, symbols: Any, *,
                     backend: str | None = "numpy") -> Callable[..., TransmissionMap]:
    r"""A vectorised function of the configurations giving the transmission indices.

    ``symbols`` are the symbols of the geometry, in the order of the columns.
    The function returns a :class:`TransmissionMap`; where a formula divides
    by zero (a singular configuration) the indices are NaN.  The formulas are
    polynomials of high degree in the configuration: values beyond about
    ``1e150`` overflow (NaN), so scale such inputs first.  The exact local
    index (an unevaluated ``Min`` at a symbolic pose) is not used: the least
    index is taken in NumPy.

    >>> import numpy as np
    >>> from sympy import symbols
    >>> from screwsym.systems.parallel import Limb, ParallelMechanism
    >>> from screwsym.systems.joints import R, P
    >>> x, y = symbols("x y", real=True)
    >>> z, p = [0, 0, 1], [x, y, 0]
    >>> m = ParallelMechanism(Limb(R([0, 0, 0], z), R([0, 1, 0], z), R(p, z), actuated=0),
    ...                       Limb(R([3, 0, 0], z), R([3, 1, 0], z), R(p, z), actuated=0),
    ...                       Limb(P([1, 0, 0]), P([0, 1, 0])))
    >>> f = transmission_map(m, [x, y])
    >>> out = f(np.array([[1.0, 2.0], [1.5, 3.0]]))
    >>> out.input.shape, out.local.shape
    ((2, 2), (2,))
    >>> bool(np.isclose(out.input[0, 0], np.sqrt(0.5)))
    True
    """
    if not isinstance(mech, ParallelMechanism):
        raise TypeError(f"mech: expected a ParallelMechanism, got {type(mech).__name__}")
    syms = _symbols(symbols)
    tr = mech.transmission()
    exprs = (*tr.input, *tr.output)
    n = len(tr.input)
    extra = set().union(*(e.free_symbols for e in exprs)) - set(syms)
    if extra:
        raise ValueError(f"symbols: the indices also depend on {sorted(map(str, extra))}; "
                         "give them values (xreplace) or list them")
    fn = lambdify(syms, exprs, backend, name="transmission_indices")
    k = len(syms)

    def numpy_indices(*configurations: Any) -> TransmissionMap:
        cols = _columns(configurations, k)
        values = fn(*cols)
        shape = np.broadcast_shapes(*(c.shape for c in cols))
        arr = [np.broadcast_to(np.asarray(v, dtype=float), shape) for v in values]
        lam = np.stack(arr[:n])
        eta = np.stack(arr[n:])
        local = np.minimum(lam.min(axis=0), eta.min(axis=0))
        return TransmissionMap(lam, eta, local)

    recipe = (mech, tuple(syms), backend)
    if len(_MADE) >= 64:  # a bounded memory of recent maps
        _MADE.pop(next(iter(_MADE)))
    _MADE[recipe] = numpy_indices
    # for Dask: a picklable recipe (the generated code is not), rebuilt once per worker
    chunk = functools.partial(_chunk, recipe)

    def indices(*configurations: Any) -> TransmissionMap:
        if not any(is_dask(c) for c in configurations):
            return numpy_indices(*configurations)
        one = len(configurations) == 1 and (k > 1 or np.ndim(configurations[0]) == 2)
        trailing = [(k,)] if one else [()] * len(configurations)
        if not one and len(configurations) != k:
            raise ValueError(f"configurations: expected one (N, {k}) array or {k} arrays, "
                             f"got {len(configurations)} arrays")
        lam, eta, local = batched(chunk, configurations, trailing,
                                  [((n,), float), ((n,), float), ((), float)])
        first = (lam.ndim - 1, *range(lam.ndim - 1))  # the joints' axis first, as NumPy's
        return TransmissionMap(lam.transpose(first), eta.transpose(first), local)

    indices.__doc__ = f"Transmission indices of a mechanism at configurations of {syms}."
    return indices


#: the NumPy functions of the maps made in this process, by their recipe (a Dask worker
#: that receives a recipe it has not seen makes the map once, then finds it here)
_MADE: dict[tuple, Callable[..., TransmissionMap]] = {}


def _chunk(recipe: tuple, *blocks: np.ndarray) -> tuple:
    """One chunk of a Dask map: ``recipe`` is ``(mechanism, symbols, backend)``."""
    fn = _MADE.get(recipe)
    if fn is None:
        mech, syms, backend = recipe
        transmission_map(mech, list(syms), backend=backend)
        fn = _MADE[recipe]
    lam, eta, local = fn(*blocks)
    return np.moveaxis(lam, 0, -1), np.moveaxis(eta, 0, -1), local


def jacobian_map(mech: ParallelMechanism, symbols: Any, *,
                 backend: str | None = "numpy") -> Callable[..., tuple[np.ndarray, np.ndarray]]:
    """A vectorised ``(Jx, Jq)``: arrays ``(N, rows, 6)`` and ``(N, rows, n)``.

    >>> import numpy as np
    >>> from sympy import symbols
    >>> from screwsym.systems.parallel import Limb, ParallelMechanism
    >>> from screwsym.systems.joints import R, P
    >>> x, y = symbols("x y", real=True)
    >>> z, p = [0, 0, 1], [x, y, 0]
    >>> m = ParallelMechanism(Limb(R([0, 0, 0], z), R([0, 1, 0], z), R(p, z), actuated=0),
    ...                       Limb(R([3, 0, 0], z), R([3, 1, 0], z), R(p, z), actuated=0),
    ...                       Limb(P([1, 0, 0]), P([0, 1, 0])))
    >>> Jx, Jq = jacobian_map(m, [x, y])(np.array([[1.0, 2.0]]))
    >>> Jx.shape, Jq.shape
    ((1, 6, 6), (1, 6, 2))
    """
    if not isinstance(mech, ParallelMechanism):
        raise TypeError(f"mech: expected a ParallelMechanism, got {type(mech).__name__}")
    syms = _symbols(symbols)
    Jx, Jq = mech.jacobian()
    fn = lambdify(syms, (Jx, Jq), backend, name="jacobian_x_q")

    def jac(*configurations: Any) -> tuple[np.ndarray, np.ndarray]:
        cols = _columns(configurations, len(syms))
        a, b = fn(*cols)
        shape = np.broadcast_shapes(*(c.shape for c in cols))
        return (np.broadcast_to(a, shape + Jx.shape).copy(),
                np.broadcast_to(b, shape + Jq.shape).copy())

    return jac
