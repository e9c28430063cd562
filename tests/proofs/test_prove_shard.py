# SPDX-License-Identifier: Apache-2.0
"""Sharded proofs (tools/prove_shard.py, PROVE_SHARD=i/N in tools/prove.sh): the plan, the
merge on synthetic shard folders, tools/prove.sh's shard mode with stub tools, and one real
check: Frama-C/WP on the `time` module whole and as 2 shards gives the same counts.

    /usr/bin/python3 -m pytest -q tests/proofs/test_prove_shard.py
    MT_SKIP_FRAMAC=1 ...   skips the real check (it runs Frama-C 4 times, about 30 s)
"""
import importlib.util
import json
import os
import random
import shutil
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_proof_report import DEFAULT_PARTS, harness, passing_set  # noqa: E402
from test_prove_driver import Prove, put_exec  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SHARD_PY = os.path.join(ROOT, "tools", "prove_shard.py")


def load(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


ps = load("prove_shard", SHARD_PY)


def run(cmd, build=None, **kw):
    env = dict(os.environ, **({"BUILD": build} if build else {}))
    p = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=ROOT, **kw)
    return p.returncode, p.stdout + p.stderr


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


# ------------------------------------------------------------------------------ (a) the plan

def real_units():
    """The units of the committed costs (every module it knows, lemmas included) and every
    CBMC proof folder, with the committed costs and records."""
    costs = ps.load_costs()
    enum = {m: {"functions": sorted(f for f in v["weights"] if f != ps.LEMMA),
                "lemma": ps.LEMMA in v["weights"]} for m, v in costs["wp"].items()}
    return ps.wp_units(enum, costs) + ps.cbmc_units(ps.cbmc_harnesses())


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_plan_puts_every_unit_in_exactly_one_shard_deterministically(n):
    units = real_units()
    ids = sorted(u["unit"] for u in units)
    assert len(ids) == len(set(ids)) > 300
    first = ps.assign([dict(u) for u in units], n, 200.0)
    shuffled = [dict(u) for u in units]
    random.Random(n).shuffle(shuffled)
    assert ps.assign(shuffled, n, 200.0) == first
    assert sorted(u["unit"] for u in first) == ids
    assert {u["shard"] for u in first} == set(range(1, n + 1))
    # every WP unit of a shard is run: whole, in part (WP_FCT) or as a lemma run
    for i in range(1, n + 1):
        whole, fct, lemma = ps.module_runs(first, i)
        ran = {f"wp:{m}:{u['name']}" for m in whole for u in first if u["module"] == m}
        ran |= {f"wp:{m}:{f}" for m, fs in fct.items() for f in fs}
        ran |= {f"wp:{m}:{ps.LEMMA}" for m in lemma}
        assert ran == {u["unit"] for u in first if u["shard"] == i and u["tool"] == "wp"}


def test_plan_is_longest_first_to_the_least_loaded_shard():
    units = [ps.unit("cbmc", "", n, c) for n, c in (("d", 4), ("b", 6), ("a", 10), ("c", 5))]
    got = {u["name"]: u["shard"] for u in ps.assign(units, 2)}
    assert got == {"a": 1, "b": 2, "c": 2, "d": 1}
    # ties by name, whatever the input order; shard 1 starts with its fixed load
    ties = [ps.unit("cbmc", "", n, 3) for n in ("y", "x", "z")]
    assert {u["name"]: u["shard"] for u in ps.assign(ties, 2)} == {"x": 1, "y": 2, "z": 1}
    assert {u["name"]: u["shard"] for u in ps.assign(ties, 2, 100.0)} == \
        {"x": 2, "y": 2, "z": 2}


def test_plan_costs_do_not_decide_completeness():
    enum = {"new": {"functions": ["f", "g"], "lemma": True},
            "time": {"functions": ["mt_time_extend", "mt_brand_new"], "lemma": False}}
    units = ps.wp_units(enum, ps.load_costs())
    assert sorted(u["unit"] for u in units) == [
        "wp:new:@lemma", "wp:new:f", "wp:new:g", "wp:time:mt_brand_new", "wp:time:mt_time_extend"]
    assert all(u["cost"] > 0 for u in units)


def test_enumeration_reads_frama_c_metrics():
    metrics = """[kernel] Parsing kernel/src/time.c (with preprocessing)
[metrics] Defined functions (3)
  =====================
   mt_a (0 call); mt_b (address taken) (2 calls);
   mt_c (1 call);
  
  Specified-only functions (1)
"""
    assert ps.parse_enumeration(metrics, "/*@\nlemma L:\n  \\true;\n*/") == \
        (["mt_a", "mt_b", "mt_c"], True)
    assert ps.parse_enumeration(metrics, "int lemma_count;")[1] is False
    with pytest.raises(ValueError):
        ps.parse_enumeration(metrics.replace("(3)", "(4)"), "")


def test_shard_argument_is_checked():
    assert ps.parse_shard("2/3") == (2, 3) and ps.parse_shard("4") == (None, 4)
    for bad in ("0/2", "3/2", "x", "1/0"):
        with pytest.raises(SystemExit):
            ps.parse_shard(bad)


# ------------------------------------------------------------------------------ (b) the merge

# module -> function -> (goals, smoke tests); lemma goals per module
FUNCS = {"sem": {"mt_sem_init": (5, 2), "mt_sem_wait": (30, 6), "mt_sem_signal_i": (12, 4)},
         "time": {"mt_time_extend": (20, 5), "mt_time_ext_init": (9, 3)}}
LEMMAS = {"time": 2}
HARNESSES = ["mt_sem_init", "mt_sem_signal_i", "mt_sem_wait", "mt_time_extend"]
BASELINE = {"wp.proved": 10, "cbmc.passed": 1}
# A traceability file the synthetic goals discharge (a clause of each module).
REQUIREMENTS = [{"id": "R-T", "text": "synthetic", "clauses": ["mt_sem_wait:g0",
                                                                "mt_time_extend:g0"]}]


def props(names):
    return {n: {"qed": {"total": 1, "valid": 1}, "wp:main": {"total": 1, "valid": 1}}
            for n in names}


def wp_module(d, module, names):
    """A module folder as `make wp-<module>` writes it, for the units `names`."""
    rep, log, total = {"wp:functions": {}}, [], 0
    for f in names:
        if f == ps.LEMMA:
            rep["wp:axiomatics"] = {"": props([f"lemma_L{k}" for k in range(LEMMAS[module])])}
            log += [f"[wp] [Qed] Goal typed_lemma_L{k} : Valid (1ms)"
                    for k in range(LEMMAS[module])]
            total += LEMMAS[module]
            continue
        goals, smoke = FUNCS[module][f]
        # goal 0 is a labelled ensures clause, which the traceability file below names
        rep["wp:functions"][f] = props([f"{f}_ensures_g0"] +
                                       [f"{f}_g{k}" for k in range(1, goals)] +
                                       [f"{f}_wp_smoke_s{k}" for k in range(smoke)])
        log += [f"[wp] [Qed] Goal typed_{f}_ensures_g0 : Valid (2ms)"]
        log += [f"[wp] [Qed] Goal typed_{f}_g{k} : Valid (2ms)" for k in range(1, goals)]
        log += [f"[wp] [Passed] Smoke-test typed_{f}_wp_smoke_s{k}" for k in range(smoke)]
        total += goals + smoke
    rep["wp:global"] = {"qed": {"total": total, "valid": total},
                        "wp:main": {"total": total, "valid": total}}
    if not rep["wp:functions"]:
        del rep["wp:functions"]
    write(os.path.join(d, module, "report.json"), json.dumps(rep))
    write(os.path.join(d, module, "wp.log"), "\n".join([f"[wp] [Cache] found:{total}"] + log))
    write(os.path.join(d, module, "time.txt"), "1.0\n")


def synthetic_units():
    wp = [ps.unit("wp", m, f, float(sum(FUNCS[m][f]))) for m in FUNCS for f in FUNCS[m]]
    wp.append(ps.unit("wp", "time", ps.LEMMA, 2.0))
    return ps.assign(wp + [ps.unit("cbmc", "", h, float(len(h))) for h in HARNESSES], 2)


def proof_folder(build, units, parts, canary, others):
    """A build folder with WP module folders for `units`, their CBMC results, and (others)
    the summaries of every other part of the passing set."""
    proof = os.path.join(build, "proof")
    by_mod = {}
    for u in units:
        if u["tool"] == "wp":
            by_mod.setdefault(u["module"], []).append(u["name"])
    for m, names in by_mod.items():
        wp_module(os.path.join(proof, "wp"), m, names)
    if canary:
        write(os.path.join(proof, "wp", "canary", "result.txt"),
              "wp-canary: 6 functions as expected (3 contradictions found, 3 controls clean)\n")
    hs = sorted(u["name"] for u in units if u["tool"] == "cbmc")
    if hs:
        write(os.path.join(proof, "cbmc", "summary.json"), json.dumps({
            "harnesses": len(hs), "passed": len(hs), "record_mode": "replay",
            "properties_fresh": len(hs), "properties_replayed": 0, "coverage_fresh": 0,
            "coverage_replayed": len(hs), "tier": "default", "seconds": 1.0,
            "missing_proofs": [], "clauses_unchecked": [],
            "results": [harness(h) for h in hs]}))
    for rel, value in passing_set().items():
        if others and not rel.startswith(("wp/", "cbmc/summary", "parts", "timing",
                                          "selftest/", "tla/trace/")):
            write(os.path.join(proof, rel), json.dumps(value))
    write(os.path.join(proof, "parts.json"),
          json.dumps({p: {"rc": 0, "seconds": 1.5} for p in parts}))
    write(os.path.join(proof, "versions.txt"), "frama-c 25.0\n")
    return proof


class Shards:
    """One unsharded folder and two shard folders of the same synthetic proofs."""

    def __init__(self, tmp):
        self.tmp = str(tmp)
        self.units = synthetic_units()
        self.baseline = os.path.join(self.tmp, "baseline.json")
        write(self.baseline, json.dumps(BASELINE))
        self.requirements = os.path.join(self.tmp, "requirements.json")
        write(self.requirements, json.dumps(REQUIREMENTS))
        self.whole = os.path.join(self.tmp, "whole")
        proof_folder(self.whole, self.units, DEFAULT_PARTS, True, True)
        self.shards = []
        for i in (1, 2):
            b = os.path.join(self.tmp, f"shard{i}")
            mine = [u for u in self.units if u["shard"] == i]
            parts = DEFAULT_PARTS if i == 1 else ["wp", "cbmc"]
            proof = proof_folder(b, mine, parts, i == 1, i == 1)
            ps.write_shard(proof, self.units, i, 2, DEFAULT_PARTS, DEFAULT_PARTS)
            self.shards.append(b)
        self.out = os.path.join(self.tmp, "merged")

    def report_whole(self):
        run([sys.executable, os.path.join(ROOT, "proofs", "wp", "gate.py"), "--wp-dir",
             os.path.join(self.whole, "proof", "wp"), "--modules", "sem,time",
             "--requirements", self.requirements])
        rc, out = run([sys.executable, os.path.join(ROOT, "tools", "proof_report.py"),
                       "--default-parts", " ".join(DEFAULT_PARTS), "--baseline", self.baseline],
                      build=self.whole)
        return rc, out, summary(self.whole)

    def merge(self, *builds):
        return run([sys.executable, SHARD_PY, "merge", "--baseline", self.baseline,
                    "--requirements", self.requirements, self.out] + list(builds or self.shards))

    def report(self, shard, i):
        return run([sys.executable, os.path.join(ROOT, "tools", "proof_report.py"),
                    "--default-parts", "wp cbmc", "--shard", f"{i}/2", "--baseline",
                    self.baseline], build=shard)

    def edit_report(self, shard, module, change):
        p = os.path.join(shard, "proof", "wp", module, "report.json")
        with open(p, encoding="utf-8") as f:
            rep = json.load(f)
        change(rep)
        write(p, json.dumps(rep))

    def shared(self):
        """(a WP unit of shard 2 whose module shard 1 also runs)."""
        mods1 = {u["module"] for u in self.units if u["shard"] == 1 and u["tool"] == "wp"}
        return next(u for u in self.units if u["shard"] == 2 and u["tool"] == "wp" and
                    u["module"] in mods1 and u["name"] != ps.LEMMA)


def summary(build):
    """The report's summary without the timing, parts and versions."""
    with open(os.path.join(build, "proof", "summary.json"), encoding="utf-8") as f:
        s = json.load(f)
    return {k: v for k, v in s.items() if k not in ("timing", "parts", "versions")}


def wp_counts(wp_dir, module):
    """One module of the WP gate's summary: counts, findings, and the counts per function."""
    with open(os.path.join(wp_dir, "summary.json"), encoding="utf-8") as f:
        m = json.load(f)["modules"][module]
    keys = ("goals", "proved", "smoke", "smoke_passed")
    return ({k: m[k] for k in keys}, m["by_prover"], m["fatal"], m["failures"],
            {f: {k: v[k] for k in keys} for f, v in m["functions"].items()})


@pytest.fixture
def shards(tmp_path):
    return Shards(tmp_path)


def test_merge_of_two_shards_gives_the_summary_of_one_run(shards):
    assert {u["shard"] for u in shards.units if u["tool"] == "wp"} == {1, 2}
    assert {u["shard"] for u in shards.units if u["tool"] == "cbmc"} == {1, 2}
    rc_w, out_w, whole = shards.report_whole()
    assert rc_w == 0, out_w
    rc, out = shards.merge()
    assert rc == 0, out
    assert "every unit of the plan exactly once" in out and "PROVE OK: everything" in out
    assert summary(shards.out) == whole
    for m in FUNCS:
        assert wp_counts(os.path.join(shards.out, "proof", "wp"), m) == \
            wp_counts(os.path.join(shards.whole, "proof", "wp"), m)
    assert (whole["wp"]["goals"], whole["wp"]["smoke"], whole["cbmc"]["harnesses"]) == (78, 20, 4)


def test_merge_fails_on_a_unit_in_no_shard(shards):
    u = shards.shared()
    shards.edit_report(shards.shards[1], u["module"], lambda r: r["wp:functions"].pop(u["name"]))
    rc, out = shards.merge()
    assert rc == 1, out
    assert f"{u['unit']}: in no shard (planned for shard 2)" in out


def test_merge_fails_on_a_unit_in_two_shards(shards):
    u = shards.shared()
    with open(os.path.join(shards.shards[1], "proof", "wp", u["module"], "report.json"),
              encoding="utf-8") as f:
        props = json.load(f)["wp:functions"][u["name"]]
    shards.edit_report(shards.shards[0], u["module"],
                       lambda r: r["wp:functions"].update({u["name"]: props}))
    rc, out = shards.merge()
    assert rc == 1, out
    assert f"{u['unit']}: in shards 1, 2" in out


def test_merge_fails_on_a_harness_in_no_shard_and_a_missing_shard(shards):
    p = os.path.join(shards.shards[1], "proof", "cbmc", "summary.json")
    with open(p, encoding="utf-8") as f:
        s = json.load(f)
    gone = s["results"].pop()["function"]
    write(p, json.dumps(s))
    rc, out = shards.merge()
    assert rc == 1 and f"cbmc:{gone}: in no shard" in out, out
    rc, out = shards.merge(shards.shards[0])
    assert rc == 1 and "shard 2/2: not given" in out, out
    write(os.path.join(shards.shards[1], "proof", "parts.json"), json.dumps({"wp": {"rc": 0}}))
    rc, out = shards.merge()
    assert rc == 1 and "shard 2/2: part cbmc has units but did not run" in out, out


def test_shard_report_is_partial_and_judges_what_the_shard_ran(shards):
    s2 = shards.shards[1]
    gate = [sys.executable, os.path.join(ROOT, "proofs", "wp", "gate.py"), "--wp-dir",
            os.path.join(s2, "proof", "wp"), "--modules",
            ",".join(ps.shard_modules(ps.load_shard(s2)))]
    run(gate)
    write(shards.baseline, json.dumps({"wp.proved": 10 ** 6}))
    rc, out = shards.report(s2, 2)
    assert rc == 0, out
    assert "PROVE OK: shard 2/2: partial" in out and "left to the merge: WP smoke canary" in out
    s = summary(s2)
    assert s["partial"] is True and s["ok"] is True and s["complete"] is False
    u = next(u for u in shards.units if u["shard"] == 2 and u["tool"] == "wp")
    shards.edit_report(s2, u["module"], lambda r: r.update({"wp:functions": {
        f: {p: {"wp:main": {"total": 1, "valid": 0}} for p in v}
        for f, v in r.get("wp:functions", {}).items()}}))
    run(gate)
    rc, out = shards.report(s2, 2)
    assert rc == 1 and "PROVE FAILED" in out, out


# ------------------------------------------------------------------------------ prove.sh

STUB_SHARD = """#!/usr/bin/env python3
import os, sys
if sys.argv[1] == "plan":
    d = sys.argv[sys.argv.index("--out") + 1]
    os.makedirs(os.path.join(d, "shard"), exist_ok=True)
    open(os.path.join(d, "shard.json"), "w").write("{}")
    open(os.path.join(d, "shard", "wp.txt"), "w").write("time mt_time_extend\\n")
    open(os.path.join(d, "shard", "cbmc.txt"), "w").write(os.environ.get("STUB_CBMC", ""))
    print("stub plan " + sys.argv[2])
elif sys.argv[1] == "wp":
    path = os.path.join(os.environ["BUILD"], "proof", "wp", "summary.json")
    open(path, "a").close()
    os.utime(path)  # written by this run (an append of nothing keeps the old time)
"""


@pytest.mark.parametrize("shard,cbmc,parts", [
    ("1/2", "mt_sem_init\n", DEFAULT_PARTS), ("2/2", "mt_sem_init\n", ["wp", "cbmc"]),
    ("2/2", "", ["wp"])])
def test_prove_sh_in_a_shard_runs_its_share(tmp_path, shard, cbmc, parts):
    prove = Prove(tmp_path)
    put_exec(os.path.join(prove.repo, "tools", "prove_shard.py"), STUB_SHARD)
    rc, out = prove.run(PROVE_SHARD=shard, STUB_CBMC=cbmc)
    assert rc == 0, out
    assert f"stub plan {shard}" in out and f"PROVE OK: shard {shard}: partial" in out
    assert sorted(prove.parts()) == sorted(parts)


# ------------------------------------------------------------------------------ (c) real WP run

@pytest.mark.skipif(os.environ.get("MT_SKIP_FRAMAC") == "1" or not shutil.which("frama-c"),
                    reason="MT_SKIP_FRAMAC=1, or no frama-c")
def test_wp_time_whole_equals_two_merged_shards(tmp_path):
    whole, out = str(tmp_path / "whole"), str(tmp_path / "merged")
    enum = ps.enumerate_wp(whole, only={"time"})
    rc, log = run(["make", "--no-print-directory", "wp-time", f"BUILD={whole}"], timeout=600)
    assert rc == 0, log
    wp_whole = os.path.join(whole, "proof", "wp")
    run([sys.executable, os.path.join(ROOT, "proofs", "wp", "gate.py"), "--wp-dir", wp_whole,
         "--modules", "time"])
    with open(os.path.join(wp_whole, "time", "report.json"), encoding="utf-8") as f:
        rep = json.load(f)
    # the enumeration is what WP proves: every function, and the lemmas
    assert enum["time"]["functions"] == sorted(rep["wp:functions"])
    assert enum["time"]["lemma"] is bool(rep.get("wp:axiomatics"))

    units = ps.assign(ps.wp_units(enum, ps.load_costs()), 2)
    builds = []
    for i in (1, 2):
        b = str(tmp_path / f"shard{i}")
        ps.write_shard(os.path.join(b, "proof"), units, i, 2, ["wp"], ["wp"], canary=False)
        rc, log = run([sys.executable, SHARD_PY, "wp", os.path.join(b, "proof", "shard.json")],
                      build=b, timeout=600)
        assert rc == 0, log
        builds.append(b)
    runs = [ps.module_runs(units, i) for i in (1, 2)]
    assert all(not whole_ for whole_, _, _ in runs)          # split: no shard runs it whole
    assert any(lemma and fct for _, fct, lemma in runs)      # and a lemma run merged in a shard
    assert ps.merge_wp(out, [ps.load_shard(b) for b in builds]) == []
    got, want = wp_counts(os.path.join(out, "proof", "wp"), "time"), wp_counts(wp_whole, "time")
    assert got == want
    assert want[0]["goals"] > 100 and want[0]["proved"] == want[0]["goals"]
