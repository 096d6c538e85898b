#pragma once

// A control's G-code dialect as a small table of syntax (issue 13): the words
// of a probing move, a rapid and a feed move, a pause, and how the control
// keeps the positions it probed. The generator (program_writer.h) reads the
// table; a dialect is never a copy of the generator. Each table cites what
// it was checked against in dialect.cpp; a detail that could not be checked
// is left out (README, "Programs for your control").

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace probecycle {

enum class DialectId { linuxcnc, grbl };

struct Dialect {
    DialectId id{DialectId::linuxcnc};
    const char* name;       // the CLI's word: "linuxcnc"
    const char* title;      // "LinuxCNC"
    const char* extension;  // of the program file: "ngc"
    // Starts a comment to the end of the line that the control never acts on.
    const char* comment;
    // The modes every program sets first: mm, incremental, feed per minute.
    const char* modes;
    const char* probe_word;  // a probing move toward the part that alarms without a trigger
    const char* rapid_word;
    const char* feed_word;
    // A pause: the message line ({text}; empty: the message is a comment),
    // then the word that stops until cycle start.
    const char* pause_message;
    const char* pause_word;
    // Lines after the modes that open the control's record ({id}: the plan's
    // id, {kind}: delay, ring or cycle).
    std::vector<const char*> open_record;
    // A line after each recorded probe ({n}: its number, from 1); empty: none.
    const char* after_recorded_probe;
    // Lines before the end that close the record.
    std::vector<const char*> close_record;
    // Back to absolute distances, and the end of the program.
    std::vector<const char*> end;
    // Header lines: where the positions go and what the import reads.
    std::vector<const char*> record_notes;
};

const Dialect& linuxcnc_dialect();
const Dialect& grbl_dialect();
const Dialect& dialect(DialectId id);
// By the CLI's word; nullopt when unknown.
std::optional<DialectId> dialect_from_string(std::string_view word);
// "linuxcnc, grbl"
std::string dialect_names();

}  // namespace probecycle
