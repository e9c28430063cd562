# SPDX-License-Identifier: Apache-2.0
"""Front end: preprocess, collect declarations, contracts and logic."""

import os
import re
import subprocess

from .acsl import strip_annotation
from .contracts import TWO_STATE, FuncContract, parse_contract, parse_logic_block
from .cparse import DeclParser, Program, c_tokens
from .errors import CParseError, TranslateError, fail


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


# the repository: tools/acsl2cbmc/frontend.py is three levels below it
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def rel(path):
    try:
        r = os.path.relpath(path, os.getcwd())
        return r if not r.startswith("..") else path
    except ValueError:
        return path
