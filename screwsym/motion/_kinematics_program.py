r"""Forward kinematics and the space Jacobian as straight-line programs (cost linear in the joints).

Explanation
===========

The closed forms of :meth:`Chain.forward` and :meth:`Chain.jacobian` grow with the joints
faster than linearly whatever the form: an entry of ``R_1(q_1) ... R_n(q_n)`` for spatial
axes is a sum over the products of one of ``cos q_k, sin q_k`` (or 1) per joint, up to
``2^(n-1)`` and more terms expanded (about 1.7x to 3x per added joint in ``count_ops`` in
``benchmarks/bench_scaling.py --growth``; more at 15-degree geometry, where each coefficient
is a sum over ``Q(sqrt 2, sqrt 3)``), and a nested or gathered form only shortens this by a
factor.  The same product as a *program* -- one assignment per entry of each partial
product, ``T_k = T_(k-1) exp6($_k, q_k)``, with the exponential's entries in the symbols
``c_k = cos q_k, s_k = sin q_k`` -- costs a constant number of operations per joint.

The same assignments substituted into each other are the *product form* of
``Chain.forward(q, form="product")`` and ``Chain.jacobian(q, form="product")``
(:func:`product_forward`): the untidied nested product, built in a time linear in the joints
(the expressions share their subexpressions), no larger than plain SymPy's product of the
exponentials in ``count_ops`` (the same on a spatial chain with rational geometry, about half at
15-degree geometry, whose constants are tidied once per joint) and without the sums of angles of
the default tidied form.

Exactness: every assignment is the SymPy expression of one entry of the partial product
(SymPy's arithmetic drops products by a literal 0 or 1); substituting the assignments back
(:meth:`Program.expressions`) gives the untidied product of exponentials.  The tests compare
it with :meth:`Chain.forward` and :meth:`Chain.jacobian` symbolically and with modern_robotics
numerically.

References
==========

Lynch & Park, *Modern Robotics*, 2017, Sections 4.1 and 5.1 (the product of exponentials and
the space Jacobian ``J_i = Ad(T_(i-1)) $_i``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, cast

from sympy import Add, Expr, ImmutableMatrix, S, Symbol, cos, sin, sympify

from ..algebra.budget import charge
from ..core.checks import check_choice
from ..core.tidy import tidy
from ._poe import STEP_UNITS
from .displacement import exp6
from .newton_euler import Program, _Writer  # the dynamics programs' writer, shared

if TYPE_CHECKING:
    from .chain import Chain

__all__ = ["kinematics_program"]

WHAT = ("forward", "jacobian")

#: the forms of ``Chain.forward`` and ``Chain.jacobian``: tidied (the default), the nested product
FORMS = ("tidy", "product")


def _exponential(W: _Writer, twist: Any, qk: Symbol, k: int) -> tuple[list, list]:
    """``exp6($_k, q_k)`` as ``(R, p)`` entries in ``c_k, s_k`` (assigned) and constants.

    A prismatic joint: ``(I, v q)``.  A unit ``omega`` (revolute or helical, pitch ``h = omega . v``):
    Rodrigues' ``R = I + s K + (1 - c) K^2`` with ``K^2 = omega omega^T - I``, and
    ``p = (I - R)(omega x v) + h omega q = -(s K r + (1 - c) K^2 r) + h omega q`` for ``r = omega x v``
    (Lynch & Park 2017, Proposition 3.25); the constants tidied once (numbers in their normal
    form).  Any other twist: :func:`exp6` with ``cos q_k, sin q_k`` assigned."""
    w, v = list(twist.omega), list(twist.v_O)
    if all(x == 0 for x in w):
        return [[int(i == j) for j in range(3)] for i in range(3)], [x * qk for x in v]
    if tidy(w[0] ** 2 + w[1] ** 2 + w[2] ** 2) != 1:
        E = exp6(twist, qk)
        trig = {f(qk): W.let(f(qk), f"{name}{k}") for f, name in ((cos, "c"), (sin, "s")) if E.matrix.has(f(qk))}
        return ([[E.R[i, j].xreplace(trig) for j in range(3)] for i in range(3)],
                [E.p[i].xreplace(trig) for i in range(3)])
    c, s = W.let(cos(qk), f"c{k}"), W.let(sin(qk), f"s{k}")
    K = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
    K2 = [[tidy(w[i] * w[j]) - int(i == j) for j in range(3)] for i in range(3)]
    r = [tidy(w[1] * v[2] - w[2] * v[1]), tidy(w[2] * v[0] - w[0] * v[2]), tidy(w[0] * v[1] - w[1] * v[0])]
    Kr = [tidy(sum(K[i][j] * r[j] for j in range(3))) for i in range(3)]
    K2r = [tidy(sum(K2[i][j] * r[j] for j in range(3))) for i in range(3)]
    h = tidy(w[0] * v[0] + w[1] * v[1] + w[2] * v[2])
    R = [[int(i == j) + s * K[i][j] + (1 - c) * K2[i][j] for j in range(3)] for i in range(3)]
    p = [-(s * Kr[i] + (1 - c) * K2r[i]) + h * w[i] * qk for i in range(3)]
    return R, p


def kinematics_program(chain: Chain, what: str = "forward") -> Program:
    r"""``T(q)`` (``what="forward"``, the 4x4 matrix) or the space Jacobian (``"jacobian"``, 6 x n)
    as a straight-line :class:`~screwsym.motion.newton_euler.Program` in ``q1 .. qn``.

    One assignment per entry of each partial product ``T_k = T_(k-1) exp6($_k, q_k)`` that
    is not a number or a symbol: the program's size grows linearly with the joints where the
    closed forms grow geometrically (module docstring).  Any chain (helical joints too:
    ``exp6`` is the general exponential).

    >>> from screwsym import Chain, Transform, Twist
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])], Transform.translation([2, 0, 0]))
    >>> p = arm.kinematics_program()
    >>> print(p)
    c1 = cos(q1)
    s1 = sin(q1)
    c2 = cos(q2)
    s2 = sin(q2)
    p2x = c1*(1 - c2) + s1*s2
    p2y = -c1*s2 + s1*(1 - c2)
    r2xx = c1*c2 - s1*s2
    r2xy = -c1*s2 - c2*s1
    px = p2x + 2*r2xx
    py = p2y - 2*r2xy
    T = [r2xx, r2xy, 0, px, -r2xy, r2xx, 0, py, 0, 0, 1, 0, 0, 0, 0, 1]
    >>> p.operations()
    Operations(multiplications=10, additions=8, functions=4)
    >>> (p.expressions() - arm.forward(p.arguments[0]).matrix).applyfunc(lambda e: e.expand(trig=True)).is_zero_matrix
    True
    """
    what = check_choice(what, "what", WHAT)
    n = chain.n_joints
    q = ImmutableMatrix([Symbol(f"q{i + 1}", real=True) for i in range(n)])
    W = _Writer({str(x) for x in q} | {str(s) for t in chain.twists for s in t.matrix.free_symbols}
                | {str(s) for s in chain.home.matrix.free_symbols})
    axes = "xyz"
    R: list[list[Any]] = [[int(i == j) for j in range(3)] for i in range(3)]
    p: list[Any] = [0, 0, 0]
    columns: list[list[Any]] = []
    for k, (twist, qk) in enumerate(zip(chain.twists, q, strict=True), start=1):
        if what == "jacobian":  # J_k = Ad(T_(k-1)) $_k = (R w; R v + p x R w)
            w = [sum(R[i][j] * twist.omega[j] for j in range(3)) for i in range(3)]
            Rv = [sum(R[i][j] * twist.v_O[j] for j in range(3)) for i in range(3)]
            v = [Rv[0] + p[1] * w[2] - p[2] * w[1], Rv[1] + p[2] * w[0] - p[0] * w[2],
                 Rv[2] + p[0] * w[1] - p[1] * w[0]]
            columns.append([W.let(x, f"j{k}{name}") for x, name in
                            zip(w + v, ("wx", "wy", "wz", "vx", "vy", "vz"), strict=True)])
        ER, Ep = _exponential(W, twist, qk, k)
        p = [W.let(p[i] + sum(R[i][j] * Ep[j] for j in range(3)), f"p{k}{axes[i]}") for i in range(3)]
        R = [[W.let(sum(R[i][m] * ER[m][j] for m in range(3)), f"r{k}{axes[i]}{axes[j]}") for j in range(3)]
             for i in range(3)]
    if what == "jacobian":
        out = ImmutableMatrix([[columns[c][r] for c in range(n)] for r in range(6)]) if n else ImmutableMatrix.zeros(6, 0)
        return Program((q,), tuple(W.assigns), out, "J")
    HR, Hp = chain.home.R, chain.home.p
    TR = [[sum(R[i][m] * HR[m, j] for m in range(3)) for j in range(3)] for i in range(3)]
    Tp = [W.let(p[i] + sum(R[i][m] * Hp[m] for m in range(3)), f"p{axes[i]}") for i in range(3)]
    rows = [[*TR[i], Tp[i]] for i in range(3)] + [[0, 0, 0, 1]]
    return Program((q,), tuple(W.assigns), ImmutableMatrix(rows), "T")


# ---------------------------------------------------------------- the product form (opt-in)
class _PassThrough:
    """A writer for :func:`_exponential` that assigns nothing: the expressions themselves."""

    @staticmethod
    def let(expr: Any, name: str) -> Any:
        return sympify(expr, strict=True)


def _dot(pairs: Any) -> Expr:
    """``sum a b`` over the pairs, products by a literal 0 skipped and by 1 not formed, one ``Add``."""
    terms = []
    for a, b in pairs:
        if a is S.Zero or b is S.Zero:
            continue
        terms.append(a if b is S.One else b if a is S.One else a * b)
    return Add(*terms) if terms else S.Zero


class _Products:
    """The partial products ``T_k = T_(k-1) exp6($_k, q_k)`` of one chain at one ``q`` as SymPy
    expressions, untidied (extended as far as asked, shared by ``forward`` and ``jacobian``)."""

    def __init__(self, twists: tuple, q: tuple) -> None:
        self.twists, self.q = twists, q
        one, zero = S.One, S.Zero
        self.prefixes: list[tuple[list, list]] = [
            ([[one, zero, zero], [zero, one, zero], [zero, zero, one]], [zero, zero, zero])]

    def upto(self, k: int) -> list[tuple[list, list]]:
        while len(self.prefixes) <= k:
            i = len(self.prefixes) - 1
            charge(STEP_UNITS)
            R, p = self.prefixes[-1]
            ER, Ep = _exponential(cast(Any, _PassThrough), self.twists[i], self.q[i], i + 1)
            ER = [[sympify(x, strict=True) for x in row] for row in ER]
            Ep = [sympify(x, strict=True) for x in Ep]
            p = [_dot([(S.One, p[r]), *((R[r][m], Ep[m]) for m in range(3))]) for r in range(3)]
            R = [[_dot((R[r][m], ER[m][c]) for m in range(3)) for c in range(3)] for r in range(3)]
            self.prefixes.append((R, p))
        return self.prefixes

    def column(self, k: int, twist: Any) -> list[Expr]:
        """``Ad(T_(k)) $`` as ``(R w; R v + p x R w)``."""
        R, p = self.upto(k)[k]
        w = [_dot((R[r][m], twist.omega[m]) for m in range(3)) for r in range(3)]
        v = [_dot((R[r][m], twist.v_O[m]) for m in range(3)) for r in range(3)]
        return w + [_dot([(S.One, v[i]), (p[j], w[k])]) - _dot([(p[k], w[j])])
                    for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1))]


#: the partial products of the last few chains and joint values (``forward`` then ``jacobian`` at
#: the same ``q`` share them; the expressions depend only on the key)
_RECENT: dict = {}
_RECENT_SIZE = 4


def _products(twists: Any, q: tuple) -> _Products:
    key = (tuple(twists), q)
    hit = _RECENT.get(key)
    if hit is None:
        hit = _RECENT[key] = _Products(tuple(twists), q)
        while len(_RECENT) > _RECENT_SIZE:
            try:
                del _RECENT[next(iter(_RECENT))]
            except (KeyError, RuntimeError, StopIteration):  # another thread took it first
                break
    return hit


def product_forward(twists: Any, home: Any, q: tuple) -> tuple[ImmutableMatrix, ImmutableMatrix]:
    r"""``(R, p)`` of ``exp6($_1, q_1) ... exp6($_n, q_n) M`` as the nested product, untidied.

    The entries of the straight-line program (:func:`kinematics_program`) substituted into each
    other -- SymPy's own arithmetic, products by a literal 0 skipped and by 1 not formed -- so
    the sums of angles are not gathered (``cos(q1)*cos(q2) - sin(q1)*sin(q2)`` stays so) and a
    rational factor is distributed as SymPy does.  ``Chain.forward(q, form="product")``.

    >>> from sympy import symbols
    >>> from screwsym import Chain, Transform, Twist
    >>> arm = Chain([Twist.rotation([0, 0, 1], point=[0, 0, 0]),
    ...              Twist.rotation([0, 0, 1], point=[1, 0, 0])], Transform.translation([2, 0, 0]))
    >>> q = symbols("q1 q2", real=True)
    >>> T = arm.forward(q, form="product")
    >>> T.R[0, 0], arm.forward(q).R[0, 0]
    (-sin(q1)*sin(q2) + cos(q1)*cos(q2), cos(q1 + q2))
    >>> T.p[0]
    (1 - cos(q2))*cos(q1) - sin(q1)*sin(q2) + 2*cos(q1)*cos(q2)
    >>> arm.jacobian(q, form="product")[3:, 1].T
    Matrix([[sin(q1), -cos(q1), 0]])
    """
    R, p = _products(twists, q).upto(len(twists))[-1]
    HR = [[sympify(home.R[i, j], strict=True) for j in range(3)] for i in range(3)]
    Hp = [sympify(x, strict=True) for x in home.p]
    TR = [[_dot((R[r][m], HR[m][c]) for m in range(3)) for c in range(3)] for r in range(3)]
    Tp = [_dot([(S.One, p[r]), *((R[r][m], Hp[m]) for m in range(3))]) for r in range(3)]
    return ImmutableMatrix(TR), ImmutableMatrix(Tp)


def product_space_jacobian(twists: Any, q: tuple) -> ImmutableMatrix:
    """The space Jacobian as the nested product (columns ``Ad(T_(i-1)) $_i``, untidied)."""
    P = _products(twists, q)
    cols = [P.column(i, t) for i, t in enumerate(twists)]
    return ImmutableMatrix(6, len(cols), lambda r, c: cols[c][r])


def product_body_jacobian(body_twists: Any, q: tuple) -> ImmutableMatrix:
    """The body Jacobian as the nested product: column ``i`` is ``Ad(exp6(B_n, -q_n) ...
    exp6(B_(i+1), -q_(i+1))) B_i`` (the space recursion on the body twists from the tip)."""
    rev = tuple(reversed(body_twists))
    P = _products(rev, tuple(-x for x in reversed(q)))
    cols = [P.column(i, t) for i, t in enumerate(rev)][::-1]
    return ImmutableMatrix(6, len(cols), lambda r, c: cols[c][r])
