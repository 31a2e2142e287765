r"""The formulas of Chapter 1 that several floors use, each written once.

Pure functions of a screw's parts ``(S, S0)``, of an axis or of 6-vectors in
the book's ray order, with no checks and no tidying: the callers check their
arguments first and bring the result to the form they promise.
:func:`foot_point`, :func:`pitch_ratio` and :func:`dual_part` work on SymPy
columns (exact or symbolic) and on NumPy arrays of floats alike, so the
drawings of ``screwsym.plot`` and the symbolic core compute the same formula.

- :func:`foot_point`: ``S x S0 / S . S`` (1.16);
- :func:`pitch_ratio`: ``S . S0 / S . S`` (1.34);
- :func:`dual_part`: ``r x S + h S``, the dual part of the screw of pitch
  ``h`` on the axis through ``r`` along ``S`` (1.36, 1.38, 1.48);
- :func:`moved`: a screw carried by the rigid motion ``(R, p)``,
  ``(R S; R S0 + p x R S)``, the origin shift (1.32) after a rotation;
- :data:`SWAP`: the half swap ``Delta`` of the reciprocal product (1.45);
- :func:`reciprocal_form`: the reciprocal product ``x^T Delta y`` of two
  6-vectors (1.45);
- :func:`cross_matrix`: the matrix ``[v]x`` of the cross product,
  ``[v]x w = v x w``;
- :func:`bracket` and :func:`ad_matrix`: the Lie bracket of two twists in ray
  order, ``[a, b] = ad(a) b``.

:func:`reciprocal_form`, :func:`cross_matrix`, :func:`bracket` and
:func:`ad_matrix` take SymPy columns, lists or tuples (and give SymPy
results), or NumPy arrays (and give arrays; a stack of vectors along the last
axis gives a stack of results).  ``dot`` is the dot product the formulas
and the core's decisions share.
"""

from __future__ import annotations

from typing import Any

from sympy import Add, ImmutableMatrix, zeros
from sympy.matrices import MatrixBase

__all__ = [
    "foot_point",
    "pitch_ratio",
    "dual_part",
    "moved",
    "SWAP",
    "reciprocal_form",
    "cross_matrix",
    "bracket",
    "ad_matrix",
]

#: the index permutation of ``Delta = [[0, I], [I, 0]]``: ``(Delta x)[i] = x[SWAP[i]]``, so
#: that the reciprocal product (1.45) ``$1 o $2 = S1 . S2^0 + S2 . S1^0`` is
#: ``sum(x1[SWAP[i]] * x2[i])``; NumPy and numba code index with it (``M[..., SWAP]``)
SWAP = (3, 4, 5, 0, 1, 2)


def dot(a: Any, b: Any) -> Any:
    """``a . b`` of two vectors (SymPy columns or NumPy arrays).

    For SymPy vectors the sum of the products, as ``Matrix.dot`` finds it for
    finite entries (``Add`` of the same terms), without its detour through a
    matrix product (most of the cost of a symbolic dot product).

    >>> from sympy import ImmutableMatrix
    >>> dot(ImmutableMatrix([1, 2, 3]), ImmutableMatrix([4, 5, 6]))
    32
    """
    if isinstance(a, MatrixBase) and isinstance(b, MatrixBase) and len(a) == len(b):
        return Add(*[x * y for x, y in zip(a, b, strict=True)])
    return a.dot(b)


def _cross(a: Any, b: Any) -> Any:
    if isinstance(a, MatrixBase):
        return a.cross(b)
    import numpy as np

    return np.cross(a, b)


def _symbolic(x: Any) -> bool:
    """Whether ``x`` is a SymPy matrix, a list or a tuple (else a NumPy array)."""
    return isinstance(x, (MatrixBase, list, tuple))


def _cross3(a: Any, b: Any) -> tuple[Any, Any, Any]:
    """The entries of ``a x b`` for two sequences of three entries, as ``Matrix.cross`` forms them."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def foot_point(S: Any, S0: Any) -> Any:
    r"""The point of the line (or screw axis) ``(S; S0)`` nearest the origin, ``S x S0 / S . S`` (1.16).

    For a screw the same formula gives the foot of its axis, since ``S x (h S) = 0``
    (1.36).  Holds where ``S != 0``.

    >>> from sympy import ImmutableMatrix
    >>> foot_point(ImmutableMatrix([1, 1, 0]), ImmutableMatrix([1, 0, 0])).T    # Example 1.4
    Matrix([[0, 0, -1/2]])
    >>> import numpy as np
    >>> foot_point(np.array([1.0, 1, 0]), np.array([1.0, 0, 0]))
    array([ 0. ,  0. , -0.5])
    """
    return _cross(S, S0) / dot(S, S)


def pitch_ratio(S: Any, S0: Any) -> Any:
    r"""The pitch of the screw ``(S; S0)``, ``h = S . S0 / S . S`` (1.34).

    Only the formula, which holds where ``S != 0``: the special cases (a
    couple's ``oo``, a line vector's 0, a float residue of ``S . S0``) are
    :func:`screwsym.core.screw.pitch`'s.

    >>> from sympy import ImmutableMatrix
    >>> pitch_ratio(ImmutableMatrix([1, 1, 0]), ImmutableMatrix([1, 0, 0]))      # Example 1.4
    1/2
    """
    return dot(S, S0) / dot(S, S)


def dual_part(r: Any, S: Any, h: Any = 0) -> Any:
    r"""The dual part ``r x S + h S`` of the screw of pitch ``h`` on the axis through ``r`` along ``S``.

    A line vector's moment ``r x S`` (1.9) for ``h = 0``; a screw's dual part
    (1.36, 1.38), a twist's ``v_O`` (1.48, 1.53), a wrench's ``C_O`` (1.57).

    >>> from sympy import ImmutableMatrix
    >>> dual_part(ImmutableMatrix([0, 1, 0]), ImmutableMatrix([1, 0, 0]), 2).T
    Matrix([[2, 0, -1]])
    """
    return _cross(r, S) + h * S


def moved(R: Any, p: Any, S: Any, S0: Any) -> tuple[Any, Any]:
    r"""The screw ``(S; S0)`` carried by the rigid motion ``x -> R x + p``: ``(R S; R S0 + p x R S)``.

    The direction part turns, and the moment part is turned and taken about
    the new origin: the origin shift (1.32) after a rotation.  In ray order it
    is the same for a line vector, a twist and a wrench: the adjoint action
    ``Ad(T) = [[R, 0], [[p]x R, R]]``.  ``R=None`` is the identity, so that
    ``moved(None, -A, S, S0)`` is the shift of origin to ``A`` (1.32).
    Returns the pair of parts.

    >>> from sympy import ImmutableMatrix
    >>> S, S0 = ImmutableMatrix([1, 0, 0]), ImmutableMatrix([0, 0, 0])
    >>> [v.T for v in moved(None, ImmutableMatrix([0, 0, 1]), S, S0)]
    [Matrix([[1, 0, 0]]), Matrix([[0, 1, 0]])]
    """
    if R is not None:
        S, S0 = R * S, R * S0
    return S, S0 + _cross(p, S)


def reciprocal_form(x: Any, y: Any) -> Any:
    r"""The reciprocal product of two 6-vectors in ray order, ``x^T Delta y`` (1.45).

    With ``x = (S1; S1^0)`` and ``y = (S2; S2^0)`` it is
    ``$1 o $2 = S1 . S2^0 + S2 . S1^0``, the symmetric form of the half swap
    ``Delta = [[0, I], [I, 0]]`` (:data:`SWAP`): the mutual moment of two lines
    (1.23), the power of a wrench on a twist (1.45).  Only the formula: the
    checks and the tidying are :func:`screwsym.core.screw.reciprocal_product`'s.

    >>> from sympy import ImmutableMatrix
    >>> reciprocal_form(ImmutableMatrix([1, 1, 0, 1, 0, 0]), [1, 1, 0, 1, 0, 0])
    2
    >>> import numpy as np
    >>> float(reciprocal_form(np.array([1.0, 0, 0, 0, 0, 0]), np.array([0.0, 0, 0, 2, 0, 0])))
    2.0
    """
    if _symbolic(x):
        return (Add(*[x[i] * y[i + 3] for i in range(3)])
                + Add(*[y[i] * x[i + 3] for i in range(3)]))
    return (x[..., :3] * y[..., 3:]).sum(axis=-1) + (y[..., :3] * x[..., 3:]).sum(axis=-1)


def cross_matrix(v: Any) -> Any:
    r"""The 3x3 matrix ``[v]x`` with ``[v]x w = v x w``: the cross product as a matrix.

    Skew-symmetric, ``[v]x^T = -[v]x``.  The moment ``r x S`` of a line (1.9)
    is ``[r]x S``; in a rigid motion ``(R, p)`` a screw's dual part turns with
    ``[p]x R`` (the adjoint action, :func:`moved`).

    >>> from sympy import ImmutableMatrix
    >>> cross_matrix(ImmutableMatrix([1, 2, 3]))
    Matrix([
    [ 0, -3,  2],
    [ 3,  0, -1],
    [-2,  1,  0]])
    >>> import numpy as np
    >>> cross_matrix(np.array([1.0, 2, 3])) @ np.array([0.0, 0, 1])
    array([ 2., -1.,  0.])
    """
    if _symbolic(v):
        x, y, z = v
        return ImmutableMatrix([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    import numpy as np

    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    o = np.zeros_like(x)
    return np.stack([np.stack([o, -z, y], -1), np.stack([z, o, -x], -1),
                     np.stack([-y, x, o], -1)], -2)


def bracket(a: Any, b: Any) -> Any:
    r"""The Lie bracket of two twists in ray order: ``[a, b] = (wa x wb; wa x vb - wb x va)``.

    For ``a = (wa; va)`` and ``b = (wb; vb)`` (``v`` the velocity of the body
    point at the origin), ``[a, b] = ad(a) b`` (:func:`ad_matrix`): the rate
    of change of a screw ``b`` fixed in a body that moves with the twist ``a``
    (twists and wrenches alike, both carried by the adjoint action in ray
    order; Murray, Li & Sastry 1994, Section 2.4, written in the order
    ``(w; v)``).  Antisymmetric, and it satisfies the Jacobi identity.  A
    SymPy result is a 6x1 ``ImmutableMatrix``.

    >>> bracket([0, 0, 1, 0, 0, 0], [0, 0, 1, 0, -1, 0]).T     # parallel rotations
    Matrix([[0, 0, 0, 1, 0, 0]])
    >>> import numpy as np
    >>> bracket(np.array([0.0, 0, 1, 0, 0, 0]), np.array([1.0, 0, 0, 0, 0, 0]))
    array([0., 1., 0., 0., 0., 0.])
    """
    if _symbolic(a):
        wa, va, wb, vb = a[0:3], a[3:6], b[0:3], b[3:6]
        # wa x vb + va x wb: the same entries as wa x vb - wb x va, as Matrix arithmetic forms them
        moment = [p + q for p, q in zip(_cross3(wa, vb), _cross3(va, wb), strict=True)]
        return ImmutableMatrix(6, 1, [*_cross3(wa, wb), *moment])
    import numpy as np

    wa, va, wb, vb = a[..., :3], a[..., 3:], b[..., :3], b[..., 3:]
    return np.concatenate([np.cross(wa, wb), np.cross(wa, vb) + np.cross(va, wb)], axis=-1)


def ad_matrix(s: Any) -> Any:
    r"""The 6x6 matrix ``ad(s) = [[[w]x, 0], [[v]x, [w]x]]`` of ``x -> [s, x]``, ``s = (w; v)``.

    The matrix of :func:`bracket` with its first argument fixed, in ray order:
    ``ad(s) x = [s, x]``; the derivative at the identity of the adjoint action
    ``Ad = [[R, 0], [[p]x R, R]]`` (:func:`moved`) along the twist ``s``.

    >>> ad_matrix([0, 0, 1, 1, 0, 0]) * ImmutableMatrix([1, 0, 0, 0, 0, 0])
    Matrix([
    [0],
    [1],
    [0],
    [0],
    [0],
    [0]])
    >>> import numpy as np
    >>> ad_matrix(np.array([0.0, 0, 1, 1, 0, 0])).shape
    (6, 6)
    """
    if _symbolic(s):
        W, V = cross_matrix(s[0:3]), cross_matrix(s[3:6])
        return ImmutableMatrix.vstack(W.row_join(zeros(3, 3)), V.row_join(W))
    import numpy as np

    W, V = cross_matrix(s[..., :3]), cross_matrix(s[..., 3:])
    out = np.zeros(s.shape[:-1] + (6, 6), dtype=np.result_type(s))
    out[..., :3, :3] = W
    out[..., 3:, :3] = V
    out[..., 3:, 3:] = W
    return out
