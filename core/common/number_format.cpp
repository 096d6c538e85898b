#include "core/common/number_format.h"

#include <cmath>
#include <cstdio>

namespace probecycle {

std::string format_number(double value, int significant) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
    return buffer;
}

}  // namespace probecycle
