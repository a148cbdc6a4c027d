#pragma once
// An overlay as a record, like a force model of the simulation: its name, when
// it is on, and how it paints. WorldPainter lays out the box and its panels,
// then walks the table of overlays (overlay_table.h) in order; the order is
// the order things are drawn, each one over those before it.

#include "ui/drawing/world_painter.h"

#include <QPainter>

#include <string_view>

namespace forcelab {

/// What an overlay sees while it paints: the painter, where the box and the
/// panels are, the world and the options, and what the painter keeps from
/// frame to frame (sprites, the paths' layer) or reports about this frame.
struct PaintContext {
    QPainter& painter;
    const QRectF& area;                 ///< widget px, the whole area painted
    const ViewTransform& view;          ///< the box's place in the area
    const sim::World& world;
    const PaintOptions& options;
    const WorldPainter::Panels& panels; ///< where the panels beside the box go
    qreal dpr;                          ///< the paint device's pixel ratio
    BallSprites& sprites;               ///< the balls' cached images
    PathLayer& paths;                   ///< the trails drawn so far
    PaintedFrame& frame;                ///< what this frame drew, for tests
    double& momentumScale;              ///< the momenta inset's scale, kept while the arrows fit
    /// Each ball's acceleration, worked out once per frame when an overlay
    /// that is on needs it and there are balls; null otherwise.
    const sim::Matrix2X* accelerations = nullptr;
};

struct OverlayInfo {
    std::string_view name; ///< the lesson's overlay name where it has one: "grid", "trails"
    bool (*on)(const PaintContext&);
    void (*paint)(const PaintContext&);
    /// Whether it needs the balls' accelerations with these options (nullptr: never).
    bool (*needsAccelerations)(const PaintOptions&) = nullptr;
    /// A panel beside the box (readout, totals, legends): drawn in its strip,
    /// which a zoomed world never covers.
    bool panel = false;
};

/// Where the balls are drawn: their positions, or the slow-motion
/// interpolation between two steps when the options give one that fits.
inline const sim::Matrix2X& drawnPositions(const sim::BallState& balls, const PaintOptions& options)
{
    return options.positions && options.positions->cols() == balls.size() ? *options.positions : balls.position;
}

/// The theme's colours, or the plain ones.
inline const CanvasColors& colorsOf(const PaintOptions& options)
{
    static const CanvasColors plain;
    return options.colors ? *options.colors : plain;
}

} // namespace forcelab
