# SPDX-License-Identifier: Apache-2.0
"""proofs/cbmc/keytext.py: the text a CBMC record key digests moves with the analysed program
and the kernel lines a record names, and with nothing else.

    /usr/bin/python3 -m pytest -q tests/proofs/test_cbmc_keytext.py
"""
import os
import subprocess
import sys

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
KEYTEXT = os.path.join(ROOT, "proofs", "cbmc", "keytext.py")

LOGIC = '''# 1 "@ROOT@/build/proof/cbmc/gen/mtc_logic.h"
typedef struct {{ int token; }} mt_sem_t;
static int mtc_q{a}(int mtc_st, int mtc_e0)
{{
    int mtc_i_{a};
    for (mtc_i_{a} = 0; mtc_i_{a} < mtc_e0; mtc_i_{a}++) {{ if (mtc_i_{a} == 3) return 1; }}
    return 0;
}}
static int mtc_q{b}(int mtc_st, int mtc_e0)
{{
    return mtc_e0 > 7;
}}
static int mtc_MtUsed(int mtc_st, int x)
{{
    return mtc_q{a}(mtc_st, x);
}}
static int mtc_MtUnused(int mtc_st, int x)
{{
    return mtc_q{b}(mtc_st, x);
}}
int mt_unused_proto(int x);
extern const char *const mt_unused_names[3 + 1];
extern const char *const mt_unused_sized[(int)3 + 1];
extern int mt_used_object;
int mt_sem_wait(mt_sem_t *s);
static int mtc_model(int x)
{{
    return x;
}}
'''

KERNEL = '''# {line} "@ROOT@/kernel/src/sem.c"
int mt_sem_wait(mt_sem_t *s)
{{
    return s->token{body} + mt_used_object;
}}
# 40 "@ROOT@/kernel/src/sem.c"
int mt_sem_unused(mt_sem_t *s)
{{
    return 0;
}}
'''

HARNESS = '''# 1 "@ROOT@/proofs/cbmc/proofs/mt_sem_wait/mt_sem_wait_harness.c"
void harness(void)
{
    mt_sem_t s;
    int r = mt_sem_wait(&s);
    __CPROVER_assert(mtc_MtUsed(0, r), "used");
}
'''


def key_text(a=1, b=2, line=10, body="", head="cbmc --unwind 2", shift=0):
    logic = LOGIC.format(a=a, b=b)
    if shift:
        logic = logic.replace("typedef", "\n" * shift + "typedef")
    text = "\n".join([head, "== harness.c", HARNESS, "== sem.c", logic,
                      KERNEL.format(line=line, body=body)])
    p = subprocess.run([sys.executable, KEYTEXT], input=text, capture_output=True, text=True,
                       check=True)
    return p.stdout


def test_unreferenced_functions_and_prototypes_go():
    out = key_text()
    assert "mtc_MtUsed" in out and "mt_sem_wait" in out
    assert "mtc_MtUnused" not in out
    assert "mt_unused_proto" not in out
    assert "mt_unused_names" not in out and "extern int mt_used_object;" in out
    assert "mt_unused_sized" not in out, "a cast in the size is not a function type"
    assert "mt_sem_unused" not in out
    assert "mtc_model" not in out
    assert "mtc_e0 > 7" not in out, "the helper only an unused function calls stays"


def test_a_name_in_the_options_keeps_its_function():
    out = key_text(head="cbmc; replace-calls mt_sem_wait:mtc_model")
    assert "mtc_model" in out


def test_header_line_shifts_and_quantifier_numbers_leave_the_text():
    base = key_text()
    assert key_text(shift=5) == base
    assert key_text(a=7, b=3) == base


def test_kernel_lines_and_bodies_move_the_text():
    base = key_text()
    assert key_text(line=11) != base, "a kernel function's line is named by coverage records"
    assert key_text(body=" + 1") != base
    assert key_text(head="cbmc --unwind 3") != base


GOTO_CC = os.path.join(ROOT, ".tools", "bin", "goto-cc")


# `make test` runs before CBMC is installed (the README's prove command installs it); there the
# keys are not computed at all. `make prove` computes every harness's keys and fails on an error,
# and `make cbmc-test` (part of it) checks the same targets (RecordKeys in
# tools/acsl2cbmc/tests/test_acsl2cbmc.py).
@pytest.mark.skipif(not os.access(GOTO_CC, os.X_OK), reason="goto-cc not installed (.tools/bin)")
def test_the_real_tree_keys_are_digests():
    """Every proof folder's make target still yields a digest through keytext.py."""
    proof = os.path.join(ROOT, "proofs", "cbmc", "proofs", "mt_sem_init")
    for target in ("result-key", "cover-key"):
        p = subprocess.run(["make", "-s", "-C", proof, target], capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        assert len(p.stdout.strip()) == 64
