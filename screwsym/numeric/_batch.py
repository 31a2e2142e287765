"""The batch shape of a generated function's result (shared by the dynamics of chains and of closed loops)."""

from __future__ import annotations

from typing import Any

import numpy as np


def shaped(f: Any, trailing: tuple[int, ...]) -> Any:
    """``f`` with its result shaped ``(..., *trailing)``, the batch shape that of its inputs."""

    def g(*args: Any) -> np.ndarray:
        batch = np.broadcast_shapes(*(np.shape(a)[:-1] for a in args))
        out = np.asarray(f(*args))
        if out.size == int(np.prod(batch + trailing)):
            return out.reshape(batch + trailing)
        return np.broadcast_to(out.reshape(trailing), batch + trailing).copy()  # a constant

    g.__doc__ = f.__doc__
    return g
