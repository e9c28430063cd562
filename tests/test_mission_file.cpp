// SPDX-License-Identifier: Apache-2.0
// Mission files (mission/wpl.h, report.h): QGC WPL 110 reading, writing,
// round trip, precise errors, and the execution plan of `mt-mission check`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mission_file_test_util.h"
#include "report.h"
#include "wpl.h"

namespace
{

using mt_test::FileRead;
using mt_test::ParseWpl;
using mt_test::ReadMissionFile;

std::string Write(const std::vector<mt_wpl_item_t> &items)
{
    size_t need = mt_wpl_write(items.data(), items.size(), nullptr, 0) + 1;
    std::string s(need, '\0');
    mt_wpl_write(items.data(), items.size(), &s[0], need);
    s.resize(need - 1);
    return s;
}

bool SameItem(const mt_wpl_item_t &a, const mt_wpl_item_t &b)
{
    if (a.seq != b.seq || a.current != b.current || a.frame != b.frame || a.command != b.command ||
        a.autocontinue != b.autocontinue) {
        return false;
    }
    for (int f = 0; f < 7; f++) {
        if (std::isnan(a.p[f]) != std::isnan(b.p[f])) {
            return false;
        }
        if (!std::isnan(a.p[f]) && std::memcmp(&a.p[f], &b.p[f], sizeof(double)) != 0) {
            return false;
        }
    }
    return true;
}

struct Plan {
    mt_status_t st;
    std::vector<mt_plan_step_t> steps;
    mt_report_t rep;
    std::string Seq() const
    {
        std::string s;
        for (const auto &p : steps) {
            s += (s.empty() ? "" : " ") + std::string(p.kind == MT_MISSION_KIND_NAV ? "n" : "d") +
                 std::to_string(p.index);
        }
        return s;
    }
};

Plan Check(const std::string &text, size_t max_plan = 200)
{
    Plan p;
    p.steps.resize(max_plan);
    p.st = mt_report_check(text.data(), text.size(), p.steps.data(), max_plan, &p.rep);
    p.steps.resize(p.rep.nplan);
    return p;
}

const char *const kValidFiles[] = {
    "plain.waypoints",     "nested_jumps.waypoints",      "repeat_forever.waypoints",
    "jump_tags.waypoints", "do_only_stretches.waypoints", "conditions.waypoints",
    "land_rtl.waypoints"};

TEST(MissionFile, EveryValidFileRoundTripsExactly)
{
    for (const char *name : kValidFiles) {
        FileRead a = ParseWpl(ReadMissionFile(name));
        ASSERT_EQ(a.st, MT_OK) << name << ": " << a.err.reason;
        ASSERT_GE(a.items.size(), 2u) << name;
        std::string w1 = Write(a.items);
        FileRead b = ParseWpl(w1);
        ASSERT_EQ(b.st, MT_OK) << name;
        ASSERT_EQ(a.items.size(), b.items.size()) << name;
        for (size_t i = 0; i < a.items.size(); i++) {
            EXPECT_TRUE(SameItem(a.items[i], b.items[i])) << name << " item " << i;
        }
        EXPECT_EQ(Write(b.items), w1) << name; // the writer is a fixed point
    }
}

TEST(MissionFile, RoundTripKeepsAwkwardValues)
{
    mt_wpl_item_t it{};
    it.current = 1;
    it.frame = 3;
    it.command = 16;
    it.autocontinue = 1;
    it.p[0] = 0.1;
    it.p[1] = 1e-300;
    it.p[2] = -0.0;
    it.p[3] = NAN;
    it.p[4] = -35.123456789012345;
    it.p[5] = 149.98765432109876;
    it.p[6] = 1e308;
    std::vector<mt_wpl_item_t> v{it};
    FileRead b = ParseWpl(Write(v));
    ASSERT_EQ(b.st, MT_OK);
    ASSERT_EQ(b.items.size(), 1u);
    EXPECT_TRUE(SameItem(it, b.items[0]));
    EXPECT_TRUE(std::signbit(b.items[0].p[2]));
}

TEST(MissionFile, AcceptsCrlfSpacesAndBlankLines)
{
    FileRead p = ParseWpl("\r\nQGC WPL 110\r\n0 1 0 16 0 0 0 0 -35.3 149.1 584 1\r\n\r\n"
                     "1  0  3  22  0 0 0 0 0 0 20 1\n");
    ASSERT_EQ(p.st, MT_OK) << p.err.reason;
    EXPECT_EQ(p.items.size(), 2u);
    EXPECT_EQ(p.items[1].line, 5u);
    EXPECT_EQ(p.items[1].command, 22u);
}

struct BadText {
    const char *what;
    std::string text;
    mt_status_t st;
    uint32_t line;
    uint32_t field;
    const char *reason_has;
};

TEST(MissionFile, MalformedTextGivesLineFieldAndReason)
{
    const std::string h = "QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t-35\t149\t584\t1\n";
    const std::vector<BadText> cases = {
        {"empty", "", MT_E_MISSION_SYNTAX, 1, 0, "empty file"},
        {"wrong header", "QGC WPL 120\n", MT_E_MISSION_SYNTAX, 1, 0, "header"},
        {"header only after data", "0 1 0 16 0 0 0 0 0 0 0 1\n", MT_E_MISSION_SYNTAX, 1, 0,
         "header"},
        {"missing fields", h + "1\t0\t3\t16\t0\t0\n", MT_E_MISSION_SYNTAX, 3, 7, "missing"},
        {"extra field", h + "1 0 3 16 0 0 0 0 0 0 0 1 9\n", MT_E_MISSION_SYNTAX, 3, 13,
         "more than 12"},
        {"bad seq", h + "x 0 3 16 0 0 0 0 0 0 0 1\n", MT_E_MISSION_SYNTAX, 3, 1, "seq"},
        {"current 2", h + "1 2 3 16 0 0 0 0 0 0 0 1\n", MT_E_MISSION_SYNTAX, 3, 2, "current"},
        {"negative frame", h + "1 0 -3 16 0 0 0 0 0 0 0 1\n", MT_E_MISSION_SYNTAX, 3, 3, "frame"},
        {"command word", h + "1 0 3 WP 0 0 0 0 0 0 0 1\n", MT_E_MISSION_SYNTAX, 3, 4, "command"},
        {"param garbage", h + "1 0 3 16 0 0 0 1.2.3 0 0 0 1\n", MT_E_MISSION_SYNTAX, 3, 8,
         "param4"},
        {"alt garbage", h + "1 0 3 16 0 0 0 0 0 0 12m 1\n", MT_E_MISSION_SYNTAX, 3, 11, "altitude"},
        {"autocontinue", h + "1 0 3 16 0 0 0 0 0 0 0 yes\n", MT_E_MISSION_SYNTAX, 3, 12,
         "autocontinue"},
        {"long token", h + "1 0 3 16 " + std::string(100, '1') + " 0 0 0 0 0 0 1\n",
         MT_E_MISSION_SYNTAX, 3, 5, "too long"},
        {"NUL", h + std::string("1 0 3 16 0\0 0 0 0 0 0 0 1\n", 26), MT_E_MISSION_SYNTAX, 3, 5,
         "NUL"},
        // a comment before the header is skipped, so the data line is where the header is missing
        {"comment, no header", "# x\n0 1 0 16 0 0 0 0 0 0 0 1\n", MT_E_MISSION_SYNTAX, 2, 0, "header"},
        {"header only", "QGC WPL 110\n", MT_E_MISSION_SIZE, 1, 0, "no items after the header"},
        {"header only, then blanks and comments", "\n# c\nQGC WPL 110\r\n\r\n# c\n", MT_E_MISSION_SIZE, 3,
         0, "no items after the header"},
        {"CR-only line ends still count fields", "QGC WPL 110\r0 1 0 16 0 0 0 0 0 0 0 1\r1 0 3 16 0\r",
         MT_E_MISSION_SYNTAX, 3, 6, "missing"},
    };
    for (const BadText &c : cases) {
        FileRead p = ParseWpl(c.text);
        EXPECT_EQ(p.st, c.st) << c.what;
        EXPECT_EQ(p.err.st, c.st) << c.what;
        EXPECT_EQ(p.err.line, c.line) << c.what;
        EXPECT_EQ(p.err.field, c.field) << c.what;
        EXPECT_NE(std::string(p.err.reason).find(c.reason_has), std::string::npos)
            << c.what << ": " << p.err.reason;
    }
}

TEST(MissionFile, TooManyItems)
{
    std::string t = "QGC WPL 110\n";
    for (unsigned i = 0; i <= MT_CFG_MISSION_MAX_CMDS; i++) {
        t += std::to_string(i) + " 0 3 16 0 0 0 0 0 0 0 1\n";
    }
    FileRead p = ParseWpl(t);
    EXPECT_EQ(p.st, MT_E_MISSION_SIZE);
    EXPECT_EQ(p.err.line, MT_CFG_MISSION_MAX_CMDS + 2u);
}

TEST(MissionFile, ConversionRules)
{
    mt_wpl_item_t it{};
    it.command = 16;
    it.frame = 3;
    it.p[0] = 1.2345; // rounds to 1235 (3 decimals)
    it.p[3] = NAN;
    it.p[4] = -35.3632621;
    it.p[5] = 149.1652374;
    it.p[6] = 584.09;
    mt_mission_cmd_t c{};
    mt_wpl_error_t e{};
    ASSERT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_OK);
    EXPECT_EQ(c.param[0], 1235);
    EXPECT_EQ(c.param[3], MT_MISSION_PARAM_NAN);
    EXPECT_EQ(c.x, -353632621);
    EXPECT_EQ(c.y, 1491652374);
    EXPECT_EQ(c.z, 58409);
    it.p[1] = INFINITY;
    EXPECT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_E_MISSION_PARAM);
    EXPECT_EQ(e.field, 6u);
    it.p[1] = 3e6; // above 2147483.647
    EXPECT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_E_MISSION_PARAM);
    it.p[1] = 0;
    it.p[6] = NAN;
    EXPECT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_E_MISSION_PARAM);
    EXPECT_EQ(e.field, 11u);
    it.p[6] = 0;
    it.p[4] = 300.0; // does not fit 1e-7 deg in int32
    EXPECT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_E_MISSION_PARAM);
    it.p[4] = 0;
    it.command = 70000;
    EXPECT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_E_MISSION_CMD);
    it.command = 16;
    it.frame = 300;
    EXPECT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_E_MISSION_FRAME);
    EXPECT_STREQ(mt_wpl_cmd_name(177), "DO_JUMP");
    EXPECT_EQ(mt_wpl_cmd_name(12345), nullptr);
}

// ------------------------------------------------------------------ plans

TEST(MissionPlan, PlainWaypoints)
{
    Plan p = Check(ReadMissionFile("plain.waypoints"));
    EXPECT_EQ(p.st, MT_OK);
    EXPECT_TRUE(p.rep.valid);
    EXPECT_EQ(p.Seq(), "n1 n2 n3 n4 n5");
    EXPECT_FALSE(p.rep.truncated);
}

TEST(MissionPlan, NestedJumpsUnrolled)
{
    Plan p = Check(ReadMissionFile("nested_jumps.waypoints"));
    EXPECT_EQ(p.Seq(), "n1 n2 n3 n2 n3 n2 n3 n5 n2 n3 n2 n3 n2 n3 n5 n7");
}

TEST(MissionPlan, RepeatForeverIsTruncated)
{
    Plan p = Check(ReadMissionFile("repeat_forever.waypoints"), 10);
    EXPECT_TRUE(p.rep.valid);
    EXPECT_EQ(p.rep.truncated, (int)MT_REPORT_FOREVER);
    EXPECT_EQ(p.Seq(), "n1 n2 d3 n4 n2 d3 n4 n2 d3 n4");
}

TEST(MissionPlan, JumpTags)
{
    Plan p = Check(ReadMissionFile("jump_tags.waypoints"));
    EXPECT_EQ(p.Seq(), "n1 n3 n4 n3 n4 n7");
}

TEST(MissionPlan, DoStretchesStartWithTheNextNav)
{
    // the first do command of each stretch starts just before the nav command after it,
    // the others while that nav command runs; the trailing one before the last nav
    Plan p = Check(ReadMissionFile("do_only_stretches.waypoints"));
    EXPECT_EQ(p.Seq(), "d1 n3 d2 d4 n7 d5 d6 d8 n9");
}

TEST(MissionPlan, Conditions)
{
    Plan p = Check(ReadMissionFile("conditions.waypoints"));
    EXPECT_EQ(p.Seq(), "n1 d2 n5 d3 d4 d6 n8 d7 n9");
}

TEST(MissionPlan, LandAndRtl)
{
    Plan p = Check(ReadMissionFile("land_rtl.waypoints"));
    EXPECT_EQ(p.Seq(), "n1 n2 n3 d4 n5 n6");
}

struct BadFile {
    const char *name;
    mt_status_t st;
    uint32_t line;
    uint32_t index;
};

TEST(MissionPlan, InvalidFilesAreReportedWithLineAndIndex)
{
    const BadFile cases[] = {
        {"bad/header.waypoints", MT_E_MISSION_SYNTAX, 1, MT_MISSION_NONE},
        {"bad/missing_field.waypoints", MT_E_MISSION_SYNTAX, 3, MT_MISSION_NONE},
        {"bad/not_a_number.waypoints", MT_E_MISSION_SYNTAX, 3, 1},
        {"bad/header_only.waypoints", MT_E_MISSION_SIZE, 1, 0},
        {"bad/values.waypoints", MT_E_MISSION_PARAM, 3, 1},
        {"bad/do_only_forever.waypoints", MT_E_MISSION_LOOP, 4, 2},
        {"bad/jump_target.waypoints", MT_E_MISSION_JUMP, 4, 2},
        {"bad/unknown_tag.waypoints", MT_E_MISSION_JUMP, 4, 2},
    };
    for (const BadFile &c : cases) {
        Plan p = Check(ReadMissionFile(c.name));
        EXPECT_EQ(p.st, c.st) << c.name;
        EXPECT_FALSE(p.rep.valid) << c.name;
        ASSERT_GE(p.rep.nerr, 1u) << c.name;
        EXPECT_EQ(p.rep.errors[0].line, c.line) << c.name;
        EXPECT_EQ(p.rep.errors[0].index, c.index) << c.name;
        EXPECT_TRUE(p.steps.empty()) << c.name;
    }
    // every problem of a file is listed, not just the first
    Plan v = Check(ReadMissionFile("bad/values.waypoints"));
    ASSERT_EQ(v.rep.nerr, 4u);
    EXPECT_EQ(v.rep.errors[1].st, MT_E_MISSION_PARAM);
    EXPECT_EQ(v.rep.errors[2].st, MT_E_MISSION_LOCATION);
    EXPECT_EQ(v.rep.errors[3].st, MT_E_MISSION_CMD);
}

TEST(MissionPlan, JsonShape)
{
    Plan p = Check(ReadMissionFile("repeat_forever.waypoints"), 3);
    std::string j(mt_report_json(&p.rep, nullptr, 0) + 1, '\0');
    mt_report_json(&p.rep, &j[0], j.size());
    EXPECT_EQ(
        j.rfind("{\"valid\": true, \"errors\": [], \"warnings\": [], \"warnings_not_shown\": 0, "
                "\"plan\": [{\"index\": 1, \"command\": 22, "
                "\"name\": \"NAV_TAKEOFF\", \"kind\": \"nav\", \"during\": null}",
                0),
        0u)
        << j;
    EXPECT_NE(j.find("\"truncated\": true, \"truncated_reason\": \"repeats forever\", "
                     "\"plan_total\": null}"),
              std::string::npos)
        << j;
    EXPECT_NE(j.find("\"errors\": [], \"warnings\": [], \"warnings_not_shown\": 0, \"plan\": ["),
              std::string::npos)
        << j;
    Plan b = Check("QGC WPL 110\n0 1 0 16 0 0 0 0 0 0 0 1\n1 0 3 16 \"x 0 0 0 0 0 0 1\n");
    std::string k(mt_report_json(&b.rep, nullptr, 0) + 1, '\0');
    mt_report_json(&b.rep, &k[0], k.size());
    EXPECT_NE(k.find("\\\"x"), std::string::npos) << k; // quotes escaped
    EXPECT_NE(k.find("\"valid\": false"), std::string::npos);
}

// ------------------------------------------------- what real ground stations write

const std::string kHome = "0\t1\t0\t16\t0\t0\t0\t0\t-35.363262\t149.165237\t584.09\t1";

std::string Text(const mt_report_t &rep, const char *file)
{
    std::string t(mt_report_text(&rep, file, nullptr, 0) + 1, '\0');
    mt_report_text(&rep, file, &t[0], t.size());
    t.resize(t.size() - 1);
    return t;
}

std::string Json(const mt_report_t &rep)
{
    std::string j(mt_report_json(&rep, nullptr, 0) + 1, '\0');
    mt_report_json(&rep, &j[0], j.size());
    j.resize(j.size() - 1);
    return j;
}

TEST(MissionFileCompat, CommentLinesAreSkipped)
{
    FileRead p = ParseWpl("# saved by MAVProxy\nQGC WPL 110\n# home\n" + kHome +
                     "\n  \t# indented comment 1 0 3 16\n1 0 3 22 0 0 0 0 0 0 15 1\n#\n");
    ASSERT_EQ(p.st, MT_OK) << p.err.reason;
    ASSERT_EQ(p.items.size(), 2u);
    EXPECT_EQ(p.items[0].line, 4u);
    EXPECT_EQ(p.items[1].line, 6u);
    EXPECT_EQ(p.items[1].command, 22u);
    EXPECT_EQ(p.items[1].p[6], 15.0);
    EXPECT_EQ(p.warn.n, 0u);
}

TEST(MissionFileCompat, Utf8BomIsAccepted)
{
    FileRead p = ParseWpl("\xEF\xBB\xBFQGC WPL 110\n" + kHome + "\n");
    ASSERT_EQ(p.st, MT_OK) << p.err.reason;
    ASSERT_EQ(p.items.size(), 1u);
    EXPECT_EQ(p.items[0].p[4], -35.363262);
    // only at the very start: a BOM in the middle of a line is not a number
    FileRead q = ParseWpl("QGC WPL 110\n0 1 0 16 \xEF\xBB\xBF" "0 0 0 0 0 0 0 1\n");
    EXPECT_EQ(q.st, MT_E_MISSION_SYNTAX);
    EXPECT_EQ(q.err.field, 5u);
}

TEST(MissionFileCompat, CrOnlyCrlfAndLfLineEndsReadAlike)
{
    const std::string lf = "QGC WPL 110\n" + kHome + "\n1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t15\t1\n\n" +
                           "2\t0\t3\t21\t0\t0\t0\t0\t0\t0\t0\t1\n";
    std::string cr = lf;
    std::string crlf;
    for (char &c : cr) {
        if (c == '\n') {
            c = '\r';
        }
    }
    for (char c : lf) {
        crlf += (c == '\n') ? std::string("\r\n") : std::string(1, c);
    }
    FileRead a = ParseWpl(lf);
    FileRead b = ParseWpl(cr);
    FileRead c = ParseWpl(crlf);
    ASSERT_EQ(a.st, MT_OK);
    ASSERT_EQ(b.st, MT_OK) << b.err.reason;
    ASSERT_EQ(c.st, MT_OK) << c.err.reason;
    ASSERT_EQ(a.items.size(), 3u);
    ASSERT_EQ(b.items.size(), 3u);
    ASSERT_EQ(c.items.size(), 3u);
    for (size_t i = 0; i < 3; i++) {
        EXPECT_TRUE(SameItem(a.items[i], b.items[i])) << i;
        EXPECT_TRUE(SameItem(a.items[i], c.items[i])) << i;
        EXPECT_EQ(a.items[i].line, b.items[i].line) << i; // a CR is one line end, CRLF too
        EXPECT_EQ(a.items[i].line, c.items[i].line) << i;
    }
    EXPECT_EQ(b.items[2].line, 5u);
}

TEST(MissionFileCompat, CommittedBomCrlfAndCrOnlyFilesMatchTheirLfText)
{
    const std::string lf = "QGC WPL 110\n0\t1\t0\t16\t0.000000\t0.000000\t0.000000\t0.000000\t-35.363262\t"
                           "149.165237\t584.090000\t1\n1 0 3 22 0 0 0 0 0 0 15 1\n"
                           "2 0 3 16 0 0 0 0 -35.361908 149.163399 30 1\n3 0 3 21 0 0 0 0 0 0 0 1\n";
    FileRead want = ParseWpl(lf);
    ASSERT_EQ(want.st, MT_OK);
    for (const char *name : {"comments_bom_crlf.waypoints", "cr_only.waypoints"}) {
        FileRead got = ParseWpl(ReadMissionFile(name));
        ASSERT_EQ(got.st, MT_OK) << name << ": " << got.err.reason;
        ASSERT_EQ(got.items.size(), 4u) << name;
        for (size_t i = 0; i < 4; i++) {
            EXPECT_TRUE(SameItem(want.items[i], got.items[i])) << name << " item " << i;
        }
        EXPECT_EQ(got.warn.n, 0u) << name;
    }
    EXPECT_EQ(ParseWpl(ReadMissionFile("comments_bom_crlf.waypoints")).items[3].line, 9u);
}

TEST(MissionFileCompat, SeqGapIsRenumberedWithAWarning)
{
    FileRead p = ParseWpl("QGC WPL 110\n" + kHome + "\n2 0 3 22 0 0 0 0 0 0 15 1\n3 0 3 21 0 0 0 0 0 0 0 1\n");
    ASSERT_EQ(p.st, MT_OK) << p.err.reason;
    ASSERT_EQ(p.items.size(), 3u);
    EXPECT_EQ(p.items[1].seq, 1u);
    EXPECT_EQ(p.items[2].seq, 2u);
    ASSERT_EQ(p.warn.n, 1u); // one discontinuity, one warning
    EXPECT_EQ(p.warn.w[0].st, MT_OK);
    EXPECT_EQ(p.warn.w[0].line, 3u);
    EXPECT_EQ(p.warn.w[0].field, 1u);
    EXPECT_EQ(p.warn.w[0].index, 1u);
    EXPECT_STREQ(p.warn.w[0].reason, "seq: 2 where 1 was expected; renumbered to 1 (jump targets use the new numbers)");
    // out of order: 0 2 1 -> two discontinuities
    FileRead q = ParseWpl("QGC WPL 110\n" + kHome + "\n2 0 3 22 0 0 0 0 0 0 15 1\n1 0 3 21 0 0 0 0 0 0 0 1\n");
    ASSERT_EQ(q.st, MT_OK);
    EXPECT_EQ(q.items[2].command, 21u);
    EXPECT_EQ(q.items[2].seq, 2u);
    EXPECT_EQ(q.warn.n, 2u);
    // the committed fixture: valid, with the warning in the report
    Plan c = Check(ReadMissionFile("warn/seq_gap.waypoints"));
    EXPECT_EQ(c.st, MT_OK);
    EXPECT_TRUE(c.rep.valid);
    ASSERT_EQ(c.rep.warnings.n, 1u);
    EXPECT_EQ(c.rep.warnings.w[0].line, 3u);
    EXPECT_EQ(c.Seq(), "n1");
}

TEST(MissionFileCompat, WarningsBeyondTheListAreCounted)
{
    std::string t = "QGC WPL 110\n" + kHome + "\n";
    for (unsigned i = 1; i <= 40; i++) {
        t += std::to_string(2 * i) + " 0 3 16 0 0 0 0 0 0 0 1\n"; // every seq jumps
    }
    FileRead p = ParseWpl(t);
    ASSERT_EQ(p.st, MT_OK);
    EXPECT_EQ(p.items.size(), 41u);
    EXPECT_EQ(p.warn.n, (size_t)MT_WPL_MAX_WARNINGS);
    EXPECT_EQ(p.warn.dropped, 40u - MT_WPL_MAX_WARNINGS);
}

TEST(MissionFileCompat, MissionPlannerHomeWithCommandZero)
{
    FileRead p = ParseWpl(ReadMissionFile("warn/mission_planner_home.waypoints"));
    ASSERT_EQ(p.st, MT_OK) << p.err.reason;
    EXPECT_EQ(p.items[0].command, 16u);
    ASSERT_EQ(p.warn.n, 1u);
    EXPECT_EQ(p.warn.w[0].line, 3u);
    EXPECT_EQ(p.warn.w[0].field, 4u);
    EXPECT_EQ(p.warn.w[0].index, 0u);
    Plan c = Check(ReadMissionFile("warn/mission_planner_home.waypoints"));
    EXPECT_TRUE(c.rep.valid);
    EXPECT_EQ(c.Seq(), "n1 n2 n3");
    // only the home: command 0 later is an unknown command
    Plan d = Check("QGC WPL 110\n" + kHome + "\n1 0 3 0 0 0 0 0 0 0 0 1\n");
    EXPECT_EQ(d.st, MT_E_MISSION_CMD);
    EXPECT_EQ(d.rep.errors[0].index, 1u);
}

TEST(MissionFileCompat, DoCommandInFrameOneIsAccepted)
{
    EXPECT_EQ(mt_wpl_frame_ignored(183), 1);  // DO_SET_SERVO
    EXPECT_EQ(mt_wpl_frame_ignored(177), 1);  // DO_JUMP
    EXPECT_EQ(mt_wpl_frame_ignored(112), 1);  // CONDITION_DELAY
    EXPECT_EQ(mt_wpl_frame_ignored(201), 0);  // DO_SET_ROI: a location
    EXPECT_EQ(mt_wpl_frame_ignored(16), 0);   // nav
    EXPECT_EQ(mt_wpl_frame_ignored(9999), 0); // unknown
    mt_wpl_item_t it{};
    it.command = 183;
    it.frame = 1;
    it.p[0] = 9;
    it.p[1] = 1500;
    mt_mission_cmd_t c{};
    mt_wpl_error_t e{};
    ASSERT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_OK);
    EXPECT_EQ(c.frame, 2u);
    it.frame = 3; // a frame the kernel takes is passed as is
    ASSERT_EQ(mt_wpl_to_cmd(&it, &c, &e), MT_OK);
    EXPECT_EQ(c.frame, 3u);

    Plan p = Check(ReadMissionFile("warn/do_frame1.waypoints"));
    EXPECT_EQ(p.st, MT_OK);
    EXPECT_TRUE(p.rep.valid);
    EXPECT_EQ(p.Seq(), "n1 d2 n3 d4 n5");
    ASSERT_EQ(p.rep.warnings.n, 2u);
    EXPECT_EQ(p.rep.warnings.w[0].line, 4u);
    EXPECT_EQ(p.rep.warnings.w[0].field, 3u);
    EXPECT_EQ(p.rep.warnings.w[0].index, 2u);
    EXPECT_STREQ(p.rep.warnings.w[0].reason, "frame 1 ignored: command 183 (DO_SET_SERVO) has no "
                                             "location; checked as frame 2 (MISSION)");
    // a nav command, or a do command with a location, in frame 1 is still refused
    Plan n = Check("QGC WPL 110\n" + kHome + "\n1 0 1 16 0 0 0 0 -35.36 149.16 30 1\n"
                   "2 0 1 201 0 0 0 0 -35.36 149.16 30 1\n");
    EXPECT_EQ(n.st, MT_E_MISSION_FRAME);
    ASSERT_EQ(n.rep.nerr, 2u);
    EXPECT_EQ(n.rep.errors[0].index, 1u);
    EXPECT_EQ(n.rep.errors[1].index, 2u);
}

TEST(MissionFileCompat, HeaderOnlyFileReportsTheHeaderLine)
{
    Plan p = Check(ReadMissionFile("bad/header_only.waypoints"));
    EXPECT_EQ(p.st, MT_E_MISSION_SIZE);
    EXPECT_FALSE(p.rep.valid);
    ASSERT_EQ(p.rep.nerr, 1u);
    EXPECT_EQ(p.rep.errors[0].line, 1u);
    EXPECT_EQ(Text(p.rep, "h.waypoints"),
              "h.waypoints:1: index 0: no items after the header: a mission needs at least the "
              "home entry "
              "(index 0) [MT_E_MISSION_SIZE]\nh.waypoints: INVALID (1 error)\n");
}

TEST(MissionFileCompat, WarningsAreListedInJsonAndText)
{
    Plan p = Check(ReadMissionFile("warn/mission_planner_home.waypoints"));
    const std::string j = Json(p.rep);
    EXPECT_NE(
        j.find(
            "\"errors\": [], \"warnings\": [{\"line\": 3, \"field\": 4, \"index\": 0, \"reason\": "
            "\"home: command 0 (Mission Planner) read as WAYPOINT (16)\"}], "
            "\"warnings_not_shown\": 0"),
        std::string::npos)
        << j;
    const std::string t = Text(p.rep, "mp.waypoints");
    EXPECT_EQ(t.rfind("mp.waypoints:3: field 4: index 0: warning: home: command 0 (Mission Planner) read as "
                      "WAYPOINT (16)\nmp.waypoints: valid, 4 items\n",
                      0),
              0u)
        << t;
}

TEST(MissionPlanTruncation, SaysWhy)
{
    // repeats forever: the sequencer comes back to a state it was in
    Plan f = Check(ReadMissionFile("repeat_forever.waypoints"), 10);
    EXPECT_EQ(f.rep.truncated, (int)MT_REPORT_FOREVER);
    EXPECT_EQ(f.rep.plan_total, 0u);
    EXPECT_NE(Text(f.rep, "f").find("  ... truncated after 10 steps: the mission repeats forever\n"),
              std::string::npos);
    EXPECT_NE(Json(f.rep).find("\"truncated\": true, \"truncated_reason\": \"repeats forever\""),
              std::string::npos);
    // finite, 16 steps, limit 5: longer than the limit, not "forever"
    Plan l = Check(ReadMissionFile("nested_jumps.waypoints"), 5);
    EXPECT_TRUE(l.rep.valid);
    EXPECT_EQ(l.rep.truncated, (int)MT_REPORT_OVER_LIMIT);
    EXPECT_EQ(l.rep.plan_total, 16u);
    EXPECT_EQ(l.steps.size(), 5u);
    EXPECT_NE(Text(l.rep, "n").find("  ... truncated after 5 steps: longer than the plan limit (16 steps in all; "
                                    "--max-plan)\n"),
              std::string::npos)
        << Text(l.rep, "n");
    EXPECT_NE(Json(l.rep).find("\"truncated\": true, \"truncated_reason\": \"longer than the plan limit\", "
                               "\"plan_total\": 16}"),
              std::string::npos)
        << Json(l.rep);
    // exactly at the limit: complete
    Plan e = Check(ReadMissionFile("nested_jumps.waypoints"), 16);
    EXPECT_EQ(e.rep.truncated, (int)MT_REPORT_COMPLETE);
    EXPECT_EQ(e.rep.plan_total, 16u);
    // finite but far too long to run out (30000 x 30000 laps): over the limit, length unknown
    Plan h = Check("QGC WPL 110\n" + kHome + "\n1 0 3 16 0 0 0 0 -35.1 149 30 1\n"
                   "2 0 3 16 0 0 0 0 -35.2 149 30 1\n3 0 2 177 1 30000 0 0 0 0 0 1\n"
                   "4 0 2 177 1 30000 0 0 0 0 0 1\n5 0 3 21 0 0 0 0 0 0 0 1\n",
                   5);
    EXPECT_TRUE(h.rep.valid);
    EXPECT_EQ(h.rep.truncated, (int)MT_REPORT_OVER_LIMIT);
    EXPECT_EQ(h.rep.plan_total, 0u);
    EXPECT_NE(Text(h.rep, "h").find("longer than the plan limit (no end and no repetition found"),
              std::string::npos);
}

TEST(MissionPlan, EachDoStepSaysWhetherItsStartDependsOnTiming)
{
    // item 2 of the mission rules: one verify policy, and the report says which do commands
    // start with the nav advance (any timing) and which while a nav command runs (later, or
    // dropped, under slower do commands)
    Plan p = Check(ReadMissionFile("conditions.waypoints"));
    ASSERT_EQ(p.Seq(), "n1 d2 n5 d3 d4 d6 n8 d7 n9");
    const uint16_t during[] = {MT_MISSION_NONE,
                               MT_MISSION_NONE,
                               MT_MISSION_NONE,
                               5,
                               5,
                               MT_MISSION_NONE,
                               MT_MISSION_NONE,
                               8,
                               MT_MISSION_NONE};
    ASSERT_EQ(p.steps.size(), 9u);
    for (size_t i = 0; i < p.steps.size(); i++) {
        EXPECT_EQ(p.steps[i].during, during[i]) << i;
    }
    const std::string t = Text(p.rep, "c.waypoints");
    EXPECT_NE(t.find("#3    DO_SET_SERVO (183)  while #5 runs*"), std::string::npos) << t;
    EXPECT_NE(t.find("it is dropped if the nav command completes first"), std::string::npos) << t;
    EXPECT_EQ(t.find("#2    CONDITION_DELAY (112)  while"), std::string::npos) << t;
    const std::string j = Json(p.rep);
    EXPECT_NE(j.find("{\"index\": 3, \"command\": 183, \"name\": \"DO_SET_SERVO\", \"kind\": "
                     "\"do\", \"during\": 5}"),
              std::string::npos)
        << j;
    // a trailing do command starts with the advance, then the mission completes
    Plan q = Check("QGC WPL 110\n" + kHome + "\n1\t0\t3\t22\t0\t0\t0\t0\t0\t0\t15\t1\n" +
                   "2\t0\t2\t208\t2\t0\t0\t0\t0\t0\t0\t1\n");
    EXPECT_EQ(q.Seq(), "n1 d2");
    EXPECT_EQ(q.rep.truncated, (int)MT_REPORT_COMPLETE);
    ASSERT_EQ(q.steps.size(), 2u);
    EXPECT_EQ(q.steps[1].during, MT_MISSION_NONE);
    EXPECT_EQ(Text(q.rep, "p").find("runs*"), std::string::npos);
}

} // namespace
