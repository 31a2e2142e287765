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

from collections.abc import Iterator
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from sympy import (
    ImmutableMatrix,
    zeros,
)
from sympy.core.symbol import Str
from sympy.logic.boolalg import Boolean

from ..core.basic import ScrewsymBasic
from ..core.checks import check_exact
from ..core.screw import Screw, ScrewLike, check_screw
from ..core.twist import Twist
from ..core.wrench import Wrench

if TYPE_CHECKING:
    from typing_extensions import Self


if TYPE_CHECKING:
    from typing_extensions import Self

from ..algebra.budget import BUDGET, MAX_CASES
from ..algebra.circle import trig_substitute
from ..algebra.linalg import cramer_vectors, primitive_vector
from ..algebra.rings import to_expr, to_ring
from ._rank_cases import Node, analysis, budgeted_cases, swapped, top_case

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

    screwsym.core.screw.reciprocal_product, screwsym.systems.parallel.Limb

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
        return analysis(self.matrix).rank

    def basis(self) -> ScrewSystem:
        """Members that span the system generically: the first ones independent at a test point.

        A set of members independent at one rational point is independent for
        generic values, and there are ``rank`` of them, so they are a basis
        (generically; where the rank drops, see :meth:`rank_conditions`).

        >>> from screwsym import ScrewSystem
        >>> ScrewSystem([1, 0, 0, 0, 0, 0], [2, 0, 0, 0, 0, 0], [0, 0, 0, 1, 0, 0]).basis()
        ScrewSystem(Screw([1, 0, 0], [0, 0, 0]), Screw([0, 0, 0], [1, 0, 0]))
        """
        pivots = analysis(self.matrix).pivots
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
            return analysis(ImmutableMatrix(s.matrix)).rank == 0
        return analysis(self.matrix.row_join(s.matrix)).rank == self.rank

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
        cases = budgeted_cases(self.matrix, max_cases, budget, "rank_conditions")
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
            (n.condition, None if n.rank is None else basis_system(n, kind))
            for n in budgeted_cases(self.matrix, max_cases, budget, "reciprocal_cases")
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
        cases = budgeted_cases(self.matrix, max_cases, budget, "substitutions")
        return [(n.condition, None if n.relation else dict(n.subs)) for n in cases]


def _check_system(value: Any, name: str) -> ScrewSystem:
    if not isinstance(value, ScrewSystem):
        raise TypeError(f"{name}: expected a ScrewSystem, got {type(value).__name__}")
    return value


@lru_cache(maxsize=256)
def _reciprocal_of(M: ImmutableMatrix, kind: type[Screw]) -> ScrewSystem:
    """The generic reciprocal basis of the system ``M`` (``reciprocal``), computed once."""
    return basis_system(top_case(M), kind)


def basis_with(node: Node, kind: type[Screw], subs: dict | None) -> ScrewSystem:
    """The reciprocal basis of a case (``basis_system``) with a later case's substitution
    made: valid wherever that later case holds, inside the node's."""
    basis = basis_system(node, kind)
    return trig_substitute(basis, subs) if subs else basis


def basis_system(node: Node, kind: type[Screw]) -> ScrewSystem:
    """The reciprocal basis of a case, by Cramer's rule on its minor (see ``reciprocal``)."""
    if node.rank == 0:
        eye = ImmutableMatrix.eye(6)
        return ScrewSystem(*(kind.from_matrix(eye[:, k]) for k in range(6)))
    if node.rank == 6:
        return ScrewSystem(kind=kind if kind in _KIND_NAMES.values() else None)
    rg = to_ring(node.matrix)
    R = rg.ring
    B = [swapped(c) for c in rg.cols]
    vectors = [primitive_vector(v, R) for v in cramer_vectors(B, node.rows, node.cols, R)]
    return ScrewSystem(*(kind.from_matrix([to_expr(e, R) for e in v]) for v in vectors))
