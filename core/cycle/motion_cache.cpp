#include "core/cycle/motion_cache.h"

#include <algorithm>

namespace probecycle {

void MotionCache::bind(const MotionLimits& limits, const AxisDynamics& dynamics) {
    if (limits_ && *limits_ == limits && dynamics_ == dynamics) return;
    limits_ = limits;
    dynamics_ = dynamics;
    kernel_ = AxisKernel(dynamics);
    moves_ = {};
    rooms_ = {};
    touch_count_ = 0;
}

std::optional<MotionCache::Move> MotionCache::move(double distance_mm, double feed_mm_s) const {
    return moves_.find(distance_mm, feed_mm_s);
}

void MotionCache::store_move(double distance_mm, double feed_mm_s, const Move& move) {
    moves_.store(distance_mm, feed_mm_s, move);
}

std::optional<double> MotionCache::approach_room_mm(double feed_mm_s, double delay_s) const {
    return rooms_.find(feed_mm_s, delay_s);
}

void MotionCache::store_approach_room(double feed_mm_s, double delay_s, double room_mm) {
    rooms_.store(feed_mm_s, delay_s, room_mm);
}

std::optional<MotionCache::SolvedTouch> MotionCache::touch(const TouchKey& key,
                                                           double distance_mm) {
    for (std::size_t i = 0; i < touch_count_; ++i) {
        const std::uint8_t slot = touch_order_[i];
        const KeptTouch& kept = touches_[slot];
        if (!(kept.key == key)) continue;
        const SolvedTouch& t = kept.touch;
        if (distance_mm == t.distance_mm || (t.reference && distance_mm > t.distance_mm)) {
            std::copy_backward(touch_order_.begin(),
                               touch_order_.begin() + static_cast<std::ptrdiff_t>(i),
                               touch_order_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
            touch_order_[0] = slot;
            return t;
        }
    }
    return std::nullopt;
}

void MotionCache::store_touch(const TouchKey& key, const SolvedTouch& touch) {
    // A free slot while there is one, else the least recently used.
    const std::uint8_t slot = touch_count_ < touches_.size()
                                  ? static_cast<std::uint8_t>(touch_count_)
                                  : touch_order_[touches_.size() - 1];
    touch_count_ = std::min(touch_count_ + 1, touches_.size());
    std::copy_backward(touch_order_.begin(),
                       touch_order_.begin() + static_cast<std::ptrdiff_t>(touch_count_) - 1,
                       touch_order_.begin() + static_cast<std::ptrdiff_t>(touch_count_));
    touch_order_[0] = slot;
    touches_[slot] = {key, touch};
}

template <typename Value>
std::optional<Value> MotionCache::Table<Value>::find(double key1, double key2) const {
    for (std::size_t i = 0; i < count; ++i) {
        if (entries[i].key1 == key1 && entries[i].key2 == key2) return entries[i].value;
    }
    return std::nullopt;
}

template <typename Value>
void MotionCache::Table<Value>::store(double key1, double key2, const Value& value) {
    entries[next] = {key1, key2, value};
    next = (next + 1) % entries.size();
    count = std::max(count, next == 0 ? entries.size() : next);
}

}  // namespace probecycle
