// SPDX-License-Identifier: Apache-2.0
// Helpers for the mission file tests (test_mission_file.cpp, test_mission_plan.cpp): read a
// committed fixture, and parse a text as WPL 110 or as a QGroundControl .plan.
#ifndef MISSION_FILE_TEST_UTIL_H
#define MISSION_FILE_TEST_UTIL_H

#include <gtest/gtest.h>

#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "plan.h"
#include "wpl.h"

#ifndef MT_MISSIONS_DIR
#define MT_MISSIONS_DIR "tests/missions"
#endif

namespace mt_test
{

/** The bytes of tests/missions/<name>. */
inline std::string ReadMissionFile(const std::string &name)
{
    std::ifstream f(std::string(MT_MISSIONS_DIR) + "/" + name, std::ios::binary);
    EXPECT_TRUE(f.good()) << name;
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

/** What a reader returned: status, items, error, warnings. */
struct FileRead {
    mt_status_t st;
    std::vector<mt_wpl_item_t> items;
    mt_wpl_error_t err;
    mt_wpl_warnings_t warn;
};

inline FileRead ParseWpl(const std::string &text)
{
    FileRead r{};
    r.items.resize(MT_CFG_MISSION_MAX_CMDS);
    size_t n = 0;
    r.st = mt_wpl_parse(text.data(), text.size(), r.items.data(), r.items.size(), &n, &r.err,
                        &r.warn);
    r.items.resize(n);
    return r;
}

inline FileRead ParsePlan(const std::string &text, size_t cap = MT_CFG_MISSION_MAX_CMDS)
{
    FileRead r{};
    r.items.resize(cap);
    size_t n = 0;
    r.st = mt_plan_parse(text.data(), text.size(), r.items.data(), cap, &n, &r.err, &r.warn);
    r.items.resize(n);
    return r;
}

} // namespace mt_test

#endif
