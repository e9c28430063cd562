# SPDX-License-Identifier: Apache-2.0
"""The writers of what tools/proof_report.py reads, with stub tools instead of make, CBMC and
the installer: tools/prove.sh (parts.json, its exit status), hal_chibios/proofs/run_cbmc.sh
(cbmc-summary.json) and proofs/cbmc/run.py's "timeout" flag. No prover runs.

    /usr/bin/python3 -m pytest -q tests/proofs/test_prove_driver.py
"""
import importlib.util
import json
import os
import shutil
import signal
import stat
import subprocess
import sys
import time

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_proof_report import DEFAULT_PARTS, Proof, assert_fails, passing_set  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

STUB_BOOTSTRAP = """#!/bin/sh
echo "stub bootstrap $*"
"""
# make PART: touches the part's summary (unless the part is in STUB_STALE), exits 2 for the
# parts in STUB_FAIL, takes 3 s for the parts in STUB_SLOW.
STUB_MAKE = """#!/usr/bin/env bash
part="$2"
echo "stub make $part"
case "$part" in
    wp) f=wp/summary.json ;;
    cbmc) f=cbmc/summary.json ;;
    cbmc-test) f=cbmc/test/summary.json ;;
    tla) f=tla/summary.json ;;
    tla-trace-mission) f=tla/trace-mission/summary.json ;;
    chibios-cbmc) f=hal_chibios/cbmc-summary.json ;;
    *) f="" ;;
esac
case " ${STUB_STALE:-} " in
    *" $part "*) ;;
    *) if [ -n "$f" ]; then touch "$BUILD/proof/$f"; fi ;;
esac
case " ${STUB_FAIL:-} " in *" $part "*) exit 2 ;; esac
case " ${STUB_SLOW:-} " in *" $part "*) sleep 3 ;; esac
exit 0
"""
# cbmc ... --function H [--cover assertion]: the property run fails for the harnesses in
# STUB_FAILING; the coverage run misses one assertion of the harnesses in STUB_UNREACHED.
STUB_CBMC = """#!/usr/bin/env bash
h=""
cover=no
while [ "$#" -gt 0 ]; do
    case "$1" in --function) h="$2"; shift ;; --cover) cover=yes ;; esac
    shift
done
if [ "$cover" = yes ]; then
    echo "[$h.coverage.1] line 10 assertion: SATISFIED"
    case " ${STUB_UNREACHED:-} " in
        *" $h "*) echo "[$h.coverage.2] line 11 assertion: FAILED" ;;
        *) echo "[$h.coverage.2] line 11 assertion: SATISFIED" ;;
    esac
    exit 0
fi
case " ${STUB_FAILING:-} " in *" $h "*) echo "[$h.assertion.1] FAILURE"; exit 10 ;; esac
echo "VERIFICATION SUCCESSFUL"
"""


def put_exec(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)


def copy_in(repo, rel):
    os.makedirs(os.path.dirname(os.path.join(repo, rel)), exist_ok=True)
    shutil.copy2(os.path.join(ROOT, rel), os.path.join(repo, rel))


def stub_path(tmp, name, text):
    put_exec(os.path.join(tmp, "bin", name), text)
    return os.path.join(tmp, "bin") + os.pathsep + os.environ["PATH"]


# ------------------------------------------------------------------------------ tools/prove.sh

class Prove:
    """A copy of the prove driver and the report in a tree of their own, with stub make."""

    def __init__(self, tmp):
        self.repo = os.path.join(str(tmp), "repo")
        for rel in ("tools/prove.sh", "tools/proof_report.py", "tools/proof_gate.py",
                    "tools/requirements.py"):
            copy_in(self.repo, rel)
        put_exec(os.path.join(self.repo, "tools", "bootstrap.sh"), STUB_BOOTSTRAP)
        put_exec(os.path.join(self.repo, "proofs", "cbmc", "cbmc.mk"), "")
        self.path = stub_path(str(tmp), "make", STUB_MAKE)
        self.build = os.path.join(str(tmp), "build")
        self.proof = os.path.join(self.build, "proof")
        for rel, value in passing_set().items():
            if rel not in ("parts.json", "timing.json"):
                Proof.put_json(os.path.join(self.proof, rel), value)

    def run(self, **env):
        e = {k: v for k, v in os.environ.items() if k not in ("PROVE_GATE", "PROVE_PARTS")}
        e.update(BUILD=self.build, PATH=self.path, **env)
        p = subprocess.run(["bash", os.path.join(self.repo, "tools", "prove.sh")],
                           capture_output=True, text=True, env=e, cwd=self.build, timeout=120)
        return p.returncode, p.stdout + p.stderr

    def parts(self):
        with open(os.path.join(self.proof, "parts.json"), encoding="utf-8") as f:
            return json.load(f)


@pytest.fixture
def prove(tmp_path):
    return Prove(tmp_path)


def test_prove_sh_records_every_part_and_passes(prove):
    rc, out = prove.run()
    assert rc == 0, out
    assert "PROVE OK" in out
    parts = prove.parts()
    assert sorted(parts) == sorted(DEFAULT_PARTS)
    for p in parts.values():
        assert p["rc"] == 0 and isinstance(p["seconds"], float) and p["started"] > 0
        assert p["lane"] in (1, 2)
    with open(os.path.join(prove.proof, "timing.json"), encoding="utf-8") as f:
        assert sorted(json.load(f)) == sorted(DEFAULT_PARTS)


def test_prove_sh_exit_status_is_the_reports(prove):
    rc, out = prove.run(STUB_FAIL="tla")
    assert rc == 1, out
    assert prove.parts()["tla"]["rc"] == 2
    assert "  - part tla: make tla exited with status 2" in out


def test_prove_sh_gate_ignores_prove_gate_baseline(prove):
    rc, out = prove.run(STUB_FAIL="cbmc", PROVE_GATE="baseline")
    assert rc == 1, out
    assert "PROVE_GATE=baseline is ignored" in out and "part cbmc: make cbmc exited" in out


def test_prove_sh_summary_not_written_by_its_part_is_stale(prove):
    old = time.time() - 3600
    os.utime(os.path.join(prove.proof, "cbmc", "summary.json"), (old, old))
    rc, out = prove.run(STUB_STALE="cbmc")
    assert rc == 1, out
    assert "part cbmc: summary" in out and "stale" in out


def test_prove_sh_drops_summaries_of_optional_parts_it_does_not_run(prove):
    # an earlier make prove-selftest left a summary with a mutant not rejected; a make prove
    # that runs no mutants neither reads it nor fails on it
    path = os.path.join(prove.proof, "selftest", "summary.json")
    with open(path, encoding="utf-8") as f:
        st = json.load(f)
    st["results"][1].update(ok=False, reason="CBMC time-out")
    st["ok"] = 1
    Proof.put_json(path, st)
    Proof.put_json(os.path.join(prove.proof, "cbmc", "summary-max.json"), {"harnesses": 0})
    rc, out = prove.run()
    assert rc == 0, out
    assert not os.path.exists(path)
    assert not os.path.exists(os.path.join(prove.proof, "cbmc", "summary-max.json"))
    assert os.path.exists(os.path.join(prove.proof, "hal_chibios", "cbmc-summary.json"))


def test_prove_sh_keeps_the_summary_of_an_optional_part_it_runs(prove):
    # the stub make writes no selftest summary: the one left is kept, and judged stale
    path = os.path.join(prove.proof, "selftest", "summary.json")
    old = time.time() - 3600
    os.utime(path, (old, old))
    rc, out = prove.run(PROVE_EXTRA="prove-selftest-ci")
    assert rc == 1, out
    assert os.path.exists(path)
    assert "part prove-selftest-ci: summary" in out and "stale" in out


def test_prove_sh_prove_parts_runs_only_those(prove):
    rc, out = prove.run(PROVE_PARTS="wp tla")
    assert rc == 0, out
    assert list(prove.parts()) == ["wp", "tla"] and "stub make cbmc" not in out


def test_prove_sh_lanes_take_the_parts_from_one_queue(prove):
    rc, out = prove.run()
    assert rc == 0, out
    assert ("2 lane(s) take the parts in this order: cbmc wp tla tla-trace-mission cbmc-test "
            "chibios-cbmc\n") in out
    # while one lane is in a long part, the other takes every part that waits
    for slow in ("wp", "cbmc"):
        rc, out = prove.run(STUB_SLOW=slow)
        assert rc == 0, out
        lanes = {p: e["lane"] for p, e in prove.parts().items()}
        assert lanes[slow] in (1, 2) and len(lanes) == 6, lanes
        assert all(lane == 3 - lanes[slow] for p, lane in lanes.items() if p != slow), lanes
    rc, out = prove.run(PROVE_LANES="1")
    assert rc == 0, out
    assert list(prove.parts()) == ["cbmc", "wp", "tla", "tla-trace-mission", "cbmc-test",
                                   "chibios-cbmc"]
    assert {e["lane"] for e in prove.parts().values()} == {1}


def test_prove_sh_queue_gives_each_part_to_one_lane(prove):
    """Two lanes taking 40 instant parts as fast as they can: each part runs once."""
    names = [f"p{i:02d}" for i in range(40)]
    rc, out = prove.run(PROVE_PARTS=" ".join(names))
    ran = [line.split()[-1] for line in out.splitlines() if line.startswith("stub make p")]
    assert sorted(ran) == names, out
    assert sorted(prove.parts()) == names


# ------------------------------------------------------------------------------ run_cbmc.sh

class Chibios:
    """A copy of hal_chibios/proofs/run_cbmc.sh in a tree of its own, with stub cbmc."""

    def __init__(self, tmp):
        self.tmp = str(tmp)
        self.repo = os.path.join(self.tmp, "repo")
        copy_in(self.repo, "hal_chibios/proofs/run_cbmc.sh")
        self.path = stub_path(self.tmp, "cbmc", STUB_CBMC)

    def run(self, build, *harnesses, **env):
        e = dict(os.environ, BUILD=build, PATH=self.path, **env)
        p = subprocess.run(["bash", os.path.join(self.repo, "hal_chibios", "proofs", "run_cbmc.sh")]
                           + list(harnesses), capture_output=True, text=True, env=e,
                           cwd=self.tmp, timeout=60)
        where = build if os.path.isabs(build) else os.path.join(self.repo, build)
        with open(os.path.join(where, "proof", "hal_chibios", "cbmc-summary.json"),
                  encoding="utf-8") as f:
            return p.returncode, p.stdout + p.stderr, json.load(f)


def test_run_cbmc_writes_the_summary_under_a_relative_build(tmp_path):
    rc, out, s = Chibios(tmp_path).run(
        "b", "harness_wrap", "harness_ticks_ceil", "harness_subtick_monotonic",
        STUB_FAILING="harness_ticks_ceil", STUB_UNREACHED="harness_subtick_monotonic")
    assert rc == 1, out
    assert s["harnesses"] == 3 and s["passed"] == 1
    got = {r["name"]: (r["passed"], r["coverage_reached"], r["coverage_total"])
           for r in s["results"]}
    assert got == {"harness_wrap": (True, 2, 2), "harness_ticks_ceil": (False, 2, 2),
                   "harness_subtick_monotonic": (False, 1, 2)}
    assert all(isinstance(r["seconds"], int) for r in s["results"])


def test_run_cbmc_passes_every_default_harness_under_an_absolute_build(tmp_path):
    rc, out, s = Chibios(tmp_path).run(str(tmp_path / "abs"))
    assert rc == 0, out
    assert s["harnesses"] == 5 and s["passed"] == 5


def test_run_cbmc_summary_failure_fails_the_report(tmp_path):
    _, _, s = Chibios(tmp_path).run("b", "harness_wrap", "harness_ticks_ceil",
                                    STUB_FAILING="harness_ticks_ceil")
    proof = Proof(tmp_path / "report")
    proof.put("hal_chibios/cbmc-summary.json", s)
    assert_fails(proof.run(), "ChibiOS port CBMC harness harness_ticks_ceil", "not passed")


# ------------------------------------------------------------------------------ run.py timeout

def load_run_py():
    spec = importlib.util.spec_from_file_location(
        "cbmc_run", os.path.join(ROOT, "proofs", "cbmc", "run.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.parametrize("rc,flag", [(-signal.SIGKILL, True), (2, False)])
def test_run_py_flags_a_property_run_killed_by_the_timeout(tmp_path, monkeypatch, rc, flag):
    run = load_run_py()
    monkeypatch.setattr(run, "run_make", lambda name, big, target, timeout: (
        rc, 5.0, 1.0, "partial" + ("\ntimeout: killed after 5.0 s" if flag else "")))
    f, _, _ = run.property_run("mt_x", False, str(tmp_path), 5.0, {}, None, "fresh")
    assert f["passed"] is False and f.get("timeout") is (True if flag else None)


def test_run_py_flags_a_coverage_run_killed_by_the_timeout(tmp_path, monkeypatch):
    run = load_run_py()
    os.makedirs(tmp_path / "mt_x")
    with open(tmp_path / "mt_x" / "result.json", "w", encoding="utf-8") as f:
        json.dump([{"result": [{"property": "p", "status": "SUCCESS"}]},
                   {"cProverStatus": "success"}], f)
    codes = {"result": 0, "coverage": -signal.SIGKILL}
    monkeypatch.setattr(run, "input_keys", lambda name, big: (None, None))
    monkeypatch.setattr(run, "run_make", lambda name, big, target, timeout: (
        codes[target], 1.0, 1.0, "out"))
    e = run.run_one("mt_x", False, str(tmp_path), 5.0, {}, "fresh")
    assert e["passed"] is False and e["timeout"] is True and e["properties"] == 1


def test_run_py_saves_records_whole(tmp_path, monkeypatch):
    """Records are merged into the file as it is now and written whole (renamed into place), so
    a run stopped while saving, or a run of other harnesses beside it, loses no record."""
    run = load_run_py()
    path = str(tmp_path / "records.json")
    monkeypatch.setattr(run, "RECORD", path)
    run.save_records({"mt_a": {"key": "1"}})
    run.save_records(dict(run.load_records(), **{"mt_b": {"key": "2"}}))
    assert run.load_records() == {"mt_a": {"key": "1"}, "mt_b": {"key": "2"}}
    assert sorted(os.listdir(tmp_path)) == ["records.json"], "no temporary file is left"

    def broken(*a, **k):
        raise KeyboardInterrupt("stopped while saving")
    monkeypatch.setattr(run.json, "dumps", broken)
    with pytest.raises(KeyboardInterrupt):
        run.save_records({"mt_c": {"key": "3"}})
    monkeypatch.undo()
    with open(path, encoding="utf-8") as f:
        assert json.load(f) == {"mt_a": {"key": "1"}, "mt_b": {"key": "2"}}, \
            "a save stopped half-way truncated the records"
