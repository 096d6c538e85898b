#include "core/common/json_guard.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace probecycle {

namespace {

struct Frame {
    bool object{false};
    bool expect_key{false};
    std::string key;  // the key whose value is being read (objects)
    std::vector<std::pair<std::string, std::size_t>> keys;  // key and its line
};

class Scanner {
  public:
    Scanner(std::string_view text, std::size_t max_depth) : text_(text), max_depth_(max_depth) {}

    std::optional<FieldError> run() {
        while (pos_ < text_.size()) {
            const char ch = text_[pos_];
            if (ch == '\0') return problem(null_byte());
            if (ch == '"') {
                if (auto error = string_token()) return error;
                continue;
            }
            if (ch == '{' || ch == '[') {
                if (stack_.size() >= max_depth_) return problem(too_deep());
                Frame frame;
                frame.object = ch == '{';
                frame.expect_key = frame.object;
                stack_.push_back(std::move(frame));
            } else if (ch == '}' || ch == ']') {
                if (!stack_.empty()) stack_.pop_back();
            } else if (ch == ',') {
                if (!stack_.empty() && stack_.back().object) stack_.back().expect_key = true;
            } else if (ch == '-' || (ch >= '0' && ch <= '9')) {
                if (auto error = number_token()) return error;
                continue;
            }
            advance();
        }
        return std::nullopt;
    }

  private:
    void advance() {
        if (text_[pos_] == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        ++pos_;
    }

    std::string path() const {
        std::string out;
        for (const Frame& f : stack_) {
            if (!f.object || f.key.empty()) continue;
            if (!out.empty()) out += '.';
            out += f.key;
        }
        return out.empty() ? std::string("file") : out;
    }

    Message at(const char* code, const char* text) const {
        Message m = allowed_text(code, text);
        m.args = {arg("line", ArgKind::integer, static_cast<double>(line_)),
                  arg("column", ArgKind::integer, static_cast<double>(column_))};
        return m;
    }

    Message null_byte() const {
        return at("nul_byte", QT_TRANSLATE_NOOP("FieldError",
                                                "text without NUL bytes; one is at line %1, "
                                                "column %2"));
    }

    Message too_deep() const {
        Message m = at("too_deep", QT_TRANSLATE_NOOP("FieldError",
                                                     "at most %3 levels of nesting; line %1, "
                                                     "column %2 opens one more"));
        m.args.push_back(arg("max_depth", ArgKind::integer, static_cast<double>(max_depth_)));
        return m;
    }

    FieldError problem(Message allowed, std::string value = {}) const {
        return FieldError{path(), std::move(value), std::move(allowed)};
    }

    // A string: a key when an object expects one, else a value. Escapes are
    // kept as written (two spellings of one key are not merged).
    std::optional<FieldError> string_token() {
        const std::size_t start_line = line_;
        const std::size_t start_column = column_;
        advance();  // the opening quote
        std::string content;
        while (pos_ < text_.size() && text_[pos_] != '"') {
            if (text_[pos_] == '\0') return problem(null_byte());
            if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) {
                content += text_[pos_];
                advance();
            }
            content += text_[pos_];
            advance();
        }
        if (pos_ < text_.size()) advance();  // the closing quote; nlohmann reports a missing one
        if (stack_.empty() || !stack_.back().object || !stack_.back().expect_key) {
            return std::nullopt;
        }
        Frame& frame = stack_.back();
        frame.expect_key = false;
        if (content.empty()) {
            Message m = allowed_text(
                "empty_key", QT_TRANSLATE_NOOP("FieldError",
                                               "a key with a name; line %1, column %2 has an "
                                               "empty key \"\""));
            m.args = {arg("line", ArgKind::integer, static_cast<double>(start_line)),
                      arg("column", ArgKind::integer, static_cast<double>(start_column))};
            return problem(std::move(m));
        }
        for (const auto& [key, key_line] : frame.keys) {
            if (key != content) continue;
            frame.key = content;
            Message m = allowed_text(
                "duplicate_key",
                QT_TRANSLATE_NOOP("FieldError",
                                  "each key once per object; it is given at line %1 and again "
                                  "at line %2"));
            m.args = {arg("first_line", ArgKind::integer, static_cast<double>(key_line)),
                      arg("line", ArgKind::integer, static_cast<double>(start_line))};
            return problem(std::move(m));
        }
        frame.keys.emplace_back(content, start_line);
        frame.key = std::move(content);
        return std::nullopt;
    }

    std::optional<FieldError> number_token() {
        const std::size_t start = pos_;
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (!((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' ||
                  c == 'E')) {
                break;
            }
            advance();
        }
        const std::string token(text_.substr(start, pos_ - start));
        errno = 0;
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        // Only a well-formed number that overflows: nlohmann reports the rest.
        if (end == token.c_str() + token.size() && errno == ERANGE && std::isinf(value)) {
            Message m = allowed_text("number_overflow",
                                     QT_TRANSLATE_NOOP("FieldError",
                                                       "a number a double can hold (up to about "
                                                       "1.8e308); at line %1 it is out of range"));
            m.args = {arg("line", ArgKind::integer, static_cast<double>(line_))};
            return problem(std::move(m), token);
        }
        return std::nullopt;
    }

    std::string_view text_;
    std::size_t max_depth_;
    std::size_t pos_{0};
    std::size_t line_{1};
    std::size_t column_{1};
    std::vector<Frame> stack_;
};

}  // namespace

std::optional<FieldError> check_json_text(std::string_view text, std::size_t max_depth) {
    return Scanner(text, max_depth).run();
}

std::optional<FieldError> parse_checked_json(std::string_view text, std::size_t max_depth,
                                             nlohmann::ordered_json& root) {
    if (std::optional<FieldError> error = check_json_text(text, max_depth)) return error;
    try {
        root = nlohmann::ordered_json::parse(text.begin(), text.end());
    } catch (const nlohmann::json::exception& e) {
        return FieldError{"file", "",
                          Message{"malformed_json",
                                  "FieldError",
                                  QT_TRANSLATE_NOOP("FieldError", "malformed JSON: %1"),
                                  {text_arg("detail", e.what())}}};
    }
    return std::nullopt;
}

}  // namespace probecycle
