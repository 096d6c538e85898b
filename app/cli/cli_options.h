#pragma once

// Shared plumbing of probecycle-cli's commands, on top of CLI11: options that
// take a number or a whole number within a range (checked by CLI11 with a
// message that names the option, the value and the range), the scenario a
// command reads (a file and --set overrides), and output to stdout or a file.

#include <CLI/CLI.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/report_header.h"
#include "core/cycle/scenario.h"

namespace probecycle::cli {

// Bad usage or bad input found after parsing: printed on stderr, exit code 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// A decimal number option within [min, max], kept as typed until read.
struct NumberArg {
    NumberArg(double lo, double hi) : min(lo), max(hi) {}
    double min{0.0};
    double max{0.0};
    std::string text;
    bool given() const { return !text.empty(); }
    double value() const;  // the checked number (call only when given)
    std::optional<double> optional() const;
    double value_or(double fallback) const { return given() ? value() : fallback; }
};

// A whole-number option within [min, max].
struct IntegerArg {
    IntegerArg(long long lo, long long hi) : min(lo), max(hi) {}
    long long min{0};
    long long max{0};
    std::string text;
    bool given() const { return !text.empty(); }
    long long value() const;
    long long value_or(long long fallback) const { return given() ? value() : fallback; }
};

// Registers --name taking a number in [arg.min, arg.max] (a whole number for
// IntegerArg). `unit` shows in --help ("MM", "S").
CLI::Option* add_number(CLI::App& app, const std::string& name, NumberArg& arg,
                        const std::string& help, const std::string& unit);
CLI::Option* add_integer(CLI::App& app, const std::string& name, IntegerArg& arg,
                         const std::string& help);

// The strict forms: a decimal number (no hex, no inf or nan) within the
// range, or nothing; the problem as "got 'x'; allowed: ..." otherwise.
std::optional<std::string> number_problem(const std::string& text, double min, double max);
std::optional<std::string> integer_problem(const std::string& text, long long min, long long max);
double parse_number(const std::string& text, const std::string& name, double min, double max);
// A comma-separated list of such numbers, none empty ("1,,2" and "," are refused).
std::vector<double> parse_number_list(const std::string& text, const std::string& name, double min,
                                      double max);

// SCENARIO.json and --set section.key=value (repeatable, applied in order).
struct ScenarioArgs {
    std::string file;
    std::vector<std::string> sets;
};
void add_scenario_args(CLI::App& app, ScenarioArgs& args);
// Defaults or the file, then each --set; validated. A bad file throws
// std::runtime_error starting with its path; a bad --set a ScenarioError.
Scenario load_scenario(const ScenarioArgs& args);

// A CSV report's header (report_header.h): today, or SOURCE_DATE_EPOCH's
// day, and the file name of `input` (its folder left out), or `fallback`
// without one.
ReportHeader report_header_of(const std::string& input, const std::string& fallback);

// The text to stdout; a failed write (a full disk, a closed stream) throws
// std::runtime_error ("cannot write the standard output: <the system's
// reason>; ..."), so the command exits 2 instead of 0 with its output lost.
void print(const std::string& text);
// Standard output flushed; a failure throws as print() does.
void flush_output();

// The text to stdout, or atomically to `path` when one is given.
void write_output(const std::string& path, const std::string& text);

}  // namespace probecycle::cli
