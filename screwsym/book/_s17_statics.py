"""Section 1.7, statics: (1.55)-(1.58) and the wrench decomposition."""

from __future__ import annotations

from sympy import symbols

from ._common import Z3, book_cross, book_dot, real, ss, stack, vec
from ._statement import statement

_SEC = "1.7"


@statement(
    "1.55", "1.7.1", "A force as a line vector",
    r"f\$=(\mathbf f;\ f\mathbf S_0)=(\mathbf f;\ \mathbf C_0),\qquad \mathbf f=f\mathbf S,"
    r"\ \ \mathbf S_0=\mathbf r\times\mathbf S,\ \ \mathbf C_0=f\mathbf S_0=\mathbf r\times\mathbf f",
    "identity",
    """Wrench.force(f S, point=r): the dual part is f r x S = r x f; the force has no moment
    about r (moment_about); through O the moment is 0.""",
    notes=("\"C0 = f S0 = f r x S0\" (as scanned) should read f r x S. Review: the mathematics "
           "is right; it may be a loss in the scan rather than a book error.",),
)
def _e1_55(c):
    S, r = vec("S"), vec("r")
    f = symbols("f", real=True, nonzero=True)
    W = ss.Wrench.force(f * S, point=r)
    c.zero("C_O - f r x S", W.C_O - f * book_cross(r, S))
    c.zero("C_O - r x f", W.C_O - book_cross(r, f * S))
    c.zero("moment about r", W.moment_about(r))
    c.zero("through O: C_O", ss.Wrench.force(f * S, point=Z3).C_O)


@statement(
    "1.56", "1.7.2", "Moment of a couple",
    r"\mathbf C=(\mathbf r_2-\mathbf r_1)\times\mathbf f_2=(\mathbf r_1-\mathbf r_2)\times\mathbf f_1,"
    r"\qquad \mathbf f_1=-\mathbf f_2",
    "identity",
    """Two opposite forces through r1 and r2 (Wrench.force) add to (0; C) with
    C = (r2 - r1) x f2 = (r1 - r2) x f1, normal to f1 and to r2 - r1, and with the same
    moment about every point a (moment_about).""",
)
def _e1_56(c):
    r1, r2, f1, a = vec("r1"), vec("r2"), vec("f1"), vec("a")
    f2 = -f1
    W = ss.Wrench.force(f1, point=r1) + ss.Wrench.force(f2, point=r2)
    C = W.C_O
    c.zero("resultant force", W.f)
    c.zero("C - (r2 - r1) x f2", C - book_cross(r2 - r1, f2))
    c.zero("C - (r1 - r2) x f1", C - book_cross(r1 - r2, f1))
    c.zero("C . f1", book_dot(C, f1))
    c.zero("C . (r2 - r1)", book_dot(C, r2 - r1))
    c.zero("moment about a - C", W.moment_about(a) - C)


@statement(
    "Wrench decomposition", "1.7.3", "A force plus a parallel couple is a wrench",
    r"f_1(\mathbf S_1;\ \mathbf S_1^0)=f_1(\mathbf S_1;\ \mathbf S_{01})+C(\mathbf 0;\ \mathbf S_1),"
    r"\qquad \mathbf S_1^0=\mathbf S_{01}+h\mathbf S_1,\ \ h=C/f_1",
    "identity",
    """Wrench.from_axis(r, S, 0, magnitude=f) + Wrench.couple(C S) equals Wrench.from_axis(r, S, C/f, magnitude=f); decompose_screw() of the latter returns a force on the axis and a couple parallel to
    S.""",
    errata=("Section heading \"A Twist Acting on a Body\" should read \"A Wrench Acting on a "
            "Body\"; the index i in f1(S_i; S0i) should be 1.",),
    notes=("Review, not an erratum: any system reduces to one force plus one couple; the "
           "couple must be parallel to the force only for the wrench (dyname), as the next "
           "sentence says.",),
)
def _e_wrench_dec(c):
    S, r = vec("S"), vec("r")
    f = symbols("f", real=True, nonzero=True)
    C = real("C")
    W = ss.Wrench.from_axis(r, S, C / f, magnitude=f)
    parts = ss.Wrench.from_axis(r, S, 0, magnitude=f) + ss.Wrench.couple(C * S)
    c.zero("force + couple - wrench", parts.matrix - W.matrix)
    force, couple = ss.decompose_screw(W)
    c.zero("couple part parallel to S", book_cross(couple.S0, S))
    c.zero("couple part - C S", couple.S0 - C * S)
    c.zero("force part - f (S; r x S)", force.matrix - stack(f * S, f * book_cross(r, S)))


@statement(
    "1.57", "1.7.3", "Wrench with the origin on its axis",
    r"f_1(\mathbf S_1;\ \mathbf S_1^0)=(\mathbf f_1;\ \mathbf C_0),\qquad \mathbf S_{01}=\mathbf 0,"
    r"\ \ \mathbf C_0=\mathbf C=C\,\mathbf S_1=h\,\mathbf f_1",
    "conditional",
    """Wrench.from_axis(O, S1, h, magnitude=f1): the dual part is h f1 = C S1, parallel to f1. With
    the origin off the axis (through a generic r) the dual part is not h f1: (1.57)'s
    form fails there.""",
    errata=("(1.57) and (1.58) are printed identically; (1.57) is the case with O on the "
            "axis (dual part C = h f1, parallel to f1), (1.58) the case with O off the axis.",),
)
def _e1_57(c):
    S1 = vec("S1")
    f1 = symbols("f1", real=True, nonzero=True)
    h = real("h")
    W = ss.Wrench.from_axis(Z3, S1, h, magnitude=f1)
    c.zero("C_O - h f1", W.C_O - h * W.f)
    c.zero("C_O - C S1 (C = h f1)", W.C_O - (h * f1) * S1)
    c.zero("C_O x f1", book_cross(W.C_O, W.f))
    Woff = ss.Wrench.from_axis(vec("r"), S1, h, magnitude=f1)
    c.nonzero("book's (1.57) form with O off the axis: C_O - h f1", Woff.C_O - h * Woff.f, book=True)


@statement(
    "1.58", "1.7.3", "Wrench with the origin off its axis",
    r"f_1(\mathbf S_1;\ \mathbf S_1^0)=(\mathbf f_1;\ \mathbf C_0),\qquad \mathbf C_0=f_1\mathbf S_1^0"
    r"=\mathbf r\times\mathbf f_1+C\,\mathbf S_1=\mathbf r\times\mathbf f_1+h\,\mathbf f_1",
    "identity",
    """Wrench.from_axis(r, S1, h, magnitude=f1), generic: C_O = r x f1 + h f1 = f1 (r x S1 + (C/f1)
    S1); its pitch is h (origin independent); its moment about the axis point r is the
    couple h f1 alone; in general C_O is not parallel to f1.""",
    errata=("Printed identically to (1.57); see the note there.",),
)
def _e1_58(c):
    S1, r = vec("S1"), vec("r")
    f1 = symbols("f1", real=True, nonzero=True)
    h = real("h")
    W = ss.Wrench.from_axis(r, S1, h, magnitude=f1)
    fv = f1 * S1
    c.zero("C_O - (r x f1 + h f1)", W.C_O - (book_cross(r, fv) + h * fv))
    c.zero("pitch - h", ss.pitch(W) - h)
    c.zero("moment about r - h f1", W.moment_about(r) - h * fv)
    c.nonzero("C_O not parallel to f1 in general", book_cross(W.C_O, fv))
