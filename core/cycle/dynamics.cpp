#include "core/cycle/dynamics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

// Formulas: dynamics.h and docs/model.md, "Controller dynamics after
// interpolation". The first-order lag's response to a ramp r_m solves
// y' = (r_m - y) / T from rest: the particular solution sum_k (-T)^k r_(m-k)
// plus the homogeneous term that makes y(0) = 0.

namespace probecycle {

const char* to_string(FilterKind kind) {
    switch (kind) {
        case FilterKind::none:
            return "none";
        case FilterKind::linear:
            return "linear";
        case FilterKind::exponential:
            return "exponential";
        case FilterKind::bell:
            return "bell";
    }
    return "?";
}

bool AxisDynamics::active() const {
    return filter != FilterKind::none || servo_time_constant_s > 0.0;
}

double AxisDynamics::lag_s() const {
    double lag = servo_time_constant_s;
    switch (filter) {
        case FilterKind::none:
            break;
        case FilterKind::linear:
            lag += 0.5 * filter_time_s;
            break;
        case FilterKind::exponential:
            lag += filter_time_s;
            break;
        case FilterKind::bell:
            lag += 0.5 * (filter_time_s + filter2_time_s);
            break;
    }
    return lag;
}

namespace {

// Decay exponents beyond this are negligible (AxisKernel::decay).
constexpr double kNegligibleDecay = 60.0;

double power(double x, int p) {
    double value = 1.0;
    for (int i = 0; i < p; ++i) value *= x;
    return value;
}

// 1 / p! for the ramps r_p a kernel meets: up to r_5, a jerk step's r_3
// integrated once for each of two moving averages. (A table, not divisions:
// the ramps are summed for every break in every state.)
constexpr std::array<double, 6> kInverseFactorial = {1.0,       1.0,        1.0 / 2.0,
                                                     1.0 / 6.0, 1.0 / 24.0, 1.0 / 120.0};

// tau^p / p! for 0 <= p <= 5.
double ramp(int p, double tau) {
    return power(tau, p) * kInverseFactorial[static_cast<std::size_t>(p)];
}

}  // namespace

AxisKernel::AxisKernel(const AxisDynamics& d) : in_position_mm_(d.in_position_mm) {
    if (!d.active()) return;  // the ideal axis: the identity kernel
    switch (d.filter) {
        case FilterKind::none:
            break;
        case FilterKind::linear:
            window_[fir_count_++] = d.filter_time_s;
            break;
        case FilterKind::bell:
            window_[fir_count_++] = d.filter_time_s;
            window_[fir_count_++] = d.filter2_time_s;
            break;
        case FilterKind::exponential:
            lag_[lag_count_++] = d.filter_time_s;
            break;
    }
    if (d.servo_time_constant_s > 0.0) lag_[lag_count_++] = d.servo_time_constant_s;
    for (int i = 0; i < fir_count_; ++i) window_s_ += window_[static_cast<std::size_t>(i)];
    double norm = 1.0;
    for (int f = 0; f < fir_count_; ++f) norm *= window_[static_cast<std::size_t>(f)];
    term_count_ = 1 << fir_count_;
    for (int subset = 0; subset < term_count_; ++subset) {
        double shift = 0.0;
        double sign = 1.0;
        for (int f = 0; f < fir_count_; ++f) {
            if ((subset & (1 << f)) != 0) {
                shift += window_[static_cast<std::size_t>(f)];
                sign = -sign;
            }
        }
        term_shift_[static_cast<std::size_t>(subset)] = shift;
        term_weight_[static_cast<std::size_t>(subset)] = sign / norm;
    }
    for (int i = 0; i < lag_count_; ++i) {
        lag_sum_s_ += lag_[static_cast<std::size_t>(i)];
        rate_[static_cast<std::size_t>(i)] = 1.0 / lag_[static_cast<std::size_t>(i)];
    }
    slow_rate_ = lag_count_ == 2 ? std::min(rate_[0], rate_[1]) : rate_[0];
    // decay() drops an age tau - shift with (tau - shift) * slow_rate_ >
    // kNegligibleDecay; one time constant more keeps the test clear of rounding.
    settled_age_s_ = window_s_ + (lag_count_ > 0 ? (kNegligibleDecay + 1.0) / slow_rate_ : 0.0);
    // Two lags closer than this are one double pole: the partial fractions
    // would divide by their difference.
    double_pole_ =
        lag_count_ == 2 && std::abs(lag_[0] - lag_[1]) <= 1e-9 * std::max(lag_[0], lag_[1]);

    // Normalised moments mu_k = M_k / k! convolve as sequences: a lag has T^k,
    // two lags sum_i T1^i T2^(k-i), a moving average W^k / (k+1)!.
    for (std::size_t k = 0; k < lag_moment_.size(); ++k) {
        double mu = k == 0 ? 1.0 : 0.0;
        if (lag_count_ == 1) mu = power(lag_[0], static_cast<int>(k));
        if (lag_count_ == 2) {
            mu = 0.0;
            for (std::size_t i = 0; i <= k; ++i) {
                mu += power(lag_[0], static_cast<int>(i)) * power(lag_[1], static_cast<int>(k - i));
            }
        }
        lag_moment_[k] = mu;
    }
    std::array<double, 4> mu{};
    for (std::size_t k = 0; k < mu.size(); ++k) mu[k] = lag_moment_[k];
    for (int f = 0; f < fir_count_; ++f) {
        const double w = window_[static_cast<std::size_t>(f)];
        std::array<double, 4> next{};
        for (std::size_t k = 0; k < next.size(); ++k) {
            for (std::size_t i = 0; i <= k; ++i) {
                // W^i / (i + 1)!
                next[k] += mu[k - i] * ramp(static_cast<int>(i), w) / static_cast<double>(i + 1);
            }
        }
        mu = next;
    }
    moment_ = mu;
    // The decaying parts of unit speed, acceleration and jerk steps once
    // settled (at the age window_s_): one term per subset of the windows,
    // each at the age less its shift (with lags alone, one term at age 0).
    if (lag_count_ > 0) {
        for (int n = 1; n <= 3; ++n) {
            TailParts& parts = settled_parts_[static_cast<std::size_t>(n - 1)];
            for (int k = 0; k < term_count_; ++k) {
                const double age = window_s_ - term_shift_[static_cast<std::size_t>(k)];
                const double weight = term_weight_[static_cast<std::size_t>(k)];
                const TailParts term = lag_transient_parts(n + fir_count_, age, decay(age));
                parts.a1 += weight * term.a1;
                parts.a2 += weight * term.a2;
                parts.b += weight * term.b;
            }
        }
    }
}

inline AxisKernel::Decay AxisKernel::decay(double tau) const {
    Decay d;
    if (tau == 0.0) {  // a tail's start, asked once per root: no exponentials
        d.e1 = lag_count_ >= 1 ? 1.0 : 0.0;
        d.e2 = lag_count_ == 2 ? 1.0 : 0.0;
        return d;
    }
    // Past kNegligibleDecay time constants of the slowest lag every
    // exponential is under e^-60 (1e-26): its terms are below the rounding of
    // any position, so they are 0 without calling exp (on a slow approach the
    // breaks lie hundreds of time constants back).
    if (tau * slow_rate_ > kNegligibleDecay) return d;
    if (lag_count_ >= 1) d.e1 = std::exp(-tau * rate_[0]);
    if (lag_count_ == 2) d.e2 = double_pole_ ? d.e1 : std::exp(-tau * rate_[1]);
    return d;
}

inline AxisKernel::TailParts AxisKernel::lag_transient_parts(int m, double tau,
                                                             const Decay& d) const {
    TailParts parts;
    if (lag_count_ == 0) return parts;
    const double t1 = lag_[0];
    if (lag_count_ == 1) {
        parts.a1 = -power(-t1, m) * d.e1;
    } else if (double_pole_) {
        parts.a1 = -power(-t1, m) * (m + 1 + tau / t1) * d.e1;
        parts.b = -power(-t1, m) * d.e1 / t1;  // the s in (m + 1 + (tau + s)/T)
    } else {
        const double t2 = lag_[1];
        parts.a1 = power(-t1, m + 1) * d.e1 / (t1 - t2);
        parts.a2 = -power(-t2, m + 1) * d.e2 / (t1 - t2);
    }
    return parts;
}

inline double AxisKernel::lag_transient(int m, double tau, const Decay& d) const {
    const TailParts parts = lag_transient_parts(m, tau, d);
    return parts.a1 + parts.a2;
}

double AxisKernel::lag_polynomial(int m, double tau) const {
    // The moment expansion sum_k (-1)^k mu_k r_(m-k), by Horner in tau: the
    // coefficient of tau^j is (-1)^(m-j) mu_(m-j) / j!.
    double poly = 0.0;
    for (int j = m; j >= 0; --j) {
        const double mu = lag_moment_[static_cast<std::size_t>(m - j)];
        poly = poly * tau +
               ((m - j) % 2 == 0 ? mu : -mu) * kInverseFactorial[static_cast<std::size_t>(j)];
    }
    return poly;
}

void AxisKernel::accumulate(const std::array<double, 3>& steps, double tau, bool transient_only,
                            double& position, double& speed) const {
    if (transient_only && lag_count_ == 0) return;
    for (int k = 0; k < term_count_; ++k) {
        const double age = tau - term_shift_[static_cast<std::size_t>(k)];
        const double weight = term_weight_[static_cast<std::size_t>(k)];
        // Causal: nothing before the (shifted) break; the transient alone is
        // asked for ages >= 0 only.
        if (age < 0.0 || (age == 0.0 && !transient_only)) continue;
        const Decay d = decay(age);
        for (int n = 1; n <= 3; ++n) {
            const double step = steps[static_cast<std::size_t>(n - 1)];
            if (step == 0.0) continue;
            const int m = n + fir_count_;
            double g = lag_transient(m, age, d);
            double dg = lag_transient(m - 1, age, d);
            if (!transient_only) {
                g += lag_polynomial(m, age);
                dg += lag_polynomial(m - 1, age);
            }
            position += weight * step * g;
            speed += weight * step * dg;
        }
    }
}

void AxisKernel::accumulate_settled(const std::array<double, 3>& steps, TailParts& parts) const {
    for (std::size_t n = 0; n < steps.size(); ++n) {
        if (steps[n] == 0.0) continue;
        parts.a1 += steps[n] * settled_parts_[n].a1;
        parts.a2 += steps[n] * settled_parts_[n].a2;
        parts.b += steps[n] * settled_parts_[n].b;
    }
}

// The tails' exponentials are decay(s): e2 is 0 with one lag and unused
// (a2 = 0) with a double pole.
KinematicState AxisKernel::tail_state(const TailParts& p, double s) const {
    KinematicState out;
    if (lag_count_ == 0) return out;
    const Decay d = decay(s);
    const double r1 = rate_[0];
    const double r2 = lag_count_ == 2 ? rate_[1] : 1.0;
    const double first = p.a1 + p.b * s;
    out.position_mm = first * d.e1 + p.a2 * d.e2;
    out.speed_mm_s = (p.b - first * r1) * d.e1 - p.a2 * r2 * d.e2;
    out.accel_mm_s2 = (first * r1 - 2.0 * p.b) * r1 * d.e1 + p.a2 * r2 * r2 * d.e2;
    return out;
}

AxisKernel::TailParts AxisKernel::shifted(const TailParts& p, double s) const {
    // (a1 + b (s + s')) e^(-(s + s')/T1) = ((a1 + b s) + b s') e^(-s/T1) e^(-s'/T1).
    const Decay d = decay(s);
    return {(p.a1 + p.b * s) * d.e1, p.a2 * d.e2, p.b * d.e1};
}

AxisCommand& AxisCommand::operator=(const AxisCommand& other) {
    if (this == &other) return *this;
    std::copy_n(other.breaks_.begin(), other.count_, breaks_.begin());
    count_ = other.count_;
    t_s_ = other.t_s_;
    state_ = other.state_;
    jerk_ = other.jerk_;
    return *this;
}

void AxisCommand::add_break(double speed, double accel, double jerk) {
    const std::array<double, 3> step = {speed - state_.speed_mm_s, accel - state_.accel_mm_s2,
                                        jerk - jerk_};
    if (step[0] == 0.0 && step[1] == 0.0 && step[2] == 0.0) return;
    state_.speed_mm_s = speed;
    state_.accel_mm_s2 = accel;
    jerk_ = jerk;
    if (count_ > 0 && breaks_[count_ - 1].t_s == t_s_) {
        // Two changes at one instant are one break.
        Break& last = breaks_[count_ - 1];
        for (std::size_t i = 0; i < step.size(); ++i) last.step[i] += step[i];
        last.after = state_;
        last.jerk_after = jerk_;
        return;
    }
    if (count_ == breaks_.size()) return;  // cannot happen: plans have at most 7 segments
    breaks_[count_++] = {t_s_, step, state_, jerk_};
}

void AxisCommand::append(const SegmentPlan& plan, double duration_s) {
    double remaining = duration_s;
    for (std::size_t i = 0; i < plan.count && remaining > 0.0; ++i) {
        const Segment& seg = plan.segments[i];
        const double speed = seg.step_speed_mm_s >= 0.0 ? seg.step_speed_mm_s : state_.speed_mm_s;
        add_break(speed, seg.accel_mm_s2, seg.jerk_mm_s3);
        const double dt = std::min(seg.duration_s, remaining);
        state_ = integrate(dt, state_, jerk_);
        t_s_ += dt;
        remaining -= dt;
    }
}

void AxisCommand::close() {
    add_break(0.0, 0.0, 0.0);
}

AxisMotion::AxisMotion(const AxisKernel& kernel, const AxisCommand& command)
    : kernel_(kernel), command_(command) {
    sum_prefix(0);
}

void AxisMotion::reset(const AxisCommand& command) {
    std::size_t same = 0;
    const std::size_t shared = std::min(command.size(), command_.size());
    while (same < shared && command.at(same).t_s == command_.at(same).t_s &&
           command.at(same).step == command_.at(same).step) {
        ++same;
    }
    command_ = command;
    sum_prefix(same);
}

void AxisMotion::sum_prefix(std::size_t first) {
    if (kernel_.lag_count() == 0) return;  // moving averages alone settle without a tail
    for (std::size_t i = first; i < command_.size(); ++i) {
        const AxisCommand::Break& b = command_.at(i);
        AxisKernel::TailParts parts;
        if (i > 0) parts = kernel_.shifted(prefix_[i - 1], b.t_s - command_.at(i - 1).t_s);
        kernel_.accumulate_settled(b.step, parts);
        prefix_[i] = parts;
    }
}

KinematicState AxisMotion::state(double t_s) const {
    if (t_s <= 0.0) return {};
    const std::size_t count = command_.size();
    const double window = kernel_.window_s();
    // Breaks further back than the windows (with lags alone, every break up
    // to t): the moment expansion of the command they make, plus their
    // decaying parts, summed once per motion (prefix_).
    std::size_t settled = 0;
    while (settled < count && t_s - command_.at(settled).t_s >= window) ++settled;
    KinematicState out;
    if (settled > 0) {
        const AxisCommand::Break& b = command_.at(settled - 1);
        out = moment_expansion(kernel_, b, t_s);
        if (kernel_.lag_count() > 0) {
            const KinematicState tail =
                kernel_.tail_state(prefix_[settled - 1], t_s - b.t_s - window);
            out.position_mm += tail.position_mm;
            out.speed_mm_s += tail.speed_mm_s;
        }
    }
    for (std::size_t i = settled; i < count; ++i) {
        const AxisCommand::Break& b = command_.at(i);
        if (t_s <= b.t_s) break;
        kernel_.accumulate(b.step, t_s - b.t_s, false, out.position_mm, out.speed_mm_s);
    }
    // Commands here never move backward, and the kernel is non-negative: what
    // falls below zero is rounding in the sums.
    out.position_mm = std::max(out.position_mm, 0.0);
    out.speed_mm_s = std::max(out.speed_mm_s, 0.0);
    return out;
}

namespace {

// A root of an increasing f from `t` (f(lo) < 0 at `lo`), by the steps
// `eval(t) -> {f, step}` proposes (Newton's), kept inside the bracket once
// one is known, else bisection; before a point with f >= 0 is found, a
// step that does not advance doubles the distance from `lo` instead (at
// least `scale`, the time over which f changes). A step under
// `step_tolerance` (relative to max(1, t)) is the last: Newton converges
// quadratically there, so the root's error is of the order step^2 / scale.
template <typename Eval>
double safeguarded_root(double lo, double t, double f_tolerance, double step_tolerance,
                        double scale, Eval eval) {
    double hi = std::numeric_limits<double>::infinity();
    for (int iter = 0; iter < 200; ++iter) {
        const auto [f, step] = eval(t);
        if (std::abs(f) <= f_tolerance) return t;
        if (f > 0.0) {
            hi = t;
        } else {
            lo = t;
        }
        double next = t + step;
        const bool bracketed = std::isfinite(hi);
        if (!(next > lo) || (bracketed && !(next < hi)) || !std::isfinite(next)) {
            next = bracketed ? 0.5 * (lo + hi) : lo + std::max(2.0 * (t - lo), scale);
        } else if (std::abs(step) <= step_tolerance * std::max(1.0, t)) {
            return next;
        }
        if (bracketed && hi - lo <= 1e-15 * std::max(1.0, hi)) return hi;
        t = next;
    }
    return std::isfinite(hi) ? hi : t;
}

// The Newton step in time that brings a decaying `value` (falling at `rate`)
// down to `level`: on log(value / level) while the value is far from the
// level (exact in one step for a single exponential), within a factor of 1.5
// of it on the value itself, which converges as fast without a logarithm.
// (The band is tested without dividing, so the branch does not wait for it.)
double decay_step(double value, double rate, double level) {
    if (!(value > 0.0 && rate > 0.0)) return 0.0;
    if (1.5 * value > level && value < 1.5 * level) return (value - level) / rate;
    return value / rate * std::log(value / level);
}

}  // namespace

double AxisMotion::time_at_position(double position_mm, double guess_s) const {
    KinematicState at;
    return time_at_position(position_mm, guess_s, at);
}

double AxisMotion::time_at_position(double position_mm, double guess_s, KinematicState& at) const {
    if (position_mm <= 0.0) {
        at = {};
        return 0.0;
    }
    const double scale = std::max(kernel_.window_s() + kernel_.lag_time_s(), 1e-6);
    // Positions set the overtravel and the recorded trigger, which the
    // published checks compare to 1e-14 mm: a last step under 1e-7 s leaves
    // an error under 1e-12 s.
    double last_t = -1.0;
    const double t =
        safeguarded_root(0.0, std::max(guess_s, 1e-9), 1e-12 * std::max(1.0, position_mm), 1e-7,
                         scale, [&](double t_s) {
                             at = state(t_s);
                             last_t = t_s;
                             const double f = at.position_mm - position_mm;
                             const double step = at.speed_mm_s > 0.0 ? -f / at.speed_mm_s : 0.0;
                             return std::pair{f, step};
                         });
    if (t != last_t) at = state(t);
    return t;
}

double AxisMotion::in_position_time() const {
    const double t_end = command_.end_s();
    const double x_end = command_.end_state().position_mm;
    const double width = kernel_.in_position_mm();
    // f = width - error rises through 0. The tail is a sum of decaying
    // exponentials (decay_step).
    const auto eval = [&](double t) {
        const KinematicState s = state(t);
        const double e = x_end - s.position_mm;
        return std::pair{width - e, decay_step(e, s.speed_mm_s, width)};
    };
    const double t_ref = t_end + kernel_.window_s();
    if (kernel_.lag_count() > 0 && t_ref == t_end) {
        // Lags alone: every break has settled at the command's end, and the
        // error is the tail's.
        return t_end + tail_root(tail_at(t_end), width, false);
    }
    const auto [f_end, step_end] = eval(t_end);
    if (f_end >= 0.0) return t_end;
    if (kernel_.lag_count() > 0 && eval(t_ref).first < 0.0) {
        // Still out of position when every break has settled: the error is
        // the tail alone, solved without the breaks.
        return t_ref + tail_root(tail_at(t_ref), width, false);
    }
    const double first = t_end + step_end;
    return safeguarded_root(t_end, first > t_end ? first : t_end, 1e-12 * width, 1e-7,
                            std::max(kernel_.window_s() + kernel_.lag_time_s(), 1e-6), eval);
}

AxisKernel::TailParts AxisMotion::tail_at(double t_ref) const {
    if (kernel_.lag_count() == 0 || command_.size() == 0) return {};
    const std::size_t last = command_.size() - 1;
    return kernel_.shifted(prefix_[last], t_ref - command_.at(last).t_s - kernel_.window_s());
}

double AxisMotion::tail_root(const AxisKernel::TailParts& parts, double level, bool speed) const {
    // The remaining error (position) or speed deficit is minus the tail's
    // position or speed: decaying exponentials, so Newton runs on
    // log(value / level) (decay_step).
    const auto eval = [&](double s) {
        const KinematicState tail = kernel_.tail_state(parts, s);
        const double value = speed ? -tail.speed_mm_s : -tail.position_mm;
        const double rate = speed ? tail.accel_mm_s2 : tail.speed_mm_s;  // -d/ds value
        const double f = level - value;
        return std::pair{f, decay_step(value, rate, level)};
    };
    const auto [f0, step0] = eval(0.0);
    if (f0 >= 0.0) return 0.0;
    // A tail's root is a phase's end time: a last step under 1e-6 s leaves an
    // error of the order 1e-12 / T s, a nanosecond at the least T.
    return safeguarded_root(0.0, step0 > 0.0 ? step0 : 0.0, 1e-12 * level, 1e-6,
                            std::max(kernel_.lag_time_s(), 1e-6), eval);
}

double AxisMotion::time_at_speed_deficit(double deficit_mm_s, double guess_s) const {
    const double target = command_.end_state().speed_mm_s - deficit_mm_s;
    if (target <= 0.0) return 0.0;
    const auto f = [&](double t) { return state(t).speed_mm_s - target; };
    if (kernel_.lag_count() > 0 && command_.size() > 0) {
        // Cruising once every break has settled: the deficit is the tail's.
        const double t_ref = command_.at(command_.size() - 1).t_s + kernel_.window_s();
        if (f(t_ref) < 0.0) return t_ref + tail_root(tail_at(t_ref), deficit_mm_s, true);
        guess_s = t_ref;
    }
    double lo = 0.0;
    double hi = std::max(guess_s, 1e-6);
    for (int i = 0; i < 200 && f(hi) < 0.0; ++i) {
        lo = hi;
        hi *= 2.0;
    }
    // Illinois regula falsi: the speed has no cheap derivative here.
    double f_lo = f(lo);
    double f_hi = f(hi);
    int side = 0;
    for (int iter = 0; iter < 100 && hi - lo > 1e-12 * std::max(1.0, hi); ++iter) {
        const double t =
            f_hi - f_lo > 0.0 ? (lo * f_hi - hi * f_lo) / (f_hi - f_lo) : 0.5 * (lo + hi);
        const double ft = f(t);
        if (ft >= 0.0) {
            hi = t;
            f_hi = ft;
            if (side == 1) f_lo *= 0.5;
            side = 1;
        } else {
            lo = t;
            f_lo = ft;
            if (side == -1) f_hi *= 0.5;
            side = -1;
        }
        if (ft == 0.0) return t;
    }
    return hi;
}

}  // namespace probecycle
