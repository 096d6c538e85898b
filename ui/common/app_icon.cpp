#include "ui/common/app_icon.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

namespace probecycle::ui {

namespace {

// A probe over a surface: body, stylus, ball, and the trigger "ping".
QPixmap draw(int size) {
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(size / 64.0, size / 64.0);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0x1f, 0x5f, 0xb4));
    p.drawRoundedRect(QRectF(20, 4, 24, 26), 5, 5);
    p.setBrush(QColor(0x44, 0x44, 0x44));
    p.drawRect(QRectF(30, 30, 4, 16));
    p.setBrush(QColor(0xc0, 0x39, 0x2b));
    p.drawEllipse(QPointF(32, 49), 6, 6);
    p.setBrush(QColor(0x7f, 0x7f, 0x7f));
    p.drawRect(QRectF(6, 56, 52, 5));
    QPen ping(QColor(0xe6, 0x7e, 0x22));
    ping.setWidthF(2.5);
    p.setPen(ping);
    p.setBrush(Qt::NoBrush);
    p.drawArc(QRectF(42, 40, 14, 14), -60 * 16, 120 * 16);
    p.drawArc(QRectF(8, 40, 14, 14), 120 * 16, 120 * 16);
    return pixmap;
}

}  // namespace

QIcon app_icon() {
    QIcon icon;
    for (int size : {16, 24, 32, 48, 64, 128, 256}) icon.addPixmap(draw(size));
    return icon;
}

}  // namespace probecycle::ui
