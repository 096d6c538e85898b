// platform_file.h on POSIX: open(O_EXCL), fsync, rename, and Linux's
// renameat2(RENAME_EXCHANGE) for the folder swap.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "core/common/platform_file.h"

namespace probecycle::platform {

namespace {

std::error_code errno_code(int error_number) {
    return {error_number, std::generic_category()};
}

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

}  // namespace

NewFile write_new_file(const std::filesystem::path& path, std::string_view contents,
                       unsigned posix_mode, std::error_code& error) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        if (errno == EEXIST) return NewFile::exists;
        error = errno_code(errno);
        return NewFile::failed;
    }
    int failure = 0;
    if (!write_all(fd, contents)) failure = errno != 0 ? errno : EIO;
    if (failure == 0 && ::fsync(fd) != 0) failure = errno;
    // open() made it 0600 whatever the mode asked: the mode of the file it
    // replaces, not narrowed by the umask.
    if (failure == 0 && ::fchmod(fd, static_cast<mode_t>(posix_mode)) != 0) failure = errno;
    if (::close(fd) != 0 && failure == 0) failure = errno;
    if (failure != 0) {
        ::unlink(path.c_str());
        error = errno_code(failure);
        return NewFile::failed;
    }
    return NewFile::written;
}

std::error_code replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0) return errno_code(errno);
    return {};
}

std::error_code exchange_folders(const std::filesystem::path& incoming,
                                 const std::filesystem::path& folder,
                                 const std::filesystem::path& /*aside*/) {
    if (::renameat2(AT_FDCWD, incoming.c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) != 0)
        return errno_code(errno);
    return {};
}

}  // namespace probecycle::platform
