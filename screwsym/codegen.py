r"""From closed forms to numeric functions: :func:`lambdify` and :func:`c_source`.

Explanation
===========

A derivation in screwsym ends in a SymPy expression, matrix or screw.  This
module turns it into a function of NumPy arrays, in one of three back ends,
or into C source for a controller.

Array convention (used by :mod:`screwsym.numeric` as well):

* a screw argument or result is an array of shape ``(..., 6)`` in the book's
  ray order ``(S; S0)`` (a twist ``(omega; v_O)``, a wrench ``(f; C_O)``);
* a vector (``vector('A')``, any column or row matrix of symbols) is
  ``(..., 3)`` (``(..., n)`` for ``n`` entries), a matrix ``(..., m, n)``;
* a symbol is a scalar ``(...)``;
* the leading ("batch") dimensions of all arguments broadcast as in NumPy,
  and every result has the broadcast batch shape in front of its own shape.
  A single screw ``(6,)`` gives a scalar result as ``numpy.float64``.

Input is checked in one place (:func:`_as_real_array`, :func:`_prepare`):
a wrong trailing shape, batch shapes that do not broadcast, complex, boolean
or non-numeric input raise ``TypeError``/``ValueError`` naming the argument,
what was expected and what came.  Integer and ``float32`` input is computed
in ``float64``.

Where a formula divides, the generated code follows IEEE 754 and never warns:
``x/0`` gives ``inf`` or ``nan``.  What that means for each function of
:mod:`screwsym.numeric` (for instance the pitch of a couple is ``inf``, as
the symbolic :func:`screwsym.pitch` gives ``oo``) is written in its
docstring.

Back ends
=========

``"numpy"`` (default, no extra dependency)
    NumPy array expressions after common-subexpression elimination,
    evaluated in blocks of :data:`BLOCK` rows so that the temporaries stay
    in cache.
``"numba"`` (the compiled back end; ``pip install screwsym[fast]``)
    One fused loop per function, compiled by ``numba.njit`` on first call
    (one signature: C-contiguous ``float64``), ``error_model='numpy'`` so
    that division follows IEEE 754.  Chosen by the figures in
    ``benchmarks/README.md``: it reaches the memory-bound floor, needs no C
    compiler at run time and compiles in well under a second.
``"c"``
    The :func:`c_source` of the expression, compiled with the system C
    compiler (``cc``) into a shared library and called through ``ctypes``.

A single point (every argument unbatched: a ``(6,)`` screw, a ``(3,)``
vector, a Python or NumPy float) takes a fast path in every back end: the
same common-subexpression code in plain Python floats (``math``), which is
faster than any array call.  A division by zero there falls back to the
array code, so its IEEE result is the same.

Generated functions have stable names (``name`` or ``lambdified_<hash of
the expression>``), their source is registered in :mod:`linecache` so that
``inspect.getsource`` and tracebacks show it, and they are cached per
signature ``(args, expr, backend, cse, name)``.

Examples
========

>>> import numpy as np
>>> from screwsym import Screw, vector, pitch, lambdify
>>> s = Screw(vector("S"), vector("S0"))
>>> f = lambdify([s], pitch(s), name="pitch_of")
>>> f(np.array([1.0, 1.0, 0.0, 1.0, 0.0, 0.0]))        # Example 1.4
np.float64(0.5)
>>> f(np.array([[1.0, 0, 0, 2, 0, 0], [0, 0, 2, 0, 0, 1]]))
array([2. , 0.5])
>>> import inspect
>>> print(inspect.getsource(f).splitlines()[0])
def pitch_of(s, *, out=None):

See Also
========

screwsym.numeric, c_source

References
==========

.. [1] SymPy, ``sympy.utilities.lambdify`` and ``sympy.cse``.
.. [2] kingdon (tBuLi/kingdon), ``kingdon/codegen.py``: derive once, generate
   fast code, register the source in ``linecache``.
"""

from __future__ import annotations

import ctypes
import hashlib
import keyword
import linecache
import math
import os
import shutil
import subprocess
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from sympy import Basic, Expr, I, ImmutableMatrix, Symbol, cse, numbered_symbols, srepr, sympify
from sympy.core.sympify import SympifyError
from sympy.matrices import MatrixBase
from sympy.printing.c import C99CodePrinter
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.pycode import PythonCodePrinter

__all__ = ["lambdify", "c_source", "BACKENDS", "BLOCK"]

#: the back ends :func:`lambdify` knows
BACKENDS: tuple[str, ...] = ("numpy", "numba", "c")

#: rows per block in the NumPy back end: 16384 rows of float64 temporaries
#: (128 KiB each) stay in the L2 cache; measured best between 4096 and 65536.
BLOCK: int = 16384

_CACHE: dict[tuple, Callable] = {}
_C_RESERVED = frozenset(C99CodePrinter().reserved_words)
# names the generated code itself uses; user symbols never take them
_RESERVED = frozenset({"numpy", "math", "ctypes"}) | _C_RESERVED


# --------------------------------------------------------------------------
# Input checking for arrays: all of it, and all of its wording, lives here.
# --------------------------------------------------------------------------


class _BlockNumPyPrinter(NumPyPrinter):
    """SymPy's NumPy printer, with ``Piecewise`` as nested ``numpy.where``.

    ``numpy.select`` (what the stock printer writes) costs several
    microseconds per call, which on blocks of :data:`BLOCK` rows doubled the
    time of the pitch; nested ``where`` gives the same values.  Everything
    else is SymPy's printer unchanged.
    """

    def _print_Piecewise(self, expr):  # noqa: N802 - SymPy's printer protocol
        if expr.args[-1].cond != True:  # noqa: E712 - SymPy's true, not Python's
            # as SymPy's printers: no default branch means nan where none holds
            return super()._print_Piecewise(expr)
        text = self._print(expr.args[-1].expr)
        for e, c in reversed(expr.args[:-1]):
            text = f"numpy.where({self._print(c)}, {self._print(e)}, {text})"
        return text


def _describe_trailing(trailing: tuple[int, ...], what: str) -> str:
    dims = ", ".join(str(d) for d in trailing)
    return f"(..., {dims}) for {what}" if trailing else f"(...) for {what}"


def _as_real_array(value: Any, name: str, trailing: tuple[int, ...], what: str) -> np.ndarray:
    """Return ``value`` as a ``float64`` array whose shape ends in ``trailing``.

    Raises ``TypeError`` for complex, boolean, string or other non-real
    input and ``ValueError`` for a wrong trailing shape; each message names
    the argument, says what was expected and what came.

    >>> _as_real_array([1, 2, 3], "A", (3,), "a point").dtype
    dtype('float64')
    >>> _as_real_array(np.zeros((4, 5)), "s", (6,), "a screw (S; S0)")
    Traceback (most recent call last):
    ...
    ValueError: s: expected an array of shape (..., 6) for a screw (S; S0), got shape (4, 5)
    >>> _as_real_array(np.ones(6, complex), "s", (6,), "a screw (S; S0)")
    Traceback (most recent call last):
    ...
    TypeError: s: expected real numbers, got dtype complex128 (screwsym computes in real arithmetic; pass .real if the imaginary part is meant to be dropped)
    """
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
        try:
            arr = arr.astype(np.float64)
        except (TypeError, ValueError) as exc:
            raise TypeError(
                f"{name}: expected an array of real numbers, got {type(value).__name__} "
                f"holding objects that are not real numbers ({exc})"
            ) from None
    elif kind not in "fiu":
        raise TypeError(f"{name}: expected an array of real numbers, got dtype {arr.dtype}")
    nt = len(trailing)
    if arr.ndim < nt or arr.shape[arr.ndim - nt :] != trailing:
        raise ValueError(
            f"{name}: expected an array of shape {_describe_trailing(trailing, what)}, "
            f"got shape {arr.shape}"
        )
    return arr.astype(np.float64, copy=False)


def _prepare(
    specs: Sequence[_Arg], values: Sequence[Any], contiguous: bool = False
) -> tuple[list[np.ndarray], tuple[int, ...], int]:
    """Check every argument and bring it to 2-D ``(n_i, k)``, ``n_i`` = 1 or ``n``.

    Returns the 2-D arrays, the broadcast batch shape and ``n``, its size.
    An argument whose batch shape is the full one, or has one element, is
    reshaped (a view where possible); any other broadcast is materialised.
    """
    arrays = [_as_real_array(v, a.name, a.trailing, a.what) for a, v in zip(specs, values, strict=True)]
    batches = [arr.shape[: arr.ndim - len(a.trailing)] for a, arr in zip(specs, arrays, strict=True)]
    try:
        shape = np.broadcast_shapes(*batches)
    except ValueError:
        listed = ", ".join(f"{a.name} has batch shape {b}" for a, b in zip(specs, batches, strict=True))
        raise ValueError(
            f"{', '.join(a.name for a in specs)}: expected batch (leading) shapes that "
            f"broadcast together, got {listed}"
        ) from None
    n = math.prod(shape)
    out = []
    for a, arr, batch in zip(specs, arrays, batches, strict=True):
        if batch != shape and math.prod(batch) != 1:
            arr = np.broadcast_to(arr, shape + a.trailing)
        arr = arr.reshape(-1, a.size)
        if contiguous and not arr.flags.c_contiguous:
            arr = np.ascontiguousarray(arr)
        out.append(arr)
    return out, shape, n


# --------------------------------------------------------------------------
# Normalising what lambdify is given
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class _Arg:
    """One argument: its parameter name, its symbols and its trailing shape."""

    name: str
    symbols: tuple[Symbol, ...]
    trailing: tuple[int, ...]
    what: str

    @property
    def size(self) -> int:
        return math.prod(self.trailing)


@dataclass(frozen=True)
class _Out:
    """One result: its flat entries and its trailing shape."""

    exprs: tuple[Expr, ...]
    trailing: tuple[int, ...]

    @property
    def size(self) -> int:
        return math.prod(self.trailing)


def _stem(symbols: Sequence[Symbol]) -> str | None:
    """``A`` for ``A_x, A_y, A_z``; None when the names share no such stem."""
    stems = {str(s).rpartition("_")[0] for s in symbols}
    if len(stems) == 1:
        return stems.pop() or None
    return None


def _is_clean(name: str) -> bool:
    return (
        name.isidentifier()
        and name.isascii()
        and not keyword.iskeyword(name)
        and not name.startswith("_")
        and name not in _RESERVED
    )


def _matrix_symbols(m: MatrixBase, where: str) -> tuple[Symbol, ...]:
    entries = tuple(m)
    for e in entries:
        if not isinstance(e, Symbol):
            raise TypeError(f"{where}: expected symbols as entries, got {e!r} ({type(e).__name__})")
    return entries


def _normalise_args(args: Any, names: Sequence[str] | None) -> list[_Arg]:
    from .screw import Screw

    if isinstance(args, (Basic, MatrixBase)):
        args = [args]
    if not isinstance(args, (list, tuple)):
        raise TypeError(
            f"args: expected a list of symbols, vectors and screws, got {type(args).__name__}"
        )
    if names is not None and len(names) != len(args):
        raise ValueError(f"names: expected {len(args)} names, one per argument, got {len(names)}")
    specs: list[_Arg] = []
    used: set[str] = set()
    for i, a in enumerate(args):
        where = f"args[{i}]"
        if isinstance(a, Screw):
            syms = _matrix_symbols(a.as_matrix(), where)
            trailing: tuple[int, ...] = (6,)
            what = f"a {type(a).__name__.lower()} (S; S0)"
            stems = (_stem(syms[:3]), _stem(syms[3:]))
            default = "s" if None in stems else (stems[0] or "s").lower()
        elif isinstance(a, MatrixBase):
            syms = _matrix_symbols(a, where)
            trailing = (len(syms),) if 1 in a.shape else tuple(a.shape)
            what = f"a {len(syms)}-vector" if len(trailing) == 1 else f"a {a.rows}x{a.cols} matrix"
            default = _stem(syms) or "v"
        elif isinstance(a, Symbol):
            syms, trailing, what, default = (a,), (), "a scalar", str(a)
        else:
            raise TypeError(
                f"{where}: expected a Symbol, a matrix of symbols (vector('A')) or a screw "
                f"with symbolic components, got {type(a).__name__} {a!r}"
            )
        name = names[i] if names is not None else default
        if names is not None and not _is_clean(name):
            raise ValueError(f"names[{i}]: expected a Python identifier, got {name!r}")
        if not _is_clean(name) or name in used:
            base = name if _is_clean(name) else "arg"
            name = next(f"{base}{j}" for j in range(len(args) + 1) if f"{base}{j}" not in used)
        used.add(name)
        specs.append(_Arg(name, syms, trailing, what))
    seen: dict[Symbol, str] = {}
    for spec in specs:
        for sym in spec.symbols:
            if sym in seen:
                raise ValueError(
                    f"args: the symbol {sym} appears twice (in {seen[sym]} and {spec.name})"
                )
            seen[sym] = spec.name
    return specs


def _normalise_expr(expr: Any) -> tuple[list[_Out], bool]:
    """Flatten ``expr`` to results; the flag says whether a tuple was given."""
    from .screw import Screw

    is_tuple = isinstance(expr, (tuple, list))
    items = list(expr) if is_tuple else [expr]
    outs = []
    for i, e in enumerate(items):
        where = f"expr[{i}]" if is_tuple else "expr"
        if isinstance(e, Screw):
            outs.append(_Out(tuple(e.as_matrix()), (6,)))
        elif isinstance(e, MatrixBase):
            trailing = (len(e),) if 1 in e.shape else tuple(e.shape)
            outs.append(_Out(tuple(sympify(x, strict=True) for x in e), trailing))
        else:
            try:
                x = sympify(e, strict=True)
            except SympifyError:
                x = None
            if not isinstance(x, Expr):
                raise TypeError(
                    f"{where}: expected a SymPy expression, matrix, screw or a tuple of these, "
                    f"got {type(e).__name__} {e!r}"
                )
            outs.append(_Out((x,), ()))
    for i, out in enumerate(outs):
        for x in out.exprs:
            if not isinstance(x, Expr) or x.has(I):
                raise ValueError(
                    f"expr: expected real expressions (screwsym generates real arithmetic), "
                    f"got {x} in result {i}"
                )
    return outs, is_tuple


# --------------------------------------------------------------------------
# Source generation
# --------------------------------------------------------------------------


def _symbol_names(specs: Sequence[_Arg]) -> dict[Symbol, Symbol]:
    """Replacement of component symbols by clean, distinct identifiers."""
    taken = {spec.name for spec in specs} | {f"{spec.name}_" for spec in specs if not spec.trailing}
    mapping: dict[Symbol, Symbol] = {}
    k = 0
    for spec in specs:
        if not spec.trailing:
            # a scalar argument is its own variable
            mapping[spec.symbols[0]] = Symbol(spec.name, real=True)
            continue
        for sym in spec.symbols:
            name = str(sym)
            if not _is_clean(name) or name in taken:
                while f"_a{k}" in taken:
                    k += 1
                name = f"_a{k}"
            taken.add(name)
            mapping[sym] = Symbol(name, real=True)
    return mapping


@dataclass
class _Plan:
    specs: list[_Arg]
    outs: list[_Out]
    is_tuple: bool
    names: dict[Symbol, Symbol]
    replacements: list[tuple[Symbol, Expr]]
    reduced: list[Expr]
    name: str
    key_hash: str


def _plan(args: Any, expr: Any, use_cse: bool, name: str | None, names: Any) -> _Plan:
    specs = _normalise_args(args, names)
    outs, is_tuple = _normalise_expr(expr)
    allowed = {s for spec in specs for s in spec.symbols}
    free = set().union(*(x.free_symbols for out in outs for x in out.exprs))
    missing = free - allowed
    if missing:
        listed = ", ".join(sorted(str(s) for s in missing))
        raise ValueError(f"expr: the symbols {listed} are not among args")
    mapping = _symbol_names(specs)
    flat = [x.xreplace(mapping) for out in outs for x in out.exprs]
    if use_cse:
        replacements, reduced = cse(flat, symbols=numbered_symbols("_c"))
    else:
        replacements, reduced = [], flat
    key_hash = hashlib.sha1(
        srepr((tuple(tuple(s.symbols) for s in specs), tuple(flat))).encode()
    ).hexdigest()[:10]
    if name is None:
        name = f"lambdified_{key_hash}"
    elif not _is_clean(name):
        raise ValueError(f"name: expected a Python identifier not starting with '_', got {name!r}")
    return _Plan(specs, outs, is_tuple, mapping, replacements, list(reduced), name, key_hash)


def _split(plan: _Plan) -> list[list[Expr]]:
    """The reduced expressions grouped per result."""
    groups, k = [], 0
    for out in plan.outs:
        groups.append(plan.reduced[k : k + len(out.exprs)])
        k += len(out.exprs)
    return groups


def _scalar_path(plan: _Plan, indent: str) -> list[str]:
    """Pure-Python float evaluation for a single point (see the module docstring)."""
    printer = PythonCodePrinter({"fully_qualified_modules": True})
    conds = []
    for spec in plan.specs:
        if spec.trailing:
            conds.append(
                f"_type({spec.name}) is _ndarray and {spec.name}.shape == {spec.trailing!r} "
                f"and {spec.name}.dtype.kind in 'fiu'"
            )
        else:
            conds.append(f"_type({spec.name}) in _SCALAR_TYPES")
    lines = []
    for spec in plan.specs:
        if spec.trailing:
            lines.append(
                f"{indent}if _type({spec.name}) is list or _type({spec.name}) is tuple:\n"
                f"{indent}    {spec.name} = _asarray({spec.name})"
            )
    lines.append(f"{indent}if out is None and {' and '.join(conds) or 'True'}:")
    inner = indent + "    "
    lines.append(f"{inner}try:")
    body = inner + "    "
    for spec in plan.specs:
        if spec.trailing:
            targets = ", ".join(str(plan.names[s]) for s in spec.symbols)
            lines.append(f"{body}{targets}, = {spec.name}.reshape(-1).tolist()")
    for sym, e in plan.replacements:
        lines.append(f"{body}{sym} = {printer.doprint(e)}")
    results = []
    for out, group in zip(plan.outs, _split(plan), strict=True):
        items = [printer.doprint(e) for e in group]
        if not out.trailing:
            results.append(f"_float64({items[0]})")
        elif len(out.trailing) == 1:
            results.append(f"_array(({', '.join(items)},), _float64)")
        else:
            m, n = out.trailing
            rows = ", ".join("(" + ", ".join(items[r * n : (r + 1) * n]) + ",)" for r in range(m))
            results.append(f"_array(({rows},), _float64)")
    ret = ", ".join(results) + ("," if plan.is_tuple and len(results) == 1 else "")
    lines.append(f"{body}return {ret}")
    lines.append(f"{inner}except (ZeroDivisionError, ValueError, OverflowError):")
    lines.append(f"{body}pass  # IEEE 754 inf/nan: let the array code produce it")
    return lines


def _docstring(plan: _Plan, backend: str, doc: str | None) -> str:
    if doc is None:
        params = "\n".join(
            f"    {spec.name} : array of shape {_describe_trailing(spec.trailing, spec.what)}"
            for spec in plan.specs
        )
        doc = (
            f"Generated by screwsym.lambdify (backend {backend!r}).\n\n"
            f"Parameters\n==========\n\n{params}\n"
        )
    return repr(doc)


def _outputs(
    out: Any, trailings: tuple[tuple[int, ...], ...], shape: tuple[int, ...], n: int
) -> list[np.ndarray]:
    """Fresh result arrays, or 2-D views of the caller's ``out`` arrays, checked."""
    if out is None:
        return [np.empty((n, math.prod(t))) if t else np.empty(n) for t in trailings]
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
    return views


def _returns(plan: _Plan) -> str:
    parts = []
    for j, out in enumerate(plan.outs):
        parts.append(f"_out{j}.reshape(_shape + {out.trailing!r})[()]")
    return ", ".join(parts) + ("," if plan.is_tuple and len(parts) == 1 else "")


def _numpy_source(plan: _Plan, doc: str | None) -> str:
    printer = _BlockNumPyPrinter()
    kplan = _scalar_suffixed(plan)
    params = ", ".join(spec.name for spec in plan.specs)
    lines = [f"def {plan.name}({params}, *, out=None):", f"    {_docstring(plan, 'numpy', doc)}"]
    lines += _scalar_path(plan, "    ")
    lines.append(f"    ({params},), _shape, _n = _prepare(_SPECS, ({params},))")
    lines.append(f"    {', '.join(f'_out{j}' for j in range(len(plan.outs)))}, = "
                 "_outputs(out, _OUTS, _shape, _n)")
    lines.append("    with _errstate(divide='ignore', invalid='ignore', over='ignore'):")
    lines.append("        for _i in range(0, _n, _BLOCK):")
    lines.append("            _j = _i + _BLOCK")
    ind = "            "
    for spec in plan.specs:
        block = f"({spec.name} if {spec.name}.shape[0] == 1 else {spec.name}[_i:_j])"
        if not spec.trailing:
            lines.append(f"{ind}{spec.name}_ = {block}[:, 0]")
            continue
        lines.append(f"{ind}_b = {block}")
        for c, sym in enumerate(spec.symbols):
            lines.append(f"{ind}{plan.names[sym]} = _b[:, {c}]")
    for sym, e in kplan.replacements:
        lines.append(f"{ind}{sym} = {printer.doprint(e)}")
    for j, (out, group) in enumerate(zip(kplan.outs, _split(kplan), strict=True)):
        if not out.trailing:
            lines.append(f"{ind}_out{j}[_i:_j] = {printer.doprint(group[0])}")
        else:
            for c, e in enumerate(group):
                lines.append(f"{ind}_out{j}[_i:_j, {c}] = {printer.doprint(e)}")
    lines.append(f"    return {_returns(plan)}")
    return "\n".join(lines) + "\n"


def _kernel_source(plan: _Plan) -> str:
    """A fused loop over ``_n`` rows, for numba (Python syntax, ``math`` functions)."""
    printer = PythonCodePrinter({"fully_qualified_modules": True})
    params = ", ".join(spec.name for spec in plan.specs)
    outs = ", ".join(f"_out{j}" for j in range(len(plan.outs)))
    lines = [f"def {plan.name}_kernel(_n, {params}, {outs}):"]
    for spec in plan.specs:
        lines.append(f"    _d_{spec.name} = 0 if {spec.name}.shape[0] == 1 else 1")
    lines.append("    for _i in range(_n):")
    ind = "        "
    for spec in plan.specs:
        if not spec.trailing:
            lines.append(f"{ind}{spec.name}_ = {spec.name}[_i * _d_{spec.name}, 0]")
            continue
        for c, sym in enumerate(spec.symbols):
            lines.append(f"{ind}{plan.names[sym]} = {spec.name}[_i * _d_{spec.name}, {c}]")
    for sym, e in plan.replacements:
        lines.append(f"{ind}{sym} = {printer.doprint(e)}")
    for j, (out, group) in enumerate(zip(plan.outs, _split(plan), strict=True)):
        if not out.trailing:
            lines.append(f"{ind}_out{j}[_i] = {printer.doprint(group[0])}")
        else:
            for c, e in enumerate(group):
                text = printer.doprint(e)
                lines.append(f"{ind}_out{j}[_i, {c}] = {text}")
    return "\n".join(lines) + "\n"


def _wrapper_source(plan: _Plan, backend: str, doc: str | None) -> str:
    """The Python function that checks input and calls the compiled loop."""
    params = ", ".join(spec.name for spec in plan.specs)
    outs = ", ".join(f"_out{j}" for j in range(len(plan.outs)))
    lines = [f"def {plan.name}({params}, *, out=None):", f"    {_docstring(plan, backend, doc)}"]
    lines += _scalar_path(plan, "    ")
    lines.append(f"    ({params},), _shape, _n = _prepare(_SPECS, ({params},), True)")
    lines.append(f"    {', '.join(f'_out{j}' for j in range(len(plan.outs)))}, = "
                 "_outputs(out, _OUTS, _shape, _n)")
    lines.append(f"    _kernel(_n, {params}, {outs})")
    lines.append(f"    return {_returns(plan)}")
    return "\n".join(lines) + "\n"


def _register(source: str, plan: _Plan, backend: str, namespace: dict) -> dict:
    filename = f"<screwsym-codegen-{backend}-{plan.name}-{plan.key_hash}>"
    linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
    exec(compile(source, filename, "exec"), namespace)  # noqa: S102 - our own generated code
    return namespace


def _base_namespace(plan: _Plan) -> dict:
    return {
        "numpy": np,
        "math": math,
        "_type": type,
        "_ndarray": np.ndarray,
        "_asarray": np.asarray,
        "_array": np.array,
        "_float64": np.float64,
        "_empty": np.empty,
        "_errstate": np.errstate,
        "_prepare": _prepare,
        "_SPECS": tuple(plan.specs),
        "_OUTS": tuple(out.trailing for out in plan.outs),
        "_outputs": _outputs,
        "_BLOCK": BLOCK,
        "_SCALAR_TYPES": (float, int, np.float64),
    }


def _scalar_suffixed(plan: _Plan) -> _Plan:
    """The plan with every scalar parameter's symbol renamed ``name_``.

    The array back ends hold a scalar parameter as a 2-D array and bind its
    value (a column, or one number per row) as ``name_``.
    """
    rename = {
        plan.names[spec.symbols[0]]: Symbol(f"{spec.name}_", real=True)
        for spec in plan.specs
        if not spec.trailing
    }
    if not rename:
        return plan
    return _Plan(
        plan.specs,
        plan.outs,
        plan.is_tuple,
        plan.names,
        [(s, e.xreplace(rename)) for s, e in plan.replacements],
        [e.xreplace(rename) for e in plan.reduced],
        plan.name,
        plan.key_hash,
    )


def _build_numpy(plan: _Plan, doc: str | None) -> Callable:
    source = _numpy_source(plan, doc)
    ns = _register(source, plan, "numpy", _base_namespace(plan))
    return ns[plan.name]


def _build_numba(plan: _Plan, doc: str | None) -> Callable:
    try:
        import numba
    except ImportError:  # pragma: no cover - depends on the environment
        raise ImportError(
            "backend 'numba' needs numba: pip install 'screwsym[fast]' (or use backend='numpy')"
        ) from None
    kplan = _scalar_suffixed(plan)
    source = _kernel_source(kplan) + "\n\n" + _wrapper_source(plan, "numba", doc)
    ns = _base_namespace(plan)
    ns["_kernel"] = None
    _register(source, plan, "numba", ns)
    # one signature in practice: C-contiguous float64 2-D arrays; IEEE division
    ns["_kernel"] = numba.njit(error_model="numpy", cache=False)(ns[f"{plan.name}_kernel"])
    fn = ns[plan.name]
    fn.kernel = ns["_kernel"]
    return fn


# --------------------------------------------------------------------------
# C
# --------------------------------------------------------------------------


def _c_expr(printer: C99CodePrinter, e: Expr) -> str:
    # the C99 printer writes Piecewise over several lines; one line reads better
    return " ".join(printer.doprint(e).split())


def _c_source_from_plan(plan: _Plan) -> str:
    printer = C99CodePrinter()
    point_params, loop_params, call_args = [], ["size_t n"], []
    for spec in plan.specs:
        if spec.trailing:
            point_params.append(f"const double *restrict {spec.name}")
            call_args.append(f"{spec.name} + i * {spec.name}_step")
        else:
            point_params.append(f"double {spec.name}")
            call_args.append(f"{spec.name}[i * {spec.name}_step]")
        loop_params += [f"const double *{spec.name}", f"ptrdiff_t {spec.name}_step"]
    for j, out in enumerate(plan.outs):
        point_params.append(f"double *restrict out{j}")
        loop_params.append(f"double *out{j}")
        call_args.append(f"out{j} + i * {out.size}")
    shapes = "; ".join(
        f"{spec.name}: {spec.size} double{'s' if spec.size > 1 else ''} ({spec.what})"
        for spec in plan.specs
    )
    outs = "; ".join(f"out{j}: {out.size} double{'s' if out.size > 1 else ''}"
                     for j, out in enumerate(plan.outs))
    lines = [
        f"/* Generated by screwsym.codegen.c_source: {plan.name} ({plan.key_hash}).",
        f" * Inputs per point: {shapes}.",
        f" * Outputs per point: {outs}.",
        " * Screws are 6 doubles in the order (S; S0).",
        " * The loop reads row i of each input at ptr + i*step: step is the row length,",
        " * or 0 to broadcast one row to all n. */",
        "#include <math.h>",
        "#include <stddef.h>",
        "",
        f"void {plan.name}_point({', '.join(point_params)})",
        "{",
    ]
    for spec in plan.specs:
        if spec.trailing:
            for c, sym in enumerate(spec.symbols):
                lines.append(f"    const double {plan.names[sym]} = {spec.name}[{c}];")
    for sym, e in plan.replacements:
        lines.append(f"    const double {sym} = {_c_expr(printer, e)};")
    for j, group in enumerate(_split(plan)):
        for c, e in enumerate(group):
            lines.append(f"    out{j}[{c}] = {_c_expr(printer, e)};")
    lines += [
        "}",
        "",
        f"void {plan.name}({', '.join(loop_params)})",
        "{",
        "    for (size_t i = 0; i < n; ++i) {",
        f"        {plan.name}_point({', '.join(call_args)});",
        "    }",
        "}",
        "",
    ]
    return "\n".join(lines)


def c_source(
    args: Any, expr: Any, *, name: str | None = None, cse: bool = True, names: Any = None
) -> str:
    r"""C99 source for ``expr`` as a function of ``args``, via SymPy's C printer.

    Explanation
    ===========

    Two functions are written: ``NAME_point`` evaluates one point (a scalar
    argument is a ``double``, a vector or screw a pointer to its 3 or 6
    doubles, each result a pointer to its doubles), and ``NAME`` loops over
    ``n`` points, reading row ``i`` of each input at ``ptr + i*step``
    (``step`` is the row length, or 0 to broadcast one row).  Screws are in
    the book's order ``(S; S0)``.  Link with ``-lm``.

    Examples
    ========

    >>> from screwsym import Screw, vector, reciprocal_product
    >>> from screwsym.codegen import c_source
    >>> s1, s2 = Screw(vector("S"), vector("S0")), Screw(vector("T"), vector("T0"))
    >>> src = c_source([s1, s2], reciprocal_product(s1, s2), name="recip", names=["s1", "s2"])
    >>> print(src[src.index("void recip_point"):src.index("void recip(")].strip())
    void recip_point(const double *restrict s1, const double *restrict s2, double *restrict out0)
    {
        const double S_x = s1[0];
        const double S_y = s1[1];
        const double S_z = s1[2];
        const double S0_x = s1[3];
        const double S0_y = s1[4];
        const double S0_z = s1[5];
        const double T_x = s2[0];
        const double T_y = s2[1];
        const double T_z = s2[2];
        const double T0_x = s2[3];
        const double T0_y = s2[4];
        const double T0_z = s2[5];
        out0[0] = S0_x*T_x + S0_y*T_y + S0_z*T_z + S_x*T0_x + S_y*T0_y + S_z*T0_z;
    }

    Parameters
    ==========

    args, expr, name, cse, names
        As for :func:`lambdify`.

    See Also
    ========

    lambdify
    """
    return _c_source_from_plan(_plan(args, expr, cse, name, names))


def _compiler() -> str | None:
    for cc in (os.environ.get("CC"), "cc", "gcc", "clang"):
        if cc and shutil.which(cc):
            return cc
    return None


def _build_c(plan: _Plan, doc: str | None) -> Callable:
    cc = _compiler()
    if cc is None:
        raise RuntimeError("backend 'c' needs a C compiler: none of $CC, cc, gcc, clang found")
    source = _c_source_from_plan(plan)
    tmp = tempfile.mkdtemp(prefix="screwsym-c-")
    c_path = os.path.join(tmp, f"{plan.name}.c")
    so_path = os.path.join(tmp, f"{plan.name}.so")
    with open(c_path, "w") as fh:
        fh.write(source)
    cmd = [cc, "-O3", "-std=c99", "-shared", "-fPIC", c_path, "-o", so_path, "-lm"]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"backend 'c': {' '.join(cmd)} failed:\n{done.stderr}")
    lib = ctypes.CDLL(so_path)
    cfunc = getattr(lib, plan.name)
    ptr = ctypes.POINTER(ctypes.c_double)
    argtypes: list = [ctypes.c_size_t]
    for _ in plan.specs:
        argtypes += [ptr, ctypes.c_ssize_t]
    argtypes += [ptr] * len(plan.outs)
    cfunc.argtypes = argtypes
    cfunc.restype = None
    steps = [spec.size for spec in plan.specs]

    def kernel(n: int, *arrays: np.ndarray) -> None:
        ins, outs = arrays[: len(steps)], arrays[len(steps) :]
        call: list = [n]
        for arr, step in zip(ins, steps, strict=True):
            call += [arr.ctypes.data_as(ptr), step if arr.shape[0] != 1 else 0]
        call += [o.ctypes.data_as(ptr) for o in outs]
        cfunc(*call)

    ns = _base_namespace(plan)
    ns["_kernel"] = kernel
    wrapper = _wrapper_source(plan, "c", doc)
    text = wrapper + "\n# C source compiled for this function:\n" + "".join(
        "# " + line + "\n" for line in source.splitlines()
    )
    _register(text, plan, "c", ns)
    fn = ns[plan.name]
    fn.kernel = kernel
    fn.c_library = lib
    fn.c_source = source
    return fn


_BUILDERS = {"numpy": _build_numpy, "numba": _build_numba, "c": _build_c}


def lambdify(
    args: Any,
    expr: Any,
    backend: str = "numpy",
    *,
    cse: bool = True,
    name: str | None = None,
    names: Sequence[str] | None = None,
    doc: str | None = None,
) -> Callable:
    r"""Turn ``expr`` into a vectorised numeric function of ``args``.

    Explanation
    ===========

    ``args`` is a list that may mix SymPy symbols (each becomes a scalar
    array ``(...)``), matrices of symbols such as ``vector('A')`` (``(...,
    3)``) and screws with symbolic components (``(..., 6)``, order
    ``(S; S0)``).  ``expr`` may be a scalar expression, a matrix, a screw
    (returned as ``(..., 6)``) or a tuple of these (a tuple of arrays comes
    back).  Leading dimensions broadcast as in NumPy.  See the module
    docstring for the back ends, the single-point fast path and the behaviour
    where a formula divides by zero.

    Common-subexpression elimination (``sympy.cse``) is on by default.  The
    function is cached per ``(args, expr, backend, cse, name, names)``, named
    ``name`` (default ``lambdified_<hash>``, stable across sessions) and its
    source is visible to ``inspect.getsource``.

    Every generated function also takes ``out=``: an array (a tuple of
    arrays for a tuple result) of the result's full shape, C-contiguous
    ``float64``, to write into instead of allocating; for ``N = 10**6``
    screws a fresh result costs about as much again as the compiled loop
    itself (page faults on new memory).

    Examples
    ========

    >>> import numpy as np
    >>> from screwsym import Twist, vector, lambdify
    >>> t, P = Twist(vector("w"), vector("v")), vector("P")
    >>> vel = lambdify([t, P], t.velocity_at(P), names=["twist", "point"])
    >>> vel(np.array([0.0, 0, 1, 0, 0, 0]), np.array([[1.0, 0, 0], [0, 2, 0]]))
    array([[ 0.,  1.,  0.],
           [-2.,  0.,  0.]])

    Parameters
    ==========

    args : list
        Symbols, matrices of symbols and screws of symbols; every component a
        distinct ``Symbol``.
    expr : Expr, Matrix, Screw or tuple
        What to compute; its free symbols must be among ``args``.
    backend : {"numpy", "numba", "c"}
        ``"numba"`` needs ``pip install 'screwsym[fast]'``; ``"c"`` a C compiler.
    cse : bool
        Common-subexpression elimination (default True).
    name : str, optional
        The generated function's name.
    names : list of str, optional
        Parameter names (default: derived from the symbols, ``s`` for a screw).
    doc : str, optional
        The generated function's docstring.

    See Also
    ========

    c_source, screwsym.numeric
    """
    if backend not in _BUILDERS:
        raise ValueError(f"backend: expected one of {', '.join(map(repr, BACKENDS))}, got {backend!r}")
    names_key = tuple(names) if names is not None else None
    try:
        key = (_freeze(args), _freeze(expr), backend, bool(cse), name, names_key, doc)
        hash(key)
    except TypeError:
        key = None
    if key is not None and key in _CACHE:
        return _CACHE[key]
    plan = _plan(args, expr, cse, name, names)
    fn = _BUILDERS[backend](plan, doc)
    if key is not None:
        _CACHE[key] = fn
    return fn


def _freeze(x: Any) -> Any:
    if isinstance(x, (list, tuple)):
        return tuple(_freeze(i) for i in x)
    if isinstance(x, MatrixBase):
        return ImmutableMatrix(x)
    return x
