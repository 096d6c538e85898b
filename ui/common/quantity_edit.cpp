#include "ui/common/quantity_edit.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <vector>

#include "ui/common/plot_view.h"

namespace probecycle::ui {

namespace {

// A slider stops only at round numbers in its unit, so a drag goes
// 3000 -> 3200 mm/min, not 3000 -> 3220. Log sliders step through
// 1-1.9 by 0.1, 2-4.8 by 0.2 and 5-9.5 by 0.5 of each decade: two
// significant digits, 35 stops a decade, each 4-10 % from the next (a
// 1-2-5 grid made fine enough to drag). Linear sliders step by the 1-2-5
// number that gives about 200 stops.
constexpr int kLogMantissas[] = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 22,
                                 24, 26, 28, 30, 32, 34, 36, 38, 40, 42, 44, 46,
                                 48, 50, 55, 60, 65, 70, 75, 80, 85, 90, 95};  // tenths
constexpr double kLinearStops = 200.0;

double round_decimals(double value, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return std::round(value * scale) / scale;
}

// The values a slider stops at, in display units, ascending: round numbers
// from lo to hi that the spin box shows exactly (its decimals).
std::vector<double> slider_stops(SliderScale scale, double lo, double hi, int decimals) {
    std::vector<double> stops;
    const double tolerance = 1e-9 * std::max(std::abs(lo), std::abs(hi));
    const auto keep = [&](double v) {
        if (v < lo - tolerance || v > hi + tolerance) return;
        if (std::abs(round_decimals(v, decimals) - v) > 1e-9 * std::max(1.0, std::abs(v))) return;
        if (stops.empty() || v > stops.back()) stops.push_back(round_decimals(v, decimals));
    };
    if (scale == SliderScale::log && lo > 0.0) {
        const int first = static_cast<int>(std::floor(std::log10(lo)));
        const int last = static_cast<int>(std::ceil(std::log10(hi)));
        for (int e = first; e <= last; ++e) {
            for (const int tenths : kLogMantissas) {
                // tenths * 10^(e-1), divided when the power is negative so 0.3 stays 0.3.
                const int p = e - 1;
                keep(p >= 0 ? tenths * std::pow(10.0, p) : tenths / std::pow(10.0, -p));
            }
        }
    } else if (hi > lo) {
        const double step =
            std::max(PlotView::nice_step((hi - lo) / kLinearStops), std::pow(10.0, -decimals));
        const auto count = static_cast<long long>(std::floor((hi - lo) / step + 1e-9));
        for (long long k = 0; k <= count; ++k) keep(lo + static_cast<double>(k) * step);
    }
    if (stops.empty()) stops.push_back(lo);
    return stops;
}

}  // namespace

QuantityEdit::QuantityEdit(const KeyInfo& info, QWidget* parent)
    : QWidget(parent), info_(info), view_(parameter_view(info)) {
    setObjectName(QStringLiteral("edit:") + view_.key);
    label_ = new QLabel(this);
    spin_ = new UnitSpinBox(view_.min, view_.max, view_.decimals, value_, this, view_.factor);
    spin_->setObjectName(QStringLiteral("spin:") + view_.key);
    spin_->setMinimumWidth(124);
    spin_->set_unit([this] { return view_.unit; });
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
        column->addWidget(slider_);
        connect(slider_, &QSlider::valueChanged, this, &QuantityEdit::on_slider_moved);
    }
    connect(spin_, &QDoubleSpinBox::valueChanged, this, &QuantityEdit::on_spin_changed);
    apply_view();
}

void QuantityEdit::apply_view() {
    const QSignalBlocker block(spin_);
    label_->setText(view_.label);
    spin_->retranslate();  // the locale of the interface language, the unit
    spin_->setDecimals(view_.decimals);
    spin_->setRange(view_.min * view_.factor, view_.max * view_.factor);
    spin_->setSpecialValueText(view_.zero_text);
    spin_->set_internal_value(value_);

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
        const QSignalBlocker block_slider(slider_);
        stops_ = slider_stops(view_.slider, view_.slider_min * view_.factor,
                              view_.slider_max * view_.factor, view_.decimals);
        const int last = static_cast<int>(stops_.size()) - 1;
        slider_->setRange(0, last);
        slider_->setSingleStep(1);
        slider_->setPageStep(std::max(1, last / 10));
        slider_->setValue(slider_position(value_));
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
        spin_->set_internal_value(value);
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
    const double display =
        std::clamp(slider_value(position) * view_.factor, spin_->minimum(), spin_->maximum());
    {
        const QSignalBlocker block(spin_);
        spin_->setValue(display);
    }
    const double value = display / view_.factor;
    if (value == value_) return;
    value_ = value;
    emit edited(value_);
}

// The stop nearest the value (in log terms on a log slider): a value between
// stops puts the slider at the nearer one without changing the value.
int QuantityEdit::slider_position(double value) const {
    if (stops_.empty()) return 0;
    const double display = value * view_.factor;
    const auto above = std::lower_bound(stops_.begin(), stops_.end(), display);
    if (above == stops_.begin()) return 0;
    if (above == stops_.end()) return static_cast<int>(stops_.size()) - 1;
    const auto below = above - 1;
    const bool log = view_.slider == SliderScale::log && *below > 0.0 && display > 0.0;
    const double to_below = log ? std::log(display / *below) : display - *below;
    const double to_above = log ? std::log(*above / display) : *above - display;
    return static_cast<int>((to_below <= to_above ? below : above) - stops_.begin());
}

double QuantityEdit::slider_value(int position) const {
    if (stops_.empty()) return view_.slider_min;
    const auto index =
        static_cast<std::size_t>(std::clamp(position, 0, static_cast<int>(stops_.size()) - 1));
    return stops_[index] / view_.factor;
}

}  // namespace probecycle::ui
