// The arrows overlay: velocity [velocity], acceleration [acceleration], net
// force F = m a [forces] and one force per model that acts [sources], from each
// ball's centre. They share one set of scales (WorldPainter::arrowScales) and
// stay on the stage, out of the panels.

#include "overlay_table.h"

#include "arrow.h"

#include <QList>

namespace forcelab {

namespace {

// Each model's force on a ball, F = m a_model, in the model's colour, at the
// net force's scale: on screen the parts add up to the whole. Few balls: all
// of them; many: the selected one (each costs a pass over every model).
void paintSourceArrows(const PaintContext& c, const QList<int>& which, double forceScale, double head)
{
    QPainter& p = c.painter;
    const sim::BallState& balls = c.world.balls();
    const sim::Matrix2X& at = drawnPositions(balls, c.options);
    const int n = balls.size();
    QList<int> traced;
    if (n <= WorldPainter::kMaxSourceBalls)
        traced = which;
    else if (c.options.selected >= 0 && c.options.selected < n)
        traced.append(c.options.selected);
    for (int i : traced) {
        const sim::Vec2 x = at.col(i);
        for (const sim::World::SourceAcceleration& source : c.world.accelerationBySource(i)) {
            QList<QLineF> lines;
            appendArrow(lines, c.view.toWidget(x),
                        c.view.toWidget(x + forceScale * balls.mass[i] * source.acceleration), 0.8 * head);
            p.setPen(QPen(WorldPainter::sourceColor(source.model), 2.0 * c.options.lineScale, Qt::SolidLine,
                          Qt::RoundCap));
            p.drawLines(lines);
        }
    }
}

void paintArrows(const PaintContext& c)
{
    QPainter& p = c.painter;
    const ViewTransform& view = c.view;
    const PaintOptions& options = c.options;
    const sim::Matrix2X* accelerations = c.accelerations;
    const sim::BallState& balls = c.world.balls();
    const sim::Matrix2X& at = drawnPositions(balls, options);
    const int n = balls.size();
    QList<int> which;
    if (n <= WorldPainter::kMaxArrowBalls) {
        which.reserve(n);
        for (int i = 0; i < n; ++i)
            which.append(i);
    } else if (options.selected >= 0 && options.selected < n) {
        which.append(options.selected);
    }
    const double head = 9.0 * options.lineScale;
    const WorldPainter::ArrowScales scales = WorldPainter::arrowScales(c.world, view, options, accelerations);
    p.save();
    p.setClipRect(view.worldClip(), Qt::IntersectClip); // arrows stay on the stage, out of the panels
    p.setRenderHint(QPainter::Antialiasing, true);
    if (options.overlays.velocity) {
        QList<QLineF> lines;
        for (int i : which) {
            const sim::Vec2 x = at.col(i);
            appendArrow(lines, view.toWidget(x), view.toWidget(x + scales.velocity * balls.velocity.col(i)), head);
        }
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kVelocity), 2.0 * options.lineScale, Qt::SolidLine, Qt::RoundCap));
        p.drawLines(lines);
    }
    if (options.overlays.acceleration && accelerations) {
        QList<QLineF> lines;
        for (int i : which) {
            const sim::Vec2 x = at.col(i);
            appendArrow(lines, view.toWidget(x), view.toWidget(x + scales.acceleration * accelerations->col(i)),
                        head);
        }
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kAcceleration), 2.0 * options.lineScale, Qt::SolidLine,
                      Qt::RoundCap));
        p.drawLines(lines);
    }
    c.frame.forceScale = scales.force;
    if (options.overlays.forces && accelerations) {
        // The net force F = m a: the same direction as the acceleration arrow,
        // but a heavy ball's is longer by its mass.
        QList<QLineF> lines;
        for (int i : which) {
            const sim::Vec2 x = at.col(i);
            const qsizetype before = lines.size();
            appendArrow(lines, view.toWidget(x),
                        view.toWidget(x + scales.force * balls.mass[i] * sim::Vec2(accelerations->col(i))), head);
            if (lines.size() > before)
                c.frame.forceLengths.push_back(lines[before].length());
        }
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kForce), 3.0 * options.lineScale, Qt::SolidLine, Qt::RoundCap));
        p.drawLines(lines);
    }
    if (options.overlays.forceSources)
        paintSourceArrows(c, which, scales.force, head);
    p.restore();
}

} // namespace

OverlayInfo arrowsOverlay()
{
    return {.name = "arrows",
            .on = [](const PaintContext& c) {
                const Overlays& o = c.options.overlays;
                return o.velocity || o.acceleration || o.forces || o.forceSources;
            },
            .paint = &paintArrows,
            .needsAccelerations = [](const PaintOptions& o) {
                return o.overlays.acceleration || o.overlays.forces || o.overlays.forceSources;
            }};
}

} // namespace forcelab
