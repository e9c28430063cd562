#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Sharded proofs: `make prove` split over N machines, and one report from their results.

    tools/prove_shard.py plan N|i/N [--parts "wp cbmc ..."] [--default-parts "..."] [--out DIR]
    tools/prove_shard.py wp SHARD_FILE
    tools/prove_shard.py merge [--baseline FILE] OUT_BUILD SHARD_BUILD...
    tools/prove_shard.py costs WP_DIR

Units. WP: one (module, function) per function defined in a module as Frama-C's own parser
sees it (-metrics "Defined functions"; a header's static inline function is a unit of every
module that defines it), and one (module, "@lemma") for a module whose normalized code holds a
lemma (a run with -wp-fct proves no lemma). Nothing comes from a hand-kept list, so a new
function is always in some shard. The enumeration is cached in $BUILD/proof/wp-units/, keyed
by the digest of Frama-C's version, the module's sources and the headers of its include
folders. CBMC: one unit per proof folder proofs/cbmc/proofs/<fn>/, pending ones included.

Costs only balance the shards (every unit is in exactly one shard whatever they say): a WP
unit costs its module's wall seconds times its share of the module's goals + smoke tests, from
proofs/shard_costs.json (`costs` rewrites it from a full `make wp` folder; a unit it does not
know costs its module's mean); a CBMC harness its recorded property_cpu_seconds
(proofs/cbmc/records.json; unknown: the largest). Shard 1 starts with shard1_fixed_seconds,
the parts that run there only. Assignment: longest first (cost descending, then unit name),
each to the least loaded shard (the lowest on a tie): the same plan on every machine.

plan   prints the plan; i/N with --out DIR (tools/prove.sh: $BUILD/proof) writes DIR/shard.json
       (the shard's index and the whole plan) and DIR/shard/{wp,cbmc}.txt (its units).
wp     one shard's WP units (the part wp of `make prove PROVE_SHARD=i/N`): a module whose units
       are all in the shard runs whole, else `make wp-<m> WP_FCT_<m>=f1,f2`, and its lemmas in
       a run of their own (WP_PROP_<m>=@lemma, $BUILD/proof/wp-lemma) merged into the module's
       folder; shard 1 also runs the canary; then proofs/wp/gate.py on the shard's modules.
merge  the shards' build folders into OUT_BUILD: per WP module the union of the shards' reports
       (report.json, wp.log, time.txt), then proofs/wp/gate.py; one CBMC summary; the other
       parts' summaries, the canary and the versions from shard 1. Fails when a unit of the
       plan is in no shard or in two (or a shard ran one the plan lacks); else runs
       tools/proof_report.py, strict gate, on OUT_BUILD: its exit status is the gate's.
"""
import argparse
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
sys.path.insert(0, os.path.join(ROOT, "proofs", "wp"))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import cache as wp_cache  # noqa: E402  (proofs/wp/cache.py)
import gate as wp_gate  # noqa: E402  (proofs/wp/gate.py)
import proof_gate  # noqa: E402  (tools/proof_gate.py)

COSTS = os.path.join(ROOT, "proofs", "shard_costs.json")
RECORDS = os.path.join(ROOT, "proofs", "cbmc", "records.json")
CBMC_PROOFS = os.path.join(ROOT, "proofs", "cbmc", "proofs")
LEMMA = "@lemma"
UNKNOWN_MODULE_S = 10.0
SHARDED = ("wp", "cbmc")          # the parts split over the shards; the others run in shard 1


def read_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def write_json(path, value):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        json.dump(value, f, indent=1, sort_keys=True)
        f.write("\n")


def build_dir():
    return os.path.join(ROOT, os.environ.get("BUILD", "build"))


def make(args, quiet=False):
    p = subprocess.run(["make", "--no-print-directory"] + args, cwd=ROOT,
                       stdout=subprocess.PIPE if quiet else None, text=True)
    return p.returncode, p.stdout


# ------------------------------------------------------------------------------ enumeration

def wp_modules():
    """[(module, [sources], include flags)] in proofs/proofs.mk's order (`make wp-list`)."""
    rc, out = make(["-s", "wp-list"], quiet=True)
    if rc != 0:
        raise SystemExit("prove_shard: make wp-list failed")
    return [(m, srcs.split(), inc.strip()) for m, srcs, inc in
            (ln.split("|") for ln in out.splitlines() if ln.count("|") == 2)]


def module_digest(version, srcs, inc):
    """The inputs of one module's enumeration: Frama-C's version, its sources, its flags and
    every header under its include folders."""
    h = hashlib.sha256(f"{version}\n{inc}\n".encode())
    files = [os.path.join(ROOT, s) for s in srcs]
    for d in re.findall(r"-I\s*(\S+)", inc):
        for dp, _, names in sorted(os.walk(os.path.join(ROOT, d))):
            files += [os.path.join(dp, n) for n in sorted(names) if n.endswith(".h")]
    for p in files:
        h.update(os.path.relpath(p, ROOT).encode() + b"\0")
        with open(p, "rb") as f:
            h.update(f.read())
    return h.hexdigest()


DEFINED_RE = re.compile(r"Defined functions \((\d+)\)\n\s*=+\n(.*?)\n\s*\n", re.S)
LEMMA_RE = re.compile(r"(?:^|/\*@)\s*lemma\s+\w+", re.M)


def parse_enumeration(metrics, code):
    """(functions, has lemma) from Frama-C's -metrics output and its -print code."""
    m = DEFINED_RE.search(metrics)
    if not m:
        raise ValueError("no 'Defined functions' list in the -metrics output")
    names = sorted({item.split()[0] for item in m.group(2).split(";") if item.strip()})
    if len(names) != int(m.group(1)):
        raise ValueError(f"{m.group(1)} defined functions announced, {len(names)} read")
    return names, bool(LEMMA_RE.search(code))


def enumerate_module(name, srcs, inc, cache_dir, version):
    """{"functions": [...], "lemma": bool} of one module, from the cache when its digest is
    unchanged, else from one Frama-C run (parse only, about 1 s)."""
    digest = module_digest(version, srcs, inc)
    cfile = os.path.join(cache_dir, name + ".json")
    if os.path.exists(cfile):
        cached = read_json(cfile)
        if cached.get("digest") == digest:
            return cached
    with tempfile.TemporaryDirectory() as tmp:
        code = os.path.join(tmp, "code.c")
        p = subprocess.run(["frama-c"] + srcs + [f"-cpp-extra-args={inc}", "-metrics",
                                                 "-print", "-ocode", code],
                           cwd=ROOT, capture_output=True, text=True)
        if p.returncode != 0 or not os.path.exists(code):
            raise SystemExit(f"prove_shard: frama-c could not parse {name}:\n"
                             + (p.stdout + p.stderr)[-2000:])
        with open(code, encoding="utf-8", errors="replace") as f:
            functions, lemma = parse_enumeration(p.stdout, f.read())
    entry = {"digest": digest, "functions": functions, "lemma": lemma}
    write_json(cfile, entry)
    return entry


def enumerate_wp(build, only=None):
    """{module: {"functions", "lemma"}} for every WP module (or those in `only`)."""
    version = subprocess.run(["frama-c", "-version"], capture_output=True,
                             text=True).stdout.strip()
    mods = [m for m in wp_modules() if only is None or m[0] in only]
    cache_dir = os.path.join(build, "proof", "wp-units")
    with ThreadPoolExecutor(max_workers=2) as ex:
        found = ex.map(lambda m: enumerate_module(m[0], m[1], m[2], cache_dir, version), mods)
        return {m[0]: e for m, e in zip(mods, found)}


def cbmc_harnesses():
    return sorted(d for d in os.listdir(CBMC_PROOFS)
                  if os.path.exists(os.path.join(CBMC_PROOFS, d, "cbmc-proof.txt")))


# ------------------------------------------------------------------------------ plan

def load_costs():
    return read_json(COSTS) if os.path.exists(COSTS) else {}


def unit(tool, module, name, cost):
    uid = f"wp:{module}:{name}" if tool == "wp" else f"cbmc:{name}"
    return {"unit": uid, "tool": tool, "module": module, "name": name, "cost": round(cost, 3)}


def wp_units(enum, costs):
    """The WP units of the enumeration, each with its estimated seconds."""
    units = []
    for m, e in enum.items():
        known = costs.get("wp", {}).get(m)
        names = e["functions"] + ([LEMMA] if e["lemma"] else [])
        if known and known.get("weights"):
            w = known["weights"]
            mean = sum(w.values()) / len(w)
            total = sum(w.get(n, mean) for n in names)
            for n in names:
                units.append(unit("wp", m, n, known["seconds"] * w.get(n, mean) / total))
        else:
            units += [unit("wp", m, n, UNKNOWN_MODULE_S / len(names)) for n in names]
    return units


def cbmc_units(names):
    rec = read_json(RECORDS) if os.path.exists(RECORDS) else {}
    secs = {n: r["property_cpu_seconds"] for n, r in rec.items() if "property_cpu_seconds" in r}
    default = max(secs.values(), default=1.0)
    return [unit("cbmc", "", n, secs.get(n, default)) for n in names]


def assign(units, n, shard1_fixed=0.0):
    """Longest first, each unit to the least loaded shard; sets unit["shard"] (1..n)."""
    load = [shard1_fixed] + [0.0] * (n - 1)
    for u in sorted(units, key=lambda u: (-u["cost"], u["unit"])):
        i = min(range(n), key=lambda k: (load[k], k))
        u["shard"] = i + 1
        load[i] += u["cost"]
    return sorted(units, key=lambda u: u["unit"])


def shard1_only(parts):
    """The work of shard 1 alone: every part but wp and cbmc, and the WP canary."""
    return [p for p in parts if p not in SHARDED] + (["the WP canary"] if "wp" in parts else [])


def make_plan(n, parts, build):
    costs = load_costs()
    units = wp_units(enumerate_wp(build), costs) if "wp" in parts else []
    units += cbmc_units(cbmc_harnesses()) if "cbmc" in parts else []
    fixed = costs.get("shard1_fixed_seconds", 0.0) if shard1_only(parts) else 0.0
    return assign(units, n, fixed)


def plan_digest(units):
    return hashlib.sha256(json.dumps(units, sort_keys=True).encode()).hexdigest()


def write_shard(out, units, i, n, parts, default_parts, canary=None):
    """DIR/shard.json, DIR/shard/wp.txt and DIR/shard/cbmc.txt for shard i of n."""
    mine = [u for u in units if u["shard"] == i]
    write_json(os.path.join(out, "shard.json"), {
        "shard": i, "of": n, "parts": parts, "default_parts": default_parts,
        "canary": i == 1 if canary is None else canary, "digest": plan_digest(units),
        "units": units})
    os.makedirs(os.path.join(out, "shard"), exist_ok=True)
    for tool in SHARDED:
        with open(os.path.join(out, "shard", tool + ".txt"), "w", encoding="utf-8") as f:
            f.writelines((f"{u['module']} " if tool == "wp" else "") + u["name"] + "\n"
                         for u in mine if u["tool"] == tool)


def module_runs(units, i):
    """Shard i's WP runs: (whole modules, {module: functions}, lemma-only modules), in plan
    order."""
    by_mod = defaultdict(list)
    for u in units:
        if u["tool"] == "wp":
            by_mod[u["module"]].append(u)
    whole, fct, lemma = [], {}, []
    for m, us in by_mod.items():
        mine = [u["name"] for u in us if u["shard"] == i]
        if len(mine) == len(us):
            whole.append(m)
            continue
        if [f for f in mine if f != LEMMA]:
            fct[m] = [f for f in mine if f != LEMMA]
        if LEMMA in mine:
            lemma.append(m)
    return whole, fct, lemma


def print_plan(units, n, parts, this=None):
    wp = [u for u in units if u["tool"] == "wp"]
    print(f"shard plan: {n} shard(s), {len(units)} units: WP {len(wp)} in "
          f"{len({u['module'] for u in wp})} modules, CBMC {len(units) - len(wp)} harnesses "
          f"(estimated seconds: {os.path.relpath(COSTS, ROOT)}, proofs/cbmc/records.json)")
    for i in range(1, n + 1):
        mine = [u for u in units if u["shard"] == i]
        whole, fct, lemma = module_runs(units, i)
        print(f"  shard {i}/{n}: {sum(u['cost'] for u in mine):6.0f} s est.: "
              f"{len(mine) - sum(u['tool'] == 'cbmc' for u in mine)} WP units ({len(whole)} "
              f"modules whole, {len(fct)} in part, {len(lemma)} lemma runs), "
              f"{sum(u['tool'] == 'cbmc' for u in mine)} CBMC harnesses")
    if shard1_only(parts):
        print(f"  shard-independent, in shard 1 only: {', '.join(shard1_only(parts))} (about "
              f"{load_costs().get('shard1_fixed_seconds', 0.0):.0f} s more)")
    if this:
        whole, fct, lemma = module_runs(units, this)
        runs = [f"{m} whole" for m in whole] + [f"{m} {len(f)} functions" for m, f in
                                                fct.items()] + [f"{m} lemmas" for m in lemma]
        print(f"this shard {this}/{n}: WP {', '.join(runs) or 'nothing'}")


# ------------------------------------------------------------------------------ WP merge

def merge_reports(reports):
    """Union of WP JSON reports (of disjoint units: merge() checks that), global counts summed."""
    out = {"wp:global": {}, "wp:axiomatics": {}, "wp:functions": {}}
    for r in reports:
        for key in ("wp:functions", "wp:axiomatics"):
            out[key].update(r.get(key, {}))
        for prover, v in r.get("wp:global", {}).items():
            acc = out["wp:global"].setdefault(prover, {"total": 0, "valid": 0})
            acc["total"] += v.get("total", 0)
            acc["valid"] += v.get("valid", 0)
            if "rank" in v:
                acc["rank"] = max(acc.get("rank", 0), v["rank"])
    return {k: v for k, v in out.items() if v}


def merge_logs(paths):
    """The logs one after the other, each after a "==== path" line, with their WP cache lines
    summed into one first line (proofs/wp/cache.py reads the first)."""
    sums, body = {}, []
    for p in paths:
        body.append(f"==== {p}\n")
        with open(p, encoding="utf-8", errors="replace") as f:
            for ln in f:
                m = wp_cache.CACHE_LINE.match(ln.rstrip("\n"))
                if not m:
                    body.append(ln)
                    continue
                for k, v in wp_cache.CACHE_KV.findall(m.group(1)):
                    sums[k] = sums.get(k, 0) + int(v)
    head = ["[wp] [Cache] " + ", ".join(f"{k}:{v}" for k, v in sums.items()) + "\n"] if sums else []
    return "".join(head + body)


def merge_module(dirs, out):
    """One module's folders (each report.json, wp.log, time.txt) into `out`; the report only
    when every folder has one (a failed run is not hidden)."""
    reports = [os.path.join(d, "report.json") for d in dirs]
    logs = [os.path.join(d, "wp.log") for d in dirs if os.path.exists(os.path.join(d, "wp.log"))]
    secs = 0.0
    for d in dirs:
        t = os.path.join(d, "time.txt")
        if os.path.exists(t):
            with open(t, encoding="utf-8") as f:
                secs += float(f.read().split()[0])
    complete = all(os.path.exists(p) for p in reports)
    merged = merge_reports([read_json(p) for p in reports if os.path.exists(p)])
    text = merge_logs(logs)
    os.makedirs(out, exist_ok=True)
    for name in ("report.json", "wp.log", "time.txt"):
        if os.path.exists(os.path.join(out, name)):
            os.remove(os.path.join(out, name))
    if complete:
        write_json(os.path.join(out, "report.json"), merged)
    with open(os.path.join(out, "wp.log"), "w", encoding="utf-8") as f:
        f.write(text)
    with open(os.path.join(out, "time.txt"), "w", encoding="utf-8") as f:
        f.write(f"{secs:.1f}\n")


def run_gate(wp_dir, modules, requirements=""):
    """proofs/wp/gate.py on the modules; requirements: a traceability file to check too (only
    over the whole module set: the merge)."""
    extra = ["--requirements", requirements] if requirements else []
    return subprocess.run([sys.executable, os.path.join(ROOT, "proofs", "wp", "gate.py"),
                           "--wp-dir", wp_dir, "--modules", ",".join(modules)] + extra).returncode


def run_wp(shard_file):
    """One shard's WP units (see the module doc); exit status: the make runs', and the WP
    gate's in the shard that runs the canary (elsewhere the gate cannot pass without it; the
    report checks every other item of the WP summary)."""
    sh = read_json(shard_file)
    build = build_dir()
    wp_dir = os.path.join(build, "proof", "wp")
    lemma_dir = os.path.join(build, "proof", "wp-lemma")
    jobs = "-j" + os.environ.get("WP_JOBS", "2")
    whole, fct, lemma = module_runs(sh["units"], sh["shard"])
    rc = 0
    runs = [m for m in dict.fromkeys(u["module"] for u in sh["units"]) if m in whole or m in fct]
    if runs:
        rc |= make([jobs, f"BUILD={build}"] + [f"wp-{m}" for m in runs] +
                   [f"WP_FCT_{m}={','.join(fs)}" for m, fs in fct.items()])[0]
    if lemma:
        rc |= make([jobs, f"BUILD={build}", f"WP_DIR={lemma_dir}"] +
                   [f"wp-{m}" for m in lemma] + [f"WP_PROP_{m}={LEMMA}" for m in lemma])[0]
        for m in lemma:
            dirs = ([os.path.join(wp_dir, m)] if m in fct else []) + [os.path.join(lemma_dir, m)]
            merge_module(dirs, os.path.join(wp_dir, m))
    if sh["canary"]:
        rc |= make([f"BUILD={build}", "wp-canary"])[0]
    modules = [m for m in dict.fromkeys(u["module"] for u in sh["units"])
               if m in whole or m in fct or m in lemma]
    g = run_gate(wp_dir, modules)
    return 1 if rc or (sh["canary"] and g) else 0


# ------------------------------------------------------------------------------ merge

def load_shard(build):
    path = os.path.join(build, "proof", "shard.json")
    if not os.path.exists(path):
        raise SystemExit(f"prove_shard: {build}: no proof/shard.json (not the BUILD folder of "
                         "`make prove PROVE_SHARD=i/N`)")
    sh = read_json(path)
    sh["build"] = build
    pfile = os.path.join(build, "proof", "parts.json")
    sh["ran"] = read_json(pfile) if os.path.exists(pfile) else {}
    return sh


def unit_problems(planned, seen):
    """Every planned unit exactly once in `seen` ({unit: [shard index]}), nothing else."""
    bad = []
    for u in planned:
        where = seen.get(u["unit"], [])
        if not where:
            bad.append(f"{u['unit']}: in no shard (planned for shard {u['shard']})")
        elif len(where) > 1:
            bad.append(f"{u['unit']}: in shards {', '.join(map(str, sorted(where)))}")
    known = {u["unit"] for u in planned}
    bad += [f"{x}: run by shard {', '.join(map(str, w))} but not in the plan"
            for x, w in sorted(seen.items()) if x not in known]
    return bad


def shard_modules(sh):
    return list(dict.fromkeys(u["module"] for u in sh["units"]
                              if u["tool"] == "wp" and u["shard"] == sh["shard"]))


def merge_wp(out, shards, requirements=""):
    """Per module, the union of the shards' reports; the canary of the shard that ran it; the
    WP gate on the result (OUT/proof/wp/summary.json). Returns the unit problems."""
    planned = [u for u in shards[0]["units"] if u["tool"] == "wp"]
    if not planned:
        return []
    seen = defaultdict(list)
    for sh in shards:
        for m in shard_modules(sh):
            p = os.path.join(sh["build"], "proof", "wp", m, "report.json")
            r = read_json(p) if os.path.exists(p) else {}
            for f in r.get("wp:functions", {}):
                seen[f"wp:{m}:{f}"].append(sh["shard"])
            if r.get("wp:axiomatics"):
                seen[f"wp:{m}:{LEMMA}"].append(sh["shard"])
    wp_dir = os.path.join(out, "proof", "wp")
    modules = list(dict.fromkeys(u["module"] for u in planned))
    for m in modules:
        merge_module([os.path.join(sh["build"], "proof", "wp", m) for sh in shards
                      if m in shard_modules(sh)], os.path.join(wp_dir, m))
    for sh in shards:
        canary = os.path.join(sh["build"], "proof", "wp", "canary")
        if sh["canary"] and os.path.isdir(canary):
            shutil.copytree(canary, os.path.join(wp_dir, "canary"), dirs_exist_ok=True)
    run_gate(wp_dir, modules, requirements)
    return unit_problems(planned, seen)


def merge_cbmc(out, shards):
    """One CBMC summary from the shards' (results by harness). Returns the unit problems."""
    planned = [u for u in shards[0]["units"] if u["tool"] == "cbmc"]
    if not planned:
        return []
    seen, results, missing, modes, secs = defaultdict(list), {}, set(), set(), 0.0
    unchecked = set()
    for sh in shards:
        if not any(u["tool"] == "cbmc" and u["shard"] == sh["shard"] for u in sh["units"]):
            continue
        p = os.path.join(sh["build"], "proof", "cbmc", "summary.json")
        s = read_json(p) if os.path.exists(p) else {}
        for r in s.get("results", []):
            seen["cbmc:" + r["function"]].append(sh["shard"])
            results[r["function"]] = r
        missing.update(s.get("missing_proofs") or [])
        unchecked.update(s.get("clauses_unchecked", ["no clauses_unchecked list in " + p]))
        modes.add(s.get("record_mode", "?"))
        secs += s.get("seconds", 0.0)
    res = [results[n] for n in sorted(results)]

    def count(key, value):
        return sum(r.get(key) == value for r in res)
    write_json(os.path.join(out, "proof", "cbmc", "summary.json"), {
        "harnesses": len(res), "passed": count("passed", True),
        "record_mode": " ".join(sorted(modes)),
        "properties_replayed": count("property_source", "replayed"),
        "properties_fresh": count("property_source", "fresh"),
        "coverage_replayed": count("coverage_source", "replayed"),
        "coverage_fresh": count("coverage_source", "fresh"),
        "tier": "default", "seconds": round(secs, 1), "missing_proofs": sorted(missing),
        "clauses_unchecked": sorted(unchecked), "results": res})
    return unit_problems(planned, seen)


def merge_parts(out, shards):
    """parts.json and timing.json: wp and cbmc from every shard that ran them (first non-zero
    exit status, longest wall time, earliest start), the others as shard 1 ran them; with
    their summaries, tool versions and logs (proof/logs/shard-<i>/)."""
    first = next(sh for sh in shards if sh["shard"] == 1)
    names = list(dict.fromkeys([p for p in SHARDED if any(p in sh["ran"] for sh in shards)]
                               + list(first["ran"])))
    parts = {}
    for name in names:
        if name not in SHARDED:
            parts[name] = first["ran"][name]
            rel = proof_gate.SUMMARIES.get(proof_gate.PART_SUMMARY.get(name, ""), "")
            src = os.path.join(first["build"], "proof", rel)
            if rel and os.path.exists(src):
                os.makedirs(os.path.dirname(os.path.join(out, "proof", rel)), exist_ok=True)
                shutil.copy2(src, os.path.join(out, "proof", rel))
            continue
        es = [sh["ran"][name] for sh in shards if name in sh["ran"]]
        parts[name] = {"rc": next((e["rc"] for e in es if e.get("rc") != 0), 0),
                       "seconds": max(e.get("seconds", 0.0) for e in es),
                       "started": min(e.get("started", 0) for e in es)}
    write_json(os.path.join(out, "proof", "parts.json"), parts)
    write_json(os.path.join(out, "proof", "timing.json"),
               {k: v.get("seconds", 0.0) for k, v in parts.items()})
    for name in ("versions.txt", "cache.txt"):
        src = os.path.join(first["build"], "proof", name)
        if os.path.exists(src):
            shutil.copy2(src, os.path.join(out, "proof", name))
    for sh in shards:
        logs = os.path.join(sh["build"], "proof", "logs")
        if os.path.isdir(logs):
            shutil.copytree(logs, os.path.join(out, "proof", "logs", f"shard-{sh['shard']}"),
                            dirs_exist_ok=True)


def fresh_out(out):
    """OUT/proof, emptied when an earlier merge wrote it; refused when it holds anything else."""
    proof = os.path.join(out, "proof")
    if os.path.isdir(proof) and os.listdir(proof):
        if not os.path.exists(os.path.join(proof, "merge.json")):
            raise SystemExit(f"prove_shard: {proof} is not empty and not an earlier merge: "
                             "give another OUT_BUILD")
        shutil.rmtree(proof)
    os.makedirs(proof)


def merge(out, builds, baseline, requirements=os.path.join(ROOT, "proofs", "requirements.json")):
    shards = sorted((load_shard(b) for b in builds), key=lambda s: s["shard"])
    bad = []
    n, digest = shards[0]["of"], shards[0]["digest"]
    for sh in shards:
        if (sh["of"], sh["digest"]) != (n, digest):
            bad.append(f"{sh['build']}: shard {sh['shard']}/{sh['of']} of another plan than "
                       f"{shards[0]['build']} (another commit, shard count or part list)")
        bad += [f"shard {sh['shard']}/{n}: part {t} has units but did not run (parts.json)"
                for t in SHARDED if t not in sh["ran"] and
                any(u["tool"] == t and u["shard"] == sh["shard"] for u in sh["units"])]
    got = [sh["shard"] for sh in shards]
    bad += [f"shard {i}/{n}: not given" for i in range(1, n + 1) if i not in got]
    bad += [f"shard {i}/{n}: given {got.count(i)} times" for i in sorted(set(got))
            if got.count(i) > 1]
    if bad:
        return fail(bad)
    fresh_out(out)
    bad = merge_wp(out, shards, requirements) + merge_cbmc(out, shards)
    write_json(os.path.join(out, "proof", "merge.json"),
               {"shards": [os.path.abspath(sh["build"]) for sh in shards], "of": n,
                "digest": digest, "problems": bad})
    if bad:
        return fail(bad)
    merge_parts(out, shards)
    print(f"prove-merge: {n} shard(s), every unit of the plan exactly once; the report:")
    env = dict(os.environ, BUILD=os.path.abspath(out))
    return subprocess.run([sys.executable, os.path.join(ROOT, "tools", "proof_report.py"),
                           "--default-parts", " ".join(shards[0]["default_parts"]),
                           "--baseline", baseline], cwd=ROOT, env=env).returncode


def fail(problems):
    print(f"prove-merge: FAILED: {len(problems)} problem(s):")
    for p in problems:
        print("  - " + p)
    return 1


# ------------------------------------------------------------------------------ costs

def write_costs(wp_dir):
    """proofs/shard_costs.json from a full `make wp` folder: per module its wall seconds and the
    goals + smoke tests of each function (the lemmas: @lemma)."""
    costs = load_costs()
    wp = {}
    for m, _, _ in wp_modules():
        s = wp_gate.module_stats(m, wp_dir)
        if s["missing"] or not s["time_s"]:
            continue
        weights = defaultdict(int)
        for f, v in s["functions"].items():
            weights[LEMMA if f.startswith("lemma") else f] += v["goals"] + v["smoke"]
        wp[m] = {"seconds": s["time_s"], "weights": dict(sorted(weights.items()))}
    costs["wp"] = wp
    costs.setdefault("shard1_fixed_seconds", 0.0)
    write_json(COSTS, costs)
    print(f"prove_shard: {len(wp)} modules in {os.path.relpath(COSTS, ROOT)}")
    return 0


# ------------------------------------------------------------------------------ main

def parse_shard(text):
    m = re.fullmatch(r"(?:(\d+)/)?(\d+)", text.strip())
    i, n = (int(m.group(1)) if m and m.group(1) else None), (int(m.group(2)) if m else 0)
    if not m or n < 1 or (i is not None and not 1 <= i <= n):
        raise SystemExit(f"prove_shard: shard {text!r}: expected N or i/N with 1 <= i <= N")
    return i, n


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("plan")
    p.add_argument("shard", help="N (the whole plan) or i/N")
    p.add_argument("--parts", default=" ".join(SHARDED))
    p.add_argument("--default-parts", default="")
    p.add_argument("--out", help="write DIR/shard.json and DIR/shard/ (needs i/N)")
    p = sub.add_parser("wp")
    p.add_argument("shard_file")
    p = sub.add_parser("merge")
    p.add_argument("--baseline", default="proofs/baseline.json")
    p.add_argument("--requirements", default=os.path.join(ROOT, "proofs", "requirements.json"))
    p.add_argument("out")
    p.add_argument("builds", nargs="+")
    p = sub.add_parser("costs")
    p.add_argument("wp_dir")
    args = ap.parse_args(argv)
    if args.cmd == "wp":
        return run_wp(args.shard_file)
    if args.cmd == "merge":
        return merge(args.out, args.builds, args.baseline, args.requirements)
    if args.cmd == "costs":
        return write_costs(args.wp_dir)
    i, n = parse_shard(args.shard)
    parts = args.parts.split()
    units = make_plan(n, parts, build_dir())
    print_plan(units, n, parts, i)
    if args.out:
        if i is None:
            raise SystemExit("prove_shard: --out needs i/N")
        write_shard(args.out, units, i, n, parts, args.default_parts.split() or parts)
    return 0


if __name__ == "__main__":
    sys.exit(main())
