r"""Screws ``$ = (S; S0)`` and the algebra of Sections 1.4.2 and 1.5.

Convention (used everywhere in screwsym): a screw is written in the book's
*ray order*, direction part first, dual (moment) part second::

    $ = (S; S0)        line vector (S; S_0), twist (omega; v_O), wrench (f; C_O)

``S`` is the primary (direction) 3-vector and ``S0`` the dual (moment)
3-vector about the origin O.  ``s.matrix`` stacks them into the 6x1
column ``[S; S0]`` in that order.

A :class:`Screw` is a SymPy ``Basic`` whose ``args`` are ``(S, S0)``, each a
3x1 ``ImmutableMatrix``; everything it is lives in ``args``, so ``subs``,
``xreplace``, ``free_symbols``, hashing, pickling and ``func(*args)`` work as
for any SymPy object.  :class:`~screwsym.core.line.LineVector`,
:class:`~screwsym.core.twist.Twist` and :class:`~screwsym.core.wrench.Wrench` are
subclasses; the meaning of a screw comes from its type.

Each kind declares its own algebra in class attributes, which the base reads
and never names a subclass: ``_kind`` (twists and wrenches may not be added
to each other or read as one another), ``_combination`` (the class of a sum,
a zero multiple or a derivative) and the line class of a decomposition,
declared by the line class itself (``class LineVector(Screw, line_of=Screw)``).

References
==========

Huang, Li & Ding, *Theory of Parallel Mechanisms*, Springer 2013, Chapter 1.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any, ClassVar, TypeAlias, TypeVar, cast, overload

from sympy import Expr, ImmutableMatrix, S, nan, oo, zeros
from sympy.matrices import MatrixBase

from .basic import ScrewsymBasic
from .by_parts import is_zero_vector_by_parts
from .checks import (
    check_choice,
    check_flag,
    check_nonzero_vector,
    check_pitch,
    check_scalar,
    check_six,
    check_vector,
    describe,
    refusing_strings,
    shape_of,
)
from .conditions import CONDS, piecewise, vanishes
from .decide import float_tau, is_zero, is_zero_scaled, is_zero_vector, norm
from .formulas import dot, dual_part, foot_point, moved, pitch_ratio, reciprocal_form
from .tidy import finish, is_polynomial, moment_minus

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import DTypeLike
    from typing_extensions import Self

    # type-only: the line class is made in .line, which imports this module; at run time
    # the axis is built through the registry of line classes (Screw._line_class).  Twist and
    # Wrench (which import this module too) only type decompose_screw's overloads.
    from .line import LineVector
    from .twist import Twist
    from .wrench import Wrench

__all__ = [
    "Screw",
    "pitch",
    "axis",
    "foot",
    "decompose_screw",
    "classify",
    "shift_origin",
    "reciprocal_product",
    "is_reciprocal",
    "distance_to_origin",
    "direction_cosines",
    "unit",
]

# What the checks (screwsym.core.checks) accept.  SymPy ships no type information, so to a
# type checker its classes (Expr, MatrixBase) are Any and these unions accept anything; they
# say what the functions take, and the checks refuse the rest at run time.

#: a real scalar: a SymPy expression (its symbols declared ``real=True``), a Python or NumPy number
ScalarLike: TypeAlias = "Expr | int | float | np.integer | np.floating"
#: a 3-vector: a 3x1 or 1x3 SymPy matrix, a list or tuple of three scalars, or a NumPy array
VectorLike: TypeAlias = "MatrixBase | Sequence[ScalarLike] | np.ndarray"
#: a 6-vector ``(S; S0)``: a 6x1 or 1x6 SymPy matrix, a list or tuple of six, or a NumPy array
SixVectorLike: TypeAlias = "MatrixBase | Sequence[ScalarLike] | np.ndarray"
#: a matrix: a SymPy matrix, nested lists or tuples of scalars, or a 2-d NumPy array
MatrixLike: TypeAlias = "MatrixBase | Sequence[Sequence[ScalarLike]] | np.ndarray"
#: a screw: a Screw (of a kind the function accepts), or a 6-vector in the book's order (S; S0)
ScrewLike: TypeAlias = "Screw | SixVectorLike"


class Screw(ScrewsymBasic):
    r"""A screw $ = (S; S0): direction part ``S`` first, dual part ``S0`` second.

    Explanation
    ===========

    The book (1.31) reserves the word for ``S . S0 != 0``; like the book a few
    lines later, screwsym calls every pair a screw and classifies it with
    :func:`classify`: a line vector (pitch 0), a couple ``(0; C)`` (pitch
    ``oo``), a proper screw, or the zero screw.

    Components must be finite and real: numbers, or expressions whose
    symbols are declared ``real=True`` (a symbol without assumptions is
    refused, since ``is_real`` cannot vouch for it).  A real symbol of unknown
    sign is welcome; decisions that depend on its sign come back as None.

    Every kind builds from the same named constructors, inherited unchanged:
    ``Cls(S, S0)``, :meth:`from_matrix` (a 6-vector), :meth:`from_axis`
    (point, direction, pitch; ``magnitude=`` by keyword), :meth:`through`
    (two points) and :meth:`couple`.

    Examples
    ========

    >>> from screwsym import Screw
    >>> s = Screw([1, 1, 0], [1, 0, 0])          # Example 1.4
    >>> s
    Screw([1, 1, 0], [1, 0, 0])
    >>> s.pitch
    1/2
    >>> s.axis
    LineVector([1, 1, 0], [1/2, -1/2, 0])
    >>> s.foot.T
    Matrix([[0, 0, -1/2]])
    >>> s.matrix.T
    Matrix([[1, 1, 0, 1, 0, 0]])
    >>> Screw([1, 1, 0, 1, 0, 0])
    Traceback (most recent call last):
    ...
    TypeError: Screw(S, S0) takes two 3-vectors; for a 6-vector (S; S0) use Screw.from_matrix(M)

    Parameters
    ==========

    S : 3-vector
        The primary (direction) part.
    S0 : 3-vector
        The dual (moment) part, the moment about the origin O.

    See Also
    ========

    screwsym.core.line.LineVector, screwsym.core.twist.Twist, screwsym.core.wrench.Wrench
    """

    __slots__ = ()

    # above Matrix's 10.01, so ``Matrix * screw`` defers to Screw.__rmul__ (which refuses)
    _op_priority = 20.0
    # NumPy defers to Screw.__rmul__ (which refuses arrays) instead of broadcasting over it
    __array_ufunc__ = None

    #: names of the two parts, used in error messages and printing
    _part_names: tuple[str, str] = ("S", "S0")
    #: the kind of a screw that may not mix with other kinds ("twist", "wrench"), or None
    _kind: ClassVar[str | None] = None
    #: the class of a linear combination (sum, zero multiple, derivative); None: the class itself
    _combination: type[Screw] | None = None
    #: the class of the axis line of a decomposition, declared by ``line_of=`` below
    _line_classes: dict[type[Screw], type[Screw]] = {}
    #: whether the kind's invariant makes the pitch 0 (a line vector's does)
    _pitch_is_zero: bool = False

    def __init_subclass__(cls, *, line_of: type[Screw] | None = None, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        if line_of is not None:
            Screw._line_classes[line_of] = cls

    def __new__(cls, S: VectorLike, S0: VectorLike | None = None) -> Self:
        if S0 is None:
            if isinstance(S, (list, tuple)) and len(S) == 6 or getattr(S, "shape", None) in (
                (6,),
                (6, 1),
                (1, 6),
            ):
                raise TypeError(
                    f"{cls.__name__}(S, S0) takes two 3-vectors; for a 6-vector (S; S0) use "
                    f"{cls.__name__}.from_matrix(M)"
                )
            raise TypeError(f"{cls.__name__}(S, S0): missing the dual part {cls._part_names[1]}")
        S = check_vector(S, cls._part_names[0])
        S0 = check_vector(S0, cls._part_names[1])
        cls._check_parts(S, S0, cls._part_names)
        return ScrewsymBasic.__new__(cls, S, S0)

    @classmethod
    def _check_parts(cls, S: ImmutableMatrix, S0: ImmutableMatrix,
                     label: str | tuple[str, str], incident: bool = False) -> None:
        """Kinds that constrain ``(S; S0)`` raise here, naming ``label`` (a name, or the parts').

        ``incident``: ``S . S0 = 0`` holds identically by the construction (``S0 = r x S``),
        so a line kind need not prove it again.
        """

    @classmethod
    def _rebuild(cls, S: ImmutableMatrix, S0: ImmutableMatrix, name: str,
                 incident: bool = False) -> Self:
        """``cls`` from checked parts of the argument ``name`` (errors name the argument)."""
        cls._check_parts(S, S0, name, incident)
        return ScrewsymBasic.__new__(cls, S, S0)

    @classmethod
    def _combination_class(cls) -> type[Screw]:
        return cls._combination or cls

    @classmethod
    def _line_class(cls) -> type[Screw]:
        return Screw._line_classes.get(cls, cls)

    # ----------------------------------------------------------------- parts
    @property
    def S(self) -> ImmutableMatrix:
        """The primary (direction) part, a 3x1 ``ImmutableMatrix``."""
        return self.args[0]

    @property
    def S0(self) -> ImmutableMatrix:
        """The dual (moment) part about the origin, a 3x1 ``ImmutableMatrix``."""
        return self.args[1]

    def _lambdify_argument(self) -> tuple[ImmutableMatrix, str]:
        # code generation's protocol (screwsym.codegen knows no screwsym class)
        return self.matrix, f"a {type(self).__name__.lower()} (S; S0)"

    def _lambdify_outputs(self) -> ImmutableMatrix:
        # a screw result is returned as its 6 components, (..., 6)
        return self.matrix

    @property
    def matrix(self) -> ImmutableMatrix:
        """The 6x1 column ``[S; S0]`` in the book's ray order."""
        return ImmutableMatrix.vstack(self.S, self.S0)

    def __array__(self, dtype: DTypeLike | None = None, copy: bool | None = None) -> np.ndarray:
        """The six components in ray order ``(S; S0)`` as a NumPy array.

        Numbers give ``float64`` (or ``dtype``); a screw with symbols gives an
        object array, and refuses a numeric ``dtype`` with ``TypeError``.

        >>> import numpy as np
        >>> np.asarray(Screw([1, 1, 0], [1, 0, 0]), dtype=float)
        array([1., 1., 0., 1., 0., 0.])
        """
        import numpy as np

        entries = list(self.matrix)
        free = self.free_symbols
        if free:
            if dtype is not None and np.dtype(dtype) != np.dtype(object):
                names = ", ".join(sorted(str(x) for x in free))
                raise TypeError(
                    f"cannot convert a symbolic {type(self).__name__} to an array of "
                    f"{np.dtype(dtype)}: substitute numbers for {names}"
                )
            return np.array(entries, dtype=object)
        values = np.array([float(e) for e in entries])
        return values if dtype is None else values.astype(dtype)

    @classmethod
    def from_matrix(cls, M: SixVectorLike, *, name: str = "M") -> Self:
        """Build a screw from a 6-vector ``[S; S0]`` (6x1, 1x6, list, tuple or array).

        >>> Screw.from_matrix([1, 0, 0, 0, 1, 0])
        Screw([1, 0, 0], [0, 1, 0])
        """
        S_, S0_ = check_six(M, name)
        return cls._rebuild(S_, S0_, name)

    @classmethod
    def from_axis(cls, point: VectorLike, direction: VectorLike, pitch: ScalarLike = 0, *,
                  magnitude: ScalarLike = 1) -> Self:
        r"""The screw of pitch ``h`` on the axis through ``point`` along ``direction`` (1.38).

        ``$ = m (S; r x S + h S)`` with ``r = point``, ``S = direction``,
        ``h = pitch`` and ``m = magnitude``: for a twist ``m`` is the angular
        speed when ``S`` is a unit vector (1.52), for a wrench the force's
        size (1.57).  ``pitch=0`` gives a line vector's coordinates (1.9).
        A zero direction raises (use :meth:`couple` for an infinite pitch).

        Examples
        ========

        >>> from screwsym import Screw, LineVector, Twist
        >>> from sympy import symbols
        >>> h, w = symbols("h omega", real=True)
        >>> Screw.from_axis([0, 1, 0], [1, 0, 0], h)
        Screw([1, 0, 0], [h, 0, -1])
        >>> LineVector.from_axis([0, 0, 1], [1, 0, 0])    # Fig. 1.5: (1 0 0; 0 1 0)
        LineVector([1, 0, 0], [0, 1, 0])
        >>> Twist.from_axis([1, 0, 0], [0, 0, 1], magnitude=w)      # (1.48)
        Twist([0, 0, omega], [0, -omega, 0])
        """
        r = check_vector(point, "point")
        S_ = check_nonzero_vector(direction, "direction", "an axis needs a non-zero direction")
        h = check_pitch(pitch, "pitch")
        m = check_scalar(magnitude, "magnitude")
        # a kind that refuses the result (a line vector of zero direction) names the culprit
        label = "magnitude" if is_zero(m) is True else "point, direction, pitch"
        # with h = 0 the moment is m r x S: S . S0 = 0 identically, not proved again
        return cls._rebuild(m * S_, m * dual_part(r, S_, h), label, incident=h == 0)

    @classmethod
    def through(cls, A: VectorLike, B: VectorLike) -> Self:
        r"""The line through the points ``A`` and ``B``, directed from A to B: ``(B - A; A x (B - A))``.

        ``S = B - A`` (1.1) and ``S0 = A x S`` (1.9).

        >>> from screwsym import LineVector, vector
        >>> L = LineVector.through(vector("A"), vector("B"))
        >>> L.S.T
        Matrix([[-A_x + B_x, -A_y + B_y, -A_z + B_z]])
        """
        A = check_vector(A, "A")
        B = check_vector(B, "B")
        if is_zero_vector(B - A) is True:
            raise ValueError(f"A, B: expected two distinct points, got A = B = {list(A)}")
        S_ = B - A
        return cls._rebuild(S_, dual_part(A, S_), "A, B", incident=True)

    @classmethod
    def couple(cls, C: VectorLike) -> Self:
        """The couple ``(0; C)``: a screw of infinite pitch, a free vector.

        >>> Screw.couple([0, 0, 5]).pitch
        oo
        """
        return cls._rebuild(zeros(3, 1), check_vector(C, "C"), "C")

    # --------------------------------------------------- derived quantities
    @property
    def pitch(self) -> Expr:
        """The pitch ``h = S.S0 / S.S`` (1.34); see :func:`pitch`."""
        return _pitch(self)

    @property
    def axis(self) -> LineVector:
        """The axis line vector ``(S; S0 - h S)`` (1.36); see :func:`axis`."""
        return _axis(self)

    @property
    def foot(self) -> ImmutableMatrix:
        """The point of the axis nearest the origin (1.16); see :func:`foot`."""
        return _foot(self)

    @property
    def distance_to_origin(self) -> Expr:
        """Distance from the origin to the axis (1.18); see :func:`distance_to_origin`."""
        return _distance_to_origin(self)

    @property
    def direction_cosines(self) -> ImmutableMatrix:
        """``S / |S|`` (1.5); see :func:`direction_cosines`."""
        return _direction_cosines(self)

    def classify(self) -> str | None:
        """``'line'``, ``'couple'``, ``'screw'``, ``'zero'`` or None; see :func:`classify`."""
        return _classify(self)

    def decompose(self, *, tidy: bool = True) -> tuple[Screw, Screw]:
        """Axis line vector plus parallel couple (1.37); see :func:`decompose_screw`."""
        return _decompose(self, tidy=check_flag(tidy, "tidy"))

    def unit(self, *, tidy: bool = True) -> Self:
        """The unit screw, normalised as in (1.5); see :func:`unit`."""
        return _unit(self, tidy=check_flag(tidy, "tidy"))

    def shift_origin(self, A: VectorLike, *, tidy: bool = True) -> Self:
        """The same screw with its moment taken about ``A`` (1.32); see :func:`shift_origin`."""
        return shift_origin_unchecked(self, check_vector(A, "A"), check_flag(tidy, "tidy"))

    def reciprocal_product(self, other: ScrewLike, *, tidy: bool = True) -> Expr:
        """``S1.S2^0 + S2.S1^0`` (1.45); see :func:`reciprocal_product`."""
        return reciprocal_product_unchecked(
            self, check_screw(other, "other", Screw), check_flag(tidy, "tidy")
        )

    def is_reciprocal(self, other: ScrewLike) -> bool | None:
        """Whether the reciprocal product vanishes; see :func:`is_reciprocal`."""
        return _is_reciprocal(self, check_screw(other, "other", Screw))

    def equals(self, other: ScrewLike) -> bool | None:
        """Whether ``self`` and ``other`` are the same screw mathematically.

        ``==`` compares structure, as everywhere in SymPy; ``equals`` decides
        whether all six components of the difference vanish: True, False, or
        None when the symbols do not decide.  The classes may differ.

        >>> from sympy import symbols
        >>> x = symbols("x", real=True)
        >>> a, b = Screw([x*(x + 1), 0, 0], [0, 0, 0]), Screw([x**2 + x, 0, 0], [0, 0, 0])
        >>> a == b, a.equals(b)
        (False, True)
        """
        other = check_screw(other, "other", Screw)
        return is_zero_vector(self.matrix - other.matrix)

    # ------------------------------------------------------------ algebra
    def __add__(self, other: Screw) -> Screw:
        """``$1 + $2 = (S1 + S2; S1^0 + S2^0)`` (1.39)."""
        if not isinstance(other, Screw):
            return NotImplemented
        if self._kind and other._kind and self._kind != other._kind:
            raise TypeError(
                f"cannot add a {type(self).__name__} and a {type(other).__name__}: "
                "a twist is a motion and a wrench a force system"
            )
        cls = (other if other._kind and not self._kind else self)._combination_class()
        return cls(self.S + other.S, self.S0 + other.S0)

    def __sub__(self, other: Screw) -> Screw:
        if not isinstance(other, Screw):
            return NotImplemented
        return self + (-other)

    def __neg__(self) -> Self:
        # -$ = (-S; -S0) is of the same kind without a new check: the kinds' conditions
        # (a line's S != 0 and S . S0 = 0, 1.10) are homogeneous, so they hold for -$ as
        # they held for $ (proving S . S0 = 0 again was most of a symbolic line's negation)
        return ScrewsymBasic.__new__(type(self), -self.S, -self.S0)

    def __pos__(self) -> Self:
        return self

    def __mul__(self, k: ScalarLike) -> Screw:
        """``lambda $ = (lambda S; lambda S0)`` (1.44)."""
        if isinstance(k, Screw):
            raise TypeError(
                "cannot multiply two screws with '*'; for the reciprocal product (1.45) "
                "use reciprocal_product(s1, s2)"
            )
        k = check_scalar(k, "k")
        cls = self._combination_class() if is_zero(k) is True else type(self)
        return cls(k * self.S, k * self.S0)

    if TYPE_CHECKING:
        def __rmul__(self, k: ScalarLike) -> Screw: ...
    else:
        __rmul__ = __mul__

    def __truediv__(self, k: ScalarLike) -> Screw:
        return self * (S.One / check_scalar(k, "k", nonzero=True))

    # ------------------------------------------------ SymPy integration
    def _apply(self, f: Callable[[ImmutableMatrix], ImmutableMatrix],
               cls: type[Screw] | None = None) -> Any:
        cls = type(self) if cls is None else cls
        return cls(f(self.S), f(self.S0))

    def _eval_simplify(self, **kwargs: Any) -> Self:
        return self._apply(lambda m: m.simplify(**kwargs))

    if TYPE_CHECKING:
        # ScrewsymBasic.diff gives what _eval_diff_parts gives: a screw (Twist and Wrench say
        # their own kind)
        def diff(self, *symbols: Any, **kwargs: Any) -> Screw: ...

    def _eval_diff_parts(self, *symbols: Any, **kwargs: Any) -> Screw:
        """Differentiate both parts: ``d$/dt = (dS/dt; dS0/dt)``.

        The derivative of a line vector is in general not a line vector, so it
        comes back as a :class:`Screw`.

        >>> from sympy import symbols
        >>> t = symbols("t", real=True)
        >>> Screw([t, 0, 0], [0, t**2, 0]).diff(t)
        Screw([1, 0, 0], [0, 2*t, 0])
        """
        return self._apply(lambda m: m.diff(*symbols, **kwargs), self._combination_class())

    def _eval_evalf_parts(self, n: int = 15, **options: Any) -> Self:
        """Evaluate both parts numerically to ``n`` digits."""
        return self._apply(lambda m: m.evalf(n, **options))

    def expand(self, **hints: Any) -> Self:
        """Expand every component.

        >>> from sympy import symbols
        >>> t = symbols("t", real=True)
        >>> Screw([(t + 1)**2, 0, 0], [0, 0, 0]).expand()
        Screw([t**2 + 2*t + 1, 0, 0], [0, 0, 0])
        """
        return self._apply(lambda m: m.expand(**hints))

    def applyfunc(self, f: Callable[[Expr], Any]) -> Self:
        """Apply ``f`` to every one of the six components (e.g. ``cancel``).

        >>> from sympy import cos, sin, symbols, trigsimp
        >>> t = symbols("t", real=True)
        >>> Screw([cos(t)**2 + sin(t)**2, 0, 0], [0, 0, 0]).applyfunc(trigsimp)
        Screw([1, 0, 0], [0, 0, 0])
        """
        g = refusing_strings(f, "applyfunc")  # a matrix would parse a string result
        return self._apply(lambda m: m.applyfunc(g))

    # ------------------------------------------------------------ printing
    def _sympystr(self, printer: Any) -> str:
        parts = ", ".join(
            "[" + ", ".join(printer._print(e) for e in part) + "]" for part in self.args
        )
        return f"{type(self).__name__}({parts})"

    def _latex(self, printer: Any) -> str:
        from .printing import latex_screw

        return latex_screw(self, printer)

    def _pretty(self, printer: Any) -> Any:
        from .printing import pretty_screw

        return pretty_screw(self, printer)


#: a screw of any kind, for the private operations that keep the kind of their argument
_S = TypeVar("_S", bound=Screw)


def check_screw(value: Any, name: str, cls: type[_S]) -> _S:
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
    if isinstance(value, Screw):
        if value._kind is not None and value._kind != cls._kind:
            raise TypeError(f"{name}: expected a {cls.__name__}, got {type(value).__name__}")
        return cls._rebuild(value.S, value.S0, name)
    if isinstance(value, (str, bytes)) or shape_of(value) is None:
        raise TypeError(
            f"{name}: expected a {cls.__name__} or a 6-vector (S; S0), got {describe(value)}"
        )
    S_, S0_ = check_six(value, name)
    return cls._rebuild(S_, S0_, name)


# --------------------------------------------------------------------------
# The chapter's operations, each written once.  The public function checks its
# arguments (naming them as the caller wrote them) and calls the unchecked one,
# which methods call too with their own names checked.  The unchecked ones other
# modules of the core call have public names (``*_unchecked``, ``require_axis``,
# ``finite_pitch``), kept out of ``__all__``: they trust their arguments.
# --------------------------------------------------------------------------


def require_axis(s: Screw, what: str, name: str | None = None) -> None:
    """Raise ``ValueError`` when ``S`` is provably zero: a couple, or the zero screw."""
    if is_zero_vector(s.S) is not True:
        return
    prefix = f"{name}: " if name else ""
    if is_zero_vector(s.S0) is True:
        raise ValueError(f"{prefix}the zero screw (0; 0) has no {what}")
    raise ValueError(f"{prefix}a couple (0; C) has no {what}: its axis lies at infinity; got {s}")


def _pitch(s: Screw, name: str | None = None, tidy: bool = True, conds: str = "none") -> Expr:
    if not s._pitch_is_zero and is_zero_vector_by_parts(s.S) is True:
        if is_zero_vector(s.S0) is True:
            raise ValueError(f"{name + ': ' if name else ''}the zero screw (0; 0) has no pitch")
        return oo
    h = finite_pitch(s, tidy)
    if conds != "piecewise" or s._pitch_is_zero or not s.free_symbols or is_zero_vector_by_parts(s.S) is not None:
        return h
    # _where_direction_vanishes, with the direction's zero decided by its parts above
    S_zero = vanishes(s.S)
    return piecewise([(nan, S_zero & vanishes(s.S0)), (oo, S_zero)], h)


def finite_pitch(s: Screw, tidy: bool = False) -> Expr:
    """``S . S0 / S . S`` (1.34), for a screw not known to be a couple.

    A line vector's pitch is 0 by its invariant, and a float screw whose
    ``S . S0`` is zero under the float policy has pitch exactly 0, as
    :func:`classify` calls it a line.  Tidied, the quotient is cancelled:
    ``S . S`` is a common factor whenever the dual part is ``r x S + h S``
    (the cross term vanishes on expansion), which gives ``h``.
    """
    ss0 = dot(s.S, s.S0)
    if s._pitch_is_zero:
        return S.Zero
    if tidy and float_tau(ss0) is None:
        # exact: the quotient in lowest terms is 0 exactly when S . S0 expands to 0, so the
        # zero test of the float policy below would only repeat the same expansion
        return finish(pitch_ratio(s.S, s.S0))
    if is_zero_scaled(ss0, norm(s.S) * norm(s.S0)) is True:
        return S.Zero
    return pitch_ratio(s.S, s.S0)


def _known(cls: type[_S], S_: ImmutableMatrix, S0_: ImmutableMatrix) -> _S:
    """``cls(S_, S0_)`` for parts derived from a checked screw by an operation that keeps
    the kind's invariant identically (the axis moment ``S0 - h S`` has ``S . (S0 - h S) = 0``
    (1.36); a shift of origin keeps ``S . S0``), so checking again would only re-prove it."""
    return ScrewsymBasic.__new__(cls, S_, S0_)


def _where_direction_vanishes(s: Screw, value: Any, couple_value: Any = nan) -> Any:
    """``value`` where ``S != 0``; ``couple_value`` where ``S = 0 != S0``; ``nan`` at (0; 0).

    The ``conds="piecewise"`` form of a generic result: a ``Piecewise`` when
    the symbols do not decide whether ``S`` vanishes (a line vector's ``S``
    does not, by its invariant), else ``value`` itself.
    """
    if s._pitch_is_zero or s.free_symbols == set() or is_zero_vector(s.S) is not None:
        return value
    S_zero = vanishes(s.S)
    return piecewise([(nan, S_zero & vanishes(s.S0)), (couple_value, S_zero)], value)


def pitch(s: ScrewLike, *, tidy: bool = True, conds: str = "none") -> Expr:
    r"""The pitch of a screw, ``h = S . S0 / S . S`` (1.34).

    Explanation
    ===========

    The pitch does not depend on the origin (1.33).  A couple ``(0; C)`` has
    infinite pitch and gives ``oo``; the zero screw has none and raises
    ``ValueError``.  A line vector's pitch is 0.  With symbols the result is
    the formula in lowest terms (``tidy=False``: as built); it holds where
    ``S != 0``.  With ``conds="piecewise"`` it is a ``Piecewise`` right for
    every value of the symbols: ``oo`` where ``S = 0 != S0``, ``nan`` at the
    zero screw, the formula elsewhere.

    Examples
    ========

    >>> from screwsym import Screw, pitch, vector
    >>> pitch(Screw([1, 0, 0], [1, 0, 0]))         # Example 1.2
    1
    >>> pitch([1, 1, 0, 1, 0, 0])                  # Example 1.4, as a 6-vector
    1/2
    >>> pitch(Screw.couple([0, 0, 1]))
    oo
    >>> from sympy import symbols
    >>> h, x = symbols("h x", real=True)
    >>> pitch(Screw.from_axis(vector("r"), vector("S"), h))     # (1.38): S.S cancels
    h
    >>> pitch(Screw([x, 0, 0], [0, 0, 1]))                      # generic: holds where x != 0
    0
    >>> pitch(Screw([x, 0, 0], [0, 0, 1]), conds="piecewise")   # a couple at x = 0
    Piecewise((oo, Eq(x, 0)), (0, True))

    Parameters
    ==========

    s : Screw or 6-vector
    tidy : bool
        Return the result in lowest terms (default), or as built.
    conds : {"none", "piecewise"}
        ``"piecewise"``: the cases where ``S`` vanishes as a ``Piecewise``.

    See Also
    ========

    axis, classify, screwsym.core.tidy.tidy
    """
    return _pitch(
        check_screw(s, "s", Screw), "s", check_flag(tidy, "tidy"),
        check_choice(conds, "conds", CONDS),
    )


def _axis(s: Screw, name: str | None = None, tidy: bool = True) -> LineVector:
    require_axis(s, "axis", name)
    line = cast("type[LineVector]", Screw._line_class())
    if s._pitch_is_zero:
        return finish(line._rebuild(s.S, s.S0, name or "s"), tidy)
    if tidy:
        return _known(line, s.S, _axis_moment(s, True))
    return line(s.S, _axis_moment(s, False))


def _axis_moment(s: Screw, tidy: bool, h: Expr | None = None) -> ImmutableMatrix:
    """The axis moment ``S0 - h S`` (1.36), for the pitch ``h`` (found, and tidied first
    when ``tidy``, unless the caller has it already)."""
    h = finite_pitch(s, tidy) if h is None else h
    return moment_minus(s.S0, h, s.S) if tidy else s.S0 - h * s.S


def axis(s: ScrewLike, *, tidy: bool = True) -> LineVector:
    r"""The axis of a screw as a line vector ``(S; S0 - h S)`` (1.36, 1.37).

    The axis has the screw's direction and pitch 0.  A couple has no axis in
    finite space and raises ``ValueError``.  With symbols the result holds
    where ``S != 0``; it comes in lowest terms, the pitch cancelled first
    (``tidy=False``: as built).

    Examples
    ========

    >>> from sympy import symbols
    >>> from screwsym import Screw, axis, vector
    >>> axis(Screw([1, 1, 0], [1, 0, 0]))           # Example 1.4
    LineVector([1, 1, 0], [1/2, -1/2, 0])
    >>> h = symbols("h", real=True)
    >>> axis(Screw.from_axis(vector("r"), [0, 0, 1], h))          # (S; r x S)
    LineVector([0, 0, 1], [r_y, -r_x, 0])
    """
    return _axis(check_screw(s, "s", Screw), "s", check_flag(tidy, "tidy"))


def _foot(s: Screw, name: str | None = None, tidy: bool = True,
          conds: str = "none") -> ImmutableMatrix:
    require_axis(s, "foot point", name)
    P = finish(foot_point(s.S, s.S0), tidy)
    return _where_direction_vanishes(s, P) if conds == "piecewise" else P


def foot(s: ScrewLike, *, tidy: bool = True, conds: str = "none") -> ImmutableMatrix:
    r"""The point of the line (or screw axis) nearest the origin, ``P = S x S0 / S.S`` (1.16).

    For a screw the same formula gives the foot of its axis, since
    ``S x (h S) = 0`` (1.36).  With symbols it holds where ``S != 0``, in
    lowest terms (``tidy=False``: as built); ``conds="piecewise"`` gives
    ``nan`` where ``S = 0`` (a couple's axis is at infinity).

    Examples
    ========

    >>> from screwsym import LineVector, foot
    >>> foot(LineVector.through([1, 2, 3], [1, 2, 4])).T
    Matrix([[1, 2, 0]])
    """
    return _foot(
        check_screw(s, "s", Screw), "s", check_flag(tidy, "tidy"),
        check_choice(conds, "conds", CONDS),
    )


def _distance_to_origin(s: Screw, name: str | None = None, tidy: bool = True,
                        conds: str = "none") -> Expr:
    if not tidy or float_tau(*s.matrix) is not None:
        d = norm(_foot(s, name, tidy=False))
    else:
        # The foot is S x S0' / S.S for the axis moment S0' = S0 - h S, and S . S0' = 0, so
        # Lagrange's identity |S x S0'|^2 = |S|^2 |S0'|^2 - (S . S0')^2 gives |S0'| / |S|:
        # short when the pitch cancels; else |S x S0| / S.S, the foot's length, is shorter.
        require_axis(s, "foot point", name)
        h = finite_pitch(s, True)
        if is_polynomial(h):
            d = finish(norm(_axis_moment(s, True, h)) / norm(s.S))
        else:
            d = finish(norm(_foot(s, name)))
    return _where_direction_vanishes(s, d) if conds == "piecewise" else d


def distance_to_origin(s: ScrewLike, *, tidy: bool = True, conds: str = "none") -> Expr:
    r"""Distance from the origin to the line or screw axis, ``|P|`` (1.17, 1.18).

    Computed as the book's ``|S0| / |S|`` (1.18) for the axis line vector
    ``(S; S0 - h S)``, which equals ``|S x S0| / (S . S)`` by Lagrange's
    identity; ``tidy=False`` gives ``|S x S0 / S . S|`` as built.  With
    symbols it holds where ``S != 0``; ``conds="piecewise"`` gives ``nan``
    where ``S = 0``.

    >>> from screwsym import LineVector, distance_to_origin, vector
    >>> distance_to_origin(LineVector.through([3, 4, 0], [3, 4, 1]))
    5
    >>> distance_to_origin(LineVector(vector("S"), vector("S0")))
    sqrt(S0_x**2 + S0_y**2 + S0_z**2)/sqrt(S_x**2 + S_y**2 + S_z**2)
    """
    return _distance_to_origin(
        check_screw(s, "s", Screw), "s", check_flag(tidy, "tidy"),
        check_choice(conds, "conds", CONDS),
    )


def _direction_cosines(s: Screw, name: str | None = None, tidy: bool = True,
                       conds: str = "none") -> ImmutableMatrix:
    require_axis(s, "direction", name)
    dc = finish(s.S / norm(s.S), tidy)
    return _where_direction_vanishes(s, dc) if conds == "piecewise" else dc


def direction_cosines(s: ScrewLike, *, tidy: bool = True, conds: str = "none") -> ImmutableMatrix:
    r"""The direction cosines ``(l, m, n) = S / |S|`` (1.5).

    With symbols it holds where ``S != 0``; ``conds="piecewise"`` gives
    ``nan`` where ``S = 0``.

    >>> from screwsym import LineVector, direction_cosines
    >>> direction_cosines(LineVector.through([0, 0, 0], [2, 0, 0])).T
    Matrix([[1, 0, 0]])
    """
    return _direction_cosines(
        check_screw(s, "s", Screw), "s", check_flag(tidy, "tidy"),
        check_choice(conds, "conds", CONDS),
    )


def _unit(s: _S, name: str | None = None, tidy: bool = True) -> _S:
    if is_zero_vector(s.S) is True:
        if is_zero_vector(s.S0) is True:
            prefix = f"{name}: " if name else ""
            raise ValueError(f"{prefix}the zero screw (0; 0) cannot be normalised")
        n = norm(s.S0)
    else:
        n = norm(s.S)
    return finish(type(s)(s.S / n, s.S0 / n), tidy)


@overload
def unit(s: _S, *, tidy: bool = True) -> _S: ...
@overload
def unit(s: SixVectorLike, *, tidy: bool = True) -> Screw: ...


def unit(s: ScrewLike, *, tidy: bool = True) -> Screw:
    r"""The unit screw: ``$ / |S|``, or ``$ / |S0|`` for a couple (1.5, Example 1.3).

    The book normalises a line vector or screw by the length of its direction
    part, so that ``S`` is a unit vector and the pitch is unchanged; a couple
    ``(0; C)`` is normalised by ``|C|``.  The zero screw raises ``ValueError``.
    With symbols, the generic result divides by ``|S|`` and holds where
    ``S != 0``.  The kind (line vector, twist, wrench) is kept.  The parts
    come in lowest terms (``tidy=False``: as built).

    >>> from screwsym import Screw, unit
    >>> unit(Screw([0, 3, 4], [1, 0, 0]))
    Screw([0, 3/5, 4/5], [1/5, 0, 0])
    >>> unit(Screw.couple([0, 0, -2]))
    Screw([0, 0, 0], [0, 0, -1])
    """
    return _unit(check_screw(s, "s", Screw), "s", check_flag(tidy, "tidy"))


def _decompose(s: Screw, name: str | None = None, tidy: bool = True) -> tuple[Screw, Screw]:
    require_axis(s, "axis, so no line-plus-couple decomposition", name)
    general = s._combination_class()
    h = finite_pitch(s, tidy)
    moment = _axis_moment(s, tidy, h)
    line = _known(general._line_class(), s.S, moment) if tidy else general._line_class()(s.S, moment)
    return line, general(zeros(3, 1), h * s.S)


@overload
def decompose_screw(s: Twist, *, tidy: bool = True) -> tuple[Twist, Twist]: ...
@overload
def decompose_screw(s: Wrench, *, tidy: bool = True) -> tuple[Wrench, Wrench]: ...
@overload
def decompose_screw(s: ScrewLike, *, tidy: bool = True) -> tuple[Screw, Screw]: ...


def decompose_screw(s: ScrewLike, *, tidy: bool = True) -> tuple[Screw, Screw]:
    r"""Split a screw into its axis line vector and a parallel couple (1.37).

    ``(S; S0) = (S; S0 - h S) + (0; h S)``.  Returns the pair
    ``(line, couple)``; for a twist these are a rotation and a translation
    (both :class:`~screwsym.core.twist.Twist`), for a wrench a force and a couple
    (both :class:`~screwsym.core.wrench.Wrench`).  With symbols it holds where
    ``S != 0``; the pitch is cancelled first (``tidy=False``: as built).

    >>> from screwsym import Screw, decompose_screw
    >>> line, couple = decompose_screw(Screw([1, 1, 0], [1, 0, 0]))
    >>> line, couple
    (LineVector([1, 1, 0], [1/2, -1/2, 0]), Screw([0, 0, 0], [1/2, 1/2, 0]))
    >>> line + couple
    Screw([1, 1, 0], [1, 0, 0])
    """
    return _decompose(check_screw(s, "s", Screw), "s", check_flag(tidy, "tidy"))


def _classify(s: Screw) -> str | None:
    S_zero = is_zero_vector(s.S)
    if S_zero is True:
        S0_zero = is_zero_vector(s.S0)
        return None if S0_zero is None else ("zero" if S0_zero else "couple")
    if S_zero is None:
        return None
    if s._pitch_is_zero:
        return "line"
    dot_zero = is_zero_scaled(dot(s.S, s.S0), norm(s.S) * norm(s.S0))
    return None if dot_zero is None else ("line" if dot_zero else "screw")


def classify(s: ScrewLike) -> str | None:
    r"""Classify a screw as in the table at the end of Section 1.4.2.

    Returns ``'line'`` (``S != 0``, ``S.S0 = 0``, pitch 0), ``'couple'``
    (``S = 0``, ``S0 != 0``, pitch ``oo``), ``'screw'`` (``S.S0 != 0``),
    ``'zero'`` for ``(0; 0)``, or None when the symbols do not decide.
    Floats follow the float policy (README, "Floats"), as the constructors do.

    Examples
    ========

    >>> from screwsym import Screw, classify
    >>> from sympy import symbols
    >>> classify(Screw([1, 1, 0], [1, 0, 0])), classify(Screw.couple([1, 0, 0]))
    ('screw', 'couple')
    >>> x = symbols("x", real=True)
    >>> classify(Screw([1, 0, 0], [x, 0, 0])) is None
    True
    """
    return _classify(check_screw(s, "s", Screw))


def shift_origin_unchecked(s: _S, A: ImmutableMatrix, tidy: bool = True) -> _S:
    """:func:`shift_origin` (1.32) of a screw and a 3x1 column already checked.

    Keeps the class of ``s``; a twist's velocity at a point and a wrench's
    moment about a point call this too.
    """
    S_, S0_ = moved(None, -A, s.S, s.S0)  # a pure translation by -A (1.32)
    if tidy:
        return _known(type(s), S_, finish(S0_))
    return type(s)(S_, S0_)


@overload
def shift_origin(s: _S, A: VectorLike, *, tidy: bool = True) -> _S: ...
@overload
def shift_origin(s: SixVectorLike, A: VectorLike, *, tidy: bool = True) -> Screw: ...


def shift_origin(s: ScrewLike, A: VectorLike, *, tidy: bool = True) -> Screw:
    r"""The same screw with its dual part taken about the point ``A`` (1.32).

    ``S^A = S^0 + AO x S = S^0 - A x S``, where ``A`` is the position of the
    new origin in the old frame.  ``S`` and the pitch do not change (1.33).
    The result holds for every value of the symbols and comes in lowest
    terms (``tidy=False``: as built).

    Examples
    ========

    >>> from screwsym import Screw, shift_origin
    >>> s = Screw.from_axis([0, 1, 0], [1, 0, 0], 2)
    >>> shift_origin(s, [0, 1, 0])                   # A on the axis: (S; hS)
    Screw([1, 0, 0], [2, 0, 0])
    """
    return shift_origin_unchecked(
        check_screw(s, "s", Screw), check_vector(A, "A"), check_flag(tidy, "tidy")
    )


def reciprocal_product_unchecked(s1: Screw, s2: Screw, tidy: bool = False) -> Expr:
    """:func:`reciprocal_product` (1.45) of two screws already checked, tidied when ``tidy``.

    The formula is :func:`screwsym.core.formulas.reciprocal_form`'s; the
    mutual moment of two lines and the power of a wrench on a twist call this too.
    """
    return finish(reciprocal_form([*s1.S, *s1.S0], [*s2.S, *s2.S0]), tidy)


def _is_reciprocal(s1: Screw, s2: Screw) -> bool | None:
    scale = norm(s1.S) * norm(s2.S0) + norm(s2.S) * norm(s1.S0)
    return is_zero_scaled(reciprocal_product_unchecked(s1, s2), scale)


def reciprocal_product(s1: ScrewLike, s2: ScrewLike, *, tidy: bool = True) -> Expr:
    r"""The reciprocal product ``$1 o $2 = S1 . S2^0 + S2 . S1^0`` (1.45).

    For two line vectors it is their mutual moment (1.23); for a twist and a
    wrench it is the power (see :func:`screwsym.core.wrench.power`).  It does not
    depend on the origin (1.47).  It holds for every value of the symbols and
    comes in lowest terms (``tidy=False``: as built).

    Examples
    ========

    >>> from screwsym import Screw, reciprocal_product
    >>> reciprocal_product(Screw([1, 0, 0], [0, 0, 0]), Screw([0, 1, 0], [0, 0, 1]))
    0
    >>> reciprocal_product([1, 1, 0, 1, 0, 0], [1, 1, 0, 1, 0, 0])
    2
    """
    return reciprocal_product_unchecked(
        check_screw(s1, "s1", Screw), check_screw(s2, "s2", Screw), check_flag(tidy, "tidy")
    )


def is_reciprocal(s1: ScrewLike, s2: ScrewLike) -> bool | None:
    r"""Whether ``$1 o $2 = 0`` (1.45): True, False, or None when the symbols do not decide.

    Floats follow the float policy, relative to ``|S1||S2^0| + |S2||S1^0|``.

    >>> from screwsym import Screw, is_reciprocal
    >>> is_reciprocal(Screw([1, 0, 0], [0, 0, 0]), Screw([0, 1, 0], [0, 0, 1]))
    True
    >>> is_reciprocal(Screw([1, 0, 0], [1, 0, 0]), Screw([1, 0, 0], [0, 0, 0]))
    False
    """
    return _is_reciprocal(check_screw(s1, "s1", Screw), check_screw(s2, "s2", Screw))
