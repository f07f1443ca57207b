"""torseur's expression text (canonical or presentation) to sympy.

A small recursive-descent reader of the engine's syntax (``+ - * / ^``, parentheses, decimal
and integer numbers, ``cos sin tan sqrt exp ln atan`` and ``dot ddot``), written here instead of
``sympy.parse_expr`` so that nothing is evaluated by Python and names such as ``lambda``, ``E``,
``I``, ``S`` or ``N`` stay plain symbols. Each coordinate ``q`` becomes ``Function("q")(t)`` with
``t = Symbol("t")``, ``dot(q)`` its derivative, ``ddot(q)`` the second; every other name is a
``Symbol`` (``pi`` is π unless the spec declares that name).
"""

from __future__ import annotations

import re
from typing import Iterable, List, Tuple

_TOKEN = re.compile(r"\s*(?:(\d+\.\d*|\.\d+|\d+)|([A-Za-z_][A-Za-z0-9_]*)|(\S))")

_FUNCTIONS = {
    "cos": "cos",
    "sin": "sin",
    "tan": "tan",
    "sqrt": "sqrt",
    "exp": "exp",
    "ln": "log",
    "log": "log",
    "atan": "atan",
    "abs": "Abs",
    "sign": "sign",
}


def _tokens(text: str) -> List[Tuple[str, str]]:
    out = []
    pos = 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            raise ValueError(f"cannot read `{text}` at {pos}")
        number, name, op = m.groups()
        if number is not None:
            out.append(("num", number))
        elif name is not None:
            out.append(("name", name))
        else:
            out.append(("op", op))
        pos = m.end()
    return out


class _Reader:
    def __init__(self, text: str, coordinates: Iterable[str]):
        import sympy

        self.sp = sympy
        self.text = text
        self.toks = _tokens(text)
        self.k = 0
        self.t = sympy.Symbol("t")
        self.coordinates = set(coordinates)

    def peek(self):
        return self.toks[self.k] if self.k < len(self.toks) else ("end", "")

    def take(self, op: str = None):
        tok = self.peek()
        if op is not None and tok != ("op", op):
            raise ValueError(f"`{self.text}`: expected `{op}`, found `{tok[1]}`")
        self.k += 1
        return tok

    def expression(self):
        sign = 1
        if self.peek() in (("op", "-"), ("op", "+")):
            sign = -1 if self.take()[1] == "-" else 1
        total = sign * self.term()
        while self.peek() in (("op", "+"), ("op", "-")):
            op = self.take()[1]
            t = self.term()
            total = total + t if op == "+" else total - t
        return total

    def term(self):
        value = self.power()
        while self.peek() in (("op", "*"), ("op", "/")):
            op = self.take()[1]
            rhs = self.power()
            value = value * rhs if op == "*" else value / rhs
        return value

    def power(self):
        base = self.atom()
        if self.peek() == ("op", "^"):
            self.take()
            if self.peek() in (("op", "-"), ("op", "+")):
                sign = -1 if self.take()[1] == "-" else 1
                return base ** (sign * self.power())
            return base ** self.power()
        return base

    def atom(self):
        kind, text = self.take()
        sp = self.sp
        if kind == "num":
            return sp.Rational(text) if "." in text else sp.Integer(text)
        if kind == "op" and text == "(":
            e = self.expression()
            self.take(")")
            return e
        if kind == "op" and text == "-":
            return -self.power()
        if kind == "name":
            if self.peek() == ("op", "("):
                return self.call(text)
            if text in self.coordinates:
                return sp.Function(text)(self.t)
            if text == "t":
                return self.t
            if text == "pi":
                return sp.pi
            return sp.Symbol(text)
        raise ValueError(f"`{self.text}`: unexpected `{text}`")

    def call(self, name: str):
        sp = self.sp
        self.take("(")
        if name in ("dot", "ddot"):
            kind, q = self.take()
            self.take(")")
            if kind != "name" or q not in self.coordinates:
                raise ValueError(f"`{self.text}`: {name}() of `{q}`, which is not a coordinate")
            return sp.Function(q)(self.t).diff(self.t, 1 if name == "dot" else 2)
        arg = self.expression()
        self.take(")")
        if name not in _FUNCTIONS:
            raise ValueError(f"`{self.text}`: unknown function `{name}`")
        return getattr(sp, _FUNCTIONS[name])(arg)


def to_sympy(text: str, coordinates: Iterable[str]):
    """Reads one expression of torseur's syntax as a sympy expression."""
    r = _Reader(text, coordinates)
    e = r.expression()
    if r.peek()[0] != "end":
        raise ValueError(f"`{text}`: unexpected `{r.peek()[1]}`")
    return e
