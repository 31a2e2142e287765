"""The registry of Chapter 1: contents, metadata, verification, honesty."""

import pytest
from sympy import Matrix

import screwsym
from screwsym.book import KINDS, Construction, Entry, entries, entry, verify_all

NUMBERED = [f"1.{i}" for i in range(1, 59)]
OTHERS = [
    "Example 1.1", "Example 1.2", "Example 1.3", "Example 1.4",
    "Theorem 1.1", "Theorem 1.2", "Theorem 1.3",
    "Homogeneity", "Derivation of 1.16", "Special case S0=0", "Special case S=0",
    "Classification", "Translation twist", "Wrench decomposition", "Line vector plus couple",
    "Counting: lines", "Counting: unit line vectors", "Counting: unit screws", "Counting: screws",
    "Fig. 1.5",
]


def test_every_statement_is_registered():
    ids = [e.id for e in entries()]
    assert set(NUMBERED + OTHERS) <= set(ids)
    assert len(ids) == len(set(ids)) == len(NUMBERED) + len(OTHERS)


def test_metadata():
    for e in entries():
        assert e.kind in KINDS
        assert e.title and e.statement and e.construction and e.section
        assert isinstance(e.errata, tuple) and isinstance(e.notes, tuple)


def test_errata_recorded():
    assert any("only if" in x for x in entry("Theorem 1.1").errata)
    assert any("(1.35)" in x for x in entry("1.37").errata)
    assert entry("1.30").errata and entry("1.57").errata and entry("1.27").errata
    assert entry("Line vector plus couple").errata
    # Review rows are notes, not errata
    assert entry("1.17").notes and not entry("1.17").errata
    assert entry("1.25").notes


def test_lookup():
    assert entry("(1.34)") is entry("1.34")
    assert entry("example 1.4") is entry("Example 1.4")
    with pytest.raises(KeyError, match="unknown entry id '1.99'"):
        entry("1.99")
    with pytest.raises(TypeError, match="expected a string"):
        entry(1.34)


def test_repr_latex():
    e = entry("1.10")
    assert e._repr_latex_() == r"$$ \mathbf S\cdot\mathbf S_0=0 \tag{1.10} $$"


def test_whole_book_verifies():
    results = verify_all(jobs=2)
    bad = [(r.id, r.error, [(c.label, c.residual) for c in r.failures]) for r in results if not r.ok]
    assert not bad
    for r in results:
        assert r.residual == 0 and r.elapsed >= 0
        assert all(x == 0 or all(e == 0 for e in x) for x in r.residuals)


def test_book_versions_shown_failing():
    for id_ in ("Theorem 1.1", "1.30", "1.57", "1.27", "Line vector plus couple", "1.25", "1.24"):
        r = entry(id_).verify()
        assert r.ok and any(c.book for c in r.checks), id_


def test_result_of_a_failing_construction():
    def build(c: Construction):
        x = screwsym.vector("x")
        c.zero("missing term", (x[0] + x[1]) ** 2 - x[0] ** 2 - x[1] ** 2)
        c.nonzero("not a counter-example", x[0] - x[0])

    r = Entry("t", "0", "test", "x", "identity", "test", build).verify()
    assert not r.ok
    assert (r.residual - 2 * screwsym.vector("x")[0] * screwsym.vector("x")[1]).expand() == 0
    assert len(r.failures) == 2


def test_construction_error_fails_entry():
    def build(c):
        raise RuntimeError("boom")

    r = Entry("t", "0", "test", "x", "identity", "test", build).verify()
    assert not r.ok and "boom" in r.error


def test_bad_kind():
    with pytest.raises(ValueError, match="kind: expected one of"):
        Entry("t", "0", "t", "x", "theorem", "t", lambda c: None)


# ------------------------------------------------------- honesty of the checker
def test_broken_pitch_fails_dependent_entries(monkeypatch):
    real = screwsym.pitch
    monkeypatch.setattr(screwsym, "pitch", lambda s: 2 * real(s))
    for id_ in ("1.34", "1.54", "Example 1.4", "Example 1.2", "1.58"):
        assert not entry(id_).verify().ok, id_


def test_broken_reciprocal_product_fails_dependent_entries(monkeypatch):
    monkeypatch.setattr(screwsym, "reciprocal_product", lambda a, b: a.S.dot(b.S0))
    for id_ in ("1.45", "1.47", "1.40"):
        assert not entry(id_).verify().ok, id_


def test_broken_shift_origin_direction_fails(monkeypatch):
    monkeypatch.setattr(screwsym, "shift_origin", lambda s, A: type(s)(s.S, s.S0 + Matrix(A).cross(s.S)))
    for id_ in ("1.32", "1.46", "1.29"):
        assert not entry(id_).verify().ok, id_


def test_broken_mutual_moment_fails(monkeypatch):
    monkeypatch.setattr(screwsym, "mutual_moment", lambda a, b: -screwsym.reciprocal_product(a, b))
    for id_ in ("1.23", "1.25", "1.26"):
        assert not entry(id_).verify().ok, id_




