#pragma once

// The parameter panel: Machine, Probe and Cycle groups with one editor per
// scenario key. It shows a Scenario and reports edits as whole new
// scenarios; it computes nothing.

#include <QWidget>
#include <vector>

#include "core/cycle/scenario.h"

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;

namespace probecycle::ui {

class QuantityEdit;

class ParameterPanel : public QWidget {
    Q_OBJECT

  public:
    explicit ParameterPanel(QWidget* parent = nullptr);

    // Shows the scenario; emits nothing.
    void set_scenario(const Scenario& scenario);

  signals:
    // `key` is the dotted key edited; edits of one key in a row may be merged.
    void edited(const probecycle::Scenario& scenario, const QString& key);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslate();
    void update_enabled();
    void emit_edit(const QString& key);

    Scenario scenario_;
    QLabel* note_{nullptr};
    QGroupBox* machine_box_{nullptr};
    QGroupBox* probe_box_{nullptr};
    QGroupBox* cycle_box_{nullptr};
    QLabel* accel_label_{nullptr};
    QComboBox* accel_model_{nullptr};
    QWidget* filter_row_{nullptr};  // under the acceleration model's keys
    QLabel* filter_label_{nullptr};
    QComboBox* filter_{nullptr};
    QCheckBox* latched_{nullptr};
    QLabel* strategy_label_{nullptr};
    QComboBox* strategy_{nullptr};
    QLabel* feature_label_{nullptr};
    QComboBox* feature_{nullptr};
    QWidget* backoff_from_row_{nullptr};  // two-touch only
    QLabel* backoff_from_label_{nullptr};
    QComboBox* backoff_from_{nullptr};
    QWidget* tolerance_action_row_{nullptr};  // a feature's size check only
    QLabel* tolerance_action_label_{nullptr};
    QComboBox* tolerance_action_{nullptr};
    std::vector<QuantityEdit*> edits_;
};

}  // namespace probecycle::ui
