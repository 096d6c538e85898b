#pragma once

// The plans the program tests share: the golden files, the importers' logs
// and the rs274 check are made from these; and small logs in each control's
// format (the core's importer tests and the window's).

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "core/cycle/scenario.h"
#include "core/program/plan.h"
#include "core/program/program_writer.h"

namespace probecycle::program_test {

// The golden files' day.
inline const std::string kDate = "2026-01-15";

inline DelayPlanOptions golden_delay_options() {
    DelayPlanOptions options;
    options.touch = {'X', 1};
    options.feeds_mm_min = {30.0, 300.0, 2000.0};
    options.repeats = 2;
    return options;
}

// The Fanuc-type ring program's spindle command (Haas's M19 with an angle
// option, as an example of what a user gives).
inline ProgramOptions golden_options() {
    return ProgramOptions{"M19 R180."};
}

struct NamedPlan {
    std::string name;  // "delay", "ring", "cycle", "cycle_single", "cycle_bore", ...
    ProbingPlan plan;
};

// The default scenario for a known part (part position uncertainty 0): the
// golden files and the hand-computed plans were made so; the default's 0.5 mm
// lengthens each first search by it, which CyclePlan's tests check.
inline Scenario known_part() {
    Scenario s;
    s.cycle.part_position_uncertainty_mm = 0.0;
    return s;
}

// The tuned cycle on a bore: the default scenario (two-touch) on its 50 mm bore.
inline Scenario golden_bore() {
    Scenario bore = known_part();
    bore.cycle.feature = Feature::bore;
    return bore;
}
// On a boss, single-touch at 300 mm/min, each side touched twice (cycle.repeats).
inline Scenario golden_boss() {
    Scenario boss = known_part();
    boss.cycle.feature = Feature::boss;
    boss.cycle.strategy = Strategy::single_touch;
    boss.cycle.probe_feed_mm_min = 300.0;
    boss.cycle.repeats = 2.0;
    return boss;
}

// A pocket along Y, 40 mm wide with a 4 mm ball (36 mm between stylus
// centres), single-touch twice a side, its size checked to +-0.05 mm: out of
// tolerance the program stops.
inline Scenario golden_pocket() {
    Scenario pocket;
    pocket.cycle.feature = Feature::pocket;
    pocket.cycle.feature_size_mm = 36.0;
    pocket.cycle.strategy = Strategy::single_touch;
    pocket.cycle.probe_feed_mm_min = 300.0;
    pocket.cycle.repeats = 2.0;
    pocket.cycle.size_tolerance_mm = 0.05;
    pocket.cycle.tolerance_action = ToleranceAction::stop;
    return pocket;
}
// A web along X, 10 mm wide with a 2 mm ball (12 mm between stylus
// centres), two-touch, its size checked to +-0.02 mm: out of tolerance the
// program flags it.
inline Scenario golden_web() {
    Scenario web;
    web.cycle.feature = Feature::web;
    web.cycle.feature_size_mm = 12.0;
    web.cycle.size_tolerance_mm = 0.02;
    web.cycle.tolerance_action = ToleranceAction::flag;
    return web;
}

// Every program the tests write, from the default scenario.
inline std::vector<NamedPlan> golden_plans() {
    const Scenario scenario = known_part();
    Scenario single = scenario;
    single.cycle.strategy = Strategy::single_touch;
    single.cycle.probe_feed_mm_min = 300.0;
    return {
        {"delay", make_delay_plan(scenario, golden_delay_options())},
        {"ring", make_ring_plan(scenario, RingPlanOptions{})},
        {"cycle", make_cycle_plan(scenario, CyclePlanOptions{})},
        {"cycle_single", make_cycle_plan(single, CyclePlanOptions{{'X', 1}})},
        {"cycle_bore", make_cycle_plan(golden_bore(), CyclePlanOptions{})},
        {"cycle_boss", make_cycle_plan(golden_boss(), CyclePlanOptions{})},
        {"cycle_pocket", make_cycle_plan(golden_pocket(), CyclePlanOptions{{'Y', 1}, 4.0})},
        {"cycle_web", make_cycle_plan(golden_web(), CyclePlanOptions{{'X', 1}, 2.0})},
        {"cycle_bore_ball", make_cycle_plan(golden_bore(), CyclePlanOptions{{'Z', -1}, 6.0})},
    };
}

// A small plan with protected moves (StepKind::guard), as a feature's program
// makes them: out from a centre to a touch's start, the touch, back to the
// start and to the centre; then down along Z, protected too.
inline ProbingPlan guarded_plan() {
    const auto step = [](StepKind kind, char axis, int direction, double distance_mm,
                         double feed_mm_min, std::string text) {
        ProgramStep s;
        s.kind = kind;
        s.axis = axis;
        s.direction = direction;
        s.distance_mm = distance_mm;
        s.feed_mm_min = feed_mm_min;
        s.recorded = kind == StepKind::probe;
        s.text = std::move(text);
        return s;
    };
    ProbingPlan plan;
    plan.kind = ProgramKind::cycle;
    plan.values = {{"cycle.position_feed_mm_min", "3000"}, {"point_uncertainty_mm", "0.002"}};
    ProgramStep pause;
    pause.kind = StepKind::pause;
    pause.text = "check: the probe stands at the centre; resume to start";
    plan.steps = {pause,
                  step(StepKind::guard, 'X', 1, 20.0, 3000.0, "out to the X+ start"),
                  step(StepKind::probe, 'X', 1, 6.0, 2000.0, "X+ at 2000 mm/min"),
                  step(StepKind::move, 'X', -1, 5.2, 10000.0, "back to the start"),
                  step(StepKind::guard, 'X', -1, 20.0, 3000.0, "back to the centre"),
                  step(StepKind::guard, 'Z', -1, 10.0, 3000.0, "down by the clearance")};
    return plan;
}

// Z- at 100 and 1000 mm/min, twice each.
inline DelayPlanOptions small_delay_options() {
    DelayPlanOptions options;
    options.touch = {'Z', -1};
    options.feeds_mm_min = {100.0, 1000.0};
    options.repeats = 2;
    return options;
}
inline ProbingPlan small_delay_plan() {
    return make_delay_plan(Scenario{}, small_delay_options());
}

// grbl's report of a probe: "[PRB:x,y,z:1]" (0: no trigger).
inline std::string prb(double x, double y, double z, int ok = 1) {
    char line[128];
    std::snprintf(line, sizeof line, "[PRB:%.3f,%.3f,%.3f:%d]\n", x, y, z, ok);
    return line;
}

// grbl's answers to the plan's signature moves (plan_signature), from
// `start`: four [PRB:...:0] lines, each followed by "ok".
inline std::string grbl_signature(const ProbingPlan& plan, std::array<double, 3> start = {}) {
    const PlanSignature signature = plan_signature(plan);
    const std::size_t axis = signature.axis == 'X' ? 0 : signature.axis == 'Y' ? 1 : 2;
    std::string log;
    for (const double back : signature.back_mm) {
        std::array<double, 3> at = start;
        at[axis] += signature.direction * (kSignatureOut_mm + back);
        log += prb(at[0], at[1], at[2], 0) + "ok\n";
        at[axis] -= signature.direction * back;
        log += prb(at[0], at[1], at[2], 0) + "ok\nok\n";
    }
    return log;
}

// A grbl console for small_delay_plan(): the signature (lines 3 to 12),
// the locating touch (line 13), then 4 recorded (lines 15, 17, 19, 21).
inline std::string grbl_console() {
    std::string log = "Grbl 1.1h ['$' for help]\nok\n";
    log += grbl_signature(small_delay_plan());
    log += prb(0, 0, -20.0) + "ok\n";
    for (double z : {-20.017, -20.018, -20.150, -20.151}) log += prb(0, 0, z) + "ok\n";
    return log;
}

// A LinuxCNC LOG file as a program writes it: its plan line, then a
// "probecycle touch" line per recorded touch at these X, Y, Z.
inline std::string linuxcnc_touch_log(const ProbingPlan& plan,
                                      const std::vector<std::array<double, 3>>& touches) {
    std::string log = "probecycle plan " + plan_id(plan) + " " + to_string(plan.kind) + "\n";
    for (std::size_t i = 0; i < touches.size(); ++i) {
        char line[160];
        std::snprintf(line, sizeof line, "probecycle touch %zu %.6f %.6f %.6f\n", i + 1,
                      touches[i][0], touches[i][1], touches[i][2]);
        log += line;
    }
    return log;
}

// A LinuxCNC LOG file of a delay plan: a recorded touch at each Z.
inline std::string linuxcnc_log(const ProbingPlan& plan, const std::vector<double>& zs) {
    std::vector<std::array<double, 3>> touches;
    for (const double z : zs) touches.push_back({1.0, 2.0, z});
    return linuxcnc_touch_log(plan, touches);
}

// A LinuxCNC LOG file of a ring plan: X+, X-, Y+, Y- on a circle of this
// radius about 0, at 0 deg, then at 180 deg, with 2 µm of runout along X.
constexpr double kRingLogRadius_mm = 21.997;
inline std::string linuxcnc_ring_log(const ProbingPlan& plan) {
    const double r = kRingLogRadius_mm;
    const double points[4][2] = {{r, 0}, {-r, 0}, {0, r}, {0, -r}};
    std::vector<std::array<double, 3>> touches;
    for (int i = 0; i < 8; ++i) {
        const double runout = i < 4 ? 0.002 : -0.002;
        touches.push_back({points[i % 4][0] + runout, points[i % 4][1], 0.0});
    }
    return linuxcnc_touch_log(plan, touches);
}

}  // namespace probecycle::program_test
