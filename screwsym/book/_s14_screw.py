"""Section 1.4.2, the screw: (1.31)-(1.38), classification, Examples 1.1-1.4."""

from __future__ import annotations

from sympy import Matrix, Rational, oo, sqrt, symbols

from ._common import Z3, book_cross, book_dot, real, ss, stack, vec
from ._statement import statement

_SEC = "1.4.2"


def _screw():
    S, S0, a = vec("S"), vec("D"), vec("a")
    return S, S0, a, ss.Screw(S, S0)


def _book_pitch(S, S0):
    return book_dot(S, S0) / book_dot(S, S)


@statement(
    "1.31", _SEC, "Definition of a screw",
    r"\$=(\mathbf S;\ \mathbf S^0),\qquad \mathbf S\cdot\mathbf S^0\neq0",
    "definition",
    """Screw(S, S0) keeps S and S0 as its parts; (1 1 0; 1 0 0) with S . S0 = 1 is
    classified 'screw'; a LineVector with S . S0 != 0 is refused (ValueError); (1 0 0; 0 1 0) is a line and (0 0 0;
    1 0 0) a couple, not screws.""",
    errata=("(1.31) defines a screw with S . S0 != 0, yet the book then calls line vectors "
            "(h = 0) and couples (S = 0) screws. The library calls every nonzero (S; S0) a "
            "screw and classifies it by S and h.",),
)
def _e1_31(c):
    S, S0, a, s = _screw()
    c.zero("Screw(S, S0).S - S", s.S - S)
    c.zero("Screw(S, S0).S0 - S0", s.S0 - S0)
    c.holds("classify((1 1 0; 1 0 0)) == 'screw'", ss.classify(ss.Screw([1, 1, 0], [1, 0, 0])) == "screw")
    try:
        ss.LineVector([1, 1, 0], [1, 0, 0])
        refused = False
    except ValueError:
        refused = True
    c.holds("LineVector with S . S0 = 1 raises ValueError", refused)
    c.holds("(1 0 0; 0 1 0), S . S0 = 0, is a line, not a screw",
            ss.classify(ss.Screw([1, 0, 0], [0, 1, 0])) == "line")
    c.holds("(0 0 0; 1 0 0), S = 0, is a couple, not a screw",
            ss.classify(ss.Screw([0, 0, 0], [1, 0, 0])) == "couple")


@statement(
    "1.32", _SEC, "Origin shift of the dual part",
    r"\mathbf S^A=\mathbf S^0+\overrightarrow{AO}\times\mathbf S",
    "definition",
    """shift_origin(screw, a) of a generic screw against S0 + AO x S with AO = -a. The
    direction is pinned: shift_origin(Screw.from_axis(p, S, h), a) is
    Screw.from_axis(p - a, S, h); a force through a has no moment about a. The wrong
    direction S0 + a x S fails.""",
)
def _e1_32(c):
    S, S0, a, s = _screw()
    p, f = vec("p"), vec("f")
    h = real("h")
    c.zero("shift_origin(s, a).S0 - (S0 + (-a) x S)", ss.shift_origin(s, a).S0 - (S0 + book_cross(-a, S)))
    c.zero("shift_origin(from_axis(p, S, h), a) - from_axis(p - a, S, h)",
           ss.shift_origin(ss.Screw.from_axis(p, S, h), a).matrix
           - ss.Screw.from_axis(p - a, S, h).matrix)
    c.zero("moment of a force through a about a", ss.shift_origin(ss.Wrench.force(f, point=a), a).S0)
    c.nonzero("counter-example: the wrong direction S0 + a x S",
              ss.shift_origin(s, a).S0 - (S0 + book_cross(a, S)))


@statement(
    "1.33", _SEC, "S . S0 does not depend on the origin",
    r"\mathbf S\cdot\mathbf S^A=\mathbf S\cdot\mathbf S^0",
    "identity",
    """S . shift_origin(s, a).S0 - S . S0 for a generic screw s and point a. S^A is
    pinned by an independent construction: the screw (S; p x S + h S) on the axis
    through p, built by hand, has S^A = (p - a) x S + h S about a. A change of the
    dual part that is not perpendicular to S (S0 + a) changes S . S0.""",
)
def _e1_33(c):
    S, S0, a, s = _screw()
    c.zero("S . S^A - S . S0", book_dot(S, ss.shift_origin(s, a).S0) - book_dot(S, S0))
    p, h = vec("p"), real("h")
    on_axis = ss.Screw(S, book_cross(p, S) + h * S)
    c.zero("axis through p: S^A - ((p - a) x S + h S)",
           ss.shift_origin(on_axis, a).S0 - (book_cross(p - a, S) + h * S))
    c.nonzero("counter-example: S . (S0 + a) - S . S0 (a shift along S)", book_dot(S, S0 + a) - book_dot(S, S0))


@statement(
    "1.34", _SEC, "Pitch of a screw",
    r"h=\frac{\mathbf S\cdot\mathbf S^0}{\mathbf S\cdot\mathbf S}=\frac{lp+mq+nr}{l^2+m^2+n^2}",
    "definition",
    """pitch of the screw (l m n; p q r), generic components, against the printed ratio;
    the pitch is origin-independent (pitch of shift_origin(s, a)); a line vector has pitch
    0; a couple (0; S) has pitch oo; Screw.from_axis(r, S, h) has pitch h.""",
    errata=("The components l, m, n here are general, not direction cosines; the scalar r "
            "collides with the position vector r.",),
)
def _e1_34(c):
    l, m, n, p, q, r = real("l m n p q r")
    s = ss.Screw([l, m, n], [p, q, r])
    c.zero("pitch - (lp + mq + nr)/(l^2 + m^2 + n^2)",
           ss.pitch(s) - (l * p + m * q + n * r) / (l**2 + m**2 + n**2))
    a = vec("a")
    c.zero("pitch(shift_origin(s, a)) - pitch(s)", ss.pitch(ss.shift_origin(s, a)) - ss.pitch(s))
    c.zero("pitch of a line vector", ss.pitch(ss.LineVector.from_axis(vec("r"), vec("S"))))
    c.holds("pitch of the couple (0; 0 0 1) is oo", ss.pitch(ss.Screw.couple([0, 0, 1])) == oo)
    h = real("h")
    c.zero("pitch(from_axis(r, S, h)) - h", ss.pitch(ss.Screw.from_axis(vec("r"), vec("S"), h)) - h)


@statement(
    "1.35", _SEC, "Dual part split along and across S",
    r"(\mathbf S;\ \mathbf S^0)=(\mathbf S;\ \mathbf S^0-h\mathbf S+h\mathbf S),\qquad "
    r"\mathbf S^0-h\mathbf S\perp\mathbf S,\quad \mathbf S^0-h\mathbf S=\mathbf S_0",
    "identity",
    """Generic screw: axis(s).S0 = S0 - h S with h the book's ratio, axis(s).S = S, S . (S0 - h S) = 0, decompose_screw(s)'s line part is (S; S0 - h S), and its parts
    add back to s.""",
    errata=("S^0 and S_0 are both printed \"S0\": \"S0 - hS = S0\" reads "
            "S^0 - h S = S_0 = r x S, the moment of the axis.",),
)
def _e1_35(c):
    S, S0, a, s = _screw()
    h = _book_pitch(S, S0)
    ax = ss.axis(s)
    c.zero("axis(s).S0 - (S0 - h S)", ax.S0 - (S0 - h * S))
    c.zero("axis(s).S - S", ax.S - S)
    c.zero("S . (S0 - h S)", book_dot(S, ax.S0))
    line, couple = ss.decompose_screw(s)
    c.zero("decompose: line part - (S; S0 - h S)", line.matrix - stack(S, S0 - h * S))
    c.zero("line + couple - s", (line + couple).matrix - stack(S, S0))


@statement(
    "1.36", _SEC, "Equation of the screw axis",
    r"\mathbf r\times\mathbf S=\mathbf S^0-h\mathbf S",
    "conditional",
    """Generic screw, P = foot(s) (library): every point P + t S satisfies the equation
    and contains() is True; P = S x (S0 - h S)/(S . S); the point P + S x w off the axis does not satisfy it, and contains((1 1 0; 1 0 0), O)
    is False.""",
)
def _e1_36(c):
    S, S0, a, s = _screw()
    t = real("t")
    h = _book_pitch(S, S0)
    P = ss.foot(s)
    c.zero("(P + t S) x S - (S0 - h S)", book_cross(P + t * S, S) - (S0 - h * S))
    c.holds("contains(s, P + t S) is True", ss.contains(s, P + t * S) is True)
    c.holds("contains((1 1 0; 1 0 0), O) is False (its axis is x = y, z = -1/2)",
            ss.contains(ss.Screw([1, 1, 0], [1, 0, 0]), [0, 0, 0]) is False)
    c.zero("P - S x (S0 - h S)/(S . S)", P - book_cross(S, S0 - h * S) / book_dot(S, S))
    w = vec("w")
    c.nonzero("counter-example: r = P + S x w", book_cross(P + book_cross(S, w), S) - (S0 - h * S))


@statement(
    "1.37", _SEC, "Screw = axis line vector + parallel couple",
    r"\$=(\mathbf S;\ \mathbf S^0)=(\mathbf S;\ \mathbf S^0-h\mathbf S)+(\mathbf 0;\ h\mathbf S)",
    "identity",
    """decompose_screw(s) of a generic screw: the line part is (S; S0 - h S) with pitch 0, the
    couple part is (0; h S), and their sum is s.""",
    errata=("\"From Eq. (1.25), a screw can be expressed as\" should read Eq. (1.35).",),
)
def _e1_37(c):
    S, S0, a, s = _screw()
    h = _book_pitch(S, S0)
    line, couple = ss.decompose_screw(s)
    c.zero("line - (S; S0 - h S)", line.matrix - stack(S, S0 - h * S))
    c.zero("couple - (0; h S)", couple.matrix - stack(Z3, h * S))
    c.zero("pitch(line)", ss.pitch(line))
    c.zero("line + couple - s", (line + couple).matrix - stack(S, S0))


@statement(
    "1.38", _SEC, "Screw from axis point, direction and pitch",
    r"\$=(\mathbf S;\ \mathbf S^0)=(\mathbf S;\ \mathbf r\times\mathbf S+h\mathbf S)"
    r"=(\mathbf S;\ \mathbf S_0+h\mathbf S)=(\mathbf S;\ \mathbf S_0)+(\mathbf 0;\ h\mathbf S)",
    "definition",
    """Screw.from_axis(r, S, h) with generic r, S, h against (S; r x S + h S); its pitch is h, its axis is (S; r x S), r lies on its axis (and (1, 2, 4) does not lie on a
    numeric one), and it is the line vector
    (S; r x S) plus the couple (0; h S).""",
    errata=("Mixed notation: the first \"S0\" is S^0, the others S_0.",),
    notes=("A couple not parallel to S also gives a screw, with a displaced axis (see the "
           "entry 'Line vector plus couple'). Four factors determine a screw: 4 + 1 + 1 = 6 "
           "parameters.",),
)
def _e1_38(c):
    r, S = vec("r"), vec("S")
    h = real("h")
    s = ss.Screw.from_axis(r, S, h)
    c.zero("from_axis(r, S, h) - (S; r x S + h S)", s.matrix - stack(S, book_cross(r, S) + h * S))
    c.zero("pitch - h", ss.pitch(s) - h)
    c.zero("axis(s).S0 - r x S", ss.axis(s).S0 - book_cross(r, S))
    c.zero("axis(s).S - S", ss.axis(s).S - S)
    c.holds("contains(s, r) is True", ss.contains(s, r) is True)
    c.holds("contains(from_axis((1, 2, 3), (0, 1, 1), 2), (1, 2, 4)) is False",
            ss.contains(ss.Screw.from_axis([1, 2, 3], [0, 1, 1], 2), [1, 2, 4]) is False)
    parts = ss.LineVector.from_axis(r, S) + ss.Screw.couple(h * S)
    c.zero("(S; S0) + (0; h S) - s", parts.matrix - s.matrix)


@statement(
    "Classification", _SEC, "Screw, line vector, couple",
    r"\begin{array}{lll}\text{Screw:}&(\mathbf S;\ \mathbf S^0):&\mathbf S\neq\mathbf 0,\ "
    r"\mathbf S\cdot\mathbf S^0\neq0,\ \infty\neq h\neq0\\ \text{Line vector:}&"
    r"(\mathbf S;\ \mathbf S_0):&\mathbf S\neq\mathbf 0,\ \mathbf S\cdot\mathbf S_0=0,\ h=0\\"
    r"\text{Couple:}&(\mathbf 0;\ \mathbf S):&\mathbf S\neq\mathbf 0,\ h=\infty\end{array}",
    "definition",
    """classify() on a screw, a line, a couple and the zero screw, with numbers and with
    symbols (l > 0 and h > 0 in (l m n; h l h m h n)); with S != 0,
    h (S . S) = S . S0, so S . S0 != 0 exactly when h != 0. Undecided cases answer None: the generic (S; S0), and (l
    m n; 0 0 p) with generic p.""",
    errata=("S . S0 != 0 and h != 0 are listed as separate conditions, but given S != 0 "
            "they are the same; 'h = oo' for S = 0 needs a special case (0/0).",),
)
def _e_classify(c):
    c.holds("(1 1 0; 1 0 0) is a screw", ss.classify(ss.Screw([1, 1, 0], [1, 0, 0])) == "screw")
    c.holds("(1 0 0; 0 1 0) is a line", ss.classify(ss.Screw([1, 0, 0], [0, 1, 0])) == "line")
    c.holds("(0 0 0; 0 0 1) is a couple", ss.classify(ss.Screw([0, 0, 0], [0, 0, 1])) == "couple")
    c.holds("(0 0 0; 0 0 0) is the zero screw", ss.classify(ss.Screw([0, 0, 0], [0, 0, 0])) == "zero")
    l = symbols("l", positive=True)
    m, n = real("m n")
    h = symbols("h", positive=True)  # classify() decides S.S0 = h(l^2+m^2+n^2) != 0 only for h > 0
    c.holds("symbolic (l m n; hl hm hn), h > 0, is a screw",
            ss.classify(ss.Screw([l, m, n], [h * l, h * m, h * n])) == "screw")
    c.holds("symbolic (l m n; 0 0 0) is a line", ss.classify(ss.Screw([l, m, n], [0, 0, 0])) == "line")
    S, S0, a, s = _screw()
    c.zero("h (S . S) - S . S0", ss.pitch(s) * book_dot(S, S) - book_dot(S, S0))
    c.holds("generic (S; S0): undecided (None), S might be 0 and S . S0 might vanish",
            ss.classify(s) is None)
    c.holds("(l m n; 0 0 p), l > 0, generic p: undecided (line when n p = 0)",
            ss.classify(ss.Screw([l, m, n], [0, 0, real("p")])) is None)


@statement(
    "Example 1.1", _SEC, "A screw whose axis passes through the origin",
    r"(l\ m\ n;\ hl\ hm\ hn)\ \text{has pitch } h \text{ and its axis passes through } O",
    "identity",
    """s = Screw(S, h S) with generic S, h: pitch(s) = h, the axis is (S; 0), the foot point is O and contains(s, O) is True; (1 0 0) is not on the
    axis of (1 2 3; 2 4 6).""",
)
def _ex1_1(c):
    S = vec("S")
    h = real("h")
    s = ss.Screw(S, h * S)
    c.zero("pitch - h", ss.pitch(s) - h)
    c.zero("axis moment S0 - h S", ss.axis(s).S0)
    c.zero("axis direction - S", ss.axis(s).S - S)
    c.zero("foot point", ss.foot(s))
    c.holds("contains(s, O) is True", ss.contains(s, Z3) is True)
    c.holds("contains((1 2 3; 2 4 6), (1, 0, 0)) is False (the axis is along (1, 2, 3))",
            ss.contains(ss.Screw([1, 2, 3], [2, 4, 6]), [1, 0, 0]) is False)


@statement(
    "Example 1.2", _SEC, "The screw (1 0 0; 1 0 0)",
    r"h=\frac{\mathbf S\cdot\mathbf S^0}{\mathbf S\cdot\mathbf S}=1,\qquad "
    r"\mathbf r\times\mathbf S=\mathbf S^0-h\mathbf S=\mathbf 0",
    "numeric",
    """pitch((1 0 0; 1 0 0)) = 1 exactly, its axis moment is 0, it is classified 'screw',
    and its axis is the X axis (contains (5, 0, 0), not (0, 1, 0)).""",
    notes=("Here h = 1 really is the number 1 (not oo, which the scanned text also shows as 1).",),
)
def _ex1_2(c):
    s = ss.Screw([1, 0, 0], [1, 0, 0])
    c.zero("pitch - 1", ss.pitch(s) - 1)
    c.zero("axis moment", ss.axis(s).S0)
    c.zero("axis direction - (1, 0, 0)", ss.axis(s).S - Matrix([1, 0, 0]))
    c.holds("classify == 'screw'", ss.classify(s) == "screw")
    c.holds("axis is the X axis: contains (5, 0, 0)", ss.contains(s, [5, 0, 0]) is True)
    c.holds("(0, 1, 0) is off the axis: contains is False", ss.contains(s, [0, 1, 0]) is False)


@statement(
    "Example 1.3", _SEC, "The unit screw (1 1 1; 1 1 1)/sqrt(3)",
    r"\tfrac{1}{\sqrt3}(1\ 1\ 1;\ 1\ 1\ 1):\ |\mathbf S|=1,\ h=1,\ \text{axis through } O"
    r"\text{ along } (1\ 1\ 1)",
    "numeric",
    """s = Screw((1,1,1)/sqrt3, (1,1,1)/sqrt3): |S|^2 = 1, it is unit((1 1 1; 1 1 1)),
    pitch 1, axis moment 0, and the axis contains (1, 1, 1) but not (1, 1, 0). A couple
    is normalised by |S0| instead.""",
)
def _ex1_3(c):
    u = Matrix([1, 1, 1]) / sqrt(3)
    s = ss.Screw(u, u)
    c.zero("S . S - 1", book_dot(s.S, s.S) - 1)
    c.zero("unit((1 1 1; 1 1 1)) - s", ss.unit(ss.Screw([1, 1, 1], [1, 1, 1])).matrix - s.matrix)
    c.zero("unit of the couple (0; 0 0 -2) is (0; 0 0 -1)",
           ss.unit(ss.Screw.couple([0, 0, -2])).matrix - Matrix([0, 0, 0, 0, 0, -1]))
    c.zero("pitch - 1", ss.pitch(s) - 1)
    c.zero("axis moment", ss.axis(s).S0)
    c.zero("axis direction - S", ss.axis(s).S - u)
    c.holds("axis contains (1, 1, 1)", ss.contains(s, [1, 1, 1]) is True)
    c.holds("(1, 1, 0) is off the axis: contains is False", ss.contains(s, [1, 1, 0]) is False)


@statement(
    "Example 1.4", _SEC, "Identify (1 1 0; 1 0 0) and find its axis",
    r"h=\frac{\mathbf S\cdot\mathbf S^0}{\mathbf S\cdot\mathbf S}=\frac12,\qquad "
    r"\mathbf r\times\mathbf S=\mathbf S^0-h\mathbf S=\left(\tfrac12\ \ -\tfrac12\ \ 0\right)^T",
    "numeric",
    """s = Screw((1,1,0), (1,0,0)): pitch 1/2, axis (1 1 0; 1/2 -1/2 0), foot point
    (0, 0, -1/2), every (t, t, -1/2) on the axis, distance 1/2, a proper screw; the unit
    screw s/sqrt2 has the same pitch.""",
    notes=("Completion of the book's solution (the book stops at r x S): foot point "
           "(0, 0, -1/2), the axis x = y, z = -1/2, at distance 1/2 from O.",),
)
def _ex1_4(c):
    s = ss.Screw([1, 1, 0], [1, 0, 0])
    t = real("t")
    half = Rational(1, 2)
    c.zero("pitch - 1/2", ss.pitch(s) - half)
    c.zero("axis moment - (1/2, -1/2, 0)", ss.axis(s).S0 - Matrix([half, -half, 0]))
    c.zero("axis direction - (1, 1, 0)", ss.axis(s).S - Matrix([1, 1, 0]))
    c.zero("foot - (0, 0, -1/2)", ss.foot(s) - Matrix([0, 0, -half]))
    c.zero("(t, t, -1/2) x S - (1/2, -1/2, 0)", book_cross(Matrix([t, t, -half]), s.S) - Matrix([half, -half, 0]))
    c.zero("distance - 1/2", ss.distance_to_origin(s) - half)
    c.holds("classify == 'screw'", ss.classify(s) == "screw")
    c.zero("unit screw pitch - 1/2", ss.pitch(s / sqrt(2)) - half)
