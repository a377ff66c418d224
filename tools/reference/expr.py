"""Expressions of the problem format: a tokenizer, a parser to a small tree, an evaluator.

Written from the grammar in the format's spec, independently of the Rust parser:

    sum     = product (("+" | "-") product)*
    product = unary (("*" | "/") unary)*
    unary   = ("-" | "+") unary | power
    power   = primary ("^" unary)?        # right associative, tighter than unary minus
    primary = number | name "'"* | name "(" sum ("," sum)* ")" | frame "." axis | "(" sum ")"

so `-2^2` is -4, `2^-1` is 0.5 and `2^3^2` is 512.

Values are floats or `Vec`s (a vector kept as components per frame), so one evaluator
serves both scalar and vector expressions: `2*A.x + L*N.y` evaluates to a `Vec`.
"""

import math


class ExprError(Exception):
    """A syntax or evaluation error, with the 1-based column when known."""

    def __init__(self, message, column=None):
        super().__init__(message if column is None else f"column {column}: {message}")
        self.column = column


class Vec:
    """A vector as components in named frames: {frame: [x, y, z]}."""

    def __init__(self, parts=None):
        self.parts = parts or {}

    def __add__(self, other):
        out = {f: list(c) for f, c in self.parts.items()}
        for f, c in other.parts.items():
            cur = out.setdefault(f, [0.0, 0.0, 0.0])
            for i in range(3):
                cur[i] += c[i]
        return Vec(out)

    def scale(self, k):
        return Vec({f: [k * x for x in c] for f, c in self.parts.items()})

    def frames(self):
        return set(self.parts)


FUNCS = {
    "sin": (1, math.sin), "cos": (1, math.cos), "tan": (1, math.tan),
    "asin": (1, math.asin), "acos": (1, math.acos), "atan": (1, math.atan),
    "atan2": (2, math.atan2), "sqrt": (1, math.sqrt), "exp": (1, math.exp),
    "ln": (1, math.log), "abs": (1, abs),
    "sign": (1, lambda x: (x > 0) - (x < 0)),
    "min": (None, min), "max": (None, max),
}


def tokenize(text):
    """Tokens as (kind, value, column): kinds num, name (value (name, primes)), unit, op."""
    toks = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        col = i + 1
        if c.isspace():
            i += 1
        elif c.isdigit() or (c == "." and i + 1 < n and text[i + 1].isdigit()):
            j = i
            while j < n and text[j].isdigit():
                j += 1
            if j < n and text[j] == ".":
                j += 1
                while j < n and text[j].isdigit():
                    j += 1
            if j < n and text[j] in "eE":
                k = j + 1
                if k < n and text[k] in "+-":
                    k += 1
                if k < n and text[k].isdigit():
                    while k < n and text[k].isdigit():
                        k += 1
                    j = k
            toks.append(("num", float(text[i:j]), col))
            i = j
        elif c.isalpha():
            j = i
            while j < n and (text[j].isalnum() or text[j] == "_"):
                j += 1
            name = text[i:j]
            # `A.x`: a unit vector; the axis must be one letter x, y or z.
            if j + 1 < n and text[j] == "." and text[j + 1] in "xyz" and not (
                j + 2 < n and (text[j + 2].isalnum() or text[j + 2] == "_")
            ):
                toks.append(("unit", (name, "xyz".index(text[j + 1])), col))
                i = j + 2
                continue
            primes = 0
            while j < n and text[j] == "'":
                primes += 1
                j += 1
            toks.append(("name", (name, primes), col))
            i = j
        elif c in "+-*/^(),":
            toks.append(("op", c, col))
            i += 1
        else:
            raise ExprError(f"unexpected character {c!r}", col)
    return toks


class _Parser:
    def __init__(self, text):
        self.toks = tokenize(text)
        self.pos = 0
        self.end_col = len(text) + 1

    def peek(self):
        return self.toks[self.pos] if self.pos < len(self.toks) else ("end", None, self.end_col)

    def take_op(self, ops):
        kind, val, _ = self.peek()
        if kind == "op" and val in ops:
            self.pos += 1
            return val
        return None

    def expect(self, op):
        kind, val, col = self.peek()
        if kind != "op" or val != op:
            raise ExprError(f"expected {op!r}", col)
        self.pos += 1

    def sum(self):
        node = self.product()
        while True:
            op = self.take_op("+-")
            if op is None:
                return node
            node = (op, node, self.product())

    def product(self):
        node = self.unary()
        while True:
            op = self.take_op("*/")
            if op is None:
                return node
            node = (op, node, self.unary())

    def unary(self):
        op = self.take_op("+-")
        if op == "-":
            return ("neg", self.unary())
        if op == "+":
            return self.unary()
        return self.power()

    def power(self):
        base = self.primary()
        if self.take_op("^"):
            # The exponent is a unary: `2^-1`, and `2^3^2` = 2^(3^2).
            return ("^", base, self.unary())
        return base

    def primary(self):
        kind, val, col = self.peek()
        if kind == "num":
            self.pos += 1
            return ("num", val)
        if kind == "unit":
            self.pos += 1
            return ("unit", val[0], val[1], col)
        if kind == "name":
            self.pos += 1
            name, primes = val
            nk, nv, _ = self.peek()
            if nk == "op" and nv == "(" and primes == 0:
                if name not in FUNCS:
                    raise ExprError(f"unknown function {name!r}", col)
                self.pos += 1
                args = [self.sum()]
                while self.take_op(","):
                    args.append(self.sum())
                self.expect(")")
                arity = FUNCS[name][0]
                if arity is not None and arity != len(args):
                    raise ExprError(f"{name} takes {arity} argument(s)", col)
                return ("call", name, args, col)
            return ("name", name, primes, col)
        if kind == "op" and val == "(":
            self.pos += 1
            node = self.sum()
            self.expect(")")
            return node
        raise ExprError("expected a number, a name or '('", col)


def parse(text):
    """Parses an expression (a string, or a JSON number) into a tree.

    Raises ExprError on a syntax error.
    """
    if isinstance(text, bool):
        raise ExprError("expected an expression, found a boolean")
    if isinstance(text, (int, float)):
        return ("num", float(text))
    if not isinstance(text, str):
        raise ExprError(f"expected an expression, found {type(text).__name__}")
    p = _Parser(text)
    node = p.sum()
    kind, _, col = p.peek()
    if kind != "end":
        raise ExprError("unexpected text after the expression", col)
    return node


def names_in(node, out=None):
    """The set of (name, primes) and ('unit', frame) references in a tree."""
    out = set() if out is None else out
    tag = node[0]
    if tag == "name":
        out.add((node[1], node[2]))
    elif tag == "unit":
        out.add(("unit", node[1]))
    elif tag == "neg":
        names_in(node[1], out)
    elif tag == "call":
        for a in node[2]:
            names_in(a, out)
    elif tag in "+-*/^":
        names_in(node[1], out)
        names_in(node[2], out)
    return out


def evaluate(node, lookup):
    """Evaluates a tree. `lookup(name, primes, column)` gives a name's float value.

    Unit vectors evaluate to Vec. Raises ExprError on a type error.
    """
    tag = node[0]
    if tag == "num":
        return node[1]
    if tag == "name":
        return float(lookup(node[1], node[2], node[3]))
    if tag == "unit":
        comps = [0.0, 0.0, 0.0]
        comps[node[2]] = 1.0
        return Vec({node[1]: comps})
    if tag == "neg":
        v = evaluate(node[1], lookup)
        return v.scale(-1.0) if isinstance(v, Vec) else -v
    if tag == "call":
        args = [evaluate(a, lookup) for a in node[2]]
        if any(isinstance(a, Vec) for a in args):
            raise ExprError(f"{node[1]} of a vector", node[3])
        return float(FUNCS[node[1]][1](*args))
    a = evaluate(node[1], lookup)
    b = evaluate(node[2], lookup)
    va, vb = isinstance(a, Vec), isinstance(b, Vec)
    if tag in "+-":
        if va != vb:
            # `0` may stand for the zero vector in a sum.
            if (not va and a == 0.0) or (not vb and b == 0.0):
                a = a if va else Vec()
                b = b if vb else Vec()
            else:
                raise ExprError("adding a scalar and a vector")
        if isinstance(a, Vec):
            return a + (b if tag == "+" else b.scale(-1.0))
        return a + b if tag == "+" else a - b
    if tag == "*":
        if va and vb:
            raise ExprError("product of two vectors")
        if va:
            return a.scale(b)
        if vb:
            return b.scale(a)
        return a * b
    if tag == "/":
        if vb:
            raise ExprError("division by a vector")
        return a.scale(1.0 / b) if va else a / b
    if tag == "^":
        if va or vb:
            raise ExprError("power of a vector")
        return a ** b
    raise ExprError(f"internal: unknown node {tag}")
