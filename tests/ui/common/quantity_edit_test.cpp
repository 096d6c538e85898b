// A scenario key's editor: its spin box is a UnitSpinBox in the key's
// display unit; set_value() speaks internal units and is not an edit.

#include "ui/common/quantity_edit.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <cmath>

#include "core/cycle/scenario.h"
#include "ui/common/parameter_info.h"

namespace probecycle::ui {
namespace {

TEST(QuantityEdit, ItsSpinBoxShowsTheKeysDisplayUnit) {
    int checked = 0;
    for (const KeyInfo& info : numeric_keys()) {
        const ParameterView view = parameter_view(info);
        QuantityEdit edit(info);
        UnitSpinBox* spin = edit.spin_box();
        EXPECT_EQ(spin->suffix(), QStringLiteral(" ") + view.unit) << info.key;
        EXPECT_EQ(spin->decimals(), view.decimals) << info.key;
        EXPECT_DOUBLE_EQ(spin->minimum(), view.min * view.factor) << info.key;
        QSignalSpy edits(&edit, &QuantityEdit::edited);
        const double value = 0.5 * (view.min + view.max);
        edit.set_value(value);
        EXPECT_DOUBLE_EQ(edit.value(), value) << info.key;
        EXPECT_NEAR(spin->internal_value(), value,
                    0.5 * std::pow(10.0, -view.decimals) / view.factor + 1e-12 * std::abs(value))
            << info.key;
        EXPECT_EQ(edits.count(), 0) << info.key;
        ++checked;
    }
    EXPECT_GT(checked, 10);
}

}  // namespace
}  // namespace probecycle::ui
