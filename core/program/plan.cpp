#include "core/program/plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/common/input_error.h"
#include "core/common/json_guard.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/uncertainty.h"
#include "core/program/feature_result.h"

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "probecycle-probing-plan";
constexpr int kVersion = 1;
constexpr std::size_t kMaxDepth = 3;  // root > steps > step
// Distances in a program are written to 1 µm; the plan holds them so rounded
// (up, where more room is the safe side), so that the program and the plan
// agree to the digit.
constexpr double kStep_mm = 0.001;
Message program_message(const char* code, const char* text, std::vector<MessageArg> args) {
    return Message{code, "Program", text, std::move(args)};
}

// How far a touch at `feed_mm_min` that stops `overtravel_mm` past its
// surface searches past the farthest place that surface can be: the model's
// (search_beyond_mm, cycle.h). Every probing move is that far past the
// farthest surface, so the control never brakes for the move's end before the
// touch has stopped where the model puts it. InputError when
// cycle.search_beyond_mm is set and does not reach the stop.
double checked_search_beyond_mm(const Scenario& scenario, double feed_mm_min,
                                double overtravel_mm) {
    const double set = scenario.cycle.search_beyond_mm;
    if (set > 0.0 && set < overtravel_mm) {
        Message allowed = allowed_text(
            "program_search_beyond",
            QT_TRANSLATE_NOOP("FieldError",
                              "at least %1, the stop of the touch at %2 past its surface (a "
                              "search that ends sooner is braking when it touches), or 0 for "
                              "automatic"));
        allowed.args = {significant_arg("stop_mm", ArgKind::length_mm, overtravel_mm, 4),
                        arg("feed_mm_min", ArgKind::feed_mm_min, feed_mm_min)};
        throw InputError(
            FieldError{"cycle.search_beyond_mm", format_number(set), std::move(allowed)}
                .to_message());
    }
    return search_beyond_mm(scenario, overtravel_mm);
}

// The model's single touch at `feed_mm_min` from `approach_mm`.
CycleResult single_touch(const Scenario& scenario, double feed_mm_min, double approach_mm) {
    Scenario s = scenario;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.feature = Feature::surface;
    s.cycle.probe_feed_mm_min = feed_mm_min;
    s.cycle.approach_mm = approach_mm;
    return evaluate(s);
}

// A touch's stop past its surface, worst case, as the model predicts it: at
// the programmed feed (what the program's moves back from the stop count on)
// and at up to the highest feed override (what the stylus must survive and
// the search must reach past).
struct TouchStops {
    double at_feed_mm{0.0};
    double at_override_mm{0.0};
};

// InputError when the stop at the override reaches the probe's limit (the
// stylus would be overrun).
void check_overtravel(const Scenario& scenario, double feed_mm_min, double overtravel_mm) {
    if (overtravel_mm < scenario.probe.overtravel_limit_mm) return;
    throw InputError(program_message(
        "program_overtravel",
        QT_TRANSLATE_NOOP("Program",
                          "at %1 and up to %4 % feed override the model's overtravel is %2, at "
                          "or over the probe's limit %3: lower the feed (or "
                          "cycle.feed_override_max_pct) or check the scenario"),
        {arg("feed_mm_min", ArgKind::feed_mm_min, feed_mm_min),
         significant_arg("overtravel_mm", ArgKind::length_mm, overtravel_mm, 4),
         arg("limit_mm", ArgKind::length_mm, scenario.probe.overtravel_limit_mm),
         arg("feed_override_pct", ArgKind::number, scenario.cycle.feed_override_max_pct, 0)}));
}

// The stops of a single touch at a feed from `approach_mm`, checked.
TouchStops checked_stops(const Scenario& scenario, double feed_mm_min, double approach_mm) {
    const TouchResult touch = single_touch(scenario, feed_mm_min, approach_mm).first_touch();
    check_overtravel(scenario, feed_mm_min, touch.override_overtravel_mm);
    return {touch.overtravel_mm, touch.override_overtravel_mm};
}

void add_values(ProbingPlan& plan, const Scenario& scenario,
                std::initializer_list<const char*> keys) {
    for (const char* key : keys) {
        if (const KeyInfo* info = find_any_key(key)) {
            plan.values.push_back({key, value_text(scenario, *info)});
        }
    }
}

void add_value(ProbingPlan& plan, const char* key, double value) {
    plan.values.push_back({key, format_exact(value)});
}

// Keys every plan names: what decides the start distances and the overtravel.
void add_machine_values(ProbingPlan& plan, const Scenario& scenario) {
    add_values(plan, scenario,
               {"machine.accel_model", "machine.time_constant_s", "machine.max_accel_mm_s2",
                "machine.max_jerk_mm_s3", "machine.filter", "machine.filter_time_s",
                "machine.servo_time_constant_s", "machine.scan_period_s",
                "machine.controller_latency_s", "probe.interface_delay_s", "probe.pretravel_mm",
                "probe.overtravel_limit_mm", "cycle.feed_override_max_pct"});
}

// A step that moves along `along` (distance and feed as given).
ProgramStep motion_step(StepKind kind, const AxisDirection& along, double distance_mm,
                        double feed_mm_min, std::string text) {
    ProgramStep step;
    step.kind = kind;
    step.axis = along.axis;
    step.direction = along.direction;
    step.distance_mm = distance_mm;
    step.feed_mm_min = feed_mm_min;
    step.text = std::move(text);
    return step;
}

ProgramStep probe_step(const AxisDirection& at, double distance_mm, double feed_mm_min,
                       bool recorded, std::string text) {
    ProgramStep step = motion_step(StepKind::probe, at, round_up_to(distance_mm, kStep_mm),
                                   feed_mm_min, std::move(text));
    step.recorded = recorded;
    return step;
}

AxisDirection opposite(const AxisDirection& at) {
    return {at.axis, -at.direction};
}

// A move away from the surface touched from `at` (feed 0: rapid).
ProgramStep move_back(const AxisDirection& at, double distance_mm, double feed_mm_min,
                      std::string text) {
    return motion_step(StepKind::move, opposite(at), round_up_to(distance_mm, kStep_mm),
                       feed_mm_min, std::move(text));
}

// A protected move along `along` (the probe armed, a move that must not trigger).
ProgramStep guard_step(const AxisDirection& along, double distance_mm, double feed_mm_min,
                       std::string text) {
    return motion_step(StepKind::guard, along, distance_mm, feed_mm_min, std::move(text));
}

// A plain move along `along` (feed 0: rapid).
ProgramStep move_step(const AxisDirection& along, double distance_mm, double feed_mm_min,
                      std::string text) {
    return motion_step(StepKind::move, along, distance_mm, feed_mm_min, std::move(text));
}

ProgramStep pause_step(std::string text) {
    ProgramStep step;
    step.kind = StepKind::pause;
    step.text = std::move(text);
    return step;
}

std::string mm_text(double value) {
    return format_fixed(value, 3) + " mm";
}

std::string feed_text(double feed_mm_min) {
    return format_number(feed_mm_min) + " mm/min";
}

// " 2 of 3" for the k-th of `repeats` measuring touches, "" for one.
std::string repeat_text(int k, int repeats) {
    if (repeats <= 1) return {};
    // (Appended piece by piece: g++ 12 warns falsely of an overlapping
    // memcpy in " " + std::to_string(k).)
    std::string text(" ");
    text += std::to_string(k);
    text += " of ";
    text += std::to_string(repeats);
    return text;
}

// One point touched with the scenario's strategy from `distance_mm` before the
// nominal surface, which may lie up to `uncertainty_mm` farther, then back to
// `distance_mm` before it (its recorded probes carry `orientation_deg`).
// Single-touch: a recorded touch at the probing feed. Two-touch: a fast
// touch, the backoff, the measuring touch (recorded). The measuring touch is
// made `repeats` times, as the model averages them (cycle.repeats):
// single-touch back to the start and again; two-touch backed off from where
// the measuring touch stopped and again at the measuring feed.
// Every search ends checked_search_beyond_mm() past the farthest place its
// surface can be: the first past the nominal surface plus the uncertainty;
// every later one past where the touch before stopped, so it covers the whole
// move back from there (the backoff, or the return of a single-touch repeat)
// even where the real overtravel differs from the model's.
void add_point(ProbingPlan& plan, const Scenario& scenario, const AxisDirection& at,
               double distance_mm, double uncertainty_mm, double orientation_deg,
               const std::string& back_to, int repeats) {
    const Cycle& c = scenario.cycle;
    const std::string name = to_string(at);
    if (c.strategy == Strategy::single_touch) {
        const TouchStops stops = checked_stops(scenario, c.probe_feed_mm_min, distance_mm);
        const double beyond =
            checked_search_beyond_mm(scenario, c.probe_feed_mm_min, stops.at_override_mm);
        const double back = distance_mm + stops.at_feed_mm;
        for (int k = 1; k <= repeats; ++k) {
            // A repeat starts where the first did, from where it stopped.
            const double farthest =
                k == 1 ? distance_mm + uncertainty_mm : round_up_to(back, kStep_mm);
            plan.steps.push_back(probe_step(
                at, farthest + beyond, c.probe_feed_mm_min, true,
                name + repeat_text(k, repeats) + " at " + feed_text(c.probe_feed_mm_min)));
            plan.steps.back().orientation_deg = orientation_deg;
            plan.steps.push_back(
                move_back(at, back, c.return_feed_mm_min, "back to the " + back_to));
        }
        return;
    }
    Scenario s = scenario;
    s.cycle.feature = Feature::surface;
    s.cycle.approach_mm = distance_mm;
    const CycleResult result = evaluate(s);
    for (const TouchResult* touch : {&result.first_touch(), &result.measuring_touch()}) {
        check_overtravel(scenario, mm_s_to_mm_min(touch->programmed_feed_mm_s),
                         touch->override_overtravel_mm);
    }
    const double first_overtravel = result.first_touch().overtravel_mm;
    // The backoff must clear the stop at the highest feed override too.
    const double first_stop = result.first_touch().override_overtravel_mm;
    // G38.2 leaves the probe where it stopped. A backoff measured from the
    // recorded trigger (cycle.backoff_from) is longer by the stop's distance
    // from it, which the model predicts.
    double backoff = c.backoff_mm;
    if (c.backoff_from == BackoffFrom::trigger) {
        backoff += std::max(0.0, first_overtravel - result.first_touch().recorded_mm);
    }
    if (backoff <= first_stop) {
        throw InputError(program_message(
            "program_backoff",
            QT_TRANSLATE_NOOP("Program",
                              "the backoff %1 does not clear the first touch's overtravel %2: set "
                              "cycle.backoff_mm to at least %3 (the recommended backoff)"),
            {arg("backoff_mm", ArgKind::length_mm, backoff),
             significant_arg("overtravel_mm", ArgKind::length_mm, first_stop, 4),
             arg("recommended_mm", ArgKind::length_mm, result.recommended_backoff_mm())}));
    }
    const TouchResult& measuring = result.measuring_touch();
    const double first_beyond = checked_search_beyond_mm(scenario, c.probe_feed_mm_min, first_stop);
    const double measuring_beyond =
        checked_search_beyond_mm(scenario, c.measure_feed_mm_min, measuring.override_overtravel_mm);
    plan.steps.push_back(probe_step(at, distance_mm + uncertainty_mm + first_beyond,
                                    c.probe_feed_mm_min, false,
                                    name + " first touch at " + feed_text(c.probe_feed_mm_min)));
    plan.steps.push_back(move_back(at, backoff, c.return_feed_mm_min, "backoff"));
    // From the backoff's end the surface lies at most the backoff away (the
    // probe stopped past it).
    plan.steps.push_back(probe_step(at, round_up_to(backoff, kStep_mm) + measuring_beyond,
                                    c.measure_feed_mm_min, true,
                                    name + " measuring touch" + repeat_text(1, repeats) + " at " +
                                        feed_text(c.measure_feed_mm_min)));
    plan.steps.back().orientation_deg = orientation_deg;
    double last_overtravel = measuring.overtravel_mm;
    if (repeats > 1) {
        // The model's repeat (cycle.cpp): from the measuring touch's stop the
        // backoff (longer by the stop's distance from the recorded trigger when
        // the backoff is measured from the trigger), then the measuring touch
        // from the backoff less its reference in front of the surface.
        double repeat_backoff = c.backoff_mm;
        if (c.backoff_from == BackoffFrom::trigger) {
            repeat_backoff += std::max(0.0, measuring.overtravel_mm - measuring.recorded_mm);
        }
        const double repeat_distance = repeat_backoff - measuring.overtravel_mm;
        const TouchStops repeat_stops =
            checked_stops(scenario, c.measure_feed_mm_min, repeat_distance);
        last_overtravel = repeat_stops.at_feed_mm;
        const double repeat_beyond =
            checked_search_beyond_mm(scenario, c.measure_feed_mm_min, repeat_stops.at_override_mm);
        for (int k = 2; k <= repeats; ++k) {
            plan.steps.push_back(move_back(at, repeat_backoff, c.return_feed_mm_min, "backoff"));
            plan.steps.push_back(probe_step(at,
                                            round_up_to(repeat_backoff, kStep_mm) + repeat_beyond,
                                            c.measure_feed_mm_min, true,
                                            name + " measuring touch" + repeat_text(k, repeats) +
                                                " at " + feed_text(c.measure_feed_mm_min)));
            plan.steps.back().orientation_deg = orientation_deg;
        }
    }
    plan.steps.push_back(move_back(at, distance_mm + last_overtravel, c.return_feed_mm_min,
                                   "back to the " + back_to));
}

// The feature's touch points, by the side of the centre they lie on (the
// model's order, cycle.h): a bore or boss X+, X-, Y+, Y-; a pocket or web both
// sides along the chosen axis, + first.
std::vector<AxisDirection> feature_sides(Feature feature, char axis) {
    if (feature == Feature::bore || feature == Feature::boss) {
        return {{'X', 1}, {'X', -1}, {'Y', 1}, {'Y', -1}};
    }
    return {{axis, 1}, {axis, -1}};
}

// Refuses what a feature's program cannot do: a pocket or web along Z, a boss
// or web without a clearance to move over its wall, moves from the centre
// longer than a plan holds.
void check_feature_plan(const Scenario& scenario, const CyclePlanOptions& options) {
    const Cycle& c = scenario.cycle;
    // A protected move that meets an obstruction stops as a touch at the
    // positioning feed would: the stylus must survive it.
    const double guard = protected_move_overtravel_mm(scenario, c.position_feed_mm_min / 60.0);
    if (guard >= scenario.probe.overtravel_limit_mm) {
        Message allowed = allowed_text(
            "program_position_feed",
            QT_TRANSLATE_NOOP("FieldError",
                              "a feed at which an obstruction met by a protected move stops "
                              "short of the probe's %1 limit (now %2 past it)"));
        allowed.args = {arg("limit_mm", ArgKind::length_mm, scenario.probe.overtravel_limit_mm, 3),
                        significant_arg("overtravel_mm", ArgKind::length_mm, guard, 4)};
        throw InputError(FieldError{"cycle.position_feed_mm_min",
                                    format_number(c.position_feed_mm_min), std::move(allowed)}
                             .to_message());
    }
    if ((c.feature == Feature::pocket || c.feature == Feature::web) && options.touch.axis == 'Z') {
        Message allowed = allowed_text(
            "program_feature_axis",
            QT_TRANSLATE_NOOP("FieldError",
                              "X+, X-, Y+ or Y- for a %1 (touched from both sides along X or Y)"));
        allowed.args = {feature_arg("feature", c.feature)};
        throw InputError(
            FieldError{"axis", to_string(options.touch), std::move(allowed)}.to_message());
    }
    if (lifts_over(c.feature) && round_up_to(c.clearance_mm, kStep_mm) < kStep_mm) {
        Message allowed = allowed_text(
            "program_clearance",
            QT_TRANSLATE_NOOP("FieldError",
                              "at least %1 for a %2 (the probe moves over its wall between "
                              "touches)"));
        allowed.args = {arg("min_mm", ArgKind::length_mm, kStep_mm),
                        feature_arg("feature", c.feature)};
        throw InputError(
            FieldError{"cycle.clearance_mm", format_number(c.clearance_mm), std::move(allowed)}
                .to_message());
    }
    if (start_radius_mm(c) > kMaxPlanDistance_mm) {
        // The largest size whose start radius is the plan's longest move.
        const double max_size = 2.0 * (lifts_over(c.feature) ? kMaxPlanDistance_mm - c.approach_mm
                                                             : kMaxPlanDistance_mm + c.approach_mm);
        Message allowed = allowed_text(
            "program_feature_size",
            QT_TRANSLATE_NOOP("FieldError",
                              "at most %1 for a %2's program (its moves from the centre to the "
                              "touches' starts are at most %3)"));
        allowed.args = {arg("max_mm", ArgKind::length_mm, max_size),
                        feature_arg("feature", c.feature),
                        arg("limit_mm", ArgKind::length_mm, kMaxPlanDistance_mm)};
        throw InputError(FieldError{"cycle.feature_size_mm", format_number(c.feature_size_mm),
                                    std::move(allowed)}
                             .to_message());
    }
}

// A feature's touches as the cycle model moves (cycle.h, start_radius_mm and
// lifts_over; cycle.cpp, evaluate_into), each with the scenario's strategy
// (add_point). Every move toward the part is a protected move at the
// positioning feed. A pocket or bore: from the centre at the measuring depth,
// out to each touch's start and back to the centre. A boss or web: from above
// the centre at the clearance height, per side out over its start, down by the
// clearance, the touch toward the centre, back to the start, up by the
// clearance at the rapid feed (away from the part, as the model lifts) and back
// over the centre. Unlike the model, which moves straight from start to start,
// the probe goes back through (or over) the centre between touches: every move
// runs along one axis, and the program ends where it started.
void add_feature_touches(ProbingPlan& plan, const Scenario& scenario,
                         const CyclePlanOptions& options) {
    const Cycle& c = scenario.cycle;
    const int repeats = repeat_count(scenario.cycle);
    const bool outside = lifts_over(c.feature);
    // Rounded to the programs' digits on the side that leaves more room to
    // the wall: inside, a start no nearer the wall than the model's; outside,
    // no nearer the side.
    const double radius = outside ? round_up_to(start_radius_mm(c), kStep_mm)
                                  : round_down_to(start_radius_mm(c), kStep_mm);
    const double clearance = round_up_to(c.clearance_mm, kStep_mm);
    const double feed = c.position_feed_mm_min;
    const AxisDirection down{'Z', -1};
    const std::string feature = to_string(c.feature);
    const std::string along = c.feature == Feature::pocket || c.feature == Feature::web
                                  ? std::string(" along ") + options.touch.axis
                                  : std::string();
    // The searches reach the part position uncertainty past each nominal
    // wall: how far off centre the probe may stand.
    const double uncertainty = c.part_position_uncertainty_mm;
    const std::string tolerance =
        uncertainty > 0.0 ? " (within " + mm_text(uncertainty) + ")" : std::string();
    plan.steps.push_back(
        pause_step(outside ? "check: the probe ball stands over the centre of the " + feature +
                                 along + tolerance + ", " + mm_text(clearance) +
                                 " above the measuring depth; resume to start"
                           : "check: the probe ball stands at the centre of the " + feature +
                                 along + tolerance + " at the measuring depth; resume to start"));
    for (const AxisDirection& side : feature_sides(c.feature, options.touch.axis)) {
        const std::string name = to_string(side);
        if (!outside) {
            // A start at the centre (a feature 2 approach distances wide, to
            // the micrometre) needs no move out.
            if (radius > 0.0) {
                plan.steps.push_back(
                    guard_step(side, radius, feed, "out to the start of the " + name + " touch"));
            }
            add_point(plan, scenario, side, c.approach_mm, uncertainty, 0.0, "start", repeats);
            if (radius > 0.0) {
                plan.steps.push_back(
                    guard_step(opposite(side), radius, feed, "back to the centre"));
            }
            continue;
        }
        plan.steps.push_back(
            guard_step(side, radius, feed, "out over the start of the " + name + " side"));
        plan.steps.push_back(guard_step(down, clearance, feed, "down to the measuring depth"));
        // The side faces away from the centre: it is touched toward it.
        add_point(plan, scenario, opposite(side), c.approach_mm, uncertainty, 0.0, "start",
                  repeats);
        plan.steps.push_back(move_step(opposite(down), clearance, 0.0, "up by the clearance"));
        plan.steps.push_back(guard_step(opposite(side), radius, feed, "back over the centre"));
    }
}

void check_range(double value, double min, double max, const char* key, const char* unit) {
    if (!(value >= min && value <= max)) {
        throw InputError(
            FieldError{key, format_number(value), range_allowed(min, max, unit)}.to_message());
    }
}

}  // namespace

const char* to_string(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::delay:
            return "delay";
        case ProgramKind::ring:
            return "ring";
        case ProgramKind::cycle:
            return "cycle";
    }
    return "delay";
}

std::optional<ProgramKind> program_kind_from_string(std::string_view word) {
    for (ProgramKind kind : {ProgramKind::delay, ProgramKind::ring, ProgramKind::cycle}) {
        if (word == to_string(kind)) return kind;
    }
    return std::nullopt;
}

std::vector<const ProgramStep*> ProbingPlan::recorded() const {
    std::vector<const ProgramStep*> out;
    for (const ProgramStep& step : steps) {
        if (step.kind == StepKind::probe && step.recorded) out.push_back(&step);
    }
    return out;
}

bool ProbingPlan::has_guards() const {
    return std::any_of(steps.begin(), steps.end(),
                       [](const ProgramStep& step) { return step.kind == StepKind::guard; });
}

std::optional<AxisDirection> axis_direction_from_string(std::string_view text) {
    if (text.size() != 2) return std::nullopt;
    const char axis = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    if (axis != 'X' && axis != 'Y' && axis != 'Z') return std::nullopt;
    if (text[1] != '+' && text[1] != '-') return std::nullopt;
    return AxisDirection{axis, text[1] == '+' ? 1 : -1};
}

std::string to_string(const AxisDirection& group) {
    return std::string(1, group.axis) + (group.direction > 0 ? "+" : "-");
}

std::vector<double> default_delay_feeds(const Scenario& scenario) {
    std::vector<double> feeds = {30.0, 100.0, 300.0, 1000.0, 2000.0};
    const double own = scenario.cycle.probe_feed_mm_min;
    if (std::find(feeds.begin(), feeds.end(), own) == feeds.end()) feeds.push_back(own);
    std::sort(feeds.begin(), feeds.end());
    return feeds;
}

ProbingPlan make_delay_plan(const Scenario& scenario, const DelayPlanOptions& options) {
    std::vector<double> feeds =
        options.feeds_mm_min.empty() ? default_delay_feeds(scenario) : options.feeds_mm_min;
    std::sort(feeds.begin(), feeds.end());
    feeds.erase(std::unique(feeds.begin(), feeds.end()), feeds.end());
    if (feeds.size() < 2 || feeds.size() > kMaxPlanFeeds) {
        Message allowed = allowed_text(
            "feed_count", QT_TRANSLATE_NOOP("FieldError", "from 2 to %1 different feeds"));
        allowed.args = {arg("max", ArgKind::integer, static_cast<double>(kMaxPlanFeeds))};
        std::string given;
        for (double feed : feeds) given += (given.empty() ? "" : ", ") + format_number(feed);
        throw InputError(FieldError{"feeds", given, std::move(allowed)}.to_message());
    }
    for (double feed : feeds) {
        check_range(feed, kMinPlanFeed_mm_min, kMaxPlanFeed_mm_min, "feeds", "mm/min");
    }
    check_range(options.repeats, 1, kMaxPlanRepeats, "repeats", "");
    check_range(options.margin_mm, 0.0, 100.0, "margin_mm", "mm");
    check_range(options.placement_mm, 0.1, kMaxPlanDistance_mm, "placement_mm", "mm");
    ProbingPlan plan;
    plan.kind = ProgramKind::delay;
    add_machine_values(plan, scenario);
    add_values(plan, scenario, {"cycle.probe_feed_mm_min"});
    add_value(plan, "repeats", options.repeats);
    add_value(plan, "margin_mm", options.margin_mm);
    add_value(plan, "placement_mm", options.placement_mm);

    // Start distance per feed: the room to reach it, plus the margin.
    std::vector<double> start_mm;
    std::vector<TouchStops> stops;
    for (double feed : feeds) {
        start_mm.push_back(
            round_up_to(approach_room_mm(scenario, feed / 60.0) + options.margin_mm, kStep_mm));
        stops.push_back(checked_stops(scenario, feed, start_mm.back()));
    }
    // Every search ends checked_search_beyond_mm() past the farthest place the
    // surface can be: the locating touch's past the placement, every later
    // one's past where the touch before stopped (the whole retract).
    std::vector<double> beyond_mm;
    for (std::size_t f = 0; f < feeds.size(); ++f) {
        beyond_mm.push_back(checked_search_beyond_mm(scenario, feeds[f], stops[f].at_override_mm));
    }
    {
        const AxisDirection& group = options.touch;
        const std::string name = to_string(group);
        plan.steps.push_back(
            pause_step("check: the probe stands in front of the surface, at most " +
                       mm_text(options.placement_mm) + " from it, touching along " + name +
                       "; resume to start"));
        const TouchStops locate = checked_stops(scenario, feeds.front(), options.placement_mm);
        plan.steps.push_back(
            probe_step(group,
                       options.placement_mm +
                           checked_search_beyond_mm(scenario, feeds.front(), locate.at_override_mm),
                       feeds.front(), false, "locate the surface at " + feed_text(feeds.front())));
        double stop_beyond = locate.at_feed_mm;  // where the previous touch left the probe
        for (std::size_t f = 0; f < feeds.size(); ++f) {
            for (int r = 0; r < options.repeats; ++r) {
                const double retract = start_mm[f] + stop_beyond;
                plan.steps.push_back(move_back(group, retract, 0.0,
                                               "to " + mm_text(start_mm[f]) +
                                                   " before the surface: room to reach " +
                                                   feed_text(feeds[f]) + " plus the margin"));
                plan.steps.push_back(
                    probe_step(group, round_up_to(retract, kStep_mm) + beyond_mm[f], feeds[f], true,
                               name + " at " + feed_text(feeds[f]) + ", " + std::to_string(r + 1) +
                                   " of " + std::to_string(options.repeats)));
                stop_beyond = stops[f].at_feed_mm;
            }
        }
        plan.steps.push_back(
            move_back(group, options.placement_mm + stop_beyond, 0.0, "clear of the surface"));
    }
    return plan;
}

ProbingPlan make_ring_plan(const Scenario& scenario, const RingPlanOptions& options) {
    check_range(options.gauge_diameter_mm, 0.1, 2000.0, "gauge_diameter_mm", "mm");
    check_range(options.ball_diameter_mm, 0.1, 100.0, "ball_diameter_mm", "mm");
    check_range(options.centre_tolerance_mm, 0.0, 100.0, "centre_tolerance_mm", "mm");
    const double to_wall = 0.5 * (options.gauge_diameter_mm - options.ball_diameter_mm);
    if (to_wall <= options.centre_tolerance_mm) {
        throw InputError(program_message(
            "program_gauge_small",
            QT_TRANSLATE_NOOP("Program",
                              "the gauge (%1) leaves the ball (%2) no more room than the centre "
                              "tolerance %3: a larger gauge or a smaller ball"),
            {arg("gauge_diameter_mm", ArgKind::length_mm, options.gauge_diameter_mm),
             arg("ball_diameter_mm", ArgKind::length_mm, options.ball_diameter_mm),
             arg("tolerance_mm", ArgKind::length_mm, options.centre_tolerance_mm)}));
    }
    ProbingPlan plan;
    plan.kind = ProgramKind::ring;
    add_machine_values(plan, scenario);
    add_values(plan, scenario,
               {"cycle.strategy", "cycle.probe_feed_mm_min", "cycle.measure_feed_mm_min",
                "cycle.backoff_mm", "cycle.backoff_from", "cycle.return_feed_mm_min"});
    add_value(plan, "gauge_diameter_mm", options.gauge_diameter_mm);
    add_value(plan, "ball_diameter_mm", options.ball_diameter_mm);
    add_value(plan, "centre_tolerance_mm", options.centre_tolerance_mm);
    for (double orientation : {0.0, 180.0}) {
        plan.steps.push_back(pause_step(
            orientation == 0.0
                ? "check: the spindle is oriented to 0 deg and the probe ball stands at the gauge "
                  "centre (within " +
                      mm_text(options.centre_tolerance_mm) +
                      ") at the measuring depth; resume to start"
                : std::string("turn the spindle to 180 deg; the probe stays at the gauge centre; "
                              "resume")));
        for (const AxisDirection at : {AxisDirection{'X', 1}, AxisDirection{'X', -1},
                                       AxisDirection{'Y', 1}, AxisDirection{'Y', -1}}) {
            // The probe may stand the tolerance off centre, so a touch may
            // need that much more; the return is measured from the wall, so
            // it lands on the centre whatever the start.
            // One measuring touch a point: the fit takes every point on its own.
            add_point(plan, scenario, at, to_wall, options.centre_tolerance_mm, orientation,
                      "centre", 1);
        }
    }
    return plan;
}

namespace {

// The values the feature's result needs (feature_result.h, result_spec); the
// uncertainty to the nanometre, the digits the programs' logs print.
void add_result_values(ProbingPlan& plan, const Scenario& scenario,
                       const CyclePlanOptions& options) {
    add_value(plan, kBallDiameterValue, options.ball_diameter_mm);
    const CycleResult model = evaluate(scenario);
    add_value(plan, kPointUncertaintyValue, std::round(model.uncertainty_mm() * 1e6) / 1e6);
    // How the point's budget splits between its points (a size or
    // a centre combines them; feature_result.cpp).
    add_value(plan, kIndependentUncertaintyValue,
              std::round(independent_expanded_uncertainty_mm(
                             uncertainty_budget(scenario, model.trigger_speed_mm_s())) *
                         1e6) /
                  1e6);
    add_values(plan, scenario, {"probe.artefact_uncertainty_mm", "machine.thermal_drift_mm"});
    if (scenario.cycle.feature != Feature::surface && scenario.cycle.size_tolerance_mm > 0.0) {
        add_values(plan, scenario, {"cycle.size_tolerance_mm", "cycle.tolerance_action"});
    }
}

}  // namespace

ProbingPlan make_cycle_plan(const Scenario& scenario, const CyclePlanOptions& options) {
    const Feature feature = scenario.cycle.feature;
    check_range(options.ball_diameter_mm, 0.0, 100.0, "ball_diameter_mm", "mm");
    if (lifts_over(feature) && options.ball_diameter_mm >= scenario.cycle.feature_size_mm) {
        // A boss's or web's stylus centres stand the ball's diameter apart
        // over its size: a ball that large leaves it no size.
        Message allowed =
            allowed_text("program_ball_diameter",
                         QT_TRANSLATE_NOOP("FieldError",
                                           "less than %1, the %2's distance between stylus centres "
                                           "(cycle.feature_size_mm)"));
        allowed.args = {arg("size_mm", ArgKind::length_mm, scenario.cycle.feature_size_mm),
                        feature_arg("feature", feature)};
        throw InputError(FieldError{"ball_diameter_mm", format_number(options.ball_diameter_mm),
                                    std::move(allowed)}
                             .to_message());
    }
    if (feature != Feature::surface) check_feature_plan(scenario, options);
    ProbingPlan plan;
    plan.kind = ProgramKind::cycle;
    add_machine_values(plan, scenario);
    add_values(plan, scenario,
               {"cycle.strategy", "cycle.approach_mm", "cycle.probe_feed_mm_min",
                "cycle.measure_feed_mm_min", "cycle.backoff_mm", "cycle.backoff_from",
                "cycle.return_feed_mm_min"});
    // The repeats when there are any (a plan of one touch a point reads as before).
    if (repeat_count(scenario.cycle) > 1) add_values(plan, scenario, {"cycle.repeats"});
    if (feature != Feature::surface) {
        add_values(plan, scenario,
                   {"cycle.feature", "cycle.feature_size_mm", "cycle.position_feed_mm_min"});
        if (lifts_over(feature)) add_values(plan, scenario, {"cycle.clearance_mm"});
        add_result_values(plan, scenario, options);
        add_feature_touches(plan, scenario, options);
        return plan;
    }
    add_result_values(plan, scenario, options);
    plan.steps.push_back(pause_step("check: the probe stands " +
                                    mm_text(scenario.cycle.approach_mm) +
                                    " in front of the surface, touching along " +
                                    to_string(options.touch) + "; resume to start"));
    add_point(plan, scenario, options.touch, scenario.cycle.approach_mm,
              scenario.cycle.part_position_uncertainty_mm, 0.0, "start",
              repeat_count(scenario.cycle));
    return plan;
}

// --- The plan file ---

namespace {

const char* to_word(StepKind kind) {
    switch (kind) {
        case StepKind::pause:
            return "pause";
        case StepKind::probe:
            return "probe";
        case StepKind::move:
            return "move";
        case StepKind::guard:
            return "guard";
    }
    return "probe";
}

class PlanReader {
  public:
    std::vector<FieldError> errors;

    void fail(std::string key, const Json& value, Message allowed) {
        errors.push_back({std::move(key), value.is_null() ? "" : value.dump(), std::move(allowed)});
    }

    // Not one of the `words` allowed (listed as "X, Y, Z").
    void fail_word(std::string key, const Json& value, const char* words) {
        Message allowed =
            allowed_text("unknown_word", QT_TRANSLATE_NOOP("FieldError", "one of %1"));
        allowed.args = {text_arg("allowed_words", words)};
        fail(std::move(key), value, std::move(allowed));
    }

    double number(const Json& object, const std::string& where, const char* name, double min,
                  double max, const char* unit) {
        const std::string key = where + "." + name;
        if (!object.contains(name)) {
            fail(key, nullptr, range_allowed(min, max, unit));
            return min;
        }
        const Json& value = object[name];
        const double number = value.is_number() ? value.get<double>() : std::nan("");
        if (!(number >= min && number <= max)) {
            fail(key, value, range_allowed(min, max, unit));
            return min;
        }
        return number == 0.0 ? 0.0 : number;
    }

    std::string text(const Json& object, const std::string& where, const std::string& name,
                     std::size_t max_chars) {
        if (!object.contains(name)) return {};
        const Json& value = object[name];
        if (!value.is_string() || value.get<std::string>().size() > max_chars ||
            value.get<std::string>().find_first_of("\r\n") != std::string::npos) {
            Message allowed = allowed_text(
                "one_line_text",
                QT_TRANSLATE_NOOP("FieldError", "one line of text, at most %1 characters"));
            allowed.args = {arg("max", ArgKind::integer, static_cast<double>(max_chars))};
            fail(where + "." + name, value, std::move(allowed));
            return {};
        }
        return value.get<std::string>();
    }

    ProgramStep step(const Json& body, const std::string& where) {
        ProgramStep step;
        if (!body.is_object()) {
            fail(where, body,
                 allowed_text("not_an_object",
                              QT_TRANSLATE_NOOP("FieldError", "an object of keys")));
            return step;
        }
        static const char* const kKeys[] = {
            "step",        "axis",     "direction",       "distance_mm",
            "feed_mm_min", "recorded", "orientation_deg", "text"};
        for (const auto& item : body.items()) {
            const std::string& name = item.key();
            if (std::find_if(std::begin(kKeys), std::end(kKeys),
                             [&name](const char* k) { return name == k; }) == std::end(kKeys)) {
                Message allowed =
                    allowed_text("unknown_key",
                                 QT_TRANSLATE_NOOP("FieldError", "unknown key; allowed in %1: %2"));
                allowed.args = {text_arg("section", "a step"),
                                text_arg("allowed_keys",
                                         "step, axis, direction, distance_mm, feed_mm_min, "
                                         "recorded, orientation_deg, text")};
                std::string key = where;
                key += '.';
                key += name;
                fail(std::move(key), nullptr, std::move(allowed));
            }
        }
        const Json kind = body.contains("step") ? body["step"] : Json();
        if (kind == "pause") {
            step.kind = StepKind::pause;
        } else if (kind == "probe") {
            step.kind = StepKind::probe;
        } else if (kind == "move") {
            step.kind = StepKind::move;
        } else if (kind == "guard") {
            step.kind = StepKind::guard;
        } else {
            fail_word(where + ".step", kind, "pause, probe, move, guard");
            return step;
        }
        step.text = text(body, where, "text", kMaxPauseTextChars);
        if (step.kind == StepKind::pause) return step;
        const Json axis = body.contains("axis") ? body["axis"] : Json();
        if (axis == "X" || axis == "Y" || axis == "Z") {
            step.axis = axis.get<std::string>()[0];
        } else {
            fail_word(where + ".axis", axis, "X, Y, Z");
        }
        const Json direction = body.contains("direction") ? body["direction"] : Json();
        if (direction == 1 || direction == -1) {
            step.direction = direction.get<int>();
        } else {
            fail_word(where + ".direction", direction, "1, -1");
        }
        step.distance_mm = number(body, where, "distance_mm", kStep_mm, kMaxPlanDistance_mm, "mm");
        // A probe's feed is one the lab reads back and a protected move's a
        // positioning feed (kMaxPlanFeed_mm_min); a plain move may be a rapid
        // (0) or a return faster than any probe.
        const bool move = step.kind == StepKind::move;
        step.feed_mm_min = number(body, where, "feed_mm_min", move ? 0.0 : kMinPlanFeed_mm_min,
                                  move ? kMaxPlanFeed_mm_min * 2.0 : kMaxPlanFeed_mm_min, "mm/min");
        if (body.contains("recorded")) {
            const Json& recorded = body["recorded"];
            if (recorded.is_boolean() && (step.kind == StepKind::probe || !recorded.get<bool>())) {
                step.recorded = recorded.get<bool>();
            } else {
                fail(where + ".recorded", recorded,
                     allowed_text(
                         "recorded_flag",
                         QT_TRANSLATE_NOOP("FieldError", "true or false (true on a probe only)")));
            }
        }
        if (body.contains("orientation_deg")) {
            // The ring's two spindle orientations, as the lab reads them.
            const Json& orientation = body["orientation_deg"];
            if (orientation == 0 || orientation == 180) {
                step.orientation_deg = orientation.get<double>();
            } else {
                fail_word(where + ".orientation_deg", orientation, "0, 180");
            }
        }
        return step;
    }
};

}  // namespace

std::string probing_plan_json(const ProbingPlan& plan) {
    Json root = Json::object();
    root["format"] = kFormat;
    root["version"] = kVersion;
    root["kind"] = to_string(plan.kind);
    Json values = Json::object();
    for (const PlanValue& v : plan.values) values[v.key] = v.text;
    root["values"] = values;
    Json steps = Json::array();
    for (const ProgramStep& step : plan.steps) {
        Json s = Json::object();
        s["step"] = to_word(step.kind);
        if (step.kind != StepKind::pause) {
            s["axis"] = std::string(1, step.axis);
            s["direction"] = step.direction;
            s["distance_mm"] = step.distance_mm;
            s["feed_mm_min"] = step.feed_mm_min;
        }
        if (step.kind == StepKind::probe) {
            s["recorded"] = step.recorded;
            s["orientation_deg"] = step.orientation_deg;
        }
        s["text"] = step.text;
        steps.push_back(std::move(s));
    }
    root["steps"] = std::move(steps);
    return root.dump(2) + "\n";
}

ProbingPlan parse_probing_plan(std::string_view text) {
    Json root;
    if (std::optional<FieldError> error = parse_checked_json(text, kMaxDepth, root)) {
        throw PlanError({std::move(*error)});
    }
    if (!root.is_object() || !root.contains("format") || root["format"] != kFormat) {
        throw PlanError(
            {{"format", root.is_object() && root.contains("format") ? root["format"].dump() : "",
              allowed_text("plan_file_format",
                           QT_TRANSLATE_NOOP("FieldError",
                                             "\"probecycle-probing-plan\" (a plan that "
                                             "probecycle-cli program wrote)"))}});
    }
    if (!root.contains("version") || root["version"] != kVersion) {
        throw PlanError(
            {{"version", root.contains("version") ? root["version"].dump() : "",
              allowed_text(
                  "plan_file_version",
                  QT_TRANSLATE_NOOP("FieldError", "1 (a newer ProbeCycle wrote this file)"))}});
    }
    PlanReader reader;
    ProbingPlan plan;
    for (const auto& item : root.items()) {
        const std::string& key = item.key();
        const Json& value = item.value();
        if (key == "format" || key == "version") continue;
        if (key == "kind") {
            const std::optional<ProgramKind> kind =
                value.is_string() ? program_kind_from_string(value.get<std::string>())
                                  : std::nullopt;
            if (kind) {
                plan.kind = *kind;
            } else {
                reader.fail_word(key, value, "delay, ring, cycle");
            }
        } else if (key == "values" && value.is_object()) {
            for (const auto& v : value.items()) {
                const std::string shown = reader.text(value, key, v.key(), 100);
                plan.values.push_back({v.key(), shown});
            }
        } else if (key == "steps" && value.is_array() && value.size() <= kMaxPlanSteps) {
            for (std::size_t i = 0; i < value.size(); ++i) {
                plan.steps.push_back(reader.step(value[i], "steps." + std::to_string(i + 1)));
            }
        } else if (key == "values" || key == "steps") {
            Message allowed = allowed_text(
                key == "values" ? "plan_values" : "plan_steps",
                key == "values" ? QT_TRANSLATE_NOOP("FieldError", "an object of keys")
                                : QT_TRANSLATE_NOOP("FieldError", "a list of at most 20000 steps"));
            reader.fail(key, value.size() > 3 ? Json(nullptr) : value, std::move(allowed));
        } else {
            Message allowed = allowed_text(
                "unknown_key", QT_TRANSLATE_NOOP("FieldError", "unknown key; allowed in %1: %2"));
            allowed.args = {text_arg("section", "the plan"),
                            text_arg("allowed_keys", "format, version, kind, values, steps")};
            reader.fail(key, nullptr, std::move(allowed));
        }
    }
    if (reader.errors.empty() && plan.recorded().empty()) {
        reader.fail("steps", nullptr,
                    allowed_text("plan_no_touch",
                                 QT_TRANSLATE_NOOP("FieldError",
                                                   "no recorded probe; a plan needs one or more")));
    }
    if (!reader.errors.empty()) throw PlanError(std::move(reader.errors));
    return plan;
}

std::string plan_id(const ProbingPlan& plan) {
    // FNV-1a, 64 bits: a name for the plan, not a protection.
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (const char c : probing_plan_json(plan)) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ULL;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

PlanSignature plan_signature(const ProbingPlan& plan) {
    PlanSignature signature;
    for (const ProgramStep& step : plan.steps) {
        if (step.kind != StepKind::probe) continue;
        if (step.axis == 'Z' && step.direction > 0) signature.direction = -1;
        break;
    }
    const std::string id = plan_id(plan);
    for (std::size_t i = 0; i < 2; ++i) {
        const unsigned long part = std::stoul(id.substr(8 * i, 8), nullptr, 16);
        signature.codes[i] = static_cast<int>(part % static_cast<unsigned long>(kSignatureCodes));
        signature.back_mm[i] = kSignatureFirst_mm + kSignatureStep_mm * signature.codes[i];
    }
    return signature;
}

}  // namespace probecycle
