// Five-axis comparison measurement: compare run, compare cerrors, compare
// simulate. Every input file is read and checked before anything is written;
// errors name the file, the line and the column.

#include <iostream>
#include <memory>

#include "app/cli/cli_options.h"
#include "app/cli/commands.h"
#include "core/common/csv_reader.h"
#include "core/common/file_io.h"
#include "core/common/number_format.h"
#include "core/comparison/comparison.h"
#include "core/comparison/comparison_files.h"
#include "core/comparison/comparison_project.h"
#include "core/comparison/comparison_report.h"
#include "core/comparison/comparison_simulator.h"

namespace probecycle::cli {

namespace {

// --c-axis X,Y: two coordinates.
struct AxisArgs {
    std::string position;
    NumberArg angle{kMinComparisonAngle_deg, kMaxComparisonAngle_deg};
};

void add_axis_args(CLI::App& cmd, AxisArgs& args) {
    cmd.add_option("--c-axis", args.position,
                   "Position of the C axis in machine X and Y, mm (e.g. 200,100)")
        ->type_name("X,Y")
        ->required();
    add_number(cmd, "--angle-deg", args.angle,
               "Angle C turns between the two measurements, deg (default 180)", "DEG");
}

CAxisSetup axis_setup(const AxisArgs& args) {
    const auto comma = args.position.find(',');
    if (comma == std::string::npos || args.position.find(',', comma + 1) != std::string::npos) {
        throw UsageError("--c-axis: got '" + args.position +
                         "'; expected two coordinates X,Y in mm, e.g. 200,100");
    }
    CAxisSetup setup;
    setup.x_mm = parse_number(args.position.substr(0, comma), "--c-axis (X)", -kMaxCoordinate_mm,
                              kMaxCoordinate_mm);
    setup.y_mm = parse_number(args.position.substr(comma + 1), "--c-axis (Y)", -kMaxCoordinate_mm,
                              kMaxCoordinate_mm);
    setup.angle_deg = args.angle.value_or(180.0);
    return setup;
}

std::string format_axis(const CAxisSetup& setup) {
    return format_number(setup.x_mm) + "," + format_number(setup.y_mm);
}

void require_both(const ComparisonFiles& files) {
    if (!blocks_paired(files)) {
        throw UsageError(
            "the block is needed at both angles: give --block-c0 and --block-c180 together");
    }
}

void add_run(CLI::App& compare) {
    struct Args {
        std::string plan;
        std::string reference_cmm;
        std::string test_omm;
        std::string reference_omm;
        AxisArgs axis;
        std::string block_c0;
        std::string block_c180;
        NumberArg tolerance{kMinTolerance_mm, kMaxTolerance_mm};
        std::string report;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = compare.add_subcommand(
        "run", "The comparison: the test part's deviations free of the machine's error (JSON)");
    cmd->add_option("--plan", args->plan,
                    "Inspection plan: x_mm,y_mm,z_mm,i,j,k (outward unit normal), or DMIS")
        ->type_name("FILE")
        ->required();
    cmd->add_option("--reference-cmm", args->reference_cmm,
                    "The reference part's CMM points, x_mm,y_mm,z_mm, in the plan's order")
        ->type_name("FILE")
        ->required();
    cmd->add_option("--test-omm", args->test_omm,
                    "The test part's on-machine points at C = 0, in the plan's order")
        ->type_name("FILE")
        ->required();
    cmd->add_option("--reference-omm", args->reference_omm,
                    "The reference part's on-machine points after the turn, in the plan's order")
        ->type_name("FILE")
        ->required();
    add_axis_args(*cmd, args->axis);
    cmd->add_option("--block-c0", args->block_c0,
                    "Block touched at C = 0: face,x_mm,y_mm,z_mm, faces A, B, C")
        ->type_name("FILE");
    cmd->add_option("--block-c180", args->block_c180, "The block touched after the turn")
        ->type_name("FILE");
    add_number(*cmd, "--tolerance", args->tolerance,
               "Count the points whose |deviation| exceeds this, mm", "MM");
    cmd->add_option("--report", args->report,
                    "Also write the Comparison tab's CSV report to FILE (atomically)")
        ->type_name("FILE");
    cmd->callback([args] {
        const ComparisonFiles files{args->plan,          args->reference_cmm, args->test_omm,
                                    args->reference_omm, args->block_c0,      args->block_c180};
        require_both(files);
        const CAxisSetup c_axis = axis_setup(args->axis);
        ComparisonInput input = read_comparison_files(files);
        input.c_axis = c_axis;
        input.tolerance_mm = args->tolerance.optional();
        const ComparisonResult result = run_comparison(input);
        if (!args->report.empty()) {
            write_output(
                args->report,
                comparison_report_csv(input, result, report_header_of(args->test_omm, "untitled")));
        }
        print(comparison_json(result).dump(2) + '\n');
    });
}

void add_cerrors(CLI::App& compare) {
    struct Args {
        std::string block_c0;
        std::string block_c180;
        AxisArgs axis;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = compare.add_subcommand(
        "cerrors",
        "The C axis's six errors from a block touched at C = 0 and after the turn (JSON)");
    cmd->add_option("--block-c0", args->block_c0,
                    "Block touched at C = 0: face,x_mm,y_mm,z_mm, faces A, B, C")
        ->type_name("FILE")
        ->required();
    cmd->add_option("--block-c180", args->block_c180, "The block touched after the turn")
        ->type_name("FILE")
        ->required();
    add_axis_args(*cmd, args->axis);
    cmd->callback([args] {
        const CAxisSetup setup = axis_setup(args->axis);
        const std::vector<BlockTouch> zero =
            read_block_file(ComparisonFile::block_c0, args->block_c0);
        const std::vector<BlockTouch> turned =
            read_block_file(ComparisonFile::block_c180, args->block_c180);
        const CAxisIdentification result = identify_c_axis(zero, turned, setup);
        print(c_axis_identification_json(result, setup).dump(2) + '\n');
    });
}

void add_simulate(CLI::App& compare) {
    struct Args {
        std::string out;
        IntegerArg seed{0, 9007199254740992LL};
        NumberArg noise{0.0, 0.1};
        NumberArg cmm_noise{0.0, 0.1};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = compare.add_subcommand(
        "simulate", "Write an example data set with its known truth (truth.csv) to a folder");
    cmd->add_option("--out", args->out, "Folder for the files; made if missing")
        ->type_name("DIR")
        ->required();
    add_integer(*cmd, "--seed", args->seed, "Seed of the noise and the plan's jitter (default 1)");
    add_number(*cmd, "--noise-mm", args->noise,
               "Noise of every on-machine touch, per axis, mm (default 0)", "MM");
    add_number(*cmd, "--cmm-noise-mm", args->cmm_noise,
               "Noise of the CMM's points, per axis, mm (default 0)", "MM");
    cmd->callback([args] {
        ComparisonSimulationOptions options;
        options.seed = static_cast<std::uint64_t>(args->seed.value_or(1));
        options.omm_noise_mm = args->noise.value_or(0.0);
        options.cmm_noise_mm = args->cmm_noise.value_or(0.0);
        const ComparisonDataSet data = simulate_comparison(options);
        const ComparisonInput& in = data.input;
        std::vector<ComparisonExampleFile> files = comparison_example_files(data);
        files.push_back({"simulation.json", simulation_json(data, options).dump(2) + "\n"});
        // One set: built beside the folder and swapped in whole, so a reader
        // never meets files of two seeds, and a refusal leaves none.
        std::vector<OutputFile> set;
        nlohmann::ordered_json written = nlohmann::ordered_json::array();
        for (const ComparisonExampleFile& file : files) {
            set.push_back({file.name, file.text});
            written.push_back(file.name);
        }
        write_folder_atomically(args->out, set);
        const std::string d = args->out + "/";
        nlohmann::ordered_json out = simulation_json(data, options);
        out["folder"] = args->out;
        out["files"] = written;
        out["run"] = "probecycle-cli compare run --plan " + d + "plan.csv --reference-cmm " + d +
                     "reference_cmm.csv --test-omm " + d + "test_omm.csv --reference-omm " + d +
                     "reference_omm.csv --c-axis " + format_axis(in.c_axis) + " --block-c0 " + d +
                     "block_c0.csv --block-c180 " + d + "block_c180.csv";
        print(out.dump(2) + '\n');
    });
}

}  // namespace

void add_compare_commands(CLI::App& app) {
    CLI::App* compare = app.add_subcommand(
        "compare", "Five-axis comparison measurement: reference part, C-axis errors, deviations");
    compare->require_subcommand(1);
    add_run(*compare);
    add_cerrors(*compare);
    add_simulate(*compare);
}

}  // namespace probecycle::cli
