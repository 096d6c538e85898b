// The window's document (ui/window/document.h): the scenario and its undo,
// the file, and unsaved work told from its pages' changed() by comparing
// their sessions with the file's, driven through a page of the test's own.

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QSignalSpy>
#include <QUndoStack>
#include <optional>
#include <string>

#include "core/cycle/scenario.h"
#include "core/project/project_file.h"
#include "ui/common/page.h"
#include "ui/window/document.h"

namespace probecycle::ui {
namespace {

// A page whose whole session is one number and one text.
class FakePage : public Page {
  public:
    std::optional<std::string> report_csv(ReportRows /*rows*/) override { return "a,b\n"; }
    std::size_t report_points() const override { return 0; }
    QString last_error() const override { return {}; }
    void export_dialog() override {}
    void save_session(Project& project, const QString& /*base_folder*/) const override {
        project.delay.interpolation_period_s = period_s;
        project.delay.touches_csv = touches;
    }
    bool restore_session(const Project& project, const QString& /*base_folder*/) override {
        period_s = project.delay.interpolation_period_s;
        touches = project.delay.touches_csv;
        return true;
    }
    void edit(double period, std::string text = {}) {
        period_s = period;
        touches = std::move(text);
        emit changed();
    }

    double period_s{0.0};
    std::string touches;
};

TEST(Document, EditsAreUndoableAndMarkTheDocumentModified) {
    Document document;
    QSignalSpy shown(&document, &Document::scenario_changed);
    Scenario s = document.scenario();
    s.cycle.probe_feed_mm_min = 1234.0;
    document.edit(s, [] { return QStringLiteral("edit"); });
    EXPECT_EQ(document.scenario().cycle.probe_feed_mm_min, 1234.0);
    EXPECT_TRUE(document.has_unsaved_changes());
    EXPECT_EQ(shown.count(), 1);
    document.undo_stack()->undo();
    EXPECT_EQ(document.scenario().cycle.probe_feed_mm_min, Scenario{}.cycle.probe_feed_mm_min);
    EXPECT_FALSE(document.has_unsaved_changes());
    EXPECT_EQ(shown.count(), 2);
}

TEST(Document, EditsOfOneKeyInARowAreOneStep) {
    Document document;
    Scenario s = document.scenario();
    for (const double feed : {100.0, 200.0, 300.0}) {
        s.cycle.probe_feed_mm_min = feed;
        document.edit(
            s, [] { return QStringLiteral("feed"); }, 7);
    }
    EXPECT_EQ(document.undo_stack()->count(), 1);
    document.undo_stack()->undo();
    EXPECT_EQ(document.scenario().cycle.probe_feed_mm_min, Scenario{}.cycle.probe_feed_mm_min);
}

TEST(Document, NamesTheFileOrUntitled) {
    Document document;
    EXPECT_EQ(document.display_name(), QStringLiteral("Untitled"));
    document.reset(Scenario{}, QStringLiteral("/tmp/cell 7.probecycle"), true);
    EXPECT_EQ(document.display_name(), QStringLiteral("cell 7.probecycle"));
    EXPECT_TRUE(document.is_project());
    EXPECT_FALSE(document.has_unsaved_changes());
}

TEST(Document, APageEditInAProjectIsUnsavedUntilItIsUndoneByHand) {
    Document document;
    FakePage page;
    document.add_page(&page);
    document.reset(Scenario{}, QStringLiteral("/tmp/a.probecycle"), true);
    document.mark_session_saved();
    QSignalSpy modified(&document, &Document::modified_changed);

    page.edit(0.002);
    EXPECT_TRUE(document.has_unsaved_changes());
    // The title hears of it once the event loop has run, once per pass.
    page.edit(0.003);
    QCoreApplication::processEvents();
    EXPECT_EQ(modified.count(), 1);

    // Back to what the file holds: nothing unsaved, and the title told.
    page.edit(0.0);
    QCoreApplication::processEvents();
    EXPECT_FALSE(document.has_unsaved_changes());
    EXPECT_EQ(modified.count(), 2);
}

TEST(Document, OutsideAProjectPageDataIsTheSessionsNotTheFiles) {
    Document document;
    FakePage page;
    document.add_page(&page);
    document.reset(Scenario{}, QStringLiteral("/tmp/a.json"), false);
    EXPECT_FALSE(document.session_has_data());
    page.edit(0.0, "X+,1,2\n");
    // A scenario file does not hold it, so leaving does not lose the file's work...
    EXPECT_FALSE(document.has_unsaved_changes());
    // ...but opening a project would replace it, and it is in no file.
    EXPECT_TRUE(document.session_unsaved());
    EXPECT_TRUE(document.session_has_data());
}

TEST(Document, AProjectHoldsTheScenarioTheBaselineAndEveryPage) {
    Document document;
    FakePage page;
    document.add_page(&page);
    Scenario s;
    s.cycle.probe_feed_mm_min = 900.0;
    document.reset(s, {}, false);
    Scenario baseline;
    baseline.cycle.probe_feed_mm_min = 600.0;
    document.set_baseline(baseline);
    page.edit(0.004, "touches");

    const Project project = document.project(QString());
    EXPECT_EQ(project.scenario.cycle.probe_feed_mm_min, 900.0);
    ASSERT_TRUE(project.baseline.has_value());
    EXPECT_EQ(project.baseline->cycle.probe_feed_mm_min, 600.0);
    EXPECT_EQ(project.delay.interpolation_period_s, 0.004);

    FakePage other;
    Document reopened;
    reopened.add_page(&other);
    reopened.restore_pages(project, QString());
    EXPECT_EQ(other.period_s, 0.004);
    EXPECT_EQ(other.touches, "touches");
}

TEST(Document, ABaselinePinnedInAProjectIsUnsaved) {
    Document document;
    document.reset(Scenario{}, QStringLiteral("/tmp/a.probecycle"), true);
    document.mark_session_saved();
    document.set_baseline(Scenario{});
    EXPECT_TRUE(document.has_unsaved_changes());
    document.set_baseline(std::nullopt);
    EXPECT_FALSE(document.has_unsaved_changes());
}

// The report's title block is the session's, as the pages' data: in the
// project, restored from it, and unsaved work of a project when changed.
TEST(Document, ReportDetailsAreProjectDataAndMarkAProjectModified) {
    Document document;
    document.reset(Scenario{}, QStringLiteral("/tmp/a.probecycle"), true);
    document.mark_session_saved();
    ASSERT_FALSE(document.has_unsaved_changes());
    QSignalSpy modified(&document, &Document::modified_changed);
    ReportDetails details;
    details.customer = "Acme";
    document.set_report_details(details);
    EXPECT_TRUE(document.has_unsaved_changes());
    EXPECT_GE(modified.count(), 1);
    EXPECT_EQ(document.project(QString()).report.customer, "Acme");
    document.mark_session_saved();
    EXPECT_FALSE(document.has_unsaved_changes());

    Project other;
    other.report.author = "J. Engineer";
    document.restore_pages(other, QString());
    EXPECT_EQ(document.report_details(), other.report);
}

}  // namespace
}  // namespace probecycle::ui
