#include "core/cycle/scenario.h"
#include "tests/core/common/line_ends.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace probecycle {
namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

bool contains(const std::string& haystack, const std::string& needle) {
    return lower(haystack).find(lower(needle)) != std::string::npos;
}

template <typename F>
std::optional<ScenarioError> scenario_error_from(F&& action) {
    try {
        action();
    } catch (const ScenarioError& error) {
        return error;
    }
    return std::nullopt;
}

// Shortest text forms a range bound may be printed in.
std::vector<std::string> number_spellings(double x) {
    std::vector<std::string> out;
    for (const char* format : {"%g", "%.17g", "%.1f", "%.0f"}) {
        char buf[64];
        std::snprintf(buf, sizeof buf, format, x);
        out.emplace_back(buf);
    }
    nlohmann::json j = x;
    out.push_back(j.dump());
    return out;
}

bool mentions_number(const std::string& text, double x) {
    for (const std::string& spelling : number_spellings(x)) {
        if (contains(text, spelling)) return true;
    }
    return false;
}

// `key` itself, or a key under it ("spindle" matches "spindle.speed").
bool names_key(const FieldError& e, const std::string& key) {
    return e.key == key || e.key.rfind(key + ".", 0) == 0;
}

// The error names `key`; when given, the offending value and the allowed
// words; the message (what()) carries all three.
void expect_names(const std::optional<ScenarioError>& error, const std::string& key,
                  const std::string& value, const std::vector<std::string>& allowed_words = {}) {
    ASSERT_TRUE(error.has_value()) << "no ScenarioError for " << key << " = " << value;
    ASSERT_FALSE(error->errors().empty());
    const std::string what = error->what();
    EXPECT_TRUE(contains(what, key)) << what;
    const auto it = std::find_if(error->errors().begin(), error->errors().end(),
                                 [&](const FieldError& e) { return names_key(e, key); });
    ASSERT_NE(it, error->errors().end()) << "no FieldError with key " << key << ": " << what;
    if (!value.empty()) {
        EXPECT_TRUE(contains(it->value, value)) << "value '" << it->value << "' for " << key;
        EXPECT_TRUE(contains(what, value)) << what;
    }
    EXPECT_FALSE(render(it->allowed).empty()) << what;
    EXPECT_TRUE(contains(what, render(it->allowed))) << what;
    for (const std::string& word : allowed_words) {
        EXPECT_TRUE(contains(render(it->allowed), word))
            << "allowed '" << render(it->allowed) << "' lacks " << word;
    }
    const std::string message = it->message();
    EXPECT_TRUE(contains(message, key)) << message;
    EXPECT_TRUE(contains(message, render(it->allowed))) << message;
}

// Field-by-field equality through the public accessors.
void expect_same_scenario(const Scenario& a, const Scenario& b) {
    EXPECT_EQ(a.machine.accel_model, b.machine.accel_model);
    EXPECT_EQ(a.machine.latched_input, b.machine.latched_input);
    EXPECT_EQ(a.cycle.strategy, b.cycle.strategy);
    EXPECT_EQ(a.cycle.feature, b.cycle.feature);
    for (const KeyInfo& info : numeric_keys()) {
        EXPECT_EQ(get_number(a, info.key), get_number(b, info.key)) << info.key;
    }
}

const std::vector<std::string> kNumericKeys = {
    "machine.time_constant_s",
    "machine.max_accel_mm_s2",
    "machine.max_jerk_mm_s3",
    "machine.rapid_feed_mm_min",
    "machine.block_change_s",
    "machine.scan_period_s",
    "machine.controller_latency_s",
    "machine.repeatability_2sigma_mm",
    "machine.thermal_drift_mm",
    "probe.pretravel_mm",
    "probe.interface_delay_s",
    "probe.repeatability_2sigma_mm",
    "probe.lobing_mm",
    "probe.artefact_uncertainty_mm",
    "probe.overtravel_limit_mm",
    "probe.reseat_mm",
    "probe.calibration_feed_mm_min",
    "cycle.feature_size_mm",
    "cycle.approach_mm",
    "cycle.search_beyond_mm",
    "cycle.probe_feed_mm_min",
    "cycle.measure_feed_mm_min",
    "cycle.backoff_mm",
    "cycle.return_feed_mm_min",
    "cycle.target_uncertainty_mm",
    "cycle.min_start_mm",
    "cycle.min_feed_mm_min",
    "cycle.size_tolerance_mm",
    "cycle.knee_tolerance",
    "cycle.position_feed_mm_min",
    "cycle.feed_override_max_pct",
    "cycle.clearance_mm",
    "machine.filter_time_s",
    "machine.filter2_time_s",
    "machine.servo_time_constant_s",
    "machine.in_position_mm",
    "probe.max_feed_mm_min",
    "cycle.part_position_uncertainty_mm",
    "cycle.repeats",
    "cycle.parts_per_year",
    "cycle.cycles_per_part",
    "cycle.machine_rate_per_hour",
};

// ---------------------------------------------------------------------------
// Defaults and the key table.

TEST(ScenarioDefaults, TypicalMachiningCentreWithStandardSkipInput) {
    const Scenario s;
    // Values the issue fixes.
    EXPECT_EQ(s.machine.accel_model, AccelModel::time_constant);
    EXPECT_EQ(s.machine.time_constant_s, 0.06);
    EXPECT_EQ(s.machine.scan_period_s, 0.004);
    EXPECT_FALSE(s.machine.latched_input);
    EXPECT_EQ(s.cycle.strategy, Strategy::two_touch);
    EXPECT_EQ(s.cycle.feature, Feature::surface);
    EXPECT_EQ(s.cycle.measure_feed_mm_min, 30.0);
    EXPECT_EQ(s.cycle.target_uncertainty_mm, 0.0);
    EXPECT_TRUE(validate(s).empty());
    EXPECT_NO_THROW(validate_or_throw(s));
}

TEST(ScenarioDefaults, MotionLimitsCarryTheMachine) {
    Scenario s;
    s.machine.accel_model = AccelModel::jerk_limited;
    s.machine.time_constant_s = 0.08;
    s.machine.max_accel_mm_s2 = 1234.0;
    s.machine.max_jerk_mm_s3 = 56789.0;
    const MotionLimits limits = s.motion_limits();
    EXPECT_EQ(limits.model, AccelModel::jerk_limited);
    EXPECT_EQ(limits.time_constant_s, 0.08);
    EXPECT_EQ(limits.max_accel_mm_s2, 1234.0);
    EXPECT_EQ(limits.max_jerk_mm_s3, 56789.0);
}

TEST(NumericKeys, EveryDocumentedNumericKeyOnce) {
    std::set<std::string> listed;
    for (const KeyInfo& info : numeric_keys()) {
        EXPECT_TRUE(listed.insert(info.key).second) << "duplicate " << info.key;
    }
    EXPECT_EQ(listed, std::set<std::string>(kNumericKeys.begin(), kNumericKeys.end()));
}

TEST(NumericKeys, RangesHoldTheDefaultsAndLookupWorks) {
    const Scenario defaults;
    for (const KeyInfo& info : numeric_keys()) {
        SCOPED_TRACE(info.key);
        EXPECT_LE(info.min, info.max);
        ASSERT_NE(info.unit, nullptr);
        ASSERT_NE(info.description, nullptr);
        EXPECT_GT(std::string(info.description).size(), 0u);
        const std::optional<double> value = get_number(defaults, info.key);
        ASSERT_TRUE(value.has_value());
        EXPECT_GE(*value, info.min);
        EXPECT_LE(*value, info.max);
        const KeyInfo* found = find_key(info.key);
        ASSERT_NE(found, nullptr);
        EXPECT_STREQ(found->key, info.key);
    }
    EXPECT_EQ(find_key("machine.nope"), nullptr);
    EXPECT_EQ(find_key("cycle.strategy"), nullptr);
    EXPECT_EQ(find_key(""), nullptr);
}

TEST(NumericKeys, SetAndGetEveryKey) {
    for (const KeyInfo& info : numeric_keys()) {
        SCOPED_TRACE(info.key);
        Scenario s;
        const double value = info.min + 0.5 * (std::min(info.max, info.min + 10.0) - info.min);
        ASSERT_TRUE(set_number(s, info.key, value));
        EXPECT_EQ(get_number(s, info.key), value);
    }
    Scenario s;
    EXPECT_FALSE(set_number(s, "cycle.strategy", 1.0));
    EXPECT_FALSE(set_number(s, "machine.nope", 1.0));
    EXPECT_FALSE(get_number(s, "machine.nope").has_value());
    EXPECT_FALSE(get_number(s, "cycle.strategy").has_value());
}

TEST(NumericKeys, SetNumberWritesTheNamedField) {
    Scenario s;
    ASSERT_TRUE(set_number(s, "machine.scan_period_s", 0.000004));
    EXPECT_EQ(s.machine.scan_period_s, 0.000004);
    ASSERT_TRUE(set_number(s, "probe.reseat_mm", 0.3));
    EXPECT_EQ(s.probe.reseat_mm, 0.3);
    ASSERT_TRUE(set_number(s, "cycle.measure_feed_mm_min", 25.0));
    EXPECT_EQ(s.cycle.measure_feed_mm_min, 25.0);
    ASSERT_TRUE(set_number(s, "probe.calibration_feed_mm_min", 60.0));
    EXPECT_EQ(s.probe.calibration_feed_mm_min, 60.0);
}

// ---------------------------------------------------------------------------
// Enum words.

TEST(EnumWords, RoundTrip) {
    for (Strategy v : {Strategy::single_touch, Strategy::two_touch}) {
        EXPECT_EQ(strategy_from_string(to_string(v)), v);
    }
    for (Feature v :
         {Feature::surface, Feature::web, Feature::pocket, Feature::bore, Feature::boss}) {
        EXPECT_EQ(feature_from_string(to_string(v)), v);
    }
    for (AccelModel v :
         {AccelModel::time_constant, AccelModel::constant_accel, AccelModel::jerk_limited}) {
        EXPECT_EQ(accel_model_from_string(to_string(v)), v);
    }
    EXPECT_STREQ(to_string(Strategy::single_touch), "single_touch");
    EXPECT_STREQ(to_string(Strategy::two_touch), "two_touch");
    EXPECT_STREQ(to_string(Feature::surface), "surface");
    EXPECT_STREQ(to_string(Feature::web), "web");
    EXPECT_STREQ(to_string(Feature::pocket), "pocket");
    EXPECT_STREQ(to_string(Feature::bore), "bore");
    EXPECT_STREQ(to_string(Feature::boss), "boss");
    EXPECT_FALSE(strategy_from_string("three_touch").has_value());
    EXPECT_FALSE(feature_from_string("sphere").has_value());
    EXPECT_FALSE(accel_model_from_string("linear").has_value());
    EXPECT_FALSE(strategy_from_string("").has_value());
}

// ---------------------------------------------------------------------------
// JSON.

TEST(ScenarioJson, EmptyObjectIsTheDefaults) {
    expect_same_scenario(scenario_from_json("{}"), Scenario{});
    expect_same_scenario(scenario_from_json("{\"machine\": {}, \"probe\": {}, \"cycle\": {}}"),
                         Scenario{});
}

TEST(ScenarioJson, WindowsLineEndsReadAsUnixOnes) {
    Scenario changed;
    changed.cycle.probe_feed_mm_min = 1234.0;
    const std::string text = test::with_crlf(scenario_to_json(changed));
    ASSERT_NE(text.find("\r\n"), std::string::npos);
    EXPECT_EQ(scenario_to_json(scenario_from_json(text)), scenario_to_json(changed));
}

TEST(ScenarioJson, EveryKeyOptionalAndReadIntoItsField) {
    const Scenario s = scenario_from_json(R"({
        "machine": {"accel_model": "jerk_limited", "max_jerk_mm_s3": 50000, "latched_input": true,
                    "scan_period_s": 0.000004},
        "probe": {"pretravel_mm": 0.002},
        "cycle": {"strategy": "single_touch", "feature": "bore", "probe_feed_mm_min": 480}
    })");
    Scenario expected;
    expected.machine.accel_model = AccelModel::jerk_limited;
    expected.machine.max_jerk_mm_s3 = 50000.0;
    expected.machine.latched_input = true;
    expected.machine.scan_period_s = 0.000004;
    expected.probe.pretravel_mm = 0.002;
    expected.cycle.strategy = Strategy::single_touch;
    expected.cycle.feature = Feature::bore;
    expected.cycle.probe_feed_mm_min = 480.0;
    expect_same_scenario(s, expected);
}

TEST(ScenarioJson, WritesEverySectionAndKeyWithEnumsAsWords) {
    const nlohmann::json j = nlohmann::json::parse(scenario_to_json(Scenario{}));
    ASSERT_TRUE(j.is_object());
    const std::map<std::string, std::set<std::string>> expected = {
        {"machine",
         {"accel_model", "time_constant_s", "max_accel_mm_s2", "max_jerk_mm_s3", "filter",
          "filter_time_s", "filter2_time_s", "servo_time_constant_s", "in_position_mm",
          "block_change_s", "rapid_feed_mm_min", "scan_period_s", "controller_latency_s",
          "latched_input", "repeatability_2sigma_mm", "thermal_drift_mm"}},
        {"probe",
         {"pretravel_mm", "interface_delay_s", "repeatability_2sigma_mm", "lobing_mm",
          "artefact_uncertainty_mm", "overtravel_limit_mm", "reseat_mm", "calibration_feed_mm_min",
          "max_feed_mm_min"}},
        {"cycle",
         {"strategy",
          "feature",
          "feature_size_mm",
          "approach_mm",
          "probe_feed_mm_min",
          "measure_feed_mm_min",
          "backoff_mm",
          "backoff_from",
          "return_feed_mm_min",
          "position_feed_mm_min",
          "feed_override_max_pct",
          "clearance_mm",
          "target_uncertainty_mm",
          "min_start_mm",
          "min_feed_mm_min",
          "size_tolerance_mm",
          "tolerance_action",
          "knee_tolerance",
          "part_position_uncertainty_mm",
          "search_beyond_mm",
          "repeats",
          "parts_per_year",
          "cycles_per_part",
          "machine_rate_per_hour"}},
    };
    EXPECT_EQ(j.size(), expected.size());
    for (const auto& [section, keys] : expected) {
        ASSERT_TRUE(j.contains(section)) << section;
        std::set<std::string> written;
        for (const auto& item : j[section].items()) written.insert(item.key());
        EXPECT_EQ(written, keys) << section;
    }
    EXPECT_EQ(j["machine"]["accel_model"], "time_constant");
    EXPECT_EQ(j["machine"]["filter"], "none");
    EXPECT_EQ(j["machine"]["latched_input"], false);
    EXPECT_EQ(j["cycle"]["strategy"], "two_touch");
    EXPECT_EQ(j["cycle"]["feature"], "surface");
    EXPECT_EQ(j["machine"]["scan_period_s"], 0.004);
    EXPECT_EQ(j["cycle"]["measure_feed_mm_min"], 30.0);
}

TEST(ScenarioJson, RandomScenariosRoundTripExactly) {
    std::mt19937_64 rng{42};
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int valid = 0;
    for (int i = 0; i < 2000; ++i) {
        Scenario s;
        for (const KeyInfo& info : numeric_keys()) {
            const double hi = std::min(info.max, info.min + 1000.0);
            ASSERT_TRUE(set_number(s, info.key, info.min + unit(rng) * (hi - info.min)));
        }
        s.cycle.repeats = std::round(s.cycle.repeats);  // a whole number
        s.machine.accel_model = static_cast<AccelModel>(rng() % 3);
        s.machine.latched_input = rng() % 2 == 0;
        s.cycle.strategy = static_cast<Strategy>(rng() % 2);
        s.cycle.feature = static_cast<Feature>(rng() % 5);
        if (!validate(s).empty()) continue;  // a cross-field check; not this test's concern
        ++valid;
        const std::string text = scenario_to_json(s);
        const Scenario back = scenario_from_json(text);
        expect_same_scenario(back, s);
        ASSERT_EQ(scenario_to_json(back), text);
        if (HasFailure()) return;
    }
    EXPECT_GT(valid, 100);
}

struct BadJsonCase {
    const char* name;
    const char* json;
    const char* key;
    const char* value;  // "" = not checked
    std::vector<std::string> allowed;
};

// clang-format off
const BadJsonCase kBadJsonCases[] = {
    // name                  json                                                  key                            value          allowed words
    {"unknown_key",          R"({"machine": {"scan_period": 0.004}})",             "machine.scan_period",         "",            {}},
    {"unknown_section",      R"({"spindle": {"speed": 1}})",                       "spindle",                     "",            {}},
    {"number_as_string",     R"({"machine": {"scan_period_s": "0.004"}})",         "machine.scan_period_s",       "0.004",       {}},
    {"number_as_null",       R"({"probe": {"pretravel_mm": null}})",               "probe.pretravel_mm",          "null",        {}},
    {"number_as_bool",       R"({"cycle": {"approach_mm": true}})",                "cycle.approach_mm",           "true",        {}},
    {"bool_as_number",       R"({"machine": {"latched_input": 1}})",               "machine.latched_input",       "1",           {"true", "false"}},
    {"enum_as_number",       R"({"cycle": {"strategy": 2}})",                      "cycle.strategy",              "2",           {"single_touch", "two_touch"}},
    {"section_as_array",     R"({"probe": [1, 2]})",                               "probe",                       "",            {}},
    {"negative_pretravel",   R"({"probe": {"pretravel_mm": -0.001}})",             "probe.pretravel_mm",          "-0.001",      {}},
    {"negative_delay",       R"({"probe": {"interface_delay_s": -1}})",            "probe.interface_delay_s",     "-1",          {}},
    {"negative_backoff",     R"({"cycle": {"backoff_mm": -2}})",                   "cycle.backoff_mm",            "-2",          {}},
    {"zero_probe_feed",      R"({"cycle": {"probe_feed_mm_min": 0}})",             "cycle.probe_feed_mm_min",     "0",           {}},
    {"zero_measure_feed",    R"({"cycle": {"measure_feed_mm_min": 0}})",           "cycle.measure_feed_mm_min",   "0",           {}},
    {"zero_return_feed",     R"({"cycle": {"return_feed_mm_min": 0}})",            "cycle.return_feed_mm_min",    "0",           {}},
    {"zero_time_constant",   R"({"machine": {"time_constant_s": 0}})",             "machine.time_constant_s",     "0",           {}},
    {"huge_scan_period",     R"({"machine": {"scan_period_s": 1e6}})",             "machine.scan_period_s",       "",            {}},
    {"unknown_strategy",     R"({"cycle": {"strategy": "three_touch"}})",          "cycle.strategy",              "three_touch", {"single_touch", "two_touch"}},
    {"unknown_feature",      R"({"cycle": {"feature": "sphere"}})",                "cycle.feature",               "sphere",      {"surface", "web", "pocket", "bore", "boss"}},
    {"unknown_accel_model",  R"({"machine": {"accel_model": "linear"}})",          "machine.accel_model",         "linear",      {"time_constant", "constant_accel", "jerk_limited"}},
};
// clang-format on

class BadJson : public testing::TestWithParam<BadJsonCase> {};

TEST_P(BadJson, ScenarioErrorNamesKeyValueAndAllowed) {
    const BadJsonCase& c = GetParam();
    expect_names(scenario_error_from([&] { scenario_from_json(c.json); }), c.key, c.value,
                 c.allowed);
}

INSTANTIATE_TEST_SUITE_P(EveryPath, BadJson, testing::ValuesIn(kBadJsonCases),
                         [](const testing::TestParamInfo<BadJsonCase>& case_info) {
                             return std::string(case_info.param.name);
                         });

TEST(ScenarioJson, MalformedTextIsAScenarioErrorNamingTheLine) {
    for (const char* text : {"{", "", "{\"machine\": {\"scan_period_s\": 0.004,}}",
                             "{\"machine\": {\"scan_period_s\": NaN}}", "not json"}) {
        SCOPED_TRACE(text);
        const auto error = scenario_error_from([&] { scenario_from_json(text); });
        ASSERT_TRUE(error.has_value());
        EXPECT_FALSE(error->errors().empty());
        EXPECT_TRUE(contains(error->what(), "line")) << error->what();
    }
}

// A number no double holds is refused like any other bad input, not thrown
// through as a library exception.
TEST(ScenarioJson, NumberBeyondDoubleIsAScenarioError) {
    const auto error = scenario_error_from(
        [&] { scenario_from_json(R"({"machine": {"scan_period_s": 1e400}})"); });
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(error->what(), "out of range")) << error->what();
    // It names the key and the line (it said only "number overflow parsing '1e400'").
    EXPECT_TRUE(contains(error->what(), "machine.scan_period_s")) << error->what();
    EXPECT_TRUE(contains(error->what(), "line 1")) << error->what();
}

TEST(ScenarioJson, TopLevelMustBeAnObject) {
    for (const char* text : {"[]", "42", "\"machine\"", "null"}) {
        SCOPED_TRACE(text);
        const auto error = scenario_error_from([&] { scenario_from_json(text); });
        ASSERT_TRUE(error.has_value());
        EXPECT_FALSE(error->errors().empty());
        EXPECT_GT(std::string(error->what()).size(), 0u);
    }
}

TEST(ScenarioJson, EveryKeyBelowItsMinimumOrAboveItsMaximumIsRejected) {
    for (const KeyInfo& info : numeric_keys()) {
        SCOPED_TRACE(info.key);
        const std::string key = info.key;
        const std::string section = key.substr(0, key.find('.'));
        const std::string field = key.substr(key.find('.') + 1);
        std::vector<double> bad = {info.min - std::max(1.0, std::abs(info.min))};
        if (std::isfinite(info.max) && info.max < 1e300) bad.push_back(2.0 * info.max + 1.0);
        for (double value : bad) {
            nlohmann::json j;
            j[section][field] = value;
            const auto error = scenario_error_from([&] { scenario_from_json(j.dump()); });
            expect_names(error, key, "");
            if (!error || HasFailure()) return;
            const auto it = std::find_if(error->errors().begin(), error->errors().end(),
                                         [&](const FieldError& e) { return e.key == key; });
            // The allowed range is spelled out.
            EXPECT_TRUE(mentions_number(render(it->allowed), info.min)) << render(it->allowed);
            if (std::isfinite(info.max)) {
                EXPECT_TRUE(mentions_number(render(it->allowed), info.max)) << render(it->allowed);
            }
            EXPECT_TRUE(mentions_number(it->value, value)) << it->value;
        }
        // Both bounds themselves are allowed.
        for (double value : {info.min, info.max}) {
            if (!std::isfinite(value)) continue;
            nlohmann::json j;
            j[section][field] = value;
            Scenario s;
            ASSERT_TRUE(set_number(s, key, value));
            if (!validate(s).empty()) continue;  // a cross-field check at the extreme
            EXPECT_NO_THROW(scenario_from_json(j.dump())) << value;
        }
    }
}

// "Delays and distances may be 0."
TEST(ScenarioValidate, DelaysAndDistancesMayBeZero) {
    for (const char* key :
         {"machine.scan_period_s", "machine.controller_latency_s", "probe.pretravel_mm",
          "probe.interface_delay_s", "probe.repeatability_2sigma_mm", "probe.reseat_mm",
          "probe.calibration_feed_mm_min", "cycle.backoff_mm", "cycle.target_uncertainty_mm"}) {
        SCOPED_TRACE(key);
        Scenario s;
        ASSERT_TRUE(set_number(s, key, 0.0));
        EXPECT_TRUE(validate(s).empty()) << (validate(s).empty() ? "" : validate(s)[0].message());
    }
}

TEST(ScenarioValidate, ReportsEveryBadFieldAndThrowsTheSame) {
    Scenario s;
    s.machine.scan_period_s = -1.0;
    s.probe.pretravel_mm = std::numeric_limits<double>::quiet_NaN();
    const std::vector<FieldError> errors = validate(s);
    std::set<std::string> keys;
    for (const FieldError& e : errors) keys.insert(e.key);
    EXPECT_TRUE(keys.count("machine.scan_period_s"));
    EXPECT_TRUE(keys.count("probe.pretravel_mm"));
    const auto error = scenario_error_from([&] { validate_or_throw(s); });
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(error->errors().size(), errors.size());
    EXPECT_TRUE(contains(error->what(), "machine.scan_period_s"));
    EXPECT_TRUE(contains(error->what(), "probe.pretravel_mm"));
}

TEST(ScenarioValidate, RepeatsAreAWholeNumber) {
    Scenario s;
    s.cycle.repeats = 2.5;
    const std::vector<FieldError> errors = validate(s);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].key, "cycle.repeats");
    EXPECT_EQ(errors[0].message(), "cycle.repeats: got 2.5; allowed: a whole number from 1 to 20");
    for (double bad : {0.0, 21.0}) {
        s.cycle.repeats = bad;
        ASSERT_EQ(validate(s).size(), 1u) << bad;
        EXPECT_EQ(validate(s)[0].key, "cycle.repeats");
    }
    s.cycle.repeats = 20.0;
    EXPECT_TRUE(validate(s).empty());
    EXPECT_THROW(scenario_from_json(R"({"cycle": {"repeats": 3.5}})"), ScenarioError);
    const Scenario three = scenario_from_json(R"({"cycle": {"repeats": 3}})");
    EXPECT_EQ(three.cycle.repeats, 3.0);
    // Written as the count it is.
    EXPECT_NE(scenario_to_json(three).find("\"repeats\": 3,"), std::string::npos);
}

TEST(ScenarioValidate, NanAndInfinityAreRejected) {
    for (const KeyInfo& info : numeric_keys()) {
        for (double bad :
             {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
            Scenario s;
            ASSERT_TRUE(set_number(s, info.key, bad));
            const std::vector<FieldError> errors = validate(s);
            EXPECT_TRUE(std::any_of(errors.begin(), errors.end(),
                                    [&](const FieldError& e) { return e.key == info.key; }))
                << info.key << " = " << bad;
        }
    }
}

TEST(FieldError, MessageNamesKeyValueAndAllowed) {
    const FieldError e{"machine.scan_period_s", "-1",
                       allowed_text("out_of_range", "a number in [0, 0.1]")};
    const std::string m = e.message();
    EXPECT_NE(m.find("machine.scan_period_s"), std::string::npos) << m;
    EXPECT_NE(m.find("-1"), std::string::npos) << m;
    EXPECT_NE(m.find("a number in [0, 0.1]"), std::string::npos) << m;
    const ScenarioError error({e});
    ASSERT_EQ(error.errors().size(), 1u);
    EXPECT_EQ(error.errors()[0].key, "machine.scan_period_s");
    EXPECT_NE(std::string(error.what()).find(m), std::string::npos) << error.what();
}

// ---------------------------------------------------------------------------
// --set section.key=value

struct GoodSettingCase {
    const char* assignment;
    const char* key;  // numeric key to read back, or "" for the check below
    double value;
};

// clang-format off
const GoodSettingCase kGoodSettings[] = {
    // assignment                                   key                               value
    {"machine.scan_period_s=0.000004",              "machine.scan_period_s",          0.000004},
    {"machine.scan_period_s=4e-6",                  "machine.scan_period_s",          4e-6},
    {"cycle.probe_feed_mm_min=480",                 "cycle.probe_feed_mm_min",        480.0},
    {"probe.pretravel_mm=0",                        "probe.pretravel_mm",             0.0},
    {"probe.calibration_feed_mm_min=60",            "probe.calibration_feed_mm_min",  60.0},
    {"cycle.target_uncertainty_mm=0.01",            "cycle.target_uncertainty_mm",    0.01},
    {"cycle.knee_tolerance=0.05",                   "cycle.knee_tolerance",           0.05},
};
// clang-format on

class GoodSetting : public testing::TestWithParam<GoodSettingCase> {};

TEST_P(GoodSetting, WritesTheKey) {
    const GoodSettingCase& c = GetParam();
    Scenario s;
    apply_setting(s, c.assignment);
    EXPECT_EQ(get_number(s, c.key), c.value);
    EXPECT_TRUE(validate(s).empty());
}

INSTANTIATE_TEST_SUITE_P(Numbers, GoodSetting, testing::ValuesIn(kGoodSettings));

TEST(ApplySetting, EnumWordsAndBooleans) {
    Scenario s;
    apply_setting(s, "cycle.strategy=single_touch");
    apply_setting(s, "cycle.feature=bore");
    apply_setting(s, "machine.accel_model=jerk_limited");
    apply_setting(s, "machine.latched_input=true");
    EXPECT_EQ(s.cycle.strategy, Strategy::single_touch);
    EXPECT_EQ(s.cycle.feature, Feature::bore);
    EXPECT_EQ(s.machine.accel_model, AccelModel::jerk_limited);
    EXPECT_TRUE(s.machine.latched_input);
    apply_setting(s, "machine.latched_input=false");
    EXPECT_FALSE(s.machine.latched_input);
}

struct BadSettingCase {
    const char* name;
    const char* assignment;
    const char* key;
    const char* value;  // "" = not checked
    std::vector<std::string> allowed;
};

// clang-format off
const BadSettingCase kBadSettings[] = {
    // name                 assignment                              key                          value          allowed words
    {"nan",                 "machine.scan_period_s=nan",            "machine.scan_period_s",     "nan",         {}},
    {"NaN",                 "probe.pretravel_mm=NaN",               "probe.pretravel_mm",        "nan",         {}},
    {"inf",                 "probe.pretravel_mm=inf",               "probe.pretravel_mm",        "inf",         {}},
    {"negative",            "machine.scan_period_s=-0.001",         "machine.scan_period_s",     "-0.001",      {}},
    {"negative_feed",       "cycle.probe_feed_mm_min=-100",         "cycle.probe_feed_mm_min",   "-100",        {}},
    {"zero_feed",           "cycle.measure_feed_mm_min=0",          "cycle.measure_feed_mm_min", "0",           {}},
    {"huge",                "machine.scan_period_s=1e6",            "machine.scan_period_s",     "",            {}},
    {"string_for_number",   "machine.scan_period_s=\"0.004\"",      "machine.scan_period_s",     "0.004",       {}},
    {"word_for_number",     "machine.scan_period_s=fast",           "machine.scan_period_s",     "fast",        {}},
    {"bool_for_number",     "machine.scan_period_s=true",           "machine.scan_period_s",     "true",        {}},
    {"word_for_bool",       "machine.latched_input=yes",            "machine.latched_input",     "yes",         {"true", "false"}},
    {"number_for_bool",     "machine.latched_input=1",              "machine.latched_input",     "1",           {"true", "false"}},
    {"number_for_enum",     "cycle.strategy=2",                     "cycle.strategy",            "2",           {"single_touch", "two_touch"}},
    {"unknown_strategy",    "cycle.strategy=three_touch",           "cycle.strategy",            "three_touch", {"single_touch", "two_touch"}},
    {"unknown_feature",     "cycle.feature=sphere",                 "cycle.feature",             "sphere",      {"surface", "web", "pocket", "bore", "boss"}},
    {"unknown_model",       "machine.accel_model=linear",           "machine.accel_model",       "linear",      {"time_constant", "constant_accel", "jerk_limited"}},
    {"unknown_key",         "machine.scan_period=0.004",            "machine.scan_period",       "",            {}},
    {"unknown_section",     "spindle.speed=1",                      "spindle",                   "",            {}},
    {"empty_value",         "machine.scan_period_s=",               "machine.scan_period_s",     "",            {}},
};
// clang-format on

class BadSetting : public testing::TestWithParam<BadSettingCase> {};

// As --set is used: apply, then validate the result.
TEST_P(BadSetting, ScenarioErrorNamesKeyValueAndAllowed) {
    const BadSettingCase& c = GetParam();
    Scenario s;
    expect_names(scenario_error_from([&] {
                     apply_setting(s, c.assignment);
                     validate_or_throw(s);
                 }),
                 c.key, c.value, c.allowed);
}

INSTANTIATE_TEST_SUITE_P(EveryPath, BadSetting, testing::ValuesIn(kBadSettings),
                         [](const testing::TestParamInfo<BadSettingCase>& case_info) {
                             return std::string(case_info.param.name);
                         });

TEST(ApplySetting, MalformedAssignmentsAreScenarioErrors) {
    for (const char* assignment :
         {"machine.scan_period_s", "scan_period_s=0.004", "=0.004", "", "machine.=1", ".x=1"}) {
        SCOPED_TRACE(assignment);
        Scenario s;
        const auto error = scenario_error_from([&] {
            apply_setting(s, assignment);
            validate_or_throw(s);
        });
        ASSERT_TRUE(error.has_value());
        EXPECT_FALSE(error->errors().empty());
        EXPECT_GT(std::string(error->what()).size(), 0u);
    }
}

TEST(ApplySetting, RejectedWordLeavesTheScenarioUnchanged) {
    Scenario s;
    const std::string before = scenario_to_json(s);
    EXPECT_THROW(apply_setting(s, "cycle.strategy=three_touch"), ScenarioError);
    EXPECT_THROW(apply_setting(s, "machine.nope=1"), ScenarioError);
    EXPECT_THROW(apply_setting(s, "machine.latched_input=yes"), ScenarioError);
    EXPECT_EQ(scenario_to_json(s), before);
}

// --- The key table (one table of every key) ---

TEST(KeyTable, EveryKeyHasALabelADescriptionAndADefaultInRange) {
    const Scenario defaults;
    ASSERT_EQ(scenario_keys().size(), 49u);
    for (const KeyInfo& key : scenario_keys()) {
        SCOPED_TRACE(key.key);
        EXPECT_GT(std::string(key.label).size(), 0u);
        EXPECT_GT(std::string(key.description).size(), 20u);
        ASSERT_NE(find_any_key(key.key), nullptr);
        EXPECT_STREQ(find_any_key(key.key)->label, key.label);
        const std::string value = value_text(defaults, key);
        EXPECT_FALSE(value.empty());
        if (key.kind == KeyKind::number) {
            // A number without a unit is a fraction (cycle.knee_tolerance), a
            // count or an amount of any currency.
            const std::set<std::string> counts = {"cycle.repeats", "cycle.parts_per_year",
                                                  "cycle.cycles_per_part",
                                                  "cycle.machine_rate_per_hour"};
            if (std::string(key.unit).empty() && counts.count(key.key) == 0) {
                EXPECT_LE(key.max, 1.0) << "no unit";
            }
            EXPECT_LE(key.min, key.max);
            const double v = *get_number(defaults, key.key);
            EXPECT_LE(key.min, v);
            EXPECT_LE(v, key.max);
            EXPECT_EQ(find_key(key.key), find_any_key(key.key));
        } else {
            EXPECT_EQ(find_key(key.key), nullptr) << "find_key() is for numbers only";
        }
        if (key.kind == KeyKind::word) {
            const std::vector<std::string> words = allowed_words(key);
            EXPECT_NE(std::find(words.begin(), words.end(), value), words.end());
        }
    }
}

TEST(KeyTable, SectionsAndTheirKeysComeFromTheTable) {
    EXPECT_EQ(scenario_sections(), (std::vector<std::string>{"machine", "probe", "cycle"}));
    std::size_t total = 0;
    for (const std::string& section : scenario_sections()) {
        for (const std::string& name : section_key_names(section)) {
            EXPECT_NE(find_any_key(section + "." + name), nullptr) << section << "." << name;
            ++total;
        }
    }
    EXPECT_EQ(total, scenario_keys().size());
    EXPECT_TRUE(section_key_names("nope").empty());
}

TEST(KeyTable, EveryWordOfEveryWordKeyIsAcceptedBySetAndJson) {
    for (const KeyInfo& key : scenario_keys()) {
        for (const std::string& word : allowed_words(key)) {
            Scenario s;
            apply_setting(s, std::string(key.key) + "=" + word);
            EXPECT_EQ(value_text(s, key), word);
            EXPECT_EQ(value_text(scenario_from_json(scenario_to_json(s)), key), word);
        }
    }
}

// --- Presets merge over the current scenario ---

TEST(MergeJson, APresetChangesOnlyItsKeys) {
    Scenario base;
    base.cycle.probe_feed_mm_min = 1234.0;
    base.machine.accel_model = AccelModel::jerk_limited;
    const Scenario merged =
        merge_json(base, R"({"machine": {"scan_period_s": 0.000004, "latched_input": true},
                  "probe": {"pretravel_mm": 0.0005}})");
    EXPECT_EQ(merged.machine.scan_period_s, 0.000004);
    EXPECT_TRUE(merged.machine.latched_input);
    EXPECT_EQ(merged.probe.pretravel_mm, 0.0005);
    EXPECT_EQ(merged.cycle.probe_feed_mm_min, 1234.0);
    EXPECT_EQ(merged.machine.accel_model, AccelModel::jerk_limited);
}

TEST(MergeJson, ABadPresetChangesNothingAndNamesTheKey) {
    const Scenario base;
    const auto error = scenario_error_from([&] {
        (void)merge_json(base, R"({"machine": {"scan_period_s": 0.001, "time_constant_s": -1}})");
    });
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(error->what(), "machine.time_constant_s")) << error->what();
    // A merge that fails returns nothing, so the base is all the caller has.
    EXPECT_EQ(scenario_to_json(base), scenario_to_json(Scenario{}));
}

// --- Hardening: what fuzzing found (each failed before its fix) ---

TEST(ScenarioJson, DeepNestingIsRefusedNamingKeyAndLine) {
    for (const std::string& text :
         {"{\"machine\":{\"time_constant_s\":" + std::string(60000, '[') + std::string(60000, ']') +
              "}}",
          "{\"machine\":" + std::string(60000, '[') + std::string(60000, ']') + "}"}) {
        const auto error = scenario_error_from([&] { (void)scenario_from_json(text); });
        ASSERT_TRUE(error.has_value());
        EXPECT_TRUE(contains(error->what(), "machine")) << error->what();
        EXPECT_TRUE(contains(error->what(), "line 1")) << error->what();
        EXPECT_TRUE(contains(error->what(), "nesting")) << error->what();
    }
}

TEST(ScenarioJson, BytesAfterANulAreNotIgnored) {
    const std::string text = std::string(R"({"cycle":{"strategy":"single_touch"}})") + '\0' + "{{{";
    const auto error = scenario_error_from([&] { (void)scenario_from_json(text); });
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(error->what(), "NUL")) << error->what();
}

TEST(ScenarioJson, ADuplicateKeyIsRefusedNamingBothLines) {
    const auto error = scenario_error_from([&] {
        (void)scenario_from_json(
            "{\"machine\":{\"time_constant_s\":5,\n\"time_constant_s\":0.05}}");
    });
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(error->what(), "machine.time_constant_s")) << error->what();
    EXPECT_TRUE(contains(error->what(), "line 1 and again at line 2")) << error->what();
}

TEST(ScenarioJson, AnEmptyKeyIsCalledAnEmptyKey) {
    const auto error = scenario_error_from([&] { (void)scenario_from_json(R"({"":{}})"); });
    ASSERT_TRUE(error.has_value());
    EXPECT_TRUE(contains(error->what(), "empty key")) << error->what();
}

TEST(ApplySetting, NumbersAreDecimalAndWhiteSpaceIsIgnoredOnBothSides) {
    Scenario s;
    for (const char* bad : {"0x10", "0X10", "1e400", "inf", "nan", "10 mm", "1,5", ""}) {
        EXPECT_TRUE(scenario_error_from([&] {
                        apply_setting(s, std::string("cycle.probe_feed_mm_min=") + bad);
                    }).has_value())
            << bad;
    }
    apply_setting(s, "cycle.probe_feed_mm_min= 1500");
    EXPECT_EQ(s.cycle.probe_feed_mm_min, 1500.0);
    apply_setting(s, "cycle.probe_feed_mm_min=1600 ");
    EXPECT_EQ(s.cycle.probe_feed_mm_min, 1600.0);
    apply_setting(s, "cycle.probe_feed_mm_min=1.7e3");
    EXPECT_EQ(s.cycle.probe_feed_mm_min, 1700.0);
}

TEST(ApplySetting, NegativeZeroIsWrittenAsZero) {
    Scenario s;
    apply_setting(s, "machine.scan_period_s=-0");
    EXPECT_FALSE(std::signbit(s.machine.scan_period_s));
    EXPECT_EQ(scenario_to_json(s).find("-0"), std::string::npos);
    const Scenario from_file = scenario_from_json(R"({"machine": {"scan_period_s": -0.0}})");
    EXPECT_FALSE(std::signbit(from_file.machine.scan_period_s));
    Scenario direct;
    set_number(direct, "cycle.backoff_mm", -0.0);
    EXPECT_FALSE(std::signbit(direct.cycle.backoff_mm));
}

// The table of keys in docs/files.md ("The scenario file") tells the same story
// as the key table: every key, with its default, and no other.
TEST(KeyTable, TheDocsListEveryKeyWithItsDefault) {
    std::ifstream in(PROBECYCLE_FILES_DOC_PATH);
    ASSERT_TRUE(in) << PROBECYCLE_FILES_DOC_PATH;
    std::map<std::string, std::string> rows;  // key -> default column
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("| `", 0) != 0) continue;
        const std::size_t key_end = line.find("` |", 3);
        const std::size_t default_end = line.find(" |", key_end + 3);
        if (key_end == std::string::npos || default_end == std::string::npos) continue;
        const std::string key = line.substr(3, key_end - 3);
        if (key.find('.') == std::string::npos) continue;
        std::string value = line.substr(key_end + 4, default_end - key_end - 4);
        value.erase(std::remove(value.begin(), value.end(), '`'), value.end());
        rows[key] = value;
    }
    const Scenario defaults;
    for (const KeyInfo& key : scenario_keys()) {
        const auto it = rows.find(key.key);
        ASSERT_NE(it, rows.end()) << key.key << " is not in the key table of docs/files.md";
        EXPECT_EQ(it->second, value_text(defaults, key)) << key.key;
        rows.erase(it);
    }
    for (const auto& [key, value] : rows) {
        ADD_FAILURE() << key << " is in docs/files.md but not a key";
    }
}

// The keys a scenario's model, filter, strategy and feature leave unused: the
// window hides their editors and the PDF report leaves them out.
TEST(KeyTable, AKeyAppliesOnlyWhereTheScenarioUsesIt) {
    Scenario s;
    s.machine.accel_model = AccelModel::time_constant;
    s.machine.filter = FilterKind::none;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.feature = Feature::surface;
    EXPECT_TRUE(key_applies(s, "machine.time_constant_s"));
    for (const char* key :
         {"machine.max_accel_mm_s2", "machine.max_jerk_mm_s3", "machine.filter_time_s",
          "machine.filter2_time_s", "cycle.backoff_mm", "cycle.backoff_from",
          "cycle.feature_size_mm", "cycle.tolerance_action", "cycle.clearance_mm"}) {
        EXPECT_FALSE(key_applies(s, key)) << key;
    }
    EXPECT_TRUE(key_applies(s, "probe.max_feed_mm_min"));
    EXPECT_TRUE(key_applies(s, "no.such_key"));

    s.machine.accel_model = AccelModel::jerk_limited;
    s.machine.filter = FilterKind::linear;
    s.cycle.strategy = Strategy::two_touch;
    s.cycle.feature = Feature::boss;
    s.cycle.size_tolerance_mm = 0.05;
    EXPECT_FALSE(key_applies(s, "machine.time_constant_s"));
    for (const char* key :
         {"machine.max_accel_mm_s2", "machine.max_jerk_mm_s3", "machine.filter_time_s",
          "cycle.backoff_mm", "cycle.backoff_from", "cycle.feature_size_mm",
          "cycle.tolerance_action", "cycle.clearance_mm", "machine.rapid_feed_mm_min"}) {
        EXPECT_TRUE(key_applies(s, key)) << key;
    }
    EXPECT_FALSE(key_applies(s, "machine.filter2_time_s"));  // a bell filter's second stage
    s.machine.filter = FilterKind::bell;
    EXPECT_TRUE(key_applies(s, "machine.filter2_time_s"));
}

}  // namespace
}  // namespace probecycle
