"""Thin printers: SymPy's code printers with one semantics for every back end.

Each printer is SymPy's own (Python, NumPy, C99) with the few constructs
overridden where the stock printers disagree with each other:

* integer literals beyond 2**53 print as the nearest double everywhere (C
  would truncate them to 64 bits; Python would compute exactly);
* ``pi``, ``E`` and every ``Float`` print as the nearest double (C99 has no
  ``M_PI``);
* a power with a non-integer exponent is the real ``pow``: ``nan`` for a
  negative base (C's ``cbrt`` and Python's complex power disagreed);
* ``Mod`` takes the sign of the divisor (Python's ``%``, ``numpy.mod``; C
  gets a helper around ``fmod``);
* ``Min``/``Max`` and ``sign`` propagate ``nan`` (C's ``fmin`` does not);
* ``Piecewise`` is a chain of conditionals, ``nan`` where no branch holds;
* ``floor``/``ceiling`` stay floating point (``math.floor`` is an int).

Module references print as ``_m`` (math) and ``_np`` (NumPy), names only
screwsym binds.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from sympy import Expr, Float, Integer
from sympy.printing.c import C99CodePrinter
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.pycode import PythonCodePrinter

_EXACT = 2**53


def _double(value) -> str:
    """The nearest double to a SymPy number, as a literal valid in Python and C."""
    x = float(value)
    text = repr(x)
    if text in ("inf", "-inf"):
        return text  # replaced by the caller
    return text if ("." in text or "e" in text) else text + ".0"


class _Common:
    """Overrides shared by the Python-syntax printers."""

    _inf = "_m.inf"
    _nan = "_m.nan"

    if TYPE_CHECKING:
        # a mixin: the SymPy printer it is mixed into prints the parts
        def _print(self, expr: Any, **kwargs: Any) -> str: ...

    def _module_format(self, fqn, register=True):  # noqa: D401 - SymPy's protocol
        head, _, tail = fqn.partition(".")
        if head == "math":
            return "_m." + tail
        if head == "numpy":
            return "_np." + tail
        raise TypeError(f"screwsym printers: unexpected module reference {fqn!r}")

    def _number(self, value) -> str:
        text = _double(value)
        if text == "inf":
            return self._inf
        if text == "-inf":
            return f"(-{self._inf})"
        return text

    def _print_Integer(self, expr):
        p = int(expr)
        return str(p) if abs(p) <= _EXACT else self._number(p)

    def _print_Rational(self, expr):
        if abs(expr.p) <= _EXACT and expr.q <= _EXACT:  # doubles: their quotient is rounded once
            return f"({self._print(Integer(expr.p))}/{self._print(Integer(expr.q))})"
        # Python's int division is correctly rounded: (10**400 + 1)/10**400 is 1.0, not inf/inf
        return self._number(expr.p / expr.q)

    def _print_Half(self, expr):
        return "0.5"

    def _print_Float(self, expr):
        return self._number(expr)

    def _print_NumberSymbol(self, expr):
        return self._number(expr)

    _print_Pi = _print_Exp1 = _print_NumberSymbol

    def _print_Infinity(self, expr):
        return self._inf

    def _print_NegativeInfinity(self, expr):
        return f"(-{self._inf})"

    def _print_NaN(self, expr):
        return self._nan

    # -- the constructs every target prints alike, up to its names (``_functions``) and
    # -- its conditional expression (``_conditional``): written once here

    #: the target's function for each of min, max, sign, abs and mod
    _functions: dict[str, str] = {}
    _true, _false = "True", "False"

    def _conditional(self, condition: str, then: str, otherwise: str) -> str:
        raise NotImplementedError

    def _call(self, name: str, *args) -> str:
        return f"{self._functions[name]}({', '.join(self._print(a) for a in args)})"

    def _fold(self, args, name):
        """``f(f(a, b), c)``: a left fold of the binary function ``name``."""
        text = self._print(args[0])
        for other in args[1:]:
            text = f"{self._functions[name]}({text}, {self._print(other)})"
        return text

    def _print_Min(self, expr):
        return self._fold(expr.args, "min")  # nan propagates in every target's helper

    def _print_Max(self, expr):
        return self._fold(expr.args, "max")

    def _print_sign(self, expr):
        return self._call("sign", expr.args[0])

    def _print_Abs(self, expr):
        return self._call("abs", expr.args[0])

    def _print_Mod(self, expr):
        return self._call("mod", *expr.args)

    def _print_Piecewise(self, expr):
        text = None
        for e, c in reversed(expr.args):
            if c == True:  # noqa: E712 - SymPy's true
                text = self._print(e)
            elif c == False:  # noqa: E712
                continue
            else:
                text = self._conditional(self._print(c), self._print(e), text or self._nan)
        return text or self._nan

    def _print_BooleanTrue(self, expr):
        return self._true

    def _print_BooleanFalse(self, expr):
        return self._false


class ScalarPrinter(_Common, PythonCodePrinter):
    """Python floats, ``math``: the single-point path (and, via a subclass, numba)."""

    def __init__(self):
        super().__init__({"fully_qualified_modules": True, "strict": True})

    def _print_Pow(self, expr, rational=False):
        b, e = expr.base, expr.exp
        if e == -1:
            return f"(1.0/({self._print(b)}))"
        if e.is_Integer and e < 0:  # numba raises for 0.0**-n; 1/0.0 follows error_model
            return f"(1.0/({self._print(b)})**({self._print(-e)}))"
        if e == 2 and b.is_Symbol:  # one correctly rounded product, as pow(b, 2); faster
            return f"({self._print(b)}*{self._print(b)})"
        if e.is_Integer:
            return f"({self._print(b)})**({self._print(e)})"
        if e == Float(0.5) or e == Integer(1) / 2:
            return f"{self._sqrt}({self._print(b)})"
        if e == -Integer(1) / 2:
            return f"(1.0/{self._sqrt}({self._print(b)}))"
        return f"_m.pow({self._print(b)}, {self._print(e)})"

    _helper = "_"  # helpers are _min, _max, _sign, _mod (see PY_HELPERS)
    #: the square root: NaN for a negative number (``_sqrt`` of PY_HELPERS) as in the array
    #: code, where ``math.sqrt`` raises (a closed form with a branch that does not exist at
    #: the point, an inverse kinematics, would otherwise leave the single-point path)
    _sqrt = "_sqrt"

    @property
    def _functions(self):
        h = self._helper
        return {"min": f"{h}min", "max": f"{h}max", "sign": f"{h}sign", "mod": f"{h}mod",
                "abs": "abs"}

    def _conditional(self, condition, then, otherwise):
        return f"(({then}) if ({condition}) else ({otherwise}))"

    def _print_Not(self, expr):
        # SymPy 1.13 (our floor) prints Not(_c1) as ``not_c1``: its operator lacks the space
        return f"(not ({self._print(expr.args[0])}))"

    def _print_floor(self, expr):
        return f"float(_m.floor({self._print(expr.args[0])}))"

    def _print_ceiling(self, expr):
        return f"float(_m.ceil({self._print(expr.args[0])}))"


class NumbaPrinter(ScalarPrinter):
    """The fused loop: as the scalar path, with NumPy's float ``floor``/``ceil``."""

    _helper = "_nb_"  # the helpers compiled by numba
    _sqrt = "_m.sqrt"  # NaN for a negative number under error_model='numpy'

    def _print_floor(self, expr):
        return f"_np.floor({self._print(expr.args[0])})"

    def _print_ceiling(self, expr):
        return f"_np.ceil({self._print(expr.args[0])})"


class BlockPrinter(_Common, NumPyPrinter):
    """NumPy array expressions on blocks of rows."""

    _inf = "_np.inf"
    _nan = "_np.nan"

    # no math macros: M_PI_2, M_LN2, ... are POSIX, not C99 (-std=c99 lacks them); the
    # constants print as their doubles, like pi and E
    math_macros: dict = {}  # noqa: RUF012 - SymPy's class attribute, never mutated

    def __init__(self):
        super().__init__({"strict": True})

    _functions = {"min": "_np.minimum", "max": "_np.maximum", "sign": "_np.sign",
                  "abs": "_np.abs", "mod": "_np.mod", "and": "_np.logical_and",
                  "or": "_np.logical_or"}

    def _conditional(self, condition, then, otherwise):
        # nested where (numpy.select costs microseconds per call); nan where no branch holds
        return f"_np.where({condition}, {then}, {otherwise})"

    def _print_And(self, expr):
        # logical_and.reduce (SymPy's) fails on operands of different batch shapes
        return self._fold(expr.args, "and")

    def _print_Or(self, expr):
        return self._fold(expr.args, "or")


#: helpers of the single-point path and (compiled by numba) of the fused loop
PY_HELPERS = """\
def _min(a, b):
    return a if (a <= b or a != a) else b


def _max(a, b):
    return a if (a >= b or a != a) else b


def _sign(x):
    return 1.0 if x > 0 else (-1.0 if x < 0 else 0.0 * x)


def _mod(a, b):
    return a % b if b != 0.0 else _m.nan


def _sqrt(x):
    return _m.sqrt(x) if x >= 0.0 else _m.nan
"""

#: helpers every generated C file defines (static inline: no unused warnings)
C_HELPERS = """\
static inline double ss_mod(double a, double b)
{
    /* the sign of the divisor, as Python's % and numpy.mod */
    double r = fmod(a, b);
    return (r != 0.0 && ((r < 0.0) != (b < 0.0))) ? r + b : r;
}
static inline double ss_min(double a, double b) { return (a <= b || a != a) ? a : b; }
static inline double ss_max(double a, double b) { return (a >= b || a != a) ? a : b; }
static inline double ss_sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0 * x); }
#if defined(__GNUC__) || defined(__clang__)
#define SS_PREFETCH(p) __builtin_prefetch(p)
#else
#define SS_PREFETCH(p) ((void)0)
#endif
"""


class CPrinter(_Common, C99CodePrinter):
    """C99 with the same semantics."""

    _inf = "INFINITY"
    _nan = "NAN"

    # no math macros: M_PI_2, M_LN2, ... are POSIX, not C99 (-std=c99 lacks them); the
    # constants print as their doubles, like pi and E
    math_macros: dict = {}  # noqa: RUF012 - SymPy's class attribute, never mutated

    def __init__(self):
        super().__init__({"strict": True})

    def _module_format(self, fqn, register=True):  # pragma: no cover - C has no modules
        raise TypeError(f"screwsym C printer: unexpected module reference {fqn!r}")

    def _print_Integer(self, expr):
        p = int(expr)
        return f"{p}.0" if abs(p) <= _EXACT else self._number(p)

    def _print_Pow(self, expr, rational=False):
        b, e = expr.base, expr.exp
        if e == Integer(1) / 2:
            return f"sqrt({self._print(b)})"
        if e == -Integer(1) / 2:
            return f"(1.0/sqrt({self._print(b)}))"
        if e == -1:
            return f"(1.0/({self._print(b)}))"
        return f"pow({self._print(b)}, {self._print(e)})"

    _functions = {"min": "ss_min", "max": "ss_max", "sign": "ss_sign", "abs": "fabs",
                  "mod": "ss_mod"}
    _true, _false = "1", "0"

    def _conditional(self, condition, then, otherwise):
        return f"(({condition}) ? ({then}) : ({otherwise}))"

    def _print_floor(self, expr):
        return f"floor({self._print(expr.args[0])})"

    def _print_ceiling(self, expr):
        return f"ceil({self._print(expr.args[0])})"

    def doprint_line(self, e: Expr) -> str:
        return " ".join(self.doprint(e).split())
