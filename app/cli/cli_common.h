#pragma once

// Shared plumbing of probecycle-cli: argument parsing, loading a scenario with
// --set overrides, and the error type that maps to exit code 2.

#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/cycle/scenario.h"

namespace probecycle::cli {

// Bad usage or bad input: printed on stderr, exit code 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct Args {
    std::vector<std::string> positional;
    std::map<std::string, std::vector<std::string>> options;  // "--name" -> values
    std::map<std::string, bool> flags;                        // "--name" present

    bool has(const std::string& name) const;
    std::optional<std::string> value(const std::string& name) const;  // last one given
    const std::vector<std::string>& values(const std::string& name) const;
};

// Options in `value_options` take a value ("--x V" or "--x=V"); those in
// `flag_options` take none. Anything else starting with "--" is a UsageError.
Args parse_args(std::span<const std::string> args, const std::vector<std::string>& value_options,
                const std::vector<std::string>& flag_options = {});

// A number option within [min, max]; UsageError naming the option otherwise.
double number_option(const Args& args, const std::string& name, double min, double max);
std::optional<double> optional_number_option(const Args& args, const std::string& name, double min,
                                             double max);
double parse_number(const std::string& text, const std::string& what, double min, double max);

// The scenario: defaults, or the file given as the first positional argument,
// then each --set section.key=value in order; validated. Throws ScenarioError.
Scenario load_scenario(const Args& args);

}  // namespace probecycle::cli
