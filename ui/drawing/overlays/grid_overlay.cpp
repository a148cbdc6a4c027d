// The grid overlay [grid]: faint lines every 50 px and stronger, labelled ones
// every 100 px in the box as a lesson opens it; zoomed or moved, the labelled
// lines are a round spacing (1, 2 or 5 × 10^k px) for the scale. The student
// reads positions off the picture in the readout's units at any zoom.

#include "overlay_table.h"

#include "ui/drawing/display_units.h"
#include "ui/drawing/human_number.h"
#include "ui/drawing/round_steps.h"

#include <QList>

#include <cmath>

namespace forcelab {

double WorldPainter::gridStep(double scale)
{
    return roundStep(kGridLabelPixels / scale);
}

namespace {

void paintGrid(const PaintContext& c)
{
    const ViewTransform& view = c.view;
    if (!(view.scale() > 0.0))
        return;
    QPainter& p = c.painter;
    const CanvasColors& colors = colorsOf(c.options);
    const QRectF shown = view.shownBox();
    if (shown.isEmpty())
        return;
    const sim::BoxSettings& size = c.world.settings().box;
    // The box as a lesson opens it: lines every 50 px, labels every 100 px
    // (lesson 1 says so), unless they would be closer than 8 px. Zoomed or
    // moved: the round spacing for the scale.
    const double major = view.moved() ? WorldPainter::gridStep(view.scale()) : 100.0;
    const double minor = 0.5 * major;
    if (!view.moved() && !(view.toWidget(minor) >= 8.0))
        return; // lines closer than 8 px would only grey the box
    c.frame.gridStep = major;
    // The lines strictly inside the box that are on screen, as multiples of the minor step.
    const sim::Vec2 from = view.toWorld(shown.topLeft()), to = view.toWorld(shown.bottomRight());
    auto range = [&](double low, double high, double length) {
        const auto first = static_cast<long long>(std::max(1.0, std::ceil(low / minor)));
        auto last = static_cast<long long>(std::floor(high / minor));
        if (static_cast<double>(last) * minor >= length)
            --last;
        return std::pair(first, last);
    };
    const auto [firstX, lastX] = range(from.x(), to.x(), size.width);
    const auto [firstY, lastY] = range(from.y(), to.y(), size.height);
    QList<QLineF> minorLines, majorLines;
    for (long long k = firstX; k <= lastX; ++k) {
        const double x = view.toWidget(sim::Vec2(static_cast<double>(k) * minor, 0.0)).x();
        (k % 2 ? minorLines : majorLines).append(QLineF(x, shown.top(), x, shown.bottom()));
    }
    for (long long k = firstY; k <= lastY; ++k) {
        const double y = view.toWidget(sim::Vec2(0.0, static_cast<double>(k) * minor)).y();
        (k % 2 ? minorLines : majorLines).append(QLineF(shown.left(), y, shown.right(), y));
    }
    p.setRenderHint(QPainter::Antialiasing, false);
    p.setPen(QPen(QColor::fromRgb(colors.gridMinor), 1.0));
    p.drawLines(minorLines);
    p.setPen(QPen(QColor::fromRgb(colors.gridMajor), 1.0));
    p.drawLines(majorLines);

    // Labels on the major lines, along the top and the left of what is shown;
    // the first one across the top says the unit.
    if (!(view.toWidget(major) >= 40.0))
        return; // labels closer than 40 px would run into each other
    const double k = c.options.lineScale;
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(11 * k)));
    p.setFont(font);
    p.setPen(QColor::fromRgb(colors.gridText));
    const int decimals = roundStepDecimals(major);
    bool unit = true;
    const ShownUnit length = shownUnit(QStringLiteral("px"), displayUnits()); // m in SI
    const bool converted = length.px != 0;
    for (long long i = (firstX + 1) / 2; 2 * i <= lastX; ++i) {
        const double x = static_cast<double>(i) * major;
        QString text = converted ? humanNumber(length.toShown(x), 4) : QString::number(x, 'f', decimals);
        if (unit)
            text += QLatin1Char(' ') + length.text;
        unit = false;
        p.drawText(QPointF(view.toWidget(sim::Vec2(x, 0.0)).x() + 3, shown.top() + 13 * k), text);
        c.frame.gridLabelsX << text;
    }
    // Down the left in the same unit as across the top (in SI: 1, 2, … m,
    // not the pixels behind them).
    for (long long i = (firstY + 1) / 2; 2 * i <= lastY; ++i) {
        const double y = static_cast<double>(i) * major;
        const QString text = converted ? humanNumber(length.toShown(y), 4) : QString::number(y, 'f', decimals);
        p.drawText(QPointF(shown.left() + 4, view.toWidget(sim::Vec2(0.0, y)).y() - 3), text);
        c.frame.gridLabelsY << text;
    }
}

} // namespace

OverlayInfo gridOverlay()
{
    return {.name = "grid",
            .on = [](const PaintContext& c) { return c.options.overlays.grid; },
            .paint = &paintGrid};
}

} // namespace forcelab
