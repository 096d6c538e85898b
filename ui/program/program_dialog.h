#pragma once

// "Program…" on the Latency and Calibration tabs and File > "Program for
// the Control…" (docs/programs.md): the delay-stability test, the
// ring-gauge calibration or the tuned cycle as a program for the user's
// control. The plan and the program are the core's (core/program/plan.h,
// program_writer.h), the same calls as `probecycle-cli program
// delay|ring|cycle`; this dialog edits the options, shows the program as it
// will be saved, shows the core's refusal in place (Save disabled) and saves
// the program with its plan beside it (the import needs the plan).
//
// The public functions are the dialog's behaviour as tests drive it; the
// widgets call the same functions.

#include <QDialog>
#include <QString>
#include <optional>
#include <string>
#include <vector>

#include "core/common/message.h"
#include "core/cycle/scenario.h"
#include "core/program/dialect.h"
#include "core/program/plan.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QTimer;

namespace probecycle::ui {

class UnitSpinBox;

// The dialects the core writes, in its order (a dialect the core adds is
// offered without a change here).
std::vector<DialectId> program_dialects();

// The plan file saved beside `program_path`: "delay.ngc" -> "delay.plan.json".
QString plan_path_for(const QString& program_path);

class ProgramDialog : public QDialog {
    Q_OBJECT

  public:
    // `kind`: delay, ring or cycle. The options start at the core's defaults (the
    // delay test's feeds from the scenario).
    ProgramDialog(ProgramKind kind, const Scenario& scenario, QWidget* parent = nullptr);
    ~ProgramDialog() override;

    ProgramKind kind() const { return kind_; }

    void set_dialect(DialectId id);
    DialectId dialect_id() const;
    // The delay test's options; the feeds as given (empty: the default feeds).
    void set_delay_options(const DelayPlanOptions& options);
    DelayPlanOptions delay_options() const;
    // The feeds as typed: numbers separated by semicolons or spaces (and by
    // commas where the decimal sign is a point).
    void set_feeds_text(const QString& text);
    // The tuned cycle's options (the cycle kind only).
    void set_cycle_options(const CyclePlanOptions& options);
    CyclePlanOptions cycle_options() const;
    void set_ring_options(const RingPlanOptions& options);
    RingPlanOptions ring_options() const;

    // Edits are coalesced into one update per pass of the event loop; this
    // updates at once.
    void update_now();
    // The plan of the options shown; nullopt when the core refuses them.
    const std::optional<ProbingPlan>& plan() const { return plan_; }
    // The program as previewed and saved (empty when refused).
    QString program_text() const;
    // The refusal shown, in the interface language (empty when none).
    QString problem() const;
    bool can_save() const;
    // The date the program's header carries (report_date() when opened).
    const std::string& date() const { return date_; }

    // Writes the plan to plan_path_for(path), then the program to `path`,
    // each atomically; false with last_error() (and nothing written after a
    // failure) when refused or unwritable. Remembers the folder.
    bool save(const QString& path);
    QString last_error() const { return last_error_; }

  signals:
    // After save(): the program's and the plan's paths, the dialect.
    void saved(const QString& program_path, const QString& plan_path, DialectId dialect);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    // The axis and direction box of the delay test and the tuned cycle.
    void build_axis(QFormLayout* form, const AxisDirection& touch);
    void set_axis(const AxisDirection& touch);
    AxisDirection axis() const;
    void build_cycle_options(QFormLayout* form);
    void build_delay_options(QFormLayout* form);
    void build_ring_options(QFormLayout* form);
    void schedule_update();
    void retranslate();
    void show_problem();
    void save_dialog();
    std::optional<std::vector<double>> parsed_feeds() const;
    QString field_label(const std::string& key) const;

    ProgramKind kind_;
    Scenario scenario_;
    std::string date_;

    QLabel* intro_{nullptr};
    QLabel* dialect_label_{nullptr};
    QComboBox* dialect_{nullptr};
    // Delay test and tuned cycle
    QLabel* axis_label_{nullptr};
    QComboBox* axis_{nullptr};
    // Delay test
    QLabel* feeds_label_{nullptr};
    QLineEdit* feeds_{nullptr};
    QLabel* repeats_label_{nullptr};
    QSpinBox* repeats_{nullptr};
    QLabel* margin_label_{nullptr};
    UnitSpinBox* margin_{nullptr};
    QLabel* placement_label_{nullptr};
    UnitSpinBox* placement_{nullptr};
    // Ring gauge
    QLabel* gauge_label_{nullptr};
    UnitSpinBox* gauge_{nullptr};
    QLabel* ball_label_{nullptr};
    UnitSpinBox* ball_{nullptr};
    QLabel* tolerance_label_{nullptr};
    UnitSpinBox* tolerance_{nullptr};
    // The block that turns the spindle to 180 deg, for a dialect whose ring
    // program needs it from the user (the Fanuc type; the CLI's --orient-180).
    QLabel* orient_label_{nullptr};
    QLineEdit* orient_{nullptr};
    // The probe's input, for a dialect whose probing moves name it
    // (Siemens's MEAS=; the CLI's --probe-input).
    QLabel* probe_input_label_{nullptr};
    QComboBox* probe_input_{nullptr};

    QLabel* preview_label_{nullptr};
    QPlainTextEdit* preview_{nullptr};
    QLabel* problem_label_{nullptr};
    QLabel* status_{nullptr};
    QPushButton* save_button_{nullptr};
    QPushButton* close_button_{nullptr};
    QTimer* update_timer_{nullptr};

    std::optional<ProbingPlan> plan_;
    QString program_;
    // The refusal: the core's message, or the feeds that are not numbers.
    std::optional<Message> refusal_;
    QString bad_feed_;
    QString last_error_;
};

}  // namespace probecycle::ui
