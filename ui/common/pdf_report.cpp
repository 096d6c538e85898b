#include "ui/common/pdf_report.h"

#include <QAbstractTextDocumentLayout>
#include <QBuffer>
#include <QCoreApplication>
#include <QDateTime>
#include <QFont>
#include <QFontMetricsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextDocument>
#include <QUrl>
#include <algorithm>
#include <utility>

// Qt 6.4: QPdfWriter (a QPagedPaintDevice; its painter's origin is the
// top-left of the printable area, in device pixels at resolution()),
// QTextDocument::setPageSize/drawContents and documentLayout()->
// setPaintDevice() so that point sizes are those of the PDF's resolution.

namespace probecycle::ui {

namespace {

// Device pixels per inch of the PDF: pictures of 1600 px fill the 180 mm
// text width at about 225 dpi, sharp on paper.
constexpr int kResolution = 300;
constexpr double kMargin_mm = 15.0;
constexpr double kBodyPoints = 9.0;

QString paragraphs(const QString& text) {
    return text.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>"));
}

}  // namespace

PdfReport::PdfReport(QString title) : title_(std::move(title)) {}

void PdfReport::add_heading(const QString& text) {
    blocks_.push_back({Kind::heading, text, {}, {}});
}

void PdfReport::add_paragraph(const QString& text) {
    blocks_.push_back({Kind::paragraph, text, {}, {}});
}

void PdfReport::add_item(const QString& title, const QString& text) {
    blocks_.push_back({Kind::item, text, {{title}}, {}});
}

void PdfReport::add_table(const QList<QStringList>& rows) {
    if (rows.isEmpty()) return;
    blocks_.push_back({Kind::table, {}, rows, {}});
}

void PdfReport::add_image(const QImage& image) {
    if (image.isNull()) return;
    blocks_.push_back({Kind::image, {}, {}, image});
}

void PdfReport::add_page_break() {
    blocks_.push_back({Kind::page_break, {}, {}, {}});
}

namespace {

// Reproducible builds' SOURCE_DATE_EPOCH, when set to whole seconds: the
// PDF's creation date then comes from it, so the same report is the same
// bytes (Qt 6.4's QPdfWriter has no setter for the date; it writes the
// current time as "/CreationDate (D:YYYYMMDDHHmmSSZ)", whose 14 digits are
// replaced in place so no offset in the file moves).
void apply_source_date(QByteArray& pdf) {
    const QByteArray epoch = qgetenv("SOURCE_DATE_EPOCH");
    bool ok = false;
    const qint64 seconds = epoch.toLongLong(&ok);
    if (!ok || seconds < 0) return;
    const QByteArray digits = QDateTime::fromSecsSinceEpoch(seconds, Qt::UTC)
                                  .toString(QStringLiteral("yyyyMMddHHmmss"))
                                  .toLatin1();
    const QByteArray key = "/CreationDate (D:";
    const qsizetype at = pdf.indexOf(key);
    if (at < 0 || digits.size() != 14 || at + key.size() + 14 > pdf.size()) return;
    pdf.replace(at + key.size(), 14, digits);
}

}  // namespace

QByteArray PdfReport::render() const {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QPdfWriter writer(&buffer);
    writer.setResolution(kResolution);
    writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait,
                                     QMarginsF(kMargin_mm, kMargin_mm, kMargin_mm, kMargin_mm),
                                     QPageLayout::Millimeter));
    writer.setTitle(title_);
    writer.setCreator(QStringLiteral("ProbeCycle %1").arg(QCoreApplication::applicationVersion()));

    QFont font;
    font.setPointSizeF(kBodyPoints);
    // Chinese from the Simplified Chinese cut of Noto CJK: fontconfig's first
    // CJK choice is the Japanese one, whose shapes (and the PDF's text, as
    // pdftotext reads it) differ for some characters (页, 示).
    // DejaVu first for Latin and Cyrillic (both from the packages the README's
    // setup installs: fonts-dejavu-core, fonts-noto-cjk).
    font.setFamilies({QStringLiteral("DejaVu Sans"), QStringLiteral("Noto Sans CJK SC")});
    const QFontMetricsF metrics(font, &writer);
    const QRect page = writer.pageLayout().paintRectPixels(kResolution);
    const double footer_height = 4.0 * metrics.height();
    const QSizeF body(page.width(), page.height() - footer_height);

    QTextDocument document;
    document.documentLayout()->setPaintDevice(&writer);
    document.setDefaultFont(font);
    document.setDocumentMargin(0.0);
    document.setPageSize(body);

    QString html = QStringLiteral("<h1>%1</h1>").arg(title_.toHtmlEscaped());
    int image_count = 0;
    bool break_next = false;
    const auto open_block = [&](const QString& tag) {
        const QString style =
            break_next ? QStringLiteral(" style=\"page-break-before: always\"") : QString();
        break_next = false;
        return QStringLiteral("<%1%2").arg(tag, style);
    };
    for (const Block& block : blocks_) {
        switch (block.kind) {
            case Kind::heading:
                html += open_block(QStringLiteral("h2")) + QLatin1Char('>') +
                        block.text.toHtmlEscaped() + QStringLiteral("</h2>");
                break;
            case Kind::paragraph:
                html += open_block(QStringLiteral("p")) + QLatin1Char('>') +
                        paragraphs(block.text) + QStringLiteral("</p>");
                break;
            case Kind::item:
                html += open_block(QStringLiteral("p")) + QStringLiteral("><b>") +
                        block.rows.front().front().toHtmlEscaped() + QStringLiteral("</b><br>") +
                        paragraphs(block.text) + QStringLiteral("</p>");
                break;
            case Kind::table: {
                html += open_block(QStringLiteral("table")) +
                        QStringLiteral(
                            " border=\"1\" cellspacing=\"0\" cellpadding=\"4\" width=\"100%\" "
                            "style=\"border-color: #999999; border-style: solid\">");
                for (qsizetype r = 0; r < block.rows.size(); ++r) {
                    const QString cell = r == 0 ? QStringLiteral("th") : QStringLiteral("td");
                    html += QStringLiteral("<tr>");
                    for (const QString& text : block.rows[r]) {
                        html += QStringLiteral("<%1 align=\"left\">%2</%1>")
                                    .arg(cell, paragraphs(text));
                    }
                    html += QStringLiteral("</tr>");
                }
                html += QStringLiteral("</table>");
                break;
            }
            case Kind::image: {
                const QString name = QStringLiteral("image%1").arg(image_count++);
                document.addResource(QTextDocument::ImageResource, QUrl(name), block.image);
                // The text width, the picture's aspect. The layout takes an
                // image's size in pixels of 96 dpi and scales it to the PDF's.
                const double width = body.width() * 96.0 / writer.logicalDpiX();
                const double height =
                    width * block.image.height() / std::max(1, block.image.width());
                html += open_block(QStringLiteral("p")) +
                        QStringLiteral("><img src=\"%1\" width=\"%2\" height=\"%3\"></p>")
                            .arg(name)
                            .arg(static_cast<int>(width))
                            .arg(static_cast<int>(height));
                break;
            }
            case Kind::page_break:
                break_next = true;
                break;
        }
    }
    document.setHtml(html);

    QPainter painter(&writer);
    const int pages = std::max(1, document.pageCount());
    for (int i = 0; i < pages; ++i) {
        if (i > 0) writer.newPage();
        painter.save();
        painter.translate(0.0, -i * body.height());
        document.drawContents(&painter, QRectF(QPointF(0.0, i * body.height()), body));
        painter.restore();

        painter.save();
        painter.setFont(font);
        painter.setPen(QColor(0x55, 0x55, 0x55));
        const QRectF footer(0.0, body.height() + 0.5 * metrics.height(), body.width(),
                            3.5 * metrics.height());
        painter.drawLine(footer.topLeft(), footer.topRight());
        const QString number =
            QCoreApplication::translate("PdfReport", "Page %1 of %2").arg(i + 1).arg(pages);
        const double number_width = metrics.horizontalAdvance(number) + metrics.height();
        painter.drawText(footer.adjusted(0.0, 0.2 * metrics.height(), -number_width, 0.0),
                         Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, footer_);
        painter.drawText(footer.adjusted(0.0, 0.2 * metrics.height(), 0.0, 0.0),
                         Qt::AlignRight | Qt::AlignTop, number);
        painter.restore();
    }
    painter.end();
    apply_source_date(bytes);
    return bytes;
}

}  // namespace probecycle::ui
