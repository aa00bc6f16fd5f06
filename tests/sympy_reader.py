#!/usr/bin/env python3
"""Reads every `expr` of `lagrangelab derive --format json` documents with SymPy, as a
Python reader would, and prints for each document given "file <path>" and then the values,
one per line, in document order.

The grammar (docs/user/derivation.md#expressions-in-json): numbers (integers, decimals,
a/b), identifiers (symbols: q1, qd1, qdd1, t, parameters, structured names), pi, + - * /,
^ for powers, parentheses, and the functions sin cos tan tanh exp log sqrt. An equation
is "lhs = rhs": each side is read alone. Each identifier's value is a function of its
name that tests/test_json_expressions.cpp computes the same way."""
import json
import re
import sys

import sympy

FUNCTIONS = {"sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan, "tanh": sympy.tanh, "exp": sympy.exp,
             "log": sympy.log, "sqrt": sympy.sqrt, "pi": sympy.pi}


def value_of(name):
    return 0.2 + sum((i + 1) * ord(c) for i, c in enumerate(name)) % 1000 / 1000.0


def expressions(node):
    """Every expr string in document order (matrices row by row)."""
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "expr" or key in ("B", "C", "g", "Q", "Ekin", "Epot"):
                yield from strings(value)
            elif isinstance(value, (dict, list)):
                yield from expressions(value)
    elif isinstance(node, list):
        for item in node:
            yield from expressions(item)


def strings(value):
    if isinstance(value, str):
        yield from value.split(" = ") if " = " in value else [value]
    elif isinstance(value, list):
        for v in value:
            yield from strings(v)


def evaluate(text):
    names = set(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", text)) - set(FUNCTIONS)
    local = dict(FUNCTIONS)
    local.update({n: sympy.Symbol(n) for n in names})
    e = sympy.sympify(text, locals=local, convert_xor=True)
    # xreplace with 30-digit numbers, then evalf: the value subs() gives, in a third of its time.
    return float(e.xreplace({local[n]: sympy.Float(value_of(n), 30) for n in names}).evalf(30))


def main():
    for path in sys.argv[1:]:
        print("file " + path)
        with open(path, encoding="utf-8") as f:
            document = json.load(f)
        for text in expressions(document):
            print(repr(evaluate(text)))


if __name__ == "__main__":
    main()
