"""Every input error message of the core, pinned."""

import numpy as np
import pytest
from sympy import I, ImmutableMatrix, Matrix, Rational, symbols

import screwsym
from screwsym import LineVector, Screw, Twist, Wrench, vector
from screwsym.core.checks import check_scalar, check_vector

x = symbols("x", real=True)


@pytest.mark.parametrize(
    "value",
    [
        [1, 2, 3],
        (1, 2, 3),
        Matrix([1, 2, 3]),
        Matrix([[1, 2, 3]]),
        ImmutableMatrix([1, 2, 3]),
        np.array([1, 2, 3]),
        np.array([[1], [2], [3]]),
        [[1], [2], [3]],
    ],
)
def test_vector_forms_accepted(value):
    assert check_vector(value, "r") == ImmutableMatrix([1, 2, 3])


def test_numpy_and_python_numbers_accepted():
    assert check_vector(np.array([1.5, 0, 0]), "r")[0] == 1.5
    assert check_scalar(np.int64(3), "k") == 3
    assert check_scalar(Rational(1, 3), "k") == Rational(1, 3)


ERRORS = [
    (
        lambda: Screw("abc", [0, 0, 0]),
        TypeError,
        "S: expected a 3-vector (list, tuple or SymPy Matrix), got str 'abc'",
    ),
    (
        lambda: Screw(5, [0, 0, 0]),
        TypeError,
        "S: expected a 3-vector (list, tuple or SymPy Matrix), got int 5",
    ),
    (
        lambda: Screw(x, [0, 0, 0]),
        TypeError,
        "S: expected a 3-vector (list, tuple or SymPy Matrix), got Symbol x",
    ),
    (lambda: Screw([1, 2], [0, 0, 0]), ValueError, "S: expected a 3-vector, got shape (2,)"),
    (
        lambda: Screw(np.zeros((2, 3)), [0, 0, 0]),
        ValueError,
        "S: expected a 3-vector, got shape (2, 3)",
    ),
    (
        lambda: Screw([1, 2, 3], Matrix([1, 2, 3, 4])),
        ValueError,
        "S0: expected a 3-vector, got shape (4, 1)",
    ),
    (
        lambda: Screw([1, 2, "x"], [0, 0, 0]),
        TypeError,
        "S[2]: expected a real number or SymPy expression, got str 'x' (strings are never evaluated)",
    ),
    (
        lambda: Screw([1, None, 0], [0, 0, 0]),
        TypeError,
        "S[1]: expected a real number or SymPy expression, got NoneType None",
    ),
    (
        lambda: Screw([True, 0, 0], [0, 0, 0]),
        TypeError,
        "S[0]: expected a real number or SymPy expression, got bool True",
    ),
    (lambda: Screw([1, I, 0], [0, 0, 0]), ValueError, "S[1]: expected a real value, got I"),
    (
        lambda: Screw([1, 0, 0], np.array([1j, 0, 0])),
        ValueError,
        "S0[0]: expected a real value, got 1.0*I",
    ),
    (
        lambda: Twist([0, 0, 0], ["v", 0, 0]),
        TypeError,
        "v_O[0]: expected a real number or SymPy expression, got str 'v' (strings are never evaluated)",
    ),
    (lambda: Wrench([0, 0, 0, 1], [0, 0, 0]), ValueError, "f: expected a 3-vector, got shape (4,)"),
    (lambda: Wrench([0, 0, 1], [1, 2]), ValueError, "C_O: expected a 3-vector, got shape (2,)"),
    (
        lambda: Screw.from_matrix([1, 2, 3]),
        ValueError,
        "M: expected a 6-vector (S; S0), got shape (3,)",
    ),
    (
        lambda: Screw.from_matrix("123456"),
        TypeError,
        "M: expected a 6-vector (list, tuple or SymPy Matrix), got str '123456'",
    ),
    (
        lambda: Screw.from_axis([0, 0, 0], [1, 0, 0], "h"),
        TypeError,
        "pitch: expected a real number or SymPy expression, got str 'h' (strings are never evaluated)",
    ),
    (
        lambda: Screw.from_axis([0, 0, 0], [1, 0, 0], [1]),
        TypeError,
        "pitch: expected a real number or SymPy expression, got list [1]",
    ),
    (
        lambda: Screw.from_axis([0, 0, 0], [1, 0, 0], I),
        ValueError,
        "pitch: expected a real value, got I",
    ),
    (
        lambda: Screw.couple("C"),
        TypeError,
        "C: expected a 3-vector (list, tuple or SymPy Matrix), got str 'C'",
    ),
    (
        lambda: screwsym.pitch("s"),
        TypeError,
        "s: expected a Screw or a 6-vector (S; S0), got str 's'",
    ),
    (lambda: screwsym.pitch(3), TypeError, "s: expected a Screw or a 6-vector (S; S0), got int 3"),
    (
        lambda: screwsym.pitch([1, 2, 3, 4, 5]),
        ValueError,
        "s: expected a 6-vector (S; S0), got shape (5,)",
    ),
    (
        lambda: screwsym.reciprocal_product([1, 0, 0, 0, 0, 0], None),
        TypeError,
        "s2: expected a Screw or a 6-vector (S; S0), got NoneType None",
    ),
    (
        lambda: screwsym.shift_origin(Screw([1, 0, 0], [0, 0, 0]), [1, 2]),
        ValueError,
        "A: expected a 3-vector, got shape (2,)",
    ),
    (
        lambda: screwsym.mutual_moment([1, 0, 0, 1, 0, 0], [1, 0, 0, 0, 0, 0]),
        ValueError,
        "l1: a line vector needs S.S0 = 0 (1.10), got S.S0 = 1",
    ),
    (
        lambda: screwsym.common_normal(LineVector([1, 0, 0], [0, 0, 0]), "L"),
        TypeError,
        "l2: expected a LineVector or a 6-vector (S; S0), got str 'L'",
    ),
    (
        lambda: screwsym.contains(LineVector([1, 0, 0], [0, 0, 0]), "p"),
        TypeError,
        "point: expected a 3-vector (list, tuple or SymPy Matrix), got str 'p'",
    ),
    (
        lambda: LineVector.from_axis([0, 0, 0], [0, 0, 0]),
        ValueError,
        "direction: an axis needs a non-zero direction, got [0, 0, 0]",
    ),
    (
        lambda: Twist.from_axis("r", [0, 0, 1]),
        TypeError,
        "point: expected a 3-vector (list, tuple or SymPy Matrix), got str 'r'",
    ),
    (
        lambda: Twist.from_axis([0, 0, 0], [0, 0, 1], I),
        ValueError,
        "pitch: expected a real value, got I",
    ),
    (lambda: Wrench.force([1, 0, 0], point=[0, 0]), ValueError, "point: expected a 3-vector, got shape (2,)"),
    (
        lambda: Wrench.from_axis([0, 0, 0], [1, 0, 0], 0, magnitude="f"),
        TypeError,
        "magnitude: expected a real number or SymPy expression, got str 'f' (strings are never evaluated)",
    ),
    (
        lambda: Wrench.couple([0, 0, 1]).moment_about(7),
        TypeError,
        "point: expected a 3-vector (list, tuple or SymPy Matrix), got int 7",
    ),
    (lambda: vector(3), TypeError, "name: expected a str, got int 3"),
    (
        lambda: vector(""),
        ValueError,
        "name: expected a non-empty name without spaces, commas or colons, got ''",
    ),
    (
        lambda: vector("a b"),
        ValueError,
        "name: expected a non-empty name without spaces, commas or colons, got 'a b'",
    ),
]


@pytest.mark.parametrize("call, error, message", ERRORS, ids=[m[:40] for _, _, m in ERRORS])
def test_error_messages(call, error, message):
    with pytest.raises(error) as info:
        call()
    assert str(info.value) == message


def test_strings_are_never_evaluated(monkeypatch):
    def boom(*args, **kwargs):  # pragma: no cover - must not be reached
        raise AssertionError("eval called")

    monkeypatch.setattr("builtins.eval", boom)
    with pytest.raises(TypeError, match="strings are never evaluated"):
        Screw(["__import__('os')", 0, 0], [0, 0, 0])
