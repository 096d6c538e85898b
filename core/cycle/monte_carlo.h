#pragma once

// Monte Carlo of the single-touch trigger error (docs/model.md, "Monte Carlo";
// "One touch"): the wait for the next scan is uniform in [0, t_s] and the probe
// adds its repeatability (normal, 2 sigma as specified). The mean lag is what
// calibration removes, so errors are reported about it.

#include <cstdint>
#include <vector>

#include "core/cycle/scenario.h"

namespace probecycle {

struct Histogram {
    double lo_mm{0.0};
    double bin_width_mm{0.0};
    std::vector<std::uint64_t> counts;
    double mean_mm{0.0};
    double stddev_mm{0.0};
    double min_mm{0.0};
    double max_mm{0.0};
};

// Reproducible: the same seed gives the same histogram with the same standard
// library (the std:: distributions' algorithms are the library's own).
struct MonteCarloOptions {
    std::uint64_t samples{100000};
    std::uint64_t seed{42};
    int bins{50};
};

// At the measuring touch's trigger speed (see CycleResult::measuring_touch()).
Histogram monte_carlo_trigger_error(const Scenario& scenario, const MonteCarloOptions& options);
// The same for a given trigger speed.
Histogram monte_carlo_trigger_error(const Machine& machine, const Probe& probe,
                                    double trigger_speed_mm_s, const MonteCarloOptions& options);

}  // namespace probecycle
