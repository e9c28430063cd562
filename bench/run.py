#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Metronome benchmark driver (`make bench`): see bench/README.md.

Runs the programs built by bench/bench.mk, in this order:
  1. callgrind entries (exact instruction counts; two at a time),
  2. wall-clock benchmarks (interleaved rounds, medians with min/max; alone),
  3. Cortex-M4 code size, disassembly counts and RAM per object,
  4. the proof-suite timing row (if another target has produced it),
then prints one table (also written to BUILD/bench/results.txt) and writes
BUILD/bench/results.json. Targets are reported as PASS/FAIL, never enforced:
the exit status is non-zero only when the harness itself breaks.
"""
import argparse
import concurrent.futures
import datetime
import glob
import hashlib
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# ------------------------------------------------------------------ anchors
# Figures quoted from shared/reference/performance.md (measured there on a
# different VM; shown next to ours, never used as the gate's peer).
ANCHOR = {
    "ring_boost_net": 18.3,
    "ring_ap_net": 272.3,
    "sched_ap": {("mix", 8): 239, ("idle", 8): 164, ("mix", 32): 803, ("idle", 32): 525,
                 ("mix", 255): 5856, ("idle", 255): 3884},
    "timers_fixed": 89, "timers_per_proc": 12,
    "sem_posix": 38.0, "sem_bsem": 152.0,
    "m4_plain_push": 46, "m4_plain_pop": 46, "m4_static_cached_pushpop": 112,
    "m4_sched_run_ap": 188,
    "chibios_ram": {"semaphore": 12, "queue": 36, "thread": 68, "mutex": 16, "timer": 20},
}

ARM_CC = "arm-none-eabi-gcc"
ARM_FLAGS = ["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16", "-Os",
             "-ffunction-sections", "-fdata-sections", "-std=c11"]
KINC = ["-Ikernel/include", "-Ikernel/port", "-Ikernel/spec"]

HOT = ["mt_oring_push", "mt_oring_pop", "mt_bring_write", "mt_bring_read", "mt_sched_tick",
       "mt_sched_run", "mt_sched_end_loop", "mt_proc_dispatch", "mt_sem_wait_s", "mt_sem_signal_i",
       "mt_sem_wait", "mt_sem_signal"]


class HarnessError(Exception):
    pass


def log(msg):
    print(f"bench: {msg}", file=sys.stderr, flush=True)


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT, **kw)


def env_int(name, default, minimum):
    v = os.environ.get(name, "")
    try:
        x = int(float(v)) if v.strip() else default
    except ValueError:
        raise HarnessError(f"{name}={v!r} is not a number")
    return max(minimum, x)


def parse_results(text):
    out = {}
    for line in text.splitlines():
        if line.startswith("RESULT "):
            parts = line.split()
            out[parts[1]] = parts[2:]
    return out


# ---------------------------------------------------------------- machine
def machine_info(build):
    info = {}
    p = run(["lscpu"])
    for line in p.stdout.splitlines():
        k, _, v = line.partition(":")
        k, v = k.strip(), v.strip()
        if k in ("Model name", "CPU(s)", "Thread(s) per core", "Core(s) per socket", "Socket(s)",
                 "Hypervisor vendor", "Architecture"):
            info[k] = v
    info["gcc"] = run(["gcc", "--version"]).stdout.splitlines()[0]
    info["valgrind"] = run(["valgrind", "--version"]).stdout.strip()
    b = run(["dpkg-query", "-W", "-f=${Version}", "libboost-dev"])
    info["boost"] = b.stdout.strip() if b.returncode == 0 else "?"
    try:
        with open("/proc/loadavg") as f:
            info["loadavg_start"] = " ".join(f.read().split()[:3])
    except OSError:
        info["loadavg_start"] = "?"
    g = run(["git", "rev-parse", "--short", "HEAD"])
    info["commit"] = g.stdout.strip() if g.returncode == 0 else "no commit"
    d = run(["git", "status", "--porcelain", "--", "kernel", "hal_posix"])
    info["kernel_tree_dirty"] = bool(d.stdout.strip()) if d.returncode == 0 else None
    h = hashlib.sha256()
    for f in sorted(glob.glob(os.path.join(ROOT, "kernel", "*", "*.[ch]")) +
                    glob.glob(os.path.join(ROOT, "kernel", "include", "mt", "*.h")) +
                    glob.glob(os.path.join(ROOT, "hal_posix", "*.[ch]"))):  # one sorted list
        with open(f, "rb") as fh:
            h.update(os.path.relpath(f, ROOT).encode() + b"\0" + fh.read())
    info["kernel_sources_sha256"] = h.hexdigest()[:16]
    info["date"] = datetime.datetime.now().isoformat(timespec="seconds")
    info["flags_host"] = "-O2 -g (gcc/g++, same for Metronome and every peer)"
    return info


# -------------------------------------------------------------- callgrind
def cg_job(build, binary, entry, n, args, tag):
    out = os.path.join(build, "bench", "cg", tag + ".cg")
    cmd = ["valgrind", "--tool=callgrind", f"--toggle-collect={entry}", f"--callgrind-out-file={out}",
           os.path.join(build, "bench", binary), "cg", entry, str(n)] + [str(a) for a in args]
    p = run(cmd)
    if p.returncode != 0:
        raise HarnessError(f"{' '.join(cmd)} failed:\n{p.stdout}\n{p.stderr[-2000:]}")
    ir = None
    with open(os.path.join(ROOT, out)) as f:
        for line in f:
            if line.startswith("summary:") or line.startswith("totals:"):
                ir = int(line.split()[1])
                break
    if ir is None:
        raise HarnessError(f"no summary in {out}")
    res = parse_results(p.stdout).get(entry, [])
    calls = int(res[2]) if len(res) >= 3 and res[1] == "calls" else None
    return {"tag": tag, "binary": binary, "entry": entry, "n": n, "args": list(map(str, args)),
            "ir": ir, "per_op": ir / n, "calls": calls,
            "command": " ".join(cmd[:4]) + " " + " ".join(cmd[4:])}


def callgrind_phase(build):
    os.makedirs(os.path.join(ROOT, build, "bench", "cg"), exist_ok=True)
    jobs = []
    ring_n = 1_000_000  # multiple of 64 (push 64 / pop 64 batches)
    for e in ("base", "mt", "mtw", "boost", "boostrt", "ap"):
        jobs.append(("bench_ring", f"bench_ring_{e}", ring_n, [], f"ring_{e}"))
    for size in (1, 64):
        for e in ("mt", "boost", "ap"):
            jobs.append(("bench_ring", f"bench_bytes_{e}_{size}", 100_000, [], f"bytes_{e}_{size}"))
    ticks = 4000  # 10 s at 400 Hz: whole periods of every rate in the sets
    for ntask in (8, 32, 255):
        binary = "kernel_stub255" if ntask == 255 else "kernel_stub"
        for tset in ("mix", "idle"):
            for impl in ("mt", "ap"):
                jobs.append((binary, f"bench_sched_{impl}", ticks, [tset, ntask], f"sched_{impl}_{tset}_{ntask}"))
    for tset in ("mix", "idle"):
        jobs.append(("kernel_posix", "bench_sched_mt", ticks, [tset, 8], f"schedposix_mt_{tset}_8"))
    for nproc in range(1, 9):
        for impl in ("mt", "ap"):
            jobs.append(("kernel_stub", f"bench_proc_{impl}", 100_000, [nproc], f"proc_{impl}_{nproc}"))
    for impl in ("mt", "posix", "bsem"):
        jobs.append(("kernel_posix", f"bench_sem_{impl}", 100_000, [], f"sem_{impl}"))
    jobs.append(("kernel_stub", "bench_sem_mt", 100_000, [], "semstub_mt"))

    results = {}
    workers = max(1, min(2, os.cpu_count() or 1))
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as ex:
        futs = [ex.submit(cg_job, build, *j) for j in jobs]
        for f in futs:
            r = f.result()
            results[r["tag"]] = r
    return results


# ------------------------------------------------------------- wall clock
def series(res, key):
    v = res.get(key)
    if v is None:
        raise HarnessError(f"missing result {key}")
    return {"median": float(v[0]), "min": float(v[1]), "max": float(v[2]),
            "samples": [float(x) for x in v[3].split(",")]}


def paired_ratio(a, b):
    r = [x / y for x, y in zip(a["samples"], b["samples"]) if y > 0]
    return statistics.median(r) if r else None


def wallclock_phase(build):
    out = {}
    binary = os.path.join(build, "bench", "bench_ring")
    rounds = env_int("BENCH_ROUNDS", 21, 3)
    ap_div = env_int("BENCH_AP_DIV", 10, 1)
    # throughput: calibrate, then fit the default 1e8 items into the budget;
    # bench_ring also rescales the items of later rounds if the machine slows down
    budget = env_int("BENCH_BUDGET_S", 180, 10)
    rtt_budget = env_int("BENCH_RTT_BUDGET_S", 60, 5)
    env = dict(os.environ, BENCH_AP_DIV=str(ap_div), BENCH_TPUT_BUDGET_S=str(budget),
               BENCH_RTT_BUDGET_S=str(rtt_budget))
    user_items = os.environ.get("BENCH_ITEMS", "").strip()
    items = env_int("BENCH_ITEMS", 100_000_000, 64_000)
    cal_items = 2_000_000
    t0 = time.time()
    p = run([binary, "tput", str(cal_items), "1", "mt,mtw,boost,ap"], env=env)
    if p.returncode != 0:
        raise HarnessError(f"throughput calibration failed: {p.stderr}")
    per_item = (time.time() - t0) / cal_items
    capped = False
    fit = int(budget / (per_item * rounds) / 1_000_000) * 1_000_000
    if fit < items:
        items, capped = max(fit, 1_000_000), True
    log(f"throughput: {items} items x {rounds} rounds (AP reference {items // ap_div} items), "
        f"budget {budget} s")
    t0 = time.time()
    p = run([binary, "tput", str(items), str(rounds), "mt,mtw,boost,ap"], env=env)
    if p.returncode != 0:
        raise HarnessError(f"throughput run failed: {p.stderr}")
    res = parse_results(p.stdout)
    nused = [int(float(x)) for x in res.get("tput.n", [items, items, items, 0])[:3]]
    if nused[1] < items:
        capped = True
    tp = {v: series(res, f"tput.{v}") for v in ("mt", "mtw", "boost", "ap")}
    tps = {v: series(res, f"tput_steady.{v}") for v in ("mt", "mtw", "boost", "ap")}
    out["tput"] = {"items": items, "items_min": nused[1], "items_max": nused[2], "ap_items": items // ap_div,
                   "user_items": bool(user_items), "rounds": rounds, "capped_by_budget": capped,
                   "budget_s": budget, "seconds": round(time.time() - t0, 1),
                   "pinned": res.get("tput.pinned", ["0"])[0] == "1", "ops_per_s": tp,
                   "ratio_mt_boost": tp["mt"]["median"] / tp["boost"]["median"],
                   "ratio_mt_ap": tp["mt"]["median"] / tp["ap"]["median"],
                   "paired_ratio_mt_boost": paired_ratio(tp["mt"], tp["boost"]),
                   "paired_ratio_mtw_boost": paired_ratio(tp["mtw"], tp["boost"]),
                   "steady_ratio_mtw_boost": tps["mtw"]["median"] / tps["boost"]["median"],
                   "paired_ratio_mt_ap": paired_ratio(tp["mt"], tp["ap"]),
                   "steady_ops_per_s": tps,
                   "steady_ratio_mt_boost": tps["mt"]["median"] / tps["boost"]["median"],
                   "steady_ratio_mt_ap": tps["mt"]["median"] / tps["ap"]["median"]}

    # round trip
    rtt_n = env_int("BENCH_RTT", 100_000, 1000)
    log(f"round trip: {rtt_n} round trips x {rounds} rounds")
    t0 = time.time()
    p = run([binary, "rtt", str(rtt_n), str(rounds), "bare,mt,boost,ap"], env=env)
    if p.returncode != 0:
        raise HarnessError(f"round-trip run failed: {p.stderr}")
    res = parse_results(p.stdout)
    rn = [int(float(x)) for x in res.get("rtt.n", [rtt_n, rtt_n, rtt_n, 0])[:3]]
    rt = {v: series(res, f"rtt.{v}") for v in ("bare", "mt", "boost", "ap")}
    rts = {v: series(res, f"rtt_steady.{v}") for v in ("bare", "mt", "boost", "ap")}
    out["rtt"] = {"roundtrips": rtt_n, "roundtrips_min": rn[1], "rounds": rounds, "seconds": round(time.time() - t0, 1),
                  "pinned": res.get("rtt.pinned", ["0"])[0] == "1", "ns": rt,
                  "ratio_mt_bare": rt["mt"]["median"] / rt["bare"]["median"],
                  "ratio_boost_bare": rt["boost"]["median"] / rt["bare"]["median"],
                  "ratio_ap_bare": rt["ap"]["median"] / rt["bare"]["median"],
                  "paired_ratio_mt_bare": paired_ratio(rt["mt"], rt["bare"]),
                  "steady_ns": rts,
                  "steady_ratio_mt_bare": rts["mt"]["median"] / rts["bare"]["median"],
                  "steady_ratio_boost_bare": rts["boost"]["median"] / rts["bare"]["median"]}

    # semaphores, one thread
    pairs = 200_000
    log(f"semaphores: {pairs} pairs x {rounds} rounds")
    p = run([os.path.join(build, "bench", "kernel_posix"), "semwall", str(pairs), str(rounds)])
    if p.returncode != 0:
        raise HarnessError(f"semaphore wall-clock run failed: {p.stderr}")
    res = parse_results(p.stdout)
    sw = {v: series(res, f"semwall.{v}") for v in ("mt", "posix", "bsem")}
    out["sem"] = {"pairs": pairs, "rounds": rounds, "ns": sw,
                  "ratio_mt_posix": sw["mt"]["median"] / sw["posix"]["median"],
                  "ratio_mt_bsem": sw["mt"]["median"] / sw["bsem"]["median"]}
    return out


# ------------------------------------------------------------ Cortex-M4
def parse_objdump(text):
    """Function name -> {'insns': [mnemonic], 'calls': [symbol]} from objdump -dr."""
    funcs = {}
    cur = None
    for line in text.splitlines():
        m = re.match(r"^[0-9a-f]+ <([^>]+)>:$", line)
        if m:
            cur = funcs.setdefault(m.group(1), {"insns": [], "calls": []})
            continue
        if cur is None:
            continue
        m = re.match(r"^\s+[0-9a-f]+:\s+(R_ARM_\w+)\s+(\S+)", line)
        if m:
            if m.group(1) in ("R_ARM_THM_CALL", "R_ARM_THM_JUMP24", "R_ARM_THM_JUMP19", "R_ARM_CALL",
                              "R_ARM_JUMP24"):
                cur["calls"].append(m.group(2))
            continue
        m = re.match(r"^\s+[0-9a-f]+:\s+([a-z][\w.]*)", line)
        if m:
            cur["insns"].append(m.group(1))
    return funcs


def section_sizes(obj):
    p = run(["arm-none-eabi-size", "-A", obj])
    sizes = {}
    for line in p.stdout.splitlines():
        parts = line.split()
        if len(parts) >= 2 and parts[0].startswith(".text.") and parts[1].isdigit():
            sizes[parts[0][len(".text."):]] = int(parts[1])
    return sizes


def fn_closure(name, funcs):
    seen, todo = [], [name]
    while todo:
        f = todo.pop()
        if f in seen or f not in funcs:
            continue
        seen.append(f)
        todo.extend(funcs[f]["calls"])
    return seen


def fn_stats(name, funcs, sizes):
    cl = fn_closure(name, funcs)
    insns = [i for f in cl for i in funcs[f]["insns"]]
    ext = sorted({c for f in cl for c in funcs[f]["calls"] if c not in funcs})
    return {"size": sizes.get(name), "closure": cl, "closure_size": sum(sizes.get(f, 0) for f in cl),
            "udiv": sum(1 for i in insns if i.startswith(("udiv", "sdiv"))),
            "dmb": sum(1 for i in insns if i.startswith("dmb")),
            "external_calls": ext,
            "libgcc_div_calls": [c for c in ext if re.match(r"__aeabi_.*div", c)]}


def arm_phase(build):
    if shutil.which(ARM_CC) is None:
        return {"available": False}
    out_dir = os.path.join(build, "bench", "arm")
    os.makedirs(os.path.join(ROOT, out_dir), exist_ok=True)
    res = {"available": True, "flags": " ".join(ARM_FLAGS), "modules": {}, "functions": {}, "ram": {}}
    res["compiler"] = run([ARM_CC, "--version"]).stdout.splitlines()[0]
    all_funcs, all_sizes = {}, {}
    srcs = sorted(glob.glob(os.path.join(ROOT, "kernel", "src", "*.c")))
    for src in srcs:
        mod = os.path.basename(src)[:-2]
        obj = os.path.join(out_dir, mod + ".o")
        p = run([ARM_CC] + ARM_FLAGS + KINC + ["-Ikernel/src", "-c", os.path.relpath(src, ROOT), "-o", obj])
        if p.returncode != 0:
            raise HarnessError(f"Cortex-M4 build of {src} failed:\n{p.stderr}")
        s = run(["arm-none-eabi-size", obj]).stdout.splitlines()[-1].split()
        res["modules"][mod] = {"text": int(s[0]), "data": int(s[1]), "bss": int(s[2])}
        funcs = parse_objdump(run(["arm-none-eabi-objdump", "-dr", "--no-show-raw-insn", obj]).stdout)
        sizes = section_sizes(obj)
        for f in funcs:
            funcs[f]["module"] = mod
        all_funcs.update(funcs)
        all_sizes.update(sizes)
        res["modules"][mod]["funcs"] = funcs
        res["modules"][mod]["sizes"] = sizes
    for h in HOT:
        mod = next((m for m, v in res["modules"].items() if h in v["funcs"]), None)
        if mod is None:
            res["functions"][h] = None
            continue
        v = res["modules"][mod]
        res["functions"][h] = dict(fn_stats(h, v["funcs"], v["sizes"]), module=mod)
    # push+pop together (shared helpers counted once)
    if "objring" in res["modules"]:
        v = res["modules"]["objring"]
        cl = sorted(set(fn_closure("mt_oring_push", v["funcs"]) + fn_closure("mt_oring_pop", v["funcs"])))
        res["oring_pushpop_size"] = sum(v["sizes"].get(f, 0) for f in cl)
        res["oring_pushpop_closure"] = cl
    # the word ring (inline in mt/wordring.h) as compiled into a caller: bench/src/m4_wring.c
    obj = os.path.join(out_dir, "m4_wring.o")
    p = run([ARM_CC] + ARM_FLAGS + KINC + ["-c", "bench/src/m4_wring.c", "-o", obj])
    if p.returncode != 0:
        raise HarnessError(f"Cortex-M4 build of m4_wring.c failed:\n{p.stderr}")
    funcs = parse_objdump(run(["arm-none-eabi-objdump", "-dr", "--no-show-raw-insn", obj]).stdout)
    sizes = section_sizes(obj)
    res["wring"] = {f: fn_stats(f, funcs, sizes) for f in ("bench_m4_wring_push", "bench_m4_wring_pop")}
    res["wring_pushpop_size"] = sum(v["closure_size"] for v in res["wring"].values())
    # the ArduPilot-style scheduler reference, same flags
    obj = os.path.join(out_dir, "ref_ap_sched.o")
    p = run([ARM_CC] + ARM_FLAGS + ["-DREF_AP_SCHED_ONLY", "-Ibench/src", "-c", "bench/src/ref_ap_sched.c",
                                    "-o", obj])
    if p.returncode != 0:
        raise HarnessError(f"Cortex-M4 build of ref_ap_sched.c failed:\n{p.stderr}")
    funcs = parse_objdump(run(["arm-none-eabi-objdump", "-dr", "--no-show-raw-insn", obj]).stdout)
    sizes = section_sizes(obj)
    res["ref_ap"] = {f: fn_stats(f, funcs, sizes) for f in ("ap_sched_run", "ap_sched_tick", "ap_sched_end_loop")}
    # RAM per object
    variants = [("tasks8", ["-DMT_CFG_SCHED_MAX_TASKS=8"]), ("tasks32", ["-DMT_CFG_SCHED_MAX_TASKS=32"]),
                ("tasks64", []), ("tasks255", ["-DMT_CFG_SCHED_MAX_TASKS=255"]),
                ("cacheline0", ["-DMT_CFG_CACHE_LINE=0u"])]
    for tag, defs in variants:
        for target, cc, nm in (("m4", ARM_CC, "arm-none-eabi-nm"), ("host", "gcc", "nm")):
            obj = os.path.join(out_dir, f"sizes_{target}_{tag}.o")
            flags = (ARM_FLAGS if target == "m4" else ["-O2", "-std=c11", "-fno-common"])
            p = run([cc] + flags + defs + KINC + ["-c", "bench/src/sizes.c", "-o", obj])
            if p.returncode != 0:
                raise HarnessError(f"sizes.c ({target}, {tag}) failed:\n{p.stderr}")
            sz = {}
            for line in run([nm, "-S", obj]).stdout.splitlines():
                parts = line.split()
                if len(parts) == 4 and parts[3].startswith("bench_sizeof_"):
                    sz[parts[3][len("bench_sizeof_"):]] = int(parts[1], 16)
            res["ram"].setdefault(target, {})[tag] = sz
    for mod in res["modules"].values():  # keep the JSON small
        mod.pop("funcs", None)
    return res


# ---------------------------------------------------------------- proofs
def read_parts(path):
    """{part: seconds} from a timing file of tools/prove.sh, or None."""
    if not os.path.isfile(path):
        return None
    try:
        with open(path) as f:
            return {k: float(v) for k, v in json.load(f).items()}
    except (OSError, ValueError):
        return None


def proof_phase(build):
    """Wall times of the last `make prove` with a cold WP cache (full proof) and with a warm
    one (incremental): tools/prove.sh writes build/proof/timing-{cold,warm}.json, one entry
    per part; and of each WP module in the last run (build/proof/wp/<module>/time.txt)."""
    found = {}
    proof = os.path.join(ROOT, build, "proof")
    for kind in ("cold", "warm"):
        parts = read_parts(os.path.join(proof, f"timing-{kind}.json"))
        if parts:
            found[kind] = parts
    modules = {}
    for t in sorted(glob.glob(os.path.join(proof, "wp", "*", "time.txt"))):
        try:
            with open(t) as f:
                modules[os.path.basename(os.path.dirname(t))] = float(f.read().strip())
        except (OSError, ValueError):
            pass
    if modules:
        found["wp_modules"] = modules
    return found


def proof_times(found, kind):
    """Short text for the table: the wall time of each proof part of the last `make prove` of
    this kind (cold: full proof; warm: incremental), or None."""
    parts = (found or {}).get(kind)
    if not parts:
        return None
    text = ", ".join(f"{k} {v:.0f} s" for k, v in parts.items())
    return text + f"; total {sum(parts.values()):.0f} s"


def slowest_module(found):
    mods = (found or {}).get("wp_modules") or {}
    if not mods:
        return None
    slow = max(mods, key=mods.get)
    return f"{slow} {mods[slow]:.0f} s"


# ------------------------------------------------------------------ table
def wc_ap_div(t):
    return max(1, round(t["items"] / t["ap_items"])) if t["ap_items"] else "?"


def fmt_ir(x):
    return f"{x:,.1f}"


def fmt_ops(s):
    return f"{s['median'] / 1e6:.1f}M [{s['min'] / 1e6:.1f}-{s['max'] / 1e6:.1f}]"


def fmt_ns(s):
    return f"{s['median']:.0f} [{s['min']:.0f}-{s['max']:.0f}]"


def linfit(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return my - b * mx, b


def build_report(info, cg, wc, arm, proofs, elapsed_cg, elapsed_wc):
    rows = []   # (section, benchmark, metronome, peer, peer value, ratio, note)
    targets = []
    J = {"machine": info, "callgrind": cg, "wallclock": wc, "arm": arm, "proofs": proofs}

    def row(sec, name, mt, peer="", pv="", ratio="", note=""):
        rows.append((sec, name, mt, peer, pv, ratio, note))

    def target(tid, name, ok, detail, exact=True, gated=True):
        """A target line of issue 24's table (P1-P9). exact: judged on instruction counts or sizes
        (make bench-check runs those alone); gated: False for a figure that is only reported."""
        targets.append({"id": tid, "target": name, "pass": bool(ok), "detail": detail, "exact": exact,
                        "gated": gated})

    # ---- rings, single thread
    base = cg["ring_base"]["per_op"]
    net = {k: cg[f"ring_{k}"]["per_op"] - base for k in ("mt", "mtw", "boost", "boostrt", "ap")}
    J["ring_ir_net"] = net
    row("RING", "loop baseline Ir/item", fmt_ir(base), "", "", "", "subtracted below")
    row("RING", "wring push+pop Ir/item (net, 32-bit words)", fmt_ir(net["mtw"]), "boost spsc cap<4096>",
        fmt_ir(net["boost"]), f"{net['mtw'] / net['boost']:.2f}x", "word ring, capacity 4096 at compile time")
    row("RING", "oring push+pop Ir/item (net, elem 4)", fmt_ir(net["mt"]), "boost spsc cap<4096>",
        fmt_ir(net["boost"]), f"{net['mt'] / net['boost']:.2f}x", f"perf.md boost {ANCHOR['ring_boost_net']}")
    row("RING", "oring push+pop Ir/item (net, elem 4)", fmt_ir(net["mt"]), "boost spsc runtime 4096",
        fmt_ir(net["boostrt"]), f"{net['mt'] / net['boostrt']:.2f}x", "")
    row("RING", "oring push+pop Ir/item (net, elem 4)", fmt_ir(net["mt"]), "AP-style ObjectBuffer",
        fmt_ir(net["ap"]), f"{net['mt'] / net['ap']:.2f}x", f"perf.md AP {ANCHOR['ring_ap_net']}")
    for size in (1, 64):
        m = cg[f"bytes_mt_{size}"]["per_op"]
        for peer, lab in (("boost", "boost spsc<uint8_t> bulk"), ("ap", "AP-style ByteBuffer")):
            p = cg[f"bytes_{peer}_{size}"]["per_op"]
            row("RING", f"bring write+read {size} B, Ir", fmt_ir(m), lab, fmt_ir(p), f"{m / p:.2f}x", "")
    target("P1", "object ring push+pop (word ring fast path), net Ir per item <= boost spsc_queue "
           "(compile-time capacity)", net["mtw"] <= net["boost"],
           f"{net['mtw']:.1f} vs {net['boost']:.1f} net Ir/item ({net['mtw'] / net['boost']:.2f}x); the generic "
           f"object ring (run-time size and capacity) {net['mt']:.1f} ({net['mt'] / net['boost']:.2f}x)")
    bm, bb = cg["bytes_mt_64"]["per_op"], cg["bytes_boost_64"]["per_op"]
    target("P2", "byte ring write+read of 64 B, Ir <= 2x boost bulk", bm <= 2 * bb,
           f"{bm:.1f} vs {bb:.1f} Ir ({bm / bb:.2f}x)")
    if wc is None:  # make bench-check: instruction counts and sizes only
        return bench_rest(cg, None, arm, proofs, row, target, J, rows, targets)

    # ---- rings, two threads. Targets are judged on the steady-state medians
    # (median over short chunks inside each round, then median over rounds):
    # on a shared VM the plain round medians mostly measure other processes.
    t = wc["tput"]
    ts = t["steady_ops_per_s"]
    cap = " budget-capped" if t["capped_by_budget"] else ""
    nlab = (f"{t['items_min']:.1e}-{t['items_max']:.1e}" if t["items_min"] != t["items_max"]
            else f"{t['items_max']:.1e}")
    row("RING", f"throughput ops/s, steady ({nlab} items{cap})", fmt_ops(ts["mt"]), "boost spsc cap<4096>",
        fmt_ops(ts["boost"]), f"{t['steady_ratio_mt_boost']:.2f}x",
        f"{t['rounds']} rounds; median of 65536-item chunks per round (AP: 65536/{wc_ap_div(t)})")
    row("RING", "throughput ops/s, steady (word ring)", fmt_ops(ts["mtw"]), "boost spsc cap<4096>",
        fmt_ops(ts["boost"]), f"{t['steady_ratio_mtw_boost']:.2f}x", f"paired {t['paired_ratio_mtw_boost']:.2f}x")
    row("RING", "throughput ops/s, steady", fmt_ops(ts["mt"]), f"AP-style ObjectBuffer (items/{wc_ap_div(t)})",
        fmt_ops(ts["ap"]), f"{t['steady_ratio_mt_ap']:.2f}x", "")
    row("RING", "throughput ops/s, round medians", fmt_ops(t["ops_per_s"]["mt"]), "boost spsc cap<4096>",
        fmt_ops(t["ops_per_s"]["boost"]), f"{t['ratio_mt_boost']:.2f}x",
        f"items/elapsed per round; paired {t['paired_ratio_mt_boost']:.2f}x")
    row("RING", "throughput ops/s, round medians (word ring)", fmt_ops(t["ops_per_s"]["mtw"]),
        "boost spsc cap<4096>", fmt_ops(t["ops_per_s"]["boost"]),
        f"{t['ops_per_s']['mtw']['median'] / t['ops_per_s']['boost']['median']:.2f}x",
        f"paired {t['paired_ratio_mtw_boost']:.2f}x")
    row("RING", "throughput ops/s, round medians", fmt_ops(t["ops_per_s"]["mt"]), "AP-style ObjectBuffer",
        fmt_ops(t["ops_per_s"]["ap"]), f"{t['ratio_mt_ap']:.2f}x", f"paired {t['paired_ratio_mt_ap']:.2f}x")
    target("P3", "two-thread throughput (word ring), paired-round median >= 1.0x boost (stretch 1.5x)",
           t["paired_ratio_mtw_boost"] >= 1.0,
           f"paired {t['paired_ratio_mtw_boost']:.2f}x (steady {t['steady_ratio_mtw_boost']:.2f}x); generic "
           f"object ring: paired {t['paired_ratio_mt_boost']:.2f}x, steady {t['steady_ratio_mt_boost']:.2f}x",
           exact=False, gated=False)
    r = wc["rtt"]
    rs = r["steady_ns"]
    for v, lab in (("mt", "Metronome oring"), ("boost", "boost spsc"), ("ap", "AP-style ObjectBuffer")):
        row("RING", f"round trip ns, steady ({lab})", fmt_ns(rs[v]), "bare cache-line ping-pong",
            fmt_ns(rs["bare"]), f"{rs[v]['median'] / rs['bare']['median']:.2f}x",
            f"{r['rounds']} rounds; median of 256-round-trip chunks" if v == "mt" else "")
    for v, lab in (("mt", "Metronome oring"), ("boost", "boost spsc")):
        row("RING", f"round trip ns, round medians ({lab})", fmt_ns(r["ns"][v]), "bare cache-line ping-pong",
            fmt_ns(r["ns"]["bare"]), f"{r['ns'][v]['median'] / r['ns']['bare']['median']:.2f}x",
            f"{r['roundtrips_min']}-{r['roundtrips']} round trips per round" if v == "mt" else "")
    target("P4", "round trip <= 2.5x a bare cache line", r["steady_ratio_mt_bare"] <= 2.5,
           f"steady {r['steady_ratio_mt_bare']:.2f}x (boost {r['steady_ratio_boost_bare']:.2f}x; round medians "
           f"mt {r['ratio_mt_bare']:.2f}x, boost {r['ratio_boost_bare']:.2f}x)", exact=False)
    return bench_rest(cg, wc, arm, proofs, row, target, J, rows, targets)


def bench_rest(cg, wc, arm, proofs, row, target, J, rows, targets):
    """The report's instruction-count and size sections (also all of make bench-check)."""

    # ---- scheduler
    J["sched"] = {}
    worst = {}
    for ntask in (8, 32, 255):
        for tset in ("mix", "idle"):
            m = cg[f"sched_mt_{tset}_{ntask}"]
            a = cg[f"sched_ap_{tset}_{ntask}"]
            ratio = m["per_op"] / a["per_op"]
            same = (m["calls"] == a["calls"])
            J["sched"][f"{tset}_{ntask}"] = {"mt": m["per_op"], "ap": a["per_op"], "ratio": ratio,
                                             "runs_mt": m["calls"], "runs_ap": a["calls"]}
            worst.setdefault(ntask, []).append((tset, ratio))
            note = f"perf.md ap {ANCHOR['sched_ap'][(tset, ntask)]}; runs {m['calls']}"
            if not same:
                note += f" (AP ran {a['calls']}!)"
            row("SCHED", f"tick Ir, {tset}, {ntask} tasks", fmt_ir(m["per_op"]), "AP-style run()",
                fmt_ir(a["per_op"]), f"{ratio:.2f}x", note)
    for tset in ("mix", "idle"):
        m = cg[f"schedposix_mt_{tset}_8"]["per_op"]
        a = cg[f"sched_ap_{tset}_8"]["per_op"]
        row("SCHED", f"tick Ir, {tset}, 8 tasks, hal_posix sim time", fmt_ir(m), "AP-style run() (stub time)",
            fmt_ir(a), f"{m / a:.2f}x", "info: port time cost included")
    for ntask, lst in worst.items():
        mix = [x for s, x in lst if s == "mix"][0]
        target("P6", f"scheduler mixed tick, {ntask} tasks, Ir <= 0.5x the ArduPilot-style scan", mix <= 0.5,
               f"mix {mix:.2f}x (idle {[x for s, x in lst if s == 'idle'][0]:.2f}x, info)")
    idle = J["sched"]
    slope_mt = (idle["idle_255"]["mt"] - idle["idle_8"]["mt"]) / 247
    slope_ap = (idle["idle_255"]["ap"] - idle["idle_8"]["ap"]) / 247
    J["sched"]["idle_slope_per_task"] = {"mt": slope_mt, "ap": slope_ap}
    row("SCHED", "idle scan Ir per task (slope 8->255)", fmt_ir(slope_mt), "AP-style run()", fmt_ir(slope_ap),
        f"{slope_mt / slope_ap:.2f}x", "perf.md ap 15.1, pre 7.1")

    # ---- procs
    xs = list(range(1, 9))
    fits = {}
    for impl in ("mt", "ap"):
        ys = [cg[f"proc_{impl}_{n}"]["per_op"] for n in xs]
        fits[impl] = linfit(xs, ys) + (ys,)
    J["proc"] = {k: {"fixed": v[0], "per_proc": v[1], "per_dispatch": v[2]} for k, v in fits.items()}
    for n in (1, 4, 8):
        m, a = fits["mt"][2][n - 1], fits["ap"][2][n - 1]
        row("PROC", f"dispatch Ir, {n} proc{'s' if n > 1 else ''}", fmt_ir(m), "AP-style _run_timers",
            fmt_ir(a), f"{m / a:.2f}x", "")
    row("PROC", "dispatch fixed Ir (fit 1..8)", fmt_ir(fits["mt"][0]), "AP-style _run_timers",
        fmt_ir(fits["ap"][0]), f"{fits['mt'][0] / fits['ap'][0]:.2f}x", f"perf.md ap {ANCHOR['timers_fixed']}")
    row("PROC", "dispatch Ir per proc (fit 1..8)", fmt_ir(fits["mt"][1]), "AP-style _run_timers",
        fmt_ir(fits["ap"][1]), f"{fits['mt'][1] / fits['ap'][1]:.2f}x", f"perf.md ap {ANCHOR['timers_per_proc']}")
    target("P8", "timer-proc dispatch: fixed Ir <= the ArduPilot-style fixed, <= 20 Ir per proc",
           fits["mt"][0] <= fits["ap"][0] and fits["mt"][1] <= 20,
           f"{fits['mt'][0]:.1f} + {fits['mt'][1]:.1f}/proc (ArduPilot-style {fits['ap'][0]:.1f} + "
           f"{fits['ap'][1]:.1f}/proc)")

    # ---- semaphores
    sm, sp, sb = (cg[f"sem_{k}"]["per_op"] for k in ("mt", "posix", "bsem"))
    ss = cg["semstub_mt"]["per_op"]
    J["sem_ir"] = {"mt": sm, "posix": sp, "bsem": sb, "mt_stub_lock": ss}
    row("SEM", "signal+wait Ir (hal_posix lock)", fmt_ir(sm), "POSIX sem_t", fmt_ir(sp), f"{sm / sp:.2f}x",
        f"perf.md sem_t {ANCHOR['sem_posix']}")
    row("SEM", "signal+wait Ir (hal_posix lock)", fmt_ir(sm), "mutex+condvar bsem", fmt_ir(sb), f"{sm / sb:.2f}x",
        f"perf.md bsem {ANCHOR['sem_bsem']}")
    row("SEM", "signal+wait Ir (bench stub lock)", fmt_ir(ss), "POSIX sem_t", fmt_ir(sp), f"{ss / sp:.2f}x",
        "info: kernel logic without the host lock")
    if wc is not None:
        s = wc["sem"]
        row("SEM", "signal+wait ns (hal_posix)", fmt_ns(s["ns"]["mt"]), "POSIX sem_t", fmt_ns(s["ns"]["posix"]),
            f"{s['ratio_mt_posix']:.2f}x", f"{s['rounds']} rounds x {s['pairs']}")
        row("SEM", "signal+wait ns (hal_posix)", fmt_ns(s["ns"]["mt"]), "mutex+condvar bsem",
            fmt_ns(s["ns"]["bsem"]), f"{s['ratio_mt_bsem']:.2f}x", "")
    target("P9", "semaphore signal+wait on the host port, Ir <= POSIX sem_t", sm <= sp,
           f"{sm:.1f} vs {sp:.1f} Ir/pair ({sm / sp:.2f}x)")

    # ---- Cortex-M4
    if arm.get("available"):
        f = arm["functions"]
        for mod, v in sorted(arm["modules"].items()):
            row("M4", f"module {mod}.o text/data/bss B", f"{v['text']}/{v['data']}/{v['bss']}", "", "", "",
                "-Os -ffunction-sections")
        for h in HOT:
            st = f.get(h)
            if st is None:
                continue
            note = f"udiv {st['udiv']}, dmb {st['dmb']}"
            if st["libgcc_div_calls"]:
                note += ", calls " + "/".join(st["libgcc_div_calls"])
            incl = "+".join(x for x in st["closure"] if x != h)
            peer, pv, ratio = "", "", ""
            if h == "mt_oring_push":
                peer, pv = "perf.md plain push", str(ANCHOR["m4_plain_push"])
            elif h == "mt_oring_pop":
                peer, pv = "perf.md plain pop", str(ANCHOR["m4_plain_pop"])
            elif h == "mt_sched_run":
                ap = arm["ref_ap"]["ap_sched_run"]
                peer, pv = "AP-style run() (this run)", f"{ap['closure_size']} (udiv {ap['udiv']})"
                ratio = f"{st['closure_size'] / ap['closure_size']:.2f}x"
                note += f"; perf.md ap {ANCHOR['m4_sched_run_ap']}"
            if pv and not ratio and pv.isdigit():
                ratio = f"{st['closure_size'] / int(pv):.2f}x"
            row("M4", f"{h} B" + (f" (+{incl})" if incl else ""), str(st["closure_size"]), peer, pv, ratio, note)
        pp = arm.get("oring_pushpop_size")
        wp, wr = arm.get("wring_pushpop_size"), arm.get("wring", {})
        if wr:
            row("M4", "word ring push+pop B (inline, as compiled into a caller)", str(wp), "", "", "",
                f"dmb push {wr['bench_m4_wring_push']['dmb']} / pop {wr['bench_m4_wring_pop']['dmb']}, "
                f"udiv {wr['bench_m4_wring_push']['udiv'] + wr['bench_m4_wring_pop']['udiv']}")
        if pp is not None and wr:
            push, pop = wr["bench_m4_wring_push"], wr["bench_m4_wring_pop"]
            gpush, gpop = f["mt_oring_push"], f["mt_oring_pop"]
            target("P5", "Cortex-M4 object ring push+pop (word ring fast path) <= 160 B, no udiv, <= 2 dmb per "
                   "operation",
                   wp <= 160 and push["udiv"] + pop["udiv"] == 0 and push["dmb"] <= 2 and pop["dmb"] <= 2,
                   f"{wp} B, udiv {push['udiv'] + pop['udiv']}, dmb push {push['dmb']} / pop {pop['dmb']} (static); "
                   f"the generic object ring {pp} B, dmb push {gpush['dmb']} / pop {gpop['dmb']}")
        sr = f.get("mt_sched_run")
        if sr:
            ap = arm["ref_ap"]["ap_sched_run"]["closure_size"]
            target("P7", "Cortex-M4 tick path: no libgcc division call, <= 2x the ArduPilot-style run() size",
                   not sr["libgcc_div_calls"] and sr["closure_size"] <= 2 * ap,
                   f"{sr['closure_size']} B against {ap} B ({sr['closure_size'] / ap:.2f}x), libgcc division "
                   f"calls {len(sr['libgcc_div_calls'])}")
        ram = arm["ram"]["m4"]
        host = arm["ram"]["host"]
        for typ, tag, peer, pv in (("mt_bring_t", "tasks64", "ChibiOS input queue", ANCHOR["chibios_ram"]["queue"]),
                                   ("mt_bring_t", "cacheline0", "ChibiOS input queue", ANCHOR["chibios_ram"]["queue"]),
                                   ("mt_oring_t", "tasks64", "", ""), ("mt_oring_t", "cacheline0", "", ""),
                                   ("mt_sem_t", "tasks64", "ChibiOS semaphore", ANCHOR["chibios_ram"]["semaphore"]),
                                   ("mt_proc_set_t", "tasks64", "", ""),
                                   ("mt_sched_t", "tasks8", "", ""), ("mt_sched_t", "tasks32", "", ""),
                                   ("mt_sched_t", "tasks64", "", ""), ("mt_sched_t", "tasks255", "", "")):
            lab = {"tasks64": "default", "cacheline0": "MT_CFG_CACHE_LINE=0", "tasks8": "8 tasks",
                   "tasks32": "32 tasks", "tasks255": "255 tasks"}[tag]
            if typ == "mt_sched_t" and tag == "tasks64":
                lab = "64 tasks (default)"
            m4 = ram[tag].get(typ)
            row("RAM", f"sizeof({typ}) {lab}, M4 B", str(m4), peer, str(pv) if pv else "",
                f"{m4 / pv:.2f}x" if pv else "", f"x86-64 {host[tag].get(typ)} B")
    else:
        row("M4", "Cortex-M4 code size", "not measured", "", "", "", "arm-none-eabi-gcc not installed")
        for tid, name in (("P5", "Cortex-M4 object ring push+pop"), ("P7", "Cortex-M4 tick path")):
            target(tid, name, False, "not measured: arm-none-eabi-gcc not installed")

    # ---- proofs
    for kind, what in (("cold", "full, cold WP cache"), ("warm", "incremental, warm WP cache")):
        ptxt = proof_times(proofs, kind)
        row("PROOF", f"make prove wall time ({what})",
            ptxt if ptxt else "no such run in this build tree", "", "", "",
            f"last one: build/proof/timing-{kind}.json")
    slow = slowest_module(proofs)
    if slow:
        row("PROOF", "slowest WP module, last make wp", slow, "", "", "",
            "build/proof/wp/*/time.txt")
    return rows, targets, J


def target_lines(targets):
    out = []
    for t in sorted(targets, key=lambda t: t["id"]):
        verdict = ("PASS" if t["pass"] else "FAIL") if t["gated"] else "REPORT"
        out.append(f"TARGET {verdict}  {t['id']} {t['target']}: {t['detail']}")
    return out


def render(info, rows, targets, elapsed):
    hdr = ("Section", "Benchmark", "Metronome", "Peer", "Peer value", "Ratio", "Note")
    widths = [max(len(str(r[i])) for r in rows + [hdr]) for i in range(7)]
    widths[6] = min(widths[6], 60)
    lines = []
    title = (f"Metronome bench: {info.get('Model name', '?')}, {info.get('CPU(s)', '?')} CPUs "
             f"({info.get('Core(s) per socket', '?')} cores/socket, {info.get('Thread(s) per core', '?')} thr/core), "
             f"load {info.get('loadavg_start', '?')} | {info['gcc']} -O2 | {info['valgrind']} | "
             f"boost {info['boost']} | {info['date']} | commit {info['commit']}"
             f"{' + local changes' if info.get('kernel_tree_dirty') else ''} (kernel+hal_posix sha256 "
             f"{info['kernel_sources_sha256']})")
    lines.append(title)
    try:
        l0 = float(info.get("loadavg_start", "0").split()[0])
        l1 = float(info.get("loadavg_end", "0").split()[0])
        ncpu = int(info.get("CPU(s)", "1"))
        if max(l0, l1) > 0.5 * ncpu:
            lines.append(f"WARNING: machine busy (load average {l0:.1f} at start, {l1:.1f} at end, {ncpu} CPUs): "
                         "wall-clock figures are indicative only; Ir figures are unaffected")
    except ValueError:
        pass
    lines.append("Ir = callgrind instructions (exact); wall clock = median [min-max] of interleaved rounds; "
                 "ratio = Metronome / peer (lower is better for Ir/ns/bytes, higher for ops/s)")
    sep = "-+-".join("-" * w for w in widths)

    def fmt(r):
        return " | ".join(str(c).ljust(w) for c, w in zip(r, widths)).rstrip()
    lines.append(fmt(hdr))
    lines.append(sep)
    prev = None
    for r in rows:
        if prev is not None and r[0] != prev:
            lines.append(sep)
        lines.append(fmt(r))
        prev = r[0]
    lines.append(sep)
    lines.extend(target_lines(targets))
    gated = [t for t in targets if t["gated"]]
    npass = sum(1 for t in gated if t["pass"])
    lines.append(f"targets: {npass}/{len(gated)} pass (make bench-check gates the exact ones); "
                 f"bench run time {elapsed:.0f} s (excluding the build)")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--skip-wallclock", action="store_true", help="callgrind and sizes only (development)")
    ap.add_argument("--check", action="store_true",
                    help="make bench-check: the exact target lines only; exit 1 when one is missed")
    args = ap.parse_args()
    os.chdir(ROOT)
    build = args.build
    t_start = time.time()
    info = machine_info(build)
    log("callgrind phase")
    cg = callgrind_phase(build)
    t_cg = time.time() - t_start
    if args.check:
        log("Cortex-M4 phase")
        arm = arm_phase(build)
        _, targets, _ = build_report(info, cg, None, arm, {}, t_cg, 0.0)
        exact = [t for t in targets if t["exact"] and t["gated"]]
        print("\n".join(target_lines(exact)))
        met = sum(1 for t in exact if t["pass"])
        missed = list(dict.fromkeys(t["id"] for t in exact if not t["pass"]))
        print(f"bench-check: {met}/{len(exact)} exact target lines met"
              + (f"; missed: {' '.join(missed)}" if missed else ""))
        return 1 if missed else 0
    wc = None
    if args.skip_wallclock:
        wc = {"tput": None}
    else:
        log("wall-clock phase")
        wc = wallclock_phase(build)
    t_wc = time.time() - t_start - t_cg
    log("Cortex-M4 phase")
    arm = arm_phase(build)
    proofs = proof_phase(build)
    try:
        with open("/proc/loadavg") as f:
            info["loadavg_end"] = " ".join(f.read().split()[:3])
    except OSError:
        pass
    if args.skip_wallclock:
        print(json.dumps({k: v["per_op"] for k, v in cg.items()}, indent=1))
        return 0
    rows, targets, J = build_report(info, cg, wc, arm, proofs, t_cg, t_wc)
    elapsed = time.time() - t_start
    table = render(info, rows, targets, elapsed)
    print(table)
    J["targets"] = targets
    J["table_rows"] = [dict(zip(("section", "benchmark", "metronome", "peer", "peer_value", "ratio", "note"), r))
                       for r in rows]
    J["elapsed_s"] = {"total": round(elapsed, 1), "callgrind": round(t_cg, 1), "wallclock": round(t_wc, 1)}
    out_dir = os.path.join(ROOT, build, "bench")
    with open(os.path.join(out_dir, "results.json"), "w") as f:
        json.dump(J, f, indent=1, default=str)
    with open(os.path.join(out_dir, "results.txt"), "w") as f:
        f.write(table + "\n")
    log(f"wrote {os.path.join(build, 'bench', 'results.json')} and results.txt")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except HarnessError as e:
        print(f"bench: harness error: {e}", file=sys.stderr)
        sys.exit(1)
