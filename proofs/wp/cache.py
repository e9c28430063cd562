#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The committed WP result cache (proofs/wp/cache/<module>.json).

Frama-C/WP keeps one file per prover task in a session's cache directory, named by the
digest of the exact task text sent to the prover (the Why3 task as the prover's driver
prints it, prover name included) and holding the prover's verdict. A result is reused only
for a byte-identical task. This tool moves those files between the session directory under
build/ and one committed bundle per module:

  cache.py seed BUNDLE DIR   write the bundle's entries into DIR (entries already there win)
  cache.py save DIR BUNDLE   write every entry of DIR into BUNDLE (sorted, one per line)
  cache.py count LOG         "replayed N fresh M": prover results of a WP run taken from the
                             cache, and obtained by running a prover in that run

`make wp` seeds each module's session from its bundle (unless WP_CACHE=none), so a clean
clone re-proves unchanged goals from recorded verdicts; `make wp-cache-save` re-runs WP in
cleanup mode (entries no goal uses are dropped) and rewrites the bundles. The proof report
says how many results were replayed (assumption W4).
"""
import json
import os
import re
import sys

HASH_RE = re.compile(r"^[0-9a-f]{32}$")
# WP writes floats the OCaml way ("time": 2.), which JSON does not accept.
OCAML_FLOAT = re.compile(r"(\d)\.(?=\s*[,}\]])")
CACHE_LINE = re.compile(r"^\[wp\] \[Cache\] (.*)$")
CACHE_KV = re.compile(r"(\w+):(\d+)")


def seed(bundle, d):
    if not os.path.exists(bundle):
        return 0
    with open(bundle, encoding="utf-8") as f:
        entries = json.load(f)
    os.makedirs(d, exist_ok=True)
    n = 0
    for h, v in entries.items():
        if not HASH_RE.match(h):
            raise SystemExit(f"cache.py: bad key {h!r} in {bundle}")
        p = os.path.join(d, h + ".json")
        if not os.path.exists(p):
            with open(p, "w", encoding="utf-8") as f:
                json.dump(v, f)
            n += 1
    return n


def save(d, bundle):
    entries = {}
    if os.path.isdir(d):
        for name in sorted(os.listdir(d)):
            h, ext = os.path.splitext(name)
            if ext == ".json" and HASH_RE.match(h):
                with open(os.path.join(d, name), encoding="utf-8") as f:
                    entries[h] = json.loads(OCAML_FLOAT.sub(r"\1.0", f.read()))
    os.makedirs(os.path.dirname(bundle) or ".", exist_ok=True)
    with open(bundle, "w", encoding="utf-8") as f:
        f.write("{\n")
        f.write(",\n".join(f"{json.dumps(h)}: {json.dumps(entries[h], sort_keys=True)}"
                           for h in sorted(entries)))
        f.write("\n}\n")
    return len(entries)


def count(log):
    """(replayed, fresh) from WP's "[wp] [Cache] found:N, updated:M" line (smoke tests
    included): N prover results were taken from the cache, M came from provers run now.
    (0, None) when the line is missing (cache off, or nothing went to a prover)."""
    if os.path.exists(log):
        with open(log, encoding="utf-8", errors="replace") as f:
            for ln in f:
                m = CACHE_LINE.match(ln)
                if m:
                    kv = {k: int(v) for k, v in CACHE_KV.findall(m.group(1))}
                    return kv.get("found", 0), kv.get("updated", 0) + kv.get("missed", 0)
    return 0, None


def main(argv):
    if len(argv) == 4 and argv[1] == "seed":
        print(f"cache: {seed(argv[2], argv[3])} entries seeded from {argv[2]}")
    elif len(argv) == 4 and argv[1] == "save":
        print(f"cache: {save(argv[2], argv[3])} entries in {argv[3]}")
    elif len(argv) == 3 and argv[1] == "count":
        c, f = count(argv[2])
        print(f"replayed {c} fresh " + (str(f) if f is not None else "all (cache off)"))
    else:
        print(__doc__)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
