r"""screwsym: symbolic screw theory on SymPy.

Convention, used everywhere: a screw is written in the book's ray order,
direction part first, dual (moment) part second, ``$ = (S; S0)``: a line
vector ``(S; S_0)``, a twist ``(omega; v_O)``, a wrench ``(f; C_O)``.
The reference is Chapter 1 of Huang, Li & Ding, *Theory of Parallel
Mechanisms* (Springer 2013); docstrings cite its equation numbers.

>>> from screwsym import Screw
>>> s = Screw([1, 1, 0], [1, 0, 0])
>>> s.pitch, s.axis
(1/2, LineVector([1, 1, 0], [1/2, -1/2, 0]))
"""

import importlib
from typing import TYPE_CHECKING as _TYPE_CHECKING
from typing import Any as _Any

from ._launch import interrupted_quietly as _interrupted_quietly
from ._version import __version__ as __version__

with _interrupted_quietly():  # the import takes most of the command line's first second
    from .core import (
        CommonNormal,
        LineVector,
        Screw,
        SpatialInertia,
        Twist,
        Wrench,
        axis,
        classify,
        common_normal,
        contains,
        decompose_screw,
        direction_cosines,
        distance_to_origin,
        foot,
        is_coplanar,
        is_reciprocal,
        mutual_moment,
        pitch,
        power,
        reciprocal_product,
        shift_origin,
        tidy,
        unit,
        vector,
    )
    from .core.printing import init_printing as init_printing

if _TYPE_CHECKING:  # loaded on first use (_LAZY_NAMES below); a type checker sees them here
    from .motion import Chain, Transform, convert, convert_from, exp6, log6
    from .systems import (
        Cylindrical,
        Helical,
        Limb,
        Mechanism,
        Mobility,
        ParallelMechanism,
        Parallelogram,
        Prismatic,
        Revolute,
        ScrewSystem,
        Spherical,
        Universal,
    )

#: What ``from screwsym import *`` binds.  It names nothing that ``from sympy import *``
#: binds too (tests/package/test_namespace.py checks it), so a notebook may star-import
#: both: screwsym's ``lambdify``, ``init_printing``, ``plot`` and ``__version__`` are
#: attributes of the package (``screwsym.lambdify``) but not star-imported.
__all__ = [
    # the objects of Chapter 1 (screwsym.core)
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
    # rigid motions (screwsym.motion)
    "Transform",
    "exp6",
    "log6",
    "Chain",
    "convert",
    "convert_from",
    # screw systems and mechanisms (screwsym.systems)
    "ScrewSystem",
    "Revolute",
    "Prismatic",
    "Helical",
    "Cylindrical",
    "Universal",
    "Spherical",
    "Limb",
    "ParallelMechanism",
    "Mobility",
    "Parallelogram",
    "Mechanism",
    # floors loaded on first use
    "book",
    "codegen",
    "numeric",
]

# Subpackages that pull in more (the book registry, code generation, plotting)
# load on first use, so ``import screwsym`` stays light; ``dir`` lists them.
_LAZY_MODULES = ("book", "cli", "codegen", "motion", "numeric", "plot", "systems")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__) | set(_LAZY_MODULES) | {"lambdify"})


#: The rigid motions and the screw systems load on first use too (``screwsym.Chain``,
#: ``from screwsym import ScrewSystem``): the book and the objects of Chapter 1 need
#: only the core, and ``screwsym verify`` starts faster without them.
_LAZY_NAMES = {
    **dict.fromkeys(("Chain", "Transform", "convert", "convert_from", "exp6", "log6"), "motion"),
    **dict.fromkeys(
        ("Cylindrical", "Helical", "Limb", "Mechanism", "Mobility", "ParallelMechanism",
         "Parallelogram", "Prismatic", "Revolute", "ScrewSystem", "Spherical", "Universal"),
        "systems",
    ),
}


def __getattr__(name: str) -> _Any:
    if name in _LAZY_NAMES:
        value = getattr(importlib.import_module(f".{_LAZY_NAMES[name]}", __name__), name)
        globals()[name] = value
        return value
    if name in _LAZY_MODULES:
        return importlib.import_module(f".{name}", __name__)
    if name == "lambdify":
        return importlib.import_module(".codegen", __name__).lambdify
    raise AttributeError(f"module 'screwsym' has no attribute {name!r}")
