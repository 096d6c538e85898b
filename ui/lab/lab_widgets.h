#pragma once

// Small widgets the two lab tabs share: a typed editor for the lab's own
// quantities (they are not scenario keys, so QuantityEdit's key table does not
// know them), a list of warnings with severity colours, and the translated
// titles of the lab's warning codes.

#include <QDoubleSpinBox>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/lab/calibration.h"
#include "core/lab/delay_fit.h"

class QLabel;
class QPlainTextEdit;
class QVBoxLayout;

namespace probecycle::ui {

// A value with its unit, in internal units (mm, s) while the box shows display
// units (factor: display = internal * factor). The unit text is re-read on
// retranslate(). Edits are reported by QDoubleSpinBox::valueChanged, once per
// value typed (no keyboard tracking).
class UnitSpinBox : public QDoubleSpinBox {
  public:
    UnitSpinBox(double min, double max, int decimals, double value, QWidget* parent = nullptr,
                double factor = 1.0);

    void set_unit(std::function<QString()> unit);
    void retranslate();

    double internal_value() const { return value() / factor_; }
    void set_internal_value(double value);

  private:
    double factor_;
    std::function<QString()> unit_;
};

// Rows of "title: message", coloured by severity; an "all clear" line when empty.
class LabWarningList : public QWidget {
  public:
    explicit LabWarningList(QWidget* parent = nullptr);

    struct Item {
        QString code;
        Severity severity{Severity::info};
        QString title;
        QString message;
    };
    void show_items(const std::vector<Item>& items);
    void set_empty_text(const QString& text);

    QStringList codes() const;
    QStringList texts() const;

  private:
    QVBoxLayout* layout_{nullptr};
    QLabel* empty_{nullptr};
    std::vector<QLabel*> rows_;
    std::vector<Item> items_;
};

LabWarningList::Item warning_item(const CalibrationWarning& warning);
LabWarningList::Item warning_item(const LatencyWarning& warning, const QString& group);

// The paste box of a lab tab: CSV text in a fixed-width font.
QPlainTextEdit* make_csv_editor(QWidget* parent);
// Replaces the editor's text as one undoable edit (setPlainText would drop
// the undo history, and with it what the user had pasted).
void replace_text_undoably(QPlainTextEdit* editor, const QString& text);
// A message built when shown, so that it can be built again in the language
// chosen later (keep_translated in ui/common/language.h).
using LiveText = std::function<QString()>;

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

// A lab tab's report export (issue 12): the save dialog, starting in the last
// folder used (dialog_start) with `file_name`, ".csv" added; empty when the
// user cancels.
QString ask_report_path(QWidget* parent, const QString& title, const QString& file_name);
// Writes the report atomically (write_file) and says where in `status`, or
// why not (then false, with `error`); remembers the folder.
bool write_report(const QString& path, const std::string& csv, QLabel* status, QString& error);

// A message in the error colour.
void show_error(QLabel* label, const QString& text);
// What the core threw, in the interface language: CsvError, InputError,
// ScenarioError and FileError carry messages (translate()); anything else is
// unexpected and shown as such.
QString lab_error_text(const std::exception& error);
// lab_error_text of the exception being handled, built anew at each call.
LiveText current_error_text();
// Shows `text` in `label` in the error colour, again after each language switch.
void show_live_error(QLabel* label, LiveText text);
// "Saved FILE" in `label`, again after each language switch.
void show_saved(QLabel* label, const QString& path);

// Lengths and times at the resolution calibration needs (4 decimals in mm,
// 0.1 µm), in the interface language.
QString lab_mm(double mm, int decimals = 4);
QString lab_signed_um(double mm);
QString lab_signed_length(double mm);  // µm below 0.1 mm, else mm
QString lab_ms(double seconds);

}  // namespace probecycle::ui
