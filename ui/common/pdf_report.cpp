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
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFormat>
#include <QTextFragment>
#include <QTextFrame>
#include <QTextLayout>
#include <QTextTable>
#include <QUrl>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

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

void PdfReport::add_subheading(const QString& text) {
    blocks_.push_back({Kind::subheading, text, {}, {}});
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

void PdfReport::add_fields(const QList<QStringList>& pairs) {
    if (pairs.isEmpty()) return;
    blocks_.push_back({Kind::fields, {}, pairs, {}});
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

// A table splits after its header and at least this many rows.
constexpr int kRowsBeforeSplit = 3;
// A table no taller than this share of a page is not split at all.
constexpr double kShortTableShare = 0.15;
// Paragraphs up to this share of a page between a heading and a table or a
// picture go on to the next page with them.
constexpr double kLeadInShare = 0.15;
// A picture shrinks to this share of its size at the least to stay on a page.
constexpr double kMinImageShare = 0.75;

// One thing on the page in reading order: a paragraph or heading, or a table.
struct Element {
    QTextBlock block;
    QTextTable* table{nullptr};
    bool heading() const { return table == nullptr && block.blockFormat().headingLevel() > 0; }
    bool image() const {
        if (table != nullptr) return false;
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            if (it.fragment().charFormat().isImageFormat()) return true;
        }
        return false;
    }
};

class Pages {
  public:
    Pages(QTextDocument& document, double page_height)
        : layout_(document.documentLayout()), height_(page_height) {}

    int page_of(double y) const { return static_cast<int>(std::floor(y / height_)); }
    bool starts_page(const Element& e) const {
        const double y = top(e);
        return y - page_of(y) * height_ < 1.0;
    }
    // A paragraph's lines, not its block: the layout moves a line that does
    // not fit (a picture) to the next page within the block.
    double top(const Element& e) const {
        if (e.table != nullptr) return layout_->frameBoundingRect(e.table).top();
        const QTextLayout* lines = e.block.layout();
        const double y = layout_->blockBoundingRect(e.block).top();
        return lines->lineCount() > 0 ? y + lines->lineAt(0).y() : y;
    }
    double bottom(const Element& e) const {
        if (e.table != nullptr) return layout_->frameBoundingRect(e.table).bottom();
        const QRectF rect = layout_->blockBoundingRect(e.block);
        const QTextLayout* lines = e.block.layout();
        return lines->lineCount() > 0
                   ? std::max(rect.bottom(),
                              rect.top() + lines->lineAt(lines->lineCount() - 1).rect().bottom())
                   : rect.bottom();
    }
    double height(const Element& e) const { return bottom(e) - top(e); }
    // Where a paragraph's first line would start on the page it begins on.
    double block_top(const Element& e) const {
        return layout_->blockBoundingRect(e.block).top() + e.block.blockFormat().topMargin();
    }
    // The bottom of what must stay with the heading above it: a table's header
    // and first rows, a paragraph's first two lines, a picture.
    double lead_bottom(const Element& e) const {
        if (e.table != nullptr) {
            const int last = std::min(1 + kRowsBeforeSplit, e.table->rows()) - 1;
            double y = top(e);
            for (int column = 0; column < e.table->columns(); ++column) {
                const QTextBlock block = e.table->cellAt(last, column).lastCursorPosition().block();
                y = std::max(y, layout_->blockBoundingRect(block).bottom());
            }
            return y;
        }
        const QRectF rect = layout_->blockBoundingRect(e.block);
        const QTextLayout* lines = e.block.layout();
        if (lines->lineCount() == 0) return rect.bottom();
        return rect.top() + lines->lineAt(std::min(lines->lineCount(), 2) - 1).rect().bottom();
    }
    double page_height() const { return height_; }

  private:
    QAbstractTextDocumentLayout* layout_;
    double height_;
};

void break_before(const Element& e) {
    if (e.table != nullptr) {
        QTextTableFormat format = e.table->format();
        format.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
        e.table->setFormat(format);
        return;
    }
    QTextBlockFormat format = e.block.blockFormat();
    format.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
    QTextCursor(e.block).setBlockFormat(format);
}

// The document laid out at its page size, with page breaks added before
// what would split badly (see render()). Elements are looked at in order, so
// a break moves only what comes after the ones already placed.
// The first element that must go on the page with the start of
// elements[i]: the headings right over it and, over a table or a picture,
// the short paragraphs that lead in to it under those headings.
std::size_t group_start(const std::vector<Element>& elements, std::size_t i, const Pages& pages) {
    const bool lead_in_allowed = elements[i].table != nullptr || elements[i].image();
    double lead_in = 0.0;
    std::size_t start = i;
    while (start > 0) {
        const Element& before = elements[start - 1];
        if (!before.heading()) {
            if (!lead_in_allowed || elements[start].heading() || before.table != nullptr ||
                before.image()) {
                break;
            }
            lead_in += pages.height(before);
            if (lead_in > kLeadInShare * pages.page_height()) break;
        }
        --start;
    }
    // Paragraphs without a heading over them are not a lead-in.
    return elements[start].heading() ? start : i;
}

// A picture pushed to the next page shrinks instead, to no less than
// kMinImageShare of its size, when that fits it into the room left.
bool shrink_into(const Element& image, double room) {
    const double factor = 0.97 * room / image.block.layout()->lineAt(0).height();
    if (factor < kMinImageShare || factor >= 1.0) return false;
    for (auto it = image.block.begin(); !it.atEnd(); ++it) {
        const QTextFragment fragment = it.fragment();
        if (!fragment.charFormat().isImageFormat()) continue;
        QTextImageFormat format = fragment.charFormat().toImageFormat();
        format.setWidth(format.width() * factor);
        format.setHeight(format.height() * factor);
        QTextCursor cursor(image.block);
        cursor.setPosition(fragment.position());
        cursor.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
        cursor.setCharFormat(format);
        return true;
    }
    return false;
}

// The document laid out at its page size, with page breaks added before
// what would split badly (see render()). Elements are looked at in order, so
// a change moves only what comes after the ones already placed.
void keep_together(QTextDocument& document) {
    std::vector<Element> elements;
    for (auto it = document.rootFrame()->begin(); !it.atEnd(); ++it) {
        if (auto* table = qobject_cast<QTextTable*>(it.currentFrame())) {
            elements.push_back({{}, table});
        } else if (it.currentBlock().isValid() && !it.currentBlock().text().isEmpty()) {
            elements.push_back({it.currentBlock(), nullptr});
        }
    }
    const Pages pages(document, document.pageSize().height());
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const Element& e = elements[i];
        if (e.heading()) continue;
        const Element& first = elements[group_start(elements, i, pages)];
        const int page = pages.page_of(pages.top(first));
        if (pages.starts_page(first)) continue;
        if (e.image() && pages.page_of(pages.top(e)) != page) {
            // From where the block starts: the picture's line is what moved.
            const double room = (page + 1) * pages.page_height() - pages.block_top(e);
            if (shrink_into(e, room)) continue;
        }
        const bool headed = &first != &e;
        const bool lead_split =
            (headed || e.table != nullptr) && pages.page_of(pages.lead_bottom(e) - 1.0) != page;
        const bool short_table_split = e.table != nullptr &&
                                       pages.height(e) <= kShortTableShare * pages.page_height() &&
                                       pages.page_of(pages.bottom(e) - 1.0) != page;
        if (lead_split || short_table_split) break_before(first);
    }
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
            case Kind::subheading:
                html += open_block(QStringLiteral("h3")) + QLatin1Char('>') +
                        block.text.toHtmlEscaped() + QStringLiteral("</h3>");
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
                            " border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\" "
                            "style=\"border-color: #999999; border-style: solid\">");
                // The header row in <thead>: repeated on every page the table goes on to.
                for (qsizetype r = 0; r < block.rows.size(); ++r) {
                    const QString cell = r == 0 ? QStringLiteral("th") : QStringLiteral("td");
                    if (r == 0) html += QStringLiteral("<thead>");
                    html += QStringLiteral("<tr>");
                    for (const QString& text : block.rows[r]) {
                        html += QStringLiteral("<%1 align=\"left\">%2</%1>")
                                    .arg(cell, paragraphs(text));
                    }
                    html += QStringLiteral("</tr>");
                    if (r == 0) html += QStringLiteral("</thead>");
                }
                html += QStringLiteral("</table>");
                break;
            }
            case Kind::fields: {
                html += open_block(QStringLiteral("table")) +
                        QStringLiteral(" border=\"0\" cellspacing=\"0\" cellpadding=\"2\">");
                for (const QStringList& pair : block.rows) {
                    html += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                                .arg(paragraphs(pair.value(0)), paragraphs(pair.value(1)));
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
    keep_together(document);

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
