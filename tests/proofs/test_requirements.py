# SPDX-License-Identifier: Apache-2.0
"""tools/requirements.py: a requirement is discharged only when every clause it names is a
proved WP goal, every test exists and every TLA+ property is checked by a passing model.

    /usr/bin/python3 -m pytest -q tests/proofs/test_requirements.py
"""
import json
import os
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import requirements as reqs  # noqa: E402

GOOD = {"id": "R-X", "text": "no signal is lost",
        "clauses": ["mt_sem_signal_i:set.token", "mt_sem_signal:given"],
        "tests": ["SemSim.SignalThenWait"], "models": ["Sem.NoLostWakeup"]}


def wp_dir(tmp_path, goals):
    """A WP folder with one module whose report holds `goals` ({name: proved?})."""
    d = tmp_path / "wp"
    (d / "sem").mkdir(parents=True)
    per = {n: {"wp:main": {"total": 1, "valid": 1 if ok else 0}} for n, ok in goals.items()}
    (d / "sem" / "report.json").write_text(json.dumps({"wp:functions": {"f": per}}))
    return str(d)


def run(tmp_path, req, goals):
    d = wp_dir(tmp_path, goals)
    (res,) = reqs.check([req], reqs.wp_goals(d, ["sem"]), ROOT)
    return res


PROVED = {"mt_sem_signal_i_set_ensures_token": True, "mt_sem_signal_ensures_given_part1": True,
          "mt_sem_signal_ensures_given_part2": True}


def test_a_discharged_requirement_is_ok(tmp_path):
    res = run(tmp_path, GOOD, PROVED)
    assert res["ok"], res["problems"]
    assert [c["state"] for c in res["clauses"]] == ["proved", "proved"]


def test_a_clause_not_proved_fails(tmp_path):
    res = run(tmp_path, GOOD, dict(PROVED, mt_sem_signal_ensures_given_part2=False))
    assert not res["ok"] and res["problems"] == ["clause mt_sem_signal:given: not proved"]


def test_a_clause_without_a_goal_fails(tmp_path):
    goals = {k: v for k, v in PROVED.items() if "signal_i" not in k}
    res = run(tmp_path, GOOD, goals)
    assert res["problems"] == ["clause mt_sem_signal_i:set.token: missing"]


def test_a_malformed_clause_fails(tmp_path):
    res = run(tmp_path, dict(GOOD, clauses=["mt_sem_signal given"]), PROVED)
    assert res["problems"] == ["clause mt_sem_signal given: malformed"]


def test_a_missing_test_fails(tmp_path):
    res = run(tmp_path, dict(GOOD, tests=["SemSim.NoSuchTest"]), PROVED)
    assert res["problems"] == ["test SemSim.NoSuchTest: no such TEST in tests/"]


def test_a_model_property_no_passing_configuration_checks_fails(tmp_path):
    # defined in Ring.tla, but only configurations that must fail name it
    res = run(tmp_path, dict(GOOD, models=["Ring.NeverFull", "Sem.NoSuchProperty"]), PROVED)
    assert res["problems"] == [
        "model Ring.NeverFull: not checked by a passing configuration",
        "model Sem.NoSuchProperty: not checked by a passing configuration"]


def test_a_property_on_a_continuation_line_is_checked(tmp_path):
    """An INVARIANTS list goes on on indented lines (tla/cfg/Mission_nested.cfg's second line
    names LookAheadBounded); a commented-out name is not checked."""
    root = tmp_path / "root"
    (root / "tla" / "cfg").mkdir(parents=True)
    (root / "tla" / "M.tla").write_text("---- MODULE M ----\nA == TRUE\nB == TRUE\nC == TRUE\n====\n")
    (root / "tla" / "cfg" / "M.cfg").write_text(
        "CONSTANTS\n    K = 1\nINVARIANTS A\n    B \\* C\n")
    (root / "tla" / "models.json").write_text(json.dumps(
        {"models": [{"name": "M", "module": "M", "config": "cfg/M.cfg", "expect": "pass"}]}))
    assert reqs.checked_properties(str(root)) == {"M.A", "M.B"}


def test_tests_and_models_do_not_replace_a_clause(tmp_path):
    res = run(tmp_path, dict(GOOD, clauses=[]), PROVED)
    assert res["problems"] == ["no contract clause"]


def test_the_committed_file_names_only_what_exists():
    """Every test and model of proofs/requirements.json exists; every clause is well formed
    and names a function of the kernel's public headers (its goals are checked by make wp)."""
    rs = reqs.load(os.path.join(ROOT, "proofs", "requirements.json"))
    assert len(rs) >= 15 and len({r["id"] for r in rs}) == len(rs)
    res = reqs.check(rs, {}, ROOT)
    sys.path.insert(0, os.path.join(ROOT, "proofs", "cbmc"))
    import run as cbmc_run  # noqa: E402  (the public function list)
    public = cbmc_run.header_functions()
    for r in res:
        assert all(p.startswith("clause ") and p.endswith(": missing") for p in r["problems"]), \
            (r["id"], r["problems"])
        for c in r["clauses"]:
            assert reqs.CLAUSE_RE.match(c["name"]).group("fn") in public, c["name"]
