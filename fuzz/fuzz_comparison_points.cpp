// Comparison input files: the text read as a plan, as measured points and as
// a block, then, when it is a plan, the whole pipeline on it (the nominal
// points as every measurement, the test part shifted). Any input is refused
// with a CsvError or std::invalid_argument, or gives finite results.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "core/common/csv_reader.h"
#include "core/comparison/comparison.h"
#include "core/comparison/comparison_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace probecycle;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        (void)parse_points(text);
    } catch (const CsvError& e) {
        (void)e.what();
    }
    try {
        (void)parse_block(text);
    } catch (const CsvError& e) {
        (void)e.what();
    }
    try {
        ComparisonInput input;
        input.plan = parse_plan(text);
        for (const PlanPoint& p : input.plan) {
            input.reference_cmm.push_back(p.nominal);
            input.reference_omm.push_back(p.nominal);
            input.test_omm.push_back(p.nominal + 0.01 * p.normal);
        }
        input.tolerance_mm = 0.01;
        const ComparisonResult result = run_comparison(input);
        for (const ComparisonPoint& p : result.points) {
            if (!std::isfinite(p.deviation_mm) || !std::isfinite(p.direct_deviation_mm) ||
                !std::isfinite(p.system_error_mm)) {
                std::abort();
            }
        }
    } catch (const CsvError& e) {
        (void)e.what();
    } catch (const std::invalid_argument& e) {
        (void)e.what();
    }
    return 0;
}
