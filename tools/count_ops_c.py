#!/usr/bin/python3
"""Apply SymPy's count_ops rules to a C function that offsetgen emitted.

Why: the SymPy baseline (tools/sympy_baseline.py) reports sum(count_ops) over
its cse output.  To compare like with like, we count OUR generated C with the
very same rules: every temporary RHS and the return expression is parsed with
SymPy (temporaries and parameters become plain symbols) and passed to
sympy.count_ops(visual=False).

C constructs SymPy cannot parse are counted by hand with fixed costs:
    cond ? a : b      1 for the select, plus the parts
    a < b (<=,>,>=,==,!=)  1 per comparison, plus the operands
    && / ||           1 each
    !c                1
Casts and float literal suffixes are stripped; sinf/fabs/... are mapped to
their SymPy equivalents (unknown calls become undefined functions, 1 op each).

Usage:
    /usr/bin/python3 tools/count_ops_c.py generated/gyroid_o4.h gyroid_o4_offset
prints {"function": ..., "sympy_count_ops": N, "lines": K} (K = statements counted).
Exit codes: 0 ok, 2 usage/input error (file/function missing, unparsable code).
"""

import argparse
import json
import keyword
import re
import sys

import sympy
from sympy.parsing.sympy_parser import parse_expr, standard_transformations

EXIT_USAGE = 2

# C math function (without float 'f' / long 'l' suffix) -> SymPy callable.
C_FUNCS = {
    "sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan,
    "asin": sympy.asin, "acos": sympy.acos, "atan": sympy.atan, "atan2": sympy.atan2,
    "sinh": sympy.sinh, "cosh": sympy.cosh, "tanh": sympy.tanh,
    "asinh": sympy.asinh, "acosh": sympy.acosh, "atanh": sympy.atanh,
    "exp": sympy.exp, "log": sympy.log, "sqrt": sympy.sqrt, "cbrt": sympy.cbrt,
    "pow": sympy.Pow, "fabs": sympy.Abs, "abs": sympy.Abs,
    "fmin": sympy.Min, "fmax": sympy.Max, "floor": sympy.floor, "ceil": sympy.ceiling,
    "fmod": sympy.Mod,
    # offsetgen's inline sin/cos helpers count as the calls they replace.
    "offsetgen_sin": sympy.sin, "offsetgen_cos": sympy.cos,
}
CAST_RE = re.compile(r"\(\s*(?:const\s+)?(?:double|float|int|long|unsigned|long\s+double)\s*\)")
STATIC_CAST_RE = re.compile(r"static_cast\s*<\s*(?:double|float|int)\s*>")
FLOAT_SUFFIX_RE = re.compile(r"(\b\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)[fFlL]\b")
IDENT_RE = re.compile(r"[A-Za-z_]\w*")
COMPARISONS = ("<=", ">=", "==", "!=", "<", ">")


class CountError(Exception):
    """Input the counter cannot handle; reported with exit status 2."""


# ---------------------------------------------------------------- extraction

def strip_comments(text):
    """Remove // and /* */ comments so they cannot hide braces or semicolons."""
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def matching(text, start, open_ch, close_ch):
    """Index of the bracket closing the one at `start` (which must be open_ch)."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == open_ch:
            depth += 1
        elif text[i] == close_ch:
            depth -= 1
            if depth == 0:
                return i
    raise CountError("unbalanced %r at offset %d" % (open_ch, start))


def function_body(source, name):
    """Return (params, body) of the DEFINITION of `name` (prototypes are skipped)."""
    text = strip_comments(source)
    for m in re.finditer(r"\b%s\s*\(" % re.escape(name), text):
        open_paren = m.end() - 1
        close_paren = matching(text, open_paren, "(", ")")
        rest = text[close_paren + 1:]
        after = re.match(r"\s*(?:noexcept|const|__attribute__\s*\(\(.*?\)\)|\s)*\{", rest, re.S)
        if after:
            brace = close_paren + 1 + after.end() - 1
            end = matching(text, brace, "{", "}")
            return text[open_paren + 1:close_paren], text[brace + 1:end]
    raise CountError("no definition of function %r found" % name)


def split_statements(body):
    """Split a function body into ';'-terminated statements (no nested blocks allowed)."""
    if "{" in body or "}" in body:
        raise CountError("nested blocks ({...}) are not supported; expected straight-line code")
    return [s.strip() for s in body.split(";") if s.strip()]


DECL_RE = re.compile(
    r"^(?:static\s+)?(?:const\s+)?(?:double|float|auto|int)\s+(?:const\s+)?"
    r"([A-Za-z_]\w*)\s*(?:=\s*(.*))?$", re.S)
ASSIGN_RE = re.compile(r"^(\*?\s*[A-Za-z_]\w*(?:\s*\[\s*\w+\s*\])?)\s*([-+*/]?)=(?!=)\s*(.*)$", re.S)


def statement_rhs(stmt):
    """Expression to count for one statement, plus extra ops (compound assignment)."""
    m = DECL_RE.match(stmt)
    if m:
        return m.group(2), 0          # None for a bare declaration
    if stmt == "return":
        return None, 0
    if stmt.startswith("return") and not re.match(r"return\w", stmt):
        return stmt[len("return"):].strip(), 0
    if stmt.startswith("(void)"):
        return None, 0
    m = ASSIGN_RE.match(stmt)
    if m:
        return m.group(3), (1 if m.group(2) else 0)
    raise CountError("cannot understand statement: %s" % stmt)


# ---------------------------------------------------------------- counting

def normalise(expr):
    """Drop casts and float/long literal suffixes; C and SymPy agree on the rest."""
    expr = CAST_RE.sub(" ", expr)
    expr = STATIC_CAST_RE.sub(" ", expr)
    return FLOAT_SUFFIX_RE.sub(r"\1", expr)


def top_level_scan(expr):
    """Yield (index, char) of characters outside any parentheses/brackets."""
    depth = 0
    for i, ch in enumerate(expr):
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        elif depth == 0:
            yield i, ch


def strip_outer_parens(expr):
    """'(a + b)' -> 'a + b', repeatedly, only when the parens wrap everything."""
    expr = expr.strip()
    while expr.startswith("(") and matching(expr, 0, "(", ")") == len(expr) - 1:
        expr = expr[1:-1].strip()
    return expr


def split_ternary(expr):
    """Split a top-level 'c ? a : b' into (c, a, b), or None if there is none."""
    q = None
    nested = 0
    for i, ch in top_level_scan(expr):
        if ch == "?":
            if q is None:
                q = i
            else:
                nested += 1
        elif ch == ":" and q is not None:
            if nested == 0:
                return expr[:q], expr[q + 1:i], expr[i + 1:]
            nested -= 1
    if q is not None:
        raise CountError("'?' without matching ':' in: %s" % expr)
    return None


def split_binary(expr, ops):
    """Split at the LAST top-level occurrence of any operator in `ops` (left-assoc)."""
    found = None
    top = dict(top_level_scan(expr))
    i = 0
    while i < len(expr):
        if i in top:
            for op in ops:
                if expr.startswith(op, i) and all(j in top for j in range(i, i + len(op))):
                    if op in ("<", ">") and (expr.startswith(op * 2, i) or
                                             (i > 0 and expr[i - 1] == op)):
                        break          # shift operator, not a comparison
                    if op in ("<", ">") and expr.startswith(op + "=", i):
                        break          # handled as <= / >=
                    found = (i, op)
                    i += len(op) - 1
                    break
        i += 1
    if found is None:
        return None
    i, op = found
    return expr[:i], op, expr[i + len(op):]


def has_boolean(expr):
    """True when expr needs the hand-counted path (?:, comparisons, logic) at top level."""
    e = strip_outer_parens(expr)
    if split_ternary(e) is not None:
        return True
    for ops in (("||",), ("&&",), ("==", "!="), ("<=", ">=", "<", ">")):
        if split_binary(e, ops) is not None:
            return True
    return e.startswith("!") and not e.startswith("!=")


def count_expr(expr, counter):
    """count_ops of a C expression, with the fixed costs for ?:, comparisons and logic."""
    e = strip_outer_parens(expr)
    if not e:
        raise CountError("empty expression")
    t = split_ternary(e)
    if t is not None:
        return 1 + sum(count_expr(part, counter) for part in t)
    for ops in (("||",), ("&&",), ("==", "!="), ("<=", ">=", "<", ">")):
        b = split_binary(e, ops)
        if b is not None:
            return 1 + count_expr(b[0], counter) + count_expr(b[2], counter)
    if e.startswith("!") and not e.startswith("!="):
        return 1 + count_expr(e[1:], counter)
    rewritten, extra = hoist_booleans(e, counter)
    return extra + counter.sympy_count(rewritten)


def hoist_booleans(expr, counter):
    """Replace parenthesised sub-expressions/call arguments that contain ?: or
    comparisons by fresh symbols (cost 0) and count them separately."""
    out, extra, i = [], 0, 0
    while i < len(expr):
        if expr[i] != "(":
            out.append(expr[i])
            i += 1
            continue
        j = matching(expr, i, "(", ")")
        args = split_args(expr[i + 1:j])
        new_args = []
        for a in args:
            if has_boolean(a):
                extra += count_expr(a, counter)
                new_args.append(counter.placeholder())
            else:
                r, e = hoist_booleans(a, counter)
                extra += e
                new_args.append(r)
        out.append("(" + ",".join(new_args) + ")")
        i = j + 1
    return "".join(out), extra


def split_args(inner):
    """Split a parenthesised group at top-level commas (function arguments)."""
    parts, last = [], 0
    for i, ch in top_level_scan(inner):
        if ch == ",":
            parts.append(inner[last:i])
            last = i + 1
    parts.append(inner[last:])
    return parts


class SympyCounter:
    """Turns an arithmetic C expression into SymPy and counts it.

    Every identifier is renamed (v_<name> for variables, f_<name> for calls)
    so C names can never collide with SymPy names (E, S, N, beta, lambda...)."""

    def __init__(self):
        self._n_placeholders = 0

    def placeholder(self):
        self._n_placeholders += 1
        return "_hoisted%d" % self._n_placeholders

    def sympy_count(self, expr):
        local = {}
        text = re.sub(r"([A-Za-z_]\w*)\s*\[\s*(\w+)\s*\]", r"\1__idx_\2", expr)

        def rename(m):
            name = m.group(0)
            follows_call = re.match(r"\s*\(", text[m.end():]) is not None
            if follows_call:
                key = "f_" + name
                local[key] = c_function(name)
            else:
                key = "v_" + name
                local[key] = sympy.Symbol(key)
            return key

        renamed = re.sub(r"(?<![\w.])[A-Za-z_]\w*", lambda m: rename_guard(m, rename), text)
        try:
            parsed = parse_expr(renamed, local_dict=local,
                                transformations=standard_transformations)
        except Exception as exc:  # SyntaxError, TokenError, TypeError...
            raise CountError("SymPy cannot parse %r (%s)" % (expr.strip(), exc))
        return int(sympy.count_ops(parsed, visual=False))


def rename_guard(match, rename):
    """Leave exponent parts of numeric literals (1e-5 -> 'e' is not an identifier) alone."""
    start = match.start()
    text = match.string
    if start > 0 and (text[start - 1].isdigit() or text[start - 1] == "."):
        return match.group(0)
    return rename(match)


def c_function(name):
    """SymPy callable for a C math function name (float 'f' / long 'l' variants too)."""
    for base in (name, name[:-1] if name[-1:] in ("f", "l") else None):
        if base and base in C_FUNCS:
            return C_FUNCS[base]
    if keyword.iskeyword(name):
        raise CountError("unexpected keyword %r used as a call" % name)
    return sympy.Function(name)


def count_function(source, name, per_line=False):
    """Sum count_ops over every statement of function `name` in `source`."""
    _params, body = function_body(source, name)
    counter = SympyCounter()
    total, lines, details = 0, 0, []
    for stmt in split_statements(body):
        rhs, extra = statement_rhs(stmt)
        if rhs is None:
            continue
        n = extra + count_expr(normalise(rhs), counter)
        total += n
        lines += 1
        details.append({"statement": " ".join(stmt.split()), "count_ops": n})
    result = {"function": name, "sympy_count_ops": total, "lines": lines}
    if per_line:
        result["per_line"] = details
    return result


def parse_args(argv):
    p = argparse.ArgumentParser(
        description="Count the operations of one generated C function with SymPy's "
                    "count_ops rules (to compare with tools/sympy_baseline.py).")
    p.add_argument("header", help="C/C++ header or source file")
    p.add_argument("function", help="name of the function to count")
    p.add_argument("--per-line", action="store_true",
                   help="also list each counted statement with its count (for checking)")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    try:
        with open(args.header, encoding="utf-8") as f:
            source = f.read()
    except OSError as exc:
        print("count_ops_c: cannot read %s: %s" % (args.header, exc.strerror), file=sys.stderr)
        return EXIT_USAGE
    try:
        result = count_function(source, args.function, args.per_line)
    except CountError as exc:
        print("count_ops_c: %s: %s" % (args.header, exc), file=sys.stderr)
        return EXIT_USAGE
    print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
