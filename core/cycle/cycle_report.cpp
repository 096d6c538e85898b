#include "core/cycle/cycle_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/common/csv_writer.h"
#include "core/common/message_json.h"
#include "core/common/report_header.h"
#include "core/common/units.h"
#include "core/cycle/fixes.h"
#include "core/cycle/uncertainty.h"

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

Json warnings_json(const std::vector<Warning>& warnings) {
    Json list = Json::array();
    for (const Warning& w : warnings) {
        const Message m = w.to_message();
        list.push_back({{"code", m.code},
                        {"severity", to_string(w.severity)},
                        {"message", render(m)},
                        {"values", message_values(m)}});
    }
    return list;
}

// The warnings of an evaluation, each with the fix the window offers.
Json warnings_json(const Scenario& scenario, const Analysis& analysis) {
    Json list = warnings_json(analysis.cycle.warnings());
    for (std::size_t i = 0; i < analysis.cycle.warnings().size(); ++i) {
        const std::optional<Fix> fix = fix_for(scenario, analysis, analysis.cycle.warnings()[i]);
        if (!fix) continue;
        Json changes = Json::object();
        for (const auto& [key, value] : fix_changes(scenario, *fix)) changes[key] = value;
        list[i]["fix"] = std::move(changes);
    }
    return list;
}

Json touch_json(const TouchResult& touch) {
    return {{"programmed_feed_mm_min", mm_s_to_mm_min(touch.programmed_feed_mm_s)},
            {"trigger_speed_mm_min", mm_s_to_mm_min(touch.trigger_speed_mm_s)},
            {"overtravel_mm", touch.overtravel_mm},
            {"override_overtravel_mm", touch.override_overtravel_mm},
            {"mean_overtravel_mm", touch.mean_overtravel_mm},
            {"recorded_mm", touch.recorded_mm},
            {"search_mm", touch.search_mm}};
}

Json budget_json(const UncertaintyBudget& b) {
    Json lines = Json::array();
    for (const BudgetLine& l : b.lines) {
        lines.push_back({{"term", to_string(l.term)},
                         {"key", l.key},
                         {"stated_as", to_string(l.distribution)},
                         {"value_mm", l.value_mm},
                         {"divisor", divisor(l.distribution)},
                         {"averaged", l.averaged},
                         {"standard_mm", l.standard_mm}});
    }
    return {{"coverage_factor", kCoverageFactor},
            {"repeats", b.repeats},
            {"lines", std::move(lines)},
            {"combined_standard_mm", b.combined_standard_mm},
            {"expanded_mm", b.expanded_mm}};
}

}  // namespace

std::string evaluation_to_json(const Scenario& scenario, const Analysis& analysis) {
    const CycleResult& r = analysis.cycle;
    Json out = Json::object();
    out["cycle_time_s"] = r.total();
    // An invalid cycle's time is no cycle time; the errors say why.
    out["valid"] = r.valid();
    Json reasons = Json::array();
    for (const Warning& w : r.warnings()) {
        if (w.severity == Severity::error) reasons.push_back(to_string(w.code));
    }
    out["invalid_reasons"] = std::move(reasons);
    out["overtravel_mm"] = r.overtravel_mm();
    // At up to the highest feed override, as the checks take it.
    out["checked_overtravel_mm"] = r.checked_overtravel_mm();
    out["overtravel_touch"] = r.overtravel_touch() == 2 ? "second" : "first";
    out["trigger_speed_mm_min"] = mm_s_to_mm_min(r.trigger_speed_mm_s());
    out["uncertainty_mm"] = r.uncertainty_mm();
    // The trigger's part of it, and the budget line by line.
    out["trigger_uncertainty_mm"] = r.trigger_uncertainty_mm();
    out["uncertainty_budget"] = budget_json(uncertainty_budget(scenario, r.trigger_speed_mm_s()));
    out["scan_range_mm"] = r.scan_range_mm();
    out["recommended_backoff_mm"] = r.recommended_backoff_mm();
    out["knee_feed_mm_min"] =
        analysis.knee_feed_mm_min ? Json(*analysis.knee_feed_mm_min) : Json(nullptr);
    out["knee_cycle_time_s"] =
        analysis.knee_cycle_time_s ? Json(*analysis.knee_cycle_time_s) : Json(nullptr);
    // The touches the model distinguishes (the same one twice for
    // single-touch): where each stops, where the control records it, and how
    // far its probing move searches from its start.
    out["first_touch"] = touch_json(r.first_touch());
    out["measuring_touch"] = touch_json(r.measuring_touch());
    Json phases = Json::array();
    for (const PhaseRecord& p : r.phases()) {
        phases.push_back({{"name", to_string(p.phase)},
                          {"touch", p.touch},
                          {"start_s", p.start_s},
                          {"time_s", p.time_s},
                          {"distance_mm", p.distance_mm}});
    }
    out["phases"] = std::move(phases);
    out["warnings"] = warnings_json(scenario, analysis);
    return out.dump(2) + "\n";
}

std::string move_to_json(const Scenario& scenario, double distance_mm, double feed_mm_min) {
    const MotionLimits limits = scenario.motion_limits();
    const double v = mm_min_to_mm_s(feed_mm_min);
    Json out = Json::object();
    out["time_s"] = block_time_s(scenario, distance_mm, v);
    out["command_time_s"] = move_time_s(limits, distance_mm, v);
    out["peak_speed_mm_min"] = mm_s_to_mm_min(move_peak_speed_mm_s(limits, distance_mm, v));
    out["accel_model"] = to_string(limits.model);
    out["filter"] = to_string(scenario.machine.filter);
    return out.dump(2) + "\n";
}

std::string monte_carlo_to_json(const MonteCarloOptions& options, const Histogram& h) {
    Json out = Json::object();
    out["samples"] = options.samples;
    out["seed"] = options.seed;
    out["mean_mm"] = h.mean_mm;
    out["stddev_mm"] = h.stddev_mm;
    out["min_mm"] = h.min_mm;
    out["max_mm"] = h.max_mm;
    out["bin_lo_mm"] = h.lo_mm;
    out["bin_width_mm"] = h.bin_width_mm;
    out["counts"] = h.counts;
    return out.dump(2) + "\n";
}

std::string sweep_to_csv(const SweepResult& sweep, const SweepResult* optimised) {
    std::string csv = "feed_mm_min,cycle_time_s,overtravel_mm,checked_overtravel_mm,uncertainty_mm";
    for (Phase phase : all_phases()) csv += std::string(",") + to_string(phase) + "_s";
    csv += ",valid,invalid_reasons,feed_reached";
    csv += optimised != nullptr ? ",cycle_time_recommended_backoff_s\n" : "\n";
    for (std::size_t i = 0; i < sweep.points.size(); ++i) {
        const SweepPoint& p = sweep.points[i];
        csv += csv_feed_mm_min(p.feed_mm_min) + ',' + csv_time_s(p.cycle_time_s) + ',' +
               csv_length_mm(p.overtravel_mm) + ',' + csv_length_mm(p.checked_overtravel_mm) + ',' +
               csv_length_mm(p.uncertainty_mm);
        for (double t : p.phase_time_s) csv += ',' + csv_time_s(t);
        csv += p.valid() ? ",true," : ",false," + invalid_codes_text(p.invalid_codes, ";");
        csv += p.feed_reached ? ",true" : ",false";
        if (optimised != nullptr) csv += ',' + csv_time_s(optimised->points[i].cycle_time_s);
        csv += '\n';
    }
    return csv;
}

std::string sweep_summary(const SweepResult& sweep, const Scenario& scenario) {
    // One knee everywhere (the sweep, the readout, the report, the CLI):
    // find_knee's on the optimised curve (as analyse()), here over the sweep's
    // own range.
    double from = std::numeric_limits<double>::infinity();
    double to = 0.0;
    for (const SweepPoint& p : sweep.points) {
        from = std::min(from, p.feed_mm_min);
        to = std::max(to, p.feed_mm_min);
    }
    std::string line = "knee";
    if (scenario.cycle.strategy == Strategy::two_touch) {
        line += " (recommended backoff at each feed, as evaluate and the window)";
    }
    std::optional<Warning> range_end;
    if (sweep.points.empty()) {
        line += ": none";
    } else {
        const KneeSearch knee =
            find_knee(scenario, from, std::max(from, to), {.recommended_backoff = true});
        line += " from " + csv_feed_mm_min(from) + " to " + csv_feed_mm_min(to) + " mm/min: ";
        line += knee.knee_feed_mm_min ? csv_feed_mm_min(*knee.knee_feed_mm_min) + " mm/min"
                : knee.none_reached
                    ? "none (the first touch does not reach the feed from its start)"
                    : "none (no valid feed: each overtravels the probe's limit or backs off too "
                      "little)";
        range_end = knee.range_end_warning;
    }
    line += "; fastest feed meeting the target uncertainty";
    if (scenario.cycle.target_uncertainty_mm <= 0.0) {
        line += ": no target set";
    } else {
        line += " (" + csv_exact(scenario.cycle.target_uncertainty_mm) + " mm): ";
        line += sweep.max_feed_meeting_target_mm_min
                    ? csv_feed_mm_min(*sweep.max_feed_meeting_target_mm_min) + " mm/min"
                    : "none in the range";
    }
    if (range_end) {
        line += std::string("; ") + to_string(range_end->code) + ": " + range_end->message();
    }
    return line;
}

std::string csv_report(const Scenario& scenario, const Analysis& analysis,
                       std::span<const double> feeds_mm_min, const ReportHeader& header) {
    const SweepResult sweep = sweep_feeds(scenario, feeds_mm_min);
    std::optional<SweepResult> optimised;
    if (scenario.cycle.strategy == Strategy::two_touch) {
        optimised = sweep_feeds(scenario, feeds_mm_min, {.recommended_backoff = true});
    }
    const CycleResult& r = analysis.cycle;
    std::string csv = report_header_csv("cycle report", "scenario", header);
    csv += "# scenario\nkey,value,unit\n";
    // The words and flags first, then the numbers, each in the key table's order.
    for (const KeyInfo& key : scenario_keys()) {
        if (key.kind != KeyKind::number) {
            csv += std::string(key.key) + ',' + value_text(scenario, key) + ",\n";
        }
    }
    // The user's values as given, not rounded: the report reproduces the scenario.
    for (const KeyInfo& key : numeric_keys()) {
        csv += std::string(key.key) + ',' + csv_exact(*get_number(scenario, key.key)) + ',' +
               key.unit + '\n';
    }
    // The keys of `probecycle-cli evaluate` (docs/cli.md), with their units.
    const auto row = [&csv](const char* key, const std::string& value, const char* unit) {
        csv += csv_line({key, value, unit});
    };
    csv += "\n# summary\nkey,value,unit\n";
    row("cycle_time_s", csv_time_s(r.total()), "s");
    row("valid", r.valid() ? "true" : "false", "");
    row("invalid_reasons", invalid_codes_text(r.invalid_codes(), ";"), "");
    row("overtravel_mm", csv_length_mm(r.overtravel_mm()), "mm");
    row("checked_overtravel_mm", csv_length_mm(r.checked_overtravel_mm()), "mm");
    row("overtravel_touch", r.overtravel_touch() == 2 ? "second" : "first", "");
    row("trigger_speed_mm_min", csv_feed_mm_min(mm_s_to_mm_min(r.trigger_speed_mm_s())), "mm/min");
    row("uncertainty_mm", csv_length_mm(r.uncertainty_mm()), "mm");
    row("trigger_uncertainty_mm", csv_length_mm(r.trigger_uncertainty_mm()), "mm");
    row("scan_range_mm", csv_length_mm(r.scan_range_mm()), "mm");
    row("recommended_backoff_mm", csv_length_mm(r.recommended_backoff_mm()), "mm");
    row("knee_feed_mm_min",
        analysis.knee_feed_mm_min ? csv_feed_mm_min(*analysis.knee_feed_mm_min) : std::string(),
        "mm/min");
    row("knee_cycle_time_s", csv_time_s(analysis.knee_cycle_time_s), "s");
    // The budget behind uncertainty_mm, one line per term.
    const UncertaintyBudget budget = uncertainty_budget(scenario, r.trigger_speed_mm_s());
    csv += "\n# uncertainty budget (k = " + csv_exact(kCoverageFactor) + ", repeats " +
           std::to_string(budget.repeats) +
           ")\nterm,key,stated_as,value_mm,divisor,averaged,standard_mm\n";
    for (const BudgetLine& l : budget.lines) {
        csv += csv_line({to_string(l.term), l.key, to_string(l.distribution),
                         csv_length_mm(l.value_mm), csv_exact(divisor(l.distribution)),
                         l.averaged ? "true" : "false", csv_length_mm(l.standard_mm)});
    }
    csv += csv_line(
        {"combined_standard", "", "", "", "", "", csv_length_mm(budget.combined_standard_mm)});
    csv += csv_line({"expanded", "", "", "", "", "", csv_length_mm(budget.expanded_mm)});
    // touch counts from 1 here (evaluate's JSON counts from 0).
    csv += "\n# phases\ntouch,name,start_s,time_s,distance_mm\n";
    for (const PhaseRecord& p : r.phases()) {
        csv += std::to_string(p.touch + 1) + ',' + to_string(p.phase) + ',' +
               csv_time_s(p.start_s) + ',' + csv_time_s(p.time_s) + ',' +
               csv_length_mm(p.distance_mm) + '\n';
    }
    csv += '\n';
    csv += csv_warnings_header();
    for (const Warning& w : r.warnings()) {
        csv += csv_warning_row(to_string(w.code), to_string(w.severity), w.message());
    }
    csv += "\n# sweep\n" + sweep_to_csv(sweep, optimised ? &*optimised : nullptr);
    return csv;
}

std::vector<double> report_feeds(const Scenario& scenario, const Analysis& analysis) {
    std::vector<double> feeds = {10,   20,   30,   50,   75,   100,  150,  200,
                                 300,  400,  500,  600,  800,  1000, 1200, 1500,
                                 2000, 2500, 3000, 4000, 5000, 6000, 8000, 10000};
    feeds.push_back(scenario.cycle.probe_feed_mm_min);
    if (analysis.knee_feed_mm_min) feeds.push_back(*analysis.knee_feed_mm_min);
    std::sort(feeds.begin(), feeds.end());
    feeds.erase(std::unique(feeds.begin(), feeds.end()), feeds.end());
    return feeds;
}

std::string csv_report(const Scenario& scenario, const ReportHeader& header) {
    const Analysis analysis = analyse(scenario);
    return csv_report(scenario, analysis, report_feeds(scenario, analysis), header);
}

}  // namespace probecycle
