r"""From closed forms to numeric functions: :func:`lambdify` and :func:`c_source`.

Explanation
===========

A derivation in screwsym ends in a SymPy expression, matrix or screw.  This
package turns it into a function of NumPy arrays, in one of three back ends,
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

Input is checked in one place (:mod:`screwsym.codegen._runtime`): a wrong
trailing shape, batch shapes that do not broadcast, complex, boolean,
``None`` or non-numeric input raise ``TypeError``/``ValueError`` naming the
argument, what was expected and what came.  Integer and ``float32`` input
is computed in ``float64``.  ``out=`` may be an input: that input is then
read from a copy.

How it works: one plan, thin printers
=====================================

The expression is checked against one list of supported constructs
(arithmetic, ``exp``, ``log``, trigonometric and hyperbolic functions and
their inverses, ``atan2``, ``Abs``, ``sign``, ``floor``, ``ceiling``,
``Mod``, ``Min``, ``Max``, ``Piecewise`` with relational conditions, ``pi``,
``E``, ``oo``, ``nan``); anything else (``Sum``, ``Subs``, ``gamma``,
``zoo``, ...) is refused at ``lambdify`` time with a ``TypeError`` naming
the construct.  The plan renames every symbol to a name screwsym chooses
(``_x0, _x1, ...``), eliminates common subexpressions (``_c0, ...``) and
lists the stores into the results.  Small printers (SymPy's Python, NumPy
and C99 printers with a few overrides) print that plan for each target.  A
user's symbol, argument and function names never appear in generated code:
the parameter names you see are set on the finished function's code object,
and what each parameter is appears only in escaped comments.

One semantics in every back end and in the single-point path (IEEE 754
where a formula divides: ``x/0`` is ``inf`` or ``nan``, never a warning):

* integer literals beyond ``2**53`` are the nearest double;
* a power with a non-integer exponent of a negative number is ``nan``;
* ``Mod(a, b)`` has the sign of ``b`` (Python's ``%``);
* ``Min``, ``Max``, ``sign`` of ``nan`` are ``nan``;
* a ``Piecewise`` with no branch that holds gives ``nan``.

Back ends
=========

``backend=None`` (default)
    ``"numba"`` when numba is installed (``pip install -e ".[fast]"`` from a clone),
    ``"numpy"`` otherwise.
``"numpy"``
    NumPy array expressions after common-subexpression elimination,
    evaluated in blocks of :data:`BLOCK` rows so that the temporaries stay
    in cache.
``"numba"``
    One fused loop per function, compiled by ``numba.njit`` (C-contiguous
    ``float64``, ``error_model='numpy'``).  The generated module is written,
    content-addressed, to the cache directory (:func:`cache_dir`), so that
    numba's on-disk cache serves the next process without compiling.
``"c"``
    The :func:`c_source` of the expression, compiled with the system C
    compiler into a CPython extension module (where Python's and NumPy's C
    headers are found; a plain shared library otherwise) in the cache
    directory (or a temporary directory that is removed); its loop over
    rows is called through ``ctypes``, one point through the module's
    ``METH_FASTCALL`` function.  A new process loads the cached module and
    its Python wrapper in milliseconds, without CSE or printing.

A single point (every argument unbatched and ``float64``: a ``(6,)`` screw,
a ``(3,)`` vector, a Python or NumPy float) takes a fast path in every back
end: in C the compiled point function, called at the cost of one C call
(about pinocchio's Python call for the UR5's kinematics and dynamics,
``benchmarks/bench_one_pose.py``); elsewhere the same plan in plain Python
floats (plans of up to 500 statements; 1000 in NumPy, whose array code pays
per operation), a square root of a negative number NaN there as
in the arrays, and where that path would divide by zero or overflow, the array
code gives the IEEE result instead.

Generated functions are cached in memory per signature (bounded, least
recently used first; one build per signature when threads race), named
``name`` (default ``lambdified_<hash>``), and their source is registered in
:mod:`linecache` so that ``inspect.getsource`` and tracebacks show it.

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
>>> f.__name__, str(inspect.signature(f))
('pitch_of', '(s, *, out=None)')

See Also
========

screwsym.numeric, c_source

References
==========

.. [1] SymPy, ``sympy.utilities.lambdify``, ``sympy.cse`` and the code printers.
.. [2] kingdon (tBuLi/kingdon), ``kingdon/codegen.py``: derive once, generate
   fast code, register the source in ``linecache``, numba as a wrapper.
"""

from __future__ import annotations

import importlib.util
from collections.abc import Callable, Sequence
from typing import Any

from . import _build
from ._build import BLOCK, cache_dir, clear_cache, compiler, load_index, save_index
from ._emit import c_source as _c_source_from_plan
from ._plan import build_plan, code_digest
from ._runtime import describe_trailing

__all__ = [
    "lambdify",
    "c_source",
    "cache_dir",
    "clear_cache",
    "BACKENDS",
    "BLOCK",
    "default_backend",
    "resolve_backend",
    "load_index",
    "save_index",
    "code_digest",
    "compiler",
]

#: the back ends :func:`lambdify` knows
BACKENDS: tuple[str, ...] = ("numpy", "numba", "c")

_HAS_NUMBA: bool | None = None


def default_backend() -> str:
    """``"numba"`` when numba is installed, else ``"numpy"``: the back end ``backend=None`` means.

    >>> default_backend() == ("numba" if importlib.util.find_spec("numba") else "numpy")
    True
    >>> resolve_backend(None) == default_backend()
    True
    """
    global _HAS_NUMBA
    if _HAS_NUMBA is None:
        _HAS_NUMBA = importlib.util.find_spec("numba") is not None
    return "numba" if _HAS_NUMBA else "numpy"


def resolve_backend(backend: Any) -> str:
    """The back end ``backend`` names, checked; None is :func:`default_backend`.

    >>> resolve_backend("numpy")
    'numpy'
    """
    if backend is None:
        return default_backend()
    if not isinstance(backend, str) or backend not in BACKENDS:
        raise ValueError(
            f"backend: expected one of {', '.join(map(repr, BACKENDS))} or None, got {backend!r}"
        )
    return backend


def lambdify(
    args: Any,
    expr: Any,
    backend: str | None = None,
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
    (returned as ``(..., 6)``), a tuple of these (a tuple of arrays comes
    back), or any object with a method ``_lambdify_outputs()`` that returns
    such a tuple.  Leading dimensions broadcast as in NumPy.  See the
    package docstring for the back ends, the supported constructs, the
    single-point path and the behaviour where a formula divides by zero.

    Common-subexpression elimination (``sympy.cse``) is on by default.  The
    function is cached per signature, named ``name`` (default
    ``lambdified_<hash>``, stable across sessions) and its source is visible
    to ``inspect.getsource``.

    Every generated function also takes ``out=``: an array (a tuple of
    arrays for a tuple result) of the result's full shape, C-contiguous
    ``float64``, to write into instead of allocating.  It may be one of the
    inputs.

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
    expr : Expr, Matrix, Screw, tuple, or an object with ``_lambdify_outputs()``
        What to compute; its free symbols must be among ``args``.
    backend : {None, "numpy", "numba", "c"}
        None (default): numba when installed, else NumPy.  ``"numba"`` needs
        ``pip install -e ".[fast]"`` from a clone; ``"c"`` a C compiler.
    cse : bool
        Common-subexpression elimination (default True).
    name : str, optional
        The generated function's name (a Python identifier).
    names : list of str, optional
        Parameter names (default: derived from the symbols, ``s`` for a
        screw); identifiers, distinct, not ``out``.
    doc : str, optional
        The generated function's docstring.

    See Also
    ========

    c_source, screwsym.numeric
    """
    backend = resolve_backend(backend)
    if not isinstance(cse, bool):
        raise TypeError(f"cse: expected True or False, got {type(cse).__name__} {cse!r}")
    if doc is not None and not isinstance(doc, str):
        raise TypeError(f"doc: expected a string, got {type(doc).__name__}")
    plan = build_plan(args, expr, cse, name, names, backend)
    if doc is None:
        params = "\n".join(
            f"    {spec.name} : array of shape {describe_trailing(spec.trailing, spec.what)}"
            for spec in plan.specs
        )
        doc = (
            f"Generated by screwsym.lambdify (backend {backend!r}).\n\n"
            f"Parameters\n==========\n\n{params}\n"
        )
    builder = _build.BUILDERS[backend]
    return _build.cached((plan.key, doc), lambda: builder(plan, cse, doc))


def c_source(
    args: Any, expr: Any, *, name: str | None = None, cse: bool = True, names: Any = None
) -> str:
    r"""C99 source for ``expr`` as a function of ``args``, via SymPy's C printer.

    Explanation
    ===========

    Two functions are exported: ``screwsym_NAME_point`` evaluates one point
    (a scalar argument is a ``double``, a vector or screw a pointer to its 3
    or 6 doubles, each result a pointer to its doubles; its code is the
    ``static inline`` ``screwsym_NAME_eval``, which the loop inlines), and
    ``screwsym_NAME`` loops over ``n`` points, reading row ``i`` of each
    input at ``ptr + i*step`` (``step`` is the row length, or 0 to broadcast
    one row), and returns the number of points whose first result is ``nan``.  Screws are in the book's order ``(S; S0)``.  Link with
    ``-lm``.  Every identifier is screwsym's (``_a0``, ``_x0``, ``_c0``,
    ``_o0``); ``NAME`` is checked to be an identifier and prefixed.  The
    semantics are those of :func:`lambdify` (see the package docstring).

    Examples
    ========

    >>> from screwsym import Screw, vector, reciprocal_product
    >>> from screwsym.codegen import c_source
    >>> s1, s2 = Screw(vector("S"), vector("S0")), Screw(vector("T"), vector("T0"))
    >>> src = c_source([s1, s2], reciprocal_product(s1, s2), name="recip", names=["s1", "s2"])
    >>> start, end = src.index("static inline void screwsym_recip_eval"), src.index("void screwsym_recip_point")
    >>> print(src[start:end].strip())
    static inline void screwsym_recip_eval(const double *restrict _a0, const double *restrict _a1, double *restrict _o0)
    {
        const double _x0 = _a0[0];
        const double _x1 = _a0[1];
        const double _x2 = _a0[2];
        const double _x3 = _a0[3];
        const double _x4 = _a0[4];
        const double _x5 = _a0[5];
        const double _x6 = _a1[0];
        const double _x7 = _a1[1];
        const double _x8 = _a1[2];
        const double _x9 = _a1[3];
        const double _x10 = _a1[4];
        const double _x11 = _a1[5];
        _o0[0] = _x0*_x9 + _x1*_x10 + _x11*_x2 + _x3*_x6 + _x4*_x7 + _x5*_x8;
    }

    Parameters
    ==========

    args, expr, name, cse, names
        As for :func:`lambdify`.

    See Also
    ========

    lambdify
    """
    if not isinstance(cse, bool):
        raise TypeError(f"cse: expected True or False, got {type(cse).__name__} {cse!r}")
    plan = build_plan(args, expr, cse, name, names, "c")
    from ._plan import prepared

    plan = prepared(plan, cse)
    return _c_source_from_plan(plan, f"screwsym_{plan.name}")
