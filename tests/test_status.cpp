// SPDX-License-Identifier: Apache-2.0
// Status enum: distinct explicit values below the count sentinel, one stable
// distinct name per status (mt/status.h).
#include <cstring>
#include <set>
#include <string>

#include "mt_test_util.h"

namespace
{

struct Named {
    mt_status_t st;
    const char *name;
};

// The documented list, spelled out independently of status.c.
const Named kAll[] = {
    {MT_OK, "MT_OK"},
    {MT_E_INVALID, "MT_E_INVALID"},
    {MT_E_FULL, "MT_E_FULL"},
    {MT_E_EMPTY, "MT_E_EMPTY"},
    {MT_E_DUPLICATE, "MT_E_DUPLICATE"},
    {MT_E_TIMEOUT, "MT_E_TIMEOUT"},
    {MT_E_BUSY, "MT_E_BUSY"},
    {MT_E_RANGE, "MT_E_RANGE"},
    {MT_E_TASK_ORDER, "MT_E_TASK_ORDER"},
    {MT_E_TASK_RATE, "MT_E_TASK_RATE"},
    {MT_E_TASK_BUDGET, "MT_E_TASK_BUDGET"},
    {MT_E_TASK_COUNT, "MT_E_TASK_COUNT"},
    {MT_E_LOOP_RATE, "MT_E_LOOP_RATE"},
    {MT_E_TASK_FN, "MT_E_TASK_FN"},
    {MT_W_DROPPED_OLDEST, "MT_W_DROPPED_OLDEST"},
    {MT_E_MISSION_CMD, "MT_E_MISSION_CMD"},
    {MT_E_MISSION_PARAM, "MT_E_MISSION_PARAM"},
    {MT_E_MISSION_LOCATION, "MT_E_MISSION_LOCATION"},
    {MT_E_MISSION_FRAME, "MT_E_MISSION_FRAME"},
    {MT_E_MISSION_JUMP, "MT_E_MISSION_JUMP"},
    {MT_E_MISSION_LOOP, "MT_E_MISSION_LOOP"},
    {MT_E_MISSION_SIZE, "MT_E_MISSION_SIZE"},
    {MT_E_MISSION_SYNTAX, "MT_E_MISSION_SYNTAX"},
    {MT_E_STATE, "MT_E_STATE"},
    {MT_W_WQ_MERGED, "MT_W_WQ_MERGED"},
    {MT_E_BUS_MSG_SIZE, "MT_E_BUS_MSG_SIZE"},
    {MT_E_BUS_QUEUE_LEN, "MT_E_BUS_QUEUE_LEN"},
    {MT_E_BUS_STORAGE, "MT_E_BUS_STORAGE"},
    {MT_E_BUS_BEHIND, "MT_E_BUS_BEHIND"},
    {MT_E_BUS_TORN, "MT_E_BUS_TORN"},
    {MT_W_BUS_MISSED, "MT_W_BUS_MISSED"},
};

TEST(Status, ValuesDistinctAndBelowCount)
{
    std::set<int> values;
    for (const Named &n : kAll) {
        EXPECT_GE(static_cast<int>(n.st), 0) << n.name;
        EXPECT_LT(static_cast<int>(n.st), static_cast<int>(MT_STATUS_COUNT)) << n.name;
        EXPECT_TRUE(values.insert(static_cast<int>(n.st)).second) << "duplicate value " << n.name;
    }
    // every value below the sentinel is a listed status (no gaps, no extras)
    EXPECT_EQ(values.size(), static_cast<size_t>(MT_STATUS_COUNT));
    EXPECT_EQ(MT_OK, 0);
}

TEST(Status, EveryStatusHasItsOwnDistinctName)
{
    std::set<std::string> names;
    for (const Named &n : kAll) {
        const char *s = mt_status_str(n.st);
        ASSERT_NE(s, nullptr);
        EXPECT_STREQ(s, n.name);
        EXPECT_STRNE(s, "MT_STATUS_?");
        EXPECT_TRUE(names.insert(s).second) << "duplicate name " << s;
    }
    EXPECT_EQ(names.size(), static_cast<size_t>(MT_STATUS_COUNT));
}

TEST(Status, SentinelIsNotAStatus)
{
    EXPECT_STREQ(mt_status_str(MT_STATUS_COUNT), "MT_STATUS_?");
    EXPECT_STREQ(mt_status_str(static_cast<mt_status_t>(1000)), "MT_STATUS_?");
    EXPECT_STREQ(mt_status_names[MT_STATUS_COUNT], "MT_STATUS_?");
}

// The contract of mt_status_str returns the table's entry; the table itself holds the names.
TEST(Status, TheTableHoldsTheNames)
{
    for (const Named &n : kAll) {
        EXPECT_STREQ(mt_status_names[n.st], n.name);
        EXPECT_EQ(mt_status_str(n.st), mt_status_names[n.st]);
    }
}

} // namespace
