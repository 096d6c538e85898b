// The CSV reports' words as a reader reads them (English: this test loads no
// translation): columns with their units, quantities of a group, symbols as
// they are.

#include "ui/common/report_tables.h"

#include <gtest/gtest.h>

namespace probecycle::ui {
namespace {

TEST(ReportWord, ColumnsQuantitiesAndSectionsReadAsWords) {
    EXPECT_EQ(report_word(QStringLiteral("center_x_mm")), QStringLiteral("Centre X [mm]"));
    EXPECT_EQ(report_word(QStringLiteral("delay_s")), QStringLiteral("Delay [s]"));
    EXPECT_EQ(report_word(QStringLiteral("feed_mm_min")), QStringLiteral("Feed [mm/min]"));
    EXPECT_EQ(report_word(QStringLiteral("orientation_deg")),
              QStringLiteral("Spindle orientation [deg]"));
    EXPECT_EQ(report_word(QStringLiteral("effective_radius")), QStringLiteral("Effective radius"));
    EXPECT_EQ(report_word(QStringLiteral("residual X+")), QStringLiteral("Residual X+"));
    EXPECT_EQ(report_word(QStringLiteral("ring")), QStringLiteral("Ring gauge"));
    EXPECT_EQ(report_word(QStringLiteral("warnings")), QStringLiteral("Warnings"));
    EXPECT_EQ(report_word(QStringLiteral("mm")), QStringLiteral("mm"));
}

TEST(ReportWord, SymbolsAndUnknownWordsStayAsTheyAre) {
    EXPECT_EQ(report_word(QStringLiteral("ex")), QStringLiteral("ex"));
    EXPECT_EQ(report_word(QStringLiteral("X+")), QStringLiteral("X+"));
    EXPECT_EQ(report_word(QStringLiteral("x_mm")), QStringLiteral("x [mm]"));
    EXPECT_EQ(report_word(QStringLiteral("lab_ring.csv")), QStringLiteral("lab_ring.csv"));
}

}  // namespace
}  // namespace probecycle::ui
