"""The home of the functions :func:`screwsym.lambdify` generates: what lets them be pickled.

A generated function is named, for :mod:`pickle`, by its module (this one) and
a qualified name ``k<key>_<backend>_<doc digest>.<name>``, where ``key`` is the
content hash of its generated code.  Pickling stores that reference, not code.
Unpickling looks the name up here: a function alive in the process is found
as it is; otherwise it is read back from the disk cache
(:func:`screwsym.codegen.cache_dir`), from the generated module or library
and the description saved beside it when it was built, without SymPy work.
Where neither holds it (another machine, no usable disk cache, the file
pruned), unpickling raises :class:`pickle.UnpicklingError` saying how to
rebuild it: call ``lambdify`` with the same arguments in that process.

Examples
========

>>> import pickle
>>> import numpy as np
>>> from sympy import symbols
>>> from screwsym import lambdify
>>> x = symbols("x", real=True)
>>> f = lambdify([x], x**2 + 1, "numpy", name="square_plus_one")
>>> g = pickle.loads(pickle.dumps(f))
>>> g is f, g(np.array([1.0, 2.0]))
(True, array([2., 5.]))
"""

from __future__ import annotations

import pickle
import re
import types
import weakref
from typing import Any

__all__ = ["register"]

#: what reads a function back from the disk cache (set by screwsym.codegen._build, which
#: the package imports before this module: no import cycle)
LOADER: Any = None

#: the generated functions alive in this process, by the first part of their qualified name
_LIVE: weakref.WeakValueDictionary[str, Any] = weakref.WeakValueDictionary()

#: the first part of a generated function's qualified name: its code's key, back end, doc
_REFERENCE = re.compile(r"k([0-9a-f]{24})_(numpy|numba|c)_([0-9a-f]{12})")


def register(fn: Any, reference: str) -> None:
    """Make ``fn`` (named ``fn.__name__``) the function ``reference`` of this module."""
    fn.__module__ = __name__
    fn.__qualname__ = f"{reference}.{fn.__name__}"
    _LIVE[reference] = fn


def __getattr__(reference: str) -> types.SimpleNamespace:
    # PEP 562: pickle asks for ``reference``, then for the function's name in it
    match = _REFERENCE.fullmatch(reference)
    if match is None:
        raise AttributeError(f"module {__name__!r} has no attribute {reference!r}")
    fn = _LIVE.get(reference)
    if fn is None and LOADER is not None:
        fn = LOADER(reference, match.group(2))
    if fn is None:  # not AttributeError: pickle would replace this message by its own
        raise pickle.UnpicklingError(
            f"{__name__}: the function {reference} made by screwsym.lambdify is neither in "
            "this process nor in its disk cache (screwsym.codegen.cache_dir()): call "
            "screwsym.lambdify with the same arguments here to rebuild it (pickle the "
            "symbolic arguments and expression rather than the function)"
        )
    return types.SimpleNamespace(**{fn.__name__: fn})
