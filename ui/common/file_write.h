#pragma once

// Every file the window writes goes through core's write_file_atomically, the
// same writer as the CLI's: a temporary file beside the target, then a rename,
// so the target is the old or the complete new file, links are written
// through and permissions kept.

#include <QByteArray>
#include <QString>

namespace probecycle::ui {

// False on failure, with `error` the reason in the interface language.
bool write_file(const QString& path, const QByteArray& bytes, QString& error);

}  // namespace probecycle::ui
