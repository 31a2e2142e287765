"""The shared formulas of screwsym.core.formulas: each identity checked once, with generic symbols.

Every check is a predicate on the formula (or formulas) it is given, so that
the same check is shown to reject a wrong formula: a transposed cross-product
matrix, a bracket with a sign swapped, a reciprocal product without the half
swap.  A check that passed on a wrong formula would prove nothing.
"""

import numpy as np
import pytest
from sympy import ImmutableMatrix, Matrix, Rational, expand, eye, symbols, zeros

from screwsym import Screw, reciprocal_product
from screwsym.core.formulas import (
    SWAP,
    ad_matrix,
    bracket,
    cross_matrix,
    dot,
    moved,
    reciprocal_form,
)

t = symbols("t", real=True)


def six(name):
    """A generic 6-vector of real symbols, a 6x1 column."""
    return ImmutableMatrix(symbols(f"{name}0:6", real=True))


def is_zero_column(v):
    return all(expand(e) == 0 for e in v)


A, B, C = six("a"), six("b"), six("c")
V, W = ImmutableMatrix(symbols("v0:3", real=True)), ImmutableMatrix(symbols("w0:3", real=True))


# ------------------------------------------------------------ wrong formulas
def transposed_cross_matrix(v):
    return cross_matrix(v).T


def bracket_moment_sign_swapped(a, b):
    """``(wa x wb; wb x va - wa x vb)``: antisymmetric still, but not a Lie bracket."""
    top, moment = bracket(a, b)[:3, 0], bracket(a, b)[3:, 0]
    return ImmutableMatrix.vstack(top, -moment)


def bracket_moment_plus(a, b):
    """``(wa x wb; wa x vb + wb x va)``: the sign of the second term swapped."""
    wa, va, wb, vb = a[:3, 0], a[3:, 0], b[:3, 0], b[3:, 0]
    return ImmutableMatrix.vstack(wa.cross(wb), wa.cross(vb) + wb.cross(va))


def ad_matrix_blocks_transposed(s):
    """``[[[w]x, [v]x], [0, [w]x]]``: the lower-left block moved to the upper right."""
    return ad_matrix(s).T.applyfunc(lambda e: -e)


def reciprocal_without_swap(x, y):
    """``x^T y``: the Euclidean product, not the reciprocal one."""
    return dot(x, y)


def reciprocal_with_minus(x, y):
    """``S1 . S2^0 - S2 . S1^0``."""
    return dot(x[:3, 0], y[3:, 0]) - dot(y[:3, 0], x[3:, 0])


# ------------------------------------------------------------ the checks
def cross_matrix_is_the_cross_product(cm):
    """``[v]x w = v x w``."""
    return is_zero_column(cm(V) * W - V.cross(W))


def ad_matrix_is_the_bracket(ad, br):
    """``ad(a) b = [a, b]``."""
    return is_zero_column(ad(A) * B - br(A, B))


def bracket_is_antisymmetric(br):
    return is_zero_column(br(A, B) + br(B, A))


def bracket_satisfies_jacobi(br):
    return is_zero_column(br(A, br(B, C)) + br(B, br(C, A)) + br(C, br(A, B)))


def bracket_is_the_derivative_of_the_adjoint_action(br):
    """``d/dt Ad(exp(t a)) b`` at ``t = 0`` is ``[a, b]``: the rigid motion ``x -> R x + p``
    of the twist ``a = (w; v)`` has ``R = I + t [w]x + O(t^2)`` and ``p = t v + O(t^2)``,
    and :func:`moved` is its action on the screw ``b`` (a formula of its own, (1.32))."""
    w, v = A[:3, 0], A[3:, 0]
    R = eye(3) + t * Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    S, S0 = moved(R, t * v, B[:3, 0], B[3:, 0])
    rate = Matrix.vstack(S, S0).diff(t).subs(t, 0)
    return is_zero_column(rate - br(A, B))


#: the half swap written out as a matrix, apart from SWAP
DELTA = Matrix.vstack(Matrix.hstack(zeros(3), eye(3)), Matrix.hstack(eye(3), zeros(3)))


def reciprocal_is_x_delta_y(rf):
    """``x^T Delta y`` with ``Delta = [[0, I], [I, 0]]`` (1.45)."""
    return expand(rf(A, B) - (A.T * DELTA * B)[0, 0]) == 0


def reciprocal_is_the_screws_product(rf):
    """The product of two screws ``S1 . S2^0 + S2 . S1^0`` (1.45) as :func:`reciprocal_product`
    gives it (the screws' own function, through their checks)."""
    s1, s2 = Screw(A[:3, 0], A[3:, 0]), Screw(B[:3, 0], B[3:, 0])
    return expand(rf(A, B) - reciprocal_product(s1, s2, tidy=False)) == 0


# ------------------------------------------------------------ the tests
def test_cross_matrix_is_the_cross_product_and_a_transposed_one_is_not():
    assert cross_matrix_is_the_cross_product(cross_matrix)
    assert not cross_matrix_is_the_cross_product(transposed_cross_matrix)


def test_ad_matrix_is_the_bracket_and_wrong_ones_are_not():
    assert ad_matrix_is_the_bracket(ad_matrix, bracket)
    assert not ad_matrix_is_the_bracket(ad_matrix_blocks_transposed, bracket)
    assert not ad_matrix_is_the_bracket(ad_matrix, bracket_moment_plus)


def test_bracket_is_antisymmetric_and_a_sign_swap_is_not():
    assert bracket_is_antisymmetric(bracket)
    assert not bracket_is_antisymmetric(bracket_moment_plus)


def test_bracket_satisfies_jacobi_and_a_sign_swap_does_not():
    # the swapped moment sign is antisymmetric, so only the Jacobi identity sees it
    assert bracket_is_antisymmetric(bracket_moment_sign_swapped)
    assert bracket_satisfies_jacobi(bracket)
    assert not bracket_satisfies_jacobi(bracket_moment_sign_swapped)


def test_bracket_is_the_rate_of_the_adjoint_action():
    assert bracket_is_the_derivative_of_the_adjoint_action(bracket)
    assert not bracket_is_the_derivative_of_the_adjoint_action(bracket_moment_sign_swapped)
    assert not bracket_is_the_derivative_of_the_adjoint_action(bracket_moment_plus)


def test_reciprocal_form_is_x_delta_y_and_the_euclidean_product_is_not():
    assert reciprocal_is_x_delta_y(reciprocal_form)
    assert not reciprocal_is_x_delta_y(reciprocal_without_swap)
    assert not reciprocal_is_x_delta_y(reciprocal_with_minus)


def test_reciprocal_form_is_the_screws_reciprocal_product():
    assert reciprocal_is_the_screws_product(reciprocal_form)
    assert not reciprocal_is_the_screws_product(reciprocal_with_minus)


def test_the_half_swap_is_delta():
    assert DELTA == eye(6)[list(SWAP), :]


# ------------------------------------------- NumPy arrays: the same formulas
@pytest.mark.parametrize("case", range(5))
def test_arrays_give_the_sympy_values(case):
    rng = np.random.default_rng([31, case])
    a, b = rng.integers(-9, 10, size=(2, 6)).astype(float)
    ea, eb = ImmutableMatrix([Rational(int(e)) for e in a]), ImmutableMatrix([Rational(int(e)) for e in b])
    assert float(reciprocal_form(a, b)) == float(reciprocal_form(ea, eb))
    assert np.array_equal(bracket(a, b), np.array(bracket(ea, eb), dtype=float).ravel())
    assert np.array_equal(ad_matrix(a), np.array(ad_matrix(ea), dtype=float))
    assert np.array_equal(cross_matrix(a[:3]), np.array(cross_matrix(ea[:3, 0]), dtype=float))


def test_arrays_stack_along_the_last_axis():
    rng = np.random.default_rng([31, 99])
    a, b = rng.normal(size=(2, 4, 6))
    assert np.allclose(reciprocal_form(a, b), [reciprocal_form(x, y) for x, y in zip(a, b, strict=True)])
    assert np.allclose(bracket(a, b), [bracket(x, y) for x, y in zip(a, b, strict=True)])
    assert np.allclose(ad_matrix(a), [ad_matrix(x) for x in a])
    assert np.allclose(cross_matrix(a[:, :3]), [cross_matrix(x) for x in a[:, :3]])


def test_lists_and_tuples_give_sympy_results():
    assert bracket([0, 0, 1, 0, 0, 0], (1, 0, 0, 0, 0, 0)) == ImmutableMatrix([0, 1, 0, 0, 0, 0])
    assert isinstance(ad_matrix([1, 2, 3, 4, 5, 6]), ImmutableMatrix)
    assert cross_matrix((1, 2, 3)) == cross_matrix(ImmutableMatrix([1, 2, 3]))
    assert reciprocal_form([1, 0, 0, 0, 0, 0], [0, 0, 0, 2, 0, 0]) == 2
