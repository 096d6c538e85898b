#include "core/common/report_header.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace probecycle {
namespace {

TEST(ReportHeader, TitleDateVersionAndSubjectAsCommentLines) {
    const ReportHeader header{.date = "2026-11-26", .version = "1.2.3", .subject = "bore.json"};
    EXPECT_EQ(report_header_csv("cycle report", "scenario", header),
              "# ProbeCycle cycle report\n# date,2026-11-26\n# version,1.2.3\n"
              "# scenario,bore.json\n\n");
    // A name with a comma stays one field; the version defaults to the program's.
    const ReportHeader pasted{.date = "2026-11-26", .subject = "left, then right.csv"};
    EXPECT_EQ(report_header_csv("delay fit report", "touches", pasted),
              "# ProbeCycle delay fit report\n# date,2026-11-26\n# version," + program_version() +
                  "\n# touches,\"left, then right.csv\"\n\n");
    EXPECT_FALSE(program_version().empty());
}

// Sets SOURCE_DATE_EPOCH, or removes it for nullptr.
void set_epoch(const char* value) {
#ifdef _WIN32
    _putenv_s("SOURCE_DATE_EPOCH", value != nullptr ? value : "");  // "" removes it
#else
    if (value != nullptr) {
        ::setenv("SOURCE_DATE_EPOCH", value, 1);
    } else {
        ::unsetenv("SOURCE_DATE_EPOCH");
    }
#endif
}

// The date is today's, or SOURCE_DATE_EPOCH's, so that tests and reproducible
// runs write the same bytes.
TEST(ReportHeader, DateIsTodayOrThatOfSourceDateEpoch) {
    const char* before = std::getenv("SOURCE_DATE_EPOCH");
    const std::optional<std::string> saved =
        before != nullptr ? std::optional<std::string>(before) : std::nullopt;
    set_epoch("1764115200");
    EXPECT_EQ(report_date(), "2025-11-26");
    set_epoch("1764201599");  // the last second of that day
    EXPECT_EQ(report_date(), "2025-11-26");
    set_epoch("0");
    EXPECT_EQ(report_date(), "1970-01-01");
    set_epoch(nullptr);
    const std::string today = report_date();
    ASSERT_EQ(today.size(), 10U) << today;
    EXPECT_EQ(today[4], '-');
    EXPECT_EQ(today[7], '-');
    EXPECT_GE(today, "2025-01-01");
    // Not a number of seconds: ignored, today's date.
    set_epoch("yesterday");
    EXPECT_EQ(report_date(), today);
    if (saved) {
        set_epoch(saved->c_str());
    } else {
        set_epoch(nullptr);
    }
}

}  // namespace
}  // namespace probecycle
