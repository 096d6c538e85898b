#pragma once

// Each subcommand takes the arguments after its name, writes its output to
// stdout, and returns the exit code. Errors are thrown (UsageError,
// ScenarioError, std::runtime_error) and reported by main() with exit code 2.

#include <span>
#include <string>

namespace probecycle::cli {

int run_defaults(std::span<const std::string> args);
int run_evaluate(std::span<const std::string> args);
int run_move(std::span<const std::string> args);
int run_sweep(std::span<const std::string> args);
int run_report(std::span<const std::string> args);
int run_montecarlo(std::span<const std::string> args);

// The calibration and latency lab (issue 4), in commands_lab.cpp.
int run_calibrate(std::span<const std::string> args);
int run_latency(std::span<const std::string> args);

}  // namespace probecycle::cli
