#pragma once

// Example data for the lab (the window's "Simulate example data", as the
// Comparison tab has): the touches a probe as the scenario describes it would
// record, in the CSV the fits read, so that a new user sees the Calibration
// and Latency tabs at work before touching a machine. The data are drawn
// with a fixed seed: the same scenario gives the same text.

#include <cstdint>
#include <string>

#include "core/cycle/scenario.h"

namespace probecycle {

// The example's stylus ball: 3 mm, the usual for ring-gauge calibration.
inline constexpr double kExampleBallDiameter_mm = 3.0;
// The example's stylus runout, about what a stylus set on centre keeps.
inline constexpr double kExampleRunoutX_mm = 0.003;
inline constexpr double kExampleRunoutY_mm = -0.002;

// Touches in a ring gauge of `gauge_diameter_mm` centred at X100 Y-200: eight
// at each spindle orientation (0 and 180 degrees) spread round the bore. Each
// is the ball centre at the trigger: the gauge radius less the ball's radius
// less the probe's pretravel, with the pretravel varying by the probe's
// lobing round the directions (a three-lobed kinematic probe), the stylus
// runout (kExampleRunout*) turning with the spindle, and the probe's
// repeatability as noise (normal, its 2 sigma). Columns
// `orientation_deg,x_mm,y_mm` under a comment line that says what was drawn.
std::string example_ring_csv(const Scenario& scenario, double gauge_diameter_mm,
                             std::uint32_t seed = 1);

// The delay-stability test: touches of a surface at X 10 mm travelling X+,
// three at each of 100, 300, 1000, 2000 and 3000 mm/min. Each records where
// the axis was when the control took the position: the trigger point, plus the
// feed times the delay - the probe's interface delay, the control's latency
// and the wait for the next scan (uniform over the scan period); with a
// latched input the interface delay alone - with the machine's and the
// probe's repeatability as noise.
// Columns `axis,direction,feed_mm_min,measured_mm`.
std::string example_delay_csv(const Scenario& scenario, std::uint32_t seed = 1);

}  // namespace probecycle
