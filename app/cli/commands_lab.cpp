// The calibration and latency lab (issue 4): calibrate ring|length,
// latency fit|compensate. Each reads its input completely and checks it before
// writing anything; errors name the file line, the column or the option.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/common/file_io.h"
#include "core/common/message_json.h"
#include "core/lab/calibration.h"
#include "core/lab/calibration_report.h"
#include "app/cli/cli_common.h"
#include "app/cli/commands.h"
#include "core/lab/compensation.h"
#include "core/common/csv_reader.h"
#include "core/lab/delay_fit.h"
#include "core/cycle/cycle_report.h"
#include "core/cycle/scenario.h"
#include "core/common/units.h"

namespace probecycle::cli {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kCalibrateUsage =
    "usage: calibrate ring FILE.csv --gauge-diameter MM [--runout-limit MM] [--report FILE.csv] "
    "[--residual-limit MM]\n"
    "       calibrate length --surface-z MM --trigger-z MM [--trigger-z MM ...] "
    "[--active-length MM] [--nominal-length MM] [--wear-limit MM]";
constexpr const char* kLatencyUsage =
    "usage: latency fit FILE.csv [--interpolation-period-s S] [--apply-to SCENARIO.json] "
    "[--group AXIS+|AXIS-]\n"
    "       latency compensate [SCENARIO.json] [--set K=V ...] [--feed MM_MIN] "
    "[--touch constant|braking] [--speed-fraction F] [--interpolation-period-s S] "
    "[--lag-cycles N] [--trigger-phase P] [--direction +1|-1] [--counts-per-mm C] "
    "[--counter-bits B] [--counter-at-zero COUNTS] [--naive-delay-s S] [--sweep N] [--trace]";

// Position coordinates of a machine: generous, but catches a stray exponent.

template <typename W>
Json warnings_json(const std::vector<W>& warnings) {
    Json out = Json::array();
    for (const auto& w : warnings) {
        out.push_back(warning_json(to_string(w.code), w.severity, w.message));
    }
    return out;
}

Json optional_json(const std::optional<double>& value) {
    return value ? Json(*value) : Json(nullptr);
}

// The one positional argument a subcommand reads: its input file.
const std::string& input_file(const Args& args, const char* command) {
    if (args.positional.empty()) {
        throw UsageError(std::string(command) + ": missing the input file (FILE.csv)");
    }
    if (args.positional.size() > 1) {
        throw UsageError(std::string(command) + ": expected one input file, got '" +
                         args.positional[1] + "' too");
    }
    return args.positional[0];
}

// Reads and parses a lab CSV; a CsvError becomes a message starting with the path.
template <typename Parse>
auto read_lab_csv(const std::string& path, Parse parse) {
    const std::string text = read_text_file(path);
    try {
        return parse(text);
    } catch (const CsvError& e) {
        throw std::runtime_error(path + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

int whole_number_option(const Args& args, const std::string& name, int min, int max, int fallback) {
    const auto text = args.value(name);
    if (!text) return fallback;
    const std::string allowed =
        "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
    double value = 0.0;
    try {
        value = parse_number(*text, name, min, max);
    } catch (const UsageError&) {
        value = std::nan("");
    }
    if (!(value == std::floor(value))) {
        throw UsageError(name + ": got '" + *text + "'; allowed: " + allowed);
    }
    return static_cast<int>(value);
}

// --- calibrate ---

int run_calibrate_ring(std::span<const std::string> argv) {
    const Args args =
        parse_args(argv, {"--gauge-diameter", "--runout-limit", "--residual-limit", "--report"});
    const std::string& path = input_file(args, "ring");
    RingCalibrationOptions options;
    options.gauge_diameter_mm = number_option(args, "--gauge-diameter", 0.1, 2000.0);
    options.runout_limit_mm =
        optional_number_option(args, "--runout-limit", 0.0, 10.0).value_or(options.runout_limit_mm);
    options.residual_limit_mm = optional_number_option(args, "--residual-limit", 0.0, 10.0)
                                    .value_or(options.residual_limit_mm);

    std::vector<RingPoint> points;
    const RingCalibration result = read_lab_csv(path, [&](const std::string& text) {
        points = parse_ring_csv(text);
        return calibrate_ring(points, options);
    });
    // The same CSV report as the Calibration tab exports.
    if (const auto report = args.value("--report")) {
        write_file_atomically(*report, calibration_report_csv(
                                           RingReportInput{points, options, result}, std::nullopt));
    }

    Json out = Json::object();
    out["gauge_diameter_mm"] = options.gauge_diameter_mm;
    out["center_x_mm"] = result.center_x_mm;
    out["center_y_mm"] = result.center_y_mm;
    out["runout_x_mm"] = optional_json(result.runout_x_mm);
    out["runout_y_mm"] = optional_json(result.runout_y_mm);
    out["effective_radius_mm"] = result.effective_radius_mm;
    const auto& by_direction = result.radius_by_direction;
    out["radius_by_direction"] = {{"x_plus", optional_json(by_direction.x_plus_mm)},
                                  {"x_minus", optional_json(by_direction.x_minus_mm)},
                                  {"y_plus", optional_json(by_direction.y_plus_mm)},
                                  {"y_minus", optional_json(by_direction.y_minus_mm)}};
    out["residual_max_mm"] = result.residual_max_mm;
    Json fits = Json::array();
    for (std::size_t o = 0; o < result.fits.size(); ++o) {
        if (!result.fits[o]) continue;
        const auto& fit = *result.fits[o];
        fits.push_back({{"orientation_deg", o == 0 ? 0 : 180},
                        {"center_x_mm", fit.center_x_mm},
                        {"center_y_mm", fit.center_y_mm},
                        {"radius_mm", fit.radius_mm},
                        {"residual_max_mm", fit.residual_max_mm}});
    }
    out["fits"] = fits;
    out["warnings"] = warnings_json(result.warnings);
    std::cout << out.dump(2) << '\n';
    return 0;
}

int run_calibrate_length(std::span<const std::string> argv) {
    const Args args = parse_args(argv, {"--surface-z", "--trigger-z", "--active-length",
                                        "--nominal-length", "--wear-limit"});
    if (!args.positional.empty()) {
        throw UsageError("calibrate length takes no file; got '" + args.positional[0] +
                         "' (give each touch as --trigger-z MM)");
    }
    LengthCalibrationInput input;
    input.surface_z_mm = number_option(args, "--surface-z", -kMaxCoordinate_mm, kMaxCoordinate_mm);
    if (args.values("--trigger-z").empty()) {
        throw UsageError(
            "missing required option --trigger-z (the Z recorded at the touch; repeat "
            "it for several touches)");
    }
    for (const auto& text : args.values("--trigger-z")) {
        input.trigger_z_mm.push_back(
            parse_number(text, "--trigger-z", -kMaxCoordinate_mm, kMaxCoordinate_mm));
    }
    input.active_length_mm =
        optional_number_option(args, "--active-length", 0.0, 2000.0).value_or(0.0);
    input.nominal_length_mm = optional_number_option(args, "--nominal-length", 0.001, 2000.0);
    input.wear_limit_mm =
        optional_number_option(args, "--wear-limit", 0.0, 100.0).value_or(input.wear_limit_mm);
    const LengthCalibration result = calibrate_length(input);

    Json out = Json::object();
    out["effective_length_mm"] = result.effective_length_mm;
    out["nominal_length_mm"] = optional_json(input.nominal_length_mm);
    out["wear_mm"] = optional_json(result.wear_mm);
    out["surface_z_mm"] = input.surface_z_mm;
    out["active_length_mm"] = input.active_length_mm;
    out["trigger_z_mean_mm"] = result.trigger_z_mean_mm;
    out["trigger_z_range_mm"] = result.trigger_z_range_mm;
    out["touches"] = result.touches;
    out["warnings"] = warnings_json(result.warnings);
    std::cout << out.dump(2) << '\n';
    return 0;
}

// --- latency fit ---

int run_latency_fit(std::span<const std::string> argv) {
    const Args args = parse_args(argv, {"--interpolation-period-s", "--apply-to", "--group"});
    const std::string& path = input_file(args, "fit");
    DelayFitOptions options;
    options.interpolation_period_s =
        optional_number_option(args, "--interpolation-period-s", 1e-6, 1.0);
    if (args.has("--group") && !args.has("--apply-to")) {
        throw UsageError("--group chooses the delay for --apply-to; give --apply-to SCENARIO.json");
    }
    const DelayFit fit = read_lab_csv(
        path, [&](const std::string& text) { return fit_delay(parse_delay_csv(text), options); });

    Json out = Json::object();
    if (options.interpolation_period_s) {
        out["interpolation_period_s"] = *options.interpolation_period_s;
    }
    Json groups = Json::array();
    Json warnings = Json::array();
    for (const auto& g : fit.groups) {
        Json group = Json::object();
        group["axis"] = g.axis;
        group["direction"] = g.direction;
        group["delay_s"] = g.delay_s;
        group["zero_speed_position_mm"] = g.zero_speed_position_mm;
        if (options.interpolation_period_s) {
            group["lag_cycles"] = optional_json(g.lag_cycles);
            // Whole cycles for `latency compensate --lag-cycles` (compensation.h).
            group["compensation_lag_cycles"] =
                lag_cycles_for_delay(g.delay_s, *options.interpolation_period_s);
        }
        group["residual_2sigma_mm"] = optional_json(g.residual_2sigma_mm);
        Json feeds = Json::array();
        for (const auto& f : g.feeds) {
            feeds.push_back({{"feed_mm_min", f.feed_mm_min},
                             {"mean_mm", f.mean_mm},
                             {"range_mm", f.range_mm},
                             {"n", f.n}});
        }
        group["feeds"] = feeds;
        groups.push_back(group);
        for (const auto& w : g.warnings) {
            Json warning = {{"code", to_string(w.code)},
                            {"severity", to_string(w.severity)},
                            {"group", g.name()}};
            warning.update(message_json(w.message));
            warnings.push_back(warning);
        }
    }
    out["groups"] = groups;
    out["warnings"] = warnings;

    if (const auto scenario_path = args.value("--apply-to")) {
        Scenario scenario;
        try {
            scenario = scenario_from_json(read_text_file(*scenario_path));
        } catch (const ScenarioError& e) {
            throw std::runtime_error(*scenario_path + ": invalid scenario:\n" + e.what());
        }
        AppliedDelay applied;
        try {
            applied = controller_latency_from_fit(fit, scenario, args.value("--group"));
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string(args.has("--group") ? "--group: " : "--apply-to: ") +
                             e.what());
        }
        scenario = apply_delay(scenario, applied);
        write_file_atomically(*scenario_path, scenario_to_json(scenario));
        out["applied"] = {
            {"file", *scenario_path},
            {"key", "machine.controller_latency_s"},
            {"value_s", applied.controller_latency_s},
            {"previous_s", applied.previous_s},
            {"group", applied.group},
            {"rule", render(applied.rule)},
            {"total_delay_s", applied.total_delay_s},
            {"less_interface_delay_s", applied.interface_delay_s},
            {"less_half_scan_period_s", applied.half_scan_s},
        };
    }
    std::cout << out.dump(2) << '\n';
    return 0;
}

// --- latency compensate ---

std::uint64_t counter_option(const Args& args, const std::string& name, int counter_bits) {
    const std::string text = *args.value(name);
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    const std::uint64_t max = counter_mask(counter_bits);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size() || value > max) {
        throw UsageError(name + ": got '" + text + "'; allowed: a whole number from 0 to " +
                         std::to_string(max) + " (a " + std::to_string(counter_bits) +
                         "-bit counter)");
    }
    return value;
}

Json errors_json(const std::array<double, kCompensationMethodCount>& errors) {
    Json out = Json::object();
    for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
        out[to_string(static_cast<CompensationMethod>(m))] = errors[m];
    }
    return out;
}

int run_latency_compensate(std::span<const std::string> argv) {
    const Args args =
        parse_args(argv,
                   {"--set", "--feed", "--touch", "--speed-fraction", "--interpolation-period-s",
                    "--lag-cycles", "--trigger-phase", "--direction", "--counts-per-mm",
                    "--counter-bits", "--counter-at-zero", "--naive-delay-s", "--sweep"},
                   {"--trace"});
    const Scenario scenario = load_scenario(args);

    CompensationSetup setup;
    setup.limits = scenario.motion_limits();
    setup.feed_mm_min = optional_number_option(args, "--feed", 1.0, 100000.0)
                            .value_or(scenario.cycle.probe_feed_mm_min);
    if (const auto touch = args.value("--touch")) {
        if (*touch == "constant") {
            setup.touch = TouchMotion::constant_speed;
        } else if (*touch == "braking") {
            setup.touch = TouchMotion::braking;
        } else {
            throw UsageError("--touch: got '" + *touch + "'; allowed: constant, braking");
        }
    }
    if (args.has("--speed-fraction") && setup.touch != TouchMotion::braking) {
        throw UsageError("--speed-fraction applies to --touch braking");
    }
    setup.braking_speed_fraction = optional_number_option(args, "--speed-fraction", 0.001, 1.0)
                                       .value_or(setup.braking_speed_fraction);
    setup.interpolation_period_s =
        optional_number_option(args, "--interpolation-period-s", 1e-5, 0.1)
            .value_or(setup.interpolation_period_s);
    setup.lag_cycles = whole_number_option(
        args, "--lag-cycles", 0, static_cast<int>(IncrementRing::kCapacity) - 1, setup.lag_cycles);
    if (const auto phase = optional_number_option(args, "--trigger-phase", 0.0, 1.0)) {
        if (*phase >= 1.0) {
            throw UsageError("--trigger-phase: got '" + *args.value("--trigger-phase") +
                             "'; allowed: a number from 0 to below 1 (the fraction of the cycle)");
        }
        setup.trigger_phase = *phase;
    }
    if (const auto direction = args.value("--direction")) {
        if (*direction == "+1" || *direction == "1") {
            setup.direction = 1;
        } else if (*direction == "-1") {
            setup.direction = -1;
        } else {
            throw UsageError("--direction: got '" + *direction + "'; allowed: +1, -1");
        }
    }
    setup.counts_per_mm =
        optional_number_option(args, "--counts-per-mm", 1.0, 1e7).value_or(setup.counts_per_mm);
    setup.counter_bits = whole_number_option(args, "--counter-bits", 16, 64, setup.counter_bits);
    if (args.has("--counter-at-zero")) {
        setup.counter_at_zero = counter_option(args, "--counter-at-zero", setup.counter_bits);
    }
    setup.naive_delay_s = optional_number_option(args, "--naive-delay-s", 0.0, 1.0);
    const int sweep_points = whole_number_option(args, "--sweep", 2, 100, 0);
    if (const auto errors = validate(setup); !errors.empty()) {
        std::string text;
        for (const auto& e : errors) text += (text.empty() ? "--" : "; --") + e.message();
        throw UsageError(text);
    }

    const CompensationComparison result = simulate_compensation(setup);
    Json out = Json::object();
    Json s = Json::object();
    s["accel_model"] = to_string(setup.limits.model);
    s["feed_mm_min"] = setup.feed_mm_min;
    s["direction"] = setup.direction;
    s["touch"] = to_string(setup.touch);
    if (setup.touch == TouchMotion::braking) s["speed_fraction"] = setup.braking_speed_fraction;
    s["interpolation_period_s"] = setup.interpolation_period_s;
    s["lag_cycles"] = setup.lag_cycles;
    s["trigger_phase"] = setup.trigger_phase;
    s["counts_per_mm"] = setup.counts_per_mm;
    s["counter_bits"] = setup.counter_bits;
    s["naive_delay_s"] = result.naive_delay_s;
    out["setup"] = s;
    out["trigger"] = {{"position_mm", result.trigger_position_mm},
                      {"speed_mm_s", result.trigger_speed_mm_s},
                      {"dt_s", result.dt_s}};
    out["recorded"] = {{"position_mm", result.recorded_position_mm},
                       {"speed_mm_s", result.recorded_speed_mm_s},
                       {"p1_mm", result.p1_mm},
                       {"p2_mm", result.p2_mm},
                       {"counter_wraps", result.counter_wraps}};
    Json methods = Json::array();
    for (const auto& m : result.methods) {
        methods.push_back({{"method", to_string(m.method)},
                           {"position_mm", m.position_mm},
                           {"error_mm", m.error_mm}});
    }
    out["methods"] = methods;
    if (sweep_points > 0) {
        // Fractions of the feed from 1 (braking just begun) down to 1/N.
        std::vector<double> fractions;
        for (int k = sweep_points; k >= 1; --k) {
            fractions.push_back(static_cast<double>(k) / sweep_points);
        }
        Json rows = Json::array();
        for (const auto& row : sweep_braking(setup, fractions)) {
            rows.push_back({{"speed_fraction", row.speed_fraction},
                            {"trigger_speed_mm_s", row.trigger_speed_mm_s},
                            {"error_mm", errors_json(row.error_mm)}});
        }
        out["braking_sweep"] = rows;
    }
    if (args.has("--trace")) {
        Json trace = Json::array();
        for (const auto& sample : result.trace) {
            trace.push_back({{"cycle", sample.cycle},
                             {"time_s", sample.time_s},
                             {"position_mm", sample.position_mm},
                             {"speed_mm_s", sample.speed_mm_s},
                             {"counter", sample.counter},
                             {"increment", sample.increment}});
        }
        out["trace"] = trace;
    }
    std::cout << out.dump(2) << '\n';
    return 0;
}

std::span<const std::string> after_verb(std::span<const std::string> args) {
    return args.subspan(1);
}

}  // namespace

int run_calibrate(std::span<const std::string> args) {
    if (args.empty())
        throw UsageError(std::string("missing what to calibrate\n") + kCalibrateUsage);
    if (args[0] == "--help" || args[0] == "help") {
        std::cout << kCalibrateUsage << '\n';
        return 0;
    }
    if (args[0] == "ring") return run_calibrate_ring(after_verb(args));
    if (args[0] == "length") return run_calibrate_length(after_verb(args));
    throw UsageError("unknown calibration '" + args[0] + "'; allowed: ring, length\n" +
                     kCalibrateUsage);
}

int run_latency(std::span<const std::string> args) {
    if (args.empty()) throw UsageError(std::string("missing fit or compensate\n") + kLatencyUsage);
    if (args[0] == "--help" || args[0] == "help") {
        std::cout << kLatencyUsage << '\n';
        return 0;
    }
    if (args[0] == "fit") return run_latency_fit(after_verb(args));
    if (args[0] == "compensate") return run_latency_compensate(after_verb(args));
    throw UsageError("unknown latency command '" + args[0] + "'; allowed: fit, compensate\n" +
                     kLatencyUsage);
}

}  // namespace probecycle::cli
