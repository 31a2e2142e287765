# mypy: warn-unused-ignores
"""Typed use of screwsym: checked by mypy, and run, in test_typing.py.

Every annotation below must hold for mypy: constructors and classmethods
return ``Self`` (a subclass's constructor gives the subclass), twists and
wrenches keep their kind through their algebra, ``Transform.apply`` gives
back what it is given.  Run, each annotation is also checked against the
value's class.  :func:`refused` holds what mypy must refuse: each line carries
an ignore for the error it must raise, and this file has mypy warn of
unused ignores (the first line), so a line mypy stops refusing fails it.
"""

from __future__ import annotations

from sympy import ImmutableMatrix, Symbol, pi

from screwsym import (
    LineVector,
    Screw,
    ScrewSystem,
    Transform,
    Twist,
    Wrench,
    axis,
    convert_from,
    decompose_screw,
    exp6,
    pitch,
    shift_origin,
    tidy,
    unit,
)
from screwsym.core.screw import ScalarLike, ScrewLike, VectorLike


def _exactly(value: object, cls: type) -> None:
    assert type(value) is cls, f"{value!r} is a {type(value).__name__}, annotated {cls.__name__}"


def usage() -> None:
    h = Symbol("h", real=True)
    point: VectorLike = [0, 1, 0]
    k: ScalarLike = 2
    six: ScrewLike = [1, 1, 0, 1, 0, 0]

    s: Screw = Screw.from_axis(point, [1, 0, 0], h)
    line: LineVector = LineVector.through([0, 0, 0], [1, 0, 0])
    line2: LineVector = LineVector.from_matrix([0, 1, 0, 0, 0, 0])
    t: Twist = Twist.rotation([0, 0, 1], point=point)
    t2: Twist = Twist.from_axis(point, [0, 0, 1], 3, magnitude=k)
    w: Wrench = Wrench.force([0, 0, -10], point=[1, 0, 0])
    c: Wrench = Wrench.couple([0, 0, 1])
    for value, cls in [(s, Screw), (line, LineVector), (line2, LineVector), (t, Twist),
                       (t2, Twist), (w, Wrench), (c, Wrench)]:
        _exactly(value, cls)
    # the axis of any screw is a line vector, to mypy as at run time
    axes: list[LineVector] = [s.axis, t.axis, w.axis, axis(s)]
    for ax in axes:
        _exactly(ax, LineVector)
    assert t.axis.contains(point) is True

    # the algebra of twists and wrenches closes; a sum of lines is a screw
    t_sum: Twist = t + t2 - 2 * t / 3
    w_sum: Wrench = -w + c * k
    lines: Screw = line + line2
    shifted: LineVector = line.shift_origin([1, 2, 3])
    u: Twist = t.unit()
    u2: Wrench = unit(w)
    shifted2: Twist = shift_origin(t, [1, 0, 0])
    # a twist splits into two twists (rotation, translation), a wrench into two wrenches
    t_parts: tuple[Twist, Twist] = t2.decompose()
    w_parts: tuple[Wrench, Wrench] = decompose_screw(w)
    # so does its derivative; a line's derivative is a screw
    rate: Twist = Twist([h, 0, 0], [0, 0, h]).diff(h)
    line_rate: Screw = LineVector([h, 0, 0], [0, 0, 0]).diff(h)
    _exactly(rate, Twist)
    _exactly(line_rate, Screw)
    for part in t_parts:
        _exactly(part, Twist)
    for part_w in w_parts:
        _exactly(part_w, Wrench)
    for value, cls in [(t_sum, Twist), (w_sum, Wrench), (lines, Screw),
                       (shifted, LineVector), (u, Twist), (u2, Wrench), (shifted2, Twist)]:
        _exactly(value, cls)

    # functions and properties
    assert pitch(six) == pitch(Screw.from_matrix(six))
    a: Screw = axis(s)
    foot: ImmutableMatrix = s.foot
    decided: bool | None = line.is_reciprocal(line2)
    _exactly(a, LineVector)
    _exactly(foot, ImmutableMatrix)
    assert decided is True

    # motions carry each kind as it is
    T: Transform = Transform.rotation([0, 0, 1], pi / 2) @ exp6(t, 1)
    moved: Twist = T.apply(t)
    moved_line: LineVector = T.apply(line)
    composed: Transform = T.apply(T.inverse())
    x: ImmutableMatrix = T.apply([1, 0, 0])
    back: Wrench = convert_from([0, 0, 5, 7, 0, 0], "spatialmath", Wrench)
    tidied: Twist = tidy(moved)
    for value, cls in [(T, Transform), (moved, Twist), (moved_line, LineVector),
                       (composed, Transform), (x, ImmutableMatrix), (back, Wrench),
                       (tidied, Twist)]:
        _exactly(value, cls)

    system: ScrewSystem = ScrewSystem(t, t2)
    members: list[Screw] = list(system)
    assert members == [t, t2]


def refused() -> None:
    """What mypy must refuse (never run: the test only type-checks it)."""
    w = Wrench.force([0, 0, -10], point=[1, 0, 0])
    n: int = Screw([1, 0, 0], [0, 0, 0])  # type: ignore[assignment]  # a screw is no int
    t: Twist = w  # type: ignore[assignment]  # a wrench is no twist
    line: LineVector = LineVector.through([0, 0, 0], [1, 0, 0]) * 2  # type: ignore[assignment]  # k * line is a Screw (0 * line is no line)
    q: Transform = Transform.identity().apply(w)  # type: ignore[assignment]  # a wrench moves as a wrench
    print(n, t, line, q)
