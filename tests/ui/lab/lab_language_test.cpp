// The lab tabs in Chinese and Russian: the texts that come from core (file
// errors, warnings, the applied-delay rule, setup errors) are translated, not
// shown in English (ui/common/language.h, ui/common/text_format.h).

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <cstdlib>

#include "core/lab/calibration.h"
#include "core/lab/delay_fit.h"
#include "tests/ui/lab/lab_test_data.h"
#include "ui/common/language.h"
#include "ui/lab/calibration_tab.h"
#include "ui/lab/compensation_panel.h"
#include "ui/lab/latency_tab.h"

namespace probecycle::ui {
namespace {

using lab_test::lab_data;

// Touches with warnings: X+ about 10 ms with an unstable feed at 1000 mm/min,
// Y- at two feeds (few feeds), one touch each.
constexpr const char* kWarningTouches =
    "axis,direction,feed_mm_min,measured_mm\n"
    "X,1,100,10.0167\nX,1,100,10.0169\nX,1,1000,10.1667\nX,1,1000,10.1747\n"
    "X,1,2000,10.3333\nX,1,2000,10.3335\n"
    "Y,-1,500,5.0\nY,-1,900,4.9999\n";

// Words of three letters or more in an English template, less the names that
// stay as written in every language (CSV columns, scenario keys).
QSet<QString> english_words(const char* text) {
    static const QSet<QString> kKept = {QStringLiteral("direction"),
                                        QStringLiteral("probe"),
                                        QStringLiteral("interface_delay_s"),
                                        QStringLiteral("machine"),
                                        QStringLiteral("scan_period_s"),
                                        QStringLiteral("latched_input"),
                                        QStringLiteral("y_mm")};
    QSet<QString> words;
    static const QRegularExpression kWord(QStringLiteral("[A-Za-z_]{3,}"));
    auto it = kWord.globalMatch(QString::fromUtf8(text));
    while (it.hasNext()) {
        const QString word = it.next().captured();
        if (!kKept.contains(word)) words.insert(word);
    }
    return words;
}

// The English words of `templates` that `shown` contains, as whole words,
// separated by spaces ("" when none).
std::string english_left(const QString& shown, const std::vector<const char*>& templates) {
    QStringList left;
    for (const char* text : templates) {
        for (const QString& word : english_words(text)) {
            const QRegularExpression whole(QStringLiteral("\\b%1\\b").arg(word));
            if (whole.match(shown).hasMatch()) left << word;
        }
    }
    return left.join(QLatin1Char(' ')).toStdString();
}

// With PROBECYCLE_LAB_SCREENSHOTS=DIR, the tab as shown, to look at.
void save_screenshot(QWidget& tab, const QString& name) {
    const char* out = std::getenv("PROBECYCLE_LAB_SCREENSHOTS");
    if (out == nullptr) return;
    QCoreApplication::processEvents();
    tab.grab().save(QString::fromLocal8Bit(out) + QLatin1Char('/') + name + QLatin1Char('_') +
                    current_language() + QStringLiteral(".png"));
}

class LabLanguage : public ::testing::TestWithParam<const char*> {
  protected:
    void SetUp() override {
        ASSERT_EQ(apply_language(QLatin1String(GetParam())), QLatin1String(GetParam()));
    }
    void TearDown() override { apply_language(QStringLiteral("en")); }
};

TEST_P(LabLanguage, CalibrationWarningsAndErrorsAreTranslated) {
    CalibrationTab tab;
    tab.resize(1280, 800);
    tab.show();
    tab.set_gauge_diameter_mm(50.0);
    ASSERT_TRUE(tab.import_file(lab_data("lab_ring_one_orientation.csv")))
        << tab.last_error().toStdString();
    tab.set_length_inputs({10.0, QStringLiteral("110.0012"), 0.0, 99.0});
    ASSERT_TRUE(tab.warning_codes().contains(QStringLiteral("single_orientation")));
    ASSERT_TRUE(tab.warning_codes().contains(QStringLiteral("length_wear")));

    // The templates behind what is shown.
    const RingCalibration& ring = *tab.result();
    std::vector<const char*> templates;
    for (const CalibrationWarning& w : ring.warnings) templates.push_back(w.message.text);
    for (const CalibrationWarning& w : tab.length_result()->warnings) {
        templates.push_back(w.message.text);
    }
    const QString shown = tab.warning_texts().join(QLatin1Char('\n'));
    EXPECT_EQ(english_left(shown, templates), "") << shown.toStdString();
    if (QLatin1String(GetParam()) == QLatin1String("zh_CN")) {
        EXPECT_TRUE(shown.contains(QStringLiteral("只给出了定向 0°：无法求跳动")))
            << shown.toStdString();
    } else {
        EXPECT_TRUE(shown.contains(QStringLiteral("задана только ориентация 0°: биения нет")))
            << shown.toStdString();
    }

    // A file error names its line and column in the interface language.
    EXPECT_FALSE(tab.import_file(lab_data("lab_ring_text_in_number.csv")));
    const QString error = tab.last_error();
    EXPECT_EQ(english_left(error, {"line %1, column %2: %3",
                                   "'%1' is not a number (use '.' as the decimal point)"}),
              "")
        << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("4"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("y_mm"))) << error.toStdString();
    save_screenshot(tab, QStringLiteral("calibration_tab"));

    // A refusal: the gauge smaller than the touches.
    tab.set_points_text(QStringLiteral("orientation_deg,x_mm,y_mm\n0,10,0\n0,-10,0\n0,0,10\n"));
    tab.set_gauge_diameter_mm(10.0);
    EXPECT_FALSE(tab.fit());
    EXPECT_EQ(english_left(tab.last_error(),
                           {"the touches lie on a circle of radius %1, not inside the gauge of "
                            "radius %2 (diameter %3): the effective ball radius would not be "
                            "positive; check the gauge diameter"}),
              "")
        << tab.last_error().toStdString();
}

TEST_P(LabLanguage, LatencyWarningsTheRuleAndSetupErrorsAreTranslated) {
    LatencyTab tab;
    tab.resize(1280, 800);
    tab.show();
    tab.set_touches_text(QString::fromUtf8(kWarningTouches));
    ASSERT_TRUE(tab.fit()) << tab.last_error().toStdString();
    for (const char* code : {"few_feeds", "single_touch_feed", "unstable_delay"}) {
        EXPECT_TRUE(tab.warning_codes().contains(QLatin1String(code))) << code;
    }
    std::vector<const char*> templates;
    for (const DelayGroup& g : tab.delay_fit()->groups) {
        for (const LatencyWarning& w : g.warnings) templates.push_back(w.message.text);
    }
    const QString shown = tab.warning_texts().join(QLatin1Char('\n'));
    EXPECT_EQ(english_left(shown, templates), "") << shown.toStdString();
    // Units in the interface language, not the core's English "mm/min".
    EXPECT_FALSE(shown.contains(QStringLiteral("mm/min, "))) << shown.toStdString();

    // The rule that chose the group, in the tooltip of the breakdown.
    tab.set_scenario(Scenario{});
    auto* breakdown = tab.findChild<QLabel*>(QStringLiteral("apply-breakdown"));
    ASSERT_NE(breakdown, nullptr);
    const auto pending = tab.pending_application();
    ASSERT_TRUE(pending.has_value()) << tab.apply_problem().toStdString();
    EXPECT_FALSE(breakdown->toolTip().isEmpty());
    EXPECT_EQ(english_left(breakdown->toolTip(), {pending->rule.text}), "")
        << breakdown->toolTip().toStdString();
    save_screenshot(tab, QStringLiteral("latency_tab"));

    // A delay that cannot be applied, and a bad file.
    Scenario slow_interface;
    slow_interface.probe.interface_delay_s = 0.02;
    tab.set_scenario(slow_interface);
    EXPECT_FALSE(tab.apply_to_scenario());
    EXPECT_EQ(english_left(tab.last_error(),
                           {"the fitted delay of %1, %2, is shorter than the scenario's "
                            "probe.interface_delay_s + half of machine.scan_period_s (%3): the "
                            "controller latency would be negative; check those keys (or "
                            "machine.latched_input) in the scenario"}),
              "")
        << tab.last_error().toStdString();
    EXPECT_FALSE(tab.import_file(lab_data("lab_delay_text_in_number.csv")));
    EXPECT_EQ(english_left(tab.last_error(), {"line %1, column %2: %3",
                                              "'%1' is not a number (use '.' as the decimal "
                                              "point)"}),
              "")
        << tab.last_error().toStdString();
    save_screenshot(tab, QStringLiteral("latency_tab_error"));

    // The compensation setup names its fields by the window's labels.
    EXPECT_EQ(CompensationPanel::field_label("feed-mm-min"),
              QLatin1String(GetParam()) == QLatin1String("zh_CN") ? QStringLiteral("进给率")
                                                                  : QStringLiteral("Подача"));
}

// Test names in ctest: "zh_CN", "ru".
struct LanguageName {
    std::string operator()(const testing::TestParamInfo<const char*>& language) const {
        return language.param;
    }
};

INSTANTIATE_TEST_SUITE_P(Languages, LabLanguage, ::testing::Values("zh_CN", "ru"), LanguageName{});

}  // namespace
}  // namespace probecycle::ui
