// A value with its unit: display units in the box, internal units outside,
// the unit re-read on retranslate, one edit per value typed.

#include "ui/common/unit_spin_box.h"

#include <gtest/gtest.h>

#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>

namespace probecycle::ui {
namespace {

TEST(UnitSpinBox, ShowsDisplayUnitsAndSpeaksInternalUnits) {
    // A tolerance in mm shown in µm.
    UnitSpinBox box(1e-4, 100.0, 1, 0.01, nullptr, 1000.0);
    EXPECT_DOUBLE_EQ(box.value(), 10.0);
    EXPECT_DOUBLE_EQ(box.internal_value(), 0.01);
    EXPECT_DOUBLE_EQ(box.minimum(), 0.1);
    EXPECT_DOUBLE_EQ(box.maximum(), 100000.0);
    box.set_internal_value(0.0025);
    EXPECT_DOUBLE_EQ(box.value(), 2.5);
    EXPECT_EQ(box.decimals(), 1);
}

TEST(UnitSpinBox, TheUnitIsReadAgainOnRetranslate) {
    UnitSpinBox box(0.0, 10.0, 3, 1.0);
    QString unit = QStringLiteral("mm");
    box.set_unit([&unit] { return unit; });
    EXPECT_EQ(box.suffix(), QStringLiteral(" mm"));
    unit = QStringLiteral("мм");
    EXPECT_EQ(box.suffix(), QStringLiteral(" mm"));
    box.retranslate();
    EXPECT_EQ(box.suffix(), QStringLiteral(" мм"));
}

TEST(UnitSpinBox, OneEditPerValueTyped) {
    UnitSpinBox box(0.0, 1000.0, 1, 1.0);
    box.show();
    QSignalSpy edits(&box, &QDoubleSpinBox::valueChanged);
    box.findChild<QLineEdit*>()->selectAll();
    QTest::keyClicks(&box, QStringLiteral("123.4"));
    EXPECT_EQ(edits.count(), 0);
    QTest::keyClick(&box, Qt::Key_Return);
    ASSERT_EQ(edits.count(), 1);
    EXPECT_DOUBLE_EQ(box.internal_value(), 123.4);
}

}  // namespace
}  // namespace probecycle::ui
