"""Chain.from_dh: the product of exponentials of a Denavit-Hartenberg table, exactly.

The reference in every test is the product of the rows' homogeneous matrices, built here
directly from the conventions' definitions (not through screwsym):
standard (Denavit & Hartenberg 1955) A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i);
modified (Craig 2005, (3.6)) A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i).
"""

from __future__ import annotations

import pytest
from sympy import Matrix, Rational, atan2, cos, expand, expand_trig, eye, pi, sin, symbols, zeros

from screwsym import Chain, Transform

q = symbols("q1:8", real=True)

# Universal Robots' published standard DH parameters of the UR5 (Universal Robots,
# "DH parameters for calculations of kinematics and dynamics", the UR5 table)
D1, A2, A3, D4, D5, D6 = (Rational(x) for x in ("0.089159", "-0.425", "-0.39225",
                                                 "0.10915", "0.09465", "0.0823"))
UR5_STANDARD = [(0, pi / 2, D1, 0), (A2, 0, 0, 0), (A3, 0, 0, 0),
                (0, pi / 2, D4, 0), (0, -pi / 2, D5, 0), (0, 0, D6, 0)]
# the same robot in Craig's modified form: row i holds a_{i-1}, alpha_{i-1} (since
# Tx(a) Rx(alpha) commutes, the standard product regroups into these rows, and a_6 = alpha_6 = 0
# leaves no tool transform)
UR5_MODIFIED = [(0, 0, D1, 0), (0, pi / 2, 0, 0), (A2, 0, 0, 0),
                (A3, 0, D4, 0), (0, pi / 2, D5, 0), (0, -pi / 2, D6, 0)]


# Pythagorean angles: cos and sin rational, so every entry is a rational number
PYTHAGOREAN = [atan2(4, 3), atan2(-5, 12), atan2(24, -7), atan2(-8, -15), atan2(20, 21),
               atan2(-12, 35), atan2(9, 40)]


def Rz(t):
    return Matrix([[cos(t), -sin(t), 0, 0], [sin(t), cos(t), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])


def Rx(t):
    return Matrix([[1, 0, 0, 0], [0, cos(t), -sin(t), 0], [0, sin(t), cos(t), 0], [0, 0, 0, 1]])


def Tr(x, y, z):
    return Matrix([[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]])


def dh_product(rows, convention, joints, qs):
    """The forward kinematics as the product of the rows' matrices, from the definitions."""
    T = eye(4)
    for (a, alpha, d, theta), kind, qi in zip(rows, joints, qs, strict=True):
        theta, d = (theta + qi, d) if kind == "R" else (theta, d + qi)
        if convention == "standard":
            T = T * Rz(theta) * Tr(0, 0, d) * Tr(a, 0, 0) * Rx(alpha)
        else:
            T = T * Rx(alpha) * Tr(a, 0, 0) * Rz(theta) * Tr(0, 0, d)
    return T


def vanishes(M) -> bool:
    return all(expand(expand_trig(e)) == 0 for e in M)


@pytest.mark.parametrize("convention,rows", [("standard", UR5_STANDARD), ("modified", UR5_MODIFIED)])
def test_ur5_both_conventions_symbolically(convention, rows):
    """Six symbolic angles: the PoE chain's forward kinematics minus the DH product is 0."""
    chain = Chain.from_dh(rows, convention)
    qs = q[:6]
    difference = chain.forward(qs).matrix - dh_product(rows, convention, "RRRRRR", qs)
    assert vanishes(difference)
    # and the two conventions' tables describe the same robot
    assert Chain.from_dh(UR5_STANDARD) == Chain.from_dh(UR5_MODIFIED, "modified")


def test_a_wrong_convention_is_seen():
    """The check rejects a wrong answer: the standard table read as modified is another robot."""
    wrong = Chain.from_dh(UR5_STANDARD, "modified")
    qs = PYTHAGOREAN[:6]
    difference = wrong.forward(qs).matrix - dh_product(UR5_STANDARD, "standard", "RRRRRR", qs)
    assert difference.applyfunc(expand) != zeros(4, 4)




def test_panda_modified_dh_at_exact_points():
    """Franka Emika's published modified-DH table of the Panda (Franka Control Interface docs,
    "Robot and interface specifications": a, d, alpha per joint, and the flange d = 0.107),
    at exact poses with rational sines and cosines (differences exactly 0)."""
    rows = PANDA_MODIFIED_DH
    chain = Chain.from_dh(rows, "modified", tool=Transform.translation([0, 0, Rational("0.107")]))
    for shift in range(3):
        qs = PYTHAGOREAN[shift:] + PYTHAGOREAN[:shift]
        expected = dh_product(rows, "modified", "R" * 7, qs) * Tr(0, 0, Rational("0.107"))
        assert (chain.forward(qs).matrix - expected).applyfunc(expand) == zeros(4, 4)


PANDA_MODIFIED_DH = [
    # a           alpha    d                  theta
    (0,           0,        Rational("0.333"), 0),
    (0,           -pi / 2,  0,                 0),
    (0,           pi / 2,   Rational("0.316"), 0),
    (Rational("0.0825"),  pi / 2,  0,          0),
    (Rational("-0.0825"), -pi / 2, Rational("0.384"), 0),
    (0,           pi / 2,   0,                 0),
    (Rational("0.088"),   pi / 2,  0,          0),
]


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_prismatic_and_offsets_exact(convention):
    """An RPR arm with exact numbers: the prismatic row's d and the revolute rows' theta
    carry offsets; exact points with rational sines and cosines, differences exactly 0."""
    rows = [(Rational(3, 10), pi / 2, Rational(2, 5), pi / 6), (0, -pi / 3, Rational(1, 9), pi / 3),
            (Rational(-1, 7), 0, 0, pi / 4)]
    chain = Chain.from_dh(rows, convention, joints="RPR")
    assert chain.twists[1].omega == Matrix([0, 0, 0])  # prismatic: a pure translation (0; v)
    qs = [PYTHAGOREAN[0], Rational(5, 11), PYTHAGOREAN[1]]
    difference = chain.forward(qs).matrix - dh_product(rows, convention, "RPR", qs)
    assert difference.applyfunc(lambda e: expand(expand_trig(e))) == zeros(4, 4)


@pytest.mark.slow
@pytest.mark.parametrize("convention", ["standard"])
def test_prismatic_and_offsets_with_symbols(convention):
    """An RPR arm with symbolic lengths, twist angle and offsets (a theta offset on a revolute
    row, a d offset on a prismatic row).  The chain is built once with the symbols; then the
    symbols and the joints take exact values with rational sines and cosines, and the chain
    (its twists and home with the values put in) and the DH product agree exactly, at several such points."""
    a1, a3, d1, d2, t1, t3, al = params = symbols("a1 a3 d1 d2 t1 t3 alpha", real=True)
    rows = [(a1, pi / 2, d1, t1), (0, al, d2, pi / 3), (a3, 0, 0, t3)]
    chain = Chain.from_dh(rows, convention, joints="RPR")
    assert chain.free_symbols == set(params)
    assert chain.twists[1].omega == Matrix([0, 0, 0])  # prismatic: a pure translation (0; v)
    for shift in range(2):
        angles = PYTHAGOREAN[shift:] + PYTHAGOREAN[:shift]
        values = dict(zip(params, [Rational(3, 10), Rational(-1, 7), Rational(2, 5), Rational(1, 9),
                                   angles[0], angles[1], angles[2]], strict=True))
        qs = [angles[3], Rational(5, 11), angles[4]]
        exact_rows = [tuple(Matrix(r).subs(values)) for r in rows]
        expected = dh_product(exact_rows, convention, "RPR", qs)
        exact = Chain([t.matrix.xreplace(values) for t in chain.twists],
                      Transform.from_matrix(chain.home.matrix.xreplace(values)))
        got = exact.forward(qs).matrix
        assert (got - expected).applyfunc(lambda e: expand(expand_trig(e))) == zeros(4, 4)


def test_base_and_tool():
    base = Transform.rotation([0, 0, 1], pi / 2, point=[1, 0, 0])
    tool = Transform.translation([0, 0, Rational(1, 10)])
    rows = UR5_STANDARD[:3]
    chain = Chain.from_dh(rows, base=base, tool=tool)
    expected = base.matrix * dh_product(rows, "standard", "RRR", q[:3]) * tool.matrix
    assert vanishes(chain.forward(q[:3]).matrix - expected)


def test_errors():
    with pytest.raises(ValueError, match="rows: expected at least one DH row"):
        Chain.from_dh([])
    with pytest.raises(ValueError, match=r"rows\[0\]: expected 4 entries"):
        Chain.from_dh([(0, 0, 1)])
    with pytest.raises(TypeError, match=r"rows\[0\]\[1\]: strings are never evaluated|rows\[0\]\[1\]"):
        Chain.from_dh([(0, "pi/2", 0, 0)])
    with pytest.raises(ValueError, match="convention: expected one of 'standard', 'modified'"):
        Chain.from_dh([(0, 0, 1, 0)], "craig")
    with pytest.raises(ValueError, match=r"joints\[1\]: expected 'R' \(revolute"):
        Chain.from_dh([(0, 0, 1, 0), (0, 0, 1, 0)], joints="RX")
    with pytest.raises(ValueError, match="joints: expected 2 joint kinds"):
        Chain.from_dh([(0, 0, 1, 0), (0, 0, 1, 0)], joints="R")
    with pytest.raises(TypeError, match="base"):
        Chain.from_dh([(0, 0, 1, 0)], base=[[1, 0], [0, 1]])
