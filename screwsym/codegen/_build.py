"""Turn printed plans into functions: exec, numba, C; the caches.

In memory: a bounded LRU cache of built functions, one build per signature
even when many threads ask at once.  On disk (numba's modules, C's shared
libraries): a content-addressed cache in the user's cache directory, see
:func:`cache_dir`.
"""

from __future__ import annotations

import ctypes
import functools
import hashlib
import importlib.util
import json
import linecache
import math
import os
import shutil
import stat
import struct
import subprocess
import sys
import tempfile
import threading
from collections import OrderedDict
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from . import _emit, generated
from ._plan import Out, Plan, prepared
from ._printers import PY_HELPERS
from ._runtime import Arg, Trailings, prepare

#: rows per block in the NumPy back end: 16384 rows of float64 temporaries
#: (128 KiB each) stay in the L2 cache; measured best between 4096 and 65536.
BLOCK: int = 16384

#: at most this many generated functions are kept in memory (least recently used go first)
CACHE_SIZE: int = 512

_CACHE: OrderedDict[tuple, Callable] = OrderedDict()
_LOCK = threading.Lock()
_BUILDING: dict[tuple, threading.Lock] = {}


def cached(key: tuple, build: Callable[[], Callable]) -> Callable:
    """The function cached under ``key``, built once (per key) by ``build``."""
    with _LOCK:
        fn = _CACHE.get(key)
        if fn is not None:
            _CACHE.move_to_end(key)
            return fn
        lock = _BUILDING.setdefault(key, threading.Lock())
    with lock:  # one build per key; other threads asking for it wait here
        try:
            with _LOCK:
                fn = _CACHE.get(key)
            if fn is None:
                fn = build()
                with _LOCK:
                    _CACHE[key] = fn
                    while len(_CACHE) > CACHE_SIZE:
                        _CACHE.popitem(last=False)
        finally:
            with _LOCK:
                _BUILDING.pop(key, None)
    return fn


def clear_cache() -> None:
    """Forget every generated function held in memory (the disk cache stays)."""
    with _LOCK:
        _CACHE.clear()


def cache_dir() -> Path | None:
    """The directory of generated modules and libraries, created with mode 0o700.

    ``$SCREWSYM_CACHE_DIR`` if set, else ``$XDG_CACHE_HOME/screwsym``, else
    ``~/.cache/screwsym``.  None (no disk cache: functions are built in
    memory) when it cannot be created, or is not a directory (a symbolic link
    is not followed) owned by this user, that others cannot write and this
    process can.  Its subfolders (``numba/``, ``c/``) are held to the same
    rules.  Files are named by a content hash of the generated code (which
    includes :func:`screwsym.codegen.code_digest`, a digest of screwsym's
    source) and by the SHA-256 of their own content, which is checked before
    a file is loaded; they are written atomically, and at most
    :data:`DISK_FILES` of each kind are kept.
    """
    root = os.environ.get("SCREWSYM_CACHE_DIR")
    if not root:
        base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
        root = os.path.join(base, "screwsym")
    path = Path(root)
    try:
        path.mkdir(mode=0o700, parents=True, exist_ok=True)
    except OSError:
        return None
    return path if _is_private(path, stat.S_ISDIR) else None


def _is_private(path: Path, kind: Callable[[int], bool]) -> bool:
    """``path`` is of ``kind`` (not a link), owned by this user, not writable by others.

    A directory must also be writable by this process (a read-only cache is not used)."""
    try:
        st = path.lstat()
    except OSError:
        return False
    return (
        kind(st.st_mode)
        and (not hasattr(os, "getuid") or st.st_uid == os.getuid())
        and not st.st_mode & (stat.S_IWGRP | stat.S_IWOTH)
        and (not stat.S_ISDIR(st.st_mode) or os.access(path, os.W_OK | os.X_OK))
    )


def _subdir(name: str) -> Path | None:
    """The subfolder ``name`` of the cache, or None where it is not private to this user.

    ``os.mkdir`` does not follow a link; an existing link, a folder of another
    user or one that others can write (or its ``__pycache__``, where numba
    keeps its own files) makes the disk cache unused."""
    root = cache_dir()
    if root is None:
        return None
    sub = root / name
    try:
        os.mkdir(sub, 0o700)
    except FileExistsError:
        pass
    except OSError:
        return None
    if not _is_private(sub, stat.S_ISDIR):
        return None
    pycache = sub / "__pycache__"
    if os.path.lexists(pycache) and not _is_private(pycache, stat.S_ISDIR):
        return None
    return sub


#: hex digits of a file's SHA-256 in its name
DIGEST_CHARS = 32


def _digest(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()[:DIGEST_CHARS]


def _read_private(path: Path) -> bytes | None:
    """The bytes of the regular file ``path`` (not a link) if it is private to this user."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
    except OSError:
        return None
    with os.fdopen(fd, "rb") as fh:
        st = os.fstat(fh.fileno())
        if (
            not stat.S_ISREG(st.st_mode)
            or (hasattr(os, "getuid") and st.st_uid != os.getuid())
            or st.st_mode & (stat.S_IWGRP | stat.S_IWOTH)
        ):
            return None
        return fh.read()


def find_artifact(sub: Path, stem: str, suffix: str) -> tuple[Path, bytes] | None:
    """The file ``{stem}-{digest}{suffix}`` of ``sub`` whose content has that digest, read.

    A file whose content does not match the digest in its name, or that is
    not a private regular file, is never loaded (a mismatch is removed)."""
    try:
        candidates = sorted(sub.glob(f"{stem}-*{suffix}"))
    except OSError:
        return None
    for path in candidates:
        data = _read_private(path)
        if data is not None and path.name == f"{stem}-{_digest(data)}{suffix}":
            return path, data
        if data is not None:
            path.unlink(missing_ok=True)
    return None


def _store(sub: Path, stem: str, suffix: str, data: bytes) -> Path | None:
    """Write ``data`` as ``{stem}-{digest}{suffix}`` in ``sub``; None where it cannot be written."""
    path = sub / f"{stem}-{_digest(data)}{suffix}"
    try:
        _write_atomic(path, data)
    except OSError:
        return None
    _prune(sub, suffix)
    return path


#: at most this many generated modules (numba) or libraries (C) are kept on disk
DISK_FILES: int = 1000


def _prune(sub: Path, suffix: str) -> None:
    """Remove the least recently written files beyond :data:`DISK_FILES` (and numba's caches)."""
    try:
        files = sorted(sub.glob(f"screwsym_*{suffix}"), key=lambda p: p.stat().st_mtime)
        for old in files[: max(0, len(files) - DISK_FILES)]:
            old.unlink(missing_ok=True)
            for cached in (sub / "__pycache__").glob(f"{old.stem}.*"):
                cached.unlink(missing_ok=True)
    except OSError:  # another process pruned first
        pass


def _write_atomic(path: Path, data: bytes) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".tmp-")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


# ------------------------------------------------------------------ finishing


def _finish(fn: Any, plan: Plan, doc: str, backend: str) -> Any:
    """Give the generated ``_fn`` the user's names, as data on its code object.

    The function is registered in :mod:`screwsym.codegen.generated` (so that it
    pickles by reference), and what a new process needs to load it again is
    saved beside its module or library.  Returns the function (typed Any: the
    backends attach their own attributes to it)."""
    code = fn.__code__
    n = len(plan.specs)
    varnames = tuple(spec.name for spec in plan.specs) + code.co_varnames[n:]
    changes: dict[str, Any] = {"co_varnames": varnames, "co_name": plan.name}
    if hasattr(code, "co_qualname"):
        changes["co_qualname"] = plan.name
    fn.__code__ = code.replace(**changes)
    fn.__name__ = fn.__qualname__ = plan.name
    fn.__doc__ = doc
    fn._screwsym_meta = meta = _meta(plan, backend)
    reference = f"k{plan.key}_{backend}_{_digest(doc.encode())[:12]}"
    generated.register(fn, reference)
    path = _index_path(reference, backend)
    if path is not None and not path.exists():
        try:
            _write_atomic(path, json.dumps({**meta, "doc": doc}).encode())
        except OSError:  # pragma: no cover - a full disk: unpickling elsewhere says so
            pass
    return fn


def load_reference(reference: str, backend: str) -> Callable | None:
    """The function ``reference`` of :mod:`screwsym.codegen.generated`, from the disk cache."""
    path = _index_path(reference, backend)
    text = None if path is None else _read_private(path)
    if text is None:
        return None
    try:
        doc = json.loads(text)["doc"]
    except (ValueError, KeyError, TypeError):
        return None
    if not isinstance(doc, str) or not reference.endswith(_digest(doc.encode())[:12]):
        return None
    return load_index(reference, doc, backend)


generated.LOADER = load_reference


def _namespace(plan: Plan) -> dict:
    ns = {
        "_m": math,
        "_np": np,
        "_type": type,
        "_ndarray": np.ndarray,
        "_f64": np.float64,
        "_dt": np.dtype(np.float64),
        "_fb": np.frombuffer,
        "_ba": bytearray,
        "_StructError": struct.error,
        **{f"_pk{out.size}": struct.Struct(f"{out.size}d").pack for out in plan.outs},
        "_array": np.array,
        "_errstate": np.errstate,
        "_prepare": prepare,
        "_SPECS": tuple(plan.specs),
        "_OUTS": Trailings((out.trailing for out in plan.outs), plan.is_tuple),
        "_BLOCK": BLOCK,
    }
    exec(compile(PY_HELPERS, "<screwsym-codegen-helpers>", "exec"), ns)  # noqa: S102 - ours
    return ns


def _exec(source: str, plan: Plan, backend: str, ns: dict) -> Callable:
    filename = f"<screwsym-codegen-{backend}-{plan.key}>"
    linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
    exec(compile(source, filename, "exec"), ns)  # noqa: S102 - our own generated code
    return ns["_fn"]


def _meta(plan: Plan, backend: str) -> dict:
    """What an index needs to find and run a generated function again (no expressions)."""
    return {
        "key": plan.key,
        "name": plan.name,
        "is_tuple": plan.is_tuple,
        "specs": [[spec.name, list(spec.trailing), spec.what] for spec in plan.specs],
        "outs": [list(out.trailing) for out in plan.outs],
        "backend": backend,
    }


def build_numpy(plan: Plan, use_cse: bool, doc: str) -> Callable:
    plan = prepared(plan, use_cse)
    source = _emit.numpy_source(plan)
    fn = _exec(source, plan, "numpy", _namespace(plan))
    sub = _subdir("numpy")
    if sub is not None:  # kept, content-addressed, for load_index in a new process
        _store(sub, f"screwsym_generated_{plan.key}", ".py", source.encode())
    return _finish(fn, plan, doc, "numpy")


def _numba_module(plan: Plan, use_cse: bool, from_index: bool = False):
    """Import (writing it first if new) the module of ``plan`` from the disk cache.

    The module runs from the bytes read and checked against the digest in its
    file name (no bytecode cache is read); without a usable cache folder it is
    compiled in memory, without numba's disk cache.  A plan read from an index
    (``from_index``) has no expressions to print: its module must be found."""
    modname = f"screwsym_generated_{plan.key}"
    if modname in sys.modules:
        return sys.modules[modname]
    sub = _subdir("numba")
    found = None if sub is None else find_artifact(sub, modname, ".py")
    if found is None and sub is not None and not from_index:
        full = prepared(plan, use_cse)
        data = _emit.numba_source(full, PY_HELPERS).encode()
        path = _store(sub, modname, ".py", data)
        found = None if path is None else (path, data)
    mod = type(sys)(modname)
    if found is None:
        if from_index:  # its module is gone, or not what its name says
            raise OSError(f"no cached module for {modname}")
        full = prepared(plan, use_cse)
        source = _emit.numba_source(full, PY_HELPERS).replace("cache=True", "cache=False")
        _exec(source, full, "numba", mod.__dict__)
        sys.modules[modname] = mod
        return mod
    path, data = found
    mod.__file__ = str(path)
    sys.modules[modname] = mod
    try:
        exec(compile(data, str(path), "exec"), mod.__dict__)  # noqa: S102 - checked, ours
    except BaseException:
        del sys.modules[modname]
        raise
    return mod


def _numba_function(mod, plan: Plan, doc: str) -> Callable:
    mod._SPECS = tuple(plan.specs)
    mod._OUTS = Trailings((out.trailing for out in plan.outs), plan.is_tuple)
    # a fresh function object per plan: the user's names are set on it, not on the module's
    base = mod._fn
    fn = type(base)(base.__code__, mod.__dict__, "_fn", None, base.__closure__)
    fn.__kwdefaults__ = dict(base.__kwdefaults__ or {})
    fn = _finish(fn, plan, doc, "numba")
    fn.load_kernel = mod._load  # the numba dispatcher (imports numba, compiles or loads)
    return fn


def _index_path(tag: str, backend: str = "numba") -> Path | None:
    sub = _subdir(backend)
    return None if sub is None else sub / f"index-{tag}.json"


def save_index(tag: str, fn: Callable) -> None:
    """Remember, under ``tag``, which generated module ``fn`` (numba) came from.

    :mod:`screwsym.numeric` tags its functions with a digest of screwsym's
    source, so that a new process can load them without rebuilding the
    symbolic expressions; any change to the source changes the tag.
    """
    meta = getattr(fn, "_screwsym_meta", None)
    if meta is None:
        return
    path = _index_path(tag, meta.get("backend", "numba"))
    if path is not None:
        _write_atomic(path, json.dumps(meta).encode())


def load_index(tag: str, doc: str, backend: str = "numba") -> Callable | None:
    """The function (``backend`` numba, numpy or c) saved under ``tag``, or None (never saved, or unreadable).

    A NumPy function is its generated source, read back (checked against the
    digest in its file name) and executed: no SymPy work, no numba import, so
    a new process's first call of a :mod:`screwsym.numeric` function costs
    milliseconds.
    """
    path = _index_path(tag, backend)
    if path is None or (backend == "numba" and importlib.util.find_spec("numba") is None):
        return None
    text = _read_private(path)
    if text is None:
        return None
    try:
        meta = json.loads(text)
        key = meta["key"]
        if not (isinstance(key, str) and key.isalnum() and key.isascii()):
            return None
        plan = Plan(
            tuple(Arg(str(n), tuple(int(d) for d in t), str(w)) for n, t, w in meta["specs"]),
            tuple(Out(tuple(int(d) for d in t)) for t in meta["outs"]),
            bool(meta["is_tuple"]), (), (), (), str(meta["name"]), key,
        )  # fmt: skip
        if backend == "c":
            return _load_c(path.parent, f"screwsym_k{key}", doc, plan)
        found = find_artifact(path.parent, f"screwsym_generated_{key}", ".py")
        if found is None:
            return None
        if backend == "numpy":
            fn = _exec(found[1].decode(), plan, "numpy", _namespace(plan))
            return _finish(fn, plan, doc, "numpy")
        return _numba_function(_numba_module(plan, False, from_index=True), plan, doc)
    except (OSError, ValueError, KeyError, TypeError):
        return None


def build_numba(plan: Plan, use_cse: bool, doc: str) -> Callable:
    if importlib.util.find_spec("numba") is None:
        raise ImportError(
            "backend 'numba' needs numba: pip install -e \".[fast]\" in a clone of screwsym"
            " (or use backend='numpy')"
        )
    return _numba_function(_numba_module(plan, use_cse), plan, doc)


# ------------------------------------------------------------------------ C


def compiler() -> str | None:
    """The C compiler of the C back end: ``$CC``, ``cc``, ``gcc`` or ``clang``, or None.

    >>> compiler() is None or isinstance(compiler(), str)
    True
    """
    # asked on every call of a numeric function (its default back end): the PATH search is
    # remembered for the CC and PATH it was made with (31 us a call before, 0.3 us after)
    return _find_compiler(os.environ.get("CC"), os.environ.get("PATH"))


@functools.lru_cache(maxsize=8)
def _find_compiler(cc_env: str | None, path: str | None) -> str | None:
    for cc in (cc_env, "cc", "gcc", "clang"):
        if cc and shutil.which(cc, path=path):
            return cc
    return None


def python_headers() -> list[str] | None:
    """The include folders of Python's and NumPy's C headers, or None where either is missing.

    With them the C back end builds each function as a CPython extension
    module (see :func:`screwsym.codegen._emit.c_extension_source`): one point
    per call at the cost of a C call.  Without them, a plain library.
    """
    import sysconfig

    py = sysconfig.get_paths().get("include") or ""
    inc = np.get_include()
    ok = (os.path.isfile(os.path.join(py, "Python.h"))
          and os.path.isfile(os.path.join(inc, "numpy", "arrayobject.h")))
    return [py, inc] if ok else None


def _abi() -> str:
    """A tag of the Python and NumPy an extension module was built for (in its file name)."""
    import sysconfig

    text = f"{sys.version}|{np.__version__}|{sysconfig.get_config_var('EXT_SUFFIX')}"
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def _compile_c(source: str, include: list[str] | None = None) -> bytes:
    """The shared library compiled from ``source`` (an extension module with ``include``)."""
    cc = compiler()
    if cc is None:
        raise RuntimeError("backend 'c' needs a C compiler: none of $CC, cc, gcc, clang found")
    with tempfile.TemporaryDirectory(prefix="screwsym-c-") as tmp:
        c_path = os.path.join(tmp, "generated.c")
        tmp_so = os.path.join(tmp, "generated.so")
        with open(c_path, "w") as fh:
            fh.write(source)
        flags = ["-std=c99"] if include is None else ["-std=c11", *(f"-I{d}" for d in include)]
        cmd = [cc, "-O3", *flags, "-shared", "-fPIC", c_path, "-o", tmp_so, "-lm"]
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"backend 'c': {' '.join(cmd)} failed:\n{done.stderr}")
        return Path(tmp_so).read_bytes()


_EXTENSIONS: dict[str, Any] = {}


def _extension(path: Path, cname: str) -> Any:
    """The extension module ``cname`` at ``path`` (a checked artefact), loaded once."""
    import importlib.machinery

    mod = _EXTENSIONS.get(cname)
    if mod is None:
        loader = importlib.machinery.ExtensionFileLoader(cname, str(path))
        spec = importlib.util.spec_from_file_location(cname, str(path), loader=loader)
        assert spec is not None
        mod = importlib.util.module_from_spec(spec)
        loader.exec_module(mod)
        _EXTENSIONS[cname] = mod
    return mod


def _c_function(plan: Plan, lib: Any, text: str, doc: str, point: Any = None) -> Any:
    """The generated wrapper ``text`` around the loop of the loaded library ``lib``.

    ``point`` is the extension module's one-point function, where there is one."""
    cname = f"screwsym_k{plan.key}"
    cfunc = getattr(lib, cname)
    ptr = ctypes.POINTER(ctypes.c_double)
    argtypes: list = [ctypes.c_size_t]
    for _ in plan.specs:
        argtypes += [ptr, ctypes.c_ssize_t]
    argtypes += [ptr] * len(plan.outs)
    cfunc.argtypes = argtypes
    cfunc.restype = ctypes.c_size_t  # the rows whose first result is nan
    steps = [spec.size for spec in plan.specs]

    def kernel(n: int, *arrays: np.ndarray) -> int:
        ins, outs = arrays[: len(steps)], arrays[len(steps) :]
        call: list = [n]
        for arr, step in zip(ins, steps, strict=True):
            call += [arr.ctypes.data_as(ptr), step if arr.shape[0] != 1 else 0]
        call += [o.ctypes.data_as(ptr) for o in outs]
        return cfunc(*call)

    ns = _namespace(plan)
    ns["_kernel"] = kernel
    ns["_point"] = point
    fn = _finish(_exec(text, plan, "c", ns), plan, doc, "c")
    fn.kernel = kernel
    fn.c_library = lib
    marker = "# C source compiled for this function:\n"
    fn.c_source = "".join(line[2:] + "\n" for line in
                          text[text.index(marker) + len(marker):].splitlines())
    return fn


def _load_c(sub: Path | None, cname: str, doc: str, plan: Plan) -> Any:
    """The cached function ``cname`` (extension module first, else plain library), or None."""
    if sub is None:
        return None
    for stem, ext in ((f"{cname}_py{_abi()}", True), (cname, False)):
        so = find_artifact(sub, stem, ".so")
        py = find_artifact(sub, stem, ".py")
        if so is not None and py is not None:
            point = _extension(so[0], cname).point if ext else None
            return _c_function(plan, ctypes.CDLL(str(so[0])), py[1].decode(), doc, point)
    return None


def build_c(plan: Plan, use_cse: bool, doc: str) -> Callable:
    cname = f"screwsym_k{plan.key}"
    sub = _subdir("c")
    found = _load_c(sub, cname, doc, plan)  # no CSE nor printing where it is on disk
    if found is not None:
        return found
    plan = prepared(plan, use_cse)
    source = _emit.c_source(plan, cname)
    include = python_headers()
    stem = cname
    if include is not None:
        source += _emit.c_extension_source(plan, cname)
        stem = f"{cname}_py{_abi()}"
    data = _compile_c(source, include)
    text = _emit.c_wrapper_source(plan, include is not None) + (
        "\n# C source compiled for this function:\n"
        + "".join("# " + line + "\n" for line in source.splitlines()))
    so_path = None if sub is None else _store(sub, stem, ".so", data)
    tmp = None
    if so_path is not None:
        _store(so_path.parent, stem, ".py", text.encode())
    else:
        tmp = tempfile.TemporaryDirectory(prefix="screwsym-c-")
        so_path = Path(tmp.name) / f"{stem}.so"
        so_path.write_bytes(data)
    try:  # a library stays mapped after its file is removed
        point = _extension(so_path, cname).point if include is not None else None
        return _c_function(plan, ctypes.CDLL(str(so_path)), text, doc, point)
    finally:
        if tmp is not None:
            tmp.cleanup()


BUILDERS = {"numpy": build_numpy, "numba": build_numba, "c": build_c}
