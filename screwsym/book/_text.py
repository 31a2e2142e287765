r"""Plain text from the registry's LaTeX statements, for terminals.

The statements use a small, fixed part of LaTeX (``\mathbf``, ``\frac``,
``\sqrt``, ``\text``, ``vmatrix`` and ``array`` environments, sub- and
superscripts, Greek letters and operators).  :func:`latex_to_text` reads that
part with a brace-aware parser and refuses nothing: an unknown command is
written by its name without the backslash.  The tests render every entry and
check that no LaTeX is left.

>>> latex_to_text(r"h=\frac{\mathbf S\cdot\mathbf S^0}{\mathbf S\cdot\mathbf S}")
'h = (S·S⁰)/(S·S)'
>>> latex_to_text(r"\tfrac{1}{\sqrt3}(1\ 1\ 1;\ 1\ 1\ 1)")
'1/√3(1 1 1; 1 1 1)'
>>> latex_to_text(r"M_m=-a_{12}\sin\alpha_{12}")
'M_m = -a_12 sin α_12'
"""

from __future__ import annotations

__all__ = ["latex_to_text"]

_SYMBOLS = {
    "times": "×", "cdot": "·", "circ": "∘", "neq": "≠", "ne": "≠", "iff": "⇔",
    "Rightarrow": "⇒", "perp": "⊥", "infty": "∞", "lambda": "λ", "omega": "ω",
    "alpha": "α", "rho": "ρ", "mu": "μ", "theta": "θ", "pi": "π", "in": "∈", "dim": "dim ",
    "sin": " sin ", "cos": " cos ", "$": "$", "{": "{", "}": "}", ",": " ", ";": " ", ":": " ",
    "!": "", " ": " ", "quad": "   ", "qquad": "    ", "left": "", "right": "", "le": "≤",
    "ge": "≥", "to": "→", "ldots": "...", "dots": "...",
}
_ARGUMENT = ("mathbf", "boldsymbol", "text", "mathrm", "operatorname", "mathit", "bm")
_SUPER = {"0": "⁰", "2": "²", "T": "ᵀ", "4": "⁴", "5": "⁵", "6": "⁶"}


class _Reader:
    def __init__(self, tex: str) -> None:
        self.s, self.i = tex, 0

    def peek(self) -> str:
        return self.s[self.i] if self.i < len(self.s) else ""

    def command(self) -> str:
        j = self.i + 1
        if j < len(self.s) and not self.s[j].isalpha():
            self.i = j + 1
            return self.s[j]
        while j < len(self.s) and self.s[j].isalpha():
            j += 1
        name, self.i = self.s[self.i + 1:j], j
        return name

    def group(self, stop: str = "") -> str:
        """Render until the closing brace (or ``stop`` / the end)."""
        out: list[str] = []
        while self.i < len(self.s):
            ch = self.peek()
            if ch == "}" or (stop and self.s.startswith(stop, self.i)):
                break
            out.append(self.token())
        return "".join(out)

    def argument(self) -> str:
        while self.peek() == " ":
            self.i += 1
        if self.peek() == "{":
            self.i += 1
            inner = self.group()
            self.i += 1  # the closing brace
            return inner
        if self.peek() == "\\":
            return self.token()
        ch = self.peek()
        self.i += 1
        return ch

    def environment(self, name: str) -> str:
        if name == "array" and self.peek() == "{":
            self.argument()  # the column specification
        end = f"\\end{{{name}}}"
        body = self.group(stop=end)
        self.i += len(end)
        rows = [[" ".join(c.split()) for c in r.split("\x00")] for r in body.split("\x01")]
        rows = [r for r in rows if any(r)]
        if name == "vmatrix":
            return "det[" + "; ".join(" ".join(r) for r in rows) + "]"
        return "\n" + "\n".join("   ".join(r) for r in rows) + "\n"

    def token(self) -> str:
        ch = self.peek()
        if ch == "\\":
            name = self.command()
            if name == "\\":
                return "\x01"  # a row break inside an environment, a line break outside
            if name in ("frac", "tfrac", "dfrac"):
                num, den = self.argument(), self.argument()
                return f"{_wrap(num)}/{_wrap(den)}"
            if name == "sqrt":
                return "√" + _wrap(self.argument())
            if name in _ARGUMENT:
                return self.argument()
            if name == "overrightarrow":
                return self.argument() + "\u20d7"
            if name == "begin":
                return self.environment(self.argument())
            return _SYMBOLS.get(name, name)
        self.i += 1
        if ch == "{":
            inner = self.group()
            self.i += 1
            return inner
        if ch == "&":
            return "\x00"
        if ch == "^":
            arg = self.argument()
            return _SUPER.get(arg, "^" + _wrap(arg))
        if ch == "_":
            arg = self.argument()
            return "₀" if arg == "0" else "_" + _wrap(arg)
        return ch


def _wrap(s: str) -> str:
    """Parenthesise a fraction's part or an index when it has an operator in it."""
    s = s.strip()
    return f"({s})" if any(op in s for op in "+-×·/∘ ") else s


def _space_relations(s: str) -> str:
    for rel in ("=", "⇔", "⇒", "≠"):
        s = s.replace(rel, f" {rel} ")
    return " ".join(s.split(" ")) if "\n" not in s else s


def latex_to_text(tex: str) -> str:
    r"""Render one of the registry's LaTeX statements as plain Unicode text.

    >>> print(latex_to_text(r"\mathbf S_0=\begin{vmatrix}\mathbf i&\mathbf j&\mathbf k\\ "
    ...                     r"x_1&y_1&z_1\\ L&M&N\end{vmatrix}"))
    S₀ = det[i j k; x_1 y_1 z_1; L M N]
    """
    text = _Reader(tex).group().replace("\x00", "  ").replace("\x01", "\n")
    lines = [" ".join(_space_relations(line).split()) for line in text.splitlines()]
    return "\n".join(line for line in lines if line)
