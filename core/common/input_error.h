#pragma once

// Input that a computation refuses, outside a file's lines (those are
// CsvError): a gauge smaller than the touches, a length that is not positive,
// a delay group the fit does not have, comparison files whose point counts
// differ. It is a std::invalid_argument whose
// what() is the English text, and carries the message for the window.

#include <stdexcept>
#include <utility>

#include "core/common/message.h"

namespace probecycle {

class InputError : public std::invalid_argument {
  public:
    explicit InputError(Message message)
        : std::invalid_argument(render(message)), message_(std::move(message)) {}
    const Message& to_message() const { return message_; }

  private:
    Message message_;
};

}  // namespace probecycle
