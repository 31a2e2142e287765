r"""Vectorised numeric versions of the chapter's operations.

Explanation
===========

Each function here is *generated* by :func:`screwsym.lambdify` from the
symbolic operation of the core applied to generic symbols, for instance
``pitch(Screw(vector('S'), vector('S0')))``, on first use.
The numeric and the symbolic results therefore cannot drift apart: change
the formula in :mod:`screwsym.core.screw` and the numbers follow.  Each is
defined once in this module, by a function decorated with
:func:`numeric_definition` that returns the generic arguments and the core's
operation on them, and whose docstring is the generated function's;
:data:`NAMES` lists them in the order they are defined.

Array convention: a screw is an array of shape ``(..., 6)`` in the book's
order ``(S; S0)`` (a twist ``(omega; v_O)``, a wrench ``(f; C_O)``), a point
or vector ``(..., 3)``, a scalar ``(...)``; leading dimensions broadcast as in
NumPy; a screw result comes back ``(..., 6)``.  Wrong trailing shapes,
batch shapes that do not broadcast and complex input raise ``TypeError`` or
``ValueError`` naming the argument (see :mod:`screwsym.codegen`).

Where a formula divides by ``S . S`` the result follows the symbolic
function where it has a value and IEEE 754 otherwise, and it never warns:
the pitch of a couple ``(0; C)`` is ``inf`` (the symbolic
:func:`screwsym.pitch` gives ``oo``), of the zero screw ``nan`` (the
symbolic one raises); the foot point of a couple, whose axis lies at
infinity, is ``nan`` (the symbolic one raises).

The functions here use the numba back end once numba is imported in the
process (``pip install -e ".[fast]"`` from a clone, then ``import numba``),
else the C back end where a C compiler is found, else NumPy
(:func:`default_backend`), so that a new process's first call pays no numba
import; each is generated on first use and kept in the disk cache (see
:func:`screwsym.codegen.cache_dir`), from which a new process reads it back
without SymPy work (and numba's cache spares it the compilation, the C
library is loaded as it is).  :func:`functions_for` gives the same set
for a chosen back end, e.g. ``functions_for("numpy")`` or ``functions_for("c")``.

With the C back end a batch of C-contiguous ``float64`` arrays goes to the
compiled loop directly, and a large result (1 to 64 MB) that the caller has let
go is handed out again by the next call of the same function, instead of fresh
memory that the system must zero first (:mod:`screwsym.numeric._direct`): a
result still referenced in any way (a name, a view, a list) is never reused, and
at most one such array per function stays held after its last use
(:func:`screwsym.numeric.recycle_results` turns this off).

Examples
========

>>> import numpy as np
>>> from screwsym import numeric
>>> numeric.pitch(np.array([1.0, 1.0, 0.0, 1.0, 0.0, 0.0]))        # Example 1.4
np.float64(0.5)
>>> screws = np.array([[1.0, 0, 0, 2, 0, 0], [0, 0, 0, 0, 0, 5]])
>>> numeric.pitch(screws)                                  # a screw and a couple
array([ 2., inf])
>>> numeric.line_through(np.zeros(3), np.array([[1.0, 0, 0], [0, 0, 2]]))
array([[1., 0., 0., 0., 0., 0.],
       [0., 0., 2., 0., 0., 0.]])

See Also
========

screwsym.codegen.lambdify
"""

from __future__ import annotations

import math
import re
import sys
import threading
import types
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from sympy import And, Eq, Integer, Ne, Or, Piecewise, Rational, cancel, nan, zeros

from ..codegen import code_digest, compiler, lambdify, load_index, resolve_backend, save_index
from ..core import screw as _core
from ..core.line import LineVector
from ..core.screw import Screw
from ..core.twist import Twist
from ..core.vectors import vector
from ..core.wrench import Wrench
from ._direct import direct, entry

#: what a definition returns: its generic arguments by parameter name, in order, and the
#: core's operation applied to them
_Made = tuple[dict[str, Any], Any]


@dataclass(frozen=True)
class Definition:
    """One generated function of this module: its name, its docstring and how to make it.

    ``make()`` returns ``(params, expr)``: the generic symbolic arguments
    (a screw of symbols, a vector of symbols) by the generated function's
    parameter names, in order, and the core's operation applied to them.
    """

    name: str
    doc: str
    make: Callable[[], _Made]

    def build(self) -> tuple[list, Any, list[str]]:
        """``(args, expr, parameter names)``, as :func:`screwsym.codegen.lambdify` takes them."""
        params, expr = self.make()
        return list(params.values()), expr, list(params)


class Definitions(Mapping[str, Definition]):
    """The registry of the generated functions: name -> :class:`Definition`, in the order defined.

    :meth:`register` is the decorator of one definition; this module's
    registry is :data:`DEFINITIONS` (its decorator :func:`numeric_definition`),
    closed once the module's definitions are in, so that :data:`NAMES` lists
    all of them.

    >>> from sympy import Symbol
    >>> registry = Definitions()
    >>> @registry.register
    ... def _half():
    ...     "Half of ``x``."
    ...     x = Symbol("x", real=True)
    ...     return {"x": x}, x / 2
    >>> list(registry), registry["half"].build()
    (['half'], ([x], x/2, ['x']))
    >>> @registry.register
    ... def _half():
    ...     "Half again."
    Traceback (most recent call last):
    ...
    ValueError: _half: a function 'half' is defined already
    """

    def __init__(self) -> None:
        self._by_name: dict[str, Definition] = {}
        self._closed = False

    def register(self, make: Callable[[], _Made]) -> Definition:
        """Register ``make`` as the function named as ``make`` without its leading underscore.

        ``def _pitch(): ...`` defines ``pitch``: the underscore leaves the
        module attribute ``pitch`` to the generated function, made on first
        use.  The docstring of ``make`` is the generated function's.  A name
        defined twice, a name not of that form, a missing docstring or a
        closed registry raise ``ValueError``.
        """
        where = getattr(make, "__name__", repr(make))
        if self._closed:
            raise ValueError(f"{where}: the registry is closed (the module's definitions are in)")
        if not re.fullmatch(r"_[A-Za-z]\w*", where):
            raise ValueError(f"{where}: expected the name '_' + the generated function's name")
        name = where[1:]
        if name in self._by_name:
            raise ValueError(f"{where}: a function {name!r} is defined already")
        doc = getattr(make, "__doc__", None)
        if not isinstance(doc, str) or not doc.strip():
            raise ValueError(f"{where}: expected a docstring (the generated function's)")
        definition = Definition(name, doc, make)
        self._by_name[name] = definition
        return definition

    def close(self) -> None:
        """Refuse further definitions."""
        self._closed = True

    def __getitem__(self, name: str) -> Definition:
        return self._by_name[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._by_name)

    def __len__(self) -> int:
        return len(self._by_name)


#: the range of ``S . S`` and ``S0 . S0`` in which the formulas of degree 2 (1.16, 1.34)
#: neither underflow nor overflow: every part then has size in ``[2^-480, 2^480]``, so that
#: each product of two components is a normal double (or a harmless subnormal beside a
#: normal term) and no sum of three overflows
_LOW, _HIGH = Rational(1, 2**960), Integer(2**960)


def _is_zero(v: Any) -> Any:
    """Each component of ``v`` is zero (exactly: not its square sum, which can underflow)."""
    return And(*(Eq(x, 0) for x in v))


def _in_range(s: Screw) -> tuple[Any, Any]:
    """Where the plain formula of a pitch or foot point is accurate in floats: two cases.

    ``S . S`` within ``[_LOW, _HIGH]`` and ``S0 . S0`` too (the common case,
    four comparisons), or ``S . S`` within it and ``S0`` zero (a line through
    the origin).  Outside both (a screw scaled by ``1e-200`` or ``1e200``, a
    couple, a part not finite) the generated kernel gives ``nan`` and
    :func:`_wrapped` recomputes those elements, and only those, on the
    parts scaled to size 1.  One branch per element: no pass over the array.
    The cases are separate branches of the ``Piecewise`` (not one ``|``), so
    that the test of ``S0`` for zero is made only where ``S0 . S0`` is out of
    range, not for every screw.
    """
    SS, S0S0 = s.S.dot(s.S), s.S0.dot(s.S0)
    good = (SS >= _LOW) & (SS <= _HIGH)
    return good & (S0S0 >= _LOW) & (S0S0 <= _HIGH), good & _is_zero(s.S0)


def _is_couple(s: Screw) -> Any:
    """``S`` zero and ``S0`` not (written with ``Ne``: no test shared with :func:`_in_range`'s)."""
    return _is_zero(s.S) & Or(*(Ne(x, 0) for x in s.S0))


#: the generated functions' definitions, in the order of :data:`NAMES`
DEFINITIONS = Definitions()
numeric_definition = DEFINITIONS.register


@numeric_definition
def _pitch() -> _Made:
    r"""The pitch ``h = S . S0 / S . S`` (1.34) of screws ``(..., 6)``; returns ``(...)``.

    Generated from :func:`screwsym.pitch`.  A couple ``(0; C)`` gives
    ``inf`` (symbolically ``oo``), the zero screw ``nan`` (symbolically an
    error).

    Examples
    ========

    >>> import numpy as np
    >>> from screwsym.numeric import pitch
    >>> pitch(np.array([[1.0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 0, 1], [0, 0, 0, 0, 0, 0]]))
    array([ 1., inf, nan])
    """
    s = Screw(vector("S"), vector("S0"))
    # The first two branches are the book's formula where the parts are in range (the common
    # case first: four comparisons per screw); the third says what the symbolic pitch gives
    # for a couple (oo); the zero screw has none (nan here, an error there), and out of range
    # the nan is recomputed scaled by the wrapper (see _in_range, which implies S != 0).
    common, through_origin = _in_range(s)
    return {"s": s}, Piecewise(
        (_core.pitch(s), common),
        (_core.pitch(Screw(s.S, zeros(3, 1))), through_origin),  # 0: S0 is zero there
        (_core.pitch(Screw.couple(s.S0)), _is_couple(s)),
        (nan, True),
    )


@numeric_definition
def _foot() -> _Made:
    r"""The axis point nearest the origin, ``P = S x S0 / S . S`` (1.16): ``(..., 6)`` -> ``(..., 3)``.

    Generated from :func:`screwsym.foot`.  A couple has no axis in finite
    space: its foot point is ``nan`` (symbolically an error).

    Examples
    ========

    >>> import numpy as np
    >>> from screwsym.numeric import foot
    >>> foot(np.array([1.0, 1, 0, 1, 0, 0]))               # Example 1.4
    array([ 0. ,  0. , -0.5])
    """
    s = Screw(vector("S"), vector("S0"))
    # (1.16) as S x S0 times one factor 1/S.S, which carries the guard: one Piecewise per
    # screw (not one per component, each testing S0 for zero); the factor is 0 where S0 is
    # zero (the foot is the origin there) and nan out of range, recomputed by the wrapper
    SS = s.S.dot(s.S)
    cross = _core.foot(s).applyfunc(lambda e: cancel(e * SS))  # S x S0, from the core's (1.16)
    common, through_origin = _in_range(s)
    return {"s": s}, cross * Piecewise((1 / SS, common), (0, through_origin), (nan, True))


@numeric_definition
def _reciprocal_product() -> _Made:
    r"""The reciprocal product ``S1 . S2^0 + S2 . S1^0`` (1.45) of two screw arrays.

    Generated from :func:`screwsym.reciprocal_product`; ``(..., 6)`` and
    ``(..., 6)`` (batch shapes broadcast) -> ``(...)``.

    Examples
    ========

    >>> import numpy as np
    >>> from screwsym.numeric import reciprocal_product
    >>> reciprocal_product(np.array([1.0, 0, 0, 0, 0, 0]), np.array([0.0, 1, 0, 0, 0, 1]))
    np.float64(0.0)
    """
    s1, s2 = Screw(vector("S"), vector("S0")), Screw(vector("T"), vector("T0"))
    return {"s1": s1, "s2": s2}, _core.reciprocal_product(s1, s2)


@numeric_definition
def _shift_origin() -> _Made:
    r"""The screw with its dual part taken about ``A``: ``(S; S0 - A x S)`` (1.32).

    Generated from :func:`screwsym.shift_origin`; screws ``(..., 6)`` and
    points ``(..., 3)`` -> ``(..., 6)``.

    Examples
    ========

    >>> import numpy as np
    >>> from screwsym.numeric import shift_origin
    >>> shift_origin(np.array([1.0, 0, 0, 2, 0, -1]), np.array([0.0, 1, 0]))
    array([1., 0., 0., 2., 0., 0.])
    """
    s, A = Screw(vector("S"), vector("S0")), vector("A")
    return {"s": s, "A": A}, _core.shift_origin(s, A)


@numeric_definition
def _line_through() -> _Made:
    r"""The line through ``A`` and ``B``, ``(B - A; A x (B - A))`` (1.1, 1.9).

    Generated from :meth:`screwsym.LineVector.through`; points ``(..., 3)``
    -> line vectors ``(..., 6)``.  ``A = B`` gives the zero screw (the
    symbolic constructor raises).

    Examples
    ========

    >>> import numpy as np
    >>> from screwsym.numeric import line_through
    >>> line_through(np.array([1.0, 0, 0]), np.array([1.0, 1, 0]))
    array([0., 1., 0., 0., 0., 1.])
    """
    A, B = vector("A"), vector("B")
    return {"A": A, "B": B}, LineVector.through(A, B)


@numeric_definition
def _velocity_at() -> _Made:
    r"""The velocity ``v_P = v_O + omega x P`` of the body point at ``point``.

    Generated from :meth:`screwsym.Twist.velocity_at`; twists ``(omega;
    v_O)`` ``(..., 6)`` and points ``(..., 3)`` -> ``(..., 3)``.

    Examples
    ========

    >>> import numpy as np
    >>> from screwsym.numeric import velocity_at
    >>> velocity_at(np.array([0.0, 0, 1, 0, 0, 0]), np.array([1.0, 0, 0]))
    array([0., 1., 0.])
    """
    t, P = Twist(vector("omega"), vector("v")), vector("P")
    return {"twist": t, "point": P}, t.velocity_at(P)


@numeric_definition
def _moment_about() -> _Made:
    r"""The moment ``C_A = C_O - A x f`` of a wrench about ``point`` (1.32).

    Generated from :meth:`screwsym.Wrench.moment_about`; wrenches ``(f;
    C_O)`` ``(..., 6)`` and points ``(..., 3)`` -> ``(..., 3)``.

    Examples
    ========

    >>> import numpy as np
    >>> from screwsym.numeric import moment_about
    >>> moment_about(np.array([0.0, 0, -10, 0, 10, 0]), np.array([1.0, 0, 0]))
    array([0., 0., 0.])
    """
    w, P = Wrench(vector("f"), vector("C")), vector("P")
    return {"wrench": w, "point": P}, w.moment_about(P)


DEFINITIONS.close()

#: the names of the generated functions, in a fixed order: that of their definitions above
NAMES: tuple[str, ...] = tuple(DEFINITIONS)

# the generated functions are module attributes made on first use (__getattr__ below)
__all__ = [*NAMES, "functions_for", "NAMES"]

_BUILT: dict[tuple[str, str], Callable] = {}
_LOCK = threading.Lock()


#: the functions of degree 0 in each part of the screw: ``f(a S; b S0) = (b/a) f(S; S0)``
#: for a pitch (1.34) and a foot point (1.16); evaluated on the parts scaled to size 1
#: they neither underflow nor overflow where the result itself does not (issue 20)
SCALE_FREE: tuple[str, ...] = ("pitch", "foot")


def _rescaled(fn: Callable, a: np.ndarray, name: str) -> Any:
    """``fn`` evaluated on ``(S/2^e; S0/2^e0)``, its result scaled back by ``2^(e0 - e)``.

    ``2^e`` is the power of two at or above the largest ``|S_i|`` (likewise
    ``2^e0`` for ``S0``): dividing by it is exact, and the scaled parts have
    size 1, so that ``S . S`` cannot underflow (``nan`` for a screw scaled by
    ``1e-200``) nor overflow (``nan`` at ``1e200``).  A part that is zero or
    not finite is left as it is.
    """
    with np.errstate(all="ignore"):
        m, m0 = np.abs(a[..., :3]).max(axis=-1), np.abs(a[..., 3:]).max(axis=-1)
        e = np.where((m > 0) & np.isfinite(m), np.frexp(m)[1], 0)
        e0 = np.where((m0 > 0) & np.isfinite(m0), np.frexp(m0)[1], 0)
        x = np.concatenate([np.ldexp(a[..., :3], -e[..., None]),
                            np.ldexp(a[..., 3:], -e0[..., None])], axis=-1)
    shift = e0 - e if name == "pitch" else (e0 - e)[..., None]
    with np.errstate(over="ignore"):  # a result beyond the floats is inf, as unscaled
        return np.ldexp(fn(x), shift)


def _wrapped(fn: Callable, name: str) -> Callable:
    """``fn`` with the direct call of its C loop on plain batches, and scale-free where it must be.

    For a C function, a plain batch (see :mod:`screwsym.numeric._direct`) runs
    the loop directly, into a recycled result where the last one was let go;
    anything else takes the generated function's own path.  For the pitch and
    the foot point (:data:`SCALE_FREE`) the kernel's guard (:func:`_in_range`,
    one branch per element) leaves ``nan`` where ``S . S`` or ``S0 . S0`` is out
    of range; only those elements (``nan`` results: also the zero screw, a
    couple's foot point and non-finite input, which come back the same) are
    computed again by :func:`_rescaled`.  The C loop counts the rows it left
    ``nan``, so the direct path looks at the result again only where that count
    is not zero; the other paths take one ``isnan`` pass over the result.
    Input that is not a float or integer array ending in 6 is answered by
    ``fn`` (its own checks).  Returns ``fn`` itself where there is nothing to add
    (no C loop, not scale-free).
    """
    call = direct(fn)
    scale_free = name in SCALE_FREE
    if call is None and not scale_free:
        return fn
    pitch, float64, isnan = name == "pitch", np.float64, math.isnan

    def redo(s: Any, r: Any, first: Any) -> None:
        """Recompute the rows of ``r`` (``first``: its first number per screw) that are nan."""
        where = np.nonzero(np.isnan(first))
        a = np.broadcast_to(np.asarray(s, dtype=np.float64), first.shape + (6,))
        r[where] = _rescaled(fn, a[where], name)

    def one(s: Any, result: Any, out: Any = None) -> Any:
        """``result`` of one screw ``s``, recomputed scaled where it is nan."""
        if not isnan(result if pitch else result[0]):  # the common case (math.isnan: 40 ns)
            return result
        again = _rescaled(fn, np.asarray(s, dtype=np.float64), name)
        if out is None:
            return again
        out[...] = again
        return result if isinstance(result, np.ndarray) else out[()]  # a 0-d out

    def rest(args: tuple, out: Any) -> Any:
        """Everything but one screw: the direct call of the C loop, else the generated path."""
        if call is not None:
            done = call(args, out)
            if done is not None:
                r, count = done
                if count and scale_free:
                    redo(args[0], r, r if pitch else r[..., 0])
                return r
        result = fn(*args, out=out)
        if not scale_free:
            return result
        r = result if out is None else out
        # one number per screw (a float for one screw: r[..., 0] would be a 0-d array)
        first = r if pitch else r[0] if r.ndim == 1 else r[..., 0]
        if type(first) is float64 or first.ndim == 0:  # one screw (np.ndim: 2 us a call)
            return one(args[0], result, out)
        # numpy.minimum propagates nan: one read of the result, no array of flags made
        # (isnan(first).any() wrote one), and the flags only where a nan is
        if r.size == 0 or not isnan(np.minimum.reduce(r, axis=None)):  # r: contiguous, often
            return result
        redo(args[0], r, first)
        return result

    # one screw: the C extension's point function first, as in the generated function
    wrapper = entry(fn, rest, one if scale_free else None)
    wrapper.__name__ = wrapper.__qualname__ = fn.__name__
    wrapper.__module__ = __name__  # pickled by reference: screws.<name> (see __getattr__)
    wrapper.__doc__ = fn.__doc__
    wrapper.__wrapped__ = fn  # type: ignore[attr-defined]
    wrapper.__dict__.update({k: v for k, v in vars(fn).items() if k != "__wrapped__"})
    return wrapper


def default_backend() -> str:
    """The back end of this module's functions: numba once imported, else C where a compiler is, else NumPy.

    Compiled loops run at memory speed (the NumPy back end, a dozen array
    expressions per block, does not).  numba only once the user has imported
    it, so that a new process's first call pays no numba import (0.5 s quiet,
    seconds under load); otherwise the C back end where a C compiler is found
    (each library compiled once, about 0.2 s, then loaded from the disk cache
    in milliseconds, see :func:`screwsym.codegen.cache_dir`); NumPy on a
    machine with neither.  :func:`functions_for` chooses another.

    >>> default_backend() in ("numba", "c", "numpy")
    True
    """
    if "numba" in sys.modules and resolve_backend(None) == "numba":
        return "numba"
    return "c" if compiler() is not None else "numpy"


def _function(name: str, backend: str | None = None) -> Callable:
    backend = default_backend() if backend is None else resolve_backend(backend)
    key = (name, backend)
    fn = _BUILT.get(key)
    if fn is None:
        with _LOCK:
            fn = _BUILT.get(key)
            if fn is None:  # (another thread may have made it meanwhile)
                definition = DEFINITIONS[name]
                tag = f"{name}-{code_digest()}"
                fn = load_index(tag, definition.doc, backend)
                if fn is None:
                    args, expr, names = definition.build()
                    fn = lambdify(args, expr, backend, name=name, names=names,
                                  doc=definition.doc)
                    save_index(tag, fn)
                fn = _BUILT[key] = _wrapped(fn, name)
    return fn


def functions_for(backend: str | None = None) -> types.SimpleNamespace:
    """The generated functions for ``backend``, as attributes named as in :data:`NAMES`.

    ``backend=None`` (default) is :func:`default_backend`, as for the
    module's own functions.  Built on first use and cached;
    ``functions_for().pitch is pitch``.

    Examples
    ========

    >>> from screwsym import numeric
    >>> numeric.functions_for().pitch is numeric.pitch
    True
    >>> sorted(vars(numeric.functions_for("numpy")))[:3]
    ['foot', 'line_through', 'moment_about']
    """
    return types.SimpleNamespace(**{name: _function(name, backend) for name in NAMES})


def __getattr__(name: str) -> Callable:
    # PEP 562: the module's functions are generated on first use
    if name in NAMES:
        return _function(name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(NAMES))


# The generated functions live in their own namespaces, so doctest would not
# find their examples among this module's members; list them here.
__test__ = {name: DEFINITIONS[name].doc for name in NAMES}
