#pragma once

// Reading back what the control recorded (issue 13, "Reading back"): the
// positions of a program's recorded touches, matched one by one to the plan
// that generated the program, as the lab's CSV (the delay CSV of
// parse_delay_csv or the ring CSV of parse_ring_csv). All or nothing: a touch
// that did not trigger, a missing or an extra position, or a file from another
// plan is a CsvError naming the line, and no table is returned.

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/program/dialect.h"
#include "core/program/plan.h"

namespace probecycle {

// One position the control recorded: X, Y, Z, and its line in the file.
struct RecordedPosition {
    std::size_t line{0};
    std::array<double, 3> xyz{};
};

// LinuxCNC: the program's LOG file ("probecycle plan <id> <kind>", then
// "probecycle touch <n> <x> <y> <z>" per recorded touch; the plan's id must
// be `expected_plan_id`), or the PROBEOPEN file (9 numbers per probe: every
// probe, the locating and first touches too). Blank lines are skipped.
std::vector<RecordedPosition> read_linuxcnc_positions(std::string_view text,
                                                      const ProbingPlan& plan);
// grbl: a sender's console log; "[PRB:x,y,z:1]" wherever it stands on a
// line is a probe (every probe, as in the program), ":0" or an "ALARM:"
// line a probe that did not trigger; every other line is ignored.
std::vector<RecordedPosition> read_grbl_positions(std::string_view text);

// Fanuc-type: the DPRNT output of the program, as a serial terminal, a
// memory card or a file caught it: "PROBECYCLE PLAN <id in letters> <KIND>",
// then "TOUCH <n> X <x> Y <y> Z <z>" per recorded touch (the plan's id must
// be `plan`'s; touches numbered from 1); "PROBECYCLE NO TRIGGER" (the
// program's alarm branch) is a probe that did not trigger. Lines end with
// CR, LF, CR LF or LF CR CR; control bytes (DC2/DC4 of POPEN/PCLOS, NUL)
// and '%' are dropped; a number may have leading spaces, a sign and spaces
// between its sign and its digits. Other lines (another program's output on
// the same channel) are ignored.
std::vector<RecordedPosition> read_fanuc_positions(std::string_view text, const ProbingPlan& plan);

// The lab's CSV for the plan's recorded touches: `axis,direction,feed_mm_min,
// measured_mm` for a delay plan, `orientation_deg,x_mm,y_mm` for a ring plan.
// `positions` are every probe of the plan in order (`every_probe`) or its
// recorded touches only. Throws CsvError naming the line; InputError for a
// cycle plan (the lab has no table for it).
std::string lab_csv_from_positions(const ProbingPlan& plan,
                                   const std::vector<RecordedPosition>& positions,
                                   bool every_probe);

// The whole import: the file in the dialect, matched to the plan.
std::string import_machine_log(const ProbingPlan& plan, DialectId dialect, std::string_view text);

}  // namespace probecycle
