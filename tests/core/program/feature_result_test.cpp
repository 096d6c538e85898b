// A feature's result from its recorded touches, hand-computed for each
// feature: the sides of a real plan, the ball, the repeats' mean, the
// uncertainty of a size and of a centre, and the tolerance check both ways.

#include "core/program/feature_result.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/input_error.h"
#include "core/cycle/cycle.h"

namespace probecycle {
namespace {

using Touches = std::vector<std::array<double, 3>>;

Scenario single_touch(Feature feature, double size_mm) {
    Scenario s;
    s.cycle.feature = feature;
    s.cycle.feature_size_mm = size_mm;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.probe_feed_mm_min = 300.0;
    return s;
}

ResultSpec spec_of(const Scenario& scenario, CyclePlanOptions options) {
    const std::optional<ResultSpec> spec = result_spec(make_cycle_plan(scenario, options));
    EXPECT_TRUE(spec.has_value());
    return *spec;
}

TEST(FeatureResult, BoreDiameterAndCentreFromItsFourSides) {
    // A 50 mm bore, 6 mm ball: 44 mm between stylus centres.
    const ResultSpec spec = spec_of(single_touch(Feature::bore, 44.0), {{'Z', -1}, 6.0});
    ASSERT_EQ(spec.sides.size(), 4u);
    EXPECT_EQ(spec.touch_side, (std::vector<std::size_t>{0, 1, 2, 3}));
    EXPECT_DOUBLE_EQ(spec.nominal_size_mm(), 50.0);
    const FeatureResult r = feature_result(
        spec, Touches{{22.006, 0, 0}, {-21.998, 0, 0}, {0, 22.010, 0}, {0, -21.994, 0}});
    // X: 22.006 + 21.998 = 44.004; Y: 22.010 + 21.994 = 44.004.
    EXPECT_NEAR(r.centre_distance_mm, 44.004, 1e-12);
    EXPECT_NEAR(r.size_mm, 50.004, 1e-12);
    EXPECT_NEAR(*r.centre_mm[0], 0.004, 1e-12);
    EXPECT_NEAR(*r.centre_mm[1], 0.008, 1e-12);
    EXPECT_NEAR(r.deviation_mm, 0.004, 1e-12);
    EXPECT_FALSE(r.checked);
}

TEST(FeatureResult, BossDiameterLessTheBall) {
    // A 50 mm boss, 6 mm ball: 56 mm between stylus centres; its sides are
    // touched toward the centre.
    const ResultSpec spec = spec_of(single_touch(Feature::boss, 56.0), {{'Z', -1}, 6.0});
    EXPECT_EQ(to_string(spec.sides[0]), "X+");
    EXPECT_EQ(to_string(spec.sides[3]), "Y-");
    const FeatureResult r = feature_result(
        spec, Touches{{28.003, 0, 0}, {-27.999, 0, 0}, {0, 28.001, 0}, {0, -28.001, 0}});
    EXPECT_NEAR(r.size_mm, 50.002, 1e-12);  // (56.002 + 56.002)/2 - 6
    EXPECT_NEAR(*r.centre_mm[0], 0.002, 1e-12);
    EXPECT_NEAR(*r.centre_mm[1], 0.0, 1e-12);
}

TEST(FeatureResult, PocketWidthAndCentreFromTheMeanOfTheRepeats) {
    Scenario pocket = single_touch(Feature::pocket, 36.0);
    pocket.cycle.repeats = 2.0;
    const ResultSpec spec = spec_of(pocket, {{'Y', 1}, 4.0});
    EXPECT_EQ(spec.touch_side, (std::vector<std::size_t>{0, 0, 1, 1}));
    const FeatureResult r = feature_result(
        spec, Touches{{0, 18.010, 0}, {0, 18.012, 0}, {0, -17.990, 0}, {0, -17.992, 0}});
    EXPECT_NEAR(r.side_mm[0], 18.011, 1e-12);
    EXPECT_NEAR(r.side_mm[1], -17.991, 1e-12);
    EXPECT_NEAR(r.size_mm, 40.002, 1e-12);  // 36.002 + 4
    EXPECT_FALSE(r.centre_mm[0].has_value());
    EXPECT_NEAR(*r.centre_mm[1], 0.010, 1e-12);
}

TEST(FeatureResult, WebToleranceBothWays) {
    Scenario web = single_touch(Feature::web, 12.0);
    web.cycle.size_tolerance_mm = 0.01;
    const Touches touches{{6.03, 0, 0}, {-5.95, 0, 0}};
    // 11.98 between stylus centres, 9.98 wide with the 2 mm ball: 0.02 under.
    const FeatureResult out = feature_result(spec_of(web, {{'X', 1}, 2.0}), touches);
    EXPECT_NEAR(out.size_mm, 9.98, 1e-12);
    EXPECT_NEAR(*out.centre_mm[0], 0.04, 1e-12);
    EXPECT_NEAR(out.deviation_mm, -0.02, 1e-12);
    EXPECT_TRUE(out.checked);
    EXPECT_TRUE(out.out_of_tolerance);
    web.cycle.size_tolerance_mm = 0.03;
    const FeatureResult in = feature_result(spec_of(web, {{'X', 1}, 2.0}), touches);
    EXPECT_TRUE(in.checked);
    EXPECT_FALSE(in.out_of_tolerance);
    // The action is the plan's.
    web.cycle.tolerance_action = ToleranceAction::stop;
    EXPECT_EQ(spec_of(web, {{'X', 1}, 2.0}).tolerance_action, ToleranceAction::stop);
}

TEST(FeatureResult, SurfacePositionIsHalfTheBallBeyondTheStylusCentre) {
    Scenario surface;
    surface.cycle.size_tolerance_mm = 0.01;  // a surface has no size to check
    const ResultSpec spec = spec_of(surface, {{'Z', -1}, 6.0});
    const FeatureResult r = feature_result(spec, Touches{{1.0, 2.0, -10.003}});
    EXPECT_NEAR(r.size_mm, -13.003, 1e-12);
    EXPECT_FALSE(r.checked);
    const FeatureResult plus =
        feature_result(spec_of(surface, {{'X', 1}, 6.0}), Touches{{5, 0, 0}});
    EXPECT_NEAR(plus.size_mm, 8.0, 1e-12);
}

// The points' independent terms: a difference of two has sqrt(2) a point's,
// their mean 1/sqrt(2); a bore's diameter, the mean of two widths, a point's.
// The shared terms: a size carries the calibration artefact's
// uncertainty whole, a centre the thermal drift's (feature_result.cpp). The
// point's is the model's whole budget.
TEST(FeatureResult, UncertaintiesCombineTheIndependentTermsAndTheSharedOnes) {
    const Scenario bore = single_touch(Feature::bore, 44.0);
    const ResultSpec spec = spec_of(bore, {});
    const CycleResult model = evaluate(bore);
    EXPECT_NEAR(spec.point_uncertainty_mm, model.uncertainty_mm(), 5e-7);
    // Defaults: the trigger's, lobing +-1 um and the machine's 2 um (2 sigma)
    // are independent; the artefact's 1 um (k = 2) and +-2 um of drift shared.
    const double trigger = model.trigger_uncertainty_mm();
    const double independent =
        std::sqrt(trigger * trigger + 4.0 * (1e-6 / 3.0 + 1e-6));  // 2 sqrt(u^2 ...)
    EXPECT_NEAR(spec.independent_uncertainty_mm, independent, 5e-7);
    EXPECT_DOUBLE_EQ(spec.artefact_uncertainty_mm, 0.001);
    EXPECT_DOUBLE_EQ(spec.thermal_drift_mm, 0.002);
    const FeatureResult r = feature_result(spec, Touches(4));
    EXPECT_DOUBLE_EQ(r.size_uncertainty_mm, std::hypot(spec.independent_uncertainty_mm, 0.001));
    EXPECT_DOUBLE_EQ(
        r.centre_uncertainty_mm,
        std::hypot(spec.independent_uncertainty_mm / std::sqrt(2.0), 2.0 * 0.002 / std::sqrt(3.0)));
    ResultSpec pocket = spec;
    pocket.feature = Feature::pocket;
    pocket.independent_uncertainty_mm = 0.002;
    pocket.artefact_uncertainty_mm = 0.0;
    EXPECT_DOUBLE_EQ(size_uncertainty_mm(pocket), 0.002 * std::sqrt(2.0));
    ResultSpec surface = pocket;
    surface.feature = Feature::surface;
    surface.point_uncertainty_mm = 0.003;
    EXPECT_DOUBLE_EQ(size_uncertainty_mm(surface), 0.003);
    // Checked by sampling: the spread of a width of two points each with
    // standard deviation 1 is sqrt(2).
    double sum2 = 0.0;
    const int n = 200000;
    unsigned state = 42;
    const auto uniform = [&state] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / double(1u << 24) - 0.5;  // variance 1/12
    };
    for (int i = 0; i < n; ++i) {
        const double w = std::sqrt(12.0) * (uniform() - uniform());
        sum2 += w * w;
    }
    EXPECT_NEAR(std::sqrt(sum2 / n), std::sqrt(2.0), 0.01);
}

TEST(FeatureResult, ABallAsLargeAsABossIsRefused) {
    EXPECT_THROW(make_cycle_plan(single_touch(Feature::boss, 6.0), {{'Z', -1}, 6.0}), InputError);
    EXPECT_THROW(make_cycle_plan(single_touch(Feature::web, 12.0), {{'X', 1}, 12.0}), InputError);
    EXPECT_NO_THROW(make_cycle_plan(single_touch(Feature::boss, 56.0), {{'Z', -1}, 6.0}));
}

TEST(FeatureResult, APlanWithoutTheResultsValuesIsRefused) {
    ProbingPlan plan = make_cycle_plan(single_touch(Feature::bore, 44.0), {});
    EXPECT_FALSE(result_spec(make_ring_plan(Scenario{}, RingPlanOptions{})).has_value());
    for (PlanValue& value : plan.values) {
        if (value.key == kPointUncertaintyValue) value.text.assign(1, 'x');
    }
    EXPECT_THROW(result_spec(plan), InputError);
    ProbingPlan edited = make_cycle_plan(single_touch(Feature::bore, 44.0), {});
    for (ProgramStep& step : edited.steps) {
        if (step.recorded && step.axis == 'Y') step.axis = 'X';
    }
    EXPECT_THROW(result_spec(edited), InputError);
}

}  // namespace
}  // namespace probecycle
