#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Run the CBMC proofs and judge them.

  proofs/cbmc/run.py [-j N] [--max] [--summary FILE] [--harnesses FILE] [FUNCTION...]

1. tools/acsl2cbmc translates the ACSL contracts (build/proof/cbmc/gen/).
2. Every proof folder proofs/cbmc/proofs/<fn>/ (or the ones named) is built and run twice,
   N at a time: the property run (all check flags, unwinding assertions) and the coverage run
   (--cover location).
3. A harness passes when no property fails, the coverage of the kernel code it reaches is at
   least 90 %, and every MTC_REACH witness of the harness is reached (a harness whose
   assumptions are contradictory reports success with almost no coverage: this catches it).

Verdict records (assumption B10): proofs/cbmc/records.json holds, per harness, the verdicts of
its last passing runs, each with the digest of that run's inputs (`make result-key` and `make
cover-key` in the proof folder: tool versions, every option, and every source of the binary as
goto-cc's preprocessor expands it; computed here in one process, input_keys). A run whose
digest equals the recorded one is replayed from the record instead of being run again.
CBMC_RECORD selects:
  replay (default)  replay the property and coverage verdicts whose digest is unchanged
  properties        run every property run (a record with the same digest must agree with it:
                    same number of properties, none failed), replay coverage verdicts (CI)
  fresh             run every property run and every coverage run
  save              as replay, then record every run made fresh by a passing harness

Writes build/proof/cbmc/summary.json ({"harnesses", "passed", "results": [{"function",
"properties", "failed", "coverage", "seconds", ...}]}) and prints one line per harness.
Exit status 0 only if every harness passes. --max runs the capacity-maximum tier
(CBMC_BIG=1, see lib/mtc_objects.h), written to summary-max.json. --harnesses FILE (one name a
line; a shard's share, tools/prove_shard.py) runs those as the default list is run: the
pending ones among them are listed as pending, not run.
"""

import argparse
import hashlib
import json
import os
import re
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
PROOFS = os.path.join(HERE, "proofs")
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from runtool import run_timed  # noqa: E402
import keytext  # noqa: E402  (proofs/cbmc/keytext.py)

COVERAGE_MIN = 90.0


def proof_names():
    return sorted(d for d in os.listdir(PROOFS)
                  if os.path.exists(os.path.join(PROOFS, d, "cbmc-proof.txt")))


def makefile_vars(name):
    """The simple assignments (NAME = value, continuation lines joined) of a proof folder's
    Makefile ({} without one: its build then fails on its own)."""
    path = os.path.join(PROOFS, name, "Makefile")
    if not os.path.exists(path):
        return {}
    with open(path, encoding="utf-8") as f:
        text = re.sub(r"\\\n", " ", f.read())
    return {m.group(1): m.group(2).strip()
            for m in re.finditer(r"^([A-Z_]+)\s*[:?]?=(.*)$", text, re.M)}


def proof_function(name):
    """The function a proof folder checks: its Makefile's FUNCTION, else the folder's name (a
    function whose clauses are split over several folders, assumption B17)."""
    return makefile_vars(name).get("FUNCTION") or name


def harness_path(name):
    """A proof folder's harness: its own, or its FUNCTION's (a folder on part of the clauses)."""
    fn = proof_function(name)
    return os.path.join(PROOFS, fn, f"{fn}_harness.c")


def proof_clauses(name):
    """The clause tags a proof folder checks (its Makefile's CLAUSES), or None: all of them."""
    v = makefile_vars(name).get("CLAUSES")
    return set(v.split()) if v is not None else None


CLAUSE_FLAGS = "-DMTC_CLAUSES $(addprefix -DMTC_CLAUSE_,$(CLAUSES))"
# What may stand before CLAUSE_FLAGS in a split folder's CBMC_CFG_EXTRA: nothing, or a module's
# configuration from Makefile.common (the topic bus's small configuration, B7).
CLAUSE_PREFIXES = ("", "$(BUS_CBMC_CFG) ")


def selection_problems(name):
    """A clause selection must be the one CLAUSES states: the Makefile's CBMC_CFG_EXTRA is
    exactly CLAUSE_FLAGS (after one of CLAUSE_PREFIXES) when CLAUSES is set, and MTC_CLAUSE
    appears nowhere else in the folder
    (a hand-written -DMTC_CLAUSES, or a #define in the harness, would switch clauses off that
    the coverage check below never sees)."""
    v = makefile_vars(name)
    out = []
    if "CLAUSES" in v and v.get("CBMC_CFG_EXTRA") not in [p + CLAUSE_FLAGS
                                                          for p in CLAUSE_PREFIXES]:
        out.append(f"{name}: CLAUSES is set, CBMC_CFG_EXTRA is not "
                   f"[$(BUS_CBMC_CFG) ]{CLAUSE_FLAGS}")
    d = os.path.join(PROOFS, name)
    for fn in sorted(os.listdir(d)) if os.path.isdir(d) else []:
        with open(os.path.join(d, fn), encoding="utf-8", errors="replace") as f:
            text = f.read()
        if fn == "Makefile":
            text = text.replace(CLAUSE_FLAGS, "")
        if "MTC_CLAUSE" in text:
            out.append(f"{name}: MTC_CLAUSE in {fn} outside CBMC_CFG_EXTRA = {CLAUSE_FLAGS}")
    return out


def unchecked_clauses(functions, folders_of):
    """Per function, the clause tags (manifest.json "tags") that none of its proof folders
    checks, and the tags a folder names that the contract does not have: ["F: tag (...)"]."""
    out = []
    for fn, folders in sorted(folders_of.items()):
        out += [p for n in folders for p in selection_problems(n)]
        sels = [proof_clauses(n) for n in folders]
        if any(x is None for x in sels):
            continue
        if fn not in functions:
            out.append(f"{fn}: no contract for the FUNCTION of {', '.join(folders)}")
            continue
        tags = set(functions[fn].get("tags", []))
        named = set().union(*sels)
        out += [f"{fn}: {t} (checked by no proof folder)" for t in sorted(tags - named)]
        out += [f"{fn}: {t} (named in CLAUSES, not a clause of the contract)"
                for t in sorted(named - tags)]
    return out


HEADER_FN = re.compile(r"^[A-Za-z_][\w \t*]*?\b(mt_\w+)\s*\(", re.M)


def header_functions(inc=None):
    """The functions declared or defined in the kernel's public headers (kernel/include/mt/,
    or the folder inc), read from the text with comments (ACSL included) removed."""
    names = set()
    inc = inc or os.path.join(ROOT, "kernel", "include", "mt")
    for fn in sorted(os.listdir(inc)):
        if fn.endswith(".h"):
            with open(os.path.join(inc, fn), encoding="utf-8") as f:
                text = re.sub(r"/\*.*?\*/|//[^\n]*", "", f.read(), flags=re.S)
            names.update(m.group(1) for m in HEADER_FN.finditer(text))
    return names


def run_make(name, big, target, timeout):
    """Run `make target` in the proof folder (runtool.run_timed: its own process group, killed
    after timeout seconds); returns (rc, wall s, cpu s, output)."""
    cmd = ["make", "-s", "-C", os.path.join(PROOFS, name), target]
    if big:
        cmd.append("CBMC_BIG=1")
    r = run_timed(cmd, timeout)
    out = r.out + (f"\ntimeout: killed after {timeout} s" if r.timed_out else "")
    return r.rc, r.wall, r.cpu, out


def killed_by_timeout(rc):
    """A run killed by run_make's timer (SIGKILL to its process group; its output then ends
    with "timeout: killed after N s"): the result gets "timeout": true."""
    return rc == -signal.SIGKILL


def messages(path):
    with open(path) as f:
        return json.load(f)


def parse_result(path):
    res = {"properties": 0, "failed": 0, "failures": [], "status": "?"}
    for m in messages(path):
        if "result" in m:
            for r in m["result"]:
                res["properties"] += 1
                if r["status"] != "SUCCESS":
                    res["failed"] += 1
                    loc = r.get("sourceLocation", {})
                    res["failures"].append({
                        "property": r["property"], "status": r["status"],
                        "description": r.get("description", ""),
                        "where": f"{os.path.relpath(loc.get('file', '?'), ROOT)}:"
                                 f"{loc.get('line', '?')}"})
        if "cProverStatus" in m:
            res["status"] = m["cProverStatus"]
    return res


def parse_coverage(path, harness_file):
    goals = []
    for m in messages(path):
        if "goals" in m:
            goals = m["goals"]
    kernel_dir = os.path.join(ROOT, "kernel") + os.sep
    k_total = k_hit = 0
    uncovered = []
    reach_lines = {}
    with open(harness_file) as f:
        for n, line in enumerate(f, 1):
            if line.strip().startswith("MTC_REACH("):
                reach_lines[n] = re.sub(r"\s*/\*.*\*/\s*$", "", line.strip())
    reach_ok = {n: True for n in reach_lines}
    for g in goals:
        loc = g.get("sourceLocation", {})
        f = loc.get("file", "")
        hit = g["status"] == "satisfied"
        if f.startswith(kernel_dir):
            k_total += 1
            k_hit += hit
            if not hit:
                uncovered.append(f"{os.path.relpath(f, ROOT)}:{loc.get('line')} "
                                 f"({loc.get('function')})")
        if os.path.abspath(f) == os.path.abspath(harness_file):
            lines = set()
            for fn_lines in g.get("basicBlockLines", {}).values():
                for part in fn_lines.values():
                    for x in str(part).split(","):
                        if "-" in x:
                            a, b = x.split("-")
                            lines.update(range(int(a), int(b) + 1))
                        elif x.strip():
                            lines.add(int(x))
            if len(lines) == 1:
                (ln,) = lines
                if ln in reach_ok and not hit:
                    reach_ok[ln] = False
    return {
        "goals": len(goals),
        "goals_covered": sum(g["status"] == "satisfied" for g in goals),
        "kernel_goals": k_total,
        "kernel_covered": k_hit,
        "coverage": round(100.0 * k_hit / k_total, 1) if k_total else 0.0,
        "uncovered": uncovered,
        "reach": [{"witness": reach_lines[n][len("MTC_REACH("):-2], "reached": ok}
                  for n, ok in sorted(reach_ok.items())],
    }


COVER_FIELDS = ("coverage", "kernel_goals", "kernel_covered", "goals", "goals_covered",
                "uncovered", "reach")
RECORD = os.path.join(HERE, "records.json")
MODES = ("replay", "properties", "fresh", "save")


def load_records():
    if os.path.exists(RECORD):
        with open(RECORD) as f:
            return json.load(f)
    return {}


def save_records(records):
    # written beside the file, then renamed over it: a run stopped while saving leaves the
    # previous file whole
    tmp = RECORD + ".tmp"
    with open(tmp, "w") as f:
        f.write("{\n")
        f.write(",\n".join(f"{json.dumps(n)}: {json.dumps(records[n], sort_keys=True)}"
                           for n in sorted(records)))
        f.write("\n}\n")
    os.replace(tmp, RECORD)


KEYS_MK = os.path.join(HERE, "keys.mk")
_PREPROCESSED = {}


def preprocessed(argv):
    """goto-cc's preprocessor output for argv (None when it fails), memoised: the library
    sources are the same, with the same options, in most proofs of one run."""
    key = tuple(argv)
    if key not in _PREPROCESSED:
        p = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                           encoding="utf-8")
        _PREPROCESSED[key] = p.stdout if p.returncode == 0 else None
    return _PREPROCESSED[key]


def key_text(head, v, extra_defines):
    """The text Makefile.common's result-key or cover-key recipe gives keytext.py (the head
    text, then each source as goto-cc preprocesses it, the repository's path written @ROOT@),
    cut by keytext.py; None when a source does not preprocess."""
    parts = [head]
    for src in v["srcs"].split():
        pp = preprocessed([v["goto_cc"], "-E"] + v["defines"].split() + extra_defines.split()
                          + v["includes"].split() + [src])
        if pp is None:
            return None
        parts += ["== " + src + "\n", pp]
    # the recipe's `sed 's|ROOT|@ROOT@|g'`: the path as a basic regular expression
    root = re.compile(re.escape(v["root"]).replace(r"\.", "."))
    text = root.sub("@ROOT@", "".join(parts))
    return keytext.key_text(text)


def digest(text):
    return None if text is None else hashlib.sha256(text.encode("utf-8")).hexdigest()


def key_inputs(name, big):
    """What keys.mk prints for a proof folder (None when make fails)."""
    p = subprocess.run(["make", "-s", "-C", os.path.join(PROOFS, name), "-f", "Makefile", "-f",
                        KEYS_MK, "key-inputs"] + (["CBMC_BIG=1"] if big else []),
                       capture_output=True, text=True, encoding="utf-8")
    v = dict(line.split("\t", 1) for line in p.stdout.splitlines() if "\t" in line)
    return v if p.returncode == 0 and len(v) == 9 else None


def property_key_text(v):
    with open(v["makefile_common"], encoding="utf-8") as f:
        common = f.read()
    return key_text(f"{v['property_line']}\nresult\n{common}", v, "")


def input_keys(name, big):
    """(property run's key, coverage run's key): the digests of `make result-key` and `make
    cover-key` in the proof folder, computed here from the values keys.mk prints (one make
    call, each preprocessed source once per run); (None, None) when make fails."""
    v = key_inputs(name, big)
    if v is None:
        return None, None
    return digest(property_key_text(v)), digest(
        key_text(f"{v['cover_line']}\ncover {v['cover_defines']}\n", v, v["cover_defines"]))


BIG_DEFINE = "-DMTC_BIG=1"


def same_program_in_both_tiers(name):
    """True when CBMC_BIG=1 changes nothing CBMC analyses in this proof: its property key text
    (every source as preprocessed, cut to what the harness reaches, and every option) is the
    default tier's once the one define is taken out of its options line. MTC_BIG changes only
    the capacity helpers of lib/mtc_objects.[ch]; a harness that never reaches them is the same
    program in both tiers, and its verdicts are the default tier's (make cbmc)."""
    v, v_big = key_inputs(name, False), key_inputs(name, True)
    if v is None or v_big is None or BIG_DEFINE not in v_big["property_line"]:
        return False
    text, text_big = property_key_text(v), property_key_text(v_big)
    if text is None or text_big is None:
        return False
    options, rest = text_big.split("\n", 1)
    return options.replace(BIG_DEFINE, "") + "\n" + rest == text


def property_run(name, big, out_root, timeout, rec, key, mode):
    """The property verdict: replayed from the record when the digest of its inputs matches
    (modes replay and save), run otherwise. Returns (fields, wall s, cpu s); fields has
    "passed" False and "error" or "failures" when it did not pass."""
    if mode in ("replay", "save") and key and rec.get("result_key") == key:
        return ({"properties": rec["properties"], "failed": 0, "failures": [],
                 "property_source": "replayed",
                 "property_recorded": rec.get("result_recorded", "?")}, 0.0, 0.0)
    rc, wall, cpu, out = run_make(name, big, "result", timeout)
    d = os.path.join(out_root, name)
    f = {"properties": 0, "failed": 0, "property_source": "fresh"}
    if rc != 0 or not os.path.exists(os.path.join(d, "result.json")):
        f.update({"error": out.strip()[-2000:], "passed": False})
        if killed_by_timeout(rc):
            f["timeout"] = True
        return f, wall, cpu
    r = parse_result(os.path.join(d, "result.json"))
    f.update({k: r[k] for k in ("properties", "failed", "failures")})
    if r["failed"] or r["status"] != "success":
        f["passed"] = False
    if key and rec.get("result_key") == key and (r["failed"] or
                                                  r["properties"] != rec["properties"]):
        # the same inputs gave another verdict than the record: B10's premise is broken
        f.update({"passed": False, "error": f"record disagrees: recorded {rec['properties']} "
                  f"properties, none failed; this run {r['properties']}, {r['failed']} failed"})
    return f, wall, cpu


def run_one(name, big, out_root, timeout, records, mode):
    """Property verdict, then coverage verdict; each replayed from the record when the digest
    of its inputs matches (see CBMC_RECORD), run otherwise."""
    rec = records.get(name, {}) if not big else {}
    rkey, ckey = input_keys(name, big)
    p, wall, cpu = property_run(name, big, out_root, timeout, rec, rkey, mode)
    entry = dict({"function": name, "contract": proof_function(name), "coverage": 0.0,
                  "seconds": round(wall, 1), "cpu_seconds": round(cpu, 1)}, **p)
    if entry.get("passed") is False:
        # a failed property fails the harness whatever its coverage: no coverage run
        entry.setdefault("coverage_source", "not run (the property run did not pass)")
        return entry
    d = os.path.join(out_root, name)
    key = ckey
    if mode in ("replay", "properties", "save") and key and rec.get("key") == key:
        c = {k: rec[k] for k in COVER_FIELDS}
        entry["coverage_source"] = "replayed"
        entry["coverage_recorded"] = rec.get("recorded", "?")
    else:
        rc, wall2, cpu2, out = run_make(name, big, "coverage", max(1.0, timeout - wall))
        entry["seconds"] = round(wall + wall2, 1)
        entry["cpu_seconds"] = round(cpu + cpu2, 1)
        entry["coverage_cpu_seconds"] = round(cpu2, 1)
        if rc != 0 or not os.path.exists(os.path.join(d, "coverage.json")):
            entry.update({"error": out.strip()[-2000:], "passed": False})
            if killed_by_timeout(rc):
                entry["timeout"] = True
            return entry
        c = parse_coverage(os.path.join(d, "coverage.json"),
                           harness_path(name))
        entry["coverage_source"] = "fresh"
    entry.update({k: c[k] for k in COVER_FIELDS})
    # the properties passed (a failed one returned above): coverage and witnesses decide
    entry["passed"] = c["coverage"] >= COVERAGE_MIN and all(x["reached"] for x in c["reach"])
    if entry["passed"] and not big:
        new = dict(rec)
        if entry["property_source"] == "fresh" and rkey:
            new.update(result_key=rkey, properties=entry["properties"],
                       result_recorded=time.strftime("%Y-%m-%d"),
                       property_cpu_seconds=round(cpu, 1))
        if entry["coverage_source"] == "fresh" and key:
            new.update({k: c[k] for k in COVER_FIELDS}, key=key,
                       recorded=time.strftime("%Y-%m-%d"),
                       coverage_cpu_seconds=entry["coverage_cpu_seconds"])
        if new != rec:
            entry["_record"] = new
    return entry


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*")
    ap.add_argument("-j", type=int, default=2)
    ap.add_argument("--max", action="store_true", help="capacity-maximum tier (CBMC_BIG=1)")
    ap.add_argument("--summary", default=None)
    # A hang detector, not a budget: the slowest harness, mt_mission_set_current, took 674 s of
    # CPU for its property and coverage runs when recorded (records.json), which a fresh run
    # (make prove-cold, or an edit of the mission files) must be able to finish.
    ap.add_argument("--timeout", type=float, default=float(os.environ.get("CBMC_TIMEOUT", "1200")),
                    help="per harness, seconds (default: CBMC_TIMEOUT, else 1200)")
    ap.add_argument("--harnesses", metavar="FILE", help="the harnesses to run, one a line")
    args = ap.parse_args()

    names = args.names or proof_names()
    if args.harnesses:
        with open(args.harnesses) as f:
            names = [n for n in f.read().split() if n]
    # Harnesses that do not finish within the CI budget yet (proofs/cbmc/pending.json, each
    # with its reason) are not run by default; they count as not passed, and the summary
    # lists them. Name them, or set CBMC_ALL=1, to run them.
    pending = {}
    pfile = os.path.join(HERE, "pending.json")
    if os.path.exists(pfile):
        pending = json.load(open(pfile))
    skipped = []
    if not args.names and os.environ.get("CBMC_ALL") != "1":
        skipped = [n for n in names if n in pending]
        names = [n for n in names if n not in pending]
    unknown = [n for n in names if n not in proof_names()]
    if unknown:
        print(f"cbmc: no proof folder for {', '.join(unknown)}", file=sys.stderr)
        return 2
    gen = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "acsl2cbmc"), "--root",
                          ROOT, "--out", os.path.join(ROOT, "build/proof/cbmc/gen")],
                         capture_output=True, text=True)
    if gen.returncode != 0:
        print(gen.stdout + gen.stderr, file=sys.stderr)
        return 2
    print(gen.stdout.strip().splitlines()[-1])
    # missing proofs: every public kernel function with a contract, and every function the
    # public headers declare (with or without a contract), needs a folder. A kernel-internal
    # function (declared in kernel/src/, e.g. mt_wq_schedule_slot_i in mt_wq_int.h: a helper
    # that two files of a split module share) is checked, like a static helper, inside the
    # harnesses of the public functions that call it (its body is linked, never stubbed), and
    # its contract is proved by WP.
    manifest = json.load(open(os.path.join(ROOT, "build/proof/cbmc/gen/manifest.json")))
    public = {f for f, v in manifest["functions"].items()
              if not v["static"] and f not in manifest["stubs"] and f != "mt_port_halt"
              and not re.search(r"(^|/)kernel/src/", v["file"])}
    folders_of = {}
    for n in proof_names():
        folders_of.setdefault(proof_function(n), []).append(n)
    missing = sorted((public | header_functions()) - set(folders_of))
    if missing:
        print(f"cbmc: public functions without a proof: {', '.join(missing)}")
    # a function split over several folders (CLAUSES): together they check every clause
    unchecked = unchecked_clauses(manifest["functions"], folders_of)
    for u in unchecked:
        print(f"cbmc: clause not checked: {u}")
    open(os.path.join(ROOT, "build/proof/cbmc/gen/.stamp"), "a").close()
    os.utime(os.path.join(ROOT, "build/proof/cbmc/gen/.stamp"))

    mode = os.environ.get("CBMC_RECORD", "replay") or "replay"
    if mode not in MODES:
        print(f"cbmc: CBMC_RECORD={mode}: expected {', '.join(MODES)}", file=sys.stderr)
        return 2
    records = load_records()
    # The capacity-maximum tier runs only the proofs it changes: the others are the same
    # program as in the default tier, which make cbmc checks (make prove-cold runs both).
    same_program = []
    if args.max:
        same_program = [n for n in names if same_program_in_both_tiers(n)]
        names = [n for n in names if n not in same_program]
        print(f"cbmc-max: {len(names)} proofs reach the capacity helpers MTC_BIG changes; "
              f"{len(same_program)} are the same program in both tiers (their verdicts are the "
              "default tier's, make cbmc), not run again")
    tier = "proofs-max" if args.max else "proofs"
    out_root = os.path.join(ROOT, "build/proof/cbmc", tier)
    # Longest first: the recorded CPU time of each property run orders the queue (a harness
    # without one goes first), so the 2 workers do not end on one long harness while the other
    # core idles. The order changes no verdict; the summary lists the harnesses by name.
    names.sort(key=lambda n: (-records.get(n, {}).get("property_cpu_seconds", 1e9), n))
    t0 = time.monotonic()
    with ThreadPoolExecutor(max_workers=max(1, args.j)) as ex:
        futs = [ex.submit(run_one, n, args.max, out_root, args.timeout, records, mode)
                for n in names]
        results = []
        for n, f in zip(names, futs):
            e = f.result()
            results.append(e)
            status = "ok  " if e["passed"] else "FAIL"
            reach = e.get("reach", [])
            rec = e.pop("_record", None)
            if rec and mode == "save":
                # saved as each harness ends, merged into the file as it is now (a run stopped
                # half-way keeps what it proved; runs of other harnesses side by side keep theirs)
                save_records(dict(load_records(), **{n: rec}))
            src = {"replayed": " (replayed)", "fresh": " (fresh)   "}.get(
                e.get("coverage_source"), "")
            psrc = {"replayed": " (replayed)", "fresh": " (fresh)   "}.get(
                e.get("property_source"), "")
            print(f"{status} {n:28s} {e['properties']:6d} props {e['failed']:3d} failed{psrc} "
                  f"coverage {e['coverage']:5.1f}% ({e.get('kernel_covered', 0)}/"
                  f"{e.get('kernel_goals', 0)}){src}  witnesses "
                  f"{sum(x['reached'] for x in reach)}/{len(reach)}  "
                  f"{e['seconds']:6.1f}s ({e['cpu_seconds']:.1f}s cpu)", flush=True)
            for x in e.get("failures", []):
                print(f"     FAILED {x['property']}: {x['description']} [{x['where']}]")
            if e.get("failed"):
                print("     VERIFICATION FAILED (see build/proof/cbmc/.../result.json for traces: "
                      f"make -C proofs/cbmc/proofs/{n} result)")
            for x in reach:
                if not x["reached"]:
                    print(f"     witness not reached: {x['witness']}")
            if e.get("coverage", 100) < COVERAGE_MIN and "uncovered" in e:
                for u in e["uncovered"]:
                    print(f"     uncovered: {u}")
            if "error" in e:
                print("     " + e["error"].replace("\n", "\n     "))
    total = time.monotonic() - t0
    for n in skipped:
        print(f"PEND {n:28s} not run: {pending[n]}")
        results.append({"function": n, "contract": proof_function(n), "passed": False,
                        "pending": pending[n], "properties": 0,
                        "failed": 0, "coverage": 0.0, "seconds": 0.0, "cpu_seconds": 0.0})
    results.sort(key=lambda e: e["function"])
    passed = sum(e["passed"] for e in results)
    replayed = sum(e.get("coverage_source") == "replayed" for e in results)
    p_replayed = sum(e.get("property_source") == "replayed" for e in results)
    summary = {"harnesses": len(results), "passed": passed, "record_mode": mode,
               "properties_replayed": p_replayed,
               "properties_fresh": sum(e.get("property_source") == "fresh" for e in results),
               "coverage_replayed": replayed,
               "coverage_fresh": sum(e.get("coverage_source") == "fresh" for e in results),
               "tier": "max" if args.max else "default",
               "same_program_as_default": same_program,
               "seconds": round(total, 1), "missing_proofs": missing,
               "clauses_unchecked": unchecked, "results": results}
    path = args.summary or os.path.join(
        ROOT, "build/proof/cbmc", "summary-max.json" if args.max else "summary.json")
    with open(path, "w") as f:
        json.dump(summary, f, indent=1)
    print(f"cbmc: {passed}/{len(results)} harnesses passed in {total:.0f}s; property verdicts: "
          f"{summary['properties_fresh']} run, {p_replayed} replayed; coverage verdicts: "
          f"{summary['coverage_fresh']} run, {replayed} replayed; records: "
          f"{os.path.relpath(RECORD, ROOT)} (assumption B10, CBMC_RECORD={mode}) -> "
          f"{os.path.relpath(path, ROOT)}")
    return 0 if passed == len(results) and not missing and not unchecked else 1


if __name__ == "__main__":
    sys.exit(main())
