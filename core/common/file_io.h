#pragma once

// Reading and writing whole files. Every file ProbeCycle writes goes through
// write_file_atomically, so a crash or a full disk never leaves half a file.

#include <stdexcept>
#include <string>
#include <string_view>

#include "core/common/message.h"

namespace probecycle {

// A file that could not be read or written: the path, what was attempted and
// the system's reason. what() is the English text of to_message().
class FileError : public std::runtime_error {
  public:
    enum class Action { read, write };
    FileError(Action action, std::string path, std::string reason);
    Action action() const { return action_; }
    const std::string& path() const { return path_; }
    const std::string& reason() const { return reason_; }
    // "cannot write %1: %2" / "cannot open %1: %2"
    Message to_message() const;

  private:
    Action action_;
    std::string path_;
    std::string reason_;
};

// Writes via a temporary file in the same directory and a rename, so the
// target is either the old or the complete new file. A symbolic link is
// written through (the link stays), an existing file keeps its permissions.
// Throws FileError naming the path.
void write_file_atomically(const std::string& path, std::string_view contents);
// Whole file as text. Throws FileError naming the path.
std::string read_text_file(const std::string& path);

}  // namespace probecycle
