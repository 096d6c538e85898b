// Scenario JSON: parse, validate, evaluate and analyse, write back, read the
// written file again. Any input either is refused with a ScenarioError (whose
// message is built, as the CLI prints it) or round-trips to the same scenario
// and evaluates to finite results.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/cycle/cycle.h"
#include "core/cycle/cycle_report.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace probecycle;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Scenario scenario;
    try {
        scenario = scenario_from_json(text);
    } catch (const ScenarioError& e) {
        for (const FieldError& error : e.errors()) (void)error.message();
        return 0;
    }
    const std::string written = scenario_to_json(scenario);
    if (scenario_to_json(scenario_from_json(written)) != written) std::abort();
    const CycleResult result = evaluate(scenario);
    if (!std::isfinite(result.total()) || result.total() < 0.0) std::abort();
    if (!std::isfinite(result.overtravel_mm()) || !std::isfinite(result.uncertainty_mm())) {
        std::abort();
    }
    for (const Warning& w : result.warnings()) (void)w.message();
    // The knee search and the JSON the CLI prints, on small inputs only (it
    // sweeps hundreds of feeds).
    if (size < 512) (void)evaluation_to_json(scenario, analyse(scenario));
    return 0;
}
