"""The command line."""

import json

from screwsym.cli import main


def test_verify_some_table(capsys):
    assert main(["verify", "1.1", "1.34", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert "1.34" in out and "Pitch of a screw" in out and "holds" in out
    assert "2 of 2 statements hold" in out


def test_verify_markdown_and_json(capsys):
    assert main(["verify", "Example 1.4", "--format", "markdown", "--jobs", "1"]) == 0
    assert "| Example 1.4 | Identify" in capsys.readouterr().out
    assert main(["verify", "1.10", "--format", "json", "--jobs", "1"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["ok"] and data["entries"][0]["id"] == "1.10" and data["entries"][0]["kind"] == "identity"


def test_verify_fails_with_exit_1(monkeypatch, capsys):
    import screwsym

    real = screwsym.pitch
    monkeypatch.setattr(screwsym, "pitch", lambda s: 2 * real(s))
    assert main(["verify", "1.34", "--jobs", "1"]) == 1
    out = capsys.readouterr().out
    assert "FAILS" in out and "residual" in out


def test_bad_id_exit_2(capsys):
    assert main(["verify", "1.99"]) == 2
    assert "unknown entry id '1.99'" in capsys.readouterr().err
    assert main(["show", "nope"]) == 2


def test_show(capsys):
    assert main(["show", "Theorem 1.1"]) == 0
    out = capsys.readouterr().out
    assert "kind: conditional" in out and "errata:" in out and "construction:" in out
    assert main(["show", "1.34", "--latex"]) == 0
    assert r"\frac{\mathbf S\cdot\mathbf S^0}" in capsys.readouterr().out
    assert main(["show", "1.34"]) == 0
    assert "(S·S⁰)/(S·S)" in capsys.readouterr().out


def test_list(capsys):
    assert main(["list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 78 and lines[0].startswith("1.1 ")


def test_usage_error():
    assert main(["frobnicate"]) == 2
