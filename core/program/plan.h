#pragma once

// What a probing program does, before it is written in a control's dialect:
// the delay-stability test, the ring-gauge calibration and the
// tuned cycle as a list of steps, each an incremental move from where the
// previous one left the probe. The generator (program_writer.h) writes the
// steps in a dialect; the importer (machine_log.h) matches what the control
// recorded to the plan's recorded touches. The plan is a file of its own
// (probing_plan_json / parse_probing_plan) so that the import, days later, knows which touch
// was which.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/cycle/scenario.h"

namespace probecycle {

enum class ProgramKind { delay, ring, cycle };
const char* to_string(ProgramKind kind);
std::optional<ProgramKind> program_kind_from_string(std::string_view word);

enum class StepKind {
    pause,  // the operator does what `text` says, then resumes (cycle start)
    probe,  // a probing move: stops at the trigger, an alarm when none comes
    move,   // a plain move: rapid (feed 0) or at a feed
    // A protected move: at a feed with the probe armed, a move that must not
    // trigger. A trigger means the path is obstructed: the program stops with
    // an alarm where the dialect can branch (dialect.h, guard_word).
    guard,
};

struct ProgramStep {
    StepKind kind{StepKind::probe};
    char axis{'X'};           // 'X', 'Y' or 'Z'
    int direction{-1};        // +1 or -1, the direction of travel
    double distance_mm{0.0};  // the length of the move (probe: the farthest it may go)
    double feed_mm_min{0.0};  // 0: rapid (a plain move only)
    // A probe whose trigger position the lab uses; the others locate the
    // surface or make the first touch of a two-touch point.
    bool recorded{false};
    double orientation_deg{0.0};  // ring: the spindle orientation of the touch
    std::string text;             // pause: what the operator does; otherwise a note
};

// A scenario value the plan was made from, shown in the program's header.
struct PlanValue {
    std::string key;   // "cycle.probe_feed_mm_min", or a program option ("gauge_diameter_mm")
    std::string text;  // as the scenario file writes it
};

struct ProbingPlan {
    ProgramKind kind{ProgramKind::delay};
    std::vector<PlanValue> values;
    std::vector<ProgramStep> steps;

    // The recorded probes, in order.
    std::vector<const ProgramStep*> recorded() const;
    // Whether a step is a protected move (StepKind::guard).
    bool has_guards() const;
};

// One axis and direction of the delay test ("X-").
struct AxisDirection {
    char axis{'Z'};
    int direction{-1};
};
// "X+", "z-" (case-insensitive); nullopt otherwise.
std::optional<AxisDirection> axis_direction_from_string(std::string_view text);
std::string to_string(const AxisDirection& group);

// The allowed ranges of the options, shared by the CLI and the plan file.
constexpr double kMinPlanFeed_mm_min = 1.0;
constexpr double kMaxPlanFeed_mm_min = 100000.0;
constexpr double kMaxPlanDistance_mm = 1000.0;
constexpr int kMaxPlanRepeats = 100;
constexpr std::size_t kMaxPlanSteps = 20000;
constexpr std::size_t kMaxPlanFeeds = 20;
constexpr std::size_t kMaxPauseTextChars = 200;

// The delay-stability test (ISO 230-10; docs/cli.md, "Delay fit") along one axis
// and direction: `repeats` touches at each feed, each from the distance the axis needs to
// reach that feed (approach_room_mm) plus `margin_mm`, so every touch is at
// full speed. The program opens with a pause (the operator checks that the
// probe stands in front of the surface, at most `placement_mm` away) and a
// locating touch at the slowest feed that is not recorded. One axis and
// direction per program: neither LinuxCNC (M0 stays in Auto mode, m-code.adoc)
// nor grbl (jogging only when Idle, jogging.md) lets the operator jog the
// probe to another surface at a pause; the lab fits the groups of several
// imports pasted together. After each touch a rapid retract puts the
// probe at the next touch's start distance: the retract is that distance plus
// the overtravel the model predicts at the touch's feed (G38.2 stops where the
// axis stopped, not at the trigger).
struct DelayPlanOptions {
    AxisDirection touch{'Z', -1};
    // Empty: 30, 100, 300, 1000, 2000 mm/min and the scenario's probing feed.
    std::vector<double> feeds_mm_min;
    int repeats{5};
    double margin_mm{1.0};
    double placement_mm{10.0};
};
// The default feeds of the test: 30, 100, 300, 1000 and 2000 mm/min and the
// scenario's probing feed (docs/programs.md, `program delay`).
std::vector<double> default_delay_feeds(const Scenario& scenario);

// The ring-gauge calibration (docs/cli.md, "Ring gauge"): from the gauge
// centre, touches at X+, X-, Y+, Y- with the spindle at 0 deg, then the same
// four at 180 deg (the operator turns the spindle at a pause; every return is
// measured from the wall, so the probe is back at the centre), each point the scenario's
// strategy (two-touch: a fast touch, the backoff, the measuring touch).
struct RingPlanOptions {
    double gauge_diameter_mm{50.0};
    double ball_diameter_mm{6.0};
    // How far off the gauge centre the operator may leave the probe.
    double centre_tolerance_mm{1.0};
};

// The tuned cycle: the scenario's strategy, feeds, backoff and start distance
// (cycle.*), the touches of its feature (cycle.feature):
// - a surface along `touch` (the probe stands approach_mm in front of it);
// - a bore X+, X-, Y+, Y-, a pocket both walls along touch's axis (X or Y;
//   its sign is not used: + first, as the model): from the centre at the
//   measuring depth, a protected move (StepKind::guard, at
//   cycle.position_feed_mm_min) out to each touch's start
//   (start_radius_mm, cycle.h), the touch, a protected move back to the centre;
// - a boss its X+, X-, Y+, Y- sides, a web both sides along touch's axis:
//   from above the centre, cycle.clearance_mm over the measuring depth,
//   per side a protected move out over the start, one down by the clearance,
//   the touch toward the centre, a rapid up by the clearance, a protected move
//   back over the centre.
// The model moves straight from start to start; the programs go back through
// the centre between touches. Each touch's measuring touch is made
// cycle.repeats times, as the model averages them (single-touch: back to the
// start and again; two-touch: backed off from where it stopped and again),
// every one recorded.
// The plan holds what the feature's result needs (feature_result.h): the
// stylus's effective ball diameter, the model's uncertainty of one measured
// point (point_uncertainty_mm) and, with cycle.size_tolerance_mm set, the
// size's tolerance and what happens outside it.
struct CyclePlanOptions {
    AxisDirection touch{'Z', -1};
    // The stylus's effective ball diameter (the ring calibration's); 0: the
    // results are stylus-centre positions and distances.
    double ball_diameter_mm{0.0};
};

// Throw InputError naming the option and what is allowed.
ProbingPlan make_delay_plan(const Scenario& scenario, const DelayPlanOptions& options);
ProbingPlan make_ring_plan(const Scenario& scenario, const RingPlanOptions& options);
ProbingPlan make_cycle_plan(const Scenario& scenario, const CyclePlanOptions& options);

// The plan file (2-space JSON, "\n" at the end):
//   {"format": "probecycle-probing-plan", "version": 1, "kind": "delay",
//    "values": {"cycle.probe_feed_mm_min": "2000", ...},
//    "steps": [{"step": "pause", "text": "..."},
//              {"step": "probe", "axis": "Z", "direction": -1, "distance_mm": 3.1,
//               "feed_mm_min": 30, "recorded": true, "orientation_deg": 0, "text": ""},
//              {"step": "guard", "axis": "X", "direction": 1, "distance_mm": 20,
//               "feed_mm_min": 3000, "text": ""}, ...]}
std::string probing_plan_json(const ProbingPlan& plan);
// A plan file's problems.
class PlanError : public FileContentError {
  public:
    explicit PlanError(std::vector<FieldError> errors)
        : FileContentError(FileKind::plan, std::move(errors)) {}
};

// Throws PlanError listing every problem, keyed by its dotted path
// ("steps.3.feed_mm_min").
ProbingPlan parse_probing_plan(std::string_view text);
// 16 hex digits naming the plan (a hash of probing_plan_json): the program and the
// LinuxCNC log carry it, so that a log from another plan is told apart.
std::string plan_id(const ProbingPlan& plan);

// grbl's console holds no text of the program's (without more, a console from
// another plan with the same count of probes would import silently, every touch
// under the wrong feed). The grbl program therefore opens with a signature of
// the plan that grbl reports itself: twice, a protected move (G38.3) out in
// free air of kSignatureOut + d mm, then one back of d mm and a rapid back of
// kSignatureOut, where d = kSignatureFirst + code * kSignatureStep (two codes,
// each < kSignatureCodes, from the plan id). grbl answers each protected move
// with [PRB:...:0], so the import reads d from two reports' difference,
// whatever the start. One code in 6400 is shared by chance.
// The probe goes at most kSignatureOut + the largest d (1.09 mm) out, along
// Z+ (Z- when the plan's first probe moves along Z+, away from its surface).
constexpr int kSignatureCodes = 80;
constexpr double kSignatureFirst_mm = 0.20;
constexpr double kSignatureStep_mm = 0.01;
constexpr double kSignatureOut_mm = 0.10;
constexpr double kSignatureFeed_mm_min = 300.0;
struct PlanSignature {
    char axis{'Z'};
    int direction{1};                 // out: +1 or -1
    std::array<int, 2> codes{};       // each in [0, kSignatureCodes)
    std::array<double, 2> back_mm{};  // d of each pair
};
PlanSignature plan_signature(const ProbingPlan& plan);

}  // namespace probecycle
