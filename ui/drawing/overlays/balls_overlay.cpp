// The balls, always drawn: each as its cached sprite (or one antialiased
// ellipse), balls touching another in the marked colour when [colliding] is on
// or the collision response is "flag", the theme's outlines and rings, and a
// dotted ring round the ball the readout or the selection talks about; a nail
// head on each pinned ball and, when zoomed, a cross on the centre of each
// large ball.

#include "overlay_table.h"

#include "ui/drawing/palette.h"

#include <algorithm>
#include <cmath>

namespace forcelab {

namespace {

// The balls' discs, skipping those outside `area`.
void paintDiscs(const PaintContext& c, bool mark)
{
    QPainter& p = c.painter;
    const sim::BallState& balls = c.world.balls();
    const int n = balls.size();
    const sim::Matrix2X& at = drawnPositions(balls, c.options);
    const double s = c.view.scale();
    const QPointF origin = c.view.toWidget(sim::Vec2(0.0, 0.0));
    const CanvasColors& colors = colorsOf(c.options);
    const QRectF& area = c.area;
    const qreal dpr = c.dpr;
    // Sprites are antialiased already: placed at whole device pixels with
    // antialiasing off, the raster engine copies them without resampling.
    const QTransform device = p.deviceTransform();
    const QTransform toLogical = device.inverted();
    p.setRenderHint(QPainter::Antialiasing, false);
    p.setPen(Qt::NoPen);
    for (int i = 0; i < n; ++i) {
        const double x = origin.x() + at(0, i) * s;
        const double y = origin.y() + at(1, i) * s;
        const double r = balls.radius[i] * s;
        // Off-screen (or not a number: the comparisons are false) is skipped.
        if (!(x + r >= area.left() && x - r <= area.right() && y + r >= area.top() && y - r <= area.bottom()))
            continue;
        const bool marked = mark && balls.colliding[static_cast<std::size_t>(i)] != 0;
        const sim::Rgb own = balls.color[static_cast<std::size_t>(i)];
        const sim::Rgb color = drawnBallColor(own, colors);
        const QImage* sprite = c.options.sprites ? c.sprites.sprite(r * dpr, color, marked, dpr) : nullptr;
        if (sprite) {
            // Top-left device pixel of the sprite: the disc's centre is the
            // middle of the sprite, rounded to whole pixels.
            const double half = 0.5 * sprite->width();
            const double left = std::round(device.m11() * x + device.dx() - half);
            const double top = std::round(device.m22() * y + device.dy() - half);
            p.drawImage(toLogical.map(QPointF(left, top)), *sprite);
        } else {
            p.setRenderHint(QPainter::Antialiasing, true);
            const QColor fill = QColor::fromRgb(marked ? c.sprites.markedColor() : color);
            p.setBrush(fill);
            p.setPen(QPen(fill.darker(150), std::max(1.0, 0.08 * r)));
            p.drawEllipse(QPointF(x, y), r, r);
            p.setPen(Qt::NoPen);
            p.setRenderHint(QPainter::Antialiasing, false);
        }
    }
}

// The theme's outlines: every ball's edge in a dark line, and a thick second
// ring round a touching ball, so a touch is seen without telling colours apart.
void paintOutlines(const PaintContext& c, bool mark)
{
    QPainter& p = c.painter;
    const sim::BallState& balls = c.world.balls();
    const int n = balls.size();
    const sim::Matrix2X& at = drawnPositions(balls, c.options);
    const double s = c.view.scale();
    const CanvasColors& colors = colorsOf(c.options);
    const double k = c.options.lineScale;
    if (!((qAlpha(colors.ballOutline) > 0 || (colors.ringMarked && mark)) && n <= WorldPainter::kMaxArrowBalls))
        return;
    p.setBrush(Qt::NoBrush);
    const QPen outline(QColor::fromRgba(colors.ballOutline), colors.outlineWidth * k);
    const QPen ring(QColor::fromRgb(colors.frame), 3.0 * k);
    for (int i = 0; i < n; ++i) {
        const QPointF centre = c.view.toWidget(sim::Vec2(at.col(i)));
        const double r = balls.radius[i] * s;
        if (qAlpha(colors.ballOutline) > 0) {
            p.setPen(outline);
            p.drawEllipse(centre, r, r);
        }
        if (colors.ringMarked && mark && balls.colliding[static_cast<std::size_t>(i)] != 0) {
            p.setPen(ring);
            const double out = r + 4.0 * k;
            p.drawEllipse(centre, out, out);
        }
    }
}

// Zoomed in, a ball can fill the screen and hide where its centre is (lesson
// 19's Earth wobbles 2.4 px): a cross marks the centre of each ball drawn
// larger than kCentreMarkRadius.
void paintCentreMarks(const PaintContext& c)
{
    const sim::BallState& balls = c.world.balls();
    const int n = balls.size();
    if (!c.view.moved() || n > WorldPainter::kMaxArrowBalls)
        return;
    QPainter& p = c.painter;
    const double k = c.options.lineScale;
    const double arm = 7.0 * k;
    const sim::Matrix2X& at = drawnPositions(balls, c.options);
    QList<QLineF> lines;
    for (int i = 0; i < n; ++i) {
        if (!(c.view.toWidget(balls.radius[i]) >= WorldPainter::kCentreMarkRadius * k))
            continue;
        const QPointF centre = c.view.toWidget(sim::Vec2(at.col(i)));
        if (!c.area.adjusted(-arm, -arm, arm, arm).contains(centre))
            continue;
        lines << QLineF(centre - QPointF(arm, 0), centre + QPointF(arm, 0))
              << QLineF(centre - QPointF(0, arm), centre + QPointF(0, arm));
    }
    if (lines.isEmpty())
        return;
    // A white halo under a dark cross: seen on any ball colour.
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(QPen(QColor(255, 255, 255, 220), 4.0 * k, Qt::SolidLine, Qt::RoundCap));
    p.drawLines(lines);
    p.setPen(QPen(QColor::fromRgb(canvas_colors::kSelection), 2.0 * k, Qt::SolidLine, Qt::RoundCap));
    p.drawLines(lines);
}

// A pinned ball carries a nail head on its centre: a dark disc with a light
// rim, so the class sees which balls cannot move.
void paintPins(const PaintContext& c)
{
    const sim::BallState& balls = c.world.balls();
    if (!balls.anyPinned())
        return;
    QPainter& p = c.painter;
    const double k = c.options.lineScale;
    const sim::Matrix2X& at = drawnPositions(balls, c.options);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(QPen(QColor(255, 255, 255, 230), 1.5 * k));
    p.setBrush(QColor::fromRgb(canvas_colors::kFrame));
    for (int i = 0; i < balls.size(); ++i) {
        if (!balls.pinned[static_cast<std::size_t>(i)])
            continue;
        // As large as the ball allows, and never larger than 5 px (times the line scale).
        const double r = std::min(5.0 * k, 0.45 * c.view.toWidget(balls.radius[i]));
        if (r >= 1.0)
            p.drawEllipse(c.view.toWidget(sim::Vec2(at.col(i))), r, r);
    }
}

void paintBalls(const PaintContext& c)
{
    const sim::BallState& balls = c.world.balls();
    const int n = balls.size();
    // Collision responses mark balls; "flag" exists to show exactly that.
    const bool colliding =
        c.options.overlays.colliding || c.world.settings().collisions.response == sim::Response::Flag;
    const bool mark = colliding && balls.colliding.size() == static_cast<std::size_t>(n);
    paintDiscs(c, mark);
    QPainter& p = c.painter;
    p.setRenderHint(QPainter::Antialiasing, true);
    paintOutlines(c, mark);
    paintCentreMarks(c);
    paintPins(c);
    // The ball the readout or the selection talks about gets a ring.
    int ringed = c.options.selected;
    if (ringed < 0 && c.options.overlays.readout && n > 0)
        ringed = 0;
    if (ringed >= 0 && ringed < n) {
        const QPointF centre = c.view.toWidget(drawnPositions(balls, c.options).col(ringed));
        const double r = balls.radius[ringed] * c.view.scale() + 4.0 * c.options.lineScale;
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kSelection), 2.0 * c.options.lineScale, Qt::DotLine));
        p.drawEllipse(centre, r, r);
    }
}

} // namespace

OverlayInfo ballsOverlay()
{
    return {.name = "balls", .on = [](const PaintContext&) { return true; }, .paint = &paintBalls};
}

} // namespace forcelab
