// platform_file.h on Windows (Win32 API, wide-character paths).
// - CreateFileW with CREATE_NEW fails with ERROR_FILE_EXISTS when the name
//   is taken; FlushFileBuffers writes the file to the disk.
// - MoveFileExW with MOVEFILE_REPLACE_EXISTING replaces an existing file;
//   MOVEFILE_WRITE_THROUGH returns only once the move is on the disk.
// (Microsoft's Win32 reference for CreateFileW, FlushFileBuffers and
// MoveFileExW.) Windows has no call that swaps two folders in one step:
// exchange_folders renames twice, as platform_file.h says.

#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>

#include <algorithm>
#include <cstddef>

#include "core/common/platform_file.h"

namespace probecycle::platform {

namespace {

std::error_code last_error() {
    return {static_cast<int>(::GetLastError()), std::system_category()};
}

bool write_all(HANDLE file, std::string_view contents) {
    const char* data = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        const DWORD chunk = static_cast<DWORD>(std::min<std::size_t>(left, DWORD{1} << 30));
        DWORD written = 0;
        if (::WriteFile(file, data, chunk, &written, nullptr) == 0 || written == 0) return false;
        data += written;
        left -= written;
    }
    return true;
}

bool move(const std::filesystem::path& from, const std::filesystem::path& to, DWORD flags) {
    return ::MoveFileExW(from.c_str(), to.c_str(), flags | MOVEFILE_WRITE_THROUGH) != 0;
}

}  // namespace

NewFile write_new_file(const std::filesystem::path& path, std::string_view contents,
                       unsigned /*posix_mode*/, std::error_code& error) {
    HANDLE file = ::CreateFileW(path.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW,
                                FILE_ATTRIBUTE_NORMAL, nullptr);
    if (file == INVALID_HANDLE_VALUE) {
        const DWORD code = ::GetLastError();
        if (code == ERROR_FILE_EXISTS || code == ERROR_ALREADY_EXISTS) return NewFile::exists;
        error = {static_cast<int>(code), std::system_category()};
        return NewFile::failed;
    }
    std::error_code failure;
    if (!write_all(file, contents) || ::FlushFileBuffers(file) == 0) failure = last_error();
    if (::CloseHandle(file) == 0 && !failure) failure = last_error();
    if (failure) {
        ::DeleteFileW(path.c_str());
        error = failure;
        return NewFile::failed;
    }
    return NewFile::written;
}

std::error_code replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
    if (!move(from, to, MOVEFILE_REPLACE_EXISTING)) return last_error();
    return {};
}

std::error_code exchange_folders(const std::filesystem::path& incoming,
                                 const std::filesystem::path& folder,
                                 const std::filesystem::path& aside) {
    if (!move(folder, aside, 0)) return last_error();
    if (!move(incoming, folder, 0)) {
        const std::error_code error = last_error();
        move(aside, folder, 0);  // the old folder back where it was
        return error;
    }
    return {};
}

}  // namespace probecycle::platform
