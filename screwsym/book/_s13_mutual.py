"""Section 1.3, mutual moment of two lines: (1.19)-(1.27)."""

from __future__ import annotations

from sympy import Matrix, cos, pi, sin, sqrt

from ._common import (
    book_cross,
    book_dot,
    canonical_pair,
    generic_lines,
    real,
    ss,
    vec,
    x_axis_and_generic_line,
)
from ._registry import statement

_SEC = "1.3"
_CONVENTION = (
    "Sign convention (transcription section 9, row 6): (1.24)/(1.25) hold when the unit "
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
    """Line 1 the X axis, line 2 generic (library); a12, the unit normal a12 and the feet
    from the library's common_normal; mutual_moment must equal a12 a12 x S2 . S1 and
    a12 a21 x S1 . S2; a12 >= 0; the feet differ by a12 a12. The normal reversed
    (a21 in the first formula) gives a non-zero difference.""",
    notes=("OCR: \"projecting the moment vector - a12 a12 x S1 on the line S2\": the leading "
           "symbol is a minus, i.e. a12 a21 x S1.",),
)
def _e1_21(c):
    L1, L2, q, w = x_axis_and_generic_line()
    cn = ss.common_normal(L1, L2)
    M = ss.mutual_moment(L1, L2)
    S1, S2 = L1.S, L2.S
    c.zero("M - a12 (a12 x S2) . S1", M - cn.a12 * book_dot(book_cross(cn.normal, S2), S1))
    c.zero("M - a12 (a21 x S1) . S2", M - cn.a12 * book_dot(book_cross(-cn.normal, S1), S2))
    c.zero("foot2 - foot1 - a12 a12", cn.foot2 - cn.foot1 - cn.a12 * cn.normal)
    c.nonnegative("a12 >= 0", cn.a12)
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
    cos of alpha; S2 x S1 + a12 sin alpha12 = 0. For generic lines (X axis and a generic
    line): S1 x S2 = |S1||S2| sin(alpha12) a12 and S1 . S2 = |S1||S2| cos(alpha12).
    The reversed convention (normal from 2 to 1) fails.""",
    errata=(_CONVENTION,),
)
def _e1_24(c):
    L1, L2, a12, alpha = canonical_pair()
    cn = ss.common_normal(L1, L2)
    c.zero("a12 from common_normal - a12", cn.a12 - a12)
    c.zero("normal - k", cn.normal - Matrix([0, 0, 1]))
    c.zero("sin(alpha12) - sin(alpha)", sin(cn.alpha12) - sin(alpha))
    c.zero("S2 x S1 + a12 sin(alpha12)", book_cross(L2.S, L1.S) + cn.normal * sin(cn.alpha12))
    G1, G2, q, w = x_axis_and_generic_line()
    g = ss.common_normal(G1, G2)
    n1, n2 = sqrt(book_dot(G1.S, G1.S)), sqrt(book_dot(w, w))


    c.zero("generic: S1 x S2 - |S1||S2| sin(alpha12) a12",
           book_cross(G1.S, w) - n1 * n2 * sin(g.alpha12) * g.normal)
    c.zero("generic: S1 . S2 - |S1||S2| cos(alpha12)", book_dot(G1.S, w) - n1 * n2 * cos(g.alpha12))
    c.nonzero("counter-example: reversed convention, S2 x S1 - a12 sin(alpha12)",
              book_cross(L2.S, L1.S) - cn.normal * sin(cn.alpha12), at={a12: 1, alpha: pi / 2},
              book=True)


@statement(
    "1.25", _SEC, "Mutual moment from distance and twist angle",
    r"M_m=(\mathbf r_2-\mathbf r_1)\cdot\mathbf S_2\times\mathbf S_1=-a_{12}\sin\alpha_{12}",
    "identity",
    """Canonical unit pair via the library: mutual_moment + a12 sin(alpha12) = 0 with
    a12, alpha12 from common_normal. Frame independence: for the X axis and a generic
    line, M = -|S1||S2| a12 sin(alpha12) from the library's common_normal, a12 >= 0,
    and common_normal(L2, L1) (the reversed convention, applied consistently) gives the
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
    G1, G2, q, w = x_axis_and_generic_line()
    g = ss.common_normal(G1, G2)
    MG = ss.mutual_moment(G1, G2)
    nn = sqrt(book_dot(G1.S, G1.S)) * sqrt(book_dot(w, w))
    c.zero("generic: M + |S1||S2| a12 sin(alpha12)", MG + nn * g.a12 * sin(g.alpha12))
    c.nonnegative("generic: a12 >= 0", g.a12)
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
    """Library lines through a common point c (generic directions), and parallel lines
    (S2 = mu S1): mutual_moment vanishes and is_coplanar is True. The canonical skew pair
    gives M != 0. Anti-parallel lines have alpha12 = pi, not 0.""",
    errata=("The book says parallel lines have alpha12 = 0; they may be anti-parallel, "
            "alpha12 in {0, pi} (sin alpha12 = 0). M = 0 either way.",),
)
def _e1_27(c):
    cpt, A, B, ra, rb = vec("c"), vec("A"), vec("B"), vec("ra"), vec("rb")
    mu = real("mu")
    I1, I2 = ss.LineVector.from_axis(cpt, A), ss.LineVector.from_axis(cpt, B)
    c.zero("intersecting: M", ss.mutual_moment(I1, I2))
    c.holds("intersecting: is_coplanar", ss.is_coplanar(I1, I2))
    P1, P2 = ss.LineVector.from_axis(ra, A), ss.LineVector.from_axis(rb, mu * A)
    c.zero("parallel: M", ss.mutual_moment(P1, P2))
    c.holds("parallel: is_coplanar", ss.is_coplanar(P1, P2))
    L1, L2, a12, alpha = canonical_pair()
    c.nonzero("counter-example: skew canonical pair, M", ss.mutual_moment(L1, L2),
              at={a12: 1, alpha: pi / 2})
    X = ss.LineVector.from_axis([0, 0, 0], [1, 0, 0])
    anti = ss.LineVector.from_axis([0, 1, 0], [-1, 0, 0])
    cn = ss.common_normal(X, anti)
    c.zero("anti-parallel: sin(alpha12)", sin(cn.alpha12))
    c.nonzero("book's \"parallel => alpha12 = 0\" fails: anti-parallel alpha12", cn.alpha12, book=True)

