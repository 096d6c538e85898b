#pragma once

// The Latency tab of the lab (docs/cli.md, "The calibration and latency
// lab"; docs/window.md): two panels one above the
// other, the delay fit (delay_fit_panel.h) and the compensation comparison
// (compensation_panel.h). The tab hands the scenario to both and lets the
// comparison take its period and lag from the fit.
//
// The public functions are the tab's behaviour as tests drive it; they
// forward to the panels, whose buttons call the same functions.

#include <QList>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <cstddef>
#include <optional>

#include "core/cycle/scenario.h"
#include "core/lab/compensation.h"
#include "core/lab/delay_fit.h"
#include "ui/common/page.h"
#include "ui/lab/compensation_panel.h"
#include "ui/lab/delay_fit_panel.h"

class QSplitter;

namespace probecycle::ui {

class PlotView;

class LatencyTab : public Page {
    Q_OBJECT

  public:
    explicit LatencyTab(QWidget* parent = nullptr);
    ~LatencyTab() override;

    // The window's current scenario: its interface delay, scan period and
    // latched input for "Apply", its machine dynamics for the comparison.
    // "Apply" stays disabled until a scenario is set.
    void set_scenario(const probecycle::Scenario& scenario);

    DelayFitPanel* delay_fit_panel() const { return delay_; }
    CompensationPanel* compensation_panel() const { return compensation_; }

    // --- Delay from touches (DelayFitPanel) ---
    void set_touches_text(const QString& csv) { delay_->set_touches_text(csv); }
    QString touches_text() const { return delay_->touches_text(); }
    void set_interpolation_period_s(double period_s) {
        delay_->set_interpolation_period_s(period_s);
    }
    bool fit() { return delay_->fit(); }
    bool load_example() { return delay_->load_example(); }
    bool import_file(const QString& path) { return delay_->import_file(path); }
    ProgramDialog* open_program_dialog() { return delay_->open_program_dialog(); }
    bool import_machine_log(const MachineLogChoice& choice) {
        return delay_->import_machine_log(choice);
    }
    bool export_report(const QString& path, ReportRows rows = ReportRows::all) {
        return delay_->export_report(path, rows);
    }
    void export_dialog() override { delay_->export_dialog(); }
    std::optional<std::string> report_csv(ReportRows rows) override {
        return delay_->report_csv(rows);
    }
    // The fitted touches.
    std::size_t report_points() const override { return delay_->fitted_touches().size(); }
    const std::optional<DelayFit>& delay_fit() const { return delay_->delay_fit(); }
    const std::vector<DelayTouch>& fitted_touches() const { return delay_->fitted_touches(); }
    QString last_error() const override { return delay_->last_error(); }
    QStringList warning_codes() const { return delay_->warning_codes(); }
    QStringList warning_texts() const { return delay_->warning_texts(); }
    QStringList results_text() const { return delay_->results_text(); }
    QList<QPointF> plotted_touches(int group) const { return delay_->plotted_touches(group); }
    QList<QPointF> plotted_line(int group) const { return delay_->plotted_line(group); }
    PlotView* delay_plot() const { return delay_->delay_plot(); }

    // --- Apply to the scenario (DelayFitPanel) ---
    void set_applied_group(const QString& name) { delay_->set_applied_group(name); }
    std::optional<AppliedDelay> pending_application() const {
        return delay_->pending_application();
    }
    QString apply_problem() const { return delay_->apply_problem(); }
    bool apply_to_scenario() { return delay_->apply_to_scenario(); }

    // --- Compensation comparison (CompensationPanel) ---
    using CompensationInputs = CompensationPanel::Inputs;
    void set_compensation_inputs(const CompensationInputs& inputs) {
        compensation_->set_inputs(inputs);
    }
    CompensationInputs compensation_inputs() const { return compensation_->inputs(); }
    void update_comparison_now() { compensation_->update_comparison_now(); }
    const std::optional<CompensationComparison>& comparison() const {
        return compensation_->comparison();
    }
    QList<QPointF> comparison_curve(CompensationMethod method) const {
        return compensation_->comparison_curve(method);
    }
    QString comparison_error() const { return compensation_->comparison_error(); }
    PlotView* comparison_plot() const { return compensation_->comparison_plot(); }

    // --- Project: the delay fit's session and the comparison's inputs ---
    void save_session(Project& project, const QString& base_folder) const override;
    bool restore_session(const Project& project, const QString& base_folder) override;

  signals:
    // "Apply to scenario": the key (machine.controller_latency_s, or
    // probe.interface_delay_s with a latched input) and its value in s.
    void delay_applied(const QString& key, double value_s);

  private:
    void take_lag_from_fit();

    QSplitter* splitter_{nullptr};
    DelayFitPanel* delay_{nullptr};
    CompensationPanel* compensation_{nullptr};
};

}  // namespace probecycle::ui
