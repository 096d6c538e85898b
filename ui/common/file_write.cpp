#include "ui/common/file_write.h"

#include <QFile>
#include <string_view>

#include "core/common/file_io.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

bool write_file(const QString& path, const QByteArray& bytes, QString& error) {
    try {
        write_file_atomically(
            QFile::encodeName(path).toStdString(),
            std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    } catch (const FileError& e) {
        error = translate(e.reason());
        return false;
    }
    return true;
}

}  // namespace probecycle::ui
