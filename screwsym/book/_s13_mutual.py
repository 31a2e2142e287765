"""Section 1.3, mutual moment of two lines: (1.19)-(1.27)."""

from __future__ import annotations

from sympy import Matrix, cos, pi, sin, sqrt, symbols

from ._common import (
    book_cross,
    book_dot,
    canonical_pair,
    generic_lines,
    placed_pair,
    real,
    ss,
    vec,
)
from ._statement import statement

_SEC = "1.3"
_CONVENTION = (
    "Sign convention (Section 1.3, Eqs. (1.24)-(1.25)): (1.24)/(1.25) hold when the unit "
    "normal a12 points from line 1 to line 2 and alpha12 is measured right-handedly about "
    "a12 from S1 to S2 (S1 x S2 = a12 sin alpha12); the reversed convention gives "
    "+a12 sin alpha12. The library defines M by (1.23) and derives (1.25) from common_normal."
)
_UNIT = (
    "Review, not an erratum: (1.25) needs unit S1, S2, which the book states just before "
    "(1.24). In general M = -|S1||S2| a12 sin alpha12 (an extension, verified here)."
)


@statement(
    "1.19", _SEC, "Line 1",
    r"\mathbf r_1\times\mathbf S_1=\mathbf S_{01}",
    "definition",
    "LineVector.from_axis(r1, S1).S0 against the determinant expansion of r1 x S1.",
)
def _e1_19(c):
    r1, S1 = vec("r1"), vec("S1")
    c.zero("S01 - r1 x S1", ss.LineVector.from_axis(r1, S1).S0 - book_cross(r1, S1))


@statement(
    "1.20", _SEC, "Line 2",
    r"\mathbf r_2\times\mathbf S_2=\mathbf S_{02}",
    "definition",
    "LineVector.from_axis(r2, S2).S0 against the determinant expansion of r2 x S2.",
)
def _e1_20(c):
    r2, S2 = vec("r2"), vec("S2")
    c.zero("S02 - r2 x S2", ss.LineVector.from_axis(r2, S2).S0 - book_cross(r2, S2))


@statement(
    "1.21", _SEC, "Mutual moment: moment of S2 about the line S1",
    r"M_m=a_{12}\,\mathbf a_{12}\times\mathbf S_2\cdot\mathbf S_1"
    r"=a_{12}\,\mathbf a_{21}\times\mathbf S_1\cdot\mathbf S_2,\qquad \mathbf a_{21}=-\mathbf a_{12}",
    "identity",
    """Line 1 through a generic point p along (k, 0, 0), k > 0, line 2 through a generic q
    along a generic w (library): both off the origin, neither direction a unit vector.
    a12, the unit normal a12 and the feet come from the library's common_normal;
    mutual_moment must equal a12 a12 x S2 . S1 and a12 a21 x S1 . S2; a12 >= 0; the
    normal is a unit vector perpendicular to both lines; foot 1 lies on line 1, foot 2
    on line 2, and a12 = (foot2 - foot1) . a12 (the full vector identity is (1.25)'s). The normal reversed (a21 in the first
    formula) gives a non-zero difference.""",
    notes=("The book writes \"projecting the moment vector - a12 a12 x S1 on the line S2\": "
           "the leading symbol is a minus, i.e. a12 a21 x S1.",),
)
def _e1_21(c):
    L1, L2, p, q, k, w = placed_pair()
    cn = ss.common_normal(L1, L2)
    M = ss.mutual_moment(L1, L2)
    S1, S2 = L1.S, L2.S
    c.zero("M - a12 (a12 x S2) . S1", M - cn.a12 * book_dot(book_cross(cn.normal, S2), S1))
    c.zero("M - a12 (a21 x S1) . S2", M - cn.a12 * book_dot(book_cross(-cn.normal, S1), S2))
    c.nonnegative("a12 >= 0", cn.a12)
    c.zero("a12 . a12 - 1", book_dot(cn.normal, cn.normal) - 1)
    c.zero("a12 . S1", book_dot(cn.normal, S1))
    c.zero("a12 . S2", book_dot(cn.normal, S2))
    c.zero("foot 1 on line 1: (foot1 - p) x S1", book_cross(cn.foot1 - p, S1))
    c.zero("foot 2 on line 2: (foot2 - q) x S2", book_cross(cn.foot2 - q, S2))
    c.zero("a12 = (foot2 - foot1) . a12", book_dot(cn.foot2 - cn.foot1, cn.normal) - cn.a12)
    c.nonzero("counter-example: normal reversed, M - a12 (a21 x S2) . S1",
              M - cn.a12 * book_dot(book_cross(-cn.normal, S2), S1))


@statement(
    "1.22", _SEC, "Expansion of the triple product",
    r"(\mathbf r_2-\mathbf r_1)\cdot\mathbf S_2\times\mathbf S_1"
    r"=\mathbf r_2\times\mathbf S_2\cdot\mathbf S_1+\mathbf r_1\times\mathbf S_1\cdot\mathbf S_2",
    "identity",
    """Two fully generic lines (library, through p along u and q along w): the triple
    product equals S02 . S1 + S01 . S2 built from the library's moments; sliding the
    points along their lines leaves it unchanged, and it equals mutual_moment.""",
)
def _e1_22(c):
    L1, L2, p, q, u, w = generic_lines()
    t1, t2 = real("t1 t2")
    lhs = book_dot(q - p, book_cross(w, u))
    c.zero("(r2 - r1) . S2 x S1 - (S02 . S1 + S01 . S2)", lhs - (book_dot(L2.S0, u) + book_dot(L1.S0, w)))
    slid = book_dot((q + t2 * w) - (p + t1 * u), book_cross(w, u))
    c.zero("sliding r1, r2 along the lines", slid - lhs)
    c.zero("(r2 - r1) . S2 x S1 - mutual_moment", lhs - ss.mutual_moment(L1, L2))


@statement(
    "1.23", _SEC, "Mutual moment in Plücker coordinates",
    r"M_m=\mathbf S_1\cdot\mathbf S_{02}+\mathbf S_2\cdot\mathbf S_{01}",
    "definition",
    """mutual_moment of two generic lines (library) against S1 . S02 + S2 . S01 with the
    moments written as r x S; it equals (r2 - r1) . S2 x S1.""",
)
def _e1_23(c):
    L1, L2, p, q, u, w = generic_lines()
    M = ss.mutual_moment(L1, L2)
    c.zero("M - (S1 . S02 + S2 . S01)", M - (book_dot(u, book_cross(q, w)) + book_dot(w, book_cross(p, u))))
    c.zero("M - (r2 - r1) . S2 x S1", M - book_dot(q - p, book_cross(w, u)))


@statement(
    "1.24", _SEC, "Cross product of the two unit directions",
    r"\mathbf S_2\times\mathbf S_1=-\mathbf a_{12}\sin\alpha_{12}",
    "identity",
    """Canonical pair (X axis; line through a12 k along (cos alpha, sin alpha, 0)) via
    the library: common_normal returns a12, the normal k and an angle with the sin and
    cos of alpha; S2 x S1 + a12 sin alpha12 = 0. Generic placement (line 1 through a
    generic p along (k, 0, 0), line 2 through a generic q along a generic w, neither
    direction a unit vector): S1 x S2 = |S1||S2| sin(alpha12) a12 and
    S1 . S2 = |S1||S2| cos(alpha12), and the normal points from line 1 to line 2
    ((q - p) . a12 = a12). The reversed convention (normal from 2 to 1) fails.""",
    errata=(_CONVENTION,),
)
def _e1_24(c):
    L1, L2, a12, alpha = canonical_pair()
    cn = ss.common_normal(L1, L2)
    c.zero("a12 from common_normal - a12", cn.a12 - a12)
    c.zero("normal - k", cn.normal - Matrix([0, 0, 1]))
    c.zero("sin(alpha12) - sin(alpha)", sin(cn.alpha12) - sin(alpha))
    c.zero("cos(alpha12) - cos(alpha)", cos(cn.alpha12) - cos(alpha))
    c.zero("S2 x S1 + a12 sin(alpha12)", book_cross(L2.S, L1.S) + cn.normal * sin(cn.alpha12))
    G1, G2, p, q, k, w = placed_pair()
    g = ss.common_normal(G1, G2)
    n1, n2 = sqrt(book_dot(G1.S, G1.S)), sqrt(book_dot(w, w))
    c.zero("generic: S1 x S2 - |S1||S2| sin(alpha12) a12",
           book_cross(G1.S, w) - n1 * n2 * sin(g.alpha12) * g.normal)
    c.zero("generic: S1 . S2 - |S1||S2| cos(alpha12)", book_dot(G1.S, w) - n1 * n2 * cos(g.alpha12))
    c.zero("generic: a12 points from line 1 to line 2, (q - p) . a12 - a12",
           book_dot(q - p, g.normal) - g.a12)
    c.nonzero("counter-example: reversed convention, S2 x S1 - a12 sin(alpha12)",
              book_cross(L2.S, L1.S) - cn.normal * sin(cn.alpha12), at={a12: 1, alpha: pi / 2},
              book=True)


@statement(
    "1.25", _SEC, "Mutual moment from distance and twist angle",
    r"M_m=(\mathbf r_2-\mathbf r_1)\cdot\mathbf S_2\times\mathbf S_1=-a_{12}\sin\alpha_{12}",
    "identity",
    """Canonical unit pair via the library: mutual_moment + a12 sin(alpha12) = 0 with
    a12, alpha12 from common_normal, and M = (foot2 - foot1) . S2 x S1 with the feet of
    common_normal. Generic placement (line 1 through a generic p along (k, 0, 0), line
    2 through a generic q along a generic w): M = -|S1||S2| a12 sin(alpha12), a12 >= 0,
    M = (foot2 - foot1) . S2 x S1 with the feet from common_normal (each on its
    line), and
    common_normal(L2, L1) (the reversed convention, applied consistently) gives the
    same M. The mixed convention (+a12 sin alpha12) and the unit formula on non-unit
    directions fail.""",
    errata=(_CONVENTION,),
    notes=(_UNIT,),
)
def _e1_25(c):
    L1, L2, a12, alpha = canonical_pair()
    cn = ss.common_normal(L1, L2)
    M = ss.mutual_moment(L1, L2)
    c.zero("M + a12 sin(alpha12)", M + cn.a12 * sin(cn.alpha12))
    c.zero("M - (r2 - r1) . S2 x S1", M - book_dot(cn.foot2 - cn.foot1, book_cross(L2.S, L1.S)))
    G1, G2, p, q, k, w = placed_pair()
    g = ss.common_normal(G1, G2)
    MG = ss.mutual_moment(G1, G2)
    nn = sqrt(book_dot(G1.S, G1.S)) * sqrt(book_dot(w, w))
    c.zero("generic: M + |S1||S2| a12 sin(alpha12)", MG + nn * g.a12 * sin(g.alpha12))
    c.nonnegative("generic: a12 >= 0", g.a12)
    c.zero("generic: M - (foot2 - foot1) . S2 x S1",
           MG - book_dot(g.foot2 - g.foot1, book_cross(w, G1.S)))
    c.zero("generic: foot2 - foot1 - a12 a12", g.foot2 - g.foot1 - g.a12 * g.normal)
    c.zero("generic: foot 1 on line 1", book_cross(g.foot1 - p, G1.S))
    c.zero("generic: foot 2 on line 2", book_cross(g.foot2 - q, w))
    r = ss.common_normal(G2, G1)
    c.zero("generic, lines swapped: M + |S1||S2| a21 sin(alpha21)", MG + nn * r.a12 * sin(r.alpha12))
    c.nonzero("counter-example: the opposite sign, M - a12 sin(alpha12)",
              M - cn.a12 * sin(cn.alpha12), at={a12: 1, alpha: pi / 2}, book=True)
    twice = ss.LineVector.from_axis([0, 0, 0], [2, 0, 0])
    c.nonzero("counter-example: |S1| = 2, M + a12 sin(alpha12) without |S1||S2|",
              ss.mutual_moment(twice, L2) + cn.a12 * sin(cn.alpha12), at={a12: 1, alpha: pi / 2})


@statement(
    "1.26", _SEC, "Mutual moment in components",
    r"M_m=l_1p_2+m_1q_2+n_1r_2+p_1l_2+q_1m_2+r_1n_2",
    "identity",
    """mutual_moment of (l1 m1 n1; p1 q1 r1) and (l2 m2 n2; p2 q2 r2), generic
    components, against the printed sum.""",
    errata=("The scalars r1, r2 collide with the position vectors r1, r2 (named r1s, r2s "
            "in the construction).",),
)
def _e1_26(c):
    l1, m1, n1, p1, q1, r1s, l2, m2, n2, p2, q2, r2s = real("l1 m1 n1 p1 q1 r1s l2 m2 n2 p2 q2 r2s")
    A = ss.LineVector([l1, m1, n1], [p1, q1, r1s])
    B = ss.LineVector([l2, m2, n2], [p2, q2, r2s])
    c.zero("M - (l1 p2 + m1 q2 + n1 r2 + p1 l2 + q1 m2 + r1 n2)",
           ss.mutual_moment(A, B) - (l1 * p2 + m1 * q2 + n1 * r2s + p1 * l2 + q1 * m2 + r1s * n2))


@statement(
    "1.27", _SEC, "Coplanar lines have zero mutual moment",
    r"\mathbf S_1\cdot\mathbf S_{02}+\mathbf S_2\cdot\mathbf S_{01}=0\quad(\text{lines coplanar})",
    "conditional",
    """M = 0 and is_coplanar for lines through a common generic point c along generic
    A and B, and for lines through generic ra, rb along A and mu A (any real mu).
    Both branches of common_normal in full, with A = (k, 0, 0), k > 0 (a rotation puts
    any direction there; positions and lengths stay generic): intersecting (B generic)
    gives a12 = 0, both feet at c, the normal A x B/|A x B| and the angle with
    |A||B| sin alpha12 a12 = A x B and |A||B| cos alpha12 = A . B; parallel (line 2
    along mu A, mu > 0) gives the distance |(rb - ra) x A|/|A| (compared squared), a
    unit normal perpendicular to A with foot2 - foot1 = a12 a12, foot 1 on line 1,
    foot 2 on line 2, and alpha12 = 0. Anti-parallel lines have alpha12 = pi, not 0. The skew pair (X axis;
    the line through (0, 0, 1) along Y) has M != 0 and is_coplanar False.""",
    errata=("Section 1.3 says parallel lines have alpha12 = 0; they may be anti-parallel, "
            "alpha12 in {0, pi} (sin alpha12 = 0). M = 0 either way.",),
)
def _e1_27(c):
    cpt, A, B, ra, rb = vec("c"), vec("A"), vec("B"), vec("ra"), vec("rb")
    mu = real("mu")
    I1, I2 = ss.LineVector.from_axis(cpt, A), ss.LineVector.from_axis(cpt, B)
    c.zero("intersecting: M", ss.mutual_moment(I1, I2))
    c.holds("intersecting: is_coplanar is True", ss.is_coplanar(I1, I2) is True)
    P1, P2 = ss.LineVector.from_axis(ra, A), ss.LineVector.from_axis(rb, mu * A)
    c.zero("parallel: M", ss.mutual_moment(P1, P2))
    c.holds("parallel: is_coplanar is True", ss.is_coplanar(P1, P2) is True)
    k = symbols("k", positive=True)
    X = Matrix([k, 0, 0])
    I1, I2 = ss.LineVector.from_axis(cpt, X), ss.LineVector.from_axis(cpt, B)
    ci = ss.common_normal(I1, I2)
    n = book_cross(X, B)
    nX, nB = sqrt(book_dot(X, X)), sqrt(book_dot(B, B))
    c.zero("intersecting: a12", ci.a12)
    c.zero("intersecting: foot1 - c", ci.foot1 - cpt)
    c.zero("intersecting: foot2 - c", ci.foot2 - cpt)
    c.zero("intersecting: normal - A x B/|A x B|", ci.normal - n / sqrt(book_dot(n, n)))
    c.zero("intersecting: A x B - |A||B| sin(alpha12) a12", n - nX * nB * sin(ci.alpha12) * ci.normal)
    c.zero("intersecting: A . B - |A||B| cos(alpha12)", book_dot(X, B) - nX * nB * cos(ci.alpha12))
    nu = symbols("mu", positive=True)
    cp = ss.common_normal(ss.LineVector.from_axis(ra, X), ss.LineVector.from_axis(rb, nu * X))
    dA = book_cross(rb - ra, X)
    c.zero("parallel: a12^2 - |(rb - ra) x A|^2/|A|^2", cp.a12**2 - book_dot(dA, dA) / book_dot(X, X))
    c.zero("parallel: normal . normal - 1", book_dot(cp.normal, cp.normal) - 1)
    c.zero("parallel: normal . A", book_dot(cp.normal, X))
    c.zero("parallel: foot2 - foot1 - a12 normal", cp.foot2 - cp.foot1 - cp.a12 * cp.normal)
    c.zero("parallel: foot 1 on line 1", book_cross(cp.foot1 - ra, X))
    c.zero("parallel: foot 2 on line 2", book_cross(cp.foot2 - rb, X))
    c.zero("parallel, same sense: alpha12", cp.alpha12)
    X = ss.LineVector.from_axis([0, 0, 0], [1, 0, 0])
    skew = ss.LineVector.from_axis([0, 0, 1], [0, 1, 0])
    c.nonzero("counter-example: skew pair, M", ss.mutual_moment(X, skew))
    c.holds("skew pair: is_coplanar is False", ss.is_coplanar(X, skew) is False)
    anti = ss.LineVector.from_axis([0, 1, 0], [-1, 0, 0])
    ca = ss.common_normal(X, anti)
    c.zero("anti-parallel: alpha12 - pi", ca.alpha12 - pi)
    c.zero("anti-parallel: a12 - 1, normal (0, 1, 0)",
           Matrix([ca.a12 - 1, *(ca.normal - Matrix([0, 1, 0]))]))
    c.nonzero("book's \"parallel => alpha12 = 0\" fails: anti-parallel alpha12", ca.alpha12, book=True)
