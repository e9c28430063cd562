#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Module records of WP runs (assumption W5): an unchanged module re-proves in seconds.

A module's WP verdict is a function of its inputs: the preprocessed source (every header it
includes, ACSL comments and line markers kept), the Frama-C options, the Why3 configuration
and driver, and the tool versions. `key` hashes all of them (the repository's location is
replaced by @ROOT@, so a clean clone elsewhere computes the same key):

  record.py key MODULE OUT -- FLAGS... -- SOURCES...
        write the key to OUT (build/proof/wp/<m>/key.txt after the run)
  record.py replay MODULE KEY DIR
        exit 0 when DIR holds a run of this key with every goal and smoke test passed
        (local incremental run), or after restoring DIR/report.json, wp.log and time.txt
        from proofs/wp/records/<m>.json.gz when that was recorded for this key; DIR/record.txt
        then says where the results come from ("run DATE" or "record DATE"). Exit 1
        otherwise (the caller runs Frama-C, after removing record.txt)
  record.py save MODULE DIR
        record DIR's run (its key.txt, report.json, wp.log, time.txt) in
        proofs/wp/records/<m>.json.gz; refused unless every goal and smoke test passed

`make wp` replays a record only with WP_CACHE=update (the default) or replay, and not with
WP_FCT; `make wp-cache-save` writes the records after the canary and the gate pass. The gate
and the report name every replayed module and the date of its record; WP_CACHE=none, or
WP_RECORD=no, runs Frama-C on every module.
"""
import base64
import datetime
import gzip
import hashlib
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RECORDS = os.path.join(HERE, "records")
sys.path.insert(0, HERE)
import gate  # noqa: E402  (module_stats: the gate's own reading of a run)

CONFIG_FILES = ("proofs/wp/why3.conf", "proofs/wp/z3_fixedto.drv", "proofs/wp/goal_only.sh",
                "proofs/wp/mkconf.sh")


def tool_line(cmd):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
        return (p.stdout + p.stderr).strip()
    except (OSError, subprocess.TimeoutExpired) as e:
        return f"{cmd[0]}: {e}"


def preprocess(src, flags):
    """The source as Frama-C's preprocessor sees it: its libc, its defines, comments kept."""
    share = tool_line(["frama-c", "-print-share-path"])
    incs = [f for f in flags if f.startswith("-I")]
    cmd = ["gcc", "-E", "-C", "-I.", f"-I{share}/libc", "-D__FRAMAC__",
           "-D__FC_MACHDEP_X86_64", "-dD", "-nostdinc", "-m64"] + incs + [src]
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit(f"record.py: preprocessing {src} failed:\n{p.stderr}")
    return p.stdout


def key(module, flags, sources):
    h = hashlib.sha256()

    def add(label, text):
        h.update(f"== {label}\n".encode())
        h.update(text.replace(ROOT, "@ROOT@").encode())
        h.update(b"\n")

    add("module", module)
    add("frama-c", tool_line(["frama-c", "-version"]))
    add("why3", tool_line(["why3", "--version"]))
    # the configuration the runs use: proofs.mk passes it as WHY3CONFIG ($(WP_WHY3CONF))
    conf = os.environ.get("WHY3CONFIG") or os.path.join(ROOT, "build/proof/why3.conf")
    # (running_provers_max is the machine's core count: it changes no verdict)
    text = open(conf, encoding="utf-8").read() if os.path.exists(conf) else "-"
    add("why3.conf", "\n".join(ln for ln in text.splitlines()
                               if not ln.startswith("running_provers_max")))
    for p in CONFIG_FILES:
        add(p, open(os.path.join(ROOT, p), encoding="utf-8").read())
    # Prover versions: the configuration names binaries; their version lines are hashed too.
    add("z3", tool_line(["z3", "--version"]))
    add("cvc4", tool_line(["cvc4", "--version"]))
    add("flags", " ".join(flags))
    for s in sources:
        add(s, preprocess(s, flags))
    return h.hexdigest()


def all_passed(module, d):
    st = gate.module_stats(module, os.path.dirname(d))
    return (not st["missing"] and not st["failures"] and not st["fatal"] and
            st["goals"] > 0 and st["proved"] == st["goals"] and
            st["smoke_passed"] == st["smoke"]), st


def record_path(module):
    return os.path.join(RECORDS, f"{module}.json.gz")


def write_origin(d, source, date):
    with open(os.path.join(d, "record.txt"), "w", encoding="utf-8") as f:
        f.write(f"{source} {date}\n")


def replay(module, k, d):
    kfile = os.path.join(d, "key.txt")
    # local incremental run: the last run in DIR had this key and passed
    if os.path.exists(kfile) and open(kfile).read().strip() == k:
        ok, _ = all_passed(module, d)
        if ok:
            origin = gate.read_origin(d)
            if origin is None:
                t = os.path.getmtime(os.path.join(d, "report.json"))
                origin = {"source": "run", "date": datetime.date.fromtimestamp(t).isoformat()}
                write_origin(d, origin["source"], origin["date"])
            what = "module record" if origin["source"] == "record" else "run"
            return f"not re-run: unchanged since the {what} of {origin['date']} (W5)"
    rp = record_path(module)
    if not os.path.exists(rp):
        return None
    with gzip.open(rp, "rt", encoding="utf-8") as f:
        rec = json.load(f)
    if rec.get("key") != k:
        return None
    os.makedirs(d, exist_ok=True)
    for name in ("report.json", "wp.log", "time.txt"):
        with open(os.path.join(d, name), "w", encoding="utf-8") as f:
            f.write(rec["files"][name].replace("@ROOT@", ROOT))
    write_origin(d, "record", rec["recorded"])
    with open(kfile, "w") as f:
        f.write(k + "\n")
    return f"not re-run: replayed the module record of {rec['recorded']} (W5)"


def save(module, d):
    ok, st = all_passed(module, d)
    kfile = os.path.join(d, "key.txt")
    if not ok or not os.path.exists(kfile):
        raise SystemExit(f"record.py: {module}: not recorded (the run in {d} did not pass "
                         "every goal and smoke test, or has no key)")
    origin = gate.read_origin(d)
    if origin and origin["source"] == "record":
        raise SystemExit(f"record.py: {module}: {d} holds a replayed record, not a run")
    files = {}
    for name in ("report.json", "wp.log", "time.txt"):
        with open(os.path.join(d, name), encoding="utf-8", errors="replace") as f:
            files[name] = f.read().replace(ROOT, "@ROOT@")
    rec = {"module": module, "key": open(kfile).read().strip(),
           "recorded": datetime.date.today().isoformat(), "time_s": st["time_s"],
           "goals": st["goals"], "smoke": st["smoke"], "files": files}
    os.makedirs(RECORDS, exist_ok=True)
    data = json.dumps(rec, sort_keys=True).encode()
    # mtime 0: the same record gives the same bytes
    with open(record_path(module), "wb") as raw:
        with gzip.GzipFile(fileobj=raw, mode="wb", mtime=0, filename="") as f:
            f.write(data)
    return rec


def main(argv):
    if len(argv) >= 3 and argv[0] == "key":
        module, out = argv[1], argv[2]
        rest = argv[3:]
        if not rest or rest[0] != "--" or "--" not in rest[1:]:
            raise SystemExit("usage: record.py key MODULE OUT -- FLAGS... -- SOURCES...")
        i = rest.index("--", 1)
        k = key(module, rest[1:i], rest[i + 1:])
        os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
        with open(out, "w") as f:
            f.write(k + "\n")
        return 0
    if len(argv) == 4 and argv[0] == "replay":
        why = replay(argv[1], argv[2], argv[3])
        if why is None:
            return 1
        print(why)
        return 0
    if len(argv) == 3 and argv[0] == "save":
        rec = save(argv[1], argv[2])
        print(f"record.py: {argv[1]}: {rec['goals']} goals, {rec['smoke']} smoke tests recorded")
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
