#include "ui/common/parameter_info.h"

#include <QCoreApplication>
#include <algorithm>

namespace probecycle::ui {

namespace {

constexpr const char* kContext = "Parameter";

QString tr_param(const char* text) {
    return QCoreApplication::translate(kContext, text);
}

// How the window shows each numeric key: the display unit and the factor from
// the core's internal unit to it, decimals, slider. The label and the help
// are the core's (its key table), translated here.
struct KeyText {
    const char* key;
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
    {"machine.time_constant_s", QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 1, SliderScale::log, 0.005, 0.5, nullptr},
    {"machine.max_accel_mm_s2", QT_TRANSLATE_NOOP("Parameter", "mm/s²"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.max_jerk_mm_s3", QT_TRANSLATE_NOOP("Parameter", "mm/s³"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.filter_time_s", QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 1, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.filter2_time_s", QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 1, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.servo_time_constant_s", QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 1, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "ideal servo")},
    {"machine.in_position_mm", QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 1, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.block_change_s", QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 2, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "none")},
    {"machine.rapid_feed_mm_min", QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.scan_period_s", QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 3, SliderScale::log, 1e-6, 0.02, nullptr},
    {"machine.controller_latency_s", QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.repeatability_2sigma_mm", QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 2, SliderScale::none, 0.0, 0.0, nullptr},
    {"machine.thermal_drift_mm", QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 2, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.pretravel_mm", QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 1, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.interface_delay_s", QT_TRANSLATE_NOOP("Parameter", "ms"), 1000.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.repeatability_2sigma_mm", QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 2, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.lobing_mm", QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 2, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.artefact_uncertainty_mm", QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 2, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.overtravel_limit_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 2, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.reseat_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"probe.calibration_feed_mm_min", QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "measuring feed")},
    {"probe.max_feed_mm_min", QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "no limit")},
    {"cycle.feature_size_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.approach_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.part_position_uncertainty_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "known part")},
    {"cycle.search_beyond_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "automatic")},
    {"cycle.probe_feed_mm_min", QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::log, 10.0, 10000.0, nullptr},
    {"cycle.measure_feed_mm_min", QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.backoff_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::linear, 0.0, 10.0, nullptr},
    {"cycle.repeats", QT_TRANSLATE_NOOP("Parameter", "×"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.return_feed_mm_min", QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.position_feed_mm_min", QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.feed_override_max_pct", QT_TRANSLATE_NOOP("Parameter", "%"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.clearance_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.target_uncertainty_mm", QT_TRANSLATE_NOOP("Parameter", "µm"), 1000.0, 1, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "none")},
    {"cycle.min_start_mm", QT_TRANSLATE_NOOP("Parameter", "mm"), 1.0, 3, SliderScale::none, 0.0, 0.0,
     QT_TRANSLATE_NOOP("Parameter", "none")},
    {"cycle.min_feed_mm_min", QT_TRANSLATE_NOOP("Parameter", "mm/min"), 1.0, 0, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.knee_tolerance", QT_TRANSLATE_NOOP("Parameter", "%"), 100.0, 1, SliderScale::none, 0.0, 0.0, nullptr},
    {"cycle.parts_per_year", QT_TRANSLATE_NOOP("Parameter", "/year"), 1.0, 0, SliderScale::none, 0.0, 0.0, QT_TRANSLATE_NOOP("Parameter", "not shown")},
    {"cycle.cycles_per_part", QT_TRANSLATE_NOOP("Parameter", "/part"), 1.0, 0, SliderScale::none, 0.0, 0.0, QT_TRANSLATE_NOOP("Parameter", "not shown")},
    {"cycle.machine_rate_per_hour", QT_TRANSLATE_NOOP("Parameter", "/h"), 1.0, 2, SliderScale::none, 0.0, 0.0, QT_TRANSLATE_NOOP("Parameter", "hours only")},
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
    view.label = tr_param(info.label);
    view.help = tr_param(info.description);
    if (text == std::end(kKeyTexts)) {
        // A key added to the core after this table: its own unit, plain decimals.
        view.unit = QString::fromUtf8(info.unit);
        view.decimals = 4;
        return view;
    }
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
        case AccelModel::none:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "None (feed at once)"));
    }
    return {};
}

QString filter_label(FilterKind kind) {
    switch (kind) {
        case FilterKind::none:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "None"));
        case FilterKind::linear:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Linear (moving average)"));
        case FilterKind::exponential:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Exponential"));
        case FilterKind::bell:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Bell (two averages)"));
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

QString backoff_from_label(BackoffFrom from) {
    switch (from) {
        case BackoffFrom::stop:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Where it stopped"));
        case BackoffFrom::trigger:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Trigger position"));
    }
    return {};
}

QString tolerance_action_label(ToleranceAction action) {
    switch (action) {
        case ToleranceAction::flag:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Flag it and go on"));
        case ToleranceAction::stop:
            return tr_param(QT_TRANSLATE_NOOP("Parameter", "Stop with an alarm"));
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
