r"""Ring elements back to SymPy expressions: the writer of :mod:`screwsym.motion._poe`.

Steps 2 and 3 of that module's docstring: the angle-sum formulas and the Pythagorean identity
gathered on the terms of a polynomial (its monomials packed into integers, so that the partner
of a term is one dictionary look-up), then the terms nested by the joints, the last joint's
factors outermost, or flat where that is smaller (by ``count_ops``).  The products of
generators are built in SymPy's canonical form directly (``_Writer._monomial_expr`` says why
that is exact).
"""

from __future__ import annotations

import sys
from array import array
from bisect import insort
from functools import cmp_to_key
from itertools import combinations
from typing import Any, cast

from sympy import Add, Expr, Mul, Pow, Symbol, cos, count_ops, sin
from sympy.core.basic import Basic
from sympy.polys.domains import QQ

from ..algebra.budget import charge

__all__: list[str] = []

#: forms whose estimated cost is within this of the least are measured with ``count_ops``
MARGIN = 2

#: units of the budget (about a microsecond each, measured) per term written back to an expression
WRITE_UNITS = 60

# packed monomials (the writer's gathering): 16 bits per generator's exponent
_FIELD = 1 << 16
_MASK = _FIELD - 1
_BIG = sys.byteorder == "big"
_MISSING = object()
#: SymPy's order of the arguments of a ``Mul`` or ``Add`` (``sympy.core.mul._mulsort``)
_args_sortkey = cmp_to_key(Basic.compare)


def _canonical(angle: tuple | None) -> tuple[Any, int]:
    """The angle with its first nonzero coefficient positive, and the sign taken out."""
    if angle is None:
        return None, 1
    for c in angle:
        if c:
            return (angle, 1) if c > 0 else (tuple(-x for x in angle), -1)
    return angle, 1


class _Writer:
    """Ring elements back to compact SymPy expressions (the gathering and the nesting)."""

    def __init__(self, engine: Any) -> None:  # a _poe._Engine
        self.engine = engine
        self.q = tuple(engine.q) + tuple(engine.bases)  # the angles' coordinates: joints, then geometry
        self.n = engine.n
        # generator id -> SymPy expression; trig generators also -> (angle, "c" or "s")
        self.expr_of: list[Expr] = []
        self.trig: dict[int, tuple[tuple, str]] = {}
        self.gen_id: dict[tuple[tuple, str], int] = {}
        self.last: list[int] = []  # per generator: the last joint it involves (-1: none)
        self._unpacked: dict = {}
        self._trig_once: dict = {}
        self._pair_lists: dict = {}  # trigonometric factors -> their pairs that can have a partner
        self._pair_info: dict = {}  # (g1, g2) -> what the angle-sum formulas need, or None
        self._mcost: dict = {}  # monomial -> the cost of its factors
        self._gcost: dict = {}  # generator -> its cost
        self._monos: dict = {}  # monomial -> its expression
        self._plain_monos: dict = {}  # monomial -> whether it is built without Mul.flatten
        self._factors: dict = {}  # (generator, exponent) -> its power
        self._ranked: list = []  # the factors met, in Basic.compare's order
        self._ranks: dict = {}
        for sym in engine.symbols:
            self.expr_of.append(engine.thaw.get(sym, sym))
            self.last.append(-1)
        for i, qi in enumerate(engine.q):
            if engine.kinds[i] == "P":
                self.last[engine.symbols.index(qi)] = self._order(i)
        for a, c in engine.cos_gen.items():
            self._register(a, "c", engine.symbols.index(c))
            self._register(a, "s", engine.symbols.index(engine.sin_gen[a]))
        m = len(engine.bases)
        for b, base in enumerate(engine.bases):  # the geometry's sines and cosines: angles too
            unit = tuple(1 if k == self.n + b else 0 for k in range(self.n + m))
            c, s_ = engine.circle[base]
            self._register(unit, "c", engine.symbols.index(c))
            self._register(unit, "s", engine.symbols.index(s_))
        for g, level in engine.level.items():
            self.last[g] = level
        self.cache: dict = {}

    def _order(self, joint: int) -> int:
        """The nesting level of an angle's coordinate: the joint, or -1 for the geometry's."""
        return joint if joint < self.n else -1

    def _register(self, angle: tuple, kind: str, gid: int | None = None) -> int:
        key = (angle, kind)
        if key in self.gen_id:
            return self.gen_id[key]
        arg = Add(*(c * qi for c, qi in zip(angle, self.q, strict=True) if c))
        e = cos(arg) if kind == "c" else sin(arg)
        if gid is None:
            gid = len(self.expr_of)
            self.expr_of.append(e)
            self.last.append(-1)
        else:
            self.expr_of[gid] = e
        self.last[gid] = max(self._order(i) for i, c in enumerate(angle) if c)
        self.trig[gid] = (angle, kind)
        self.gen_id[key] = gid
        if (angle, "s" if kind == "c" else "c") in self.gen_id:
            # a pair with the other function of this angle lacked its partner until now (the pairs
            # of a new generator are new entries; no others involve the angle)
            self._pair_lists.clear()
            self._pair_info.clear()
        return gid

    # --- the polynomial as a dict {monomial: coefficient}, a monomial a sorted tuple of (gen, exp)
    def to_dict(self, P: Any) -> dict:
        out = {}
        for monom, coeff in P.terms():
            out[tuple((g, k) for g, k in enumerate(monom) if k)] = coeff
        return out

    def expr(self, P: Any) -> Expr:
        terms = P.terms()
        charge(WRITE_UNITS * len(terms))  # the budget of the call under way (_poe.bounded)
        if any(sum(monom) >= _FIELD for monom, _ in terms):  # exponents beyond a packed field
            return self.write(self.to_dict(P))
        D = {_pack(monom): coeff for monom, coeff in terms}
        D = self.gather(D)
        return self.write({self._unpack(m): c for m, c in D.items()})

    # --- step 2: the angle-sum formulas and the Pythagorean identity, on packed monomials
    #
    # A monomial is packed into one integer, 16 bits per generator (generator g's exponent in
    # bits 16 g .. 16 g + 15), so that multiplying or dividing monomials is adding or
    # subtracting integers and the partner term of an angle-sum formula is one dictionary
    # look-up.  No field overflows: ``expr`` packs only polynomials of total degree below
    # 2**16, and the gathering never raises the total degree (two factors become one, or
    # ``s**2`` becomes ``c**2``).
    def _unpack(self, m: int) -> tuple:
        """The sorted ``((generator, exponent), ...)`` of a packed monomial."""
        hit = self._unpacked.get(m)
        if hit is None:
            fields = array("H")
            fields.frombytes(m.to_bytes(2 * len(self.expr_of), "little"))
            if _BIG:
                fields.byteswap()
            hit = self._unpacked[m] = tuple((g, k) for g, k in enumerate(fields) if k)
        return hit

    def _trig1(self, m: int) -> tuple:
        """The trigonometric generators of exponent 1 in a packed monomial, ascending."""
        hit = self._trig_once.get(m)
        if hit is None:
            trig = self.trig
            hit = self._trig_once[m] = tuple(g for g, k in self._unpack(m) if k == 1 and g in trig)
        return hit

    def gather(self, D: dict) -> dict:
        """The angle-sum formulas applied until none applies, then the Pythagorean identity.

        ``D`` maps packed monomials to coefficients.  A pass looks only at the terms that are
        new or whose coefficient changed in the pass before (the formulas pair two terms, and
        each pair is found from either of them), so a long polynomial is not scanned again for
        each gathering."""
        changed = True
        todo = list(D)
        lists = self._pair_lists
        while changed:
            changed = False
            before = dict(D)
            for m in todo:
                alpha = D.get(m)
                if alpha is None:
                    continue
                trig = self._trig1(m)
                candidates = lists.get(trig)
                if candidates is None:  # the pairs of these factors that can have a partner, in order
                    candidates = lists[trig] = [info for info in map(self._pair, combinations(trig, 2)) if info]
                for info in candidates:
                    partner = m + info[0]
                    beta = D.get(partner)
                    if beta is None or (beta != alpha and beta != -alpha):
                        continue
                    self._apply(D, m, partner, alpha, beta, info)
                    changed = True
                    break
            todo = [m for m, c in D.items() if before.get(m) is not c and before.get(m) != c]
            if not changed:
                changed = self._pythagoras(D)
                todo = list(D)
        return D

    def _pair(self, pair: tuple[int, int]) -> tuple | None:
        """What the angle-sum formulas need of a term with the factors ``x_g1 x_g2`` (``g1 < g2``):
        ``(partner - m, rest - m, same kind, A, B, kind of g1, g1, g2)``, or None when no partner can occur
        (remembered until a partner's generator is registered)."""
        hit = self._pair_info.get(pair, _MISSING)
        if hit is _MISSING:
            hit = self._pair_info[pair] = self._pair_uncached(*pair)
        return cast(Any, hit)

    def _pair_uncached(self, g1: int, g2: int) -> tuple | None:
        (A, k1), (B, k2) = self.trig[g1], self.trig[g2]
        if A == B:
            return None
        if k1 == k2:
            other = "s" if k1 == "c" else "c"
            h1, h2 = self.gen_id.get((A, other)), self.gen_id.get((B, other))
        else:
            h1, h2 = (self.gen_id.get((A, "c")), self.gen_id.get((B, "s"))) if k1 == "s" else \
                (self.gen_id.get((A, "s")), self.gen_id.get((B, "c")))
        if h1 is None or h2 is None:  # the partner term cannot occur (until it is registered)
            return None
        rest = -(1 << 16 * g1) - (1 << 16 * g2)
        return rest + (1 << 16 * h1) + (1 << 16 * h2), rest, k1 == k2, A, B, k1, g1, g2

    def _apply(self, D: dict, m: int, partner: int, alpha: Any, beta: Any, info: tuple) -> None:
        """Replace the terms ``m`` and ``partner`` by their angle-sum form."""
        _, rest, same, A, B, k1, g1, g2 = info
        if same:  # cos A cos B with sin A sin B (or the other way round)
            cc, ss = (alpha, beta) if k1 == "c" else (beta, alpha)
            # cc cA cB + ss sA sB: cos(A - B) when ss == cc, cos(A + B) when ss == -cc
            angle, kind, coeff = _add(A, B, -1 if ss == cc else 1), "c", cc
        else:  # sin A cos B with cos A sin B
            if k1 == "c":
                A, B = B, A
            # alpha sA cB + beta cA sB: sin(A + B) when beta == alpha, sin(A - B) when -alpha
            angle, kind, coeff = _add(A, B, 1 if beta == alpha else -1), "s", alpha
        del D[m], D[partner]
        rest += m
        canon, sgn = _canonical(angle)
        if not any(canon):  # cos(0) = 1, sin(0) = 0
            if kind == "c":
                _add_term(D, rest, coeff)
            return
        if kind == "s":
            coeff = coeff * sgn
        g = self._register(canon, kind)
        new = rest + (1 << 16 * g)
        if new not in self._trig_once:  # its factors of exponent 1 from m's, without unpacking
            once = [x for x in self._trig1(m) if x != g1 and x != g2]
            k = (rest >> 16 * g) & _MASK
            if k == 0:
                once.append(g)
                once.sort()
            elif k == 1:
                once.remove(g)
            self._trig_once[new] = tuple(once)
        _add_term(D, new, coeff)

    def _pythagoras(self, D: dict) -> bool:
        """``sin(A)**2 -> 1 - cos(A)**2`` (or the reverse) for an angle where that gives fewer terms."""
        squares = {g for m in D for g, k in self._unpack(m) if k >= 2 and g in self.trig}
        for g in sorted(squares):
            angle, kind = self.trig[g]
            h = self._register(angle, "s" if kind == "c" else "c")
            if not any((m >> 16 * h) & _MASK >= 2 for m in D):
                continue
            new = _substitute_square(D, g, h)
            if len(new) < len(D):
                D.clear()
                D.update(new)
                return True
        return False

    # --- step 3: nested by the joints, last joint outermost, or flat where smaller
    def write(self, D: dict) -> Expr:
        """``D`` as an expression: the plans of the estimate, the best measured by ``count_ops``."""
        self._plan_uncached(D)
        low = min(cost for cost, _ in self.options)
        # the estimate can be off by a sign or two: measure the close ones
        close = [plan for cost, plan in self.options if cost <= low + MARGIN]
        forms = [self._build(plan) for plan in close]
        if len(forms) == 1:
            return forms[0]
        costs = [count_ops(x) for x in forms]
        return forms[costs.index(min(costs))]

    def _plan(self, D: dict) -> tuple[int, Any]:
        """The cheapest way to write ``D`` (its cost in ``count_ops``' units, and the plan)."""
        key = tuple(sorted(D.items()))
        hit = self.cache.get(key)
        if hit is not None:
            return hit
        out = self._plan_uncached(D)
        self.cache[key] = out
        return out

    def _plan_uncached(self, D: dict) -> tuple[int, Any]:
        flat: tuple[int, Any] = (self._sum_cost(D), ("flat", D))
        self.options: list[tuple[int, Any]] = [flat]
        if not D:
            return flat
        if len(D) == 1:
            return flat
        best = flat
        options: list[tuple[int, Any]] = [flat]
        content, common, rest = _pull(D)
        outer = self._coeff_cost(content) + self._monomial_cost(common)
        n_outer = (content != 1) + len(common)
        if n_outer:
            pulled = outer + n_outer + self._sum_cost(rest)
            option: tuple[int, Any] = (pulled, ("pulled", content, common, ("flat", rest)))
            options.append(option)
            if pulled < best[0]:
                best = option
        # split by the last joint met in the terms
        last = max((self.last[g] for m in rest for g, _ in m), default=-1)
        if last >= 0:
            parts: dict = {}
            for m, c in rest.items():
                inner = tuple((g, k) for g, k in m if self.last[g] == last)
                others = tuple((g, k) for g, k in m if self.last[g] != last)
                parts.setdefault(inner, {})[others] = c
            if len(parts) > 1 or () not in parts:
                cost = len(parts) - 1
                plans = []
                for k, v in parts.items():
                    sub_cost, sub = self._plan(v)
                    sub = cast(Any, sub)
                    if sub[0] == "flat" and len(sub[1]) > 1 and all(c < 0 for c in sub[1].values()):
                        # -(a + b) k: the sign joins the outer sum as a subtraction
                        sub = ("pulled", -QQ.one, (), ("flat", {m: -c for m, c in sub[1].items()}))
                    negative = sub[0] == "pulled" and sub[1] < 0 or sub[0] == "flat" and len(sub[1]) == 1 \
                        and next(iter(sub[1].values())) < 0
                    cost += sub_cost + self._monomial_cost(k) + (1 if k and not _is_unit(sub) else 0) \
                        - (1 if negative and len(parts) > 1 else 0)
                    plans.append((k, sub))
                cost += outer + n_outer
                option = (cost, ("pulled", content, common, ("split", plans)))
                options.append(option)
                if cost < best[0]:
                    best = option
        self.options = options
        return best

    def _build(self, plan: tuple) -> Expr:
        kind = plan[0]
        if kind == "flat":
            return Add(*(self._term(m, c) for m, c in plan[1].items()))
        if kind == "pulled":
            _, content, common, inner = plan
            return Mul(QQ.to_sympy(content), self._monomial_expr(common), self._build(inner))
        return Add(*(self._product(k, sub) for k, sub in plan[1]))

    def _product(self, k: tuple, sub: tuple) -> Expr:
        """``k * sub`` as one product (``-(a + b)*k`` stays so, where ``-1*(a + b)`` would distribute)."""
        if sub[0] == "pulled":
            _, content, common, inner = sub
            return Mul(QQ.to_sympy(content), self._monomial_expr(common), self._monomial_expr(k),
                       self._build(inner))
        return self._monomial_expr(k) * self._build(sub)

    def _gen_cost(self, g: int) -> int:
        """``count_ops`` of a generator: 0 for a symbol, of ``cos(sum k_i x_i)`` for an angle (remembered)."""
        hit = self._gcost.get(g)
        if hit is None:
            if g not in self.trig:
                hit = 0
            else:
                terms = [c for c in self.trig[g][0] if c]
                hit = 1 + (len(terms) - 1) + sum(1 for c in terms if abs(c) != 1)
            self._gcost[g] = hit
        return hit

    def _factors_cost(self, m: tuple) -> int:
        """The cost of the factors of a monomial, ``sum (gen cost + (k > 1))`` (remembered)."""
        hit = self._mcost.get(m)
        if hit is None:
            gen_cost = self._gen_cost
            hit = self._mcost[m] = sum(gen_cost(g) + (k > 1) for g, k in m)
        return hit

    def _monomial_cost(self, m: tuple) -> int:
        if not m:
            return 0
        return len(m) - 1 + self._factors_cost(m)

    @staticmethod
    def _coeff_cost(c: Any) -> int:
        cost = 0
        if c.denominator != 1:
            cost += 1
        if abs(c.numerator) != 1:
            cost += 1
        if c < 0:
            cost += 1
        return cost

    def _sum_cost(self, D: dict) -> int:
        cost = max(len(D) - 1, 0)
        factors_cost = self._factors_cost
        for m, c in D.items():
            num = c.numerator
            factors = len(m) + (num != 1 and num != -1)
            cost += max(factors - 1, 0) + (c.denominator != 1) + factors_cost(m)
        if len(D) == 1 and next(iter(D.values())) < 0:
            cost += 1
        return cost

    def _monomial_expr(self, m: tuple) -> Expr:
        """The product of the generators' powers (remembered per monomial).

        For a monomial of Symbols and unevaluated ``cos``/``sin`` (distinct generators are
        distinct such expressions) the product is built from its arguments in SymPy's own
        canonical order, without ``Mul.flatten``: flatten would combine no two factors (their
        bases are distinct atoms or functions, the exponents positive integers), find no number
        among them and distribute nothing (no factor is a sum), so its result is exactly these
        factors sorted by ``Basic.compare`` (``sympy.core.mul._mulsort``), which :meth:`_rank`
        gives.  Any other generator (a root, a frozen function) takes ``Mul``."""
        hit = self._monos.get(m)
        if hit is None:
            plain = self._plain_monos[m] = all(self._plain(g) for g, _ in m)
            if plain:
                factors = [self._factor(g, k) for g, k in m]
                for f in factors:
                    if f not in self._ranks:
                        self._rank(f)
                factors.sort(key=self._ranks.__getitem__)  # every factor ranked (the ranks shift)
                hit = Mul._from_args(factors)
            else:
                hit = Mul(*(self.expr_of[g] ** k for g, k in m))
            self._monos[m] = hit
        return hit

    def _plain(self, g: int) -> bool:
        e = self.expr_of[g]
        return isinstance(e, Symbol) and e.is_commutative or type(e) in (cos, sin)

    def _factor(self, g: int, k: int) -> Expr:
        key = (g, k)
        hit = self._factors.get(key)
        if hit is None:
            hit = self._factors[key] = self.expr_of[g] if k == 1 else Pow(self.expr_of[g], k)
        return hit

    def _rank(self, factor: Expr) -> None:
        """Place the factor among the factors met so far in ``Basic.compare``'s order, a total
        order (SymPy sorts the arguments of every ``Mul`` and ``Add`` by it); the places of the
        factors after it move up by one."""
        insort(self._ranked, factor, key=_args_sortkey)
        self._ranks = {f: i for i, f in enumerate(self._ranked)}

    def _term(self, m: tuple, c: Any) -> Expr:
        mono = self._monomial_expr(m)
        if c == 1:
            return mono
        if m and self._plain_monos[m]:  # as in _monomial_expr: the coefficient first
            return Mul._from_args((QQ.to_sympy(c), *(mono.args if mono.is_Mul else (mono,))))
        return QQ.to_sympy(c) * mono


def _is_unit(plan: tuple) -> bool:
    """Whether the plan writes the constant 1 (so that ``k * 1`` costs no product)."""
    return plan[0] == "flat" and len(plan[1]) == 1 and plan[1].get(()) == 1


def _add(A: tuple, B: tuple, sgn: int) -> tuple:
    return tuple(a + sgn * b for a, b in zip(A, B, strict=True))


def _add_term(D: dict, m: Any, c: Any) -> None:
    old = D.get(m)
    if old is None:
        D[m] = c
        return
    total = old + c
    if total:
        D[m] = total
    else:
        del D[m]


def _pack(monom: tuple) -> int:
    """A ring monomial (its exponent tuple, each below ``_FIELD``) packed into one integer."""
    fields = array("H", monom)
    if _BIG:
        fields.byteswap()
    return int.from_bytes(fields.tobytes(), "little")


def _substitute_square(D: dict, g: int, h: int) -> dict:
    """``D`` (packed monomials) with ``x_g**2 -> 1 - x_h**2`` applied until ``x_g``'s exponent is below 2."""
    out: dict = {}
    two_g, two_h = 2 << 16 * g, 2 << 16 * h
    shift = 16 * g
    for m, c in reversed(D.items()):  # the terms last to first, each expanded depth first
        if (m >> shift) & _MASK < 2:
            _add_term(out, m, c)
            continue
        work = [(m, c)]
        while work:
            m, c = work.pop()
            if (m >> shift) & _MASK < 2:
                _add_term(out, m, c)
                continue
            work.append((m - two_g, c))
            work.append((m - two_g + two_h, -c))
    return out


def _pull(D: dict) -> tuple[Any, tuple, dict]:
    """The content (negative when every term is), the common monomial and the rest of ``D``."""
    from math import gcd

    nums = [c.numerator for c in D.values()]
    dens = [c.denominator for c in D.values()]
    g = 0
    for x in nums:
        g = gcd(g, int(x))
    lcm = 1
    for d in dens:
        lcm = lcm * int(d) // gcd(lcm, int(d))
    content = QQ.dtype(g, lcm)  # the rational g / lcm (QQ(g, lcm) takes a slower path)
    if all(c < 0 for c in D.values()):  # -(a + b) rather than (-a - b): one operation fewer
        content = -content
    common = dict(next(iter(D)))  # the least exponent of each generator in every term
    for m in D:
        if not common:
            break
        md = dict(m)
        for gid in list(common):
            k = md.get(gid, 0)
            if k < common[gid]:
                if k:
                    common[gid] = k
                else:
                    del common[gid]
    if not common:
        rest = D if content == 1 else {m: c / content for m, c in D.items()}
        return content, (), rest
    rest = {}
    for m, c in D.items():
        md = dict(m)
        for gid, k in common.items():
            md[gid] -= k
            if not md[gid]:
                del md[gid]
        rest[tuple(sorted(md.items()))] = c / content
    return content, tuple(sorted(common.items())), rest
