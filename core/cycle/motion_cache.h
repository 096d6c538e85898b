#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/cycle/dynamics.h"
#include "core/cycle/motion.h"

namespace probecycle {

// The solves of a machine with dynamics after interpolation, kept between the
// evaluations of one machine (a sweep's feeds, the optimiser's candidates):
// each rest-to-rest move's in-position time and each approach room is a
// root search, and many of them (positioning, a backoff from the stop, the
// measuring touch's room) do not depend on the setting that varies. Keyed by
// their exact inputs; bound to one machine's motion limits and dynamics
// (evaluating another machine empties it); a fixed, small capacity, the
// oldest forgotten first.
class MotionCache {
  public:
    // Empties the cache unless it holds `limits` and `dynamics`'s solves.
    void bind(const MotionLimits& limits, const AxisDynamics& dynamics);
    // The bound dynamics' kernel, prepared once.
    const AxisKernel& kernel() const { return kernel_; }

    // A rest-to-rest move: its time to the in-position check, and where its
    // command ends (the next block starts there).
    struct Move {
        double time_s{0.0};
        double end_mm{0.0};
        bool operator==(const Move&) const = default;
    };
    std::optional<Move> move(double distance_mm, double feed_mm_s) const;
    void store_move(double distance_mm, double feed_mm_s, const Move& move);
    // Approach room for a feed and a measurement delay.
    std::optional<double> approach_room_mm(double feed_mm_s, double delay_s) const;
    void store_approach_room(double feed_mm_s, double delay_s, double room_mm);

    // A touch's solve, kept by feed and probe timing. A touch whose approach
    // has settled before it touches (every break of its command older than
    // AxisKernel::settled_age_s()) moves as the command's moment expansion, a
    // cruise: at any longer distance it is the same touch shifted in time
    // and place. Such touches are solved once, at the distance where the
    // approach settles (a `reference`), and shifted from there, so the
    // measuring touch of a sweep (its distance changes with the first
    // touch's overtravel) is solved once, and the result is the same with or
    // without the cache. Other touches are kept for their exact distance.
    struct TouchKey {
        double feed_mm_s{0.0};
        double pretravel_mm{0.0};
        double interface_delay_s{0.0};
        double reaction_s{0.0};      // trigger to reaction, worst case (reaction_time_s)
        double scan_s{0.0};          // the scan period in it: on average half of it passes
        double record_delay_s{0.0};  // interface to recorded position (a scan, or 0 latched)
        bool operator==(const TouchKey&) const = default;
    };
    struct SolvedTouch {
        double distance_mm{0.0};  // from the approach's start to the surface
        // From the approach's start: the touch, the trigger, and the end of
        // the deceleration (the in-position check, or the reaction if later)
        // after the mean scan wait.
        double touch_s{0.0};
        double trigger_s{0.0};
        double settle_s{0.0};
        double touch_speed_mm_s{0.0};
        double trigger_speed_mm_s{0.0};
        // Past the surface, where the control records the touch: after a full
        // scan (worst case) and after the mean wait.
        double recorded_mm{0.0};
        double mean_recorded_mm{0.0};
        // From the approach's start, where the axis comes to rest: after the
        // mean scan wait (the timeline's) and after a full scan.
        double rest_mm{0.0};
        double worst_rest_mm{0.0};
        bool reference{false};  // settled: serves every longer distance
    };
    // The kept touch for `key` at `distance_mm`, or the reference to shift
    // to it.
    std::optional<SolvedTouch> touch(const TouchKey& key, double distance_mm);
    void store_touch(const TouchKey& key, const SolvedTouch& touch);

  private:
    template <typename Value>
    struct Table {
        struct Entry {
            double key1{0.0};
            double key2{0.0};
            Value value{};
        };
        std::array<Entry, 16> entries{};
        std::size_t count{0};
        std::size_t next{0};
        std::optional<Value> find(double key1, double key2) const;
        void store(double key1, double key2, const Value& value);
    };
    std::optional<MotionLimits> limits_;
    AxisDynamics dynamics_{};
    AxisKernel kernel_{};
    Table<Move> moves_;
    Table<double> rooms_;
    struct KeptTouch {
        TouchKey key;
        SolvedTouch touch;
    };
    std::array<KeptTouch, 8> touches_{};
    // The kept touches' slots, most recently used first: a sweep's first
    // touches, one per feed, do not push out its measuring touch.
    std::array<std::uint8_t, 8> touch_order_{};
    std::size_t touch_count_{0};
};

}  // namespace probecycle
