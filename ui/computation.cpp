#include "computation.h"

#include <algorithm>
#include <cmath>

namespace probecycle::ui {

Computation::Computation(std::size_t points_per_curve)
    : feeds_(log_feeds(kKneeSearchFrom_mm_min, kKneeSearchTo_mm_min,
                       std::max<std::size_t>(points_per_curve, 2))) {
    result_.single_touch.points.reserve(feeds_.size());
    result_.two_touch.points.reserve(feeds_.size());
}

const Computed& Computation::run(const Scenario& scenario) {
    Computed& r = result_;
    r.scenario = scenario;
    r.errors = validate(scenario);
    if (!r.errors.empty()) return r;

    r.analysis = analyse(scenario);
    variant_ = scenario;
    variant_.cycle.strategy = Strategy::single_touch;
    sweep_feeds_into(variant_, feeds_, r.single_touch);
    variant_.cycle.strategy = Strategy::two_touch;
    sweep_feeds_into(variant_, feeds_, r.two_touch, {.recommended_backoff = true});
    return r;
}

std::vector<double> report_feeds(const Computed& computed) {
    std::vector<double> feeds = {10,   20,   30,   50,   75,   100,  150,  200,
                                 300,  400,  500,  600,  800,  1000, 1200, 1500,
                                 2000, 2500, 3000, 4000, 5000, 6000, 8000, 10000};
    feeds.push_back(computed.scenario.cycle.probe_feed_mm_min);
    if (computed.analysis.knee_feed_mm_min) {
        feeds.push_back(std::round(*computed.analysis.knee_feed_mm_min));
    }
    std::sort(feeds.begin(), feeds.end());
    feeds.erase(std::unique(feeds.begin(), feeds.end()), feeds.end());
    return feeds;
}

}  // namespace probecycle::ui
