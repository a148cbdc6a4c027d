// The scale bar, drawn whenever the view is zoomed or moved: a bar of a round
// length in world px and the zoom, in the bottom-left corner of the stage, so
// a zoomed picture still says how large things are.

#include "overlay_table.h"
#include "panel.h"

#include "ui/drawing/display_units.h"
#include "ui/drawing/round_steps.h"

#include "sim/world/number_text.h"

#include <QFontMetricsF>

#include <cmath>

namespace forcelab {

double WorldPainter::scaleBarLength(double scale)
{
    return roundStep(kScaleBarPixels / scale);
}

namespace {

QString text(const std::string& s)
{
    return QString::fromStdString(s);
}

// "4", "0.25", "1.56", "1000": three digits, never a power of ten (the zoom is at most 1000).
QString zoomText(double zoom)
{
    return text(zoom >= 100.0 ? sim::numberText(std::round(zoom)) : sim::roundedText(zoom, 3));
}

void paintScaleBar(const PaintContext& c)
{
    const ViewTransform& view = c.view;
    if (!(view.scale() > 0.0))
        return;
    QPainter& p = c.painter;
    const double k = c.options.lineScale;
    const double length = WorldPainter::scaleBarLength(view.scale());
    const double pixels = view.toWidget(length);
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(14 * k)));
    font.setBold(true);
    const ShownUnit unit = shownUnit(QStringLiteral("px"), displayUnits()); // m in SI
    const QString label = QStringLiteral("%1 %2    zoom ×%3")
                              .arg(text(sim::numberText(unit.toShown(length))), unit.text,
                                   zoomText(c.options.camera.zoom));
    const QFontMetricsF fm(font);
    const double pad = 8.0 * k;
    const double width = std::max(pixels, fm.horizontalAdvance(label)) + 2 * pad;
    const double height = fm.height() + 14.0 * k + 2 * pad;
    const QRectF area = view.area();
    const QRectF card(area.left() + 8.0 * k, area.bottom() - 8.0 * k - height, width, height);
    drawPanelCard(p, card);
    // The bar with a tick at each end, then the words under it.
    const double y = card.top() + pad + 6.0 * k;
    const QLineF bar(card.left() + pad, y, card.left() + pad + pixels, y);
    const QColor ink(0x1d, 0x22, 0x2c);
    p.setPen(QPen(ink, 3.0 * k, Qt::SolidLine, Qt::FlatCap));
    p.drawLine(bar);
    p.setPen(QPen(ink, 2.0 * k));
    p.drawLine(QLineF(bar.p1() - QPointF(0, 6 * k), bar.p1() + QPointF(0, 6 * k)));
    p.drawLine(QLineF(bar.p2() - QPointF(0, 6 * k), bar.p2() + QPointF(0, 6 * k)));
    p.setFont(font);
    p.drawText(QPointF(card.left() + pad, y + 8.0 * k + fm.ascent()), label);
    c.frame.scaleBarLength = length;
    c.frame.scaleBar = bar;
}

} // namespace

OverlayInfo scaleBarOverlay()
{
    return {.name = "scale-bar",
            .on = [](const PaintContext& c) { return c.view.moved(); },
            .paint = &paintScaleBar};
}

} // namespace forcelab
