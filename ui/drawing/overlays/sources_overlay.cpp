// The sources legend [sources]: a panel naming each force model that is on in
// the colour of its arrows (the arrows themselves are the arrows overlay's).

#include "overlay_table.h"

#include "panel.h"

#include "sim/forces/force_models.h"

namespace forcelab {

namespace {

void paintSourceLegend(const PaintContext& c)
{
    const sim::WorldSettings& settings = c.world.settings();
    const QStringList lines = sourceLegend(settings);
    QList<QColor> colors{QColor(0x1d, 0x22, 0x2c)};
    for (const sim::ForceModelInfo& m : sim::forceModels())
        if (m.on(settings))
            colors.append(WorldPainter::sourceColor(m.name));
    drawPanel(c.painter, c.panels.sources, panelFont(kTotalsPixels, c.options.lineScale), lines, colors,
              c.options.lineScale);
}

} // namespace

OverlayInfo sourcesOverlay()
{
    // The layout gives the legend a place when the overlay is on and there are balls.
    return {.name = "sources",
            .on = [](const PaintContext& c) { return !c.panels.sources.isEmpty(); },
            .paint = &paintSourceLegend,
            .panel = true};
}

} // namespace forcelab
