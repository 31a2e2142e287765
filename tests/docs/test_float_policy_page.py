"""The float policy page states the tolerance the code uses (its snippets run in test_pages.py)."""

from pathlib import Path

PAGE = Path(__file__).resolve().parents[2] / "notebooks" / "float-policy.md"


def test_float_policy_page_states_the_tolerance_of_core_decide():
    from sympy import Float, Rational

    from screwsym.core.decide import float_tau

    text = PAGE.read_text(encoding="utf-8")
    assert float_tau(Float(1.0)) == Rational(1, 2**40)
    assert "2^{13 - p}" in text and "2^{-40}" in text
