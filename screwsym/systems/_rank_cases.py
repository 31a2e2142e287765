r"""The rank conditions of a screw system: an exhaustive, exact split into cases.

The generic rank of a system is found at a point and proved for all values
(:func:`analysis`, :func:`screwsym.algebra.linalg.proved_at`); the simplest minor that
proves it is chosen (:func:`screwsym.algebra.linalg.choose_minor`), and its factors
that can vanish at a real point (:func:`screwsym.algebra.real.real_factors`) are the
special cases.  Each is imposed in turn, the earlier ones non-zero, so the cases do not
overlap: solved for a symbol where the factor is linear in one (a substitution), at its
real points where it has finitely many (:func:`screwsym.algebra.real.real_zeros`), on
its own surface where it is linear in none (the rank proved modulo the factor,
:mod:`screwsym.algebra.surface`), and listed with rank ``None`` only where none of
these decides.  :func:`rank_cases` is the split of a system, :func:`surface_cases` the
split of a system already on a surface; every split charges its work to the budget of
the method the user called (:func:`case_budget`).

A :class:`Node` is one case: its condition, its rank, its substitution and the minor
that proves the rank there.  :meth:`ScrewSystem.rank_conditions
<screwsym.systems.screw_system.ScrewSystem.rank_conditions>` gives the user these
cases; the mobility splits (:mod:`screwsym.systems._cases`) build on them.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from sympy import (
    And,
    CRootOf,
    Eq,
    ImmutableMatrix,
    Ne,
    cancel,
    cos,
    factor_list,
    fraction,
    sin,
    true,
)
from sympy.logic.boolalg import Boolean

from ..algebra import budget as _budget
from ..algebra.budget import MAX_CASES, CaseList, TooManyCases
from ..algebra.circle import angles_of, trig_normal, trig_substitute
from ..algebra.linalg import SEEDS, ProvedRank, choose_minor, domain_matrix, proved_at
from ..algebra.real import linear_in, real_factors, real_zeros, square_split
from ..algebra.rings import PolyColumns, ring_element, ring_with, to_expr, to_ring, vanishes
from ..algebra.surface import meeting, rank_on
from ..core.checks import check_count
from ..core.decide import is_zero
from ..core.formulas import SWAP


def _factors(p, R) -> list:
    """The factors of ``p`` that can vanish at a real point (:func:`~screwsym.algebra.real.real_factors`),
    a factor proved non-zero by the symbols' assumptions (``is_zero``) left out."""
    return real_factors(p, R, lambda e: is_zero(e) is False)


@contextmanager
def case_budget(budget: int, name: str) -> Iterator[None]:
    """:func:`screwsym.algebra.budget.case_budget` with ``budget`` checked first (a positive int)."""
    with _budget.case_budget(check_count(budget, "budget"), name):
        yield


def swapped(col: tuple) -> tuple:
    """A screw's row of ``(Delta A)^T``: its two halves swapped (1.45), by the one ``SWAP``."""
    return tuple(col[i] for i in SWAP)


@lru_cache(maxsize=512)
def analysis(M: ImmutableMatrix) -> ProvedRank:
    """The generic rank, the first independent members and a minor that proves the rank.

    The rank ``r`` is found at a rational point (a non-zero minor there is a
    non-zero polynomial, so the generic rank is at least ``r``) and proved:
    the ``6 - r`` vectors Cramer's rule builds from that minor are checked to
    be reciprocal to *every* member identically, so the rank is at most
    ``r``.  If the check fails (an unlucky point) the next point is tried,
    and in the end fraction-free elimination over the polynomial ring decides.
    """
    if M.cols == 0:
        return ProvedRank(0, (), ())
    rg = to_ring(M)
    R = rg.ring
    B = [swapped(c) for c in rg.cols]
    for seed in SEEDS:
        found = proved_at(B, R, seed, skip_zero=True)
        if found is not None:
            return found
    if angles_of(R):  # pragma: no cover - unlucky points on the circle: more of them
        for seed in range(len(SEEDS) + 1, 64):
            found = proved_at(B, R, seed, skip_zero=False)
            if found is not None:
                return found
        raise RuntimeError("rank: no point on the circle proved the rank")  # pragma: no cover
    A = domain_matrix([[c[i] for c in rg.cols] for i in range(6)], R)  # pragma: no cover - unlucky points
    _, _, pivots = A.rref_den()  # pragma: no cover
    if not pivots:  # pragma: no cover
        return ProvedRank(0, (), ())
    Bp = domain_matrix([B[i] for i in pivots], R)  # pragma: no cover
    _, _, cols = Bp.rref_den()  # pragma: no cover
    return ProvedRank(len(pivots), tuple(pivots), tuple(cols))  # pragma: no cover


@dataclass(frozen=True)
class Node:
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


def budgeted_cases(M: ImmutableMatrix, max_cases: int, budget: int, name: str) -> tuple:
    limit = check_count(max_cases, "max_cases")
    with case_budget(budget, name):
        return rank_cases(M, limit)


def split_cases(run: Any, limit: int) -> tuple[Node, ...]:
    """The cases that ``run(out)`` appends to ``out``: at most ``limit`` (a ValueError beyond)."""
    out = CaseList(limit)
    try:
        run(out)
    except TooManyCases:
        raise ValueError(
            f"{_budget.budget_name('rank_conditions')}: the case split of this system has more "
            f"than {limit} cases; "
            "give some symbols values (xreplace) or pass a larger max_cases"
        ) from None
    return tuple(out)


@lru_cache(maxsize=256)
def rank_cases(M: ImmutableMatrix, limit: int = MAX_CASES) -> tuple[Node, ...]:
    return split_cases(lambda out: _node(trig_normal_matrix(M), (), (), (), out), limit)


@lru_cache(maxsize=256)
def top_case(M: ImmutableMatrix) -> Node:
    """The generic case alone (what ``reciprocal`` needs), without the case split."""
    return case_here(trig_normal_matrix(M), (), (), (), split=False)[0]


def trig_normal_matrix(M: ImmutableMatrix) -> ImmutableMatrix:
    """``M`` with sin and cos of sums and multiples of symbols expanded (:func:`trig_normal`)."""
    return M.applyfunc(trig_normal) if M.has(sin, cos) else M


def conjunction(conds) -> Boolean:
    seen = []
    for c in conds:
        if c not in seen and c is not true:
            seen.append(c)
    return And(*seen) if seen else true


def apply_subs(M: ImmutableMatrix, subs) -> ImmutableMatrix:
    """``M`` with the substitution made, each entry brought to lowest terms (``cancel``)."""
    return trig_substitute(M, subs).applyfunc(cancel) if subs else M


def known_nonzero(f_expr, nonzero: tuple) -> bool:
    """Whether ``f_expr`` is a constant multiple of a polynomial the case assumes non-zero."""
    return any(cancel(f_expr / g).is_number for g in nonzero)


def substitute_nonzero(nonzero: tuple, pairs: tuple) -> tuple | None:
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
        num = fraction(cancel(trig_substitute(g, pairs)))[0]
        if num == 0 or (num.has(sin, cos) and vanishes(num)):  # zero on the circle too
            return None
        out.extend(f for f, _ in factor_list(num)[1] if not f.is_number)
    return tuple(out)


def case_here(M: ImmutableMatrix, conds: tuple, subs: tuple, nonzero: tuple, split: bool = True):
    """The case of ``M`` (the substitution made) where its chosen minor is non-zero.

    Returns the node and the factors (as expressions) of the minor that
    split off the special cases.
    """
    if M.cols == 0 or analysis(M).rank == 0:
        return Node(conjunction(conds), 0, subs, M), []
    rg = to_ring(M)
    an = analysis(M)
    m, rows, cols = choose_minor([swapped(c) for c in rg.cols], rg.ring, an.rank, an.pivots)
    R = rg.ring
    if not split:  # the basis alone: no need to factor the minor
        return Node(true, an.rank, subs, M, rows, cols), []
    factors = [e for e in (to_expr(f, R) for f in _factors(m, R))
               if not known_nonzero(e, nonzero)]
    ne = tuple(Ne(e, 0) for e in factors)
    return Node(conjunction(conds + ne), an.rank, subs, M, rows, cols), factors


def _node(M: ImmutableMatrix, conds: tuple, subs: tuple, nonzero: tuple, out: list) -> None:
    """Analyse ``M`` under ``conds`` (already substituted into ``M``); append the cases.

    The special cases are those of the factors of the minor, one after the
    other, each with the earlier ones non-zero: the cases do not overlap.
    """
    node, factors = case_here(M, conds, subs, nonzero)
    out.append(node)
    for k, f in enumerate(factors):
        earlier = tuple(factors[:k])
        _impose(M, conds + tuple(Ne(g, 0) for g in earlier), subs, nonzero + earlier, [f], out)


def in_case(expr: Any, subs: tuple) -> Any:
    """An equation written before a case's substitution ``subs``, in the case's symbols."""
    return cancel(trig_substitute(expr, subs)) if subs else expr


def within(subs: dict, relation: tuple, node: Node) -> tuple[dict, tuple]:
    """The substitution and the relation of the case ``node`` found inside an earlier case
    (``subs``, ``relation``): ``subs`` then the node's own (made in the already substituted
    system) as one substitution; the node's relation if it has one, none if its
    substitution states the earlier surface (``fe`` imposed after a minor's factor), else
    the earlier one."""
    if not node.subs:
        return subs, node.relation or relation
    more = dict(node.subs)
    composed = {k: cancel(trig_substitute(v, more)) for k, v in subs.items()}
    composed.update(more)
    return composed, node.relation


def _impose(M, conds, subs, nonzero, pending: list, out: list) -> None:
    """Impose the equations ``pending`` (each ``= 0``) by substitution, then analyse."""
    if not pending:
        _node(M, conds, subs, nonzero, out)
        return
    expr, rest = pending[0], pending[1:]
    expr = in_case(expr, subs)
    # the equation as a polynomial in the remaining symbols, through the same ring
    rg = to_ring(ImmutableMatrix([expr, 0, 0, 0, 0, 0]))
    p = rg.cols[0][0]
    if not p:
        _impose(M, conds, subs, nonzero, rest, out)
        return
    R = rg.ring
    done: list = []  # the factors imposed so far: a later one's case has them non-zero
    for f in _factors(p, R):
        fe = to_expr(f, R)
        if known_nonzero(fe, nonzero):
            continue  # contradicts the case: no real point
        earlier = tuple(done)
        done.append(fe)
        _solve(M, conds + tuple(Ne(g, 0) for g in earlier), subs, nonzero + earlier,
               f, fe, R, rest, out)


def _solve(M, conds, subs, nonzero, f, fe, R, rest: list, out: list) -> None:
    """The cases of ``f = 0`` (``fe`` its expression): solved for a symbol, at its points, or None."""
    lin = linear_in(f, R)
    if lin is None:
        points = real_zeros(f, R)
        squares = square_split(f, R) if points is None else None
        if squares is not None:  # a sum of squares: each square is zero
            _impose(M, conds, subs, nonzero, [to_expr(e, R) for e in squares] + rest, out)
            return
        if points is None and not rest and _on_surface(M, conds, subs, nonzero, fe, out):
            return  # decided on the surface itself, modulo fe
        if points is None and rest:  # two curves of a plane meet: at the points they share
            meet = meeting(f, in_case(rest[0], subs), R)
            if meet is not None:
                if meet:  # (no common point at all: no case)
                    _impose(M, conds, subs, nonzero, [to_expr(meet, R), fe] + rest, out)
                return
        if points is None:  # not decided here: listed with rank None, every equation stated
            later = tuple(Eq(e, 0) for e in (in_case(r, subs) for r in rest) if e != 0)
            out.append(Node(conjunction(conds + (Eq(fe, 0),) + later), None, subs, M))
            return
        for pairs, condition in points:
            new_nonzero = substitute_nonzero(nonzero, pairs)
            if new_nonzero is None:
                continue
            new_subs = tuple((k, cancel(trig_substitute(v, pairs))) for k, v in subs) + pairs
            _impose(apply_subs(M, pairs), conds + (condition,), new_subs, new_nonzero, rest, out)
        return
    eq = Eq(fe, 0)
    x, a, b = lin
    value = -to_expr(b, R) / to_expr(a, R)
    if a.is_ground and value.has(CRootOf):  # at a point already: the symbol's value reads best
        eq = Eq(x, value)
    a_factors = [to_expr(g, R) for g in _factors(a, R)]
    a_factors = [g for g in a_factors if not known_nonzero(g, nonzero)]
    pairs = ((x, value),)
    new_nonzero = substitute_nonzero(nonzero, pairs)
    if new_nonzero is not None:
        new_subs = tuple((k, cancel(v.xreplace({x: value}))) for k, v in subs) + pairs
        new_conds = conds + (eq,) + tuple(Ne(g, 0) for g in a_factors)
        _impose(apply_subs(M, pairs), new_conds, new_subs, new_nonzero + tuple(a_factors), rest, out)
    for k, g in enumerate(a_factors):  # the coefficient vanishes: then so must the rest
        earlier = tuple(a_factors[:k])
        _impose(M, conds + (eq,) + tuple(Ne(h, 0) for h in earlier), subs, nonzero + earlier,
                [g, to_expr(b, R)] + rest, out)


#: a minor of more terms than this (modulo the surface) is not factored (``_on_surface``)
FACTOR_ON_SURFACE = 60


def proved_on(M: ImmutableMatrix, fe: Any, swap: bool = True) -> tuple[PolyColumns, tuple | None]:
    """``M``'s ring (with ``fe``'s symbols) and the rank of its columns proved on ``fe = 0``
    (``rank_on``: ``(rank, rows, cols, minor, basis)``, or None)."""
    rg = ring_with(M, fe)
    B = [swapped(c) for c in rg.cols] if swap else [tuple(c) for c in rg.cols]
    return rg, rank_on(B, rg.ring, ring_element(fe, rg.ring))


def _on_surface(M, conds, subs, nonzero, fe, out: list) -> bool:
    """The cases of ``fe = 0`` proved modulo ``fe`` (:mod:`screwsym.algebra.surface` says how); False: not done."""
    rg, found = proved_on(M, fe)
    RM = rg.ring
    if found is None:
        return False
    rank, rows, cols, minor, G = found
    eq = Eq(fe, 0)
    minor = minor.rem(G)  # the same values on the case, and often fewer terms
    if len(minor.terms()) > FACTOR_ON_SURFACE:
        # factoring a large minor over an algebraic field can take minutes (SymPy's
        # Trager): the case is stated with the minor whole, and where it vanishes too, None
        e = to_expr(minor, RM)
        out.append(Node(conjunction(conds + (eq, Ne(e, 0))), rank, subs, M, rows, cols,
                         relation=(fe,)))
        out.append(Node(conjunction(conds + (eq, Eq(e, 0))), None, subs, M))
        return True
    factors = [e for e in (to_expr(h, RM) for h in _factors(minor, RM))
               if not known_nonzero(e, nonzero)]
    out.append(Node(conjunction(conds + (eq,) + tuple(Ne(h, 0) for h in factors)), rank, subs, M,
                     rows, cols, relation=(fe,)))
    for k, h in enumerate(factors):  # the minor's factors zero too: two surfaces meet
        earlier = tuple(factors[:k])
        # h first: solved for a symbol or at its points where it can be, then fe there
        _impose(M, conds + tuple(Ne(g, 0) for g in earlier), subs, nonzero + earlier,
                [h, fe], out)
    return True


@lru_cache(maxsize=256)
def surface_cases(M: ImmutableMatrix, fe: Any, limit: int = MAX_CASES) -> tuple[Node, ...]:
    """The cases of ``M`` where ``fe = 0`` holds already: ``rank_cases`` for a system on a surface.

    ``fe`` is the equation of an earlier case that no substitution states
    (``Node.relation``, an irreducible polynomial linear in none of its
    symbols); the rank is proved modulo it as ``_on_surface`` proves it, and
    the cases cover the surface: where the minor also vanishes, each factor is
    imposed with ``fe`` (by a substitution where one states both).  A single
    case of rank None where no point proves a rank.
    """
    M = trig_normal_matrix(M)

    def run(out: list) -> None:
        if M.cols == 0:
            out.append(Node(Eq(fe, 0), 0, (), M, relation=(fe,)))
        elif not _on_surface(M, (), (), (), fe, out):
            out.append(Node(Eq(fe, 0), None, (), M))

    return split_cases(run, limit)


def rank_on_surface(M: ImmutableMatrix, fe: Any, swap: bool = True) -> int | None:
    """The rank of ``M``'s columns at the generic point of ``fe = 0`` (proved modulo ``fe``
    where a minor found at a point of it is non-zero); None where no point proved it."""
    if M.cols == 0:
        return 0
    found = proved_on(M, fe, swap)[1]
    return None if found is None else found[0]


def clear_caches() -> None:
    """Empty every cache of the exact algebra and of the screw systems (``lru_cache`` of the
    modules of :mod:`screwsym.algebra` and :mod:`screwsym.systems` loaded): for benchmarks,
    which time a computation from scratch."""
    for name, module in list(sys.modules.items()):
        if module is None or not name.startswith(("screwsym.algebra.", "screwsym.systems.")):
            continue
        for value in vars(module).values():
            if callable(getattr(value, "cache_clear", None)):
                value.cache_clear()
