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
* trace which operations each entry calls, and assert that every mutant of
  every operation it calls is declared, unless ``SURVIVES`` says why that
  entry cannot see that mutant;
* assert that every mutant is killed by some entry.

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
from screwsym.screw import foot as _foot


def _m(v) -> ImmutableMatrix:
    return ImmutableMatrix(Matrix(v))


# ---------------------------------------------------------------- operations
#: name -> (owner, attribute, how): how is "function", "classmethod" or "method"
OPS = {
    **{name: (ss, name, "function") for name in (
        "pitch", "axis", "foot", "decompose", "classify", "shift_origin", "reciprocal_product",
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
    "decompose couple negated": ("decompose", lambda real: lambda s: (real(s)[0], -real(s)[1])),
    "decompose parts swapped": ("decompose", lambda real: lambda s: tuple(reversed(real(s)))),
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
    "common_normal parallel: feet at the foot points": ("common_normal", lambda real: _cn(
        real, lambda a, b, d, n, al, f1, f2:
        (d, n, al, *((_foot(a), _foot(b)) if _parallel(a, b) else (f1, f2))))),
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
SURVIVES: dict[tuple[str, str], str] = {}

#: entry id -> the mutants it must kill (filled in below, checked by the tests)
KILLS: dict[str, tuple[str, ...]] = {}


# ------------------------------------------------------------------- tracing
def _same(a, b) -> bool:
    """Do two answers of an operation agree (structurally, or as an exact zero difference)?"""
    if isinstance(a, tuple) and isinstance(b, tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, Screw) and isinstance(b, Screw):
        return type(a) is type(b) and _same(a.as_matrix(), b.as_matrix())
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


@functools.lru_cache(maxsize=None)
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
    missing = [e.id for e in entries() if e.id not in KILLS]
    assert not missing, f"entries with no declared mutants: {missing}"
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
