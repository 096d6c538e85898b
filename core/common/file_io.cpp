#include "core/common/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace probecycle {

namespace {

Message file_message(FileError::Action action, const std::string& path, const std::string& reason) {
    Message m;
    m.code = action == FileError::Action::write ? "cannot_write" : "cannot_read";
    m.context = "FileError";
    m.text = action == FileError::Action::write
                 ? QT_TRANSLATE_NOOP("FileError", "cannot write %1: %2")
                 : QT_TRANSLATE_NOOP("FileError", "cannot open %1: %2");
    m.args = {text_arg("path", path), text_arg("reason", reason)};
    return m;
}

}  // namespace

FileError::FileError(Action action, std::string path, std::string reason)
    : std::runtime_error(render(file_message(action, path, reason))),
      action_(action),
      path_(std::move(path)),
      reason_(std::move(reason)) {}

Message FileError::to_message() const {
    return file_message(action_, path_, reason_);
}

void write_file_atomically(const std::string& path_given, std::string_view contents) {
    // Through a symbolic link to its target, so the link survives the rename;
    // an existing file keeps its permissions.
    std::string path = path_given;
    if (char* resolved = ::realpath(path_given.c_str(), nullptr)) {
        path = resolved;
        std::free(resolved);
    }
    mode_t mode = 0644;
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0) mode = existing.st_mode & 07777;
    const std::size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash);
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    std::string temp = dir + "/." + base + ".tmp-XXXXXX";
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) {
        throw FileError(FileError::Action::write, path_given, std::strerror(errno));
    }
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
        throw FileError(FileError::Action::write, path_given, std::strerror(err ? err : EIO));
    }
}

std::string read_text_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(FileError::Action::read, path, std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw FileError(FileError::Action::read, path, std::strerror(EIO));
    return text.str();
}

}  // namespace probecycle
