#include "core/common/csv_writer.h"

#include <cstdio>

namespace probecycle {

std::string csv_number_text(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

std::string csv_number_text(const std::optional<double>& value) {
    return value ? csv_number_text(*value) : std::string();
}

std::string csv_quote(const std::string& text) {
    std::string out = "\"";
    for (const char ch : text) {
        if (ch == '"') out += '"';
        out += ch;
    }
    return out + "\"";
}

}  // namespace probecycle
