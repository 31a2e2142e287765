"""Section 1.2, equation of a line: (1.1)-(1.18), homogeneity, special cases."""

from __future__ import annotations

from sympy import Matrix, oo, sqrt, symbols

from ._common import Z3, book_cross, book_dot, real, ss, vec
from ._statement import statement

_SEC = "1.2"


def _AB():
    x1, y1, z1, x2, y2, z2 = real("x1 y1 z1 x2 y2 z2")
    r1, r2 = Matrix([x1, y1, z1]), Matrix([x2, y2, z2])
    return r1, r2, ss.LineVector.through(r1, r2)


def _LMN():
    L, M, N = real("L M N")
    x1, y1, z1 = real("x1 y1 z1")
    return L, M, N, Matrix([x1, y1, z1]), Matrix([L, M, N])


@statement(
    "1.1", _SEC, "Direction vector of the line AB",
    r"\mathbf S=(x_2-x_1)\,\mathbf i+(y_2-y_1)\,\mathbf j+(z_2-z_1)\,\mathbf k",
    "definition",
    """A(x1,y1,z1), B(x2,y2,z2) generic real points; LineVector.through(A, B); its S
    must equal (x2-x1) i + (y2-y1) j + (z2-z1) k written with the unit vectors.""",
)
def _e1_1(c):
    r1, r2, L = _AB()
    i, j, k = Matrix([1, 0, 0]), Matrix([0, 1, 0]), Matrix([0, 0, 1])
    c.zero("S - ((x2-x1)i + (y2-y1)j + (z2-z1)k)",
           L.S - ((r2[0] - r1[0]) * i + (r2[1] - r1[1]) * j + (r2[2] - r1[2]) * k))


@statement(
    "1.2", _SEC, "Direction ratios",
    r"x_2-x_1=L,\qquad y_2-y_1=M,\qquad z_2-z_1=N",
    "definition",
    """The components of LineVector.through(A, B).S are the direction ratios L, M, N,
    each compared with its coordinate difference.""",
)
def _e1_2(c):
    r1, r2, L = _AB()
    for n, comp in enumerate("LMN"):
        c.zero(f"{comp} - ({'xyz'[n]}2-{'xyz'[n]}1)", L.S[n] - (r2[n] - r1[n]))


@statement(
    "1.3", _SEC, "Direction vector in direction ratios",
    r"\mathbf S=L\,\mathbf i+M\,\mathbf j+N\,\mathbf k",
    "identity",
    """B = A + (L, M, N) with generic real L, M, N; LineVector.through(A, B).S must be
    L i + M j + N k.""",
)
def _e1_3(c):
    L, M, N, r1, S = _LMN()
    line = ss.LineVector.through(r1, r1 + S)
    c.zero("S - (L i + M j + N k)", line.S - Matrix([L, M, N]))


@statement(
    "1.4", _SEC, "Length of S, the distance |AB|",
    r"|\mathbf S|=\sqrt{L^2+M^2+N^2}",
    "identity",
    """Line through A and A + (L, M, N); |S| is obtained from the library as
    S . direction_cosines(line); it must equal sqrt(L^2+M^2+N^2) and the distance
    sqrt((B-A).(B-A)).""",
)
def _e1_4(c):
    L, M, N, r1, S = _LMN()
    r2 = r1 + S
    line = ss.LineVector.through(r1, r2)
    norm = book_dot(line.S, ss.direction_cosines(line))
    c.zero("|S| - sqrt(L^2+M^2+N^2)", norm - sqrt(L**2 + M**2 + N**2))
    c.zero("|S| - |AB|", norm - sqrt(book_dot(r2 - r1, r2 - r1)))


@statement(
    "1.5", _SEC, "Direction cosines",
    r"l=\frac{L}{|\mathbf S|},\qquad m=\frac{M}{|\mathbf S|},\qquad n=\frac{N}{|\mathbf S|}",
    "definition",
    """direction_cosines of the line along (L, M, N) must equal (L, M, N)/sqrt(L^2+M^2+N^2).""",
)
def _e1_5(c):
    L, M, N, r1, S = _LMN()
    dc = ss.direction_cosines(ss.LineVector.from_axis(r1, S))
    c.zero("(l, m, n) - (L, M, N)/|S|", dc - Matrix([L, M, N]) / sqrt(L**2 + M**2 + N**2))


@statement(
    "1.6", _SEC, "Normalisation of the direction cosines",
    r"l^2+m^2+n^2=1",
    "identity",
    """(l, m, n) = direction_cosines of the line along generic (L, M, N); l^2+m^2+n^2-1
    must vanish.""",
    notes=("The book says \"Eq. (1.4) reduces to\"; it follows from (1.5) together with "
           "(1.4). Review: not an erratum (dividing (1.4) squared by |S|^2 does reduce it).",),
)
def _e1_6(c):
    L, M, N, r1, S = _LMN()
    l, m, n = ss.direction_cosines(ss.LineVector.from_axis(r1, S))
    c.zero("l^2 + m^2 + n^2 - 1", l**2 + m**2 + n**2 - 1)


def _line_r1_S():
    r1, S, r, w = vec("r1"), vec("S"), vec("r"), vec("w")
    return r1, S, r, w, ss.LineVector.from_axis(r1, S)


@statement(
    "1.7", _SEC, "Vector equation of the line (point-direction form)",
    r"(\mathbf r-\mathbf r_1)\times\mathbf S=\mathbf 0",
    "conditional",
    """Line through generic r1 along generic S (library). For r = r1 + t S and for
    r = B = r1 + S the expression vanishes and contains() is True; for the point r1 + S x w off the line it does not vanish. With numbers, contains() answers
    True on the line and False off it.""",
)
def _e1_7(c):
    r1, S, r, w, line = _line_r1_S()
    t = real("t")
    for lbl, pt in (("r = r1 + t S", r1 + t * S), ("r = r2 = r1 + S", r1 + S)):
        c.zero(f"(r - r1) x S at {lbl}", book_cross(pt - r1, line.S))
        c.holds(f"contains(line, {lbl}) is True", ss.contains(line, pt) is True)
    c.nonzero("counter-example: r = r1 + S x w (off the line)", book_cross(book_cross(S, w), line.S))
    N = ss.LineVector.from_axis([1, 2, 3], [2, -1, 1])
    c.holds("contains(line through (1, 2, 3) along (2, -1, 1), (3, 1, 4)) is True",
            ss.contains(N, [3, 1, 4]) is True)
    c.holds("contains(the same line, (1, 2, 4)) is False (off the line)",
            ss.contains(N, [1, 2, 4]) is False)


@statement(
    "1.8", _SEC, "Line equation in moment form",
    r"\mathbf r\times\mathbf S=\mathbf S_0",
    "conditional",
    """Line through generic r1 along S (library): (r-r1) x S equals r x S - S0 for
    every r; (r1 + t S) x S - S0 vanishes for every real t; a point off the line,
    r1 + S x w, gives a non-zero value.""",
)
def _e1_8(c):
    r1, S, r, w, line = _line_r1_S()
    t = real("t")
    c.zero("(r - r1) x S - (r x S - S0)", book_cross(r - r1, S) - (book_cross(r, S) - line.S0))
    c.zero("(r1 + t S) x S - S0", book_cross(r1 + t * S, S) - line.S0)
    c.nonzero("counter-example: r = r1 + S x w", book_cross(r1 + book_cross(S, w), S) - line.S0)


@statement(
    "1.9", _SEC, "Moment of the line about the origin",
    r"\mathbf S_0=\mathbf r_1\times\mathbf S",
    "definition",
    """LineVector.from_axis(r1, S).S0 and LineVector.through(r1, r2).S0 must equal the
    determinant expansion of r1 x S (S = r2 - r1).""",
    notes=("(S; S0) are the Plücker coordinates of the line.",),
)
def _e1_9(c):
    r1, S, r, w, line = _line_r1_S()
    c.zero("from_axis(r1, S).S0 - r1 x S", line.S0 - book_cross(r1, S))
    r2 = vec("r2")
    c.zero("through(r1, r2).S0 - r1 x (r2 - r1)",
           ss.LineVector.through(r1, r2).S0 - book_cross(r1, r2 - r1))


@statement(
    "1.10", _SEC, "Orthogonality (Plücker) condition",
    r"\mathbf S\cdot\mathbf S_0=0",
    "identity",
    """For the library's line through generic r1 along generic S, S0 is r1 x S
    (checked against the determinant expansion, which pins its sign) and S . S0
    vanishes; the counter-example (S; S) is no line (its dot product is S . S != 0),
    and the library refuses the line vector (1 2 3; 1 2 3).""",
)
def _e1_10(c):
    r1, S, r, w, line = _line_r1_S()
    c.zero("S0 - r1 x S (1.9)", line.S0 - book_cross(r1, S))
    c.zero("S . S0", book_dot(line.S, line.S0))
    try:
        ss.LineVector([1, 2, 3], [1, 2, 3])
        refused = False
    except ValueError:
        refused = True
    c.holds("LineVector((1 2 3), (1 2 3)) is refused (S . S0 = 14)", refused)
    c.nonzero("counter-example: (S; S) has S . S0 = S . S", book_dot(S, S))


@statement(
    "Homogeneity", _SEC, "(S; S0) and (lambda S; lambda S0) are the same line",
    r"(\lambda\mathbf S;\ \lambda\mathbf S_0)\ \text{and}\ (\mathbf S;\ \mathbf S_0)"
    r"\ \text{represent the same line},\ \lambda\neq0",
    "identity",
    """lam (nonzero real) times the library's line: every point r1 + t S satisfies its
    line equation, its foot point and its moment over lambda are those of the line;
    (S; 2 S0) is a different line (different foot point).""",
)
def _e_homog(c):
    r1, S, r, w, line = _line_r1_S()
    lam = symbols("lambda", real=True, nonzero=True)
    t = real("t")
    scaled = lam * line
    c.zero("(r1 + t S) x (lam S) - lam S0", book_cross(r1 + t * S, scaled.S) - scaled.S0)
    c.zero("foot(lam line) - foot(line)", ss.foot(scaled) - ss.foot(line))
    c.zero("r x (lam S) - lam S0 - lam (r x S - S0)",
           book_cross(r, scaled.S) - scaled.S0 - lam * (book_cross(r, line.S) - line.S0))
    other = ss.LineVector(line.S, 2 * line.S0)
    c.nonzero("counter-example: (S; 2 S0) has another foot point", ss.foot(other) - ss.foot(line))


def _det_IJK():
    L, M, N, r1, S = _LMN()
    I, J, K = symbols("I J K", commutative=True)
    det = Matrix([[I, J, K], [r1[0], r1[1], r1[2]], [L, M, N]]).det()
    return L, M, N, r1, S, I, J, K, det


@statement(
    "1.11", _SEC, "Determinant form of S0",
    r"\mathbf S_0=\begin{vmatrix}\mathbf i&\mathbf j&\mathbf k\\ x_1&y_1&z_1\\ L&M&N\end{vmatrix}",
    "identity",
    """The 3x3 determinant with formal symbols I, J, K in the first row, expanded by
    SymPy, must equal P I + Q J + R K with (P, Q, R) the library's moment of the line
    through (x1, y1, z1) along (L, M, N).""",
)
def _e1_11(c):
    L, M, N, r1, S, I, J, K, det = _det_IJK()
    S0 = ss.LineVector.from_axis(r1, S).S0
    c.zero("det - (P I + Q J + R K)", det - (S0[0] * I + S0[1] * J + S0[2] * K))


@statement(
    "1.12", _SEC, "Components of S0",
    r"\mathbf S_0=P\,\mathbf i+Q\,\mathbf j+R\,\mathbf k",
    "definition",
    """P, Q, R are read off the determinant (1.11) as the coefficients of i, j, k;
    the library's S0 must be P i + Q j + R k.""",
    errata=("The vector P of (1.16)-(1.18) shares its name with the scalar P here "
            "(called Pf in the constructions).",),
)
def _e1_12(c):
    L, M, N, r1, S, I, J, K, det = _det_IJK()
    P, Q, R = (det.expand().coeff(X) for X in (I, J, K))
    S0 = ss.LineVector.from_axis(r1, S).S0
    c.zero("S0 - (P i + Q j + R k)", S0 - Matrix([P, Q, R]))


@statement(
    "1.13", _SEC, "Moment components",
    r"P=y_1N-z_1M,\qquad Q=z_1L-x_1N,\qquad R=x_1M-y_1L",
    "identity",
    """The library's moment of the line through (x1, y1, z1) along (L, M, N) against
    the three printed formulas.""",
    notes=("The Q line is illegible in the scanned text and was rebuilt as the cofactor of j, "
           "Q = z1 L - x1 N.",),
)
def _e1_13(c):
    L, M, N, r1, S = _LMN()
    x1, y1, z1 = r1
    S0 = ss.LineVector.from_axis(r1, S).S0
    c.zero("S0 - (y1 N - z1 M, z1 L - x1 N, x1 M - y1 L)",
           S0 - Matrix([y1 * N - z1 * M, z1 * L - x1 * N, x1 * M - y1 * L]))


@statement(
    "1.14", _SEC, "Scalar (Cartesian) equations of the line",
    r"yN-zM-P=0,\qquad zL-xN-Q=0,\qquad xM-yL-R=0",
    "conditional",
    """E = (yN - zM - P, zL - xN - Q, xM - yL - R) with (P, Q, R) the library's moment:
    E = r x S - S0 for all r; E vanishes at (x1 + tL, y1 + tM, z1 + tN); only two
    equations are independent (L E1 + M E2 + N E3 = 0); a point off the line gives
    E != 0.""",
)
def _e1_14(c):
    L, M, N, r1, S = _LMN()
    x, y, z, t = real("x y z t")
    P, Q, R = ss.LineVector.from_axis(r1, S).S0
    E = Matrix([y * N - z * M - P, z * L - x * N - Q, x * M - y * L - R])
    c.zero("E - (r x S - S0)", E - (book_cross(Matrix([x, y, z]), S) - Matrix([P, Q, R])))
    on = {x: r1[0] + t * L, y: r1[1] + t * M, z: r1[2] + t * N}
    c.zero("E at r1 + t S", E.subs(on))
    c.zero("L E1 + M E2 + N E3", L * E[0] + M * E[1] + N * E[2])
    w = vec("w")
    off = r1 + book_cross(S, w)
    c.nonzero("counter-example: E at r1 + S x w", E.subs({x: off[0], y: off[1], z: off[2]}))


@statement(
    "1.15", _SEC, "Orthogonality condition in components",
    r"LP+MQ+NR=0",
    "identity",
    """(P, Q, R) the library's moment of the line through (x1, y1, z1) along (L, M, N),
    checked against the determinant expansion of r1 x S (which pins its sign); L P +
    M Q + N R must vanish.""",
)
def _e1_15(c):
    L, M, N, r1, S = _LMN()
    P, Q, R = ss.LineVector.from_axis(r1, S).S0
    c.zero("(P, Q, R) - r1 x S", Matrix([P, Q, R]) - book_cross(r1, S))
    c.zero("L P + M Q + N R", L * P + M * Q + N * R)


@statement(
    "Derivation of 1.16", _SEC, "Foot of the perpendicular: the derivation",
    r"\mathbf P\times\mathbf S=\mathbf S_0\ \Rightarrow\ "
    r"\mathbf S\times(\mathbf P\times\mathbf S)=\mathbf S\times\mathbf S_0,\qquad "
    r"\mathbf S\times(\mathbf P\times\mathbf S)=(\mathbf S\cdot\mathbf S)\mathbf P"
    r"-(\mathbf S\cdot\mathbf P)\mathbf S=(\mathbf S\cdot\mathbf S)\mathbf P",
    "identity",
    """P = foot(line) from the library for the line through generic r1 along S:
    P x S = S0, S . P = 0, the BAC-CAB rule S x (P x S) = (S.S) P - (S.P) S, and
    S x (P x S) = S x S0.""",
)
def _e_deriv16(c):
    r1, S, r, w, line = _line_r1_S()
    P = ss.foot(line)
    c.zero("P x S - S0", book_cross(P, S) - line.S0)
    c.zero("S . P", book_dot(S, P))
    c.zero("S x (P x S) - ((S.S) P - (S.P) S)",
           book_cross(S, book_cross(P, S)) - (book_dot(S, S) * P - book_dot(S, P) * S))
    c.zero("S x (P x S) - S x S0", book_cross(S, book_cross(P, S)) - book_cross(S, line.S0))


@statement(
    "1.16", _SEC, "Foot of the perpendicular from the origin",
    r"\mathbf P=\frac{\mathbf S\times\mathbf S_0}{\mathbf S\cdot\mathbf S}",
    "identity",
    """foot(line) of the library's line through generic r1 along S: it equals the
    formula, lies on the line ((P - r1) x S = 0) and is perpendicular to S; for a
    generic screw (S; S0) foot() is the foot of the axis: P x S = S0 - h S.""",
    errata=("The vector P shares its name with the scalar P of (1.12)-(1.13).",),
)
def _e1_16(c):
    r1, S, r, w, line = _line_r1_S()
    P = ss.foot(line)
    c.zero("P - S x S0/(S.S)", P - book_cross(S, line.S0) / book_dot(S, S))
    c.zero("(P - r1) x S", book_cross(P - r1, S))
    c.zero("P . S", book_dot(P, S))
    S0 = vec("D")
    s = ss.Screw(S, S0)
    h = book_dot(S, S0) / book_dot(S, S)
    c.zero("screw: foot x S - (S0 - h S)", book_cross(ss.foot(s), S) - (S0 - h * S))


@statement(
    "1.17", _SEC, "Magnitude and direction of P",
    r"\mathbf P=\frac{|\mathbf S|\,|\mathbf S_0|}{|\mathbf S|\,|\mathbf S|}\,\mathbf e"
    r"=\frac{|\mathbf S_0|}{|\mathbf S|}\,\mathbf e,\qquad "
    r"\mathbf e=\frac{\mathbf S\times\mathbf S_0}{|\mathbf S\times\mathbf S_0|}",
    "identity",
    """P = foot(line) of the library's line through generic r1 along S; |S x S0| =
    |S| |S0|; P is parallel to S x S0 with the same sense, perpendicular to S0, and
    |P|^2 = |S0|^2/|S|^2 (squared, so that no radicals are needed).""",
    notes=("e is parallel to S x S0 (perpendicular to S and S0); the scanned text reads "
           "\"perpendicular to S x S0\". Review: the mathematics is right; whether the "
           "book or the scan lost the word cannot be told. e is undefined when S0 = 0.",),
)
def _e1_17(c):
    r1, S, r, w, line = _line_r1_S()
    S0 = line.S0
    P = ss.foot(line)
    n = book_cross(S, S0)
    c.zero("|S x S0|^2 - |S|^2 |S0|^2", book_dot(n, n) - book_dot(S, S) * book_dot(S0, S0))
    c.zero("P x (S x S0)", book_cross(P, n))
    c.zero("P . (S x S0) - |S x S0|^2/(S.S)", book_dot(P, n) - book_dot(n, n) / book_dot(S, S))
    c.zero("P . S0", book_dot(P, S0))
    c.zero("|P|^2 - |S0|^2/|S|^2 (the magnitude, squared)",
           book_dot(P, P) - book_dot(S0, S0) / book_dot(S, S))


@statement(
    "1.18", _SEC, "Distance of the line from the origin",
    r"|\mathbf P|=\frac{|\mathbf S_0|}{|\mathbf S|}",
    "identity",
    """distance_to_origin(line) of the library's line through generic r1 along S must
    equal |S0|/|S| (compared squared) and be nonnegative.""",
)
def _e1_18(c):
    r1, S, r, w, line = _line_r1_S()
    d = ss.distance_to_origin(line)
    c.zero("d^2 - S0.S0/S.S", d**2 - book_dot(line.S0, line.S0) / book_dot(S, S))
    c.nonnegative("d >= 0", d)


@statement(
    "Special case S0=0", _SEC, "A line through the origin",
    r"\mathbf S_0=\mathbf 0:\quad(\mathbf S;\ \mathbf 0)=(l\ m\ n;\ 0\ 0\ 0)",
    "conditional",
    """The library's line through the origin along generic S: S0 = 0, foot point 0,
    distance 0, and the origin lies on it (contains() is False for (1, 0, 0) on (1 2 3; 0 0 0)); a line
    through r1 off the origin has a non-zero moment.""",
)
def _e_s0zero(c):
    S = vec("S")
    line = ss.LineVector.from_axis(Z3, S)
    c.zero("S0", line.S0)
    c.zero("foot", ss.foot(line))
    c.zero("distance", ss.distance_to_origin(line))
    c.holds("contains(line, O) is True", ss.contains(line, Z3) is True)
    c.holds("contains((1 2 3; 0 0 0), (1, 0, 0)) is False",
            ss.contains(ss.LineVector.from_axis(Z3, [1, 2, 3]), [1, 0, 0]) is False)
    r1 = vec("r1")
    c.nonzero("counter-example: line through r1 has S0 != 0", ss.LineVector.from_axis(r1, S).S0)


@statement(
    "Special case S=0", _SEC, "The line at infinity",
    r"\mathbf S=\mathbf 0:\quad(\mathbf 0;\ \mathbf S_0)=(0\ 0\ 0;\ l\ m\ n)",
    "conditional",
    """(0; S0) with S0 = (l, m, n), l > 0: the library classifies it as a couple (a
    free vector: shifting the origin leaves it unchanged), its pitch is oo, it has no
    finite foot point (ValueError), and it is normalised by |S0| = 1, not |S| = 1.""",
    notes=("The book reuses l m n for the components of S0 here: notation only.",),
)
def _e_szero(c):
    l = symbols("l", positive=True)
    m, n = real("m n")
    S0 = Matrix([l, m, n])
    s = ss.Screw(Z3, S0)
    c.holds("classify(s) == 'couple'", ss.classify(s) == "couple")
    c.holds("pitch(s) == oo", ss.pitch(s) == oo)
    c.zero("shift_origin(s, a) - s", ss.shift_origin(s, vec("a")).matrix - s.matrix)
    try:
        ss.foot(s)
        raised = False
    except ValueError:
        raised = True
    c.holds("foot(s) raises ValueError", raised)
    unit = s / sqrt(book_dot(S0, S0))
    c.zero("|S0| = 1 after normalising by |S0|", book_dot(unit.S0, unit.S0) - 1)
