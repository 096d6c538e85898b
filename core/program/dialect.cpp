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
// - G61.1, exact stop ("movement will stop at the end of each programmed
//   segment", g-code.adoc, "G61, G61.1 Exact Path Mode"): every move starts
//   and ends at rest, as the model's moves do, and is planned at the full
//   [AXIS_n] MAX_ACCELERATION. Under the default G64 LinuxCNC 2.9 plans every
//   move at half of it, keeping the other half for blending (tp/tc.c,
//   tcGetOverallMaxAccel); later versions halve it only during a blend. On
//   our test machine a G38.2 at 3000 mm/min with 800 mm/s^2 in the INI
//   braked over 1.5625 mm under G61.1 and 3.125 mm under G64. The program
//   ends with G64, LinuxCNC's default, for whatever runs next.
// - A protected move is G38.3 (g-code.adoc, "G38.n Straight Probe": "probe
//   toward workpiece, stop on contact", no error without a trip; after it
//   "Parameter 5070 is set to 1 if the probe succeeded and 0 if the probe
//   failed"). So after each G38.3 the program stops when #5070 is 1: an
//   o-word if (o-code.adoc, "Conditional": "o101 if [#31 EQ 3] ... o101
//   endif"; "Numbering": one o-number per control-flow block in the main
//   program) around "(ABORT,...)" (overview.adoc, "Abort Messages": "displays
//   a message like (MSG,) ... and aborting the current running process";
//   src/emc/rs274ngc/interp_convert.cc returns an interpreter error for it).
//   A preview never trips the probe (GET_EXTERNAL_PROBE_TRIPPED_VALUE is 0 in
//   Axis's src/emc/rs274ngc/gcodemodule.cc and in rs274's
//   src/emc/sai/saicanon.cc), so unlike a test of #5070 after G38.2 (above)
//   the branch never stops a preview. Motion itself also stops a plain move
//   when the probe input rises ("Probe tripped during non-probe move",
//   src/emc/motion/control.c); the G38.3 and its message name the move.
// - The PROBEOPEN file: the interpreter reads the probe position after every
//   straight probe, tripped or not (set_probe_data,
//   src/emc/rs274ngc/interp_internal.cc), and GET_EXTERNAL_PROBE_POSITION
//   writes it; so a G38.3 that does not trip writes its end point too (the
//   manual says "each successful straight probe"; the source is followed),
//   and the import counts the protected moves among the file's probes.
// - A cycle's result in numbered parameters #110-#118:
//   overview.adoc, "Numbered Parameters": "31-5000 - G-code user parameters.
//   These parameters are global in the G code file, and available for
//   general use. Volatile."; expressions in [ ], ABS[...], the operators
//   + - * / and GT, EQ ("Expressions", "Binary Operators", "Functions"); the
//   LOG line's "%.6f" as for the touches. Out of tolerance with a stop, the
//   program closes its log and probe file before the ABORT (above), so that
//   both hold the result line; and it stops only when #<_task> is 1
//   (overview.adoc, "Predefined Named Parameters": 1 under the task, 0 in a
//   preview), since a preview never trips the probe and would compute a size
//   from the searches' ends.
// Checked by running every generated program through LinuxCNC's own
// stand-alone interpreter, rs274 (tests/core/program/rs274_check_test.cpp),
// the abort branch too (with #5070 read as 1).
const Dialect& linuxcnc_dialect() {
    static const Dialect dialect{
        .id = DialectId::linuxcnc,
        .name = "linuxcnc",
        .title = "LinuxCNC",
        .extension = "ngc",
        .comment_open = ";",
        .comment_close = "",
        .program_start = {},
        .modes = "G21 G91 G94 G61.1",
        .probe_word = "G38.2",
        .rapid_word = "G0",
        .feed_word = "G1",
        .pause_message = "(MSG,{text})",
        .pause_word = "M0",
        .open_record = {"(PROBEOPEN probecycle_probes.txt)", "(LOGOPEN,probecycle_log.txt)",
                        "(LOG,probecycle plan {id} {kind})"},
        .before_probe = {},
        .after_probe = {},
        .skip_position = {"#5061", "#5062", "#5063"},
        .guard_word = "G38.3",
        .before_guard = {},
        .after_guard = {"o{label} if [#5070 EQ 1]",
                        "(ABORT,probecycle: the probe touched something during a protected move: "
                        "the path is obstructed)",
                        "o{label} endif"},
        .after_recorded_probe = {"(LOG,probecycle touch {n} %.6f#5061 #5062 #5063)"},
        .close_record = {"(LOGCLOSE)", "(PROBECLOSE)"},
        .end = {"G90 G64", "M2"},
        .after_end = {},
        .guard_alarm = {},
        .file_end = {},
        .record_notes =
            {"Positions: LinuxCNC writes probecycle_log.txt (one line per recorded touch)",
             "and probecycle_probes.txt (PROBEOPEN: 9 numbers per probe) in its working",
             "directory. Import the log: the probe file drops a touch that trips at the",
             "same position as the one before it."},
        .guard_notes =
            {"Protected moves are G38.3, the probe armed: one that touches something stops",
             "the program with an error (ABORT): the path is obstructed."},
        .result_record = {"(LOG,probecycle result S %.6f{size} X {centre_x} Y {centre_y} D "
                          "{deviation} T {flag})"},
        .tolerance_check = {"{flag}=0", "o9001 if [ABS[{deviation}] GT {tolerance}]", "{flag}=1",
                            "o9001 endif"},
        .out_of_tolerance = {"o9002 if [{flag} EQ 1]", "(LOG,probecycle out of tolerance)",
                             "{stop}", "o9002 endif"},
        .tolerance_stop = {"o9003 if [#<_task> EQ 1]", "(LOGCLOSE)", "(PROBECLOSE)",
                           "(ABORT,probecycle: the measured size is out of tolerance)",
                           "o9003 endif"},
        .result_notes =
            {"The log's line 'probecycle result S size X centre Y centre D deviation T",
             "flag' holds them; the import reads it and checks it against the touches."},
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
// - A protected move is G38.3 (README.md's list; grbl/motion_control.c,
//   mc_probe_cycle): without contact no alarm, the probe position is where
//   the axis stopped and grbl reports [PRB:...:0]; a contact stops the move,
//   grbl reports [PRB:...:1] and goes on with the program: grbl cannot
//   branch, so it cannot stop on an obstruction. Before every G38.2 and G38.3
//   grbl checks the probe, and alarm 4 stops it when the probe is already
//   triggered (alarm_codes_en_US.csv: "Probe fail. Probe is not in the
//   expected initial state before starting probe cycle when G38.2 and G38.3
//   is not triggered ..."): the next probing move from a probe still
//   deflected against the obstruction raises it. The import refuses a
//   console where a protected move reports :1.
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
        .id = DialectId::grbl,
        .name = "grbl",
        .title = "grbl",
        .extension = "nc",
        .comment_open = ";",
        .comment_close = "",
        .program_start = {},
        .modes = "G21 G91 G94",
        .probe_word = "G38.2",
        .rapid_word = "G0",
        .feed_word = "G1",
        .pause_message = "",
        .pause_word = "M0",
        .open_record = {},
        .before_probe = {},
        .after_probe = {},
        .guard_word = "G38.3",
        .before_guard = {},
        .after_guard = {},
        .after_recorded_probe = {},
        .close_record = {},
        .end = {"G90", "M2"},
        .after_end = {},
        .guard_alarm = {},
        .file_end = {},
        .record_notes = {"Positions: grbl answers [PRB:x,y,z:1] after each probe (machine",
                         "positions; set $13=0 for mm). Save the sender's console to a file and",
                         "import that file."},
        .guard_notes =
            {"Protected moves are G38.3, the probe armed: grbl answers [PRB:...:0] after",
             "one that touches nothing. It stops one that touches something ([PRB:...:1])",
             "but cannot branch, so the program goes on; the next G38.2 or G38.3 then",
             "stops it with ALARM:4 if the probe is still deflected. No probe follows the",
             "last protected move: the import refuses a console where one answers :1."},
        .result_notes = {"grbl has no variables or arithmetic: the program computes nothing and",
                         "checks no tolerance. probecycle import computes the feature's result",
                         "(and the tolerance check) from the console's [PRB:] lines."},
        .log_format = LogFormat::grbl_console,
    };
    return dialect;
}

// Fanuc-type macro B (Fanuc, and the controls that follow it; Haas has its
// own dialect below, this one with its look-ahead limit). Checked against
// (each passage re-read in the source named):
// - G31: Fanuc Series 15i/150i-MA Operator's Manual p.564 ("G31 IP_ ;
//   One-shot G code ... If an external skip signal is input during the
//   execution of this command, execution of the command is interrupted and
//   the next block is executed"; the coordinates at the skip in "#5061 to
//   #5080 ... #5061 1st axis coordinate value"; the feed is F or parameter
//   1428 "depending on the setting of the bit3 (SKF) in parameter No. 1400";
//   "Servo delay compensation": the stored position can have the servo
//   system's delay taken out). Haas Mill Operator's Manual, "G31 Feed Until
//   Skip" (#5061-#5066; "If the probe does not receive a skip signal ... the
//   skip signal position will be recorded at the end of the programmed move.
//   The program will continue."; "The G31 line must have a Feed command";
//   "Do not use Cutter Compensation (G41, G42) with a G31"). NCT 2000M/99M
//   manual s.18.1 and p.183 (Fanuc-compatible: #5061 is in the work
//   coordinate system, "Unless the skip signal has arrived, the above
//   variables will assume the end-point position programmed in block G31";
//   without P the first skip signal) and Yaskawa YASNAC LX3 (same: "When the
//   skip signal is not turned on in G 31 block, the skip signal position is
//   at the end of G 31 block"; its #5041 read during a move waits for the
//   move's end). Mitsubishi M700V s.15.2/15.4: G31 follows G90/G91, no alarm
//   without a trigger, and P is a bit mask of skip signals there while NCT
//   and Fanuc give P other meanings: so no P word.
// - So the program checks every probe itself: it keeps the probing axis's
//   programmed end point (the current position #5041-#5043 read in the
//   block before the G31, plus the move) and alarms when the skip position
//   is that end point. The tolerance, 0.05 mm: at rest the current position
//   stands within the in-position width of the commanded one; a touch that
//   triggers within 0.05 mm of the end of its search (which goes 1 mm, or half
//   the stylus's overtravel, past the expected surface) is taken for none,
//   the safe side. Not confirmed: that every control reads #5041 only after
//   the previous move ended (Fanuc buffers the next block during a move,
//   FS16i/18i/21i-TB "Notes on using custom macros"; Yaskawa waits). A read
//   taken early can only miss this alarm, never raise a false one. The skip
//   position is read right after the G31, with no non-buffered M code: G31
//   stops the read-ahead until the skip block ends (Series 21i/210i-MB
//   operator's manual B-63614EN/01 s.15.7.1 p.322, "M codes that are not
//   buffered, G53, G31", example "N1 G31 X100.0 ; N2 #100=1"; the 30i/31i/32i
//   manual B-63944EN/03 s.16.8 the same), as working Fanuc probing programs
//   do (mojimould/mould_moji O919100.nc: IF[#5063LE...]GOTO800, #3000=141).
// - A protected move is G31 to the move's end with the mirror of that
//   check: the end kept in #101 as for a probe, then a jump to alarm 102
//   (PROBE PATH OBSTRUCTED) when the skip position is 0.05 mm or more from
//   it. Without a skip signal the skip position is the programmed end (Haas,
//   NCT and Yaskawa above), so a skip position short of the end is a touch.
//   The moving axis's own skip variable is read: #5061 X, #5062 Y, #5063 Z
//   (15i p.564: 1st, 2nd, 3rd axis). A touch in the last 0.05 mm passes: the
//   move ends there anyway, so the stylus is deflected by at most that. An
//   early #5041 read (above) can raise this alarm falsely, never hide it.
//   GE is one of macro B's comparison operators EQ NE GT GE LT LE (the
//   tutorial "G-Code Macro Programming"; EQ, NE and LE in the working program
//   above).
// - #3000=n (TEXT) stops with alarm n (cncci.com, "Generating alarms for
//   dangerous situations": "for most control models, must range between 100
//   and 255"): 101 and 102, upper-case text. IF[...]GOTOn and the N label
//   after M30: the same working program.
// - POPEN, DPRNT[...], PCLOS: Haas 96-8000 Rev AC p.116 ("DPRNT must be the
//   only command in the block"; text "any character from A to Z or the
//   letters (+,-,/,*, and the space). When an asterisk is output, it is
//   converted to a space"; #nnnn[wf]: whole and fractional places, "The total
//   places reserved for output cannot be equal to zero or greater tha[n]
//   eight"; "leading spaces are output"; "A carriage return is sent out after
//   every DPRNT block"). So the text is letters and * only (the plan's id in
//   letters, touch numbers from a variable) and the positions #5061[44]: 4
//   decimals (0.1 um, finer than the 1 um of most skip positions), 4 whole
//   digits (9999.9999 mm, more than any travel; Haas widens a longer field),
//   4 + 4 = 8, Haas's maximum. Fanuc ends an output line with LF or LF CR CR
//   (parameter 0100#3 NCR, FS16i/18i-TB p.649); Haas's POPEN/PCLOS send DC2
//   and DC4 on its serial port (Haas 96-8000, 1999, p.115): the import takes
//   every ending and drops control bytes and '%'.
// - "%" starts and ends the file, O-number, "(...)" comments, M00, M30, G21,
//   G40, G80, G90/G91, G94: Fanuc memory-card format (FS16i/18i-TB p.649: "A
//   file starts with % or LF ... A file always ends with %"), the Rockwell
//   8520 example "POPEN; BPRNT[...]; PCLOS; M30;".
// - A cycle's result in the common variables #110-#118 (#100-#199
//   are common variables cleared at power off on Fanuc, 15i manual "Custom
//   macro", variable types), with macro B's arithmetic ([ ], ABS[...], + - /)
//   and comparisons (LE, EQ: the tutorial above), IF[...]GOTOn to an N label
//   further down as in the working program above; out of tolerance with a
//   stop, alarm 103 (the range 100-255 above) after PCLOS.
// Not confirmed, so not relied on: where DPRNT output goes (a Fanuc's I/O
// channel, a Haas's serial port or a file: the user captures it); the sign
// and leading zeros of a printed number (Fanuc parameter PRT): the import
// reads any; spindle orientation to an angle (M19 differs by maker and
// builder): the ring program takes the user's command; Mitsubishi's skip
// variables, DPRNT and #3000 (only its G31 was found).
const Dialect& fanuc_dialect() {
    static const Dialect dialect{
        .id = DialectId::fanuc,
        .name = "fanuc",
        .title = "Fanuc macro B",
        .extension = "nc",
        .comment_open = "(",
        .comment_close = ")",
        .plain_comments = true,
        .program_start = {"%", "O1300 (PROBECYCLE)"},
        .modes = "G21 G40 G80 G91 G94",
        .probe_word = "G31",
        .rapid_word = "G0",
        .feed_word = "G1",
        .pause_message = "",
        .pause_word = "M00",
        .open_record = {"POPEN", "DPRNT[PROBECYCLE*PLAN*{id_letters}*{KIND}]"},
        .before_probe = {"#101={current}{distance}"},
        .after_probe = {"IF[ABS[{skip}-#101]LT0.050]GOTO9001"},
        .current_position = {"#5041", "#5042", "#5043"},
        .skip_position = {"#5061", "#5062", "#5063"},
        .guard_word = "G31",
        .before_guard = {"#101={current}{distance}"},
        .after_guard = {"IF[ABS[{skip}-#101]GE0.050]GOTO9002"},
        .after_recorded_probe = {"#102={n}",
                                 "DPRNT[TOUCH#102[40]*X#5061[44]*Y#5062[44]*Z#5063[44]]"},
        .close_record = {"DPRNT[PROBECYCLE*END]", "PCLOS"},
        .end = {"G90", "M30"},
        .after_end = {"N9001", "DPRNT[PROBECYCLE*NO*TRIGGER]", "PCLOS",
                      "#3000=101(PROBE DID NOT TRIGGER)"},
        .guard_alarm = {"N9002", "DPRNT[PROBECYCLE*OBSTRUCTED]", "PCLOS",
                        "#3000=102(PROBE PATH OBSTRUCTED)"},
        .file_end = {"%"},
        .record_notes =
            {"Positions: DPRNT prints a line PROBECYCLE PLAN, one line TOUCH n X x Y y Z z",
             "per recorded touch (skip positions #5061-#5063, work coordinates) and",
             "PROBECYCLE END. Capture that output (your control's DPRNT channel: a serial",
             "terminal, a memory card or a file) and import it.",
             "Uses the common variables #101 and #102. Program number O1300: renumber it if",
             "your control has one.",
             "A probe that does not trigger stops with alarm 101 PROBE DID NOT TRIGGER.",
             "CHECK on Fanuc before the delay test: SKF, parameter 1400#3 on the 15i, makes",
             "G31 use a fixed skip feed instead of F; the servo delay compensation of the skip",
             "position takes the servo lag out of #5061, so the fitted delay comes out",
             "smaller than the real one."},
        .guard_notes =
            {"Protected moves are G31 to the end of the move: when the skip position is not",
             "that end, the probe touched something, and the program prints PROBECYCLE",
             "OBSTRUCTED and stops with alarm 102 PROBE PATH OBSTRUCTED."},
        .result_record =
            {"DPRNT[RESULT*S{size}[44]*X{centre_x}[44]*Y{centre_y}[44]*D{deviation}[44]*"
             "T{flag}[10]]"},
        .tolerance_check = {"{flag}=0", "IF[ABS[{deviation}]LE{tolerance}]GOTO9003", "{flag}=1",
                            "N9003"},
        .out_of_tolerance = {"IF[{flag}EQ0]GOTO9004", "DPRNT[PROBECYCLE*OUT*OF*TOLERANCE]",
                             "{stop}", "N9004"},
        .tolerance_stop = {"PCLOS", "#3000=103(SIZE OUT OF TOLERANCE)"},
        .result_notes = {"DPRNT prints them as RESULT S size X centre Y centre D deviation T flag;",
                         "the import reads that line and checks it against the touches."},
        .log_format = LogFormat::dprnt,
        .result_tolerance_mm = 2e-4,  // 4 printed decimals
        .orient_from_user = true,
    };
    return dialect;
}

// Haas (mill control with the macro option): the Fanuc-type program above,
// whose G31, #5061-#5066, DPRNT and #nnnn[44] formats are Haas's own texts
// (cited there), with the control's look-ahead limited before every read of
// a position:
// - Haas Mill Operator's Manual 96-8000 rev R (June 2007), "Macros", p.84:
//   "Lookahead is an issue of great importance to the macro programmer ...
//   This includes the interpretation of macro variables", and "G103 P1 can
//   be used to limit lookahead to 1 blocks", its example padding with empty
//   blocks after the move. A Haas does not wait for a move to end before it
//   reads #5041 or #5061 in a later block, so the program starts with
//   G103 P1 and puts three empty blocks (";", Haas's end of block) between a
//   move and the next read of a position: one block of look-ahead reaches
//   only an empty block while the move runs. Production Haas macros do the
//   same (versabuilt/Gcode r2c/haas/legacy/9001.nc, "Disable lookahead,
//   needs several empty lines after": G103 P1 and empty ";" blocks; "G103
//   P0 (Enable lookahead)" at the end, as this program ends).
// Not confirmed, so the header asks the user to prove it: how many empty
// blocks the control needs (three is more than the manual's one block of
// look-ahead; G103 P1 slows the program by a block's time per block, which
// the model leaves out); where DPRNT output goes (the Haas's serial port, or
// a file or a network share the control's settings choose).
const Dialect& haas_dialect() {
    static const Dialect dialect = [] {
        Dialect d = fanuc_dialect();
        d.id = DialectId::haas;
        d.name = "haas";
        d.title = "Haas";
        d.open_record = {"G103 P1", "POPEN", "DPRNT[PROBECYCLE*PLAN*{id_letters}*{KIND}]"};
        d.settle = {";", ";", ";"};
        d.end = {"G103 P0", "G90", "M30"};
        d.record_notes = {
            "Needs the control's macro option.",
            "Positions: DPRNT prints a line PROBECYCLE PLAN, one line TOUCH n X x Y y Z z",
            "per recorded touch (skip positions #5061-#5063, work coordinates) and",
            "PROBECYCLE END. Send DPRNT where you can catch it (the serial port, or the file",
            "or network share your control's settings choose) and import that output.",
            "Uses the common variables #101 and #102. Program number O1300: renumber it if",
            "your control has one.",
            "A probe that does not trigger stops with alarm 101 PROBE DID NOT TRIGGER.",
            "Look-ahead: G103 P1 limits it to one block, and three empty blocks stand between",
            "every move and the next read of a position (Haas manual 96-8000, Macros). Prove",
            "it out: run the program once with the probe clear of the part; its first probing",
            "move must stop with alarm 101."};
        return d;
    }();
    return dialect;
}

// Mitsubishi M70/M80 (M700V/M70V programming manual, chapter 15, "Skip
// function"; ../shared/domain.md, "Controls' probing words"):
// - G31 X.. F.. follows G90/G91 (incremental allowed); "with no trigger the
//   block ends at its target with no alarm": the program checks each probe
//   itself as the Fanuc-type one does (the end point kept in #101, a jump
//   when the skip position is that end); a skip signal already on at the
//   start ends the block at once, which the same check cannot tell from a
//   touch, as on every control. G31 P.. is a mask over the skip inputs, so
//   no P word.
// - The manual's own example reads the skip position after a dwell, the
//   "machine stop check": "G31 X100. F100 ; G04 ; #101=#5061 ;". So a G04
//   stands before every read of a position (settle), the current position
//   #5041-#5043 too.
// - The user macro's words the program uses (IF[...]GOTOn, ABS[ ], the
//   comparisons EQ LT LE GE, [ ] and + - /, common variables) are those of
//   the M700V manual, s.13.5 "User macro specifications" (its conditional
//   expressions list EQ NE GT GE LT LE).
// Not confirmed, so not relied on: #3000 user alarms and DPRNT on Mitsubishi
// (domain.md: "not confirmed for Mitsubishi"). So the program stops at M00
// with its reason in a comment on the same block (the block the control
// shows), and ends with M30 at cycle start; and the record is the common
// variables #500-#999, which stay after the program ends: #500-#503 the
// plan's id (four groups of 4 hex digits, each as a number 0-65535), #504
// the program's state (0 running, 1 done, 101 no trigger, 102 obstructed,
// 103 out of tolerance), #505 the touches kept, #506-#510 a cycle's result
// (S X Y D T), and from #520 X, Y and Z of each recorded touch. The user
// outputs the common variables (the control's data output screen) or copies
// them from the variable screen, and imports that list. Also not confirmed:
// #5041-#5043 as the current position in work coordinates (as on Fanuc);
// that #500-#999 are all present (some controls have fewer without an
// option); the text of the control's variable output file (the import
// reads "#n value", "#n=value" and "n value" lines and ignores the rest).
// The header says to prove each out.
const Dialect& mitsubishi_dialect() {
    // The Fanuc-type program's words (G31, the checks on #5041-#5043 and
    // #5061-#5063, IF[...]GOTOn, M00, M30), with the record and the stops
    // above.
    static const Dialect dialect = [] {
        Dialect d = fanuc_dialect();
        d.id = DialectId::mitsubishi;
        d.name = "mitsubishi";
        d.title = "Mitsubishi M70/M80";
        d.open_record = {"#500={id_1}", "#501={id_2}", "#502={id_3}",
                         "#503={id_4}", "#504=0",      "#505=0"};
        d.settle = {"G04"};
        d.after_recorded_probe = {"{touch_x}=#5061", "{touch_y}=#5062", "{touch_z}=#5063",
                                  "#505={n}"};
        d.close_record = {"#504=1"};
        d.after_end = {"N9001", "#504=101", "G90", "M00 (PROBE DID NOT TRIGGER)", "M30"};
        d.guard_alarm = {"N9002", "#504=102", "G90", "M00 (PROBE PATH OBSTRUCTED)", "M30"};
        d.record_notes = {
            "Positions: the program keeps them in common variables, which stay after it",
            "ends: #500-#503 the plan, #504 its state (1 done, 101 no trigger, 102",
            "obstructed, 103 out of tolerance), #505 the touches kept, and X Y Z of each",
            "touch, three variables each from #520 on (touch 1 #520-#522, touch 2",
            "#523-#525 ...). Output the common variables to a file, or copy them from the",
            "variable screen as lines #n value, and import that list. Uses #101 too.",
            "Program number O1300: renumber it if your control has one.",
            "A probe that does not trigger ends at its target with no alarm on this control:",
            "the program checks it and stops at M00 PROBE DID NOT TRIGGER (cycle start ends",
            "the program).",
            "NOT CONFIRMED for Mitsubishi, prove it out before a touch: #5041-#5043 read as",
            "the current position in work coordinates after G04 (run the program once with",
            "the probe clear of the part: its first probing move must stop at PROBE DID NOT",
            "TRIGGER); that your control has common variables #500 to the last one this",
            "program uses. #3000 alarms and DPRNT are not used: they are not confirmed for",
            "this control."};
        d.guard_notes = {
            "Protected moves are G31 to the end of the move: when the skip position is not",
            "that end, the probe touched something, and the program stops at M00 PROBE PATH",
            "OBSTRUCTED."};
        d.result_record = {"#506={size}", "#507={centre_x}", "#508={centre_y}", "#509={deviation}",
                           "#510={flag}"};
        d.out_of_tolerance = {"{stop}"};
        d.tolerance_stop = {"IF[{flag}EQ0]GOTO9004",       "#504=103", "G90",
                            "M00 (SIZE OUT OF TOLERANCE)", "M30",      "N9004"};
        d.result_notes = {"The program keeps them in #506-#510 (S X Y D T) as well; the import",
                          "reads them and checks them against the touches."};
        d.log_format = LogFormat::common_variables;
        // A copied list may hold 3 decimals: half a digit of four touches and
        // the result, with room.
        d.result_tolerance_mm = 3e-3;
        d.first_touch_variable = 520;
        d.last_variable = 999;
        return d;
    }();
    return dialect;
}

// Siemens SINUMERIK 840D sl and ONE (../shared/domain.md, "Controls' probing
// words", which gives the sources):
// - MEAS=1 G1 X=... F...: a measuring move with probe 1 on its rising edge
//   (-1 the falling edge, 2 and -2 probe 2), which stops the move at the
//   trigger and deletes the distance to go (Job Planning manual PM 03/2006,
//   s.5.7). Every production use found (Autodesk's "Siemens SINUMERIK 840D
//   Inspection" post) programs an absolute target, then STOPRE, then reads
//   $AA_MW[axis] (the trip in workpiece coordinates) and tests $A_PROBE[n]
//   (<> 1 after a measuring move: no point taken; == 1 after a positioning
//   move: the path is obstructed), and stops with MSG("...") and M0. MEAS
//   under G91 is confirmed nowhere, so each measuring and protected move is
//   one absolute block: STOPRE, the start $AA_IW[axis] (the current position
//   in workpiece coordinates) plus the move into R1, "MEAS=n G90 G1 X=R1
//   F..", and G91 again on the next block; the probe input is the user's
//   (ProgramOptions::probe_input, the CLI's --probe-input).
// - WRITE(error, "file", text) appends a line to a file (SINUMERIK ONE NC
//   programming 12/2019, p.566); text joined with << and each number as
//   SPRINT("%12.4F", value) (840D sl 10/2015): 4 decimals, 0.1 um. The error
//   variable is an INT, defined first in the program (DEF INT PC_ERROR), and
//   checked after each WRITE: a failed write stops the program.
// - No SETAL: its user range of alarm numbers was not confirmed. A stop is
//   MSG with the reason and M0; cycle start then ends the program (M30).
// - The result in R60-R68 (R parameters R0-R99 are the standard set), with
//   ( ) and ABS( ), the comparisons <= == and jumps "IF ... GOTOF label"
//   to a label on its own line ("LABEL:").
// Not confirmed, so the header asks the user to prove it: that $A_PROBE[n]
// still reads 1 after the axis stopped on a trigger (the stylus is still
// deflected by the overtravel; a probe that springs free reads as no
// trigger, the safe side); where the WRITE file lands and its name's type
// (the program's directory on the NC); the text SPRINT gives for a number.
// The import reads the lines of the last run in the file (WRITE appends).
const Dialect& siemens_dialect() {
    static const Dialect dialect{
        .id = DialectId::siemens,
        .name = "siemens",
        .title = "Siemens 840D sl / ONE",
        .extension = "mpf",
        .comment_open = ";",
        .comment_close = "",
        // Definitions come before the first block that runs.
        .program_start = {"DEF INT PC_ERROR"},
        .modes = "G71 G40 G91 G94",
        .probe_word = "G1",
        .rapid_word = "G0",
        .feed_word = "G1",
        .pause_message = R"(MSG("{text}"))",
        .pause_word = "M0",
        .open_record = {R"(WRITE(PC_ERROR,"PROBECYCLE_LOG","PROBECYCLE PLAN {id_letters} {KIND}"))",
                        "IF PC_ERROR<>0 GOTOF WRITE_FAILED"},
        .before_probe = {"STOPRE", "R1={current}{distance}"},
        .after_probe = {"G91", "STOPRE", "IF $A_PROBE[{probe}]<>1 GOTOF NO_TRIGGER"},
        .current_position = {"$AA_IW[X]", "$AA_IW[Y]", "$AA_IW[Z]"},
        .skip_position = {"$AA_MW[X]", "$AA_MW[Y]", "$AA_MW[Z]"},
        .guard_word = "G1",
        .before_guard = {"STOPRE", "R1={current}{distance}"},
        .after_guard = {"G91", "STOPRE", "IF $A_PROBE[{probe}]==1 GOTOF OBSTRUCTED"},
        .probe_move = "MEAS={input} G90 {word} {axis}=R1 F{feed}",
        .after_recorded_probe =
            {R"(WRITE(PC_ERROR,"PROBECYCLE_LOG","TOUCH {n} X"<<SPRINT("%12.4F",{x})<<" )"
             R"(Y"<<SPRINT("%12.4F",{y})<<" Z"<<SPRINT("%12.4F",{z})))",
             "IF PC_ERROR<>0 GOTOF WRITE_FAILED"},
        .close_record = {R"(WRITE(PC_ERROR,"PROBECYCLE_LOG","PROBECYCLE END"))",
                         "IF PC_ERROR<>0 GOTOF WRITE_FAILED"},
        .end = {"G90", "M30"},
        .after_end = {"NO_TRIGGER:", R"(WRITE(PC_ERROR,"PROBECYCLE_LOG","PROBECYCLE NO TRIGGER"))",
                      R"(MSG("PROBECYCLE: PROBE DID NOT TRIGGER"))", "G90", "M0", "M30",
                      "WRITE_FAILED:", R"(MSG("PROBECYCLE: WRITE TO PROBECYCLE_LOG FAILED"))",
                      "G90", "M0", "M30"},
        .guard_alarm = {"OBSTRUCTED:",
                        R"(WRITE(PC_ERROR,"PROBECYCLE_LOG","PROBECYCLE OBSTRUCTED"))",
                        R"(MSG("PROBECYCLE: PROBE PATH OBSTRUCTED"))", "G90", "M0", "M30"},
        .file_end = {},
        .record_notes =
            {"Positions: WRITE appends to the file PROBECYCLE_LOG a line PROBECYCLE PLAN, one",
             "line TOUCH n X x Y y Z z per recorded touch ($AA_MW of the probing axis, $AA_IW",
             "of the others, workpiece coordinates) and PROBECYCLE END. Import that file: the",
             "import reads its last run. Uses R1 and the INT PC_ERROR; a failed WRITE stops",
             "the program.",
             "Measuring moves: STOPRE, the target from $AA_IW into R1, MEAS=n G90 G1 to it,",
             "G91 again (MEAS under G91 is not confirmed). The probe input n is the one this",
             "program was written for: MEAS and $A_PROBE below use it.",
             "A probe that does not trigger ($A_PROBE not 1 after STOPRE) stops with the",
             "message PROBECYCLE: PROBE DID NOT TRIGGER (M0; cycle start ends the program).",
             "NOT CONFIRMED, prove it out before a touch: that $A_PROBE still reads 1 once",
             "the axis has stopped on a trigger (run one touch at reduced feed override and",
             "check the file gets its TOUCH line); where your control keeps PROBECYCLE_LOG.",
             "Check MD13220 (a probe delay the control subtracts) before a delay test."},
        .guard_notes =
            {"Protected moves are measuring moves to the end of the move: when $A_PROBE",
             "reads 1 after one, the probe touched something, and the program stops with",
             "the message PROBECYCLE: PROBE PATH OBSTRUCTED."},
        .result_record =
            {R"(WRITE(PC_ERROR,"PROBECYCLE_LOG","RESULT S"<<SPRINT("%12.4F",{size})<<" )"
             R"(X"<<SPRINT("%12.4F",{centre_x})<<" Y"<<SPRINT("%12.4F",{centre_y})<<" )"
             R"(D"<<SPRINT("%12.4F",{deviation})<<" T"<<SPRINT("%12.4F",{flag})))",
             "IF PC_ERROR<>0 GOTOF WRITE_FAILED"},
        .tolerance_check = {"{flag}=0", "IF ABS({deviation})<={tolerance} GOTOF TOLERANCE_CHECKED",
                            "{flag}=1", "TOLERANCE_CHECKED:"},
        .out_of_tolerance = {"IF {flag}==0 GOTOF TOLERANCE_DONE",
                             R"(WRITE(PC_ERROR,"PROBECYCLE_LOG","PROBECYCLE OUT OF TOLERANCE"))",
                             "{stop}", "TOLERANCE_DONE:"},
        .tolerance_stop = {R"(MSG("PROBECYCLE: SIZE OUT OF TOLERANCE"))", "G90", "M0", "M30"},
        .result_notes = {"WRITE appends them to PROBECYCLE_LOG as RESULT S size X centre Y centre",
                         "D deviation T flag; the import reads that line and checks it against",
                         "the touches."},
        .variable_prefix = "R",
        .first_result_variable = 60,
        .group_open = '(',
        .group_close = ')',
        .log_format = LogFormat::write_file,
        .result_tolerance_mm = 2e-4,  // 4 decimals, as DPRNT's
        .orient_from_user = true,
    };
    return dialect;
}

const Dialect& dialect(DialectId id) {
    switch (id) {
        case DialectId::linuxcnc:
            return linuxcnc_dialect();
        case DialectId::grbl:
            return grbl_dialect();
        case DialectId::fanuc:
            return fanuc_dialect();
        case DialectId::haas:
            return haas_dialect();
        case DialectId::mitsubishi:
            return mitsubishi_dialect();
        case DialectId::siemens:
            return siemens_dialect();
    }
    return linuxcnc_dialect();
}

const std::array<DialectId, 6>& all_dialects() {
    static constexpr std::array<DialectId, 6> kAll = {DialectId::linuxcnc,   DialectId::grbl,
                                                      DialectId::fanuc,      DialectId::haas,
                                                      DialectId::mitsubishi, DialectId::siemens};
    return kAll;
}

std::optional<DialectId> dialect_from_string(std::string_view word) {
    for (const DialectId id : all_dialects()) {
        if (word == dialect(id).name) return id;
    }
    return std::nullopt;
}

std::string dialect_names(std::string_view separator) {
    std::string names;
    for (const DialectId id : all_dialects()) {
        if (!names.empty()) names += separator;
        names += dialect(id).name;
    }
    return names;
}

bool names_probe_input(const Dialect& dialect) {
    return dialect.probe_move != nullptr &&
           std::string_view(dialect.probe_move).find("{input}") != std::string_view::npos;
}

std::size_t max_recorded_touches(const Dialect& dialect) {
    if (dialect.first_touch_variable == 0) return 0;
    return static_cast<std::size_t>(dialect.last_variable - dialect.first_touch_variable + 1) / 3;
}

std::string id_letters(std::string_view hex_id) {
    std::string letters;
    for (const char c : hex_id) {
        const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
        letters += digit < 0 ? '?' : static_cast<char>('A' + digit);
    }
    return letters;
}

}  // namespace probecycle
