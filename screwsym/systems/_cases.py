r"""The case-tree driver of the mobility splits: leaves, refinement, the Degenerate rule, merge.

``ParallelMechanism.mobility_cases`` and ``Mechanism.mobility_cases`` each split a
mechanism's analysis into the cases where a rank changes, one system after another
(the limbs' twists then the constraints; each loop's twists then the network matrix).
Both grow the same tree: a :class:`Leaf` holds the conditions so far, the substitution
that states them (``None``: undecided), the *relation* of a case that no substitution
states (the later splits are made modulo it), and the nodes that proved each rank.
:func:`refine` splits a leaf by the rank conditions of one more system
(:mod:`screwsym.systems._rank_cases`), composed with the leaf's own;
:func:`unmade_on_surface` is the Degenerate rule on a surface (a joint whose twists
lose rank there); :func:`check_cases` is the limit on their number;
:func:`merge_cases` gives the cases with the same answer as one, and
:func:`union_of` writes their condition in few terms.
"""

from __future__ import annotations

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
    sin,
    true,
)
from sympy.logic.boolalg import simplify_logic

from ..algebra.circle import circle_simplify, trig_substitute
from ._rank_cases import rank_cases, rank_on_surface, surface_cases, within
from .screw_system import ScrewSystem


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
    and the nodes of screw_system's split that proved each rank so far (limbs, constraints)."""

    conds: tuple
    subs: dict | None
    relation: tuple
    nodes: tuple


def refine(leaf: Leaf, system: ScrewSystem, limit: int) -> list[Leaf]:
    """The cases of ``system`` (already substituted) within ``leaf``: composed with it.

    On a leaf with a relation ``fe``, the system's cases on the surface ``fe = 0``
    (:func:`~screwsym.systems.screw_system._surface_cases`).  A case whose rank is
    undecided keeps ``None`` as its substitution.
    """
    out: list[Leaf] = []
    subs = cast("dict[Any, Any]", leaf.subs)  # called on decided leaves only
    M = system.matrix
    nodes = surface_cases(M, leaf.relation[0], limit) if leaf.relation else rank_cases(M, limit)
    for node in nodes:
        new_conds = leaf.conds if node.condition is true else leaf.conds + (node.condition,)
        if node.rank is None:  # undecided
            out.append(Leaf(new_conds, None, (), ()))
            continue
        composed, relation = within(subs, leaf.relation, node)
        out.append(Leaf(new_conds, composed, relation, leaf.nodes + (node,)))
    return out
