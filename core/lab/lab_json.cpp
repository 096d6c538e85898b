#include "core/lab/lab_json.h"

#include "core/common/message_json.h"

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

Json optional_json(const std::optional<double>& value) {
    return value ? Json(*value) : Json(nullptr);
}

Json errors_json(const std::array<double, kCompensationMethodCount>& errors) {
    Json out = Json::object();
    for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
        out[to_string(static_cast<CompensationMethod>(m))] = errors[m];
    }
    return out;
}

}  // namespace

Json ring_calibration_json(const RingCalibration& result, const RingCalibrationOptions& options) {
    Json out = Json::object();
    out["gauge_diameter_mm"] = options.gauge_diameter_mm;
    out["center_x_mm"] = result.center_x_mm;
    out["center_y_mm"] = result.center_y_mm;
    out["runout_x_mm"] = optional_json(result.runout_x_mm);
    out["runout_y_mm"] = optional_json(result.runout_y_mm);
    out["effective_radius_mm"] = result.effective_radius_mm;
    const auto& by_direction = result.radius_by_direction;
    out["radius_by_direction"] = {{"x_plus", optional_json(by_direction.x_plus_mm)},
                                  {"x_minus", optional_json(by_direction.x_minus_mm)},
                                  {"y_plus", optional_json(by_direction.y_plus_mm)},
                                  {"y_minus", optional_json(by_direction.y_minus_mm)}};
    out["residual_max_mm"] = result.residual_max_mm;
    Json fits = Json::array();
    for (std::size_t o = 0; o < result.fits.size(); ++o) {
        if (!result.fits[o]) continue;
        const auto& fit = *result.fits[o];
        fits.push_back({{"orientation_deg", o == 0 ? 0 : 180},
                        {"center_x_mm", fit.center_x_mm},
                        {"center_y_mm", fit.center_y_mm},
                        {"radius_mm", fit.radius_mm},
                        {"residual_max_mm", fit.residual_max_mm}});
    }
    out["fits"] = fits;
    out["warnings"] = warnings_json(result.warnings, [](auto code) { return to_string(code); });
    return out;
}

Json length_calibration_json(const LengthCalibrationInput& input, const LengthCalibration& result) {
    Json out = Json::object();
    out["effective_length_mm"] = result.effective_length_mm;
    out["nominal_length_mm"] = optional_json(input.nominal_length_mm);
    out["wear_mm"] = optional_json(result.wear_mm);
    out["surface_z_mm"] = input.surface_z_mm;
    out["active_length_mm"] = input.active_length_mm;
    out["trigger_z_mean_mm"] = result.trigger_z_mean_mm;
    out["trigger_z_range_mm"] = result.trigger_z_range_mm;
    out["touches"] = result.touches;
    out["warnings"] = warnings_json(result.warnings, [](auto code) { return to_string(code); });
    return out;
}

Json delay_fit_json(const DelayFit& fit, const DelayFitOptions& options) {
    Json out = Json::object();
    if (options.interpolation_period_s) {
        out["interpolation_period_s"] = *options.interpolation_period_s;
    }
    Json groups = Json::array();
    Json warnings = Json::array();
    for (const auto& g : fit.groups) {
        Json group = Json::object();
        group["axis"] = g.axis;
        group["direction"] = g.direction;
        group["delay_s"] = g.delay_s;
        group["zero_speed_position_mm"] = g.zero_speed_position_mm;
        if (options.interpolation_period_s) {
            group["lag_cycles"] = optional_json(g.lag_cycles);
            // Whole cycles for `latency compensate --lag-cycles` (compensation.h).
            group["compensation_lag_cycles"] =
                lag_cycles_for_delay(g.delay_s, *options.interpolation_period_s);
        }
        group["residual_2sigma_mm"] = optional_json(g.residual_2sigma_mm);
        Json feeds = Json::array();
        for (const auto& f : g.feeds) {
            feeds.push_back({{"feed_mm_min", f.feed_mm_min},
                             {"mean_mm", f.mean_mm},
                             {"range_mm", f.range_mm},
                             {"n", f.n}});
        }
        group["feeds"] = feeds;
        groups.push_back(group);
        for (const auto& w : g.warnings) {
            Json warning = {{"code", to_string(w.code)},
                            {"severity", to_string(w.severity)},
                            {"group", g.name()}};
            warning.update(message_json(w.message));
            warnings.push_back(warning);
        }
    }
    out["groups"] = groups;
    out["warnings"] = warnings;

    return out;
}

Json applied_delay_json(const AppliedDelay& applied, const std::string& file) {
    if (applied.latched) {
        return {{"file", file},
                {"key", applied.key},
                {"value_s", applied.value_s},
                {"previous_s", applied.previous_s},
                {"group", applied.group},
                {"rule", render(applied.rule)},
                {"total_delay_s", applied.total_delay_s},
                {"note",
                 "latched input: the position is captured when the signal reaches the control, "
                 "so the fitted delay is the probe's interface delay; "
                 "machine.controller_latency_s is left as it was (it still lengthens the "
                 "overtravel)"}};
    }
    return {{"file", file},
            {"key", applied.key},
            {"value_s", applied.value_s},
            {"previous_s", applied.previous_s},
            {"group", applied.group},
            {"rule", render(applied.rule)},
            {"total_delay_s", applied.total_delay_s},
            {"less_interface_delay_s", applied.interface_delay_s},
            {"less_half_scan_period_s", applied.half_scan_s}};
}

Json compensation_json(const CompensationSetup& setup, const CompensationComparison& result,
                       const std::vector<BrakingRow>& braking_sweep, bool with_trace,
                       const std::vector<LagRow>& lag_sweep) {
    Json out = Json::object();
    Json s = Json::object();
    s["accel_model"] = to_string(setup.limits.model);
    s["feed_mm_min"] = setup.feed_mm_min;
    s["direction"] = setup.direction;
    s["touch"] = to_string(setup.touch);
    if (setup.touch == TouchMotion::braking) s["speed_fraction"] = setup.braking_speed_fraction;
    s["interpolation_period_s"] = setup.interpolation_period_s;
    s["lag_cycles"] = setup.lag_cycles;
    s["compensated_lag_cycles"] = setup.compensated_lag_cycles.value_or(setup.lag_cycles);
    s["trigger_phase"] = setup.trigger_phase;
    s["counts_per_mm"] = setup.counts_per_mm;
    s["counter_bits"] = setup.counter_bits;
    s["naive_delay_s"] = result.naive_delay_s;
    out["setup"] = s;
    out["trigger"] = {{"position_mm", result.trigger_position_mm},
                      {"speed_mm_s", result.trigger_speed_mm_s},
                      {"dt_s", result.dt_s}};
    out["recorded"] = {{"position_mm", result.recorded_position_mm},
                       {"speed_mm_s", result.recorded_speed_mm_s},
                       {"p1_mm", result.p1_mm},
                       {"p2_mm", result.p2_mm},
                       {"counter_wraps", result.counter_wraps}};
    Json methods = Json::array();
    for (const auto& m : result.methods) {
        methods.push_back({{"method", to_string(m.method)},
                           {"position_mm", m.position_mm},
                           {"error_mm", m.error_mm}});
    }
    out["methods"] = methods;
    if (!braking_sweep.empty()) {
        Json rows = Json::array();
        for (const auto& row : braking_sweep) {
            rows.push_back({{"speed_fraction", row.speed_fraction},
                            {"trigger_speed_mm_s", row.trigger_speed_mm_s},
                            {"error_mm", errors_json(row.error_mm)}});
        }
        out["braking_sweep"] = rows;
    }
    if (!lag_sweep.empty()) {
        Json rows = Json::array();
        for (const LagRow& row : lag_sweep) {
            rows.push_back({{"compensated_lag_cycles", row.compensated_lag_cycles},
                            {"cycle_lag_error_mm", row.error_mm}});
        }
        out["lag_sweep"] = rows;
    }
    if (with_trace) {
        Json trace = Json::array();
        for (const auto& sample : result.trace) {
            trace.push_back({{"cycle", sample.cycle},
                             {"time_s", sample.time_s},
                             {"position_mm", sample.position_mm},
                             {"speed_mm_s", sample.speed_mm_s},
                             {"counter", sample.counter},
                             {"increment", sample.increment}});
        }
        out["trace"] = trace;
    }
    return out;
}

}  // namespace probecycle
