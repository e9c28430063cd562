# SPDX-License-Identifier: Apache-2.0
"""acsl2cbmc: translate the kernel's ACSL contracts into C that CBMC checks.

A contract is written once, in ACSL, in the kernel headers. Frama-C/WP proves it; this tool
turns the same text into C functions that a CBMC harness assumes (requires) and asserts
(ensures, behaviours, complete/disjoint behaviours, assigns), so both tools check one contract.

Usage:
  python3 tools/acsl2cbmc [--root DIR] [-I DIR]... [--out DIR] [--input FILE]... [--quiet]

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
  * a & b (bitwise and) where both operands' ranges are known and non-negative (a logic
    function's value range is its body's, e.g. a table of constants): the C operator on
    __int128, which equals ACSL's there.
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
Lemmas are not translated (WP proves them; those over two states or pointers are listed as
skipped). Anything else (\\at, \\let, axiomatics, |, ^, shifts, casts to machine integers, ...)
stops the tool with an error naming the file, function and construct: no clause is ever dropped.
"""

import argparse
import json
import os
import sys

if not __package__:
    # run as `python3 tools/acsl2cbmc`: sys.path[0] is this folder; import the package from
    # tools/ instead, so that each of its modules is loaded once, under the package's name
    _PKG_DIR = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [p for p in sys.path if os.path.abspath(p) != _PKG_DIR]
    sys.path.insert(0, os.path.dirname(_PKG_DIR))

from acsl2cbmc.errors import TranslateError  # noqa: E402
from acsl2cbmc.frontend import KERNEL_DIRS, ROOT, default_inputs, load_program, rel  # noqa: E402
from acsl2cbmc.generate import (HEADER_NOTE, STUB_PREFIXES, STUB_SKIP, clause_tag,  # noqa: E402
                                gen_abstract, gen_contract, gen_logic, gen_stub, struct_kinds)
from acsl2cbmc.translate import Translator  # noqa: E402


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
