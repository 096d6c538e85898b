#include "core/lab/lab_examples.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

namespace probecycle {

namespace {

constexpr double kGaugeCentreX_mm = 100.0;
constexpr double kGaugeCentreY_mm = -200.0;
constexpr int kPointsPerOrientation = 8;
constexpr double kSurface_mm = 10.0;
constexpr double kDelayFeeds_mm_min[] = {100.0, 300.0, 1000.0, 2000.0, 3000.0};
constexpr int kTouchesPerFeed = 3;

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

}  // namespace

std::string example_ring_csv(const Scenario& scenario, double gauge_diameter_mm,
                             std::uint32_t seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, scenario.probe.repeatability_2sigma_mm / 2.0);
    const double ball_radius_mm = kExampleBallDiameter_mm / 2.0;
    const double reach_mm = gauge_diameter_mm / 2.0 - ball_radius_mm;
    std::string csv = "# example: ring gauge " + fixed(gauge_diameter_mm, 3) + " mm at X" +
                      fixed(kGaugeCentreX_mm, 0) + " Y" + fixed(kGaugeCentreY_mm, 0) + "; ball " +
                      fixed(kExampleBallDiameter_mm, 3) + " mm; runout (" +
                      fixed(kExampleRunoutX_mm, 3) + ", " + fixed(kExampleRunoutY_mm, 3) +
                      ") mm\norientation_deg,x_mm,y_mm\n";
    for (const double orientation : {0.0, 180.0}) {
        // The runout turns with the spindle: the stylus centre is off the
        // spindle's by -runout at 0 deg and +runout at 180 deg.
        const double sign = orientation == 0.0 ? -1.0 : 1.0;
        const double cx = kGaugeCentreX_mm + sign * kExampleRunoutX_mm;
        const double cy = kGaugeCentreY_mm + sign * kExampleRunoutY_mm;
        for (int i = 0; i < kPointsPerOrientation; ++i) {
            const double angle =
                2.0 * std::numbers::pi * (i + 0.25) / static_cast<double>(kPointsPerOrientation);
            // Pretravel varies round a kinematic probe's three lobes.
            const double pretravel_mm =
                scenario.probe.pretravel_mm + scenario.probe.lobing_mm * std::cos(3.0 * angle);
            // The spindle goes on by the pretravel after the ball meets the bore.
            const double r = reach_mm + pretravel_mm + noise(random);
            csv += fixed(orientation, 0) + ',' + fixed(cx + r * std::cos(angle), 4) + ',' +
                   fixed(cy + r * std::sin(angle), 4) + '\n';
        }
    }
    return csv;
}

std::string example_delay_csv(const Scenario& scenario, std::uint32_t seed) {
    std::mt19937 random(seed);
    const double sigma_mm = std::hypot(scenario.machine.repeatability_2sigma_mm,
                                       scenario.probe.repeatability_2sigma_mm) /
                            2.0;
    std::normal_distribution<double> noise(0.0, sigma_mm);
    const double scan_s = scenario.machine.latched_input ? 0.0 : scenario.machine.scan_period_s;
    std::uniform_real_distribution<double> scan_wait(0.0, scan_s);
    // A latched input takes the position when the probe's signal arrives:
    // the control's latency and its scan no longer move the recorded point.
    const bool latched = scenario.machine.latched_input;
    const double fixed_delay_s =
        scenario.probe.interface_delay_s + (latched ? 0.0 : scenario.machine.controller_latency_s);
    std::string csv = "# example: delay-stability test, X+ to a surface at X" +
                      fixed(kSurface_mm, 3) + ", " + fixed(fixed_delay_s * 1000.0, 3) +
                      " ms of delay and a " + fixed(scan_s * 1000.0, 3) +
                      " ms scan\naxis,direction,feed_mm_min,measured_mm\n";
    for (const double feed : kDelayFeeds_mm_min) {
        const double speed_mm_s = feed / 60.0;
        for (int k = 0; k < kTouchesPerFeed; ++k) {
            const double delay_s = fixed_delay_s + (scan_s > 0.0 ? scan_wait(random) : 0.0);
            const double measured =
                kSurface_mm + scenario.probe.pretravel_mm + speed_mm_s * delay_s + noise(random);
            csv += "X,+1," + fixed(feed, 0) + ',' + fixed(measured, 4) + '\n';
        }
    }
    return csv;
}

}  // namespace probecycle
