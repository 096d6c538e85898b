// Placeholder until the lab lands (issue 4); replaced by the lab's commands.
#include "cli_common.h"
#include "commands.h"

namespace probecycle::cli {

int run_calibrate(std::span<const std::string>) {
    throw UsageError("calibrate: not available in this build");
}
int run_latency(std::span<const std::string>) {
    throw UsageError("latency: not available in this build");
}

}  // namespace probecycle::cli
