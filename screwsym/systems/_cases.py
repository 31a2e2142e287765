r"""The case-tree driver of the mobility splits: leaves, refinement, the Degenerate rule, merge.

``ParallelMechanism.mobility_cases`` and ``Mechanism.mobility_cases`` each split a
mechanism's analysis into the cases where a rank changes, one system after another
(the limbs' twists then the constraints; each loop's twists then the network matrix).
Both grow the same tree: a :class:`Leaf` holds the conditions so far, the substitution
that states them (``None``: undecided), the *relation* of a case that no substitution
states (the later splits are made modulo it), and the nodes that proved each rank.
:func:`split_mechanism` is the driver: each mechanism lists only the systems it splits
on (its :class:`Stage` s), the parts that its values may unmake, and what it gives on a
case; the driver splits each leaf by the rank conditions of one more system
(:mod:`screwsym.systems._rank_cases`), composed with the leaf's own, drops the cases
that contradict themselves, applies the Degenerate rule (:func:`unmade`, and
:func:`unmade_on_surface` on a surface: a joint whose twists lose rank there) and
keeps their number within the limit (:func:`check_cases`);
:func:`merge_cases` gives the cases with the same answer as one, and
:func:`union_of` writes their condition in few terms.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple, Protocol, TypeVar, cast

from sympy import (
    And,
    Eq,
    ImmutableMatrix,
    Ne,
    Not,
    Or,
    cos,
    count_ops,
    false,
    sin,
    true,
)
from sympy.logic.boolalg import simplify_logic

from ..algebra.circle import circle_simplify, trig_substitute
from ..algebra.rings import vanishes
from ._rank_cases import rank_cases, rank_on_surface, surface_cases, within


def unmade_on_surface(joints: Any, subs: dict[Any, Any], fe: Any) -> str | None:
    """Why the first of ``joints`` (``(name, joint)`` pairs) is unmade on a case on ``fe = 0``.

    A case that no substitution states cannot rebuild the joints there; a
    joint is unmade where its own twists lose rank (a zero axis, a universal
    joint's axes made parallel, a parallelogram folded flat: what its
    constructor refuses), here at the generic point of the surface, proved
    modulo ``fe``.  None when every joint keeps its freedoms there.
    """
    for name, joint in joints:
        here = trig_substitute(joint, subs) if subs else joint
        T = ImmutableMatrix.hstack(*(t.matrix for t in here._twists()))
        rank = rank_on_surface(T, fe)
        if rank is not None and rank < joint.freedom:
            return (f"{name}: its {joint.freedom} twist(s) have rank {rank} where {fe} = 0 "
                    "(a zero axis, or axes made parallel)")
    return None


def union_of(a: Any, b: Any) -> Any:
    """``a | b`` in the fewest terms: SymPy's ``simplify_logic`` with ``Ne`` read as ``~Eq``
    (the atoms are the rank conditions' equations).  Beyond 6 atoms the plain ``Or``: the
    minimisation grows exponentially with them (13 of 43 s of a 3-RPS with 12 symbols at 8)."""
    expr = Or(a, b).replace(lambda x: isinstance(x, Ne), lambda x: Not(Eq(*x.args)))
    if len(expr.atoms(Eq)) > 6:
        return Or(a, b)
    # points of the circle read best as a disjunction of points (and circle_simplify joins them)
    expr = simplify_logic(expr, form="dnf" if expr.has(sin, cos) else None, deep=False)
    return circle_simplify(expr.replace(lambda x: isinstance(x, Not) and isinstance(x.args[0], Eq),
                                         lambda x: Ne(*x.args[0].args)))


class Answered(Protocol):
    def answer(self) -> tuple[Any, ...]: ...


_A = TypeVar("_A", bound=Answered)


def merge_cases(cases: list[tuple[Any, _A | None]]) -> list[tuple[Any, _A | None]]:
    """Cases with the same answer as one, in the place of the first (undecided ones apart).

    Any result with an ``answer()`` (a :class:`Mobility`, a graph mechanism's
    ``MechanismMobility``) is compared by it.
    """
    merged: list[tuple[Any, _A | None]] = []
    where: dict[tuple[Any, ...], int] = {}
    joined: set[int] = set()
    for condition, m in cases:
        if m is None:
            merged.append((condition, None))
            continue
        key = m.answer()
        if key in where:
            i = where[key]
            merged[i] = (union_of(merged[i][0], condition), merged[i][1])
            joined.add(i)
        else:
            where[key] = len(merged)
            merged.append((condition, m))
    # the cases hold one at each point, so a merged case is where none of the others holds:
    # written so where that is an open condition (inequalities alone) and shorter:
    # Ne(sin(a), 0) | Ne(sin(b), 0) for a union of five conjunctions that say the same on
    # the circles (a case of equations keeps them: its roots, its points)
    for i in joined:
        others = [c for j, (c, _) in enumerate(merged) if j != i]
        if not others:
            merged[i] = (true, merged[i][1])
            continue
        alt = _complement(others)
        if alt is not None and not alt.atoms(Eq) and count_ops(alt) < count_ops(merged[i][0]):
            merged[i] = (alt, merged[i][1])
    return merged


def _complement(conditions: list) -> Any:
    """Where none of ``conditions`` holds, in few terms (None beyond 6 atoms: see ``union_of``)."""
    expr = And(*(Not(c) for c in conditions)).replace(lambda x: isinstance(x, Ne),
                                                      lambda x: Not(Eq(*x.args)))
    if len(expr.atoms(Eq)) > 6:
        return None
    expr = simplify_logic(expr, deep=False)
    return expr.replace(lambda x: isinstance(x, Not) and isinstance(x.args[0], Eq),
                        lambda x: Ne(*x.args[0].args))


def check_cases(count: int, limit: int) -> None:
    if count > limit:
        raise ValueError(
            f"mobility_cases: more than {limit} cases; give some symbols values (xreplace) "
            "or pass a larger max_cases"
        )


class Leaf(NamedTuple):
    """A case of the split: its conditions, its substitution (None: undecided), its relation
    (the equation of a case that no substitution states, the later splits made modulo it),
    the nodes of the rank split that proved each rank so far, and what the mechanism's own
    stages carry along (``extra``: the graph's joint rates closing the loops so far)."""

    conds: tuple
    subs: dict | None
    relation: tuple
    nodes: tuple
    extra: Any = None


class Stage(NamedTuple):
    """One system a mechanism's split is made on, within each decided leaf.

    ``system(leaf)`` gives the matrix whose rank conditions split the leaf (the leaf's
    substitution made) and what ``grow`` needs; ``grow(leaf, node, context)`` gives the
    leaf of the new case ``node`` (by default: ``node`` recorded in ``leaf.nodes``).
    """

    system: Callable[[Leaf], tuple[ImmutableMatrix, Any]]
    grow: Callable[[Leaf, Any, Any], Leaf] | None = None


def contradicts(conds: tuple, subs: dict) -> bool:
    """Whether the substitution of a case makes one of its own ``Ne`` conditions false."""
    for c in conds:
        for atom in c.atoms(Ne):
            if vanishes(trig_substitute(atom.lhs - atom.rhs, subs)):
                return True
    return False


def unmade(units: Any, subs: dict) -> str | None:
    """Why the first of ``units`` (``(name, joint or limb)`` pairs) is unmade by ``subs``: the
    ``ValueError`` its constructor gives with those values, as ``"name: error"``; None when
    all stand."""
    for name, unit in units:
        try:
            trig_substitute(unit, subs)
        except ValueError as error:
            return f"{name}: {error}"
    return None


def split_mechanism(stages: list[Stage], units: Any, joints: Any, result: Callable[[Leaf], Any],
                    degenerate: Callable[[str], Any], limit: int) -> list[tuple[Any, Any]]:
    """The cases of a mechanism: split by each stage's system in turn, then ``result`` of each.

    The driver both mobility splits share.  Each decided leaf is split by the rank
    conditions of its stage's system (:func:`~screwsym.systems._rank_cases.rank_cases`, or
    :func:`~screwsym.systems._rank_cases.surface_cases` modulo the leaf's relation); a new
    case is composed with its leaf (:func:`~screwsym.systems._rank_cases.within`), dropped
    where its substitution contradicts its own conditions (no point), and given as
    ``degenerate(why)`` (:class:`~screwsym.systems.parallel.Degenerate`) where its values
    unmake one of ``units``
    (``(name, joint or limb)`` pairs: :func:`unmade`) or, on a new surface, one of
    ``joints`` (:func:`unmade_on_surface`): the Degenerate rule.  An undecided case (rank
    ``None``) stays a leaf with ``None`` as its substitution and comes out with ``None``.
    At most ``limit`` leaves after each stage (:func:`check_cases`).  The degenerate cases
    are listed last.
    """
    leaves = [Leaf((), {}, (), ())]
    unmade_cases: list[tuple[Any, Any]] = []
    for stage in stages:
        grown: list[Leaf] = []
        for leaf in leaves:
            if leaf.subs is None:
                grown.append(leaf)
                continue
            M, context = stage.system(leaf)
            nodes = (surface_cases(M, leaf.relation[0], limit) if leaf.relation
                     else rank_cases(M, limit))
            for node in nodes:
                conds = leaf.conds if node.condition is true else leaf.conds + (node.condition,)
                if node.rank is None:  # undecided
                    grown.append(Leaf(conds, None, (), ()))
                    continue
                composed, relation = within(cast("dict", leaf.subs), leaf.relation, node)
                if contradicts(conds, composed):
                    continue
                why = unmade(units, composed) if node.subs else None
                if why is None and relation and relation != leaf.relation:  # a new surface
                    why = unmade_on_surface(joints, composed, relation[0])
                if why is not None:  # the case's values unmake a joint: nothing to analyse
                    unmade_cases.append((And(*conds), degenerate(why)))
                    continue
                new = Leaf(conds, composed, relation, leaf.nodes, leaf.extra)
                grown.append(stage.grow(new, node, context) if stage.grow
                             else new._replace(nodes=new.nodes + (node,)))
        leaves = grown
        check_cases(len(leaves), limit)
    out: list[tuple[Any, Any]] = []
    for leaf in leaves:
        condition = And(*leaf.conds) if leaf.conds else true
        if condition is false:
            continue
        out.append((condition, None if leaf.subs is None else result(leaf)))
    return out + unmade_cases
