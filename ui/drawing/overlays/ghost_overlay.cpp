// The ghost overlay [ghost]: a thin dashed outline per ball of the ghost world
// (the Accuracy dock's second run), over the live balls, so where the two runs
// agree the outline sits on the ball's edge and where they part it drifts away.

#include "overlay_table.h"

#include <algorithm>

namespace forcelab {

namespace {

void paintGhost(const PaintContext& c)
{
    const sim::BallState& balls = c.options.ghost->balls();
    if (balls.size() > WorldPainter::kMaxGhostBalls)
        return;
    QPainter& p = c.painter;
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    QPen pen(QColor::fromRgba(canvas_colors::kGhost), 1.5 * c.options.lineScale, Qt::DashLine);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    for (int i = 0; i < balls.size(); ++i) {
        const QPointF centre = c.view.toWidget(sim::Vec2(balls.position.col(i)));
        const double r = std::max(2.0, c.view.toWidget(balls.radius(i)));
        p.drawEllipse(centre, r, r);
    }
    p.restore();
}

} // namespace

OverlayInfo ghostOverlay()
{
    return {.name = "ghost",
            .on = [](const PaintContext& c) { return c.options.overlays.ghost && c.options.ghost; },
            .paint = &paintGhost};
}

} // namespace forcelab
