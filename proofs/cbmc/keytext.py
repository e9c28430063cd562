#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The text a CBMC record key digests (assumption B10): a harness's preprocessed sources, cut to
what can reach its verdict.

Reads, on stdin, the options line(s) and then, per source, a line "== <source>" followed by
goto-cc's preprocessed output of it; writes the key text on stdout. It keeps everything that
can change the analysed program or a recorded field, and drops what cannot:
- Function definitions, prototypes and `extern` object declarations whose name no kept text
  mentions (the options line included: goto-instrument's --replace-calls names its
  replacements there). The binary is cut the same way (goto-instrument
  --drop-unused-functions), and an object nothing names is never read, so what is dropped here
  is never analysed. Every other item (types, defined objects, initialisers, pragmas) stays.
- Line markers and blank lines, except in function definitions from kernel/: the coverage
  record names uncovered kernel lines, so a kernel function keeps its first line and its inner
  line structure.
- The numbers of the translator's quantifier helpers (mtc_q<n>, mtc_<var>_<n>), which count
  across the whole logic file: they are renamed in order of first use, consistently, so adding
  a quantifier elsewhere leaves this harness's text unchanged.
So a key moves when, and only when, the program CBMC analyses (or a kernel line it reports)
changes, not when an unrelated contract, comment or header line does."""
import bisect
import re
import sys

MARKER = re.compile(r'^# (\d+) "([^"]*)"')
# the characters that shape C's top level, string and character literals skipped whole
STRUCT = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|[{}()\[\];=\n]')
IDENT = re.compile(r"[A-Za-z_]\w*")
NOT_NAMES = {"__inline", "__restrict", "void", "char", "short", "int", "long", "float", "double",
             "signed", "unsigned",
             "_Bool", "const", "volatile", "static", "extern", "inline", "register"}
NUMBERED = re.compile(r"\bmtc_(?:q|[A-Za-z]+_)\d+\b")


class Item:
    """One top-level item: a function definition, a declaration, or anything else."""

    def __init__(self, lines):
        self.lines = lines  # (file, line, text)
        self.kind = "other"
        self.name = None
        self.text = "\n".join(t for _, _, t in lines)


def read_segment(raw):
    """Non-marker lines with their file and line number."""
    out = []
    file, line = "", 0
    for text in raw:
        m = MARKER.match(text)
        if m:
            line, file = int(m.group(1)), m.group(2)
            continue
        if text.startswith("#"):
            out.append((file, line, text))  # a pragma: an item of its own
            out.append((file, line, ";"))
        else:
            out.append((file, line, text))
        line += 1
    return out


def split_items(lines):
    """Top-level items, from the structure characters of the joined text; each item's lines
    without the blank lines around it."""
    text = "\n".join(t for _, _, t in lines)
    starts = [0]
    for _, _, t in lines:
        starts.append(starts[-1] + len(t) + 1)
    items, row, depth, paren, is_def = [], 0, 0, 0, None
    for m in STRUCT.finditer(text):
        tok = m.group(0)
        if tok in "([":
            paren += 1
        elif tok in ")]":
            paren -= 1
        elif tok == "{":
            if depth == 0 and paren == 0 and is_def is None:
                is_def = text[:m.start()].rstrip().endswith(")")
            depth += 1
        elif tok == "}":
            depth -= 1
        if depth or paren or not (tok == ";" or (tok == "}" and is_def)):
            continue
        row_end = bisect.bisect_right(starts, m.end() - 1) - 1
        items.append(make_item(lines[row:row_end + 1], "def" if tok == "}" else "decl"))
        row, is_def = row_end + 1, None
    if row < len(lines):
        items.append(make_item(lines[row:], "other"))
    return [it for it in items if it.lines]


def make_item(lines, kind):
    while lines and not lines[0][2].strip():
        lines = lines[1:]
    while lines and not lines[-1][2].strip():
        lines = lines[:-1]
    item = Item(lines)
    item.kind = kind
    return item


ATTRS = {"__attribute__", "__asm__", "__asm", "asm", "__extension__", "__typeof__", "typeof",
         "__declspec", "_Alignas", "sizeof"}


def function_name(item):
    """The declared function's name, or None when the item declares no function: the
    identifier right before the first top-level parenthesis that is not an attribute's."""
    head = item.text.split("{", 1)[0] if item.kind == "def" else item.text
    if item.kind == "decl" and (re.match(r"\s*(typedef|struct|union|enum)\b", head)
                                or "=" in head):
        return None
    depth = 0
    for m in re.finditer(r"\(|\)", head):
        if m.group(0) == ")":
            depth -= 1
            continue
        if depth == 0:
            before = head[:m.start()].rstrip()
            prev = re.search(r"[A-Za-z_]\w*$", before)
            if prev is None:
                return None
            if prev.group(0) not in ATTRS:
                return None if prev.group(0) in NOT_NAMES else prev.group(0)
        depth += 1
    return None


def extern_object_name(item):
    """The name an `extern` object declaration (no initialiser, no function type) declares."""
    if not re.match(r"\s*extern\b", item.text) or "=" in item.text:
        return None
    m = re.search(r"([A-Za-z_]\w*)\s*(?:\[[^\]]*\]\s*)*;\s*$", item.text)
    if m is None or "(" in item.text[:m.start()]:
        return None  # a function or function pointer, or not a plain object
    return m.group(1)


_SEGMENTS = {}


def segment_items(raw):
    """The top-level items of one source's preprocessed lines, named. Memoised on the text: a
    run of every harness digests the same library sources, with the same options, many times
    (proofs/cbmc/run.py computes its keys in one process); the items are never changed after."""
    text = "\n".join(raw)
    items = _SEGMENTS.get(text)
    if items is None:
        items = split_items(read_segment(raw))
        for it in items:
            if it.kind in ("def", "decl"):
                it.name = function_name(it)
                if it.name is None and it.kind == "decl":
                    it.name = extern_object_name(it)
                if it.name is None:
                    it.kind = "other"
        _SEGMENTS[text] = items
    return items


def key_text(data):
    """The key text of the whole input (the text main reads on stdin)."""
    head, segments, cur = [], [], None
    for text in data.split("\n"):
        if text.startswith("== "):
            cur = [text, []]
            segments.append(cur)
        elif cur is None:
            head.append(text)
        else:
            cur[1].append(text)
    seg_items = [(title, segment_items(raw)) for title, raw in segments]
    # reachability over names: roots are the options, the entry point and every other item
    defs = {}
    for _, items in seg_items:
        for it in items:
            if it.kind == "def":
                defs.setdefault(it.name, []).append(it)
    used = set(IDENT.findall("\n".join(head))) | {"harness"}
    for _, items in seg_items:
        for it in items:
            if it.kind == "other":
                used.update(IDENT.findall(it.text))
    todo = [n for n in used if n in defs]
    done = set()
    while todo:
        n = todo.pop()
        if n in done:
            continue
        done.add(n)
        for it in defs[n]:
            body = it.text
            for ref in set(IDENT.findall(body)):
                used.add(ref)
                if ref in defs and ref not in done:
                    todo.append(ref)
    out = [h for h in head if h.strip()]
    for title, items in seg_items:
        out.append(title)
        for it in items:
            if it.kind in ("def", "decl") and it.name not in used:
                continue
            if it.kind == "def" and "/kernel/" in it.lines[0][0]:
                out.append(f"@ {it.lines[0][0]}:{it.lines[0][1]}")
                out.extend(f"{ln - it.lines[0][1]}| {t}" for _, ln, t in it.lines)
            else:
                out.extend(t for _, _, t in it.lines if t.strip())
    text = "\n".join(out) + "\n"
    names = {}
    return NUMBERED.sub(lambda m: names.setdefault(m.group(0), f"@n{len(names)}"), text)


def main():
    sys.stdout.write(key_text(sys.stdin.read()))


if __name__ == "__main__":
    main()
