"""The work budget (``screwsym.algebra.budget``): charged inside ``case_budget``, nothing outside.

A budget is spent by ``charge``; past it the call stops with a ``ValueError`` that names
the method the user called (the outermost budget's name), never a silent overrun.  A
nested budget defers to the outer one.  ``CaseList`` refuses to grow past its limit.
"""

from __future__ import annotations

import threading

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from screwsym.algebra.budget import (
    CaseList,
    OverBudget,
    TooManyCases,
    budget_name,
    case_budget,
    charge,
)

SETTINGS = settings(max_examples=80, deadline=None, derandomize=True)


def spend(total: int, units: list[int], name: str = "rank_conditions") -> int | None:
    """Charge ``units`` one by one inside a budget of ``total``: the index of the charge that
    stopped the call (ValueError), or None if all fit."""
    done = 0
    try:
        with case_budget(total, name):
            for k, u in enumerate(units):
                done = k
                charge(u)
    except ValueError as err:
        assert name in str(err) and f"budget={total}" in str(err)
        return done
    return None


def first_over(total: int, units: list[int]) -> int | None:
    """The oracle: the first charge after which the running sum passes ``total``."""
    s = 0
    for k, u in enumerate(units):
        s += u
        if s > total:
            return k
    return None


@SETTINGS
@given(st.integers(1, 10_000), st.lists(st.integers(0, 3_000), max_size=12))
def test_the_call_stops_at_the_first_charge_past_the_budget(total, units):
    assert spend(total, units) == first_over(total, units)


def test_the_oracle_of_the_budget_can_fail():
    # a budget that let one more unit through would disagree with the oracle
    assert first_over(10, [10]) is None and first_over(10, [10, 1]) == 1
    assert spend(10, [10, 1]) == 1 and spend(10, [10, 1]) != first_over(11, [10, 1])


def test_exactly_the_budget_is_allowed_and_one_more_is_not():
    with case_budget(10, "rank_conditions"):
        charge(10)
    with pytest.raises(ValueError, match=r"^mobility_cases: .*budget=10 units"), \
            case_budget(10, "mobility_cases"):
        charge(10)
        charge(1)


def test_the_error_names_the_method_called_not_a_default():
    with pytest.raises(ValueError) as err, case_budget(5, "reciprocal_cases"):
        charge(6)
    assert str(err.value).startswith("reciprocal_cases:")
    assert "rank_conditions" not in str(err.value)  # the name given, not another one
    assert "xreplace" in str(err.value) and "larger budget" in str(err.value)


def test_nothing_is_counted_outside_a_budget():
    charge(10**18)  # no budget: no error
    assert budget_name("rank_conditions") == "rank_conditions"
    # and nothing charged outside is carried into the next budget
    with case_budget(100, "rank_conditions"):
        charge(100)


def test_an_over_budget_signal_outside_is_not_turned_into_a_value_error():
    with pytest.raises(OverBudget):
        raise OverBudget
    with pytest.raises(ValueError, match="substitutions"), case_budget(1, "substitutions"):
        raise OverBudget  # inside, the signal becomes the user's error


def test_each_budget_starts_full():
    for _ in range(3):
        with case_budget(7, "rank_conditions"):
            charge(7)


def test_the_outer_budget_holds_over_a_nested_one():
    # a larger inner budget does not extend the outer one
    with pytest.raises(ValueError, match=r"^mobility_cases: .*budget=100 "), \
            case_budget(100, "mobility_cases"):
        charge(60)
        with case_budget(10**9, "rank_conditions"):
            assert budget_name("x") == "mobility_cases"
            charge(41)
    # a smaller inner budget does not bind either: the outer one is spent
    with case_budget(100, "mobility_cases"):
        with case_budget(10, "rank_conditions"):
            charge(90)
        charge(10)
        with pytest.raises(OverBudget):  # the inner block is left; the outer still counts
            charge(1)


def test_the_budget_and_its_name_are_reset_after_an_error():
    with pytest.raises(ValueError), case_budget(1, "mobility_cases"):
        charge(2)
    assert budget_name("rank_conditions") == "rank_conditions"
    charge(10**18)


def test_other_errors_pass_through_a_budget():
    with pytest.raises(KeyError), case_budget(1, "rank_conditions"):
        raise KeyError("x")
    assert budget_name("d") == "d"


def test_budget_name():
    assert budget_name("rank_conditions") == "rank_conditions"
    with case_budget(10, "mobility_cases"):
        assert budget_name("rank_conditions") == "mobility_cases"
    assert budget_name("reciprocal_cases") == "reciprocal_cases"


def test_another_thread_does_not_share_the_budget():
    seen: list = []

    def work():
        charge(10**9)  # this thread has no budget under way
        seen.append(budget_name("none"))

    with case_budget(1, "rank_conditions"):
        th = threading.Thread(target=work)
        th.start()
        th.join()
    assert seen == ["none"]


@pytest.mark.parametrize("limit", [0, 1, 3])
def test_case_list_refuses_past_its_limit(limit):
    out = CaseList(limit)
    for k in range(limit):
        out.append(k)
    with pytest.raises(TooManyCases):
        out.append(limit)
    assert out == list(range(limit)) and out.limit == limit


def test_the_budget_bounds_the_cpu_time_of_unpriced_work():
    # a step the units do not price (SymPy's own arithmetic) is bounded by the CPU time the
    # budget allows, SLACK microseconds a unit, checked at the next charge
    import time

    import pytest

    from screwsym.algebra.budget import SLACK, case_budget, charge

    units = 2_000  # 10 ms of CPU time with SLACK = 5
    with pytest.raises(ValueError, match="its CPU time"):
        with case_budget(units, "singularities"):
            charge(1)  # well within both bounds
            start = time.process_time()
            while time.process_time() - start < 2 * SLACK * units * 1e-6:
                pass
            charge(1)
    # the same work within the time passes: the bound is the time, not the units
    with case_budget(units, "singularities"):
        charge(1)
        charge(1)


def test_a_tiny_budget_still_allows_a_few_milliseconds_of_cpu():
    # a budget of a few units bounds the time to MIN_CPU, not to SLACK * units microseconds (35 us
    # for 7 units: a garbage collection between two charges would stop it; seen under load)
    import time

    from screwsym.algebra.budget import MIN_CPU, SLACK, case_budget, charge

    assert SLACK * 7 * 1e-6 < MIN_CPU / 10
    with case_budget(7, "rank_conditions"):
        start = time.process_time()
        while time.process_time() - start < MIN_CPU / 5:
            pass
        charge(7)
    with pytest.raises(ValueError, match="its CPU time"), case_budget(7, "rank_conditions"):
        start = time.process_time()
        while time.process_time() - start < 2 * MIN_CPU:
            pass
        charge(1)


def _spin(n: int) -> int:
    """Work without a charge, as SymPy's groebner does: a loop of ``n`` steps."""
    total = 0
    for k in range(n):
        total += k * k % 7
    return total


def _fail() -> None:
    raise ZeroDivisionError("in the worker")


def test_run_bounded_stops_a_worker_past_the_budget_and_charges_its_time():
    from screwsym.algebra.budget import run_bounded

    # within the budget: the worker's answer, and its CPU time charged (t / SLACK units)
    with case_budget(2_000_000, "demo"):
        assert run_bounded(_spin, 1000) == _spin(1000)
    with pytest.raises(ValueError, match="demo: the case split needs more work than budget=40000"):
        with case_budget(40_000, "demo"):  # 0.2 s of CPU: an endless loop is ended there
            run_bounded(_spin, 10**12)
    with pytest.raises(ZeroDivisionError, match="in the worker"):  # raised in the caller
        with case_budget(2_000_000, "demo"):
            run_bounded(_fail)
    assert run_bounded(_spin, 10) == _spin(10)  # outside a budget: called here
