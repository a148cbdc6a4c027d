// An arrow as lines (arrow.h).

#include "arrow.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace forcelab {

void appendArrow(QList<QLineF>& lines, QPointF a, QPointF b, double head)
{
    const QLineF shaft(a, b);
    const double length = shaft.length();
    if (!(length >= 0.5))
        return;
    lines.append(shaft);
    const double h = std::min(head, 0.4 * length);
    const QPointF u = (a - b) / length; // unit vector from tip back to tail
    const double c = std::cos(std::numbers::pi / 7.0), s = std::sin(std::numbers::pi / 7.0);
    lines.append(QLineF(b, b + h * QPointF(c * u.x() - s * u.y(), s * u.x() + c * u.y())));
    lines.append(QLineF(b, b + h * QPointF(c * u.x() + s * u.y(), -s * u.x() + c * u.y())));
}

} // namespace forcelab
