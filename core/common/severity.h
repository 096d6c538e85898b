#pragma once

// How serious a finding is: shared by the cycle's warnings and the lab's.

namespace probecycle {

enum class Severity { info, warning, error };
const char* to_string(Severity severity);  // "info", "warning", "error"

}  // namespace probecycle
