"""Mutation catalogue of the RTL, generated from the sources, and its pairing
with the C++ model (scripts/mutation.py runs the campaigns; docs/mutation.md).

The catalogue is a pure function of the source text: the same files give the
same mutants in the same order with the same ids. Nothing here builds or runs.
"""

from __future__ import annotations

import dataclasses
import hashlib
import re
from pathlib import Path

# ---- operators -----------------------------------------------------------------------------------------------------

# Binary operator swaps, both ways.
SWAPS = {
    "+": ("arith", "-"), "-": ("arith", "+"),
    "<": ("relational", "<="), "<=": ("relational", "<"),
    ">": ("relational", ">="), ">=": ("relational", ">"),
    "==": ("equality", "!="), "!=": ("equality", "=="),
    "&&": ("logical", "||"), "||": ("logical", "&&"),
    "&": ("bitwise", "|"), "|": ("bitwise", "&"),
}
SWAPS_BY_OP = {"arith", "relational", "equality", "logical", "bitwise"}
OPERATORS = ("arith", "relational", "equality", "logical", "bitwise", "constant", "negate_if", "swap_ternary",
             "drop_not", "drop_term", "stuck_0", "stuck_1")
DROPPABLE = ("+", "-", "&&", "||", "&", "|")
# Binary precedence (SystemVerilog and C++ agree on the order of these).
PRECEDENCE = {
    "*": 11, "/": 11, "%": 11, "+": 10, "-": 10, "<<": 9, ">>": 9, "<<<": 9, ">>>": 9,
    "<": 8, "<=": 8, ">": 8, ">=": 8, "==": 7, "!=": 7, "===": 7, "!==": 7,
    "&": 6, "^": 5, "|": 4, "&&": 3, "||": 2,
}

# Areas of the campaigns. A step generator statement belongs to step
# accounting when it assigns the queue, the count or the overrun flag (or a
# signal derived only from them); the rest of the file is step timing.
STEP_ACCOUNTING_SIGNALS = re.compile(
    r"^(count|pend|overrun|req_blocked|have_steps|want_fwd|busy_o|pending_o)(_[qd]|_o)?$")
AREA_OF_FILE = {
    "sc_step_nco.sv": "step_timing",
    "sc_axis_core.sv": "step_accounting",
    "sc_profile_exec.sv": "endpoint",
    "sc_row_fifo.sv": "endpoint",
}
AREAS = ("step_timing", "step_accounting", "endpoint", "other")


def area_of(file_name: str, lhs: str) -> str:
    if file_name == "sc_step_gen.sv":
        return "step_accounting" if STEP_ACCOUNTING_SIGNALS.match(lhs or "") else "step_timing"
    return AREA_OF_FILE.get(file_name, "other")


# ---- lexing --------------------------------------------------------------------------------------------------------

@dataclasses.dataclass
class Tok:
    kind: str   # id, num, op, str
    text: str
    start: int  # character offsets in the file
    end: int


_OPS3 = ("<<<", ">>>", "===", "!==", "<<=", ">>=")
_OPS2 = ("<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "::", "+:", "-:", "->", "++", "--", "+=", "-=", "|=",
         "&=", "^=", "*=", "~&", "~|", "~^", "^~")
_SV_NUM = re.compile(r"(\d[\d_]*)?\s*'[sS]?([bBoOdDhH])\s*([0-9a-fA-FxXzZ_?]+)|'[01xXzZ](?![\w])|\d[\d_]*")
_CPP_NUM = re.compile(r"0[xX][0-9a-fA-F']+[uUlL]*|\d[\d']*(\.\d+)?([eE][+-]?\d+)?[uUlLfF]*")
_ID = re.compile(r"[A-Za-z_$][A-Za-z0-9_$]*")
# Code compiled only with these macros is not synthesised: never mutated.
SKIPPED_MACROS = ("FORMAL", "SC_COVER")


def lex_sv(text: str) -> list[Tok]:
    """Tokens of a SystemVerilog file outside comments, strings and the
    `ifdef FORMAL / `ifdef SC_COVER code (and the `else of an `ifndef)."""
    toks: list[Tok] = []
    i, n = 0, len(text)
    skip_flags: list[bool] = []         # per open conditional: is its current branch skipped
    frames: list[tuple[str, str]] = []  # (directive, macro) per open conditional
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
            continue
        if c == "`":
            m = re.match(r"`(\w+)[ \t]*(\w*)", text[i:])
            word, arg = m.group(1), m.group(2)
            if word in ("ifdef", "ifndef"):
                frames.append((word, arg))
                skip_flags.append(arg in SKIPPED_MACROS and word == "ifdef")
            elif word == "elsif":
                frames[-1] = ("ifdef", arg)
                skip_flags[-1] = arg in SKIPPED_MACROS
            elif word == "else":
                kind, macro = frames[-1]
                skip_flags[-1] = macro in SKIPPED_MACROS and kind == "ifndef"
            elif word == "endif":
                frames.pop()
                skip_flags.pop()
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if c.isspace():
            i += 1
            continue
        skipped = any(skip_flags)
        if c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            tok = Tok("str", text[i:j + 1], i, j + 1)
            i = j + 1
        else:
            m = _SV_NUM.match(text, i) if (c.isdigit() or c == "'") else None
            if m and not (c == "'" and text[i + 1:i + 2] == "("):
                tok = Tok("num", m.group(0), i, m.end())
            else:
                m = _ID.match(text, i)
                if m:
                    tok = Tok("id", m.group(0), i, m.end())
                else:
                    for ops in (_OPS3, _OPS2):
                        op = next((o for o in ops if text.startswith(o, i)), None)
                        if op:
                            break
                    op = op or c
                    tok = Tok("op", op, i, i + len(op))
            i = tok.end
        if not skipped:
            toks.append(tok)
    return toks


def lex_cpp(text: str) -> list[Tok]:
    """Tokens of a C++ file outside comments, strings and preprocessor lines."""
    toks: list[Tok] = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if c == "\n":
            at_line_start = True
            i += 1
            continue
        if c.isspace():
            i += 1
            continue
        if at_line_start and c == "#":
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        at_line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
            continue
        if c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            toks.append(Tok("str", text[i:j + 1], i, j + 1))
            i = j + 1
            continue
        m = _CPP_NUM.match(text, i) if c.isdigit() else None
        if m:
            toks.append(Tok("num", m.group(0), i, m.end()))
            i = m.end()
            continue
        m = _ID.match(text, i)
        if m:
            toks.append(Tok("id", m.group(0), i, m.end()))
            i = m.end()
            continue
        op = next((o for o in _OPS3 + _OPS2 if text.startswith(o, i)), c)
        toks.append(Tok("op", op, i, i + len(op)))
        i += len(op)
    return toks


# ---- expression regions --------------------------------------------------------------------------------------------

@dataclasses.dataclass
class Region:
    kind: str        # assign (continuous/blocking/non-blocking/declaration), cond (if), param, port
    lhs: str         # the assigned name (last identifier of the left side), '' for conditions
    start: int       # token indices of the expression [start, end)
    end: int


OPEN = {"(": ")", "[": "]", "{": "}"}


def _match(toks: list[Tok], i: int) -> int:
    """Index just past the bracket that closes toks[i]."""
    depth = 0
    for j in range(i, len(toks)):
        t = toks[j].text
        if toks[j].kind == "op" and t in OPEN:
            depth += 1
        elif toks[j].kind == "op" and t in (")", "]", "}"):
            depth -= 1
            if depth == 0:
                return j + 1
    return len(toks)


def sv_regions(toks: list[Tok]) -> list[Region]:
    """Expressions that mutants may touch: right-hand sides of assignments and
    parameter initialisers, if conditions, and instance port connections.
    Declarations' ranges, module headers and sensitivity lists are skipped."""
    regions: list[Region] = []
    i, n = 0, len(toks)
    stmt_start = 0
    stmt_kind = "assign"
    while i < n:
        t = toks[i]
        if t.kind == "id" and t.text in ("if", "while"):
            if i + 1 < n and toks[i + 1].text == "(":
                e = _match(toks, i + 1)
                regions.append(Region("cond", "", i + 2, e - 1))
                i = stmt_start = e
                stmt_kind = "assign"
                continue
        if t.kind == "id" and t.text in ("for", "case", "unique", "priority"):
            if i + 1 < n and toks[i + 1].text == "(":
                i = stmt_start = _match(toks, i + 1)
                continue
        if t.kind == "op" and t.text == "@":
            if i + 1 < n and toks[i + 1].text == "(":
                i = stmt_start = _match(toks, i + 1)
                continue
        if t.kind == "id" and t.text in ("localparam", "parameter"):
            stmt_kind = "param"
        if t.kind == "id" and t.text in ("begin", "end", "else", "always_comb", "always_ff", "always_latch",
                                         "endfunction", "endcase", "default", "generate", "endgenerate"):
            i = stmt_start = i + 1
            stmt_kind = "assign"
            continue
        if t.kind == "op" and t.text == "#" and i + 1 < n and toks[i + 1].text == "(":
            # parameter list of a module header or an instance: skipped
            i = _match(toks, i + 1)
            continue
        if t.kind == "op" and t.text == "(":
            e = _match(toks, i)
            # instance port connections: .name (expr)
            j = i + 1
            while j < e - 1:
                if toks[j].text == "." and j + 2 < e and toks[j + 1].kind == "id" and toks[j + 2].text == "(":
                    pe = _match(toks, j + 2)
                    if pe - 1 > j + 3:
                        regions.append(Region("port", toks[j + 1].text, j + 3, pe - 1))
                    j = pe
                else:
                    j += 1
            i = e
            continue
        if t.kind == "op" and t.text in ("[", "{"):
            i = _match(toks, i)
            continue
        if t.kind == "op" and t.text in (";", ":"):
            i = stmt_start = i + 1
            stmt_kind = "assign"
            continue
        if t.kind == "op" and t.text in ("=", "<="):
            lhs_ids = [x.text for x in toks[stmt_start:i] if x.kind == "id"]
            j = i + 1
            while j < n and toks[j].text != ";":
                j = _match(toks, j) if toks[j].text in OPEN else j + 1
            lhs = lhs_ids[-1] if lhs_ids else ""
            if toks[stmt_start].text == "{":
                lhs = "{" + ",".join(lhs_ids) + "}"
            regions.append(Region(stmt_kind if stmt_kind == "param" else "assign", lhs, i + 1, j))
            i = stmt_start = j + 1
            stmt_kind = "assign"
            continue
        i += 1
    return regions


def cpp_regions(toks: list[Tok]) -> list[Region]:
    """The model's expressions: right sides of assignments, compound
    assignments and initialisers, if/while conditions and return values."""
    regions: list[Region] = []
    n = len(toks)
    stmt_start = 0
    i = 0
    while i < n:
        t = toks[i]
        if t.kind == "id" and t.text in ("if", "while") and i + 1 < n and toks[i + 1].text == "(":
            e = _match(toks, i + 1)
            regions.append(Region("cond", "", i + 2, e - 1))
            i = stmt_start = e
            continue
        if t.kind == "id" and t.text == "for" and i + 1 < n and toks[i + 1].text == "(":
            i = stmt_start = _match(toks, i + 1)
            continue
        if t.kind == "id" and t.text == "return":
            j = i + 1
            while j < n and toks[j].text != ";":
                j = _match(toks, j) if toks[j].text in OPEN else j + 1
            regions.append(Region("return", "", i + 1, j))
            i = stmt_start = j + 1
            continue
        if t.kind == "op" and t.text in (";", "{", "}"):
            i = stmt_start = i + 1
            continue
        if t.kind == "op" and t.text in ("=", "+=", "-=", "|=", "&="):
            lhs_ids = [x.text for x in toks[stmt_start:i] if x.kind == "id"]
            j = i + 1
            while j < n and toks[j].text not in (";", ",", ")", "}"):
                j = _match(toks, j) if toks[j].text in OPEN else j + 1
            kind = "assign" if t.text == "=" else "compound"
            regions.append(Region(kind, lhs_ids[-1] if lhs_ids else "", i + 1, j))
            i = j
            continue
        i += 1
    return regions


# ---- expression structure ------------------------------------------------------------------------------------------

UNARY = ("!", "~", "-", "+", "&", "|", "^", "~&", "~|", "~^")
CPP_TYPES = {"bool", "int", "unsigned", "uint8_t", "uint16_t", "uint32_t", "uint64_t", "int8_t", "int16_t",
             "int32_t", "int64_t", "size_t", "u128", "i128", "Phase"}


def _is_operand_end(t: Tok) -> bool:
    return t.kind in ("id", "num", "str") or t.text in (")", "]", "}")


def primary_end(toks: list[Tok], i: int, end: int, cpp: bool) -> int:
    """Index past the primary (with its unary prefixes) starting at i."""
    while i < end and toks[i].kind == "op" and toks[i].text in UNARY:
        i += 1
    if i >= end:
        return end
    t = toks[i]
    if t.text in OPEN:
        j = _match(toks, i)
    elif t.kind in ("num", "str"):
        j = i + 1
    elif t.kind == "id":
        j = i + 1
        while j + 1 < end and toks[j].text in ("::", ".", "->") and toks[j + 1].kind == "id":
            j += 2
        if cpp and j < end and toks[j].text == "<":
            # a template argument list (static_cast<T>)
            k = j
            while k < end and toks[k].text != ">":
                k += 1
            if k + 1 < end and toks[k + 1].text == "(":
                j = k + 1
        if j < end and toks[j].text == "(":
            j = _match(toks, j)
    else:
        return i + 1
    while True:
        if j + 1 < end and not cpp and toks[j].text == "'" and toks[j + 1].text == "(":
            j = _match(toks, j + 1)
        elif j < end and toks[j].text == "[":
            j = _match(toks, j)
        elif cpp and j + 1 < end and toks[j].text in (".", "->") and toks[j + 1].kind == "id":
            j += 2
            if j < end and toks[j].text == "(":
                j = _match(toks, j)
        else:
            return j


def excluded_tokens(toks: list[Tok], start: int, end: int) -> set[int]:
    """Tokens of an SV expression that set a width, not a value: cast widths
    (W'(...)), part-select ranges ([a:b]) and replication counts ({N{...}})."""
    out: set[int] = set()
    for i in range(start, end):
        t = toks[i]
        if t.text == "'" and i + 1 < end and toks[i + 1].text == "(" and i > start:
            # the width before the apostrophe: an identifier/number, or a parenthesised group
            j = i - 1
            if toks[j].text == ")":
                depth = 0
                while j >= start:
                    if toks[j].text == ")":
                        depth += 1
                    elif toks[j].text == "(":
                        depth -= 1
                        if depth == 0:
                            break
                    j -= 1
            out.update(range(max(j, start), i))
        if t.text == "[":
            e = _match(toks, i)
            depth = 0
            has_range = False
            for k in range(i + 1, e - 1):
                if toks[k].text in OPEN:
                    depth += 1
                elif toks[k].text in (")", "]", "}"):
                    depth -= 1
                elif depth == 0 and toks[k].text in (":", "+:", "-:"):
                    has_range = True
            # a range sets a width; a constant index only picks a fixed bit
            if has_range or _is_constant_expr(toks, i + 1, e - 1):
                out.update(range(i, e))
        if t.text == "{" and i + 1 < end:
            # {N{...}}: N ends right before an inner '{'
            e = _match(toks, i)
            j = i + 1
            k = primary_end(toks, j, e, False)
            if k < e and toks[k].text == "{":
                out.update(range(j, k))
    return out


def ternary_parts(toks: list[Tok], q: int, start: int, end: int) -> tuple[int, int, int, int] | None:
    """(true arm start, colon, false arm start, false arm end) of the ternary
    whose '?' is at q, within [start, end); None when it is not one."""
    depth = 0
    nested = 0
    colon = None
    for j in range(q + 1, end):
        tx = toks[j].text
        if tx in OPEN:
            depth += 1
        elif tx in (")", "]", "}"):
            if depth == 0:
                return None
            depth -= 1
        elif depth == 0 and tx == "?":
            nested += 1
        elif depth == 0 and tx == ":":
            if nested == 0:
                colon = j
                break
            nested -= 1
    if colon is None:
        return None
    depth = 0
    false_end = end
    for j in range(colon + 1, end):
        tx = toks[j].text
        if tx in OPEN:
            depth += 1
        elif tx in (")", "]", "}"):
            if depth == 0:
                false_end = j
                break
            depth -= 1
        elif depth == 0 and tx in (",", ";"):
            false_end = j
            break
    return q + 1, colon, colon + 1, false_end


def _is_constant_expr(toks: list[Tok], start: int, end: int) -> bool:
    """No signal in it: numbers, casts and parameters (UpperCamelCase) only."""
    for t in toks[start:end]:
        if t.kind == "id" and t.text[0].islower() and t.text not in ("sc_pkg",) and not t.text.startswith("$"):
            return False
    return True


def _const_variants(text: str) -> list[str]:
    """The literal one below and one above (within its width), or the other
    fill value of '0 / '1."""
    if text in ("'0", "'1"):
        return ["'1" if text == "'0" else "'0"]
    m = re.fullmatch(r"(\d[\d_]*)?\s*'([sS]?)([bBoOdDhH])\s*([0-9a-fA-F_]+)", text)
    out = []
    if m:
        width = int(m.group(1).replace("_", "")) if m.group(1) else 32
        base = {"b": 2, "o": 8, "d": 10, "h": 16}[m.group(3).lower()]
        value = int(m.group(4).replace("_", ""), base)
        digits = len(m.group(4).replace("_", ""))
        for v in (value - 1, value + 1):
            if 0 <= v < (1 << width):
                body = {2: "b", 8: "o", 10: "d", 16: "x"}[base]
                s = format(v, body)
                if base != 10:
                    s = s.zfill(digits)
                out.append(f"{m.group(1) or ''}'{m.group(2)}{m.group(3)}{s}")
        return out
    if re.fullmatch(r"\d[\d_]*", text):
        value = int(text.replace("_", ""))
        return [str(v) for v in (value - 1, value + 1) if v >= 0]
    return out


# ---- mutants -------------------------------------------------------------------------------------------------------

@dataclasses.dataclass
class Mutant:
    id: str
    file: str        # path relative to the project root (rtl/<name>.sv)
    module: str
    line: int
    col: int
    operator: str
    original: str    # the text replaced
    replacement: str
    start: int       # character offsets in the file
    end: int
    area: str
    lhs: str
    region: tuple[int, int]   # token range of the expression (pairing)
    anchor: tuple[int, int]   # token range the mutation is about (pairing)

    def diff(self, text: str) -> str:
        """A one-line diff of the mutated source line."""
        line_start = text.rfind("\n", 0, self.start) + 1
        line_end = text.find("\n", self.end)
        line_end = len(text) if line_end < 0 else line_end
        before = text[line_start:line_end]
        after = text[line_start:self.start] + self.replacement + text[self.end:line_end]
        if "\n" in self.original:
            before = text[line_start:line_end]
        return f"- {before.strip()}\n+ {after.strip()}"

    def to_json(self) -> dict:
        return {k: getattr(self, k) for k in ("id", "file", "module", "line", "col", "operator", "original",
                                              "replacement", "area", "lhs")}


def _line_col(text: str, offset: int) -> tuple[int, int]:
    line = text.count("\n", 0, offset) + 1
    return line, offset - (text.rfind("\n", 0, offset) + 1) + 1


def _short(s: str, limit: int = 24) -> str:
    s = " ".join(s.split())
    if len(s) <= limit:
        return s
    return s[:limit] + "~" + hashlib.sha1(s.encode()).hexdigest()[:6]


def mutants_of_sv(path: Path, rel: str) -> list[Mutant]:
    text = path.read_text()
    toks = lex_sv(text)
    module = path.stem
    name = path.name
    out: list[Mutant] = []
    seen: set[tuple[int, int, str]] = set()

    def add(op: str, start: int, end: int, repl: str, region: Region, anchor: tuple[int, int], orig_label=None,
            repl_label=None):
        key = (start, end, repl)
        if key in seen or text[start:end] == repl:
            return
        seen.add(key)
        line, col = _line_col(text, start)
        orig = text[start:end]
        label = f"{_short(orig_label if orig_label is not None else orig)}->" \
                f"{_short(repl_label if repl_label is not None else repl)}"
        out.append(Mutant(id=f"{name}:{line}:{col}:{op}:{label}", file=rel, module=module, line=line, col=col,
                          operator=op, original=orig, replacement=repl, start=start, end=end,
                          area=area_of(name, region.lhs), lhs=region.lhs,
                          region=(region.start, region.end), anchor=anchor))

    for region in sv_regions(toks):
        s, e = region.start, region.end
        if s >= e:
            continue
        excluded = excluded_tokens(toks, s, e)
        if region.kind == "cond":
            a, b = toks[s].start, toks[e - 1].end
            add("negate_if", a, b, "!(" + text[a:b] + ")", region, (s, e), "if(c)", "if(!c)")
        for i in range(s, e):
            if i in excluded:
                continue
            t = toks[i]
            binary = i > s and _is_operand_end(toks[i - 1])
            if t.kind == "op" and t.text in SWAPS and binary and region.kind != "param":
                op, repl = SWAPS[t.text]
                add(op, t.start, t.end, repl, region, (i, i + 1))
            if t.kind == "op" and t.text in DROPPABLE and binary and region.kind != "param":
                pe = primary_end(toks, i + 1, e, False)
                nxt = toks[pe].text if pe < e else ";"
                if PRECEDENCE.get(nxt, 0) <= PRECEDENCE[t.text] and pe > i + 1:
                    a, b = t.start, toks[pe - 1].end
                    # keep the text before the operator (its spacing) as it is
                    add("drop_term", toks[i - 1].end, b, "", region, (i, i + 1),
                        text[toks[i - 1].end:b].strip(), "")
            if t.kind == "op" and t.text == "!" and region.kind != "param":
                add("drop_not", t.start, t.end, "", region, (i, i + 1))
            if t.kind == "op" and t.text == "?":
                parts = ternary_parts(toks, i, s, e)
                if parts:
                    ts, colon, fs, fe = parts
                    a, b = toks[ts].start, toks[fe - 1].end
                    true_txt = text[toks[ts].start:toks[colon - 1].end]
                    false_txt = text[toks[fs].start:toks[fe - 1].end]
                    add("swap_ternary", a, b, f"{false_txt} : {true_txt}", region, (i, i + 1), "c?t:f", "c?f:t")
            if t.kind == "num":
                for v in _const_variants(t.text):
                    add("constant", t.start, t.end, v, region, (i, i + 1))
        if region.kind == "assign" and not _is_constant_expr(toks, s, e):
            a, b = toks[s].start, toks[e - 1].end
            add("stuck_0", a, b, "'0", region, (s, e), "rhs")
            add("stuck_1", a, b, "'1", region, (s, e), "rhs")
    return out


def catalogue(root: Path, files: list[str] | None = None) -> list[Mutant]:
    """Every mutant of the given rtl files (default: every rtl/*.sv except
    the package), in file, then position order."""
    rtl = root / "rtl"
    paths = sorted(rtl.glob("*.sv")) if not files else [root / f for f in files]
    out: list[Mutant] = []
    for p in paths:
        if p.name == "sc_pkg.sv" and not files:
            continue
        out.extend(sorted(mutants_of_sv(p, str(p.relative_to(root))), key=lambda m: (m.start, m.end, m.id)))
    return out


# ---- pairing with the model ----------------------------------------------------------------------------------------

RTL_SUFFIX = re.compile(r"_(q|d|i|o|ni)$")
NAME_PREFIX = re.compile(r"^(cfg|hd|in)_")


def _norm_name(name: str) -> str:
    name = name.rstrip("_")
    name = RTL_SUFFIX.sub("", name)
    return NAME_PREFIX.sub("", name)


def normalise(toks: list[Tok], start: int, end: int, cpp: bool) -> list[tuple[str, int]]:
    """(normalised token, index of the original token): names without their
    register/port suffixes and member paths, no casts, no parentheses,
    booleans and sized literals as plain numbers."""
    out: list[tuple[str, int]] = []
    skip: set[int] = set() if cpp else excluded_tokens(toks, start, end)
    i = start
    while i < end:
        t = toks[i]
        if i in skip or t.text in ("(", ")"):
            i += 1
            continue
        if not cpp and t.text == "'":
            i += 1
            continue
        if cpp and t.kind == "id" and (t.text in CPP_TYPES or t.text in ("static_cast", "const")):
            i += 1
            if i < end and toks[i].text == "<":
                while i < end and toks[i].text != ">":
                    i += 1
                i += 1
            continue
        if t.kind == "id":
            # a member/package path keeps only its last name
            j = i
            while j + 2 < end + 1 and j + 1 < end and toks[j + 1].text in (".", "->", "::") and \
                    j + 2 < end and toks[j + 2].kind == "id":
                j += 2
            last = toks[j].text
            word = {"true": "1", "false": "0"}.get(last, _norm_name(last))
            out.append((word, j))
            i = j + 1
            continue
        if t.kind == "num":
            out.append((_num_value(t.text), i))
        else:
            out.append((t.text, i))
        i += 1
    return out


def _num_value(text: str) -> str:
    if text in ("'0",):
        return "0"
    m = re.fullmatch(r"(\d[\d_]*)?\s*'[sS]?([bBoOdDhH])\s*([0-9a-fA-F_]+)", text)
    if m:
        base = {"b": 2, "o": 8, "d": 10, "h": 16}[m.group(2).lower()]
        return str(int(m.group(3).replace("_", ""), base))
    t = text.rstrip("uUlL").replace("'", "").replace("_", "")
    try:
        return str(int(t, 0))
    except ValueError:
        return text


@dataclasses.dataclass
class Pairing:
    mutant_id: str
    model_file: str | None
    status: str          # paired, unpaired
    reason: str
    start: int = 0
    end: int = 0
    replacement: str = ""
    original: str = ""
    line: int = 0

    def to_json(self) -> dict:
        return dataclasses.asdict(self)


def mirror_files(root: Path, module: str) -> list[Path]:
    stem = module[3:] if module.startswith("sc_") else module
    return [p for p in (root / "cmodel" / f"{stem}.h", root / "cmodel" / f"{stem}.cpp") if p.exists()]


class ModelIndex:
    """The mirror class's expressions, normalised, for one RTL module."""

    def __init__(self, root: Path, module: str):
        self.files = []
        for p in mirror_files(root, module):
            text = p.read_text()
            toks = lex_cpp(text)
            regs = []
            for r in cpp_regions(toks):
                norm = normalise(toks, r.start, r.end, True)
                if r.kind in ("assign", "compound") and r.lhs:
                    lhs = [(_norm_name(r.lhs), -1), ("=", -1)]
                    norm = lhs + norm
                regs.append((r, norm))
            self.files.append((p, text, toks, regs))
        self.root = root


def pair(mutant: Mutant, root: Path, index: ModelIndex | None = None, min_radius: int = 2) -> Pairing:
    """The model statement that mirrors a mutant's RTL site, and the same
    change there. The RTL expression is normalised (see normalise()); a window
    around the mutated token, at least min_radius tokens each side, grows
    until it occurs exactly once in the mirror class's normalised expressions.
    No occurrence, or several however large the window: unpaired."""
    index = index or ModelIndex(root, mutant.module)
    if not index.files:
        return Pairing(mutant.id, None, "unpaired", f"no mirror class cmodel/{mutant.module[3:]}.h/.cpp")
    if mutant.operator == "stuck_1":
        return Pairing(mutant.id, None, "unpaired", "all ones of an RTL width has no width-exact model literal")
    text = (root / mutant.file).read_text()
    toks = lex_sv(text)
    rs, re_ = mutant.region
    norm = normalise(toks, rs, re_, False)
    kinds = {r.start: r for r in sv_regions(toks)}
    reg = kinds.get(rs)
    if reg is not None and reg.kind in ("assign", "param", "port") and reg.lhs and not reg.lhs.startswith("{"):
        norm = [(_norm_name(reg.lhs), -1), ("=", -1)] + norm
    elif reg is not None and reg.kind == "cond":
        norm = [("if", -1)] + norm
    words_all = [w for w, _ in norm]
    if len(words_all) == 3 and words_all[1] == "=" and words_all[0] == words_all[2]:
        return Pairing(mutant.id, None, "unpaired",
                       "a register transfer or hold default (the model updates its state in place)")
    a_tok, b_tok = mutant.anchor
    pos = [k for k, (_, ti) in enumerate(norm) if a_tok <= ti < b_tok]
    if not pos:
        return Pairing(mutant.id, None, "unpaired", "the mutated token has no normalised form (a width)")
    lo, hi = pos[0], pos[-1] + 1
    whole = mutant.operator in ("negate_if", "stuck_0")
    if whole:
        lo, hi = 0, len(norm)
    else:
        lo, hi = max(0, lo - min_radius), min(len(norm), hi + min_radius)
    while True:
        window = [w for w, _ in norm[lo:hi]]
        matches = []
        for p, mtext, mtoks, regs in index.files:
            for r, mnorm in regs:
                words = [w for w, _ in mnorm]
                if reg is not None and reg.kind == "cond":
                    words = ["if"] + words if r.kind == "cond" else words
                    mnorm = [("if", -1)] + mnorm if r.kind == "cond" else mnorm
                for o in range(0, len(words) - len(window) + 1):
                    if words[o:o + len(window)] == window:
                        if whole and (o != 0 or len(window) != len(words)):
                            continue
                        matches.append((p, mtext, mtoks, r, mnorm, o))
        if len(matches) == 1:
            break
        if not matches:
            return Pairing(mutant.id, None, "unpaired", f"no model expression matches '{' '.join(window)}'")
        if lo == 0 and hi == len(norm):
            return Pairing(mutant.id, None, "unpaired",
                           f"{len(matches)} model expressions match '{' '.join(window)}'")
        lo, hi = max(0, lo - 1), min(len(norm), hi + 1)
    p, mtext, mtoks, r, mnorm, o = matches[0]
    rel = str(p.relative_to(root))
    # the model tokens of the anchor
    anchor_norm = [k for k, (_, ti) in enumerate(norm) if a_tok <= ti < b_tok]
    m_idx = [mnorm[o + (k - lo)][1] for k in anchor_norm]
    edit = _model_edit(mutant, mtext, mtoks, r, m_idx)
    if isinstance(edit, str):
        return Pairing(mutant.id, rel, "unpaired", edit)
    s, e, repl = edit
    return Pairing(mutant.id, rel, "paired", "", s, e, repl, mtext[s:e], _line_col(mtext, s)[0])


def _model_edit(m: Mutant, text: str, toks: list[Tok], r: Region, idx: list[int]):
    """(start, end, replacement) in the model file, or a reason string."""
    if m.operator in SWAPS_BY_OP:
        t = toks[idx[0]]
        if t.text != m.original:
            return f"model operator is '{t.text}', not '{m.original}'"
        return t.start, t.end, m.replacement
    if m.operator == "constant":
        t = toks[idx[0]]
        if t.kind == "id" and t.text in ("true", "false"):
            return t.start, t.end, "false" if t.text == "true" else "true"
        if t.kind != "num":
            return f"model token '{t.text}' is not a literal"
        if "'1" in (m.original, m.replacement):
            # '1 is all ones of the RTL width; the model's literal would only move by one
            return "'0 / '1 of a multi-bit signal has no width-exact model literal"
        delta = int(_num_value(m.replacement) if m.replacement not in ("'1",) else "1") - \
            int(_num_value(m.original)) if m.original not in ("'1",) else -1
        try:
            value = int(_num_value(t.text)) + delta
        except ValueError:
            return f"model literal '{t.text}' is not an integer"
        if value < 0:
            return "model literal would be negative"
        return t.start, t.end, str(value)
    if m.operator == "drop_not":
        t = toks[idx[0]]
        return (t.start, t.end, "") if t.text == "!" else f"model token '{t.text}' is not '!'"
    if m.operator == "drop_term":
        i = idx[0]
        pe = primary_end(toks, i + 1, r.end, True)
        nxt = toks[pe].text if pe < r.end else ";"
        if PRECEDENCE.get(nxt, 0) > PRECEDENCE.get(toks[i].text, 0) or pe <= i + 1:
            return "the model's right operand is not a single term"
        return toks[i - 1].end, toks[pe - 1].end, ""
    if m.operator == "swap_ternary":
        parts = ternary_parts(toks, idx[0], r.start, r.end)
        if not parts:
            return "no model ternary"
        ts, colon, fs, fe = parts
        a, b = toks[ts].start, toks[fe - 1].end
        t_txt = text[toks[ts].start:toks[colon - 1].end]
        f_txt = text[toks[fs].start:toks[fe - 1].end]
        return a, b, f"{f_txt} : {t_txt}"
    if m.operator == "negate_if":
        a, b = toks[r.start].start, toks[r.end - 1].end
        return a, b, "!(" + text[a:b] + ")"
    if m.operator == "stuck_0":
        a, b = toks[r.start].start, toks[r.end - 1].end
        return a, b, "0"
    return f"operator {m.operator} has no model form"



def pair_all(mutants: list[Mutant], root: Path) -> dict[str, Pairing]:
    """pair() of every mutant; a model change claimed by several RTL sites
    (the model computes once what the RTL writes twice) pairs none of them."""
    indexes: dict[str, ModelIndex] = {}
    out: dict[str, Pairing] = {}
    for m in mutants:
        if m.module not in indexes:
            indexes[m.module] = ModelIndex(root, m.module)
        out[m.id] = pair(m, root, indexes[m.module])
    claims: dict[tuple, list[str]] = {}
    for mid, p in out.items():
        if p.status == "paired":
            claims.setdefault((p.model_file, p.start, p.end, p.replacement), []).append(mid)
    for ids in claims.values():
        if len(ids) > 1:
            for mid in ids:
                p = out[mid]
                out[mid] = Pairing(mid, p.model_file, "unpaired",
                                   f"{len(ids)} RTL sites match the same model statement (line {p.line})")
    return out


# ---- applying ------------------------------------------------------------------------------------------------------

def apply_edit(path: Path, start: int, end: int, original: str, replacement: str) -> str:
    """Replaces [start, end) of the file, which must hold `original`; returns
    the file's previous text (to restore it)."""
    text = path.read_text()
    if text[start:end] != original:
        raise RuntimeError(f"{path}: expected {original!r} at offset {start}, found {text[start:end]!r}")
    path.write_text(text[:start] + replacement + text[end:])
    return text
