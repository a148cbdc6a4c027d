#include "view_transform.h"

#include <algorithm>

namespace forcelab {

ViewTransform ViewTransform::fit(const sim::BoxSettings& box, const QRectF& area, double margin)
{
    ViewTransform t;
    t.m_boxSize = QSizeF(box.width, box.height);
    const double w = std::max(1.0, area.width() - 2.0 * margin);
    const double h = std::max(1.0, area.height() - 2.0 * margin);
    if (box.width > 0.0 && box.height > 0.0)
        t.m_scale = std::min(w / box.width, h / box.height);
    const QPointF centre = area.center();
    t.m_offset = centre - QPointF(0.5 * box.width * t.m_scale, 0.5 * box.height * t.m_scale);
    t.m_area = area;
    return t;
}

ViewTransform ViewTransform::fit(const sim::BoxSettings& box, const QRectF& area, double margin, const Camera& camera)
{
    ViewTransform t = fit(box, area, margin);
    if (camera.fitted())
        return t;
    t.m_scale *= camera.zoom;
    const sim::Vec2 middle = camera.centre.value_or(sim::Vec2(0.5 * box.width, 0.5 * box.height));
    t.m_offset = area.center() - QPointF(middle.x() * t.m_scale, middle.y() * t.m_scale);
    t.m_moved = true;
    return t;
}

QPointF ViewTransform::toWidget(const sim::Vec2& world) const
{
    return m_offset + QPointF(world.x() * m_scale, world.y() * m_scale);
}

sim::Vec2 ViewTransform::toWorld(const QPointF& widget) const
{
    const QPointF d = (widget - m_offset) / m_scale;
    return {d.x(), d.y()};
}

QRectF ViewTransform::boxRect() const
{
    return {m_offset, m_boxSize * m_scale};
}

} // namespace forcelab
