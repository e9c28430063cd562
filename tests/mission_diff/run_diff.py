#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Differential property test: Metronome's mission sequencer (through
tests/mission_diff/mission_diff_driver.c, public API only) against the AP_Mission reference
(ap_mission_ref.py), on random missions and operation scripts.

    run_diff.py --driver build/mission_diff/mission_diff_driver              # 1,000 missions
    run_diff.py --driver ... --count 100000                                  # the deep run
    run_diff.py --driver ... --repro SEED       # one mission, both event streams side by side
    run_diff.py --driver ... --fixtures         # the ArduPilot autotest fixtures only
    run_diff.py --self-check                    # the comparison must catch a seeded bug
    run_diff.py --driver ... --all              # self-check, fixtures, then the diff

Every mission is generated from its own seed (derived from --seed and its number), so a
mismatch is reproduced with --repro alone. On the first mismatch (lowest mission number) the
mission, the script and the first differing line are printed and the exit status is 1.

Event lines (both sides): "U<k> start <i>", "U<k> verify <i> <0|1>", "U<k> complete",
"U<k> rc <op> <status>" (update: only when not MT_OK), "U<k> cur <i|none>" and
"U<k> count <i> <n>" when the loaded nav command or a finite jump's counter changed; k counts
API calls. Callback answers: splitmix64 hash of (mission seed, k, start/verify, index) below a
per-mille probability, so they never depend on the order of the calls.
"""
import argparse
import multiprocessing
import os
import random
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import ap_mission_ref as ref  # noqa: E402
import ap_autotest_fixtures as fixtures  # noqa: E402

MASK64 = (1 << 64) - 1
KIND_START, KIND_VERIFY = 0, 1

# A valid location (frame 3, relative altitude): CMAC, 10 m
LAT, LON, ALT = -353632620, 1491652370, 1000


# ---------------------------------------------------------------- callback answers
def mix64(z):
    z = (z + 0x9E3779B97F4A7C15) & MASK64
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
    return z ^ (z >> 31)


def outcome(seed, step, kind, index, permille):
    h = mix64(seed & MASK64)
    h = mix64(h ^ step)
    h = mix64(h ^ ((kind << 16) | index))
    return h % 1000 < permille


# ---------------------------------------------------------------- missions
class Mission:
    """cmds: list of [id, frame, options, p1, p2, p3, p4, x, y, z] (home first);
    probs: (p_nav_start, p_do_start, p_nav_verify, p_do_verify) per mille;
    ops: list of (op,) / (op, arg)."""

    def __init__(self, seed, cmds, probs, ops, note=""):
        self.seed = seed
        self.cmds = cmds
        self.probs = probs
        self.ops = ops
        self.note = note

    def driver_text(self):
        out = ["mission %d %d %d %d %d %d" % ((self.seed,) + tuple(self.probs) + (len(self.cmds),))]
        out += [" ".join(str(v) for v in c) for c in self.cmds]
        out.append("ops %d" % len(self.ops))
        out += [" ".join(str(v) for v in op) for op in self.ops]
        out.append("end")
        return "\n".join(out) + "\n"

    def describe(self):
        names = {16: "WAYPOINT", 17: "LOITER_UNLIM", 19: "LOITER_TIME", 20: "RTL", 21: "LAND",
                 22: "TAKEOFF", 82: "SPLINE_WP", 93: "NAV_DELAY", 213: "SET_YAW_SPEED",
                 112: "CONDITION_DELAY", 114: "CONDITION_DISTANCE", 115: "CONDITION_YAW",
                 177: "DO_JUMP", 178: "DO_CHANGE_SPEED", 181: "DO_SET_RELAY", 183: "DO_SET_SERVO",
                 189: "DO_LAND_START", 203: "DO_DIGICAM_CONTROL", 206: "DO_SET_CAM_TRIGG_DIST",
                 208: "DO_PARACHUTE", 211: "DO_GRIPPER", 600: "JUMP_TAG", 601: "DO_JUMP_TAG"}
        lines = ["mission seed %d%s" % (self.seed, (" (%s)" % self.note) if self.note else ""),
                 "callbacks (per mille): nav start %d, do start %d, nav verify %d, do verify %d"
                 % tuple(self.probs)]
        for i, c in enumerate(self.cmds):
            cid = c[0]
            extra = ""
            if cid == 177:
                extra = " -> %d repeat %d" % (c[3] // 1000, c[4] // 1000)
            elif cid == 601:
                extra = " -> tag %d repeat %d" % (c[3] // 1000, c[4] // 1000)
            elif cid == 600:
                extra = " tag %d" % (c[3] // 1000)
            kind = "home" if i == 0 else ("nav" if ref.is_nav_id(cid) else
                                          ("jump" if cid in (177, 601) else "do"))
            lines.append("  %2d %-4s %3d %s%s" % (i, kind, cid, names.get(cid, ""), extra))
        ops = []
        for op in self.ops:
            ops.append(op[0] if len(op) == 1 else "%s %d" % op)
        lines.append("script: " + ", ".join(ops))
        return "\n".join(lines)

    def ref_cmds(self):
        return [(c[0], c[3:7]) for c in self.cmds]


def finite_jumps(m):
    return [i for i, c in enumerate(m.cmds) if i > 0 and c[0] in (177, 601) and c[4] >= 0]


def run_reference(m, deviations=None, mutant=False):
    """The event lines the reference produces for mission m (same format as the driver)."""
    seed = m.seed
    p_nav_start, p_do_start, p_nav_verify, p_do_verify = m.probs
    step = [0]
    lines = ["mission %d" % seed, "load 0 65535"]
    cmds = m.ref_cmds()

    def on_start(i):
        p = p_nav_start if ref.is_nav_id(cmds[i][0]) else p_do_start
        lines.append("U%d start %d" % (step[0], i))
        return outcome(seed, step[0], KIND_START, i, p)

    def on_verify(i):
        p = p_nav_verify if ref.is_nav_id(cmds[i][0]) else p_do_verify
        ok = outcome(seed, step[0], KIND_VERIFY, i, p)
        lines.append("U%d verify %d %d" % (step[0], i, 1 if ok else 0))
        return ok

    def on_complete():
        lines.append("U%d complete" % step[0])

    ap = ref.ApMission(cmds, on_start, on_verify, on_complete, deviations, mutant)
    jumps = finite_jumps(m)
    seen_cur = ref.NONE
    seen_count = {i: 0 for i in jumps}
    for op in m.ops:
        rep = op[1] if op[0] == "update" else 1
        for _ in range(rep):
            step[0] += 1
            if op[0] == "start":
                st = ap.start()
            elif op[0] == "stop":
                st = ap.stop()
            elif op[0] == "resume":
                st = ap.resume()
            elif op[0] == "restart":
                st = ap.restart_current()
            elif op[0] == "set":
                st = ap.set_current(op[1])
            elif op[0] == "update":
                st = ap.update()
            else:
                raise ValueError(op)
            if not (op[0] == "update" and st == ref.MT_OK):
                lines.append("U%d rc %s %d" % (step[0], op[0], st))
            cur = ap.current_nav()
            if cur != seen_cur:
                seen_cur = cur
                lines.append("U%d cur %s" % (step[0], "none" if cur == ref.NONE else cur))
            for i in jumps:
                k = ap.jump_count(i)
                if k != seen_count[i]:
                    seen_count[i] = k
                    lines.append("U%d count %d %d" % (step[0], i, k))
    lines.append("end")
    return lines


def run_driver(driver, missions):
    """Event lines per mission from the C driver (one process for the whole batch)."""
    text = "".join(m.driver_text() for m in missions)
    proc = subprocess.run([driver], input=text, capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        raise RuntimeError("driver failed (exit %d): %s" % (proc.returncode, proc.stderr.strip()))
    out = []
    cur = None
    for line in proc.stdout.splitlines():
        if line.startswith("mission "):
            cur = [line]
        elif line == "end":
            cur.append(line)
            out.append(cur)
            cur = None
        else:
            cur.append(line)
    if len(out) != len(missions):
        raise RuntimeError("driver returned %d missions for %d" % (len(out), len(missions)))
    return out


# ---------------------------------------------------------------- generator
NAV_IDS = [16] * 6 + [22, 21, 19, 17, 82, 20, 93, 213]
DO_IDS = [178, 178, 183, 208, 211, 181, 206, 203, 189]
COND_IDS = [112, 114, 115]


def nav_cmd(rng):
    cid = rng.choice(NAV_IDS)
    if cid in (20, 93, 213):   # no location: MISSION frame, zero x/y/z
        p1 = 5000 if cid == 93 else 0
        return [cid, 2, 1, p1, 0, 0, 0, 0, 0, 0]
    p1 = {16: rng.choice([0, 2000]), 19: 5000, 82: 0}.get(cid, 0)
    return [cid, 3, 1, p1, 0, 0, 0, LAT + rng.randint(-5000, 5000), LON + rng.randint(-5000, 5000),
            ALT + rng.randint(0, 5000)]


def do_cmd(rng, cid=None):
    cid = cid if cid is not None else rng.choice(DO_IDS)
    if cid == 178:
        return [cid, 2, 1, rng.randint(0, 3) * 1000, rng.choice([-2000, -1000, 5000, 12500]), -1000, 0, 0, 0, 0]
    if cid == 183:
        return [cid, 2, 1, rng.randint(1, 16) * 1000, rng.choice([1000000, 1500000, 1900000]), 0, 0, 0, 0, 0]
    if cid == 208:
        return [cid, 2, 1, 2000, 0, 0, 0, 0, 0, 0]
    if cid == 211:
        return [cid, 2, 1, 1000, rng.choice([0, 1000]), 0, 0, 0, 0, 0]
    if cid == 181:
        return [cid, 2, 1, rng.randint(0, 3) * 1000, rng.choice([0, 1000]), 0, 0, 0, 0, 0]
    if cid == 206:
        return [cid, 2, 1, rng.choice([0, 25000]), 0, 0, 0, 0, 0, 0]
    if cid == 189:  # DO_LAND_START carries a location
        return [cid, 3, 1, 0, 0, 0, 0, LAT, LON, 0]
    if cid == 112:
        return [cid, 2, 1, rng.choice([0, 3000, 10000]), 0, 0, 0, 0, 0, 0]
    if cid == 114:
        return [cid, 2, 1, rng.choice([0, 15000]), 0, 0, 0, 0, 0, 0]
    if cid == 115:
        return [cid, 2, 1, rng.randint(0, 360) * 1000, rng.choice([0, 10000]), rng.choice([-1000, 0, 1000]),
                rng.choice([0, 1000]), 0, 0, 0]
    return [cid, 2, 1, 0, 0, 0, 0, 0, 0, 0]


def jump_target(cmds, i):
    """Target index of the jump at i (DO_JUMP_TAG: first JUMP_TAG with its tag), or None."""
    c = cmds[i]
    if c[0] == 177:
        return c[3] // 1000
    if c[0] == 601:
        for j in range(1, len(cmds)):
            if cmds[j][0] == 600 and cmds[j][3] == c[3]:
                return j
        return None
    return None


def structurally_valid(cmds):
    """What the generator promises the loader: jump targets in [1, n), tags that exist, and
    every walk from every command reaches a nav command or the end (no loop without a nav
    command), judged on the graph of fall-through and jump edges."""
    n = len(cmds)
    for i in range(1, n):
        if cmds[i][0] in (177, 601):
            t = jump_target(cmds, i)
            if t is None or not 1 <= t < n:
                return False
    safe = [False] * (n + 1)
    safe[n] = True
    changed = True
    while changed:
        changed = False
        for i in range(n - 1, 0, -1):
            if safe[i]:
                continue
            c = cmds[i]
            if c[0] in (177, 601):
                t, rep = jump_target(cmds, i), c[4] // 1000
                ok = safe[t] if rep < 0 else (safe[i + 1] if rep == 0 else safe[t] and safe[i + 1])
            else:
                ok = ref.is_nav_id(c[0]) or safe[i + 1]
            if ok:
                safe[i] = True
                changed = True
    return all(safe[1:n])


def repeat_count(rng):
    r = rng.random()
    if r < 0.10:
        return 0
    if r < 0.60:
        return rng.randint(1, 3)
    if r < 0.75:
        return rng.randint(4, 12)
    if r < 0.90:
        return -1
    return rng.randint(20, 300)


def generate_commands(rng):
    size = rng.randint(1, 30)
    profile = rng.random()
    if profile < 0.10:
        p_nav = 1.0          # no do commands at all
    elif profile < 0.20:
        p_nav = 0.08         # long runs of do / condition commands
    else:
        p_nav = rng.choice([0.25, 0.4, 0.55, 0.75])
    p_cond = rng.choice([0.0, 0.2, 0.5])
    n_jumps = min(size // 2, rng.choice([0, 0, 1, 1, 2, 3, 4]))
    n_tags = rng.choice([0, 0, 0, 1, 2])
    kinds = []
    for _ in range(max(1, size - n_jumps - n_tags)):
        if rng.random() < p_nav:
            kinds.append("nav")
        else:
            kinds.append("cond" if rng.random() < p_cond else "do")
    if rng.random() < 0.2:
        kinds += ["do"] * rng.randint(1, 3)       # do commands after the last nav command
    for _ in range(n_tags):
        kinds.insert(rng.randint(0, len(kinds)), "tag")
    for _ in range(n_jumps):
        kinds.insert(rng.randint(0, len(kinds)), "jump")
    tags = []
    cmds = [[16, 0, 1, 0, 0, 0, 0, LAT, LON, 58400]]
    for k in kinds:
        if k == "nav":
            cmds.append(nav_cmd(rng))
        elif k == "do":
            cmds.append(do_cmd(rng))
        elif k == "cond":
            cmds.append(do_cmd(rng, rng.choice(COND_IDS)))
        elif k == "tag":
            tag = rng.choice([1, 2, 7, 65535]) if not tags or rng.random() < 0.7 else rng.choice(tags)
            tags.append(tag)
            cmds.append([600, 2, 1, tag * 1000, 0, 0, 0, 0, 0, 0])
        else:
            cmds.append(None)   # a jump, filled in below
    n = len(cmds)
    for i in range(1, n):
        if cmds[i] is not None:
            continue
        placed = False
        for _ in range(30):
            rep = repeat_count(rng)
            if tags and rng.random() < 0.4:
                cand = [601, 2, 1, rng.choice(tags) * 1000, rep * 1000, 0, 0, 0, 0, 0]
            else:
                if rng.random() < 0.7 and i > 1:
                    t = rng.randint(1, i - 1)          # backward: a loop
                else:
                    t = rng.randint(1, n - 1)
                cand = [177, 2, 1, t * 1000, rep * 1000, 0, 0, 0, 0, 0]
            cmds[i] = cand
            probe = [c if c is not None else do_cmd(rng, 203) for c in cmds]
            if structurally_valid(probe):
                placed = True
                break
        if not placed:
            cmds[i] = do_cmd(rng, 203)
    assert structurally_valid(cmds)
    return cmds


def generate_ops(rng, n):
    ops = []
    if rng.random() < 0.1:
        ops.append(("set", rng.randint(0, n)))      # set-current before the first start
    if rng.random() < 0.05:
        ops.append(("resume",))                     # resume before any start
    else:
        ops.append(("start",))
    budget = rng.randint(5, 200)
    while budget > 0:
        k = rng.randint(1, min(budget, 40))
        ops.append(("update", k))
        budget -= k
        r = rng.random()
        if r < 0.10:
            ops.append(("stop",))
            for _ in range(rng.choice([0, 0, 1, 2])):
                ops.append(("set", rng.randint(0, n)))
            if rng.random() < 0.15:
                ops.append(("update", 1))           # refused: not running
            ops.append(("resume",))
        elif r < 0.17:
            ops.append(("set", rng.randint(0, n)))  # while running (n: invalid)
        elif r < 0.22:
            ops.append(("restart",))
        elif r < 0.26:
            ops.append(("start",))
        elif r < 0.30:
            ops.append((rng.choice(["resume", "stop", "stop"]),))
        elif r < 0.45:
            ops.append(("resume",))                 # restarts a completed mission
    return ops


PROB_PRESETS = [
    (900, 800, 400, 500),
    (900, 1000, 300, 300),
    (1000, 1000, 1000, 1000),   # everything at once
    (700, 500, 600, 600),
    (500, 900, 500, 400),
    (950, 900, 200, 800),
]


def mission_seed(base_seed, number):
    return mix64((base_seed << 24) ^ number) & ((1 << 63) - 1)


def generate(seed):
    rng = random.Random(seed)
    cmds = generate_commands(rng)
    probs = rng.choice(PROB_PRESETS)
    return Mission(seed, cmds, probs, generate_ops(rng, len(cmds)))


# ---------------------------------------------------------------- comparison
def first_difference(got, want):
    for i in range(max(len(got), len(want))):
        g = got[i] if i < len(got) else "<nothing>"
        w = want[i] if i < len(want) else "<nothing>"
        if g != w:
            return i, g, w
    return None


def compare_batch(args):
    """Worker: missions [lo, hi) of the run; returns (count, mismatches) with at most
    `limit` mismatches (number, seed, line, got, want), in mission order."""
    driver, base_seed, lo, hi, mutant, vs_mutant, dev, limit = args
    missions = [generate(mission_seed(base_seed, k)) for k in range(lo, hi)]
    if driver is None:
        got_all = [run_reference(m) for m in missions]
    else:
        got_all = run_driver(driver, missions)
    found = []
    for k, (m, got) in enumerate(zip(missions, got_all)):
        if driver is not None and got[1] != "load 0 65535":
            found.append((lo + k, m.seed, 1, got[1], "load 0 65535 (generator bug: the C loader "
                          "rejected a mission the generator meant to be valid)"))
        else:
            want = run_reference(m, deviations=make_deviations(dev), mutant=mutant or vs_mutant)
            d = first_difference(got, want)
            if d is not None:
                found.append((lo + k, m.seed, d[0], d[1], d[2]))
        if len(found) >= limit:
            break
    return hi - lo, found


def make_deviations(dev):
    """Deviations from a tuple of (name, bool) overrides (picklable for the workers)."""
    return ref.Deviations(**dict(dev or ()))


def run_diff(driver, count, base_seed, jobs, mutant=False, vs_mutant=False, dev=(), limit=1):
    """The first `limit` mismatches (number, seed, line, got, want), in mission order."""
    batch = 250
    work = [(driver, base_seed, lo, min(count, lo + batch), mutant, vs_mutant, tuple(dev), limit)
            for lo in range(0, count, batch)]
    found = []
    with multiprocessing.Pool(jobs) as pool:
        for _, mism in pool.imap(compare_batch, work):
            found += mism
            if len(found) >= limit:
                pool.terminate()
                break
    return found[:limit]


def print_mismatch(mism, driver, label_got="C driver", label_want="reference", extra=""):
    number, seed, line, got, want = mism
    m = generate(seed)
    print("MISMATCH in mission #%d (seed %d), event line %d:" % (number, seed, line))
    print("  %-10s: %s" % (label_got, got))
    print("  %-10s: %s" % (label_want, want))
    print(m.describe())
    print("reproduce: %s --driver %s --repro %d%s" % (os.path.relpath(__file__), driver, seed, extra))


def repro(driver, seed, mutant=False, dev=()):
    m = generate(seed)
    print(m.describe())
    got = run_driver(driver, [m])[0]
    want = run_reference(m, deviations=make_deviations(dev), mutant=mutant)
    d = first_difference(got, want)
    width = max(len(x) for x in got + want) + 2
    print("%-*s %s" % (width, "C driver", "reference"))
    for i in range(max(len(got), len(want))):
        g = got[i] if i < len(got) else ""
        w = want[i] if i < len(want) else ""
        mark = "  <== first difference" if d is not None and i == d[0] else ("  *" if g != w else "")
        print("%-*s %s%s" % (width, g, w, mark))
    return 0 if d is None else 1


# ---------------------------------------------------------------- fixtures, self-check
def check_fixture(fx, lines):
    """Failures of fixture fx's ArduPilot expectations on an event stream."""
    starts = [int(x.split()[2]) for x in lines if x.split()[1:2] == ["start"]]
    pos = {}
    for n, x in enumerate(lines):
        w = x.split()
        if len(w) >= 3 and w[1] == "start":
            pos.setdefault(("start", int(w[2])), n)
        if len(w) == 4 and w[1] == "verify" and w[3] == "1":
            pos.setdefault(("done", int(w[2])), n)
        if len(w) == 2 and w[1] == "complete":
            pos.setdefault(("complete",), n)
    bad = []
    for e in fx["expect"]:
        what = e[0]
        if what == "starts":
            if starts != list(e[1]):
                bad.append("start order %s, ArduPilot expects %s" % (starts, list(e[1])))
        elif what == "started":
            if ("start", e[1]) not in pos:
                bad.append("command %d never started" % e[1])
        elif what == "before":
            a, b = pos.get(("start", e[1])), pos.get(("start", e[2]))
            if a is None or b is None or a > b:
                bad.append("command %d should start before command %d" % (e[1], e[2]))
        elif what == "during":
            d, prev, nav = e[1], e[2], e[3]
            s = pos.get(("start", d))
            lo = pos.get(("done", prev), -1) if prev is not None else -1
            hi = pos.get(("done", nav), len(lines))
            if s is None or not lo < s < hi:
                bad.append("command %d should start after %s completed and before %d completed"
                           % (d, "nothing" if prev is None else prev, nav))
        elif what == "complete_after":
            s, c = pos.get(("start", e[1])), pos.get(("complete",))
            if s is None or c is None or c < s:
                bad.append("the mission should complete after command %d started" % e[1])
        else:
            raise ValueError(e)
    return bad


def fixture_mission(fx):
    probs = fx.get("probs", (1000, 1000, 1000, 1000))
    return Mission(fx.get("seed", 1), fx["cmds"], probs, fx["ops"], fx["name"])


def run_fixtures(driver, mutant=False, quiet=False):
    """Each fixture through the reference and (with driver) the C driver; returns failures."""
    failures = []
    for fx in fixtures.FIXTURES:
        m = fixture_mission(fx)
        streams = [("reference", run_reference(m, mutant=mutant))]
        if driver is not None:
            streams.append(("C driver", run_driver(driver, [m])[0]))
        for who, lines in streams:
            if lines[1] != "load 0 65535":
                failures.append((fx["name"], who, ["rejected at load: %s" % lines[1]]))
                continue
            bad = check_fixture(fx, lines)
            if bad:
                failures.append((fx["name"], who, bad))
            elif not quiet:
                print("fixture %-28s %-9s ok   (%s)" % (fx["name"], who, fx["source"]["test"]))
    return failures


def self_check(jobs):
    """The comparison must see the seeded bug: the reference against its mutant (do
    commands started after the following nav command) on the generated missions, and the
    fixtures against the mutant. The reference against itself must agree."""
    ok = True
    same = run_diff(None, 300, 7, jobs)
    if same:
        print("self-check: the reference disagrees with itself: %r" % (same[0],))
        ok = False
    caught = run_diff(None, 1000, 1, jobs, vs_mutant=True)
    if not caught:
        print("self-check: FAILED, the diff did not catch the do-after-nav mutant in 1000 missions")
        ok = False
    else:
        c = caught[0]
        print("self-check: the diff catches the do-after-nav mutant (mission #%d, line %d: "
              "'%s' vs mutant '%s')" % (c[0], c[2], c[3], c[4]))
    fx = run_fixtures(None, mutant=True, quiet=True)
    if not fx:
        print("self-check: FAILED, no fixture rejects the do-after-nav mutant")
        ok = False
    else:
        print("self-check: %d fixture(s) reject the mutant (e.g. %s: %s)"
              % (len(fx), fx[0][0], fx[0][2][0]))
    return ok


# ---------------------------------------------------------------- main
def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--driver", help="path of the compiled mission_diff_driver")
    ap.add_argument("--count", type=int, default=1000, help="missions (default 1000)")
    ap.add_argument("--seed", type=int, default=1, help="base seed (default 1)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--mutant", action="store_true",
                    help="compare the driver with the do-after-nav mutant of the reference")
    ap.add_argument("--repro", type=int, metavar="SEED", help="run one mission, print both streams")
    ap.add_argument("--fixtures", action="store_true", help="only the ArduPilot autotest fixtures")
    ap.add_argument("--self-check", action="store_true", help="only the self-check (no driver needed)")
    ap.add_argument("--all", action="store_true", help="self-check, fixtures, then the diff")
    ap.add_argument("--list", type=int, default=1, metavar="N",
                    help="keep going and list the first N mismatches (default 1)")
    ap.add_argument("--deviation", action="append", default=[], metavar="NAME=0|1",
                    help="override one of ap_mission_ref.Deviations (exploration only)")
    a = ap.parse_args()
    dev = []
    for d in a.deviation:
        name, _, value = d.partition("=")
        if name not in ref.Deviations.NAMES or value not in ("0", "1"):
            ap.error("--deviation %s: expected one of %s with =0 or =1" % (d, ", ".join(ref.Deviations.NAMES)))
        dev.append((name, value == "1"))

    if a.repro is not None:
        return repro(a.driver, a.repro, a.mutant, dev)
    status = 0
    if a.self_check or a.all:
        if not self_check(a.jobs):
            status = 1
        if a.self_check:
            return status
    if a.driver is None:
        ap.error("--driver is required")
    if a.fixtures or a.all:
        fails = run_fixtures(a.driver, mutant=a.mutant)
        for name, who, bad in fails:
            for b in bad:
                print("fixture %s FAILED (%s): %s" % (name, who, b))
        if fails:
            status = 1
        if a.fixtures:
            return status
    t0 = time.time()
    mism = run_diff(a.driver, a.count, a.seed, a.jobs, mutant=a.mutant, dev=dev,
                    limit=max(1, a.list))
    dt = time.time() - t0
    if mism:
        print_mismatch(mism[0], a.driver, extra="".join(" --deviation %s" % d for d in a.deviation)
                       + (" --mutant" if a.mutant else ""))
        for n, seed, line, got, want in mism[1:]:
            print("also mission #%d (seed %d) line %d: C '%s', reference '%s'"
                  % (n, seed, line, got, want))
        print("mission diff: FAILED after %.1f s (%d missions, seed %d)" % (dt, a.count, a.seed))
        return 1
    print("mission diff: %d missions (seed %d) agree with the AP_Mission reference (%.1f s)"
          % (a.count, a.seed, dt))
    return status


if __name__ == "__main__":
    sys.exit(main())
