"""Print a :class:`~screwsym.codegen._plan.Plan` for each target.

One plan (unpack, CSE assignments, store) is printed by four small
functions: the single-point Python path, the NumPy block loop, the numba
loop (the same Python with array indexing) and C.  The wrapper that checks
input and calls the loop is shared by every back end.  No text a user gave
appears here except through :func:`py_comment` / :func:`c_comment`.
"""

from __future__ import annotations

import math

from ._plan import Plan
from ._printers import C_HELPERS, BlockPrinter, CPrinter, NumbaPrinter, ScalarPrinter


def py_comment(text: str) -> str:
    """``text`` as one line of a Python comment: escaped, printable ASCII only."""
    return text.encode("unicode_escape").decode("ascii")


def c_comment(text: str) -> str:
    """``text`` as the inside of a C comment: printable ASCII, no ``*/``, one line."""
    safe = "".join(ch if " " <= ch <= "~" else "?" for ch in text)
    return safe.replace("*/", "* /").replace("/*", "/ *")


def describe(plan: Plan) -> list[str]:
    """What each parameter and result is (user text: only ever printed escaped)."""
    lines = [f"function {plan.name} (key {plan.key})"]
    for i, spec in enumerate(plan.specs):
        lines.append(f"_a{i}: {spec.name}, {spec.size} number(s), {spec.what}")
    for j, out in enumerate(plan.outs):
        lines.append(f"_o{j}: result {j}, {out.size} number(s), shape (...)+{out.trailing}")
    return lines


def _params(plan: Plan) -> str:
    return ", ".join(f"_a{i}" for i in range(len(plan.specs)))


def _outs(plan: Plan) -> str:
    return ", ".join(f"_o{j}" for j in range(len(plan.outs)))


def _walk(plan: Plan, printer, unpack, assign, store) -> list[str]:
    """The plan's three steps as lines of one target: each step's line format is given.

    ``unpack(k, c, x)``, ``assign(sym, code)`` and ``store(j, c, code)`` format one
    line each; ``unpack`` may be None when the target unpacks its own way.
    """
    lines = [unpack(k, c, x) for k, c, x in plan.unpack] if unpack else []
    lines += [assign(sym, printer(e)) for sym, e in plan.assigns]
    lines += [store(j, c, printer(e)) for j, c, e in plan.stores]
    return lines


def _unpack_scalar(plan: Plan, ind: str) -> list[str]:
    lines = []
    for i, spec in enumerate(plan.specs):
        targets = [str(x) for k, _, x in plan.unpack if k == i]
        if not spec.trailing:
            lines.append(f"{ind}{targets[0]} = _a{i}")
        elif len(spec.trailing) == 1:
            lines.append(f"{ind}{', '.join(targets)}, = _a{i}.tolist()")
        else:
            lines.append(f"{ind}{', '.join(targets)}, = _a{i}.reshape(-1).tolist()")
    return lines


def _scalar_path(plan: Plan) -> list[str]:
    """Pure-Python float evaluation for a single point; IEEE cases fall through.

    Taken when every argument is a native ``float64`` array of its own shape
    (no batch) or a Python/NumPy float; integer input takes the array path,
    so that no Python integer arithmetic (exact, unlike the other paths) runs.
    """
    printer = ScalarPrinter()
    conds = []
    for i, spec in enumerate(plan.specs):
        if spec.trailing:
            conds.append(
                f"_type(_a{i}) is _ndarray and _a{i}.shape == {spec.trailing!r} "
                f"and _a{i}.dtype is _dt"
            )
        else:
            conds.append(f"(_type(_a{i}) is float or _type(_a{i}) is _f64)")
    lines = [f"    if out is None and {' and '.join(conds)}:", "        try:"]
    lines += _unpack_scalar(plan, "            ")
    for sym, e in plan.assigns:
        lines.append(f"            {sym} = {printer.doprint(e)}")
    results = []
    for j, out in enumerate(plan.outs):
        items = [printer.doprint(e) for jj, _, e in plan.stores if jj == j]
        if not out.trailing:
            results.append(f"_f64({items[0]})")
        else:  # packed doubles into a writeable buffer: faster than numpy.array of a list
            arr = f"_fb(_ba(_pk{out.size}({', '.join(items)})))"
            results.append(arr if len(out.trailing) == 1 else f"{arr}.reshape({out.trailing!r})")
    ret = ", ".join(results) + ("," if plan.is_tuple and len(results) == 1 else "")
    lines.append(f"            return {ret}")
    lines.append("        except (ZeroDivisionError, ValueError, OverflowError, _StructError):")
    lines.append("            pass  # IEEE 754 inf/nan: the array code below gives it")
    return lines


def _returns(plan: Plan) -> str:
    parts = [f"_o{j}.reshape(_shape + {out.trailing!r})[()]" for j, out in enumerate(plan.outs)]
    return ", ".join(parts) + ("," if plan.is_tuple and len(parts) == 1 else "")


#: plans of more statements than this have no single-point fast path (a single point
#: takes the compiled loop, one row): printing and compiling a huge closed form twice
#: costs seconds, and past a few hundred statements numba's or C's loop of one row is
#: faster than Python floats (the UR5's inverse kinematics, 538 statements: 8 us in numba
#: against about 45 us on floats)
SCALAR_STATEMENTS = 500
#: ... and in the NumPy back end, whose array code pays per operation on arrays of one row:
#: the inverse kinematics of the UR5, the PUMA 560 and the Panda (every branch one program,
#: ``screwsym.numeric.inverse_kinematics_function``, 508-538 statements) take one pose in
#: about 45 us on floats against 1.4 ms on the array code (``benchmarks/bench_ik.py``)
SCALAR_STATEMENTS_NUMPY = 1000


def _wrapper(plan: Plan, body: list[str], contiguous: bool, fast: bool = False,
             scalar_limit: int = SCALAR_STATEMENTS) -> list[str]:
    params = _params(plan)
    lines = [f"def _fn({params}, *, out=None):"]
    if fast:  # the extension module's point(): None unless one plain point
        lines += [
            "    if out is None:",
            f"        _r = _point({params})",
            "        if _r is not None:",
            "            return _r",
        ]
    elif len(plan.assigns) <= scalar_limit:  # a huge plan: printed (and compiled) once
        lines += _scalar_path(plan)
    lines.append(
        f"    ({params},), ({_outs(plan)},), _shape, _n = "
        f"_prepare(_SPECS, ({params},), out, _OUTS, {contiguous})"
    )
    lines += body
    lines.append(f"    return {_returns(plan)}")
    return lines


def _header(plan: Plan, backend: str) -> list[str]:
    lines = [f"# Generated by screwsym.codegen (backend {backend!r}); do not edit."]
    lines += ["# " + py_comment(text) for text in describe(plan)]
    return lines


def numpy_source(plan: Plan) -> str:
    """The NumPy back end: the wrapper with a loop over blocks of rows."""
    printer = BlockPrinter()
    body = [
        "    with _errstate(divide='ignore', invalid='ignore', over='ignore'):",
        "        for _i in range(0, _n, _BLOCK):",
        "            _j = _i + _BLOCK",
    ]
    ind = "            "
    for i in range(len(plan.specs)):
        body.append(f"{ind}_b = _a{i} if _a{i}.shape[0] == 1 else _a{i}[_i:_j]")
        for k, c, x in plan.unpack:
            if k == i:
                body.append(f"{ind}{x} = _b[:, {c}]")
    body += _walk(
        plan,
        printer.doprint,
        None,
        lambda sym, code: f"{ind}{sym} = {code}",
        lambda j, c, code: (
            f"{ind}_o{j}[_i:_j] = {code}" if not plan.outs[j].trailing
            else f"{ind}_o{j}[_i:_j, {c}] = {code}"
        ),
    )
    return "\n".join(_header(plan, "numpy") + _wrapper(plan, body, False,
                                                       scalar_limit=SCALAR_STATEMENTS_NUMPY)) + "\n"


def kernel_source(plan: Plan) -> list[str]:
    """The fused loop over ``_n`` rows (Python syntax, compiled by numba)."""
    printer = NumbaPrinter()
    params = _params(plan)
    lines = [f"def _kernel_py(_n, {params}, {_outs(plan)}):"]
    for i in range(len(plan.specs)):
        lines.append(f"    _d{i} = 0 if _a{i}.shape[0] == 1 else 1")
    lines.append("    for _i in range(_n):")
    ind = "        "
    lines += _walk(
        plan,
        printer.doprint,
        lambda k, c, x: f"{ind}{x} = _a{k}[_i * _d{k}, {c}]",
        lambda sym, code: f"{ind}{sym} = {code}",
        lambda j, c, code: (
            f"{ind}_o{j}[_i] = {code}" if not plan.outs[j].trailing
            else f"{ind}_o{j}[_i, {c}] = {code}"
        ),
    )
    return lines


def numba_source(plan: Plan, helpers: str) -> str:
    """A module: helpers and kernel compiled by numba (cached on disk), and the wrapper.

    numba is imported, and the loop compiled or loaded from numba's disk
    cache, on the first call that needs the loop: a single point never does.
    """
    lines = _header(plan, "numba") + [
        "import math as _m",
        "import struct as _struct",
        "import threading as _threading",
        "",
        "import numpy as _np",
        "",
        "from screwsym.codegen._runtime import prepare as _prepare",
        "",
        "_type, _ndarray, _f64, _array = type, _np.ndarray, _np.float64, _np.array",
        "_dt = _np.dtype(_np.float64)",
        "_fb, _ba, _StructError = _np.frombuffer, bytearray, _struct.error",
        *[f"_pk{k} = _struct.Struct('{k}d').pack" for k in sorted({o.size for o in plan.outs})],
        "_SPECS = _OUTS = None  # set by the loader",
        "_LOCK = _threading.Lock()",
        "",
        helpers,
    ]
    lines += kernel_source(plan)
    lines += [
        "",
        "",
        "def _load():",
        "    global _kernel, _nb_min, _nb_max, _nb_sign, _nb_mod",
        "    with _LOCK:",
        "        if _kernel is _stub:",
        "            from numba import njit as _njit",
        "",
        "            _nb_min = _njit(cache=True)(_min)",
        "            _nb_max = _njit(cache=True)(_max)",
        "            _nb_sign = _njit(cache=True)(_sign)",
        "            _nb_mod = _njit(error_model='numpy', cache=True)(_mod)",
        "            _kernel = _njit(error_model='numpy', cache=True)(_kernel_py)",
        "    return _kernel",
        "",
        "",
        "def _stub(*args):",
        "    return _load()(*args)",
        "",
        "",
        "_kernel = _stub",
        "",
        "",
    ]
    body = [f"    _kernel(_n, {_params(plan)}, {_outs(plan)})"]
    lines += _wrapper(plan, body, True)
    return "\n".join(lines) + "\n"


def c_wrapper_source(plan: Plan, fast: bool = False) -> str:
    """The Python wrapper of the C loop (``_kernel``); ``fast``: one point by ``_point``."""
    body = [f"    _kernel(_n, {_params(plan)}, {_outs(plan)})"]
    return "\n".join(_header(plan, "c") + _wrapper(plan, body, True, fast)) + "\n"


#: plans whose assignments print to more characters than this are written for C as a chain
#: of functions of about this size each (below)
C_CHUNK = 20_000


def _c_input(plan: Plan, k: int, c: int) -> str:
    """Component ``c`` of input ``k`` in the point function's parameters."""
    return f"_a{k}[{c}]" if plan.specs[k].trailing else f"_a{k}"


def _c_chunks(plan: Plan, cname: str, printer: CPrinter,
              codes: list[str]) -> tuple[list[str], list[str]]:
    """A large plan's point body as functions of about :data:`C_CHUNK` characters each.

    ``gcc -O3`` spends time superlinear in the size of one function on register allocation
    (``-ftime-report``: 90% in IRA/LRA and the combiner for a body of 7,000 monomials);
    each part here is a ``noinline`` function of its own, and the values one part passes to
    a later one go through a scratch array of the point function.  ``codes`` are the
    assignments' right-hand sides, printed.  Returns the parts' definitions and the point
    function's body.
    """
    slot: dict = {}  # the symbols read by a later part (or the stores): their index in _t
    made_in: dict = {}
    parts: list[list] = [[]]
    size = 0
    for (sym, e), code in zip(plan.assigns, codes, strict=True):
        if size > C_CHUNK:
            parts.append([])
            size = 0
        parts[-1].append((sym, e, code))
        made_in[sym] = len(parts) - 1
        size += len(code)
    inputs = {x for _, _, x in plan.unpack}
    uses = [set().union(*(e.free_symbols for _, e, _ in part)) for part in parts]
    uses.append(set().union(*(e.free_symbols for _, _, e in plan.stores)) if plan.stores else set())
    for k, used in enumerate(uses):
        for x in sorted(used, key=str):
            if (x in inputs or made_in.get(x, k) < k) and x not in slot:
                slot[x] = len(slot)
    defs: list[str] = []
    for k, part in enumerate(parts):
        defs += [f"static __attribute__((noinline)) void {cname}_part{k}(double *restrict _t)", "{"]
        defs += [f"    const double {x} = _t[{slot[x]}];" for x in sorted(uses[k], key=str)
                 if x in slot and made_in.get(x, -1) < k]
        for sym, _, code in part:
            defs.append(f"    const double {sym} = {code};")
            if sym in slot:
                defs.append(f"    _t[{slot[sym]}] = {sym};")
        defs += ["}", ""]
    body = [f"    double _t[{max(len(slot), 1)}];"]
    body += [f"    _t[{slot[x]}] = {_c_input(plan, k, c)};" for k, c, x in plan.unpack if x in slot]
    body += [f"    {cname}_part{k}(_t);" for k in range(len(parts))]
    body += [f"    const double {x} = _t[{slot[x]}];" for x in sorted(uses[-1], key=str)
             if x in slot]
    body += [f"    _o{j}[{c}] = {printer.doprint_line(e)};" for j, c, e in plan.stores]
    return defs, body


#: how far ahead the loop asks for its input rows, in bytes of the widest row, in each of
#: its :data:`STRETCHES`: a loop with a few operations per row leaves too few cache misses
#: in flight to read at the memory's speed (``numeric.pitch`` on 10^6 screws, at the time
#: of a PLT call per row: 7.2 -> 5.6 ns a screw with 6 KB ahead; distances of 1.5-6 KB
#: measure alike since)
PREFETCH_BYTES = 3072

#: the loop reads the rows in this many stretches in turn (row ``i`` of each, then row
#: ``i + 1`` of each): one core can have more reads in flight over several streams (a
#: bare sum of the 6 doubles of 10^6 screws in hand C, load average 2: 4.7 ns a screw in
#: one pass, 4.0 with the prefetch, 3.4-3.6 in four stretches; under a load of 6, one and
#: four stretches measure alike)
STRETCHES = 4

#: the loop is compiled twice where GCC and glibc can (function multiversioning: the
#: dynamic loader picks the one the CPU runs, so that a library in the disk cache still runs
#: on another machine): for AVX2 (VEX encoding, three-operand instructions: the foot point
#: 4.6 -> 4.2 ns a screw) and the baseline.  Not FMA: a fused multiply-add rounds once where
#: the other back ends (and the point function) round twice, so results would differ by an
#: ulp from machine to machine; AVX2 alone changes no result (no reassociation either).
C_LOOP_HEADER = """\
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 6 \\
    && defined(__GLIBC__) && !defined(SS_NO_CLONES)
#define SS_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SS_CLONES
#endif
"""


def _prefetches(plan: Plan) -> tuple[int, list[str]]:
    """The loop's look-ahead in points and its prefetch statements (one per input, row ``r``)."""
    widest = max([math.prod(s.trailing) for s in plan.specs if s.trailing] + [1])
    ahead = max(16, PREFETCH_BYTES // (8 * widest))
    return ahead, [f"SS_PREFETCH(_a{i} + (r + {ahead}) * _s{i});" for i in range(len(plan.specs))]


def c_source(plan: Plan, cname: str) -> str:
    """C99: ``cname_point`` for one point and ``cname`` looping over ``n`` points.

    The point's code is ``cname_eval`` (``static inline``: the loop inlines it,
    where a call of the exported ``cname_point`` from the loop would go through
    the library's PLT, a call per row).  The loop returns the number of rows
    whose first result is ``nan`` (one compare a row; callers that mark rows with
    ``nan``, :mod:`screwsym.numeric`, need no pass over the result to find them).
    """
    printer = CPrinter()
    point_params, point_args, loop_params, call_args = [], [], ["size_t n"], []
    for i, spec in enumerate(plan.specs):
        if spec.trailing:
            point_params.append(f"const double *restrict _a{i}")
            call_args.append(f"_a{i} + r * _s{i}")
        else:
            point_params.append(f"double _a{i}")
            call_args.append(f"_a{i}[r * _s{i}]")
        point_args.append(f"_a{i}")
        loop_params += [f"const double *_a{i}", f"ptrdiff_t _s{i}"]
    for j, out in enumerate(plan.outs):
        point_params.append(f"double *restrict _o{j}")
        point_args.append(f"_o{j}")
        loop_params.append(f"double *_o{j}")
        call_args.append(f"_o{j} + r * {out.size}")
    lines = [f"/* Generated by screwsym.codegen.c_source: {cname}."]
    lines += [f" * {c_comment(text)}" for text in describe(plan)]
    lines += [
        " * Screws are 6 doubles in the order (S; S0); a matrix is stored by rows.",
        f" * {cname}_point evaluates one point; {cname} loops over n points and reads",
        " * row i of input k at _ak + i*_sk: _sk is its row length, or 0 to broadcast",
        " * one row to all n; it returns the number of rows whose first result is nan.",
        " * Link with -lm. */",
        "#include <math.h>",
        "#include <stddef.h>",
        "",
        C_HELPERS,
        "#if defined(__GNUC__) || defined(__clang__)",
        "#define SS_UNLIKELY(c) __builtin_expect(!!(c), 0)",
        "#else",
        "#define SS_UNLIKELY(c) (c)",
        "#endif",
        C_LOOP_HEADER,
    ]
    codes = [printer.doprint_line(e) for _, e in plan.assigns]
    if sum(map(len, codes)) > C_CHUNK:
        defs, body = _c_chunks(plan, cname, printer, codes)
    else:
        defs = []
        body = [f"    const double {x} = {_c_input(plan, k, c)};" for k, c, x in plan.unpack]
        body += [f"    const double {sym} = {code};"
                 for (sym, _), code in zip(plan.assigns, codes, strict=True)]
        body += [f"    _o{j}[{c}] = {printer.doprint_line(e)};" for j, c, e in plan.stores]
    lines += defs
    lines += [f"static inline void {cname}_eval({', '.join(point_params)})", "{"]
    lines += body
    ahead, prefetches = _prefetches(plan)
    first = f"_o0[r * {plan.outs[0].size}]"
    row = [f"{cname}_eval({', '.join(call_args)});", f"if (SS_UNLIKELY({first} != {first})) ++bad;"]
    k = STRETCHES
    lines += [
        "}",
        "",
        f"void {cname}_point({', '.join(point_params)})",
        "{",
        f"    {cname}_eval({', '.join(point_args)});",
        "}",
        "",
        f"SS_CLONES size_t {cname}({', '.join(loop_params)})",
        "{",
        f"    /* {k} stretches of q rows read in turn, each asking for its rows {ahead} ahead */",
        f"    const size_t q = n / {k};",
        "    size_t bad = 0, i = 0;",
        f"    for (; i + {ahead} < q; ++i) {{",
        f"        for (size_t r = i; r < {k} * q; r += q) {{",
        *(f"            {p}" for p in prefetches),
        *(f"            {x}" for x in row),
        "        }",
        "    }",
        "    for (; i < q; ++i) {",
        f"        for (size_t r = i; r < {k} * q; r += q) {{",
        *(f"            {x}" for x in row),
        "        }",
        "    }",
        f"    for (size_t r = {k} * q; r < n; ++r) {{",
        *(f"        {x}" for x in row),
        "    }",
        "    return bad;",
        "}",
        "",
    ]
    return "\n".join(lines)


def c_extension_source(plan: Plan, cname: str) -> str:
    """A CPython extension module ``cname`` around ``cname_point``: one point per fast call.

    Its one function, ``point(*args)`` (``METH_FASTCALL``: no argument tuple
    is built), evaluates a single point when every argument is exactly what
    the single-point path takes (a C-contiguous native ``float64`` array of
    the argument's own shape, or a Python or NumPy float) and returns the
    results as NumPy arrays (a scalar as ``numpy.float64``); for anything
    else it returns ``None`` and the Python wrapper takes the general path.
    Appended to :func:`c_source` (which it calls); every identifier is
    screwsym's, and ``cname`` is ``screwsym_k`` and a hex digest.
    """
    n = len(plan.specs)
    lines = [
        "",
        "/* The CPython extension module: one point per METH_FASTCALL call. */",
        "#define PY_SSIZE_T_CLEAN",
        "#include <Python.h>",
        "#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION",
        "#include <numpy/arrayobject.h>",
        "#include <numpy/arrayscalars.h>",
        "",
        "static PyArray_Descr *screwsym_f64;",
        "",
        "static int screwsym_vec(PyObject *o, int nd, const npy_intp *dims, double **p)",
        "{",
        "    if (!PyArray_CheckExact(o)) return 0;",
        "    PyArrayObject *a = (PyArrayObject *)o;",
        "    if (PyArray_TYPE(a) != NPY_DOUBLE || PyArray_NDIM(a) != nd",
        "        || !PyArray_ISCARRAY_RO(a) || !PyArray_ISNOTSWAPPED(a)) return 0;",
        "    for (int k = 0; k < nd; ++k) if (PyArray_DIMS(a)[k] != dims[k]) return 0;",
        "    *p = (double *)PyArray_DATA(a);",
        "    return 1;",
        "}",
        "",
        "static int screwsym_num(PyObject *o, double *x)",
        "{",
        "    if (!PyFloat_CheckExact(o) && !PyArray_IsScalar(o, Double)) return 0;",
        "    *x = PyFloat_AS_DOUBLE(o);",
        "    return 1;",
        "}",
        "",
        f"static PyObject *{cname}_fast(PyObject *self, PyObject *const *args, Py_ssize_t nargs)",
        "{",
        "    (void)self;",
        f"    if (nargs != {n}) Py_RETURN_NONE;",
    ]
    call = []
    for i, spec in enumerate(plan.specs):
        if spec.trailing:
            dims = ", ".join(str(d) for d in spec.trailing)
            lines += [
                f"    static const npy_intp _d{i}[] = {{{dims}}};",
                f"    double *_p{i};",
                f"    if (!screwsym_vec(args[{i}], {len(spec.trailing)}, _d{i}, &_p{i}))"
                " Py_RETURN_NONE;",
            ]
            call.append(f"_p{i}")
        else:
            lines += [f"    double _v{i};",
                      f"    if (!screwsym_num(args[{i}], &_v{i})) Py_RETURN_NONE;"]
            call.append(f"_v{i}")
    results = list(range(len(plan.outs)))
    lines += [f"    PyObject *_r{j} = NULL;" for j in results]  # all set before any goto
    for j, out in enumerate(plan.outs):
        if out.trailing:
            dims = ", ".join(str(d) for d in out.trailing)
            lines += [
                f"    npy_intp _e{j}[] = {{{dims}}};",
                f"    _r{j} = PyArray_SimpleNew({len(out.trailing)}, _e{j}, NPY_DOUBLE);",
                f"    if (_r{j} == NULL) goto fail;",
            ]
            call.append(f"(double *)PyArray_DATA((PyArrayObject *)_r{j})")
        else:
            lines.append(f"    double _w{j};")
            call.append(f"&_w{j}")
    lines.append(f"    {cname}_point({', '.join(call)});")
    for j, out in enumerate(plan.outs):
        if not out.trailing:
            lines += [f"    _r{j} = PyArray_Scalar(&_w{j}, screwsym_f64, NULL);",
                      f"    if (_r{j} == NULL) goto fail;"]
    if plan.is_tuple:
        lines += [f"    PyObject *_t = PyTuple_New({len(plan.outs)});",
                  "    if (_t == NULL) goto fail;"]
        lines += [f"    PyTuple_SET_ITEM(_t, {j}, _r{j});" for j in results]
        lines.append("    return _t;")
    else:
        lines.append("    return _r0;")
    lines += ["fail:"]
    lines += [f"    Py_XDECREF(_r{j});" for j in results]
    lines += [
        "    return NULL;",
        "}",
        "",
        f"static PyMethodDef {cname}_methods[] = {{",
        f'    {{"point", (PyCFunction)(void (*)(void)){cname}_fast, METH_FASTCALL, NULL}},',
        "    {NULL, NULL, 0, NULL}",
        "};",
        "",
        f"static struct PyModuleDef {cname}_module = {{",
        f'    PyModuleDef_HEAD_INIT, "{cname}", NULL, -1, {cname}_methods,',
        "    NULL, NULL, NULL, NULL",
        "};",
        "",
        f"PyMODINIT_FUNC PyInit_{cname}(void)",
        "{",
        "    import_array();",
        "    screwsym_f64 = PyArray_DescrFromType(NPY_DOUBLE);",
        f"    return PyModule_Create(&{cname}_module);",
        "}",
        "",
    ]
    return "\n".join(lines)
