// A control's log (docs/programs.md), imported for a plan. The first
// byte picks the plan and the dialect: '0' to '9' and 'a' to 'h' (slots 0
// to 17; every other byte picks one, modulo 18) stand for plan (slot / 6:
// delay, ring, cycle, each from the default scenario and options) and
// dialect (slot % 6: linuxcnc, grbl, fanuc, haas, mitsubishi, siemens); the
// rest is the log. Any log is refused with a CsvError (an
// InputError for the cycle plan, which has no lab table), or gives the lab's
// CSV that parse_delay_csv / parse_ring_csv read back: one row per recorded
// touch of the plan, in order, with its axis, direction and feed (delay) or
// its orientation (ring). A blank line before the log changes nothing (every
// importer skips blank lines). For the cycle's slots the same log is also
// matched (recorded_touch_positions) to the default cycle and to a bore's
// (protected moves, two repeats at each point): the positions of exactly the
// plan's recorded touches, or a CsvError; and imported as a cycle's log
// (import_cycle_log): a finite feature result, or a CsvError.
//
// The seeds (fuzz/seeds/machine_log/, named for their first byte) are logs of
// these plans in each format. The LinuxCNC LOG files, the DPRNT outputs, the
// Mitsubishi variable lists and the Siemens WRITE files carry the plan's id, as `probecycle-cli
// program delay|ring|cycle` writes it with the default scenario and options: a change to those
// plans makes the ids stale (the import then stops at the id), and the seeds need the new ids.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"
#include "core/cycle/scenario.h"
#include "core/lab/calibration.h"
#include "core/lab/delay_fit.h"
#include "core/program/cycle_import.h"
#include "core/program/dialect.h"
#include "core/program/machine_log.h"
#include "core/program/plan.h"

namespace {

using namespace probecycle;

const std::array<ProbingPlan, 3>& plans() {
    static const std::array<ProbingPlan, 3> kPlans = {
        make_delay_plan(Scenario{}, DelayPlanOptions{}),
        make_ring_plan(Scenario{}, RingPlanOptions{}),
        make_cycle_plan(Scenario{}, CyclePlanOptions{}),
    };
    return kPlans;
}

// A two-touch bore with cycle.repeats 2: protected moves between its touches.
const ProbingPlan& bore_plan() {
    static const ProbingPlan kPlan = [] {
        Scenario bore;
        bore.cycle.feature = Feature::bore;
        bore.cycle.repeats = 2.0;
        return make_cycle_plan(bore, CyclePlanOptions{});
    }();
    return kPlan;
}

// Matched to `plan`: as many positions as it records, or a CsvError.
void check_recorded(const ProbingPlan& plan, DialectId dialect, std::string_view text) {
    try {
        if (recorded_touch_positions(plan, dialect, text).size() != plan.recorded().size()) {
            std::abort();
        }
    } catch (const CsvError& e) {
        (void)e.to_message();
    }
}

// The CSV holds one row per recorded touch of the plan, each the touch's.
void check_lab_csv(const ProbingPlan& plan, const std::string& csv) {
    const std::vector<const ProgramStep*> recorded = plan.recorded();
    if (plan.kind == ProgramKind::delay) {
        const std::vector<DelayTouch> touches = parse_delay_csv(csv);
        if (touches.size() != recorded.size()) std::abort();
        for (std::size_t i = 0; i < touches.size(); ++i) {
            if (touches[i].axis != std::string(1, recorded[i]->axis) ||
                touches[i].direction != recorded[i]->direction ||
                touches[i].feed_mm_min != recorded[i]->feed_mm_min) {
                std::abort();
            }
        }
    } else if (plan.kind == ProgramKind::ring) {
        const std::vector<RingPoint> points = parse_ring_csv(csv);
        if (points.size() != recorded.size()) std::abort();
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (points[i].orientation_deg != recorded[i]->orientation_deg) std::abort();
        }
    } else {
        std::abort();  // a cycle plan has no table
    }
}

// Imported as a cycle's log: a result of finite figures, or a CsvError.
void check_cycle_import(const ProbingPlan& plan, DialectId dialect, std::string_view text) {
    try {
        const CycleImport import = import_cycle_log(plan, dialect, text);
        if (!std::isfinite(import.result.size_mm) || !std::isfinite(import.result.deviation_mm)) {
            std::abort();
        }
        (void)cycle_import_text(import);
        (void)cycle_import_json(import);
    } catch (const CsvError& e) {
        (void)e.to_message();
    }
}

// The first byte's slot, 0 to 17: '0'-'9' and 'a'-'h' as digits, any other
// byte modulo 18.
unsigned slot(std::uint8_t byte) {
    if (byte >= '0' && byte <= '9') return byte - '0';
    if (byte >= 'a' && byte <= 'h') return byte - 'a' + 10u;
    return byte % 18u;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const unsigned pick = slot(data[0]);
    const ProbingPlan& plan = plans()[pick / 6];
    const DialectId dialect = all_dialects()[pick % 6];
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    if (plan.kind == ProgramKind::cycle) {
        check_recorded(plan, dialect, text);
        check_recorded(bore_plan(), dialect, text);
        check_cycle_import(plan, dialect, text);
        check_cycle_import(bore_plan(), dialect, text);
    }
    std::string csv;
    try {
        csv = import_machine_log(plan, dialect, text);
    } catch (const CsvError& e) {
        (void)e.to_message();
        return 0;
    } catch (const InputError& e) {
        if (plan.kind != ProgramKind::cycle) std::abort();
        (void)e.to_message();
        return 0;
    }
    check_lab_csv(plan, csv);
    if (import_machine_log(plan, dialect, "\n" + std::string(text)) != csv) std::abort();
    return 0;
}
