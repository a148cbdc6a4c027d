#include "positional_correction.h"

#include <cmath>
#include <numbers>

namespace forcelab::sim {

Vec2 lineOfImpact(const Vec2& d, double s, int a, int b)
{
    const double len = d.norm();
    if (len > 1e-12 * s && std::isfinite(len))
        return d / len;
    // The R2 low-discrepancy sequence in (a, b): well spread angles, no randomness.
    const double u = static_cast<double>(a) * 0.7548776662466927 + static_cast<double>(b) * 0.5698402909980532;
    const double angle = 2.0 * std::numbers::pi * (u - std::floor(u));
    return {std::cos(angle), std::sin(angle)};
}

void keepInsideWalls(const Vec2& before, Vec2& after, double r, const BoxSettings& box, const WallSettings& walls)
{
    const bool on[2][2] = {{walls.left, walls.right}, {walls.top, walls.bottom}};
    const double size[2] = {box.width, box.height};
    for (int k = 0; k < 2; ++k) {
        double lo = r, hi = size[k] - r;
        if (lo > hi) // wider than the box: it can only sit in the middle
            lo = hi = 0.5 * size[k];
        if (on[k][0] && before[k] >= lo && after[k] < lo)
            after[k] = lo;
        if (on[k][1] && before[k] <= hi && after[k] > hi)
            after[k] = hi;
    }
}

double separate(Vec2& pa, Vec2& pb, double ra, double rb, const Vec2& n, double wa, double wb, const BoxSettings& box,
                const WallSettings& walls)
{
    const double depth = (ra + rb) - (pb - pa).norm();
    if (!(depth > 0.0))
        return 0.0;
    const double w = wa + wb;
    const double shareA = (w > 0.0 && std::isfinite(w)) ? wa / w : 0.5;
    // Move a by its share, b by what is left, and a again by whatever b could
    // not take because of a wall. Each move stops at a wall the ball was inside.
    auto push = [&](Vec2& p, double amount, double r, double sign) {
        const Vec2 before = p;
        p += (sign * amount) * n;
        keepInsideWalls(before, p, r, box, walls);
        return sign * (p - before).dot(n); // how far it actually went along ±n
    };
    const double movedA = push(pa, depth * shareA, ra, -1.0);
    const double movedB = push(pb, depth - movedA, rb, 1.0);
    const double missing = depth - movedA - movedB;
    if (missing > 0.0)
        push(pa, missing, ra, -1.0);
    return depth;
}

} // namespace forcelab::sim
