#include "core/lab/delay_fit_report.h"

#include <algorithm>

#include "core/common/csv_writer.h"
#include "core/common/number_format.h"
#include "core/lab/compensation.h"  // lag_cycles_for_delay

namespace probecycle {

namespace {

// Cycles to 0.01: the delay's 1 us is 0.001 to 0.01 of a 0.1 to 1 ms
// interpolation cycle, and the window shows two decimals.
constexpr int kLagDecimals = 2;

const DelayGroup* group_of(const DelayFit& fit, const DelayTouch& touch) {
    const auto it = std::find_if(fit.groups.begin(), fit.groups.end(), [&](const DelayGroup& g) {
        return g.axis == touch.axis && g.direction == touch.direction;
    });
    return it == fit.groups.end() ? nullptr : &*it;
}

}  // namespace

std::string delay_fit_report_csv(std::span<const DelayTouch> touches,
                                 const DelayFitOptions& options, const DelayFit& fit,
                                 const ReportHeader& header) {
    std::string csv = report_header_csv("delay fit report", "touches", header);
    csv += "# fit\nkey,value,unit\n";
    csv += csv_line({"interpolation_period_s",
                     options.interpolation_period_s ? csv_exact(*options.interpolation_period_s)
                                                    : std::string(),
                     "s"});

    // The keys of `latency fit`'s JSON (README), one row per group.
    csv +=
        "\n# groups\ngroup,axis,direction,delay_s,zero_speed_position_mm,lag_cycles,"
        "compensation_lag_cycles,residual_2sigma_mm,touches\n";
    for (const DelayGroup& g : fit.groups) {
        std::size_t n = 0;
        for (const FeedScatter& f : g.feeds) n += f.n;
        const std::optional<double>& period = options.interpolation_period_s;
        csv += csv_line(
            {g.name(), g.axis, std::to_string(g.direction), csv_time_s(g.delay_s),
             csv_length_mm(g.zero_speed_position_mm),
             g.lag_cycles ? format_fixed(*g.lag_cycles, kLagDecimals) : std::string(),
             period ? std::to_string(lag_cycles_for_delay(g.delay_s, *period)) : std::string(),
             csv_length_mm(g.residual_2sigma_mm), std::to_string(n)});
    }

    // The stability: per feed, the mean deviation from p0 (what the chart
    // plots), the line's at that feed, and the range of its touches.
    csv += "\n# feeds\ngroup,feed_mm_min,mean_deviation_mm,fitted_deviation_mm,range_mm,n\n";
    for (const DelayGroup& g : fit.groups) {
        for (const FeedScatter& f : g.feeds) {
            csv +=
                csv_line({g.name(), csv_feed_mm_min(f.feed_mm_min),
                          csv_length_mm(f.mean_mm - g.zero_speed_position_mm),
                          csv_length_mm(g.predicted_mm(f.feed_mm_min) - g.zero_speed_position_mm),
                          csv_length_mm(f.range_mm), std::to_string(f.n)});
        }
    }

    // The touches as given, each with its distance from its group's line.
    csv += "\n# touches\nline,group,feed_mm_min,measured_mm,residual_mm\n";
    for (const DelayTouch& t : touches) {
        const DelayGroup* g = group_of(fit, t);
        csv +=
            csv_line({t.line > 0 ? std::to_string(t.line) : std::string(),
                      g != nullptr ? g->name() : std::string(), csv_exact(t.feed_mm_min),
                      csv_exact(t.measured_mm),
                      g != nullptr ? csv_length_mm(t.measured_mm - g->predicted_mm(t.feed_mm_min))
                                   : std::string()});
    }

    csv += '\n';
    csv += csv_warnings_header(true);
    for (const DelayGroup& g : fit.groups) {
        for (const LatencyWarning& w : g.warnings) {
            csv += csv_warning_row(to_string(w.code), to_string(w.severity), g.name(), w.text());
        }
    }
    return csv;
}

}  // namespace probecycle
