// The arrows overlay: velocity [velocity], acceleration [acceleration], net
// force F = m a [forces] and one force per model that acts [sources], from each
// ball's centre. They share one set of scales (WorldPainter::arrowScales) and
// stay on the stage, out of the panels. With autoArrows the scales are kept
// through a run (PaintOptions::arrowRun). A legend says what a sample arrow
// stands for: on a card in a free corner, or in the stage bar
// (PaintOptions::arrowLegendCard), which the box never shares.

#include "overlay_table.h"

#include "arrow.h"
#include "panel.h"

#include "ui/drawing/display_units.h"
#include "ui/drawing/round_steps.h"

#include "sim/world/number_text.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QList>

#include <cmath>

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

// One kind of arrow drawn: its name, unit, scale and colour.
struct LegendRow {
    QString name;
    QString unit;
    double scale = 0.0; // world px per unit of the quantity
    QRgb color = 0;
};

// The legend: for each kind of arrow drawn, a sample arrow of a round
// quantity (1, 2, 5 × 10^k, at least kArrowLegendPixels long) and its value,
// on a card in the stage's bottom-right corner.
void paintLegend(const PaintContext& c, const QList<LegendRow>& rows)
{
    const ViewTransform& view = c.view;
    if (rows.isEmpty() || !(view.scale() > 0.0))
        return;
    QPainter& p = c.painter;
    const double k = c.options.lineScale;
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(13 * k)));
    font.setBold(true);
    const QFontMetricsF fm(font);
    // The rows go to the frame (the stage bar shows them from there) and
    // are drawn from it here.
    const QList<ArrowLegendRow>& drawn = c.frame.arrowLegendRows;
    double widestArrow = 0.0, widestLabel = 0.0;
    for (const LegendRow& row : rows) {
        // In the view's units (SI or px): widget px per shown unit of the quantity.
        const ShownUnit unit = shownUnit(row.unit, displayUnits());
        const double perUnit = view.toWidget(row.scale) / unit.factor();
        if (!(perUnit > 0.0) || !std::isfinite(perUnit))
            continue;
        const double value = roundStep(WorldPainter::kArrowLegendPixels / perUnit);
        const double pixels = value * perUnit;
        const QString label = QStringLiteral("%1 %2 (%3)")
                                  .arg(QString::fromStdString(sim::numberText(value)), unit.text, row.name);
        c.frame.arrowLegendRows.append({pixels, label, row.color});
        c.frame.arrowLegend.append(QStringLiteral("%1: arrow %2 px = %3 %4")
                                       .arg(row.name, QString::number(pixels, 'f', 1),
                                            QString::fromStdString(sim::numberText(value)), unit.text));
        widestArrow = std::max(widestArrow, pixels);
        widestLabel = std::max(widestLabel, fm.horizontalAdvance(label));
    }
    if (drawn.isEmpty() || !c.options.arrowLegendCard)
        return;
    const double pad = 8.0 * k, gap = 10.0 * k, rowHeight = fm.height() + 4.0 * k;
    const double width = widestArrow + gap + widestLabel + 2 * pad;
    const double height = drawn.size() * rowHeight + 2 * pad;
    // The first corner of the painted area where the card covers neither
    // the box nor a panel (a letterbox strip, the space under an inset);
    // the bottom-right corner, over the box, when none is free.
    const QRectF area = c.area; // the whole painted area, the panels' strip too
    const double margin = 8.0 * k;
    const QRectF box = view.boxRect().intersected(area);
    const QRectF corners[] = {
        {area.right() - margin - width, area.bottom() - margin - height, width, height},
        {area.left() + margin, area.bottom() - margin - height, width, height},
        {area.right() - margin - width, area.top() + margin, width, height},
        {area.left() + margin, area.top() + margin, width, height},
    };
    QRectF card = corners[0];
    for (const QRectF& corner : corners) {
        bool free = !corner.intersects(box);
        for (const QRectF& panel : {c.panels.readout, c.panels.totals, c.panels.sources, c.panels.momenta})
            free = free && !(panel.isValid() && corner.intersects(panel));
        if (free) {
            card = corner;
            break;
        }
    }
    drawPanelCard(p, card);
    p.setFont(font);
    for (qsizetype i = 0; i < drawn.size(); ++i) {
        const double y = card.top() + pad + (static_cast<double>(i) + 0.5) * rowHeight;
        const QPointF tail(card.left() + pad, y);
        QList<QLineF> lines;
        appendArrow(lines, tail, tail + QPointF(drawn[i].pixels, 0.0), 9.0 * k);
        p.setPen(QPen(QColor::fromRgb(drawn[i].color), 2.0 * k, Qt::SolidLine, Qt::RoundCap));
        p.drawLines(lines);
        p.setPen(QColor(0x1d, 0x22, 0x2c));
        p.drawText(QPointF(card.left() + pad + widestArrow + gap, y - fm.height() / 2 + fm.ascent()), drawn[i].label);
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
            const QPointF tail = view.toWidget(x), tip = view.toWidget(x + scales.velocity * balls.velocity.col(i));
            appendArrow(lines, tail, tip, head);
            c.frame.velocityLengths.push_back(QLineF(tail, tip).length());
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
    {
        QList<LegendRow> rows;
        if (options.overlays.velocity)
            rows.append({QCoreApplication::translate("Overlay", "velocity"), QStringLiteral("px/s"), scales.velocity, canvas_colors::kVelocity});
        if (options.overlays.acceleration && accelerations)
            rows.append({QCoreApplication::translate("Overlay", "acceleration"), QStringLiteral("px/s²"), scales.acceleration,
                         canvas_colors::kAcceleration});
        if ((options.overlays.forces || options.overlays.forceSources) && accelerations)
            rows.append({QCoreApplication::translate("Overlay", "force"), QStringLiteral("mass·px/s²"), scales.force, canvas_colors::kForce});
        paintLegend(c, rows);
    }
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
