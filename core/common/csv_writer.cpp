#include "core/common/csv_writer.h"

#include <cstdio>

#include "core/common/number_format.h"

namespace probecycle {

std::string csv_time_s(double value) {
    return format_fixed(value, kReportTimeDecimals);
}

std::string csv_length_mm(double value) {
    return format_fixed(value, kReportLengthDecimals);
}

std::string csv_feed_mm_min(double value) {
    return format_fixed(value, kReportFeedDecimals);
}

std::string csv_exact(double value) {
    return format_exact(value);
}

std::string csv_time_s(const std::optional<double>& value) {
    return value ? csv_time_s(*value) : std::string();
}

std::string csv_length_mm(const std::optional<double>& value) {
    return value ? csv_length_mm(*value) : std::string();
}

std::string csv_quote(const std::string& text) {
    std::string out = "\"";
    for (const char ch : text) {
        if (ch == '"') out += '"';
        out += ch;
    }
    return out + "\"";
}

std::string csv_field(const std::string& text) {
    return text.find_first_of(",\"\r\n") == std::string::npos ? text : csv_quote(text);
}

std::string csv_line(std::initializer_list<std::string> fields) {
    std::string line;
    bool first = true;
    for (const std::string& field : fields) {
        if (!first) line += ',';
        line += field;
        first = false;
    }
    return line + '\n';
}

std::string csv_warnings_header(bool with_group) {
    return with_group ? "# warnings\ncode,severity,group,message\n"
                      : "# warnings\ncode,severity,message\n";
}

std::string csv_warning_row(std::string_view code, std::string_view severity,
                            const std::string& message) {
    return std::string(code) + ',' + std::string(severity) + ',' + csv_quote(message) + '\n';
}

std::string csv_warning_row(std::string_view code, std::string_view severity,
                            const std::string& group, const std::string& message) {
    return std::string(code) + ',' + std::string(severity) + ',' + csv_field(group) + ',' +
           csv_quote(message) + '\n';
}

}  // namespace probecycle
