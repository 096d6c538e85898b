#pragma once

// A control's G-code dialect as a small table of syntax: the words
// of a probing move, a rapid and a feed move, a pause, and how the control
// keeps the positions it probed. The generator (program_writer.h) reads the
// table; a dialect is never a copy of the generator. Each table cites what
// it was checked against in dialect.cpp; a detail that could not be checked
// is left out (docs/programs.md).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace probecycle {

enum class DialectId { linuxcnc, grbl, fanuc, haas, mitsubishi, siemens };

// How the control's record of the touches comes back (machine_log.h):
// LinuxCNC's LOG or PROBEOPEN file, a grbl sender's console, the
// Fanuc-type DPRNT output, the common variables the program stores the
// touches in (a list of "#n value" lines), or the file a Siemens program
// appends its lines to with WRITE (the DPRNT lines' words; the last run in
// the file counts).
enum class LogFormat { linuxcnc_log, grbl_console, dprnt, common_variables, write_file };

struct Dialect {
    DialectId id{DialectId::linuxcnc};
    const char* name;       // the CLI's word: "linuxcnc"
    const char* title;      // "LinuxCNC"
    const char* extension;  // of the program file: "ngc"
    // A comment that the control never acts on: comment_open, the text,
    // comment_close ("; text", "(TEXT)").
    const char* comment_open;
    const char* comment_close;
    // Comments in upper case, with letters, digits, spaces and . , - + / * = #
    // only (the rest becomes a space): what every Fanuc-type control reads.
    bool plain_comments{false};
    // Lines before the header (the file's start, a program number).
    std::vector<const char*> program_start;
    // The modes every program sets first: mm, incremental, feed per minute.
    const char* modes;
    const char* probe_word;  // a probing move toward the part
    const char* rapid_word;
    const char* feed_word;
    // A pause: the message line ({text}; empty: the message is a comment),
    // then the word that stops until cycle start.
    const char* pause_message;
    const char* pause_word;
    // Lines after the modes that open the control's record ({id}: the plan's
    // id, {id_letters}: the id in the letters of id_letters(), {kind}: delay,
    // ring or cycle, {KIND}: the same in upper case).
    std::vector<const char*> open_record;
    // Lines before and after every probing move ({current}: the variable of
    // the probing axis's current position, {skip}: of its skip position,
    // {distance}: the signed move, "+12.000"; {input} and {probe}: the probe
    // input of ProgramOptions and its number); empty: none. A control that
    // goes on without an alarm when the probe does not trigger checks here.
    std::vector<const char*> before_probe;
    std::vector<const char*> after_probe;
    // Lines before every read of a position ({current} in before_probe and
    // before_guard, {skip} in after_probe and after_guard): what makes the
    // control read it only once the move before it has ended (Haas's empty
    // blocks under G103 P1, Mitsubishi's G04); empty where the control
    // waits by itself.
    std::vector<const char*> settle{};
    // The variables {current} and {skip} stand for, per axis X, Y, Z.
    std::array<const char*, 3> current_position{};
    std::array<const char*, 3> skip_position{};
    // A protected move (StepKind::guard): the probe armed on a move that must
    // not trigger. The word, a line before it and lines after it ({current},
    // {skip} and {distance} as for a probe; {label}: a number of the move's
    // own, 1000 + its count from 1): a trigger means the path is obstructed,
    // and the lines after stop the program where the control can branch.
    const char* guard_word;
    std::vector<const char*> before_guard;
    std::vector<const char*> after_guard;
    // The probing or protected move itself ({word}: probe_word or guard_word,
    // {axis}, {distance}, {feed}, {input}: the probe's input, Siemens's
    // MEAS=1, -1, 2, -2, from ProgramOptions::probe_input); nullptr: "{word}
    // {axis}{distance} F{feed}", incremental.
    const char* probe_move{nullptr};
    // Lines after each recorded probe ({n}: its number, from 1; {touch_x},
    // {touch_y}, {touch_z}: the variables it is stored in, from
    // first_touch_variable on, three per touch).
    std::vector<const char*> after_recorded_probe;
    // Lines before the end that close the record.
    std::vector<const char*> close_record;
    // Back to absolute distances, and the end of the program.
    std::vector<const char*> end;
    // Lines after the end (reached by a jump only).
    std::vector<const char*> after_end;
    // The branch an obstructed protected move jumps to, after after_end; only
    // in a program with protected moves.
    std::vector<const char*> guard_alarm;
    // The file's last lines.
    std::vector<const char*> file_end;
    // Header lines: where the positions go and what the import reads.
    std::vector<const char*> record_notes;
    // Header lines of a program with protected moves: what the control does
    // when one touches something.
    std::vector<const char*> guard_notes;
    // A cycle plan's result (feature_result.h), in a control that computes
    // (macro variables and arithmetic); empty where it cannot (the import
    // computes it). The variables are the writer's ({size}, {centre_x},
    // {centre_y}, {deviation}, {flag}: variable_prefix and a number from
    // first_result_variable on, "#110" or "R60", in expressions grouped with
    // group_open and group_close). The log
    // line(s) of the result; the lines that set {flag} to 1 when
    // |{deviation}| > {tolerance}; the lines that report a set flag, where a
    // line "{stop}" stands for tolerance_stop when the plan stops out of
    // tolerance (and is left out when it flags).
    std::vector<const char*> result_record{};
    std::vector<const char*> tolerance_check{};
    std::vector<const char*> out_of_tolerance{};
    std::vector<const char*> tolerance_stop{};
    // Header lines of a cycle program: where its result goes.
    std::vector<const char*> result_notes{};
    const char* variable_prefix{"#"};
    int first_result_variable{110};
    char group_open{'['};
    char group_close{']'};
    // Where the record comes back, and how close a result the program
    // computed must come to the import's (half a printed digit of each of up
    // to four touches and of the result, with room).
    LogFormat log_format{LogFormat::linuxcnc_log};
    double result_tolerance_mm{1e-5};
    // A control whose record is its common variables: the first of the
    // touches' variables and the last variable it may use (0: none).
    int first_touch_variable{0};
    int last_variable{0};
    // No portable word turns the spindle to an angle: the ring program
    // needs the user's command for 180 deg (ProgramOptions).
    bool orient_from_user{false};
};

const Dialect& linuxcnc_dialect();
const Dialect& grbl_dialect();
const Dialect& fanuc_dialect();
const Dialect& haas_dialect();
const Dialect& mitsubishi_dialect();
const Dialect& siemens_dialect();
const Dialect& dialect(DialectId id);
// Every dialect, in the order the CLI and the window list them.
const std::array<DialectId, 6>& all_dialects();
// By the CLI's word; nullopt when unknown.
std::optional<DialectId> dialect_from_string(std::string_view word);
// "linuxcnc, grbl, fanuc, haas, mitsubishi, siemens"; with "|": the CLI's
// type name.
std::string dialect_names(std::string_view separator = ", ");
// Whether the dialect's probing moves name the probe's input ({input} in
// probe_move): ProgramOptions::probe_input is then the user's to give.
bool names_probe_input(const Dialect& dialect);
// The most recorded touches a plan may have in the dialect (a control
// that keeps them in variables has a fixed number); 0: no limit.
std::size_t max_recorded_touches(const Dialect& dialect);

// The plan's id (16 hex digits) in letters, 0 -> A ... f -> P: a DPRNT text
// holds letters only (Haas: "any character from A to Z" and + - / * space).
std::string id_letters(std::string_view hex_id);

}  // namespace probecycle
