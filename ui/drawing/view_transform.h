#pragma once
// The map between world coordinates (simulation px, x right, y down) and
// widget coordinates (logical px): one uniform scale and an offset that
// centres the box, so the world keeps its aspect ratio and the spare space
// becomes a letterbox.

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

    double scale() const { return m_scale; } ///< widget px per world px
    QPointF toWidget(const sim::Vec2& world) const;
    sim::Vec2 toWorld(const QPointF& widget) const;
    double toWidget(double worldLength) const { return worldLength * m_scale; }
    double toWorld(double widgetLength) const { return widgetLength / m_scale; }
    /// The box [0, width] × [0, height] in widget coordinates.
    QRectF boxRect() const;

private:
    double m_scale = 1.0;
    QPointF m_offset;   // widget position of the world origin
    QSizeF m_boxSize;   // world px
};

} // namespace forcelab
