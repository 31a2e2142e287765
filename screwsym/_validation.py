"""All input checking of screwsym, and all of its error wording, in one place.

Every public function passes its arguments through one of the ``check_*``
functions below before doing anything else.  Each returns the cleaned value
(a SymPy expression, or a 3x1 ``ImmutableMatrix``) or raises a ``TypeError``
(wrong kind of object) or ``ValueError`` (right kind, wrong value) whose
message names the argument, says what was expected and what came.

Strings are never evaluated: components go through
``sympify(..., strict=True)``, which refuses them.
"""

from __future__ import annotations

from typing import Any

from sympy import Abs, Basic, Expr, Float, ImmutableMatrix, sqrt
from sympy.core.sympify import SympifyError, sympify
from sympy.matrices import MatrixBase

from ._decide import is_zero, is_zero_vector

__all__ = [
    "check_no_strings",
    "check_scalar",
    "check_vector",
    "check_name",
    "check_screw",
    "check_line_parts",
]


def _describe(value: Any) -> str:
    """A short description of ``value`` for error messages."""
    shape = getattr(value, "shape", None)
    if shape is not None and not isinstance(value, Basic) or isinstance(value, MatrixBase):
        return f"{type(value).__name__} of shape {tuple(shape)}"
    text = " ".join(repr(value).split())
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def _shape_of(value: Any) -> tuple[int, ...] | None:
    shape = getattr(value, "shape", None)
    if shape is not None:
        return tuple(shape)
    if isinstance(value, (list, tuple)):
        return (len(value),)
    return None


def check_no_strings(value: Any, name: str) -> None:
    """Raise ``TypeError`` if a string occurs anywhere in ``value``.

    Walks tuples, lists, sets and dicts (keys and values).  Used before
    handing arguments to SymPy methods that would parse a string as code.

    >>> check_no_strings(({1: 2}, [3]), "subs")
    >>> check_no_strings([("x", 1)], "subs")
    Traceback (most recent call last):
    ...
    TypeError: subs: strings are never evaluated, got str 'x'
    """
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, (str, bytes)):
            raise TypeError(f"{name}: strings are never evaluated, got {_describe(item)}")
        if isinstance(item, dict):
            stack.extend(item.keys())
            stack.extend(item.values())
        elif isinstance(item, (list, tuple, set, frozenset)):
            stack.extend(item)


def check_scalar(value: Any, name: str, *, nonzero: bool = False) -> Expr:
    """Return ``value`` as a SymPy expression that may be real.

    Raises ``TypeError`` for strings, booleans, matrices and other non-numbers,
    and ``ValueError`` for values that are provably not real (or provably zero
    when ``nonzero`` is set).

    >>> check_scalar(3, "k")
    3
    >>> check_scalar("3", "k")
    Traceback (most recent call last):
    ...
    TypeError: k: expected a real number or SymPy expression, got str '3' (strings are never evaluated)
    """
    if isinstance(value, str):
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {_describe(value)} "
            "(strings are never evaluated)"
        )
    if (
        isinstance(value, bool)
        or isinstance(value, (MatrixBase, list, tuple))
        or (_shape_of(value) not in (None, ()))
    ):
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {_describe(value)}"
        )
    try:
        expr = sympify(value, strict=True)
    except SympifyError:
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {_describe(value)}"
        ) from None
    if not isinstance(expr, Expr):
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {_describe(value)}"
        )
    if expr.is_extended_real is False:
        raise ValueError(f"{name}: expected a real value, got {expr}")
    if nonzero and is_zero(expr) is True:
        raise ValueError(f"{name}: expected a non-zero value, got {expr}")
    return expr


def check_vector(value: Any, name: str) -> ImmutableMatrix:
    """Return ``value`` as a 3x1 ``ImmutableMatrix`` of real expressions.

    Accepts a list or tuple of three, a 3x1 or 1x3 SymPy matrix, or a NumPy
    array of shape ``(3,)``, ``(3, 1)`` or ``(1, 3)``.

    >>> check_vector([1, 2, 3], "r").T
    Matrix([[1, 2, 3]])
    >>> check_vector([1, 2], "r")
    Traceback (most recent call last):
    ...
    ValueError: r: expected a 3-vector, got shape (2,)
    """
    if (
        isinstance(value, (str, bytes))
        or isinstance(value, Basic)
        and not isinstance(value, MatrixBase)
    ):
        raise TypeError(
            f"{name}: expected a 3-vector (list, tuple or SymPy Matrix), got {_describe(value)}"
        )
    shape = _shape_of(value)
    if shape is None:
        raise TypeError(
            f"{name}: expected a 3-vector (list, tuple or SymPy Matrix), got {_describe(value)}"
        )
    if shape not in ((3,), (3, 1), (1, 3)):
        raise ValueError(f"{name}: expected a 3-vector, got shape {shape}")
    if isinstance(value, MatrixBase):
        items = list(value)
    else:
        try:
            items = [item for item in (value.reshape(3) if hasattr(value, "reshape") else value)]
        except (TypeError, ValueError):
            raise TypeError(f"{name}: expected a 3-vector, got {_describe(value)}") from None
        # a nested list [[1], [2], [3]] has shape (3,) here; unwrap one level
        items = [i[0] if isinstance(i, (list, tuple)) and len(i) == 1 else i for i in items]
    entries = [check_scalar(item, f"{name}[{i}]") for i, item in enumerate(items)]
    return ImmutableMatrix(3, 1, entries)


def check_name(value: Any, name: str) -> str:
    """Return ``value`` if it is a non-empty string usable as a symbol stem."""
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected a str, got {_describe(value)}")
    if not value or not value.strip() or any(c.isspace() or c in ",:" for c in value):
        raise ValueError(
            f"{name}: expected a non-empty name without spaces, commas or colons, got {value!r}"
        )
    return value


def check_screw(value: Any, name: str, cls: type | None = None):
    """Return ``value`` as a screw object (an instance of ``cls``).

    A screw object is passed through, or rebuilt as ``cls`` from its parts
    (so a plain screw may serve as a line vector when its parts make a line,
    but a twist never serves as a wrench, nor a wrench as a twist); a 6-vector (list, tuple, SymPy Matrix or NumPy array of six numbers, in
    the book's order ``(S; S0)``) is converted with ``cls.from_matrix``.
    """
    from .screw import Screw
    from .twist import Twist
    from .wrench import Wrench

    cls = Screw if cls is None else cls
    if isinstance(value, Screw):
        if isinstance(value, cls):
            return value
        # a twist is never read as a wrench, nor a wrench as a twist
        if any(isinstance(value, k) and not issubclass(cls, k) for k in (Twist, Wrench)):
            raise TypeError(f"{name}: expected a {cls.__name__}, got {type(value).__name__}")
        return cls(value.S, value.S0)
    if isinstance(value, (str, bytes)) or _shape_of(value) is None:
        raise TypeError(
            f"{name}: expected a {cls.__name__} or a 6-vector (S; S0), got {_describe(value)}"
        )
    return cls.from_matrix(value, name=name)


def check_six(value: Any, name: str) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    """Split a 6-vector in the book's order into its two 3x1 parts ``(S, S0)``."""
    if isinstance(value, (str, bytes)) or _shape_of(value) is None:
        raise TypeError(
            f"{name}: expected a 6-vector (list, tuple or SymPy Matrix), got {_describe(value)}"
        )
    shape = _shape_of(value)
    if shape not in ((6,), (6, 1), (1, 6)):
        raise ValueError(f"{name}: expected a 6-vector (S; S0), got shape {shape}")
    items = (
        list(value)
        if isinstance(value, MatrixBase)
        else list(value.reshape(6) if hasattr(value, "reshape") else value)
    )
    entries = [check_scalar(item, f"{name}[{i}]") for i, item in enumerate(items)]
    return ImmutableMatrix(3, 1, entries[:3]), ImmutableMatrix(3, 1, entries[3:])


def _float_tolerance(S: ImmutableMatrix, S0: ImmutableMatrix, dot: Expr) -> bool:
    """For floating-point input only: is ``S.S0`` zero up to rounding?

    Floats carry rounding error, so an exact test would reject the line
    through (0.1, 0.2, 0.3) and (0.4, 0.5, 0.7).  The symbolic layer never
    reaches this: it applies only when every quantity is a number and some is a
    Float, and the tolerance is relative to ``|S| |S0|``.
    """
    if not (dot.is_number and dot.has(Float)):
        return False
    scale = sqrt(S.dot(S) * S0.dot(S0))
    return bool(Abs(dot).evalf() <= 1e-12 * max(1.0, float(scale.evalf())))


def check_line_parts(S: ImmutableMatrix, S0: ImmutableMatrix, names=("S", "S0")) -> None:
    """Raise ``ValueError`` unless ``(S; S0)`` may be a line vector.

    A line vector has ``S != 0`` and ``S . S0 = 0`` (1.10).  Only a provable
    violation raises: undecidable symbolic cases are accepted.
    """
    if is_zero_vector(S) is True:
        raise ValueError(
            f"{names[0]}: a line vector needs a non-zero direction {names[0]}, got {list(S)}"
        )
    dot = S.dot(S0)
    if is_zero(dot) is False and not _float_tolerance(S, S0, dot):
        raise ValueError(
            f"{names[0]}, {names[1]}: a line vector needs {names[0]}.{names[1]} = 0 (1.10), "
            f"got {names[0]}.{names[1]} = {dot}"
        )
