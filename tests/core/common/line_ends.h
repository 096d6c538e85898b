#pragma once

// Input files as a Windows editor saves them, for the readers' tests: every
// reader must take "\r\n" line ends as it takes "\n".

#include <string>
#include <string_view>

namespace probecycle::test {

// `text` with every "\n" made "\r\n".
inline std::string with_crlf(std::string_view text) {
    std::string out;
    for (const char c : text) out += c == '\n' ? std::string_view("\r\n") : std::string_view(&c, 1);
    return out;
}

}  // namespace probecycle::test
