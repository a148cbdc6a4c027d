#include "world_painter.h"

#include "palette.h"
#include "trail_recorder.h"

#include "sim/collision/broad_phase/broad_phase_geometry.h"
#include "sim/forces/force_models.h"
#include "sim/world/names.h"

#include <QFontDatabase>
#include <QFontMetricsF>
#include <QLineF>
#include <QList>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <limits>
#include <optional>
#include <vector>

namespace forcelab {

namespace {
// Where the balls are drawn: their positions, or the slow-motion
// interpolation between two steps when the canvas gives one that fits.
const sim::Matrix2X& drawnPositions(const sim::BallState& balls, const PaintOptions& options)
{
    return options.positions && options.positions->cols() == balls.size() ? *options.positions : balls.position;
}

// The theme's colours, or the plain ones.
const CanvasColors& colorsOf(const PaintOptions& options)
{
    static const CanvasColors plain;
    return options.colors ? *options.colors : plain;
}

} // namespace

Overlays Overlays::fromNames(const QStringList& names)
{
    Overlays o;
    o.velocity = names.contains(QStringLiteral("velocity"));
    o.acceleration = names.contains(QStringLiteral("acceleration"));
    o.readout = names.contains(QStringLiteral("readout"));
    o.colliding = names.contains(QStringLiteral("colliding"));
    o.trails = names.contains(QStringLiteral("trails"));
    o.forces = names.contains(QStringLiteral("forces"));
    o.forceSources = names.contains(QStringLiteral("sources"));
    o.centreOfMass = names.contains(QStringLiteral("centre-of-mass"));
    o.momenta = names.contains(QStringLiteral("momenta"));
    o.apexes = names.contains(QStringLiteral("apexes"));
    o.vanes = names.contains(QStringLiteral("vanes"));
    o.impact = names.contains(QStringLiteral("impact"));
    o.broadphase = names.contains(QStringLiteral("broadphase"));
    o.histogram = names.contains(QStringLiteral("histogram"));
    o.totals = names.contains(QStringLiteral("totals"));
    // ghost stays on: it draws only while a ghost world runs.
    return o;
}

namespace {

// The panels' text: a fixed-width font at a size that grows with lineScale.
QFont panelFont(int pixels, double lineScale)
{
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPixelSize(static_cast<int>(std::lround(pixels * lineScale)));
    return font;
}

constexpr int kReadoutPixels = 14, kTotalsPixels = 13, kReadoutLines = 5, kTotalsLines = 4;

// A panel's size for `lines` lines as wide as `widest`, with its padding.
QSizeF panelSize(const QFont& font, const QString& widest, int lines, double lineScale)
{
    const QFontMetricsF fm(font);
    const double pad = 8.0 * lineScale;
    return {fm.horizontalAdvance(widest) + 2 * pad, fm.lineSpacing() * lines + 2 * pad};
}

// The widest lines the panels can show (numbers at their widest), so the
// strip does not change size while the numbers change.
QSizeF readoutSize(double lineScale)
{
    return panelSize(panelFont(kReadoutPixels, lineScale), QStringLiteral("speed     -99999.9 px/s   t = 9999.999 s"),
                     kReadoutLines, lineScale);
}

QSizeF totalsSize(double lineScale)
{
    return panelSize(panelFont(kTotalsPixels, lineScale), QStringLiteral("momentum  (-9.99999e+99, -9.99999e+99)"),
                     kTotalsLines, lineScale);
}

// The same panels in two long lines, for a strip above the box: it costs
// the box less height.
QStringList wideReadout(int i, const sim::Vec2& x, const sim::Vec2& v, const sim::Vec2& a, double t)
{
    auto w = [](double value) { return QString::number(value, 'f', 1).rightJustified(8); };
    return {
        QStringLiteral("ball %1").arg(i).leftJustified(12) +
            QStringLiteral("x %1  y %2 px    vx %3  vy %4 px/s").arg(w(x.x()), w(x.y()), w(v.x()), w(v.y())),
        QStringLiteral("t %1 s").arg(t, 0, 'f', 3).leftJustified(12) +
            QStringLiteral("ax %1  ay %2 px/s²  speed %3 px/s").arg(w(a.x()), w(a.y()), w(v.norm())),
    };
}

QStringList wideTotals(const sim::Energy& e, const sim::Vec2& m)
{
    auto num = [](double value) { return QString::number(value, 'g', 4); };
    return {
        QStringLiteral("kinetic %1  potential %2  total %3").arg(num(e.kinetic), num(e.potential), num(e.total())),
        QStringLiteral("momentum (%1, %2)").arg(num(m.x()), num(m.y())),
    };
}

QSizeF wideSize(const QFont& font, const QStringList& lines, double lineScale)
{
    QString widest;
    const QFontMetricsF fm(font);
    for (const QString& line : lines)
        if (fm.horizontalAdvance(line) > fm.horizontalAdvance(widest))
            widest = line;
    return panelSize(font, widest, static_cast<int>(lines.size()), lineScale);
}

QSizeF wideReadoutSize(double lineScale)
{
    const sim::Vec2 big(-99999.9, -99999.9);
    return wideSize(panelFont(kReadoutPixels, lineScale), wideReadout(9999, big, big, big, 9999.999), lineScale);
}

QSizeF wideTotalsSize(double lineScale)
{
    sim::Energy e;
    e.kinetic = e.potential = -9.999e+99;
    return wideSize(panelFont(kTotalsPixels, lineScale), wideTotals(e, sim::Vec2(-9.999e+99, -9.999e+99)), lineScale);
}

// The legend of the per-source force arrows: a title and one line per model that is on.
QStringList sourceLegend(const sim::WorldSettings& settings)
{
    QStringList lines{QStringLiteral("forces by source")};
    for (const sim::ForceModelInfo& m : sim::forceModels())
        if (m.on(settings))
            lines.append(QStringLiteral("── ") + QString::fromLatin1(m.name.data(), static_cast<qsizetype>(m.name.size())));
    return lines;
}

QSizeF sourcesSize(const sim::WorldSettings& settings, double lineScale)
{
    const QStringList lines = sourceLegend(settings);
    QString widest;
    for (const QString& l : lines)
        if (l.size() > widest.size())
            widest = l;
    return panelSize(panelFont(kTotalsPixels, lineScale), widest, static_cast<int>(lines.size()), lineScale);
}

// The inset's side grows with thicker lines only a little: on the stage
// view (line scale 1.6) it would otherwise take a quarter of a 1024 px width.
double momentaSide(double lineScale)
{
    const double title = panelSize(panelFont(kTotalsPixels, lineScale), QStringLiteral("momenta  p = m v"), 1, lineScale)
                             .width();
    return std::max(170.0 * std::min(lineScale, 1.2), title);
}

struct Layout {
    QRectF stage;                      // where the box is fitted
    WorldPainter::Panels panels;
};

// The panels go in a strip at the right of the area (one above the other,
// wrapping into a second column when they do not fit the height) or at the
// top (side by side, wrapping into rows), whichever leaves the box larger.
// Their sizes do not depend on the numbers, so nothing moves while a lesson runs.
Layout layoutFor(const sim::World& world, const QRectF& area, const PaintOptions& o)
{
    Layout l{area, {}};
    const sim::BoxSettings& box = world.settings().box;
    const bool any = !world.balls().empty();
    // Each panel with its size in a column and in a row: in a row the
    // readout and the totals are two long lines and the momenta inset is
    // wider than tall, so a strip above the box costs it less height.
    struct Item {
        QRectF* rect;
        QSizeF column, row;
        bool* wide; // set when the row size is used (null: the panel has one shape)
    };
    std::vector<Item> items;
    if (o.overlays.readout)
        items.push_back({&l.panels.readout, readoutSize(o.lineScale), wideReadoutSize(o.lineScale),
                         &l.panels.readoutWide});
    if (o.overlays.totals)
        items.push_back({&l.panels.totals, totalsSize(o.lineScale), wideTotalsSize(o.lineScale), &l.panels.totalsWide});
    if (o.overlays.forceSources && any) {
        const QSizeF size = sourcesSize(world.settings(), o.lineScale);
        items.push_back({&l.panels.sources, size, size, nullptr});
    }
    if (o.overlays.momenta && any) {
        const double side = momentaSide(o.lineScale);
        items.push_back({&l.panels.momenta, QSizeF(side, side), QSizeF(1.4 * side, 0.75 * side), nullptr});
    }
    if (items.empty())
        return l;
    const double gap = 8.0 * o.lineScale;
    struct Flow {
        std::vector<QRectF> at; // places relative to the strip's corner
        QSizeF extent;
    };
    // Places the panels along rows (or columns) no longer than `limit`; in
    // rows a panel takes its row shape when that fits the limit.
    auto flow = [&](bool rows, double limit) {
        Flow f;
        double along = 0.0, across = 0.0, thickness = 0.0;
        for (const Item& item : items) {
            const QSizeF size = rows && item.row.width() <= limit ? item.row : item.column;
            const double length = rows ? size.width() : size.height();
            if (along > 0.0 && along + length > limit) { // wrap
                across += thickness + gap;
                along = 0.0;
                thickness = 0.0;
            }
            f.at.push_back(QRectF(rows ? QPointF(along, across) : QPointF(across, along), size));
            along += length + gap;
            thickness = std::max(thickness, rows ? size.height() : size.width());
            const double endAlong = along - gap, endAcross = across + thickness;
            f.extent = rows ? QSizeF(std::max(f.extent.width(), endAlong), endAcross)
                            : QSizeF(endAcross, std::max(f.extent.height(), endAlong));
        }
        return f;
    };
    const Flow column = flow(false, area.height() - 2 * gap);
    const Flow row = flow(true, area.width() - 2 * gap);
    const QRectF beside = area.adjusted(0, 0, -(column.extent.width() + 2 * gap), 0);
    const QRectF below = area.adjusted(0, row.extent.height() + 2 * gap, 0, 0);
    const double sideScale = ViewTransform::fit(box, beside, o.margin).scale();
    const double topScale = ViewTransform::fit(box, below, o.margin).scale();
    const bool side = sideScale >= topScale;
    l.stage = side ? beside : below;
    const Flow& f = side ? column : row;
    const QPointF corner = side ? QPointF(beside.right() + gap, area.top() + gap) : area.topLeft() + QPointF(gap, gap);
    for (std::size_t k = 0; k < items.size(); ++k) {
        *items[k].rect = f.at[k].translated(corner);
        if (items[k].wide)
            *items[k].wide = !side && f.at[k].size() == items[k].row;
    }
    return l;
}

// A panel: a white rounded card with a thin dark edge, and its lines.
void drawPanel(QPainter& p, const QRectF& panel, const QFont& font, const QStringList& lines,
               const QList<QColor>& colors, double lineScale)
{
    p.setFont(font);
    const QFontMetricsF fm(font);
    const double pad = 8.0 * lineScale;
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(QPen(QColor(0x2d, 0x33, 0x40, 160), 1.0));
    p.setBrush(QColor(255, 255, 255, 235));
    p.drawRoundedRect(panel, 6, 6);
    double y = panel.top() + pad + fm.ascent();
    for (qsizetype k = 0; k < lines.size(); ++k) {
        p.setPen(colors.value(k, QColor(0x1d, 0x22, 0x2c)));
        p.drawText(QPointF(panel.left() + pad, y), lines[k]);
        y += fm.lineSpacing();
    }
}

} // namespace

ViewTransform WorldPainter::view(const sim::World& world, const QRectF& area, const PaintOptions& options)
{
    return ViewTransform::fit(world.settings().box, layoutFor(world, area, options).stage, options.margin);
}

WorldPainter::Panels WorldPainter::panels(const sim::World& world, const QRectF& area, const PaintOptions& options)
{
    return layoutFor(world, area, options).panels;
}

void WorldPainter::paint(QPainter& p, const QRectF& area, const sim::World& world, const PaintOptions& options,
                         qreal dpr)
{
    // One layout for the frame: where the box goes and where its panels go.
    const Layout layout = layoutFor(world, area, options);
    m_frame = PaintedFrame();
    const ViewTransform v = ViewTransform::fit(world.settings().box, layout.stage, options.margin);
    const Panels& placed = layout.panels;
    p.save();
    p.setClipRect(area);
    p.fillRect(area, QColor::fromRgb(colorsOf(options).letterbox));
    paintBox(p, v, world, options);
    if (options.overlays.broadphase)
        paintBroadPhase(p, v, world, options);
    if (options.overlays.trails && options.trails)
        paintTrails(p, v, world, options, dpr);
    if (options.overlays.centreOfMass)
        paintCentreOfMass(p, v, world, options);
    if (options.overlays.apexes && options.apexes)
        paintApexes(p, v, world, options);
    if (options.overlays.markers)
        paintMarkers(p, v, world, options);
    // Collision responses mark balls; "flag" exists to show exactly that.
    PaintOptions shown = options;
    shown.overlays.colliding = options.overlays.colliding || world.settings().collisions.response == sim::Response::Flag;
    paintBalls(p, area, v, world, shown, dpr);
    if (options.overlays.ghost && options.ghost)
        paintGhost(p, v, *options.ghost, options);

    std::optional<sim::Matrix2X> accelerations;
    if ((options.overlays.acceleration || options.overlays.readout || options.overlays.forces ||
         options.overlays.forceSources) &&
        !world.balls().empty())
        accelerations = world.accelerations();
    const sim::Matrix2X* a = accelerations ? &*accelerations : nullptr;
    if (options.overlays.velocity || options.overlays.acceleration || options.overlays.forces ||
        options.overlays.forceSources)
        paintArrows(p, v, world, options, a);
    if (options.overlays.impact && options.collision && options.collision->valid())
        paintCollision(p, v, options);
    if (options.overlays.vanes)
        paintVanes(p, v, world, options);
    if (options.overlays.totals)
        paintTotals(p, placed.totals, world, options, placed.totalsWide);
    if (options.overlays.readout)
        paintReadout(p, placed.readout, world, options, a, placed.readoutWide);
    if (!placed.sources.isEmpty())
        paintSourceLegend(p, placed.sources, world, options);
    if (!placed.momenta.isEmpty())
        paintMomenta(p, placed.momenta, world, options);
    p.restore();
}

// The ghost: a thin dashed outline per ball, over the live balls, so where the
// two runs agree the outline sits on the ball's edge and where they part it
// drifts away.
void WorldPainter::paintGhost(QPainter& p, const ViewTransform& view, const sim::World& ghost,
                              const PaintOptions& options)
{
    const sim::BallState& balls = ghost.balls();
    if (balls.size() > kMaxGhostBalls)
        return;
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    QPen pen(QColor::fromRgba(canvas_colors::kGhost), 1.5 * options.lineScale, Qt::DashLine);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    for (int i = 0; i < balls.size(); ++i) {
        const QPointF c = view.toWidget(sim::Vec2(balls.position.col(i)));
        const double r = std::max(2.0, view.toWidget(balls.radius(i)));
        p.drawEllipse(c, r, r);
    }
    p.restore();
}

void WorldPainter::paintBox(QPainter& p, const ViewTransform& view, const sim::World& world,
                            const PaintOptions& options)
{
    const CanvasColors& colors = colorsOf(options);
    const QRectF box = view.boxRect();
    p.fillRect(box, QColor::fromRgb(colors.background));

    const sim::BoxSettings& size = world.settings().box;
    if (options.overlays.grid && view.toWidget(50.0) >= 8.0) {
        // Faint lines every 50 px, stronger every 100 px: the student reads
        // positions off the picture in the same units as the readout.
        QList<QLineF> minor, major;
        for (int k = 1; 50.0 * k < size.width; ++k) {
            const double x = box.left() + view.toWidget(50.0 * k);
            (k % 2 ? minor : major).append(QLineF(x, box.top(), x, box.bottom()));
        }
        for (int k = 1; 50.0 * k < size.height; ++k) {
            const double y = box.top() + view.toWidget(50.0 * k);
            (k % 2 ? minor : major).append(QLineF(box.left(), y, box.right(), y));
        }
        p.setRenderHint(QPainter::Antialiasing, false);
        p.setPen(QPen(QColor::fromRgb(colors.gridMinor), 1.0));
        p.drawLines(minor);
        p.setPen(QPen(QColor::fromRgb(colors.gridMajor), 1.0));
        p.drawLines(major);

        if (view.toWidget(100.0) >= 40.0) {
            QFont font = p.font();
            font.setPixelSize(static_cast<int>(std::lround(11 * options.lineScale)));
            p.setFont(font);
            p.setPen(QColor::fromRgb(colors.gridText));
            for (int k = 1; 100.0 * k < size.width; ++k)
                p.drawText(QPointF(box.left() + view.toWidget(100.0 * k) + 3, box.top() + 13 * options.lineScale),
                           QString::number(100 * k));
            for (int k = 1; 100.0 * k < size.height; ++k)
                p.drawText(QPointF(box.left() + 4, box.top() + view.toWidget(100.0 * k) - 3),
                           QString::number(100 * k));
        }
    }

    // Walls that are on are solid; walls that are off are dashed, so a
    // student sees where balls can leave.
    const sim::WallSettings& walls = world.settings().walls;
    const QPen on(QColor::fromRgb(colors.frame), 3.0 * options.lineScale, Qt::SolidLine, Qt::SquareCap);
    QPen off(QColor(0x9a, 0xa2, 0xae), 1.5 * options.lineScale, Qt::DashLine, Qt::FlatCap);
    auto side = [&](bool present, QPointF a, QPointF b) {
        p.setPen(present ? on : off);
        p.drawLine(a, b);
    };
    const double h = 1.5 * options.lineScale; // keep the solid line outside the box
    side(walls.left, box.topLeft() - QPointF(h, 0), box.bottomLeft() - QPointF(h, 0));
    side(walls.right, box.topRight() + QPointF(h, 0), box.bottomRight() + QPointF(h, 0));
    side(walls.top, box.topLeft() - QPointF(0, h), box.topRight() - QPointF(0, h));
    side(walls.bottom, box.bottomLeft() + QPointF(0, h), box.bottomRight() + QPointF(0, h));
    if (walls.middle) { // stage 3's wall down the middle, as solid as the others
        const double x = box.left() + view.toWidget(0.5 * size.width);
        side(true, QPointF(x, box.top()), QPointF(x, box.bottom()));
    }
}

void WorldPainter::paintBalls(QPainter& p, const QRectF& area, const ViewTransform& view, const sim::World& world,
                              const PaintOptions& options, qreal dpr)
{
    const sim::BallState& balls = world.balls();
    const int n = balls.size();
    const sim::Matrix2X& at = drawnPositions(balls, options);
    const double s = view.scale();
    const QPointF origin = view.toWidget(sim::Vec2(0.0, 0.0));
    const bool mark = options.overlays.colliding && balls.colliding.size() == static_cast<std::size_t>(n);
    const CanvasColors& colors = colorsOf(options);

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
        const sim::Rgb color = colors.colourBlindSafe ? okabeItoColor(own) : own;
        const QImage* sprite = options.sprites ? m_sprites.sprite(r * dpr, color, marked, dpr) : nullptr;
        if (sprite) {
            // Top-left device pixel of the sprite: the disc's centre is the
            // middle of the sprite, rounded to whole pixels.
            const double half = 0.5 * sprite->width();
            const double left = std::round(device.m11() * x + device.dx() - half);
            const double top = std::round(device.m22() * y + device.dy() - half);
            p.drawImage(toLogical.map(QPointF(left, top)), *sprite);
        } else {
            p.setRenderHint(QPainter::Antialiasing, true);
            const QColor fill = QColor::fromRgb(marked ? m_sprites.markedColor() : color);
            p.setBrush(fill);
            p.setPen(QPen(fill.darker(150), std::max(1.0, 0.08 * r)));
            p.drawEllipse(QPointF(x, y), r, r);
            p.setPen(Qt::NoPen);
            p.setRenderHint(QPainter::Antialiasing, false);
        }
    }

    p.setRenderHint(QPainter::Antialiasing, true);
    // The theme's outlines: every ball's edge in a dark line, and a thick
    // second ring round a touching ball, so a touch is seen without telling
    // colours apart.
    if ((qAlpha(colors.ballOutline) > 0 || (colors.ringMarked && mark)) && n <= kMaxArrowBalls) {
        p.setBrush(Qt::NoBrush);
        const QPen outline(QColor::fromRgba(colors.ballOutline), colors.outlineWidth * options.lineScale);
        const QPen ring(QColor::fromRgb(colors.frame), 3.0 * options.lineScale);
        for (int i = 0; i < n; ++i) {
            const QPointF c = view.toWidget(sim::Vec2(at.col(i)));
            const double r = balls.radius[i] * s;
            if (qAlpha(colors.ballOutline) > 0) {
                p.setPen(outline);
                p.drawEllipse(c, r, r);
            }
            if (colors.ringMarked && mark && balls.colliding[static_cast<std::size_t>(i)] != 0) {
                p.setPen(ring);
                const double out = r + 4.0 * options.lineScale;
                p.drawEllipse(c, out, out);
            }
        }
    }
    // The ball the readout or the selection talks about gets a ring.
    int ringed = options.selected;
    if (ringed < 0 && options.overlays.readout && n > 0)
        ringed = 0;
    if (ringed >= 0 && ringed < n) {
        const QPointF c = view.toWidget(at.col(ringed));
        const double r = balls.radius[ringed] * s + 4.0 * options.lineScale;
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kSelection), 2.0 * options.lineScale, Qt::DotLine));
        p.drawEllipse(c, r, r);
    }
}

void WorldPainter::paintMarkers(QPainter& p, const ViewTransform& view, const sim::World& world,
                                const PaintOptions& options)
{
    const sim::WorldSettings& s = world.settings();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    const double k = options.lineScale;
    if (s.point.enabled) {
        const QPointF c = view.toWidget(s.point.position);
        const bool attract = s.point.kind == sim::PointKind::Attract;
        p.setPen(QPen(attract ? QColor(0x30, 0x60, 0xc0) : QColor(0xc0, 0x40, 0x30), 2.0 * k));
        p.drawEllipse(c, 9.0 * k, 9.0 * k);
        p.drawLine(c - QPointF(5 * k, 0), c + QPointF(5 * k, 0));
        if (attract)
            p.drawLine(c - QPointF(0, 5 * k), c + QPointF(0, 5 * k));
    }
    if (s.spring.enabled) {
        const QPointF c = view.toWidget(s.spring.anchor);
        const sim::BallState& balls = world.balls();
        if (balls.size() <= 50) {
            p.setPen(QPen(QColor(0x70, 0x78, 0x84), 1.5 * k, Qt::DashLine));
            const sim::Matrix2X& at = drawnPositions(balls, options);
            for (int i = 0; i < balls.size(); ++i)
                p.drawLine(c, view.toWidget(at.col(i)));
        }
        p.setPen(Qt::NoPen);
        p.setBrush(QColor::fromRgb(canvas_colors::kFrame));
        p.drawRect(QRectF(c - QPointF(5 * k, 5 * k), QSizeF(10 * k, 10 * k)));
        p.setBrush(Qt::NoBrush);
    }
    if (s.homing.enabled) {
        // Homes are per colour: collect the distinct ones among the first balls.
        const sim::BallState& balls = world.balls();
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
    const sim::PointerInput& pointer = world.pointer();
    if (s.pointer.enabled && pointer.inside) {
        // The pointer's pull (blue, hovering) or push (red, pressed): two rings.
        const QPointF c = view.toWidget(pointer.position);
        p.setPen(QPen(pointer.pressed ? QColor(0xc0, 0x40, 0x30) : QColor(0x30, 0x60, 0xc0), 1.5 * k));
        p.drawEllipse(c, 6.0 * k, 6.0 * k);
        p.drawEllipse(c, 14.0 * k, 14.0 * k);
    }
}

namespace {

// Shaft and two head strokes of an arrow from a to b.
void appendArrow(QList<QLineF>& lines, QPointF a, QPointF b, double head)
{
    const QLineF shaft(a, b);
    const double length = shaft.length();
    if (!(length >= 0.5))
        return;
    lines.append(shaft);
    const double h = std::min(head, 0.4 * length);
    const QPointF u = (a - b) / length; // unit vector from tip back to tail
    const double c = std::cos(std::numbers::pi / 7.0), s = std::sin(std::numbers::pi / 7.0);
    lines.append(QLineF(b, b + h * QPointF(c * u.x() - s * u.y(), s * u.x() + c * u.y())));
    lines.append(QLineF(b, b + h * QPointF(c * u.x() + s * u.y(), -s * u.x() + c * u.y())));
}

} // namespace

void WorldPainter::paintArrows(QPainter& p, const ViewTransform& view, const sim::World& world,
                               const PaintOptions& options, const sim::Matrix2X* accelerations)
{
    const sim::BallState& balls = world.balls();
    const sim::Matrix2X& at = drawnPositions(balls, options);
    const int n = balls.size();
    QList<int> which;
    if (n <= kMaxArrowBalls) {
        which.reserve(n);
        for (int i = 0; i < n; ++i)
            which.append(i);
    } else if (options.selected >= 0 && options.selected < n) {
        which.append(options.selected);
    }
    const double head = 9.0 * options.lineScale;
    const ArrowScales scales = arrowScales(world, view, options, accelerations);
    p.save();
    p.setClipRect(view.boxRect(), Qt::IntersectClip); // arrows stay on the stage, out of the panels
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
    m_frame.forceScale = scales.force;
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
                m_frame.forceLengths.push_back(lines[before].length());
        }
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kForce), 3.0 * options.lineScale, Qt::SolidLine, Qt::RoundCap));
        p.drawLines(lines);
    }
    if (options.overlays.forceSources) {
        // Each model's force on a ball, F = m a_model, in the model's colour,
        // at the net force's scale: on screen the parts add up to the whole.
        // Few balls: all of them; many: the selected one (each costs a pass
        // over every model).
        QList<int> traced;
        if (n <= kMaxSourceBalls)
            traced = which;
        else if (options.selected >= 0 && options.selected < n)
            traced.append(options.selected);
        for (int i : traced) {
            const sim::Vec2 x = at.col(i);
            for (const sim::World::SourceAcceleration& source : world.accelerationBySource(i)) {
                QList<QLineF> lines;
                appendArrow(lines, view.toWidget(x),
                            view.toWidget(x + scales.force * balls.mass[i] * source.acceleration), 0.8 * head);
                p.setPen(QPen(sourceColor(source.model), 2.0 * options.lineScale, Qt::SolidLine, Qt::RoundCap));
                p.drawLines(lines);
            }
        }
    }
    p.restore();
}

namespace {

// The median of the nonzero lengths of the columns of m (0 when none).
double medianLength(const sim::Matrix2X& m)
{
    std::vector<double> lengths;
    lengths.reserve(static_cast<std::size_t>(m.cols()));
    for (Eigen::Index i = 0; i < m.cols(); ++i) {
        const double l = m.col(i).norm();
        if (l > 0.0 && std::isfinite(l))
            lengths.push_back(l);
    }
    if (lengths.empty())
        return 0.0;
    const auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), mid, lengths.end());
    return *mid;
}

} // namespace

WorldPainter::ArrowScales WorldPainter::arrowScales(const sim::World& world, const ViewTransform& view,
                                                    const PaintOptions& options, const sim::Matrix2X* accelerations)
{
    const double f = options.arrowFactor > 0.0 ? options.arrowFactor : 1.0;
    ArrowScales s{f * options.velocityScale, f * options.accelerationScale, f * options.forceScale};
    if (!options.autoArrows || !(view.scale() > 0.0))
        return s;
    // A scale of k seconds draws a speed v as k v world px, k v scale screen px.
    const double v = medianLength(world.balls().velocity);
    if (v > 0.0)
        s.velocity = kArrowPixels / (view.scale() * v);
    const double a = accelerations ? medianLength(*accelerations) : 0.0;
    if (a > 0.0)
        s.acceleration = kArrowPixels / (view.scale() * a);
    if (accelerations && (options.overlays.forces || options.overlays.forceSources)) {
        // The net forces m a set the scale; the per-source arrows share it.
        sim::Matrix2X forces = *accelerations;
        const sim::BallState& balls = world.balls();
        for (Eigen::Index i = 0; i < forces.cols() && i < balls.size(); ++i)
            forces.col(i) *= balls.mass[static_cast<int>(i)];
        const double m = medianLength(forces);
        if (m > 0.0)
            s.force = kArrowPixels / (view.scale() * m);
    }
    return s;
}

void WorldPainter::paintReadout(QPainter& p, const QRectF& panel, const sim::World& world, const PaintOptions& options,
                                const sim::Matrix2X* accelerations, bool wide)
{
    const QStringList lines = readoutText(world, options.selected, accelerations, wide);
    if (lines.isEmpty())
        return;
    const QColor text(0x1d, 0x22, 0x2c);
    if (wide) {
        drawPanel(p, panel, panelFont(kReadoutPixels, options.lineScale), lines, {}, options.lineScale);
        return;
    }
    drawPanel(p, panel, panelFont(kReadoutPixels, options.lineScale), lines,
              {text, text, QColor::fromRgb(canvas_colors::kVelocity), QColor::fromRgb(canvas_colors::kAcceleration), text},
              options.lineScale);
}

QStringList WorldPainter::readoutText(const sim::World& world, int selected, const sim::Matrix2X* accelerations,
                                      bool wide)
{
    const sim::BallState& balls = world.balls();
    const int n = balls.size();
    if (n == 0)
        return {};
    const int i = selected >= 0 && selected < n ? selected : 0;
    auto num = [](double v) { return QString::number(v, 'f', 1).rightJustified(9); };
    const sim::Vec2 x = balls.position.col(i), v = balls.velocity.col(i);
    const sim::Vec2 a = accelerations ? sim::Vec2(accelerations->col(i)) : sim::Vec2(0.0, 0.0);
    if (wide)
        return wideReadout(i, x, v, a, world.time());
    return {
        QStringLiteral("ball %1").arg(i).leftJustified(17) + u'x' + QString(8, u' ') + u'y',
        QStringLiteral("position %1%2  px").arg(num(x.x()), num(x.y())),
        QStringLiteral("velocity %1%2  px/s").arg(num(v.x()), num(v.y())),
        QStringLiteral("accel.   %1%2  px/s²").arg(num(a.x()), num(a.y())),
        QStringLiteral("speed    %1 px/s   t = %2 s").arg(num(v.norm())).arg(world.time(), 0, 'f', 3),
    };
}

void WorldPainter::paintBroadPhase(QPainter& p, const ViewTransform& view, const sim::World& world,
                                   const PaintOptions&)
{
    const sim::BallState& balls = world.balls();
    const int n = balls.size();
    const sim::Detection detection = world.settings().collisions.detection;
    if (n == 0 || (detection != sim::Detection::Grid && detection != sim::Detection::Sweep))
        return;
    const QRectF box = view.boxRect();
    const double s = view.scale();
    const QColor color = QColor::fromRgb(canvas_colors::kBroadPhase);
    p.save();
    p.setClipRect(box, Qt::IntersectClip);
    p.setRenderHint(QPainter::Antialiasing, false);
    const bool perBall = n <= kMaxBroadPhaseBalls;

    // The detector's own cells and rows (sim/collision/broad_phase/broad_phase_geometry.h), so the
    // search drawn is the search the world runs.
    const sim::BroadPhaseGeometry geometry = sim::broadPhaseGeometry(world);
    if (detection == sim::Detection::Grid) {
        // Two balls are tested only when they share a cell.
        const double cell = geometry.cellSize, minX = geometry.originX, minY = geometry.originY;
        if (!(cell * s >= 4.0) || !std::isfinite(minX) || !std::isfinite(minY)) {
            p.restore();
            return; // cells smaller than 4 px would only grey the picture
        }
        const sim::Vec2 from = view.toWorld(box.topLeft()), to = view.toWorld(box.bottomRight());
        const auto firstX = static_cast<long long>(std::floor((from.x() - minX) / cell));
        const auto lastX = static_cast<long long>(std::ceil((to.x() - minX) / cell));
        const auto firstY = static_cast<long long>(std::floor((from.y() - minY) / cell));
        const auto lastY = static_cast<long long>(std::ceil((to.y() - minY) / cell));
        if (perBall && (lastX - firstX) * (lastY - firstY) <= 1'000'000) {
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
    } else {
        // Sort and sweep in rows a little taller than the tallest ball: each
        // ball's x-interval [x - r, x + r] is a band in the row of its top
        // edge; a pair is tested only when the bands overlap in one row or
        // the two rows next to each other.
        const double row = geometry.rowHeight;
        if (!(row * s >= 4.0)) {
            p.restore();
            return;
        }
        QList<QLineF> lines;
        const sim::BoxSettings& size = world.settings().box;
        for (int k = 1; k * row < size.height; ++k) {
            const double y = view.toWidget(sim::Vec2(0.0, k * row)).y();
            lines.append(QLineF(box.left(), y, box.right(), y));
        }
        if (perBall) {
            QList<QRectF> bands;
            bands.reserve(n);
            for (int i = 0; i < n; ++i) {
                const double r = balls.radius[i];
                const double top = std::floor((balls.position(1, i) - r) / row) * row;
                bands.append(QRectF(view.toWidget(sim::Vec2(balls.position(0, i) - r, top)),
                                    QSizeF(2.0 * r * s, row * s)));
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
    p.restore();
}

void WorldPainter::paintTrails(QPainter& p, const ViewTransform& view, const sim::World& world,
                               const PaintOptions& options, qreal dpr)
{
    const TrailRecorder& trails = *options.trails;
    const std::vector<int>& tracked = trails.balls();
    const sim::BallState& balls = world.balls();
    if (trails.length() < 2 || tracked.empty())
        return;
    const qint64 start = trails.windowStart(), newest = trails.recorded() - 1;
    // Up to 200 balls keep their own colour (paler, so the balls stand out
    // from their paths); more share one colour and one draw call.
    const bool ownColours = tracked.size() <= 200;
    std::vector<sim::Rgb> colors;
    colors.reserve(tracked.size());
    for (int ball : tracked) {
        sim::Rgb c = ownColours && ball < balls.size() ? balls.color[static_cast<std::size_t>(ball)]
                                                        : canvas_colors::kTrail;
        if (ownColours && colorsOf(options).colourBlindSafe)
            c = okabeItoColor(c); // the path in the ball's drawn colour
        auto pale = [](int v) { return v + (255 - v) * 35 / 100; };
        colors.push_back(qRgb(pale(qRed(c)), pale(qGreen(c)), pale(qBlue(c))) & 0xffffffu);
    }
    const double width = (ownColours ? 2.0 : 1.5) * options.lineScale;
    const QRectF box = view.boxRect();
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
    // The layer covers the box on whole pixels, so a segment lands on the
    // same pixels as when it is drawn straight onto the picture. Only the
    // segments recorded since the last frame are drawn into it.
    const QRectF cover = QRectF(box.toAlignedRect());
    PathLayer& layer = m_paths;
    const bool same = layer.generation == trails.generation() && layer.start == start && layer.box == cover &&
                      layer.scale == view.scale() && layer.dpr == dpr && layer.lineScale == options.lineScale &&
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
        layer.dpr = dpr;
        layer.lineScale = options.lineScale;
        layer.balls = tracked;
        layer.colors = colors;
        m_frame.pathLayerRebuilt = true;
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

void WorldPainter::paintCentreOfMass(QPainter& p, const ViewTransform& view, const sim::World& world,
                                     const PaintOptions& options)
{
    const sim::BallState& balls = world.balls();
    const double total = balls.mass.sum();
    if (balls.empty() || !(total > 0.0))
        return;
    // x_cm = (sum of m x) / (sum of m): it moves like one ball of the whole
    // mass pushed by the outside forces alone; the forces between the balls
    // cancel in pairs.
    const sim::Vec2 centre = (drawnPositions(balls, options) * balls.mass.matrix()) / total;
    const double k = options.lineScale;
    p.save();
    p.setClipRect(view.boxRect(), Qt::IntersectClip);
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
    const QPointF c = view.toWidget(centre);
    const double r = 8.0 * k;
    const QRectF disc(c - QPointF(r, r), QSizeF(2 * r, 2 * r));
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

void WorldPainter::paintApexes(QPainter& p, const ViewTransform& view, const sim::World& world,
                               const PaintOptions& options)
{
    // A small triangle pointing down at the top of each flight, with the
    // height the ball rose to: its lowest point above the floor (the height
    // of its centre above where it rests), the numbers the lessons compare
    // bounce by bounce.
    const double k = options.lineScale;
    const double floor = world.settings().box.height;
    p.save();
    p.setClipRect(view.boxRect(), Qt::IntersectClip);
    p.setRenderHint(QPainter::Antialiasing, true);
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(11 * k)));
    p.setFont(font);
    const QColor mark(0x6a, 0x1b, 0x9a);
    for (const ApexMark& a : *options.apexes) {
        const QPointF c = view.toWidget(sim::Vec2(a.centre.x(), a.centre.y() - a.radius));
        const double s = 5.0 * k;
        QPolygonF triangle{c + QPointF(-s, -2 * s), c + QPointF(s, -2 * s), c + QPointF(0, -s)};
        p.setPen(Qt::NoPen);
        p.setBrush(mark);
        p.drawPolygon(triangle);
        p.setPen(mark);
        p.drawText(c + QPointF(s + 2 * k, -s), QString::number(floor - a.radius - a.centre.y(), 'f', 1));
    }
    p.restore();
}

QColor WorldPainter::sourceColor(std::string_view name)
{
    // The Okabe-Ito colours (safe for the common colour-vision
    // deficiencies), with the yellow darkened to show on white and without
    // the black of the net force arrow.
    static constexpr QRgb kColors[] = {0xff0072b2, 0xffd55e00, 0xff009e73, 0xffcc79a7,
                                       0xff56b4e9, 0xffe69f00, 0xffa89a00};
    std::size_t k = 0;
    for (const sim::ForceModelInfo& m : sim::forceModels()) {
        if (m.name == name)
            break;
        ++k;
    }
    return QColor::fromRgba(kColors[k % std::size(kColors)]);
}

void WorldPainter::paintSourceLegend(QPainter& p, const QRectF& panel, const sim::World& world,
                                     const PaintOptions& options)
{
    const QStringList lines = sourceLegend(world.settings());
    QList<QColor> colors{QColor(0x1d, 0x22, 0x2c)};
    for (const sim::ForceModelInfo& m : sim::forceModels())
        if (m.on(world.settings()))
            colors.append(sourceColor(m.name));
    drawPanel(p, panel, panelFont(kTotalsPixels, options.lineScale), lines, colors, options.lineScale);
}

void WorldPainter::paintMomenta(QPainter& p, const QRectF& panel, const sim::World& world,
                                const PaintOptions& options)
{
    const sim::BallState& balls = world.balls();
    const int n = balls.size();
    const double k = options.lineScale;
    const QFont font = panelFont(kTotalsPixels, k);
    drawPanel(p, panel, font, {QStringLiteral("momenta  p = m v")}, {}, k);
    const QFontMetricsF fm(font);
    const double pad = 8.0 * k;
    // Below the title: each ball's momentum drawn from the tip of the one
    // before, and the sum from the first tail to the last tip. The sum is the
    // total momentum: a collision between two balls changes both their
    // arrows but not the sum.
    const QRectF region = panel.adjusted(pad, pad + fm.lineSpacing(), -pad, -pad);
    std::vector<sim::Vec2>& momenta = m_frame.momenta;
    momenta.resize(static_cast<std::size_t>(n));
    sim::Vec2 sum(0, 0);
    // The chain's corners: every partial sum (with the origin), so the
    // diagram is fitted to the room it takes, whichever way it points.
    sim::Vec2 lo(0, 0), hi(0, 0);
    const bool chain = n <= kMaxMomentumChain;
    for (int i = 0; i < n; ++i) {
        momenta[static_cast<std::size_t>(i)] = balls.mass[i] * balls.velocity.col(i);
        sum += momenta[static_cast<std::size_t>(i)];
        if (chain) {
            lo = lo.cwiseMin(sum);
            hi = hi.cwiseMax(sum);
        }
    }
    lo = lo.cwiseMin(sum);
    hi = hi.cwiseMax(sum);
    m_frame.momentumSum = sum;
    // A scale from the 1-1.5-2-3-5-7 ladder that fits the chain in the room,
    // kept while the chain uses between a quarter and all of it.
    const sim::Vec2 extent = hi - lo;
    const double fit = std::min(extent.x() > 0.0 ? region.width() / extent.x() : HUGE_VAL,
                                extent.y() > 0.0 ? region.height() / extent.y() : HUGE_VAL);
    double& scale = m_momentumScale;
    if (std::isfinite(fit) && fit > 0.0 && !(scale > 0.0 && scale <= fit && scale >= 0.25 * fit)) {
        const double want = 0.85 * fit;
        const double decade = std::pow(10.0, std::floor(std::log10(want)));
        scale = decade;
        for (double step : {1.0, 1.5, 2.0, 3.0, 5.0, 7.0})
            if (step * decade <= want)
                scale = step * decade;
    }
    if (!(scale > 0.0))
        scale = 1.0;
    m_frame.momentumScale = scale;
    const sim::Vec2 middle = 0.5 * (lo + hi);
    const QPointF origin = region.center() - QPointF(middle.x() * scale, middle.y() * scale);
    auto to = [&](const sim::Vec2& v) { return origin + QPointF(v.x() * scale, v.y() * scale); };
    p.save();
    p.setClipRect(panel, Qt::IntersectClip);
    p.setRenderHint(QPainter::Antialiasing, true);
    const double head = 7.0 * k;
    sim::Vec2 tail(0, 0);
    if (chain) {
        for (int i = 0; i < n; ++i) {
            const sim::Vec2 tip = tail + momenta[static_cast<std::size_t>(i)];
            QList<QLineF> lines;
            appendArrow(lines, to(tail), to(tip), head);
            p.setPen(QPen(QColor::fromRgb(balls.color[static_cast<std::size_t>(i)]).darker(115), 2.0 * k,
                          Qt::SolidLine, Qt::RoundCap));
            p.drawLines(lines);
            tail = tip;
        }
        m_frame.momentumChainTip = to(tail);
    }
    QList<QLineF> lines;
    appendArrow(lines, origin, to(sum), head);
    m_frame.momentumSumArrow = QLineF(origin, to(sum));
    p.setPen(QPen(QColor::fromRgb(canvas_colors::kForce), 3.0 * k, Qt::SolidLine, Qt::RoundCap));
    p.drawLines(lines);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor::fromRgb(canvas_colors::kForce));
    p.drawEllipse(origin, 2.5 * k, 2.5 * k);
    p.restore();
}

void WorldPainter::paintCollision(QPainter& p, const ViewTransform& view, const PaintOptions& options)
{
    const CollisionView& c = *options.collision;
    const sim::Vec2 d = c.positionB - c.positionA;
    const double distance = d.norm();
    if (!(distance > 0.0))
        return;
    const double k = options.lineScale;
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
        appendArrow(lines, view.toWidget(from), view.toWidget(from + options.velocityScale * v), head);
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
               QStringLiteral("line of impact"));
    p.setPen(QColor::fromRgb(canvas_colors::kTangent));
    p.drawText(view.toWidget(contact + t * reach) + QPointF(4 * k, -4 * k), QStringLiteral("tangent"));
}

QPointF WorldPainter::vaneCentre(const ViewTransform& view, int index, double lineScale)
{
    const QRectF box = view.boxRect();
    const double r = vaneRadius(lineScale);
    // Far enough apart that the labels, which start at a vane's left edge,
    // do not run into the next vane's ("smoothed  -267 px/s²" is about
    // 135 px at 12 px).
    const double x = box.left() + r + 14.0 * lineScale + index * (2.0 * r + 100.0 * lineScale);
    // Above the box when the space over it (the widget starts at y = 0)
    // holds a vane and its label, as in a small box in the normal layout,
    // so the vanes cover no ball; otherwise inside its top-left corner.
    const double label = 18.0 * lineScale, gap = 6.0 * lineScale;
    if (box.top() >= 2.0 * r + label + 2.0 * gap)
        return {x, box.top() - gap - label - r};
    return {x, box.top() + r + 14.0 * lineScale};
}

void WorldPainter::paintVanes(QPainter& p, const ViewTransform& view, const sim::World& world,
                              const PaintOptions& options)
{
    const sim::WindSettings& wind = world.settings().wind;
    struct Vane { sim::WindMode mode; double value; };
    std::vector<Vane> vanes;
    vanes.push_back({wind.mode, world.wind()});
    if (wind.compare != sim::WindMode::Off)
        vanes.push_back({wind.compare, world.compareWind()});
    const double k = options.lineScale;
    const double r = vaneRadius(k);
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(12 * k)));
    p.setFont(font);
    const QFontMetricsF fm(font);
    p.setRenderHint(QPainter::Antialiasing, true);
    for (std::size_t i = 0; i < vanes.size(); ++i) {
        const QPointF c = vaneCentre(view, static_cast<int>(i), k);
        // The arrow starts at the hub and points where the wind blows; its
        // length is the wind as a share of the set strength (a full radius
        // at full strength).
        p.setPen(QPen(QColor(0x9a, 0xa2, 0xae), 1.0 * k));
        p.setBrush(QColor(255, 255, 255, 215));
        p.drawEllipse(c, r, r);
        const double share = wind.strength > 0.0 ? std::clamp(vanes[i].value / wind.strength, -1.0, 1.0) : 0.0;
        QList<QLineF> lines;
        appendArrow(lines, c, c + QPointF(share * r, 0.0), 8.0 * k);
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kVane), 3.0 * k, Qt::SolidLine, Qt::RoundCap));
        p.drawLines(lines);
        p.setBrush(QColor::fromRgb(canvas_colors::kVane));
        p.setPen(Qt::NoPen);
        p.drawEllipse(c, 2.5 * k, 2.5 * k);
        const std::string_view name = sim::toString(vanes[i].mode);
        const QString label = QStringLiteral("%1  %2 px/s²")
                                  .arg(QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())))
                                  .arg(vanes[i].value, 0, 'f', 0);
        p.setPen(QColor(0x1d, 0x22, 0x2c));
        p.drawText(QPointF(c.x() - r, c.y() + r + fm.ascent() + 2.0 * k), label);
    }
}

QStringList WorldPainter::totalsText(const sim::World& world, bool wide)
{
    return totalsText(world.energy(), world.momentum(), wide);
}

QStringList WorldPainter::totalsText(const sim::Energy& e, const sim::Vec2& m, bool wide)
{
    if (wide)
        return wideTotals(e, m);
    auto num = [](double v) { return QString::number(v, 'g', 6); };
    return {
        QStringLiteral("kinetic   %1").arg(num(e.kinetic)),
        QStringLiteral("potential %1").arg(num(e.potential)),
        QStringLiteral("total     %1").arg(num(e.total())),
        QStringLiteral("momentum  (%1, %2)").arg(num(m.x()), num(m.y())),
    };
}

void WorldPainter::paintTotals(QPainter& p, const QRectF& panel, const sim::World& world, const PaintOptions& options,
                               bool wide)
{
    // What a model keeps and what it loses: energy (mass·px²/s²) and
    // momentum (mass·px/s) of all balls.
    drawPanel(p, panel, panelFont(kTotalsPixels, options.lineScale), totalsText(world, wide), {}, options.lineScale);
}

} // namespace forcelab
