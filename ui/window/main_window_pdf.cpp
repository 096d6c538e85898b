// The PDF report to hand over (docs/window.md): MainWindow::export_pdf_report and
// what each tab puts in it.

#include <QCoreApplication>
#include <QDir>
#include <QLocale>
#include <QRegularExpression>
#include <QTabWidget>
#include <optional>
#include <string>

#include "core/common/report_summary.h"
#include "ui/common/file_write.h"
#include "ui/common/page.h"
#include "ui/common/parameter_info.h"
#include "ui/common/pdf_report.h"
#include "ui/common/plot_view.h"
#include "ui/common/report_tables.h"
#include "ui/common/text_format.h"
#include "ui/common/warning_list.h"
#include "ui/comparison/comparison_tab.h"
#include "ui/cycle/cycle_charts.h"
#include "ui/cycle/optimise_panel.h"
#include "ui/cycle/uncertainty_table.h"
#include "ui/lab/calibration_tab.h"
#include "ui/lab/latency_tab.h"
#include "ui/window/document.h"
#include "ui/window/main_window.h"
#include "ui/window/report_details_dialog.h"

namespace probecycle::ui {

namespace {

// A scenario key's value as the editors show it (unit, digits, the word
// for 0 where 0 means something).
QString shown_value(const Scenario& scenario, const KeyInfo& key) {
    if (key.kind == KeyKind::number) {
        const ParameterView view = parameter_view(key);
        const double value = get_number(scenario, key.key).value_or(0.0);
        if (value == 0.0 && !view.zero_text.isEmpty()) return view.zero_text;
        return with_unit(format_number(value * view.factor, view.decimals), view.unit);
    }
    const std::string word = value_text(scenario, key);
    const std::string_view name = key.key;
    if (key.kind == KeyKind::flag) {
        return word == "true" ? MainWindow::tr("yes") : MainWindow::tr("no");
    }
    if (name == "machine.accel_model") return accel_model_label(scenario.machine.accel_model);
    if (name == "machine.filter") return filter_label(scenario.machine.filter);
    if (name == "cycle.strategy") return strategy_label(scenario.cycle.strategy);
    if (name == "cycle.backoff_from") return backoff_from_label(scenario.cycle.backoff_from);
    if (name == "cycle.tolerance_action") {
        return tolerance_action_label(scenario.cycle.tolerance_action);
    }
    if (name == "cycle.feature") return feature_label(scenario.cycle.feature);
    return QString::fromStdString(word);
}

// The size a chart is drawn at for the page, in logical pixels, whatever the
// window's size: at the page's text width (180 mm) its 12-pixel texts print
// at about 8 points, and three charts fit on a page.
constexpr QSize kChartSize{760, 330};
// Device pixels per logical pixel: about 210 dpi on paper.
constexpr double kChartScale = 2.0;

// Each chart alone, drawn for the page: not the tab with its inputs and
// buttons, nor the chart at the window's size.
void add_charts(PdfReport& report, const QList<PlotView*>& plots) {
    for (PlotView* plot : plots) {
        if (plot != nullptr) report.add_image(plot->picture(kChartSize, kChartScale));
    }
}

}  // namespace

QByteArray MainWindow::pdf_report_bytes() {
    recompute_now();
    const QString name = document_->display_name();
    QWidget* tab = tabs_->currentWidget();
    // The tab's name without the count of problems the tab bar adds.
    const QString tab_name = tabs_->tabText(tabs_->currentIndex())
                                 .remove(QRegularExpression(QStringLiteral("\\s*[(（]\\d+[)）]$")))
                                 .remove(QLatin1Char('&'));
    PdfReport report(tr("ProbeCycle report: %1").arg(name));
    report.set_footer(
        tr("Figures computed by ProbeCycle %1 from a model of the machine, probe and cycle with "
           "the inputs listed in this report. They are estimates for setting up the cycle, not "
           "a calibration certificate.")
            .arg(QCoreApplication::applicationVersion()));
    // The title block: whom the report is for and who made it, then what it
    // shows, when and by which version.
    report.add_fields(report_detail_rows(document_->report_details()));
    report.add_paragraph(tr("%1 · %2 · ProbeCycle %3")
                             .arg(tab_name, QString::fromStdString(report_date()),
                                  QCoreApplication::applicationVersion()));

    if (auto* page = qobject_cast<Page*>(tab)) {
        // The tab's charts, then its report's figures: large data summarised
        // (report_summary.h), the whole is in the CSV export.
        const ReportRows rows = ReportRows::summary;
        const std::optional<std::string> csv = page->report_csv(rows);
        if (!csv) {
            report.add_paragraph(tr("No results yet: %1").arg(page->last_error()));
            return report.render();
        }
        if (tab == calibration_tab_) {
            add_charts(report, {calibration_tab_->plot()});
        } else if (tab == latency_tab_) {
            add_charts(report, {latency_tab_->delay_plot(), latency_tab_->comparison_plot()});
        } else if (tab == comparison_tab_) {
            add_charts(report, {comparison_tab_->map(), comparison_tab_->histogram()});
        }
        const std::size_t points = page->report_points();
        if (summarised(rows, points)) {
            report.add_paragraph(
                tr("%1 points: the tables give their statistics and the %2 that deviate "
                   "most. The CSV report (Export report…) has every point.")
                    .arg(QLocale().toString(static_cast<qulonglong>(points)))
                    .arg(kReportLargestRows));
        }
        std::vector<WarningList::Item> warnings;
        for (const WarningList* list : tab->findChildren<WarningList*>()) {
            warnings.insert(warnings.end(), list->items().begin(), list->items().end());
        }
        add_report_csv(report, QString::fromStdString(*csv), warnings);
        return report.render();
    }

    // The cycle: results, charts, what to change, the scenario.
    report.add_heading(tr("Results"));
    QList<QStringList> results = {{tr("Quantity"), tr("Value"), tr("Detail")}};
    for (std::size_t i = 0; i < kReadoutCount; ++i) {
        const auto readout = static_cast<Readout>(i);
        results.append({readouts_->title_text(readout), readouts_->value_text(readout),
                        readouts_->detail_text(readout)});
    }
    report.add_table(results);
    // What the uncertainty holds, term by term.
    report.add_heading(tr("Uncertainty budget"));
    report.add_table(uncertainty_budget_rows(scenario(), computed().cycle()));
    report.add_heading(tr("Charts"));
    add_charts(report, charts_->plots());

    report.add_heading(tr("Warnings and what to change"));
    const QList<QStringList> warnings = warnings_->rows_text();
    if (warnings.isEmpty()) report.add_paragraph(tr("No warnings: the cycle runs as set."));
    for (const QStringList& row : warnings) {
        // "Error: Backoff too small", the message, and the window's fix.
        QString text = row[2];
        if (!row[3].isEmpty()) text += QLatin1Char('\n') + tr("Suggested change: %1").arg(row[3]);
        //: %1 the severity (Error, Warning, Note), %2 the warning's title
        report.add_item(tr("%1: %2").arg(row[0], row[1]), text);
    }

    // The fastest settings that meet the requirements, and their worth.
    report.add_heading(tr("The optimiser's recommendation"));
    const OptimisePanel* optimiser = optimise_panel();
    if (optimiser->result()) {
        report.add_paragraph(optimiser->saved_text());
        report.add_table(optimiser->table_rows());
        for (const QString& text : {optimiser->binding_text(), optimiser->savings_text()}) {
            if (!text.isEmpty()) report.add_paragraph(text);
        }
        const QStringList advice = optimiser->advice_texts();
        if (!advice.isEmpty()) {
            report.add_paragraph(OptimisePanel::tr("What else would save time:") +
                                 QStringLiteral("\n• ") + advice.join(QStringLiteral("\n• ")));
        }
        // From the Optimise tab: its Pareto front.
        if (tab == optimise_) add_charts(report, {optimiser->pareto()});
    } else {
        report.add_paragraph(optimiser->problem().isEmpty()
                                 ? tr("The scenario is not valid; see the warnings.")
                                 : optimiser->problem());
    }

    // The inputs the model uses: a key the scenario's model, filter,
    // strategy or feature leaves unused is hidden in the window and left out.
    report.add_heading(tr("The scenario"));
    for (const std::string& section : scenario_sections()) {
        const QString section_name = QString::fromStdString(section);
        report.add_subheading(section_label(section_name));
        QList<QStringList> rows = {{tr("Parameter"), tr("Value"), tr("Key")}};
        for (const KeyInfo& key : scenario_keys()) {
            if (section_of(key.key) != section_name || !key_applies(scenario(), key.key)) continue;
            rows.append({QCoreApplication::translate("Parameter", key.label),
                         shown_value(scenario(), key), QString::fromUtf8(key.key)});
        }
        report.add_table(rows);
    }
    return report.render();
}

bool MainWindow::export_pdf_report(const QString& path) {
    const QByteArray pdf = pdf_report_bytes();
    QString error;
    if (!write_file(path, pdf, error)) {
        report_error(QT_TR_NOOP("Could not export the PDF report"),
                     tr("%1 could not be written: %2").arg(QDir::toNativeSeparators(path), error));
        return false;
    }
    remember_folder_of(path);
    show_status(
        [path] { return tr("PDF report written to %1").arg(QDir::toNativeSeparators(path)); },
        4000);
    return true;
}

}  // namespace probecycle::ui
