// The layout of the box and its panels (panel_layout.h).

#include "panel_layout.h"

#include "overlays/panel.h"

#include <QFontMetricsF>

#include <algorithm>
#include <vector>

namespace forcelab {

namespace {

// The widest lines the panels can show (numbers at their widest), so the
// strip does not change size while the numbers change.
QSizeF readoutSize(double lineScale)
{
    return panelSize(panelFont(kReadoutPixels, lineScale), QStringLiteral("speed     -99999.9 px/s   t = 9999.999 s"),
                     kReadoutLines, lineScale);
}

QSizeF totalsSize(double lineScale)
{
    sim::Energy e;
    e.kinetic = e.potential = -9.999e+12;
    const QStringList lines = WorldPainter::totalsText(e, sim::Vec2(-9.999e+12, -9.999e+12), false);
    QString widest;
    const QFont font = panelFont(kTotalsPixels, lineScale);
    const QFontMetricsF fm(font);
    for (const QString& line : lines)
        if (fm.horizontalAdvance(line) > fm.horizontalAdvance(widest))
            widest = line;
    return panelSize(font, widest, static_cast<int>(lines.size()), lineScale);
}

// The same panels in two long lines, for a strip above the box: it costs
// the box less height.
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
    const QStringList lines =
        WorldPainter::readoutText(9999, big, big, big, 9999.999, WorldPainter::ReadoutShape::Wide);
    return wideSize(panelFont(kReadoutPixels, lineScale), lines, lineScale);
}

QSizeF wideTotalsSize(double lineScale)
{
    sim::Energy e;
    e.kinetic = e.potential = -9.999e+12;
    return wideSize(panelFont(kTotalsPixels, lineScale),
                    WorldPainter::totalsText(e, sim::Vec2(-9.999e+12, -9.999e+12), true), lineScale);
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

// A panel that is on, with its size in a column and in a row: in a row the
// readout and the totals are two long lines and the momenta inset is wider
// than tall, so a strip above the box costs it less height.
struct Item {
    QRectF* rect;
    QSizeF column, row;
    bool* wide; // set when the row size is used (null: the panel has one shape)
};

// The panels placed along rows (or columns) no longer than `limit`, relative
// to the strip's corner; in rows a panel takes its row shape when that fits.
struct Flow {
    std::vector<QRectF> at;
    QSizeF extent;
};

Flow flow(const std::vector<Item>& items, bool rows, double limit, double gap)
{
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
}

} // namespace

// The panels go in a strip at the right of the area (one above the other,
// wrapping into a second column when they do not fit the height) or at the
// top (side by side, wrapping into rows), whichever leaves the box larger.
PanelLayout layoutPanels(const sim::World& world, const QRectF& area, const PaintOptions& o)
{
    PanelLayout l{area, {}};
    const sim::BoxSettings& box = world.settings().box;
    const bool any = !world.balls().empty();
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
    const Flow column = flow(items, false, area.height() - 2 * gap, gap);
    const Flow row = flow(items, true, area.width() - 2 * gap, gap);
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

} // namespace forcelab
