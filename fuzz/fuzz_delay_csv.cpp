// Delay-test CSV: parse, then fit. Any input is refused with a CsvError or
// std::invalid_argument, or fits to finite delays.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "core/common/csv_reader.h"
#include "core/lab/delay_fit.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace probecycle;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const auto touches = parse_delay_csv(text);
        const DelayFit fit = fit_delay(touches);
        for (const DelayGroup& group : fit.groups) {
            if (!std::isfinite(group.delay_s)) std::abort();
        }
    } catch (const CsvError& e) {
        (void)e.what();
    } catch (const std::invalid_argument& e) {
        (void)e.what();
    }
    return 0;
}
