#include "core/program/feature_result.h"

#include <cmath>
#include <string_view>

#include "core/common/input_error.h"
#include "core/common/number_format.h"
#include "core/cycle/cycle.h"

namespace probecycle {

namespace {

Message result_message(const char* code, const char* text, std::vector<MessageArg> args = {}) {
    return Message{code, "MachineLog", text, std::move(args)};
}

const PlanValue* find_value(const ProbingPlan& plan, std::string_view key) {
    for (const PlanValue& value : plan.values) {
        if (value.key == key) return &value;
    }
    return nullptr;
}

[[noreturn]] void unreadable_value(std::string_view key) {
    throw InputError(result_message(
        "result_plan_value",
        QT_TRANSLATE_NOOP("MachineLog",
                          "the cycle plan has no readable value %1: write the program and its "
                          "plan again with this version of ProbeCycle"),
        {text_arg("key", std::string(key))}));
}

// A number the plan holds; `fallback` when it does not and one is given.
double plan_number(const ProbingPlan& plan, std::string_view key, std::optional<double> fallback) {
    const PlanValue* value = find_value(plan, key);
    if (value == nullptr) {
        if (fallback) return *fallback;
        unreadable_value(key);
    }
    const std::optional<double> number = parse_decimal(value->text);
    if (!number) unreadable_value(key);
    return *number;
}

[[noreturn]] void sides_do_not_match(Feature feature) {
    throw InputError(result_message(
        "result_plan_sides",
        QT_TRANSLATE_NOOP("MachineLog",
                          "the cycle plan's recorded touches do not make the sides of its %1: "
                          "was the plan file edited?"),
        {feature_arg("feature", feature)}));
}

}  // namespace

double size_with_ball_mm(Feature feature, double centre_distance_mm, double ball_diameter_mm) {
    switch (feature) {
        case Feature::pocket:
        case Feature::bore:
            return centre_distance_mm + ball_diameter_mm;
        case Feature::web:
        case Feature::boss:
            return centre_distance_mm - ball_diameter_mm;
        case Feature::surface:
            break;
    }
    return 0.0;
}

double ResultSpec::nominal_size_mm() const {
    return size_with_ball_mm(feature, nominal_mm, ball_diameter_mm);
}

std::optional<ResultSpec> result_spec(const ProbingPlan& plan) {
    if (plan.kind != ProgramKind::cycle) return std::nullopt;
    ResultSpec spec;
    if (const PlanValue* feature = find_value(plan, "cycle.feature")) {
        const std::optional<Feature> read = feature_from_string(feature->text);
        if (!read) unreadable_value("cycle.feature");
        spec.feature = *read;
    }
    if (spec.feature != Feature::surface) {
        spec.nominal_mm = plan_number(plan, "cycle.feature_size_mm", std::nullopt);
    }
    spec.ball_diameter_mm = plan_number(plan, kBallDiameterValue, 0.0);
    spec.point_uncertainty_mm = plan_number(plan, kPointUncertaintyValue, std::nullopt);
    spec.independent_uncertainty_mm =
        plan_number(plan, kIndependentUncertaintyValue, spec.point_uncertainty_mm);
    spec.artefact_uncertainty_mm = plan_number(plan, "probe.artefact_uncertainty_mm", 0.0);
    spec.thermal_drift_mm = plan_number(plan, "machine.thermal_drift_mm", 0.0);
    spec.size_tolerance_mm = plan_number(plan, "cycle.size_tolerance_mm", 0.0);
    if (const PlanValue* action = find_value(plan, "cycle.tolerance_action")) {
        const std::optional<ToleranceAction> read = tolerance_action_from_string(action->text);
        if (!read) unreadable_value("cycle.tolerance_action");
        spec.tolerance_action = *read;
    }
    // A boss's or web's side is touched toward the centre: against its
    // direction of travel.
    const bool outside = lifts_over(spec.feature);
    for (const ProgramStep* step : plan.recorded()) {
        const AxisDirection side{step->axis, outside ? -step->direction : step->direction};
        std::size_t index = 0;
        while (index < spec.sides.size() && (spec.sides[index].axis != side.axis ||
                                             spec.sides[index].direction != side.direction)) {
            ++index;
        }
        if (index == spec.sides.size()) spec.sides.push_back(side);
        spec.touch_side.push_back(index);
    }
    // The sides the formulas take: one for a surface; + and - along one axis;
    // X+, X-, Y+, Y-.
    const auto is = [&spec](std::size_t i, char axis, int direction) {
        return spec.sides[i].axis == axis && spec.sides[i].direction == direction;
    };
    bool matches = false;
    switch (spec.feature) {
        case Feature::surface:
            matches = spec.sides.size() == 1;
            break;
        case Feature::pocket:
        case Feature::web:
            matches = spec.sides.size() == 2 && spec.sides[0].axis != 'Z' &&
                      is(0, spec.sides[0].axis, 1) && is(1, spec.sides[0].axis, -1);
            break;
        case Feature::bore:
        case Feature::boss:
            matches = spec.sides.size() == 4 && is(0, 'X', 1) && is(1, 'X', -1) && is(2, 'Y', 1) &&
                      is(3, 'Y', -1);
            break;
    }
    if (!matches) sides_do_not_match(spec.feature);
    return spec;
}

// Uncertainties (docs/programs.md, "What the cycle program measures"). Each
// point's expanded uncertainty U (k = 2) is the model's whole budget
// (core/cycle/uncertainty.h). Its terms that differ from touch to touch, U_i
// (the trigger's, lobing, the machine's repeatability), are independent between
// the points; for a linear combination y = sum c_i x_i,
// u(y)^2 = sum c_i^2 u_i^2 (GUM, eq. 10):
// - a width x1 - x2: u^2 (1 + 1), sqrt(2) U_i;
// - a centre (x1 + x2)/2: u^2 (1/4 + 1/4), U_i / sqrt(2);
// - a bore's or boss's diameter, the mean of two widths
//   ((x1 - x2) + (y1 - y2))/2: u^2 (4 x 1/4), U_i.
// The two shared terms are fully correlated between the points, and each
// enters one kind of result only: the calibration artefact's error is the
// ball's effective size, outward on every point, so a size carries the
// certificate's U_a whole (the size is compared with the artefact's) and a
// centre none of it; the thermal drift moves every point alike (a half-width
// a, U_t = 2 a / sqrt(3)), so a centre carries U_t whole and a size none.
// A surface's position is one point: its whole U.
double size_uncertainty_mm(const ResultSpec& spec) {
    const double independent = spec.independent_uncertainty_mm;
    switch (spec.feature) {
        case Feature::surface:
            return spec.point_uncertainty_mm;
        case Feature::web:
        case Feature::pocket:
            return std::hypot(std::sqrt(2.0) * independent, spec.artefact_uncertainty_mm);
        case Feature::bore:
        case Feature::boss:
            break;
    }
    return std::hypot(independent, spec.artefact_uncertainty_mm);
}

double centre_uncertainty_mm(const ResultSpec& spec) {
    return std::hypot(spec.independent_uncertainty_mm / std::sqrt(2.0),
                      2.0 * spec.thermal_drift_mm / std::sqrt(3.0));
}

FeatureResult feature_result(const ResultSpec& spec,
                             const std::vector<std::array<double, 3>>& touches) {
    FeatureResult result;
    result.feature = spec.feature;
    std::vector<double> sum(spec.sides.size(), 0.0);
    std::vector<int> count(spec.sides.size(), 0);
    for (std::size_t i = 0; i < touches.size() && i < spec.touch_side.size(); ++i) {
        const std::size_t side = spec.touch_side[i];
        const char axis = spec.sides[side].axis;
        sum[side] += touches[i][axis == 'X' ? 0 : axis == 'Y' ? 1 : 2];
        ++count[side];
    }
    for (std::size_t s = 0; s < sum.size(); ++s) {
        result.side_mm.push_back(count[s] > 0 ? sum[s] / count[s] : 0.0);
    }
    const std::vector<double>& p = result.side_mm;
    switch (spec.feature) {
        case Feature::surface:
            result.size_mm = p[0] + spec.sides[0].direction * 0.5 * spec.ball_diameter_mm;
            break;
        case Feature::pocket:
        case Feature::web:
            result.centre_distance_mm = p[0] - p[1];
            result.centre_mm[spec.sides[0].axis == 'X' ? 0 : 1] = 0.5 * (p[0] + p[1]);
            break;
        case Feature::bore:
        case Feature::boss:
            result.centre_distance_mm = 0.5 * ((p[0] - p[1]) + (p[2] - p[3]));
            result.centre_mm = {0.5 * (p[0] + p[1]), 0.5 * (p[2] + p[3])};
            break;
    }
    if (spec.feature != Feature::surface) {
        result.size_mm =
            size_with_ball_mm(spec.feature, result.centre_distance_mm, spec.ball_diameter_mm);
        result.deviation_mm = result.size_mm - spec.nominal_size_mm();
    }
    result.point_uncertainty_mm = spec.point_uncertainty_mm;
    result.size_uncertainty_mm = size_uncertainty_mm(spec);
    result.centre_uncertainty_mm = centre_uncertainty_mm(spec);
    result.checked = spec.checks_tolerance();
    result.out_of_tolerance =
        result.checked && std::abs(result.deviation_mm) > spec.size_tolerance_mm;
    return result;
}

std::string size_name(Feature feature) {
    switch (feature) {
        case Feature::surface:
            return "surface position";
        case Feature::web:
            return "web width";
        case Feature::pocket:
            return "pocket width";
        case Feature::bore:
            return "bore diameter";
        case Feature::boss:
            return "boss diameter";
    }
    return "size";
}

}  // namespace probecycle
