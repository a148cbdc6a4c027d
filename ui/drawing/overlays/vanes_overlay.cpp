// The vanes overlay [vanes]: one wind vane per wind model, the acting one and
// the one wind.compare names, each an arrow from the hub whose length is the
// wind as a share of the set strength, with the model's name and its value.

#include "overlay_table.h"

#include "arrow.h"

#include "ui/drawing/display_units.h"
#include "ui/drawing/human_number.h"

#include "sim/world/names.h"

#include <QFontMetricsF>
#include <QList>

#include <algorithm>
#include <cmath>
#include <vector>

namespace forcelab {

namespace {

void paintVanes(const PaintContext& c)
{
    QPainter& p = c.painter;
    const sim::WindSettings& wind = c.world.settings().wind;
    struct Vane { sim::WindMode mode; double value; };
    std::vector<Vane> vanes;
    vanes.push_back({wind.mode, c.world.wind()});
    if (wind.compare != sim::WindMode::Off)
        vanes.push_back({wind.compare, c.world.compareWind()});
    const double k = c.options.lineScale;
    const double r = WorldPainter::vaneRadius(k);
    QFont font = p.font();
    font.setPixelSize(static_cast<int>(std::lround(12 * k)));
    p.setFont(font);
    const QFontMetricsF fm(font);
    p.setRenderHint(QPainter::Antialiasing, true);
    for (std::size_t i = 0; i < vanes.size(); ++i) {
        const QPointF hub = WorldPainter::vaneCentre(c.view, static_cast<int>(i), k);
        // The arrow starts at the hub and points where the wind blows; its
        // length is the wind as a share of the set strength (a full radius
        // at full strength).
        p.setPen(QPen(QColor(0x9a, 0xa2, 0xae), 1.0 * k));
        p.setBrush(QColor(255, 255, 255, 215));
        p.drawEllipse(hub, r, r);
        const double share = wind.strength > 0.0 ? std::clamp(vanes[i].value / wind.strength, -1.0, 1.0) : 0.0;
        QList<QLineF> lines;
        appendArrow(lines, hub, hub + QPointF(share * r, 0.0), 8.0 * k);
        p.setPen(QPen(QColor::fromRgb(canvas_colors::kVane), 3.0 * k, Qt::SolidLine, Qt::RoundCap));
        p.drawLines(lines);
        p.setBrush(QColor::fromRgb(canvas_colors::kVane));
        p.setPen(Qt::NoPen);
        p.drawEllipse(hub, 2.5 * k, 2.5 * k);
        const std::string_view name = sim::toString(vanes[i].mode);
        const ShownUnit unit = shownUnit(QStringLiteral("px/s²"), displayUnits()); // m/s² in SI
        const QString label =
            QStringLiteral("%1  %2 %3")
                .arg(QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())),
                     unit.px != 0 ? humanNumber(unit.toShown(vanes[i].value), 3)
                                  : QString::number(vanes[i].value, 'f', 0),
                     unit.text);
        p.setPen(QColor(0x1d, 0x22, 0x2c));
        p.drawText(QPointF(hub.x() - r, hub.y() + r + fm.ascent() + 2.0 * k), label);
    }
}

} // namespace

OverlayInfo vanesOverlay()
{
    return {.name = "vanes",
            .on = [](const PaintContext& c) { return c.options.overlays.vanes; },
            .paint = &paintVanes};
}

} // namespace forcelab
