// Time of impact of two circles moving on straight lines (time_of_impact.h).

#include "sim/collision/response/time_of_impact.h"

#include <cmath>

namespace forcelab::sim {

double timeOfImpact(double d0x, double d0y, double ddx, double ddy, double s)
{
    const double d2 = d0x * d0x + d0y * d0y;
    const double s2 = s * s;
    if (d2 < s2)
        return 0.0;
    const double b = d0x * ddx + d0y * ddy;
    if (!(b < 0.0)) // moving apart, side by side, or NaN
        return -1.0;
    const double c = d2 - s2; // >= 0
    const double a = ddx * ddx + ddy * ddy;
    const double disc = b * b - a * c;
    if (!(disc >= 0.0)) // the closest approach is wider than s
        return -1.0;
    const double t = c / (-b + std::sqrt(disc));
    return t <= 1.0 ? t : -1.0;
}

} // namespace forcelab::sim
