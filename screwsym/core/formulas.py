r"""The formulas of Chapter 1 that several floors use, each written once.

Pure functions of a screw's parts ``(S, S0)`` (or of an axis), with no checks
and no tidying: the callers check their arguments first and bring the result
to the form they promise.  :func:`foot_point`, :func:`pitch_ratio` and
:func:`dual_part` work on SymPy columns (exact or symbolic) and on NumPy
arrays of floats alike, so the drawings of ``screwsym.plot`` and the
symbolic core compute the same formula.

- :func:`foot_point`: ``S x S0 / S . S`` (1.16);
- :func:`pitch_ratio`: ``S . S0 / S . S`` (1.34);
- :func:`dual_part`: ``r x S + h S``, the dual part of the screw of pitch
  ``h`` on the axis through ``r`` along ``S`` (1.36, 1.38, 1.48);
- :func:`moved`: a screw carried by the rigid motion ``(R, p)``,
  ``(R S; R S0 + p x R S)``, the origin shift (1.32) after a rotation;
- :data:`SWAP`: the half swap ``Delta`` of the reciprocal product (1.45).
"""

from __future__ import annotations

from typing import Any

from sympy import Add
from sympy.matrices import MatrixBase

__all__ = ["foot_point", "pitch_ratio", "dual_part", "moved", "SWAP"]

#: the index permutation of ``Delta = [[0, I], [I, 0]]``: ``(Delta x)[i] = x[SWAP[i]]``, so
#: that the reciprocal product (1.45) ``$1 o $2 = S1 . S2^0 + S2 . S1^0`` is
#: ``sum(x1[SWAP[i]] * x2[i])``; NumPy and numba code index with it (``M[..., SWAP]``)
SWAP = (3, 4, 5, 0, 1, 2)


def _dot(a: Any, b: Any) -> Any:
    """``a . b`` of two vectors (SymPy columns or NumPy arrays).

    For SymPy vectors the sum of the products, as ``Matrix.dot`` finds it for
    finite entries (``Add`` of the same terms), without its detour through a
    matrix product (most of the cost of a symbolic dot product).
    """
    if isinstance(a, MatrixBase) and isinstance(b, MatrixBase) and len(a) == len(b):
        return Add(*[x * y for x, y in zip(a, b, strict=True)])
    return a.dot(b)


def _cross(a: Any, b: Any) -> Any:
    if isinstance(a, MatrixBase):
        return a.cross(b)
    import numpy as np

    return np.cross(a, b)


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
    return _cross(S, S0) / _dot(S, S)


def pitch_ratio(S: Any, S0: Any) -> Any:
    r"""The pitch of the screw ``(S; S0)``, ``h = S . S0 / S . S`` (1.34).

    Only the formula, which holds where ``S != 0``: the special cases (a
    couple's ``oo``, a line vector's 0, a float residue of ``S . S0``) are
    :func:`screwsym.core.screw.pitch`'s.

    >>> from sympy import ImmutableMatrix
    >>> pitch_ratio(ImmutableMatrix([1, 1, 0]), ImmutableMatrix([1, 0, 0]))      # Example 1.4
    1/2
    """
    return _dot(S, S0) / _dot(S, S)


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
