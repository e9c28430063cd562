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


# ------------------------------------------------------------------------------ split contracts

def folder(tmp_path, name, text):
    d = tmp_path / name
    d.mkdir()
    (d / "Makefile").write_text(text, encoding="utf-8")
    (d / "cbmc-proof.txt").write_text("", encoding="utf-8")


def test_split_folders_must_check_every_clause(tmp_path, monkeypatch):
    monkeypatch.setattr(RUN, "PROOFS", str(tmp_path))
    flags = "CBMC_CFG_EXTRA = -DMTC_CLAUSES $(addprefix -DMTC_CLAUSE_,$(CLAUSES))\n"
    folder(tmp_path, "mt_f", "PROOF_UID = mt_f\nCLAUSES = inv left \\\n    assigns\n" + flags)
    folder(tmp_path, "mt_f__b", "PROOF_UID = mt_f__b\nFUNCTION = mt_f\nCLAUSES = ok_status\n"
           + flags)
    folder(tmp_path, "mt_g", "PROOF_UID = mt_g\n")
    functions = {"mt_f": {"tags": ["assigns", "inv", "left", "ok_status", "complete"]},
                 "mt_g": {"tags": ["assigns"]}}
    of = {}
    for n in RUN.proof_names():
        of.setdefault(RUN.proof_function(n), []).append(n)
    assert of == {"mt_f": ["mt_f", "mt_f__b"], "mt_g": ["mt_g"]}
    assert RUN.unchecked_clauses(functions, of) == [
        "mt_f: complete (checked by no proof folder)"]
    functions["mt_f"]["tags"].remove("complete")
    assert RUN.unchecked_clauses(functions, of) == []
    functions["mt_f"]["tags"].remove("left")  # a CLAUSES name that is no clause: a typo
    assert RUN.unchecked_clauses(functions, of) == [
        "mt_f: left (named in CLAUSES, not a clause of the contract)"]


def test_a_selection_outside_clauses_fails(tmp_path, monkeypatch):
    monkeypatch.setattr(RUN, "PROOFS", str(tmp_path))
    flags = "CBMC_CFG_EXTRA = -DMTC_CLAUSES $(addprefix -DMTC_CLAUSE_,$(CLAUSES))\n"
    folder(tmp_path, "mt_f", "PROOF_UID = mt_f\nCLAUSES = inv assigns\n" + flags)
    folder(tmp_path, "mt_g", "PROOF_UID = mt_g\nCBMC_CFG_EXTRA = -DMTC_CLAUSES -DMTC_CLAUSE_inv\n")
    folder(tmp_path, "mt_h", "PROOF_UID = mt_h\nCLAUSES = inv\n")
    folder(tmp_path, "mt_k", "PROOF_UID = mt_k\n")
    (tmp_path / "mt_k" / "mt_k_harness.c").write_text("#define MTC_CLAUSES\n", encoding="utf-8")
    # the topic bus's configuration may stand before the selection; nothing else may
    folder(tmp_path, "mt_b", "PROOF_UID = mt_b\nCLAUSES = inv assigns\nCBMC_CFG_EXTRA = "
           "$(BUS_CBMC_CFG) -DMTC_CLAUSES $(addprefix -DMTC_CLAUSE_,$(CLAUSES))\n")
    folder(tmp_path, "mt_x", "PROOF_UID = mt_x\nCLAUSES = inv assigns\nCBMC_CFG_EXTRA = "
           "-DX=1 -DMTC_CLAUSES $(addprefix -DMTC_CLAUSE_,$(CLAUSES))\n")
    functions = {f: {"tags": ["assigns", "inv"]} for f in ("mt_f", "mt_g", "mt_h", "mt_k",
                                                           "mt_b", "mt_x")}
    of = {f: [f] for f in functions}
    assert RUN.unchecked_clauses(functions, of) == [
        "mt_g: MTC_CLAUSE in Makefile outside CBMC_CFG_EXTRA = -DMTC_CLAUSES "
        "$(addprefix -DMTC_CLAUSE_,$(CLAUSES))",
        "mt_h: CLAUSES is set, CBMC_CFG_EXTRA is not [$(BUS_CBMC_CFG) ]-DMTC_CLAUSES "
        "$(addprefix -DMTC_CLAUSE_,$(CLAUSES))",
        "mt_h: assigns (checked by no proof folder)",
        "mt_k: MTC_CLAUSE in mt_k_harness.c outside CBMC_CFG_EXTRA = -DMTC_CLAUSES "
        "$(addprefix -DMTC_CLAUSE_,$(CLAUSES))",
        "mt_x: CLAUSES is set, CBMC_CFG_EXTRA is not [$(BUS_CBMC_CFG) ]-DMTC_CLAUSES "
        "$(addprefix -DMTC_CLAUSE_,$(CLAUSES))"]


def test_the_real_split_folders_check_every_clause(tmp_path):
    import json
    import subprocess
    import sys
    subprocess.run([sys.executable, os.path.join(ROOT, "tools", "acsl2cbmc"), "--root", ROOT,
                    "--out", str(tmp_path), "--quiet"], check=True)
    with open(tmp_path / "manifest.json", encoding="utf-8") as f:
        functions = json.load(f)["functions"]
    of = {}
    for n in RUN.proof_names():
        of.setdefault(RUN.proof_function(n), []).append(n)
    assert of["mt_sched_run"] == ["mt_sched_run", "mt_sched_run__tasks"]
    assert RUN.unchecked_clauses(functions, of) == []
    # a split folder holds no copy of the harness: it builds its function's (Makefile.common)
    for fn, folders in of.items():
        for n in folders:
            if n != fn:
                assert RUN.harness_path(n) == os.path.join(RUN.PROOFS, fn, fn + "_harness.c")
                assert not any(x.endswith(".c") for x in os.listdir(os.path.join(RUN.PROOFS, n))), n
    assert not (tmp_path / "mt_sched_run__tasks_contract.h").exists()
