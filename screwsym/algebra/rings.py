r"""Expressions as columns of a sparse polynomial ring, and back.

A matrix of rational functions of symbols (and of ``sin(q)``, ``cos(q)``, see
:mod:`~screwsym.algebra.circle`), with rational or algebraic coefficients such as
``sqrt(3)``, becomes its columns over ``K[x_1, ..., x_n]`` (:func:`to_ring`), each
column cleared of its denominators (a non-zero multiple spans the same screw), ``K``
the smallest field of the coefficients (:func:`number_field`, SymPy's
``QQ.algebraic_field``).  The arithmetic there is exact and fraction-free, so zero is
decided by reducing, never by ``simplify``; :func:`to_expr` brings an element back in
the user's symbols.

Where it does not simply call SymPy: the coefficients go through
:func:`field_element`, which converts only the irrational factors with ``K.from_sympy``
(cached), because ``from_sympy`` computes a minimal polynomial each time and fails on
huge rational factors (SymPy 1.14: ``zoo is not in any domain``).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from sympy import (
    QQ,
    Add,
    CRootOf,
    Dummy,
    ImmutableMatrix,
    Mul,
    Pow,
    Rational,
    Symbol,
    cancel,
    cos,
    sin,
)
from sympy.polys.polyutils import parallel_dict_from_expr

from .circle import TRIG_BACK, angles_of, reduce_circle, trig_entries
from .numberfield import field_lcm

__all__ = [
    "PolyColumns",
    "number_field",
    "field_element",
    "to_ring",
    "vanishes",
    "circle_normal",
    "rational_parts",
    "to_expr",
    "ring_element",
    "ring_with",
    "tree_to_ring",
    "NotInRing",
]


@dataclass(frozen=True)
class PolyColumns:
    """A system as polynomial columns: ``cols`` (n rows of 6 ring elements) and its ring.

    ``scales``: per column, the polynomial it was multiplied by to clear its denominators
    (``cols[j] = scales[j] * column j`` as functions, on the unit circle of each angle).
    """

    ring: Any
    gens: tuple
    cols: tuple  # one tuple of 6 ring elements per screw (of M.rows elements in general)
    scales: tuple = ()


@lru_cache(maxsize=64)
def number_field(numbers: tuple):
    """``QQ``, or the algebraic number field ``QQ<numbers>``."""
    return QQ.algebraic_field(*numbers) if numbers else QQ


def field_element(K, c):
    """A SymPy number as an element of ``K``: its rational parts times cached algebraic ones.

    Only the irrational factors (``sqrt(3)``) go through ``K.from_sympy``,
    which computes a minimal polynomial each time and fails on huge rational
    factors (SymPy 1.14: ``zoo is not in any domain``).
    """
    total = K.zero
    for term in Add.make_args(c):
        q, rest = term.as_coeff_Mul()
        total += K.convert(QQ.from_sympy(q)) * (K.one if rest == 1 else _product(K, rest))
    return total


def _product(K, rest):
    """A product of algebraic numbers in ``K``: each base converted once (cached), its integer
    power taken inside ``K`` (``K.from_sympy(r**11)`` of a degree-11 ``CRootOf`` computes a
    minimal polynomial of the power: minutes, issue 32)."""
    out = K.one
    for f in Mul.make_args(rest):
        b, e = f.as_base_exp()
        if e.is_Integer and e != 1 and not b.is_Rational:
            x = _algebraic(K, b)
            out *= x ** int(e) if e > 0 else K.quo(K.one, x ** int(-e))
        else:
            out *= _algebraic(K, f)
    return out


@lru_cache(maxsize=1024)
def _algebraic(K, c):
    return K.from_sympy(c)


def to_ring(M: ImmutableMatrix) -> PolyColumns:
    """The columns of ``M`` as polynomials, each column cleared of its denominators.

    A column multiplied by a non-zero polynomial spans the same screw wherever
    that polynomial is non-zero, and where it vanishes the column itself is
    undefined.  ``sin(q)`` and ``cos(q)`` of a symbol ``q`` become two ring
    symbols on the unit circle (see :func:`trig_entries`); raises
    ``ValueError`` for other entries that are not rational functions of
    symbols (``tan(t)``, ``sqrt(x)``).
    """
    return _to_ring_cached(ImmutableMatrix(M))


def vanishes(e: Any) -> bool:
    """Whether ``e`` is identically zero: a rational function of symbols and of ``sin(q)``,
    ``cos(q)``, decided in the ring (``sin(q)**2 + cos(q)**2 = 1`` for each angle).

    >>> from sympy import cos, sin, symbols
    >>> from screwsym.algebra.rings import vanishes
    >>> q = symbols("q", real=True)
    >>> vanishes((1 + cos(q)) * (1 - cos(q)) - sin(q)**2), vanishes(sin(q) - 1)
    (True, False)
    """
    if not e.has(sin, cos, CRootOf):
        return cancel(e) == 0
    # in the ring: over the algebraic field of the CRootOf (cancel would take it for a symbol)
    return not to_ring(ImmutableMatrix([e])).cols[0][0]


def circle_normal(e: Any) -> Any:
    """``e`` with its numerator and denominator reduced by ``sin(q)**2 + cos(q)**2 = 1``
    (each of degree at most 1 in ``cos(q)``: the normal form on the circle).

    >>> from sympy import cos, sin, symbols
    >>> from screwsym.algebra.rings import circle_normal
    >>> q = symbols("q", real=True)
    >>> circle_normal(sin(q)**3 + sin(q)*cos(q)**2)
    sin(q)
    """
    if not e.has(sin, cos):
        return e
    rg = to_ring(ImmutableMatrix([e]))
    num, den = rg.cols[0][0], rg.scales[0]
    # the denominator made monic *after* its reduction, so that the form is idempotent (a
    # reduction may leave it a negative leading coefficient, which the next call's monic
    # lcm would flip: 1/(sin**2 cos**2 + 1) -> 1/(-sin**4 + sin**2 + 1) -> -1/(sin**4 - ...))
    K = rg.ring.domain
    if den and den.LC != K.one:
        inv = K.quo(K.one, den.LC)
        num, den = num * inv, den * inv
    return to_expr(num, rg.ring) / to_expr(den, rg.ring)


def rational_parts(entries: list, what: str) -> tuple[list, list, list]:
    """The symbols, the algebraic numbers and the numerators and denominators of ``entries``.

    ``sin(q)`` and ``cos(q)`` of symbols are first replaced by their ring symbols
    (:func:`trig_entries`).  Raises ``ValueError`` naming ``what`` (``"screws: expected
    entries"``, ...) for an entry that is not a rational function of symbols and of sin
    and cos of symbols with rational or algebraic coefficients.
    """
    entries = trig_entries(entries)
    syms = sorted(set().union(*(e.free_symbols for e in entries)) if entries else set(), key=str)
    numbers: list = []
    parts = [part for e in entries for part in e.as_numer_denom()]
    if parts:
        _, found = parallel_dict_from_expr(parts)
        for g in found["gens"] if isinstance(found, dict) else found:
            if isinstance(g, Symbol):
                continue
            # a CRootOf of a rational polynomial is algebraic (SymPy 1.13 leaves it None)
            if g.is_number and (g.is_algebraic or isinstance(g, CRootOf)):
                numbers.append(g)
                continue
            raise ValueError(
                f"{what} that are rational functions of symbols and polynomial in sin and "
                f"cos of symbols with rational or algebraic coefficients, got {g} in an entry"
            )
    return syms, numbers, parts


@lru_cache(maxsize=512)
def _to_ring_cached(M: ImmutableMatrix) -> PolyColumns:
    entries = list(M)
    syms, numbers, parts = rational_parts(entries, "screws: expected entries")
    K = number_field(tuple(sorted(numbers, key=str)))
    gens = tuple(syms) if syms else (Dummy("c"),)
    R = K[gens]
    ring = R.ring
    if entries:
        dicts, _ = parallel_dict_from_expr(parts, gens=gens)
        polys = [ring.from_dict({m: field_element(K, c) for m, c in d.items()}) for d in dicts]
    else:
        polys = []
    cols, scales = [], []
    for j in range(M.cols):
        # M is row-major: entry (i, j) is number i * cols + j, its numerator and denominator
        nums = [polys[2 * (i * M.cols + j)] for i in range(M.rows)]
        dens = [polys[2 * (i * M.cols + j) + 1] for i in range(M.rows)]
        if all(d.is_ground for d in dens):
            cols.append(tuple(n if d == 1 else n * K.quo(K.one, d.LC)
                              for n, d in zip(nums, dens, strict=True)))
            scales.append(R.one)
            continue
        den = R.one
        for d in dens:
            den = field_lcm(den, d, R) if K.is_Algebraic else R.lcm(den, d)
        cols.append(tuple(n * R.exquo(den, d) for n, d in zip(nums, dens, strict=True)))
        scales.append(den)
    if angles_of(R):
        cols = [tuple(reduce_circle(e, R) for e in col) for col in cols]
        scales = [reduce_circle(d, R) for d in scales]
    return PolyColumns(R, tuple(syms), tuple(cols), tuple(scales))


def to_expr(p, R) -> Any:
    """A ring element as a SymPy expression in the user's symbols (``sin(q)``, not its ring symbol)."""
    e = R.to_sympy(p)
    return e.xreplace(TRIG_BACK) if angles_of(R) else e


def ring_element(e: Any, R) -> Any:
    """The polynomial ``e`` (in the user's symbols, ``sin(q)`` allowed) as an element of ``R``."""
    e = trig_entries([e])[0]
    (d,), _ = parallel_dict_from_expr([e], gens=R.symbols)
    K = R.domain
    return R.ring.from_dict({m: field_element(K, c) for m, c in d.items()})


def ring_with(M: ImmutableMatrix, fe: Any) -> PolyColumns:
    """``M``'s columns in a ring that has ``fe``'s symbols too (a case of an earlier system)."""
    extra = ImmutableMatrix(M.rows, 1, [fe] + [0] * (M.rows - 1))
    rg = to_ring(ImmutableMatrix.hstack(M, extra))
    return PolyColumns(rg.ring, rg.gens, rg.cols[:-1], rg.scales[:-1])


class NotInRing(ValueError):
    """An expression is not an element of the ring (or a fraction of two) it was to be read in."""


def tree_to_ring(e: Any, R: Any, index: dict, fractions: bool = False) -> Any:
    """The expression ``e`` as an element of the polynomial ring ``R``, by ring arithmetic on
    its expression tree: each node converted once (shared subtrees too), nothing expanded,
    no gcd taken.

    ``index`` maps each atom that is a generator (a symbol, a root ``b**(1/q)``, a
    function) to its generator of ``R``; a rational power ``b**(p/q)`` is read as the
    generator of ``b**(1/q)`` to the ``p``.  With ``fractions=False`` the result is an
    element of ``R`` and ``NotInRing`` is raised for what is not a polynomial in the
    generators (a negative power, an atom not in ``index``); with ``fractions=True`` it is a
    pair ``(numerator, denominator)`` of elements of ``R`` (the denominator the product of
    the denominators met, not reduced), and ``NotInRing`` is raised where a denominator is
    the zero polynomial.  Reading the generators back is a ring homomorphism, so a zero
    numerator proves ``e`` zero wherever it is defined.

    One walker for the floors above: :func:`screwsym.core.tidy.tidy` reads polynomials
    with it, :func:`screwsym.core.decide.is_zero` fractions.  SymPy's ``R.from_expr`` does
    the same for polynomials with a search for powers of generators at every node, and
    ``sring`` expands first; both were several times slower on the core's expressions.

    >>> from sympy import QQ, Rational, sqrt, symbols
    >>> from sympy.polys.rings import PolyRing
    >>> x, y = symbols("x y")
    >>> R = PolyRing([x, sqrt(y)], QQ, "lex")
    >>> index = dict(zip([x, sqrt(y)], R.gens))
    >>> tree_to_ring((x + 1)**2 - 2*x, R, index)
    x**2 + 1
    >>> tree_to_ring(x / (x + 1) + y**Rational(3, 2), R, index, fractions=True)
    (x*(sqrt(y))**3 + x + (sqrt(y))**3, x + 1)
    >>> tree_to_ring(1 / x, R, index)
    Traceback (most recent call last):
    ...
    screwsym.algebra.rings.NotInRing: not a polynomial in (x, sqrt(y)): 1/x
    """
    memo: dict[int, Any] = {}
    one, domain = R.one, R.domain

    def fail(x: Any) -> NotInRing:
        return NotInRing(f"not a polynomial in {tuple(R.symbols)}: {x}")

    def poly(x: Any) -> Any:
        got = memo.get(id(x))
        if got is not None:
            return got
        if x.is_Rational:
            out = R.ground_new(domain.convert(x))
        elif x.is_Add:
            out = R.zero
            for a in x.args:
                out += poly(a)
        elif x.is_Mul:
            out = one
            for a in x.args:
                out *= poly(a)
        elif x.is_Pow and x.exp.is_Integer and x.exp >= 0:
            out = poly(x.base) ** int(x.exp)
        elif x.is_Pow and x.exp.is_Rational and x.exp > 0 and not x.exp.is_Integer:
            g = index.get(Pow(x.base, Rational(1, x.exp.q)))
            if g is None:
                raise fail(x)
            out = g ** int(x.exp.p)
        else:
            out = index.get(x)
            if out is None:
                raise fail(x)
        memo[id(x)] = out
        return out

    def frac(x: Any) -> tuple:
        got = memo.get(id(x))
        if got is not None:
            return got
        if x.is_Rational:
            out = (R.ground_new(domain.convert(x)), one)
        elif x.is_Add:
            num, den = frac(x.args[0])
            for a in x.args[1:]:
                n, d = frac(a)
                if d == den:
                    num = num + n
                else:
                    num, den = num * d + n * den, den * d
            out = (num, den)
        elif x.is_Mul:
            num, den = one, one
            for a in x.args:
                n, d = frac(a)
                num, den = num * n, den * d
            out = (num, den)
        elif x.is_Pow and x.exp.is_Integer:
            n, d = frac(x.base)
            k = int(x.exp)
            if k < 0:
                n, d, k = d, n, -k
            out = (n**k, d**k)
        elif x.is_Pow and x.exp.is_Rational:
            g = index.get(Pow(x.base, Rational(1, x.exp.q)))
            if g is None:
                raise fail(x)
            k = int(x.exp.p)
            out = (g**k, one) if k >= 0 else (one, g ** (-k))
        else:
            g = index.get(x)
            if g is None:
                raise fail(x)
            out = (g, one)
        if not out[1]:
            raise NotInRing(f"a denominator is zero in {tuple(R.symbols)}: {x}")
        memo[id(x)] = out
        return out

    return frac(e) if fractions else poly(e)
