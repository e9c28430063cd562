// SPDX-License-Identifier: Apache-2.0
// Helpers for the mission tests: command builders and a recording vehicle.
#ifndef MISSION_TEST_UTIL_H
#define MISSION_TEST_UTIL_H

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mt/mission.h"

namespace mt_test
{

inline mt_mission_cmd_t Cmd(uint16_t id, int32_t p1 = 0, int32_t p2 = 0, int32_t p3 = 0,
                            int32_t p4 = 0, int32_t x = 0, int32_t y = 0, int32_t z = 0,
                            uint8_t frame = 3)
{
    mt_mission_cmd_t c{};
    c.id = id;
    c.frame = frame;
    c.param[0] = p1;
    c.param[1] = p2;
    c.param[2] = p3;
    c.param[3] = p4;
    c.x = x;
    c.y = y;
    c.z = z;
    return c;
}
inline mt_mission_cmd_t Home()
{
    return Cmd(MT_MAV_CMD_WAYPOINT, 0, 0, 0, 0, 473977418, 85455939, 58400, 0);
}
inline mt_mission_cmd_t Wp(int k = 0)
{
    return Cmd(MT_MAV_CMD_WAYPOINT, 0, 0, 0, 0, 473977418 + k * 1000, 85455939, 10000);
}
inline mt_mission_cmd_t Takeoff()
{
    return Cmd(MT_MAV_CMD_TAKEOFF, 0, 0, 0, 0, 0, 0, 2000);
}
inline mt_mission_cmd_t Land()
{
    return Cmd(MT_MAV_CMD_LAND);
}
inline mt_mission_cmd_t Rtl()
{
    return Cmd(MT_MAV_CMD_RETURN_TO_LAUNCH);
}
inline mt_mission_cmd_t Servo(int ch = 5, int pwm = 1500)
{
    return Cmd(MT_MAV_CMD_DO_SET_SERVO, ch * MT_MISSION_MILLI, pwm * MT_MISSION_MILLI);
}
inline mt_mission_cmd_t Delay(int s = 1)
{
    return Cmd(MT_MAV_CMD_CONDITION_DELAY, s * MT_MISSION_MILLI);
}
inline mt_mission_cmd_t Speed(int mps = 5)
{
    return Cmd(MT_MAV_CMD_DO_CHANGE_SPEED, 0, mps * MT_MISSION_MILLI, -MT_MISSION_MILLI);
}
inline mt_mission_cmd_t Jump(int target, int repeat)
{
    return Cmd(MT_MAV_CMD_DO_JUMP, target * MT_MISSION_MILLI, repeat * MT_MISSION_MILLI);
}
inline mt_mission_cmd_t Tag(int t)
{
    return Cmd(MT_MAV_CMD_JUMP_TAG, t * MT_MISSION_MILLI);
}
inline mt_mission_cmd_t JumpTag(int t, int repeat)
{
    return Cmd(MT_MAV_CMD_DO_JUMP_TAG, t * MT_MISSION_MILLI, repeat * MT_MISSION_MILLI);
}

// A vehicle that records every callback as "S<i>" (start), "V<i>" (verify), "C" (complete).
struct Vehicle {
    std::unique_ptr<mt_mission_t> m{new mt_mission_t()};
    std::vector<std::string> log;
    std::vector<uint16_t> starts;
    std::map<uint16_t, int> verify_after; // index -> verifies that return false first
    std::map<uint16_t, int> verify_seen;
    std::map<uint16_t, bool> refuse; // index -> start returns false
    bool default_verify = true;
    int completes = 0;
    bool saw_jump = false;

    static bool StartCb(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
    {
        auto *v = static_cast<Vehicle *>(ctx);
        if (c->id == MT_MAV_CMD_DO_JUMP || c->id == MT_MAV_CMD_DO_JUMP_TAG ||
            c->id == MT_MAV_CMD_JUMP_TAG) {
            v->saw_jump = true;
        }
        v->log.push_back("S" + std::to_string(i));
        v->starts.push_back(i);
        v->verify_seen[i] = 0;
        auto it = v->refuse.find(i);
        return it == v->refuse.end() || !it->second;
    }
    static bool VerifyCb(void *ctx, uint16_t i, const mt_mission_cmd_t *c)
    {
        auto *v = static_cast<Vehicle *>(ctx);
        if (c->id == MT_MAV_CMD_DO_JUMP || c->id == MT_MAV_CMD_DO_JUMP_TAG ||
            c->id == MT_MAV_CMD_JUMP_TAG) {
            v->saw_jump = true;
        }
        v->log.push_back("V" + std::to_string(i));
        int seen = v->verify_seen[i]++;
        auto it = v->verify_after.find(i);
        if (it != v->verify_after.end()) {
            return seen >= it->second;
        }
        return v->default_verify;
    }
    static void DoneCb(void *ctx)
    {
        auto *v = static_cast<Vehicle *>(ctx);
        v->log.push_back("C");
        v->completes++;
    }

    Vehicle()
    {
        mt_mission_init(m.get(), StartCb, VerifyCb, DoneCb, this);
    }

    mt_status_t Load(const std::vector<mt_mission_cmd_t> &cmds, uint16_t *bad_out = nullptr)
    {
        uint16_t bad = 0;
        mt_status_t st =
            mt_mission_load(m.get(), cmds.data(), static_cast<uint16_t>(cmds.size()), &bad);
        if (bad_out != nullptr) {
            *bad_out = bad;
        }
        return st;
    }
    // Run updates until complete or the limit; returns the number of updates.
    int Run(int limit = 1000)
    {
        int k = 0;
        while (k < limit && m->state == MT_MISSION_RUNNING) {
            EXPECT_EQ(mt_mission_update(m.get()), MT_OK);
            k++;
        }
        return k;
    }
    std::string Log() const
    {
        std::string s;
        for (const auto &e : log) {
            s += (s.empty() ? "" : " ") + e;
        }
        return s;
    }
    std::string Starts() const
    {
        std::string s;
        for (uint16_t i : starts) {
            s += (s.empty() ? "" : " ") + std::to_string(i);
        }
        return s;
    }
};

} // namespace mt_test

#endif
