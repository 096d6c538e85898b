#include "core/program/cycle_import.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"
#include "core/common/number_format.h"

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

Message import_message(const char* code, const char* text, std::vector<MessageArg> args = {}) {
    return Message{code, "MachineLog", text, std::move(args)};
}

// The program's figures in the order of its result line.
std::array<double, 5> expected_values(const FeatureResult& result) {
    return {result.size_mm, result.centre_mm[0].value_or(0.0), result.centre_mm[1].value_or(0.0),
            result.deviation_mm, result.out_of_tolerance ? 1.0 : 0.0};
}

// The program computed from the same touches: its figures must be the
// import's, or the program was not written from this plan (or was edited).
void check_logged(const CycleImport& import, DialectId dialect) {
    const LoggedResult& logged = import.logged;
    if (logged.line == 0) return;
    static constexpr std::array<const char*, 5> kNames = {"S", "X", "Y", "D", "T"};
    const std::array<double, 5> expected = expected_values(import.result);
    const double tolerance = logged_result_tolerance_mm(dialect);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (std::abs(logged.values[i] - expected[i]) <= tolerance) continue;
        throw CsvError(
            logged.line, "",
            import_message(
                "log_result_mismatch",
                QT_TRANSLATE_NOOP("MachineLog",
                                  "the program's result line gives %1 %2, its touches "
                                  "give %3: was the program edited, or written from "
                                  "another plan? Nothing imported"),
                {text_arg("name", kNames[i]), text_arg("logged", format_fixed(logged.values[i], 6)),
                 text_arg("computed", format_fixed(expected[i], 6))}));
    }
}

// 4 decimals (0.1 um) whatever the locale, never "-0.0000".
std::string mm(double value) {
    return format_decimals(value, 4) + " mm";
}

std::string signed_mm(double value) {
    std::string text(value >= 0.0 ? "+" : "");
    text += mm(value);
    return text;
}

}  // namespace

double logged_result_tolerance_mm(DialectId dialect) {
    // The dialect's (Dialect::result_tolerance_mm): 1e-5 mm for LinuxCNC's 6
    // decimals, 2e-4 for DPRNT's 4.
    return probecycle::dialect(dialect).result_tolerance_mm;
}

CycleImport import_cycle_log(const ProbingPlan& plan, DialectId dialect, std::string_view text) {
    const std::optional<ResultSpec> spec = result_spec(plan);
    if (!spec) {
        throw InputError(import_message(
            "log_not_cycle_plan",
            QT_TRANSLATE_NOOP("MachineLog",
                              "a %1 plan has no feature result: its import is the lab's CSV"),
            {text_arg("kind", to_string(plan.kind))}));
    }
    CycleImport import;
    import.plan_id = plan_id(plan);
    import.spec = *spec;
    import.touches = recorded_touch_positions(plan, dialect, text, import.logged);
    std::vector<std::array<double, 3>> xyz;
    for (const RecordedPosition& touch : import.touches) xyz.push_back(touch.xyz);
    import.result = feature_result(import.spec, xyz);
    check_logged(import, dialect);
    return import;
}

std::string cycle_import_text(const CycleImport& import) {
    const ResultSpec& spec = import.spec;
    const FeatureResult& r = import.result;
    const bool surface = r.feature == Feature::surface;
    const std::size_t touches = import.touches.size();
    std::string text = "plan " + import.plan_id + " (cycle, " + to_string(r.feature) +
                       "): " + std::to_string(touches) +
                       (touches == 1 ? " recorded touch\n" : " recorded touches\n");
    text += size_name(r.feature) + (surface ? " along " + to_string(spec.sides[0]) : "") + ": " +
            mm(r.size_mm) + " +- " + mm(r.size_uncertainty_mm) + " (k = 2)\n";
    for (std::size_t axis = 0; axis < 2; ++axis) {
        if (!r.centre_mm[axis]) continue;
        text += std::string("centre ") + "XY"[axis] + ": " + mm(*r.centre_mm[axis]) + " +- " +
                mm(r.centre_uncertainty_mm) + " (k = 2)\n";
    }
    text += "effective ball diameter: " + mm(spec.ball_diameter_mm);
    if (!surface) text += "; between stylus centres: " + mm(r.centre_distance_mm);
    text += "\n";
    text += "each point +- " + mm(r.point_uncertainty_mm) +
            " (k = 2, the model's budget: scan phase, repeatability, lobing, calibration "
            "artefact, machine repeatability, thermal drift; not the machine's geometry)\n";
    text += "sides (mean stylus-centre coordinate):";
    for (std::size_t s = 0; s < spec.sides.size(); ++s) {
        text += (s == 0 ? " " : ", ") + to_string(spec.sides[s]) + " " + mm(r.side_mm[s]);
    }
    text += "\n";
    if (r.checked) {
        text += "tolerance: nominal " + mm(spec.nominal_size_mm()) + " +- " +
                mm(spec.size_tolerance_mm) + ", deviation " + signed_mm(r.deviation_mm) + ": " +
                (r.out_of_tolerance ? std::string("OUT OF TOLERANCE") +
                                          (spec.tolerance_action == ToleranceAction::stop
                                               ? " (the program stops)"
                                               : " (the program flags it)")
                                    : std::string("in tolerance")) +
                "\n";
    } else if (!surface) {
        text += "deviation from the nominal " + mm(spec.nominal_size_mm()) + ": " +
                signed_mm(r.deviation_mm) + " (no tolerance check)\n";
    }
    text += import.logged.line > 0 ? "the program's own result (line " +
                                         std::to_string(import.logged.line) + ") agrees\n"
                                   : std::string("the log holds no result of the program's own\n");
    return text;
}

std::string cycle_import_json(const CycleImport& import) {
    const ResultSpec& spec = import.spec;
    const FeatureResult& r = import.result;
    Json root = Json::object();
    root["format"] = "probecycle-feature-result";
    root["version"] = 1;
    root["plan"] = import.plan_id;
    root["feature"] = to_string(r.feature);
    root["touches"] = import.touches.size();
    root["ball_diameter_mm"] = spec.ball_diameter_mm;
    root["point_uncertainty_mm"] = r.point_uncertainty_mm;
    if (r.feature == Feature::surface) {
        root["axis"] = to_string(spec.sides[0]);
        root["position_mm"] = r.size_mm;
        root["position_uncertainty_mm"] = r.size_uncertainty_mm;
    } else {
        root["size_mm"] = r.size_mm;
        root["size_uncertainty_mm"] = r.size_uncertainty_mm;
        root["centre_distance_mm"] = r.centre_distance_mm;
        for (std::size_t axis = 0; axis < 2; ++axis) {
            if (r.centre_mm[axis]) {
                root[axis == 0 ? "centre_x_mm" : "centre_y_mm"] = *r.centre_mm[axis];
            }
        }
        root["centre_uncertainty_mm"] = r.centre_uncertainty_mm;
        root["nominal_size_mm"] = spec.nominal_size_mm();
        root["deviation_mm"] = r.deviation_mm;
    }
    Json sides = Json::array();
    for (std::size_t s = 0; s < spec.sides.size(); ++s) {
        sides.push_back({{"side", to_string(spec.sides[s])}, {"mean_mm", r.side_mm[s]}});
    }
    root["sides"] = std::move(sides);
    if (r.checked) {
        root["tolerance"] = {{"tolerance_mm", spec.size_tolerance_mm},
                             {"action", to_string(spec.tolerance_action)},
                             {"out_of_tolerance", r.out_of_tolerance}};
    } else {
        root["tolerance"] = nullptr;
    }
    root["program_result_line"] = import.logged.line > 0 ? Json(import.logged.line) : Json(nullptr);
    return root.dump(2) + "\n";
}

}  // namespace probecycle
