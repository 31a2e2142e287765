r"""Entries of the book registry, their constructions and their results.

An :class:`Entry` is one statement of Chapter 1: an equation, an example, a
theorem, or an unnumbered statement.  Its ``build`` function makes generic
real symbols, builds the objects with screwsym's public API and records, in a
:class:`Construction`, the expressions that must vanish, the counter-examples
that must not, and predicates that must hold.  :meth:`Entry.verify` runs the
exact decision procedure of :mod:`screwsym.book._verify` on each of them.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from sympy import Basic, S, latex, sympify
from sympy.matrices import MatrixBase

from ._verify import decide_nonzero, decide_zero, provably_nonnegative

__all__ = ["KINDS", "Construction", "Check", "CheckResult", "Entry", "Result"]

#: the kinds of statement: a definition, an identity, a statement under a condition
#: (with counter-examples where the condition fails) and a numeric example
KINDS = ("definition", "identity", "conditional", "numeric")


@dataclass(frozen=True)
class Check:
    """One recorded check of a construction.

    ``kind`` is ``'zero'`` (``value`` must vanish identically), ``'nonzero'``
    (a counter-example: ``value`` must *not* vanish), ``'holds'`` (``value``
    is a predicate that must be ``True``) or ``'nonnegative'``.
    ``book`` marks a check that shows the book's uncorrected version failing.
    """

    label: str
    kind: str
    value: Any
    at: dict | None = None
    book: bool = False


class Construction:
    """What a statement's construction records: zeros, counter-examples, predicates.

    >>> from sympy import symbols
    >>> x = symbols("x", real=True)
    >>> c = Construction()
    >>> c.zero("square", (x + 1)**2 - x**2 - 2*x - 1)
    >>> c.nonzero("off by one", (x + 1)**2 - x**2 - 2*x)
    >>> [ch.kind for ch in c.checks]
    ['zero', 'nonzero']
    """

    def __init__(self) -> None:
        self.checks: list[Check] = []

    def zero(self, label: str, value: Any) -> None:
        """Record an expression (scalar or matrix) that must vanish identically."""
        self.checks.append(Check(label, "zero", value))

    def nonzero(self, label: str, value: Any, *, at: dict | None = None, book: bool = False) -> None:
        """Record a counter-example: ``value`` must be shown non-zero at a rational point."""
        self.checks.append(Check(label, "nonzero", value, at, book))

    def holds(self, label: str, value: Any, *, book: bool = False) -> None:
        """Record a predicate (e.g. ``classify(s) == 'couple'``) that must be True."""
        self.checks.append(Check(label, "holds", value, None, book))

    def nonnegative(self, label: str, value: Any) -> None:
        """Record an expression that must be nonnegative by its structure."""
        self.checks.append(Check(label, "nonnegative", value))


@dataclass(frozen=True)
class CheckResult:
    """The outcome of one :class:`Check`: ``ok``, the residual and how it was decided."""

    label: str
    kind: str
    ok: bool
    residual: Any
    how: str
    book: bool = False


@dataclass(frozen=True)
class Result:
    r"""The result of verifying one entry.

    ``ok`` is True when every check holds; ``residual`` is exactly ``0`` then,
    and otherwise the residual of the first failing check; ``checks`` lists
    every check's outcome; ``elapsed`` is the time taken, in seconds;
    ``error`` is the text of an exception raised by the construction.
    """

    id: str
    ok: bool
    checks: tuple[CheckResult, ...]
    elapsed: float
    error: str | None = None

    @property
    def residual(self) -> Any:
        """``0`` when the entry holds, else the first failing check's residual."""
        for c in self.checks:
            if not c.ok:
                return c.residual
        return S.Zero if self.error is None else None

    @property
    def residuals(self) -> tuple[Any, ...]:
        """The residuals of the ``zero`` checks, in order (each exactly 0 when it holds)."""
        return tuple(c.residual for c in self.checks if c.kind == "zero")

    @property
    def counterexamples(self) -> tuple[CheckResult, ...]:
        """The outcomes of the counter-example checks."""
        return tuple(c for c in self.checks if c.kind == "nonzero")

    @property
    def failures(self) -> tuple[CheckResult, ...]:
        """The checks that failed."""
        return tuple(c for c in self.checks if not c.ok)


def _run(check: Check, seed: int) -> CheckResult:
    if check.kind == "zero":
        d = decide_zero(check.value, seed=seed)
        how = f"stage {d.stage}" + ("" if d.guard else "; numeric guard disagrees")
        return CheckResult(check.label, "zero", d.ok, d.residual, how, check.book)
    if check.kind == "nonzero":
        nz, point, value = decide_nonzero(check.value, seed=seed, at=check.at)
        how = f"non-zero ({value}) at {point}" if nz else "not shown non-zero"
        residual = value if nz else S.Zero
        return CheckResult(check.label, "nonzero", nz, residual, how, check.book)
    if check.kind == "holds":
        ok = check.value is True
        return CheckResult(check.label, "holds", ok, check.value, "predicate", check.book)
    if check.kind == "nonnegative":
        ok = provably_nonnegative(check.value)
        return CheckResult(check.label, "nonnegative", ok, check.value, "structure", check.book)
    raise ValueError(f"check kind: expected zero, nonzero, holds or nonnegative, got {check.kind!r}")


@dataclass(frozen=True)
class Entry:
    r"""One statement of Chapter 1, with the construction that verifies it.

    Attributes: ``id`` (``"1.34"``, ``"Example 1.4"``, ``"Theorem 1.1"``,
    ``"Counting: lines"``, ...), ``section``, ``title``, ``statement`` (LaTeX,
    as the book means it, its slips corrected; :attr:`text` is plain text),
    ``kind`` (one of :data:`KINDS`), ``construction`` (the construction in
    words), ``errata`` (corrections of the book, each citing the book's section
    and equation), ``notes`` (remarks: readings of the scanned text, and points
    reviewed and found not to be errors) and ``build`` (the construction).

    Examples
    ========

    >>> from screwsym.book import entry
    >>> e = entry("1.33")
    >>> e.kind, e.section
    ('identity', '1.4.2')
    >>> e.verify().ok
    True
    """

    id: str
    section: str
    title: str
    statement: str
    kind: str
    construction: str
    build: Callable[[Construction], None] = field(repr=False, compare=False)
    errata: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"kind: expected one of {KINDS}, got {self.kind!r}")

    @property
    def text(self) -> str:
        """The statement as plain Unicode text (no LaTeX), for terminals.

        >>> from screwsym.book import entry
        >>> entry("1.34").text
        'h = (S·S⁰)/(S·S) = (lp+mq+nr)/(l²+m²+n²)'
        """
        from ._text import latex_to_text

        return latex_to_text(self.statement)

    @property
    def tag(self) -> str:
        """The label used in ``\\tag{}``: the equation number, or the id."""
        return self.id

    def _repr_latex_(self) -> str:
        """Jupyter shows the entry as its numbered equation."""
        return f"$$ {self.statement} \\tag{{{self.tag}}} $$"

    def construct(self) -> Construction:
        """Run the construction and return what it recorded."""
        c = Construction()
        self.build(c)
        return c

    def verify(self, *, seed: int = 0, stop_at_failure: bool = False) -> Result:
        """Verify the entry exactly; see :class:`Result`.

        With ``stop_at_failure`` the checks after the first failing one are
        not run (the result lists the checks run so far); the mutation tests
        use it to fail fast.
        """
        t0 = time.perf_counter()
        try:
            c = self.construct()
            done: list[CheckResult] = []
            for i, ch in enumerate(c.checks):
                done.append(_run(ch, seed + 7 * i))
                if stop_at_failure and not done[-1].ok:
                    break
            results = tuple(done)
            error = None if results else "the construction recorded no checks"
        except Exception as exc:  # a broken core operation must fail the entry, not the run
            results, error = (), f"{type(exc).__name__}: {exc}"
        ok = error is None and all(r.ok for r in results)
        return Result(self.id, ok, results, time.perf_counter() - t0, error)


def as_text(value: Any) -> str:
    """A one-line text form of a residual."""
    if isinstance(value, (Basic, MatrixBase)):
        return str(value.T if isinstance(value, MatrixBase) and value.cols == 1 else value)
    return str(value)


def as_latex(value: Any) -> str:
    """A LaTeX form of a residual."""
    if isinstance(value, (Basic, MatrixBase, int)):
        return latex(sympify(value, strict=True) if isinstance(value, int) else value)
    return str(value)

