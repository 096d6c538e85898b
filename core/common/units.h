#pragma once

// One internal unit per quantity: millimetres, seconds, mm/s. Feeds arrive in
// mm/min (as on the control) and are converted here and nowhere else.

namespace probecycle {

constexpr double kSecondsPerMinute = 60.0;

constexpr double mm_min_to_mm_s(double feed_mm_min) {
    return feed_mm_min / kSecondsPerMinute;
}
constexpr double mm_s_to_mm_min(double speed_mm_s) {
    return speed_mm_s * kSecondsPerMinute;
}

}  // namespace probecycle
