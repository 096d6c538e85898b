#include "core/comparison/comparison_project.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/common/csv_reader.h"
#include "core/common/field_error.h"
#include "core/common/input_error.h"
#include "core/common/json_guard.h"
#include "core/common/number_format.h"

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "probecycle-comparison";
constexpr int kVersion = 1;

[[noreturn]] void refuse(const std::string& key, const std::string& value, Message allowed) {
    throw InputError(FieldError{key, value, std::move(allowed)}.to_message());
}

struct NumberKey {
    const char* key;
    double ComparisonProject::*member;
    double min;
    double max;
    const char* unit;
};

const NumberKey kNumbers[] = {
    {"c_axis_x_mm", &ComparisonProject::c_axis_x_mm, -kMaxCoordinate_mm, kMaxCoordinate_mm, "mm"},
    {"c_axis_y_mm", &ComparisonProject::c_axis_y_mm, -kMaxCoordinate_mm, kMaxCoordinate_mm, "mm"},
    {"angle_deg", &ComparisonProject::angle_deg, kMinComparisonAngle_deg, kMaxComparisonAngle_deg,
     "deg"},
    {"tolerance_mm", &ComparisonProject::tolerance_mm, kMinTolerance_mm, kMaxTolerance_mm, "mm"},
};

struct PathKey {
    const char* key;
    std::string ComparisonProject::*member;
};

const PathKey kPaths[] = {
    {"plan", &ComparisonProject::plan},
    {"reference_cmm", &ComparisonProject::reference_cmm},
    {"test_omm", &ComparisonProject::test_omm},
    {"reference_omm", &ComparisonProject::reference_omm},
    {"block_c0", &ComparisonProject::block_c0},
    {"block_c180", &ComparisonProject::block_c180},
};

std::string allowed_keys() {
    std::string keys = "format, version";  // of a comparison project file
    for (const PathKey& p : kPaths) keys += std::string(", ") + p.key;
    for (const NumberKey& n : kNumbers) keys += std::string(", ") + n.key;
    return keys;
}

}  // namespace

nlohmann::ordered_json comparison_settings_json(const ComparisonProject& project) {
    Json out = Json::object();
    for (const PathKey& p : kPaths) out[p.key] = project.*p.member;
    for (const NumberKey& n : kNumbers) out[n.key] = project.*n.member;
    return out;
}

ComparisonProject comparison_settings_from(const nlohmann::ordered_json& object,
                                           const std::string& key_prefix,
                                           std::vector<FieldError>& errors) {
    ComparisonProject project;
    for (const auto& [name, value] : object.items()) {
        const std::string key = key_prefix + name;
        bool known = false;
        for (const PathKey& p : kPaths) {
            if (name != p.key) continue;
            known = true;
            if (!value.is_string()) {
                errors.push_back(
                    {key, value.dump(),
                     allowed_text(
                         "path_text",
                         QT_TRANSLATE_NOOP("FieldError", "a file path as text (empty: none)"))});
                continue;
            }
            project.*p.member = value.get<std::string>();
        }
        for (const NumberKey& n : kNumbers) {
            if (name != n.key) continue;
            known = true;
            const double number = value.is_number() ? value.get<double>() : std::nan("");
            if (!(number >= n.min && number <= n.max)) {
                errors.push_back({key, value.dump(), range_allowed(n.min, n.max, n.unit)});
                continue;
            }
            project.*n.member = number == 0.0 ? 0.0 : number;  // no -0
        }
        if (!known) {
            errors.push_back(
                {key, "",
                 Message{"unknown_key",
                         "FieldError",
                         QT_TRANSLATE_NOOP("FieldError", "an unknown key; allowed: %1"),
                         {text_arg("keys", allowed_keys())}}});
        }
    }
    return project;
}

std::string comparison_project_json(const ComparisonProject& project) {
    Json out = Json::object();
    out["format"] = kFormat;
    out["version"] = kVersion;
    out.update(comparison_settings_json(project));
    return out.dump(2) + "\n";
}

ComparisonProject parse_comparison_project(std::string_view text) {
    if (std::optional<FieldError> error = check_json_text(text, 2)) {
        throw InputError(error->to_message());
    }
    Json root;
    try {
        root = Json::parse(text.begin(), text.end());
    } catch (const nlohmann::json::exception& e) {
        refuse("file", "",
               Message{"malformed_json",
                       "FieldError",
                       QT_TRANSLATE_NOOP("FieldError", "malformed JSON: %1"),
                       {text_arg("detail", e.what())}});
    }
    if (!root.is_object()) {
        refuse("file", "",
               allowed_text("project_object",
                            QT_TRANSLATE_NOOP("FieldError",
                                              "a JSON object with the comparison's files and "
                                              "settings")));
    }
    if (const auto format = root.find("format"); format != root.end()) {
        if (!format->is_string() || format->get<std::string>() != kFormat) {
            refuse("format", format->dump(),
                   allowed_text("project_format",
                                QT_TRANSLATE_NOOP("FieldError", "\"probecycle-comparison\"")));
        }
        root.erase("format");
    }
    if (const auto version = root.find("version"); version != root.end()) {
        if (!version->is_number_integer() || version->get<long long>() != kVersion) {
            refuse("version", version->dump(),
                   allowed_text("project_version", QT_TRANSLATE_NOOP("FieldError", "1")));
        }
        root.erase("version");
    }
    std::vector<FieldError> errors;
    ComparisonProject project = comparison_settings_from(root, {}, errors);
    if (!errors.empty()) throw InputError(errors.front().to_message());
    return project;
}

}  // namespace probecycle
