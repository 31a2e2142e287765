"""The command line."""

import json
import os
import re
import subprocess
import sys

import pytest

from screwsym.book import entries
from screwsym.cli import main


def test_verify_some_table(capsys):
    assert main(["verify", "1.1", "1.34", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert "1.34" in out and "Pitch of a screw" in out and "holds" in out
    assert "2 of 2 statements hold" in out


def test_verify_markdown(capsys):
    assert main(["verify", "Example 1.4", "--format", "markdown", "--jobs", "1"]) == 0
    assert "| Example 1.4 | Identify" in capsys.readouterr().out


def test_verify_verbose_shows_statement_checks_and_errata(capsys):
    assert main(["verify", "-v", "1.25", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert "statement:\n    M_m = (r_2-r_1)·S_2×S_1 = -a_12 sin α_12" in out
    assert "checks:" in out and "generic: M + |S1||S2| a12 sin(alpha12)" in out
    assert "residual 0 (stage radicals)" in out
    assert "non-zero (-2) at {a12: 1, alpha12: pi/2}  [the book's wording, shown failing]" in out
    assert "errata (Huang, Li & Ding" in out and "Section 1.3, Eq. (1.25)" in out
    assert "Sign convention" in out and "transcription" not in out
    assert "1 of 1 statements hold" in out


def test_verify_json_has_everything(capsys):
    assert main(["verify", "1.27", "--format", "json", "--jobs", "1"]) == 0
    data = json.loads(capsys.readouterr().out)
    e = data["entries"][0]
    assert data["ok"] and data["complete"] and e["id"] == "1.27" and e["kind"] == "conditional"
    assert e["statement"].startswith("S_1·S_02+S_2·S_01 = 0") and "\\mathbf" in e["statement_latex"]
    labels = [c["label"] for c in e["checks"]]
    assert "parallel: foot2 - foot1 - a12 normal" in labels
    assert all(c["ok"] for c in e["checks"]) and {c["kind"] for c in e["checks"]} >= {
        "zero", "holds", "nonzero"}
    assert any(c["book"] for c in e["checks"])
    assert e["errata"] and "Section 1.3, Eq. (1.27)" in e["errata_source"]


def test_verify_fails_with_exit_1(monkeypatch, capsys):
    import screwsym

    real = screwsym.pitch
    monkeypatch.setattr(screwsym, "pitch", lambda s: 2 * real(s))
    assert main(["verify", "1.34", "--jobs", "1"]) == 1
    out = capsys.readouterr().out
    assert "FAILS" in out and "residual" in out
    assert main(["verify", "-v", "1.34", "--jobs", "1"]) == 1
    assert re.search(r"FAILS  zero +pitch - \(lp", capsys.readouterr().out)


def test_duplicate_ids_verified_once(capsys):
    assert main(["verify", "1.34", "(1.34)", "1.34", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert "1 of 1 statements hold" in out


def test_jobs_checked_and_capped(capsys, monkeypatch):
    assert main(["verify", "1.1", "--jobs", "0"]) == 2
    assert "--jobs: expected a positive integer, got 0" in capsys.readouterr().err
    seen = {}
    import screwsym.book as book

    real = book.verify_all

    def spy(ids=None, **kw):
        seen["jobs"] = kw["jobs"]
        return real(ids, **{**kw, "jobs": 1})

    monkeypatch.setattr(book, "verify_all", spy)
    assert main(["verify", "1.1", "--jobs", "100000"]) == 0
    from screwsym.cli import _cpus

    assert seen["jobs"] == _cpus() <= os.cpu_count()


def test_interrupt_ends_with_a_partial_summary(capsys, monkeypatch):
    import screwsym.book as book

    real = book.verify_all

    def interrupted(ids=None, *, progress=None, **kw):
        real(["1.1", "1.2"], progress=progress, **{**kw, "jobs": 1})
        raise KeyboardInterrupt

    monkeypatch.setattr(book, "verify_all", interrupted)
    assert main(["verify", "--jobs", "1"]) == 130
    out = capsys.readouterr().out
    assert "interrupted after 2 statements: 2 of 2 statements hold" in out
    assert main(["verify", "--format", "json", "--jobs", "1"]) == 130
    data = json.loads(capsys.readouterr().out)
    assert data["complete"] is False and data["ok"] is False and data["total"] == 2


def test_closed_stdout_ends_cleanly():
    env = dict(os.environ, PYTHONPATH=os.getcwd())
    p = subprocess.run([sys.executable, "-c",
                        "import os, sys; os.close(1); from screwsym.cli import main; "
                        "sys.exit(main(['verify', '1.1', '--jobs', '1']))"],
                       capture_output=False, stderr=subprocess.PIPE, text=True, env=env,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    assert "Traceback" not in p.stderr
    assert "standard output is closed; 1 of 1 statements hold" in p.stderr


def test_pipe_closed_by_the_reader():
    env = dict(os.environ, PYTHONPATH=os.getcwd())
    p = subprocess.run(f"'{sys.executable}' -m screwsym list | head -n 1", shell=True,
                       capture_output=True, text=True, env=env, timeout=120)
    assert p.stdout.startswith("1.1 ") and "Traceback" not in p.stderr


def test_version(capsys):
    from screwsym import __version__

    assert main(["--version"]) == 0
    assert capsys.readouterr().out.strip() == f"screwsym {__version__}"


def test_bad_id_exit_2(capsys):
    assert main(["verify", "1.99"]) == 2
    assert "unknown entry id '1.99'" in capsys.readouterr().err
    assert main(["show", "nope"]) == 2


def test_show(capsys):
    assert main(["show", "Theorem 1.1"]) == 0
    out = capsys.readouterr().out
    assert "Section 1.5.1, conditional" in out and "errata (" in out and "construction:" in out
    assert "checks (screwsym verify -v shows their results):" in out
    assert "  - only if: skew lines give a non-zero pitch: counter-example, non-zero" in out
    assert main(["show", "1.34", "--latex"]) == 0
    assert r"\frac{\mathbf S\cdot\mathbf S^0}" in capsys.readouterr().out
    assert main(["show", "1.34"]) == 0
    assert "h = (S·S⁰)/(S·S) = (lp+mq+nr)/(l²+m²+n²)" in capsys.readouterr().out


@pytest.mark.parametrize("id_", [e.id for e in entries()])
def test_show_prints_no_latex(id_, capsys):
    assert main(["show", id_]) == 0
    statement = capsys.readouterr().out.split("\n\n")[1]
    assert not re.search(r"\\|\^\{|_\{|&|\\frac|\\text", statement), statement


def test_show_renders_the_hard_cases(capsys):
    for id_, text in [("1.11", "S₀ = det[i j k; x_1 y_1 z_1; L M N]"),
                      ("Example 1.3", "1/√3(1 1 1; 1 1 1)"),
                      ("Example 1.4", "(1/2 -1/2 0)ᵀ"),
                      ("Counting: lines", "dim {(S; S₀): |S| = 1, S·S₀ = 0} = 4"),
                      ("Classification", "Line vector: (S; S₀): S ≠ 0, S·S₀ = 0, h = 0")]:
        assert main(["show", id_]) == 0
        assert text in capsys.readouterr().out, id_


def test_list(capsys):
    assert main(["list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 78 and lines[0].startswith("1.1 ")


def test_usage_error():
    assert main(["frobnicate"]) == 2


_INTERRUPT_DURING_IMPORT = '''\
# Written by tests/package/test_cli.py: a Ctrl-C that lands while SymPy is being imported,
# at the same place on every machine, instead of a signal sent after a guessed delay.
import sys

class _CtrlC:
    def find_spec(self, name, path=None, target=None):
        if name == "sympy.matrices":
            sys.meta_path.remove(self)
            raise KeyboardInterrupt
        return None

sys.meta_path.insert(0, _CtrlC())
'''


def test_ctrl_c_while_the_command_imports_ends_without_a_traceback(tmp_path):
    # Deterministic: the interrupt is raised inside SymPy's import by a sitecustomize, where
    # a signal sent after a delay lands anywhere (before the package's handler, on a loaded
    # machine) and made this test flaky.
    import os
    import subprocess
    import sys

    (tmp_path / "sitecustomize.py").write_text(_INTERRUPT_DURING_IMPORT)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(tmp_path), *filter(None, [os.environ.get("PYTHONPATH")])]))
    proc = subprocess.run([sys.executable, "-m", "screwsym", "verify", "--jobs", "1"],
                          capture_output=True, text=True, env=env, timeout=120)
    assert "Traceback" not in proc.stderr, proc.stderr
    assert proc.returncode == 130, (proc.returncode, proc.stderr)
    assert proc.stderr.strip() == "screwsym: interrupted", proc.stderr
    assert proc.stdout == ""


def test_the_interrupt_of_the_import_test_does_land(tmp_path):
    # The check above must be able to fail: the same injected interrupt, in a process that
    # imports screwsym as a library, ends with the usual traceback and not the quiet exit.
    import os
    import subprocess
    import sys

    (tmp_path / "sitecustomize.py").write_text(_INTERRUPT_DURING_IMPORT)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(tmp_path), *filter(None, [os.environ.get("PYTHONPATH")])]))
    proc = subprocess.run([sys.executable, "-c", "import screwsym"],
                          capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode != 0 and "KeyboardInterrupt" in proc.stderr, proc.stderr


def test_the_quiet_exit_is_only_for_the_command(monkeypatch):
    import pytest

    from screwsym import _launch

    monkeypatch.setattr("sys.argv", ["/usr/bin/screwsym", "verify"])
    assert _launch.launched_as_command()
    with pytest.raises(SystemExit) as exc:
        _launch.exit_if_command_line()
    assert exc.value.code == 130
    monkeypatch.setattr("sys.argv", ["my_script.py"])
    monkeypatch.setattr("sys.orig_argv", ["python", "my_script.py"], raising=False)
    assert not _launch.launched_as_command()
    _launch.exit_if_command_line()  # a user's script: nothing happens, the interrupt goes on
    monkeypatch.setattr("sys.orig_argv", ["python", "-m", "screwsym", "list"], raising=False)
    assert _launch.launched_as_command()
