// The table of overlays. The order is the drawing order: the grid and the
// walls on the box, the broad phase, the paths and the marks under the balls,
// the balls, then the ghost, the arrows and the impact over them, and last the
// vanes, the scale bar (when zoomed) and the panels beside the box.

#include "overlay_table.h"

namespace forcelab {

std::span<const OverlayInfo> overlayTable()
{
    // Built on first use, so no record is read before its file has made it.
    static const OverlayInfo kTable[] = {
        gridOverlay(),   wallsOverlay(),  broadPhaseOverlay(), trailsOverlay(), centreOfMassOverlay(),
        apexesOverlay(), markersOverlay(), ballsOverlay(),     ghostOverlay(),  arrowsOverlay(),
        impactOverlay(), vanesOverlay(),  scaleBarOverlay(),   totalsOverlay(),  readoutOverlay(),
        sourcesOverlay(), momentaOverlay(),
    };
    return kTable;
}

} // namespace forcelab
