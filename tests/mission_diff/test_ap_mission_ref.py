# SPDX-License-Identifier: Apache-2.0
"""Hand-worked cases of the AP_Mission reference (ap_mission_ref.py), each derived by
stepping through AP_Mission.cpp on paper, and the deviation flags switched both ways.

    python3 -m pytest -q tests/mission_diff
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import ap_mission_ref as ref  # noqa: E402

HOME = (16, [0, 0, 0, 0])
WP = (16, [0, 0, 0, 0])
DCS = (178, [0, 5000, 0, 0])
DELAY = (112, [3000, 0, 0, 0])
CHUTE = (208, [2000, 0, 0, 0])


def jump(target, repeat):
    return (177, [target * 1000, repeat * 1000, 0, 0])


def tag(t):
    return (600, [t * 1000, 0, 0, 0])


def jump_tag(t, repeat):
    return (601, [t * 1000, repeat * 1000, 0, 0])


class Vehicle:
    """Records the callbacks; answers from per-index tables (default true)."""

    def __init__(self, start=None, verify=None):
        self.log = []
        self.start_ans = start or {}
        self.verify_ans = verify or {}

    def start(self, i):
        self.log.append(("start", i))
        ans = self.start_ans.get(i, True)
        return ans(i) if callable(ans) else ans

    def verify(self, i):
        ans = self.verify_ans.get(i, True)
        ok = ans(i) if callable(ans) else ans
        self.log.append(("verify", i, ok))
        return ok

    def complete(self):
        self.log.append(("complete",))

    def starts(self):
        return [e[1] for e in self.log if e[0] == "start"]


def mission(cmds, vehicle, **dev):
    return ref.ApMission([HOME] + cmds, vehicle.start, vehicle.verify, vehicle.complete,
                         ref.Deviations(**dev))


def test_first_do_starts_before_the_next_nav_in_the_same_update():
    v = Vehicle()
    m = mission([WP, DCS, DELAY, WP], v)
    m.start()
    m.update()   # WP 1 verifies; DCS 2 starts, WP 4 starts; DCS 2 verifies (same update)
    assert v.log[1:] == [("verify", 1, True), ("start", 2), ("start", 4), ("verify", 2, True)]
    m.update()   # WP 4 verify true => advance (nothing left) => complete; DELAY 3 never ran
    assert v.log[-1] == ("complete",) and 3 not in v.starts()


def test_later_do_commands_run_one_per_update_while_the_nav_runs():
    v = Vehicle(verify={4: False})
    m = mission([WP, DCS, DELAY, WP], v)
    m.start()
    m.update()
    m.update()   # WP 4 still running; the do search starts DELAY 3
    assert v.starts() == [1, 2, 4, 3]


def test_trailing_do_command_starts_then_the_mission_completes():
    v = Vehicle()
    m = mission([WP, CHUTE], v)
    m.start()
    m.update()
    assert v.log[1:] == [("verify", 1, True), ("start", 2), ("complete",)]
    assert m.state == ref.COMPLETE


def test_refused_nav_start_is_skipped_in_the_same_walk():
    v = Vehicle(start={2: False})
    m = mission([WP, WP, DCS, WP], v)
    m.start()
    m.update()   # WP 2 refused; DCS 3 is the first do passed; WP 4 starts
    assert v.starts() == [1, 2, 3, 4]
    assert m.current_nav() == 4 and m.prev_nav_index == 2


def test_finite_jump_counts_then_falls_through_and_resets():
    v = Vehicle()
    m = mission([WP, jump(1, 2), WP], v)
    m.start()
    for _ in range(3):
        m.update()
    assert v.starts() == [1, 1, 1, 3]
    assert m.jump_count(2) == 0      # fell through: reset to 0 (PR #29763)


def test_do_search_does_not_count_jumps():
    v = Vehicle(verify={3: False})
    m = mission([WP, DCS, jump(2, 5), WP], v)
    m.start()
    m.update()   # advance from 2: DCS 2, jump 3 taken (count 1) -> DCS 2 passed again, ... WP 4
    # the counting walk passes the jump until it falls through: 5 takes, then reset
    assert v.starts()[:3] == [1, 2, 4]
    assert m.jump_count(3) == 0
    before = dict(m.times_run)
    m.update()   # do search from 3: the jump (count 0 < 5) is taken without counting
    assert m.times_run == before


def test_do_jump_tag_goes_to_the_first_jump_tag():
    v = Vehicle()
    m = mission([tag(7), WP, tag(7), jump_tag(7, 1), WP], v)
    m.start()
    # JUMP_TAG 1 takes the do slot silently; WP 2 starts
    assert v.starts() == [2] and m.do_index == 1
    m.update()   # WP 2 done: walk 3 (tag, do slot), 4 jump -> 1 (taken once), 1 tag, 2 = WP
    assert v.starts() == [2, 2] and m.jump_count(4) == 1
    m.update()   # WP 2 done again: 3 tag, 4 jump falls through (count back to 0), 5 = WP
    assert v.starts() == [2, 2, 5] and m.jump_count(4) == 0
    assert not [e for e in v.log if e[0] == "verify" and e[1] in (1, 3)]


def test_jump_tag_start_goes_to_the_vehicle_without_the_flag():
    v = Vehicle()
    m = mission([tag(3), WP], v, jump_tag_silent=False)
    m.start()
    assert v.starts() == [1, 2]


def test_a1_bound_completes_with_the_fix_and_stalls_without():
    never = {1: False}
    v = Vehicle(start=never)
    m = mission([WP, jump(1, -1)], v)
    m.start()    # WP 1 refused forever: 3 + 255 walks, then the fix completes the mission
    assert v.starts() == [1] * (3 + 255) and m.state == ref.COMPLETE
    v2 = Vehicle(start=never)
    m2 = mission([WP, jump(1, -1)], v2, fix_a1_bound=False, advance_bound_plus_count=False)
    m2.start()   # AP: "advanced" with nothing loaded, still RUNNING
    assert m2.state == ref.RUNNING and not m2.nav_loaded


def test_a1_nav_started_on_the_255th_walk():
    v = Vehicle(start={1: lambda i: len(v.log) >= 255})
    m = mission([WP, jump(1, -1)], v)
    m.start()
    assert m.state == ref.RUNNING and m.current_nav() == 1
    v2 = Vehicle(start={1: lambda i: len(v2.log) >= 255})
    m2 = mission([WP, jump(1, -1)], v2, fix_a1_bound=False, advance_bound_plus_count=False)
    m2.start()   # AP: started on the 255th iteration, then reported as a failure
    assert len(v2.starts()) == 255 and m2.state == ref.COMPLETE


def test_a12_set_current_past_the_last_nav_changes_nothing():
    v = Vehicle(verify={2: False})
    m = mission([WP, WP, DCS], v)
    m.start()
    m.update()
    m.stop()
    before = m.snapshot()
    assert m.set_current(3) == ref.MT_E_EMPTY and m.snapshot() == before
    m2 = mission([WP, WP, DCS], Vehicle(verify={2: False}), fix_a12_set_current=False)
    m2.start()
    m2.update()
    m2.stop()
    assert m2.set_current(3) == ref.MT_E_EMPTY and m2.nav_index == ref.NONE


def test_set_current_when_stopped_preloads_and_resume_starts_do_then_nav():
    v = Vehicle()
    m = mission([WP, DCS, WP], v)
    assert m.set_current(2) == ref.MT_OK and m.state == ref.STOPPED
    assert m.do_index == 2 and m.current_nav() == 3 and v.log == []
    assert m.resume() == ref.MT_OK
    assert v.starts() == [2, 3]


def test_resume_and_stop_state_rules():
    v = Vehicle(verify={1: False})
    m = mission([WP], v)
    m.start()
    assert m.resume() == ref.MT_E_STATE
    assert mission([WP], Vehicle(), resume_running_is_error=False).resume() == ref.MT_OK
    m.stop()
    assert m.stop() == ref.MT_E_STATE
    m3 = mission([WP], Vehicle(), stop_only_when_running=False)
    assert m3.stop() == ref.MT_OK


def test_mutant_starts_the_do_command_after_the_nav_command():
    v = Vehicle()
    m = ref.ApMission([HOME, WP, DCS, WP, CHUTE], v.start, v.verify, v.complete,
                      mutant_do_after_nav=True)
    m.start()
    m.update()
    m.update()
    assert v.starts() == [1, 3, 2]   # and the trailing parachute never starts
