"""The compiled loop of :func:`screwsym.numeric.mobility.mobility_map` (``backend="numba"``).

Householder QR with column pivoting of each limb's (unit, halves-swapped)
twists, the orthonormal null vectors past the rank as its constraints, and the
pivoted QR of their union, one configuration per iteration of a parallel loop.
The same algorithm as the NumPy back end (``screwsym.numeric.mobility._qrcp``).
Compiled with ``cache=True``: the first call on a machine compiles (seconds),
later processes load the compiled code.  Imported only when the numba back
end is asked for (``pip install -e ".[fast]"`` from a clone).
"""

from typing import Any

import numpy as np

from ..core.formulas import SWAP

try:
    import numba
except ImportError:  # pragma: no cover - numba is optional; lambdify refuses "numba" first
    numba = None  # type: ignore[assignment]  # the optional module, or None without it

_prange: Any  # numba.prange, or range without numba
if numba is not None:
    _jit = numba.njit(cache=True)
    _parallel_jit = numba.njit(parallel=True, cache=True)
    _prange = numba.prange
else:  # pragma: no cover - plain Python, so that the module imports (doctest collection)

    def _jit(f):
        return f

    _parallel_jit = _jit
    _prange = range

__all__ = ["analyse_loop", "qrcp_one"]


@_jit
def qrcp_one(C, want_q, rdiag, Qt):  # pragma: no cover - compiled
    """One item of ``screwsym.numeric.mobility._qrcp``, in loops: fills ``rdiag`` and ``Qt``."""
    m, n = C.shape
    k = min(m, n)
    used = np.zeros(m, dtype=np.bool_)
    v = np.empty(n)
    for j in range(k):
        best, p = -1.0, 0
        for c in range(m):
            if used[c]:
                continue
            t = 0.0
            for q in range(j, n):
                t += C[c, q] * C[c, q]
            if t > best:
                best, p = t, c
        used[p] = True
        nx = np.sqrt(max(best, 0.0))
        for q in range(j, n):
            v[q] = C[p, q]
        v[j] += nx if v[j] >= 0 else -nx
        vn = 0.0
        for q in range(j, n):
            vn += v[q] * v[q]
        vn = np.sqrt(vn)
        if vn > 0:
            for q in range(j, n):
                v[q] /= vn
        for c in range(m):
            t = 0.0
            for q in range(j, n):
                t += C[c, q] * v[q]
            for q in range(j, n):
                C[c, q] -= 2 * t * v[q]
        rdiag[j] = nx
        if want_q:
            for col in range(n):
                t = 0.0
                for q in range(j, n):
                    t += v[q] * Qt[q, col]
                for q in range(j, n):
                    Qt[q, col] -= 2 * v[q] * t


@_parallel_jit
def analyse_loop(T, offsets, rtol, ranks, counts, sigma):  # pragma: no cover - compiled
    """The per-configuration loop of ``screwsym.numeric.mobility._analyse_numpy``."""
    N, _, M = T.shape
    k = offsets.shape[0] - 1
    for item in _prange(N):
        union = np.zeros((6 * k, 6))
        nu = 0
        for i in range(k):
            a, b = offsets[i], offsets[i + 1]
            C = np.empty((b - a, 6))
            for c in range(b - a):
                norm = 0.0
                for q in range(6):
                    norm += T[item, q, a + c] * T[item, q, a + c]
                norm = np.sqrt(norm) if norm > 0 else 1.0
                for q in range(6):
                    C[c, q] = T[item, SWAP[q], a + c] / norm
            kk = min(b - a, 6)
            rd = np.zeros(kk)
            Qt = np.eye(6)
            qrcp_one(C, True, rd, Qt)
            r = 0
            for j in range(kk):
                if rd[j] > rtol * rd[0]:
                    r += 1
            counts[item, i] = 6 - r
            for q in range(r, 6):
                for col in range(6):
                    union[nu, col] = Qt[q, col]
                nu += 1
        rd = np.zeros(6)
        qrcp_one(union[:nu].copy(), False, rd[: min(nu, 6)], Qt)
        r = 0
        for j in range(6):
            sigma[item, j] = rd[j]
            if rd[j] > rtol * rd[0]:
                r += 1
        ranks[item] = r
