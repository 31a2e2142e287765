"""Section 1.4.1, the line vector: (1.28)-(1.30) and the special forms of Fig. 1.5."""

from __future__ import annotations

from sympy import Matrix

from ._common import Z3, book_cross, book_dot, real, ss, vec
from ._statement import statement

_SEC = "1.4.1"


@statement(
    "1.28", _SEC, "Line equation of a line vector (repeats 1.8)",
    r"\mathbf r\times\mathbf S=\mathbf S_0",
    "conditional",
    """The library's line vector through generic r along S: every point r + t S satisfies
    the equation and contains() is True; r + S x w (off the line) does not satisfy it.
    contains() answers False for a point off a numeric line. (S; S0) and (-S; -S0) are the same
    undirected line but different line vectors.""",
    errata=("\"Unit line vectors stand in one-to-one correspondence with the lines\": "
            "one-to-one with directed lines, 2-to-1 (+-) with undirected lines.",),
)
def _e1_28(c):
    r, S, w = vec("r"), vec("S"), vec("w")
    t = real("t")
    L = ss.LineVector.from_axis(r, S)
    c.zero("(r + t S) x S - S0", book_cross(r + t * S, S) - L.S0)
    c.holds("contains(L, r + t S) is True", ss.contains(L, r + t * S) is True)
    c.holds("contains((1 0 0; 0 0 1), (0, 0, 0)) is False (the line is y = 1, z = 0)",
            ss.contains(ss.LineVector([1, 0, 0], [0, 0, 1]), [0, 0, 0]) is False)
    c.zero("S . S0", book_dot(L.S, L.S0))
    c.nonzero("counter-example: (r + S x w) x S - S0", book_cross(r + book_cross(S, w), S) - L.S0)
    c.zero("-L has the same points: (r + t S) x (-S) - (-S0)", book_cross(r + t * S, (-L).S) - (-L).S0)
    c.nonzero("but -L != L as line vectors", (-L).matrix - L.matrix)


def _pab():
    p, a, b, S = vec("p"), vec("a"), vec("b"), vec("S")
    return p, a, b, S, ss.LineVector.from_axis(p, S)


@statement(
    "1.29", _SEC, "Moment of S about a new origin A",
    r"\mathbf S_A=\mathbf r_A\times\mathbf S=(\overrightarrow{AB}+\mathbf r_B)\times\mathbf S",
    "identity",
    """Line through a generic point p along S (library); S_A = shift_origin(line, a).S0;
    it equals r_A x S = (p - a) x S and (AB + r_B) x S with AB = b - a, r_B = p - b.""",
)
def _e1_29(c):
    p, a, b, S, L = _pab()
    SA = ss.shift_origin(L, a).S0
    c.zero("S_A - (p - a) x S", SA - book_cross(p - a, S))
    c.zero("S_A - ((b - a) + (p - b)) x S", SA - book_cross((b - a) + (p - b), S))


@statement(
    "1.30", _SEC, "Transfer law for the moment of a line",
    r"\mathbf S_A=\mathbf S_B+\overrightarrow{AB}\times\mathbf S",
    "identity",
    """S_A, S_B = shift_origin(line, a).S0, shift_origin(line, b).S0 of the library's line
    through p along S: S_A = S_B + (b - a) x S; the point chosen on the line does not
    matter; S itself is unchanged. The Fig. 1.4 caption (\"not origin-dependent\") fails:
    S_A differs from S0.""",
    errata=("Fig. 1.4 caption \"Line moment is not origin-dependent\": the moment is "
            "origin-dependent ((1.30)); S is not.",),
)
def _e1_30(c):
    p, a, b, S, L = _pab()
    t = real("t")
    SA, SB = ss.shift_origin(L, a).S0, ss.shift_origin(L, b).S0
    c.zero("S_A - (S_B + AB x S)", SA - (SB + book_cross(b - a, S)))
    c.zero("another point of the line: p + t S", ss.shift_origin(ss.LineVector.from_axis(p + t * S, S), a).S0 - SA)
    c.zero("S unchanged", ss.shift_origin(L, a).S - S)
    c.nonzero("Fig. 1.4 caption fails: S_A - S0", SA - L.S0, book=True)


@statement(
    "Fig. 1.5", _SEC, "Special forms of a line vector",
    r"\begin{array}{lll}(a\,b\,c;\ d\,e\,f)&(a\,b\,c;\ d\,e\,0)&(a\,b\,c;\ 0\,0\,0)\\"
    r"(a\,b\,0;\ d\,e\,f)&(a\,b\,0;\ d\,e\,0)&(a\,b\,0;\ 0\,0\,c)\\"
    r"(1\,0\,0;\ 0\,a\,b)&(1\,0\,0;\ 0\,1\,0)&(1\,0\,0;\ 0\,0\,0)\end{array}",
    "identity",
    """Each of the nine forms is built with LineVector.from_axis from the point and
    direction of its geometric meaning; the zero pattern, S . S0 = 0, and the mutual
    moment with the Z axis = S0_z are checked. General line; line meeting (or parallel
    to) the Z axis; line through O; line parallel to XY; line parallel to XY meeting Z
    perpendicularly; line in the XY plane; lines parallel to X; the X axis.""",
    notes=("The patterns are exactly as printed; their grouping into the three categories and "
           "the geometric readings are ours.",),
)
def _fig_1_5(c):
    a, b, cc, X0, Y0, Z0 = real("a b c X0 Y0 Z0")
    p, S = vec("p"), vec("S")
    Z_axis = ss.LineVector([0, 0, 1], [0, 0, 0])
    rows = {
        "(a b c; d e f) general line": (p, S, None),
        "(a b c; d e 0) meets the Z axis": (Matrix([0, 0, Z0]), S, [5]),
        "(a b c; d e 0) parallel to Z": (p, Matrix([0, 0, cc]), [5]),
        "(a b c; 0 0 0) through O": (Z3, S, [3, 4, 5]),
        "(a b 0; d e f) parallel to XY": (Matrix([X0, Y0, Z0]), Matrix([a, b, 0]), [2]),
        "(a b 0; d e 0) parallel to XY, meets Z": (Matrix([0, 0, Z0]), Matrix([a, b, 0]), [2, 5]),
        "(a b 0; 0 0 c) in the XY plane": (Matrix([X0, Y0, 0]), Matrix([a, b, 0]), [2, 3, 4]),
        "(1 0 0; 0 a b) parallel to X": (Matrix([0, -b, a]), Matrix([1, 0, 0]), [1, 2, 3]),
        "(1 0 0; 0 1 0) parallel to X through (0,0,1)": (Matrix([0, 0, 1]), Matrix([1, 0, 0]), None),
        "(1 0 0; 0 0 0) the X axis": (Z3, Matrix([1, 0, 0]), [1, 2, 3, 4, 5]),
    }
    for label, (point, direction, zeros_at) in rows.items():
        L = ss.LineVector.from_axis(point, direction)
        m = L.matrix
        for k in zeros_at or ():
            c.zero(f"{label}: component {k + 1} is 0", m[k])
        c.zero(f"{label}: S . S0", book_dot(L.S, L.S0))
        c.zero(f"{label}: mutual moment with Z - S0_z", ss.mutual_moment(Z_axis, L) - L.S0[2])
    c.zero("(a b 0; d e f): S0 = (-b Z0, a Z0, b X0 - a Y0)",
           ss.LineVector.from_axis([X0, Y0, Z0], [a, b, 0]).S0 - Matrix([-b * Z0, a * Z0, b * X0 - a * Y0]))
    c.zero("(a b 0; d e 0): S0 = Z0 (-b, a, 0)",
           ss.LineVector.from_axis([0, 0, Z0], [a, b, 0]).S0 - Z0 * Matrix([-b, a, 0]))
    c.zero("(1 0 0; 0 a b) exactly", ss.LineVector.from_axis([0, -b, a], [1, 0, 0]).matrix
           - Matrix([1, 0, 0, 0, a, b]))
    c.zero("(1 0 0; 0 1 0) exactly", ss.LineVector.from_axis([0, 0, 1], [1, 0, 0]).matrix
           - Matrix([1, 0, 0, 0, 1, 0]))
    c.nonzero("a general line has S0_z != 0", ss.LineVector.from_axis(p, S).S0[2])
