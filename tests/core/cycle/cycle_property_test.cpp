// Properties of evaluate() over 20,000 random valid scenarios (fixed seed),
// half of them with dynamics after interpolation:
// the invariants that must hold whatever the user types, beside the named
// cases in cycle_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"

namespace probecycle {
namespace {

constexpr int kScenarios = 20000;

// A value of a key, log-uniform over the key's range where it spans decades
// (so small delays are drawn as often as large ones), else uniform; zero now
// and then where zero is allowed.
double draw(const KeyInfo& key, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    if (key.min == 0.0 && unit(rng) < 0.1) return 0.0;
    const double low = key.min > 0.0 ? key.min : key.max * 1e-6;
    if (key.max / low > 100.0) return low * std::pow(key.max / low, unit(rng));
    return low + (key.max - low) * unit(rng);
}

Scenario random_valid_scenario(std::mt19937_64& rng) {
    for (;;) {
        Scenario s;
        for (const KeyInfo& key : numeric_keys()) set_number(s, key.key, draw(key, rng));
        s.cycle.repeats = std::round(s.cycle.repeats);  // a whole number
        std::uniform_int_distribution<int> pick(0, 99);
        s.machine.accel_model = static_cast<AccelModel>(pick(rng) % 4);
        // Half without dynamics after interpolation (the servo drawn 0 a
        // tenth of the time as well), half with one of the three filters.
        s.machine.filter =
            pick(rng) % 2 == 0 ? FilterKind::none : static_cast<FilterKind>(1 + pick(rng) % 3);
        if (pick(rng) % 2 == 0) s.machine.servo_time_constant_s = 0.0;
        s.machine.latched_input = pick(rng) % 2 == 0;
        s.cycle.strategy = pick(rng) % 2 == 0 ? Strategy::single_touch : Strategy::two_touch;
        s.cycle.feature = static_cast<Feature>(pick(rng) % 5);
        if (validate(s).empty()) return s;
    }
}

std::string describe(const Scenario& s) {
    return scenario_to_json(s);
}

TEST(CycleProperties, HoldForRandomValidScenarios) {
    std::mt19937_64 rng(20261124);
    int failures = 0;
    int compared = 0;  // scenarios whose faster twin was valid too
    for (int i = 0; i < kScenarios && failures < 5; ++i) {
        const Scenario s = random_valid_scenario(rng);
        const CycleResult r = evaluate(s);
        std::ostringstream problems;

        // Every output finite and non-negative.
        for (const double value :
             {r.total(), r.overtravel_mm(), r.trigger_speed_mm_s(), r.scan_range_mm(),
              r.uncertainty_mm(), r.recommended_backoff_mm()}) {
            if (!std::isfinite(value) || value < 0.0) problems << "output " << value << "; ";
        }
        // The phases' times sum to the total, and the per-kind sums agree.
        double sum = 0.0;
        for (const PhaseRecord& p : r.phases()) {
            if (!std::isfinite(p.time_s) || p.time_s < 0.0)
                problems << "phase time " << p.time_s << "; ";
            sum += p.time_s;
        }
        double by_kind = 0.0;
        for (const Phase phase : all_phases()) by_kind += r.phase_time(phase);
        const double tolerance = 1e-9 * std::max(1.0, r.total());
        if (std::abs(sum - r.total()) > tolerance) problems << "phases sum " << sum << "; ";
        if (std::abs(by_kind - r.total()) > tolerance) problems << "kinds sum " << by_kind << "; ";
        // No cycle is faster than covering the approach at the probing feed.
        const double floor_s = s.cycle.approach_mm / mm_min_to_mm_s(s.cycle.probe_feed_mm_min);
        if (r.total() < floor_s * (1.0 - 1e-12))
            problems << "under approach/feed " << floor_s << "; ";
        // The first touch overtravels no less at a higher probing feed.
        Scenario faster = s;
        faster.cycle.probe_feed_mm_min = std::min(s.cycle.probe_feed_mm_min * 1.25, 100000.0);
        if (validate(faster).empty()) {
            ++compared;
            const CycleResult rf = evaluate(faster);
            const double before = r.first_touch().overtravel_mm;
            const double after = rf.first_touch().overtravel_mm;
            // Strictly at cruise. Two touches that trigger while still
            // accelerating move alike: with a long servo lag the command may
            // already brake toward its search's end, which lies farther at
            // the faster feed (it follows the stop), so the stop can differ
            // by a few parts in a million either way (scenario 13678: 13.3582
            // against 13.3581 mm, rapid 375 mm/min, servo 0.46 s).
            const auto at_cruise = [](const TouchResult& t) {
                return t.trigger_speed_mm_s >= t.programmed_feed_mm_s * (1.0 - 1e-9);
            };
            const double slack =
                at_cruise(r.first_touch()) && at_cruise(rf.first_touch()) ? 1e-9 : 1e-5;
            if (after < before - slack * std::max(1.0, before)) {
                problems << "first-touch overtravel falls from " << before << " to " << after
                         << " at " << faster.cycle.probe_feed_mm_min << " mm/min; ";
            }
        }
        // A filter or a servo lag never shortens a move.
        const double distance = std::max(s.cycle.approach_mm, 1e-3);
        const double feed = mm_min_to_mm_s(s.cycle.return_feed_mm_min);
        Scenario ideal = s;
        ideal.machine.filter = FilterKind::none;
        ideal.machine.servo_time_constant_s = 0.0;
        if (block_time_s(s, distance, feed) < block_time_s(ideal, distance, feed) * (1.0 - 1e-12)) {
            problems << "a filter shortens a " << distance << " mm move; ";
        }
        if (!problems.str().empty()) {
            ++failures;
            ADD_FAILURE() << "scenario " << i << ": " << problems.str() << "\n" << describe(s);
        }
    }
    EXPECT_GT(compared, kScenarios / 2) << "too few scenarios had a valid faster twin";
}

}  // namespace
}  // namespace probecycle
