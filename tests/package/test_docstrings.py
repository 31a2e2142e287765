"""The library's prose keeps up with its names: no removed name, no dangling reference.

0.2.0 renamed and moved names without aliases (CHANGELOG.md), so a docstring,
comment or message that still says ``exp(...)``, ``.dof`` or ``as_matrix``
points a reader at something that is gone.  Every string literal and comment of
every module is read for the removed names; every "See Also" entry must resolve
to an object; a ``:meth:`` reference inside a class must name a method, not a
property (the methods that became properties).
"""

from __future__ import annotations

import importlib
import inspect
import io
import pkgutil
import re
import tokenize
from pathlib import Path

import pytest

import screwsym

ROOT = Path(screwsym.__file__).parent

#: a removed name (a pattern) and what replaced it
REMOVED = {
    r"\bas_matrix\b": "Screw.matrix",
    r"\.dof\b|``dof``": "Chain.n_joints, Mobility.mobility, MobilityMap.mobility",
    r"\bconstraint_system\b|\btwist_system\b": "ParallelMechanism.constraints, .twists",
    r"(?<!body_)\btwists\(\)|\bconstraints\(\)": "the properties twists, constraints",
    r"\bmechanism_numeric\b": "screwsym.numeric.mobility",
    r"screwsym\.system\b(?!s)": "screwsym.systems.screw_system",
    r"screwsym\._(validation|decide|basic)\b": "screwsym.core.checks, .decide, .basic",
    r"(?<![\w.])(exp|log)\((?!\[)": "exp6, log6 (exp([...]) is a matrix exponential)",
    r"\bnumeric\.functions\(": "numeric.functions_for",
    r"(?<![\w.])(decompose|adjoint)\((?!\))": "decompose_screw, adjoint_matrix",
}


def _texts(path: Path):
    """``(line, text)`` of every string literal and comment of the file."""
    kinds = {tokenize.STRING, tokenize.COMMENT, getattr(tokenize, "FSTRING_MIDDLE", -1)}
    for tok in tokenize.generate_tokens(io.StringIO(path.read_text()).readline):
        if tok.type in kinds:
            yield tok.start[0], tok.string


def removed_names(paths) -> list[str]:
    found = []
    for path in paths:
        for line, text in _texts(path):
            for pattern, new in REMOVED.items():
                for m in re.finditer(pattern, text):
                    found.append(f"{path.name}:{line}: {m.group(0)!r} (now {new})")
    return found


def test_no_string_or_comment_names_a_removed_name():
    assert removed_names(sorted(ROOT.rglob("*.py"))) == []


def test_the_scan_finds_removed_names(tmp_path):
    f = tmp_path / "m.py"
    f.write_text('"""See exp(twist, q) and m.dof."""\n# J = Ad(exp(-B q)) B\nx = "s.as_matrix()"\n'
                 'y = "exp([omega] theta), exp6(t, q), c.body_twists()"\n')
    assert [s.split(":")[1] for s in removed_names([f])] == ["1", "1", "2", "3"]


def _modules():
    for info in pkgutil.walk_packages(screwsym.__path__, "screwsym."):
        if info.name.startswith(("screwsym.plot", "screwsym.__main__")):
            continue  # plot needs matplotlib; __main__ runs the command line
        yield importlib.import_module(info.name)


def _documented(module):
    """``(docstring, module, class or None, where)`` of the module and what it defines."""
    yield module.__doc__, module, None, module.__name__
    for name, obj in vars(module).items():
        if getattr(obj, "__module__", None) != module.__name__:
            continue
        if inspect.isclass(obj):
            yield obj.__doc__, module, obj, f"{module.__name__}.{name}"
            for member_name, member in vars(obj).items():
                f = getattr(member, "fget", None) or getattr(member, "__func__", None) or member
                if callable(f):
                    yield f.__doc__, module, obj, f"{module.__name__}.{name}.{member_name}"
        elif inspect.isfunction(obj):
            yield obj.__doc__, module, None, f"{module.__name__}.{name}"


def _resolves(name: str, module, owner) -> bool:
    for base in ([owner] if owner is not None else []) + [module]:
        obj = base
        try:
            for part in name.split("."):
                obj = getattr(obj, part)
            return True
        except AttributeError:
            pass
    parts = name.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        try:
            for part in parts[i:]:
                obj = getattr(obj, part)
            return True
        except AttributeError:
            return False
    return False


DOCUMENTED = [d for m in _modules() for d in _documented(m)]


def test_every_see_also_entry_resolves():
    dangling = []
    for doc, module, owner, where in DOCUMENTED:
        m = re.search(r"See Also\n\s*=+\n(.*?)(\n\s*\n|\Z)", doc or "", re.S)
        if m is None:
            continue
        for name in re.split(r"[,\s]+", m.group(1).strip()):
            if name and not _resolves(name, module, owner):
                dangling.append(f"{where}: {name}")
    assert dangling == []


def test_a_meth_reference_in_a_class_names_a_method():
    wrong = []
    for doc, _, owner, where in DOCUMENTED:
        if owner is None:
            continue
        for name in re.findall(r":meth:`~?([A-Za-z_]\w*)`", doc or ""):
            if isinstance(inspect.getattr_static(owner, name, None), property):
                wrong.append(f"{where}: :meth:`{name}` is a property (:attr:)")
    assert wrong == []


@pytest.mark.parametrize("name", ["screwsym.motion.displacement.exp6", "exp6", "Transform.adjoint"])
def test_the_resolver_resolves(name):
    from screwsym.motion import displacement

    assert _resolves(name, displacement, None)
    assert not _resolves("log", displacement, None)
