#include "ui/common/text_format.h"

#include <QCoreApplication>
#include <QLocale>
#include <algorithm>
#include <cmath>

#include "core/common/units.h"
#include "ui/common/parameter_info.h"

namespace probecycle::ui {

namespace {

QString unit_us() {
    return QCoreApplication::translate("Parameter", "µs");
}

QString tr_warning(const char* text) {
    return QCoreApplication::translate("Warning", text);
}

QString signed_prefix(double value) {
    return value > 0.0 ? QStringLiteral("+") : value < 0.0 ? QStringLiteral("\u2212") : QString();
}

}  // namespace

QString format_number(double value, int decimals) {
    const double shown = std::abs(value) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : value;
    // Without group separators, as the editors show numbers: "3987", not "3,987".
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale.toString(shown, 'f', decimals);
}

QString with_unit(const QString& value, const QString& unit) {
    return value + QChar(0x00A0) + unit;  // no break between number and unit
}

SecondsColumn format_seconds_column(const std::vector<double>& seconds) {
    double largest = 0.0;
    for (const double s : seconds) largest = std::max(largest, std::abs(s));
    // One unit: ms below 10 s, so a cycle's phases read as whole numbers
    // ("180", "1620") beside the short ones ("2.0", "0.10"); s above.
    const bool in_us = largest < 0.0001 && largest > 0.0;
    const bool in_ms = !in_us && largest < 10.0 && largest > 0.0;
    const double factor = in_us ? 1e6 : in_ms ? 1e3 : 1.0;
    SecondsColumn column;
    column.unit = in_us ? unit_us() : in_ms ? unit_ms() : unit_s();
    column.numbers.reserve(static_cast<qsizetype>(seconds.size()));
    for (const double s : seconds) {
        // Each to two significant digits at least, whole from 10 up (s: one
        // decimal), at most 4 decimals.
        const double v = std::abs(s * factor);
        const int decimals = v >= 10.0 ? (in_ms || in_us ? 0 : 1)
                             : v >= 1.0 || v == 0.0
                                 ? 1
                                 : std::min(4, static_cast<int>(std::ceil(-std::log10(v))) + 1);
        column.numbers << format_number(s * factor, decimals);
    }
    return column;
}

QString format_seconds(double seconds) {
    const double a = std::abs(seconds);
    // Three significant figures, in s down to 0.1 s, then ms, then µs.
    if (a >= 10.0) return with_unit(format_number(seconds, 1), unit_s());
    if (a >= 1.0 || a == 0.0) return with_unit(format_number(seconds, 2), unit_s());
    if (a >= 0.1) return with_unit(format_number(seconds, 3), unit_s());
    if (a >= 0.0001) {
        const double ms = seconds * 1e3;
        return with_unit(format_number(ms, std::abs(ms) >= 10.0 ? 1 : 2), unit_ms());
    }
    const double us = seconds * 1e6;
    return with_unit(format_number(us, std::abs(us) >= 10.0 ? 0 : 1), unit_us());
}

QString format_mm(double mm) {
    return with_unit(format_number(mm, 3), unit_mm());
}

QString format_um(double mm) {
    const double um = mm * 1000.0;
    return with_unit(format_number(um, std::abs(um) < 1.0 ? 3 : 1), unit_um());
}

QString format_length(double mm) {
    return std::abs(mm) >= 0.1 ? format_mm(mm) : format_um(mm);
}

QString format_feed(double mm_min) {
    // Whole mm/min as the editors set them ("30 mm/min" beside "127 mm/min");
    // a tenth only below 100 mm/min where it is not a whole number.
    const bool whole = std::abs(mm_min) >= 100.0 || std::abs(mm_min - std::round(mm_min)) < 0.05;
    return with_unit(format_number(mm_min, whole ? 0 : 1), unit_mm_min());
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
        case WarningCode::knee_at_range_end:
            return tr_warning(
                QT_TRANSLATE_NOOP("Warning", "Fastest cycle at the end of the range"));
        case WarningCode::uncertainty_over_target:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Uncertainty over the target"));
        case WarningCode::calibration_feed_mismatch:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Calibration feed differs"));
        case WarningCode::no_valid_feed:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "No valid feed"));
        case WarningCode::feed_over_probe_limit:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Feed over the probe's rating"));
        case WarningCode::start_inside_uncertainty:
            return tr_warning(
                QT_TRANSLATE_NOOP("Warning", "Start within the part's position uncertainty"));
        case WarningCode::search_ends_too_soon:
            return tr_warning(QT_TRANSLATE_NOOP("Warning", "Search ends before the stop"));
        case WarningCode::protected_move_overtravel:
            return tr_warning(
                QT_TRANSLATE_NOOP("Warning", "Protected moves near the overtravel limit"));
    }
    return QString::fromUtf8(to_string(code));
}

QString format_arg(const MessageArg& a) {
    switch (a.kind) {
        case ArgKind::length_mm:
            return format_length(a.number);
        case ArgKind::time_s:
        case ArgKind::delay_s:
            return format_seconds(a.number);
        case ArgKind::feed_mm_min:
            return format_feed(a.number);
        case ArgKind::angle_deg:
            return format_number(a.number, a.decimals < 0 ? 1 : a.decimals) + QChar(0x00B0);
        case ArgKind::percent:
            return with_unit(format_number(a.number, a.decimals < 0 ? 0 : a.decimals),
                             QStringLiteral("%"));
        case ArgKind::number:
            return a.decimals < 0 ? QLocale().toString(a.number, 'g', a.significant)
                                  : format_number(a.number, a.decimals);
        case ArgKind::integer:
            return QLocale().toString(static_cast<qlonglong>(std::llround(a.number)));
        case ArgKind::message:
            return a.nested.empty() ? QString() : translate(a.nested.front());
        case ArgKind::text:
            break;
    }
    return QString::fromStdString(a.text);
}

QString translate(const Message& message) {
    const QString text = QCoreApplication::translate(message.context, message.text);
    QStringList args;
    args.reserve(static_cast<qsizetype>(message.args.size()));
    for (const MessageArg& a : message.args) args << format_arg(a);
    // One pass over %1..%9, as core's fill_template: an argument holding "%2"
    // is not substituted again.
    QString out;
    out.reserve(text.size() + 16 * args.size());
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar ch = text.at(i);
        if (ch == QLatin1Char('%') && i + 1 < text.size()) {
            const int digit = text.at(i + 1).digitValue();
            if (digit >= 1 && digit <= args.size()) {
                out += args.at(digit - 1);
                ++i;
                continue;
            }
        }
        out += ch;
    }
    return out;
}

QString warning_text(const Warning& w) {
    return translate(w.to_message());
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
        case Phase::lift:
            text = QT_TRANSLATE_NOOP("Phase", "Lift");
            break;
        case Phase::lower:
            text = QT_TRANSLATE_NOOP("Phase", "Lower");
            break;
        case Phase::block_change:
            text = QT_TRANSLATE_NOOP("Phase", "Block changes");
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
