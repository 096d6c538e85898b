#include "core/lab/delay_fit_report.h"

#include <algorithm>
#include <limits>
#include <vector>

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
                                 const ReportHeader& header, ReportRows rows) {
    std::string csv = report_header_csv("delay fit report", "touches", header);
    csv += "# fit\nkey,value,unit\n";
    csv += csv_line({"interpolation_period_s",
                     options.interpolation_period_s ? csv_exact(*options.interpolation_period_s)
                                                    : std::string(),
                     "s"});

    // The keys of `latency fit`'s JSON (docs/cli.md), one row per group.
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
    struct FeedRow {
        const DelayGroup* group;
        const FeedScatter* feed;
    };
    std::vector<FeedRow> feeds;
    std::vector<double> feed_residual_mm;
    for (const DelayGroup& g : fit.groups) {
        for (const FeedScatter& f : g.feeds) {
            feeds.push_back({&g, &f});
            feed_residual_mm.push_back(f.mean_mm - g.predicted_mm(f.feed_mm_min));
        }
    }
    const auto feed_row = [&](std::size_t i) {
        const DelayGroup& g = *feeds[i].group;
        const FeedScatter& f = *feeds[i].feed;
        return csv_line({g.name(), csv_feed_mm_min(f.feed_mm_min),
                         csv_length_mm(f.mean_mm - g.zero_speed_position_mm),
                         csv_length_mm(g.predicted_mm(f.feed_mm_min) - g.zero_speed_position_mm),
                         csv_length_mm(f.range_mm), std::to_string(f.n)});
    };
    const char* feed_columns =
        "group,feed_mm_min,mean_deviation_mm,fitted_deviation_mm,range_mm,n\n";
    if (summarised(rows, feeds.size())) {
        // The mean's distance from the line: how far the delay drifts with the feed.
        csv += "\n# feeds summary\n" + csv_stats_header();
        csv += csv_stats_row("mean_from_fitted", value_stats(feed_residual_mm));
        const std::vector<std::size_t> largest =
            largest_magnitudes(feed_residual_mm, kReportLargestRows);
        csv += '\n' + csv_largest_heading("feeds", "mean_deviation_mm - fitted_deviation_mm",
                                          largest.size(), feeds.size());
        csv += feed_columns;
        for (const std::size_t i : largest) csv += feed_row(i);
    } else {
        csv += std::string("\n# feeds\n") + feed_columns;
        for (std::size_t i = 0; i < feeds.size(); ++i) csv += feed_row(i);
    }

    // The touches as given, each with its distance from its group's line.
    std::vector<double> residual_mm(touches.size(), std::numeric_limits<double>::quiet_NaN());
    std::vector<const DelayGroup*> group(touches.size(), nullptr);
    for (std::size_t i = 0; i < touches.size(); ++i) {
        const DelayTouch& t = touches[i];
        group[i] = group_of(fit, t);
        if (group[i] != nullptr)
            residual_mm[i] = t.measured_mm - group[i]->predicted_mm(t.feed_mm_min);
    }
    const auto touch_row = [&](std::size_t i) {
        const DelayTouch& t = touches[i];
        const DelayGroup* g = group[i];
        return csv_line({t.line > 0 ? std::to_string(t.line) : std::string(),
                         g != nullptr ? g->name() : std::string(), csv_exact(t.feed_mm_min),
                         csv_exact(t.measured_mm),
                         g != nullptr ? csv_length_mm(residual_mm[i]) : std::string()});
    };
    const char* touch_columns = "line,group,feed_mm_min,measured_mm,residual_mm\n";
    if (summarised(rows, touches.size())) {
        csv += "\n# touches summary\n" + csv_stats_header();
        for (const DelayGroup& g : fit.groups) {
            std::vector<double> of_group;
            for (std::size_t i = 0; i < touches.size(); ++i) {
                if (group[i] == &g) of_group.push_back(residual_mm[i]);
            }
            csv += csv_stats_row("residual " + g.name(), value_stats(of_group));
        }
        const std::vector<std::size_t> largest =
            largest_magnitudes(residual_mm, kReportLargestRows);
        csv += '\n' + csv_largest_heading("touches", "residual_mm", largest.size(), touches.size());
        csv += touch_columns;
        for (const std::size_t i : largest) csv += touch_row(i);
    } else {
        csv += std::string("\n# touches\n") + touch_columns;
        for (std::size_t i = 0; i < touches.size(); ++i) csv += touch_row(i);
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
