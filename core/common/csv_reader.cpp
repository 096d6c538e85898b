#include "core/common/csv_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <utility>

namespace probecycle {

namespace {

// Templates in context "CsvError", like every text of this file.
Message problem(const char* code, const char* text, std::vector<MessageArg> args = {}) {
    return Message{code, "CsvError", text, std::move(args)};
}

// The problem behind its line and column; the problem alone at line 0.
Message with_position(std::size_t line, const std::string& column, const Message& what) {
    if (line == 0) return what;
    const MessageArg line_arg = arg("line", ArgKind::integer, static_cast<double>(line));
    if (column.empty()) {
        return Message{what.code,
                       "CsvError",
                       QT_TRANSLATE_NOOP("CsvError", "line %1: %2"),
                       {line_arg, message_arg("problem", what)}};
    }
    return Message{what.code,
                   "CsvError",
                   QT_TRANSLATE_NOOP("CsvError", "line %1, column %2: %3"),
                   {line_arg, text_arg("column", column), message_arg("problem", what)}};
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

CsvError::CsvError(std::size_t line, std::string column, Message problem)
    : std::runtime_error(render(with_position(line, column, problem))),
      line_(line),
      column_(std::move(column)),
      problem_(std::move(problem)) {}

Message CsvError::to_message() const {
    return with_position(line_, column_, problem_);
}

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
                                   problem("csv_missing_column",
                                           QT_TRANSLATE_NOOP("CsvError",
                                                             "missing column '%1'; the header "
                                                             "must name the columns %2 "
                                                             "(comma-separated)"),
                                           {text_arg("column", std::string(name)),
                                            text_arg("columns", expected)}));
                }
                if (count > 1) {
                    throw CsvError(
                        line_number, {},
                        problem("csv_repeated_column",
                                QT_TRANSLATE_NOOP("CsvError",
                                                  "column '%1' appears twice in the header"),
                                {text_arg("column", std::string(name))}));
                }
                index_of_required.push_back(static_cast<std::size_t>(
                    std::find(fields.begin(), fields.end(), name) - fields.begin()));
            }
            header_fields = fields.size();
            have_header = true;
            continue;
        }
        if (fields.size() != header_fields) {
            throw CsvError(
                line_number, {},
                problem("csv_field_count",
                        QT_TRANSLATE_NOOP("CsvError", "%1 fields, but the header has %2 (%3)"),
                        {arg("fields", ArgKind::integer, static_cast<double>(fields.size())),
                         arg("header_fields", ArgKind::integer, static_cast<double>(header_fields)),
                         text_arg("columns", expected)}));
        }
        CsvRow row;
        row.line = line_number;
        for (const auto index : index_of_required) row.fields.emplace_back(fields[index]);
        rows.push_back(std::move(row));
    }
    if (!have_header) {
        throw CsvError(0, {},
                       problem("csv_empty_file",
                               QT_TRANSLATE_NOOP("CsvError",
                                                 "the file is empty; expected a header line %1 "
                                                 "and one line per touch"),
                               {text_arg("columns", expected)}));
    }
    if (rows.empty()) {
        throw CsvError(0, {},
                       problem("csv_no_data",
                               QT_TRANSLATE_NOOP("CsvError",
                                                 "no data after the header; expected one line "
                                                 "per touch under %1"),
                               {text_arg("columns", expected)}));
    }
    return rows;
}

double csv_number(const CsvRow& row, std::size_t index, std::string_view column) {
    std::string_view text = row.fields.at(index);
    if (text.empty()) {
        throw CsvError(
            row.line, std::string(column),
            problem("csv_empty_field", QT_TRANSLATE_NOOP("CsvError", "empty; expected a number")));
    }
    // from_chars takes no leading '+', which a hand-written file may well have.
    if (text.front() == '+' && text.size() > 1 && text[1] != '-') text.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
        throw CsvError(row.line, std::string(column),
                       problem("csv_not_a_number",
                               QT_TRANSLATE_NOOP("CsvError",
                                                 "'%1' is not a number (use '.' as the decimal "
                                                 "point)"),
                               {text_arg("value", row.fields[index])}));
    }
    return value;
}

Message describe_lines(const std::vector<std::size_t>& lines) {
    if (lines.empty()) return problem("no_line", QT_TRANSLATE_NOOP("CsvError", "no line"));
    if (lines.size() == 1) {
        return problem("line", QT_TRANSLATE_NOOP("CsvError", "line %1"),
                       {arg("line", ArgKind::integer, static_cast<double>(lines.front()))});
    }
    // Line numbers are written alike in every language; the list stays text.
    std::string list;
    constexpr std::size_t kMaxListed = 8;
    for (std::size_t i = 0; i < lines.size() && i < kMaxListed; ++i) {
        if (i > 0) list += ", ";
        list += std::to_string(lines[i]);
    }
    if (lines.size() > kMaxListed) list += ", ...";
    return problem("lines", QT_TRANSLATE_NOOP("CsvError", "lines %1"), {text_arg("lines", list)});
}

double csv_coordinate(const CsvRow& row, std::size_t index, std::string_view column) {
    const double value = csv_number(row, index, column);
    if (std::abs(value) > kMaxCoordinate_mm) {
        throw CsvError(
            row.line, std::string(column),
            problem("csv_coordinate_out_of_range",
                    QT_TRANSLATE_NOOP("CsvError", "out of range: a coordinate within +-%1 mm"),
                    {arg("limit_mm", ArgKind::integer, kMaxCoordinate_mm)}));
    }
    return value;
}

}  // namespace probecycle
