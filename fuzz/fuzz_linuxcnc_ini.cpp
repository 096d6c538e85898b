// LinuxCNC INI file (`probecycle-cli machine linuxcnc FILE.ini`, the window's
// import): the bytes as the INI's text. Any input either gives a machine
// whose scenario passes validate(), every machine number finite, or is refused
// with a LinuxCncIniError whose what() is not empty and whose every problem
// names a section, a key or a line (its message is built, as the CLI prints
// it). Any other exception escapes and is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/cycle/scenario.h"
#include "core/program/linuxcnc_ini.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace probecycle;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Scenario scenario;
    try {
        scenario.machine = machine_from_linuxcnc_ini(text);
    } catch (const LinuxCncIniError& e) {
        if (std::string_view(e.what()).empty()) std::abort();
        for (const IniProblem& problem : e.problems()) {
            if (problem.section.empty() && problem.key.empty() && problem.line == 0) std::abort();
            (void)render(problem.to_message());
        }
        return 0;
    }
    if (!validate(scenario).empty()) std::abort();
    for (const KeyInfo& key : numeric_keys()) {
        if (!std::string_view(key.key).starts_with("machine.")) continue;
        if (!std::isfinite(*get_number(scenario, key.key))) std::abort();
    }
    return 0;
}
