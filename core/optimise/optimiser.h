#pragma once

// The optimiser (docs/cli.md, "What should I change?"): the fastest settings of
// a cycle that still meet the user's requirements, what they save against the
// current settings, which requirement stops the cycle from being faster, and
// the Pareto front of cycle time against uncertainty. Shared by
// `probecycle-cli optimise` and the window. Pure: Scenario in, OptimiseResult
// out, no Qt.
//
// Free: strategy, probing feed, measuring feed, backoff, start distance
// (approach), repeats. Required of every setting returned:
// - a valid cycle (CycleResult::valid());
// - expanded uncertainty at or under cycle.target_uncertainty_mm, or, with no
//   target (0), at or under the current scenario's: faster without losing
//   accuracy;
// - overtravel at or under max_overtravel_fraction of the probe's limit;
// - feeds from 1 mm/min up to probe.max_feed_mm_min (when set) and the
//   machine's rapid feed;
// - the start rule: approach_mm at least cycle.part_position_uncertainty_mm
//   plus approach_room_mm() of the probing feed (the touch is at full feed
//   wherever the part lies within its uncertainty);
// - a scenario that validates (a bore or pocket wider than two approaches).
// The optimiser checks each itself on the evaluated cycle, so it holds with
// and without a model that checks them too.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/message.h"
#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"

namespace probecycle {

struct OptimiseRequirements {
    // Overtravel at or under this fraction of probe.overtravel_limit_mm
    // (0.8: where evaluate() starts to warn). Allowed: kMinOvertravelFraction
    // to kMaxOvertravelFraction; optimise() refuses others (InputError).
    double max_overtravel_fraction{0.8};
    // Uncertainty bounds of the Pareto front (0: no front); the CLI allows 1
    // to kMaxParetoPoints.
    int pareto_points{20};
    // Advice (e.g. a latched input) costs an optimisation each; the window
    // may leave it out while a slider moves.
    bool advice{true};
};
// The allowed ranges of the options above, for the CLI's and the window's editors.
constexpr double kMinOvertravelFraction = 0.01;
constexpr double kMaxOvertravelFraction = 1.0;
constexpr int kMaxParetoPoints = 200;
// The start distance is set to this step (0.01 mm), rounded up.
constexpr double kApproachStep_mm = 0.01;

// The settings the optimiser chooses. Single-touch has no second touch:
// measure_feed_mm_min is the probing feed (it measures) and backoff_mm is 0.
struct Settings {
    Strategy strategy{Strategy::two_touch};
    double probe_feed_mm_min{0.0};
    double measure_feed_mm_min{0.0};
    double backoff_mm{0.0};
    double approach_mm{0.0};
    int repeats{1};
    // A feature's protected positioning moves: the optimiser lowers
    // the scenario's feed where an obstruction met at it (at the highest feed
    // override) would stop beyond the overtravel requirement. 0: the
    // scenario's.
    double position_feed_mm_min{0.0};
};
// The scenario with these settings (the rest as it was).
Scenario with_settings(const Scenario& scenario, const Settings& settings);
// The settings a scenario holds, as Settings says them (single-touch: the
// measuring feed is the probing feed, no backoff).
Settings settings_of(const Scenario& scenario);

// A setting with its evaluated figures (evaluate() of with_settings()).
struct Candidate {
    Settings settings;
    double cycle_time_s{0.0};
    double uncertainty_mm{0.0};
    double overtravel_mm{0.0};
};

// The requirements, by the codes the CLI prints in `binding`.
enum class Requirement {
    valid_cycle,          // CycleResult::valid() (and a scenario that validates)
    target_uncertainty,   // cycle.target_uncertainty_mm
    current_uncertainty,  // no target: the current scenario's uncertainty
    overtravel_fraction,  // overtravel <= fraction * probe.overtravel_limit_mm
    probe_max_feed,       // probe.max_feed_mm_min
    machine_rapid,        // machine.rapid_feed_mm_min
    start_distance,       // part position uncertainty + room to reach the feed, at least
                          // cycle.min_start_mm (and a bore's or pocket's size)
    repeats_limit,        // at most kMaxRepeats repeats
    min_feed,             // cycle.min_feed_mm_min: no touch slower
};
const char* to_string(Requirement requirement);

// A change outside the free settings that would save time, found by
// optimising again with it: "a latched input would save 2.1 s".
struct Advice {
    std::string code;  // "latched_input", "probe_max_feed"
    Message message;
    double saved_s{0.0};  // per cycle, against `best`
};

// What the saving is worth a year (cycle.parts_per_year etc.; shown when
// parts_per_year > 0).
struct Savings {
    double saved_per_part_s{0.0};  // saved_s * cycles per part (0 counts as 1)
    double hours_per_year{0.0};
    // hours_per_year * cycle.machine_rate_per_hour; none when the rate is 0.
    std::optional<double> cost_per_year;
};

struct OptimiseResult {
    Candidate best;
    Candidate current;  // the scenario as given
    // Whether the current settings meet every requirement (a valid cycle among them).
    bool current_meets_requirements{false};
    double saved_s{0.0};  // current.cycle_time_s - best.cycle_time_s
    // The uncertainty every setting had to meet: the target, or the current one.
    double uncertainty_bound_mm{0.0};
    // The requirements that stop `best` from being faster: relaxing one of
    // them (a little) would give a faster valid cycle.
    std::vector<Requirement> binding;
    // The fastest valid setting for each of pareto_points uncertainty bounds
    // from the smallest achievable uncertainty to that of the fastest
    // setting without an uncertainty requirement; dominated points dropped,
    // so uncertainty rises and cycle time falls along the list.
    std::vector<Candidate> pareto;
    std::optional<Savings> savings;
    std::vector<Advice> advice;
};

// The figures the optimiser needs of one evaluation.
struct ModelPoint {
    bool valid{false};
    double cycle_time_s{0.0};
    double uncertainty_mm{0.0};
    // The worst touch's, and each touch's, at up to the highest feed override
    // (CycleResult::checked_overtravel_mm): the requirement holds at it.
    double overtravel_mm{0.0};
    double first_overtravel_mm{0.0};
    double measuring_overtravel_mm{0.0};
    double recommended_backoff_mm{0.0};
};
// The cycle model the optimiser searches: evaluate() by default. Tests pass
// a stand-in for a revision of the model (e.g. repeats that change the time
// and the uncertainty) to check the search against a brute force on it.
// The optimiser calls it from several threads at once (its independent
// searches run side by side): it must keep no shared state unguarded.
using CycleModel = std::function<void(const Scenario&, ModelPoint&)>;
void evaluate_point(const Scenario& scenario, ModelPoint& point);

// Throws InputError when no setting meets the requirements, naming the
// requirement and the best value achievable (a target under the probe's
// repeatability / sqrt(20), overtravel over the fraction even at 1 mm/min,
// a bore too small for the start rule). Assumes a valid scenario.
OptimiseResult optimise(const Scenario& scenario, const OptimiseRequirements& requirements = {});
OptimiseResult optimise(const Scenario& scenario, const OptimiseRequirements& requirements,
                        const CycleModel& model);

// The requirements a setting fails (empty: it meets them all), on its
// evaluation `point` under the uncertainty bound `bound_mm`; the optimiser's
// own check, also used to say whether the current settings meet them.
std::vector<Requirement> unmet_requirements(const Scenario& scenario, const ModelPoint& point,
                                            double max_overtravel_fraction, double bound_mm);

}  // namespace probecycle
