#include "core/common/json_guard.h"

#include <gtest/gtest.h>

#include <string>

namespace probecycle {
namespace {

constexpr std::size_t kDepth = 4;

TEST(JsonGuard, AValidScenarioPasses) {
    EXPECT_FALSE(check_json_text(R"({"machine": {"scan_period_s": 0.004, "accel_model": "x"},
                                     "cycle": {"strategy": "two_touch"}})",
                                 kDepth));
    // Strings may hold anything that looks like structure or a key.
    EXPECT_FALSE(check_json_text(R"({"a": "{[[[[[[ \"a\": 1e999", "b": "a"})", kDepth));
}

TEST(JsonGuard, DeepNestingIsRefusedBeforeAnythingRecurses) {
    // The issue's input: 60000 brackets inside a key's value.
    const std::string deep = "{\"machine\":{\"time_constant_s\":" + std::string(60000, '[') +
                             std::string(60000, ']') + "}}";
    const auto error = check_json_text(deep, kDepth);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->key, "machine.time_constant_s");
    EXPECT_EQ(error->allowed.code, "too_deep");
    const std::string m = error->message();
    EXPECT_NE(m.find("at most 4 levels"), std::string::npos) << m;
    EXPECT_NE(m.find("line 1, column 33"), std::string::npos) << m;
    // At the top and under a section too.
    EXPECT_EQ(check_json_text("{\"machine\":" + std::string(100, '['), kDepth)->key, "machine");
    EXPECT_EQ(check_json_text(std::string(100, '['), kDepth)->key, "file");
}

TEST(JsonGuard, ANulByteIsRefusedWithItsLine) {
    const std::string text =
        std::string("{\"cycle\":{\"strategy\":\"single_touch\"}}\n") + '\0' + "{{{";
    const auto error = check_json_text(text, kDepth);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->allowed.code, "nul_byte");
    EXPECT_NE(error->message().find("line 2, column 1"), std::string::npos) << error->message();
    EXPECT_EQ(check_json_text(std::string("{\"a\":\"x") + '\0' + "\"}", kDepth)->allowed.code,
              "nul_byte");
}

TEST(JsonGuard, ADuplicateKeyNamesTheKeyAndBothLines) {
    const auto error =
        check_json_text("{\"machine\":{\"time_constant_s\":5,\n\"time_constant_s\":0.05}}", kDepth);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->key, "machine.time_constant_s");
    EXPECT_EQ(error->allowed.code, "duplicate_key");
    EXPECT_NE(error->message().find("line 1 and again at line 2"), std::string::npos)
        << error->message();
    // A section given twice, and the same key in two sections (allowed).
    EXPECT_EQ(check_json_text("{\"cycle\":{},\n\n\"cycle\":{}}", kDepth)->key, "cycle");
    EXPECT_FALSE(check_json_text(R"({"a":{"x":1},"b":{"x":1}})", kDepth));
}

TEST(JsonGuard, AnEmptyKeyIsNamedAsSuch) {
    const auto error = check_json_text("{\"\":{}}", kDepth);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->allowed.code, "empty_key");
    EXPECT_NE(error->message().find("empty key \"\""), std::string::npos) << error->message();
}

TEST(JsonGuard, ANumberTooLargeNamesTheKeyAndLine) {
    const auto error = check_json_text("{\"machine\":\n{\"scan_period_s\":1e400}}", kDepth);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->key, "machine.scan_period_s");
    EXPECT_EQ(error->value, "1e400");
    EXPECT_EQ(error->allowed.code, "number_overflow");
    EXPECT_NE(error->message().find("at line 2 it is out of range"), std::string::npos)
        << error->message();
    // Underflow to zero and ordinary large numbers pass.
    EXPECT_FALSE(check_json_text(R"({"a":1e-400,"b":-1.7e308})", kDepth));
}

}  // namespace
}  // namespace probecycle
