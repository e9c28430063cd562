// SPDX-License-Identifier: Apache-2.0
// The mission command table generated from MAVLink's definitions (tools/mavcmd/gen_mav_cmds.py:
// kernel/src/mt_mission_cmds.h, mission/mav_cmd_names.h): ids, classes and names as MAVLink
// and ArduPilot's mission loader have them. `make check-mav-cmds` fails when the committed
// tables are stale.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "mission_test_util.h"
#include "report.h"
#include "wpl.h"

using namespace mt_test;

namespace
{

// A DO command with no location, in frame 2 (MISSION) as ground stations write it.
mt_mission_cmd_t DoCmd(uint16_t id, int32_t p1 = 0, int32_t p2 = 0)
{
    return Cmd(id, p1, p2, 0, 0, 0, 0, 0, 2);
}

// mt-mission check's text and JSON reports of a WPL text.
struct Report {
    mt_status_t st;
    std::string text;
    std::string json;
};

Report CheckWpl(const std::string &wpl)
{
    std::vector<mt_plan_step_t> plan(64);
    std::unique_ptr<mt_report_t> rep(new mt_report_t());
    Report r;
    r.st = mt_report_check(wpl.data(), wpl.size(), plan.data(), plan.size(), rep.get());
    r.text.assign(mt_report_text(rep.get(), "m.waypoints", nullptr, 0) + 1, '\0');
    mt_report_text(rep.get(), "m.waypoints", &r.text[0], r.text.size());
    r.json.assign(mt_report_json(rep.get(), nullptr, 0) + 1, '\0');
    mt_report_json(rep.get(), &r.json[0], r.json.size());
    return r;
}

const char kHome[] = "QGC WPL 110\n"
                     "0\t1\t0\t16\t0\t0\t0\t0\t-35.363262\t149.165237\t584.09\t1\n"
                     "1\t0\t3\t22\t0\t0\t0\t0\t-35.363262\t149.165237\t20\t1\n";

} // namespace

TEST(MissionCmdTable, Ids214To218AreClassedAsMavlinkNumbersThem)
{
    // 214 is DO_SET_CAM_TRIGG_INTERVAL (common.xml), which ArduPilot's mission loader refuses
    // (MAV_MISSION_UNSUPPORTED); 215..218 are ardupilotmega.xml's do commands.
    EXPECT_EQ(mt_mission_kind_of(214), MT_MISSION_KIND_HOME);
    for (uint16_t id : {215, 216, 217, 218}) {
        EXPECT_EQ(mt_mission_kind_of(id), MT_MISSION_KIND_DO) << id;
    }
    EXPECT_EQ(mt_wpl_cmd_name(214), nullptr);
    EXPECT_STREQ(mt_wpl_cmd_name(215), "DO_SET_RESUME_REPEAT_DIST");
    EXPECT_STREQ(mt_wpl_cmd_name(216), "DO_SPRAYER");
    EXPECT_STREQ(mt_wpl_cmd_name(217), "DO_SEND_SCRIPT_MESSAGE");
    EXPECT_STREQ(mt_wpl_cmd_name(218), "DO_AUX_FUNCTION");
    std::vector<mt_mission_cmd_t> c{Home(), DoCmd(214)};
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 2, 1), MT_E_MISSION_CMD);
    // DO_SET_RESUME_REPEAT_DIST keeps the rule the old table gave 214 by mistake: distance >= 0
    c = {Home(), DoCmd(215, 50 * MT_MISSION_MILLI)};
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 2, 1), MT_OK);
    c = {Home(), DoCmd(215, -MT_MISSION_MILLI)};
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 2, 1), MT_E_MISSION_PARAM);
}

TEST(MissionCmdTable, DoAuxFunctionLoadsAndRuns)
{
    // DO_AUX_FUNCTION: param 1 the RC aux function, param 2 the switch position (2 = high)
    const mt_mission_cmd_t aux = DoCmd(218, 41 * MT_MISSION_MILLI, 2 * MT_MISSION_MILLI);
    std::vector<mt_mission_cmd_t> c{Home(), Takeoff(), aux, Wp(1), Land()};
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 5, 2), MT_OK);
    Vehicle v;
    ASSERT_EQ(v.Load(c), MT_OK);
    EXPECT_EQ(v.m->kind[2], MT_MISSION_KIND_DO);
    ASSERT_EQ(mt_mission_start(v.m.get()), MT_OK);
    v.Run(100);
    EXPECT_EQ(std::count(v.starts.begin(), v.starts.end(), 2), 1) << v.Starts();
    EXPECT_EQ(v.completes, 1);
}

TEST(MissionCmdTable, NavArcWaypointIsANavCommandWithALocation)
{
    EXPECT_EQ(mt_mission_kind_of(36), MT_MISSION_KIND_NAV);
    EXPECT_STREQ(mt_wpl_cmd_name(36), "NAV_ARC_WAYPOINT");
    // param 1 the arc angle (deg); x/y/z the exit point
    mt_mission_cmd_t arc = Cmd(36, 90 * MT_MISSION_MILLI, 0, 0, 0, 473987418, 85455939, 20000);
    std::vector<mt_mission_cmd_t> c{Home(), Takeoff(), Wp(1), arc, Land()};
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 5, 3), MT_OK);
    Vehicle v;
    ASSERT_EQ(v.Load(c), MT_OK);
    EXPECT_EQ(v.m->kind[3], MT_MISSION_KIND_NAV);
    c[3].frame = 2; // MISSION: ArduPilot reads it as GLOBAL
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 5, 3), MT_OK);
    c[3].frame = 1; // a location command needs a global frame
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 5, 3), MT_E_MISSION_FRAME);
    c[3].frame = 3;
    c[3].x = 910000000; // latitude 91 deg
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 5, 3), MT_E_MISSION_LOCATION);
}

TEST(MissionCmdTable, DoWinchIsADoCommand)
{
    EXPECT_EQ(mt_mission_kind_of(42600), MT_MISSION_KIND_DO);
    EXPECT_STREQ(mt_wpl_cmd_name(42600), "DO_WINCH");
    // winch 1, action 1 (length control), release 5 m at 0.5 m/s
    std::vector<mt_mission_cmd_t> c{Home(),
                                    Cmd(42600, MT_MISSION_MILLI, MT_MISSION_MILLI,
                                        5 * MT_MISSION_MILLI, MT_MISSION_MILLI / 2, 0, 0, 0, 2)};
    EXPECT_EQ(mt_mission_check_cmd(c.data(), 2, 1), MT_OK);
}

TEST(MissionCmdTable, IdsArduPilotRefusesAreStillRejected)
{
    // 1: reserved by ArduPilot; 113 CONDITION_CHANGE_ALT and 176 DO_SET_MODE: MAVLink
    // commands ArduPilot's mission loader does not accept (the old hand table did).
    for (uint16_t id : {1, 113, 176}) {
        std::vector<mt_mission_cmd_t> c{Home(), DoCmd(id)};
        EXPECT_EQ(mt_mission_check_cmd(c.data(), 2, 1), MT_E_MISSION_CMD) << id;
        EXPECT_EQ(mt_mission_kind_of(id), MT_MISSION_KIND_HOME) << id;
        EXPECT_EQ(mt_wpl_cmd_name(id), nullptr) << id;
    }
    Vehicle v;
    uint16_t bad = 0;
    EXPECT_EQ(v.Load({Home(), Takeoff(), DoCmd(1), Land()}, &bad), MT_E_MISSION_CMD);
    EXPECT_EQ(bad, 2u);
}

TEST(MissionCmdTable, ReportNamesDoSprayer)
{
    // what `mt-mission check` prints for a DO_SPRAYER (216): in the plan, and in an error
    Report ok = CheckWpl(std::string(kHome) + "2\t0\t3\t216\t1\t0\t0\t0\t0\t0\t0\t1\n" +
                         "3\t0\t3\t21\t0\t0\t0\t0\t-35.363262\t149.165237\t0\t1\n");
    ASSERT_EQ(ok.st, MT_OK) << ok.text;
    EXPECT_NE(ok.text.find("DO_SPRAYER (216)"), std::string::npos) << ok.text;
    EXPECT_NE(ok.json.find("\"command\": 216, \"name\": \"DO_SPRAYER\""), std::string::npos)
        << ok.json;
    Report bad = CheckWpl(std::string(kHome) + "2\t0\t3\t216\tnan\t0\t0\t0\t0\t0\t0\t1\n");
    EXPECT_EQ(bad.st, MT_E_MISSION_PARAM);
    EXPECT_NE(bad.text.find("command 216 (DO_SPRAYER)"), std::string::npos) << bad.text;
    // 215 is DO_SET_RESUME_REPEAT_DIST (the old name table called it DO_SPRAYER)
    Report rr = CheckWpl(std::string(kHome) + "2\t0\t3\t215\t30\t0\t0\t0\t0\t0\t0\t1\n");
    ASSERT_EQ(rr.st, MT_OK) << rr.text;
    EXPECT_NE(rr.text.find("DO_SET_RESUME_REPEAT_DIST (215)"), std::string::npos) << rr.text;
}

TEST(MissionCmdTable, ReaderIgnoresTheFrameOfDoCommandsWithoutALocation)
{
    // the reader's "frame ignored" rule follows the same generated location flag as the kernel
    EXPECT_EQ(mt_wpl_frame_ignored(216), 1);   // DO_SPRAYER
    EXPECT_EQ(mt_wpl_frame_ignored(42600), 1); // DO_WINCH
    EXPECT_EQ(mt_wpl_frame_ignored(191), 0);   // DO_GO_AROUND: ArduPilot stores a location
    EXPECT_EQ(mt_wpl_frame_ignored(188), 0);   // DO_RETURN_PATH_START: a location
    EXPECT_EQ(mt_wpl_frame_ignored(195), 0);   // DO_SET_ROI_LOCATION: a location
    EXPECT_EQ(mt_wpl_frame_ignored(36), 0);    // nav
}
