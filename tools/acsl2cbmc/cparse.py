# SPDX-License-Identifier: Apache-2.0
"""C tokenizer for the preprocessed stream and its declarations (typedefs, prototypes)."""

import re

from .ctype import BASE_INT_WORDS, QUALIFIERS, CType
from .errors import CParseError, TranslateError


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
