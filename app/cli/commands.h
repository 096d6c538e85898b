#pragma once

// probecycle-cli's command groups. Each registers its subcommands on the
// program's CLI::App; a subcommand's callback runs the command and writes
// its output to stdout. Errors are thrown (UsageError, ScenarioError,
// std::runtime_error) and reported by main() with exit code 2.

#include <CLI/CLI.hpp>

namespace probecycle::cli {

// defaults, evaluate, move, sweep, report, montecarlo (commands_cycle.cpp)
void add_cycle_commands(CLI::App& app);
// calibrate ring, calibrate length (commands_calibrate.cpp)
void add_calibrate_commands(CLI::App& app);
// latency fit, latency compensate (commands_latency.cpp)
void add_latency_commands(CLI::App& app);
// compare run, compare cerrors, compare simulate (commands_compare.cpp)
void add_compare_commands(CLI::App& app);
// program delay|ring|cycle, import (commands_program.cpp)
void add_program_commands(CLI::App& app);
// optimise (commands_optimise.cpp)
void add_optimise_commands(CLI::App& app);
// machine linuxcnc (commands_machine.cpp)
void add_machine_commands(CLI::App& app);

}  // namespace probecycle::cli
