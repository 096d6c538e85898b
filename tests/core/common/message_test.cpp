#include "core/common/message.h"

#include <gtest/gtest.h>

#include "core/common/field_error.h"
#include "core/common/message_json.h"

namespace probecycle {
namespace {

TEST(FillTemplate, ReplacesPlaceholdersInOnePass) {
    EXPECT_EQ(fill_template("%2 before %1", {"a", "b"}), "b before a");
    // An argument that holds a placeholder is not substituted again.
    EXPECT_EQ(fill_template("%1 and %2", {"%2", "x"}), "%2 and x");
    // A placeholder without an argument, a lone % and "% " stay as written.
    EXPECT_EQ(fill_template("%3 is 50 % of %", {"a"}), "%3 is 50 % of %");
}

struct ArgCase {
    ArgKind kind;
    double value;
    int decimals;
    const char* english;
};

class RenderArg : public ::testing::TestWithParam<ArgCase> {};

TEST_P(RenderArg, WritesTheValueWithItsUnit) {
    const ArgCase& c = GetParam();
    EXPECT_EQ(render_arg(arg("x", c.kind, c.value, c.decimals)), c.english);
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(Kinds, RenderArg, ::testing::Values(
    ArgCase{ArgKind::length_mm,   1.27166,  3, "1.272 mm"},
    ArgCase{ArgKind::length_mm,   0.004,   -1, "0.004 mm"},
    ArgCase{ArgKind::time_s,      0.4249,   2, "0.42 s"},
    ArgCase{ArgKind::delay_s,     0.0085,  -1, "8.5 ms"},
    ArgCase{ArgKind::delay_s,     0.00426,  1, "4.3 ms"},
    ArgCase{ArgKind::feed_mm_min, 1999.96,  0, "2000 mm/min"},
    ArgCase{ArgKind::angle_deg,   180.0,   -1, "180 deg"},
    ArgCase{ArgKind::percent,     25.4,     0, "25 %"},
    ArgCase{ArgKind::number,      3.25,    -1, "3.25"},
    ArgCase{ArgKind::integer,     7.0,     -1, "7"},
    // A value that rounds to zero never reads as -0.
    ArgCase{ArgKind::length_mm,  -0.00001,  3, "0.000 mm"},
    ArgCase{ArgKind::number,     -0.0,      0, "0"}));
// clang-format on

TEST(RenderArg, SignificantDigitsWithoutTrailingZeros) {
    EXPECT_EQ(render_arg(significant_arg("runout_mm", ArgKind::length_mm, 0.00360555, 4)),
              "0.003606 mm");
    EXPECT_EQ(render_arg(significant_arg("radius_mm", ArgKind::length_mm, 22.0, 4)), "22 mm");
    EXPECT_EQ(render_arg(significant_arg("delay_s", ArgKind::delay_s, 0.0051234, 3)), "5.12 ms");
    EXPECT_EQ(render_arg(significant_arg("ratio", ArgKind::number, 3.0, 3)), "3");
}

TEST(Render, FillsTheTemplateWithEnglishArguments) {
    Message m;
    m.code = "calibration_feed_mismatch";
    m.context = "Warning";
    m.text = QT_TRANSLATE_NOOP("Warning", "Measuring at %1 but calibrated at %2: off by %3");
    m.args = {arg("speed_mm_min", ArgKind::feed_mm_min, 1500.0, 1),
              arg("calibration_speed_mm_min", ArgKind::feed_mm_min, 500.0, 1),
              arg("error_mm", ArgKind::length_mm, 0.0667, 4), text_arg("key", "probe.x")};
    EXPECT_EQ(render(m),
              "Measuring at 1500.0 mm/min but calibrated at 500.0 mm/min: off by 0.0667 mm");

    const nlohmann::ordered_json values = message_values(m);
    EXPECT_EQ(
        values.dump(),
        R"({"speed_mm_min":1500.0,"calibration_speed_mm_min":500.0,"error_mm":0.0667,"key":"probe.x"})");
}

TEST(Render, NestsAMessageInPlace) {
    Message range;
    range.code = "range";
    range.text = "a number from %1 to %2";
    range.args = {arg("min_s", ArgKind::number, 0.0), arg("max_s", ArgKind::number, 0.1)};
    Message m;
    m.code = "out_of_range";
    m.text = "%1: got %2; allowed: %3";
    m.args = {text_arg("key", "machine.scan_period_s"), text_arg("value", "-1"),
              message_arg("allowed", range)};
    EXPECT_EQ(render(m), "machine.scan_period_s: got -1; allowed: a number from 0 to 0.1");
    EXPECT_EQ(message_values(m).dump(),
              R"({"key":"machine.scan_period_s","value":"-1","min_s":0.0,"max_s":0.1})");
}

// A value of megabytes is not echoed whole (a 10 MB string went to stderr).
TEST(FieldErrorText, ALongValueIsCutAndItsLengthSaid) {
    const FieldError e{"cycle.strategy", "\"" + std::string(10'000'000, 'x') + "\"",
                       allowed_text("unknown_word", "one of single_touch, two_touch")};
    const std::string m = e.message();
    EXPECT_LT(m.size(), 200u) << m.substr(0, 300);
    EXPECT_NE(m.find("(10000002 characters)"), std::string::npos) << m;
    EXPECT_NE(m.find("one of single_touch, two_touch"), std::string::npos) << m;
    // A cut never splits a UTF-8 character.
    const FieldError utf{"k", std::string(39, 'a') + "\xc3\xa9" + std::string(100, 'b'),
                         allowed_text("x", "y")};
    EXPECT_NE(utf.message().find(std::string(39, 'a') + "..."), std::string::npos) << utf.message();
    // A short value is shown whole.
    EXPECT_EQ(FieldError({"k", "short", allowed_text("x", "y")}).message(),
              "k: got short; allowed: y");
}

TEST(WarningJson, ListsCodeSeverityEnglishAndValues) {
    Message m;
    m.code = "large_runout";
    m.text = "stylus runout %1 exceeds %2";
    m.args = {significant_arg("runout_mm", ArgKind::length_mm, 0.0051, 4),
              significant_arg("limit_mm", ArgKind::length_mm, 0.001, 4)};
    EXPECT_EQ(
        warning_json("large_runout", Severity::warning, m).dump(),
        R"({"code":"large_runout","severity":"warning","message":"stylus runout 0.0051 mm exceeds )"
        R"(0.001 mm","values":{"runout_mm":0.0051,"limit_mm":0.001}})");
}

}  // namespace
}  // namespace probecycle
