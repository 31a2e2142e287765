r"""Type synthesis: from a wanted motion to the limbs and the mechanisms that produce it.

The constraint-synthesis method (Huang & Li 2002, 2003; Fang & Tsai 2002; Kong &
Gosselin 2004, 2007).  The wanted motion (:func:`motion`: ``"3T"``, ``"3R"``,
``"3T1R"``, ``"2T1R"``) is a twist system ``T_M`` that is the Lie algebra of a
subgroup of rigid motions, so it is the same at every pose the platform reaches;
the platform must feel exactly the wrench system ``W_M = T_M^r``.  A limb may be
used iff its constraint system ``W_L = T_L^r`` lies in ``W_M``, that is iff its
twist system ``T_L`` contains ``T_M``; a mechanism of such limbs has the wanted
motion iff the limbs' constraints together span ``W_M``.

What is enumerated (:func:`limbs`) is a finite grammar of *limb types*: a
sequence of ``kinds`` (R and P joints and parallelograms Pa, at most ``max_joints``)
with, for each joint, an axis direction label (joints with one label are parallel; a
label may be one of the motion's own directions, the ``z`` of 3T1R; a prismatic joint's
or a parallelogram's may be normal to it, "⊥z", kept only where the type with a generic
direction there is not valid: the in-plane slides of planar chains) and, for each
revolute, where its axis passes: anywhere, through the motion's centre (3R), or
through the previous revolute's point (two such axes make a U joint).  With
``perpendicular=True``, a sequence that fails with generic directions is tried again
with one or two pairs of its labels made perpendicular ("4⟂1": joint 4's axis normal
to joint 1's; "3⟂1, 3⟂2": joint 3's axis normal to the plane of joints 1 and 2; "2⟂z"),
and kept with the fewest pairs that make it pass, so that a relation is named only
where the motion needs it (the slides of Kong & Gosselin's spherical legs, normal to
the axes of a planar sub-chain).  Two types
are the same when a relabelling, the reversal of the limb (the same twists read
from the platform), or a reordering of adjacent prismatic joints and parallelograms
(translations commute) maps one to the other.

**Parallelograms.**  A planar parallelogram loop (four hinges along ``h``, two equal
rods) moves its output bar on a *circular translation*: its orientation is kept and
each point runs on a circle in the plane normal to ``h`` (Kong & Gosselin, *Type
Synthesis of Parallel Mechanisms*, Springer 2007, who list the Pa among the joints of
their limbs; the forearms of Clavel's Delta, "DELTA, a fast robot with parallel geometry",
18th ISIR 1988, and of the H4, Pierrot & Company, "H4: a new family of 4-dof parallel
robots", AIM 1999).  So a Pa is modelled as the library's compound pair
:class:`~screwsym.systems.joints.Parallelogram`: one freedom, its twist at the instance
the translation ``v = n x rod`` normal to ``h`` and to the rods, and a label that is the
hinges' direction ``h``.  At first order it is the prismatic joint along ``v``; unlike
one, ``v`` turns with the angle (``dv = n x v`` per unit angle), and that term enters
the second-order check below (and :meth:`Mechanism.second_order`), so a Pa is accepted
only where the turning of its translation stays inside the wanted motion.  The finite
argument is the classical one: the output's orientation never changes, so a limb with
a Pa has at every pose the twist system of the same type (shown in the tests by a
parallelogram closed numerically a finite step away, its coupler's rotation the
identity).  The Delta's (SS)² rod pairs are this Pa with the two rods' spins, idle
freedoms that move no link but the rods.

Every candidate is **checked**, not looked up:
it is instantiated at a random integer (generic) geometry and kept iff, exactly,

1. its twists are independent (no passive freedom) and contain ``T_M``;
2. every joint moves in the wanted motion (no joint is locked by it: joint ``k``
   is active iff ``T_M`` with the other joints' twists has the limb's rank);
3. the motion extends to second order within ``T_M``: for every joint rate
   ``qdot`` with ``J qdot`` in ``T_M`` and every constraint wrench ``w`` of the
   limb, ``sum_{i<j} w o [$_i, $_j] qdot_i qdot_j + sum_k w o dv_k qdot_k^2 = 0``
   (the derivative of the spatial twist of a serial chain is ``J qddot +
   sum_{i<j} [$_i, $_j] qdot_i qdot_j``, plus ``dv_k qdot_k^2`` for a parallelogram
   ``k``, and a path in the subgroup has its derivative in ``T_M``).  This
   rejects arrangements that have the motion only at the configuration drawn
   (an R_a R_b R_a R_b chain is 3T there and not a finite step away).

A type that passes at two independent random instances is returned (the
conditions hold on an open set, so a pass at random points is a pass of the
generic type; a failure of a generic type at two random points has probability
about zero).  The kept limbs are then re-checked by the library's exact screw
systems (:meth:`ScrewSystem.rank`, :meth:`ScrewSystem.contains`).

:func:`mechanisms` repeats each limb type ``limbs`` times, each copy carried by a
random rational motion that keeps ``T_M`` (any rotation and translation for 3T,
rotations about the centre for 3R, rotations about ``z`` and translations for
3T1R and 2T1R), and keeps the design iff the exact analysis of
:meth:`ParallelMechanism.mobility` gives the wanted mobility, motion type and
twist system with no passive freedom; it names an actuated joint per limb (the
same in every limb, the one nearest the base that works) for which the
Jacobian of :func:`~screwsym.systems.actuation.jacobian` is invertible at the
instance (no actuation singularity there), or every such joint
(``every_actuation=True``).  With ``mixed=True`` it assembles unequal limbs instead
(every multiset of the limb types, not all equal), certified the same way.

What is not in the grammar: angles other than parallel and perpendicular, three
mutually perpendicular directions (at most two pairs are tried), lines through two
joints' points (a P along the line of two U centres), helical joints, closed sub-chains
other than the parallelogram, virtual chains for motions that are not subgroups (2R1T,
1T2R, 3T2R); see the notes of the functions.

References
==========

Z. Huang and Q. C. Li, "General methodology for type synthesis of symmetrical
lower-mobility parallel manipulators and several novel manipulators", Int. J.
Robot. Res. 21(2) (2002) 131-145; "Type synthesis of symmetrical lower-mobility
parallel mechanisms using the constraint-synthesis method", Int. J. Robot. Res.
22(1) (2003) 59-79.
Y. Fang and L.-W. Tsai, "Structure synthesis of a class of 4-DoF and 5-DoF
parallel manipulators with identical limb structures", Int. J. Robot. Res.
21(9) (2002) 799-810.
X. Kong and C. M. Gosselin, "Type synthesis of 3-DOF translational parallel
manipulators based on screw theory", ASME J. Mech. Des. 126 (2004) 83-92;
*Type Synthesis of Parallel Mechanisms*, Springer 2007.
"""

from __future__ import annotations

import random
from fractions import Fraction
from itertools import combinations_with_replacement
from typing import Any, NamedTuple

from sympy import ImmutableMatrix, Integer, Rational
from sympy.polys.matrices import DomainMatrix

from ..algebra.budget import BUDGET, bounded, charge
from ..core.screw import Screw
from ..core.twist import Twist
from ._synthesis_exact import check_rows as _check_rows
from ._synthesis_exact import cross as _cross
from .actuation import jacobian
from .joints import Joint, Parallelogram, Prismatic, Revolute
from .linkage import Mechanism
from .parallel import Limb, Mobility, ParallelMechanism
from .screw_system import ScrewSystem
from .second_order import SecondOrder

__all__ = ["Motion", "motion", "LimbType", "limbs", "Design", "mechanisms", "refusals"]

_X, _Y, _Z = (1, 0, 0), (0, 1, 0), (0, 0, 1)
_MSG = ("{name}: the enumeration passed its budget of {budget} units; pass a larger "
        "budget= or fewer max_joints")


class Motion(NamedTuple):
    """A wanted motion: the twist system of a subgroup of rigid motions (:func:`motion`)."""

    name: str  #: "3T", "3R", "3T1R", "2T1R"
    twists: ScrewSystem  #: T_M, the platform's wanted twists
    directions: tuple  #: the motion's own axis directions (the z of 3T1R), integer triples
    center: tuple | None  #: the point every rotation axis passes through (3R), or None
    turns: tuple | None  #: a placement turns about these directions; None: about any
    shifts: bool  #: a placement may translate

    @property
    def dimension(self) -> int:
        """The number of freedoms wanted, ``rank T_M``."""
        return len(self.twists)

    @property
    def wrenches(self) -> ScrewSystem:
        """The wrench system the platform must feel, ``W_M = T_M^r``.

        >>> motion("3T").wrenches         # three couples
        ScrewSystem(Wrench([0, 0, 0], [1, 0, 0]), Wrench([0, 0, 0], [0, 1, 0]), Wrench([0, 0, 0], [0, 0, 1]))
        """
        return self.twists.reciprocal()


def motion(name: str) -> Motion:
    """The wanted motion ``name``: ``"3T"``, ``"3R"`` (about the origin), ``"3T1R"`` (the
    Schoenflies motion, rotation about ``z``) or ``"2T1R"`` (planar motion normal to ``z``).

    >>> m = motion("3T1R")
    >>> m.dimension, m.wrenches.rank, m.directions
    (4, 2, ((0, 0, 1),))
    >>> motion("3R").twists
    ScrewSystem(Twist([1, 0, 0], [0, 0, 0]), Twist([0, 1, 0], [0, 0, 0]), Twist([0, 0, 1], [0, 0, 0]))
    >>> motion("2R1T")
    Traceback (most recent call last):
    ...
    ValueError: name: expected one of '3T', '3R', '3T1R', '2T1R' (motions that are subgroups), got '2R1T'
    """
    def t(*e: tuple) -> list:
        return [Twist.translation(list(v)) for v in e]

    def r(*e: tuple) -> list:
        return [Twist.rotation(list(v), point=[0, 0, 0]) for v in e]

    table = {
        "3T": (t(_X, _Y, _Z), (), None, None, True),
        "3R": (r(_X, _Y, _Z), (), (0, 0, 0), None, False),
        "3T1R": (r(_Z) + t(_X, _Y, _Z), (_Z,), None, (_Z,), True),
        "2T1R": (r(_Z) + t(_X, _Y), (_Z,), None, (_Z,), True),
    }
    if not isinstance(name, str):
        raise TypeError(f"name: expected a str such as '3T', got {type(name).__name__}")
    if name not in table:
        raise ValueError(f"name: expected one of {', '.join(map(repr, table))} (motions that "
                         f"are subgroups), got {name!r}")
    tw, dirs, center, turns, shifts = table[name]
    return Motion(name, ScrewSystem(*tw), dirs, center, turns, shifts)


# ------------------------------------------------------------------ the grammar
#: a joint of a limb type: (kind "R" or "P", direction label, point label of a revolute:
#: "g" anywhere, "c" through the motion's centre, "u" through the previous revolute's point)
_Joint = tuple


def _relabel(seq: tuple, special: int, perp: tuple | None = None) -> Any:
    """The direction labels renumbered in order of first appearance (labels below ``special``,
    the motion's own directions, kept).  With ``perp`` (pairs of perpendicular labels): the
    pair ``(sequence, pairs)``, the pairs renumbered alike, each sorted, in order."""
    names: dict = {}
    perps: dict = {}
    out = []
    for kind, d, p in seq:
        if d < 0:  # normal to the motion's first direction: numbered -1, -2, ...
            perps.setdefault(d, -1 - len(perps))
            out.append((kind, perps[d], p))
            continue
        if d >= special and d not in names:
            names[d] = special + len(names)
        out.append((kind, d if d < special else names[d], p))
    if perp is None:
        return tuple(out)
    pairs = (tuple(sorted(names.get(x, x) for x in pair)) for pair in perp)
    return tuple(out), tuple(sorted(pairs))


def _reversed(seq: tuple) -> tuple:
    """The limb read from the platform: a revolute's mark "u" (through the point of the
    revolute just before it) moves to that revolute."""
    n = len(seq)
    out = []
    for k in range(n - 1, -1, -1):
        kind, d, p = seq[k]
        if kind == "R" and p != "c":
            p = "u" if k + 1 < n and seq[k + 1][2] == "u" else "g"
        out.append((kind, d, p))
    return tuple(out)


def _swaps(seq: tuple) -> list:
    """The sequences one swap of commuting neighbours away: two prismatic joints, or a
    revolute and a prismatic joint along one direction (the revolute in no point relation)."""
    out = []
    for k in range(len(seq) - 1):
        a, b = seq[k], seq[k + 1]
        after = seq[k + 2] if k + 2 < len(seq) else None
        if a[0] in ("P", "Pa") and b[0] in ("P", "Pa"):
            ok = True  # translations commute (a parallelogram's too: its output only translates)
        elif {a[0], b[0]} == {"R", "P"} and a[1] == b[1]:
            r = a if a[0] == "R" else b
            ok = r[2] != "u" and not (b[0] == "R" and after is not None and after[2] == "u")
        else:
            ok = False
        if ok:
            out.append(seq[:k] + (b, a) + seq[k + 2:])
    return out


def _variants(seq: tuple) -> list:
    """``seq`` and every sequence of commuting neighbour swaps from it (a closure, finite)."""
    seen, todo = {seq}, [seq]
    while todo:
        for s in _swaps(todo.pop()):
            if s not in seen:
                seen.add(s)
                todo.append(s)
    return list(seen)


def _canonical(seq: tuple, special: int, perp: Any = None) -> Any:
    """The least equivalent sequence; with ``perp`` (a tuple of pairs of perpendicular labels),
    the least equivalent ``(sequence, pairs)``."""
    forms = []
    for s in (seq, _reversed(seq)):
        for v in _variants(s):
            forms.append(_relabel(v, special, perp))
    return min(forms)


def _groups(seq: tuple) -> list:
    """The runs of revolutes through one point (chained by "u"), as lists of indices."""
    out: list = []
    for k, (kind, _, p) in enumerate(seq):
        if kind == "R" and p == "u":
            out[-1].append(k)
        elif kind == "R":
            out.append([k])
    return [g for g in out if len(g) > 1]


def _spherical_ok(seq: tuple, special: int) -> bool:
    """A run of three revolutes through one point is a spherical joint: its axes are any
    three, so they take fresh labels, found nowhere else; no run of four."""
    for g in _groups(seq):
        if len(g) > 3:
            return False
        if len(g) == 3:
            labels = [seq[k][1] for k in g]
            others = [j[1] for k, j in enumerate(seq) if k not in g]
            if any(d < special or d in others for d in labels):
                return False
    return True


def _candidates(kinds: tuple, n: int, special: int, center: bool):
    """Every joint sequence of length ``n`` of the grammar, canonical labels only."""
    def seqs(prefix: tuple, used: int, normal: int):
        k = len(prefix)
        if k == n:
            if _spherical_ok(prefix, special):
                yield prefix
            return
        for kind in kinds:
            # a prismatic joint may also be normal to the motion's direction (in the plane
            # of a planar motion): labels -1, -2, ...
            # (a parallelogram's label is its hinges' direction)
            extra = range(-1, -normal - 2, -1) if kind in ("P", "Pa") and special else ()
            for d in [*range(special + used + 1), *extra]:
                new = used + (d == special + used)
                if kind in ("P", "Pa"):
                    # two prismatic joints along one direction: one passive freedom
                    if kind == "P" and any(j[0] == "P" and j[1] == d for j in prefix):
                        continue
                    yield from seqs(prefix + ((kind, d, "-"),), new, normal + (d == -normal - 1))
                    continue
                points = ["g"] + (["c"] if center else [])
                last_r = prefix[-1] if prefix and prefix[-1][0] == "R" else None
                if last_r is not None and last_r[2] != "c":
                    points.append("u")
                for p in points:
                    if p == "u" and last_r is not None and last_r[1] == d:
                        continue  # the same axis twice
                    if p == "c" and any(j[0] == "R" and j[1] == d and j[2] == "c" for j in prefix):
                        continue  # the same axis twice
                    yield from seqs(prefix + (("R", d, p),), new, normal)
    yield from seqs((), 0, 0)


# ------------------------------------------------------------------ a generic instance
def _geometry(seq: tuple, mo: Motion, seed: int, perp: tuple = ()) -> list:
    """Integer joint geometry: per joint (kind, direction, point or None); a parallelogram's
    entry is ("Pa", its output's translation v, (p1, bar, rod)) (:func:`_parallelogram`).
    A label in pairs of ``perp`` is drawn normal to the labels drawn before it."""
    rnd = random.Random(seed)
    dirs: dict = {i: d for i, d in enumerate(mo.directions)}

    def vec(lo: int = -40, hi: int = 40) -> tuple:
        while True:
            v = tuple(rnd.randint(lo, hi) for _ in range(3))
            if any(v):
                return v

    def normal_to(e: tuple) -> tuple:
        while True:
            v = _cross(e, vec())
            if any(v):
                return v

    out: list[tuple[str, tuple, Any]] = []
    last: Any = None
    for kind, d, p in seq:
        if d not in dirs:
            partners = [dirs[e] for pair in perp if d in pair for e in pair if e != d and e in dirs]
            if d < 0:
                dirs[d] = normal_to(mo.directions[0])
            elif not partners:
                dirs[d] = vec()
            elif len(partners) == 1:
                dirs[d] = normal_to(partners[0])
            elif len(partners) == 2 and any(_cross(*partners)):
                dirs[d] = _cross(*partners)
            else:
                raise ValueError("perpendicular: a direction normal to three directions, or to "
                                 "two parallel ones, is not drawn generically")
        u = dirs[d]
        if kind == "P":
            out.append(("P", u, None))
            continue
        if kind == "Pa":
            bar = normal_to(u)
            rod = normal_to(u)
            while not any(_cross(bar, rod)):  # pragma: no cover - a flat draw
                rod = normal_to(u)
            p1 = vec(-200, 200)
            out.append(("Pa", _cross(_cross(bar, rod), rod), (p1, bar, rod)))
            continue
        if p == "c":
            pt = mo.center
        elif p == "u":
            pt = last
        else:
            pt = vec(-200, 200)
        last = pt
        out.append(("R", u, pt))
    return out


def _twist_rows(geom: list) -> list:
    rows = []
    for kind, u, pt in geom:
        rows.append(u + _cross(pt, u) if kind == "R" else (0, 0, 0) + u)
    return rows


def _acc_rows(geom: list) -> dict:
    """A parallelogram's own term of the second order: its output's translation ``v = n x rod``
    turns with its angle, ``dv = n x v`` (:class:`~screwsym.systems.joints.Parallelogram`)."""
    out = {}
    for k, (kind, v, extra) in enumerate(geom):
        if kind == "Pa":
            n = _cross(extra[1], extra[2])
            out[k] = (0, 0, 0) + _cross(n, v)
    return out


def _motion_rows(mo: Motion) -> list:
    return [tuple(int(x) for x in t.matrix) for t in mo.twists]


# ------------------------------------------------------------------ limb types
class LimbType(NamedTuple):
    """A limb type: joints with relations between their axes, for a wanted motion (:func:`limbs`).

    ``joints`` holds, per joint, ``(kind, direction label, point label)``: the kind ``"R"``,
    ``"P"`` or ``"Pa"`` (a parallelogram, whose label is its hinges' direction); joints
    with one direction label are parallel (labels below ``len(motion.directions)`` are the
    motion's own directions, negative labels directions normal to its first one); a
    revolute's point label is ``"g"`` (anywhere), ``"c"`` (through the motion's centre) or
    ``"u"`` (through the previous revolute's point).  ``perpendicular`` holds pairs of
    labels whose directions are normal to each other (a label in two pairs is normal to a
    plane).
    """

    motion: Motion
    joints: tuple
    perpendicular: tuple = ()

    @property
    def freedom(self) -> int:
        """The number of joints, each of one freedom."""
        return len(self.joints)

    @property
    def letters(self) -> str:
        """The joints in the literature's letters: U for two revolutes with one point, C for a
        revolute and a prismatic joint along one direction.

        >>> [t.letters for t in limbs(motion("3T"), max_joints=4)][:3]
        ['PPP', 'CPR', 'CRR']
        """
        out, k, j = [], 0, self.joints
        while k < len(j):
            kind, d, _ = j[k]
            e = k + 1
            while kind == "R" and e < len(j) and j[e][0] == "R" and j[e][2] == "u":
                e += 1
            if e - k in (2, 3):  # two or three revolutes through one point
                out.append("U" if e - k == 2 else "S")
                k = e
                continue
            nxt = j[k + 1] if k + 1 < len(j) else None
            if (e == k + 1 and nxt is not None and {kind, nxt[0]} == {"R", "P"} and nxt[1] == d
                    and not (kind == "P" and k + 2 < len(j) and j[k + 2][2] == "u")):
                out.append("C")
                k += 2
                continue
            out.append(kind * (e - k))
            k = e
        return "".join(out)

    @property
    def relations(self) -> str:
        """The relations between the axes, joints numbered from 1 at the base.

        >>> motion_3t = motion("3T")
        >>> upu = LimbType(motion_3t, (("R", 0, "g"), ("R", 1, "u"), ("P", 2, "-"),
        ...                            ("R", 1, "g"), ("R", 0, "u")))
        >>> upu.letters, upu.relations
        ('UPU', '1∥5, 2∥4')
        """
        special = len(self.motion.directions)
        names = ["x", "y", "z"]
        groups: dict = {}
        for i, (_, d, _) in enumerate(self.joints, 1):
            groups.setdefault(d, []).append(str(i))
        parts = []
        for d, idx in sorted(groups.items(), key=lambda g: (g[0] >= special, int(g[1][0]))):
            if d < 0:
                axis = self.motion.directions[0]
                label = names[axis.index(1)] if sorted(axis) == [0, 0, 1] else str(axis)
                parts.append("∥".join(idx) + f"⊥{label}")
            elif d < special:
                axis = self.motion.directions[d]
                label = names[axis.index(1)] if sorted(axis) == [0, 0, 1] else str(axis)
                parts.append("∥".join(idx) + f"∥{label}")
            elif len(idx) > 1:
                parts.append("∥".join(idx))
        first = {d: idx[0] for d, idx in groups.items()}
        for a, b in self.perpendicular:  # each label named by its first joint, z by its name
            if a < special:
                axis = self.motion.directions[a]
                label = names[axis.index(1)] if sorted(axis) == [0, 0, 1] else str(axis)
                parts.append(f"{first[b]}⟂{label}")
            else:
                parts.append(f"{first[b]}⟂{first[a]}")
        through = [str(i) for i, j in enumerate(self.joints, 1) if j[2] == "c"]
        if through:
            parts.append(",".join(through) + " through O")
        return ", ".join(parts)

    @property
    def name(self) -> str:
        """The type's name: letters and relations, e.g. ``"PRRR (2∥3∥4)"``."""
        rel = self.relations
        return f"{self.letters} ({rel})" if rel else self.letters

    def __repr__(self) -> str:
        return f"LimbType({self.motion.name}: {self.name})"

    def instance(self, seed: int = 0, actuated: Any = None) -> Limb:
        """A generic instance as a :class:`~screwsym.systems.parallel.Limb`: integer directions
        and points drawn from ``random.Random(seed)``, the relations kept.

        >>> t = [t for t in limbs(motion("3T"), max_joints=4) if t.letters == "PRRR"][0]
        >>> leg = t.instance(seed=3)
        >>> t.name, leg.freedom, leg.constraints.rank
        ('PRRR (2∥3∥4)', 4, 2)

        A parallelogram is built as the compound pair
        :class:`~screwsym.systems.joints.Parallelogram` (its hinges along its label's
        direction, its twist the translation of its output bar); a perpendicular relation
        is kept:

        >>> delta = LimbType(motion("3T"), (("R", 0, "g"), ("Pa", 1, "-"), ("R", 0, "g"),
        ...                                 ("R", 0, "g")), ((0, 1),))
        >>> leg = delta.instance()
        >>> delta.name, [type(j).__name__ for j in leg.joints]
        ('RPaRR (1∥3∥4, 2⟂1)', ['Revolute', 'Parallelogram', 'Revolute', 'Revolute'])
        >>> pa, u = leg.joints[1], leg.joints[0].args[1]
        >>> pa.normal.dot(u)     # the Delta's hinges, normal to the arm's axis
        0
        """
        geom = self._generic(seed)
        joints: list[Joint] = []
        for k, u, p in geom:
            if k == "P":
                joints.append(Prismatic(list(u)))
            elif k == "Pa":  # the compound pair: its twist is the translation u
                p1, bar, rod = p
                joints.append(Parallelogram(list(p1), [x + y for x, y in zip(p1, bar, strict=True)],
                                            [x + y for x, y in zip(p1, rod, strict=True)]))
            else:
                joints.append(Revolute(list(p), list(u)))
        return Limb(*joints, actuated=actuated)

    def _generic(self, seed: int) -> list:
        own = {d for _, d, _ in self.joints if d >= 0}
        for pair in self.perpendicular:
            if (len(pair) != 2 or not set(pair) <= own | set(range(len(self.motion.directions)))
                    or not set(pair) & own or pair[0] == pair[1]):
                raise ValueError(f"perpendicular: expected pairs of two direction labels of the "
                                 f"joints (or of the motion's), got {pair!r}")
        G = _motion_rows(self.motion)
        for attempt in range(20):  # a random point is generic but on a proper subset
            geom = _geometry(self.joints, self.motion, 7919 * seed + attempt, self.perpendicular)
            if _check_rows(_twist_rows(geom), G, _acc_rows(geom)) is None:
                return geom
        # twenty random points on the subset: not a limb type of the motion
        raise ValueError(f"seed: no generic instance of {self.name} found for {self.motion.name}")

    def build(self, seed: int = 0, actuated: Any = None) -> Limb:
        """The same as :meth:`instance`."""
        return self.instance(seed, actuated)


def _rational_row(t: Screw) -> tuple:
    if not all(isinstance(x, Rational) for x in t.matrix):
        raise ValueError("obj: expected rational geometry (no symbols, no roots): the "
                         "checks are made at numbers; substitute values first")
    return tuple(Fraction(int(x.p), int(x.q)) for x in t.matrix)


def _limb_rows(limb: Limb) -> tuple[list, dict]:
    """The limb's joint twists as rational rows, and the parallelograms' own terms (by row)."""
    rows: list = []
    acc: dict = {}
    for j in limb.joints:
        for t, a in zip(j.twists, j._accelerations(), strict=True):
            if a is not None:
                acc[len(rows)] = _rational_row(a)
            rows.append(_rational_row(t))
    return rows, acc


def refusals(obj: Limb | ParallelMechanism, mo: Motion) -> tuple[str, ...]:
    """Why a rational limb or mechanism does not give the motion ``mo``; ``()`` if it does.

    A limb: the checks 1-3 of the module docstring.  A mechanism: each limb's, then the
    exact analysis of :meth:`ParallelMechanism.mobility` (the mobility, the motion type, the
    platform's twists equal to ``T_M``, no passive freedom), then, if all of those pass,
    its second order (every motion extends, one branch).

    >>> from screwsym.systems.joints import P, R
    >>> z = [0, 0, 1]
    >>> prrr = Limb(P([1, 2, 3]), R([0, 0, 0], z), R([1, 0, 0], z), R([0, 2, 0], z))
    >>> refusals(prrr, motion("3T1R"))
    ()
    >>> tilted = Limb(P([1, 2, 3]), R([0, 0, 0], z), R([1, 0, 0], [0, 1, 1]), R([0, 2, 0], z))
    >>> refusals(tilted, motion("3T1R"))
    ('limb: its twists do not contain the wanted motion',)
    """
    if not isinstance(mo, Motion):
        raise TypeError(f"mo: expected a Motion (synthesis.motion('3T')), got {type(mo).__name__}")
    if isinstance(obj, Limb):
        rows, acc = _limb_rows(obj)
        why = _check_rows(rows, _motion_rows(mo), acc)
        return () if why is None else (f"limb: {why}",)
    if not isinstance(obj, ParallelMechanism):
        raise TypeError(f"obj: expected a Limb or a ParallelMechanism, got {type(obj).__name__}")
    out = [f"limbs[{i}]: {w.split(': ', 1)[1]}" for i, leg in enumerate(obj.limbs)
           for w in refusals(leg, mo)]
    mob = obj.mobility()
    out += _mechanism_refusals(mob, mo)
    if not out:
        out += _second_order_refusals(Mechanism.from_parallel(obj).second_order(), mo)
    return tuple(out)


def _second_order_refusals(so: SecondOrder, mo: Motion) -> list[str]:
    """The mechanism's motions to second order (Müller 2016): all of them, one branch."""
    if so.mobility != mo.dimension or so.several_branches is not False:
        return [f"to second order: mobility {so.mobility}, {so.branches} branches "
                f"(wanted {mo.dimension}, one)"]
    return []


def _mechanism_refusals(mob: Mobility, mo: Motion) -> list[str]:
    out: list[str] = []
    if mob.mobility != mo.dimension:
        out.append(f"mobility {mob.mobility}, wanted {mo.dimension}")
    if mob.motion != mo.name:
        out.append(f"motion {mob.motion}, wanted {mo.name}")
    elif (mob.twists | mo.twists).rank != mo.dimension:
        out.append("the platform's twists are not the wanted ones")
    if mob.passive:
        out.append(f"{mob.passive} passive freedoms")
    return out


def _verdict(seq: tuple, mo: Motion, G: list, seed: int, perp: tuple = ()) -> tuple[bool, Any]:
    """The verdict of two of three random points (a generic type passes at a random point but
    on a proper algebraic subset), and the reason the first point gave."""
    passes = fails = 0
    first: Any = False
    for s in (1, 2, 3):
        geom = _geometry(seq, mo, 1000 * seed + s, perp)
        why = _check_rows(_twist_rows(geom), G, _acc_rows(geom))
        if first is False:
            first = why
        passes += why is None
        fails += why is not None
        if passes == 2 or fails == 2:
            break
    return passes == 2, first


#: the failures a perpendicular relation may cure; ranks only drop on a special geometry, so a
#: generic type whose twists are dependent, or whose joint is locked, stays so
_CURABLE = ("its twists do not contain the wanted motion",
            "its motion does not extend to second order within the wanted motion")


def _perpendicular_sets(seq: tuple, special: int) -> list:
    """Sets of one or two pairs of perpendicular labels of ``seq`` (each pair with a label of
    the limb's own; the motion's directions may be the other), sets of one first."""
    labels = sorted({d for _, d, _ in seq if d >= special} | set(range(special)))
    turning = {d for k, d, _ in seq if k == "R"}
    # a slide or a parallelogram normal to the motion's direction is a label of its own (-1)
    pairs = [(a, b) for i, a in enumerate(labels) for b in labels[i + 1:]
             if b >= special and (a >= special or b in turning)]
    ones = [(p,) for p in pairs]
    twos = [(p, q) for i, p in enumerate(pairs) for q in pairs[i + 1:]]
    return ones + twos


def limbs(mo: Motion, kinds: tuple = ("R", "P"), max_joints: int = 5, min_joints: int | None = None,
          *, seed: int = 0, perpendicular: bool = False, budget: int = BUDGET) -> tuple[LimbType, ...]:
    """Every limb type of the grammar (module docstring) whose limbs give the motion ``mo``.

    Limbs of ``min_joints`` (default: the motion's dimension) to ``max_joints`` one-freedom
    joints of ``kinds`` (``"R"``, ``"P"``, ``"Pa"``: a parallelogram), each type checked
    exactly at two random instances (``seed``) and by the library's screw systems, one per
    equivalence class (relabelling, reversal, adjacent prismatic joints and parallelograms
    reordered), sorted by length then name.  With ``perpendicular``, a sequence that fails
    with generic directions is tried again with one or two pairs of its directions made
    perpendicular (an axis normal to another, or to a plane), kept with the fewest pairs
    that make it pass: a relation is named only where it is needed.
    At most ``budget`` units (a ``ValueError`` naming ``limbs`` beyond).

    >>> [t.name for t in limbs(motion("3R"), max_joints=3)]
    ['RRR (1,2,3 through O)']
    >>> [t.name for t in limbs(motion("3T"), max_joints=3)]
    ['PPP']

    The Delta's limb (Clavel 1988): a revolute, a parallelogram, two revolutes parallel to
    the first (the parallelogram's hinges in any direction; the Delta's are normal to it):

    >>> [t.name for t in limbs(motion("3T"), kinds=("R", "Pa"), max_joints=4)
    ...  if t.letters == "RPaRR"]
    ['RPaRR (1∥3∥4)']
    """
    if not isinstance(mo, Motion):
        raise TypeError(f"mo: expected a Motion (synthesis.motion('3T')), got {type(mo).__name__}")
    kinds = tuple(kinds)
    if not kinds or any(k not in ("R", "P", "Pa") for k in kinds):
        raise ValueError(f"kinds: expected a non-empty tuple of 'R', 'P' and 'Pa', got {kinds!r}")
    lo = mo.dimension if min_joints is None else min_joints
    if not isinstance(max_joints, int) or not 1 <= max_joints <= 6:
        raise ValueError(f"max_joints: expected an integer from 1 to 6, got {max_joints!r}")
    if not isinstance(lo, int) or lo < 1:
        raise ValueError(f"min_joints: expected a positive integer, got {min_joints!r}")
    special = len(mo.directions)
    G = _motion_rows(mo)
    found: dict = {}
    special_cases: dict = {}
    with bounded(budget, "limbs", _MSG):
        for n in range(max(lo, mo.dimension), max_joints + 1):
            for seq in _candidates(kinds, n, special, mo.center is not None):
                charge(200 * n)
                key = _canonical(seq, special)
                if key in found or key != seq:
                    continue
                ok, why = _verdict(seq, mo, G, seed)
                if ok:
                    found[key] = LimbType(mo, key)
                    continue
                if not perpendicular or why not in _CURABLE:
                    continue
                cured: list = []
                for rel in _perpendicular_sets(seq, special):
                    if len(rel) == 2 and any((p,) in cured for p in rel):
                        continue  # not the fewest pairs
                    charge(200 * n)
                    pkey = _canonical(seq, special, rel)
                    if pkey in special_cases:
                        cured.append(rel)
                        continue
                    try:
                        ok, _ = _verdict(seq, mo, G, seed, rel)
                    except ValueError:  # a label normal to two parallel ones: not drawn
                        continue
                    if ok:
                        cured.append(rel)
                        special_cases[pkey] = LimbType(mo, *pkey)
        # a prismatic joint normal to the motion's direction is kept only where it is needed:
        # the type with that relation dropped (a generic direction) is not found
        valid = set(found)
        for key in [k for k in found if any(j[1] < 0 for j in k)]:
            free = 1 + max([special - 1, *(j[1] for j in key)])
            for d in {j[1] for j in key if j[1] < 0}:
                loose = tuple((k, free if e == d else e, q) for k, e, q in key)
                if _canonical(loose, special) in valid:
                    del found[key]
                    break
        out = []
        for t in [*found.values(), *special_cases.values()]:
            charge(20_000)
            leg = t.instance(seed)
            T = leg.twists
            # the library's exact screw systems agree: independent twists containing T_M
            if T.rank != t.freedom or not all(T.contains(x) for x in mo.twists):
                raise AssertionError(f"limbs: {t.name}: the exact screw systems disagree")  # pragma: no cover
            out.append(t)
    return tuple(sorted(out, key=lambda t: (t.freedom, t.name)))


#: :func:`limbs`, for :func:`mechanisms` (whose argument ``limbs`` is the number of limbs)
_limbs = limbs


# ------------------------------------------------------------------ mechanisms
class Design(NamedTuple):
    """A certified mechanism (:func:`mechanisms`): ``limbs`` copies of one limb type."""

    limb: LimbType  #: the limb type, repeated
    mechanism: ParallelMechanism  #: the generic instance (actuated joints named, if found)
    mobility: Mobility  #: its exact analysis
    actuated: int | None  #: the actuated joint of every limb, or None if none was found
    #: its motions to second order (:meth:`Mechanism.second_order`): all of
    #: ``mobility.mobility``, one branch
    second_order: SecondOrder
    #: every joint index that, actuated in every limb, makes the Jacobian invertible at the
    #: instance (``mechanisms(..., every_actuation=True)``; otherwise ``actuated`` alone)
    actuations: tuple = ()
    #: the limb types, base limb first, of a design of unequal limbs
    #: (``mechanisms(..., mixed=True)``); ``()`` when every limb is ``limb``
    limb_types: tuple = ()

    @property
    def name(self) -> str:
        """``"3-UPU (1∥5, 2∥4)"``: the number of limbs and the limb type; for unequal limbs,
        each type with its number, ``"2-PPP + 1-CRR (1∥2∥3∥4)"``."""
        if not self.limb_types:
            return f"{len(self.mechanism.limbs)}-{self.limb.name}"
        counts: dict = {}
        for t in self.limb_types:
            counts[t.name] = counts.get(t.name, 0) + 1
        return " + ".join(f"{k}-{n}" for n, k in counts.items())

    def __repr__(self) -> str:
        return f"Design({self.name}, actuated={self.actuated})"


def _quaternion_rotation(q: tuple) -> ImmutableMatrix:
    a, b, c, d = (Integer(x) for x in q)
    n = a * a + b * b + c * c + d * d
    return ImmutableMatrix([
        [a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
        [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
        [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d],
    ]) / n


def _placement(mo: Motion, rnd: random.Random) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    """A random rational rigid motion that keeps ``T_M``: (rotation, translation)."""
    a = rnd.randint(1, 6)
    if mo.turns is None:
        q = (a, rnd.randint(-6, 6), rnd.randint(-6, 6), rnd.randint(-6, 6))
    else:  # about z
        q = (a, 0, 0, rnd.randint(-6, 6))
    Rm = _quaternion_rotation(q)
    shift = ImmutableMatrix([rnd.randint(-9, 9) for _ in range(3)]) if mo.shifts \
        else ImmutableMatrix([0, 0, 0])
    return Rm, shift


def _placed(leg: Limb, Rm: ImmutableMatrix, shift: ImmutableMatrix, actuated: Any) -> Limb:
    joints: list[Joint] = []
    for j in leg.joints:
        if isinstance(j, Prismatic):
            joints.append(Prismatic(Rm * j.args[0]))
        elif isinstance(j, Parallelogram):
            joints.append(Parallelogram(*(Rm * x + shift for x in j.args)))
        else:
            joints.append(Revolute(Rm * j.args[0] + shift, Rm * j.args[1]))
    return Limb(*joints, actuated=actuated)


def _mechanism(t: LimbType | tuple, count: int, seed: int, actuated: Any) -> ParallelMechanism:
    """``count`` copies of ``t``, or the limbs of the types ``t`` (a tuple), each after the
    first carried by a random placement that keeps the motion."""
    kinds = t if isinstance(t, tuple) and not isinstance(t, LimbType) else (t,) * count
    rnd = random.Random(seed)
    first = {k: k.instance(seed) for k in set(kinds)}
    legs = [first[k] if i == 0 else _placed(first[k], *_placement(k.motion, rnd), None)
            for i, k in enumerate(kinds)]
    if actuated is not None:
        legs = [Limb(*x.joints, actuated=actuated) for x in legs]
    return ParallelMechanism(*legs)


def _actuation_ok(mech: ParallelMechanism) -> bool:
    Jx, _ = jacobian(mech)
    if Jx.rows != Jx.cols:
        return False
    return DomainMatrix.from_Matrix(Jx).rank() == Jx.rows


def mechanisms(mo: Motion, limbs: int = 3, *, types: Any = None, kinds: tuple = ("R", "P"),
               max_joints: int = 5, seed: int = 0, actuate: bool = True,
               perpendicular: bool = False, every_actuation: bool = False,
               mixed: bool = False, budget: int = BUDGET) -> tuple[Design, ...]:
    """Symmetrical mechanisms of ``limbs`` equal limbs that give the motion ``mo``, certified.

    ``types`` are the limb types to try (default: :func:`limbs` of ``mo``, ``kinds`` and
    ``max_joints``).  Each design's generic instance is analysed exactly
    (:meth:`ParallelMechanism.mobility`) and kept iff its mobility is ``mo.dimension``, its
    motion type ``mo.name`` and its twists ``T_M``, with no passive freedom, and all of its
    motions extend to second order in one branch
    (:meth:`~screwsym.systems.linkage.Mechanism.second_order`, Müller 2016).  With
    ``actuate``, the first joint index (from the base) that, actuated in every limb,
    makes the Jacobian invertible at the instance is named (``None`` if none does); with
    ``every_actuation``, every such index is tried and listed in ``Design.actuations``.
    ``perpendicular`` is passed to :func:`limbs`.  With ``mixed``, the designs are the
    asymmetric ones instead: every multiset of ``limbs`` of the types, not all equal
    (``Design.limb_types``; the actuated joint, the same index in every limb).
    At most ``budget`` units (a ``ValueError`` naming ``mechanisms`` beyond); each design is
    charged 200,000 units (its analysis takes about 0.1 s), so the default covers about a
    hundred limb types: the 152 of 3T1R with five joints need ``budget=10**8``.

    >>> [d.name for d in mechanisms(motion("3R"), max_joints=3)]
    ['3-RRR (1,2,3 through O)']
    >>> d = mechanisms(motion("3R"), max_joints=3)[0]
    >>> d.mobility.mobility, d.mobility.motion, d.actuated
    (3, '3R', 0)
    """
    if not isinstance(mo, Motion):
        raise TypeError(f"mo: expected a Motion (synthesis.motion('3T')), got {type(mo).__name__}")
    if not isinstance(limbs, int) or isinstance(limbs, bool) or limbs < 1:
        raise ValueError(f"limbs: expected a positive integer, got {limbs!r}")
    out = []
    with bounded(budget, "mechanisms", _MSG):
        pool = types if types is not None else _limbs(mo, kinds, max_joints, seed=seed,
                                                          perpendicular=perpendicular,
                                                          budget=budget)
        pool = tuple(pool)
        for t in pool:
            if not isinstance(t, LimbType) or t.motion != mo:
                raise TypeError(f"types: expected limb types of the motion {mo.name}, got {t!r}")
        combos: Any = pool
        if mixed:
            combos = [c for c in combinations_with_replacement(pool, limbs) if len(set(c)) > 1]
        for combo in combos:
            t = combo[0] if mixed else combo
            charge(200_000)
            mech = _mechanism(combo, limbs, seed, None)
            mob = mech.mobility()
            if _mechanism_refusals(mob, mo):
                continue
            so = Mechanism.from_parallel(mech).second_order()
            if _second_order_refusals(so, mo):
                continue
            works: list[int] = []
            if actuate and limbs == mo.dimension:  # one actuated joint per limb
                for k in range(min(x.freedom for x in combo) if mixed else t.freedom):
                    charge(100_000)
                    if _actuation_ok(_mechanism(combo, limbs, seed, k)):
                        works.append(k)
                        if not every_actuation:
                            break
            act = works[0] if works else None
            final = _mechanism(combo, limbs, seed, act) if act is not None else mech
            out.append(Design(t, final, mob, act, so, tuple(works), combo if mixed else ()))
    return tuple(out)


