#include "core/common/csv_reader.h"

#include "core/common/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <utility>

namespace probecycle {

namespace {

std::string describe_position(std::size_t line, const std::string& column) {
    if (line == 0) return {};
    std::string text = "line " + std::to_string(line);
    if (!column.empty()) text += ", column " + column;
    return text + ": ";
}

std::string_view trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t\r");
    return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const auto comma = line.find(',', start);
        fields.push_back(trim(line.substr(start, comma - start)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return fields;
}

std::string join(std::initializer_list<std::string_view> names) {
    std::string text;
    for (const auto name : names) {
        if (!text.empty()) text += ',';
        text += name;
    }
    return text;
}

}  // namespace

CsvError::CsvError(std::size_t line, std::string column, const std::string& problem)
    : std::runtime_error(describe_position(line, column) + problem),
      line_(line),
      column_(std::move(column)) {}

std::vector<CsvRow> read_csv_rows(std::string_view text,
                                  std::initializer_list<std::string_view> required_columns) {
    constexpr std::string_view kBom = "\xEF\xBB\xBF";
    if (text.starts_with(kBom)) text.remove_prefix(kBom.size());
    const std::string expected = join(required_columns);

    std::vector<CsvRow> rows;
    std::vector<std::size_t> index_of_required;  // header position of each required column
    std::size_t header_fields = 0;
    bool have_header = false;
    std::size_t line_number = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto end = std::min(text.find('\n', start), text.size());
        const std::string_view line = trim(text.substr(start, end - start));
        start = end + 1;
        ++line_number;
        if (line.empty() || line.front() == '#') continue;

        const auto fields = split_fields(line);
        if (!have_header) {
            for (const auto name : required_columns) {
                const auto count = std::count(fields.begin(), fields.end(), name);
                if (count == 0) {
                    throw CsvError(line_number, {},
                                   "missing column '" + std::string(name) +
                                       "'; the header must name the columns " + expected +
                                       " (comma-separated)");
                }
                if (count > 1) {
                    throw CsvError(
                        line_number, {},
                        "column '" + std::string(name) + "' appears twice in the header");
                }
                index_of_required.push_back(static_cast<std::size_t>(
                    std::find(fields.begin(), fields.end(), name) - fields.begin()));
            }
            header_fields = fields.size();
            have_header = true;
            continue;
        }
        if (fields.size() != header_fields) {
            throw CsvError(line_number, {},
                           std::to_string(fields.size()) + " fields, but the header has " +
                               std::to_string(header_fields) + " (" + expected + ")");
        }
        CsvRow row;
        row.line = line_number;
        for (const auto index : index_of_required) row.fields.emplace_back(fields[index]);
        rows.push_back(std::move(row));
    }
    if (!have_header) {
        throw CsvError(
            0, {},
            "the file is empty; expected a header line " + expected + " and one line per touch");
    }
    if (rows.empty()) {
        throw CsvError(0, {},
                       "no data after the header; expected one line per touch under " + expected);
    }
    return rows;
}

double csv_number(const CsvRow& row, std::size_t index, std::string_view column) {
    std::string_view text = row.fields.at(index);
    if (text.empty()) throw CsvError(row.line, std::string(column), "empty; expected a number");
    // from_chars takes no leading '+', which a hand-written file may well have.
    if (text.front() == '+' && text.size() > 1 && text[1] != '-') text.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
        throw CsvError(
            row.line, std::string(column),
            "'" + row.fields[index] + "' is not a number (use '.' as the decimal point)");
    }
    return value;
}

std::string describe_lines(const std::vector<std::size_t>& lines) {
    if (lines.empty()) return "no line";
    std::string text = lines.size() == 1 ? "line " : "lines ";
    constexpr std::size_t kMaxListed = 8;
    for (std::size_t i = 0; i < lines.size() && i < kMaxListed; ++i) {
        if (i > 0) text += ", ";
        text += std::to_string(lines[i]);
    }
    if (lines.size() > kMaxListed) text += ", ...";
    return text;
}

double csv_coordinate(const CsvRow& row, std::size_t index, std::string_view column) {
    const double value = csv_number(row, index, column);
    if (std::abs(value) > kMaxCoordinate_mm) {
        throw CsvError(
            row.line, std::string(column),
            "out of range: a coordinate within +-" + format_number(kMaxCoordinate_mm) + " mm");
    }
    return value;
}

}  // namespace probecycle
