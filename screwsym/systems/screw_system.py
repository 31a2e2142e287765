r"""Screw systems: the span of a set of screws, its reciprocal system and its singular cases.

A *screw system* is the linear span of screws (twists or wrenches), written as
the 6 x n matrix of their columns in the book's ray order ``(S; S0)``.  Its
*reciprocal system* is the set of screws whose reciprocal product (1.45)

    $1 o $2 = S1 . S2^0 + S2 . S1^0 = x^T Delta y,   Delta = [[0, I], [I, 0]]

with every member is zero (1.46, 1.47): the null space of ``(Delta A)^T``, that
is of ``A^T`` with its two halves swapped.  The reciprocal of the twists of a
kinematic chain are the wrenches it transmits (its constraints); the reciprocal
of the constraints on a platform are its instantaneous motions.

Everything is exact.  The entries are taken as polynomials (rational functions
are brought to polynomials column by column) in their symbols, with rational
or algebraic-number coefficients such as ``sqrt(3)``; ``sin(q)`` and ``cos(q)``
of a symbol (after ``expand_trig`` of sums and multiples) are two more ring
symbols, reduced modulo ``sin(q)**2 + cos(q)**2 - 1``.  The arithmetic is
fraction-free over that polynomial ring, so zero is decided exactly and no
``simplify`` is ever called.

*Generic* means: for all values of the symbols outside a proper algebraic
subset, the one that :meth:`ScrewSystem.rank_conditions` lists exhaustively.

References
==========

Huang, Li & Ding, *Theory of Parallel Mechanisms*, Springer 2013, Sections 1.5
(reciprocity), Chapters 2 and 5 (screw systems, constraints, mobility).
"""

from __future__ import annotations

import math
import random
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass
from functools import lru_cache
from itertools import combinations
from math import gcd, lcm
from typing import TYPE_CHECKING, Any

from sympy import (
    QQ,
    ZZ,
    Add,
    And,
    CRootOf,
    Dummy,
    Eq,
    ImmutableMatrix,
    Integer,
    Ne,
    Or,
    Poly,
    Pow,
    Symbol,
    cancel,
    cos,
    expand_trig,
    factor_list,
    fraction,
    minimal_polynomial,
    radsimp,
    resultant,
    sin,
    sqrt,
    true,
    zeros,
)
from sympy.core.symbol import Str
from sympy.logic.boolalg import Boolean
from sympy.polys.densearith import dup_rem
from sympy.polys.matrices import DomainMatrix
from sympy.polys.polyutils import _sort_factors, parallel_dict_from_expr

from ..core.basic import ScrewsymBasic
from ..core.checks import check_count, check_exact
from ..core.decide import is_zero
from ..core.formulas import SWAP
from ..core.screw import Screw, ScrewLike, check_screw
from ..core.twist import Twist
from ..core.wrench import Wrench

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["ScrewSystem"]

#: the kinds an empty system can remember, by the name its marker argument holds
_KIND_NAMES: dict[str, type[Screw]] = {"Twist": Twist, "Wrench": Wrench}


def _kind_of(system: ScrewSystem) -> type[Screw] | None:
    """Twist or Wrench when the system is of one, else None (plain screws)."""
    kind = system.kind
    return kind if kind in (Twist, Wrench) else None


#: the kind of the reciprocal system: twists and wrenches are each other's reciprocals
_DUAL_KIND: dict[type[Screw], type[Screw]] = {Twist: Wrench, Wrench: Twist, Screw: Screw}
#: the class a system holds, by the members' ``_kind``
_KINDS: dict[str | None, type[Screw]] = {None: Screw, Twist._kind: Twist, Wrench._kind: Wrench}


def check_screw_system_members(values: Any, name: str, kinds: dict) -> tuple:
    """Return ``values`` as a tuple of screws of one kind: all twists, all wrenches or screws.

    ``kinds`` maps a screw class's ``_kind`` to the class a system of that
    kind holds, ``None`` to the root class (screws and line vectors, which
    mix).  Screw objects are passed through; 6-vectors (S; S0) become the
    kind of the screw objects among them, plain screws if there are none.
    Floats are refused: a screw system decides ranks exactly.

    >>> from screwsym import Screw, Twist, Wrench
    >>> from screwsym.systems.screw_system import check_screw_system_members
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
#: at most this many r x r minors are compared when choosing the one that states a case
_MINOR_BUDGET = 64
#: the default limit on the number of cases of ``rank_conditions``
MAX_CASES = 200
#: the default work budget of one case split (``rank_conditions``, ``reciprocal_cases``,
#: ``substitutions``, ``ParallelMechanism.mobility_cases``): units of polynomial arithmetic,
#: ``k! t_1 ... t_k`` for a k x k determinant whose rows have at most ``t_i`` terms, ``t**2``
#: to factor a polynomial of ``t`` terms (about a microsecond each, measured; see ``_charge``)
BUDGET = 20_000_000


class ScrewSystem(ScrewsymBasic):
    r"""The screw system spanned by ``screws``: twists, wrenches or plain screws.

    Explanation
    ===========

    ``args`` are the member screws, in order; two systems with the same span
    but other members are different objects (compare spans with
    :meth:`contains` or the rank of the union).  Members are all twists, all
    wrenches or all plain screws; 6-vectors in the order ``(S; S0)`` are read
    as plain screws.  The system of no screws is ``ScrewSystem()``.

    ``rank``, :meth:`basis`, :meth:`contains` and :meth:`reciprocal` are
    generic (see the module docstring); :meth:`rank_conditions` and
    :meth:`reciprocal_cases` give the exhaustive case split.

    Examples
    ========

    The three rotations of a spherical joint centred at a symbolic point ``p``
    and the wrenches they transmit, three forces through ``p``: a basis
    polynomial in ``p``, valid for every ``p`` (a hand-made null space gives
    ``p_x/p_z``, which blows up at ``p_z = 0``):

    >>> from screwsym import ScrewSystem, Twist, Wrench, vector
    >>> p = vector("p")
    >>> ball = ScrewSystem(*(Twist.rotation(e, point=p) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])))
    >>> ball.rank
    3
    >>> W = ball.reciprocal()
    >>> W.matrix
    Matrix([
    [   1,    0,    0],
    [   0,    1,    0],
    [   0,    0,    1],
    [   0, -p_z,  p_y],
    [ p_z,    0, -p_x],
    [-p_y,  p_x,    0]])
    >>> W == ScrewSystem(*(Wrench.force(e, point=p) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])))
    True
    >>> ball.rank_conditions()
    [(True, 3)]

    Two revolute axes, parallel to z, through the origin and through ``(a, 0, 0)``:
    the rank drops where the axes coincide, and each case has its own
    reciprocal basis.

    >>> from sympy import symbols
    >>> a = symbols("a", real=True)
    >>> RR = ScrewSystem(Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...                  Twist.rotation([0, 0, 1], point=[a, 0, 0]))
    >>> RR.rank_conditions()
    [(Ne(a, 0), 2), (Eq(a, 0), 1)]
    >>> [(c, w.rank) for c, w in RR.reciprocal_cases()]
    [(Ne(a, 0), 4), (Eq(a, 0), 5)]

    Parameters
    ==========

    *screws : Screw, Twist, Wrench or 6-vector
        The members, all of one kind.

    See Also
    ========

    screwsym.core.screw.reciprocal_product, screwsym.systems.mechanism.Limb

    References
    ==========

    Huang, Li & Ding, Sections 1.5 (1.45)-(1.47) and 2.x (screw systems).
    """

    __slots__ = ()

    def __new__(cls, *screws: ScrewLike, kind: type[Screw] | None = None) -> Self:
        # An empty system keeps its kind as a marker argument, so that ``func(*args)``
        # rebuilds it and its reciprocal is of the dual kind.
        if len(screws) == 1 and isinstance(screws[0], Str):
            marker, screws = screws[0].name, ()
            kind = _KIND_NAMES.get(marker)
            if kind is None:
                raise ValueError(f"screws: expected screws, got the unknown kind marker {marker!r}")
        members = check_screw_system_members(screws, "screws", _KINDS)
        if kind is not None and kind not in _KIND_NAMES.values():
            raise TypeError(f"kind: expected Twist or Wrench, got {kind!r}")
        if members and kind is not None and not isinstance(members[0], kind):
            raise TypeError(
                f"screws: expected members of kind {kind.__name__}, got {type(members[0]).__name__}"
            )
        if not members and kind is not None:
            return ScrewsymBasic.__new__(cls, Str(kind.__name__))
        return ScrewsymBasic.__new__(cls, *members)

    def _eval_diff_parts(self, *symbols: Any, **kwargs: Any) -> ScrewSystem:
        return self.func(*(s.diff(*symbols, **kwargs) for s in self.screws), kind=self._marked_kind)

    def _sympystr(self, printer: Any) -> str:
        marked = self._marked_kind
        if marked is not None:
            return f"ScrewSystem(kind={marked.__name__})"
        return "ScrewSystem(" + ", ".join(printer._print(s) for s in self.screws) + ")"

    def _latex(self, printer: Any) -> str:
        r"""The span of the members, each in the book's notation.

        >>> from sympy import latex
        >>> from screwsym import ScrewSystem, Twist
        >>> print(latex(ScrewSystem(Twist.translation([0, 0, 1]))))
        \operatorname{span}\left\{\left(0 \quad 0 \quad 0;\; 0 \quad 0 \quad 1\right)\right\}
        """
        if not self.screws:
            return r"\left\{0\right\}"
        inner = ",\\; ".join(printer._print(s) for s in self.screws)
        return r"\operatorname{span}\left\{" + inner + r"\right\}"

    # --------------------------------------------------------------- parts
    @property
    def screws(self) -> tuple[Screw, ...]:
        """The member screws, in order."""
        return tuple(a for a in self.args if not isinstance(a, Str))

    @property
    def _marked_kind(self) -> type[Screw] | None:
        """The kind an empty system was built with (``kind=``), else None."""
        if self.args and isinstance(self.args[0], Str):
            return _KIND_NAMES[self.args[0].name]
        return None

    @property
    def kind(self) -> type[Screw]:
        """``Twist`` or ``Wrench`` when the members are (or an empty system was built with
        ``kind=``), else ``Screw``.

        >>> from screwsym import ScrewSystem, Twist, Wrench
        >>> ScrewSystem(kind=Twist).kind, ScrewSystem(kind=Twist).reciprocal().kind
        (<class 'screwsym.core.twist.Twist'>, <class 'screwsym.core.wrench.Wrench'>)
        """
        marked = self._marked_kind
        if marked is not None:
            return marked
        for k in (Twist, Wrench):
            if self.args and isinstance(self.args[0], k):
                return k
        return Screw

    @property
    def matrix(self) -> ImmutableMatrix:
        """The 6 x n matrix whose columns are the members ``(S; S0)``, in order."""
        if not self.screws:
            return ImmutableMatrix(zeros(6, 0))
        return ImmutableMatrix.hstack(*(s.matrix for s in self.screws))

    def __len__(self) -> int:
        return len(self.screws)

    def __iter__(self) -> Iterator[Screw]:
        return iter(self.screws)

    # ----------------------------------------------------------- generic
    @property
    def rank(self) -> int:
        """The generic rank: the dimension of the span for generic values of the symbols."""
        return _analysis(self.matrix).rank

    def basis(self) -> ScrewSystem:
        """Members that span the system generically: the first ones independent at a test point.

        A set of members independent at one rational point is independent for
        generic values, and there are ``rank`` of them, so they are a basis
        (generically; where the rank drops, see :meth:`rank_conditions`).

        >>> from screwsym import ScrewSystem
        >>> ScrewSystem([1, 0, 0, 0, 0, 0], [2, 0, 0, 0, 0, 0], [0, 0, 0, 1, 0, 0]).basis()
        ScrewSystem(Screw([1, 0, 0], [0, 0, 0]), Screw([0, 0, 0], [1, 0, 0]))
        """
        pivots = _analysis(self.matrix).pivots
        return ScrewSystem(*(self.screws[i] for i in pivots), kind=_kind_of(self))

    def contains(self, screw: ScrewLike) -> bool:
        """Whether ``screw`` lies in the span, generically (for generic values of the symbols).

        Exact for numeric systems.  Decided by the generic rank of the system
        with ``screw`` added.

        >>> from screwsym import ScrewSystem
        >>> s = ScrewSystem([1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0])
        >>> s.contains([1, 1, 0, 0, 0, 0]), s.contains([0, 0, 1, 0, 0, 0])
        (True, False)
        """
        s = check_screw(screw, "screw", self.kind)
        if not self.screws:
            return _analysis(ImmutableMatrix(s.matrix)).rank == 0
        return _analysis(self.matrix.row_join(s.matrix)).rank == self.rank

    def union(self, other: ScrewSystem) -> ScrewSystem:
        """The system spanned by the members of both (the sum of the spans).

        >>> from screwsym import ScrewSystem
        >>> (ScrewSystem([1, 0, 0, 0, 0, 0]) | ScrewSystem([0, 1, 0, 0, 0, 0])).rank
        2
        """
        other = _check_system(other, "other")
        kinds = {k for k in (_kind_of(self), _kind_of(other)) if k is not None}
        return ScrewSystem(*self.screws, *other.screws, kind=kinds.pop() if len(kinds) == 1 else None)

    __or__ = union

    def intersection(self, other: ScrewSystem) -> ScrewSystem:
        """The screws in both spans (generically): the reciprocal of the union of the reciprocals.

        >>> from screwsym import ScrewSystem
        >>> a = ScrewSystem([1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0])
        >>> b = ScrewSystem([0, 1, 0, 0, 0, 0], [0, 0, 1, 0, 0, 0])
        >>> (a & b).rank, (a & b).contains([0, 1, 0, 0, 0, 0])
        (1, True)
        """
        other = _check_system(other, "other")
        both = self.reciprocal() | other.reciprocal()
        return both.reciprocal()

    __and__ = intersection

    def reciprocal(self) -> ScrewSystem:
        r"""A basis of the reciprocal system, polynomial in the symbols (1.45)-(1.47).

        Explanation
        ===========

        The screws ``y`` with ``x^T Delta y = 0`` for every member ``x``: the
        null space of the members with their halves swapped.  The basis is
        built by Cramer's rule from a non-zero r x r minor ``m`` (r the rank),
        multiplied through by ``m`` so that no division occurs, then divided by
        the greatest common divisor of its entries.  It is reciprocal to the
        system for *every* value of the symbols, and a basis wherever the
        first case of :meth:`rank_conditions` holds; elsewhere use
        :meth:`reciprocal_cases`.  Twists give wrenches, wrenches twists.

        >>> from screwsym import ScrewSystem, Wrench
        >>> ScrewSystem(Wrench.force([0, 0, 1], point=[0, 0, 0])).reciprocal().rank
        5
        """
        kind: Any = _DUAL_KIND[self.kind]  # a class: hashable, as lru_cache needs
        return _reciprocal_of(self.matrix, kind)

    def rank_conditions(
        self, *, max_cases: int = MAX_CASES, budget: int = BUDGET
    ) -> list[tuple[Boolean, int | None]]:
        r"""Where the rank is what: an exhaustive list of ``(condition, rank)`` pairs.

        Explanation
        ===========

        The first pair is the generic case.  Every real value of the symbols
        satisfies exactly one condition: the special cases of one minor are
        taken factor by factor, each with the earlier factors non-zero.  The
        conditions are SymPy booleans (``Eq``, ``Ne``, ``And``) on irreducible
        factors of the minors of the system, in the user's symbols: the rank
        is at least ``r`` exactly where some r x r minor is non-zero.  Each
        case is found by solving one factor for a symbol in which it is linear
        (splitting off the case where its coefficient vanishes) and analysing
        the system again there.  A factor in one symbol is decided at each of
        its real roots (``real_roots``: rationals, surds, ``CRootOf``), and a
        factor in ``sin(q)`` and ``cos(q)`` of one angle at each of its points
        on the circle (through ``tan(q/2)``, with ``q = pi`` apart), the
        condition then ``Eq(sin(q), s) & Eq(cos(q), c)``.  A sum of squares
        (``(x - 1)**2 + (y - 2)**2``) is zero where each square is.  Factors
        with no real zero are dropped: proved non-zero by the symbols'
        assumptions, positive definite (a positive constant, a one-symbol
        polynomial without real roots, or a quadratic with a positive leading
        coefficient and a positive definite discriminant: ``(x + 2)**2 +
        (y + 2)**2 + 4``), or with no real root or point of the circle.  Where
        a factor ``f`` is in two or more symbols and linear in none (``x**2 -
        y**3 = 2``, ``cos(a) + cos(b) = 1``), the rank on the surface is
        proved modulo ``f`` (no substitution states it; :meth:`substitutions`
        gives ``None``): exactly ``r`` wherever ``f = 0`` and an ``r x r``
        minor ``g`` is non-zero, the minor found at a point of ``f = 0`` over
        a finite field and the rank proved by the normal forms modulo a
        Groebner basis of ``f`` (and the circles).  Where ``g`` vanishes too,
        each factor of ``g`` is imposed and then ``f``; two such equations of a
        plane (two symbols, or angles, between them) meet in finitely many
        points, found from a lex Groebner basis of both (SymPy's ``groebner``)
        and decided one by one.  A case is listed with
        rank ``None`` (at most the rank of the case above it; not analysed
        further) only where two such equations in three or more symbols meet,
        or where no point proves a rank: the cases SymPy's tools here cannot
        decide.  A system with many free symbols can have
        very many cases: past ``max_cases`` a ``ValueError`` says so.  The
        work is bounded too: ``budget`` units of polynomial arithmetic
        (:data:`BUDGET`; a ``k x k`` determinant whose rows have at most
        ``t_1, ..., t_k`` terms costs ``k! t_1 ... t_k``, factoring a
        polynomial of ``t`` terms ``t**2``, about a microsecond each), past
        which a ``ValueError`` names it instead of running for minutes.

        >>> from sympy import Eq, symbols
        >>> from screwsym import ScrewSystem, Twist, Wrench
        >>> t = symbols("t", real=True)
        >>> forces = ScrewSystem(Wrench.force([1, 0, 0], point=[0, 0, 0]),
        ...                      Wrench.force([1, t, 0], point=[0, 0, 1]))
        >>> forces.rank_conditions()
        [(True, 2)]

        Entries in ``sin`` and ``cos``: a planar 3R arm (Lynch & Park, *Modern
        Robotics*, 2017, Section 5.3) is singular exactly where ``sin(q2) = 0``,
        at ``q2 = 0`` and at ``q2 = pi``:

        >>> from sympy import cos, sin
        >>> q1, q2 = symbols("q1 q2", real=True)
        >>> p2 = [cos(q1), sin(q1), 0]
        >>> p3 = [cos(q1) + cos(q1 + q2), sin(q1) + sin(q1 + q2), 0]
        >>> arm = ScrewSystem(*(Twist.rotation([0, 0, 1], point=p) for p in ([0, 0, 0], p2, p3)))
        >>> cases = arm.rank_conditions()
        >>> cases[0]
        (Ne(sin(q2), 0), 3)
        >>> sorted({r for _, r in cases[1:]}), all(c.has(Eq(sin(q2), 0)) for c, _ in cases[1:])
        ([2], True)
        """
        cases = _budgeted_cases(self.matrix, max_cases, budget, "rank_conditions")
        return [(n.condition, n.rank) for n in cases]

    def reciprocal_cases(
        self, *, max_cases: int = MAX_CASES, budget: int = BUDGET
    ) -> list[tuple[Boolean, ScrewSystem | None]]:
        """For each case of :meth:`rank_conditions`, its own basis of the reciprocal system.

        The basis of a case is valid wherever its condition holds; ``None``
        where the rank of the case is ``None``.  ``max_cases`` and ``budget``
        bound the case split as for :meth:`rank_conditions`.

        >>> from sympy import symbols
        >>> from screwsym import ScrewSystem, Twist
        >>> a = symbols("a", real=True)
        >>> RR = ScrewSystem(Twist.rotation([0, 0, 1], point=[0, 0, 0]),
        ...                  Twist.rotation([0, 0, 1], point=[a, 0, 0]))
        >>> [(c, w.rank) for c, w in RR.reciprocal_cases()]
        [(Ne(a, 0), 4), (Eq(a, 0), 5)]
        """
        kind = _DUAL_KIND[self.kind]
        return [
            (n.condition, None if n.rank is None else _basis_system(n, kind))
            for n in _budgeted_cases(self.matrix, max_cases, budget, "reciprocal_cases")
        ]

    def substitutions(
        self, *, max_cases: int = MAX_CASES, budget: int = BUDGET
    ) -> list[tuple[Boolean, dict[Any, Any] | None]]:
        """For each case of :meth:`rank_conditions`, the substitution of symbols that it makes.

        Applying the substitution (``system.xreplace(subs)``) gives a system
        whose generic rank is the case's rank.  ``None`` for a case on a
        surface ``f = 0`` that no substitution states (``f`` in two or more
        symbols, linear in none): its rank is proved modulo ``f`` instead.  At a point of the circle the
        substitution sets ``sin(q)`` and ``cos(q)`` (``{sin(q): 0, cos(q): -1}``,
        not ``q``); where the entries hold ``sin(2*q)`` or ``cos(q + r)``,
        expand them first (``expand_trig``) so that it reaches them.

        >>> from sympy import symbols
        >>> from screwsym import ScrewSystem, Twist
        >>> a = symbols("a", real=True)
        >>> RR = ScrewSystem(Twist.rotation([0, 0, 1], point=[0, 0, 0]),
        ...                  Twist.rotation([0, 0, 1], point=[a, 0, 0]))
        >>> RR.substitutions()
        [(Ne(a, 0), {}), (Eq(a, 0), {a: 0})]
        """
        cases = _budgeted_cases(self.matrix, max_cases, budget, "substitutions")
        return [(n.condition, None if n.relation else dict(n.subs)) for n in cases]


def _check_system(value: Any, name: str) -> ScrewSystem:
    if not isinstance(value, ScrewSystem):
        raise TypeError(f"{name}: expected a ScrewSystem, got {type(value).__name__}")
    return value


# ---------------------------------------------------------------------------
# Exact linear algebra over a polynomial ring
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class _Ring:
    """A system as polynomial columns: ``cols`` (n rows of 6 ring elements) and its ring.

    ``scales``: per column, the polynomial it was multiplied by to clear its denominators
    (``cols[j] = scales[j] * column j`` as functions, on the unit circle of each angle).
    """

    ring: Any
    gens: tuple
    cols: tuple  # one tuple of 6 ring elements per screw (of M.rows elements in general)
    scales: tuple = ()


@lru_cache(maxsize=64)
def _field(numbers: tuple):
    """``QQ``, or the algebraic number field ``QQ<numbers>``."""
    return QQ.algebraic_field(*numbers) if numbers else QQ


def _coefficient(K, c):
    """A SymPy number as an element of ``K``: its rational parts times cached algebraic ones.

    Only the irrational factors (``sqrt(3)``) go through ``K.from_sympy``,
    which computes a minimal polynomial each time and fails on huge rational
    factors (SymPy 1.14: ``zoo is not in any domain``).
    """
    total = K.zero
    for term in Add.make_args(c):
        q, rest = term.as_coeff_Mul()
        total += K.convert(QQ.from_sympy(q)) * (K.one if rest == 1 else _algebraic(K, rest))
    return total


@lru_cache(maxsize=1024)
def _algebraic(K, c):
    return K.from_sympy(c)


def _to_ring(M: ImmutableMatrix) -> _Ring:
    """The columns of ``M`` as polynomials, each column cleared of its denominators.

    A column multiplied by a non-zero polynomial spans the same screw wherever
    that polynomial is non-zero, and where it vanishes the column itself is
    undefined.  ``sin(q)`` and ``cos(q)`` of a symbol ``q`` become two ring
    symbols on the unit circle (see :func:`_trig_entries`); raises
    ``ValueError`` for other entries that are not rational functions of
    symbols (``tan(t)``, ``sqrt(x)``).
    """
    return _to_ring_cached(ImmutableMatrix(M))


# ---------------------------------------------------------------------------
# Trigonometric entries: sin(q) and cos(q) as two ring symbols on the unit circle
# ---------------------------------------------------------------------------
#
# Why s = sin(q), c = cos(q) with s**2 + c**2 = 1, and not t = tan(q/2): the half-angle
# substitution misses q = pi (t infinite) and writes every condition in t, a symbol the
# user never wrote; with s and c the factors of the minors are polynomials in the user's
# own sin(q) and cos(q), and every point of the circle is in the ring's reach.  The ring
# Q[s, c] / (s**2 + c**2 - 1) is an integral domain (the circle's polynomial is
# irreducible), and the polynomial of degree at most 1 in c is the unique normal form of
# a class (c**2 -> 1 - s**2: ``_reduce``), so zero is decided exactly by reducing.  The
# rational points (2t/(1+t**2), (1-t**2)/(1+t**2)) are dense on the circle, so a minor
# non-zero at one of them is a non-zero element, and a rank found there is the generic
# rank.  Factoring a reduced minor in Q[s, c, ...] covers its zeros on the circle (each
# zero is a zero of a factor).  A condition on sin(q) and cos(q) alone is decided at its
# points, found exactly through t (the real roots of the numerator of f(2t/(1+t**2),
# (1-t**2)/(1+t**2))) together with q = pi, which t cannot reach (``_circle_points``).
# A symbol ``q`` that also appears outside sin and cos is never solved for (a condition
# ``q sin(q) = 1`` is not a substitution): such a case is left undecided (None).

#: the ring symbol of ``sin(q)`` or ``cos(q)``, by ``(sin or cos, q)``; and back
_TRIG_SYMBOL: dict[tuple[Any, Any], Dummy] = {}
_TRIG_BACK: dict[Dummy, Any] = {}


def _trig_symbol(f: Any, q: Any) -> Dummy:
    d = _TRIG_SYMBOL.get((f, q))
    if d is None:
        d = Dummy(f"{f.__name__}_{q}", real=True)
        _TRIG_SYMBOL[(f, q)] = d
        _TRIG_BACK[d] = f(q)
    return d


def _trig_normal(e: Any) -> Any:
    """``e`` with sin and cos of sums and integer multiples of symbols expanded (``expand_trig``)."""
    if not e.has(sin, cos) or all(a.args[0].is_Symbol for a in e.atoms(sin, cos)):
        return e
    return expand_trig(e)


def _trig_entries(entries: list) -> list:
    """``entries`` with ``sin(q)``, ``cos(q)`` (``q`` a symbol) replaced by their ring symbols."""
    out = []
    for e in entries:
        e = _trig_normal(e)
        atoms = e.atoms(sin, cos)
        if atoms:
            e = e.xreplace({a: _trig_symbol(a.func, a.args[0]) for a in atoms
                            if a.args[0].is_Symbol})
        out.append(e)
    return out


@lru_cache(maxsize=256)
def _relations(R) -> tuple:
    """``(q, index of cos(q) or None, index of sin(q) or None)`` for each angle in the ring."""
    found: dict[Any, list] = {}
    for i, x in enumerate(R.symbols):
        back = _TRIG_BACK.get(x)
        if back is not None:
            found.setdefault(back.args[0], [None, None])[0 if back.func is cos else 1] = i
    return tuple((q, ci, si) for q, (ci, si) in found.items())


def _reduce(p, R):
    """``p`` reduced modulo ``sin(q)**2 + cos(q)**2 - 1`` for each angle: degree <= 1 in cos(q)."""
    pairs = _relations(R)
    if not pairs or not p:
        return p
    ring = p.ring
    for _, ci, si in pairs:
        if ci is None or si is None:
            continue
        one_minus_s2 = ring.one - ring.gens[si] ** 2
        while True:
            high = {m: v for m, v in p.items() if m[ci] >= 2}
            if not high:
                break
            lowered = ring.from_dict({m[:ci] + (m[ci] - 2,) + m[ci + 1:]: v
                                      for m, v in high.items()})
            p = p - ring.from_dict(high) + lowered * one_minus_s2
    return p


def _on_circle(t: Any) -> tuple:
    """The point ``(sin q, cos q)`` of the unit circle at ``t = tan(q/2)``: every point but ``q = pi``.

    ``(2 t / (1 + t**2), (1 - t**2) / (1 + t**2))``, for a number or a symbol ``t``:
    the rational parametrisation, a bijection of the function field of the circle with
    the rational functions of ``t`` (so a rank over those is the generic rank on the circle).

    >>> from sympy import Rational
    >>> from screwsym.systems.screw_system import _on_circle
    >>> _on_circle(Rational(1, 2))
    (4/5, 3/5)
    """
    return 2 * t / (1 + t**2), (1 - t**2) / (1 + t**2)


def _vanishes(e: Any) -> bool:
    """Whether ``e`` is identically zero: a rational function of symbols and of ``sin(q)``,
    ``cos(q)``, decided in the ring (``sin(q)**2 + cos(q)**2 = 1`` for each angle).

    >>> from sympy import cos, sin, symbols
    >>> from screwsym.systems.screw_system import _vanishes
    >>> q = symbols("q", real=True)
    >>> _vanishes((1 + cos(q)) * (1 - cos(q)) - sin(q)**2), _vanishes(sin(q) - 1)
    (True, False)
    """
    if not e.has(sin, cos, CRootOf):
        return cancel(e) == 0
    # in the ring: over the algebraic field of the CRootOf (cancel would take it for a symbol)
    return not _to_ring(ImmutableMatrix([e])).cols[0][0]


def _circle_normal(e: Any) -> Any:
    """``e`` with its numerator and denominator reduced by ``sin(q)**2 + cos(q)**2 = 1``
    (each of degree at most 1 in ``cos(q)``: the normal form on the circle).

    >>> from sympy import cos, sin, symbols
    >>> from screwsym.systems.screw_system import _circle_normal
    >>> q = symbols("q", real=True)
    >>> _circle_normal(sin(q)**3 + sin(q)*cos(q)**2)
    sin(q)
    """
    if not e.has(sin, cos):
        return e
    rg = _to_ring(ImmutableMatrix([e]))
    return _poly_expr(rg.cols[0][0], rg.ring) / _poly_expr(rg.scales[0], rg.ring)


def _sample_point(R, rnd: random.Random) -> list:
    """A random rational point of the ring's symbols, ``(sin q, cos q)`` on the unit circle."""
    K = R.domain
    point = [K.convert(rnd.randint(-97, 97)) for _ in R.gens]
    for _, ci, si in _relations(R):
        t = QQ(rnd.randint(-97, 97), rnd.randint(1, 97))
        s, c = _on_circle(t)
        if si is not None:
            point[si] = K.convert(s)
        if ci is not None:
            point[ci] = K.convert(c)
    return point


def _circle_simplify(expr: Any) -> Any:
    """``expr`` with ``Eq(sin(q), s) & (Eq(cos(q), c) | Eq(cos(q), -c))`` written ``Eq(sin(q), s)``.

    On the unit circle ``sin(q) = s`` holds at exactly the two points
    ``cos(q) = +-sqrt(1 - s**2)`` (one where ``s = +-1``); likewise with sin and
    cos exchanged.  For merged cases: the points of one factor given as one
    condition.

    >>> from sympy import Eq, cos, sin, symbols
    >>> from screwsym.systems.screw_system import _circle_simplify
    >>> q = symbols("q", real=True)
    >>> _circle_simplify(Eq(sin(q), 0) & (Eq(cos(q), 1) | Eq(cos(q), -1)))
    Eq(sin(q), 0)
    >>> _circle_simplify((Eq(sin(q), 0) & Eq(cos(q), 1)) | (Eq(sin(q), 0) & Eq(cos(q), -1)))
    Eq(sin(q), 0)
    >>> _circle_simplify((Eq(sin(q), 1) & Eq(cos(q), 0)) | (Eq(sin(q), 0) & Eq(cos(q), -1)))
    (Eq(sin(q), 0) & Eq(cos(q), -1)) | (Eq(sin(q), 1) & Eq(cos(q), 0))
    """
    def one(node: Any) -> Any:
        if not isinstance(node, And):
            return node
        args = list(node.args)
        for i, a in enumerate(args):
            if not (isinstance(a, Eq) and isinstance(a.lhs, (sin, cos))):
                continue
            other = cos if isinstance(a.lhs, sin) else sin
            q, value = a.lhs.args[0], a.rhs
            need = {radsimp(cancel(r)) for r in (sqrt(1 - value**2), -sqrt(1 - value**2))}
            for j, b in enumerate(args):
                if j == i or not isinstance(b, Or):
                    continue
                if all(isinstance(e, Eq) and e.lhs == other(q) for e in b.args) and \
                        {radsimp(cancel(e.rhs)) for e in b.args} == need:
                    return And(*(x for k, x in enumerate(args) if k != j))
        return node

    def pairs(node: Any) -> Any:
        if not isinstance(node, Or):
            return node
        args = [set(a.args) if isinstance(a, And) else {a} for a in node.args]
        for i in range(len(args)):
            for j in range(i + 1, len(args)):
                da, db = args[i] - args[j], args[j] - args[i]
                if len(da) != 1 or len(db) != 1:
                    continue
                (x,), (y,) = da, db
                common = args[i] & args[j]
                if not (isinstance(x, Eq) and isinstance(y, Eq) and x.lhs == y.lhs
                        and isinstance(x.lhs, (sin, cos))):
                    continue
                other = cos if isinstance(x.lhs, sin) else sin
                line = [a for a in common if isinstance(a, Eq) and a.lhs == other(x.lhs.args[0])]
                if not line:
                    continue
                value = line[0].rhs
                need = {radsimp(cancel(r)) for r in (sqrt(1 - value**2), -sqrt(1 - value**2))}
                if {radsimp(cancel(x.rhs)), radsimp(cancel(y.rhs))} == need:
                    rest = [And(*a) for k, a in enumerate(args) if k not in (i, j)]
                    return pairs(Or(And(*common), *rest))
        return node

    if not expr.has(sin, cos):
        return expr
    return expr.replace(lambda x: isinstance(x, And), one).replace(
        lambda x: isinstance(x, Or), pairs)


def _rational_parts(entries: list, what: str) -> tuple[list, list, list]:
    """The symbols, the algebraic numbers and the numerators and denominators of ``entries``.

    ``sin(q)`` and ``cos(q)`` of symbols are first replaced by their ring symbols
    (:func:`_trig_entries`).  Raises ``ValueError`` naming ``what`` (``"screws: expected
    entries"``, ...) for an entry that is not a rational function of symbols and of sin
    and cos of symbols with rational or algebraic coefficients.
    """
    entries = _trig_entries(entries)
    syms = sorted(set().union(*(e.free_symbols for e in entries)) if entries else set(), key=str)
    numbers: list = []
    parts = [part for e in entries for part in e.as_numer_denom()]
    if parts:
        _, found = parallel_dict_from_expr(parts)
        for g in found["gens"] if isinstance(found, dict) else found:
            if isinstance(g, Symbol):
                continue
            # a CRootOf of a rational polynomial is algebraic (SymPy 1.13 leaves it None)
            if g.is_number and (g.is_algebraic or isinstance(g, CRootOf)):
                numbers.append(g)
                continue
            raise ValueError(
                f"{what} that are rational functions of symbols and polynomial in sin and "
                f"cos of symbols with rational or algebraic coefficients, got {g} in an entry"
            )
    return syms, numbers, parts


@lru_cache(maxsize=512)
def _to_ring_cached(M: ImmutableMatrix) -> _Ring:
    entries = list(M)
    syms, numbers, parts = _rational_parts(entries, "screws: expected entries")
    K = _field(tuple(sorted(numbers, key=str)))
    gens = tuple(syms) if syms else (Dummy("c"),)
    R = K[gens]
    ring = R.ring
    if entries:
        dicts, _ = parallel_dict_from_expr(parts, gens=gens)
        polys = [ring.from_dict({m: _coefficient(K, c) for m, c in d.items()}) for d in dicts]
    else:
        polys = []
    cols, scales = [], []
    for j in range(M.cols):
        # M is row-major: entry (i, j) is number i * cols + j, its numerator and denominator
        nums = [polys[2 * (i * M.cols + j)] for i in range(M.rows)]
        dens = [polys[2 * (i * M.cols + j) + 1] for i in range(M.rows)]
        if all(d.is_ground for d in dens):
            cols.append(tuple(n if d == 1 else n * K.quo(K.one, d.LC)
                              for n, d in zip(nums, dens, strict=True)))
            scales.append(R.one)
            continue
        den = R.one
        for d in dens:
            den = _alg_lcm(den, d, R) if K.is_Algebraic else R.lcm(den, d)
        cols.append(tuple(n * R.exquo(den, d) for n, d in zip(nums, dens, strict=True)))
        scales.append(den)
    if _relations(R):
        cols = [tuple(_reduce(e, R) for e in col) for col in cols]
        scales = [_reduce(d, R) for d in scales]
    return _Ring(R, tuple(syms), tuple(cols), tuple(scales))


# ---------------------------------------------------------------------------
# Algebraic coefficients (sqrt(3)): the arithmetic through Q[x, theta]
# ---------------------------------------------------------------------------
#
# Over K = Q(theta) (``QQ<sqrt(3)>``) SymPy's polynomials carry ANP coefficients, and its
# determinants (Berkowitz), gcds (dense subresultant PRS) and factorisations (Trager,
# whose gcds are those PRS) are slow: profiled on Tsai's 3-RPS at a symbolic pose, 316 s
# of factoring one 6 x 6 determinant of degree 12 (not finished) and about 20 s of gcds.
# Here an element of K[x] is lifted to Q[x, theta] (theta one more symbol, degree below
# that of its minimal polynomial ``mp``); the map back, reduction modulo ``mp``, is a ring
# homomorphism, so a determinant computed in Q[x, theta] and reduced is the determinant
# over K exactly.  Factors and gcds are SymPy's own answers (the unique monic ones, in
# SymPy's order), found by cheaper routes where a proof is at hand and by SymPy otherwise.

@lru_cache(maxsize=64)
def _lift_ring(R):
    """``Q[x, theta]`` for the ring ``R = Q(theta)[x]`` (theta the last symbol)."""
    return QQ[tuple(R.symbols) + (Dummy("theta"),)]


def _lift(p, R):
    """The element ``p`` of ``Q(theta)[x]`` as a polynomial of ``Q[x, theta]``."""
    L = _lift_ring(R)
    d = {}
    for m, c in p.items():
        rep = c.to_list()
        top = len(rep) - 1
        for i, q in enumerate(rep):
            if q:
                d[m + (top - i,)] = q
    return L.ring.from_dict(d) if d else L.zero


def _drop(P, R):
    """``P`` of ``Q[x, theta]`` reduced modulo the minimal polynomial: an element of ``R``."""
    K = R.domain
    mod = K.mod.to_list()
    groups: dict = {}
    for m, c in P.items():
        groups.setdefault(m[:-1], {})[m[-1]] = c
    out = {}
    for m, cs in groups.items():
        rep = [cs.get(k, QQ.zero) for k in range(max(cs), -1, -1)]
        if len(rep) >= len(mod):
            rep = dup_rem(rep, mod, QQ)
        if rep:
            out[m] = K.new(rep)
    return R.ring.from_dict(out) if out else R.zero


def _theta_parts(P, R) -> list:
    """The coefficients of ``theta**0, theta**1, ...`` in ``P`` (``Q[x, theta]``), as polynomials
    there (up to the highest power present)."""
    L = _lift_ring(R).ring
    parts: dict = {}
    for m, c in P.items():
        parts.setdefault(m[-1], {})[m[:-1] + (0,)] = c
    top = max(parts, default=-1)
    return [L.from_dict(parts[k]) if k in parts else L.zero for k in range(top + 1)]


def _norm(P, R):
    """``Res_theta(P, mp)``: a polynomial of ``Q[x]`` (in ``Q[x, theta]``) that vanishes where
    ``P`` or one of its conjugates does."""
    L = _lift_ring(R)
    mod = R.domain.mod.to_list()
    if len(mod) == 3 and P.degree(len(R.symbols)) <= 1:
        # mp = t**2 + a t + b, P = u + v t: (u + v t1)(u + v t2) = u**2 - a u v + b v**2
        u, v = (_theta_parts(P, R) + [L.zero, L.zero])[:2]
        a, b = mod[1], mod[2]
        return u**2 - u * v * a + v**2 * b
    t = L.gens[-1]
    m = L.zero
    for k, c in enumerate(reversed(mod)):
        m += c * t**k
    # the resultant in theta: theta first
    gens = (L.symbols[-1], *L.symbols[:-1])
    S = QQ[gens]
    perm = lambda e: e[-1:] + e[:-1]  # noqa: E731
    Ps = S.ring.from_dict({perm(k): v for k, v in P.items()})
    ms = S.ring.from_dict({perm(k): v for k, v in m.items()})
    r = Ps.resultant(ms)
    if not r:
        return L.zero
    # SymPy returns the resultant in the ring without theta (or, in older versions, with it)
    drop = 1 if len(next(iter(r.keys()))) == len(gens) else 0
    return L.ring.from_dict({k[drop:] + (0,): v for k, v in r.items()})


def _alg_gcd(a, b, R):
    """``R.gcd(a, b)`` over an algebraic field: the monic gcd, by SymPy's PRS only where needed.

    Both rational (no theta): the gcd over Q is the gcd over K.  Norms coprime over
    Q: the gcd is 1 (a common factor ``h`` would give the common factor ``N(h)``).
    """
    if not a or not b or len(a) == 1 or len(b) == 1:
        return R.gcd(a, b)
    A, B = _lift(a, R), _lift(b, R)
    i = len(R.symbols)
    if A.degree(i) <= 0 and B.degree(i) <= 0:
        g = A.gcd(B)
        return _drop(g, R).monic()
    if _norm(A, R).gcd(_norm(B, R)).is_ground:
        return R.one
    return R.gcd(a, b)


def _alg_lcm(a, b, R):
    """``R.lcm(a, b)`` (SymPy's formula over a field) with the gcd of :func:`_alg_gcd`."""
    return (a * b).quo(_alg_gcd(a, b, R)).monic()


def _gcd_of(a, b, R):
    return _alg_gcd(a, b, R) if R.domain.is_Algebraic else R.gcd(a, b)


def _irreducible_over_field(g, R, seed: int = 0, tries: int = 4) -> bool:
    """True if ``g`` (in ``Q[x, theta]`` without theta, irreducible over Q) is proved irreducible
    over the algebraic field of ``R``; False: not proved.

    Such a ``g`` has no content over K in any of its symbols (a factor ``c`` of the content
    would bring its conjugates, and their product, a rational factor of ``g``), so a
    specialisation of the other symbols to integers that keeps the degree in one symbol
    and is irreducible over K (a univariate factorisation) proves ``g`` irreducible over K.
    """
    L = _lift_ring(R)
    n = len(R.symbols)
    involved = [i for i in range(n) if g.degree(i) > 0]
    if not involved:
        return True
    x = max(involved, key=lambda i: g.degree(i))
    others = [i for i in involved if i != x]
    lead = g.coeff_wrt(L.gens[x], g.degree(x))
    rnd = random.Random(seed)
    K = R.domain
    for _ in range(tries):
        point = {i: rnd.randint(-9, 9) for i in others}
        if others:
            at = [(L.gens[i], QQ(point[i])) for i in others]
            if not lead.evaluate(at):
                continue
            u = g.evaluate(at)
        else:
            u = g
        expr = u.as_expr()
        poly = Poly(expr, L.symbols[x], domain=K)
        _, fl = poly.factor_list()
        if len(fl) == 1 and fl[0][1] == 1:
            return True
        if not others:
            return False
    return False


def _factor_list(p, R) -> list:
    """``p.factor_list()[1]``: the irreducible factors with their multiplicities, SymPy's order.

    Over an algebraic field K, lifted to ``Q[x, theta]``: ``p = c * F`` with ``c`` the
    content over ``Q[x]`` of the coefficients of the powers of theta and ``F`` primitive.
    The factors of ``c`` over Q, each proved irreducible over K
    (:func:`_irreducible_over_field`), and ``F``, proved irreducible over K by its norm being
    irreducible over Q (a factorisation over K is one of the norm), are the factors over K
    (made monic, as SymPy's).  Where a proof fails, SymPy factors ``p`` over K.
    """
    if not R.domain.is_Algebraic:
        return p.factor_list()[1]
    P = _lift(p, R)
    i = len(R.symbols)
    parts = [e for e in _theta_parts(P, R) if e]
    c = parts[0]
    for e in parts[1:]:
        c = c.gcd(e)
    F = P.exquo(c)
    out = []
    if not c.is_ground:
        for g, k in c.factor_list()[1]:
            if g.is_ground:
                continue
            if not _irreducible_over_field(g, R):
                return p.factor_list()[1]
            out.append((_drop(g, R).monic(), k))
    if F.degree(i) > 0:
        fl = [(g, k) for g, k in _norm(F, R).factor_list()[1] if not g.is_ground]
        if len(fl) != 1 or fl[0][1] != 1:
            return p.factor_list()[1]
        out.append((_drop(F, R).monic(), 1))
    ring = R.ring
    dense = [(f.to_dense(), k) for f, k in out]
    return [(ring.from_dense(f), k) for f, k in _sort_factors(dense)]


def _dm(rows, R) -> DomainMatrix:
    rows = [list(r) for r in rows]
    ncols = len(rows[0]) if rows else 0
    return DomainMatrix(rows, (len(rows), ncols), R)


def _det(rows, R):
    """The determinant of a small square matrix of polynomials.

    Division-free where division is dear: cofactor expansion up to 3 x 3, and
    Berkowitz (``charpoly``) over algebraic number fields, where the exact
    divisions of fraction-free elimination cost a polynomial inversion per
    coefficient (measured: 1.5 s against 14 s for a dense 5 x 5).
    """
    n = len(rows)
    if n == 0:
        return R.one
    _charge(math.factorial(n) * math.prod(max((len(e.terms()) for e in r), default=1) or 1
                                          for r in rows))
    return _reduce(_det_unreduced(rows, R, n), R)


def _det_unreduced(rows, R, n):
    if n == 1:
        return rows[0][0]
    if R.domain.is_Algebraic:
        return _det_integer(rows, R)
    if n == 2:
        return rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0]
    if n == 3:
        (a, b, c), (d, e, f), (g, h, i) = rows
        return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    K = R.domain
    if K.is_QQ or K.is_ZZ or K.is_Algebraic:
        return _det_integer(rows, R)
    M = _dm(rows, R)
    return M.charpoly()[-1] * (-1) ** n


@lru_cache(maxsize=64)
def _integer_ring(symbols: tuple):
    return ZZ[symbols]


def _det_integer(rows, R):
    """The determinant of polynomial rows over Q or an algebraic field, through ``Z[x]``.

    Over ``Q(theta)`` the rows are lifted to ``Q[x, theta]`` (:func:`_lift`) and the result
    reduced; each row is multiplied by the common denominator of its coefficients, and
    the determinant over ``Z[x]`` by Laplace expansion with its minors shared
    (:func:`_det_laplace`: ``n 2**(n-1)`` products, no division) divided by their product.
    Measured on the 5 x 5 minors of a 3-RPS leg at a symbolic pose over ``Q(sqrt 3)``:
    2 ms, against 124 ms for SymPy's fraction-free elimination over ``Q[x, theta]`` and
    seconds for Berkowitz over ``Q(sqrt 3)[x]``.
    """
    K = R.domain
    if K.is_Algebraic:
        base = _lift_ring(R)
        rows = [[_lift(e, R) for e in r] for r in rows]
    else:
        base = R
    if base.domain.is_ZZ:
        return _det_laplace(rows, base.ring)
    Z = _integer_ring(tuple(base.symbols))
    scale = 1
    zrows = []
    for r in rows:
        den = 1
        for e in r:
            for c in e.values():
                den = lcm(den, int(c.denominator))
        scale *= den
        zrows.append([Z.ring.from_dict({m: int(c.numerator) * (den // int(c.denominator))
                                        for m, c in e.items()}) if e else Z.zero for e in r])
    d = _det_laplace(zrows, Z.ring)
    out = base.ring.from_dict({m: QQ(int(c), scale) for m, c in d.items()}) if d else base.zero
    return _drop(out, R) if K.is_Algebraic else out


def _det_laplace(rows, ring):
    """The determinant by Laplace expansion along the rows, each minor computed once."""
    n = len(rows)
    # the minors of the last rows, by the set of their columns (a bit mask)
    prev = {1 << j: e for j, e in enumerate(rows[n - 1]) if e}
    for k in range(n - 2, -1, -1):
        row = rows[k]
        cur: dict = {}
        for mask, minor in prev.items():
            for j in range(n):
                if mask >> j & 1 or not row[j]:
                    continue
                term = row[j] * minor
                if bin(mask & ((1 << j) - 1)).count("1") % 2:
                    term = -term
                new = mask | 1 << j
                cur[new] = cur[new] + term if new in cur else term
        prev = {m: v for m, v in cur.items() if v}
        if not prev:
            return ring.zero
    return prev.get((1 << n) - 1, ring.zero)


def _swap(col: tuple) -> tuple:
    """A screw's row of ``(Delta A)^T``: its two halves swapped (1.45), by the one ``SWAP``."""
    return tuple(col[i] for i in SWAP)


@dataclass(frozen=True)
class _Analysis:
    rank: int
    pivots: tuple  # the first independent members
    cols: tuple  # coordinates (of the swapped rows) of a non-zero minor on the pivots


#: the points (seeds) at which a rank is first found, then proved for all values
_SEEDS = (1, 2, 3)


def _cramer(B, rows, cols, R, m=None, width: int = 6) -> list:
    """Null vectors of the rows ``B[rows]`` by Cramer's rule on the minor ``(rows, cols)``.

    Each is multiplied through by the minor ``m``, so it is polynomial; they
    are independent wherever ``m`` is non-zero.  ``width``: the length of the rows.
    """
    if m is None:
        m = _det([[B[i][j] for j in cols] for i in rows], R)
    vectors = []
    for k in range(width):
        if k in cols:
            continue
        v = [R.zero] * width
        v[k] = m
        for jj, j in enumerate(cols):
            replaced = [[B[i][k] if c == jj else B[i][cc] for c, cc in enumerate(cols)]
                        for i in rows]
            v[j] = -_det(replaced, R)
        vectors.append(v)
    return vectors


def _proved_at(B: list, R: Any, seed: int, skip_zero: bool) -> _Analysis | None:
    """The rank found at the seeded rational point and proved for every value; None if not.

    The independent members and the minor are those of the point; the rank is
    proved when the vectors of Cramer's rule on that minor are reciprocal to
    every member identically.  ``skip_zero``: a point where every entry vanishes
    proves nothing (None) instead of being tried as rank 0.
    """
    K = R.domain
    point = _sample_point(R, random.Random(seed))
    B0 = DomainMatrix([[b(*point) if b else K.zero for b in row] for row in B], (len(B), 6), K)
    _, rows = B0.transpose().rref()
    if not rows and skip_zero:
        return None
    _, cols = B0.extract(list(rows), list(range(6))).rref() if rows else (None, ())
    if all(
        not _reduce(sum((b * x for b, x in zip(B[i], v, strict=True)), R.zero), R)
        for v in _cramer(B, rows, cols, R)
        for i in range(len(B))
        if i not in rows
    ):
        return _Analysis(len(rows), tuple(rows), tuple(cols))
    return None


@lru_cache(maxsize=512)
def _analysis(M: ImmutableMatrix) -> _Analysis:
    """The generic rank, the first independent members and a minor that proves the rank.

    The rank ``r`` is found at a rational point (a non-zero minor there is a
    non-zero polynomial, so the generic rank is at least ``r``) and proved:
    the ``6 - r`` vectors Cramer's rule builds from that minor are checked to
    be reciprocal to *every* member identically, so the rank is at most
    ``r``.  If the check fails (an unlucky point) the next point is tried,
    and in the end fraction-free elimination over the polynomial ring decides.
    """
    if M.cols == 0:
        return _Analysis(0, (), ())
    rg = _to_ring(M)
    R = rg.ring
    B = [_swap(c) for c in rg.cols]
    for seed in _SEEDS:
        found = _proved_at(B, R, seed, skip_zero=True)
        if found is not None:
            return found
    if _relations(R):  # pragma: no cover - unlucky points on the circle: more of them
        for seed in range(len(_SEEDS) + 1, 64):
            found = _proved_at(B, R, seed, skip_zero=False)
            if found is not None:
                return found
        raise RuntimeError("rank: no point on the circle proved the rank")  # pragma: no cover
    A = _dm([[c[i] for c in rg.cols] for i in range(6)], R)  # pragma: no cover - unlucky points
    _, _, pivots = A.rref_den()  # pragma: no cover
    if not pivots:  # pragma: no cover
        return _Analysis(0, (), ())
    Bp = _dm([B[i] for i in pivots], R)  # pragma: no cover
    _, _, cols = Bp.rref_den()  # pragma: no cover
    return _Analysis(len(pivots), tuple(pivots), tuple(cols))  # pragma: no cover


def _pure_translations(T: ImmutableMatrix, rotations: int) -> ImmutableMatrix:
    """The ``v`` parts of a basis of the twists in the span of ``T`` with ``omega = 0``, generic.

    ``T`` (6 x k, polynomial columns, independent) spans the twists;
    ``rotations`` is the generic rank of its ``omega`` block.  The
    combinations ``x`` with ``omega x = 0`` come by Cramer's rule on a non-zero
    minor of that block (found at a random point, so non-zero generically):
    ``k - rotations`` of them, polynomial, then ``T x``.  Cheaper than the
    intersection with the translations (a reciprocal of reciprocals).
    """
    k = T.cols
    if k == rotations:
        return ImmutableMatrix.zeros(3, 0)
    if rotations == 0:
        return ImmutableMatrix(T[3:, :])
    rg = _to_ring(ImmutableMatrix.vstack(T[:3, :], ImmutableMatrix.zeros(3, k)))
    R, K = rg.ring, rg.ring.domain
    A = [[rg.cols[j][i] for j in range(k)] for i in range(3)]  # the omega rows
    for seed in _SEEDS:
        point = _sample_point(R, random.Random(seed))
        A0 = DomainMatrix([[a(*point) if a else K.zero for a in row] for row in A], (3, k), K)
        _, rows = A0.transpose().rref()
        if len(rows) == rotations:
            break
    _, cols = A0.extract(list(rows), list(range(k))).rref()
    vectors = [_primitive(v, R) for v in _cramer(A, rows, cols, R, width=k)]
    xs = ImmutableMatrix([[_poly_expr(e, R) for e in v] for v in vectors]).T
    # y in the null space of the omega block with its columns scaled by D (``_to_ring``
    # clears denominators column by column): D y in the null space of the block itself
    moves = (ImmutableMatrix(T[3:, :]) * _column_scales(T, rg, R) * xs).applyfunc(cancel)
    return ImmutableMatrix(moves)


def _column_scales(T: ImmutableMatrix, rg: _Ring, R) -> ImmutableMatrix:
    """The diagonal of the factors ``_to_ring`` multiplied the columns of ``T``'s omega block by."""
    k = T.cols
    d = []
    for j in range(k):
        i = next((i for i in range(3) if T[i, j] != 0), None)
        d.append(1 if i is None else cancel(_poly_expr(rg.cols[j][i], R) / T[i, j]))
    return ImmutableMatrix.diag(*d) if k else ImmutableMatrix.zeros(0, 0)


@dataclass(frozen=True)
class _Node:
    """One case: its condition, rank, substitution, and the minor that proves the rank."""

    condition: Boolean
    rank: int | None
    subs: tuple  # ((symbol, value), ...)
    matrix: ImmutableMatrix  # the system with the substitution made
    rows: tuple = ()  # members of the minor
    cols: tuple = ()  # coordinates of the minor (of the swapped rows)
    #: the equations (in the user's symbols) the rank is proved modulo, where no
    #: substitution states the case (``_on_surface``); then ``subs`` does not make it
    relation: tuple = ()


def _poly_expr(p, R) -> Any:
    """A ring element as a SymPy expression in the user's symbols (``sin(q)``, not its ring symbol)."""
    e = R.to_sympy(p)
    return e.xreplace(_TRIG_BACK) if _relations(R) else e


def _minor(B, rows, cols, R):
    return _det([[B[i][j] for j in cols] for i in rows], R)


#: below this estimated work (``_charge`` units) every candidate minor is computed to choose
#: the simplest; above it, candidates are ranked by a degree bound and checked at a point first
_EXACT_CHOICE = 200_000


def _det_cost(rows) -> int:
    """The work ``_det`` charges for these rows (see :data:`BUDGET`)."""
    return math.factorial(len(rows)) * math.prod(
        max((len(e.terms()) for e in r), default=1) or 1 for r in rows)


def _choose_minor(rg: _Ring, rank: int, pivots: tuple):
    """A non-zero ``rank x rank`` minor of the swapped rows, as simple as can be found.

    Small systems: every candidate is computed and the one of least degree
    (then fewest terms) kept.  Where that would cost more than
    :data:`_EXACT_CHOICE`, the candidates are ranked by a bound on their
    degree (the sum over rows of the largest total degree), those that vanish
    at a random point (of the circle, for angles) are passed over, and the
    best of the first three non-zero ones is kept: the determinants of many
    symbols are the dearest part of a mobility analysis (profiled on a 3-RPS
    with 12 symbols: 29 of 44 s in choosing the minor).
    """
    R = rg.ring
    B = [_swap(c) for c in rg.cols]
    all_rows = list(combinations(range(len(B)), rank))
    col_sets = list(combinations(range(6), rank))
    row_sets = all_rows if len(all_rows) * len(col_sets) <= _MINOR_BUDGET else [tuple(pivots)]
    candidates = [(rows, cols) for rows in row_sets for cols in col_sets]
    subs = {c: [[B[i][j] for j in c[1]] for i in c[0]] for c in candidates}
    if sum(_det_cost(m) for m in subs.values()) > _EXACT_CHOICE:
        K = R.domain
        point = _sample_point(R, random.Random(7))
        B0 = [[b(*point) if b else K.zero for b in row] for row in B]

        def bound(c):
            deg = sum(max((sum(e.LM) if e else 0) for e in r) for r in subs[c])
            return (deg, _det_cost(subs[c]))

        picked = []
        for c in sorted(candidates, key=bound):
            rows, cols = c
            if _dm([[B0[i][j] for j in cols] for i in rows], K).det():
                picked.append(c)
                if len(picked) == 3:
                    break
        candidates = picked or candidates
    best = None
    for rows, cols in candidates:
        m = _det(subs[(rows, cols)], R)
        if not m:
            continue
        key = (max(sum(e) for e in m.monoms()), len(m.terms()))
        if best is None or key < best[0]:
            best = (key, m, rows, cols)
            if key[0] == 0:
                return best[1:]
    assert best is not None, "a system of rank r has a non-zero r x r minor on its pivot rows"
    return best[1:]


def _factors(p, R) -> list:
    """The irreducible factors of ``p`` that can vanish at a real point: not proved non-zero.

    A factor is proved non-zero by the symbols' assumptions (``is_zero``), by
    :func:`_no_real_zero` (a definite polynomial), or by having no real root
    (a polynomial in one symbol) or no point on the unit circle (a
    polynomial in ``sin(q)`` and ``cos(q)`` alone).
    """
    if p.is_ground:
        return []
    _charge(len(p.terms()) ** 2)
    fl = _factor_list(p, R)
    out = []
    for f, _ in fl:
        if f.is_ground:
            continue
        e = _poly_expr(f, R)
        if is_zero(e) is False or _no_real_zero(f, R) or _points(f, R) == ():
            continue
        out.append(f)
    return out


def _involved(f, R) -> list:
    """The indices of the ring symbols that ``f`` depends on."""
    return [i for i in range(len(R.gens)) if f.degree(i) > 0]


def _positive(p, R, depth: int = 0) -> bool:
    """True if ``p > 0`` at every real point, as proved here (False: not proved).

    Proofs: a positive constant; the symbols' assumptions (``is_positive``);
    a polynomial in one symbol without a real root, positive at one point
    (``count_roots``); a quadratic ``a x**2 + b x + c`` in a symbol with
    ``a > 0`` and ``4 a c - b**2 > 0`` everywhere, each proved the same way
    (``(x + 2)**2 + (y + 2)**2 + 4``: ``4 (y + 2)**2 + 16 > 0``).  The ring
    symbols of ``sin(q)`` and ``cos(q)`` are read as free real symbols, which
    is stronger than needed.
    """
    if not p:
        return False
    if p.is_ground:
        return bool(R.domain.to_sympy(p.LC) > 0)
    if _poly_expr(p, R).is_positive:
        return True
    involved = _involved(p, R)
    if len(involved) == 1:
        x = R.symbols[involved[0]]
        u = Poly(R.to_sympy(p), x)
        if not _rational_domain(u):
            # count_roots counts over the rationals only: a polynomial over them whose roots
            # include u's (its norm) without a real root proves u of one sign
            n = _rational_norm(u.as_expr(), x)
            return n is not None and n.count_roots() == 0 and u.nth(0).is_positive is True
        return u.count_roots() == 0 and bool(u.nth(0) > 0)  # no root, positive at 0
    if depth >= 3:
        return False
    for i in involved:
        x = R.symbols[i]
        if p.degree(i) != 2 or x.is_real is False:
            continue
        g = R.gens[i]
        a, b = p.coeff_wrt(g, 2), p.coeff_wrt(g, 1)
        c = p - a * g**2 - b * g
        if _positive(a, R, depth + 1) and _positive(4 * a * c - b**2, R, depth + 1):
            return True
    # at depth 0 the callers pass irreducible factors (``_factors``): nothing to split
    return depth > 0 and _positive_product(p, R, depth)


def _positive_product(p, R, depth: int) -> bool:
    """True if ``p = c f_1**e_1 ... f_k**e_k`` is proved positive factor by factor.

    Each factor of odd power proved positive or negative (:func:`_positive`), each of
    even power without a real zero, and the signs' product positive:
    ``(p**2 + q**2 + 1)**2`` (the leading coefficient in ``z`` of a 3-RPS's leg
    condition) and ``36 (p**2 + q**2 + 1)**2 ((p + q/sqrt(3))**2 + 1/3)**2``.
    """
    _charge(len(p.terms()) ** 2)
    fl = _factor_list(p, R)
    if len(fl) == 1 and fl[0][1] == 1:
        return False  # irreducible: nothing to gain
    sign = 1
    lead = R.domain.to_sympy(p.LC)  # LC(p) = c * prod LC(f)**k: c's sign, with the signs below
    for f, k in fl:
        lead /= R.domain.to_sympy(f.LC) ** k
        if k % 2 == 0:
            if not _no_real_zero(f, R, depth + 1):
                return False
        elif _positive(f, R, depth + 1):
            pass
        elif _positive(-f, R, depth + 1):
            sign = -sign
        else:
            return False
    return bool(lead * sign > 0)


def _square_split(f, R, depth: int = 0):
    """``(2 a x + b, 4 a c - b**2)`` where ``f = a x**2 + b x + c >= 0`` is a sum of squares, else None.

    With ``a`` a positive number and ``D = 4 a c - b**2 >= 0`` everywhere
    (proved: positive, zero, or itself of this form), ``4 a f = (2 a x + b)**2 + D``,
    so ``f = 0`` exactly where both ``2 a x + b = 0`` and ``D = 0``: two
    equations in the place of one (``(x - 1)**2 + (y - 1)**2 = 0``: ``x = 1, y = 1``).
    """
    if depth >= 4:
        return None
    for i in _involved(f, R):
        if f.degree(i) != 2 or not _solvable(i, R):
            continue
        g = R.gens[i]
        a, b = f.coeff_wrt(g, 2), f.coeff_wrt(g, 1)
        if not a.is_ground or not R.domain.to_sympy(a.LC) > 0:
            continue
        c = f - a * g**2 - b * g
        D = 4 * a * c - b**2
        if not D or _positive(D, R) or _square_split(D, R, depth + 1) is not None:
            return 2 * a * g + b, D
    return None


def _no_real_zero(f, R, depth: int = 0) -> bool:
    """True if ``f`` has no real zero: ``f`` or ``-f`` proved positive (:func:`_positive`)."""
    return _positive(f, R, depth) or _positive(-f, R, depth)


def _dimension(polys: list, R) -> int:
    """How many user symbols the polynomials involve: plain ones and angles (``sin(q)``, ``cos(q)``)."""
    seen = set()
    for p in polys:
        for i in _involved(p, R):
            x = R.symbols[i]
            seen.add(_TRIG_BACK[x].args[0] if x in _TRIG_BACK else x)
    return len(seen)


#: the most common points (Bezout's bound, the product of the degrees) two curves may have
#: for ``_meeting`` to look for them: the 3-RPS's limb curves have 60, found in 0.5 s
_MEETING = 100


def _total_degree(p) -> int:
    return max((sum(m) for m in p.monoms()), default=0)


def _meeting(f, h_expr: Any, subs: tuple, R) -> Any:
    """Where ``f = 0`` (linear in no symbol) meets ``h = 0``: an equation in fewer symbols.

    Two distinct irreducible curves of a plane (two symbols, or angles, between
    them) meet in finitely many points; the last polynomial of a lex Groebner
    basis of ``f``, ``h`` and the circles (SymPy's ``groebner``) is in one ring
    symbol and vanishes at each of them, so imposing it first, then ``f`` and
    ``h`` there, decides them.  Returns that polynomial (an element of ``R``),
    ``R.zero`` where the two have no common point even over the complex numbers
    (the basis is 1), or None: more than two symbols (a curve or more in common,
    whose basis may take minutes: see the section on surfaces), a Bezout bound
    over ``_MEETING``, or no such polynomial.
    """
    try:
        h = _reduce(_element(_in_case(h_expr, subs), R), R)
    except Exception:  # h has symbols (or a form) the ring of f has not
        return None
    if not h or _dimension([f, h], R) > 2 or _total_degree(f) * _total_degree(h) > _MEETING:
        return None
    G = _ideal([f, h], R)
    if G == [R.ring.one]:
        return R.zero
    fewer = [g for g in G if _reduce(g, R) and len(_involved(g, R)) < len(_involved(f, R))]
    return min(fewer, key=lambda g: (len(_involved(g, R)), len(g.terms()))) if fewer else None


def _solvable(i: int, R) -> bool:
    """Whether ring symbol ``i`` may be solved for: a user symbol that is not an angle of sin/cos."""
    x = R.symbols[i]
    return x not in _TRIG_BACK and not any(q == x for q, _, _ in _relations(R))


def _linear_in(f, R):
    """``(symbol, a, b)`` with ``f = a*symbol + b``; a constant ``a`` preferred; or None.

    Only a symbol that :func:`_solvable` allows (never ``sin(q)``'s ring symbol, nor ``q``).
    """
    best = None
    for i, g in enumerate(R.gens):
        if f.degree(i) != 1 or not _solvable(i, R):
            continue
        a = f.coeff_wrt(g, 1)
        b = f - a * g
        key = (0 if a.is_ground else 1, len(a.terms()), len(b.terms()), str(R.symbols[i]))
        if best is None or key < best[0]:
            best = (key, R.symbols[i], a, b)
    return None if best is None else best[1:]


def _points(f, R) -> tuple | None:
    """The real zeros of ``f`` when they are finitely many and found exactly; else None.

    Each zero is ``(pairs, condition)``: the substitution (``((x, root),)``, or
    ``((sin(q), s), (cos(q), c))``) and its condition in the user's symbols.
    Decided: ``f`` in one symbol (its real roots: ``real_roots``, surds or
    ``CRootOf``) and ``f`` in ``sin(q)``, ``cos(q)`` of one angle (the points of
    the circle, :func:`_circle_points`).  ``()`` where there is no real zero.
    """
    involved = _involved(f, R)
    if not involved:
        return None
    angles = {_TRIG_BACK[R.symbols[i]].args[0] for i in involved if R.symbols[i] in _TRIG_BACK}
    if len(angles) == 1 and all(R.symbols[i] in _TRIG_BACK for i in involved):
        return _circle_points(R.to_sympy(f), next(iter(angles)))
    if len(involved) == 1 and _solvable(involved[0], R):
        x = R.symbols[involved[0]]
        if not _rational_domain(Poly(R.to_sympy(f), x)):
            n = _rational_norm(R.to_sympy(f), x)
            return () if n is not None and n.count_roots() == 0 else None
        return _real_points(R.to_sympy(f), x)
    return None


def _rational_domain(u: Poly) -> bool:
    """Whether SymPy isolates the real roots of ``u``: integer or rational coefficients.

    ``real_roots`` and ``count_roots`` refuse algebraic coefficients (``sqrt(3) x - 1``:
    ``DomainError`` over ``EX``); such a condition stays undecided (``None``).
    """
    return u.domain.is_ZZ or u.domain.is_QQ


def _rational_norm(e: Any, x: Any) -> Poly | None:
    """A non-zero polynomial in ``x`` over the rationals whose roots include those of ``e``.

    ``e`` is a polynomial in ``x`` whose coefficients hold square roots (or other
    radicals) of rationals: each radical ``a`` becomes a symbol ``y`` and is
    eliminated by the resultant with its minimal polynomial, the product of ``e``
    over the conjugates of ``a``, which vanishes wherever ``e`` does.  None where
    no such polynomial is found (other algebraic coefficients).
    """
    radicals = sorted((a for a in e.atoms(Pow)
                       if a.base.is_Rational and a.exp.is_Rational and not a.exp.is_Integer),
                      key=str)
    for a in radicals:
        y = Dummy("y")
        _charge(Poly(e, x).degree() ** 3)
        e = resultant(e.xreplace({a: y}).expand(), minimal_polynomial(a, y), y)
    u = Poly(e, x)
    return u if _rational_domain(u) and not u.is_zero else None


@lru_cache(maxsize=1024)
def _real_points(e: Any, x: Any) -> tuple:
    """The distinct real roots ``r`` of the polynomial ``e`` in ``x``, as ``(((x, r),), Eq(x, r))``."""
    _charge(Poly(e, x).degree() ** 3)
    roots: list = []
    for r in Poly(e, x).real_roots():
        if r not in roots and _admissible(x, r):
            roots.append(r)
    return tuple((((x, r),), Eq(x, r)) for r in roots)


def _admissible(x: Any, r: Any) -> bool:
    """Whether the value ``r`` may be the symbol ``x``'s: no assumption of ``x`` refutes it."""
    for prop in ("positive", "nonnegative", "negative", "nonpositive", "nonzero", "integer"):
        if getattr(x, f"is_{prop}") and getattr(r, f"is_{prop}") is False:
            return False
    return True


@lru_cache(maxsize=1024)
def _circle_points(e: Any, q: Any) -> tuple | None:
    """The points ``(sin q, cos q)`` of the unit circle where the polynomial ``e`` vanishes.

    ``e`` is in the ring symbols of ``sin(q)`` and ``cos(q)``.  Through
    ``t = tan(q/2)``: the real roots of the numerator of ``e(2t/(1+t**2),
    (1-t**2)/(1+t**2))`` give every point but ``q = pi``, ``(0, -1)``, which is
    checked apart.  Each point is ``(((sin(q), s), (cos(q), c)), condition)``.
    """
    S, C = _trig_symbol(sin, q), _trig_symbol(cos, q)
    t = Dummy("t", real=True)
    s, c = _on_circle(t)
    num = fraction(cancel(e.xreplace({S: s, C: c})))[0]
    values: list = []
    if num.has(t) and not _rational_domain(Poly(num, t)):
        # radical coefficients: decided only where the circle has no point but q = pi
        n = _rational_norm(num, t)
        if n is None or n.count_roots() != 0:
            return None
        at_pi = radsimp(e.xreplace({S: 0, C: -1}))
        if at_pi.is_zero is None:
            return None
        values = [(Integer(0), Integer(-1))] if at_pi.is_zero else []
        return tuple((((sin(q), s), (cos(q), c)), And(Eq(sin(q), s), Eq(cos(q), c)))
                     for s, c in values)
    if num.has(t):
        _charge(Poly(num, t).degree() ** 3)
        for r in Poly(num, t).real_roots():
            value = (radsimp(cancel(2 * r / (1 + r**2))), radsimp(cancel((1 - r**2) / (1 + r**2))))
            if value not in values:
                values.append(value)
    if e.xreplace({S: 0, C: -1}) == 0 and (0, -1) not in values:
        values.append((Integer(0), Integer(-1)))
    return tuple((((sin(q), s), (cos(q), c)), And(Eq(sin(q), s), Eq(cos(q), c)))
                 for s, c in values)


class _TooManyCases(Exception):
    pass


class _OverBudget(Exception):
    pass


#: the work left to the case split under way in this thread (a one-item list), or None
_LEFT: ContextVar[list[int] | None] = ContextVar("screwsym_case_budget", default=None)


def _charge(units: int) -> None:
    """Spend ``units`` of the budget of the case split under way (none: nothing is counted)."""
    left = _LEFT.get()
    if left is not None:
        left[0] -= units
        if left[0] < 0:
            raise _OverBudget


@contextmanager
def case_budget(budget: int, name: str) -> Iterator[None]:
    """Bound the work of the case splits run inside (the outermost budget holds).

    Past it, ``ValueError`` naming ``name`` and ``budget``.
    """
    budget = check_count(budget, "budget")
    if _LEFT.get() is not None:  # an outer call's budget bounds this one too
        yield
        return
    token = _LEFT.set([budget])
    try:
        yield
    except _OverBudget:
        raise ValueError(
            f"{name}: the case split needs more work than budget={budget} units of "
            "polynomial arithmetic; give some symbols values (xreplace) or pass a larger budget"
        ) from None
    finally:
        _LEFT.reset(token)


def _budgeted_cases(M: ImmutableMatrix, max_cases: int, budget: int, name: str) -> tuple:
    limit = check_count(max_cases, "max_cases")
    with case_budget(budget, name):
        return _cases(M, limit)


class _Cases(list):
    """The list of cases found so far, refusing to grow past ``limit``."""

    def __init__(self, limit: int):
        super().__init__()
        self.limit = limit

    def append(self, node) -> None:
        if len(self) >= self.limit:
            raise _TooManyCases
        super().append(node)


def _split(run: Any, limit: int) -> tuple[_Node, ...]:
    """The cases that ``run(out)`` appends to ``out``: at most ``limit`` (a ValueError beyond)."""
    out = _Cases(limit)
    try:
        run(out)
    except _TooManyCases:
        raise ValueError(
            f"rank_conditions: the case split of this system has more than {limit} cases; "
            "give some symbols values (xreplace) or pass a larger max_cases"
        ) from None
    return tuple(out)


@lru_cache(maxsize=256)
def _cases(M: ImmutableMatrix, limit: int = MAX_CASES) -> tuple[_Node, ...]:
    return _split(lambda out: _node(_normal(M), (), (), (), out), limit)


@lru_cache(maxsize=256)
def _top(M: ImmutableMatrix) -> _Node:
    """The generic case alone (what ``reciprocal`` needs), without the case split."""
    return _here(_normal(M), (), (), (), split=False)[0]


def _normal(M: ImmutableMatrix) -> ImmutableMatrix:
    """``M`` with sin and cos of sums and multiples of symbols expanded (:func:`_trig_normal`)."""
    return M.applyfunc(_trig_normal) if M.has(sin, cos) else M


def _condition(conds) -> Boolean:
    seen = []
    for c in conds:
        if c not in seen and c is not true:
            seen.append(c)
    return And(*seen) if seen else true


def _substitute(obj: Any, subs: Any) -> Any:
    """``obj.xreplace(subs)``, where keys ``sin(q)`` and ``cos(q)`` reach ``sin(2 q)``, ``cos(q + r)``.

    The substitutions of a case split may set ``sin(q)`` and ``cos(q)`` of an
    angle ``q`` (a point of the circle); sin and cos of sums and integer
    multiples of ``q`` are expanded (``expand_trig``) before they are replaced.

    >>> from sympy import symbols, sin, cos
    >>> from screwsym.systems.screw_system import _substitute
    >>> q, r = symbols("q r", real=True)
    >>> _substitute(sin(q + r) + cos(q), {sin(q): 0, cos(q): -1})
    -sin(r) - 1
    """
    d = dict(subs)
    angles = {k.args[0] for k in d if isinstance(k, (sin, cos))}
    if angles and hasattr(obj, "atoms"):
        for a in obj.atoms(sin, cos):
            if a not in d and not a.args[0].is_Symbol and a.args[0].free_symbols & angles:
                d[a] = expand_trig(a).xreplace(d)
    return obj.xreplace(d) if d else obj


def _apply(M: ImmutableMatrix, subs) -> ImmutableMatrix:
    """``M`` with the substitution made, each entry brought to lowest terms (``cancel``)."""
    return _substitute(M, subs).applyfunc(cancel) if subs else M


def _known_nonzero(f_expr, nonzero: tuple) -> bool:
    """Whether ``f_expr`` is a constant multiple of a polynomial the case assumes non-zero."""
    return any(cancel(f_expr / g).is_number for g in nonzero)


def _substitute_nonzero(nonzero: tuple, pairs: tuple) -> tuple | None:
    """The polynomials a case assumes non-zero, after the substitution ``pairs``.

    Each becomes the irreducible factors of its numerator (the denominators
    of the values are themselves assumed non-zero).  None where one of them
    becomes zero: the substitution contradicts the case, which has no point.
    """
    keys = [x for x, _ in pairs]
    out = []
    for g in nonzero:
        if not any(g.has(x) for x in keys):
            out.append(g)
            continue
        num = fraction(cancel(_substitute(g, pairs)))[0]
        if num == 0 or (num.has(sin, cos) and _vanishes(num)):  # zero on the circle too
            return None
        out.extend(f for f, _ in factor_list(num)[1] if not f.is_number)
    return tuple(out)


def _here(M: ImmutableMatrix, conds: tuple, subs: tuple, nonzero: tuple, split: bool = True):
    """The case of ``M`` (the substitution made) where its chosen minor is non-zero.

    Returns the node and the factors (as expressions) of the minor that
    split off the special cases.
    """
    if M.cols == 0 or _analysis(M).rank == 0:
        return _Node(_condition(conds), 0, subs, M), []
    rg = _to_ring(M)
    an = _analysis(M)
    m, rows, cols = _choose_minor(rg, an.rank, an.pivots)
    R = rg.ring
    if not split:  # the basis alone: no need to factor the minor
        return _Node(true, an.rank, subs, M, rows, cols), []
    factors = [e for e in (_poly_expr(f, R) for f in _factors(m, R))
               if not _known_nonzero(e, nonzero)]
    ne = tuple(Ne(e, 0) for e in factors)
    return _Node(_condition(conds + ne), an.rank, subs, M, rows, cols), factors


def _node(M: ImmutableMatrix, conds: tuple, subs: tuple, nonzero: tuple, out: list) -> None:
    """Analyse ``M`` under ``conds`` (already substituted into ``M``); append the cases.

    The special cases are those of the factors of the minor, one after the
    other, each with the earlier ones non-zero: the cases do not overlap.
    """
    node, factors = _here(M, conds, subs, nonzero)
    out.append(node)
    for k, f in enumerate(factors):
        earlier = tuple(factors[:k])
        _impose(M, conds + tuple(Ne(g, 0) for g in earlier), subs, nonzero + earlier, [f], out)


def _in_case(expr: Any, subs: tuple) -> Any:
    """An equation written before a case's substitution ``subs``, in the case's symbols."""
    return cancel(_substitute(expr, subs)) if subs else expr


def _within(subs: dict, relation: tuple, node: _Node) -> tuple[dict, tuple]:
    """The substitution and the relation of the case ``node`` found inside an earlier case
    (``subs``, ``relation``): ``subs`` then the node's own (made in the already substituted
    system) as one substitution; the node's relation if it has one, none if its
    substitution states the earlier surface (``fe`` imposed after a minor's factor), else
    the earlier one."""
    if not node.subs:
        return subs, node.relation or relation
    more = dict(node.subs)
    composed = {k: cancel(_substitute(v, more)) for k, v in subs.items()}
    composed.update(more)
    return composed, node.relation


def _impose(M, conds, subs, nonzero, pending: list, out: list) -> None:
    """Impose the equations ``pending`` (each ``= 0``) by substitution, then analyse."""
    if not pending:
        _node(M, conds, subs, nonzero, out)
        return
    expr, rest = pending[0], pending[1:]
    expr = _in_case(expr, subs)
    # the equation as a polynomial in the remaining symbols, through the same ring
    rg = _to_ring(ImmutableMatrix([expr, 0, 0, 0, 0, 0]))
    p = rg.cols[0][0]
    if not p:
        _impose(M, conds, subs, nonzero, rest, out)
        return
    R = rg.ring
    done: list = []  # the factors imposed so far: a later one's case has them non-zero
    for f in _factors(p, R):
        fe = _poly_expr(f, R)
        if _known_nonzero(fe, nonzero):
            continue  # contradicts the case: no real point
        earlier = tuple(done)
        done.append(fe)
        _solve(M, conds + tuple(Ne(g, 0) for g in earlier), subs, nonzero + earlier,
               f, fe, R, rest, out)


def _solve(M, conds, subs, nonzero, f, fe, R, rest: list, out: list) -> None:
    """The cases of ``f = 0`` (``fe`` its expression): solved for a symbol, at its points, or None."""
    lin = _linear_in(f, R)
    if lin is None:
        points = _points(f, R)
        squares = _square_split(f, R) if points is None else None
        if squares is not None:  # a sum of squares: each square is zero
            _impose(M, conds, subs, nonzero, [_poly_expr(e, R) for e in squares] + rest, out)
            return
        if points is None and not rest and _on_surface(M, conds, subs, nonzero, fe, out):
            return  # decided on the surface itself, modulo fe
        if points is None and rest:  # two curves of a plane meet: at the points they share
            meet = _meeting(f, rest[0], subs, R)
            if meet is not None:
                if meet:  # (no common point at all: no case)
                    _impose(M, conds, subs, nonzero, [_poly_expr(meet, R), fe] + rest, out)
                return
        if points is None:  # not decided here: listed with rank None, every equation stated
            later = tuple(Eq(e, 0) for e in (_in_case(r, subs) for r in rest) if e != 0)
            out.append(_Node(_condition(conds + (Eq(fe, 0),) + later), None, subs, M))
            return
        for pairs, condition in points:
            new_nonzero = _substitute_nonzero(nonzero, pairs)
            if new_nonzero is None:
                continue
            new_subs = tuple((k, cancel(_substitute(v, pairs))) for k, v in subs) + pairs
            _impose(_apply(M, pairs), conds + (condition,), new_subs, new_nonzero, rest, out)
        return
    eq = Eq(fe, 0)
    x, a, b = lin
    value = -_poly_expr(b, R) / _poly_expr(a, R)
    if a.is_ground and value.has(CRootOf):  # at a point already: the symbol's value reads best
        eq = Eq(x, value)
    a_factors = [_poly_expr(g, R) for g in _factors(a, R)]
    a_factors = [g for g in a_factors if not _known_nonzero(g, nonzero)]
    pairs = ((x, value),)
    new_nonzero = _substitute_nonzero(nonzero, pairs)
    if new_nonzero is not None:
        new_subs = tuple((k, cancel(v.xreplace({x: value}))) for k, v in subs) + pairs
        new_conds = conds + (eq,) + tuple(Ne(g, 0) for g in a_factors)
        _impose(_apply(M, pairs), new_conds, new_subs, new_nonzero + tuple(a_factors), rest, out)
    for k, g in enumerate(a_factors):  # the coefficient vanishes: then so must the rest
        earlier = tuple(a_factors[:k])
        _impose(M, conds + (eq,) + tuple(Ne(h, 0) for h in earlier), subs, nonzero + earlier,
                [g, _poly_expr(b, R)] + rest, out)


# ---------------------------------------------------------------------------
# A case on a hypersurface f = 0 that no substitution states: the rank proved modulo f
# ---------------------------------------------------------------------------
#
# Why not a substitution: an irreducible f in two or more symbols and linear in none
# (the 3-RPS's 2 p**2 - 2 q**2 + 1 = 0, a degree-12 type II surface cubic in z) has no
# rational solution for any symbol; its roots are algebraic functions of the others.  The
# rank on the case is proved instead, pointwise: with g an r x r minor of the members
# (rows I, coordinates J) and v_1, ..., v_{6-r} the vectors of Cramer's rule on it, every
# other member's products with the v_k lie in the ideal of f (and of the circles'
# relations): wherever f = 0 and g != 0, the rows I are independent, the v_k span their
# null space, and every member is orthogonal to it, so the rank is r exactly there.
# Membership is decided by the normal form modulo a Groebner basis (SymPy's
# ``groebner``), exact.  The rank r and the minor are first found at a point of f = 0
# over a finite field (a root of f in one symbol, the others at random): a point's
# minor non-zero there is non-zero modulo f, so r is at most the rank on the case, and
# the proof above decides; a point that proves nothing is followed by another (seeds).
# What is left, f = 0 with a factor h of g zero, is imposed as two equations, h first
# (solved for a symbol or at its points where it can be, and f then in fewer symbols).
# Where h is neither and f, h are curves of a plane (two symbols or angles between them,
# ``_meeting``), they meet in finitely many points: the last polynomial of a lex Groebner
# basis of f, h (and the circles) is in one symbol, and is imposed first.  In three or
# more symbols the intersection is listed with rank None: a Groebner basis of two such
# surfaces (a curve in common) did not finish in 90 s on the 3-RPS.

#: the primes of the points of f = 0 over a finite field (large: an unlucky zero of a
#: minor at the point has probability about degree / prime)
_PRIMES = (2_147_483_647, 2_147_483_629, 2_147_483_587, 2_147_483_579, 2_147_483_563)


#: a minor of more terms than this (modulo the surface) is not factored (``_on_surface``)
_FACTOR_ON_SURFACE = 60


class _Unlucky(Exception):
    """This prime or point does not serve (a denominator or a leading coefficient vanishes)."""


def _element(e: Any, R) -> Any:
    """The polynomial ``e`` (in the user's symbols, ``sin(q)`` allowed) as an element of ``R``."""
    e = _trig_entries([e])[0]
    (d,), _ = parallel_dict_from_expr([e], gens=R.symbols)
    K = R.domain
    return R.ring.from_dict({m: _coefficient(K, c) for m, c in d.items()})


def _circle_relations(R) -> list:
    """``sin(q)**2 + cos(q)**2 - 1`` for each angle with both in the ring."""
    g = R.ring.gens
    return [g[si] ** 2 + g[ci] ** 2 - 1 for _, ci, si in _relations(R)
            if ci is not None and si is not None]


def _ideal(polys: list, R) -> list:
    """A Groebner basis (SymPy's) of ``polys`` and the circles' relations, in ``R``'s order."""
    from sympy.polys.groebnertools import groebner

    gens = [p.monic() for p in polys + _circle_relations(R)]
    _charge(sum(len(p.terms()) for p in gens) ** 2)
    return groebner(gens, R.ring)


def _modular(c, K, p: int, theta: int | None) -> int:
    """The coefficient ``c`` of ``K`` (a rational, or an algebraic number at ``theta``) mod ``p``."""
    parts = [c] if theta is None else c.to_list()
    v = 0
    for q in parts:
        q = QQ.convert(q)
        den = int(q.denominator) % p
        if not den:
            raise _Unlucky
        v = (v * (theta or 0) + int(q.numerator) * pow(den, -1, p)) % p
    return v


def _term_mod(m: tuple, c, K, p: int, theta: int | None, point: list, skip: tuple = ()) -> int:
    """The term ``c x**m`` mod ``p`` at ``point``, the symbols of ``skip`` left out."""
    t = _modular(c, K, p, theta)
    for i, k in enumerate(m):
        if k and i not in skip:
            t = t * pow(point[i], k, p) % p
    return t


def _roots_mod(coeffs: list, p: int) -> list:
    """The roots mod ``p`` of the polynomial with integer coefficients ``coeffs`` (highest first)."""
    from sympy.polys.galoistools import gf_factor_sqf, gf_sqf_part, gf_strip

    f = gf_strip([c % p for c in coeffs])
    if len(f) < 2:
        return []
    _, factors = gf_factor_sqf(gf_sqf_part(f, p, ZZ), p, ZZ)
    return [(-int(g[1])) % p for g in factors if len(g) == 2]


def _at_point(polys_rows: list, R, p: int, point: list, theta: int | None) -> list:
    """The entries (ring elements) evaluated mod ``p`` at ``point``."""
    K = R.domain
    out = []
    for row in polys_rows:
        vals = []
        for e in row:
            vals.append(sum(_term_mod(m, c, K, p, theta, point) for m, c in e.items()) % p
                        if e else 0)
        out.append(vals)
    return out


def _point_on(f, R, p: int, rnd: random.Random) -> tuple[list, int | None]:
    """A point mod ``p`` where ``f`` vanishes (and every circle holds), with ``theta``'s value.

    One symbol of ``f`` is solved for (a root of ``f`` in it, the others at random);
    when ``f`` is in sines and cosines alone, one angle's ``tan(q/2)``.  Raises
    ``_Unlucky`` where this prime or point has no such root.
    """
    K = R.domain
    theta = None
    if K.is_Algebraic:
        roots = _roots_mod([_modular(c, QQ, p, None) for c in K.mod.to_list()], p)
        if not roots:
            raise _Unlucky
        theta = roots[0]
    n = len(R.gens)
    point = [rnd.randrange(p) for _ in range(n)]
    circles = {}
    for q, ci, si in _relations(R):
        t = rnd.randrange(p)
        den = (1 + t * t) % p
        if not den:
            raise _Unlucky
        inv = pow(den, -1, p)
        circles[q] = (ci, si)
        if si is not None:
            point[si] = 2 * t * inv % p
        if ci is not None:
            point[ci] = (1 - t * t) * inv % p
    involved = _involved(f, R)
    plain = [i for i in involved if R.symbols[i] not in _TRIG_BACK]
    if plain:
        x = max(plain, key=lambda i: f.degree(i))
        by_degree: dict = {}
        for m, c in f.items():
            t = _term_mod(m, c, K, p, theta, point, skip=(x,))
            by_degree[m[x]] = (by_degree.get(m[x], 0) + t) % p
        top = max(by_degree)
        if not by_degree[top]:
            raise _Unlucky
        roots = _roots_mod([by_degree.get(k, 0) for k in range(top, -1, -1)], p)
        if not roots:
            raise _Unlucky
        point[x] = rnd.choice(roots)
        return point, theta
    # sines and cosines alone: one angle through t = tan(q/2), the numerator of f in t
    from sympy.polys.galoistools import gf_add, gf_mul, gf_pow

    q = next(_TRIG_BACK[R.symbols[i]].args[0] for i in involved)
    ci, si = circles[q]
    top = max((m[ci] if ci is not None else 0) + (m[si] if si is not None else 0)
              for m in f.monoms())
    num: list = []
    for m, c in f.items():
        t = _term_mod(m, c, K, p, theta, point, skip=(ci, si))
        a = m[si] if si is not None else 0
        b = m[ci] if ci is not None else 0
        term = gf_mul(gf_mul(gf_pow([2 % p, 0], a, p, ZZ), gf_pow([p - 1, 0, 1], b, p, ZZ), p, ZZ),
                      gf_pow([1, 0, 1], top - a - b, p, ZZ), p, ZZ)
        num = gf_add(num, [t * k % p for k in term], p, ZZ)
    roots = [t for t in _roots_mod(num, p) if (1 + t * t) % p]
    if not roots:
        raise _Unlucky
    t = rnd.choice(roots)
    inv = pow(1 + t * t, -1, p)
    if si is not None:
        point[si] = 2 * t * inv % p
    if ci is not None:
        point[ci] = (1 - t * t) * inv % p
    return point, theta


def _rank_mod(rows: list, p: int) -> tuple[tuple, tuple]:
    """The first independent rows of an integer matrix mod ``p``, and pivot coordinates of them."""
    from sympy.polys.domains import FF

    F = FF(p)
    A = DomainMatrix([[F(v) for v in r] for r in rows], (len(rows), len(rows[0])), F)
    _, pivots = A.transpose().rref()
    if not pivots:
        return (), ()
    _, cols = A.extract(list(pivots), list(range(A.shape[1]))).rref()
    return tuple(pivots), tuple(cols)


def _rank_on(rg: _Ring, f, seeds: int = 4, swap: bool = True) -> tuple | None:
    """``(rank, rows, cols, minor, basis)`` proved on ``f = 0`` where the minor is non-zero.

    ``f`` is an element of the ring of the system ``rg``; ``basis`` the Groebner basis
    of ``f`` and the circles (see the section's comment).  None where no point proved
    a rank.  ``swap``: the members are screws (their halves swapped, as ``_analysis``
    takes them); ``False`` for the columns of any matrix (``cols`` then its rows).
    """
    RM = rg.ring
    B = [_swap(c) for c in rg.cols] if swap else [tuple(c) for c in rg.cols]
    G = _ideal([f], RM)
    if G == [RM.ring.one]:
        return None  # pragma: no cover - f has points (it came with real ones)
    if all(not e.rem(G) for b in B for e in b if e):  # every member (or none) zero there
        return 0, (), (), RM.one, G
    tried: set = set()
    for seed in range(seeds):
        rnd = random.Random(seed)
        for prime in _PRIMES:
            try:
                point, theta = _point_on(f, RM, prime, rnd)
                values = _at_point(B, RM, prime, point, theta)
            except _Unlucky:
                continue
            break
        else:
            continue
        rows, cols = _rank_mod(values, prime)
        if not rows or (rows, cols) in tried:
            continue
        tried.add((rows, cols))
        minor = _minor(B, rows, cols, RM)
        if not minor.rem(G):
            continue  # pragma: no cover - zero modulo f although not at the point
        vectors = _cramer(B, rows, cols, RM, m=minor, width=len(B[0]))
        _charge(sum(len(e.terms()) for v in vectors for e in v) * len(B))
        if all(not sum((b * x for b, x in zip(B[i], v, strict=True)), RM.zero).rem(G)
               for v in vectors for i in range(len(B)) if i not in rows):
            return len(rows), rows, cols, minor, G
    return None


def _ring_with(M: ImmutableMatrix, fe: Any) -> _Ring:
    """``M``'s columns in a ring that has ``fe``'s symbols too (a case of an earlier system)."""
    extra = ImmutableMatrix(M.rows, 1, [fe] + [0] * (M.rows - 1))
    rg = _to_ring(ImmutableMatrix.hstack(M, extra))
    return _Ring(rg.ring, rg.gens, rg.cols[:-1], rg.scales[:-1])


def _proved_on(M: ImmutableMatrix, fe: Any, swap: bool = True) -> tuple[_Ring, tuple | None]:
    """``M``'s ring (with ``fe``'s symbols) and the rank of its columns proved on ``fe = 0``
    (``_rank_on``: ``(rank, rows, cols, minor, basis)``, or None)."""
    rg = _ring_with(M, fe)
    return rg, _rank_on(rg, _element(fe, rg.ring), swap=swap)


def _on_surface(M, conds, subs, nonzero, fe, out: list) -> bool:
    """The cases of ``fe = 0`` proved modulo ``fe`` (see the section's comment); False: not done."""
    rg, found = _proved_on(M, fe)
    RM = rg.ring
    if found is None:
        return False
    rank, rows, cols, minor, G = found
    eq = Eq(fe, 0)
    minor = minor.rem(G)  # the same values on the case, and often fewer terms
    if len(minor.terms()) > _FACTOR_ON_SURFACE:
        # factoring a large minor over an algebraic field can take minutes (SymPy's
        # Trager): the case is stated with the minor whole, and where it vanishes too, None
        e = _poly_expr(minor, RM)
        out.append(_Node(_condition(conds + (eq, Ne(e, 0))), rank, subs, M, rows, cols,
                         relation=(fe,)))
        out.append(_Node(_condition(conds + (eq, Eq(e, 0))), None, subs, M))
        return True
    factors = [e for e in (_poly_expr(h, RM) for h in _factors(minor, RM))
               if not _known_nonzero(e, nonzero)]
    out.append(_Node(_condition(conds + (eq,) + tuple(Ne(h, 0) for h in factors)), rank, subs, M,
                     rows, cols, relation=(fe,)))
    for k, h in enumerate(factors):  # the minor's factors zero too: two surfaces meet
        earlier = tuple(factors[:k])
        # h first: solved for a symbol or at its points where it can be, then fe there
        _impose(M, conds + tuple(Ne(g, 0) for g in earlier), subs, nonzero + earlier,
                [h, fe], out)
    return True


@lru_cache(maxsize=256)
def _surface_cases(M: ImmutableMatrix, fe: Any, limit: int = MAX_CASES) -> tuple[_Node, ...]:
    """The cases of ``M`` where ``fe = 0`` holds already: ``_cases`` for a system on a surface.

    ``fe`` is the equation of an earlier case that no substitution states
    (``_Node.relation``, an irreducible polynomial linear in none of its
    symbols); the rank is proved modulo it as ``_on_surface`` proves it, and
    the cases cover the surface: where the minor also vanishes, each factor is
    imposed with ``fe`` (by a substitution where one states both).  A single
    case of rank None where no point proves a rank.
    """
    M = _normal(M)

    def run(out: list) -> None:
        if M.cols == 0:
            out.append(_Node(Eq(fe, 0), 0, (), M, relation=(fe,)))
        elif not _on_surface(M, (), (), (), fe, out):
            out.append(_Node(Eq(fe, 0), None, (), M))

    return _split(run, limit)


def _rank_on_surface(M: ImmutableMatrix, fe: Any, swap: bool = True) -> int | None:
    """The rank of ``M``'s columns at the generic point of ``fe = 0`` (proved modulo ``fe``
    where a minor found at a point of it is non-zero); None where no point proved it."""
    if M.cols == 0:
        return 0
    found = _proved_on(M, fe, swap)[1]
    return None if found is None else found[0]


def _zero_on_surface(entries: list, fe: Any) -> bool:
    """Whether every polynomial (or rational function) of ``entries`` vanishes wherever
    ``fe = 0`` (where it is defined): each numerator is in the ideal of ``fe`` and the
    circles (one ring, one Groebner basis for all)."""
    nums = [fraction(cancel(e))[0] for e in entries]
    rg = _ring_with(ImmutableMatrix(len(nums), 1, nums), fe)
    R = rg.ring
    G = _ideal([_element(fe, R)], R)
    return all(not e.rem(G) for e in rg.cols[0])


def _null_on_surface(M: ImmutableMatrix, fe: Any) -> tuple | None:
    """The null space of the matrix ``M`` at the generic point of ``fe = 0``: ring columns.

    ``(rank, members, null)``: ``rank`` columns of ``M`` (``members``) are
    independent at a point of the surface, and each vector of Cramer's rule on
    their minor (one per other column, polynomial, that column's entry the
    minor, reduced modulo ``fe``) is a null vector wherever ``fe = 0``: the
    columns of ``null`` (``M.cols x (M.cols - rank)``, in lowest terms), a
    basis of the null space wherever ``fe = 0`` and the minor is non-zero.
    None where no point proved it.
    """
    rg, found = _proved_on(M, fe, swap=False)
    R = rg.ring
    if found is None:
        return None
    rank, members, coords, minor, G = found
    B = [tuple(c) for c in rg.cols]
    vectors = []
    for j in range(len(B)):
        if j in members:
            continue
        x = [R.zero] * len(B)
        x[j] = minor
        for pp, p in enumerate(members):
            rows = [[B[j if q == pp else members[q]][c] for c in coords]
                    for q in range(len(members))]
            x[p] = -_det(rows, R)
        # the columns were cleared of denominators (cols[k] = scales[k] * column k)
        v = [(e * s).rem(G) for e, s in zip(x, rg.scales, strict=True)]
        vectors.append([_poly_expr(e, R) for e in _primitive(v, R)])
    null = ImmutableMatrix(vectors).T if vectors else ImmutableMatrix.zeros(M.cols, 0)
    return rank, members, null


@lru_cache(maxsize=256)
def _reciprocal_of(M: ImmutableMatrix, kind: type[Screw]) -> ScrewSystem:
    """The generic reciprocal basis of the system ``M`` (``reciprocal``), computed once."""
    return _basis_system(_top(M), kind)


def _basis_with(node: _Node, kind: type[Screw], subs: dict | None) -> ScrewSystem:
    """The reciprocal basis of a case (``_basis_system``) with a later case's substitution
    made: valid wherever that later case holds, inside the node's."""
    basis = _basis_system(node, kind)
    return _substitute(basis, subs) if subs else basis


def _basis_system(node: _Node, kind: type[Screw]) -> ScrewSystem:
    """The reciprocal basis of a case, by Cramer's rule on its minor (see ``reciprocal``)."""
    if node.rank == 0:
        eye = ImmutableMatrix.eye(6)
        return ScrewSystem(*(kind.from_matrix(eye[:, k]) for k in range(6)))
    if node.rank == 6:
        return ScrewSystem(kind=kind if kind in _KIND_NAMES.values() else None)
    rg = _to_ring(node.matrix)
    R = rg.ring
    B = [_swap(c) for c in rg.cols]
    vectors = [_primitive(v, R) for v in _cramer(B, node.rows, node.cols, R)]
    return ScrewSystem(*(kind.from_matrix([_poly_expr(e, R) for e in v]) for v in vectors))


def _rationals(c, K) -> list:
    """The rational numbers that make up an element of ``K`` (itself, or an algebraic's)."""
    return [c] if (K.is_QQ or K.is_ZZ) else [q for q in c.to_list() if q]


def _primitive(v: list, R) -> list:
    """``v`` divided by the gcd of its entries, its first non-zero entry with a positive lead."""
    g = R.zero
    for e in v:
        if e:
            g = e if not g else _gcd_of(g, e, R)
    if not g:
        return v
    v = [R.exquo(e, g) if e else e for e in v]
    first = next(e for e in v if e)
    lc = first.LC
    if R.domain.is_QQ or R.domain.is_ZZ:
        neg = lc < 0
    else:  # an algebraic number: its sign as a real number
        neg = bool(R.domain.to_sympy(lc) < 0)
    if neg:
        v = [-e for e in v]
    # clear the rational content too: integer coefficients without a common factor
    coeffs = [q for e in v for c in e.coeffs() for q in _rationals(c, R.domain)]
    den = lcm(*(int(q.denominator) for q in coeffs))
    num = gcd(*(int(q.numerator * den // q.denominator) for q in coeffs))
    scale = R.domain.convert(QQ(den, num))
    v = [e * scale for e in v]
    return v

