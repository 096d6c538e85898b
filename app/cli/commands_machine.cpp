// The machine section of a scenario from a control's configuration:
// machine linuxcnc FILE.ini.

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/cli/cli_options.h"
#include "app/cli/commands.h"
#include "core/common/file_io.h"
#include "core/program/linuxcnc_ini.h"

namespace probecycle::cli {

namespace {

void add_linuxcnc(CLI::App& machine) {
    auto file = std::make_shared<std::string>();
    CLI::App* cmd = machine.add_subcommand(
        "linuxcnc",
        "The machine section of a scenario from a LinuxCNC 2.9 INI file, for ProbeCycle's "
        "LinuxCNC programs (exact stop, G61.1): constant_accel at the smallest [AXIS_X/Y/Z] "
        "MAX_ACCELERATION; the rapid feed at the smallest of their MAX_VELOCITY and [TRAJ] "
        "MAX_LINEAR_VELOCITY; the scan period one [EMCMOT] SERVO_PERIOD, the controller latency "
        "two; lengths in [TRAJ] LINEAR_UNITS. The INI says nothing about the drives' lag: "
        "servo_time_constant_s 0, filter none; the other keys the defaults (JSON)");
    cmd->add_option("FILE.ini", *file,
                    "The INI file; one with #INCLUDE lines is refused: read the FILE.ini.expanded "
                    "LinuxCNC writes beside it when it starts")
        ->required();
    cmd->callback([file] {
        const std::string text = read_text_file(*file);
        Scenario scenario;
        try {
            scenario.machine = machine_from_linuxcnc_ini(text);
        } catch (const LinuxCncIniError& e) {
            throw std::runtime_error(*file + ": invalid LinuxCNC configuration:\n" + e.what());
        }
        print(scenario_section_to_json(scenario, "machine"));
    });
}

}  // namespace

void add_machine_commands(CLI::App& app) {
    CLI::App* machine = app.add_subcommand(
        "machine", "The machine section of a scenario from your control's configuration (JSON)");
    machine->require_subcommand(1);
    add_linuxcnc(*machine);
}

}  // namespace probecycle::cli
