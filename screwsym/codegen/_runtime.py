"""What generated functions call at run time: checking arrays, allocating results.

All input checking of :func:`screwsym.lambdify`'s generated functions, and
all of its wording, lives here.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np


@dataclass(frozen=True)
class Arg:
    """One argument: its parameter name, its trailing shape and what it is."""

    name: str
    trailing: tuple[int, ...]
    what: str

    @property
    def size(self) -> int:
        return math.prod(self.trailing)


def describe_trailing(trailing: tuple[int, ...], what: str) -> str:
    dims = ", ".join(str(d) for d in trailing)
    return f"(..., {dims}) for {what}" if trailing else f"(...) for {what}"


def _is_number(v: Any) -> bool:
    if v is None or isinstance(v, (bool, np.bool_)):
        return False
    if isinstance(v, numbers.Real):
        return True
    # SymPy numbers (Rational, Float, Integer) are real numbers too
    return bool(getattr(v, "is_Number", False)) and getattr(v, "is_extended_real", False) is True


def as_real_array(value: Any, name: str, trailing: tuple[int, ...], what: str) -> np.ndarray:
    """Return ``value`` as a ``float64`` array whose shape ends in ``trailing``.

    Raises ``TypeError`` for complex, boolean, ``None``, string or other
    non-real input and ``ValueError`` for a wrong trailing shape; each
    message names the argument, says what was expected and what came.

    >>> as_real_array([1, 2, 3], "A", (3,), "a point").dtype
    dtype('float64')
    >>> as_real_array(np.zeros((4, 5)), "s", (6,), "a screw (S; S0)")
    Traceback (most recent call last):
    ...
    ValueError: s: expected an array of shape (..., 6) for a screw (S; S0), got shape (4, 5)
    >>> as_real_array(None, "h", (), "a scalar")
    Traceback (most recent call last):
    ...
    TypeError: h: expected real numbers, got None
    >>> as_real_array([10**400, 1], "h", (), "a scalar")
    Traceback (most recent call last):
    ...
    ValueError: h: expected real numbers within the range of doubles (|x| <= 1.8e308), got an integer of 401 digits
    """
    if value is None or isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: expected real numbers, got {value!r}")
    try:
        arr = value if isinstance(value, np.ndarray) else np.asarray(value)
    except (TypeError, ValueError) as exc:  # ragged nesting, unconvertible objects
        raise TypeError(
            f"{name}: expected an array of real numbers, got {type(value).__name__} ({exc})"
        ) from None
    kind = arr.dtype.kind
    if kind == "c":
        raise TypeError(
            f"{name}: expected real numbers, got dtype {arr.dtype} (screwsym computes in real "
            "arithmetic; pass .real if the imaginary part is meant to be dropped)"
        )
    if kind == "O":
        bad = next((v for v in arr.flat if not _is_number(v)), _NONE)
        if bad is not _NONE:
            raise TypeError(
                f"{name}: expected an array of real numbers, got {type(value).__name__} "
                f"holding objects that are not real numbers ({type(bad).__name__} {bad!r})"
            )
        try:
            arr = arr.astype(np.float64)
        except OverflowError:  # a Python int beyond the doubles
            raise ValueError(_out_of_range(name, arr)) from None
    elif kind not in "fiu":
        raise TypeError(f"{name}: expected an array of real numbers, got dtype {arr.dtype}")
    nt = len(trailing)
    if arr.ndim < nt or arr.shape[arr.ndim - nt :] != trailing:
        raise ValueError(
            f"{name}: expected an array of shape {describe_trailing(trailing, what)}, "
            f"got shape {arr.shape}"
        )
    return arr.astype(np.float64, copy=False)


_NONE = object()


def _out_of_range(name: str, arr: np.ndarray) -> str:
    big = next(v for v in arr.flat if isinstance(v, numbers.Integral) and abs(int(v)) > _MAX)
    return (
        f"{name}: expected real numbers within the range of doubles (|x| <= 1.8e308), got an "
        f"integer of {len(str(abs(int(big))))} digits"
    )


#: the largest double, as an integer
_MAX = int(np.finfo(np.float64).max)


class Trailings(tuple):
    """The trailing shapes of a generated function's results, and whether it returns a tuple.

    ``out=`` of a function with one result (not a tuple) is one array, never a tuple.
    """

    is_tuple: bool

    def __new__(cls, trailings: Any, is_tuple: bool) -> Trailings:
        self = super().__new__(cls, trailings)
        self.is_tuple = is_tuple
        return self


def prepare(
    specs: Sequence[Arg],
    values: Sequence[Any],
    out: Any,
    trailings: tuple[tuple[int, ...], ...],
    contiguous: bool,
) -> tuple[list[np.ndarray], list[np.ndarray], tuple[int, ...], int]:
    """Check every argument and ``out``; bring each to 2-D ``(n_i, k)``, ``n_i`` = 1 or ``n``.

    Returns the 2-D inputs, the result arrays (2-D views of ``out`` where it
    was given), the broadcast batch shape and ``n``, its size.  An input
    that shares memory with a result array is copied first, so that
    ``out=`` may be one of the inputs.
    """
    arrays = [
        as_real_array(v, a.name, a.trailing, a.what) for a, v in zip(specs, values, strict=True)
    ]
    batches = [arr.shape[: arr.ndim - len(a.trailing)] for a, arr in zip(specs, arrays, strict=True)]
    try:
        shape = np.broadcast_shapes(*batches)
    except ValueError:
        listed = ", ".join(
            f"{a.name} has batch shape {b}" for a, b in zip(specs, batches, strict=True)
        )
        raise ValueError(
            f"{', '.join(a.name for a in specs)}: expected batch (leading) shapes that "
            f"broadcast together, got {listed}"
        ) from None
    n = math.prod(shape)
    results = outputs(out, trailings, shape, n)
    ins = []
    for a, arr, batch in zip(specs, arrays, batches, strict=True):
        if out is not None and any(np.may_share_memory(arr, r) for r in results):
            arr = arr.copy()  # out= aliases this input: read from a copy
        if batch != shape and math.prod(batch) != 1:
            arr = np.broadcast_to(arr, shape + a.trailing)
        arr = arr.reshape(-1, a.size)
        if contiguous and not arr.flags.c_contiguous:
            arr = np.ascontiguousarray(arr)
        ins.append(arr)
    return ins, results, shape, n


def outputs(
    out: Any, trailings: tuple[tuple[int, ...], ...], shape: tuple[int, ...], n: int
) -> list[np.ndarray]:
    """Fresh result arrays, or 2-D views of the caller's ``out`` arrays, checked."""
    if out is None:
        return [np.empty((n, math.prod(t))) if t else np.empty(n) for t in trailings]
    if isinstance(out, tuple) and getattr(trailings, "is_tuple", True) is False:
        raise ValueError(
            f"out: expected one array (the function has one result, not a tuple), got a tuple "
            f"of {len(out)}"
        )
    outs = out if isinstance(out, tuple) else (out,)
    if len(outs) != len(trailings):
        raise ValueError(f"out: expected {len(trailings)} arrays, one per result, got {len(outs)}")
    views = []
    for j, (arr, t) in enumerate(zip(outs, trailings, strict=True)):
        where = f"out[{j}]" if isinstance(out, tuple) else "out"
        want = shape + t
        if (
            not isinstance(arr, np.ndarray)
            or arr.dtype != np.float64
            or arr.shape != want
            or not arr.flags.c_contiguous
            or not arr.flags.writeable
        ):
            got = (
                f"{arr.dtype} array of shape {arr.shape}"
                + ("" if arr.flags.c_contiguous else ", not C-contiguous")
                + ("" if arr.flags.writeable else ", read-only")
                if isinstance(arr, np.ndarray)
                else type(arr).__name__
            )
            raise ValueError(
                f"{where}: expected a writeable C-contiguous float64 array of shape {want}, "
                f"got {got}"
            )
        views.append(arr.reshape(n, math.prod(t)) if t else arr.reshape(n))
    for j in range(len(views)):
        for k in range(j):
            if np.may_share_memory(views[j], views[k]):
                raise ValueError(f"out: expected separate arrays, out[{k}] and out[{j}] overlap")
    return views

