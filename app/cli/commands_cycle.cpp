// The cycle model's commands: defaults, evaluate, move, sweep, report, montecarlo.

#include <cmath>
#include <iostream>
#include <memory>

#include "app/cli/cli_options.h"
#include "app/cli/commands.h"
#include "core/cycle/cycle_report.h"
#include "core/cycle/monte_carlo.h"
#include "core/cycle/sweep.h"

namespace probecycle::cli {

namespace {

const KeyInfo& feed_key() {
    return *find_key("cycle.probe_feed_mm_min");
}

// Counted before any is made, so an absurd step is refused, not allocated.
constexpr double kMaxSweepPoints = 1000000;

void add_defaults(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("defaults", "Print the default scenario (JSON)");
    cmd->callback([] { print(scenario_to_json(Scenario{})); });
}

void add_evaluate(CLI::App& app) {
    auto args = std::make_shared<ScenarioArgs>();
    CLI::App* cmd = app.add_subcommand(
        "evaluate", "Cycle time, overtravel, uncertainty, phases and warnings (JSON)");
    add_scenario_args(*cmd, *args);
    cmd->callback([args] {
        const Scenario scenario = load_scenario(*args);
        print(evaluation_to_json(scenario, analyse(scenario)));
    });
}

void add_move(CLI::App& app) {
    struct Args {
        ScenarioArgs scenario;
        NumberArg distance{0.0, 100000.0};
        NumberArg feed{feed_key().min, 200000.0};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand(
        "move", "One rest-to-rest move with the scenario's acceleration model (JSON)");
    add_scenario_args(*cmd, args->scenario);
    add_number(*cmd, "--distance", args->distance, "Length of the move, mm", "MM")->required();
    add_number(*cmd, "--feed", args->feed, "Programmed feed, mm/min", "MM_MIN")->required();
    cmd->callback([args] {
        const Scenario scenario = load_scenario(args->scenario);
        print(move_to_json(scenario, args->distance.value(), args->feed.value()));
    });
}

void add_sweep(CLI::App& app) {
    struct Args {
        ScenarioArgs scenario;
        NumberArg from{feed_key().min, feed_key().max};
        NumberArg to{feed_key().min, feed_key().max};
        NumberArg step{1e-6, feed_key().max};
        std::string csv;
        bool recommended_backoff{false};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand(
        "sweep", "Cycle time against the probing feed (CSV on stdout or --csv; summary on stderr)");
    add_scenario_args(*cmd, args->scenario);
    add_number(*cmd, "--from", args->from, "First feed, mm/min", "F0")->required();
    add_number(*cmd, "--to", args->to, "Last feed, mm/min (at least --from)", "F1")->required();
    add_number(*cmd, "--step", args->step, "Feed step, mm/min", "DF")->required();
    cmd->add_option("--csv", args->csv, "Write the CSV to FILE (atomically) instead of stdout")
        ->type_name("FILE");
    cmd->add_flag("--recommended-backoff", args->recommended_backoff,
                  "Two-touch: back off the recommended distance (overtravel + reseat) at each "
                  "feed, the curve of an optimised cycle");
    cmd->callback([args] {
        const Scenario scenario = load_scenario(args->scenario);
        const double from = args->from.value();
        const double to = args->to.value();
        const double step = args->step.value();
        if (to < from) {
            throw UsageError("--to: got '" + args->to.text + "'; allowed: a number from " +
                             args->from.text + " (--from) to " + std::to_string(feed_key().max));
        }
        const double points = linear_feed_count(from, to, step);
        if (points > kMaxSweepPoints) {
            throw UsageError("--step: " + std::to_string(static_cast<long long>(points)) +
                             " points from --from to --to; at most 1000000 allowed");
        }
        const SweepOptions options{.recommended_backoff = args->recommended_backoff};
        const SweepResult sweep = sweep_feeds(scenario, linear_feeds(from, to, step), options);
        write_output(args->csv, sweep_to_csv(sweep));
        std::cerr << sweep_summary(sweep, scenario) << '\n';
    });
}

void add_report(CLI::App& app) {
    struct Args {
        ScenarioArgs scenario;
        std::string csv;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand(
        "report", "The CSV report the window exports: scenario, summary, phases, warnings, sweep");
    add_scenario_args(*cmd, args->scenario);
    cmd->add_option("--csv", args->csv, "Write the report to FILE (atomically) instead of stdout")
        ->type_name("FILE");
    cmd->callback([args] {
        const Scenario scenario = load_scenario(args->scenario);
        write_output(args->csv,
                     csv_report(scenario, report_header_of(args->scenario.file, "untitled")));
    });
}

void add_montecarlo(CLI::App& app) {
    struct Args {
        ScenarioArgs scenario;
        IntegerArg samples{1, 100000000};
        IntegerArg seed{0, 9007199254740992};
        IntegerArg bins{1, 10000};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand(
        "montecarlo", "Histogram of the trigger error at the measuring touch (JSON)");
    add_scenario_args(*cmd, args->scenario);
    add_integer(*cmd, "--samples", args->samples, "Number of samples (default 100000)");
    add_integer(*cmd, "--seed", args->seed, "Random seed (default 42)");
    add_integer(*cmd, "--bins", args->bins, "Histogram bins (default 50)");
    cmd->callback([args] {
        const Scenario scenario = load_scenario(args->scenario);
        MonteCarloOptions options;
        options.samples = static_cast<std::uint64_t>(
            args->samples.value_or(static_cast<long long>(options.samples)));
        options.seed =
            static_cast<std::uint64_t>(args->seed.value_or(static_cast<long long>(options.seed)));
        options.bins = static_cast<int>(args->bins.value_or(options.bins));
        print(monte_carlo_to_json(options, monte_carlo_trigger_error(scenario, options)));
    });
}

}  // namespace

void add_cycle_commands(CLI::App& app) {
    add_defaults(app);
    add_evaluate(app);
    add_move(app);
    add_sweep(app);
    add_report(app);
    add_montecarlo(app);
}

}  // namespace probecycle::cli
