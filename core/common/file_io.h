#pragma once

// Reading and writing whole files. Every file ProbeCycle writes goes through
// write_file_atomically, so a crash or a full disk never leaves half a file.

#include <string>
#include <string_view>

namespace probecycle {

// Writes via a temporary file in the same directory and a rename, so the
// target is either the old or the complete new file. A symbolic link is
// written through (the link stays), an existing file keeps its permissions.
// Throws std::runtime_error naming the path.
void write_file_atomically(const std::string& path, std::string_view contents);
// Whole file as text. Throws std::runtime_error naming the path.
std::string read_text_file(const std::string& path);

}  // namespace probecycle
