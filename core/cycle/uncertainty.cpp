#include "core/cycle/uncertainty.h"

#include <algorithm>
#include <cmath>

#include "core/cycle/cycle.h"

namespace probecycle {

const char* to_string(BudgetTerm term) {
    switch (term) {
        case BudgetTerm::scan_wait:
            return "scan_wait";
        case BudgetTerm::probe_repeatability:
            return "probe_repeatability";
        case BudgetTerm::probe_lobing:
            return "probe_lobing";
        case BudgetTerm::calibration_artefact:
            return "calibration_artefact";
        case BudgetTerm::machine_repeatability:
            return "machine_repeatability";
        case BudgetTerm::thermal_drift:
            return "thermal_drift";
    }
    return "";
}

const char* to_string(Distribution distribution) {
    switch (distribution) {
        case Distribution::uniform_range:
            return "uniform_range";
        case Distribution::uniform_half_width:
            return "uniform_half_width";
        case Distribution::normal_2sigma:
            return "normal_2sigma";
    }
    return "";
}

double divisor(Distribution distribution) {
    switch (distribution) {
        case Distribution::uniform_range:
            return std::sqrt(12.0);
        case Distribution::uniform_half_width:
            return std::sqrt(3.0);
        case Distribution::normal_2sigma:
            return 2.0;
    }
    return 1.0;
}

namespace {

// The fixed terms, in the budget's order after the two the touch gives.
struct FixedTerm {
    BudgetTerm term;
    const char* key;
    Distribution distribution;
    double value_mm;
};
std::array<FixedTerm, 4> fixed_terms(const Scenario& s) {
    return {{
        {BudgetTerm::probe_lobing, "probe.lobing_mm", Distribution::uniform_half_width,
         s.probe.lobing_mm},
        {BudgetTerm::calibration_artefact, "probe.artefact_uncertainty_mm",
         Distribution::normal_2sigma, s.probe.artefact_uncertainty_mm},
        {BudgetTerm::machine_repeatability, "machine.repeatability_2sigma_mm",
         Distribution::normal_2sigma, s.machine.repeatability_2sigma_mm},
        {BudgetTerm::thermal_drift, "machine.thermal_drift_mm", Distribution::uniform_half_width,
         s.machine.thermal_drift_mm},
    }};
}

}  // namespace

double fixed_expanded_uncertainty_mm(const Scenario& scenario) {
    double variance = 0.0;
    for (const FixedTerm& t : fixed_terms(scenario)) {
        const double u = t.value_mm / divisor(t.distribution);
        variance += u * u;
    }
    return kCoverageFactor * std::sqrt(variance);
}

double combined_expanded_uncertainty_mm(double fixed_expanded_mm, double trigger_expanded_mm,
                                        int repeats) {
    const double n = static_cast<double>(std::max(1, repeats));
    return std::sqrt(fixed_expanded_mm * fixed_expanded_mm +
                     trigger_expanded_mm * trigger_expanded_mm / n);
}

double independent_expanded_uncertainty_mm(const UncertaintyBudget& budget) {
    double variance = 0.0;
    for (const BudgetLine& l : budget.lines) {
        if (l.term == BudgetTerm::calibration_artefact || l.term == BudgetTerm::thermal_drift)
            continue;
        variance += l.standard_mm * l.standard_mm;
    }
    return kCoverageFactor * std::sqrt(variance);
}

UncertaintyBudget uncertainty_budget(const Scenario& scenario, double trigger_speed_mm_s) {
    UncertaintyBudget b;
    b.repeats = repeat_count(scenario.cycle);
    const double root_n = std::sqrt(static_cast<double>(b.repeats));
    const auto line = [root_n](BudgetTerm term, const char* key, Distribution d, double value,
                               bool averaged) {
        return BudgetLine{term,  key,      d,
                          value, averaged, value / divisor(d) / (averaged ? root_n : 1.0)};
    };
    b.lines[0] = line(BudgetTerm::scan_wait, "machine.scan_period_s", Distribution::uniform_range,
                      scan_range_mm(scenario.machine, trigger_speed_mm_s), true);
    b.lines[1] = line(BudgetTerm::probe_repeatability, "probe.repeatability_2sigma_mm",
                      Distribution::normal_2sigma, scenario.probe.repeatability_2sigma_mm, true);
    std::size_t i = 2;
    for (const FixedTerm& t : fixed_terms(scenario))
        b.lines[i++] = line(t.term, t.key, t.distribution, t.value_mm, false);

    double variance = 0.0;
    for (const BudgetLine& l : b.lines) variance += l.standard_mm * l.standard_mm;
    b.combined_standard_mm = std::sqrt(variance);
    b.expanded_mm = kCoverageFactor * b.combined_standard_mm;
    b.trigger_expanded_mm =
        kCoverageFactor * std::hypot(b.lines[0].standard_mm, b.lines[1].standard_mm);
    b.fixed_expanded_mm = fixed_expanded_uncertainty_mm(scenario);
    return b;
}

}  // namespace probecycle
