#pragma once

// The measurement's uncertainty budget (docs/model.md, "One touch"): the terms
// the model computes from the touch (the scan wait at the trigger speed and the
// probe's repeatability) and the terms an engineer knows from the probe's data
// sheet, the calibration certificate and the machine's acceptance test, each a
// key of the scenario. They are independent, so the budget combines them as the
// GUM does (JCGM 100:2008: 5.1.2, the law of propagation with unit sensitivity
// coefficients; 4.3.7, a rectangular distribution of half-width a has
// u = a/sqrt(3); 6.2.1, U = k u_c): the combined standard uncertainty is the
// root sum of the terms' squares, expanded with k = 2.

#include <array>
#include <cstddef>

#include "core/cycle/scenario.h"

namespace probecycle {

enum class BudgetTerm {
    scan_wait,              // trigger speed x machine.scan_period_s: a range
    probe_repeatability,    // probe.repeatability_2sigma_mm: 2 sigma
    probe_lobing,           // probe.lobing_mm: a half-width
    calibration_artefact,   // probe.artefact_uncertainty_mm: k = 2
    machine_repeatability,  // machine.repeatability_2sigma_mm: 2 sigma
    thermal_drift,          // machine.thermal_drift_mm: a half-width
};
constexpr std::size_t kBudgetTermCount = 6;
const char* to_string(BudgetTerm term);

// How a term's value is stated, and so what divides it to give a standard
// uncertainty: a full range of a rectangular distribution (sqrt(12)), the
// half-width of one (sqrt(3)), or an expanded uncertainty with k = 2 or a
// 2-sigma figure of a normal one (2).
enum class Distribution { uniform_range, uniform_half_width, normal_2sigma };
const char* to_string(Distribution distribution);
double divisor(Distribution distribution);

// The coverage factor of every expanded uncertainty ProbeCycle shows.
constexpr double kCoverageFactor = 2.0;

struct BudgetLine {
    BudgetTerm term{BudgetTerm::scan_wait};
    const char* key{""};  // the scenario key the value comes from
    Distribution distribution{Distribution::uniform_range};
    double value_mm{0.0};  // as the key states it (the scan wait: its range)
    // Random from touch to touch: the mean of cycle.repeats touches has
    // 1/sqrt(repeats) of it. The others are the same for every repeat.
    bool averaged{false};
    double standard_mm{0.0};  // in the result, after averaging
};

struct UncertaintyBudget {
    std::array<BudgetLine, kBudgetTermCount> lines{};
    int repeats{1};
    double combined_standard_mm{0.0};
    double expanded_mm{0.0};  // k = 2: what "uncertainty" means everywhere
    // The expanded uncertainty of the averaged terms alone (the trigger: scan
    // wait and probe repeatability, after averaging), and of the fixed ones.
    double trigger_expanded_mm{0.0};
    double fixed_expanded_mm{0.0};
};

// The budget of a measuring touch at `trigger_speed_mm_s`, averaged over the
// scenario's cycle.repeats.
UncertaintyBudget uncertainty_budget(const Scenario& scenario, double trigger_speed_mm_s);

// The expanded uncertainty of the terms neither the feed nor the repeats
// change: lobing, calibration artefact, machine repeatability, thermal drift.
double fixed_expanded_uncertainty_mm(const Scenario& scenario);

// The expanded uncertainty of the terms that differ from one point of a
// feature to the next, so independent between its points (a size or centre
// combines them as such): the trigger's (after averaging), the probe's
// lobing (each side its own direction) and the machine's repeatability. The
// two others are shared: the calibration artefact's error is the ball's size,
// the same outward on every point; the thermal drift moves every point alike.
double independent_expanded_uncertainty_mm(const UncertaintyBudget& budget);

// GUM: sqrt(fixed^2 + trigger^2 / repeats), each expanded with k = 2 (the
// same k, so the expanded figures combine as the standard ones do).
double combined_expanded_uncertainty_mm(double fixed_expanded_mm, double trigger_expanded_mm,
                                        int repeats);

}  // namespace probecycle
