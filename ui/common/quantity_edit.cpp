#include "ui/common/quantity_edit.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace probecycle::ui {

namespace {

constexpr int kSliderSteps = 1000;

// Slider values are rounded to three significant figures so a drag lands on
// numbers an engineer would type (1230 mm/min, 4.12 ms).
double round_significant(double value, int digits) {
    if (value == 0.0 || !std::isfinite(value)) return value;
    const double magnitude = std::floor(std::log10(std::abs(value)));
    const double scale = std::pow(10.0, static_cast<double>(digits - 1) - magnitude);
    return std::round(value * scale) / scale;
}

double round_decimals(double value, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return std::round(value * scale) / scale;
}

}  // namespace

QuantityEdit::QuantityEdit(const KeyInfo& info, QWidget* parent)
    : QWidget(parent), info_(info), view_(parameter_view(info)) {
    setObjectName(QStringLiteral("edit:") + view_.key);
    label_ = new QLabel(this);
    spin_ = new QDoubleSpinBox(this);
    spin_->setObjectName(QStringLiteral("spin:") + view_.key);
    spin_->setKeyboardTracking(false);  // one edit per value typed, not per keystroke
    spin_->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    spin_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    spin_->setMinimumWidth(124);
    spin_->setAccelerated(true);
    label_->setBuddy(spin_);
    label_->setWordWrap(true);  // long labels (Russian) take two lines, not more width

    auto* row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(label_, 1);
    row->addWidget(spin_);
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(1);
    column->addLayout(row);

    if (view_.slider != SliderScale::none) {
        slider_ = new QSlider(Qt::Horizontal, this);
        slider_->setObjectName(QStringLiteral("slider:") + view_.key);
        slider_->setRange(0, kSliderSteps);
        slider_->setSingleStep(kSliderSteps / 100);
        slider_->setPageStep(kSliderSteps / 10);
        column->addWidget(slider_);
        connect(slider_, &QSlider::valueChanged, this, &QuantityEdit::on_slider_moved);
    }
    connect(spin_, &QDoubleSpinBox::valueChanged, this, &QuantityEdit::on_spin_changed);
    apply_view();
}

void QuantityEdit::apply_view() {
    const QSignalBlocker block(spin_);
    label_->setText(view_.label);
    spin_->setLocale(QLocale());  // follows the interface language
    spin_->setDecimals(view_.decimals);
    spin_->setRange(view_.min * view_.factor, view_.max * view_.factor);
    spin_->setSuffix(QStringLiteral(" ") + view_.unit);
    spin_->setSpecialValueText(view_.zero_text);
    spin_->setValue(value_ * view_.factor);

    const QLocale locale;
    QString tip = QStringLiteral("<p><b>%1</b></p><p>%2</p><p>").arg(view_.label, view_.help);
    tip += tr("Range: %1 to %2 %3")
               .arg(locale.toString(view_.min * view_.factor, 'g', 6),
                    locale.toString(view_.max * view_.factor, 'g', 6), view_.unit);
    tip += QStringLiteral("<br><code>%1</code></p>").arg(view_.key);
    setToolTip(tip);
    spin_->setToolTip(tip);
    if (slider_ != nullptr) {
        slider_->setToolTip(tip);
        slider_->setAccessibleName(view_.label);
    }
}

void QuantityEdit::retranslate() {
    view_ = parameter_view(info_);
    apply_view();
}

void QuantityEdit::set_value(double value) {
    // Unchanged values leave a slider that is being dragged alone.
    if (value == value_ && spin_->value() == round_decimals(value * view_.factor, view_.decimals)) {
        return;
    }
    value_ = value;
    {
        const QSignalBlocker block(spin_);
        spin_->setValue(value * view_.factor);
    }
    if (slider_ != nullptr) {
        const QSignalBlocker block(slider_);
        slider_->setValue(slider_position(value));
    }
}

void QuantityEdit::on_spin_changed(double display_value) {
    const double value = display_value / view_.factor;
    // The spin box shows a rounded value; only a real change is an edit.
    if (round_decimals(value_ * view_.factor, view_.decimals) == display_value) return;
    value_ = value;
    if (slider_ != nullptr) {
        const QSignalBlocker block(slider_);
        slider_->setValue(slider_position(value));
    }
    emit edited(value_);
}

void QuantityEdit::on_slider_moved(int position) {
    double display = round_significant(slider_value(position) * view_.factor, 3);
    display = round_decimals(display, view_.decimals);
    display = std::clamp(display, spin_->minimum(), spin_->maximum());
    {
        const QSignalBlocker block(spin_);
        spin_->setValue(display);
    }
    const double value = display / view_.factor;
    if (value == value_) return;
    value_ = value;
    emit edited(value_);
}

int QuantityEdit::slider_position(double value) const {
    const double lo = view_.slider_min;
    const double hi = view_.slider_max;
    double fraction = 0.0;
    if (view_.slider == SliderScale::log) {
        fraction = value <= lo ? 0.0 : std::log(value / lo) / std::log(hi / lo);
    } else if (hi > lo) {
        fraction = (value - lo) / (hi - lo);
    }
    fraction = std::clamp(fraction, 0.0, 1.0);
    return static_cast<int>(std::lround(fraction * kSliderSteps));
}

double QuantityEdit::slider_value(int position) const {
    const double fraction = static_cast<double>(position) / kSliderSteps;
    const double lo = view_.slider_min;
    const double hi = view_.slider_max;
    if (view_.slider == SliderScale::log) return lo * std::pow(hi / lo, fraction);
    return lo + fraction * (hi - lo);
}

}  // namespace probecycle::ui
