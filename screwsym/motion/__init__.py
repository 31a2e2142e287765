r"""Rigid motions, SE(3): transforms, exp6/log6 of twists, serial chains, their dynamics, conventions,
the Paden–Kahan subproblems.

Built on :mod:`screwsym.core` alone (Lynch & Park, *Modern Robotics*; Murray,
Li & Sastry).  A sibling of :mod:`screwsym.systems`: neither imports the other.
"""

from .chain import Chain, ur5
from .conventions import CONVENTIONS, Convention, convert, convert_from
from .displacement import exp6, log6, se3_matrix
from .dynamics import coriolis_matrix, gravity_torques, inverse_dynamics, mass_matrix, regressor
from .inverse_kinematics import (
    Decomposition,
    decomposition,
    inverse_kinematics,
    stage_order,
    subproblem4,
)
from .newton_euler import (
    Operations,
    Program,
    dynamics_program,
    parameter_symbols,
    regressor_program,
)
from .parameters import (
    BaseParameters,
    base_parameters,
    base_program,
    base_regressor,
    base_symbols,
    base_values,
    parameters,
)
from .subproblems import Branch, subproblem1, subproblem2, subproblem3, subproblem5
from .transform import Transform, adjoint_matrix, skew

__all__ = [
    "Transform",
    "skew",
    "adjoint_matrix",
    "exp6",
    "log6",
    "se3_matrix",
    "Chain",
    "ur5",
    "inverse_dynamics",
    "mass_matrix",
    "coriolis_matrix",
    "gravity_torques",
    "regressor",
    "dynamics_program",
    "Program",
    "Operations",
    "parameters",
    "base_parameters",
    "base_regressor",
    "base_symbols",
    "base_values",
    "base_program",
    "regressor_program",
    "parameter_symbols",
    "BaseParameters",
    "convert",
    "convert_from",
    "CONVENTIONS",
    "Convention",
    "Branch",
    "subproblem1",
    "subproblem2",
    "subproblem3",
    "subproblem4",
    "subproblem5",
    "inverse_kinematics",
    "decomposition",
    "Decomposition",
    "stage_order",
]
