r"""The three kinds of singularity of an actuated parallel mechanism, one meaning everywhere.

Each kind is a screw system that a *regular* mechanism of this kind has at full rank,
and a singularity is a configuration where the system has less (Gosselin & Angeles
1990; Zlatanov, Fenton & Benhabib 1995; Zlatanov, Bonev & Gosselin 2002):

* ``limb`` (type I, the inverse-kinematic kind): a limb's twist system below the rank
  of the limb at a generic configuration of its own (:func:`generic_limb_rank`: a
  stretched R-R-R leg), or the system of its constraints and an actuation wrench below
  ``c + 1``, ``c = 6 - generic_limb_rank`` (the actuation wrench falls into the
  constraints);
* ``constraint``: the mechanism's constraint system below the *constraint count* of a
  regular mechanism of the kind (:func:`constraint_count`);
* ``actuation`` (type II): ``Jx`` (the actuation wrenches and the constraints) below
  ``min(6, actuators + constraint count)`` (6 in space; for a planar mechanism its 3
  actuation wrenches and 3 planar constraints, for a spherical one 3 and 3) where the
  constraints keep their count.

So the *generic* rank of each system is not what the geometry given happens to have
but what the kind of mechanism has: at a configuration given by numbers, a part is
``[(True, rank)]`` where the system is singular and ``[]`` where not, and an
*architecture singularity* (a design singular at every configuration: the
Gough--Stewart platform with similar base and platform hexagons at zero orientation,
Ma & Angeles 1991) is a first entry ``(True, rank)``, the rank it has at a generic
configuration, followed by the cases where it falls further.

A limb at a type I configuration whose actuated joint adds no freedom to the others has
the *limit* actuation wrench (:func:`~screwsym.systems.actuation.limb_actuation_wrench`):
it is reported, never raised, and ``Jq`` has the zero there that the literature shows
(Gosselin & Angeles 1990, the matrix B singular; Bonev, Zlatanov & Gosselin 2003).

All the case splits of one call share one budget (:mod:`screwsym.algebra.budget`): the
call answers within it or stops with a ``ValueError`` that names ``singularities``.

References
==========

C. Gosselin and J. Angeles, "Singularity analysis of closed-loop kinematic chains",
IEEE Trans. Robot. Autom. 6(3) (1990) 281-290.
O. Ma and J. Angeles, "Architecture singularities of platform manipulators", Proc. IEEE
ICRA 1991, 1542-1547.
I. A. Bonev, D. Zlatanov and C. M. Gosselin, "Singularity analysis of 3-DOF planar
parallel mechanisms via screw theory", ASME J. Mech. Des. 125 (2003) 573-581.
D. Zlatanov, I. A. Bonev and C. M. Gosselin, "Constraint singularities of parallel
mechanisms", Proc. IEEE ICRA 2002, 496-502.
"""

from __future__ import annotations

import random
from itertools import combinations
from math import comb
from typing import Any, NamedTuple

from sympy import (
    And,
    Eq,
    ImmutableMatrix,
    Mul,
    Ne,
    Not,
    Or,
    Poly,
    cancel,
    cos,
    factor_list,
    false,
    sin,
    true,
)
from sympy.logic.boolalg import simplify_logic

from ..algebra.budget import BUDGET
from ..algebra.circle import reduce_circle, trig_substitute
from ..algebra.linalg import det_rows
from ..algebra.real import proved_positive, real_factors, solvable
from ..algebra.rings import to_expr, to_ring, vanishes
from ..algebra.surface import groebner_ideal
from ..core.decide import is_zero
from ..core.printing import result_latex, result_str
from ..core.twist import Twist
from ..core.wrench import Wrench
from ._rank_cases import analysis, case_budget, rank_on_surface, trig_normal_matrix
from .actuation import (
    _actuated,
    _displaced,
    generic_limb_rank,
    generic_values,
    limb_actuation_wrench,
)
from .screw_system import ScrewSystem

#: a Limb and a ParallelMechanism (screwsym.systems.parallel imports this module)
_Limb = Any
_Mechanism = Any

__all__ = ["Singularities", "mechanism_singularities", "constraint_count"]


class Singularities(NamedTuple):
    """The result of :func:`mechanism_singularities`: three lists of ``(condition, rank)`` pairs.

    Each pair is a set where the system of its kind has less than the rank
    of a regular mechanism of the kind (the module docstring); their ``Or``
    is the singular set of the kind, ``[]`` none.  A set is stated by the
    fewest equations that describe it (:func:`rank_strata`: one conic, each
    factor in the user's symbols), with the rank at its generic points (lower
    where a later pair of lower rank holds).  A first pair
    ``(True, r)`` is an *architecture singularity*: rank ``r`` at a generic
    configuration, singular everywhere.  ``rank`` ``None``: not decided
    there.  ``limbs`` names the limb (its index) of each entry of ``limb``.
    It prints as a table (kind, limb, condition, rank), in a terminal and in
    Jupyter (LaTeX).
    """

    limb: list  #: a limb loses a freedom or an actuation wrench falls into its constraints
    actuation: list  #: Jx loses rank while the constraints keep theirs (type II)
    constraint: list  #: the constraint system loses rank (Zlatanov, Bonev & Gosselin 2002)
    limbs: tuple = ()  #: the index of the limb of each entry of ``limb``

    def rows(self) -> list[tuple[str, str, Any, Any]]:
        """``(kind, limb, condition, rank)`` of every entry: the table's rows."""
        out: list[tuple[str, str, Any, Any]] = []
        for n, (c, r) in enumerate(self.limb):
            out.append(("limb", str(self.limbs[n]) if n < len(self.limbs) else "", c, r))
        out.extend(("actuation", "", c, r) for c, r in self.actuation)
        out.extend(("constraint", "", c, r) for c, r in self.constraint)
        return out

    def table(self) -> str:
        """The entries as a text table (kind, limb, condition, rank); "regular" when none."""
        rows = [(k, i, result_str(c), str(r)) for k, i, c, r in self.rows()]
        if not rows:
            return "Singularities: none (regular)"
        head = ("kind", "limb", "condition", "rank")
        widths = [max(len(x[j]) for x in [head, *rows]) for j in range(4)]
        lines = ["  ".join(x[j].ljust(widths[j]) for j in range(4)).rstrip() for x in [head, *rows]]
        lines.insert(1, "  ".join("-" * w for w in widths))
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.table()

    def _repr_pretty_(self, p: Any, cycle: bool) -> None:  # IPython's plain display
        p.text(self.table())

    def _repr_latex_(self) -> str:
        rows = self.rows()
        if not rows:
            return r"$\text{no singularity (regular)}$"
        body = r" \\ ".join(
            rf"\text{{{k}}} & {i} & {result_latex(c)} & {result_latex(r)}"
            for k, i, c, r in rows)
        return (r"$\begin{array}{llll} \text{kind} & \text{limb} & \text{condition} & "
                rf"\text{{rank}} \\ \hline {body} \end{{array}}$")


def _union(a: Any, b: Any) -> Any:
    """``a | b``, minimised by SymPy's ``simplify_logic`` with ``Ne`` read as ``~Eq`` (at most
    6 equations; beyond, the plain ``Or``)."""
    expr = Or(a, b).replace(lambda x: isinstance(x, Ne), lambda x: Not(Eq(*x.args)))
    if len(expr.atoms(Eq)) > 6:
        return Or(a, b)
    expr = simplify_logic(expr)
    return expr.replace(lambda x: isinstance(x, Not) and isinstance(x.args[0], Eq),
                        lambda x: Ne(*x.args[0].args))


#: the most minors of one size :func:`rank_strata` computes (beyond: the case split)
MAX_MINORS = 2000


#: the most terms (over the minors of one size) :func:`rank_strata` takes a gcd and a Groebner
#: basis of (the 3-RPR with pose (x, y, phi): 10 distinct minors of 5 x 5, 114 terms in all)
MAX_TERMS = 600


class Undecided(Exception):
    """:func:`rank_strata` cannot decide a stratum (the case split of ``rank_conditions`` then)."""


def _primitive(e: Any) -> Any:
    """The equation ``e = 0`` as the product of the distinct irreducible factors of ``e`` (the
    same zeros: a square adds no equation), each with coprime integer coefficients and a
    positive leading one, in the user's symbols."""
    _, factors = factor_list(e)
    out = []
    for f, _ in factors:
        f = f.as_content_primitive()[1]
        if Poly(f).LC() < 0:
            f = -f
        out.append(f)
    return Mul(*out) if len(out) > 1 else out[0] if out else e


def _equation(e: Any) -> Any:
    """``Eq(e, 0)`` with ``e`` made primitive and factored (:func:`_primitive`); ``Eq(x, c)``
    where ``e`` is a number times a symbol plus a number (``Eq(y, 1)``, not ``Eq(y - 1, 0)``)."""
    e = _primitive(e)
    syms = e.free_symbols
    if len(syms) == 1 and not e.has(sin, cos):
        x = next(iter(syms))
        p = Poly(e, x)
        if p.degree() == 1:
            return Eq(x, -p.nth(0) / p.LC())
    return Eq(e, 0)


def _minors(rows: list, k: int, R: Any) -> list:
    """The distinct non-zero ``k x k`` minors of the matrix ``rows`` (ring elements), monic."""
    n, m = len(rows), len(rows[0])
    if comb(n, k) * comb(m, k) > MAX_MINORS:
        raise Undecided
    found: dict = {}
    for rs in combinations(range(n), k):
        sub = [rows[i] for i in rs]
        if any(not any(r) for r in sub):
            continue
        for cs in combinations(range(m), k):
            d = det_rows([[r[j] for j in cs] for r in sub], R)
            if d:
                found.setdefault(d.monic(), None)
    return list(found)


def _squares(f: Any, R: Any, depth: int = 0) -> list | None:
    """Equations whose common real zeros are those of ``f``, where ``f >= 0`` is a sum of squares
    on the circles; else None.

    :func:`~screwsym.algebra.real.square_split` with the rest reduced on the circles at
    each step (``4 a f = (2 a x + b)**2 + D`` and ``D`` read on them, where
    ``sin(q)**2 + cos(q)**2 = 1``): a leg's squared length ``|d|**2`` with its pose
    angle in sines and cosines is zero exactly where ``d = 0``, two equations.
    """
    if depth >= 4:
        return None
    for i in range(len(R.gens)):
        if f.degree(i) != 2 or not solvable(i, R):
            continue
        g = R.gens[i]
        a = f.coeff_wrt(g, 2)
        if not a.is_ground:
            continue
        if not R.domain.to_sympy(a.LC) > 0:  # -f >= 0: the same zeros
            f, a = -f, -a
        b = f.coeff_wrt(g, 1)
        D = reduce_circle(4 * a * (f - a * g**2 - b * g) - b**2, R)
        if not D:
            return [2 * a * g + b]
        more = _squares(D, R, depth + 1) if not proved_positive(D, R) else None
        if more is not None:
            return [2 * a * g + b, *more]
    return None


def _solved_rank(M: ImmutableMatrix, eqs: list) -> tuple[int | None, list]:
    """The rank of ``M``'s columns at the generic point of the set ``eqs = 0``, where the
    equations solve one after the other for a symbol with a constant coefficient (a set
    parametrised by the other symbols: real points, and its generic point), and the
    equations solved (the others follow from them); else ``(None, eqs)``."""
    subs: dict = {}
    pending = list(eqs)
    used: list = []
    while pending:
        for e in pending:
            e2 = cancel(trig_substitute(e, subs)) if subs else e
            if e2 == 0 or vanishes(e2):  # (zero on the circles too)
                pending.remove(e)
                break
            pick = None
            for x in sorted(e2.free_symbols, key=str):
                if e2.has(sin(x), cos(x)):
                    continue
                p = Poly(e2, x)
                if p.degree() == 1 and p.LC().is_number:
                    pick = (x, -p.nth(0) / p.LC())
                    break
            if pick is not None:
                x, v = pick
                subs = {k: cancel(trig_substitute(w, {x: v})) for k, w in subs.items()}
                subs[x] = v
                pending.remove(e)
                used.append(e)
                break
        else:
            return None, eqs
    here = trig_substitute(M, subs).applyfunc(cancel)
    return analysis(trig_normal_matrix(here)).rank, used


def rank_strata(M: ImmutableMatrix, generic: int, also: Any = true) -> list:
    r"""The sets where the columns of ``M`` (a screw system) have less than ``generic``, each once.

    Explanation
    ===========

    The system has rank below ``k`` exactly where all its ``k x k`` minors
    vanish.  Their gcd ``g`` gives the surfaces of that set: each real factor
    of ``g`` (:func:`~screwsym.algebra.real.real_factors`), its rank proved at
    its generic point modulo the factor
    (:func:`~screwsym.systems._rank_cases.rank_on_surface`); what is left,
    ``minors / g = 0``, is a set of codimension two or more, written as the
    Groebner basis of those quotients (and the circles' relations: SymPy's
    ``groebner``), ``1`` where it has no point at all.  Each ``k`` from the
    generic rank down, until the set is empty.  So a singular set comes as
    the fewest equations that describe it: one conic, not points on it and
    the conic without them.  A set is listed with the rank it has at its
    generic points (at the ``k`` where that rank is ``k - 1``; lower where a
    later entry holds), each factor in the user's symbols with coprime
    integer coefficients.  Where the system's own rank is below ``generic``
    a first entry ``(also, rank)``; ``also`` is conjoined to every condition.

    Raises :class:`Undecided` where a set is neither a surface whose rank is
    proved nor solved for its symbols one after the other, or has more than
    :data:`MAX_MINORS` minors of a size: the caller then splits by cases.
    """
    M = trig_normal_matrix(ImmutableMatrix(M))
    out: list = []
    if M.cols == 0:
        return [(also, 0)] if generic > 0 else []
    top = analysis(M).rank
    if top < generic:
        out.append((also, top))
    if not M.free_symbols or top == 0:
        return out
    rg = to_ring(M)
    R = rg.ring
    if not R.domain.is_QQ:  # gcds over an algebraic field (SymPy's subresultants): minutes
        raise Undecided
    rows = [[c[i] for c in rg.cols] for i in range(M.rows)]
    listed: list = []  # the surfaces and sets already stated (ring elements / bases)
    for k in range(top, 0, -1):
        minors = _minors(rows, k, R)
        if sum(len(m.terms()) for m in minors) > MAX_TERMS:
            raise Undecided  # their gcd and Groebner basis would not be cheap
        g = minors[0]
        for m in minors[1:]:
            g = g.gcd(m)
        surfaces = [f for f in real_factors(g, R, lambda e: is_zero(e) is False)
                    if f.monic() not in listed]
        rest = [m.exquo(g) for m in minors]
        basis = ([R.ring.one] if any(r.is_ground for r in rest)
                 else groebner_ideal(rest, R))
        if not surfaces and basis == [R.ring.one]:
            break  # no point where the rank is below k: nor below any smaller
        at_rank: dict = {}
        sets = [basis] if basis != [R.ring.one] else []
        for f in list(surfaces):
            squares = _squares(f, R)
            if squares is not None:  # its real points: a set of codimension two or more
                surfaces.remove(f)
                sets.append(squares)
        for f in surfaces:
            fe = to_expr(f, R)
            rank = rank_on_surface(M, fe)
            if rank is None:
                raise Undecided
            if rank == k - 1:
                listed.append(f.monic())
                at_rank.setdefault(rank, []).append(_primitive(fe))
        for rank, fs in sorted(at_rank.items(), reverse=True):
            cond = _equation(Mul(*fs))
            out.append((And(cond, also) if also is not true else cond, rank))
        for polys in sets:
            eqs = [e for e in (to_expr(reduce_circle(b, R), R) for b in polys) if e != 0]
            key = tuple(sorted(map(str, eqs)))
            if key in listed:
                continue
            rank, eqs = _solved_rank(M, eqs)
            if rank is None:
                raise Undecided
            if rank == k - 1:
                listed.append(key)
                cond = And(*(_equation(e) for e in eqs))
                out.append((And(cond, also) if also is not true else cond, rank))
    return out


def _drops(system: ScrewSystem, generic: int, also: Any = true) -> list:
    """The sets where ``system`` has less than ``generic``: its rank strata (:func:`rank_strata`),
    or, where those cannot be decided, the cases of ``rank_conditions`` (those of one rank merged).
    """
    try:
        return rank_strata(system.matrix, generic, also)
    except Undecided:
        return _split_drops(system, generic, also)


def _split_drops(system: ScrewSystem, generic: int, also: Any = true) -> list:
    """The cases of ``rank_conditions`` where ``system`` has less than ``generic`` (those of one
    rank merged): exhaustive and disjoint, but a set may come in pieces (points on a conic,
    and the conic with those points left out).

    Where even the first (generic) case is below ``generic``, the system is singular
    everywhere (``also``): a first entry ``(also, rank)``, then the cases below it.
    """
    cases = system.rank_conditions()
    out: list = []
    first = cases[0][1]
    everywhere = first is not None and first < generic
    if everywhere:
        out.append((also, first))
    for cond, rank in cases[1:]:
        if rank is not None and rank >= generic:
            continue
        cond = And(cond, also) if also is not true else cond
        same = [i for i in range(int(everywhere), len(out)) if rank is not None and out[i][1] == rank]
        if same:
            out[same[0]] = (_union(out[same[0]][0], cond), rank)
        else:
            out.append((cond, rank))
    return out


def constraint_count(mech: _Mechanism, seeds: tuple[int, ...] = (1, 2)) -> int:
    """The rank of the constraint system of a regular mechanism of this kind.

    Explanation
    ===========

    The rank of the union of the limbs' constraint systems with each limb at a
    generic configuration of its own (moved through its joints by random
    rational amounts, as :func:`generic_limb_rank`; the largest over ``seeds``),
    at most ``6 - n`` for ``n`` actuators (a regular, non-redundantly actuated
    mechanism has as many freedoms as actuators) and at least the generic rank
    of the mechanism as given.  A planar or a spherical mechanism keeps its
    three constraints wherever its limbs go (they are properties of each limb);
    the 3-UPU's three constraint couples are independent where its limbs are
    generic, and so is the count: 3.

    >>> from sympy import Rational
    >>> from screwsym.systems.parallel import Limb, ParallelMechanism
    >>> from screwsym.systems.joints import R, P
    >>> z = [0, 0, 1]
    >>> legs = [Limb(R([a, b, 0], z), P([c - a, d - b, 0]), R([c, d, 0], z), actuated=1)
    ...         for a, b, c, d in ((0, 0, 1, 1), (3, 0, 2, 1), (0, 3, 1, 2))]
    >>> constraint_count(ParallelMechanism(*legs))      # a planar 3-RPR: its 3 planar constraints
    3
    """
    here = mech.constraints.rank
    cap = max(0, 6 - len(_actuated(mech)))
    if here >= cap:
        return here
    best = here
    for seed in seeds:
        rnd = random.Random(seed)
        wrenches: list = []
        try:
            for limb in mech.limbs:
                values = generic_values(limb, rnd)
                joints = [trig_substitute(j, values) for j in limb.joints]
                moved = _displaced(joints, rnd)
                twists = ScrewSystem(*(t for j in moved for t in j._twists()), kind=Twist)
                wrenches.extend(twists.reciprocal().basis())
        except ValueError:  # a value that degenerates a joint: the next seed
            continue
        best = max(best, min(cap, ScrewSystem(*wrenches, kind=Wrench).rank))
        if best >= cap:
            break
    return best


def _limb_part(limb: _Limb) -> tuple[list, list]:
    """The limb's singular cases and its actuation wrenches (each computed once)."""
    glr = generic_limb_rank(limb)
    part = _drops(limb.twists, glr)
    seen = [c for c, _ in part]
    constraints = list(limb.constraints.basis())
    wrenches = []
    for k in limb.actuated:
        w = limb_actuation_wrench(limb, int(k))
        wrenches.append(w)
        for cond, rank in _drops(ScrewSystem(*constraints, w, kind=Wrench), 6 - glr + 1):
            if cond not in seen:  # a condition already stated for this limb: once
                seen.append(cond)
                part.append((cond, rank))
    return part, wrenches


def mechanism_singularities(mech: _Mechanism, *, budget: int = BUDGET) -> Singularities:
    r"""The three kinds of singularity, as exhaustive conditions on the symbols.

    Explanation
    ===========

    ``limb``: for each limb, the cases where its twist system has less than
    :func:`generic_limb_rank` (it loses a freedom: an R-R leg stretched),
    then for each of its actuated joints the cases where the system of its
    constraints and its actuation wrench has less than ``c + 1`` (the
    actuation wrench falls into the constraints, so the actuator transmits
    nothing: ``w_a o $_a = 0``); a condition stated once per limb, and
    ``limbs`` names the limb of each.  ``constraint``: the cases where the
    mechanism's constraint system has less than :func:`constraint_count`.
    ``actuation``: the cases where the rows of ``Jx`` have less than
    ``min(6, actuators + constraint_count)``, each conjoined with the generic
    condition of the constraint system (so the constraints keep their rank
    there).  The conditions are the rank strata of each system
    (:func:`rank_strata`: the sets where all minors of a size vanish, each
    once, by the fewest equations), or, where those cannot be decided (an
    algebraic field, large minors), the disjoint cases of
    :meth:`ScrewSystem.rank_conditions`, on the systems as written: the actuation wrenches are polynomial in the
    symbols, and where one of them vanishes identically the case is listed too
    (a superset, never a miss).  A first entry ``(True, r)``: singular at
    every configuration (an architecture singularity).  All the splits share
    ``budget`` (:data:`~screwsym.algebra.budget.BUDGET`), past which a
    ``ValueError`` names ``singularities``.

    Examples
    ========

    A five-bar with its elbows at ``(0, 1)`` and ``(3, 1)`` and the end point
    at ``(x, y)`` (a P-P leg keeps the end link from spinning):

    >>> from sympy import symbols
    >>> from screwsym.systems.parallel import Limb, ParallelMechanism
    >>> from screwsym.systems.joints import R, P
    >>> x, y = symbols("x y", real=True)
    >>> z = [0, 0, 1]
    >>> def five_bar(p):
    ...     return ParallelMechanism(Limb(R([0, 0, 0], z), R([0, 1, 0], z), R(p, z), actuated=0),
    ...                              Limb(R([3, 0, 0], z), R([3, 1, 0], z), R(p, z), actuated=0),
    ...                              Limb(P([1, 0, 0]), P([0, 1, 0])))
    >>> s = mechanism_singularities(five_bar([x, y, 0]))
    >>> print(s)
    kind       limb  condition            rank
    ---------  ----  -------------------  ----
    limb       0     Eq(x, 0)             2
    limb       0     Eq(x, 0) & Eq(y, 1)  3
    limb       1     Eq(x, 3)             2
    limb       1     Eq(x, 3) & Eq(y, 1)  3
    actuation        Eq(y, 1)             5

    Leg 0 is stretched or folded where ``x = 0`` (the end point above its base:
    its three axes in one plane, rank 2); its actuation wrench degenerates
    where moreover the end point is its elbow ``(0, 1)``, and leg 1's where the
    end point is its elbow ``(3, 1)``; type II where both distal links lie on
    one line, ``y = 1``.  At a configuration given by numbers each part is
    ``[(True, rank)]`` or ``[]``:

    >>> mechanism_singularities(five_bar([2, 1, 0])).actuation
    [(True, 5)]
    >>> mechanism_singularities(five_bar([1, 2, 0])).actuation
    []
    """
    with case_budget(budget, "singularities"):
        return _singularities(mech)


def _singularities(mech: _Mechanism) -> Singularities:
    pairs = _actuated(mech)
    limb_part: list = []
    limbs: list = []
    wrenches: list = []  # those of actuation_wrenches(mech), each computed once
    for i, limb in enumerate(mech.limbs):
        part, ws = _limb_part(limb) if limb.actuated else (_drops(limb.twists,
                                                                   generic_limb_rank(limb)), [])
        limb_part.extend(part)
        limbs.extend([i] * len(part))
        wrenches.extend(ws)
    W = mech.constraints
    count = constraint_count(mech)
    w_cases = W.rank_conditions()
    constraint_part = _drops(W, count)
    first, first_rank = w_cases[0]
    regular_w = first if first_rank is not None and first_rank >= count else false
    J = ScrewSystem(*wrenches, *W.basis(), kind=Wrench)
    actuation_part = _drops(J, min(6, len(pairs) + count), regular_w) if regular_w is not false \
        else []
    return Singularities(limb=limb_part, actuation=actuation_part, constraint=constraint_part,
                         limbs=tuple(limbs))
