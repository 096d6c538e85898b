#pragma once

// The Latency tab of the lab (issue 4, "Tabs in the window"; domain.md,
// "Latency: measuring it and compensating it").
//
// Top: touches of one surface at several feeds (CSV `axis,direction,
// feed_mm_min,measured_mm`, pasted or imported) give the total delay per axis
// and direction; the chart shows the deviation from the zero-speed position
// against the feed with the fitted line and every touch, the tree the delay
// and its stability. "Apply to scenario" turns the delay into the scenario's
// controller latency by the CLI's --apply-to rule (controller_latency_from_fit
// in core/latency.h).
//
// Bottom: the compensation comparison. The core simulates a touch at constant
// speed or while braking and corrects the recorded position four ways; the
// chart sweeps the speed at the trigger while braking, where only methods
// that use what the axis really did (the real increments, or the latched
// timestamp) stay right and the naive v * tau over-corrects.
//
// The public functions below the constructor are the tab's behaviour as tests
// drive it; the buttons call the same functions.

#include <QList>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <QWidget>
#include <optional>
#include <vector>

#include "core/lab/compensation.h"
#include "core/lab/delay_fit.h"
#include "core/cycle/scenario.h"

class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QSplitter;
class QTableWidget;
class QTreeWidget;

namespace probecycle::ui {

class LabWarningList;
class PlotView;
class UnitSpinBox;

class LatencyTab : public QWidget {
    Q_OBJECT

  public:
    explicit LatencyTab(QWidget* parent = nullptr);
    ~LatencyTab() override;

    // The window's current scenario: its interface delay, scan period and
    // latched input for "Apply", its machine dynamics for the comparison.
    // "Apply" stays disabled until a scenario is set.
    void set_scenario(const probecycle::Scenario& scenario);

    // --- Delay from touches ---
    void set_touches_text(const QString& csv);
    QString touches_text() const;
    // The interpolation period that expresses the delay in cycles; 0 = none.
    // Refits the touches of the current fit.
    void set_interpolation_period_s(double period_s);
    // Fits the pasted touches. On bad input: false, last_error() names the
    // line, and the previous fit stays on screen.
    bool fit();
    // Reads a CSV file into the paste box and fits it.
    bool import_file(const QString& path);

    const std::optional<DelayFit>& delay_fit() const { return fit_; }
    QString last_error() const { return last_error_; }
    QStringList warning_codes() const;
    // The tree's group rows, "X+ | 8.500 ms | ...", for tests.
    QStringList results_text() const;
    // What the deviation chart draws for group `index` of delay_fit():
    // (feed mm/min, deviation µm) of every touch, and the fitted line.
    QList<QPointF> plotted_touches(int group) const;
    QList<QPointF> plotted_line(int group) const;
    PlotView* delay_plot() const { return delay_plot_; }

    // --- Apply to the scenario ---
    // The group whose delay is applied, "X+" (any case), from the groups of
    // the current fit; empty = the CLI's rule (the only group, or the longest
    // delay). A name the fit does not have is ignored.
    void set_applied_group(const QString& name);
    // What "Apply" would set; nullopt without a fit or a scenario, or when the
    // rule refuses (a negative latency), with the reason in apply_problem().
    std::optional<AppliedDelay> pending_application() const;
    QString apply_problem() const;
    // Emits controller_latency_applied(); false with last_error() when the
    // controller latency would be negative or out of the key's range.
    bool apply_to_scenario();

    // --- Compensation comparison ---
    struct CompensationInputs {
        double feed_mm_min{2000.0};
        double interpolation_period_s{0.001};
        int lag_cycles{8};
        TouchMotion touch{TouchMotion::braking};
        double speed_fraction{0.5};  // braking: the speed at the trigger / the feed
    };
    void set_compensation_inputs(const CompensationInputs& inputs);
    CompensationInputs compensation_inputs() const;
    // Runs a pending recompute now (edits are coalesced in the event loop).
    void update_comparison_now();
    const std::optional<CompensationComparison>& comparison() const { return comparison_; }
    // (speed at the trigger in % of the feed, error µm) while braking.
    QList<QPointF> comparison_curve(CompensationMethod method) const;
    QString comparison_error() const { return comparison_error_; }
    PlotView* comparison_plot() const { return comparison_plot_; }

  signals:
    // "Apply to scenario": the value for machine.controller_latency_s.
    void controller_latency_applied(double controller_latency_s);

  protected:
    void changeEvent(QEvent* event) override;
    void showEvent(QShowEvent* event) override;

  private:
    void build_delay_section();
    void build_compensation_section();
    bool fit_text(const QString& text, const QString& source);
    void apply_period();
    void set_error(const QString& text);
    void show_fit();
    void draw_fit();
    void update_apply();
    void take_lag_from_fit();
    void schedule_comparison();
    void show_comparison();
    void retranslate();
    void import_dialog();
    std::optional<std::string> chosen_group() const;
    struct ApplyState {
        std::optional<AppliedDelay> applied;
        QString problem;
    };
    ApplyState evaluate_apply() const;

    std::optional<Scenario> scenario_;

    // Delay
    QSplitter* splitter_{nullptr};
    QGroupBox* delay_group_{nullptr};
    QLabel* format_hint_{nullptr};
    QPlainTextEdit* touches_edit_{nullptr};
    QLabel* period_label_{nullptr};
    UnitSpinBox* period_{nullptr};
    QPushButton* import_button_{nullptr};
    QPushButton* fit_button_{nullptr};
    QLabel* error_label_{nullptr};
    PlotView* delay_plot_{nullptr};
    struct GroupCurves {
        int touches{-1};
        int line{-1};
    };
    std::vector<GroupCurves> group_curves_;
    QTreeWidget* tree_{nullptr};
    QLabel* warnings_title_{nullptr};
    LabWarningList* warnings_{nullptr};
    QLabel* apply_label_{nullptr};
    QComboBox* apply_group_{nullptr};
    QLabel* apply_breakdown_{nullptr};
    QPushButton* apply_button_{nullptr};

    std::vector<DelayTouch> touches_;
    DelayFitOptions fit_options_;
    std::optional<DelayFit> fit_;
    QString last_error_;
    QString last_dir_;

    // Compensation
    QGroupBox* compensation_group_{nullptr};
    QFormLayout* compensation_form_{nullptr};
    UnitSpinBox* feed_{nullptr};
    UnitSpinBox* ipo_period_{nullptr};
    QSpinBox* lag_cycles_{nullptr};
    QComboBox* touch_{nullptr};
    UnitSpinBox* speed_fraction_{nullptr};
    QPushButton* lag_from_fit_{nullptr};
    QLabel* compensation_note_{nullptr};
    QLabel* compensation_error_{nullptr};
    PlotView* comparison_plot_{nullptr};
    int method_curves_[kCompensationMethodCount]{};
    int current_fraction_curve_{-1};
    QTableWidget* methods_table_{nullptr};
    QLabel* trigger_summary_{nullptr};
    QTimer comparison_timer_;
    bool comparison_stale_{false};  // scenario changed while hidden
    std::optional<CompensationComparison> comparison_;
    std::vector<BrakingRow> sweep_;
    QString comparison_error_;
};

}  // namespace probecycle::ui
