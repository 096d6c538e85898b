#include "core/program/dialect.h"

namespace probecycle {

// LinuxCNC, checked against its manual and sources (LinuxCNC/linuxcnc, master
// of 2026-08; the same text in 2.9):
// - docs/src/gcode/g-code.adoc, "G38.n Straight Probe": G38.2 probes toward
//   the workpiece and stops on contact; "If the probe is not tripped before
//   the destination is reached G38.2 and G38.4 will signal an error" and halt
//   the program. #5061-#5069 hold the trip point (X Y Z A B C U V W) in the
//   current work coordinates, #5070 is 1 on success.
// - docs/src/gcode/overview.adoc: ";" comments to the end of the line and
//   "(...)" comments, of which MSG, LOG, PROBEOPEN, ... are active; "(MSG,)"
//   shows a message; "(PROBEOPEN filename.txt)" "store[s] the 9-number
//   coordinate consisting of XYZABCUVW of each successful straight probe",
//   "(PROBECLOSE)" closes it; "(LOGOPEN,filename.txt)" truncates and opens a
//   log, "(LOG,)" writes the rest of the comment with parameters expanded
//   ("%.xf" gives x decimals to the parameters that follow), "(LOGCLOSE)".
//   #5070 is not checked after G38.2: G38.2 already halts without a trip, and
//   the manual (#<_task>) warns that a #5070 test always fails in a preview
//   interpreter such as Axis's, which would stop every preview.
// - src/emc/task/emccanon.cc, GET_EXTERNAL_PROBE_POSITION: the probe file gets
//   "%f %f %f %f %f %f %f %f %f\n" per probe, in program units and work
//   coordinates, and only when the position differs from the previous probe's:
//   two touches that trip at the same position write one line. That is why the
//   program also writes a LOG line per touch, which the import prefers.
// - docs/src/gcode/m-code.adoc: M0 pauses until cycle start, M2 ends. M19
//   (spindle orientation) needs a spindle encoder, so the ring program asks
//   the operator to orient the spindle at a pause instead.
// - G21 (mm), G91 (incremental), G94 (units per minute), G0, G1: g-code.adoc.
// Checked by running every generated program through LinuxCNC's own
// stand-alone interpreter, rs274 (tests/core/program/rs274_check_test.cpp).
const Dialect& linuxcnc_dialect() {
    static const Dialect dialect{
        DialectId::linuxcnc,
        "linuxcnc",
        "LinuxCNC",
        "ngc",
        ";",
        "G21 G91 G94",
        "G38.2",
        "G0",
        "G1",
        "(MSG,{text})",
        "M0",
        {"(PROBEOPEN probecycle_probes.txt)", "(LOGOPEN,probecycle_log.txt)",
         "(LOG,probecycle plan {id} {kind})"},
        "(LOG,probecycle touch {n} %.6f#5061 #5062 #5063)",
        {"(LOGCLOSE)", "(PROBECLOSE)"},
        {"G90", "M2"},
        {"Positions: LinuxCNC writes probecycle_log.txt (one line per recorded touch)",
         "and probecycle_probes.txt (PROBEOPEN: 9 numbers per probe) in its working",
         "directory. Import the log: the probe file drops a touch that trips at the",
         "same position as the one before it."},
    };
    return dialect;
}

// grbl 1.1 (gnea/grbl, master of 2021-01):
// - README.md, "List of Supported G-Codes in Grbl v1.1": G38.2, G0, G1, G21,
//   G90, G91, G94, M0, M2.
// - doc/markdown/commands.md, "$#": "[PRB:0.000,0.000,0.000:0]", "the suffix
//   :1 denotes if the last probe was successful and :0 as not successful".
// - grbl/config.h MESSAGE_PROBE_COORDINATES ("Enabled by default"): after
//   every probe cycle grbl sends the [PRB:...] line unasked
//   (grbl/motion_control.c, mc_probe_cycle, report_probe_parameters); the
//   numbers are machine positions (grbl/report.c), in inches when $13=1
//   (grbl/print.c, printFloat_CoordValue), so the header asks for $13=0.
// - doc/csv/alarm_codes_en_US.csv, alarm 5: "Probe did not contact the
//   workpiece within the programmed travel for G38.2 and G38.4"; alarm 4: the
//   probe was already triggered at the start. An alarm locks out G-code, so
//   the rest of the program does not run.
// - grbl/protocol.c: "(...)" and ";" comments are dropped before parsing;
//   grbl has no message command ("MSG's NOT SUPPORTED", grbl/gcode.c), so a
//   pause's instruction is a comment the sender shows, and no spindle
//   orientation (M19 is not in the list): the operator turns the spindle.
// Not confirmed, so not relied on: what a given sender writes to its console
// log around the [PRB:] lines (the import reads [PRB:...] wherever it stands
// on a line and ignores every other line); grblHAL's extra axes in [PRB:]
// (the import takes the first three numbers, X Y Z).
const Dialect& grbl_dialect() {
    static const Dialect dialect{
        DialectId::grbl,
        "grbl",
        "grbl",
        "nc",
        ";",
        "G21 G91 G94",
        "G38.2",
        "G0",
        "G1",
        "",
        "M0",
        {},
        "",
        {},
        {"G90", "M2"},
        {"Positions: grbl answers [PRB:x,y,z:1] after each probe (machine",
         "positions; set $13=0 for mm). Save the sender's console to a file and",
         "import that file."},
    };
    return dialect;
}

const Dialect& dialect(DialectId id) {
    return id == DialectId::grbl ? grbl_dialect() : linuxcnc_dialect();
}

std::optional<DialectId> dialect_from_string(std::string_view word) {
    for (DialectId id : {DialectId::linuxcnc, DialectId::grbl}) {
        if (word == dialect(id).name) return id;
    }
    return std::nullopt;
}

std::string dialect_names() {
    return std::string(linuxcnc_dialect().name) + ", " + grbl_dialect().name;
}

}  // namespace probecycle
