"""The one plan of a generated function: unpack, CSE assignments, store.

Every identifier in the plan is chosen here: argument ``k`` is ``_a<k>``,
its components ``_x<m>``, common subexpressions ``_c<m>``, results ``_o<j>``.
A user's symbol names and argument names never reach generated source;
the parameter names the user sees are set on the finished function's code
object (data, not source).  Expressions are checked against one list of
supported constructs before anything is printed.
"""

from __future__ import annotations

import hashlib
import keyword
import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import sympy
from sympy import (
    Abs,
    Add,
    And,
    Basic,
    Eq,
    Expr,
    Float,
    Ge,
    Gt,
    I,
    ImmutableMatrix,
    Integer,
    Le,
    Lt,
    Max,
    Min,
    Mod,
    Mul,
    Ne,
    Not,
    Or,
    Piecewise,
    Pow,
    Rational,
    Symbol,
    acos,
    acosh,
    asin,
    asinh,
    atan,
    atan2,
    atanh,
    ceiling,
    cos,
    cosh,
    cse,
    exp,
    floor,
    log,
    numbered_symbols,
    sign,
    sin,
    sinh,
    srepr,
    sympify,
    tan,
    tanh,
)
from sympy.core.numbers import Exp1, Infinity, NaN, NegativeInfinity, Pi
from sympy.core.sympify import SympifyError
from sympy.functions.elementary.piecewise import ExprCondPair
from sympy.logic.boolalg import BooleanFalse, BooleanTrue
from sympy.matrices import MatrixBase

from ._runtime import Arg

# The constructs every back end prints with the same semantics (see the
# printers).  Anything else is refused before printing.
SUPPORTED: tuple[type, ...] = (
    Symbol, Integer, Rational, Float, Pi, Exp1, Infinity, NegativeInfinity, NaN,
    Add, Mul, Pow, exp, log, sin, cos, tan, asin, acos, atan, atan2, sinh, cosh, tanh,
    asinh, acosh, atanh, Abs, sign, floor, ceiling, Mod, Min, Max, Piecewise, ExprCondPair,
    Lt, Le, Gt, Ge, Eq, Ne, And, Or, Not, BooleanTrue, BooleanFalse,
)  # fmt: skip
SUPPORTED_NAMES = ", ".join(
    sorted({"pi" if t is Pi else "E" if t is Exp1 else t.__name__ for t in SUPPORTED}
           - {"ExprCondPair", "BooleanTrue", "BooleanFalse", "Infinity", "NegativeInfinity",
              "NaN", "Integer", "Rational", "Float", "Symbol", "Add", "Mul"})
)


@dataclass(frozen=True)
class Out:
    """One result: its trailing shape."""

    trailing: tuple[int, ...]

    @property
    def size(self) -> int:
        return math.prod(self.trailing)


@dataclass(frozen=True)
class Plan:
    """What a generated function computes, independent of the back end.

    ``unpack`` lists ``(argument, component, local)``; ``assigns`` the CSE
    assignments ``(local, expr)`` in order; ``stores`` ``(result, entry,
    expr)``.  ``key`` is a content hash of everything that determines the
    generated code.
    """

    specs: tuple[Arg, ...]
    outs: tuple[Out, ...]
    is_tuple: bool
    unpack: tuple[tuple[int, int, Symbol], ...]
    assigns: tuple[tuple[Symbol, Expr], ...]
    stores: tuple[tuple[int, int, Expr], ...]
    name: str
    key: str


# ---------------------------------------------------------------- arguments


def _stem(symbols: Sequence[Symbol]) -> str | None:
    """``A`` for ``A_x, A_y, A_z``; None when the names share no such stem."""
    stems = {s.name.rpartition("_")[0] for s in symbols}
    if len(stems) == 1:
        return stems.pop() or None
    return None


def is_identifier(name: Any) -> bool:
    """A name usable as a parameter or function name (never as source text)."""
    return (
        isinstance(name, str)
        and name.isidentifier()
        and name.isascii()
        and not keyword.iskeyword(name)
        and not name.startswith("_")
        and name != "out"
    )


def _matrix_symbols(m: MatrixBase, where: str) -> tuple[Symbol, ...]:
    entries = tuple(m)
    for e in entries:
        if not isinstance(e, Symbol):
            raise TypeError(f"{where}: expected symbols as entries, got {e!r} ({type(e).__name__})")
    return entries


def normalise_args(args: Any, names: Any) -> tuple[list[Arg], list[tuple[Symbol, ...]]]:
    """Check ``args`` and describe each one's array.

    An object with a method ``_lambdify_argument()`` (every screw) stands for
    the matrix of symbols that method returns, described by the string it
    returns beside it; code generation knows no screwsym class.
    """
    if isinstance(args, (Basic, MatrixBase)):
        args = [args]
    if not isinstance(args, (list, tuple)):
        raise TypeError(
            f"args: expected a list of symbols, vectors and screws, got {type(args).__name__}"
        )
    if not args:
        raise ValueError("args: expected at least one symbol, vector or screw, got an empty list")
    if names is not None:
        if not isinstance(names, (list, tuple)):
            raise TypeError(f"names: expected a list of strings, got {type(names).__name__}")
        if len(names) != len(args):
            raise ValueError(
                f"names: expected {len(args)} names, one per argument, got {len(names)}"
            )
    specs: list[Arg] = []
    symbols: list[tuple[Symbol, ...]] = []
    used: set[str] = set()
    for i, a in enumerate(args):
        where = f"args[{i}]"
        hook = getattr(type(a), "_lambdify_argument", None)
        if hook is not None and not isinstance(a, type):
            matrix, what = a._lambdify_argument()
            syms = _matrix_symbols(matrix, where)
            trailing: tuple[int, ...] = (len(syms),)
            stems = (_stem(syms[:3]), _stem(syms[3:]))
            default = "s" if None in stems else (stems[0] or "s").lower()
        elif isinstance(a, MatrixBase):
            if len(a) == 0:
                raise ValueError(f"{where}: expected a non-empty matrix of symbols, got {a!r}")
            syms = _matrix_symbols(a, where)
            trailing = (len(syms),) if 1 in a.shape else tuple(a.shape)
            what = f"a {len(syms)}-vector" if len(trailing) == 1 else f"a {a.rows}x{a.cols} matrix"
            default = _stem(syms) or "v"
        elif isinstance(a, Symbol):
            syms, trailing, what, default = (a,), (), "a scalar", a.name
        else:
            raise TypeError(
                f"{where}: expected a Symbol, a matrix of symbols (vector('A')) or a screw "
                f"with symbolic components, got {type(a).__name__} {a!r}"
            )
        if names is not None:
            name = names[i]
            if not is_identifier(name):
                raise ValueError(
                    f"names[{i}]: expected a Python identifier not starting with '_' and not "
                    f"'out', got {name!r}"
                )
            if name in used:
                raise ValueError(f"names[{i}]: expected distinct names, got {name!r} twice")
        else:
            name = default
            if not is_identifier(name) or name in used:
                base = name if is_identifier(name) else "arg"
                name = next(f"{base}{j}" for j in range(len(args) + 1) if f"{base}{j}" not in used)
        used.add(name)
        specs.append(Arg(name, trailing, what))
        symbols.append(syms)
    seen: dict[Symbol, str] = {}
    for spec, syms in zip(specs, symbols, strict=True):
        for sym in syms:
            if sym in seen:
                raise ValueError(
                    f"args: the symbol {sym} appears twice (in {seen[sym]} and {spec.name})"
                )
            seen[sym] = spec.name
    return specs, symbols


# ---------------------------------------------------------------- results


def normalise_expr(expr: Any) -> tuple[list[tuple[Out, tuple[Expr, ...]]], bool]:
    """Flatten ``expr`` to results; the flag says whether a tuple was given.

    An object with a method ``_lambdify_outputs()`` stands for what that method
    returns: a tuple of results (the core's common normal) or one matrix (a
    screw's 6 components, a rigid motion's 4x4 matrix).
    """
    expr = _outputs_of(expr, "expr", (tuple, MatrixBase), "a tuple or a matrix")
    is_tuple = isinstance(expr, (tuple, list))
    items = list(expr) if is_tuple else [expr]
    if not items:
        raise ValueError("expr: expected at least one result, got an empty tuple")
    outs = []
    for i, e in enumerate(items):
        where = f"expr[{i}]" if is_tuple else "expr"
        e = _outputs_of(e, where, (MatrixBase,), "a matrix")
        if isinstance(e, MatrixBase):
            if len(e) == 0:
                raise ValueError(f"{where}: expected a non-empty matrix, got {e!r}")
            trailing = (len(e),) if 1 in e.shape else tuple(e.shape)
            entries = []
            for x in e:
                entries.append(_scalar(x, where))
            outs.append((Out(trailing), tuple(entries)))
        else:
            outs.append((Out(()), (_scalar(e, where),)))
    return outs, is_tuple


def _outputs_of(e: Any, where: str, allowed: tuple[type, ...], expected: str) -> Any:
    hook = getattr(type(e), "_lambdify_outputs", None)
    if hook is None or isinstance(e, type):
        return e
    out = e._lambdify_outputs()
    if not isinstance(out, allowed):
        raise TypeError(
            f"{where}: _lambdify_outputs() must return {expected}, got {type(out).__name__}"
        )
    return out


def _scalar(e: Any, where: str) -> Expr:
    # bool is an int to Python, but True is not the number 1 to a user
    x = None
    if not isinstance(e, (bool, str)):
        try:
            x = sympify(e, strict=True)
        except SympifyError:
            x = None
    if not isinstance(x, Expr):
        raise TypeError(
            f"{where}: expected a SymPy expression, matrix, screw or a tuple of these, "
            f"got {type(e).__name__} {e!r}"
        )
    return x


def check_supported(x: Expr, backend: str) -> None:
    """Raise ``TypeError`` naming the first construct the back ends cannot print."""
    nodes = list(_postorder([x]))
    if any(node is I for node in nodes):
        raise ValueError(
            f"expr: expected real expressions (screwsym generates real arithmetic), got {x}"
        )
    for node in reversed(nodes):  # the outermost construct first
        if not isinstance(node, SUPPORTED):
            what = type(node).__name__
            raise TypeError(
                f"expr: backend {backend!r} cannot generate code for {what} ({node}); "
                f"supported: arithmetic, {SUPPORTED_NAMES}"
            )
        if isinstance(node, log) and len(node.args) != 1:  # pragma: no cover - SymPy folds it
            raise TypeError(f"expr: backend {backend!r} cannot generate code for {node}")
        if isinstance(node, (sympy.Rational, sympy.Float)):
            _check_double(node)


def _check_double(c: Any) -> None:
    """Raise ``ValueError`` naming ``c``, a number whose nearest double is inf or 0.

    ``x/10**400`` would otherwise be ``x*0.0`` in generated code (``inf*x`` for
    ``x*10**400``): a silent wrong number wherever ``x`` makes the result a double.
    A rational's value is Python's correctly rounded ``p/q`` (see the printers).
    """
    try:
        value = c.p / c.q if isinstance(c, sympy.Rational) else float(c)
    except OverflowError:
        value = math.inf
    if math.isinf(value) or (value == 0 and c != 0):
        text = str(c)
        shown = text if len(text) <= 40 else f"{sympy.N(c, 6)} (written in {len(text)} characters)"
        raise ValueError(
            f"expr: the constant {shown} is out of the range of float64 (magnitudes 4.9e-324 "
            f"to 1.8e308): generated code would hold {'inf' if value else '0'} for it; "
            "rescale the expression (other units) so that each of its constants is a double"
        )


def _postorder(roots: Sequence[Basic]):
    """Every node of the trees ``roots`` once (by identity), each after its arguments.

    An explicit stack, not recursion: a closed form may be deeper than Python's
    recursion limit (SymPy's own walks, ``free_symbols``, ``xreplace``,
    ``srepr``, recurse once per level).
    """
    seen: set[int] = set()
    for root in roots:
        if id(root) in seen:
            continue
        stack: list[tuple[Basic, bool]] = [(root, False)]
        while stack:
            node, ready = stack.pop()
            if ready:
                yield node
                continue
            if id(node) in seen:
                continue
            seen.add(id(node))
            stack.append((node, True))
            stack.extend((a, False) for a in reversed(node.args) if id(a) not in seen)


def _make(node: Basic, args: list) -> Basic:
    """``node.func(*args)`` without evaluation: the same operations, no assumptions asked."""
    if isinstance(node, ExprCondPair):
        return node.func(*args)
    return node.func(*args, evaluate=False)


def _free_symbols(roots: Sequence[Basic]) -> set[Symbol]:
    return {n for n in _postorder(roots) if isinstance(n, Symbol)}


def _rename(roots: Sequence[Basic], mapping: dict) -> tuple[list[Basic], int]:
    """``xreplace`` of the leaves by ``mapping``, without recursion; and the deepest level."""
    new: dict[int, Basic] = {}
    depth: dict[int, int] = {}
    for node in _postorder(roots):
        if not node.args:
            new[id(node)] = mapping.get(node, node) if isinstance(node, Symbol) else node
            depth[id(node)] = 0
            continue
        args = [new[id(a)] for a in node.args]
        changed = any(a is not b for a, b in zip(args, node.args, strict=True))
        new[id(node)] = _make(node, args) if changed else node
        depth[id(node)] = 1 + max(depth[id(a)] for a in node.args)
    return [new[id(r)] for r in roots], max((depth[id(r)] for r in roots), default=0)


def _serial(roots: Sequence[Basic]) -> str:
    """A text that determines the trees ``roots`` (``srepr`` of each leaf), without recursion."""
    index: dict[int, int] = {}
    lines: list[str] = []
    for node in _postorder(roots):
        index[id(node)] = len(lines)
        if node.args:
            lines.append(f"{type(node).__name__}({','.join(str(index[id(a)]) for a in node.args)})")
        else:
            lines.append(srepr(node))
    lines.append("roots " + ",".join(str(index[id(r)]) for r in roots))
    return "\n".join(lines)


# ---------------------------------------------------------------- the plan


_DIGEST: list[str] = []


def code_digest() -> str:
    """A digest of screwsym's source and SymPy's version: generated code from another version never matches.

    It enters the key of every generated function (so the names of the
    modules and libraries in the disk cache) and tags the index from which
    :mod:`screwsym.numeric` reads its functions back in a new process without
    building their symbolic expressions again.  It covers SymPy's version and
    every ``.py`` file of screwsym, in every subpackage, each by its path
    relative to the package: the code generator and the formulas it is given
    alike (an edited formula of the core, or a module moved, changes it).
    This is the union of what the generated code and the numeric functions'
    index depend on, so that neither cache can serve code from other source.
    Computed once per process (a few milliseconds).
    """
    if not _DIGEST:
        root = Path(__file__).resolve().parents[1]
        h = hashlib.sha256(sympy.__version__.encode())
        for path in sorted(root.rglob("*.py")):
            h.update(path.relative_to(root).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
        _DIGEST.append(h.hexdigest()[:24])
    return _DIGEST[0]


def key_of(specs, symbols, outs, is_tuple, use_cse, name, backend) -> tuple[str, list[Expr]]:
    """Content hash of the generated code, and the expressions with screwsym's names."""
    mapping: dict[Symbol, Symbol] = {}
    k = 0
    for syms in symbols:
        for sym in syms:
            mapping[sym] = Symbol(f"_x{k}", real=True)
            k += 1
    flat, _ = _rename([x for _, exprs in outs for x in exprs], mapping)
    text = srepr((
        tuple((s.name, s.trailing, s.what) for s in specs),
        tuple(out.trailing for out, _ in outs),
        is_tuple, bool(use_cse), name, backend, code_digest(),
    )) + "\n" + _serial(flat)  # fmt: skip
    return hashlib.sha256(text.encode()).hexdigest()[:24], flat


def build_plan(args: Any, expr: Any, use_cse: bool, name: Any, names: Any, backend: str) -> Plan:
    """Check everything and return the plan (without CSE: see :func:`with_cse`)."""
    program = getattr(type(expr), "_lambdify_program", None)
    if program is not None and not isinstance(expr, type):
        assigns, outputs = expr._lambdify_program()
        return program_plan(args, assigns, outputs, name, names, backend)
    if name is not None and not isinstance(name, str):
        raise TypeError(f"name: expected a string, got {type(name).__name__} {name!r}")
    if name is not None and not is_identifier(name):
        raise ValueError(f"name: expected a Python identifier not starting with '_', got {name!r}")
    specs, symbols = normalise_args(args, names)
    outs, is_tuple = normalise_expr(expr)
    for _, exprs in outs:  # first: a supported tree binds no symbol (no Sum, Lambda, ...)
        for x in exprs:
            check_supported(x, backend)
    allowed = {s for syms in symbols for s in syms}
    free = _free_symbols([x for _, exprs in outs for x in exprs])
    missing = free - allowed
    if missing:
        listed = ", ".join(sorted(str(s) for s in missing))
        raise ValueError(f"expr: the symbols {listed} are not among args")
    key, flat = key_of(specs, symbols, outs, is_tuple, use_cse, name, backend)
    unpack = []
    k = 0
    for i, syms in enumerate(symbols):
        for c in range(len(syms)):
            unpack.append((i, c, Symbol(f"_x{k}", real=True)))
            k += 1
    stores, m = [], 0
    for j, (_, exprs) in enumerate(outs):
        for c in range(len(exprs)):
            stores.append((j, c, flat[m]))
            m += 1
    for _, _, e in stores:  # after renaming, only screwsym's symbols are left
        assert all(s.name.startswith("_x") for s in _free_symbols([e]))
    return Plan(
        tuple(specs), tuple(out for out, _ in outs), is_tuple, tuple(unpack), (),
        tuple(stores), name or f"lambdified_{key[:10]}", key,
    )  # fmt: skip


def program_plan(args: Any, assigns: Sequence[tuple[Symbol, Expr]], expr: Any, name: Any,
                 names: Any, backend: str) -> Plan:
    """The plan of a straight-line program: ``assigns`` ``(symbol, expr)`` in order, then ``expr``.

    The program's assignments become the plan's common subexpressions as given (not
    searched again; see :func:`prepared`), each symbol renamed ``_c<m>`` and each
    argument ``_x<k>``, so that no name of the program reaches generated source.  Each
    right-hand side may use the arguments and the symbols assigned before it.
    """
    if name is not None and not is_identifier(name):
        raise ValueError(f"name: expected a Python identifier not starting with '_', got {name!r}")
    specs, symbols = normalise_args(args, names)
    outs, is_tuple = normalise_expr(expr)
    mapping: dict[Symbol, Symbol] = {}
    for syms in symbols:
        for sym in syms:
            mapping[sym] = Symbol(f"_x{len(mapping)}", real=True)
    allowed = set(mapping)
    for m, (t, e) in enumerate(assigns):
        check_supported(e, backend)
        missing = _free_symbols([e]) - allowed
        if not isinstance(t, Symbol) or t in allowed or missing:
            raise ValueError(f"expr: assignment {m} ({t}) uses symbols that are not defined "
                             f"before it, or defines one twice: {sorted(map(str, missing))}")
        allowed.add(t)
        mapping[t] = Symbol(f"_c{m}", real=True)
    flat = [x for _, exprs in outs for x in exprs]
    for x in flat:
        check_supported(x, backend)
    missing = _free_symbols(flat) - allowed
    if missing:
        raise ValueError(f"expr: the symbols {sorted(map(str, missing))} are not among args")
    renamed, _ = _rename([e for _, e in assigns] + flat, mapping)
    text = srepr((
        tuple((s.name, s.trailing, s.what) for s in specs),
        tuple(out.trailing for out, _ in outs), is_tuple, "program", name, backend, code_digest(),
    )) + "\n" + _serial(renamed)  # fmt: skip
    key = hashlib.sha256(text.encode()).hexdigest()[:24]
    unpack = [(i, c, mapping[sym]) for i, syms in enumerate(symbols) for c, sym in enumerate(syms)]
    k = len(assigns)
    new_assigns = tuple((mapping[t], e) for (t, _), e in zip(assigns, renamed[:k], strict=True))
    stores, m = [], k
    for j, (_, exprs) in enumerate(outs):
        for c in range(len(exprs)):
            stores.append((j, c, renamed[m]))
            m += 1
    return Plan(tuple(specs), tuple(out for out, _ in outs), is_tuple, tuple(unpack), new_assigns,
                tuple(stores), name or f"lambdified_{key[:10]}", key)


def with_cse(plan: Plan) -> Plan:
    """The plan with common subexpressions assigned to ``c0, c1, ...``."""
    exprs = [e for _, _, e in plan.stores]
    replacements, reduced = cse(exprs, symbols=numbered_symbols("_c", real=True))
    stores = tuple((j, c, e) for (j, c, _), e in zip(plan.stores, reduced, strict=True))
    return Plan(plan.specs, plan.outs, plan.is_tuple, plan.unpack, tuple(replacements),
                stores, plan.name, plan.key)


def frozen(x: Any) -> Any:
    if isinstance(x, (list, tuple)):
        return tuple(frozen(i) for i in x)
    if isinstance(x, MatrixBase):
        return ImmutableMatrix(x)
    return x


#: the most arguments one printed sum or product has, and the deepest one printed
#: expression may be, in generated code (see :func:`straight_line`)
MAX_ARGS = 32
MAX_DEPTH = 24
#: deeper than this, or with more distinct nodes, SymPy's ``cse`` (which recurses once
#: per level, and whose search of sums and products grows faster than their size) is not
#: used: the repeated subexpressions, found by hashing (:func:`straight_line` with
#: ``shared``), become locals instead
CSE_DEPTH = 120
CSE_NODES = 8000


def straight_line(plan: Plan, shared: bool = False) -> Plan:
    """The plan with every expression cut into statements of bounded size: straight-line code.

    Python's compiler recurses once per operator of a sum ``a + b + c + ...``
    (a left-nested chain) and per nested call, so a closed form of 10^5
    operations raised ``RecursionError`` (or "too many nested parentheses")
    however it was printed.  Here each sum or product of more than
    :data:`MAX_ARGS` terms is summed in chunks, and each subexpression deeper
    than :data:`MAX_DEPTH` is assigned to a local ``_t<m>`` first, walking the
    trees in an explicit post-order (no recursion), so no printed statement is
    large or deep.  With ``shared``, every subexpression that occurs more than
    once becomes a local too: the common-subexpression elimination of trees
    too large or too deep for ``sympy.cse``.  The values are unchanged
    (the same operations, grouped).
    """
    counter = iter(range(10**12))
    emitted: list[tuple[Symbol, Expr]] = []
    new: dict[int, Basic] = {}
    depth: dict[int, int] = {}  # by id of the new node
    uses: dict[int, int] = {}
    roots = [e for _, e in plan.assigns] + [e for _, _, e in plan.stores]
    if shared:
        plan, roots = _canonical(plan, roots, uses)

    def emit(e: Basic) -> Symbol:
        t = Symbol(f"_t{next(counter)}", real=True)
        emitted.append((t, e))
        depth[id(t)] = 0
        return t

    def cut(e: Basic) -> Basic:
        for node in _postorder([e]):
            if id(node) in new:
                continue
            if not node.args:
                new[id(node)] = node
                depth[id(node)] = 0
                continue
            args = [new[id(a)] for a in node.args]
            if isinstance(node, (Add, Mul)):
                while len(args) > MAX_ARGS:  # sum (multiply) in chunks, each a statement
                    args = [emit(_make(node, args[i:i + MAX_ARGS]))
                            for i in range(0, len(args), MAX_ARGS)]
            same = len(args) == len(node.args) and all(
                a is b for a, b in zip(args, node.args, strict=False))
            x = node if same else _make(node, args)
            d = 1 + max((depth.get(id(a), 0) for a in args), default=0)
            if isinstance(x, Expr) and x.args and (d > MAX_DEPTH or uses.get(id(node), 0) > 1):
                x = emit(x)
            else:
                depth[id(x)] = d
            new[id(node)] = x
        return new[id(e)]

    assigns = []
    for sym, e in plan.assigns:
        x = cut(e)
        assigns.extend(emitted)
        emitted.clear()
        assigns.append((sym, x))
    stores = []
    for j, c, e in plan.stores:
        x = cut(e)
        assigns.extend(emitted)
        emitted.clear()
        stores.append((j, c, x))
    return Plan(plan.specs, plan.outs, plan.is_tuple, plan.unpack, tuple(assigns),
                tuple(stores), plan.name, plan.key)


def _canonical(plan: Plan, roots: list, uses: dict[int, int]) -> tuple[Plan, list]:
    """One object per distinct subexpression of ``roots``, and how many parents each has.

    Equal subtrees are found by hashing in post-order (each node after its
    arguments, which are already one object each, so that comparing two
    candidates looks one level deep): the common subexpressions of trees too
    large or too deep for ``sympy.cse``, found in linear time.
    """
    table: dict[Basic, Basic] = {}
    canon: dict[int, Basic] = {}
    for node in _postorder(roots):
        args = [canon[id(a)] for a in node.args]
        same = all(a is b for a, b in zip(args, node.args, strict=True))
        x = node if same else _make(node, args)
        found = table.get(x)
        if found is None:
            table[x] = found = x
            for a in set(map(id, args)):
                uses[a] = uses.get(a, 0) + 1
        canon[id(node)] = found
    for r in roots:  # a result used twice is computed once
        uses[id(canon[id(r)])] = uses.get(id(canon[id(r)]), 0) + 1
    n = len(plan.assigns)
    new_roots = [canon[id(r)] for r in roots]
    plan = Plan(plan.specs, plan.outs, plan.is_tuple, plan.unpack,
                tuple((sym, e) for (sym, _), e in zip(plan.assigns, new_roots[:n], strict=True)),
                tuple((j, c, e) for (j, c, _), e in zip(plan.stores, new_roots[n:], strict=True)),
                plan.name, plan.key)
    return plan, new_roots


def _depth(roots: Sequence[Basic]) -> int:
    depth: dict[int, int] = {}
    for node in _postorder(roots):
        depth[id(node)] = 1 + max((depth[id(a)] for a in node.args), default=-1)
    return max((depth[id(r)] for r in roots), default=0)


def prepared(plan: Plan, use_cse: bool) -> Plan:
    """The plan as the back ends print it: CSE if asked, then :func:`straight_line`.

    ``sympy.cse`` for trees up to :data:`CSE_DEPTH` levels deep; deeper ones
    share their repeated subexpressions through :func:`straight_line`.
    """
    if not use_cse or plan.assigns:  # a program's own assignments are its CSE
        return straight_line(plan)
    roots = [e for _, _, e in plan.stores]
    large = _depth(roots) > CSE_DEPTH or sum(1 for _ in _postorder(roots)) > CSE_NODES
    return straight_line(plan, shared=True) if large else straight_line(with_cse(plan))
