"""The C loops of :mod:`screwsym.numeric` called directly on plain batches, into recycled results.

Explanation
===========

A generated function checks and reshapes its arguments in Python before its C loop
runs (:func:`screwsym.codegen._runtime.prepare`) and allocates a fresh result.  For
the plain case (every argument a C-contiguous, aligned, native ``float64`` array of the
same batch shape, ``out`` absent or a fitting array) :func:`direct` calls the loop
itself and returns, with the result, the loop's count of rows whose first result is
``nan`` (what the scale-free wrapper of the pitch and the foot point needs, without a
pass over the result).  Anything else returns ``None``: the generated function's own
path answers it, with its checks and messages.

A fresh result of ``(10^6, 6)`` doubles (48 MB) comes from pages that the system maps
anew and zeroes on first touch (glibc maps every block above 32 MB afresh): that costs
about as much as the kernel itself (``numeric.shift_origin`` on 10^6 screws: 12.3 ns a
screw, 6.9 with ``out=``).  A :class:`Recycler` keeps the last large result of a
function and hands it out again once nothing else holds it, as a caching allocator does.
"""

from __future__ import annotations

import builtins
import math
import sys
import threading
import types
from collections.abc import Callable
from typing import Any

import numpy as np

#: results of at least this many bytes are recycled (smaller ones come from malloc's heap,
#: whose pages are reused anyway) ...
RECYCLE_MIN = 1 << 20
#: ... and of at most this many: a larger result is not kept after its last use (at most
#: this much memory stays held per function once its caller has let its result go)
RECYCLE_MAX = 1 << 26


#: the switch of :func:`recycle_results` (one for the process)
_RECYCLING = {"on": True}


def recycle_results(enabled: bool | None = None) -> bool:
    """Whether the screw kernels hand out a large result again once it is let go.

    With the C back end, a result of 1 to 64 MB that the caller no longer holds
    in any way is reused by the next call of the same function (no fresh
    pages to zero: see the module's explanation).  ``recycle_results(False)``
    turns that off for the process (every result fresh, and nothing held after
    its last use); ``recycle_results()`` says whether it is on.  Returns the
    setting in force after the call.

    >>> from screwsym.numeric import recycle_results
    >>> recycle_results(False)
    False
    >>> recycle_results(True)
    True
    >>> recycle_results("yes")
    Traceback (most recent call last):
      ...
    TypeError: recycle_results: expected enabled to be True, False or None, got str
    """
    if enabled is not None:
        if not isinstance(enabled, bool):
            raise TypeError("recycle_results: expected enabled to be True, False or None, "
                            f"got {type(enabled).__name__}")
        _RECYCLING["on"] = enabled
    return _RECYCLING["on"]


def _refcounts_exact() -> bool:
    """CPython with its GIL: ``sys.getrefcount`` says exactly who holds an array."""
    gil = getattr(sys, "_is_gil_enabled", None)
    return sys.implementation.name == "cpython" and (gil is None or bool(gil()))


class Recycler:
    """The last large result of one function, handed out again once nothing else holds it.

    :meth:`empty` returns the kept array where it has the shape asked for and
    its only references are the recycler's own (no name, view, list, buffer
    or ``out=`` of the caller's refers to it: a view holds its base), else a
    new array, which it keeps instead.  Only arrays of :data:`RECYCLE_MIN` to
    :data:`RECYCLE_MAX` bytes, and only where reference counts are exact
    (CPython with the GIL).

    >>> r = Recycler()
    >>> a = r.empty((200_000, 6))
    >>> r.empty((200_000, 6)) is a          # a is still held here: a new array
    False
    >>> b = r.empty((200_000, 6)); b_id = id(b); del b
    >>> id(r.empty((200_000, 6))) == b_id   # let go: the same memory again
    True
    >>> small = r.empty((10, 6)); small is r.empty((10, 6))
    False
    """

    def __init__(self) -> None:
        self._last: np.ndarray | None = None
        self._lock = threading.Lock()
        self._on = _refcounts_exact()

    def empty(self, shape: tuple[int, ...]) -> np.ndarray:
        """A C-contiguous writeable ``float64`` array of ``shape``, its values undefined."""
        if not _RECYCLING["on"]:
            self._last = None  # turned off: let the one kept go at this function's next call
        if not (self._on and _RECYCLING["on"]) or not RECYCLE_MIN <= 8 * math.prod(shape) <= RECYCLE_MAX:
            return np.empty(shape)
        with self._lock:
            last = self._last
            # its references: self._last, the name `last` and getrefcount's argument
            if (last is not None and last.shape == shape and sys.getrefcount(last) == 3
                    and last.dtype == np.float64 and last.flags.c_contiguous
                    and last.flags.writeable):
                return last
            self._last = fresh = np.empty(shape)
            return fresh


def direct(fn: Any) -> Callable[[tuple, Any], tuple[np.ndarray, int] | None] | None:
    """``call(args, out)`` running the C loop of ``fn`` on a plain batch, or None.

    ``fn`` is a generated function of the C back end with one result and
    arguments of one trailing dimension each (its ``kernel`` returns the
    count of rows whose first result is ``nan``); for another, None.
    ``call`` returns ``(result, count)``, or None where the arguments are not
    a plain batch (see the module docstring).
    """
    kernel, meta = getattr(fn, "kernel", None), getattr(fn, "_screwsym_meta", None)
    if kernel is None or meta is None or meta["is_tuple"] or len(meta["outs"]) != 1:
        return None
    trailings = [tuple(t) for _, t, _ in meta["specs"]]
    if any(len(t) != 1 for t in trailings):
        return None
    sizes = [t[0] for t in trailings]
    trailing = tuple(meta["outs"][0])
    width = math.prod(trailing)
    recycler = Recycler()
    ndarray, f64, may_share = np.ndarray, np.dtype(np.float64), np.may_share_memory

    def call(args: tuple, out: Any) -> tuple[np.ndarray, int] | None:
        if len(args) != len(sizes):
            return None
        shape = None
        for a, k in zip(args, sizes, strict=True):
            # (dtype by identity: NumPy's own float64 descriptor; == costs 0.5 us)
            if (type(a) is not ndarray or a.ndim < 2 or a.dtype is not f64 or a.shape[-1] != k
                    or not a.flags.c_contiguous or not a.flags.aligned):
                return None
            if shape is None:
                shape = a.shape[:-1]
            elif a.shape[:-1] != shape:
                return None
        assert shape is not None
        want = shape + trailing
        if out is None:
            r = recycler.empty(want)
        elif (type(out) is ndarray and out.dtype is f64 and out.shape == want
              and out.flags.c_contiguous and out.flags.aligned and out.flags.writeable
              and not any(may_share(out, a) for a in args)):
            r = out
        else:
            return None
        n = math.prod(shape)
        count = kernel(n, *(a.reshape(n, k) for a, k in zip(args, sizes, strict=True)),
                       r.reshape(n, width) if trailing else r.reshape(n))
        return r, count

    return call


# The entry points of :func:`entry`: templates whose globals are bound per function (a
# closure, or a wrapper of *args, costs 15-30 ns more per call, a tenth of one screw's call)
_point: Any = None  # the C extension's one-point function
_rest: Any = None  # everything else: rest(args, out)
_one: Any = None  # what becomes of one point's result: one(arg0, result)


def _entry1(a0: Any, *, out: Any = None) -> Any:
    if out is None:
        r = _point(a0)
        if r is not None:
            return r
    return _rest((a0,), out)


def _entry1_one(a0: Any, *, out: Any = None) -> Any:
    if out is None:
        r = _point(a0)
        if r is not None:
            return _one(a0, r)
    return _rest((a0,), out)


def _entry2(a0: Any, a1: Any, *, out: Any = None) -> Any:
    if out is None:
        r = _point(a0, a1)
        if r is not None:
            return r
    return _rest((a0, a1), out)


def _entry2_one(a0: Any, a1: Any, *, out: Any = None) -> Any:
    if out is None:
        r = _point(a0, a1)
        if r is not None:
            return _one(a0, r)
    return _rest((a0, a1), out)


def _no_point(*args: Any) -> None:
    return None


def entry(fn: Any, rest: Callable, one: Callable | None = None) -> Callable:
    """A function of ``fn``'s parameters (by position or name) and ``out=``, calling its C parts.

    It calls the C extension's one-point function of ``fn`` first (for one
    point that returns the result, passed through ``one(arg0, result)`` where
    given), and ``rest(args, out)`` for everything else (a batch, ``out=``, or
    no extension).

    >>> def rest(args, out):
    ...     return ("rest", args, out)
    >>> def f(s, *, out=None): ...
    >>> g = entry(f, rest)
    >>> g(1.0), g(s=2.0, out=3)
    (('rest', (1.0,), None), ('rest', (2.0,), 3))
    >>> g.__name__, g.__code__.co_varnames[:1]
    ('f', ('s',))
    """
    arity = fn.__code__.co_argcount
    template = {(1, False): _entry1, (1, True): _entry1_one,
                (2, False): _entry2, (2, True): _entry2_one}.get((arity, one is not None))
    if template is None:
        raise ValueError(f"{fn.__name__}: expected one or two parameters, got {arity}")
    point = getattr(fn, "__globals__", {}).get("_point") or _no_point
    code = template.__code__
    changes: dict[str, Any] = {
        "co_varnames": fn.__code__.co_varnames[:arity] + code.co_varnames[arity:],
        "co_name": fn.__name__}
    if hasattr(code, "co_qualname"):
        changes["co_qualname"] = fn.__name__
    ns = {"__builtins__": builtins, "_point": point, "_rest": rest, "_one": one}
    made = types.FunctionType(code.replace(**changes), ns, fn.__name__)
    made.__kwdefaults__ = {"out": None}
    return made
