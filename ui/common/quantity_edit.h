#pragma once

// A typed editor for one scenario key: label, value with unit and range (a
// UnitSpinBox), and for the quantities engineers sweep by hand a slider (log
// scale where the range spans decades), stopping at round numbers in the
// display unit. It shows display units and speaks internal units.

#include <QWidget>
#include <vector>

#include "ui/common/parameter_info.h"
#include "ui/common/unit_spin_box.h"

class QLabel;
class QSlider;

namespace probecycle::ui {

class QuantityEdit : public QWidget {
    Q_OBJECT

  public:
    explicit QuantityEdit(const KeyInfo& info, QWidget* parent = nullptr);

    const QString& key() const { return view_.key; }
    // Internal units; does not emit edited().
    void set_value(double value);
    double value() const { return value_; }
    // Re-reads label, help and unit after a language change.
    void retranslate();

    QSlider* slider() const { return slider_; }
    UnitSpinBox* spin_box() const { return spin_; }

  signals:
    // A user edit, in internal units.
    void edited(double value);

  private:
    void on_spin_changed(double display_value);
    void on_slider_moved(int position);
    int slider_position(double value) const;
    double slider_value(int position) const;
    void apply_view();

    const KeyInfo& info_;
    ParameterView view_;
    double value_{0.0};
    QLabel* label_{nullptr};
    UnitSpinBox* spin_{nullptr};
    QSlider* slider_{nullptr};
    // The round values the slider stops at, display units, ascending; the
    // slider's position is an index into them.
    std::vector<double> stops_;
};

}  // namespace probecycle::ui
