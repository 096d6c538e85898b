#include "core/lab/delay_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"
#include "core/common/units.h"

namespace probecycle {

namespace {

constexpr double kMaxFeed_mm_min = 100000.0;

// Numbers in messages, in English to 3 significant digits ("0.0531 mm",
// "5.1 ms") and feeds to 6 ("1000 mm/min"); the window formats its own.
MessageArg mm(std::string name, double value_mm) {
    return significant_arg(std::move(name), ArgKind::length_mm, value_mm, 3);
}
MessageArg ms(std::string name, double value_s) {
    return significant_arg(std::move(name), ArgKind::delay_s, value_s, 3);
}
MessageArg feed(std::string name, double feed_mm_min) {
    return significant_arg(std::move(name), ArgKind::feed_mm_min, feed_mm_min, 6);
}

// Templates in context "DelayFit", like every text of this file.
Message delay_message(const char* code, const char* text, std::vector<MessageArg> args) {
    return Message{code, "DelayFit", text, std::move(args)};
}

// A group's warning: its name is the first argument, "%1: ...".
LatencyWarning warning(const DelayGroup& group, LatencyWarningCode code, Severity severity,
                       const char* text, std::vector<MessageArg> args) {
    std::vector<MessageArg> all{text_arg("group", group.name())};
    all.insert(all.end(), std::make_move_iterator(args.begin()),
               std::make_move_iterator(args.end()));
    return {code, severity, delay_message(to_string(code), text, std::move(all))};
}

// "500 mm/min, 900 mm/min": the feeds from `first` on, as nested "%1, %2"
// messages, so that the window writes the units and the separator in its
// language. The feeds are named feed_1_mm_min, feed_2_mm_min, ...
MessageArg feed_list(const std::vector<double>& feeds_mm_min, std::size_t first = 0) {
    MessageArg item = feed("feed_" + std::to_string(first + 1) + "_mm_min", feeds_mm_min[first]);
    if (first + 1 >= feeds_mm_min.size()) return item;
    //: a list of feeds, "500 mm/min, 900 mm/min"; %2 is the rest of the list
    return message_arg("feeds", delay_message("feed_list", QT_TRANSLATE_NOOP("DelayFit", "%1, %2"),
                                              {item, feed_list(feeds_mm_min, first + 1)}));
}

// Two degrees of freedom less than the touches for the line: its standard
// deviation, or nullopt when the line passes through every touch by necessity.
std::optional<double> residual_sigma(double sum_of_squares, std::size_t n, std::size_t parameters) {
    if (n <= parameters) return std::nullopt;
    return std::sqrt(sum_of_squares / static_cast<double>(n - parameters));
}

struct Curvature {
    double bow_mm{0.0};        // largest |quadratic - line| at the feeds
    double t_value{0.0};       // curvature term / its standard error (inf when exact)
    double delay_low_s{0.0};   // secant delay of the quadratic at the lowest feed
    double delay_high_s{0.0};  // and at the highest
};

// Fits measured = p0 + d * (b u + c u^2), u = v / v_max, and compares it with
// the line: a constant delay makes c vanish (the line of the delay-stability
// test holds only when tau does not depend on v).
std::optional<Curvature> curvature(const DelayGroup& group, std::span<const DelayTouch> touches,
                                   const LineFit& line) {
    const auto n = static_cast<Eigen::Index>(touches.size());
    if (group.feeds.size() < 3 || n < 4) return std::nullopt;
    const double v_max = mm_min_to_mm_s(group.feeds.back().feed_mm_min);
    const double d = group.direction;
    Eigen::Matrix<double, Eigen::Dynamic, 3> x(n, 3);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double u = mm_min_to_mm_s(touches[static_cast<std::size_t>(i)].feed_mm_min) / v_max;
        x.row(i) << 1.0, d * u, d * u * u;
        y(i) = touches[static_cast<std::size_t>(i)].measured_mm;
    }
    const Eigen::Vector3d coef = x.colPivHouseholderQr().solve(y);
    const double ssr = (x * coef - y).squaredNorm();
    const double sigma2 = ssr / static_cast<double>(n - 3);
    const Eigen::Matrix3d covariance = sigma2 * (x.transpose() * x).inverse();
    const double se = std::sqrt(std::max(covariance(2, 2), 0.0));
    const double scale = std::max(1.0, std::abs(coef(2)));
    Curvature result;
    result.t_value = se > 1e-12 * scale
                         ? coef(2) / se
                         : std::copysign(std::numeric_limits<double>::infinity(), coef(2));
    for (const auto& f : group.feeds) {
        const double v = mm_min_to_mm_s(f.feed_mm_min);
        const double u = v / v_max;
        const double quadratic = coef(0) + d * (coef(1) * u + coef(2) * u * u);
        const double straight = line.intercept + d * v * line.slope;
        result.bow_mm = std::max(result.bow_mm, std::abs(quadratic - straight));
    }
    // d * v * tau(v) = d * (b u + c u^2)  =>  tau(v) = (b + c u) / v_max.
    const double u_low = mm_min_to_mm_s(group.feeds.front().feed_mm_min) / v_max;
    result.delay_low_s = (coef(1) + coef(2) * u_low) / v_max;
    result.delay_high_s = (coef(1) + coef(2)) / v_max;
    return result;
}

void add_warnings(DelayGroup& group, std::span<const DelayTouch> touches, const LineFit& line,
                  const DelayFitOptions& options) {
    auto& warnings = group.warnings;
    if (group.feeds.size() < 3) {
        warnings.push_back(warning(
            group, LatencyWarningCode::few_feeds, Severity::warning,
            QT_TRANSLATE_NOOP("DelayFit",
                              "%1: only %2 feeds; a line through two feeds cannot show whether "
                              "the delay is constant: touch at 3 or more"),
            {arg("feeds", ArgKind::integer, static_cast<double>(group.feeds.size()))}));
    }
    if (group.delay_s < 0.0) {
        warnings.push_back(warning(
            group, LatencyWarningCode::negative_delay, Severity::warning,
            QT_TRANSLATE_NOOP("DelayFit",
                              "%1: the fitted delay is negative (%2): the recorded position moves "
                              "against the travel as the feed rises; check the direction column "
                              "(+1/-1 is the direction of travel)"),
            {ms("delay_s", group.delay_s)}));
    }
    std::vector<double> single_feeds;
    for (const auto& f : group.feeds) {
        if (f.n == 1) single_feeds.push_back(f.feed_mm_min);
    }
    if (!single_feeds.empty()) {
        warnings.push_back(warning(
            group, LatencyWarningCode::single_touch_feed, Severity::info,
            QT_TRANSLATE_NOOP("DelayFit",
                              "%1: one touch only at %2: no scatter there; repeat each touch (5 or "
                              "more) to see the stability"),
            {feed_list(single_feeds)}));
    }

    // A delay that jitters by a fixed time spreads the touches over a range
    // proportional to the speed; the probe's repeatability adds a floor at every
    // speed. So a slower feed predicts range * v_i / v_j at feed i, a faster one
    // at least its own range. A feed far above every prediction is unstable.
    for (std::size_t i = 0; i < group.feeds.size(); ++i) {
        const auto& fi = group.feeds[i];
        if (fi.n < 2) continue;
        double predicted = -1.0;
        for (std::size_t j = 0; j < group.feeds.size(); ++j) {
            const auto& fj = group.feeds[j];
            if (j == i || fj.n < 2) continue;
            predicted =
                std::max(predicted, fj.range_mm * std::max(1.0, fi.feed_mm_min / fj.feed_mm_min));
        }
        if (predicted < 0.0) continue;  // no other feed with scatter
        if (fi.range_mm > options.unstable_ratio * predicted &&
            fi.range_mm > options.scatter_floor_mm) {
            const double v = mm_min_to_mm_s(fi.feed_mm_min);
            warnings.push_back(warning(
                group, LatencyWarningCode::unstable_delay, Severity::warning,
                QT_TRANSLATE_NOOP("DelayFit",
                                  "%1: at %2 the touches spread over %3 (%4 of travel), more than "
                                  "%5x what the other feeds predict (%6): the delay is not stable "
                                  "there; repeat the touches and check the input and the "
                                  "controller load"),
                {feed("feed_mm_min", fi.feed_mm_min), mm("range_mm", fi.range_mm),
                 ms("travel_time_s", fi.range_mm / v),
                 significant_arg("ratio", ArgKind::number, options.unstable_ratio, 3),
                 mm("predicted_range_mm", predicted)}));
        }
    }

    if (const auto curve = curvature(group, touches, line)) {
        if (curve->bow_mm > options.curvature_floor_mm && std::abs(curve->t_value) > 3.0) {
            warnings.push_back(warning(
                group, LatencyWarningCode::curved_residuals, Severity::warning,
                QT_TRANSLATE_NOOP("DelayFit",
                                  "%1: the residuals curve: the touches depart from the line by up "
                                  "to %2; the delay is not constant but goes from %3 at %4 to %5 "
                                  "at %6; a correction with one delay is right at one feed only"),
                {mm("bow_mm", curve->bow_mm), ms("delay_low_s", curve->delay_low_s),
                 feed("feed_low_mm_min", group.feeds.front().feed_mm_min),
                 ms("delay_high_s", curve->delay_high_s),
                 feed("feed_high_mm_min", group.feeds.back().feed_mm_min)}));
        }
    }
}

}  // namespace

std::string LatencyWarning::text() const {
    return render(message);
}

const char* to_string(LatencyWarningCode code) {
    switch (code) {
        case LatencyWarningCode::few_feeds:
            return "few_feeds";
        case LatencyWarningCode::unstable_delay:
            return "unstable_delay";
        case LatencyWarningCode::curved_residuals:
            return "curved_residuals";
        case LatencyWarningCode::negative_delay:
            return "negative_delay";
        case LatencyWarningCode::single_touch_feed:
            return "single_touch_feed";
    }
    return "?";
}

std::string DelayGroup::name() const {
    return axis + (direction > 0 ? "+" : "-");
}

double DelayGroup::predicted_mm(double feed_mm_min) const {
    // Domain.md, "Latency": measured = p0 + dir * v * tau.
    return zero_speed_position_mm + direction * mm_min_to_mm_s(feed_mm_min) * delay_s;
}

std::optional<LineFit> fit_line(std::span<const double> x, std::span<const double> y) {
    const auto n = static_cast<Eigen::Index>(std::min(x.size(), y.size()));
    if (n < 2) return std::nullopt;
    const Eigen::Map<const Eigen::VectorXd> xs(x.data(), n);
    const Eigen::Map<const Eigen::VectorXd> ys(y.data(), n);
    // Centred normal equations: exact for the line and free of the cancellation
    // that raw sums of x^2 suffer at large positions.
    const double x_mean = xs.mean();
    const double y_mean = ys.mean();
    const Eigen::VectorXd dx = xs.array() - x_mean;
    const double sxx = dx.squaredNorm();
    if (!(sxx > 0.0)) return std::nullopt;
    const double slope = dx.dot((ys.array() - y_mean).matrix()) / sxx;
    return LineFit{y_mean - slope * x_mean, slope};
}

std::vector<DelayTouch> parse_delay_csv(std::string_view text) {
    const auto rows = read_csv_rows(text, {"axis", "direction", "feed_mm_min", "measured_mm"});
    std::vector<DelayTouch> touches;
    touches.reserve(rows.size());
    for (const auto& row : rows) {
        DelayTouch touch;
        touch.line = row.line;
        const std::string& axis = row.fields[0];
        const bool valid_axis = !axis.empty() && axis.size() <= 8 &&
                                std::isalpha(static_cast<unsigned char>(axis[0])) &&
                                std::all_of(axis.begin(), axis.end(), [](char c) {
                                    return std::isalnum(static_cast<unsigned char>(c)) != 0;
                                });
        if (!valid_axis) {
            throw CsvError(row.line, "axis",
                           delay_message("not_an_axis",
                                         QT_TRANSLATE_NOOP("DelayFit",
                                                           "'%1' is not an axis name (a letter, "
                                                           "e.g. X, Y, Z)"),
                                         {text_arg("axis", axis)}));
        }
        for (const char c : axis) {
            touch.axis += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
        const double direction = csv_number(row, 1, "direction");
        if (direction != 1.0 && direction != -1.0) {
            throw CsvError(row.line, "direction",
                           delay_message("not_a_direction",
                                         QT_TRANSLATE_NOOP("DelayFit",
                                                           "'%1' is not allowed: +1 or -1, the "
                                                           "direction of travel"),
                                         {text_arg("direction", row.fields[1])}));
        }
        touch.direction = direction > 0.0 ? 1 : -1;
        touch.feed_mm_min = csv_number(row, 2, "feed_mm_min");
        if (!(touch.feed_mm_min > 0.0 && touch.feed_mm_min <= kMaxFeed_mm_min)) {
            throw CsvError(
                row.line, "feed_mm_min",
                delay_message("feed_out_of_range",
                              QT_TRANSLATE_NOOP("DelayFit", "%1 is out of range: (0, %2] mm/min"),
                              {arg("feed_mm_min", ArgKind::number, touch.feed_mm_min),
                               arg("max_feed_mm_min", ArgKind::number, kMaxFeed_mm_min)}));
        }
        touch.measured_mm = csv_coordinate(row, 3, "measured_mm");
        touches.push_back(std::move(touch));
    }
    return touches;
}

DelayFit fit_delay(std::span<const DelayTouch> touches, const DelayFitOptions& options) {
    // Group by (axis, direction), in order of first appearance.
    std::vector<std::vector<DelayTouch>> grouped;
    std::map<std::pair<std::string, int>, std::size_t> index;
    for (const auto& touch : touches) {
        const auto key = std::make_pair(touch.axis, touch.direction);
        auto [it, inserted] = index.try_emplace(key, grouped.size());
        if (inserted) grouped.emplace_back();
        grouped[it->second].push_back(touch);
    }

    DelayFit fit;
    for (auto& members : grouped) {
        DelayGroup group;
        group.axis = members.front().axis;
        group.direction = members.front().direction;
        std::map<double, std::vector<double>> by_feed;
        std::vector<double> x;
        std::vector<double> y;
        for (const auto& touch : members) {
            group.lines.push_back(touch.line);
            by_feed[touch.feed_mm_min].push_back(touch.measured_mm);
            // Domain.md, "Latency": measured = p0 + dir * v * tau, v in mm/s.
            x.push_back(group.direction * mm_min_to_mm_s(touch.feed_mm_min));
            y.push_back(touch.measured_mm);
        }
        if (by_feed.size() < 2) {
            const MessageArg name = text_arg("group", group.name());
            const MessageArg at = feed("feed_mm_min", by_feed.begin()->first);
            const MessageArg lines = message_arg("lines", describe_lines(group.lines));
            throw CsvError(
                members.front().line, "feed_mm_min",
                members.size() == 1
                    ? delay_message("one_feed",
                                    QT_TRANSLATE_NOOP("DelayFit",
                                                      "%1: only one touch (%2, %3); the delay is "
                                                      "the slope over feeds: touch at 2 or more "
                                                      "feeds, 3 or more to check that it is "
                                                      "constant"),
                                    {name, at, lines})
                    : delay_message(
                          "one_feed",
                          QT_TRANSLATE_NOOP("DelayFit",
                                            "%1: all %2 touches are at one feed (%3, %4); the "
                                            "delay is the slope over feeds: touch at 2 or more "
                                            "feeds, 3 or more to check that it is constant"),
                          {name,
                           arg("touches", ArgKind::integer, static_cast<double>(members.size())),
                           at, lines}));
        }
        const auto line = fit_line(x, y);  // two distinct feeds: never nullopt
        group.delay_s = line->slope;
        group.zero_speed_position_mm = line->intercept;
        if (options.interpolation_period_s && *options.interpolation_period_s > 0.0) {
            group.lag_cycles = group.delay_s / *options.interpolation_period_s;
        }
        double ssr = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double r = y[i] - (line->intercept + line->slope * x[i]);
            ssr += r * r;
        }
        if (const auto sigma = residual_sigma(ssr, x.size(), 2)) {
            group.residual_2sigma_mm = 2.0 * *sigma;
        }
        for (const auto& [feed_mm_min, values] : by_feed) {
            const auto [low, high] = std::minmax_element(values.begin(), values.end());
            double sum = 0.0;
            for (const double v : values) sum += v;
            group.feeds.push_back({feed_mm_min, sum / static_cast<double>(values.size()),
                                   *high - *low, values.size()});
        }
        add_warnings(group, members, *line, options);
        fit.groups.push_back(std::move(group));
    }
    return fit;
}

ChosenGroup choose_group(const DelayFit& fit, const std::optional<std::string>& name) {
    if (fit.groups.empty()) {
        throw InputError(delay_message(
            "no_groups", QT_TRANSLATE_NOOP("DelayFit", "the fit has no groups of touches"), {}));
    }
    if (name) {
        std::string wanted;
        for (const char c : *name) {
            wanted += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
        std::string available;
        for (const DelayGroup& g : fit.groups) {
            if (g.name() == wanted) {
                return {&g, delay_message("group_chosen",
                                          QT_TRANSLATE_NOOP("DelayFit", "the group chosen"), {})};
            }
            if (!available.empty()) available += ", ";
            available += g.name();
        }
        throw InputError(delay_message(
            "unknown_group",
            QT_TRANSLATE_NOOP("DelayFit", "got '%1'; allowed: a group of the file (%2)"),
            {text_arg("group", *name), text_arg("groups", available)}));
    }
    if (fit.groups.size() == 1) {
        return {&fit.groups.front(),
                delay_message("only_group", QT_TRANSLATE_NOOP("DelayFit", "the only group"), {})};
    }
    // The scenario has one controller latency for every axis; the longest
    // delay gives the longest overtravel, the safe side for the stylus.
    const DelayGroup& longest = *std::max_element(
        fit.groups.begin(), fit.groups.end(),
        [](const DelayGroup& a, const DelayGroup& b) { return a.delay_s < b.delay_s; });
    return {
        &longest,
        delay_message("longest_delay",
                      QT_TRANSLATE_NOOP("DelayFit",
                                        "the longest delay of %1 groups (the safe side for "
                                        "overtravel); choose one to override"),
                      {arg("groups", ArgKind::integer, static_cast<double>(fit.groups.size()))})};
}

AppliedDelay delay_to_apply(const DelayFit& fit, const Scenario& scenario,
                            const std::optional<std::string>& group) {
    const ChosenGroup chosen_group = choose_group(fit, group);
    const DelayGroup* chosen = chosen_group.group;
    AppliedDelay applied;
    applied.rule = chosen_group.rule;
    applied.group = chosen->name();
    applied.total_delay_s = chosen->delay_s;
    applied.latched = scenario.machine.latched_input;
    if (applied.latched) {
        // Latched in hardware when the signal arrives: tau = t_i.
        applied.key = "probe.interface_delay_s";
        applied.interface_delay_s = applied.total_delay_s;
        applied.previous_s = scenario.probe.interface_delay_s;
        applied.value_s = applied.total_delay_s;
        if (applied.value_s < 0.0) {
            throw InputError(delay_message(
                "negative_delay",
                QT_TRANSLATE_NOOP("DelayFit",
                                  "the fitted delay of %1, %2, is negative: the input is latched, "
                                  "so it would be the probe's interface delay; check the touches"),
                {text_arg("group", applied.group),
                 significant_arg("delay_s", ArgKind::delay_s, applied.total_delay_s, 6)}));
        }
        return applied;
    }
    applied.key = "machine.controller_latency_s";
    applied.interface_delay_s = scenario.probe.interface_delay_s;
    applied.half_scan_s = scenario.machine.scan_period_s / 2.0;
    applied.previous_s = scenario.machine.controller_latency_s;
    applied.value_s = applied.total_delay_s - applied.interface_delay_s - applied.half_scan_s;
    if (applied.value_s < 0.0) {
        throw InputError(delay_message(
            "negative_latency",
            QT_TRANSLATE_NOOP("DelayFit",
                              "the fitted delay of %1, %2, is shorter than the scenario's "
                              "probe.interface_delay_s + half of machine.scan_period_s (%3): the "
                              "controller latency would be negative; check those keys (or "
                              "machine.latched_input) in the scenario"),
            {text_arg("group", applied.group),
             significant_arg("delay_s", ArgKind::delay_s, applied.total_delay_s, 6),
             significant_arg("interface_and_half_scan_s", ArgKind::delay_s,
                             applied.interface_delay_s + applied.half_scan_s, 6)}));
    }
    return applied;
}

Scenario apply_delay(const Scenario& scenario, const AppliedDelay& applied) {
    Scenario out = scenario;
    if (!set_number(out, applied.key, applied.value_s)) {
        throw std::logic_error("apply_delay: no key " + applied.key);
    }
    validate_or_throw(out);
    return out;
}

}  // namespace probecycle
