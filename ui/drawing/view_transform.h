#pragma once
// The map between world coordinates (simulation px, x right, y down) and
// widget coordinates (logical px): one uniform scale and an offset that
// centres the box, so the world keeps its aspect ratio and the spare space
// becomes a letterbox. A camera (camera.h) zooms and moves that view.

#include "ui/drawing/camera.h"

#include "sim/world/types.h"
#include "sim/world/world_settings.h"

#include <QPointF>
#include <QRectF>
#include <QSizeF>

namespace forcelab {

class ViewTransform {
public:
    ViewTransform() = default;

    /// The largest view of `box` that fits in `area` with `margin` logical px on every side.
    static ViewTransform fit(const sim::BoxSettings& box, const QRectF& area, double margin = 10.0);
    /// The fitted view zoomed by `camera.zoom` with `camera.centre` (or the
    /// box's centre) at the middle of `area`; the fitted view itself when the
    /// camera is fitted.
    static ViewTransform fit(const sim::BoxSettings& box, const QRectF& area, double margin, const Camera& camera);

    double scale() const { return m_scale; } ///< widget px per world px
    QPointF toWidget(const sim::Vec2& world) const;
    sim::Vec2 toWorld(const QPointF& widget) const;
    double toWidget(double worldLength) const { return worldLength * m_scale; }
    double toWorld(double widgetLength) const { return widgetLength / m_scale; }
    /// The box [0, width] × [0, height] in widget coordinates.
    QRectF boxRect() const;
    /// Whether a camera zoomed or moved the view away from the fitted one.
    bool moved() const { return m_moved; }
    /// The area the view was made for (widget px).
    QRectF area() const { return m_area; }
    /// Where the world's drawings may go: the box when the view is fitted
    /// (paths and arrows stay in it), the whole area when it was moved (so
    /// balls that left the box and their paths are seen when zoomed out).
    QRectF worldClip() const { return m_moved ? m_area : boxRect(); }
    /// The part of the box that is on screen: the box when fitted.
    QRectF shownBox() const { return m_moved ? boxRect().intersected(m_area) : boxRect(); }
    /// The widget position of the world origin.
    QPointF origin() const { return m_offset; }

private:
    double m_scale = 1.0;
    QPointF m_offset;   // widget position of the world origin
    QSizeF m_boxSize;   // world px
    QRectF m_area;      // widget px, the area given to fit()
    bool m_moved = false;
};

} // namespace forcelab
