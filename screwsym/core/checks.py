"""The wording of screwsym's input checks, and the generic checks.

Every public function passes its arguments through ``check_*`` functions
before doing anything else: the generic ones below (numbers, vectors,
matrices, names, choices, ...), and the invariants, which live beside their
concepts: :func:`screwsym.core.screw.check_screw` (a screw of a kind),
:func:`screwsym.core.line.check_line_parts` (the line condition
``S . S0 = 0``), :func:`screwsym.motion.transform.check_rotation` and
:func:`screwsym.systems.screw_system.check_screw_system_members` (the kinds
a screw system holds).  Each returns the cleaned value
(a SymPy expression, or a 3x1 ``ImmutableMatrix``) or raises a ``TypeError``
(wrong kind of object) or ``ValueError`` (right kind, wrong value) whose
message names the argument, says what was expected and what came.

Strings are never evaluated: components go through
``sympify(..., strict=True)``, which refuses them.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

from sympy import Basic, Expr, Float, ImmutableMatrix, S
from sympy.core.sympify import SympifyError, sympify
from sympy.matrices import MatrixBase

from .decide import is_real_where_defined, is_zero, is_zero_vector

__all__ = [
    "check_no_strings",
    "check_nonzero_vector",
    "check_scalar",
    "check_vector",
    "check_name",
]


def _np_types(*names: str) -> tuple[type, ...]:
    """NumPy's types ``numpy.<name>`` (dotted for ``ma.MaskedArray``), or ``()``.

    NumPy is not imported here: a value can be a NumPy object only when NumPy
    is loaded already, so while it is not, no value is one.
    """
    np = sys.modules.get("numpy")
    if np is None:
        return ()
    out = []
    for name in names:
        obj: Any = np
        for part in name.split("."):
            obj = getattr(obj, part)
        out.append(obj)
    return tuple(out)


def describe(value: Any) -> str:
    """A short description of ``value`` for error messages."""
    shape: Any = getattr(value, "shape", None)
    if shape is not None and not isinstance(value, Basic) or isinstance(value, MatrixBase):
        return f"{type(value).__name__} of shape {tuple(shape)}"
    text = " ".join(repr(value).split())
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def shape_of(value: Any) -> tuple[int, ...] | None:
    """The shape of an array or matrix, ``(n,)`` for a list or tuple, else ``None``."""
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
    found = find_string(value)
    if found is not None:
        raise TypeError(f"{name}: strings are never evaluated, got {describe(found)}")


def find_string(value: Any) -> Any:
    """The first string (or bytes) found anywhere in ``value``, or ``None``.

    Walks tuples, lists, sets, dicts (keys and values) and NumPy arrays (a
    string array, or the items of an object array): SymPy's ``sympify``, even
    with ``strict=True``, parses the strings inside a tuple, dict or set.

    >>> find_string([1, {2: ("x",)}])
    'x'
    >>> find_string([1, (2.0,)]) is None
    True
    """
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, (str, bytes, *_np_types("str_", "bytes_"))):
            return item
        if isinstance(item, dict):
            stack.extend(item.keys())
            stack.extend(item.values())
        elif isinstance(item, (list, tuple, set, frozenset)):
            stack.extend(item)
        elif isinstance(item, _np_types("ndarray")):
            array: Any = item
            if array.dtype.kind in "USO":
                stack.extend(array.ravel().tolist())
    return None


def refusing_strings(f: Callable[[Any], Any], name: str) -> Callable[[Any], Any]:
    """``f``, raising ``TypeError`` when it returns a string (anywhere in its result).

    For functions whose results SymPy sympifies without ``strict=True`` (a
    matrix's ``applyfunc`` parses a string result as code).

    >>> refusing_strings(lambda e: "x", "applyfunc")(1)
    Traceback (most recent call last):
    ...
    TypeError: applyfunc: strings are never evaluated, got str 'x'
    """

    def checked(value: Any) -> Any:
        result = f(value)
        check_no_strings(result, name)
        return result

    return checked


def _refuse_non_number(value: Any, name: str) -> None:
    if find_string(value) is not None:
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {describe(value)} "
            "(strings are never evaluated)"
        )
    if (
        isinstance(value, (bool, *_np_types("bool_")))
        or value is None
        or isinstance(value, (MatrixBase, list, tuple, dict, set, frozenset, *_np_types("ma.MaskedArray")))
        or (shape_of(value) not in (None, ()))
    ):
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {describe(value)}"
        )


def check_scalar(value: Any, name: str, *, nonzero: bool = False) -> Expr:
    """Return ``value`` as a finite, real SymPy expression.

    Raises ``TypeError`` for strings, booleans, ``None``, matrices, masked
    values and other non-numbers, and ``ValueError`` for NaN, infinities and
    ``zoo``, for values that are not real (provably complex, or not known to
    be real: a symbol needs ``real=True``), and for values provably zero when
    ``nonzero`` is set.

    >>> check_scalar(3, "k")
    3
    >>> check_scalar("3", "k")
    Traceback (most recent call last):
    ...
    TypeError: k: expected a real number or SymPy expression, got str '3' (strings are never evaluated)
    >>> from sympy import Symbol
    >>> check_scalar(Symbol("z"), "k")
    Traceback (most recent call last):
    ...
    ValueError: k: expected a real value, got z, which is not known to be real (declare symbols with real=True; a root needs a non-negative base)
    """
    _refuse_non_number(value, name)
    try:
        expr = sympify(value, strict=True)
    except SympifyError:
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {describe(value)}"
        ) from None
    if not isinstance(expr, Expr) or isinstance(expr, MatrixBase):
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {describe(value)}"
        )
    if expr.has(S.NaN, S.Infinity, S.NegativeInfinity, S.ComplexInfinity):
        raise ValueError(f"{name}: expected a finite real value, got {expr}")
    real = is_real_where_defined(expr)
    if real is False:
        raise ValueError(f"{name}: expected a real value, got {expr}")
    if real is None:
        raise ValueError(
            f"{name}: expected a real value, got {expr}, which is not known to be real "
            "(declare symbols with real=True; a root needs a non-negative base)"
        )
    if nonzero and is_zero(expr) is True:
        raise ValueError(f"{name}: expected a non-zero value, got {expr}")
    return expr


def check_pitch(value: Any, name: str) -> Expr:
    """:func:`check_scalar` for a finite pitch, with a pointer to ``couple`` for ``oo``."""
    if getattr(value, "is_infinite", False) or value in (float("inf"), float("-inf")):
        raise ValueError(f"{name}: expected a finite pitch; build a couple with couple(C)")
    return check_scalar(value, name)


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
        isinstance(value, (str, bytes, *_np_types("ma.MaskedArray")))
        or isinstance(value, Basic)
        and not isinstance(value, MatrixBase)
    ):
        raise TypeError(
            f"{name}: expected a 3-vector (list, tuple or SymPy Matrix), got {describe(value)}"
        )
    shape = shape_of(value)
    if shape is None:
        raise TypeError(
            f"{name}: expected a 3-vector (list, tuple or SymPy Matrix), got {describe(value)}"
        )
    if shape not in ((3,), (3, 1), (1, 3)):
        raise ValueError(f"{name}: expected a 3-vector, got shape {shape}")
    if isinstance(value, MatrixBase):
        items = list(value)
    else:
        try:
            items = [item for item in (value.reshape(3) if hasattr(value, "reshape") else value)]
        except (TypeError, ValueError):
            raise TypeError(f"{name}: expected a 3-vector, got {describe(value)}") from None
        # a nested list [[1], [2], [3]] has shape (3,) here; unwrap one level
        items = [i[0] if isinstance(i, (list, tuple)) and len(i) == 1 else i for i in items]
    entries = [check_scalar(item, f"{name}[{i}]") for i, item in enumerate(items)]
    return ImmutableMatrix(3, 1, entries)


def check_nonzero_vector(value: Any, name: str, needs: str) -> ImmutableMatrix:
    """:func:`check_vector`, and ``ValueError`` when the vector is provably zero.

    ``needs`` says what the zero vector cannot give: "an axis needs a
    non-zero direction", ...

    >>> check_nonzero_vector([0, 0, 0], "direction", "an axis needs a non-zero direction")
    Traceback (most recent call last):
    ...
    ValueError: direction: an axis needs a non-zero direction, got [0, 0, 0]
    """
    v = check_vector(value, name)
    if is_zero_vector(v) is True:
        raise ValueError(f"{name}: {needs}, got {list(v)}")
    return v


def check_name(value: Any, name: str) -> str:
    """Return ``value`` if it is a non-empty string usable as a symbol stem."""
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected a str, got {describe(value)}")
    if not value or not value.strip() or any(c.isspace() or c in ",:" for c in value):
        raise ValueError(
            f"{name}: expected a non-empty name without spaces, commas or colons, got {value!r}"
        )
    return value


def check_six(value: Any, name: str) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    """Split a 6-vector in the book's order into its two 3x1 parts ``(S, S0)``."""
    if (
        isinstance(value, (str, bytes, *_np_types("ma.MaskedArray")))
        or isinstance(value, Basic)
        and not isinstance(value, MatrixBase)
        or shape_of(value) is None
    ):
        raise TypeError(
            f"{name}: expected a 6-vector (list, tuple or SymPy Matrix), got {describe(value)}"
        )
    shape = shape_of(value)
    if shape not in ((6,), (6, 1), (1, 6)):
        raise ValueError(f"{name}: expected a 6-vector (S; S0), got shape {shape}")
    items = (
        list(value)
        if isinstance(value, MatrixBase)
        else list(value.reshape(6) if hasattr(value, "reshape") else value)
    )
    entries = [check_scalar(item, f"{name}[{i}]") for i, item in enumerate(items)]
    return ImmutableMatrix(3, 1, entries[:3]), ImmutableMatrix(3, 1, entries[3:])


# --------------------------------------------------------------------------
# Rigid motions (screwsym.motion.transform, screwsym.motion.displacement, screwsym.motion.chain,
# screwsym.motion.conventions)
# --------------------------------------------------------------------------

def check_matrix(value: Any, name: str, shape: tuple[int, int]) -> ImmutableMatrix:
    """Return ``value`` as an ``ImmutableMatrix`` of ``shape`` with real entries.

    Accepts a SymPy matrix, a NumPy array or nested lists of that shape.

    >>> check_matrix([[1, 0], [0, 1]], "M", (2, 2))
    Matrix([
    [1, 0],
    [0, 1]])
    >>> check_matrix([[1, 0]], "M", (2, 2))
    Traceback (most recent call last):
    ...
    ValueError: M: expected a 2x2 matrix, got shape (1, 2)
    """
    if isinstance(value, (str, bytes)) or isinstance(value, Basic) and not isinstance(
        value, MatrixBase
    ):
        raise TypeError(
            f"{name}: expected a {shape[0]}x{shape[1]} matrix (SymPy Matrix, NumPy array or "
            f"nested lists), got {describe(value)}"
        )
    if isinstance(value, MatrixBase):
        got: tuple[int, ...] | None = tuple(value.shape)
        rows = value.tolist()
    else:
        got = shape_of(value)
        if got is None:
            raise TypeError(
                f"{name}: expected a {shape[0]}x{shape[1]} matrix (SymPy Matrix, NumPy array "
                f"or nested lists), got {describe(value)}"
            )
        rows = value.tolist() if hasattr(value, "tolist") else list(value)
        if got == (len(rows),) and all(isinstance(r, (list, tuple)) for r in rows):
            widths = {len(r) for r in rows}
            got = (len(rows), widths.pop()) if len(widths) == 1 else (len(rows), -1)
    if got != shape:
        raise ValueError(f"{name}: expected a {shape[0]}x{shape[1]} matrix, got shape {got}")
    entries = [
        check_scalar(item, f"{name}[{i}, {j}]")
        for i, row in enumerate(rows)
        for j, item in enumerate(row)
    ]
    return ImmutableMatrix(shape[0], shape[1], entries)


def check_choice(value: Any, name: str, choices: tuple[str, ...]) -> str:
    """Return ``value`` if it is one of the strings ``choices``.

    >>> check_choice("body", "frame", ("space", "body"))
    'body'
    >>> check_choice("world", "frame", ("space", "body"))
    Traceback (most recent call last):
    ...
    ValueError: frame: expected one of 'space', 'body', got 'world'
    """
    if not isinstance(value, str):
        raise TypeError(
            f"{name}: expected one of {', '.join(map(repr, choices))}, got {describe(value)}"
        )
    if value not in choices:
        raise ValueError(f"{name}: expected one of {', '.join(map(repr, choices))}, got {value!r}")
    return value


def check_instance(value: Any, name: str, cls: type) -> Any:
    """Return ``value`` if it is an instance of ``cls``, else raise ``TypeError``.

    >>> check_instance(3, "n", int)
    3
    >>> check_instance(3.0, "n", int)
    Traceback (most recent call last):
    ...
    TypeError: n: expected a int, got float
    """
    if not isinstance(value, cls):
        raise TypeError(f"{name}: expected a {cls.__name__}, got {type(value).__name__}")
    return value


def check_sequence(value: Any, name: str, what: str, length: int | None = None) -> list:
    """Return the items of a list, tuple, SymPy ``Tuple``, matrix or array as a list.

    ``what`` names the items in messages; with ``length`` the count is checked.

    >>> check_sequence((1, 2), "q", "joint values", 2)
    [1, 2]
    >>> check_sequence("q1", "q", "joint values")
    Traceback (most recent call last):
    ...
    TypeError: q: expected a sequence of joint values, got str
    >>> check_sequence([1], "q", "joint values", 2)
    Traceback (most recent call last):
    ...
    ValueError: q: expected 2 joint values, got 1
    """
    from sympy import Tuple

    ok = isinstance(value, (list, tuple, Tuple, MatrixBase)) or (
        isinstance(value, _np_types("ndarray")) and getattr(value, "ndim", None) == 1
    )
    if not ok:
        raise TypeError(f"{name}: expected a sequence of {what}, got {type(value).__name__}")
    items = list(value)
    if length is not None and len(items) != length:
        raise ValueError(f"{name}: expected {length} {what}, got {len(items)}")
    return items


def check_point_or_direction(value: Any, name: str) -> ImmutableMatrix:
    """:func:`check_vector` for what a motion carries, refusing a bare 6-vector by name.

    >>> check_point_or_direction([1, 0, 0, 0, 0, 0], "obj")
    Traceback (most recent call last):
    ...
    TypeError: obj: expected a point or direction (3-vector), a screw or a Transform, got list [1, 0, 0, 0, 0, 0]; wrap a 6-vector with Screw.from_matrix, Twist.from_matrix or Wrench.from_matrix
    """
    if shape_of(value) in ((6,), (6, 1), (1, 6)):
        raise TypeError(
            f"{name}: expected a point or direction (3-vector), a screw or a Transform, got "
            f"{describe(value)}; wrap a 6-vector with Screw.from_matrix, Twist.from_matrix "
            "or Wrench.from_matrix"
        )
    return check_vector(value, name)


# --------------------------------------------------------------------------
# Screw systems and mechanisms (screwsym.systems.screw_system, screwsym.systems.parallel,
# screwsym.numeric.mobility)
# --------------------------------------------------------------------------


def check_exact(value: Any, name: str) -> Any:
    """Return the checked SymPy object ``value`` if it holds no float, else ``ValueError``.

    Screw systems and the joints of a mechanism decide ranks exactly.

    >>> from sympy import ImmutableMatrix, Rational
    >>> check_exact(ImmutableMatrix([Rational(1, 2), 0, 0]), "point").T
    Matrix([[1/2, 0, 0]])
    >>> check_exact(ImmutableMatrix([0.5, 0, 0]), "point")
    Traceback (most recent call last):
    ...
    ValueError: point: expected exact entries (integers, rationals, algebraic numbers, symbols), got the float 0.500000000000000; screw systems decide ranks exactly (use Rational, or screwsym.numeric.mobility for floating point)
    """
    floats = value.atoms(Float)
    if floats:
        raise ValueError(
            f"{name}: expected exact entries (integers, rationals, algebraic numbers, "
            f"symbols), got the float {min(floats)}; screw systems decide ranks exactly "
            "(use Rational, or screwsym.numeric.mobility for floating point)"
        )
    return value


def check_count(value: Any, name: str) -> int:
    """Return ``value`` if it is a positive ``int`` (not a bool).

    >>> check_count(0, "max_cases")
    Traceback (most recent call last):
    ...
    ValueError: max_cases: expected a positive integer, got 0
    """
    if isinstance(value, bool) or not isinstance(value, int):
        raise TypeError(f"{name}: expected a positive integer, got {describe(value)}")
    if value < 1:
        raise ValueError(f"{name}: expected a positive integer, got {value}")
    return value


def check_positive_float(value: Any, name: str) -> float:
    """Return ``value`` as a positive finite ``float`` (a tolerance).

    >>> check_positive_float(-1, "rtol")
    Traceback (most recent call last):
    ...
    ValueError: rtol: expected a positive finite number, got -1
    """
    if isinstance(value, (bool, str, bytes)) or not isinstance(value, (int, float)):
        raise TypeError(f"{name}: expected a positive finite number, got {describe(value)}")
    if not (0 < value < float("inf")):
        raise ValueError(f"{name}: expected a positive finite number, got {value}")
    return float(value)


def check_tidy_input(value: Any, name: str) -> None:
    """Raise ``TypeError`` unless ``value`` is something :func:`screwsym.core.tidy` works on.

    That is a SymPy object or matrix, a number, or a tuple or list of these
    (nested); strings are refused anywhere in it.

    >>> check_tidy_input([1, (2,)], "expr")
    >>> check_tidy_input({"x": 1}, "expr")
    Traceback (most recent call last):
    ...
    TypeError: expr: expected a SymPy expression, matrix, screwsym object, or a tuple or list of them, got dict {'x': 1}
    """
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, (str, bytes)):
            raise TypeError(f"{name}: strings are never evaluated, got {describe(item)}")
        if isinstance(item, (list, tuple)):
            stack.extend(item)
        elif not isinstance(item, (Basic, MatrixBase, int, float, *_np_types("number"))):
            raise TypeError(
                f"{name}: expected a SymPy expression, matrix, screwsym object, "
                f"or a tuple or list of them, got {describe(item)}"
            )


def check_flag(value: Any, name: str) -> bool:
    """Return ``value`` if it is a bool (``True`` or ``False``).

    >>> check_flag(1, "tidy")
    Traceback (most recent call last):
    ...
    TypeError: tidy: expected True or False, got int 1
    """
    if not isinstance(value, bool):
        raise TypeError(f"{name}: expected True or False, got {describe(value)}")
    return value
