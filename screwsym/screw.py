r"""Screws ``$ = (S; S0)`` and the algebra of Sections 1.4.2 and 1.5.

Convention (used everywhere in screwsym): a screw is written in the book's
*ray order*, direction part first, dual (moment) part second::

    $ = (S; S0)        line vector (S; S_0), twist (omega; v_O), wrench (f; C_O)

``S`` is the primary (direction) 3-vector and ``S0`` the dual (moment)
3-vector about the origin O.  ``as_matrix()`` stacks them into the 6x1
column ``[S; S0]`` in that order.

A :class:`Screw` is a SymPy ``Basic`` whose ``args`` are ``(S, S0)``, each a
3x1 ``ImmutableMatrix``; everything it is lives in ``args``, so ``subs``,
``xreplace``, ``free_symbols``, hashing, pickling and ``func(*args)`` work as
for any SymPy object.  :class:`~screwsym.line.LineVector`,
:class:`~screwsym.twist.Twist` and :class:`~screwsym.wrench.Wrench` are
subclasses; the meaning of a screw comes from its type.

References
==========

Huang, Li & Ding, *Theory of Parallel Mechanisms*, Springer 2013, Chapter 1.
"""

from __future__ import annotations

from typing import Any

from sympy import Expr, ImmutableMatrix, S, oo, sqrt, zeros

from ._basic import ScrewsymBasic
from ._decide import is_zero, is_zero_vector
from ._validation import check_scalar, check_screw, check_six, check_vector

__all__ = [
    "Screw",
    "pitch",
    "axis",
    "foot",
    "decompose",
    "classify",
    "shift_origin",
    "reciprocal_product",
    "is_reciprocal",
    "distance_to_origin",
    "direction_cosines",
]

ScrewLike = Any  # a Screw, or a 6-vector (list, tuple, SymPy Matrix, NumPy array) in (S; S0) order
VectorLike = Any  # a 3-vector: list, tuple, SymPy Matrix or NumPy array of three


class Screw(ScrewsymBasic):
    r"""A screw $ = (S; S0): direction part ``S`` first, dual part ``S0`` second.

    Explanation
    ===========

    The book (1.31) reserves the word for ``S . S0 != 0``; like the book a few
    lines later, screwsym calls every pair a screw and classifies it with
    :func:`classify`: a line vector (pitch 0), a couple ``(0; C)`` (pitch
    ``oo``), a proper screw, or the zero screw.

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
    >>> s.as_matrix().T
    Matrix([[1, 1, 0, 1, 0, 0]])

    Parameters
    ==========

    S : 3-vector
        The primary (direction) part.
    S0 : 3-vector
        The dual (moment) part, the moment about the origin O.

    See Also
    ========

    screwsym.line.LineVector, screwsym.twist.Twist, screwsym.wrench.Wrench
    """

    __slots__ = ()

    # above Matrix's 10.01, so ``Matrix * screw`` defers to Screw.__rmul__ (which refuses)
    _op_priority = 20.0
    # NumPy defers to Screw.__rmul__ (which refuses arrays) instead of broadcasting over it
    __array_ufunc__ = None

    #: names of the two parts, used in error messages and printing
    _part_names: tuple[str, str] = ("S", "S0")

    def __new__(cls, S: VectorLike, S0: VectorLike):
        S = check_vector(S, cls._part_names[0])
        S0 = check_vector(S0, cls._part_names[1])
        cls._check_parts(S, S0)
        return ScrewsymBasic.__new__(cls, S, S0)

    @classmethod
    def _check_parts(cls, S: ImmutableMatrix, S0: ImmutableMatrix) -> None:
        """Subclasses that constrain ``(S; S0)`` raise here."""

    # ----------------------------------------------------------------- parts
    @property
    def S(self) -> ImmutableMatrix:
        """The primary (direction) part, a 3x1 ``ImmutableMatrix``."""
        return self.args[0]

    @property
    def S0(self) -> ImmutableMatrix:
        """The dual (moment) part about the origin, a 3x1 ``ImmutableMatrix``."""
        return self.args[1]

    def as_matrix(self) -> ImmutableMatrix:
        """The 6x1 column ``[S; S0]`` in the book's ray order."""
        return ImmutableMatrix.vstack(self.S, self.S0)

    @classmethod
    def from_matrix(cls, M: Any, *, name: str = "M"):
        """Build a screw from a 6-vector ``[S; S0]`` (6x1, 1x6, list or tuple).

        >>> Screw.from_matrix([1, 0, 0, 0, 1, 0])
        Screw([1, 0, 0], [0, 1, 0])
        """
        S_, S0_ = check_six(M, name)
        return cls(S_, S0_)

    @classmethod
    def from_axis(cls, r: VectorLike, S: VectorLike, h: Any):
        r"""The screw of pitch ``h`` on the axis through ``r`` along ``S`` (1.38).

        ``$ = (S; r x S + h S)``.  Use :meth:`couple` for an infinite pitch.

        >>> from screwsym import Screw, vector
        >>> from sympy import symbols
        >>> h = symbols("h", real=True)
        >>> s = Screw.from_axis([0, 1, 0], [1, 0, 0], h)
        >>> s
        Screw([1, 0, 0], [h, 0, -1])
        >>> s.pitch
        h
        """
        r = check_vector(r, "r")
        S_ = check_vector(S, "S")
        h = check_scalar(h, "h")
        if h.is_infinite:
            raise ValueError("h: expected a finite pitch; build a couple with couple(C)")
        return cls(S_, r.cross(S_) + h * S_)

    @classmethod
    def couple(cls, C: VectorLike):
        """The couple ``(0; C)``: a screw of infinite pitch, a free vector.

        >>> Screw.couple([0, 0, 5]).pitch
        oo
        """
        return cls(zeros(3, 1), check_vector(C, "C"))

    # --------------------------------------------------- derived quantities
    @property
    def pitch(self) -> Expr:
        """The pitch ``h = S.S0 / S.S`` (1.34); see :func:`pitch`."""
        return pitch(self)

    @property
    def axis(self):
        """The axis line vector ``(S; S0 - h S)`` (1.36); see :func:`axis`."""
        return axis(self)

    @property
    def foot(self) -> ImmutableMatrix:
        """The point of the axis nearest the origin (1.16); see :func:`foot`."""
        return foot(self)

    @property
    def distance_to_origin(self) -> Expr:
        """Distance from the origin to the axis (1.18); see :func:`distance_to_origin`."""
        return distance_to_origin(self)

    @property
    def direction_cosines(self) -> ImmutableMatrix:
        """``S / |S|`` (1.5); see :func:`direction_cosines`."""
        return direction_cosines(self)

    def classify(self) -> str | None:
        """``'line'``, ``'couple'``, ``'screw'``, ``'zero'`` or None; see :func:`classify`."""
        return classify(self)

    def decompose(self):
        """Axis line vector plus parallel couple (1.37); see :func:`decompose`."""
        return decompose(self)

    def shift_origin(self, A: VectorLike):
        """The same screw with its moment taken about ``A`` (1.32); see :func:`shift_origin`."""
        return shift_origin(self, A)

    def reciprocal_product(self, other: ScrewLike) -> Expr:
        """``S1.S2^0 + S2.S1^0`` (1.45); see :func:`reciprocal_product`."""
        return reciprocal_product(self, other)

    def is_reciprocal(self, other: ScrewLike) -> bool | None:
        """Whether the reciprocal product vanishes; see :func:`is_reciprocal`."""
        return is_reciprocal(self, other)

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
        other = check_screw(other, "other")
        return is_zero_vector(self.as_matrix() - other.as_matrix())

    # ------------------------------------------------------------ algebra
    def _general_class(self) -> type:
        """The class of a linear combination: a line vector's is the general screw."""
        from .line import LineVector

        return Screw if isinstance(self, LineVector) else type(self)

    def __add__(self, other):
        """``$1 + $2 = (S1 + S2; S1^0 + S2^0)`` (1.39)."""
        if not isinstance(other, Screw):
            return NotImplemented
        cls = _sum_class(self, other)
        return cls(self.S + other.S, self.S0 + other.S0)

    def __sub__(self, other):
        if not isinstance(other, Screw):
            return NotImplemented
        return self + (-other)

    def __neg__(self):
        return type(self)(-self.S, -self.S0)

    def __pos__(self):
        return self

    def __mul__(self, k):
        """``lambda $ = (lambda S; lambda S0)`` (1.44)."""
        if isinstance(k, Screw):
            raise TypeError(
                "cannot multiply two screws with '*'; for the reciprocal product (1.45) "
                "use reciprocal_product(s1, s2)"
            )
        k = check_scalar(k, "k")
        cls = type(self)
        if cls is not self._general_class() and is_zero(k) is True:
            cls = Screw  # 0 times a line vector is the zero screw, not a line
        return cls(k * self.S, k * self.S0)

    __rmul__ = __mul__

    def __truediv__(self, k):
        return self * (S.One / check_scalar(k, "k", nonzero=True))

    # ------------------------------------------------ SymPy integration
    def _apply(self, f, cls=None):
        cls = type(self) if cls is None else cls
        return cls(f(self.S), f(self.S0))

    def _eval_simplify(self, **kwargs):
        return self._apply(lambda m: m.simplify(**kwargs))

    def _eval_diff_parts(self, *symbols, **kwargs):
        """Differentiate both parts: ``d$/dt = (dS/dt; dS0/dt)``.

        The derivative of a line vector is in general not a line vector, so it
        comes back as a :class:`Screw`.

        >>> from sympy import symbols
        >>> t = symbols("t", real=True)
        >>> Screw([t, 0, 0], [0, t**2, 0]).diff(t)
        Screw([1, 0, 0], [0, 2*t, 0])
        """
        return self._apply(lambda m: m.diff(*symbols, **kwargs), self._general_class())

    def _eval_evalf_parts(self, n: int = 15, **options):
        """Evaluate both parts numerically to ``n`` digits."""
        return self._apply(lambda m: m.evalf(n, **options))

    def expand(self, **hints):
        """Expand every component."""
        return self._apply(lambda m: m.expand(**hints))

    def applyfunc(self, f):
        """Apply ``f`` to every one of the six components (e.g. ``cancel``)."""
        return self._apply(lambda m: m.applyfunc(f))

    # ------------------------------------------------------------ printing
    def _sympystr(self, printer) -> str:
        parts = ", ".join(
            "[" + ", ".join(printer._print(e) for e in part) + "]" for part in self.args
        )
        return f"{type(self).__name__}({parts})"

    def _latex(self, printer) -> str:
        from .printing import latex_screw

        return latex_screw(self, printer)

    def _pretty(self, printer):
        from .printing import pretty_screw

        return pretty_screw(self, printer)


def _sum_class(a: Screw, b: Screw) -> type:
    """Class of ``a + b``: twists add to a twist, wrenches to a wrench.

    A twist and a wrench cannot be added: one is a motion, the other a force.
    """
    from .twist import Twist
    from .wrench import Wrench

    kinds = {c for c in (Twist, Wrench) for x in (a, b) if isinstance(x, c)}
    if len(kinds) == 2:
        raise TypeError(
            f"cannot add a {type(a).__name__} and a {type(b).__name__}: "
            "a twist is a motion and a wrench a force system"
        )
    return kinds.pop() if kinds else Screw


# --------------------------------------------------------------------------
# The chapter's operations, each written once.
# --------------------------------------------------------------------------


def _decided_couple(s: Screw) -> bool:
    """True when ``S`` is provably zero (a couple or the zero screw)."""
    return is_zero_vector(s.S) is True


def pitch(s: ScrewLike) -> Expr:
    r"""The pitch of a screw, ``h = S . S0 / S . S`` (1.34).

    Explanation
    ===========

    The pitch does not depend on the origin (1.33).  A couple ``(0; C)`` has
    infinite pitch and gives ``oo``; the zero screw has none and raises
    ``ValueError``.  With symbols the formula is returned as it stands.

    Examples
    ========

    >>> from screwsym import Screw, pitch
    >>> pitch(Screw([1, 0, 0], [1, 0, 0]))         # Example 1.2
    1
    >>> pitch([1, 1, 0, 1, 0, 0])                  # Example 1.4, as a 6-vector
    1/2
    >>> pitch(Screw.couple([0, 0, 1]))
    oo

    See Also
    ========

    axis, classify
    """
    s = check_screw(s, "s")
    if _decided_couple(s):
        if is_zero_vector(s.S0) is True:
            raise ValueError("s: the zero screw (0; 0) has no pitch")
        return oo
    return _pitch_formula(s)


def _pitch_formula(s: Screw) -> Expr:
    """``S . S0 / S . S`` (1.34), for a screw already known not to be a couple."""
    return s.S.dot(s.S0) / s.S.dot(s.S)


def _axis_moment(s: Screw, h: Expr) -> ImmutableMatrix:
    """``S0 - h S``, the moment of the axis line (1.35), given the pitch ``h``."""
    return s.S0 - h * s.S


def _require_axis(s: Screw, what: str) -> None:
    if _decided_couple(s):
        raise ValueError(f"s: a couple (0; C) has no {what}: its axis lies at infinity; got {s}")


def axis(s: ScrewLike):
    r"""The axis of a screw as a line vector ``(S; S0 - h S)`` (1.36, 1.37).

    The axis has the screw's direction and pitch 0.  A couple has no axis in
    finite space and raises ``ValueError``.

    Examples
    ========

    >>> from screwsym import Screw, axis
    >>> axis(Screw([1, 1, 0], [1, 0, 0]))           # Example 1.4
    LineVector([1, 1, 0], [1/2, -1/2, 0])
    """
    from .line import LineVector

    s = check_screw(s, "s")
    _require_axis(s, "axis")
    return LineVector(s.S, _axis_moment(s, _pitch_formula(s)))


def foot(s: ScrewLike) -> ImmutableMatrix:
    r"""The point of the line (or screw axis) nearest the origin, ``P = S x S0 / S.S`` (1.16).

    For a screw the same formula gives the foot of its axis, since
    ``S x (h S) = 0`` (1.36).

    Examples
    ========

    >>> from screwsym import LineVector, foot
    >>> foot(LineVector.through([1, 2, 3], [1, 2, 4])).T
    Matrix([[1, 2, 0]])
    """
    s = check_screw(s, "s")
    _require_axis(s, "foot point")
    return s.S.cross(s.S0) / s.S.dot(s.S)


def distance_to_origin(s: ScrewLike) -> Expr:
    r"""Distance from the origin to the line or screw axis, ``|P|`` (1.17, 1.18).

    Computed as ``|S x S0| / (S . S)``, which for a line vector equals the
    book's ``|S0| / |S|`` (1.18).

    >>> from screwsym import LineVector, distance_to_origin
    >>> distance_to_origin(LineVector.through([3, 4, 0], [3, 4, 1]))
    5
    """
    P = foot(s)
    return sqrt(P.dot(P))


def direction_cosines(s: ScrewLike) -> ImmutableMatrix:
    r"""The direction cosines ``(l, m, n) = S / |S|`` (1.5).

    >>> from screwsym import LineVector, direction_cosines
    >>> direction_cosines(LineVector.through([0, 0, 0], [2, 0, 0])).T
    Matrix([[1, 0, 0]])
    """
    s = check_screw(s, "s")
    _require_axis(s, "direction")
    return s.S / sqrt(s.S.dot(s.S))


def decompose(s: ScrewLike):
    r"""Split a screw into its axis line vector and a parallel couple (1.37).

    ``(S; S0) = (S; S0 - h S) + (0; h S)``.  Returns the pair
    ``(line, couple)``; for a twist these are a rotation and a translation
    (both :class:`~screwsym.twist.Twist`), for a wrench a force and a couple
    (both :class:`~screwsym.wrench.Wrench`).

    >>> from screwsym import Screw, decompose
    >>> line, couple = decompose(Screw([1, 1, 0], [1, 0, 0]))
    >>> line, couple
    (LineVector([1, 1, 0], [1/2, -1/2, 0]), Screw([0, 0, 0], [1/2, 1/2, 0]))
    >>> line + couple
    Screw([1, 1, 0], [1, 0, 0])
    """
    from .line import LineVector

    s = check_screw(s, "s")
    _require_axis(s, "axis, so no line-plus-couple decomposition")
    general = s._general_class()
    line_cls = LineVector if general is Screw else general
    h = _pitch_formula(s)
    return line_cls(s.S, _axis_moment(s, h)), general(zeros(3, 1), h * s.S)


def classify(s: ScrewLike) -> str | None:
    r"""Classify a screw as in the table at the end of Section 1.4.2.

    Returns ``'line'`` (``S != 0``, ``S.S0 = 0``, pitch 0), ``'couple'``
    (``S = 0``, ``S0 != 0``, pitch ``oo``), ``'screw'`` (``S.S0 != 0``),
    ``'zero'`` for ``(0; 0)``, or None when the symbols do not decide.

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
    s = check_screw(s, "s")
    S_zero = is_zero_vector(s.S)
    if S_zero is True:
        S0_zero = is_zero_vector(s.S0)
        return None if S0_zero is None else ("zero" if S0_zero else "couple")
    if S_zero is None:
        return None
    dot_zero = is_zero(s.S.dot(s.S0))
    return None if dot_zero is None else ("line" if dot_zero else "screw")


def shift_origin(s: ScrewLike, A: VectorLike):
    r"""The same screw with its dual part taken about the point ``A`` (1.32).

    ``S^A = S^0 + AO x S = S^0 - A x S``, where ``A`` is the position of the
    new origin in the old frame.  ``S`` and the pitch do not change (1.33).

    Examples
    ========

    >>> from screwsym import Screw, shift_origin
    >>> s = Screw.from_axis([0, 1, 0], [1, 0, 0], 2)
    >>> shift_origin(s, [0, 1, 0])                   # A on the axis: (S; hS)
    Screw([1, 0, 0], [2, 0, 0])
    """
    s = check_screw(s, "s")
    A = check_vector(A, "A")
    return type(s)(s.S, s.S0 - A.cross(s.S))


def reciprocal_product(s1: ScrewLike, s2: ScrewLike) -> Expr:
    r"""The reciprocal product ``$1 o $2 = S1 . S2^0 + S2 . S1^0`` (1.45).

    For two line vectors it is their mutual moment (1.23); for a twist and a
    wrench it is the power (see :func:`screwsym.wrench.power`).  It does not
    depend on the origin (1.47).

    Examples
    ========

    >>> from screwsym import Screw, reciprocal_product
    >>> reciprocal_product(Screw([1, 0, 0], [0, 0, 0]), Screw([0, 1, 0], [0, 0, 1]))
    0
    >>> reciprocal_product([1, 1, 0, 1, 0, 0], [1, 1, 0, 1, 0, 0])
    2
    """
    s1 = check_screw(s1, "s1")
    s2 = check_screw(s2, "s2")
    return s1.S.dot(s2.S0) + s2.S.dot(s1.S0)


def is_reciprocal(s1: ScrewLike, s2: ScrewLike) -> bool | None:
    r"""Whether ``$1 o $2 = 0`` (1.45): True, False, or None when the symbols do not decide.

    >>> from screwsym import Screw, is_reciprocal
    >>> is_reciprocal(Screw([1, 0, 0], [0, 0, 0]), Screw([0, 1, 0], [0, 0, 1]))
    True
    """
    return is_zero(reciprocal_product(s1, s2))
