// The cycle-model subcommands: defaults, evaluate, move, sweep, montecarlo.

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/cli/cli_common.h"
#include "app/cli/commands.h"
#include "core/common/file_io.h"
#include "core/cycle/monte_carlo.h"
#include "core/cycle/cycle_report.h"
#include "core/cycle/sweep.h"
#include "core/common/units.h"

namespace probecycle::cli {

namespace {

using Json = nlohmann::ordered_json;

const KeyInfo& feed_key() {
    return *find_key("cycle.probe_feed_mm_min");
}

void expect_no_positional(const Args& args, const char* command) {
    if (!args.positional.empty()) {
        throw UsageError(std::string(command) + " takes no file; got '" + args.positional[0] + "'");
    }
}

}  // namespace

int run_defaults(std::span<const std::string> argv) {
    const Args args = parse_args(argv, {});
    expect_no_positional(args, "defaults");
    std::cout << scenario_to_json(Scenario{});
    return 0;
}

int run_evaluate(std::span<const std::string> argv) {
    const Scenario scenario = load_scenario(parse_args(argv, {"--set"}));
    std::cout << evaluation_to_json(analyse(scenario));
    return 0;
}

int run_move(std::span<const std::string> argv) {
    const Args args = parse_args(argv, {"--set", "--distance", "--feed"});
    const Scenario scenario = load_scenario(args);
    const double distance = number_option(args, "--distance", 0.0, 100000.0);
    const double feed = number_option(args, "--feed", feed_key().min, 200000.0);
    const MotionLimits limits = scenario.motion_limits();
    const double v = mm_min_to_mm_s(feed);
    Json out = Json::object();
    out["time_s"] = move_time_s(limits, distance, v);
    out["peak_speed_mm_min"] = mm_s_to_mm_min(move_peak_speed_mm_s(limits, distance, v));
    out["accel_model"] = to_string(limits.model);
    std::cout << out.dump(2) << '\n';
    return 0;
}

int run_sweep(std::span<const std::string> argv) {
    const Args args =
        parse_args(argv, {"--set", "--from", "--to", "--step", "--csv"}, {"--recommended-backoff"});
    const Scenario scenario = load_scenario(args);
    const KeyInfo& key = feed_key();
    const double from = number_option(args, "--from", key.min, key.max);
    const double to = number_option(args, "--to", from, key.max);
    const double step = number_option(args, "--step", 1e-6, key.max);
    // Counted before any is made, so an absurd step is refused, not allocated.
    constexpr double kMaxPoints = 1000000;
    const double points = std::floor((to - from) / step + 1e-9) + 1.0;
    if (points > kMaxPoints) {
        throw UsageError("--step: " + std::to_string(static_cast<long long>(points)) +
                         " points from --from to --to; at most 1000000 allowed");
    }
    const std::vector<double> feeds = linear_feeds(from, to, step);
    const SweepOptions options{.recommended_backoff = args.has("--recommended-backoff")};
    const SweepResult sweep = sweep_feeds(scenario, feeds, options);
    const std::string csv = sweep_to_csv(sweep);
    if (const std::optional<std::string> path = args.value("--csv")) {
        write_file_atomically(*path, csv);
    } else {
        std::cout << csv;
    }
    std::cerr << sweep_summary(sweep, scenario, options) << '\n';
    return 0;
}

int run_report(std::span<const std::string> argv) {
    const Args args = parse_args(argv, {"--set", "--csv"});
    const std::string csv = csv_report(load_scenario(args));
    if (const std::optional<std::string> path = args.value("--csv")) {
        write_file_atomically(*path, csv);
    } else {
        std::cout << csv;
    }
    return 0;
}

int run_montecarlo(std::span<const std::string> argv) {
    const Args args = parse_args(argv, {"--set", "--samples", "--seed", "--bins"});
    const Scenario scenario = load_scenario(args);
    MonteCarloOptions options;
    if (auto n = optional_number_option(args, "--samples", 1, 1e8)) {
        options.samples = static_cast<std::uint64_t>(*n);
    }
    if (auto seed = optional_number_option(args, "--seed", 0, 9007199254740992.0)) {
        options.seed = static_cast<std::uint64_t>(*seed);
    }
    if (auto bins = optional_number_option(args, "--bins", 1, 10000)) {
        options.bins = static_cast<int>(*bins);
    }
    const Histogram h = monte_carlo_trigger_error(scenario, options);
    Json out = Json::object();
    out["samples"] = options.samples;
    out["seed"] = options.seed;
    out["mean_mm"] = h.mean_mm;
    out["stddev_mm"] = h.stddev_mm;
    out["min_mm"] = h.min_mm;
    out["max_mm"] = h.max_mm;
    out["bin_lo_mm"] = h.lo_mm;
    out["bin_width_mm"] = h.bin_width_mm;
    out["counts"] = h.counts;
    std::cout << out.dump(2) << '\n';
    return 0;
}

}  // namespace probecycle::cli
