r"""The work budget of an exact procedure, and the limit on the cases of a split.

Exact decisions (a determinant of polynomials, a factorisation, a Groebner basis) can
take longer than any user waits.  Every procedure of this floor *charges* its work,
in units of polynomial arithmetic (:func:`charge`), to the budget of the call under way
(:func:`case_budget`, a context manager), and the call stops with a ``ValueError``
naming the method the user called once the budget is spent: an answer within its
budget, or a clear refusal, never a call without a bound.  Outside a budget nothing is
counted.  The units are calibrated so that one is about a microsecond: ``k! t_1 ... t_k``
for a k x k determinant whose rows have at most ``t_i`` terms, ``t**2`` to factor a
polynomial of ``t`` terms.

Not every step can be priced in advance (SymPy's own arithmetic inside a step: a
Groebner basis, a factorisation over an extension).  So the budget is also a bound on
the processor time of the call: ``budget`` units allow ``SLACK`` times as many
microseconds of CPU time (:data:`SLACK`), checked at every charge.  A call that passes
it stops with the same error at its next charge; CPU time, not wall time, so that a
loaded machine does not stop a call that an idle one answers.

A step that can neither be priced in advance nor stopped midway (SymPy's ``groebner``)
runs in a worker process whose CPU time is limited to what the budget has left
(:func:`run_bounded`): stopped there, it ends the call with the same error.

SymPy has no such budget (its ``polys`` run to the end), hence this module.
"""

from __future__ import annotations

import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from time import process_time
from typing import Any, TypeVar

__all__ = [
    "TooManyCases",
    "OverBudget",
    "charge",
    "budget_name",
    "case_budget",
    "bounded",
    "run_bounded",
    "CaseList",
    "MAX_CASES",
    "BUDGET",
    "SLACK",
    "MIN_CPU",
]


#: the default limit on the number of cases of a split (``rank_conditions``, ``mobility_cases``)
MAX_CASES = 200


#: the default work budget of one case split (``rank_conditions``, ``reciprocal_cases``,
#: ``substitutions``, both ``mobility_cases``, ``singularities``): units of polynomial arithmetic,
#: ``k! t_1 ... t_k`` for a k x k determinant whose rows have at most ``t_i`` terms, ``t**2``
#: to factor a polynomial of ``t`` terms (about a microsecond each, measured; see ``charge``)
BUDGET = 20_000_000


#: a budget of ``n`` units also bounds the call's CPU time to ``SLACK * n`` microseconds (the
#: units are calibrated at about a microsecond each; the slack is for the unpriced steps)
SLACK = 5
#: ... and never to less than this many seconds: a budget of a few units (a test's) would
#: otherwise stop on a garbage collection or a page fault between two charges
MIN_CPU = 0.005


class TooManyCases(Exception):
    """A split found more cases than its limit (:class:`CaseList`)."""


class OverBudget(Exception):
    """The work of a split passed its budget (:func:`charge`)."""


#: the work left to the case split under way in this thread (a one-item list), or None
_LEFT: ContextVar[list[int] | None] = ContextVar("screwsym_case_budget", default=None)
#: the CPU time (``time.process_time``) at which the split under way stops, or None
_DEADLINE: ContextVar[float | None] = ContextVar("screwsym_case_deadline", default=None)
#: the name of the method the user called, whose budget holds (for the errors), or None
_NAME: ContextVar[str | None] = ContextVar("screwsym_case_budget_name", default=None)


def charge(units: int) -> None:
    """Spend ``units`` of the budget of the case split under way (none: nothing is counted).

    >>> with case_budget(10, "rank_conditions"):
    ...     charge(11)
    Traceback (most recent call last):
    ...
    ValueError: rank_conditions: the case split needs more work than budget=10 units of polynomial arithmetic (or its CPU time, budget x SLACK microseconds); give some symbols values (xreplace) or pass a larger budget
    >>> charge(11)  # outside a budget nothing is counted
    """
    left = _LEFT.get()
    if left is not None:
        left[0] -= units
        if left[0] < 0:
            raise OverBudget
        deadline = _DEADLINE.get()
        if deadline is not None and process_time() > deadline:
            raise OverBudget


def budget_name(default: str) -> str:
    """The name of the method whose budget holds (:func:`case_budget`), else ``default``: the
    method a user called, for the errors of the procedures it runs.

    >>> with case_budget(10, "mobility_cases"):
    ...     budget_name("rank_conditions")
    'mobility_cases'
    >>> budget_name("rank_conditions")
    'rank_conditions'
    """
    return _NAME.get() or default


@contextmanager
def case_budget(budget: int, name: str) -> Iterator[None]:
    """Bound the work of the case splits run inside (the outermost budget holds).

    ``budget`` is a positive ``int`` (the caller checks it); ``name`` is the method the
    user called.  Past the budget, ``ValueError`` naming ``name`` and ``budget``.
    """
    if _LEFT.get() is not None:  # an outer call's budget bounds this one too
        yield
        return
    token = _LEFT.set([budget])
    name_token = _NAME.set(name)
    deadline_token = _DEADLINE.set(process_time() + max(SLACK * budget * 1e-6, MIN_CPU))
    try:
        yield
    except OverBudget:
        raise ValueError(
            f"{name}: the case split needs more work than budget={budget} units of "
            "polynomial arithmetic (or its CPU time, budget x SLACK microseconds); give some "
            "symbols values (xreplace) or pass a larger budget"
        ) from None
    finally:
        _LEFT.reset(token)
        _NAME.reset(name_token)
        _DEADLINE.reset(deadline_token)


@contextmanager
def bounded(budget: int, name: str, message: str) -> Iterator[None]:
    """The exact arithmetic of the method ``name`` within ``budget`` units, with its own error.

    As :func:`case_budget` (the outermost budget holds, and its error names its method), but
    past the budget the ``ValueError`` says ``message``, formatted with ``name`` and
    ``budget``: what the method computes and what a user can do instead.  ``budget`` is a
    positive ``int`` (the caller checks it).

    >>> msg = "{name}: more than budget={budget} units; pass a larger budget"
    >>> with bounded(10, "forward", msg):
    ...     charge(11)
    Traceback (most recent call last):
    ...
    ValueError: forward: more than budget=10 units; pass a larger budget
    >>> with case_budget(100, "singularities"), bounded(10, "forward", msg):
    ...     charge(11)                       # the outer budget holds
    """
    if _LEFT.get() is not None:  # an outer call's budget holds (its error names it)
        yield
        return
    with case_budget(budget, name):
        try:
            yield
        except OverBudget:
            raise ValueError(message.format(name=name, budget=budget)) from None


_T = TypeVar("_T")


def run_bounded(fn: Callable[..., _T], *args: Any) -> _T:
    """``fn(*args)`` in a worker process stopped when the budget under way runs out of CPU time.

    For a step that can neither be priced in advance nor stopped midway (SymPy's
    ``groebner`` runs to the end).  The worker (forked where the platform can, spawned
    otherwise: then ``fn`` must be a module-level function, and ``args`` and the result
    must pickle either way) may spend the CPU time the budget has left
    (``budget x SLACK`` microseconds from its start, less what the call spent); a
    profiling timer (``ITIMER_PROF``, CPU time) ends it there, and the call stops with
    the budget's ``ValueError``, as at a :func:`charge`.  Where the platform has no such
    timer (Windows) the worker is ended after that much wall time instead, which a loaded
    machine reaches sooner.  Its CPU time is then charged to the budget as the share of
    the CPU bound it used (``t`` microseconds as ``t / SLACK`` units).  An exception in
    ``fn`` is raised here.  Outside a budget, and in a daemonic process (a worker of a
    ``multiprocessing`` pool, which may not start processes), ``fn(*args)`` runs here,
    unbounded as before.

    >>> with case_budget(1_000_000, "demo"):
    ...     run_bounded(pow, 2, 10)
    1024
    >>> run_bounded(pow, 2, 10)                  # outside a budget: called here
    1024
    """
    import multiprocessing as mp

    deadline = _DEADLINE.get()
    if deadline is None or _LEFT.get() is None or mp.current_process().daemon:
        return fn(*args)
    left = deadline - process_time()
    if left <= 0:
        raise OverBudget
    ctx: Any = mp.get_context("fork" if "fork" in mp.get_all_start_methods() else "spawn")
    timer = hasattr(signal, "setitimer")
    receive, send = ctx.Pipe(duplex=False)
    worker = ctx.Process(target=_run_worker, args=(send, fn, args, left if timer else None), daemon=True)
    worker.start()
    send.close()
    try:
        if not receive.poll(None if timer else left):
            raise OverBudget  # no timer: the wall time is up
        try:
            status, value, used = receive.recv()
        except EOFError:  # the worker ended without an answer
            worker.join()
            if timer and worker.exitcode == -signal.SIGPROF:
                raise OverBudget from None
            raise RuntimeError(f"run_bounded: the worker process ended with exit code "
                               f"{worker.exitcode} and no answer") from None
    finally:
        if worker.is_alive():
            worker.kill()
        worker.join()
        receive.close()
    charge(int(used * 1e6 / SLACK))
    if status == "error":
        raise value
    return value


def _run_worker(send: Any, fn: Callable, args: tuple, seconds: float | None) -> None:
    """The worker of :func:`run_bounded`: ``fn(*args)`` under a CPU timer, the answer sent."""
    if seconds is not None:
        signal.signal(signal.SIGPROF, signal.SIG_DFL)  # the default action ends the process
        signal.setitimer(signal.ITIMER_PROF, seconds)
    start = process_time()
    try:
        answer: tuple = ("ok", fn(*args))
    except Exception as error:  # raised again in the caller
        answer = ("error", error)
    if seconds is not None:
        signal.setitimer(signal.ITIMER_PROF, 0)
    used = process_time() - start
    try:
        send.send((*answer, used))
    except Exception as error:  # an answer that does not pickle
        send.send(("error", RuntimeError(f"run_bounded: the answer cannot be sent back: {error!r}"), used))
    send.close()


class CaseList(list):
    """The list of cases found so far, refusing to grow past ``limit``."""

    def __init__(self, limit: int):
        super().__init__()
        self.limit = limit

    def append(self, node) -> None:
        if len(self) >= self.limit:
            raise TooManyCases
        super().append(node)
