#pragma once

// A probing plan as a program in a control's dialect (docs/programs.md). The
// program opens with a header of comments: what it does, the plan's id, the
// date, the scenario values the plan used, the warning to prove it out at
// reduced rapid override with the probe clear of the part, and where the
// control puts the positions. Every move is incremental (G91) from where the
// probe stands, so the program never drives to a coordinate the user did not
// choose.

#include <string>

#include "core/program/dialect.h"
#include "core/program/plan.h"

namespace probecycle {

// What a program needs beyond the plan in some dialects.
struct ProgramOptions {
    // The control's command that turns the spindle to 180 deg ("M19 R180."):
    // the ring program of a dialect with orient_from_user needs it, since no
    // word does that on every control of the dialect. One line of upper-case
    // letters, digits, spaces and . + - # [ ] =.
    std::string orient_180_command;
    // The probe's input in a dialect whose probing moves name it (Siemens's
    // MEAS=): 1 or 2, negative for a probe whose signal falls when it
    // triggers.
    int probe_input{1};
};

// Throws InputError (naming the option) when `options` cannot serve the plan
// in the dialect: the ring program without the orient command, a command
// with other characters, a probe input other than 1, -1, 2, -2; or when the
// plan records more touches than the dialect can keep.
void check_program_options(const ProbingPlan& plan, const Dialect& dialect,
                           const ProgramOptions& options);

// `date` as YYYY-MM-DD (report_date(): today, or SOURCE_DATE_EPOCH's day).
// Throws InputError as check_program_options does.
std::string write_program(const ProbingPlan& plan, const Dialect& dialect, const std::string& date,
                          const ProgramOptions& options = {});

// A distance or coordinate as the programs write it: 3 decimals, '.' whatever
// the locale ("-10.500").
std::string program_number(double value);
// A feed as the programs write it: up to one decimal ("30", "1500.5").
std::string program_feed(double feed_mm_min);

}  // namespace probecycle
