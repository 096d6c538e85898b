#include "ui/window/document.h"

#include <QFileInfo>
#include <QUndoStack>
#include <utility>

#include "ui/common/page.h"
#include "ui/window/scenario_command.h"

namespace probecycle::ui {

Document::Document(QObject* parent) : QObject(parent), undo_(new QUndoStack(this)) {
    session_check_.setSingleShot(true);
    session_check_.setInterval(0);
    connect(&session_check_, &QTimer::timeout, this, [this] {
        if (has_unsaved_changes() != last_modified_) emit modified_changed();
    });
    connect(undo_, &QUndoStack::cleanChanged, this, &Document::modified_changed);
    connect(this, &Document::modified_changed, this,
            [this] { last_modified_ = has_unsaved_changes(); });
    empty_session_ = session_snapshot();
    saved_session_ = empty_session_;
}

void Document::apply(const Scenario& scenario) {
    scenario_ = scenario;
    emit scenario_changed();
}

void Document::edit(const Scenario& scenario, std::function<QString()> describe, int merge_id) {
    undo_->push(new ScenarioCommand([this](const Scenario& s) { apply(s); }, scenario_, scenario,
                                    std::move(describe), merge_id));
}

QString Document::display_name() const {
    return file_.isEmpty() ? tr("Untitled") : QFileInfo(file_).fileName();
}

void Document::reset(const Scenario& scenario, const QString& file, bool is_project) {
    undo_->clear();
    file_ = file;
    is_project_ = is_project;
    apply(scenario);
    undo_->setClean();
    emit modified_changed();
}

void Document::mark_saved(const QString& file, bool is_project) {
    file_ = file;
    is_project_ = is_project;
    undo_->setClean();
    emit modified_changed();
}

void Document::mark_session_saved() {
    saved_session_ = session_snapshot();
    emit modified_changed();
}

void Document::mark_session_unsaved() {
    saved_session_ = empty_session_;
    emit modified_changed();
}

void Document::add_page(Page* page) {
    pages_.append(page);
    connect(page, &Page::changed, &session_check_, qOverload<>(&QTimer::start));
    empty_session_ = session_snapshot();
    saved_session_ = empty_session_;
}

void Document::set_baseline(const std::optional<Scenario>& baseline) {
    baseline_ = baseline;
    session_check_.start();
}

void Document::set_report_details(const ReportDetails& details) {
    report_details_ = details;
    if (has_unsaved_changes() != last_modified_) emit modified_changed();
}

Project Document::project(const QString& base_folder) const {
    Project project;
    project.scenario = scenario_;
    project.baseline = baseline_;
    project.report = report_details_;
    for (const Page* page : pages_) page->save_session(project, base_folder);
    return project;
}

void Document::restore_pages(const Project& project, const QString& base_folder) {
    // A part that no longer loads (the program's checks changed) shows its
    // message in its tab; every other part is taken as stored.
    for (Page* page : pages_) page->restore_session(project, base_folder);
    set_report_details(project.report);
}

std::string Document::session_snapshot() const {
    Project state = project(QString());
    state.scenario = Scenario{};
    // The lab's data can be megabytes, and the check runs after every edit
    // of a page: each text stands in as its length and hash, which tell
    // texts apart as surely, without writing them into JSON.
    for (std::string* text : {&state.ring.points_csv, &state.ring.fitted_csv,
                              &state.delay.touches_csv, &state.delay.fitted_csv}) {
        *text =
            std::to_string(text->size()) + ':' + std::to_string(std::hash<std::string>{}(*text));
    }
    return project_json(state);
}

bool Document::session_unsaved() const {
    return session_snapshot() != saved_session_;
}

bool Document::session_has_data() const {
    return session_snapshot() != empty_session_;
}

bool Document::has_unsaved_changes() const {
    return !undo_->isClean() || (is_project_ && session_unsaved());
}

}  // namespace probecycle::ui
