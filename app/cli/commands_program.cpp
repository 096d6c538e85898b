// Programs for the user's control and reading back what it recorded (issue
// 13): program delay|ring|cycle writes the program (and the plan it follows),
// import turns the control's log into the lab's CSV.

#include <iostream>
#include <memory>
#include <optional>

#include "app/cli/cli_options.h"
#include "app/cli/commands.h"
#include "app/cli/lab_input.h"
#include "core/common/file_io.h"
#include "core/common/input_error.h"
#include "core/common/report_header.h"
#include "core/program/cycle_import.h"
#include "core/program/machine_log.h"
#include "core/program/program_writer.h"

namespace probecycle::cli {

namespace {

struct ProgramArgs {
    ScenarioArgs scenario;
    std::string dialect;
    std::string out;
    std::string plan;
    std::string probe_input{"1"};
};

CLI::Validator dialect_check() {
    return CLI::Validator(
        [](std::string& word) {
            return dialect_from_string(word) ? std::string()
                                             : "got '" + word + "'; allowed: " + dialect_names();
        },
        "");
}

CLI::Validator axis_check() {
    return CLI::Validator(
        [](std::string& word) {
            return axis_direction_from_string(word)
                       ? std::string()
                       : "got '" + word + "'; allowed: X+, X-, Y+, Y-, Z+, Z-";
        },
        "");
}

void add_common(CLI::App& cmd, ProgramArgs& args) {
    add_scenario_args(cmd, args.scenario);
    cmd.add_option("--dialect", args.dialect, "The control's G-code: " + dialect_names())
        ->type_name(dialect_names("|"))
        ->required()
        ->check(dialect_check());
    cmd.add_option("--out", args.out, "Write the program to FILE (atomically; default stdout)")
        ->type_name("FILE");
    cmd.add_option("--plan", args.plan,
                   "Also write the plan the program follows to FILE.json (atomically): the "
                   "import needs it")
        ->type_name("FILE.json");
    cmd.add_option("--probe-input", args.probe_input,
                   "siemens: the probe's input in MEAS=: 1 or 2, negative for a probe whose "
                   "signal falls when it triggers (default 1); the other dialects have none")
        ->type_name("1|-1|2|-2")
        ->check(CLI::Validator(
            [](std::string& word) {
                return word == "1" || word == "-1" || word == "2" || word == "-2"
                           ? std::string()
                           : "got '" + word + "'; allowed: 1, -1, 2, -2";
            },
            ""));
}

// A plan's refusal in the options' words: "feeds: ..." reads "--feeds: ...".
std::string in_option_words(std::string text) {
    for (const char* key : {"feeds", "repeats", "margin_mm", "placement_mm", "gauge_diameter_mm",
                            "ball_diameter_mm", "centre_tolerance_mm", "axis"}) {
        const std::string prefix = std::string(key) + ":";
        if (text.rfind(prefix, 0) != 0) continue;
        std::string option = "--" + std::string(key);
        for (char& c : option) c = c == '_' ? '-' : c;
        return option + text.substr(prefix.size() - 1);
    }
    return text;
}

// Runs `make` on the scenario; an option the plan refuses is a usage error.
template <typename Make>
void write_plan_and_program(const ProgramArgs& args, Make make, ProgramOptions options = {}) {
    options.probe_input = std::stoi(args.probe_input);  // checked: 1, -1, 2 or -2
    const Scenario scenario = load_scenario(args.scenario);
    ProbingPlan plan;
    std::string program;
    try {
        plan = make(scenario);
        program = write_program(plan, dialect(*dialect_from_string(args.dialect)), report_date(),
                                options);
    } catch (const InputError& e) {
        throw UsageError(in_option_words(e.what()));
    }
    // The program and its plan are one output: both or neither. (A kill
    // between the two renames can pair a new plan with an old program: the
    // plan id that the program prints into its log tells them apart at the
    // import.)
    const std::string plan_text = args.plan.empty() ? std::string() : probing_plan_json(plan);
    if (!args.out.empty()) {
        std::vector<OutputFile> outputs = {{args.out, program}};
        if (!args.plan.empty()) outputs.push_back({args.plan, plan_text});
        write_files_atomically(outputs);
        return;
    }
    // The program on stdout: the plan only once the program is out whole.
    print(program);
    flush_output();
    if (!args.plan.empty()) write_file_atomically(args.plan, plan_text);
}

void add_delay(CLI::App& program) {
    struct Args {
        ProgramArgs common;
        std::string axis{"Z-"};
        std::optional<std::string> feeds;
        IntegerArg repeats{1, kMaxPlanRepeats};
        NumberArg margin{0.0, 100.0};
        NumberArg placement{0.1, kMaxPlanDistance_mm};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = program.add_subcommand(
        "delay", "The delay-stability test (ISO 230-10) along one axis and direction");
    add_common(*cmd, args->common);
    cmd->add_option("--axis", args->axis,
                    "Axis and direction of travel (default Z-; one per program: the control "
                    "cannot jog at a pause)")
        ->type_name("X+|X-|Y+|Y-|Z+|Z-")
        ->check(axis_check());
    cmd->add_option("--feeds", args->feeds,
                    "Feeds, mm/min, comma-separated (default 30,100,300,1000,2000 and the "
                    "scenario's probing feed)")
        ->type_name("F,F,...");
    add_integer(*cmd, "--repeats", args->repeats, "Touches at each feed (default 5)");
    add_number(*cmd, "--margin-mm", args->margin,
               "Start this much farther out than the distance to reach the feed (default 1)", "MM");
    add_number(*cmd, "--placement-mm", args->placement,
               "The probe stands at most this far from the surface at the start (default 10)",
               "MM");
    cmd->callback([args] {
        DelayPlanOptions options;
        options.touch = *axis_direction_from_string(args->axis);
        if (args->feeds) {
            options.feeds_mm_min = parse_number_list(*args->feeds, "--feeds", kMinPlanFeed_mm_min,
                                                     kMaxPlanFeed_mm_min);
        }
        options.repeats = static_cast<int>(args->repeats.value_or(options.repeats));
        options.margin_mm = args->margin.value_or(options.margin_mm);
        options.placement_mm = args->placement.value_or(options.placement_mm);
        write_plan_and_program(args->common,
                               [&](const Scenario& s) { return make_delay_plan(s, options); });
    });
}

void add_ring(CLI::App& program) {
    struct Args {
        ProgramArgs common;
        NumberArg gauge{0.1, 2000.0};
        NumberArg ball{0.1, 100.0};
        NumberArg tolerance{0.0, 100.0};
        std::string orient_180;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = program.add_subcommand(
        "ring", "Ring-gauge calibration: 4 points at spindle 0 deg, 4 at 180 deg");
    add_common(*cmd, args->common);
    add_number(*cmd, "--gauge-diameter-mm", args->gauge, "Ring gauge diameter (default 50)", "MM");
    add_number(*cmd, "--ball-diameter-mm", args->ball, "Stylus ball diameter (default 6)", "MM");
    add_number(*cmd, "--centre-tolerance-mm", args->tolerance,
               "How far off the gauge centre the probe may start (default 1)", "MM");
    cmd->add_option("--orient-180", args->orient_180,
                    "fanuc, haas, mitsubishi, siemens: your control's command that turns the "
                    "spindle to "
                    "180 deg, as your manual gives it (e.g. \"M19 R180.\"); required there, "
                    "ProbeCycle does not guess it. Other dialects: the operator turns the "
                    "spindle at a pause")
        ->type_name("\"BLOCK\"");
    cmd->callback([args] {
        RingPlanOptions options;
        options.gauge_diameter_mm = args->gauge.value_or(options.gauge_diameter_mm);
        options.ball_diameter_mm = args->ball.value_or(options.ball_diameter_mm);
        options.centre_tolerance_mm = args->tolerance.value_or(options.centre_tolerance_mm);
        write_plan_and_program(
            args->common, [&](const Scenario& s) { return make_ring_plan(s, options); },
            ProgramOptions{args->orient_180, 1});
    });
}

void add_cycle(CLI::App& program) {
    struct Args {
        ProgramArgs common;
        std::string axis{"Z-"};
        NumberArg ball{0.0, 100.0};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = program.add_subcommand(
        "cycle",
        "The scenario's cycle (strategy, feeds, backoff, start distance) on its feature: a "
        "surface, a bore or boss (X+, X-, Y+, Y-), a pocket or web, with protected moves "
        "between the touches");
    add_common(*cmd, args->common);
    cmd->add_option("--axis", args->axis,
                    "A surface: axis and direction of travel (default Z-); a pocket or web: the "
                    "axis its two walls are touched along (X or Y, + first); a bore or boss: not "
                    "used")
        ->type_name("X+|X-|Y+|Y-|Z+|Z-")
        ->check(axis_check());
    add_number(*cmd, "--ball-diameter-mm", args->ball,
               "The stylus's effective ball diameter (from calibrate ring), for the feature's "
               "size and a surface's position (default 0: between stylus centres)",
               "MM");
    cmd->callback([args] {
        CyclePlanOptions options;
        options.touch = *axis_direction_from_string(args->axis);
        options.ball_diameter_mm = args->ball.value_or(options.ball_diameter_mm);
        write_plan_and_program(args->common,
                               [&](const Scenario& s) { return make_cycle_plan(s, options); });
    });
}

void add_import(CLI::App& app) {
    struct Args {
        std::string dialect;
        std::string plan;
        std::string log;
        std::string out;
        bool json{false};
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand(
        "import",
        "The control's record of a program's touches: a delay or ring program's as the lab's CSV "
        "(the delay CSV of 'latency fit' or the ring CSV of 'calibrate ring'), a cycle "
        "program's as the feature's result (size, centre, uncertainty, tolerance)");
    cmd->add_option("LOG", args->log,
                    "LinuxCNC: probecycle_log.txt (or the PROBEOPEN file); grbl: the sender's "
                    "console saved to a file; fanuc, haas: the program's DPRNT output as captured; "
                    "mitsubishi: the common variables #500-#999 as a list of '#n value' lines; "
                    "siemens: the file PROBECYCLE_LOG the program's WRITE appends to")
        ->required();
    cmd->add_option("--dialect", args->dialect, "The control: " + dialect_names())
        ->type_name(dialect_names("|"))
        ->required()
        ->check(dialect_check());
    cmd->add_option("--plan", args->plan, "The plan file 'program --plan' wrote with the program")
        ->type_name("FILE.json")
        ->required();
    cmd->add_option("--out", args->out,
                    "Write the CSV or the result to FILE (atomically; default stdout)")
        ->type_name("FILE");
    cmd->add_flag("--json", args->json,
                  "A cycle plan: the feature's result as JSON (default text)");
    cmd->callback([args] {
        ProbingPlan plan;
        try {
            plan = parse_probing_plan(read_text_file(args->plan));
        } catch (const PlanError& e) {
            throw std::runtime_error(args->plan + ": not a probing plan:\n" + e.what());
        }
        const DialectId id = *dialect_from_string(args->dialect);
        if (plan.kind == ProgramKind::cycle) {
            // A plan without the result's values is the plan file's fault.
            try {
                (void)result_spec(plan);
            } catch (const InputError& e) {
                throw std::runtime_error(args->plan + ": " + e.what());
            }
            write_output(args->out, read_lab_csv(args->log, [&](const std::string& text) {
                             const CycleImport import = import_cycle_log(plan, id, text);
                             return args->json ? cycle_import_json(import)
                                               : cycle_import_text(import);
                         }));
            return;
        }
        write_output(args->out, read_lab_csv(args->log, [&](const std::string& text) {
                         return import_machine_log(plan, id, text);
                     }));
    });
}

}  // namespace

void add_program_commands(CLI::App& app) {
    CLI::App* program = app.add_subcommand("program",
                                           "A probing program for your control (LinuxCNC, grbl, "
                                           "Fanuc, Haas, Mitsubishi, Siemens) and its plan");
    program->require_subcommand(1);
    add_delay(*program);
    add_ring(*program);
    add_cycle(*program);
    add_import(app);
}

}  // namespace probecycle::cli
