#pragma once

// The delay-fit half of the Latency tab (docs/cli.md, "The calibration and
// latency lab").
//
// Touches of one surface at several feeds (CSV `axis,direction,feed_mm_min,
// measured_mm`, pasted or imported) give the total delay per axis and
// direction; the chart shows the deviation from the zero-speed position
// against the feed with the fitted line and every touch, the tree the delay
// and its stability. "Apply to scenario" turns the delay into the scenario's
// controller latency by the CLI's --apply-to rule (delay_to_apply
// in core/lab/delay_fit.h).

#include <QGroupBox>
#include <QList>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/report_summary.h"
#include "core/cycle/scenario.h"
#include "core/lab/delay_fit.h"
#include "core/project/project_file.h"
#include "ui/lab/lab_widgets.h"
#include "ui/program/machine_log_import.h"

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTreeWidget;

namespace probecycle::ui {

class FitInput;
class PlotView;
class ProgramDialog;
class UnitSpinBox;
class WarningList;

class DelayFitPanel : public QGroupBox {
    Q_OBJECT

  public:
    explicit DelayFitPanel(QWidget* parent = nullptr);
    ~DelayFitPanel() override;

    // The scenario "Apply" works on; disabled until one is set.
    void set_scenario(const probecycle::Scenario& scenario);

    void set_touches_text(const QString& csv);
    QString touches_text() const;
    // The interpolation period that expresses the delay in cycles; 0 = none.
    // Refits the touches of the current fit.
    void set_interpolation_period_s(double period_s);
    // Fits the pasted touches. On bad input: false, last_error() names the
    // line, and the previous fit stays on screen.
    bool fit();
    // "Example data": the delay test simulated for the scenario's machine and
    // probe (core/lab/lab_examples.h), pasted and fitted.
    bool load_example();
    // Reads a CSV file into the paste box and fits it.
    bool import_file(const QString& path);
    // "Program…": the delay-stability test's program for the scenario set
    // (the default scenario before one is set), in a window-modal dialog.
    ProgramDialog* open_program_dialog();
    // "Import machine log…": the control's record of a delay program, read
    // with its plan into the paste box and fitted. False with last_error()
    // (the file and line named) and the paste box and the fit as they were.
    bool import_machine_log(const MachineLogChoice& choice);
    // The fit and stability report (core delay_fit_report.h, the bytes of
    // `latency fit --report`), written atomically; false with last_error()
    // without a fit or when the file cannot be written. A summary
    // (report_summary.h) is the PDF report's.
    bool export_report(const QString& path, ReportRows rows = ReportRows::all);
    // The report's save dialog, then export_report() (the tab's button and
    // the window's "Export CSV Report" on this tab).
    void export_dialog();
    // The report's text; nullopt with last_error() without a fit.
    std::optional<std::string> report_csv(ReportRows rows);

    const std::optional<DelayFit>& delay_fit() const { return fit_; }
    // The touches behind delay_fit().
    const std::vector<DelayTouch>& fitted_touches() const { return touches_; }
    QString last_error() const { return last_error_; }
    QStringList warning_codes() const;
    QStringList warning_texts() const;  // "title: message", as shown
    // The tree's group rows, "X+ | 8.500 ms | ...".
    QStringList results_text() const;
    // What the deviation chart draws for group `index` of delay_fit():
    // (feed mm/min, deviation µm) of every touch, and the fitted line.
    QList<QPointF> plotted_touches(int group) const;
    QList<QPointF> plotted_line(int group) const;
    PlotView* delay_plot() const { return delay_plot_; }

    // The group "Apply" uses, "X+" (any case); empty = the CLI's rule (the
    // only group, or the longest delay). A name the fit does not have is ignored.
    void set_applied_group(const QString& name);
    // What "Apply" would set; nullopt without a fit or a scenario, or when the
    // rule refuses (a negative latency), with the reason in apply_problem().
    std::optional<AppliedDelay> pending_application() const;
    QString apply_problem() const;
    // Emits delay_applied(); false with last_error() when the
    // controller latency would be negative or out of the key's range.
    bool apply_to_scenario();

    // The inputs as the project file holds them: the paste box as typed, the
    // CSV behind the fit on screen, the period and the group for "Apply".
    DelaySession session() const;
    // Takes them back and fits the stored CSV; false (with last_error())
    // when that no longer fits.
    bool restore(const DelaySession& session);

    // For the compensation comparison: the fit's interpolation period and the
    // lag in whole cycles of the group "Apply" uses (core lag_cycles_for_delay);
    // nullopt without a fit or a period.
    struct LagFromFit {
        double interpolation_period_s{0.0};
        int lag_cycles{0};
    };
    std::optional<LagFromFit> lag_from_fit() const;

  signals:
    // "Apply to scenario": the key (machine.controller_latency_s, or
    // probe.interface_delay_s with a latched input) and its value in s.
    void delay_applied(const QString& key, double value_s);
    // The fit, its period or the group for "Apply" changed.
    void fit_changed();

  protected:
    void changeEvent(QEvent* event) override;

  private:
    QWidget* build_input_column();
    QWidget* build_results_column();
    QLayout* build_apply_row();
    void build_plot();
    bool fit_text(const QString& text, const QString& source);
    void apply_period();
    void set_error(std::function<QString()> text);
    void show_fit();
    void draw_fit();
    void update_apply();
    void retranslate();
    void import_dialog();
    std::optional<std::string> chosen_group() const;
    struct ApplyState {
        std::optional<AppliedDelay> applied;
        QString problem;
    };
    ApplyState evaluate_apply() const;

    std::optional<Scenario> scenario_;

    QLabel* format_hint_{nullptr};
    FitInput* input_{nullptr};
    QPlainTextEdit* touches_edit_{nullptr};  // input_'s
    QLabel* period_label_{nullptr};
    UnitSpinBox* period_{nullptr};
    PlotView* delay_plot_{nullptr};
    struct GroupCurves {
        int touches{-1};
        int line{-1};
    };
    std::vector<GroupCurves> group_curves_;
    QTreeWidget* tree_{nullptr};
    QWidget* results_{nullptr};  // the column of the tree and the warnings
    QLabel* warnings_title_{nullptr};
    WarningList* warnings_{nullptr};
    QLabel* apply_label_{nullptr};
    QComboBox* apply_group_{nullptr};
    QLabel* apply_breakdown_{nullptr};
    QPushButton* apply_button_{nullptr};
    QLabel* export_status_{nullptr};
    QPushButton* export_button_{nullptr};

    std::vector<DelayTouch> touches_;
    QString fitted_text_;                 // the CSV behind fit_
    std::string touches_from_{"pasted"};  // the report's subject: touches_' file, or "pasted"
    DelayFitOptions fit_options_;
    std::optional<DelayFit> fit_;
    QString last_error_;
};

}  // namespace probecycle::ui
