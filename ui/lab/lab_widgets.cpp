#include "ui/lab/lab_widgets.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <cmath>

#include "ui/common/file_write.h"
#include "ui/common/parameter_info.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

namespace {

QString tr_lab(const char* text) {
    return QCoreApplication::translate("probecycle::ui::Lab", text);
}

}  // namespace

WarningList::Item warning_item(const CalibrationWarning& warning) {
    WarningList::Item item;
    item.code = QString::fromUtf8(to_string(warning.code));
    item.severity = warning.severity;
    // The core's message is the same text the CLI prints; the title is translated.
    item.message = translate(warning.message);
    switch (warning.code) {
        case CalibrationWarningCode::points_one_side:
            item.title = tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Points on one side"));
            break;
        case CalibrationWarningCode::large_runout:
            item.title = tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Large stylus runout"));
            break;
        case CalibrationWarningCode::large_residual:
            item.title = tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Point off the circle"));
            break;
        case CalibrationWarningCode::single_orientation:
            item.title =
                tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "One orientation only: no runout"));
            break;
        case CalibrationWarningCode::exact_fit:
            item.title =
                tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Three points: exact fit"));
            break;
        case CalibrationWarningCode::length_wear:
            item.title =
                tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Length far from the nominal"));
            break;
    }
    return item;
}

WarningList::Item warning_item(const LatencyWarning& warning, const QString& group) {
    WarningList::Item item;
    item.code = QString::fromUtf8(to_string(warning.code));
    item.severity = warning.severity;
    item.message = translate(warning.message);
    QString title;
    switch (warning.code) {
        case LatencyWarningCode::few_feeds:
            title = tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Fewer than 3 feeds"));
            break;
        case LatencyWarningCode::unstable_delay:
            title = tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Unstable delay"));
            break;
        case LatencyWarningCode::curved_residuals:
            title = tr_lab(
                QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Residuals curve: the delay changes"));
            break;
        case LatencyWarningCode::negative_delay:
            title = tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Negative delay"));
            break;
        case LatencyWarningCode::single_touch_feed:
            title = tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "One touch at a feed"));
            break;
    }
    //: %1 the group ("X+"), %2 the warning's title
    item.title = tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "%1: %2")).arg(group, title);
    return item;
}

QString ask_report_path(QWidget* parent, const QString& title, const QString& file_name) {
    QString path = QFileDialog::getSaveFileName(
        parent, title, dialog_start(file_name),
        tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "CSV files (*.csv)")));
    if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".csv");
    return path;
}

bool write_report(const QString& path, const std::string& csv, QLabel* status, QString& error) {
    QString reason;
    if (!write_file(path, QByteArray::fromStdString(csv), reason)) {
        // Said again in the new language after a switch.
        const auto message = [path, reason] {
            return tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "%1 could not be written: %2"))
                .arg(QDir::toNativeSeparators(path), reason);
        };
        error = message();
        show_live_error(status, message);
        return false;
    }
    remember_folder_of(path);
    show_saved(status, path);
    return true;
}

QString lab_mm(double mm, int decimals) {
    return with_unit(format_number(mm, decimals), unit_mm());
}

QString lab_signed_um(double mm) {
    const double um = std::round(mm * 10000.0) / 10.0;  // no "-0.0"
    const QString sign = um > 0.0   ? QStringLiteral("+")
                         : um < 0.0 ? QStringLiteral("\u2212")
                                    : QString();
    return sign + with_unit(format_number(std::abs(um), 1), unit_um());
}

QString lab_signed_length(double mm) {
    if (std::abs(mm) < 0.1) return lab_signed_um(mm);
    const QString sign = mm > 0.0 ? QStringLiteral("+") : QStringLiteral("\u2212");
    return sign + lab_mm(std::abs(mm));
}

QString lab_ms(double seconds) {
    return with_unit(format_number(seconds * 1000.0, 3), unit_ms());
}

}  // namespace probecycle::ui
