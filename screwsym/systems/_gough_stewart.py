r"""The direct kinematics of the Gough-Stewart platforms whose legs meet in pairs: 3-3, 6-3.

Six legs, joined in pairs at three platform points ``B_1, B_2, B_3`` (the octahedral 3-3
when the base points pair up too; the 6-3 when they do not).  Each ``B_j`` lies on the
circle where the spheres of its two legs meet: ``B_j = O_j + x_j u_j + y_j v_j`` with ``O_j``
on the axis through the two base points and ``u_j``, ``v_j`` orthogonal rational vectors
across it, so that ``|u_j|**2 x_j**2 + |v_j|**2 y_j**2 = rho_j**2``; the platform triangle
gives ``|B_j - B_k|**2 = d_jk**2``.  Six polynomial equations with rational coefficients
in six unknowns: SymPy's Groebner basis (grevlex, then ``fglm`` to lex) puts them in
*shape position*, every unknown a polynomial in the last one, which is the root of a
univariate polynomial of degree 16 (Nanua, Waldron & Murthy 1990: at most 16 modes; for the
3-3 they come in pairs mirrored in the base plane).  Each real root gives one mode, every
coordinate a polynomial in the root (exact, in ``Q(r)``); the rotation maps the platform
triangle onto ``B_1 B_2 B_3``.  A basis not in shape position (a double mode, a mode not
separated by the last unknown, after trying the three ``y_j`` as the last) is refused, not
guessed.  SymPy's ``groebner`` cannot be stopped midway: it runs in a worker process ended
when the budget's CPU time runs out (:func:`screwsym.algebra.budget.run_bounded`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from sympy import Dummy, ImmutableMatrix, Matrix, Poly, Symbol, factor_list, groebner, symbols

from ..algebra.budget import charge, run_bounded
from ._root_field import RealRoot, real_roots_of

__all__ = ["SpatialMode", "paired_modes", "paired_legs"]


@dataclass(frozen=True)
class SpatialMode:
    """One assembly mode of a spatial platform: ``position`` (the platform frame's origin) and
    ``rotation`` (3 x 3, exact), the platform point ``b`` at ``position + rotation * b``.

    ``root`` is the root of the polynomial it comes from; :meth:`evalf` gives the pose to
    any number of digits.
    """

    position: ImmutableMatrix
    rotation: ImmutableMatrix
    root: Any
    multiplicity: int = 1

    @property
    def pose(self) -> tuple[ImmutableMatrix, ImmutableMatrix]:
        """``(position, rotation)``, exact."""
        return (self.position, self.rotation)

    def evalf(self, n: int = 15) -> tuple[ImmutableMatrix, ImmutableMatrix]:
        """``(position, rotation)`` with entries to ``n`` significant digits."""
        return (self.position.evalf(n), self.rotation.evalf(n))


def paired_legs(base: tuple, platform: tuple) -> list | None:
    """The legs grouped by platform point: ``[(b_j, a_i, a_k, i, k), ...]`` (three platform
    points, each on two legs to distinct base points), or None when they do not pair so."""
    groups: dict = {}
    for leg, (a, b) in enumerate(zip(base, platform, strict=True)):
        groups.setdefault(b, []).append((a, leg))
    if len(groups) != 3 or any(len(g) != 2 for g in groups.values()):
        return None
    out = []
    for b, ((a1, i), (a2, k)) in groups.items():
        if a1 == a2:
            return None
        out.append((b, a1, a2, i, k))
    return out


def _sub(p: tuple, q: tuple) -> Matrix:
    return Matrix(p) - Matrix(q)


def _across(e: Matrix) -> tuple[Matrix, Matrix]:
    """Two rational vectors orthogonal to ``e`` and to each other."""
    k = min(range(3), key=lambda i: (abs(e[i]), i))
    w = Matrix([1 if i == k else 0 for i in range(3)])
    u = e.cross(w)
    return u, e.cross(u)


def _circles(pairs: list, l2: tuple) -> list:
    """Each platform point's circle: centre ``O``, ``u``, ``v``, ``rho**2``."""
    out = []
    for _, a1, a2, i, k in pairs:
        e = _sub(a2, a1)
        L = e.dot(e)
        s = (l2[i] - l2[k] + L) / (2 * L)
        O = Matrix(a1) + s * e
        u, v = _across(e)
        out.append((O, u, v, l2[i] - s**2 * L))
    return out


def _shape(basis: list, gens: tuple) -> tuple[Poly, dict] | None:
    """``(P(last), {var: g(last)})`` when the lex basis is ``var - g(last)``, ``P(last)``."""
    last = gens[-1]
    polys = [Poly(b, *gens, domain="QQ") for b in basis]
    uni = [p for p in polys if p.free_symbols <= {last}]
    if len(uni) != 1 or len(polys) != len(gens):
        return None
    values = {}
    for p in polys:
        if p is uni[0]:
            continue
        lead = p.LM()
        vars_ = [g for g, k in zip(gens, lead.exponents, strict=True) if k]
        if len(vars_) != 1 or lead.exponents[gens.index(vars_[0])] != 1:
            return None
        var = vars_[0]
        rest = p - Poly(p.LC() * var, *gens, domain="QQ")
        if not rest.free_symbols <= {last}:
            return None
        values[var] = Poly(-rest.as_expr() / p.LC(), last, domain="QQ")
    if len(values) != len(gens) - 1:
        return None
    return Poly(uni[0].as_expr(), last, domain="QQ"), values


def _lex_basis(eqs: list, n: int) -> tuple[str, list | None]:
    """The reduced lex Groebner basis of ``eqs`` (coefficient dicts of polynomials in ``n``
    unknowns, the last the lowest): SymPy's ``groebner`` in grevlex, then ``fglm`` to lex.
    ``("one", None)`` for no solution, ``("infinite", None)`` for a basis not
    zero-dimensional, else ``("lex", dicts)``.  Dicts in and out: it runs in a worker
    process (:func:`screwsym.algebra.budget.run_bounded`)."""
    zs = symbols(f"z0:{n}")
    G = groebner([Poly.from_dict(e, *zs, domain="QQ").as_expr() for e in eqs], *zs, order="grevlex")
    if list(G.exprs) == [1]:
        return "one", None
    if not G.is_zero_dimensional:
        return "infinite", None
    return "lex", [Poly(e, *zs, domain="QQ").as_dict() for e in G.fglm("lex").exprs]


def paired_modes(base: tuple, platform: tuple, l2: tuple, pairs: list) -> tuple[Poly, list]:
    """The univariate polynomial and the real modes of a platform whose legs pair at the
    platform (:func:`paired_legs`)."""
    circles = _circles(pairs, l2)
    xs = [Dummy(f"x{j + 1}") for j in range(3)]
    ys = [Dummy(f"y{j + 1}") for j in range(3)]
    B = [O + x * u + y * v for (O, u, v, _), x, y in zip(circles, xs, ys, strict=True)]
    eqs = [
        Poly(u.dot(u) * x**2 + v.dot(v) * y**2 - r2, *xs, *ys, domain="QQ")
        for (_, u, v, r2), x, y in zip(circles, xs, ys, strict=True)
    ]
    bpts = [Matrix(p[0]) for p in pairs]
    for j, k in ((0, 1), (1, 2), (2, 0)):
        d = B[j] - B[k]
        side = Poly(d.dot(d) - (bpts[j] - bpts[k]).dot(bpts[j] - bpts[k]), *xs, *ys, domain="QQ")
        # less the two circles: bilinear in (x_j, y_j, 1) and (x_k, y_k, 1) (u_j . v_j = 0),
        # the same ideal, and its Groebner basis is much cheaper
        eqs.append(side - eqs[j] - eqs[k])
    for last in (2, 1, 0):
        others = [g for j, g in enumerate(ys) if j != last]
        gens = (*xs, *others, ys[last])
        # SymPy's groebner cannot be stopped midway: a worker process, ended when the
        # budget's CPU time runs out (a 6-3 whose base points are not coplanar takes about
        # 70 s, 2 s with a planar base), its CPU time charged when it returns
        kind, lex = run_bounded(_lex_basis, [Poly(e.as_expr(), *gens, domain="QQ").as_dict()
                                             for e in eqs], len(gens))
        charge(1000)
        if kind == "one":
            return Poly(1, Symbol(f"y{last + 1}"), domain="ZZ"), []
        if kind == "infinite" or lex is None:
            raise NotImplementedError(
                "direct_kinematics: infinitely many (complex) solutions of the closure equations; "
                "whether they hold a real family is not decided here"
            )
        shape = _shape([Poly.from_dict(e, *gens, domain="QQ").as_expr() for e in lex], gens)
        charge(1000)
        if shape is not None:
            break
    else:
        raise NotImplementedError(
            "direct_kinematics: the closure equations are not in shape position (a repeated "
            "mode?); this case is not handled"
        )
    P, values = shape
    y = ys[last]
    values[y] = Poly(y, y, domain="QQ")
    name = Symbol(f"y{last + 1}")
    P = Poly(P.as_expr().subs(y, name), name, domain="QQ")
    _, P = P.clear_denoms(convert=True)
    P = P.primitive()[1]
    if P.LC() < 0:
        P = -P
    modes = []
    _, factors = factor_list(P)
    for g, mult in factors:
        g = Poly(g.as_expr().subs(name, y), y, domain="QQ")
        for root in real_roots_of(g):
            modes.append(_mode(root, circles, xs, ys, values, bpts, mult))
    return P, modes


def _mode(root: RealRoot, circles: list, xs: list, ys: list, values: dict, bpts: list, mult: int) -> SpatialMode:
    """The pose at one root: the platform points from the shape basis, the rotation mapping
    the platform triangle onto them (exact, in ``Q(r)``)."""
    pts = []
    for (O, u, v, _), x, y in zip(circles, xs, ys, strict=True):
        X, Y = root.reduce(values[x]), root.reduce(values[y])
        pts.append([O[i] + X * u[i] + Y * v[i] for i in range(3)])
    e1 = [pts[1][i] - pts[0][i] for i in range(3)]
    e2 = [pts[2][i] - pts[0][i] for i in range(3)]
    e3 = _cross(e1, e2)
    f1, f2 = bpts[1] - bpts[0], bpts[2] - bpts[0]
    F = Matrix.hstack(f1, f2, f1.cross(f2)).inv()  # rational
    rot = [[root.reduce(sum((col[i] * F[c, j] for c, col in enumerate((e1, e2, e3))), Poly(0, root.g.gen, domain="QQ"))) for j in range(3)] for i in range(3)]
    p = [pts[0][i] - sum((rot[i][j] * bpts[0][j] for j in range(3)), Poly(0, root.g.gen, domain="QQ")) for i in range(3)]
    rotation = ImmutableMatrix([[root.value(e) for e in row] for row in rot])
    position = ImmutableMatrix([root.value(root.reduce(e)) for e in p])
    return SpatialMode(position, rotation, root.expr, mult)


def _cross(a: list, b: list) -> list:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

