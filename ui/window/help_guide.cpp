#include "ui/window/help_guide.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QFileInfo>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace probecycle::ui {

namespace {

// Each paragraph is one text to translate; the formulas are those of
// docs/model.md ("One touch", "Strategies and features") and docs/cli.md ("The
// calibration and latency lab").
QString section(const QString& title, const QString& body) {
    return QStringLiteral("<h3>%1</h3><p>%2</p>").arg(title, body);
}

#ifndef PROBECYCLE_README_PATH
#define PROBECYCLE_README_PATH ""
#endif

}  // namespace

QString help_guide_html(const QString& readme_path) {
    QString html;
    html += section(
        HelpGuide::tr("Getting started"),
        HelpGuide::tr(
            "<b>1. Start near your machine.</b> Choose the preset closest to your control and "
            "probe (Presets), or read a LinuxCNC machine from its INI file (File &gt; Import "
            "Machine). Every value is typical until you replace it with yours. "
            "<b>2. Enter what you know.</b> From the probe's data sheet: its pretravel, "
            "repeatability and overtravel limit; from the control: its scan period; from your "
            "cycle: the feature, the feeds and the backoff. What you do not know, the delays, "
            "you measure in the Latency tab (its Example data shows how). "
            "<b>3. Read the six numbers at the top.</b> Cycle time: the whole cycle as set. "
            "Overtravel: how far the axis runs past the trigger, against the probe's limit, at "
            "the highest feed override. Trigger speed: the feed when the measuring touch "
            "triggers. Uncertainty (k = 2): the measurement's budget; its tooltip lists the "
            "terms. Recommended backoff: the least that lets the second touch reseat and reach "
            "its feed. Knee: the feed beyond which a faster search saves almost no time. "
            "<b>4. Follow the warnings</b>, errors first; each button sets the value that "
            "clears its warning, and the Optimise tab finds the fastest settings that meet your "
            "limits. <b>Where the numbers come from</b>: a model of the axis's motion "
            "(acceleration, filters, servo lag), the probe and the control's delays, with the "
            "formulas below; nothing is measured unless you measure it."));
    html += section(
        HelpGuide::tr("One touch, phase by phase"),
        HelpGuide::tr(
            "<b>Approach</b>: from the start position to the surface at the probing feed. "
            "<b>Pretravel</b>: the stylus deflects until the probe triggers. <b>Interface "
            "delay</b> t<sub>i</sub>: the probe's interface passes the signal on. "
            "<b>Controller delay</b>: the control's latency t<sub>c</sub> plus the wait until "
            "it scans the input, anything from nothing to a whole scan period t<sub>s</sub>: "
            "the cycle time takes the mean wait, t<sub>s</sub>/2, the overtravel the worst "
            "case, t<sub>s</sub>. <b>Deceleration</b>: the axis brakes to rest. Two-touch then "
            "<b>backs off</b>, touches again slowly (the <b>2nd</b> phases) and <b>returns</b> "
            "to the start; a web, pocket, bore or boss adds the <b>positioning</b> moves out "
            "from its centre to each touch and back. With a block change time, every move "
            "adds it (<b>block change</b>)."));
    html += section(
        HelpGuide::tr("The formulas"),
        HelpGuide::tr(
            "Overtravel = pretravel + v &middot; (t<sub>i</sub> + t<sub>c</sub> + "
            "t<sub>s</sub>) + the braking distance (v&middot;T/2 with a time constant T), the "
            "worst case; on average the axis stops v &middot; t<sub>s</sub>/2 short of it, and "
            "a two-touch cycle's second approach is the backoff less that mean stop. "
            "Scan range R = v &middot; t<sub>s</sub> (0 with a latched input). The trigger's "
            "uncertainty (k = 2) U<sub>t</sub> = &radic;(R&sup2;/3 + repeatability&sup2;), over "
            "&radic;N for N repeats; the uncertainty (k = 2) is its budget with the terms no "
            "feed changes, U = &radic;(U<sub>t</sub>&sup2; + 4 (lobing&sup2;/3 + artefact&sup2;/4 "
            "+ machine repeatability&sup2;/4 + thermal drift&sup2;/3)). Recommended backoff = the "
            "first touch's overtravel + the larger of the reseat distance and the distance the "
            "second touch needs to reach its feed, rounded up to the micrometre. The tooltip "
            "of every parameter says where it enters."));
    html += section(
        HelpGuide::tr("Reading the charts"),
        HelpGuide::tr(
            "<b>Cycle time against the probing feed</b>: single-touch and two-touch (with the "
            "recommended backoff at each feed), the knee (the lowest feed whose cycle time is "
            "within the knee tolerance, 1 % by default, of the fastest valid cycle) and this "
            "cycle. Feeds whose cycle cannot run (overtravel over the limit, backoff too small) "
            "are invalid and never count as fast. <b>Overtravel and uncertainty</b> against "
            "the feed, with the probe's limit and your target. <b>Phases</b>: where the time "
            "goes. <b>Position and speed</b> through the whole cycle."));
    html += section(
        HelpGuide::tr("Warnings"),
        HelpGuide::tr(
            "Errors come first: an error means the cycle cannot run as set, and no cycle time "
            "is shown for it. Where a warning has a one-click fix, its button sets the value "
            "that clears it; Undo takes it back."));
    html += section(
        HelpGuide::tr("Measuring the delay"),
        HelpGuide::tr(
            "On the machine, touch the same surface at several feeds (for example 30, 100, "
            "300, 1000 and 2000 mm/min, five times each), each time from far enough out to be "
            "at full feed, and note the recorded positions. Paste them into the Latency tab "
            "(axis, direction, feed, measured) and press Fit: measured = p<sub>0</sub> + v "
            "&middot; &tau;, and the delay &tau; = t<sub>i</sub> + t<sub>c</sub> + "
            "t<sub>s</sub>/2 gives the controller's latency t<sub>c</sub>, which Apply writes "
            "into the scenario. The Calibration tab fits the stylus's runout and effective "
            "radius from a ring gauge touched at spindle 0&deg; and 180&deg;."));
    if (!readme_path.isEmpty()) {
        html += section(HelpGuide::tr("More"),
                        HelpGuide::tr("The README and the docs folder beside it explain the "
                                      "model in full, with its limits, the files, the "
                                      "command line and the lab. <a href=\"%1\">Open the "
                                      "README</a>.")
                            .arg(QUrl::fromLocalFile(readme_path).toString()));
    }
    return html;
}

HelpGuide::HelpGuide(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("help-guide"));
    text_ = new QTextBrowser(this);
    text_->setOpenExternalLinks(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(text_, 1);
    layout->addWidget(buttons);
    resize(640, 720);
    retranslate();
}

QString HelpGuide::html() const {
    return text_->toHtml();
}

void HelpGuide::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(event);
}

void HelpGuide::retranslate() {
    setWindowTitle(tr("ProbeCycle guide"));
    // The README beside the sources this program was built from, if it is there.
    const QString readme = QStringLiteral(PROBECYCLE_README_PATH);
    text_->setHtml(help_guide_html(QFileInfo::exists(readme) ? readme : QString()));
}

}  // namespace probecycle::ui
