#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Generate the mission command tables from MAVLink's definitions.

    python3 tools/mavcmd/gen_mav_cmds.py           write the generated headers
    python3 tools/mavcmd/gen_mav_cmds.py --check   exit 1 with a diff when they are stale
    python3 tools/mavcmd/gen_mav_cmds.py --list    print id, name, class, location per command

Which commands: every command ArduPilot's mission loader accepts (AP_LOADER_ACCEPTS below, by
MAVLink name). Their ids, and whether params 5-7 carry a location (the `hasLocation` attribute
of the XML <entry>), come from common.xml and ardupilotmega.xml of the pinned pymavlink
(PYMAVLINK_VERSION; tools/bootstrap.sh test installs it into .tools/pymavlink). The class
follows ArduPilot's AP_Mission::is_nav_cmd; the parameter rules (F_NAN3 ... F_INT2) are
Metronome's reading of ArduPilot's sanity checks and conversions (PARAM_RULES).

Outputs (committed: the kernel builds and is proved without Python):
    kernel/src/mt_mission_cmds.h   MT_MISSION_CMD_ROWS (the {id, kind, flags} rows of
                                   mission_check.c's k_cmds), N_CMDS and the F_* flags, private
                                   to mission_check.c
    mission/mav_cmd_names.h        id -> MAVLink name (no MAV_CMD_ prefix) and location flag,
                                   private to mission/wpl.c
    kernel/spec/mt_spec_mission_cmds.h
                                   ACSL only: MtMissionIsNavId / MtMissionIsDoId, the ids of
                                   the table's nav and do rows (mt_mission_kind_of's contract)
Standard library only; the XML is parsed with xml.etree.
"""
import argparse
import difflib
import importlib
import os
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
PRIVATE_SITE = os.path.join(ROOT, ".tools", "pymavlink")
PYMAVLINK_VERSION = "2.4.50"
XML_FILES = ("common.xml", "ardupilotmega.xml")
KERNEL_OUT = "kernel/src/mt_mission_cmds.h"
NAMES_OUT = "mission/mav_cmd_names.h"
SPEC_OUT = "kernel/spec/mt_spec_mission_cmds.h"
TOOL = "tools/mavcmd/gen_mav_cmds.py"

# The cases of ArduPilot's AP_Mission::mavlink_int_to_mission_cmd
# (libraries/AP_Mission/AP_Mission.cpp) at ArduPilot/ardupilot commit
# 6f0c7d9b0beb98ef0b63f867ca47a1c260f1593f, in the switch's order, plus NAV_ARC_WAYPOINT, which
# ArduPilot PR 31139 (merged 2025-11, Copter 4.7) added to that switch after that commit.
# Cases under a build option are listed too (DO_GRIPPER: AP_GRIPPER_ENABLED, NAV_PAYLOAD_PLACE:
# AP_MISSION_NAV_PAYLOAD_PLACE_ENABLED, NAV_SCRIPT_TIME: AP_SCRIPTING_ENABLED); ArduPlane
# refuses NAV_SPLINE_WAYPOINT, the other vehicles accept it. Ids 0 and 1 are refused there.
# ArduPilot's AP_Mission::stored_in_location (same file): the commands whose x/y/z ArduPilot
# stores, range-checks and frame-checks as a location. F_LOC is set for these and for every
# command whose MAVLink entry has hasLocation="true": NAV_CONTINUE_AND_CHANGE_ALT,
# NAV_GUIDED_ENABLE and DO_GO_AROUND have no hasLocation in the XML, yet ArduPilot rejects an
# out-of-range latitude in them, so the kernel does too.
AP_STORED_IN_LOCATION = [
    "NAV_WAYPOINT", "NAV_LOITER_UNLIM", "NAV_LOITER_TURNS", "NAV_LOITER_TIME", "NAV_LAND",
    "NAV_TAKEOFF", "NAV_CONTINUE_AND_CHANGE_ALT", "NAV_LOITER_TO_ALT", "NAV_SPLINE_WAYPOINT",
    "NAV_GUIDED_ENABLE", "DO_SET_HOME", "DO_LAND_START", "DO_GO_AROUND", "DO_SET_ROI",
    "NAV_VTOL_TAKEOFF", "NAV_VTOL_LAND", "NAV_PAYLOAD_PLACE",
]

AP_LOADER_ACCEPTS = [
    "NAV_WAYPOINT",
    "NAV_LOITER_UNLIM",
    "NAV_LOITER_TURNS",
    "NAV_LOITER_TIME",
    "NAV_RETURN_TO_LAUNCH",
    "NAV_LAND",
    "NAV_TAKEOFF",
    "NAV_CONTINUE_AND_CHANGE_ALT",
    "NAV_LOITER_TO_ALT",
    "NAV_ARC_WAYPOINT",  # ArduPilot PR 31139
    "NAV_SPLINE_WAYPOINT",
    "NAV_GUIDED_ENABLE",
    "NAV_DELAY",
    "CONDITION_DELAY",
    "CONDITION_DISTANCE",
    "CONDITION_YAW",
    "DO_JUMP",
    "DO_JUMP_TAG",
    "JUMP_TAG",
    "DO_CHANGE_SPEED",
    "DO_SET_HOME",
    "DO_SET_RELAY",
    "DO_REPEAT_RELAY",
    "DO_SET_SERVO",
    "DO_REPEAT_SERVO",
    "DO_RETURN_PATH_START",
    "DO_LAND_START",
    "DO_GO_AROUND",
    "DO_SET_ROI_LOCATION",
    "DO_SET_ROI_NONE",
    "DO_SET_ROI",
    "DO_DIGICAM_CONFIGURE",
    "DO_DIGICAM_CONTROL",
    "DO_MOUNT_CONTROL",
    "DO_SET_CAM_TRIGG_DIST",
    "DO_FENCE_ENABLE",
    "DO_AUX_FUNCTION",
    "DO_PARACHUTE",
    "DO_INVERTED_FLIGHT",
    "DO_GRIPPER",
    "DO_GUIDED_LIMITS",
    "DO_AUTOTUNE_ENABLE",
    "NAV_ALTITUDE_WAIT",
    "NAV_VTOL_TAKEOFF",
    "NAV_VTOL_LAND",
    "DO_VTOL_TRANSITION",
    "DO_SET_REVERSE",
    "DO_ENGINE_CONTROL",
    "NAV_PAYLOAD_PLACE",
    "NAV_SET_YAW_SPEED",
    "DO_WINCH",
    "DO_SET_RESUME_REPEAT_DIST",
    "DO_SPRAYER",
    "DO_SEND_SCRIPT_MESSAGE",
    "NAV_SCRIPT_TIME",
    "NAV_ATTITUDE_TIME",
    "DO_PAUSE_CONTINUE",
    "DO_GIMBAL_MANAGER_PITCHYAW",
    "IMAGE_START_CAPTURE",
    "IMAGE_STOP_CAPTURE",
    "SET_CAMERA_ZOOM",
    "SET_CAMERA_FOCUS",
    "SET_CAMERA_SOURCE",
    "VIDEO_START_CAPTURE",
    "VIDEO_STOP_CAPTURE",
]

# AP_Mission::is_nav_cmd (same commit): id <= MAV_CMD_NAV_LAST, plus these.
NAV_EXCEPTIONS = ["NAV_SET_YAW_SPEED", "NAV_SCRIPT_TIME", "NAV_ATTITUDE_TIME"]
# The kernel's jump classes (mt/mission.h): DO_JUMP and DO_JUMP_TAG jump, JUMP_TAG is a tag.
JUMP = ["DO_JUMP", "DO_JUMP_TAG"]
TAG = ["JUMP_TAG"]

# Parameter rules, not in the XML (mission_check.c params_ok): NAN3/NAN4 param 3/4 may be NaN
# (AP_Mission::sanity_check_params: NaN is refused elsewhere); NN1/NN2 param 1/2 >= 0 and
# INT1/INT2 param 1/2 an integer (ArduPilot stores them in unsigned or integer fields).
# Carried over from the hand-written table this generator replaced; a command not listed has
# none of them.
PARAM_RULES = {
    "NAV_WAYPOINT": ["NAN4", "NN1", "NN2"],  # hold s, acceptance radius m (uint16/uint8 p1)
    "NAV_LOITER_UNLIM": ["NAN4"],
    "NAV_LOITER_TURNS": ["NN1"],  # turns
    "NAV_LOITER_TIME": ["NN1"],  # seconds (uint16 p1)
    "NAV_LAND": ["NAN4"],
    "NAV_TAKEOFF": ["NAN4"],
    "NAV_SPLINE_WAYPOINT": ["NN1"],  # hold s (uint16 p1)
    "NAV_VTOL_TAKEOFF": ["NAN4"],
    "NAV_VTOL_LAND": ["NAN3", "NAN4"],
    "CONDITION_DELAY": ["NN1"],
    "CONDITION_DISTANCE": ["NN1"],
    "CONDITION_YAW": ["NN2"],  # turn rate; angle, direction, relative: mission_check.c special_ok
    "DO_CHANGE_SPEED": ["INT1"],  # speed type (uint8)
    "DO_SET_RELAY": ["NN1", "INT1"],  # relay number (uint8)
    "DO_REPEAT_RELAY": ["NN1", "NN2", "INT1", "INT2"],  # relay, count
    "DO_SET_SERVO": ["NN2", "INT1", "INT2"],  # channel, pwm (uint16)
    "DO_REPEAT_SERVO": ["NN1", "NN2", "INT1", "INT2"],  # channel, pwm
    "DO_SET_CAM_TRIGG_DIST": ["NN1"],  # metres
    "DO_SET_RESUME_REPEAT_DIST": ["NN1"],  # metres (uint16 p1)
    "JUMP_TAG": ["NN1", "INT1"],  # tag (uint16)
}

FLAG_BITS = [("LOC", 0x01), ("NAN3", 0x02), ("NAN4", 0x04), ("NN1", 0x08), ("NN2", 0x10),
             ("INT1", 0x20), ("INT2", 0x40)]
FLAG_DOC = {
    "LOC": "uses x/y/z as a location: global frame, lat/lon range",
    "NAN3": "param 3 may be NaN",
    "NAN4": "param 4 may be NaN",
    "NN1": "param 1 >= 0",
    "NN2": "param 2 >= 0",
    "INT1": "param 1 is an integer",
    "INT2": "param 2 is an integer",
}
KIND_C = {"nav": "MT_MISSION_KIND_NAV", "do": "MT_MISSION_KIND_DO",
          "jump": "MT_MISSION_KIND_JUMP", "tag": "MT_MISSION_KIND_TAG"}


def fail(msg):
    sys.stderr.write(f"gen_mav_cmds: {msg}\n")
    raise SystemExit(2)


def pymavlink_dir():
    """The directory of the pinned pymavlink (.tools/pymavlink first, then the interpreter's)."""
    if os.path.isdir(PRIVATE_SITE):
        sys.path.insert(0, PRIVATE_SITE)
    try:
        pymavlink = importlib.import_module("pymavlink")
    except ImportError:
        fail(f"pymavlink {PYMAVLINK_VERSION} is not importable: run tools/bootstrap.sh test")
    try:
        import importlib.metadata as md
        version = md.version("pymavlink")
    except Exception:  # no metadata: fall back on the module's own stamp
        version = getattr(pymavlink, "__version__", "?")
    if version != PYMAVLINK_VERSION:
        fail(f"pymavlink {version} imported from {os.path.dirname(pymavlink.__file__)}, "
             f"need {PYMAVLINK_VERSION}: run tools/bootstrap.sh test")
    return os.path.dirname(os.path.abspath(pymavlink.__file__))


def read_mav_cmd(xml_dir):
    """{name without MAV_CMD_: (id, has_location, file)} over XML_FILES (the MAV_CMD enum)."""
    cmds = {}
    for fname in XML_FILES:
        path = os.path.join(xml_dir, "dialects", "v20", fname)
        if not os.path.isfile(path):
            fail(f"{path}: missing from pymavlink {PYMAVLINK_VERSION}")
        root = ET.parse(path).getroot()
        for enum in root.iter("enum"):
            if enum.get("name") != "MAV_CMD":
                continue
            for entry in enum.findall("entry"):
                full = entry.get("name", "")
                if not full.startswith("MAV_CMD_"):
                    fail(f"{fname}: MAV_CMD entry {full!r} lacks the MAV_CMD_ prefix")
                name = full[len("MAV_CMD_"):]
                value = int(entry.get("value"), 0)
                loc = entry.get("hasLocation")
                if loc not in (None, "true", "false"):
                    fail(f"{fname}: {full}: hasLocation={loc!r}")
                rec = (value, loc == "true", fname)
                if name in cmds and cmds[name][:2] != rec[:2]:
                    fail(f"{full}: {cmds[name][2]} and {fname} disagree")
                cmds.setdefault(name, rec)
    return cmds


def build_table(cmds):
    """Rows (id, name, kind, flags names) sorted by id; fails loudly on any inconsistency."""
    for group, names in (("AP_LOADER_ACCEPTS", AP_LOADER_ACCEPTS),
                         ("NAV_EXCEPTIONS", NAV_EXCEPTIONS), ("JUMP", JUMP), ("TAG", TAG),
                         ("PARAM_RULES", list(PARAM_RULES)), ("NAV_LAST", ["NAV_LAST"])):
        missing = [n for n in names if n not in cmds]
        if missing:
            fail(f"{group}: MAV_CMD_{', MAV_CMD_'.join(missing)} not in {' / '.join(XML_FILES)} "
                 f"of pymavlink {PYMAVLINK_VERSION}")
    dup = sorted({n for n in AP_LOADER_ACCEPTS if AP_LOADER_ACCEPTS.count(n) > 1})
    if dup:
        fail(f"AP_LOADER_ACCEPTS lists {dup} twice")
    for group, names in (("NAV_EXCEPTIONS", NAV_EXCEPTIONS), ("JUMP", JUMP), ("TAG", TAG),
                         ("PARAM_RULES", list(PARAM_RULES)),
                         ("AP_STORED_IN_LOCATION", AP_STORED_IN_LOCATION)):
        stray = [n for n in names if n not in AP_LOADER_ACCEPTS]
        if stray:
            fail(f"{group} names {stray}, which AP_LOADER_ACCEPTS does not list")
    known_flags = {f for f, _ in FLAG_BITS} - {"LOC"}
    for name, flags in PARAM_RULES.items():
        bad = [f for f in flags if f not in known_flags]
        if bad:
            fail(f"PARAM_RULES[{name}]: unknown flag(s) {bad}")
    nav_last = cmds["NAV_LAST"][0]
    rows = []
    for name in AP_LOADER_ACCEPTS:
        ident, loc, _ = cmds[name]
        if not 2 <= ident <= 0xFFFF:
            fail(f"MAV_CMD_{name} = {ident}: not a 16-bit mission command id")
        if name in JUMP:
            kind = "jump"
        elif name in TAG:
            kind = "tag"
        elif ident <= nav_last or name in NAV_EXCEPTIONS:
            kind = "nav"
        else:
            kind = "do"
        flags = (["LOC"] if loc or name in AP_STORED_IN_LOCATION else []) + PARAM_RULES.get(name, [])
        flags = [f for f, _ in FLAG_BITS if f in flags]  # bit order
        rows.append((ident, name, kind, flags))
    rows.sort()
    ids = [r[0] for r in rows]
    if len(set(ids)) != len(ids):
        fail(f"two names share an id: {sorted(i for i in ids if ids.count(i) > 1)}")
    return rows, nav_last


def banner(fname, brief):
    return [
        "/* SPDX-License-Identifier: Apache-2.0 */",
        "/* Generated by " + TOOL + ", do not edit; pymavlink " + PYMAVLINK_VERSION + " */",
        "/**",
        " * @file " + fname,
        " * @brief " + brief,
        " *",
        " * Every command ArduPilot's mission loader accepts"
        " (AP_Mission::mavlink_int_to_mission_cmd,",
        " * the list in " + TOOL + "), with its id and location flag from",
        " * MAVLink's common.xml and ardupilotmega.xml. `make mav-cmds` regenerates this file,",
        " * `make check-mav-cmds` (part of make test) fails when it is stale.",
        " */",
    ]


COLUMN_LIMIT = 100  # .clang-format


def align_comments(cells):
    """Lines "code /* comment */" with the comments aligned the way clang-format 14 aligns
    consecutive trailing comments (AlignTrailingComments, ColumnLimit 100): a run of lines
    shares one column while every line still fits, the next line starts a new run."""
    out, run, lo, hi = [], [], 0, 0

    def flush():
        out.extend(code.ljust(lo) + comment for code, comment in run)

    for code, comment in cells:
        need, room = len(code) + 1, COLUMN_LIMIT - len(comment)
        if need > room:
            fail(f"line too long for {COLUMN_LIMIT} columns: {code} {comment}")
        if run and (need > hi or room < lo):
            flush()
            run = []
        if not run:
            lo, hi = need, room
        else:
            lo, hi = max(lo, need), min(hi, room)
        run.append((code, comment))
    flush()
    return out


def class_comment(name, kind):
    if kind == "do" and name.startswith("CONDITION_"):
        return " (condition)"
    return ""


def render_kernel(rows, nav_last):
    out = banner("mt_mission_cmds.h",
                 "The mission command table's rows, private to mission_check.c: id, class, checks.")
    out += [
        "#ifndef MT_MISSION_CMDS_H",
        "#define MT_MISSION_CMDS_H",
        "",
        "#include \"mt/mission.h\"",
        "",
        "/* Command table flags: F_LOC is the XML's hasLocation, the others ArduPilot's parameter",
        " * rules (mission_check.c params_ok). */",
    ]
    out += align_comments([(f"#define F_{f} 0x{bit:02x}u", f"/* {FLAG_DOC[f]} */")
                           for f, bit in FLAG_BITS])
    out += [
        "",
        f"#define N_CMDS {len(rows)}u",
        "",
        "/* The rows of mission_check.c's `static const cmd_info_t k_cmds[N_CMDS]`,",
        f" * {{id, kind, flags}}, sorted by id. Class: nav when id <= {nav_last} (MAV_CMD_NAV_LAST) or one of",
        f" * AP_Mission::is_nav_cmd's exceptions ({', '.join(NAV_EXCEPTIONS)});",
        " * the conditions (CONDITION_*) are do commands. A macro, not the array itself, so that",
        " * the array stays a definition of mission_check.c alone. */",
        "/* clang-format off */",
    ]
    cells = []
    for ident, name, kind, flags in rows:
        fl = " | ".join("F_" + f for f in flags) if flags else "0u"
        cells.append((f"    {{{ident}u, {KIND_C[kind]}, {fl}}},", f"/* {name} */"))
    code_w = max(len(c) for c, _ in cells) + 1
    line_w = max(code_w + len(m) for _, m in cells) + 1
    if line_w + 1 > COLUMN_LIMIT:
        fail(f"MT_MISSION_CMD_ROWS needs {line_w + 1} columns")
    out.append("#define MT_MISSION_CMD_ROWS".ljust(line_w) + "\\")
    for k, (c, m) in enumerate(cells):
        text = c.ljust(code_w) + m
        out.append(text if k == len(cells) - 1 else text.ljust(line_w) + "\\")
    out += ["/* clang-format on */", "", "#endif /* MT_MISSION_CMDS_H */", ""]
    return "\n".join(out)


def render_names(rows):
    out = banner("mav_cmd_names.h",
                 "MAVLink names of the mission commands, private to mission/wpl.c.")
    out += [
        "#ifndef MT_MAV_CMD_NAMES_H",
        "#define MT_MAV_CMD_NAMES_H",
        "",
        "#include <stdint.h>",
        "",
        "typedef struct {",
        "    uint16_t id;",
    ]
    out += align_comments([
        ("    uint8_t location;", "/* 1: params 5-7 carry a location (hasLocation) */"),
        ("    const char *name;", "/* MAVLink name without MAV_CMD_ */")])
    out += [
        "} mt_mav_cmd_name_t;",
        "",
        f"#define MT_MAV_CMD_NAMES_COUNT {len(rows)}u",
        "",
        "/* Sorted by id; the same commands as the kernel's table"
        " (kernel/src/mt_mission_cmds.h). */",
        "static const mt_mav_cmd_name_t k_mav_cmd_names[MT_MAV_CMD_NAMES_COUNT] = {",
    ]
    for ident, name, _kind, flags in rows:
        out.append(f"    {{{ident}u, {1 if 'LOC' in flags else 0}u, \"{name}\"}},")
    out += ["};", "", "#endif /* MT_MAV_CMD_NAMES_H */", ""]
    return "\n".join(out)


def id_disjunction(ids, indent):
    """ACSL `id == a || id == b || ...` over ids, wrapped at COLUMN_LIMIT."""
    terms = [f"id == {i}" for i in ids]
    lines, cur = [], indent
    for k, t in enumerate(terms):
        piece = t + (" ||" if k < len(terms) - 1 else ";")
        if cur != indent and len(cur) + 1 + len(piece) > COLUMN_LIMIT:
            lines.append(cur)
            cur = indent
        cur = cur + piece if cur == indent else cur + " " + piece
    lines.append(cur)
    return lines


def render_spec(rows, nav_last):
    out = banner("mt_spec_mission_cmds.h",
                 "ACSL classes of the mission command ids, the ones mission_check.c's table gives.")
    out += [
        "#ifndef MT_SPEC_MISSION_CMDS_H",
        "#define MT_SPEC_MISSION_CMDS_H",
        "",
        "/* ACSL only (empty to a C compiler), included by mt_spec_mission.h: the ids of the rows of",
        " * kernel/src/mt_mission_cmds.h by class, for mt_mission_kind_of's contract, and by check",
        " * flag (MtMissionFlag*), for mt_mission_check_cmd's. The jumps (DO_JUMP, DO_JUMP_TAG) and",
        " * JUMP_TAG are mt_spec_mission.h's MtMissionIsJumpId and MT_MAV_CMD_JUMP_TAG; every other",
        " * id is unknown.",
        f" * Nav: id <= {nav_last} (MAV_CMD_NAV_LAST) or one of AP_Mission::is_nav_cmd's exceptions",
        f" * ({', '.join(NAV_EXCEPTIONS)}). Do: every other command",
        " * but the jumps and JUMP_TAG (the conditions CONDITION_* are do commands). */",
        "",
        "/*@ predicate MtMissionIsNavId(integer id) =",
    ]
    out += id_disjunction([r[0] for r in rows if r[2] == "nav"], " " * 8)
    out += [
        "    predicate MtMissionIsDoId(integer id) =",
    ]
    out += id_disjunction([r[0] for r in rows if r[2] == "do"], " " * 8)
    out += ["    // the check flags of the table's row of id (0 for an unknown id); bits as named below",
            "    logic integer MtMissionCmdFlags(integer id) ="]
    for ident, name, _, flags in rows:
        value = sum(bit for f, bit in FLAG_BITS if f in flags)
        out.append(f"        id == {ident} ? 0x{value:02x} : // {name}: {' '.join(flags) or '-'}")
    out.append("        0x00;")
    for flag, bit in FLAG_BITS:
        out += [f"    // F_{flag}: {FLAG_DOC[flag]}",
                f"    predicate MtMissionFlag{flag.capitalize()}(integer id) = "
                f"(MtMissionCmdFlags(id) & 0x{bit:02x}) != 0;"]
    out += ["*/", "", "#endif /* MT_SPEC_MISSION_CMDS_H */", ""]
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true",
                    help="regenerate in memory; exit 1 with a diff when a committed file differs")
    ap.add_argument("--list", action="store_true", help="print the table and exit")
    args = ap.parse_args()

    rows, nav_last = build_table(read_mav_cmd(pymavlink_dir()))
    if args.list:
        for ident, name, kind, flags in rows:
            cls = "condition" if class_comment(name, kind) else kind
            print(f"{ident:6d} {name:28s} {cls:9s} {' '.join(flags)}")
        return 0
    outputs = {KERNEL_OUT: render_kernel(rows, nav_last), NAMES_OUT: render_names(rows),
               SPEC_OUT: render_spec(rows, nav_last)}
    stale = 0
    for rel, text in outputs.items():
        path = os.path.join(ROOT, rel)
        try:
            with open(path, encoding="utf-8") as f:
                old = f.read()
        except FileNotFoundError:
            old = None
        if old == text:
            continue
        if args.check:
            stale += 1
            sys.stdout.writelines(difflib.unified_diff(
                (old or "").splitlines(True), text.splitlines(True),
                fromfile=f"{rel} (committed)", tofile=f"{rel} (generated)"))
        else:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
            print(f"gen_mav_cmds: wrote {rel} ({len(rows)} commands)")
    if args.check:
        if stale:
            print(f"gen_mav_cmds: {stale} generated file(s) stale: run `make mav-cmds` and commit",
                  file=sys.stderr)
            return 1
        print(f"gen_mav_cmds: {KERNEL_OUT}, {NAMES_OUT} and {SPEC_OUT} match pymavlink "
              f"{PYMAVLINK_VERSION} ({len(rows)} commands)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
