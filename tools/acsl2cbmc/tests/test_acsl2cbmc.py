# SPDX-License-Identifier: Apache-2.0
"""Tests of the translator tools/acsl2cbmc (pytest: tools/test_acsl2cbmc.sh, `make cbmc-test`).

1. A small sample contract (predicate, logic function, \\exists, \\forall, \\old, \\valid,
   \\separated, behaviours, assigns with a range) is translated; the generated C is checked
   for the expected pieces, and CBMC proves the sample function against it.
2. Mutations of the sample are caught under the clause's own label: a mutated ensures
   (`+ 1` -> `+ 2`), and an implementation writing a location outside the assigns clause.
3. Unsupported ACSL makes the translator fail loudly (exit 2, the construct named).
4. The kernel: a copy of kernel/ with one ensures clause mutated (mt_bring_commit, behaviour
   ok: `\\result == MT_OK` -> `\\result == MT_E_FULL`) is rejected by CBMC (assertion
   "mt_bring_commit: ensures ok.status") and by Frama-C/WP (goal
   mt_bring_commit_ok_ensures_status not proved), while the unmutated copy passes both.
5. A two-state predicate P{L1, L2} applied as P{Pre, Post}(x) in an ensures clause, and C
   globals in contracts, on a second sample: proved, and a changed scalar or struct field is
   caught under the clause's label.
   Skipped (with a message) when frama-c is not installed; SKIP_WP=1 skips the WP half.
7. Divisions at the narrowest exact width (class Division): the generated width for each kind
   of operand range, exact quotients and remainders (negative operands included), wrong
   quotients caught, and an operand outside a checked range reported, not computed wrongly.
6. The keys of the recorded verdicts (CBMC property and coverage records, B10): equal for
   copies of the tree at two other paths and for the repository itself, changed by an option
   and by a comment line added to a header; the property key also by a comment in
   Makefile.common, which leaves the coverage key as it is; run.py's own computation of both
   keys (input_keys) gives the make targets' digests. run.py's replay
   (RecordReplay): recorded from a passing run, replayed only for its digest, and a record
   that disagrees with a fresh property run (CBMC_RECORD=properties) fails the harness.

Everything runs on copies under build/proof/cbmc/test/; kernel/ is never modified. conftest.py
writes build/proof/cbmc/test/summary.json (read by tools/proof_report.py).
"""

import json
import os
import re
import shutil
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.dirname(HERE)                       # the package: python3 tools/acsl2cbmc
ROOT = os.path.dirname(os.path.dirname(TOOL))
WORK = os.path.join(ROOT, "build", "proof", "cbmc", "test")
BIN = os.path.join(ROOT, ".tools", "bin")
LIB = os.path.join(ROOT, "proofs", "cbmc", "lib")
CHECKS = ["--bounds-check", "--pointer-check", "--pointer-primitive-check",
          "--pointer-overflow-check", "--signed-overflow-check", "--unsigned-overflow-check",
          "--conversion-check", "--div-by-zero-check", "--undefined-shift-check",
          "--unwinding-assertions", "--no-malloc-may-fail"]

SAMPLE_H = r"""
#include <stdint.h>
#include <stdbool.h>

#define MT_COUNTER_CAP_MAX 1000u

typedef struct {
    uint32_t n;       /* items stored */
    uint32_t hits;    /* not written by push */
    uint8_t *buf;
    uint32_t cap;
} mt_counter_t;

/*@ predicate MtCounterInv(mt_counter_t *c) =
        \valid(c) && 1 <= c->cap <= MT_COUNTER_CAP_MAX && c->n <= c->cap &&
        \valid(c->buf + (0 .. c->cap - 1)) && \separated(c, c->buf + (0 .. c->cap - 1));

    logic integer MtCounterRoom(mt_counter_t *c) = c->cap - c->n;

    predicate MtCounterHas(mt_counter_t *c, integer v) =
        \exists integer i; 0 <= i < c->n && c->buf[i] == v;
*/

/*@ requires inv: MtCounterInv(c);
    assigns c->n, c->buf[0 .. c->cap - 1];
    ensures inv: MtCounterInv(c);
    ensures kept: \forall integer i; 0 <= i < \old(c->n) ==> c->buf[i] == \old(c->buf[i]);
    behavior room:
      assumes MtCounterRoom(c) > 0;
      ensures status: \result == 0;
      ensures grown: c->n == \old(c->n) + 1;
      ensures stored: c->buf[\old(c->n)] == v && MtCounterHas(c, v);
    behavior full:
      assumes MtCounterRoom(c) == 0;
      ensures status: \result == 2;
      ensures same: c->n == \old(c->n);
    complete behaviors;
    disjoint behaviors;
*/
int mt_counter_push(mt_counter_t *c, uint8_t v);
"""

SAMPLE_C = r"""
#include "mt_counter.h"

int mt_counter_push(mt_counter_t *c, uint8_t v)
{
    if (c->n >= c->cap) {
        return 2;
    }
    c->buf[c->n] = v;
    c->n++;
    return 0;
}
"""

SAMPLE_HARNESS = r"""
#include "mtc_logic.h"
#include "mt_counter_push_contract.h"

void harness(void)
{
    mt_counter_t *c = (mt_counter_t *)mtc_alloc(sizeof(mt_counter_t), 1u, MTC_K_mt_counter_t);
    /* capacities 1..2: MtCounterHas is a bounded loop over the stored items, and CBMC runs
     * with --unwind 3 and unwinding assertions */
    __CPROVER_assume(c->cap >= 1u && c->cap <= 2u);
    c->buf = (uint8_t *)mtc_alloc(1u, c->cap, MTC_K_BYTES);
    uint8_t v = mtc_nondet_u8();
    __CPROVER_assume(mtc_pre_mt_counter_push(c, v));
    mtc_snapshot();
    int res = mt_counter_push(c, v);
    mtc_post_mt_counter_push(c, v, res);
}
"""


def translate(inputs, incs, out):
    cmd = [sys.executable, TOOL, "--out", out]
    for f in inputs:
        cmd += ["--input", f]
    for d in incs:
        cmd += ["-I", d]
    return subprocess.run(cmd, capture_output=True, text=True)


def cbmc_failures(goto_srcs, incs, workdir, extra=(), defines=()):
    """Compile and run CBMC; returns (failed property descriptions, total properties)."""
    gb = os.path.join(workdir, "h.goto")
    cc = subprocess.run([os.path.join(BIN, "goto-cc"), "-DCBMC", *defines, "--function", "harness",
                         "-o", gb]
                        + [f"-I{d}" for d in incs] +
                        # ghost.c's array sizes (mt_spec.h, which reads mt/config.h)
                        [f"-I{os.path.join(ROOT, d)}" for d in ("kernel/include", "kernel/spec")] +
                        goto_srcs, capture_output=True, text=True)
    if cc.returncode != 0:
        raise AssertionError("goto-cc failed:\n" + cc.stdout + cc.stderr)
    r = subprocess.run([os.path.join(BIN, "cbmc"), gb, "--unwind", "3", "--json-ui", *CHECKS,
                        *extra], capture_output=True, text=True)
    if r.returncode not in (0, 10):
        raise AssertionError("cbmc failed:\n" + r.stderr[-3000:])
    failed, total = [], 0
    for m in json.loads(r.stdout):
        for x in m.get("result", []):
            total += 1
            if x["status"] != "SUCCESS":
                failed.append(x["description"])
    return failed, total


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


class Sample(unittest.TestCase):
    """The translator on a self-contained sample contract."""

    def setUp(self):
        self.dir = os.path.join(WORK, "sample", self.id().split(".")[-1])
        shutil.rmtree(self.dir, ignore_errors=True)
        self.src = os.path.join(self.dir, "src")
        self.out = os.path.join(self.dir, "gen")
        write(os.path.join(self.src, "mt_counter.h"), SAMPLE_H)
        write(os.path.join(self.src, "mt_counter.c"), SAMPLE_C)
        write(os.path.join(self.dir, "harness.c"), SAMPLE_HARNESS)

    def run_sample(self, header=SAMPLE_H, impl=SAMPLE_C):
        write(os.path.join(self.src, "mt_counter.h"), header)
        write(os.path.join(self.src, "mt_counter.c"), impl)
        t = translate([os.path.join(self.src, "mt_counter.h")], [self.src], self.out)
        self.assertEqual(t.returncode, 0, t.stderr)
        srcs = [os.path.join(self.dir, "harness.c"), os.path.join(self.src, "mt_counter.c"),
                os.path.join(LIB, "mtc.c"), os.path.join(LIB, "ghost.c")]
        return cbmc_failures(srcs, [self.src, self.out, LIB], self.dir)

    def test_translation_output(self):
        t = translate([os.path.join(self.src, "mt_counter.h")], [self.src], self.out)
        self.assertEqual(t.returncode, 0, t.stderr)
        self.assertRegex(t.stdout, r"mt_counter_push\s+\d+ clauses translated: 1 requires, "
                                   r"7 ensures, 2 behaviors \(2 assumes\), 1 complete, 1 disjoint")
        self.assertIn("none dropped", t.stdout)
        with open(os.path.join(self.out, "mt_counter_push_contract.h")) as f:
            c = f.read()
        with open(os.path.join(self.out, "mtc_logic.h")) as f:
            logic = f.read()
        # requires -> a predicate the harness assumes; ensures -> labelled assertions
        self.assertIn("static int mtc_pre_mt_counter_push(mt_counter_t *c, uint8_t v)", c)
        for lab in ("ensures inv", "ensures kept", "ensures room.status", "ensures room.grown",
                    "ensures room.stored", "ensures full.status", "ensures full.same",
                    "complete behaviors room, full", "disjoint behaviors room, full",
                    "assigns (mt_counter_t.hits)", "assigns (bytes)"):
            self.assertIn(f'"mt_counter_push: {lab}"', c)
        # behaviours: assumes evaluated in the pre-state, ensures guarded by them
        self.assertIn("int mtc_b_room = ((mtc_MtCounterRoom(1, c) > ((__int128)0ull)));", c)
        # \old reads the snapshot; \forall in an ensures is one nondeterministic witness
        self.assertIn("(*MTC_OLD(&((c)->n)))", c)
        self.assertIn("mtc_nondet_i128()", c)
        # assigns: c->n one location, c->buf[0 .. cap-1] a range evaluated in the pre-state
        self.assertIn("mtc_in_one((const void *)(mtc_a), (__CPROVER_size_t)(mtc_n), "
                      "(const void *)&((c)->n), sizeof((c)->n))", c)
        self.assertIn("mtc_in_range(", c)
        # logic: integers in __int128, \exists as a bounded loop, \valid/\separated
        self.assertIn("static __int128 mtc_MtCounterRoom(int mtc_st, const mt_counter_t *mtc_p_c)", logic)
        self.assertRegex(logic, r"for \(mtc_i_\d+ = mtc_lo; mtc_i_\d+ < mtc_hi; mtc_i_\d+\+\+\)")
        self.assertIn("__CPROVER_w_ok(", logic)
        self.assertIn("mtc_separated(", logic)
        # the manifest names every label
        with open(os.path.join(self.out, "manifest.json")) as f:
            man = json.load(f)
        self.assertIn("mt_counter_push: ensures room.grown",
                      man["functions"]["mt_counter_push"]["labels"])

    def test_line_comment_before_logic(self):
        # a logic block whose first line is an ACSL line comment is still a logic block
        header = SAMPLE_H + ("/*@ // a note before the first word\n"
                             "    predicate MtCounterEmpty(mt_counter_t *c) = c->n == 0;\n"
                             "*/\n")
        write(os.path.join(self.src, "mt_counter.h"), header)
        t = translate([os.path.join(self.src, "mt_counter.h")], [self.src], self.out)
        self.assertEqual(t.returncode, 0, t.stderr)
        with open(os.path.join(self.out, "mtc_logic.h")) as f:
            self.assertIn("mtc_MtCounterEmpty(", f.read())

    def test_cbmc_proves_sample(self):
        failed, total = self.run_sample()
        self.assertEqual(failed, [])
        self.assertGreater(total, 100)

    def test_mutated_ensures_caught_by_label(self):
        mutated = SAMPLE_H.replace("ensures grown: c->n == \\old(c->n) + 1;",
                                   "ensures grown: c->n == \\old(c->n) + 2;")
        self.assertNotEqual(mutated, SAMPLE_H)
        failed, _ = self.run_sample(header=mutated)
        self.assertEqual(failed, ["mt_counter_push: ensures room.grown"])

    def test_assigns_violation_caught(self):
        bad = SAMPLE_C.replace("c->n++;", "c->n++;\n    c->hits++;")
        failed, _ = self.run_sample(impl=bad)
        self.assertIn("mt_counter_push: assigns (mt_counter_t.hits)", failed)
        self.assertNotIn("mt_counter_push: ensures room.grown", failed)

    def test_wrong_implementation_caught(self):
        bad = SAMPLE_C.replace("c->buf[c->n] = v;", "c->buf[c->n] = (uint8_t)(v ^ 1u);")
        failed, _ = self.run_sample(impl=bad)
        # `stored` is a conjunction: one assertion per conjunct, both under its label
        self.assertEqual(sorted(set(failed)), ["mt_counter_push: ensures room.stored"])


class Unsupported(unittest.TestCase):
    """Constructs outside the subset stop the translator (exit 2), naming the construct."""

    CASES = {
        "at": ("ensures e: c->n == \\at(c->n, Pre);", r"\\at"),
        "let": ("ensures e: \\let k = c->n; k == 0;", r"\\let"),
        "bitwise": ("ensures e: (c->n | 1) == 0;", "bitwise operator '\\|'"),
        "bitwise_signed": ("ensures e: ((c->n - 5) & 1) == 0;",
                           "bitwise & on an operand not known to be non-negative"),
        "machine_cast": ("ensures e: (uint8_t)c->n == 0;", "cast to the machine type"),
        "unbounded_exists": ("requires e: \\exists integer i; c->buf[i] == 0 && i == 0;",
                             "cannot find the bounds"),
        "reads": None,
        "no_assigns": None,
        "axiomatic": None,
        "terminates": ("terminates c->n == 0;", "unsupported contract clause 'terminates'"),
        "unknown_name": ("ensures e: Undefined(c);", "unknown logic function"),
    }

    def translate_contract(self, name, contract, extra_logic=""):
        d = os.path.join(WORK, "unsupported", name)
        shutil.rmtree(d, ignore_errors=True)
        h = ("#include <stdint.h>\ntypedef struct { uint32_t n; uint8_t *buf; } mt_c_t;\n"
             f"{extra_logic}\n/*@ {contract} */\nint mt_c_f(mt_c_t *c);\n")
        write(os.path.join(d, "c.h"), h)
        return translate([os.path.join(d, "c.h")], [d], os.path.join(d, "gen"))

    def test_cases(self):
        base = "requires v: \\valid(c);\n    assigns \\nothing;\n    "
        for name, case in self.CASES.items():
            with self.subTest(name):
                if name == "reads":
                    r = self.translate_contract(
                        name, base + "ensures e: P(c);",
                        "/*@ predicate P(mt_c_t *c) reads c->n; */")
                    want = "reads clause"
                elif name == "no_assigns":
                    r = self.translate_contract(name, "ensures e: c->n == 0;")
                    want = "no assigns clause"
                elif name == "axiomatic":
                    r = self.translate_contract(
                        name, base + "ensures e: c->n == 0;",
                        "/*@ axiomatic A { logic integer F(integer x); } */")
                    # only parameterless predicate declarations (abstract constants) translate
                    want = "unsupported in an axiomatic block: 'logic'"
                else:
                    r = self.translate_contract(name, base + case[0])
                    want = case[1]
                self.assertEqual(r.returncode, 2, r.stdout + r.stderr)
                self.assertRegex(r.stderr, want)
                self.assertIn("acsl2cbmc: error:", r.stderr)


class BitwiseAnd(unittest.TestCase):
    """a & b on operands known to be non-negative: a C fact, with the range a logic function's
    body gives its value (a table of constants) carried to its uses."""

    def test_translated(self):
        d = os.path.join(WORK, "bitwise_and")
        shutil.rmtree(d, ignore_errors=True)
        h = ("#include <stdint.h>\ntypedef struct { uint32_t n; } mt_c_t;\n"
             "/*@ logic integer Flags(integer id) = id == 3 ? 0x05 : id == 7 ? 0x02 : 0x00;\n"
             "    predicate Loc(integer id) = (Flags(id) & 0x01) != 0; */\n"
             "/*@ requires v: \\valid(c);\n    assigns \\nothing;\n"
             "    ensures odd: \\result == ((c->n & 1) != 0);\n"
             "    ensures loc: Loc(c->n) ==> \\result == 1; */\nint mt_c_f(mt_c_t *c);\n")
        write(os.path.join(d, "c.h"), h)
        r = translate([os.path.join(d, "c.h")], [d], os.path.join(d, "gen"))
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(d, "gen", "mtc_logic.h")) as f:
            self.assertIn("(mtc_Flags(mtc_st, mtc_p_id) & ((__int128)0x01ull))", f.read())


TWO_STATE_H = r"""
#include <stdint.h>

typedef struct {
    int32_t a;
    int32_t b[2];
} mt_pair_t;

typedef struct {
    uint32_t n;
    uint32_t hits;
    mt_pair_t p[3];
} mt_box_t;

extern uint8_t mt_scratch[4];

/*@ predicate Kept{L1, L2}(mt_box_t *x) =
        \at(x->hits, L1) == \at(x->hits, L2) &&
        \forall integer i; 0 <= i < 3 ==> \at(x->p[i], L1) == \at(x->p[i], L2);

    predicate Sep(mt_box_t *x, uint8_t *s) = \separated(x, s + (0 .. 3));
*/

/*@ requires v: \valid(x) && Sep(x, &mt_scratch[0]) && \separated(x, mt_scratch + (0 .. 3));
    assigns x->n, mt_scratch[0 .. 3];
    ensures kept: Kept{Pre, Post}(x);
    ensures counted: x->n == \old(x->n) / 2;
*/
void mt_box_f(mt_box_t *x);
"""

TWO_STATE_C = r"""
#include "mt_box.h"

uint8_t mt_scratch[4];

void mt_box_f(mt_box_t *x)
{
    mt_scratch[x->n % 4u] = 1u;
    x->n = x->n / 2u;
}
"""

TWO_STATE_HARNESS = r"""
#include "mtc_logic.h"
#include "mt_box_f_contract.h"

void harness(void)
{
    mt_box_t *x = (mt_box_t *)mtc_alloc(sizeof(mt_box_t), 1u, MTC_K_mt_box_t);
    __CPROVER_assume(mtc_pre_mt_box_f(x));
    mtc_snapshot();
    mt_box_f(x);
    mtc_post_mt_box_f(x);
}
"""


class TwoState(unittest.TestCase):
    """A predicate over two memory states applied as P{Pre, Post}(...) in an ensures clause
    (expanded: \\at(e, Pre) reads the snapshot, \\at(e, Post) the current state, struct
    equality field by field), and C globals in contracts (`&g[0]`, `g + (a .. b)`)."""

    def run_box(self, impl=TWO_STATE_C):
        d = os.path.join(WORK, "two-state", self.id().split(".")[-1])
        shutil.rmtree(d, ignore_errors=True)
        write(os.path.join(d, "src", "mt_box.h"), TWO_STATE_H)
        write(os.path.join(d, "src", "mt_box.c"), impl)
        write(os.path.join(d, "harness.c"), TWO_STATE_HARNESS)
        t = translate([os.path.join(d, "src", "mt_box.h")], [os.path.join(d, "src")],
                      os.path.join(d, "gen"))
        self.assertEqual(t.returncode, 0, t.stderr)
        self.assertIn("two-state predicate, expanded at each use", t.stdout)
        srcs = [os.path.join(d, "harness.c"), os.path.join(d, "src", "mt_box.c"),
                os.path.join(LIB, "mtc.c"), os.path.join(LIB, "ghost.c")]
        return cbmc_failures(srcs, [os.path.join(d, "src"), os.path.join(d, "gen"), LIB], d)

    def test_passes(self):
        failed, total = self.run_box()
        self.assertEqual(failed, [])
        self.assertGreater(total, 10)

    def test_scalar_change_caught(self):
        failed, _ = self.run_box(TWO_STATE_C.replace("x->n = x->n / 2u;",
                                                     "x->n = x->n / 2u;\n    x->hits++;"))
        self.assertIn("mt_box_f: ensures kept", failed)

    def test_struct_change_caught(self):
        failed, _ = self.run_box(TWO_STATE_C.replace("x->n = x->n / 2u;",
                                                     "x->n = x->n / 2u;\n    x->p[2].b[1]++;"))
        self.assertIn("mt_box_f: ensures kept", failed)
        self.assertNotIn("mt_box_f: ensures counted", failed)


DIV_H = r"""
#include <stdint.h>

/*@ logic integer MtHalf(integer v) = v / 2;
    logic integer MtRem(integer v) = v % 1000;
*/

/*@ requires nz: b >= 1;
    assigns \nothing;
    ensures q: \result == a / b;
    ensures r: a % b == a - \result * b;
*/
uint32_t mt_q32(uint32_t a, uint32_t b);

/*@ requires nz: c >= 1;
    requires ord: a >= b;
    assigns \nothing;
    ensures q: \result == (a - b) / c;
*/
uint64_t mt_q64(uint64_t a, uint64_t b, uint64_t c);

/*@ assigns \nothing;
    ensures q: \result == x / 7;
    ensures rem: MtRem(x) == x - (x / 1000) * 1000;
*/
int32_t mt_qs(int32_t x);

/*@ assigns \nothing;
    ensures half: \result == MtHalf(x);
*/
int64_t mt_half(int64_t x);

/*@ assigns \nothing;
    ensures half: \result == MtHalf(x * 2);
*/
uint64_t mt_half_u(uint64_t x);

/*@ requires nz: h >= 1;
    assigns \nothing;
    ensures wide: \result <= (t * 1000) / h;
*/
uint64_t mt_wide(uint64_t t, uint32_t h);
"""

DIV_C = r"""
#include "mt_div.h"

uint32_t mt_q32(uint32_t a, uint32_t b) { return a / b; }
uint64_t mt_q64(uint64_t a, uint64_t b, uint64_t c) { return (a - b) / c; }
int32_t mt_qs(int32_t x) { return (int32_t)((int64_t)x / 7); }
int64_t mt_half(int64_t x) { return x / 2; }
uint64_t mt_half_u(uint64_t x) { return x; }
"""

DIV_HARNESS = r"""
#include "mtc_logic.h"
#include "mt_q32_contract.h"
#include "mt_q64_contract.h"
#include "mt_qs_contract.h"
#include "mt_half_contract.h"
#include "mt_half_u_contract.h"

/* Concrete operands: the test is about the values the translation computes (widths, signs,
 * truncation toward zero, 64-bit extremes), not about the solver. */
#define Q32(a, b) if (mtc_pre_mt_q32(a, b)) { mtc_post_mt_q32(a, b, mt_q32(a, b)); }
#define Q64(a, b, c) if (mtc_pre_mt_q64(a, b, c)) { mtc_post_mt_q64(a, b, c, mt_q64(a, b, c)); }
#define QS(x) if (mtc_pre_mt_qs(x)) { mtc_post_mt_qs(x, mt_qs(x)); }
#define HALF(x) if (mtc_pre_mt_half(x)) { mtc_post_mt_half(x, mt_half(x)); }
#define HALF_U(x) if (mtc_pre_mt_half_u(x)) { mtc_post_mt_half_u(x, mt_half_u(x)); }

void harness(void)
{
    mtc_snapshot();
    Q32(7u, 2u) Q32(5u, 7u) Q32(0xFFFFFFFFu, 1u) Q32(0xFFFFFFFFu, 0xFFFFFFFFu)
    Q64(0xFFFFFFFFFFFFFFFFull, 0ull, 3ull) Q64(10ull, 3ull, 7ull) Q64(10ull, 10ull, 1ull)
    QS(-13) QS(13) QS(-1) QS(-2147483647 - 1) QS(0x7FFFFFFF) QS(-1999)
    HALF(-3) HALF(5) HALF(-9223372036854775807ll - 1) HALF(0x7FFFFFFFFFFFFFFFll)
    HALF_U(5ull) HALF_U(0x3FFFFFFFFFFFFFFFull)
    HALF_U(0x4000000000000000ull) /* MtHalf(2^63): outside the checked signed range */
}
"""


CALLS_H = r"""
#include <stdint.h>
#include "mt_spec.h"

/*@ requires slot: slot < MT_CALL_SLOTS;
    assigns MtCalls[slot];
    ensures counted: MtCalls[slot] == MtCount64(\old(MtCalls[slot]), 1);
*/
void mt_invoke_t(uint32_t slot);

/*@ predicate OthersKept{L1, L2}(integer i) = \forall integer k; 0 <= k < 4 ==> k != i ==>
        \at(MtCalls[MT_CALL_TASK(k)], L2) == \at(MtCalls[MT_CALL_TASK(k)], L1);
    predicate NoneCalled{L1, L2} = \forall integer k; 0 <= k < 4 ==>
        \at(MtCalls[MT_CALL_TASK(k)], L2) == \at(MtCalls[MT_CALL_TASK(k)], L1);
*/

/*@ requires i < 4;
    assigns MtCalls[MT_CALL_TASK(0) .. MT_CALL_TASK(3)];
    behavior run:
      assumes go != 0;
      ensures once: MtCalls[MT_CALL_TASK(i)] == MtCount64(\old(MtCalls[MT_CALL_TASK(i)]), 1);
      ensures others: OthersKept{Pre, Post}(i);
    behavior idle:
      assumes go == 0;
      ensures none: NoneCalled{Pre, Post};
*/
void mt_run_one(uint32_t i, uint32_t go);
"""

CALLS_C = r"""
#include "mt_calls.h"

void mt_run_one(uint32_t i, uint32_t go)
{
    if (go != 0u) {
        mt_invoke_t(MT_CALL_TASK(i));
    }
}
"""

CALLS_HARNESS = r"""
#include "mtc_logic.h"
#include "mt_run_one_contract.h"

void harness(void)
{
    uint32_t i = mtc_nondet_u32();
    uint32_t go = mtc_nondet_u32();
    mtc_ghosts_nondet();
    __CPROVER_assume(mtc_pre_mt_run_one(i, go));
    mtc_snapshot();
    mt_run_one(i, go);
    mtc_post_mt_run_one(i, go);
}
"""


class CallCounts(unittest.TestCase):
    """Ghost arrays (the call counters MtCalls of kernel/spec/mt_spec.h): read in the pre- and
    post-state, assigned by element and by range, havocked by a trampoline's stub; function-like
    slot macros in annotations; a two-state predicate with no parameters."""

    def run_calls(self, header=CALLS_H, impl=CALLS_C, defines=()):
        d = os.path.join(WORK, "calls", self.id().split(".")[-1])
        shutil.rmtree(d, ignore_errors=True)
        src, out = os.path.join(d, "src"), os.path.join(d, "gen")
        write(os.path.join(src, "mt_calls.h"), header)
        write(os.path.join(src, "mt_calls.c"), impl)
        write(os.path.join(d, "harness.c"), CALLS_HARNESS)
        incs = [src, os.path.join(ROOT, "kernel", "spec"), os.path.join(ROOT, "kernel", "include")]
        t = translate([os.path.join(src, "mt_calls.h")], incs, out)
        self.assertEqual(t.returncode, 0, t.stderr)
        srcs = [os.path.join(d, "harness.c"), os.path.join(src, "mt_calls.c"),
                os.path.join(out, "mtc_stubs.c"), os.path.join(LIB, "mtc.c"),
                os.path.join(LIB, "ghost.c")]
        return cbmc_failures(srcs, incs + [out, LIB], d, defines=defines)

    def test_passes(self):
        failed, total = self.run_calls()
        self.assertEqual(failed, [])
        self.assertGreater(total, 10)

    def test_missing_call_caught(self):
        failed, _ = self.run_calls(impl=CALLS_C.replace("        mt_invoke_t(MT_CALL_TASK(i));\n",
                                                        "        (void)i;\n"))
        self.assertEqual(failed, ["mt_run_one: ensures run.once"])

    def test_wrong_slot_caught(self):
        failed, _ = self.run_calls(impl=CALLS_C.replace("MT_CALL_TASK(i)", "MT_CALL_TASK(0)"))
        self.assertEqual(sorted(failed), ["mt_run_one: ensures run.once",
                                          "mt_run_one: ensures run.others"])

    def test_call_when_idle_caught(self):
        failed, _ = self.run_calls(impl=CALLS_C.replace("if (go != 0u)", "if (go != 1u)"))
        self.assertIn("mt_run_one: ensures idle.none", failed)

    def test_frame_caught(self):
        failed, _ = self.run_calls(header=CALLS_H.replace(
            "assigns MtCalls[MT_CALL_TASK(0) .. MT_CALL_TASK(3)];", "assigns MtCalls[MT_CALL_TASK(0)];"))
        self.assertEqual(failed, ["mt_run_one: assigns (MtCalls)"])


ABSTRACT_H = r"""
#include <stdint.h>
/*@ axiomatic Env {
      predicate Racing;
    }
*/

typedef struct {
    uint32_t n;
    uint32_t m;
    uint32_t a[2];
} mt_box_t;

/*@ predicate Capped(mt_box_t *b) = \forall integer k; 0 <= k < b->n && k < b->m ==> b->a[k] == k; */

/*@ requires \valid(b) && b->n < 2;
    requires Capped(b);
    assigns b->a[0 .. 1];
    ensures capped: Capped(b);
    ensures quiet: !Racing ==> \result == 1;
*/
int bx_touch(mt_box_t *b);
"""

ABSTRACT_C = r"""
#include "box.h"

int bx_touch(mt_box_t *b)
{
    b->a[b->n] = 99u;
    return 1;
}
"""

ABSTRACT_HARNESS = r"""
#include "mtc_logic.h"
#include "bx_touch_contract.h"

void harness(void)
{
    mt_box_t *g = (mt_box_t *)mtc_alloc(sizeof(mt_box_t), 1u, MTC_K_mt_box_t);
    mtc_ghosts_nondet();
    __CPROVER_assume(mtc_pre_bx_touch(g));
    mtc_snapshot();
    int r = bx_touch(g);
    mtc_post_bx_touch(g, r);
}
"""


class AbstractAndBounds(unittest.TestCase):
    """An axiomatic (abstract, parameterless) predicate is one nondeterministic value per run,
    the same at every read: both values are explored. A quantifier with two upper bounds
    (0 <= k < n && k < m) ranges over the first and keeps the second as a guard: the write of
    a[n] lies outside the range whatever m is."""

    def run_box(self, impl=ABSTRACT_C):
        d = os.path.join(WORK, "abstract", self.id().split(".")[-1])
        shutil.rmtree(d, ignore_errors=True)
        src, out = os.path.join(d, "src"), os.path.join(d, "gen")
        write(os.path.join(src, "box.h"), ABSTRACT_H)
        write(os.path.join(src, "box.c"), impl)
        write(os.path.join(d, "harness.c"), ABSTRACT_HARNESS)
        incs = [src, os.path.join(ROOT, "kernel", "spec"), os.path.join(ROOT, "kernel", "include")]
        t = translate([os.path.join(src, "box.h")], incs, out)
        self.assertEqual(t.returncode, 0, t.stderr)
        srcs = [os.path.join(d, "harness.c"), os.path.join(src, "box.c"),
                os.path.join(out, "mtc_stubs.c"), os.path.join(LIB, "mtc.c"),
                os.path.join(LIB, "ghost.c")]
        return cbmc_failures(srcs, incs + [out, LIB], d)

    def test_passes(self):
        failed, total = self.run_box()
        self.assertEqual(failed, [])
        self.assertGreater(total, 5)

    def test_the_quiet_run_is_explored(self):
        failed, _ = self.run_box(ABSTRACT_C.replace("return 1;", "return 0;"))
        self.assertEqual(failed, ["bx_touch: ensures quiet"])

    def test_the_second_bound_is_a_guard_not_a_range(self):
        # writing inside the range [0, n) is caught: the range is n's
        failed, _ = self.run_box(ABSTRACT_C.replace("b->a[b->n] = 99u;", "b->a[0] = 99u;"))
        self.assertEqual(failed, ["bx_touch: ensures capped"])


class ClauseSelection(unittest.TestCase):
    """A proof folder that sets CLAUSES (-DMTC_CLAUSES -DMTC_CLAUSE_<tag>...) checks only the
    clauses it names (assumption B17; run.py checks that a function's folders together name
    every clause)."""

    run_calls = CallCounts.run_calls

    def test_only_the_named_clauses_are_checked(self):
        wrong = CALLS_C.replace("MT_CALL_TASK(i)", "MT_CALL_TASK(0)")
        sel = ("-DMTC_CLAUSES", "-DMTC_CLAUSE_run_others", "-DMTC_CLAUSE_assigns")
        failed, _ = self.run_calls(impl=wrong, defines=sel)
        self.assertEqual(failed, ["mt_run_one: ensures run.others"])
        failed, _ = self.run_calls(impl=wrong, defines=("-DMTC_CLAUSES", "-DMTC_CLAUSE_run_once"))
        self.assertEqual(failed, ["mt_run_one: ensures run.once"])
        # the two selections together are the whole contract's verdict (test_wrong_slot_caught)
        failed, _ = self.run_calls(impl=wrong, defines=("-DMTC_CLAUSES", "-DMTC_CLAUSE_idle_none"))
        self.assertEqual(failed, [])

    def test_tags_in_the_manifest(self):
        d = os.path.join(WORK, "calls", "tags")
        shutil.rmtree(d, ignore_errors=True)
        src, out = os.path.join(d, "src"), os.path.join(d, "gen")
        write(os.path.join(src, "mt_calls.h"), CALLS_H)
        incs = [src, os.path.join(ROOT, "kernel", "spec"), os.path.join(ROOT, "kernel", "include")]
        t = translate([os.path.join(src, "mt_calls.h")], incs, out)
        self.assertEqual(t.returncode, 0, t.stderr)
        with open(os.path.join(out, "manifest.json")) as f:
            fn = json.load(f)["functions"]["mt_run_one"]
        self.assertEqual(fn["tags"], ["assigns", "idle_none", "run_once", "run_others"])


class Division(unittest.TestCase):
    """ACSL / and % at the narrowest exact width (Translator.divide): unsigned and signed 32
    bits, unsigned and signed 64 bits where the operands' ranges are known, a checked 64-bit
    division where they are not (logic-function parameters, differences), __int128 where they
    can leave 64 bits. Negative operands keep ACSL's truncation; a value outside the checked range is a
    failed check under its own description, not a wrong quotient."""

    def setUp(self):
        self.dir = os.path.join(WORK, "division", self.id().split(".")[-1])
        shutil.rmtree(self.dir, ignore_errors=True)
        self.src = os.path.join(self.dir, "src")
        self.out = os.path.join(self.dir, "gen")
        write(os.path.join(self.src, "mt_div.h"), DIV_H)
        write(os.path.join(self.dir, "harness.c"), DIV_HARNESS)

    def run_div(self, impl=DIV_C, defines=()):
        write(os.path.join(self.src, "mt_div.c"), impl)
        t = translate([os.path.join(self.src, "mt_div.h")], [self.src], self.out)
        self.assertEqual(t.returncode, 0, t.stderr)
        srcs = [os.path.join(self.dir, "harness.c"), os.path.join(self.src, "mt_div.c"),
                os.path.join(LIB, "mtc.c"), os.path.join(LIB, "ghost.c")]
        return cbmc_failures(srcs, [self.src, self.out, LIB], self.dir,
                             ["--external-sat-solver", "cadical"] if shutil.which("cadical") else [],
                             defines)

    def gen(self, name):
        with open(os.path.join(self.out, name)) as f:
            return f.read()

    def test_widths(self):
        t = translate([os.path.join(self.src, "mt_div.h")], [self.src], self.out)
        self.assertEqual(t.returncode, 0, t.stderr)
        self.assertIn("(unsigned int)(((__int128)(a))) / (unsigned int)(((__int128)(b)))",
                      self.gen("mt_q32_contract.h"))                   # uint32: unsigned 32
        self.assertIn("mtc_udiv64(", self.gen("mt_q64_contract.h"))       # a difference
        self.assertIn("(int)(", self.gen("mt_qs_contract.h"))             # int32 / 7: signed 32
        self.assertIn("mtc_sdiv64(", self.gen("mtc_logic.h"))             # MtHalf(v): unknown
        self.assertIn("mtc_smod64(", self.gen("mtc_logic.h"))             # MtRem(v): unknown
        wide = self.gen("mt_wide_contract.h")
        self.assertNotIn("mtc_udiv64", wide)
        self.assertNotIn("unsigned long long)", wide)
        # beyond 64 bits and non-negative: the macros of lib/mtc.h (operators, or the B11 models)
        self.assertIn("MTC_UDIV128(MTC_UMUL128(((__int128)(t)), ((__int128)1000ull)), "
                      "((__int128)(h)))", wide)

    def test_exact(self):
        failed, total = self.run_div()
        # the only failures: MtHalf(x * 2) for x = 2^62, whose operand 2^63 leaves the checked
        # range: the range check, the conversion check of the 64-bit operand, and the ensures
        # clause that the out-of-range quotient then fails; every other quotient is exact
        self.assertEqual(sorted(failed), [
            "arithmetic overflow on signed type conversion in (signed long long int)a",
            "mt_half_u: ensures half",
            "spec division: operands in [-2^63, 2^63)"])
        self.assertGreater(total, 20)

    def test_model(self):
        # with the models of unsigned division and products (-DMTC_DIV_MODEL, B11) the
        # verdicts are those of the operators: the same three failures, and a wrong quotient
        # is still caught
        failed, total = self.run_div(defines=["-DMTC_DIV_MODEL"])
        self.assertEqual(sorted(failed), [
            "arithmetic overflow on signed type conversion in (signed long long int)a",
            "mt_half_u: ensures half",
            "spec division: operands in [-2^63, 2^63)"])
        self.assertGreater(total, 20)
        bad = DIV_C.replace("return (a - b) / c;", "return (a - b) / c - (a == b + c);")
        failed, _ = self.run_div(bad, defines=["-DMTC_DIV_MODEL"])
        self.assertIn("mt_q64: ensures q", failed)

    def test_wrong_quotients_caught(self):
        bad = (DIV_C.replace("return a / b;", "return a / b + (a == 7u);")
               .replace("return (int32_t)((int64_t)x / 7);", "return (x < 0) ? (int32_t)(((int64_t)x - 6) / 7) : (int32_t)((int64_t)x / 7);")
               .replace("return (a - b) / c;", "return (a - b) / c - (a == b + c);"))
        failed, _ = self.run_div(bad)
        for lab in ("mt_q32: ensures q", "mt_q64: ensures q", "mt_qs: ensures q"):
            self.assertIn(lab, failed)


def copy_tool(dst):
    """The translator's package (its modules, not its tests) into dst/tools/acsl2cbmc."""
    shutil.copytree(TOOL, os.path.join(dst, "tools", "acsl2cbmc"),
                    ignore=shutil.ignore_patterns("tests", "__pycache__", ".pytest_cache"))


def copy_kernel(dst):
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "kernel"), os.path.join(dst, "kernel"))
    copy_tool(dst)


MUT_FIND = """    behavior ok:
      assumes n <= r->reserved;
      ensures status: \\result == MT_OK;"""
MUT_REPL = """    behavior ok:
      assumes n <= r->reserved;
      ensures status: \\result == MT_E_FULL;"""
MUT_LABEL = "mt_bring_commit: ensures ok.status"
WP_GOAL = "mt_bring_commit_ok_ensures_status"


class KernelMutation(unittest.TestCase):
    """One mutated ensures clause of a kernel header, checked by both tools."""

    @classmethod
    def setUpClass(cls):
        cls.dirs = {}
        for variant in ("original", "mutated"):
            d = os.path.join(WORK, "kernel-mutation", variant)
            copy_kernel(d)
            if variant == "mutated":
                h = os.path.join(d, "kernel/include/mt/ring.h")
                with open(h) as f:
                    text = f.read()
                if text.count(MUT_FIND) != 1:
                    raise unittest.SkipTest("the mt_bring_commit contract changed: update MUT_FIND")
                with open(h, "w") as f:
                    f.write(text.replace(MUT_FIND, MUT_REPL))
            cls.dirs[variant] = d

    def cbmc(self, variant):
        d = self.dirs[variant]
        gen = os.path.join(d, "gen")
        t = subprocess.run([sys.executable, os.path.join(d, "tools", "acsl2cbmc"),
                            "--root", d, "--out", gen, "--quiet"], capture_output=True, text=True)
        self.assertEqual(t.returncode, 0, t.stderr)
        with open(os.path.join(gen, ".stamp"), "w"):
            pass
        out = os.path.join(d, "cbmc")
        r = subprocess.run(["make", "-s", "-C",
                            os.path.join(ROOT, "proofs/cbmc/proofs/mt_bring_commit"), "result",
                            f"ROOT={d}", f"GEN={gen}", f"OUT={out}", f"TOOLS_BIN={BIN}"],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        failed = []
        with open(os.path.join(out, "result.json")) as f:
            for m in json.load(f):
                for x in m.get("result", []):
                    if x["status"] != "SUCCESS":
                        failed.append(x["description"])
        return failed

    def test_cbmc(self):
        self.assertEqual(self.cbmc("original"), [])
        self.assertEqual(self.cbmc("mutated"), [MUT_LABEL])

    def wp(self, variant):
        d = self.dirs[variant]
        conf = os.path.join(ROOT, "build", "proof", "why3.conf")
        if not os.path.exists(conf):
            subprocess.run([os.path.join(ROOT, "proofs", "wp", "mkconf.sh")], check=True,
                           capture_output=True)
        report = os.path.join(d, "wp.json")
        inc = " ".join(f"-I{d}/kernel/{x}" for x in ("include", "port", "spec", "src"))
        r = subprocess.run(["frama-c", "-wp", "-wp-fct", "mt_bring_commit", "-wp-rte",
                            "-warn-unsigned-overflow", "-warn-unsigned-downcast",
                            "-wp-model", "Typed", "-wp-prover", "cvc4,Z3:4.8.12:fixedTO",
                            "-wp-timeout", "10", "-wp-par", "2", "-wp-cache", "none",
                            f"-cpp-extra-args={inc}", "-wp-report-json", report,
                            os.path.join(d, "kernel/src/ring.c")],
                           capture_output=True, text=True, env={**os.environ, "WHY3CONFIG": conf})
        self.assertTrue(os.path.exists(report), r.stdout[-3000:] + r.stderr[-3000:])
        with open(report) as f:
            goals = json.load(f)["wp:functions"]["mt_bring_commit"]
        bad = sorted(k for k, v in goals.items() if k != "wp:section" and
                     v["wp:main"].get("valid", 0) != v["wp:main"]["total"])
        return bad, goals

    @unittest.skipIf(shutil.which("frama-c") is None or os.environ.get("SKIP_WP") == "1",
                     "frama-c not installed (tools/bootstrap.sh prove) or SKIP_WP=1")
    def test_wp(self):
        bad, goals = self.wp("original")
        self.assertIn(WP_GOAL, goals)
        self.assertEqual(bad, [])
        bad, _ = self.wp("mutated")
        self.assertEqual(bad, [WP_GOAL])


def copy_for_keys(dst):
    """kernel/, the CBMC proof farm, the runners' helper and the translator, at another path."""
    shutil.rmtree(dst, ignore_errors=True)
    for d in ("kernel", os.path.join("proofs", "cbmc")):
        shutil.copytree(os.path.join(ROOT, d), os.path.join(dst, d))
    shutil.copy(os.path.join(ROOT, "proofs", "runtool.py"), os.path.join(dst, "proofs"))
    copy_tool(dst)


def prepend(path, text):
    with open(path, encoding="utf-8") as f:
        body = f.read()
    with open(path, "w", encoding="utf-8") as f:
        f.write(text + body)


def lower_ring_cap(root):
    """A one-line header change in the copy at root: the byte ring's largest capacity."""
    ring_h = os.path.join(root, "kernel", "include", "mt", "ring.h")
    with open(ring_h, encoding="utf-8") as f:
        text = f.read()
    assert "#define MT_BRING_CAP_MAX 0x40000000u" in text
    with open(ring_h, "w", encoding="utf-8") as f:
        f.write(text.replace("#define MT_BRING_CAP_MAX 0x40000000u",
                             "#define MT_BRING_CAP_MAX 0x3FFFFFFFu"))


class RecordKeys(unittest.TestCase):
    """The digests that decide whether a recorded CBMC verdict may be replayed (assumption
    B10): the same for the same inputs at another path, different after a one-line change of
    a source or header, or of an option."""

    def setUp(self):
        # fresh copies for each test: a test changes a header in its copy b
        self.a = os.path.join(WORK, "keys", "a")
        self.b = os.path.join(WORK, "keys", "elsewhere", "b")
        copy_for_keys(self.a)
        copy_for_keys(self.b)

    def cover_key(self, root, extra=(), target="cover-key"):
        p = subprocess.run(["make", "-s", "-C", os.path.join(root, "proofs", "cbmc", "proofs",
                                                           "mt_bring_write"), target,
                            f"TOOLS_BIN={BIN}"] + list(extra),
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        key = p.stdout.strip()
        self.assertRegex(key, r"^[0-9a-f]{64}$")
        return key

    @unittest.skipUnless(os.path.exists(os.path.join(BIN, "goto-cc")), "CBMC not installed")
    def test_cover_key(self):
        k_repo = self.cover_key(ROOT)
        k_a = self.cover_key(self.a)
        self.assertEqual(k_a, self.cover_key(self.b), "the key depends on the location")
        self.assertEqual(k_a, k_repo, "a copy of the repository gives another key")
        self.assertNotEqual(k_a, self.cover_key(self.a, ["UNWIND=7"]), "an option is not in the key")
        # keytext.py: a moved header line is not in the key; a new declaration is
        prepend(os.path.join(self.b, "kernel", "include", "mt", "ring.h"), "/* moved */\n")
        self.assertEqual(k_a, self.cover_key(self.b), "a moved header line changed the key")
        lower_ring_cap(self.b)
        self.assertNotEqual(k_a, self.cover_key(self.b), "a header change is not in the key")

    @unittest.skipUnless(os.path.exists(os.path.join(BIN, "goto-cc")), "CBMC not installed")
    def test_result_key(self):
        """The property run's key: like the coverage key, and it also covers Makefile.common
        (whose recipes build and run the binary); the coverage key does not, and it covers the
        coverage binary's COVER_DEFINES."""
        def key(root, extra=()):
            return self.cover_key(root, extra, target="result-key")
        k_a = key(self.a)
        self.assertEqual(k_a, key(self.b), "the key depends on the location")
        self.assertEqual(k_a, key(ROOT), "a copy of the repository gives another key")
        self.assertNotEqual(k_a, self.cover_key(self.a), "the two keys are the same digest")
        self.assertNotEqual(k_a, key(self.a, ["UNWIND=7"]), "an option is not in the key")
        self.assertNotEqual(self.cover_key(self.a),
                            self.cover_key(self.a, ["COVER_DEFINES=-DMTC_COVER_ONLY"]),
                            "the coverage binary's defines are not in the coverage key")
        prepend(os.path.join(self.b, "proofs", "cbmc", "Makefile.common"), "# moved\n")
        self.assertNotEqual(k_a, key(self.b), "Makefile.common is not in the property key")
        self.assertEqual(self.cover_key(self.a), self.cover_key(self.b),
                         "a comment in Makefile.common changed the coverage key")


    def run_py_keys(self, root, name):
        code = ("import sys; sys.path.insert(0, sys.argv[1]); import run; "
                "print(*run.input_keys(sys.argv[2], False))")
        p = subprocess.run([sys.executable, "-c", code, os.path.join(root, "proofs", "cbmc"),
                            name], capture_output=True, text=True,
                           env=dict(os.environ, TOOLS_BIN=BIN))
        self.assertEqual(p.returncode, 0, p.stderr)
        return p.stdout.split()

    def make_keys(self, root, name):
        d = os.path.join(root, "proofs", "cbmc", "proofs", name)
        keys = []
        for target in ("result-key", "cover-key"):
            p = subprocess.run(["make", "-s", "-C", d, target, f"TOOLS_BIN={BIN}"],
                               capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, p.stderr)
            keys.append(p.stdout.strip())
        return keys

    @unittest.skipUnless(os.path.exists(os.path.join(BIN, "goto-cc")), "CBMC not installed")
    def test_run_py_keys(self):
        """proofs/cbmc/run.py computes both keys in one process from what keys.mk prints (each
        source preprocessed once per run, keytext.py in-process): the digests of the two make
        targets, for a proof with its own coverage defines and one with a split clause list,
        and again after a header change."""
        for name in ("mt_bring_write", "mt_sched_run", "mt_topic_publish_i__notify"):
            keys = self.run_py_keys(self.a, name)
            self.assertEqual(keys, self.make_keys(self.a, name), name)
            self.assertEqual(len(set(keys)), 2, name)
        lower_ring_cap(self.b)
        keys = self.run_py_keys(self.b, "mt_bring_write")
        self.assertEqual(keys, self.make_keys(self.b, "mt_bring_write"))
        self.assertNotEqual(keys, self.run_py_keys(self.a, "mt_bring_write"))


    @unittest.skipUnless(os.path.exists(os.path.join(BIN, "goto-cc")), "CBMC not installed")
    def test_max_tier_runs_only_what_it_changes(self):
        """make cbmc-max (CBMC_BIG=1) skips a proof whose analysed program is the default
        tier's: the byte ring's write reaches the capacity helpers MTC_BIG changes, the
        semaphore's init does not; a changed helper body in a copy makes init differ too."""
        code = ("import sys; sys.path.insert(0, sys.argv[1]); import run; "
                "print(*[run.same_program_in_both_tiers(n) for n in sys.argv[2:]])")

        def same(root, *names):
            p = subprocess.run([sys.executable, "-c", code,
                                os.path.join(root, "proofs", "cbmc")] + list(names),
                               capture_output=True, text=True, env=dict(os.environ, TOOLS_BIN=BIN))
            self.assertEqual(p.returncode, 0, p.stderr)
            return p.stdout.split()
        self.assertEqual(same(self.a, "mt_bring_write", "mt_sem_init"), ["False", "True"])
        harness = os.path.join(self.b, "proofs", "cbmc", "proofs", "mt_sem_init",
                               "mt_sem_init_harness.c")
        prepend(harness, "#ifdef MTC_BIG\nint mtc_big_seen = 1;\n#endif\n")
        self.assertEqual(same(self.b, "mt_sem_init"), ["False"])


class RecordReplay(unittest.TestCase):
    """proofs/cbmc/run.py's use of the verdict records (B10), on a copy of the tree and its
    records, with the quickest harness: a passing run is recorded; a recorded verdict is
    replayed only for its digest; CBMC_RECORD=properties runs the property run again and
    fails a harness whose record disagrees with it."""
    NAME = "mt_sem_valid"

    def setUp(self):
        self.root = os.path.join(WORK, "replay", "r")
        copy_for_keys(self.root)
        self.records = os.path.join(self.root, "proofs", "cbmc", "records.json")
        self.out = os.path.join(self.root, "build", "proof", "cbmc", "proofs", self.NAME)

    def run_py(self, mode):
        env = dict(os.environ, TOOLS_BIN=BIN, CBMC_RECORD=mode)
        p = subprocess.run([sys.executable, os.path.join(self.root, "proofs", "cbmc", "run.py"),
                            self.NAME], capture_output=True, text=True, env=env)
        with open(os.path.join(self.root, "build", "proof", "cbmc", "summary.json")) as f:
            s = json.load(f)
        return p.returncode, p.stdout + p.stderr, s, s["results"][0]

    def record(self):
        with open(self.records) as f:
            return json.load(f)[self.NAME]

    def tamper(self, **kw):
        with open(self.records) as f:
            recs = json.load(f)
        recs[self.NAME].update(kw)
        with open(self.records, "w") as f:
            json.dump(recs, f)

    @unittest.skipUnless(os.path.exists(os.path.join(BIN, "goto-cc")), "CBMC not installed")
    def test_replay(self):
        self.tamper(result_key="0" * 64, properties=0)
        rc, out, s, e = self.run_py("save")
        self.assertEqual(rc, 0, out)
        self.assertEqual((e["property_source"], e["passed"]), ("fresh", True), out)
        rec = self.record()
        self.assertRegex(rec["result_key"], r"^[0-9a-f]{64}$")
        self.assertEqual(rec["properties"], e["properties"])
        self.assertGreater(rec["properties"], 0)

        shutil.rmtree(self.out)
        rc, out, s, e = self.run_py("replay")
        self.assertEqual(rc, 0, out)
        self.assertEqual((e["property_source"], e["coverage_source"]), ("replayed", "replayed"))
        self.assertEqual((s["properties_replayed"], s["properties_fresh"]), (1, 0))
        self.assertEqual(e["properties"], rec["properties"])
        self.assertFalse(os.path.exists(os.path.join(self.out, "result.json")),
                         "a replayed verdict ran CBMC")

        rc, out, s, e = self.run_py("properties")
        self.assertEqual(rc, 0, out)
        self.assertEqual((e["property_source"], e["coverage_source"]), ("fresh", "replayed"))
        self.assertTrue(os.path.exists(os.path.join(self.out, "result.json")))

        self.tamper(properties=rec["properties"] + 1)
        rc, out, s, e = self.run_py("properties")
        self.assertEqual(rc, 1, out)
        self.assertFalse(e["passed"])
        self.assertIn("record disagrees", e.get("error", ""), out)

        self.tamper(result_key="f" * 64)
        rc, out, s, e = self.run_py("replay")
        self.assertEqual(rc, 0, out)
        self.assertEqual(e["property_source"], "fresh", "a record of other inputs was replayed")
        self.assertEqual(e["properties"], rec["properties"])

