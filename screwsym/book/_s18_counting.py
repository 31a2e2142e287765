"""The counting statements: infinity^4 lines, infinity^5 unit screws, infinity^6 screws."""

from __future__ import annotations

import math
from fractions import Fraction

from sympy import Matrix, Rational, symbols

from ._common import book_cross, book_dot, ss, stack
from ._statement import statement

_POINT = {"a": Rational(2, 7), "b": Rational(-3, 5), "u": Rational(2, 3), "v": Rational(-5, 4),
          "h": Rational(1, 3), "rho": 2}


def _parametrised():
    """Direction on the unit sphere (rational, stereographic) and a foot in its normal plane."""
    a, b, u, v, h, rho = symbols("a b u v h rho", real=True)
    d = 1 + a**2 + b**2
    S = Matrix([2 * a, 2 * b, 1 - a**2 - b**2]) / d
    e1 = book_cross(S, Matrix([1, 0, 0]))
    e2 = book_cross(S, e1)
    foot = u * e1 + v * e2
    return (a, b, u, v, h, rho), S, foot


def _values() -> dict:
    return {symbols(k, real=True): v for k, v in _POINT.items()}


def _at_point(foot, S):
    """foot() of the library's line through ``foot`` along ``S`` at the rational point."""
    at = _values()
    return ss.foot(ss.LineVector.from_axis(foot.xreplace(at), S.xreplace(at)))


class _NotRational(Exception):
    """A part the forward differentiation of :func:`_jacobian_at` does not take."""


def _jacobian_at(vec, params) -> Matrix:
    """The Jacobian of ``vec`` with respect to ``params`` at the rational point, exactly.

    Forward differentiation in exact fractions: every node of the expression
    tree carries its value and its gradient at the point (sums, products,
    integer powers, square roots of rational squares), so the Jacobian is the
    exact one, without building its symbolic entries.  Anything else falls
    back to SymPy's ``jacobian`` at the point.
    """
    index = {p: i for i, p in enumerate(params)}
    n = len(params)
    zero = [Fraction(0)] * n

    def ev(x, memo):
        got = memo.get(id(x))
        if got is not None:
            return got
        if x.is_Rational:
            out = (Fraction(int(x.p), int(x.q)), zero)
        elif x.is_Symbol:
            v = _POINT[x.name]
            g = list(zero)
            if x in index:
                g[index[x]] = Fraction(1)
            out = (Fraction(v), g)
        elif x.is_Add:
            parts = [ev(a, memo) for a in x.args]
            out = (sum(v for v, _ in parts), [sum(col) for col in zip(*(g for _, g in parts), strict=True)])
        elif x.is_Mul:
            v, g = Fraction(1), zero
            for a in x.args:
                va, ga = ev(a, memo)
                v, g = v * va, [v * dga + va * dg for dg, dga in zip(g, ga, strict=True)]
            out = (v, g)
        elif x.is_Pow and x.exp.is_Integer:
            vb, gb = ev(x.base, memo)
            k = int(x.exp)
            if vb == 0 and k < 1:
                raise _NotRational
            d = k * vb ** (k - 1)
            out = (vb**k, [d * dg for dg in gb])
        elif x.is_Pow and x.exp == Rational(1, 2):
            vb, gb = ev(x.base, memo)
            r = _rational_sqrt(vb)
            if r is None or r == 0:
                raise _NotRational
            out = (r, [dg / (2 * r) for dg in gb])
        else:
            raise _NotRational
        memo[id(x)] = out
        return out

    try:
        rows = []
        for e in vec:
            rows.append([Rational(d.numerator, d.denominator) for d in ev(e, {})[1]])
        return Matrix(rows)
    except (_NotRational, KeyError):
        J = vec.jacobian(Matrix(params))
        return J.xreplace({p: _POINT[p.name] for p in J.free_symbols})


def _rational_sqrt(v: Fraction) -> Fraction | None:
    if v < 0:
        return None
    rn, rd = math.isqrt(v.numerator), math.isqrt(v.denominator)
    return Fraction(rn, rd) if rn * rn == v.numerator and rd * rd == v.denominator else None


def _rank(vec6, params):
    """Exact rank of the Jacobian at the generic rational point."""
    return _jacobian_at(vec6, params).rank()


_HOW = """Directions S on the unit sphere by the rational stereographic map of (a, b), foot
    points u e1 + v e2 in the plane normal to S; the 6-vectors are built with the library
    ({what}); the exact rank of their Jacobian at the rational point a=2/7, b=-3/5,
    u=2/3, v=-5/4, h=1/3, rho=2 is the dimension. The map itself is checked against the
    book's formula (S; foot x S + h S), so that a wrong formula of the same rank fails."""


@statement(
    "Counting: lines", "1.2", "There are infinity^4 lines in space",
    r"\dim\{(\mathbf S;\ \mathbf S_0):\ |\mathbf S|=1,\ \mathbf S\cdot\mathbf S_0=0\}=4"
    r"\quad(\infty^4\ \text{lines})",
    "numeric",
    _HOW.format(what="LineVector.from_axis(foot, S)") + """ The constraint map
    (S.S - 1, S.S0) has a Jacobian of rank 2 on the variety, 6 - 2 = 4.""",
    errata=("The book says the six coordinates \"are related by Eqs. (1.6) and (1.11)\"; the "
            "constraints are the normalisation (1.6) (or homogeneity) and the orthogonality "
            "(1.10)/(1.15); (1.11) is a definition.",),
)
def _count_lines(c):
    (a, b, u, v, h, rho), S, foot = _parametrised()
    line = ss.LineVector.from_axis(foot, S)
    L = line.matrix
    c.zero("the map: L - (S; foot x S)", L - stack(S, book_cross(foot, S)))
    c.zero("foot(L) - foot at the rational point", _at_point(foot, S) - foot.xreplace(_values()))
    c.zero("rank - 4", _rank(L, (a, b, u, v)) - 4)
    x = Matrix(symbols("x1:7", real=True))
    G = Matrix([book_dot(x[:3, :], x[:3, :]) - 1, book_dot(x[:3, :], x[3:, :])])
    pt = L.xreplace({a: _POINT["a"], b: _POINT["b"], u: _POINT["u"], v: _POINT["v"]})
    JG = G.jacobian(x).xreplace(dict(zip(x, pt, strict=False)))
    c.zero("point on the variety", G.xreplace(dict(zip(x, pt, strict=False))))
    c.zero("rank of the constraints - 2", JG.rank() - 2)


@statement(
    "Counting: unit line vectors", "1.4.1", "Unit line vectors and the infinity^4 lines",
    r"\dim\{\text{unit line vectors}\}=4;\ (\mathbf S;\ \mathbf S_0)\ \text{and}\ "
    r"(-\mathbf S;\ -\mathbf S_0)\ \text{are the same undirected line}",
    "numeric",
    _HOW.format(what="LineVector.from_axis(foot, S)") + """ The unit line vectors L and -L
    are different vectors on the same line (same foot point).""",
    errata=("One-to-one with directed lines; 2-to-1 (+-) with undirected lines.",),
)
def _count_unit_lines(c):
    (a, b, u, v, h, rho), S, foot = _parametrised()
    L = ss.LineVector.from_axis(foot, S)
    c.zero("the map: L - (S; foot x S)", L.matrix - stack(S, book_cross(foot, S)))
    c.zero("foot(L) - foot at the rational point", _at_point(foot, S) - foot.xreplace(_values()))
    c.zero("rank - 4", _rank(L.matrix, (a, b, u, v)) - 4)
    c.zero("|S|^2 - 1", book_dot(L.S, L.S) - 1)
    c.zero("foot(-L) - foot(L)", ss.foot(-L) - ss.foot(L))
    c.nonzero("-L != L", (-L).matrix - L.matrix)


@statement(
    "Counting: unit screws", "1.4.2", "There are infinity^5 unit screws",
    r"\dim\{(\mathbf S;\ \mathbf r\times\mathbf S+h\mathbf S):\ |\mathbf S|=1\}=5\quad(\infty^5)",
    "numeric",
    _HOW.format(what="Screw.from_axis(foot, S, h)"),
)
def _count_unit_screws(c):
    (a, b, u, v, h, rho), S, foot = _parametrised()
    s = ss.Screw.from_axis(foot, S, h).matrix
    c.zero("the map: s - (S; foot x S + h S)", s - stack(S, book_cross(foot, S) + h * S))
    c.zero("rank - 5", _rank(s, (a, b, u, v, h)) - 5)


@statement(
    "Counting: screws", "1.4.2", "There are infinity^6 screws",
    r"\dim\{\rho(\mathbf S;\ \mathbf r\times\mathbf S+h\mathbf S)\}=6\quad(\infty^6)",
    "numeric",
    _HOW.format(what="rho * Screw.from_axis(foot, S, h)") + """ Four factors (axis position
    and direction, pitch, magnitude): 4 + 1 + 1 = 6.""",
)
def _count_screws(c):
    (a, b, u, v, h, rho), S, foot = _parametrised()
    s = (rho * ss.Screw.from_axis(foot, S, h)).matrix
    c.zero("the map: s - rho (S; foot x S + h S)", s - rho * stack(S, book_cross(foot, S) + h * S))
    c.zero("rank - 6", _rank(s, (a, b, u, v, h, rho)) - 6)
