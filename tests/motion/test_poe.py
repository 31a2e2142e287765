"""The ring path of the product of exponentials (``motion/_poe.py``): its writer's shortcuts.

The writer packs monomials into integers for the angle-sum gathering and builds the products of
generators without ``Mul.flatten``; both are checked here against the plain constructions, and
each check is shown to reject a wrong answer.
"""

from __future__ import annotations

import random

import pytest
from sympy import (
    Integer,
    Mul,
    Rational,
    cancel,
    cos,
    expand,
    expand_trig,
    sin,
    srepr,
    symbols,
)
from sympy.polys.domains import QQ

from screwsym import Chain, Twist, exp6
from screwsym.motion import _poe
from screwsym.motion._poe_writer import _FIELD, _pack, _Writer


def _spatial(k: int) -> Chain:
    axes = [(0, 0, 1), (0, 1, 0), (1, 0, 0)]
    return Chain([Twist.rotation(list(axes[i % 3]), point=[Rational(i, 2), Rational(i % 2, 3), Rational(i, 5)])
                  for i in range(k)])


def _plain(chain: Chain, q: tuple) -> list:
    """FK (R row by row, p) and the space Jacobian by plain SymPy products of ``exp6``, untidied."""
    R = [[Integer(int(i == j)) for j in range(3)] for i in range(3)]
    p = [Integer(0)] * 3
    cols = []
    for t, qi in zip(chain.twists, q, strict=True):
        w, v = list(t.omega), list(t.v_O)
        Rw = [sum((R[i][j] * w[j] for j in range(3)), Integer(0)) for i in range(3)]
        Rv = [sum((R[i][j] * v[j] for j in range(3)), Integer(0)) for i in range(3)]
        cols.append(Rw + [Rv[0] + p[1] * Rw[2] - p[2] * Rw[1], Rv[1] + p[2] * Rw[0] - p[0] * Rw[2],
                          Rv[2] + p[0] * Rw[1] - p[1] * Rw[0]])
        E = exp6(t, qi)
        p = [sum((R[i][j] * E.p[j] for j in range(3)), p[i]) for i in range(3)]
        R = [[sum((R[i][k] * E.R[k, j] for k in range(3)), Integer(0)) for j in range(3)] for i in range(3)]
    return [x for row in R for x in row] + p + [x for c in cols for x in c]


def test_products_of_generators_are_built_in_sympys_canonical_form():
    # symbols with different assumptions sort by more than their names (m positive before zdd real
    # by name, after it in Basic.compare): the built product must equal Mul's own, argument for argument
    m = symbols("m", positive=True)
    zdd, a = symbols("zdd a", real=True)
    b = symbols("b")
    q = symbols("q1:4", real=True)
    chain = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]), Twist.rotation([0, 1, 0], point=[a, 0, 0]),
                   Twist.translation([1, 0, 0])])
    engine = _poe._Engine(list(chain.twists), chain.home, q, extra=[m, zdd, b])
    writer = _Writer(engine)
    gens = list(range(len(writer.expr_of)))
    assert all(writer._plain(g) for g in gens)
    rng = random.Random(5)
    for _ in range(300):
        chosen = sorted(rng.sample(gens, rng.randint(1, min(5, len(gens)))))
        mono = tuple((g, rng.choice([1, 1, 2, 3])) for g in chosen)
        coeff = QQ(rng.choice([1, -1, 2, -3]), rng.choice([1, 1, 5]))
        plain = Mul(*(writer.expr_of[g] ** k for g, k in mono))
        built = writer._monomial_expr(mono)
        assert built == plain and srepr(built) == srepr(plain) and hash(built) == hash(plain)
        term = writer._term(mono, coeff)
        assert term == Rational(coeff.numerator, coeff.denominator) * plain
    # the check tells a product in another order apart (what _from_args would give unsorted)
    wrong = Mul._from_args((m, zdd))
    assert Mul(m, zdd).args == (zdd, m) and wrong != m * zdd


def test_ring_results_equal_the_plain_product_and_a_perturbed_one_is_told_apart():
    q = symbols("q1:4", real=True)
    chain = _spatial(3)
    ours = list(chain.forward(q).matrix[:3, :]) + list(chain.jacobian(q))
    plain = _plain(chain, q)
    # R row by row, p: chain.forward(q).matrix[:3, :] is row by row with p as the 4th column
    ours_fk = [ours[4 * i + j] for i in range(3) for j in range(3)] + [ours[4 * i + 3] for i in range(3)]
    ours_j = ours[12:]
    cols = [ours_j[i::3] for i in range(3)]  # the 6 x 3 matrix, row by row -> columns
    ours_flat = ours_fk + [x for c in cols for x in c]
    assert len(ours_flat) == len(plain)
    # symbolically: each cosine and sine by the rational parametrisation of the circle
    t = symbols("t1:4", real=True)
    circle = {f(qi): e for qi, ti in zip(q, t, strict=True)
              for f, e in ((cos, (1 - ti**2) / (1 + ti**2)), (sin, 2 * ti / (1 + ti**2)))}

    def vanishes(d):
        return cancel(expand_trig(d).xreplace(circle)) == 0

    for x, y in zip(ours_flat, plain, strict=True):
        assert vanishes(x - y)
    # independently: at random rational points of the circles (cos, sin exact), entry by entry
    rng = random.Random(3)
    for _ in range(3):
        point = {}
        for qi in q:
            t = Rational(rng.randint(1, 9), rng.randint(1, 9))  # cos = (1 - t^2)/(1 + t^2) ...
            point[cos(qi)] = (1 - t**2) / (1 + t**2)
            point[sin(qi)] = 2 * t / (1 + t**2)
        values = [x.xreplace(point) for x in ours_flat]
        assert values == [y.xreplace(point) for y in plain]
    bad = list(ours_flat)
    bad[13] = bad[13] + sin(q[0]) * Rational(1, 10**6)
    assert not vanishes(bad[13] - plain[13])
    assert bad[13].xreplace(point) != plain[13].xreplace(point)


def test_forward_and_jacobian_do_not_depend_on_the_calls_before():
    q = symbols("q1:6", real=True)
    chain = _spatial(5)
    _poe._RECENT.clear()
    fk1, j1 = chain.forward(q).matrix, chain.jacobian(q)
    _poe._RECENT.clear()
    j2 = chain.jacobian(q)
    fk2 = chain.forward(q).matrix
    assert srepr(fk1) == srepr(fk2) and srepr(j1) == srepr(j2)
    assert len(_poe._RECENT) <= _poe._RECENT_SIZE


def test_a_degree_beyond_the_packed_fields_is_written_unpacked():
    q = symbols("q1:2", real=True)
    chain = _spatial(1)
    engine = _poe._Engine(list(chain.twists), chain.home, q)
    writer = _Writer(engine)
    c = engine.gen_of[engine.cos_gen[next(iter(engine.cos_gen))]]
    big = c ** (_FIELD + 1)
    assert writer.expr(big) == cos(q[0]) ** (_FIELD + 1)
    assert expand(writer.expr(c**2 + 2 * c)) == cos(q[0]) ** 2 + 2 * cos(q[0])


@pytest.mark.parametrize("k", [2, 3])
def test_packing_round_trips(k):
    q = symbols(f"q1:{k + 1}", real=True)
    chain = _spatial(k)
    engine = _poe._Engine(list(chain.twists), chain.home, q)
    writer = _Writer(engine)
    R, p = engine.forward()
    for P in [x for row in R for x in row] + p:
        for monom, _ in P.terms():
            assert writer._unpack(_pack(monom)) == tuple((g, e) for g, e in enumerate(monom) if e)
