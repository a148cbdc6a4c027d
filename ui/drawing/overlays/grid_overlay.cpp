// The grid overlay [grid]: faint lines every 50 px, stronger every 100 px,
// labelled every 100 px, so the student reads positions off the picture in the
// same units as the readout.

#include "overlay_table.h"

#include <QList>

#include <cmath>

namespace forcelab {

namespace {

void paintGrid(const PaintContext& c)
{
    const ViewTransform& view = c.view;
    if (!(view.toWidget(50.0) >= 8.0))
        return; // lines closer than 8 px would only grey the box
    QPainter& p = c.painter;
    const CanvasColors& colors = colorsOf(c.options);
    const QRectF box = view.boxRect();
    const sim::BoxSettings& size = c.world.settings().box;
    QList<QLineF> minor, major;
    for (int k = 1; 50.0 * k < size.width; ++k) {
        const double x = box.left() + view.toWidget(50.0 * k);
        (k % 2 ? minor : major).append(QLineF(x, box.top(), x, box.bottom()));
    }
    for (int k = 1; 50.0 * k < size.height; ++k) {
        const double y = box.top() + view.toWidget(50.0 * k);
        (k % 2 ? minor : major).append(QLineF(box.left(), y, box.right(), y));
    }
    p.setRenderHint(QPainter::Antialiasing, false);
    p.setPen(QPen(QColor::fromRgb(colors.gridMinor), 1.0));
    p.drawLines(minor);
    p.setPen(QPen(QColor::fromRgb(colors.gridMajor), 1.0));
    p.drawLines(major);

    if (view.toWidget(100.0) >= 40.0) {
        const double k = c.options.lineScale;
        QFont font = p.font();
        font.setPixelSize(static_cast<int>(std::lround(11 * k)));
        p.setFont(font);
        p.setPen(QColor::fromRgb(colors.gridText));
        for (int i = 1; 100.0 * i < size.width; ++i)
            p.drawText(QPointF(box.left() + view.toWidget(100.0 * i) + 3, box.top() + 13 * k),
                       QString::number(100 * i));
        for (int i = 1; 100.0 * i < size.height; ++i)
            p.drawText(QPointF(box.left() + 4, box.top() + view.toWidget(100.0 * i) - 3), QString::number(100 * i));
    }
}

} // namespace

OverlayInfo gridOverlay()
{
    return {.name = "grid",
            .on = [](const PaintContext& c) { return c.options.overlays.grid; },
            .paint = &paintGrid};
}

} // namespace forcelab
