// The trails overlay [trails]: the path behind each ball the recorder follows
// (or the selected one), paler than the ball. The paths are kept as a layer
// (path_layer.h) to which each frame adds only the newest segments.

#include "overlay_table.h"

#include "ui/drawing/palette.h"
#include "ui/drawing/trail_recorder.h"

#include <QList>

#include <vector>

namespace forcelab {

namespace {

void paintTrails(const PaintContext& c)
{
    QPainter& p = c.painter;
    const ViewTransform& view = c.view;
    const PaintOptions& options = c.options;
    const TrailRecorder& trails = *options.trails;
    const std::vector<int>& tracked = trails.balls();
    const sim::BallState& balls = c.world.balls();
    if (trails.length() < 2 || tracked.empty())
        return;
    const qint64 start = trails.windowStart(), newest = trails.recorded() - 1;
    // Up to 200 balls keep their own colour (paler, so the balls stand out
    // from their paths); more share one colour and one draw call.
    const bool ownColours = tracked.size() <= 200;
    std::vector<sim::Rgb> colors;
    colors.reserve(tracked.size());
    for (int ball : tracked) {
        sim::Rgb color = ownColours && ball < balls.size() ? balls.color[static_cast<std::size_t>(ball)]
                                                           : canvas_colors::kTrail;
        if (ownColours)
            color = drawnBallColor(color, colorsOf(options)); // the path in the ball's drawn colour
        auto pale = [](int v) { return v + (255 - v) * 35 / 100; };
        colors.push_back(qRgb(pale(qRed(color)), pale(qGreen(color)), pale(qBlue(color))) & 0xffffffu);
    }
    const double width = (ownColours ? 2.0 : 1.5) * options.lineScale;
    // The box, or the whole stage when zoomed or moved (paths out of the box show then).
    const QRectF box = view.worldClip();
    // Records from..to as line segments, each ball in its colour.
    auto drawSegments = [&](QPainter& q, qint64 from, qint64 to) {
        q.setRenderHint(QPainter::Antialiasing, true);
        QList<QLineF> shared;
        for (std::size_t slot = 0; slot < tracked.size(); ++slot) {
            const int s = static_cast<int>(slot);
            QList<QLineF> own;
            QList<QLineF>& lines = ownColours ? own : shared;
            const QPointF first = trails.atRecord(s, from);
            QPointF previous = view.toWidget(sim::Vec2(first.x(), first.y()));
            for (qint64 r = from + 1; r <= to; ++r) {
                const QPointF w = trails.atRecord(s, r);
                const QPointF next = view.toWidget(sim::Vec2(w.x(), w.y()));
                lines.append(QLineF(previous, next));
                previous = next;
            }
            if (ownColours) {
                q.setPen(QPen(QColor::fromRgb(colors[slot]), width, Qt::SolidLine, Qt::RoundCap));
                q.drawLines(own);
            }
        }
        if (!ownColours) {
            q.setPen(QPen(QColor::fromRgb(colors.front()), width, Qt::SolidLine, Qt::RoundCap));
            q.drawLines(shared);
        }
    };
    if (!options.incrementalPaths) {
        p.save();
        p.setClipRect(box, Qt::IntersectClip);
        drawSegments(p, start, newest);
        p.restore();
        return;
    }
    // The layer covers the box (or the stage) on whole pixels, so a segment
    // lands on the same pixels as when it is drawn straight onto the
    // picture. Only the segments recorded since the last frame are drawn
    // into it.
    const QRectF cover = QRectF(box.toAlignedRect());
    const qreal dpr = c.dpr;
    PathLayer& layer = c.paths;
    const bool same = layer.generation == trails.generation() && layer.start == start && layer.box == cover &&
                      layer.scale == view.scale() && layer.origin == view.origin() && layer.dpr == dpr &&
                      layer.lineScale == options.lineScale &&
                      layer.balls == tracked && layer.colors == colors && layer.drawnTo >= start &&
                      layer.drawnTo <= newest && !layer.image.isNull();
    if (!same) {
        const QSize pixels = (cover.size() * dpr).toSize();
        if (layer.image.size() != pixels || layer.image.devicePixelRatio() != dpr) {
            layer.image = QImage(pixels, QImage::Format_ARGB32_Premultiplied);
            layer.image.setDevicePixelRatio(dpr);
        }
        layer.image.fill(Qt::transparent);
        layer.generation = trails.generation();
        layer.start = start;
        layer.drawnTo = start;
        layer.box = cover;
        layer.scale = view.scale();
        layer.origin = view.origin();
        layer.dpr = dpr;
        layer.lineScale = options.lineScale;
        layer.balls = tracked;
        layer.colors = colors;
        c.frame.pathLayerRebuilt = true;
    }
    if (layer.drawnTo < newest) {
        QPainter q(&layer.image);
        q.translate(-cover.topLeft());
        q.setClipRect(box);
        drawSegments(q, layer.drawnTo, newest);
        layer.drawnTo = newest;
    }
    p.drawImage(cover.topLeft(), layer.image);
}

} // namespace

OverlayInfo trailsOverlay()
{
    return {.name = "trails",
            .on = [](const PaintContext& c) { return c.options.overlays.trails && c.options.trails; },
            .paint = &paintTrails};
}

} // namespace forcelab
