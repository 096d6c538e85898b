#include "core/common/file_io.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <system_error>
#include <utility>
#include <vector>

#include "core/common/platform_file.h"

namespace probecycle {

namespace fs = std::filesystem;

std::filesystem::path path_from_utf8(std::string_view utf8) {
    // fs::path(std::string) takes the narrow text in the system's code page,
    // which on Windows is not UTF-8; from char8_t it is UTF-8 everywhere.
    return {std::u8string(utf8.begin(), utf8.end())};
}

std::string utf8_from_path(const std::filesystem::path& path) {
    const std::u8string text = path.u8string();
    return {text.begin(), text.end()};
}

bool is_windows_device_name(std::string_view file_name) {
    // Windows takes CON, PRN, AUX, NUL, COM1-9 and LPT1-9 as devices in any
    // folder, whatever the extension and case ("nul.csv", "Com1.txt"), and
    // ignores trailing dots and spaces ("CON ."). Microsoft's "Naming Files,
    // Paths, and Namespaces".
    std::string stem(file_name.substr(0, file_name.find('.')));
    while (!stem.empty() && (stem.back() == ' ' || stem.back() == '.')) stem.pop_back();
    for (char& c : stem) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (stem == "CON" || stem == "PRN" || stem == "AUX" || stem == "NUL") return true;
    return stem.size() == 4 && (stem.compare(0, 3, "COM") == 0 || stem.compare(0, 3, "LPT") == 0) &&
           stem[3] >= '1' && stem[3] <= '9';
}

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

// The system's own words for an error (not translated: they come from the C
// library or Windows).
Message system_reason(const std::error_code& error) {
    Message m = reason("system_error", "%1");
    m.args = {text_arg("system_error", error.message())};
    return m;
}

Message not_regular(fs::file_type type) {
    if (type == fs::file_type::directory) {
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

[[noreturn]] void fail_read(const std::string& path, const Message& why) {
    throw FileError(FileError::Action::read, path, why);
}

// Where a link leads, hop by hop, to a path that is not a link (at most
// kMaxLinkHops, as the kernel's own limit), or nullopt for a loop.
constexpr int kMaxLinkHops = 40;
std::optional<fs::path> end_of_links(const fs::path& start) {
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

bool writable(fs::perms perms) {
    constexpr fs::perms any_write =
        fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
    return (perms & any_write) != fs::perms::none;
}

// Where the bytes go: the target of a symbolic link (so the link survives
// the rename), an existing regular file, or a new path. Anything else is
// refused, so a device, a FIFO or a directory is never replaced, nor a file
// its owner made read-only.
fs::path write_target(const std::string& given) {
    fs::path path_given = path_from_utf8(given);
#ifdef _WIN32
    if (is_windows_device_name(utf8_from_path(path_given.filename()))) {
        fail_write(given, reason("device_name",
                                 QT_TRANSLATE_NOOP("FileError",
                                                   "its name is a Windows device's (CON, PRN, "
                                                   "AUX, NUL, COM1-9, LPT1-9, with any "
                                                   "extension); give another name")));
    }
#endif
    std::error_code ec;
    const fs::file_status link = fs::symlink_status(path_given, ec);
    if (!fs::exists(link) && ec == std::errc::no_such_file_or_directory) return path_given;  // new
    if (ec) fail_write(given, system_reason(ec));
    fs::path path = path_given;
    if (fs::is_symlink(link)) {
        path = fs::canonical(path_given, ec);
        if (ec) {
            if (ec != std::errc::no_such_file_or_directory) fail_write(given, system_reason(ec));
            // A link (or a chain of links) to a file that does not exist yet:
            // write it where the last link points, when that folder exists,
            // keeping every link.
            const std::optional<fs::path> where = end_of_links(path_given);
            std::error_code dir_ec;
            if (!where ||
                !fs::is_directory(
                    where->parent_path().empty() ? fs::path(".") : where->parent_path(), dir_ec)) {
                fail_write(given, reason("dangling_link",
                                         QT_TRANSLATE_NOOP("FileError",
                                                           "it is a symbolic link to a folder that "
                                                           "does not exist")));
            }
            return *where;
        }
    }
    const fs::file_status st = fs::status(path, ec);
    if (!ec && fs::exists(st)) {
        if (!fs::is_regular_file(st)) fail_write(given, not_regular(st.type()));
        if (!writable(st.permissions())) {
            fail_write(given,
                       reason("read_only", QT_TRANSLATE_NOOP("FileError",
                                                             "it is read-only; ProbeCycle does "
                                                             "not replace a protected file")));
        }
    }
    return path;
}

// The longest file name most file systems take (NAME_MAX on Linux, 255
// UTF-16 units on NTFS), in bytes.
constexpr std::size_t kMaxNameBytes = 255;
constexpr std::size_t kTempSuffixBytes = 6;  // random letters and digits

// The start of a temporary file's name for `base`: hidden, and short enough
// that the whole name fits even when `base` itself is as long as a name can
// be. A cut never splits a UTF-8 character.
std::string temp_prefix(const std::string& base, const char* kind = ".tmp-") {
    const std::string_view tail = kind;
    std::size_t room = std::min(base.size(), kMaxNameBytes - 1 - tail.size() - kTempSuffixBytes);
    while (room > 0 && room < base.size() &&
           (static_cast<unsigned char>(base[room]) & 0xC0) == 0x80)
        --room;
    std::string prefix(1, '.');
    prefix.append(base, 0, room);
    prefix.append(tail);
    return prefix;
}

bool is_temp_name(const std::string& name, const std::string& prefix) {
    if (name.size() != prefix.size() + kTempSuffixBytes ||
        name.compare(0, prefix.size(), prefix) != 0)
        return false;
    for (std::size_t i = prefix.size(); i < name.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        if (std::isalnum(c) == 0) return false;
    }
    return true;
}

// `prefix` and six random letters or digits: a name for a temporary file or
// folder, to be created exclusively (a name taken is tried again).
std::string temp_name(const std::string& prefix) {
    static constexpr std::string_view kChars =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    thread_local std::mt19937_64 random{std::random_device{}()};
    std::uniform_int_distribution<std::size_t> pick(0, kChars.size() - 1);
    std::string name = prefix;
    for (std::size_t i = 0; i < kTempSuffixBytes; ++i) name += kChars[pick(random)];
    return name;
}
constexpr int kTempNameTries = 100;

// Temporary files (or folders) of this writer for `base` that a killed write
// left: of our naming and not touched for a minute (a concurrent write's is
// younger). Best effort: what cannot be removed stays.
void remove_stale_temps(const fs::path& dir, const std::string& prefix, bool folders = false) {
    const auto cutoff = fs::file_time_type::clock::now() - std::chrono::minutes(1);
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = utf8_from_path(it->path().filename());
        if (!is_temp_name(name, prefix)) continue;
        std::error_code entry_ec;
        if (it->is_symlink(entry_ec)) continue;
        if (folders ? !it->is_directory(entry_ec) : !it->is_regular_file(entry_ec)) continue;
        const auto written = fs::last_write_time(it->path(), entry_ec);
        if (!entry_ec && written < cutoff) fs::remove_all(it->path(), entry_ec);
    }
}

// The folder a path is in ("." for a bare name) and its last part.
std::pair<fs::path, std::string> split_path(const fs::path& path) {
    const fs::path parent = path.parent_path();
    return {parent.empty() ? fs::path(".") : parent, utf8_from_path(path.filename())};
}

// The folder could not take a new file: say which folder.
Message folder_reason(const fs::path& dir, const std::error_code& error) {
    if (error != std::errc::permission_denied && error != std::errc::operation_not_permitted &&
        error != std::errc::read_only_file_system)
        return system_reason(error);
    Message m = reason("folder_not_writable",
                       QT_TRANSLATE_NOOP("FileError", "the folder %1 cannot be written to (%2)"));
    m.args = {text_arg("folder", utf8_from_path(dir)), text_arg("system_error", error.message())};
    return m;
}

// A file written completely beside its target, not yet renamed into place.
struct Prepared {
    std::string given;  // as the caller named it, for messages
    fs::path target;    // where the rename puts it
    fs::path temp;
};

// The complete file in a temporary beside `target`, flushed to the disk,
// with the mode of the file it will replace (or 0644).
Prepared prepare(const std::string& given, const fs::path& target, std::string_view contents) {
    unsigned mode = 0644;
    std::error_code ec;
    const fs::file_status existing = fs::status(target, ec);
    if (!ec && fs::exists(existing)) mode = static_cast<unsigned>(existing.permissions()) & 07777;
    const auto [dir, base] = split_path(target);
    const std::string prefix = temp_prefix(base);
    for (int attempt = 0; attempt < kTempNameTries; ++attempt) {
        const fs::path temp = dir / path_from_utf8(temp_name(prefix));
        std::error_code error;
        switch (platform::write_new_file(temp, contents, mode, error)) {
            case platform::NewFile::written:
                return {given, target, temp};
            case platform::NewFile::exists:
                continue;
            case platform::NewFile::failed:
                fail_write(given, folder_reason(dir, error));
        }
    }
    fail_write(given, system_reason(std::make_error_code(std::errc::file_exists)));
}

// Two outputs that name one file (the same path, or through a link).
bool same_file(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    const auto canonical_a = fs::weakly_canonical(a, ec);
    const auto canonical_b = fs::weakly_canonical(b, ec);
    return a == b || (!ec && canonical_a == canonical_b);
}

void remove_all_temps(const std::vector<Prepared>& prepared) {
    std::error_code ignored;
    for (const Prepared& p : prepared) fs::remove(p.temp, ignored);
}

// An empty folder of a new name `prefix`XXXXXX in `parent`.
fs::path make_temp_folder(const std::string& given, const fs::path& parent,
                          const std::string& prefix) {
    for (int attempt = 0; attempt < kTempNameTries; ++attempt) {
        fs::path temp = parent / path_from_utf8(temp_name(prefix));
        std::error_code ec;
        if (fs::create_directory(temp, ec)) return temp;
        if (ec) fail_write(given, folder_reason(parent, ec));
    }
    fail_write(given, system_reason(std::make_error_code(std::errc::file_exists)));
}

// A free name beside `folder`'s for the old folder during a swap (Windows).
fs::path aside_name(const fs::path& parent, const std::string& prefix) {
    for (int attempt = 0; attempt < kTempNameTries; ++attempt) {
        fs::path aside = parent / path_from_utf8(temp_name(prefix));
        std::error_code ec;
        if (!fs::exists(fs::symlink_status(aside, ec))) return aside;
    }
    return parent / path_from_utf8(temp_name(prefix));
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
    std::vector<fs::path> targets;
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
        remove_all_temps(prepared);
        throw;
    }
    // Every file is complete: now the renames, each atomic.
    for (std::size_t i = 0; i < prepared.size(); ++i) {
        const std::error_code error = platform::replace_file(prepared[i].temp, prepared[i].target);
        if (error) {
            remove_all_temps({prepared.begin() + static_cast<std::ptrdiff_t>(i), prepared.end()});
            fail_write(prepared[i].given, system_reason(error));
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
    // The folder as it stands: a link to a folder is followed (the link stays).
    std::error_code ec;
    std::string trimmed = folder_given;
    while (trimmed.size() > 1 && (trimmed.back() == '/' || trimmed.back() == '\\'))
        trimmed.pop_back();
    fs::path folder = path_from_utf8(trimmed);
    if (fs::is_symlink(fs::symlink_status(folder, ec))) {
        const fs::path resolved = fs::canonical(folder, ec);
        if (ec) fail_write(folder_given, system_reason(ec));
        folder = resolved;
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
            const std::string name = utf8_from_path(it->path().filename());
            const bool ours = std::any_of(files.begin(), files.end(),
                                          [&](const OutputFile& f) { return f.path == name; });
            std::error_code entry_ec;
            if (ours && it->is_regular_file(entry_ec) && !it->is_symlink(entry_ec)) continue;
            if (++count <= 3) others += (others.empty() ? "" : ", ") + name;
        }
        if (ec) fail_write(folder_given, folder_reason(folder, ec));
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
    const fs::path temp = make_temp_folder(folder_given, parent, temp_prefix(base, ".new-"));
    const fs::path aside = aside_name(parent, temp_prefix(base, ".old-"));
    try {
        std::vector<OutputFile> inside;
        inside.reserve(files.size());
        for (const OutputFile& f : files)
            inside.push_back({utf8_from_path(temp / path_from_utf8(f.path)), f.contents});
        write_files_atomically(inside);
        fs::permissions(temp, fs::perms(0755), ec);
        const std::error_code error = exists ? platform::exchange_folders(temp, folder, aside)
                                             : platform::replace_file(temp, folder);
        if (error) fail_write(folder_given, system_reason(error));
    } catch (...) {
        fs::remove_all(temp, ec);
        throw;
    }
    // The old set: at the temporary's name after a swap in one step, aside
    // after a swap in two.
    fs::remove_all(temp, ec);
    fs::remove_all(aside, ec);
    remove_stale_temps(parent, temp_prefix(base, ".new-"), true);
    remove_stale_temps(parent, temp_prefix(base, ".old-"), true);
}

std::string read_text_file(const std::string& given, std::size_t max_bytes) {
    const fs::path path = path_from_utf8(given);
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec) fail_read(given, system_reason(ec));  // "No such file or directory" among them
    if (fs::is_directory(st)) fail_read(given, not_regular(st.type()));
    if (fs::is_regular_file(st)) {
        const std::uintmax_t size = fs::file_size(path, ec);
        if (!ec && size > max_bytes) fail_read(given, too_large(size, max_bytes));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_read(given, system_reason(std::error_code(errno, std::generic_category())));
    // Read at most one byte over the limit, so a pipe or a device cannot make
    // the text grow without bound.
    std::string text;
    std::array<char, 65536> buffer{};
    while (in && text.size() <= max_bytes) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) fail_read(given, system_reason(std::make_error_code(std::errc::io_error)));
    if (text.size() > max_bytes) fail_read(given, too_large(std::nullopt, max_bytes));
    return text;
}

}  // namespace probecycle
