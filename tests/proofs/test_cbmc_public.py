# SPDX-License-Identifier: Apache-2.0
"""proofs/cbmc/run.py's list of public functions: every function a public header declares
needs a CBMC proof folder, with or without an ACSL contract (the gate's missing_proofs).

    /usr/bin/python3 -m pytest -q tests/proofs/test_cbmc_public.py
"""
import importlib.util
import os

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SPEC = importlib.util.spec_from_file_location("cbmc_run", os.path.join(ROOT, "proofs", "cbmc",
                                                                       "run.py"))
RUN = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(RUN)

HEADER = """#ifndef MT_FAKE_H
#define MT_FAKE_H
#include <stdint.h>
#define MT_FAKE_HZ(x) ((x) * 1000u)
/*@ requires \\valid(p);
    ensures mt_not_a_function(p) == 0; */
uint32_t mt_fake_init(mt_fake_t *p,
                      uint32_t n);
static inline uint32_t mt_fake_count(const mt_fake_t *p) { return p->n; }
// uint32_t mt_commented_out(void);
/* mt_in_a_comment(void); */
typedef void (*mt_fake_fn)(void *arg);
#endif
"""


def test_declarations_and_inline_definitions_are_found(tmp_path):
    (tmp_path / "fake.h").write_text(HEADER, encoding="utf-8")
    assert RUN.header_functions(str(tmp_path)) == {"mt_fake_init", "mt_fake_count"}


def test_every_public_function_has_a_proof_folder():
    declared = RUN.header_functions()
    assert len(declared) >= 100
    assert sorted(declared - set(RUN.proof_names())) == []
