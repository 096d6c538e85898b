#pragma once

// The parameter panel: Machine, Probe and Cycle groups with one editor per
// scenario key. It shows a Scenario and reports edits as whole new
// scenarios; it computes nothing.

#include <QWidget>
#include <vector>

#include "core/cycle/scenario.h"

class QBoxLayout;
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

    // The groups stand in one column (Machine, Probe, Cycle), or in two
    // (Cycle beside the others) once the panel is at least two_column_width()
    // wide. one_column_height() is the height the one column needs.
    static int one_column_width() { return 320; }
    static int two_column_width() { return 2 * one_column_width() - 12; }
    int one_column_height() const;

  signals:
    // `key` is the dotted key edited; edits of one key in a row may be merged.
    void edited(const probecycle::Scenario& scenario, const QString& key);

  protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    void retranslate();
    void update_enabled();
    void emit_edit(const QString& key);
    void set_two_columns(bool two);

    Scenario scenario_;
    QLabel* note_{nullptr};
    QGroupBox* machine_box_{nullptr};
    QGroupBox* probe_box_{nullptr};
    QGroupBox* cycle_box_{nullptr};
    QBoxLayout* columns_{nullptr};
    QBoxLayout* first_column_{nullptr};
    QBoxLayout* second_column_{nullptr};
    bool two_columns_{false};
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
