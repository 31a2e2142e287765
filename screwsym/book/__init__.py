r"""Chapter 1 of Huang, Li & Ding as verified statements.

Every numbered equation (1.1)-(1.58), Examples 1.1-1.4, Theorems 1.1-1.3,
the unnumbered statements, the counting statements and Fig. 1.5 are entries
of a registry.  Each is built from screwsym's public operations on generic
real symbols and verified by an exact decision procedure.

>>> from screwsym.book import entry
>>> e = entry("1.34")
>>> e.title, e.kind
('Pitch of a screw', 'definition')
>>> r = e.verify()
>>> r.ok, r.residual
(True, 0)
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from ._entry import KINDS, Check, CheckResult, Construction, Entry, Result, as_text
from ._registry import entries, entry, ids
from ._verify import Decision, decide_nonzero, decide_zero

__all__ = [
    "KINDS",
    "Check",
    "CheckResult",
    "Construction",
    "Decision",
    "Entry",
    "Result",
    "as_text",
    "decide_nonzero",
    "decide_zero",
    "entries",
    "entry",
    "ids",
    "verify_all",
]


def _ignore_sigint() -> None:  # workers leave Ctrl-C to the parent, which stops the pool
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _verify_one(args: tuple[str, int]) -> Result:
    id_, seed = args
    return entry(id_).verify(seed=seed)


def verify_all(ids: Iterable[str] | None = None, *, seed: int = 0,
               progress: Callable[[int, int, Result], object] | None = None,
               jobs: int = 1) -> list[Result]:
    """Verify the named entries (all by default), in order.

    ``progress(i, n, result)`` is called after each entry.  With ``jobs > 1``
    the entries are shared among that many worker processes (each entry is
    independent); the results come back in the registry's order.

    >>> from screwsym.book import verify_all
    >>> [r.ok for r in verify_all(["1.1", "Example 1.2"])]
    [True, True]
    """
    if not isinstance(jobs, int) or isinstance(jobs, bool) or jobs < 1:
        raise ValueError(f"jobs: expected a positive integer, got {jobs!r}")
    chosen = entries() if ids is None else [entry(i) for i in ids]
    work = [(e.id, seed) for e in chosen]
    results: list[Result] = []
    if jobs == 1 or len(work) < 2:
        for i, w in enumerate(work):
            results.append(_verify_one(w))
            if progress is not None:
                progress(i, len(work), results[-1])
        return results
    import multiprocessing as mp

    method = "fork" if "fork" in mp.get_all_start_methods() else None
    with mp.get_context(method).Pool(jobs, initializer=_ignore_sigint) as pool:
        for i, r in enumerate(pool.imap(_verify_one, work, chunksize=1)):
            results.append(r)
            if progress is not None:
                progress(i, len(work), r)
    return results
