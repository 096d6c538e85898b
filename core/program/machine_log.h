#pragma once

// Reading back what the control recorded (docs/programs.md): the
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

// The result line of a cycle program that computes its feature's result
// (LinuxCNC's "probecycle result S s X x Y y D d T t", the Fanuc-type DPRNT's
// "RESULT S s X x Y y D d T t"), and whether it wrote "out of tolerance".
struct LoggedResult {
    std::size_t line{0};  // 0: the log holds no result line
    // The size (a surface: its position), the centre's X and Y, the
    // deviation and the out-of-tolerance flag (0 or 1).
    std::array<double, 5> values{};
    std::size_t out_of_tolerance_line{0};  // 0: none
};

// LinuxCNC: the program's LOG file ("probecycle plan <id> <kind>", then
// "probecycle touch <n> <x> <y> <z>" per recorded touch; the plan's id must
// be `plan`'s), or the PROBEOPEN file (9 numbers per probe: every probe, the
// locating and first touches too, and every protected move, whose G38.3 writes
// its end point when it does not trip). Blank lines are skipped.
// A cycle program's result line and "probecycle out of tolerance" go to
// `result` when given.
std::vector<RecordedPosition> read_linuxcnc_positions(std::string_view text,
                                                      const ProbingPlan& plan,
                                                      LoggedResult* result = nullptr);
// grbl: a sender's console log; "[PRB:x,y,z:1]" wherever it stands on a
// line is a probe (every probe and protected move, in the plan's order);
// every other line is ignored. A probe that did not trigger (":0", or an
// "ALARM:" line) and a protected move that did (":1": its path is obstructed)
// are a CsvError naming the line.
std::vector<RecordedPosition> read_grbl_positions(std::string_view text, const ProbingPlan& plan);

// Fanuc-type: the DPRNT output of the program, as a serial terminal, a
// memory card or a file caught it: "PROBECYCLE PLAN <id in letters> <KIND>",
// then "TOUCH <n> X <x> Y <y> Z <z>" per recorded touch (the plan's id must
// be `plan`'s; touches numbered from 1); "PROBECYCLE NO TRIGGER" (the
// program's alarm branch) is a probe that did not trigger, "PROBECYCLE
// OBSTRUCTED" a protected move that did. Lines end with
// CR, LF, CR LF or LF CR CR; control bytes (DC2/DC4 of POPEN/PCLOS, NUL)
// and '%' are dropped; a number may have leading spaces, a sign and spaces
// between its sign and its digits. Other lines (another program's output on
// the same channel) are ignored.
// A cycle program's "RESULT ..." line (after the PLAN line) and "PROBECYCLE
// OUT OF TOLERANCE" go to `result` when given.
// Siemens's WRITE file holds the same lines, the last run after the earlier
// ones (WRITE appends): with `last_run`, the lines before the last
// "PROBECYCLE PLAN" line are ignored.
std::vector<RecordedPosition> read_fanuc_positions(std::string_view text, const ProbingPlan& plan,
                                                   LoggedResult* result = nullptr,
                                                   bool last_run = false);

// Mitsubishi: the common variables the program kept (dialect.cpp), as a
// list of "#n value", "#n=value" or "n value" lines from the control's
// variable output or copied from its variable screen; other lines, vacant
// variables and variables outside #500 to the dialect's last are ignored.
// The plan in #500-#503 must be `plan`'s; the state #504 must be 1 (done)
// or 103 (stopped out of tolerance), else a CsvError says why the program
// stopped; #505 touches from dialect.first_touch_variable on, X Y Z each.
// A cycle program's result #506-#510 (S X Y D T) goes to `result` when
// given. A variable listed twice with two values is a CsvError.
std::vector<RecordedPosition> read_variable_positions(std::string_view text,
                                                      const ProbingPlan& plan,
                                                      const Dialect& dialect,
                                                      LoggedResult* result = nullptr);

// The positions of the plan's recorded touches, in order, from `positions`:
// every probe and protected move of the plan in order (`every_probe`) or its
// recorded touches only. Throws CsvError naming the line: a missing or an
// extra position, or an axis that moved where the plan moves another alone.
std::vector<RecordedPosition> match_recorded_touches(const ProbingPlan& plan,
                                                     const std::vector<RecordedPosition>& positions,
                                                     bool every_probe);

// The lab's CSV for the plan's recorded touches: `axis,direction,feed_mm_min,
// measured_mm` for a delay plan, `orientation_deg,x_mm,y_mm` for a ring plan.
// `positions` as for match_recorded_touches. Throws CsvError naming the line;
// InputError for a cycle plan (the lab has no table for it).
std::string lab_csv_from_positions(const ProbingPlan& plan,
                                   const std::vector<RecordedPosition>& positions,
                                   bool every_probe);

// The file in the dialect, matched to the plan: the positions of its recorded
// touches, for a plan of any kind (a cycle's too). Throws CsvError as the import does.
std::vector<RecordedPosition> recorded_touch_positions(const ProbingPlan& plan, DialectId dialect,
                                                       std::string_view text);

// The positions in the dialect's file, matched to the plan, and the result
// line when the program logged one.
std::vector<RecordedPosition> recorded_touch_positions(const ProbingPlan& plan, DialectId dialect,
                                                       std::string_view text, LoggedResult& result);

// The whole import: the file in the dialect, matched to the plan, as the
// lab's CSV (InputError for a cycle plan).
std::string import_machine_log(const ProbingPlan& plan, DialectId dialect, std::string_view text);

}  // namespace probecycle
