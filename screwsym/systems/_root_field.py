r"""Exact arithmetic at one real root of a rational polynomial (for the assembly modes).

A real root ``r`` of an irreducible ``g`` in ``Q[t]`` is held as ``g``, the index of
``r`` among the real roots of ``g`` (increasing, SymPy's ``CRootOf`` numbering) and an
isolating interval with rational ends.  An element of ``Q(r)`` is a polynomial in ``t``
reduced modulo ``g``: it is zero exactly when the remainder is (``g`` irreducible), and
its sign is decided by refining the interval (SymPy's ``refine_root``, Sturm sequences)
until the element has no root in it (``count_roots``), then reading the sign at a
rational point of the interval: a proof, not a float comparison.  SymPy's
``CRootOf`` has no public sign of a polynomial at the root, hence this module.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from sympy import CRootOf, Integer, Poly, Rational

from ..algebra.budget import charge

__all__ = ["RealRoot", "real_roots_of"]


@dataclass(frozen=True)
class RealRoot:
    """The ``index``-th real root of the irreducible ``g`` (a ``Poly`` over QQ), isolated in
    ``[low, high]`` (rational ends; ``low == high`` for a rational root).

    >>> from sympy import Poly, symbols
    >>> t = symbols("t")
    >>> r = real_roots_of(Poly(t**2 - 2, t))[1]
    >>> r.expr, r.sign(Poly(t - 1, t)), r.sign(Poly(t**2 - 2, t))
    (sqrt(2), 1, 0)
    """

    g: Poly
    index: int
    low: Rational
    high: Rational

    @property
    def expr(self) -> Any:
        """The root as a SymPy number: a rational, a surd (degree 2) or a ``CRootOf``."""
        if self.g.degree() == 1:
            return self.low
        return CRootOf(self.g.as_expr(), self.index, radicals=self.g.degree() == 2)

    def reduce(self, h: Poly) -> Poly:
        """``h`` modulo ``g``: the normal form of ``h(r)`` in ``Q(r)``."""
        charge(h.degree() * self.g.degree() + 1)
        return h.rem(self.g)

    def is_zero(self, h: Poly) -> bool:
        """``h(r) == 0``, exactly."""
        return self.reduce(h).is_zero

    def sign(self, h: Poly) -> int:
        """The sign of ``h(r)`` (-1, 0, 1), proved by interval refinement."""
        h = self.reduce(h)
        if h.is_zero:
            return 0
        if h.is_ground:
            return 1 if h.LC() > 0 else -1
        if self.low == self.high:
            v = h(self.low)
            return 1 if v > 0 else (-1 if v < 0 else 0)
        low, high = self.low, self.high
        while h.count_roots(low, high) > 0:  # h(r) != 0: the interval shrinks past h's roots
            charge(h.degree() * self.g.degree() * 10)
            low, high = self.g.refine_root(low, high, eps=(high - low) / 16)
        v = h((low + high) / 2)
        return 1 if v > 0 else (-1 if v < 0 else 0)

    def inverse(self, h: Poly) -> Poly:
        """``1/h(r)`` in ``Q(r)`` (``h(r) != 0``: the caller checked)."""
        h = self.reduce(h)
        charge(self.g.degree() ** 2 * 10)
        return Poly(1 / h.LC(), self.g.gen, domain="QQ") if h.is_ground else h.invert(self.g)

    def value(self, h: Poly) -> Any:
        """``h(r)`` as a SymPy expression (a polynomial in the root, of degree below ``g``'s)."""
        h = self.reduce(h)
        r = self.expr
        return sum((c * r**k for (k,), c in h.terms()), Integer(0))


def real_roots_of(g: Poly) -> list[RealRoot]:
    """The real roots of the irreducible ``g``, increasing, each isolated exactly (Sturm).

    >>> from sympy import Poly, symbols
    >>> t = symbols("t")
    >>> [r.expr for r in real_roots_of(Poly(t**3 - 3*t + 1, t))]
    [CRootOf(t**3 - 3*t + 1, 0), CRootOf(t**3 - 3*t + 1, 1), CRootOf(t**3 - 3*t + 1, 2)]
    """
    charge(g.degree() ** 3 * 20)
    if g.degree() == 1:
        root = -g.nth(0) / g.nth(1)
        return [RealRoot(g, 0, root, root)]
    return [
        RealRoot(g, i, Rational(a), Rational(b))
        for i, ((a, b), _) in enumerate(g.intervals())
    ]
