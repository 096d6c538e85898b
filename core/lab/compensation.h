#pragma once

// Compensation of the trigger position (docs/cli.md, "Compensation"):
// timestamp interpolation, cycle-lag compensation from a ring buffer of
// encoder increments, and a simulator that compares them with the naive
// v * tau correction, at constant speed and while braking.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/common/field_error.h"
#include "core/cycle/motion.h"

namespace probecycle {

// --- Timestamp interpolation ---
// P = P1 + (P2 - P1) * dt / T_ipo: P1, P2 the positions at the start and end of
// the interpolation cycle in which the edge was latched, dt its time in it.
double interpolate_trigger_mm(double p1_mm, double p2_mm, double dt_s,
                              double interpolation_period_s);

// --- Encoder counter with roll-over ---
// Mask of a counter `bits` wide (1..64).
std::uint64_t counter_mask(int counter_bits);
// The signed change from `previous` to `current` of a counter that wraps at
// 2^bits: the shortest way round, right while one cycle moves the counter by
// less than half its range.
std::int64_t counter_increment(std::uint64_t previous, std::uint64_t current, int counter_bits);

// The last 50 per-cycle feedback increments, in counts: the ring buffer a
// control with cycle-lag compensation keeps, and whose last N increments it
// subtracts from the recorded position.
class IncrementRing {
  public:
    static constexpr std::size_t kCapacity = 50;

    explicit IncrementRing(int counter_bits = 32) : counter_bits_(counter_bits) {}

    // The raw counter read at the end of an interpolation cycle. The first read
    // only sets the reference; each later one adds an increment, dropping the
    // oldest beyond kCapacity.
    void push_counter(std::uint64_t raw_counter);
    // Increments held (at most kCapacity).
    std::size_t size() const { return size_; }
    // The increment `age` cycles back: 0 the newest. Requires age < size().
    std::int64_t increment(std::size_t age) const;
    // Sum of the newest `n` increments; std::out_of_range when n > size().
    std::int64_t sum_latest(std::size_t n) const;
    int counter_bits() const { return counter_bits_; }

  private:
    std::array<std::int64_t, kCapacity> increments_{};
    std::size_t newest_{kCapacity - 1};
    std::size_t size_{0};
    std::optional<std::uint64_t> last_raw_;
    int counter_bits_;
};

// The lag N, in whole interpolation cycles, for cycle-lag compensation from a
// delay measured at constant speed: such a test sees the N cycles plus, on
// average, half a cycle (the trigger's place in its cycle), so N = round(tau/T
// - 1/2), within the ring's 0..49. The simulator's naive delay, (N + 1/2) T,
// is the same relation the other way round.
int lag_cycles_for_delay(double delay_s, double interpolation_period_s);

// Cycle-lag compensation: the position the control recorded, less the last
// `lag_cycles` increments: where the axis was `lag_cycles` cycles earlier.
double compensate_cycle_lag_mm(double recorded_mm, const IncrementRing& ring,
                               std::size_t lag_cycles, double counts_per_mm);

// The naive correction: recorded - direction * v * tau, assuming the axis kept
// the speed v through the whole delay.
double compensate_naive_mm(double recorded_mm, int direction, double speed_mm_s, double delay_s);

// --- Simulator ---

enum class TouchMotion { constant_speed, braking };
const char* to_string(TouchMotion motion);

enum class CompensationMethod { uncompensated, naive_v_tau, cycle_lag, timestamp };
constexpr std::size_t kCompensationMethodCount = 4;
const char* to_string(CompensationMethod method);

struct CompensationSetup {
    MotionLimits limits{};
    double feed_mm_min{2000.0};
    int direction{1};  // +1 / -1: sign of the axis travel
    TouchMotion touch{TouchMotion::constant_speed};
    // Braking: the speed at the trigger as a fraction of the feed, in (0, 1].
    double braking_speed_fraction{0.5};
    double interpolation_period_s{0.001};
    // The control records the position `lag_cycles` cycles after the end of the
    // cycle in which the probe triggered.
    int lag_cycles{8};
    // The lag the cycle-lag compensation subtracts, set apart from the true lag
    // (a published study compensated 7-9 cycles on a machine that lagged about
    // 10). By default the true lag_cycles.
    std::optional<int> compensated_lag_cycles;
    // Where in its cycle the trigger falls: dt = phase * T_ipo, in [0, 1).
    double trigger_phase{0.4};
    double counts_per_mm{10000.0};  // encoder resolution (0.1 um)
    int counter_bits{32};
    // Raw counter at position 0; by default chosen so the counter wraps during
    // the lag, which the roll-over handling must survive.
    std::optional<std::uint64_t> counter_at_zero;
    // Delay the naive correction uses; by default (lag + 0.5) * T_ipo, the mean
    // a delay-stability test at constant speed measures.
    std::optional<double> naive_delay_s;
};

// Ranges and cross-checks, naming the field (the CLI option without "--").
std::vector<FieldError> validate(const CompensationSetup& setup);

struct TraceSample {
    int cycle{0};               // 0: start of the trigger's cycle (P1), 1: its end (P2)
    double time_s{0.0};         // relative to the trigger
    double position_mm{0.0};    // true axis position
    double speed_mm_s{0.0};     // signed
    std::uint64_t counter{0};   // raw encoder counter (wraps)
    std::int64_t increment{0};  // counts since the previous cycle (0 for the first)
};

struct MethodResult {
    CompensationMethod method{};
    double position_mm{0.0};
    double error_mm{0.0};  // position - true trigger position
};

struct CompensationComparison {
    double trigger_position_mm{0.0};  // true
    double trigger_speed_mm_s{0.0};   // magnitude at the trigger
    double recorded_speed_mm_s{0.0};  // magnitude when the control records
    double recorded_position_mm{0.0};
    double dt_s{0.0};
    double p1_mm{0.0};
    double p2_mm{0.0};
    double naive_delay_s{0.0};
    int counter_wraps{0};  // roll-overs in the trace
    std::array<MethodResult, kCompensationMethodCount> methods{};
    // The last 51 cycles up to the recording: 50 increments, the ring's content.
    std::vector<TraceSample> trace;

    const MethodResult& result(CompensationMethod method) const {
        return methods[static_cast<std::size_t>(method)];
    }
};

// Assumes a valid setup (validate() first).
CompensationComparison simulate_compensation(const CompensationSetup& setup);

// The comparison chart: errors of each method against the speed at the
// trigger, while braking, for the given fractions of the feed in (0, 1].
struct BrakingRow {
    double speed_fraction{0.0};
    double trigger_speed_mm_s{0.0};
    std::array<double, kCompensationMethodCount> error_mm{};
};
std::vector<BrakingRow> sweep_braking(const CompensationSetup& setup,
                                      std::span<const double> speed_fractions);

// The cycle-lag method's error against the lag it compensates, the true lag
// as set: one row per compensated lag from 0 to the ring's 49.
struct LagRow {
    int compensated_lag_cycles{0};
    double error_mm{0.0};
};
std::vector<LagRow> sweep_compensated_lag(const CompensationSetup& setup);

}  // namespace probecycle
