"""No call of the library hands text to a parser: sympify is always strict.

SymPy's ``sympify`` without ``strict=True`` parses a string as Python, so every
call of it in screwsym passes ``strict=True`` (a literal), and ``parse_expr``,
``eval`` and ``exec`` are not called, except ``exec`` of the source that
``screwsym.codegen`` generates itself (tests/codegen/test_codegen_safety.py).
"""

from __future__ import annotations

import ast
from pathlib import Path

import screwsym

ROOT = Path(screwsym.__file__).parent
#: the modules allowed to ``exec``: code generation runs the source it printed
EXEC_ALLOWED = {"codegen/_build.py"}


def _name(func: ast.expr) -> str:
    return func.id if isinstance(func, ast.Name) else getattr(func, "attr", "")


def parser_calls(path: Path, rel: str) -> list[str]:
    bad = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if not isinstance(node, ast.Call):
            continue
        name = _name(node.func)
        strict = any(k.arg == "strict" and isinstance(k.value, ast.Constant) and k.value.value is True
                     for k in node.keywords)
        if name == "sympify" and not strict:
            bad.append(f"{rel}:{node.lineno}: sympify without strict=True")
        elif name in ("parse_expr", "eval") or name == "exec" and rel not in EXEC_ALLOWED:
            bad.append(f"{rel}:{node.lineno}: {name}")
    return bad


def test_no_call_hands_text_to_a_parser():
    found = []
    for path in sorted(ROOT.rglob("*.py")):
        found += parser_calls(path, path.relative_to(ROOT).as_posix())
    assert found == []


def test_the_scan_finds_parser_calls(tmp_path):
    f = tmp_path / "m.py"
    f.write_text("sympify(x)\nsympy.sympify(x, strict=False)\nsympify(x, strict=True)\n"
                 "eval('1')\nparse_expr(s)\nexec(s)\n")
    assert [s.split(":")[1] for s in parser_calls(f, "m.py")] == ["1", "2", "4", "5", "6"]


def test_a_book_residual_that_is_a_python_number_or_bool_keeps_its_latex():
    # the strict sympify of an int (or bool) gives what the non-strict one gave
    from screwsym.book._entry import as_latex

    assert (as_latex(3), as_latex(True), as_latex(0)) == ("3", r"\text{True}", "0")
