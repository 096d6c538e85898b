#include "core/common/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

namespace probecycle {

namespace {

Message file_message(FileError::Action action, const std::string& path, const Message& reason) {
    Message m;
    m.code = reason.code;
    m.context = "FileError";
    m.text = action == FileError::Action::write
                 ? QT_TRANSLATE_NOOP("FileError", "cannot write %1: %2")
                 : QT_TRANSLATE_NOOP("FileError", "cannot open %1: %2");
    m.args = {text_arg("path", path), message_arg("reason", reason)};
    return m;
}

Message reason(const char* code, const char* text) {
    return make_message(code, "FileError", text);
}

// The system's own words for an errno value (not translated: they come from
// the C library).
Message system_reason(int error_number) {
    Message m = reason("system_error", "%1");
    m.args = {text_arg("system_error", std::strerror(error_number))};
    return m;
}

Message not_regular(const struct stat& st) {
    if (S_ISDIR(st.st_mode)) {
        return reason("is_a_directory", QT_TRANSLATE_NOOP("FileError", "it is a directory"));
    }
    return reason("not_a_regular_file",
                  QT_TRANSLATE_NOOP("FileError",
                                    "it is not a regular file (a pipe, a device or a socket); "
                                    "ProbeCycle writes only regular files"));
}

// A regular file's size is known; a pipe's only to be over the limit.
Message too_large(std::optional<std::uintmax_t> size_bytes, std::size_t max_bytes) {
    const MessageArg limit_bytes =
        arg("limit_bytes", ArgKind::integer, static_cast<double>(max_bytes));
    const MessageArg limit_mib =
        arg("limit_mib", ArgKind::number, static_cast<double>(max_bytes) / 1048576.0);
    if (!size_bytes) {
        Message m = reason("file_too_large",
                           QT_TRANSLATE_NOOP("FileError",
                                             "it has more than %1 bytes, the limit for an input "
                                             "file (%2 MiB)"));
        m.args = {limit_bytes, limit_mib};
        return m;
    }
    Message m = reason("file_too_large",
                       QT_TRANSLATE_NOOP("FileError",
                                         "it has %1 bytes; the limit for an input file is %2 "
                                         "bytes (%3 MiB)"));
    m.args = {arg("size_bytes", ArgKind::integer, static_cast<double>(*size_bytes)), limit_bytes,
              limit_mib};
    return m;
}

[[noreturn]] void fail_write(const std::string& path, const Message& why) {
    throw FileError(FileError::Action::write, path, why);
}

// Where a link leads, hop by hop, to a path that is not a link (at most
// kMaxLinkHops, as the kernel's own limit), or nullopt for a loop.
constexpr int kMaxLinkHops = 40;
std::optional<std::filesystem::path> end_of_links(const std::filesystem::path& start) {
    namespace fs = std::filesystem;
    fs::path at = start;
    for (int hop = 0; hop < kMaxLinkHops; ++hop) {
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(at, ec))) return at;
        const fs::path target = fs::read_symlink(at, ec);
        if (ec) return std::nullopt;
        at = target.is_absolute() ? target : at.parent_path() / target;
    }
    return std::nullopt;
}

// Where the bytes go: the target of a symbolic link (so the link survives
// the rename), an existing regular file, or a new path. Anything else is
// refused, so a device, a FIFO or a directory is never replaced, nor a file
// its owner made read-only.
std::string write_target(const std::string& path_given) {
    struct stat link {};
    if (::lstat(path_given.c_str(), &link) != 0) {
        if (errno == ENOENT) return path_given;  // a new file
        fail_write(path_given, system_reason(errno));
    }
    std::string path = path_given;
    if (S_ISLNK(link.st_mode)) {
        char* resolved = ::realpath(path_given.c_str(), nullptr);
        if (resolved == nullptr) {
            if (errno != ENOENT) fail_write(path_given, system_reason(errno));
            // A link (or a chain of links) to a file that does not exist yet:
            // write it where the last link points, when that folder exists,
            // keeping every link.
            const std::optional<std::filesystem::path> where = end_of_links(path_given);
            std::error_code ec;
            if (!where || !std::filesystem::is_directory(where->parent_path().empty()
                                                             ? std::filesystem::path(".")
                                                             : where->parent_path(),
                                                         ec)) {
                fail_write(path_given,
                           reason("dangling_link",
                                  QT_TRANSLATE_NOOP("FileError",
                                                    "it is a symbolic link to a folder that "
                                                    "does not exist")));
            }
            return where->string();
        }
        path = resolved;
        std::free(resolved);
    }
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (!S_ISREG(st.st_mode)) fail_write(path_given, not_regular(st));
        if ((st.st_mode & 0222) == 0) {
            fail_write(path_given,
                       reason("read_only", QT_TRANSLATE_NOOP("FileError",
                                                             "it is read-only; ProbeCycle does "
                                                             "not replace a protected file")));
        }
    }
    return path;
}

// The longest file name most file systems take (NAME_MAX on Linux).
constexpr std::size_t kMaxNameBytes = 255;
constexpr std::size_t kTempSuffixBytes = 6;  // mkstemp's XXXXXX

// The start of a temporary file's name for `base`: hidden, and short enough
// that the whole name fits even when `base` itself is as long as a name can be.
std::string temp_prefix(const std::string& base, const char* kind = ".tmp-") {
    const std::string_view tail = kind;
    const std::size_t room = kMaxNameBytes - 1 - tail.size() - kTempSuffixBytes;
    std::string prefix(1, '.');
    prefix.append(base, 0, room);
    prefix.append(tail);
    return prefix;
}

bool is_temp_name(const std::string& name, const std::string& prefix) {
    // mkstemp replaces XXXXXX with six letters or digits.
    if (name.size() != prefix.size() + kTempSuffixBytes ||
        name.compare(0, prefix.size(), prefix) != 0)
        return false;
    for (std::size_t i = prefix.size(); i < name.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        if (std::isalnum(c) == 0) return false;
    }
    return true;
}

// Temporary files (or folders) of this writer for `base` that a killed write
// left: of our naming and not touched for a minute (a concurrent write's is
// younger). Best effort: what cannot be removed stays.
void remove_stale_temps(const std::string& dir, const std::string& prefix, bool folders = false) {
    namespace fs = std::filesystem;
    const auto cutoff = fs::file_time_type::clock::now() - std::chrono::minutes(1);
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!is_temp_name(name, prefix)) continue;
        std::error_code entry_ec;
        if (it->is_symlink(entry_ec)) continue;
        if (folders ? !it->is_directory(entry_ec) : !it->is_regular_file(entry_ec)) continue;
        const auto written = fs::last_write_time(it->path(), entry_ec);
        if (!entry_ec && written < cutoff) fs::remove_all(it->path(), entry_ec);
    }
}

std::pair<std::string, std::string> split_path(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return {".", path};
    return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

// The folder could not take a new file: say which folder.
Message folder_reason(const std::string& dir, int error_number) {
    if (error_number != EACCES && error_number != EPERM && error_number != EROFS)
        return system_reason(error_number);
    Message m = reason("folder_not_writable",
                       QT_TRANSLATE_NOOP("FileError", "the folder %1 cannot be written to (%2)"));
    m.args = {text_arg("folder", dir), text_arg("system_error", std::strerror(error_number))};
    return m;
}

// A file written completely beside its target, not yet renamed into place.
struct Prepared {
    std::string given;   // as the caller named it, for messages
    std::string target;  // where the rename puts it
    std::string temp;
};

// False when a write failed (errno says why).
bool write_all(int fd, std::string_view contents) {
    const char* data = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        left -= static_cast<std::size_t>(n);
    }
    return true;
}

// The complete file in a temporary beside `target`, flushed to the disk,
// with the mode of the file it will replace (or 0644).
Prepared prepare(const std::string& given, const std::string& target, std::string_view contents) {
    mode_t mode = 0644;
    struct stat existing {};
    if (::stat(target.c_str(), &existing) == 0) mode = existing.st_mode & 07777;
    const auto [dir, base] = split_path(target);
    std::string temp = dir + "/" + temp_prefix(base) + "XXXXXX";
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) fail_write(given, folder_reason(dir, errno));
    bool ok = write_all(fd, contents);
    const int saved_errno = ok ? 0 : errno;
    ok = ok && ::fsync(fd) == 0;
    ok = (::close(fd) == 0) && ok;
    // mkstemp makes the file 0600: give it the old file's mode, or 0644.
    ok = ok && ::chmod(temp.c_str(), mode) == 0;
    if (!ok) {
        const int err = saved_errno != 0 ? saved_errno : errno;
        ::unlink(temp.c_str());
        fail_write(given, system_reason(err != 0 ? err : EIO));
    }
    return {given, target, temp};
}

// Two outputs that name one file (the same path, or through a link).
bool same_file(const std::string& a, const std::string& b) {
    std::error_code ec;
    const auto canonical_a = std::filesystem::weakly_canonical(a, ec);
    const auto canonical_b = std::filesystem::weakly_canonical(b, ec);
    return a == b || (!ec && canonical_a == canonical_b);
}

void unlink_all(const std::vector<Prepared>& prepared) {
    for (const Prepared& p : prepared) ::unlink(p.temp.c_str());
}

}  // namespace

FileError::FileError(Action action, std::string path, Message reason)
    : std::runtime_error(render(file_message(action, path, reason))),
      action_(action),
      path_(std::move(path)),
      reason_(std::move(reason)) {}

Message FileError::to_message() const {
    return file_message(action_, path_, reason_);
}

void write_files_atomically(const std::vector<OutputFile>& files) {
    std::vector<std::string> targets;
    for (const OutputFile& file : files) {
        targets.push_back(write_target(file.path));
        for (std::size_t i = 0; i + 1 < targets.size(); ++i) {
            if (same_file(targets[i], targets.back())) {
                Message m = reason("same_file_twice",
                                   QT_TRANSLATE_NOOP("FileError",
                                                     "another output of this command goes "
                                                     "there too (%1); give each output a "
                                                     "file of its own"));
                m.args = {text_arg("other", files[i].path)};
                fail_write(file.path, m);
            }
        }
    }
    std::vector<Prepared> prepared;
    try {
        for (std::size_t i = 0; i < files.size(); ++i) {
            prepared.push_back(prepare(files[i].path, targets[i], files[i].contents));
        }
    } catch (...) {
        unlink_all(prepared);
        throw;
    }
    // Every file is complete: now the renames, each atomic.
    for (std::size_t i = 0; i < prepared.size(); ++i) {
        if (std::rename(prepared[i].temp.c_str(), prepared[i].target.c_str()) != 0) {
            const int err = errno;
            unlink_all({prepared.begin() + static_cast<std::ptrdiff_t>(i), prepared.end()});
            fail_write(prepared[i].given, system_reason(err));
        }
    }
    for (const Prepared& p : prepared) {
        const auto [dir, base] = split_path(p.target);
        remove_stale_temps(dir, temp_prefix(base));
    }
}

void write_file_atomically(const std::string& path, std::string_view contents) {
    write_files_atomically({{path, contents}});
}

void write_folder_atomically(const std::string& folder_given,
                             const std::vector<OutputFile>& files) {
    namespace fs = std::filesystem;
    // The folder as it stands: a link to a folder is followed (the link stays).
    std::error_code ec;
    std::string folder = folder_given;
    while (folder.size() > 1 && folder.back() == '/') folder.pop_back();
    if (fs::is_symlink(fs::symlink_status(folder, ec))) {
        const fs::path resolved = fs::canonical(folder, ec);
        if (ec) fail_write(folder_given, system_reason(ec.value()));
        folder = resolved.string();
    }
    const fs::file_status status = fs::status(folder, ec);
    const bool exists = fs::exists(status);
    if (exists && !fs::is_directory(status)) {
        fail_write(folder_given,
                   reason("not_a_folder", QT_TRANSLATE_NOOP("FileError",
                                                            "it is not a folder; give a folder "
                                                            "that does not exist yet, or one this "
                                                            "command wrote before")));
    }
    if (exists) {
        // Replacing the folder replaces all it holds: only an earlier set of
        // the same files (or nothing) is replaced.
        std::string others;
        int count = 0;
        for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            const bool ours = std::any_of(files.begin(), files.end(),
                                          [&](const OutputFile& f) { return f.path == name; });
            std::error_code entry_ec;
            if (ours && it->is_regular_file(entry_ec) && !it->is_symlink(entry_ec)) continue;
            if (++count <= 3) others += (others.empty() ? "" : ", ") + name;
        }
        if (ec) fail_write(folder_given, folder_reason(folder, ec.value()));
        if (count > 0) {
            if (count > 3) others += ", ...";
            Message m = reason("folder_holds_other_files",
                               QT_TRANSLATE_NOOP("FileError",
                                                 "the folder holds %1 entries other than the "
                                                 "files this command writes (%2); give a new "
                                                 "or empty folder"));
            m.args = {arg("count", ArgKind::integer, count), text_arg("names", others)};
            fail_write(folder_given, m);
        }
    }
    const auto [parent, base] = split_path(folder);
    if (!fs::is_directory(parent, ec)) {
        fail_write(folder_given,
                   reason("no_parent_folder",
                          QT_TRANSLATE_NOOP("FileError", "its parent folder does not exist")));
    }
    std::string temp = parent + "/" + temp_prefix(base, ".new-") + "XXXXXX";
    if (::mkdtemp(temp.data()) == nullptr) fail_write(folder_given, folder_reason(parent, errno));
    try {
        std::vector<OutputFile> inside;
        inside.reserve(files.size());
        for (const OutputFile& f : files) inside.push_back({temp + "/" + f.path, f.contents});
        write_files_atomically(inside);
        ::chmod(temp.c_str(), 0755);
        if (!exists) {
            if (std::rename(temp.c_str(), folder.c_str()) != 0)
                fail_write(folder_given, system_reason(errno));
        } else {
            // The new folder and the old swap places in one step: a reader
            // sees the old set or the new, never a mix. The old then goes.
            if (::renameat2(AT_FDCWD, temp.c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) != 0)
                fail_write(folder_given, system_reason(errno));
        }
    } catch (...) {
        fs::remove_all(temp, ec);
        throw;
    }
    fs::remove_all(temp, ec);  // the old set, after an exchange
    remove_stale_temps(parent, temp_prefix(base, ".new-"), true);
}

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        throw FileError(FileError::Action::read, path, system_reason(errno));
    }
    if (S_ISDIR(st.st_mode)) throw FileError(FileError::Action::read, path, not_regular(st));
    if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > max_bytes) {
        throw FileError(FileError::Action::read, path,
                        too_large(static_cast<std::uintmax_t>(st.st_size), max_bytes));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(FileError::Action::read, path, system_reason(errno));
    // Read at most one byte over the limit, so a pipe or a device cannot make
    // the text grow without bound.
    std::string text;
    char buffer[65536];
    while (in && text.size() <= max_bytes) {
        in.read(buffer, sizeof buffer);
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) throw FileError(FileError::Action::read, path, system_reason(EIO));
    if (text.size() > max_bytes) {
        throw FileError(FileError::Action::read, path, too_large(std::nullopt, max_bytes));
    }
    return text;
}

}  // namespace probecycle
