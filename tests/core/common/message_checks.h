#pragma once

// What every message of the core must be for the window to translate it and
// the CLI's JSON to list it (core/common/message.h).

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "core/common/message.h"
#include "core/common/message_json.h"

namespace probecycle::test {

// A stable code, a template with its translation context, one argument per
// placeholder %1..%N, and exactly `names` as its values (nested messages
// included), in that order; a name with a unit (_mm, _s, _mm_min, _deg) holds a
// number, not text.
inline void expect_translatable(const Message& m, const std::vector<std::string>& names) {
    EXPECT_FALSE(m.code.empty()) << m.text;
    EXPECT_FALSE(std::string_view(m.context).empty()) << m.code;
    ASSERT_FALSE(std::string_view(m.text).empty()) << m.code;
    const std::string_view text = m.text;
    for (std::size_t k = 1; k <= 9; ++k) {
        const char placeholder[] = {'%', static_cast<char>('0' + k), '\0'};
        const bool used = text.find(placeholder) != std::string_view::npos;
        EXPECT_EQ(used, k <= m.args.size()) << m.code << ": %" << k << " in \"" << text << '"';
    }
    const nlohmann::ordered_json values = message_values(m);
    std::vector<std::string> got;
    for (auto it = values.begin(); it != values.end(); ++it) {
        got.push_back(it.key());
        for (const std::string_view unit : {"_mm", "_s", "_mm_min", "_deg"}) {
            if (it.key().ends_with(unit)) {
                EXPECT_TRUE(it.value().is_number()) << m.code << ": " << it.key();
            }
        }
    }
    EXPECT_EQ(got, names) << m.code << ": " << render(m);
}

}  // namespace probecycle::test
