#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Trace validation of tla/Ring.tla, tla/Sem.tla and tla/Mission.tla against the C code.

Builds tools/trace/ring_trace against kernel/src/ring.c and objring.c (with
the tracing mt_atomic.h of tools/trace/shim) and tools/trace/sem_trace against
kernel/src/sem.c and hal_posix/port.c (port calls intercepted with --wrap),
runs them for several configurations and seeds, and checks each trace with
TLC through tla/RingTrace.tla or tla/SemTrace.tla: the trace is
accepted iff TLC reports the invariant
TraceNotAccepted violated (a state with the whole log consumed is reachable);
it is rejected when TLC reports a deadlock (a state from which no model step
matches the next event; the accepted end state stutters). As a control, one
mutated copy per configuration (one logged index value changed) must be
rejected.

tools/trace/mission_trace runs kernel/src/mission*.c on fixed missions with
seeded random operations and callback outcomes; tla/MissionTrace.tla
replays each log (callbacks in order with index and outcome, cursor state
after each call). Two controls per mission must be rejected at the changed
event: one logged nav_idx changed ("mutated") and one callback outcome that
the kernel acts on flipped ("flipped": a verify, or the start of a nav
command; a do command's start result is ignored).

    tools/trace/run_traces.py [--jar JAR] [--out DIR] [--seeds N] [--only ring sem mission]

Writes <out>/summary.json; exits non-zero on any unexpected result.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "proofs"))
from runtool import run_timed  # noqa: E402

# (name, kind, cap, max_msg, max_len, drop)
CASES = [
    ("byte_c4", "byte", 4, 40, 3, 0),
    ("byte_c3", "byte", 3, 30, 3, 0),
    ("obj_push_c3", "obj", 3, 30, 1, 0),
    ("obj_drop_c2", "obj", 2, 30, 1, 1),
    ("obj_drop_c3", "obj", 3, 30, 1, 1),
]

# sem_trace WAITS SIGNALS per seed
SEM_CASE = ("sem_posix", 40, 20)

# mission_trace MISSION OPS per seed (missions defined in mission_trace.c)
MISSION_CASES = [
    ("mission_nested", "nested", 200),
    ("mission_forever", "forever", 200),
    ("mission_tags_do", "tags_do", 200),
    ("mission_do_runs", "do_runs", 200),
]
MISSION_SEEDS = 2
# MT_CFG_MISSION_ADVANCE_EXTRA of the traced mission*.c, and the model's Extra: 2, as in the
# CBMC harnesses and the TLC configurations. The default 255 is the same code with a larger
# loop bound, which only a walk with more refused nav starts than the traces have reaches;
# the model's walk then costs TLC about 10 times more (forever: 30 s a trace instead of 3 s).
MISSION_ADVANCE_EXTRA = 2

RE_LOAD = re.compile(r'k \|-> "load", f \|-> "(\w+)", v \|-> (\d+)\]')
RE_RESUME = re.compile(r'k \|-> "resume", r \|-> (TRUE|FALSE)\]')
RE_NAVIDX = re.compile(r'snap \|-> TRUE, .*?navidx \|-> (\d+)')
RE_CB = re.compile(r'k \|-> "(start|verify)", i \|-> (\d+), r \|-> (TRUE|FALSE)\]')
RE_TN = re.compile(r'^TN == (\d+)$', re.M)
RE_TKIND = re.compile(r'^TKind == <<(.*)>>$', re.M)


def mission_kinds(text):
    """Kind of each index 1..TN-1 of a mission trace module (list index i - 1)."""
    return [k.strip().strip('"') for k in RE_TKIND.search(text).group(1).split(",")]


KINC = ["-I" + os.path.join(ROOT, "kernel", d) for d in ("include", "port", "spec", "src")]
KSRC = os.path.join(ROOT, "kernel", "src")
WRAP = ["mt_port_lock", "mt_port_unlock", "mt_port_lock_isr", "mt_port_unlock_isr",
        "mt_port_suspend_s", "mt_port_resume_i"]


def build(out):
    cc = ["gcc", "-std=c11", "-O1", "-g", "-Wall", "-Wextra", "-Werror"]
    ring = os.path.join(out, "ring_trace")
    subprocess.run(cc + ["-I" + os.path.join(HERE, "shim")] + KINC +
                   [os.path.join(HERE, "ring_trace.c"), os.path.join(KSRC, "ring.c"),
                    os.path.join(KSRC, "objring.c"), os.path.join(KSRC, "status.c"),
                    "-o", ring], check=True)
    sem = os.path.join(out, "sem_trace")
    # port.c also holds the proc and work-queue threads, hence proc.c, invoke.c, time.c and wq*.c
    wq_srcs = [os.path.join(KSRC, f) for f in ("wq.c", "wq_timer.c", "wq_run.c", "wq_report.c")]
    subprocess.run(cc + KINC + ["-I" + os.path.join(ROOT, "hal_posix"),
                                os.path.join(HERE, "sem_trace.c"), os.path.join(KSRC, "sem.c"),
                                os.path.join(KSRC, "proc.c"), os.path.join(KSRC, "invoke.c"),
                                os.path.join(KSRC, "time.c")] + wq_srcs + [
                                os.path.join(ROOT, "hal_posix", "port.c"),
                                "-Wl," + ",".join("--wrap=" + w for w in WRAP),
                                "-pthread", "-o", sem], check=True)
    mission = os.path.join(out, "mission_trace")
    subprocess.run(cc + ["-Wconversion", "-Wsign-conversion", "-Wshadow", "-Wstrict-prototypes",
                         "-DMT_CFG_MISSION_ADVANCE_EXTRA=%du" % MISSION_ADVANCE_EXTRA]
                   + KINC + [os.path.join(HERE, "mission_trace.c"),
                             os.path.join(KSRC, "mission.c"),
                             os.path.join(KSRC, "mission_check.c"),
                             os.path.join(KSRC, "mission_seq.c"),
                             os.path.join(KSRC, "mission_invoke.c"), "-o", mission], check=True)
    return ring, sem, mission


def write_cfg(path, kind, cap, max_msg, max_len, drop):
    with open(path, "w") as f:
        f.write("CONSTANTS\n")
        f.write('    Kind = "%s"\n    Cap = %d\n    MaxMsg = %d\n    MaxLen = %d\n'
                % (kind, cap, max_msg, max_len))
        f.write("    DropOldest = %s\n" % ("TRUE" if drop else "FALSE"))
        f.write('    Api = "core"\n    PublishEarly = FALSE\n    WriterDropOldest = FALSE\n'
                '    CountReports = FALSE\n')
        f.write("SPECIFICATION TraceSpec\nINVARIANT TraceNotAccepted\n")


def write_sem_cfg(path):
    with open(path, "w") as f:
        f.write("CONSTANTS\n    Waiters = {w1}\n    w1 = w1\n    MaxSignals <- Signals\n"
                "    InitToken = 0\n    SignalNoResume = FALSE\n    TimeoutIgnoresResume = FALSE\n"
                "SPECIFICATION TraceSpec\nINVARIANT TraceNotAccepted\n")


def write_mission_cfg(path):
    # the model's invariants hold on every state of the trace too (the trace missions have
    # no model configuration of their own); TraceNotAccepted comes last
    with open(path, "w") as f:
        f.write("CONSTANTS\n    N <- TN\n    Kind <- TKind\n    Tgt <- TTgt\n    Rep <- TRep\n"
                "    NONE = 0\n    Extra = %d\n    VARIANT = \"ap\"\nSPECIFICATION TraceSpec\n"
                % MISSION_ADVANCE_EXTRA +
                "INVARIANTS TypeOK CursorsValid NavActive CountersBounded NoCallbackSeesJump\n"
                "    CompleteOncePerRun LookAheadBounded LookAheadMatches AdvanceFollowsOrder\n"
                "    FirstDoBeforeNav TrailingDoStarts TraceNotAccepted\n")


def mutate_mission(data_path, variant):
    """Mission: "mutated" changes the nav_idx of the middle state-carrying event
    (to the next value in 0..TN-1, 0 standing for MT_MISSION_NONE); "flipped"
    flips the outcome of the middle callback whose outcome the kernel acts on (a
    verify, or the start of a nav command). Returns the index of the changed
    event (0: none)."""
    with open(data_path) as f:
        text = f.read()
    n = int(RE_TN.search(text).group(1))
    if variant == "mutated":
        found = list(RE_NAVIDX.finditer(text))
        group = 1
    else:
        kinds = mission_kinds(text)
        found = [m for m in RE_CB.finditer(text)
                 if m.group(1) == "verify" or kinds[int(m.group(2)) - 1] == "nav"]
        group = 3
    if not found:
        return 0
    m = found[len(found) // 2]
    if variant == "mutated":
        v = str((int(m.group(1)) + 1) % n)
    else:
        v = "FALSE" if m.group(3) == "TRUE" else "TRUE"
    with open(data_path, "w") as f:
        f.write(text[:m.start(group)] + v + text[m.end(group):])
    return text.count("[op |-> ", 0, m.start(group))


def mutate(data_path, slots):
    """Ring: change the value of the middle load event (mod 2*slots).
    Semaphore (slots None): flip the result of the middle resume_i event."""
    with open(data_path) as f:
        text = f.read()
    found = list((RE_LOAD if slots else RE_RESUME).finditer(text))
    if not found:
        return False
    m = found[len(found) // 2]
    if slots:
        v = str((int(m.group(2)) + 1) % (2 * slots))
        new = text[:m.start(2)] + v + text[m.end(2):]
    else:
        v = "FALSE" if m.group(1) == "TRUE" else "TRUE"
        new = text[:m.start(1)] + v + text[m.end(1):]
    with open(data_path, "w") as f:
        f.write(new)
    return True


def tlc(args, work, spec):
    # -Xss: the mission model's walk recurses once per command it visits (with
    # MT_CFG_MISSION_ADVANCE_EXTRA 255 the default stack overflows)
    # a private java.io.tmpdir: TLC copies the standard modules there before parsing them,
    # and a shared one races with every other TLC run (see tla/run_tlc.py)
    tmp = os.path.join(work, "tmp")
    os.makedirs(tmp, exist_ok=True)
    cmd = ["java", "-XX:+UseParallelGC", "-Xmx1g", "-Xss64m", "-Djava.io.tmpdir=" + tmp,
           "-cp", args.jar, "tlc2.TLC",
           "-workers", "auto", "-cleanup", "-metadir", os.path.join(work, "states"),
           "-config", spec + ".cfg", spec + ".tla"]
    run = run_timed(cmd, args.timeout, cwd=work)
    log = run.out + ("\ntimeout: killed after %d s" % args.timeout if run.timed_out else "")
    if run.timed_out:
        result = "error"
    elif re.search(r"^Error: Invariant TraceNotAccepted is violated", log, re.M):
        result = "accepted"
    elif re.search(r"^Error: Deadlock reached", log, re.M):
        result = "rejected"   # no model step matches the next event
    else:
        result = "error"
    m = re.findall(r"([\d,]+) distinct states found", log)
    distinct = int(m[-1].replace(",", "")) if m else None
    return result, distinct, log


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--jar", default=os.path.join(ROOT, ".tools", "tla", "tla2tools.jar"))
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "proof", "tla", "trace"))
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--timeout", type=int, default=300)
    ap.add_argument("--only", nargs="+", choices=("ring", "sem", "mission"),
                    help="run these families only (default: all)")
    args = ap.parse_args()
    args.jar = os.path.abspath(args.jar)
    args.out = os.path.abspath(args.out)
    os.makedirs(args.out, exist_ok=True)
    ring_exe, sem_exe, mission_exe = build(args.out)
    families = set(args.only or ("ring", "sem", "mission"))

    results = []
    t_all = time.monotonic()
    jobs = []
    if "ring" in families:
        jobs += [c for c in CASES]
    if "sem" in families:
        jobs.append(SEM_CASE)
    if "mission" in families:
        jobs += [c for c in MISSION_CASES]
    for job in jobs:
        seeds = args.seeds
        controls = [("mutated", "rejected")]
        if job is SEM_CASE:
            name, waits, signals = job
            kind, cap, max_msg, max_len, drop, slots = "sem", None, None, None, 0, None
            spec, datamod = "SemTrace", "SemTraceData.tla"
            modules = ("Sem.tla", "SemTrace.tla")
        elif job in MISSION_CASES:
            name, mission, ops = job
            kind, cap, max_msg, max_len, drop, slots = "mission", None, None, None, 0, None
            spec, datamod = "MissionTrace", "MissionTraceData.tla"
            modules = ("Mission.tla", "MissionTrace.tla")
            seeds = min(args.seeds, MISSION_SEEDS)
            controls = [("mutated", "rejected"), ("flipped", "rejected")]
        else:
            name, kind, cap, max_msg, max_len, drop = job
            slots = cap if kind == "byte" else cap + 1
            spec, datamod = "RingTrace", "RingTraceData.tla"
            modules = ("Ring.tla", "RingTrace.tla")
        for seed in range(1, seeds + 1):
            runs = [("trace", "accepted")]
            if seed == 1:
                runs += controls
            for variant, expect in runs:
                label = "%s_s%d%s" % (name, seed, "" if variant == "trace" else "_" + variant)
                work = os.path.join(args.out, label)
                shutil.rmtree(work, ignore_errors=True)
                os.makedirs(work)
                if kind == "sem":
                    subprocess.run([sem_exe, str(waits), str(signals), str(seed), work],
                                   check=True, stdout=subprocess.DEVNULL)
                elif kind == "mission":
                    subprocess.run([mission_exe, mission, str(ops), str(seed), work], check=True)
                else:
                    subprocess.run([ring_exe, kind, str(cap), str(max_msg), str(max_len),
                                    str(drop), str(seed), work], check=True)
                data = os.path.join(work, datamod)
                with open(data) as f:
                    text = f.read()
                events = text.count("k |-> ") if kind != "mission" else text.count("[op |-> ")
                changed = 0
                if kind == "mission" and variant != "trace":
                    changed = mutate_mission(data, variant)
                    if not changed:
                        continue
                elif variant == "mutated" and not mutate(data, slots):
                    continue
                for mod in modules:
                    shutil.copy(os.path.join(ROOT, "tla", mod), work)
                if kind == "sem":
                    write_sem_cfg(os.path.join(work, spec + ".cfg"))
                elif kind == "mission":
                    write_mission_cfg(os.path.join(work, spec + ".cfg"))
                else:
                    write_cfg(os.path.join(work, spec + ".cfg"), kind, cap, max_msg,
                              max_len, drop)
                t0 = time.monotonic()
                result, distinct, log = tlc(args, work, spec)
                seconds = round(time.monotonic() - t0, 1)
                with open(os.path.join(work, "tlc.log"), "w") as f:
                    f.write(log)
                shutil.rmtree(os.path.join(work, "states"), ignore_errors=True)
                shutil.rmtree(os.path.join(work, "tmp"), ignore_errors=True)
                ok = result == expect
                rec = {"name": label, "kind": kind, "cap": cap, "max_msg": max_msg,
                       "max_len": max_len, "drop_oldest": bool(drop), "seed": seed,
                       "events": events, "expect": expect, "result": result,
                       "distinct_states": distinct, "seconds": seconds, "ok": ok}
                if kind == "mission":
                    rec["mission"] = mission
                    rec["ops"] = ops
                    rec["completions"] = int(re.search(r"^Completions == (\d+)", text, re.M).group(1))
                    # what the trace exercised: calls per operation and status, refused starts
                    calls = {}
                    for op, rc in re.findall(r'\[op \|-> "(\w+)", arg \|-> \d+, rc \|-> "(\w+)"', text):
                        if op != "update_do":
                            key = ("update" if op == "update_nav" else op) + ":" + rc
                            calls[key] = calls.get(key, 0) + 1
                    rec["calls"] = dict(sorted(calls.items()))
                    # nav starts refused (a do command's start result is ignored)
                    kinds = mission_kinds(text)
                    rec["refused_starts"] = sum(
                        1 for m in RE_CB.finditer(text)
                        if m.group(1) == "start" and kinds[int(m.group(2)) - 1] == "nav"
                        and m.group(3) == "FALSE")
                stuck = re.findall(r"^/\\ ti = (\d+)", log, re.M)
                if result == "rejected" and stuck:
                    rec["unmatched_event"] = int(stuck[-1])   # Trace[ti]: no model step matches
                if changed:
                    # a control must fail at the changed event (a flipped outcome of the
                    # nav half of an update shows at the state check of the do half)
                    rec["changed_event"] = changed
                    if rec.get("unmatched_event") not in (changed, changed + 1):
                        rec["ok"] = ok = False
                if drop and variant == "trace":
                    # MT_W_DROPPED_OLDEST returns versus objects the consumer discarded
                    with open(data) as f:
                        text = f.read()
                    rec["dropped_oldest_returns"] = text.count('"MT_W_DROPPED_OLDEST"')
                    rec["lost"] = int(re.search(r"lost \|-> (\d+)", text).group(1))
                results.append(rec)
                print("%-4s %-26s %5d events  %-9s %8s states %6.1f s%s" % (
                    "ok" if ok else "FAIL", label, events, result,
                    distinct if distinct is not None else "-", seconds,
                    "  (event %d unmatched)" % rec["unmatched_event"]
                    if "unmatched_event" in rec else ""), flush=True)
    passed = sum(1 for r in results if r["ok"])
    over = [r["name"] for r in results
            if r.get("dropped_oldest_returns", 0) > r.get("lost", 0)]
    if over:
        print("note: MT_W_DROPPED_OLDEST returned more often than objects were lost in: "
              + ", ".join(over))
    summary = {"traces": results, "passed": passed, "total": len(results),
               "dropped_oldest_over_reported": over,
               "seconds": round(time.monotonic() - t_all, 1)}
    with open(os.path.join(args.out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
        f.write("\n")
    print("tla-trace: %d/%d as expected" % (passed, len(results)))
    return 0 if passed == len(results) else 1


if __name__ == "__main__":
    sys.exit(main())
