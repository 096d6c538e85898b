#pragma once

// A value with its unit in one spin box, for the quantities that are not
// scenario keys (the lab's, the comparison's): the box shows display units
// and speaks internal units (mm, s; display = internal * factor). The unit
// text is re-read on retranslate(). Edits are reported by
// QDoubleSpinBox::valueChanged, once per value typed (no keyboard tracking).
// QuantityEdit is one of these with a scenario key's label, help and slider.

#include <QDoubleSpinBox>
#include <QString>
#include <functional>

namespace probecycle::ui {

class UnitSpinBox : public QDoubleSpinBox {
  public:
    UnitSpinBox(double min, double max, int decimals, double value, QWidget* parent = nullptr,
                double factor = 1.0);

    void set_unit(std::function<QString()> unit);
    void retranslate();

    double internal_value() const { return value() / factor_; }
    void set_internal_value(double value);

  private:
    double factor_;
    std::function<QString()> unit_;
};

}  // namespace probecycle::ui
