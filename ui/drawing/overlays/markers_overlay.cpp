// The markers overlay [markers]: the point force's centre, the spring's anchor
// and its lines to the balls, the homes of the homing force, and the pointer's
// pull or push.

#include "overlay_table.h"

#include <algorithm>
#include <vector>

namespace forcelab {

namespace {

void paintMarkers(const PaintContext& c)
{
    QPainter& p = c.painter;
    const ViewTransform& view = c.view;
    const sim::WorldSettings& s = c.world.settings();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    const double k = c.options.lineScale;
    if (s.point.enabled) {
        const QPointF at = view.toWidget(s.point.position);
        const bool attract = s.point.kind == sim::PointKind::Attract;
        p.setPen(QPen(attract ? QColor(0x30, 0x60, 0xc0) : QColor(0xc0, 0x40, 0x30), 2.0 * k));
        p.drawEllipse(at, 9.0 * k, 9.0 * k);
        p.drawLine(at - QPointF(5 * k, 0), at + QPointF(5 * k, 0));
        if (attract)
            p.drawLine(at - QPointF(0, 5 * k), at + QPointF(0, 5 * k));
    }
    if (s.spring.enabled) {
        const QPointF anchor = view.toWidget(s.spring.anchor);
        const sim::BallState& balls = c.world.balls();
        if (balls.size() <= 50) {
            p.setPen(QPen(QColor(0x70, 0x78, 0x84), 1.5 * k, Qt::DashLine));
            const sim::Matrix2X& at = drawnPositions(balls, c.options);
            for (int i = 0; i < balls.size(); ++i)
                p.drawLine(anchor, view.toWidget(at.col(i)));
        }
        p.setPen(Qt::NoPen);
        p.setBrush(QColor::fromRgb(canvas_colors::kFrame));
        p.drawRect(QRectF(anchor - QPointF(5 * k, 5 * k), QSizeF(10 * k, 10 * k)));
        p.setBrush(Qt::NoBrush);
    }
    if (s.homing.enabled) {
        // Homes are per colour: collect the distinct ones among the first balls.
        const sim::BallState& balls = c.world.balls();
        struct Home { sim::Vec2 at; sim::Rgb color; };
        std::vector<Home> homes;
        for (int i = 0; i < std::min(balls.size(), 4000) && homes.size() < 32; ++i) {
            const sim::Vec2 at = balls.home.col(i);
            const sim::Rgb color = balls.color[static_cast<std::size_t>(i)];
            if (std::none_of(homes.begin(), homes.end(), [&](const Home& h) { return h.color == color && h.at == at; }))
                homes.push_back({at, color});
        }
        for (const Home& h : homes) {
            p.setPen(QPen(QColor::fromRgb(h.color), 3.0 * k));
            p.drawEllipse(view.toWidget(h.at), 12.0 * k, 12.0 * k);
        }
    }
    const sim::PointerInput& pointer = c.world.pointer();
    if (s.pointer.enabled && pointer.inside) {
        // The pointer's pull (blue, hovering) or push (red, pressed): two rings.
        const QPointF at = view.toWidget(pointer.position);
        p.setPen(QPen(pointer.pressed ? QColor(0xc0, 0x40, 0x30) : QColor(0x30, 0x60, 0xc0), 1.5 * k));
        p.drawEllipse(at, 6.0 * k, 6.0 * k);
        p.drawEllipse(at, 14.0 * k, 14.0 * k);
    }
}

} // namespace

OverlayInfo markersOverlay()
{
    return {.name = "markers",
            .on = [](const PaintContext& c) { return c.options.overlays.markers; },
            .paint = &paintMarkers};
}

} // namespace forcelab
