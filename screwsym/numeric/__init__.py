r"""Floats: the chapter's operations generated as vectorised functions, and numeric kernels.

- :mod:`~screwsym.numeric.screws`: ``pitch``, ``foot``, ``reciprocal_product``, ...
  generated from the symbolic core (``numeric.pitch(array)``);
- :mod:`~screwsym.numeric.mobility`: :func:`mobility_map`, the mobility of a
  parallel mechanism at many configurations at once;
- :mod:`~screwsym.numeric.transmission`: :func:`transmission_map` and
  :func:`jacobian_map`, transmission indices and Jacobians over a grid;
- :mod:`~screwsym.numeric.dynamics`: a chain's dynamics as generated functions,
  :func:`forward_dynamics`;
- :mod:`~screwsym.numeric.loop_dynamics`: a closed loop's inverse dynamics and mass
  matrix as generated functions of its configuration's symbols;
- :mod:`~screwsym.numeric.loop_program`: the same as straight-line programs
  (:func:`loop_dynamics_program`);
- :mod:`~screwsym.numeric.ik`: :func:`inverse_kinematics_function`, every closed-form
  inverse kinematics branch at many poses.

Built on :mod:`screwsym.codegen`, :mod:`screwsym.core`, :mod:`screwsym.systems` and
:mod:`screwsym.motion`.
"""

from collections.abc import Callable

from . import screws
from ._direct import recycle_results
from .dynamics import DynamicsFunctions, dynamics_functions, forward_dynamics
from .ik import inverse_kinematics_function
from .loop_dynamics import LoopDynamicsFunctions, loop_dynamics_functions
from .loop_program import LoopProgram, loop_dynamics_program
from .mobility import MobilityMap, mobility_map
from .screws import NAMES, functions_for
from .transmission import TransmissionMap, jacobian_map, transmission_map

__all__ = [*NAMES, "functions_for", "NAMES", "MobilityMap", "mobility_map",
           "DynamicsFunctions", "dynamics_functions", "forward_dynamics",
           "TransmissionMap", "transmission_map", "jacobian_map",
           "recycle_results", "inverse_kinematics_function",
           "LoopDynamicsFunctions", "loop_dynamics_functions",
           "LoopProgram", "loop_dynamics_program"]


def __getattr__(name: str) -> Callable:
    # the generated functions are made on first use, by screws' own __getattr__ (PEP 562)
    if name in NAMES:
        return getattr(screws, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(NAMES))
