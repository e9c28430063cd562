# SPDX-License-Identifier: Apache-2.0
"""Translation of ACSL terms and predicates to C (Translator)."""

import re

from .ctype import BASE_INT_WORDS, CType
from .errors import fail


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
I32_MIN = -(1 << 31)
I32_MAX = (1 << 31) - 1
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
    if op == "&" and ra[0] >= 0 and rb[0] >= 0:
        return (0, min(ra[1], rb[1]))
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
            if op == "&" and not all(rg is not None and rg[0] >= 0 for rg in (la.rng, lb.rng)):
                # the C operator on the two's complement of a wider type equals ACSL's only
                # where both operands are non-negative; that is the only use supported
                fail(w, f"unsupported: bitwise & on an operand not known to be non-negative "
                     f"({self.show(e)})")
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
          * both ranges known: the narrowest of unsigned 32, signed 32, unsigned 64 and signed
            64 bits that holds them (and the quotient), without a check; __int128 when none
            does and a range can leave the signed and unsigned 64-bit ranges (e.g. ticks *
            10^6), through MTC_UDIV128 / MTC_UMOD128 when both are non-negative (the
            operator, or the model of B11);
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
        if (within(ra, I32_MIN, I32_MAX) and within(rb, I32_MIN, I32_MAX)
                and not (ra[0] == I32_MIN and rb[0] <= -1 <= rb[1])):
            # signed 32 bits, the width of the kernel's int32_t arithmetic (INT_MIN / -1, the
            # one quotient that leaves it, excluded by the ranges)
            return f"(({INT128})((int)({a}) {op} (int)({b})))", out
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
        return fn, LT("int", rng=ld.rng)

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
