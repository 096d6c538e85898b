// optimise: the fastest settings that meet the requirements (docs/cli.md,
// "What should I change?").

#include <iostream>
#include <memory>

#include "app/cli/cli_options.h"
#include "app/cli/commands.h"
#include "core/common/file_io.h"
#include "core/optimise/optimise_json.h"
#include "core/optimise/optimiser.h"

namespace probecycle::cli {

void add_optimise_commands(CLI::App& app) {
    struct Args {
        ScenarioArgs scenario;
        NumberArg fraction{kMinOvertravelFraction, kMaxOvertravelFraction};
        IntegerArg pareto_points{1, kMaxParetoPoints};
        std::string apply;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand(
        "optimise",
        "The fastest settings that meet the requirements, what they save, what binds and the "
        "Pareto front of cycle time against uncertainty (JSON)");
    add_scenario_args(*cmd, args->scenario);
    add_number(*cmd, "--max-overtravel-fraction", args->fraction,
               "Overtravel at most this fraction of the probe's limit (default 0.8)", "F");
    add_integer(*cmd, "--pareto-points", args->pareto_points,
                "Uncertainty bounds of the Pareto front (default 20)");
    cmd->add_option("--apply", args->apply,
                    "Write the scenario with the best settings to FILE.json (atomically)")
        ->type_name("FILE.json");
    cmd->callback([args] {
        const Scenario scenario = load_scenario(args->scenario);
        OptimiseRequirements requirements;
        requirements.max_overtravel_fraction =
            args->fraction.value_or(requirements.max_overtravel_fraction);
        requirements.pareto_points =
            static_cast<int>(args->pareto_points.value_or(requirements.pareto_points));
        const OptimiseResult result = optimise(scenario, requirements);
        if (!args->apply.empty()) {
            write_file_atomically(args->apply,
                                  scenario_to_json(with_settings(scenario, result.best.settings)));
        }
        print(optimise_to_json(result));
    });
}

}  // namespace probecycle::cli
