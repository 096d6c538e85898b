#include "core/common/csv_reader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/core/common/message_checks.h"

namespace probecycle {
namespace {

using test::expect_translatable;

// The error a text gives, read with the columns a, b.
CsvError error_of(const std::string& text) {
    try {
        const auto rows = read_csv_rows(text, {"a", "b"});
        for (const CsvRow& row : rows) {
            csv_number(row, 0, "a");
            csv_coordinate(row, 1, "b");
        }
    } catch (const CsvError& e) {
        return e;
    }
    ADD_FAILURE() << "no error: " << text;
    return CsvError(0, {}, Message{});
}

struct CsvMessageCase {
    const char* name;
    const char* text;
    const char* code;
    std::vector<std::string> problem_values;
    const char* english;  // what(), unchanged from the plain-text errors
};
void PrintTo(const CsvMessageCase& c, std::ostream* os) {
    *os << c.name;
}

class CsvErrorMessages : public testing::TestWithParam<CsvMessageCase> {};

TEST_P(CsvErrorMessages, CarryTheProblemAsAMessageAndThePositionAsArguments) {
    const CsvMessageCase& c = GetParam();
    const CsvError e = error_of(c.text);
    EXPECT_EQ(std::string(e.what()), c.english);
    EXPECT_EQ(render(e.to_message()), c.english);
    EXPECT_EQ(e.problem().code, c.code);
    EXPECT_EQ(e.to_message().code, c.code);
    expect_translatable(e.problem(), c.problem_values);
    // The position: the line and the column as arguments, the problem nested.
    std::vector<std::string> values;
    if (e.line() > 0) values.push_back("line");
    if (!e.column().empty()) values.push_back("column");
    values.insert(values.end(), c.problem_values.begin(), c.problem_values.end());
    expect_translatable(e.to_message(), values);
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(Problems, CsvErrorMessages, testing::Values(
    CsvMessageCase{"Empty",          "",                   "csv_empty_file",              {"columns"},                           "the file is empty; expected a header line a,b and one line per touch"},
    CsvMessageCase{"NoData",         "a,b\n",              "csv_no_data",                 {"columns"},                           "no data after the header; expected one line per touch under a,b"},
    CsvMessageCase{"MissingColumn",  "a\n1\n",             "csv_missing_column",          {"column", "columns"},                 "line 1: missing column 'b'; the header must name the columns a,b (comma-separated)"},
    CsvMessageCase{"RepeatedColumn", "a,b,a\n1,2,3\n",     "csv_repeated_column",         {"column"},                            "line 1: column 'a' appears twice in the header"},
    CsvMessageCase{"FieldCount",     "a,b\n1,2\n1\n",      "csv_field_count",             {"fields", "header_fields", "columns"}, "line 3: 1 fields, but the header has 2 (a,b)"},
    CsvMessageCase{"EmptyField",     "a,b\n,2\n",          "csv_empty_field",             {},                                    "line 2, column a: empty; expected a number"},
    CsvMessageCase{"NotANumber",     "a,b\n# c\n1x,2\n",   "csv_not_a_number",            {"value"},                             "line 3, column a: '1x' is not a number (use '.' as the decimal point)"},
    CsvMessageCase{"OutOfRange",     "a,b\n1,2e6\n",       "csv_coordinate_out_of_range", {"limit_mm"},                          "line 2, column b: out of range: a coordinate within +-100000 mm"}));
// clang-format on

TEST(DescribeLines, OneTemplateForOneLineAnotherForSeveral) {
    const Message one = describe_lines({4});
    EXPECT_EQ(render(one), "line 4");
    expect_translatable(one, {"line"});
    const Message several = describe_lines({2, 5, 7});
    EXPECT_EQ(render(several), "lines 2, 5, 7");
    expect_translatable(several, {"lines"});
    EXPECT_STRNE(one.text, several.text);
    EXPECT_EQ(render(describe_lines({1, 2, 3, 4, 5, 6, 7, 8, 9})),
              "lines 1, 2, 3, 4, 5, 6, 7, 8, ...");
    EXPECT_EQ(render(describe_lines({})), "no line");
}

}  // namespace
}  // namespace probecycle
