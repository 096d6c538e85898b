#pragma once

// Reading and writing whole files. Every file ProbeCycle writes goes through
// write_file_atomically, the CLI's and the window's alike, so a crash or a
// full disk never leaves half a file; every input file is read through
// read_text_file, with one size limit.

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/message.h"

namespace probecycle {

// The largest input file read: scenarios and lab files are kilobytes; 16 MiB
// is hundreds of thousands of touches, and reads in a few seconds.
constexpr std::size_t kMaxInputFileBytes = std::size_t{16} << 20;

// A file that could not be read or written: the path, what was attempted and
// why. what() is the English text of to_message().
class FileError : public std::runtime_error {
  public:
    enum class Action { read, write };
    FileError(Action action, std::string path, Message reason);
    Action action() const { return action_; }
    const std::string& path() const { return path_; }
    // Why, without the path: "it is a directory", or the system's reason.
    const Message& reason() const { return reason_; }
    // "cannot write %1: %2" / "cannot open %1: %2"
    Message to_message() const;

  private:
    Action action_;
    std::string path_;
    Message reason_;
};

// Writes via a temporary file in the same directory and a rename, so the
// target is either the old or the complete new file. A symbolic link (or a
// chain of them) is written through (the links stay), an existing file keeps
// its permissions. Only a regular file or a new path is written: a directory,
// a FIFO, a device, a socket, a link to nothing or a read-only file is
// refused and left as it is. The rename makes a new file: a file with other
// hard links is replaced under this name only (the other names keep the old
// text). After a successful write, temporary files of this writer's naming
// for the same target that a killed write left behind (older than a minute)
// are removed. Throws FileError naming the path.
void write_file_atomically(const std::string& path, std::string_view contents);

// One file of an output written as a unit: its path and its text.
struct OutputFile {
    std::string path;
    std::string_view contents;
};

// Several files as one output (a program and its plan, a report and the
// scenario it applies to): every target is checked as write_file_atomically
// checks it, and no two may be the same file; each is then written complete
// to a temporary file beside its target, and only when all are complete are
// they renamed into place, in order. A refusal or a failed write leaves every
// target as it was. (A kill between two renames can leave a new file beside
// an old one: the files themselves must make that detectable, as a
// program's plan id does.)
void write_files_atomically(const std::vector<OutputFile>& files);

// A set of files as one folder (`compare simulate --out`); each file's path
// is its name in the folder. The set is built in a temporary folder beside
// `folder` and renamed into place, or swapped with the existing folder in
// one step, so a reader sees the old set or the new, never a mix. (Windows
// has no such swap: the old folder is renamed aside and the new one in, so
// a reader between the two renames finds no folder, never a mix either.) An existing
// folder is replaced only when it holds nothing but files of the set's names
// (an earlier set) or nothing at all; otherwise refused, naming what else it
// holds. A symbolic link to a folder is followed.
void write_folder_atomically(const std::string& folder, const std::vector<OutputFile>& files);

// A path given as UTF-8 text (as the CLI and the window pass every path) for
// std::filesystem, and back. On Windows a std::string path would be read in
// the system's code page, and a Chinese or Russian folder name lost.
std::filesystem::path path_from_utf8(std::string_view utf8);
std::string utf8_from_path(const std::filesystem::path& path);

// A file name Windows takes for a device in any folder: CON, PRN, AUX, NUL,
// COM1-9 or LPT1-9, with any extension and in any case ("nul.csv"). On
// Windows the writers refuse such a name (writing there would go to the
// device); elsewhere it is an ordinary name.
bool is_windows_device_name(std::string_view file_name);

// Whole file as text, at most `max_bytes`. A directory or a larger file is
// refused. Pipes and devices are read (a scenario may come from a pipe).
// Throws FileError naming the path.
std::string read_text_file(const std::string& path, std::size_t max_bytes = kMaxInputFileBytes);

}  // namespace probecycle
