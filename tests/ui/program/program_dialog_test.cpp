// Programs for the control and its log read back, in the window
// (docs/programs.md, "In the window"): the dialog's program is the core's for
// the same plan, a refusal is shown in place and disables Save, Save writes the
// program and its plan, and "Import machine log" fills a tab's paste box and
// fits, or leaves the tab as it was and names the line; in every language.

#include "ui/program/program_dialog.h"

#include <gtest/gtest.h>

#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/common/file_io.h"
#include "core/program/machine_log.h"
#include "core/program/program_writer.h"
#include "tests/core/program/program_test_plans.h"
#include "ui/common/language.h"
#include "ui/lab/calibration_tab.h"
#include "ui/lab/latency_tab.h"
#include "ui/program/machine_log_import.h"

namespace probecycle::ui {
namespace {

std::string read_back(const QString& path) {
    return read_text_file(QFile::encodeName(path).toStdString());
}

void write_text(const QString& path, const std::string& text) {
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text.data(), static_cast<qint64>(text.size()));
}

QString shown_text(const QWidget& dialog, const char* name) {
    const auto* label = dialog.findChild<QLabel*>(QLatin1String(name));
    return label && label->isVisible() ? label->text() : QString();
}

using program_test::grbl_console;
using program_test::linuxcnc_log;
using program_test::linuxcnc_ring_log;
using program_test::small_delay_options;

TEST(ProgramDialog, OffersTheCoresDialects) {
    const std::vector<DialectId> dialects = program_dialects();
    ASSERT_GE(dialects.size(), 2u);
    EXPECT_EQ(dialects[0], DialectId::linuxcnc);
    EXPECT_EQ(dialects[1], DialectId::grbl);
    EXPECT_EQ(plan_path_for(QStringLiteral("/tmp/x/delay.ngc")),
              QStringLiteral("/tmp/x/delay.plan.json"));
}

TEST(ProgramDialog, ThePreviewIsTheCoresProgramInEveryDialect) {
    Scenario scenario;
    scenario.cycle.probe_feed_mm_min = 1500.0;
    ProgramDialog delay(ProgramKind::delay, scenario);
    // The defaults: the core's, the feeds from the scenario.
    EXPECT_EQ(delay.delay_options().feeds_mm_min, default_delay_feeds(scenario));
    const DelayPlanOptions options = small_delay_options();
    delay.set_delay_options(options);
    ProgramDialog ring(ProgramKind::ring, scenario);
    RingPlanOptions ring_options;
    ring_options.gauge_diameter_mm = 40.0;
    ring_options.ball_diameter_mm = 4.0;
    ring.set_ring_options(ring_options);
    for (DialectId id : program_dialects()) {
        SCOPED_TRACE(dialect(id).name);
        delay.set_dialect(id);
        delay.update_now();
        const ProbingPlan delay_plan = make_delay_plan(scenario, options);
        ASSERT_TRUE(delay.can_save()) << delay.problem().toStdString();
        EXPECT_EQ(delay.program_text().toStdString(),
                  write_program(delay_plan, dialect(id), delay.date()));
        EXPECT_EQ(probing_plan_json(*delay.plan()), probing_plan_json(delay_plan));
        EXPECT_EQ(
            delay.findChild<QPlainTextEdit*>(QStringLiteral("program-preview"))->toPlainText(),
            delay.program_text());

        ring.set_dialect(id);
        ring.update_now();
        auto* orient = ring.findChild<QLineEdit*>(QStringLiteral("program-orient-180"));
        ASSERT_NE(orient, nullptr);
        EXPECT_EQ(orient->isEnabled(), dialect(id).orient_from_user);
        ProgramOptions program_options;
        if (dialect(id).orient_from_user) {
            // No common word turns the spindle: refused until the user gives the block.
            EXPECT_FALSE(ring.can_save());
            // ... naming the field, not the CLI's option.
            EXPECT_TRUE(ring.problem().startsWith(QStringLiteral("Spindle to 180°:")))
                << ring.problem().toStdString();
            orient->setText(QStringLiteral("M19 R180."));
            ring.update_now();
            program_options.orient_180_command = "M19 R180.";
        }
        ASSERT_TRUE(ring.can_save()) << ring.problem().toStdString();
        EXPECT_EQ(ring.program_text().toStdString(),
                  write_program(make_ring_plan(scenario, ring_options), dialect(id), ring.date(),
                                program_options));
        orient->clear();
    }
}

// The probe's input is asked only where the probing moves name it
// (Siemens's MEAS=); the program is the core's with the input chosen.
TEST(ProgramDialog, TheProbeInputServesTheDialectsThatNameIt) {
    const Scenario scenario;
    ProgramDialog delay(ProgramKind::delay, scenario);
    delay.set_delay_options(small_delay_options());
    auto* input = delay.findChild<QComboBox*>(QStringLiteral("program-probe-input"));
    ASSERT_NE(input, nullptr);
    ASSERT_EQ(input->count(), 4);
    for (DialectId id : program_dialects()) {
        SCOPED_TRACE(dialect(id).name);
        delay.set_dialect(id);
        delay.update_now();
        EXPECT_EQ(input->isEnabled(), names_probe_input(dialect(id)));
    }
    delay.set_dialect(DialectId::siemens);
    input->setCurrentIndex(3);  // probe 2, signal falling
    delay.update_now();
    ProgramOptions options;
    options.probe_input = -2;
    EXPECT_EQ(delay.program_text().toStdString(),
              write_program(make_delay_plan(scenario, small_delay_options()),
                            dialect(DialectId::siemens), delay.date(), options));
    EXPECT_NE(delay.program_text().indexOf(QStringLiteral("MEAS=-2 G90 G1 Z=R1")), -1);
    EXPECT_NE(delay.program_text().indexOf(QStringLiteral("IF $A_PROBE[2]<>1 GOTOF NO_TRIGGER")),
              -1);
}

TEST(ProgramDialog, TheTunedCycleIsTheCoresProgramInEveryDialect) {
    Scenario scenario;
    scenario.cycle.probe_feed_mm_min = 1500.0;
    ProgramDialog cycle(ProgramKind::cycle, scenario);
    EXPECT_EQ(to_string(cycle.cycle_options().touch), to_string(CyclePlanOptions{}.touch));
    CyclePlanOptions options;
    options.touch = {'X', 1};
    cycle.set_cycle_options(options);
    for (DialectId id : program_dialects()) {
        SCOPED_TRACE(dialect(id).name);
        cycle.set_dialect(id);
        cycle.update_now();
        ASSERT_TRUE(cycle.can_save()) << cycle.problem().toStdString();
        const ProbingPlan plan = make_cycle_plan(scenario, options);
        EXPECT_EQ(cycle.program_text().toStdString(),
                  write_program(plan, dialect(id), cycle.date()));
        EXPECT_EQ(probing_plan_json(*cycle.plan()), probing_plan_json(plan));
    }
    // The feeds, the backoff and the start distance are the scenario's.
    EXPECT_NE(cycle.program_text().indexOf(QStringLiteral("1500")), -1);
}

TEST(ProgramDialog, ATunedCycleTheCoreRefusesIsShownInPlace) {
    Scenario scenario;
    // Two-touch with a backoff that leaves the probe deflected after the
    // first touch's overtravel.
    scenario.cycle.backoff_mm = 0.01;
    ProgramDialog cycle(ProgramKind::cycle, scenario);
    cycle.show();
    cycle.update_now();
    EXPECT_FALSE(cycle.can_save());
    EXPECT_TRUE(cycle.program_text().isEmpty());
    EXPECT_FALSE(cycle.findChild<QPushButton*>(QStringLiteral("program-save"))->isEnabled());
    const QString shown = shown_text(cycle, "program-problem");
    // The window shows the backoff in its own units (10.0 µm).
    EXPECT_TRUE(shown.startsWith(QStringLiteral("the backoff ")) &&
                shown.indexOf(QStringLiteral("does not clear the first touch's overtravel")) != -1)
        << shown.toStdString();
    EXPECT_NE(shown.indexOf(QStringLiteral("set cycle.backoff_mm to at least")), -1)
        << shown.toStdString();
}

TEST(ProgramDialog, AFeaturesCycleIsTheCoresProgramAndItsAxisIsNamedWhenRefused) {
    Scenario bore;
    bore.cycle.feature = Feature::bore;
    ProgramDialog cycle(ProgramKind::cycle, bore);
    cycle.show();
    cycle.set_dialect(DialectId::linuxcnc);
    cycle.update_now();
    ASSERT_TRUE(cycle.can_save()) << cycle.problem().toStdString();
    EXPECT_EQ(
        cycle.program_text().toStdString(),
        write_program(make_cycle_plan(bore, CyclePlanOptions{}), linuxcnc_dialect(), cycle.date()));
    EXPECT_NE(cycle.program_text().indexOf(QStringLiteral("G38.3")), -1);
    // A bore is touched at X+, X-, Y+ and Y-: the axis is not used.
    EXPECT_FALSE(cycle.findChild<QComboBox*>(QStringLiteral("program-axis"))->isEnabled());

    // A pocket along Z is refused naming the dialog's field; along X it is written.
    Scenario pocket;
    pocket.cycle.feature = Feature::pocket;
    ProgramDialog along(ProgramKind::cycle, pocket);
    along.show();
    along.update_now();
    EXPECT_TRUE(along.findChild<QComboBox*>(QStringLiteral("program-axis"))->isEnabled());
    EXPECT_FALSE(along.can_save());
    EXPECT_TRUE(shown_text(along, "program-problem")
                    .startsWith(QStringLiteral("Axis and direction: got Z-; allowed: X+, X-, Y+ "
                                               "or Y- for a pocket")))
        << shown_text(along, "program-problem").toStdString();
    along.set_cycle_options(CyclePlanOptions{{'X', 1}});
    along.update_now();
    EXPECT_TRUE(along.can_save()) << along.problem().toStdString();
}

TEST(ProgramDialog, TheTabsOpenItWithTheirScenarioAndGauge) {
    Scenario scenario;
    scenario.cycle.probe_feed_mm_min = 1500.0;
    LatencyTab latency;
    latency.set_scenario(scenario);
    ProgramDialog* delay = latency.open_program_dialog();
    ASSERT_NE(delay, nullptr);
    EXPECT_EQ(delay->kind(), ProgramKind::delay);
    EXPECT_EQ(delay->delay_options().feeds_mm_min, default_delay_feeds(scenario));
    delay->close();

    CalibrationTab calibration;
    calibration.set_scenario(scenario);
    calibration.set_gauge_diameter_mm(40.0);
    ProgramDialog* ring = calibration.open_program_dialog();
    ASSERT_NE(ring, nullptr);
    EXPECT_EQ(ring->kind(), ProgramKind::ring);
    EXPECT_DOUBLE_EQ(ring->ring_options().gauge_diameter_mm, 40.0);
    ring->update_now();
    RingPlanOptions options;
    options.gauge_diameter_mm = 40.0;
    EXPECT_EQ(probing_plan_json(*ring->plan()),
              probing_plan_json(make_ring_plan(scenario, options)));
    ring->close();
}

TEST(ProgramDialog, ARefusalIsShownInPlaceAndDisablesSave) {
    ProgramDialog dialog(ProgramKind::delay, Scenario{});
    dialog.show();
    auto* save = dialog.findChild<QPushButton*>(QStringLiteral("program-save"));
    ASSERT_NE(save, nullptr);
    dialog.update_now();
    EXPECT_TRUE(save->isEnabled());
    EXPECT_TRUE(shown_text(dialog, "program-problem").isEmpty());

    // One feed: the core wants two; the option is named as the dialog labels it.
    dialog.set_feeds_text(QStringLiteral("100"));
    dialog.update_now();
    EXPECT_FALSE(save->isEnabled());
    EXPECT_FALSE(dialog.plan().has_value());
    EXPECT_TRUE(dialog.program_text().isEmpty());
    EXPECT_EQ(shown_text(dialog, "program-problem"), dialog.problem());
    EXPECT_EQ(dialog.problem().toStdString(),
              "Feeds: got 100; allowed: from 2 to 20 different feeds");

    // Not numbers.
    dialog.set_feeds_text(QStringLiteral("100; fast"));
    dialog.update_now();
    EXPECT_FALSE(save->isEnabled());
    EXPECT_TRUE(dialog.problem().contains(QStringLiteral("fast")))
        << dialog.problem().toStdString();

    // The model's overtravel at a feed over the probe's limit.
    dialog.set_feeds_text(QStringLiteral("100; 90000"));
    dialog.update_now();
    EXPECT_FALSE(save->isEnabled());
    EXPECT_TRUE(dialog.problem().contains(QStringLiteral("overtravel")))
        << dialog.problem().toStdString();

    // Save refuses too, and writes nothing.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("delay.ngc"));
    EXPECT_FALSE(dialog.save(path));
    EXPECT_EQ(dialog.last_error(), dialog.problem());
    EXPECT_FALSE(QFileInfo::exists(path));
    EXPECT_FALSE(QFileInfo::exists(plan_path_for(path)));

    // Back to good feeds: Save again.
    dialog.set_feeds_text(QStringLiteral("30, 300; 2000"));
    dialog.update_now();
    EXPECT_TRUE(save->isEnabled()) << dialog.problem().toStdString();
    EXPECT_EQ(dialog.delay_options().feeds_mm_min, (std::vector<double>{30.0, 300.0, 2000.0}));
    EXPECT_TRUE(shown_text(dialog, "program-problem").isEmpty());

    // The ring: a ball as large as the gauge.
    ProgramDialog ring(ProgramKind::ring, Scenario{});
    ring.show();
    ring.set_ring_options({6.0, 6.0, 1.0});
    ring.update_now();
    EXPECT_FALSE(ring.findChild<QPushButton*>(QStringLiteral("program-save"))->isEnabled());
    EXPECT_TRUE(ring.problem().startsWith(QStringLiteral("the gauge (6.000")))
        << ring.problem().toStdString();
}

TEST(ProgramDialog, SaveWritesTheProgramAndItsPlanBesideIt) {
    QTemporaryDir dir;
    ProgramDialog dialog(ProgramKind::delay, Scenario{});
    dialog.set_delay_options(small_delay_options());
    dialog.set_dialect(DialectId::grbl);
    QSignalSpy saved(&dialog, &ProgramDialog::saved);
    const QString path = dir.filePath(QStringLiteral("delay.nc"));
    ASSERT_TRUE(dialog.save(path)) << dialog.last_error().toStdString();
    EXPECT_EQ(read_back(path), dialog.program_text().toStdString());
    const QString plan_path = dir.filePath(QStringLiteral("delay.plan.json"));
    EXPECT_EQ(read_back(plan_path), probing_plan_json(*dialog.plan()));
    EXPECT_EQ(probing_plan_json(parse_probing_plan(read_back(plan_path))),
              probing_plan_json(make_delay_plan(Scenario{}, small_delay_options())));
    ASSERT_EQ(saved.count(), 1);
    EXPECT_EQ(saved[0][1].toString(), plan_path);
    EXPECT_TRUE(shown_text(dialog, "program-status").isEmpty());  // the dialog is not shown
    dialog.show();
    ASSERT_TRUE(dialog.save(path));
    EXPECT_EQ(shown_text(dialog, "program-status"),
              QStringLiteral("Saved delay.nc and its plan delay.plan.json"));

    // A folder that is not there: false, the reason, and no program.
    const QString nowhere = dir.filePath(QStringLiteral("missing/delay.nc"));
    EXPECT_FALSE(dialog.save(nowhere));
    EXPECT_TRUE(dialog.last_error().contains(QStringLiteral("delay.plan.json")))
        << dialog.last_error().toStdString();
    EXPECT_FALSE(QFileInfo::exists(nowhere));
}

class MachineLogImport : public ::testing::Test {
  protected:
    // The plan saved by the dialog, as a user would.
    QString save_plan(ProgramKind kind, DialectId id) {
        ProgramDialog dialog(kind, Scenario{});
        if (kind == ProgramKind::delay) dialog.set_delay_options(small_delay_options());
        dialog.set_dialect(id);
        const QString path = dir_.filePath(QString::fromUtf8(to_string(kind)) + QLatin1Char('.') +
                                           QString::fromUtf8(dialect(id).extension));
        EXPECT_TRUE(dialog.save(path)) << dialog.last_error().toStdString();
        return plan_path_for(path);
    }
    QString log(const char* name, const std::string& text) {
        QString path = dir_.filePath(QLatin1String(name));
        write_text(path, text);
        return path;
    }

    QTemporaryDir dir_;
};

TEST_F(MachineLogImport, AGrblConsoleFillsTheTouchesAndFits) {
    const QString plan = save_plan(ProgramKind::delay, DialectId::grbl);
    const QString console = log("console.txt", grbl_console());
    LatencyTab tab;
    tab.show();
    ASSERT_TRUE(tab.import_machine_log({DialectId::grbl, plan, console}))
        << tab.last_error().toStdString();
    const ProbingPlan parsed = parse_probing_plan(read_back(plan));
    EXPECT_EQ(tab.touches_text().toStdString(),
              import_machine_log(parsed, DialectId::grbl, grbl_console()));
    ASSERT_TRUE(tab.delay_fit().has_value());
    ASSERT_EQ(tab.delay_fit()->groups.size(), 1u);
    EXPECT_EQ(tab.delay_fit()->groups[0].name(), "Z-");
    EXPECT_GT(tab.delay_fit()->groups[0].delay_s, 0.0);
}

TEST_F(MachineLogImport, ALinuxCncLogFillsTheTouchesAndFits) {
    const QString plan = save_plan(ProgramKind::delay, DialectId::linuxcnc);
    const ProbingPlan parsed = parse_probing_plan(read_back(plan));
    const std::string text = linuxcnc_log(parsed, {-20.0171, -20.0172, -20.1501, -20.1502});
    LatencyTab tab;
    ASSERT_TRUE(
        tab.import_machine_log({DialectId::linuxcnc, plan, log("probecycle_log.txt", text)}))
        << tab.last_error().toStdString();
    EXPECT_EQ(tab.touches_text().toStdString(),
              import_machine_log(parsed, DialectId::linuxcnc, text));
    ASSERT_TRUE(tab.delay_fit().has_value());
    EXPECT_EQ(tab.delay_fit()->groups[0].name(), "Z-");
}

TEST_F(MachineLogImport, ARingLogFillsThePointsAndFits) {
    const QString plan = save_plan(ProgramKind::ring, DialectId::linuxcnc);
    const ProbingPlan parsed = parse_probing_plan(read_back(plan));
    CalibrationTab tab;
    tab.set_gauge_diameter_mm(50.0);
    ASSERT_TRUE(tab.import_machine_log(
        {DialectId::linuxcnc, plan, log("probecycle_log.txt", linuxcnc_ring_log(parsed))}))
        << tab.last_error().toStdString();
    EXPECT_EQ(tab.points_text().toStdString(),
              import_machine_log(parsed, DialectId::linuxcnc, linuxcnc_ring_log(parsed)));
    ASSERT_TRUE(tab.result().has_value());
    EXPECT_NEAR(*tab.result()->runout_x_mm, -0.002, 1e-9);
    EXPECT_NEAR(tab.result()->effective_radius_mm, 25.0 - program_test::kRingLogRadius_mm, 1e-9);
}

TEST_F(MachineLogImport, ABrokenLogLeavesTheTabAsItWasAndNamesTheLine) {
    const QString plan = save_plan(ProgramKind::delay, DialectId::grbl);
    LatencyTab tab;
    tab.show();
    ASSERT_TRUE(tab.import_machine_log({DialectId::grbl, plan, log("good.txt", grbl_console())}));
    const QString text = tab.touches_text();
    const double delay_s = tab.delay_fit()->groups[0].delay_s;

    // The log ends early: its last position (line 19) is named.
    const std::string good = grbl_console();
    const QString missing = log("missing.txt", good.substr(0, good.rfind("[PRB:")));
    EXPECT_FALSE(tab.import_machine_log({DialectId::grbl, plan, missing}));
    EXPECT_EQ(tab.touches_text(), text);
    ASSERT_TRUE(tab.delay_fit().has_value());
    EXPECT_EQ(tab.delay_fit()->groups[0].delay_s, delay_s);
    EXPECT_TRUE(tab.last_error().startsWith(QStringLiteral("missing.txt: line 19")))
        << tab.last_error().toStdString();
    const auto* error = tab.findChild<QLabel*>(QStringLiteral("delay-error"));
    EXPECT_TRUE(error->isVisible());
    EXPECT_TRUE(error->text().contains(QStringLiteral("line 19")));

    // A ring plan on the Latency tab, a file that is no plan, a plan not there.
    const QString ring_plan = save_plan(ProgramKind::ring, DialectId::grbl);
    EXPECT_FALSE(tab.import_machine_log({DialectId::grbl, ring_plan, missing}));
    EXPECT_EQ(tab.last_error().toStdString(),
              "ring.plan.json is the plan of a ring-gauge calibration program; this tab reads "
              "the log of a delay-stability test program.");
    EXPECT_FALSE(tab.import_machine_log({DialectId::grbl, missing, missing}));
    EXPECT_TRUE(tab.last_error().startsWith(QStringLiteral("missing.txt is not a probing plan")))
        << tab.last_error().toStdString();
    EXPECT_FALSE(tab.import_machine_log(
        {DialectId::grbl, dir_.filePath(QStringLiteral("none.plan.json")), missing}));
    EXPECT_TRUE(tab.last_error().contains(QStringLiteral("none.plan.json")))
        << tab.last_error().toStdString();
    EXPECT_EQ(tab.touches_text(), text);
    EXPECT_EQ(tab.delay_fit()->groups[0].delay_s, delay_s);
}

// With PROBECYCLE_LAB_SCREENSHOTS=DIR, the dialog as shown, to look at.
void save_screenshot(QWidget& dialog, const QString& name) {
    const char* out = std::getenv("PROBECYCLE_LAB_SCREENSHOTS");
    if (out == nullptr) return;
    QCoreApplication::processEvents();
    dialog.grab().save(QString::fromLocal8Bit(out) + QLatin1Char('/') + name + QLatin1Char('_') +
                       current_language() + QStringLiteral(".png"));
}

class ProgramLanguage : public ::testing::TestWithParam<const char*> {
  protected:
    void SetUp() override {
        ASSERT_EQ(apply_language(QLatin1String(GetParam())), QLatin1String(GetParam()));
    }
    void TearDown() override { apply_language(QStringLiteral("en")); }
};

// Latin words left in a text that should be translated, less G-code, file
// and key names.
QString english_left(const QString& text) {
    static const QRegularExpression kWord(QStringLiteral("\\b[a-z]{4,}\\b"));
    static const QStringList kKept = {QStringLiteral("json"), QStringLiteral("plan"),
                                      QStringLiteral("probecycle"), QStringLiteral("txt"),
                                      QStringLiteral("version")};
    QStringList left;
    auto it = kWord.globalMatch(text);
    while (it.hasNext()) {
        const QString word = it.next().captured();
        if (!kKept.contains(word)) left << word;
    }
    return left.join(QLatin1Char(' '));
}

TEST_P(ProgramLanguage, TheDialogsAndTheirMessagesAreTranslated) {
    const bool english = QLatin1String(GetParam()) == QLatin1String("en");
    ProgramDialog delay(ProgramKind::delay, Scenario{});
    delay.show();
    save_screenshot(delay, QStringLiteral("program_delay"));
    delay.set_feeds_text(QStringLiteral("100"));
    delay.update_now();
    const QString refusal = shown_text(delay, "program-problem");
    EXPECT_FALSE(refusal.isEmpty());
    if (!english) {
        EXPECT_EQ(english_left(refusal), QString()) << refusal.toStdString();
        EXPECT_NE(delay.findChild<QPushButton*>(QStringLiteral("program-save"))->text(),
                  QStringLiteral("Save program…"));
    }
    save_screenshot(delay, QStringLiteral("program_delay_refused"));

    ProgramDialog ring(ProgramKind::ring, Scenario{});
    ring.show();
    ring.set_ring_options({6.0, 6.0, 1.0});
    ring.update_now();
    if (!english) {
        EXPECT_EQ(english_left(ring.problem()), QString()) << ring.problem().toStdString();
    }
    save_screenshot(ring, QStringLiteral("program_ring_refused"));
    ring.set_ring_options({});
    ring.update_now();
    save_screenshot(ring, QStringLiteral("program_ring"));

    ProgramDialog cycle(ProgramKind::cycle, Scenario{});
    cycle.show();
    cycle.update_now();
    EXPECT_TRUE(cycle.can_save()) << cycle.problem().toStdString();
    if (!english) {
        EXPECT_NE(cycle.windowTitle(), QStringLiteral("Tuned cycle program"));
        EXPECT_EQ(english_left(cycle.windowTitle()), QString());
    }
    save_screenshot(cycle, QStringLiteral("program_cycle"));
    Scenario pocket;
    pocket.cycle.feature = Feature::pocket;
    ProgramDialog refused(ProgramKind::cycle, pocket);
    refused.show();
    refused.set_cycle_options(CyclePlanOptions{{'Z', -1}});
    refused.update_now();
    EXPECT_FALSE(refused.can_save());
    if (!english) {
        EXPECT_EQ(english_left(refused.problem()), QString()) << refused.problem().toStdString();
    }
    save_screenshot(refused, QStringLiteral("program_cycle_pocket_refused"));

    MachineLogDialog log(ProgramKind::ring);
    log.show();
    save_screenshot(log, QStringLiteral("machine_log"));
}

TEST(ProgramLanguageSwitch, TextsRetranslateLive) {
    ProgramDialog dialog(ProgramKind::delay, Scenario{});
    dialog.show();
    dialog.set_feeds_text(QStringLiteral("100"));
    dialog.update_now();
    const QString english = shown_text(dialog, "program-problem");
    LatencyTab tab;
    tab.show();
    QTemporaryDir dir;
    const QString not_a_plan = dir.filePath(QStringLiteral("x.plan.json"));
    write_text(not_a_plan, "{\"format\": \"probecycle-probing-plan\", \"version\": 2}\n");
    EXPECT_FALSE(tab.import_machine_log({DialectId::grbl, not_a_plan, QString()}));
    const QString english_error = tab.last_error();

    ASSERT_EQ(apply_language(QStringLiteral("ru")), QStringLiteral("ru"));
    QCoreApplication::processEvents();
    const QString russian = shown_text(dialog, "program-problem");
    EXPECT_NE(russian, english);
    EXPECT_EQ(english_left(russian), QString()) << russian.toStdString();
    EXPECT_EQ(dialog.windowTitle(), QCoreApplication::translate("probecycle::ui::ProgramDialog",
                                                                "Delay-stability test program"));
    EXPECT_NE(dialog.windowTitle(), QStringLiteral("Delay-stability test program"));
    EXPECT_NE(tab.last_error(), english_error);
    EXPECT_EQ(english_left(tab.last_error()).toStdString(), "") << tab.last_error().toStdString();
    apply_language(QStringLiteral("en"));
    QCoreApplication::processEvents();
    EXPECT_EQ(shown_text(dialog, "program-problem"), english);
}

struct LanguageName {
    std::string operator()(const ::testing::TestParamInfo<const char*>& info) const {
        return info.param;
    }
};

INSTANTIATE_TEST_SUITE_P(Languages, ProgramLanguage, ::testing::Values("en", "zh_CN", "ru"),
                         LanguageName{});

}  // namespace
}  // namespace probecycle::ui
