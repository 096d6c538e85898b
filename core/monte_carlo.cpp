#include "monte_carlo.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "cycle.h"

namespace probecycle {

Histogram monte_carlo_trigger_error(const Machine& machine, const Probe& probe,
                                    double trigger_speed_mm_s, const MonteCarloOptions& options) {
    // domain.md, "Controller response": the scan wait is uniform in [0, t_s]
    // (none with a latched input); its mean, range/2, is removed by calibration.
    const double range = scan_range_mm(machine, trigger_speed_mm_s);
    const double sigma = 0.5 * probe.repeatability_2sigma_mm;
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> scan(0.0, 1.0);
    std::normal_distribution<double> repeat(0.0, 1.0);

    const std::uint64_t n = std::max<std::uint64_t>(options.samples, 1);
    std::vector<double> samples(n);
    double sum = 0.0;
    for (double& x : samples) {
        x = range * (scan(rng) - 0.5) + sigma * repeat(rng);
        sum += x;
    }
    Histogram h;
    const double count = static_cast<double>(n);
    h.mean_mm = sum / count;
    double squares = 0.0;
    for (double x : samples) squares += (x - h.mean_mm) * (x - h.mean_mm);
    h.stddev_mm = n > 1 ? std::sqrt(squares / (count - 1.0)) : 0.0;
    const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
    h.min_mm = *lo;
    h.max_mm = *hi;

    const int bins = std::max(options.bins, 1);
    h.counts.assign(static_cast<std::size_t>(bins), 0);
    h.lo_mm = h.min_mm;
    const double width = h.max_mm - h.min_mm;
    h.bin_width_mm = width > 0.0 ? width / bins : 1.0;
    for (double x : samples) {
        auto bin = static_cast<std::size_t>((x - h.lo_mm) / h.bin_width_mm);
        h.counts[std::min(bin, h.counts.size() - 1)] += 1;
    }
    return h;
}

Histogram monte_carlo_trigger_error(const Scenario& scenario, const MonteCarloOptions& options) {
    const CycleResult cycle = evaluate(scenario);
    return monte_carlo_trigger_error(scenario.machine, scenario.probe,
                                     cycle.measuring_touch().trigger_speed_mm_s, options);
}

}  // namespace probecycle
