#include "core/cycle/scenario.h"

#include "core/common/number_format.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

// A numeric key and where it lives in the scenario.
struct NumericKey {
    KeyInfo info;
    double& (*ref)(Scenario&);
};

#define PC_REF(section, field) [](Scenario& s) -> double& { return s.section.field; }

// The one table of numeric keys: names, units, ranges, meanings. Validation,
// JSON, --set and the window's editors all read it. Ranges are what a real
// machine or probe can plausibly have; zero is allowed where the issue says
// delays and distances may be 0.
const std::vector<NumericKey>& numeric_key_table() {
    static const std::vector<NumericKey> table = {
        {{"machine.time_constant_s", "s", 0.001, 2.0,
          "Acceleration time constant T: the programmed feed is reached in T seconds (a = v/T). "
          "Used by the time_constant model."},
         PC_REF(machine, time_constant_s)},
        {{"machine.max_accel_mm_s2", "mm/s^2", 1.0, 200000.0,
          "Maximum axis acceleration. Used by the constant_accel and jerk_limited models."},
         PC_REF(machine, max_accel_mm_s2)},
        {{"machine.max_jerk_mm_s3", "mm/s^3", 10.0, 1.0e9,
          "Maximum axis jerk. Used by the jerk_limited (S-curve) model."},
         PC_REF(machine, max_jerk_mm_s3)},
        {{"machine.rapid_feed_mm_min", "mm/min", 100.0, 200000.0,
          "Rapid feed, used for the positioning moves between touches."},
         PC_REF(machine, rapid_feed_mm_min)},
        {{"machine.scan_period_s", "s", 0.0, 0.1,
          "Period at which the controller scans the skip input (~4 ms standard, ~4 us high-speed). "
          "The wait for the next scan is the single-touch uncertainty and adds to overtravel."},
         PC_REF(machine, scan_period_s)},
        {{"machine.controller_latency_s", "s", 0.0, 0.5,
          "Fixed controller latency after the scan; the axis keeps moving (overtravel)."},
         PC_REF(machine, controller_latency_s)},
        {{"probe.pretravel_mm", "mm", 0.0, 1.0,
          "Mechanical pretravel from first contact to trigger (typically 0.001-0.05 mm)."},
         PC_REF(probe, pretravel_mm)},
        {{"probe.interface_delay_s", "s", 0.0, 0.5,
          "Time the probe interface (receiver) takes to pass the trigger to the controller."},
         PC_REF(probe, interface_delay_s)},
        {{"probe.repeatability_2sigma_mm", "mm", 0.0, 1.0,
          "Probe unidirectional repeatability (2 sigma), combined into the uncertainty."},
         PC_REF(probe, repeatability_2sigma_mm)},
        {{"probe.overtravel_limit_mm", "mm", 0.01, 100.0,
          "Stylus deflection range: the probe must stop within it or the probe or stylus is "
          "damaged."},
         PC_REF(probe, overtravel_limit_mm)},
        {{"probe.reseat_mm", "mm", 0.0, 10.0,
          "Distance the probe needs to reseat after a trigger; the backoff must clear overtravel "
          "plus this."},
         PC_REF(probe, reseat_mm)},
        {{"probe.calibration_feed_mm_min", "mm/min", 0.0, 100000.0,
          "Feed at which the probe was calibrated; 0 = the measuring feed. A different measuring "
          "feed shifts the delay travel and so the measured value."},
         PC_REF(probe, calibration_feed_mm_min)},
        {{"cycle.feature_size_mm", "mm", 0.0, 10000.0,
          "Distance between opposite stylus-centre contact points (web/pocket width, bore/boss "
          "diameter less the ball diameter). Unused for a surface."},
         PC_REF(cycle, feature_size_mm)},
        {{"cycle.approach_mm", "mm", 0.0, 1000.0,
          "Start distance in front of the nominal surface. Should cover the part's position "
          "uncertainty and the distance needed to reach the feed."},
         PC_REF(cycle, approach_mm)},
        {{"cycle.probe_feed_mm_min", "mm/min", 1.0, 100000.0,
          "Feed of the (first) touch; single-touch measures at it."},
         PC_REF(cycle, probe_feed_mm_min)},
        {{"cycle.measure_feed_mm_min", "mm/min", 1.0, 100000.0,
          "Feed of the second, measuring touch of two-touch (typically 30 mm/min)."},
         PC_REF(cycle, measure_feed_mm_min)},
        {{"cycle.backoff_mm", "mm", 0.0, 1000.0,
          "Two-touch: distance backed off from where the first touch stopped."},
         PC_REF(cycle, backoff_mm)},
        {{"cycle.return_feed_mm_min", "mm/min", 1.0, 200000.0,
          "Feed of the backoff and of the return to the start position."},
         PC_REF(cycle, return_feed_mm_min)},
        {{"cycle.target_uncertainty_mm", "mm", 0.0, 10.0,
          "Target for the expanded (k=2) uncertainty; 0 = no target."},
         PC_REF(cycle, target_uncertainty_mm)},
    };
    return table;
}

#undef PC_REF

const NumericKey* find_numeric(std::string_view key) {
    for (const NumericKey& k : numeric_key_table()) {
        if (key == k.info.key) return &k;
    }
    return nullptr;
}

// Values in messages: 12 digits, so a value just out of range reads as such.
std::string number_text(double value) {
    return format_number(value, 12);
}

Message range_text(const KeyInfo& info) {
    Message m =
        allowed_text("out_of_range", QT_TRANSLATE_NOOP("FieldError", "a number from %1 to %2 %3"));
    m.args = {arg("min", ArgKind::number, info.min), arg("max", ArgKind::number, info.max),
              text_arg("unit", info.unit)};
    return m;
}

Message one_of(const char* words) {
    Message m = allowed_text("unknown_word", QT_TRANSLATE_NOOP("FieldError", "one of %1"));
    m.args = {text_arg("allowed_words", words)};
    return m;
}

Message bool_words() {
    return allowed_text("not_a_bool", QT_TRANSLATE_NOOP("FieldError", "true or false"));
}

const char* enum_allowed(std::string_view key) {
    if (key == "machine.accel_model") return "time_constant, constant_accel, jerk_limited";
    if (key == "cycle.strategy") return "single_touch, two_touch";
    if (key == "cycle.feature") return "surface, web, pocket, bore, boss";
    return nullptr;
}

Message unknown_key(const std::string& section, const std::string& keys) {
    Message m = allowed_text("unknown_key",
                             QT_TRANSLATE_NOOP("FieldError", "unknown key; allowed in %1: %2"));
    m.args = {text_arg("section", section), text_arg("allowed_keys", keys)};
    return m;
}

Message with_detail(const char* code, const char* text, std::string detail) {
    Message m = allowed_text(code, text);
    m.args = {text_arg("detail", std::move(detail))};
    return m;
}

// Sets an enum key from a word; false when the word is not one of the allowed.
bool set_enum(Scenario& s, std::string_view key, std::string_view word) {
    if (key == "machine.accel_model") {
        if (auto v = accel_model_from_string(word)) return s.machine.accel_model = *v, true;
    } else if (key == "cycle.strategy") {
        if (auto v = strategy_from_string(word)) return s.cycle.strategy = *v, true;
    } else if (key == "cycle.feature") {
        if (auto v = feature_from_string(word)) return s.cycle.feature = *v, true;
    }
    return false;
}

const std::vector<std::string>& section_keys(std::string_view section) {
    static const std::vector<std::string> machine = {
        "accel_model",       "time_constant_s", "max_accel_mm_s2",      "max_jerk_mm_s3",
        "rapid_feed_mm_min", "scan_period_s",   "controller_latency_s", "latched_input"};
    static const std::vector<std::string> probe = {
        "pretravel_mm",        "interface_delay_s", "repeatability_2sigma_mm",
        "overtravel_limit_mm", "reseat_mm",         "calibration_feed_mm_min"};
    static const std::vector<std::string> cycle = {"strategy",
                                                   "feature",
                                                   "feature_size_mm",
                                                   "approach_mm",
                                                   "probe_feed_mm_min",
                                                   "measure_feed_mm_min",
                                                   "backoff_mm",
                                                   "return_feed_mm_min",
                                                   "target_uncertainty_mm"};
    static const std::vector<std::string> none;
    if (section == "machine") return machine;
    if (section == "probe") return probe;
    if (section == "cycle") return cycle;
    return none;
}

std::string join(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) {
        if (!out.empty()) out += ", ";
        out += w;
    }
    return out;
}

}  // namespace

MotionLimits Scenario::motion_limits() const {
    return {machine.accel_model, machine.time_constant_s, machine.max_accel_mm_s2,
            machine.max_jerk_mm_s3};
}

namespace {
std::string join_messages(const std::vector<FieldError>& errors) {
    std::string text;
    for (const FieldError& e : errors) {
        if (!text.empty()) text += '\n';
        text += e.message();
    }
    return text;
}
}  // namespace

ScenarioError::ScenarioError(std::vector<FieldError> errors)
    : std::runtime_error(join_messages(errors)), errors_(std::move(errors)) {}

const std::vector<KeyInfo>& numeric_keys() {
    static const std::vector<KeyInfo> keys = [] {
        std::vector<KeyInfo> out;
        for (const NumericKey& k : numeric_key_table()) out.push_back(k.info);
        return out;
    }();
    return keys;
}

const KeyInfo* find_key(std::string_view dotted_key) {
    const NumericKey* k = find_numeric(dotted_key);
    return k ? &k->info : nullptr;
}

std::optional<double> get_number(const Scenario& scenario, std::string_view dotted_key) {
    const NumericKey* k = find_numeric(dotted_key);
    if (!k) return std::nullopt;
    return k->ref(const_cast<Scenario&>(scenario));  // the accessor only reads here
}

bool set_number(Scenario& scenario, std::string_view dotted_key, double value) {
    const NumericKey* k = find_numeric(dotted_key);
    if (!k) return false;
    k->ref(scenario) = value;
    return true;
}

std::vector<FieldError> validate(const Scenario& scenario) {
    std::vector<FieldError> errors;
    for (const NumericKey& k : numeric_key_table()) {
        const double value = *get_number(scenario, k.info.key);
        if (!std::isfinite(value) || value < k.info.min || value > k.info.max) {
            errors.push_back({k.info.key, number_text(value), range_text(k.info)});
        }
    }
    // Internal features: both start positions lie inside the feature
    // (domain.md, "Features"), so it must be wider than two approach distances.
    const Cycle& c = scenario.cycle;
    if ((c.feature == Feature::pocket || c.feature == Feature::bore) &&
        !(c.feature_size_mm > 2.0 * c.approach_mm)) {
        Message allowed = allowed_text(
            "feature_narrower_than_approach",
            QT_TRANSLATE_NOOP("FieldError", "more than twice cycle.approach_mm (%1) for a %2"));
        allowed.args = {arg("min_size_mm", ArgKind::length_mm, 2.0 * c.approach_mm),
                        text_arg("feature", to_string(c.feature))};
        errors.push_back({"cycle.feature_size_mm", number_text(c.feature_size_mm), allowed});
    }
    return errors;
}

void validate_or_throw(const Scenario& scenario) {
    std::vector<FieldError> errors = validate(scenario);
    if (!errors.empty()) throw ScenarioError(std::move(errors));
}

Scenario scenario_from_json(std::string_view text) {
    Json root;
    try {
        root = Json::parse(text.begin(), text.end());
    } catch (const nlohmann::json::parse_error& e) {
        // nlohmann's message names the line and column.
        throw ScenarioError(
            {{"file", "",
              with_detail("malformed_json", QT_TRANSLATE_NOOP("FieldError", "malformed JSON: %1"),
                          e.what())}});
    } catch (const nlohmann::json::exception& e) {
        // e.g. out_of_range.406 for a number such as 1e400 that no double holds.
        throw ScenarioError(
            {{"file", "",
              with_detail("number_overflow",
                          QT_TRANSLATE_NOOP("FieldError", "a number out of range: %1"),
                          e.what())}});
    }
    if (!root.is_object()) {
        throw ScenarioError({{"file", "",
                              allowed_text("not_an_object",
                                           QT_TRANSLATE_NOOP("FieldError",
                                                             "a JSON object with sections machine, "
                                                             "probe, cycle"))}});
    }
    Scenario scenario;
    std::vector<FieldError> errors;
    for (const auto& [section, body] : root.items()) {
        const std::vector<std::string>& keys = section_keys(section);
        if (keys.empty()) {
            errors.push_back(
                {section, "",
                 allowed_text(
                     "unknown_section",
                     QT_TRANSLATE_NOOP("FieldError",
                                       "unknown section; allowed: machine, probe, cycle"))});
            continue;
        }
        if (!body.is_object()) {
            errors.push_back({section, body.dump(),
                              allowed_text("not_an_object",
                                           QT_TRANSLATE_NOOP("FieldError", "an object of keys"))});
            continue;
        }
        for (const auto& [name, value] : body.items()) {
            const std::string dotted = section + "." + name;
            if (const NumericKey* k = find_numeric(dotted)) {
                if (!value.is_number()) {
                    errors.push_back({dotted, value.dump(), range_text(k->info)});
                } else {
                    k->ref(scenario) = value.get<double>();
                }
            } else if (const char* words = enum_allowed(dotted)) {
                if (!value.is_string() || !set_enum(scenario, dotted, value.get<std::string>())) {
                    errors.push_back({dotted, value.dump(), one_of(words)});
                }
            } else if (dotted == "machine.latched_input") {
                if (!value.is_boolean()) {
                    errors.push_back({dotted, value.dump(), bool_words()});
                } else {
                    scenario.machine.latched_input = value.get<bool>();
                }
            } else {
                errors.push_back({dotted, "", unknown_key(section, join(keys))});
            }
        }
    }
    // Range errors too, so one run names every problem in the file (keys with
    // the wrong type kept their defaults and are not reported twice).
    for (FieldError& e : validate(scenario)) errors.push_back(std::move(e));
    if (!errors.empty()) throw ScenarioError(std::move(errors));
    return scenario;
}

std::string scenario_to_json(const Scenario& scenario) {
    Json root = Json::object();
    for (const char* section : {"machine", "probe", "cycle"}) {
        Json body = Json::object();
        for (const std::string& name : section_keys(section)) {
            const std::string dotted = std::string(section) + "." + name;
            if (const NumericKey* k = find_numeric(dotted)) {
                body[name] = *get_number(scenario, k->info.key);
            } else if (dotted == "machine.accel_model") {
                body[name] = to_string(scenario.machine.accel_model);
            } else if (dotted == "machine.latched_input") {
                body[name] = scenario.machine.latched_input;
            } else if (dotted == "cycle.strategy") {
                body[name] = to_string(scenario.cycle.strategy);
            } else if (dotted == "cycle.feature") {
                body[name] = to_string(scenario.cycle.feature);
            }
        }
        root[section] = std::move(body);
    }
    return root.dump(2) + "\n";
}

void apply_setting(Scenario& scenario, std::string_view assignment) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        throw ScenarioError({{std::string(assignment), "",
                              allowed_text("not_an_assignment",
                                           QT_TRANSLATE_NOOP("FieldError", "section.key=value"))}});
    }
    const std::string key(assignment.substr(0, eq));
    const std::string value(assignment.substr(eq + 1));
    if (const NumericKey* k = find_numeric(key)) {
        // Strict: the whole text is a finite number (strtod also reads "nan", "inf").
        errno = 0;
        char* end = nullptr;
        const double number = std::strtod(value.c_str(), &end);
        if (value.empty() || end != value.c_str() + value.size() || errno == ERANGE ||
            !std::isfinite(number)) {
            throw ScenarioError({{key, value.empty() ? "nothing" : value, range_text(k->info)}});
        }
        k->ref(scenario) = number;
    } else if (const char* words = enum_allowed(key)) {
        if (!set_enum(scenario, key, value)) throw ScenarioError({{key, value, one_of(words)}});
    } else if (key == "machine.latched_input") {
        if (value == "true") {
            scenario.machine.latched_input = true;
        } else if (value == "false") {
            scenario.machine.latched_input = false;
        } else {
            throw ScenarioError({{key, value, bool_words()}});
        }
    } else {
        const std::size_t dot = key.find('.');
        const std::string section = dot == std::string::npos ? key : key.substr(0, dot);
        const std::vector<std::string>& keys = section_keys(section);
        throw ScenarioError(
            {{key, "",
              keys.empty() ? allowed_text("unknown_key",
                                          QT_TRANSLATE_NOOP("FieldError",
                                                            "unknown key; sections are machine, "
                                                            "probe, cycle"))
                           : unknown_key(section, join(keys))}});
    }
}

const char* to_string(Strategy strategy) {
    return strategy == Strategy::single_touch ? "single_touch" : "two_touch";
}

const char* to_string(Feature feature) {
    switch (feature) {
        case Feature::surface:
            return "surface";
        case Feature::web:
            return "web";
        case Feature::pocket:
            return "pocket";
        case Feature::bore:
            return "bore";
        case Feature::boss:
            return "boss";
    }
    return "?";
}

std::optional<Strategy> strategy_from_string(std::string_view word) {
    if (word == "single_touch") return Strategy::single_touch;
    if (word == "two_touch") return Strategy::two_touch;
    return std::nullopt;
}

std::optional<Feature> feature_from_string(std::string_view word) {
    for (Feature f :
         {Feature::surface, Feature::web, Feature::pocket, Feature::bore, Feature::boss}) {
        if (word == to_string(f)) return f;
    }
    return std::nullopt;
}

std::optional<AccelModel> accel_model_from_string(std::string_view word) {
    for (AccelModel m :
         {AccelModel::time_constant, AccelModel::constant_accel, AccelModel::jerk_limited}) {
        if (word == to_string(m)) return m;
    }
    return std::nullopt;
}

}  // namespace probecycle
