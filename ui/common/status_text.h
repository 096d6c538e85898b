#pragma once

// Errors and outcomes shown in a label, in the interface language: what the
// core threw, built again after each language switch (keep_translated in
// ui/common/language.h), in the error colour, and "Saved FILE".

#include <QString>
#include <exception>
#include <functional>

class QLabel;

namespace probecycle::ui {

// A message built when shown, so that it can be built again in the language
// chosen later (keep_translated in ui/common/language.h).
using LiveText = std::function<QString()>;

// A message in the error colour.
void show_error(QLabel* label, const QString& text);
// What the core threw, in the interface language: CsvError, InputError,
// FileContentError (a scenario, plan or project file's) and FileError carry messages (translate());
// anything else is unexpected and shown as such.
QString error_text(const std::exception& error);
// error_text of the exception being handled, built anew at each call.
LiveText current_error_text();
// Shows `text` in `label` in the error colour, again after each language switch.
void show_live_error(QLabel* label, LiveText text);
// "Saved FILE" in `label`, again after each language switch.
void show_saved(QLabel* label, const QString& path);

}  // namespace probecycle::ui
