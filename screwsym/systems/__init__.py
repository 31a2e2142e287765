r"""Screw systems, kinematic pairs, and the mobility of parallel mechanisms and of any linkage.

Built on :mod:`screwsym.core` alone (Huang, Li & Ding, Chapters 2 and 5).  A
sibling of :mod:`screwsym.motion`: neither imports the other.
"""

from .graph import Mechanism, MechanismMobility, SecondOrder, lie_bracket
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
from .mechanism import (
    Degenerate,
    Limb,
    Mobility,
    MotionType,
    ParallelMechanism,
    motion_of,
    motion_type,
)
from .screw_system import ScrewSystem

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
]
