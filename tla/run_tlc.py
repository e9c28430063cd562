#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Run the TLA+ models listed in tla/models.json with TLC and check the results.

Each manifest entry names a module, a config and the expected result: "pass"
(no error; the distinct-state count must equal the pinned one), or the name of
the invariant or temporal property a broken variant must violate, or
"deadlock". Optional fields: "deps", modules the module EXTENDS (copied
beside it), and "tlc_args", extra TLC options (e.g. ["-deadlock"] for a spec
with a terminal state). A run fails on any other outcome, on a missing or different
pinned count for a passing model, on a TLC error, or on a timeout.

    tla/run_tlc.py                  CI configurations (deep == false)
    tla/run_tlc.py --deep           the larger configurations (deep == true)
    tla/run_tlc.py --only NAME ...  selected entries
    tla/run_tlc.py --update         re-measure and rewrite the pinned counts,
                                    depths and runtimes in the manifest
    --reuse-local                   (make reprove) when every input (the selection, each file
                                    of tla/, this runner, TLC's jar, Java's version, heap and
                                    time limit) is byte-identical to this output folder's last
                                    run, and every model of that run was as expected, keep its
                                    summary, marked "replayed_local": not checked now
    --jobs N (TLA_JOBS, default 2)  models checked side by side; each TLC keeps
                                    -workers auto, and its own CPU time is reported

Results go to <out>/summary.json (<out>/summary-deep.json for --deep) and one
log per model in <out>/logs/. TLC runs on a copy of the module and config in
<out>/work/<name>/, so nothing is written into tla/.
"""
import argparse
import glob
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "proofs"))
from runtool import run_timed  # noqa: E402

MANIFEST = os.path.join(HERE, "models.json")

RE_DISTINCT = re.compile(r"([\d,]+) states generated, ([\d,]+) distinct states found")
RE_DEPTH = re.compile(r"The depth of the complete state graph search is (\d+)")
RE_INV = re.compile(r"^Error: Invariant (\w+) is violated", re.M)
RE_PROP = re.compile(r"^Error: Temporal properties were violated", re.M)
RE_DEADLOCK = re.compile(r"^Error: Deadlock reached", re.M)
RE_OK = re.compile(r"^Model checking completed\. No error has been found\.", re.M)
RE_CFG_PROPS = re.compile(r"^\s*PROPERT(?:Y|IES)\s+(.*)$", re.M)


def cfg_properties(cfg_text):
    """Temporal property names listed in a TLC config (comments removed)."""
    text = re.sub(r"\\\*.*", "", cfg_text)
    text = re.sub(r"\(\*.*?\*\)", "", text, flags=re.S)
    names = []
    for line in RE_CFG_PROPS.findall(text):
        names += line.split()
    return names


def classify(log, props):
    """Outcome of one TLC run: 'pass', an invariant or property name,
    'deadlock', or 'error: ...'."""
    m = RE_INV.search(log)
    if m:
        return m.group(1)
    if RE_PROP.search(log):
        if len(props) == 1:
            return props[0]
        return "temporal:" + "|".join(props)
    if RE_DEADLOCK.search(log):
        return "deadlock"
    if RE_OK.search(log):
        return "pass"
    tail = [l for l in log.strip().splitlines() if l.strip()][-3:]
    return "error: " + " / ".join(tail)


def counts(log):
    distinct = generated = depth = None
    found = RE_DISTINCT.findall(log)
    if found:
        generated = int(found[-1][0].replace(",", ""))
        distinct = int(found[-1][1].replace(",", ""))
    m = RE_DEPTH.findall(log)
    if m:
        depth = int(m[-1])
    return distinct, generated, depth


def run_one(entry, args):
    name = entry["name"]
    work = os.path.join(args.out, "work", name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    module = entry["module"]
    for mod in [module] + entry.get("deps", []):
        shutil.copy(os.path.join(HERE, mod + ".tla"), work)
    cfg_src = os.path.join(HERE, entry["config"])
    cfg = os.path.basename(cfg_src)
    shutil.copy(cfg_src, os.path.join(work, cfg))
    with open(cfg_src) as f:
        props = cfg_properties(f.read())
    # TLC writes the standard modules (Naturals.tla, ...) into java.io.tmpdir before it parses
    # them: a shared /tmp lets one run read another's half-written copy ("Parsing or semantic
    # analysis failed" when models, traces and mutants run side by side), so each run has its own.
    tmp = os.path.join(work, "tmp")
    os.makedirs(tmp)
    cmd = ["java", "-XX:+UseParallelGC", "-Xmx" + args.heap, "-Djava.io.tmpdir=" + tmp,
           "-cp", args.jar, "tlc2.TLC",
           "-workers", "auto", "-cleanup"] + entry.get("tlc_args", []) + [
           "-metadir", os.path.join(work, "states"), "-config", cfg, module + ".tla"]
    timeout = entry.get("timeout_s", args.timeout)
    # One process per model, its own CPU time (wait4), also when models run side by side (--jobs).
    run = run_timed(cmd, timeout, cwd=work)
    log = run.out
    if run.timed_out:
        outcome = "error: timeout after %d s" % timeout
    else:
        outcome = classify(log, props)
    seconds = round(run.wall, 1)
    cpu = round(run.cpu, 1)
    os.makedirs(os.path.join(args.out, "logs"), exist_ok=True)
    with open(os.path.join(args.out, "logs", name + ".log"), "w") as f:
        f.write("$ " + " ".join(cmd) + "\n" + log)
    shutil.rmtree(work, ignore_errors=True)
    distinct, generated, depth = counts(log)
    expect = entry["expect"]
    res = {"name": name, "module": module, "config": entry["config"], "deep": entry["deep"],
           "expect": expect, "result": outcome, "distinct_states": distinct,
           "generated_states": generated, "depth": depth, "seconds": seconds,
           "cpu_s": cpu}
    problems = []
    if outcome != expect:
        problems.append("expected %s, got %s" % (expect, outcome))
    elif expect == "pass" and not args.update:
        pinned = entry.get("distinct_states")
        if pinned is None:
            problems.append("no pinned distinct-state count (run with --update)")
        elif pinned != distinct:
            problems.append("distinct states %s, manifest pins %s" % (distinct, pinned))
        if entry.get("depth") is not None and depth != entry["depth"]:
            res["note"] = "depth %s, manifest has %s" % (depth, entry["depth"])
    res["ok"] = not problems
    if problems:
        res["problem"] = "; ".join(problems)
    return res


def inputs_digest(args, selected):
    """The digest of everything a run's verdicts depend on (--reuse-local)."""
    h = hashlib.sha256()
    java = subprocess.run(["java", "-version"], capture_output=True, text=True)
    h.update((java.stdout + java.stderr).encode("utf-8"))
    h.update(json.dumps([[e["name"] for e in selected], args.deep, args.heap,
                         args.timeout]).encode("utf-8"))
    paths = sorted(p for p in glob.glob(os.path.join(HERE, "**", "*"), recursive=True)
                   if "__pycache__" not in p)
    paths += [os.path.join(ROOT, "proofs", "runtool.py"), args.jar]
    for path in paths:
        if os.path.isfile(path):
            h.update(("\0" + os.path.relpath(path, ROOT) + "\0").encode("utf-8"))
            with open(path, "rb") as f:
                h.update(f.read())
    return h.hexdigest()


def replay_local(summary_path, inputs_path, digest):
    """The summary of this folder's last run when its inputs were the same and it passed (its
    file rewritten with "replayed_local": the time of that run), else None."""
    try:
        with open(inputs_path) as f:
            recorded, when = f.read().split(None, 1)
        with open(summary_path) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        return None
    if recorded != digest or summary.get("passed") != summary.get("total"):
        return None
    summary["replayed_local"] = when.strip()
    with open(summary_path, "w") as f:
        json.dump(summary, f, indent=2)
        f.write("\n")
    return summary


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--deep", action="store_true", help="run the deep configurations")
    ap.add_argument("--only", nargs="+", metavar="NAME", help="run these entries only")
    ap.add_argument("--update", action="store_true", help="rewrite the pinned counts")
    ap.add_argument("--jar", default=os.path.join(ROOT, ".tools", "tla", "tla2tools.jar"))
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "proof", "tla"))
    ap.add_argument("--timeout", type=int, default=int(os.environ.get("TLA_TIMEOUT", "120")),
                    help="per-model cap in seconds for CI entries (deep entries: 10x)")
    ap.add_argument("--heap", default=os.environ.get("TLA_HEAP", "2g"))
    ap.add_argument("--jobs", "-j", type=int, default=int(os.environ.get("TLA_JOBS", "2")),
                    help="models checked side by side (each TLC keeps -workers auto)")
    ap.add_argument("--reuse-local", action="store_true",
                    help="replay this folder's last run when its inputs are identical")
    args = ap.parse_args()
    args.jar = os.path.abspath(args.jar)
    args.out = os.path.abspath(args.out)
    if not os.path.isfile(args.jar):
        sys.exit("run_tlc: %s not found (tools/bootstrap.sh prove installs it)" % args.jar)
    if args.deep:
        args.timeout *= 10

    with open(MANIFEST) as f:
        manifest = json.load(f)
    entries = manifest["models"]
    if args.only:
        unknown = set(args.only) - {e["name"] for e in entries}
        if unknown:
            sys.exit("run_tlc: unknown entries: " + ", ".join(sorted(unknown)))
        selected = [e for e in entries if e["name"] in args.only]
    else:
        selected = [e for e in entries if e["deep"] == args.deep]

    os.makedirs(args.out, exist_ok=True)
    out = os.path.join(args.out, "summary-deep.json" if args.deep else "summary.json")
    inputs = os.path.join(args.out, "inputs-deep.txt" if args.deep else "inputs.txt")
    digest = inputs_digest(args, selected)
    if args.reuse_local and not args.update:
        summary = replay_local(out, inputs, digest)
        if summary is not None:
            print("tla: %d/%d replayed from this folder's run of %s (identical inputs): not "
                  "checked now" % (summary["passed"], summary["total"], summary["replayed_local"]))
            return 0
    if os.path.exists(inputs):
        os.remove(inputs)
    results = []
    t_all = time.monotonic()
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        futs = [ex.submit(run_one, e, args) for e in selected]
        for e, f in zip(selected, futs):
            r = f.result()
            results.append(r)
            count = "" if r["distinct_states"] is None else "%d states" % r["distinct_states"]
            print("%-4s %-34s %-28s %14s %7.1f s %7.1f s cpu%s" % (
                "ok" if r["ok"] else "FAIL", r["name"], r["result"][:28], count, r["seconds"],
                r["cpu_s"],
                "" if r["ok"] else "  " + r["problem"]), flush=True)
            if args.update and r["ok"]:
                if e["expect"] == "pass":
                    e["distinct_states"] = r["distinct_states"]
                    e["depth"] = r["depth"]
                e["runtime_s"] = r["seconds"]
                e["cpu_s"] = r["cpu_s"]

    passed = sum(1 for r in results if r["ok"])
    summary = {"models": results, "passed": passed, "total": len(results),
               "seconds": round(time.monotonic() - t_all, 1)}
    with open(out, "w") as f:
        json.dump(summary, f, indent=2)
        f.write("\n")
    if passed == len(results) and not args.update:
        with open(inputs, "w") as f:
            f.write("%s %s\n" % (digest, time.strftime("%Y-%m-%dT%H:%M:%S")))
    if args.update:
        with open(MANIFEST, "w") as f:
            json.dump(manifest, f, indent=2)
            f.write("\n")
    print("tla: %d/%d as expected in %.0f s (%s)" % (passed, len(results), summary["seconds"],
                                                    os.path.relpath(out, os.getcwd())))
    return 0 if passed == len(results) else 1


if __name__ == "__main__":
    sys.exit(main())
