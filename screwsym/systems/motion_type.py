r"""The motion type of a twist system: how many translations, rotations and helical freedoms.

:func:`motion_of` reads what a platform's twists move, the label a reader of the
literature expects ("3T1R" for the Schoenflies motion, "1H" with its pitch for a
helical freedom), with the directions of each part; :func:`motion_type` writes the
label.  Exact: ranks are proved (:mod:`screwsym.algebra.linalg`), and on a case that
no substitution states (a surface ``f = 0``) modulo ``f``
(:func:`motion_on_surface`).

References
==========

K. H. Hunt, *Kinematic Geometry of Mechanisms*, Oxford 1978, Ch. 12; Huang, Li &
Ding, *Theory of Parallel Mechanisms*, Springer 2013, Sections 1.6 and 5.
"""

from __future__ import annotations

import random
from typing import Any, NamedTuple

from sympy import (
    ImmutableMatrix,
    cancel,
)
from sympy.polys.matrices import DomainMatrix

from ..algebra.circle import sample_point
from ..algebra.linalg import SEEDS, cramer_vectors, primitive_vector
from ..algebra.rings import PolyColumns, to_expr, to_ring
from ..algebra.surface import null_on_surface, zero_on_surface
from ._rank_cases import analysis
from .screw_system import ScrewSystem

__all__ = [
    "MotionType",
    "motion_type",
    "motion_of",
]


def motion_type(rotations: int, translations: int, helical: int = 0) -> str:
    """``"3T1R"``, ``"1T2R"``, ``"3T"``, ``"1R"``, ``"1H"``; ``"0"`` for a structure.

    Translations first, then rotations, then helical freedoms, as the
    literature writes them ("3T1R" for the Schoenflies motion).  ``helical``
    counts those of the ``rotations`` (independent angular velocities) that are
    helical: they cannot be made rotations (pitch 0) by adding translations of
    the system (see :func:`motion_of`).

    >>> motion_type(2, 1), motion_type(1, 3), motion_type(0, 3), motion_type(0, 0)
    ('1T2R', '3T1R', '3T', '0')
    >>> motion_type(1, 0, helical=1), motion_type(2, 0, helical=1)
    ('1H', '1R1H')
    """
    for value, name in ((rotations, "rotations"), (translations, "translations"),
                        (helical, "helical")):
        if isinstance(value, bool) or not isinstance(value, int) or value < 0:
            raise ValueError(f"{name}: expected a non-negative integer, got {value!r}")
    if helical > rotations:
        raise ValueError(f"helical: expected at most rotations = {rotations}, got {helical}")
    pure = rotations - helical
    text = "".join(f"{n}{x}" for n, x in ((translations, "T"), (pure, "R"), (helical, "H")) if n)
    return text or "0"


class MotionType(NamedTuple):
    """What a twist system moves (:func:`motion_of`): counts, directions, helical pitches."""

    motion: str | None  #: the label of :func:`motion_type`, e.g. "3T1R", "1H"; None: undecided
    rotations: int  #: independent angular velocities (helical freedoms included)
    translations: int  #: independent pure translations (twists with omega = 0)
    helical_pitches: tuple | None  #: the pitch of each helical freedom; None: undecided
    rotation_directions: ImmutableMatrix  #: 3 x rotations: independent angular velocities
    translation_directions: ImmutableMatrix  #: 3 x translations: the pure translations


def motion_of(twists: ScrewSystem) -> MotionType:
    r"""The motion type of a twist system: translations, rotations and helical freedoms.

    Explanation
    ===========

    ``rotations`` is the rank of the angular velocities ``omega`` of the
    system's twists and ``translations`` the dimension of its pure
    translations ``P`` (its twists with ``omega = 0``).  A rotational freedom
    is *helical* when no translation of ``P`` turns it into a rotation
    (pitch 0).  On the twists of the system whose ``omega`` is orthogonal to
    every translation of ``P`` (the others become rotations by adding one),
    the pitch form ``q(x) = omega . v`` is well defined modulo ``P``;
    measured against ``omega . omega``, its eigenvalues are the principal
    pitches of that part of the system (Hunt 1978, Ch. 12; Huang, Li & Ding
    2013, §1.6).  If the form takes both signs, its zero-pitch twists
    (rotations) span that part and there is no helical freedom; if it is
    semidefinite of rank ``h``, ``h`` freedoms are helical, with the
    non-zero principal pitches as ``helical_pitches``.  Generic in the
    symbols, like the ranks.  With symbols and two or more such dimensions,
    the sign of the form may depend on the symbols' values (it is not a
    generic property: it can take either sign on open sets): where SymPy's
    assumptions cannot decide the sign of a coefficient of its characteristic
    polynomial, ``motion`` and ``helical_pitches`` are None ("cannot
    decide"); the counts and directions are still given.  Substitute values
    (or give the symbols assumptions) to decide.

    Examples
    ========

    >>> from screwsym import ScrewSystem, Twist
    >>> helix = Twist.screw_motion([0, 0, 1], point=[1, 0, 0], pitch=3)
    >>> motion_of(ScrewSystem(helix)).motion, motion_of(ScrewSystem(helix)).helical_pitches
    ('1H', (3,))
    >>> moves = [Twist.translation(e) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
    >>> motion_of(ScrewSystem(helix, *moves)).motion        # the helix splits: Schoenflies
    '3T1R'
    >>> motion_of(ScrewSystem(helix, moves[0])).motion      # a translation across the axis
    '1T1H'
    """
    zeros = ImmutableMatrix.zeros(3, 0)
    if not len(twists):
        return MotionType(motion_type(0, 0), 0, 0, (), zeros, zeros)
    omega = twists.matrix[:3, :]
    spin = analysis(ImmutableMatrix.vstack(omega, ImmutableMatrix.zeros(3, omega.cols)))
    rotations = spin.rank
    translations = twists.rank - rotations
    # the pure translations the platform has: its twists with omega = 0 (generic, polynomial)
    moves = pure_translations(twists.matrix, rotations) if translations else zeros
    pitches = helical_pitches(twists, moves) if rotations else ()
    return MotionType(
        motion=None if pitches is None else motion_type(rotations, translations, len(pitches)),
        rotations=rotations,
        translations=translations,
        helical_pitches=pitches,
        rotation_directions=ImmutableMatrix(omega.extract([0, 1, 2], list(spin.pivots))),
        translation_directions=ImmutableMatrix(moves),
    )


def motion_on_surface(twists: ScrewSystem, fe: Any) -> MotionType | None:
    """:func:`motion_of` at the generic point of the surface ``fe = 0``, for independent twists.

    The ranks and null spaces of :func:`motion_of` proved modulo ``fe``
    (``null_on_surface``).  The helical test is made for one rotation left once
    the translations are taken off (its pitch zero modulo ``fe`` or not); with
    two or more, ``motion`` and ``helical_pitches`` are None (the sign of the
    pitch form is not decided on a surface).  None where no point of the
    surface proved a rank.
    """
    empty = ImmutableMatrix.zeros(3, 0)
    if not len(twists):
        return MotionType(motion_type(0, 0), 0, 0, (), empty, empty)
    T = twists.matrix
    omega = ImmutableMatrix(T[:3, :])
    found = null_on_surface(omega, fe)
    if found is None:  # pragma: no cover - no point of the surface proved the rank
        return None
    rotations, members, null = found
    moves = ImmutableMatrix(T[3:, :]) * null if null.cols else empty
    pitches: tuple | None = ()
    if rotations:
        X = T
        C = (moves.T * X[:3, :]).applyfunc(cancel) if moves.cols else None
        if C is not None and not zero_on_surface(list(C), fe):
            # the twists whose omega is orthogonal to every translation (see helical_pitches)
            kept = null_on_surface(ImmutableMatrix(C), fe)
            if kept is None:  # pragma: no cover - no point of the surface proved the rank
                return None
            X = (X * kept[2]).applyfunc(cancel)
        spin = null_on_surface(ImmutableMatrix(X[:3, :]), fe)
        if spin is None:  # pragma: no cover - no point of the surface proved the rank
            return None
        X = X.extract(list(range(6)), list(spin[1]))  # one twist per rotation, modulo moves
        if X.cols == 1:
            pitch = cancel(X[:3, 0].dot(X[3:, 0]) / X[:3, 0].dot(X[:3, 0]))
            pitches = () if zero_on_surface([pitch], fe) else (pitch,)
        elif X.cols:
            pitches = None
    return MotionType(
        motion=None if pitches is None else motion_type(rotations, T.cols - rotations,
                                                        len(pitches)),
        rotations=rotations,
        translations=T.cols - rotations,
        helical_pitches=pitches,
        rotation_directions=ImmutableMatrix(omega.extract([0, 1, 2], list(members))),
        translation_directions=ImmutableMatrix(moves),
    )


def helical_pitches(twists: ScrewSystem, moves: ImmutableMatrix) -> tuple | None:
    """The pitches of the helical freedoms of ``twists`` (translations ``moves``): see motion_of.

    None where the sign of the pitch form cannot be decided.
    """
    from sympy import Dummy, Poly, roots
    X = twists.matrix
    C = (moves.T * X[:3, :]).applyfunc(cancel) if moves.cols else None
    if C is not None and any(e != 0 for e in C):
        # the twists whose omega is orthogonal to every translation (reciprocal to the
        # couples along them: a twist (w; v) and a couple (0; d) have product w . d): the
        # combinations X a of the system's twists with C a = 0, generic in the symbols as the
        # ranks are (a small null space, not the reciprocal of a reciprocal system)
        basis = C.nullspace(simplify=cancel)
        if not basis:
            return ()
        X = ImmutableMatrix.hstack(*(X * v for v in basis)).applyfunc(cancel)
    spin = analysis(ImmutableMatrix.vstack(X[:3, :], ImmutableMatrix.zeros(3, X.cols)))
    X = X.extract(list(range(6)), list(spin.pivots))  # one twist per rotation, modulo moves
    k = X.cols
    if k == 0:
        return ()
    W, V = X[:3, :], X[3:, :]
    M = W.T * V
    Q = ImmutableMatrix(k, k, lambda i, j: cancel((M[i, j] + M[j, i]) / 2))
    G = ImmutableMatrix(k, k, lambda i, j: cancel(W.col(i).dot(W.col(j))))
    h = analysis(ImmutableMatrix.vstack(Q, ImmutableMatrix.zeros(6 - k, k))).rank
    if h == 0:
        return ()
    if k == 1:
        return (cancel(Q[0, 0] / G[0, 0]),)
    lam = Dummy("lambda")
    p = Poly(cancel((Q - lam * G).det(method="berkowitz")), lam)
    p = Poly(p.as_expr() / lam ** (k - h), lam)  # the zero pitches are rotations
    c = [cancel(x) for x in p.all_coeffs()]  # real-rooted: Q, G symmetric, G > 0
    # p is real-rooted, so Descartes' rule of signs counts its positive roots exactly (zero
    # coefficients skipped): the pitches are all of one sign (a semidefinite form) iff the
    # coefficients of p(lam) or of p(-lam) do not change sign
    # coefficients of undecided sign cannot undo a change between two of known sign
    signs = [0 if x.is_zero else 1 if x.is_positive else -1 if x.is_negative else None
             for x in c]
    changes = [len({x for x in seq if x}) > 1 for seq in (
        signs, [None if x is None else (-1) ** i * x for i, x in enumerate(signs)])]
    if all(changes):  # indefinite: spanned by rotations
        return ()
    if None in signs:
        return None  # the form's sign cannot be decided: see the docstring
    found = roots(p, lam)
    if sum(found.values()) < h and not p.free_symbols - {lam}:  # pragma: no cover - quintics
        return tuple(p.all_roots())
    return tuple(r for r, n in found.items() for _ in range(n))


def pure_translations(T: ImmutableMatrix, rotations: int) -> ImmutableMatrix:
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
    rg = to_ring(ImmutableMatrix.vstack(T[:3, :], ImmutableMatrix.zeros(3, k)))
    R, K = rg.ring, rg.ring.domain
    A = [[rg.cols[j][i] for j in range(k)] for i in range(3)]  # the omega rows
    for seed in SEEDS:
        point = sample_point(R, random.Random(seed))
        A0 = DomainMatrix([[a(*point) if a else K.zero for a in row] for row in A], (3, k), K)
        _, rows = A0.transpose().rref()
        if len(rows) == rotations:
            break
    _, cols = A0.extract(list(rows), list(range(k))).rref()
    vectors = [primitive_vector(v, R) for v in cramer_vectors(A, rows, cols, R, width=k)]
    xs = ImmutableMatrix([[to_expr(e, R) for e in v] for v in vectors]).T
    # y in the null space of the omega block with its columns scaled by D (``to_ring``
    # clears denominators column by column): D y in the null space of the block itself
    moves = (ImmutableMatrix(T[3:, :]) * _column_scales(T, rg, R) * xs).applyfunc(cancel)
    return ImmutableMatrix(moves)


def _column_scales(T: ImmutableMatrix, rg: PolyColumns, R) -> ImmutableMatrix:
    """The diagonal of the factors ``to_ring`` multiplied the columns of ``T``'s omega block by."""
    k = T.cols
    d = []
    for j in range(k):
        i = next((i for i in range(3) if T[i, j] != 0), None)
        d.append(1 if i is None else cancel(to_expr(rg.cols[j][i], R) / T[i, j]))
    return ImmutableMatrix.diag(*d) if k else ImmutableMatrix.zeros(0, 0)
