"""Section 1.5, screw algebra: (1.39)-(1.47), Theorems 1.1-1.3, line vector plus couple."""

from __future__ import annotations

from sympy import cos, pi, sin, symbols

from ._common import Z3, book_cross, book_dot, canonical_pair, generic_lines, real, ss, stack, vec
from ._statement import statement

_SEC = "1.5"


def _two_screws():
    S1, D1, S2, D2 = vec("S1"), vec("D1"), vec("S2"), vec("D2")
    return S1, D1, S2, D2, ss.Screw(S1, D1), ss.Screw(S2, D2)


def _through_c():
    cpt, A, B = vec("c"), vec("A"), vec("B")
    return cpt, A, B, ss.LineVector.from_axis(cpt, A), ss.LineVector.from_axis(cpt, B)


@statement(
    "1.39", "1.5.1", "Sum of two screws",
    r"\$_1+\$_2=(\mathbf S_1+\mathbf S_2;\ \mathbf S_1^0+\mathbf S_2^0)",
    "definition",
    "The library's sum of two generic screws against the componentwise sum.",
)
def _e1_39(c):
    S1, D1, S2, D2, s1, s2 = _two_screws()
    c.zero("(s1 + s2) - (S1 + S2; S1^0 + S2^0)", (s1 + s2).matrix - stack(S1 + S2, D1 + D2))


@statement(
    "Theorem 1.1", "1.5.1", "Sum of two line vectors",
    r"\$_1+\$_2\ \text{is a line vector}\iff\text{the axes are coplanar, given }"
    r"\mathbf S_1+\mathbf S_2\neq\mathbf 0",
    "conditional",
    """Generic lines (library): (S1 + S2) . (S01 + S02) equals mutual_moment, so the sum
    has pitch 0 exactly when M = 0. If: lines through a common point, and parallel lines,
    give pitch 0. Only if: the skew canonical pair gives a non-zero pitch. The condition
    S1 + S2 != 0 is needed: opposite parallel lines add to a couple, not a line vector.""",
    errata=("The book states \"only if\" but its proof proves \"if\"; the true statement is "
            "\"if and only if\", given S1 + S2 != 0 (else the sum is a couple or zero).",),
)
def _th1_1(c):
    L1, L2, p, q, u, w = generic_lines()
    sm = L1 + L2
    c.zero("(S1 + S2) . (S01 + S02) - M", book_dot(sm.S, sm.S0) - ss.mutual_moment(L1, L2))
    cpt, A, B, I1, I2 = _through_c()
    c.zero("if (intersecting): pitch of the sum", ss.pitch(I1 + I2))
    ra, mu = vec("ra"), symbols("mu", positive=True)
    c.zero("if (parallel, S2 = mu S1): pitch of the sum",
           ss.pitch(ss.LineVector.from_axis(ra, A) + ss.LineVector.from_axis(cpt, mu * A)))
    K1, K2, a12, alpha = canonical_pair()
    c.nonzero("only if: skew lines give a non-zero pitch", ss.pitch(K1 + K2), at={a12: 1, alpha: pi / 2})
    opp = ss.LineVector.from_axis([0, 0, 0], [1, 0, 0]) + ss.LineVector.from_axis([0, 1, 0], [-1, 0, 0])
    c.holds("coplanar but S1 + S2 = 0: the sum is a couple", ss.classify(opp) == "couple", book=True)


@statement(
    "1.40", "1.5.1", "The sum of two coplanar line vectors has zero pitch",
    r"(\mathbf S_1+\mathbf S_2)\cdot(\mathbf S_{01}+\mathbf S_{02})=0",
    "conditional",
    """Generic lines (library): the product equals S1.S01 + S2.S02 + reciprocal_product;
    it vanishes for intersecting and for parallel lines; pitch(L1 + L2) equals
    M/|S1 + S2|^2; for the skew canonical pair it is -a12 sin(alpha)/(2 + 2 cos(alpha)),
    non-zero.""",
)
def _e1_40(c):
    L1, L2, p, q, u, w = generic_lines()
    sm = L1 + L2
    c.zero("general: (S1+S2).(S01+S02) - (S1.S01 + S2.S02 + $1 o $2)",
           book_dot(sm.S, sm.S0) - (book_dot(u, L1.S0) + book_dot(w, L2.S0) + ss.reciprocal_product(L1, L2)))
    c.zero("pitch(L1 + L2) - M/|S1 + S2|^2",
           ss.pitch(sm) - ss.mutual_moment(L1, L2) / book_dot(u + w, u + w))
    cpt, A, B, I1, I2 = _through_c()
    s = I1 + I2
    c.zero("intersecting", book_dot(s.S, s.S0))
    ra, mu = vec("ra"), real("mu")
    P = ss.LineVector.from_axis(ra, A) + ss.LineVector.from_axis(cpt, mu * A)
    c.zero("parallel", book_dot(P.S, P.S0))
    K1, K2, a12, alpha = canonical_pair()
    c.zero("skew canonical pair: pitch + a12 sin(alpha)/(2 + 2 cos(alpha))",
           ss.pitch(K1 + K2) + a12 * sin(alpha) / (2 + 2 * cos(alpha)))
    c.nonzero("counter-example: skew pair pitch", ss.pitch(K1 + K2), at={a12: 1, alpha: pi / 2})


@statement(
    "Theorem 1.2", "1.5.1", "Two intersecting line vectors",
    r"\text{If two line vectors intersect, their sum is a line vector through the "
    r"intersection point }(\mathbf S_1+\mathbf S_2\neq\mathbf 0)",
    "conditional",
    """Library lines through a common generic point c: the sum has pitch 0 and contains
    c. A point r on line 1 only (line 2 generic) is not on the sum, and with numbers contains()
    answers True for a point of the sum and False for a point of line 1 only. With S2 = -S1 the
    sum is the zero screw.""",
    errata=("Tacitly needs S1 + S2 != 0; otherwise the sum is (0; 0).",),
)
def _th1_2(c):
    cpt, A, B, I1, I2 = _through_c()
    s = I1 + I2
    c.zero("pitch of the sum", ss.pitch(s))
    c.zero("c x (S1 + S2) - (S01 + S02)", book_cross(cpt, s.S) - s.S0)
    c.holds("contains(sum, c) is True", ss.contains(s, cpt) is True)
    N = ss.LineVector.from_axis([1, 2, 3], [1, 0, 0]) + ss.LineVector.from_axis([1, 2, 3], [0, 1, 0])
    c.holds("numbers: the sum through (1, 2, 3) contains (2, 3, 3)", ss.contains(N, [2, 3, 3]) is True)
    c.holds("numbers: (2, 2, 3), on line 1 only, is not on the sum", ss.contains(N, [2, 2, 3]) is False)
    q = vec("q")
    t = real("t")
    G2 = ss.LineVector.from_axis(q, B)
    r = cpt + t * A
    sG = I1 + G2
    c.nonzero("counter-example: r on line 1 only, r x (S1 + S2) - (S01 + S02)",
              book_cross(r, sG.S) - sG.S0)
    z = ss.LineVector.from_axis([1, 2, 3], [1, 0, 0]) + ss.LineVector.from_axis([1, 2, 3], [-1, 0, 0])
    c.holds("S2 = -S1: the sum is the zero screw", ss.classify(z) == "zero")


@statement(
    "1.41", "1.5.1", "Equation of the resultant line",
    r"\mathbf r\times(\mathbf S_1+\mathbf S_2)=\mathbf S_{01}+\mathbf S_{02}",
    "conditional",
    """For library lines through c, every point c + t (S1 + S2) satisfies the line
    equation of the sum and contains() is True; c + A (on line 1 only) does not, and contains() answers False for it with numbers.""",
)
def _e1_41(c):
    cpt, A, B, I1, I2 = _through_c()
    t = real("t")
    s = I1 + I2
    r = cpt + t * (A + B)
    c.zero("r x (S1 + S2) - (S01 + S02)", book_cross(r, A + B) - (I1.S0 + I2.S0))
    c.holds("contains(sum, r) is True", ss.contains(s, r) is True)
    N = ss.LineVector.from_axis([1, 2, 3], [1, 0, 0]) + ss.LineVector.from_axis([1, 2, 3], [0, 1, 0])
    c.holds("numbers: contains(sum, (1, 2, 3) + (1, 0, 0)) is False", ss.contains(N, [2, 2, 3]) is False)
    c.nonzero("counter-example: r = c + S1", book_cross(cpt + A, A + B) - (I1.S0 + I2.S0))


@statement(
    "1.42", "1.5.1", "The intersection point lies on both lines",
    r"\mathbf r_1\times\mathbf S_1=\mathbf S_{01},\qquad \mathbf r_1\times\mathbf S_2=\mathbf S_{02}",
    "conditional",
    """Library lines through the generic point r1: both equations hold and contains() is
    True for each; with line 2 through a generic q instead, r1 (on line 1 only) fails the second equation; contains() answers False for a point off a
    numeric line.""",
)
def _e1_42(c):
    r1, A, B = vec("r1"), vec("A"), vec("B")
    L1, L2 = ss.LineVector.from_axis(r1, A), ss.LineVector.from_axis(r1, B)
    c.zero("r1 x S1 - S01", book_cross(r1, A) - L1.S0)
    c.zero("r1 x S2 - S02", book_cross(r1, B) - L2.S0)
    c.holds("contains(L1, r1) and contains(L2, r1)", ss.contains(L1, r1) is True and ss.contains(L2, r1) is True)
    c.holds("numbers: (1, 2, 3) is not on the line through O along (0, 1, 0)",
            ss.contains(ss.LineVector.from_axis([0, 0, 0], [0, 1, 0]), [1, 2, 3]) is False)
    G2 = ss.LineVector.from_axis(vec("q"), B)
    c.nonzero("counter-example: r1 on line 1 only, r1 x S2 - S02", book_cross(r1, B) - G2.S0)


@statement(
    "1.43", "1.5.1", "The intersection point lies on the resultant",
    r"\mathbf r_1\times(\mathbf S_1+\mathbf S_2)=\mathbf S_{01}+\mathbf S_{02}",
    "conditional",
    """Library lines through r1: r1 satisfies the equation of the sum. With line 2 through
    a generic q, r x (S1 + S2) - (S01 + S02) = r x S2 - S02 != 0 for r on line 1 only.""",
)
def _e1_43(c):
    r1, A, B = vec("r1"), vec("A"), vec("B")
    s = ss.LineVector.from_axis(r1, A) + ss.LineVector.from_axis(r1, B)
    c.zero("r1 x (S1 + S2) - (S01 + S02)", book_cross(r1, s.S) - s.S0)
    G2 = ss.LineVector.from_axis(vec("q"), B)
    sG = ss.LineVector.from_axis(r1, A) + G2
    c.zero("r on line 1 only: residual = r1 x S2 - S02",
           (book_cross(r1, sG.S) - sG.S0) - (book_cross(r1, B) - G2.S0))
    c.nonzero("counter-example: r on line 1 only", book_cross(r1, sG.S) - sG.S0)


@statement(
    "Line vector plus couple", "1.5.1", "A line vector plus a couple (remark after 1.43)",
    r"(\mathbf S;\ \mathbf S_0)+(\mathbf 0;\ \mathbf C)\ \text{is a line vector}\iff"
    r"\mathbf S\cdot\mathbf C=0",
    "conditional",
    """Library line through p along S plus the couple (0; C): pitch = S . C/(S . S); with
    C = S x w (perpendicular) the pitch is 0 and the numeric example (1 0 0; 0 0 0) +
    (0; 0 0 1) is classified a line, refuting the book; with S . C != 0 it is a screw.""",
    errata=("\"The sum of a line vector and a couple is not a line vector\" is too strong: "
            "it is a line vector (a parallel, displaced line) exactly when C is perpendicular "
            "to S.",),
)
def _lv_plus_couple(c):
    p, S, C, w = vec("p"), vec("S"), vec("C"), vec("w")
    L = ss.LineVector.from_axis(p, S)
    c.zero("pitch - S . C/(S . S)", ss.pitch(L + ss.Screw.couple(C)) - book_dot(S, C) / book_dot(S, S))
    c.zero("C = S x w: pitch of the sum", ss.pitch(L + ss.Screw.couple(book_cross(S, w))))
    X = ss.LineVector.from_axis([0, 0, 0], [1, 0, 0])
    c.holds("book fails: (1 0 0; 0 0 0) + (0; 0 0 1) is a line",
            ss.classify(X + ss.Screw.couple([0, 0, 1])) == "line", book=True)
    c.nonzero("S . C != 0: pitch of (1 0 0; 0 0 0) + (0; 1 0 0)", ss.pitch(X + ss.Screw.couple([1, 0, 0])))


@statement(
    "Theorem 1.3", "1.5.1", "The sum of two couples",
    r"(\mathbf 0;\ \mathbf C_1)+(\mathbf 0;\ \mathbf C_2)=(\mathbf 0;\ \mathbf C_1+\mathbf C_2)"
    r"\ \text{is a couple if not zero}",
    "conditional",
    """Library couples with generic C1, C2: the sum is (0; C1 + C2); with C1 = (a,0,0),
    C2 = (b,0,0), a, b > 0, classify() says couple; C2 = -C1 gives the zero screw, not a
    couple.""",
)
def _th1_3(c):
    C1, C2 = vec("C1"), vec("C2")
    s = ss.Screw.couple(C1) + ss.Screw.couple(C2)
    c.zero("sum - (0; C1 + C2)", s.matrix - stack(Z3, C1 + C2))
    a, b = symbols("a b", positive=True)
    c.holds("classify == 'couple'", ss.classify(ss.Screw.couple([a, 0, 0]) + ss.Screw.couple([b, 0, 0])) == "couple")
    z = ss.Screw.couple([1, 2, 3]) + ss.Screw.couple([-1, -2, -3])
    c.holds("counter-example: C2 = -C1 gives the zero screw, not a couple", ss.classify(z) == "zero")


@statement(
    "1.44", "1.5.2", "Product of a scalar and a screw",
    r"\lambda\$=(\lambda\mathbf S;\ \lambda\mathbf S^0)",
    "definition",
    """lam times a generic screw (library) against (lam S; lam S0); for lam != 0 the
    pitch and the foot of the axis are unchanged; 0 times a screw is the zero screw.""",
)
def _e1_44(c):
    S1, D1, S2, D2, s1, s2 = _two_screws()
    lam = real("lambda")
    c.zero("lam s - (lam S; lam S0)", (lam * s1).matrix - stack(lam * S1, lam * D1))
    nz = symbols("mu", real=True, nonzero=True)
    c.zero("pitch(mu s) - pitch(s)", ss.pitch(nz * s1) - ss.pitch(s1))
    c.zero("foot(mu s) - foot(s)", ss.foot(nz * s1) - ss.foot(s1))
    c.holds("0 times (1 1 0; 1 0 0) is the zero screw", ss.classify(0 * ss.Screw([1, 1, 0], [1, 0, 0])) == "zero")


@statement(
    "1.45", "1.5.3", "Reciprocal product",
    r"\$_1\circ\$_2=\mathbf S_1\cdot\mathbf S_2^0+\mathbf S_2\cdot\mathbf S_1^0",
    "definition",
    """reciprocal_product of two generic screws against the formula; it is symmetric;
    $ o $ = 2 h S . S; for line vectors it is mutual_moment; for a twist (omega; v_O) and
    a wrench (a force f through r_f plus a couple C) power() equals f . (velocity of r_f) + C . omega; is_reciprocal answers True for a turn
    about Z and a force along Z, False for a force along Y through (1, 0, 0).""",
)
def _e1_45(c):
    S1, D1, S2, D2, s1, s2 = _two_screws()
    c.zero("$1 o $2 - (S1 . S2^0 + S2 . S1^0)",
           ss.reciprocal_product(s1, s2) - (book_dot(S1, D2) + book_dot(S2, D1)))
    c.zero("symmetric", ss.reciprocal_product(s1, s2) - ss.reciprocal_product(s2, s1))
    c.zero("$ o $ - 2 h S . S", ss.reciprocal_product(s1, s1) - 2 * ss.pitch(s1) * book_dot(S1, S1))
    L1, L2, p, q, u, w = generic_lines()
    c.zero("lines: $1 o $2 - mutual moment", ss.reciprocal_product(L1, L2) - ss.mutual_moment(L1, L2))
    om, vO, f, rf, Cw = vec("omega"), vec("v"), vec("f"), vec("rf"), vec("Cw")
    T = ss.Twist(om, vO)
    W = ss.Wrench.force(f, point=rf) + ss.Wrench.couple(Cw)
    c.zero("power - (f . v(rf) + C . omega)", ss.power(T, W) - (book_dot(f, T.velocity_at(rf)) + book_dot(Cw, om)))
    z_turn = ss.Screw([0, 0, 1], [0, 0, 0])
    c.holds("is_reciprocal: a turn about Z and a force along Z through (1, 0, 0)",
            ss.is_reciprocal(z_turn, ss.Screw([0, 0, 1], [0, -1, 0])) is True)
    c.holds("is_reciprocal is False: a force along Y through (1, 0, 0) (product 1)",
            ss.is_reciprocal(z_turn, ss.Screw([0, 1, 0], [0, 0, 1])) is False)


@statement(
    "1.46", "1.5.3", "Both screws about a new origin A",
    r"\$_1^A=(\mathbf S_1;\ \mathbf S_1^0+\overrightarrow{AO}\times\mathbf S_1),\qquad "
    r"\$_2^A=(\mathbf S_2;\ \mathbf S_2^0+\overrightarrow{AO}\times\mathbf S_2)",
    "definition",
    """shift_origin of two generic screws to a against (S_i; S_i^0 + AO x S_i), AO = -a;
    the direction is pinned with from_axis (axis point p becomes p - a).""",
)
def _e1_46(c):
    S1, D1, S2, D2, s1, s2 = _two_screws()
    a, p = vec("a"), vec("p")
    h = real("h")
    AO = -a
    c.zero("$1^A - (S1; S1^0 + AO x S1)", ss.shift_origin(s1, a).matrix - stack(S1, D1 + book_cross(AO, S1)))
    c.zero("$2^A - (S2; S2^0 + AO x S2)", ss.shift_origin(s2, a).matrix - stack(S2, D2 + book_cross(AO, S2)))
    c.zero("pin: shift_origin(from_axis(p, S1, h), a) - from_axis(p - a, S1, h)",
           ss.shift_origin(ss.Screw.from_axis(p, S1, h), a).matrix
           - ss.Screw.from_axis(p - a, S1, h).matrix)


@statement(
    "1.47", "1.5.3", "The reciprocal product does not depend on the origin",
    r"\$_1^A\circ\$_2^A=\mathbf S_1\cdot(\mathbf S_2^0+\overrightarrow{AO}\times\mathbf S_2)"
    r"+\mathbf S_2\cdot(\mathbf S_1^0+\overrightarrow{AO}\times\mathbf S_1)=\$_1\circ\$_2",
    "identity",
    """reciprocal_product of the two generic screws shifted to a generic a (library)
    equals the expanded middle expression and the unshifted product, and the middle expression
    holds term by term (S1 . S2^A = S1 . (S2^0 + AO x S2)), which pins the shift.""",
)
def _e1_47(c):
    S1, D1, S2, D2, s1, s2 = _two_screws()
    a = vec("a")
    AO = -a
    shifted = ss.reciprocal_product(ss.shift_origin(s1, a), ss.shift_origin(s2, a))
    c.zero("$1^A o $2^A - middle expression",
           shifted - (book_dot(S1, D2 + book_cross(AO, S2)) + book_dot(S2, D1 + book_cross(AO, S1))))
    c.zero("$1^A o $2^A - $1 o $2", shifted - ss.reciprocal_product(s1, s2))
    s1A, s2A = ss.shift_origin(s1, a), ss.shift_origin(s2, a)
    c.zero("term by term: S1 . S2^A - S1 . (S2^0 + AO x S2)",
           book_dot(S1, s2A.S0) - book_dot(S1, D2 + book_cross(AO, S2)))
    c.zero("term by term: S2 . S1^A - S2 . (S1^0 + AO x S1)",
           book_dot(S2, s1A.S0) - book_dot(S2, D1 + book_cross(AO, S1)))


