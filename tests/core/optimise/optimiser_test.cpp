// The optimiser (core/optimise/optimiser.h): on varied scenarios
// (every acceleration model, a filter after interpolation, both strategies,
// surface, bore, pocket and boss, a latched input, a part position
// uncertainty, a probe's maximum feed) its best setting meets every
// requirement, re-evaluates to the figures it reports, and is within 0.5 % of
// the fastest a brute force over a grid of every free setting finds; a
// hand-computed case; impossible requirements; the Pareto front. The brute
// force runs on evaluate() and on a stand-in for the model once it averages
// repeats, where it tries repeat counts up to 20.

#include "core/optimise/optimiser.h"
#include "core/cycle/preset.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/common/file_io.h"
#include "core/common/input_error.h"
#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"
#include "core/optimise/optimise_json.h"

namespace probecycle {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The search is tested on the trigger's part of the uncertainty, which the
// feeds and the repeats change, so the hand computations stay short: the
// budget's fixed terms are zero here unless a case sets them (as
// OptimiserBudget's tests do; uncertainty.h). So are the optimiser's bounds
// (a known part, no shortest start, 1 mm/min the slowest feed), which
// OptimiserBounds' tests set.
Scenario without_fixed_terms(Scenario s) {
    s.probe.lobing_mm = s.probe.artefact_uncertainty_mm = 0.0;
    s.machine.repeatability_2sigma_mm = s.machine.thermal_drift_mm = 0.0;
    return s;
}

// What optimise() refuses a scenario with: its message's code and text.
std::pair<std::string, std::string> refusal(const Scenario& s) {
    try {
        optimise(s);
    } catch (const InputError& e) {
        return {e.to_message().code, e.what()};
    }
    ADD_FAILURE() << "no error";
    return {};
}

Scenario scenario_with(const std::vector<std::string>& sets) {
    Scenario s = without_fixed_terms(Scenario{});
    s.cycle.part_position_uncertainty_mm = 0.0;
    s.cycle.min_start_mm = 0.0;
    s.cycle.min_feed_mm_min = 1.0;
    for (const std::string& set : sets) apply_setting(s, set);
    validate_or_throw(s);
    return s;
}

double uncertainty_bound(const Scenario& s, const CycleModel& model) {
    if (s.cycle.target_uncertainty_mm > 0.0) return s.cycle.target_uncertainty_mm;
    ModelPoint current;
    model(s, current);
    return current.uncertainty_mm;
}

// Every requirement of the issue, checked here without the optimiser's code.
bool meets_requirements(const Scenario& s, const ModelPoint& p, double fraction, double bound) {
    const Cycle& c = s.cycle;
    if (!validate(s).empty() || !p.valid) return false;
    if (p.uncertainty_mm > bound * (1.0 + 1e-12)) return false;
    if (p.overtravel_mm > fraction * s.probe.overtravel_limit_mm) return false;
    const bool two = c.strategy == Strategy::two_touch;
    for (const double feed : {c.probe_feed_mm_min, two ? c.measure_feed_mm_min : 1.0}) {
        if (feed < 1.0 || feed > s.machine.rapid_feed_mm_min) return false;
        if (s.probe.max_feed_mm_min > 0.0 && feed > s.probe.max_feed_mm_min) return false;
    }
    return c.approach_mm >= c.part_position_uncertainty_mm +
                                approach_room_mm(s, mm_min_to_mm_s(c.probe_feed_mm_min));
}

// A feed of the editors' digits (1 mm/min from 100 up, 0.1 below).
bool on_feed_digits(double feed) {
    const double scaled = feed >= 100.0 ? feed : feed * 10.0;
    return std::abs(scaled - std::round(scaled)) < 1e-9;
}

struct BruteForce {
    double time_s{kInf};
    Scenario best;
    long evaluations{0};
};

std::vector<double> log_grid(double lo, double hi, int n) {
    std::vector<double> out;
    if (!(hi > lo)) return {lo};
    for (int i = 0; i < n; ++i)
        out.push_back(lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1)));
    return out;
}

std::vector<double> linear_grid(double lo, double hi, int n) {
    std::vector<double> out;
    for (int i = 0; i < n; ++i) out.push_back(lo + (hi - lo) * i / (n - 1));
    return out;
}

// The brute force: every strategy and repeat count, probing and measuring
// feeds on a grid, start distances on a grid (and the start rule's
// smallest), backoffs around the one the model recommends and on a grid;
// then the same again on a fine grid around the best feeds. Every setting
// checked against every requirement.
class Brute {
  public:
    Brute(const Scenario& s, const CycleModel& model, double fraction, std::vector<int> repeats)
        : s_(s), model_(model), fraction_(fraction), repeats_(std::move(repeats)) {
        bound_ = uncertainty_bound(s, model);
        cap_ = s.machine.rapid_feed_mm_min;
        if (s.probe.max_feed_mm_min > 0.0) cap_ = std::min(cap_, s.probe.max_feed_mm_min);
        cap_ = std::min(cap_, 100000.0);
    }

    BruteForce run(int coarse, int fine) {
        BruteForce out;
        for (const Strategy strategy : {Strategy::single_touch, Strategy::two_touch}) {
            const bool two = strategy == Strategy::two_touch;
            for (const int n : repeats_) {
                const std::vector<double> feeds = log_grid(1.0, cap_, coarse);
                double best_f1 = 0.0;
                double best_fm = 0.0;
                double best = kInf;
                for (const double f1 : feeds) {
                    for (const double fm : two ? feeds : std::vector<double>{f1}) {
                        const double t = try_feeds(strategy, n, f1, fm, out);
                        if (t < best) {
                            best = t;
                            best_f1 = f1;
                            best_fm = fm;
                        }
                    }
                }
                if (!std::isfinite(best)) continue;
                // Fine: within a coarse step either side, in whole mm/min.
                const double step = std::pow(cap_, 1.0 / (coarse - 1));
                const auto near = [&](double f) {
                    std::vector<double> grid =
                        linear_grid(std::max(1.0, f / step), std::min(cap_, f * step), fine);
                    for (double& g : grid)
                        g = g >= 100.0 ? std::floor(g) : std::floor(g * 10.0) / 10.0;
                    return grid;
                };
                for (const double f1 : near(best_f1)) {
                    for (const double fm : two ? near(best_fm) : std::vector<double>{f1}) {
                        try_feeds(strategy, n, f1, fm, out);
                    }
                }
            }
        }
        return out;
    }

  private:
    double try_feeds(Strategy strategy, int n, double f1, double fm, BruteForce& out) {
        const bool two = strategy == Strategy::two_touch;
        Scenario s = s_;
        s.cycle.strategy = strategy;
        s.cycle.repeats = n;
        s.cycle.probe_feed_mm_min = f1;
        s.cycle.measure_feed_mm_min = two ? fm : f1;
        const double room =
            s.cycle.part_position_uncertainty_mm + approach_room_mm(s, mm_min_to_mm_s(f1));
        std::vector<double> approaches = {std::ceil(room * 100.0 - 1e-9) / 100.0,
                                          std::ceil(room * 100.0) / 100.0 + 0.01, room + 1.0,
                                          room + 5.0};
        const bool internal =
            s.cycle.feature == Feature::bore || s.cycle.feature == Feature::pocket;
        if (internal) {
            for (const double a : linear_grid(0.01, 0.5 * s.cycle.feature_size_mm, 12))
                approaches.push_back(std::floor(a * 100.0) / 100.0);
            approaches.push_back(std::ceil(0.5 * s.cycle.feature_size_mm * 100.0) / 100.0 - 0.01);
        }
        double best = kInf;
        ModelPoint p;
        for (const double a : approaches) {
            if (a < 0.0 || a > 1000.0) continue;
            s.cycle.approach_mm = a;
            std::vector<double> backoffs = {0.0};
            if (two) {
                s.cycle.backoff_mm = 1.0;
                model_(s, p);
                ++out.evaluations;
                const double rec = p.recommended_backoff_mm;
                backoffs = {rec - 0.001, rec, rec + 0.001, rec + 0.1, rec + 1.0};
                for (const double g : linear_grid(0.5, 8.0, 6)) backoffs.push_back(g);
            }
            for (const double b : backoffs) {
                if (b < 0.0) continue;
                s.cycle.backoff_mm = b;
                model_(s, p);
                ++out.evaluations;
                if (!meets_requirements(s, p, fraction_, bound_)) continue;
                best = std::min(best, p.cycle_time_s);
                if (p.cycle_time_s < out.time_s) {
                    out.time_s = p.cycle_time_s;
                    out.best = s;
                }
            }
        }
        return best;
    }

    Scenario s_;
    const CycleModel& model_;
    double fraction_;
    std::vector<int> repeats_;
    double bound_{0.0};
    double cap_{0.0};
};

// What every optimised result must satisfy, whatever the scenario.
void expect_sound(const Scenario& s, const OptimiseResult& r, const CycleModel& model,
                  double fraction) {
    const Scenario applied = with_settings(s, r.best.settings);
    ModelPoint p;
    model(applied, p);
    EXPECT_TRUE(meets_requirements(applied, p, fraction, uncertainty_bound(s, model)))
        << "time " << p.cycle_time_s << " u " << p.uncertainty_mm << " ot " << p.overtravel_mm;
    EXPECT_TRUE(unmet_requirements(applied, p, fraction, r.uncertainty_bound_mm).empty());
    // The figures reported are those of the settings as written.
    EXPECT_EQ(p.cycle_time_s, r.best.cycle_time_s);
    EXPECT_EQ(p.uncertainty_mm, r.best.uncertainty_mm);
    EXPECT_EQ(p.overtravel_mm, r.best.overtravel_mm);
    EXPECT_TRUE(on_feed_digits(r.best.settings.probe_feed_mm_min))
        << r.best.settings.probe_feed_mm_min;
    EXPECT_TRUE(on_feed_digits(r.best.settings.measure_feed_mm_min));
    EXPECT_NEAR(r.best.settings.approach_mm * 100.0,
                std::round(r.best.settings.approach_mm * 100.0), 1e-6);
    EXPECT_NEAR(r.saved_s, r.current.cycle_time_s - r.best.cycle_time_s, 1e-12);
    // The Pareto front: uncertainty rises, time falls; each point sound.
    for (std::size_t i = 0; i < r.pareto.size(); ++i) {
        const Candidate& c = r.pareto[i];
        const Scenario point = with_settings(s, c.settings);
        model(point, p);
        EXPECT_TRUE(meets_requirements(point, p, fraction, kInf)) << i;
        EXPECT_EQ(p.cycle_time_s, c.cycle_time_s);
        if (i > 0) {
            EXPECT_GT(c.uncertainty_mm, r.pareto[i - 1].uncertainty_mm) << i;
            EXPECT_LT(c.cycle_time_s, r.pareto[i - 1].cycle_time_s) << i;
        }
    }
}

// The repeat counts the brute force tries: one while the model gives every
// count the same cycle (before it averages repeats), else a spread to 20.
std::vector<int> repeat_counts(const Scenario& s, const CycleModel& model) {
    Scenario two = s;
    two.cycle.repeats = 2.0;
    Scenario one = s;
    one.cycle.repeats = 1.0;
    ModelPoint p1;
    ModelPoint p2;
    model(one, p1);
    model(two, p2);
    if (p1.cycle_time_s == p2.cycle_time_s && p1.uncertainty_mm == p2.uncertainty_mm) return {1};
#if defined(__SANITIZE_ADDRESS__)
    // Under the sanitizers (a Debug build, ~50 times slower) fewer counts:
    // that run looks for memory errors, the Release run for the optimum.
    return {1, 3, 20};
#else
    return {1, 2, 3, 5, 8, 13, 20};
#endif
}

struct BruteCase {
    const char* name;
    std::vector<std::string> sets;
    int coarse{36};
    int fine{32};
};

void averaged_repeats_model(const Scenario& s, ModelPoint& p);

// The optimiser on `model` against the brute force on the same model.
void expect_as_fast_as_brute_force(const BruteCase& c, const CycleModel& model) {
    const Scenario s = scenario_with(c.sets);
    OptimiseRequirements requirements;
    requirements.pareto_points = 8;
    const OptimiseResult r = optimise(s, requirements, model);
    expect_sound(s, r, model, requirements.max_overtravel_fraction);

#if defined(__SANITIZE_ADDRESS__)
    // Halved where the case's grid is fine enough to halve.
    const int coarse = c.coarse >= 24 ? c.coarse / 2 : c.coarse;
    const int fine = c.fine >= 24 ? c.fine / 2 : c.fine;
#else
    const int coarse = c.coarse;
    const int fine = c.fine;
#endif
    const BruteForce brute =
        Brute(s, model, requirements.max_overtravel_fraction, repeat_counts(s, model))
            .run(coarse, fine);
    ASSERT_TRUE(std::isfinite(brute.time_s));
    EXPECT_LE(r.best.cycle_time_s, brute.time_s * 1.005)
        << "brute force: " << to_string(brute.best.cycle.strategy) << " N "
        << brute.best.cycle.repeats << " " << brute.best.cycle.probe_feed_mm_min << "/"
        << brute.best.cycle.measure_feed_mm_min << " backoff " << brute.best.cycle.backoff_mm
        << " approach " << brute.best.cycle.approach_mm
        << "; optimiser: " << to_string(r.best.settings.strategy) << " N "
        << r.best.settings.repeats << " " << r.best.settings.probe_feed_mm_min << "/"
        << r.best.settings.measure_feed_mm_min << " approach " << r.best.settings.approach_mm;
    // The brute force checks the same requirements on a subset of the
    // settings: it cannot beat the optimum by more than the rounding.
    EXPECT_GE(r.best.cycle_time_s, brute.time_s * 0.9);
}

class OptimiserAgainstBruteForce : public testing::TestWithParam<BruteCase> {};

TEST_P(OptimiserAgainstBruteForce, FindsTheFastestValidSettingWithinHalfAPercent) {
    expect_as_fast_as_brute_force(GetParam(), CycleModel(evaluate_point));
}

// The same on a stand-in for the model once it averages repeats (below):
// the brute force then tries repeat counts up to 20.
class OptimiserAgainstBruteForceAveragedRepeats : public testing::TestWithParam<BruteCase> {};

TEST_P(OptimiserAgainstBruteForceAveragedRepeats, FindsTheFastestValidSettingWithinHalfAPercent) {
    expect_as_fast_as_brute_force(GetParam(), CycleModel(averaged_repeats_model));
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(Optimise, OptimiserAgainstBruteForceAveragedRepeats, testing::Values(
    BruteCase{"surface_target", {"cycle.target_uncertainty_mm=0.003"}},
    BruteCase{"bore_jerk_limited", {"machine.accel_model=jerk_limited", "cycle.feature=bore", "cycle.feature_size_mm=30", "cycle.target_uncertainty_mm=0.01"}},
    BruteCase{"surface_fanuc_filter", {"machine.accel_model=none", "machine.filter=exponential", "machine.filter_time_s=0.032", "machine.servo_time_constant_s=0.033", "cycle.target_uncertainty_mm=0.006"}, 16, 12},
    BruteCase{"pocket_part_uncertainty", {"cycle.feature=pocket", "cycle.part_position_uncertainty_mm=2", "cycle.target_uncertainty_mm=0.008"}}),
    [](const testing::TestParamInfo<BruteCase>& case_info) { return std::string(case_info.param.name); });
// clang-format on

// clang-format off
INSTANTIATE_TEST_SUITE_P(Optimise, OptimiserAgainstBruteForce, testing::Values(
    BruteCase{"surface_time_constant", {}},
    BruteCase{"surface_target", {"cycle.target_uncertainty_mm=0.003"}},
    // The default budget's fixed terms, 3.416 um together: the trigger may have the rest of 5 um.
    BruteCase{"bore_budget", {"probe.lobing_mm=0.001", "probe.artefact_uncertainty_mm=0.001", "machine.repeatability_2sigma_mm=0.002", "machine.thermal_drift_mm=0.002", "cycle.feature=bore", "cycle.target_uncertainty_mm=0.005"}},
    BruteCase{"bore_time_constant", {"cycle.feature=bore", "cycle.target_uncertainty_mm=0.005"}},
    BruteCase{"surface_constant_accel", {"machine.accel_model=constant_accel", "machine.max_accel_mm_s2=1500", "cycle.target_uncertainty_mm=0.004"}},
    BruteCase{"bore_jerk_limited", {"machine.accel_model=jerk_limited", "cycle.feature=bore", "cycle.feature_size_mm=30", "cycle.target_uncertainty_mm=0.01"}},
    BruteCase{"boss_no_accel", {"machine.accel_model=none", "cycle.feature=boss", "cycle.target_uncertainty_mm=0.02"}},
    BruteCase{"surface_fanuc_filter", {"machine.accel_model=none", "machine.filter=exponential", "machine.filter_time_s=0.032", "machine.servo_time_constant_s=0.033", "cycle.target_uncertainty_mm=0.006"}, 16, 12},
    BruteCase{"surface_latched", {"machine.latched_input=true", "cycle.target_uncertainty_mm=0.002"}},
    BruteCase{"pocket_part_uncertainty", {"cycle.feature=pocket", "cycle.part_position_uncertainty_mm=2", "cycle.target_uncertainty_mm=0.008"}},
    BruteCase{"bore_probe_max_feed", {"cycle.feature=bore", "probe.max_feed_mm_min=1500", "cycle.target_uncertainty_mm=0.05"}},
    BruteCase{"surface_short_stylus", {"probe.overtravel_limit_mm=0.5", "cycle.backoff_from=trigger", "cycle.target_uncertainty_mm=0.01"}},
    // (At 3000 mm/min an obstruction would stop 5.4 mm past on this machine: 2000.)
    BruteCase{"web_slow_machine", {"cycle.feature=web", "machine.time_constant_s=0.2", "machine.rapid_feed_mm_min=5000", "cycle.position_feed_mm_min=2000", "cycle.target_uncertainty_mm=0.1"}}),
    [](const testing::TestParamInfo<BruteCase>& case_info) { return std::string(case_info.param.name); });
// clang-format on

// A stand-in for the model once repeats are averaged: N measuring touches
// divide the uncertainty by sqrt(N), and each repeat adds a backoff and a
// measuring approach per touch point.
void averaged_repeats_model(const Scenario& s, ModelPoint& p) {
    evaluate_point(s, p);
    const double n = s.cycle.repeats;
    p.uncertainty_mm /= std::sqrt(n);
    const Cycle& c = s.cycle;
    const double feed = mm_min_to_mm_s(c.strategy == Strategy::two_touch ? c.measure_feed_mm_min
                                                                         : c.probe_feed_mm_min);
    const double again =
        c.strategy == Strategy::two_touch ? std::max(c.backoff_mm, 0.2) : c.approach_mm;
    p.cycle_time_s += (n - 1.0) * touch_count(c.feature) * (again / feed + 0.1);
}

TEST(Optimiser, WithAveragedRepeatsFindsTheFastestRepeatCount) {
    const CycleModel model(averaged_repeats_model);
    // A target under the repeatability: at least two repeats.
    for (const double target : {0.0008, 0.0012, 0.004}) {
        SCOPED_TRACE(target);
        const Scenario s = scenario_with({"cycle.target_uncertainty_mm=" + std::to_string(target)});
        OptimiseRequirements requirements;
        requirements.pareto_points = 5;
        const OptimiseResult r = optimise(s, requirements, model);
        expect_sound(s, r, model, requirements.max_overtravel_fraction);
        if (target < 0.001) {
            EXPECT_GE(r.best.settings.repeats, 2);
        }
        const BruteForce brute = Brute(s, model, 0.8, {1, 2, 3, 4, 5, 6}).run(16, 12);
        ASSERT_TRUE(std::isfinite(brute.time_s));
        EXPECT_LE(r.best.cycle_time_s, brute.time_s * 1.005)
            << "brute force: " << to_string(brute.best.cycle.strategy) << " N "
            << brute.best.cycle.repeats << " " << brute.best.cycle.probe_feed_mm_min << "/"
            << brute.best.cycle.measure_feed_mm_min << "; optimiser N " << r.best.settings.repeats
            << " " << r.best.settings.probe_feed_mm_min << "/"
            << r.best.settings.measure_feed_mm_min;
    }
}

// Hand-computed: a surface with a latched input (the uncertainty is the
// repeatability at any feed, so single-touch wins), no acceleration (the feed
// at once, so the start rule needs no room: the start distance is the part
// position uncertainty, 2 mm) and no delays but the scan t_s = 4 ms. The cycle
// is T(v) = (s + p)/v + t_s + (s + p + v t_s)/v_r, falling up to
// v = sqrt((s + p) v_r / t_s) = 17343 mm/min; the overtravel p + v t_s at
// most half the 1 mm limit caps it first: v = (0.5 - 0.0051)/0.004 =
// 123.725 mm/s = 7423.5 mm/min, to the editors' digits 7423.
// A bore on the Fanuc-type machine (lags of 85 ms) at the default
// 120 % feed override: its protected moves at 3000 mm/min meet an obstruction
// at 3600 mm/min and stop 5.105 mm past it, over the 5 mm limit, so every
// setting is invalid and no probing setting changes that. The optimiser
// lowers the positioning feed to the highest that keeps the stop within its
// overtravel requirement and says so in the best settings, which run.
TEST(Optimiser, LowersAPositioningFeedThatWouldOverrunTheStylus) {
    const Scenario s = scenario_with(
        {"machine.accel_model=none", "machine.filter=exponential", "machine.filter_time_s=0.032",
         "machine.servo_time_constant_s=0.033", "machine.controller_latency_s=0.014",
         "cycle.feature=bore", "cycle.feature_size_mm=40", "cycle.position_feed_mm_min=3000",
         "cycle.target_uncertainty_mm=0.005"});
    ASSERT_FALSE(evaluate(s).valid());
    EXPECT_NEAR(protected_move_overtravel_mm(s, 50.0), 0.005 + 60.0 * 0.085, 1e-9);
    OptimiseRequirements requirements;
    requirements.pareto_points = 0;
    requirements.advice = false;
    const OptimiseResult r = optimise(s, requirements);
    EXPECT_FALSE(r.current_meets_requirements);
    // Under (4 - 0.005) / (1.2 x 0.085) mm/s = 39.167 mm/s, 2350 mm/min, rounded down.
    EXPECT_EQ(r.best.settings.position_feed_mm_min, 2349.0);
    EXPECT_LT(protected_move_overtravel_mm(s, mm_min_to_mm_s(2349.0)), 0.8 * 5.0);
    EXPECT_GT(protected_move_overtravel_mm(s, mm_min_to_mm_s(2351.0)), 0.8 * 5.0);
    const Scenario best = with_settings(s, r.best.settings);
    const CycleResult run = evaluate(best);
    EXPECT_TRUE(run.valid());
    EXPECT_DOUBLE_EQ(run.total(), r.best.cycle_time_s);
    // A positioning feed that does not overrun the stylus is left as it is.
    Scenario safe = s;
    safe.cycle.position_feed_mm_min = 2000.0;
    EXPECT_EQ(optimise(safe, requirements).best.settings.position_feed_mm_min, 2000.0);
}

// "Binding" means that relaxing the requirement makes the best
// setting faster. Checked here through optimise() itself, on the bore with a
// 5 um target whose best setting lies well under it (a single touch at about
// 3 um: the target does not bind) and with a part position uncertainty of
// 0.5 mm and a probe rated to 5000 mm/min (the customer's bore in docs/cli.md): every
// requirement named binding, relaxed by 10 %, gives a faster best setting,
// and the target, relaxed, does not where it is not named.
TEST(Optimiser, EveryBindingRequirementRelaxedGivesAFasterBest) {
    // Binding means faster by at least 0.1 % of the cycle (kMeaningfulSaving).
    OptimiseRequirements requirements;
    requirements.pareto_points = 0;
    requirements.advice = false;
    const auto best_time = [&](const Scenario& s, double fraction) {
        OptimiseRequirements r = requirements;
        r.max_overtravel_fraction = fraction;
        return optimise(s, r).best.cycle_time_s;
    };
    const std::vector<Scenario> cases = {
        scenario_with({"cycle.feature=bore", "cycle.feature_size_mm=40",
                       "cycle.target_uncertainty_mm=0.005", "cycle.backoff_mm=3",
                       "cycle.probe_feed_mm_min=3000"}),
        scenario_with({"cycle.feature=bore", "cycle.feature_size_mm=40",
                       "cycle.target_uncertainty_mm=0.005", "cycle.backoff_mm=3",
                       "cycle.probe_feed_mm_min=3000", "cycle.part_position_uncertainty_mm=0.5",
                       "probe.max_feed_mm_min=5000"}),
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
        SCOPED_TRACE(k);
        const Scenario& s = cases[k];
        const OptimiseResult r = optimise(s, requirements);
        const double best = r.best.cycle_time_s;
        const auto binds = [&](Requirement q) {
            return std::find(r.binding.begin(), r.binding.end(), q) != r.binding.end();
        };
        Scenario relaxed = s;
        relaxed.cycle.target_uncertainty_mm *= 1.1;
        EXPECT_EQ(binds(Requirement::target_uncertainty),
                  best_time(relaxed, 0.8) < best * (1.0 - 1e-3))
            << r.best.uncertainty_mm;
        EXPECT_EQ(binds(Requirement::overtravel_fraction),
                  best_time(s, 0.88) < best * (1.0 - 1e-3));
        if (s.probe.max_feed_mm_min > 0.0) {
            relaxed = s;
            relaxed.probe.max_feed_mm_min *= 1.1;
            EXPECT_EQ(binds(Requirement::probe_max_feed),
                      best_time(relaxed, 0.8) < best * (1.0 - 1e-3));
        }
        if (s.cycle.part_position_uncertainty_mm > 0.0) {
            relaxed = s;
            relaxed.cycle.part_position_uncertainty_mm /= 1.1;
            EXPECT_EQ(binds(Requirement::start_distance),
                      best_time(relaxed, 0.8) < best * (1.0 - 1e-3));
        }
        if (k == 0) {  // the best lies well under the 5 um target: not binding
            EXPECT_LT(r.best.uncertainty_mm, 0.8 * 0.005);
            EXPECT_FALSE(binds(Requirement::target_uncertainty));
        } else {  // docs/cli.md's customer bore: the target binds; the probe's
                  // 5000 mm/min relaxed saves 0.46 ms of 5.18 s, under 0.1 %: not
            EXPECT_TRUE(binds(Requirement::target_uncertainty));
            EXPECT_FALSE(binds(Requirement::probe_max_feed));
        }
    }
}

TEST(Optimiser, HandComputedSingleTouchIsCappedByTheOvertravelFraction) {
    const Scenario s = scenario_with(
        {"machine.accel_model=none", "machine.latched_input=true", "machine.controller_latency_s=0",
         "probe.interface_delay_s=0", "probe.pretravel_mm=0.0051", "probe.overtravel_limit_mm=1",
         "cycle.strategy=single_touch", "cycle.part_position_uncertainty_mm=2",
         "cycle.feed_override_max_pct=100"});
    OptimiseRequirements requirements;
    requirements.max_overtravel_fraction = 0.5;
    const OptimiseResult r = optimise(s, requirements);
    EXPECT_EQ(r.best.settings.strategy, Strategy::single_touch);
    EXPECT_EQ(r.best.settings.probe_feed_mm_min, 7423.0);
    EXPECT_EQ(r.best.settings.approach_mm, 2.0);
    const double v = 7423.0 / 60.0;
    const double v_return = 10000.0 / 60.0;
    const double overtravel = 0.0051 + v * 0.004;
    EXPECT_NEAR(r.best.overtravel_mm, overtravel, 1e-12);
    // The cycle waits half the 4 ms scan on average and stops v * 2 ms short
    // of the worst-case overtravel.
    const double mean_overtravel = 0.0051 + v * 0.002;
    EXPECT_NEAR(r.best.cycle_time_s, 2.0051 / v + 0.002 + (2.0 + mean_overtravel) / v_return, 1e-9);
    EXPECT_DOUBLE_EQ(r.best.uncertainty_mm, 0.001);
    for (const Requirement binds :
         {Requirement::overtravel_fraction, Requirement::start_distance}) {
        EXPECT_NE(std::find(r.binding.begin(), r.binding.end(), binds), r.binding.end())
            << to_string(binds);
    }
}

TEST(Optimiser, NoTargetKeepsTheCurrentUncertainty) {
    const Scenario s;  // two-touch at 2000 then 30 mm/min, no target
    const OptimiseResult r = optimise(s);
    EXPECT_LE(r.best.uncertainty_mm, r.current.uncertainty_mm * (1.0 + 1e-12));
    EXPECT_EQ(r.uncertainty_bound_mm, r.current.uncertainty_mm);
    EXPECT_TRUE(r.current_meets_requirements);
    EXPECT_GT(r.saved_s, 0.0);
    EXPECT_NE(std::find(r.binding.begin(), r.binding.end(), Requirement::current_uncertainty),
              r.binding.end());
    ASSERT_FALSE(r.advice.empty());
    EXPECT_EQ(r.advice.front().code, "latched_input");
    EXPECT_GT(r.advice.front().saved_s, 0.0);
    EXPECT_FALSE(r.savings.has_value());
}

TEST(Optimiser, SavingsAYear) {
    const Scenario s = scenario_with({"cycle.parts_per_year=100000", "cycle.cycles_per_part=3",
                                      "cycle.machine_rate_per_hour=90"});
    const OptimiseResult r = optimise(s);
    ASSERT_TRUE(r.savings.has_value());
    EXPECT_DOUBLE_EQ(r.savings->saved_per_part_s, 3.0 * r.saved_s);
    EXPECT_DOUBLE_EQ(r.savings->hours_per_year, 3.0 * r.saved_s * 100000.0 / 3600.0);
    ASSERT_TRUE(r.savings->cost_per_year.has_value());
    EXPECT_DOUBLE_EQ(*r.savings->cost_per_year, r.savings->hours_per_year * 90.0);
}

TEST(Optimiser, ATargetUnderTheRepeatabilityIsRefusedNamingIt) {
    // Before the model averages repeats the smallest is the repeatability;
    // after, the repeatability / sqrt(20). 0.0002 is under both.
    const auto [code, text] = refusal(scenario_with({"cycle.target_uncertainty_mm=0.0002"}));
    EXPECT_EQ(code, "target_uncertainty");
    EXPECT_NE(text.find("0.0002 mm"), std::string::npos) << text;
    EXPECT_NE(text.find("smallest achievable"), std::string::npos) << text;
}

// The target holds for the whole budget, whose fixed terms no
// feed or repeat count lowers.
TEST(OptimiserBudget, TheBestMeetsTheTargetWithTheFixedTerms) {
    const Scenario s =
        scenario_with({"probe.lobing_mm=0.001", "probe.artefact_uncertainty_mm=0.001",
                       "machine.repeatability_2sigma_mm=0.002", "machine.thermal_drift_mm=0.002",
                       "cycle.target_uncertainty_mm=0.004"});
    // 2 sqrt((1/sqrt3)^2 + 0.5^2 + 1^2 + (2/sqrt3)^2) um.
    const double fixed = 2.0 * std::sqrt(1.0 / 3.0 + 0.25 + 1.0 + 4.0 / 3.0) * 1e-3;
    const OptimiseResult r = optimise(s);
    const CycleResult cycle = evaluate(with_settings(s, r.best.settings));
    EXPECT_NEAR(cycle.uncertainty_mm(), r.best.uncertainty_mm, 1e-12);
    EXPECT_LE(cycle.uncertainty_mm(), 0.004 * (1.0 + 1e-9));
    // The trigger's share is what the fixed terms leave of the target.
    EXPECT_LE(cycle.trigger_uncertainty_mm(),
              std::sqrt(0.004 * 0.004 - fixed * fixed) * (1.0 + 1e-9));
    // And the budget binds it: the same target without the fixed terms
    // allows a faster setting.
    EXPECT_LT(optimise(without_fixed_terms(s)).best.cycle_time_s, r.best.cycle_time_s);
}

TEST(OptimiserBudget, ATargetUnderTheFixedTermsIsRefusedNamingThem) {
    const auto [code, text] = refusal(
        scenario_with({"machine.thermal_drift_mm=0.005", "cycle.target_uncertainty_mm=0.005"}));
    EXPECT_EQ(code, "target_uncertainty");
    // 2 * 5/sqrt(3) um = 5.774 um of thermal drift alone.
    EXPECT_NE(text.find("thermal drift, are 0.005774 mm together"), std::string::npos) << text;
}

TEST(Optimiser, AnOvertravelFractionNoFeedMeetsIsRefusedNamingIt) {
    // 0.005 mm pretravel alone is over 1 % of a 0.1 mm limit.
    const Scenario s = scenario_with({"probe.overtravel_limit_mm=0.1"});
    OptimiseRequirements requirements;
    requirements.max_overtravel_fraction = 0.01;
    try {
        optimise(s, requirements);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.to_message().code, "overtravel_fraction");
        EXPECT_NE(std::string(e.what()).find("1 %"), std::string::npos) << e.what();
    }
    requirements.max_overtravel_fraction = 1.5;
    EXPECT_THROW(optimise(s, requirements), InputError);
}

TEST(Optimiser, ABoreTooSmallForTheStartRuleIsRefusedNamingIt) {
    const Scenario s =
        scenario_with({"cycle.feature=bore", "cycle.feature_size_mm=4", "cycle.approach_mm=1",
                       "cycle.part_position_uncertainty_mm=3"});
    try {
        optimise(s);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.to_message().code, "start_distance");
    }
}

TEST(Optimiser, TheProbesMaximumFeedBindsAndIsAdvised) {
    const Scenario s =
        scenario_with({"probe.max_feed_mm_min=800", "cycle.part_position_uncertainty_mm=5",
                       "cycle.target_uncertainty_mm=0.05"});
    const OptimiseResult r = optimise(s);
    EXPECT_LE(r.best.settings.probe_feed_mm_min, 800.0);
    EXPECT_NE(std::find(r.binding.begin(), r.binding.end(), Requirement::probe_max_feed),
              r.binding.end());
    const auto advice = std::find_if(r.advice.begin(), r.advice.end(),
                                     [](const Advice& a) { return a.code == "probe_max_feed"; });
    ASSERT_NE(advice, r.advice.end());
    EXPECT_GT(advice->saved_s, 0.0);
}

TEST(Optimiser, TheParetoFrontSpansTheUncertainties) {
    const Scenario s = scenario_with({"cycle.feature=bore"});
    const OptimiseResult r = optimise(s);
    ASSERT_GE(r.pareto.size(), 5u);
    // From the smallest achievable (the repeatability at 1 mm/min, averaged
    // over the most measurements) to the fastest's.
    EXPECT_NEAR(r.pareto.front().uncertainty_mm, 0.001 / std::sqrt(double{kMaxRepeats}), 1e-5);
    for (std::size_t i = 1; i < r.pareto.size(); ++i) {
        EXPECT_GT(r.pareto[i].uncertainty_mm, r.pareto[i - 1].uncertainty_mm);
        EXPECT_LT(r.pareto[i].cycle_time_s, r.pareto[i - 1].cycle_time_s);
    }
    // Its fastest end is the fastest setting without an uncertainty
    // requirement: no slower than the best under one.
    EXPECT_LE(r.pareto.back().cycle_time_s, r.best.cycle_time_s);
}

}  // namespace
}  // namespace probecycle

namespace probecycle {
namespace {

// What the optimiser proposes is what a shop would run. On the bore example and
// the defaults, on every machine preset, with the default bounds (the part
// within 0.5 mm, no start under 1 mm, no feed under 10 mm/min) and a 5 um
// target for the whole budget: every start and feed within them, and the
// settings applied ("Apply", --apply) give a valid cycle that carries no error.
TEST(OptimiserBounds, EveryBestOnEveryPresetIsWithinTheBoundsAndValid) {
    const std::filesystem::path resources = PROBECYCLE_RESOURCES_DIR;
    const std::vector<std::pair<std::string, Scenario>> bases = {
        {"defaults", Scenario{}},
        {"bore_two_touch", scenario_from_json(read_text_file(
                               (resources / "examples/bore_two_touch.json").string()))}};
    int checked = 0;
    for (const auto& [name, base] : bases) {
        for (const auto& entry : std::filesystem::directory_iterator(resources / "presets")) {
            if (entry.path().filename().string().rfind("machine_", 0) != 0) continue;
            SCOPED_TRACE(name + " + " + entry.path().filename().string());
            Scenario s =
                merge_json(base, parse_preset(read_text_file(entry.path().string())).scenario_json);
            s.cycle.target_uncertainty_mm = 0.005;
            const OptimiseResult r = optimise(s);
            const Settings& b = r.best.settings;
            EXPECT_GE(b.approach_mm, s.cycle.min_start_mm);
            EXPECT_GE(b.approach_mm, s.cycle.part_position_uncertainty_mm);
            EXPECT_GE(b.probe_feed_mm_min, s.cycle.min_feed_mm_min);
            EXPECT_GE(b.measure_feed_mm_min, s.cycle.min_feed_mm_min);
            const CycleResult applied = evaluate(with_settings(s, b));
            EXPECT_TRUE(applied.valid()) << invalid_codes_text(applied.invalid_codes(), ", ");
            for (const Warning& w : applied.warnings())
                EXPECT_NE(w.severity, Severity::error) << to_string(w.code);
            EXPECT_LE(applied.uncertainty_mm(), 0.005 * (1.0 + 1e-9));
            ++checked;
        }
    }
    EXPECT_GE(checked, 12);
}

// The binding requirements' searches run side by side on other threads:
// the result is the same however the threads are scheduled, run after run,
// and the same as a binding check run alone would give (the relaxed
// overtravel fraction, re-optimised here on this thread).
TEST(Optimiser, TheResultDoesNotDependOnWhichThreadRanWhat) {
    const std::filesystem::path resources = PROBECYCLE_RESOURCES_DIR;
    Scenario s =
        scenario_from_json(read_text_file((resources / "examples/bore_two_touch.json").string()));
    s.cycle.target_uncertainty_mm = 0.005;
    s.probe.max_feed_mm_min = 800.0;
    const std::string first = optimise_to_json(optimise(s));
    for (int run = 0; run < 6; ++run) EXPECT_EQ(optimise_to_json(optimise(s)), first);

    const OptimiseResult r = optimise(s);
    OptimiseRequirements relaxed;
    relaxed.max_overtravel_fraction = 0.8 * 1.1;  // the default, relaxed by 10 %
    relaxed.pareto_points = 0;
    relaxed.advice = false;
    const bool faster = optimise(s, relaxed).best.cycle_time_s < r.best.cycle_time_s * (1.0 - 1e-3);
    const bool named = std::find(r.binding.begin(), r.binding.end(),
                                 Requirement::overtravel_fraction) != r.binding.end();
    EXPECT_EQ(named, faster);
}

// The example bore with the 5 um target: before, a single touch at 6.6
// mm/min starting 0.01 mm from the wall (a known part, no bounds). With
// the defaults no touch starts under 1 mm from its wall.
TEST(OptimiserBounds, TheBoreNoLongerStartsMicrometresFromTheWall) {
    const std::filesystem::path resources = PROBECYCLE_RESOURCES_DIR;
    Scenario s =
        scenario_from_json(read_text_file((resources / "examples/bore_two_touch.json").string()));
    const OptimiseResult r = optimise(s);
    EXPECT_GE(r.best.settings.approach_mm, 1.0);
    s.cycle.part_position_uncertainty_mm = 0.0;
    s.cycle.min_start_mm = 0.0;
    s.cycle.min_feed_mm_min = 1.0;
    const OptimiseResult unbounded = optimise(s);
    EXPECT_LT(unbounded.best.settings.approach_mm, 0.1);  // what the issue found
}

// A shortest start the best setting sits on binds: relaxed by 10 %, the best
// is faster. A slowest feed is the Pareto front's slow end.
TEST(OptimiserBounds, TheShortestStartBindsAndTheSlowestFeedEndsTheFront) {
    Scenario s = scenario_with({"cycle.strategy=single_touch", "cycle.min_start_mm=3",
                                "cycle.min_feed_mm_min=25", "cycle.target_uncertainty_mm=0.01"});
    OptimiseRequirements requirements;
    requirements.pareto_points = 4;
    const OptimiseResult r = optimise(s, requirements);
    EXPECT_DOUBLE_EQ(r.best.settings.approach_mm, 3.0);
    EXPECT_NE(std::find(r.binding.begin(), r.binding.end(), Requirement::start_distance),
              r.binding.end());
    ASSERT_FALSE(r.pareto.empty());
    EXPECT_DOUBLE_EQ(r.pareto.front().settings.measure_feed_mm_min, 25.0);
    for (const Candidate& c : r.pareto) {
        EXPECT_GE(c.settings.probe_feed_mm_min, 25.0);
        EXPECT_GE(c.settings.measure_feed_mm_min, 25.0);
        EXPECT_GE(c.settings.approach_mm, 3.0);
    }
    // The current scenario under the slowest feed is named as unmet.
    s.cycle.probe_feed_mm_min = 20.0;
    const ModelPoint p = [&] {
        ModelPoint point;
        evaluate_point(s, point);
        return point;
    }();
    const std::vector<Requirement> unmet = unmet_requirements(s, p, 0.8, 0.01);
    EXPECT_NE(std::find(unmet.begin(), unmet.end(), Requirement::min_feed), unmet.end());
}

}  // namespace
}  // namespace probecycle
