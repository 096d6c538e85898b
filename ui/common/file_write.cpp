#include "ui/common/file_write.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <string_view>

#include "core/common/file_io.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

std::string core_path(const QString& path) {
    return path.toStdString();  // UTF-8
}

bool write_file(const QString& path, const QByteArray& bytes, QString& error) {
    try {
        write_file_atomically(
            core_path(path),
            std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    } catch (const FileError& e) {
        error = translate(e.reason());
        return false;
    }
    return true;
}

namespace {
// One folder for the whole window: the user's last place, whichever tab.
QString& folder() {
    static QString last;
    return last;
}
}  // namespace

QString dialog_start(const QString& file_name) {
    QString dir = folder();
    if (dir.isEmpty() || !QFileInfo(dir).isDir()) {
        dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    }
    if (dir.isEmpty()) dir = QDir::homePath();
    return file_name.isEmpty() ? dir : QDir(dir).filePath(file_name);
}

void remember_folder_of(const QString& path) {
    if (!path.isEmpty()) folder() = QFileInfo(path).absolutePath();
}

QString remembered_folder() {
    return folder();
}

void set_remembered_folder(const QString& dir) {
    folder() = dir;
}

}  // namespace probecycle::ui
