#include "app/cli/cli_options.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "core/common/file_io.h"
#include "core/common/number_format.h"

namespace probecycle::cli {

namespace {

std::string range_text(double min, double max) {
    return "a number from " + format_number(min) + " to " + format_number(max);
}

}  // namespace

std::optional<std::string> number_problem(const std::string& text, double min, double max) {
    const std::optional<double> value = parse_decimal(text);
    if (value && *value >= min && *value <= max) return std::nullopt;
    return "got '" + text + "'; allowed: " + range_text(min, max);
}

std::optional<std::string> integer_problem(const std::string& text, long long min, long long max) {
    long long value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (!text.empty() && ec == std::errc() && end == text.data() + text.size() && value >= min &&
        value <= max) {
        return std::nullopt;
    }
    return "got '" + text + "'; allowed: a whole number from " + std::to_string(min) + " to " +
           std::to_string(max);
}

double parse_number(const std::string& text, const std::string& name, double min, double max) {
    if (const auto problem = number_problem(text, min, max))
        throw UsageError(name + ": " + *problem);
    return *parse_decimal(text);
}

std::vector<double> parse_number_list(const std::string& text, const std::string& name, double min,
                                      double max) {
    std::vector<double> numbers;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma - start);
        if (number_problem(item, min, max)) {
            std::string message = name;
            message.append(": got '").append(text).append("'; allowed: numbers separated by ");
            message.append("commas, each from ").append(format_number(min)).append(" to ");
            message.append(format_number(max)).append(" (item ");
            message.append(std::to_string(numbers.size() + 1));
            message.append(item.empty() ? " is empty)" : ", '" + item + "', is not)");
            throw UsageError(message);
        }
        numbers.push_back(*parse_decimal(item));
        if (comma == std::string::npos) return numbers;
        start = comma + 1;
    }
}

double NumberArg::value() const {
    return *parse_decimal(text);  // checked by the option's validator
}

std::optional<double> NumberArg::optional() const {
    return given() ? std::optional<double>(value()) : std::nullopt;
}

long long IntegerArg::value() const {
    long long value = 0;
    std::from_chars(text.data(), text.data() + text.size(), value);  // checked when parsed
    return value;
}

CLI::Option* add_number(CLI::App& app, const std::string& name, NumberArg& arg,
                        const std::string& help, const std::string& unit) {
    const double min = arg.min;
    const double max = arg.max;
    return app
        .add_option(name, arg.text,
                    help + " (" + format_number(min) + " to " + format_number(max) + ")")
        ->type_name(unit)
        ->check(CLI::Validator(
            [min, max](std::string& text) { return number_problem(text, min, max).value_or(""); },
            ""));
}

CLI::Option* add_integer(CLI::App& app, const std::string& name, IntegerArg& arg,
                         const std::string& help) {
    const long long min = arg.min;
    const long long max = arg.max;
    return app
        .add_option(name, arg.text,
                    help + " (" + std::to_string(min) + " to " + std::to_string(max) + ")")
        ->type_name("N")
        ->check(CLI::Validator(
            [min, max](std::string& text) { return integer_problem(text, min, max).value_or(""); },
            ""));
}

void add_scenario_args(CLI::App& app, ScenarioArgs& args) {
    app.add_option("SCENARIO.json", args.file,
                   "Scenario file (JSON); the defaults when none is given");
    app.add_option("--set", args.sets,
                   "Override one scenario key, e.g. --set cycle.probe_feed_mm_min=1500; "
                   "repeatable, applied in order")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
}

Scenario load_scenario(const ScenarioArgs& args) {
    Scenario scenario;
    if (!args.file.empty()) {
        try {
            scenario = scenario_from_json(read_text_file(args.file));
        } catch (const ScenarioError& e) {
            throw std::runtime_error(args.file + ": invalid scenario:\n" + e.what());
        }
    }
    for (const std::string& assignment : args.sets) apply_setting(scenario, assignment);
    validate_or_throw(scenario);
    return scenario;
}

ReportHeader report_header_of(const std::string& input, const std::string& fallback) {
    ReportHeader header;
    header.date = report_date();
    header.subject = input.empty() ? fallback : utf8_from_path(path_from_utf8(input).filename());
    return header;
}

namespace {

[[noreturn]] void fail_standard_output(int error) {
    throw std::runtime_error(
        std::string("cannot write the standard output") +
        (error != 0 ? std::string(": ") + std::strerror(error) : std::string()) +
        "; the output is incomplete");
}

}  // namespace

void print(const std::string& text) {
    errno = 0;
    std::cout << text;
    if (!std::cout.good()) fail_standard_output(errno);
}

void flush_output() {
    errno = 0;
    std::cout.flush();
    if (std::fflush(stdout) != 0 || !std::cout.good() || std::ferror(stdout) != 0) {
        fail_standard_output(errno);
    }
}

void write_output(const std::string& path, const std::string& text) {
    if (path.empty()) {
        print(text);
    } else {
        write_file_atomically(path, text);
    }
}

}  // namespace probecycle::cli
