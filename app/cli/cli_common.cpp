#include "app/cli/cli_common.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/common/file_io.h"
#include "core/cycle/cycle_report.h"

namespace probecycle::cli {

bool Args::has(const std::string& name) const {
    return options.count(name) > 0 || flags.count(name) > 0;
}

std::optional<std::string> Args::value(const std::string& name) const {
    const auto it = options.find(name);
    if (it == options.end() || it->second.empty()) return std::nullopt;
    return it->second.back();
}

const std::vector<std::string>& Args::values(const std::string& name) const {
    static const std::vector<std::string> none;
    const auto it = options.find(name);
    return it == options.end() ? none : it->second;
}

namespace {
bool contains(const std::vector<std::string>& list, const std::string& word) {
    for (const std::string& item : list) {
        if (item == word) return true;
    }
    return false;
}

std::string option_list(const std::vector<std::string>& a, const std::vector<std::string>& b) {
    std::string out;
    for (const auto* list : {&a, &b}) {
        for (const std::string& item : *list) {
            if (!out.empty()) out += ", ";
            out += item;
        }
    }
    return out.empty() ? "none" : out;
}
}  // namespace

Args parse_args(std::span<const std::string> args, const std::vector<std::string>& value_options,
                const std::vector<std::string>& flag_options) {
    Args out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 2 || arg.compare(0, 2, "--") != 0) {
            out.positional.push_back(arg);
            continue;
        }
        const std::size_t eq = arg.find('=');
        const std::string name = arg.substr(0, eq);
        if (contains(value_options, name)) {
            if (eq != std::string::npos) {
                out.options[name].push_back(arg.substr(eq + 1));
            } else if (i + 1 < args.size()) {
                out.options[name].push_back(args[++i]);
            } else {
                throw UsageError("option " + name + " needs a value");
            }
        } else if (contains(flag_options, name) && eq == std::string::npos) {
            out.flags[name] = true;
        } else {
            throw UsageError("unknown option " + name +
                             "; allowed: " + option_list(value_options, flag_options));
        }
    }
    return out;
}

double parse_number(const std::string& text, const std::string& what, double min, double max) {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    std::ostringstream range;
    range << "a number from " << min << " to " << max;
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE ||
        !std::isfinite(value) || value < min || value > max) {
        throw UsageError(what + ": got '" + text + "'; allowed: " + range.str());
    }
    return value;
}

std::optional<double> optional_number_option(const Args& args, const std::string& name, double min,
                                             double max) {
    const std::optional<std::string> text = args.value(name);
    if (!text) return std::nullopt;
    return parse_number(*text, name, min, max);
}

double number_option(const Args& args, const std::string& name, double min, double max) {
    const std::optional<double> value = optional_number_option(args, name, min, max);
    if (!value) throw UsageError("missing required option " + name);
    return *value;
}

Scenario load_scenario(const Args& args) {
    if (args.positional.size() > 1) {
        throw UsageError("expected at most one scenario file, got '" + args.positional[1] +
                         "' too");
    }
    Scenario scenario;
    if (!args.positional.empty()) {
        const std::string& path = args.positional[0];
        try {
            scenario = scenario_from_json(read_text_file(path));
        } catch (const ScenarioError& e) {
            throw std::runtime_error(path + ": invalid scenario:\n" + e.what());
        }
    }
    for (const std::string& assignment : args.values("--set")) {
        apply_setting(scenario, assignment);
    }
    validate_or_throw(scenario);
    return scenario;
}

}  // namespace probecycle::cli
