#include "core/common/number_format.h"

#include <charconv>
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

std::optional<double> parse_decimal(std::string_view text) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!text.empty() && space(text.front())) text.remove_prefix(1);
    while (!text.empty() && space(text.back())) text.remove_suffix(1);
    if (text.empty() || (text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X'))) {
        return std::nullopt;
    }
    double value = 0.0;
    const auto [end, ec] =
        std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

double round_up_to(double value, double step) {
    return std::ceil(value / step - 1e-6) * step;
}

double round_down_to(double value, double step) {
    return std::floor(value / step + 1e-6) * step;
}

}  // namespace probecycle
