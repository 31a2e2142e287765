r"""The mobility analysis at many configurations at once, in floating point.

:func:`mobility_map` turns a :class:`~screwsym.systems.parallel.ParallelMechanism`
whose joints depend on symbols into a vectorised function of arrays of those
symbols' values: the joint twists of every limb are generated once with
:func:`screwsym.lambdify`, and at each configuration the ranks come from a
rank-revealing decomposition.  Use it to map where a mechanism meets a
constraint singularity over a workspace grid; use the exact
:meth:`~screwsym.systems.parallel.ParallelMechanism.mobility_cases` to find the
conditions themselves.

Rank, numerically
=================

A rank of twists mixes units (``omega`` a rate, ``v`` a rate times a length),
so first the moment rows of every configuration's twists are divided by a
length of that configuration, ``L = sum_j |omega_j| |v_j| / sum_j |omega_j|**2``
(``1`` where that is zero): the numerical rank is then unit-free, and a
mechanism and its copy scaled by ``1e8`` (or ``1e-8``) give the same map, as
the project's float policy is scale-invariant (:mod:`screwsym.core.decide`).
Then every twist is scaled to unit length (as a 6-vector); a limb's twists with
their halves swapped are decomposed by Householder QR with column pivoting
(``B^T P = Q R``), and its rank is the number of diagonal entries ``|R_jj|``
(non-increasing, estimates of the singular values) greater than ``rtol``
times the largest one (default ``rtol = 1e-9``).  The limb's constraint
system is spanned by the columns of ``Q`` past the rank: an orthonormal
basis of the wrenches reciprocal to its twists (the null space of
``(Delta A)^T``), 6-vectors in the order ``(f; C_O)``.  The union of the
limbs' constraints is decomposed the same way with the same relative
tolerance; its ``|R_jj|`` come back as ``sigma`` (relative to 1, as the
null vectors are unit vectors), so a map can show how near a configuration
is to a constraint singularity, not only whether it is one.  Pivoted QR is
rank-revealing in practice though not in the worst case (Kahan's matrix);
where it matters, check a configuration with ``numpy.linalg.svd``.

The NumPy back end (the default here) runs each step of the decomposition as
a few array operations over all configurations; ``backend="numba"`` compiles
the same algorithm as one parallel loop (``pip install -e ".[fast]"`` from a clone,
module ``screwsym.numeric._mobility_numba``), cached on disk by numba: the first call
on a machine compiles for seconds, later processes load it in under one.
The default stays NumPy (unlike :func:`screwsym.lambdify`'s) because under
load the two were within 1.3-2.5x of each other on the 3-RPS map, not worth
a first compilation nobody asked for.

Maps larger than memory
=======================

The function :func:`mobility_map` returns takes NumPy or Dask arrays.  Given a
Dask array (``pip install -e ".[dask]"`` from a clone, or ``pip install
"dask[array]"``), it returns a :class:`MobilityMap` of lazy Dask arrays chunked like the configurations:
each chunk is analysed by the same NumPy (or numba) code when the result is
computed, on the local scheduler or a cluster (``dask.array.blockwise``;
see ``screwsym.numeric._chunks``).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np
from sympy import ImmutableMatrix
from sympy.matrices import MatrixBase

from ..codegen import lambdify
from ..core.checks import check_positive_float
from ..core.formulas import SWAP
from ..systems.actuation import generic_limb_rank
from ..systems.parallel import ParallelMechanism
from ._chunks import batched, is_dask

# UNDEFINED (below) is public too, documented in mobility_map; not in __all__ yet, as the
# README's module table lists __all__
__all__ = ["MobilityMap", "mobility_map"]

#: the mark of a configuration where the mechanism is undefined (a twist not finite:
#: a NaN or infinite value given, or a formula dividing by zero there): its mobility,
#: constraint rank and limb constraints are ``-1`` and its ``sigma`` NaN, on every back end
UNDEFINED: int = -1


class MobilityMap(NamedTuple):
    """Arrays over the configurations (batch shape ``...``) from :func:`mobility_map`."""

    mobility: np.ndarray  #: ``(...)`` int: 6 - rank of the union; UNDEFINED (-1) where undefined
    constraint_rank: np.ndarray  #: ``(...)`` int: rank of that union
    limb_constraints: np.ndarray  #: ``(..., k)`` int: 6 - rank of each limb's twists
    sigma: np.ndarray  #: ``(..., 6)``: ``|R_jj|`` of the union's pivoted QR, largest first
    #: ``(...)`` int: the limbs' momentary internal motions, ``sum_i (g_i - rank T_i)`` with
    #: ``g_i`` the limb's generic rank (a leg at its own singularity: a stretched R-R-R leg);
    #: ``mobility + internal`` is what ``ParallelMechanism.mobility()`` gives there
    internal: np.ndarray


def mobility_map(
    mechanism: ParallelMechanism, args: Any, *, rtol: float = 1e-9, backend: str = "numpy"
) -> Callable[..., MobilityMap]:
    r"""A vectorised function giving the mobility of ``mechanism`` at many configurations.

    Explanation
    ===========

    ``args`` lists the symbols the joints depend on (symbols and vectors
    such as ``vector('p')``, as for :func:`screwsym.lambdify`).  The function
    returned takes one array per argument (scalars ``(...)``, vectors
    ``(..., 3)``, batch shapes broadcasting) and returns a
    :class:`MobilityMap`.  See the module docstring for the tolerance.  A
    configuration whose twists are not all finite (a NaN or infinite value)
    is marked :data:`UNDEFINED`: ``-1`` in the integer fields, NaN in
    ``sigma``, the same on every back end.  ``mobility`` is ``6`` minus the
    rank of the limbs' constraints; at a limb's own singularity (a leg
    stretched) the limb has a momentary idle motion, which
    :meth:`~screwsym.systems.parallel.ParallelMechanism.mobility` counts in
    its mobility and this map reports in a field of its own, ``internal``:
    ``mobility + internal`` agrees with ``mobility()`` at every configuration.  The rank is unit-free (the
    moment rows are divided by a length of each configuration): scaling the
    mechanism and its arguments by ``1e8`` changes no mobility.  Given Dask
    arrays, the fields come back as lazy Dask arrays, computed chunk by
    chunk (see the module docstring).

    Examples
    ========

    A planar four-bar whose joint B moves along the x-axis: at ``b_y = 0``
    all four joints are collinear and the coupler gains a freedom.

    >>> import numpy as np
    >>> from sympy import symbols
    >>> from screwsym.systems.parallel import ParallelMechanism, Limb
    >>> from screwsym.systems.joints import R
    >>> from screwsym.numeric.mobility import mobility_map
    >>> bx, by = symbols("b_x b_y", real=True)
    >>> z = [0, 0, 1]
    >>> fourbar = ParallelMechanism(Limb(R([0, 0, 0], z), R([bx, by, 0], z)),
    ...                             Limb(R([4, 0, 0], z), R([3, 0, 0], z)))
    >>> f = mobility_map(fourbar, [bx, by])
    >>> f(np.array([1.0, 1.0, 2.0]), np.array([1.0, 0.0, 0.5])).mobility
    array([1, 2, 1])
    >>> f(np.array([1.0, np.nan]), np.array([np.inf, 0.5])).mobility
    array([-1, -1])
    >>> da = __import__("pytest").importorskip("dask.array")
    >>> lazy = f(da.from_array(np.array([1.0, 1.0, 2.0]), chunks=2), np.array([1.0, 0.0, 0.5]))
    >>> lazy.mobility.chunks, lazy.mobility.compute()
    (((2, 1),), array([1, 2, 1]))

    Parameters
    ==========

    mechanism : ParallelMechanism
    args : list
        Symbols and vectors of symbols; every free symbol of the mechanism.
    rtol : float
        The relative tolerance of the numerical rank (default ``1e-9``).
    backend : {"numpy", "numba", "c"}
        The back end of the generated twist function.
    """
    if not isinstance(mechanism, ParallelMechanism):
        raise TypeError(
            f"mechanism: expected a ParallelMechanism, got {type(mechanism).__name__}"
        )
    rtol = check_positive_float(rtol, "rtol")
    limbs = mechanism.limbs
    matrices = tuple(ImmutableMatrix(limb.twists.matrix) for limb in limbs)
    listed = args if isinstance(args, (list, tuple)) else [args]
    given: set[Any] = set()
    for a in listed:
        given |= getattr(a, "free_symbols", set())
    missing = sorted(set().union(*(m.free_symbols for m in matrices)) - given, key=str)
    if missing:
        raise ValueError(
            f"args: expected every symbol of the mechanism, missing {', '.join(map(str, missing))}"
        )
    twists_of = lambdify(list(listed), matrices, backend=backend)
    generic = sum(generic_limb_rank(limb) for limb in limbs)  # sum_i g_i
    sizes = [m.cols for m in matrices]
    offsets = tuple(int(x) for x in np.cumsum([0, *sizes]))
    analyse = _analyse_numba if backend == "numba" else _analyse_numpy

    def numpy_mobility(*values):
        Ts = twists_of(*values)
        if not isinstance(Ts, tuple):  # pragma: no cover - a one-limb mechanism
            Ts = (Ts,)
        batch = np.broadcast_shapes(*(T.shape[:-2] for T in Ts))
        T = np.concatenate(
            [np.broadcast_to(T, batch + (6, n)).reshape(-1, 6, n)
             for T, n in zip(Ts, sizes, strict=True)], axis=-1)
        # a configuration whose twists are not all finite (a NaN or inf value, a formula
        # dividing by zero there) is undefined: analysed as zeros, then marked (UNDEFINED)
        undefined = ~np.isfinite(T).all(axis=(1, 2))
        if undefined.any():
            T = np.where(undefined[:, None, None], 0.0, T)
        ranks, counts, sigma = analyse(_unit_free(T), offsets, rtol)
        if undefined.any():
            ranks, counts, sigma = ranks.copy(), counts.copy(), sigma.copy()
            ranks[undefined] = 6 - UNDEFINED  # so that mobility = 6 - rank is UNDEFINED
            counts[undefined] = UNDEFINED
            sigma[undefined] = np.nan
        k = len(sizes)
        # sum_i (g_i - rank T_i), rank T_i = 6 - counts_i
        internal = np.where(undefined, UNDEFINED, generic - 6 * k + counts.sum(axis=-1))
        return (
            (6 - ranks).reshape(batch),
            np.where(undefined, UNDEFINED, ranks).reshape(batch),
            counts.reshape(batch + (k,)),
            sigma.reshape(batch + (6,)),
            internal.reshape(batch),
        )

    trailing = [_trailing(a) for a in listed]
    outputs = [((), np.int64), ((), np.int64), ((len(sizes),), np.int64), ((6,), float),
               ((), np.int64)]
    recipe = (mechanism, tuple(ImmutableMatrix(a) if isinstance(a, MatrixBase) else a
                               for a in listed), rtol, backend)
    if len(_MADE) >= 64:  # a bounded memory of recent maps
        _MADE.pop(next(iter(_MADE)))
    _MADE[recipe] = numpy_mobility
    # for Dask: a picklable recipe (the generated code is not), rebuilt once per worker
    chunk = functools.partial(_chunk, recipe)

    def mobility(*values):
        """The mobility at each configuration (see screwsym.numeric.mobility.mobility_map)."""
        if any(is_dask(v) for v in values):
            return MobilityMap(*batched(chunk, values, trailing, outputs))
        return MobilityMap(*numpy_mobility(*values))

    mobility.__name__ = "mobility_map_of_" + type(mechanism).__name__
    return mobility


#: the NumPy functions of the maps made in this process, by their recipe (a Dask worker
#: that receives a recipe it has not seen makes the map once, then finds it here)
_MADE: dict[tuple, Callable[..., tuple]] = {}


def _chunk(recipe: tuple, *blocks: np.ndarray) -> tuple:
    """One chunk of a Dask map: ``recipe`` is ``(mechanism, args, rtol, backend)``."""
    fn = _MADE.get(recipe)
    if fn is None:
        mechanism, args, rtol, backend = recipe
        mobility_map(mechanism, list(args), rtol=rtol, backend=backend)
        fn = _MADE[recipe]
    return fn(*blocks)


def _trailing(a: Any) -> tuple[int, ...]:
    """The trailing shape of one argument's array: ``()`` for a symbol, ``(n,)`` for a vector."""
    if isinstance(a, MatrixBase):
        return (len(a),) if 1 in a.shape else tuple(a.shape)
    hook = getattr(type(a), "_lambdify_argument", None)
    if hook is not None:
        return (len(a._lambdify_argument()[0]),)
    return ()


def _unit_free(T: np.ndarray) -> np.ndarray:
    r"""Twists ``(N, 6, M)`` with their moment rows divided by a length of their configuration.

    A rank of twists mixes units: ``omega`` is a rate, ``v`` a rate times a
    length.  Dividing ``v`` by the length ``L = sum_j |omega_j| |v_j| /
    sum_j |omega_j|**2`` of the configuration (``1`` where it is zero or not
    finite: all translations, or all axes through the origin) leaves the rank
    unchanged in exact arithmetic and makes the numerical one unit-free: a
    mechanism scaled by any factor gives the same matrix up to the scale of
    the prismatic columns, which the unit-length normalisation removes.  This
    is the float policy of :mod:`screwsym.core.decide` (relative, so scale
    invariant) applied to a rank.

    >>> T = np.array([[[0, 0], [0, 0], [1, 1], [0, 0], [0, -1e8], [0, 0]]], dtype=float)
    >>> _unit_free(T)[0, 4]                     # R about z through O and through (1e8, 0, 0)
    array([ 0., -2.])
    """
    w = np.sqrt(np.einsum("nqm,nqm->nm", T[:, :3], T[:, :3]))
    v = np.sqrt(np.einsum("nqm,nqm->nm", T[:, 3:], T[:, 3:]))
    num, den = (w * v).sum(axis=-1), (w * w).sum(axis=-1)
    ok = (num > 0) & (den > 0) & np.isfinite(num) & np.isfinite(den)
    L = np.where(ok, num / np.where(ok, den, 1.0), 1.0)
    out = np.array(T, dtype=float, copy=True)
    out[:, 3:] /= L[:, None, None]
    return out


def _qrcp(C: np.ndarray, want_q: bool):
    """Householder QR with column pivoting of a batch of vector sets, in NumPy.

    ``C`` is ``(m, n, N)``: ``m`` vectors of ``R^n`` for each of ``N`` items,
    the batch last so that every operation runs over long contiguous rows.
    Returns ``|R_jj|`` ``(min(m, n), N)`` (non-increasing down the first axis)
    and, if asked, ``Q^T`` ``(n, n, N)``, whose rows past the rank span the
    orthogonal complement of the vectors.  Written out (not
    ``numpy.linalg.qr``, which has no column pivoting, nor ``svd``, which
    costs 5-8 us per 6 x 6 matrix here) so that each step is a few array
    operations over the whole batch.
    """
    C = np.array(C, dtype=float, copy=True)
    m, n, N = C.shape
    k = min(m, n)
    rdiag = np.zeros((k, N))
    Qt = np.repeat(np.eye(n)[:, :, None], N, axis=2) if want_q else None
    used = np.zeros((m, N), dtype=bool)
    for j in range(k):
        rest = C[:, j:, :]
        norms = np.einsum("cqn,cqn->cn", rest, rest)
        norms[used] = -1.0
        p = np.argmax(norms, axis=0)
        np.put_along_axis(used, p[None, :], True, axis=0)
        nx = np.sqrt(np.maximum(np.take_along_axis(norms, p[None, :], axis=0)[0], 0.0))
        v = np.take_along_axis(rest, p[None, None, :], axis=0)[0]  # (n - j, N), a copy
        v[0] += np.where(v[0] >= 0, 1.0, -1.0) * nx
        vn = np.sqrt(np.einsum("qn,qn->n", v, v))
        v /= np.where(vn == 0, 1.0, vn)
        t = np.einsum("cqn,qn->cn", rest, v)
        rest -= 2 * t[:, None, :] * v[None, :, :]
        rdiag[j] = nx
        if Qt is not None:  # want_q
            qs = Qt[j:, :, :]
            qs -= 2 * v[:, None, :] * np.einsum("qn,qkn->kn", v, qs)[None, :, :]
    return rdiag, Qt


def _rank(rdiag: np.ndarray, rtol: float) -> np.ndarray:
    """Numerical rank from ``|R_jj|`` ``(k, N)``, largest first."""
    if rdiag.shape[0] == 0:
        return np.zeros(rdiag.shape[1:], dtype=int)
    return np.sum(rdiag > rtol * rdiag[:1], axis=0)


def _analyse_numpy(T: np.ndarray, offsets: tuple, rtol: float):
    """``T`` ``(N, 6, M)``: every limb's twists side by side, limb i in columns offsets[i:i+2]."""
    N = T.shape[0]
    k = len(offsets) - 1
    norms = np.sqrt(np.einsum("nqm,nqm->mn", T, T))
    rows = np.transpose(T, (2, 1, 0))[:, SWAP, :] / np.where(norms == 0, 1.0, norms)[:, None, :]
    nulls, counts = [], []
    for i in range(k):
        rdiag, Qt = _qrcp(rows[offsets[i]:offsets[i + 1]], True)
        r = _rank(rdiag, rtol)
        low = int(r.min()) if N else 6  # rows below every item's rank are never null vectors
        keep = np.arange(low, 6)[:, None] >= r[None, :]
        nulls.append(Qt[low:] * keep[:, None, :])
        counts.append(6 - r)
    union = np.concatenate(nulls, axis=0)
    rdiag, _ = _qrcp(union, False)
    sigma = np.zeros((N, 6))
    sigma[:, : rdiag.shape[0]] = rdiag[:6].T
    return _rank(sigma.T, rtol), np.stack(counts, axis=-1), sigma


def _analyse_numba(T: np.ndarray, offsets: tuple, rtol: float):
    """:func:`_analyse_numpy` as one compiled parallel loop (``screwsym.numeric._mobility_numba``)."""
    from ._mobility_numba import analyse_loop

    N = T.shape[0]
    k = len(offsets) - 1
    ranks = np.zeros(N, dtype=np.int64)
    counts = np.zeros((N, k), dtype=np.int64)
    sigma = np.zeros((N, 6))
    analyse_loop(np.ascontiguousarray(T, dtype=np.float64),
                 np.asarray(offsets, dtype=np.int64), rtol, ranks, counts, sigma)
    return ranks, counts, sigma
