#include "core/common/number_format.h"

#include <algorithm>
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

std::string format_decimals(double value, int decimals) {
    if (!std::isfinite(value)) return format_number(value);
    char buffer[352];  // DBL_MAX in fixed notation is 309 digits
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed,
                                   std::clamp(decimals, 0, 30));
    std::string text(buffer, end.ptr);
    if (text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
    return text;
}

std::string format_fixed(double value, int decimals) {
    std::string text = format_decimals(value, decimals);
    if (std::isfinite(value) && text.find('.') != std::string::npos) {
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    return text;
}

std::string format_exact(double value) {
    if (!std::isfinite(value)) return format_number(value);
    char buffer[40];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, end) : format_number(value, 17);
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

namespace {
// `count` steps: divided by the steps per unit where that is a whole number
// (0.01 mm: 191 / 100 is 1.91, the double nearest it, where 191 * 0.01 is
// 1.9100000000000001), so a rounded value prints as the editors show it.
double steps_to_value(double count, double step) {
    const double per_unit = 1.0 / step;
    return per_unit == std::floor(per_unit) ? count / per_unit : count * step;
}
}  // namespace

double round_up_to(double value, double step) {
    return steps_to_value(std::ceil(value / step - 1e-6), step);
}

double round_down_to(double value, double step) {
    return steps_to_value(std::floor(value / step + 1e-6), step);
}

}  // namespace probecycle
