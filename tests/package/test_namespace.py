"""``from sympy import *`` then ``from screwsym import *`` leaves every SymPy name working.

A notebook user types both; screwsym's ``__all__`` (and each floor's) must bind
no name that SymPy's star import binds.  The check is on object identity, so a
screwsym wrapper of the same name would fail it too.
"""

import importlib
import pkgutil
import subprocess
import sys

import pytest

import screwsym

SYMPY: dict = {}
exec("from sympy import *", SYMPY)  # noqa: S102 - a fixed statement, no user text

PUBLIC = ["screwsym"] + [
    info.name
    for info in pkgutil.walk_packages(screwsym.__path__, "screwsym.")
    if not any(part.startswith("_") for part in info.name.split("."))
    and not info.name.startswith(("screwsym.cli", "screwsym.plot"))  # plot needs matplotlib
]


def shadowed(module_name: str) -> list[str]:
    """The SymPy names that ``from <module_name> import *`` rebinds to something else."""
    ns = dict(SYMPY)
    exec(f"from {module_name} import *", ns)  # noqa: S102 - module names from pkgutil
    return sorted(n for n in SYMPY if n != "__builtins__" and ns[n] is not SYMPY[n])


#: modules whose star import rebinds a SymPy name on purpose: screwsym's version of the same
#: idea (a lambdify that also takes screws, an init_printing that also prints them); the
#: package's ``__all__`` leaves both out, so ``from screwsym import *`` binds neither.
ON_PURPOSE = {"screwsym.codegen": ["lambdify"], "screwsym.core.printing": ["init_printing"]}


@pytest.mark.parametrize("module_name", PUBLIC)
def test_a_star_import_shadows_no_sympy_name(module_name):
    assert shadowed(module_name) == ON_PURPOSE.get(module_name, [])


def test_the_plot_floor_shadows_nothing_either():
    pytest.importorskip("matplotlib")
    assert shadowed("screwsym.plot") == ["plot"]  # plot's own star import is explicit: its plot()
    assert "plot" not in screwsym.__all__


def test_the_checker_sees_a_shadow(tmp_path, monkeypatch):
    (tmp_path / "shadowing_mod.py").write_text("from sympy import Symbol\nexp = 1\n__all__ = ['exp']\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    importlib.invalidate_caches()
    assert shadowed("shadowing_mod") == ["exp"]


def test_the_notebook_line_works():
    code = ("from sympy import *; from screwsym import *; x = Symbol('x'); "
            "print(exp(x), log(x), S(1), exp6.__module__)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["exp(x)", "log(x)", "1", "screwsym.motion.displacement"]
