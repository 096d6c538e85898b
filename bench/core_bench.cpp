// probecycle-bench: the core's speed targets (docs/speed.md). Run on one core:
//   probecycle-bench --benchmark_min_time=0.5

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/common/file_io.h"
#include "core/common/units.h"
#include "core/comparison/comparison.h"
#include "core/comparison/comparison_simulator.h"
#include "core/cycle/cycle.h"
#include "core/cycle/motion.h"
#include "core/cycle/motion_cache.h"
#include "core/cycle/preset.h"
#include "core/cycle/sweep.h"
#include "core/optimise/optimiser.h"

namespace {

using namespace probecycle;

struct MoveCase {
    double distance_mm;
    double feed_mm_s;
};

// Realistic moves: 0.01-500 mm at 10-30000 mm/min, log-uniform, fixed seed.
std::vector<MoveCase> random_moves() {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> log_d(std::log(0.01), std::log(500.0));
    std::uniform_real_distribution<double> log_f(std::log(10.0), std::log(30000.0));
    std::vector<MoveCase> moves(4096);
    for (MoveCase& m : moves) {
        m.distance_mm = std::exp(log_d(rng));
        m.feed_mm_s = mm_min_to_mm_s(std::exp(log_f(rng)));
    }
    return moves;
}

void run_moves(benchmark::State& state, const MotionLimits& limits) {
    const std::vector<MoveCase> moves = random_moves();
    std::size_t i = 0;
    for (auto _ : state) {
        const MoveCase& m = moves[i++ & (moves.size() - 1)];
        benchmark::DoNotOptimize(move_time_s(limits, m.distance_mm, m.feed_mm_s));
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void BM_MoveTime_TimeConstant(benchmark::State& state) {
    run_moves(state, {AccelModel::time_constant, 0.06, 2000.0, 40000.0});
}
void BM_MoveTime_ConstantAccel(benchmark::State& state) {
    run_moves(state, {AccelModel::constant_accel, 0.06, 2000.0, 40000.0});
}
void BM_MoveTime_JerkLimited(benchmark::State& state) {
    run_moves(state, {AccelModel::jerk_limited, 0.06, 2000.0, 40000.0});
}

Scenario two_touch_bore() {
    Scenario s;
    s.cycle.strategy = Strategy::two_touch;
    s.cycle.feature = Feature::bore;
    s.cycle.feature_size_mm = 40.0;
    return s;
}

void run_evaluate(benchmark::State& state, const Scenario& scenario) {
    CycleResult result;
    for (auto _ : state) {
        evaluate_into(scenario, result);
        benchmark::DoNotOptimize(result.total());
    }
}

void run_sweep1000(benchmark::State& state, const Scenario& scenario) {
    const std::vector<double> feeds = log_feeds(10.0, 10000.0, 1000);
    SweepResult sweep;
    for (auto _ : state) {
        sweep_feeds_into(scenario, feeds, sweep);
        benchmark::DoNotOptimize(sweep.points.data());
    }
}

// The bore with Fanuc-type dynamics after interpolation: the skip
// feed commanded at once, an exponential filter and a servo lag.
Scenario filtered_bore() {
    Scenario s = two_touch_bore();
    s.machine.accel_model = AccelModel::none;
    s.machine.filter = FilterKind::exponential;
    s.machine.filter_time_s = 0.032;
    s.machine.servo_time_constant_s = 0.033;
    s.machine.in_position_mm = 0.02;
    s.cycle.backoff_mm = 3.0;  // over the recommended 2.63 mm: a valid cycle
    return s;
}

// The bore on the two other presets' machines, read from resources/presets
// (so the figures follow the files): a Mitsubishi-type G31 without acc/dec
// (the feed at once, a servo lag alone) and linear acc/dec after
// interpolation (a moving average and a servo); and the slowest combination
// the model has, a bell filter (32 ms and 10 ms windows) after a jerk-limited
// plan, with a 33 ms servo.
Scenario preset_bore(const char* preset) {
    Scenario s = two_touch_bore();
    s.cycle.backoff_mm = 3.0;  // over the recommended backoff of both presets: valid cycles
    return merge_json(s,
                      parse_preset(read_text_file(std::string(PROBECYCLE_PRESETS_DIR "/") + preset))
                          .scenario_json);
}
Scenario mitsubishi_bore() {
    return preset_bore("machine_mitsubishi_g31.json");
}
Scenario linear_filter_bore() {
    return preset_bore("machine_linear_after_interpolation.json");
}
Scenario bell_jerk_bore() {
    Scenario s = filtered_bore();  // its servo and in-position width
    s.machine.accel_model = AccelModel::jerk_limited;
    s.machine.filter = FilterKind::bell;
    s.machine.filter2_time_s = 0.01;  // after the first window, filter_time_s (32 ms)
    s.cycle.backoff_mm = 3.5;         // over the recommended 3.23 mm: a valid cycle
    return s;
}
Scenario as_surface(Scenario s) {
    s.cycle.feature = Feature::surface;  // as BM_Sweep1000: the default surface
    return s;
}

void BM_Evaluate(benchmark::State& state) {
    run_evaluate(state, two_touch_bore());
}
void BM_Evaluate_Mitsubishi(benchmark::State& state) {
    run_evaluate(state, mitsubishi_bore());
}
void BM_Evaluate_LinearFilter(benchmark::State& state) {
    run_evaluate(state, linear_filter_bore());
}
void BM_Evaluate_BellJerk(benchmark::State& state) {
    run_evaluate(state, bell_jerk_bore());
}
void BM_Sweep1000_Mitsubishi(benchmark::State& state) {
    run_sweep1000(state, as_surface(mitsubishi_bore()));
}
void BM_Sweep1000_LinearFilter(benchmark::State& state) {
    run_sweep1000(state, as_surface(linear_filter_bore()));
}
void BM_Sweep1000_BellJerk(benchmark::State& state) {
    run_sweep1000(state, as_surface(bell_jerk_bore()));
}

void BM_Evaluate_Filtered(benchmark::State& state) {
    run_evaluate(state, filtered_bore());
}

// A candidate evaluation as the sweeps, the knee search, the optimiser and the
// fixes make them: the summary (Detail::summary) on a MotionCache already
// bound to the machine, at another probing feed each time (256 feeds from
// 100 to 2000 mm/min, more than the cache holds: every first touch is solved
// afresh; the moves and the measuring touch, which do not change with the
// feed, come from the cache).
void BM_Evaluate_Filtered_Candidate(benchmark::State& state) {
    Scenario scenario = filtered_bore();
    const std::vector<double> feeds = log_feeds(100.0, 2000.0, 256);
    CycleResult result;
    MotionCache cache;
    std::size_t i = 0;
    for (auto _ : state) {
        scenario.cycle.probe_feed_mm_min = feeds[i++ % feeds.size()];
        evaluate_into(scenario, result, cache, Detail::summary);
        benchmark::DoNotOptimize(result.total());
    }
}

// The sweep on every interpolator plan with every filter after interpolation:
// BM_Sweep1000_BellJerk's surface (a 33 ms servo, the bell's windows 32 and
// 10 ms, a 3.5 mm backoff) with the plan and the filter replaced. Where the
// 0.5 ms target holds beyond the presets.
void BM_Sweep1000_Dynamics(benchmark::State& state, AccelModel plan, FilterKind filter) {
    Scenario scenario = as_surface(bell_jerk_bore());
    scenario.machine.accel_model = plan;
    scenario.machine.filter = filter;
    run_sweep1000(state, scenario);
}

void BM_Sweep1000(benchmark::State& state) {
    run_sweep1000(state, Scenario{});  // the default: two-touch surface
}

void BM_Sweep1000_Filtered(benchmark::State& state) {
    run_sweep1000(state, as_surface(filtered_bore()));
}

void BM_Analyse(benchmark::State& state) {
    const Scenario scenario = two_touch_bore();
    for (auto _ : state) benchmark::DoNotOptimize(analyse(scenario));
}

// The optimiser on the bore with the defaults (no target: the
// current uncertainty), everything the window shows: the best setting, the
// binding requirements, the advice (a second optimisation with a latched
// input) and the 20-point Pareto front.
void BM_Optimise(benchmark::State& state) {
    const Scenario scenario = two_touch_bore();
    for (auto _ : state) benchmark::DoNotOptimize(optimise(scenario));
}
// The same without the Pareto front and the advice: the best setting alone.
void BM_Optimise_BestOnly(benchmark::State& state) {
    const Scenario scenario = two_touch_bore();
    OptimiseRequirements requirements;
    requirements.pareto_points = 0;
    requirements.advice = false;
    for (auto _ : state) benchmark::DoNotOptimize(optimise(scenario, requirements));
}

// The whole comparison pipeline (C-axis identification with its
// uncertainty, three surface fits, every projection) on the simulator's
// data: 16 x 12 = 192 and 115 x 87 = 10,005 plan points, jittered.
void compare(benchmark::State& state, int columns, int rows) {
    ComparisonSimulationOptions options;
    options.columns = columns;
    options.rows = rows;
    options.omm_noise_mm = 0.0005;
    options.cmm_noise_mm = 0.0003;
    const ComparisonDataSet data = simulate_comparison(options);
    for (auto _ : state) {
        benchmark::DoNotOptimize(run_comparison(data.input));
    }
    state.counters["points"] = static_cast<double>(data.input.plan.size());
}
void BM_Compare200(benchmark::State& state) {
    compare(state, 16, 12);
}
void BM_Compare10000(benchmark::State& state) {
    compare(state, 115, 87);
}
}  // namespace

BENCHMARK(BM_MoveTime_TimeConstant);
BENCHMARK(BM_MoveTime_ConstantAccel);
BENCHMARK(BM_MoveTime_JerkLimited);
BENCHMARK(BM_Evaluate);
BENCHMARK(BM_Evaluate_Filtered);
BENCHMARK(BM_Sweep1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Sweep1000_Filtered)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Evaluate_Mitsubishi);
BENCHMARK(BM_Sweep1000_Mitsubishi)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Evaluate_LinearFilter);
BENCHMARK(BM_Sweep1000_LinearFilter)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Evaluate_BellJerk);
BENCHMARK(BM_Evaluate_Filtered_Candidate);
BENCHMARK(BM_Sweep1000_BellJerk)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Analyse)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Optimise)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Optimise_BestOnly)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_Compare200)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Compare10000)->Unit(benchmark::kMillisecond);

// BM_Sweep1000_Dynamics/<plan>/<filter>, named by the scenario files' words.
const bool kSweepMatrixRegistered = [] {
    for (const AccelModel plan : {AccelModel::time_constant, AccelModel::constant_accel,
                                  AccelModel::jerk_limited, AccelModel::none}) {
        for (const FilterKind filter :
             {FilterKind::none, FilterKind::linear, FilterKind::exponential, FilterKind::bell}) {
            const std::string name =
                std::string("BM_Sweep1000_Dynamics/") + to_string(plan) + "/" + to_string(filter);
            benchmark::RegisterBenchmark(name.c_str(), BM_Sweep1000_Dynamics, plan, filter)
                ->Unit(benchmark::kMicrosecond);
        }
    }
    return true;
}();

BENCHMARK_MAIN();
