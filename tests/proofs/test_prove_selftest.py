# SPDX-License-Identifier: Apache-2.0
"""tools/prove_selftest.py without WP or CBMC: the rotation, the judgement of one mutant, and
proofs/mutants.json against the kernel sources (the list must follow the code).

    /usr/bin/python3 -m pytest -q tests/proofs/test_prove_selftest.py
"""
import importlib.util
import itertools
import math
import os
import subprocess
import sys

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(ROOT, "tools", "prove_selftest.py")

_spec = importlib.util.spec_from_file_location("prove_selftest", SCRIPT)
ps = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(ps)

MUTANTS = ps.load_mutants(os.path.join(ROOT, "proofs", "mutants.json"))
IDS = [m["id"] for m in MUTANTS]
VERDICTS = (True, False, None)
REJECT_BY = (["wp"], ["cbmc"], ["wp", "cbmc"])


# --- rotation ------------------------------------------------------------------------------

@pytest.mark.parametrize("n", [1, 2, 3, 5, 7, 24, len(MUTANTS), 31])
def test_rotation_covers_every_mutant_within_ceil_n_over_k_landings(n):
    for k in range(1, n + 1):
        rounds = math.ceil(n / k)
        for c0 in (0, 1, 2, 7, 159, 10**6 + 3):
            seen = set()
            for c in range(c0, c0 + rounds):
                pos = ps.rotation(n, k, c)
                assert len(pos) == k and len(set(pos)) == k, (n, k, c, pos)
                assert all(0 <= p < n for p in pos)
                assert pos == sorted(pos), "selection is in file order"
                seen.update(pos)
            assert seen == set(range(n)), (n, k, c0)


def test_rotation_is_the_window_at_c_times_k():
    n = len(MUTANTS)
    for c in range(0, 3 * n):
        assert ps.rotation(n, 2, c) == sorted({(2 * c) % n, (2 * c + 1) % n})


def test_rotation_larger_than_the_list_selects_every_mutant_once():
    assert ps.rotation(5, 9, 3) == [0, 1, 2, 3, 4]
    assert ps.rotation(0, 2, 3) == []
    with pytest.raises(ValueError):
        ps.rotation(5, 0, 3)


def test_list_rotation_prints_the_selection_without_running():
    n = len(MUTANTS)
    p = subprocess.run([sys.executable, SCRIPT, "--list-rotation", "2", "5"],
                       capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert p.returncode == 0, p.stderr
    want = " ".join(IDS[i] for i in ps.rotation(n, 2, 5))
    assert "commit count 5" in p.stdout and p.stdout.rstrip().split("-> ")[1].startswith(want)


def test_commit_count_is_zero_outside_a_git_checkout(tmp_path):
    assert ps.commit_count(str(tmp_path)) == 0


# --- judgement -----------------------------------------------------------------------------

@pytest.mark.parametrize("reject_by,wp,cbmc",
                         [(r, w, c) for r in REJECT_BY for w, c in itertools.product(VERDICTS, VERDICTS)])
def test_judge_ok_only_when_every_required_tool_rejects(reject_by, wp, cbmc):
    verdicts = {"wp": wp, "cbmc": cbmc}
    ok, reason = ps.judge(reject_by, wp, cbmc)
    assert ok == all(verdicts[t] is True for t in reject_by)
    assert isinstance(reason, str) and reason
    for t, name in (("wp", "WP"), ("cbmc", "CBMC")):
        v = verdicts[t]
        if t in reject_by and v is False:
            assert f"{name} accepted it (must reject)" in reason
        if t in reject_by and v is None:
            # no verdict is not an acceptance
            assert f"{name} gave no verdict" in reason and f"{name} accepted" not in reason
        if t not in reject_by and ok:
            word = {True: f"bonus: {name} rejected it too", False: f"{name} accepted it (not required)",
                    None: f"{name} gave no verdict"}[v]
            assert word in reason


def test_judge_names_why_a_required_tool_gave_no_verdict():
    ok, reason = ps.judge(["wp", "cbmc"], True, None, {"cbmc": "time-out"})
    assert not ok and "CBMC gave no verdict (time-out)" in reason


@pytest.mark.parametrize("bad", [[], ["tla"], ["wp", "wp"], "wp", None])
def test_judge_refuses_a_malformed_reject_by(bad):
    with pytest.raises(ValueError):
        ps.judge(bad, True, True)


# --- proofs/mutants.json follows the code ---------------------------------------------------

def test_mutant_ids_are_unique():
    assert len(IDS) == len(set(IDS))


@pytest.mark.parametrize("m", MUTANTS, ids=IDS)
def test_mutant_reject_by_is_a_non_empty_subset_of_wp_and_cbmc(m):
    rb = m.get("reject_by")
    assert isinstance(rb, list) and rb and len(set(rb)) == len(rb) and set(rb) <= {"wp", "cbmc"}


@pytest.mark.parametrize("m", MUTANTS, ids=IDS)
def test_mutant_names_cbmc_only_with_a_harness_folder(m):
    harness = m.get("harness", m["function"])
    folder = os.path.join(ROOT, "proofs", "cbmc", "proofs", harness)
    if "cbmc" in m["reject_by"]:
        assert os.path.isdir(folder), f"{m['id']}: no CBMC harness folder {folder}"
    elif os.path.isdir(folder):
        # a harness exists but is known to accept the mutant: the list says why
        assert isinstance(m.get("cbmc_accepts"), str) and m["cbmc_accepts"].strip(), m["id"]


@pytest.mark.parametrize("m", MUTANTS, ids=IDS)
def test_mutant_find_text_occurs_exactly_once_in_its_file(m):
    with open(os.path.join(ROOT, m["file"]), encoding="utf-8") as f:
        text = f.read()
    assert text.count(m["find"]) == 1, f"{m['id']}: find text occurs {text.count(m['find'])} times in {m['file']}"
    assert m["find"] != m["replace"]


_run_spec = importlib.util.spec_from_file_location(
    "cbmc_run", os.path.join(ROOT, "proofs", "cbmc", "run.py"))
cbmc_run = importlib.util.module_from_spec(_run_spec)
_run_spec.loader.exec_module(cbmc_run)


@pytest.mark.parametrize("m", MUTANTS, ids=IDS)
def test_mutant_harness_checks_the_cbmc_clauses_it_names(m):
    """A folder on part of a function's clauses (CLAUSES, B17) must be the one that checks the
    clauses the mutant names: M46 named a notifier clause but ran the folder without it, and
    CBMC accepted the mutant."""
    harness = m.get("harness", m["function"])
    selected = cbmc_run.proof_clauses(harness)
    for name in (m.get("clauses") or {}).get("cbmc", []):
        tag = name.split(": ensures ", 1)[-1].replace(".", "_")
        assert selected is None or tag in selected, \
            f"{m['id']}: harness folder {harness} does not check {name!r} (CLAUSES {selected})"


# --- named clauses ------------------------------------------------------------------------

def test_a_failure_of_a_named_clause_rejects():
    v, why, hits = ps.clause_verdict(["f_ensures_quiet"], ["f_ensures_quiet", "f_assigns"], "x")
    assert v is True and hits == ["f_ensures_quiet"] and "f_ensures_quiet" in why


def test_a_failure_elsewhere_is_no_verdict_when_clauses_are_named():
    # the mutant broke something, but not the clause it is meant to break: no rejection
    v, why, hits = ps.clause_verdict(["f_ensures_quiet"], ["f_assert_rte_mem_access"], "x")
    assert v is None and hits == [] and "none of its named clauses" in why


def test_no_failure_is_an_acceptance_whatever_is_named():
    assert ps.clause_verdict(["f_ensures_quiet"], [], "x")[0] is False
    assert ps.clause_verdict(None, [], "x")[0] is False


def test_without_named_clauses_any_failure_rejects_and_says_so():
    v, why, _ = ps.clause_verdict(None, ["f_ensures"], "x")
    assert v is True and "no clause named" in why


def test_failed_goal_names_come_from_the_gate_summary():
    mod = {"failures": ["put: put_ensures_quiet {'total': 1, 'valid': 0}",
                        "put: put_wp_smoke_default_requires {'total': 1, 'valid': 0}"]}
    assert ps.wp_failed_goals(mod) == ["put_ensures_quiet", "put_wp_smoke_default_requires"]


def test_failed_properties_are_named_by_their_description():
    entry = {"failed": 1, "failures": [{"property": "p.1", "description": "f: ensures a.b"}]}
    assert ps.cbmc_failed_properties(entry) == ["f: ensures a.b"]


@pytest.mark.parametrize("bad", [{"wp": []}, {"wp": "x"}, {"smt": ["x"]}, {"cbmc": [""]}, ["x"]])
def test_malformed_clauses_are_refused(bad):
    with pytest.raises(ValueError):
        ps.check_clauses({"reject_by": ["wp"], "clauses": bad})


@pytest.mark.parametrize("m", MUTANTS, ids=IDS)
def test_named_clauses_are_well_formed_and_labelled_in_the_kernel(m):
    ps.check_clauses(m)
    kernel = ""
    for d in ("kernel/include/mt", "kernel/src", "kernel/spec"):
        for n in sorted(os.listdir(os.path.join(ROOT, d))):
            with open(os.path.join(ROOT, d, n), encoding="utf-8") as f:
                kernel += f.read()
    for name in (m.get("clauses") or {}).get("cbmc", []):
        # "<function>: ensures <behavior>.<label>": the label is a clause label in the kernel
        label = name.rsplit(" ", 1)[-1].rsplit(".", 1)[-1]
        assert f"{label}:" in kernel, f"{m['id']}: no clause labelled {label!r}"
    for name in (m.get("clauses") or {}).get("wp", []):
        for kind in ("_ensures_", "_loop_invariant_", "_assert_", "_requires_"):
            if kind in name:
                label = name.split(kind, 1)[1]
                assert f"{label}:" in kernel, f"{m['id']}: no clause labelled {label!r}"
