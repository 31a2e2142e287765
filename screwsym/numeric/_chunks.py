r"""Maps larger than memory: a batched NumPy function run on NumPy or Dask arrays.

:func:`batched` applies a function of NumPy arrays that works configuration by
configuration (each result entry depends only on the same batch entry of the
arguments) to arguments that may be Dask arrays.  Without a Dask argument it
simply calls the function.  With one, it returns Dask arrays built by one
:func:`dask.array.blockwise` call: each chunk of the batch runs the function
on NumPy blocks, lazily, on whatever scheduler computes the result (the local
threaded scheduler, processes or a ``dask.distributed`` cluster); nothing runs
before ``compute()``.  The results of one chunk are packed into one float
array (so the function runs once per chunk however many results it has) and
unpacked lazily.  Dask is optional (``pip install -e ".[dask]"`` from a clone,
or ``pip install "dask[array]"``); it is imported only when a Dask array is given.

Used by :func:`screwsym.numeric.mobility.mobility_map`; the other numeric maps
of the package use it the same way.
"""

from __future__ import annotations

import string
import sys
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

__all__ = ["batched", "is_dask"]


def is_dask(value: Any) -> bool:
    """Whether ``value`` is a Dask array (without importing Dask when it is not loaded)."""
    da = sys.modules.get("dask.array")
    return da is not None and isinstance(value, da.Array)


def batched(
    fn: Callable[..., tuple[np.ndarray, ...]],
    values: Sequence[Any],
    trailing_in: Sequence[tuple[int, ...]],
    outputs: Sequence[tuple[tuple[int, ...], Any]],
) -> tuple[Any, ...]:
    r"""``fn(*values)``, chunk by chunk when a value is a Dask array.

    Explanation
    ===========

    ``fn`` takes NumPy arrays, argument ``i`` of shape ``batch_i +
    trailing_in[i]`` (the batch shapes broadcasting), and returns a tuple of
    arrays, result ``j`` of shape ``batch + outputs[j][0]`` and dtype
    ``outputs[j][1]``.  It must work entry by entry along the batch (a map
    over configurations).  With no Dask array among ``values`` this is
    ``fn(*values)``.  Otherwise every value becomes a Dask array with its
    trailing axes in one chunk, the batch chunks are unified, and the results
    come back as lazy Dask arrays chunked like the batch.  Integer results
    travel as float64 inside a chunk (exact below ``2**53``).  For the
    process-based schedulers and ``dask.distributed``, ``fn`` must pickle: a
    module-level function or a ``functools.partial`` of one with picklable
    arguments.  A function made by :func:`screwsym.lambdify` pickles by
    reference and loads only where its disk cache is shared
    (:mod:`screwsym.codegen.generated`); on other machines rebuild it inside
    ``fn`` from its recipe, as :func:`~screwsym.numeric.mobility.mobility_map` does.

    Examples
    ========

    >>> import numpy as np
    >>> def norms(v):
    ...     return (np.linalg.norm(v, axis=-1), v.sum(axis=-1).astype(int))
    >>> n, s = batched(norms, [np.ones((4, 3))], [(3,)], [((), float), ((), int)])
    >>> n.round(3), s
    (array([1.732, 1.732, 1.732, 1.732]), array([3, 3, 3, 3]))
    >>> da = __import__("pytest").importorskip("dask.array")
    >>> v = da.ones((10, 3), chunks=(4, 3))
    >>> n, s = batched(norms, [v], [(3,)], [((), float), ((), int)])
    >>> n.chunks, s.dtype, float(n.sum().compute()) == 10 * 3 ** 0.5
    (((4, 4, 2),), dtype('int64'), True)
    """
    if not any(is_dask(v) for v in values):
        return fn(*values)
    import dask.array as da

    arrays = [da.asarray(v) for v in values]
    for i, (a, t) in enumerate(zip(arrays, trailing_in, strict=True)):
        if a.ndim < len(t) or tuple(a.shape[a.ndim - len(t):]) != tuple(t):
            raise ValueError(
                f"values[{i}]: expected an array of shape (..., {', '.join(map(str, t))}), "
                f"got shape {a.shape}"
            )
    batch = np.broadcast_shapes(*(tuple(a.shape[: a.ndim - len(t)])
                                  for a, t in zip(arrays, trailing_in, strict=True)))
    nb = len(batch)
    letters = iter(string.ascii_letters)
    bidx = "".join(next(letters) for _ in range(nb))
    pairs: list[Any] = []
    for a, t in zip(arrays, trailing_in, strict=True):
        a = da.broadcast_to(a, batch + tuple(t))
        if t:
            a = a.rechunk({nb + k: -1 for k in range(len(t))})
        pairs += [a, bidx + "".join(next(letters) for _ in t)]
    sizes = [int(np.prod(shape, dtype=int)) for shape, _ in outputs]
    total = sum(sizes)
    packed_axis = next(letters)

    def chunk(*blocks: np.ndarray) -> np.ndarray:
        results = fn(*blocks)
        shape = np.broadcast_shapes(*(b.shape[: b.ndim - len(t)]
                                      for b, t in zip(blocks, trailing_in, strict=True)))
        return np.concatenate(
            [np.asarray(r, dtype=float).reshape(shape + (n,))
             for r, n in zip(results, sizes, strict=True)], axis=-1)

    packed = da.blockwise(chunk, bidx + packed_axis, *pairs,
                          new_axes={packed_axis: total}, concatenate=True,
                          dtype=float, meta=np.empty((0,) * (nb + 1)))
    out = []
    offset = 0
    for (shape, dtype), n in zip(outputs, sizes, strict=True):
        part = packed[..., offset:offset + n]
        offset += n
        part = part.reshape(batch + tuple(shape)) if shape else part[..., 0]
        out.append(part.astype(dtype))
    return tuple(out)
