#pragma once

// CSV input (the lab's files, later the comparison points): the files hold the
// positions a machine recorded, typed or exported by hand, so every error
// names the line and the column and says what was expected. Errors are
// messages (core/common/message.h): the CLI prints what(), the window
// translates to_message().

#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/message.h"

namespace probecycle {

// A bad input file. line() is 1-based (0 when the problem is the file as a
// whole); column() is the header name, empty when the problem is the line.
// what() is the English text of to_message().
class CsvError : public std::runtime_error {
  public:
    CsvError(std::size_t line, std::string column, Message problem);
    std::size_t line() const { return line_; }
    const std::string& column() const { return column_; }
    // What is wrong, without the position.
    const Message& problem() const { return problem_; }
    // "line %1, column %2: %3", "line %1: %2", or the problem alone at line 0;
    // the line and the column are arguments, the problem a nested message.
    Message to_message() const;

  private:
    std::size_t line_;
    std::string column_;
    Message problem_;
};

struct CsvRow {
    std::size_t line{0};              // 1-based line in the file
    std::vector<std::string> fields;  // in the order of the required columns, trimmed
};

// Reads a comma-separated table whose header holds `required_columns` (in any
// order; extra columns are ignored). Blank lines and lines starting with '#'
// are skipped; a UTF-8 byte-order mark and CRLF line ends are accepted.
// Throws CsvError for an empty file, a missing or repeated column, a line with
// a different number of fields than the header, or no data lines.
std::vector<CsvRow> read_csv_rows(std::string_view text,
                                  std::initializer_list<std::string_view> required_columns);

// A finite number; CsvError naming the line and column otherwise.
double csv_number(const CsvRow& row, std::size_t index, std::string_view column);
// Machine coordinates: no axis travels more than this far from its zero.
constexpr double kMaxCoordinate_mm = 100000.0;
// A number in column `index` that is a coordinate within +-kMaxCoordinate_mm.
double csv_coordinate(const CsvRow& row, std::size_t index, std::string_view column);

// Lines of the file for messages: "line 4" (argument "line") or "lines 2, 5, 7"
// (argument "lines", at most 8 listed), each a template of its own.
Message describe_lines(const std::vector<std::size_t>& lines);

}  // namespace probecycle
