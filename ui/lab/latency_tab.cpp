#include "ui/lab/latency_tab.h"

#include <QSplitter>
#include <QVBoxLayout>

namespace probecycle::ui {

LatencyTab::LatencyTab(QWidget* parent) : Page(parent) {
    setObjectName(QStringLiteral("lab-latency"));
    delay_ = new DelayFitPanel(this);
    compensation_ = new CompensationPanel(this);
    splitter_ = new QSplitter(Qt::Vertical, this);
    splitter_->setChildrenCollapsible(false);
    splitter_->addWidget(delay_);
    splitter_->addWidget(compensation_);
    // Its inputs, table and notes need this much; the touches and the tree above can scroll.
    compensation_->setMinimumHeight(270);
    delay_->setMinimumHeight(300);
    splitter_->setStretchFactor(0, 6);
    splitter_->setStretchFactor(1, 5);
    auto* root = new QVBoxLayout(this);
    root->addWidget(splitter_);

    connect(delay_, &DelayFitPanel::delay_applied, this, &LatencyTab::delay_applied);
    connect(delay_, &DelayFitPanel::fit_changed, this, [this] {
        compensation_->set_lag_from_fit_available(delay_->lag_from_fit().has_value());
        emit changed();  // the project keeps the CSV behind the fit
    });
    connect(compensation_, &CompensationPanel::lag_from_fit_requested, this,
            &LatencyTab::take_lag_from_fit);
    watch_inputs();
}

LatencyTab::~LatencyTab() = default;

void LatencyTab::set_scenario(const probecycle::Scenario& scenario) {
    delay_->set_scenario(scenario);
    compensation_->set_scenario(scenario);
}

void LatencyTab::save_session(Project& project, const QString& /*base_folder*/) const {
    project.delay = delay_->session();
    project.compensation = compensation_->inputs();
}

bool LatencyTab::restore_session(const Project& project, const QString& /*base_folder*/) {
    const bool restored = delay_->restore(project.delay);
    compensation_->set_inputs(project.compensation);
    return restored;
}

void LatencyTab::take_lag_from_fit() {
    const auto lag = delay_->lag_from_fit();
    if (!lag) return;
    CompensationInputs inputs = compensation_->inputs();
    inputs.interpolation_period_s = lag->interpolation_period_s;
    inputs.lag_cycles = lag->lag_cycles;
    compensation_->set_inputs(inputs);
}

}  // namespace probecycle::ui
