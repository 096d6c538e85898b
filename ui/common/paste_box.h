#pragma once

// The paste box of a lab tab: CSV text the user pastes or imports from a
// file, replaced as one undoable edit, and the name of where it came from.

#include <QString>
#include <optional>
#include <string>

#include "ui/common/status_text.h"

class QPlainTextEdit;
class QWidget;

namespace probecycle::ui {

// The paste box of a lab tab: CSV text in a fixed-width font.
QPlainTextEdit* make_csv_editor(QWidget* parent);
// Replaces the editor's text as one undoable edit (setPlainText would drop
// the undo history, and with it what the user had pasted).
void replace_text_undoably(QPlainTextEdit* editor, const QString& text);
// Reads a CSV file into a paste box as one undoable edit: a bad file's named
// line can then be corrected there, and undo brings back what was pasted.
// Returns the text, or nullopt with `error` saying why the file was unreadable.
std::optional<QString> import_csv_into(QPlainTextEdit* editor, const QString& path,
                                       LiveText& error);

// Where a lab tab's data came from, for its report's header (report_header.h):
// the file it was imported from while the text is still that file's, else
// "pasted".
struct ImportedText {
    QString file_name;  // without its folder
    QString text;
};
std::string data_source_name(const std::optional<ImportedText>& imported, const QString& text);

}  // namespace probecycle::ui
