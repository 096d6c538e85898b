#pragma once

// The lines every CSV report opens with: what the report is, the
// date, the program's version, and what it is of. They are comment lines
// ("# date,2026-11-26"): a CSV reader that skips "#" lines skips them, and a
// spreadsheet shows each as two cells, the name and the value.

#include <string>
#include <string_view>

namespace probecycle {

// What the caller knows; each report adds its title and the name of its subject.
struct ReportHeader {
    std::string date;       // YYYY-MM-DD; report_date() for today
    std::string version{};  // program_version() when empty
    // What the report is of: a file name, or "untitled" (a scenario never
    // saved), or "pasted" (lab data typed or pasted in the window).
    std::string subject{"untitled"};
};

// "# ProbeCycle <title>", "# date,...", "# version,...", "# <subject_key>,...",
// then an empty line.
std::string report_header_csv(std::string_view title, std::string_view subject_key,
                              const ReportHeader& header);

// Today's date (UTC) as YYYY-MM-DD, or the date of SOURCE_DATE_EPOCH (seconds
// since 1970, the reproducible-builds convention) when it is set: tests and
// reproducible runs get fixed bytes.
std::string report_date();

// The program's version, as the window's Help > About shows it.
std::string program_version();

}  // namespace probecycle
