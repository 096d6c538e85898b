#include "ui/common/paste_box.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QPlainTextEdit>
#include <QTextCursor>

#include "core/common/file_io.h"
#include "ui/common/file_write.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

namespace {

QString tr_paste(const char* text) {
    return QCoreApplication::translate("probecycle::ui::PasteBox", text);
}

}  // namespace

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
        bytes = read_text_file(core_path(path));
    } catch (const FileError& e) {
        error = [name = QFileInfo(path).fileName(), reason = e.reason()] {
            return tr_paste(
                       QT_TRANSLATE_NOOP("probecycle::ui::PasteBox", "%1 could not be read: %2"))
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

}  // namespace probecycle::ui
