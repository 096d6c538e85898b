// The uncertainty budget (uncertainty.h): hand-computed lines, the GUM
// combination, repeats averaging only the touch's random terms, and the
// cycle's figure being the budget's.
#include "core/cycle/uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"

namespace probecycle {
namespace {

TEST(UncertaintyBudget, HandComputedAtTheDefaultsSingleTouchAt3000) {
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.probe_feed_mm_min = 3000.0;
    const UncertaintyBudget b = uncertainty_budget(s, 50.0);  // 3000 mm/min
    ASSERT_EQ(b.lines.size(), kBudgetTermCount);
    // 3000 mm/min (50 mm/s) with a 4 ms scan is a 0.2 mm range; u = R/sqrt(12).
    EXPECT_EQ(b.lines[0].term, BudgetTerm::scan_wait);
    EXPECT_STREQ(b.lines[0].key, "machine.scan_period_s");
    EXPECT_NEAR(b.lines[0].value_mm, 0.2, 1e-15);
    EXPECT_NEAR(b.lines[0].standard_mm, 0.2 / std::sqrt(12.0), 1e-15);
    EXPECT_TRUE(b.lines[0].averaged);
    // 1 um 2 sigma: 0.5 um.
    EXPECT_EQ(b.lines[1].term, BudgetTerm::probe_repeatability);
    EXPECT_NEAR(b.lines[1].standard_mm, 0.0005, 1e-15);
    EXPECT_TRUE(b.lines[1].averaged);
    // +-1 um lobing: 1/sqrt(3) um; 1 um (k = 2) artefact: 0.5 um; 2 um (2
    // sigma) machine: 1 um; +-2 um thermal: 2/sqrt(3) um. None averaged.
    const double expected[] = {0.001 / std::sqrt(3.0), 0.0005, 0.001, 0.002 / std::sqrt(3.0)};
    const BudgetTerm terms[] = {BudgetTerm::probe_lobing, BudgetTerm::calibration_artefact,
                                BudgetTerm::machine_repeatability, BudgetTerm::thermal_drift};
    for (int i = 0; i < 4; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(b.lines[2 + i].term, terms[i]);
        EXPECT_NEAR(b.lines[2 + i].standard_mm, expected[i], 1e-15);
        EXPECT_FALSE(b.lines[2 + i].averaged);
    }
    const double fixed_u2 = 1e-6 * (1.0 / 3.0 + 0.25 + 1.0 + 4.0 / 3.0);
    const double trigger_u2 = 0.04 / 12.0 + 0.0005 * 0.0005;
    EXPECT_NEAR(b.combined_standard_mm, std::sqrt(fixed_u2 + trigger_u2), 1e-15);
    EXPECT_NEAR(b.expanded_mm, 2.0 * std::sqrt(fixed_u2 + trigger_u2), 1e-15);
    EXPECT_NEAR(b.fixed_expanded_mm, 2.0 * std::sqrt(fixed_u2), 1e-15);
    EXPECT_NEAR(b.trigger_expanded_mm, 2.0 * std::sqrt(trigger_u2), 1e-15);

    // The cycle's figure is the budget's; the trigger's part is the old one.
    const CycleResult r = evaluate(s);
    EXPECT_NEAR(r.uncertainty_mm(), b.expanded_mm, 1e-15);
    EXPECT_NEAR(r.trigger_uncertainty_mm(), b.trigger_expanded_mm, 1e-15);
}

TEST(UncertaintyBudget, RepeatsAverageTheTouchsTermsOnly) {
    Scenario s;
    s.cycle.repeats = 4.0;
    const UncertaintyBudget four = uncertainty_budget(s, 0.5);
    s.cycle.repeats = 1.0;
    const UncertaintyBudget one = uncertainty_budget(s, 0.5);
    EXPECT_EQ(four.repeats, 4);
    for (std::size_t i = 0; i < kBudgetTermCount; ++i) {
        SCOPED_TRACE(i);
        const double factor = four.lines[i].averaged ? 0.5 : 1.0;  // 1/sqrt(4)
        EXPECT_NEAR(four.lines[i].standard_mm, one.lines[i].standard_mm * factor, 1e-18);
    }
    EXPECT_NEAR(four.fixed_expanded_mm, one.fixed_expanded_mm, 1e-18);
    EXPECT_NEAR(four.trigger_expanded_mm, one.trigger_expanded_mm / 2.0, 1e-18);
}

TEST(UncertaintyBudget, ALatchedInputHasNoScanTerm) {
    Scenario s;
    s.machine.latched_input = true;
    const UncertaintyBudget b = uncertainty_budget(s, 50.0);
    EXPECT_EQ(b.lines[0].value_mm, 0.0);
    EXPECT_EQ(b.lines[0].standard_mm, 0.0);
}

TEST(UncertaintyBudget, DivisorsAreTheGumsForEachWayOfStatingAValue) {
    EXPECT_DOUBLE_EQ(divisor(Distribution::uniform_range), std::sqrt(12.0));
    EXPECT_DOUBLE_EQ(divisor(Distribution::uniform_half_width), std::sqrt(3.0));
    EXPECT_DOUBLE_EQ(divisor(Distribution::normal_2sigma), 2.0);
}

// Property (fixed seed): over random scenarios the cycle's uncertainty is the
// root sum of squares of the budget's lines times k, never under either part,
// and the combination of the expanded parts gives the same figure.
TEST(UncertaintyBudget, TheCyclesFigureIsTheRootSumOfSquaresOfTheLines) {
    std::mt19937 rng(28);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        SCOPED_TRACE(i);
        Scenario s;
        s.machine.scan_period_s = 0.01 * unit(rng);
        s.machine.repeatability_2sigma_mm = 0.005 * unit(rng);
        s.machine.thermal_drift_mm = 0.01 * unit(rng);
        s.probe.repeatability_2sigma_mm = 0.003 * unit(rng);
        s.probe.lobing_mm = 0.003 * unit(rng);
        s.probe.artefact_uncertainty_mm = 0.002 * unit(rng);
        s.cycle.strategy = unit(rng) < 0.5 ? Strategy::single_touch : Strategy::two_touch;
        s.cycle.probe_feed_mm_min = 50.0 + 2000.0 * unit(rng);
        s.cycle.measure_feed_mm_min = 5.0 + 100.0 * unit(rng);
        s.cycle.backoff_mm = 4.0;
        s.cycle.repeats = 1.0 + std::floor(5.0 * unit(rng));
        const CycleResult r = evaluate(s);
        const UncertaintyBudget b = uncertainty_budget(s, r.trigger_speed_mm_s());
        double sum = 0.0;
        for (const BudgetLine& line : b.lines) sum += line.standard_mm * line.standard_mm;
        EXPECT_NEAR(r.uncertainty_mm(), kCoverageFactor * std::sqrt(sum), 1e-15);
        EXPECT_GE(r.uncertainty_mm(), r.trigger_uncertainty_mm());
        EXPECT_GE(r.uncertainty_mm(), b.fixed_expanded_mm);
        EXPECT_NEAR(combined_expanded_uncertainty_mm(b.fixed_expanded_mm, b.trigger_expanded_mm, 1),
                    r.uncertainty_mm(), 1e-15);
    }
}

}  // namespace
}  // namespace probecycle
