"""Plain SymPy (no screwsym) check of the statements of Chapter 1, in the style of
Section 0.3 of the transcription: every check goes through ``simplify``.

Run: ``python benchmarks/plain_sympy_check.py``; prints the number of checks and the time.
"""

import time

from sympy import (
    Matrix,
    MatrixBase,
    Rational,
    cos,
    eye,
    factor,
    simplify,
    sin,
    sqrt,
    symbols,
    together,
    zeros,
)


def V(name):
    return Matrix(symbols(f"{name}_x {name}_y {name}_z", real=True))


def pitch(S, S0):
    return S.dot(S0) / S.dot(S)


def recip(S1, S01, S2, S02):
    return S1.dot(S02) + S2.dot(S01)


def is_zero(e):
    if isinstance(e, MatrixBase):
        return all(is_zero(x) for x in e)
    return simplify(e) == 0 or factor(together(e.expand())) == 0


def nonzero(e):
    return not is_zero(e)


def checks():
    t, lam, h, w, f, C, mu = symbols("t lambda h omega f C mu", real=True)
    L, M, N, x, y, z = symbols("L M N x y z", real=True)
    r1, r2, r, S, S0, a, b, p, q, wv = (V(n) for n in "r1 r2 r S D a b p q w".split())
    A, B, c = V("A"), V("B"), V("c")
    S1, S2, D1, D2 = V("S1"), V("S2"), V("D1"), V("D2")
    i, j, k = eye(3).col(0), eye(3).col(1), eye(3).col(2)
    out = []
    add = out.append
    # 1.2
    add(is_zero((r2 - r1) - ((r2[0] - r1[0]) * i + (r2[1] - r1[1]) * j + (r2[2] - r1[2]) * k)))
    Sl = Matrix([L, M, N])
    add(is_zero(Sl.norm() - sqrt(L**2 + M**2 + N**2)))
    l_, m_, n_ = Sl / Sl.norm()
    add(is_zero(l_**2 + m_**2 + n_**2 - 1))
    Sr = r2 - r1
    add(is_zero((r1 + t * Sr - r1).cross(Sr)))
    add(nonzero((r1 + Sr.cross(wv) - r1).cross(Sr)))
    S0l = r1.cross(Sr)
    add(is_zero((r - r1).cross(Sr) - (r.cross(Sr) - S0l)))
    add(is_zero((r1 + t * Sr).cross(Sr) - S0l))
    add(is_zero(Sr.dot(S0l)))
    add(is_zero(r.cross(lam * Sr) - lam * S0l - lam * (r.cross(Sr) - S0l)))
    I, J, K = symbols("I J K")
    x1, y1, z1 = r1
    det = Matrix([[I, J, K], [x1, y1, z1], [L, M, N]]).det()
    P, Q, R = y1 * N - z1 * M, z1 * L - x1 * N, x1 * M - y1 * L
    add(is_zero(det - (P * I + Q * J + R * K)))
    add(is_zero(r1.cross(Sl) - Matrix([P, Q, R])))
    E = Matrix([y * N - z * M - P, z * L - x * N - Q, x * M - y * L - R])
    add(is_zero(E - (Matrix([x, y, z]).cross(Sl) - Matrix([P, Q, R]))))
    add(is_zero(E.subs({x: x1 + t * L, y: y1 + t * M, z: z1 + t * N})))
    add(is_zero(L * E[0] + M * E[1] + N * E[2]))
    add(is_zero(L * P + M * Q + N * R))
    S0 = r1.cross(S)
    Pf = S.cross(S0) / S.dot(S)
    add(is_zero(S.cross(Pf.cross(S)) - (S.dot(S) * Pf - S.dot(Pf) * S)))
    add(is_zero(Pf.cross(S) - S0))
    add(is_zero(Pf.dot(S)))
    add(is_zero((Pf - r1).cross(S)))
    add(is_zero(S.cross(S0).dot(S.cross(S0)) - S.dot(S) * S0.dot(S0)))
    add(is_zero(Pf.cross(S.cross(S0))))
    add(is_zero(Pf.dot(S0)))
    add(is_zero(Pf.dot(Pf) - S0.dot(S0) / S.dot(S)))
    # 1.3: canonical pair and the Cayley-rotated generic placement
    a12, al = symbols("a12 alpha12", real=True)
    C1, C2 = Matrix([1, 0, 0]), Matrix([cos(al), sin(al), 0])
    ah = Matrix([0, 0, 1])
    R1, R2 = zeros(3, 1), a12 * ah
    add(is_zero(recip(C1, R1.cross(C1), C2, R2.cross(C2)) + a12 * sin(al)))
    add(is_zero(C2.cross(C1) + ah * sin(al)))
    add(is_zero((R1 - R2).dot(C2.cross(C1)) - a12 * sin(al)))
    q1, q2, q3, u1, u2 = symbols("q1 q2 q3 u1 u2", real=True)
    Qm = Matrix([[0, -q3, q2], [q3, 0, -q1], [-q2, q1, 0]])
    Rot = (eye(3) - Qm).inv() * (eye(3) + Qm)
    d = V("d")
    G1, G2 = Rot * C1, Rot * C2
    g1, g2 = Rot * R1 + d + u1 * G1, Rot * R2 + d + u2 * G2
    add(is_zero(recip(G1, g1.cross(G1), G2, g2.cross(G2)) + a12 * sin(al)))
    ra, rb = V("ra"), V("rb")
    add(is_zero((rb - ra).dot(S2.cross(S1)) - (rb.cross(S2).dot(S1) + ra.cross(S1).dot(S2))))
    add(is_zero(recip(S1, ra.cross(S1), S2, rb.cross(S2)) - (rb - ra).dot(S2.cross(S1))))
    add(is_zero(recip(A, c.cross(A), B, c.cross(B))))
    add(is_zero(recip(A, ra.cross(A), mu * A, rb.cross(mu * A))))
    # 1.4
    SA = (p - a).cross(S)
    add(is_zero(SA - ((b - a) + (p - b)).cross(S)))
    add(is_zero(SA - ((p - b).cross(S) + (b - a).cross(S))))
    add(is_zero((p + t * S - a).cross(S) - SA))
    add(is_zero(((p - a).cross(S) + h * S) - ((p.cross(S) + h * S) + (-a).cross(S))))
    add(is_zero(S.dot(S0 + (-a).cross(S)) - S.dot(S0)))
    Sg = V("S")
    add(is_zero(pitch(Sg, S0 - a.cross(Sg)) - pitch(Sg, S0)))
    Dg = V("D")
    hh = pitch(Sg, Dg)
    add(is_zero(Sg.dot(Dg - hh * Sg)))
    Pg = Sg.cross(Dg) / Sg.dot(Sg)
    add(is_zero((Pg + t * Sg).cross(Sg) - (Dg - hh * Sg)))
    add(is_zero(Pg - Sg.cross(Dg - hh * Sg) / Sg.dot(Sg)))
    add(is_zero(pitch(Sg, r.cross(Sg) + h * Sg) - h))
    add(is_zero(pitch(Sg, h * Sg) - h))
    add(pitch(Matrix([1, 1, 0]), Matrix([1, 0, 0])) == Rational(1, 2))
    # 1.5
    add(is_zero((S1 + S2).dot(D1 + D2) - (S1.dot(D1) + S2.dot(D2) + recip(S1, D1, S2, D2))))
    add(is_zero((A + B).dot(c.cross(A) + c.cross(B))))
    add(is_zero(c.cross(A + B) - (c.cross(A) + c.cross(B))))
    add(is_zero(pitch(S, p.cross(S) + C * S.cross(wv)) - 0))
    add(is_zero(pitch(lam * Sg, lam * Dg) - pitch(Sg, Dg)))
    add(is_zero(recip(Sg, Dg, Sg, Dg) - 2 * pitch(Sg, Dg) * Sg.dot(Sg)))
    AO = -a
    add(is_zero(recip(S1, D1 + AO.cross(S1), S2, D2 + AO.cross(S2)) - recip(S1, D1, S2, D2)))
    # 1.6, 1.7
    add(is_zero(w * r.cross(S) - r.cross(w * S)))
    add(is_zero(r.cross(w * S) - (w * S).cross(zeros(3, 1) - r)))
    v0 = w * (r.cross(S) + h * S)
    add(is_zero(v0 - (h * w * S + (w * S).cross(-r))))
    add(is_zero(v0.cross(w * S) - r.cross(w * S).cross(w * S)))
    add(is_zero((w * S).dot(v0) / (w * S).dot(w * S) - h))
    add(is_zero(f * r.cross(S) - r.cross(f * S)))
    f1 = V("f1")
    add(is_zero(r1.cross(f1) + r2.cross(-f1) - (r2 - r1).cross(-f1)))
    add(is_zero((r1 - a).cross(f1) + (r2 - a).cross(-f1) - (r1 - r2).cross(f1)))
    add(is_zero(f * (r.cross(S) + (C / f) * S) - (r.cross(f * S) + C * S)))
    # counting
    th, ph, uu, vv = symbols("theta phi u v", real=True)
    Sd = Matrix([sin(th) * cos(ph), sin(th) * sin(ph), cos(th)])
    e1 = Matrix([cos(th) * cos(ph), cos(th) * sin(ph), -sin(th)])
    e2 = Matrix([-sin(ph), cos(ph), 0])
    ft = uu * e1 + vv * e2
    Lv = Matrix.vstack(Sd, ft.cross(Sd))
    pt = {th: Rational(7, 10), ph: Rational(3, 10), uu: Rational(2, 3), vv: Rational(-5, 4)}
    Jn = Lv.jacobian([th, ph, uu, vv]).subs(pt).evalf(30)
    add(Jn.rank(iszerofunc=lambda e: abs(e) < 1e-20) == 4)
    return out


def main():
    t0 = time.perf_counter()
    results = checks()
    dt = time.perf_counter() - t0
    print(f"plain SymPy: {sum(results)} of {len(results)} checks pass in {dt:.2f} s")
    return dt


if __name__ == "__main__":
    main()
