#pragma once

// What a cycle program measures: the feature's result from its recorded
// touches (a surface's position, a web's or pocket's width and centre, a
// bore's or boss's diameter and centre), its uncertainty from the model's, and
// the size's tolerance check. One computation: the program writer writes it in
// a control's arithmetic (the same variables in every dialect that can
// compute), and the import computes it from the positions the control
// recorded.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/cycle/scenario.h"
#include "core/program/plan.h"

namespace probecycle {

// What the plan says of its result: read from its values (make_cycle_plan
// writes them).
struct ResultSpec {
    Feature feature{Feature::surface};
    // The sides of the centre the touches lie on, in the plan's order (a
    // surface: its one touch direction); a bore or boss X+, X-, Y+, Y-, a
    // pocket or web + then - along its axis.
    std::vector<AxisDirection> sides;
    // Per recorded touch (ProbingPlan::recorded()), the index of its side.
    std::vector<std::size_t> touch_side;
    // cycle.feature_size_mm: the nominal distance between opposite
    // stylus-centre contact points.
    double nominal_mm{0.0};
    // The stylus's effective ball diameter (from its calibration): a bore's or
    // pocket's size is the stylus-centre distance plus it, a boss's or web's
    // less it, a surface lies half of it beyond the stylus centre. 0: sizes
    // between stylus centres.
    double ball_diameter_mm{0.0};
    // The model's expanded (k = 2) uncertainty of one measured point
    // (CycleResult::uncertainty_mm(), the mean of the repeats).
    double point_uncertainty_mm{0.0};
    // Its terms independent between the feature's points
    // (independent_expanded_uncertainty_mm; a plan without it: the whole
    // point's), the calibration artefact's certified uncertainty (k = 2; a size
    // carries it whole, a centre not) and the thermal drift's half-width (a
    // centre carries it whole, a size not).
    double independent_uncertainty_mm{0.0};
    double artefact_uncertainty_mm{0.0};
    double thermal_drift_mm{0.0};
    double size_tolerance_mm{0.0};  // 0: no check
    ToleranceAction tolerance_action{ToleranceAction::flag};

    // The feature's nominal size, the ball taken into account.
    double nominal_size_mm() const;
    bool checks_tolerance() const { return size_tolerance_mm > 0.0 && feature != Feature::surface; }
};

// The plan values make_cycle_plan adds for the result.
constexpr const char* kBallDiameterValue = "ball_diameter_mm";
constexpr const char* kPointUncertaintyValue = "point_uncertainty_mm";
constexpr const char* kIndependentUncertaintyValue = "independent_uncertainty_mm";

// The result spec of a cycle plan; nullopt for a delay or ring plan. Throws
// InputError when a value it needs is missing or unreadable, or when the
// recorded touches do not make the feature's sides.
std::optional<ResultSpec> result_spec(const ProbingPlan& plan);

struct FeatureResult {
    Feature feature{Feature::surface};
    // Per side (ResultSpec::sides), the mean stylus-centre coordinate along
    // its axis over its recorded touches.
    std::vector<double> side_mm;
    // A surface: its position along the touch's axis (the stylus centre plus
    // half the ball diameter in the touch direction). A web or pocket: its
    // width; a bore or boss: its diameter, the mean of the X and Y widths.
    double size_mm{0.0};
    // Between opposite stylus-centre contact points (the model's
    // feature_size_mm): the size without the ball; 0 for a surface.
    double centre_distance_mm{0.0};
    // The centre along X and Y where the feature has one (a pocket or web
    // along its axis only).
    std::array<std::optional<double>, 2> centre_mm{};
    // Expanded (k = 2) uncertainties: of one point (the model's), of the size
    // (a surface: its position) and of a centre coordinate.
    double point_uncertainty_mm{0.0};
    double size_uncertainty_mm{0.0};
    double centre_uncertainty_mm{0.0};
    // The size less the nominal size (a feature; 0 for a surface), and
    // whether it lies outside the tolerance (checked only with one).
    double deviation_mm{0.0};
    bool checked{false};
    bool out_of_tolerance{false};
};

// The result from the recorded touches' positions (X, Y, Z; one per recorded
// touch, in order). Assumes touches.size() == spec.touch_side.size().
FeatureResult feature_result(const ResultSpec& spec,
                             const std::vector<std::array<double, 3>>& touches);

// A web's, pocket's, bore's or boss's size from the distance between its
// opposite stylus-centre contact points: plus the ball inside (a pocket, a
// bore), less it outside (a web, a boss).
double size_with_ball_mm(Feature feature, double centre_distance_mm, double ball_diameter_mm);

// The expanded uncertainties of a size (a surface: its position) and of a
// centre from the spec's points (see feature_result.cpp).
double size_uncertainty_mm(const ResultSpec& spec);
double centre_uncertainty_mm(const ResultSpec& spec);

// "bore diameter", "pocket width", "surface position", ...
std::string size_name(Feature feature);

}  // namespace probecycle
