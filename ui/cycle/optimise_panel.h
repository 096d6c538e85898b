#pragma once

// "What should I change?" (docs/window.md, the Optimise tab): the
// requirements, the fastest settings that meet them beside the current ones,
// the time (and money) saved, what limits the cycle in plain words, what else
// would save time, one click to apply, and the Pareto front of cycle time
// against uncertainty. It runs the core's optimiser (core/optimise/optimiser.h),
// the CLI's `optimise`.

#include <QList>
#include <QPointF>
#include <QString>
#include <QWidget>
#include <optional>
#include <vector>

#include "core/cycle/scenario.h"
#include "core/optimise/optimiser.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace probecycle::ui {

class PlotView;
class QuantityEdit;

class OptimisePanel : public QWidget {
    Q_OBJECT

  public:
    explicit OptimisePanel(QWidget* parent = nullptr);

    // Optimises `scenario` (a valid one) and shows the result, or why there
    // is none.
    void show_scenario(const Scenario& scenario);
    const std::optional<OptimiseResult>& result() const { return result_; }
    // The optimiser's refusal as shown (empty when there is a result).
    QString problem() const;
    int optimise_count() const { return optimise_count_; }

    // The overtravel requirement, a fraction of the probe's limit (the
    // session's, not the scenario's).
    double overtravel_fraction() const;
    void set_overtravel_fraction(double fraction);

    // What the user reads: the saving and the binding requirements.
    QString saved_text() const;
    QString binding_text() const;
    QStringList advice_texts() const;
    QString savings_text() const;  // empty without cycle.parts_per_year
    // The settings table as shown: a header row, then one row per setting
    // (name, current, best), for the PDF report.
    QList<QStringList> table_rows() const;
    QList<QPointF> pareto_points() const;  // (uncertainty µm, cycle time s)
    // The uncertainty every setting had to meet, a vertical line on the
    // Pareto chart: its x in µm, none before a result.
    QList<QPointF> bound_points() const;
    QPair<double, double> pareto_x_range() const;
    // The Pareto chart, for the PDF report.
    PlotView* pareto() const { return pareto_; }

  signals:
    // A requirement that is a scenario key was edited (internal units).
    void requirement_edited(const QString& key, double value);
    // The overtravel fraction changed: optimise again.
    void options_changed();
    // Apply: the scenario with the best settings.
    void apply_requested(const Scenario& scenario);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslate();
    void show_result();

    Scenario scenario_;
    // What result_ (or refusal_) was found for: the optimiser (its front
    // included, about 20 ms) runs again only when one of them changed.
    std::optional<Scenario> optimised_scenario_;
    double optimised_fraction_{0.0};
    std::optional<OptimiseResult> result_;
    std::optional<Message> refusal_;
    int optimise_count_{0};

    QLabel* requirements_title_{nullptr};
    std::vector<QuantityEdit*> requirement_edits_;
    QLabel* fraction_label_{nullptr};
    QDoubleSpinBox* fraction_{nullptr};
    QLabel* summary_{nullptr};
    QLabel* binding_{nullptr};
    QLabel* advice_{nullptr};
    QLabel* savings_{nullptr};
    QTableWidget* table_{nullptr};
    QPushButton* apply_{nullptr};
    PlotView* pareto_{nullptr};
    int pareto_line_{-1};
    int current_marker_{-1};
    int best_marker_{-1};
    int bound_rule_{-1};
};

}  // namespace probecycle::ui
