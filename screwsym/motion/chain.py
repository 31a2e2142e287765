r"""Serial chains by the product of exponentials: forward kinematics and Jacobians.

Explanation
===========

A serial chain of ``n`` one-degree-of-freedom joints is given by the joint
twists ``$_1 ... $_n`` at the home configuration, all in the space (base)
frame, and the home pose ``M`` of the end frame.  A revolute joint's twist is
the unit line vector of its axis ``(omega; r x omega)``, a prismatic joint's
is ``(0; v)`` with a unit ``v``, a helical joint's has pitch ``h``
``(omega; r x omega + h omega)``.  With joint variables ``q`` (angles, or
lengths for prismatic joints), Brockett's product of exponentials gives

    T(q) = exp6($_1, q_1) ... exp6($_n, q_n) M,

and the space Jacobian's column ``i`` is joint ``i``'s twist carried to the
current configuration, ``Ad(exp6($_1, q_1) ... exp6($_{i-1}, q_{i-1})) $_i``:
the twist of the current joint axis in ray order ``(omega; v_O)``, so that the
end body's twist is ``J_s(q) dq/dt``.  The body Jacobian has the same
columns expressed in the end frame, ``J_b = Ad(T(q)^-1) J_s``.

The results are exact SymPy expressions in ``q`` (symbols or numbers),
tidied without ``simplify``: each column is built from the current axis
direction and a current point of the axis (so the moment is one cross
product), and each entry is expanded, relieved of ``sin^2 + cos^2`` pairs and
its products of sines and cosines gathered into sines and cosines of sums
(SymPy's ``fu`` rule ``TR10i``).  For numbers over many poses, pass them to
:func:`screwsym.lambdify`.

References
==========

R. W. Brockett, "Robotic manipulators and the product of exponentials
formula", 1984.  Lynch & Park, *Modern Robotics*, Cambridge 2017, Sections
4.1 and 5.1.  Huang, Li & Ding, *Theory of Parallel Mechanisms*, Springer
2013, Section 1.6 (twists).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, TypeAlias

import numpy as np
from sympy import Expr, ImmutableMatrix, Rational, Tuple
from sympy.matrices import MatrixBase

from ..algebra.budget import BUDGET, charge
from ..core.basic import ScrewsymBasic
from ..core.checks import (
    check_choice,
    check_flag,
    check_instance,
    check_scalar,
    check_sequence,
)
from ..core.decide import is_zero_vector
from ..core.formulas import moved
from ..core.inertia import SpatialInertia
from ..core.screw import ScalarLike, ScrewLike, check_screw
from ..core.tidy import tidy
from ..core.twist import Twist
from . import _kinematics_program as _kp
from . import _poe
from . import dynamics as _dynamics
from . import newton_euler as _newton_euler
from . import parameters as _parameters
from .angles import RecognisedAngle, angle_step, warn_recognised
from .dh import dh_twists_and_home, recognise_dh_angles
from .displacement import exp6
from .transform import Transform
from .urdf import read_urdf

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["Chain", "ur5"]

#: joint values: a list or tuple of scalars (or a SymPy Tuple or matrix, a 1-d NumPy array)
JointValues: TypeAlias = Sequence[ScalarLike] | MatrixBase | np.ndarray


def _carried_column(T: Transform, twist: Twist) -> ImmutableMatrix:
    """``Ad(T) $``: the joint twist carried by the motion ``T``, ``(R w; R v + p x R w)``, tidied.

    The action of :func:`screwsym.core.formulas.moved`, equal to
    ``T.adjoint() * $.matrix``; each part is tidied.
    """
    w, v = moved(T.R, T.p, twist.omega, twist.v_O)
    return ImmutableMatrix.vstack(tidy(w), tidy(v))


class Chain(ScrewsymBasic):
    r"""A serial chain: joint twists at home, in the space frame, and the home pose.

    Explanation
    ===========

    ``args == (twists, home)``: a SymPy ``Tuple`` of :class:`~screwsym.core.twist.Twist`
    (revolute, prismatic or helical joints, base to tip) and the home
    :class:`~screwsym.motion.transform.Transform` ``M`` of the end frame.  See the
    module docstring for the formulas.  The joint twists need not be unit
    twists; a unit twist makes ``q`` an angle (revolute, helical) or a length
    (prismatic).

    Examples
    ========

    A planar two-link arm (links 1 and 1, both joints about z):

    >>> from sympy import symbols
    >>> from screwsym import Chain, Transform, Twist
    >>> q1, q2 = symbols("q1 q2", real=True)
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])],
    ...             Transform.translation([2, 0, 0]))
    >>> arm.forward([q1, q2]).p.T
    Matrix([[cos(q1) + cos(q1 + q2), sin(q1) + sin(q1 + q2), 0]])
    >>> arm.jacobian([q1, q2])
    Matrix([
    [0,        0],
    [0,        0],
    [1,        1],
    [0,  sin(q1)],
    [0, -cos(q1)],
    [0,        0]])
    >>> arm.jacobian([q1, q2], frame="body")[3:, :]
    Matrix([
    [    sin(q2), 0],
    [cos(q2) + 1, 1],
    [          0, 0]])

    Parameters
    ==========

    twists : sequence of Twist (or 6-vectors (omega; v_O))
        The joint twists at the home configuration, in the space frame.
    home : Transform, optional
        The end frame's pose at home (default the identity).
    inertias : sequence of SpatialInertia, optional
        One per link (link ``i`` is the body moved by joints ``1 .. i``), each in
        the SPACE frame at the home configuration ``q = 0``; needed by the
        dynamics (:meth:`inverse_dynamics`, :meth:`mass_matrix`, ...).  Without
        them the chain is purely kinematic, ``args == (twists, home)``; with them
        ``args == (twists, home, inertias)``.
    link_frames : sequence of Transform, optional
        When given, ``inertias[i]`` is expressed in link ``i``'s own frame, whose
        pose at home in the space frame is ``link_frames[i]`` (as Modern Robotics'
        ``M_0i``); each is carried to the space frame, ``link_frames[i].apply(inertias[i])``.

    See Also
    ========

    screwsym.motion.displacement.exp6, screwsym.motion.transform.Transform.adjoint
    """

    # the record of recognised angles (``recognised``), set once by the file readers
    __slots__ = ("_recognised",)

    def __new__(cls, twists: Sequence[ScrewLike], home: Transform | None = None,
                inertias: Sequence[SpatialInertia] | None = None, *,
                link_frames: Sequence[Transform] | None = None) -> Self:
        twists = check_sequence(twists, "twists", "twists")
        if len(twists) == 0:
            raise ValueError("twists: expected at least one joint twist, got none")
        joints = Tuple(*(check_screw(t, f"twists[{i}]", Twist) for i, t in enumerate(twists)))
        for i, t in enumerate(joints):
            if is_zero_vector(t.matrix) is True:
                raise ValueError(f"twists[{i}]: a joint twist cannot be zero, got {t}")
        home = Transform.identity() if home is None else check_instance(home, "home", Transform)
        if inertias is None:
            if link_frames is not None:
                raise ValueError("link_frames: given without inertias")
            return ScrewsymBasic.__new__(cls, joints, home)
        bodies = check_sequence(inertias, "inertias", "spatial inertias", len(joints))
        bodies = [check_instance(b, f"inertias[{i}]", SpatialInertia) for i, b in enumerate(bodies)]
        if link_frames is not None:
            frames = check_sequence(link_frames, "link_frames", "transforms", len(joints))
            bodies = [
                check_instance(T, f"link_frames[{i}]", Transform).apply(b)
                for i, (T, b) in enumerate(zip(frames, bodies, strict=True))
            ]
        return ScrewsymBasic.__new__(cls, joints, home, Tuple(*bodies))

    @classmethod
    def from_dh(cls, rows: Sequence[Sequence[ScalarLike]], convention: str = "standard",
                joints: str | Sequence[str] | None = None, *,
                base: Transform | None = None, tool: Transform | None = None,
                angles: str = "exact") -> Chain:
        r"""The chain of a Denavit–Hartenberg table of rows ``(a, alpha, d, theta)``.

        ``convention`` is ``"standard"`` (Denavit & Hartenberg 1955) or
        ``"modified"`` (Craig 1986/2005); ``joints`` is a string such as
        ``"RRPRRR"`` saying per row which entry is the variable (``R``: theta,
        ``P``: d; default all revolute).  Exact: see
        :func:`screwsym.motion.dh.dh_twists_and_home` for the conventions' table.

        ``angles="pi/12"`` reads float angles (``alpha``, ``theta``) that are
        multiples of pi/12 as those multiples, as :meth:`from_urdf` does, listed
        in :attr:`recognised` (:func:`screwsym.motion.dh.recognise_dh_angles`).

        >>> from sympy import pi
        >>> Chain.from_dh([(1, 0, 0, 0), (1, 0, 0, 0)]).home.p.T
        Matrix([[2, 0, 0]])
        """
        rows, found = recognise_dh_angles(rows, angles)
        warn_recognised(found, angle_step(angles) or 12)
        twists, home = dh_twists_and_home(rows, convention, joints, base=base, tool=tool)
        return cls(twists, home)._with_recognised(found)

    @classmethod
    def from_urdf(cls, source: Any, base: str | None = None, tip: str | None = None, *,
                  angles: str = "pi/12", angle_tol: ScalarLike | None = None,
                  inertias: bool = False, budget: int = BUDGET) -> Chain:
        r"""The chain of the serial path from link ``base`` to link ``tip`` of a URDF robot.

        ``source`` is a file path or the XML text.  Numbers are read exactly
        from their decimal text, but for the ``rpy`` angles that print a
        multiple of pi/12 to four or more decimal places (``1.5708``,
        ``-1.5707963``, ``1.5707963267948966``: pi/2), which are read as that
        multiple (the rule and why: :mod:`screwsym.motion.angles`); each such
        value is listed in :attr:`recognised` and in a
        :class:`~screwsym.motion.angles.RecognisedAngleWarning`.
        ``angles="exact"`` keeps every decimal as written; ``angles="pi/N"``
        recognises multiples of pi/N.  Needs ``defusedxml`` (``pip install -e
        ".[urdf]"``).  See :func:`screwsym.motion.urdf.urdf_twists_and_home`
        for the rules and the errors.

        With ``inertias=True`` the chain also carries each moving body's
        :class:`~screwsym.core.inertia.SpatialInertia`, in the space frame at
        home (:func:`screwsym.motion.urdf.read_inertials`), for the dynamics;
        a moving body without mass is then an error naming its joint, a link
        with an inertia that is provably not physical one naming the link.  By default
        (``inertias=False``) the kinematics alone are read, since many URDF
        files leave links without mass.  ``budget`` bounds the exact arithmetic
        of the reading (:func:`screwsym.motion.urdf.read_urdf`).

        >>> from screwsym.motion.urdf import TWO_LINK_URDF
        >>> Chain.from_urdf(TWO_LINK_URDF, angles="exact").n_joints
        2
        >>> Chain.from_urdf(TWO_LINK_URDF, angles="exact", inertias=True)
        Traceback (most recent call last):
        ...
        ValueError: source: the body moved by joint 'shoulder' (upper) has no mass; pass inertias=False to read the kinematics alone
        """
        read = read_urdf(source, base, tip, angles=angles, angle_tol=angle_tol,
                         inertials=check_flag(inertias, "inertias"), budget=budget)
        if read.inertials is None:
            return cls(twists=read.twists, home=read.home)._with_recognised(read.recognised)
        bodies = []
        for body in read.inertials:
            if body.mass == 0:
                raise ValueError(
                    f"source: the body moved by joint {body.joint!r} ({', '.join(body.links)}) "
                    "has no mass; pass inertias=False to read the kinematics alone"
                )
            # read_inertials checked each link's inertia where the file writes it (rational
            # entries); turned and summed (parallel axes) they stay physical: not checked again
            # on the turned entries (sines of the file's angles: minutes for SymPy's signs)
            bodies.append(SpatialInertia._new(body.mass, body.com, body.inertia))
        return cls(read.twists, read.home, bodies)._with_recognised(read.recognised)

    def _with_recognised(self, recognised: tuple[RecognisedAngle, ...]) -> Self:
        """Set the record of recognised angles, once, as the reader builds the chain."""
        self._recognised = tuple(recognised)
        return self

    @property
    def recognised(self) -> tuple[RecognisedAngle, ...]:
        """The decimal angles the file reader took for multiples of pi/N (``()`` if none).

        Each a :class:`~screwsym.motion.angles.RecognisedAngle` (the text as
        written, the element where it stood, the value used), in the order read.
        Set by :meth:`from_urdf` and :meth:`from_dh`; a chain built otherwise,
        or rebuilt from its ``args`` (``subs``, pickling), has none.
        """
        return getattr(self, "_recognised", ())

    @property
    def twists(self) -> tuple[Twist, ...]:
        """The joint twists at home, base to tip, in the space frame."""
        return tuple(self.args[0])

    @property
    def home(self) -> Transform:
        """The end frame's pose at the home configuration."""
        return self.args[1]

    @property
    def inertias(self) -> tuple[SpatialInertia, ...] | None:
        """The links' spatial inertias, in the space frame at home, or None for a kinematic chain."""
        return tuple(self.args[2]) if len(self.args) > 2 else None

    @property
    def n_joints(self) -> int:
        """The number of joints."""
        return len(self.args[0])

    def body_twists(self) -> tuple[Twist, ...]:
        """The joint twists at home in the end frame, ``Ad(M^-1) $_i``.

        >>> from screwsym import Chain, Transform, Twist
        >>> Chain([Twist([0, 0, 1], [0, 0, 0])], Transform.translation([1, 0, 0])).body_twists()
        (Twist([0, 0, 1], [0, 1, 0]),)
        """
        Minv = self.home.inverse()
        return tuple(Minv.apply(t) for t in self.twists)

    def _check_q(self, q: Any) -> tuple[Expr, ...]:
        values = check_sequence(q, "q", "joint values", self.n_joints)
        return tuple(check_scalar(v, f"q[{i}]") for i, v in enumerate(values))

    def forward(self, q: JointValues, *, budget: int = BUDGET, form: str = "tidy") -> Transform:
        r"""The forward kinematics ``T(q) = exp6($_1, q_1) ... exp6($_n, q_n) M``, tidied
        (``form="product"``: the untidied nested product instead, :func:`~screwsym.motion._kinematics_program.product_forward`).

        ``budget`` bounds the exact arithmetic (default
        :data:`~screwsym.algebra.budget.BUDGET`, 20,000,000 units of about a
        microsecond: a product of polynomials of ``a`` and ``b`` terms costs
        ``a b``, a term written back 60; the CPU time is bounded to ``SLACK``
        microseconds a unit).  Past it, a ``ValueError`` naming the method: a
        long chain with symbolic joint values grows fast, where
        :meth:`kinematics_program` grows linearly.

        >>> from sympy import pi, symbols
        >>> from screwsym import Chain, Transform, Twist
        >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0])], Transform.translation([1, 0, 0]))
        >>> arm.forward([pi/2])
        Transform(R=[[0, -1, 0], [1, 0, 0], [0, 0, 1]], p=[0, 1, 0])
        >>> arm.forward(symbols("q1", real=True, seq=True), budget=10)
        Traceback (most recent call last):
        ...
        ValueError: forward: the exact arithmetic needs more than budget=10 units (a long chain, or symbolic joint values with angles that are no multiple of pi/12); pass a larger budget, or use Chain.kinematics_program (Chain.dynamics_program for the dynamics) for a straight-line program that grows linearly
        """
        q = self._check_q(q)
        with _poe.bounded(budget, "forward"):
            if check_choice(form, "form", _kp.FORMS) == "product":
                return Transform._new(*_kp.product_forward(self.twists, self.home, q))
            fast = _poe.fast_forward(self.twists, self.home, q)
            if fast is not None:
                return Transform._new(*fast)
            return self._forward_stepwise(q)

    def _forward_stepwise(self, q: tuple[Expr, ...]) -> Transform:
        """The general path: each product of an exponential tidied (numbers, helical joints, ...)."""
        T = Transform.identity()
        for twist, qi in zip(self.twists, q, strict=True):
            charge(_poe.STEP_UNITS)
            T = tidy(T @ exp6(twist, qi))
        return tidy(T @ self.home)

    def jacobian(self, q: JointValues, frame: str = "space", *,
                 budget: int = BUDGET, form: str = "tidy") -> ImmutableMatrix:
        r"""The 6 x n Jacobian in ray order, ``frame="space"`` or ``"body"``, tidied (``form``: as in :meth:`forward`).

        Column ``i`` is joint ``i``'s twist at the configuration ``q``,
        ``(omega_i; v_i)``: in the space frame (moments about the base origin)
        for ``"space"``, in the end frame (moments about the end frame's origin)
        for ``"body"``.  The twist of the end body is ``J dq/dt``.  ``budget``
        bounds the exact arithmetic as in :meth:`forward` (default
        :data:`~screwsym.algebra.budget.BUDGET`); past it, a ``ValueError``
        naming ``jacobian``.

        >>> from sympy import symbols
        >>> from screwsym import Chain, Twist
        >>> q = symbols("q1 q2", real=True)
        >>> Chain([Twist([0, 0, 1], [0, 0, 0]), Twist([0, 0, 0], [1, 0, 0])]).jacobian(q)
        Matrix([
        [0,        0],
        [0,        0],
        [1,        0],
        [0,  cos(q1)],
        [0,  sin(q1)],
        [0,        0]])
        """
        q = self._check_q(q)
        frame = check_choice(frame, "frame", ("space", "body"))
        with _poe.bounded(budget, "jacobian"):
            if check_choice(form, "form", _kp.FORMS) == "product":
                return (_kp.product_space_jacobian(self.twists, q) if frame == "space"
                        else _kp.product_body_jacobian(self.body_twists(), q))
            if frame == "space":
                fast = _poe.fast_space_jacobian(self.twists, self.home, q)
            else:
                fast = _poe.fast_body_jacobian(self.body_twists(), self.home, q)
            if fast is not None:
                return fast
            return self._jacobian_stepwise(q, frame)

    def _jacobian_stepwise(self, q: tuple[Expr, ...], frame: str) -> ImmutableMatrix:
        """The general path of :meth:`jacobian`: each product tidied."""
        columns: list[ImmutableMatrix] = []
        T = Transform.identity()
        if frame == "space":
            for twist, qi in zip(self.twists, q, strict=True):
                charge(_poe.STEP_UNITS)
                columns.append(_carried_column(T, twist))
                T = tidy(T @ exp6(twist, qi))
        else:
            # J_b column i = Ad(exp6(B_n, -q_n) ... exp6(B_{i+1}, -q_{i+1})) B_i
            for twist, qi in zip(reversed(self.body_twists()), reversed(q), strict=True):
                charge(_poe.STEP_UNITS)
                columns.append(_carried_column(T, twist))
                T = tidy(T @ exp6(twist, -qi))
            columns.reverse()
        return ImmutableMatrix.hstack(*columns)

    def inverse_kinematics(self, T: Any, free: Any = (), *, budget: int = BUDGET) -> tuple:
        """Every closed-form branch (condition, q) reaching ``T``: :func:`screwsym.motion.inverse_kinematics.inverse_kinematics`."""
        from .inverse_kinematics import inverse_kinematics

        return inverse_kinematics(self, T, free, budget=budget)

    def _eval_evalf_parts(self, n: int = 15, **options: Any) -> Chain:
        """The chain with every number a float: ``chain.evalf()`` (numeric work is faster on it)."""
        parts = [Tuple(*(t.evalf(n, **options) for t in self.args[0])),
                 self.home.evalf(n, **options)]
        if self.inertias is not None:
            parts.append(Tuple(*(b.evalf(n, **options) for b in self.inertias)))
        return ScrewsymBasic.__new__(type(self), *parts)

    # ---------------------------------------------------------------- dynamics
    def inverse_dynamics(self, q: JointValues, qd: JointValues, qdd: JointValues,
                         gravity: Any = None, *, budget: int = BUDGET) -> ImmutableMatrix:
        """The joint torques by Newton–Euler: :func:`screwsym.motion.dynamics.inverse_dynamics` (``budget``: as there)."""
        return _dynamics.inverse_dynamics(self, q, qd, qdd, gravity, budget=budget)

    def mass_matrix(self, q: JointValues, *, budget: int = BUDGET) -> ImmutableMatrix:
        """The mass matrix by composite rigid bodies: :func:`screwsym.motion.dynamics.mass_matrix` (``budget``: as there)."""
        return _dynamics.mass_matrix(self, q, budget=budget)

    def coriolis_matrix(self, q: JointValues, qd: JointValues, *,
                        budget: int = BUDGET) -> ImmutableMatrix:
        """The Christoffel-form Coriolis matrix: :func:`screwsym.motion.dynamics.coriolis_matrix` (``budget``: as there)."""
        return _dynamics.coriolis_matrix(self, q, qd, budget=budget)

    def gravity_torques(self, q: JointValues, gravity: Any = None, *,
                        budget: int = BUDGET) -> ImmutableMatrix:
        """The gravity torques: :func:`screwsym.motion.dynamics.gravity_torques` (``budget``: as there)."""
        return _dynamics.gravity_torques(self, q, gravity, budget=budget)

    def regressor(self, q: JointValues, qd: JointValues, qdd: JointValues,
                  gravity: Any = None, *, budget: int = BUDGET) -> ImmutableMatrix:
        """The torques' regressor in the inertial parameters: :func:`screwsym.motion.dynamics.regressor` (``budget``: as there)."""
        return _dynamics.regressor(self, q, qd, qdd, gravity, budget=budget)

    def dynamics_program(self, what: str = "inverse_dynamics",
                         gravity: Any = None, **options: Any) -> _newton_euler.Program:
        """A straight-line program (customised Newton–Euler): :func:`screwsym.motion.newton_euler.dynamics_program`;
        with ``parameters="base"`` (and ``extras=``), :func:`screwsym.motion.parameters.base_program`."""
        if options.get("parameters") == "base":
            return _parameters.base_program(self, what, gravity, **{
                k: v for k, v in options.items() if k != "parameters"})
        return _newton_euler.dynamics_program(self, what, gravity, **options)

    def kinematics_program(self, what: str = "forward") -> _newton_euler.Program:
        """``T(q)`` or the space Jacobian as a straight-line program, linear in the joints: :func:`screwsym.motion._kinematics_program.kinematics_program`."""
        from ._kinematics_program import kinematics_program

        return kinematics_program(self, what)

    def parameters(self, numbers: bool = False, extras: Sequence[str] = ()) -> ImmutableMatrix:
        """The 10n standard inertial parameters (symbols, or the chain's numbers): :func:`screwsym.motion.parameters.parameters`."""
        return _parameters.parameters(self, numbers, extras)

    def base_parameters(self, gravity: Any = None, extras: Sequence[str] = ()) -> ImmutableMatrix:
        """The base parameters, exact linear combinations of :meth:`parameters`: :func:`screwsym.motion.parameters.base_parameters`."""
        return _parameters.base_parameters(self, gravity, extras).parameters

    def base_regressor(self, q: JointValues, qd: JointValues, qdd: JointValues,
                       gravity: Any = None, extras: Sequence[str] = ()) -> ImmutableMatrix:
        """The n x b base regressor, ``base_regressor @ base_parameters == regressor @ parameters``: :func:`screwsym.motion.parameters.base_regressor`."""
        return _parameters.base_regressor(self, q, qd, qdd, gravity, extras)

    def _sympystr(self, printer: Any) -> str:
        twists = ", ".join(printer._print(t) for t in self.twists)
        if self.inertias is None:
            return f"Chain([{twists}], {printer._print(self.home)})"
        bodies = ", ".join(printer._print(b) for b in self.inertias)
        return f"Chain([{twists}], {printer._print(self.home)}, inertias=[{bodies}])"


def ur5() -> Chain:
    r"""The UR5 arm of Lynch & Park, *Modern Robotics*, Example 4.5, exact.

    Six revolute joints given by their twists in the space frame at the home
    pose, in ray order ``(omega; v_O)``, with the example's dimensions in
    metres as exact rationals (W1 = 109/1000, W2 = 82/1000, L1 = 425/1000,
    L2 = 392/1000, H1 = 89/1000, H2 = 95/1000).  The screw axes are the
    example's table: joint 6 is ``(0, 1, 0; H2 - H1, 0, L1 + L2)``, the flange's
    own z-axis through the flange origin ``(L1 + L2, W1 + W2, H1 - H2)``
    (up to version 0.2.0 this function gave it ``H2 - W2``, a slip that moved the
    flange 6 mm when joint 6 turned).

    >>> from screwsym.motion.chain import ur5
    >>> arm = ur5()
    >>> arm.n_joints, arm.home.matrix[:3, 3].T
    (6, Matrix([[817/1000, 191/1000, -3/500]]))
    >>> arm.twists[1]
    Twist([0, 1, 0], [-89/1000, 0, 0])
    >>> arm.twists[5]
    Twist([0, 1, 0], [3/500, 0, 817/1000])
    """
    w1, w2, l1, l2, h1, h2 = (Rational(x, 1000) for x in (109, 82, 425, 392, 89, 95))
    home = [[-1, 0, 0, l1 + l2], [0, 0, 1, w1 + w2], [0, 1, 0, h1 - h2], [0, 0, 0, 1]]
    screws = [
        (0, 0, 1, 0, 0, 0),
        (0, 1, 0, -h1, 0, 0),
        (0, 1, 0, -h1, 0, l1),
        (0, 1, 0, -h1, 0, l1 + l2),
        (0, 0, -1, -w1, l1 + l2, 0),
        (0, 1, 0, h2 - h1, 0, l1 + l2),
    ]
    return Chain([Twist.from_matrix(s) for s in screws], Transform.from_matrix(home))
