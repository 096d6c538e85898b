#pragma once

// The uncertainty budget (core/cycle/uncertainty.h) as a table the
// window and the PDF report show: one row per term, then the combined and
// the expanded uncertainty. The readout's tooltip and the report read the
// same rows.

#include <QList>
#include <QString>
#include <QStringList>

#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"

namespace probecycle::ui {

// A header row, a row per term (what it is, its value as the key states it,
// how it is stated, its standard uncertainty, its share of the combined
// variance), then the combined standard and the expanded uncertainty.
QList<QStringList> uncertainty_budget_rows(const Scenario& scenario, const CycleResult& cycle);

// The rows as an HTML table, for a tooltip.
QString rows_to_html_table(const QList<QStringList>& rows);

}  // namespace probecycle::ui
