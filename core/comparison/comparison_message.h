#pragma once

// The comparison's messages share one translation context, "Comparison"
// (core/common/message.h).

#include <utility>
#include <vector>

#include "core/common/message.h"

namespace probecycle {

inline Message comparison_message(const char* code, const char* text,
                                  std::vector<MessageArg> args) {
    return Message{code, "Comparison", text, std::move(args)};
}

}  // namespace probecycle
