// The apexes overlay [apexes]: a small triangle pointing down at the top of
// each flight, with the height the ball rose to: its lowest point above the
// floor (the height of its centre above where it rests), the numbers the
// lessons compare bounce by bounce.

#include "overlay_table.h"

#include <cmath>

namespace forcelab {

namespace {

void paintApexes(const PaintContext& c)
{
    QPainter& p = c.painter;
    const ViewTransform& view = c.view;
    const double k = c.options.lineScale;
    const double floor = c.world.settings().box.height;
    p.save();
    p.setClipRect(view.worldClip(), Qt::IntersectClip);
    p.setRenderHint(QPainter::Antialiasing, true);
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(11 * k)));
    p.setFont(font);
    const QColor mark(0x6a, 0x1b, 0x9a);
    for (const ApexMark& a : *c.options.apexes) {
        const QPointF top = view.toWidget(sim::Vec2(a.centre.x(), a.centre.y() - a.radius));
        const double s = 5.0 * k;
        QPolygonF triangle{top + QPointF(-s, -2 * s), top + QPointF(s, -2 * s), top + QPointF(0, -s)};
        p.setPen(Qt::NoPen);
        p.setBrush(mark);
        p.drawPolygon(triangle);
        p.setPen(mark);
        p.drawText(top + QPointF(s + 2 * k, -s), QString::number(floor - a.radius - a.centre.y(), 'f', 1));
    }
    p.restore();
}

} // namespace

OverlayInfo apexesOverlay()
{
    return {.name = "apexes",
            .on = [](const PaintContext& c) { return c.options.overlays.apexes && c.options.apexes; },
            .paint = &paintApexes};
}

} // namespace forcelab
