#include "core/cycle/monte_carlo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>

#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"

namespace probecycle {
namespace {

// 3000 mm/min with a 4 ms scan: a 0.2 mm range.
constexpr double kSpeed_mm_s = 50.0;

Machine scanned_machine() {
    Machine m;
    m.scan_period_s = 0.004;
    m.latched_input = false;
    return m;
}

Probe probe_with_repeatability(double rep_2sigma_mm) {
    Probe p;
    p.repeatability_2sigma_mm = rep_2sigma_mm;
    return p;
}

std::uint64_t total_count(const Histogram& h) {
    return std::accumulate(h.counts.begin(), h.counts.end(), std::uint64_t{0});
}

void expect_consistent(const Histogram& h, const MonteCarloOptions& options) {
    ASSERT_EQ(h.counts.size(), static_cast<std::size_t>(options.bins));
    EXPECT_EQ(total_count(h), options.samples);
    EXPECT_TRUE(std::isfinite(h.lo_mm));
    EXPECT_TRUE(std::isfinite(h.bin_width_mm));
    EXPECT_TRUE(std::isfinite(h.mean_mm));
    EXPECT_TRUE(std::isfinite(h.stddev_mm));
    EXPECT_GE(h.bin_width_mm, 0.0);
    EXPECT_GE(h.stddev_mm, 0.0);
    EXPECT_LE(h.min_mm, h.mean_mm + 1e-15);
    EXPECT_GE(h.max_mm, h.mean_mm - 1e-15);
    // Every sample inside the histogram's span.
    const double tol = 1e-12 + 1e-9 * (std::abs(h.lo_mm) + h.bin_width_mm * options.bins);
    EXPECT_GE(h.min_mm, h.lo_mm - tol);
    EXPECT_LE(h.max_mm, h.lo_mm + h.bin_width_mm * options.bins + tol);
}

struct TheoryCase {
    const char* name;
    double scan_period_s;
    bool latched;
    double repeatability_2sigma_mm;
};

// clang-format off
const TheoryCase kTheoryCases[] = {
    // name                  t_s [s]   latched  rep 2 sigma [mm]
    {"scan_only",            0.004,    false,   0.0},
    {"scan_and_probe",       0.004,    false,   0.05},
    {"probe_dominates",      0.0004,   false,   0.02},
    {"latched_probe_only",   0.004,    true,    0.002},
};
// clang-format on

class MonteCarloTheory : public testing::TestWithParam<TheoryCase> {};

// Uniform range R = v t_s: sigma = R / sqrt(12); repeatability: sigma = rep / 2.
TEST_P(MonteCarloTheory, StddevAndMeanAsTheoryPredicts) {
    const TheoryCase& c = GetParam();
    Machine m = scanned_machine();
    m.scan_period_s = c.scan_period_s;
    m.latched_input = c.latched;
    const Probe p = probe_with_repeatability(c.repeatability_2sigma_mm);
    MonteCarloOptions options;
    options.samples = 200000;
    options.seed = 42;
    options.bins = 40;
    const Histogram h = monte_carlo_trigger_error(m, p, kSpeed_mm_s, options);
    expect_consistent(h, options);
    const double range = c.latched ? 0.0 : kSpeed_mm_s * c.scan_period_s;
    const double sigma = std::sqrt(range * range / 12.0 +
                                   c.repeatability_2sigma_mm * c.repeatability_2sigma_mm / 4.0);
    EXPECT_NEAR(h.stddev_mm, sigma, 0.01 * sigma);
    // Errors about the mean lag (removed by calibration): centred on 0.
    EXPECT_NEAR(h.mean_mm, 0.0, 5.0 * sigma / std::sqrt(static_cast<double>(options.samples)));
}

INSTANTIATE_TEST_SUITE_P(Cases, MonteCarloTheory, testing::ValuesIn(kTheoryCases),
                         [](const testing::TestParamInfo<TheoryCase>& case_info) {
                             return std::string(case_info.param.name);
                         });

TEST(MonteCarlo, ScanPhaseAloneIsUniformOverTheRange) {
    const Machine m = scanned_machine();
    const Probe p = probe_with_repeatability(0.0);
    MonteCarloOptions options;
    options.samples = 100000;
    options.bins = 20;
    const Histogram h = monte_carlo_trigger_error(m, p, kSpeed_mm_s, options);
    expect_consistent(h, options);
    // Within +-R/2 = +-0.1 mm, and reaching close to both ends.
    EXPECT_GE(h.min_mm, -0.1 - 1e-12);
    EXPECT_LE(h.max_mm, 0.1 + 1e-12);
    EXPECT_LT(h.min_mm, -0.099);
    EXPECT_GT(h.max_mm, 0.099);
    // Flat: every bin wholly inside the range holds about samples / bins.
    for (std::size_t k = 0; k < h.counts.size(); ++k) {
        const double lo = h.lo_mm + h.bin_width_mm * static_cast<double>(k);
        const double hi = lo + h.bin_width_mm;
        if (lo < -0.1 || hi > 0.1) continue;
        const double expected =
            static_cast<double>(options.samples) * h.bin_width_mm / 0.2;  // uniform density
        EXPECT_NEAR(static_cast<double>(h.counts[k]), expected, 6.0 * std::sqrt(expected))
            << "bin " << k;
    }
}

TEST(MonteCarlo, ReproducibleWithTheSameSeedDifferentWithAnother) {
    const Machine m = scanned_machine();
    const Probe p = probe_with_repeatability(0.01);
    MonteCarloOptions options;
    options.samples = 20000;
    options.seed = 42;
    const Histogram a = monte_carlo_trigger_error(m, p, kSpeed_mm_s, options);
    const Histogram b = monte_carlo_trigger_error(m, p, kSpeed_mm_s, options);
    EXPECT_EQ(a.counts, b.counts);
    EXPECT_EQ(a.mean_mm, b.mean_mm);
    EXPECT_EQ(a.stddev_mm, b.stddev_mm);
    EXPECT_EQ(a.min_mm, b.min_mm);
    EXPECT_EQ(a.max_mm, b.max_mm);
    EXPECT_EQ(a.lo_mm, b.lo_mm);
    EXPECT_EQ(a.bin_width_mm, b.bin_width_mm);
    options.seed = 43;
    const Histogram c = monte_carlo_trigger_error(m, p, kSpeed_mm_s, options);
    EXPECT_NE(a.counts, c.counts);
    EXPECT_NE(a.mean_mm, c.mean_mm);
}

TEST(MonteCarlo, ScenarioOverloadUsesTheMeasuringTouch) {
    for (Strategy strategy : {Strategy::single_touch, Strategy::two_touch}) {
        Scenario s;
        s.cycle.strategy = strategy;
        s.cycle.probe_feed_mm_min = 3000.0;
        MonteCarloOptions options;
        options.samples = 5000;
        const Histogram from_scenario = monte_carlo_trigger_error(s, options);
        const double v = evaluate(s).measuring_touch().trigger_speed_mm_s;
        const Histogram direct = monte_carlo_trigger_error(s.machine, s.probe, v, options);
        EXPECT_EQ(from_scenario.counts, direct.counts) << to_string(strategy);
        EXPECT_EQ(from_scenario.stddev_mm, direct.stddev_mm);
    }
}

TEST(MonteCarlo, NoSpreadAtAllIsHandled) {
    // Latched input and a perfect probe: every error is 0.
    Machine m = scanned_machine();
    m.latched_input = true;
    const Probe p = probe_with_repeatability(0.0);
    MonteCarloOptions options;
    options.samples = 1000;
    options.bins = 10;
    const Histogram h = monte_carlo_trigger_error(m, p, kSpeed_mm_s, options);
    expect_consistent(h, options);
    EXPECT_EQ(h.stddev_mm, 0.0);
    EXPECT_EQ(h.mean_mm, 0.0);
}

TEST(MonteCarlo, FewSamplesAndOneBin) {
    const Machine m = scanned_machine();
    const Probe p = probe_with_repeatability(0.001);
    for (std::uint64_t samples : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{7}}) {
        MonteCarloOptions options;
        options.samples = samples;
        options.bins = 1;
        const Histogram h = monte_carlo_trigger_error(m, p, kSpeed_mm_s, options);
        expect_consistent(h, options);
    }
}

}  // namespace
}  // namespace probecycle
