#include "core/common/report_summary.h"

#include <algorithm>
#include <cmath>

#include "core/common/csv_writer.h"

namespace probecycle {

bool summarised(ReportRows rows, std::size_t count) {
    return rows == ReportRows::summary && count > kReportFullRows;
}

ValueStats value_stats(std::span<const double> values) {
    ValueStats s;
    double sum = 0.0;
    for (const double v : values) {
        if (!std::isfinite(v)) continue;
        if (s.count == 0) {
            s.min = v;
            s.max = v;
        }
        s.min = std::min(s.min, v);
        s.max = std::max(s.max, v);
        sum += v;
        ++s.count;
    }
    if (s.count == 0) return s;
    s.mean = sum / static_cast<double>(s.count);
    // Two passes: the squares of deviations, not of values, keep the digits
    // of residuals of a micrometre on positions of hundreds of millimetres.
    double squares = 0.0;
    for (const double v : values) {
        if (std::isfinite(v)) squares += (v - s.mean) * (v - s.mean);
    }
    if (s.count > 1) s.std = std::sqrt(squares / static_cast<double>(s.count - 1));
    return s;
}

std::vector<std::size_t> largest_magnitudes(std::span<const double> values, std::size_t n) {
    std::vector<std::size_t> order;
    order.reserve(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (std::isfinite(values[i])) order.push_back(i);
    }
    const std::size_t shown = std::min(n, order.size());
    const auto larger = [&values](std::size_t a, std::size_t b) {
        const double ma = std::abs(values[a]);
        const double mb = std::abs(values[b]);
        return ma != mb ? ma > mb : a < b;
    };
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(shown),
                      order.end(), larger);
    order.resize(shown);
    return order;
}

std::string csv_stats_header() {
    return "quantity,count,min_mm,max_mm,mean_mm,std_mm\n";
}

std::string csv_stats_row(const std::string& quantity, const ValueStats& stats) {
    if (stats.count == 0) return csv_line({quantity, "0", "", "", "", ""});
    return csv_line({quantity, std::to_string(stats.count), csv_length_mm(stats.min),
                     csv_length_mm(stats.max), csv_length_mm(stats.mean),
                     csv_length_mm(stats.std)});
}

std::string csv_largest_heading(const std::string& what, const std::string& column,
                                std::size_t shown, std::size_t count) {
    return "# " + what + ": the " + std::to_string(shown) + " largest |" + column + "| of " +
           std::to_string(count) + "\n";
}

}  // namespace probecycle
