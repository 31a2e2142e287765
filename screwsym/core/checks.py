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

from typing import TYPE_CHECKING, Any, ClassVar, Protocol, TypeVar

import numpy as np
from sympy import Basic, Expr, Float, ImmutableMatrix, S
from sympy.core.sympify import SympifyError, sympify
from sympy.matrices import MatrixBase

from .decide import is_real_where_defined, is_zero, is_zero_scaled, is_zero_vector, norm

if TYPE_CHECKING:
    from typing_extensions import Self

    class _ScrewKind(Protocol):
        """What :func:`check_screw` uses of a screw class (``screwsym.core.screw.Screw``,
        which this module cannot import: that module imports this one)."""

        _root: ClassVar[type[Any]]
        _kind: ClassVar[str | None]

        @classmethod
        def _rebuild(cls, S: ImmutableMatrix, S0: ImmutableMatrix, name: str) -> Self: ...

    _K = TypeVar("_K", bound=_ScrewKind)

__all__ = [
    "check_no_strings",
    "check_nonzero_vector",
    "check_scalar",
    "check_vector",
    "check_name",
    "check_screw",
    "check_line_parts",
]


def _describe(value: Any) -> str:
    """A short description of ``value`` for error messages."""
    shape: Any = getattr(value, "shape", None)
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


def _refuse_non_number(value: Any, name: str) -> None:
    if isinstance(value, str):
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {_describe(value)} "
            "(strings are never evaluated)"
        )
    if (
        isinstance(value, (bool, np.bool_))
        or value is None
        or isinstance(value, (MatrixBase, list, tuple, np.ma.MaskedArray))
        or (_shape_of(value) not in (None, ()))
    ):
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {_describe(value)}"
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
            f"{name}: expected a real number or SymPy expression, got {_describe(value)}"
        ) from None
    if not isinstance(expr, Expr) or isinstance(expr, MatrixBase):
        raise TypeError(
            f"{name}: expected a real number or SymPy expression, got {_describe(value)}"
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
        isinstance(value, (str, bytes, np.ma.MaskedArray))
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
        raise TypeError(f"{name}: expected a str, got {_describe(value)}")
    if not value or not value.strip() or any(c.isspace() or c in ",:" for c in value):
        raise ValueError(
            f"{name}: expected a non-empty name without spaces, commas or colons, got {value!r}"
        )
    return value


def check_screw(value: Any, name: str, cls: type[_K]) -> _K:
    """Return ``value`` as a screw object, an instance of ``cls``.

    A screw object of class ``cls`` is passed through.  Another screw is
    rebuilt as ``cls`` from its parts (a plain screw may serve as a line
    vector when its parts make a line), except across kinds: a twist is never
    read as a wrench or a line, nor a wrench as a twist (each kind declares
    its ``_kind``).  A 6-vector (list, tuple, SymPy Matrix or NumPy array of
    six numbers, in the book's order ``(S; S0)``) goes through
    ``cls.from_matrix``.  Errors name the argument ``name``.
    """
    if isinstance(value, cls):
        return value
    if isinstance(value, cls._root):
        if value._kind is not None and value._kind != cls._kind:
            raise TypeError(f"{name}: expected a {cls.__name__}, got {type(value).__name__}")
        return cls._rebuild(value.S, value.S0, name)
    if isinstance(value, (str, bytes)) or _shape_of(value) is None:
        raise TypeError(
            f"{name}: expected a {cls.__name__} or a 6-vector (S; S0), got {_describe(value)}"
        )
    S_, S0_ = check_six(value, name)
    return cls._rebuild(S_, S0_, name)


def check_six(value: Any, name: str) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    """Split a 6-vector in the book's order into its two 3x1 parts ``(S, S0)``."""
    if (
        isinstance(value, (str, bytes, np.ma.MaskedArray))
        or isinstance(value, Basic)
        and not isinstance(value, MatrixBase)
        or _shape_of(value) is None
    ):
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


def check_line_parts(S: ImmutableMatrix, S0: ImmutableMatrix, label: str | tuple[str, str]) -> None:
    """Raise ``ValueError`` unless ``(S; S0)`` may be a line vector.

    A line vector has ``S != 0`` and ``S . S0 = 0`` (1.10).  Only a provable
    violation raises: undecidable symbolic cases are accepted, and floats are
    judged by the float policy of :func:`screwsym.core.decide.is_zero_scaled`.
    ``label`` starts the message: the argument's name, or the names of the
    two parts (a tuple) when the parts were given.
    """
    first, both = (label[0], ", ".join(label)) if isinstance(label, tuple) else (label, label)
    if is_zero_vector(S) is True:
        raise ValueError(f"{first}: a line vector needs a non-zero direction S, got {list(S)}")
    dot = S.dot(S0)
    if is_zero_scaled(dot, norm(S) * norm(S0)) is False:
        raise ValueError(f"{both}: a line vector needs S.S0 = 0 (1.10), got S.S0 = {dot}")


# --------------------------------------------------------------------------
# Rigid motions (screwsym.motion.transform, screwsym.motion.displacement, screwsym.motion.chain,
# screwsym.motion.conventions)
# --------------------------------------------------------------------------

#: symbolic entries larger than this (``count_ops``) are not put through the
#: exact decision of :func:`check_rotation`; they are accepted undecided
ROTATION_CHECK_OPS = 400


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
            f"nested lists), got {_describe(value)}"
        )
    if isinstance(value, MatrixBase):
        got: tuple[int, ...] | None = tuple(value.shape)
        rows = value.tolist()
    else:
        got = _shape_of(value)
        if got is None:
            raise TypeError(
                f"{name}: expected a {shape[0]}x{shape[1]} matrix (SymPy Matrix, NumPy array "
                f"or nested lists), got {_describe(value)}"
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


def _decide_small(expr: Expr) -> bool | None:
    """Zero-decision for an entry of ``R^T R - I`` (of size 1 for a rotation).

    Numbers follow the float policy (:func:`screwsym.core.decide.is_zero_scaled`
    with scale 1: exact for exact numbers); symbolic entries up to
    ``ROTATION_CHECK_OPS`` operations are decided exactly, larger ones not at all.
    """
    if expr.is_number:
        return is_zero_scaled(expr, S.One)
    if expr.count_ops() > ROTATION_CHECK_OPS:
        return None
    return is_zero(expr)


def check_rotation(value: Any, name: str) -> ImmutableMatrix:
    """Return ``value`` as a 3x3 rotation matrix, refusing a provably improper one.

    A rotation satisfies ``R^T R = I`` and ``det R = 1``.  Only a provable
    violation raises: entries that are numbers are decided exactly (floats by
    the float policy of :func:`screwsym.core.decide.is_zero_scaled`), symbolic
    entries with the exact decision of
    :func:`screwsym.core.decide.is_zero` when they are no larger than
    ``ROTATION_CHECK_OPS`` operations; larger ones are accepted undecided.

    >>> check_rotation([[0, -1, 0], [1, 0, 0], [0, 0, 1]], "R").shape
    (3, 3)
    >>> check_rotation([[1, 0, 0], [0, 1, 0], [0, 0, -1]], "R")
    Traceback (most recent call last):
    ...
    ValueError: R: expected a rotation (det R = 1), got det R = -1
    >>> check_rotation([[1, 1, 0], [0, 1, 0], [0, 0, 1]], "R")
    Traceback (most recent call last):
    ...
    ValueError: R: expected an orthonormal matrix (R^T R = I), got R^T R - I = Matrix([[0, 1, 0], [1, 1, 0], [0, 0, 0]])
    """
    R = check_matrix(value, name, (3, 3))
    gram = R.T * R - ImmutableMatrix.eye(3)
    if any(_decide_small(e) is False for e in gram):
        raise ValueError(
            f"{name}: expected an orthonormal matrix (R^T R = I), got R^T R - I = "
            f"Matrix({gram.tolist()})"
        )
    # R^T R = I leaves det R = +-1; the sign is decided for numeric entries only
    det = R.det(method="berkowitz") if all(e.is_number for e in R) else None
    if det is not None and _decide_small(det - 1) is False:
        raise ValueError(f"{name}: expected a rotation (det R = 1), got det R = {det}")
    return R


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
            f"{name}: expected one of {', '.join(map(repr, choices))}, got {_describe(value)}"
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
        isinstance(value, np.ndarray) and value.ndim == 1
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
    if _shape_of(value) in ((6,), (6, 1), (1, 6)):
        raise TypeError(
            f"{name}: expected a point or direction (3-vector), a screw or a Transform, got "
            f"{_describe(value)}; wrap a 6-vector with Screw.from_matrix, Twist.from_matrix "
            "or Wrench.from_matrix"
        )
    return check_vector(value, name)


# --------------------------------------------------------------------------
# Screw systems and mechanisms (screwsym.systems.screw_system, screwsym.systems.mechanism,
# screwsym.numeric.mobility)
# --------------------------------------------------------------------------


def check_screw_system_members(values: Any, name: str, kinds: dict) -> tuple:
    """Return ``values`` as a tuple of screws of one kind: all twists, all wrenches or screws.

    ``kinds`` maps a screw class's ``_kind`` to the class a system of that
    kind holds, ``None`` to the root class (screws and line vectors, which
    mix).  Screw objects are passed through; 6-vectors (S; S0) become the
    kind of the screw objects among them, plain screws if there are none.
    Floats are refused: a screw system decides ranks exactly.

    >>> from screwsym import Screw, Twist, Wrench
    >>> kinds = {None: Screw, "twist": Twist, "wrench": Wrench}
    >>> check_screw_system_members([Twist([1, 0, 0], [0, 0, 0])], "screws", kinds)
    (Twist([1, 0, 0], [0, 0, 0]),)
    >>> check_screw_system_members([Twist([1, 0, 0], [0, 0, 0]),
    ...                             Wrench([1, 0, 0], [0, 0, 0])], "screws", kinds)
    Traceback (most recent call last):
    ...
    TypeError: screws: expected screws of one kind, got Twist and Wrench
    """
    root = kinds[None]
    values = tuple(values)
    found: list = []
    for v in values:
        if isinstance(v, root):
            k = v._kind if v._kind in kinds else None
            if k not in found:
                found.append(k)
    if len(found) > 1:
        raise TypeError(
            f"{name}: expected screws of one kind, got "
            f"{' and '.join(kinds[k].__name__ for k in found)}"
        )
    cls = kinds[found[0]] if found else root
    screws = tuple(check_screw(v, f"{name}[{i}]", cls) for i, v in enumerate(values))
    for i, s in enumerate(screws):
        check_exact(s, f"{name}[{i}]")
    return screws


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
        raise TypeError(f"{name}: expected a positive integer, got {_describe(value)}")
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
        raise TypeError(f"{name}: expected a positive finite number, got {_describe(value)}")
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
            raise TypeError(f"{name}: strings are never evaluated, got {_describe(item)}")
        if isinstance(item, (list, tuple)):
            stack.extend(item)
        elif not isinstance(item, (Basic, MatrixBase, int, float, np.number)):
            raise TypeError(
                f"{name}: expected a SymPy expression, matrix, screwsym object, "
                f"or a tuple or list of them, got {_describe(item)}"
            )


def check_flag(value: Any, name: str) -> bool:
    """Return ``value`` if it is a bool (``True`` or ``False``).

    >>> check_flag(1, "tidy")
    Traceback (most recent call last):
    ...
    TypeError: tidy: expected True or False, got int 1
    """
    if not isinstance(value, bool):
        raise TypeError(f"{name}: expected True or False, got {_describe(value)}")
    return value
