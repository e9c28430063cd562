#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The example vehicle's file-level call graph must be acyclic (vehicle/README.md).

Compiles every vehicle/**/*.c to an object, maps each symbol an object leaves undefined
(nm) to the vehicle file that defines it, prints "file -> files it calls or uses" and
exits 1 on a cycle (with the cycle), 2 when a file does not compile.

usage: check_callgraph.py CC [CFLAGS...]      (make test-vehicle runs it)
"""
import glob, os, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def symbols(obj):
    out = subprocess.run(["nm", "-P", obj], capture_output=True, text=True, check=True).stdout
    defined, used = set(), set()
    for f in (line.split() for line in out.splitlines()):
        if len(f) >= 2 and f[1] == "U":
            used.add(f[0])
        elif len(f) >= 2 and f[1] in "TDBR":
            defined.add(f[0])
    return defined, used


def main(argv):
    files = sorted(os.path.relpath(p, ROOT) for p in glob.glob(ROOT + "/vehicle/**/*.c", recursive=True))
    owner, uses = {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        for i, f in enumerate(files):
            obj = os.path.join(tmp, "%d.o" % i)
            if subprocess.run(argv[1:] + ["-c", f, "-o", obj], cwd=ROOT).returncode != 0:
                return 2
            defined, uses[f] = symbols(obj)
            owner.update((s, f) for s in defined)
    graph = {f: sorted({owner[s] for s in uses[f] if s in owner} - {f}) for f in files}
    for f in files:
        print("%-36s -> %s" % (f, ", ".join(graph[f]) or "-"))
    state, path = {}, []

    def visit(f):  # depth-first: a file met again while on the path closes a cycle
        state[f] = 1
        path.append(f)
        for g in graph[f]:
            if state.get(g) == 1:
                return path[path.index(g):] + [g]
            if g not in state and (c := visit(g)):
                return c
        path.pop()
        state[f] = 2

    for f in files:
        if f not in state and (c := visit(f)):
            print("call graph: CYCLE " + " -> ".join(c))
            return 1
    print("call graph: %d files, %d edges, acyclic" % (len(files), sum(map(len, graph.values()))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
