// Every key at and just inside its limits, and at the values that cannot be
// told from zero (a subnormal servo time constant once gave a NaN cycle time
// marked valid): a value the scenario accepts gives finite figures everywhere
// the evaluation prints them; a subnormal number is zero.
// Beside the random scenarios of cycle_property_test.cpp, which never draw
// these edges.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/cycle/cycle_report.h"
#include "core/cycle/preset.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"

namespace probecycle {
namespace {

// The values of a key's edges: its limits, the next doubles inside them,
// and, where zero is allowed, the smallest subnormal, the largest subnormal
// and the smallest normal number.
std::vector<double> edge_values(const KeyInfo& key) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    std::vector<double> values = {key.min, key.max, std::nextafter(key.min, kInf),
                                  std::nextafter(key.max, -kInf)};
    if (key.min <= 0.0 && key.max > 0.0) {
        values.push_back(std::numeric_limits<double>::denorm_min());
        values.push_back(std::nextafter(std::numeric_limits<double>::min(), 0.0));
        values.push_back(std::numeric_limits<double>::min());
        values.push_back(1e-300);
    }
    return values;
}

// Every null (a NaN or an infinity as nlohmann writes it) in the JSON, by path.
void find_nulls(const nlohmann::json& j, const std::string& path, std::vector<std::string>& out) {
    if (j.is_null()) out.push_back(path);
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) find_nulls(*it, path + "." + it.key(), out);
    }
    if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) {
            find_nulls(j[i], path + "[" + std::to_string(i) + "]", out);
        }
    }
}

Scenario preset(const std::string& name) {
    std::ifstream in(std::filesystem::path(PROBECYCLE_RESOURCES_DIR) / "presets" / name);
    std::ostringstream text;
    text << in.rdbuf();
    return scenario_from_json(parse_preset(text.str()).scenario_json);
}

TEST(ScenarioEdges, ASubnormalNumberIsZero) {
    for (const KeyInfo& key : numeric_keys()) {
        Scenario s;
        ASSERT_TRUE(set_number(s, key.key, std::numeric_limits<double>::denorm_min()));
        EXPECT_EQ(*get_number(s, key.key), 0.0) << key.key;
        // And as a scenario file gives it: zero, or refused where zero is
        // outside the key's range.
        const std::string dotted = key.key;
        const std::size_t dot = dotted.find('.');
        const std::string text =
            "{\"" + dotted.substr(0, dot) + "\": {\"" + dotted.substr(dot + 1) + "\": 4.9e-324}}";
        try {
            EXPECT_EQ(*get_number(scenario_from_json(text), key.key), 0.0) << key.key;
            EXPECT_LE(key.min, 0.0) << key.key;
        } catch (const ScenarioError& e) {
            EXPECT_GT(key.min, 0.0) << key.key << ": " << e.what();
            EXPECT_NE(std::string(e.what()).find(key.key), std::string::npos) << e.what();
        }
    }
}

TEST(ScenarioEdges, ServoTimeConstantThatCannotBeToldFromZeroGivesTheIdealServo) {
    // Before: a NaN cycle time, "valid": true.
    Scenario s;
    s.machine.servo_time_constant_s = 0.0;
    const double ideal = analyse(s).cycle.total();
    set_number(s, "machine.servo_time_constant_s", std::numeric_limits<double>::denorm_min());
    const Analysis a = analyse(s);
    EXPECT_TRUE(std::isfinite(a.cycle.total()));
    EXPECT_EQ(a.cycle.total(), ideal);
}

TEST(ScenarioEdges, EveryAcceptedEdgeGivesFiniteFiguresEverywhere) {
    int evaluated = 0;
    for (const Scenario& base : {Scenario{}, preset("machine_fanuc_exponential_servo.json")}) {
        for (const KeyInfo& key : numeric_keys()) {
            for (const double value : edge_values(key)) {
                Scenario s = base;
                set_number(s, key.key, value);
                if (!validate(s).empty()) continue;  // refused with a message: tested elsewhere
                ++evaluated;
                const nlohmann::json j = nlohmann::json::parse(evaluation_to_json(s, analyse(s)));
                std::vector<std::string> nulls;
                find_nulls(j, "", nulls);
                // No knee (no valid feed to find it among) is null by design.
                std::erase_if(nulls, [](const std::string& path) {
                    return path == ".knee_feed_mm_min" || path == ".knee_cycle_time_s";
                });
                EXPECT_TRUE(nulls.empty())
                    << key.key << " = " << value << ": " << (nulls.empty() ? "" : nulls.front())
                    << " is not a number (" << nulls.size() << " in all)";
            }
        }
    }
    EXPECT_GT(evaluated, 300);
}

}  // namespace
}  // namespace probecycle
