// Ring-gauge CSV: parse, then calibrate. Any input is refused with a
// CsvError or std::invalid_argument, or calibrates to finite numbers.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "core/common/csv_reader.h"
#include "core/lab/calibration.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace probecycle;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const auto points = parse_ring_csv(text);
        RingCalibrationOptions options;
        options.gauge_diameter_mm = 50.0;
        const RingCalibration result = calibrate_ring(points, options);
        if (!std::isfinite(result.center_x_mm) || !std::isfinite(result.center_y_mm)) std::abort();
    } catch (const CsvError& e) {
        (void)e.what();
    } catch (const std::invalid_argument& e) {
        (void)e.what();
    }
    return 0;
}
