#pragma once
// Where the box and its panels go in the painted area: the panels that are on
// (readout, totals, legend of the force sources, momenta inset) take a strip
// beside the box or above it, whichever leaves the box larger, so they never
// cover the physics.

#include "world_painter.h"

namespace forcelab {

struct PanelLayout {
    QRectF stage;                ///< where the box is fitted
    WorldPainter::Panels panels; ///< the panels' places (empty rects for those that are off)
};

/// The layout for `area`. The panels' sizes do not depend on the numbers they
/// show, so nothing moves while a lesson runs.
PanelLayout layoutPanels(const sim::World& world, const QRectF& area, const PaintOptions& options);

} // namespace forcelab
