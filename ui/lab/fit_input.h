#pragma once

// The input that the ring-gauge fit (Calibration tab) and the delay fit
// (Latency tab) share: the paste box, "Import CSV…", "Fit", "Program…" and
// "Import machine log…", the fit's error under them (again in the language
// chosen later, with a note while the previous result stays on screen), and
// where the text came from. The owner makes its own settings between the
// paste box and the buttons, lays them out, and fits the text (FitText);
// its charts and tables stay its own.

#include <QObject>
#include <QString>
#include <functional>
#include <optional>
#include <string>

#include "core/cycle/scenario.h"
#include "core/program/plan.h"
#include "ui/common/paste_box.h"
#include "ui/program/machine_log_import.h"

class QLabel;
class QPlainTextEdit;
class QPushButton;
class QVBoxLayout;
class QWidget;

namespace probecycle::ui {

class ProgramDialog;

class FitInput : public QObject {
    Q_OBJECT

  public:
    // Parses and fits `text` and shows the result; on a refusal calls
    // show_fit_error(source) and returns false. `source` is the file's name,
    // empty for pasted text.
    using FitText = std::function<bool(const QString& text, const QString& source)>;
    // The object names of the widgets, for tests and style.
    struct Names {
        const char* editor;
        const char* program;
        const char* log;
        const char* error;
    };

    // `owner` is the tab or panel: the dialogs' parent. `last_error` is the
    // owner's, set with every error shown here. `has_result`: a previous
    // result is on screen (then an error says it is still shown).
    FitInput(ProgramKind kind, Names names, QWidget* owner, QString& last_error,
             std::function<bool()> has_result);

    // The paste box, made first (the focus follows the order widgets are made).
    QPlainTextEdit* make_editor(QWidget* parent);
    // The buttons and the error label, made after the owner's settings.
    void make_buttons(QWidget* parent);
    // Adds Import … Fit, Program and Import machine log, and the error, under `column`.
    void add_buttons_to(QVBoxLayout* column);
    void set_fit_text(FitText fit_text) { fit_text_ = std::move(fit_text); }
    // "Simulate example data": `make` gives the example's CSV for the
    // scenario and settings now (core/lab/lab_examples.h).
    void set_example_text(std::function<QString()> make) { example_text_ = std::move(make); }

    QPlainTextEdit* editor() const { return editor_; }
    QPushButton* fit_button() const { return fit_button_; }
    QPushButton* import_button() const { return import_button_; }
    QPushButton* program_button() const { return program_button_; }
    QPushButton* log_button() const { return log_button_; }
    QPushButton* example_button() const { return example_button_; }

    // Fits the paste box's text.
    bool fit();
    // Puts the example data into the paste box and fits them; its report
    // names them "example".
    bool load_example();
    // Reads a CSV file into the paste box and fits it; false as fit(), or
    // when the file cannot be read.
    bool import_file(const QString& path);
    // The open dialog titled `title`, then import_file().
    void import_dialog(const QString& title);
    // The control's record of a program of this kind, read with its plan into
    // the paste box and fitted; false with nothing changed when it fails.
    bool import_machine_log(const MachineLogChoice& choice);
    void import_machine_log_dialog();
    // "Program…" for `scenario`, window-modal; a save makes its control and
    // plan the next import's.
    ProgramDialog* open_program_dialog(const Scenario& scenario);

    // Shows `text` (none: hides the error) in the interface language.
    void set_error(LiveText text);
    // The error being handled, prefixed by `source` when not empty.
    void show_fit_error(const QString& source);
    // The report's subject for the text fitted: the imported file's name, or "pasted".
    std::string source_of(const QString& text) const;

    void retranslate();

  private:
    ProgramKind kind_;
    Names names_;
    QWidget* owner_;
    QString& last_error_;
    std::function<bool()> has_result_;
    FitText fit_text_;
    std::function<QString()> example_text_;

    QPlainTextEdit* editor_{nullptr};
    QPushButton* import_button_{nullptr};
    QPushButton* fit_button_{nullptr};
    QPushButton* example_button_{nullptr};
    QPushButton* program_button_{nullptr};
    QPushButton* log_button_{nullptr};
    QLabel* error_label_{nullptr};

    std::optional<ImportedText> imported_;
    MachineLogChoice log_choice_;  // the last import's, or the last program saved
};

}  // namespace probecycle::ui
