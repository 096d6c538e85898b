#pragma once

// The compensation half of the Latency tab (docs/cli.md, "The calibration
// and latency lab": how the recorded trigger position is compensated).
//
// The core simulates a touch at constant speed or while braking and corrects
// the recorded position four ways; the chart sweeps the speed at the trigger
// while braking, where only methods that use what the axis really did (the
// real increments, or the latched timestamp) stay right and the naive v * tau
// over-corrects. Edits and scenario changes are coalesced into one recompute
// in the event loop, deferred while the panel is hidden.

#include <QGroupBox>
#include <QList>
#include <QPointF>
#include <QString>
#include <QTimer>
#include <optional>
#include <string>
#include <vector>

#include "core/cycle/scenario.h"
#include "core/lab/compensation.h"
#include "core/project/project_file.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSpinBox;
class QTabWidget;
class QTableWidget;

namespace probecycle::ui {

class PlotView;
class UnitSpinBox;

class CompensationPanel : public QGroupBox {
    Q_OBJECT

  public:
    explicit CompensationPanel(QWidget* parent = nullptr);
    ~CompensationPanel() override;

    // The machine's dynamics for the simulation (the defaults while the
    // scenario is invalid). Recomputes in the event loop.
    void set_scenario(const probecycle::Scenario& scenario);

    // The inputs the window edits, as the project file holds them.
    using Inputs = CompensationSession;
    // Sets the inputs and recomputes at once.
    void set_inputs(const Inputs& inputs);
    Inputs inputs() const;
    // Runs a pending recompute now (edits are coalesced in the event loop).
    void update_comparison_now();
    const std::optional<CompensationComparison>& comparison() const { return comparison_; }
    // (speed at the trigger in % of the feed, error µm) while braking.
    QList<QPointF> comparison_curve(CompensationMethod method) const;
    QString comparison_error() const { return comparison_error_; }
    PlotView* comparison_plot() const { return comparison_plot_; }
    // (compensated lag in cycles, error µm) of the real-increments method,
    // with the machine's lag as set.
    QList<QPointF> lag_curve() const;
    PlotView* lag_plot() const { return lag_plot_; }

    // "Take period and lag from the fit" is enabled while a fit offers them.
    void set_lag_from_fit_available(bool available);

    // The window's name of a setup field: validate() names the fields by the
    // CLI's options ("feed-mm-min"), which mean nothing in the window.
    static QString field_label(const std::string& key);

  signals:
    void lag_from_fit_requested();

  protected:
    void changeEvent(QEvent* event) override;
    void showEvent(QShowEvent* event) override;

  private:
    QWidget* build_input_column();
    void build_plot();
    void build_lag_plot();
    void show_lag_sweep();
    QWidget* build_table_column();
    void schedule_comparison();
    void show_comparison();
    void retranslate();

    std::optional<Scenario> scenario_;

    QFormLayout* form_{nullptr};
    UnitSpinBox* feed_{nullptr};
    UnitSpinBox* ipo_period_{nullptr};
    QSpinBox* lag_cycles_{nullptr};
    QSpinBox* compensated_lag_{nullptr};
    QComboBox* touch_{nullptr};
    UnitSpinBox* speed_fraction_{nullptr};
    QPushButton* lag_from_fit_{nullptr};
    QLabel* note_{nullptr};
    QLabel* error_label_{nullptr};
    PlotView* comparison_plot_{nullptr};
    int method_curves_[kCompensationMethodCount]{};
    int current_fraction_curve_{-1};
    QTabWidget* charts_{nullptr};
    PlotView* lag_plot_{nullptr};
    int lag_error_curve_{-1};
    int lag_marker_curve_{-1};       // the compensated lag in use
    int true_lag_marker_curve_{-1};  // the machine's lag
    QTableWidget* methods_table_{nullptr};
    QLabel* trigger_summary_{nullptr};
    QTimer comparison_timer_;
    bool comparison_stale_{false};  // scenario changed while hidden
    std::optional<CompensationComparison> comparison_;
    std::vector<BrakingRow> sweep_;
    std::vector<LagRow> lag_sweep_;
    QString comparison_error_;
};

}  // namespace probecycle::ui
