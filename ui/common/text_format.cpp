#include "ui/common/text_format.h"

#include <QCoreApplication>
#include <QLocale>
#include <cmath>

#include "ui/common/language.h"
#include "ui/common/parameter_info.h"
#include "core/common/units.h"

namespace probecycle::ui {

namespace {

QString number(double value, int decimals) {
    return QLocale().toString(value, 'f', decimals);
}

QString unit_us() {
    return QCoreApplication::translate("Parameter", "µs");
}

QString with_unit(const QString& value, const QString& unit) {
    return value + QChar(0x00A0) + unit;  // no break between number and unit
}

QString tr_warning(const char* text) {
    return QCoreApplication::translate("Warning", text);
}

QString signed_prefix(double value) {
    return value > 0.0 ? QStringLiteral("+") : value < 0.0 ? QStringLiteral("\u2212") : QString();
}

}  // namespace

QString format_seconds(double seconds) {
    const double a = std::abs(seconds);
    // Three significant figures, in s down to 0.1 s, then ms, then µs.
    if (a >= 10.0) return with_unit(number(seconds, 1), unit_s());
    if (a >= 1.0 || a == 0.0) return with_unit(number(seconds, 2), unit_s());
    if (a >= 0.1) return with_unit(number(seconds, 3), unit_s());
    if (a >= 0.0001) {
        const double ms = seconds * 1e3;
        return with_unit(number(ms, std::abs(ms) >= 10.0 ? 1 : 2), unit_ms());
    }
    const double us = seconds * 1e6;
    return with_unit(number(us, std::abs(us) >= 10.0 ? 0 : 1), unit_us());
}

QString format_mm(double mm) {
    return with_unit(number(mm, 3), unit_mm());
}

QString format_um(double mm) {
    const double um = mm * 1000.0;
    return with_unit(number(um, std::abs(um) < 1.0 ? 3 : 1), unit_um());
}

QString format_length(double mm) {
    return std::abs(mm) >= 0.1 ? format_mm(mm) : format_um(mm);
}

QString format_feed(double mm_min) {
    return with_unit(number(mm_min, std::abs(mm_min) >= 100.0 ? 0 : 1), unit_mm_min());
}

QString format_signed_seconds(double seconds) {
    return signed_prefix(seconds) + format_seconds(std::abs(seconds));
}

QString format_signed_length(double mm) {
    return signed_prefix(mm) + format_length(std::abs(mm));
}

QString warning_title(WarningCode code) {
    switch (code) {
        case WarningCode::overtravel_limit:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Overtravel near or over the limit"));
        case WarningCode::backoff_too_small:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Backoff too small"));
        case WarningCode::backoff_excess:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Backoff longer than needed"));
        case WarningCode::touch_while_accelerating:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Touch while accelerating"));
        case WarningCode::feed_beyond_knee:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Feedrate beyond the knee"));
        case WarningCode::uncertainty_over_target:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Uncertainty over the target"));
        case WarningCode::calibration_feed_mismatch:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Calibration feed differs"));
    }
    return QString::fromUtf8(to_string(code));
}

QString warning_text(const Warning& w) {
    if (current_language() == QLatin1String("en")) return QString::fromStdString(w.message());
    // Meaning of a, b, c, d per code: cycle.h, struct Warning.
    switch (w.code) {
        case WarningCode::overtravel_limit: {
            const QString percent = number(100.0 * w.a / w.b, 0);
            return w.severity == Severity::error
                       ? tr_warning(
                             QT_TRANSLATE_NOOP(
                                 "Warning",
                                 "Overtravel %1 is %2 % of the probe's %3 limit: the probe or "
                                 "stylus will be damaged; lower the feed or the delays"))
                             .arg(format_mm(w.a), percent, format_mm(w.b))
                       : tr_warning(QT_TRANSLATE_NOOP("Warning",
                                                      "Overtravel %1 is %2 % of the probe's %3 "
                                                      "limit: little margin left for the stylus"))
                             .arg(format_mm(w.a), percent, format_mm(w.b));
        }
        case WarningCode::backoff_too_small:
            return tr_warning(
                       QT_TRANSLATE_NOOP(
                           "Warning",
                           "Backoff %1 is less than the first touch's overtravel plus reseat, "
                           "%2: the probe may not reseat before the second touch"))
                .arg(format_mm(w.a), format_mm(w.b));
        case WarningCode::backoff_excess:
            return tr_warning(
                       QT_TRANSLATE_NOOP(
                           "Warning",
                           "Backoff %1 is more than the recommended %2 and wastes %3 per cycle"))
                .arg(format_mm(w.a), format_mm(w.b), format_seconds(w.c));
        case WarningCode::touch_while_accelerating: {
            const char* text =
                w.d > 0.5
                    ? QT_TRANSLATE_NOOP("Warning",
                                        "Second touch starts closer than the distance needed to "
                                        "reach its feed: it triggers at %1 instead of %2, an error "
                                        "of %3 against a calibration at full feed")
                    : QT_TRANSLATE_NOOP(
                          "Warning",
                          "First touch starts closer than the distance needed to reach "
                          "its feed: it triggers at %1 instead of %2, an error of %3 "
                          "against a calibration at full feed");
            return tr_warning(text).arg(format_feed(mm_s_to_mm_min(w.a)),
                                        format_feed(mm_s_to_mm_min(w.b)), format_length(w.c));
        }
        case WarningCode::feed_beyond_knee:
            if (w.c <= 0.0) {
                return tr_warning(
                           QT_TRANSLATE_NOOP(
                               "Warning",
                               "Probing feed %1 is beyond the knee at %2 and no faster: the "
                               "cycle takes %3 longer, with more overtravel and uncertainty"))
                    .arg(format_feed(mm_s_to_mm_min(w.a)), format_feed(mm_s_to_mm_min(w.b)),
                         format_seconds(-w.c));
            }
            return tr_warning(QT_TRANSLATE_NOOP(
                                  "Warning",
                                  "Probing feed %1 is beyond the knee at %2: the extra feed saves "
                                  "only %3 (under 1 %) while overtravel and uncertainty grow"))
                .arg(format_feed(mm_s_to_mm_min(w.a)), format_feed(mm_s_to_mm_min(w.b)),
                     format_seconds(w.c));
        case WarningCode::uncertainty_over_target:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Uncertainty %1 exceeds the target %2"))
                .arg(format_length(w.a), format_length(w.b));
        case WarningCode::calibration_feed_mismatch:
            return tr_warning(
                       QT_TRANSLATE_NOOP(
                           "Warning",
                           "Measuring at %1 but calibrated at %2: the delay travel shifts the "
                           "measured value by %3; calibrate at the measuring feed"))
                .arg(format_feed(mm_s_to_mm_min(w.a)), format_feed(mm_s_to_mm_min(w.b)),
                     format_length(w.c));
    }
    return QString::fromStdString(w.message());
}

QString phase_label(Phase phase) {
    const char* text = nullptr;
    switch (phase) {
        case Phase::approach:
            text = QT_TRANSLATE_NOOP("Phase", "Approach");
            break;
        case Phase::pretravel:
            text = QT_TRANSLATE_NOOP("Phase", "Pretravel");
            break;
        case Phase::interface_delay:
            text = QT_TRANSLATE_NOOP("Phase", "Interface delay");
            break;
        case Phase::controller_delay:
            text = QT_TRANSLATE_NOOP("Phase", "Controller delay");
            break;
        case Phase::deceleration:
            text = QT_TRANSLATE_NOOP("Phase", "Deceleration");
            break;
        case Phase::backoff:
            text = QT_TRANSLATE_NOOP("Phase", "Backoff");
            break;
        case Phase::second_approach:
            text = QT_TRANSLATE_NOOP("Phase", "2nd approach");
            break;
        case Phase::second_pretravel:
            text = QT_TRANSLATE_NOOP("Phase", "2nd pretravel");
            break;
        case Phase::second_interface_delay:
            text = QT_TRANSLATE_NOOP("Phase", "2nd interface delay");
            break;
        case Phase::second_controller_delay:
            text = QT_TRANSLATE_NOOP("Phase", "2nd controller delay");
            break;
        case Phase::second_deceleration:
            text = QT_TRANSLATE_NOOP("Phase", "2nd deceleration");
            break;
        case Phase::return_move:
            text = QT_TRANSLATE_NOOP("Phase", "Return");
            break;
        case Phase::position:
            text = QT_TRANSLATE_NOOP("Phase", "Positioning");
            break;
    }
    return text != nullptr ? QCoreApplication::translate("Phase", text)
                           : QString::fromUtf8(to_string(phase));
}

const char* severity_colour(Severity severity) {
    switch (severity) {
        case Severity::error:
            return "#c0392b";
        case Severity::warning:
            return "#b9770e";
        case Severity::info:
            break;
    }
    return "#2471a3";
}

}  // namespace probecycle::ui
