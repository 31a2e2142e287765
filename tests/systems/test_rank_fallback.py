"""The fallback of ``analysis`` (``screwsym/systems/_rank_cases.py``), exercised.

``analysis`` finds the generic rank at the seeded points (``SEEDS``) and proves it; when
no point proves it, fraction-free elimination over the polynomial ring decides (the
branch marked ``pragma: no cover``: points are unlucky with probability near zero, so
the default suite never runs it).  Here the seeds are taken away (``SEEDS = ()``) or every
point made to fail (``proved_at`` returning None), and the rank, the basis, the
reciprocal system and the case split found through the fallback are compared with those
of the normal path.  The caches of the exact algebra are emptied around each test.
"""

from __future__ import annotations

import random

import pytest
from sympy import Matrix, cos, sin, sqrt, symbols

import screwsym.systems._rank_cases as rank_cases_module
from screwsym import ScrewSystem, Twist, vector

a, b = symbols("a b", real=True)
q = symbols("q", real=True)


def ball(p):
    return ScrewSystem(*(Twist.rotation(e, point=p) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])))


def random_system(case: int) -> ScrewSystem:
    """Screws with entries in a, b (some with sqrt(3)), and a member that depends on
    others with a coefficient in a: a rank deficit the fallback must see."""
    rng = random.Random(f"{case}-fallback")
    atoms = [1, a, b, a * b] + ([sqrt(3)] if case % 2 else [])

    def entry():
        return sum(rng.randint(-2, 2) * rng.choice(atoms) for _ in range(2))

    screws = [[entry() for _ in range(6)] for _ in range(rng.randint(2, 4))]
    i, j = rng.sample(range(len(screws)), 2)
    screws.append([u + a * v for u, v in zip(screws[i], screws[j], strict=True)])
    return ScrewSystem(*screws)


SYSTEMS = {
    "ball": lambda: ball(vector("p")),
    "deficit": lambda: ScrewSystem([a, 1, 0, 0, 0, 0], [0, 0, 1, b, 0, 0],
                                   [a, 1, 1, b, 0, 0], [0, 0, 0, 0, 0, 0]),
    "zero": lambda: ScrewSystem([0] * 6, [0] * 6),
    "sqrt3": lambda: ScrewSystem(Twist.rotation([1, sqrt(3), 0], point=[a, 0, 0]),
                                 Twist.rotation([0, 1, 0], point=[0, b, 1]),
                                 Twist.rotation([1, 0, 0], point=[a, b, 0]),
                                 Twist.translation([a, 1, 0])),
    # random1 (40 s), random2 and random4 are left out: the last two's rank_conditions()
    # runs past a minute on the normal path too, its budget notwithstanding (a defect of the
    # split's accounting, in the code before issue 31 as well; issue 32 asks for bounded
    # work everywhere)
    **{f"random{k}": (lambda k=k: random_system(k)) for k in (0, 3, 5)},
}


@pytest.fixture
def fresh():
    """Empty every cache of the exact algebra and the systems before and after."""
    rank_cases_module.clear_caches()
    yield
    rank_cases_module.clear_caches()


def answers(system: ScrewSystem) -> tuple:
    an = rank_cases_module.analysis(system.matrix)
    return (an, system.rank, system.basis(), system.reciprocal(), system.rank_conditions())


@pytest.mark.parametrize("name", list(SYSTEMS))
def test_the_fallback_agrees_with_the_seeded_points(name, fresh, monkeypatch):
    system = SYSTEMS[name]()
    normal = answers(system)
    rank_cases_module.clear_caches()
    calls = []
    elimination = rank_cases_module.domain_matrix

    def spy(rows, R):
        calls.append(len(rows))
        return elimination(rows, R)

    monkeypatch.setattr(rank_cases_module, "SEEDS", ())
    monkeypatch.setattr(rank_cases_module, "domain_matrix", spy)
    fallback = answers(system)
    assert calls, "the fallback (fraction-free elimination) did not run"
    assert fallback == normal
    # the rank is the generic rank: at most the members, and that of SymPy at a point
    point = {s: 3 + 2 * k for k, s in enumerate(sorted(system.matrix.free_symbols, key=str))}
    assert fallback[1] == Matrix(system.matrix.xreplace(point)).rank()


def test_the_fallback_sees_a_member_removed(fresh, monkeypatch):
    # the comparison can fail: a system without its independent member has a lower rank
    monkeypatch.setattr(rank_cases_module, "SEEDS", ())
    s = SYSTEMS["deficit"]()
    fewer = ScrewSystem(*list(s)[:1], *list(s)[2:])
    assert s.rank == 2 and fewer.rank == 2
    assert ScrewSystem(*list(s)[:1]).rank == 1 != s.rank


def test_every_point_failing_falls_back_to_elimination(fresh, monkeypatch):
    system = random_system(3)
    normal = answers(system)
    rank_cases_module.clear_caches()
    monkeypatch.setattr(rank_cases_module, "proved_at", lambda *args, **kw: None)
    assert answers(system)[:4] == normal[:4]


def test_on_the_circle_more_points_are_tried(fresh, monkeypatch):
    system = ScrewSystem(Twist.rotation([cos(q), sin(q), 0], point=[0, 0, 0]),
                         Twist.rotation([1, 0, 0], point=[0, 0, 0]),
                         Twist.rotation([0, 1, 0], point=[0, 0, 0]))
    normal = answers(system)
    assert normal[1] == 2
    rank_cases_module.clear_caches()
    monkeypatch.setattr(rank_cases_module, "SEEDS", ())
    assert answers(system) == normal
    # and where no point of the circle proves the rank, a clear error (no elimination there)
    rank_cases_module.clear_caches()
    monkeypatch.setattr(rank_cases_module, "proved_at", lambda *args, **kw: None)
    with pytest.raises(RuntimeError, match="no point on the circle proved the rank"):
        _ = system.rank
