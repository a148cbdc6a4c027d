#pragma once
// The broad phase's geometry for drawing it: the cells of the uniform grid and
// the rows of sort and sweep, as the detectors themselves lay them out, so the
// overlay a lesson shows is the search the world runs.

#include "sim/world/world.h"

namespace forcelab::sim {

struct BroadPhaseGeometry {
    double cellSize = 0.0;             ///< px, grid cell side (0: no cells)
    double originX = 0.0, originY = 0.0; ///< px, where cell (0, 0) starts
    double rowHeight = 0.0;            ///< px, sweep row height; row k spans [k h, (k + 1) h) (0: no rows)
};

/// The geometry of the world's detection: the detector's own from the last
/// step, once the world has stepped with that detector, else what it would
/// lay out for the balls where they are now (a paused lesson at t = 0).
BroadPhaseGeometry broadPhaseGeometry(const World& world);

} // namespace forcelab::sim
