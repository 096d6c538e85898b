// The Comparison tab's project file: written, read back, and refused with
// the key named.

#include "core/comparison/comparison_project.h"

#include <gtest/gtest.h>

#include <string>

#include "core/common/input_error.h"

namespace probecycle {
namespace {

std::string refusal(const std::string& text) {
    try {
        (void)parse_comparison_project(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(ComparisonProjectTest, WritesAndReadsBackEveryField) {
    ComparisonProject p;
    p.plan = "plan.csv";
    p.reference_cmm = "cmm/ref.csv";
    p.test_omm = "/abs/test.csv";
    p.reference_omm = "ref_omm.csv";
    p.block_c0 = "b0.csv";
    p.c_axis_x_mm = 200.5;
    p.c_axis_y_mm = -100.0;
    p.angle_deg = 90.0;
    p.tolerance_mm = 0.02;
    const std::string text = comparison_project_json(p);
    EXPECT_EQ(text.rfind("{\n  \"format\": \"probecycle-comparison\",\n  \"version\": 1,", 0), 0u);
    const ComparisonProject q = parse_comparison_project(text);
    EXPECT_EQ(q.plan, p.plan);
    EXPECT_EQ(q.reference_cmm, p.reference_cmm);
    EXPECT_EQ(q.test_omm, p.test_omm);
    EXPECT_EQ(q.reference_omm, p.reference_omm);
    EXPECT_EQ(q.block_c0, p.block_c0);
    EXPECT_EQ(q.block_c180, "");
    EXPECT_DOUBLE_EQ(q.c_axis_x_mm, 200.5);
    EXPECT_DOUBLE_EQ(q.c_axis_y_mm, -100.0);
    EXPECT_DOUBLE_EQ(q.angle_deg, 90.0);
    EXPECT_DOUBLE_EQ(q.tolerance_mm, 0.02);
}

TEST(ComparisonProjectTest, MissingKeysTakeTheirDefaults) {
    const ComparisonProject q = parse_comparison_project("{\"plan\": \"p.csv\"}");
    EXPECT_EQ(q.plan, "p.csv");
    EXPECT_DOUBLE_EQ(q.angle_deg, 180.0);
    EXPECT_DOUBLE_EQ(q.tolerance_mm, 0.01);
}

TEST(ComparisonProjectTest, RefusesWithTheKeyAndWhatIsAllowed) {
    EXPECT_EQ(refusal("{\"angle_deg\": 0}"),
              "angle_deg: got 0; allowed: a number from 1 to 359 deg");
    EXPECT_EQ(refusal("{\"tolerance_mm\": \"0.01\"}"),
              "tolerance_mm: got \"0.01\"; allowed: a number from 1e-06 to 100 mm");
    EXPECT_NE(refusal("{\"plan\": 3}").find("plan: got 3; allowed: a file path as text"),
              std::string::npos);
    EXPECT_NE(
        refusal("{\"colour\": 3}").find("colour: an unknown key; allowed: format, version, plan"),
        std::string::npos);
    EXPECT_NE(refusal("{\"version\": 2}").find("version: got 2"), std::string::npos);
    EXPECT_NE(refusal("[1]").find("file"), std::string::npos);
    EXPECT_NE(refusal("{\"plan\": \"a\", \"plan\": \"b\"}").find("plan"), std::string::npos);
    EXPECT_NE(refusal("{\"plan\": ").find("malformed JSON"), std::string::npos);
    EXPECT_NE(refusal("{\"c_axis_x_mm\": 1e400}").find("c_axis_x_mm"), std::string::npos);
}

}  // namespace
}  // namespace probecycle
