# SPDX-License-Identifier: Apache-2.0
"""Executable reference of ArduPilot's mission sequencer (AP_Mission), for the differential
test of Metronome's kernel/src/mission*.c (tests/mission_diff/run_diff.py).

Written from a reading of libraries/AP_Mission/AP_Mission.cpp (upstream master as of
2025-07, commit 90700977c553, the baseline of /work/shared/reference/ardupilot.md §1.5 and
§3.5); no ArduPilot code is reproduced. The functions below keep AP's names and structure so
that each can be checked against the one it models:

    update                    verify the nav command (or advance when none is loaded),
                              then the do part, in the same call
    advance_current_nav_cmd   drop the do command; walk (counting jumps) from one past the
                              last nav command set, or from a given index; the FIRST do
                              command passed starts if none is loaded (its start result is
                              ignored); a nav command is set and started, a refused start
                              is skipped and the walk goes on in the same call; the end of
                              the list fails the advance (the caller completes the
                              mission); 255 iterations at most
    advance_current_do_cmd    once no do command is loaded: get_next_do_cmd from the do
                              index + 1 (index 1 when there is none); nothing => all done
    get_next_do_cmd           get_next_cmd without counting; a nav command stops it
    get_next_cmd              follow DO_JUMP / DO_JUMP_TAG (a tag becomes a jump to the
                              first JUMP_TAG carrying it): repeat -1 is taken forever;
                              otherwise taken while times_run < repeat, the counter going
                              up only when counting; a jump not taken falls through and,
                              when counting, has its counter reset to 0 (PR #29763, option
                              DontZeroCounter clear); 64 jumps per call; a target outside
                              [1, total) fails; a non-counting walk that meets its first
                              jump again fails
    start / stop / resume / set_current_cmd / restart_current_nav_cmd

Where Metronome deliberately differs from AP, the difference is modelled behind a named
flag of `Deviations` (all True = Metronome's contract, all False = AP as read):

    jump_tag_silent            JUMP_TAG (600) takes the do slot and is verified true at the
                               first verify without a callback (as AP), but its start is
                               not passed to the vehicle either (AP records the tag, then
                               also calls the vehicle's start callback).
    vehicle_owns_library_do    every do/condition command goes to the vehicle's start and
                               verify callbacks. AP's library starts some do commands
                               itself (servo, relay, gripper, camera, parachute, ...) and
                               verifies them true without a callback (LIBRARY_START,
                               LIBRARY_VERIFY).
    fix_a1_bound               A-1: when 255 iterations of the nav advance pass without a
                               nav command starting, the advance fails and the mission
                               completes; a nav command started on the 255th iteration is
                               accepted. AP (uint8 post-decrement guard) returns "advanced"
                               with nothing loaded in the first case and fails right after
                               starting the command in the second.
    fix_a12_set_current        A-12: set_current(i) on a mission that is not running, when
                               the walk from i reaches the end without a nav command,
                               returns MT_E_EMPTY and changes nothing (AP clears the do
                               command, sets the nav index to none, may already have reset
                               or counted jumps, and returns false).
    resume_running_is_error    resume() while RUNNING returns MT_E_STATE and does nothing
                               (AP restarts the loaded commands through set_current_cmd).
    stop_only_when_running     stop() when not RUNNING returns MT_E_STATE and does nothing
                               (AP sets STOPPED from any state, COMPLETE included).
    advance_bound_plus_count   the nav advance may visit the command count plus 255
                               commands (MT_CFG_MISSION_ADVANCE_EXTRA) instead of 255 in
                               all: a valid mission with more than 255 do commands in a row
                               before a nav command reaches it (AP stalls there, A-1); only
                               nav starts refused inside a loop can exhaust the bound, which
                               then completes the mission (fix_a1_bound).
    jump_table_unbounded       jump counters are never lost (A-6): AP's table holds 100
                               (or 15) jumps and a full table makes finite jumps never
                               taken. With at most ~30 commands per generated mission the
                               table is never full, so this flag has no observable effect.

Not modelled (AP features Metronome does not have): landing / return-path flags, the
waypoint history and rewind-on-resume (DO_SET_RESUME_REPEAT_DIST, so `resuming_mission`
is always false), re-reading the nav command from storage on resume (the mission never
changes under the sequencer here), jump-tag ages, MIS_OPTIONS (DontZeroCounter clear).

Return values: the API methods return Metronome status codes (mt/status.h); AP's void or
bool results are mapped as Metronome's header documents them (start, update, resume,
set_current while running and restart return MT_OK also when the mission completed).

`mutant_do_after_nav` (a test of the test, not a deviation): the nav advance passes do
commands without starting them and starts the first one only after the next nav command
started, and never at the end of the list. That is the order the pre-rewrite C sequencer
used; run_diff.py --self-check asserts the comparison catches it.
"""

NONE = 0xFFFF

# Metronome status codes (kernel/include/mt/status.h)
MT_OK = 0
MT_E_INVALID = 1
MT_E_EMPTY = 3
MT_E_STATE = 23

STOPPED, RUNNING, COMPLETE = 0, 1, 2

DO_JUMP = 177
JUMP_TAG = 600
DO_JUMP_TAG = 601

# AP's highest "nav" id (MAV_CMD_NAV_LAST) and the nav ids above it
NAV_LAST = 95
NAV_EXTRA = (213, 42702, 42703)  # NAV_SET_YAW_SPEED, NAV_SCRIPT_TIME, NAV_ATTITUDE_TIME

# Do commands AP's library handles itself (used only when vehicle_owns_library_do is
# False). It starts these without the vehicle: aux function, gripper, servo/relay events,
# camera items, fence, parachute, script message, sprayer, resume-repeat distance, gimbal
# pitch/yaw; and verifies these true without the vehicle (the fence enable is not among
# them: its verify goes to the vehicle).
LIBRARY_START = frozenset((218, 211, 181, 182, 183, 184, 202, 203, 206, 2000, 2001, 531, 532,
                           534, 2500, 2501, 207, 208, 217, 216, 215, 1000))
LIBRARY_VERIFY = LIBRARY_START - {207}

ADVANCE_MAX_LOOPS = 255   # iterations of one nav advance
JUMPS_PER_WALK = 64       # jumps followed by one get_next_cmd
MILLI = 1000


def is_nav_id(cmd_id):
    """AP's classification: nav iff id <= NAV_LAST or one of the listed extras."""
    return cmd_id <= NAV_LAST or cmd_id in NAV_EXTRA


class Deviations:
    """Metronome's deliberate differences from AP (see the module docstring)."""

    NAMES = ("jump_tag_silent", "vehicle_owns_library_do", "fix_a1_bound",
             "fix_a12_set_current", "resume_running_is_error", "stop_only_when_running",
             "jump_table_unbounded", "advance_bound_plus_count")
    OFF_BY_DEFAULT = ()

    def __init__(self, metronome=True, **overrides):
        for name in self.NAMES:
            setattr(self, name, metronome and name not in self.OFF_BY_DEFAULT)
        for name, value in overrides.items():
            if name not in self.NAMES:
                raise TypeError("unknown deviation %r" % name)
            setattr(self, name, value)


class ModelError(Exception):
    """The reference was driven outside what it models (a generator bug)."""


class ApMission:
    """One mission object. cmds: list of (id, [p1, p2, p3, p4]) with the params in
    thousandths (MT_MISSION_MILLI), index 0 being home. Callbacks:
    start_fn(index) -> bool, verify_fn(index) -> bool, complete_fn()."""

    def __init__(self, cmds, start_fn, verify_fn, complete_fn, deviations=None,
                 mutant_do_after_nav=False):
        self.cmds = [(int(c[0]), [int(p) for p in c[1]]) for c in cmds]
        self.total = len(self.cmds)
        self.start_fn = start_fn
        self.verify_fn = verify_fn
        self.complete_fn = complete_fn
        self.dev = deviations if deviations is not None else Deviations()
        self.mutant = mutant_do_after_nav
        # AP's cursors and flags (AP names without the leading underscore)
        self.state = STOPPED
        self.nav_index = NONE          # _nav_cmd.index (last nav command set)
        self.nav_loaded = False        # _flags.nav_cmd_loaded
        self.do_index = NONE           # _do_cmd.index
        self.do_loaded = False         # _flags.do_cmd_loaded
        self.do_all_done = False       # _flags.do_cmd_all_done
        self.prev_nav_index = NONE     # _prev_nav_cmd_index
        self.times_run = {}            # jump tracking: jump index -> times run
        self.resuming_mission = False  # rewind-on-resume is not modelled

    # ------------------------------------------------------------ command facts
    def cmd_id(self, i):
        return self.cmds[i][0]

    def is_nav(self, i):
        return is_nav_id(self.cmd_id(i))

    def jump_of(self, i):
        """(target, repeat) of DO_JUMP / DO_JUMP_TAG at i, or None for other commands."""
        cid, p = self.cmds[i]
        if cid == DO_JUMP:
            return p[0] // MILLI, p[1] // MILLI
        if cid == DO_JUMP_TAG:
            return self.index_of_jump_tag(p[0] // MILLI), p[1] // MILLI
        return None

    def index_of_jump_tag(self, tag):
        """First JUMP_TAG carrying tag, 0 when there is none (AP get_index_of_jump_tag)."""
        for j in range(1, self.total):
            cid, p = self.cmds[j]
            if cid == JUMP_TAG and p[0] // MILLI == tag:
                return j
        return 0

    # ------------------------------------------------------------ jump resolution
    def get_next_cmd(self, start, increment):
        """Index of the first non-jump command reached from start, or None."""
        idx = start
        first_jump = NONE
        loops_left = JUMPS_PER_WALK
        while idx < self.total:
            jump = self.jump_of(idx)
            if jump is None:
                return idx
            if loops_left == 0:
                return None
            loops_left -= 1
            target, repeat = jump
            if target >= self.total or target == 0:
                return None
            if not increment and first_jump == idx:
                return None
            if first_jump == NONE:
                first_jump = idx
            if repeat == -1 or self.times_run.get(idx, 0) < repeat:
                if increment and not self.resuming_mission:
                    self.times_run[idx] = self.times_run.get(idx, 0) + 1
                idx = target
            else:
                if increment:
                    # a completed loop forgets its count (DontZeroCounter clear)
                    self.times_run[idx] = 0
                idx += 1
        return None

    def get_next_do_cmd(self, start):
        if start >= self.total:
            return None
        r = self.get_next_cmd(start, False)
        if r is None or self.is_nav(r):
            return None
        return r

    # ------------------------------------------------------------ start / verify
    def start_command(self, i):
        cid = self.cmd_id(i)
        if cid == JUMP_TAG and self.dev.jump_tag_silent:
            return True
        if cid in LIBRARY_START and not self.dev.vehicle_owns_library_do:
            return True
        return self.start_fn(i)

    def verify_command(self, i):
        cid = self.cmd_id(i)
        if cid == JUMP_TAG:
            return True
        if cid in LIBRARY_VERIFY and not self.dev.vehicle_owns_library_do:
            return True
        return self.verify_fn(i)

    def complete(self):
        self.state = COMPLETE
        self.complete_fn()

    # ------------------------------------------------------------ the two cursors
    def advance_current_nav_cmd(self, starting_index=0):
        if self.state != RUNNING or self.nav_loaded:
            return False
        self.do_index = NONE
        self.do_loaded = False
        self.do_all_done = False
        cmd_index = starting_index - 1 if starting_index > 0 else self.nav_index
        cmd_index = 1 if cmd_index == NONE else cmd_index + 1
        pending_do = NONE   # mutant only: the do command it will start after the nav command
        iterations = 0
        bound = ADVANCE_MAX_LOOPS
        if self.dev.advance_bound_plus_count:
            bound += self.total
        while not self.nav_loaded and iterations < bound:
            iterations += 1
            r = self.get_next_cmd(cmd_index, True)
            if r is None:
                return False
            if self.is_nav(r):
                self.prev_nav_index = self.nav_index
                self.nav_index = r
                if self.start_command(r):
                    self.nav_loaded = True
                    if self.mutant and pending_do != NONE:
                        self.do_index = pending_do
                        self.do_loaded = True
                        self.start_command(pending_do)
            elif not self.do_loaded and pending_do == NONE:
                if self.mutant:
                    pending_do = r
                else:
                    self.do_index = r
                    self.do_loaded = True
                    self.start_command(r)   # the result is ignored
            cmd_index = r + 1
        if self.dev.fix_a1_bound:
            if not self.nav_loaded:
                return False
        else:
            # AP's guard: loaded on the 255th iteration => failure; never loaded => the
            # post-decrement wraps and the advance "succeeds" with nothing loaded
            if self.nav_loaded and iterations == bound:
                return False
        if not self.do_loaded:
            self.do_all_done = True
        return True

    def advance_current_do_cmd(self):
        if self.state != RUNNING or self.do_all_done:
            return
        start = 1 if self.do_index == NONE else self.do_index + 1
        r = self.get_next_do_cmd(start)
        if r is None:
            self.do_all_done = True
            return
        self.do_index = r
        self.do_loaded = True
        self.start_command(r)

    # ------------------------------------------------------------ AP's own entry points
    def reset(self):
        self.nav_loaded = False
        self.do_loaded = False
        self.do_all_done = False
        self.nav_index = NONE
        self.do_index = NONE
        self.prev_nav_index = NONE
        self.times_run = {}

    def set_current_cmd(self, index):
        """AP set_current_cmd; returns AP's bool."""
        if index >= self.total or self.total == 1:
            return False
        self.do_index = NONE
        self.do_loaded = False
        self.do_all_done = False
        self.nav_loaded = False
        if index == 0 or self.state == COMPLETE:
            self.prev_nav_index = NONE
            self.times_run = {}
            if index == 0:
                index = 1
        if self.state != RUNNING:
            guard = 0
            while not self.nav_loaded:
                guard += 1
                if guard > 100000:
                    raise ModelError("set_current_cmd walk does not end (do-only loop?)")
                r = self.get_next_cmd(index, True)
                if r is None:
                    self.nav_index = NONE
                    return False
                if self.is_nav(r):
                    self.nav_index = r
                    self.nav_loaded = True
                elif not self.do_loaded:
                    self.do_index = r
                    self.do_loaded = True
                index = r + 1
            if not self.do_loaded:
                self.do_all_done = True
            self.state = STOPPED
            return True
        if not self.advance_current_nav_cmd(index):
            self.complete()
            return False
        return True

    # ------------------------------------------------------------ Metronome's API
    def start(self):
        if self.total < 2:
            return MT_E_EMPTY
        self.state = RUNNING
        self.reset()
        if not self.advance_current_nav_cmd():
            self.complete()
        return MT_OK

    def stop(self):
        if self.dev.stop_only_when_running and self.state != RUNNING:
            return MT_E_STATE
        self.state = STOPPED
        return MT_OK

    def resume(self):
        if self.state == RUNNING and self.dev.resume_running_is_error:
            return MT_E_STATE
        if self.total < 2:
            return MT_E_EMPTY
        if self.state == COMPLETE:
            return self.start()
        if self.state == STOPPED:
            self.state = RUNNING
            if self.nav_index == NONE:
                return self.start()
        if self.do_loaded and self.do_index != NONE:
            self.set_current_cmd(self.do_index)
        elif self.nav_loaded:
            self.set_current_cmd(self.nav_index)
        return MT_OK

    def snapshot(self):
        return (self.state, self.nav_index, self.nav_loaded, self.do_index, self.do_loaded,
                self.do_all_done, self.prev_nav_index, dict(self.times_run))

    def restore(self, s):
        (self.state, self.nav_index, self.nav_loaded, self.do_index, self.do_loaded,
         self.do_all_done, self.prev_nav_index, times) = s
        self.times_run = dict(times)

    def set_current(self, i):
        if self.total < 2:
            return MT_E_EMPTY
        if i >= self.total:
            return MT_E_INVALID
        if self.state == RUNNING:
            self.set_current_cmd(i)
            return MT_OK
        saved = self.snapshot()
        if self.set_current_cmd(i):
            return MT_OK
        if self.dev.fix_a12_set_current:
            self.restore(saved)
        return MT_E_EMPTY

    def restart_current(self):
        if self.state != RUNNING:
            return MT_E_STATE
        if self.nav_index == 0 or self.nav_index >= self.total:
            return MT_E_STATE
        self.set_current_cmd(self.nav_index)
        return MT_OK

    def update(self):
        if self.state != RUNNING or self.total == 0:
            return MT_E_STATE
        if not self.nav_loaded or self.nav_index == NONE:
            if not self.advance_current_nav_cmd():
                self.complete()
                return MT_OK
        elif self.verify_command(self.nav_index):
            self.nav_loaded = False
            if not self.advance_current_nav_cmd():
                self.complete()
                return MT_OK
        if not self.do_loaded:
            self.advance_current_do_cmd()
        elif self.verify_command(self.do_index):
            self.do_loaded = False
        return MT_OK

    # ------------------------------------------------------------ observations
    def current_nav(self):
        """The nav command that is loaded (Metronome: mt_mission_get's is_current)."""
        if self.nav_loaded and self.state != COMPLETE:
            return self.nav_index
        return NONE

    def jump_count(self, i):
        """Times the finite jump at i was taken since its last reset (0 otherwise)."""
        jump = self.jump_of(i)
        if jump is None or jump[1] < 0:
            return 0
        return self.times_run.get(i, 0)
