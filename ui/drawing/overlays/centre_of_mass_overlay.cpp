// The centre-of-mass overlay [centre-of-mass]: the centre of mass of all balls,
// drawn as the usual quartered disc, and the dashed path it has taken.

#include "overlay_table.h"

namespace forcelab {

namespace {

void paintCentreOfMass(const PaintContext& c)
{
    QPainter& p = c.painter;
    const ViewTransform& view = c.view;
    const PaintOptions& options = c.options;
    const sim::BallState& balls = c.world.balls();
    const double total = balls.mass.sum();
    if (balls.empty() || !(total > 0.0))
        return;
    // x_cm = (sum of m x) / (sum of m): it moves like one ball of the whole
    // mass pushed by the outside forces alone; the forces between the balls
    // cancel in pairs.
    const sim::Vec2 centre = (drawnPositions(balls, options) * balls.mass.matrix()) / total;
    const double k = options.lineScale;
    p.save();
    p.setClipRect(view.worldClip(), Qt::IntersectClip);
    p.setRenderHint(QPainter::Antialiasing, true);
    if (options.centreOfMassPath && options.centreOfMassPath->size() >= 2) {
        QPolygonF path;
        path.reserve(static_cast<qsizetype>(options.centreOfMassPath->size()));
        for (const sim::Vec2& x : *options.centreOfMassPath)
            path.append(view.toWidget(x));
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kCentreOfMass), 1.5 * k, Qt::DashLine, Qt::RoundCap));
        p.setBrush(Qt::NoBrush);
        p.drawPolyline(path);
    }
    // The usual sign: a disc in quarters, two dark and two white.
    const QPointF at = view.toWidget(centre);
    const double r = 8.0 * k;
    const QRectF disc(at - QPointF(r, r), QSizeF(2 * r, 2 * r));
    p.setPen(Qt::NoPen);
    p.setBrush(Qt::white);
    p.drawEllipse(disc);
    p.setBrush(QColor::fromRgb(canvas_colors::kCentreOfMass));
    p.drawPie(disc, 0, 90 * 16);
    p.drawPie(disc, 180 * 16, 90 * 16);
    p.setPen(QPen(QColor::fromRgb(canvas_colors::kCentreOfMass), 1.5 * k));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(disc);
    p.restore();
}

} // namespace

OverlayInfo centreOfMassOverlay()
{
    return {.name = "centre-of-mass",
            .on = [](const PaintContext& c) { return c.options.overlays.centreOfMass; },
            .paint = &paintCentreOfMass};
}

} // namespace forcelab
