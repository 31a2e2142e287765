r"""Angles written as decimals: the multiple of pi/N a decimal is a printing of.

Explanation
===========

A robot file writes pi/2 as ``1.5708``, ``-1.5707963`` or ``1.5707963267948966``:
the decimal is the angle *rounded to the digits the program printed*.  Read
as written, exactly, ``1.5708`` is the rational 3927/2500, and its sine and
cosine are transcendental numbers that no product of matrices cancels: a
robot read that way is exact but out of reach (a Kinova arm took minutes for
forward kinematics).  :func:`recognise_decimal` takes the decimal back to the
multiple of ``pi/N`` (``N = 12`` by default: multiples of 15 degrees, whose
sines and cosines lie in Q(sqrt 2, sqrt 3)) that it is a printing of, by this
rule:

- the text has ``d >= 4`` decimal places (digits after the point, less the
  exponent: ``1.5708`` has 4, ``15.708e-1`` has 4, ``1.57`` has 2), and
- either the decimal *is* ``k pi/N`` rounded to ``d`` places,
  ``|x - k pi/N| < 10**-d / 2`` (decided exactly: pi is irrational, there
  is no tie), or, for the texts a program writes from a binary float, the
  decimal and ``k pi/N`` round to the same IEEE double (text of 15 or more
  significant digits) or the same single (7 or more; ``1.5707964`` is
  ``numpy.float32(pi/2)`` printed).

Why four places: with ``d`` places a decimal chosen without pi in mind lands
within half a unit of the last place of some multiple of pi/12 with
probability ``10**-d / (pi/12)``: 3.8% for two places (``1.57`` is
``round(pi/2, 2)``, and so is a length-like ``1.57`` a designer meant), 0.4%
for three, 0.04% for four.  From four places on, a match is the printing of
the multiple beyond reasonable doubt, so ``1.57`` and ``3.14`` are kept as
written and ``1.5708`` and ``3.1416`` are recognised; an exact zero is zero
(not reported).  Each
recognised value is reported (:class:`RecognisedAngle`: the text, where it
stood, the value used) and a :class:`RecognisedAngleWarning` says so; a user
who wants every decimal as written asks for ``angles="exact"``.

:func:`recognise_float` is the same rule for a binary float (a Python float
or ``numpy.float32``, whose printed precision is its own): the float lies
within 4 units in its last place of ``k pi/N`` (as a double; as a single
for a value a single holds exactly).  :func:`recognise_trig_float`
recognises the float nearest a sine or cosine of such an angle (``0.5``,
``0.7071067811865476``, ...: within ``TRIG_TOL``) for rotation matrices
written as floats.
"""

from __future__ import annotations

import math
import re
import warnings
from collections.abc import Sequence
from functools import lru_cache
from typing import Any, NamedTuple

import mpmath  # type: ignore[import-untyped]  # SymPy's dependency: pi to any precision
import numpy as np
from sympy import QQ, Dummy, Expr, Float, Pow, Rational, S, cos, expand_trig, pi, sin, sqrt
from sympy.core.sorting import default_sort_key
from sympy.polys.polyerrors import CoercionFailed, GeneratorsError, PolynomialError
from sympy.polys.rings import ring

from ..algebra.budget import charge
from ..algebra.circle import reduce_powers
from ..algebra.numberfield import reduce_surds, surd_split

__all__ = ["RecognisedAngle", "RecognisedAngleWarning", "recognise_decimal", "recognise_float",
           "recognise_trig_float", "angle_step", "warn_recognised", "constant_trig_normal",
           "MIN_PLACES", "TRIG_TOL", "NOISE"]

#: the noise of double arithmetic on angles up to a turn: 4 units in the last place of a double
#: at 2 pi (about 3.6e-15); a decimal this close to k pi/N (0 included: ``-5.19179e-17``, as a
#: CAD exporter writes a zero) is a printing of it
NOISE = 4 * math.ulp(2 * math.pi)
#: a decimal text needs at least this many decimal places to be recognised
MIN_PLACES = 4
#: the longest text looked at (characters): |x - k pi/N| then needs at most about 400 digits
_LONGEST = 400
#: recognise only angles up to this size (in radians); a larger decimal is kept as written
_LARGEST = 10**4
#: a float within this many units in the last place of k pi/N is a printing of it: a program
#: that computes ``k * math.pi / N`` is typically an ulp or two from the double nearest k pi/N
_ULPS = 4
_DECIMAL = re.compile(r"([+-]?)([0-9]*)(?:\.([0-9]*))?(?:[eE]([+-]?[0-9]+))?", re.ASCII)


#: units of the budget (screwsym.algebra.budget, about a microsecond each) charged per term
#: of an expanded entry in constant_trig_normal (its conversion and reduction, measured)
_UNITS_PER_TERM = 100
#: an angle up to this many times another is written through it (constant_trig_normal)
_MULTIPLE = 4

_PI_OVER = re.compile(r"pi/([1-9][0-9]{0,3})", re.ASCII)


def angle_step(angles: Any) -> int | None:
    """``N`` of the policy ``angles="pi/N"``, or None for ``"exact"``; else a clear error.

    >>> from screwsym.motion.angles import angle_step
    >>> angle_step("pi/12"), angle_step("exact")
    (12, None)
    """
    if not isinstance(angles, str):
        raise TypeError(f"angles: expected 'exact' or 'pi/N' (a str), got {type(angles).__name__}")
    if angles == "exact":
        return None
    m = _PI_OVER.fullmatch(angles.replace(" ", ""))
    if m is None:
        raise ValueError(f"angles: expected 'exact' or 'pi/N' with N a positive integer, "
                         f"e.g. 'pi/12', got {angles!r}")
    return int(m.group(1))


def warn_recognised(recognised: Sequence[RecognisedAngle], n: int, stacklevel: int = 3) -> None:
    """One :class:`RecognisedAngleWarning` listing ``recognised`` (nothing if it is empty)."""
    if not recognised:
        return
    listed = "; ".join(f"{r.element}: {r.text} -> {r.value}" for r in recognised)
    warnings.warn(
        f"read {len(recognised)} value(s) as the multiple of pi/{n} (or its sine or cosine) "
        f"they print: {listed} (angles='exact' keeps them as written; the chain's `recognised` "
        "lists them)", RecognisedAngleWarning, stacklevel=stacklevel + 1)


class RecognisedAngleWarning(UserWarning):
    """A decimal angle was read as the multiple of pi/N it is a printing of.

    Silence it with ``warnings.filterwarnings("ignore", category=RecognisedAngleWarning)``;
    ``angles="exact"`` keeps the decimals as written instead.
    """


class RecognisedAngle(NamedTuple):
    """One recognised value: ``text`` as written, ``element`` where it stood, ``value`` used."""

    text: str
    element: str
    value: Expr


def _places_and_digits(text: str) -> tuple[int, int] | None:
    """(decimal places, significant digits) of a decimal text, or None if it is not one."""
    m = _DECIMAL.fullmatch(text.strip())
    if m is None or not (m.group(2) or m.group(3)):
        return None
    whole, frac, exp = m.group(2), m.group(3) or "", m.group(4)
    places = len(frac) - (int(exp) if exp else 0)
    significant = len((whole + frac).lstrip("0"))
    return places, significant


def _log10_size(text: str) -> int | None:
    """About log10 |x| of a decimal text (within one), or None for zero; without computing x."""
    m = _DECIMAL.fullmatch(text.strip())
    assert m is not None
    digits = (m.group(2) or "") + (m.group(3) or "")
    stripped = digits.lstrip("0")
    if not stripped:
        return None
    exponent = int(m.group(4)) if m.group(4) else 0
    return len(m.group(2) or "") - (len(digits) - len(stripped)) + exponent


def _nearest(x: Rational, n: int) -> int:
    """The integer k with k pi/n nearest x (x of size at most _LARGEST)."""
    with mpmath.workdps(40):
        return int(mpmath.nint(mpmath.mpf(x.p) / x.q * n / mpmath.pi))


def _gap(x: Rational, k: int, n: int, places: int) -> mpmath.mpf:
    """|x - k pi/n|, to enough digits to compare with 10**-places (pi is irrational: never 0)."""
    with mpmath.workdps(places + 30):
        return abs(mpmath.mpf(x.p) / x.q - k * mpmath.pi / n)


def _ulp(x: Any, single: bool) -> float:
    """The spacing of doubles (or singles) at ``x``."""
    return float(np.spacing(np.float32(abs(float(x))))) if single else math.ulp(float(x))


def recognise_decimal(text: str, n: int = 12) -> Expr | None:
    r"""The multiple ``k pi/n`` that the decimal ``text`` is a printing of, or None.

    See the module docstring for the rule (at least four decimal places, and
    the decimal is ``k pi/n`` rounded to its places, or the double or single
    nearest it, or within ``NOISE``).  An exact zero is not "recognised": it is
    exact already (None); ``-5.19179e-17`` is 0.

    >>> from screwsym.motion.angles import recognise_decimal
    >>> recognise_decimal("1.5708"), recognise_decimal("-1.5707963"), recognise_decimal("1.5707963267948966")
    (pi/2, -pi/2, pi/2)
    >>> recognise_decimal("0.7854"), recognise_decimal("3.1416"), recognise_decimal("1.5707964")
    (pi/4, pi, pi/2)
    >>> print(recognise_decimal("1.57"), recognise_decimal("1.5709"), recognise_decimal("0.5"))
    None None None
    >>> recognise_decimal("-5.19179e-17"), recognise_decimal("2.55351e-15"), recognise_decimal("1e-13")
    (0, 0, None)
    """
    if len(text) > _LONGEST:
        return None
    shape = _places_and_digits(text)
    if shape is None:
        return None
    places, significant = shape
    if places < MIN_PLACES:
        return None
    size = _log10_size(text)
    if size is None or size > 5:
        return None  # zero, or more than _LARGEST: not an angle to recognise
    if size < -20:
        return S.Zero  # far below NOISE: not built as a Rational (1e-99999999 would be huge)
    x = Rational(text.strip())
    if x == 0 or abs(x) > _LARGEST:
        return None
    k = _nearest(x, n)
    gap = _gap(x, k, n, min(places, _LONGEST))
    if gap <= NOISE:
        return k * pi / n  # float noise of a computation on angles up to a turn (k = 0 too)
    if k == 0:
        return None
    if gap * 2 * mpmath.mpf(10) ** places < 1:
        return k * pi / n
    for digits, single in ((15, False), (7, True)):
        if significant >= digits and gap <= _ULPS * _ulp(x, single):
            return k * pi / n
    return None


def recognise_float(value: float, n: int = 12) -> Expr | None:
    r"""The multiple ``k pi/n`` within 4 ulps (double or single) of the float ``value``, or None.

    >>> import numpy as np
    >>> from screwsym.motion.angles import recognise_float
    >>> recognise_float(np.pi / 2), recognise_float(float(np.float32(np.pi / 4))), recognise_float(-np.pi)
    (pi/2, pi/4, -pi)
    >>> print(recognise_float(1.5708), recognise_float(0.0))
    None None
    """
    x = float(value)
    if x == 0 or not abs(x) <= _LARGEST:
        return None
    k = _nearest(Rational(x), n)
    gap = _gap(Rational(x), k, n, 20)
    if gap <= NOISE:
        return k * pi / n
    # the single-precision window only for a float that is a single (numpy.float32, or its value)
    single = float(np.float32(x)) == x
    if gap <= _ULPS * _ulp(x, False) or (single and gap <= _ULPS * _ulp(x, True)):
        return k * pi / n
    return None


#: a rotation entry within this of a sine or cosine is a printing of it: 4 units in the last
#: place of a single-precision float at 1 (2**-21, about 4.8e-7)
TRIG_TOL = 2.0**-21


@lru_cache(maxsize=16)
def _trig_values(n: int) -> tuple[tuple[float, Expr], ...]:
    """Every sine and cosine of a multiple of pi/n, as (float, exact value), sorted."""
    values = {v for k in range(2 * n) for v in (cos(k * pi / n), sin(k * pi / n))}
    return tuple(sorted((float(v), v) for v in values))


def recognise_trig_float(value: float, n: int = 12) -> Expr | None:
    r"""The sine or cosine of a multiple of ``pi/n`` within ``TRIG_TOL`` of the float ``value``.

    For the entries of a rotation matrix written as floats (doubles or
    singles): ``TRIG_TOL`` is four units in the last place of a single at 1
    (``2**-21``), so that ``numpy.float32`` matrices and doubles computed
    with a rounding or two are recognised; None if no value is that close.

    >>> from screwsym.motion.angles import recognise_trig_float
    >>> recognise_trig_float(0.7071067811865476), recognise_trig_float(-0.8660254)
    (sqrt(2)/2, -sqrt(3)/2)
    >>> recognise_trig_float(0.5000000000000001), recognise_trig_float(6.1e-17)
    (1/2, 0)
    >>> recognise_trig_float(0.7071) is None
    True
    """
    x = float(value)
    best = min(_trig_values(n), key=lambda fv: abs(fv[0] - x))
    return best[1] if abs(best[0] - x) <= TRIG_TOL else None


def constant_trig_normal(entries: Sequence[Expr]) -> list[Expr] | None:
    r"""Numbers built from sines and cosines of constant angles, in one expanded normal form.

    A robot file whose angles are no multiple of pi/12 (``-1.8``, ``0.0486795``: the
    SO-100 arm) holds ``cos(9/5)``, ``sin(9/5)``, ... in its frames: transcendental
    numbers, which SymPy keeps as products nested one level per frame.  Here each pair
    ``cos(a), sin(a)`` of a constant angle ``a`` is a pair of ring generators ``c, s``
    on the circle ``c**2 + s**2 = 1`` (as the joint angles are in the product of
    exponentials), square roots of primes are generators with ``r**2 = p``, and the
    entries are expanded and reduced modulo those relations (every ``s**k``, ``k >= 2``,
    made ``s**(k mod 2) (1 - c**2)**(k // 2)``; the relations' leading terms are
    coprime, a Groebner basis): a polynomial of bounded degree in each pair, flat, so that
    the next product does not nest it again.  Every step is an identity, so each entry
    is the number it was given.  An angle that is 2, 3 or 4 times another (as written)
    is given by the multiple-angle formulas; other distinct angles are taken as
    independent: the form is then not unique, but always exact.

    Returns None when there is no sine or cosine of a constant angle, or when an entry
    is not such a polynomial (a quotient by one, a float, pi, ...): the caller keeps its
    own arithmetic.

    >>> from sympy import Rational, cos, sin
    >>> from screwsym.motion.angles import constant_trig_normal
    >>> a = Rational(9, 5)
    >>> constant_trig_normal([(cos(a)*cos(a) - sin(a)*sin(a))*cos(a) + 2*sin(a)**2*cos(a)])
    [cos(9/5)]
    >>> constant_trig_normal([Rational(1, 2)]) is None
    True
    """
    atoms = set()
    for e in entries:
        atoms |= {a for a in e.atoms(sin, cos) if not a.free_symbols}
    if not atoms or any(e.has(Float) for e in entries):  # a float is not made a rational
        return None
    angles = sorted({a.args[0] for a in atoms}, key=default_sort_key)
    gens: list[Expr] = []
    forward: dict[Expr, Expr] = {}
    bases: list[Expr] = []
    for b in angles:
        # an angle that is a small multiple of another (3.14158 = 2 x 1.57079 in so100.urdf):
        # its sine and cosine by the multiple-angle formulas, no pair of its own
        a = next((a for a in bases if (b / a).is_Integer and 2 <= abs(b / a) <= _MULTIPLE), None)
        if a is not None:
            x = Dummy("x")
            i = bases.index(a)
            on = {cos(x): gens[2 * i], sin(x): gens[2 * i + 1]}
            k = b / a
            forward[cos(b)] = expand_trig(cos(k * x)).xreplace(on)
            forward[sin(b)] = expand_trig(sin(k * x)).xreplace(on)
            continue
        c_, s_ = Dummy("c"), Dummy("s")
        forward[cos(b)], forward[sin(b)] = c_, s_
        gens += [c_, s_]
        bases.append(b)
    pairs = [(2 * i, 2 * i + 1) for i in range(len(bases))]
    replaced = [e.xreplace(forward) for e in entries]
    # square roots of rationals (15-degree angles in the same file): a generator per prime
    roots: dict[int, Expr] = {}
    surd_of: dict[Expr, Expr] = {}
    for e in replaced:
        for p in e.atoms(Pow):
            if p.exp == S.Half and p.base.is_Rational and p.base > 0 and p not in surd_of:
                split = surd_split(p.base)
                if split is None:
                    return None
                k, primes = split
                surd_of[p] = k * math.prod((roots.setdefault(q, Dummy("r")) for q in primes), start=S.One)
    replaced = [e.xreplace(surd_of) for e in replaced]
    order = list(roots)
    gens += [roots[q] for q in order]
    surds = [(len(gens) - len(order) + i, q) for i, q in enumerate(order)]
    R, *_ = ring(gens, QQ)
    back = {d: f for f, d in forward.items()}
    back.update({roots[q]: sqrt(q) for q in order})
    out = []
    for e in replaced:
        if e.atoms(sin, cos) or any(not x.is_Dummy for x in e.free_symbols):
            return None
        try:
            P = R.from_expr(e) if e.free_symbols else R(QQ.from_sympy(e))
        except (CoercionFailed, GeneratorsError, PolynomialError, ValueError):
            return None
        charge(_UNITS_PER_TERM * len(P.terms()))  # the bound of the call under way (from_urdf)
        if surds:
            P = reduce_surds(P, surds)
        P = reduce_powers(P, pairs)
        out.append(P.as_expr(*gens).xreplace(back))
    return out
