#include "ui/common/status_text.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLabel>
#include <QStringList>

#include "core/common/csv_reader.h"
#include "core/common/file_io.h"
#include "core/common/input_error.h"
#include "core/cycle/scenario.h"
#include "ui/common/language.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

namespace {

QString tr_status(const char* text) {
    return QCoreApplication::translate("probecycle::ui::StatusText", text);
}

}  // namespace

void show_error(QLabel* label, const QString& text) {
    label->setStyleSheet(QStringLiteral("color: #c0392b;"));
    label->setText(text);
    label->setVisible(!text.isEmpty());
}

QString error_text(const std::exception& error) {
    if (const auto* csv = dynamic_cast<const CsvError*>(&error)) {
        return translate(csv->to_message());
    }
    if (const auto* lab = dynamic_cast<const InputError*>(&error)) {
        return translate(lab->to_message());
    }
    if (const auto* file = dynamic_cast<const FileError*>(&error)) {
        return translate(file->to_message());
    }
    if (const auto* content = dynamic_cast<const FileContentError*>(&error)) {
        QStringList lines;
        for (const FieldError& e : content->errors()) lines << translate(e.to_message());
        return lines.join(QLatin1Char('\n'));
    }
    //: an exception the window does not expect (out of memory...); %1 its English text
    return tr_status(QT_TRANSLATE_NOOP("probecycle::ui::StatusText", "Unexpected error: %1"))
        .arg(QString::fromLocal8Bit(error.what()));
}

LiveText current_error_text() {
    return [error = std::current_exception()]() -> QString {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const std::exception& e) {
            return error_text(e);
        } catch (...) {
            return tr_status(
                       QT_TRANSLATE_NOOP("probecycle::ui::StatusText", "Unexpected error: %1"))
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
        label->setText(
            tr_status(QT_TRANSLATE_NOOP("probecycle::ui::StatusText", "Saved %1")).arg(name));
        label->show();
    });
}

}  // namespace probecycle::ui
