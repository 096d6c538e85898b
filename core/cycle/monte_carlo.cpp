#include "core/cycle/monte_carlo.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/cycle/cycle.h"

namespace probecycle {

Histogram monte_carlo_trigger_error(const Machine& machine, const Probe& probe,
                                    double trigger_speed_mm_s, const MonteCarloOptions& options) {
    // The scan wait is uniform in [0, t_s] (none with a latched input); its
    // mean, range/2, is removed by calibration (docs/model.md, "One touch").
    const double range = scan_range_mm(machine, trigger_speed_mm_s);
    const double sigma = 0.5 * probe.repeatability_2sigma_mm;
    const std::uint64_t n = std::max<std::uint64_t>(options.samples, 1);

    // The same seeded sequence twice: once for the moments and the extent,
    // once to bin it, so no sample is kept (1e8 samples cost no memory).
    const auto for_each_sample = [&](auto&& visit) {
        std::mt19937_64 rng(options.seed);
        std::uniform_real_distribution<double> scan(0.0, 1.0);
        std::normal_distribution<double> repeat(0.0, 1.0);
        for (std::uint64_t i = 0; i < n; ++i) {
            const double u = scan(rng);
            visit(range * (u - 0.5) + sigma * repeat(rng));
        }
    };

    Histogram h;
    h.min_mm = std::numeric_limits<double>::infinity();
    h.max_mm = -std::numeric_limits<double>::infinity();
    double mean = 0.0;
    double m2 = 0.0;  // Welford's running sum of squared deviations
    std::uint64_t seen = 0;
    for_each_sample([&](double x) {
        ++seen;
        const double delta = x - mean;
        mean += delta / static_cast<double>(seen);
        m2 += delta * (x - mean);
        h.min_mm = std::min(h.min_mm, x);
        h.max_mm = std::max(h.max_mm, x);
    });
    h.mean_mm = mean;
    h.stddev_mm = n > 1 ? std::sqrt(m2 / static_cast<double>(n - 1)) : 0.0;

    const int bins = std::max(options.bins, 1);
    h.counts.assign(static_cast<std::size_t>(bins), 0);
    h.lo_mm = h.min_mm;
    const double width = h.max_mm - h.min_mm;
    h.bin_width_mm = width > 0.0 ? width / bins : 1.0;
    for_each_sample([&](double x) {
        const auto bin = static_cast<std::size_t>((x - h.lo_mm) / h.bin_width_mm);
        h.counts[std::min(bin, h.counts.size() - 1)] += 1;
    });
    return h;
}

Histogram monte_carlo_trigger_error(const Scenario& scenario, const MonteCarloOptions& options) {
    const CycleResult cycle = evaluate(scenario);
    return monte_carlo_trigger_error(scenario.machine, scenario.probe,
                                     cycle.measuring_touch().trigger_speed_mm_s, options);
}

}  // namespace probecycle
