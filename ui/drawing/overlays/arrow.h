#pragma once
// The arrows the overlays draw (velocities, forces, momenta, the wind vanes):
// a shaft and two head strokes, collected as lines so each colour is one draw call.

#include <QLineF>
#include <QList>
#include <QPointF>

namespace forcelab {

/// Appends the shaft and the two head strokes of an arrow from a to b; the
/// head is `head` px long, at most 0.4 of the shaft. Nothing for an arrow
/// shorter than half a pixel.
void appendArrow(QList<QLineF>& lines, QPointF a, QPointF b, double head);

} // namespace forcelab
