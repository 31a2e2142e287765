r"""URDF robots to product-of-exponentials chains, read exactly and parsed safely.

Explanation
===========

:meth:`Chain.from_urdf <screwsym.motion.chain.Chain.from_urdf>` (:func:`urdf_twists_and_home`) reads a URDF file (a path, or
the XML text) and builds the :class:`~screwsym.motion.chain.Chain` of the
serial path from the link ``base`` to the link ``tip``:

- **joints**: ``revolute`` and ``continuous`` (a unit rotation twist about the
  joint's axis through the joint frame's origin), ``prismatic`` (a unit
  translation twist along the axis) and ``fixed`` (no joint: its origin is
  folded into the next frame).  ``floating`` and ``planar`` joints, joints with
  ``<mimic>`` and a link that is the child of two joints (a closed loop) are
  refused with a ``ValueError`` naming the element, *when they are on the
  path*; elsewhere in the file they are not looked at (the Panda's mimic
  finger joint is fine for a chain that ends at the hand).
- **frames**: a joint's ``<origin xyz="x y z" rpy="r p y"/>`` is the child
  link's frame in the parent link's frame, ``T = (R, xyz)`` with the
  fixed-axis X-Y-Z rotation ``R = Rz(y) Ry(p) Rx(r)`` (the URDF
  specification); the joint variable is 0 there.  The joint ``<axis xyz>`` is in
  the joint (child) frame; default ``1 0 0``; an axis that is not exactly of
  length 1 is divided by its (exact) length.
- **home and joint variables**: the home pose is the ``tip`` link's frame at
  ``q = 0``, and the joints are ordered base to tip: ``q_i`` is the URDF joint
  value (radians, metres).
- **numbers** are read exactly from their decimal text: ``0.089159`` is
  ``Rational("0.089159") = 89159/1000000``, ``2.7518e-02`` is
  ``13759/500000``; the text must be a decimal number (no expressions), and is
  never passed through a float or evaluated.
- **angles** (``rpy``) are a policy, chosen by the ``angles`` keyword:
  ``"exact"`` (the default) keeps the decimal as written, so that
  ``1.5707963267948966`` is that rational number, not pi/2 (exact, but the
  trigonometry of such numbers makes long expressions); ``"pi/N"`` (opt-in,
  ``N`` a positive integer, e.g. ``"pi/12"``) replaces an rpy angle ``x``
  that lies within ``angle_tol`` (default ``10**-9`` rad) of a multiple
  ``k pi/N`` by that multiple, and keeps every other angle as written; an angle
  within 10**-3 of a multiple but outside ``angle_tol`` is kept as written
  with a ``UserWarning`` that names the joint (``1.5708`` written to five digits
  is not silently taken for pi/2, nor silently left alone).  Only rpy angles
  are ever changed; lengths, axes and inertias are always as written.

:func:`read_inertials` reads the links' ``<inertial>`` data along the same
path: per moving body (the links that joint ``i`` moves, merged across
``fixed`` joints, massless links such as an ``ee_link`` contributing nothing)
the exact mass, centre of mass and inertia about the centre of mass, in the
space frame at home.

XML is parsed with ``defusedxml`` (an optional dependency: ``pip install -e
".[urdf]"``), which refuses external entities and entity-expansion bombs; its
``DefusedXmlException`` (a ``ValueError``) is raised as it comes.  Names in the
file (robot, links, joints) are kept as data: they appear in error messages
and in :func:`read_inertials`' records, never in code.

References
==========

The URDF specification, http://wiki.ros.org/urdf/XML (joint, link, origin
and inertial elements).  Lynch & Park, *Modern Robotics*, Cambridge 2017,
Section 4.1.3 (the product of exponentials from a robot description).
"""

from __future__ import annotations

import importlib
import importlib.resources
import math
import os
import re
import stat
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any, NamedTuple

from sympy import Add, Expr, ImmutableMatrix, Rational, S, cos, pi, sin, sqrt, zeros

from ..algebra.budget import BUDGET, bounded, charge
from ..core.checks import check_count, check_scalar
from ..core.inertia import check_inertia_tensor
from ..core.screw import ScalarLike
from ..core.tidy import tidy
from ..core.twist import Twist
from .angles import (
    MIN_PLACES,
    RecognisedAngle,
    angle_step,
    constant_trig_normal,
    recognise_decimal,
    warn_recognised,
)
from .transform import Transform

__all__ = ["urdf_twists_and_home", "read_inertials", "read_urdf", "UrdfRobot", "LinkInertial",
           "path_joints", "sample_urdf", "SAMPLES", "MAX_NUMBER_CHARS", "MAX_EXPONENT", "MAX_FILE_BYTES"]

#: a decimal number as URDF writes one (ASCII digits only; no expressions, no nan/inf)
_DECIMAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?", re.ASCII)
#: the longest number text read (characters) and the largest decimal exponent: a 12-character
#: ``1e99999999`` would otherwise be a 100-million-digit integer
MAX_NUMBER_CHARS = 100
MAX_EXPONENT = 300
#: a larger angle (radians) is kept as written, never compared with multiples of pi/N
_LARGEST_ANGLE = 10**4
#: an angle this close to a multiple, but not recognised, is warned about
_NEAR_MISS = 1e-3
#: units of the budget (about a microsecond each) per product of two terms in a frame product
_UNITS_PER_PRODUCT = 200
#: the joint types on a path
_MOVING = ("revolute", "continuous", "prismatic")
_SUPPORTED = _MOVING + ("fixed",)

_INSTALL = 'pip install -e ".[urdf]"'


def _etree() -> Any:
    try:
        ElementTree = importlib.import_module("defusedxml.ElementTree")
    except ImportError as error:  # pragma: no cover - exercised without the extra
        raise ImportError(
            "reading URDF needs the package defusedxml (a safe XML parser): "
            f"install it with {_INSTALL} (or pip install defusedxml)") from error
    return ElementTree


def _number(text: str | None, where: str) -> Rational:
    """The exact rational of a decimal text such as ``0.089159`` or ``2.7518e-02``.

    ASCII digits only, at most ``MAX_NUMBER_CHARS`` characters and a decimal
    exponent of at most ``MAX_EXPONENT`` in size (the number itself, not the
    exponent as written: ``0.000e400`` is refused, ``1e-300`` is read).
    """
    if text is None or not _DECIMAL.fullmatch(text.strip()):
        raise ValueError(f"{where}: expected a decimal number, got {text!r}")
    text = text.strip()
    if len(text) > MAX_NUMBER_CHARS:
        raise ValueError(f"{where}: expected a decimal number of at most {MAX_NUMBER_CHARS} "
                         f"characters, got one of {len(text)}")
    mantissa, _, exponent = text.lower().partition("e")
    if exponent and abs(int(exponent)) > MAX_EXPONENT:
        raise ValueError(f"{where}: expected a decimal exponent of at most {MAX_EXPONENT} in size, "
                         f"got {text!r}")
    return Rational(text)


def _texts(text: str | None, where: str, count: int, default: str) -> list[str]:
    if text is None:
        text = default
    parts = text.split()
    if len(parts) != count:
        raise ValueError(f"{where}: expected {count} decimal numbers, got {text!r}")
    return parts


def _numbers(text: str | None, where: str, count: int, default: str) -> list[Rational]:
    return [_number(p, where) for p in _texts(text, where, count, default)]


class _AnglePolicy:
    """``"exact"``, or recognising multiples of pi/N (printed precision, or within ``angle_tol``).

    Keeps the :class:`RecognisedAngle` records of the values it changed, in order.
    """

    def __init__(self, angles: Any, angle_tol: Any) -> None:
        self.n = angle_step(angles)
        self.tol: float | None = None
        if angle_tol is not None:
            tol = check_scalar(angle_tol, "angle_tol")
            if not tol.is_number or not (0 < tol < Rational(1, 10**3)):
                raise ValueError(f"angle_tol: expected a number in (0, 1/1000), got {angle_tol!r}")
            self.tol = float(tol)
        self.recognised: list[RecognisedAngle] = []

    def __call__(self, text: str, where: str) -> Expr:
        x = _number(text, where)
        if self.n is None or x == 0 or abs(x) > _LARGEST_ANGLE:
            return x  # (an angle of 10**4 radians or more is no printing of a multiple of pi)
        if self.tol is None:
            target = recognise_decimal(text, self.n)
        else:
            k = round(float(x) * self.n / math.pi)
            target = k * pi / self.n
            if abs(float((x - target).evalf(30))) > self.tol:
                target = None
        if target is not None:
            self.recognised.append(RecognisedAngle(text.strip(), where, target))
            return target
        k = round(float(x) * self.n / math.pi)
        gap = abs(float((x - k * pi / self.n).evalf(30)))
        if gap <= _NEAR_MISS and k != 0:
            warnings.warn(
                f"{where}: the angle {text.strip()} is {gap:.1e} from {k * pi / self.n} but is "
                f"not a printing of it to {MIN_PLACES} or more decimal places: kept as written",
                UserWarning, stacklevel=5)
        return x

    def report(self) -> tuple[RecognisedAngle, ...]:
        """The recognised values, each once (the inertials walk the joints' origins again)."""
        return tuple(dict.fromkeys(self.recognised))

    def warn(self) -> None:
        """One :class:`RecognisedAngleWarning` listing what was recognised (if anything)."""
        warn_recognised(self.report(), self.n or 12, stacklevel=4)


#: the error past the budget of reading a file's frames (:func:`_bounded`)
_MESSAGE = ("{name}: the exact arithmetic of the file's frames needs more than budget={budget} "
            "units (sines of many angles that are no multiple of pi/12: they are kept exact); "
            "pass a larger budget")


@contextmanager
def _bounded(budget: int, name: str) -> Iterator[None]:
    """The frames' exact arithmetic within ``budget`` (:mod:`screwsym.algebra.budget`)."""
    with bounded(budget, name, _MESSAGE):
        yield


def _exact(M: ImmutableMatrix) -> ImmutableMatrix:
    """``M`` in a normal form that does not grow from frame to frame.

    Numbers built from square roots (the frames of a robot at 15-degree multiples, in
    Q(sqrt 2, sqrt 3)) come out as ``a + b sqrt 2 + c sqrt 3 + d sqrt 6``
    (:mod:`screwsym.algebra.numberfield`, through ``tidy``: a 7-joint robot at 15 degrees,
    105 s before, 0.06 s with it).  Numbers with sines and cosines of angles that are no
    multiple of pi/12 (the SO-100's ``-1.8``) are expanded polynomials in those sines and
    cosines reduced on their circles (:func:`~screwsym.motion.angles.constant_trig_normal`),
    where ``tidy`` would leave them nested one level deeper per frame.
    """
    flat = constant_trig_normal(list(M))
    return tidy(M) if flat is None else ImmutableMatrix(M.rows, M.cols, flat)


def _product(A: ImmutableMatrix, B: ImmutableMatrix) -> ImmutableMatrix:
    """``A B`` in :func:`_exact`'s normal form, its expansion charged to the budget first."""
    a = [len(Add.make_args(e)) for e in A]
    b = [len(Add.make_args(e)) for e in B]
    if max(a) > 1 and max(b) > 1:
        charge(_UNITS_PER_PRODUCT * sum(a[i * A.cols + k] * b[k * B.cols + j]
                                        for i in range(A.rows) for j in range(B.cols)
                                        for k in range(A.cols)))
    return _exact(A * B)


def _compose(A: Transform, B: Transform) -> Transform:
    """``A @ B`` (first ``B``, then ``A``) with :func:`_product`'s arithmetic."""
    return Transform._new(_product(A.R, B.R), _product(A.R, B.p) + A.p)


def _rpy_matrix(r: Expr, p: Expr, y: Expr) -> ImmutableMatrix:
    """``Rz(y) Ry(p) Rx(r)``, the URDF fixed-axis X-Y-Z rotation."""
    cr, sr, cp, sp, cy, sy = cos(r), sin(r), cos(p), sin(p), cos(y), sin(y)
    Rz = ImmutableMatrix([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    Ry = ImmutableMatrix([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    Rx = ImmutableMatrix([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    return _exact(Rz * Ry * Rx)


def _origin(element: Any, where: str, policy: _AnglePolicy) -> Transform:
    """The transform of an ``<origin>`` child of ``element`` (identity when absent)."""
    origin = element.find("origin")
    if origin is None:
        return Transform.identity()
    xyz = _numbers(origin.get("xyz"), f"{where}: <origin xyz>", 3, "0 0 0")
    rpy_where = f"{where}: <origin rpy>"
    texts = _texts(origin.get("rpy"), rpy_where, 3, "0 0 0")
    rpy = [policy(a, f"{rpy_where} {part}") for a, part in zip(texts, ("roll", "pitch", "yaw"), strict=True)]
    return Transform._new(_rpy_matrix(*rpy), ImmutableMatrix(xyz))


#: the largest URDF file read, in bytes (the largest example-robot-data file is under 1 MB)
MAX_FILE_BYTES = 64 * 2**20
#: byte-order marks that say the encoding (expat reads them and the XML declaration)
_BOMS = (b"\xef\xbb\xbf", b"\xff\xfe", b"\xfe\xff")


def _file_bytes(path: Path) -> bytes:
    """The bytes of a regular file of at most MAX_FILE_BYTES, or a ValueError naming the path."""
    try:
        info = path.stat()
    except OSError as error:
        raise ValueError(f"source: no URDF file at {str(path)!r} ({error.strerror}); "
                         "XML text must start with '<'") from None
    if not stat.S_ISREG(info.st_mode):
        raise ValueError(f"source: expected a regular file, got {str(path)!r} "
                         "(a directory, device or pipe)")
    if info.st_size > MAX_FILE_BYTES:
        raise ValueError(f"source: the file {str(path)!r} has {info.st_size} bytes, more than "
                         f"{MAX_FILE_BYTES} (MAX_FILE_BYTES)")
    with path.open("rb") as f:
        data = f.read(MAX_FILE_BYTES + 1)
    if len(data) > MAX_FILE_BYTES:
        raise ValueError(f"source: the file {str(path)!r} grew past {MAX_FILE_BYTES} bytes")
    return data


def _xml_of(source: Any) -> str | bytes:
    """The XML of ``source`` (a path, the text, or its bytes), as the parser takes it.

    Bytes keep their encoding, read by the parser from a byte-order mark or the
    XML declaration (UTF-16, latin-1, ...); a leading UTF-8 byte-order mark or
    white space is allowed before the XML.
    """
    if isinstance(source, os.PathLike):
        data = _file_bytes(Path(source))
    elif isinstance(source, bytes | bytearray):
        data = bytes(source)
    elif isinstance(source, str):
        text = source.lstrip("\ufeff \t\r\n")
        if text.startswith("<"):
            return text
        if not source.strip():
            raise ValueError("source: expected a URDF file path or its XML text, got an empty string")
        if "<" in source or "\n" in source:
            raise ValueError(f"source: expected a URDF file path or XML text starting with '<', "
                             f"got {source[:40]!r}...")
        data = _file_bytes(Path(source))
    else:
        raise TypeError(f"source: expected a URDF file path or its XML text, got {type(source).__name__}")
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    if not data.startswith(_BOMS[1:]):
        data = data.lstrip(b" \t\r\n")
    if not data:
        raise ValueError("source: the URDF is empty")
    return data


class _Joint(NamedTuple):
    name: str
    type: str
    parent: str
    child: str
    element: Any


class _Robot:
    """The links and joints of a URDF ``<robot>`` element, as data."""

    def __init__(self, source: Any) -> None:
        ElementTree = _etree()
        try:
            root = ElementTree.fromstring(_xml_of(source))
        except ElementTree.ParseError as error:
            raise ValueError(f"source: not well-formed XML: {error}") from None
        if root.tag != "robot":
            raise ValueError(f"source: expected a <robot> root element, got <{root.tag}>")
        self.name = root.get("name", "")
        self.links: dict[str, Any] = {}
        for link in root.findall("link"):
            name = link.get("name")
            if not name:
                raise ValueError("source: a <link> without a name")
            if name in self.links:
                raise ValueError(f"source: two <link> elements named {name!r}")
            self.links[name] = link
        self.joints: dict[str, _Joint] = {}
        self.parent_joint: dict[str, list[_Joint]] = {}
        self.child_joints: dict[str, list[_Joint]] = {}
        for element in root.findall("joint"):
            name = element.get("name")
            if not name:
                raise ValueError("source: a <joint> without a name")
            if name in self.joints:
                raise ValueError(f"source: two <joint> elements named {name!r}")
            parent, child = element.find("parent"), element.find("child")
            if parent is None or child is None or not parent.get("link") or not child.get("link"):
                raise ValueError(f"<joint name={name!r}>: expected <parent link=...> and <child link=...>")
            joint = _Joint(name, element.get("type", ""), parent.get("link"), child.get("link"), element)
            for end in (joint.parent, joint.child):
                if end not in self.links:
                    raise ValueError(f"<joint name={name!r}>: no <link> named {end!r}")
            self.joints[name] = joint
            self.parent_joint.setdefault(joint.child, []).append(joint)
            self.child_joints.setdefault(joint.parent, []).append(joint)

    def roots(self) -> list[str]:
        return [n for n in self.links if n not in self.parent_joint]

    def path(self, base: str | None, tip: str | None) -> tuple[str, str, list[_Joint]]:
        """The joints from ``base`` down to ``tip``, checked (base, tip, joints)."""
        if base is None:
            roots = self.roots()
            if len(roots) != 1:
                raise ValueError(f"base: the file has {len(roots)} root links {roots}; name one")
            base = roots[0]
        if tip is None:
            leaves = [n for n in self.links if n not in self.child_joints]
            if len(leaves) != 1:
                raise ValueError(f"tip: the file has {len(leaves)} leaf links {leaves}; name one")
            tip = leaves[0]
        for arg, name in (("base", base), ("tip", tip)):
            if not isinstance(name, str):
                raise TypeError(f"{arg}: expected a link name (str), got {type(name).__name__}")
            if name not in self.links:
                raise ValueError(f"{arg}: no <link> named {name!r} in robot {self.name!r}")
        joints: list[_Joint] = []
        link = tip
        while link != base:
            parents = self.parent_joint.get(link, [])
            if len(parents) > 1:
                names = [j.name for j in parents]
                raise ValueError(f"<link name={link!r}>: the child of {len(parents)} joints {names} "
                                 f"(a closed loop): a serial chain cannot be read through it")
            if not parents:
                raise ValueError(f"tip: the link {tip!r} is not below the link {base!r}")
            joint = parents[0]
            if joints and any(j.name == joint.name for j in joints):  # pragma: no cover - cycle
                raise ValueError(f"<joint name={joint.name!r}>: the joints form a cycle")
            joints.append(joint)
            link = joint.parent
            if len(joints) > len(self.joints):
                raise ValueError(f"<joint name={joint.name!r}>: the joints form a cycle")
        joints.reverse()
        for joint in joints:
            where = f"<joint name={joint.name!r} type={joint.type!r}>"
            if joint.type not in _SUPPORTED:
                raise ValueError(f"{where}: only revolute, continuous, prismatic and fixed joints "
                                 f"can be on the path from {base!r} to {tip!r}")
            if joint.element.find("mimic") is not None:
                raise ValueError(f"{where}: a <mimic> joint on the path from {base!r} to {tip!r} "
                                 f"is not an independent joint; a chain cannot hold it")
        return base, tip, joints


def _axis(joint: _Joint) -> ImmutableMatrix:
    where = f"<joint name={joint.name!r}>: <axis xyz>"
    element = joint.element.find("axis")
    axis = ImmutableMatrix(_numbers(None if element is None else element.get("xyz"), where, 3, "1 0 0"))
    norm2 = axis.dot(axis)
    if norm2 == 0:
        raise ValueError(f"{where}: expected a non-zero axis, got {list(axis)}")
    return axis if norm2 == 1 else tidy(axis / sqrt(norm2))


def _walk(robot: _Robot, joints: list[_Joint], policy: _AnglePolicy) -> list[tuple[_Joint, Transform]]:
    """Each joint on the path with its frame (the child link's frame) at home."""
    T = Transform.identity()
    frames = []
    for joint in joints:
        T = _compose(T, _origin(joint.element, f"<joint name={joint.name!r}>", policy))
        frames.append((joint, T))
    return frames


def path_joints(source: Any, base: str | None = None, tip: str | None = None) -> tuple[str, ...]:
    """The names of the moving joints on the path from ``base`` to ``tip``: the chain's joint order.

    >>> from screwsym.motion.urdf import path_joints
    >>> path_joints(TWO_LINK_URDF)
    ('shoulder', 'elbow')
    """
    robot = _Robot(source)
    _, _, joints = robot.path(base, tip)
    return tuple(j.name for j in joints if j.type in _MOVING)


def urdf_twists_and_home(source: Any, base: str | None = None, tip: str | None = None, *,
                         angles: str = "pi/12",
                         angle_tol: ScalarLike | None = None) -> tuple[list[Twist], Transform]:
    r"""The joint twists and home pose of the path from link ``base`` to link ``tip``.

    Explanation
    ===========

    ``source`` is a URDF file path (``str`` or ``os.PathLike``) or its XML
    text (a ``str`` starting with ``<``, or ``bytes``); ``base`` defaults to
    the root link, ``tip`` to the only leaf link (an error lists them when
    there are several).  The joint twists are in ``base``'s frame, in ray
    order ``(omega; v_O)``, one per moving joint on the path, base to tip (their
    names: :func:`path_joints`); the home pose is ``tip``'s frame at ``q = 0``.
    See the module docstring for what is read, the angle policy (``angles``,
    ``angle_tol``) and what is refused.  Use it as :meth:`Chain.from_urdf
    <screwsym.motion.chain.Chain.from_urdf>`, which makes the chain of these parts.

    Examples
    ========

    >>> from screwsym import Chain
    >>> print(TWO_LINK_URDF)
    <robot name="two_link">
      <link name="base"/> <link name="upper"/> <link name="fore"/>
      <link name="hand">
        <inertial>
          <mass value="2"/> <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.03"/>
        </inertial>
      </link>
      <joint name="shoulder" type="revolute">
        <parent link="base"/> <child link="upper"/>
        <origin xyz="0 0 0.089159"/> <axis xyz="0 1 0"/>
      </joint>
      <joint name="elbow" type="continuous">
        <parent link="upper"/> <child link="fore"/>
        <origin xyz="0.425 0 0" rpy="0 0 1.5707963267948966"/> <axis xyz="0 0 1"/>
      </joint>
      <joint name="wrist_flange" type="fixed">
        <parent link="fore"/> <child link="hand"/> <origin xyz="0.1 0 0"/>
      </joint>
    </robot>
    >>> import warnings
    >>> from screwsym.motion.angles import RecognisedAngleWarning
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", RecognisedAngleWarning)   # (it lists what .recognised does)
    ...     arm = Chain.from_urdf(TWO_LINK_URDF)
    >>> arm.recognised
    (RecognisedAngle(text='1.5707963267948966', element="<joint name='elbow'>: <origin rpy> yaw", value=pi/2),)
    >>> arm.twists
    (Twist([0, 1, 0], [-89159/1000000, 0, 0]), Twist([0, 0, 1], [0, -17/40, 0]))
    >>> arm.home.matrix
    Matrix([
    [0, -1, 0,       17/40],
    [1,  0, 0,        1/10],
    [0,  0, 1, 89159/1000000],
    [0,  0, 0,           1]])

    With ``angles="exact"`` the angle is the decimal as written, exactly:

    >>> Chain.from_urdf(TWO_LINK_URDF, angles="exact").home.R[0, 0]
    cos(7853981633974483/5000000000000000)

    Parameters
    ==========

    source : str, os.PathLike or bytes
    base, tip : str, optional
        Link names.
    angles : ``"pi/12"`` (default), ``"pi/N"`` or ``"exact"``
        Recognise rpy decimals that print a multiple of pi/N (the rule:
        :mod:`screwsym.motion.angles`), or keep every decimal as written.
    angle_tol : number, optional
        Instead of the printed-precision rule, recognise an angle within this
        many radians of a multiple of pi/N; in (0, 10**-3).

    References
    ==========

    The URDF specification (joint and origin elements); Lynch & Park 2017, Section 4.1.3.
    """
    policy = _AnglePolicy(angles, angle_tol)
    robot = _Robot(source)
    with _bounded(BUDGET, "urdf_twists_and_home"):
        twists, home = _twists_and_home(robot, *robot.path(base, tip), policy)
    policy.warn()
    return twists, home


def _twists_and_home(robot: _Robot, base: str, tip: str, joints: list[_Joint],
                     policy: _AnglePolicy) -> tuple[list[Twist], Transform]:
    twists = []
    T = Transform.identity()
    for joint, T in _walk(robot, joints, policy):
        if joint.type in _MOVING:
            direction = _product(T.R, _axis(joint))
            twists.append(Twist.translation(direction) if joint.type == "prismatic"
                          else Twist(direction, _exact(T.p.cross(direction))))
    if not twists:
        raise ValueError(f"tip: the path from {base!r} to {tip!r} has no moving joint")
    return twists, T


class LinkInertial(NamedTuple):
    """The inertia of the body a joint moves, in the space frame at home (exact).

    ``joint``: the joint's name; ``links``: the links merged into the body;
    ``mass``; ``com``: the centre of mass, a 3x1 matrix (the zero vector for a
    massless body); ``inertia``: the 3x3 inertia matrix about the centre of
    mass, in the space frame's axes.
    """

    joint: str
    links: tuple[str, ...]
    mass: Expr
    com: ImmutableMatrix
    inertia: ImmutableMatrix


def _link_inertial(robot: _Robot, name: str, T: Transform,
                   policy: _AnglePolicy) -> tuple[Expr, ImmutableMatrix, ImmutableMatrix] | None:
    """A link's (mass, com, inertia about com) in the space frame, for its frame ``T``; None if none."""
    inertial = robot.links[name].find("inertial")
    if inertial is None:
        return None
    where = f"<link name={name!r}>: <inertial>"
    mass_el = inertial.find("mass")
    mass = _number(None if mass_el is None else mass_el.get("value"), f"{where} <mass value>")
    if mass < 0:
        raise ValueError(f"{where} <mass value>: expected a mass >= 0, got {mass}")
    if mass == 0:
        return None
    frame = _compose(T, _origin(inertial, where, policy))
    el = inertial.find("inertia")
    keys = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
    if el is None:
        raise ValueError(f"{where}: expected an <inertia> element")
    ixx, ixy, ixz, iyy, iyz, izz = (_number(el.get(k), f"{where} <inertia {k}>") for k in keys)
    I_local = ImmutableMatrix([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
    # physical where the file writes it, in the inertial frame (rational entries: decided
    # at once); the turn R I R^T keeps the eigenvalues, so the turned inertia is physical too
    check_inertia_tensor(I_local, f"{where} <inertia>")
    R = frame.R
    return mass, frame.p, _exact(R * I_local * R.T)


def read_inertials(source: Any, base: str | None = None, tip: str | None = None, *,
                   angles: str = "pi/12",
                   angle_tol: ScalarLike | None = None) -> tuple[LinkInertial, ...]:
    r"""The inertia of each moving body on the path from ``base`` to ``tip``, exact, at home.

    Explanation
    ===========

    One :class:`LinkInertial` per moving joint of ``Chain.from_urdf``'s
    chain, in the same order: the body is the joint's child link together with
    every link attached to it through ``fixed`` joints (on the path or off it)
    and every link behind a joint off the path, locked at that joint's zero
    position (the Panda's fingers are part of its last body, as in pinocchio's
    model with those joints at zero and at rest).  A link's ``<inertial>`` gives its mass
    ``m``, its centre of mass ``c`` (the inertial origin) and its inertia
    ``I`` about ``c`` in the inertial frame; in the space frame at home these are
    ``c_s = T c`` and ``I_s = R I R^T`` (``T`` the inertial frame at home, ``R`` its
    rotation).  Merged links add up: ``m = sum m_k``, ``c = sum m_k c_k / m``,
    ``I = sum (I_k + m_k (|d_k|^2 E - d_k d_k^T))`` with ``d_k = c_k - c``
    (Steiner's parallel-axis theorem); a massless link (``mass 0`` or no
    ``<inertial>``) adds nothing.  ``angles`` applies to the inertial origins'
    ``rpy`` as to the joints'.

    Examples
    ========

    >>> from screwsym.motion.urdf import read_inertials
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")      # the RecognisedAngleWarning of pi/2
    ...     body = read_inertials(TWO_LINK_URDF)[1]
    >>> body.joint, body.links, body.mass
    ('elbow', ('fore', 'hand'), 2)
    >>> body.com.T
    Matrix([[17/40, 1/10, 89159/1000000]])
    >>> body.inertia              # the hand's, turned a quarter-turn about z
    Matrix([
    [1/50,     0,     0],
    [   0, 1/100,     0],
    [   0,     0, 3/100]])

    References
    ==========

    The URDF specification (inertial element); Featherstone, *Rigid Body
    Dynamics Algorithms*, Springer 2008, Section 2.13 (moving and adding inertias).
    """
    policy = _AnglePolicy(angles, angle_tol)
    robot = _Robot(source)
    _, _, joints = robot.path(base, tip)
    with _bounded(BUDGET, "read_inertials"):
        out = _inertials(robot, joints, policy)
    policy.warn()
    return out


def _body_parts(robot: _Robot, joint: _Joint, T0: Transform, on_path: set[str],
                policy: _AnglePolicy) -> list[tuple[str, Transform]]:
    """The links of the body joint moves with their frames: its child, and every link below it
    through fixed joints and joints off the path (locked at zero: the Panda's fingers).  Each
    link is reached once: a link that is the child of two joints, or a cycle, is refused."""
    parts: list[tuple[str, Transform]] = []
    seen: set[str] = set()
    stack = [(joint.child, T0)]
    while stack:
        link, T = stack.pop()
        parents = robot.parent_joint.get(link, [])
        if len(parents) > 1:
            names = [j.name for j in parents]
            raise ValueError(f"<link name={link!r}>: the child of {len(parents)} joints {names} "
                             "(a closed loop): its inertia cannot be given to one body")
        if link in seen:  # pragma: no cover - a cycle makes a link the child of two joints
            raise ValueError(f"<link name={link!r}>: the joints form a cycle")
        seen.add(link)
        parts.append((link, T))
        for j in robot.child_joints.get(link, []):
            if j.type == "fixed" or j.name not in on_path:
                if j.child in seen or j.child == joint.parent:
                    raise ValueError(f"<joint name={j.name!r}>: the joints form a cycle "
                                     f"(back to the link {j.child!r})")
                stack.append((j.child, _compose(T, _origin(j.element, f"<joint name={j.name!r}>", policy))))
    return parts


def _inertials(robot: _Robot, joints: list[_Joint], policy: _AnglePolicy) -> tuple[LinkInertial, ...]:
    frames = dict((j.name, T) for j, T in _walk(robot, joints, policy))
    on_path = {j.name for j in joints}
    order = {name: i for i, name in enumerate(robot.links)}
    out = []
    for joint in joints:
        if joint.type not in _MOVING:
            continue
        parts = _body_parts(robot, joint, frames[joint.name], on_path, policy)
        parts.sort(key=lambda part: order[part[0]])
        pieces = [p for p in (_link_inertial(robot, link, T, policy) for link, T in parts) if p is not None]
        mass: Expr = sum((m for m, _, _ in pieces), S.Zero)
        if mass == 0:
            com, inertia = zeros(3, 1), zeros(3, 3)
        else:
            com = _exact(sum((m * c for m, c, _ in pieces), zeros(3, 1)) / mass)
            inertia = zeros(3, 3)
            for m, c, I in pieces:
                d = c - com
                inertia += I + m * (d.dot(d) * ImmutableMatrix.eye(3) - d * d.T)
            inertia = _exact(inertia)
        out.append(LinkInertial(joint.name, tuple(link for link, _ in parts), mass,
                                ImmutableMatrix(com), ImmutableMatrix(inertia)))
    return tuple(out)


class UrdfRobot(NamedTuple):
    """What :func:`read_urdf` reads: ``twists``, ``home``, ``inertials`` (or None) and ``recognised``."""

    twists: tuple[Twist, ...]
    home: Transform
    inertials: tuple[LinkInertial, ...] | None
    recognised: tuple[RecognisedAngle, ...]


def read_urdf(source: Any, base: str | None = None, tip: str | None = None, *,
              angles: str = "pi/12", angle_tol: ScalarLike | None = None,
              inertials: bool = False, budget: int = BUDGET) -> UrdfRobot:
    r"""Read the file once: twists and home, the inertials if asked, and the recognised angles.

    What :meth:`Chain.from_urdf <screwsym.motion.chain.Chain.from_urdf>` uses:
    :func:`urdf_twists_and_home` and :func:`read_inertials` in one parse, with
    one :class:`~screwsym.motion.angles.RecognisedAngleWarning` listing every
    angle recognised (the same angle of a joint is listed once).  The exact
    arithmetic of the frames is bounded by ``budget`` (units of polynomial
    arithmetic, :mod:`screwsym.algebra.budget`; a file with many angles that are
    no multiple of pi/12 can pass it): past it, a ``ValueError``.

    >>> import warnings
    >>> from screwsym.motion.angles import RecognisedAngleWarning
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     robot = read_urdf(TWO_LINK_URDF, inertials=True)
    >>> [w.category.__name__ for w in caught], robot.inertials[1].mass
    (['RecognisedAngleWarning'], 2)
    >>> [(r.text, r.value) for r in robot.recognised]
    [('1.5707963267948966', pi/2)]
    """
    policy = _AnglePolicy(angles, angle_tol)
    budget = check_count(budget, "budget")
    robot = _Robot(source)
    base, tip, joints = robot.path(base, tip)
    with _bounded(budget, "from_urdf"):
        twists, home = _twists_and_home(robot, base, tip, joints, policy)
        bodies = _inertials(robot, joints, policy) if inertials else None
    policy.warn()
    return UrdfRobot(tuple(twists), home, bodies, policy.report())


#: the robot files shipped in the package (screwsym/motion/urdf_samples, from example-robot-data)
SAMPLES = ("panda.urdf", "ur5_robot.urdf")


def sample_urdf(name: str) -> Path:
    """The path of a URDF file shipped with screwsym: ``"panda.urdf"`` or ``"ur5_robot.urdf"``.

    Found through :mod:`importlib.resources` in the installed package, so that it
    works from any directory (the files' origin and licences:
    ``screwsym/motion/urdf_samples/README.md``).

    >>> from screwsym import Chain
    >>> from screwsym.motion.urdf import sample_urdf
    >>> sample_urdf("ur5_robot.urdf").name
    'ur5_robot.urdf'
    >>> Chain.from_urdf(sample_urdf("ur5_robot.urdf"), "base_link", "tool0").n_joints
    6
    """
    if name not in SAMPLES:
        raise ValueError(f"name: expected one of {SAMPLES}, got {name!r}")
    path = importlib.resources.files("screwsym.motion") / "urdf_samples" / name
    if not isinstance(path, Path):  # pragma: no cover - a package imported from a zip file
        raise ValueError(f"name: {name!r} is not a file on disk here (the package is zipped)")
    return path


#: a small URDF used by the examples (a two-joint arm with a fixed flange)
TWO_LINK_URDF = """<robot name="two_link">
  <link name="base"/> <link name="upper"/> <link name="fore"/>
  <link name="hand">
    <inertial>
      <mass value="2"/> <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.03"/>
    </inertial>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/> <child link="upper"/>
    <origin xyz="0 0 0.089159"/> <axis xyz="0 1 0"/>
  </joint>
  <joint name="elbow" type="continuous">
    <parent link="upper"/> <child link="fore"/>
    <origin xyz="0.425 0 0" rpy="0 0 1.5707963267948966"/> <axis xyz="0 0 1"/>
  </joint>
  <joint name="wrist_flange" type="fixed">
    <parent link="fore"/> <child link="hand"/> <origin xyz="0.1 0 0"/>
  </joint>
</robot>"""
