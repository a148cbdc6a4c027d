// The readout overlay [readout]: a panel with the position, velocity and
// acceleration of the selected ball (ball 0 when none), the velocity and the
// acceleration in their arrows' colours. The lines are WorldPainter::readoutText's.

#include "overlay_table.h"

#include "panel.h"

namespace forcelab {

namespace {

void paintReadout(const PaintContext& c)
{
    const bool wide = c.panels.readoutWide;
    const double k = c.options.lineScale;
    const QStringList lines = WorldPainter::readoutText(c.world, c.options.selected, c.accelerations, wide);
    if (lines.isEmpty())
        return;
    const QColor text(0x1d, 0x22, 0x2c);
    if (wide) {
        drawPanel(c.painter, c.panels.readout, panelFont(kReadoutPixels, k), lines, {}, k);
        return;
    }
    drawPanel(c.painter, c.panels.readout, panelFont(kReadoutPixels, k), lines,
              {text, text, QColor::fromRgb(canvas_colors::kVelocity), QColor::fromRgb(canvas_colors::kAcceleration), text},
              k);
}

} // namespace

OverlayInfo readoutOverlay()
{
    return {.name = "readout",
            .on = [](const PaintContext& c) { return c.options.overlays.readout; },
            .paint = &paintReadout,
            .needsAccelerations = [](const PaintOptions&) { return true; },
            .panel = true};
}

} // namespace forcelab
