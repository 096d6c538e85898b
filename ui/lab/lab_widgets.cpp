#include "ui/lab/lab_widgets.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QTextCursor>
#include <QVBoxLayout>
#include <cmath>

#include "core/common/csv_reader.h"
#include "core/common/file_io.h"
#include "core/common/input_error.h"
#include "core/cycle/scenario.h"
#include "ui/common/file_write.h"
#include "ui/common/language.h"
#include "ui/common/parameter_info.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

namespace {

QString tr_lab(const char* text) {
    return QCoreApplication::translate("probecycle::ui::Lab", text);
}

}  // namespace

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

LabWarningList::LabWarningList(QWidget* parent) : QWidget(parent) {
    layout_ = new QVBoxLayout(this);
    layout_->setContentsMargins(0, 0, 0, 0);
    layout_->setSpacing(4);
    empty_ = new QLabel(this);
    empty_->setWordWrap(true);
    empty_->setStyleSheet(QStringLiteral("color: #1e8449;"));
    layout_->addWidget(empty_);
    layout_->addStretch(1);  // rows stay at the top
}

void LabWarningList::set_empty_text(const QString& text) {
    empty_->setText(text);
}

void LabWarningList::show_items(const std::vector<Item>& items) {
    items_ = items;
    while (rows_.size() < items.size()) {
        auto* label = new QLabel(this);
        label->setWordWrap(true);
        label->setTextFormat(Qt::RichText);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        layout_->insertWidget(layout_->count() - 1, label);  // before the stretch
        rows_.push_back(label);
    }
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        QLabel* label = rows_[i];
        if (i >= items.size()) {
            label->hide();
            continue;
        }
        const Item& item = items[i];
        const QString colour = QLatin1String(severity_colour(item.severity));
        label->setStyleSheet(
            QStringLiteral("QLabel { border-style: solid; border-color: %1; border-width: 0px 0px "
                           "0px 4px; padding-left: 6px; }")
                .arg(colour));
        label->setText(QStringLiteral("<b style=\"color:%1\">%2</b><br>%3")
                           .arg(colour, item.title.toHtmlEscaped(), item.message.toHtmlEscaped()));
        label->setToolTip(item.code);
        label->show();
    }
    empty_->setVisible(items.empty());
}

QStringList LabWarningList::codes() const {
    QStringList out;
    for (const Item& item : items_) out << item.code;
    return out;
}

QStringList LabWarningList::texts() const {
    QStringList out;
    for (const Item& item : items_) out << item.title + QStringLiteral(": ") + item.message;
    return out;
}

LabWarningList::Item warning_item(const CalibrationWarning& warning) {
    LabWarningList::Item item;
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

LabWarningList::Item warning_item(const LatencyWarning& warning, const QString& group) {
    LabWarningList::Item item;
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

void replace_text_undoably(QPlainTextEdit* editor, const QString& text) {
    QTextCursor cursor(editor->document());
    cursor.beginEditBlock();
    cursor.select(QTextCursor::Document);
    cursor.insertText(text);
    cursor.endEditBlock();
}

std::optional<QString> import_csv_into(QPlainTextEdit* editor, const QString& path,
                                       LiveText& error) {
    // Core's reader, as the CLI's: the same size limit (a 1 GB file once ended
    // in bad_alloc) and the same reasons, translated.
    std::string bytes;
    try {
        bytes = read_text_file(QFile::encodeName(path).toStdString());
    } catch (const FileError& e) {
        error = [name = QFileInfo(path).fileName(), reason = e.reason()] {
            return tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "%1 could not be read: %2"))
                .arg(name, translate(reason));
        };
        return std::nullopt;
    }
    const QString text = QString::fromStdString(bytes);
    replace_text_undoably(editor, text);
    return text;
}

QPlainTextEdit* make_csv_editor(QWidget* parent) {
    auto* edit = new QPlainTextEdit(parent);
    edit->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    edit->setLineWrapMode(QPlainTextEdit::NoWrap);
    edit->setTabChangesFocus(true);
    return edit;
}

std::string data_source_name(const std::optional<ImportedText>& imported, const QString& text) {
    return imported && imported->text == text ? imported->file_name.toStdString() : "pasted";
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
        // Said again in the new language after a switch (issue 12).
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

void show_error(QLabel* label, const QString& text) {
    label->setStyleSheet(QStringLiteral("color: #c0392b;"));
    label->setText(text);
    label->setVisible(!text.isEmpty());
}

QString lab_error_text(const std::exception& error) {
    if (const auto* csv = dynamic_cast<const CsvError*>(&error)) {
        return translate(csv->to_message());
    }
    if (const auto* lab = dynamic_cast<const InputError*>(&error)) {
        return translate(lab->to_message());
    }
    if (const auto* file = dynamic_cast<const FileError*>(&error)) {
        return translate(file->to_message());
    }
    if (const auto* scenario = dynamic_cast<const ScenarioError*>(&error)) {
        QStringList lines;
        for (const FieldError& e : scenario->errors()) lines << translate(e.to_message());
        return lines.join(QLatin1Char('\n'));
    }
    //: an exception the lab does not expect (out of memory...); %1 its English text
    return tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Unexpected error: %1"))
        .arg(QString::fromLocal8Bit(error.what()));
}

LiveText current_error_text() {
    return [error = std::current_exception()]() -> QString {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const std::exception& e) {
            return lab_error_text(e);
        } catch (...) {
            return tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Unexpected error: %1"))
                .arg(QStringLiteral("?"));
        }
        return {};
    };
}

void show_live_error(QLabel* label, LiveText text) {
    keep_translated(
        label, [label, text = std::move(text)] { show_error(label, text ? text() : QString()); });
}

void show_saved(QLabel* label, const QString& path) {
    keep_translated(label, [label, name = QFileInfo(path).fileName()] {
        label->setStyleSheet({});
        label->setText(tr_lab(QT_TRANSLATE_NOOP("probecycle::ui::Lab", "Saved %1")).arg(name));
        label->show();
    });
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
