#include "ui/cycle/computation.h"

#include <algorithm>
#include <cmath>

#include "core/common/vector_state.h"

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

    clear_vector_upper_state();  // what Qt painted may have left them in use
    r.analysis = analyse(scenario);
    variant_ = scenario;
    variant_.cycle.strategy = Strategy::single_touch;
    sweep_feeds_into(variant_, feeds_, r.single_touch);
    variant_.cycle.strategy = Strategy::two_touch;
    sweep_feeds_into(variant_, feeds_, r.two_touch, {.recommended_backoff = true});
    return r;
}

}  // namespace probecycle::ui
