#pragma once

// The scenario: machine, probe and cycle. Defaults describe a typical vertical
// machining centre with a standard (scanned) skip input and an optical probe;
// every one is a typical value, to be replaced by the user's measured one.

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/field_error.h"
#include "core/cycle/dynamics.h"
#include "core/cycle/motion.h"

namespace probecycle {

enum class Strategy { single_touch, two_touch };
enum class Feature { surface, web, pocket, bore, boss };
// A pocket or bore: the probe measures from inside, starting at the centre.
constexpr bool is_internal(Feature feature) {
    return feature == Feature::pocket || feature == Feature::bore;
}
// Number of touches of a feature (surface 1, web/pocket 2, bore/boss 4).
int touch_count(Feature feature);
// How many times a measuring touch may be repeated and averaged
// (cycle.repeats): the key's range and the optimiser's search.
constexpr int kMaxRepeats = 20;
// Where a two-touch backoff is measured from: where the probe
// stopped (Renishaw's cycles) or the trigger position the control recorded
// (the skip position many macros back off from).
enum class BackoffFrom { stop, trigger };
// What a cycle program does with a feature's size outside its tolerance
// (cycle.size_tolerance_mm): flag it (a variable and the log line) or stop
// with an alarm.
enum class ToleranceAction { flag, stop };

struct Machine {
    AccelModel accel_model{AccelModel::time_constant};
    double time_constant_s{kDefaultTimeConstant_s};
    double max_accel_mm_s2{2000.0};
    double max_jerk_mm_s3{40000.0};
    // Dynamics after interpolation (docs/model.md, "Controller dynamics after
    // interpolation"); none and 0 = the ideal axis.
    FilterKind filter{FilterKind::none};
    double filter_time_s{0.03};
    double filter2_time_s{0.01};
    double servo_time_constant_s{0.0};
    double in_position_mm{0.01};
    // The control's block change: time each move of the cycle adds after it
    // ends, before the next starts (Phase::block_change). 0 = none.
    double block_change_s{0.0};
    double rapid_feed_mm_min{30000.0};
    double scan_period_s{0.004};
    double controller_latency_s{0.002};
    bool latched_input{false};
    // Uncertainty budget (uncertainty.h): the axes' positioning
    // repeatability (2 sigma) and the thermal drift between calibration and
    // measurement (a half-width). Typical of a machining centre in a shop.
    double repeatability_2sigma_mm{0.002};
    double thermal_drift_mm{0.002};
    bool operator==(const Machine&) const = default;
};

struct Probe {
    double pretravel_mm{0.005};
    double interface_delay_s{0.002};
    double repeatability_2sigma_mm{0.001};
    // Uncertainty budget (uncertainty.h): the pretravel variation
    // over directions left after calibration (a half-width; a kinematic
    // probe's data sheet gives about 1 µm of 2D lobing), and the calibration
    // artefact's certified uncertainty (k = 2; a ring gauge's certificate).
    double lobing_mm{0.001};
    double artefact_uncertainty_mm{0.001};
    double overtravel_limit_mm{5.0};
    double reseat_mm{0.2};
    // Feed at which the probe was calibrated; 0 = the measuring feed.
    double calibration_feed_mm_min{0.0};
    // The maker's rated maximum probing speed; 0 = no limit. A probing or
    // measuring feed over it is an error (feed_over_probe_limit).
    double max_feed_mm_min{0.0};
    bool operator==(const Probe&) const = default;
};

struct Cycle {
    Strategy strategy{Strategy::two_touch};
    Feature feature{Feature::surface};
    // Distance between opposite stylus-centre contact points (web/pocket width,
    // bore/boss diameter less the ball diameter); unused for a surface.
    double feature_size_mm{50.0};
    double approach_mm{5.0};
    // How far the surface may lie from nominal; the start distance must cover
    // it plus the distance to reach the probing feed, so the touch is at full
    // feed wherever the part is. 0 = a known part. 0.5 mm by default, a part
    // set in a fixture or a vise by hand, or a casting's tolerance; a known
    // part is the exception.
    double part_position_uncertainty_mm{0.5};
    // How far a probing move searches past the farthest place its surface can
    // be: the nominal surface plus the part position uncertainty, or for a
    // second touch or a repeat where the touch before stopped. It must reach
    // past the touch's stop (search_ends_too_soon). 0 = automatic
    // (search_beyond_mm() in cycle.h).
    double search_beyond_mm{0.0};
    // Feed of the (first) touch; single-touch measures at it.
    double probe_feed_mm_min{2000.0};
    // Feed of the second, measuring touch of two-touch.
    double measure_feed_mm_min{30.0};
    double backoff_mm{2.0};
    BackoffFrom backoff_from{BackoffFrom::stop};
    // The measuring touch is made this many times and averaged: a
    // whole number, stored as a number as every key of the table is.
    double repeats{1.0};
    double return_feed_mm_min{10000.0};
    // Protected positioning moves of a feature (probe armed): between touches
    // and from/to the centre (docs/model.md, "Strategies and features").
    double position_feed_mm_min{3000.0};
    // The highest feed override the operator may turn the cycle up to, in %:
    // every overtravel check (the touches, the protected moves,
    // the searches and the backoff that must clear the first touch's stop)
    // holds at it. 120 %: an operator can turn every common control's dial
    // that far (Siemens' panels and LinuxCNC's sample configurations stop
    // there); Fanuc-type and Heidenhain panels reach 150 %, Haas' 200 %.
    double feed_override_max_pct{120.0};
    // Boss/web: height the probe lifts to, over the wall, between touches.
    double clearance_mm{10.0};
    double target_uncertainty_mm{0.0};  // 0 = no target
    // Bounds of what the optimiser proposes: no touch starts
    // closer to its surface than min_start_mm (a shop keeps the probe a
    // millimetre off a wall it has not yet found), and no touch is slower
    // than min_feed_mm_min (a probing feed a shop would accept).
    double min_start_mm{1.0};
    double min_feed_mm_min{10.0};
    // The cycle program's check of a feature's measured size: +- this about
    // its nominal size (feature_size_mm); 0 = no check.
    double size_tolerance_mm{0.0};
    ToleranceAction tolerance_action{ToleranceAction::flag};
    // The knee is the lowest feed whose cycle time is within this fraction of
    // the best (docs/model.md, "Cycle time against feed").
    double knee_tolerance{0.01};
    // Savings of optimised settings (the optimiser's report); 0 = not shown.
    double parts_per_year{0.0};
    double cycles_per_part{0.0};
    double machine_rate_per_hour{0.0};  // any currency
    bool operator==(const Cycle&) const = default;
};

struct Scenario {
    Machine machine;
    Probe probe;
    Cycle cycle;

    MotionLimits motion_limits() const;
    AxisDynamics axis_dynamics() const;
    bool operator==(const Scenario&) const = default;
};

// A scenario file's (or a --set's) problems.
class ScenarioError : public FileContentError {
  public:
    explicit ScenarioError(std::vector<FieldError> errors)
        : FileContentError(FileKind::scenario, std::move(errors)) {}
};

// Range checks and cross-field checks; empty when the scenario is valid.
std::vector<FieldError> validate(const Scenario& scenario);
void validate_or_throw(const Scenario& scenario);

// One table describes every key of the scenario file: its dotted name, kind,
// unit and range, a short label and what it means (both marked for
// translation, context "Parameter"). Validation, JSON in and out, --set,
// presets, the CLI's `defaults` and the window's editors and tooltips all
// read it; defaults come from the structs above.
enum class KeyKind { number, word, flag };  // word: one of a list (an enum)
struct KeyInfo {
    const char* key;   // "machine.scan_period_s"
    const char* unit;  // numbers: the internal unit ("s", "mm", "mm/min"); else ""
    double min;        // numbers: the allowed range, inclusive
    double max;
    const char* description;  // what it is and how it enters the model
    const char* label{""};    // a short name for an editor or a column
    KeyKind kind{KeyKind::number};
};
// Every key, in file order (sections machine, probe, cycle).
const std::vector<KeyInfo>& scenario_keys();
// The numeric keys, in file order.
const std::vector<KeyInfo>& numeric_keys();
// Lookup by dotted key: find_key() among the numeric keys, find_any_key()
// among all; nullptr when unknown.
const KeyInfo* find_key(std::string_view dotted_key);
const KeyInfo* find_any_key(std::string_view dotted_key);
// The sections, in file order, and the keys' names (without the section) of one.
const std::vector<std::string>& scenario_sections();
std::vector<std::string> section_key_names(std::string_view section);
// The words a word key allows, in order ("time_constant", ...); empty otherwise.
std::vector<std::string> allowed_words(const KeyInfo& key);
// A key's value in a scenario as the file writes it ("0.004", "two_touch", "true").
std::string value_text(const Scenario& scenario, const KeyInfo& key);
// Whether the scenario's acceleration model, filter, strategy and feature use
// the key (the jerk only under the jerk-limited model, the backoff only with two
// touches...): the window hides the editors of the others and the PDF report
// leaves them out. Unknown keys and keys every scenario uses give true.
bool key_applies(const Scenario& scenario, std::string_view dotted_key);

// Read/write a numeric key by dotted name (the UI's editors and --set use these).
std::optional<double> get_number(const Scenario& scenario, std::string_view dotted_key);
// Returns false when the key is not numeric; the value is not range-checked
// here. A negative zero is stored as zero.
bool set_number(Scenario& scenario, std::string_view dotted_key, double value);

// JSON. Parsing checks every key, type, enum word and range; it throws
// ScenarioError (naming the key or the line) and never returns a partial scenario.
Scenario scenario_from_json(std::string_view text);
// A partial scenario file (a preset) over `base`: only the keys it names
// change. Checked like scenario_from_json, all or nothing.
Scenario merge_json(const Scenario& base, std::string_view partial_json);
std::string scenario_to_json(const Scenario& scenario);
// One section ("machine") as a scenario file holding only it, every key of it
// written as scenario_to_json writes it: {"machine": {...}}.
std::string scenario_section_to_json(const Scenario& scenario, std::string_view section);
// `--set section.key=value`: a decimal number, true/false, or a bare enum word;
// white space around the value is ignored.
void apply_setting(Scenario& scenario, std::string_view assignment);

const char* to_string(Strategy strategy);
const char* to_string(BackoffFrom from);
const char* to_string(ToleranceAction action);
const char* to_string(Feature feature);
// The feature's name ("bore") as a message argument, translated where it is
// shown (the CLI prints the English word, the key file's).
MessageArg feature_arg(std::string name, Feature feature);
std::optional<Strategy> strategy_from_string(std::string_view word);
std::optional<BackoffFrom> backoff_from_from_string(std::string_view word);
std::optional<ToleranceAction> tolerance_action_from_string(std::string_view word);
std::optional<Feature> feature_from_string(std::string_view word);
std::optional<AccelModel> accel_model_from_string(std::string_view word);
std::optional<FilterKind> filter_kind_from_string(std::string_view word);

}  // namespace probecycle
