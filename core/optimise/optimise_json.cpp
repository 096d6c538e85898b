#include "core/optimise/optimise_json.h"

#include <nlohmann/json.hpp>

#include "core/common/message_json.h"

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

Json candidate_json(const Candidate& c) {
    const Settings& s = c.settings;
    return {{"strategy", to_string(s.strategy)},
            {"probe_feed_mm_min", s.probe_feed_mm_min},
            {"measure_feed_mm_min", s.measure_feed_mm_min},
            {"backoff_mm", s.backoff_mm},
            {"approach_mm", s.approach_mm},
            {"repeats", s.repeats},
            {"position_feed_mm_min", s.position_feed_mm_min},
            {"cycle_time_s", c.cycle_time_s},
            {"uncertainty_mm", c.uncertainty_mm},
            {"checked_overtravel_mm", c.overtravel_mm}};
}

}  // namespace

std::string optimise_to_json(const OptimiseResult& r) {
    Json out = Json::object();
    out["best"] = candidate_json(r.best);
    out["current"] = candidate_json(r.current);
    out["current_meets_requirements"] = r.current_meets_requirements;
    out["uncertainty_bound_mm"] = r.uncertainty_bound_mm;
    out["saved_s"] = r.saved_s;
    Json binding = Json::array();
    for (const Requirement requirement : r.binding) binding.push_back(to_string(requirement));
    out["binding"] = std::move(binding);
    Json advice = Json::array();
    for (const Advice& a : r.advice) {
        advice.push_back({{"code", a.code},
                          {"message", render(a.message)},
                          {"saved_s", a.saved_s},
                          {"values", message_values(a.message)}});
    }
    out["advice"] = std::move(advice);
    if (r.savings) {
        out["savings"] = {
            {"saved_per_part_s", r.savings->saved_per_part_s},
            {"hours_per_year", r.savings->hours_per_year},
            {"cost_per_year",
             r.savings->cost_per_year ? Json(*r.savings->cost_per_year) : Json(nullptr)}};
    } else {
        out["savings"] = nullptr;
    }
    Json pareto = Json::array();
    for (const Candidate& c : r.pareto) pareto.push_back(candidate_json(c));
    out["pareto"] = std::move(pareto);
    return out.dump(2) + "\n";
}

}  // namespace probecycle
