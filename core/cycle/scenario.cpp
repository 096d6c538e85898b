#include "core/cycle/scenario.h"

#include "core/common/json_guard.h"
#include "core/common/number_format.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

constexpr std::array kAccelModels = {AccelModel::time_constant, AccelModel::constant_accel,
                                     AccelModel::jerk_limited, AccelModel::none};
constexpr std::array kFilterKinds = {FilterKind::none, FilterKind::linear, FilterKind::exponential,
                                     FilterKind::bell};
constexpr std::array kStrategies = {Strategy::single_touch, Strategy::two_touch};
constexpr std::array kBackoffFroms = {BackoffFrom::stop, BackoffFrom::trigger};
constexpr std::array kToleranceActions = {ToleranceAction::flag, ToleranceAction::stop};
constexpr std::array kFeatures = {Feature::surface, Feature::web, Feature::pocket, Feature::bore,
                                  Feature::boss};

// The words of an enum, from its own to_string, so the list cannot drift.
template <typename Enum, std::size_t N>
std::vector<std::string> enum_words(const std::array<Enum, N>& values) {
    std::vector<std::string> words;
    words.reserve(N);
    for (const Enum v : values) words.emplace_back(to_string(v));
    return words;
}

template <typename Enum>
bool set_from(Enum& field, std::optional<Enum> value) {
    if (!value) return false;
    field = *value;
    return true;
}

// A key of the table and where it lives in the scenario.
struct KeyEntry {
    KeyInfo info;
    double& (*number)(Scenario&) = nullptr;  // number keys
    bool& (*flag)(Scenario&) = nullptr;      // flag keys
    std::vector<std::string> words;          // word keys: allowed, in order
    std::string (*get_word)(const Scenario&) = nullptr;
    bool (*set_word)(Scenario&, std::string_view) = nullptr;
};

KeyEntry number(KeyInfo info, double& (*ref)(Scenario&)) {
    KeyEntry e;
    e.info = info;
    e.number = ref;
    return e;
}

KeyEntry flag(KeyInfo info, bool& (*ref)(Scenario&)) {
    KeyEntry e;
    e.info = info;
    e.flag = ref;
    return e;
}

KeyEntry word(KeyInfo info, std::vector<std::string> words, std::string (*get)(const Scenario&),
              bool (*set)(Scenario&, std::string_view)) {
    KeyEntry e;
    e.info = info;
    e.words = std::move(words);
    e.get_word = get;
    e.set_word = set;
    return e;
}

#define PC_NUMBER(section, field) ([](Scenario& s) -> double& { return s.section.field; })

// The one table of scenario keys, in file order. Ranges are what a real
// machine or probe can plausibly have; zero is allowed where delays and
// distances may be 0. Labels and descriptions are the window's (translated
// there, context "Parameter"); units are the internal ones.
const std::vector<KeyEntry>& key_table() {
    static const std::vector<KeyEntry> table = {
        word(
            {"machine.accel_model", "", 0.0, 0.0,
             QT_TRANSLATE_NOOP("Parameter",
                               "How the control accelerates before interpolation: a time "
                               "constant (a = v/T, common on many controls), a constant "
                               "acceleration, a jerk-limited S-curve, or none (the feed is "
                               "commanded at once and stopped at once, as on a skip block "
                               "without acc/dec; then the filter after interpolation and the "
                               "servo shape the motion). Sets every move time and the braking "
                               "distance after the trigger."),
             QT_TRANSLATE_NOOP("Parameter", "Acceleration model"), KeyKind::word},
            enum_words<AccelModel>(kAccelModels),
            [](const Scenario& s) { return std::string(to_string(s.machine.accel_model)); },
            [](Scenario& s, std::string_view w) {
                return set_from(s.machine.accel_model, accel_model_from_string(w));
            }),
        number(
            {"machine.time_constant_s", "s", 0.001, 2.0,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "Acceleration time constant T: the control reaches any programmed feed in T (a "
                 "= v/T). Sets the distance to reach the feed (v*T/2) and the braking distance "
                 "after the trigger, and so overtravel and cycle time. Used by the time-constant "
                 "model."),
             QT_TRANSLATE_NOOP("Parameter", "Time constant")},
            PC_NUMBER(machine, time_constant_s)),
        number({"machine.max_accel_mm_s2", "mm/s^2", 1.0, 200000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Maximum axis acceleration, used by the constant-acceleration and jerk-limited "
                    "models for every move and for braking after the trigger."),
                QT_TRANSLATE_NOOP("Parameter", "Max. acceleration")},
               PC_NUMBER(machine, max_accel_mm_s2)),
        number({"machine.max_jerk_mm_s3", "mm/s^3", 10.0, 1.0e9,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Maximum axis jerk, used by the jerk-limited (S-curve) model: lower jerk "
                    "lengthens every acceleration and the braking after the trigger."),
                QT_TRANSLATE_NOOP("Parameter", "Max. jerk")},
               PC_NUMBER(machine, max_jerk_mm_s3)),
        word(
            {"machine.filter", "", 0.0, 0.0,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "Acc/dec filter after interpolation: none, linear (a moving average of the "
                 "commanded speed over the filter time), exponential (first order, time "
                 "constant = the filter time) or bell (two moving averages, the filter time and "
                 "the second filter time). After the trigger the axis drains it: v*T/2 more "
                 "(linear), v*T (exponential), v*(T1+T2)/2 (bell)."),
             QT_TRANSLATE_NOOP("Parameter", "Filter after interpolation"), KeyKind::word},
            enum_words<FilterKind>(kFilterKinds),
            [](const Scenario& s) { return std::string(to_string(s.machine.filter)); },
            [](Scenario& s, std::string_view w) {
                return set_from(s.machine.filter, filter_kind_from_string(w));
            }),
        number({"machine.filter_time_s", "s", 0.0005, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Time of the filter after interpolation: the linear filter's window, the "
                    "exponential filter's time constant, or the bell filter's first window "
                    "(Fanuc: the cutting-feed acc/dec time constant)."),
                QT_TRANSLATE_NOOP("Parameter", "Filter time")},
               PC_NUMBER(machine, filter_time_s)),
        number({"machine.filter2_time_s", "s", 0.0005, 1.0,
                QT_TRANSLATE_NOOP("Parameter",
                                  "Second window of the bell filter after interpolation (the "
                                  "S-shaping time)."),
                QT_TRANSLATE_NOOP("Parameter", "Second filter time")},
               PC_NUMBER(machine, filter2_time_s)),
        number({"machine.servo_time_constant_s", "s", 0.0, 0.5,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Servo time constant Tp = 1/Kv (position loop gain): the axis trails the "
                    "command by v*Tp and, after the command stops, travels that much more. 0 = "
                    "the axis follows the command exactly."),
                QT_TRANSLATE_NOOP("Parameter", "Servo time constant")},
               PC_NUMBER(machine, servo_time_constant_s)),
        number({"machine.in_position_mm", "mm", 0.0001, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "In-position width: with a filter or a servo lag, a move counts as done "
                    "when the axis is within this of its commanded end, and the next move "
                    "starts then. The overtravel is still where the axis comes to rest."),
                QT_TRANSLATE_NOOP("Parameter", "In-position width")},
               PC_NUMBER(machine, in_position_mm)),
        number({"machine.block_change_s", "s", 0.0, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Time the control adds at each block change, after a move ends and before "
                    "the next starts: block processing, the wait for the in-position check and, "
                    "after a probing move, for the skip position to be read. Every move of the "
                    "cycle (touches, backoffs, returns, positioning moves) adds it once. 0 means "
                    "none."),
                QT_TRANSLATE_NOOP("Parameter", "Block change time")},
               PC_NUMBER(machine, block_change_s)),
        number(
            {"machine.rapid_feed_mm_min", "mm/min", 100.0, 200000.0,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "Rapid feed: a boss or web lifts over its wall at it, away from the part. Moves "
                 "toward the part are protected, at the positioning feed."),
             QT_TRANSLATE_NOOP("Parameter", "Rapid feed")},
            PC_NUMBER(machine, rapid_feed_mm_min)),
        number(
            {"machine.scan_period_s", "s", 0.0, 0.1,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "Period at which the control scans the skip input (about 4 ms on a standard "
                 "input, 4 µs on a high-speed input). The wait for the next scan, from nothing "
                 "to a full period, is the single-touch uncertainty (trigger speed × scan "
                 "period); the overtravel takes the worst case, a full period of travel, and the "
                 "cycle time the mean wait, half a period."),
             QT_TRANSLATE_NOOP("Parameter", "Scan period")},
            PC_NUMBER(machine, scan_period_s)),
        number({"machine.controller_latency_s", "s", 0.0, 0.5,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Fixed latency of the control after it has seen the input. Removed by "
                    "calibration, but the axis keeps moving: adds trigger speed × latency to the "
                    "overtravel."),
                QT_TRANSLATE_NOOP("Parameter", "Machine response time")},
               PC_NUMBER(machine, controller_latency_s)),
        flag({"machine.latched_input", "", 0.0, 0.0,
              QT_TRANSLATE_NOOP("Parameter",
                                "The control latches (or timestamps) the position in hardware at "
                                "the trigger: the scan-period wait leaves the measured value, but "
                                "not the travel - the machine still stops late."),
              QT_TRANSLATE_NOOP("Parameter", "Latched (hardware-captured) input"), KeyKind::flag},
             [](Scenario& s) -> bool& { return s.machine.latched_input; }),
        number({"machine.repeatability_2sigma_mm", "mm", 0.0, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Unidirectional positioning repeatability of the axes, 2 sigma, from the "
                    "machine's acceptance test (ISO 230-2 states R = 4 sigma: enter R/2). A term "
                    "of the uncertainty budget: u = value/2, the same for repeated touches."),
                QT_TRANSLATE_NOOP("Parameter", "Positioning repeatability (2σ)")},
               PC_NUMBER(machine, repeatability_2sigma_mm)),
        number({"machine.thermal_drift_mm", "mm", 0.0, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "How far the machine's and the part's temperature may move the measured "
                    "point between calibration and measurement, ± (measure it: probe an artefact "
                    "again after the time a batch takes). A term of the uncertainty budget: u = "
                    "value/√3, the same for repeated touches."),
                QT_TRANSLATE_NOOP("Parameter", "Thermal drift (±)")},
               PC_NUMBER(machine, thermal_drift_mm)),
        number({"probe.pretravel_mm", "mm", 0.0, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Mechanical pretravel from first contact to the trigger threshold (typically "
                    "1-50 µm). Independent of speed and removed by calibration; adds to the "
                    "overtravel and takes pretravel / speed."),
                QT_TRANSLATE_NOOP("Parameter", "Pretravel")},
               PC_NUMBER(probe, pretravel_mm)),
        number({"probe.interface_delay_s", "s", 0.0, 0.5,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Time the probe interface (receiver) needs to pass the trigger to the control. "
                    "Constant, so calibration removes it from the measured value, but it adds "
                    "trigger speed × delay to the overtravel."),
                QT_TRANSLATE_NOOP("Parameter", "Interface response time")},
               PC_NUMBER(probe, interface_delay_s)),
        number({"probe.repeatability_2sigma_mm", "mm", 0.0, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Unidirectional repeatability of the probe, 2 sigma. A term of the "
                    "uncertainty budget with the scan-period range: u = value/2, averaged "
                    "over repeated touches."),
                QT_TRANSLATE_NOOP("Parameter", "Repeatability (2σ)")},
               PC_NUMBER(probe, repeatability_2sigma_mm)),
        number({"probe.lobing_mm", "mm", 0.0, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Pretravel variation over the directions the cycle probes that calibration "
                    "leaves, ± (the data sheet's 2D lobing: about 1 µm for a kinematic probe, "
                    "0.25 µm for a strain-gauge one; 0 when the probe is calibrated in every "
                    "direction it measures). A term of the uncertainty budget: u = value/√3, the "
                    "same for repeated touches."),
                QT_TRANSLATE_NOOP("Parameter", "Lobing (±)")},
               PC_NUMBER(probe, lobing_mm)),
        number({"probe.artefact_uncertainty_mm", "mm", 0.0, 1.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Expanded uncertainty (k = 2) of the artefact the probe is calibrated on, "
                    "from its calibration certificate (a ring gauge's diameter, a gauge block's "
                    "length). A term of the uncertainty budget: u = value/2, the same for "
                    "repeated touches."),
                QT_TRANSLATE_NOOP("Parameter", "Calibration artefact (k = 2)")},
               PC_NUMBER(probe, artefact_uncertainty_mm)),
        number({"probe.overtravel_limit_mm", "mm", 0.01, 100.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Stylus deflection range of the probe in the probing direction. The axis must "
                    "stop within it or the probe or stylus is damaged; short styli along Z and "
                    "small bores are the critical cases."),
                QT_TRANSLATE_NOOP("Parameter", "Overtravel limit")},
               PC_NUMBER(probe, overtravel_limit_mm)),
        number(
            {"probe.reseat_mm", "mm", 0.0, 10.0,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "Distance the probe needs to reseat after a trigger. The two-touch backoff must "
                 "clear the first touch's overtravel plus this."),
             QT_TRANSLATE_NOOP("Parameter", "Reseat distance")},
            PC_NUMBER(probe, reseat_mm)),
        number({"probe.calibration_feed_mm_min", "mm/min", 0.0, 100000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Feed at which the probe was calibrated. Measuring at another feed shifts the "
                    "delay travel and so the measured value; 0 means calibrated at the measuring "
                    "feed."),
                QT_TRANSLATE_NOOP("Parameter", "Calibration feed")},
               PC_NUMBER(probe, calibration_feed_mm_min)),
        number({"probe.max_feed_mm_min", "mm/min", 0.0, 100000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "The probe maker's rated maximum probing speed. A touch faster than it is an "
                    "error: the probe may not trigger reliably or may be damaged. 0 means no "
                    "limit."),
                QT_TRANSLATE_NOOP("Parameter", "Probe's maximum feed")},
               PC_NUMBER(probe, max_feed_mm_min)),
        word(
            {"cycle.strategy", "", 0.0, 0.0,
             QT_TRANSLATE_NOOP("Parameter",
                               "Single-touch measures at the probing feed. Two-touch finds the "
                               "surface fast, backs off, and measures with a slow second touch."),
             QT_TRANSLATE_NOOP("Parameter", "Strategy"), KeyKind::word},
            enum_words<Strategy>(kStrategies),
            [](const Scenario& s) { return std::string(to_string(s.cycle.strategy)); },
            [](Scenario& s, std::string_view w) {
                return set_from(s.cycle.strategy, strategy_from_string(w));
            }),
        word(
            {"cycle.feature", "", 0.0, 0.0,
             QT_TRANSLATE_NOOP("Parameter",
                               "A surface needs one touch, a web or pocket two opposite touches, "
                               "a bore or boss four; the probe moves out from the feature's "
                               "centre to each touch and back at the positioning feed."),
             QT_TRANSLATE_NOOP("Parameter", "Feature"), KeyKind::word},
            enum_words<Feature>(kFeatures),
            [](const Scenario& s) { return std::string(to_string(s.cycle.feature)); },
            [](Scenario& s, std::string_view w) {
                return set_from(s.cycle.feature, feature_from_string(w));
            }),
        number({"cycle.feature_size_mm", "mm", 0.0, 10000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Distance between opposite stylus-centre contact points: web or pocket width, "
                    "bore or boss diameter less the ball diameter. Sets the positioning moves "
                    "out from the centre to each touch and back; unused for a surface."),
                QT_TRANSLATE_NOOP("Parameter", "Feature size")},
               PC_NUMBER(cycle, feature_size_mm)),
        number(
            {"cycle.approach_mm", "mm", 0.0, 1000.0,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "Start distance in front of the nominal surface. Must cover the part's position "
                 "uncertainty, and should cover the distance needed to reach the feed so the "
                 "touch happens at full speed. Approached at the probing feed, returned at the "
                 "return feed."),
             QT_TRANSLATE_NOOP("Parameter", "Approach distance")},
            PC_NUMBER(cycle, approach_mm)),
        number({"cycle.part_position_uncertainty_mm", "mm", 0.0, 100.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "How far the surface may lie from its nominal position (a casting, a part "
                    "clamped by hand). The start distance must cover it plus the distance to "
                    "reach the probing feed, so the touch is at full feed wherever the part "
                    "lies. 0 means a known part: its surface is where the drawing puts it."),
                QT_TRANSLATE_NOOP("Parameter", "Part position uncertainty")},
               PC_NUMBER(cycle, part_position_uncertainty_mm)),
        number({"cycle.search_beyond_mm", "mm", 0.0, 100.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "How far each probing move searches past the farthest place its surface can "
                    "be (the nominal surface plus the part position uncertainty; for a second "
                    "touch or a repeat, where the touch before stopped) before the control gives "
                    "up. It must reach past the touch's stop: a search that ends sooner is "
                    "braking when it touches, triggers below the feed and stops at its end. 0 "
                    "means automatic: halfway from the touch's stop to the probe's overtravel "
                    "limit."),
                QT_TRANSLATE_NOOP("Parameter", "Search beyond surface")},
               PC_NUMBER(cycle, search_beyond_mm)),
        number(
            {"cycle.probe_feed_mm_min", "mm/min", 1.0, 100000.0,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "Feed of the (first) touch; single-touch measures at it. A higher feed shortens "
                 "the approach but lengthens the braking, the overtravel and the return, and "
                 "raises the single-touch uncertainty."),
             QT_TRANSLATE_NOOP("Parameter", "Probing feedrate")},
            PC_NUMBER(cycle, probe_feed_mm_min)),
        number({"cycle.measure_feed_mm_min", "mm/min", 1.0, 100000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Feed of the second, measuring touch of two-touch (typically 30 mm/min). Sets "
                    "the two-touch uncertainty; the second approach, the backoff less where the "
                    "first touch stopped (on average), is travelled at it."),
                QT_TRANSLATE_NOOP("Parameter", "Measuring feedrate")},
               PC_NUMBER(cycle, measure_feed_mm_min)),
        number({"cycle.backoff_mm", "mm", 0.0, 1000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Two-touch: distance the probe backs off after the first touch, from where "
                    "it stopped or from the recorded trigger position (Backoff from). It must "
                    "leave the second touch room to reseat the probe and to reach the measuring "
                    "feed; any more is approached again at the slow measuring feed and wasted."),
                QT_TRANSLATE_NOOP("Parameter", "Backoff")},
               PC_NUMBER(cycle, backoff_mm)),
        number({"cycle.repeats", "", 1.0, kMaxRepeats,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "How many times the measuring touch is made and averaged (two-touch: back "
                    "off and touch again at the measuring feed; single-touch: back to the start "
                    "and touch again). The random parts of the uncertainty, scan phase and "
                    "repeatability, fall by the square root of this; each repeat adds its moves "
                    "to the cycle. A whole number."),
                QT_TRANSLATE_NOOP("Parameter", "Measurements")},
               PC_NUMBER(cycle, repeats)),
        word(
            {"cycle.backoff_from", "", 0.0, 0.0,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "Two-touch: where the backoff is measured from. stop: from where the probe "
                 "stopped after the first touch (Renishaw's cycles). trigger: from the trigger "
                 "position the control recorded (the skip position a macro reads); the axis "
                 "then moves back its overtravel beyond that position as well."),
             QT_TRANSLATE_NOOP("Parameter", "Backoff from"), KeyKind::word},
            enum_words<BackoffFrom>(kBackoffFroms),
            [](const Scenario& s) { return std::string(to_string(s.cycle.backoff_from)); },
            [](Scenario& s, std::string_view w) {
                return set_from(s.cycle.backoff_from, backoff_from_from_string(w));
            }),
        number({"cycle.return_feed_mm_min", "mm/min", 1.0, 200000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Feed of the backoff and of the return to the start position (start distance "
                    "plus overtravel)."),
                QT_TRANSLATE_NOOP("Parameter", "Return feedrate")},
               PC_NUMBER(cycle, return_feed_mm_min)),
        number({"cycle.position_feed_mm_min", "mm/min", 1.0, 100000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Web, pocket, bore, boss: feed of the protected positioning moves (probe "
                    "armed, so a collision stops the axis) from the feature's centre out to each "
                    "touch and back to the centre."),
                QT_TRANSLATE_NOOP("Parameter", "Positioning feed")},
               PC_NUMBER(cycle, position_feed_mm_min)),
        number({"cycle.feed_override_max_pct", "%", 100.0, 200.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "The highest feed override the operator may turn the cycle up to. Feed "
                    "override speeds up every move at feed, the touches and the protected "
                    "positioning moves too, so every overtravel check holds at it: the stylus's "
                    "limit, the searches past each stop and the backoff that must clear the first "
                    "touch's stop. The cycle time is at 100 %. 120 % is as far as every common "
                    "control's dial turns; set what your machine's panel allows (Fanuc-type and "
                    "Heidenhain 150 %, Haas 200 %), or 100 where the program locks the override."),
                QT_TRANSLATE_NOOP("Parameter", "Highest feed override")},
               PC_NUMBER(cycle, feed_override_max_pct)),
        number({"cycle.clearance_mm", "mm", 0.0, 1000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Boss or web: height the probe lifts above the measuring depth to pass over "
                    "the wall between touches (up at the rapid feed, down at the positioning "
                    "feed)."),
                QT_TRANSLATE_NOOP("Parameter", "Clearance height")},
               PC_NUMBER(cycle, clearance_mm)),
        number({"cycle.target_uncertainty_mm", "mm", 0.0, 10.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Target for the expanded (k = 2) uncertainty of the measured point, the whole "
                    "budget (the trigger's part and the terms no feed changes); a warning "
                    "appears above it. 0 means no target."),
                QT_TRANSLATE_NOOP("Parameter", "Target uncertainty")},
               PC_NUMBER(cycle, target_uncertainty_mm)),
        number({"cycle.min_start_mm", "mm", 0.0, 100.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "The shortest start distance the optimiser proposes: no touch starts closer "
                    "to its nominal surface, whatever the part position uncertainty and the feed "
                    "allow. 0 means no minimum."),
                QT_TRANSLATE_NOOP("Parameter", "Shortest approach")},
               PC_NUMBER(cycle, min_start_mm)),
        number({"cycle.min_feed_mm_min", "mm/min", 1.0, 1000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "The slowest probing or measuring feed the optimiser proposes (the probe "
                    "maker's or the shop's slowest probing speed); with the probe's maximum "
                    "feed and the rapid feed it bounds every feed the optimiser tries."),
                QT_TRANSLATE_NOOP("Parameter", "Slowest feed")},
               PC_NUMBER(cycle, min_feed_mm_min)),
        number({"cycle.size_tolerance_mm", "mm", 0.0, 100.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Web, pocket, bore, boss: the cycle program checks the measured size (width "
                    "or diameter) against the feature size plus or minus this, and the import "
                    "does the same. 0 means no check."),
                QT_TRANSLATE_NOOP("Parameter", "Size tolerance")},
               PC_NUMBER(cycle, size_tolerance_mm)),
        word(
            {"cycle.tolerance_action", "", 0.0, 0.0,
             QT_TRANSLATE_NOOP(
                 "Parameter",
                 "What the cycle program does when the measured size is outside its tolerance. "
                 "flag: sets its out-of-tolerance variable and writes OUT OF TOLERANCE to its "
                 "log, then goes on. stop: the same, then stops with an alarm."),
             QT_TRANSLATE_NOOP("Parameter", "If out of tolerance"), KeyKind::word},
            enum_words<ToleranceAction>(kToleranceActions),
            [](const Scenario& s) { return std::string(to_string(s.cycle.tolerance_action)); },
            [](Scenario& s, std::string_view w) {
                return set_from(s.cycle.tolerance_action, tolerance_action_from_string(w));
            }),
        number({"cycle.knee_tolerance", "", 0.0, 0.5,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "The knee is the lowest probing feed whose cycle time is within this fraction "
                    "of the fastest cycle, among the feeds whose overtravel stays within the "
                    "probe's limit. Faster than the knee buys little time for more overtravel and "
                    "uncertainty."),
                QT_TRANSLATE_NOOP("Parameter", "Knee tolerance")},
               PC_NUMBER(cycle, knee_tolerance)),
        number({"cycle.parts_per_year", "", 0.0, 1e9,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "Parts made per year, for the savings: time saved per part times this. 0 "
                    "means savings are not shown."),
                QT_TRANSLATE_NOOP("Parameter", "Parts per year")},
               PC_NUMBER(cycle, parts_per_year)),
        number({"cycle.cycles_per_part", "", 0.0, 10000.0,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "How many times this probing cycle runs per part, for the savings. 0 means "
                    "savings are not shown."),
                QT_TRANSLATE_NOOP("Parameter", "Cycles per part")},
               PC_NUMBER(cycle, cycles_per_part)),
        number({"cycle.machine_rate_per_hour", "", 0.0, 1e6,
                QT_TRANSLATE_NOOP(
                    "Parameter",
                    "What an hour of the machine costs, in any currency, for the savings per "
                    "year. 0 means the savings are shown in hours only."),
                QT_TRANSLATE_NOOP("Parameter", "Machine rate per hour")},
               PC_NUMBER(cycle, machine_rate_per_hour)),
    };
    return table;
}

#undef PC_NUMBER

const KeyEntry* find_entry(std::string_view key) {
    for (const KeyEntry& e : key_table()) {
        if (key == e.info.key) return &e;
    }
    return nullptr;
}

// Values in messages: 12 digits, so a value just out of range reads as such.
std::string number_text(double value) {
    return format_number(value, 12);
}

Message range_text(const KeyInfo& info) {
    return range_allowed(info.min, info.max, info.unit);
}

std::string join(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) {
        if (!out.empty()) out += ", ";
        out += w;
    }
    return out;
}

// What a key allows, for its error message.
Message allowed_for(const KeyEntry& e) {
    if (e.number != nullptr) return range_text(e.info);
    if (e.flag != nullptr) {
        return allowed_text("not_a_bool", QT_TRANSLATE_NOOP("FieldError", "true or false"));
    }
    Message m = allowed_text("unknown_word", QT_TRANSLATE_NOOP("FieldError", "one of %1"));
    m.args = {text_arg("allowed_words", join(e.words))};
    return m;
}

Message unknown_key(const std::string& section, const std::string& keys) {
    Message m = allowed_text("unknown_key",
                             QT_TRANSLATE_NOOP("FieldError", "unknown key; allowed in %1: %2"));
    m.args = {text_arg("section", section), text_arg("allowed_keys", keys)};
    return m;
}

Message unknown_section() {
    Message m = allowed_text("unknown_section",
                             QT_TRANSLATE_NOOP("FieldError", "unknown section; allowed: %1"));
    m.args = {text_arg("allowed_sections", join(scenario_sections()))};
    return m;
}

Message with_detail(const char* code, const char* text, std::string detail) {
    Message m = allowed_text(code, text);
    m.args = {text_arg("detail", std::move(detail))};
    return m;
}

// -0 and +0 are one value; the files and reports write 0. A subnormal
// number (under 2.2e-308) cannot be told from zero by the model: its inverse
// overflows (a servo time constant of 4.9e-324 s gave a NaN cycle time), so
// it is zero too.
double without_negative_zero(double value) {
    return value == 0.0 || std::fpclassify(value) == FP_SUBNORMAL ? 0.0 : value;
}

// Deeper than a scenario needs (root, section, value, and one more so that a
// list given as a value is refused as a wrong type, not as nesting).
constexpr std::size_t kMaxJsonDepth = 4;

}  // namespace

MotionLimits Scenario::motion_limits() const {
    return {machine.accel_model, machine.time_constant_s, machine.max_accel_mm_s2,
            machine.max_jerk_mm_s3};
}

AxisDynamics Scenario::axis_dynamics() const {
    return {machine.filter, machine.filter_time_s, machine.filter2_time_s,
            machine.servo_time_constant_s, machine.in_position_mm};
}

int touch_count(Feature feature) {
    switch (feature) {
        case Feature::surface:
            return 1;
        case Feature::web:
        case Feature::pocket:
            return 2;
        case Feature::bore:
        case Feature::boss:
            return 4;
    }
    return 1;
}

bool key_applies(const Scenario& scenario, std::string_view dotted_key) {
    const Machine& m = scenario.machine;
    const Cycle& c = scenario.cycle;
    const bool two_touch = c.strategy == Strategy::two_touch;
    const bool several_touches = touch_count(c.feature) > 1;
    // A boss or web is touched from outside: the probe lifts over it at the rapid feed.
    const bool lifts = c.feature == Feature::boss || c.feature == Feature::web;
    struct Rule {
        std::string_view key;
        bool applies;
    };
    const Rule rules[] = {
        {"machine.time_constant_s", m.accel_model == AccelModel::time_constant},
        {"machine.max_accel_mm_s2",
         m.accel_model == AccelModel::constant_accel || m.accel_model == AccelModel::jerk_limited},
        {"machine.max_jerk_mm_s3", m.accel_model == AccelModel::jerk_limited},
        {"machine.filter_time_s", m.filter != FilterKind::none},
        {"machine.filter2_time_s", m.filter == FilterKind::bell},
        {"machine.in_position_mm", scenario.axis_dynamics().active()},
        {"machine.rapid_feed_mm_min", lifts},
        {"cycle.position_feed_mm_min", several_touches},
        {"cycle.clearance_mm", lifts},
        {"cycle.feature_size_mm", several_touches},
        {"cycle.size_tolerance_mm", several_touches},
        {"cycle.tolerance_action", several_touches && c.size_tolerance_mm > 0.0},
        {"cycle.measure_feed_mm_min", two_touch},
        {"cycle.backoff_mm", two_touch},
        {"cycle.backoff_from", two_touch},
    };
    for (const Rule& rule : rules) {
        if (rule.key == dotted_key) return rule.applies;
    }
    return true;
}

const std::vector<KeyInfo>& scenario_keys() {
    static const std::vector<KeyInfo> keys = [] {
        std::vector<KeyInfo> out;
        for (const KeyEntry& e : key_table()) out.push_back(e.info);
        return out;
    }();
    return keys;
}

const std::vector<KeyInfo>& numeric_keys() {
    static const std::vector<KeyInfo> keys = [] {
        std::vector<KeyInfo> out;
        for (const KeyEntry& e : key_table()) {
            if (e.number != nullptr) out.push_back(e.info);
        }
        return out;
    }();
    return keys;
}

const KeyInfo* find_key(std::string_view dotted_key) {
    const KeyEntry* e = find_entry(dotted_key);
    return e != nullptr && e->number != nullptr ? &e->info : nullptr;
}

const KeyInfo* find_any_key(std::string_view dotted_key) {
    const KeyEntry* e = find_entry(dotted_key);
    return e != nullptr ? &e->info : nullptr;
}

const std::vector<std::string>& scenario_sections() {
    static const std::vector<std::string> sections = [] {
        std::vector<std::string> out;
        for (const KeyEntry& e : key_table()) {
            const std::string_view key = e.info.key;
            const std::string section(key.substr(0, key.find('.')));
            if (std::find(out.begin(), out.end(), section) == out.end()) out.push_back(section);
        }
        return out;
    }();
    return sections;
}

std::vector<std::string> section_key_names(std::string_view section) {
    std::vector<std::string> names;
    for (const KeyEntry& e : key_table()) {
        const std::string_view key = e.info.key;
        const std::size_t dot = key.find('.');
        if (key.substr(0, dot) == section) names.emplace_back(key.substr(dot + 1));
    }
    return names;
}

std::vector<std::string> allowed_words(const KeyInfo& key) {
    const KeyEntry* e = find_entry(key.key);
    return e != nullptr ? e->words : std::vector<std::string>{};
}

std::string value_text(const Scenario& scenario, const KeyInfo& key) {
    const KeyEntry* e = find_entry(key.key);
    if (e == nullptr) return {};
    auto& s = const_cast<Scenario&>(scenario);  // the accessors only read here
    if (e->number != nullptr) return number_text(e->number(s));
    if (e->flag != nullptr) return e->flag(s) ? "true" : "false";
    return e->get_word(scenario);
}

std::optional<double> get_number(const Scenario& scenario, std::string_view dotted_key) {
    const KeyEntry* e = find_entry(dotted_key);
    if (e == nullptr || e->number == nullptr) return std::nullopt;
    return e->number(const_cast<Scenario&>(scenario));  // the accessor only reads here
}

bool set_number(Scenario& scenario, std::string_view dotted_key, double value) {
    const KeyEntry* e = find_entry(dotted_key);
    if (e == nullptr || e->number == nullptr) return false;
    e->number(scenario) = without_negative_zero(value);
    return true;
}

std::vector<FieldError> validate(const Scenario& scenario) {
    std::vector<FieldError> errors;
    for (const KeyInfo& key : numeric_keys()) {
        const double value = *get_number(scenario, key.key);
        if (!std::isfinite(value) || value < key.min || value > key.max) {
            errors.push_back({key.key, number_text(value), range_text(key)});
        }
    }
    // Internal features: both start positions lie inside the feature
    // (docs/model.md, "Strategies and features"), so it must be wider than two
    // approach distances.
    const Cycle& c = scenario.cycle;
    if (is_internal(c.feature) && !(c.feature_size_mm > 2.0 * c.approach_mm)) {
        Message allowed = allowed_text(
            "feature_narrower_than_approach",
            QT_TRANSLATE_NOOP("FieldError", "more than twice cycle.approach_mm (%1) for a %2"));
        allowed.args = {arg("min_size_mm", ArgKind::length_mm, 2.0 * c.approach_mm),
                        feature_arg("feature", c.feature)};
        errors.push_back({"cycle.feature_size_mm", number_text(c.feature_size_mm), allowed});
    }
    // A count of measurements (cycle.repeats): a whole number.
    if (std::isfinite(c.repeats) && c.repeats != std::floor(c.repeats)) {
        const KeyInfo& key = *find_key("cycle.repeats");
        Message allowed = allowed_text(
            "not_a_whole_number", QT_TRANSLATE_NOOP("FieldError", "a whole number from %1 to %2"));
        allowed.args = {text_arg("min", number_text(key.min)),
                        text_arg("max", number_text(key.max))};
        errors.push_back({key.key, number_text(c.repeats), allowed});
    }
    return errors;
}

void validate_or_throw(const Scenario& scenario) {
    std::vector<FieldError> errors = validate(scenario);
    if (!errors.empty()) throw ScenarioError(std::move(errors));
}

Scenario merge_json(const Scenario& base, std::string_view text) {
    // What nlohmann would accept silently or crash on: depth, NUL bytes,
    // duplicate and empty keys, numbers too large (with key and line).
    if (std::optional<FieldError> error = check_json_text(text, kMaxJsonDepth)) {
        throw ScenarioError({std::move(*error)});
    }
    Json root;
    try {
        root = Json::parse(text.begin(), text.end());
    } catch (const nlohmann::json::parse_error& e) {
        // nlohmann's message names the line and column.
        throw ScenarioError(
            {{"file", "",
              with_detail("malformed_json", QT_TRANSLATE_NOOP("FieldError", "malformed JSON: %1"),
                          e.what())}});
    } catch (const nlohmann::json::exception& e) {
        throw ScenarioError(
            {{"file", "",
              with_detail("number_overflow",
                          QT_TRANSLATE_NOOP("FieldError", "a number out of range: %1"),
                          e.what())}});
    }
    if (!root.is_object()) {
        throw ScenarioError({{"file", "",
                              allowed_text("not_an_object",
                                           QT_TRANSLATE_NOOP("FieldError",
                                                             "a JSON object with sections machine, "
                                                             "probe, cycle"))}});
    }
    Scenario scenario = base;
    std::vector<FieldError> errors;
    for (const auto& [section, body] : root.items()) {
        const std::vector<std::string> keys = section_key_names(section);
        if (keys.empty()) {
            errors.push_back({section, "", unknown_section()});
            continue;
        }
        if (!body.is_object()) {
            errors.push_back({section, body.dump(),
                              allowed_text("not_an_object",
                                           QT_TRANSLATE_NOOP("FieldError", "an object of keys"))});
            continue;
        }
        for (const auto& [name, value] : body.items()) {
            std::string dotted = section;
            dotted += '.';
            dotted += name;
            const KeyEntry* e = find_entry(dotted);
            if (e == nullptr) {
                errors.push_back({dotted, "", unknown_key(section, join(keys))});
            } else if (e->number != nullptr && value.is_number()) {
                e->number(scenario) = without_negative_zero(value.get<double>());
            } else if (e->flag != nullptr && value.is_boolean()) {
                e->flag(scenario) = value.get<bool>();
            } else if (e->set_word == nullptr || !value.is_string() ||
                       !e->set_word(scenario, value.get<std::string>())) {
                errors.push_back({dotted, value.dump(), allowed_for(*e)});
            }
        }
    }
    // Range errors too, so one run names every problem in the file (keys with
    // the wrong type kept their defaults and are not reported twice).
    for (FieldError& e : validate(scenario)) errors.push_back(std::move(e));
    if (!errors.empty()) throw ScenarioError(std::move(errors));
    return scenario;
}

Scenario scenario_from_json(std::string_view text) {
    return merge_json(Scenario{}, text);
}

namespace {

// Every key of the sections `only` names (all of them when empty), as the file writes them.
std::string sections_to_json(const Scenario& scenario, std::string_view only) {
    Json root = Json::object();
    for (const KeyEntry& e : key_table()) {
        const std::string_view key = e.info.key;
        const std::size_t dot = key.find('.');
        if (!only.empty() && key.substr(0, dot) != only) continue;
        Json& body = root[std::string(key.substr(0, dot))];
        const std::string name(key.substr(dot + 1));
        auto& s = const_cast<Scenario&>(scenario);  // the accessors only read here
        if (e.number != nullptr) {
            const double value = without_negative_zero(e.number(s));
            // A count is written as one ("repeats": 3), when it is whole.
            if (key == "cycle.repeats" && value == std::floor(value) && std::abs(value) < 1e9) {
                body[name] = static_cast<long long>(value);
            } else {
                body[name] = value;
            }
        } else if (e.flag != nullptr) {
            body[name] = e.flag(s);
        } else {
            body[name] = e.get_word(scenario);
        }
    }
    return root.dump(2) + "\n";
}

}  // namespace

std::string scenario_to_json(const Scenario& scenario) {
    return sections_to_json(scenario, {});
}

std::string scenario_section_to_json(const Scenario& scenario, std::string_view section) {
    return sections_to_json(scenario, section);
}

void apply_setting(Scenario& scenario, std::string_view assignment) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        throw ScenarioError({{std::string(assignment), "",
                              allowed_text("not_an_assignment",
                                           QT_TRANSLATE_NOOP("FieldError", "section.key=value"))}});
    }
    const std::string key(assignment.substr(0, eq));
    const std::string value(assignment.substr(eq + 1));
    const KeyEntry* e = find_entry(key);
    if (e == nullptr) {
        const std::string section = key.substr(0, key.find('.'));
        const std::vector<std::string> keys = section_key_names(section);
        throw ScenarioError(
            {{key, "",
              keys.empty() ? allowed_text("unknown_key",
                                          QT_TRANSLATE_NOOP("FieldError",
                                                            "unknown key; sections are machine, "
                                                            "probe, cycle"))
                           : unknown_key(section, join(keys))}});
    }
    if (e->number != nullptr) {
        const std::optional<double> number = parse_decimal(value);
        if (!number)
            throw ScenarioError({{key, value.empty() ? "nothing" : value, allowed_for(*e)}});
        e->number(scenario) = without_negative_zero(*number);
    } else if (e->flag != nullptr) {
        if (value == "true") {
            e->flag(scenario) = true;
        } else if (value == "false") {
            e->flag(scenario) = false;
        } else {
            throw ScenarioError({{key, value, allowed_for(*e)}});
        }
    } else if (!e->set_word(scenario, value)) {
        throw ScenarioError({{key, value, allowed_for(*e)}});
    }
}

const char* to_string(Strategy strategy) {
    return strategy == Strategy::single_touch ? "single_touch" : "two_touch";
}

const char* to_string(BackoffFrom from) {
    return from == BackoffFrom::stop ? "stop" : "trigger";
}

const char* to_string(ToleranceAction action) {
    return action == ToleranceAction::flag ? "flag" : "stop";
}

const char* to_string(Feature feature) {
    switch (feature) {
        case Feature::surface:
            return "surface";
        case Feature::web:
            return "web";
        case Feature::pocket:
            return "pocket";
        case Feature::bore:
            return "bore";
        case Feature::boss:
            return "boss";
    }
    return "?";
}

MessageArg feature_arg(std::string name, Feature feature) {
    const char* text = "?";
    switch (feature) {
        case Feature::surface:
            text = QT_TRANSLATE_NOOP("Feature", "surface");
            break;
        case Feature::web:
            text = QT_TRANSLATE_NOOP("Feature", "web");
            break;
        case Feature::pocket:
            text = QT_TRANSLATE_NOOP("Feature", "pocket");
            break;
        case Feature::bore:
            text = QT_TRANSLATE_NOOP("Feature", "bore");
            break;
        case Feature::boss:
            text = QT_TRANSLATE_NOOP("Feature", "boss");
            break;
    }
    return message_arg(std::move(name),
                       make_message(std::string("feature_") + to_string(feature), "Feature", text));
}

std::optional<Strategy> strategy_from_string(std::string_view word) {
    for (Strategy s : kStrategies) {
        if (word == to_string(s)) return s;
    }
    return std::nullopt;
}

std::optional<BackoffFrom> backoff_from_from_string(std::string_view word) {
    for (BackoffFrom f : kBackoffFroms) {
        if (word == to_string(f)) return f;
    }
    return std::nullopt;
}

std::optional<ToleranceAction> tolerance_action_from_string(std::string_view word) {
    for (ToleranceAction a : kToleranceActions) {
        if (word == to_string(a)) return a;
    }
    return std::nullopt;
}

std::optional<Feature> feature_from_string(std::string_view word) {
    for (Feature f : kFeatures) {
        if (word == to_string(f)) return f;
    }
    return std::nullopt;
}

std::optional<AccelModel> accel_model_from_string(std::string_view word) {
    for (AccelModel m : kAccelModels) {
        if (word == to_string(m)) return m;
    }
    return std::nullopt;
}

std::optional<FilterKind> filter_kind_from_string(std::string_view word) {
    for (FilterKind k : kFilterKinds) {
        if (word == to_string(k)) return k;
    }
    return std::nullopt;
}

}  // namespace probecycle
