"""No method of any screwsym object evaluates a string: a walk with payloads that leave a trace.

Every public method and operator of one object of every kind (the screws, line
objects, Transform, Chain, ScrewSystem, every joint, Limb, ParallelMechanism,
Mobility) and every public function of the top package is called with
arguments holding a string whose evaluation as Python sets an attribute on a
module; none may set it.  SymPy's ``refine``, ``has``, ``find``, ``count``,
``dummy_eq`` (and ``==`` through a tuple or dict) parse such strings
(issue 20), so the walk is first shown to find the trace through SymPy itself.
"""

from __future__ import annotations

import operator
import types

import numpy as np
import pytest
from sympy import Abs, Basic, ImmutableMatrix, Symbol

import screwsym
from screwsym import (
    Chain,
    Cylindrical,
    Helical,
    Limb,
    LineVector,
    ParallelMechanism,
    Prismatic,
    Revolute,
    Screw,
    ScrewSystem,
    Spherical,
    Transform,
    Twist,
    Universal,
    Wrench,
    common_normal,
)

#: the module the payload writes to, and the attribute it sets
TRACE = types.ModuleType("trace_target")
PAYLOAD = "__import__('sys').modules['trace_target'].__setattr__('ran', 1)"

x = Symbol("x", real=True)
y = Symbol("y", positive=True)


def _objects():
    limb = Limb(Revolute([0, 0, 0], [0, 0, 1]), Prismatic([0, 0, 1]), Spherical([x, 0, 1]))
    pm = ParallelMechanism(
        limb, Limb(Revolute([1, 0, 0], [0, 0, 1]), Prismatic([0, 0, 1]), Spherical([1, 0, 1]))
    )
    return {
        # each holds an Abs, a root or a symbol: where SymPy's refine has something to do
        "Screw": Screw([Abs(x), 0, 1], [0, 0, 0]),
        "LineVector": LineVector([1, 0, 0], [0, Abs(x), 0]),
        "Twist": Twist([Abs(x), 0, 1], [0, 1, 0]),
        "Wrench": Wrench([Abs(x), 0, 1], [0, 1, 0]),
        "CommonNormal": common_normal(LineVector([1, 0, 0], [0, 0, 0]),
                                      LineVector([0, 1, 0], [-x, 0, 1])),
        "Transform": Transform.rotation([1, 1, y], x),
        "Chain": Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
                        Twist.rotation([0, 1, 0], point=[1, 0, x])]),
        "ScrewSystem": ScrewSystem(Twist([1, 0, 0], [0, 0, x]), Twist([0, 1, 0], [0, 0, 0])),
        "Revolute": Revolute([0, 0, x], [0, 0, 1]),
        "Prismatic": Prismatic([0, x, 1]),
        "Helical": Helical([0, 0, x], [0, 0, 1], 2),
        "Cylindrical": Cylindrical([0, 0, x], [0, 0, 1]),
        "Universal": Universal([0, 0, x], [1, 0, 0], [0, 1, 0]),
        "Spherical": Spherical([0, 0, x]),
        "Limb": limb,
        "ParallelMechanism": pm,
        "Mobility": pm.mobility(),
    }


def _arguments(payload):
    """Argument lists holding ``payload``: bare, in a list, tuple, dict, set, NumPy array."""
    holders = [payload, [payload], (payload,), {x: payload}, {payload}, np.array([payload])]
    calls = [((h,), {}) for h in holders]
    calls += [((x, payload), {}), ((payload, payload), {}), ((x, 1, payload), {}),
              ((x, (payload,)), {}), ((), {"subs": {x: payload}})]
    return calls


def _ran() -> bool:
    return TRACE.__dict__.pop("ran", None) is not None


@pytest.fixture(autouse=True)
def _trace_module(monkeypatch):
    monkeypatch.setitem(__import__("sys").modules, "trace_target", TRACE)
    _ran()


def _walk(obj, call) -> list[str]:
    """Every public method of ``obj`` and every operator, called with every payload argument."""
    traces = []
    for name in dir(obj):
        if name.startswith("_") or name == "expr_free_symbols":  # deprecated by SymPy 1.9
            continue
        try:
            method = getattr(obj, name)
        except Exception:  # a property may refuse this object (not a string matter)
            continue
        if not callable(method):
            continue
        for args, kwargs in _arguments(PAYLOAD):
            call(method, args, kwargs)
            if _ran():
                traces.append(f"{name}{args!r:.60}")
    binary = [operator.eq, operator.ne, operator.add, operator.sub, operator.mul,
              operator.truediv, operator.matmul, operator.contains]
    for op in binary:
        for (arg,), _ in _arguments(PAYLOAD)[:6]:
            for a, b in ((obj, arg), (arg, obj)):
                call(op, (a, b), {})
                if _ran():
                    traces.append(f"{op.__name__}({type(a).__name__}, {type(b).__name__})")
    return traces


def _call(f, args, kwargs):
    try:
        f(*args, **kwargs)
    except Exception:  # refusals are the point; only the trace is checked
        pass


@pytest.mark.parametrize("kind", list(_objects()))
def test_no_public_method_of_any_kind_evaluates_a_string(kind):
    assert _walk(_objects()[kind], _call) == []


def test_no_public_function_evaluates_a_string():
    traces = []
    for name in screwsym.__all__:
        f = getattr(screwsym, name)
        if isinstance(f, types.FunctionType):
            for args, kwargs in _arguments(PAYLOAD):
                _call(f, args, kwargs)
                if _ran():
                    traces.append(f"{name}{args!r:.60}")
    assert traces == []


def test_the_walk_finds_the_trace_through_sympys_own_methods():
    # SymPy's methods, not screwsym's guarded ones: the payload does run there
    s = _objects()["Screw"]

    def unguarded(method, args, kwargs):
        f = getattr(Basic, getattr(method, "__name__", ""), None)
        if f is not None and not isinstance(method, types.BuiltinFunctionType):
            _call(f, (s, *args), kwargs)

    found = _walk(s, unguarded)
    assert any(t.startswith("refine") for t in found)
    assert any(t.startswith("has") for t in found)
    # == on a matrix (a field of Mobility) parses the strings in a tuple, even strictly
    _call(operator.eq, (ImmutableMatrix([1]), (PAYLOAD,)), {})
    assert _ran()


def test_the_issue_example_refine_refuses_the_string():
    s = Screw([Abs(x), 0, 1], [0, 0, 0])
    with pytest.raises(TypeError, match="refine: strings are never evaluated"):
        s.refine(PAYLOAD)
    assert not _ran()
    from sympy import Q

    assert s.refine(Q.positive(x)) == Screw([x, 0, 1], [0, 0, 0])


def test_equality_with_a_string_holder_is_false_without_sympy():
    s = Screw([1, 0, 0], [0, 0, 0])
    assert (s == (PAYLOAD,)) is False and (s != {x: PAYLOAD}) is True
    assert not _ran()
    assert s == Screw([1, 0, 0], [0, 0, 0]) and hash(s) == hash(Screw([1, 0, 0], [0, 0, 0]))
    m = _objects()["Mobility"]
    assert m == tuple(m) and m.count(m.motion) == 1 and m.motion in m
    assert m.index(m.twists) == 9 and m != tuple(m)[:-1] + ({x: PAYLOAD},)
    assert not _ran()
