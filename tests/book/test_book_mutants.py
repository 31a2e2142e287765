"""Every entry of the book registry kills the wrong versions of the operations it uses.

Explanation
===========

``MUTANTS`` is a table of broken versions of the public core operations (a sign
flipped, a term dropped, an argument swapped, a predicate that always answers
the same).  Each mutant is applied with ``monkeypatch`` where the registry
reads the operation: functions through the package namespace (``ss.pitch``),
constructors and methods on the classes (``Screw.from_axis``,
``Twist.velocity_at``).

``KILLS`` declares, for every entry, the mutants it must kill.  The tests

* run every entry against each mutant it declares and assert that the entry
  FAILS (a check fails, or the construction raises a library error);
* trace every call an entry's construction makes to a core operation, work out
  each mutant's answer on the same arguments, and assert that every mutant that
  changes an answer the entry receives is declared in ``KILLS`` or excused in
  ``SURVIVES`` with the reason (a mutant that answers the same on every call,
  such as the pitch of a couple doubled, cannot be seen by that entry), and
  that nothing is declared that the entry cannot see;
* assert that every entry kills at least one mutant and every mutant is killed
  by some entry, and that each excused pair really survives.

The entries run with ``stop_at_failure`` and each mutant is applied once for all
the entries that declare it.
"""

from __future__ import annotations

import functools
from collections import defaultdict

import pytest
from sympy import ImmutableMatrix, Matrix, S, cancel, expand, zeros
from sympy.matrices import MatrixBase

import screwsym as ss
from screwsym import LineVector, Screw, Twist, Wrench
from screwsym.book import entries, entry
from screwsym.core.screw import foot as _foot

#: the mutation harness takes about a minute: CI runs it (--slow), the default run does not
pytestmark = pytest.mark.slow

def _m(v) -> ImmutableMatrix:
    return ImmutableMatrix(Matrix(v))


# ---------------------------------------------------------------- operations
#: name -> (owner, attribute, how): how is "function", "classmethod" or "method"
OPS = {
    **{name: (ss, name, "function") for name in (
        "pitch", "axis", "foot", "decompose_screw", "classify", "shift_origin", "reciprocal_product",
        "is_reciprocal", "distance_to_origin", "direction_cosines", "unit", "contains",
        "mutual_moment", "is_coplanar", "common_normal", "power")},
    "from_axis": (Screw, "from_axis", "classmethod"),
    "through": (Screw, "through", "classmethod"),
    "couple": (Screw, "couple", "classmethod"),
    "Twist.rotation": (Twist, "rotation", "classmethod"),
    "Twist.translation": (Twist, "translation", "classmethod"),
    "Twist.screw_motion": (Twist, "screw_motion", "classmethod"),
    "Wrench.force": (Wrench, "force", "classmethod"),
    "velocity_at": (Twist, "velocity_at", "method"),
    "moment_about": (Wrench, "moment_about", "method"),
    "add": (Screw, "__add__", "method"),
    "scale": (Screw, "__mul__", "method"),
    "neg": (Screw, "__neg__", "method"),
}


def _real(op):
    owner, attr, how = OPS[op]
    if how == "classmethod":
        return owner.__dict__[attr].__func__
    if how == "method":
        return owner.__dict__[attr]
    return getattr(owner, attr)


def _install(monkeypatch, op, fn):
    owner, attr, how = OPS[op]
    if how == "classmethod":
        monkeypatch.setattr(owner, attr, classmethod(fn))
    else:
        monkeypatch.setattr(owner, attr, fn)
        if attr == "__mul__":
            monkeypatch.setattr(owner, "__rmul__", fn)


# ------------------------------------------------------------------- mutants
# Each mutant: name -> (operation, factory); factory(real) returns the broken version.
def _cn_fields(cn):
    return cn.a12, cn.normal, cn.alpha12, cn.foot1, cn.foot2


def _cn(real, change):
    def broken(l1, l2):
        return ss.CommonNormal(*change(l1, l2, *_cn_fields(real(l1, l2))))

    return broken


def _parallel(l1, l2) -> bool:
    return _m(l1.S).cross(_m(l2.S)).applyfunc(lambda e: e.expand()) == zeros(3, 1)


def _intersecting(l1, l2) -> bool:
    return not _parallel(l1, l2) and (
        (_m(l1.S).dot(_m(l2.S0)) + _m(l2.S).dot(_m(l1.S0))).expand() == 0)


def _classify_map(table):
    def factory(real):
        return lambda s: table.get(real(s), real(s))

    return factory


MUTANTS = {
    # pitch (1.34)
    "pitch doubled": ("pitch", lambda real: lambda s: 2 * real(s)),
    "pitch sign flipped": ("pitch", lambda real: lambda s: -real(s)),
    # axis (1.35), (1.36): (S; S0 - h S)
    "axis moment negated": ("axis", lambda real: lambda s: LineVector(real(s).S, -real(s).S0)),
    "axis direction reversed": ("axis", lambda real: lambda s: LineVector(-real(s).S, real(s).S0)),
    # foot (1.16)
    "foot sign flipped": ("foot", lambda real: lambda s: -real(s)),
    "foot not divided by S.S": ("foot", lambda real: lambda s: real(s) * _m(s.S).dot(_m(s.S))),
    # decompose (1.37)
    "decompose couple negated": ("decompose_screw", lambda real: lambda s: (real(s)[0], -real(s)[1])),
    "decompose parts swapped": ("decompose_screw", lambda real: lambda s: tuple(reversed(real(s)))),
    # classify (table after 1.38)
    "classify always screw": ("classify", lambda real: lambda s: "screw"),
    "classify line and couple swapped": ("classify", _classify_map({"line": "couple",
                                                                    "couple": "line"})),
    "classify never undecided": ("classify", _classify_map({None: "screw"})),
    "classify zero as couple": ("classify", _classify_map({"zero": "couple"})),
    # shift_origin (1.32): S^A = S0 + AO x S = S0 - A x S
    "shift_origin the wrong way": (
        "shift_origin", lambda real: lambda s, A: type(s)(s.S, _m(s.S0) + _m(A).cross(_m(s.S)))),
    "shift_origin does nothing": ("shift_origin", lambda real: lambda s, A: s),
    "shift_origin adds A": (
        "shift_origin", lambda real: lambda s, A: Screw(real(s, A).S, real(s, A).S0 + _m(A))),
    # reciprocal product (1.45)
    "reciprocal_product drops S2.S01": (
        "reciprocal_product", lambda real: lambda a, b: _m(a.S).dot(_m(b.S0))),
    "reciprocal_product sign flipped": ("reciprocal_product", lambda real: lambda a, b: -real(a, b)),
    "is_reciprocal always True": ("is_reciprocal", lambda real: lambda a, b: True),
    "is_reciprocal always False": ("is_reciprocal", lambda real: lambda a, b: False),
    # (1.18), (1.5)
    "distance_to_origin squared": ("distance_to_origin", lambda real: lambda s: real(s) ** 2),
    "distance_to_origin not divided by |S|": (
        "distance_to_origin",
        lambda real: lambda s: real(s) * _m(s.S).dot(_m(s.S)) ** S.Half),
    "direction_cosines not normalised": ("direction_cosines", lambda real: lambda s: _m(s.S)),
    "direction_cosines sign flipped": ("direction_cosines", lambda real: lambda s: -real(s)),
    "unit not normalised": ("unit", lambda real: lambda s: s),
    # Section 1.3
    "contains always True": ("contains", lambda real: lambda s, p: True),
    "contains always False": ("contains", lambda real: lambda s, p: False),
    "mutual_moment sign flipped": ("mutual_moment", lambda real: lambda a, b: -real(a, b)),
    "mutual_moment drops S2.S01": (
        "mutual_moment", lambda real: lambda a, b: _m(a.S).dot(_m(b.S0))),
    "is_coplanar always True": ("is_coplanar", lambda real: lambda a, b: True),
    "is_coplanar always False": ("is_coplanar", lambda real: lambda a, b: False),
    "common_normal drops line 1's position": (
        "common_normal", lambda real: lambda a, b: real(LineVector(a.S, [0, 0, 0]), b)),
    "common_normal feet from line 1's foot": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (d, n, al, f1 - _foot(a), f2 - _foot(a)))),
    "common_normal normal reversed": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (d, -n, al, f1, f2))),
    "common_normal alpha12 negated": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (d, n, -al, f1, f2))),
    "common_normal feet swapped": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (d, n, al, f2, f1))),
    "common_normal a12 doubled": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (2 * d, n, al, f1, f2))),
    "common_normal parallel: normal reversed": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (d, -n if _parallel(a, b) else n, al, f1, f2))),
    "common_normal parallel: foot 2 slid along line 2": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (d, n, al, f1, f2 + b.S if _parallel(a, b) else f2))),
    "common_normal parallel: alpha12 always 0": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (d, n, 0 if _parallel(a, b) else al, f1, f2))),
    "common_normal intersecting: normal reversed": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2: (d, -n if _intersecting(a, b) else n, al, f1, f2))),
    "common_normal intersecting: feet at the foot points": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2:
        (d, n, al, *((_foot(a), _foot(b)) if _intersecting(a, b) else (f1, f2))))),
    # Sections 1.6, 1.7
    "power sign of f.v_O flipped": (
        "power", lambda real: lambda t, w: _m(t.S).dot(_m(w.S0)) - _m(w.S).dot(_m(t.S0))),
    "power drops omega.C_O": ("power", lambda real: lambda t, w: _m(w.S).dot(_m(t.S0))),
    # constructors (every kind)
    "from_axis moment sign flipped": (
        "from_axis", lambda real: lambda cls, point, direction, pitch=0, *, magnitude=1:
        real(cls, -_m(point), direction, pitch, magnitude=magnitude)),
    "from_axis pitch term negated": (
        "from_axis", lambda real: lambda cls, point, direction, pitch=0, *, magnitude=1:
        real(cls, point, direction, -pitch, magnitude=magnitude)),
    "from_axis magnitude only on S": (
        "from_axis", lambda real: lambda cls, point, direction, pitch=0, *, magnitude=1:
        cls(magnitude * _m(direction), real(cls, point, direction, pitch).S0)),
    "through points swapped": ("through", lambda real: lambda cls, A, B: real(cls, B, A)),
    "through moment sign flipped": (
        "through", lambda real: lambda cls, A, B: real(cls, -_m(A), _m(B) - 2 * _m(A))),
    "couple in the primary part": ("couple", lambda real: lambda cls, C: cls(C, [0, 0, 0])),
    "couple sign flipped": ("couple", lambda real: lambda cls, C: real(cls, -_m(C))),
    "Twist.rotation moment sign flipped": (
        "Twist.rotation", lambda real: lambda cls, omega, *, point:
        real(cls, omega, point=-_m(point))),
    "Twist.translation parts swapped": (
        "Twist.translation", lambda real: lambda cls, v: cls(v, [0, 0, 0])),
    "Twist.screw_motion pitch negated": (
        "Twist.screw_motion", lambda real: lambda cls, omega, *, point, pitch:
        real(cls, omega, point=point, pitch=-pitch)),
    "Wrench.force moment sign flipped": (
        "Wrench.force", lambda real: lambda cls, f, *, point: real(cls, f, point=-_m(point))),
    # methods
    "velocity_at sign of omega x P flipped": (
        "velocity_at", lambda real: lambda self, point: 2 * _m(self.v_O) - real(self, point)),
    "moment_about sign of A x f flipped": (
        "moment_about", lambda real: lambda self, point: 2 * _m(self.C_O) - real(self, point)),
    "add subtracts the dual parts": (
        "add", lambda real: lambda self, other:
        real(self, other) if not isinstance(other, Screw) else
        type(real(self, other))(_m(self.S) + _m(other.S), _m(self.S0) - _m(other.S0))),
    "scale leaves the dual part": (
        "scale", lambda real: lambda self, k:
        type(real(self, k))(k * _m(self.S), _m(self.S0)) if k != 0 else real(self, k)),
    "neg keeps the dual part": ("neg", lambda real: lambda self: Screw(-_m(self.S), self.S0)),
}


def _apply(monkeypatch, name):
    op, factory = MUTANTS[name]
    _install(monkeypatch, op, factory(_real(op)))


def _mutants_of(op):
    return [m for m, (o, _) in MUTANTS.items() if o == op]


# --------------------------------------------------------------- declarations
#: for an (entry, mutant) pair that the entry cannot see although it calls the
#: mutant's operation: why.
_REFLECTED = ("every check relates the lines' own coordinates; the moment-flipped from_axis "
              "builds the line through -r instead of r, a reflection of the whole figure in O "
              "under which the statement is invariant; (1.9), (1.10), (1.15), (1.19) pin it")
_PITCH_OF_AXIS = ("the pitch does not depend on the axis point, so from_axis with its moment "
                  "flipped has the same pitch; (1.38) pins from_axis")
SURVIVES: dict[tuple[str, str], str] = {
    ("1.1", "through moment sign flipped"): "(1.1) is the direction S only; (1.9) pins the moment",
    ("1.2", "through moment sign flipped"): "direction ratios only; (1.9) pins the moment",
    ("1.3", "through moment sign flipped"): "direction only; (1.9) pins the moment",
    ("1.4", "through points swapped"): "|S| = |AB| is symmetric in A and B",
    ("1.4", "through moment sign flipped"): "|S| does not involve the moment",
    ("1.5", "from_axis moment sign flipped"): "direction cosines depend on S only",
    ("1.6", "from_axis moment sign flipped"): "direction cosines depend on S only",
    ("1.6", "direction_cosines sign flipped"): "l^2 + m^2 + n^2 is even in (l, m, n); (1.5) "
                                                "pins the sign",
    ("Derivation of 1.16", "from_axis moment sign flipped"): _REFLECTED,
    ("1.17", "from_axis moment sign flipped"): _REFLECTED,
    ("1.18", "from_axis moment sign flipped"): "|S0|/|S| is even in S0",
    ("Special case S0=0", "from_axis moment sign flipped"):
        "the counter-example only asks that r1 x S does not vanish, true of -r1 x S too",
    ("Homogeneity", "foot sign flipped"): "compares foot(lambda L) with foot(L): the same "
                                          "wrong foot on both sides; (1.16) pins foot",
    ("1.21", "common_normal alpha12 negated"): "(1.21) does not involve alpha12; (1.24) pins it",
    ("1.24", "common_normal feet from line 1's foot"): "(1.24) does not involve the feet; "
                                                       "(1.21), (1.25) pin them",
    ("1.24", "common_normal feet swapped"): "(1.24) does not involve the feet; (1.21) pins them",
    ("1.27", "mutual_moment sign flipped"): "(1.27) asks only whether M vanishes; (1.25) pins "
                                            "its sign",
    ("1.30", "from_axis moment sign flipped"): "S_A = S_B + AB x S holds for every line; (1.29) "
                                               "pins the line's moment",
    ("1.32", "from_axis pitch term negated"): "both sides of the pin are built with from_axis "
                                              "and the same pitch; (1.38) pins the pitch term",
    ("1.46", "from_axis pitch term negated"): "both sides of the pin are built with from_axis "
                                              "and the same pitch; (1.38) pins the pitch term",
    ("1.34", "from_axis moment sign flipped"): _PITCH_OF_AXIS,
    ("1.34", "shift_origin the wrong way"): "the pitch is unchanged by any change of S0 "
                                            "perpendicular to S; (1.32), (1.33) pin the shift",
    ("1.34", "shift_origin does nothing"): "the pitch of the unshifted screw is the same; "
                                           "(1.32), (1.33) pin the shift",
    ("1.34", "couple sign flipped"): "the pitch of (0; -C) is oo as well",
    ("Theorem 1.1", "pitch doubled"): "the theorem is about pitch zero or not; (1.34), (1.40) "
                                      "pin the value",
    ("Theorem 1.1", "pitch sign flipped"): "the theorem is about pitch zero or not; (1.34), "
                                           "(1.40) pin the value",
    ("Theorem 1.1", "from_axis moment sign flipped"): _REFLECTED,
    ("Line vector plus couple", "from_axis moment sign flipped"): _PITCH_OF_AXIS,
    ("1.44", "pitch doubled"): "compares pitch(mu s) with pitch(s); (1.34) pins pitch",
    ("1.44", "pitch sign flipped"): "compares pitch(mu s) with pitch(s); (1.34) pins pitch",
    ("1.44", "foot sign flipped"): "compares foot(mu s) with foot(s); (1.16) pins foot",
    ("1.45", "from_axis moment sign flipped"): _REFLECTED,
    ("1.54", "from_axis moment sign flipped"): _PITCH_OF_AXIS,
    ("1.57", "from_axis moment sign flipped"): "the axis through O is unchanged, and the "
                                               "counter-example only asks for a non-zero value",
}

#: entry id -> the mutants it must kill (each checked by the tests below)
KILLS: dict[str, tuple[str, ...]] = {
    '1.1': ('through points swapped',),
    '1.2': ('through points swapped',),
    '1.3': ('through points swapped',),
    '1.4': ('direction_cosines not normalised', 'direction_cosines sign flipped'),
    '1.5': ('direction_cosines not normalised', 'direction_cosines sign flipped'),
    '1.6': ('direction_cosines not normalised',),
    '1.7': ('contains always False', 'contains always True', 'from_axis moment sign flipped'),
    '1.8': ('from_axis moment sign flipped',),
    '1.9': (
        'from_axis moment sign flipped', 'through moment sign flipped', 'through points swapped',
    ),
    '1.10': ('from_axis moment sign flipped',),
    'Homogeneity': (
        'foot not divided by S.S', 'from_axis moment sign flipped', 'scale leaves the dual part',
    ),
    '1.11': ('from_axis moment sign flipped',),
    '1.12': ('from_axis moment sign flipped',),
    '1.13': ('from_axis moment sign flipped',),
    '1.14': ('from_axis moment sign flipped',),
    '1.15': ('from_axis moment sign flipped',),
    'Derivation of 1.16': ('foot not divided by S.S', 'foot sign flipped'),
    '1.16': ('foot not divided by S.S', 'foot sign flipped', 'from_axis moment sign flipped'),
    '1.17': ('foot not divided by S.S', 'foot sign flipped'),
    '1.18': ('distance_to_origin not divided by |S|', 'distance_to_origin squared'),
    'Special case S0=0': ('contains always False', 'contains always True'),
    'Special case S=0': (
        'classify always screw', 'classify line and couple swapped', 'pitch sign flipped',
        'scale leaves the dual part', 'shift_origin adds A',
    ),
    '1.19': ('from_axis moment sign flipped',),
    '1.20': ('from_axis moment sign flipped',),
    '1.21': (
        'common_normal a12 doubled', "common_normal drops line 1's position",
        "common_normal feet from line 1's foot", 'common_normal feet swapped',
        'common_normal normal reversed', 'from_axis moment sign flipped',
        'mutual_moment drops S2.S01', 'mutual_moment sign flipped',
    ),
    '1.22': (
        'from_axis moment sign flipped', 'mutual_moment drops S2.S01', 'mutual_moment sign flipped',
    ),
    '1.23': (
        'from_axis moment sign flipped', 'mutual_moment drops S2.S01', 'mutual_moment sign flipped',
    ),
    '1.24': (
        'common_normal a12 doubled', 'common_normal alpha12 negated',
        "common_normal drops line 1's position", 'common_normal normal reversed',
        'from_axis moment sign flipped',
    ),
    '1.25': (
        'common_normal a12 doubled', 'common_normal alpha12 negated',
        "common_normal drops line 1's position", "common_normal feet from line 1's foot",
        'common_normal feet swapped', 'common_normal normal reversed',
        'from_axis moment sign flipped', 'mutual_moment drops S2.S01', 'mutual_moment sign flipped',
    ),
    '1.26': ('mutual_moment drops S2.S01', 'mutual_moment sign flipped'),
    '1.27': (
        'common_normal a12 doubled', 'common_normal alpha12 negated',
        "common_normal drops line 1's position", "common_normal feet from line 1's foot",
        'common_normal feet swapped', 'common_normal intersecting: feet at the foot points',
        'common_normal intersecting: normal reversed', 'common_normal normal reversed',
        'common_normal parallel: alpha12 always 0',
        'common_normal parallel: foot 2 slid along line 2',
        'common_normal parallel: normal reversed', 'from_axis moment sign flipped',
        'is_coplanar always False', 'is_coplanar always True', 'mutual_moment drops S2.S01',
    ),
    '1.28': (
        'contains always False', 'contains always True', 'from_axis moment sign flipped',
        'neg keeps the dual part',
    ),
    '1.29': (
        'from_axis moment sign flipped', 'shift_origin adds A', 'shift_origin does nothing',
        'shift_origin the wrong way',
    ),
    '1.30': ('shift_origin adds A', 'shift_origin does nothing', 'shift_origin the wrong way'),
    'Fig. 1.5': ('from_axis moment sign flipped', 'mutual_moment sign flipped'),
    '1.31': ('classify always screw', 'classify line and couple swapped'),
    '1.32': (
        'Wrench.force moment sign flipped', 'from_axis moment sign flipped', 'shift_origin adds A',
        'shift_origin does nothing', 'shift_origin the wrong way',
    ),
    '1.33': ('shift_origin adds A', 'shift_origin does nothing', 'shift_origin the wrong way'),
    '1.34': (
        'couple in the primary part', 'from_axis pitch term negated', 'pitch doubled',
        'pitch sign flipped', 'shift_origin adds A',
    ),
    '1.35': (
        'add subtracts the dual parts', 'axis direction reversed', 'axis moment negated',
        'decompose couple negated', 'decompose parts swapped',
    ),
    '1.36': (
        'contains always False', 'contains always True', 'foot not divided by S.S',
        'foot sign flipped',
    ),
    '1.37': ('add subtracts the dual parts', 'decompose couple negated', 'decompose parts swapped'),
    '1.38': (
        'add subtracts the dual parts', 'axis direction reversed', 'axis moment negated',
        'contains always False', 'contains always True', 'couple in the primary part',
        'couple sign flipped', 'from_axis moment sign flipped', 'from_axis pitch term negated',
        'pitch doubled', 'pitch sign flipped',
    ),
    'Classification': (
        'classify always screw', 'classify line and couple swapped', 'classify never undecided',
        'classify zero as couple', 'pitch doubled', 'pitch sign flipped',
    ),
    'Example 1.1': (
        'axis direction reversed', 'contains always False', 'contains always True', 'pitch doubled',
        'pitch sign flipped',
    ),
    'Example 1.2': (
        'axis direction reversed', 'contains always False', 'contains always True', 'pitch doubled',
        'pitch sign flipped',
    ),
    'Example 1.3': (
        'axis direction reversed', 'contains always False', 'contains always True',
        'couple in the primary part', 'couple sign flipped', 'pitch doubled', 'pitch sign flipped',
        'unit not normalised',
    ),
    'Example 1.4': (
        'axis direction reversed', 'axis moment negated', 'distance_to_origin not divided by |S|',
        'distance_to_origin squared', 'foot not divided by S.S', 'foot sign flipped',
        'pitch doubled', 'pitch sign flipped', 'scale leaves the dual part',
    ),
    '1.39': ('add subtracts the dual parts',),
    'Theorem 1.1': (
        'add subtracts the dual parts', 'classify always screw', 'classify line and couple swapped',
        'mutual_moment drops S2.S01', 'mutual_moment sign flipped',
    ),
    '1.40': (
        'add subtracts the dual parts', 'from_axis moment sign flipped',
        'mutual_moment drops S2.S01', 'mutual_moment sign flipped', 'pitch doubled',
        'pitch sign flipped', 'reciprocal_product drops S2.S01', 'reciprocal_product sign flipped',
    ),
    'Theorem 1.2': (
        'add subtracts the dual parts', 'classify always screw', 'classify zero as couple',
        'contains always False', 'contains always True', 'from_axis moment sign flipped',
    ),
    '1.41': (
        'add subtracts the dual parts', 'contains always False', 'contains always True',
        'from_axis moment sign flipped',
    ),
    '1.42': ('contains always False', 'contains always True', 'from_axis moment sign flipped'),
    '1.43': ('add subtracts the dual parts', 'from_axis moment sign flipped'),
    'Line vector plus couple': (
        'add subtracts the dual parts', 'classify always screw', 'classify line and couple swapped',
        'couple in the primary part', 'couple sign flipped', 'pitch doubled', 'pitch sign flipped',
    ),
    'Theorem 1.3': (
        'add subtracts the dual parts', 'classify always screw', 'classify line and couple swapped',
        'classify zero as couple', 'couple in the primary part', 'couple sign flipped',
    ),
    '1.44': (
        'classify always screw', 'classify zero as couple', 'foot not divided by S.S',
        'scale leaves the dual part',
    ),
    '1.45': (
        'Wrench.force moment sign flipped', 'add subtracts the dual parts',
        'couple in the primary part', 'couple sign flipped', 'is_reciprocal always False',
        'is_reciprocal always True', 'mutual_moment drops S2.S01', 'mutual_moment sign flipped',
        'pitch doubled', 'pitch sign flipped', 'power drops omega.C_O',
        'power sign of f.v_O flipped', 'reciprocal_product drops S2.S01',
        'reciprocal_product sign flipped', 'velocity_at sign of omega x P flipped',
    ),
    '1.46': (
        'from_axis moment sign flipped', 'shift_origin adds A', 'shift_origin does nothing',
        'shift_origin the wrong way',
    ),
    '1.47': (
        'reciprocal_product drops S2.S01', 'reciprocal_product sign flipped', 'shift_origin adds A',
        'shift_origin does nothing', 'shift_origin the wrong way',
    ),
    '1.48': (
        'Twist.rotation moment sign flipped', 'from_axis magnitude only on S',
        'from_axis moment sign flipped',
    ),
    '1.49': (
        'from_axis magnitude only on S', 'from_axis moment sign flipped',
        'velocity_at sign of omega x P flipped',
    ),
    '1.50': ('from_axis magnitude only on S', 'from_axis moment sign flipped'),
    '1.51': ('from_axis magnitude only on S', 'from_axis moment sign flipped'),
    'Translation twist': ('Twist.translation parts swapped', 'shift_origin adds A'),
    '1.52': (
        'Twist.screw_motion pitch negated', 'Twist.translation parts swapped',
        'add subtracts the dual parts', 'from_axis magnitude only on S',
        'from_axis moment sign flipped', 'from_axis pitch term negated',
    ),
    '1.53': (
        'from_axis magnitude only on S', 'from_axis moment sign flipped',
        'from_axis pitch term negated', 'velocity_at sign of omega x P flipped',
    ),
    '1.54': (
        'from_axis magnitude only on S', 'from_axis pitch term negated', 'pitch doubled',
        'pitch sign flipped',
    ),
    '1.55': ('Wrench.force moment sign flipped', 'moment_about sign of A x f flipped'),
    '1.56': ('Wrench.force moment sign flipped', 'add subtracts the dual parts'),
    'Wrench decomposition': (
        'add subtracts the dual parts', 'couple in the primary part', 'couple sign flipped',
        'decompose couple negated', 'decompose parts swapped', 'from_axis magnitude only on S',
        'from_axis moment sign flipped', 'from_axis pitch term negated',
    ),
    '1.57': ('from_axis magnitude only on S', 'from_axis pitch term negated'),
    '1.58': (
        'from_axis magnitude only on S', 'from_axis moment sign flipped',
        'from_axis pitch term negated', 'moment_about sign of A x f flipped', 'pitch doubled',
        'pitch sign flipped',
    ),
    'Counting: lines': ('foot sign flipped', 'from_axis moment sign flipped'),
    'Counting: unit line vectors': (
        'foot sign flipped', 'from_axis moment sign flipped', 'neg keeps the dual part',
    ),
    'Counting: unit screws': ('from_axis moment sign flipped', 'from_axis pitch term negated'),
    'Counting: screws': (
        'from_axis moment sign flipped', 'from_axis pitch term negated',
        'scale leaves the dual part',
    ),
}


# ------------------------------------------------------------------- tracing
def _same(a, b) -> bool:
    """Do two answers of an operation agree (structurally, or as an exact zero difference)?"""
    if isinstance(a, tuple) and isinstance(b, tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, Screw) and isinstance(b, Screw):
        return type(a) is type(b) and _same(a.matrix, b.matrix)
    if isinstance(a, ss.CommonNormal) and isinstance(b, ss.CommonNormal):
        return all(_same(x, y) for x, y in zip(a.args, b.args, strict=True))
    if a is None or b is None or isinstance(a, (bool, str)) or isinstance(b, (bool, str)):
        return a == b
    if a == b:
        return True
    try:
        d = a - b
        if isinstance(d, MatrixBase):
            return all(cancel(expand(x)) == 0 for x in d)
        return cancel(expand(d)) == 0
    except (TypeError, ValueError):
        return False


def _answer(fn, args, kwargs):
    try:
        return fn(*args, **kwargs)
    except Exception as exc:  # a mutant that raises where the real one answers differs
        return ("raised", type(exc).__name__)


@functools.cache
def _visible() -> dict[str, frozenset[str]]:
    """For each entry, the mutants that change an answer its construction gets.

    Every operation is wrapped; on each call the real answer is compared with
    the answer of each mutant of that operation on the same arguments.  A
    mutant that answers the same on every call an entry makes cannot be seen by
    that entry (the pitch of a couple doubled is still oo).
    """
    mp = pytest.MonkeyPatch()
    seen: set[str] = set()
    quiet: list[bool] = []
    broken = {m: factory(_real(op)) for m, (op, factory) in MUTANTS.items()}
    try:
        for op in OPS:
            real = _real(op)
            mine = [m for m in _mutants_of(op)]

            def wrap(*a, __real=real, __mine=mine, **k):
                answer = __real(*a, **k)
                if quiet:  # called by a mutant being compared: not a call of the entry
                    return answer
                quiet.append(True)
                try:
                    for m in __mine:
                        if m not in seen and not _same(answer, _answer(broken[m], a, k)):
                            seen.add(m)
                finally:
                    quiet.pop()
                return answer

            _install(mp, op, wrap)
        out = {}
        for e in entries():
            seen.clear()
            e.construct()
            out[e.id] = frozenset(seen)
        return out
    finally:
        mp.undo()


# --------------------------------------------------------------------- tests
def test_every_entry_declares_what_it_kills():
    missing = [e.id for e in entries() if not KILLS.get(e.id)]
    assert not missing, f"entries that kill no broken operation: {missing}"
    unknown = {m for ms in KILLS.values() for m in ms} - set(MUTANTS)
    assert not unknown


def test_every_visible_mutant_is_declared():
    """A mutant that changes an answer an entry gets is declared killed or excused."""
    gaps = [(i, m) for i, ms in _visible().items() for m in sorted(ms)
            if m not in KILLS.get(i, ()) and (i, m) not in SURVIVES]
    assert not gaps, gaps


def test_declared_mutants_change_what_the_entry_sees():
    visible = _visible()
    wrong = [(i, m) for i, ms in KILLS.items() for m in ms if m not in visible[i]]
    wrong += [(i, m) for (i, m) in SURVIVES if m not in visible[i]]
    assert not wrong, wrong


def test_every_mutant_is_killed_somewhere():
    declared = {m for ms in KILLS.values() for m in ms}
    assert set(MUTANTS) <= declared, set(MUTANTS) - declared


def _by_mutant() -> dict[str, list[str]]:
    out = defaultdict(list)
    for id_, ms in KILLS.items():
        for m in ms:
            out[m].append(id_)
    return out


@pytest.mark.parametrize("mutant", sorted(MUTANTS))
def test_mutant_is_killed_by_every_entry_that_declares_it(mutant, monkeypatch):
    _apply(monkeypatch, mutant)
    survivors = []
    for id_ in _by_mutant().get(mutant, []):
        r = entry(id_).verify(stop_at_failure=True)
        if r.ok:
            survivors.append(id_)
        else:
            # a broken mutant (wrong signature) would "kill" by a TypeError: not a kill
            assert r.error is None or r.error.startswith("ValueError"), (id_, r.error)
    assert not survivors, f"{mutant} passes {survivors}"


def test_survivor_reasons_are_real(monkeypatch):
    """Each excused pair really survives (else it belongs in KILLS)."""
    for (id_, m), why in SURVIVES.items():
        assert why
        with monkeypatch.context() as mp:
            _apply(mp, m)
            assert entry(id_).verify().ok, (id_, m)
