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

from ._version import __version__
from .chain import Chain
from .conventions import convert, convert_from
from .displacement import exp, log
from .line import (
    CommonNormal,
    LineVector,
    common_normal,
    contains,
    is_coplanar,
    mutual_moment,
)
from .mechanism import Limb, Mobility, ParallelMechanism
from .printing import init_printing
from .screw import (
    Screw,
    axis,
    classify,
    decompose,
    direction_cosines,
    distance_to_origin,
    foot,
    is_reciprocal,
    pitch,
    reciprocal_product,
    shift_origin,
    unit,
)
from .system import ScrewSystem
from .tidy import tidy
from .transform import Transform
from .twist import Twist
from .vectors import vector
from .wrench import Wrench, power

__all__ = [
    "__version__",
    "Screw",
    "LineVector",
    "Twist",
    "Wrench",
    "CommonNormal",
    "vector",
    "pitch",
    "axis",
    "foot",
    "decompose",
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
    "init_printing",
    "lambdify",
    "book",
    "codegen",
    "mechanism_numeric",
    "numeric",
    "plot",
    # rigid motions (issue 10)
    "Transform",
    "exp",
    "log",
    "Chain",
    "convert",
    "convert_from",
    "ScrewSystem",
    "Limb",
    "ParallelMechanism",
    "Mobility",
]

# Subpackages that pull in more (the book registry, code generation, plotting)
# load on first use, so ``import screwsym`` stays light; ``dir`` lists them.
_LAZY_MODULES = ("book", "cli", "codegen", "mechanism_numeric", "numeric", "plot")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__) | set(_LAZY_MODULES))


def __getattr__(name: str):
    if name in _LAZY_MODULES:
        return importlib.import_module(f".{name}", __name__)
    if name == "lambdify":
        return importlib.import_module(".codegen", __name__).lambdify
    raise AttributeError(f"module 'screwsym' has no attribute {name!r}")
