#pragma once

// One problem with one input field: a scenario key, a CLI option, a column.
// It names the field, the value as given and what is allowed; the allowed
// part is a message of its own, so the window can translate it.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/message.h"

namespace probecycle {

// A value longer than this is shown by its first kShownStartChars characters
// and its length.
constexpr std::size_t kMaxShownValueChars = 80;
constexpr std::size_t kShownStartChars = 40;

struct FieldError {
    std::string key;    // e.g. "machine.scan_period_s"
    std::string value;  // the offending value as text; empty when there is none to show
    Message allowed;    // e.g. "a number from 0 to 0.1 s"

    // "%1: got %2; allowed: %3", or "%1: %3" without a value; a long value is cut.
    Message to_message() const;
    std::string message() const;  // in English
};

// The kinds of file whose problems are listed field by field.
enum class FileKind { scenario, plan, project };
const char* to_string(FileKind kind);  // "scenario", "plan", "project"

// Every problem found in one file, each keyed by its dotted path there, and
// which kind of file it is: ScenarioError (scenario.h), PlanError (plan.h) and
// ProjectError (project_file.h) are these, so a caller can catch one kind or
// all. what() lists the problems in English, one a line.
class FileContentError : public std::runtime_error {
  public:
    FileContentError(FileKind kind, std::vector<FieldError> errors);
    FileKind kind() const { return kind_; }
    const std::vector<FieldError>& errors() const { return errors_; }

  private:
    FileKind kind_;
    std::vector<FieldError> errors_;
};

// An "allowed" message with no arguments (its text marked for translation).
Message allowed_text(const char* code, const char* text);
// "a number from %1 to %2 %3" (without a unit: "a number from %1 to %2").
Message range_allowed(double min, double max, const char* unit);

}  // namespace probecycle
