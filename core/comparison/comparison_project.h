#pragma once

// The Comparison tab's project file: its file paths and settings, as JSON
// (docs/comparison.md, "Files"):
//   {"format": "probecycle-comparison", "version": 1,
//    "plan": "plan.csv", "reference_cmm": ..., "test_omm": ...,
//    "reference_omm": ..., "block_c0": "", "block_c180": "",
//    "c_axis_x_mm": 200, "c_axis_y_mm": 100, "angle_deg": 180,
//    "tolerance_mm": 0.01}
// A relative path is relative to the project file's folder; an empty one is
// not given. Every key is optional on reading (a default), none unknown.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/field_error.h"

namespace probecycle {

struct ComparisonProject {
    std::string plan;
    std::string reference_cmm;
    std::string test_omm;
    std::string reference_omm;
    std::string block_c0;
    std::string block_c180;
    double c_axis_x_mm{0.0};
    double c_axis_y_mm{0.0};
    double angle_deg{180.0};
    double tolerance_mm{0.01};
};

// The allowed ranges, shared with the window's editors and the CLI's options.
constexpr double kMinComparisonAngle_deg = 1.0;
constexpr double kMaxComparisonAngle_deg = 359.0;
constexpr double kMinTolerance_mm = 1e-6;
constexpr double kMaxTolerance_mm = 100.0;

std::string comparison_project_json(const ComparisonProject& project);
// The settings as a JSON object without format and version, and back (for
// the window's project file, which holds them as one section). Reading
// collects every problem, keyed `key_prefix` + key, and keeps the default of
// a refused key.
nlohmann::ordered_json comparison_settings_json(const ComparisonProject& project);
ComparisonProject comparison_settings_from(const nlohmann::ordered_json& object,
                                           const std::string& key_prefix,
                                           std::vector<FieldError>& errors);
// InputError naming the key, the value and what is allowed, for malformed
// JSON, an unknown key, a wrong type or a number out of range.
ComparisonProject parse_comparison_project(std::string_view text);

}  // namespace probecycle
