#include "core/common/vector_state.h"

#include <gtest/gtest.h>

#include "core/cycle/cycle.h"

namespace probecycle {
namespace {

// clear_vector_upper_state() only changes how fast legacy SSE code runs after
// AVX code (measured in probecycle-ui-bench, BM_Recompute_Fanuc); what the
// core computes between calls is the same to the bit.
TEST(VectorState, ClearingTheUpperHalvesChangesNoResult) {
    Scenario s;
    s.cycle.feature = Feature::bore;
    s.machine.accel_model = AccelModel::none;
    s.machine.filter = FilterKind::exponential;
    s.machine.filter_time_s = 0.032;
    s.machine.servo_time_constant_s = 0.033;
    ASSERT_TRUE(validate(s).empty());
    const CycleResult before = evaluate(s);
    clear_vector_upper_state();
    const CycleResult after = evaluate(s);
    clear_vector_upper_state();
    clear_vector_upper_state();  // and again: nothing to clear
    const CycleResult again = evaluate(s);
    EXPECT_EQ(after.total(), before.total());
    EXPECT_EQ(again.total(), before.total());
    EXPECT_EQ(after.overtravel_mm(), before.overtravel_mm());
    EXPECT_EQ(after.uncertainty_mm(), before.uncertainty_mm());
}

}  // namespace
}  // namespace probecycle
