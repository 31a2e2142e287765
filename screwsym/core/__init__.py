r"""The objects of Chapter 1 and their algebra: lines, screws, twists, wrenches.

This floor imports nothing of screwsym above it.  Its public modules:

- :mod:`~screwsym.core.screw`: :class:`Screw` and the operations every kind shares;
- :mod:`~screwsym.core.line`, :mod:`~screwsym.core.twist`, :mod:`~screwsym.core.wrench`:
  the three kinds of screw (line vector, twist, wrench);
- :mod:`~screwsym.core.inertia`: :class:`SpatialInertia`, a body's map from twists to momenta;
- :mod:`~screwsym.core.vectors`, :mod:`~screwsym.core.tidy`, :mod:`~screwsym.core.printing`;
- :mod:`~screwsym.core.formulas`: the formulas the floors share (foot point, pitch,
  axis to screw, a screw moved by a rigid motion, the half swap, the reciprocal
  product of 6-vectors, the cross-product matrix, the Lie bracket of twists and
  its matrix), each written once;
- :mod:`~screwsym.core.conditions`: the ``conds="piecewise"`` machinery (the
  conditions of a result on request);
- :mod:`~screwsym.core.decide` (exact decisions and the float policy),
  :mod:`~screwsym.core.checks` (input checks and their wording) and
  :mod:`~screwsym.core.basic` (the SymPy base of every object), which the
  floors above build on.
"""

from .inertia import SpatialInertia
from .line import CommonNormal, LineVector, common_normal, contains, is_coplanar, mutual_moment
from .screw import (
    Screw,
    axis,
    classify,
    decompose_screw,
    direction_cosines,
    distance_to_origin,
    foot,
    is_reciprocal,
    pitch,
    reciprocal_product,
    shift_origin,
    unit,
)
from .tidy import tidy
from .twist import Twist
from .vectors import vector
from .wrench import Wrench, power

__all__ = [
    "Screw",
    "LineVector",
    "Twist",
    "Wrench",
    "SpatialInertia",
    "CommonNormal",
    "vector",
    "pitch",
    "axis",
    "foot",
    "decompose_screw",
    "classify",
    "shift_origin",
    "reciprocal_product",
    "is_reciprocal",
    "distance_to_origin",
    "direction_cosines",
    "unit",
    "contains",
    "mutual_moment",
    "is_coplanar",
    "common_normal",
    "power",
    "tidy",
]
