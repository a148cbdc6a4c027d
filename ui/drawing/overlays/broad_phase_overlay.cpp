// The broad-phase overlay [broadphase]: the uniform grid's cells (those that
// hold a ball shaded) or the sort-and-sweep rows with each ball's x-interval.
// The cells and rows are the detector's own (sim/collision/broad_phase/
// broad_phase_geometry.h), so the search drawn is the search the world runs.

#include "overlay_table.h"

#include "sim/collision/broad_phase/broad_phase_geometry.h"

#include <QList>

#include <algorithm>
#include <cmath>
#include <vector>

namespace forcelab {

namespace {

// Two balls are tested only when they share a cell.
void paintCells(const PaintContext& c, const sim::BroadPhaseGeometry& geometry, const QColor& color)
{
    QPainter& p = c.painter;
    const ViewTransform& view = c.view;
    const sim::BallState& balls = c.world.balls();
    const int n = balls.size();
    const QRectF box = view.shownBox();
    const double s = view.scale();
    const double cell = geometry.cellSize, minX = geometry.originX, minY = geometry.originY;
    if (!(cell * s >= 4.0) || !std::isfinite(minX) || !std::isfinite(minY))
        return; // cells smaller than 4 px would only grey the picture
    const sim::Vec2 from = view.toWorld(box.topLeft()), to = view.toWorld(box.bottomRight());
    const auto firstX = static_cast<long long>(std::floor((from.x() - minX) / cell));
    const auto lastX = static_cast<long long>(std::ceil((to.x() - minX) / cell));
    const auto firstY = static_cast<long long>(std::floor((from.y() - minY) / cell));
    const auto lastY = static_cast<long long>(std::ceil((to.y() - minY) / cell));
    if (n <= WorldPainter::kMaxBroadPhaseBalls && (lastX - firstX) * (lastY - firstY) <= 1'000'000) {
        // Shade the cells that hold at least one ball.
        const long long nx = lastX - firstX + 1;
        std::vector<unsigned char> used(static_cast<std::size_t>(nx * (lastY - firstY + 1)), 0);
        QList<QRectF> rects;
        for (int i = 0; i < n; ++i) {
            const double r = balls.radius[i], x = balls.position(0, i), y = balls.position(1, i);
            const long long x0 = std::max(firstX, static_cast<long long>(std::floor((x - r - minX) / cell)));
            const long long x1 = std::min(lastX, static_cast<long long>(std::floor((x + r - minX) / cell)));
            const long long y0 = std::max(firstY, static_cast<long long>(std::floor((y - r - minY) / cell)));
            const long long y1 = std::min(lastY, static_cast<long long>(std::floor((y + r - minY) / cell)));
            for (long long cy = y0; cy <= y1; ++cy)
                for (long long cx = x0; cx <= x1; ++cx) {
                    unsigned char& u = used[static_cast<std::size_t>((cy - firstY) * nx + (cx - firstX))];
                    if (!u) {
                        u = 1;
                        rects.append(QRectF(view.toWidget(sim::Vec2(minX + cx * cell, minY + cy * cell)),
                                            QSizeF(cell * s, cell * s)));
                    }
                }
        }
        QColor fill = color;
        fill.setAlpha(28);
        p.setPen(Qt::NoPen);
        p.setBrush(fill);
        p.drawRects(rects);
    }
    QList<QLineF> lines;
    for (long long cx = firstX; cx <= lastX; ++cx) {
        const double x = view.toWidget(sim::Vec2(minX + cx * cell, 0.0)).x();
        lines.append(QLineF(x, box.top(), x, box.bottom()));
    }
    for (long long cy = firstY; cy <= lastY; ++cy) {
        const double y = view.toWidget(sim::Vec2(0.0, minY + cy * cell)).y();
        lines.append(QLineF(box.left(), y, box.right(), y));
    }
    QColor line = color;
    line.setAlpha(110);
    p.setPen(QPen(line, 1.0));
    p.drawLines(lines);
}

// Sort and sweep in rows a little taller than the tallest ball: each ball's
// x-interval [x - r, x + r] is a band in the row of its top edge; a pair is
// tested only when the bands overlap in one row or the two rows next to each
// other.
void paintRows(const PaintContext& c, const sim::BroadPhaseGeometry& geometry, const QColor& color)
{
    QPainter& p = c.painter;
    const ViewTransform& view = c.view;
    const sim::BallState& balls = c.world.balls();
    const int n = balls.size();
    const QRectF box = view.shownBox();
    const double s = view.scale();
    const double row = geometry.rowHeight;
    if (!(row * s >= 4.0))
        return;
    QList<QLineF> lines;
    const sim::BoxSettings& size = c.world.settings().box;
    for (int k = 1; k * row < size.height; ++k) {
        const double y = view.toWidget(sim::Vec2(0.0, k * row)).y();
        lines.append(QLineF(box.left(), y, box.right(), y));
    }
    if (n <= WorldPainter::kMaxBroadPhaseBalls) {
        QList<QRectF> bands;
        bands.reserve(n);
        for (int i = 0; i < n; ++i) {
            const double r = balls.radius[i];
            const double top = std::floor((balls.position(1, i) - r) / row) * row;
            bands.append(QRectF(view.toWidget(sim::Vec2(balls.position(0, i) - r, top)), QSizeF(2.0 * r * s, row * s)));
        }
        QColor fill = color;
        fill.setAlpha(36);
        p.setPen(Qt::NoPen);
        p.setBrush(fill);
        p.drawRects(bands);
    }
    QColor line = color;
    line.setAlpha(140);
    p.setPen(QPen(line, 1.0, Qt::DashLine));
    p.drawLines(lines);
}

void paintBroadPhase(const PaintContext& c)
{
    const sim::Detection detection = c.world.settings().collisions.detection;
    if (c.world.balls().size() == 0 || (detection != sim::Detection::Grid && detection != sim::Detection::Sweep))
        return;
    QPainter& p = c.painter;
    p.save();
    p.setClipRect(c.view.worldClip(), Qt::IntersectClip);
    p.setRenderHint(QPainter::Antialiasing, false);
    const sim::BroadPhaseGeometry geometry = sim::broadPhaseGeometry(c.world);
    const QColor color = QColor::fromRgb(canvas_colors::kBroadPhase);
    if (detection == sim::Detection::Grid)
        paintCells(c, geometry, color);
    else
        paintRows(c, geometry, color);
    p.restore();
}

} // namespace

OverlayInfo broadPhaseOverlay()
{
    return {.name = "broadphase",
            .on = [](const PaintContext& c) { return c.options.overlays.broadphase; },
            .paint = &paintBroadPhase};
}

} // namespace forcelab
