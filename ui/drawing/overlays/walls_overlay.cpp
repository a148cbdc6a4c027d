// The walls, always drawn: walls that are on are solid, walls that are off
// are dashed, so a student sees where balls can leave.

#include "overlay_table.h"

namespace forcelab {

namespace {

void paintWalls(const PaintContext& c)
{
    QPainter& p = c.painter;
    const QRectF box = c.view.boxRect();
    const double k = c.options.lineScale;
    const sim::WallSettings& walls = c.world.settings().walls;
    const QPen on(QColor::fromRgb(colorsOf(c.options).frame), 3.0 * k, Qt::SolidLine, Qt::SquareCap);
    QPen off(QColor(0x9a, 0xa2, 0xae), 1.5 * k, Qt::DashLine, Qt::FlatCap);
    auto side = [&](bool present, QPointF a, QPointF b) {
        p.setPen(present ? on : off);
        p.drawLine(a, b);
    };
    const double h = 1.5 * k; // keep the solid line outside the box
    side(walls.left, box.topLeft() - QPointF(h, 0), box.bottomLeft() - QPointF(h, 0));
    side(walls.right, box.topRight() + QPointF(h, 0), box.bottomRight() + QPointF(h, 0));
    side(walls.top, box.topLeft() - QPointF(0, h), box.topRight() - QPointF(0, h));
    side(walls.bottom, box.bottomLeft() + QPointF(0, h), box.bottomRight() + QPointF(0, h));
    if (walls.middle) { // stage 3's wall down the middle, as solid as the others
        const double x = box.left() + c.view.toWidget(0.5 * c.world.settings().box.width);
        side(true, QPointF(x, box.top()), QPointF(x, box.bottom()));
    }
}

} // namespace

OverlayInfo wallsOverlay()
{
    return {.name = "walls", .on = [](const PaintContext&) { return true; }, .paint = &paintWalls};
}

} // namespace forcelab
