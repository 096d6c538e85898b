#include "ui/lab/latency_tab.h"

#include <QSplitter>
#include <QVBoxLayout>

namespace probecycle::ui {

LatencyTab::LatencyTab(QWidget* parent) : QWidget(parent) {
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
    });
    connect(compensation_, &CompensationPanel::lag_from_fit_requested, this,
            &LatencyTab::take_lag_from_fit);
}

LatencyTab::~LatencyTab() = default;

void LatencyTab::set_scenario(const probecycle::Scenario& scenario) {
    delay_->set_scenario(scenario);
    compensation_->set_scenario(scenario);
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
