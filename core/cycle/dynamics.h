#pragma once

// Controller dynamics after interpolation (docs/model.md, "Controller dynamics
// after interpolation"): the interpolator's command passes an acc/dec filter
// after interpolation, then the servo, before it is the axis's actual motion.
//
//   command x_c --> filter (moving averages or a first-order lag) --> servo
//   (first-order lag, Tp = 1/Kv) --> actual x_a
//
// Every stage is linear and time-invariant with a non-negative impulse
// response of unit area, so the actual position is the command convolved
// with one kernel h, it is monotone wherever the command is, and it drains to
// the command's end. The command is piecewise constant-jerk (motion.h): a sum
// of ramps r_n(t - t_k) = (t - t_k)^n / n! (n = 1 speed steps, 2 acceleration
// steps, 3 jerk steps) started at its breaks t_k. The response to each is in
// closed form:
//   - a first-order lag T turns r_m into sum_k (-T)^k r_(m-k) - (-T)^m e^(-t/T);
//     two lags T1 != T2 into (T1 L_T1 - T2 L_T2) / (T1 - T2); two equal ones
//     into sum_p (p+1)(-T)^p r_(m-p) - (-T)^m (m + 1 + t/T) e^(-t/T);
//   - a moving average over W turns any response g_n into
//     (g_(n+1)(t) - g_(n+1)(t - W)) / W (its integral's difference).
// Once a break lies further back than the moving averages' windows, the sum
// of the polynomial parts of its response is the moment expansion of the
// command, x - mu1 v + mu2 a - mu3 j (mu_k = M_k / k!, M_k the kernel's
// moments: W^k/(k+1) for a moving average, k! T^k for a lag); only the
// decaying exponentials are summed break by break. That keeps the sum free of
// cancellation on long moves, and no time stepping is involved.

#include <array>
#include <cstddef>

#include "core/cycle/motion.h"

namespace probecycle {

enum class FilterKind { none, linear, exponential, bell };
const char* to_string(FilterKind kind);

struct AxisDynamics {
    FilterKind filter{FilterKind::none};
    double filter_time_s{0.03};         // linear: window; exponential: time constant; bell: T1
    double filter2_time_s{0.01};        // bell: the second window T2
    double servo_time_constant_s{0.0};  // Tp = 1/Kv; 0 = the axis follows the command
    // In-position width: a block counts as done when the following error
    // (command end - actual) is under it.
    double in_position_mm{0.01};

    bool operator==(const AxisDynamics&) const = default;

    // False for the ideal axis (no filter, no servo lag): then the actual
    // motion is the command and the plans of motion.h are used as they are.
    bool active() const;
    // The actual position's lag behind the command at constant speed, in
    // time: W/2 (linear), T (exponential), (T1 + T2)/2 (bell), plus Tp.
    double lag_s() const;
};

// The kernel of a set of dynamics, prepared once for many evaluations.
class AxisKernel {
  public:
    AxisKernel() = default;
    explicit AxisKernel(const AxisDynamics& dynamics);

    bool active() const { return fir_count_ + lag_count_ > 0; }
    // Normalised moments mu_k = M_k / k! of the whole kernel (mu_1 = lag_s).
    double moment(int k) const { return moment_[static_cast<std::size_t>(k)]; }
    // Sum of the moving averages' windows: a break further back than this
    // has a polynomial response plus decaying exponentials only.
    double window_s() const { return window_s_; }
    // Sum of the first-order lags' time constants (0 without lags).
    double lag_time_s() const { return lag_sum_s_; }
    // The age past which a break's response is the moment expansion alone:
    // its decaying parts are exactly 0 there (past kNegligibleDecay time
    // constants of the slowest lag beyond the windows; the windows alone
    // without lags). A motion all of whose breaks are older is the command's
    // moment expansion, the same at any later time up to a shift.
    double settled_age_s() const { return settled_age_s_; }
    double in_position_mm() const { return in_position_mm_; }

    // Adds to `position` and `speed` the response at age tau > 0 to the steps
    // of one break (speed, acceleration, jerk: the ramps r_1, r_2, r_3), or
    // with `transient_only` its decaying part alone (for tau >= window_s(),
    // where the polynomial part is the moment expansion).
    void accumulate(const std::array<double, 3>& steps, double tau, bool transient_only,
                    double& position, double& speed) const;

    // The decaying part of a response once its breaks are settled (age >=
    // window_s()), by exponential: s after where its parts were taken it is
    //   a1 e^(-s/T1) + a2 e^(-s/T2) + b s e^(-s/T1)
    // (b for two equal lags only), so a tail is solved without the breaks.
    struct TailParts {
        double a1{0.0};
        double a2{0.0};
        double b{0.0};
    };
    // Adds the parts of one break's steps (speed, acceleration, jerk) taken
    // where it settles, from the unit steps' parts prepared with the kernel.
    void accumulate_settled(const std::array<double, 3>& steps, TailParts& parts) const;
    // Position, speed and acceleration of a tail at s >= 0 after where its
    // parts were taken (one pair of exponentials for all three).
    KinematicState tail_state(const TailParts& parts, double s) const;
    // The same tail's parts taken `s` >= 0 later.
    TailParts shifted(const TailParts& parts, double s) const;
    int lag_count() const { return lag_count_; }

  private:
    struct Decay {
        double e1{0.0};  // exp(-tau / T1)
        double e2{0.0};  // exp(-tau / T2)
    };
    Decay decay(double tau) const;
    // The lags alone on r_m at age tau > 0: the polynomial part, and the
    // transient split by exponential as in TailParts (its value a1 + a2).
    double lag_polynomial(int m, double tau) const;
    TailParts lag_transient_parts(int m, double tau, const Decay& d) const;
    double lag_transient(int m, double tau, const Decay& d) const;

    int fir_count_{0};
    std::array<double, 2> window_{};
    int lag_count_{0};
    std::array<double, 2> lag_{};
    std::array<double, 2> rate_{};  // 1 / lag_: the exponentials' rates
    double slow_rate_{0.0};         // the smaller rate (0 without lags)
    bool double_pole_{false};
    // A moving average over W turns a response g into (G(t) - G(t - W)) / W,
    // G its integral (the response to the next ramp): one term per subset of
    // the windows, at the age less the subset's windows, weighted by its sign
    // over the windows' product (one term, shift 0 and weight 1, without).
    int term_count_{1};
    std::array<double, 4> term_shift_{};
    std::array<double, 4> term_weight_{1.0, 0.0, 0.0, 0.0};
    std::array<double, 6> lag_moment_{1.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // of the lags alone
    // The parts of a unit speed, acceleration and jerk step at age window_s_.
    std::array<TailParts, 3> settled_parts_{};
    std::array<double, 4> moment_{1.0, 0.0, 0.0, 0.0};
    double window_s_{0.0};
    double lag_sum_s_{0.0};
    double settled_age_s_{0.0};
    double in_position_mm_{0.01};
};

// The command of one block (a move, or a touch from its start to its stop),
// as breaks where its speed, acceleration or jerk changes, starting at rest
// at position 0 and time 0.
class AxisCommand {
  public:
    struct Break {
        double t_s;
        std::array<double, 3> step;  // of speed, acceleration, jerk
        KinematicState after;        // the command's state just after the break
        double jerk_after;
    };

    AxisCommand() = default;
    // Copies the breaks there are (commands are copied into every motion).
    AxisCommand(const AxisCommand& other) { *this = other; }
    AxisCommand& operator=(const AxisCommand& other);

    // Appends `duration_s` of the plan (cut there if shorter than the plan).
    void append(const SegmentPlan& plan, double duration_s);
    // Brings the command to rest at its current position (a break that cancels
    // speed, acceleration and jerk).
    void close();

    double end_s() const { return t_s_; }
    const KinematicState& end_state() const { return state_; }  // where the command is now
    std::size_t size() const { return count_; }
    const Break& at(std::size_t i) const { return breaks_[i]; }

  private:
    void add_break(double speed, double accel, double jerk);

    // Only breaks_[0, count_) are set: Break has no initialisers, so a
    // command is not 800 bytes of zeros to write and copy.
    std::array<Break, 12> breaks_;
    std::size_t count_{0};
    double t_s_{0.0};
    KinematicState state_{};
    double jerk_{0.0};
};

// The actual position and speed at `t_s` once every break up to `last` is
// older than the windows and no later break has come: the polynomial part of
// the response, the moment expansion x - mu1 v + mu2 a - mu3 j of the command
// (past kernel.settled_age_s() it is the whole response).
inline KinematicState moment_expansion(const AxisKernel& kernel, const AxisCommand::Break& last,
                                       double t_s) {
    const KinematicState c = integrate(t_s - last.t_s, last.after, last.jerk_after);
    const double mu1 = kernel.moment(1);
    const double mu2 = kernel.moment(2);
    const double mu3 = kernel.moment(3);
    KinematicState out;
    out.position_mm =
        c.position_mm - mu1 * c.speed_mm_s + mu2 * c.accel_mm_s2 - mu3 * last.jerk_after;
    out.speed_mm_s = c.speed_mm_s - mu1 * c.accel_mm_s2 + mu2 * last.jerk_after;
    return out;
}

// The actual motion of a command through a kernel.
class AxisMotion {
  public:
    AxisMotion() = default;
    AxisMotion(const AxisKernel& kernel, const AxisCommand& command);
    // The same kernel on another command; the breaks it shares with the
    // current one from the start keep their decaying parts (a touch is its
    // approach cut where the axis reacts, then stopped).
    void reset(const AxisCommand& command);

    // Actual position and speed at time t (acceleration is not computed).
    KinematicState state(double t_s) const;
    // First time the actual position reaches `position_mm`, for a command
    // that never moves backward and goes on at least that far; `guess_s` a
    // time near it.
    double time_at_position(double position_mm, double guess_s) const;
    // The same, with the actual state there (`at`), which the solve has
    // mostly evaluated already.
    double time_at_position(double position_mm, double guess_s, KinematicState& at) const;
    // First time from the command's end at which the following error is
    // under the in-position width (a closed command).
    double in_position_time() const;
    // First time the actual speed is within `deficit_mm_s` of the command's
    // (an open command cruising at the end).
    double time_at_speed_deficit(double deficit_mm_s, double guess_s) const;

    const AxisCommand& command() const { return command_; }

  private:
    // prefix_ from break `first` on.
    void sum_prefix(std::size_t first);
    // The tail of all breaks at t_ref (every one settled by then: t_ref at
    // least the last break's time plus window_s()).
    AxisKernel::TailParts tail_at(double t_ref) const;
    // The first s >= 0 at which the tail's error (or, with `speed`, its speed
    // deficit) is down to `level`.
    double tail_root(const AxisKernel::TailParts& parts, double level, bool speed) const;

    AxisKernel kernel_{};
    AxisCommand command_{};
    // The decaying parts of breaks 0..i, taken where break i has settled (at
    // t_i + window_s(); with lags alone at t_i), so that a state needs one
    // pair of exponentials for all the settled breaks behind it.
    std::array<AxisKernel::TailParts, 12> prefix_{};
};

}  // namespace probecycle
