#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Read a vehicle binary log (vehicle/src/logger.c) and print what it holds.

    logdump.py [--json] FILE

Record: 'M' 'T' type len payload[len] sum, sum = (type + len + payload) mod 256,
little-endian integers, every payload starting with the time in us (uint64).
Exit status 0 when every record is well formed and the times never go backwards,
1 otherwise."""

import json
import struct
import sys

TYPES = {1: "ATT", 2: "POS", 3: "CTUN", 4: "BARO", 5: "GPS", 6: "CMD", 7: "EV", 8: "BATT"}


def read(data):
    """(records, errors): records are (type, time_us, payload)."""
    recs, errors = [], []
    i = 0
    last_t = 0
    while i < len(data):
        if data[i:i + 2] != b"MT" or i + 4 > len(data):
            errors.append("offset %d: no record header" % i)
            break
        typ, ln = data[i + 2], data[i + 3]
        end = i + 4 + ln
        if end + 1 > len(data):
            errors.append("offset %d: truncated record" % i)
            break
        payload = data[i + 4:end]
        if (typ + ln + sum(payload)) % 256 != data[end]:
            errors.append("offset %d: bad checksum" % i)
        if typ not in TYPES:
            errors.append("offset %d: unknown type %d" % (i, typ))
        if ln < 8:
            errors.append("offset %d: payload without a time" % i)
        else:
            t = struct.unpack_from("<Q", payload)[0]
            if t < last_t:
                errors.append("offset %d: time goes backwards (%d < %d)" % (i, t, last_t))
            last_t = max(last_t, t)
            recs.append((typ, t, payload))
        i = end + 1
    return recs, errors


def main(argv):
    as_json = "--json" in argv
    files = [a for a in argv if a != "--json"]
    if len(files) != 1:
        sys.stderr.write("usage: logdump.py [--json] FILE\n")
        return 2
    with open(files[0], "rb") as f:
        data = f.read()
    recs, errors = read(data)
    counts = {}
    for typ, _, _ in recs:
        counts[TYPES.get(typ, str(typ))] = counts.get(TYPES.get(typ, str(typ)), 0) + 1
    cmds = [struct.unpack_from("<QHHB", p) for typ, _, p in recs if typ == 6]
    out = {"bytes": len(data), "records": len(recs), "counts": counts, "errors": errors,
           "first_us": recs[0][1] if recs else 0, "last_us": recs[-1][1] if recs else 0,
           "commands": [{"t_us": c[0], "index": c[1], "id": c[2], "event": c[3]} for c in cmds]}
    if as_json:
        print(json.dumps(out, indent=1))
    else:
        print("%s: %d bytes, %d records, %.1f s" % (files[0], len(data), len(recs),
                                                  (out["last_us"] - out["first_us"]) * 1e-6))
        for k in sorted(counts):
            print("  %-5s %7d" % (k, counts[k]))
        for e in errors[:10]:
            print("error: " + e)
    return 0 if not errors else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
