// The latency lab: latency fit (the delay from touches at several feeds,
// optionally applied to a scenario) and latency compensate (compare the
// trigger-position compensations on a simulated touch).

#include <charconv>
#include <iostream>
#include <memory>

#include "app/cli/cli_options.h"
#include "app/cli/commands.h"
#include "app/cli/lab_input.h"
#include "core/common/file_io.h"
#include "core/lab/compensation.h"
#include "core/lab/delay_fit.h"
#include "core/lab/delay_fit_report.h"
#include "core/lab/lab_json.h"

namespace probecycle::cli {

namespace {

void add_fit(CLI::App& latency) {
    struct Args {
        std::string file;
        NumberArg interpolation_period{1e-6, 1.0};
        std::string apply_to;
        std::string group;
        std::string report;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = latency.add_subcommand(
        "fit", "The delay from touches at several feeds, per axis and direction (JSON)");
    cmd->add_option("FILE.csv", args->file,
                    "Touches: axis,direction,feed_mm_min,measured_mm (direction +1 or -1)")
        ->required();
    add_number(*cmd, "--interpolation-period-s", args->interpolation_period,
               "The control's interpolation cycle, to give the delay in cycles, s", "S");
    cmd->add_option("--apply-to", args->apply_to,
                    "Write the delay the fit implies into SCENARIO.json (atomically): the "
                    "controller latency, or the interface delay when the input is latched")
        ->type_name("SCENARIO.json");
    cmd->add_option("--group", args->group,
                    "With --apply-to: the group to apply, e.g. X+ (default: the only group, or "
                    "the longest delay)")
        ->type_name("AXIS+|AXIS-");
    cmd->add_option("--report", args->report,
                    "Also write the Latency tab's CSV report (the delay per group, its stability "
                    "per feed, every touch's residual) to FILE (atomically)")
        ->type_name("FILE");
    cmd->callback([args] {
        if (!args->group.empty() && args->apply_to.empty()) {
            throw UsageError(
                "--group chooses the delay for --apply-to; give --apply-to SCENARIO.json");
        }
        DelayFitOptions options;
        options.interpolation_period_s = args->interpolation_period.optional();
        std::vector<DelayTouch> touches;
        const DelayFit fit = read_lab_csv(args->file, [&](const std::string& text) {
            touches = parse_delay_csv(text);
            return fit_delay(touches, options);
        });
        // Everything is checked before anything is written: a refusal
        // writes nothing, and the report and the scenario are one output.
        nlohmann::ordered_json out = delay_fit_json(fit, options);
        std::vector<OutputFile> outputs;
        std::string report;
        if (!args->report.empty()) {
            // The same CSV report as the Latency tab exports.
            report = delay_fit_report_csv(touches, options, fit, report_header_of(args->file, ""));
            outputs.push_back({args->report, report});
        }
        std::string applied_scenario;
        if (!args->apply_to.empty()) {
            Scenario scenario;
            try {
                scenario = scenario_from_json(read_text_file(args->apply_to));
            } catch (const ScenarioError& e) {
                throw std::runtime_error(args->apply_to + ": invalid scenario:\n" + e.what());
            }
            AppliedDelay applied;
            const std::optional<std::string> group =
                args->group.empty() ? std::nullopt : std::optional<std::string>(args->group);
            try {
                applied = delay_to_apply(fit, scenario, group);
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string(group ? "--group: " : "--apply-to: ") + e.what());
            }
            applied_scenario = scenario_to_json(apply_delay(scenario, applied));
            outputs.push_back({args->apply_to, applied_scenario});
            out["applied"] = applied_delay_json(applied, args->apply_to);
        }
        write_files_atomically(outputs);
        print(out.dump(2) + '\n');
    });
}

// A raw counter value within the counter's width.
std::uint64_t counter_value(const std::string& text, int counter_bits) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    const std::uint64_t max = counter_mask(counter_bits);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size() || value > max) {
        throw UsageError("--counter-at-zero: got '" + text +
                         "'; allowed: a whole number from 0 to " + std::to_string(max) + " (a " +
                         std::to_string(counter_bits) + "-bit counter)");
    }
    return value;
}

void add_compensate(CLI::App& latency) {
    struct Args {
        ScenarioArgs scenario;
        NumberArg feed{1.0, 100000.0};
        std::string touch;
        NumberArg speed_fraction{0.001, 1.0};
        NumberArg interpolation_period{1e-5, 0.1};
        IntegerArg lag_cycles{0, static_cast<long long>(IncrementRing::kCapacity) - 1};
        NumberArg trigger_phase{0.0, 1.0};
        std::string direction;
        NumberArg counts_per_mm{1.0, 1e7};
        IntegerArg counter_bits{16, 64};
        std::string counter_at_zero;
        NumberArg naive_delay{0.0, 1.0};
        IntegerArg sweep{2, 100};
        bool trace{false};
        IntegerArg compensated_lag_cycles{0, static_cast<long long>(IncrementRing::kCapacity) - 1};
        bool lag_sweep{false};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = latency.add_subcommand(
        "compensate",
        "Compare trigger-position compensations (naive v*tau, cycle lag, timestamp) on a "
        "simulated touch (JSON)");
    add_scenario_args(*cmd, args->scenario);
    add_number(*cmd, "--feed", args->feed, "Probing feed, mm/min (default: the scenario's)",
               "MM_MIN");
    cmd->add_option("--touch", args->touch,
                    "At constant speed, or while the axis brakes (default constant)")
        ->type_name("constant|braking")
        ->check(CLI::Validator(
            [](std::string& word) {
                return word == "constant" || word == "braking"
                           ? std::string()
                           : "got '" + word + "'; allowed: constant, braking";
            },
            ""));
    add_number(*cmd, "--speed-fraction", args->speed_fraction,
               "With --touch braking: the speed at the trigger as a fraction of the feed "
               "(default 0.5)",
               "F");
    add_number(*cmd, "--interpolation-period-s", args->interpolation_period,
               "Interpolation cycle, s (default 0.001)", "S");
    add_integer(*cmd, "--lag-cycles", args->lag_cycles,
                "Cycles between the trigger's cycle and the recorded position (default 8)");
    add_integer(*cmd, "--compensated-lag-cycles", args->compensated_lag_cycles,
                "The lag the cycle-lag compensation subtracts (default: --lag-cycles)");
    add_number(*cmd, "--trigger-phase", args->trigger_phase,
               "Where in its cycle the trigger falls, below 1 (default 0.4)", "P");
    cmd->add_option("--direction", args->direction, "Direction of travel (default +1)")
        ->type_name("+1|-1")
        ->check(CLI::Validator(
            [](std::string& word) {
                return word == "+1" || word == "1" || word == "-1"
                           ? std::string()
                           : "got '" + word + "'; allowed: +1, -1";
            },
            ""));
    add_number(*cmd, "--counts-per-mm", args->counts_per_mm,
               "Encoder counts per mm (default 10000)", "C");
    add_integer(*cmd, "--counter-bits", args->counter_bits,
                "Width of the position counter in bits (default 32)");
    cmd->add_option("--counter-at-zero", args->counter_at_zero,
                    "Raw counter value at position 0 (default: one that wraps during the lag)")
        ->type_name("COUNTS");
    add_number(*cmd, "--naive-delay-s", args->naive_delay,
               "Delay the naive v*tau correction uses, s (default (lag + 0.5) cycles)", "S");
    add_integer(*cmd, "--sweep", args->sweep,
                "Also compare the methods at N speeds while braking, from the feed down to 1/N");
    cmd->add_flag("--trace", args->trace, "Also print the simulated per-cycle trace");
    cmd->add_flag("--lag-sweep", args->lag_sweep,
                  "Also give the cycle-lag error for every compensated lag from 0 to 49");
    cmd->callback([args] {
        const Scenario scenario = load_scenario(args->scenario);
        CompensationSetup setup;
        setup.limits = scenario.motion_limits();
        setup.feed_mm_min = args->feed.value_or(scenario.cycle.probe_feed_mm_min);
        if (args->touch == "braking") setup.touch = TouchMotion::braking;
        if (args->speed_fraction.given() && setup.touch != TouchMotion::braking) {
            throw UsageError("--speed-fraction applies to --touch braking");
        }
        setup.braking_speed_fraction = args->speed_fraction.value_or(setup.braking_speed_fraction);
        setup.interpolation_period_s =
            args->interpolation_period.value_or(setup.interpolation_period_s);
        setup.lag_cycles = static_cast<int>(args->lag_cycles.value_or(setup.lag_cycles));
        if (args->compensated_lag_cycles.given()) {
            setup.compensated_lag_cycles = static_cast<int>(args->compensated_lag_cycles.value());
        }
        if (args->trigger_phase.given()) {
            if (args->trigger_phase.value() >= 1.0) {
                throw UsageError(
                    "--trigger-phase: got '" + args->trigger_phase.text +
                    "'; allowed: a number from 0 to below 1 (the fraction of the cycle)");
            }
            setup.trigger_phase = args->trigger_phase.value();
        }
        if (args->direction == "-1") setup.direction = -1;
        setup.counts_per_mm = args->counts_per_mm.value_or(setup.counts_per_mm);
        setup.counter_bits = static_cast<int>(args->counter_bits.value_or(setup.counter_bits));
        if (!args->counter_at_zero.empty()) {
            setup.counter_at_zero = counter_value(args->counter_at_zero, setup.counter_bits);
        }
        setup.naive_delay_s = args->naive_delay.optional();
        if (const auto errors = validate(setup); !errors.empty()) {
            std::string text;
            for (const auto& e : errors) text += (text.empty() ? "--" : "; --") + e.message();
            throw UsageError(text);
        }
        const CompensationComparison result = simulate_compensation(setup);
        std::vector<BrakingRow> braking;
        if (args->sweep.given()) {
            // Fractions of the feed from 1 (braking just begun) down to 1/N.
            const long long n = args->sweep.value();
            std::vector<double> fractions;
            for (long long k = n; k >= 1; --k) {
                fractions.push_back(static_cast<double>(k) / static_cast<double>(n));
            }
            braking = sweep_braking(setup, fractions);
        }
        std::vector<LagRow> lags;
        if (args->lag_sweep) lags = sweep_compensated_lag(setup);
        print(compensation_json(setup, result, braking, args->trace, lags).dump(2) + '\n');
    });
}

}  // namespace

void add_latency_commands(CLI::App& app) {
    CLI::App* latency =
        app.add_subcommand("latency", "The latency lab: measure the delay, compare compensations");
    latency->require_subcommand(1);
    add_fit(*latency);
    add_compensate(*latency);
}

}  // namespace probecycle::cli
