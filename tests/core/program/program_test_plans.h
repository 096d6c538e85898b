#pragma once

// The plans the program tests share: the golden files, the importers' logs
// and the rs274 check are made from these.

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
    std::string name;  // "delay", "ring", "cycle", "cycle_single"
    ProbingPlan plan;
};

// Every program the tests write, from the default scenario.
inline std::vector<NamedPlan> golden_plans() {
    const Scenario scenario;
    Scenario single = scenario;
    single.cycle.strategy = Strategy::single_touch;
    single.cycle.probe_feed_mm_min = 300.0;
    return {
        {"delay", make_delay_plan(scenario, golden_delay_options())},
        {"ring", make_ring_plan(scenario, RingPlanOptions{})},
        {"cycle", make_cycle_plan(scenario, CyclePlanOptions{})},
        {"cycle_single", make_cycle_plan(single, CyclePlanOptions{{'X', 1}})},
    };
}

}  // namespace probecycle::program_test
