#include "core/common/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

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

Message too_large(double size_bytes, std::size_t max_bytes) {
    Message m =
        reason("file_too_large", QT_TRANSLATE_NOOP("FileError",
                                                   "it is larger than %1 MiB, the limit for an "
                                                   "input file (%2 MiB read)"));
    m.args = {arg("limit_mib", ArgKind::number, static_cast<double>(max_bytes) / 1048576.0),
              arg("size_mib", ArgKind::number, size_bytes / 1048576.0, 1)};
    return m;
}

[[noreturn]] void fail_write(const std::string& path, const Message& why) {
    throw FileError(FileError::Action::write, path, why);
}

// Where the bytes go: the target of a symbolic link (so the link survives
// the rename), an existing regular file, or a new path. Anything else is
// refused, so a device, a FIFO or a directory is never replaced.
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
            // A link to a file that does not exist yet: write it where the link
            // points, when that directory exists, keeping the link.
            std::error_code ec;
            const std::filesystem::path target = std::filesystem::read_symlink(path_given, ec);
            const std::filesystem::path where =
                target.is_absolute() ? target
                                     : std::filesystem::path(path_given).parent_path() / target;
            if (ec || !std::filesystem::is_directory(where.parent_path().empty()
                                                         ? std::filesystem::path(".")
                                                         : where.parent_path())) {
                fail_write(path_given,
                           reason("dangling_link",
                                  QT_TRANSLATE_NOOP("FileError",
                                                    "it is a symbolic link to a folder that "
                                                    "does not exist")));
            }
            return where.string();
        }
        path = resolved;
        std::free(resolved);
    }
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        fail_write(path_given, not_regular(st));
    return path;
}

bool is_temp_name(const std::string& name, const std::string& prefix) {
    // mkstemp replaces XXXXXX with six letters or digits.
    if (name.size() != prefix.size() + 6 || name.compare(0, prefix.size(), prefix) != 0)
        return false;
    for (std::size_t i = prefix.size(); i < name.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        if (std::isalnum(c) == 0) return false;
    }
    return true;
}

// Temporary files of this writer for `base` that a killed write left: of our
// naming, regular, and not touched for a minute (a concurrent write's file is
// younger). Best effort: a file that cannot be removed stays.
void remove_stale_temps(const std::string& dir, const std::string& base) {
    namespace fs = std::filesystem;
    const std::string prefix = "." + base + ".tmp-";
    const auto cutoff = fs::file_time_type::clock::now() - std::chrono::minutes(1);
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!is_temp_name(name, prefix)) continue;
        std::error_code entry_ec;
        if (!it->is_regular_file(entry_ec) || it->is_symlink(entry_ec)) continue;
        const auto written = fs::last_write_time(it->path(), entry_ec);
        if (!entry_ec && written < cutoff) fs::remove(it->path(), entry_ec);
    }
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

void write_file_atomically(const std::string& path_given, std::string_view contents) {
    const std::string path = write_target(path_given);
    mode_t mode = 0644;
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0) mode = existing.st_mode & 07777;
    const std::size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash);
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    std::string temp = dir + "/." + base + ".tmp-XXXXXX";
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) fail_write(path_given, system_reason(errno));
    const char* data = contents.data();
    std::size_t left = contents.size();
    bool ok = true;
    while (ok && left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0 && errno == EINTR) continue;
        ok = n > 0;
        if (ok) {
            data += n;
            left -= static_cast<std::size_t>(n);
        }
    }
    const int saved_errno = errno;
    ok = ok && ::fsync(fd) == 0;
    ok = (::close(fd) == 0) && ok;
    // mkstemp makes the file 0600: give it the old file's mode, or 0644.
    ok = ok && ::chmod(temp.c_str(), mode) == 0;
    if (!ok || std::rename(temp.c_str(), path.c_str()) != 0) {
        const int err = ok ? errno : saved_errno;
        ::unlink(temp.c_str());
        fail_write(path_given, system_reason(err != 0 ? err : EIO));
    }
    remove_stale_temps(dir, base);
}

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        throw FileError(FileError::Action::read, path, system_reason(errno));
    }
    if (S_ISDIR(st.st_mode)) throw FileError(FileError::Action::read, path, not_regular(st));
    if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > max_bytes) {
        throw FileError(FileError::Action::read, path,
                        too_large(static_cast<double>(st.st_size), max_bytes));
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
        throw FileError(FileError::Action::read, path,
                        too_large(static_cast<double>(text.size()), max_bytes));
    }
    return text;
}

}  // namespace probecycle
