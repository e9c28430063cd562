# SPDX-License-Identifier: Apache-2.0
"""Contracts and logic definitions: their parse from the annotation text."""

import re

from .acsl import AParser, acsl_tokens, strip_annotation
from .errors import TranslateError, fail


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
        self.rng = None               # a logic function's value bounds, once its body is read


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


def quantifies_pointers(p):
    """Whether the expression ahead opens with a quantifier whose binder names a pointer."""
    if not (p.at("\\forall") or p.at("\\exists")):
        return False
    j = 1
    while p.peek(j) is not None and p.peek(j).text != ";":
        if p.peek(j).text == "*":
            return True
        j += 1
    return False


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
            if quantifies_pointers(p):
                skip_definition(p)
                prog.skipped.append(f"{where}: lemma {name} (over pointers, WP only)")
                continue
            body = p.expr()
            p.take(";")
            prog.lemmas.append((name, body, f"{where}: lemma {name}"))
        else:
            fail(where, f"unsupported global annotation {kw!r} (only predicate, logic, lemma "
                 "and ghost declarations are translated)")
