"""Section 1.6, instantaneous kinematics: (1.48)-(1.54) and the translation twist."""

from __future__ import annotations

from sympy import symbols

from ._common import Z3, book_cross, book_dot, real, ss, stack, vec
from ._statement import statement

_SEC = "1.6"


def _rot():
    S, r = vec("S"), vec("r")
    w = symbols("omega", real=True, nonzero=True)
    return S, r, w, ss.Twist.from_axis(r, S, magnitude=w)


@statement(
    "1.48", "1.6.1", "Twist of a pure rotation",
    r"\omega\$=\omega(\mathbf S;\ \mathbf S_0)=(\omega\mathbf S;\ \omega\mathbf S_0)",
    "definition",
    """Twist.from_axis(r, S, magnitude=omega) and Twist.rotation(omega S, point=r),
    generic, against (omega S; omega r x S).""",
)
def _e1_48(c):
    S, r, w, T = _rot()
    c.zero("from_axis - (omega S; omega r x S)", T.matrix - stack(w * S, w * book_cross(r, S)))
    c.zero("Twist.rotation(omega S, point=r) - (omega S; omega r x S)",
           ss.Twist.rotation(w * S, point=r).matrix - stack(w * S, w * book_cross(r, S)))


@statement(
    "1.49", "1.6.1", "The rotation axis",
    r"\mathbf r\times\mathbf S=\mathbf S_0",
    "conditional",
    """Twist.from_axis(r, S, magnitude=omega): every axis point r + t S satisfies (r + t S) x S =
    S0 (the dual part over omega) and has zero velocity (velocity_at); a point off the
    axis, r + S x u, moves.""",
)
def _e1_49(c):
    S, r, w, T = _rot()
    t = real("t")
    c.zero("(r + t S) x S - v_O/omega", book_cross(r + t * S, S) - T.S0 / w)
    c.zero("velocity_at(r + t S)", T.velocity_at(r + t * S))
    c.nonzero("counter-example: velocity_at(r + S x u)", T.velocity_at(r + book_cross(S, vec("u"))))


@statement(
    "1.50", "1.6.1", "The dual part is the velocity of the point at O",
    r"\omega\mathbf S_0=\omega\,\mathbf r\times\mathbf S=\mathbf r\times\boldsymbol\omega=\mathbf v_0",
    "identity",
    """Twist.from_axis(r, S, magnitude=omega): the dual part equals omega r x S, r x omega_vec, the
    velocity omega_vec x (O - r) of the body point at O, and velocity_at(O).""",
)
def _e1_50(c):
    S, r, w, T = _rot()
    wv = w * S
    c.zero("v_O - omega r x S", T.v_O - w * book_cross(r, S))
    c.zero("v_O - r x omega", T.v_O - book_cross(r, wv))
    c.zero("v_O - omega x (O - r)", T.v_O - book_cross(wv, Z3 - r))
    c.zero("v_O - velocity_at(O)", T.v_O - T.velocity_at(Z3))


@statement(
    "1.51", "1.6.1", "Twist as angular velocity and velocity of the origin point",
    r"\omega\$=(\boldsymbol\omega;\ \mathbf v_0)",
    "definition",
    """Twist.rotation: omega (the property) = omega S and v_O = r x omega S; with the axis
    through O the twist is (omega; 0); an axis off O gives v_O != 0.""",
    notes=("\"(v; 0) or (v; 0)\" reads omega(S; 0) or (omega; 0). Review: more likely an "
           "duplication in the scanned text than a book error.",),
)
def _e1_51(c):
    S, r, w, T = _rot()
    c.zero("omega - omega S", T.omega - w * S)
    c.zero("v_O - r x omega", T.v_O - book_cross(r, w * S))
    c.zero("axis through O: v_O", ss.Twist.from_axis(Z3, S, magnitude=w).v_O)
    c.nonzero("axis through r != O: v_O", T.v_O)


@statement(
    "Translation twist", "1.6.2", "Instantaneous translation",
    r"\mathbf v=v\,\mathbf S,\qquad \text{twist}=v(\mathbf 0;\ \mathbf S)=(\mathbf 0;\ \mathbf v)",
    "identity",
    """Twist.translation(v S): it is (0; v S), it does not change when the origin moves
    (shift_origin), and every point has the velocity v S (velocity_at).""",
    notes=("\"(as illustrated in Fig. 1.7)\": Fig. 1.7 shows rotation. Review: the figure "
           "reference cannot be checked from the scanned text. v is the translational speed.",),
)
def _e_translation(c):
    S, a, p = vec("S"), vec("a"), vec("p")
    v = real("v")
    T = ss.Twist.translation(v * S)
    c.zero("translation - (0; v S)", T.matrix - stack(Z3, v * S))
    c.zero("shift_origin(T, a) - T", ss.shift_origin(T, a).matrix - T.matrix)
    c.zero("velocity_at(p) - v S", T.velocity_at(p) - v * S)


def _screw_motion():
    S, r = vec("S"), vec("r")
    w = symbols("omega", real=True, nonzero=True)
    h = real("h")
    return S, r, w, h, ss.Twist.from_axis(r, S, h, magnitude=w)


@statement(
    "1.52", "1.6.3", "Screw motion = rotation + translation along the axis",
    r"\omega_1\$_1=(\omega_1\mathbf S_1;\ \omega_1\mathbf S_{01})+(\mathbf 0;\ v_1\mathbf S_1)"
    r"=(\omega_1\mathbf S_1;\ \omega_1\mathbf S_{01}+h\,\omega_1\mathbf S_1)=\omega_1(\mathbf S_1;\ \mathbf S_1^0)",
    "identity",
    """Twist.from_axis(r, S, magnitude=omega) + Twist.translation(h omega S) equals
    Twist.from_axis(r, S, h, magnitude=omega), Twist.screw_motion(omega S, point=r,
    pitch=h) and omega (S; r x S + h S).""",
    errata=("\"instantaneous wrench omega1(S1; S01)\" should read twist (rotation); "
            "\"v2(0; S1)\" should read v1(0; S1); the left side's index i should be 1.",),
    notes=("Review: \"(S1; S01) is unit screw\" is consistent with the book's own \"a line "
           "vector is a special screw with zero pitch\", so that part is not an erratum.",),
)
def _e1_52(c):
    S, r, w, h, T = _screw_motion()
    parts = ss.Twist.from_axis(r, S, magnitude=w) + ss.Twist.translation(h * w * S)
    c.zero("rotation + translation - screw_motion", parts.matrix - T.matrix)
    c.zero("from_axis - omega (S; r x S + h S)", T.matrix - stack(w * S, w * (book_cross(r, S) + h * S)))
    c.zero("Twist.screw_motion(omega S, point=r, pitch=h) - omega (S; r x S + h S)",
           ss.Twist.screw_motion(w * S, point=r, pitch=h).matrix
           - stack(w * S, w * (book_cross(r, S) + h * S)))


@statement(
    "1.53", "1.6.3", "General twist",
    r"\omega_1\$_1=(\boldsymbol\omega_1;\ \mathbf v_0),\qquad \boldsymbol\omega_1=\omega_1\mathbf S_1,"
    r"\ \ \mathbf v_0=\omega_1\mathbf S_1^0=\mathbf r\times\boldsymbol\omega_1+h\,\boldsymbol\omega_1",
    "identity",
    """Twist.from_axis(r, S, h, magnitude=omega): v_O = h omega S + omega S x (O - r) (the
    velocity of the body point at O); the velocity at the axis point r is h omega S,
    along S; v_O x omega = (r x omega) x omega, so v_O is parallel to omega when the axis
    passes through O and not otherwise.""",
    notes=("Scanned text: the book's (v1; v0) is (omega1; v0).",),
)
def _e1_53(c):
    S, r, w, h, T = _screw_motion()
    wv = w * S
    c.zero("v_O - (h omega + omega x (O - r))", T.S0 - (h * wv + book_cross(wv, -r)))
    c.zero("v_O - (r x omega + h omega)", T.v_O - (book_cross(r, wv) + h * wv))
    c.zero("velocity_at(r) - h omega", T.velocity_at(r) - h * wv)
    c.zero("velocity_at(r) x S", book_cross(T.velocity_at(r), S))
    c.zero("v_O x omega - (r x omega) x omega", book_cross(T.v_O, wv) - book_cross(book_cross(r, wv), wv))
    c.zero("axis through O: v_O x omega", book_cross(ss.Twist.from_axis(Z3, S, h, magnitude=w).v_O, wv))
    c.nonzero("counter-example: axis off O, v_O x omega", book_cross(T.v_O, wv))


@statement(
    "1.54", "1.6.3", "Pitch of a twist",
    r"h=\frac{\mathbf S_1\cdot\mathbf S_1^0}{\mathbf S_1\cdot\mathbf S_1}"
    r"=\frac{\boldsymbol\omega_1\cdot\mathbf v_0}{\boldsymbol\omega_1\cdot\boldsymbol\omega_1}",
    "identity",
    """pitch(Twist.from_axis(r, S, h, magnitude=omega)) is h and equals
    omega . v_O/(omega . omega).""",
)
def _e1_54(c):
    S, r, w, h, T = _screw_motion()
    c.zero("pitch - h", ss.pitch(T) - h)
    c.zero("omega . v_O/(omega . omega) - h", book_dot(T.omega, T.v_O) / book_dot(T.omega, T.omega) - h)
