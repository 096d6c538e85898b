// Probing plan file (docs/programs.md): parse, write back, read the written file
// again. Any input either is refused with a PlanError (whose messages are
// built, as the CLI prints them) or is a plan with a recorded probe that
// writes a file reading back to the same text and the same plan id.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/cycle/scenario.h"
#include "core/program/plan.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace probecycle;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    ProbingPlan plan;
    try {
        plan = parse_probing_plan(text);
    } catch (const PlanError& e) {
        for (const FieldError& error : e.errors()) (void)error.message();
        return 0;
    }
    if (plan.recorded().empty()) std::abort();
    const std::string written = probing_plan_json(plan);
    const ProbingPlan back = parse_probing_plan(written);
    if (probing_plan_json(back) != written) std::abort();
    if (plan_id(back) != plan_id(plan)) std::abort();
    return 0;
}
