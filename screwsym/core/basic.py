"""The base of every screwsym SymPy object: a ``Basic`` that never evaluates a string.

SymPy's ``subs``, ``xreplace``, ``match``, ``matches``, ``diff``,
``evalf(subs=...)``, ``refine``, ``has``, ``find``, ``count``, ``dummy_eq``,
... sympify their arguments without ``strict=True``, so a string passed to
them is parsed and evaluated as Python; even the strict sympify of ``==``
parses the strings inside a tuple or dict.  screwsym promises that text a
user wrote is never run: every screwsym object derives from
:class:`ScrewsymBasic`, whose versions of ``subs``, ``xreplace``, ``match``,
``matches``, ``diff`` and ``evalf`` are written here, and every other public
method SymPy's ``Basic`` gives it is wrapped once (:func:`_refusing_strings`,
the loop at the end of this module): each refuses strings (anywhere in its
arguments) with a ``TypeError`` before SymPy sees them.  ``==`` and ``!=``
with an object holding a string are ``False`` and ``True``, decided without
SymPy.

>>> from sympy import Abs, Symbol
>>> from screwsym import Screw
>>> x = Symbol("x", real=True)
>>> Screw([Abs(x), 0, 1], [0, 0, 0]).refine("Q.positive(x)")
Traceback (most recent call last):
...
TypeError: refine: strings are never evaluated, got str 'Q.positive(x)'
>>> Screw([1, 0, 0], [0, 0, 0]) == ("1",)
False
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from types import FunctionType
from typing import TYPE_CHECKING, Any

from .checks import check_no_strings, find_string

if TYPE_CHECKING:
    from typing_extensions import Self

    class Basic:
        """What a type checker sees of ``sympy.Basic``: SymPy ships no types.

        Were the base the untyped ``sympy.Basic`` itself (Any to mypy), every screwsym
        object would pass for every type: ``2 * twist`` would be an int, and
        ``x: int = Screw(...)`` accepted.  This declares what screwsym uses and leaves
        any other attribute Any.
        """

        args: tuple[Any, ...]
        free_symbols: set[Any]

        def __new__(cls, *args: Any) -> Self: ...
        def __getattr__(self, name: str) -> Any: ...
        def subs(self, *args: Any, **kwargs: Any) -> Any: ...
        def xreplace(self, rule: Any, *args: Any, **kwargs: Any) -> Any: ...
        def match(self, pattern: Any, *args: Any, **kwargs: Any) -> dict[Any, Any] | None: ...
        def matches(self, expr: Any, *args: Any, **kwargs: Any) -> dict[Any, Any] | None: ...
else:
    from sympy import Basic

__all__ = ["ScrewsymBasic"]


def _values(kwargs: dict[str, Any]) -> tuple[Any, ...]:
    """The values of keyword arguments: their names are Python identifiers, never evaluated."""
    return tuple(kwargs.values())


class ScrewsymBasic(Basic):
    """A SymPy ``Basic`` whose ``subs``, ``xreplace``, ``match``, ``diff`` and ``evalf`` refuse strings.

    >>> from sympy import Symbol
    >>> from screwsym import Screw
    >>> x = Symbol("x", real=True)
    >>> Screw([x, 0, 0], [0, 0, 0]).subs(x, 2)
    Screw([2, 0, 0], [0, 0, 0])
    >>> Screw([x, 0, 0], [0, 0, 0]).subs(x, "2")
    Traceback (most recent call last):
    ...
    TypeError: subs: strings are never evaluated, got str '2'
    """

    __slots__ = ()

    # subs and xreplace give Any: a rule may replace the object itself (``s.subs(s, 0)``)
    def subs(self, *args: Any, **kwargs: Any) -> Any:
        check_no_strings((args, _values(kwargs)), "subs")
        if kwargs.get("simultaneous"):
            # SymPy's simultaneous substitution passes through placeholder symbols with no
            # assumptions, which the constructors (real components) refuse: substitute in
            # each part instead, where the placeholders never meet a constructor
            return self.func(*(a.subs(*args, **kwargs) for a in self.args))
        return super().subs(*args, **kwargs)

    def xreplace(self, rule: Any, *args: Any, **kwargs: Any) -> Any:
        check_no_strings((rule, args, _values(kwargs)), "xreplace")
        return super().xreplace(rule, *args, **kwargs)

    def match(self, pattern: Any, *args: Any, **kwargs: Any) -> dict[Any, Any] | None:
        check_no_strings((pattern, args, _values(kwargs)), "match")
        return super().match(pattern, *args, **kwargs)

    def matches(self, expr: Any, *args: Any, **kwargs: Any) -> dict[Any, Any] | None:
        check_no_strings((expr, args, _values(kwargs)), "matches")
        return super().matches(expr, *args, **kwargs)

    def diff(self, *symbols: Any, **kwargs: Any) -> Basic:
        check_no_strings((symbols, _values(kwargs)), "diff")
        return self._eval_diff_parts(*symbols, **kwargs)

    def _eval_diff_parts(self, *symbols: Any, **kwargs: Any) -> Basic:
        """Differentiate ``args`` one by one; subclasses override for their own result class."""
        return self.func(*(a.diff(*symbols, **kwargs) for a in self.args))

    def evalf(self, n: int = 15, subs: Any = None, **options: Any) -> Self:
        check_no_strings((subs, _values(options)), "evalf")
        return self._eval_evalf_parts(n, subs=subs, **options)

    def _eval_evalf_parts(self, n: int, **options: Any) -> Self:
        return self.func(*(a.evalf(n, **options) for a in self.args))

    def n(self, n: int = 15, subs: Any = None, **options: Any) -> Self:
        return self.evalf(n, subs=subs, **options)

    def __eq__(self, other: object) -> bool:
        # Basic.__eq__ sympifies ``other``: strictly, but the strings inside a tuple, dict
        # or set are parsed all the same (SymPy's converters for containers are not strict)
        if not isinstance(other, Basic) and find_string(other) is not None:
            return False
        return super().__eq__(other)  # type: ignore[no-any-return]

    def __ne__(self, other: object) -> bool:
        equal = self.__eq__(other)
        return equal if equal is NotImplemented else not equal

    __hash__ = Basic.__hash__


#: public methods of ``Basic`` that take no expression, left unwrapped: ``sort_key``'s
#: ``order`` is a name looked up in a table, never parsed
_TAKES_NO_EXPRESSION = frozenset({"sort_key"})


def _refusing_strings(name: str, method: Callable[..., Any]) -> Callable[..., Any]:
    """``method`` of ``Basic``, refusing strings anywhere in its arguments first."""

    def guarded(self: Any, *args: Any, **kwargs: Any) -> Any:
        check_no_strings((args, _values(kwargs)), name)
        return method(self, *args, **kwargs)

    guarded.__name__ = guarded.__qualname__ = name
    guarded.__doc__ = (
        f"SymPy's ``Basic.{name}``, refusing strings in its arguments (never evaluated)."
    )
    return guarded


def _guard_inherited_methods() -> None:
    """Wrap every public method ``ScrewsymBasic`` inherits from SymPy (whatever its version)."""
    for name in dir(Basic):
        if name.startswith("_") or name in vars(ScrewsymBasic) or name in _TAKES_NO_EXPRESSION:
            continue
        member = inspect.getattr_static(Basic, name)
        if isinstance(member, FunctionType):
            setattr(ScrewsymBasic, name, _refusing_strings(name, member))


_guard_inherited_methods()
