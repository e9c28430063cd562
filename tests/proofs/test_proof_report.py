# SPDX-License-Identifier: Apache-2.0
"""tools/proof_report.py, the strict gate of `make prove` (tools/proof_gate.py), on synthetic
summaries: a complete passing set, then one change per failure kind. Each failing case asserts
the exit status 1 and that a listed problem names the culprit (part, goal, harness, model,
trace or mutant). No prover runs.

    /usr/bin/python3 -m pytest -q tests/proofs/test_proof_report.py
"""
import json
import os
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
REPORT = os.path.join(ROOT, "tools", "proof_report.py")
DEFAULT_PARTS = ["wp", "cbmc", "cbmc-test", "chibios-cbmc", "tla", "tla-trace-mission"]
CANARY_OK = "wp-canary: 6 functions as expected (3 contradictions found, 3 controls clean)"


def fn(goals, smoke):
    return {"goals": goals, "proved": goals, "smoke": smoke, "smoke_passed": smoke, "time_s": 1.0}


def module(goals, smoke, functions, replayed, fresh):
    return {"goals": goals, "proved": goals, "smoke": smoke, "smoke_passed": smoke,
            "time_s": 10.0, "prover_time_s": 5.0, "by_prover": {"z3": goals},
            "cache_replayed": replayed, "cache_fresh": fresh,
            "functions": functions, "failures": [], "fatal": []}


def harness(name):
    return {"function": name, "passed": True, "properties": 120, "failed": 0, "coverage": 96.5,
            "seconds": 2.0, "cpu_seconds": 2.0, "property_source": "fresh",
            "coverage_source": "replayed", "reach": [{"witness": "ok_path", "reached": True}]}


def expected(name, expect="pass"):
    return {"name": name, "ok": True, "expect": expect, "result": expect, "seconds": 1.0}


def passing_set():
    """{path under $BUILD/proof: JSON} of a run where everything is proved."""
    wp = {
        "modules": {
            "sched": module(1100, 300, {"mt_sched_tick": fn(600, 150),
                                        "mt_sched_add": fn(500, 150)}, 1000, 400),
            "ring": module(5200, 1500, {"mt_ring_write": fn(5200, 1500)}, 6700, 0),
        },
        "goals": 6300, "proved": 6300, "smoke": 1800, "smoke_passed": 1800,
        "by_prover": {"z3": 6300}, "cache_replayed": 1000, "cache_fresh": 400,
        "modules_run": ["ring", "sched"],
        "acsl_forbidden": [], "smoke_canary": CANARY_OK, "pass": True,
        "requirements": [{"id": "R-1", "text": "ring writes in order", "ok": True,
                          "clauses": [{"name": "mt_ring_write:data", "state": "proved"}],
                          "tests": [], "models": [], "problems": []}],
    }
    names = ["mt_ring_write", "mt_sched_add", "mt_sched_tick"]
    cbmc = {"harnesses": 3, "passed": 3, "record_mode": "properties", "properties_fresh": 3,
            "properties_replayed": 0, "coverage_fresh": 0, "coverage_replayed": 3,
            "tier": "default", "seconds": 6.0, "missing_proofs": [], "clauses_unchecked": [],
            "results": [harness(n) for n in names]}
    tla = {"models": [dict(expected("Ring_ci"), module="Ring", config="cfg/ring.cfg",
                           distinct_states=1234),
                      expected("Ring_lost_item", "invariant")],
           "passed": 2, "total": 2, "seconds": 2.0}
    return {
        "parts.json": {p: {"rc": 0, "seconds": 1.5} for p in DEFAULT_PARTS},
        "timing.json": {p: 1.5 for p in DEFAULT_PARTS},
        "wp/summary.json": wp,
        "cbmc/summary.json": cbmc,
        "cbmc/test/summary.json": {"tests": 19, "passed": 19, "failed": 0, "skipped": 0,
                                   "not_passed": []},
        "tla/summary.json": tla,
        "tla/trace-mission/summary.json": {
            "traces": [expected("mission_seed_1"), expected("mission_skip_verify", "reject")],
            "passed": 2, "total": 2},
        "tla/trace/summary.json": {
            "traces": [expected("ring_seed_1"), expected("sem_seed_1"),
                       expected("mission_seed_1")], "passed": 3, "total": 3},
        "hal_chibios/cbmc-summary.json": {
            "harnesses": 2, "passed": 2,
            "results": [{"name": n, "passed": True, "coverage_reached": 3, "coverage_total": 3,
                         "seconds": 1} for n in ("harness_wrap", "harness_ticks_ceil")]},
        "selftest/summary.json": {
            "mutants": 2, "ok": 2, "killed": 2,
            "results": [{"id": "M1", "function": "mt_ring_write", "applied": True, "ok": True,
                         "wp": True, "cbmc": True, "reason": "rejected by WP and CBMC"},
                        {"id": "M2", "function": "mt_sched_tick", "applied": True, "ok": True,
                         "wp": True, "cbmc": None, "reason": "rejected by WP"}]},
    }


BASELINE = {"wp.proved": 6000, "wp.smoke_passed": 1700, "cbmc.passed": 3, "tla.passed": 2,
            "tla_trace.passed": 2, "translator.passed": 19}


class Result:
    def __init__(self, proc, proof):
        self.rc = proc.returncode
        self.out = proc.stdout + proc.stderr
        with open(os.path.join(proof, "summary.json"), encoding="utf-8") as f:
            self.summary = json.load(f)
        self.problems = self.summary["problems"]


class Proof:
    """A synthetic $BUILD/proof tree, and runs of the report on it."""

    def __init__(self, tmp):
        self.tmp = str(tmp)
        self.build = os.path.join(self.tmp, "build")
        self.proof = os.path.join(self.build, "proof")
        self.baseline = os.path.join(self.tmp, "baseline.json")
        self.put_json(self.baseline, BASELINE)
        for rel, value in passing_set().items():
            self.put(rel, value)

    @staticmethod
    def put_json(path, value):
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            json.dump(value, f)

    def put(self, rel, value):
        self.put_json(os.path.join(self.proof, rel), value)

    def get(self, rel):
        with open(os.path.join(self.proof, rel), encoding="utf-8") as f:
            return json.load(f)

    def edit(self, rel, change):
        value = self.get(rel)
        change(value)
        self.put(rel, value)

    def drop(self, rel):
        os.remove(os.path.join(self.proof, rel))

    def run(self, *args, env=None, baseline=True):
        e = {k: v for k, v in os.environ.items() if k != "PROVE_GATE"}
        e.update(BUILD=self.build, **(env or {}))
        cmd = [sys.executable, REPORT] + (["--baseline", self.baseline] if baseline else [])
        proc = subprocess.run(cmd + list(args), capture_output=True, text=True, env=e,
                              cwd=self.tmp, timeout=60)
        return Result(proc, self.proof)


@pytest.fixture
def proof(tmp_path):
    return Proof(tmp_path)


def assert_passes(res):
    assert res.rc == 0, res.out
    assert "PROVE OK" in res.out and res.summary["ok"] is True and res.problems == []


def assert_fails(res, *words):
    """Exit status 1, and one listed problem (summary.json and console) holds every word."""
    assert res.rc == 1, res.out
    assert "PROVE FAILED" in res.out and res.summary["ok"] is False
    hits = [p for p in res.problems if all(w in p for w in words)]
    assert hits, f"no problem names {words}: {res.problems}"
    assert "  - " + hits[0] in res.out


# ------------------------------------------------------------------------------ the passing set

def test_complete_set_passes_with_every_output(proof):
    res = proof.run()
    assert_passes(res)
    s = res.summary
    for key in ("wp", "cbmc", "tla", "translator", "selftest", "tla_trace", "assumptions",
                "timing", "versions", "counts", "problems", "ok", "complete", "parts"):
        assert key in s, key
    assert s["gate"] == "strict" and s["complete"] is True
    assert s["parts"]["wp"]["rc"] == 0 and s["tla_trace"] == {"traces": 2, "passed": 2}
    # the absolute BUILD wins over the repository root
    for name in ("summary.json", "junit.xml", "report.md"):
        assert os.path.exists(os.path.join(proof.proof, name)), name


def test_report_lists_every_assumption_and_the_wp_cache_per_module(proof):
    res = proof.run()
    assert_passes(res)
    with open(os.path.join(proof.proof, "report.md"), encoding="utf-8") as f:
        md = f.read()
    with open(os.path.join(ROOT, "proofs", "assumptions.json"), encoding="utf-8") as f:
        ids = [a["id"] for a in json.load(f)]
    assert ids and all(f"| {i} |" in md for i in ids)
    for line in ("sched: 1000 prover verdicts replayed from the WP cache, 400 fresh",
                 "ring: 6700 prover verdicts replayed from the WP cache, 0 fresh"):
        assert line in md and line in res.out, line


def test_optional_summaries_may_be_absent(proof):
    # parts outside the default list that did not run: their summaries may be absent
    proof.edit("parts.json", lambda p: p.pop("chibios-cbmc"))
    for rel in ("tla/trace/summary.json", "hal_chibios/cbmc-summary.json",
                "selftest/summary.json"):
        proof.drop(rel)
    assert_passes(proof.run("--default-parts",
                            " ".join(p for p in DEFAULT_PARTS if p != "chibios-cbmc")))


# ------------------------------------------------------------------------------ parts and summaries

def test_part_exit_status_fails(proof):
    proof.edit("parts.json", lambda p: p["tla"].update(rc=1))
    assert_fails(proof.run(), "part tla", "status 1")


def test_missing_required_summary_fails(proof):
    proof.drop("tla/summary.json")
    assert_fails(proof.run(), "part tla", "missing")


def test_missing_required_summary_fails_without_parts_json(proof):
    proof.drop("parts.json")
    proof.drop("cbmc/test/summary.json")
    assert_fails(proof.run(), "part cbmc-test", "missing")


def test_required_part_outside_the_default_list_may_be_absent(proof):
    # PROVE_PARTS="wp tla" on a tree without CBMC: cbmc is not in prove.sh's default list
    proof.put("parts.json", {"wp": {"rc": 0, "seconds": 1.0}, "tla": {"rc": 0, "seconds": 1.0}})
    proof.drop("cbmc/summary.json")
    proof.put_json(proof.baseline, {k: v for k, v in BASELINE.items() if k != "cbmc.passed"})
    assert_passes(proof.run("--default-parts", "wp tla tla-trace-mission"))
    assert_fails(proof.run("--default-parts", " ".join(DEFAULT_PARTS)), "part cbmc", "missing")


def test_part_that_ran_without_its_summary_fails(proof):
    proof.edit("parts.json", lambda p: p.update({"tla-trace": {"rc": 0, "seconds": 9.0}}))
    proof.drop("tla/trace/summary.json")
    assert_fails(proof.run(), "part tla-trace", "missing")


def test_unreadable_summary_fails(proof):
    with open(os.path.join(proof.proof, "cbmc/summary.json"), "w", encoding="utf-8") as f:
        f.write('{"harnesses": 3,')
    assert_fails(proof.run(), "part cbmc", "unreadable")


def test_summary_older_than_its_part_fails(proof):
    proof.edit("parts.json", lambda p: p["wp"].update(started=time.time() + 100.0))
    assert_fails(proof.run(), "part wp", "stale")


# ------------------------------------------------------------------------------ WP

def unprove(wp):
    wp["proved"] = 6250
    m = wp["modules"]["sched"]
    m["proved"] = 1050
    m["failures"] = ["mt_sched_tick: typed_mt_sched_tick_ensures_budget_kept "
                     "{'total': 1, 'valid': 0}"]


def test_wp_goal_unproved_fails(proof):
    proof.edit("wp/summary.json", unprove)
    res = proof.run()
    assert_fails(res, "WP", "6250/6300 goals proved")
    assert_fails(res, "WP module sched", "typed_mt_sched_tick_ensures_budget_kept")


def test_wp_no_goal_fails(proof):
    proof.edit("wp/summary.json", lambda w: w.update(goals=0, proved=0, modules={}))
    assert_fails(proof.run(), "WP: 0/0 goals proved")


def test_wp_smoke_test_proved_fails(proof):
    def prove_smoke(wp):
        wp["smoke_passed"] = 1799
        m = wp["modules"]["ring"]
        m["smoke_passed"] = 1499
        m["failures"] = ["mt_ring_write: _wp_smoke_mt_ring_write_dead_code_s12 "
                         "{'total': 1, 'valid': 0}"]
    proof.edit("wp/summary.json", prove_smoke)
    res = proof.run()
    assert_fails(res, "1799/1800 smoke tests passed")
    assert_fails(res, "WP module ring", "_wp_smoke_mt_ring_write_dead_code_s12")


def test_wp_gate_pass_false_fails(proof):
    proof.edit("wp/summary.json", lambda w: w.update({"pass": False}))
    assert_fails(proof.run(), "WP gate did not pass", "pass: false")


AXIOM = "kernel/include/mt/ring.h:12: ACSL keyword 'axiom'"


def test_wp_axiom_finding_not_listed_fails(proof):
    proof.edit("wp/summary.json", lambda w: w.update(acsl_forbidden=[AXIOM]))
    assert_fails(proof.run(), AXIOM, "not accepted by an assumption")


def assumptions_with_site(proof, site):
    with open(os.path.join(ROOT, "proofs", "assumptions.json"), encoding="utf-8") as f:
        items = json.load(f)
    items.append({"id": "T1", "tool": "WP", "what": "ring axiom", "why": "test",
                  "acsl_sites": [site]})
    path = os.path.join(proof.tmp, "assumptions.json")
    proof.put_json(path, items)
    return path


def test_wp_axiom_finding_listed_in_acsl_sites_passes(proof):
    proof.edit("wp/summary.json", lambda w: w.update(acsl_forbidden=[AXIOM]))
    path = assumptions_with_site(proof, "kernel/include/mt/ring.h:axiom:RingCountLaw")
    res = proof.run("--assumptions", path)
    assert_passes(res)
    with open(os.path.join(proof.proof, "report.md"), encoding="utf-8") as f:
        assert f"{AXIOM}: accepted by assumption T1" in f.read()


@pytest.mark.parametrize("site", ["kernel/include/mt/sem.h:axiom:RingCountLaw",
                                  "kernel/include/mt/ring.h:admit:RingCountLaw"])
def test_wp_acsl_site_matches_path_and_keyword(proof, site):
    proof.edit("wp/summary.json", lambda w: w.update(acsl_forbidden=[AXIOM]))
    res = proof.run("--assumptions", assumptions_with_site(proof, site))
    assert_fails(res, AXIOM, "not accepted")


def test_unreadable_baseline_fails(proof):
    with open(proof.baseline, "w", encoding="utf-8") as f:
        f.write("{")
    assert_fails(proof.run(), proof.baseline, "unreadable")


def test_malformed_acsl_site_fails(proof):
    path = assumptions_with_site(proof, "kernel/include/mt/ring.h")
    assert_fails(proof.run("--assumptions", path), "T1", "acsl_sites entry")


def test_requirements_matrix_missing_fails(proof):
    proof.edit("wp/summary.json", lambda w: w.pop("requirements"))
    assert_fails(proof.run(), "traceability: no requirements matrix")


def test_requirement_not_discharged_fails(proof):
    def unprove(w):
        r = w["requirements"][0]
        r.update(ok=False, problems=["clause mt_ring_write:data: not proved"])
        r["clauses"][0]["state"] = "not proved"
    proof.edit("wp/summary.json", unprove)
    res = proof.run()
    assert_fails(res, "traceability: requirement R-1", "mt_ring_write:data: not proved")


def test_report_prints_the_traceability_matrix(proof):
    res = proof.run()
    assert res.rc == 0, res.out
    with open(os.path.join(proof.proof, "report.md"), encoding="utf-8") as f:
        md = f.read()
    assert "## Traceability" in md and "| R-1 ring writes in order | 1/1: `mt_ring_write:data`" in md


def test_wp_canary_not_run_fails(proof):
    proof.edit("wp/summary.json", lambda w: w.update(smoke_canary="not run"))
    assert_fails(proof.run(), "smoke canary: not run")


def test_wp_canary_miss_fails(proof):
    proof.edit("wp/summary.json",
               lambda w: w.update(smoke_canary="wp-canary: FAIL (canary_false_requires)"))
    assert_fails(proof.run(), "smoke canary", "canary_false_requires")


def test_wp_log_finding_fails(proof):
    proof.edit("wp/summary.json", lambda w: w["modules"]["sched"].update(
        fatal=["missing assigns clause: mt_sched_add"]))
    assert_fails(proof.run(), "WP module sched", "missing assigns clause: mt_sched_add")


# ------------------------------------------------------------------------------ CBMC

def cbmc_result(proof, name, **fields):
    def change(cb):
        r = next(x for x in cb["results"] if x["function"] == name)
        r.update(fields)
        cb["passed"] = sum(x["passed"] is True for x in cb["results"])
    proof.edit("cbmc/summary.json", change)


def test_cbmc_failed_harness_fails(proof):
    cbmc_result(proof, "mt_ring_write", passed=False, failed=1, failures=[
        {"property": "mt_ring_write.assertion.3", "status": "FAILURE",
         "description": "no_lost_item", "where": "kernel/src/ring.c:40"}])
    res = proof.run()
    assert_fails(res, "CBMC harness mt_ring_write", "failed property", "no_lost_item")
    assert_fails(res, "CBMC: 2/3 harnesses passed")


@pytest.mark.parametrize("flag", [True, False], ids=["timeout-flag", "error-text-only"])
def test_cbmc_timeout_fails_as_timeout(proof, flag):
    fields = {"passed": False, "error": "make: *** [result] Killed\ntimeout: killed after 600 s"}
    if flag:
        fields["timeout"] = True
    cbmc_result(proof, "mt_sched_tick", **fields)
    res = proof.run()
    assert_fails(res, "CBMC harness mt_sched_tick", "timeout (timeout: killed after 600 s)")
    assert not any("mt_sched_tick" in p and "error:" in p for p in res.problems)


@pytest.mark.parametrize("fields,cause", [
    ({"coverage": 61.0}, "coverage 61.0% below 90%"),
    ({"reach": [{"witness": "full_ring_path", "reached": False}]},
     "witness not reached: full_ring_path"),
    ({"error": "goto-cc: error: syntax error"}, "error: goto-cc: error: syntax error"),
])
def test_cbmc_coverage_witness_error_fail(proof, fields, cause):
    cbmc_result(proof, "mt_sched_add", passed=False, **fields)
    assert_fails(proof.run(), "CBMC harness mt_sched_add", cause)


def test_cbmc_pending_harness_fails(proof):
    cbmc_result(proof, "mt_sched_tick", passed=False, pending="takes 40 min with 8 tasks")
    assert_fails(proof.run(), "CBMC harness mt_sched_tick", "pending", "takes 40 min")


def test_cbmc_missing_proof_fails(proof):
    proof.edit("cbmc/summary.json", lambda c: c.update(missing_proofs=["mt_bus_publish"]))
    assert_fails(proof.run(), "mt_bus_publish", "no harness")


def split_harness(proof, passed):
    """A second harness of mt_sched_tick, on part of its clauses (B17)."""
    def change(cb):
        cb["results"].append(dict(harness("mt_sched_tick__b"), contract="mt_sched_tick",
                                  passed=passed, failed=0 if passed else 2))
        cb["harnesses"] += 1
        cb["passed"] += passed
    proof.edit("cbmc/summary.json", change)


def function_row(proof, fn):
    with open(os.path.join(proof.proof, "report.md"), encoding="utf-8") as f:
        return next(line for line in f if line.startswith(f"| sched | {fn} |"))


def test_cbmc_split_harnesses_one_row(proof):
    split_harness(proof, True)
    assert_passes(proof.run())
    assert "| pass (2 harnesses) |" in function_row(proof, "mt_sched_tick")


def test_cbmc_split_harness_failing_fails_its_function(proof):
    split_harness(proof, False)
    assert_fails(proof.run(), "mt_sched_tick__b")
    row = function_row(proof, "mt_sched_tick")
    assert "mt_sched_tick: pass" in row and "mt_sched_tick__b: FAIL (2 properties)" in row


def test_cbmc_unchecked_clause_fails(proof):
    # a function split over proof folders (CLAUSES) whose folders leave a clause out
    proof.edit("cbmc/summary.json", lambda c: c.update(
        clauses_unchecked=["mt_sched_run: assigns (checked by no proof folder)"]))
    assert_fails(proof.run(), "contract clause mt_sched_run: assigns", "checked by no proof folder")


def test_cbmc_no_unchecked_list_fails(proof):
    proof.edit("cbmc/summary.json", lambda c: c.pop("clauses_unchecked"))
    assert_fails(proof.run(), "no clauses_unchecked list")


def test_cbmc_no_harness_fails(proof):
    proof.edit("cbmc/summary.json", lambda c: c.update(harnesses=0, passed=0, results=[]))
    assert_fails(proof.run(), "CBMC: 0/0 harnesses passed")


# ------------------------------------------------------------------------------ the other parts

def test_translator_failure_fails(proof):
    proof.edit("cbmc/test/summary.json", lambda t: t.update(
        passed=18, failed=1, not_passed=["test_mutated_ensures_rejected"]))
    assert_fails(proof.run(), "translator tests", "18/19", "test_mutated_ensures_rejected")


def test_tlc_model_unexpected_fails(proof):
    def change(t):
        t["models"][1].update(ok=False, result="pass")
        t["passed"] = 1
    proof.edit("tla/summary.json", change)
    assert_fails(proof.run(), "TLC model Ring_lost_item", "expected invariant, got pass")


def test_mission_trace_unexpected_fails(proof):
    def change(t):
        t["traces"][1].update(ok=False, result="accept")
        t["passed"] = 1
    proof.edit("tla/trace-mission/summary.json", change)
    assert_fails(proof.run(), "tla-trace-mission", "mission_skip_verify", "got accept")


def test_ring_trace_unexpected_fails(proof):
    def change(t):
        t["traces"][0].update(ok=False, result="deadlock")
        t["passed"] = 2
    proof.edit("tla/trace/summary.json", change)
    assert_fails(proof.run(), "make tla-trace)", "ring_seed_1", "got deadlock")


def test_chibios_cbmc_failure_fails(proof):
    def change(c):
        c["results"][1].update(passed=False, coverage_reached=2)
        c["passed"] = 1
    proof.edit("hal_chibios/cbmc-summary.json", change)
    assert_fails(proof.run(), "ChibiOS port CBMC harness harness_ticks_ceil", "2/3")


def test_cbmc_max_failure_fails(proof):
    # make prove-cold's capacity-maximum tier: present only when it ran, judged like make cbmc
    tier = {"harnesses": 2, "passed": 2, "results": [harness("mt_bring_write"),
                                                      harness("mt_oring_push")]}
    proof.put("cbmc/summary-max.json", tier)
    assert_passes(proof.run())
    tier["results"][1].update(passed=False, failed=1, failures=[
        {"property": "mtc_post.assertion.1", "description": "ensures full"}])
    tier["passed"] = 1
    proof.put("cbmc/summary-max.json", tier)
    res = proof.run()
    assert_fails(res, "CBMC capacity-maximum tier harness mt_oring_push", "ensures full")
    assert_fails(res, "CBMC capacity-maximum tier", "1/2 harnesses passed")


@pytest.mark.parametrize("old", [False, True], ids=["ok-format", "killed-format"])
def test_selftest_mutant_not_rejected_fails(proof, old):
    def change(s):
        r = s["results"][1]
        if old:
            for k in ("ok", "wp", "cbmc"):
                r.pop(k)
            s["results"][0].pop("ok")
            s["results"][0]["killed"] = True
            r["killed"] = False
            s.pop("ok")
            s["killed"] = 1
        else:
            r.update(ok=False, reason="WP accepted it (must reject)")
            s["ok"] = 1
    proof.edit("selftest/summary.json", change)
    assert_fails(proof.run(), "mutant M2", "mt_sched_tick", "not rejected")


def test_count_below_baseline_floor_fails(proof):
    proof.put_json(proof.baseline, dict(BASELINE, **{"wp.proved": 6400}))
    assert_fails(proof.run(), "baseline: wp.proved = 6300 < 6400")


def test_committed_baseline_is_the_default_floor(proof):
    with open(os.path.join(ROOT, "proofs", "baseline.json"), encoding="utf-8") as f:
        floor = json.load(f)["translator.passed"]
    proof.edit("cbmc/test/summary.json", lambda t: t.update(tests=1, passed=1))
    res = proof.run(baseline=False)
    assert_fails(res, f"translator.passed = 1 < {floor}", "proofs/baseline.json")


def put_mode(proof, mode):
    with open(os.path.join(proof.proof, "cache.txt"), "w", encoding="utf-8") as f:
        f.write(mode + "\n")


@pytest.mark.parametrize("mode,words", [("cold", "every cache emptied"),
                                         ("warm", "Frama-C on every module from source")])
def test_report_names_the_run_mode(proof, mode, words):
    put_mode(proof, mode)
    res = proof.run()
    assert_passes(res)
    assert res.summary["mode"] == mode and words in res.summary["mode_text"]
    assert f"run: {mode} (" in res.out and f"PROVE OK: everything proved (strict gate, {mode})" \
        in res.out
    with open(os.path.join(proof.proof, "report.md"), encoding="utf-8") as f:
        assert f"Run: {mode} (" in f.read()


def replay_sched(wp):
    wp["modules"]["sched"]["replayed_local"] = "2026-11-26 22:16:37 UTC"
    wp["modules_run"] = ["ring"]
    wp["modules_replayed_local"] = ["sched"]


@pytest.mark.parametrize("mode", ["warm", "cold"])
def test_wp_module_replayed_from_a_local_run_fails_in_make_prove(proof, mode):
    put_mode(proof, mode)
    proof.edit("wp/summary.json", replay_sched)
    assert_fails(proof.run(), "WP module sched", f"not proved in this {mode} run")


def test_reprove_passes_and_names_the_replayed_modules(proof):
    put_mode(proof, "reprove")
    proof.edit("wp/summary.json", replay_sched)
    res = proof.run()
    assert res.rc == 0 and res.problems == [], res.out
    assert "REPROVE OK" in res.out and "not proved now: WP sched" in res.out
    assert "\nPROVE OK" not in res.out
    with open(os.path.join(proof.proof, "report.md"), encoding="utf-8") as f:
        assert "WP modules replayed, NOT proved in this run" in f.read()


def replay_tla(t):
    t["replayed_local"] = "2026-11-29T05:20:00"


@pytest.mark.parametrize("mode", ["warm", "cold"])
def test_tlc_replayed_from_a_local_run_fails_in_make_prove(proof, mode):
    put_mode(proof, mode)
    proof.edit("tla/summary.json", replay_tla)
    assert_fails(proof.run(), "TLC: models replayed from the local run",
                 f"not checked in this {mode} run")


def test_reprove_passes_and_names_replayed_tlc(proof):
    put_mode(proof, "reprove")
    proof.edit("tla/summary.json", replay_tla)
    res = proof.run()
    assert res.rc == 0 and res.problems == [], res.out
    assert "REPROVE OK" in res.out and "not proved now: TLC's models" in res.out
    with open(os.path.join(proof.proof, "report.md"), encoding="utf-8") as f:
        assert "REPLAYED from this tree's run of 2026-11-29T05:20:00" in f.read()


@pytest.mark.parametrize("mode", ["baseline", "full"])
def test_prove_gate_does_not_soften_the_gate(proof, mode):
    proof.edit("wp/summary.json", unprove)
    res = proof.run(env={"PROVE_GATE": mode})
    assert_fails(res, "6250/6300 goals proved")
    assert ("warning: PROVE_GATE=baseline is ignored" in res.out) == (mode == "baseline")


def test_junit_has_one_failing_testcase_per_problem_kind(proof):
    cbmc_result(proof, "mt_sched_tick", passed=False, pending="slow")
    proof.edit("wp/summary.json", lambda w: w.update(smoke_canary="not run"))
    assert proof.run().rc == 1
    with open(os.path.join(proof.proof, "junit.xml"), encoding="utf-8") as f:
        xml = f.read()
    suites = {s.get("name"): s for s in ET.fromstring(xml)}
    cases = {c.get("name"): c.find("failure") is not None for c in suites["gate"]}
    # the pending harness also lowers the CBMC count, below the floor of 3
    failing = {"wp-canary", "cbmc-pending", "cbmc-count", "baseline"}
    assert {k for k, bad in cases.items() if bad} == failing and "wp-goals" in cases
    assert suites["gate"].get("failures") == str(len(failing))
    pending = [c for c in suites["cbmc"] if c.get("name") == "mt_sched_tick"][0]
    assert "pending" in pending.find("failure").get("message")
