r"""Screw systems, kinematic pairs, and the mobility of parallel mechanisms and of any linkage.

Built on :mod:`screwsym.core` and :mod:`screwsym.algebra` alone (Huang, Li & Ding, Chapters 2 and 5).  A
sibling of :mod:`screwsym.motion`: neither imports the other.
"""

from .assembly import (
    AssemblyFamily,
    AssemblyModes,
    CertifiedMode,
    PlanarMode,
    SpatialMode,
    direct_kinematics,
    leg_lengths,
)
from .joints import (
    Cylindrical,
    Helical,
    Joint,
    Parallelogram,
    Prismatic,
    Revolute,
    Spherical,
    Universal,
)
from .limb_kinematics import LimbBranch, limb_joint_values
from .linkage import Mechanism, MechanismMobility
from .motion_type import MotionType, motion_of, motion_type
from .parallel import Degenerate, Limb, Mobility, ParallelMechanism
from .screw_system import ScrewSystem
from .second_order import SecondOrder, lie_bracket

__all__ = [
    "ScrewSystem",
    "Joint",
    "Revolute",
    "Prismatic",
    "Helical",
    "Cylindrical",
    "Universal",
    "Spherical",
    "Parallelogram",
    "Limb",
    "ParallelMechanism",
    "Mobility",
    "Degenerate",
    "motion_type",
    "motion_of",
    "MotionType",
    "Mechanism",
    "MechanismMobility",
    "SecondOrder",
    "lie_bracket",
    "direct_kinematics",
    "leg_lengths",
    "limb_joint_values",
    "LimbBranch",
    "AssemblyModes",
    "PlanarMode",
    "AssemblyFamily",
    "SpatialMode",
    "CertifiedMode",
]
