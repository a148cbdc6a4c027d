// The impact overlay [impact]: the selected ball's last collision, frozen at
// the frame it was found: where both balls were, the line of impact and the
// tangent, and their velocities before (dashed) and after (solid).

#include "overlay_table.h"

#include "arrow.h"

#include <QCoreApplication>
#include <QList>

#include <cmath>

namespace forcelab {

namespace {

void paintImpact(const PaintContext& context)
{
    QPainter& p = context.painter;
    const ViewTransform& view = context.view;
    const CollisionView& c = *context.options.collision;
    const sim::Vec2 d = c.positionB - c.positionA;
    const double distance = d.norm();
    if (!(distance > 0.0))
        return;
    const double k = context.options.lineScale;
    // n: the line of impact (centre to centre); t: the tangent, at right
    // angles to it. An impulse acts only along n, so the velocity components
    // along t are the same before and after.
    const sim::Vec2 n = d / distance;
    const sim::Vec2 t(-n.y(), n.x());
    const sim::Vec2 contact = c.positionA + n * (c.radiusA * distance / (c.radiusA + c.radiusB));
    const double reach = 1.6 * (c.radiusA + c.radiusB) + 30.0;
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    // Where the balls were: outlines.
    p.setPen(QPen(QColor(0x50, 0x58, 0x66), 1.0 * k, Qt::DotLine));
    p.drawEllipse(view.toWidget(c.positionA), view.toWidget(c.radiusA), view.toWidget(c.radiusA));
    p.drawEllipse(view.toWidget(c.positionB), view.toWidget(c.radiusB), view.toWidget(c.radiusB));
    p.setPen(QPen(QColor::fromRgb(canvas_colors::kTangent), 1.5 * k, Qt::DashLine));
    p.drawLine(view.toWidget(contact - t * reach), view.toWidget(contact + t * reach));
    p.setPen(QPen(QColor::fromRgb(canvas_colors::kImpactLine), 2.0 * k));
    p.drawLine(view.toWidget(c.positionA - n * (c.radiusA + reach)), view.toWidget(c.positionB + n * (c.radiusB + reach)));

    // Velocities: before dashed, after solid, from each centre.
    const double head = 9.0 * k;
    QList<QLineF> before, after;
    auto arrow = [&](QList<QLineF>& lines, const sim::Vec2& from, const sim::Vec2& v) {
        appendArrow(lines, view.toWidget(from), view.toWidget(from + context.options.velocityScale * v), head);
    };
    arrow(before, c.positionA, c.beforeA);
    arrow(before, c.positionB, c.beforeB);
    arrow(after, c.positionA, c.afterA);
    arrow(after, c.positionB, c.afterB);
    const QColor v = QColor::fromRgb(canvas_colors::kVelocity);
    p.setPen(QPen(v.lighter(150), 2.0 * k, Qt::DashLine, Qt::RoundCap));
    p.drawLines(before);
    p.setPen(QPen(v, 2.5 * k, Qt::SolidLine, Qt::RoundCap));
    p.drawLines(after);

    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(12 * k)));
    p.setFont(font);
    p.setPen(QColor::fromRgb(canvas_colors::kImpactLine));
    p.drawText(view.toWidget(c.positionB + n * (c.radiusB + reach)) + QPointF(4 * k, -4 * k),
               QCoreApplication::translate("Overlay", "line of impact"));
    p.setPen(QColor::fromRgb(canvas_colors::kTangent));
    p.drawText(view.toWidget(contact + t * reach) + QPointF(4 * k, -4 * k), QCoreApplication::translate("Overlay", "tangent"));
}

} // namespace

OverlayInfo impactOverlay()
{
    return {.name = "impact",
            .on = [](const PaintContext& c) {
                return c.options.overlays.impact && c.options.collision && c.options.collision->valid();
            },
            .paint = &paintImpact};
}

} // namespace forcelab
