#include "core/lab/compensation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/csv_reader.h"
#include "core/common/number_format.h"
#include "core/common/units.h"

namespace probecycle {

double interpolate_trigger_mm(double p1_mm, double p2_mm, double dt_s,
                              double interpolation_period_s) {
    // Domain.md, "Latency", "Timestamp interpolation": P3 = P1 + (P2 - P1) dt / T_ipo.
    return p1_mm + (p2_mm - p1_mm) * dt_s / interpolation_period_s;
}

std::uint64_t counter_mask(int counter_bits) {
    if (counter_bits >= 64) return ~std::uint64_t{0};
    return (std::uint64_t{1} << counter_bits) - 1;
}

std::int64_t counter_increment(std::uint64_t previous, std::uint64_t current, int counter_bits) {
    // Domain.md, "Cycle-lag compensation": "encoder pulses, with counter
    // roll-over handled". The difference modulo 2^bits, read as the signed
    // value nearest zero (two's complement in that width).
    const std::uint64_t mask = counter_mask(counter_bits);
    const std::uint64_t difference = (current - previous) & mask;
    if (counter_bits >= 64) return static_cast<std::int64_t>(difference);
    const std::uint64_t half = std::uint64_t{1} << (counter_bits - 1);
    if (difference < half) return static_cast<std::int64_t>(difference);
    return static_cast<std::int64_t>(difference) - static_cast<std::int64_t>(mask) - 1;
}

void IncrementRing::push_counter(std::uint64_t raw_counter) {
    if (last_raw_) {
        newest_ = (newest_ + 1) % kCapacity;
        increments_[newest_] = counter_increment(*last_raw_, raw_counter, counter_bits_);
        size_ = std::min(size_ + 1, kCapacity);
    }
    last_raw_ = raw_counter;
}

std::int64_t IncrementRing::increment(std::size_t age) const {
    return increments_[(newest_ + kCapacity - age % kCapacity) % kCapacity];
}

std::int64_t IncrementRing::sum_latest(std::size_t n) const {
    if (n > size_) {
        throw std::out_of_range("the ring holds " + std::to_string(size_) + " increments, not " +
                                std::to_string(n));
    }
    std::int64_t sum = 0;
    for (std::size_t age = 0; age < n; ++age) sum += increment(age);
    return sum;
}

double compensate_cycle_lag_mm(double recorded_mm, const IncrementRing& ring,
                               std::size_t lag_cycles, double counts_per_mm) {
    // Domain.md, "Cycle-lag compensation": subtract the last N increments.
    return recorded_mm - static_cast<double>(ring.sum_latest(lag_cycles)) / counts_per_mm;
}

int lag_cycles_for_delay(double delay_s, double interpolation_period_s) {
    const double cycles = std::round(delay_s / interpolation_period_s - 0.5);
    return static_cast<int>(
        std::clamp(cycles, 0.0, static_cast<double>(IncrementRing::kCapacity - 1)));
}

double compensate_naive_mm(double recorded_mm, int direction, double speed_mm_s, double delay_s) {
    // The plain v * tau correction: it assumes the axis kept its speed through
    // the delay, which is wrong while braking (docs/cli.md, "Compensation").
    return recorded_mm - direction * speed_mm_s * delay_s;
}

const char* to_string(TouchMotion motion) {
    switch (motion) {
        case TouchMotion::constant_speed:
            return "constant_speed";
        case TouchMotion::braking:
            return "braking";
    }
    return "?";
}

const char* to_string(CompensationMethod method) {
    switch (method) {
        case CompensationMethod::uncompensated:
            return "uncompensated";
        case CompensationMethod::naive_v_tau:
            return "naive_v_tau";
        case CompensationMethod::cycle_lag:
            return "cycle_lag";
        case CompensationMethod::timestamp:
            return "timestamp";
    }
    return "?";
}

std::vector<FieldError> validate(const CompensationSetup& setup) {
    std::vector<FieldError> errors;
    const auto check = [&errors](const char* key, double value, double min, double max,
                                 bool min_open, bool max_open) {
        const bool above = min_open ? value > min : value >= min;
        const bool below = max_open ? value < max : value <= max;
        if (!(above && below)) {
            Message allowed = allowed_text(
                "out_of_range",
                min_open ? (max_open ? QT_TRANSLATE_NOOP("FieldError", "a number in (%1, %2)")
                                     : QT_TRANSLATE_NOOP("FieldError", "a number in (%1, %2]"))
                         : (max_open ? QT_TRANSLATE_NOOP("FieldError", "a number in [%1, %2)")
                                     : QT_TRANSLATE_NOOP("FieldError", "a number in [%1, %2]")));
            allowed.args = {arg("min", ArgKind::number, min), arg("max", ArgKind::number, max)};
            errors.push_back({key, format_number(value), allowed});
        }
    };
    check("feed-mm-min", setup.feed_mm_min, 0.0, 100000.0, true, false);
    if (setup.direction != 1 && setup.direction != -1) {
        errors.push_back(
            {"direction", std::to_string(setup.direction),
             allowed_text("not_a_direction", QT_TRANSLATE_NOOP("FieldError", "+1 or -1"))});
    }
    check("speed-fraction", setup.braking_speed_fraction, 0.0, 1.0, true, false);
    check("interpolation-period-s", setup.interpolation_period_s, 1e-5, 0.1, false, false);
    check("lag-cycles", setup.lag_cycles, 0.0, static_cast<double>(IncrementRing::kCapacity) - 1.0,
          false, false);
    check("trigger-phase", setup.trigger_phase, 0.0, 1.0, false, true);
    check("counts-per-mm", setup.counts_per_mm, 1.0, 1e7, false, false);
    check("counter-bits", setup.counter_bits, 16.0, 64.0, false, false);
    if (setup.naive_delay_s) check("naive-delay-s", *setup.naive_delay_s, 0.0, 1.0, false, false);
    if (setup.compensated_lag_cycles) {
        check("compensated-lag-cycles", *setup.compensated_lag_cycles, 0.0,
              static_cast<double>(IncrementRing::kCapacity) - 1.0, false, false);
    }
    if (errors.empty() && setup.counter_bits < 64) {
        // One cycle must move the counter by less than half its range, or the
        // roll-over cannot be told from a move the other way.
        const double counts_per_cycle =
            mm_min_to_mm_s(setup.feed_mm_min) * setup.interpolation_period_s * setup.counts_per_mm;
        const double half_range = std::ldexp(1.0, setup.counter_bits - 1);
        if (counts_per_cycle >= half_range) {
            Message allowed = allowed_text(
                "counter_too_narrow",
                QT_TRANSLATE_NOOP("FieldError",
                                  "a counter wide enough that one cycle (%1 counts) moves it by "
                                  "less than half its range"));
            allowed.args = {arg("counts_per_cycle", ArgKind::number, counts_per_cycle)};
            errors.push_back({"counter-bits", std::to_string(setup.counter_bits), allowed});
        }
    }
    return errors;
}

namespace {

void append(SegmentPlan& to, const SegmentPlan& from) {
    for (std::size_t i = 0; i < from.count; ++i) {
        to.push(from.segments[i].duration_s, from.segments[i].accel_mm_s2,
                from.segments[i].jerk_mm_s3);
    }
}

// Time into a braking plan started at `start_speed_mm_s` at which the speed
// has fallen to `speed_mm_s` (it falls monotonically while braking).
double time_at_speed_s(const SegmentPlan& stop, double start_speed_mm_s, double speed_mm_s) {
    double lo = 0.0;
    double hi = stop.duration_s();
    const KinematicState start{0.0, start_speed_mm_s, 0.0};
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (stop.state_at(mid, start).speed_mm_s > speed_mm_s) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

}  // namespace

CompensationComparison simulate_compensation(const CompensationSetup& setup) {
    const double v = mm_min_to_mm_s(setup.feed_mm_min);
    const double period = setup.interpolation_period_s;
    const int lag = setup.lag_cycles;
    const double direction = setup.direction;

    // The axis from rest: accelerate, cruise, and (braking) stop, from the
    // cycle model's motion laws (motion.h).
    SegmentPlan plan;
    double t_trigger = 0.0;
    const double reach_s = reach_time_s(setup.limits, v);
    if (setup.touch == TouchMotion::constant_speed) {
        // Trigger one cycle into the cruise, which lasts past the recording.
        plan = plan_accelerate(setup.limits, v, (lag + 12) * period);
        t_trigger = reach_s + period;
    } else {
        const double cruise_s = 60.0 * period;
        plan = plan_accelerate(setup.limits, v, cruise_s);
        const SegmentPlan stop = plan_stop(setup.limits, v, v, 0.0);
        const double fraction = setup.braking_speed_fraction;
        const double t_in_stop = fraction < 1.0 ? time_at_speed_s(stop, v, fraction * v) : 0.0;
        append(plan, stop);
        t_trigger = reach_s + cruise_s + t_in_stop;
    }

    const auto position_at = [&](double t_s) { return direction * plan.state_at(t_s).position_mm; };
    const auto speed_at = [&](double t_s) { return plan.state_at(t_s).speed_mm_s; };

    CompensationComparison out;
    out.dt_s = setup.trigger_phase * period;
    out.trigger_position_mm = position_at(t_trigger);
    out.trigger_speed_mm_s = speed_at(t_trigger);
    // The delay a delay-stability test at constant speed finds for this control
    // (the slope of its line, docs/cli.md, "Delay fit"): the lag plus, on
    // average, the half cycle between the trigger and the end of its cycle.
    out.naive_delay_s = setup.naive_delay_s.value_or((lag + 0.5) * period);

    // Cycle j ends at tau_j = t_trigger - dt + j T: j = 0 and 1 bound the cycle
    // of the trigger, j = 1 + lag is when the control records.
    const int last = 1 + lag;
    const int first = last - static_cast<int>(IncrementRing::kCapacity);
    const auto time_of = [&](int j) { return t_trigger - out.dt_s + j * period; };
    const auto counts_at = [&](int j) {
        return static_cast<std::int64_t>(
            std::llround(position_at(time_of(j)) * setup.counts_per_mm));
    };
    const std::uint64_t mask = counter_mask(setup.counter_bits);
    // By default the counter passes zero half-way through the lag.
    const std::uint64_t counter_at_zero = setup.counter_at_zero.value_or(
        (std::uint64_t{0} - static_cast<std::uint64_t>(counts_at(1 + lag / 2))) & mask);

    IncrementRing ring(setup.counter_bits);
    out.trace.reserve(IncrementRing::kCapacity + 1);
    for (int j = first; j <= last; ++j) {
        const std::int64_t counts = counts_at(j);
        TraceSample sample;
        sample.cycle = j;
        sample.time_s = time_of(j) - t_trigger;
        sample.position_mm = position_at(time_of(j));
        sample.speed_mm_s = direction * speed_at(time_of(j));
        sample.counter = (counter_at_zero + static_cast<std::uint64_t>(counts)) & mask;
        ring.push_counter(sample.counter);
        if (j > first) {
            // What the ring holds: the increment read through the roll-over.
            const std::uint64_t before = out.trace.back().counter;
            sample.increment = counter_increment(before, sample.counter, setup.counter_bits);
            if ((sample.increment > 0 && sample.counter < before) ||
                (sample.increment < 0 && sample.counter > before)) {
                ++out.counter_wraps;
            }
        }
        out.trace.push_back(sample);
    }

    // The control's own position is the unwrapped count (it accumulates the
    // increments), so the recorded and the cycle positions are quantised.
    const double resolution_mm = 1.0 / setup.counts_per_mm;
    out.recorded_position_mm = static_cast<double>(counts_at(last)) * resolution_mm;
    out.recorded_speed_mm_s = speed_at(time_of(last));
    out.p1_mm = static_cast<double>(counts_at(0)) * resolution_mm;
    out.p2_mm = static_cast<double>(counts_at(1)) * resolution_mm;

    const auto set = [&](CompensationMethod method, double position_mm) {
        out.methods[static_cast<std::size_t>(method)] = {method, position_mm,
                                                         position_mm - out.trigger_position_mm};
    };
    set(CompensationMethod::uncompensated, out.recorded_position_mm);
    set(CompensationMethod::naive_v_tau,
        compensate_naive_mm(out.recorded_position_mm, setup.direction, v, out.naive_delay_s));
    set(CompensationMethod::cycle_lag,
        compensate_cycle_lag_mm(
            out.recorded_position_mm, ring,
            static_cast<std::size_t>(setup.compensated_lag_cycles.value_or(lag)),
            setup.counts_per_mm));
    set(CompensationMethod::timestamp,
        interpolate_trigger_mm(out.p1_mm, out.p2_mm, out.dt_s, period));
    return out;
}

std::vector<BrakingRow> sweep_braking(const CompensationSetup& setup,
                                      std::span<const double> speed_fractions) {
    std::vector<BrakingRow> rows;
    rows.reserve(speed_fractions.size());
    CompensationSetup braking = setup;
    braking.touch = TouchMotion::braking;
    for (const double fraction : speed_fractions) {
        braking.braking_speed_fraction = fraction;
        const auto comparison = simulate_compensation(braking);
        BrakingRow row;
        row.speed_fraction = fraction;
        row.trigger_speed_mm_s = comparison.trigger_speed_mm_s;
        for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
            row.error_mm[m] = comparison.methods[m].error_mm;
        }
        rows.push_back(row);
    }
    return rows;
}

std::vector<LagRow> sweep_compensated_lag(const CompensationSetup& setup) {
    std::vector<LagRow> rows;
    rows.reserve(IncrementRing::kCapacity);
    CompensationSetup with = setup;
    for (int n = 0; n < static_cast<int>(IncrementRing::kCapacity); ++n) {
        with.compensated_lag_cycles = n;
        rows.push_back(
            {n, simulate_compensation(with).result(CompensationMethod::cycle_lag).error_mm});
    }
    return rows;
}

}  // namespace probecycle
