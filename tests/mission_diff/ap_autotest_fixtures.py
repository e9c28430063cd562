# SPDX-License-Identifier: Apache-2.0
"""Regression fixtures whose expectations come from ArduPilot's own SITL autotests
(Tools/autotest), not from ap_mission_ref.py. run_diff.py --fixtures runs each mission with
every callback answering true (start, then updates) through the reference and the C driver,
and checks the expectations on both event streams.

Each fixture: the mission (home first; the autotest's mission file translated to
mt_mission_cmd_t rows [id, frame, options, p1..p4 x1000, lat, lon (1e-7 deg), alt (cm)]), the
script, the expectations, and where they come from. The autotests watch a simulated
vehicle, so what they assert is coarser than a callback order; each fixture says what the
autotest observes and how that becomes the expectation:

    ("starts", [...])          exact order of the start callbacks
    ("started", i)             command i is started at some point
    ("before", a, b)           a starts before b
    ("during", d, prev, nav)   d starts after nav command prev completed (verify true) and
                               before nav command nav completed: d is in effect on the leg
                               to nav
    ("complete_after", i)      the mission completes after command i started

Mission files are quoted by their path and the commit of ArduPilot/ardupilot that holds
them; the test functions by file and name (they were renamed over time, both names given).
"""

HOME = [16, 0, 1, 0, 0, 0, 0, -353632620, 1491652370, 58400]


def loc(lat_deg, lon_deg, alt_m):
    return [int(round(lat_deg * 1e7)), int(round(lon_deg * 1e7)), int(round(alt_m * 100))]


def nav(cid, lat=0.0, lon=0.0, alt=0.0, p=(0, 0, 0, 0)):
    return [cid, 3, 1] + [int(round(v * 1000)) for v in p] + loc(lat, lon, alt)


def do(cid, p=(0, 0, 0, 0)):
    return [cid, 2, 1] + [int(round(v * 1000)) for v in p] + [0, 0, 0]


FIXTURES = [
    {
        "name": "copter_parachute_at_end",
        # QGC WPL: 1 TAKEOFF 20 m; 2 DO_PARACHUTE p1=2 (release); nothing after it
        "cmds": [HOME,
                 nav(22, alt=20),
                 do(208, (2, 0, 0, 0))],
        "ops": [("start",), ("update", 4)],
        "expect": [("starts", [1, 2]), ("complete_after", 2)],
        "source": {
            "test": "arducopter.py test_parachute (later Parachute), 'Test triggering "
                    "parachute in mission'",
            "mission": "Tools/autotest/ArduCopter_Tests/Parachute/copter_parachute_mission.txt "
                       "@ 649adbc9b81a8cdb78b867f1cdc6a24b90c5f2c0",
            "observed": "after AUTO and throttle up the test waits for the simulated "
                        "parachute's 'BANG': the DO_PARACHUTE after the last nav command is "
                        "started once the takeoff completes, and nothing follows it",
        },
    },
    {
        "name": "plane_parachute_at_end",
        # 1 TAKEOFF 10 m; 2 WAYPOINT; 3 DO_PARACHUTE p1=2
        "cmds": [HOME,
                 nav(22, -35.362125, 149.165039, 10),
                 nav(16, -35.364845, 149.163452, 11),
                 do(208, (2, 0, 0, 0))],
        "ops": [("start",), ("update", 5)],
        "expect": [("starts", [1, 2, 3]), ("complete_after", 3)],
        "source": {
            "test": "arduplane.py test_parachute (later Parachute)",
            "mission": "Tools/autotest/ArduPlane_Tests/Parachute/plane-parachute-mission.txt "
                       "@ 649adbc9b81a8cdb78b867f1cdc6a24b90c5f2c0",
            "observed": "set waypoint 1, AUTO, arm, then wait_statustext('BANG'): the "
                        "trailing DO_PARACHUTE starts after the last waypoint",
        },
    },
    {
        "name": "plane_do_change_speed_legs",
        # 1 WP; 2 DCS 10; 3 WP; 4 DCS 20; 5 WP; 6 DCS 15; 7 WP; 8 WP
        "cmds": [HOME,
                 nav(16, -35.366949, 149.172570, 50),
                 do(178, (0, 10, 0, 0)),
                 nav(16, -35.361489, 149.166778, 50),
                 do(178, (0, 20, 0, 0)),
                 nav(16, -35.362949, 149.162221, 50),
                 do(178, (0, 15, 0, 0)),
                 nav(16, -35.364969, 149.165044, 50),
                 nav(16, -35.361791, 149.165045, 50)],
        "ops": [("start",), ("update", 12)],
        "expect": [("during", 2, 1, 3), ("during", 4, 3, 5), ("during", 6, 5, 7),
                   ("before", 2, 4), ("before", 4, 6)],
        "source": {
            "test": "arduplane.py DO_CHANGE_SPEED -> DO_CHANGE_SPEED_mission",
            "mission": "Tools/autotest/ArduPlane_Tests/DO_CHANGE_SPEED/mission.txt "
                       "@ 649adbc9b81a8cdb78b867f1cdc6a24b90c5f2c0",
            "observed": "checks (current waypoint, airspeed) = (1, trim), (3, 10), (5, 20), "
                        "(7, 15), each held 5 s: the DO_CHANGE_SPEED before waypoint k is in "
                        "effect while k is the current waypoint, not before the previous one "
                        "completed",
        },
    },
    {
        "name": "takeoff_change_speed_waypoint",
        # the smallest case of the pattern above: 1 TAKEOFF; 2 DO_CHANGE_SPEED; 3 WAYPOINT
        "cmds": [HOME,
                 nav(22, alt=10),
                 do(178, (1, 15, 0, 0)),
                 nav(16, -35.362656, 149.165072, 20)],
        "ops": [("start",), ("update", 4)],
        "expect": [("starts", [1, 2, 3]), ("during", 2, 1, 3)],
        "source": {
            "test": "arduplane.py DO_CHANGE_SPEED_mission (the pattern); arducopter.py "
                    "DO_CHANGE_SPEED uses the same layout (TAKEOFF, WAYPOINT, DCS, WAYPOINT...)",
            "mission": "rows 1-3 of Tools/autotest/ArduCopter_Tests/DO_CHANGE_SPEED/mission.txt "
                       "@ 2ccf64f962e8346c0f193e2ec17c6d6a2af86ff7 (its row 2 waypoint dropped)",
            "observed": "the new speed holds on the leg to the waypoint after the "
                        "DO_CHANGE_SPEED. The strict order 1, 2, 3 (the speed change started "
                        "before the waypoint, in the same update) is what the autotest's "
                        "timing cannot separate from 1, 3, 2; it is AP_Mission's "
                        "advance_current_nav_cmd order, kept here because the brief requires it",
        },
    },
    {
        "name": "copter_gripper_grab_release",
        # 1 TAKEOFF 5 m; 2 DO_GRIPPER grab; 3 DO_GRIPPER release; 4 LAND
        "cmds": [HOME,
                 nav(22, alt=5),
                 do(211, (0, 1, 0, 0)),
                 do(211, (0, 0, 0, 0)),
                 nav(21, p=(0, 0, 0, 1))],
        # a landing takes many updates: nav commands verify true one update in four, do
        # commands at once (every other fixture answers true to everything)
        "probs": (1000, 1000, 250, 1000),
        "seed": 3,
        "ops": [("start",), ("update", 40)],
        "expect": [("started", 2), ("started", 3), ("before", 2, 3), ("during", 2, 1, 4),
                   ("during", 3, 1, 4)],
        "source": {
            "test": "arducopter.py test_gripper_mission (later TestGripperMission / "
                    "GripperMission)",
            "mission": "Tools/autotest/ArduCopter_Tests/TestGripperMission/"
                       "copter-gripper-mission.txt @ 25d1be144a945aac4e072d644bb3a5475b97fcd7",
            "observed": "AUTO, then expects 'Gripper Grabbed' and after it 'Gripper "
                        "Released' before the landing ends the flight: both do commands "
                        "between TAKEOFF and LAND run, in list order, after the takeoff",
        },
    },
]
