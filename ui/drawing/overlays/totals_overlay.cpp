// The totals overlay [totals]: a panel with what a model keeps and what it
// loses, the energy (mass·px²/s²) and the momentum (mass·px/s) of all balls.
// The lines are WorldPainter::totalsText's.

#include "overlay_table.h"

#include "panel.h"

namespace forcelab {

namespace {

void paintTotals(const PaintContext& c)
{
    const double k = c.options.lineScale;
    drawPanel(c.painter, c.panels.totals, panelFont(kTotalsPixels, k),
              WorldPainter::totalsText(c.world, c.panels.totalsWide), {}, k);
}

} // namespace

OverlayInfo totalsOverlay()
{
    return {.name = "totals",
            .on = [](const PaintContext& c) { return c.options.overlays.totals; },
            .paint = &paintTotals,
            .panel = true};
}

} // namespace forcelab
