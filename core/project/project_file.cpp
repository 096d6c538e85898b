#include "core/project/project_file.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <nlohmann/json.hpp>

#include "core/common/csv_reader.h"
#include "core/common/field_error.h"
#include "core/common/json_guard.h"
#include "core/common/number_format.h"

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "probecycle-project";
constexpr int kVersion = 1;
// root > scenario > machine, and one more, so that a value that is an object
// where a number belongs is named by its key rather than by its depth.
constexpr std::size_t kMaxDepth = 4;

// The lab's sections, one table for reading, writing and naming the keys.
struct NumberKey {
    const char* section;
    const char* name;
    double min;
    double max;
    const char* unit;
    double& (*ref)(Project&);
};

struct IntKey {
    const char* section;
    const char* name;
    int min;
    int max;
    int& (*ref)(Project&);
};

struct TextKey {
    const char* section;
    const char* name;
    std::string& (*ref)(Project&);
};

// clang-format off
const NumberKey kNumbers[] = {
    {"ring", "gauge_diameter_mm", kMinGaugeDiameter_mm, kMaxGaugeDiameter_mm, "mm",
     [](Project& p) -> double& { return p.ring.options.gauge_diameter_mm; }},
    {"ring", "runout_limit_mm", 0.0, kMaxLabLimit_mm, "mm",
     [](Project& p) -> double& { return p.ring.options.runout_limit_mm; }},
    {"ring", "residual_limit_mm", 0.0, kMaxLabLimit_mm, "mm",
     [](Project& p) -> double& { return p.ring.options.residual_limit_mm; }},
    {"ring", "magnification", 0.0, kRingMagnifications[std::size(kRingMagnifications) - 1], "",
     [](Project& p) -> double& { return p.ring.magnification; }},
    {"length", "surface_z_mm", -kMaxCoordinate_mm, kMaxCoordinate_mm, "mm",
     [](Project& p) -> double& { return p.length.surface_z_mm; }},
    {"length", "active_length_mm", 0.0, kMaxLength_mm, "mm",
     [](Project& p) -> double& { return p.length.active_length_mm; }},
    {"length", "nominal_length_mm", 0.0, kMaxLength_mm, "mm",
     [](Project& p) -> double& { return p.length.nominal_length_mm; }},
    {"delay", "interpolation_period_s", 0.0, kMaxInterpolationPeriod_s, "s",
     [](Project& p) -> double& { return p.delay.interpolation_period_s; }},
    {"compensation", "feed_mm_min", kMinCompensationFeed_mm_min, kMaxCompensationFeed_mm_min,
     "mm/min", [](Project& p) -> double& { return p.compensation.feed_mm_min; }},
    {"compensation", "interpolation_period_s", kMinInterpolationPeriod_s,
     kMaxInterpolationPeriod_s, "s",
     [](Project& p) -> double& { return p.compensation.interpolation_period_s; }},
    {"compensation", "speed_fraction", kMinSpeedFraction, 1.0, "",
     [](Project& p) -> double& { return p.compensation.speed_fraction; }},
};

const IntKey kInts[] = {
    {"compensation", "lag_cycles", 0, kMaxLagCycles,
     [](Project& p) -> int& { return p.compensation.lag_cycles; }},
    {"compensation", "compensated_lag_cycles", -1, kMaxLagCycles,
     [](Project& p) -> int& { return p.compensation.compensated_lag_cycles; }},
};

const TextKey kTexts[] = {
    {"ring", "points_csv", [](Project& p) -> std::string& { return p.ring.points_csv; }},
    {"ring", "fitted_csv", [](Project& p) -> std::string& { return p.ring.fitted_csv; }},
    {"length", "trigger_z", [](Project& p) -> std::string& { return p.length.trigger_z; }},
    {"delay", "touches_csv", [](Project& p) -> std::string& { return p.delay.touches_csv; }},
    {"delay", "fitted_csv", [](Project& p) -> std::string& { return p.delay.fitted_csv; }},
    {"delay", "applied_group", [](Project& p) -> std::string& { return p.delay.applied_group; }},
    {"report", "customer", [](Project& p) -> std::string& { return p.report.customer; }},
    {"report", "machine", [](Project& p) -> std::string& { return p.report.machine; }},
    {"report", "part", [](Project& p) -> std::string& { return p.report.part; }},
    {"report", "author", [](Project& p) -> std::string& { return p.report.author; }},
    {"report", "notes", [](Project& p) -> std::string& { return p.report.notes; }},
};
// clang-format on

// The sections the tables above describe: the lab's, written before
// "comparison", and the PDF report's title block, written after it.
constexpr const char* kLabSections[] = {"ring", "length", "delay", "compensation"};
constexpr const char* kReportSection = "report";
constexpr const char* kTouchKey = "touch";  // in compensation: a word
constexpr TouchMotion kTouchMotions[] = {TouchMotion::constant_speed, TouchMotion::braking};

std::string join_words(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
    return out;
}

std::vector<std::string> section_keys(std::string_view section) {
    std::vector<std::string> keys;
    for (const TextKey& k : kTexts) {
        if (section == k.section) keys.emplace_back(k.name);
    }
    for (const NumberKey& k : kNumbers) {
        if (section == k.section) keys.emplace_back(k.name);
    }
    for (const IntKey& k : kInts) {
        if (section == k.section) keys.emplace_back(k.name);
    }
    if (section == "compensation") keys.emplace_back(kTouchKey);
    return keys;
}

Message unknown_key_in(const std::string& where, const std::vector<std::string>& keys) {
    return Message{"unknown_key",
                   "FieldError",
                   QT_TRANSLATE_NOOP("FieldError", "unknown key; allowed in %1: %2"),
                   {text_arg("section", where), text_arg("allowed_keys", join_words(keys))}};
}

std::vector<std::string> top_keys() {
    std::vector<std::string> keys = {"format", "version", "scenario", "baseline", "comparison"};
    keys.insert(keys.end(), std::begin(kLabSections), std::end(kLabSections));
    keys.emplace_back(kReportSection);
    return keys;
}

// A scenario section, read as a scenario file is; its problems keyed under `key`.
std::optional<Scenario> read_scenario(const Json& value, const std::string& key,
                                      std::vector<FieldError>& errors) {
    try {
        return scenario_from_json(value.dump());
    } catch (const ScenarioError& e) {
        for (const FieldError& error : e.errors()) {
            errors.push_back(
                {error.key == "file" ? key : key + "." + error.key, error.value, error.allowed});
        }
    }
    return std::nullopt;
}

// A fit's CSV text must read as the lab reads it: the problem with its line.
template <typename Parse>
void check_csv(const std::string& text, const std::string& key, Parse parse,
               std::vector<FieldError>& errors) {
    if (text.empty()) return;
    try {
        parse(text);
    } catch (const CsvError& e) {
        errors.push_back({key, "", e.to_message()});
    }
}

void read_section(const std::string& section, const Json& body, Project& project,
                  std::vector<FieldError>& errors) {
    if (!body.is_object()) {
        errors.push_back(
            {section, body.dump(),
             allowed_text("not_an_object", QT_TRANSLATE_NOOP("FieldError", "an object of keys"))});
        return;
    }
    for (const auto& [name, value] : body.items()) {
        std::string key = section;
        key += '.';
        key += name;
        bool known = false;
        for (const TextKey& k : kTexts) {
            if (section != k.section || name != k.name) continue;
            known = true;
            if (value.is_string()) {
                k.ref(project) = value.get<std::string>();
            } else {
                errors.push_back({key, value.dump(),
                                  allowed_text("text", QT_TRANSLATE_NOOP("FieldError", "text"))});
            }
        }
        for (const NumberKey& k : kNumbers) {
            if (section != k.section || name != k.name) continue;
            known = true;
            const double number = value.is_number() ? value.get<double>() : std::nan("");
            if (number >= k.min && number <= k.max) {
                k.ref(project) = number == 0.0 ? 0.0 : number;  // no -0
            } else {
                errors.push_back({key, value.dump(), range_allowed(k.min, k.max, k.unit)});
            }
        }
        for (const IntKey& k : kInts) {
            if (section != k.section || name != k.name) continue;
            known = true;
            const long long number = value.is_number_integer() ? value.get<long long>() : k.min - 1;
            if (number >= k.min && number <= k.max) {
                k.ref(project) = static_cast<int>(number);
            } else {
                Message allowed =
                    allowed_text("whole_number",
                                 QT_TRANSLATE_NOOP("FieldError", "a whole number from %1 to %2"));
                allowed.args = {arg("min", ArgKind::integer, k.min),
                                arg("max", ArgKind::integer, k.max)};
                errors.push_back({key, value.dump(), std::move(allowed)});
            }
        }
        if (section == "compensation" && name == kTouchKey) {
            known = true;
            const Json& word = value;  // clang cannot capture a structured binding
            const auto* found =
                std::find_if(std::begin(kTouchMotions), std::end(kTouchMotions),
                             [&word](TouchMotion m) { return word == to_string(m); });
            if (found != std::end(kTouchMotions)) {
                project.compensation.touch = *found;
            } else {
                Message allowed =
                    allowed_text("unknown_word", QT_TRANSLATE_NOOP("FieldError", "one of %1"));
                allowed.args = {text_arg("allowed_words", "constant_speed, braking")};
                errors.push_back({key, value.dump(), std::move(allowed)});
            }
        }
        if (!known) errors.push_back({key, "", unknown_key_in(section, section_keys(section))});
    }
}

}  // namespace

std::string project_json(const Project& project) {
    auto& p = const_cast<Project&>(project);  // the tables' accessors only read here
    Json root = Json::object();
    root["format"] = kFormat;
    root["version"] = kVersion;
    root["scenario"] = Json::parse(scenario_to_json(project.scenario));
    root["baseline"] =
        project.baseline ? Json::parse(scenario_to_json(*project.baseline)) : Json(nullptr);
    const auto write_section = [&](const char* section) {
        Json& body = root[section] = Json::object();
        for (const TextKey& k : kTexts) {
            if (std::string_view(section) == k.section) body[k.name] = k.ref(p);
        }
        for (const NumberKey& k : kNumbers) {
            if (std::string_view(section) == k.section) body[k.name] = k.ref(p);
        }
        for (const IntKey& k : kInts) {
            if (std::string_view(section) == k.section) body[k.name] = k.ref(p);
        }
        if (std::string_view(section) == "compensation") {
            body[kTouchKey] = to_string(project.compensation.touch);
        }
    };
    for (const char* section : kLabSections) write_section(section);
    root["comparison"] = comparison_settings_json(project.comparison);
    write_section(kReportSection);
    return root.dump(2) + "\n";
}

Project parse_project(std::string_view text) {
    Json root;
    if (std::optional<FieldError> error = parse_checked_json(text, kMaxDepth, root)) {
        throw ProjectError({std::move(*error)});
    }
    if (!root.is_object() || !root.contains("format") || root["format"] != kFormat) {
        throw ProjectError(
            {{"format", root.is_object() && root.contains("format") ? root["format"].dump() : "",
              allowed_text("project_file_format",
                           QT_TRANSLATE_NOOP("FieldError",
                                             "\"probecycle-project\" (a ProbeCycle project)"))}});
    }
    if (!root.contains("version") || !root["version"].is_number_integer() ||
        root["version"].get<long long>() != kVersion) {
        // Only a later version is a newer ProbeCycle's file; 0, null or "1"
        // is a damaged one.
        const bool newer = root.contains("version") && root["version"].is_number_integer() &&
                           root["version"].get<long long>() > kVersion;
        throw ProjectError(
            {{"version", root.contains("version") ? root["version"].dump() : "",
              newer ? allowed_text(
                          "project_file_version",
                          QT_TRANSLATE_NOOP("FieldError", "1 (a newer ProbeCycle wrote this file)"))
                    : allowed_text("project_file_version_damaged",
                                   QT_TRANSLATE_NOOP("FieldError",
                                                     "the whole number 1 (this ProbeCycle's "
                                                     "project version)"))}});
    }
    Project project;
    std::vector<FieldError> errors;
    bool has_scenario = false;
    for (const auto& [key, value] : root.items()) {
        if (key == "format" || key == "version") continue;
        if (key == "scenario") {
            has_scenario = true;
            if (std::optional<Scenario> s = read_scenario(value, key, errors))
                project.scenario = *s;
        } else if (key == "baseline") {
            if (value.is_null()) continue;
            if (std::optional<Scenario> s = read_scenario(value, key, errors))
                project.baseline = *s;
        } else if (key == "comparison") {
            if (value.is_object()) {
                project.comparison = comparison_settings_from(value, "comparison.", errors);
            } else {
                errors.push_back(
                    {key, value.dump(),
                     allowed_text("not_an_object",
                                  QT_TRANSLATE_NOOP("FieldError", "an object of keys"))});
            }
        } else if (key == kReportSection ||
                   std::find(std::begin(kLabSections), std::end(kLabSections), key) !=
                       std::end(kLabSections)) {
            read_section(key, value, project, errors);
        } else {
            errors.push_back({key, "", unknown_key_in("the project", top_keys())});
        }
    }
    if (!has_scenario) {
        errors.push_back(
            {"scenario", "",
             allowed_text("missing_scenario",
                          QT_TRANSLATE_NOOP("FieldError", "missing; a project holds a scenario"))});
    }
    const double magnification = project.ring.magnification;
    if (std::find(std::begin(kRingMagnifications), std::end(kRingMagnifications), magnification) ==
        std::end(kRingMagnifications)) {
        Message allowed =
            allowed_text("unknown_word", QT_TRANSLATE_NOOP("FieldError", "one of %1"));
        allowed.args = {text_arg("allowed_words", "0, 1, 10, 100, 1000, 10000")};
        errors.push_back({"ring.magnification", format_number(magnification), std::move(allowed)});
    }
    check_csv(project.ring.fitted_csv, "ring.fitted_csv", parse_ring_csv, errors);
    check_csv(project.delay.fitted_csv, "delay.fitted_csv", parse_delay_csv, errors);
    if (!errors.empty()) throw ProjectError(std::move(errors));
    return project;
}

bool is_project_text(std::string_view text) {
    // A scenario file has no text values that could hold the format's name,
    // so a file that names it is a project (and a damaged one is refused as a
    // project, with the project's messages). Nor has it a "format" key or a
    // "scenario" section: a file with both is a project whose format is
    // wrong, refused for that one thing rather than for every section a
    // scenario does not know.
    return text.find(std::string("\"") + kFormat + "\"") != std::string_view::npos ||
           (text.find("\"format\"") != std::string_view::npos &&
            text.find("\"scenario\"") != std::string_view::npos);
}

}  // namespace probecycle
