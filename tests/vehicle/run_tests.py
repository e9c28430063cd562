#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""make test-vehicle: the example vehicle's tests (SITL flights, fault injection, bad
missions, the schedulability check and its agreement with what SITL measures).

    run_tests.py [--build DIR] [-k SUBSTRING] [--firmware ELF]

--firmware: the MAVLink tests against the ChibiOS firmware's ground-station session under QEMU
(make test-vehicle-fw) instead of the SITL; tests it cannot run say why (SKIP).

Each test runs the SITL binary (build/sitl/metronome-sitl, simulated time unless said
otherwise) or tools/sched_check.py and checks its output. Prints one line per test and a
summary; exit status 1 when any test fails.
"""

import argparse
import json
import math
import os
import re
import signal
import struct
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "vehicle", "tools"))
import logdump  # noqa: E402

PY = sys.executable
MISSIONS = os.path.join(ROOT, "vehicle", "missions")


class Fail(Exception):
    pass


class Skip(Exception):
    """The test cannot run on this vehicle (--firmware); the reason."""


def check(cond, what):
    if not cond:
        raise Fail(what)


class Run:
    """One SITL run: exit status, stdout, the task table and the counters."""

    def __init__(self, binary, args, timeout=120, env=None):
        t0 = time.time()
        p = subprocess.run([binary] + args, capture_output=True, text=True, timeout=timeout, cwd=ROOT, env=env)
        self.seconds = time.time() - t0
        self.rc, self.out, self.err = p.returncode, p.stdout, p.stderr
        self.lines = self.out.splitlines()
        self.tasks = {}
        hdr = next((i for i, l in enumerate(self.lines) if l.startswith("task ") and "pending" in l), None)
        if hdr is not None:
            for l in self.lines[hdr + 1:]:
                f = l.split()
                if len(f) != 12 or not f[3].isdigit():
                    break
                self.tasks[f[0]] = dict(zip(["rate", "budget", "runs", "expect", "min", "max", "mean",
                                             "overrun", "slips", "skips", "pending"],
                                            [f[1]] + [int(x) for x in f[2:]]))

    def events(self, prefix):
        """Console lines after the time stamp that start with prefix."""
        out = []
        for l in self.lines:
            m = re.match(r"\[\s*[0-9.]+\] (.*)$", l)
            if m and m.group(1).startswith(prefix):
                out.append(m.group(1))
        return out

    def line(self, prefix):
        return next((l for l in self.lines if l.startswith(prefix)), None)

    def value(self, pattern):
        m = re.search(pattern, self.out)
        check(m is not None, "no match for %r in the output" % pattern)
        return int(m.group(1))


class Suite:
    def __init__(self, build):
        self.sitl = os.path.join(build, "sitl", "metronome-sitl")
        self.sitl_over = os.path.join(build, "sitl", "metronome-sitl-overloaded")
        self.sitl_asan = os.path.join(build, "sitl-asan", "metronome-sitl")
        self.sitl_tsan = os.path.join(build, "sitl-tsan", "metronome-sitl")
        self.tmp = tempfile.mkdtemp(prefix="veh-tests-")
        self.cache = {}
        self.firmware = None  # --firmware: the vehicle of the MAVLink sessions

    def fly(self, mission, *extra, binary=None):
        args = ["--quiet"] + list(extra) + ([mission] if mission else [])
        key = (binary or self.sitl, tuple(args))
        if key not in self.cache:
            self.cache[key] = Run(binary or self.sitl, args)
        return self.cache[key]

    def sched(self, table, *extra):
        j = os.path.join(self.tmp, "sched-%d.json" % len(self.cache))
        t0 = time.time()
        p = subprocess.run([PY, os.path.join(ROOT, "tools", "sched_check.py"), table, "--json", j] + list(extra),
                           capture_output=True, text=True, timeout=300, cwd=ROOT)
        res = json.load(open(j)) if os.path.exists(j) else None
        return p.returncode, p.stdout + p.stderr, res, time.time() - t0


# ---- flights --------------------------------------------------------------------------------

def started(run):
    return [re.match(r"mission: #(\d+) (\w+) started", e).group(1, 2) for e in run.events("mission: #")
            if " started" in e]


def flight_ok(run, log=None):
    """A completed flight: exit 0, COMPLETE, nominal table facts (Z3: no task misses a
    release, so no slip and nothing pending; honest budgets, so no overrun; which tasks
    may be skipped is checked against Z3's lateness in t_agreement), no lost data."""
    check(run.rc == 0, "exit status %d (expected 0)\n%s" % (run.rc, run.out[-2000:]))
    check(run.line("mission: COMPLETE") is not None, "mission not complete")
    check(run.line("run ended: mission complete, vehicle landed and disarmed") is not None, "run end")
    check(len(run.tasks) == 12, "task table has %d rows" % len(run.tasks))
    for name, r in run.tasks.items():
        check(r["slips"] == 0 and r["pending"] <= 1 and r["overrun"] == 0,
              "%s: slips %d pending %d overruns %d" % (name, r["slips"], r["pending"], r["overrun"]))
        check(r["expect"] - 1 <= r["runs"] <= r["expect"], "%s ran %d times, expected %d" % (name, r["runs"],
                                                                                           r["expect"]))
    check(run.value(r"long loops (\d+)") == 0, "long loops")
    check(run.value(r"(\d+) dropped, \d+ queued, \d+ failed reads") == 0, "barometer samples dropped")
    check(run.value(r"bus: \d+ transactions, \d+ waited for the bus, (\d+) timeouts") == 0, "bus timeouts")
    check(run.value(r"bus collisions (\d+)") == 0, "bus collisions")
    check(run.value(r"log: \d+ records, \d+ bytes to the sink, (\d+) dropped") == 0, "log records dropped")
    battery_ok(run)
    if log is not None:
        data = open(log, "rb").read()
        recs, errors = logdump.read(data)
        check(not errors, "log: %s" % errors[:3])
        check(len(recs) == run.value(r"log: (\d+) records"), "log records in the file vs the summary")
        check(len(data) == run.value(r"log: \d+ records, (\d+) bytes"), "log bytes in the file vs the summary")
        cmds = [struct.unpack_from("<QHHB", p) for typ, _, p in recs if typ == 6]
        check(len([c for c in cmds if c[3] == 1]) == run.value(r"mission: COMPLETE \((\d+) commands started"),
              "CMD start records vs commands started")
        check(any(c[3] == 3 for c in cmds), "no mission-complete record in the log")


def battery_ok(run):
    """The battery monitor (a 3 Hz interval work item) and its topic: one run per period of
    the flight (the interval is measured from the item's starts), every reading published,
    and every reading received by housekeeping or counted as missed, none lost silently."""
    runs = run.value(r"battery item: (\d+) runs")
    seconds = run.value(r"scheduler: loop \d+ Hz, \d+ tasks, (\d+) ticks") / 400.0
    check(abs(runs - 3 * seconds) <= 2, "battery item ran %d times in %.1f s (3 Hz)" % (runs, seconds))
    check(run.value(r"work queue \w+: \d+ runs, (\d+) merged") == 0, "merged activations")
    check(run.value(r"work queue \w+: \d+ runs, \d+ merged, (\d+) periods missed") == 0, "periods missed")
    m = re.search(r"interval ([0-9.]+) ms \(min ([0-9.]+), max ([0-9.]+)\)", run.out)
    check(m is not None and abs(float(m.group(1)) - 333.3) < 2.0 and float(m.group(3)) < 340.0,
          "battery interval %s" % (m.group(0) if m else None))
    check(run.value(r"max [0-9.]+\), (\d+) failed reads") == 0, "battery reads failed")
    pub = run.value(r"topic battery: (\d+) published")
    check(pub == runs, "published %d of %d readings" % (pub, runs))
    got = run.value(r"housekeeping: (\d+) received")
    lost = run.value(r"housekeeping: \d+ received, (\d+) missed")
    check(got + lost == pub or got + lost + 1 == pub, "received %d + missed %d vs published %d" % (got, lost, pub))
    check(run.value(r"topic battery: \d+ published, (\d+) refused") == 0, "refused publishes")


def t_plain(S):
    log = os.path.join(S.tmp, "plain.bin")
    r = S.fly(os.path.join(MISSIONS, "plain.waypoints"), "--log", log)
    flight_ok(r, log)
    check(started(r) == [("1", "TAKEOFF"), ("2", "WAYPOINT"), ("3", "WAYPOINT"), ("4", "WAYPOINT"),
                         ("5", "WAYPOINT"), ("6", "LAND")], "command sequence %s" % started(r))
    check([re.search(r"#(\d+)", e).group(1) for e in r.events("mission: waypoint #")] == ["2", "3", "4", "5"],
          "waypoints reached")
    check(r.events("mission: complete") == ["mission: complete"], "mission complete once")
    check(r.value(r"servo writes (\d+)") == 0, "servo writes")


def t_jumps(S):
    r = S.fly(os.path.join(MISSIONS, "jumps.waypoints"))
    flight_ok(r)
    square = [("2", "WAYPOINT"), ("3", "WAYPOINT"), ("4", "WAYPOINT")]
    check(started(r) == [("1", "TAKEOFF")] + square * 3 + [("6", "WAYPOINT"), ("7", "LAND")],
          "command sequence %s" % started(r))
    check(r.value(r"\((\d+) commands started") == 12, "12 commands")


def t_land(S):
    r = S.fly(os.path.join(MISSIONS, "land.waypoints"))
    flight_ok(r)
    # AP_Mission order: the do command after a nav command starts just before the next one
    check(started(r) == [("1", "TAKEOFF"), ("2", "DO_CHANGE_SPEED"), ("3", "WAYPOINT"), ("4", "DO_SET_SERVO"),
                         ("5", "WAYPOINT"), ("7", "LAND")], "command sequence %s" % started(r))
    m = re.search(r"vehicle: landed at ([0-9.]+) m from home", r.out)
    check(m is not None and 83.0 < float(m.group(1)) < 89.0, "landed at the LAND location (86 m from home)")
    check(r.value(r"servo writes (\d+)") == 1, "one servo write")


def t_rtl(S):
    r = S.fly(os.path.join(MISSIONS, "rtl.waypoints"))
    flight_ok(r)
    check(started(r) == [("1", "TAKEOFF"), ("2", "WAYPOINT"), ("3", "WAYPOINT"), ("4", "RTL")], "sequence")
    check(r.events("mission: RTL home reached, landing") != [], "RTL reached home")
    m = re.search(r"vehicle: landed at ([0-9.]+) m from home", r.out)
    check(m is not None and float(m.group(1)) < 2.0, "landed at home")


def t_loiter(S):
    r = S.fly(os.path.join(MISSIONS, "loiter.waypoints"))
    flight_ok(r)
    # the delay starts with LOITER_TIME and holds back the servo, not the loiter
    check(started(r) == [("1", "TAKEOFF"), ("2", "LOITER_TURNS"), ("3", "CONDITION_DELAY"), ("5", "LOITER_TIME"),
                         ("4", "DO_SET_SERVO"), ("6", "CONDITION_YAW"), ("8", "WAYPOINT"),
                         ("7", "CONDITION_DISTANCE"), ("9", "RTL")], "command sequence %s" % started(r))
    for c in ("#3 CONDITION_DELAY done", "#6 CONDITION_YAW done", "#7 CONDITION_DISTANCE done"):
        check(r.events("mission: " + c) != [], c)


def t_stop_resume(S):
    r = S.fly(os.path.join(MISSIONS, "plain.waypoints"), "--event", "20:stop", "--event", "26:resume")
    flight_ok(r)
    check(r.events("gcs: mission stopped at #3") != [], "stopped at #3")
    check(r.events("vehicle: mode AUTO -> HOLD") != [] and r.events("vehicle: mode HOLD -> AUTO") != [],
          "HOLD while stopped")
    check(r.events("gcs: mission resumed") != [], "resumed")
    # resume restarts the active nav command (#3 started twice), then the rest as usual
    check(started(r) == [("1", "TAKEOFF"), ("2", "WAYPOINT"), ("3", "WAYPOINT"), ("3", "WAYPOINT"),
                         ("4", "WAYPOINT"), ("5", "WAYPOINT"), ("6", "LAND")], "sequence %s" % started(r))
    # nothing happens to the mission while it is stopped
    ev = [(float(m.group(1)), m.group(2)) for m in re.finditer(r"\[\s*([0-9.]+)\] (mission: [^\n]*)", r.out)]
    check(not any(20.0 < t < 26.0 for t, _ in ev), "mission events while stopped")


def t_loiter_unlim(S):
    """LOITER_UNLIM holds forever; a ground-station 'land' ends the flight, the mission stays
    incomplete and the run says so (exit 1)."""
    r = S.fly(os.path.join(ROOT, "tests", "vehicle", "missions", "loiter_unlim.waypoints"), "--event", "30:land")
    check(r.rc == 1, "exit status %d (expected 1)" % r.rc)
    check(started(r) == [("1", "TAKEOFF"), ("2", "LOITER_UNLIM")], "sequence %s" % started(r))
    check(r.events("mission: #2 LOITER_UNLIM complete") == [], "LOITER_UNLIM completed")
    ev = [(float(m.group(1)), m.group(2)) for m in re.finditer(r"\[\s*([0-9.]+)\] ([^\n]*)", r.out)]
    check([t for t, e in ev if e == "gcs: land"] == [30.0], "land at 30 s")
    check(r.line("run ended: vehicle landed and disarmed, mission not complete") is not None, "run end")
    check(r.line("mission: NOT COMPLETE: mission stopped at #2") is not None, "summary")
    m = re.search(r"vehicle: landed at ([0-9.]+) m from home", r.out)
    check(m is not None and 18.0 < float(m.group(1)) < 22.0, "landed at the loiter point")
    for name, t in r.tasks.items():
        check(t["slips"] == 0 and t["overrun"] == 0, "%s slipped" % name)


def t_builtin_matches_file(S):
    a = S.fly(None, "--builtin")
    b = S.fly(os.path.join(MISSIONS, "builtin.waypoints"))
    flight_ok(a)
    strip = lambda run: [l for l in run.lines if not l.startswith("mission: 8 items")]
    check(strip(a) == strip(b), "the built-in table and builtin.waypoints fly differently")


def t_deterministic(S):
    r1 = Run(S.sitl, ["--quiet", os.path.join(MISSIONS, "plain.waypoints")])
    r2 = S.fly(os.path.join(MISSIONS, "plain.waypoints"))
    check(r1.out == r2.out, "two runs differ")
    r3 = Run(S.sitl, ["--quiet", "--seed", "7", os.path.join(MISSIONS, "plain.waypoints")])
    flight_ok(r3)
    check(r3.out != r1.out, "another seed gives the same run")


def t_fault_injection(S):
    r = S.fly(os.path.join(MISSIONS, "plain.waypoints"), "--overrun", "gcs_update:2200:20:0.5")
    check(r.rc == 0 and r.line("mission: COMPLETE") is not None, "mission not complete under the fault")
    g = r.tasks["gcs_update"]
    runs = r.value(r"fault injection: (\d+) runs of gcs_update overran")
    check(runs > 50 and g["overrun"] == runs, "gcs_update overruns %d, injected %d" % (g["overrun"], runs))
    slipped = [n for n, t in r.tasks.items() if t["slips"] > 0]
    check(r.value(r"overruns: \d+, slips: (\d+)") > 0 and "nav_update" in slipped,
          "slips counted (tasks with slips: %s)" % slipped)
    check(sum(t["slips"] for t in r.tasks.values()) == r.value(r"overruns: \d+, slips: (\d+)"), "slip total")
    check(r.value(r"long loops (\d+)") > 0, "long loops counted")
    lost = r.value(r"(\d+) dropped, \d+ queued")
    check(lost > 0 and r.value(r"barometer: (\d+) samples published") ==
          r.value(r"(\d+) taken") + lost + r.value(r"(\d+) queued"),
          "barometer: every sample taken, queued or counted as dropped")
    for name in ("imu_read", "attitude_run", "motors_output"):
        check(r.tasks[name]["runs"] == r.tasks[name]["expect"], "fast task %s missed a tick" % name)


def timeline_slices(ev, tid):
    """The X events of one track as a forest: each slice with its parent's name (None at the top).
    Fails on a partial overlap, which Perfetto's thread tracks cannot show (slices nest or are
    disjoint)."""
    xs = sorted((e for e in ev if e["ph"] == "X" and e["tid"] == tid), key=lambda e: (e["ts"], -e["dur"]))
    stack, out = [], []
    for e in xs:
        end = e["ts"] + e["dur"]
        # a zero-length slice contains nothing; one that ends at e's start contains e only
        # when e has no length either
        while stack and (stack[-1]["dur"] == 0 or stack[-1]["ts"] + stack[-1]["dur"] < e["ts"] or
                         (stack[-1]["ts"] + stack[-1]["dur"] == e["ts"] and e["dur"] > 0)):
            stack.pop()
        if stack:
            top_end = stack[-1]["ts"] + stack[-1]["dur"]
            check(end <= top_end, "track %d: %s [%d, %d] overlaps %s [%d, %d] partly" % (
                tid, e["name"], e["ts"], end, stack[-1]["name"], stack[-1]["ts"], top_end))
        out.append((e, stack[-1]["name"] if stack else None))
        stack.append(e)
    return out


def t_timeline(S):
    """--timeline: a Chrome trace-event file whose events agree with the flight summary, event by
    event where the summary allows (each task's runs, min/max/mean run time, overruns, slips, budget
    skips; the proc sets' dispatches; the work queue's runs)."""
    path = os.path.join(S.tmp, "timeline.json")
    args = ["--quiet", "--timeline", path, "--overrun", "gcs_update:2200:20:0.5",
            os.path.join(MISSIONS, "plain.waypoints")]
    r = Run(S.sitl, args)
    check(r.rc == 0 and r.line("mission: COMPLETE") is not None, "flight not complete")
    plain = S.fly(os.path.join(MISSIONS, "plain.waypoints"), "--overrun", "gcs_update:2200:20:0.5")
    strip = lambda out: [l for l in out.splitlines() if not l.startswith(("timeline file:", "sitl: "))]
    check(strip(r.out) == strip(plain.out), "the timeline changed the run")
    with open(path) as f:
        doc = json.load(f)
    ev = doc["traceEvents"]
    threads = {e["tid"]: e["args"]["name"] for e in ev if e["ph"] == "M" and e["name"] == "thread_name"}
    check(sorted(threads) == [1, 2, 3, 4] and threads[4] == "work queue veh_lp", "tracks: %s" % threads)
    for e in ev:
        check(e["ph"] in ("M", "X", "i") and e["pid"] == 1 and e["tid"] in threads and
              isinstance(e["ts"], int) and e["ts"] >= 0 and isinstance(e["name"], str), "event %r" % e)
        check(e["ph"] != "X" or (isinstance(e["dur"], int) and e["dur"] >= 0), "slice %r" % e)
        check(e["ph"] != "i" or (e["s"] == "t" and e["args"]["task"] in r.tasks), "instant %r" % e)
    main = timeline_slices(ev, 1)
    ticks = [e for e, parent in main if e["name"].startswith("tick ")]
    check(len(ticks) == r.value(r"scheduler: loop \d+ Hz, \d+ tasks, (\d+) ticks") and
          all(parent is None for e, parent in main if e["name"].startswith("tick ")), "tick slices")
    runs = {}
    for e, parent in main:
        if not e["name"].startswith("tick "):
            check(parent is not None and parent.startswith("tick "), "%s at %d outside a tick" % (e["name"], e["ts"]))
            runs.setdefault(e["name"], []).append(e)
    check(sorted(runs) == sorted(r.tasks), "tasks with slices: %s" % sorted(runs))
    inst = [e for e in ev if e["ph"] == "i"]
    ends = {(e["name"], e["ts"] + e["dur"]) for es in runs.values() for e in es if e["dur"] > e["args"]["allowed_us"]}
    starts = {(e["name"], e["ts"]) for es in runs.values() for e in es}
    for name, t in r.tasks.items():
        d = [e["dur"] for e in runs[name]]
        check(len(d) == t["runs"] and min(d) == t["min"] and max(d) == t["max"] and sum(d) // len(d) == t["mean"],
              "%s: %d slices (min %d max %d mean %d) against runs %d (min %d max %d mean %d)" % (
                  name, len(d), min(d), max(d), sum(d) // len(d), t["runs"], t["min"], t["max"], t["mean"]))
        over = [e for e in inst if e["name"] == "overrun" and e["args"]["task"] == name]
        at_end = sum((name, e["ts"]) in ends for e in over)
        check(len(over) == t["overrun"] and at_end == len(over),
              "%s: %d overrun events (%d at the end of a run longer than its allowance) against %d" % (
                  name, len(over), at_end, t["overrun"]))
        slip = [e for e in inst if e["name"] == "slip" and e["args"]["task"] == name]
        check(sum(e["args"]["missed"] for e in slip) == t["slips"] and all((name, e["ts"]) in starts for e in slip),
              "%s: slip events missing %d against %d" % (name, sum(e["args"]["missed"] for e in slip), t["slips"]))
        skip = [e for e in inst if e["name"] == "budget skip" and e["args"]["task"] == name]
        check(len(skip) == t["skips"], "%s: %d budget skip events against %d" % (name, len(skip), t["skips"]))
    check(r.value(r"overruns: (\d+),") > 0 and r.value(r"slips: (\d+),") > 0 and
          r.value(r"budget skips: (\d+),") > 0, "the run has overruns, slips and budget skips to show")
    timer, io, work = (timeline_slices(ev, t) for t in (2, 3, 4))
    check(len(timer) == r.value(r"timer procs: (\d+) dispatches") and all(p is None for _, p in timer),
          "timer dispatch slices %d" % len(timer))
    check(len(io) == r.value(r"io procs: (\d+) dispatches"), "io dispatch slices %d" % len(io))
    check(len(work) == r.value(r"work queue veh_lp: (\d+) runs") and
          sum(e["name"] == "battery" for e, _ in work) == r.value(r"battery item: (\d+) runs"),
          "work item slices %d" % len(work))


def t_bad_mission(S):
    for f, line, what in (("tests/missions/bad/missing_field.waypoints", None, "field"),
                          ("tests/missions/bad/jump_target.waypoints", None, "MT_E_MISSION_JUMP")):
        r = Run(S.sitl, ["--quiet", os.path.join(ROOT, f)])
        check(r.rc == 1, "%s: exit status %d (expected 1)" % (f, r.rc))
        check(r.line("mission file rejected: " + os.path.join(ROOT, f)) is not None, "%s: no rejection" % f)
        errs = [l for l in r.lines if l.startswith("  " + os.path.join(ROOT, f) + ":")]
        check(errs and what in errs[0], "%s: error line %s" % (f, errs))
        check(r.events("vehicle: arming refused: no valid mission loaded") != [], "%s: arming not refused" % f)
        check(r.events("vehicle: armed") == [] and r.events("mission: #") == [], "%s: the vehicle armed" % f)
        check(r.line("flight time: 0.0 s (never armed)") is not None, "%s: flight time" % f)
        check(r.line("mission: NOT COMPLETE: no mission") is not None, "%s: summary" % f)


def t_unreadable_mission(S):
    r = Run(S.sitl, ["--quiet", os.path.join(S.tmp, "does-not-exist.waypoints")])
    check(r.rc == 2 and "cannot read mission file" in r.err, "missing file: rc %d %s" % (r.rc, r.err))


def t_realtime(S):
    """The hop mission on real threads (timer, IO, main loop) against the wall clock, in the
    ThreadSanitizer build: the vehicle's cross-thread data (barometer link, log ring, bus,
    device registers, the battery topic written by the work-queue thread) must be race-free."""
    env = dict(os.environ, TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1")
    r = Run(S.sitl_tsan, ["--quiet", "--realtime", os.path.join(MISSIONS, "hop.waypoints")], timeout=120,
            env=env)
    check("ThreadSanitizer" not in r.err, "TSan: %s" % r.err[-3000:])
    check(r.rc == 0 and r.line("mission: COMPLETE") is not None, "real-time hop: rc %d\n%s" % (r.rc, r.out[-1500:]))
    check(r.line("metronome SITL: real time") is not None, "not real time")
    check(started(r) == [("1", "TAKEOFF"), ("2", "LAND")], "sequence")
    m = re.search(r"sitl: ([0-9.]+) s flown in ([0-9.]+) s of wall time", r.err)
    check(m and float(m.group(2)) > 0.8 * float(m.group(1)), "real time means wall time: %s" % r.err)
    check(r.value(r"bus collisions (\d+)") == 0, "bus collisions with real threads")
    check(r.value(r"log: \d+ records, \d+ bytes to the sink, (\d+) dropped") == 0, "log dropped")
    check(r.value(r"timer procs: (\d+) dispatches") > 5000, "the timer thread ran")
    check(r.value(r"battery item: (\d+) runs") >= 3 * int(float(m.group(1))) - 2,
          "the work-queue thread served the battery item")
    check(r.value(r"housekeeping: (\d+) received") >= r.value(r"battery item: (\d+) runs") - 2,
          "battery readings crossed from the work-queue thread to the main loop")


def t_sanitizers(S):
    for args in (["--quiet", os.path.join(MISSIONS, "loiter.waypoints")],
                 ["--quiet", "--event", "20:stop", "--event", "22:resume", os.path.join(MISSIONS, "jumps.waypoints")],
                 ["--quiet", os.path.join(ROOT, "tests/missions/bad/values.waypoints")]):
        r = Run(S.sitl_asan, args, timeout=300)
        check(r.rc in (0, 1) and "runtime error" not in r.err and "AddressSanitizer" not in r.err,
              "sanitizers: rc %d %s" % (r.rc, r.err[-1500:]))
        ref = Run(S.sitl, args)
        check(r.out == ref.out, "ASan/UBSan build flies differently from the gcc build")


# ---- schedulability -----------------------------------------------------------------------------

def t_sched_nominal(S):
    rc, out, res, secs = S.sched(os.path.join(ROOT, "vehicle", "tasks.def"))
    check(rc == 0 and "verdict: SCHEDULABLE" in out, "nominal table: rc %d\n%s" % (rc, out))
    check(all(t["miss"] == "never" for t in res["tasks"]), "verdicts")
    late = {t["name"]: t["lateness_ticks"] for t in res["tasks"] if t["lateness_ticks"]}
    # with the costs measured on the firmware (wall times, MAVLink link included): the tasks
    # after the two event spikes (gcs_update arming, mission_update starting a command) can be
    # left for the next tick when the spikes coincide, the status line (last, 1 Hz) for two;
    # the tasks before them are never late
    check(late == {"mission_update": 1, "telemetry_send": 1, "log_write": 1, "housekeeping": 1,
                   "status_line": 2} and res["aligned_skip_possible"] is True, "lateness %s" % late)
    check(res["fast_end_max_us"] <= res["period_us"], "fast loop")
    S.nominal = res


def t_sched_overloaded(S):
    rc, out, res, secs = S.sched(os.path.join(ROOT, "tests", "vehicle", "overloaded.def"))
    check(rc == 1 and "verdict: NOT SCHEDULABLE" in out, "overloaded table: rc %d\n%s" % (rc, out))
    v = {t["name"]: t for t in res["tasks"]}
    # hand analysis (overloaded.def): one heavy task per tick; nav_update at 2, 4, 6...,
    # mission_update at 5, 9, 13..., telemetry_send at 3, 7, 11... (4 ticks apart, interval 2)
    check(v["telemetry_send"]["miss"] == "must" and v["telemetry_send"]["must_by_tick"] == 7 and
          v["telemetry_send"]["lateness_ticks"] == 2, "telemetry_send: %s" % v["telemetry_send"])
    check(all(t["miss"] == "never" for n, t in v.items() if n != "telemetry_send"), "others never miss")
    check(v["mission_update"]["lateness_ticks"] == 1, "mission_update is one tick late at worst")
    check(all(t["lateness_ticks"] == 0 for n, t in v.items() if n not in ("telemetry_send", "mission_update")),
          "the others are never late")
    check(res["counterexample"]["task"] == "telemetry_send" and res["counterexample"]["tick"] == 7,
          "counterexample")
    check("counterexample: an execution in which telemetry_send falls two releases behind" in out, "printed")
    S.overloaded = res


def t_sched_rejects(S):
    base = open(os.path.join(ROOT, "vehicle", "tasks.def")).read()

    def edit(name, field, value):
        """The table with one field (0-based, after the name) of task `name` replaced."""
        m = re.search(r"SCHED_TASK\(%s,([^)]*)\)" % name, base)
        check(m is not None, "no task %s in vehicle/tasks.def" % name)
        f = [x.strip() for x in m.group(1).split(",")]
        f[field] = str(value(f))
        return base.replace(m.group(0), "SCHED_TASK(%s, %s)" % (name, ", ".join(f)))

    cases = [(edit("gps_update", 4, lambda f: int(f[1])), "dishonest budget"),  # cost_max = budget
             (edit("status_line", 1, lambda f: 2600), "MT_E_TASK_BUDGET"),    # budget > period
             (edit("housekeeping", 2, lambda f: 2), "MT_E_TASK_RATE"),        # a fast priority
             (edit("log_write", 2, lambda f: 1 + int(
                 re.search(r"SCHED_TASK\(housekeeping,[^,]*,[^,]*,\s*(\d+)", base).group(1))),
              "MT_E_TASK_ORDER"),                                              # priorities out of order
             (base.replace("SCHED_LOOP(400)", "SCHED_LOOP(400)\nint x;"), "not a table entry"),
             (base.replace("SCHED_LOOP(400)", "SCHED_LOOP(40)"), "MT_E_LOOP_RATE")]
    for text, what in cases:
        check(text != base, "test case did not change the table: %s" % what)
        p = os.path.join(S.tmp, "bad.def")
        open(p, "w").write(text)
        rc, out, res, secs = S.sched(p)
        check(rc == 2 and what in out, "%s: rc %d %s" % (what, rc, out))


def missed(t):
    """SITL: a release was missed (a slip counted, or two releases pending)."""
    return t["slips"] > 0 or t["pending"] >= 2


def t_agreement(S):
    """Slips appear in SITL exactly where Z3 says they must, and nowhere it says never."""
    nominal = S.nominal if hasattr(S, "nominal") else None
    over = S.overloaded if hasattr(S, "overloaded") else None
    check(nominal is not None and over is not None, "the sched-check tests must run first")
    for m in ("plain", "jumps", "land", "rtl", "loiter", "builtin"):
        S.fly(os.path.join(MISSIONS, m + ".waypoints"))
    # nominal: every flight of this suite (Z3: never skipped) shows no skip and no slip
    flights = [run for (b, _), run in S.cache.items() if b == S.sitl and run.line("mission: COMPLETE") and
               "--overrun" not in run.out and "fault injection" not in run.out]
    check(len(flights) >= 6, "too few nominal flights to compare (%d)" % len(flights))
    for run in flights:
        for t in nominal["tasks"]:
            r = run.tasks[t["name"]]
            check(t["miss"] == "never" and not missed(r), "nominal: %s missed in SITL" % t["name"])
            if t["lateness_ticks"] == 0:
                check(r["skips"] == 0, "nominal: Z3 says %s is never skipped, SITL skipped it" % t["name"])
    # overloaded: a whole flight with the overloaded table, and the first ticks
    run = S.fly(os.path.join(MISSIONS, "plain.waypoints"), binary=S.sitl_over)
    check(run.line("mission: COMPLETE") is not None, "the overloaded vehicle still completes its mission")
    for t in over["tasks"]:
        r = run.tasks[t["name"]]
        if t["miss"] == "must":
            check(missed(r) and r["slips"] > 0, "%s: Z3 says it must miss, SITL: slips %d pending %d"
                  % (t["name"], r["slips"], r["pending"]))
        else:
            check(t["miss"] == "never" and not missed(r), "%s: Z3 %s, SITL slips %d pending %d"
                  % (t["name"], t["miss"], r["slips"], r["pending"]))
            if t["lateness_ticks"] == 0:
                check(r["skips"] == 0, "%s: Z3 says never skipped, SITL skipped it %d times" % (t["name"],
                                                                                           r["skips"]))
    # hand analysis: mission_update and nav_update are both due at tick 4 (nav_update runs),
    # then mission_update runs at ticks 5, 9, 13..., where nav_update is never due: exactly
    # one skip in SITL
    check(run.tasks["mission_update"]["skips"] == 1, "mission_update skips %d" % run.tasks["mission_update"]["skips"])
    by = next(t["must_by_tick"] for t in over["tasks"] if t["miss"] == "must")
    early = Run(S.sitl_over, ["--quiet", "--ticks", str(by - 1), os.path.join(MISSIONS, "plain.waypoints")])
    late = Run(S.sitl_over, ["--quiet", "--ticks", str(by), os.path.join(MISSIONS, "plain.waypoints")])
    check(early.rc == 0 and late.rc == 0, "tick-limited runs")
    check(not missed(early.tasks["telemetry_send"]) and missed(late.tasks["telemetry_send"]),
          "the miss appears exactly at tick %d: %s / %s" % (by, early.tasks["telemetry_send"],
                                                           late.tasks["telemetry_send"]))


def t_vprint(S):
    p = subprocess.run([os.path.join(os.path.dirname(S.sitl), "test_vprint")], capture_output=True, text=True,
                       timeout=60)
    check(p.returncode == 0 and "0 failures" in p.stdout, p.stdout + p.stderr)


def t_encoding(S):
    """The Z3 encoding of a tick against the kernel itself: SITL runs kernel/src/sched.c and
    traces every input of each tick (sample time, timer rounds with their due times and costs,
    each task's simulated cost) and the kernel's decisions (tasks run, tasks skipped, end of
    the scan). Given the same inputs, the model must decide the same, tick by tick."""
    sys.path.insert(0, os.path.join(ROOT, "tools"))
    import sched_check as sc
    import z3
    for binary, table, ticks in ((S.sitl_over, os.path.join(ROOT, "tests", "vehicle", "overloaded.def"), 600),
                                 (S.sitl, os.path.join(ROOT, "vehicle", "tasks.def"), 200)):
        tr = os.path.join(S.tmp, "trace-%s.txt" % os.path.basename(table))
        run = Run(binary, ["--quiet", "--ticks", str(ticks), "--trace", tr, os.path.join(MISSIONS, "plain.waypoints")])
        check(run.rc == 0, "traced run: %s" % run.err)
        t = sc.parse(table)
        sc.validate(t)
        tp = t.timer[0]
        rounds = {}            # due time -> cost
        ticks_in = []          # (sample, {task: cost}, tick, end, run, skip)
        cur = None
        for line in open(tr):
            f = line.split()
            if f[0] == "R":
                rounds[int(f[1])] = int(f[2])
            elif f[0] == "S":
                cur = [int(f[1]), {}]
            elif f[0] == "E":
                cur[1][int(f[1])] = int(f[2])
            elif f[0] == "K":
                ticks_in.append((cur[0], cur[1], int(f[1]), int(f[2]), int(f[3], 16), int(f[4], 16)))
        check(len(ticks_in) == ticks, "%d ticks traced" % len(ticks_in))
        grid0 = min(rounds)    # the timer grid: grid0 + m * tp
        s = z3.Solver()
        due = [None if k.fast else z3.Bool("due%d" % i) for i, k in enumerate(t.tasks)]
        model = sc.TickModel(t, "x", 0)
        terms = model.build(s, "a", lambda i: due[i], z3.IntVal(0))
        n = len(t.tasks)
        last_run = [0] * n
        decided = skips = 0
        for sample, costs, tick, end, run_mask, skip_mask in ticks_in:
            d0 = grid0 + -(-(sample - grid0) // tp) * tp   # first round due at or after the sample
            s.push()
            s.add(z3.Int("lat_x_a") == 0, z3.Int("phase_x_a") == d0 - sample)
            if d0 - tp in rounds:
                s.add(z3.Int("carry_x_a") == rounds[d0 - tp])
            for m in range(model.rounds):
                if d0 + m * tp in rounds:
                    s.add(z3.Int("round%d_x_a" % m) == rounds[d0 + m * tp])
            for i, k in enumerate(t.tasks):
                if not k.fast:
                    s.add(due[i] == (tick - last_run[i] >= k.interval))
                if i in costs:
                    s.add(z3.Int("e%d_x_a" % i) == costs[i])
            check(s.check() == z3.sat, "tick %d: the traced inputs are outside the model" % tick)
            m = s.model()
            got_run = sum(1 << i for i in range(n) if not t.tasks[i].fast and z3.is_true(m.eval(terms["run"][i])))
            got_skip = sum(1 << i for i in range(n) if z3.is_true(m.eval(terms["skip"][i])))
            want_run = run_mask & ~sum(1 << i for i in range(n) if t.tasks[i].fast)
            check(got_run == want_run and got_skip == skip_mask,
                  "tick %d: model runs %x skips %x, kernel runs %x skips %x" % (tick, got_run, got_skip, want_run,
                                                                               skip_mask))
            check(m.eval(terms["wend"]).as_long() == end - sample,
                  "tick %d: model ends at %d us, SITL at %d us" % (tick, m.eval(terms["wend"]).as_long(),
                                                                   end - sample))
            s.pop()
            for i in range(n):
                if run_mask >> i & 1:
                    last_run[i] = tick
            decided += 1
            skips += bin(skip_mask).count("1")
        check(decided == ticks, "ticks compared")
        if "overloaded" in table:
            check(skips > 200, "the overloaded trace has skips to compare (%d)" % skips)


# ---- the MAVLink link (pymavlink's mavutil as the ground station) ----------------------------

def mavlink_session(S, args, timeout=90, binary=None):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import mavgcs
    if S.firmware:
        if binary is not None:
            raise Skip("a SITL build of its own (%s); the firmware is one build" % os.path.basename(binary))
        try:
            return mavgcs, mavgcs.FirmwareSession(S.firmware, ["--quiet"] + args, timeout=timeout)
        except mavgcs.Unsupported as e:
            raise Skip(str(e))
    return mavgcs, mavgcs.Session(binary or S.sitl, ["--quiet"] + args, timeout=timeout)


def t_mavlink_flight(S):
    """A ground station on UDP watches a whole flight at 20x: identity and modes, the streams at
    their rates, the parameter protocol (list, read, set, an out-of-range set refused), the
    console lines as STATUSTEXT, MISSION_CURRENT and MISSION_ITEM_REACHED for every nav
    command, and the SITL's summary counts what crossed the link."""
    g, sess = mavlink_session(S, ["--speedup", "20", os.path.join(MISSIONS, "plain.waypoints")])
    mav = g.mav
    with sess as s:
        hb = s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(hb.type == mav.MAV_TYPE_QUADROTOR and hb.autopilot == mav.MAV_AUTOPILOT_ARDUPILOTMEGA,
              "identity: %s" % hb)
        check(hb.get_srcComponent() == mav.MAV_COMP_ID_AUTOPILOT1, "component id %d" % hb.get_srcComponent())
        s.conn.mav.param_request_list_send(1, 1)
        plist = [s.wait("PARAM_VALUE") for _ in range(5)]
        check([(p.param_id, p.param_index, p.param_count, p.param_value) for p in plist] ==
              [("SYSID_THISMAV", 0, 5, 1.0), ("WPNAV_SPEED", 1, 5, 500.0), ("FS_GCS_ENABLE", 2, 5, 1.0),
               ("FS_GCS_TIMEOUT", 3, 5, 5.0), ("PILOT_TKOFF_ALT", 4, 5, 0.0)],
              "parameter list %s" % [str(p) for p in plist])
        check([p.param_type for p in plist] == [mav.MAV_PARAM_TYPE_INT16, mav.MAV_PARAM_TYPE_REAL32,
                                                mav.MAV_PARAM_TYPE_INT8, mav.MAV_PARAM_TYPE_REAL32,
                                                mav.MAV_PARAM_TYPE_REAL32],
              "parameter types")
        s.conn.mav.param_set_send(1, 1, b"WPNAV_SPEED", 900.0, mav.MAV_PARAM_TYPE_REAL32)
        check(s.wait("PARAM_VALUE").param_value == 900.0, "WPNAV_SPEED set")
        s.conn.mav.param_set_send(1, 1, b"WPNAV_SPEED", 5000.0, mav.MAV_PARAM_TYPE_REAL32)
        check(s.wait("PARAM_VALUE").param_value == 900.0, "out-of-range set answered with the value in force")
        s.conn.mav.param_request_read_send(1, 1, b"SYSID_THISMAV", -1)
        check(s.wait("PARAM_VALUE").param_id == "SYSID_THISMAV", "read by name")
        a, b = s.arm_and_auto()
        check(a.result == mav.MAV_RESULT_ACCEPTED and b.result == mav.MAV_RESULT_ACCEPTED, "arm, AUTO: %s %s" % (a, b))
        s.wait("STATUSTEXT", lambda m: m.text == "mission: complete", seconds=80)
        s.wait("HEARTBEAT", lambda m: not (m.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED))
        s.stop()
    out = s.out
    modes = [(m.custom_mode, bool(m.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED), m.system_status)
             for m in s.of("HEARTBEAT")]
    check((mav.COPTER_MODE_STABILIZE, False, mav.MAV_STATE_STANDBY) in modes and
          (mav.COPTER_MODE_AUTO, True, mav.MAV_STATE_ACTIVE) in modes, "modes seen: %s" % sorted(set(modes)))
    check(modes[-1][1] is False, "disarmed at the end")
    # one frame sequence for the whole link (the files that pack messages share it): on the
    # loss-free local link, every frame is the previous one's number + 1
    seqs = [m.get_seq() for _, m in s.msgs if m.get_srcSystem() == 1]
    gaps = [(a, b) for a, b in zip(seqs, seqs[1:]) if (b - a) % 256 != 1]
    check(len(seqs) > 1000 and not gaps, "frame numbers: %d gaps, first %s" % (len(gaps), gaps[:5]))
    # rates, in the vehicle's time: ATTITUDE 10 Hz, positions 5 Hz each, HEARTBEAT 1 Hz
    att = [m.time_boot_ms for m in s.of("ATTITUDE")]
    secs = (att[-1] - att[0]) / 1000.0
    gaps = [b - a for a, b in zip(att, att[1:])]
    check(secs > 40 and 95 <= min(gaps) and max(gaps) <= 105, "ATTITUDE every 100 ms over %.0f s: gaps %d..%d ms"
          % (secs, min(gaps), max(gaps)))
    pos = s.of("GLOBAL_POSITION_INT")
    check(abs(len(pos) - 5 * secs) <= 2 and abs(len(s.of("GPS_RAW_INT")) - 5 * secs) <= 2, "5 Hz positions")
    check(abs(len(s.of("HEARTBEAT")) - secs) <= 2 and abs(len(s.of("SYS_STATUS")) - secs) <= 2, "1 Hz heartbeat")
    check(max(p.relative_alt for p in pos) > 14000 and abs(pos[0].lat - 465197000) < 200, "position: %s" % pos[0])
    gps = s.of("GPS_RAW_INT")[-1]
    check(gps.fix_type == 3 and gps.satellites_visible > 5, "GPS: %s" % gps)
    st = s.of("SYS_STATUS")
    check(all(0 < x.load <= 1000 for x in st[5:]) and 14000 < st[-1].voltage_battery < 17500, "SYS_STATUS %s" % st[-1])
    check(st[-1].onboard_control_sensors_health & st[-1].onboard_control_sensors_present ==
          st[-1].onboard_control_sensors_present, "sensors healthy")
    check(st[-1].onboard_control_sensors_health & mav.MAV_SYS_STATUS_GEOFENCE and
          not st[-1].onboard_control_sensors_present & mav.MAV_SYS_STATUS_GEOFENCE, "no fence, not breached")
    check([m.seq for m in s.of("MISSION_ITEM_REACHED")] == [1, 2, 3, 4, 5, 6], "items reached")
    cur = [m for _, m in s.msgs[s.uploaded_at:] if m.get_type() == "MISSION_CURRENT"]
    check(all(c.total == 6 for c in cur) and {2, 3, 4, 5} <= {c.seq for c in cur} and
          mav.MISSION_STATE_ACTIVE in {c.mission_state for c in cur}, "MISSION_CURRENT")
    texts = s.lines(complete=True)
    said = [e[:95] for e in S_events(out)]
    check(texts == said[:len(texts)] and len(texts) >= len(said) - 2, "every console line as STATUSTEXT:\n%s\n%s"
          % (texts, said))
    check(any(m.severity == mav.MAV_SEVERITY_WARNING and "refused" in m.text for m in s.of("STATUSTEXT")),
          "warnings as such")
    # the cruise speed set from the ground (9 m/s) is flown: 5 m/s before
    check(float(re.search(r"max ground speed ([0-9.]+)", out).group(1)) > 8.0, "WPNAV_SPEED flown")
    sent, nbytes, full, lost, recvd, ignored, dropped, unsigned, noise, unknown, refused, unsup = link_counts(out)
    check(full == 0 and lost == 0 and dropped == 0 and noise == 0 and unknown == 0 and refused == 1,
          "link counts %s" % (link_counts(out),))
    check(sent >= len(s.msgs) and recvd >= 5, "messages: %d sent, %d seen by the GCS" % (sent, len(s.msgs)))
    # the SITL ends on SIGINT, the firmware on 'q' from its console
    end = "run ended: interrupted (console)" if S.firmware else "run ended: interrupted (signal)"
    check(s.out.count(end) == 1, "the session ends as asked: %s" % end)


def link_counts(out):
    """The summary's link line: sent, bytes, not sent, lines lost, received, ignored, frames
    dropped (CRC), frames dropped (signing), noise bytes, unknown parameters, refused sets,
    unsupported commands."""
    m = re.search(r"link \(MAVLink 2\): (\d+) messages, (\d+) bytes sent, (\d+) not sent \(ring full\), (\d+) "
                  r"console lines lost; (\d+) messages received, (\d+) ignored, (\d+) frames dropped, (\d+) "
                  r"unsigned, (\d+) bytes not in a valid frame, (\d+) parameter requests unknown, (\d+) "
                  r"sets refused, (\d+) commands unsupported", out)
    check(m is not None, "link summary line:\n" + out[-2000:])
    return tuple(map(int, m.groups()))


def S_events(out):
    return [m.group(1) for m in re.finditer(r"^\[\s*[0-9.]+\] (.*)$", out, re.M)]


def t_mavlink_no_mission(S, binary=None):
    """Without a mission the vehicle waits for the ground station (no 'never armed' end), tells
    it there is no mission, survives garbage on the link (counted), answers an unknown parameter
    by counting it, and streams to whoever talked to it last."""
    g, sess = mavlink_session(S, ["--speedup", "50"], binary=binary)
    mav = g.mav
    with sess as s:
        hb = s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(hb.system_status == mav.MAV_STATE_STANDBY and not hb.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED,
              "standby")
        cur = s.wait("MISSION_CURRENT")
        check(cur.mission_state == mav.MISSION_STATE_NO_MISSION and cur.total == 0, "no mission: %s" % cur)
        # past the 15 s a run without a ground station waits for arming
        s.wait("ATTITUDE", lambda m: m.time_boot_ms > 20000, seconds=40)
        # a corrupted frame (CRC) and noise: dropped and counted, the link goes on
        good = s.conn.mav.param_request_read_encode(1, 1, b"SYSID_THISMAV", -1).pack(s.conn.mav)
        bad = bytearray(good)
        bad[-1] ^= 0xFF
        s.conn.write(b"\xfd" * 3000)  # a datagram over the SITL's 2 KB: dropped whole, counted
        s.conn.write(bytes(bad) + b"\x00\x01garbage")
        s.conn.mav.param_request_read_send(1, 1, b"NO_SUCH_PARAM", -1)
        s.conn.mav.param_request_read_send(1, 1, b"WPNAV_SPEED", -1)
        check(s.wait("PARAM_VALUE").param_id == "WPNAV_SPEED", "answered after the garbage")
        # a float no integer holds (found by fuzz_link: the refusal's text converted it; UBSan)
        s.conn.mav.param_set_send(1, 1, b"WPNAV_SPEED", 1e30, mav.MAV_PARAM_TYPE_REAL32)
        check(s.wait("PARAM_VALUE").param_value == 500.0, "1e30 refused, 500 in force")
        s.wait_text(lambda m: m.text.startswith("param: WPNAV_SPEED refused (out of range"))
        # a second ground station talks: the vehicle now answers there
        check(len(s.conn.clients) == 1, "one vehicle address: %s" % s.conn.clients)
        other = g.mavutil.mavlink_connection("udpout:%s:%d" % next(iter(s.conn.clients)), source_system=254,
                                             dialect="ardupilotmega")
        try:
            t_end = time.time() + 20
            got = None
            while got is None and time.time() < t_end:
                other.mav.heartbeat_send(mav.MAV_TYPE_GCS, mav.MAV_AUTOPILOT_INVALID, 0, 0, 0)
                got = other.recv_match(type="HEARTBEAT", blocking=True, timeout=0.5)
            check(got is not None and got.get_srcSystem() == 1, "the vehicle answers the new sender")
        finally:
            other.close()
        s.stop()
    out = s.out
    check("run ended: interrupted (signal)" in out, "session end:\n" + out[-800:])
    sent, nbytes, full, lost, recvd, ignored, dropped, unsigned, noise, unknown, refused, unsup = link_counts(out)
    check(dropped == 1, "the corrupted frame is counted (%d)" % dropped)
    check(noise == len(bad) + len(b"\x00\x01garbage"), "bytes outside valid frames counted (%d)" % noise)
    check(unknown == 1 and refused == 1, "unknown parameter and refused set counted")
    check(recvd >= 3, "received %d: the two reads and a heartbeat at least" % recvd)
    check(s.rc == 1, "exit status %s (no mission completed)" % s.rc)
    m = re.search(r"MAVLink udp: \d+ bytes received, (\d+) datagrams dropped", out)
    check(m is not None and int(m.group(1)) == 1, "the oversized datagram is counted: %s" % (m and m.group(0)))
    return s


def t_mavlink_flood(S):
    """Bad input on a byte stream, by name: truncated frames (a frame cut short, then the next
    ones) and a flood of 1000 parameter reads sent at once. The vehicle never stops answering,
    and nothing is lost silently: a cut frame is counted (frames dropped or bytes outside a
    valid frame), and every read is either answered or counted where it was lost (the SITL:
    datagrams dropped, messages not sent; the firmware: UART bytes dropped or overrun)."""
    g, sess = mavlink_session(S, ["--speedup", "10"])
    mav = g.mav
    n = 1000
    with sess as s:
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        frame = s.conn.mav.param_request_read_encode(1, 1, b"WPNAV_SPEED", -1).pack(s.conn.mav)
        for cut in (3, len(frame) // 2, len(frame) - 1):
            s.conn.write(frame[:cut])
            mark = s.mark()
            end = time.time() + 10 * s.scale
            # the cut frame swallows the start of what follows: ask until an answer comes
            while s.wait_any("PARAM_VALUE", since=mark, seconds=0.5) is None:
                check(time.time() < end, "no answer after a frame cut at %d bytes" % cut)
                s.conn.mav.param_request_read_send(1, 1, b"WPNAV_SPEED", -1)
        mark = s.mark()
        for _ in range(n):
            s.conn.mav.param_request_read_send(1, 1, b"", 1)  # by index: WPNAV_SPEED
        # the answers, until all came or none for 2 s (1 s of vehicle time answers 400)
        answers, quiet = 0, time.time() + 2 * s.scale
        while answers < n and time.time() < quiet:
            s.poll()
            got = len([m for _, m in s.msgs[mark:] if m.get_type() == "PARAM_VALUE"])
            if got > answers:
                answers, quiet = got, time.time() + 2 * s.scale
        check(s.command(31000).result == mav.MAV_RESULT_UNSUPPORTED, "a command answered after the flood")
        # the vehicle answers in order: answers that came after a pause of 2 s (a loaded machine)
        # came before the command's; and those this side's socket dropped (read too late)
        answers = len([m for _, m in s.msgs[mark:] if m.get_type() == "PARAM_VALUE"])
        gcs_drops = 0 if S.firmware else s.rx_drops()
        s.stop()
    out = s.out
    sent, nbytes, full, lost, recvd, ignored, dropped, unsigned, noise, unknown, refused, unsup = link_counts(out)
    check(dropped + noise > 0, "the cut frames are counted: %d frames dropped, %d bytes outside" % (dropped, noise))
    if S.firmware:
        m = re.search(r"link UART: \d+ bytes received, (\d+) dropped \(receive ring full\), (\d+) overruns", out)
        check(m is not None, "link UART line:\n" + out[-1500:])
        lost_in = int(m.group(1)) + int(m.group(2))
        check(answers == n or lost_in > 0 or full > 0 or dropped > 3,
              "%d of %d reads answered, no loss counted (%s)" % (answers, n, m.group(0)))
    else:
        m = re.search(r"MAVLink udp: \d+ bytes received, (\d+) datagrams dropped", out)
        check(m is not None, "udp line:\n" + out[-1500:])
        # every read reached the parser or was counted as a dropped datagram; every one that
        # reached it was answered (received here or dropped at this side's socket) or counted as
        # not sent
        check(answers + gcs_drops + full + int(m.group(1)) >= n,
              "%d of %d reads answered (%d more dropped at the ground station's socket), %d not sent, "
              "%d datagrams dropped" % (answers, n, gcs_drops, full, int(m.group(1))))
    print("     flood: %d of %d reads answered, %d dropped at the ground station's socket; link: %d not sent, "
          "%d frames dropped, %d bytes outside frames; %s"
          % (answers, n, gcs_drops, full, dropped, noise, m.group(0)))


def close_or_nan(a, b):
    return (math.isnan(a) and math.isnan(b)) or abs(a - b) < 1e-3


def same_items(got, want, legacy=False):
    """Downloaded MISSION_ITEM_INTs against uploaded items (legacy MISSION_ITEM carries x and y
    as float32 degrees: within 1e-5 degree)."""
    check(len(got) == len(want), "%d items on board, %d uploaded" % (len(got), len(want)))
    tol = 100 if legacy else 0
    for g, w in zip(got, want):
        check(g.command == w["command"] and g.frame == w["frame"] and g.autocontinue == w["autocontinue"] and
              abs(g.x - w["x"]) <= tol and abs(g.y - w["y"]) <= tol and abs(g.z - w["z"]) < 1e-3 and
              all(close_or_nan(getattr(g, "param%d" % k), w["param%d" % k]) for k in range(1, 5)),
              "item %d: on board %s, uploaded %s" % (g.seq, g, w))


def t_mavlink_mission_upload(S):
    """A mission uploaded by the ground station (MISSION_ITEM_INT, as QGroundControl) is
    downloaded back item for item and flown exactly as the same file; rejected uploads get the
    matching MAV_MISSION_RESULT and a STATUSTEXT with the item, and leave the mission on board
    as it was; messages addressed to another vehicle (mission, parameter, command) are not
    taken; MISSION_ITEM (float, older ground stations), clear and set-current."""
    g, sess = mavlink_session(S, ["--speedup", "10"])
    mav = g.mav
    plain = g.wpl_items(os.path.join(MISSIONS, "plain.waypoints"))
    with sess as s:
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        ack, asked = s.upload(plain)
        check(ack.type == mav.MAV_MISSION_ACCEPTED and asked == list(range(7)), "upload: %s %s" % (ack, asked))
        same_items(s.download(), plain)
        a, b = s.arm_and_auto()
        check(a.result == mav.MAV_RESULT_ACCEPTED and b.result == mav.MAV_RESULT_ACCEPTED, "arm, AUTO: %s %s" % (a, b))
        s.wait("STATUSTEXT", lambda m: m.text == "mission: complete", seconds=60)
        s.wait("HEARTBEAT", lambda m: not (m.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED))
        flown = [re.match(r"mission: #(\d+) (\w+) started", t).group(1, 2)
                 for t in s.lines(complete=True) if re.match(r"mission: #\d+ \w+ started", t)]
        check(flown == [("1", "TAKEOFF"), ("2", "WAYPOINT"), ("3", "WAYPOINT"), ("4", "WAYPOINT"),
                        ("5", "WAYPOINT"), ("6", "LAND")], "the uploaded mission flown as the file: %s" % flown)
        # rejected uploads, each leaving plain on board
        # the file layer rejects an item as it arrives (the NaN altitude: no more requests), the
        # kernel's check the whole mission once every item is in
        bad = [("unknown command", 3, dict(command=9999), mav.MAV_MISSION_UNSUPPORTED, list(range(7))),
               ("NaN altitude", 2, dict(z=float("nan")), mav.MAV_MISSION_INVALID_PARAM7, [0, 1, 2]),
               ("latitude 95 degrees", 2, dict(x=950000000), mav.MAV_MISSION_INVALID_PARAM5_X, list(range(7))),
               ("unsupported frame", 4, dict(frame=1), mav.MAV_MISSION_UNSUPPORTED_FRAME, list(range(7)))]
        for what, i, change, result, want_asked in bad:
            items = [dict(it) for it in plain]
            items[i].update(change)
            ack, asked = s.upload(items)
            check(ack.type == result and asked == want_asked, "%s: ack %s asked %s" % (what, ack, asked))
            s.wait("STATUSTEXT", lambda m: m.text.startswith("mission upload rejected: item %d" % i))
        # addressed to another vehicle (system 7): not taken, whatever the message
        mark = s.mark()
        s.conn.mav.mission_count_send(7, 1, 3, mav.MAV_MISSION_TYPE_MISSION)
        s.conn.mav.mission_clear_all_send(7, 1, mav.MAV_MISSION_TYPE_MISSION)
        s.conn.mav.param_set_send(7, 1, b"WPNAV_SPEED", 700.0, mav.MAV_PARAM_TYPE_REAL32)
        s.conn.mav.command_long_send(7, 1, 31000, 0, 0, 0, 0, 0, 0, 0, 0)
        check(s.wait_any("MISSION_REQUEST_INT", since=mark, seconds=2) is None and
              not [m for _, m in s.msgs[mark:] if m.get_type() in ("MISSION_ACK", "PARAM_VALUE", "COMMAND_ACK")],
              "a message for system 7 was answered")
        same_items(s.download(), plain)
        # a link that drops in the middle of an upload: cancelled at 8 s, the mission unchanged
        ack, asked = s.upload(plain, answer=lambda seq: seq if seq < 3 else None)
        check(ack.type == mav.MAV_MISSION_OPERATION_CANCELLED and asked[:4] == [0, 1, 2, 3],
              "upload cut at item 3: %s %s" % (ack, asked[:6]))
        jump = plain[:6] + [dict(plain[1], command=mav.MAV_CMD_DO_JUMP, frame=2, param1=99.0, param2=1.0,
                                 x=0, y=0, z=0.0)] + plain[6:]
        ack, asked = s.upload(jump)
        check(ack.type == mav.MAV_MISSION_INVALID, "jump to a command that does not exist: %s" % ack)
        s.wait("STATUSTEXT", lambda m: m.text.startswith("mission upload rejected: item 6: MT_E_MISSION_JUMP"))
        same_items(s.download(), plain)
        # the float form of older ground stations
        jumps = g.wpl_items(os.path.join(MISSIONS, "jumps.waypoints"))
        ack, asked = s.upload(jumps, legacy=True)
        check(ack.type == mav.MAV_MISSION_ACCEPTED, "MISSION_ITEM upload: %s" % ack)
        same_items(s.download(), jumps, legacy=True)
        s.conn.mav.mission_set_current_send(1, 1, 4)
        cur = s.wait("MISSION_CURRENT", lambda m: m.seq == 4)
        check(cur.total == len(jumps) - 1, "MISSION_CURRENT total excludes home: %s" % cur)
        s.conn.mav.mission_clear_all_send(1, 1, mav.MAV_MISSION_TYPE_MISSION)
        check(s.wait("MISSION_ACK").type == mav.MAV_MISSION_ACCEPTED, "clear")
        home = s.download()
        check(len(home) == 1 and abs(home[0].x - jumps[0]["x"]) <= 100, "home stays after a clear: %s" % home)
        s.stop()
    sent, nbytes, full, lost, recvd, ignored, dropped, unsigned, noise, unknown, refused, unsup = link_counts(s.out)
    # ignored: the four messages for system 7
    check(full == 0 and lost == 0 and dropped == 0 and ignored == 4, "link counts %s" % (link_counts(s.out),))


def t_mavlink_mission_protocol(S):
    """The vehicle drives an upload as ArduPilot does: it asks again for an item after 1 s and
    cancels after 8 s without one; an item out of sequence gets INVALID_SEQUENCE and the upload
    goes on; fences are not supported; a running mission is not cleared (ERROR). A valid upload
    in flight replaces the mission (mt_mission_replace): the vehicle starts the new mission's
    item at the same index again and flies the new mission; when that index is gone it holds
    (LOITER) and says so."""
    g, sess = mavlink_session(S, ["--speedup", "10"])
    mav = g.mav
    plain = g.wpl_items(os.path.join(MISSIONS, "plain.waypoints"))
    with sess as s:
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        ack, asked = s.upload(plain[:3], answer=lambda seq: None)
        check(ack.type == mav.MAV_MISSION_OPERATION_CANCELLED and set(asked) == {0} and 7 <= len(asked) <= 10,
              "timeout: %s after %d requests" % (ack, len(asked)))
        s.wait("STATUSTEXT", lambda m: m.text.startswith("mission upload cancelled: no item #0"))
        first = []

        def out_of_order(seq):
            if seq == 2 and not first:
                first.append(seq)
                return 3  # one item ahead
            return seq
        ack, asked = s.upload(plain, answer=out_of_order)
        check(ack.type == mav.MAV_MISSION_ACCEPTED and mav.MAV_MISSION_INVALID_SEQUENCE in s.acks and
              asked[:4] == [0, 1, 2, 2], "out of sequence: %s %s %s" % (ack, s.acks, asked))
        s.arm_and_auto()
        s.conn.mav.mission_count_send(1, 1, 2, mav.MAV_MISSION_TYPE_FENCE)
        check(s.wait("MISSION_ACK").type == mav.MAV_MISSION_UNSUPPORTED, "fence")
        s.wait("STATUSTEXT", lambda m: m.text.startswith("mission: #2 WAYPOINT started"), seconds=60)
        s.conn.mav.mission_clear_all_send(1, 1, mav.MAV_MISSION_TYPE_MISSION)
        check(s.wait("MISSION_ACK").type == mav.MAV_MISSION_ERROR, "clear during the mission")
        # in flight at #2: the same mission with #2 and #3 moved and one more waypoint
        moved = [dict(w) for w in plain]
        moved[2]["x"] += 900
        moved[3]["y"] += 900
        moved.insert(6, dict(moved[5], y=moved[5]["y"] + 900))
        for k, w in enumerate(moved):
            w["seq"] = k
        t0 = s.mark()
        ack, asked = s.upload(moved)
        check(ack.type == mav.MAV_MISSION_ACCEPTED, "upload in flight: %s" % ack)
        s.wait_text(lambda t: t.text == "mission replaced in flight (8 items): continuing at #2", since=t0)
        s.wait_text(lambda t: t.text.startswith("mission: #2 WAYPOINT started"), since=t0)
        same_items(s.download(), moved)
        # at #4, a shorter one without it: the vehicle holds in LOITER and says so
        s.wait("STATUSTEXT", lambda m: m.text.startswith("mission: #4 WAYPOINT started"), seconds=60)
        t1 = s.mark()
        ack, asked = s.upload(plain[:4])
        check(ack.type == mav.MAV_MISSION_ACCEPTED, "shorter upload in flight: %s" % ack)
        s.wait_text(lambda t: t.text == "mission replaced in flight (4 items): #4 is gone, holding", since=t1)
        heartbeat_mode(s, mav, mav.COPTER_MODE_LOITER)
        same_items(s.download(), plain[:4])
        check(s.command(mav.MAV_CMD_NAV_LAND).result == mav.MAV_RESULT_ACCEPTED, "land after the hold")
        s.wait_text(lambda t: t.text.startswith("vehicle: landed"), seconds=60, since=t1)
        s.stop()
    started = [e for e in S_events(s.out) if re.match(r"mission: #\d+ \w+ started", e)]
    check([e.split()[1] for e in started] == ["#1", "#2", "#2", "#3", "#4"], "items started: %s" % started)


def heartbeat_mode(s, mav, custom, seconds=30):
    return s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1 and m.custom_mode == custom, seconds=seconds,
                  since=s.sent_at)


def t_mavlink_commands(S):
    """COMMAND_LONG and SET_MODE as ArduPilot answers them: arming refused with the pre-arm
    reason until the checks pass, AUTO refused while disarmed, MISSION_START, a disarm in flight
    refused, DO_SET_MISSION_CURRENT, LOITER (the mission stops) and AUTO (it resumes), RTL home,
    STABILIZE on the ground, then MISSION_START again and LAND where the vehicle is; an unknown
    command UNSUPPORTED, an unknown mode FAILED."""
    g, sess = mavlink_session(S, ["--speedup", "10", os.path.join(MISSIONS, "plain.waypoints")])
    mav = g.mav
    with sess as s:
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(s.command(31000).result == mav.MAV_RESULT_UNSUPPORTED, "unknown command")
        a = s.command(mav.MAV_CMD_COMPONENT_ARM_DISARM, 1.0)
        check(a.result == mav.MAV_RESULT_FAILED, "arming before the pre-arm checks pass: %s" % a)
        s.wait_text(lambda m: m.text.startswith("vehicle: arming refused: "), since=s.sent_at)
        b = s.command(mav.MAV_CMD_DO_SET_MODE, 1.0, float(mav.COPTER_MODE_AUTO))
        check(b.result == mav.MAV_RESULT_FAILED, "AUTO while disarmed: %s" % b)
        s.wait_text(lambda m: m.text == "gcs: AUTO refused: arm first", since=s.sent_at)
        check(s.command(mav.MAV_CMD_DO_SET_MODE, 1.0, 13.0).result == mav.MAV_RESULT_FAILED, "mode 13 (SPORT)")
        a, _ = s.arm_and_auto()
        check(a.result == mav.MAV_RESULT_ACCEPTED, "arm")
        s.wait_text(lambda m: m.text.startswith("mission: #2 WAYPOINT started"), since=s.sent_at)
        d = s.command(mav.MAV_CMD_COMPONENT_ARM_DISARM, 0.0)
        check(d.result == mav.MAV_RESULT_FAILED, "disarm in flight without force: %s" % d)
        check(s.command(mav.MAV_CMD_DO_SET_MISSION_CURRENT, 4.0).result == mav.MAV_RESULT_ACCEPTED, "set current")
        s.wait_text(lambda m: m.text.startswith("mission: #4 WAYPOINT started"), since=s.sent_at)
        check(s.command(mav.MAV_CMD_DO_SET_MODE, 1.0, float(mav.COPTER_MODE_LOITER)).result ==
              mav.MAV_RESULT_ACCEPTED, "LOITER")
        heartbeat_mode(s, mav, mav.COPTER_MODE_LOITER)
        n0 = s.mark()
        check(s.command(mav.MAV_CMD_DO_SET_MODE, 1.0, float(mav.COPTER_MODE_AUTO)).result ==
              mav.MAV_RESULT_ACCEPTED, "AUTO again")
        resumed = s.sent_at
        s.wait_text(lambda m: m.text == "gcs: mission resumed", since=resumed)
        s.wait_text(lambda m: m.text.startswith("mission: #4 WAYPOINT started"), since=resumed)
        check(s.command(mav.MAV_CMD_NAV_RETURN_TO_LAUNCH).result == mav.MAV_RESULT_ACCEPTED, "RTL")
        heartbeat_mode(s, mav, mav.COPTER_MODE_RTL)
        s.wait_text(lambda m: m.text.startswith("vehicle: landed at"), seconds=60, since=s.sent_at)
        landed = [t for t in s.lines(n0) if t.startswith("vehicle: landed at")][-1]
        check(float(re.search(r"landed at ([0-9.]+) m", landed).group(1)) < 2.0, "RTL lands home: %s" % landed)
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1 and not (m.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED))
        s.conn.mav.set_mode_send(1, mav.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, mav.COPTER_MODE_STABILIZE)
        check(s.wait("COMMAND_ACK", lambda m: m.command == mav.MAV_CMD_DO_SET_MODE).result ==
              mav.MAV_RESULT_ACCEPTED, "SET_MODE STABILIZE on the ground")
        # again from the start, then land where it is
        check(s.command(mav.MAV_CMD_COMPONENT_ARM_DISARM, 1.0).result == mav.MAV_RESULT_ACCEPTED, "re-arm")
        check(s.command(mav.MAV_CMD_MISSION_START).result == mav.MAV_RESULT_ACCEPTED, "MISSION_START")
        s.wait_text(lambda m: m.text.startswith("mission: #3 WAYPOINT started"), seconds=60,
               since=s.sent_at)
        n1 = s.mark()
        check(s.command(mav.MAV_CMD_NAV_LAND).result == mav.MAV_RESULT_ACCEPTED, "LAND")
        heartbeat_mode(s, mav, mav.COPTER_MODE_LAND)
        s.wait_text(lambda m: m.text.startswith("vehicle: landed at"), seconds=60, since=s.sent_at)
        landed = [t for t in s.lines(n1) if t.startswith("vehicle: landed at")][-1]
        check(float(re.search(r"landed at ([0-9.]+) m", landed).group(1)) > 20.0, "LAND lands there: %s" % landed)
        s.stop()
    counts = link_counts(s.out)
    check(counts[-1] == 1, "one command counted unsupported: %s" % (counts,))


def param_value(s, name, value=None, mav=None):
    """PARAM_SET (value given) or PARAM_REQUEST_READ of name; the PARAM_VALUE answering it."""
    mark = s.mark()
    if value is None:
        s.conn.mav.param_request_read_send(1, 1, name.encode(), -1)
    else:
        s.conn.mav.param_set_send(1, 1, name.encode(), value, mav.MAV_PARAM_TYPE_REAL32)
    return s.wait("PARAM_VALUE", lambda m: m.param_id == name, since=mark)


def t_mavlink_guided_takeoff(S):
    """QGroundControl's Takeoff and Start Mission actions, step by step as its ArduPilot plugin
    sends them: PILOT_TKOFF_ALT read as the least takeoff altitude, GUIDED, arm, NAV_TAKEOFF to
    max(PILOT_TKOFF_ALT, the slider's 5 m); the vehicle climbs there and holds; ArduCopter's
    refusals (disarmed, not GUIDED/LOITER, not above the vehicle, already flying, a COMMAND_INT
    in another frame); LAND; then an uploaded mission started with GUIDED, arm, MISSION_START."""
    g, sess = mavlink_session(S, ["--speedup", "10"])
    mav = g.mav
    with sess as s:
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(param_value(s, "PILOT_TKOFF_ALT").param_value == 0.0, "PILOT_TKOFF_ALT default 0")
        check(param_value(s, "PILOT_TKOFF_ALT", 1500.0, mav).param_value == 0.0, "1500 cm refused")
        check(param_value(s, "PILOT_TKOFF_ALT", 800.0, mav).param_value == 800.0, "800 cm set")
        a = s.command(mav.MAV_CMD_NAV_TAKEOFF, p7=8.0)
        check(a.result == mav.MAV_RESULT_FAILED, "takeoff disarmed: %s" % a)
        s.wait_text(lambda m: m.text == "gcs: takeoff refused: arm first", since=s.sent_at)
        a, _ = s.arm_and_auto()  # AUTO is refused: no mission
        check(a.result == mav.MAV_RESULT_ACCEPTED, "arm in STABILIZE")
        a = s.command(mav.MAV_CMD_NAV_TAKEOFF, p7=8.0)
        check(a.result == mav.MAV_RESULT_FAILED, "takeoff in STABILIZE: %s" % a)
        s.wait_text(lambda m: m.text == "gcs: takeoff refused: only in GUIDED or LOITER", since=s.sent_at)
        check(s.command(mav.MAV_CMD_COMPONENT_ARM_DISARM, 0.0).result == mav.MAV_RESULT_ACCEPTED, "disarm")
        # QGroundControl: takeoff altitude = max(PILOT_TKOFF_ALT / 100, the slider)
        alt = max(param_value(s, "PILOT_TKOFF_ALT").param_value / 100.0, 5.0)
        check(s.command(mav.MAV_CMD_DO_SET_MODE, 1.0, float(mav.COPTER_MODE_GUIDED)).result ==
              mav.MAV_RESULT_ACCEPTED, "GUIDED on the ground, disarmed")
        hb = heartbeat_mode(s, mav, mav.COPTER_MODE_GUIDED)
        check(hb.base_mode & mav.MAV_MODE_FLAG_GUIDED_ENABLED and not hb.base_mode & mav.MAV_MODE_FLAG_AUTO_ENABLED,
              "GUIDED flags: %s" % hb)
        check(s.command(mav.MAV_CMD_COMPONENT_ARM_DISARM, 1.0).result == mav.MAV_RESULT_ACCEPTED, "arm in GUIDED")
        hb = s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1 and m.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED,
                    since=s.sent_at)
        # as ArduCopter: armed on the ground is STANDBY (QGroundControl: not flying)
        check(hb.custom_mode == mav.COPTER_MODE_GUIDED and hb.system_status == mav.MAV_STATE_STANDBY,
              "armed on the ground: %s" % hb)
        mark = s.mark()
        s.conn.mav.command_int_send(1, 1, mav.MAV_FRAME_GLOBAL, mav.MAV_CMD_NAV_TAKEOFF, 0, 0, 0, 0, 0, 0, 0, 0,
                                    alt)
        a = s.wait("COMMAND_ACK", lambda m: m.command == mav.MAV_CMD_NAV_TAKEOFF, since=mark)
        check(a.result == mav.MAV_RESULT_DENIED, "COMMAND_INT takeoff in MAV_FRAME_GLOBAL: %s" % a)
        # (not 0 m: as in ArduCopter, the vehicle's own altitude on the ground is an estimate, a few
        # centimetres either side of home)
        a = s.command(mav.MAV_CMD_NAV_TAKEOFF, p7=-2.0)
        check(a.result == mav.MAV_RESULT_FAILED, "takeoff to -2 m: %s" % a)
        s.wait_text(lambda m: m.text == "gcs: takeoff refused: the altitude is not above the vehicle",
                    since=s.sent_at)
        start = s.wait("GLOBAL_POSITION_INT")
        a = s.command(mav.MAV_CMD_NAV_TAKEOFF, p7=alt)
        check(a.result == mav.MAV_RESULT_ACCEPTED, "takeoff to %.1f m: %s" % (alt, a))
        s.wait_text(lambda m: m.text == "gcs: takeoff to 8.0 m", since=s.sent_at)
        s.wait_text(lambda m: m.text.startswith("vehicle: takeoff complete at "), seconds=30, since=s.sent_at)
        # it holds there: 3 s (vehicle time) of positions within 0.7 m of the target, right above
        held = s.mark()
        t0 = s.wait("GLOBAL_POSITION_INT").time_boot_ms
        s.wait("GLOBAL_POSITION_INT", lambda m: m.time_boot_ms > t0 + 3000, seconds=10)
        pos = [m for _, m in s.msgs[held:] if m.get_type() == "GLOBAL_POSITION_INT"]
        check(len(pos) >= 10, "positions while holding: %d" % len(pos))
        for m in pos:
            check(abs(m.relative_alt / 1000.0 - alt) < 0.7, "holds %.1f m: %.2f m" % (alt, m.relative_alt / 1000.0))
            # within 1 m: 1e-7 degree is 1.1 cm of latitude, 0.77 cm of longitude at 46.5 N
            check(abs(m.lat - start.lat) < 90 and abs(m.lon - start.lon) < 130,
                  "above the takeoff point %s: %s" % (start, m))
        hb = heartbeat_mode(s, mav, mav.COPTER_MODE_GUIDED)
        check(hb.system_status == mav.MAV_STATE_ACTIVE, "in the air: ACTIVE: %s" % hb)
        a = s.command(mav.MAV_CMD_NAV_TAKEOFF, p7=20.0)
        check(a.result == mav.MAV_RESULT_FAILED, "takeoff again: %s" % a)
        s.wait_text(lambda m: m.text == "gcs: takeoff refused: already flying", since=s.sent_at)
        check(s.command(mav.MAV_CMD_NAV_LAND).result == mav.MAV_RESULT_ACCEPTED, "LAND")
        s.wait_text(lambda m: m.text.startswith("vehicle: landed at"), seconds=60, since=s.sent_at)
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1 and not (m.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED))
        # QGroundControl's Start Mission on the ground: GUIDED, arm, MISSION_START
        ack, _ = s.upload(g.wpl_items(os.path.join(MISSIONS, "plain.waypoints")))
        check(ack.type == mav.MAV_MISSION_ACCEPTED, "upload: %s" % ack)
        check(s.command(mav.MAV_CMD_DO_SET_MODE, 1.0, float(mav.COPTER_MODE_GUIDED)).result ==
              mav.MAV_RESULT_ACCEPTED, "GUIDED again")
        check(s.command(mav.MAV_CMD_COMPONENT_ARM_DISARM, 1.0).result == mav.MAV_RESULT_ACCEPTED, "arm again")
        check(s.command(mav.MAV_CMD_MISSION_START).result == mav.MAV_RESULT_ACCEPTED, "MISSION_START")
        heartbeat_mode(s, mav, mav.COPTER_MODE_AUTO)
        s.wait_text(lambda m: m.text.startswith("mission: #2 WAYPOINT started"), seconds=60, since=s.sent_at)
        s.stop()


def t_mavlink_link_loss(S):
    """A ground station that goes silent for FS_GCS_TIMEOUT (vehicle time) while the vehicle
    flies: RTL by default (home, landed), LAND with FS_GCS_ENABLE 5 (where it is), the mission
    goes on with 0; the link's return is said; an FS_GCS_ENABLE that is not an action refused."""
    g, sess = mavlink_session(S, ["--speedup", "10", os.path.join(MISSIONS, "plain.waypoints")])
    mav = g.mav
    with sess as s:
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        s.conn.mav.param_set_send(1, 1, b"FS_GCS_ENABLE", 3.0, mav.MAV_PARAM_TYPE_INT8)
        check(s.wait("PARAM_VALUE").param_value == 1.0, "FS_GCS_ENABLE 3 refused, RTL kept")
        for action, set_to, mode in (("RTL", None, mav.COPTER_MODE_RTL), ("LAND", 5.0, mav.COPTER_MODE_LAND),
                                     ("continuing (FS_GCS_ENABLE 0)", 0.0, None)):
            if set_to is not None:
                s.conn.mav.param_set_send(1, 1, b"FS_GCS_ENABLE", set_to, mav.MAV_PARAM_TYPE_INT8)
                check(s.wait("PARAM_VALUE").param_value == set_to, "FS_GCS_ENABLE %s" % set_to)
            n0 = s.mark()
            a, b = s.arm_and_auto() if action == "RTL" else (
                s.command(mav.MAV_CMD_COMPONENT_ARM_DISARM, 1.0), s.command(mav.MAV_CMD_MISSION_START))
            check(a.result == mav.MAV_RESULT_ACCEPTED and b.result == mav.MAV_RESULT_ACCEPTED,
                  "%s: arm, start" % action)
            s.wait_text(lambda m: m.text.startswith("mission: #3 WAYPOINT started"), seconds=60,
                   since=s.sent_at)
            s.hb_on = False
            s.sent_at = quiet = s.mark()
            s.wait_text(lambda m: m.text == "failsafe: ground station link lost: " + action, seconds=30,
                   since=quiet)
            # a failsafe holds: CRITICAL, as ArduCopter says it (FS_GCS_ENABLE 0: none, ACTIVE)
            hb = s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1, since=s.mark())
            check(hb.system_status == (mav.MAV_STATE_ACTIVE if mode is None else mav.MAV_STATE_CRITICAL),
                  "%s: %s" % (action, hb))
            if mode is not None:
                heartbeat_mode(s, mav, mode)
            s.hb_on = True
            s.wait_text(lambda m: m.text.startswith("failsafe: ground station link back"), since=quiet)
            if mode is None:
                s.wait_text(lambda m: m.text == "mission: complete", seconds=60, since=quiet)
            else:
                s.wait_text(lambda m: m.text.startswith("vehicle: landed at"), seconds=60, since=quiet)
            landed = [t for t in s.lines(n0) if t.startswith("vehicle: landed at")][-1]
            dist = float(re.search(r"landed at ([0-9.]+) m", landed).group(1))
            check((dist < 2.0) if action == "RTL" else (dist > 20.0) if action == "LAND" else True,
                  "%s: %s" % (action, landed))
            s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1 and not (m.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED))
            s.conn.mav.set_mode_send(1, mav.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED, mav.COPTER_MODE_STABILIZE)
            s.wait("COMMAND_ACK", lambda m: m.command == mav.MAV_CMD_DO_SET_MODE)
        s.stop()


def t_mavlink_reached_order(S):
    """MISSION_ITEM_REACHED over a mission with jumps (jumps.waypoints uploaded over MAVLink)
    comes in the order of the nav steps `mt-mission check --json` predicts for it."""
    tool = os.path.join(os.path.dirname(os.path.dirname(S.sitl)), "mt-mission")
    path = os.path.join(MISSIONS, "jumps.waypoints")
    p = subprocess.run([tool, "check", "--json", path], capture_output=True, text=True, timeout=60)
    check(p.returncode == 0, "mt-mission check: %s" % p.stderr)
    plan = json.loads(p.stdout)
    check(not plan["truncated"], "the plan ends")
    want = [st["index"] for st in plan["plan"] if st["kind"] == "nav"]
    g, sess = mavlink_session(S, ["--speedup", "20"])
    mav = g.mav
    with sess as s:
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        ack, _ = s.upload(g.wpl_items(path))
        check(ack.type == mav.MAV_MISSION_ACCEPTED, "upload: %s" % ack)
        a, b = s.arm_and_auto()
        check(a.result == mav.MAV_RESULT_ACCEPTED and b.result == mav.MAV_RESULT_ACCEPTED, "arm, AUTO")
        s.wait_text(lambda m: m.text == "mission: complete", seconds=90)
        s.stop()
    got = [m.seq for m in s.of("MISSION_ITEM_REACHED")]
    check(len(want) > 6 and got == want, "items reached %s, mt-mission predicts %s" % (got, want))


def t_mavlink_signing(S):
    """MAVLink 2 signing (--signing-key): the vehicle signs every frame; an unsigned command is
    dropped (no answer, counted); signed with the same key (pymavlink's setup_signing) it is
    accepted and the vehicle flies."""
    key = bytes(range(1, 33))
    g, sess = mavlink_session(S, ["--speedup", "10", "--signing-key", key.hex(),
                                  os.path.join(MISSIONS, "plain.waypoints")])
    mav = g.mav
    with sess as s:
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(s.conn.mav.signing.sig_count > 0, "the vehicle's frames carry a signature")
        check(s.unanswered(mav.MAV_CMD_COMPONENT_ARM_DISARM, 1.0), "an unsigned command was answered")
        s.conn.setup_signing(key, sign_outgoing=True)
        a, b = s.arm_and_auto()
        check(a.result == mav.MAV_RESULT_ACCEPTED and b.result == mav.MAV_RESULT_ACCEPTED, "signed: %s %s" % (a, b))
        s.wait_text(lambda m: m.text.startswith("mission: #2 WAYPOINT started"), seconds=60)
        hb = s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(hb.get_signed() and s.conn.mav.signing.goodsig_count > 100 and s.conn.mav.signing.badsig_count == 0,
              "pymavlink checks the vehicle's signatures with the key: %d good, %d bad"
              % (s.conn.mav.signing.goodsig_count, s.conn.mav.signing.badsig_count))
        s.stop()
    counts = link_counts(s.out)
    check(counts[7] >= 2 and counts[6] == 0, "unsigned frames dropped and counted (heartbeats, the command): %s"
          % (counts,))
    check("MAVLink signing on" in s.out, "said at start")


def t_mavlink_setup_signing(S):
    """SETUP_SIGNING over the link, as MAVProxy's `signing setup` sends it and ArduPilot takes it:
    the vehicle signs from then on and drops unsigned frames (a command goes unanswered, counted);
    signed with the key, a command is answered; a signed all-zero key turns signing off and an
    unsigned command is answered again. Runs on the firmware too (no command-line key)."""
    key = bytes(range(33, 65))
    g, sess = mavlink_session(S, ["--speedup", "10"])
    mav = g.mav
    with sess as s:
        hb = s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(s.command(31000).result == mav.MAV_RESULT_UNSUPPORTED, "unsigned command answered")
        # MAVLink's signature clock: 10 us units since 2015-01-01
        stamp = int((time.time() - 1420070400) * 1e5)
        check(s.conn.mav.signing.sig_count == 0, "no signed frame before SETUP_SIGNING")
        mark = s.mark()
        s.conn.mav.setup_signing_send(1, 1, key, stamp)
        s.wait_text(lambda m: m.text == "link: signing on (SETUP_SIGNING from 255/190)", since=mark)
        s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(s.conn.mav.signing.sig_count > 0, "the vehicle signs (frames with a signature seen)")
        check(s.unanswered(31000), "an unsigned command was answered while signing is on")
        s.conn.setup_signing(key, sign_outgoing=True)
        check(s.command(31000).result == mav.MAV_RESULT_UNSUPPORTED, "signed command answered")
        hb = s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1)
        check(hb.get_signed() and s.conn.mav.signing.badsig_count == 0 and s.conn.mav.signing.goodsig_count > 5,
              "pymavlink checks the vehicle's signatures: %d good, %d bad"
              % (s.conn.mav.signing.goodsig_count, s.conn.mav.signing.badsig_count))
        mark = s.mark()
        s.conn.mav.setup_signing_send(1, 1, bytes(32), 0)  # signed: the key holder turns it off
        # the ground station drops its key too (with a key, pymavlink drops unsigned frames)
        s.conn.mav.signing.sign_outgoing = False
        s.conn.mav.signing.secret_key = None
        s.wait_text(lambda m: m.text == "link: signing off (SETUP_SIGNING from 255/190)", since=mark)
        check(s.command(31000).result == mav.MAV_RESULT_UNSUPPORTED, "unsigned command answered again")
        check(not s.wait("HEARTBEAT", lambda m: m.get_srcSystem() == 1).get_signed(), "the vehicle signs no more")
        s.stop()
    counts = link_counts(s.out)
    check(counts[7] >= 1 and counts[6] == 0, "the unsigned frames dropped are counted: %s" % (counts,))


class MAVProxy:
    """MAVProxy (the pinned one in .tools/mavproxy, on the pinned pymavlink) as a console
    program: commands on its stdin, its output read line by line."""

    def __init__(self, master, cwd):
        import queue
        import threading
        env = dict(os.environ, PYTHONPATH=os.pathsep.join(
            [os.path.join(ROOT, ".tools", "mavproxy"), os.path.join(ROOT, ".tools", "pymavlink")]))
        self.p = subprocess.Popen([PY, os.path.join(ROOT, ".tools", "mavproxy", "bin", "mavproxy.py"),
                                   "--master", master], cwd=cwd, env=env,
                                  stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  text=True, bufsize=1)
        self.q = queue.Queue()
        self.lines = []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.p.stdout:
            self.q.put(line.rstrip("\n"))
        self.q.put(None)

    def send(self, cmd):
        self.p.stdin.write(cmd + "\n")
        self.p.stdin.flush()

    def expect(self, patterns, seconds):
        """The first output line matching one of the regexes (its index and the line)."""
        import queue
        end = time.time() + seconds
        while time.time() < end:
            try:
                line = self.q.get(timeout=max(0.01, end - time.time()))
            except queue.Empty:
                break
            if line is None:
                raise Fail("MAVProxy exited:\n" + "\n".join(self.lines[-30:]))
            self.lines.append(line)
            for i, pat in enumerate(patterns):
                if re.search(pat, line):
                    return i, line
        raise Fail("MAVProxy: none of %s in %d s:\n%s" % (patterns, seconds, "\n".join(self.lines[-30:])))

    def close(self):
        if self.p.poll() is None:
            try:
                self.send("exit")
                self.p.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                self.p.kill()
                self.p.wait()


def free_udp_port():
    import socket
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def t_mavproxy_flight(S):
    """A real ground station, MAVProxy (pinned, from PyPI), driven as a user would type:
    `wp load` of a QGC WPL file, `arm throttle` (again while the pre-arm checks refuse),
    `mode auto`; the vehicle flies the file's mission to its end at 4x (the firmware: at the pace
    QEMU gives it), and MAVProxy shows its messages; then `mode guided`, `arm throttle`,
    `takeoff 8`, `mode land`."""
    work = tempfile.mkdtemp(prefix="mavproxy-", dir=S.tmp)
    if S.firmware:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import mavgcs
        qemu = mavgcs.Qemu(S.firmware)
        mp = MAVProxy("tcp:127.0.0.1:%d" % qemu.port, work)
        scale = 4.0 / mavgcs.FW_MIN_RATE  # the waits below are written for 4x
    else:
        port = free_udp_port()
        mp = MAVProxy("udpin:127.0.0.1:%d" % port, work)
        sitl = subprocess.Popen([S.sitl, "--quiet", "--mavlink", "udp:127.0.0.1:%d" % port, "--speedup", "4",
                                 "--timeout", "300"], cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True)
        scale = 1.0
    try:
        mp.expect([r"Detected vehicle 1:1"], 30 * scale)
        mp.send("set heartbeat 10")  # 1 Hz of the vehicle's time at 4x needs more than 1 Hz here
        mp.send("wp load %s" % os.path.join(MISSIONS, "plain.waypoints"))
        mp.expect([r"Sent all 7 waypoints"], 30 * scale)
        mp.expect([r"AP: mission: 7 items uploaded"], 30 * scale)
        end = time.time() + 60 * scale
        while True:
            mp.send("arm throttle")
            i, line = mp.expect([r"^ARMED", r"COMPONENT_ARM_DISARM: FAILED"], 10 * scale)
            if i == 0:
                break
            check(time.time() < end, "MAVProxy could not arm: " + line)
            time.sleep(0.3)
        mp.send("mode auto")
        mp.expect([r"AP: mission: #1 TAKEOFF started"], 30 * scale)
        mp.expect([r"AP: mission: complete"], 120 * scale)
        mp.expect([r"^DISARMED"], 30 * scale)
        # then a takeoff as a MAVProxy user types it, and a landing
        mp.send("mode guided")
        mp.expect([r"Mode GUIDED"], 30 * scale)
        mp.send("arm throttle")
        mp.expect([r"^ARMED"], 30 * scale)
        mp.send("takeoff 8")
        mp.expect([r"NAV_TAKEOFF: ACCEPTED"], 30 * scale)
        mp.expect([r"AP: vehicle: takeoff complete at"], 60 * scale)
        mp.send("mode land")
        mp.expect([r"AP: vehicle: landed at"], 60 * scale)
        mp.expect([r"^DISARMED"], 30 * scale)
    finally:
        mp.close()
        if S.firmware:
            qemu.quit()
            _, out, _ = qemu.finish()
        else:
            if sitl.poll() is None:
                sitl.send_signal(signal.SIGINT)
            out, err = sitl.communicate(timeout=30)
    flown = [re.match(r"mission: #(\d+) (\w+) started", e).group(1, 2) for e in S_events(out)
             if re.match(r"mission: #\d+ \w+ started", e)]
    check(flown == [("1", "TAKEOFF"), ("2", "WAYPOINT"), ("3", "WAYPOINT"), ("4", "WAYPOINT"),
                    ("5", "WAYPOINT"), ("6", "LAND")], "the file flown from MAVProxy: %s" % flown)
    check("mission: COMPLETE" in out and "failsafe" not in out, "summary:\n" + out[-1500:])
    check(any("waypoint 6" in l for l in mp.lines), "MAVProxy followed MISSION_CURRENT")
    # what an ArduPilot vehicle would not make MAVProxy say: a fence breach (SYS_STATUS health),
    # an FTP timeout (the vehicle answers FTP with NAK at once)
    check(not any(("fence breach" in l) or ("FTP: request timed out" in l) for l in mp.lines),
          "MAVProxy complained:\n%s" % "\n".join(l for l in mp.lines if "fence" in l or "FTP" in l))


def t_mavlink_sanitizers(S):
    """The link's parser and answers under ASan+UBSan: the same session, no report."""
    s = t_mavlink_no_mission(S, binary=S.sitl_asan)
    check("runtime error" not in s.err and "AddressSanitizer" not in s.err, "sanitizers: %s" % s.err[-1500:])


TESTS = [
    ("vprint: console formatter against printf (ASan+UBSan)", t_vprint),
    ("sched_check: vehicle/tasks.def is schedulable", t_sched_nominal),
    ("sched_check: the overloaded table fails, telemetry_send must miss", t_sched_overloaded),
    ("sched_check: malformed and dishonest tables are rejected", t_sched_rejects),
    ("sitl: plain mission", t_plain),
    ("sitl: jumps (DO_JUMP repeat 2)", t_jumps),
    ("sitl: land at a location", t_land),
    ("sitl: RTL", t_rtl),
    ("sitl: loiter turns/time, conditions, servo", t_loiter),
    ("sitl: stop and resume in the middle", t_stop_resume),
    ("sitl: LOITER_UNLIM holds until the ground station lands it", t_loiter_unlim),
    ("sitl: built-in mission = builtin.waypoints", t_builtin_matches_file),
    ("sitl: deterministic simulated time", t_deterministic),
    ("sitl: fault injection (gcs_update overruns)", t_fault_injection),
    ("sitl: --timeline agrees with the flight summary, event by event", t_timeline),
    ("sitl: malformed missions rejected, vehicle stays disarmed", t_bad_mission),
    ("sitl: unreadable mission file", t_unreadable_mission),
    ("sitl: agreement with sched_check (nominal and overloaded)", t_agreement),
    ("sched_check: the tick encoding decides as the kernel, tick by tick", t_encoding),
    ("sitl: ASan+UBSan build", t_sanitizers),
    ("sitl: --realtime on real threads (TSan build)", t_realtime),
    ("mavlink: a ground station watches a flight (streams, parameters, mission)", t_mavlink_flight),
    ("mavlink: no mission, garbage on the link, a second ground station", t_mavlink_no_mission),
    ("mavlink: the same session in the ASan+UBSan build", t_mavlink_sanitizers),
    ("mavlink: truncated frames and a flood of requests", t_mavlink_flood),
    ("mavlink: mission upload, download, rejections, clear, set current", t_mavlink_mission_upload),
    ("mavlink: mission protocol timing, sequence, replaced in flight", t_mavlink_mission_protocol),
    ("mavlink: commands (arm, modes, mission start, current, RTL, land)", t_mavlink_commands),
    ("mavlink: GUIDED takeoff and start as QGroundControl sends them", t_mavlink_guided_takeoff),
    ("mavlink: link loss (RTL, LAND, continue)", t_mavlink_link_loss),
    ("mavlink: items reached in the order mt-mission predicts (jumps)", t_mavlink_reached_order),
    ("mavlink: signing (unsigned command dropped, signed accepted)", t_mavlink_signing),
    ("mavlink: SETUP_SIGNING turns signing on and off over the link", t_mavlink_setup_signing),
    ("mavproxy: wp load, arm throttle, mode auto: the mission flown; takeoff", t_mavproxy_flight),
]


# --firmware: the tests the firmware's session cannot run, and why.
FW_SKIP = {
    t_mavlink_no_mission: "UDP only: a datagram over 2 KB dropped whole, a second ground station at another "
                          "address; the firmware's link is one byte stream (a UART, one TCP client)",
}


def main(argv):
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("-k", default="")
    ap.add_argument("--firmware", metavar="ELF", help="the MAVLink tests against this firmware under QEMU")
    args = ap.parse_args(argv)
    S = Suite(os.path.abspath(args.build))
    S.firmware = args.firmware and os.path.abspath(args.firmware)
    need = (S.sitl, S.sitl_over, S.sitl_asan, S.sitl_tsan, os.path.join(os.path.dirname(S.sitl), "test_vprint"))
    for b in ((S.firmware,) if S.firmware else need) + (os.path.join(os.path.abspath(args.build), "mt-mission"),):
        if not os.access(b, os.R_OK if b == S.firmware else os.X_OK):
            print("missing %s (make test-vehicle builds it)" % b)
            return 2
    failed = skipped = 0
    n = 0
    t0 = time.time()
    for name, fn in TESTS:
        if args.k not in name or (S.firmware and not name.startswith(("mavlink:", "mavproxy:"))):
            continue  # the firmware runs the ground-station sessions only
        n += 1
        t1 = time.time()
        try:
            if S.firmware and fn in FW_SKIP:
                raise Skip(FW_SKIP[fn])
            fn(S)
            print("PASS %-62s %6.1f s" % (name, time.time() - t1))
        except Skip as e:
            skipped += 1
            print("SKIP %-62s %6.1f s\n     %s" % (name, time.time() - t1, e))
        except (Fail, subprocess.TimeoutExpired, KeyError, TypeError, AttributeError, TimeoutError,
                ValueError) as e:
            failed += 1
            print("FAIL %-62s %6.1f s\n     %s" % (name, time.time() - t1, str(e).replace("\n", "\n     ")))
    print("test-vehicle%s: %d/%d passed%s in %.1f s" % (" (firmware)" if S.firmware else "", n - failed - skipped,
                                                     n, ", %d skipped" % skipped if skipped else "", time.time() - t0))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
