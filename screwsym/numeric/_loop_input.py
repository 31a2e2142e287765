"""The checks of a closed loop's input, shared by
:func:`~screwsym.numeric.loop_program.loop_dynamics_program` and
:func:`~screwsym.numeric.loop_dynamics.loop_dynamics_functions`: the mechanism, the symbols
its configuration is given in, and that they cover it."""

from __future__ import annotations

from typing import Any

from sympy import Symbol

from ..core.checks import check_sequence


def check_mechanism(mech: Any) -> None:
    """``mech`` a :class:`~screwsym.systems.linkage.Mechanism` with inertias, or a clear
    ``TypeError``/``ValueError``."""
    from ..systems.linkage import Mechanism

    if not isinstance(mech, Mechanism):
        raise TypeError(f"mech: expected a Mechanism, got {type(mech).__name__}")
    if not mech.inertia_pairs:
        raise ValueError("mech: the mechanism has no inertias; build it with "
                         "Mechanism(..., inertias={link: SpatialInertia(...)})")


def check_symbols(symbols: Any) -> list:
    """``symbols`` as a list of distinct ``Symbol``: a ``TypeError`` or ``ValueError`` naming
    the entry otherwise.

    >>> from sympy import symbols
    >>> check_symbols(symbols("x y"))
    [x, y]
    """
    syms = list(check_sequence(symbols, "symbols", "symbols"))
    for i, s in enumerate(syms):
        if not isinstance(s, Symbol):
            raise TypeError(f"symbols[{i}]: expected a Symbol, got {s!r}")
    if len(set(syms)) != len(syms):
        raise ValueError("symbols: a symbol is given twice")
    return syms


def check_covered(mech: Any, syms: list, also: Any = frozenset()) -> None:
    """A ``ValueError`` naming the symbols of ``mech``'s joints and inertias (and of
    ``also``) that are not among ``syms``."""
    free: set = set(also)
    for _, _, j in mech.joints:
        free |= j.free_symbols
    for p in mech.inertia_pairs:
        free |= p.args[1].free_symbols
    missing = free - set(syms)
    if missing:
        raise ValueError("symbols: the mechanism's configuration has the symbols "
                         f"{sorted(map(str, missing))} not among them")
