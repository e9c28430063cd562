#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""make sched-check: is a Metronome task table schedulable? (Z3)

    sched_check.py [--horizon N] [--json FILE] [--quiet] TASKS.def

Reads a task table from its single source (the X-macro file the C build includes,
e.g. vehicle/tasks.def: SCHED_LOOP, SCHED_TIMER, SCHED_FAST, SCHED_TASK), validates it
as mt_sched_validate() does, and encodes one main-loop tick exactly as
kernel/src/sched.c runs it:

  * the sample arrives; the time before the scan is the part of a timer round that
    started before the sample and is still running (0 .. timer cost);
  * tasks are scanned once, in table order; fast tasks (priority < 3) always run;
    a normal task is due when tick - last_run >= interval, interval =
    max(1, floor(loop_rate * 1000 / rate_mhz)) (fixed at init); a due task whose
    budget exceeds the time left is skipped and stays due; a task that runs sets
    last_run = tick;
  * time left = max(0, period - elapsed at scan start) + extra, reduced after each
    run by the wall time since the scan started (S-9), floored at 0;
  * slips += floor(dt / interval) - 1 when dt >= 2 intervals; a run >= 4 intervals
    late is "not achieved" and adds 100 us of extra time to the next loops (at most
    5000 us); more than 50 clean loops take 50 us off;

with each run taking a nondeterministic time in [cost_min, cost_max] and the timer
thread pre-empting the main loop every timer period at any phase, each round taking
[cost_min, cost_max]: a round that falls due while a task runs extends that task's
wall time (exactly the SITL's rule: served when the running task still has work
left at the round's due time).

Analyses:
  1. Aligned (all ticks). While no task is ever skipped, every task runs exactly at its
     releases, so tick k's due set is {i : k mod interval_i == 0}. Z3 searches one
     symbolic tick k in [1, hyperperiod] (with symbolic execution times, timer phase
     and round costs) for a skip. None: by induction every release is served at its
     own tick, forever (no slip, no skip, lateness 0): the table is schedulable.
  2. Per task (when a skip is possible). A task's fate depends only on the tasks
     before it in the scan (later ones run after it), so each task is decided on its
     prefix of the table:
     a. Z3: can it be skipped at all, whatever the earlier tasks' due states? No: it
        never misses a release (lateness 0). Else: can it be skipped n ticks in a row
        (n = 2..4, the ticks chained exactly, from any state)? No, and n <= interval:
        it is at most n - 1 ticks late and never misses (a miss takes `interval`
        skips in a row).
     b. Otherwise every reachable state of the prefix from start-up is enumerated
        (for each task the ticks since its last run, capped at 4 intervals: sched.c only
        compares it with 1, 2 and 4 intervals), each tick's outcomes decided by Z3
        (which of the due tasks some execution runs). The state graph is finite, so
        the verdicts hold for every tick: the task NEVER misses a release, MUST miss
        one (on every execution; by which tick at the latest), or MAY; its worst-case
        lateness (ticks from a release to the run, or unbounded); a counterexample
        tick schedule for a failing task.
     Both assume the extra loop time stays 0. That holds by induction when no task can
     run 4 intervals late while it is 0: a task of (a) is never skipped, and the tool
     checks the explored graphs of (b); otherwise it reports the verdicts as undecided.

Also checked: honest budgets (cost_max plus the timer rounds that can fall into one run
fit the budget), and that each tick ends within the period (no lost sample, so the fast
tasks meet the loop rate): the fast loop's worst case is maximised by Z3, and a normal
task starts only when its budget fits the time left, so with honest budgets and no extra
time a tick never runs past the period.

Exit status: 0 schedulable, 1 not schedulable, 2 bad input. The verdicts hold for
the model: execution times within the stated ranges and no other pre-emption of the
main loop than the timer thread (the IO thread runs below the main loop).
"""

import argparse
import json
import math
import re
import sys
import time

try:
    import z3
except ImportError:  # pragma: no cover
    sys.stderr.write("sched_check: the Z3 Python bindings are missing (tools/bootstrap.sh sched)\n")
    sys.exit(2)

# mt/sched.h
RATE_MIN, RATE_MAX = 50, 2000
MAX_TASKS = 64
FAST_PRIO_LIMIT = 3
SLOWDOWN = 4
EXTRA_STEP, EXTRA_DECAY, EXTRA_MAX, CLEAN_LOOPS = 100, 50, 5000, 50
MAX_SKIP_RUN = 4  # longest run of consecutive skips the chained check tries


class TableError(Exception):
    pass


class Task:
    def __init__(self, name, fast, rate_hz, budget, prio, cmin, cmax, line):
        self.name, self.fast, self.rate_hz = name, fast, rate_hz
        self.budget, self.prio, self.cmin, self.cmax, self.line = budget, prio, cmin, cmax, line
        self.interval = 1


class Table:
    def __init__(self):
        self.loop_hz = None
        self.timer = None  # (period, cmin, cmax)
        self.latency = 0   # the scan can start up to this long after the sample
        self.tasks = []
        self.path = ""

    @property
    def period(self):
        return 1000000 // self.loop_hz


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def parse(path):
    """Read the X-macro table. Every non-comment line must be one entry."""
    t = Table()
    t.path = path
    with open(path, encoding="utf-8") as f:
        text = strip_comments(f.read())
    num = r"\s*(-?\d+)\s*"
    ident = r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*"
    pats = {
        "SCHED_LOOP": re.compile(r"^SCHED_LOOP\(" + num + r"\)$"),
        "SCHED_LATENCY": re.compile(r"^SCHED_LATENCY\(" + num + r"\)$"),
        "SCHED_TIMER": re.compile(r"^SCHED_TIMER\(" + num + "," + num + "," + num + r"\)$"),
        "SCHED_FAST": re.compile(r"^SCHED_FAST\(" + ident + "," + num + "," + num + "," + num + "," + num + r"\)$"),
        "SCHED_TASK": re.compile(r"^SCHED_TASK\(" + ident + "," + num + "," + num + "," + num + "," + num + "," + num + r"\)$"),
    }
    for lineno, raw in enumerate(text.split("\n"), 1):
        line = raw.strip()
        if not line:
            continue
        kind = line.split("(", 1)[0].strip()
        m = pats.get(kind, re.compile("^$")).match(line)
        if not m:
            raise TableError("%s:%d: not a table entry: %s" % (path, lineno, line))
        g = m.groups()
        if kind == "SCHED_LOOP":
            if t.loop_hz is not None:
                raise TableError("%s:%d: second SCHED_LOOP" % (path, lineno))
            t.loop_hz = int(g[0])
        elif kind == "SCHED_LATENCY":
            t.latency = int(g[0])
        elif kind == "SCHED_TIMER":
            if t.timer is not None:
                raise TableError("%s:%d: second SCHED_TIMER" % (path, lineno))
            t.timer = tuple(int(x) for x in g)
        elif kind == "SCHED_FAST":
            t.tasks.append(Task(g[0], True, 0, int(g[2]), int(g[1]), int(g[3]), int(g[4]), lineno))
        else:
            t.tasks.append(Task(g[0], False, int(g[1]), int(g[2]), int(g[3]), int(g[4]), int(g[5]), lineno))
    if t.loop_hz is None:
        raise TableError("%s: no SCHED_LOOP" % path)
    if t.timer is None:
        t.timer = (1000, 0, 0)
    return t


def validate(t):
    """mt_sched_validate() (same order, same statuses) plus the model's own checks."""
    if not RATE_MIN <= t.loop_hz <= RATE_MAX:
        raise TableError("MT_E_LOOP_RATE: loop rate %d Hz outside [%d, %d]" % (t.loop_hz, RATE_MIN, RATE_MAX))
    n = len(t.tasks)
    if not 1 <= n <= MAX_TASKS:
        raise TableError("MT_E_TASK_COUNT: %d tasks" % n)
    period = t.period
    for i, k in enumerate(t.tasks):
        where = "entry %d (%s, line %d)" % (i, k.name, k.line)
        rate_mhz = k.rate_hz * 1000
        if k.prio < FAST_PRIO_LIMIT:
            if rate_mhz != 0:
                raise TableError("MT_E_TASK_RATE: %s: a fast task (priority < 3) has rate 0" % where)
        else:
            if not 1 <= rate_mhz <= t.loop_hz * 1000:
                raise TableError("MT_E_TASK_RATE: %s: rate %d Hz outside (0, %d]" % (where, k.rate_hz, t.loop_hz))
            if k.budget < 1:
                raise TableError("MT_E_TASK_BUDGET: %s: budget 0" % where)
        if k.budget > period:
            raise TableError("MT_E_TASK_BUDGET: %s: budget %d us > period %d us" % (where, k.budget, period))
        if i > 0 and t.tasks[i - 1].prio > k.prio:
            raise TableError("MT_E_TASK_ORDER: %s: priority %d after %d" % (where, k.prio, t.tasks[i - 1].prio))
        k.interval = 1 if k.prio < FAST_PRIO_LIMIT else max(1, (t.loop_hz * 1000) // rate_mhz)
    tp, tmin, tmax = t.timer
    if not 0 <= t.latency < t.period:
        raise TableError("latency %d us outside [0, period)" % t.latency)
    if not (tp > 0 and 0 <= tmin <= tmax and 2 * tmax < tp):
        raise TableError("timer: period %d us, cost %d..%d us (need 0 <= min <= max < period / 2)" % t.timer)
    for i, k in enumerate(t.tasks):
        if not 0 <= k.cmin <= k.cmax:
            raise TableError("entry %d (%s): cost range %d..%d" % (i, k.name, k.cmin, k.cmax))
        if k.cmax + tmax * rounds_in_run(t, k.cmax) > k.budget:
            raise TableError("entry %d (%s): dishonest budget: %d us < worst-case cost %d us + %d "
                             "timer rounds of %d us" % (i, k.name, k.budget, k.cmax,
                                                       rounds_in_run(t, k.cmax), tmax))


def rounds_in_run(t, cost):
    """Most timer rounds one run of `cost` us can be pre-empted by: n rounds stretch it to
    at most cost + n tmax, and n rounds need (n - 1) periods inside it."""
    tp, _, tmax = t.timer
    return 1 + (cost + tmax) // (tp - tmax)


def lcm_all(xs):
    r = 1
    for x in xs:
        r = r * x // math.gcd(r, x)
    return r


class TickModel:
    """Z3 encoding of one scan of mt_sched_run() with the timing model."""

    def __init__(self, table, name, max_extra):
        self.t = table
        self.name = name
        tp, tmin, tmax = table.timer
        # A sound bound on the end of any tick: fast tasks run whatever is left, a normal
        # task starts only while time is left (<= period + extra after the scan start),
        # each run is stretched by at most ceil(run / (tp - tmax)) + 1 timer rounds.
        fast = sum(k.cmax for k in table.tasks if k.fast)
        longest = max([k.cmax for k in table.tasks if not k.fast] + [0])
        span = table.latency + tmax + max(fast, table.period + max_extra) + longest
        bound = span + tmax * (span // (tp - tmax) + 2)
        self.rounds = bound // tp + 2  # rounds that can start inside a tick, with margin
        self.vars = {}

    def build(self, s, tick, due_of, avail_extra):
        """Constrain one tick into solver s. due_of(i) -> Bool (normal tasks);
        avail_extra: Int extra time. Returns a dict of the tick's terms."""
        t = self.t
        tp, tmin, tmax = t.timer
        P = t.period
        nm = "%s_%s" % (self.name, tick)
        terms = {"run": [], "skip": [], "exec": [], "avail": [], "wend": None}
        w0 = z3.Int("w0_" + nm)
        lat = z3.Int("lat_" + nm)              # wake-up latency and work in the sample wait
        s.add(lat >= 0, lat <= t.latency)
        phase = z3.Int("phase_" + nm)          # first timer round at or after the wake-up
        carry_c = z3.Int("carry_" + nm)        # cost of the round before the sample
        s.add(phase >= 0, phase < tp, carry_c >= tmin, carry_c <= tmax)
        rc = []
        for m in range(self.rounds):
            c = z3.Int("round%d_%s" % (m, nm))
            s.add(c >= tmin, c <= tmax)
            rc.append(c)
        d = [lat + phase + m * tp for m in range(self.rounds)]
        # the scan starts after the latency, later still if a timer round that started
        # before then is still running
        s.add(w0 == lat + z3.If(phase - tp + carry_c > 0, phase - tp + carry_c, 0))
        terms["phase"] = phase
        ta = z3.Int("ta_" + nm)
        s.add(ta == z3.If(w0 >= P, 0, P - w0) + avail_extra)
        terms["w0"] = w0
        terms["ta"] = ta
        w = w0
        for i, k in enumerate(t.tasks):
            e = z3.Int("e%d_%s" % (i, nm))
            s.add(e >= k.cmin, e <= k.cmax)
            avail = z3.If(w - w0 >= ta, 0, ta - (w - w0))
            av = z3.Int("av%d_%s" % (i, nm))
            s.add(av == avail)
            if k.fast:
                run = z3.BoolVal(True)
                skip = z3.BoolVal(False)
            else:
                due = due_of(i)
                fits = k.budget <= av
                run = z3.Bool("run%d_%s" % (i, nm))
                skip = z3.Bool("skip%d_%s" % (i, nm))
                s.add(run == z3.And(due, fits), skip == z3.And(due, z3.Not(fits)))
            wn = z3.Int("wt%d_%s" % (i, nm))
            # the SITL's spend: the rounds that fall due while work is left are served
            # inside the run; end: when the work left reaches 0 (named terms keep it linear)
            end = w + e
            for m in range(self.rounds):
                served = z3.And(d[m] >= w, d[m] < end)
                nend = z3.Int("end%d_%d_%s" % (i, m, nm))
                s.add(nend == z3.If(served, end + rc[m], end))
                end = nend
            s.add(wn == z3.If(run, end, w))
            w = wn
            terms["run"].append(run)
            terms["skip"].append(skip)
            terms["exec"].append(e)
            terms["avail"].append(av)
        terms["wend"] = w
        terms["left"] = z3.If(w - w0 >= ta, 0, ta - (w - w0))
        return terms


def aligned_check(table, deadline_s):
    """Analysis 1: a symbolic tick of the aligned schedule."""
    t = table
    normal = [k for k in t.tasks if not k.fast]
    H = lcm_all([k.interval for k in normal]) if normal else 1
    s = z3.Solver()
    s.set("timeout", int(deadline_s * 1000))
    k = z3.Int("k")
    s.add(k >= 1, k <= H)
    model = TickModel(t, "al", 0)

    def due_of(i):
        return k % t.tasks[i].interval == 0

    terms = model.build(s, "a", due_of, 0)
    out = {"hyperperiod": H}
    # (a) can any task be skipped?
    s.push()
    s.add(z3.Or(*terms["skip"]) if terms["skip"] else z3.BoolVal(False))
    r = s.check()
    if r == z3.unknown:
        raise TableError("Z3 gave up on the aligned check (%s)" % s.reason_unknown())
    out["skip_possible"] = r == z3.sat
    if r == z3.sat:
        m = s.model()
        out["witness"] = tick_row(t, m, terms, m.eval(k).as_long())
    s.pop()
    # (b) worst-case end of the fast loop (maximised on the fast tasks alone: they come first)
    nfast = sum(1 for x in t.tasks if x.fast)
    fs = z3.Solver()
    fs.set("timeout", int(deadline_s * 1000))
    fterms = TickModel(prefix(t, nfast), "fa", 0).build(fs, "a", lambda i: z3.BoolVal(False), 0)
    out["fast_max"] = maximise(fs, fterms["wend"], 0, wall_bound(t, sum(x.cmax for x in t.tasks if x.fast)))
    return out


def maximise(s, term, lo, hi):
    """Largest value of an Int term under s (binary search; term is bounded by hi)."""
    s.push()
    s.add(term >= lo)
    if s.check() != z3.sat:
        s.pop()
        return None
    best = s.model().eval(term).as_long()
    s.pop()
    lo = best + 1
    while lo <= hi:
        mid = (lo + hi) // 2
        s.push()
        s.add(term >= mid)
        r = s.check()
        if r == z3.sat:
            best = s.model().eval(term).as_long()
            lo = best + 1
        elif r == z3.unsat:
            hi = mid - 1
        else:
            s.pop()
            raise TableError("Z3 gave up while maximising (%s)" % s.reason_unknown())
        s.pop()
    return best


def tick_row(t, m, terms, k):
    ran, skipped = [], []
    for i, x in enumerate(t.tasks):
        if z3.is_true(m.eval(terms["run"][i])):
            ran.append("%s(%d)" % (x.name, m.eval(terms["exec"][i]).as_long()))
        if z3.is_true(m.eval(terms["skip"][i])):
            skipped.append("%s(%d>%d)" % (x.name, x.budget, m.eval(terms["avail"][i]).as_long()))
    phase = None if terms["phase"] is None else m.eval(terms["phase"]).as_long()
    return {"tick": k, "phase": phase, "w0": m.eval(terms["w0"]).as_long(),
            "available": m.eval(terms["ta"]).as_long(), "end": m.eval(terms["wend"]).as_long(),
            "ran": ran, "skipped": skipped}


def wall_bound(table, work):
    """Upper bound of the time from the sample to the end of `work` us of task execution:
    the scan starts at most one timer round late, and the rounds that start in [0, W)
    number at most W / tp + 1, so W <= 2 tmax + work + tmax W / tp."""
    tp, _, tmax = table.timer
    return table.latency + ((2 * tmax + work) * tp + (tp - tmax) - 1) // (tp - tmax)


def all_fit(table, due_mask, extra):
    """Arithmetic fast path: every due task fits even in the worst case (all costs at their
    maximum, the most pre-emption), and the tick ends within the period. Then the only
    outcome is "every due task runs" and no query is needed."""
    work = 0
    for i, k in enumerate(table.tasks):
        if k.fast or due_mask >> i & 1:
            if not k.fast and k.budget > table.period + extra - wall_bound(table, work):
                return False
            work += k.cmax
    return wall_bound(table, work) <= table.period


def prefix(table, n):
    """The table's first n tasks (same loop and timer)."""
    p = Table()
    p.loop_hz, p.timer, p.path, p.tasks = table.loop_hz, table.timer, table.path, table.tasks[:n]
    p.latency = table.latency
    return p


class Oracle:
    """Z3 decides one tick of a (prefix) table: for a due set, which run/skip outcomes
    some execution (costs, timer phase, round costs) produces. The extra time is 0 for
    the outcomes (the explorations' assumption) and free for can_skip."""

    def __init__(self, table, deadline_s):
        self.t = table
        self.s = z3.Solver()
        self.timeout_ms = int(deadline_s * 1000)
        self.s.set("timeout", self.timeout_ms)
        self.extra = z3.Int("extra")
        self.due = [None if k.fast else z3.Bool("due%d" % i) for i, k in enumerate(table.tasks)]
        self.s.add(self.extra == 0)  # the per-task analysis runs without extra time (see S3)
        self.terms = TickModel(table, "or", 0).build(self.s, "x", lambda i: self.due[i], self.extra)
        self.cache = {}
        self.queries = 0
        self.fast_path = 0

    def check(self):
        self.queries += 1
        r = self.s.check()
        if r == z3.unknown:
            raise TableError("Z3 gave up on a tick (%s)" % self.s.reason_unknown())
        return r == z3.sat

    def can_skip(self, i):
        """Can task i be skipped in some tick, whatever the earlier tasks' due states (extra
        time 0)? Returns an example tick or None."""
        s = self.s
        s.push()
        s.add(self.extra == 0, self.due[i], self.terms["skip"][i])
        row = tick_row(self.t, s.model(), self.terms, 0) if self.check() else None
        s.pop()
        return row

    def can_skip_run(self, i, k):
        """Can task i be skipped in k consecutive ticks, from any state (every task's ticks
        since its last run arbitrary) of the prefix? The k ticks are chained exactly
        (a task that runs has waited 1 tick at the next one). Returns a bool."""
        t = self.t
        s = z3.Solver()
        s.set("timeout", self.timeout_ms)
        gaps = []
        for j, x in enumerate(t.tasks):
            g = z3.Int("g%d" % j)
            s.add(g >= 1)
            gaps.append(g)
        model = TickModel(t, "r", 0)
        for tick in range(k):
            cur = list(gaps)
            terms = model.build(s, tick, lambda j, cur=cur: cur[j] >= t.tasks[j].interval, 0)
            s.add(terms["skip"][i])
            gaps = [z3.If(terms["run"][j], 1, cur[j] + 1) if not x.fast else cur[j]
                    for j, x in enumerate(t.tasks)]
        self.queries += 1
        r = s.check()
        if r == z3.unknown:
            raise TableError("Z3 gave up on %d ticks of skips (%s)" % (k, s.reason_unknown()))
        return r == z3.sat

    def outcomes(self, due_mask):
        """[(run_mask, example_row)] for the due set (bit i: task i due), extra time 0."""
        if due_mask in self.cache:
            return self.cache[due_mask]
        t, s, terms = self.t, self.s, self.terms
        if all_fit(t, due_mask, 0):
            self.fast_path += 1
            self.cache[due_mask] = [(due_mask, None)]
            return self.cache[due_mask]
        s.push()
        s.add(self.extra == 0)
        for i, k in enumerate(t.tasks):
            if not k.fast:
                s.add(self.due[i] == bool(due_mask >> i & 1))
        found = []
        while self.check():
            m = s.model()
            run = 0
            for i, k in enumerate(t.tasks):
                if not k.fast and z3.is_true(m.eval(terms["run"][i])):
                    run |= 1 << i
            found.append((run, tick_row(t, m, terms, 0)))
            s.add(z3.Or([terms["run"][i] != bool(run >> i & 1)
                         for i, k in enumerate(t.tasks) if not k.fast and due_mask >> i & 1]
                        or [z3.BoolVal(False)]))
        s.pop()
        self.cache[due_mask] = found
        return found


class Explorer:
    """Every reachable state of a (prefix) table from start-up, extra time 0, each tick's
    outcomes decided by the oracle. State: for each task the ticks since its last run
    before the scan (tick - last_run), capped at 4 intervals."""

    def __init__(self, table, oracle, max_states):
        self.t, self.o = table, oracle
        t = table
        n = len(t.tasks)
        self.normal = [i for i, k in enumerate(t.tasks) if not k.fast]
        self.iv = [k.interval for k in t.tasks]
        self.cap = [4 * k.interval for k in t.tasks]
        init = tuple(1 for _ in range(n))  # tick 1: 1 - last_run 0
        self.index = {init: 0}
        self.states = [init]
        self.succ = []
        self.parent = [None]
        self.late_run = None  # a reachable run 4 intervals late (extra time would grow)
        q = 0
        while q < len(self.states):
            gaps = self.states[q]
            due = 0
            for i in self.normal:
                if gaps[i] >= self.iv[i]:
                    due |= 1 << i
            edges = []
            for run, row in oracle.outcomes(due):
                if self.late_run is None and any(run >> i & 1 and gaps[i] >= SLOWDOWN * self.iv[i]
                                                 for i in self.normal):
                    self.late_run = q
                ng = tuple(1 if (run >> i & 1) else min(gaps[i] + 1, self.cap[i]) for i in range(n))
                j = self.index.get(ng)
                if j is None:
                    if len(self.states) >= max_states:
                        raise TableError("more than %d states" % max_states)
                    j = len(self.states)
                    self.index[ng] = j
                    self.states.append(ng)
                    self.parent.append((q, run, row))
                edges.append((j, run))
            if not edges:
                raise TableError("internal: a tick with no outcome")
            self.succ.append(edges)
            q += 1

    def missed(self, i):
        """States in which task i is two releases behind (a slip counted or pending)."""
        return [k for k, g in enumerate(self.states) if g[i] >= 2 * self.iv[i]]

    def can_avoid(self, bad):
        """Per state: can some run from it avoid `bad` forever? (greatest fixpoint)"""
        bad = set(bad)
        alive = [k not in bad for k in range(len(self.states))]
        changed = True
        while changed:
            changed = False
            for k in range(len(self.states)):
                if alive[k] and not any(alive[j] for j, _ in self.succ[k]):
                    alive[k] = False
                    changed = True
        return alive

    def latest_entry(self, bad):
        """When every run enters `bad`: the latest tick of the first entry."""
        bad = set(bad)
        memo = {}
        stack = [(0, False)]
        while stack:
            k, done = stack.pop()
            if k in bad:
                memo[k] = 0
            elif done:
                memo[k] = 1 + max(memo[j] for j, _ in self.succ[k])
            elif k not in memo:
                stack.append((k, True))
                stack.extend((j, False) for j, _ in self.succ[k] if j not in memo)
        return memo[0] + 1  # ticks count from 1

    def lateness(self, i):
        """Worst lateness of task i (ticks from a release to its run) and whether it is
        unbounded (a reachable run of the prefix never runs it again)."""
        worst = max([g[i] - self.iv[i] for g in self.states if g[i] >= self.iv[i]] + [0])
        capped = [k for k, g in enumerate(self.states) if g[i] >= self.cap[i]]
        if not capped:
            return worst, False
        alive = {k: True for k in capped}
        changed = True
        while changed:
            changed = False
            for k in capped:
                if alive[k] and not any(alive.get(j, False) and not run >> i & 1 for j, run in self.succ[k]):
                    alive[k] = False
                    changed = True
        return worst, any(alive.values())

    def path_to(self, target):
        rows = []
        k = target
        while self.parent[k] is not None:
            rows.append(self.parent[k])
            k = self.parent[k][0]
        rows.reverse()
        return rows


def fmt_row(r):
    ran = " ".join(r["ran"]) if r["ran"] else "-"
    sk = " ".join(r["skipped"]) if r["skipped"] else "-"
    if r.get("phase") is None:
        return "  tick %5d: ran %s" % (r["tick"], ran)
    return ("  tick %5d: timer phase %d us, scan starts %d us after the sample, %d us available, "
            "ends at %d us\n              ran (us): %s\n              skipped (budget > time left): %s"
            % (r["tick"], r["phase"], r["w0"], r["available"], r["end"], ran, sk))


def analyse(t, args, out):
    """The per-task analysis (2). Returns (rows, witness, extra_ok)."""
    rows = {}
    witness = None
    extra_ok = True
    undecided = []
    for i, k in enumerate(t.tasks):
        if k.fast:
            continue
        pre = prefix(t, i + 1)
        # arithmetic first: even with every earlier task running at its worst-case cost (more
        # work only ends later), the time left before task i fits its budget
        if k.budget <= t.period - wall_bound(t, sum(x.cmax for x in t.tasks[:i])):
            rows[i] = ("never", 0, False, None, "meets its rate: never skipped (worst-case sum)")
            continue
        oracle = Oracle(pre, args.timeout)
        if oracle.can_skip(i) is None:
            rows[i] = ("never", 0, False, None, "meets its rate: never skipped (Z3, any due state)")
            continue
        # skipped k ticks in a row from any state? A miss needs `interval` of them.
        bound = None
        for run in range(2, min(k.interval, MAX_SKIP_RUN) + 1):
            if not oracle.can_skip_run(i, run):
                bound = run - 1
                break
        if bound is not None:
            rows[i] = ("never", bound, False, None, "meets its rate: never skipped %d ticks in a row "
                       "(Z3, any state), so at most %d tick%s late" % (bound + 1, bound, "" if bound == 1 else "s"))
            continue
        try:
            ex = Explorer(pre, oracle, args.max_states)
        except TableError as e:
            undecided.append(i)
            rows[i] = ("undecided", None, False, None, "undecided: %s in the state search" % e)
            continue
        if ex.late_run is not None:
            extra_ok = False
        bad = ex.missed(i)
        late, unbounded = ex.lateness(i)
        info = "%d states, %d ticks decided by Z3" % (len(ex.states), len(oracle.cache) - oracle.fast_path)
        if not bad:
            rows[i] = ("never", late, False, None, "meets its rate: never misses a release (%s)" % info)
            continue
        if ex.can_avoid(bad)[0]:
            rows[i] = ("may", late, unbounded, None, "MAY miss releases (%s)" % info)
        else:
            by = ex.latest_entry(bad)
            rows[i] = ("must", late, unbounded, by, "MUST miss releases, on every execution by tick %d "
                       "(%s)" % (by, info))
        if witness is None:
            target = min(bad)  # breadth-first: the earliest
            path = ex.path_to(target)
            sched = []
            for n, (q, run, row) in enumerate(path, 1):
                if row is None:  # decided by the worst-case sum: every due task ran
                    row = {"phase": None, "ran": [pre.tasks[j].name for j in range(len(pre.tasks))
                                                   if pre.tasks[j].fast or run >> j & 1], "skipped": []}
                r = dict(row)
                r["tick"] = n
                sched.append(r)
            witness = (k.name, len(path) + 1, sched)
    if not extra_ok:
        for i, r in list(rows.items()):
            rows[i] = ("undecided", r[1], r[2], None, r[4] + "; but a task can run 4 intervals late, "
                       "so the extra loop time can grow, which this verdict did not model")
    return rows, witness, extra_ok


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("table")
    ap.add_argument("--json", help="write the verdicts as JSON to this file")
    ap.add_argument("--timeout", type=float, default=60.0, help="Z3 time limit per query, seconds")
    ap.add_argument("--max-states", type=int, default=500000, help="state search limit per task")
    args = ap.parse_args(argv)
    t0 = time.time()
    try:
        t = parse(args.table)
        validate(t)
    except (OSError, TableError) as e:
        sys.stderr.write("sched-check: %s\n" % e)
        return 2
    P = t.period
    tp, tmin, tmax = t.timer
    nfast = sum(1 for k in t.tasks if k.fast)
    print("sched-check: %s (Z3 %s)" % (t.path, z3.get_version_string()))
    print("loop %d Hz (period %d us), %d tasks (%d fast), timer procs every %d us taking %d..%d us%s"
          % (t.loop_hz, P, len(t.tasks), nfast, tp, tmin, tmax,
             (", scan starts up to %d us after the sample" % t.latency) if t.latency else ""))
    result = {"table": t.path, "loop_hz": t.loop_hz, "period_us": P, "tasks": []}
    try:
        al = aligned_check(t, args.timeout)
        H = al["hyperperiod"]
        print("hyperperiod %d ticks (%.1f s)" % (H, H / t.loop_hz))
        print("Z3, worst case: the fast loop ends %d us after the sample (period %d)" % (al["fast_max"], P))
        fast_ok = al["fast_max"] <= P
        if not al["skip_possible"]:
            print("Z3, one symbolic tick of the hyperperiod with every release on time: no task can be "
                  "skipped,\n  so by induction every release is served at its own tick, forever")
            rows = {i: ("never", 0, False, None, "meets its rate (proved for all ticks)")
                    for i, k in enumerate(t.tasks) if not k.fast}
            witness, extra_ok = None, True
        else:
            w = al["witness"]
            print("Z3, one symbolic tick of the hyperperiod with every release on time: tick %d can skip "
                  "%s;\n  each task is decided on its prefix of the table:" % (w["tick"], ", ".join(w["skipped"])))
            rows, witness, extra_ok = analyse(t, args, result)
    except TableError as e:
        sys.stderr.write("sched-check: %s\n" % e)
        return 2
    result.update({"hyperperiod": H, "fast_end_max_us": al["fast_max"],
                   "aligned_skip_possible": al["skip_possible"], "extra_stays_zero": extra_ok})
    ok = fast_ok and all(r[0] == "never" for r in rows.values())
    print("%-16s %7s %5s %6s %9s  %s" % ("task", "rate_hz", "ticks", "budget", "lateness", "verdict"))
    for i, k in enumerate(t.tasks):
        if k.fast:
            verdict, late, unb, by = ("never" if fast_ok else "must"), 0, False, None
            text = ("runs every tick; no tick runs past the period" if fast_ok else
                    "the fast loop alone can run past the period: samples are lost")
        else:
            verdict, late, unb, by, text = rows[i]
        upper = False
        upper = "at most" in text
        lat = "unbounded" if unb else ("?" if late is None else ("<=%d" if upper else "%d") % late)
        print("%-16s %7s %5d %6d %9s  %s" % (k.name, "fast" if k.fast else str(k.rate_hz), k.interval,
                                            k.budget, lat, text))
        result["tasks"].append({"name": k.name, "interval": k.interval, "budget": k.budget, "miss": verdict,
                                "lateness_ticks": late, "lateness_is_bound": upper, "lateness_unbounded": unb,
                                "must_by_tick": by})
    if witness is not None:
        name, first, sched = witness
        print("counterexample: an execution in which %s falls two releases behind at tick %d "
              "(ticks with a skip):" % (name, first))
        shown = [r for r in sched if r["skipped"]]
        if len(shown) > 8:
            shown = shown[:5] + [None] + shown[-2:]
        for r in shown:
            print("  ..." if r is None else fmt_row(r))
        result["counterexample"] = {"task": name, "tick": first, "schedule": sched}
    result["schedulable"] = ok
    result["seconds"] = round(time.time() - t0, 2)
    print("verdict: %s (%.1f s)" % ("SCHEDULABLE" if ok else "NOT SCHEDULABLE", time.time() - t0))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(result, f, indent=1)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
