#pragma once
// The table of overlays, in the order they are drawn, and the records it is
// made of (one per file in this folder).

#include "overlay.h"

#include <span>

namespace forcelab {

/// Every overlay, in the order WorldPainter draws them over the box.
std::span<const OverlayInfo> overlayTable();

// The records, in table order.
OverlayInfo gridOverlay();
OverlayInfo wallsOverlay();
OverlayInfo broadPhaseOverlay();
OverlayInfo trailsOverlay();
OverlayInfo apexesOverlay();
OverlayInfo markersOverlay();
OverlayInfo ballsOverlay();
OverlayInfo centreOfMassOverlay();
OverlayInfo ghostOverlay();
OverlayInfo arrowsOverlay();
OverlayInfo impactOverlay();
OverlayInfo vanesOverlay();
OverlayInfo scaleBarOverlay();
OverlayInfo totalsOverlay();
OverlayInfo readoutOverlay();
OverlayInfo sourcesOverlay();
OverlayInfo momentaOverlay();

} // namespace forcelab
