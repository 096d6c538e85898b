#pragma once

// "Import machine log…" on the Latency and Calibration tabs (docs/programs.md,
// reading the results back): what the control recorded while it ran a program of ours,
// read with the plan saved beside the program and turned into the lab's CSV
// by the core (import_machine_log, the CLI's `import`). The tab then puts the
// CSV into its paste box and fits it, as Import CSV does. All or nothing: on
// any problem the tab keeps its text and its fit and shows why, with the line.

#include <QDialog>
#include <QString>
#include <functional>
#include <optional>

#include "core/program/dialect.h"
#include "core/program/plan.h"
#include "ui/common/paste_box.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

namespace probecycle {
struct Scenario;
}

namespace probecycle::ui {

class ProgramDialog;

// What to import: the control, the plan file, the log.
struct MachineLogChoice {
    DialectId dialect{DialectId::linuxcnc};
    QString plan_path;
    QString log_path;
};

// The lab's CSV of the log, for a tab that fits `kind` plans (delay or
// ring); nullopt with `error` (built anew in the language of the moment) when
// a file cannot be read, the plan is not a plan or not of that kind, or the
// core refuses the log (the line named).
std::optional<QString> machine_log_csv(const MachineLogChoice& choice, ProgramKind kind,
                                       LiveText& error);

// A tab's "Import machine log…": the log's CSV, fitted by the tab's
// `fit_text(text, source)` (which shows its own error); when it fits, the
// paste box gets the CSV as one undoable edit and `imported` names the log.
// False with nothing changed when the import (`show_error`) or the fit fails.
bool import_machine_log_into(QPlainTextEdit* editor, const MachineLogChoice& choice,
                             ProgramKind kind, std::optional<ImportedText>& imported,
                             const std::function<bool(const QString&, const QString&)>& fit_text,
                             const std::function<void(LiveText)>& show_error);

// A tab's "Program…": the dialog, window-modal and deleted when closed; a
// save makes its control and plan the next import's (`next_import`, a
// member of `tab`).
ProgramDialog* open_program_dialog(QWidget* tab, ProgramKind kind, const Scenario& scenario,
                                   MachineLogChoice& next_import);
// A tab's "Import machine log…": the dialog with `last` filled in; Import
// keeps the choice in `last` and runs `import` with it.
void open_machine_log_dialog(QWidget* tab, ProgramKind kind, MachineLogChoice& last,
                             std::function<bool(const MachineLogChoice&)> import);

// Asks for the control, the plan and the log; the tab imports on accept.
class MachineLogDialog : public QDialog {
    Q_OBJECT

  public:
    explicit MachineLogDialog(ProgramKind kind, QWidget* parent = nullptr);

    void set_choice(const MachineLogChoice& choice);
    MachineLogChoice choice() const;

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslate();
    void update_buttons();
    void browse_plan();
    void browse_log();

    ProgramKind kind_;
    QLabel* intro_{nullptr};
    QLabel* dialect_label_{nullptr};
    QComboBox* dialect_{nullptr};
    QLabel* dialect_hint_{nullptr};
    QLabel* plan_label_{nullptr};
    QLineEdit* plan_path_{nullptr};
    QPushButton* plan_browse_{nullptr};
    QLabel* log_label_{nullptr};
    QLineEdit* log_path_{nullptr};
    QPushButton* log_browse_{nullptr};
    QPushButton* import_button_{nullptr};
    QPushButton* cancel_button_{nullptr};
};

}  // namespace probecycle::ui
