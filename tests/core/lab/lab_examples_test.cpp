#include "core/lab/lab_examples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/cycle/scenario.h"
#include "core/lab/calibration.h"
#include "core/lab/delay_fit.h"

namespace probecycle {
namespace {

// The fits find in the example what it was drawn with.

TEST(LabExamples, TheRingFitFindsTheRunoutAndTheEffectiveRadiusDrawn) {
    Scenario s;
    s.probe.pretravel_mm = 0.005;
    const std::vector<RingPoint> points = parse_ring_csv(example_ring_csv(s, 50.0));
    ASSERT_EQ(points.size(), 16u);
    RingCalibrationOptions options;
    options.gauge_diameter_mm = 50.0;
    const RingCalibration fit = calibrate_ring(points, options);
    EXPECT_NEAR(fit.center_x_mm, 100.0, 0.001);
    EXPECT_NEAR(fit.center_y_mm, -200.0, 0.001);
    ASSERT_TRUE(fit.runout_x_mm && fit.runout_y_mm);
    EXPECT_NEAR(*fit.runout_x_mm, kExampleRunoutX_mm, 0.001);
    EXPECT_NEAR(*fit.runout_y_mm, kExampleRunoutY_mm, 0.001);
    // The ball's radius less the pretravel: 1.5 - 0.005 mm.
    EXPECT_NEAR(fit.effective_radius_mm, 1.495, 0.001);
    EXPECT_TRUE(fit.warnings.empty());
}

TEST(LabExamples, TheDelayFitFindsTheScenariosDelays) {
    Scenario s;
    s.probe.interface_delay_s = 0.002;
    s.machine.controller_latency_s = 0.004;
    s.machine.scan_period_s = 0.002;
    const DelayFit fit = fit_delay(parse_delay_csv(example_delay_csv(s)));
    ASSERT_EQ(fit.groups.size(), 1u);
    EXPECT_EQ(fit.groups[0].name(), "X+");
    EXPECT_EQ(fit.groups[0].feeds.size(), 5u);
    // tau = t_i + t_c + half a scan on average, within the scan's scatter.
    EXPECT_NEAR(fit.groups[0].delay_s, 0.002 + 0.004 + 0.001, 0.0006);
    // Applied, the control's latency comes back.
    const AppliedDelay applied = delay_to_apply(fit, s);
    EXPECT_EQ(applied.key, "machine.controller_latency_s");
    EXPECT_NEAR(applied.value_s, 0.004, 0.0006);
}

// The control latches the position when the signal arrives: the interface
// delay alone, which "Apply" then writes.
TEST(LabExamples, ALatchedInputRecordsTheInterfaceDelayAlone) {
    Scenario s;
    s.machine.latched_input = true;
    s.machine.scan_period_s = 0.004;
    s.machine.repeatability_2sigma_mm = 0.0;
    s.probe.repeatability_2sigma_mm = 0.0;
    const DelayFit fit = fit_delay(parse_delay_csv(example_delay_csv(s)));
    ASSERT_EQ(fit.groups.size(), 1u);
    EXPECT_NEAR(fit.groups[0].delay_s, s.probe.interface_delay_s, 1e-5);
    const AppliedDelay applied = delay_to_apply(fit, s);
    EXPECT_EQ(applied.key, "probe.interface_delay_s");
    EXPECT_NEAR(applied.value_s, s.probe.interface_delay_s, 1e-5);
}

TEST(LabExamples, OneSeedOneText) {
    const Scenario s;
    EXPECT_EQ(example_ring_csv(s, 50.0, 7), example_ring_csv(s, 50.0, 7));
    EXPECT_NE(example_ring_csv(s, 50.0, 7), example_ring_csv(s, 50.0, 8));
    EXPECT_EQ(example_delay_csv(s, 7), example_delay_csv(s, 7));
    EXPECT_NE(example_delay_csv(s, 7), example_delay_csv(s, 8));
}

}  // namespace
}  // namespace probecycle
