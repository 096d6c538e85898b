#pragma once

// The few file operations that differ between POSIX and Windows, for
// file_io.cpp only: creating a file that must not exist yet, writing it to
// the disk, replacing a file by a rename and swapping two folders.
// platform_file_posix.cpp and platform_file_windows.cpp implement them; the
// build picks one. Everything else in file_io.cpp is std::filesystem.

#include <filesystem>
#include <string_view>
#include <system_error>

namespace probecycle::platform {

enum class NewFile { written, exists, failed };

// Creates `path` only if nothing has that name (exclusively), writes all of
// `contents`, flushes it to the disk and closes it. `posix_mode` is the new
// file's permission bits on POSIX (not narrowed by the umask); Windows has
// none. On `failed`, `error` says why and nothing is left at `path`.
NewFile write_new_file(const std::filesystem::path& path, std::string_view contents,
                       unsigned posix_mode, std::error_code& error);

// Renames `from` to `to`, replacing a file at `to` in one step (a reader sees
// the old file or the new, never neither), and makes the rename durable.
std::error_code replace_file(const std::filesystem::path& from, const std::filesystem::path& to);

// Puts the folder `incoming` where `folder` is; the old folder ends at
// `incoming`'s name (POSIX) or at `aside` (Windows), for the caller to
// remove. POSIX (Linux's RENAME_EXCHANGE) swaps the two in one step, so a
// reader sees the old folder or the new. Windows has no such call: `folder`
// is renamed to `aside` (a free name beside it), then `incoming` into its
// place, and a reader between the two renames finds no folder; if the second
// rename fails the first is undone.
std::error_code exchange_folders(const std::filesystem::path& incoming,
                                 const std::filesystem::path& folder,
                                 const std::filesystem::path& aside);

}  // namespace probecycle::platform
