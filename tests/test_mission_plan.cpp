// SPDX-License-Identifier: Apache-2.0
// QGroundControl .plan files (mission/plan.h, mfile.h): reading, refusing, writing, the
// .plan <-> QGC WPL 110 conversion and its round trip, and the check report of a .plan.
#include <gtest/gtest.h>

#include <cjson/cJSON.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mfile.h"
#include "mission_file_test_util.h"
#include "plan.h"
#include "report.h"
#include "wpl.h"

namespace
{

using mt_test::FileRead;
using mt_test::ParsePlan;
using mt_test::ParseWpl;
using mt_test::ReadMissionFile;

std::string WritePlan(const std::vector<mt_wpl_item_t> &items)
{
    char *out = nullptr;
    size_t len = 0;
    mt_wpl_error_t e{};
    EXPECT_EQ(mt_plan_write(items.data(), items.size(), &out, &len, &e), MT_OK) << e.reason;
    std::string s = out != nullptr ? std::string(out, len) : std::string();
    std::free(out);
    return s;
}

std::string WriteWpl(const std::vector<mt_wpl_item_t> &items)
{
    size_t need = mt_wpl_write(items.data(), items.size(), nullptr, 0) + 1;
    std::string s(need, '\0');
    mt_wpl_write(items.data(), items.size(), &s[0], need);
    s.resize(need - 1);
    return s;
}

bool SameValue(double a, double b)
{
    return std::isnan(a) ? std::isnan(b) : std::memcmp(&a, &b, sizeof a) == 0;
}

// command, frame, autocontinue and the 7 parameters, bit for bit (NaN == NaN)
void ExpectSameMission(const std::vector<mt_wpl_item_t> &a, const std::vector<mt_wpl_item_t> &b)
{
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); i++) {
        EXPECT_EQ(a[i].command, b[i].command) << i;
        EXPECT_EQ(a[i].frame, b[i].frame) << i;
        EXPECT_EQ(a[i].autocontinue, b[i].autocontinue) << i;
        EXPECT_EQ(a[i].seq, b[i].seq) << i;
        for (int f = 0; f < 7; f++) {
            EXPECT_TRUE(SameValue(a[i].p[f], b[i].p[f])) << "item " << i << " param " << f + 1 << ": "
                                                          << a[i].p[f] << " vs " << b[i].p[f];
        }
    }
}

// A minimal valid .plan around the given mission items (JSON text of the array).
std::string PlanWith(const std::string &items, const std::string &extra = "")
{
    return "{\"fileType\": \"Plan\", \"version\": 1, " + extra +
           "\"mission\": {\"version\": 2, \"firmwareType\": 3, \"plannedHomePosition\": [-35.36, 149.16, 584], "
           "\"items\": [" +
           items + "]}}";
}

std::string Simple(int command, int frame, const std::string &params, int jump_id = -1)
{
    return "{\"type\": \"SimpleItem\", \"autoContinue\": true, \"command\": " + std::to_string(command) +
           ", \"frame\": " + std::to_string(frame) + ", \"params\": [" + params + "]" +
           (jump_id >= 0 ? ", \"doJumpId\": " + std::to_string(jump_id) : std::string()) + "}";
}

TEST(MissionPlanFile, ReadsTheQgcExample)
{
    FileRead r = ParsePlan(ReadMissionFile("qgc_example.plan"));
    ASSERT_EQ(r.st, MT_OK) << r.err.reason;
    ASSERT_EQ(r.items.size(), 10u);
    const mt_wpl_item_t &h = r.items[0];
    EXPECT_EQ(h.command, 16u);
    EXPECT_EQ(h.frame, 0u);
    EXPECT_EQ(h.current, 1u);
    EXPECT_EQ(h.p[4], -35.363262);
    EXPECT_EQ(h.p[5], 149.165237);
    EXPECT_EQ(h.p[6], 584.09);
    const mt_wpl_item_t &t = r.items[1];
    EXPECT_EQ(t.seq, 1u);
    EXPECT_EQ(t.current, 0u);
    EXPECT_EQ(t.command, 22u);
    EXPECT_EQ(t.frame, 3u);
    EXPECT_EQ(t.autocontinue, 1u);
    EXPECT_TRUE(std::isnan(t.p[3])); // null
    EXPECT_EQ(t.p[4], -35.3632621);
    EXPECT_EQ(t.p[6], 20.0);
    EXPECT_EQ(r.items[2].command, 178u);
    EXPECT_EQ(r.items[2].p[1], 6.5);
    EXPECT_EQ(r.items[6].command, 177u);
    EXPECT_EQ(r.items[6].p[0], 3.0); // doJumpId 3 is index 3
    EXPECT_EQ(r.items[6].p[1], 1.0);
    EXPECT_EQ(r.items[8].p[6], 40.25);
    EXPECT_EQ(r.items[9].command, 20u);
    ASSERT_EQ(r.warn.n, 2u);
    EXPECT_STREQ(r.warn.w[0].reason, "geoFence: 1 polygon(s) and 0 circle(s) not carried (the mission only is read)");
    EXPECT_STREQ(r.warn.w[1].reason, "rallyPoints: 1 point(s) not carried (the mission only is read)");
    EXPECT_EQ(r.warn.w[0].index, MT_MISSION_NONE);
}

TEST(MissionPlanFile, CheckReportOfAPlan)
{
    const std::string text = ReadMissionFile("qgc_example.plan");
    std::vector<mt_plan_step_t> steps(64);
    mt_report_t rep{};
    // the content decides (a .plan starts with '{'), and so does the explicit format
    ASSERT_EQ(mt_report_check(text.data(), text.size(), steps.data(), steps.size(), &rep), MT_OK);
    EXPECT_TRUE(rep.valid);
    EXPECT_EQ(rep.nitems, 10u);
    EXPECT_EQ(rep.warnings.n, 2u);
    std::string seq;
    for (size_t i = 0; i < rep.nplan; i++) {
        seq += (seq.empty() ? "" : " ") + std::string(steps[i].kind == MT_MISSION_KIND_NAV ? "n" : "d") +
               std::to_string(steps[i].index);
    }
    EXPECT_EQ(seq, "n1 d2 n3 d4 n5 n3 d4 n5 d7 n8 n9");
    mt_report_t rep2{};
    ASSERT_EQ(mt_report_check_as(MT_MFILE_PLAN, text.data(), text.size(), steps.data(), steps.size(), &rep2), MT_OK);
    EXPECT_EQ(rep2.nplan, rep.nplan);
    // read as WPL on purpose: not a WPL header
    mt_report_t rep3{};
    EXPECT_EQ(mt_report_check_as(MT_MFILE_WPL, text.data(), text.size(), steps.data(), steps.size(), &rep3),
              MT_E_MISSION_SYNTAX);
}

TEST(MissionPlanFile, ComplexItemIsRefusedWithItsIndex)
{
    FileRead r = ParsePlan(ReadMissionFile("bad/complex_item.plan"));
    EXPECT_EQ(r.st, MT_E_MISSION_CMD);
    EXPECT_EQ(r.err.st, MT_E_MISSION_CMD);
    EXPECT_EQ(r.err.index, 4u); // items[3], after the home
    EXPECT_STREQ(r.err.reason,
                 "mission.items[3]: complex item \"survey\" refused: QGC makes its waypoints only on upload");
    EXPECT_TRUE(r.items.empty());
    for (const char *type : {"CorridorScan", "StructureScan"}) {
        FileRead c = ParsePlan(PlanWith(Simple(22, 3, "0,0,0,0,0,0,10") + ", {\"type\": \"ComplexItem\", "
                                   "\"complexItemType\": \"" + type + "\"}"));
        EXPECT_EQ(c.st, MT_E_MISSION_CMD) << type;
        EXPECT_EQ(c.err.index, 2u) << type;
        EXPECT_NE(std::string(c.err.reason).find(type), std::string::npos) << c.err.reason;
    }
}

struct BadPlan {
    const char *what;
    std::string text;
    mt_status_t st;
    uint32_t line;
    uint32_t field;
    uint32_t index;
    const char *reason_has;
};

TEST(MissionPlanFile, MalformedPlansGiveWhereAndWhy)
{
    const std::string ok1 = Simple(16, 3, "0,0,0,0,-35.3,149.1,20");
    const uint32_t none = MT_MISSION_NONE;
    const std::vector<BadPlan> cases = {
        {"empty", "", MT_E_MISSION_SYNTAX, 1, 0, none, "unexpected end"},
        {"not JSON", "{\n  \"fileType\": Plan\n}", MT_E_MISSION_SYNTAX, 2, 0, none, "syntax error"},
        {"cut short", "{\"fileType\": \"Plan\",\n", MT_E_MISSION_SYNTAX, 2, 0, none, "unexpected end"},
        {"trailing text", PlanWith(ok1) + "\n}", MT_E_MISSION_SYNTAX, 2, 0, none, "text after"},
        {"NUL byte", std::string("{\"a\": \0}", 8), MT_E_MISSION_SYNTAX, 1, 0, none, "NUL"},
        {"top level array", "[1, 2]", MT_E_MISSION_SYNTAX, 1, 0, none, "not a JSON object"},
        {"no fileType", "{\"version\": 1}", MT_E_MISSION_SYNTAX, 0, 0, none, "fileType: missing"},
        {"fileType", "{\"fileType\": \"Fence\"}", MT_E_MISSION_SYNTAX, 0, 0, none, "fileType: not \"Plan\""},
        {"version", "{\"fileType\": \"Plan\", \"version\": 2}", MT_E_MISSION_SYNTAX, 0, 0, none, "version: not 1"},
        {"no mission", "{\"fileType\": \"Plan\", \"version\": 1}", MT_E_MISSION_SYNTAX, 0, 0, none,
         "mission: missing"},
        {"mission version 1",
         "{\"fileType\": \"Plan\", \"version\": 1, \"mission\": {\"version\": 1, \"items\": []}}",
         MT_E_MISSION_SYNTAX, 0, 0, none, "mission.version: not 2"},
        {"no home",
         "{\"fileType\": \"Plan\", \"version\": 1, \"mission\": {\"version\": 2, \"items\": []}}",
         MT_E_MISSION_SYNTAX, 0, 0, 0, "plannedHomePosition: missing"},
        {"home not a number",
         "{\"fileType\": \"Plan\", \"version\": 1, \"mission\": {\"version\": 2, \"plannedHomePosition\": "
         "[1, \"x\", 3], \"items\": []}}",
         MT_E_MISSION_SYNTAX, 0, 10, 0, "plannedHomePosition[1]"},
        {"items not an array", PlanWith("").replace(PlanWith("").find("\"items\": []"), 11, "\"items\": 7"),
         MT_E_MISSION_SYNTAX, 0, 0, none, "mission.items: not an array"},
        {"item not an object", PlanWith(ok1 + ", 5"), MT_E_MISSION_SYNTAX, 0, 0, 2, "items[1]: not an object"},
        {"item type", PlanWith("{\"type\": \"Fancy\"}"), MT_E_MISSION_SYNTAX, 0, 0, 1, "Fancy"},
        {"command", PlanWith("{\"type\": \"SimpleItem\", \"command\": \"16\"}"), MT_E_MISSION_SYNTAX, 0, 4, 1,
         "items[0].command: not an unsigned integer"},
        {"no command", PlanWith("{\"type\": \"SimpleItem\"}"), MT_E_MISSION_SYNTAX, 0, 4, 1,
         "items[0].command: missing"},
        {"frame", PlanWith(ok1 + ", " + Simple(16, -1, "0,0,0,0,0,0,0")), MT_E_MISSION_SYNTAX, 0, 3, 2,
         "items[1].frame"},
        {"six params", PlanWith(Simple(16, 3, "0,0,0,0,0,0")), MT_E_MISSION_SYNTAX, 0, 5, 1,
         "params: not an array of 7"},
        {"param text", PlanWith(Simple(16, 3, "0,0,\"x\",0,0,0,0")), MT_E_MISSION_SYNTAX, 0, 7, 1,
         "params[2]: not a number or null"},
        {"param infinite", PlanWith(Simple(16, 3, "0,0,0,0,0,0,1e999")), MT_E_MISSION_SYNTAX, 0, 11, 1,
         "params[6]: out of range"},
        {"autoContinue",
         PlanWith("{\"type\": \"SimpleItem\", \"autoContinue\": 1, \"command\": 16, \"frame\": 3, "
                  "\"params\": [0,0,0,0,0,0,0]}"),
         MT_E_MISSION_SYNTAX, 0, 12, 1, "autoContinue: not true or false"},
        {"doJumpId",
         PlanWith("{\"type\": \"SimpleItem\", \"autoContinue\": true, \"command\": 16, \"frame\": 3, "
                  "\"params\": [0,0,0,0,0,0,0], \"doJumpId\": -2}"),
         MT_E_MISSION_SYNTAX, 0, 1, 1, "doJumpId: not an unsigned integer"},
        {"jump to nobody", PlanWith(Simple(16, 3, "0,0,0,0,0,0,0", 1) + ", " + Simple(177, 2, "5,1,0,0,0,0,0", 2)),
         MT_E_MISSION_JUMP, 0, 5, 2, "DO_JUMP to doJumpId 5: no item has it"},
        {"jump NaN", PlanWith(Simple(16, 3, "0,0,0,0,0,0,0", 1) + ", " + Simple(177, 2, "null,1,0,0,0,0,0", 2)),
         MT_E_MISSION_JUMP, 0, 5, 2, "not a doJumpId"},
    };
    for (const BadPlan &c : cases) {
        FileRead r = ParsePlan(c.text);
        EXPECT_EQ(r.st, c.st) << c.what << ": " << r.err.reason;
        EXPECT_EQ(r.err.st, c.st) << c.what;
        EXPECT_EQ(r.err.line, c.line) << c.what;
        EXPECT_EQ(r.err.field, c.field) << c.what;
        EXPECT_EQ(r.err.index, c.index) << c.what;
        EXPECT_NE(std::string(r.err.reason).find(c.reason_has), std::string::npos) << c.what << ": " << r.err.reason;
        EXPECT_TRUE(r.items.empty()) << c.what;
    }
}

TEST(MissionPlanFile, SizeLimits)
{
    std::string items;
    for (int i = 0; i < 5; i++) {
        items += std::string(i ? ", " : "") + Simple(16, 3, "0,0,0,0,0,0,0");
    }
    FileRead r = ParsePlan(PlanWith(items), 5); // 5 items + home > 5
    EXPECT_EQ(r.st, MT_E_MISSION_SIZE);
    EXPECT_NE(std::string(r.err.reason).find("more than 5"), std::string::npos);
    EXPECT_EQ(ParsePlan(PlanWith(items), 6).st, MT_OK);
    // more JSON values than the limit: refused before cJSON allocates them
    std::string many = "{\"a\": [" + std::string(2 * MT_PLAN_MAX_VALUES, ',') + "]}";
    FileRead m = ParsePlan(many);
    EXPECT_EQ(m.st, MT_E_MISSION_SIZE);
    EXPECT_NE(std::string(m.err.reason).find("JSON values"), std::string::npos);
    // deep nesting: cJSON's nesting limit, an error and no crash
    FileRead d = ParsePlan(std::string(100000, '[') + std::string(100000, ']'));
    EXPECT_EQ(d.st, MT_E_MISSION_SYNTAX);
}

TEST(MissionPlanFile, DoJumpIdsAreMappedToIndices)
{
    // doJumpIds need not be the indices (QGC maps them on load)
    FileRead r = ParsePlan(PlanWith(Simple(22, 3, "0,0,0,0,0,0,10", 11) + ", " +
                               Simple(16, 3, "0,0,0,0,-35.3,149.1,20", 12) + ", " +
                               Simple(177, 2, "12,2,0,0,0,0,0", 13) + ", " + Simple(21, 3, "0,0,0,0,0,0,0", 14)));
    ASSERT_EQ(r.st, MT_OK) << r.err.reason;
    EXPECT_EQ(r.items[3].p[0], 2.0);
    ASSERT_EQ(r.warn.n, 1u);
    EXPECT_EQ(r.warn.w[0].index, 3u);
    EXPECT_STREQ(r.warn.w[0].reason, "mission.items[2]: DO_JUMP to doJumpId 12 is index 2");
    // written back, doJumpId is the index and param 1 stays the index
    FileRead b = ParsePlan(WritePlan(r.items));
    ASSERT_EQ(b.st, MT_OK);
    EXPECT_EQ(b.items[3].p[0], 2.0);
    EXPECT_EQ(b.warn.n, 0u);
}

TEST(MissionPlanFile, RoundTripPlanToWplToPlanKeepsEveryItem)
{
    FileRead a = ParsePlan(ReadMissionFile("qgc_example.plan"));
    ASSERT_EQ(a.st, MT_OK);
    // .plan -> WPL -> items
    FileRead w = ParseWpl(WriteWpl(a.items));
    ASSERT_EQ(w.st, MT_OK) << w.err.reason;
    EXPECT_EQ(w.warn.n, 0u);
    ExpectSameMission(a.items, w.items);
    // -> .plan -> items
    const std::string plan1 = WritePlan(w.items);
    FileRead b = ParsePlan(plan1);
    ASSERT_EQ(b.st, MT_OK) << b.err.reason;
    EXPECT_EQ(b.warn.n, 0u); // no geofence or rally points in what we write
    ExpectSameMission(a.items, b.items);
    EXPECT_EQ(b.items[0].p[4], -35.363262); // the home
    EXPECT_EQ(b.items[0].p[5], 149.165237);
    EXPECT_EQ(b.items[0].p[6], 584.09);
    EXPECT_EQ(WritePlan(b.items), plan1); // the writer is a fixed point
}

TEST(MissionPlanFile, ConvertWplToPlanAndBack)
{
    FileRead w = ParseWpl(ReadMissionFile("plain.waypoints"));
    ASSERT_EQ(w.st, MT_OK);
    const std::string plan = WritePlan(w.items);
    // what QGC reads: check the structure with cJSON itself
    cJSON *root = cJSON_Parse(plan.c_str());
    ASSERT_NE(root, nullptr);
    EXPECT_STREQ(cJSON_GetObjectItemCaseSensitive(root, "fileType")->valuestring, "Plan");
    EXPECT_EQ(cJSON_GetObjectItemCaseSensitive(root, "version")->valuedouble, 1.0);
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(root, "mission");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(cJSON_GetObjectItemCaseSensitive(m, "version")->valuedouble, 2.0);
    const cJSON *home = cJSON_GetObjectItemCaseSensitive(m, "plannedHomePosition");
    ASSERT_EQ(cJSON_GetArraySize(home), 3);
    EXPECT_EQ(cJSON_GetArrayItem(home, 0)->valuedouble, -35.363262);
    EXPECT_EQ(cJSON_GetArrayItem(home, 2)->valuedouble, 584.09);
    const cJSON *items = cJSON_GetObjectItemCaseSensitive(m, "items");
    ASSERT_EQ(cJSON_GetArraySize(items), 5);
    const cJSON *wp = cJSON_GetArrayItem(items, 2); // index 3: WAYPOINT 2 1.5 0 nan
    EXPECT_STREQ(cJSON_GetObjectItemCaseSensitive(wp, "type")->valuestring, "SimpleItem");
    EXPECT_EQ(cJSON_GetObjectItemCaseSensitive(wp, "command")->valuedouble, 16.0);
    EXPECT_EQ(cJSON_GetObjectItemCaseSensitive(wp, "doJumpId")->valuedouble, 3.0);
    EXPECT_TRUE(cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(wp, "autoContinue")));
    const cJSON *p = cJSON_GetObjectItemCaseSensitive(wp, "params");
    EXPECT_EQ(cJSON_GetArrayItem(p, 1)->valuedouble, 1.5);
    EXPECT_TRUE(cJSON_IsNull(cJSON_GetArrayItem(p, 3))); // NaN
    EXPECT_TRUE(cJSON_IsArray(cJSON_GetObjectItemCaseSensitive(
        cJSON_GetObjectItemCaseSensitive(root, "geoFence"), "polygons")));
    cJSON_Delete(root);
    // and back: the same mission, and the same WPL text
    FileRead b = ParsePlan(plan);
    ASSERT_EQ(b.st, MT_OK) << b.err.reason;
    ExpectSameMission(w.items, b.items);
    EXPECT_EQ(WriteWpl(b.items), WriteWpl(w.items));
}

TEST(MissionPlanFile, WriterValues)
{
    std::vector<mt_wpl_item_t> v(2);
    v[0].command = 16;
    v[0].p[4] = 47.3977419;
    v[0].p[5] = 8.545594;
    v[0].p[6] = 487.989;
    v[1].command = 16;
    v[1].frame = 3;
    v[1].seq = 1;
    v[1].p[0] = 0.1 + 0.2; // 0.30000000000000004: needs 17 digits
    v[1].p[1] = -0.0;
    v[1].p[2] = 1e-300;
    v[1].p[3] = NAN;
    v[1].p[6] = 20;
    const std::string s = WritePlan(v);
    EXPECT_NE(s.find("0.30000000000000004"), std::string::npos) << s;
    EXPECT_NE(s.find("[0.30000000000000004, -0, 1e-300, null, 0, 0, 20]"), std::string::npos) << s;
    FileRead r = ParsePlan(s);
    ASSERT_EQ(r.st, MT_OK);
    EXPECT_TRUE(SameValue(r.items[1].p[0], 0.1 + 0.2));
    EXPECT_TRUE(std::signbit(r.items[1].p[1]));
    EXPECT_EQ(r.items[1].autocontinue, 0u);
    // what JSON cannot hold
    char *out = nullptr;
    size_t len = 0;
    mt_wpl_error_t e{};
    v[1].p[2] = INFINITY;
    EXPECT_EQ(mt_plan_write(v.data(), v.size(), &out, &len, &e), MT_E_MISSION_PARAM);
    EXPECT_EQ(e.index, 1u);
    EXPECT_EQ(e.field, 7u);
    EXPECT_EQ(out, nullptr);
    v[1].p[2] = 0;
    v[0].p[5] = NAN;
    EXPECT_EQ(mt_plan_write(v.data(), v.size(), &out, &len, &e), MT_E_MISSION_PARAM);
    EXPECT_EQ(e.index, 0u);
    EXPECT_EQ(mt_plan_write(v.data(), 0, &out, &len, &e), MT_E_MISSION_SIZE);
}

TEST(MissionPlanFile, FormatByNameAndContent)
{
    EXPECT_EQ(mt_mfile_format_of_path("a/b.plan"), MT_MFILE_PLAN);
    EXPECT_EQ(mt_mfile_format_of_path("B.PLAN"), MT_MFILE_PLAN);
    EXPECT_EQ(mt_mfile_format_of_path("x.waypoints"), MT_MFILE_WPL);
    EXPECT_EQ(mt_mfile_format_of_path("x.Txt"), MT_MFILE_WPL);
    EXPECT_EQ(mt_mfile_format_of_path("x.mission"), MT_MFILE_WPL);
    EXPECT_EQ(mt_mfile_format_of_path("x.json"), MT_MFILE_AUTO);
    EXPECT_EQ(mt_mfile_format_of_path("plan"), MT_MFILE_AUTO);
    EXPECT_EQ(mt_mfile_sniff(" \r\n\t{", 5), MT_MFILE_PLAN);
    EXPECT_EQ(mt_mfile_sniff("\xEF\xBB\xBF{", 4), MT_MFILE_PLAN);
    EXPECT_EQ(mt_mfile_sniff("QGC WPL 110\n", 12), MT_MFILE_WPL);
    EXPECT_EQ(mt_mfile_sniff("", 0), MT_MFILE_WPL);
    // a BOM before the JSON is accepted too
    FileRead r = ParsePlan("\xEF\xBB\xBF" + PlanWith(Simple(16, 3, "0,0,0,0,0,0,0")));
    EXPECT_EQ(r.st, MT_OK) << r.err.reason;
}

} // namespace
