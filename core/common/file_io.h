#pragma once

// Reading and writing whole files. Every file ProbeCycle writes goes through
// write_file_atomically, the CLI's and the window's alike, so a crash or a
// full disk never leaves half a file; every input file is read through
// read_text_file, with one size limit.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

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
// target is either the old or the complete new file. A symbolic link is
// written through (the link stays), an existing file keeps its permissions.
// Only a regular file or a new path is written: a directory, a FIFO, a
// device, a socket or a link to nothing is refused and left as it is. After
// a successful write, temporary files of this writer's naming for the same
// target that a killed write left behind (older than a minute) are removed.
// Throws FileError naming the path.
void write_file_atomically(const std::string& path, std::string_view contents);

// Whole file as text, at most `max_bytes`. A directory or a larger file is
// refused. Pipes and devices are read (a scenario may come from a pipe).
// Throws FileError naming the path.
std::string read_text_file(const std::string& path, std::size_t max_bytes = kMaxInputFileBytes);

}  // namespace probecycle
