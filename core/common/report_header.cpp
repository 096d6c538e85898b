#include "core/common/report_header.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "core/common/csv_writer.h"
#include "core/common/number_format.h"

#ifndef PROBECYCLE_VERSION
#define PROBECYCLE_VERSION "0"
#endif

namespace probecycle {

std::string report_header_csv(std::string_view title, std::string_view subject_key,
                              const ReportHeader& header) {
    const std::string version = header.version.empty() ? program_version() : header.version;
    return "# ProbeCycle " + std::string(title) + "\n# date," + csv_field(header.date) +
           "\n# version," + csv_field(version) + "\n# " + std::string(subject_key) + ',' +
           csv_field(header.subject) + "\n\n";
}

std::string report_date() {
    using namespace std::chrono;
    sys_seconds now = time_point_cast<seconds>(system_clock::now());
    if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
        const std::optional<double> seconds_since = parse_decimal(epoch);
        if (seconds_since && *seconds_since >= 0.0 && *seconds_since < 253402300800.0) {
            now = sys_seconds(seconds(static_cast<long long>(*seconds_since)));
        }
    }
    const year_month_day day{floor<days>(now)};
    char text[16];
    std::snprintf(text, sizeof text, "%04d-%02u-%02u", static_cast<int>(day.year()),
                  static_cast<unsigned>(day.month()), static_cast<unsigned>(day.day()));
    return text;
}

std::string program_version() {
    return PROBECYCLE_VERSION;
}

}  // namespace probecycle
