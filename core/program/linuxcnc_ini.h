#pragma once

// The machine section of a scenario from a LinuxCNC 2.9 configuration (its
// INI file), for the programs ProbeCycle writes for LinuxCNC: exact stop
// (G61.1), G38.2/G38.3 probing moves and G0, on trivkins.
//
// What the INI gives, as measured on LinuxCNC 2.9 (linuxcnc-uspace, trivkins,
// drives as ideal loopbacks):
// - In exact stop the trajectory planner plans every move at the full
//   [AXIS_x] MAX_ACCELERATION (G64 would use half); [JOINT_n] and [TRAJ]
//   MAX_LINEAR_ACCELERATION do not act on a coordinated move. So
//   constant_accel at the smallest of [AXIS_X], [AXIS_Y], [AXIS_Z].
// - [TRAJ] MAX_LINEAR_VELOCITY (before 2.8: MAX_VELOCITY there) caps every
//   move, G0 and probing moves included: the rapid feed is the smallest of it
//   and the three axes' MAX_VELOCITY.
// - The probe input is read once per servo period Ts ([EMCMOT] SERVO_PERIOD,
//   ns); after the period that sees it the planner brakes two periods later:
//   overtravel = d + 2*v*Ts + v^2/(2a), d in [0, v*Ts]. So the scan period is
//   Ts, the controller latency 2*Ts, and the input is not latched.
// - Each block costs about two servo periods more than its trapezoid, and the
//   next waits on average 1.6 task cycles ([TASK] CYCLE_TIME; LinuxCNC's
//   default 0.1 s where the file has none): machine.block_change_s (fitted,
//   linuxcnc_ini.cpp).
// - Lengths are in [TRAJ] LINEAR_UNITS.
// The INI says nothing about the drives' following error: the servo time
// constant is 0 and there is no filter after interpolation. The other keys
// of the machine section keep their defaults.
//
// The file is read as LinuxCNC's IniFile reads it: `[SECTION]` lines, `KEY =
// VALUE` (white space around both trimmed; the value is everything after the
// first '=', so a comment after a value is part of it), lines whose first
// non-blank character is '#' or ';' are comments, a line ending in '\' goes
// on in the next. Only the first block of a section is read, and in it the
// first line of a key (an empty value there counts as no value). Section and
// key names are case-sensitive. #INCLUDE lines are refused: LinuxCNC expands
// them (with the shell's expansion of the file name) into FILE.ini.expanded
// beside the INI when it starts, and that file is the one to read.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/message.h"
#include "core/cycle/scenario.h"

namespace probecycle {

// One thing wrong with the INI file: where, and what is wrong and allowed.
struct IniProblem {
    std::string section;  // "AXIS_Z"; empty when the problem is a line of its own
    std::string key;      // "MAX_ACCELERATION"; empty when the problem is the section
    std::size_t line{0};  // 1-based; 0 for a section or key that is missing
    Message problem;      // "got 0.5; allowed: a number from 1 to 200000 mm/s^2 (for ...)"

    // "[AXIS_Z] MAX_ACCELERATION, line 40: %problem", "[AXIS_Z] MAX_ACCELERATION:
    // %problem" (missing), "[AXIS_Z]: %problem" or "line 7: %problem".
    Message to_message() const;
};

// The INI file refused: every problem found, in the order the sections are
// read ([EMCMOT], [TRAJ], [AXIS_X], [AXIS_Y], [AXIS_Z]); what() is their
// English text, one a line.
class LinuxCncIniError : public std::runtime_error {
  public:
    explicit LinuxCncIniError(std::vector<IniProblem> problems);
    const std::vector<IniProblem>& problems() const { return problems_; }

  private:
    std::vector<IniProblem> problems_;
};

// The machine the INI describes (above); every other key as Machine{} has
// it. Throws LinuxCncIniError naming every missing section or key, every
// value that is not a number (or, for LINEAR_UNITS, a unit) and every value
// whose machine key would leave its range, with the range in the INI's units.
Machine machine_from_linuxcnc_ini(std::string_view text);

}  // namespace probecycle
