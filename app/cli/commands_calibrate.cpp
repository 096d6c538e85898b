// The calibration lab: calibrate ring, calibrate length. Each reads its input
// completely and checks it before writing anything; errors name the file
// line, the column or the option.

#include <iostream>
#include <memory>

#include "app/cli/cli_options.h"
#include "app/cli/commands.h"
#include "app/cli/lab_input.h"
#include "core/common/csv_reader.h"
#include "core/lab/calibration.h"
#include "core/lab/calibration_report.h"
#include "core/lab/lab_json.h"

namespace probecycle::cli {

namespace {

void add_ring(CLI::App& calibrate) {
    struct Args {
        std::string file;
        NumberArg gauge_diameter{0.1, 2000.0};
        NumberArg runout_limit{0.0, 10.0};
        NumberArg residual_limit{0.0, 10.0};
        std::string report;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = calibrate.add_subcommand(
        "ring", "Ring-gauge calibration: gauge centre, stylus runout, effective radius (JSON)");
    cmd->add_option("FILE.csv", args->file,
                    "Touches: orientation_deg,x_mm,y_mm, 3 or more per spindle orientation")
        ->required();
    add_number(*cmd, "--gauge-diameter", args->gauge_diameter,
               "Calibrated diameter of the ring gauge, mm", "MM")
        ->required();
    add_number(*cmd, "--runout-limit", args->runout_limit,
               "Warn above this stylus runout, mm (default 0.01)", "MM");
    add_number(*cmd, "--residual-limit", args->residual_limit,
               "Warn when a point is further off its circle, mm (default 0.005)", "MM");
    cmd->add_option("--report", args->report,
                    "Also write the Calibration tab's CSV report to FILE (atomically)")
        ->type_name("FILE");
    cmd->callback([args] {
        RingCalibrationOptions options;
        options.gauge_diameter_mm = args->gauge_diameter.value();
        options.runout_limit_mm = args->runout_limit.value_or(options.runout_limit_mm);
        options.residual_limit_mm = args->residual_limit.value_or(options.residual_limit_mm);
        std::vector<RingPoint> points;
        const RingCalibration result = read_lab_csv(args->file, [&](const std::string& text) {
            points = parse_ring_csv(text);
            return calibrate_ring(points, options);
        });
        if (!args->report.empty()) {
            // The same CSV report as the Calibration tab exports.
            write_output(args->report,
                         calibration_report_csv(RingReportInput{points, options, result},
                                                std::nullopt, report_header_of(args->file, "")));
        }
        print(ring_calibration_json(result, options).dump(2) + '\n');
    });
}

void add_length(CLI::App& calibrate) {
    struct Args {
        NumberArg surface_z{-kMaxCoordinate_mm, kMaxCoordinate_mm};
        std::vector<std::string> trigger_z;
        NumberArg active_length{0.0, 2000.0};
        NumberArg nominal_length{0.001, 2000.0};
        NumberArg wear_limit{0.0, 100.0};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = calibrate.add_subcommand(
        "length", "Effective probe length from a surface of known Z, or its wear (JSON)");
    add_number(*cmd, "--surface-z", args->surface_z,
               "Known Z of the gauge top, sphere or block, mm", "MM")
        ->required();
    cmd->add_option("--trigger-z", args->trigger_z,
                    "Z the control recorded at a touch, mm; repeat it for several touches")
        ->type_name("MM")
        ->allow_extra_args(false);
    add_number(*cmd, "--active-length", args->active_length,
               "Tool length offset active while probing, mm (default 0)", "MM");
    add_number(*cmd, "--nominal-length", args->nominal_length,
               "Nominal probe length, to give the result as wear, mm", "MM");
    add_number(*cmd, "--wear-limit", args->wear_limit, "Warn above this wear, mm (default 0.5)",
               "MM");
    cmd->callback([args] {
        if (args->trigger_z.empty()) {
            throw UsageError(
                "missing required option --trigger-z (the Z recorded at the touch; repeat "
                "it for several touches)");
        }
        LengthCalibrationInput input;
        input.surface_z_mm = args->surface_z.value();
        for (const std::string& text : args->trigger_z) {
            input.trigger_z_mm.push_back(
                parse_number(text, "--trigger-z", -kMaxCoordinate_mm, kMaxCoordinate_mm));
        }
        input.active_length_mm = args->active_length.value_or(0.0);
        input.nominal_length_mm = args->nominal_length.optional();
        input.wear_limit_mm = args->wear_limit.value_or(input.wear_limit_mm);
        const LengthCalibration result = calibrate_length(input);
        print(length_calibration_json(input, result).dump(2) + '\n');
    });
}

}  // namespace

void add_calibrate_commands(CLI::App& app) {
    CLI::App* calibrate = app.add_subcommand(
        "calibrate", "The calibration lab: ring-gauge radius and runout, length");
    calibrate->require_subcommand(1);
    add_ring(*calibrate);
    add_length(*calibrate);
}

}  // namespace probecycle::cli
