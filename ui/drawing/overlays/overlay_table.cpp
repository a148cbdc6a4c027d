// The table of overlays. The order is the drawing order: the grid and the
// walls on the box, the broad phase, the paths and the marks under the
// balls, the balls, then over them the centre of mass (often inside a ball:
// lesson 19's is 2.4 px from the Earth's centre), the ghost, the arrows and
// the impact, and last the vanes, the scale bar (when zoomed) and the panels
// beside the box.

#include "overlay_table.h"

namespace forcelab {

std::span<const OverlayInfo> overlayTable()
{
    // Built on first use, so no record is read before its file has made it.
    static const OverlayInfo kTable[] = {
        gridOverlay(),   wallsOverlay(),   broadPhaseOverlay(),   trailsOverlay(), apexesOverlay(),
        markersOverlay(), ballsOverlay(),  centreOfMassOverlay(), ghostOverlay(),  arrowsOverlay(),
        impactOverlay(), vanesOverlay(),  scaleBarOverlay(),   totalsOverlay(),  readoutOverlay(),
        sourcesOverlay(), momentaOverlay(),
    };
    return kTable;
}

} // namespace forcelab
