#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""acsl2cbmc: translate the kernel's ACSL contracts into C that CBMC checks.

A contract is written once, in ACSL, in the kernel headers. Frama-C/WP proves it; this tool
turns the same text into C functions that a CBMC harness assumes (requires) and asserts
(ensures, behaviours, complete/disjoint behaviours, assigns), so both tools check one contract.

Usage:
  tools/acsl2cbmc.py [--root DIR] [-I DIR]... [--out DIR] [--input FILE]... [--quiet]

Default input: every kernel header and source under ROOT/kernel (preprocessed once with
`gcc -E -C -dD -DCBMC`, which keeps the annotation comments). Output in OUT (default
ROOT/build/proof/cbmc/gen):

  mtc_logic.h        ghost externs, object kinds, one C function per ACSL predicate/logic function
  <F>_contract.h     for every function F with a contract:
                       int  mtc_pre_F(params)            conjunction of the requires clauses
                       void mtc_req_F(params)            asserts each requires clause (callers, stubs)
                       void mtc_post_F(params[, result]) asserts every ensures clause, behaviour,
                                                         complete/disjoint behaviours and the assigns
                                                         frame, against the snapshot (\\old)
  mtc_stubs.c        contract stubs (assert requires, havoc assigns, assume ensures) for the port
                     functions and the callback dispatchers (mt_port_*, mt_invoke*)
  manifest.json      per function: clause counts and the assertion labels

Semantics of the translation (see proofs/cbmc/README.md for the full list):
  * ACSL integers are __int128 in C: every integer read is widened first, so no spec
    expression wraps for the value ranges of the kernel (|x| < 2^100); CBMC's overflow checks
    stay on for the generated code, so an out-of-range spec computation is reported, not hidden.
  * a / b and a % b are computed at the narrowest width that is exact for their operands
    (Translator.divide): 32 or 64 bits when the operands' ranges, derived from the C types
    they are read from, fit; __int128 when a range can leave 64 bits; otherwise 64 bits behind
    an assertion that the operands are in range (a failed assertion, never a wrong value).
  * booleans read from C memory are normalised with `!= 0`.
  * \\old(e) reads memory through the snapshot registry (proofs/cbmc/lib/mtc.c): the harness
    copies every object it allocated (deep: buffers are objects of their own) before the call.
  * \\valid / \\valid_read (p + (a .. b)) -> __CPROVER_w_ok / __CPROVER_r_ok of the byte range
    (true when a > b).
  * \\separated(l1, ..., ln) -> pairwise: different objects, or disjoint byte ranges in the same
    object (exact for the byte ranges named).
  * \\forall / \\exists over `integer i; lo <= i < hi` (or `<=`, or `lo <= i && i < hi`): in an
    asserted position a \\forall becomes one assertion about a nondeterministic i (covers every i,
    however large the range); elsewhere a loop from lo to hi (unwound by CBMC; unwinding
    assertions catch a bound that is too small).
  * assigns: every location of every snapshotted object that no assigns location covers must be
    unchanged (one nondeterministic index per array, so whole arrays are checked); locations are
    evaluated in the pre-state, as in ACSL.
Anything else (\\at, \\let, lemmas, axiomatics, bitwise operators, casts to machine integers, ...)
stops the tool with an error naming the file, function and construct: no clause is ever dropped.
"""

import argparse
import json
import os
import re
import subprocess
import sys

# ----------------------------------------------------------------------------------------------
# errors


class TranslateError(Exception):
    pass


class CParseError(TranslateError):
    """A C declaration the tolerant top-level walk may skip (system headers)."""


def fail(where, msg):
    raise TranslateError(f"{where}: {msg}")


# ----------------------------------------------------------------------------------------------
# C types


class CType:
    """kind: int | bool | void | ptr | array | struct | enum | fn.  `alias` is the typedef
    name used to spell the type in generated code."""

    def __init__(self, kind, **kw):
        self.kind = kind
        self.alias = kw.get("alias")
        self.spell = kw.get("spell")      # C spelling of a base type ("unsigned int")
        self.to = kw.get("to")            # ptr/array target
        self.dim = kw.get("dim")          # array dimension text
        self.name = kw.get("name")        # struct/enum typedef name
        self.fields = kw.get("fields")    # struct: list of (name, CType)
        self.ret = kw.get("ret")          # fn
        self.params = kw.get("params")    # fn
        self.const = kw.get("const", False)

    def copy(self, **changes):
        t = CType.__new__(CType)
        t.__dict__.update(self.__dict__)
        t.__dict__.update(changes)
        return t

    def with_alias(self, alias):
        return self.copy(alias=alias)

    def is_intlike(self):
        return self.kind in ("int", "enum")

    def is_scalar(self):
        return self.kind in ("int", "enum", "bool", "ptr")

    def is_fnptr(self):
        return self.kind == "ptr" and self.to is not None and self.to.kind == "fn"

    def c(self, name="", const_target=False):
        """C declaration of `name` with this type."""
        if self.kind == "ptr":
            if self.to.kind == "fn":
                if self.alias:
                    return f"{self.alias} {name}".strip()
                ps = ", ".join(p.c() for p in self.to.params) or "void"
                return f"{self.to.ret.c()} (*{name})({ps})"
            inner = self.to.c()
            if const_target and not inner.startswith("const "):
                inner = "const " + inner
            if self.alias and not const_target:
                return f"{self.alias} {name}".strip()
            return f"{inner} *{name}".strip()
        if self.kind == "array":
            return self.to.c(f"{name}[{self.dim}]")
        base = self.alias or self.spell or (self.name if self.kind in ("struct", "enum") else None)
        if base is None:
            base = {"bool": "_Bool", "void": "void", "int": "int"}[self.kind]
        if self.const and not base.startswith("const "):
            base = "const " + base
        return f"{base} {name}".strip()

    def __repr__(self):
        return f"CType({self.kind},{self.alias or self.spell or self.name})"


BASE_INT_WORDS = {"char", "short", "int", "long", "signed", "unsigned", "__int128"}
QUALIFIERS = {"const", "volatile", "restrict", "__restrict", "__restrict__", "static", "inline",
              "__inline", "__inline__", "extern", "__extension__", "register", "_Noreturn",
              "__const"}


# ----------------------------------------------------------------------------------------------
# C tokenizer for the preprocessed stream

C_PUNCT = ["...", "<<=", ">>=", "->", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||",
           "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "##"]


class Tok:
    __slots__ = ("kind", "text", "file", "line")

    def __init__(self, kind, text, file, line):
        self.kind, self.text, self.file, self.line = kind, text, file, line

    def __repr__(self):
        return f"{self.kind}:{self.text!r}"


def c_tokens(src):
    """Tokens of preprocessed C: ident, num, str, punct, comment, define."""
    i, n = 0, len(src)
    file, line = "<input>", 1
    at_bol = True
    out = []
    while i < n:
        ch = src[i]
        if ch == "\n":
            line += 1
            i += 1
            at_bol = True
            continue
        if ch in " \t\r\f\v":
            i += 1
            continue
        if at_bol and ch == "#":
            j = src.find("\n", i)
            j = n if j < 0 else j
            directive = src[i:j]
            # a directive may continue on following lines (comments kept by -C)
            m = re.match(r'#\s*(\d+)\s+"([^"]*)"', directive)
            if m:
                line = int(m.group(1))
                file = m.group(2)
                i = j + 1
                at_bol = True
                continue
            m = re.match(r"#\s*define\s+([A-Za-z_]\w*)(\([^)]*\))?\s*(.*)", directive)
            if m:
                out.append(Tok("define", (m.group(1), m.group(2), m.group(3)), file, line))
            i = j
            continue
        at_bol = False
        if src.startswith("/*", i):
            j = src.find("*/", i + 2)
            if j < 0:
                raise TranslateError(f"{file}:{line}: unterminated comment")
            text = src[i:j + 2]
            out.append(Tok("comment", text, file, line))
            line += text.count("\n")
            i = j + 2
            continue
        if src.startswith("//", i):
            j = src.find("\n", i)
            j = n if j < 0 else j
            if src.startswith("//@", i):      # one-line annotation: same as /*@ ... */
                out.append(Tok("comment", "/*@" + src[i + 3:j] + " */", file, line))
            i = j
            continue
        if ch.isalpha() or ch == "_":
            j = i + 1
            while j < n and (src[j].isalnum() or src[j] == "_"):
                j += 1
            out.append(Tok("ident", src[i:j], file, line))
            i = j
            continue
        if ch.isdigit():
            j = i + 1
            while j < n and (src[j].isalnum() or src[j] in "._"):
                j += 1
            out.append(Tok("num", src[i:j], file, line))
            i = j
            continue
        if ch in "\"'":
            j = i + 1
            while j < n and src[j] != ch:
                j += 2 if src[j] == "\\" else 1
            out.append(Tok("str", src[i:j + 1], file, line))
            i = j + 1
            continue
        for p in C_PUNCT:
            if src.startswith(p, i):
                out.append(Tok("punct", p, file, line))
                i += len(p)
                break
        else:
            out.append(Tok("punct", ch, file, line))
            i += 1
    return out


# ----------------------------------------------------------------------------------------------
# C declarations (typedefs, prototypes) of the preprocessed translation unit


class Program:
    def __init__(self):
        self.typedefs = {}        # name -> CType
        self.enum_consts = {}     # name -> value text
        self.macros = {}          # name -> (params, body)
        self.logic = []           # list of LogicDef in order
        self.logic_by_name = {}
        self.ghosts = []          # list of (name, CType)
        self.ghost_arrays = []    # list of (name, element type words, size text)
        self.lemmas = []          # list of (name, expr, where)
        self.skipped = []         # logic declarations over two memory states (WP only)
        self.cvars = {}           # kernel global variables (extern mt_*) -> CType
        self.logic2 = []          # two-state predicates, expanded at each use
        self.keep_file = lambda path: False   # files whose declarations we translate
        self.functions = {}       # name -> FuncContract
        self.func_order = []


class FuncDecl:
    def __init__(self, name, ret, params, static, file, line):
        self.name, self.ret, self.params, self.static = name, ret, params, static
        self.file, self.line = file, line


class DeclParser:
    """Recursive-descent parser for the declarations we need; tolerant of system headers."""

    def __init__(self, prog, toks):
        self.prog = prog
        self.toks = toks
        self.i = 0

    # -- helpers
    def peek(self, k=0):
        j = self.i + k
        return self.toks[j] if j < len(self.toks) else None

    def at(self, text, k=0):
        t = self.peek(k)
        return t is not None and t.kind in ("punct", "ident") and t.text == text

    def take(self, text=None):
        t = self.peek()
        if t is None:
            raise CParseError("unexpected end of input")
        if text is not None and t.text != text:
            raise CParseError(f"{t.file}:{t.line}: expected {text!r}, got {t.text!r}")
        self.i += 1
        return t

    def skip_attributes(self):
        while self.peek() is not None and self.peek().kind == "ident" and self.peek().text in (
                "__attribute__", "__asm__", "__asm", "__declspec", "_Alignas", "__THROW",
                "__wur", "__nonnull"):
            self.take()
            if self.at("("):
                self.skip_balanced("(", ")")

    def skip_balanced(self, o, c):
        depth = 0
        while True:
            t = self.take()
            if t.text == o:
                depth += 1
            elif t.text == c:
                depth -= 1
                if depth == 0:
                    return

    # -- types
    def is_type_start(self, t):
        if t is None or t.kind != "ident":
            return False
        return (t.text in BASE_INT_WORDS or t.text in QUALIFIERS or t.text in (
            "void", "_Bool", "struct", "union", "enum", "float", "double", "__builtin_va_list")
            or t.text in self.prog.typedefs)

    def parse_specifiers(self):
        """Returns a CType for the declaration specifiers, plus storage flags."""
        words, static, const = [], False, False
        result = None
        while True:
            self.skip_attributes()
            t = self.peek()
            if t is None or t.kind != "ident":
                break
            w = t.text
            if w in QUALIFIERS:
                self.take()
                if w == "static":
                    static = True
                if w in ("const", "__const"):
                    const = True
                continue
            if w in ("struct", "union"):
                self.take()
                tag = None
                if self.peek().kind == "ident":
                    tag = self.take().text
                if self.at("{"):
                    fields = self.parse_struct_body()
                    result = CType("struct", name=tag, fields=fields)
                else:
                    result = CType("struct", name=tag, fields=None, spell=f"{w} {tag}")
                continue
            if w == "enum":
                self.take()
                tag = None
                if self.peek().kind == "ident":
                    tag = self.take().text
                if self.at("{"):
                    self.parse_enum_body()
                result = CType("enum", name=tag, spell=f"enum {tag}" if tag else None)
                continue
            if w in BASE_INT_WORDS or w in ("void", "_Bool", "float", "double"):
                if result is not None and not words:
                    break
                words.append(self.take().text)
                continue
            if w in self.prog.typedefs and result is None and not words:
                self.take()
                result = self.prog.typedefs[w].with_alias(w)
                continue
            break
        if words:
            if "float" in words or "double" in words:
                result = CType("float", spell=" ".join(words))
            elif words == ["void"]:
                result = CType("void")
            elif words == ["_Bool"]:
                result = CType("bool", spell="_Bool")
            else:
                result = CType("int", spell=" ".join(words))
        if result is None:
            t = self.peek()
            raise CParseError(f"{t.file}:{t.line}: type expected at {t.text!r}")
        if const:
            result = result.copy(const=True)
        return result, static

    def parse_struct_body(self):
        self.take("{")
        fields = []
        while not self.at("}"):
            base, _ = self.parse_specifiers()
            while True:
                name, t = self.parse_declarator(base)
                if self.at(":"):
                    raise CParseError("bit-fields are not supported")
                fields.append((name, t))
                if self.at(","):
                    self.take()
                    continue
                break
            self.take(";")
        self.take("}")
        return fields

    def parse_enum_body(self):
        self.take("{")
        value = -1
        while not self.at("}"):
            name = self.take().text
            if self.at("="):
                self.take()
                expr = []
                depth = 0
                while not (depth == 0 and (self.at(",") or self.at("}"))):
                    t = self.take()
                    depth += t.text == "("
                    depth -= t.text == ")"
                    expr.append(t.text)
                self.prog.enum_consts[name] = " ".join(expr)
            else:
                self.prog.enum_consts[name] = None
            if self.at(","):
                self.take()
        self.take("}")

    def parse_declarator(self, base):
        """Declarator: pointers, name, arrays, function parameters; (*name)(...) form."""
        t = base
        while self.at("*"):
            self.take()
            t = CType("ptr", to=t)
            while self.peek() and self.peek().text in ("const", "volatile", "restrict",
                                                        "__restrict", "__restrict__"):
                self.take()
        self.skip_attributes()
        if self.at("(") and self.at("*", 1):
            # function pointer: ( * name ) ( params )
            self.take("(")
            self.take("*")
            name = self.take().text if self.peek().kind == "ident" else ""
            self.take(")")
            params = self.parse_params()
            return name, CType("ptr", to=CType("fn", ret=t, params=[p for _, p in params]))
        name = ""
        if self.peek() is not None and self.peek().kind == "ident" and not self.is_type_start(
                self.peek()):
            name = self.take().text
        while self.at("["):
            self.take("[")
            dim = []
            while not self.at("]"):
                dim.append(self.take().text)
            self.take("]")
            t = CType("array", to=t, dim=" ".join(dim))
        if self.at("("):
            params = self.parse_params()
            t = CType("fn", ret=t, params=[p for _, p in params], pnames=None)
            t.param_names = [n for n, _ in params]
        self.skip_attributes()
        return name, t

    def parse_params(self):
        self.take("(")
        params = []
        if self.at("void") and self.at(")", 1):
            self.take()
        while not self.at(")"):
            if self.at("..."):
                self.take()
                params.append(("...", CType("void")))
                continue
            base, _ = self.parse_specifiers()
            name, t = self.parse_declarator(base)
            if t.kind == "array":        # array parameters are pointers
                t = CType("ptr", to=t.to)
            params.append((name, t))
            if self.at(","):
                self.take()
        self.take(")")
        return params

    # -- top level
    def parse_top(self, on_decl):
        """Walk the top level; call on_decl(kind, payload, first_tok) for each declaration
        (kind: 'comment', 'define', 'func', 'other')."""
        while self.peek() is not None:
            t = self.peek()
            if t.kind == "comment":
                self.take()
                on_decl("comment", t, t)
                continue
            if t.kind == "define":
                self.take()
                on_decl("define", t.text, t)
                continue
            if t.text == ";":
                self.take()
                continue
            start = self.i
            try:
                self.parse_one(on_decl)
            except CParseError as e:
                # tolerate exotic system declarations; never ours
                self.i = start
                names = self.skip_declaration()
                if any(n.startswith(("mt_", "Mt")) for n in names) and "/kernel/" in (t.file or ""):
                    raise CParseError(f"{t.file}:{t.line}: cannot parse declaration: {e}")
                on_decl("other", None, t)

    def skip_declaration(self):
        depth = 0
        names = []
        while self.peek() is not None:
            t = self.take()
            if t.kind == "ident":
                names.append(t.text)
            if t.text in ("(", "["):
                depth += 1
            elif t.text in (")", "]"):
                depth -= 1
            elif t.text == "{":
                depth += 1
            elif t.text == "}":
                depth -= 1
                if depth == 0 and not self.at(";") and not (self.peek() and self.peek().kind == "ident"):
                    return names
            elif t.text == ";" and depth == 0:
                return names
        return names

    def parse_one(self, on_decl):
        first = self.peek()
        if self.at("typedef"):
            self.take()
            base, _ = self.parse_specifiers()
            while True:
                name, t = self.parse_declarator(base)
                if t.kind == "struct" and t.name is None:
                    t.name = name
                if t.kind == "enum" and t.name is None:
                    t.name = name
                self.prog.typedefs[name] = t
                if self.at(","):
                    self.take()
                    continue
                break
            self.take(";")
            on_decl("other", None, first)
            return
        # skip leading comments inside a declaration are not expected
        base, static = self.parse_specifiers()
        if self.at(";"):
            self.take()
            on_decl("other", None, first)
            return
        name, t = self.parse_declarator(base)
        if t.kind == "fn":
            fd = FuncDecl(name, t.ret, list(zip(t.param_names, t.params)), static, first.file,
                          first.line)
            if self.at("{"):
                self.skip_balanced("{", "}")
            else:
                while not self.at(";"):
                    self.take()
                self.take(";")
            on_decl("func", fd, first)
            return
        # variable declaration(s): the globals of the translated files may appear in
        # contracts (a static one only in the contracts of its own file's static helpers)
        if self.prog.keep_file(first.file):
            self.prog.cvars[name] = t
        depth = 0
        while True:
            tt = self.take()
            if tt.text in ("(", "{", "["):
                depth += 1
            elif tt.text in (")", "}", "]"):
                depth -= 1
            elif tt.text == ";" and depth == 0:
                break
        on_decl("other", None, first)


# ----------------------------------------------------------------------------------------------
# ACSL tokenizer and parser

A_PUNCT = ["<==>", "==>", "-->", "<-->", "^^", "..", "->", "==", "!=", "<=", ">=", "&&", "||",
           "<<", ">>"]


class ATok:
    __slots__ = ("kind", "text")

    def __init__(self, kind, text):
        self.kind, self.text = kind, text

    def __repr__(self):
        return self.text


def acsl_tokens(text, where):
    out = []
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch.isspace():
            i += 1
            continue
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if ch == "\\" or ch.isalpha() or ch == "_":
            j = i + 1
            while j < n and (text[j].isalnum() or text[j] == "_"):
                j += 1
            out.append(ATok("id", text[i:j]))
            i = j
            continue
        if ch.isdigit():
            j = i + 1
            while j < n and (text[j].isalnum() or text[j] == "_"):
                j += 1
            out.append(ATok("num", text[i:j]))
            i = j
            continue
        if ch in "\"'":
            fail(where, "string/character literals are not supported in ACSL annotations")
        for p in A_PUNCT:
            if text.startswith(p, i):
                out.append(ATok("op", p))
                i += len(p)
                break
        else:
            out.append(ATok("op", ch))
            i += 1
    return out


def strip_annotation(comment):
    body = comment[3:-2]                       # strip /*@ and */
    lines = []
    for ln in body.split("\n"):
        s = ln.lstrip()
        if s.startswith("@") and not s.startswith("@/"):
            s = " " + s[1:]
            lines.append(s)
        else:
            lines.append(ln)
    return "\n".join(lines)


# AST: tuples (tag, ...)


class AParser:
    def __init__(self, toks, where, types):
        self.toks = toks
        self.i = 0
        self.where = where
        self.types = types     # callable: name -> bool (is a type name)

    def peek(self, k=0):
        j = self.i + k
        return self.toks[j] if j < len(self.toks) else None

    def at(self, text, k=0):
        t = self.peek(k)
        return t is not None and t.text == text

    def take(self, text=None):
        t = self.peek()
        if t is None:
            fail(self.where, f"unexpected end of annotation (expected {text!r})")
        if text is not None and t.text != text:
            fail(self.where, f"expected {text!r}, found {t.text!r}")
        self.i += 1
        return t

    def done(self):
        return self.i >= len(self.toks)

    # expressions --------------------------------------------------------------------------
    def expr(self):
        return self.ternary()

    def ternary(self):
        c = self.equiv()
        if self.at("?"):
            self.take()
            a = self.ternary()
            self.take(":")
            b = self.ternary()
            return ("ite", c, a, b)
        return c

    def equiv(self):
        e = self.implies()
        while self.at("<==>"):
            self.take()
            e = ("equiv", e, self.implies())
        return e

    def implies(self):
        e = self.lor()
        if self.at("==>"):
            self.take()
            return ("implies", e, self.implies())
        return e

    def lor(self):
        e = self.land()
        while self.at("||") or self.at("^^"):
            if self.at("^^"):
                fail(self.where, "unsupported ACSL construct: ^^ (xor)")
            self.take()
            e = ("or", e, self.land())
        return e

    def land(self):
        e = self.bitor()
        while self.at("&&"):
            self.take()
            e = ("and", e, self.bitor())
        return e

    def bitor(self):
        e = self.equality()
        for op in ("|", "^", "&", "-->", "<-->"):
            if self.at(op) and not (op == "&" and self.at("&", 1)):
                fail(self.where, f"unsupported ACSL construct: bitwise operator {op!r}")
        return e

    def equality(self):
        e = self.relation()
        while self.at("==") or self.at("!="):
            op = self.take().text
            e = ("rel", [e, op, self.relation()])
        return e

    def relation(self):
        first = self.shift()
        chain = [first]
        while self.peek() is not None and self.peek().text in ("<", "<=", ">", ">="):
            chain.append(self.take().text)
            chain.append(self.shift())
        if len(chain) == 1:
            return first
        return ("rel", chain)

    def shift(self):
        e = self.additive()
        if self.at("<<") or self.at(">>"):
            fail(self.where, "unsupported ACSL construct: shift")
        return e

    def additive(self):
        e = self.mult()
        while self.at("+") or self.at("-"):
            op = self.take().text
            e = ("bin", op, e, self.mult())
        return e

    def mult(self):
        e = self.unary()
        while self.at("*") or self.at("/") or self.at("%"):
            op = self.take().text
            e = ("bin", op, e, self.unary())
        return e

    def is_cast(self):
        if not self.at("("):
            return False
        j = 1
        t = self.peek(j)
        if t is None or t.kind != "id":
            return False
        if not (self.types(t.text) or t.text in ("integer", "const", "unsigned", "signed", "struct",
                                                 "int", "char", "long", "short", "void", "_Bool")):
            return False
        while self.peek(j) is not None and self.peek(j).text != ")":
            if self.peek(j).text not in ("*", "const", "struct", "unsigned", "signed", "int",
                                         "char", "long", "short") and self.peek(j).kind != "id":
                return False
            j += 1
        return True

    def unary(self):
        t = self.peek()
        if t is None:
            fail(self.where, "unexpected end of expression")
        if t.text in ("\\forall", "\\exists"):
            return self.binder()
        if t.text == "!":
            self.take()
            return ("not", self.unary())
        if t.text == "-":
            self.take()
            return ("neg", self.unary())
        if t.text == "+":
            self.take()
            return self.unary()
        if t.text == "~":
            fail(self.where, "unsupported ACSL construct: ~")
        if t.text == "*":
            self.take()
            return ("deref", self.unary())
        if t.text == "&":
            self.take()
            return ("addr", self.unary())
        if self.is_cast():
            self.take("(")
            words = []
            while not self.at(")"):
                words.append(self.take().text)
            self.take(")")
            return ("cast", words, self.unary())
        return self.postfix()

    def postfix(self):
        e = self.primary()
        while True:
            if self.at("["):
                self.take()
                idx = self.range_or_expr()
                self.take("]")
                e = ("index", e, idx)
            elif self.at("."):
                self.take()
                e = ("dot", e, self.take().text)
            elif self.at("->"):
                self.take()
                e = ("arrow", e, self.take().text)
            elif self.at("(") or (self.at("{") and e[0] == "id"):
                if e[0] != "id":
                    fail(self.where, "unsupported call of a non-name")
                labels = []
                if self.at("{"):
                    # memory-state labels of a logic application: P{Pre, Post}(...)
                    self.take("{")
                    while not self.at("}"):
                        t = self.take()
                        if t.text != ",":
                            labels.append(t.text)
                    self.take("}")
                args = []
                if labels and not self.at("("):
                    # P{L1, L2} with no parameters
                    e = ("call", e[1], args, tuple(labels))
                    continue
                self.take("(")
                while not self.at(")"):
                    args.append(self.range_or_expr())
                    if self.at(","):
                        self.take()
                self.take(")")
                e = ("call", e[1], args, tuple(labels)) if labels else ("call", e[1], args)
            else:
                return e

    def range_or_expr(self):
        a = self.expr()
        if self.at(".."):
            self.take()
            b = self.expr()
            return ("range", a, b)
        return a

    def primary(self):
        t = self.take()
        if t.kind == "num":
            return ("num", t.text)
        if t.text == "(":
            e = self.range_or_expr()
            self.take(")")
            return e
        if t.kind == "id":
            w = t.text
            if w == "\\result":
                return ("result",)
            if w == "\\null":
                return ("null",)
            if w == "\\true":
                return ("true",)
            if w == "\\false":
                return ("false",)
            if w == "\\old":
                self.take("(")
                e = self.range_or_expr()
                self.take(")")
                return ("old", e)
            if w == "\\at":
                self.take("(")
                e = self.range_or_expr()
                self.take(",")
                lab = self.take().text
                self.take(")")
                return ("at", e, lab)
            if w in ("\\valid", "\\valid_read"):
                self.take("(")
                e = self.range_or_expr()
                self.take(")")
                return ("valid", w == "\\valid_read", e)
            if w == "\\separated":
                self.take("(")
                locs = []
                while not self.at(")"):
                    locs.append(self.range_or_expr())
                    if self.at(","):
                        self.take()
                self.take(")")
                if len(locs) < 2:
                    fail(self.where, "\\separated needs at least two locations")
                return ("separated", locs)
            if w in ("\\min", "\\max"):
                self.take("(")
                a = self.expr()
                self.take(",")
                b = self.expr()
                self.take(")")
                return ("minmax", w[1:], a, b)
            if w.startswith("\\"):
                fail(self.where, f"unsupported ACSL construct: {w}")
            if w == "sizeof":
                fail(self.where, "unsupported ACSL construct: sizeof")
            return ("id", w)
        fail(self.where, f"unexpected token {t.text!r}")

    def binder(self):
        q = self.take().text
        vars_ = []
        while True:
            words = []
            while self.peek() is not None and self.peek().kind == "id" and self.peek(1) is not None \
                    and self.peek(1).kind == "id":
                words.append(self.take().text)
            while self.at("*"):
                fail(self.where, "unsupported: quantification over pointers")
            name = self.take().text
            if not words:
                if not vars_:
                    fail(self.where, f"quantified variable {name} has no type")
                words = vars_[-1][0].split()
            vars_.append((" ".join(words), name))
            if self.at(","):
                self.take()
                continue
            break
        self.take(";")
        body = self.expr()
        # \forall integer a, b; P is \forall integer a; \forall integer b; P
        kind = "forall" if q == "\\forall" else "exists"
        for v in reversed(vars_[1:]):
            body = (kind, v, body)
        return (kind, vars_[0], body)


# ----------------------------------------------------------------------------------------------
# contracts and logic definitions


class Clause:
    def __init__(self, kind, label, expr, index):
        self.kind, self.label, self.expr, self.index = kind, label, expr, index

    def name(self):
        return self.label if self.label else f"#{self.index}"


class Behavior:
    def __init__(self, name):
        self.name = name
        self.assumes = []
        self.ensures = []


class FuncContract:
    def __init__(self, decl, text, file, line):
        self.decl = decl
        self.text = text
        self.file, self.line = file, line
        self.requires = []
        self.ensures = []
        self.assigns = None        # list of location exprs; [] == \nothing
        self.behaviors = []
        self.complete = []         # list of lists of names
        self.disjoint = []
        self.ghost_def = None      # C text of a ghost (lemma) function


class LogicDef:
    def __init__(self, kind, name, ret, params, body, where, labels=()):
        self.kind, self.name, self.ret, self.params, self.body, self.where = \
            kind, name, ret, params, body, where
        self.labels = tuple(labels)   # two-state definitions: expanded at each use
        self.abstract = False         # declared in an axiomatic block, no definition


def parse_contract(fc, where, is_type):
    toks = acsl_tokens(strip_annotation(fc.text), where)
    p = AParser(toks, where, is_type)
    beh = None
    counters = {"requires": 0, "ensures": 0, "assumes": 0}

    def label_and_expr(kind):
        counters[kind] += 1
        label = None
        if p.peek() is not None and p.peek().kind == "id" and p.at(":", 1) and not p.at("::", 1):
            label = p.take().text
            p.take(":")
        e = p.expr()
        p.take(";")
        return Clause(kind, label, e, counters[kind])

    while not p.done():
        kw = p.take().text
        if kw == "requires":
            if beh is not None:
                fail(where, f"unsupported: requires inside behavior {beh.name}")
            fc.requires.append(label_and_expr("requires"))
        elif kw == "ensures":
            c = label_and_expr("ensures")
            (beh.ensures if beh is not None else fc.ensures).append(c)
        elif kw == "assumes":
            if beh is None:
                fail(where, "assumes outside a behavior")
            beh.assumes.append(label_and_expr("assumes"))
        elif kw == "assigns":
            if beh is not None:
                fail(where, f"unsupported: assigns inside behavior {beh.name} "
                     "(give one assigns clause for the whole function)")
            if fc.assigns is not None:
                fail(where, "unsupported: several assigns clauses (merge them)")
            locs = []
            if p.at("\\nothing"):
                p.take()
            else:
                while True:
                    locs.append(p.range_or_expr())
                    if p.at(","):
                        p.take()
                        continue
                    break
            p.take(";")
            fc.assigns = locs
        elif kw in ("behavior", "behaviour"):
            name = p.take().text
            p.take(":")
            beh = Behavior(name)
            fc.behaviors.append(beh)
        elif kw in ("complete", "disjoint"):
            p.take("behaviors") if p.at("behaviors") else p.take("behaviours")
            names = []
            while not p.at(";"):
                names.append(p.take().text)
                if p.at(","):
                    p.take()
            p.take(";")
            (fc.complete if kw == "complete" else fc.disjoint).append(names)
            beh = None
        else:
            fail(where, f"unsupported contract clause {kw!r}")
    if fc.assigns is None:
        fail(where, "no assigns clause (the kernel's contracts always have one; an implicit "
             "assigns would be 'everything')")


TWO_STATE = re.compile(r"\b[A-Za-z_]\w*\{\s*\w+\s*,\s*\w+\s*\}\s*\(")


def take_labels(p):
    """Consume an optional label list `{L1, L2}` after a logic name; returns the names."""
    names = []
    if p.at("{"):
        p.take("{")
        while not p.at("}"):
            t = p.take().text
            if t != ",":
                names.append(t)
        p.take("}")
    return names


def parse_params(p):
    params = []
    if p.at("("):
        p.take("(")
        while not p.at(")"):
            words = []
            while not (p.at(",") or p.at(")")):
                words.append(p.take().text)
            pname = words[-1]
            ptype = " ".join(words[:-1]).replace(" *", "*").replace("*", " *")
            params.append((pname, ptype.strip()))
            if p.at(","):
                p.take()
        p.take(")")
    return params


def skip_definition(p):
    """Skip the rest of a declaration up to its final `;` (a quantifier's binder `;` is not it)."""
    depth = 0
    binders = []          # depth of each quantifier whose binder `;` is still to come
    while True:
        t = p.take().text
        if t in ("(", "[", "{"):
            depth += 1
        elif t in (")", "]", "}"):
            depth -= 1
        elif t in ("\\forall", "\\exists"):
            binders.append(depth)
        elif t == ";":
            if binders and binders[-1] == depth:
                binders.pop()
            elif depth == 0:
                return


def parse_logic_block(prog, text, where, is_type):
    toks = acsl_tokens(strip_annotation(text), where)
    p = AParser(toks, where, is_type)
    while not p.done():
        kw = p.take().text
        if kw == "ghost":
            words = []
            while not p.at(";"):
                words.append(p.take().text)
            p.take(";")
            if words[-1] == "]" and "[" in words:
                # a ghost array: `ghost T Name[SIZE];` (SIZE a C constant expression)
                k = words.index("[")
                prog.ghost_arrays.append((words[k - 1], " ".join(words[:k - 1]),
                                          " ".join(words[k + 1:-1])))
                continue
            name = words[-1]
            ctype = " ".join(words[:-1])
            prog.ghosts.append((name, ctype))
        elif kw in ("predicate", "logic"):
            ret = None
            if kw == "logic":
                words = [p.take().text]
                while p.at("*"):
                    words.append(p.take().text)
                ret = " ".join(words)
            name = p.take().text
            labels = take_labels(p)
            if len(labels) > 1:
                # relates two memory states: no single-state C twin. A predicate with a
                # plain definition is kept as a macro, expanded at each application
                # P{Pre, Post}(...) in an ensures clause (its \\at(e, L) become \\old(e) or
                # e); anything else (reads, axiomatic) is WP's only, and a contract that
                # uses it fails translation as an unknown predicate.
                start = p.i
                try:
                    params = parse_params(p)
                    if kw != "predicate" or not p.at("="):
                        raise TranslateError("not a plain predicate definition")
                    p.take("=")
                    body = p.expr()
                    p.take(";")
                except TranslateError:
                    p.i = start
                    skip_definition(p)
                    prog.skipped.append(f"{where}: {kw} {name} (two memory states, WP only)")
                    continue
                ld = LogicDef(kw, name, ret, params, body, f"{where}: {kw} {name}", labels)
                prog.logic_by_name[name] = ld
                prog.logic2.append(ld)
                continue
            params = parse_params(p)
            if p.at("reads"):
                fail(where, f"unsupported: reads clause on {name}")
            if not p.at("="):
                fail(where, f"unsupported: {kw} {name} without a definition (axiomatic)")
            p.take("=")
            body = p.expr()
            p.take(";")
            ld = LogicDef(kw, name, ret, params, body, f"{where}: {kw} {name}")
            prog.logic.append(ld)
            prog.logic_by_name[name] = ld
        elif kw == "axiomatic":
            # `axiomatic Name { predicate P; }`: abstract constants, declared and
            # never defined (no axiom: the gate would list one). Each is an environment choice
            # that no function assigns; in the CBMC build it is one nondeterministic value per
            # run (mtc_abstract_<name> in mtc_stubs.c), the same in every state.
            p.take()                      # the block's name
            p.take("{")
            while not p.at("}"):
                dk = p.take().text
                if dk != "predicate":
                    fail(where, f"unsupported in an axiomatic block: {dk!r} (only parameterless "
                         "predicate declarations)")
                ret = None
                name = p.take().text
                if not p.at(";"):
                    fail(where, f"{dk} {name} in an axiomatic block: only a parameterless "
                         "declaration is translated")
                p.take(";")
                ld = LogicDef(dk, name, ret, [], None, f"{where}: {dk} {name} (abstract)")
                ld.abstract = True
                prog.logic.append(ld)
                prog.logic_by_name[name] = ld
            p.take("}")
        elif kw == "lemma":
            name = p.take().text
            if len(take_labels(p)) > 1:
                skip_definition(p)
                prog.skipped.append(f"{where}: lemma {name} (two memory states, WP only)")
                continue
            p.take(":")
            body = p.expr()
            p.take(";")
            prog.lemmas.append((name, body, f"{where}: lemma {name}"))
        else:
            fail(where, f"unsupported global annotation {kw!r} (only predicate, logic, lemma "
                 "and ghost declarations are translated)")


# ----------------------------------------------------------------------------------------------
# translation of terms and predicates to C

INT128 = "__int128"


class LT:
    """Logic-level type of a translated expression."""

    def __init__(self, kind, ctype=None, rng=None):
        self.kind = kind      # int | bool | ptr | struct | fnptr
        self.ctype = ctype    # ptr: the pointer CType; struct: the struct CType
        self.rng = rng        # int: (lo, hi), bounds every value can take, or None (unknown)

    def __repr__(self):
        return f"LT({self.kind})"


U32_MAX = (1 << 32) - 1
U64_MAX = (1 << 64) - 1
I64_MIN = -(1 << 63)
I128_MAX = (1 << 127) - 1
I64_MAX = (1 << 63) - 1


# A C integer literal's digits: hexadecimal, octal (a leading 0) or decimal.
INT_LIT = r"(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)"


def int_value(digits):
    """The value of INT_LIT's digits, read as C reads them."""
    return int(digits, 16 if digits[:2] in ("0x", "0X") else 8 if digits[0] == "0" else 10)


def int_range(ctype):
    """Bounds of a C integer type (x86_64, LP64), or None."""
    if ctype.kind == "bool":
        return (0, 1)
    if ctype.kind == "enum":
        # int or unsigned int, as the compiler chooses for the enumeration's values
        return (-(1 << 31), (1 << 32) - 1)
    words = (ctype.spell or "").split()
    if ctype.kind != "int" or not words:
        return None
    if "__int128" in words:
        bits = 128
    elif "char" in words:
        bits = 8
    elif "short" in words:
        bits = 16
    elif "long" in words:
        bits = 64
    else:
        bits = 32
    if "unsigned" in words:
        return (0, (1 << bits) - 1)
    return (-(1 << (bits - 1)), (1 << (bits - 1)) - 1)


def rng_op(op, ra, rb):
    """Bounds of ra op rb (interval arithmetic; None when unknown)."""
    if ra is None or rb is None:
        return None
    if op == "+":
        return (ra[0] + rb[0], ra[1] + rb[1])
    if op == "-":
        return (ra[0] - rb[1], ra[1] - rb[0])
    if op == "*":
        c = [x * y for x in ra for y in rb]
        return (min(c), max(c))
    if op in ("/", "%") and ra[0] >= 0 and rb[0] >= 1:
        if op == "/":
            return (ra[0] // rb[1], ra[1] // rb[0])
        return (0, min(ra[1], rb[1] - 1))
    return None


def rng_hull(ra, rb):
    if ra is None or rb is None:
        return None
    return (min(ra[0], rb[0]), max(ra[1], rb[1]))


class Ctx:
    """Translation context.
    state: 0 (current memory), 1 (pre-state snapshot), or 'mtc_st' (chosen at run time,
    inside logic functions). env: name -> (C expression, CType or 'integer')."""

    def __init__(self, tr, where, state, env, result=None, allow_old=True):
        self.tr = tr
        self.where = where
        self.state = state
        self.env = env
        self.result = result            # (cexpr, CType) or None
        self.allow_old = allow_old

    def with_state(self, st):
        return Ctx(self.tr, self.where, st, self.env, self.result, self.allow_old)

    def bind(self, name, cexpr, ctype):
        env = dict(self.env)
        env[name] = (cexpr, ctype)
        return Ctx(self.tr, self.where, self.state, env, self.result, self.allow_old)


class Translator:
    def __init__(self, prog):
        self.prog = prog
        self.helpers = []       # generated helper functions (quantifier loops), in order
        self.nq = 0
        self.uid = 0

    # -- types ------------------------------------------------------------------------------
    def ctype_of_words(self, words, where):
        """ACSL type words (logic parameter / cast) -> 'integer' or CType."""
        w = [x for x in words if x != "const"]
        stars = 0
        while w and w[-1] == "*":
            stars += 1
            w = w[:-1]
        name = " ".join(w)
        if name == "integer" and stars == 0:
            return "integer"
        if name in ("boolean", "real"):
            fail(where, f"unsupported logic type {name}")
        if name in self.prog.typedefs:
            t = self.prog.typedefs[name].with_alias(name)
        elif name.startswith("struct "):
            t = CType("struct", name=name[7:], spell=name)
        elif name in ("void",):
            t = CType("void")
        elif all(x in BASE_INT_WORDS for x in name.split()):
            t = CType("int", spell=name)
        elif name == "_Bool":
            t = CType("bool", spell="_Bool")
        else:
            fail(where, f"unknown type {name!r}")
        for _ in range(stars):
            t = CType("ptr", to=t)
        return t

    def resolve(self, t):
        """Follow typedef aliases to the defining CType (struct fields)."""
        if t.kind == "struct" and t.fields is None:
            name = t.name or (t.spell or "").replace("struct ", "")
            for td in self.prog.typedefs.values():
                if td.kind == "struct" and td.name == name and td.fields is not None:
                    return td
        return t

    def field_type(self, st, fname, where):
        st = self.resolve(st)
        if st.kind != "struct" or st.fields is None:
            fail(where, f"field {fname} of a non-struct")
        for n, t in st.fields:
            if n == fname:
                return t
        fail(where, f"struct {st.name} has no field {fname}")

    # -- leaves -----------------------------------------------------------------------------
    def num(self, text, where):
        """An integer literal: its C text and its value (hexadecimal, octal or decimal, as C)."""
        m = re.fullmatch(INT_LIT + r"[uUlL]*", text)
        if not m:
            fail(where, f"unsupported number {text!r}")
        digits = m.group(1)
        v = int_value(digits)
        if v > 0xFFFFFFFFFFFFFFFF:
            fail(where, f"literal {text} does not fit in 64 bits")
        return f"(({INT128}){digits}ull)", v

    def widen(self, cexpr, ctype):
        """C value of a machine type -> logic value."""
        if ctype == "integer":
            return cexpr, LT("int")
        if ctype.kind in ("int", "enum"):
            return f"(({INT128})({cexpr}))", LT("int", rng=int_range(ctype))
        if ctype.kind == "bool":
            return f"(({INT128})(({cexpr}) != 0))", LT("int", rng=(0, 1))
        if ctype.kind == "ptr":
            if ctype.to.kind == "fn":
                return cexpr, LT("fnptr", ctype)
            return cexpr, LT("ptr", ctype)
        if ctype.kind == "array":
            return f"(&({cexpr})[0])", LT("ptr", CType("ptr", to=ctype.to))
        if ctype.kind == "struct":
            return cexpr, LT("struct", ctype)
        fail("?", f"cannot use a value of type {ctype}")

    def mem(self, lvtext, ctx):
        """Read of the C lvalue `lvtext` (sub-expressions already in ctx's state)."""
        if ctx.state == 0:
            return lvtext
        if ctx.state == 1:
            return f"(*MTC_OLD(&({lvtext})))"
        return f"(*MTC_AT({ctx.state}, &({lvtext})))"

    def ghost_read(self, name, ctx):
        if ctx.state == 0:
            return name
        if ctx.state == 1:
            return f"mtc_old_{name}"
        return f"({ctx.state} ? mtc_old_{name} : {name})"

    # -- lvalues ----------------------------------------------------------------------------
    def lval(self, e, ctx):
        """(C lvalue text, CType) for a memory lvalue, or None."""
        tag = e[0]
        w = ctx.where
        if tag == "arrow":
            p, lt = self.term(e[1], ctx)
            if lt.kind != "ptr":
                fail(w, f"-> on a non-pointer ({self.show(e[1])})")
            ft = self.field_type(lt.ctype.to, e[2], w)
            return f"({p})->{e[2]}", ft
        if tag == "dot":
            inner = self.lval(e[1], ctx)
            if inner is None:
                fail(w, f"unsupported: field of a non-lvalue ({self.show(e)})")
            text, t = inner
            ft = self.field_type(t, e[2], w)
            return f"({text}).{e[2]}", ft
        if tag == "index":
            if e[2][0] == "range":
                fail(w, f"a range is only allowed in \\valid, \\separated and assigns "
                     f"({self.show(e)})")
            idx = self.index(e[2], ctx)
            inner = self.lval(e[1], ctx) if e[1][0] in ("arrow", "dot", "index") else None
            if inner is not None and inner[1].kind == "array":
                return f"({inner[0]})[{idx}]", inner[1].to
            p, lt = self.term(e[1], ctx)
            if lt.kind != "ptr":
                fail(w, f"index of a non-pointer ({self.show(e[1])})")
            return f"({p})[{idx}]", self.target(lt.ctype, w)
        if tag == "deref":
            p, lt = self.term(e[1], ctx)
            if lt.kind != "ptr":
                fail(w, f"* of a non-pointer ({self.show(e[1])})")
            return f"(*({p}))", self.target(lt.ctype, w)
        if tag == "id" and e[1] in self.prog.cvars and e[1] not in ctx.env:
            return e[1], self.prog.cvars[e[1]]
        return None

    def target(self, ptype, w):
        t = ptype.to
        if t.kind == "void":
            fail(w, "dereference of a void pointer (cast it first)")
        return t

    def index(self, e, ctx):
        c, lt = self.term(e, ctx)
        if lt.kind != "int":
            fail(ctx.where, f"non-integer index {self.show(e)}")
        return f"(long long)({c})"

    # -- terms ------------------------------------------------------------------------------
    def term(self, e, ctx):
        """Translate a term; returns (C expression, LT)."""
        w = ctx.where
        tag = e[0]
        if tag == "num":
            c, v = self.num(e[1], w)
            return c, LT("int", rng=(v, v))
        if tag == "true":
            return f"(({INT128})1)", LT("int", rng=(1, 1))
        if tag == "false":
            return f"(({INT128})0)", LT("int", rng=(0, 0))
        if tag == "null":
            return "((void *)0)", LT("ptr", CType("ptr", to=CType("void")))
        if tag == "result":
            if ctx.result is None:
                fail(w, "\\result outside an ensures clause of a non-void function")
            return self.widen(*ctx.result)
        if tag == "id":
            name = e[1]
            if name in ctx.env:
                return self.widen(*ctx.env[name])
            for g, gt in self.prog.ghosts:
                if g == name:
                    return self.widen(self.ghost_read(name, ctx), self.ghost_ctype(g))
            if name in self.prog.logic_by_name:
                ld = self.prog.logic_by_name[name]
                if ld.params:
                    fail(w, f"{name} used without arguments")
                return self.call(ld, [], ctx)
            if name in self.prog.enum_consts:
                return f"(({INT128})({name}))", LT("int")
            if name in self.prog.macros:
                params, body = self.prog.macros[name]
                if params is not None:
                    fail(w, f"function-like macro {name} used as a term")
                m = re.fullmatch(r"\(?\s*" + INT_LIT + r"[uUlL]*\s*\)?", body.strip())
                v = int_value(m.group(1)) if m else None
                return f"(({INT128})({name}))", LT("int", rng=(v, v) if m else None)
            if name in self.prog.cvars:
                # a C global variable: an array is its first element's address (the same in
                # every state), a scalar is read in the context's state
                t = self.prog.cvars[name]
                if t.kind == "array":
                    return f"(&({name})[0])", LT("ptr", CType("ptr", to=t.to))
                return self.widen(self.mem(name, ctx), t)
            fail(w, f"unknown identifier {name!r}")
        if tag == "old":
            if not ctx.allow_old:
                fail(w, "\\old outside an ensures clause")
            if ctx.state != 0:
                return self.term(e[1], ctx)
            return self.term(e[1], ctx.with_state(1))
        if tag == "index" and self.ghost_array(e[1]):
            g, et = self.ghost_array(e[1])
            if e[2][0] == "range":
                fail(w, f"a range is only allowed in assigns ({self.show(e)})")
            return self.widen(f"({self.ghost_read(g, ctx)})[{self.index(e[2], ctx)}]",
                              self.ctype_of_words(et.split(), w))
        if tag in ("arrow", "dot", "index", "deref"):
            lv = self.lval(e, ctx)
            text, t = lv
            if t.kind == "struct":
                return text, LT("struct", t)
            if t.kind == "array":
                return f"(&({text})[0])", LT("ptr", CType("ptr", to=t.to))
            return self.widen(self.mem(text, ctx), t)
        if tag == "call":
            name = e[1]
            if (name not in self.prog.logic_by_name and name in self.prog.macros and
                    self.prog.macros[name][0] is not None and len(e) == 3):
                # a function-like C macro of integer arguments (the MT_CALL_* slots): the C
                # compiler expands it over the translated arguments
                params = [x for x in self.prog.macros[name][0].strip("()").split(",") if x.strip()]
                if len(params) != len(e[2]):
                    fail(w, f"macro {name} takes {len(params)} arguments, got {len(e[2])}")
                args = []
                for a in e[2]:
                    c, lt = self.term(a, ctx)
                    self.want(lt, "int", a, w)
                    args.append(c)
                return f"(({INT128})({name}({', '.join(args)})))", LT("int")
            if name not in self.prog.logic_by_name:
                fail(w, f"unknown logic function or predicate {name!r}")
            ld = self.prog.logic_by_name[name]
            if ld.labels or len(e) > 3:
                return self.pred(self.expand(ld, e, ctx), ctx), LT("bool")
            return self.call(ld, e[2], ctx)
        if tag == "at":
            fail(w, f"unsupported ACSL construct: \\at ({self.show(e)}; only inside a "
                 "two-state predicate applied with {Pre, Post} in an ensures clause)")
        if tag == "here":
            return self.term(e[1], ctx.with_state(0))
        if tag == "addr":
            lv = self.lval(e[1], ctx)
            if lv is None:
                fail(w, f"address of a non-lvalue ({self.show(e)})")
            return f"(&({lv[0]}))", LT("ptr", CType("ptr", to=lv[1]))
        if tag == "neg":
            c, lt = self.term(e[1], ctx)
            self.want(lt, "int", e, w)
            return f"(-{c})", LT("int")
        if tag == "bin":
            op = e[1]
            a, la = self.term(e[2], ctx)
            b, lb = self.term(e[3], ctx)
            if la.kind == "ptr" and lb.kind == "int" and op in ("+", "-"):
                return self.ptr_arith(a, la, op, b), la
            if la.kind == "int" and lb.kind == "ptr" and op == "+":
                return self.ptr_arith(b, lb, op, a), lb
            self.want(la, "int", e[2], w)
            self.want(lb, "int", e[3], w)
            if op in ("/", "%"):
                return self.divide(op, a, la, b, lb)
            r = rng_op(op, la.rng, lb.rng)
            if (op == "*" and la.rng is not None and lb.rng is not None and la.rng[0] >= 0
                    and lb.rng[0] >= 0 and U64_MAX < r[1] <= I128_MAX):
                # a product of non-negative values beyond 64 bits: MTC_UMUL128 (lib/mtc.h), the
                # operator itself unless the proof models arithmetic (B11)
                return f"MTC_UMUL128({a}, {b})", LT("int", rng=r)
            return f"({a} {op} {b})", LT("int", rng=r)
        if tag == "cast":
            t = self.ctype_of_words(e[1], w)
            c, lt = self.term(e[2], ctx)
            if t == "integer":
                self.want(lt, "int", e[2], w)
                return c, lt
            if t.kind == "ptr":
                if lt.kind != "ptr":
                    fail(w, f"cast of a non-pointer to {' '.join(e[1])}")
                return f"(({t.c()})({c}))", LT("ptr", t)
            fail(w, f"unsupported: cast to the machine type {' '.join(e[1])} (ACSL casts to C "
                 "integer types wrap; write the arithmetic explicitly)")
        if tag == "ite":
            c = self.pred(e[1], ctx)
            a, la = self.term(e[2], ctx)
            b, lb = self.term(e[3], ctx)
            if la.kind != lb.kind:
                fail(w, f"branches of ?: have different types ({self.show(e)})")
            if la.kind == "int":
                return f"({c} ? {a} : {b})", LT("int", rng=rng_hull(la.rng, lb.rng))
            return f"({c} ? {a} : {b})", la
        if tag == "minmax":
            a, la = self.term(e[2], ctx)
            b, lb = self.term(e[3], ctx)
            self.want(la, "int", e[2], w)
            self.want(lb, "int", e[3], w)
            fn = "mtc_min" if e[1] == "min" else "mtc_max"
            r = None
            if la.rng and lb.rng:
                pick = min if e[1] == "min" else max
                r = (pick(la.rng[0], lb.rng[0]), pick(la.rng[1], lb.rng[1]))
            return f"{fn}({a}, {b})", LT("int", rng=r)
        if tag in ("rel", "and", "or", "not", "implies", "equiv", "valid", "separated",
                   "forall", "exists"):
            return self.pred(e, ctx), LT("bool")
        if tag == "range":
            fail(w, f"a range is only allowed in \\valid, \\separated and assigns ({self.show(e)})")
        fail(w, f"unsupported term {self.show(e)}")

    def divide(self, op, a, la, b, lb):
        """a / b or a % b on ACSL integers, computed at the narrowest exact width.
        ACSL division truncates toward zero, as C's does, so for operands that a C type of
        width W holds, the W-bit operation gives the same value as the __int128 one. CBMC's
        circuit for a 128-bit signed division is many times that of a 64-bit one, and when the
        kernel divides the same values at the same width the solver can share one circuit.
          * both ranges known: the narrowest of unsigned 32, unsigned 64 and signed 64 bits
            that holds them, without a check; __int128 when none does and a range can leave
            the signed and unsigned 64-bit ranges (e.g. ticks * 10^6), through MTC_UDIV128 /
            MTC_UMOD128 when both are non-negative (the operator, or the model of B11);
          * a dividend known to be in (-2^64, 2^64) but not of one sign (a difference of two
            64-bit values) over a known non-negative divisor: unsigned 64 bits, behind an
            assertion that the dividend is not negative;
          * a range not known (a logic function's integer parameter): signed 64 bits, behind an
            assertion that both operands are in [-2^63, 2^63).
        An operand outside its assertion's range is reported as a failed check of the harness
        (mtc_udiv64 / mtc_sdiv64 in proofs/cbmc/lib/mtc.h), never computed wrongly. Every
        narrowing cast is also under CBMC's --conversion-check, so even a wrong range (say, a
        macro whose value differs in the harness build) shows as a failed check."""
        r = rng_op(op, la.rng, lb.rng)
        out = LT("int", rng=r)

        def within(rg, lo, hi):
            return rg is not None and lo <= rg[0] and rg[1] <= hi

        ra, rb = la.rng, lb.rng
        if within(ra, 0, U32_MAX) and within(rb, 0, U32_MAX):
            return f"(({INT128})((unsigned int)({a}) {op} (unsigned int)({b})))", out
        if within(ra, 0, U64_MAX) and within(rb, 0, U64_MAX):
            return (f"(({INT128})((unsigned long long)({a}) {op} (unsigned long long)({b})))",
                    out)
        if within(ra, I64_MIN, I64_MAX) and within(rb, I64_MIN, I64_MAX):
            return f"(({INT128})((long long)({a}) {op} (long long)({b})))", out
        if ra is not None and rb is not None:
            if within(ra, -U64_MAX, U64_MAX) and within(rb, 0, U64_MAX):
                fn = "mtc_udiv64" if op == "/" else "mtc_umod64"
                return f"{fn}({a}, {b})", out
            if within(ra, 0, I128_MAX) and within(rb, 0, I128_MAX):
                fn = "MTC_UDIV128" if op == "/" else "MTC_UMOD128"
                return f"{fn}({a}, {b})", out
            return f"({a} {op} {b})", out
        if any(rg is not None and not within(rg, I64_MIN, I64_MAX) for rg in (ra, rb)):
            return f"({a} {op} {b})", out
        fn = "mtc_sdiv64" if op == "/" else "mtc_smod64"
        return f"{fn}({a}, {b})", out

    def want(self, lt, kind, e, w):
        if lt.kind == "bool" and kind == "int":
            fail(w, f"predicate used as a term: {self.show(e)}")
        if lt.kind != kind:
            fail(w, f"expected an {kind}, got {lt.kind}: {self.show(e)}")

    def ptr_arith(self, p, lt, op, i):
        if lt.ctype.to.kind == "void":
            return f"((void *)((const char *)({p}) {op} (long long)({i})))"
        return f"(({p}) {op} (long long)({i}))"

    def ghost_array(self, e):
        """(name, element type words) when e names a ghost array, else None."""
        if e[0] == "id":
            for g, et, _ in self.prog.ghost_arrays:
                if g == e[1]:
                    return g, et
        return None

    def ghost_ctype(self, name):
        for g, gt in self.prog.ghosts:
            if g == name:
                return self.ctype_of_words(gt.split(), name)
        return None

    def call(self, ld, args, ctx):
        w = ctx.where
        if len(args) != len(ld.params):
            fail(w, f"{ld.name} takes {len(ld.params)} arguments, got {len(args)}")
        cargs = [str(ctx.state) if ctx.state in (0, 1) else ctx.state]
        for (pname, ptype), a in zip(ld.params, args):
            t = self.ctype_of_words(ptype.split(), ld.where)
            c, lt = self.term(a, ctx)
            if t == "integer" or t.kind in ("int", "enum", "bool"):
                self.want(lt, "int", a, w)
            elif t.kind == "ptr":
                if lt.kind not in ("ptr", "fnptr"):
                    fail(w, f"argument {self.show(a)} of {ld.name} is not a pointer")
            cargs.append(c)
        fn = f"mtc_{ld.name}({', '.join(cargs)})"
        if ld.kind == "predicate":
            return fn, LT("bool")
        return fn, LT("int")

    STATE_LABELS = {"Pre": "old", "Old": "old", "Post": "here", "Here": "here"}

    def expand(self, ld, e, ctx):
        """A two-state predicate applied as P{A, B}(args) in an ensures clause: its body with
        the parameters replaced by the arguments and each \\at(x, Li) by \\old(x) (Li bound to
        Pre/Old) or x in the post-state (Li bound to Post/Here)."""
        w = ctx.where
        labels = e[3] if len(e) > 3 else ()
        if len(labels) != len(ld.labels):
            fail(w, f"{ld.name} takes {len(ld.labels)} memory-state labels, got {len(labels)}")
        if len(e[2]) != len(ld.params):
            fail(w, f"{ld.name} takes {len(ld.params)} arguments, got {len(e[2])}")
        lmap = {}
        for formal, actual in zip(ld.labels, labels):
            if actual not in self.STATE_LABELS:
                fail(w, f"unsupported state label {actual} in {ld.name}{{...}} (only Pre, Old, "
                     "Post, Here)")
            lmap[formal] = actual
        if not ctx.allow_old and any(self.STATE_LABELS[a] == "old" for a in lmap.values()):
            fail(w, f"{ld.name}{{{', '.join(labels)}}} outside an ensures clause")
        pmap = dict(zip((n for n, _ in ld.params), e[2]))
        free = set()

        def ids(x):
            if isinstance(x, tuple):
                if x and x[0] == "id":
                    free.add(x[1])
                for y in x:
                    ids(y)
            elif isinstance(x, list):
                for y in x:
                    ids(y)
        ids(list(e[2]))

        def sub(x, bound):
            if isinstance(x, list):
                return [sub(y, bound) for y in x]
            if not isinstance(x, tuple) or not x:
                return x
            tag = x[0]
            if tag == "id":
                return pmap[x[1]] if x[1] in pmap and x[1] not in bound else x
            if tag in ("forall", "exists"):
                v = x[1][1]
                if v in free:
                    fail(w, f"expanding {ld.name}: bound variable {v} would capture an argument")
                return (tag, x[1], sub(x[2], bound | {v}))
            if tag == "at":
                if x[2] not in lmap:
                    fail(w, f"expanding {ld.name}: unknown label {x[2]}")
                return (self.STATE_LABELS[lmap[x[2]]], sub(x[1], bound))
            if tag == "call" and len(x) > 3:
                for lab in x[3]:
                    if lab not in lmap:
                        fail(w, f"expanding {ld.name}: unknown label {lab}")
                return ("call", x[1], sub(x[2], bound), tuple(lmap[lab] for lab in x[3]))
            return tuple(sub(y, bound) if isinstance(y, (tuple, list)) else y for y in x)
        if ld.kind != "predicate":
            fail(w, f"unsupported: two-state logic function {ld.name}")
        return sub(ld.body, frozenset())

    # -- predicates -------------------------------------------------------------------------
    def pred(self, e, ctx):
        """Translate a predicate to a C int expression (0/1), evaluation mode."""
        w = ctx.where
        tag = e[0]
        if tag == "and":
            return f"({self.pred(e[1], ctx)} && {self.pred(e[2], ctx)})"
        if tag == "or":
            return f"({self.pred(e[1], ctx)} || {self.pred(e[2], ctx)})"
        if tag == "not":
            return f"(!{self.pred(e[1], ctx)})"
        if tag == "implies":
            return f"(!{self.pred(e[1], ctx)} || {self.pred(e[2], ctx)})"
        if tag == "equiv":
            return f"({self.pred(e[1], ctx)} == {self.pred(e[2], ctx)})"
        if tag == "true":
            return "1"
        if tag == "false":
            return "0"
        if tag == "rel":
            return self.rel(e, ctx)
        if tag == "valid":
            return self.valid(e, ctx)
        if tag == "separated":
            return self.separated(e, ctx)
        if tag in ("forall", "exists"):
            return self.quant_loop(e, ctx)
        if tag == "old":
            if not ctx.allow_old:
                fail(w, "\\old outside an ensures clause")
            return self.pred(e[1], ctx.with_state(1) if ctx.state == 0 else ctx)
        if tag == "here":
            return self.pred(e[1], ctx.with_state(0))
        if tag == "ite":
            return f"({self.pred(e[1], ctx)} ? {self.pred(e[2], ctx)} : {self.pred(e[3], ctx)})"
        c, lt = self.term(e, ctx)
        if lt.kind == "bool":
            return c
        if lt.kind == "int":
            return f"({c} != 0)"
        if lt.kind in ("ptr", "fnptr"):
            return f"({c} != 0)"
        fail(w, f"not a predicate: {self.show(e)}")

    def rel(self, e, ctx):
        chain = e[1]
        parts = []
        vals = [self.term(x, ctx) for x in chain[0::2]]
        for k, op in enumerate(chain[1::2]):
            (a, la), (b, lb) = vals[k], vals[k + 1]
            if la.kind == "struct" or lb.kind == "struct":
                fail(ctx.where, "unsupported: struct comparison outside an asserted ensures "
                     f"clause ({self.show(e)})")
            if la.kind == "bool" or lb.kind == "bool":
                if op not in ("==", "!="):
                    fail(ctx.where, f"ordering of predicates: {self.show(e)}")
            elif (la.kind in ("ptr", "fnptr")) != (lb.kind in ("ptr", "fnptr")):
                fail(ctx.where, f"comparison of a pointer with an integer: {self.show(e)}")
            if la.kind in ("ptr", "fnptr") and op not in ("==", "!="):
                fail(ctx.where, f"unsupported: ordering of pointers ({self.show(e)})")
            if la.kind in ("ptr", "fnptr"):
                parts.append(f"((const void *)({a}) {op} (const void *)({b}))")
            else:
                parts.append(f"({a} {op} {b})")
        return "(" + " && ".join(parts) + ")"

    # locations: (pointer C expr, element size C expr, lo, hi) ; lo/hi None = single object
    def loc(self, e, ctx):
        w = ctx.where
        if e[0] == "bin" and e[1] == "+" and e[3][0] == "range":
            p, lt = self.term(e[2], ctx)
            if lt.kind != "ptr":
                fail(w, f"range added to a non-pointer: {self.show(e)}")
            lo, llo = self.term(e[3][1], ctx)
            hi, lhi = self.term(e[3][2], ctx)
            self.want(llo, "int", e[3][1], w)
            self.want(lhi, "int", e[3][2], w)
            return self.charp(p, lt), self.esize(p, lt), lo, hi
        if e[0] == "range":
            fail(w, f"a bare range is not a location: {self.show(e)}")
        p, lt = self.term(e, ctx)
        if lt.kind != "ptr":
            fail(w, f"not a location (pointer expected): {self.show(e)}")
        return self.charp(p, lt), self.esize(p, lt), None, None

    def charp(self, p, lt):
        if lt.ctype.to.kind == "void":
            return f"((const char *)({p}))"
        return p

    def esize(self, p, lt):
        if lt.ctype.to.kind == "void":
            return "1"
        return f"sizeof(*({p}))"

    def valid(self, e, ctx):
        fn = "__CPROVER_r_ok" if e[1] else "__CPROVER_w_ok"
        p, esz, lo, hi = self.loc(e[2], ctx)
        if lo is None:
            return f"{fn}({p}, {esz})"
        return (f"(({lo}) > ({hi}) || {fn}(({p}) + (long long)({lo}), "
                f"(__CPROVER_size_t)(({hi}) - ({lo}) + 1) * {esz}))")

    def separated(self, e, ctx):
        locs = [self.loc(x, ctx) for x in e[1]]
        parts = []
        for a in range(len(locs)):
            for b in range(a + 1, len(locs)):
                parts.append(f"mtc_separated({self.locargs(locs[a])}, {self.locargs(locs[b])})")
        return "(" + " && ".join(parts) + ")"

    def locargs(self, l):
        p, esz, lo, hi = l
        if lo is None:
            return f"(const void *)({p}), ({INT128})0, ({INT128})0, ({INT128})({esz})"
        return f"(const void *)({p}), {lo}, {hi}, ({INT128})({esz})"

    # quantifiers ---------------------------------------------------------------------------
    def quant_parts(self, e, ctx):
        """Split `\\forall integer i; G ==> P` / `\\exists integer i; G && P` into the bound
        variable, its C bounds (lo inclusive, hi exclusive) and the rest P."""
        kind, (vtype, vname), body = e
        w = ctx.where
        if vtype not in ("integer", "int", "unsigned", "uint32_t", "uint64_t", "uint8_t",
                         "int32_t", "size_t"):
            fail(w, f"unsupported quantifier type {vtype}")
        if kind == "forall":
            if body[0] != "implies":
                fail(w, f"unsupported \\forall form (expected \\forall {vtype} {vname}; "
                     f"lo <= {vname} < hi ==> P): {self.show(e)}")
            guard, rest = body[1], body[2]
        else:
            if body[0] != "and":
                fail(w, f"unsupported \\exists form (expected \\exists {vtype} {vname}; "
                     f"lo <= {vname} < hi && P): {self.show(e)}")
            guard, rest = body[1], body[2]
            # (a && b) && P : flatten so that the bound is the first conjunct(s)
        conj = []

        def flat(x):
            if x[0] == "and":
                flat(x[1])
                flat(x[2])
            else:
                conj.append(x)
        flat(guard)
        if kind == "exists":
            # the guard may have absorbed part of P: G && P is parsed left-assoc
            pass
        lo = hi = None
        extra = []
        # The first bound of each side found is the loop's range; any further bound conjunct
        # (`0 <= d < q && d < n`) stays a guard of the body, so the range is never replaced.
        for c in conj:
            if c[0] == "rel" and len(c[1]) == 5 and c[1][2] == ("id", vname) and \
                    c[1][1] in ("<=", "<") and c[1][3] in ("<", "<=") and lo is None and hi is None:
                lo = (c[1][0], c[1][1])
                hi = (c[1][4], c[1][3])
            elif c[0] == "rel" and len(c[1]) == 3 and c[1][0] == ("id", vname) and \
                    c[1][1] in ("<", "<=") and hi is None:
                hi = (c[1][2], c[1][1])
            elif c[0] == "rel" and len(c[1]) == 3 and c[1][2] == ("id", vname) and \
                    c[1][1] in ("<=", "<") and lo is None:
                lo = (c[1][0], c[1][1])
            else:
                extra.append(c)
        if lo is None or hi is None:
            fail(w, f"cannot find the bounds of {vname} in {self.show(guard)} (write "
                 f"lo <= {vname} < hi)")
        for c in extra:
            rest = ("implies", c, rest) if kind == "forall" else ("and", c, rest)
        return vname, lo, hi, rest

    def quant_bounds(self, lo, hi, ctx):
        lo_c, llo = self.term(lo[0], ctx)
        hi_c, lhi = self.term(hi[0], ctx)
        self.want(llo, "int", lo[0], ctx.where)
        self.want(lhi, "int", hi[0], ctx.where)
        if lo[1] == "<":
            lo_c = f"({lo_c} + 1)"
        if hi[1] == "<=":
            hi_c = f"({hi_c} + 1)"
        return lo_c, hi_c

    def quant_loop(self, e, ctx):
        """Evaluation-mode quantifier: a helper function with a bounded loop."""
        kind = e[0]
        vname, lo, hi, rest = self.quant_parts(e, ctx)
        self.nq += 1
        fname = f"mtc_q{self.nq}"
        var = f"mtc_{vname}_{self.nq}"
        # the helper takes every variable in scope, and the state
        params = []
        args = []
        inner_env = {}
        for n, (cexpr, ct) in ctx.env.items():
            pn = f"mtc_e{len(params)}"
            if ct == "integer":
                params.append(f"{INT128} {pn}")
            else:
                params.append(ct.c(pn) if ct.kind != "array" else CType("ptr", to=ct.to).c(pn))
            args.append(cexpr)
            inner_env[n] = (pn, ct)
        if ctx.result is not None:
            params.append(ctx.result[1].c("mtc_result"))
            args.append(ctx.result[0])
            result = ("mtc_result", ctx.result[1])
        else:
            result = None
        st_dyn = ctx.state not in (0, 1)
        if st_dyn:
            params.insert(0, "int mtc_st")
            args.insert(0, ctx.state)
        inner = Ctx(self, ctx.where, "mtc_st" if st_dyn else ctx.state, inner_env, result,
                    ctx.allow_old)
        lo_c, hi_c = self.quant_bounds(lo, hi, inner)
        inner = inner.bind(vname, var, "integer")
        body = self.pred(rest, inner)
        if kind == "forall":
            loop = (f"    for ({var} = mtc_lo; {var} < mtc_hi; {var}++) {{\n"
                    f"        if (!{body}) return 0;\n    }}\n    return 1;\n")
        else:
            loop = (f"    for ({var} = mtc_lo; {var} < mtc_hi; {var}++) {{\n"
                    f"        if ({body}) return 1;\n    }}\n    return 0;\n")
        src = (f"/* {ctx.where}: {self.show(e)} */\n"
               f"static int {fname}({', '.join(params) or 'void'})\n{{\n"
               f"    {INT128} mtc_lo = {lo_c};\n    {INT128} mtc_hi = {hi_c};\n"
               f"    {INT128} {var};\n{loop}}}\n")
        self.helpers.append(src)
        return f"{fname}({', '.join(args)})"

    # asserted predicates ---------------------------------------------------------------------
    def assert_pred(self, e, ctx, label, indent):
        """Statements asserting predicate e; a \\forall becomes an assertion about a
        nondeterministic witness, conjunctions and implications are split."""
        pad = " " * indent
        tag = e[0]
        msg = cstr(label)
        if tag == "and":
            return (self.assert_pred(e[1], ctx, label, indent) +
                    self.assert_pred(e[2], ctx, label, indent))
        if tag == "implies":
            return (f"{pad}if ({self.pred(e[1], ctx)}) {{\n" +
                    self.assert_pred(e[2], ctx, label, indent + 4) + f"{pad}}}\n")
        if tag == "ite":
            return (f"{pad}if ({self.pred(e[1], ctx)}) {{\n" +
                    self.assert_pred(e[2], ctx, label, indent + 4) + f"{pad}}} else {{\n" +
                    self.assert_pred(e[3], ctx, label, indent + 4) + f"{pad}}}\n")
        if tag == "old" and ctx.state == 0:
            return self.assert_pred(e[1], ctx.with_state(1), label, indent)
        if tag == "here" and ctx.state == 0:
            return self.assert_pred(e[1], ctx, label, indent)
        if tag == "call" and e[1] in self.prog.logic_by_name and \
                (len(e) > 3 or self.prog.logic_by_name[e[1]].labels):
            return self.assert_pred(self.expand(self.prog.logic_by_name[e[1]], e, ctx), ctx,
                                    label, indent)
        if tag == "forall":
            vname, lo, hi, rest = self.quant_parts(e, ctx)
            self.uid += 1
            var = f"mtc_{vname}_w{self.uid}"
            lo_c, hi_c = self.quant_bounds(lo, hi, ctx)
            inner = ctx.bind(vname, var, "integer")
            return (f"{pad}{{\n{pad}    {INT128} {var} = mtc_nondet_i128();\n"
                    f"{pad}    if ({lo_c} <= {var} && {var} < {hi_c}) {{\n" +
                    self.assert_pred(rest, inner, label, indent + 8) + f"{pad}    }}\n{pad}}}\n")
        if tag == "rel" and len(e[1]) == 3 and e[1][1] in ("==", "!="):
            a, la = self.term(e[1][0], ctx)
            b, lb = self.term(e[1][2], ctx)
            if la.kind == "struct" or lb.kind == "struct":
                if e[1][1] != "==":
                    fail(ctx.where, "unsupported: struct disequality")
                return self.assert_struct_eq(e, ctx, label, indent)
        return f"{pad}__CPROVER_assert({self.pred(e, ctx)}, {msg});\n"

    def assert_struct_eq(self, e, ctx, label, indent):
        """X == \\old(X) for a struct lvalue X: field-wise, one nondeterministic index per
        array (so every element is covered)."""
        lhs_e, rhs_e = e[1][0], e[1][2]
        if ctx.state == 0:
            # X == \\at(X, Post) from a two-state predicate: the post-state is the current one
            lhs_e = lhs_e[1] if lhs_e[0] == "here" else lhs_e
            rhs_e = rhs_e[1] if rhs_e[0] == "here" else rhs_e
        if lhs_e[0] == "old" and rhs_e[0] != "old":
            lhs_e, rhs_e = rhs_e, lhs_e
        if rhs_e[0] != "old" or lhs_e[0] == "old":
            fail(ctx.where, f"unsupported struct comparison (only X == \\old(X)): {self.show(e)}")
        lhs = self.lval(lhs_e, ctx)
        if lhs is None or self.lval(rhs_e[1], ctx) is None or \
                self.lval(rhs_e[1], ctx)[0] != lhs[0]:
            fail(ctx.where, f"unsupported struct comparison (only X == \\old(X)): {self.show(e)}")
        ltext, lt = lhs
        pad = " " * indent
        tname = self.type_name(lt)
        msg = cstr(label)
        code = [f"{pad}{{\n",
                f"{pad}    const {tname} *mtc_now = &({ltext});\n",
                f"{pad}    const {tname} *mtc_was = MTC_OLD(&({ltext}));\n"]
        code.append(self.walk(lt, "(*mtc_now)", "(*mtc_was)", indent + 4, "",
                              lambda n, w_, path, pd: f"{pd}__CPROVER_assert({n} == {w_}, {msg});\n"))
        code.append(f"{pad}}}\n")
        return "".join(code)

    def type_name(self, t):
        if t.alias:
            return t.alias
        for n, td in self.prog.typedefs.items():
            if td is t or (td.kind == "struct" and td.name == t.name and td.fields is not None):
                return n
        fail("?", f"no typedef name for {t}")

    def walk(self, t, now, was, indent, path, leaf):
        """Code visiting every scalar leaf of the objects `now` and `was` (C lvalues of type
        t): leaf(now_leaf, was_leaf, path, pad) gives the statement for one leaf. Arrays get
        one nondeterministic index each."""
        t = self.resolve(t)
        pad = " " * indent
        if t.kind == "struct":
            if t.fields is None:
                fail("?", f"incomplete struct {t}")
            return "".join(self.walk(ft, f"{now}.{fn}", f"{was}.{fn}", indent, f"{path}.{fn}",
                                     leaf) for fn, ft in t.fields)
        if t.kind == "array":
            self.uid += 1
            j = f"mtc_j{self.uid}"
            return (f"{pad}{{\n{pad}    __CPROVER_size_t {j} = mtc_nondet_size();\n"
                    f"{pad}    if ({j} < sizeof({now}) / sizeof(({now})[0])) {{\n" +
                    self.walk(t.to, f"({now})[{j}]", f"({was})[{j}]", indent + 8, f"{path}[]",
                              leaf) + f"{pad}    }}\n{pad}}}\n")
        if t.kind in ("int", "enum", "bool", "ptr"):
            return leaf(now, was, path, pad)
        fail("?", f"unsupported field type {t}")

    # -- assigns ------------------------------------------------------------------------------
    def assigns_loc(self, e, ctx):
        """Assigns location evaluated in the pre-state -> ('ghost', name) or
        (base address, stride, count, width) C expressions."""
        w = ctx.where
        if e[0] == "id" and any(g == e[1] for g, _ in self.prog.ghosts):
            return ("ghost", e[1])
        if e[0] == "index" and self.ghost_array(e[1]):
            g = e[1][1]
            if e[2][0] == "range":
                lo, llo = self.term(e[2][1], ctx)
                hi, lhi = self.term(e[2][2], ctx)
                self.want(llo, "int", e[2][1], w)
                self.want(lhi, "int", e[2][2], w)
                return ("range", f"(const void *)&({g}[(long long)({lo})])",
                        f"(({hi}) - ({lo}) + 1)", f"sizeof({g}[0])")
            return ("one", f"(const void *)&({g}[{self.index(e[2], ctx)}])", f"sizeof({g}[0])")
        if e[0] == "id" and self.ghost_array(e):
            g = e[1]
            return ("one", f"(const void *)&({g}[0])", f"sizeof({g})")
        # find a range index in the lvalue chain
        path = []
        x = e
        while x[0] in ("dot", "arrow", "index"):
            path.append(x)
            x = x[1]
        ranges = [p for p in path if p[0] == "index" and p[2][0] == "range"]
        if len(ranges) > 1:
            fail(w, f"unsupported: two ranges in one assigns location ({self.show(e)})")
        if ranges:
            rnode = ranges[0]
            lo_e, hi_e = rnode[2][1], rnode[2][2]
            lo, llo = self.term(lo_e, ctx)
            hi, lhi = self.term(hi_e, ctx)
            self.want(llo, "int", lo_e, w)
            self.want(lhi, "int", hi_e, w)
            with_lo = self.replace(e, rnode, ("index", rnode[1], lo_e))
            elem = ("index", rnode[1], lo_e)
            lv = self.lval(with_lo, ctx)
            lv_elem = self.lval(elem, ctx)
            if lv is None or lv_elem is None:
                fail(w, f"unsupported assigns location {self.show(e)}")
            count = f"(({hi}) - ({lo}) + 1)"
            if with_lo == elem:
                return ("range", f"(const void *)&({lv[0]})", count, f"sizeof({lv[0]})")
            return ("strided", f"(const void *)&({lv[0]})", f"sizeof({lv_elem[0]})", count,
                    f"sizeof({lv[0]})")
        lv = self.lval(e, ctx)
        if lv is None:
            fail(w, f"unsupported assigns location {self.show(e)}")
        return ("one", f"(const void *)&({lv[0]})", f"sizeof({lv[0]})")

    def replace(self, e, old, new):
        if e is old:
            return new
        if isinstance(e, tuple):
            return tuple(self.replace(x, old, new) if isinstance(x, (tuple, list)) else x
                         for x in e)
        if isinstance(e, list):
            return [self.replace(x, old, new) for x in e]
        return e

    # -- pretty printing ------------------------------------------------------------------------
    def show(self, e):
        if not isinstance(e, tuple):
            return str(e)
        tag = e[0]
        s = self.show
        if tag == "num":
            return e[1]
        if tag == "id":
            return e[1]
        if tag in ("result", "null", "true", "false"):
            return "\\" + tag
        if tag == "old":
            return f"\\old({s(e[1])})"
        if tag == "here":
            return f"\\at({s(e[1])}, Here)"
        if tag == "at":
            return f"\\at({s(e[1])}, {e[2]})"
        if tag == "addr":
            return f"&{s(e[1])}"
        if tag == "bin":
            return f"({s(e[2])} {e[1]} {s(e[3])})"
        if tag == "rel":
            return " ".join(s(x) if isinstance(x, tuple) else x for x in e[1])
        if tag in ("and", "or", "implies", "equiv"):
            op = {"and": "&&", "or": "||", "implies": "==>", "equiv": "<==>"}[tag]
            return f"({s(e[1])} {op} {s(e[2])})"
        if tag == "not":
            return f"!{s(e[1])}"
        if tag == "neg":
            return f"-{s(e[1])}"
        if tag == "arrow":
            return f"{s(e[1])}->{e[2]}"
        if tag == "dot":
            return f"{s(e[1])}.{e[2]}"
        if tag == "index":
            return f"{s(e[1])}[{s(e[2])}]"
        if tag == "deref":
            return f"*{s(e[1])}"
        if tag == "range":
            return f"{s(e[1])} .. {s(e[2])}"
        if tag == "call":
            labs = f"{{{', '.join(e[3])}}}" if len(e) > 3 else ""
            return f"{e[1]}{labs}({', '.join(s(a) for a in e[2])})"
        if tag == "cast":
            return f"({' '.join(e[1])}){s(e[2])}"
        if tag == "ite":
            return f"({s(e[1])} ? {s(e[2])} : {s(e[3])})"
        if tag == "minmax":
            return f"\\{e[1]}({s(e[2])}, {s(e[3])})"
        if tag == "valid":
            return f"\\valid{'_read' if e[1] else ''}({s(e[2])})"
        if tag == "separated":
            return f"\\separated({', '.join(s(x) for x in e[1])})"
        if tag in ("forall", "exists"):
            return f"\\{tag} {e[1][0]} {e[1][1]}; {s(e[2])}"
        return repr(e)


def cstr(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


# ----------------------------------------------------------------------------------------------
# front end: preprocess, collect declarations, contracts and logic


KERNEL_DIRS = ["kernel/include", "kernel/port", "kernel/spec", "kernel/src"]


def default_inputs(root):
    files = []
    for d in ("kernel/include/mt", "kernel/port", "kernel/spec", "kernel/src"):
        p = os.path.join(root, d)
        for f in sorted(os.listdir(p)):
            if f.endswith(".h"):
                files.append(os.path.join(p, f))
    src = os.path.join(root, "kernel/src")
    for f in sorted(os.listdir(src)):
        if f.endswith(".c"):
            files.append(os.path.join(src, f))
    return files


def preprocess(inputs, incdirs, cpp):
    tu = "".join(f'#include "{os.path.abspath(f)}"\n' for f in inputs)
    cmd = cpp.split() + ["-E", "-C", "-dD", "-DCBMC", "-x", "c", "-std=gnu11"]
    for d in incdirs:
        cmd += ["-I", d]
    cmd += ["-"]
    r = subprocess.run(cmd, input=tu, capture_output=True, text=True)
    if r.returncode != 0:
        raise TranslateError("preprocessing failed:\n" + r.stderr)
    return r.stdout


def is_annotation(text):
    return text.startswith("/*@")


def annotation_kind(text):
    body = strip_annotation(text).lstrip()
    # ACSL line comments before the first word (`/*@ // why ... predicate P = ...`) do not
    # decide the kind: skip them, else a logic block would be read as a contract.
    while body.startswith("//"):
        nl = body.find("\n")
        body = "" if nl < 0 else body[nl + 1:].lstrip()
    m = re.match(r"[A-Za-z_\\]+", body)
    word = m.group(0) if m else ""
    if word in ("predicate", "logic", "ghost", "lemma", "axiomatic", "inductive", "type",
                "global"):
        return "global"
    if word in ("loop", "assert", "check", "admit", "invariant", "for"):
        return "code"
    return "contract"


def load_program(inputs, incdirs, cpp, keep_file):
    """keep_file(path) -> True for the files whose annotations we translate."""
    text = preprocess(inputs, incdirs, cpp)
    toks = [t for t in c_tokens(text) if t.kind != "comment" or is_annotation(t.text)]
    prog = Program()
    prog.keep_file = keep_file
    pending = [None]
    global_blocks = []

    def is_type(name):
        return name in prog.typedefs

    def on_decl(kind, payload, tok):
        if kind == "define":
            name, params, body = payload
            prog.macros[name] = (params, body)
            return
        if kind == "comment":
            if not is_annotation(payload.text) or not keep_file(payload.file):
                return
            ak = annotation_kind(payload.text)
            where = f"{rel(payload.file)}:{payload.line}"
            if ak == "global" and "/@" in payload.text:
                ghost_function(prog, payload, where, is_type)
                pending[0] = None
            elif ak == "global":
                parse_logic_block(prog, payload.text, where, is_type)
                pending[0] = None
            elif ak == "contract":
                pending[0] = payload
            else:
                fail(where, "statement annotation at top level")
            return
        if kind == "func" and pending[0] is not None:
            c = pending[0]
            pending[0] = None
            fd = payload
            if fd.static:
                # static helpers of different files may share a name
                base = os.path.splitext(os.path.basename(c.file))[0]
                if fd.name in prog.functions and prog.functions[fd.name].file != c.file:
                    fd.name = f"{fd.name}__{base}"
            if fd.name in prog.functions:
                # the same header seen again; keep the first, but the text must agree
                if prog.functions[fd.name].text != c.text:
                    fail(f"{rel(c.file)}:{c.line}", f"two different contracts for {fd.name}")
                return
            if fd.static and TWO_STATE.search(c.text):
                # an internal helper whose contract relates two memory states (a WP frame
                # fact such as MtSchedKept{Pre, Post}): CBMC checks the public functions,
                # which inline their helpers, so this contract is WP's business only
                prog.skipped.append(f"{rel(c.file)}:{c.line}: contract of static {fd.name} "
                                    "(two memory states, WP only)")
                return
            fc = FuncContract(fd, c.text, c.file, c.line)
            parse_contract(fc, f"{rel(c.file)}:{c.line}: {fd.name}", is_type)
            prog.functions[fd.name] = fc
            prog.func_order.append(fd.name)
            return
        if kind in ("func", "other"):
            if pending[0] is not None and kind == "other":
                c = pending[0]
                fail(f"{rel(c.file)}:{c.line}", "contract not followed by a function declaration")
            pending[0] = None

    DeclParser(prog, toks).parse_top(on_decl)
    return prog


def ghost_function(prog, tok, where, is_type):
    """`/*@ ghost /@ contract @/ <C function definition> */`: a lemma function (WP proves
    its contract; ghost code calls it). Its contract is translated like any other, and its
    definition is emitted into the contract header so a harness can check it."""
    body = strip_annotation(tok.text).strip()
    if not body.startswith("ghost"):
        fail(where, "unsupported ghost annotation")
    body = body[len("ghost"):]
    a = body.find("/@")
    b = body.find("@/", a)
    if a < 0 or b < 0 or body[:a].strip():
        fail(where, "unsupported ghost annotation (expected: ghost /@ contract @/ function)")
    contract = "/*@" + body[a + 2:b] + "*/"
    cdef = body[b + 2:].strip()
    toks = [t for t in c_tokens(cdef) if t.kind != "comment"]
    for t in toks:
        t.file, t.line = tok.file, tok.line
    found = []
    dp = DeclParser(prog, toks)
    try:
        dp.parse_one(lambda kind, payload, first: found.append(payload) if kind == "func" else None)
    except CParseError as e:
        fail(where, f"cannot parse the ghost function: {e}")
    if len(found) != 1 or dp.peek() is not None:
        fail(where, "a ghost annotation must hold exactly one function definition")
    fd = found[0]
    if fd.name in prog.functions:
        return
    fc = FuncContract(fd, contract, tok.file, tok.line)
    fc.ghost_def = cdef
    parse_contract(fc, f"{where}: ghost {fd.name}", is_type)
    prog.functions[fd.name] = fc
    prog.func_order.append(fd.name)


ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rel(path):
    try:
        r = os.path.relpath(path, os.getcwd())
        return r if not r.startswith("..") else path
    except ValueError:
        return path


# ----------------------------------------------------------------------------------------------
# generation


HEADER_NOTE = ("/* Generated by tools/acsl2cbmc.py from the ACSL annotations; do not edit.\n"
               " * The contract is the ACSL text in the kernel headers: change it there. */\n")


def struct_kinds(prog):
    names = []
    for n, t in prog.typedefs.items():
        if t.kind == "struct" and t.fields is not None and n.startswith("mt_"):
            names.append(n)
    return names


def gen_logic(prog, tr, incs):
    out = [HEADER_NOTE, "#ifndef MTC_LOGIC_H\n#define MTC_LOGIC_H\n\n"]
    for h in incs:
        out.append(f'#include "{h}"\n')
    out.append('#include "mtc.h"\n\n')
    out.append("/* ghost variables of the kernel specification (proofs/cbmc/lib/ghost.c) */\n")
    for g, gt in prog.ghosts:
        out.append(f"extern {gt} {g};\nextern {gt} mtc_old_{g};\n")
    for g, gt, n in prog.ghost_arrays:
        out.append(f"extern {gt} {g}[{n}];\nextern {gt} mtc_old_{g}[{n}];\n")
    out.append("\n/* object kinds of the snapshot registry (frame checks walk fields by type) */\n")
    out.append("enum {\n    MTC_K_BYTES = 0,\n")
    for k, n in enumerate(struct_kinds(prog)):
        out.append(f"    MTC_K_{n} = {k + 1},\n")
    out.append("    MTC_K_COUNT\n};\n\n")
    out.append("/* ACSL logic: one C function per predicate / logic function; mtc_st selects the\n"
               " * memory state (0: now, 1: the pre-state snapshot). */\n")
    for ld in prog.logic:
        if ld.abstract:
            ret = "int"
            out.append(f"/* {ld.where}: one value per run, in every state (mtc_stubs.c) */\n"
                       f"{ret} mtc_abstract_{ld.name}(void);\n"
                       f"static {ret} mtc_{ld.name}(int mtc_st)\n{{\n"
                       f"    (void)mtc_st;\n    return mtc_abstract_{ld.name}();\n}}\n\n")
            continue
        env = {}
        params = ["int mtc_st"]
        for pname, ptype in ld.params:
            t = tr.ctype_of_words(ptype.split(), ld.where)
            cn = f"mtc_p_{pname}"
            if t == "integer":
                params.append(f"{INT128} {cn}")
            elif t.kind in ("int", "enum", "bool"):
                params.append(f"{INT128} {cn}")
                t = "integer"
            else:
                params.append(t.c(cn, const_target=True))
                if t.kind == "ptr":
                    t = CType("ptr", to=t.to.copy(const=True))
            env[pname] = (cn, t)
        ctx = Ctx(tr, ld.where, "mtc_st", env, None, allow_old=False)
        start = len(tr.helpers)
        if ld.kind == "predicate":
            body = tr.pred(ld.body, ctx)
            ret = "int"
        else:
            if ld.ret != "integer":
                fail(ld.where, f"unsupported logic return type {ld.ret}")
            body, lt = tr.term(ld.body, ctx)
            tr.want(lt, "int", ld.body, ld.where)
            ret = INT128
        helpers = tr.helpers[start:]
        del tr.helpers[start:]
        out.extend(h + "\n" for h in helpers)
        out.append(f"/* {ld.where} */\nstatic {ret} mtc_{ld.name}({', '.join(params)})\n{{\n"
                   f"    (void)mtc_st;\n    return {body};\n}}\n\n")
    out.append("#endif\n")
    return "".join(out)


def func_env(fc):
    env = {}
    for pname, ptype in fc.decl.params:
        if pname == "...":
            fail(fc.decl.name, "variadic functions are not supported")
        env[pname] = (pname, ptype)
    return env


def result_of(fc):
    if fc.decl.ret.kind == "void":
        return None
    return ("mtc_result", fc.decl.ret)


def param_list(fc, with_result):
    ps = [t.c(n) for n, t in fc.decl.params]
    if with_result and fc.decl.ret.kind != "void":
        ps.append(fc.decl.ret.c("mtc_result"))
    return ", ".join(ps) or "void"


def clause_tag(label):
    """The tag of a post-state clause (label "F: ensures inv" -> inv, "F: ensures ok.status" ->
    ok_status, "F: complete behaviors a, b" -> complete, "F: disjoint ..." -> disjoint,
    "F: assigns" -> assigns). A proof folder that sets CLAUSES checks only the clauses it names:
    its binary is built with -DMTC_CLAUSES -DMTC_CLAUSE_<tag>..., and run.py fails a function
    whose folders' CLAUSES together leave one of its tags out (assumption B17)."""
    what = label.split(": ", 1)[1]
    if what.startswith(("complete ", "disjoint ")):
        return what.split()[0]
    if what.startswith("ensures "):
        what = what[len("ensures "):]
    return re.sub(r"\W", "_", what)


def clause_block(label, code):
    """code, compiled unless the proof selects clauses (MTC_CLAUSES) and not this one."""
    tag = clause_tag(label)
    return (f"#if !defined(MTC_CLAUSES) || defined(MTC_CLAUSE_{tag})\n" + "".join(code) +
            "#endif\n")


def gen_contract(prog, tr, fc, kinds):
    # local names (mtc_j<n>, mtc_<v>_w<n>) count from 0 in each contract header, so a contract
    # added elsewhere leaves this header's text, and the record keys of its proofs, unchanged
    tr.uid = 0
    name = fc.decl.name
    where = f"{rel(fc.file)}:{fc.line}: {name}"
    env = func_env(fc)
    stats = {"requires": 0, "ensures": 0, "behaviors": 0, "assumes": 0, "complete": 0,
             "disjoint": 0, "assigns_locations": 0}
    labels = []
    tr.helpers = []
    body_pre, body_req = [], []
    ctx_pre = Ctx(tr, where, 0, env, None, allow_old=False)
    for c in fc.requires:
        cw = Ctx(tr, f"{where}: requires {c.name()}", 0, env, None, allow_old=False)
        body_pre.append(f"    /* requires {c.name()}: {tr.show(c.expr)} */\n"
                        f"    if (!{tr.pred(c.expr, cw)}) return 0;\n")
        lab = f"{name}: requires {c.name()}"
        body_req.append(f"    __CPROVER_assert({tr.pred(c.expr, cw)}, {cstr(lab)});\n")
        stats["requires"] += 1
    post = []
    res = result_of(fc)
    for c in fc.ensures:
        lab = f"{name}: ensures {c.name()}"
        cw = Ctx(tr, f"{where}: ensures {c.name()}", 0, env, res)
        post.append(clause_block(lab, [f"    /* ensures {c.name()}: {tr.show(c.expr)} */\n",
                                       tr.assert_pred(c.expr, cw, lab, 4)]))
        labels.append(lab)
        stats["ensures"] += 1
    bvars = {}
    for b in fc.behaviors:
        stats["behaviors"] += 1
        v = f"mtc_b_{b.name}"
        bvars[b.name] = v
        conds = []
        for a in b.assumes:
            cw = Ctx(tr, f"{where}: behavior {b.name}: assumes", 1, env, None, allow_old=False)
            conds.append(tr.pred(a.expr, cw))
            stats["assumes"] += 1
        shown = " && ".join(tr.show(a.expr) for a in b.assumes) or "\\true"
        post.append(f"    /* behavior {b.name}: assumes {shown} (pre-state) */\n")
        post.append(f"    int {v} = {' && '.join(conds) if conds else '1'};\n")
    for b in fc.behaviors:
        v = bvars[b.name]
        post.append(f"    if ({v}) {{\n")
        for c in b.ensures:
            lab = f"{name}: ensures {b.name}.{c.name()}"
            cw = Ctx(tr, f"{where}: behavior {b.name}: ensures {c.name()}", 0, env, res)
            post.append(clause_block(lab, [f"        /* ensures {c.name()}: {tr.show(c.expr)} */\n",
                                           tr.assert_pred(c.expr, cw, lab, 8)]))
            labels.append(lab)
            stats["ensures"] += 1
        post.append("    }\n")
    for names in fc.complete:
        names = names or [b.name for b in fc.behaviors]
        for n in names:
            if n not in bvars:
                fail(where, f"complete behaviors: unknown behavior {n}")
        lab = f"{name}: complete behaviors {', '.join(names)}"
        post.append(clause_block(lab, [f"    __CPROVER_assert({' || '.join(bvars[n] for n in names)}, "
                                       f"{cstr(lab)});\n"]))
        labels.append(lab)
        stats["complete"] += 1
    for names in fc.disjoint:
        names = names or [b.name for b in fc.behaviors]
        for n in names:
            if n not in bvars:
                fail(where, f"disjoint behaviors: unknown behavior {n}")
        lab = f"{name}: disjoint behaviors {', '.join(names)}"
        post.append(clause_block(lab, [f"    __CPROVER_assert({' + '.join(bvars[n] for n in names)} "
                                       f"<= 1, {cstr(lab)});\n"]))
        labels.append(lab)
        stats["disjoint"] += 1
    for b in fc.behaviors:
        post.append(f"    (void){bvars[b.name]};\n")

    # assigns: covers macro + frame walk over the registry + ghost frame
    cw = Ctx(tr, f"{where}: assigns", 1, env, None)
    cover_terms = []
    ghosts_assigned = set()
    for l in fc.assigns:
        r = tr.assigns_loc(l, cw)
        stats["assigns_locations"] += 1
        if r[0] == "ghost":
            ghosts_assigned.add(r[1])
            continue
        args = ", ".join(r[1:])
        cover_terms.append(f"mtc_in_{r[0]}((const void *)(mtc_a), (__CPROVER_size_t)(mtc_n), "
                           f"{args}) /* {tr.show(l)} */")
    frame_fn = f"mtc_frame_{name}"
    fparams = param_list(fc, True)
    fargs = [n for n, _ in fc.decl.params] + (["mtc_result"] if res else [])
    covers = " || \\\n    ".join(cover_terms) if cover_terms else "0"
    frame = [f"/* assigns {', '.join(tr.show(l) for l in fc.assigns) or chr(92) + 'nothing'}:\n"
             f" * every other location of every snapshotted object is unchanged. */\n",
             f"#define MTC_COVERS(mtc_a, mtc_n) ( \\\n    {covers})\n",
             f"static void {frame_fn}({fparams}{', ' if fparams != 'void' else ''}int mtc_obj)\n{{\n"]
    frame[-1] = frame[-1].replace("(void, int mtc_obj)", "(int mtc_obj)")
    for n, _ in fc.decl.params:
        frame.append(f"    (void){n};\n")
    if res:
        frame.append("    (void)mtc_result;\n")
    for g, _, n in prog.ghost_arrays:
        lab = cstr(f"{name}: assigns ({g})")
        frame.append(f"    if (mtc_obj == 0) {{\n"
                     f"        __CPROVER_size_t mtc_k = mtc_nondet_size();\n"
                     f"        if (mtc_k < (__CPROVER_size_t)({n}) && "
                     f"!MTC_COVERS(&{g}[mtc_k], sizeof({g}[0])))\n"
                     f"            __CPROVER_assert({g}[mtc_k] == mtc_old_{g}[mtc_k], {lab});\n"
                     f"    }}\n")
    frame.append("    if (mtc_obj >= mtc_nobjs) return;\n")
    frame.append("    const mtc_obj_t *mtc_o = &mtc_objs[mtc_obj];\n")
    # One nondeterministic element of the object; a single object (count 1, every struct the
    # harnesses build) uses the constant 0, so that symex resolves the element statically and
    # field accesses stay field-sensitive (a symbolic element index turns every access into a
    # byte extraction at a symbolic offset of the whole object: millions of SAT variables).
    frame.append("    __CPROVER_size_t mtc_e = mtc_o->count == 1u ? (__CPROVER_size_t)0u "
                 ": mtc_nondet_size();\n")
    frame.append("    if (mtc_e >= mtc_o->count) return;\n")
    frame.append("    switch (mtc_o->kind) {\n")
    frame.append("    case MTC_K_BYTES: {\n"
                 "        const unsigned char *mtc_now = (const unsigned char *)mtc_o->orig + mtc_e;\n"
                 "        const unsigned char *mtc_was = (const unsigned char *)mtc_o->copy + mtc_e;\n"
                 f"        if (!MTC_COVERS(mtc_now, 1)) __CPROVER_assert(*mtc_now == *mtc_was, "
                 f"{cstr(name + ': assigns (bytes)')});\n"
                 "        break;\n    }\n")
    for k in kinds:
        frame.append(f"    case MTC_K_{k}: {{\n"
                     f"        const {k} *mtc_now = (const {k} *)mtc_o->orig + mtc_e;\n"
                     f"        const {k} *mtc_was = (const {k} *)mtc_o->copy + mtc_e;\n")
        def leaf(n, w_, path, pd, k=k):
            lab = cstr(f"{name}: assigns ({k}{path})")
            return (f"{pd}if (!MTC_COVERS(&({n}), sizeof({n}))) "
                    f"__CPROVER_assert({n} == {w_}, {lab});\n")
        frame.append(tr.walk(prog.typedefs[k], "(*mtc_now)", "(*mtc_was)", 8, "", leaf))
        frame.append("        break;\n    }\n")
    frame.append("    default:\n        __CPROVER_assert(0, \"snapshot: unknown object kind\");\n")
    frame.append("    }\n}\n#undef MTC_COVERS\n\n")

    lab = f"{name}: assigns"
    code = [f"    /* assigns */\n"]
    for i in range(MTC_MAX_OBJS):
        code.append(f"    {frame_fn}({', '.join(fargs + [str(i)])});\n")
    for g, _ in prog.ghosts:
        if g not in ghosts_assigned:
            code.append(f"    __CPROVER_assert({g} == mtc_old_{g}, "
                        f"{cstr(name + ': assigns (' + g + ')')});\n")
    post.append(clause_block(lab, code))
    labels.append(lab)

    helpers = "".join(h + "\n" for h in tr.helpers)
    tr.helpers = []
    guard = f"MTC_CONTRACT_{name.upper()}_H"
    ghost = ""
    if fc.ghost_def:
        ghost = (f"/* the ghost (lemma) function itself, from its annotation */\n"
                 f"{fc.ghost_def}\n\n")
    text = [HEADER_NOTE, f"/* {where} */\n", f"#ifndef {guard}\n#define {guard}\n\n",
            '#include "mtc_logic.h"\n\n', ghost, helpers,
            f"/* requires (conjunction; the harness assumes it) */\n"
            f"static int mtc_pre_{name}({param_list(fc, False)})\n{{\n",
            *[f"    (void){n};\n" for n, _ in fc.decl.params],
            *body_pre, "    return 1;\n}\n\n",
            f"/* requires, one assertion per clause (for callers and stubs) */\n"
            f"static void mtc_req_{name}({param_list(fc, False)})\n{{\n",
            *[f"    (void){n};\n" for n, _ in fc.decl.params],
            *body_req, "}\n\n", *frame,
            f"/* ensures, behaviours and assigns; \\old reads the snapshot (mtc_snapshot). A\n"
            f" * coverage build of a proof that sets COVER_DEFINES = -DMTC_COVER_ONLY leaves them out\n"
            f" * (they only feed assertions, which the coverage run drops: assumption B5). */\n"
            f"static void mtc_post_{name}({param_list(fc, True)})\n{{\n",
            "#if !defined(MTC_COVER_ONLY)\n", *post, "#else\n",
            *[f"    (void){n};\n" for n in fargs], "#endif\n", "}\n\n#endif\n"]
    return "".join(text), stats, labels


MTC_MAX_OBJS = 6
STUB_PREFIXES = ("mt_port_", "mt_invoke", "mt_mission_invoke", "mt_bus_invoke", "mt_seq_recheck")
STUB_SKIP = ("mt_port_halt",)   # hand-written: reaching it is an error (assert(0))


def gen_abstract(ld):
    """An abstract predicate (axiomatic declaration): chosen once, nondeterministically, on its
    first read, then the same for the rest of the run."""
    return (f"/* {ld.where} */\nint mtc_abstract_{ld.name}(void)\n{{\n"
            f"    static int mtc_chosen;\n    static int mtc_value;\n"
            f"    if (!mtc_chosen) {{\n        mtc_value = mtc_nondet_bool();\n"
            f"        mtc_chosen = 1;\n"
            f"    }}\n    return mtc_value;\n}}\n\n")


def gen_stub(prog, tr, fc):
    """Contract stub: assert requires, evaluate behaviour assumptions, havoc the assigns,
    nondet result, assume ensures. \\old is supported for ghost variables and for memory
    that is not assigned."""
    name = fc.decl.name
    where = f"{rel(fc.file)}:{fc.line}: {name} (stub)"
    env = func_env(fc)
    res = result_of(fc)
    out = [f"/* {where}: contract stub */\n{fc.decl.ret.c(name)}({param_list(fc, False)})\n{{\n"]
    for g, gt in prog.ghosts:
        out.append(f"    {gt} mtc_pre_{g} = {g};\n")
    # a ghost array's pre-call copy only where an ensures clause names the array
    ens_text = " ".join(tr.show(c.expr) for c in fc.ensures + [c for b in fc.behaviors
                                                                 for c in b.ensures])
    arrays = [(g, gt, n) for g, gt, n in prog.ghost_arrays
              if re.search(r"\b" + re.escape(g) + r"\b", ens_text)]
    for g, gt, n in arrays:
        out.append(f"    {gt} mtc_pre_{g}[{n}];\n    __CPROVER_array_copy(mtc_pre_{g}, {g});\n")
    for c in fc.requires:
        cw = Ctx(tr, f"{where}: requires {c.name()}", 0, env, None, allow_old=False)
        out.append(f"    __CPROVER_assert({tr.pred(c.expr, cw)}, "
                   f"{cstr(name + ': requires ' + c.name())});\n")
    bvars = {}
    for b in fc.behaviors:
        cw = Ctx(tr, f"{where}: behavior {b.name}", 0, env, None, allow_old=False)
        conds = [tr.pred(a.expr, cw) for a in b.assumes] or ["1"]
        bvars[b.name] = f"mtc_b_{b.name}"
        out.append(f"    int mtc_b_{b.name} = {' && '.join(conds)};\n")
    assigned = []
    for l in fc.assigns:
        if l[0] == "id" and any(g == l[1] for g, _ in prog.ghosts):
            out.append(f"    __CPROVER_havoc_object(&{l[1]});\n")
            assigned.append(l[1])
        elif l[0] == "index" and tr.ghost_array(l[1]) and l[2][0] != "range":
            g, et = tr.ghost_array(l[1])
            cw = Ctx(tr, f"{where}: assigns", 0, env, None, allow_old=False)
            out.append(f"    {{ {tr.ctype_of_words(et.split(), where).c('mtc_h')}; "
                       f"__CPROVER_havoc_object(&mtc_h); {g}[{tr.index(l[2], cw)}] = mtc_h; }}\n")
        elif l[0] == "deref" and l[1][0] == "id" and l[1][1] in env:
            pt = env[l[1][1]][1]
            if pt.kind != "ptr":
                fail(where, f"assigns {tr.show(l)}: not a pointer parameter")
            out.append(f"    {{ {pt.to.c('mtc_h')}; __CPROVER_havoc_object(&mtc_h); "
                       f"*({l[1][1]}) = mtc_h; }}\n")
        else:
            fail(where, f"stub: unsupported assigns location {tr.show(l)}")
    if res:
        out.append(f"    {fc.decl.ret.c('mtc_result')};\n    __CPROVER_havoc_object(&mtc_result);\n")
        if fc.decl.ret.kind == "bool":
            out.append("    mtc_result = mtc_nondet_bool();\n")
    # \old in a stub: ghosts only (their pre-call values are in mtc_pre_<g>)
    tr_old = StubTranslator(tr.prog, prog.ghosts)
    for c in fc.ensures:
        cw = Ctx(tr_old, f"{where}: ensures {c.name()}", 0, env, res)
        out.append(f"    __CPROVER_assume({tr_old.pred(c.expr, cw)}); /* ensures {c.name()} */\n")
    for b in fc.behaviors:
        for c in b.ensures:
            cw = Ctx(tr_old, f"{where}: behavior {b.name}: ensures {c.name()}", 0, env, res)
            out.append(f"    if ({bvars[b.name]}) __CPROVER_assume({tr_old.pred(c.expr, cw)});"
                       f" /* {b.name}.{c.name()} */\n")
    for g, _ in prog.ghosts:
        out.append(f"    (void)mtc_pre_{g};\n")
    for g, _, _ in arrays:
        out.append(f"    (void)mtc_pre_{g};\n")
    if res:
        out.append("    return mtc_result;\n")
    out.append("}\n\n")
    return "".join(out)


class StubTranslator(Translator):
    """\\old inside a stub: the ghosts' values at the call (locals mtc_pre_<g>)."""

    def __init__(self, prog, ghosts):
        super().__init__(prog)

    def ghost_read(self, name, ctx):
        if ctx.state == 0:
            return name
        if ctx.state == 1:
            return f"mtc_pre_{name}"
        fail(ctx.where, "dynamic state in a stub")

    def mem(self, lvtext, ctx):
        if ctx.state == 0:
            return lvtext
        fail(ctx.where, "stub: \\old of memory is not supported (only of ghost variables)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--root", default=ROOT)
    ap.add_argument("-I", dest="incs", action="append", default=None,
                    help="include directory (default: the kernel's)")
    ap.add_argument("--input", action="append", default=None,
                    help="file to translate (default: every kernel header and source)")
    ap.add_argument("--out", default=None)
    ap.add_argument("--cpp", default="gcc")
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)
    root = os.path.abspath(args.root)
    incs = [os.path.abspath(d) for d in (args.incs or [os.path.join(root, d) for d in KERNEL_DIRS])]
    inputs = [os.path.abspath(f) for f in (args.input or default_inputs(root))]
    out = os.path.abspath(args.out or os.path.join(root, "build/proof/cbmc/gen"))
    keep_dirs = [os.path.dirname(f) for f in inputs] + incs

    def keep_file(path):
        if not path or path.startswith("<"):
            return False
        ap_ = os.path.abspath(path)
        return any(ap_.startswith(d.rstrip("/") + "/") for d in keep_dirs)

    try:
        prog = load_program(inputs, incs, args.cpp, keep_file)
        tr = Translator(prog)
        kinds = struct_kinds(prog)
        # headers the generated code includes: the public umbrella plus private headers seen
        hdrs = []
        for f in inputs:
            if f.endswith(".h"):
                base = os.path.basename(f)
                d = os.path.dirname(f)
                if os.path.basename(d) == "mt":
                    base = "mt/" + base
                if base not in hdrs:
                    hdrs.append(base)
        logic = gen_logic(prog, tr, hdrs)
        results = {}
        texts = {}
        for fname in prog.func_order:
            fc = prog.functions[fname]
            text, stats, labels = gen_contract(prog, tr, fc, kinds)
            texts[fname] = text
            results[fname] = {"file": rel(fc.file), "line": fc.line, "static": fc.decl.static,
                              "stats": stats, "labels": labels,
                              "tags": sorted({clause_tag(lab) for lab in labels})}
        stubs = [HEADER_NOTE, '#include "mtc_logic.h"\n\n']
        stubs.extend(gen_abstract(ld) for ld in prog.logic if ld.abstract)
        stubbed = []
        for fname in prog.func_order:
            fc = prog.functions[fname]
            if fname.startswith(STUB_PREFIXES) and fname not in STUB_SKIP:
                stubs.append(gen_stub(prog, Translator(prog), fc))
                stubbed.append(fname)
    except TranslateError as e:
        print(f"acsl2cbmc: error: {e}", file=sys.stderr)
        return 2
    os.makedirs(out, exist_ok=True)

    def write(name, text):
        path = os.path.join(out, name)
        old = None
        if os.path.exists(path):
            with open(path) as f:
                old = f.read()
        if old != text:
            with open(path, "w") as f:
                f.write(text)

    write("mtc_logic.h", logic)
    for fname, text in texts.items():
        write(f"{fname}_contract.h", text)
    write("mtc_stubs.c", "".join(stubs))
    write("manifest.json", json.dumps({"functions": results, "stubs": stubbed,
                                       "logic": [ld.name for ld in prog.logic],
                                       "ghosts": [g for g, _ in prog.ghosts] +
                                                 [g for g, _, _ in prog.ghost_arrays]}, indent=1) + "\n")
    if not args.quiet:
        tot = 0
        print(f"acsl2cbmc: {len(prog.logic)} logic definitions, {len(prog.ghosts)} ghosts, "
              f"{len(results)} contracts -> {rel(out)}")
        for fname, r in results.items():
            s = r["stats"]
            n = s["requires"] + s["ensures"] + s["assumes"] + s["complete"] + s["disjoint"] + \
                (1 if True else 0)
            tot += n
            print(f"  {fname:28s} {n:3d} clauses translated: {s['requires']} requires, "
                  f"{s['ensures']} ensures, {s['behaviors']} behaviors ({s['assumes']} assumes), "
                  f"{s['complete']} complete, {s['disjoint']} disjoint, assigns "
                  f"({s['assigns_locations']} locations)"
                  f"{'  [static helper]' if r['static'] else ''}"
                  f"{'  [stub]' if fname in stubbed else ''}")
        print(f"acsl2cbmc: {tot} clauses translated, none dropped")
        for ld in prog.logic2:
            print(f"  two-state predicate, expanded at each use: {ld.where}")
        for sk in prog.skipped:
            print(f"  not translated (WP only): {sk}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
