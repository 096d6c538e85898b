#include "core/optimise/optimiser.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "core/common/input_error.h"
#include "core/common/task_group.h"
#include "core/common/units.h"
#include "core/cycle/motion_cache.h"
#include "core/cycle/uncertainty.h"

namespace probecycle {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The lowest feed a scenario allows (cycle.probe_feed_mm_min's minimum).
constexpr double kMinFeed_mm_min = 1.0;
// Uncertainties equal but for their last bits meet a bound (the current
// scenario's uncertainty is the bound when there is no target).
constexpr double kUncertaintyRelTolerance = 1e-12;

// The start distance rounded up to kApproachStep_mm, strictly: never under
// `distance_mm` (round_up_to forgives a millionth of a step, which the start
// rule's check would not).
double approach_up(double distance_mm) {
    double steps = std::ceil(distance_mm / kApproachStep_mm);
    double rounded = steps / 100.0;
    while (rounded < distance_mm) rounded = ++steps / 100.0;
    return rounded;
}
static_assert(kApproachStep_mm == 0.01, "approach_up divides by 100");

// The highest feed a setting may use: the probe's rated maximum (when set),
// the machine's rapid feed, the key's range.
double feed_cap_mm_min(const Scenario& scenario) {
    double cap =
        std::min(scenario.machine.rapid_feed_mm_min, find_key("cycle.probe_feed_mm_min")->max);
    if (scenario.probe.max_feed_mm_min > 0.0) cap = std::min(cap, scenario.probe.max_feed_mm_min);
    return cap;
}

// The largest start distance a bore or pocket allows (validate(): the
// feature wider than two approaches), on the 0.01 mm grid; the key's maximum
// for the rest.
// The start rule: a start at least the part position uncertainty
// plus the room to reach the probing feed (approach_room_mm), and never
// closer than cycle.min_start_mm: no engineer starts a touch 10 um from a
// wall whose place is known only to a casting's tolerance.
double start_rule_mm(const Scenario& scenario, double probe_feed_mm_min) {
    return std::max(scenario.cycle.min_start_mm,
                    scenario.cycle.part_position_uncertainty_mm +
                        approach_room_mm(scenario, mm_min_to_mm_s(probe_feed_mm_min)));
}

double approach_max_mm(const Cycle& cycle) {
    const double key_max = find_key("cycle.approach_mm")->max;
    if (!is_internal(cycle.feature)) return key_max;
    double steps = std::ceil(cycle.feature_size_mm * 50.0) - 1.0;
    while (steps >= 0.0 && !(cycle.feature_size_mm > 2.0 * (steps / 100.0))) steps -= 1.0;
    return std::min(key_max, steps / 100.0);
}

// The model's uncertainty of N averaged measuring touches at speed v (the
// uncertainty budget of docs/model.md, "One touch", F its fixed terms):
// U(v, N)^2 = F^2 +
// expanded_uncertainty_mm(scan_range_mm(machine, v), rep)^2 / N, solved for
// the highest measuring feed whose U meets `bound_mm`;
// kInf when every feed does, a negative value when none does. A first guess
// only: the search checks the evaluated uncertainty (which, before the model
// averaged repeats, is not divided by sqrt(N)).
double closed_form_measure_feed_bound(const Scenario& scenario, int repeats, double bound_mm) {
    if (!std::isfinite(bound_mm)) return kInf;
    const double rep = scenario.probe.repeatability_2sigma_mm;
    const double fixed = fixed_expanded_uncertainty_mm(scenario);
    const double slack = (bound_mm * bound_mm - fixed * fixed) * repeats - rep * rep;
    if (slack < 0.0) return -1.0;
    if (scan_range_mm(scenario.machine, 1.0) <= 0.0) return kInf;  // latched or no scan
    // expanded^2 = R^2/3 + rep^2 with R = v * t_s.
    const double range_mm = std::sqrt(3.0 * slack);
    return mm_s_to_mm_min(range_mm / scenario.machine.scan_period_s);
}

// Minimum of f over [lo, hi] on a log scale: a grid, then golden section
// between the best grid point's neighbours. f is +inf where a setting fails a
// requirement; the grid finds the feasible region, the golden section its
// best point (or its edge). Returns the best point seen.
struct Best1D {
    double x{0.0};
    double f{kInf};
};
template <class F>
Best1D minimise_log(F&& f, double lo, double hi, int grid, int golden_iterations) {
    Best1D best;
    const auto consider = [&](double x) {
        const double value = f(x);
        if (value < best.f) best = {x, value};
        return value;
    };
    if (!(hi > lo)) {
        consider(lo);
        return best;
    }
    const double log_lo = std::log(lo);
    const double log_hi = std::log(hi);
    const auto at = [&](int i) {
        return i == 0          ? lo
               : i == grid - 1 ? hi
                               : std::exp(log_lo + (log_hi - log_lo) * i / (grid - 1));
    };
    int best_i = -1;
    double best_grid = kInf;
    for (int i = 0; i < grid; ++i) {
        const double value = consider(at(i));
        if (value < best_grid) {
            best_grid = value;
            best_i = i;
        }
    }
    if (best_i < 0) return best;
    double a = std::log(at(std::max(best_i - 1, 0)));
    double b = std::log(at(std::min(best_i + 1, grid - 1)));
    constexpr double kGolden = 0.6180339887498949;
    double c = b - kGolden * (b - a);
    double d = a + kGolden * (b - a);
    double fc = consider(std::exp(c));
    double fd = consider(std::exp(d));
    // To 1e-5 of the feed: ten times finer than the editors' digits at their
    // finest (1 mm/min at 10000 mm/min), which the result is rounded to.
    for (int i = 0; i < golden_iterations && b - a > 1e-5; ++i) {
        if (fc <= fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - kGolden * (b - a);
            fc = consider(std::exp(c));
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + kGolden * (b - a);
            fd = consider(std::exp(d));
        }
    }
    return best;
}

// The highest x in [lo, hi] (log scale) where `ok` holds, for a property
// that holds below some x and fails above it; lo when none holds.
template <class Ok>
double last_ok_log(Ok&& ok, double lo, double hi) {
    if (ok(hi)) return hi;
    double a = std::log(lo);
    double b = std::log(hi);
    for (int i = 0; i < 60 && b - a > 1e-9; ++i) {
        const double m = 0.5 * (a + b);
        (ok(std::exp(m)) ? a : b) = m;
    }
    return std::exp(a);
}

// Start distance steps tried above and below the one found (see rounded()).
constexpr int kStartLevelsAbove = 2;
constexpr int kStartLevelsBelow = 8;

// The best of one strategy and repeat count under one uncertainty bound.
struct Cell {
    bool found{false};
    double probe_feed_mm_min{0.0};
    double measure_feed_mm_min{0.0};
    double time_s{kInf};
    double uncertainty_mm{0.0};
};

// The search: evaluations of settings with the backoff the cycle recommends
// and the start distances the start rule allows, and the best setting of a
// strategy and repeat count under an uncertainty bound.
class Search {
  public:
    Search(const Scenario& scenario, const CycleModel& model, double max_overtravel_fraction)
        : base_(scenario),
          scratch_(scenario),
          touch_(scenario),
          model_(model),
          overtravel_max_mm_(max_overtravel_fraction * scenario.probe.overtravel_limit_mm),
          cap_mm_min_(feed_cap_mm_min(scenario)),
          approach_max_mm_(approach_max_mm(scenario.cycle)),
          min_feed_mm_min_(std::max(kMinFeed_mm_min, scenario.cycle.min_feed_mm_min)) {
        last_backoff_mm_ = scenario.cycle.backoff_mm;
        repeats_ignored_ = detect_repeats_ignored();
        overtravel_feed_mm_min_ = feed_bound_overtravel();
        start_feed_mm_min_ = feed_bound_start();
    }

    const Scenario& base() const { return base_; }
    double cap_mm_min() const { return cap_mm_min_; }
    // The slowest feed a touch may use (cycle.min_feed_mm_min).
    double min_feed() const { return min_feed_mm_min_; }
    double overtravel_feed_mm_min() const { return overtravel_feed_mm_min_; }
    double start_feed_mm_min() const { return start_feed_mm_min_; }
    bool repeats_ignored() const { return repeats_ignored_; }
    int max_repeats() const { return repeats_ignored_ ? 1 : kMaxRepeats; }
    double overtravel_max_mm() const { return overtravel_max_mm_; }

    // The smallest start distance the start rule allows at a probing feed
    // (start_rule_mm), rounded up to the editors' digits.
    double approach_min_mm(double probe_feed_mm_min) const {
        return approach_up(start_rule_mm(base_, probe_feed_mm_min));
    }

    // Start distances worth trying at a probing feed: the start rule's
    // minimum and, in a bore or pocket, the largest the feature allows.
    // Time is close to linear in the start distance (a longer touch at the
    // probing feed against shorter positioning moves across the feature, at
    // the positioning feed) and concave where a move gets too short to reach
    // its feed, so the fastest lies at an end. Empty when none is allowed.
    int approaches(double probe_feed_mm_min, double out[2]) const {
        const double low = approach_min_mm(probe_feed_mm_min);
        if (low > approach_max_mm_) return 0;
        out[0] = low;
        if (is_internal(base_.cycle.feature) && approach_max_mm_ > low) {
            out[1] = approach_max_mm_;
            return 2;
        }
        return 1;
    }

    // Evaluates one setting (two-touch: with the backoff it recommends) into `point`.
    const ModelPoint& evaluate(Strategy strategy, int repeats, double probe_feed_mm_min,
                               double measure_feed_mm_min, double approach_mm) {
        Cycle& c = scratch_.cycle;
        c.strategy = strategy;
        c.repeats = repeats;
        c.probe_feed_mm_min = probe_feed_mm_min;
        c.approach_mm = approach_mm;
        if (strategy == Strategy::single_touch) {
            c.measure_feed_mm_min = probe_feed_mm_min;
            c.backoff_mm = 0.0;
            model_(scratch_, point_);
            return point_;
        }
        c.measure_feed_mm_min = measure_feed_mm_min;
        c.backoff_mm = last_backoff_mm_;
        model_(scratch_, point_);
        if (c.backoff_mm != point_.recommended_backoff_mm) {
            c.backoff_mm = last_backoff_mm_ = point_.recommended_backoff_mm;
            model_(scratch_, point_);
        }
        return point_;
    }

    // One single-touch surface from the start rule's distance: a touch's
    // overtravel and uncertainty at a feed do not depend on the feature, and
    // a bore's start may not fit the feed being tried.
    const ModelPoint& evaluate_touch(int repeats, double feed_mm_min) {
        Cycle& c = touch_.cycle;
        c.strategy = Strategy::single_touch;
        c.feature = Feature::surface;
        c.repeats = repeats;
        c.probe_feed_mm_min = feed_mm_min;
        c.measure_feed_mm_min = feed_mm_min;
        c.backoff_mm = 0.0;
        c.approach_mm = approach_min_mm(feed_mm_min);
        model_(touch_, point_);
        return point_;
    }

    // Cycle time of a setting at its best start distance, kInf when it
    // fails a requirement (start rule and feed caps are met by construction).
    double time_s(Strategy strategy, int repeats, double probe_feed_mm_min,
                  double measure_feed_mm_min, double bound_mm, double* approach_out = nullptr,
                  double* uncertainty_out = nullptr) {
        double starts[2];
        const int n = approaches(probe_feed_mm_min, starts);
        double best = kInf;
        for (int i = 0; i < n; ++i) {
            const ModelPoint& p =
                evaluate(strategy, repeats, probe_feed_mm_min, measure_feed_mm_min, starts[i]);
            if (!p.valid || p.overtravel_mm > overtravel_max_mm_ ||
                p.uncertainty_mm > bound_mm * (1.0 + kUncertaintyRelTolerance)) {
                continue;
            }
            if (p.cycle_time_s < best) {
                best = p.cycle_time_s;
                if (approach_out != nullptr) *approach_out = starts[i];
                if (uncertainty_out != nullptr) *uncertainty_out = p.uncertainty_mm;
            }
        }
        return best;
    }

    // The highest measuring feed whose evaluated uncertainty meets the bound
    // with `repeats`: the closed form, checked and, where the model differs
    // from it, found by bisection. Negative when not even 1 mm/min does.
    double measure_feed_bound(int repeats, double bound_mm) {
        double guess = closed_form_measure_feed_bound(base_, repeats, bound_mm);
        if (guess == kInf) guess = cap_mm_min_;
        const auto meets = [&](double feed) {
            const ModelPoint& p = evaluate_touch(repeats, feed);
            return p.uncertainty_mm <= bound_mm * (1.0 + kUncertaintyRelTolerance);
        };
        const double hi = std::min(std::max(guess, min_feed_mm_min_), cap_mm_min_);
        if (guess >= min_feed_mm_min_ && meets(hi)) return std::min(guess, cap_mm_min_);
        if (!meets(min_feed_mm_min_)) return -1.0;
        return last_ok_log(meets, min_feed_mm_min_, hi);
    }

    // The fastest setting of one strategy and repeat count whose uncertainty
    // meets `bound_mm` (kInf: no uncertainty requirement). Two-touch:
    // coordinate descent over the two feeds, which barely interact (the
    // first touch's feed sets its own time and the backoff's length; the
    // measuring feed the second touch's), each a log grid and a golden
    // section.
    Cell cell(Strategy strategy, int repeats, double bound_mm, int grid = 24) {
        Cell out;
        const double feed_hi = std::min({cap_mm_min_, overtravel_feed_mm_min_, start_feed_mm_min_});
        const double measure_hi =
            std::min({cap_mm_min_, overtravel_feed_mm_min_, measure_feed_bound(repeats, bound_mm)});
        if (feed_hi < min_feed_mm_min_ || measure_hi < min_feed_mm_min_) return out;
        // The coarse search (a grid of 12: the Pareto front's points, the
        // cells of more repeats that only bound the search) refines less:
        // its points are drawn, not applied.
        const bool coarse = grid <= 12;
        const int kGoldenIterations = coarse ? 14 : 40;
        const int kRounds = coarse ? 2 : 4;
        if (strategy == Strategy::single_touch) {
            const double hi = std::min(feed_hi, measure_hi);
            const Best1D b =
                minimise_log([&](double f) { return time_s(strategy, repeats, f, f, bound_mm); },
                             min_feed_mm_min_, hi, grid, kGoldenIterations);
            if (!std::isfinite(b.f)) return out;
            out = {true, b.x, b.x, b.f, 0.0};
        } else {
            double measure =
                std::clamp(base_.cycle.measure_feed_mm_min, min_feed_mm_min_, measure_hi);
            double probe = std::clamp(base_.cycle.probe_feed_mm_min, min_feed_mm_min_, feed_hi);
            double previous = kInf;
            for (int round = 0; round < kRounds; ++round) {
                const Best1D b1 = minimise_log(
                    [&](double f) { return time_s(strategy, repeats, f, measure, bound_mm); },
                    min_feed_mm_min_, feed_hi, grid, kGoldenIterations);
                if (std::isfinite(b1.f)) probe = b1.x;
                const Best1D b2 = minimise_log(
                    [&](double f) { return time_s(strategy, repeats, probe, f, bound_mm); },
                    min_feed_mm_min_, measure_hi, grid, kGoldenIterations);
                if (!std::isfinite(b2.f)) {
                    if (!std::isfinite(b1.f)) return out;
                    continue;
                }
                measure = b2.x;
                out = {true, probe, measure, b2.f, 0.0};
                if (previous - b2.f <= 1e-9 * b2.f) break;
                previous = b2.f;
            }
            if (!out.found) return out;
        }
        time_s(strategy, repeats, out.probe_feed_mm_min, out.measure_feed_mm_min, bound_mm, nullptr,
               &out.uncertainty_mm);
        return out;
    }

    // The smallest uncertainty any setting reaches: the slowest measuring
    // feed, the most repeats.
    double smallest_uncertainty_mm() {
        const double feed = min_feed_mm_min_;
        return evaluate_touch(max_repeats(), feed).uncertainty_mm;
    }

  private:
    // Whether the model ignores cycle.repeats (before the model averaged
    // repeated touches): then every repeat count is the same cycle and only
    // one is searched.
    bool detect_repeats_ignored() {
        const double feed =
            std::clamp(base_.cycle.probe_feed_mm_min, min_feed_mm_min_, cap_mm_min_);
        const ModelPoint one = evaluate_touch(1, feed);
        const ModelPoint two = evaluate_touch(2, feed);
        return one.cycle_time_s == two.cycle_time_s && one.uncertainty_mm == two.uncertainty_mm;
    }

    // The highest feed whose touch (from far enough out to reach it)
    // overtravels no more than the requirement allows and leaves a valid
    // cycle: overtravel grows with the feed. Under 1 mm/min when none does.
    double feed_bound_overtravel() {
        const auto ok = [&](double feed) {
            const ModelPoint& p = evaluate_touch(1, feed);
            return p.first_overtravel_mm <= overtravel_max_mm_ &&
                   p.first_overtravel_mm < base_.probe.overtravel_limit_mm;
        };
        if (cap_mm_min_ < min_feed_mm_min_ || !ok(min_feed_mm_min_)) return 0.0;
        return last_ok_log(ok, min_feed_mm_min_, cap_mm_min_);
    }

    // A bore or pocket: the highest probing feed whose start distance (part
    // position uncertainty plus the room to reach the feed) fits the feature.
    double feed_bound_start() {
        if (!is_internal(base_.cycle.feature)) return kInf;
        const auto ok = [&](double feed) { return approach_min_mm(feed) <= approach_max_mm_; };
        if (cap_mm_min_ < min_feed_mm_min_ || !ok(min_feed_mm_min_)) return 0.0;
        return last_ok_log(ok, min_feed_mm_min_, cap_mm_min_);
    }

    Scenario base_;
    Scenario scratch_;
    Scenario touch_;
    const CycleModel& model_;
    ModelPoint point_;
    double overtravel_max_mm_;
    double cap_mm_min_;
    double approach_max_mm_;
    double min_feed_mm_min_;
    double last_backoff_mm_{0.0};
    bool repeats_ignored_{false};
    double overtravel_feed_mm_min_{0.0};
    double start_feed_mm_min_{kInf};
};

Requirement uncertainty_requirement(const Scenario& scenario) {
    return scenario.cycle.target_uncertainty_mm > 0.0 ? Requirement::target_uncertainty
                                                      : Requirement::current_uncertainty;
}

// The fastest setting under `bound_mm` over both strategies and every
// useful repeat count, from the cells; none when no setting meets it.
//
// Repeats: counted up from the fewest whose closed-form uncertainty can meet
// the bound. More repeats only add time (a touch more each), so the search
// stops at a count whose fastest setting without the uncertainty
// requirement is no faster than the best found, or whose fastest setting
// already meets the bound without it (more repeats cannot beat that).
struct SearchOutcome {
    Strategy strategy{Strategy::two_touch};
    int repeats{1};
    Cell cell;
};
class Optimiser {
  public:
    Optimiser(const Scenario& scenario, const CycleModel& model, double fraction)
        : search_(scenario, model, fraction), model_(model) {}

    Search& search() { return search_; }

    const Cell& unconstrained(Strategy strategy, int repeats) {
        const auto key = std::make_pair(static_cast<int>(strategy), repeats);
        auto it = unconstrained_.find(key);
        if (it == unconstrained_.end()) {
            // A coarser grid for more repeats: their cells only bound the
            // search from below and serve the Pareto front's slow end.
            const int grid = repeats == 1 ? 24 : 12;
            it = unconstrained_.emplace(key, search_.cell(strategy, repeats, kInf, grid)).first;
        }
        return it->second;
    }

    // `unimodal`: stop counting repeats up once a count's fastest setting is
    // slower than the last count's. Its time is N touches of a time that falls
    // as the bound allows a faster measuring feed, N (a + c / sqrt(N U^2 -
    // rep^2)), which has one minimum in N; the Pareto front's points, where
    // the exact search over every count costs most, use it.
    std::optional<SearchOutcome> fastest(double bound_mm, int grid = 24, bool unimodal = false) {
        std::optional<SearchOutcome> best;
        // The fewest repeats whose mean can meet the bound at all (a scan
        // range of 0): N (bound^2 - F^2) >= rep^2.
        const double rep = search_.base().probe.repeatability_2sigma_mm;
        const double fixed = fixed_expanded_uncertainty_mm(search_.base());
        int fewest = 1;
        if (std::isfinite(bound_mm) && bound_mm > 0.0) {
            const double room = bound_mm * bound_mm - fixed * fixed;
            const double most = search_.max_repeats();
            fewest =
                room > 0.0
                    ? static_cast<int>(std::clamp(std::ceil(rep * rep / room - 1e-9), 1.0, most))
                    : search_.max_repeats();
        }
        fewest = std::min(fewest, search_.max_repeats());
        for (const Strategy strategy : {Strategy::single_touch, Strategy::two_touch}) {
            double last_time = kInf;
            for (int n = fewest; n <= search_.max_repeats(); ++n) {
                const Cell& free = unconstrained(strategy, n);
                if (!free.found) break;
                if (best && free.time_s >= best->cell.time_s) break;
                const bool meets =
                    free.uncertainty_mm <= bound_mm * (1.0 + kUncertaintyRelTolerance);
                const Cell cell = meets ? free : search_.cell(strategy, n, bound_mm, grid);
                if (cell.found && (!best || cell.time_s < best->cell.time_s))
                    best = SearchOutcome{strategy, n, cell};
                if (meets) break;
                if (unimodal && cell.found) {
                    if (cell.time_s > last_time) break;
                    last_time = cell.time_s;
                }
            }
        }
        return best;
    }

    // The setting to the editors' digits: the feeds down or up a step, the
    // start distances allowed, the recommended backoff; each evaluated and
    // checked against every requirement. Rounding down keeps the
    // requirements that grow with the feed, up may be faster where the time
    // still falls; the fastest that meets them all is kept.
    std::optional<Candidate> rounded(const SearchOutcome& outcome, double bound_mm,
                                     double fraction) {
        Search& s = search_;
        const bool two = outcome.strategy == Strategy::two_touch;
        const auto feeds_near = [&](double feed) {
            std::vector<double> feeds;
            const double down = round_feed_down(feed);
            if (down >= search_.min_feed()) {
                feeds.push_back(down);
                const double lower = round_feed_down(down - 0.5 * feed_step_mm_min(down - 0.05));
                if (lower >= search_.min_feed()) feeds.push_back(lower);
            }
            const double up = round_feed_up(feed);
            if (up <= s.cap_mm_min() && up != down) feeds.push_back(up);
            if (feeds.empty()) feeds.push_back(search_.min_feed());
            return feeds;
        };
        std::vector<double> probes = feeds_near(outcome.cell.probe_feed_mm_min);
        // The start distance is rounded up to 0.01 mm, so the time is a
        // staircase in the probing feed: just under the feed where the start
        // rule's distance steps up, a step of start distance is saved, which
        // at a slow feed and a short start is worth more than the feed. Try
        // the highest feed of each step near the one found.
        const double level = s.approach_min_mm(outcome.cell.probe_feed_mm_min);
        const double feed_hi =
            std::min({s.cap_mm_min(), s.overtravel_feed_mm_min(), s.start_feed_mm_min()});
        for (int k = -kStartLevelsAbove; k <= kStartLevelsBelow; ++k) {
            const double start = level - k * kApproachStep_mm;
            if (start < 0.0 || feed_hi < search_.min_feed()) continue;
            const double corner =
                last_ok_log([&](double f) { return s.approach_min_mm(f) <= start + 1e-12; },
                            search_.min_feed(), feed_hi);
            const double feed = round_feed_down(corner);
            if (feed >= search_.min_feed() && s.approach_min_mm(feed) <= start + 1e-12 &&
                std::find(probes.begin(), probes.end(), feed) == probes.end()) {
                probes.push_back(feed);
            }
        }
        const std::vector<double> measures =
            two ? feeds_near(outcome.cell.measure_feed_mm_min) : std::vector<double>{0.0};
        std::optional<Settings> best;
        double best_time = kInf;
        for (const double probe : probes) {
            for (const double measure_or_none : measures) {
                const double measure = two ? measure_or_none : probe;
                double starts[2];
                const int n = s.approaches(probe, starts);
                for (int i = 0; i < n; ++i) {
                    const ModelPoint& p =
                        s.evaluate(outcome.strategy, outcome.repeats, probe, measure, starts[i]);
                    if (p.cycle_time_s >= best_time) continue;
                    const Settings settings{outcome.strategy, probe,
                                            measure,          two ? p.recommended_backoff_mm : 0.0,
                                            starts[i],        outcome.repeats};
                    if (!unmet_requirements(with_settings(s.base(), settings), p, fraction,
                                            bound_mm)
                             .empty()) {
                        continue;
                    }
                    best = settings;
                    best_time = p.cycle_time_s;
                }
            }
        }
        if (!best) return std::nullopt;
        // The figures reported are those of the settings as written.
        const Scenario scenario = with_settings(s.base(), *best);
        ModelPoint check;
        model_(scenario, check);
        if (!unmet_requirements(scenario, check, fraction, bound_mm).empty()) return std::nullopt;
        return Candidate{*best, check.cycle_time_s, check.uncertainty_mm, check.overtravel_mm};
    }

  private:
    Search search_;
    const CycleModel& model_;
    std::map<std::pair<int, int>, Cell> unconstrained_;
};

Message impossible_message(Optimiser& optimiser, const Scenario& scenario, double bound_mm,
                           double fraction) {
    Search& s = optimiser.search();
    if (s.cap_mm_min() < s.min_feed()) {
        Message m = make_message("probe_max_feed", "Optimise",
                                 QT_TRANSLATE_NOOP("Optimise",
                                                   "no setting meets the requirements: the "
                                                   "probe's maximum feed %1 is under the lowest "
                                                   "feed, %2"));
        m.args = {arg("max_feed_mm_min", ArgKind::feed_mm_min, scenario.probe.max_feed_mm_min),
                  arg("min_feed_mm_min", ArgKind::feed_mm_min, s.min_feed())};
        return m;
    }
    if (s.overtravel_feed_mm_min() < s.min_feed()) {
        const ModelPoint& p = s.evaluate_touch(1, s.min_feed());
        Message m = make_message(
            "overtravel_fraction", "Optimise",
            QT_TRANSLATE_NOOP("Optimise",
                              "no setting meets the requirements: the overtravel must stay at "
                              "or under %1 of the probe's limit %2 (probe.overtravel_limit_mm), "
                              "and even at %3 it is %4"));
        m.args = {arg("fraction", ArgKind::percent, 100.0 * fraction),
                  arg("limit_mm", ArgKind::length_mm, scenario.probe.overtravel_limit_mm),
                  arg("feed_mm_min", ArgKind::feed_mm_min, s.min_feed()),
                  significant_arg("overtravel_mm", ArgKind::length_mm, p.first_overtravel_mm, 4)};
        return m;
    }
    if (s.start_feed_mm_min() < s.min_feed()) {
        Message m = make_message(
            "start_distance", "Optimise",
            QT_TRANSLATE_NOOP("Optimise",
                              "no setting meets the requirements: a start distance of the part "
                              "position uncertainty %1 plus the room to reach even %2 (%3) "
                              "does not fit a %4 of %5"));
        m.args = {
            arg("part_position_uncertainty_mm", ArgKind::length_mm,
                scenario.cycle.part_position_uncertainty_mm),
            arg("feed_mm_min", ArgKind::feed_mm_min, s.min_feed()),
            significant_arg("approach_mm", ArgKind::length_mm, s.approach_min_mm(s.min_feed()), 4),
            feature_arg("feature", scenario.cycle.feature),
            arg("feature_size_mm", ArgKind::length_mm, scenario.cycle.feature_size_mm)};
        return m;
    }
    const double smallest = s.smallest_uncertainty_mm();
    if (smallest > bound_mm * (1.0 + kUncertaintyRelTolerance)) {
        const bool target = uncertainty_requirement(scenario) == Requirement::target_uncertainty;
        Message m = make_message(
            to_string(uncertainty_requirement(scenario)), "Optimise",
            target
                ? QT_TRANSLATE_NOOP("Optimise",
                                    "no setting meets the target uncertainty %1 "
                                    "(cycle.target_uncertainty_mm): the smallest achievable "
                                    "is %2, at %3 and cycle.repeats %4 (the probe's repeatability "
                                    "is %5; the budget's terms no feed changes, lobing, "
                                    "calibration artefact, machine repeatability and thermal "
                                    "drift, are %6 together)")
                : QT_TRANSLATE_NOOP("Optimise",
                                    "no setting meets the current uncertainty %1: the "
                                    "smallest achievable is %2, at %3 and cycle.repeats %4 (the "
                                    "probe's repeatability is %5; the budget's terms no feed "
                                    "changes, lobing, calibration artefact, machine "
                                    "repeatability and thermal drift, are %6 together)"));
        m.args = {significant_arg("bound_mm", ArgKind::length_mm, bound_mm, 4),
                  significant_arg("smallest_mm", ArgKind::length_mm, smallest, 4),
                  arg("feed_mm_min", ArgKind::feed_mm_min, s.min_feed()),
                  arg("repeats", ArgKind::integer, s.max_repeats()),
                  significant_arg("repeatability_mm", ArgKind::length_mm,
                                  scenario.probe.repeatability_2sigma_mm, 4),
                  significant_arg("fixed_mm", ArgKind::length_mm,
                                  fixed_expanded_uncertainty_mm(scenario), 4)};
        return m;
    }
    return make_message("no_valid_setting", "Optimise",
                        QT_TRANSLATE_NOOP("Optimise", "no setting meets every requirement"));
}

struct Core {
    Candidate best;
    SearchOutcome outcome;
};

// The optimisation without the extras (Pareto, advice): the fastest setting
// to the editors' digits under `bound_mm`.
Core fastest_rounded(Optimiser& optimiser, const Scenario& scenario, double bound_mm,
                     double fraction) {
    const std::optional<SearchOutcome> outcome = optimiser.fastest(bound_mm);
    if (!outcome) throw InputError(impossible_message(optimiser, scenario, bound_mm, fraction));
    std::optional<Candidate> best = optimiser.rounded(*outcome, bound_mm, fraction);
    if (!best) throw InputError(impossible_message(optimiser, scenario, bound_mm, fraction));
    return {*best, *outcome};
}

// The setting sits on a feed bound: within 0.2 % or two feed steps of it.
// Not exactly on it: the backoff (1 um) and the start distance (0.01 mm)
// are rounded up, so the time is a fine staircase in the feed and the
// fastest feed can be a step or two under the bound it presses against.
bool on_bound(double feed_mm_min, double bound_mm_min) {
    return std::isfinite(bound_mm_min) &&
           feed_mm_min + std::max(0.002 * bound_mm_min, 2.0 * feed_step_mm_min(feed_mm_min)) >
               bound_mm_min;
}

}  // namespace

const char* to_string(Requirement requirement) {
    switch (requirement) {
        case Requirement::valid_cycle:
            return "valid_cycle";
        case Requirement::target_uncertainty:
            return "target_uncertainty";
        case Requirement::current_uncertainty:
            return "current_uncertainty";
        case Requirement::overtravel_fraction:
            return "overtravel_fraction";
        case Requirement::probe_max_feed:
            return "probe_max_feed";
        case Requirement::machine_rapid:
            return "machine_rapid";
        case Requirement::start_distance:
            return "start_distance";
        case Requirement::repeats_limit:
            return "repeats_limit";
        case Requirement::min_feed:
            return "min_feed";
    }
    return "";
}

Scenario with_settings(const Scenario& scenario, const Settings& settings) {
    Scenario out = scenario;
    Cycle& c = out.cycle;
    c.strategy = settings.strategy;
    c.probe_feed_mm_min = settings.probe_feed_mm_min;
    c.measure_feed_mm_min = settings.measure_feed_mm_min;
    c.backoff_mm = settings.backoff_mm;
    c.approach_mm = settings.approach_mm;
    c.repeats = settings.repeats;
    if (settings.position_feed_mm_min > 0.0) c.position_feed_mm_min = settings.position_feed_mm_min;
    return out;
}

Settings settings_of(const Scenario& scenario) {
    const Cycle& c = scenario.cycle;
    const bool two = c.strategy == Strategy::two_touch;
    return {c.strategy,
            c.probe_feed_mm_min,
            two ? c.measure_feed_mm_min : c.probe_feed_mm_min,
            two ? c.backoff_mm : 0.0,
            c.approach_mm,
            static_cast<int>(c.repeats),
            c.position_feed_mm_min};
}

void evaluate_point(const Scenario& scenario, ModelPoint& point) {
    thread_local CycleResult result;
    thread_local MotionCache cache;  // the candidates share the machine
    evaluate_into(scenario, result, cache, Detail::summary);
    point.valid = result.valid();
    point.cycle_time_s = result.total();
    point.uncertainty_mm = result.uncertainty_mm();
    point.overtravel_mm = result.checked_overtravel_mm();
    // At the highest feed override, as the checks take them.
    point.first_overtravel_mm = result.first_touch().override_overtravel_mm;
    point.measuring_overtravel_mm = result.measuring_touch().override_overtravel_mm;
    point.recommended_backoff_mm = result.recommended_backoff_mm();
}

std::vector<Requirement> unmet_requirements(const Scenario& scenario, const ModelPoint& point,
                                            double max_overtravel_fraction, double bound_mm) {
    std::vector<Requirement> unmet;
    const Cycle& c = scenario.cycle;
    const bool two = c.strategy == Strategy::two_touch;
    bool valid = point.valid;
    bool start_ok = true;
    for (const FieldError& error : validate(scenario)) {
        if (error.key == "cycle.feature_size_mm") {
            start_ok = false;
        } else {
            valid = false;
        }
    }
    if (!valid) unmet.push_back(Requirement::valid_cycle);
    if (point.uncertainty_mm > bound_mm * (1.0 + kUncertaintyRelTolerance))
        unmet.push_back(uncertainty_requirement(scenario));
    if (point.overtravel_mm > max_overtravel_fraction * scenario.probe.overtravel_limit_mm)
        unmet.push_back(Requirement::overtravel_fraction);
    const double fastest =
        two ? std::max(c.probe_feed_mm_min, c.measure_feed_mm_min) : c.probe_feed_mm_min;
    if (scenario.probe.max_feed_mm_min > 0.0 && fastest > scenario.probe.max_feed_mm_min)
        unmet.push_back(Requirement::probe_max_feed);
    if (fastest > scenario.machine.rapid_feed_mm_min) unmet.push_back(Requirement::machine_rapid);
    if (start_ok) start_ok = c.approach_mm >= start_rule_mm(scenario, c.probe_feed_mm_min);
    const double slowest =
        two ? std::min(c.probe_feed_mm_min, c.measure_feed_mm_min) : c.probe_feed_mm_min;
    if (slowest < c.min_feed_mm_min) unmet.push_back(Requirement::min_feed);
    if (!start_ok) unmet.push_back(Requirement::start_distance);
    if (!(c.repeats >= 1.0 && c.repeats <= kMaxRepeats && c.repeats == std::floor(c.repeats)))
        unmet.push_back(Requirement::repeats_limit);
    return unmet;
}

OptimiseResult optimise(const Scenario& scenario, const OptimiseRequirements& requirements) {
    return optimise(scenario, requirements, CycleModel(evaluate_point));
}

namespace {

Candidate candidate_of(const Scenario& scenario, const ModelPoint& point) {
    return {settings_of(scenario), point.cycle_time_s, point.uncertainty_mm, point.overtravel_mm};
}

// A requirement is relaxed by this much (10 %) to see whether it binds.
constexpr double kRelax = 1.1;
// A saving under this fraction of the cycle (0.1 %) binds nothing and is no
// advice: the editors' rounding of the feeds and the start moves the time by
// about as much (the example bore's probe rated to 5000 mm/min "bound" its
// best by 0.46 ms in 5.18 s).
constexpr double kMeaningfulSaving = 1e-3;

// The binding requirements of `best` (see OptimiseResult::binding):
// binding means that relaxing the requirement makes the best setting faster,
// so each one that can be relaxed alone (the uncertainty bound, the
// overtravel fraction, the probe's maximum feed, the part position
// uncertainty behind the start rule) is checked by optimising again with it
// relaxed by 10 %. The rapid (which also times the lifts) and the repeat
// limit (the key's range) are named by where the best setting lies.
//
// The searches of a scenario of their own are independent: those that need
// nothing of the best setting start before it is found
// (start_independent()), the others once it is (start_dependent()), each on
// a TaskGroup while the caller goes on with the optimiser it has (the best
// setting, the uncertainty bound's check, the Pareto front). finish() waits
// and compares their times in a fixed order, so the result does not depend
// on which thread ran what.
class BindingChecks {
  public:
    BindingChecks(const Scenario& scenario, const CycleModel& model, double bound_mm,
                  double fraction)
        : scenario_(scenario), model_(model), bound_mm_(bound_mm), fraction_(fraction) {}

    // The overtravel fraction, the probe's maximum feed and the part position
    // uncertainty behind the start rule, each relaxed.
    void start_independent() {
        const Scenario& scenario = scenario_;
        if (fraction_ < kMaxOvertravelFraction) {
            later(overtravel_s_, scenario, std::min(kMaxOvertravelFraction, fraction_ * kRelax));
        }
        if (scenario.probe.max_feed_mm_min > 0.0) {
            Scenario changed = scenario;
            changed.probe.max_feed_mm_min *= kRelax;
            later(probe_max_feed_s_, changed, fraction_);
        }
        // The start rule: the part position uncertainty lengthens the start,
        // or a bore's size caps the feed (not relaxed: the feature is the part's).
        if (scenario.cycle.part_position_uncertainty_mm > 0.0) {
            Scenario changed = scenario;
            changed.cycle.part_position_uncertainty_mm /= kRelax;
            later(part_position_s_, changed, fraction_);
        }
    }

    // The shortest start and the slowest feed, relaxed where the best
    // setting presses against them.
    void start_dependent(Optimiser& optimiser, const Candidate& best) {
        const Scenario& scenario = scenario_;
        const Settings& b = best.settings;
        // The shortest start, relaxed as the part's uncertainty is (it binds
        // only when the part's does not; searched anyway, side by side).
        if (scenario.cycle.min_start_mm > 0.0 &&
            b.approach_mm <= approach_up(scenario.cycle.min_start_mm) + 1e-9) {
            Scenario changed = scenario;
            changed.cycle.min_start_mm /= kRelax;
            later(min_start_s_, changed, fraction_);
        }
        // The slowest feed: lower, a tight target might need fewer repeats.
        const Search& s = optimiser.search();
        const double slowest = b.strategy == Strategy::two_touch
                                   ? std::min(b.probe_feed_mm_min, b.measure_feed_mm_min)
                                   : b.probe_feed_mm_min;
        if (slowest <= s.min_feed() * (1.0 + 1e-9) && s.min_feed() > kMinFeed_mm_min) {
            Scenario changed = scenario;
            changed.cycle.min_feed_mm_min = std::max(kMinFeed_mm_min, s.min_feed() / kRelax);
            later(min_feed_s_, changed, fraction_);
        }
    }

    std::vector<Requirement> finish(Optimiser& optimiser, const Candidate& best) {
        const Scenario& scenario = scenario_;
        const double faster_than = best.cycle_time_s * (1.0 - kMeaningfulSaving);
        std::vector<Requirement> binding;
        const bool uncertainty =
            std::isfinite(bound_mm_) &&
            relaxed_time(optimiser, scenario, bound_mm_ * kRelax, fraction_) < faster_than;
        tasks_.wait();
        if (uncertainty) binding.push_back(uncertainty_requirement(scenario));
        if (overtravel_s_ < faster_than) binding.push_back(Requirement::overtravel_fraction);
        if (probe_max_feed_s_ < faster_than) binding.push_back(Requirement::probe_max_feed);
        Search& s = optimiser.search();
        const Settings& b = best.settings;
        const bool two = b.strategy == Strategy::two_touch;
        const double top =
            two ? std::max(b.probe_feed_mm_min, b.measure_feed_mm_min) : b.probe_feed_mm_min;
        const bool probe_cap = scenario.probe.max_feed_mm_min > 0.0 &&
                               scenario.probe.max_feed_mm_min <= scenario.machine.rapid_feed_mm_min;
        if (on_bound(top, s.cap_mm_min()) && !probe_cap)
            binding.push_back(Requirement::machine_rapid);
        if (min_feed_s_ < faster_than) binding.push_back(Requirement::min_feed);
        const bool start = part_position_s_ < faster_than || min_start_s_ < faster_than;
        if (start || (on_bound(b.probe_feed_mm_min, s.start_feed_mm_min()) &&
                      s.start_feed_mm_min() < s.cap_mm_min()))
            binding.push_back(Requirement::start_distance);
        if (b.repeats == kMaxRepeats && std::isfinite(bound_mm_))
            binding.push_back(Requirement::repeats_limit);
        return binding;
    }

  private:
    // The fastest time with a requirement relaxed; infinite when none meets them.
    static double relaxed_time(Optimiser& other, const Scenario& changed, double bound,
                               double relaxed_fraction) {
        try {
            return fastest_rounded(other, changed, bound, relaxed_fraction).best.cycle_time_s;
        } catch (const InputError&) {
            return kInf;
        }
    }
    void later(double& result, const Scenario& changed, double relaxed_fraction) {
        tasks_.run([this, &result, changed, relaxed_fraction] {
            Optimiser other(changed, model_, relaxed_fraction);
            result = relaxed_time(other, changed, bound_mm_, relaxed_fraction);
        });
    }

    const Scenario& scenario_;
    const CycleModel& model_;
    double bound_mm_;
    double fraction_;
    double overtravel_s_{kInf};
    double probe_max_feed_s_{kInf};
    double part_position_s_{kInf};
    double min_start_s_{kInf};
    double min_feed_s_{kInf};
    TaskGroup tasks_;  // last: destroyed (its tasks waited for) first
};

}  // namespace

OptimiseResult optimise(const Scenario& given, const OptimiseRequirements& requirements,
                        const CycleModel& model) {
    const double fraction = requirements.max_overtravel_fraction;
    if (!(fraction >= kMinOvertravelFraction && fraction <= kMaxOvertravelFraction)) {
        Message m =
            make_message("overtravel_fraction_range", "Optimise",
                         QT_TRANSLATE_NOOP("Optimise",
                                           "the overtravel fraction %1 is out of range: allowed "
                                           "from %2 to %3"));
        m.args = {arg("fraction", ArgKind::number, fraction),
                  arg("min", ArgKind::number, kMinOvertravelFraction),
                  arg("max", ArgKind::number, kMaxOvertravelFraction)};
        throw InputError(m);
    }
    OptimiseResult result;
    ModelPoint current;
    model(given, current);
    result.current = candidate_of(given, current);
    // A feature's protected moves that would overrun the stylus
    // (an obstruction met at the positioning feed, at the highest feed
    // override, stops at or past the probe's limit) make every setting
    // invalid, and no probing setting changes them: the search then runs with
    // the positioning feed lowered to the highest that keeps that stop within
    // the overtravel requirement (as the one-click fix does at 80 %), and the
    // best settings carry it.
    Scenario scenario = given;
    if (touch_count(given.cycle.feature) > 1 &&
        protected_move_overtravel_mm(given, mm_min_to_mm_s(given.cycle.position_feed_mm_min)) >=
            given.probe.overtravel_limit_mm) {
        const std::optional<double> feed = highest_position_feed_mm_min(
            given, given.cycle.position_feed_mm_min, requirements.max_overtravel_fraction);
        if (feed && *feed < given.cycle.position_feed_mm_min) {
            scenario.cycle.position_feed_mm_min = *feed;
        }
    }
    const double target = scenario.cycle.target_uncertainty_mm;
    const double bound = target > 0.0 ? target : current.uncertainty_mm;
    result.uncertainty_bound_mm = bound;
    result.current_meets_requirements = unmet_requirements(given, current, fraction, bound).empty();

    BindingChecks checks(scenario, model, bound, fraction);
    checks.start_independent();
    Optimiser optimiser(scenario, model, fraction);
    const Core core = fastest_rounded(optimiser, scenario, bound, fraction);
    result.best = core.best;
    result.best.settings.position_feed_mm_min = scenario.cycle.position_feed_mm_min;
    result.saved_s = result.current.cycle_time_s - result.best.cycle_time_s;
    checks.start_dependent(optimiser, result.best);

    const Cycle& c = scenario.cycle;
    if (c.parts_per_year > 0.0) {
        Savings savings;
        savings.saved_per_part_s =
            result.saved_s * (c.cycles_per_part > 0.0 ? c.cycles_per_part : 1.0);
        savings.hours_per_year = savings.saved_per_part_s * c.parts_per_year / 3600.0;
        if (c.machine_rate_per_hour > 0.0)
            savings.cost_per_year = savings.hours_per_year * c.machine_rate_per_hour;
        result.savings = savings;
    }

    if (requirements.pareto_points > 0) {
        // From the smallest achievable uncertainty to that of the fastest
        // setting without an uncertainty requirement.
        const double low = optimiser.search().smallest_uncertainty_mm();
        double high = low;
        double free_time = kInf;
        for (const Strategy strategy : {Strategy::single_touch, Strategy::two_touch}) {
            const Cell& free = optimiser.unconstrained(strategy, 1);
            if (free.found && free.time_s < free_time) {
                free_time = free.time_s;
                high = free.uncertainty_mm;
            }
        }
        const int n = requirements.pareto_points;
        std::vector<Candidate> points;
        for (int k = 0; k < n; ++k) {
            // Evenly on a log scale: the uncertainties span decades.
            const double b = n == 1 || !(high > low)
                                 ? high
                                 : low * std::pow(high / low, static_cast<double>(k) / (n - 1));
            const std::optional<SearchOutcome> outcome = optimiser.fastest(b, 12, true);
            if (!outcome) continue;
            if (std::optional<Candidate> point = optimiser.rounded(*outcome, b, fraction))
                points.push_back(*point);
        }
        std::sort(points.begin(), points.end(), [](const Candidate& x, const Candidate& y) {
            return x.uncertainty_mm < y.uncertainty_mm ||
                   (x.uncertainty_mm == y.uncertainty_mm && x.cycle_time_s < y.cycle_time_s);
        });
        for (const Candidate& point : points) {
            if (result.pareto.empty() || point.cycle_time_s < result.pareto.back().cycle_time_s)
                result.pareto.push_back(point);
        }
        for (Candidate& point : result.pareto) {
            point.settings.position_feed_mm_min = scenario.cycle.position_feed_mm_min;
        }
    }

    result.binding = checks.finish(optimiser, result.best);

    if (requirements.advice) {
        const bool uncertainty_binds =
            std::find(result.binding.begin(), result.binding.end(),
                      uncertainty_requirement(scenario)) != result.binding.end();
        const auto advise = [&](Scenario changed, std::string code, Message message) {
            try {
                Optimiser other(changed, model, fraction);
                const Core better = fastest_rounded(other, changed, bound, fraction);
                const double saved = result.best.cycle_time_s - better.best.cycle_time_s;
                if (saved < kMeaningfulSaving * result.best.cycle_time_s) return;
                message.args.push_back(significant_arg("saved_s", ArgKind::time_s, saved, 3));
                result.advice.push_back({std::move(code), std::move(message), saved});
            } catch (const InputError&) {
            }
        };
        if (uncertainty_binds && !scenario.machine.latched_input &&
            scenario.machine.scan_period_s > 0.0) {
            Scenario changed = scenario;
            changed.machine.latched_input = true;
            Message m =
                make_message("latched_input", "Optimise",
                             QT_TRANSLATE_NOOP("Optimise",
                                               "the skip input's scan period %1 limits the "
                                               "measuring feed; a latched input would save %2 "
                                               "a cycle"));
            m.args = {arg("scan_period_s", ArgKind::delay_s, scenario.machine.scan_period_s)};
            advise(changed, "latched_input", m);
        }
        if (std::find(result.binding.begin(), result.binding.end(), Requirement::probe_max_feed) !=
            result.binding.end()) {
            Scenario changed = scenario;
            changed.probe.max_feed_mm_min = 0.0;
            Message m =
                make_message("probe_max_feed", "Optimise",
                             QT_TRANSLATE_NOOP("Optimise",
                                               "the probe's maximum feed %1 limits the cycle; a "
                                               "probe rated for faster feeds would save %2 a "
                                               "cycle"));
            m.args = {arg("max_feed_mm_min", ArgKind::feed_mm_min, scenario.probe.max_feed_mm_min)};
            advise(changed, "probe_max_feed", m);
        }
    }
    return result;
}

}  // namespace probecycle
