#pragma once

// Every file the window writes goes through core's write_file_atomically, the
// same writer as the CLI's: a temporary file beside the target, then a rename,
// so the target is the old or the complete new file, links are written
// through and permissions kept.

#include <QByteArray>
#include <QString>
#include <string>

namespace probecycle::ui {

// A path for the core's file functions, which take UTF-8 on every platform
// (core/common/file_io.h). QFile::encodeName would give the system's code
// page on Windows, where a Chinese or Russian folder name would be lost.
std::string core_path(const QString& path);

// False on failure, with `error` the reason in the interface language.
bool write_file(const QString& path, const QByteArray& bytes, QString& error);

// Where a file dialog starts: the folder of the last file the user
// opened or wrote in any tab, else the user's documents, never "/"; with
// `file_name` the suggested file in it.
QString dialog_start(const QString& file_name = {});
// The folder of a file the user chose or wrote, for the next dialog.
void remember_folder_of(const QString& path);
// The folder remembered (empty before any), to save across sessions, and
// to set it again at the next start.
QString remembered_folder();
void set_remembered_folder(const QString& folder);

}  // namespace probecycle::ui
