#include "ui/common/parameter_info.h"

#include <QCoreApplication>
#include <algorithm>

namespace probecycle::ui {

namespace {

constexpr const char* kContext = "Parameter";

QString tr_param(const char* text) {
    return QCoreApplication::translate(kContext, text);
}

// The window's own words for each key. Units: the display unit and the
// factor from the core's internal unit to it.
struct KeyText {
    const char* key;
    const char* label;
    const char* help;
    const char* unit;
    double factor;
    int decimals;
    SliderScale slider;
    double slider_min;
    double slider_max;
    const char* zero_text;
};

// clang-format off
const KeyText kKeyTexts[] = {
    {"machine.time_constant_s",
     QT_TRANSLATE_NOOP("Parameter", "Time constant"),
     QT_TRANSLATE_NOOP("Parameter", "Acceleration time constant T: the control reaches any programmed feed in T (a = v/T). Sets the distance to reach the feed (v*T/2) and the braking distance after the trigger, and so overtravel and cycle time. Used by the time-constant model."),
     QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 1, SliderScale::log, 0.005, 0.5, nullptr},
    {"machine.max_accel_mm_s2",
     QT_TRANSLATE_NOOP("Parameter", "Max. acceleration"),
     QT_TRANSLATE_NOOP("Parameter", "Maximum axis acceleration, used by the constant-acceleration and jerk-limited models for every move and for braking after the trigger."),
     QT_TRANSLATE_NOOP("Parameter", "mm/s²"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.max_jerk_mm_s3",
     QT_TRANSLATE_NOOP("Parameter", "Max. jerk"),
     QT_TRANSLATE_NOOP("Parameter", "Maximum axis jerk, used by the jerk-limited (S-curve) model: lower jerk lengthens every acceleration and the braking after the trigger."),
     QT_TRANSLATE_NOOP("Parameter", "mm/s³"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.rapid_feed_mm_min",
     QT_TRANSLATE_NOOP("Parameter", "Rapid feed"),
     QT_TRANSLATE_NOOP("Parameter", "Rapid feed of the positioning moves between the touches of a web, pocket, bore or boss."),
     QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.scan_period_s",
     QT_TRANSLATE_NOOP("Parameter", "Scan period"),
     QT_TRANSLATE_NOOP("Parameter", "Period at which the control scans the skip input (about 4 ms on a standard input, 4 µs on a high-speed input). The wait for the next scan is the single-touch uncertainty (trigger speed × scan period) and, worst case, adds a full period of travel to the overtravel."),
     QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 3, SliderScale::log, 1e-6, 0.02, nullptr},
    {"machine.controller_latency_s",
     QT_TRANSLATE_NOOP("Parameter", "Machine response time"),
     QT_TRANSLATE_NOOP("Parameter", "Fixed latency of the control after it has seen the input. Removed by calibration, but the axis keeps moving: adds trigger speed × latency to the overtravel."),
     QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.pretravel_mm",
     QT_TRANSLATE_NOOP("Parameter", "Pretravel"),
     QT_TRANSLATE_NOOP("Parameter", "Mechanical pretravel from first contact to the trigger threshold (typically 1-50 µm). Independent of speed and removed by calibration; adds to the overtravel and takes pretravel / speed."),
     QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 1, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.interface_delay_s",
     QT_TRANSLATE_NOOP("Parameter", "Interface response time"),
     QT_TRANSLATE_NOOP("Parameter", "Time the probe interface (receiver) needs to pass the trigger to the control. Constant, so calibration removes it from the measured value, but it adds trigger speed × delay to the overtravel."),
     QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.repeatability_2sigma_mm",
     QT_TRANSLATE_NOOP("Parameter", "Repeatability (2σ)"),
     QT_TRANSLATE_NOOP("Parameter", "Unidirectional repeatability of the probe, 2 sigma. Combined with the scan-period range into the expanded (k = 2) uncertainty."),
     QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 2, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.overtravel_limit_mm",
     QT_TRANSLATE_NOOP("Parameter", "Overtravel limit"),
     QT_TRANSLATE_NOOP("Parameter", "Stylus deflection range of the probe in the probing direction. The axis must stop within it or the probe or stylus is damaged; short styli along Z and small bores are the critical cases."),
     QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 2, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.reseat_mm",
     QT_TRANSLATE_NOOP("Parameter", "Reseat distance"),
     QT_TRANSLATE_NOOP("Parameter", "Distance the probe needs to reseat after a trigger. The two-touch backoff must clear the first touch's overtravel plus this."),
     QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.calibration_feed_mm_min",
     QT_TRANSLATE_NOOP("Parameter", "Calibration feed"),
     QT_TRANSLATE_NOOP("Parameter", "Feed at which the probe was calibrated. Measuring at another feed shifts the delay travel and so the measured value; 0 means calibrated at the measuring feed."),
     QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "measuring feed")},
    {"cycle.feature_size_mm",
     QT_TRANSLATE_NOOP("Parameter", "Feature size"),
     QT_TRANSLATE_NOOP("Parameter", "Distance between opposite stylus-centre contact points: web or pocket width, bore or boss diameter less the ball diameter. Sets the positioning moves between touches; unused for a surface."),
     QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.approach_mm",
     QT_TRANSLATE_NOOP("Parameter", "Approach distance"),
     QT_TRANSLATE_NOOP("Parameter", "Start distance in front of the nominal surface. Must cover the part's position uncertainty, and should cover the distance needed to reach the feed so the touch happens at full speed. Approached at the probing feed, returned at the return feed."),
     QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.probe_feed_mm_min",
     QT_TRANSLATE_NOOP("Parameter", "Probing feedrate"),
     QT_TRANSLATE_NOOP("Parameter", "Feed of the (first) touch; single-touch measures at it. A higher feed shortens the approach but lengthens the braking, the overtravel and the return, and raises the single-touch uncertainty."),
     QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::log, 10.0, 10000.0, nullptr},
    {"cycle.measure_feed_mm_min",
     QT_TRANSLATE_NOOP("Parameter", "Measuring feedrate"),
     QT_TRANSLATE_NOOP("Parameter", "Feed of the second, measuring touch of two-touch (typically 30 mm/min). Sets the two-touch uncertainty; the second approach, backoff less the first overtravel, is travelled at it."),
     QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.backoff_mm",
     QT_TRANSLATE_NOOP("Parameter", "Backoff"),
     QT_TRANSLATE_NOOP("Parameter", "Two-touch: distance the probe backs off from where the first touch stopped. Must be at least the first touch's overtravel plus the reseat distance; any more is approached again at the slow measuring feed and wasted."),
     QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::linear, 0.0, 10.0, nullptr},
    {"cycle.return_feed_mm_min",
     QT_TRANSLATE_NOOP("Parameter", "Return feedrate"),
     QT_TRANSLATE_NOOP("Parameter", "Feed of the backoff and of the return to the start position (start distance plus overtravel)."),
     QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.target_uncertainty_mm",
     QT_TRANSLATE_NOOP("Parameter", "Target uncertainty"),
     QT_TRANSLATE_NOOP("Parameter", "Target for the expanded (k = 2) uncertainty of the measuring touch; a warning appears above it. 0 means no target."),
     QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 1, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "none")},
};
// clang-format on

}  // namespace

QString section_of(std::string_view dotted_key) {
    const std::size_t dot = dotted_key.find('.');
    return QString::fromUtf8(dotted_key.data(),
                             static_cast<qsizetype>(dot == std::string_view::npos ? 0 : dot));
}

ParameterView parameter_view(const KeyInfo& info) {
    ParameterView view;
    view.key = QString::fromUtf8(info.key);
    view.min = info.min;
    view.max = info.max;
    const auto* text = std::find_if(std::begin(kKeyTexts), std::end(kKeyTexts),
                                    [&](const KeyText& t) { return view.key == t.key; });
    if (text == std::end(kKeyTexts)) {
        // A key added to the core after this table: show it as the core describes it.
        view.label = view.key.section(QLatin1Char('.'), 1);
        view.help = QString::fromUtf8(info.description);
        view.unit = QString::fromUtf8(info.unit);
        view.decimals = 4;
        return view;
    }
    view.label = tr_param(text->label);
    view.help = tr_param(text->help);
    view.unit = tr_param(text->unit);
    view.factor = text->factor;
    view.decimals = text->decimals;
    view.slider = text->slider;
    view.slider_min = std::clamp(text->slider_min, info.min, info.max);
    view.slider_max = std::clamp(text->slider_max, info.min, info.max);
    if (view.slider == SliderScale::log && view.slider_min <= 0.0)
        view.slider = SliderScale::linear;
    if (text->zero_text != nullptr) view.zero_text = tr_param(text->zero_text);
    return view;
}

QString accel_model_label(AccelModel model) {
    switch (model) {
        case AccelModel::time_constant:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Time constant (T)"));
        case AccelModel::constant_accel:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Constant accel."));
        case AccelModel::jerk_limited:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "S-curve (jerk)"));
    }
    return {};
}

QString strategy_label(Strategy strategy) {
    switch (strategy) {
        case Strategy::single_touch:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Single-touch"));
        case Strategy::two_touch:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Two-touch"));
    }
    return {};
}

QString feature_label(Feature feature) {
    switch (feature) {
        case Feature::surface:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Surface (1 touch)"));
        case Feature::web:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Web (2 touches)"));
        case Feature::pocket:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Pocket (2 touches)"));
        case Feature::bore:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Bore (4 touches)"));
        case Feature::boss:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Boss (4 touches)"));
    }
    return {};
}

QString section_label(const QString& section) {
    if (section == QLatin1String("machine")) {
        return tr_param(QT_TRANSLATE_NOOP("Parameter", "Machine"));
    }
    if (section == QLatin1String("probe")) return tr_param(QT_TRANSLATE_NOOP("Parameter", "Probe"));
    if (section == QLatin1String("cycle")) return tr_param(QT_TRANSLATE_NOOP("Parameter", "Cycle"));
    return section;
}

QString unit_mm() {
    return tr_param(QT_TRANSLATE_NOOP("Parameter", "mm"));
}
QString unit_um() {
    return tr_param(QT_TRANSLATE_NOOP("Parameter", "µm"));
}
QString unit_s() {
    return tr_param(QT_TRANSLATE_NOOP("Parameter", "s"));
}
QString unit_ms() {
    return tr_param(QT_TRANSLATE_NOOP("Parameter", "ms"));
}
QString unit_mm_min() {
    return tr_param(QT_TRANSLATE_NOOP("Parameter", "mm/min"));
}

}  // namespace probecycle::ui
