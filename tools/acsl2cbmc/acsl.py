# SPDX-License-Identifier: Apache-2.0
"""ACSL tokenizer and parser."""

from .errors import fail


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
        e = self.bitand()
        for op in ("|", "^", "-->", "<-->"):
            if self.at(op):
                fail(self.where, f"unsupported ACSL construct: bitwise operator {op!r}")
        return e

    def bitand(self):
        # C's precedence: & binds looser than == (write (a & m) != 0)
        e = self.equality()
        while self.at("&") and not self.at("&", 1):
            self.take()
            e = ("bin", "&", e, self.equality())
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
