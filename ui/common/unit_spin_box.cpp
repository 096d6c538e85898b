#include "ui/common/unit_spin_box.h"

#include <QLocale>
#include <utility>

namespace probecycle::ui {

UnitSpinBox::UnitSpinBox(double min, double max, int decimals, double value, QWidget* parent,
                         double factor)
    : QDoubleSpinBox(parent), factor_(factor) {
    setKeyboardTracking(false);  // one edit per value typed, not per keystroke
    setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    setAccelerated(true);
    setDecimals(decimals);
    setRange(min * factor, max * factor);
    setValue(value * factor);
    setMinimumWidth(120);
}

void UnitSpinBox::set_unit(std::function<QString()> unit) {
    unit_ = std::move(unit);
    retranslate();
}

void UnitSpinBox::retranslate() {
    setLocale(QLocale());
    if (unit_) setSuffix(QStringLiteral(" ") + unit_());
}

void UnitSpinBox::set_internal_value(double value) {
    setValue(value * factor_);
}

}  // namespace probecycle::ui
