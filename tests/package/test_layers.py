"""The package's import graph: the floors and the rules between them.

No module of screwsym imports another in a circle; a floor imports only the
floors the rules allow (``LAYERS``); no private name crosses a floor.

Every ``import`` statement is read from the source, also those inside
functions (a lazy import still makes a circle of dependencies), and resolved
to the screwsym module it names.  ``screwsym/__init__.py`` loads its lazy
subpackages through ``importlib`` on attribute access, which is no import
statement, so the package may re-export everything while the modules depend
on each other one way only.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

import screwsym

ROOT = Path(screwsym.__file__).parent


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _modules() -> dict[str, Path]:
    return {_module_name(p): p for p in ROOT.rglob("*.py")}


def _resolve(module: str, is_package: bool, node: ast.ImportFrom) -> str:
    if node.level == 0:
        return node.module or ""
    base = module.split(".") if is_package else module.split(".")[:-1]
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _is_type_checking(node: ast.AST) -> bool:
    test = getattr(node, "test", None)
    return isinstance(node, ast.If) and (
        (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING")
        or (isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")
    )


def runtime_nodes(tree: ast.AST):
    """Every node of ``tree`` but those under ``if TYPE_CHECKING:``, which never run."""
    stack = [tree]
    while stack:
        node = stack.pop()
        yield node
        if _is_type_checking(node):
            stack.extend(node.orelse)  # type: ignore[attr-defined]
        else:
            stack.extend(ast.iter_child_nodes(node))


def import_graph() -> dict[str, set[str]]:
    """Edges ``module -> screwsym modules it imports`` when it runs (statements anywhere in the
    file, in functions too, but not the type-only ones under ``if TYPE_CHECKING:``: a circle of
    annotations is no circle of imports).  The floor rules below read every statement."""
    modules = _modules()
    graph: dict[str, set[str]] = {m: set() for m in modules}
    for module, path in modules.items():
        is_package = path.name == "__init__.py"
        for node in runtime_nodes(ast.parse(path.read_text(), str(path))):
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = _resolve(module, is_package, node)
                names = [f"{base}.{a.name}" for a in node.names]
                # ``from . import sub`` needs the submodule; ``from .m import x`` needs m
                targets = names if all(n in modules for n in names) else [base]
            for target in targets:
                # ``import screwsym.x.y`` depends on the deepest screwsym module named
                while target and target not in modules and "." in target:
                    target = target.rsplit(".", 1)[0]
                if target in modules and target != module:
                    graph[module].add(target)
    return graph


def find_cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """A cycle of the graph as a list of nodes (first = last), or None."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> list[str] | None:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph[node]):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state and (cycle := visit(nxt)):
                return cycle
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state and (cycle := visit(node)):
            return cycle
    return None


def test_no_import_cycles():
    cycle = find_cycle(import_graph())
    assert cycle is None, "import cycle: " + " -> ".join(cycle)


#: The floors (subpackages) and what each may import ("A -> B": A may import B).  ``top`` is
#: the package's own modules (``__init__``, ``cli``, ``__main__``, ``_version``): the public face.
LAYERS: dict[str, set[str]] = {
    "algebra": set(),  # the exact algebra: decisions over Q, number fields and the circle
    "core": {"algebra"},
    "motion": {"core", "algebra"},
    "systems": {"core", "algebra"},
    "codegen": set(),
    "numeric": {"codegen", "core", "systems", "motion", "algebra"},  # motion: a Chain's dynamics as generated functions (numeric.dynamics, issue 21)
    "plot": {"core", "numeric", "motion", "systems"},  # the 3-D view draws chains and mechanisms (issue 37)
    "book": {"top"},
    "top": {"algebra", "core", "motion", "systems", "codegen", "numeric", "plot", "book"},
}


def floor(module: str) -> str:
    parts = module.split(".")
    if len(parts) > 1 and parts[1] in LAYERS:
        return parts[1]
    return "top"


def import_statements() -> list[tuple[str, str, list[str]]]:
    """``(module, target module, imported names)`` for every use of a screwsym module.

    An import names its module; ``from screwsym import core`` (or ``from .. import core``)
    imports the module ``screwsym.core``, not a name of the package.  A module bound to a
    name (``from ..core import screw as _core``, ``import screwsym as ss``) is used through
    attributes, so ``_core._pitch`` and ``ss.core.screw.pitch`` count as imports of
    ``_pitch`` from ``screwsym.core.screw`` and of ``pitch`` from ``screwsym.core.screw``.
    """
    modules = _modules()
    out = []
    for module, path in modules.items():
        is_package = path.name == "__init__.py"
        tree = ast.parse(path.read_text(), str(path))
        bound: dict[str, str] = {}  # a local name -> the screwsym module it is bound to
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                base = _resolve(module, is_package, node)
                if base != "screwsym" and not base.startswith("screwsym."):
                    continue
                names = []
                for a in node.names:
                    full = f"{base}.{a.name}"
                    if full in modules:
                        out.append((module, full, []))
                        bound[a.asname or a.name] = full
                    else:
                        names.append(a.name)
                if names or not node.names:
                    out.append((module, base, names))
            elif isinstance(node, ast.Import):
                for a in node.names:
                    if a.name == "screwsym" or a.name.startswith("screwsym."):
                        out.append((module, a.name, []))
                        if a.asname:
                            bound[a.asname] = a.name
                        else:
                            bound["screwsym"] = "screwsym"
        for node in ast.walk(tree):
            if not isinstance(node, ast.Attribute) or isinstance(
                getattr(node, "_parent_attribute", None), ast.Attribute
            ):
                continue
            chain: list[str] = []
            value: ast.AST = node
            while isinstance(value, ast.Attribute):
                chain.append(value.attr)
                value.value._parent_attribute = value  # type: ignore[attr-defined]
                value = value.value
            if not (isinstance(value, ast.Name) and value.id in bound):
                continue
            target, parts = bound[value.id], chain[::-1]
            while parts and f"{target}.{parts[0]}" in modules:
                target = f"{target}.{parts.pop(0)}"
            if parts:
                out.append((module, target, parts[:1]))
    return out


def layer_violations(statements) -> list[str]:
    """Every import that breaks a rule: a floor not allowed, or a private name across floors."""
    bad = []
    for module, target, names in statements:
        src, dst = floor(module), floor(target)
        if src == dst:
            continue
        if dst not in LAYERS[src]:
            bad.append(f"{module} imports {target}: {src} may not import {dst}")
            continue
        parts = target.split(".")[1:] + [n for n in names if n != "*"]
        if any(p.startswith("_") and not p.startswith("__") for p in parts):
            bad.append(f"{module} imports {target} {names}: a private name crosses a floor")
    return bad


def test_the_floors_keep_their_rules():
    assert layer_violations(import_statements()) == []


def test_the_rules_are_the_documented_ones():
    # core imports nothing above it; codegen imports no screwsym object; motion and systems are
    # siblings; book and the command line go through the public face only
    assert LAYERS["algebra"] == set() and LAYERS["codegen"] == set()
    assert LAYERS["core"] == {"algebra"}
    assert "systems" not in LAYERS["motion"] and "motion" not in LAYERS["systems"]
    assert LAYERS["book"] == {"top"}


@pytest.mark.parametrize(
    "statement, broken",
    [
        (("screwsym.core.screw", "screwsym.motion.transform", ["Transform"]), True),  # up a floor
        (("screwsym.codegen._plan", "screwsym.core.screw", ["Screw"]), True),  # codegen -> object
        (("screwsym.motion.chain", "screwsym.systems", ["ScrewSystem"]), True),  # sibling
        (("screwsym.algebra.rings", "screwsym.core.screw", ["Screw"]), True),  # algebra is the floor
        (("screwsym.systems.screw_system", "screwsym.algebra.rings", ["to_ring"]), False),
        (("screwsym.numeric.screws", "screwsym.codegen", ["_build"]), True),  # private name
        (("screwsym.numeric.screws", "screwsym.codegen._build", ["x"]), True),  # private module
        (("screwsym.cli", "screwsym.book._entry", ["as_text"]), True),  # private, from the top
        (("screwsym.book._s12_lines", "screwsym.core", ["Screw"]), True),  # book past the face
        (("screwsym.motion.chain", "screwsym.core.screw", ["foot"]), False),
        (("screwsym.core.line", "screwsym.core.tidy", ["_finish"]), False),  # inside a floor
        (("screwsym.book._common", "screwsym", []), False),
    ],
)
def test_the_rule_checker_rejects_what_it_should(statement, broken):
    assert bool(layer_violations([statement])) is broken


@pytest.mark.parametrize(
    "graph, cycle",
    [
        ({"a": {"b"}, "b": {"c"}, "c": {"a"}}, ["a", "b", "c", "a"]),
        ({"a": {"b"}, "b": set()}, None),
        ({"a": {"a"}}, ["a", "a"]),
    ],
)
def test_the_cycle_finder_finds_cycles(graph, cycle):
    assert find_cycle(graph) == cycle


def test_a_type_only_import_makes_no_cycle_but_a_lazy_one_does(tmp_path, monkeypatch):
    pkg = tmp_path / "screwsym"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from .b import x\n")
    (pkg / "b.py").write_text(
        "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from .a import y\nelse:\n    pass\n"
    )
    monkeypatch.setattr(__import__(__name__), "ROOT", pkg)
    assert find_cycle(import_graph()) is None
    (pkg / "b.py").write_text("import typing\nif typing.TYPE_CHECKING:\n    pass\nelse:\n    from .a import y\n")
    assert find_cycle(import_graph()) == ["screwsym.a", "screwsym.b", "screwsym.a"]


def test_a_lazy_import_counts(tmp_path, monkeypatch):
    # a function-level import closes a circle as much as a module-level one
    pkg = tmp_path / "screwsym"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from .b import x\n")
    (pkg / "b.py").write_text("def f():\n    from . import a\n")
    monkeypatch.setattr(__import__(__name__), "ROOT", pkg)
    assert find_cycle(import_graph()) == ["screwsym.a", "screwsym.b", "screwsym.a"]


@pytest.mark.parametrize(
    "where, source, broken",
    [
        ("book/x.py", "from .. import core\n", True),  # the book past the face, as a module
        ("book/x.py", "from screwsym import core\n", True),
        ("book/x.py", "import screwsym as ss\nss.core.screw.pitch\n", True),
        ("book/x.py", "import screwsym as ss\nss.Screw\n", False),
        ("numeric/y.py", "from ..core import screw as _core\n_core._pitch(1)\n", True),
        ("numeric/y.py", "from ..core import screw as _core\n_core.pitch(1)\n", False),
        ("numeric/y.py", "import screwsym.core.screw as m\nm._pitch\n", True),
        ("numeric/y.py", "from .. import core\ncore.screw._pitch\n", True),
        ("motion/z.py", "from .. import core\ncore.screw.pitch\n", False),  # core is allowed
        ("motion/z.py", "from .. import systems\n", True),
    ],
)
def test_the_rule_checker_reads_modules_imported_by_name(tmp_path, monkeypatch, where, source,
                                                          broken):
    # ``from screwsym import core`` imports the module screwsym.core, and a module bound to a
    # name is used through its attributes: neither may carry a floor or a private name past
    # the rules
    pkg = tmp_path / "screwsym"
    for sub in ("", "core", "book", "numeric", "motion", "systems"):
        (pkg / sub).mkdir(exist_ok=True)
        (pkg / sub / "__init__.py").write_text("")
    (pkg / "core" / "screw.py").write_text("def pitch(s): ...\ndef _pitch(s): ...\n")
    (pkg / where).write_text(source)
    monkeypatch.setattr(__import__(__name__), "ROOT", pkg)
    assert bool(layer_violations(import_statements())) is broken


# ------------------------------------------------------------------ the house's size
#: the longest a module of screwsym may be: past it a module holds more than one idea
MAX_MODULE_LINES = 1000
#: the most underscore names one module may import from another (``from .m import _x``, or
#: ``m._x`` through a module bound to a name); a private module imported by name does not count
MAX_PRIVATE_IMPORTS = 10


def private_imports(statements) -> list[tuple[str, str, str]]:
    """``(module, target, name)`` for every underscore name a module takes from another."""
    return sorted({(module, target, name) for module, target, names in statements
                   for name in names
                   if name.startswith("_") and not name.startswith("__") and target != module})


def test_no_module_is_longer_than_the_limit():
    long = {name: n for name, path in _modules().items()
            if (n := len(path.read_text().splitlines())) > MAX_MODULE_LINES}
    assert long == {}


def test_few_private_names_cross_modules():
    found = private_imports(import_statements())
    assert len(found) <= MAX_PRIVATE_IMPORTS, found


def test_the_private_import_counter_sees_both_forms():
    statements = [("screwsym.a", "screwsym.b", ["_x", "y"]), ("screwsym.a", "screwsym.b", ["_x"]),
                  ("screwsym.c", "screwsym.c", ["_self"]), ("screwsym.d", "screwsym.e", ["__all__"])]
    assert private_imports(statements) == [("screwsym.a", "screwsym.b", "_x")]


def test_every_module_of_the_algebra_floor_has_a_test_that_imports_it():
    tests = Path(__file__).parents[1]
    text = "\n".join(p.read_text() for p in tests.rglob("test_*.py"))
    modules = [m for m in _modules() if m.startswith("screwsym.algebra.")]
    assert modules
    untested = [m for m in modules
                if not re.search(rf"(from {re.escape(m)} import|import {re.escape(m)}\b|"
                                 rf"from screwsym\.algebra import [^\n]*\b{m.rsplit('.', 1)[1]}\b)",
                                 text)]
    assert untested == []
