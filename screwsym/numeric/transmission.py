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
from sympy import lambdify as sympy_lambdify

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
    by zero (a singular configuration: a zero actuation wrench or output
    twist) the indices are NaN, and nowhere else; every other index lies in
    ``[0, 1]`` (rounding beyond it is clipped).  The exact local index (an
    unevaluated ``Min`` at a symbolic pose) is not used: the least index is
    taken in NumPy.

    Scale: the formulas are polynomials of high degree in the configuration,
    which overflow in floating point from about ``1e150`` (and underflow
    below ``1e-150``).  The indices are dimensionless, so where the
    mechanism's geometry is homogeneous in the length symbols (every point of
    the mechanism scales with them: no constant length, the symbols inside
    ``sin``/``cos`` are angles and are not scaled), each configuration's lengths
    are first divided by a power of two near their largest (exact in floating
    point): the same indices at ``1e-150`` or ``1e150`` times a configuration as
    at it.  Otherwise the configurations whose lengths lie beyond ``2**±64``
    are evaluated one by one with ``mpmath`` (SymPy's ``lambdify``; its
    exponents have no bound), slower but right.

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
    lengths, homogeneous = _length_symbols(mech, syms)
    wide = functools.cache(lambda: sympy_lambdify(syms, exprs, "mpmath"))

    def numpy_indices(*configurations: Any) -> TransmissionMap:
        cols = _columns(configurations, k)
        shape = np.broadcast_shapes(*(c.shape for c in cols))
        cols = [np.broadcast_to(c, shape) for c in cols]
        if homogeneous:
            cols = _normalised(cols, lengths)
        values = _evaluate(fn, cols, lengths, None if homogeneous else wide)
        arr = [np.broadcast_to(v, shape) for v in values]
        lam = _in_zero_one(np.stack(arr[:n]))
        eta = _in_zero_one(np.stack(arr[n:]))
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


def _length_symbols(mech: ParallelMechanism, syms: list) -> tuple[list[int], bool]:
    """The columns of the length symbols (those of ``syms`` in no ``sin``/``cos``), and whether
    the mechanism's geometry is homogeneous in them: each twist of each limb, with every
    length symbol ``s`` made ``2 s``, is ``2**d`` times its direction and ``2**(d + 1)`` times
    its moment (every point doubles, no constant length), decided exactly."""
    from sympy import Function, cancel, cos, sin

    twists = [t.matrix for limb in mech.limbs for t in limb.twists.screws]
    angles = set()
    for M in twists:
        for f in M.atoms(sin, cos, Function):
            angles |= f.free_symbols
    cols = [j for j, s in enumerate(syms) if s not in angles]
    doubled = {syms[j]: 2 * syms[j] for j in cols}
    if not cols:
        return cols, False
    for M in twists:
        D = M.xreplace(doubled)
        ratios = set()
        for i in range(6):
            if M[i] == 0:
                if cancel(D[i]) != 0:
                    return cols, False
                continue
            r = cancel(D[i] / M[i] / (2 if i >= 3 else 1))
            if not r.is_number:
                return cols, False
            ratios.add(r)
        if len(ratios) > 1:
            return cols, False
    return cols, True


def _in_zero_one(a: np.ndarray) -> np.ndarray:
    """``a`` (its own array) with each index in ``[0, 1]``: an index is ``|w o t|`` over the
    largest such product, so beyond only by rounding (clipped), and ``inf`` is a division by
    zero, the singular pose (nan, as 0/0 is).  In place, in two passes where none is out."""
    if a.size == 0 or (a.min() >= 0 and a.max() <= 1):  # (a nan fails both)
        return a  # the common case: two reductions
    with np.errstate(invalid="ignore"):
        out = ~((a >= 0) & (a <= 1)) & ~np.isnan(a)
    if out.any():
        v = a[out]
        a[out] = np.where(np.isinf(v), np.nan, np.clip(v, 0.0, 1.0))
    return a


def _normalised(cols: list, lengths: list[int]) -> list:
    """The configurations with their lengths divided by a power of two near the largest (exact)."""
    big = np.max(np.abs(np.stack([cols[j] for j in lengths])), axis=0)
    with np.errstate(invalid="ignore"):
        _, e = np.frexp(np.where(np.isfinite(big) & (big > 0), big, 1.0))
    out = list(cols)
    for j in lengths:
        out[j] = np.ldexp(cols[j], -e)
    return out


#: beyond these magnitudes of a length (``2**±64``) a configuration is evaluated with mpmath
_WIDE = (2.0**-64, 2.0**64)


def _evaluate(fn: Callable[..., Any], cols: list, lengths: list[int],
              wide: Callable[[], Any] | None) -> list:
    """``fn`` at the configurations in float64; those whose largest length is extreme (where
    the geometry is not homogeneous, so cannot be rescaled: ``wide`` is given) one by one
    with ``wide()``, the indices in mpmath, whose exponents do not overflow."""
    with np.errstate(all="ignore"):
        values = [np.asarray(v, dtype=float) for v in fn(*cols)]
    if wide is None or not lengths or not cols[0].ndim:
        return values
    # a configuration is far where its largest length is beyond 2**64 (its indices then
    # overflow to inf, nan or 0: looked at only where one is) or below 2**-64 (then its first
    # length is): in the common case reductions and one pass over one column
    shape = np.broadcast_shapes(*(np.shape(v) for v in values), cols[0].shape)
    cand = np.abs(cols[lengths[0]]) < _WIDE[0]
    for v in values:
        if v.size and not (v.min() > 0 and v.max() < np.inf):  # (a nan fails both)
            cand = cand | np.broadcast_to(~((v > 0) & (v < np.inf)), shape)
    idx = np.flatnonzero(cand)
    if not idx.size:
        return values
    where = np.unravel_index(idx, shape)
    big = np.abs(np.broadcast_to(cols[lengths[0]], shape)[where])  # each one's largest length
    for j in lengths[1:]:
        np.maximum(big, np.abs(np.broadcast_to(cols[j], shape)[where]), out=big)
    far = np.zeros(shape, dtype=bool)
    far[where] = (big > _WIDE[1]) | ((big > 0) & (big < _WIDE[0]))
    if not far.any():
        return values
    out = [np.array(np.broadcast_to(v, far.shape), dtype=float) for v in values]
    import mpmath  # type: ignore[import-untyped]  # SymPy's own dependency

    f = wide()
    for at in zip(*np.nonzero(far), strict=True):
        row = [mpmath.mpf(float(np.broadcast_to(c, shape)[at])) for c in cols]
        try:
            got = [float(v) for v in f(*row)]
        except ZeroDivisionError:  # a division by zero: the singular pose, nan
            got = [np.nan] * len(out)
        for v, g in zip(out, got, strict=True):
            v[at] = g
    return out


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
