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

from ._entry import KINDS, Check, CheckResult, Construction, Entry, Result
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
    "decide_nonzero",
    "decide_zero",
    "entries",
    "entry",
    "ids",
    "verify_all",
]


def verify_all(ids=None, *, seed: int = 0, progress=None) -> list[Result]:
    """Verify the named entries (all by default); ``progress(i, n, entry)`` is called before each.

    >>> from screwsym.book import verify_all
    >>> [r.ok for r in verify_all(["1.1", "Example 1.2"])]
    [True, True]
    """
    chosen = entries() if ids is None else [entry(i) for i in ids]
    results = []
    for i, e in enumerate(chosen):
        if progress is not None:
            progress(i, len(chosen), e)
        results.append(e.verify(seed=seed))
    return results
