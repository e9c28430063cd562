// SPDX-License-Identifier: Apache-2.0
// Mission sequencer (mt/mission.h): every command kind, every status, jumps,
// the do cursor, stop/resume in every state, and the fixed reference defects.
#include <cstring>

#include "mission_test_util.h"
#include "mt/status.h"

using namespace mt_test;

namespace
{

std::vector<mt_mission_cmd_t> Plain()
{
    return {Home(), Takeoff(), Wp(1), Wp(2), Land()};
}

TEST(Mission, KindOfClassifiesEveryNamedCommand)
{
    const uint16_t navs[] = {16, 17, 18, 19, 20, 21, 22, 82, 30, 31, 84, 85, 93, 94, 213, 42702};
    const uint16_t dos[] = {112, 114, 115, 178, 179, 183, 189, 181, 201, 206, 211, 3000};
    for (uint16_t id : navs) {
        EXPECT_EQ(mt_mission_kind_of(id), MT_MISSION_KIND_NAV) << id;
    }
    for (uint16_t id : dos) {
        EXPECT_EQ(mt_mission_kind_of(id), MT_MISSION_KIND_DO) << id;
    }
    EXPECT_EQ(mt_mission_kind_of(177), MT_MISSION_KIND_JUMP);
    EXPECT_EQ(mt_mission_kind_of(601), MT_MISSION_KIND_JUMP);
    EXPECT_EQ(mt_mission_kind_of(600), MT_MISSION_KIND_TAG);
    EXPECT_EQ(mt_mission_kind_of(0), MT_MISSION_KIND_HOME);
    EXPECT_EQ(mt_mission_kind_of(9999), MT_MISSION_KIND_HOME);
}

TEST(Mission, PlainWaypointsRunInOrderAndCompleteOnce)
{
    Vehicle v;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    EXPECT_EQ(v.m->state, MT_MISSION_STOPPED);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    EXPECT_EQ(v.m->nav, 1);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 3 4");
    EXPECT_EQ(v.completes, 1);
    EXPECT_EQ(v.m->state, MT_MISSION_COMPLETE);
    EXPECT_EQ(v.m->completions, 1u);
    // further updates do nothing and never complete twice
    EXPECT_EQ(mt_mission_update(v.m.get()), MT_E_STATE);
    EXPECT_EQ(v.completes, 1);
}

TEST(Mission, NavCursorWaitsForVerify)
{
    Vehicle v;
    v.verify_after[2] = 3;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    mt_mission_update(v.m.get()); // 1 verifies, 2 starts
    EXPECT_EQ(v.m->nav, 2);
    mt_mission_update(v.m.get());
    mt_mission_update(v.m.get());
    mt_mission_update(v.m.get());
    EXPECT_EQ(v.m->nav, 2);
    mt_mission_update(v.m.get());
    EXPECT_EQ(v.m->nav, 3);
    EXPECT_EQ(v.m->prev_nav, 2);
}

TEST(Mission, FirstDoStartsBeforeNextNavTheRestOneAtATime)
{
    // AP advance_current_nav_cmd / advance_current_do_cmd. 1 takeoff, 2 speed, 3 delay,
    // 4 servo, 5 wp, 6 land: when the takeoff verifies, the walk to the waypoint starts the
    // speed command (the first do command it passes) and then the waypoint, in that order;
    // the speed command is verified in the same update; the delay and the servo start one
    // at a time, each at the update after the previous one verified, while the waypoint runs.
    Vehicle v;
    v.verify_after[5] = 100; // wp takes long
    v.verify_after[3] = 2;   // delay verifies on its third check
    ASSERT_EQ(v.Load({Home(), Takeoff(), Speed(), Delay(), Servo(), Wp(), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    EXPECT_EQ(v.Log(), "S1");
    EXPECT_EQ(v.m->do_done, 1); // no do command before the takeoff
    mt_mission_update(v.m.get());
    EXPECT_EQ(v.Log(), "S1 V1 S2 S5 V2");
    EXPECT_EQ(v.m->nav, 5);
    EXPECT_EQ(v.m->do_cmd, MT_MISSION_NONE);
    mt_mission_update(v.m.get()); // V5 false, the do search starts the delay
    EXPECT_EQ(v.m->do_cmd, 3);
    mt_mission_update(v.m.get());
    mt_mission_update(v.m.get());
    EXPECT_EQ(v.m->do_cmd, 3);    // the condition holds back the servo, not the waypoint
    mt_mission_update(v.m.get()); // delay verifies
    EXPECT_EQ(v.m->do_cmd, MT_MISSION_NONE);
    mt_mission_update(v.m.get()); // servo starts
    EXPECT_EQ(v.m->do_cmd, 4);
    mt_mission_update(v.m.get());
    EXPECT_EQ(v.m->do_done, 0);
    mt_mission_update(v.m.get()); // the do search reaches nav 5: do_done
    EXPECT_EQ(v.m->do_done, 1);
    EXPECT_EQ(v.Starts(), "1 2 5 3 4");
    EXPECT_EQ(v.m->nav, 5);
}

TEST(Mission, DoBetweenTwoNavsStartsBeforeTheSecond)
{
    // The case: TAKEOFF, DO_CHANGE_SPEED, WAYPOINT starts 1, 2, 3 (not 1, 3, 2).
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Speed(), Wp()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 3");
    EXPECT_EQ(v.Log(), "S1 V1 S2 S3 V2 V3 C");
}

TEST(Mission, UnfinishedDoCommandsAreDroppedWhenNavCompletes)
{
    // 1 takeoff, 2 delay (never done), 3 servo, 4 wp, 5 land
    Vehicle v;
    v.verify_after[2] = 1000;
    v.verify_after[4] = 3;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Delay(), Servo(), Wp(), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 4 5"); // servo 3 never started: the delay held it back
    EXPECT_EQ(v.completes, 1);
}

TEST(Mission, LeadingDoStretchRunsDuringFirstNav)
{
    Vehicle v;
    v.verify_after[3] = 5;
    ASSERT_EQ(v.Load({Home(), Speed(), Servo(), Takeoff(), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 3 2 4"); // speed, takeoff; the servo while the takeoff runs
}

TEST(Mission, TrailingDoCommandStartsThenMissionCompletes)
{
    // AP: the walk past the last nav command starts the first do command it passes, then
    // reaches the end and completes the mission in the same update (the autotest waits
    // for a trailing DO_PARACHUTE to fire). A second trailing do command is passed.
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Land(), Servo(), Speed()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 3");
    EXPECT_EQ(v.Log(), "S1 V1 S2 V2 S3 C");
    EXPECT_EQ(v.completes, 1);

    Vehicle p;
    const mt_mission_cmd_t parachute = Cmd(208, 2 * MT_MISSION_MILLI, 0, 0, 0, 0, 0, 0, 2);
    ASSERT_EQ(p.Load({Home(), Takeoff(), parachute}), MT_OK);
    ASSERT_EQ(mt_mission_start(p.m.get()), MT_OK);
    p.Run();
    EXPECT_EQ(p.Log(), "S1 V1 S2 C");
}

TEST(Mission, DoOnlyMissionStartsItsFirstDoAndCompletesAtStart)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Servo(), Speed()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    EXPECT_EQ(v.m->state, MT_MISSION_COMPLETE);
    EXPECT_EQ(v.completes, 1);
    EXPECT_EQ(v.Log(), "S1 C");
}

TEST(Mission, RefusedNavStartIsSkipped)
{
    Vehicle v;
    v.refuse[2] = true;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    mt_mission_update(v.m.get()); // 2 refuses: the walk goes on to 3 in the same update
    EXPECT_EQ(v.Log(), "S1 V1 S2 S3");
    EXPECT_EQ(v.m->nav, 3);
    EXPECT_EQ(v.m->prev_nav, 2);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 3 4");
    EXPECT_EQ(v.log.end() - std::find(v.log.begin(), v.log.end(), "V2"), 0); // never verified
    EXPECT_EQ(v.completes, 1);
}

TEST(Mission, RefusedDoStartIsIgnored)
{
    // AP ignores a do command's start result: it stays active until it verifies.
    Vehicle v;
    v.refuse[2] = true;
    v.verify_after[2] = 1;
    v.verify_after[3] = 10;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Servo(), Speed(), Wp(), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.verify_after[4] = 10;
    mt_mission_update(v.m.get());
    EXPECT_EQ(v.Log(), "S1 V1 S2 S4 V2");
    EXPECT_EQ(v.m->do_cmd, 2);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 4 3 5");
}

TEST(Mission, ConditionsLandAndRtlAreSequenced)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Delay(2), Cmd(MT_MAV_CMD_CONDITION_DISTANCE, 5000),
                      Cmd(MT_MAV_CMD_CONDITION_YAW, 90000, 10000, MT_MISSION_MILLI, 0), Wp(), Rtl(),
                      Land()}),
              MT_OK);
    v.verify_after[5] = 10;
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 5 3 4 6 7");
}

// ------------------------------------------------------------------ jumps

TEST(Mission, FiniteJumpRepeatsThenFallsThroughAndResets)
{
    // 1 wp, 2 wp, 3 jump->1 x2, 4 land
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Jump(1, 2), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    int k = 0;
    while (v.m->state == MT_MISSION_RUNNING && k++ < 100) {
        mt_mission_update(v.m.get());
        EXPECT_LE(mt_mission_jump_count(v.m.get(), 3), 2);
        EXPECT_GE(mt_mission_jump_count(v.m.get(), 3), 0);
    }
    EXPECT_EQ(v.Starts(), "1 2 1 2 1 2 4");
    EXPECT_EQ(mt_mission_jump_count(v.m.get(), 3), 0); // reset on fall-through
    EXPECT_FALSE(v.saw_jump);
}

TEST(Mission, RepeatZeroJumpIsNeverTaken)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Jump(1, 0), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 3");
}

TEST(Mission, RepeatForeverNeverCompletes)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Servo(), Wp(2), Jump(1, -1), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.verify_after[3] = 0;
    int n = v.Run(200);
    EXPECT_EQ(n, 200);
    EXPECT_EQ(v.completes, 0);
    EXPECT_EQ(v.m->state, MT_MISSION_RUNNING);
    EXPECT_EQ(mt_mission_jump_count(v.m.get(), 4), 0);
    EXPECT_FALSE(v.saw_jump);
}

TEST(Mission, NestedJumps)
{
    // 1 wp, 2 wp, 3 jump->2 x1, 4 jump->1 x1, 5 land
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Jump(2, 1), Jump(1, 1), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 2 1 2 2 5");
}

TEST(Mission, JumpTagsResolveToFirstTag)
{
    // 1 takeoff, 2 tag 7, 3 wp, 4 jump-tag 7 x2, 5 land
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Tag(7), Wp(1), JumpTag(7, 2), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 3 3 3 5");
    EXPECT_FALSE(v.saw_jump);
}

TEST(Mission, JumpToJumpIsFollowed)
{
    // 1 wp, 2 jump->4 forever (goto), 3 wp (skipped), 4 jump->5 x0? no: 4 land
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Jump(4, -1), Wp(3), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 4");
}

TEST(Mission, NextNavIsPureAndMatchesExecution)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Servo(), Wp(2), Jump(1, 3), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    int checked = 0;
    for (int k = 0; k < 100 && v.m->state == MT_MISSION_RUNNING; k++) {
        // the look-ahead from past the active nav command predicts the next one loaded
        std::unique_ptr<mt_mission_t> before(new mt_mission_t(*v.m));
        uint16_t predicted = MT_MISSION_NONE;
        mt_status_t st =
            mt_mission_next_nav(v.m.get(), static_cast<uint16_t>(v.m->nav_idx + 1u), &predicted);
        EXPECT_EQ(std::memcmp(before.get(), v.m.get(), sizeof(mt_mission_t)), 0)
            << "look-ahead changed state";
        const uint16_t nav = v.m->nav;
        mt_mission_update(v.m.get());
        if (v.m->state == MT_MISSION_RUNNING && v.m->nav != nav) {
            ASSERT_EQ(st, MT_OK);
            EXPECT_EQ(v.m->nav, predicted);
            checked++;
        }
        if (v.m->state == MT_MISSION_COMPLETE) {
            EXPECT_NE(st, MT_OK); // nothing after the land
        }
    }
    EXPECT_EQ(checked, 8); // 1 -> 3, 3 -> 1 (three times more), 1 -> 3, 3 -> 5
    EXPECT_EQ(v.Starts(), "1 2 3 1 2 3 1 2 3 1 2 3 5");
    uint16_t out = 0;
    EXPECT_EQ(mt_mission_next_nav(v.m.get(), 0, &out), MT_E_INVALID);
    EXPECT_EQ(out, MT_MISSION_NONE);
    EXPECT_EQ(mt_mission_next_nav(v.m.get(), 6, &out), MT_E_INVALID);
    EXPECT_EQ(mt_mission_next_nav(v.m.get(), 2, &out), MT_OK);
    EXPECT_EQ(out, 3);
}

TEST(Mission, NextNavReportsEnd)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Servo()}), MT_OK);
    uint16_t out = 0;
    EXPECT_EQ(mt_mission_next_nav(v.m.get(), 2, &out), MT_E_EMPTY);
    EXPECT_EQ(out, MT_MISSION_NONE);
}

// ------------------------------------------------------------------ validation statuses

struct Bad {
    const char *what;
    std::vector<mt_mission_cmd_t> cmds;
    mt_status_t st;
    uint16_t index;
};

TEST(MissionCheck, EveryRejectionHasItsStatusAndIndex)
{
    mt_mission_cmd_t nan_p1 = Wp();
    nan_p1.param[0] = MT_MISSION_PARAM_NAN;
    mt_mission_cmd_t nan_p3 = Wp();
    nan_p3.param[2] = MT_MISSION_PARAM_NAN;
    mt_mission_cmd_t bad_lat = Wp();
    bad_lat.x = 900000001;
    mt_mission_cmd_t bad_lon = Wp();
    bad_lon.y = -1800000001;
    mt_mission_cmd_t local_frame = Wp();
    local_frame.frame = 1;
    mt_mission_cmd_t home_not_wp = Takeoff();
    const std::vector<Bad> cases = {
        {"unknown id", {Home(), Wp(), Cmd(9999)}, MT_E_MISSION_CMD, 2},
        {"reserved id 0", {Home(), Cmd(0)}, MT_E_MISSION_CMD, 1},
        {"home not a waypoint", {home_not_wp, Wp()}, MT_E_MISSION_CMD, 0},
        {"NaN param 1", {Home(), nan_p1}, MT_E_MISSION_PARAM, 1},
        {"NaN param 3 of waypoint", {Home(), Wp(), nan_p3}, MT_E_MISSION_PARAM, 2},
        {"negative delay", {Home(), Wp(), Delay(-1)}, MT_E_MISSION_PARAM, 2},
        {"yaw angle 400", {Home(), Cmd(MT_MAV_CMD_CONDITION_YAW, 400000)}, MT_E_MISSION_PARAM, 1},
        {"servo channel 0", {Home(), Wp(), Servo(0)}, MT_E_MISSION_PARAM, 2},
        {"servo fractional",
         {Home(), Cmd(MT_MAV_CMD_DO_SET_SERVO, 5500, 1500000)},
         MT_E_MISSION_PARAM,
         1},
        {"speed type 9", {Home(), Cmd(MT_MAV_CMD_DO_CHANGE_SPEED, 9000)}, MT_E_MISSION_PARAM, 1},
        {"set home 2", {Home(), Cmd(MT_MAV_CMD_DO_SET_HOME, 2000)}, MT_E_MISSION_PARAM, 1},
        {"latitude", {Home(), Wp(), bad_lat}, MT_E_MISSION_LOCATION, 2},
        {"longitude", {Home(), bad_lon}, MT_E_MISSION_LOCATION, 1},
        {"local frame", {Home(), local_frame}, MT_E_MISSION_FRAME, 1},
        {"jump to 0", {Home(), Wp(), Jump(0, 1)}, MT_E_MISSION_JUMP, 2},
        {"jump past end", {Home(), Wp(), Jump(3, 1)}, MT_E_MISSION_JUMP, 2},
        {"repeat -2", {Home(), Wp(), Jump(1, -2)}, MT_E_MISSION_JUMP, 2},
        {"repeat 32768", {Home(), Wp(), Jump(1, 32768)}, MT_E_MISSION_JUMP, 2},
        {"fractional target",
         {Home(), Wp(), Cmd(MT_MAV_CMD_DO_JUMP, 1500, 1000)},
         MT_E_MISSION_JUMP,
         2},
        {"unknown tag", {Home(), Wp(), Tag(1), JumpTag(2, 1)}, MT_E_MISSION_JUMP, 3},
        {"do-only repeat forever (A-2)",
         {Home(), Servo(), Jump(1, -1), Wp()},
         MT_E_MISSION_LOOP,
         1},
        {"do-only finite loop", {Home(), Wp(), Servo(), Jump(2, 3)}, MT_E_MISSION_LOOP, 2},
        {"jump to itself (A-5)", {Home(), Wp(), Jump(2, -1)}, MT_E_MISSION_LOOP, 2},
        {"jump-only cycle", {Home(), Wp(), Jump(3, -1), Jump(2, -1)}, MT_E_MISSION_LOOP, 2},
        {"loop skipping its navs",
         {Home(), Servo(), Jump(5, -1), Wp(), Wp(), Servo(), Jump(1, -1)},
         MT_E_MISSION_LOOP,
         1},
        {"tag loop without nav",
         {Home(), Wp(), Tag(3), Servo(), JumpTag(3, -1)},
         MT_E_MISSION_LOOP,
         2},
    };
    for (const Bad &c : cases) {
        Vehicle v;
        ASSERT_EQ(v.Load(Plain()), MT_OK);
        const uint32_t gen = v.m->generation;
        std::unique_ptr<mt_mission_t> before(new mt_mission_t(*v.m));
        uint16_t bad = 0;
        EXPECT_EQ(v.Load(c.cmds, &bad), c.st) << c.what;
        EXPECT_EQ(bad, c.index) << c.what;
        // the active mission is untouched
        EXPECT_EQ(v.m->generation, gen) << c.what;
        EXPECT_EQ(v.m->total, 5) << c.what;
        EXPECT_EQ(std::memcmp(before->cmd, v.m->cmd, sizeof before->cmd), 0) << c.what;
        EXPECT_EQ(std::memcmp(before->kind, v.m->kind, sizeof before->kind), 0) << c.what;
        EXPECT_EQ(std::memcmp(before->count, v.m->count, sizeof before->count), 0) << c.what;
    }
}

TEST(MissionCheck, FramesAsArduPilotsLoaderTakesThem)
{
    // a location command in frame 2 (MISSION) is read as GLOBAL by ArduPilot, so it loads;
    // a do command's frame is not looked at (frame 1 included); frame 1 on a location is refused
    mt_mission_cmd_t mission_frame_loc = Wp();
    mission_frame_loc.frame = 2;
    mt_mission_cmd_t servo_local = Servo();
    servo_local.frame = 1;
    Vehicle v;
    EXPECT_EQ(v.Load({Home(), mission_frame_loc, servo_local}), MT_OK);
    mt_mission_cmd_t guided = Cmd(92, MT_MISSION_MILLI, 0, 0, 0, 0, 0, 0, 2);
    // GUIDED_ENABLE: ArduPilot stores a location (0, 0 here) and takes frame 2
    EXPECT_EQ(v.Load({Home(), Wp(), guided}), MT_OK);
    guided.frame = 1;
    uint16_t bad = 0;
    EXPECT_EQ(v.Load({Home(), Wp(), guided}, &bad), MT_E_MISSION_FRAME);
    EXPECT_EQ(bad, 2);
}

TEST(MissionCheck, NanAllowedWhereAPAllowsIt)
{
    mt_mission_cmd_t wp = Wp();
    wp.param[3] = MT_MISSION_PARAM_NAN;
    mt_mission_cmd_t land = Land();
    land.param[3] = MT_MISSION_PARAM_NAN;
    mt_mission_cmd_t vtol = Cmd(85);
    vtol.param[2] = MT_MISSION_PARAM_NAN;
    vtol.param[3] = MT_MISSION_PARAM_NAN;
    Vehicle v;
    EXPECT_EQ(v.Load({Home(), wp, land, vtol}), MT_OK);
}

TEST(MissionCheck, SizeLimits)
{
    Vehicle v;
    uint16_t bad = 7;
    std::vector<mt_mission_cmd_t> big(MT_CFG_MISSION_MAX_CMDS + 1u, Wp());
    EXPECT_EQ(mt_mission_load(v.m.get(), big.data(), 0, &bad), MT_E_MISSION_SIZE);
    EXPECT_EQ(bad, 0);
    EXPECT_EQ(mt_mission_load(v.m.get(), big.data(), static_cast<uint16_t>(big.size()), &bad),
              MT_E_MISSION_SIZE);
    big[0] = Home();
    EXPECT_EQ(mt_mission_load(v.m.get(), big.data(), MT_CFG_MISSION_MAX_CMDS, &bad), MT_OK);
    EXPECT_EQ(bad, MT_MISSION_NONE);
    EXPECT_EQ(v.m->total, MT_CFG_MISSION_MAX_CMDS);
}

TEST(MissionCheck, ManyJumpsNeverOverflowATable)
{
    // AP silently stops taking jumps after 15/100 distinct ones
    std::vector<mt_mission_cmd_t> c{Home()};
    for (int k = 0; k < 150; k++) {
        c.push_back(Wp(k));
        c.push_back(Jump(static_cast<int>(c.size()) - 1, 1));
    }
    c.push_back(Land());
    Vehicle v;
    ASSERT_EQ(v.Load(c), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run(10000);
    EXPECT_EQ(v.starts.size(), 301u); // every waypoint twice, then land
}

TEST(MissionCheck, CheckCmdAcceptsEveryTableCommand)
{
    for (uint16_t id :
         {16,  17,  18,  19,  20,  21,   22,   30,   31,   36,   82,   83,    84,    85,   92,
          93,  94,  112, 114, 179, 181,  182,  184,  188,  189,  191,  193,   194,   195,  197,
          201, 202, 203, 205, 206, 207,  208,  210,  211,  212,  213,  215,   216,   217,  218,
          222, 223, 531, 532, 534, 1000, 2000, 2001, 2500, 2501, 3000, 42600, 42702, 42703}) {
        std::vector<mt_mission_cmd_t> c{Home(), Cmd(id)};
        EXPECT_EQ(mt_mission_check_cmd(c.data(), 2, 1), MT_OK) << id;
    }
}

// ------------------------------------------------------------------ state machine

TEST(MissionState, StatusesOfEveryOperation)
{
    Vehicle v;
    EXPECT_EQ(mt_mission_start(v.m.get()), MT_E_EMPTY);
    EXPECT_EQ(mt_mission_resume(v.m.get()), MT_E_EMPTY);
    EXPECT_EQ(mt_mission_set_current(v.m.get(), 1), MT_E_EMPTY);
    EXPECT_EQ(mt_mission_stop(v.m.get()), MT_E_STATE);
    EXPECT_EQ(mt_mission_update(v.m.get()), MT_E_STATE);
    EXPECT_EQ(mt_mission_restart_current(v.m.get()), MT_E_STATE);
    ASSERT_EQ(v.Load({Home()}), MT_OK);
    EXPECT_EQ(mt_mission_start(v.m.get()), MT_E_EMPTY);
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    EXPECT_EQ(mt_mission_resume(v.m.get()), MT_E_STATE);
    uint16_t bad = 0;
    EXPECT_EQ(v.Load(Plain(), &bad), MT_E_STATE);
    EXPECT_EQ(bad, MT_MISSION_NONE);
    EXPECT_EQ(v.m->generation, 2u);
    EXPECT_TRUE(v.log.size() == 1u);
}

TEST(MissionState, FailedSetCurrentHasNoSideEffects)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Jump(1, 2), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    mt_mission_update(v.m.get());
    mt_mission_update(v.m.get());
    std::unique_ptr<mt_mission_t> before(new mt_mission_t(*v.m));
    size_t calls = v.log.size();
    EXPECT_EQ(mt_mission_set_current(v.m.get(), 5), MT_E_INVALID);
    EXPECT_EQ(mt_mission_set_current(v.m.get(), 60000), MT_E_INVALID);
    EXPECT_EQ(std::memcmp(before.get(), v.m.get(), sizeof(mt_mission_t)), 0);
    EXPECT_EQ(v.log.size(), calls);
}

TEST(MissionState, SetCurrentWhileStoppedPastTheLastNavChangesNothing)
{
    // AP's stopped set_current_cmd clears its cursors before it finds no nav command
    // and returns false; here nothing changes and the status says why.
    Vehicle v;
    v.default_verify = false;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Wp(1), Jump(1, 2), Servo()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    ASSERT_EQ(mt_mission_stop(v.m.get()), MT_OK);
    std::unique_ptr<mt_mission_t> before(new mt_mission_t(*v.m));
    EXPECT_EQ(mt_mission_set_current(v.m.get(), 4), MT_E_EMPTY);
    EXPECT_EQ(std::memcmp(before.get(), v.m.get(), sizeof(mt_mission_t)), 0);
    EXPECT_EQ(mt_mission_set_current(v.m.get(), 3), MT_OK); // the jump leads back to 1
    EXPECT_EQ(v.m->nav, 1);
    EXPECT_EQ(mt_mission_jump_count(v.m.get(), 3), 1);
    // running, the same index starts the trailing servo and completes the mission
    ASSERT_EQ(mt_mission_resume(v.m.get()), MT_OK);
    v.log.clear();
    EXPECT_EQ(mt_mission_set_current(v.m.get(), 4), MT_OK);
    EXPECT_EQ(v.Log(), "S4 C");
    EXPECT_EQ(v.m->state, MT_MISSION_COMPLETE);
}

TEST(MissionState, SetCurrentWhileRunningStartsThatNav)
{
    Vehicle v;
    v.default_verify = false;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    EXPECT_EQ(mt_mission_set_current(v.m.get(), 3), MT_OK);
    EXPECT_EQ(v.m->nav, 3);
    EXPECT_EQ(v.Starts(), "1 3");
    EXPECT_EQ(mt_mission_set_current(v.m.get(), 0), MT_OK); // 0 means 1
    EXPECT_EQ(v.m->nav, 1);
}

TEST(MissionState, SetCurrentToDoCommandRunsItBeforeNextNav)
{
    Vehicle v;
    v.verify_after[4] = 5;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Wp(), Servo(), Wp(), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    ASSERT_EQ(mt_mission_set_current(v.m.get(), 3), MT_OK);
    EXPECT_EQ(v.Log(), "S1 S3 S4");
    v.Run();
    EXPECT_EQ(v.Starts(), "1 3 4 5");
}

TEST(MissionState, SetCurrentZeroResetsJumpCounters)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Jump(1, 5), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    for (int k = 0; k < 4; k++) {
        mt_mission_update(v.m.get());
    }
    EXPECT_GT(mt_mission_jump_count(v.m.get(), 3), 0);
    ASSERT_EQ(mt_mission_set_current(v.m.get(), 2), MT_OK);
    EXPECT_GT(mt_mission_jump_count(v.m.get(), 3), 0); // kept
    ASSERT_EQ(mt_mission_set_current(v.m.get(), 0), MT_OK);
    EXPECT_EQ(mt_mission_jump_count(v.m.get(), 3), 0);
}

TEST(MissionState, StopResumeBeforeStartRunsFromTheBeginning)
{
    Vehicle v;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    EXPECT_EQ(mt_mission_stop(v.m.get()), MT_E_STATE);
    ASSERT_EQ(mt_mission_resume(v.m.get()), MT_OK);
    EXPECT_EQ(v.m->nav, 1);
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 3 4");
    EXPECT_EQ(v.completes, 1);
}

TEST(MissionState, StopResumeWithNavActiveRestartsIt)
{
    Vehicle v;
    v.verify_after[2] = 100;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    mt_mission_update(v.m.get());
    ASSERT_EQ(mt_mission_stop(v.m.get()), MT_OK);
    EXPECT_EQ(mt_mission_update(v.m.get()), MT_E_STATE);
    EXPECT_EQ(mt_mission_stop(v.m.get()), MT_E_STATE);
    ASSERT_EQ(mt_mission_resume(v.m.get()), MT_OK);
    EXPECT_EQ(v.Starts(), "1 2 2");
    EXPECT_EQ(v.m->nav, 2);
}

TEST(MissionState, StopResumeWithDoActiveRestartsBoth)
{
    Vehicle v;
    v.verify_after[3] = 100;
    v.verify_after[2] = 100;
    ASSERT_EQ(v.Load({Home(), Takeoff(), Delay(), Wp(), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    mt_mission_update(v.m.get());
    EXPECT_EQ(v.m->do_cmd, 2);
    ASSERT_EQ(mt_mission_stop(v.m.get()), MT_OK);
    ASSERT_EQ(mt_mission_resume(v.m.get()), MT_OK);
    EXPECT_EQ(v.Starts(), "1 2 3 2 3"); // set-current at the do command: it, then the nav
    EXPECT_EQ(v.m->do_cmd, 2);
    EXPECT_EQ(v.m->nav, 3);
}

TEST(MissionState, ResumeWithRefusedNavMovesOn)
{
    Vehicle v;
    v.verify_after[2] = 100;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    mt_mission_update(v.m.get());
    ASSERT_EQ(mt_mission_stop(v.m.get()), MT_OK);
    v.refuse[2] = true;
    ASSERT_EQ(mt_mission_resume(v.m.get()), MT_OK);
    EXPECT_EQ(v.m->nav, 3);
    EXPECT_EQ(v.m->prev_nav, 2);
}

TEST(MissionState, ResumeAfterCompleteRestarts)
{
    Vehicle v;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    ASSERT_EQ(v.completes, 1);
    EXPECT_EQ(mt_mission_stop(v.m.get()), MT_E_STATE);
    ASSERT_EQ(mt_mission_resume(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.completes, 2);
    EXPECT_EQ(v.m->completions, 2u);
    EXPECT_EQ(v.Starts(), "1 2 3 4 1 2 3 4");
}

TEST(MissionState, SetCurrentWhileStoppedOrCompletePreloads)
{
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Jump(1, 1), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    ASSERT_EQ(v.m->state, MT_MISSION_COMPLETE);
    ASSERT_EQ(mt_mission_set_current(v.m.get(), 2), MT_OK);
    EXPECT_EQ(v.m->state, MT_MISSION_STOPPED); // COMPLETE -> STOPPED
    EXPECT_EQ(v.m->nav, 2);                    // pre-loaded, not started
    EXPECT_EQ(v.m->nav_idx, 2);
    v.starts.clear();
    ASSERT_EQ(mt_mission_resume(v.m.get()), MT_OK);
    v.Run();
    EXPECT_EQ(v.Starts(), "2 1 2 4");
}

TEST(MissionState, RestartCurrent)
{
    Vehicle v;
    v.verify_after[1] = 100;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    ASSERT_EQ(mt_mission_restart_current(v.m.get()), MT_OK);
    EXPECT_EQ(v.Starts(), "1 1");
    v.refuse[1] = true;
    ASSERT_EQ(mt_mission_restart_current(v.m.get()), MT_OK);
    EXPECT_EQ(v.m->nav, 2);
    ASSERT_EQ(mt_mission_stop(v.m.get()), MT_OK);
    EXPECT_EQ(mt_mission_restart_current(v.m.get()), MT_E_STATE);
}

// mt_mission_replace: a running mission swapped between two updates (an upload in flight).
static mt_status_t Replace(Vehicle &v, const std::vector<mt_mission_cmd_t> &cmds, uint16_t *bad)
{
    return mt_mission_replace(v.m.get(), cmds.data(), static_cast<uint16_t>(cmds.size()), bad);
}

TEST(MissionReplace, ContinuesAtTheSameIndexWithTheNewCommand)
{
    Vehicle v;
    v.verify_after[2] = 100;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Wp(3)}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run(3); // 1 verified, 2 flying
    ASSERT_EQ(v.m->nav, 2);
    const uint32_t gen = v.m->generation;
    uint16_t bad = 0;
    std::vector<mt_mission_cmd_t> next{Home(), Wp(7), Wp(8), Servo(), Wp(9), Land()};
    ASSERT_EQ(Replace(v, next, &bad), MT_OK);
    EXPECT_EQ(bad, MT_MISSION_NONE);
    EXPECT_EQ(v.m->state, MT_MISSION_RUNNING);
    EXPECT_EQ(v.m->total, 6);
    EXPECT_EQ(v.m->generation, gen + 1);
    EXPECT_EQ(v.m->nav, 2); // the command now at index 2 was started
    EXPECT_EQ(v.Starts(), "1 2 2");
    mt_mission_cmd_t out{};
    bool cur = false;
    ASSERT_EQ(mt_mission_get(v.m.get(), 2, &out, &cur), MT_OK);
    EXPECT_TRUE(cur);
    EXPECT_EQ(out.x, Wp(8).x);
    v.verify_after.clear();
    v.Run();
    EXPECT_EQ(v.Starts(), "1 2 2 3 4 5");
    EXPECT_EQ(v.completes, 1);
}

TEST(MissionReplace, AtADoCommandItStartsAndTheWalkGoesOn)
{
    Vehicle v;
    v.verify_after[2] = 100;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Wp(3)}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run(3);
    ASSERT_EQ(v.m->nav, 2);
    uint16_t bad = 0;
    ASSERT_EQ(Replace(v, {Home(), Wp(1), Servo(), Wp(5)}, &bad), MT_OK);
    EXPECT_EQ(v.Starts(), "1 2 2 3");
    EXPECT_EQ(v.m->nav, 3);
    EXPECT_EQ(v.m->do_cmd, 2);
}

TEST(MissionReplace, IndexGoneStopsWithNothingSet)
{
    Vehicle v;
    v.verify_after[3] = 100;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Wp(3)}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run(5);
    ASSERT_EQ(v.m->nav, 3);
    const size_t calls = v.log.size();
    uint16_t bad = 0;
    ASSERT_EQ(Replace(v, {Home(), Wp(4), Wp(5)}, &bad), MT_OK);
    EXPECT_EQ(v.m->state, MT_MISSION_STOPPED);
    EXPECT_EQ(v.m->nav, MT_MISSION_NONE);
    EXPECT_EQ(v.m->nav_idx, MT_MISSION_NONE);
    EXPECT_EQ(v.m->do_cmd, MT_MISSION_NONE);
    EXPECT_EQ(v.m->total, 3);
    EXPECT_EQ(v.log.size(), calls); // no callback: the vehicle holds
    EXPECT_EQ(v.completes, 0);
    // an empty mission (home only) is held the same way
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    ASSERT_EQ(Replace(v, {Home()}, &bad), MT_OK);
    EXPECT_EQ(v.m->state, MT_MISSION_STOPPED);
    EXPECT_EQ(v.m->total, 1);
}

TEST(MissionReplace, InvalidListChangesNothing)
{
    Vehicle v;
    v.verify_after[2] = 100;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Wp(3)}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run(3);
    const mt_mission_t before = *v.m;
    const size_t calls = v.log.size();
    uint16_t bad = 0;
    mt_mission_cmd_t far = Wp(1);
    far.x = MT_MISSION_LAT_MAX + 1; // beyond 90 degrees
    EXPECT_EQ(Replace(v, {Home(), Wp(1), far}, &bad), MT_E_MISSION_LOCATION);
    EXPECT_EQ(bad, 2);
    EXPECT_EQ(Replace(v, {Home(), Wp(1), Jump(9, 1)}, &bad), MT_E_MISSION_JUMP);
    EXPECT_EQ(bad, 2);
    EXPECT_EQ(Replace(v, {}, &bad), MT_E_MISSION_SIZE);
    EXPECT_EQ(bad, 0);
    EXPECT_EQ(0, std::memcmp(&before, v.m.get(), sizeof before));
    EXPECT_EQ(v.log.size(), calls);
}

TEST(MissionReplace, RefusedUnlessRunning)
{
    Vehicle v;
    uint16_t bad = 0;
    EXPECT_EQ(Replace(v, {Home(), Wp(1)}, &bad), MT_E_STATE);
    EXPECT_EQ(bad, MT_MISSION_NONE);
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2)}), MT_OK);
    EXPECT_EQ(Replace(v, {Home(), Wp(1)}, &bad), MT_E_STATE);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run();
    ASSERT_EQ(v.m->state, MT_MISSION_COMPLETE);
    EXPECT_EQ(Replace(v, {Home(), Wp(1)}, &bad), MT_E_STATE);
    EXPECT_EQ(v.m->total, 3);
}

TEST(MissionReplace, JumpCountersKeptByIndexAsArduPilotKeysThem)
{
    // 1 wp, 2 wp, 3 jump->1 x3, 4 land: replaced after the jump was taken twice
    Vehicle v;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Jump(1, 3), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.verify_after[2] = 100;
    while (v.m->state == MT_MISSION_RUNNING && mt_mission_jump_count(v.m.get(), 3) < 2) {
        mt_mission_update(v.m.get());
    }
    v.Run(3); // flying 2 again, third lap
    ASSERT_EQ(mt_mission_jump_count(v.m.get(), 3), 2);
    ASSERT_EQ(v.m->nav, 2);
    uint16_t bad = 0;
    v.starts.clear();
    // same jump at 3 with 5 repeats: 2 taken, 3 left (a fresh counter would give 5)
    ASSERT_EQ(Replace(v, {Home(), Wp(1), Wp(2), Jump(1, 5), Land()}, &bad), MT_OK);
    EXPECT_EQ(mt_mission_jump_count(v.m.get(), 3), 2);
    v.verify_after.clear();
    v.Run();
    EXPECT_EQ(v.Starts(), "2 1 2 1 2 1 2 4");
    // a smaller repeat count than the taken count: kept at the new count, so it falls through
    Vehicle w;
    ASSERT_EQ(w.Load({Home(), Wp(1), Wp(2), Jump(1, 3), Land()}), MT_OK);
    ASSERT_EQ(mt_mission_start(w.m.get()), MT_OK);
    while (w.m->state == MT_MISSION_RUNNING && mt_mission_jump_count(w.m.get(), 3) < 2) {
        mt_mission_update(w.m.get());
    }
    ASSERT_EQ(mt_mission_jump_count(w.m.get(), 3), 2);
    ASSERT_EQ(Replace(w, {Home(), Wp(1), Wp(2), Jump(1, 1), Land()}, &bad), MT_OK);
    EXPECT_EQ(mt_mission_jump_count(w.m.get(), 3), 1);
    // a jump where the old list had a waypoint starts at 0; and one where it had a jump
    // whose index the new list moved is not kept either
    ASSERT_EQ(Replace(w, {Home(), Wp(1), Wp(2), Wp(3), Jump(1, 2), Land()}, &bad), MT_OK);
    EXPECT_EQ(mt_mission_jump_count(w.m.get(), 4), 0);
}

TEST(MissionState, AllNavsRefusedCompletesWithoutSpinning)
{
    // AP's advance gives up after 255 commands and stays RUNNING with nothing loaded,
    // re-scanning at every update. Here the advance visits at most the command count plus
    // 255 commands and then completes the mission, once.
    Vehicle v;
    v.refuse[1] = v.refuse[2] = true;
    ASSERT_EQ(v.Load({Home(), Wp(1), Wp(2), Jump(1, -1)}), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    EXPECT_EQ(v.starts.size(), 4u + 255u);
    EXPECT_EQ(v.m->state, MT_MISSION_COMPLETE);
    EXPECT_EQ(v.completes, 1);
    EXPECT_EQ(mt_mission_update(v.m.get()), MT_E_STATE);
    EXPECT_EQ(v.completes, 1);
}

TEST(MissionState, NavAfterLongDoStretchIsLoadedAtEveryBoundary)
{
    // AP gives up after 255 iterations of its nav search (post-decremented guard).
    // A nav command reached on the 255th step makes AP complete right after starting it;
    // one beyond makes AP report success with no nav loaded and never complete. Here the
    // nav command is loaded and the mission completes once, on either side of 255.
    for (int dos = 250; dos <= 260; dos++) {
        std::vector<mt_mission_cmd_t> c{Home()};
        for (int k = 0; k < dos; k++) {
            c.push_back(Servo());
        }
        c.push_back(Wp(1));
        c.push_back(Land());
        Vehicle v;
        v.verify_after[static_cast<uint16_t>(dos + 1)] = 3 * dos; // room for the do stretch
        ASSERT_EQ(v.Load(c), MT_OK) << dos;
        ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK) << dos;
        EXPECT_EQ(v.m->nav, dos + 1) << dos;
        EXPECT_EQ(v.m->state, MT_MISSION_RUNNING) << dos;
        EXPECT_EQ(v.completes, 0) << dos;
        v.Run(100000);
        // the first do command, the waypoint, the rest of the do stretch, then land
        EXPECT_EQ(v.starts.size(), static_cast<size_t>(dos) + 2u) << dos;
        EXPECT_EQ(v.starts.front(), 1) << dos;
        EXPECT_EQ(v.starts[1], dos + 1) << dos;
        EXPECT_EQ(v.starts.back(), dos + 2) << dos;
        EXPECT_EQ(v.completes, 1) << dos;
    }
}

TEST(MissionState, GetReportsCurrentByIndex)
{
    Vehicle v;
    v.default_verify = false;
    ASSERT_EQ(v.Load(Plain()), MT_OK);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    mt_mission_cmd_t c{};
    bool cur = false;
    ASSERT_EQ(mt_mission_get(v.m.get(), 1, &c, &cur), MT_OK);
    EXPECT_TRUE(cur);
    EXPECT_EQ(c.id, MT_MAV_CMD_TAKEOFF);
    // command 16 (WAYPOINT id) is not "current" because nav index is 1
    ASSERT_EQ(mt_mission_get(v.m.get(), 0, &c, &cur), MT_OK);
    EXPECT_FALSE(cur);
    EXPECT_EQ(c.id, MT_MAV_CMD_WAYPOINT);
    c.id = 1234;
    EXPECT_EQ(mt_mission_get(v.m.get(), 5, &c, &cur), MT_E_INVALID);
    EXPECT_EQ(c.id, 1234);
    EXPECT_EQ(mt_mission_jump_count(v.m.get(), 1), 0);
    EXPECT_EQ(mt_mission_jump_count(v.m.get(), 99), 0);
}

TEST(MissionStatus, NamesOfMissionStatuses)
{
    EXPECT_STREQ(mt_status_str(MT_E_MISSION_CMD), "MT_E_MISSION_CMD");
    EXPECT_STREQ(mt_status_str(MT_E_MISSION_PARAM), "MT_E_MISSION_PARAM");
    EXPECT_STREQ(mt_status_str(MT_E_MISSION_LOCATION), "MT_E_MISSION_LOCATION");
    EXPECT_STREQ(mt_status_str(MT_E_MISSION_FRAME), "MT_E_MISSION_FRAME");
    EXPECT_STREQ(mt_status_str(MT_E_MISSION_JUMP), "MT_E_MISSION_JUMP");
    EXPECT_STREQ(mt_status_str(MT_E_MISSION_LOOP), "MT_E_MISSION_LOOP");
    EXPECT_STREQ(mt_status_str(MT_E_MISSION_SIZE), "MT_E_MISSION_SIZE");
    EXPECT_STREQ(mt_status_str(MT_E_MISSION_SYNTAX), "MT_E_MISSION_SYNTAX");
    EXPECT_STREQ(mt_status_str(MT_E_STATE), "MT_E_STATE");
    // statuses appended after the mission ones (work queue, ...) keep these values
    EXPECT_GT(static_cast<int>(MT_STATUS_COUNT), static_cast<int>(MT_E_STATE));
}

} // namespace
