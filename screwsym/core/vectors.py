"""Generic symbolic 3-vectors for derivations."""

from __future__ import annotations

from sympy import ImmutableMatrix, symbols

from .checks import check_name

__all__ = ["vector"]


def vector(name: str) -> ImmutableMatrix:
    """A 3x1 ``ImmutableMatrix`` of real symbols ``name_x, name_y, name_z``.

    >>> from screwsym import vector
    >>> r = vector("r")
    >>> r.T
    Matrix([[r_x, r_y, r_z]])
    >>> r[0].is_real
    True
    """
    name = check_name(name, "name")
    return ImmutableMatrix(symbols(f"{name}_x {name}_y {name}_z", real=True))
