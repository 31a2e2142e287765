"""Inputs that cannot go wrong silently (issue 8): non-finite, masked, non-real,
floats under one policy, strings never evaluated, NumPy conversion."""

from __future__ import annotations

import builtins
import math

import mpmath
import numpy as np
import pytest
from sympy import Float, I, Rational, Symbol, latex, nan, oo, sqrt, symbols, zoo

import screwsym
from screwsym import (
    CommonNormal,
    LineVector,
    Screw,
    Twist,
    Wrench,
    classify,
    common_normal,
    contains,
    is_coplanar,
    is_reciprocal,
    pitch,
)

x = Symbol("x", real=True)


# ------------------------------------------------------------- non-finite, masked
@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: LineVector([float("nan"), 0, 0], [0, 0, 1]), "S[0]: expected a finite real value, got nan"),
        (lambda: Screw([1, 0, 0], [0, 0, oo]), "S0[2]: expected a finite real value, got oo"),
        (lambda: Screw([1, 0, 0], [0, 0, -oo]), "S0[2]: expected a finite real value, got -oo"),
        (lambda: Screw([1, 0, 0], [0, zoo, 0]), "S0[1]: expected a finite real value, got zoo"),
        (lambda: Screw([1, 0, 0], [0, nan, 0]), "S0[1]: expected a finite real value, got nan"),
        (lambda: Screw(np.array([1.0, np.inf, 0]), [0, 0, 0]), "S[1]: expected a finite real value, got oo"),
        (lambda: Screw.from_matrix([1, 0, 0, 0, 0, float("inf")]), "M[5]: expected a finite real value, got oo"),
        (lambda: Screw([1, 0, 0], [x + oo, 0, 0]), "S0[0]: expected a finite real value, got oo"),
        (lambda: Screw.from_axis([0, 0, 0], [1, 0, 0], oo),
         "pitch: expected a finite pitch; build a couple with couple(C)"),
        (lambda: 2 * Screw([1, 0, 0], [0, 0, 0]) * float("nan"), "k: expected a finite real value, got nan"),
    ],
)
def test_non_finite_values_are_refused(call, message):
    with pytest.raises(ValueError) as info:
        call()
    assert str(info.value) == message


def test_masked_arrays_are_refused():
    masked = np.ma.masked_array([1.0, 2.0, 3.0], mask=[0, 1, 0])
    with pytest.raises(TypeError, match=r"S: expected a 3-vector \(list, tuple or SymPy Matrix\), got MaskedArray"):
        Screw(masked, [0, 0, 0])
    with pytest.raises(TypeError, match=r"M: expected a 6-vector .*got MaskedArray"):
        Screw.from_matrix(np.ma.masked_array(np.ones(6)))
    with pytest.raises(TypeError, match=r"k: expected a real number or SymPy expression, got MaskedArray"):
        Screw([1, 0, 0], [0, 0, 0]) * np.ma.masked_array(2.0, mask=True)


def test_none_and_booleans_are_not_numbers():
    with pytest.raises(TypeError, match=r"S\[0\]: expected a real number or SymPy expression, got NoneType None"):
        Screw([None, 0, 0], [0, 0, 0])
    with pytest.raises(TypeError, match=r"S0\[1\]: expected a real number .*got bool True"):
        Screw([1, 0, 0], [0, True, 0])


# ---------------------------------------------------------------------- real
def test_components_must_be_known_real():
    z = Symbol("z")
    with pytest.raises(ValueError) as info:
        Screw([z, 0, 0], [0, 0, 0])
    assert str(info.value) == (
        "S[0]: expected a real value, got z, which is not known to be real "
        "(declare symbols with real=True; a root needs a non-negative base)"
    )
    with pytest.raises(ValueError, match=r"S0\[0\]: expected a real value, got sqrt\(x\)"):
        Screw([1, 0, 0], [sqrt(x), 0, 0])
    with pytest.raises(ValueError, match=r"S\[1\]: expected a real value, got I"):
        Screw([1, I, 0], [0, 0, 0])
    # real wherever defined: quotients of real symbols, roots of non-negative bases
    y = Symbol("y", real=True)
    p = Symbol("p", positive=True)
    assert Screw([x / y, sqrt(x**2 + y**2), sqrt(p)], [0, 0, 0]).S[0] == x / y


def test_constructors_classify_and_pitch_agree_on_an_unknown_sign():
    # a real symbol of unknown sign is accepted everywhere, and every decision about it is None
    s = Screw([1, 0, 0], [x, 0, 0])
    assert classify(s) is None and pitch(s) == x
    assert LineVector([1, 0, 0], [0, x, 0]).pitch == 0
    L = LineVector([1, 0, 0], [x, 0, 0])  # S.S0 = x: undecided, so accepted as the user says
    assert L.classify() == "line" and L.pitch == 0


# -------------------------------------------------------------------- floats
def test_the_float_policy_is_relative():
    # a tiny line vector with S.S0 != 0 at its own scale is not a line, however small
    with pytest.raises(ValueError, match=r"a line vector needs S.S0 = 0"):
        LineVector([1e-6, 0, 0], [1e-7, 0, 0])
    with pytest.raises(ValueError, match=r"a line vector needs S.S0 = 0"):
        LineVector([1e200, 0, 0], [1e200, 0, 0])  # no overflow to inf
    L = LineVector.through([0.1, 0.2, 0.3], [0.4, 0.5, 0.7])
    for k in (1e-150, 1e-3, 1.0, 1e3, 1e150):
        scaled = Screw(L.S * k, L.S0 * k)
        assert classify(scaled) == "line" and pitch(scaled) == 0
        LineVector(scaled.S, scaled.S0)


def test_an_exact_line_survives_evalf():
    L = LineVector.through([Rational(1, 3), Rational(2, 7), 1], [2, Rational(5, 3), Rational(1, 9)])
    for digits in (3, 5, 15, 30):
        assert isinstance(L.evalf(digits), LineVector)


def test_float_lines_classify_and_meet_consistently():
    L = LineVector.through([0.1, 0.2, 0.3], [0.4, 0.5, 0.7])
    assert classify(Screw(L.S, L.S0)) == "line" and pitch(Screw(L.S, L.S0)) == 0
    M = LineVector.through([0.1, 0.2, 0.3], [0.7, -0.5, 0.2])  # through the same point
    assert is_coplanar(L, M) is True
    assert common_normal(L, M).a12 == 0
    assert contains(L, [0.7, 0.8, 1.1]) is True
    assert contains(L, [0.7, 0.8, 1.2]) is False
    assert is_coplanar(L, LineVector.through([0.1, 0.2, 1.3], [0.7, -0.5, 1.2])) is False
    assert is_reciprocal(L, L) is True


def _reference_distance(r1, d1, r2, d2):
    """The distance of the lines through r1 along d1 and r2 along d2, in 60-digit mpmath."""
    mpmath.mp.dps = 60
    r1, d1, r2, d2 = (mpmath.matrix([mpmath.mpf(e) for e in v]) for v in (r1, d1, r2, d2))

    def cross(a, b):
        return mpmath.matrix([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])

    n = cross(d1, d2)
    return abs(sum((r2 - r1)[i] * n[i] for i in range(3))) / mpmath.norm(n)


@pytest.mark.parametrize("angle", [1e-2, 1e-5, 1e-8, 1e-10, 1e-11])
def test_nearly_parallel_float_lines_get_the_true_distance(angle):
    # line 2 is line 1 tilted by ``angle`` about the offset (1, -1, 0) between them, which is
    # perpendicular to both: the common normal is that offset, with its feet at the two points
    r1, d1, r2, d2 = [0.3, -1.2, 0.7], [1.0, 1.0, 0.7], [1.3, -2.2, 0.7], [1.0, 1.0, 0.7 + angle]
    cn = common_normal(LineVector.from_axis(r1, d1), LineVector.from_axis(r2, d2))
    ref = _reference_distance(r1, d1, r2, d2)
    assert abs(float(cn.a12) - float(ref)) <= 1e-9 * float(ref)
    assert abs(float(cn.a12) - math.sqrt(2)) <= 1e-9
    # where the normal meets nearly parallel lines is ill-conditioned: a rounding of the
    # lines' position by 1e-16 moves the feet along them by about 1e-16 / angle
    foot1, foot2 = (np.array(f, dtype=float).ravel() for f in (cn.foot1, cn.foot2))
    assert np.allclose(foot1, r1, rtol=0, atol=1e-14 / angle)
    assert np.allclose(foot2, r2, rtol=0, atol=1e-14 / angle)
    normal = np.array(cn.normal, dtype=float).ravel()
    assert np.allclose(foot2 - foot1, float(cn.a12) * normal, rtol=0, atol=1e-9)


def test_float_lines_parallel_up_to_rounding_are_parallel():
    l1 = LineVector.through([0.1, 0.2, 0.3], [0.4, 0.5, 0.7])
    l2 = LineVector.through([1.1, 0.2, 0.3], [1.4, 0.5, 0.7])
    cn = common_normal(l1, l2)
    u = np.array([0.3, 0.3, 0.4]) / math.sqrt(0.34)
    d = np.array([1.0, 0, 0])
    true = np.linalg.norm(d - d.dot(u) * u)
    assert abs(float(cn.a12) - true) <= 1e-12 * true
    assert cn.alpha12 == 0 and all(abs(float(e)) < 10 for e in cn.foot1)


# ------------------------------------------------------- strings never run
PAYLOAD = "__import__('builtins').__setattr__('screwsym_was_here', 1)"


def _untouched():
    return not hasattr(builtins, "screwsym_was_here")


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda s: s.subs(x, PAYLOAD), "subs"),
        (lambda s: s.subs({x: PAYLOAD}), "subs"),
        (lambda s: s.subs([(PAYLOAD, 1)]), "subs"),
        (lambda s: s.xreplace({x: PAYLOAD}), "xreplace"),
        (lambda s: s.diff(PAYLOAD), "diff"),
        (lambda s: s.evalf(subs={x: PAYLOAD}), "evalf"),
        (lambda s: s.n(subs={x: PAYLOAD}), "evalf"),
        (lambda s: s.match(PAYLOAD), "match"),  # Basic.match sympifies without strict=True
        (lambda s: s.matches(PAYLOAD), "matches"),
    ],
)
@pytest.mark.parametrize(
    "obj",
    [
        Screw([x, 0, 0], [0, 0, 0]),
        LineVector([1, 0, 0], [0, x, 0]),
        Twist([0, 0, x], [0, 0, 0]),
        Wrench([0, 0, 1], [x, 0, 0]),
        common_normal(LineVector([1, 0, 0], [0, 0, 0]), LineVector([0, 1, 0], [x, 0, 0])),
    ],
    ids=["Screw", "LineVector", "Twist", "Wrench", "CommonNormal"],
)
def test_strings_are_never_evaluated(obj, call, name):
    with pytest.raises(TypeError, match=rf"{name}: strings are never evaluated"):
        call(obj)
    assert _untouched()


@pytest.mark.parametrize(
    "obj",
    [Screw([x, 0, 0], [0, 0, 0]), LineVector([1, 0, 0], [0, x, 0]), Twist([0, 0, x], [0, 0, 0])],
    ids=["Screw", "LineVector", "Twist"],
)
def test_applyfunc_never_evaluates_a_string_result(obj):
    # Matrix.applyfunc sympifies what f returns without strict=True: the string was run
    with pytest.raises(TypeError, match="applyfunc: strings are never evaluated"):
        obj.applyfunc(lambda e: PAYLOAD)
    assert _untouched()
    assert obj.applyfunc(lambda e: 2 * e) == obj * 2


@pytest.mark.parametrize("which", range(5))
def test_the_common_normal_constructor_never_evaluates_strings(which):
    # ImmutableMatrix(normal) and the foot points sympify their entries without strict=True
    parts = [0, [0, 0, 1], 0, [0, 0, 0], [0, 0, 0]]
    parts[which] = PAYLOAD if which in (0, 2) else [PAYLOAD, 0, 0]
    with pytest.raises(TypeError, match="CommonNormal: strings are never evaluated"):
        CommonNormal(*parts)
    assert _untouched()


def test_plot_subs_refuses_strings():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from screwsym.plot import plot_screw

    with pytest.raises(TypeError, match=r"subs: strings are never evaluated"):
        plot_screw(Screw([1, 0, 0], [x, 0, 0]), subs={x: PAYLOAD})
    assert _untouched()


def test_the_string_guard_still_substitutes_numbers():
    s = Screw([x, 0, 0], [0, x**2, 0])
    assert s.subs(x, 2) == Screw([2, 0, 0], [0, 4, 0])
    assert s.xreplace({x: 3}) == Screw([3, 0, 0], [0, 9, 0])
    assert s.diff(x) == Screw([1, 0, 0], [0, 2 * x, 0])
    assert s.evalf(3, subs={x: 2}) == Screw([Float(2, 3), 0, 0], [0, Float(4, 3), 0])


def test_the_string_guard_lets_keyword_arguments_through():
    # keyword names are strings but never evaluated: they were refused ("got str 'chop'")
    s = Screw([x, 0, 0], [0, x**2, 0])
    assert s.subs(x, 2, evaluate=True) == Screw([2, 0, 0], [0, 4, 0])
    assert s.evalf(3, subs={x: Rational(1, 3)}, chop=True) == s.evalf(3, subs={x: Rational(1, 3)})
    assert s.diff(x, evaluate=True) == Screw([1, 0, 0], [0, 2 * x, 0])
    assert s.match(s) == {}
    with pytest.raises(TypeError, match="subs: strings are never evaluated"):
        s.subs(x, 2, simultaneous=PAYLOAD)
    assert _untouched()


# ---------------------------------------------------------- NumPy, names
def test_numpy_conversion_in_ray_order():
    s = Screw([1, 1, 0], [1, 0, 0])
    assert np.asarray(s, dtype=float).tolist() == [1.0, 1.0, 0.0, 1.0, 0.0, 0.0]
    assert np.asarray(Twist([0, 0, 2], [3, 0, 0])).dtype == np.float64
    assert np.array([s, 2 * s]).shape == (2, 6)
    with pytest.raises(TypeError, match=r"cannot convert a symbolic Screw to an array of float64: substitute numbers for x"):
        np.asarray(Screw([x, 0, 0], [0, 0, 0]), dtype=float)


def test_dir_and_all_list_every_public_name():
    for name in ("book", "codegen", "numeric", "unit", "CommonNormal", "exp6", "Revolute"):
        assert name in screwsym.__all__ and name in dir(screwsym)
    # attributes that a star import leaves out, since SymPy's star import binds the same names
    import importlib

    homes = {
        "lambdify": importlib.import_module("screwsym.codegen").lambdify,
        "plot": importlib.import_module("screwsym.plot"),
        "init_printing": importlib.import_module("screwsym.core.printing").init_printing,
        "__version__": importlib.import_module("screwsym._version").__version__,
    }
    for name, home in homes.items():
        assert name not in screwsym.__all__ and name in dir(screwsym)
        assert getattr(screwsym, name) is home
    # the star import binds exactly __all__, each name resolving
    ns: dict = {}
    exec("from screwsym import *", ns)  # noqa: S102 - a fixed statement
    assert sorted(set(ns) - {"__builtins__"}) == sorted(screwsym.__all__)
    assert all(ns[name] is getattr(screwsym, name) for name in screwsym.__all__)


# ---------------------------------------------------------- CommonNormal
def test_common_normal_is_a_sympy_object():
    z = Symbol("z", positive=True)
    cn = common_normal(LineVector.from_axis([0, 0, 0], [1, 0, 0]), LineVector.from_axis([0, 0, z], [0, 1, 0]))
    assert isinstance(cn, CommonNormal) and cn.func(*cn.args) == cn
    assert cn.free_symbols == {z}
    assert cn.subs(z, 2).a12 == 2
    assert latex(cn).startswith(r"a_{12} = z,\quad \mathbf{a}_{12}")
    assert cn._lambdify_outputs() == cn.args
    assert str(cn) == "CommonNormal(a12=z, normal=[0, 0, 1], alpha12=pi/2, foot1=[0, 0, 0], foot2=[0, 0, z])"
    h = symbols("h", real=True)
    assert Screw.from_axis([0, 0, 0], [1, 0, 0], h).pitch == h


def test_simultaneous_subs():
    y = Symbol("y", real=True)
    s = Screw([x, y, 0], [0, 0, x])
    assert s.subs({x: y, y: x}, simultaneous=True) == Screw([y, x, 0], [0, 0, y])
    L = LineVector([1, 0, 0], [0, x, y])
    assert L.subs({x: y, y: x}, simultaneous=True) == LineVector([1, 0, 0], [0, y, x])
